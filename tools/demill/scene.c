/* scene.c: checks a scene file's tree and builds its world through the
 * public API (scene.h). The world's, materials', pairs' and drum's keys are
 * the parameter registry's names (demill_param_name() over the key ranges
 * the headers give each group), so that a key the library adds is a scene
 * key at once; the other sections are described here. */
#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clumps.h"
#include "scene.h"

#define MAX_NAMES 128
#define PI 3.14159265358979323846

typedef struct ctx {
    scene *s;
    const tree *root;
    const char *dir;
    int mode;
    char *err;
    size_t errlen;
} ctx;

/* ---- messages ---------------------------------------------------------------- */

static int fail(ctx *c, const tree *n, const char *fmt, ...)
{
    char path[512], msg[512];
    tree_path(c->root, n, path, sizeof path);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (n->line > 0)
        snprintf(c->err, c->errlen, "%s:%d: %s%s%s", n->src, n->line, path, *path ? ": " : "", msg);
    else
        snprintf(c->err, c->errlen, "--set %s: %s", path, msg);
    return -1;
}

static const char *kind_name(const tree *n)
{
    return n->kind == TREE_MAP ? "a map" : n->kind == TREE_SEQ ? "a list" : n->text;
}

/* Levenshtein distance, for did-you-mean (names are short). */
static size_t distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), row[64];
    if (la >= 63 || lb >= 63)
        return 99;
    for (size_t j = 0; j <= lb; j++)
        row[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            const size_t up = row[j];
            const size_t sub = diag + (a[i - 1] != b[j - 1]);
            row[j] = sub < up + 1 ? sub : up + 1;
            if (row[j - 1] + 1 < row[j])
                row[j] = row[j - 1] + 1;
            diag = up;
        }
    }
    return row[lb];
}

/* Every key of the map must be one of names[0..n). */
static int check_keys(ctx *c, const tree *map, const char *const *names, size_t n)
{
    for (size_t k = 0; k < map->n; k++) {
        const char *key = map->kid[k]->key;
        size_t best = 99, at = 0;
        for (size_t j = 0; j < n; j++) {
            if (!strcmp(key, names[j])) {
                best = 0;
                break;
            }
            const size_t d = distance(key, names[j]);
            if (d < best) {
                best = d;
                at = j;
            }
        }
        if (best == 0)
            continue;
        char list[1024] = "";
        for (size_t j = 0; j < n && strlen(list) < 900; j++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", j ? ", " : "",
                     names[j]);
        if (best <= 2 || (best <= 4 && strlen(key) > 8))
            return fail(c, map->kid[k], "unknown key (did you mean '%s'?)", names[at]);
        return fail(c, map->kid[k], "unknown key; expected one of %s", list);
    }
    return 0;
}

static int need_kind(ctx *c, const tree *n, tree_kind kind)
{
    static const char *const what[] = {"a value", "a map of keys", "a list"};
    if (n->kind == kind)
        return 0;
    return fail(c, n, "expected %s, got %s", what[kind], n->kind == TREE_SCALAR ? "a value" : kind_name(n));
}

static const tree *need(ctx *c, const tree *map, const char *key)
{
    const tree *t = tree_get(map, key);
    if (!t)
        fail(c, map, "missing '%s'", key);
    return t;
}

/* ---- numbers ------------------------------------------------------------------- */

static int to_number(const tree *n, double *out)
{
    if (n->kind != TREE_SCALAR || n->quoted || !*n->text)
        return -1;
    char *end;
    *out = strtod(n->text, &end);
    return *end || !isfinite(*out) ? -1 : 0;
}

static int number(ctx *c, const tree *n, double lo, double hi, double *out)
{
    if (to_number(n, out) || *out < lo || *out > hi) {
        if (lo == -HUGE_VAL && hi == HUGE_VAL)
            return fail(c, n, "expected a number, got '%s'", kind_name(n));
        if (hi == HUGE_VAL)
            return fail(c, n, "expected a number >= %g, got '%s'", lo, kind_name(n));
        return fail(c, n, "expected a number in [%g, %g], got '%s'", lo, hi, kind_name(n));
    }
    return 0;
}

static int positive(ctx *c, const tree *n, double *out)
{
    if (to_number(n, out) || !(*out > 0))
        return fail(c, n, "expected a number > 0, got '%s'", kind_name(n));
    return 0;
}

/* A list of exactly `count` numbers (count 0: 1 to max, *got receives it). */
static int numbers(ctx *c, const tree *n, size_t count, size_t max, double *out, size_t *got)
{
    const size_t want = count ? count : max;
    if (n->kind != TREE_SEQ || (count && n->n != count) || (!count && (n->n < 1 || n->n > max))) {
        if (count)
            return fail(c, n, "expected a list of %zu numbers, got %s", count, kind_name(n));
        return fail(c, n, "expected a list of 1 to %zu numbers, got %s", max, kind_name(n));
    }
    for (size_t k = 0; k < n->n && k < want; k++)
        if (number(c, n->kid[k], -HUGE_VAL, HUGE_VAL, &out[k]))
            return -1;
    if (got)
        *got = n->n;
    return 0;
}

/* The text of a bound: "(0" for an open bound reported as the value next to
 * a round one (demill_param_bounds()), "[0" for a closed one. */
static void bound_text(double v, double towards, int lower, char *buf, size_t len)
{
    char a[40], b[40];
    const double next = nextafter(v, towards);
    snprintf(a, sizeof a, "%.17g", v);
    snprintf(b, sizeof b, "%.17g", next);
    if (strlen(b) < strlen(a))
        snprintf(buf, len, lower ? "(%g" : "%g)", next);
    else
        snprintf(buf, len, lower ? "[%g" : "%g]", v);
}

/* ---- the registry's keys ------------------------------------------------------- */

/* The keys of a group: the registry's names in [first, last] that start
 * with `prefix`, without it. Read-only keys are past each group's settable
 * range (docs: world 150-199, drum 450-499). */
typedef struct group {
    size_t n;
    int32_t key[MAX_NAMES];
    const char *name[MAX_NAMES];
} group;

static void registry(group *g, const char *prefix, int32_t first, int32_t last)
{
    g->n = 0;
    const size_t lp = strlen(prefix);
    for (int32_t k = first; k <= last && g->n < MAX_NAMES; k++) {
        const char *name = demill_param_name(k);
        if (name && !strncmp(name, prefix, lp)) {
            g->key[g->n] = k;
            g->name[g->n++] = name + lp;
        }
    }
}

static void group_world(group *g) { registry(g, "world.", 100, 149); }
static void group_material(group *g) { registry(g, "material.", 200, 299); }
static void group_pair(group *g) { registry(g, "pair.", 300, 399); }
static void group_drum(group *g) { registry(g, "drum.", 400, 449); }

static int32_t group_key(const group *g, const char *name)
{
    for (size_t k = 0; k < g->n; k++)
        if (!strcmp(g->name[k], name))
            return g->key[k];
    return 0;
}

/* Names of the choices of the enum keys (material.h, world.h). */
typedef struct choice {
    int32_t key;
    const char *names[7];
} choice;

static const choice choices[] = {
    {DEMILL_WORLD_INTEGRATOR, {"", "velocity_verlet", "symplectic_euler", "iterative_refinement"}},
    {DEMILL_PAIR_NORMAL, {"none", "linear", "hertz", "thornton", "walton_braun", "plastic_paths"}},
    {DEMILL_PAIR_DAMPING, {"none", "viscous", "restitution"}},
    {DEMILL_PAIR_TANGENTIAL, {"none", "coulomb", "spring", "mindlin"}},
    {DEMILL_PAIR_ROLLING, {"none", "constant_torque", "spring"}},
    {DEMILL_PAIR_COHESION, {"none", "jkr", "capillary"}},
};

static const choice *choice_of(int32_t key)
{
    for (size_t k = 0; k < sizeof choices / sizeof choices[0]; k++)
        if (choices[k].key == key)
            return &choices[k];
    return NULL;
}

/* The value of a registry key's node: a number, a choice's name, or
 * true/false for a switch; checked against the key's bounds. */
static int key_value(ctx *c, const tree *n, int32_t key, double *out)
{
    const choice *ch = choice_of(key);
    if (n->kind == TREE_SCALAR && ch)
        for (int v = 0; v < 7; v++)
            if (ch->names[v] && *ch->names[v] && !strcmp(n->text, ch->names[v])) {
                *out = v;
                return 0;
            }
    const char *unit = demill_param_unit(key);
    if (n->kind == TREE_SCALAR && !strcmp(unit, "bool") &&
        (!strcmp(n->text, "true") || !strcmp(n->text, "false"))) {
        *out = !strcmp(n->text, "true");
        return 0;
    }
    double lo, hi;
    demill_param_bounds(key, &lo, &hi, NULL);
    /* whole numbers and the rest of the key's checks are the setter's */
    if (!to_number(n, out) && *out >= lo && *out <= hi)
        return 0;
    if (ch) {
        char list[256] = "";
        for (int v = 0; v < 7; v++)
            if (ch->names[v] && *ch->names[v])
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s",
                         *list ? ", " : "", ch->names[v]);
        return fail(c, n, "expected one of %s, got '%s'", list, kind_name(n));
    }
    if (!strcmp(unit, "bool"))
        return fail(c, n, "expected true or false, got '%s'", kind_name(n));
    char a[48], b[48], u[40] = "";
    if (strcmp(unit, "1"))
        snprintf(u, sizeof u, " %s", unit);
    bound_text(lo, -HUGE_VAL, 1, a, sizeof a);
    bound_text(hi, HUGE_VAL, 0, b, sizeof b);
    if (hi >= 1e30 && (a[1] == '0' && !a[2]))
        return fail(c, n, "expected a number %s 0%s, got '%s'", a[0] == '(' ? ">" : ">=", u,
                    kind_name(n));
    return fail(c, n, "expected a number in %s, %s%s, got '%s'", a, b, u, kind_name(n));
}

/* A library call that failed on a node: its message, after the node. */
static int api(ctx *c, const tree *n, demill_status st)
{
    if (st == DEMILL_OK)
        return 0;
    /* the library's messages start with the key's or the function's name
     * ("material.density: ", "wall_add_plane: "), which the node's path
     * stands for here */
    const char *msg = demill_world_last_error(c->s->w);
    const size_t word = strspn(msg, "abcdefghijklmnopqrstuvwxyz_.");
    if (word && !strncmp(msg + word, ": ", 2))
        msg += word + 2;
    return fail(c, n, "%s", msg);
}

/* In restart mode only the entries given with --set are applied. */
static int applies(const ctx *c, const tree *n)
{
    return c->mode != SCENE_RESTART || n->line == 0;
}

/* ---- sections ------------------------------------------------------------------ */

static const char *const top_keys[] = {"world", "materials", "pairs", "particles", "walls",
                                       "drum", "bodies", "feeds", "outlets", "outputs", "stop",
                                       "templates"};

static int material_index(ctx *c, const tree *n, size_t *at)
{
    if (n->kind == TREE_SCALAR)
        for (size_t k = 0; k < c->s->nmat; k++)
            if (!strcmp(c->s->matname[k], n->text)) {
                *at = k;
                return 0;
            }
    char list[512] = "";
    for (size_t k = 0; k < c->s->nmat && strlen(list) < 400; k++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", k ? ", " : "",
                 c->s->matname[k]);
    return fail(c, n, "expected a material of 'materials' (%s), got '%s'", *list ? list : "none defined",
                kind_name(n));
}

static int material_of(ctx *c, const tree *item, demill_id *id)
{
    const tree *m = need(c, item, "material");
    size_t k;
    if (!m || material_index(c, m, &k))
        return -1;
    *id = c->s->mat[k];
    return 0;
}

static const char *const world_extra[] = {"dimension", "gravity", "steps_per_contact"};
static const char *const k_pair_extra[] = {"materials"};

/* world: before anything else; a time step of "auto" is set at the end. */
static int world_section(ctx *c, const tree *t, const tree **auto_dt)
{
    scene *s = c->s;
    group g;
    group_world(&g);
    const char *names[MAX_NAMES + 3];
    size_t n = 0;
    for (size_t k = 0; k < 3; k++)
        names[n++] = world_extra[k];
    for (size_t k = 0; k < g.n; k++)
        names[n++] = g.name[k];
    *auto_dt = NULL;
    s->dim = 3;
    if (!t) {
        double have = 3;
        if (c->mode == SCENE_RESTART)
            demill_world_get(s->w, DEMILL_WORLD_DIMENSION, &have);
        else if (demill_world_create(3, &s->w) != DEMILL_OK)
            return fail(c, c->root, "cannot create a world");
        s->dim = (int)have;
        return 0;
    }
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, names, n))
        return -1;
    const tree *d = tree_get(t, "dimension");
    double dim = 3;
    if (d && (to_number(d, &dim) || (dim != 2 && dim != 3)))
        return fail(c, d, "expected 2 or 3, got '%s'", kind_name(d));
    if (c->mode == SCENE_RESTART) {
        double have;
        demill_world_get(s->w, DEMILL_WORLD_DIMENSION, &have);
        if (d && dim != have)
            return fail(c, d, "the checkpoint's world is %gD", have);
        dim = have;
    } else if (demill_world_create((int32_t)dim, &s->w) != DEMILL_OK) {
        return fail(c, t, "cannot create a world");
    }
    s->dim = (int)dim;
    for (size_t k = 0; k < t->n; k++) {
        const tree *e = t->kid[k];
        if (!strcmp(e->key, "dimension") || !applies(c, e))
            continue;
        if (!strcmp(e->key, "gravity")) {
            double gv[3];
            if (numbers(c, e, 3, 3, gv, NULL))
                return -1;
            for (int j = 0; j < 3; j++)
                if (api(c, e, demill_world_set(s->w, DEMILL_WORLD_GRAVITY_X + j, gv[j])))
                    return -1;
        } else if (!strcmp(e->key, "steps_per_contact")) {
            double v;
            if (number(c, e, 1, 1e6, &v))
                return -1;
        } else if (!strcmp(e->key, "time_step") && e->kind == TREE_SCALAR && !e->quoted &&
                   !strcmp(e->text, "auto")) {
            *auto_dt = e;
        } else {
            const int32_t key = group_key(&g, e->key);
            double v;
            if (key_value(c, e, key, &v) || api(c, e, demill_world_set(s->w, key, v)))
                return -1;
        }
    }
    return 0;
}

static int materials_section(ctx *c, const tree *t)
{
    scene *s = c->s;
    s->nmat = 0;
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_MAP))
        return -1;
    if (t->n > SCENE_MAX_MATERIALS)
        return fail(c, t, "expected at most %d materials", SCENE_MAX_MATERIALS);
    demill_id have[SCENE_MAX_MATERIALS];
    size_t nhave = 0;
    if (c->mode == SCENE_RESTART) {
        demill_world_ids(s->w, DEMILL_KIND_MATERIAL, have, SCENE_MAX_MATERIALS, &nhave);
        if (nhave != t->n)
            return fail(c, t, "the checkpoint has %zu materials, the scene %zu", nhave, t->n);
    }
    group g;
    group_material(&g);
    for (size_t k = 0; k < t->n; k++) {
        const tree *m = t->kid[k];
        if (need_kind(c, m, TREE_MAP) || check_keys(c, m, g.name, g.n))
            return -1;
        s->matname[k] = m->key;
        if (c->mode == SCENE_RESTART)
            s->mat[k] = have[k];
        else if (api(c, m, demill_material_create(s->w, &s->mat[k])))
            return -1;
        s->nmat = k + 1;
        for (size_t j = 0; j < m->n; j++) {
            const tree *e = m->kid[j];
            double v;
            if (!applies(c, e))
                continue;
            const int32_t key = group_key(&g, e->key);
            if (key_value(c, e, key, &v) || api(c, e, demill_material_set(s->w, s->mat[k], key, v)))
                return -1;
        }
    }
    return 0;
}

static int pairs_section(ctx *c, const tree *t)
{
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_SEQ))
        return -1;
    group g;
    group_pair(&g);
    const char *names[MAX_NAMES + 1] = {k_pair_extra[0]};
    for (size_t k = 0; k < g.n; k++)
        names[k + 1] = g.name[k];
    for (size_t k = 0; k < t->n; k++) {
        const tree *p = t->kid[k];
        if (need_kind(c, p, TREE_MAP) || check_keys(c, p, names, g.n + 1))
            return -1;
        const tree *m = need(c, p, "materials");
        if (!m)
            return -1;
        size_t a, b;
        if (m->kind != TREE_SEQ || m->n != 2)
            return fail(c, m, "expected a list of two materials, got %s", kind_name(m));
        if (material_index(c, m->kid[0], &a) || material_index(c, m->kid[1], &b))
            return -1;
        for (size_t j = 0; j < p->n; j++) {
            const tree *e = p->kid[j];
            double v;
            if (!strcmp(e->key, "materials") || !applies(c, e))
                continue;
            const int32_t key = group_key(&g, e->key);
            if (key_value(c, e, key, &v) ||
                api(c, e, demill_pair_set(c->s->w, c->s->mat[a], c->s->mat[b], key, v)))
                return -1;
        }
    }
    return 0;
}

static const char *const drum_extra[] = {"material", "start_time", "parts"};
static const char *const k_parts[] = {"shell", "caps", "lifters"}; /* DEMILL_DRUM_PART_* 1-3 */

/* parts: a material of their own for the shell, caps or lifters. */
static int drum_parts(ctx *c, const tree *t)
{
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_parts, 3))
        return -1;
    for (size_t k = 0; k < t->n; k++) {
        const tree *e = t->kid[k];
        size_t m;
        int32_t part = 1;
        while (strcmp(e->key, k_parts[part - 1]))
            part++;
        if (material_index(c, e, &m))
            return -1;
        if (applies(c, e) &&
            api(c, e, demill_drum_set_material(c->s->w, c->s->drum, part, c->s->mat[m])))
            return -1;
    }
    return 0;
}

static int drum_section(ctx *c, const tree *t)
{
    scene *s = c->s;
    s->drum = DEMILL_ID_NONE;
    s->drum_start = 0;
    s->speed_key = 0;
    if (!t)
        return 0;
    group g;
    group_drum(&g);
    const char *names[MAX_NAMES + 3] = {drum_extra[0], drum_extra[1], drum_extra[2]};
    for (size_t k = 0; k < g.n; k++)
        names[k + 3] = g.name[k];
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, names, g.n + 3))
        return -1;
    const tree *st = tree_get(t, "start_time");
    if (st && number(c, st, 0, HUGE_VAL, &s->drum_start))
        return -1;
    if (c->mode == SCENE_RESTART) {
        size_t n = 0;
        demill_world_ids(s->w, DEMILL_KIND_DRUM, &s->drum, 1, &n);
        if (n != 1)
            return fail(c, t, "the checkpoint has no drum");
    } else {
        demill_id m;
        if (material_of(c, t, &m) || api(c, t, demill_drum_create(s->w, m, &s->drum)))
            return -1;
    }
    for (size_t k = 0; k < t->n; k++) {
        const tree *e = t->kid[k];
        if (!strcmp(e->key, "material") || !strcmp(e->key, "start_time"))
            continue;
        if (!strcmp(e->key, "parts")) {
            if (drum_parts(c, e))
                return -1;
            continue;
        }
        const int32_t key = group_key(&g, e->key);
        double v;
        if (key_value(c, e, key, &v))
            return -1;
        if (key == DEMILL_DRUM_SPEED || key == DEMILL_DRUM_SPEED_RPM ||
            key == DEMILL_DRUM_SPEED_FRACTION) {
            if (s->speed_key)
                return fail(c, e, "one speed only (speed, speed_rpm or speed_fraction)");
            s->speed_key = key; /* set at start_time by the runner */
            s->speed_value = v;
            s->speed_set = e->line == 0;
            continue;
        }
        if (applies(c, e) && api(c, e, demill_drum_set(s->w, s->drum, key, v)))
            return -1;
    }
    return 0;
}

static const char *const k_sizes[] = {"classes", "rosin_rammler", "normal"};

/* sizes: one of classes: [[d, fraction], ...], rosin_rammler: [d63, n, d_min,
 * d_max], normal: [mean, sd, d_min, d_max]. */
static int sizes_of(ctx *c, const tree *t, int32_t *dist, double *params, size_t *np)
{

    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_sizes, 3))
        return -1;
    if (t->n != 1)
        return fail(c, t, "expected one of classes, rosin_rammler or normal");
    const tree *e = t->kid[0];
    if (!strcmp(e->key, "classes")) {
        *dist = DEMILL_SIZES_CLASSES;
        if (e->kind != TREE_SEQ || e->n < 1 || e->n > 32)
            return fail(c, e, "expected a list of 1 to 32 [diameter, mass fraction] pairs");
        for (size_t k = 0; k < e->n; k++)
            if (numbers(c, e->kid[k], 2, 2, params + 2 * k, NULL))
                return -1;
        *np = 2 * e->n;
        return 0;
    }
    *dist = !strcmp(e->key, "normal") ? DEMILL_SIZES_NORMAL : DEMILL_SIZES_ROSIN_RAMMLER;
    *np = 4;
    return numbers(c, e, 4, 4, params, NULL);
}

static const char *const k_region[] = {"box", "cylinder", "half_space"};

/* A region: drum, {box: [6]}, {cylinder: [7]} or, where `half` allows it,
 * {half_space: [point, normal]}. */
static int region_of(ctx *c, const tree *t, int half, int32_t *kind, double *params, size_t *np)
{
    if (t->kind == TREE_SCALAR && !strcmp(t->text, "drum")) {
        if (!tree_get(c->root, "drum"))
            return fail(c, t, "the region drum needs a 'drum' section");
        *kind = DEMILL_REGION_DRUM;
        *np = 0;
        return 0;
    }
    if (t->kind != TREE_MAP || t->n != 1)
        return fail(c, t, "expected drum, {box: [x_lo, y_lo, z_lo, x_hi, y_hi, z_hi]}, "
                          "{cylinder: [x0, y0, z0, x1, y1, z1, radius]}%s",
                    half ? " or {half_space: [x, y, z, nx, ny, nz]}" : "");
    if (check_keys(c, t, k_region, half ? 3 : 2))
        return -1;
    const char *k = t->kid[0]->key;
    *kind = !strcmp(k, "box") ? DEMILL_REGION_BOX
            : !strcmp(k, "cylinder") ? DEMILL_REGION_CYLINDER : DEMILL_REGION_HALF_SPACE;
    *np = *kind == DEMILL_REGION_CYLINDER ? 7 : 6;
    return numbers(c, t->kid[0], *np, *np, params, NULL);
}

int scene_region_contains(int32_t kind, const double *r, int dim, const double p[3])
{
    if (kind == DEMILL_REGION_BOX) {
        int in = 1;
        for (int j = 0; j < dim; j++)
            in &= p[j] >= r[j] && p[j] <= r[3 + j];
        return in;
    }
    /* a cylinder: within the radius of the axis, between its ends */
    double axis[3], d[3], len2 = 0, along = 0, off = 0;
    for (int j = 0; j < 3; j++) {
        axis[j] = r[3 + j] - r[j];
        d[j] = p[j] - r[j];
        len2 += axis[j] * axis[j];
        along += d[j] * axis[j];
    }
    along /= len2;
    for (int j = 0; j < 3; j++)
        off += (d[j] - along * axis[j]) * (d[j] - along * axis[j]);
    return along >= 0 && along <= 1 && off <= r[6] * r[6];
}

/* A CSV file of particles: a header naming the columns (x, y, z, radius,
 * vx, vy, vz; z and the velocities optional), then one particle a row. */
static int csv_particles(ctx *c, const tree *n, demill_id mat)
{
    char path[4096];
    if (n->kind != TREE_SCALAR || !*n->text)
        return fail(c, n, "expected a file name, got %s", kind_name(n));
    if (n->text[0] == '/')
        snprintf(path, sizeof path, "%s", n->text);
    else
        snprintf(path, sizeof path, "%s/%s", c->dir, n->text);
    if (c->mode == SCENE_CHECK)
        return 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return fail(c, n, "cannot open %s", path);
    static const char *const cols[] = {"x", "y", "z", "radius", "vx", "vy", "vz"};
    int at[7] = {-1, -1, -1, -1, -1, -1, -1}, ncol = 0;
    char line[4096];
    int rc = -1;
    double *pos = NULL, *rad = NULL, *vel = NULL;
    size_t np = 0, cap = 0;
    long row = 1;
    if (!fgets(line, sizeof line, f)) {
        fail(c, n, "%s: empty", path);
        goto out;
    }
    for (char *save, *tok = strtok_r(line, ",\r\n", &save); tok; tok = strtok_r(NULL, ",\r\n", &save)) {
        while (*tok == ' ')
            tok++;
        int j = 0;
        while (j < 7 && strcmp(tok, cols[j]))
            j++;
        if (j == 7 || at[j] >= 0) {
            fail(c, n, "%s:1: column '%s': expected x, y, z, radius, vx, vy or vz, each once", path, tok);
            goto out;
        }
        at[j] = ncol++;
    }
    if (at[0] < 0 || at[1] < 0 || at[3] < 0) {
        fail(c, n, "%s:1: expected columns x, y and radius at least", path);
        goto out;
    }
    while (fgets(line, sizeof line, f)) {
        row++;
        if (strspn(line, " \r\n") == strlen(line))
            continue;
        double v[7] = {0};
        char *p = line;
        for (int k = 0; k < ncol; k++) {
            char *end;
            const double x = strtod(p, &end);
            if (end == p || !isfinite(x) || (*end != ',' && k + 1 < ncol)) {
                fail(c, n, "%s:%ld: column %d: expected a number", path, row, k + 1);
                goto out;
            }
            for (int j = 0; j < 7; j++)
                if (at[j] == k)
                    v[j] = x;
            p = end + (*end == ',');
        }
        if (np == cap) {
            cap = cap ? 2 * cap : 1024;
            double *a = realloc(pos, 3 * cap * sizeof *a), *b = a ? realloc(rad, cap * sizeof *b) : NULL;
            pos = a ? a : pos;
            rad = b ? b : rad;
            double *d = b ? realloc(vel, 3 * cap * sizeof *d) : NULL;
            vel = d ? d : vel;
            if (!d) {
                fail(c, n, "%s: out of memory", path);
                goto out;
            }
        }
        for (int j = 0; j < 3; j++) {
            pos[3 * np + j] = v[j];
            vel[3 * np + j] = v[4 + j];
        }
        rad[np++] = v[3];
    }
    rc = np ? api(c, n, demill_particles_add(c->s->w, mat, np, pos, rad, vel, 0, NULL))
            : fail(c, n, "%s: no particles", path);
out:
    fclose(f);
    free(pos);
    free(rad);
    free(vel);
    return rc;
}

/* ---- clumps: templates and their fills ------------------------------------------ */

static const char *const k_templates[] = {"material", "spheres", "stl"};
static const char *const k_template_stl[] = {"file", "scale", "spheres", "cells"};

/* Whether n or a node below it was given with --set. */
static int set_within(const tree *n)
{
    if (n->line == 0)
        return 1;
    for (size_t k = 0; k < n->n; k++)
        if (set_within(n->kid[k]))
            return 1;
    return 0;
}

/* A whole number in [lo, hi]. */
static int whole(ctx *c, const tree *n, double lo, double hi, double *out)
{
    if (to_number(n, out) || *out < lo || *out > hi || *out != floor(*out))
        return fail(c, n, "expected a whole number in [%g, %g], got '%s'", lo, hi, kind_name(n));
    return 0;
}

/* A template of spheres, [[x, y, z, r], ...] (demill_clump_template_add),
 * made only when the scene is built (the union's mass properties of many
 * overlapping spheres take long: 13 s of CPU for 400). */
static int template_spheres(ctx *c, const tree *t, demill_id mat, demill_id *id)
{
    if (t->kind != TREE_SEQ || t->n < 1 || t->n > 100000)
        return fail(c, t, "expected a list of 1 to 100000 spheres [x, y, z, radius], got %s",
                    kind_name(t));
    double *xyz = malloc(3 * t->n * sizeof *xyz), *r = malloc(t->n * sizeof *r);
    int rc = xyz && r ? 0 : fail(c, t, "out of memory");
    for (size_t k = 0; k < t->n && !rc; k++) {
        double v[4];
        rc = numbers(c, t->kid[k], 4, 4, v, NULL);
        memcpy(xyz + 3 * k, v, sizeof v - sizeof v[3]);
        r[k] = v[3];
    }
    if (!rc && c->mode == SCENE_BUILD)
        rc = api(c, t, demill_clump_template_add(c->s->w, mat, t->n, xyz, r, id));
    free(xyz);
    free(r);
    return rc;
}

/* A template that fills an STL file's closed mesh with spheres
 * (demill_clump_template_from_stl), read only when the scene is built. */
static int template_stl(ctx *c, const tree *t, demill_id mat, demill_id *id)
{
    const tree *f, *e;
    double scale = 1, n = 0, cells = 64;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_template_stl, 4) ||
        !(f = need(c, t, "file")) || !(e = need(c, t, "spheres")) || whole(c, e, 1, 1e6, &n))
        return -1;
    if (f->kind != TREE_SCALAR || !*f->text)
        return fail(c, f, "expected a file name, got %s", kind_name(f));
    if ((e = tree_get(t, "scale")) && positive(c, e, &scale))
        return -1;
    if ((e = tree_get(t, "cells")) && whole(c, e, 4, 256, &cells))
        return -1;
    if (c->s->dim != 3)
        return fail(c, t, "a template from a mesh needs a 3D world");
    char path[4096];
    snprintf(path, sizeof path, "%s%s%s", f->text[0] == '/' ? "" : c->dir,
             f->text[0] == '/' ? "" : "/", f->text);
    if (c->mode != SCENE_BUILD)
        return 0;
    return api(c, t, demill_clump_template_from_stl(c->s->w, mat, path, scale, (size_t)n, (int)cells, id));
}

/* templates: a map of named clump templates, each of a material and either
 * its spheres or an STL file's mesh filled with spheres. */
static int templates_section(ctx *c, const tree *t)
{
    scene *s = c->s;
    s->ntmpl = 0;
    s->tmpl_counted = c->mode != SCENE_RESTART;
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_MAP))
        return -1;
    if (t->n > SCENE_MAX_TEMPLATES)
        return fail(c, t, "expected at most %d templates", SCENE_MAX_TEMPLATES);
    if (c->mode == SCENE_RESTART) {
        size_t have = 0;
        demill_world_ids(s->w, DEMILL_KIND_TEMPLATE, s->tmpl, SCENE_MAX_TEMPLATES, &have);
        if (have != t->n)
            return fail(c, t, "the checkpoint has %zu templates, the scene %zu", have, t->n);
    }
    for (size_t k = 0; k < t->n; k++) {
        const tree *m = t->kid[k], *sp, *stl;
        demill_id mat;
        if (need_kind(c, m, TREE_MAP) || check_keys(c, m, k_templates, 3))
            return -1;
        if (c->mode == SCENE_RESTART && set_within(m))
            return fail(c, m, "templates cannot change on a restart");
        if (material_of(c, m, &mat))
            return -1;
        sp = tree_get(m, "spheres");
        stl = tree_get(m, "stl");
        if (!!sp == !!stl)
            return fail(c, m, "expected either spheres or stl");
        s->tmplname[k] = m->key;
        if (c->mode != SCENE_RESTART)
            s->tmpl[k] = DEMILL_ID_NONE;
        s->tmpl_clumps[k] = 0;
        s->ntmpl = k + 1;
        if (sp ? template_spheres(c, sp, mat, &s->tmpl[k]) : template_stl(c, stl, mat, &s->tmpl[k]))
            return -1;
    }
    return 0;
}

static int template_index(ctx *c, const tree *n, size_t *at)
{
    for (size_t k = 0; n->kind == TREE_SCALAR && k < c->s->ntmpl; k++)
        if (!strcmp(c->s->tmplname[k], n->text)) {
            *at = k;
            return 0;
        }
    char list[512] = "";
    for (size_t k = 0; k < c->s->ntmpl && strlen(list) < 400; k++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", k ? ", " : "",
                 c->s->tmplname[k]);
    return fail(c, n, "expected a template of 'templates' (%s), got '%s'",
                *list ? list : "none defined", kind_name(n));
}

/* splitmix64 (Steele, Lea and Flood 2014, Fast splittable pseudorandom
 * number generators): the random order of a mix's clumps. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* A clump fill (demill_clump_fill_region): `template` names one template,
 * or is a list of [template, mass fraction] pairs, a mix. A mix's target is
 * shared by mass: a mass M gives template k the mass f_k M, a count N the
 * counts n_k ∝ f_k / m_k (m_k a clump's mass), by largest remainder, and a
 * fraction J the volume share J (f_k / ρ_k) / Σ (f_j / ρ_j), ρ_k = m_k / V_k;
 * each template's clumps are those its share asks of
 * demill_clump_fill_region. They are placed in a seeded random order of
 * their templates, as demill_fill_region() mixes its sizes, each run of
 * clumps of one template in that order by a call of its own (its own seed,
 * drawn from the item's). */
static int clump_fill(ctx *c, const tree *tm, int32_t kind, const double *rp, size_t nr,
                      int32_t target, double value, uint64_t seed)
{
    scene *s = c->s;
    size_t which[SCENE_MAX_TEMPLATES], nt = 1;
    double frac[SCENE_MAX_TEMPLATES] = {1}, sum = 0;
    if (tm->kind == TREE_SEQ) {
        if (tm->n < 1 || tm->n > SCENE_MAX_TEMPLATES)
            return fail(c, tm, "expected a list of 1 to %d [template, mass fraction] pairs",
                        SCENE_MAX_TEMPLATES);
        nt = tm->n;
        for (size_t k = 0; k < nt; k++) {
            const tree *pr = tm->kid[k];
            if (pr->kind != TREE_SEQ || pr->n != 2)
                return fail(c, pr, "expected a pair [template, mass fraction], got %s", kind_name(pr));
            if (template_index(c, pr->kid[0], &which[k]) ||
                number(c, pr->kid[1], 0, HUGE_VAL, &frac[k]))
                return -1;
            for (size_t j = 0; j < k; j++)
                if (which[j] == which[k])
                    return fail(c, pr->kid[0], "template '%s' given twice", pr->kid[0]->text);
            sum += frac[k];
        }
        if (!(sum > 0))
            return fail(c, tm, "the mass fractions sum to 0");
    } else if (template_index(c, tm, &which[0])) {
        return -1;
    }
    if (c->mode != SCENE_BUILD)
        return 0;
    demill_world *w = s->w;
    size_t added = 0;
    if (nt == 1) {
        if (api(c, tm, demill_clump_fill_region(w, kind, rp, nr, s->tmpl[which[0]], target, value,
                                                seed, NULL, 0, &added)))
            return -1;
        s->tmpl_clumps[which[0]] += added;
        return 0;
    }
    /* each template's clumps */
    double m[SCENE_MAX_TEMPLATES], share[SCENE_MAX_TEMPLATES], ssum = 0;
    size_t n[SCENE_MAX_TEMPLATES];
    for (size_t k = 0; k < nt; k++) {
        double v;
        demill_clump_template_get(w, s->tmpl[which[k]], DEMILL_TEMPLATE_MASS, &m[k]);
        demill_clump_template_get(w, s->tmpl[which[k]], DEMILL_TEMPLATE_VOLUME, &v);
        share[k] = frac[k] / (target == DEMILL_FILL_FRACTION ? m[k] / v : m[k]);
        ssum += share[k];
    }
    if (target == DEMILL_FILL_COUNT) {
        double rem[SCENE_MAX_TEMPLATES];
        size_t total = 0;
        for (size_t k = 0; k < nt; k++) {
            const double x = value * share[k] / ssum;
            n[k] = (size_t)floor(x);
            rem[k] = x - floor(x);
            total += n[k];
        }
        for (size_t it = 0; it < nt && (double)total + 0.5 < value; it++, total++) {
            size_t best = 0;
            for (size_t k = 1; k < nt; k++)
                best = rem[k] > rem[best] ? k : best;
            n[best]++;
            rem[best] = -1;
        }
    } else {
        /* the clumps the share asks for: the count a fill would add, which
         * it reports, adding nothing, when the ids' buffer is too small */
        for (size_t k = 0; k < nt; k++) {
            demill_id none;
            const double v = target == DEMILL_FILL_MASS ? value * frac[k] / sum : value * share[k] / ssum;
            n[k] = 0;
            if (!(frac[k] > 0))
                continue;
            const demill_status st = demill_clump_fill_region(w, kind, rp, nr, s->tmpl[which[k]],
                                                              target, v, seed, &none, 0, &n[k]);
            if (st != DEMILL_ERR_BUFFER_TOO_SMALL) {
                api(c, tm->kid[k], st);
                return -1;
            }
        }
    }
    size_t total = 0;
    for (size_t k = 0; k < nt; k++)
        total += n[k];
    if (!total)
        return fail(c, tm, "the target asks for no clump");
    unsigned char *order = malloc(total);
    if (!order)
        return fail(c, tm, "out of memory");
    uint64_t state = seed;
    for (size_t k = 0, at = 0; k < nt; k++)
        for (size_t j = 0; j < n[k]; j++)
            order[at++] = (unsigned char)k;
    for (size_t k = total - 1; k > 0; k--) {
        const size_t j = (size_t)(splitmix64(&state) % (k + 1));
        const unsigned char t = order[k];
        order[k] = order[j];
        order[j] = t;
    }
    int rc = 0;
    for (size_t i = 0, j; i < total && !rc; i = j) {
        const size_t k = order[i];
        for (j = i; j < total && order[j] == k; j++)
            ;
        rc = api(c, tm->kid[k], demill_clump_fill_region(w, kind, rp, nr, s->tmpl[which[k]],
                                                         DEMILL_FILL_COUNT, (double)(j - i),
                                                         splitmix64(&state), NULL, 0, &added));
        s->tmpl_clumps[which[k]] += rc ? 0 : added;
    }
    free(order);
    return rc;
}

static const char *const k_particles[] = {"material", "csv",   "region",   "sizes",
                                          "count",    "mass",  "fraction", "seed", "template"};

static int particles_section(ctx *c, const tree *t)
{

    if (!t)
        return 0;
    if (need_kind(c, t, TREE_SEQ))
        return -1;
    for (size_t k = 0; k < t->n; k++) {
        const tree *p = t->kid[k];
        demill_id mat = DEMILL_ID_NONE;
        if (need_kind(c, p, TREE_MAP) || check_keys(c, p, k_particles, 9))
            return -1;
        if (c->mode == SCENE_RESTART && applies(c, p) )
            return fail(c, p, "particles cannot change on a restart");
        const tree *tm = tree_get(p, "template");
        if (tm && (tree_get(p, "material") || tree_get(p, "sizes") || tree_get(p, "csv")))
            return fail(c, p, "a fill of clumps has no material, sizes or csv: its templates give them");
        if (!tm && material_of(c, p, &mat))
            return -1;
        const tree *csv = tree_get(p, "csv"), *region = tree_get(p, "region");
        if (!!csv == !!region)
            return fail(c, p, "expected either csv or region");
        if (csv) {
            if (p->n != 2)
                return fail(c, p, "a csv entry has material and csv only");
            if (c->mode != SCENE_RESTART && csv_particles(c, csv, mat))
                return -1;
            continue;
        }
        int32_t kind = 0, dist = 0, target = 0;
        double rp[7], sp[64], value = 0, seed = 1;
        size_t nr = 0, ns = 0;
        const tree *sz = tm ? NULL : need(c, p, "sizes");
        if (region_of(c, region, 0, &kind, rp, &nr) || (!tm && (!sz || sizes_of(c, sz, &dist, sp, &ns))))
            return -1;
        static const char *const targets[] = {"count", "mass", "fraction"};
        for (int j = 0; j < 3; j++) {
            const tree *v = tree_get(p, targets[j]);
            if (!v)
                continue;
            if (target)
                return fail(c, v, "one of count, mass or fraction only");
            target = j + 1; /* DEMILL_FILL_COUNT, _MASS, _FRACTION */
            if (positive(c, v, &value))
                return -1;
        }
        if (!target)
            return fail(c, p, "missing one of count, mass or fraction");
        const tree *sd = tree_get(p, "seed");
        if (sd && (number(c, sd, 0, 9007199254740992.0, &seed) || seed != floor(seed)))
            return fail(c, sd, "expected a whole number >= 0, got '%s'", kind_name(sd));
        if (tm) {
            if (clump_fill(c, tm, kind, rp, nr, target, value, (uint64_t)seed))
                return -1;
            continue;
        }
        if (c->mode != SCENE_BUILD)
            continue;
        if (api(c, p, demill_fill_region(c->s->w, kind, rp, nr, mat, dist, sp, ns, target, value,
                                         (uint64_t)seed, NULL, 0, NULL)))
            return -1;
    }
    return 0;
}

static const char *const k_motion[] = {"velocity", "angular_velocity", "centre", "start"};

static const char *const k_harmonic[] = {"mode", "axis", "amplitude", "frequency", "phase"};

static int motion_of(ctx *c, const tree *wall, size_t index, demill_id id)
{
    const tree *m = tree_get(wall, "motion"), *h = tree_get(wall, "harmonic"),
               *sv = tree_get(wall, "surface_velocity");
    if (m && h)
        return fail(c, h, "a wall has motion or harmonic, not both");
    if (m) {

        double v[3][3], start = 0, now = 0;
        const tree *e[3], *st = tree_get(m, "start");
        if (need_kind(c, m, TREE_MAP) || check_keys(c, m, k_motion, 4))
            return -1;
        for (int j = 0; j < 3; j++)
            if ((e[j] = tree_get(m, k_motion[j])) && numbers(c, e[j], 3, 3, v[j], NULL))
                return -1;
        if (st && number(c, st, 0, HUGE_VAL, &start))
            return -1;
        /* a motion from a later time: set by the runner when it comes */
        if (c->mode == SCENE_RESTART && (demill_world_get(c->s->w, DEMILL_WORLD_TIME, &now), start > now))
            return fail(c, st, "the motion starts at %g s, after the checkpoint's %g s: a restart "
                               "cannot start it", start, now);
        if (start > 0 && c->mode == SCENE_BUILD) {
            if (c->s->nmotion == SCENE_MAX_MOTIONS)
                return fail(c, st, "at most %d walls' motions may start late", SCENE_MAX_MOTIONS);
            scene_motion *mo = &c->s->motion[c->s->nmotion++];
            *mo = (scene_motion){id, (int)index, start, {{0}}, {e[0] != NULL, e[1] != NULL, e[2] != NULL}, 0};
            memcpy(mo->v, v, sizeof v);
        } else if (c->mode == SCENE_BUILD &&
                   api(c, m, demill_wall_set_motion(c->s->w, id, e[0] ? v[0] : NULL,
                                                    e[1] ? v[1] : NULL, e[2] ? v[2] : NULL)))
            return -1;
    }
    if (h) {

        double axis[3], amp, freq, phase = 0;
        if (need_kind(c, h, TREE_MAP) || check_keys(c, h, k_harmonic, 5))
            return -1;
        const tree *mode = need(c, h, "mode"), *ax = need(c, h, "axis"),
                   *a = need(c, h, "amplitude"), *fr = need(c, h, "frequency"),
                   *ph = tree_get(h, "phase");
        if (!mode || !ax || !a || !fr)
            return -1;
        int32_t md;
        if (mode->kind == TREE_SCALAR && !strcmp(mode->text, "translation"))
            md = DEMILL_HARMONIC_TRANSLATION;
        else if (mode->kind == TREE_SCALAR && !strcmp(mode->text, "rotation"))
            md = DEMILL_HARMONIC_ROTATION;
        else
            return fail(c, mode, "expected translation or rotation, got '%s'", kind_name(mode));
        if (numbers(c, ax, 3, 3, axis, NULL) || number(c, a, -HUGE_VAL, HUGE_VAL, &amp) ||
            positive(c, fr, &freq) || (ph && number(c, ph, -HUGE_VAL, HUGE_VAL, &phase)))
            return -1;
        if (c->mode == SCENE_BUILD &&
            api(c, h, demill_wall_set_harmonic(c->s->w, id, md, axis, amp, freq, phase)))
            return -1;
    }
    if (sv) {
        double v[3];
        if (numbers(c, sv, 3, 3, v, NULL) ||
            (c->mode == SCENE_BUILD && api(c, sv, demill_wall_set_surface_velocity(c->s->w, id, v))))
            return -1;
    }
    return 0;
}

static const char *const k_bodies[] = {"mass", "centre", "free_axes", "gravity", "springs", "force",
                                       "load"};
static const char *const k_spring[] = {"axis", "stiffness", "damping", "rest"};
static const char *const k_force[] = {"amplitude", "frequency", "phase"};
static const char *const k_load[] = {"force", "start", "ramp"};
static const char *const k_axes[] = {"x", "y", "z"};

/* An axis's name: 0 for x, 1 for y, 2 for z; -1 with a message. */
static int axis_of(ctx *c, const tree *n)
{
    for (int k = 0; k < 3; k++)
        if (n->kind == TREE_SCALAR && !strcmp(n->text, k_axes[k]))
            return k;
    return fail(c, n, "expected x, y or z, got '%s'", kind_name(n));
}

/* The index in 'bodies' of the body named by n: 0, or -1 with a message. */
static int body_index(ctx *c, const tree *n, int *at)
{
    for (size_t j = 0; j < c->s->nbody; j++)
        if (n->kind == TREE_SCALAR && !strcmp(n->text, c->s->bodyname[j])) {
            *at = (int)j;
            return 0;
        }
    return fail(c, n, "expected a body of 'bodies', got '%s'", kind_name(n));
}

/* bodies: a map of named bodies (demill/body.h), before the walls that
 * name them. */
static int bodies_section(ctx *c, const tree *t)
{
    scene *s = c->s;
    s->nbody = 0;
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_MAP))
        return -1;
    if (t->n > SCENE_MAX_BODIES)
        return fail(c, t, "expected at most %d bodies", SCENE_MAX_BODIES);
    if (c->mode == SCENE_RESTART) {
        size_t have = 0;
        demill_world_ids(s->w, DEMILL_KIND_BODY, s->body, SCENE_MAX_BODIES, &have);
        if (have != t->n)
            return fail(c, t, "the checkpoint has %zu bodies, the scene %zu", have, t->n);
    }
    for (size_t k = 0; k < t->n; k++) {
        const tree *b = t->kid[k], *e;
        double mass, centre[3] = {0, 0, 0};
        int32_t axes = 0;
        uint32_t flags = 0;
        if (need_kind(c, b, TREE_MAP) || check_keys(c, b, k_bodies, sizeof k_bodies / sizeof k_bodies[0]))
            return -1;
        if (c->mode == SCENE_RESTART && applies(c, b))
            return fail(c, b, "bodies cannot change on a restart");
        s->bodyname[k] = b->key;
        s->nbody = k + 1;
        if (!(e = need(c, b, "mass")) || positive(c, e, &mass))
            return -1;
        if ((e = tree_get(b, "centre")) && numbers(c, e, 3, 3, centre, NULL))
            return -1;
        if ((e = tree_get(b, "free_axes"))) {
            if (e->kind != TREE_SEQ)
                return fail(c, e, "expected a list of axes (x, y, z), got %s", kind_name(e));
            for (size_t j = 0; j < e->n; j++) {
                const int ax = axis_of(c, e->kid[j]);
                if (ax < 0)
                    return -1;
                axes |= DEMILL_BODY_AXIS_X << ax;
            }
        }
        if ((e = tree_get(b, "gravity"))) {
            if (e->kind != TREE_SCALAR || (strcmp(e->text, "true") && strcmp(e->text, "false")))
                return fail(c, e, "expected true or false, got '%s'", kind_name(e));
            flags = strcmp(e->text, "true") ? DEMILL_BODY_NO_GRAVITY : 0;
        }
        if (c->mode != SCENE_RESTART &&
            api(c, b, demill_body_add(s->w, mass, centre, axes, flags, &s->body[k])))
            return -1;
        if ((e = tree_get(b, "springs"))) {
            if (e->kind != TREE_SEQ)
                return fail(c, e, "expected a list of springs, got %s", kind_name(e));
            for (size_t j = 0; j < e->n; j++) {
                const tree *sp = e->kid[j], *ax, *st, *dm, *rs;
                double v[3] = {0, 0, 0};
                int a;
                if (need_kind(c, sp, TREE_MAP) || check_keys(c, sp, k_spring, 4) ||
                    !(ax = need(c, sp, "axis")) || (a = axis_of(c, ax)) < 0 ||
                    !(st = need(c, sp, "stiffness")) || number(c, st, 0, HUGE_VAL, &v[0]) ||
                    ((dm = tree_get(sp, "damping")) && number(c, dm, 0, HUGE_VAL, &v[1])) ||
                    ((rs = tree_get(sp, "rest")) && number(c, rs, -HUGE_VAL, HUGE_VAL, &v[2])))
                    return -1;
                if (c->mode != SCENE_RESTART &&
                    api(c, sp, demill_body_set_spring(s->w, s->body[k], DEMILL_BODY_AXIS_X << a, v[0],
                                                      v[1], v[2])))
                    return -1;
            }
        }
        if ((e = tree_get(b, "force"))) {
            const tree *am, *fr, *ph;
            double amp[3], freq, phase = 0;
            if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_force, 3) ||
                !(am = need(c, e, "amplitude")) || numbers(c, am, 3, 3, amp, NULL) ||
                !(fr = need(c, e, "frequency")) || number(c, fr, 0, HUGE_VAL, &freq) ||
                ((ph = tree_get(e, "phase")) && number(c, ph, -HUGE_VAL, HUGE_VAL, &phase)))
                return -1;
            if (c->mode != SCENE_RESTART &&
                api(c, e, demill_body_set_force(s->w, s->body[k], amp, freq, phase)))
                return -1;
        }
        s->load[k].on = 0;
        if ((e = tree_get(b, "load"))) {
            /* a constant force from start, reached over ramp: the runner sets
             * it, at the samples where it changes, as the external force of
             * frequency 0 */
            const tree *f, *st, *rp;
            scene_load *ld = &s->load[k];
            ld->start = ld->ramp = ld->applied = 0;
            if (tree_get(b, "force"))
                return fail(c, e, "a body has a force or a load, not both");
            if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_load, 3) ||
                !(f = need(c, e, "force")) || numbers(c, f, 3, 3, ld->force, NULL) ||
                ((st = tree_get(e, "start")) && number(c, st, 0, HUGE_VAL, &ld->start)) ||
                ((rp = tree_get(e, "ramp")) && number(c, rp, 0, HUGE_VAL, &ld->ramp)))
                return -1;
            ld->on = 1;
        }
    }
    return 0;
}

/* The wall shapes: their vectors (3 numbers each), then their numbers;
 * keys past `required` are optional (0, or no caps). */
typedef struct shape {
    const char *name;
    int nvec, nnum, required, caps;
    const char *keys[6];
} shape;

static const shape shapes[] = {
    {"plane", 2, 0, 2, 0, {"point", "normal"}},
    {"rectangle", 3, 2, 5, 0, {"centre", "normal", "direction", "half_width", "half_height"}},
    {"disc", 2, 2, 3, 0, {"centre", "normal", "outer_radius", "inner_radius"}},
    {"cylinder", 2, 2, 4, 1, {"point", "axis", "radius", "length", "caps"}},
    {"cone", 2, 3, 5, 1, {"point", "axis", "radius_start", "radius_end", "length", "caps"}},
};
#define NSHAPES (sizeof shapes / sizeof shapes[0])
static const char *const k_caps[] = {"none", "start", "end", "both"};
static const char *const k_stl[] = {"file", "scale", "transform"};
static const char *const k_polyline[] = {"points", "closed"};
static const char *const k_walls[] = {"material", "plane",  "rectangle", "disc",
                                      "cylinder", "cone",   "stl",       "polyline",
                                      "motion",   "harmonic", "surface_velocity", "body"};

static int add_shape(ctx *c, const shape *sh, const tree *t, demill_id mat, demill_id *id)
{
    double v[3][3] = {{0}}, x[3] = {0};
    int32_t caps = DEMILL_CAPS_NONE;
    const int nkeys = sh->nvec + sh->nnum + sh->caps;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, sh->keys, (size_t)nkeys))
        return -1;
    for (int k = 0; k < nkeys; k++) {
        const tree *e = k < sh->required ? need(c, t, sh->keys[k]) : tree_get(t, sh->keys[k]);
        if (k < sh->required && !e)
            return -1;
        if (!e)
            continue;
        if (k < sh->nvec) {
            if (numbers(c, e, 3, 3, v[k], NULL))
                return -1;
        } else if (k < sh->nvec + sh->nnum) {
            if (number(c, e, -HUGE_VAL, HUGE_VAL, &x[k - sh->nvec]))
                return -1;
        } else {
            while (caps < 4 && (e->kind != TREE_SCALAR || strcmp(e->text, k_caps[caps])))
                caps++;
            if (caps == 4)
                return fail(c, e, "expected none, start, end or both, got '%s'", kind_name(e));
        }
    }
    if (c->mode != SCENE_BUILD)
        return 0;
    demill_world *w = c->s->w;
    demill_status st;
    switch (sh - shapes) {
    case 0: st = demill_wall_add_plane(w, mat, v[0], v[1], id); break;
    case 1: st = demill_wall_add_rectangle(w, mat, v[0], v[1], v[2], x[0], x[1], id); break;
    case 2: st = demill_wall_add_disc(w, mat, v[0], v[1], x[0], x[1], id); break;
    case 3: st = demill_wall_add_cylinder(w, mat, v[0], v[1], x[0], x[1], caps, id); break;
    default: st = demill_wall_add_cone(w, mat, v[0], v[1], x[0], x[1], x[2], caps, id); break;
    }
    return api(c, t, st);
}

static int add_stl(ctx *c, const tree *stl, demill_id mat, demill_id *id)
{
    double scale = 1, tr[12];
    const tree *f, *sc, *tf;
    if (need_kind(c, stl, TREE_MAP) || check_keys(c, stl, k_stl, 3) || !(f = need(c, stl, "file")))
        return -1;
    if (f->kind != TREE_SCALAR || !*f->text)
        return fail(c, f, "expected a file name, got %s", kind_name(f));
    if ((sc = tree_get(stl, "scale")) && positive(c, sc, &scale))
        return -1;
    if ((tf = tree_get(stl, "transform")) && numbers(c, tf, 12, 12, tr, NULL))
        return -1;
    char path[4096];
    snprintf(path, sizeof path, "%s%s%s", f->text[0] == '/' ? "" : c->dir,
             f->text[0] == '/' ? "" : "/", f->text);
    if (c->mode != SCENE_BUILD)
        return 0;
    return api(c, stl, demill_wall_load_stl(c->s->w, mat, path, scale, tf ? tr : NULL, id));
}

/* A 2D polyline: points [[x, y, 0], ...], closed or not. */
static int add_polyline(ctx *c, const tree *t, demill_id mat, demill_id *id)
{
    const tree *pts, *cl;
    int closed = 0;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_polyline, 2) || !(pts = need(c, t, "points")))
        return -1;
    if (pts->kind != TREE_SEQ || pts->n < 2 || pts->n > 100000)
        return fail(c, pts, "expected a list of 2 to 100000 points [x, y, 0], got %s", kind_name(pts));
    if ((cl = tree_get(t, "closed"))) {
        if (cl->kind != TREE_SCALAR || (strcmp(cl->text, "true") && strcmp(cl->text, "false")))
            return fail(c, cl, "expected true or false, got '%s'", kind_name(cl));
        closed = !strcmp(cl->text, "true");
    }
    double *xyz = malloc(3 * pts->n * sizeof *xyz);
    if (!xyz)
        return fail(c, t, "out of memory");
    int rc = 0;
    for (size_t k = 0; k < pts->n && !rc; k++)
        rc = numbers(c, pts->kid[k], 3, 3, xyz + 3 * k, NULL);
    if (!rc && c->mode == SCENE_BUILD)
        rc = api(c, t, demill_wall_add_polyline(c->s->w, mat, pts->n, xyz, closed, id));
    free(xyz);
    return rc;
}

static int walls_section(ctx *c, const tree *t)
{
    c->s->nmotion = 0;
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_SEQ))
        return -1;
    for (size_t k = 0; k < t->n; k++) {
        const tree *wl = t->kid[k];
        demill_id mat, id = DEMILL_ID_NONE;
        if (need_kind(c, wl, TREE_MAP) || check_keys(c, wl, k_walls, sizeof k_walls / sizeof k_walls[0]))
            return -1;
        if (c->mode == SCENE_RESTART && applies(c, wl))
            return fail(c, wl, "walls cannot change on a restart");
        if (material_of(c, wl, &mat))
            return -1;
        const tree *geometry = NULL;
        size_t which = NSHAPES; /* NSHAPES: stl; NSHAPES + 1: polyline */
        for (size_t j = 0; j <= NSHAPES + 1; j++) {
            const tree *g = tree_get(wl, j < NSHAPES ? shapes[j].name : j == NSHAPES ? "stl" : "polyline");
            if (g && geometry)
                return fail(c, g, "a wall has one shape (plane, rectangle, disc, cylinder, cone, stl or "
                                  "polyline)");
            if (g) {
                geometry = g;
                which = j;
            }
        }
        if (!geometry)
            return fail(c, wl, "missing its shape: plane, rectangle, disc, cylinder, cone, stl or polyline");
        if (which < NSHAPES ? add_shape(c, &shapes[which], geometry, mat, &id)
            : which == NSHAPES ? add_stl(c, geometry, mat, &id)
                               : add_polyline(c, geometry, mat, &id))
            return -1;
        if (motion_of(c, wl, k, id))
            return -1;
        const tree *b = tree_get(wl, "body");
        if (b) {
            int j = 0;
            if (body_index(c, b, &j) ||
                (c->mode == SCENE_BUILD && api(c, b, demill_body_attach_wall(c->s->w, c->s->body[j], id))))
                return -1;
        }
    }
    return 0;
}

static const char *const k_feeds[] = {"material", "region", "sizes", "mass_rate", "velocity",
                                      "start", "stop", "seed"};
static const char *const k_outlets[] = {"region", "edges", "interval"};

static int feeds_section(ctx *c, const tree *t)
{
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_SEQ))
        return -1;
    for (size_t k = 0; k < t->n; k++) {
        const tree *f = t->kid[k], *e;
        demill_id mat, id;
        int32_t kind = 0, dist = 0;
        double rp[7], sp[64], rate, vel[3] = {0, 0, 0}, start = 0, stop = INFINITY, seed = 1;
        size_t nr = 0, ns = 0;
        if (need_kind(c, f, TREE_MAP) || check_keys(c, f, k_feeds, sizeof k_feeds / sizeof k_feeds[0]))
            return -1;
        if (c->mode == SCENE_RESTART && applies(c, f))
            return fail(c, f, "feeds cannot change on a restart");
        const tree *region = need(c, f, "region"), *sz = region ? need(c, f, "sizes") : NULL,
                   *mr = sz ? need(c, f, "mass_rate") : NULL;
        if (!mr || material_of(c, f, &mat) || region_of(c, region, 0, &kind, rp, &nr) ||
            sizes_of(c, sz, &dist, sp, &ns) || positive(c, mr, &rate))
            return -1;
        if ((e = tree_get(f, "velocity")) && numbers(c, e, 3, 3, vel, NULL))
            return -1;
        if ((e = tree_get(f, "start")) && number(c, e, -HUGE_VAL, HUGE_VAL, &start))
            return -1;
        if ((e = tree_get(f, "stop")) && number(c, e, start, HUGE_VAL, &stop))
            return -1;
        if ((e = tree_get(f, "seed")) && (number(c, e, 0, 9007199254740992.0, &seed) || seed != floor(seed)))
            return fail(c, e, "expected a whole number >= 0, got '%s'", kind_name(e));
        if (c->mode == SCENE_BUILD &&
            api(c, f, demill_feed_create(c->s->w, kind, rp, nr, mat, dist, sp, ns, rate, vel, start,
                                         stop, (uint64_t)seed, &id)))
            return -1;
    }
    return 0;
}

static int outlets_section(ctx *c, const tree *t)
{
    c->s->noutlets = 0;
    if (!t)
        return 0;
    if (need_kind(c, t, TREE_SEQ))
        return -1;
    if (t->n > SCENE_MAX_OUTLETS)
        return fail(c, t, "expected at most %d outlets", SCENE_MAX_OUTLETS);
    for (size_t k = 0; k < t->n; k++) {
        const tree *o = t->kid[k], *e;
        int32_t kind = 0;
        double rp[7], edges[31], interval = 0.1;
        size_t nr = 0, ne = 0;
        if (need_kind(c, o, TREE_MAP) || check_keys(c, o, k_outlets, 3))
            return -1;
        if (c->mode == SCENE_RESTART && applies(c, o))
            return fail(c, o, "outlets cannot change on a restart");
        const tree *region = need(c, o, "region");
        if (!region || region_of(c, region, 1, &kind, rp, &nr))
            return -1;
        if ((e = tree_get(o, "edges")) && numbers(c, e, 0, 31, edges, &ne))
            return -1;
        if ((e = tree_get(o, "interval")) && positive(c, e, &interval))
            return -1;
        if (c->mode == SCENE_BUILD &&
            api(c, o, demill_outlet_create(c->s->w, kind, rp, nr, ne, edges, interval,
                                           &c->s->outlet[k])))
            return -1;
        c->s->noutlets = c->mode == SCENE_BUILD ? k + 1 : 0;
    }
    if (c->mode == SCENE_RESTART) {
        /* the checkpoint's outlets, made from this list in its order */
        size_t have = 0;
        if (demill_world_ids(c->s->w, DEMILL_KIND_OUTLET, c->s->outlet, SCENE_MAX_OUTLETS,
                             &have) != DEMILL_OK || have != t->n)
            return fail(c, t, "the checkpoint has %zu outlets, the scene %zu", have, t->n);
        c->s->noutlets = have;
    }
    return 0;
}

/* The bodies' fields by name, with the components x, y and z. */
static const struct {
    const char *name;
    int32_t field;
} body_fields[] = {{"position", DEMILL_BODY_POSITION},
                   {"velocity", DEMILL_BODY_VELOCITY},
                   {"force_particles", DEMILL_BODY_FORCE_PARTICLES},
                   {"force_spring", DEMILL_BODY_FORCE_SPRING},
                   {"force_damper", DEMILL_BODY_FORCE_DAMPER},
                   {"force_external", DEMILL_BODY_FORCE_EXTERNAL}};

/* The energy terms of demill_world_energy() as quantities, energy.NAME. */
static const struct {
    const char *name;
    int32_t term;
} energy_terms[] = {{"kinetic_translational", DEMILL_ENERGY_KINETIC_TRANSLATIONAL},
                    {"kinetic_rotational", DEMILL_ENERGY_KINETIC_ROTATIONAL},
                    {"potential", DEMILL_ENERGY_POTENTIAL},
                    {"elastic_normal", DEMILL_ENERGY_ELASTIC_NORMAL},
                    {"elastic_tangential", DEMILL_ENERGY_ELASTIC_TANGENTIAL},
                    {"elastic_rolling", DEMILL_ENERGY_ELASTIC_ROLLING},
                    {"wall_work", DEMILL_ENERGY_WALL_WORK},
                    {"dissipated_normal", DEMILL_ENERGY_DISSIPATED_NORMAL},
                    {"dissipated_tangential", DEMILL_ENERGY_DISSIPATED_TANGENTIAL},
                    {"dissipated_friction", DEMILL_ENERGY_DISSIPATED_FRICTION},
                    {"dissipated_rolling", DEMILL_ENERGY_DISSIPATED_ROLLING},
                    {"dissipated_plastic", DEMILL_ENERGY_DISSIPATED_PLASTIC},
                    {"dissipated_rolling_viscous", DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS},
                    {"dissipated_local", DEMILL_ENERGY_DISSIPATED_LOCAL},
                    {"dissipated", DEMILL_ENERGY_DISSIPATED},
                    {"cohesion", DEMILL_ENERGY_COHESION},
                    {"total", DEMILL_ENERGY_TOTAL},
                    {"flow", DEMILL_ENERGY_FLOW},
                    {"body_kinetic", DEMILL_ENERGY_BODY_KINETIC},
                    {"body_elastic", DEMILL_ENERGY_BODY_ELASTIC},
                    {"body_potential", DEMILL_ENERGY_BODY_POTENTIAL},
                    {"body_dissipated", DEMILL_ENERGY_BODY_DISSIPATED},
                    {"body_work", DEMILL_ENERGY_BODY_WORK}};

const char *scene_energy_name(int32_t term)
{
    for (size_t k = 0; k < sizeof energy_terms / sizeof energy_terms[0]; k++)
        if (energy_terms[k].term == term)
            return energy_terms[k].name;
    return NULL;
}

/* outlet.N.mass or outlet.N.count: N's index into outlets[] in *index
 * and 1 for count in *count; 0 if n names one, else -1. */
static int outlet_quantity(const char *n, int *index, int *count)
{
    char *end;
    if (strncmp(n, "outlet.", 7) || !isdigit((unsigned char)n[7]))
        return -1;
    const long k = strtol(n + 7, &end, 10);
    if (k >= SCENE_MAX_OUTLETS || (strcmp(end, ".mass") && strcmp(end, ".count")))
        return -1;
    *index = (int)k;
    *count = !strcmp(end, ".count");
    return 0;
}

/* A quantity by name: a world.* or drum.* key of the registry,
 * body.NAME.FIELD_C (FIELD a body field, C x, y or z), outlet.N.mass and
 * outlet.N.count (what outlets[N] has removed since it was made),
 * particles.centre_C (the particles' centre of mass) or energy.NAME (a term
 * of the energy account, demill_world_energy()). */
static int quantity_of(ctx *c, const tree *n, scene_quantity *q)
{
    *q = (scene_quantity){.body = -1, .outlet = -1};
    if (n->kind == TREE_SCALAR) {
        q->name = n->text;
        for (int32_t k = 100; k < 500 && !q->key; k++) {
            const char *name = demill_param_name(k);
            if (name && !strcmp(name, n->text) && (k < 200 || k >= 400))
                q->key = k;
        }
        if (q->key >= 400 && !tree_get(c->root, "drum"))
            return fail(c, n, "a drum quantity without a drum");
        if (q->key)
            return 0;
        for (size_t k = 0; k < sizeof energy_terms / sizeof energy_terms[0]; k++)
            if (!strncmp(n->text, "energy.", 7) && !strcmp(n->text + 7, energy_terms[k].name)) {
                q->energy = energy_terms[k].term;
                return 0;
            }
        if (!strncmp(n->text, "particles.centre_", 17) && n->text[17] && !n->text[18] &&
            strchr("xyz", n->text[17]) && n->text[17] - 'x' < c->s->dim) {
            q->centre = 1;
            q->comp = n->text[17] - 'x';
            return 0;
        }
        if (!outlet_quantity(n->text, &q->outlet, &q->outlet_count)) {
            const tree *o = tree_get(c->root, "outlets");
            if (!o || o->kind != TREE_SEQ || (size_t)q->outlet >= o->n)
                return fail(c, n, "'%s': the scene has %zu outlets", n->text,
                            o && o->kind == TREE_SEQ ? o->n : 0);
            return 0;
        }
        const char *dot = strrchr(n->text, '.'), *under = dot ? strrchr(dot, '_') : NULL;
        if (!strncmp(n->text, "body.", 5) && dot > n->text + 5 && under && under[1] &&
            !under[2] && strchr("xyz", under[1])) {
            for (size_t b = 0; b < c->s->nbody; b++)
                if (strlen(c->s->bodyname[b]) == (size_t)(dot - n->text - 5) &&
                    !strncmp(c->s->bodyname[b], n->text + 5, (size_t)(dot - n->text - 5)))
                    q->body = (int)b;
            for (size_t f = 0; f < sizeof body_fields / sizeof body_fields[0]; f++)
                if (strlen(body_fields[f].name) == (size_t)(under - dot - 1) &&
                    !strncmp(body_fields[f].name, dot + 1, (size_t)(under - dot - 1)))
                    q->field = body_fields[f].field;
            q->comp = under[1] - 'x';
            if (q->body >= 0 && q->field && q->comp < c->s->dim)
                return 0;
        }
    }
    return fail(c, n, "expected a world.* or drum.* quantity of the parameter registry (e.g. "
                      "world.time, drum.power), body.NAME.FIELD_x (FIELD position, velocity, "
                      "force_particles, force_spring, force_damper or force_external), "
                      "outlet.N.mass, outlet.N.count, particles.centre_x or energy.NAME "
                      "(NAME a term of the energy account, e.g. dissipated_normal), got '%s'",
                kind_name(n));
}

const char *scene_quantity_unit(const scene_quantity *q)
{
    if (q->body >= 0)
        return q->field == DEMILL_BODY_POSITION ? "m" : q->field == DEMILL_BODY_VELOCITY ? "m/s" : "N";
    if (q->centre)
        return "m";
    if (q->outlet >= 0)
        return q->outlet_count ? "1" : "kg";
    if (q->energy)
        return "J";
    return demill_param_unit(q->key);
}

demill_status scene_quantity_read(const scene *s, const scene_quantity *q, double *value)
{
    if (q->body >= 0) {
        double v[3];
        const demill_status st = demill_body_get(s->w, s->body[q->body], q->field, v);
        *value = v[q->comp];
        return st;
    }
    if (q->energy)
        return demill_world_energy(s->w, q->energy, value);
    if (q->centre) {
        double m, c[3];
        const demill_status st = clumps_charge(s->w, &m, c);
        *value = c[q->comp];
        return st;
    }
    if (q->outlet >= 0) {
        uint64_t counts[32];
        double masses[32];
        size_t nc;
        const demill_status st =
            demill_outlet_read(s->w, s->outlet[q->outlet], counts, masses, 32, &nc, NULL);
        *value = 0;
        for (size_t k = 0; st == DEMILL_OK && k < nc; k++)
            *value += q->outlet_count ? (double)counts[k] : masses[k];
        return st;
    }
    return q->key < 400 ? demill_world_get(s->w, q->key, value)
                        : demill_drum_get(s->w, s->drum, q->key, value);
}

static const char *const k_outputs[] = {"every",    "csv",      "columns",      "vtk_every",
                                        "checkpoint_every", "pictures", "power_by_size",
                                        "discharge", "amplitude", "shear",
                                        "conveyor", "janssen", "dissipation",
                                        "repose"};
static const char *const k_amplitude[] = {"of", "window"};
static const char *const k_dissipation[] = {"window"};
static const char *const k_repose[] = {"centre", "ring"};
static const char *const k_discharge[] = {"outlet", "orifice_diameter", "half_angle",
                                          "stagnant_angle", "bulk_region"};

static const char *const k_shear[] = {"wall", "held", "lid", "area", "bin"};

/* outputs.shear: a direct shear test (shear.h): the wall (its index in
 * walls) whose motion, from its start, shears the sample, the bodies that
 * hold the other half, the lid's body, the shear plane's area and the
 * displacement over which the curve is averaged. */
static int shear_of(ctx *c, const tree *t)
{
    scene *s = c->s;
    const tree *e, *wl = tree_get(c->root, "walls"), *m, *v, *st;
    double index, vel[3];
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_shear, 5))
        return -1;
    if (!(e = need(c, t, "wall")) || number(c, e, 0, HUGE_VAL, &index))
        return -1;
    if (index != floor(index) || !wl || wl->kind != TREE_SEQ || index >= (double)wl->n)
        return fail(c, e, "expected the index of one of the scene's %zu walls, got '%s'",
                    wl && wl->kind == TREE_SEQ ? wl->n : 0, e->text);
    s->shear_wall = (int)index;
    m = tree_get(wl->kid[s->shear_wall], "motion");
    if (!(v = m ? tree_get(m, "velocity") : NULL))
        return fail(c, e, "wall %d has no motion.velocity to shear the sample with", s->shear_wall);
    if (numbers(c, v, 3, 3, vel, NULL))
        return -1;
    s->shear_speed = sqrt(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
    if (!(s->shear_speed > 0))
        return fail(c, v, "the shearing wall's velocity is zero");
    for (int k = 0; k < 3; k++)
        s->shear_dir[k] = vel[k] / s->shear_speed;
    s->shear_start = 0;
    if ((st = tree_get(m, "start")) && number(c, st, 0, HUGE_VAL, &s->shear_start))
        return -1;
    if (!(e = need(c, t, "held")))
        return -1;
    if (e->kind != TREE_SEQ || e->n < 1 || e->n > SCENE_MAX_BODIES)
        return fail(c, e, "expected a list of bodies, got %s", kind_name(e));
    for (size_t k = 0; k < e->n; k++)
        if (body_index(c, e->kid[k], &s->held[k]))
            return -1;
    s->nheld = e->n;
    if (!(e = need(c, t, "lid")) || body_index(c, e, &s->lid) || !(e = need(c, t, "area")) ||
        positive(c, e, &s->shear_area))
        return -1;
    s->shear_bin = 1e-3;
    if ((e = tree_get(t, "bin")) && positive(c, e, &s->shear_bin))
        return -1;
    s->shear_on = 1;
    return 0;
}

/* outputs.discharge: the outlet whose discharge rate is measured, the
 * orifice, the hopper's half-angle and a flat bottom's stagnant-zone angle
 * (degrees) for Beverloo's correlation with Rose and Tanaka's factor, and
 * where the bed's solid fraction is measured. */
static int discharge_of(ctx *c, const tree *t)
{
    scene *s = c->s;
    const tree *e, *o = tree_get(c->root, "outlets");
    double index, deg;
    size_t np;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_discharge, 5))
        return -1;
    if (s->dim != 3)
        return fail(c, t, "the discharge against Beverloo's correlation is for 3D scenes");
    if (!(e = need(c, t, "outlet")) || number(c, e, 0, SCENE_MAX_OUTLETS - 1, &index))
        return -1;
    if (index != floor(index) || !o || o->kind != TREE_SEQ || index >= (double)o->n)
        return fail(c, e, "expected the index of one of the scene's %zu outlets, got '%s'",
                    o && o->kind == TREE_SEQ ? o->n : 0, e->text);
    s->discharge_outlet = (int)index;
    if (!(e = need(c, t, "orifice_diameter")) || positive(c, e, &s->orifice))
        return -1;
    s->half_angle = s->stagnant_angle = 0.5 * PI;
    if ((e = tree_get(t, "half_angle"))) {
        if (number(c, e, 1, 90, &deg))
            return -1;
        s->half_angle = deg * PI / 180;
    }
    deg = 45;
    if ((e = tree_get(t, "stagnant_angle")) && number(c, e, 1, 89, &deg))
        return -1;
    s->stagnant_angle = deg * PI / 180;
    if (!(e = need(c, t, "bulk_region")) || region_of(c, e, 0, &s->bulk_kind, s->bulk_params, &np))
        return -1;
    if (s->bulk_kind == DEMILL_REGION_DRUM)
        return fail(c, e, "expected a box or a cylinder");
    s->discharge_on = 1;
    return 0;
}

static const char *const k_conveyor[] = {"chute", "feed", "outlet", "from"};

/* The index of an item of the scene's list `list` (feeds, outlets) in n:
 * 0, or -1 with a message. */
static int conveyor_item(ctx *c, const tree *n, const char *list, int *index)
{
    const tree *l = tree_get(c->root, list);
    double v = 0;
    if (number(c, n, 0, 1e9, &v))
        return -1;
    if (v != floor(v) || !l || l->kind != TREE_SEQ || v >= (double)l->n)
        return fail(c, n, "expected the index of one of the scene's %zu %s, got '%s'",
                    l && l->kind == TREE_SEQ ? l->n : 0, list, n->text);
    *index = (int)v;
    return 0;
}

/* outputs.conveyor: the body holding the chute (none by default), the
 * feed and the outlet, and when the steady state is taken to begin. The
 * belt is the walls with a surface velocity, the same on each. */
static int conveyor_of(ctx *c, const tree *t)
{
    scene *s = c->s;
    const tree *e, *walls = tree_get(c->root, "walls"), *belt = NULL;
    int feed;
    double sv[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_conveyor, 4))
        return -1;
    for (size_t k = 0; walls && walls->kind == TREE_SEQ && k < walls->n; k++) {
        const tree *w = tree_get(walls->kid[k], "surface_velocity");
        if (!w)
            continue;
        if (numbers(c, w, 3, 3, v, NULL))
            return -1;
        if (belt && (v[0] != sv[0] || v[1] != sv[1] || v[2] != sv[2]))
            return fail(c, w, "expected the surface velocity of the belt's other walls");
        belt = w;
        memcpy(sv, v, sizeof sv);
    }
    if (!belt)
        return fail(c, t, "the conveyor needs a belt: a wall with a surface_velocity");
    s->belt_speed = sqrt(sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2]);
    if (!(s->belt_speed > 0))
        return fail(c, belt, "expected a belt moving (a surface velocity not 0)");
    for (int k = 0; k < 3; k++)
        s->belt_dir[k] = sv[k] / s->belt_speed;
    s->conveyor_chute = -1;
    if ((e = tree_get(t, "chute"))) {
        for (size_t k = 0; e->kind == TREE_SCALAR && k < s->nbody && s->conveyor_chute < 0; k++)
            if (!strcmp(e->text, s->bodyname[k]))
                s->conveyor_chute = (int)k;
        if (s->conveyor_chute < 0)
            return fail(c, e, "expected a body of 'bodies', got '%s'", kind_name(e));
    }
    if (!(e = need(c, t, "feed")) || conveyor_item(c, e, "feeds", &feed))
        return -1;
    const tree *f = tree_get(c->root, "feeds")->kid[feed];
    s->feed_along = 0;
    if ((e = tree_get(f, "velocity"))) {
        if (numbers(c, e, 3, 3, v, NULL))
            return -1;
        s->feed_along = v[0] * s->belt_dir[0] + v[1] * s->belt_dir[1] + v[2] * s->belt_dir[2];
    }
    if (!(e = need(c, f, "mass_rate")) || positive(c, e, &s->feed_rate))
        return -1;
    if (!(e = need(c, t, "outlet")) || conveyor_item(c, e, "outlets", &s->conveyor_outlet) ||
        !(e = need(c, t, "from")) || number(c, e, 0, HUGE_VAL, &s->conveyor_from))
        return -1;
    s->conveyor_on = 1;
    return 0;
}

static const char *const k_janssen[] = {"wall", "floor", "band", "zone", "window"};

/* The index of a wall of the scene's `walls` (outputs.janssen.wall, .floor):
 * its item in *item, 0, or -1 with a message. */
static int wall_item(ctx *c, const tree *e, const tree **item, int *index)
{
    const tree *ws = tree_get(c->root, "walls");
    double k = 0;
    if (number(c, e, 0, HUGE_VAL, &k) || k != floor(k) || !ws || ws->kind != TREE_SEQ ||
        k >= (double)ws->n)
        return fail(c, e, "expected the index of one of the scene's %zu walls, got '%s'",
                    ws && ws->kind == TREE_SEQ ? ws->n : 0, kind_name(e));
    *index = (int)k;
    *item = ws->kid[*index];
    return 0;
}

/* outputs.janssen: the silo's side, a cylinder of `walls` whose axis is
 * along gravity, the floor it stands on (a plane or a disc across that
 * axis), the bands' height, the heights above the floor where K, the wall
 * friction and the bulk density are measured, and the window before
 * stop.time over which the samples are averaged (the walls' own keys were
 * checked by the walls section). */
static int janssen_of(ctx *c, const tree *t)
{
    scene *s = c->s;
    const tree *e, *side, *fl, *cyl, *f;
    double g[3], gn = 0, axis[3], an = 0, len = 0, p[3], fp[3], fnorm[3], cross = 0, fn = 0, dot = 0;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_janssen, 5))
        return -1;
    if (s->dim != 3)
        return fail(c, t, "the silo's wall stress against Janssen's is for 3D scenes");
    if (!(e = need(c, t, "wall")) || wall_item(c, e, &side, &s->silo_wall))
        return -1;
    if (!(cyl = tree_get(side, "cylinder")))
        return fail(c, e, "walls.%d is not a cylinder", s->silo_wall);
    numbers(c, tree_get(cyl, "point"), 3, 3, p, NULL);
    numbers(c, tree_get(cyl, "axis"), 3, 3, axis, NULL);
    to_number(tree_get(cyl, "radius"), &s->silo_radius);
    to_number(tree_get(cyl, "length"), &len);
    for (int j = 0; j < 3; j++) {
        demill_world_get(s->w, DEMILL_WORLD_GRAVITY_X + j, &g[j]);
        gn += g[j] * g[j];
        an += axis[j] * axis[j];
    }
    gn = sqrt(gn);
    an = sqrt(an);
    for (int j = 0; j < 3; j++) {
        const double cj = axis[(j + 1) % 3] * g[(j + 2) % 3] - axis[(j + 2) % 3] * g[(j + 1) % 3];
        cross += cj * cj;
        s->silo_up[j] = gn > 0 ? -g[j] / gn : 0;
    }
    if (!(gn > 0) || sqrt(cross) > 1e-9 * gn * an)
        return fail(c, e, "the cylinder's axis is not along gravity");
    if (!(e = need(c, t, "floor")) || wall_item(c, e, &fl, &s->silo_floor))
        return -1;
    if (!(f = tree_get(fl, "plane")) && !(f = tree_get(fl, "disc")))
        return fail(c, e, "walls.%d is not a plane or a disc", s->silo_floor);
    numbers(c, tree_get(f, tree_get(f, "point") ? "point" : "centre"), 3, 3, fp, NULL);
    numbers(c, tree_get(f, "normal"), 3, 3, fnorm, NULL);
    for (int j = 0; j < 3; j++) {
        fn += fnorm[j] * fnorm[j];
        dot += fnorm[j] * s->silo_up[j];
    }
    if (fabs(fabs(dot) - sqrt(fn)) > 1e-9 * sqrt(fn))
        return fail(c, e, "the floor is not across the cylinder's axis");
    /* the axis's point at the floor's level, and the side's top above it */
    double level = 0, along = 0;
    for (int j = 0; j < 3; j++) {
        level += (fp[j] - p[j]) * s->silo_up[j];
        along += axis[j] / an * s->silo_up[j];
    }
    for (int j = 0; j < 3; j++)
        s->silo_point[j] = p[j] + level * s->silo_up[j];
    s->silo_top = fmax(0, len * along) - level;
    if (!(e = need(c, t, "band")) || positive(c, e, &s->silo_band))
        return -1;
    if (!(e = need(c, t, "zone")) || numbers(c, e, 2, 2, s->silo_zone, NULL))
        return -1;
    if (!(s->silo_zone[0] >= 0 && s->silo_zone[1] > s->silo_zone[0] + s->silo_band))
        return fail(c, e, "expected two heights above the floor, 0 <= from < to, more than a band "
                          "apart");
    if (!(e = need(c, t, "window")) || positive(c, e, &s->silo_window))
        return -1;
    if (!tree_get(tree_get(c->root, "stop"), "time"))
        return fail(c, t, "needs a stop.time (its window ends there)");
    s->janssen_on = 1;
    return 0;
}

static int outputs_section(ctx *c, const tree *t)
{

    scene *s = c->s;
    s->every = 1e-3;
    s->csv_file[0] = '\0';
    s->ncol = 0;
    s->vtk_every = s->checkpoint_every = 0;
    s->charge_png = s->power_png = s->series_png = 0;
    s->nedges = 0;
    s->discharge_on = 0;
    s->namp = 0;
    s->shear_on = 0;
    s->conveyor_on = 0;
    s->janssen_on = 0;
    s->dissipation_on = s->repose_on = 0;
    if (!t)
        return 0;
    const tree *e;
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_outputs, sizeof k_outputs / sizeof k_outputs[0]))
        return -1;
    if ((e = tree_get(t, "every")) && positive(c, e, &s->every))
        return -1;
    if ((e = tree_get(t, "vtk_every")) && number(c, e, 0, HUGE_VAL, &s->vtk_every))
        return -1;
    if ((e = tree_get(t, "checkpoint_every")) && number(c, e, 0, HUGE_VAL, &s->checkpoint_every))
        return -1;
    if ((e = tree_get(t, "csv"))) {
        if (e->kind != TREE_SCALAR || !*e->text || strchr(e->text, '/') || strlen(e->text) > 200)
            return fail(c, e, "expected a file name without a folder, got %s", kind_name(e));
        snprintf(s->csv_file, sizeof s->csv_file, "%s", e->text);
    }
    if ((e = tree_get(t, "columns"))) {
        if (e->kind != TREE_SEQ || e->n < 1 || e->n > SCENE_MAX_COLUMNS)
            return fail(c, e, "expected a list of 1 to %d quantities", SCENE_MAX_COLUMNS);
        for (size_t k = 0; k < e->n; k++)
            if (quantity_of(c, e->kid[k], &s->col[k]))
                return -1;
        s->ncol = e->n;
    }
    if ((e = tree_get(t, "pictures"))) {
        if (e->kind != TREE_SEQ)
            return fail(c, e, "expected a list of pictures (charge, power, series), got %s",
                        kind_name(e));
        for (size_t k = 0; k < e->n; k++) {
            const tree *q = e->kid[k];
            if (q->kind == TREE_SCALAR && !strcmp(q->text, "charge"))
                s->charge_png = 1;
            else if (q->kind == TREE_SCALAR && !strcmp(q->text, "power"))
                s->power_png = 1;
            else if (q->kind == TREE_SCALAR && !strcmp(q->text, "series")) {
                if (!tree_get(t, "columns"))
                    return fail(c, q, "the series picture draws outputs.columns, which are not given");
                s->series_png = 1;
                continue;
            } else
                return fail(c, q, "expected charge, power or series, got '%s'", kind_name(q));
            if (!tree_get(c->root, "drum"))
                return fail(c, q, "the %s picture needs a drum", q->text);
        }
    }
    if ((e = tree_get(t, "power_by_size"))) {
        if (!tree_get(c->root, "drum"))
            return fail(c, e, "the power by size class needs a drum");
        if (numbers(c, e, 0, SCENE_MAX_EDGES, s->edges, &s->nedges))
            return -1;
        for (size_t k = 0; k < s->nedges; k++)
            if (!(s->edges[k] > (k ? s->edges[k - 1] : 0)))
                return fail(c, e->kid[k], "expected increasing diameters > 0, got '%s'",
                            e->kid[k]->text);
    }
    if ((e = tree_get(t, "discharge")) && discharge_of(c, e))
        return -1;
    if ((e = tree_get(t, "amplitude"))) {
        const tree *of, *win;
        if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_amplitude, 2) ||
            !(of = need(c, e, "of")) || !(win = need(c, e, "window")) ||
            positive(c, win, &s->amp_window))
            return -1;
        if (of->kind != TREE_SEQ || of->n < 1 || of->n > SCENE_MAX_COLUMNS)
            return fail(c, of, "expected a list of 1 to %d quantities", SCENE_MAX_COLUMNS);
        for (size_t k = 0; k < of->n; k++)
            if (quantity_of(c, of->kid[k], &s->amp[k]))
                return -1;
        s->namp = of->n;
    }
    if ((e = tree_get(t, "shear"))) {
        if (c->mode == SCENE_RESTART)
            return fail(c, e, "the shear test is measured from a scene's start, not on a restart");
        if (shear_of(c, e))
            return -1;
    }
    if ((e = tree_get(t, "conveyor"))) {
        if (c->mode == SCENE_RESTART)
            return fail(c, e, "the conveyor is measured from a scene's start, not on a restart");
        if (conveyor_of(c, e))
            return -1;
    }
    if ((e = tree_get(t, "janssen")) && janssen_of(c, e))
        return -1;
    if ((e = tree_get(t, "dissipation"))) {
        const tree *win;
        if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_dissipation, 1) ||
            !(win = need(c, e, "window")) || positive(c, win, &s->dissipation_window))
            return -1;
        s->dissipation_on = 1;
    }
    if ((e = tree_get(t, "repose"))) {
        const tree *ce, *ring;
        s->repose_ring = 0;
        if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_repose, 2) ||
            !(ce = need(c, e, "centre")) || numbers(c, ce, 3, 3, s->repose_centre, NULL) ||
            ((ring = tree_get(e, "ring")) && positive(c, ring, &s->repose_ring)))
            return -1;
        if (s->dim != 3)
            return fail(c, e, "the angle of repose of an axisymmetric heap is for 3D scenes");
        s->repose_on = 1;
    }
    return 0;
}

static const char *const k_stop[] = {"time", "revolutions", "empty", "steady"};
static const char *const k_steady[] = {"quantity", "window", "tolerance"};

static int stop_section(ctx *c, const tree *t)
{
    scene *s = c->s;
    s->stop_time = s->stop_revolutions = NAN;
    s->empty_kind = 0;
    s->steady_on = 0;
    if (!t)
        return fail(c, c->root, "missing 'stop' (time, revolutions, empty or steady)");
    if (need_kind(c, t, TREE_MAP) || check_keys(c, t, k_stop, 4))
        return -1;
    const tree *e;
    if ((e = tree_get(t, "time")) && positive(c, e, &s->stop_time))
        return -1;
    if ((e = tree_get(t, "revolutions"))) {
        if (!tree_get(c->root, "drum"))
            return fail(c, e, "revolutions need a drum");
        if (positive(c, e, &s->stop_revolutions) || s->stop_revolutions != floor(s->stop_revolutions))
            return fail(c, e, "expected a whole number > 0, got '%s'", kind_name(e));
        if (!s->speed_key)
            return fail(c, e, "the drum has no speed (speed, speed_rpm or speed_fraction)");
    }
    if ((e = tree_get(t, "empty"))) {
        size_t np;
        if (region_of(c, e, 0, &s->empty_kind, s->empty_params, &np))
            return -1;
        if (s->empty_kind == DEMILL_REGION_DRUM)
            return fail(c, e, "expected a box or a cylinder, got drum");
    }
    if ((e = tree_get(t, "steady"))) {
        const tree *q, *wn, *tol;
        if (need_kind(c, e, TREE_MAP) || check_keys(c, e, k_steady, 3) ||
            !(q = need(c, e, "quantity")) || !(wn = need(c, e, "window")) ||
            !(tol = need(c, e, "tolerance")))
            return -1;
        if (quantity_of(c, q, &s->steady))
            return -1;
        s->steady_on = 1;
        if (positive(c, wn, &s->steady_window) || positive(c, tol, &s->steady_tolerance))
            return -1;
    }
    if (isnan(s->stop_time) && isnan(s->stop_revolutions) && !s->empty_kind && !s->steady_on)
        return fail(c, t, "expected time, revolutions, empty or steady");
    if (s->namp && isnan(s->stop_time))
        return fail(c, t, "outputs.amplitude needs a stop.time (its window ends there)");
    if (s->dissipation_on && isnan(s->stop_time))
        return fail(c, t, "outputs.dissipation needs a stop.time (its window ends there)");
    return 0;
}

int scene_build(scene *s, const tree *root, const char *dir, int mode, char *err, size_t errlen)
{
    ctx c = {s, root, dir, mode, err, errlen};
    demill_world *given = mode == SCENE_RESTART ? s->w : NULL;
    if (mode != SCENE_RESTART)
        s->w = NULL;
    const tree *auto_dt = NULL;
    int rc = -1;
    if (need_kind(&c, root, TREE_MAP) ||
        check_keys(&c, root, top_keys, sizeof top_keys / sizeof top_keys[0]) ||
        world_section(&c, tree_get(root, "world"), &auto_dt) ||
        materials_section(&c, tree_get(root, "materials")) ||
        pairs_section(&c, tree_get(root, "pairs")) || drum_section(&c, tree_get(root, "drum")) ||
        bodies_section(&c, tree_get(root, "bodies")) ||
        walls_section(&c, tree_get(root, "walls")) ||
        templates_section(&c, tree_get(root, "templates")) ||
        particles_section(&c, tree_get(root, "particles")) ||
        feeds_section(&c, tree_get(root, "feeds")) || outlets_section(&c, tree_get(root, "outlets")) ||
        outputs_section(&c, tree_get(root, "outputs")) || stop_section(&c, tree_get(root, "stop")))
        goto out;
    if (auto_dt) {
        double spc = 0, dt;
        const tree *e = tree_get(tree_get(root, "world"), "steps_per_contact");
        if (e)
            to_number(e, &spc);
        if (mode == SCENE_BUILD &&
            (api(&c, auto_dt, demill_world_suggest_time_step(s->w, 0, spc, &dt, NULL, NULL)) ||
             api(&c, auto_dt, demill_world_set(s->w, DEMILL_WORLD_TIME_STEP, dt))))
            goto out;
    }
    demill_world_get(s->w, DEMILL_WORLD_TIME_STEP, &s->dt);
    rc = 0;
out:
    if (rc && mode != SCENE_RESTART) {
        demill_world_destroy(s->w);
        s->w = NULL;
    }
    if (mode == SCENE_RESTART)
        s->w = given;
    return rc;
}

/* One group's table: key, unit, allowed values, default. */
static void key_table(FILE *f, const char *title, const group *g)
{
    fprintf(f, "#### %s\n\n| key | unit | allowed | default |\n|---|---|---|---|\n", title);
    for (size_t k = 0; k < g->n; k++) {
        double lo, hi, def;
        demill_param_bounds(g->key[k], &lo, &hi, &def);
        const char *unit = demill_param_unit(g->key[k]);
        const choice *ch = choice_of(g->key[k]);
        char allowed[256] = "", dflt[64];
        snprintf(dflt, sizeof dflt, "%g", def);
        if (ch) {
            for (int v = 0; v < 7; v++)
                if (ch->names[v] && *ch->names[v])
                    snprintf(allowed + strlen(allowed), sizeof allowed - strlen(allowed), "%s%s",
                             *allowed ? ", " : "", ch->names[v]);
            snprintf(dflt, sizeof dflt, "%s", ch->names[(int)def]);
            unit = "choice";
        } else if (!strcmp(unit, "bool")) {
            snprintf(allowed, sizeof allowed, "true, false");
            snprintf(dflt, sizeof dflt, "%s", def ? "true" : "false");
        } else {
            char a[48], b[48];
            bound_text(lo, -HUGE_VAL, 1, a, sizeof a);
            bound_text(hi, HUGE_VAL, 0, b, sizeof b);
            snprintf(allowed, sizeof allowed, "%s, %s", a, b);
        }
        fprintf(f, "| `%s` | %s | %s | %s |\n", g->name[k], unit, allowed, dflt);
    }
    fputc('\n', f);
}

/* The sections whose keys are the runner's own, with those keys. */
#define KEYS(a) a, sizeof a / sizeof a[0]
typedef struct section {
    const char *name;
    const char *const *keys;
    size_t n;
} section;

static const section sections[] = {
    {"(top level)", KEYS(top_keys)},
    {"world (besides the registry's keys)", KEYS(world_extra)},
    {"pairs[] (besides the registry's keys)", KEYS(k_pair_extra)},
    {"drum (besides the registry's keys)", KEYS(drum_extra)},
    {"drum.parts", KEYS(k_parts)},
    {"templates.NAME", KEYS(k_templates)},
    {"templates.NAME.stl", KEYS(k_template_stl)},
    {"particles[]", KEYS(k_particles)},
    {"particles[].sizes, feeds[].sizes", KEYS(k_sizes)},
    {"particles[].region, feeds[].region, outlets[].region, stop.empty, "
     "outputs.discharge.bulk_region",
     KEYS(k_region)},
    {"bodies.NAME", KEYS(k_bodies)},
    {"bodies.NAME.springs[]", KEYS(k_spring)},
    {"bodies.NAME.force", KEYS(k_force)},
    {"bodies.NAME.load", KEYS(k_load)},
    {"walls[]", KEYS(k_walls)},
    {"walls[].plane", shapes[0].keys, 2},
    {"walls[].rectangle", shapes[1].keys, 5},
    {"walls[].disc", shapes[2].keys, 4},
    {"walls[].cylinder", shapes[3].keys, 5},
    {"walls[].cone", shapes[4].keys, 6},
    {"walls[].stl", KEYS(k_stl)},
    {"walls[].polyline", KEYS(k_polyline)},
    {"walls[].motion", KEYS(k_motion)},
    {"walls[].harmonic", KEYS(k_harmonic)},
    {"feeds[]", KEYS(k_feeds)},
    {"outlets[]", KEYS(k_outlets)},
    {"outputs", KEYS(k_outputs)},
    {"outputs.discharge", KEYS(k_discharge)},
    {"outputs.amplitude", KEYS(k_amplitude)},
    {"outputs.shear", KEYS(k_shear)},
    {"outputs.conveyor", KEYS(k_conveyor)},
    {"outputs.janssen", KEYS(k_janssen)},
    {"outputs.dissipation", KEYS(k_dissipation)},
    {"outputs.repose", KEYS(k_repose)},
    {"stop", KEYS(k_stop)},
    {"stop.steady", KEYS(k_steady)},
};

void scene_list_keys(FILE *f)
{
    fputs("#### sections\n\n| section | keys |\n|---|---|\n", f);
    for (size_t k = 0; k < sizeof sections / sizeof sections[0]; k++) {
        fprintf(f, "| %s |", sections[k].name);
        for (size_t j = 0; j < sections[k].n; j++)
            fprintf(f, "%s `%s`", j ? "," : "", sections[k].keys[j]);
        fputs(" |\n", f);
    }
    fputc('\n', f);
    group g;
    group_world(&g);
    key_table(f, "world", &g);
    group_material(&g);
    key_table(f, "materials.NAME", &g);
    group_pair(&g);
    key_table(f, "pairs[]", &g);
    group_drum(&g);
    key_table(f, "drum", &g);
}
