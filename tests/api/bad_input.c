/* bad_input.c: bad input is rejected and leaves no trace.
 *
 * Proves the requirement "Bad input: NaN or infinite values, negative or zero
 * radius/density/stiffness, dt <= 0, unknown enum values, a material pair with
 * no model, a freed or foreign handle, overlapping insertion when the caller
 * asked for none — each returns its error code with a message naming the
 * problem, and the world is unchanged".
 *
 * Every bad call is checked three ways:
 *  1. it returns exactly the status code the headers document for that fault;
 *  2. demill_world_last_error() afterwards is a new, non-empty message that
 *     names the fault (the parameter name such as "world.time_step", the
 *     field, the index of the particle in the batch, "not finite", ...);
 *  3. a snapshot of everything the public API can observe (every world
 *     parameter, every particle field, id and material id in id order, every
 *     material and pair parameter, every wall field, every energy term, and
 *     every contact field and contact id pair) taken before and after the call
 *     is bitwise identical.
 * The scene is realistic: a 2D and a 3D world with two materials whose pairs
 * have full contact models (Hertz + restitution damping + Mindlin; linear +
 * viscous + Coulomb + constant-torque rolling; linear + restitution + spring
 * + rolling), a moving plane wall and 20 particles stacked on it, stepped 300
 * times so that contacts carry tangential history.
 *
 * As a stronger check that failures leave no hidden trace, every scene that
 * saw a batch of bad calls is stepped 100 more times next to a twin built the
 * same way that never saw them (but made the same read-only queries), and the
 * two must still agree bitwise.
 *
 * Where one value breaks two documented rules at once (NaN as the z component
 * in a 2D world, NaN disc thickness in 3D) either rule's code is accepted.
 * The test case "documented_codes" holds the cases whose code is checked
 * against the @return list of the one function concerned (a non-whole choice,
 * unknown add flags, the 2D-only angle read in 3D), so that a disagreement
 * there is reported on its own.
 *
 * A test reports every broken case on stderr and fails with the first one.
 */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "meshes.h"
#include "stl_write.h"
#include "testutil.h"

#define RAD 0.004          /* particle radius of the scene, m */
#define BUILD_STEPS 300    /* steps before the bad calls: contacts have history */
#define TWIN_STEPS 100     /* steps after them, next to the twin */
#define MAXP 64

static const double nonfinite[3] = {NAN, INFINITY, -INFINITY};
#define NONFINITE "finite|nan|inf"

/* ------------------------------------------------------------------------ */
/* Snapshots of the observable state                                         */

typedef struct item {
    const char *what;
    int32_t key;
    uint32_t idx;
    int32_t status;
    uint64_t bits;
} item;

typedef struct snap {
    item *it;
    size_t n, cap;
} snap;

typedef struct scene {
    demill_world *w;
    int dim;
    demill_id mat[4];
    int nmat;
    demill_id wall[4]; /* walls the snapshot reads (live or removed) */
    int nwall;
    demill_id pid[MAXP]; /* every particle id ever added, in order */
    size_t np;
    demill_id gone_p[2], gone_wall; /* removed ids (setup_removed) */
    demill_id body;                 /* a body the snapshot reads (setup_body) */
    demill_id tmpl, clump;          /* a clump template and a clump (setup_clump) */
    demill_id mesh_tmpl;            /* a template from a mesh (setup_mesh_template, 3D) */
    unsigned nsnaps;
    int calls, failures;
    char ctx[256];
    char first[2048];
} scene;

static void put(snap *s, const char *what, int32_t key, size_t idx, int32_t status,
                uint64_t bits)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 2048;
        s->it = realloc(s->it, s->cap * sizeof *s->it);
        ck_assert_ptr_nonnull(s->it);
    }
    s->it[s->n++] = (item){what, key, (uint32_t)idx, status, bits};
}

static void put_d(snap *s, const char *what, int32_t key, size_t idx, int32_t status, double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    put(s, what, key, idx, status, b);
}

/* Ids are opaque and differ between twin worlds, so the snapshot records a
 * known id by what it names (kind and position in the scene's lists). */
static uint64_t id_code(const scene *sc, demill_id id)
{
    for (size_t k = 0; k < sc->np; k++)
        if (sc->pid[k] == id)
            return (2ull << 60) | k;
    for (int k = 0; k < sc->nmat; k++)
        if (sc->mat[k] == id)
            return (1ull << 60) | (uint64_t)k;
    for (int k = 0; k < sc->nwall; k++)
        if (sc->wall[k] == id)
            return (3ull << 60) | (uint64_t)k;
    if (id && id == sc->tmpl)
        return 4ull << 60;
    if (id && id == sc->clump)
        return 5ull << 60;
    if (id && id == sc->mesh_tmpl)
        return 6ull << 60;
    return id == DEMILL_ID_NONE ? 0 : (0xfull << 60) ^ id;
}

static void snap_free(snap *s)
{
    free(s->it);
    s->it = NULL;
    s->n = s->cap = 0;
}

static void snap_take(scene *sc, snap *s)
{
    static const int32_t world_keys[] = {100, 101, 102, 103, 104, 105, 106, 107, 108, 110,
                                         111, 112, 113, 114, 150, 151, 152, 153, 154, 155,
                                         156, 157, 158};
    demill_world *w = sc->w;
    demill_status st;
    memset(s, 0, sizeof *s);
    sc->nsnaps++;

    for (size_t k = 0; k < sizeof world_keys / sizeof world_keys[0]; k++) {
        double v = 0.0;
        st = demill_world_get(w, world_keys[k], &v);
        put_d(s, "world", world_keys[k], 0, st, v);
    }

    /* particles, in id order */
    size_t n = 0, cnt;
    st = demill_particles_read_ids(w, DEMILL_PARTICLE_ID, NULL, 0, &n);
    put(s, "particle count", 0, 0, st, n);
    double *buf = calloc(3 * n + 3, sizeof *buf);
    demill_id *ids = calloc(n + 1, sizeof *ids);
    ck_assert(buf && ids);
    for (int32_t f = DEMILL_PARTICLE_POSITION; f <= DEMILL_PARTICLE_FIXED; f++) {
        if (f == DEMILL_PARTICLE_ANGLE && sc->dim == 3)
            continue;
        size_t size = (size_t)demill_particle_field_size(f);
        memset(buf, 0, (3 * n + 3) * sizeof *buf);
        cnt = 0;
        st = demill_particles_read(w, f, buf, n, &cnt);
        put(s, "particle field count", f, 0, st, cnt);
        for (size_t i = 0; i < size * n; i++)
            put_d(s, "particle field", f, i, st, buf[i]);
    }
    for (int32_t f = DEMILL_PARTICLE_ID; f <= DEMILL_PARTICLE_CLUMP; f++) {
        memset(ids, 0, (n + 1) * sizeof *ids);
        cnt = 0;
        st = demill_particles_read_ids(w, f, ids, n, &cnt);
        put(s, "particle id count", f, 0, st, cnt);
        for (size_t i = 0; i < n; i++)
            put(s, "particle id", f, i, st, id_code(sc, ids[i]));
    }

    /* materials and every pair of them */
    for (int m = 0; m < sc->nmat; m++)
        for (int32_t key = 200; key <= 215; key++) {
            double v = 0.0;
            st = demill_material_get(w, sc->mat[m], key, &v);
            put_d(s, "material", key, (size_t)m, st, v);
        }
    static const int32_t pair_keys[] = {300, 301, 302, 303, 304, 310, 311, 312, 313, 314,
                                        315, 316, 317, 318, 319, 331, 332, 333, 334};
    for (int a = 0; a < sc->nmat; a++)
        for (int b = a; b < sc->nmat; b++)
            for (size_t k = 0; k < sizeof pair_keys / sizeof pair_keys[0]; k++) {
                double v = 0.0;
                st = demill_pair_get(w, sc->mat[a], sc->mat[b], pair_keys[k], &v);
                put_d(s, "pair", pair_keys[k], (size_t)(16 * a + b), st, v);
            }

    /* walls */
    for (int k = 0; k < sc->nwall; k++)
        for (int32_t f = DEMILL_WALL_POINT; f <= DEMILL_WALL_TORQUE; f++) {
            double v[3] = {0, 0, 0};
            st = demill_wall_get(w, sc->wall[k], f, v);
            for (int c = 0; c < 3; c++)
                put_d(s, "wall", f, (size_t)(3 * k + c), st, v[c]);
        }

    /* bodies */
    size_t nb = 0;
    st = demill_world_ids(w, DEMILL_KIND_BODY, NULL, 0, &nb);
    put(s, "body count", 0, 0, st, nb);
    if (sc->body) {
        for (int32_t f = DEMILL_BODY_POSITION; f <= DEMILL_BODY_FORCE_EXTERNAL; f++) {
            double v[3] = {0, 0, 0};
            st = demill_body_get(w, sc->body, f, v);
            for (int c = 0; c < 3; c++)
                put_d(s, "body", f, (size_t)c, st, v[c]);
        }
        for (int32_t t = DEMILL_ENERGY_BODY_KINETIC; t <= DEMILL_ENERGY_BODY_WORK; t++) {
            double v = 0.0;
            st = demill_body_energy(w, sc->body, t, &v);
            put_d(s, "body energy", t, 0, st, v);
        }
    }

    /* clumps */
    if (sc->clump) {
        for (int32_t f = DEMILL_CLUMP_POSITION; f <= DEMILL_CLUMP_MASS; f++) {
            double v[4] = {0, 0, 0, 0};
            st = demill_clump_get(w, sc->clump, f, v);
            for (int c = 0; c < 4; c++)
                put_d(s, "clump", f, (size_t)c, st, v[c]);
        }
        demill_id m[4] = {0};
        size_t nm = 0;
        st = demill_clump_members(w, sc->clump, m, 4, &nm);
        put(s, "clump members", 0, 0, st, nm);
        for (size_t k = 0; k < 4; k++)
            put(s, "clump member", 0, k, st, id_code(sc, m[k]));
    }
    /* templates: how many, and the fields and spheres of the scene's */
    size_t nt = 0;
    st = demill_world_ids(w, DEMILL_KIND_TEMPLATE, NULL, 0, &nt);
    put(s, "template count", 0, 0, st, nt);
    const demill_id tmpls[2] = {sc->tmpl, sc->mesh_tmpl};
    for (int k = 0; k < 2; k++) {
        if (!tmpls[k])
            continue;
        for (int32_t f = DEMILL_TEMPLATE_MASS; f <= DEMILL_TEMPLATE_FIT_CELL; f++) {
            double v[9] = {0};
            st = demill_clump_template_get(w, tmpls[k], f, v);
            for (int c = 0; c < 9; c++)
                put_d(s, "template", f, (size_t)(9 * k + c), st, v[c]);
        }
        double b[12] = {0}, r[4] = {0};
        size_t ns = 0;
        st = demill_clump_template_spheres(w, tmpls[k], b, r, 4, &ns);
        put(s, "template spheres", 0, (size_t)k, st, ns);
        for (size_t c = 0; c < 4; c++) {
            put_d(s, "template sphere radius", 0, 4 * (size_t)k + c, st, r[c]);
            for (int a = 0; a < 3; a++)
                put_d(s, "template sphere centre", a, 4 * (size_t)k + c, st, b[3 * c + a]);
        }
    }

    /* energies */
    for (int32_t t = DEMILL_ENERGY_KINETIC_TRANSLATIONAL; t <= DEMILL_ENERGY_ELASTIC_ROLLING;
         t++) {
        double v = 0.0;
        st = demill_world_energy(w, t, &v);
        put_d(s, "energy", t, 0, st, v);
    }

    /* contacts */
    size_t nc = 0;
    st = demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &nc);
    put(s, "contact count", 0, 0, st, nc);
    double *cbuf = calloc(3 * nc + 3, sizeof *cbuf);
    demill_id *ca = calloc(nc + 1, sizeof *ca), *cb = calloc(nc + 1, sizeof *cb);
    ck_assert(cbuf && ca && cb);
    for (int32_t f = DEMILL_CONTACT_POINT; f <= DEMILL_CONTACT_ROLLING_TORQUE; f++) {
        size_t size = (size_t)demill_contact_field_size(f);
        cnt = 0;
        st = demill_contacts_read(w, f, cbuf, nc, &cnt);
        put(s, "contact field count", f, 0, st, cnt);
        for (size_t i = 0; i < size * nc; i++)
            put_d(s, "contact field", f, i, st, cbuf[i]);
    }
    cnt = 0;
    st = demill_contacts_read_ids(w, ca, cb, nc, &cnt);
    put(s, "contact ids count", 0, 0, st, cnt);
    for (size_t i = 0; i < nc; i++) {
        put(s, "contact id a", 0, i, st, id_code(sc, ca[i]));
        put(s, "contact id b", 0, i, st, id_code(sc, cb[i]));
    }

    /* the counters again: a query that had to rebuild lists a failed call
     * invalidated shows here at once */
    for (size_t k = 0; k < sizeof world_keys / sizeof world_keys[0]; k++) {
        double v = 0.0;
        st = demill_world_get(w, world_keys[k], &v);
        put_d(s, "world after queries", world_keys[k], 0, st, v);
    }
    free(cbuf);
    free(ca);
    free(cb);
    free(buf);
    free(ids);
}

/* 1 and a description of the first difference if the snapshots differ. */
static int snap_diff(const snap *x, const snap *y, char *out, size_t len)
{
    size_t n = x->n < y->n ? x->n : y->n;
    for (size_t k = 0; k < n; k++) {
        const item *a = &x->it[k], *b = &y->it[k];
        if (strcmp(a->what, b->what) || a->key != b->key || a->idx != b->idx) {
            snprintf(out, len, "layout differs at item %zu (%s %d [%u] vs %s %d [%u])", k,
                     a->what, (int)a->key, (unsigned)a->idx, b->what, (int)b->key,
                     (unsigned)b->idx);
            return 1;
        }
        if (a->status != b->status || a->bits != b->bits) {
            double da, db;
            memcpy(&da, &a->bits, sizeof da);
            memcpy(&db, &b->bits, sizeof db);
            snprintf(out, len,
                     "%s key %d [%u]: status %d -> %d, value %.17g -> %.17g (bits %016llx -> "
                     "%016llx)",
                     a->what, (int)a->key, (unsigned)a->idx, (int)a->status, (int)b->status, da,
                     db, (unsigned long long)a->bits, (unsigned long long)b->bits);
            return 1;
        }
    }
    if (x->n != y->n) {
        snprintf(out, len, "%zu observable values before, %zu after", x->n, y->n);
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Recording failures                                                         */

static void ctx(scene *sc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sc->ctx, sizeof sc->ctx, fmt, ap);
    va_end(ap);
}

static void note_fail(scene *sc, const char *call, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    sc->failures++;
    fprintf(stderr, "bad_input [%dD] %s | %s | %s\n", sc->dim, sc->ctx, call, msg);
    if (sc->failures == 1)
        snprintf(sc->first, sizeof sc->first, "[%dD] %s | %s | %s", sc->dim, sc->ctx, call, msg);
}

/* Case-insensitive: does msg contain one of the '|'-separated alternatives? */
static int mentions(const char *msg, const char *alts)
{
    const char *p = alts;
    for (;;) {
        const char *bar = strchr(p, '|');
        size_t len = bar ? (size_t)(bar - p) : strlen(p);
        for (const char *h = msg; len == 0 || *h; h++) {
            size_t k = 0;
            while (k < len && h[k] && tolower((unsigned char)h[k]) == tolower((unsigned char)p[k]))
                k++;
            if (k == len)
                return 1;
        }
        if (!bar)
            return 0;
        p = bar + 1;
    }
}

static const char *codes_text(unsigned mask)
{
    static char text[512];
    size_t used = 0;
    text[0] = '\0';
    for (int c = 0; c < 32; c++)
        if (mask & (1u << c))
            used += (size_t)snprintf(text + used, sizeof text - used, "%s%d (%s)",
                                     used ? " or " : "", c, demill_strerror(c));
    return text;
}

#define PRIMER_KEY (-12345)

static void bad_check(scene *sc, const char *call, unsigned mask, demill_status got,
                      const char *const *needles, snap *before, const char *primer)
{
    char msg[768];
    snprintf(msg, sizeof msg, "%s", demill_world_last_error(sc->w));
    sc->calls++;
    if (got < 0 || got > 31 || !(mask & (1u << got)))
        note_fail(sc, call, "returned %d (%s), expected %s; message \"%s\"", (int)got,
             demill_strerror(got), codes_text(mask), msg);
    if (!msg[0])
        note_fail(sc, call, "the last-error message is empty");
    else if (!strcmp(msg, primer))
        note_fail(sc, call, "the last-error message was not set by the call (still \"%s\")", msg);
    for (size_t k = 0; needles[k]; k++)
        if (!mentions(msg, needles[k]))
            note_fail(sc, call, "message \"%s\" does not mention \"%s\"", msg, needles[k]);
    snap after;
    snap_take(sc, &after);
    char diff[1024];
    if (snap_diff(before, &after, diff, sizeof diff))
        note_fail(sc, call, "the world changed: %s", diff);
    snap_free(before);
    snap_free(&after);
}

/* Snapshot, a primer error (so that a call that fails without setting its
 * own message is caught), the bad call, then the checks. */
#define BAD_ANY(sc, mask, call, ...)                                                           \
    do {                                                                                       \
        snap before_;                                                                          \
        snap_take((sc), &before_);                                                             \
        double primer_v_;                                                                      \
        char primer_[768];                                                                     \
        demill_world_get((sc)->w, PRIMER_KEY, &primer_v_);                                     \
        snprintf(primer_, sizeof primer_, "%s", demill_world_last_error((sc)->w));            \
        demill_status got_ = (call);                                                           \
        const char *const needles_[] = {__VA_ARGS__, NULL};                                    \
        bad_check((sc), #call, (mask), got_, needles_, &before_, primer_);                     \
    } while (0)
#define BIT(code) (1u << (code))
#define BAD(sc, code, call, ...) BAD_ANY(sc, BIT(code), call, __VA_ARGS__)

/* ------------------------------------------------------------------------ */
/* The scene                                                                  */

static void set_model(demill_world *w, demill_id a, demill_id b, int normal, int damping,
                      int tangential, int rolling)
{
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_NORMAL, normal));
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_DAMPING, damping));
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_TANGENTIAL, tangential));
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_ROLLING, rolling));
}

static demill_id add_one(scene *sc, demill_id mat, double x, double y, double z, double r)
{
    double p[3] = {x, y, sc->dim == 3 ? z : 0.0};
    demill_id id;
    DM_OK(sc->w, demill_particles_add(sc->w, mat, 1, p, &r, NULL, 0, &id));
    ck_assert_uint_lt(sc->np, MAXP);
    sc->pid[sc->np++] = id;
    return id;
}

/* Two materials A (Hertz + restitution + Mindlin with itself) and B (linear +
 * viscous + Coulomb + rolling torque with itself; linear + restitution +
 * spring + rolling with A), a plane wall y = 0 of material A sliding along x,
 * and 20 particles (A and B alternating) stacked on it with small overlaps,
 * set moving and spinning, then stepped BUILD_STEPS times. */
static void scene_build(scene *sc, int dim)
{
    memset(sc, 0, sizeof *sc);
    sc->dim = dim;
    ctx(sc, "building the scene");
    ck_assert_int_eq(demill_world_create(dim, &sc->w), DEMILL_OK);
    demill_world *w = sc->w;
    demill_id a, b;
    DM_OK(w, demill_material_create(w, &a));
    DM_OK(w, demill_material_create(w, &b));
    sc->mat[0] = a;
    sc->mat[1] = b;
    sc->nmat = 2;
    DM_OK(w, demill_material_set(w, a, DEMILL_MATERIAL_RESTITUTION, 0.6));
    DM_OK(w, demill_material_set(w, a, DEMILL_MATERIAL_FRICTION, 0.4));
    DM_OK(w, demill_material_set(w, a, DEMILL_MATERIAL_ROLLING_FRICTION, 0.05));
    DM_OK(w, demill_material_set(w, b, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, b, DEMILL_MATERIAL_STIFFNESS, 2e5));
    DM_OK(w, demill_material_set(w, b, DEMILL_MATERIAL_RESTITUTION, 0.4));
    DM_OK(w, demill_material_set(w, b, DEMILL_MATERIAL_FRICTION, 0.3));
    DM_OK(w, demill_material_set(w, b, DEMILL_MATERIAL_ROLLING_FRICTION, 0.1));
    set_model(w, a, a, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_MINDLIN,
              DEMILL_ROLLING_NONE);
    set_model(w, b, b, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, DEMILL_TANGENTIAL_COULOMB,
              DEMILL_ROLLING_CONSTANT_TORQUE);
    DM_OK(w, demill_pair_set(w, b, b, DEMILL_PAIR_VISCOUS_DAMPING, 2.0));
    set_model(w, a, b, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_SPRING,
              DEMILL_ROLLING_CONSTANT_TORQUE);

    const double point[3] = {0, 0, 0}, normal[3] = {0, 1, 0}, vel[3] = {0.02, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, a, point, normal, &sc->wall[0]));
    sc->nwall = 1;
    DM_OK(w, demill_wall_set_motion(w, sc->wall[0], vel, NULL, NULL));

    const double d = 2 * RAD * 0.9998, y0 = RAD * 0.9998;
    int k = 0;
    if (dim == 3) {
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++, k++)
                add_one(sc, sc->mat[k % 2], (i - 1.5) * d, y0, (j - 1.5) * d, RAD);
        const double h = sqrt(4 * RAD * RAD - d * d / 2) * 0.9998;
        for (int i = 0; i <= 2; i += 2)
            for (int j = 0; j <= 2; j += 2, k++)
                add_one(sc, sc->mat[k % 2], (i - 1.0) * d, y0 + h, (j - 1.0) * d, RAD);
    } else {
        for (int row = 0; row < 5; row++)
            for (int i = 0; i < 6 - row; i++, k++)
                add_one(sc, sc->mat[k % 2], (i - (5 - row) / 2.0) * d,
                        y0 + row * d * sqrt(3.0) / 2 * 0.9998, 0, RAD);
    }
    ck_assert_uint_eq(sc->np, 20);

    double v[60], om[60];
    for (int i = 0; i < 20; i++) {
        v[3 * i] = 2e-3 * sin(1.7 * i + 0.3);
        v[3 * i + 1] = 1e-3 * cos(2.3 * i);
        v[3 * i + 2] = dim == 3 ? 2e-3 * sin(0.9 * i + 1) : 0.0;
        om[3 * i] = dim == 3 ? 0.5 * cos(1.1 * i) : 0.0;
        om[3 * i + 1] = dim == 3 ? 0.5 * sin(0.7 * i) : 0.0;
        om[3 * i + 2] = 0.5 * cos(1.9 * i);
    }
    DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_VELOCITY, v, 20));
    DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_ANGULAR_VELOCITY, om, 20));
    DM_OK(w, demill_world_step(w, BUILD_STEPS));

    /* the scene is what the checks need: particle and wall contacts, with
     * history (how many particle contacts survive the build depends on the
     * contact model's details, so only a few are asked for) */
    double c, wc, et;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &c));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &wc));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_ELASTIC_TANGENTIAL, &et));
    ck_assert_msg(c >= 3 && wc >= 5 && et > 0,
                  "%dD scene: %g contacts, %g wall contacts, tangential energy %g", dim, c, wc,
                  et);
}

static void scene_free(scene *sc)
{
    demill_world_destroy(sc->w);
    sc->w = NULL;
}

static size_t pcount(scene *sc)
{
    size_t n = 0;
    DM_OK(sc->w, demill_particles_read_ids(sc->w, DEMILL_PARTICLE_ID, NULL, 0, &n));
    return n;
}

/* A field of every particle in id order (caller frees). */
static double *read_field(scene *sc, int32_t f, size_t *n)
{
    *n = pcount(sc);
    double *buf = calloc(3 * *n + 3, sizeof *buf);
    ck_assert_ptr_nonnull(buf);
    size_t cnt;
    DM_OK(sc->w, demill_particles_read(sc->w, f, buf, *n, &cnt));
    return buf;
}

static demill_id id_at(scene *sc, size_t k)
{
    size_t n = pcount(sc);
    demill_id *ids = calloc(n + 1, sizeof *ids);
    ck_assert_ptr_nonnull(ids);
    DM_OK(sc->w, demill_particles_read_ids(sc->w, DEMILL_PARTICLE_ID, ids, n, &n));
    ck_assert_uint_lt(k, n);
    demill_id id = ids[k];
    free(ids);
    return id;
}

static int same(scene *a, scene *b, const char *when)
{
    snap sa, sb;
    char diff[1024];
    snap_take(a, &sa);
    snap_take(b, &sb);
    int d = snap_diff(&sa, &sb, diff, sizeof diff);
    if (d) {
        ctx(a, "twin comparison");
        note_fail(a, when, "%s", diff);
    }
    snap_free(&sa);
    snap_free(&sb);
    return !d;
}

typedef void (*scene_fn)(scene *sc);

/* Builds twin scenes, runs setup on both, the bad calls on one, fix on both,
 * steps both and compares them. Returns the number of failures; the first is
 * appended to `first`. */
static int run_twins(int dim, scene_fn setup, scene_fn bad, scene_fn fix, char *first,
                     size_t len)
{
    scene a, b;
    scene_build(&a, dim);
    scene_build(&b, dim);
    if (setup) {
        setup(&a);
        setup(&b);
    }
    same(&a, &b, "the twin scenes differ before any bad call");
    bad(&a);
    ck_assert_msg(a.calls > 0, "no bad call was made");
    while (b.nsnaps < a.nsnaps) { /* the twin makes the same queries */
        snap s;
        snap_take(&b, &s);
        snap_free(&s);
    }
    if (fix) {
        fix(&a);
        fix(&b);
    }
    ctx(&a, "stepping after the bad calls");
    DM_OK(a.w, demill_world_step(a.w, TWIN_STEPS));
    DM_OK(b.w, demill_world_step(b.w, TWIN_STEPS));
    same(&a, &b, "after the bad calls and 100 steps the world differs from its twin");
    if (a.failures && !first[0])
        snprintf(first, len, "%s", a.first);
    int failures = a.failures;
    scene_free(&a);
    scene_free(&b);
    return failures;
}

static void both_dims(scene_fn setup, scene_fn bad, scene_fn fix)
{
    char first[2048] = "";
    int failures = 0;
    for (int dim = 2; dim <= 3; dim++)
        failures += run_twins(dim, setup, bad, fix, first, sizeof first);
    ck_assert_msg(failures == 0, "%d failure(s) (all listed on stderr); first: %s", failures,
                  first);
}

/* ------------------------------------------------------------------------ */
/* World parameters                                                           */

static void bad_world_set(scene *sc)
{
    demill_world *w = sc->w;
    for (int32_t key = 100; key <= 114; key++) {
        const char *name = demill_param_name(key);
        ck_assert_ptr_nonnull(name);
        /* NaN is also a nonzero gravity z in 2D, and disc thickness is 2D only */
        int both = (sc->dim == 2 && key == DEMILL_WORLD_GRAVITY_Z) ||
                   (sc->dim == 3 && key == DEMILL_WORLD_DISC_THICKNESS);
        for (int k = 0; k < 3; k++) {
            ctx(sc, "world_set key %d = %g", (int)key, nonfinite[k]);
            if (both)
                BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                        demill_world_set(w, key, nonfinite[k]), name);
            else
                BAD(sc, DEMILL_ERR_NOT_FINITE, demill_world_set(w, key, nonfinite[k]), name,
                    NONFINITE);
        }
    }
    static const struct {
        int32_t key;
        double v;
    } invalid[] = {
        {DEMILL_WORLD_TIME_STEP, 0.0},        {DEMILL_WORLD_TIME_STEP, -0.0},
        {DEMILL_WORLD_TIME_STEP, -1e-5},      {DEMILL_WORLD_TIME_STEP, -1e300},
        {DEMILL_WORLD_SKIN, 0.0},             {DEMILL_WORLD_SKIN, -0.2},
        {DEMILL_WORLD_SKIN, 0.009},           {DEMILL_WORLD_SKIN, 10.5},
        {DEMILL_WORLD_ENERGY_TRACKING, 2},    {DEMILL_WORLD_ENERGY_TRACKING, -1},
        {DEMILL_WORLD_ENERGY_TRACKING, 0.5},
        {DEMILL_WORLD_THREADS, -1},           {DEMILL_WORLD_THREADS, 1.5},
        {DEMILL_WORLD_THREADS, 1025},
        {DEMILL_WORLD_REFINE_TOLERANCE, 0.0},  {DEMILL_WORLD_REFINE_TOLERANCE, -1e-3},
        {DEMILL_WORLD_REFINE_TOLERANCE, 1.5},
        {DEMILL_WORLD_REFINE_MAX_ITERATIONS, 0}, {DEMILL_WORLD_REFINE_MAX_ITERATIONS, 101},
        {DEMILL_WORLD_REFINE_MAX_ITERATIONS, 2.5},
        {DEMILL_WORLD_WATCHDOG, 2},            {DEMILL_WORLD_WATCHDOG, 0.5},
        {DEMILL_WORLD_WATCHDOG_OVERLAP, 0.0},  {DEMILL_WORLD_WATCHDOG_OVERLAP, 1.01},
        {DEMILL_WORLD_WATCHDOG_INTERVAL, 0},   {DEMILL_WORLD_WATCHDOG_INTERVAL, 1.5},
        {DEMILL_WORLD_WATCHDOG_INTERVAL, 2e6},
        {DEMILL_WORLD_SINGLE_PRECISION, 2},    {DEMILL_WORLD_SINGLE_PRECISION, 0.5},
        {DEMILL_WORLD_ORIENTATION_TRACKING, 2}, {DEMILL_WORLD_ORIENTATION_TRACKING, -1},
    };
    for (size_t k = 0; k < sizeof invalid / sizeof invalid[0]; k++) {
        ctx(sc, "world_set key %d = %g", (int)invalid[k].key, invalid[k].v);
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_world_set(w, invalid[k].key, invalid[k].v),
            demill_param_name(invalid[k].key));
    }
    if (sc->dim == 2) {
        ctx(sc, "negative disc thickness");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, -0.01), "world.disc_thickness");
        ctx(sc, "gravity z in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_world_set(w, DEMILL_WORLD_GRAVITY_Z, 1.0),
            "world.gravity_z");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_world_set(w, DEMILL_WORLD_GRAVITY_Z, -9.81),
            "world.gravity_z");
    } else {
        ctx(sc, "disc thickness in 3D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, 0.01),
            "world.disc_thickness");
    }
    /* more than one thread needs a library built with threads; the failed
     * setting changes nothing */
    ctx(sc, "world.threads = 2");
    demill_status st = demill_world_set(w, DEMILL_WORLD_THREADS, 2);
    ck_assert_msg(st == DEMILL_OK || st == DEMILL_ERR_UNSUPPORTED, "world.threads = 2: %s",
                  demill_strerror(st));
    double threads;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_THREADS, &threads));
    ck_assert_double_eq(threads, st == DEMILL_OK ? 2 : 1);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_THREADS, 1));
    static const double integrators[] = {0, 4, 7, -1, 1000};
    for (size_t k = 0; k < sizeof integrators / sizeof integrators[0]; k++) {
        ctx(sc, "integrator %g", integrators[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY,
            demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrators[k]), "world.integrator");
    }
    static const int32_t unknown[] = {0,   1,   99,  117, 120,  149, 159, 199,
                                      200, 250, 300, 399, -1, 2147483647, -2147483647 - 1};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown[k]);
        ctx(sc, "world_set unknown key %d", (int)unknown[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_world_set(w, unknown[k], 1.0), num);
        double v = 42.0;
        ctx(sc, "world_get unknown key %d", (int)unknown[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_world_get(w, unknown[k], &v), num);
        ck_assert_msg(v == 42.0, "world_get wrote %g for unknown key %d", v, (int)unknown[k]);
    }
    for (int32_t key = 150; key <= 158; key++) {
        double cur;
        DM_OK(w, demill_world_get(w, key, &cur));
        const double tries[2] = {cur, cur + 1};
        for (int k = 0; k < 2; k++) {
            ctx(sc, "world_set read-only key %d = %g", (int)key, tries[k]);
            BAD(sc, DEMILL_ERR_READ_ONLY, demill_world_set(w, key, tries[k]),
                demill_param_name(key), "read");
        }
    }
    for (int32_t key = 100; key <= 158; key += (key == 114 ? 36 : 1)) {
        ctx(sc, "world_get key %d into NULL", (int)key);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_world_get(w, key, NULL), "NULL");
    }
}

START_TEST(world_parameters)
{
    both_dims(NULL, bad_world_set, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Material parameters                                                        */

static void bad_material_set(scene *sc)
{
    demill_world *w = sc->w;
    for (int m = 0; m < 2; m++) {
        const demill_id mat = sc->mat[m];
        static const int32_t keys[] = {200, 201, 202, 203, 204, 205, 206, 210, 212, 213};
        for (size_t q = 0; q < sizeof keys / sizeof keys[0]; q++)
            for (int k = 0; k < 3; k++) {
                const int32_t key = keys[q];
                ctx(sc, "material %d key %d = %g", m, (int)key, nonfinite[k]);
                BAD(sc, DEMILL_ERR_NOT_FINITE, demill_material_set(w, mat, key, nonfinite[k]),
                    demill_param_name(key), NONFINITE);
            }
        static const struct {
            int32_t key;
            double v;
        } invalid[] = {
            {DEMILL_MATERIAL_DENSITY, 0.0},          {DEMILL_MATERIAL_DENSITY, -0.0},
            {DEMILL_MATERIAL_DENSITY, -2500},        {DEMILL_MATERIAL_YOUNGS_MODULUS, 0.0},
            {DEMILL_MATERIAL_YOUNGS_MODULUS, -1e8},  {DEMILL_MATERIAL_POISSON_RATIO, 0.5},
            {DEMILL_MATERIAL_POISSON_RATIO, -0.1},   {DEMILL_MATERIAL_POISSON_RATIO, 0.7},
            {DEMILL_MATERIAL_STIFFNESS, 0.0},        {DEMILL_MATERIAL_STIFFNESS, -1e5},
            {DEMILL_MATERIAL_RESTITUTION, -1e-300},  {DEMILL_MATERIAL_RESTITUTION, 1.5},
            {DEMILL_MATERIAL_RESTITUTION, -0.5},     {DEMILL_MATERIAL_RESTITUTION, 1.0000001},
            {DEMILL_MATERIAL_FRICTION, -0.1},        {DEMILL_MATERIAL_ROLLING_FRICTION, -0.1},
            {DEMILL_MATERIAL_YIELD_STRESS, -1e-300}, {DEMILL_MATERIAL_YIELD_STRESS, 2e30},
            {DEMILL_MATERIAL_LOCAL_DAMPING, -0.1},   {DEMILL_MATERIAL_LOCAL_DAMPING, 1.0},
            {DEMILL_MATERIAL_LOCAL_DAMPING, -1e-300},
            {DEMILL_MATERIAL_RIGID, 0.5},            {DEMILL_MATERIAL_RIGID, 2},
            {DEMILL_MATERIAL_RIGID, -1},             {DEMILL_MATERIAL_RIGID, 1e-300},
            {DEMILL_MATERIAL_SURFACE_ENERGY, -1e-300}, {DEMILL_MATERIAL_SURFACE_ENERGY, 2e6},
        };
        for (size_t k = 0; k < sizeof invalid / sizeof invalid[0]; k++) {
            ctx(sc, "material %d key %d = %g", m, (int)invalid[k].key, invalid[k].v);
            BAD(sc, DEMILL_ERR_INVALID_VALUE,
                demill_material_set(w, mat, invalid[k].key, invalid[k].v),
                demill_param_name(invalid[k].key));
        }
        static const int32_t unknown[] = {0, 100, 199, 216, 250, 299, 300, 310, -1};
        for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
            char num[16];
            snprintf(num, sizeof num, "%d", (int)unknown[k]);
            ctx(sc, "material %d unknown key %d", m, (int)unknown[k]);
            BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_material_set(w, mat, unknown[k], 1.0), num);
            double v = 42.0;
            BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_material_get(w, mat, unknown[k], &v), num);
            ck_assert(v == 42.0);
        }
        ctx(sc, "material %d get into NULL", m);
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_material_get(w, mat, DEMILL_MATERIAL_DENSITY, NULL), "NULL");
    }
}

START_TEST(material_parameters)
{
    both_dims(NULL, bad_material_set, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Pair parameters                                                            */

static void bad_pair_set(scene *sc)
{
    demill_world *w = sc->w;
    static const int32_t keys[] = {300, 301, 302, 303, 304, 310, 311, 312, 313, 314, 315, 316, 317,
                                   318, 319, 320, 321, 322, 323, 324, 327, 328, 331, 332, 333, 334};
    const demill_id A = sc->mat[0], B = sc->mat[1];
    const demill_id pairs[4][2] = {{A, B}, {B, A}, {A, A}, {B, B}};
    for (int p = 0; p < 4; p++) {
        const demill_id a = pairs[p][0], b = pairs[p][1];
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
            for (int j = 0; j < 3; j++) {
                ctx(sc, "pair %d key %d = %g", p, (int)keys[k], nonfinite[j]);
                BAD(sc, DEMILL_ERR_NOT_FINITE, demill_pair_set(w, a, b, keys[k], nonfinite[j]),
                    demill_param_name(keys[k]), NONFINITE);
            }
        static const struct {
            int32_t key;
            double v;
        } enums[] = {
            {DEMILL_PAIR_NORMAL, 6},      {DEMILL_PAIR_NORMAL, 7},     {DEMILL_PAIR_NORMAL, -1},
            {DEMILL_PAIR_NORMAL, 100},    {DEMILL_PAIR_DAMPING, 3},    {DEMILL_PAIR_DAMPING, -1},
            {DEMILL_PAIR_TANGENTIAL, 4},  {DEMILL_PAIR_TANGENTIAL, -1},
            {DEMILL_PAIR_ROLLING, 3},     {DEMILL_PAIR_ROLLING, -1},
            {DEMILL_PAIR_COHESION, 3},    {DEMILL_PAIR_COHESION, -1},
        };
        for (size_t k = 0; k < sizeof enums / sizeof enums[0]; k++) {
            ctx(sc, "pair %d law key %d = %g", p, (int)enums[k].key, enums[k].v);
            BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_pair_set(w, a, b, enums[k].key, enums[k].v),
                demill_param_name(enums[k].key));
        }
        static const struct {
            int32_t key;
            double v;
        } invalid[] = {
            {DEMILL_PAIR_RESTITUTION, -1e-300},
            {DEMILL_PAIR_RESTITUTION, 1.5},
            {DEMILL_PAIR_RESTITUTION, -0.5},
            {DEMILL_PAIR_FRICTION, -0.1},
            {DEMILL_PAIR_ROLLING_FRICTION, -0.1},
            {DEMILL_PAIR_NORMAL_STIFFNESS, 0.0},
            {DEMILL_PAIR_NORMAL_STIFFNESS, -1e5},
            {DEMILL_PAIR_VISCOUS_DAMPING, -1.0},
            {DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, 0.0},
            {DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, -0.3},
            {DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR, -1.0},
            {DEMILL_PAIR_COULOMB_REGULARISATION, 0.0},
            {DEMILL_PAIR_COULOMB_REGULARISATION, -1.0},
            {DEMILL_PAIR_ROLLING_REGULARISATION, 0.0},
            {DEMILL_PAIR_ROLLING_REGULARISATION, -1.0},
            {DEMILL_PAIR_CLAMP_NORMAL, 2},
            {DEMILL_PAIR_CLAMP_NORMAL, -1},
            {DEMILL_PAIR_CLAMP_NORMAL, 0.5},
            {DEMILL_PAIR_YIELD_PRESSURE, -1e-300},
            {DEMILL_PAIR_YIELD_PRESSURE, 2e30},
            {DEMILL_PAIR_PLASTIC_FIT_C0, -2e30},
            {DEMILL_PAIR_PLASTIC_FIT_C1, 2e30},
            {DEMILL_PAIR_PLASTIC_FIT_C2, -2e30},
            {DEMILL_PAIR_PLASTIC_FIT_EXPONENT, 0.0},
            {DEMILL_PAIR_PLASTIC_FIT_EXPONENT, 3.0},
            {DEMILL_PAIR_PLASTIC_FIT_EXPONENT, -1.0},
            {DEMILL_PAIR_ROLLING_STIFFNESS, -1e-300},
            {DEMILL_PAIR_ROLLING_STIFFNESS, -0.1},
            {DEMILL_PAIR_ROLLING_DAMPING_RATIO, -0.3},
            {DEMILL_PAIR_ADHESION_WORK, -1e-3},
            {DEMILL_PAIR_ADHESION_WORK, 2e6},
            {DEMILL_PAIR_LIQUID_VOLUME, 0.0},
            {DEMILL_PAIR_LIQUID_VOLUME, -1e-12},
            {DEMILL_PAIR_LIQUID_VOLUME, 2.0},
            {DEMILL_PAIR_SURFACE_TENSION, -0.01},
            {DEMILL_PAIR_CONTACT_ANGLE, -0.1},
            {DEMILL_PAIR_CONTACT_ANGLE, 1.6},
        };
        for (size_t k = 0; k < sizeof invalid / sizeof invalid[0]; k++) {
            ctx(sc, "pair %d key %d = %g", p, (int)invalid[k].key, invalid[k].v);
            BAD(sc, DEMILL_ERR_INVALID_VALUE,
                demill_pair_set(w, a, b, invalid[k].key, invalid[k].v),
                demill_param_name(invalid[k].key));
        }
        static const int32_t unknown[] = {0, 100, 200, 299, 305, 309, 339, 390, 399, -1};
        for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
            char num[16];
            snprintf(num, sizeof num, "%d", (int)unknown[k]);
            ctx(sc, "pair %d unknown key %d", p, (int)unknown[k]);
            BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_pair_set(w, a, b, unknown[k], 1.0), num);
            double v = 42.0;
            BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_pair_get(w, a, b, unknown[k], &v), num);
            ck_assert(v == 42.0);
        }
        ctx(sc, "pair %d get into NULL", p);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_pair_get(w, a, b, DEMILL_PAIR_NORMAL, NULL),
            "NULL");
    }
}

START_TEST(pair_parameters)
{
    both_dims(NULL, bad_pair_set, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Adding particles                                                           */

/* Five valid particles far above the stack and apart from each other. */
static void far_batch(const scene *sc, double pos[15], double rad[5], double vel[15])
{
    for (int k = 0; k < 5; k++) {
        pos[3 * k] = -0.2 + 0.05 * k;
        pos[3 * k + 1] = 0.3;
        pos[3 * k + 2] = sc->dim == 3 ? 0.01 * k : 0.0;
        rad[k] = RAD;
        vel[3 * k] = 0.01;
        vel[3 * k + 1] = -0.02;
        vel[3 * k + 2] = sc->dim == 3 ? 0.005 : 0.0;
    }
}

static void bad_particles_add(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id mat = sc->mat[1];
    double pos[15], rad[5], vel[15];
    demill_id ids[5];
    static const char *const comp_name[] = {"position", "velocity"};
    for (uint32_t flags = 0; flags <= DEMILL_ADD_NO_OVERLAP; flags++) {
        /* a non-finite value in particle 2 of 5 */
        for (int which = 0; which < 2; which++)
            for (int c = 0; c < 3; c++)
                for (int j = 0; j < 3; j++) {
                    far_batch(sc, pos, rad, vel);
                    (which ? vel : pos)[3 * 2 + c] = nonfinite[j];
                    ctx(sc, "particles_add flags %u: %s[%d] of particle 2 = %g", (unsigned)flags,
                        comp_name[which], c, nonfinite[j]);
                    if (sc->dim == 2 && c == 2)
                        BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                                demill_particles_add(w, mat, 5, pos, rad, vel, flags, ids),
                                "particle 2", comp_name[which]);
                    else
                        BAD(sc, DEMILL_ERR_NOT_FINITE,
                            demill_particles_add(w, mat, 5, pos, rad, vel, flags, ids),
                            "particle 2", comp_name[which], NONFINITE);
                }
        for (int j = 0; j < 3; j++) {
            far_batch(sc, pos, rad, vel);
            rad[2] = nonfinite[j];
            ctx(sc, "particles_add flags %u: radius of particle 2 = %g", (unsigned)flags,
                nonfinite[j]);
            BAD(sc, DEMILL_ERR_NOT_FINITE,
                demill_particles_add(w, mat, 5, pos, rad, vel, flags, ids), "particle 2",
                "radius", NONFINITE);
        }
        /* zero and negative radii, at the start, middle and end of the batch */
        static const double radii[] = {0.0, -0.0, -RAD, -1e300};
        for (size_t j = 0; j < sizeof radii / sizeof radii[0]; j++)
            for (int at = 0; at < 5; at += 2) {
                char who[32];
                snprintf(who, sizeof who, "particle %d", at);
                far_batch(sc, pos, rad, vel);
                rad[at] = radii[j];
                ctx(sc, "particles_add flags %u: radius of particle %d = %g", (unsigned)flags,
                    at, radii[j]);
                BAD(sc, DEMILL_ERR_INVALID_VALUE,
                    demill_particles_add(w, mat, 5, pos, rad, NULL, flags, ids), who, "radius");
            }
        /* the first bad particle is the one named */
        far_batch(sc, pos, rad, vel);
        rad[1] = -RAD;
        rad[3] = -RAD;
        ctx(sc, "particles_add flags %u: particles 1 and 3 bad", (unsigned)flags);
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_particles_add(w, mat, 5, pos, rad, vel, flags, ids), "particle 1", "radius");
        far_batch(sc, pos, rad, vel);
        ctx(sc, "particles_add flags %u: NULL arrays", (unsigned)flags);
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_particles_add(w, mat, 5, NULL, rad, vel, flags, ids), "position");
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_particles_add(w, mat, 5, pos, NULL, vel, flags, ids), "radi");
        if (sc->dim == 2) {
            for (int which = 0; which < 2; which++) {
                far_batch(sc, pos, rad, vel);
                (which ? vel : pos)[3 * 2 + 2] = 0.01;
                ctx(sc, "particles_add flags %u: %s z of particle 2 in 2D", (unsigned)flags,
                    comp_name[which]);
                BAD(sc, DEMILL_ERR_DIMENSION,
                    demill_particles_add(w, mat, 5, pos, rad, vel, flags, ids), "particle 2",
                    comp_name[which]);
            }
        }
    }
}

START_TEST(particles_add_values)
{
    both_dims(NULL, bad_particles_add, NULL);
}
END_TEST

/* Overlapping batches: against an existing particle, within the batch,
 * against the wall, behind the wall, and a large particle reaching an
 * existing one. Each returns the index of its first offending particle. */
typedef struct overlap_case {
    const char *name;
    int index; /* the offending particle of the batch */
    const char *needle;
} overlap_case;

static const overlap_case overlap_cases[] = {
    {"overlaps an existing particle", 2, "particle 2"},
    {"two new particles overlap each other", 2, "particle 2|particle 3"},
    {"penetrates the wall", 4, "wall"},
    {"lies behind the wall", 1, "wall"},
    {"sits exactly on an existing particle", 0, "particle 0"},
    {"is large and reaches an existing particle", 3, "particle 3"},
};
#define NOVERLAP (sizeof overlap_cases / sizeof overlap_cases[0])

static void overlap_batch(scene *sc, size_t c, double pos[15], double rad[5], double vel[15])
{
    size_t n;
    double *x = read_field(sc, DEMILL_PARTICLE_POSITION, &n);
    far_batch(sc, pos, rad, vel);
    switch (c) {
    case 0:
        pos[6] = x[0] + 0.5 * RAD;
        pos[7] = x[1];
        pos[8] = x[2];
        break;
    case 1:
        pos[9] = pos[6] + 1.5 * RAD;
        pos[10] = pos[7];
        pos[11] = pos[8];
        break;
    case 2:
        pos[12] = -0.3;
        pos[13] = 0.5 * RAD;
        break;
    case 3:
        pos[3] = -0.3;
        pos[4] = -0.1;
        break;
    case 4:
        memcpy(pos, x + 3 * (n / 2), 3 * sizeof *pos);
        break;
    default: {
        /* centre 0.03 m + RAD above the highest particle, radius 0.03 m + RAD/2 */
        size_t top = 0;
        for (size_t i = 1; i < n; i++)
            if (x[3 * i + 1] > x[3 * top + 1])
                top = i;
        memcpy(pos + 9, x + 3 * top, 3 * sizeof *pos);
        pos[10] += 0.03 + RAD;
        rad[3] = 0.03 + 0.5 * RAD;
        break;
    }
    }
    free(x);
}

static void bad_overlap(scene *sc)
{
    double pos[15], rad[5], vel[15];
    demill_id ids[5];
    for (size_t c = 0; c < NOVERLAP; c++) {
        overlap_batch(sc, c, pos, rad, vel);
        ctx(sc, "DEMILL_ADD_NO_OVERLAP: particle %d %s", overlap_cases[c].index,
            overlap_cases[c].name);
        BAD(sc, DEMILL_ERR_OVERLAP,
            demill_particles_add(sc->w, sc->mat[c % 2], 5, pos, rad, vel, DEMILL_ADD_NO_OVERLAP,
                                 ids),
            overlap_cases[c].needle, "overlap");
    }
}

START_TEST(particles_add_overlap)
{
    both_dims(NULL, bad_overlap, NULL);
}
END_TEST

/* Without the flag the same batches are accepted as given. */
START_TEST(particles_add_overlap_allowed_without_flag)
{
    for (int dim = 2; dim <= 3; dim++)
        for (size_t c = 0; c < NOVERLAP; c++) {
            scene sc;
            scene_build(&sc, dim);
            double pos[15], rad[5], vel[15];
            demill_id ids[5];
            overlap_batch(&sc, c, pos, rad, vel);
            size_t n0 = pcount(&sc);
            DM_OK(sc.w, demill_particles_add(sc.w, sc.mat[c % 2], 5, pos, rad, vel, 0, ids));
            ck_assert_uint_eq(pcount(&sc), n0 + 5);
            for (int k = 0; k < 5; k++) {
                double x[3], r;
                DM_OK(sc.w, demill_particle_get(sc.w, ids[k], DEMILL_PARTICLE_POSITION, x));
                DM_OK(sc.w, demill_particle_get(sc.w, ids[k], DEMILL_PARTICLE_RADIUS, &r));
                ck_assert_msg(!memcmp(x, pos + 3 * k, sizeof x) && r == rad[k],
                              "%dD case %zu: particle %d not added as given", dim, c, k);
            }
            /* the overlaps (up to coincident centres) are deeper than the
             * watchdog allows; without it the world steps */
            DM_OK(sc.w, demill_world_set(sc.w, DEMILL_WORLD_WATCHDOG, 0));
            DM_OK(sc.w, demill_world_step(sc.w, 1));
            scene_free(&sc);
        }
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Writing particles                                                          */

static const int32_t writable[] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                                   DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_RADIUS,
                                   DEMILL_PARTICLE_ANGLE};
static const char *const field_word[] = {"", "position", "velocity", "angular", "radius",
                                         "", "", "", "angle"};

/* Components a 2D world requires to be 0 for a field (bit c). */
static int zero_in_2d(int32_t f)
{
    return f == DEMILL_PARTICLE_POSITION || f == DEMILL_PARTICLE_VELOCITY ? 4
           : f == DEMILL_PARTICLE_ANGULAR_VELOCITY                        ? 3
                                                                          : 0;
}

static void bad_particles_write(scene *sc)
{
    demill_world *w = sc->w;
    const int nf = sc->dim == 2 ? 5 : 4;
    for (int fi = 0; fi < nf; fi++) {
        const int32_t f = writable[fi];
        const size_t size = (size_t)demill_particle_field_size(f);
        size_t n;
        double *cur = read_field(sc, f, &n), *in = calloc(3 * n + 3, sizeof *in);
        ck_assert_ptr_nonnull(in);
        const size_t mid = n / 2;
        char who[32];
        snprintf(who, sizeof who, "particle %zu", mid);
        for (size_t c = 0; c < size; c++)
            for (int j = 0; j < 3; j++) {
                memcpy(in, cur, 3 * n * sizeof *in);
                in[size * mid + c] = nonfinite[j];
                ctx(sc, "particles_write field %d: component %zu of particle %zu = %g", (int)f,
                    c, mid, nonfinite[j]);
                if (sc->dim == 2 && (zero_in_2d(f) >> c & 1))
                    BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                            demill_particles_write(w, f, in, n), who, field_word[f]);
                else
                    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_particles_write(w, f, in, n), who,
                        field_word[f], NONFINITE);
            }
        if (f == DEMILL_PARTICLE_RADIUS) {
            static const double radii[] = {0.0, -0.0, -RAD};
            for (size_t j = 0; j < 3; j++) {
                memcpy(in, cur, n * sizeof *in);
                in[mid] = radii[j];
                ctx(sc, "particles_write radius of particle %zu = %g", mid, radii[j]);
                BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_write(w, f, in, n), who,
                    "radius");
            }
        }
        if (sc->dim == 2)
            for (size_t c = 0; c < size; c++)
                if (zero_in_2d(f) >> c & 1) {
                    memcpy(in, cur, 3 * n * sizeof *in);
                    in[size * mid + c] = 0.5;
                    ctx(sc, "particles_write field %d: component %zu of particle %zu in 2D",
                        (int)f, c, mid);
                    BAD(sc, DEMILL_ERR_DIMENSION, demill_particles_write(w, f, in, n), who,
                        field_word[f]);
                }
        /* wrong counts and NULL */
        const size_t counts[3] = {n - 1, n + 1, 0};
        for (int j = 0; j < 3; j++) {
            char num[32];
            snprintf(num, sizeof num, "%zu", counts[j]);
            memcpy(in, cur, 3 * n * sizeof *in);
            ctx(sc, "particles_write field %d with n = %zu of %zu", (int)f, counts[j], n);
            BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_write(w, f, in, counts[j]), num);
        }
        ctx(sc, "particles_write field %d from NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particles_write(w, f, NULL, n), "NULL");
        free(cur);
        free(in);
    }
    size_t n = pcount(sc);
    double *zeros = calloc(3 * n + 3, sizeof *zeros);
    ck_assert_ptr_nonnull(zeros);
    if (sc->dim == 3) {
        ctx(sc, "particles_write angle in 3D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_particles_write(w, DEMILL_PARTICLE_ANGLE, zeros, n), "angle|2D");
    }
    static const int32_t ro[] = {DEMILL_PARTICLE_MASS, DEMILL_PARTICLE_FORCE,
                                 DEMILL_PARTICLE_TORQUE};
    for (int k = 0; k < 3; k++) {
        size_t m;
        double *cur = read_field(sc, ro[k], &m);
        ctx(sc, "particles_write read-only field %d", (int)ro[k]);
        BAD(sc, DEMILL_ERR_READ_ONLY, demill_particles_write(w, ro[k], cur, m), "read");
        free(cur);
    }
    static const int32_t unknown[] = {0, 11, 99, 100, 101, -1};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown[k]);
        ctx(sc, "particles_write unknown field %d", (int)unknown[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_particles_write(w, unknown[k], zeros, n), num);
    }
    free(zeros);
}

START_TEST(particles_write_values)
{
    both_dims(NULL, bad_particles_write, NULL);
}
END_TEST

static void bad_particle_set(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id p = id_at(sc, pcount(sc) / 2);
    const int nf = sc->dim == 2 ? 5 : 4;
    for (int fi = 0; fi < nf; fi++) {
        const int32_t f = writable[fi];
        const size_t size = (size_t)demill_particle_field_size(f);
        double cur[3] = {0, 0, 0}, in[3];
        DM_OK(w, demill_particle_get(w, p, f, cur));
        for (size_t c = 0; c < size; c++)
            for (int j = 0; j < 3; j++) {
                memcpy(in, cur, sizeof in);
                in[c] = nonfinite[j];
                ctx(sc, "particle_set field %d component %zu = %g", (int)f, c, nonfinite[j]);
                if (sc->dim == 2 && (zero_in_2d(f) >> c & 1))
                    BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                            demill_particle_set(w, p, f, in), field_word[f]);
                else
                    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_particle_set(w, p, f, in),
                        field_word[f], NONFINITE);
            }
        if (f == DEMILL_PARTICLE_RADIUS) {
            static const double radii[] = {0.0, -0.0, -RAD};
            for (int j = 0; j < 3; j++) {
                ctx(sc, "particle_set radius = %g", radii[j]);
                BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particle_set(w, p, f, &radii[j]),
                    "radius");
            }
        }
        if (sc->dim == 2)
            for (size_t c = 0; c < size; c++)
                if (zero_in_2d(f) >> c & 1) {
                    memcpy(in, cur, sizeof in);
                    in[c] = 0.5;
                    ctx(sc, "particle_set field %d component %zu in 2D", (int)f, c);
                    BAD(sc, DEMILL_ERR_DIMENSION, demill_particle_set(w, p, f, in),
                        field_word[f]);
                }
        ctx(sc, "particle_set field %d from NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particle_set(w, p, f, NULL), "NULL");
        ctx(sc, "particle_get field %d into NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particle_get(w, p, f, NULL), "NULL");
    }
    const double zero[3] = {0, 0, 0};
    if (sc->dim == 3) {
        ctx(sc, "particle_set angle in 3D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_particle_set(w, p, DEMILL_PARTICLE_ANGLE, zero),
            "angle|2D");
    }
    static const int32_t ro[] = {DEMILL_PARTICLE_MASS, DEMILL_PARTICLE_FORCE,
                                 DEMILL_PARTICLE_TORQUE};
    for (int k = 0; k < 3; k++) {
        double cur[3];
        DM_OK(w, demill_particle_get(w, p, ro[k], cur));
        ctx(sc, "particle_set read-only field %d", (int)ro[k]);
        BAD(sc, DEMILL_ERR_READ_ONLY, demill_particle_set(w, p, ro[k], cur), "read");
    }
    static const int32_t unknown[] = {0, 11, 99, 100, 101, -1};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown[k]);
        double out[3] = {42, 42, 42};
        ctx(sc, "particle_set/get unknown field %d", (int)unknown[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_particle_set(w, p, unknown[k], zero), num);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_particle_get(w, p, unknown[k], out), num);
        ck_assert(out[0] == 42 && out[1] == 42 && out[2] == 42);
    }
}

START_TEST(particle_set_values)
{
    both_dims(NULL, bad_particle_set, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Walls                                                                      */

static void bad_walls(scene *sc)
{
    demill_world *w = sc->w;
    const int flat = sc->dim == 2;
    const demill_id mat = sc->mat[1], wall = sc->wall[0];
    const double point[3] = {0.3, -0.05, 0}, normal[3] = {-1, 1, 0};
    static const char *const names[] = {"point", "normal"};
    demill_id out = DEMILL_ID_NONE;
    for (int which = 0; which < 2; which++)
        for (int c = 0; c < 3; c++)
            for (int j = 0; j < 3; j++) {
                double p[3], nrm[3];
                memcpy(p, point, sizeof p);
                memcpy(nrm, normal, sizeof nrm);
                (which ? nrm : p)[c] = nonfinite[j];
                ctx(sc, "wall_add_plane %s[%d] = %g", names[which], c, nonfinite[j]);
                if (flat && c == 2)
                    BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                            demill_wall_add_plane(w, mat, p, nrm, &out), names[which]);
                else
                    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_wall_add_plane(w, mat, p, nrm, &out),
                        names[which], NONFINITE);
            }
    const double zero[3] = {0, 0, 0};
    ctx(sc, "wall_add_plane zero normal");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_plane(w, mat, point, zero, &out),
        "normal");
    ctx(sc, "wall_add_plane NULL arguments");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_plane(w, mat, NULL, normal, &out), "point");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_plane(w, mat, point, NULL, &out), "normal");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_plane(w, mat, point, normal, NULL), "out");
    if (flat) {
        const double pz[3] = {0.3, -0.05, 0.1}, nz[3] = {0, 1, 0.1};
        ctx(sc, "wall_add_plane z in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_plane(w, mat, pz, normal, &out), "point");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_plane(w, mat, point, nz, &out), "normal");
    }

    /* motion: velocity, angular velocity, centre */
    const double v0[3] = {0.01, 0, 0}, w0[3] = {0, 0, 0.5}, c0[3] = {0.1, 0, 0};
    static const char *const mnames[] = {"velocity", "angular", "centre"};
    for (int which = 0; which < 3; which++)
        for (int c = 0; c < 3; c++)
            for (int j = 0; j < 3; j++)
                for (int others = 0; others < 2; others++) {
                    double vv[3], ww[3], cc[3];
                    memcpy(vv, v0, sizeof vv);
                    memcpy(ww, w0, sizeof ww);
                    memcpy(cc, c0, sizeof cc);
                    double *bad = which == 0 ? vv : which == 1 ? ww : cc;
                    bad[c] = nonfinite[j];
                    /* the other two arguments given, or NULL */
                    const double *av = which == 0 || others ? vv : NULL;
                    const double *aw = which == 1 || others ? ww : NULL;
                    const double *ac = which == 2 || others ? cc : NULL;
                    ctx(sc, "wall_set_motion %s[%d] = %g (others %s)", mnames[which], c,
                        nonfinite[j], others ? "given" : "NULL");
                    int dimbad = flat && (which == 1 ? c < 2 : c == 2);
                    if (dimbad)
                        BAD_ANY(sc, BIT(DEMILL_ERR_NOT_FINITE) | BIT(DEMILL_ERR_DIMENSION),
                                demill_wall_set_motion(w, wall, av, aw, ac), mnames[which]);
                    else
                        BAD(sc, DEMILL_ERR_NOT_FINITE,
                            demill_wall_set_motion(w, wall, av, aw, ac), mnames[which],
                            NONFINITE);
                }
    if (flat) {
        const double vz[3] = {0.01, 0, 0.1}, wx[3] = {0.5, 0, 0.5}, wy[3] = {0, 0.5, 0},
                     cz[3] = {0.1, 0, 0.1};
        ctx(sc, "wall_set_motion out of plane in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_set_motion(w, wall, vz, w0, c0), "velocity");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_set_motion(w, wall, v0, wx, c0), "angular");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_set_motion(w, wall, NULL, wy, NULL),
            "angular");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_set_motion(w, wall, v0, w0, cz), "centre");
    }
    static const int32_t unknown[] = {0, 9, 99, -1};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown[k]);
        double o[3] = {42, 42, 42};
        ctx(sc, "wall_get unknown field %d", (int)unknown[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_wall_get(w, wall, unknown[k], o), num);
        ck_assert(o[0] == 42 && o[1] == 42 && o[2] == 42);
    }
    ctx(sc, "wall_get into NULL");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_get(w, wall, DEMILL_WALL_POINT, NULL), "NULL");
}

START_TEST(wall_values)
{
    both_dims(NULL, bad_walls, NULL);
}
END_TEST

/* The finite walls' constructors (3D only), harmonic motion and surface
 * velocity: every bad value refused with its code and a message naming it,
 * the world unchanged. */
static void bad_finite_walls(scene *sc)
{
    demill_world *w = sc->w;
    const int flat = sc->dim == 2;
    const demill_id mat = sc->mat[1], wall = sc->wall[0];
    const double p[3] = {0.3, 0.05, 0}, a[3] = {0, 1, 0}, x[3] = {1, 0, 0};
    demill_id out = DEMILL_ID_NONE;
    if (flat) {
        ctx(sc, "finite walls in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_wall_add_cylinder(w, mat, p, a, 0.1, 0.2, DEMILL_CAPS_NONE, &out), "3D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_wall_add_cone(w, mat, p, a, 0.1, 0.0, 0.2, DEMILL_CAPS_NONE, &out), "3D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_disc(w, mat, p, a, 0.1, 0.0, &out), "3D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_wall_add_rectangle(w, mat, p, a, x, 0.1, 0.1, &out), "3D");
    } else {
        for (int c = 0; c < 3; c++)
            for (int j = 0; j < 3; j++) {
                double pb[3], ab[3];
                memcpy(pb, p, sizeof pb);
                memcpy(ab, a, sizeof ab);
                pb[c] = ab[(c + 1) % 3] = nonfinite[j];
                ctx(sc, "finite walls: point[%d] = %g", c, nonfinite[j]);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_cylinder(w, mat, pb, a, 0.1, 0.2, DEMILL_CAPS_NONE, &out),
                    "point", NONFINITE);
                BAD(sc, DEMILL_ERR_NOT_FINITE, demill_wall_add_disc(w, mat, pb, a, 0.1, 0, &out),
                    "point", NONFINITE);
                ctx(sc, "finite walls: axis[%d] = %g", (c + 1) % 3, nonfinite[j]);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_cone(w, mat, p, ab, 0.1, 0, 0.2, DEMILL_CAPS_NONE, &out),
                    "axis", NONFINITE);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_rectangle(w, mat, p, a, ab, 0.1, 0.1, &out), "direction",
                    NONFINITE);
                ctx(sc, "finite walls: a size of %g", nonfinite[j]);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_cylinder(w, mat, p, a, nonfinite[j], 0.2, 0, &out),
                    "radius", NONFINITE);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_disc(w, mat, p, a, 0.1, nonfinite[j], &out), "inner",
                    NONFINITE);
                BAD(sc, DEMILL_ERR_NOT_FINITE,
                    demill_wall_add_rectangle(w, mat, p, a, x, 0.1, nonfinite[j], &out),
                    "half_height", NONFINITE);
            }
        const double zero[3] = {0, 0, 0}, up[3] = {0, 5, 0};
        ctx(sc, "finite walls: bad shapes");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_wall_add_cylinder(w, mat, p, zero, 0.1, 0.2, 0, &out), "axis", "zero");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_cylinder(w, mat, p, a, -0.1, 0.2, 0, &out),
            "radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_cylinder(w, mat, p, a, 0.0, 0.2, 0, &out),
            "radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_cylinder(w, mat, p, a, 0.1, 0.0, 0, &out),
            "length");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_cylinder(w, mat, p, a, 0.1, -1, 0, &out),
            "length");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_cylinder(w, mat, p, a, 0.1, 0.2, 4, &out),
            "caps");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_wall_add_cone(w, mat, p, a, 0.1, -0.01, 0.2, 0, &out), "radius_end");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_disc(w, mat, p, zero, 0.1, 0, &out),
            "normal", "zero");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_disc(w, mat, p, a, 0.1, 0.1, &out),
            "inner_radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_disc(w, mat, p, a, 0.1, 0.2, &out),
            "inner_radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_disc(w, mat, p, a, 0.0, 0.0, &out),
            "outer_radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_disc(w, mat, p, a, 0.1, -0.1, &out),
            "inner_radius");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_rectangle(w, mat, p, a, up, 0.1, 0.1, &out),
            "parallel");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_wall_add_rectangle(w, mat, p, a, zero, 0.1, 0.1, &out), "direction");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_rectangle(w, mat, p, a, x, 0.0, 0.1, &out),
            "half_width");
        ctx(sc, "finite walls: NULL arguments");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_cylinder(w, mat, NULL, a, 0.1, 0.2, 0, &out),
            "point");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_cone(w, mat, p, NULL, 0.1, 0, 0.2, 0, &out),
            "axis");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_disc(w, mat, p, a, 0.1, 0, NULL), "out");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_rectangle(w, mat, p, a, NULL, 0.1, 0.1, &out),
            "direction");
    }

    /* harmonic motion */
    const double z[3] = {0, 0, 1}, zero[3] = {0, 0, 0};
    ctx(sc, "wall_set_harmonic bad mode, axis, values");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_wall_set_harmonic(w, wall, 0, a, 1e-3, 10, 0), "mode");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_wall_set_harmonic(w, wall, 3, a, 1e-3, 10, 0), "mode");
    BAD(sc, DEMILL_ERR_NULL_POINTER,
        demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, NULL, 1e-3, 10, 0), "axis");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, zero, 1e-3, 10, 0), "axis");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, a, 1e-3, 0, 0),
        "frequency");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_ROTATION, z, 1e-3, -5, 0), "frequency");
    for (int j = 0; j < 3; j++) {
        ctx(sc, "wall_set_harmonic with %g", nonfinite[j]);
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, a, nonfinite[j], 10, 0),
            "amplitude", NONFINITE);
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, a, 1e-3, nonfinite[j], 0),
            "frequency", NONFINITE);
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_ROTATION, z, 1e-3, 10, nonfinite[j]),
            "phase", NONFINITE);
        const double an[3] = {nonfinite[j], 1, 0};
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, an, 1e-3, 10, 0),
            "axis", NONFINITE);
        const double un[3] = {0.1, nonfinite[j], 0};
        ctx(sc, "wall_set_surface_velocity with %g", nonfinite[j]);
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_wall_set_surface_velocity(w, wall, un), "velocity",
            NONFINITE);
    }
    if (flat) {
        ctx(sc, "wall motions out of the plane in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, z, 1e-3, 10, 0), "axis");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_ROTATION, a, 1e-3, 10, 0), "z");
        const double uz[3] = {0.1, 0, 0.1};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_set_surface_velocity(w, wall, uz), "velocity");
    }
}

START_TEST(finite_wall_values)
{
    both_dims(NULL, bad_finite_walls, NULL);
}
END_TEST

/* A mesh (3D: a roof of two triangles) or polyline (2D: a V) beside the
 * stack, so that the bad calls meet a world with one. */
static void setup_mesh(scene *sc)
{
    static const double v[] = {0.1,  0.02, -0.05, 0.15, 0.05, -0.05,
                               0.15, 0.05, 0.05,  0.1,  0.02, 0.05};
    static const double p[] = {0.1, 0.05, 0, 0.13, 0.01, 0, 0.16, 0.05, 0};
    static const uint32_t t[] = {0, 1, 2, 0, 2, 3};
    demill_world *w = sc->w;
    if (sc->dim == 3)
        DM_OK(w, demill_wall_add_mesh(w, sc->mat[0], 4, v, 2, t, &sc->wall[sc->nwall]));
    else
        DM_OK(w, demill_wall_add_polyline(w, sc->mat[0], 3, p, 0, &sc->wall[sc->nwall]));
    sc->nwall++;
}

static void bad_meshes(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id mat = sc->mat[1];
    demill_id out = DEMILL_ID_NONE;
    double v[] = {0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1};
    uint32_t t[] = {0, 1, 2, 1, 3, 2};
    size_t nv, ne;
    if (sc->dim == 2) {
        ctx(sc, "wall_add_mesh in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_mesh(w, mat, 4, v, 2, t, &out), "3D");
        double p[] = {0, 0, 0, 0.1, 0, 0, 0.2, 0.05, 0};
        ctx(sc, "wall_add_polyline bad points");
        for (int j = 0; j < 3; j++) {
            p[4] = nonfinite[j];
            BAD(sc, DEMILL_ERR_NOT_FINITE, demill_wall_add_polyline(w, mat, 3, p, 0, &out),
                "vertex 1", NONFINITE);
        }
        p[4] = 0.0;
        p[5] = 0.01;
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_polyline(w, mat, 3, p, 0, &out), "point 1",
            "z");
        p[5] = 0.0;
        p[6] = 0.1;
        p[7] = 0.0;
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_polyline(w, mat, 3, p, 0, &out),
            "segment 1", "zero length");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_polyline(w, mat, 2, p, 1, &out),
            "points");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_polyline(w, mat, 1, p, 0, &out),
            "points");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_polyline(w, mat, 3, p, 2, &out),
            "closed");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_polyline(w, mat, 3, NULL, 0, &out),
            "points");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_polyline(w, mat, 3, p, 0, NULL), "out");
    } else {
        double p[] = {0, 0, 0, 0.1, 0, 0, 0.2, 0.05, 0};
        ctx(sc, "wall_add_polyline in 3D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_wall_add_polyline(w, mat, 3, p, 0, &out), "2D");
        ctx(sc, "wall_add_mesh bad vertices");
        for (int j = 0; j < 3; j++) {
            v[7] = nonfinite[j];
            BAD(sc, DEMILL_ERR_NOT_FINITE, demill_wall_add_mesh(w, mat, 4, v, 2, t, &out),
                "vertex 2", NONFINITE);
        }
        v[7] = 0.0;
        ctx(sc, "wall_add_mesh bad triangles");
        t[4] = 4;
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_mesh(w, mat, 4, v, 2, t, &out),
            "triangle 1", "vertex 4");
        t[4] = 1; /* triangle 1 is (1, 1, 2) */
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_mesh(w, mat, 4, v, 2, t, &out),
            "triangle 1", "zero area");
        t[4] = 3; /* vertex 3 on the line through 1 and 2: 1 + 2 (2 - 1) */
        v[9] = -1.0, v[11] = 2.0;
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_mesh(w, mat, 4, v, 2, t, &out),
            "triangle 1", "zero area");
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_add_mesh(w, mat, 4, v, 0, t, &out),
            "triangles");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_mesh(w, mat, 4, NULL, 2, t, &out),
            "vertices");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_mesh(w, mat, 4, v, 2, NULL, &out),
            "triangles");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_add_mesh(w, mat, 4, v, 2, t, NULL), "out");
    }
    ctx(sc, "wall_mesh_info");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_mesh_info(w, sc->wall[0], &nv, &ne), "mesh");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_mesh_info(w, sc->wall[1], NULL, &ne),
        "n_vertices");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_wall_mesh_info(w, sc->wall[1], &nv, NULL),
        "n_elements");
    DM_OK(w, demill_wall_mesh_info(w, sc->wall[1], &nv, &ne));
    ck_assert(nv == (sc->dim == 3 ? 4u : 3u) && ne == 2);
}

START_TEST(mesh_values)
{
    both_dims(setup_mesh, bad_meshes, NULL);
}
END_TEST

/* The mesh of setup_mesh records its loads; the scene's first wall does not. */
static void setup_loads(scene *sc)
{
    setup_mesh(sc);
    DM_OK(sc->w, demill_wall_loads_start(sc->w, sc->wall[sc->nwall - 1]));
    DM_OK(sc->w, demill_world_step(sc->w, 10));
}

static void bad_loads(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id mesh = sc->wall[sc->nwall - 1];
    const size_t n = 2; /* two triangles (3D), two segments (2D) */
    double out[3];
    ctx(sc, "wall_loads");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_loads(w, mesh, n + 1, out, NULL, NULL, NULL,
                                                        NULL), "n = 3", "2 elements");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_loads(w, mesh, 1, NULL, NULL, NULL, NULL,
                                                        NULL), "n = 1");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_loads(w, sc->wall[0], 1, out, NULL, NULL, NULL,
                                                        NULL), "records no loads");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_loads(w, sc->pid[0], 1, out, NULL, NULL, NULL,
                                                         NULL), "wall");
    ctx(sc, "wall_loads_start, wall_loads_stop");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_loads_start(w, sc->pid[0]), "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_loads_start(w, DEMILL_ID_NONE), "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_loads_stop(w, sc->mat[0]), "wall");
}

START_TEST(wall_loads_values)
{
    both_dims(setup_loads, bad_loads, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Bodies and fixed particles                                                 */

/* A body free along y on a spring, driven, with a plane wall x = 0.5 of its
 * own; particle 0 (id order) fixed. */
static void setup_body(scene *sc)
{
    demill_world *w = sc->w;
    const double c[3] = {0, 0.1, 0}, p[3] = {0.5, 0, 0}, n[3] = {-1, 0, 0}, f[3] = {0, 1, 0};
    const double one = 1.0;
    DM_OK(w, demill_body_add(w, 0.3, c, DEMILL_BODY_AXIS_Y, 0, &sc->body));
    DM_OK(w, demill_body_set_spring(w, sc->body, DEMILL_BODY_AXIS_Y, 1000, 1, 0.1));
    DM_OK(w, demill_body_set_force(w, sc->body, f, 10, 0.1));
    DM_OK(w, demill_wall_add_plane(w, sc->mat[0], p, n, &sc->wall[1]));
    DM_OK(w, demill_body_attach_wall(w, sc->body, sc->wall[1]));
    sc->nwall = 2;
    DM_OK(w, demill_particle_set(w, id_at(sc, 0), DEMILL_PARTICLE_FIXED, &one));
    DM_OK(w, demill_world_step(w, 10));
}

static void bad_bodies(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id b = sc->body;
    const double c[3] = {0, 0, 0}, v1[3] = {0.1, 0, 0};
    demill_id out;
    double o[3];
    ctx(sc, "body_add");
    const double masses[3] = {0.0, -1.0, -INFINITY};
    for (int k = 0; k < 3; k++)
        BAD_ANY(sc, BIT(DEMILL_ERR_INVALID_VALUE) | BIT(DEMILL_ERR_NOT_FINITE),
                demill_body_add(w, masses[k], c, DEMILL_BODY_AXIS_X, 0, &out), "mass");
    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_add(w, NAN, c, 1, 0, &out), "mass");
    for (int k = 0; k < 3; k++) {
        double bad[3] = {0, 0, 0};
        bad[k] = NAN;
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_add(w, 1.0, bad, 1, 0, &out), "centre");
    }
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_add(w, 1.0, c, 8, 0, &out), "free_axes");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_add(w, 1.0, c, -1, 0, &out), "free_axes");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_add(w, 1.0, c, 1, 2, &out), "flags");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_body_add(w, 1.0, NULL, 1, 0, &out), "centre");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_body_add(w, 1.0, c, 1, 0, NULL), "out");
    if (sc->dim == 2) {
        const double cz[3] = {0, 0, 1};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_body_add(w, 1.0, c, DEMILL_BODY_AXIS_Z, 0, &out),
            "2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_body_add(w, 1.0, cz, 1, 0, &out), "2D");
    }

    ctx(sc, "body_set_spring");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_body_set_spring(w, b, 2, -1, 0, 0), "stiffness");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_body_set_spring(w, b, 2, 1, -1, 0), "damping");
    for (int k = 0; k < 3; k++) {
        double v[3] = {1, 1, 0};
        v[k] = NAN;
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_set_spring(w, b, 2, v[0], v[1], v[2]),
            "finite");
        v[k] = INFINITY;
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_set_spring(w, b, 2, v[0], v[1], v[2]),
            "finite");
    }
    const int32_t axes[4] = {0, 3, 8, -2};
    for (int k = 0; k < 4; k++)
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_set_spring(w, b, axes[k], 1, 0, 0), "axis");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_body_set_spring(w, b, DEMILL_BODY_AXIS_X, 1, 0, 0), "does not move");
    BAD(sc, sc->dim == 2 ? DEMILL_ERR_DIMENSION : DEMILL_ERR_INVALID_VALUE,
        demill_body_set_spring(w, b, DEMILL_BODY_AXIS_Z, 1, 0, 0), "z");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_body_set_spring(w, sc->wall[1], 2, 1, 0, 0),
        "body");

    ctx(sc, "body_set_force");
    for (int k = 0; k < 3; k++) {
        double a[3] = {0, 1, 0};
        a[k] = NAN;
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_set_force(w, b, a, 10, 0), "amplitude");
    }
    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_set_force(w, b, v1, NAN, 0), "frequency");
    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_body_set_force(w, b, v1, 10, INFINITY), "phase");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_body_set_force(w, b, v1, -1, 0), "frequency");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_body_set_force(w, b, NULL, 10, 0), "amplitude");
    if (sc->dim == 2) {
        const double az[3] = {0, 0, 1};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_body_set_force(w, b, az, 10, 0), "2D");
    }

    ctx(sc, "body_attach_wall");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_body_attach_wall(w, b, sc->wall[1]), "already");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_body_attach_wall(w, b, sc->wall[0]), "moves");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_body_attach_wall(w, b, sc->pid[1]), "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_body_attach_wall(w, sc->wall[0], sc->wall[1]),
        "body");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_wall_set_motion(w, sc->wall[1], v1, NULL, NULL),
        "attached");

    ctx(sc, "body_get, body_energy, body_remove");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_get(w, b, 0, o), "body field");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_get(w, b, 7, o), "body field");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_body_get(w, b, DEMILL_BODY_POSITION, NULL), "out");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_energy(w, b, DEMILL_ENERGY_TOTAL, o), "energy");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_energy(w, b, DEMILL_ENERGY_FLOW, o), "energy");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_body_energy(w, b, 19, o), "energy");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_body_energy(w, b, DEMILL_ENERGY_BODY_WORK, NULL),
        "value");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_body_remove(w, sc->wall[1]), "body");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_body_get(w, DEMILL_ID_NONE, 1, o), "body");

    ctx(sc, "fixed particles");
    const demill_id fixed = id_at(sc, 0);
    const double bad_flags[3] = {2.0, 0.5, -1.0};
    for (int k = 0; k < 3; k++)
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_particle_set(w, fixed, DEMILL_PARTICLE_FIXED, bad_flags + k), "fixed");
    const double nan1 = NAN;
    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_particle_set(w, fixed, DEMILL_PARTICLE_FIXED, &nan1),
        "fixed");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particle_set(w, fixed, DEMILL_PARTICLE_VELOCITY, v1),
        "fixed");
    const double spin[3] = {0, 0, 1};
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_particle_set(w, fixed, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin), "fixed");
    size_t n;
    double *vel = read_field(sc, DEMILL_PARTICLE_VELOCITY, &n);
    vel[0] = 0.5; /* particle 0, the fixed one */
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_write(w, DEMILL_PARTICLE_VELOCITY, vel, n),
        "particle 0", "fixed");
    free(vel);

    ctx(sc, "the iterative refinement with a body");
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT));
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_world_step(w, 1), "refinement", "bodies");
}

/* Choosing an integrator makes the forces be evaluated afresh: the twin
 * chooses velocity Verlet too. */
static void fix_integrator(scene *sc)
{
    DM_OK(sc->w, demill_world_set(sc->w, DEMILL_WORLD_INTEGRATOR,
                                  DEMILL_INTEGRATOR_VELOCITY_VERLET));
}

START_TEST(body_values)
{
    both_dims(setup_body, bad_bodies, fix_integrator);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Clumps                                                                     */

/* A clump of two overlapping spheres of material A above the stack, turning
 * and falling onto it, its members among the scene's particles. */
static void setup_clump(scene *sc)
{
    demill_world *w = sc->w;
    const double c[6] = {0, 0, 0, 1.2 * RAD, 0, 0}, r[2] = {RAD, RAD};
    const double at[3] = {0, 0.04, 0}, v[3] = {0.01, -0.2, 0};
    const double spin[3] = {0, 0, 3};
    DM_OK(w, demill_clump_template_add(w, sc->mat[0], 2, c, r, &sc->tmpl));
    DM_OK(w, demill_clump_add(w, sc->tmpl, at, NULL, &sc->clump));
    DM_OK(w, demill_clump_set(w, sc->clump, DEMILL_CLUMP_VELOCITY, v));
    DM_OK(w, demill_clump_set(w, sc->clump, DEMILL_CLUMP_ANGULAR_VELOCITY, spin));
    size_t n;
    DM_OK(w, demill_clump_members(w, sc->clump, sc->pid + sc->np, 2, &n));
    sc->np += n;
    DM_OK(w, demill_world_step(w, 10));
}

static void bad_clumps(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id t = sc->tmpl, c = sc->clump, mat = sc->mat[0];
    const double cen[6] = {0, 0, 0, 3 * RAD, 0, 0}, rad[2] = {RAD, RAD};
    const double at[3] = {0, 0.2, 0}, q1[4] = {1, 0, 0, 0}, zero4[4] = {0, 0, 0, 0};
    demill_id out;
    double o[9];

    ctx(sc, "clump_template_add");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_template_add(w, mat, 0, cen, rad, &out), "n = 0");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_add(w, mat, 2, NULL, rad, &out),
        "centres");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_add(w, mat, 2, cen, NULL, &out),
        "radii");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_add(w, mat, 2, cen, rad, NULL), "out");
    for (int k = 0; k < 3; k++) {
        double bad[6];
        memcpy(bad, cen, sizeof bad);
        bad[3 + k] = nonfinite[k];
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_template_add(w, mat, 2, bad, rad, &out),
            "centre 1", NONFINITE);
        double br[2] = {RAD, nonfinite[k]};
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_template_add(w, mat, 2, cen, br, &out),
            "radius 1", NONFINITE);
    }
    const double nonpositive[2] = {0.0, -RAD};
    for (int k = 0; k < 2; k++) {
        double br[2] = {nonpositive[k], RAD};
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_template_add(w, mat, 2, cen, br, &out),
            "radius 0");
    }
    const double tiny[2] = {1e-110, 1e-110}; /* a mass that underflows to 0 */
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_template_add(w, mat, 2, cen, tiny, &out),
        "mass");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_template_add(w, t, 2, cen, rad, &out),
        "material");
    if (sc->dim == 2) {
        const double cz[6] = {0, 0, 0, 3 * RAD, 0, RAD};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_template_add(w, mat, 2, cz, rad, &out), "2D");
    }

    ctx(sc, "clump_template_get");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_template_get(w, t, 0, o), "template field");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_template_get(w, t, 12, o), "template field");
    for (int32_t f = DEMILL_TEMPLATE_MESH_VOLUME; f <= DEMILL_TEMPLATE_FIT_CELL; f++)
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_template_get(w, t, f, o), "mesh");
    BAD(sc, DEMILL_ERR_NULL_POINTER,
        demill_clump_template_get(w, t, DEMILL_TEMPLATE_MASS, NULL), "out");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_template_get(w, c, DEMILL_TEMPLATE_MASS, o),
        "template");

    ctx(sc, "clump_add");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_add(w, t, NULL, NULL, &out), "position");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_add(w, t, at, NULL, NULL), "out");
    for (int k = 0; k < 3; k++) {
        double bad[3] = {0, 0.2, 0}, bq[4] = {1, 0, 0, 0};
        bad[k] = nonfinite[k];
        bq[k == 0 ? 0 : 3] = nonfinite[k];
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_add(w, t, bad, NULL, &out), "position",
            NONFINITE);
        BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_add(w, t, at, bq, &out), "orientation",
            NONFINITE);
    }
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_add(w, t, at, zero4, &out), "orientation",
        "norm");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_add(w, mat, at, q1, &out), "template");
    if (sc->dim == 2) {
        const double az[3] = {0, 0.2, 0.1}, qx[4] = {1, 0.1, 0, 0};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_add(w, t, az, NULL, &out), "2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_add(w, t, at, qx, &out), "about z");
    }

    ctx(sc, "clump_get, clump_set");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_get(w, c, 0, o), "clump field");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_get(w, c, 9, o), "clump field");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_get(w, c, DEMILL_CLUMP_POSITION, NULL), "out");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_get(w, t, DEMILL_CLUMP_POSITION, o), "clump");
    const int32_t readonly[4] = {DEMILL_CLUMP_ANGULAR_MOMENTUM, DEMILL_CLUMP_FORCE,
                                 DEMILL_CLUMP_TORQUE, DEMILL_CLUMP_MASS};
    for (int k = 0; k < 4; k++)
        BAD(sc, DEMILL_ERR_READ_ONLY, demill_clump_set(w, c, readonly[k], q1), "read-only");
    BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_set(w, c, 9, q1), "clump field");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_set(w, c, DEMILL_CLUMP_POSITION, NULL), "in");
    const int32_t vectors[3] = {DEMILL_CLUMP_POSITION, DEMILL_CLUMP_VELOCITY,
                                DEMILL_CLUMP_ANGULAR_VELOCITY};
    for (int f = 0; f < 3; f++)
        for (int k = 0; k < 3; k++) {
            double bad[3] = {0, 0, 0};
            bad[2 - k] = nonfinite[k];
            BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_set(w, c, vectors[f], bad), NONFINITE);
        }
    const double bq[4] = {NAN, 0, 0, 1};
    BAD(sc, DEMILL_ERR_NOT_FINITE, demill_clump_set(w, c, DEMILL_CLUMP_ORIENTATION, bq),
        "orientation", NONFINITE);
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_clump_set(w, c, DEMILL_CLUMP_ORIENTATION, zero4),
        "norm");
    if (sc->dim == 2) {
        const double vz[3] = {0, 0, 1}, wx[3] = {1, 0, 0}, qy[4] = {1, 0, 0.1, 0};
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_set(w, c, DEMILL_CLUMP_VELOCITY, vz), "2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_set(w, c, DEMILL_CLUMP_POSITION, vz), "2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_set(w, c, DEMILL_CLUMP_ANGULAR_VELOCITY, wx),
            "2D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_set(w, c, DEMILL_CLUMP_ORIENTATION, qy),
            "about z");
    }

    ctx(sc, "clump_members, particle_clump, clump_remove");
    demill_id ids[2];
    size_t n;
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_members(w, c, NULL, 0, NULL), "NULL");
    BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL, demill_clump_members(w, c, ids, 1, &n), "capacity");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_members(w, mat, ids, 2, &n), "clump");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particle_clump(w, sc->pid[0], NULL), "clump");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particle_clump(w, c, &out), "particle");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_remove(w, t), "clump");

    ctx(sc, "members through the particle API");
    DM_OK(w, demill_clump_members(w, c, ids, 2, &n));
    const double p[3] = {0, 0.3, 0}, one = 1.0;
    const int32_t fields[4] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                               DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_RADIUS};
    for (int k = 0; k < 4; k++)
        BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particle_set(w, ids[1], fields[k], p), "clump");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particle_set(w, ids[0], DEMILL_PARTICLE_FIXED, &one),
        "clump");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_remove(w, 1, ids + 1), "clump");
    double *pos = read_field(sc, DEMILL_PARTICLE_POSITION, &n);
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_write(w, DEMILL_PARTICLE_POSITION, pos, n),
        "clump");
    free(pos);

    ctx(sc, "what clumps do not support yet");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_material_set(w, mat, DEMILL_MATERIAL_DENSITY, 3000), "template");
    if (sc->dim == 2)
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, 0.01), "template");
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT));
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_world_step(w, 1), "refinement", "clumps");
}

START_TEST(clump_values)
{
    both_dims(setup_clump, bad_clumps, fix_integrator);
}
END_TEST

/* A regular octahedron |x| + |y| + |z| <= a about (0, 0.3, 0): 8 triangles,
 * wound counter-clockwise seen from outside. */
static dm_test_mesh octahedron(double a)
{
    dm_test_mesh m = {0};
    const double p[6][3] = {{a, 0.3, 0},  {-a, 0.3, 0}, {0, 0.3 + a, 0},
                            {0, 0.3 - a, 0}, {0, 0.3, a},  {0, 0.3, -a}};
    for (int k = 0; k < 6; k++)
        dm_test_mesh_vertex(&m, p[k]);
    static const uint32_t f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                     {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int k = 0; k < 8; k++)
        dm_test_mesh_triangle(&m, f[k][0], f[k][1], f[k][2]);
    return m;
}

/* The clump scene and, in 3D, a template of two spheres in an octahedron. */
static void setup_mesh_template(scene *sc)
{
    setup_clump(sc);
    if (sc->dim == 3) {
        dm_test_mesh m = octahedron(2 * RAD);
        DM_OK(sc->w, demill_clump_template_from_mesh(sc->w, sc->mat[1], m.nv, m.v, m.nt, m.t, 2,
                                                     16, &sc->mesh_tmpl));
        dm_test_mesh_free(&m);
    }
}

static void bad_mesh_templates(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id mat = sc->mat[0];
    dm_test_mesh m = octahedron(2 * RAD);
    demill_id out;
    char *none = dm_test_temp_file("none.stl", "", 0);
    remove(none); /* a path that was a file and is no more */
    if (sc->dim == 2) {
        ctx(sc, "clump_template_from_mesh, _from_stl in 2D");
        BAD(sc, DEMILL_ERR_DIMENSION,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 2, 16, &out), "3D");
        BAD(sc, DEMILL_ERR_DIMENSION, demill_clump_template_from_stl(w, mat, none, 1, 2, 16, &out),
            "3D");
    } else {
        ctx(sc, "clump_template_from_mesh");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 0, 16, &out),
            "no spheres");
        const int cells[3] = {3, 257, -1};
        for (int k = 0; k < 3; k++)
            BAD(sc, DEMILL_ERR_INVALID_VALUE,
                demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 2, cells[k], &out),
                "cells");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt - 1, m.t, 2, 16, &out),
            "not closed");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, 3, m.t, 2, 16, &out),
            "4 triangles");
        for (int k = 0; k < 3; k++) {
            dm_test_mesh b = octahedron(2 * RAD);
            b.v[4] = nonfinite[k];
            BAD(sc, DEMILL_ERR_NOT_FINITE,
                demill_clump_template_from_mesh(w, mat, b.nv, b.v, b.nt, b.t, 2, 16, &out),
                "vertex 1", "nan|infinite");
            dm_test_mesh_free(&b);
        }
        dm_test_mesh b = octahedron(2 * RAD);
        b.t[5] = 6;
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, b.nv, b.v, b.nt, b.t, 2, 16, &out),
            "triangle 1", "vertex 6");
        b.t[5] = 2; /* triangle 1 is (2, 1, 2) */
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, b.nv, b.v, b.nt, b.t, 2, 16, &out),
            "triangle 1", "zero area");
        for (size_t t = 0; t < b.nt; t++) { /* inside out */
            b.t[3 * t + 1] = m.t[3 * t + 2];
            b.t[3 * t + 2] = m.t[3 * t + 1];
        }
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, b.nv, b.v, b.nt, b.t, 2, 16, &out),
            "inside out");
        b.t[1] = m.t[1], b.t[2] = m.t[2]; /* triangle 0 turned back */
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_mesh(w, mat, b.nv, b.v, b.nt, b.t, 2, 16, &out),
            "oriented");
        dm_test_mesh_free(&b);
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_clump_template_from_mesh(w, mat, m.nv, NULL, m.nt, m.t, 2, 16, &out),
            "vertices");
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, NULL, 2, 16, &out),
            "triangles");
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 2, 16, NULL), "out");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_clump_template_from_mesh(w, sc->tmpl, m.nv, m.v, m.nt, m.t, 2, 16, &out),
            "material");

        ctx(sc, "clump_template_from_stl");
        double *corners = dm_test_mesh_corners(&m);
        size_t size;
        uint8_t *open = dm_test_stl_ascii("open", corners, m.nt - 1, NULL, &size);
        char *open_path = dm_test_temp_file("open.stl", open, size);
        static const char junk[] = "not an STL file\n";
        char *junk_path = dm_test_temp_file("junk.stl", junk, sizeof junk - 1);
        uint8_t *good = dm_test_stl_ascii("good", corners, m.nt, NULL, &size);
        char *good_path = dm_test_temp_file("good.stl", good, size);
        BAD(sc, DEMILL_ERR_IO, demill_clump_template_from_stl(w, mat, none, 1, 2, 16, &out), none,
            "no such file");
        BAD(sc, DEMILL_ERR_FORMAT,
            demill_clump_template_from_stl(w, mat, junk_path, 1, 2, 16, &out), junk_path,
            "not an STL file");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_stl(w, mat, open_path, 1, 2, 16, &out), open_path,
            "not closed");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_stl(w, mat, good_path, 1, 0, 16, &out), good_path,
            "no spheres");
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_clump_template_from_stl(w, mat, good_path, 1, 2, 300, &out), good_path,
            "cells");
        const double scales[4] = {0.0, -1.0, NAN, INFINITY};
        for (int k = 0; k < 4; k++)
            BAD(sc, DEMILL_ERR_INVALID_VALUE,
                demill_clump_template_from_stl(w, mat, good_path, scales[k], 2, 16, &out),
                good_path, "scale");
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_from_stl(w, mat, NULL, 1, 2, 16,
                                                                        &out), "path");
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_clump_template_from_stl(w, mat, good_path, 1, 2, 16, NULL), "out");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_clump_template_from_stl(w, sc->clump, good_path, 1, 2, 16, &out), "material");
        const char *paths[3] = {open_path, junk_path, good_path};
        for (int k = 0; k < 3; k++)
            remove(paths[k]);
        free(open_path);
        free(junk_path);
        free(good_path);
        free(open);
        free(good);
        free(corners);

        ctx(sc, "clump_template_get of a mesh template");
        double o[9];
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_clump_template_get(w, sc->mesh_tmpl, 12, o),
            "template field");
        BAD(sc, DEMILL_ERR_NULL_POINTER,
            demill_clump_template_get(w, sc->mesh_tmpl, DEMILL_TEMPLATE_FIT_CELL, NULL), "out");
    }
    ctx(sc, "clump_template_spheres");
    double b[6], r[2];
    size_t n;
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_spheres(w, sc->tmpl, NULL, NULL, 0,
                                                                   NULL), "count");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_spheres(w, sc->tmpl, b, NULL, 2, &n),
        "radii");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_clump_template_spheres(w, sc->tmpl, NULL, r, 2, &n),
        "centres");
    n = 7;
    BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL,
        demill_clump_template_spheres(w, sc->tmpl, b, r, 1, &n), "capacity");
    ck_assert_uint_eq(n, 2);
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_template_spheres(w, mat, b, r, 2, &n),
        "template");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_clump_template_spheres(w, sc->clump, b, r, 2, &n),
        "template");
    free(none);
    dm_test_mesh_free(&m);
}

START_TEST(mesh_template_values)
{
    both_dims(setup_mesh_template, bad_mesh_templates, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Handles: removed, foreign, wrong kind, none                                */

/* Removes particles 3 and 7 (id order) and a wall, then adds particles and a
 * wall again so that the freed slots are reused. */
static void setup_removed(scene *sc)
{
    demill_world *w = sc->w;
    sc->gone_p[0] = id_at(sc, 3);
    sc->gone_p[1] = id_at(sc, 7);
    DM_OK(w, demill_particles_remove(w, 2, sc->gone_p));
    const double p[3] = {-0.5, 0, 0}, n[3] = {1, 0, 0}, q[3] = {0.5, 0, 0}, m[3] = {-1, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, sc->mat[0], p, n, &sc->gone_wall));
    DM_OK(w, demill_wall_remove(w, sc->gone_wall));
    DM_OK(w, demill_wall_add_plane(w, sc->mat[1], q, m, &sc->wall[1]));
    sc->wall[2] = sc->gone_wall; /* the snapshot reads it too: it must stay invalid */
    sc->nwall = 3;
    add_one(sc, sc->mat[0], 0.1, 0.3, 0.0, RAD);
    add_one(sc, sc->mat[1], 0.2, 0.3, 0.0, RAD);
}

static void bad_removed(scene *sc)
{
    demill_world *w = sc->w;
    const double v[3] = {0.1, 0, 0};
    double out[3];
    for (int k = 0; k < 2; k++) {
        const demill_id gone = sc->gone_p[k];
        ctx(sc, "removed particle %d", k);
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_particle_set(w, gone, DEMILL_PARTICLE_VELOCITY, v), "particle");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_particle_get(w, gone, DEMILL_PARTICLE_VELOCITY, out), "particle");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_remove(w, 1, &gone), "ids[0]");
        const demill_id list[3] = {sc->pid[0], sc->pid[1], gone};
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_remove(w, 3, list), "ids[2]");
    }
    ctx(sc, "both removed particles");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_remove(w, 2, sc->gone_p), "ids[0]");
    ctx(sc, "removed wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_set_motion(w, sc->gone_wall, v, NULL, NULL),
        "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_get(w, sc->gone_wall, DEMILL_WALL_POINT, out),
        "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_remove(w, sc->gone_wall), "wall");
}

START_TEST(removed_handles)
{
    both_dims(setup_removed, bad_removed, NULL);
}
END_TEST

/* Ids of an identical scene in another world: same kind, index and
 * generation, only the world differs. */
static void bad_foreign(scene *sc)
{
    demill_world *w = sc->w;
    scene o;
    scene_build(&o, sc->dim);
    const demill_id om = o.mat[0], op = o.pid[0], ow = o.wall[0];
    double pos[15], rad[5], vel[15], out[3];
    demill_id ids[5], wid;
    far_batch(sc, pos, rad, vel);
    const double p[3] = {0.3, -0.05, 0}, n[3] = {-1, 1, 0}, v[3] = {0.1, 0, 0};
    ctx(sc, "material of another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_material_set(w, om, DEMILL_MATERIAL_DENSITY, 3000),
        "material");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_material_get(w, om, DEMILL_MATERIAL_DENSITY, out),
        "material");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE,
        demill_pair_set(w, om, sc->mat[1], DEMILL_PAIR_FRICTION, 0.2), "another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE,
        demill_pair_set(w, sc->mat[0], o.mat[1], DEMILL_PAIR_FRICTION, 0.2), "another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE,
        demill_pair_get(w, sc->mat[0], o.mat[1], DEMILL_PAIR_FRICTION, out), "another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_add(w, om, 5, pos, rad, vel, 0, ids),
        "material");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_add_plane(w, om, p, n, &wid), "material");
    ctx(sc, "particle of another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particle_set(w, op, DEMILL_PARTICLE_VELOCITY, v),
        "particle");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particle_get(w, op, DEMILL_PARTICLE_VELOCITY, out),
        "particle");
    const demill_id list[2] = {sc->pid[0], op};
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_remove(w, 2, list), "ids[1]");
    ctx(sc, "wall of another world");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_set_motion(w, ow, v, NULL, NULL), "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_get(w, ow, DEMILL_WALL_POINT, out), "wall");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_remove(w, ow), "wall");
    scene_free(&o);
}

START_TEST(foreign_handles)
{
    both_dims(NULL, bad_foreign, NULL);
}
END_TEST

static void bad_kind(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id M = sc->mat[0], P = sc->pid[0], W = sc->wall[0];
    /* not a material: a particle, a wall, none, garbage */
    const demill_id not_mat[4] = {P, W, DEMILL_ID_NONE, ~(demill_id)0};
    const demill_id not_part[4] = {M, W, DEMILL_ID_NONE, ~(demill_id)0};
    const demill_id not_wall[4] = {M, P, DEMILL_ID_NONE, ~(demill_id)0};
    double pos[15], rad[5], vel[15], out[3];
    demill_id ids[5], wid;
    far_batch(sc, pos, rad, vel);
    const double p[3] = {0.3, -0.05, 0}, n[3] = {-1, 1, 0}, v[3] = {0.1, 0, 0};
    ctx(sc, "a garbage id as a material: the message names both kinds");
    BAD(sc, DEMILL_ERR_INVALID_HANDLE,
        demill_material_set(w, ~(demill_id)0, DEMILL_MATERIAL_DENSITY, 3000),
        "is an unknown id, expected a material id");
    for (int k = 0; k < 4; k++) {
        const demill_id x = not_mat[k];
        ctx(sc, "id 0x%llx as a material", (unsigned long long)x);
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_material_set(w, x, DEMILL_MATERIAL_DENSITY, 3000), "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_material_get(w, x, DEMILL_MATERIAL_DENSITY, out), "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_pair_set(w, x, M, DEMILL_PAIR_FRICTION, 0.2),
            "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_pair_set(w, M, x, DEMILL_PAIR_FRICTION, 0.2),
            "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_pair_get(w, M, x, DEMILL_PAIR_FRICTION, out),
            "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_add(w, x, 5, pos, rad, vel, 0, ids),
            "material");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_add_plane(w, x, p, n, &wid), "material");
    }
    for (int k = 0; k < 4; k++) {
        const demill_id x = not_part[k];
        ctx(sc, "id 0x%llx as a particle", (unsigned long long)x);
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particle_set(w, x, DEMILL_PARTICLE_VELOCITY, v),
            "particle");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE,
            demill_particle_get(w, x, DEMILL_PARTICLE_VELOCITY, out), "particle");
        const demill_id list[3] = {sc->pid[1], sc->pid[2], x};
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_particles_remove(w, 3, list), "ids[2]");
    }
    for (int k = 0; k < 4; k++) {
        const demill_id x = not_wall[k];
        ctx(sc, "id 0x%llx as a wall", (unsigned long long)x);
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_set_motion(w, x, v, NULL, NULL), "wall");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_get(w, x, DEMILL_WALL_POINT, out), "wall");
        BAD(sc, DEMILL_ERR_INVALID_HANDLE, demill_wall_remove(w, x), "wall");
    }
}

START_TEST(wrong_kind_and_none_handles)
{
    both_dims(NULL, bad_kind, NULL);
}
END_TEST

static void bad_remove(scene *sc)
{
    demill_world *w = sc->w;
    const demill_id a = sc->pid[4], b = sc->pid[9];
    const demill_id twice[3] = {a, b, a}, same2[2] = {b, b};
    ctx(sc, "particles_remove with an id listed twice");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_remove(w, 3, twice), "ids[0]|ids[2]",
        "twice|duplicate|more than once|repeated");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_particles_remove(w, 2, same2), "ids[0]|ids[1]",
        "twice|duplicate|more than once|repeated");
    ctx(sc, "particles_remove from NULL");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particles_remove(w, 2, NULL), "ids");
}

START_TEST(particles_remove_duplicates)
{
    both_dims(NULL, bad_remove, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Reading: small buffers, NULL outputs, unknown fields                       */

#define SENTINEL 0xa5

static int untouched(const void *buf, size_t bytes)
{
    const unsigned char *b = buf;
    for (size_t k = 0; k < bytes; k++)
        if (b[k] != SENTINEL)
            return 0;
    return 1;
}

static void check_count(scene *sc, const char *what, size_t got, size_t want)
{
    if (got != want)
        note_fail(sc, what, "*count = %zu, expected the needed size %zu", got, want);
}

static void check_untouched(scene *sc, const char *what, const void *buf, size_t bytes)
{
    if (!untouched(buf, bytes))
        note_fail(sc, what, "the buffer was written although the call failed");
}

static void bad_reads(scene *sc)
{
    demill_world *w = sc->w;
    const size_t n = pcount(sc);
    double *buf = malloc((3 * n + 3) * sizeof *buf);
    demill_id *ib = malloc((n + 1) * sizeof *ib), *ib2;
    ck_assert(buf && ib);
    size_t cnt;
    const char *small = "capacity|small|buffer";
    for (int32_t f = DEMILL_PARTICLE_POSITION; f <= (sc->dim == 2 ? 8 : 7); f++) {
        const size_t bytes = (3 * n + 3) * sizeof *buf;
        const size_t caps[2] = {n - 1, 0};
        for (int j = 0; j < 2; j++) {
            memset(buf, SENTINEL, bytes);
            cnt = 12345;
            ctx(sc, "particles_read field %d, capacity %zu of %zu", (int)f, caps[j], n);
            BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL, demill_particles_read(w, f, buf, caps[j], &cnt),
                small);
            check_count(sc, "particles_read", cnt, n);
            check_untouched(sc, "particles_read", buf, bytes);
        }
        ctx(sc, "particles_read field %d, out and count NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particles_read(w, f, NULL, n, NULL), "NULL");
    }
    for (int32_t f = DEMILL_PARTICLE_ID; f <= DEMILL_PARTICLE_CLUMP; f++) {
        const size_t bytes = (n + 1) * sizeof *ib;
        memset(ib, SENTINEL, bytes);
        cnt = 12345;
        ctx(sc, "particles_read_ids field %d, capacity %zu of %zu", (int)f, n - 1, n);
        BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL, demill_particles_read_ids(w, f, ib, n - 1, &cnt),
            small);
        check_count(sc, "particles_read_ids", cnt, n);
        check_untouched(sc, "particles_read_ids", ib, bytes);
        ctx(sc, "particles_read_ids field %d, out and count NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_particles_read_ids(w, f, NULL, n, NULL), "NULL");
    }
    static const int32_t unknown_p[] = {0, 11, 99, 100, -1};
    for (size_t k = 0; k < sizeof unknown_p / sizeof unknown_p[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown_p[k]);
        ctx(sc, "particles_read unknown field %d", (int)unknown_p[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_particles_read(w, unknown_p[k], buf, n, &cnt),
            num);
    }
    static const int32_t unknown_i[] = {0, 1, 99, 103, -1};
    for (size_t k = 0; k < sizeof unknown_i / sizeof unknown_i[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown_i[k]);
        ctx(sc, "particles_read_ids unknown field %d", (int)unknown_i[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_particles_read_ids(w, unknown_i[k], ib, n, &cnt),
            num);
    }

    /* contacts */
    size_t nc = 0;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &nc));
    ck_assert_uint_gt(nc, 1);
    double *cbuf = malloc((3 * nc + 3) * sizeof *cbuf);
    ib2 = malloc((nc + 1) * sizeof *ib2);
    free(ib);
    ib = malloc((nc + 1) * sizeof *ib);
    ck_assert(cbuf && ib && ib2);
    for (int32_t f = DEMILL_CONTACT_POINT; f <= DEMILL_CONTACT_ROLLING_TORQUE; f++) {
        const size_t bytes = (3 * nc + 3) * sizeof *cbuf;
        memset(cbuf, SENTINEL, bytes);
        cnt = 12345;
        ctx(sc, "contacts_read field %d, capacity %zu of %zu", (int)f, nc - 1, nc);
        BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL, demill_contacts_read(w, f, cbuf, nc - 1, &cnt),
            small);
        check_count(sc, "contacts_read", cnt, nc);
        check_untouched(sc, "contacts_read", cbuf, bytes);
        ctx(sc, "contacts_read field %d, out and count NULL", (int)f);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_contacts_read(w, f, NULL, nc, NULL), "NULL");
    }
    for (int which = 0; which < 3; which++) {
        const size_t bytes = (nc + 1) * sizeof *ib;
        memset(ib, SENTINEL, bytes);
        memset(ib2, SENTINEL, bytes);
        cnt = 12345;
        ctx(sc, "contacts_read_ids (%s), capacity %zu of %zu",
            which == 0 ? "a and b" : which == 1 ? "a only" : "b only", nc - 1, nc);
        BAD(sc, DEMILL_ERR_BUFFER_TOO_SMALL,
            demill_contacts_read_ids(w, which != 2 ? ib : NULL, which != 1 ? ib2 : NULL, nc - 1,
                                     &cnt),
            small);
        check_count(sc, "contacts_read_ids", cnt, nc);
        check_untouched(sc, "contacts_read_ids a", ib, bytes);
        check_untouched(sc, "contacts_read_ids b", ib2, bytes);
    }
    ctx(sc, "contacts_read_ids, every pointer NULL");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_contacts_read_ids(w, NULL, NULL, nc, NULL), "NULL");
    static const int32_t unknown_c[] = {0, 7, 99, -1};
    for (size_t k = 0; k < sizeof unknown_c / sizeof unknown_c[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown_c[k]);
        ctx(sc, "contacts_read unknown field %d", (int)unknown_c[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_contacts_read(w, unknown_c[k], cbuf, nc, &cnt),
            num);
    }

    /* energies */
    for (int32_t t = DEMILL_ENERGY_KINETIC_TRANSLATIONAL; t <= DEMILL_ENERGY_TOTAL; t++) {
        ctx(sc, "world_energy term %d into NULL", (int)t);
        BAD(sc, DEMILL_ERR_NULL_POINTER, demill_world_energy(w, t, NULL), "NULL");
    }
    static const int32_t unknown_e[] = {0, 24, 100, -1};
    for (size_t k = 0; k < sizeof unknown_e / sizeof unknown_e[0]; k++) {
        char num[16];
        snprintf(num, sizeof num, "%d", (int)unknown_e[k]);
        double v = 42.0;
        ctx(sc, "world_energy unknown term %d", (int)unknown_e[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY, demill_world_energy(w, unknown_e[k], &v), num);
        ck_assert(v == 42.0);
    }
    free(buf);
    free(ib);
    free(ib2);
    free(cbuf);
}

START_TEST(reads)
{
    both_dims(NULL, bad_reads, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* A material pair with no contact model                                      */

/* Material C with three particles far above the stack. */
static void add_c_particles(scene *sc)
{
    DM_OK(sc->w, demill_material_create(sc->w, &sc->mat[2]));
    sc->nmat = 3;
    for (int k = 0; k < 3; k++)
        add_one(sc, sc->mat[2], 0.1 + 0.05 * k, 0.3, 0.0, RAD);
}

static void setup_c_no_pairs(scene *sc)
{
    add_c_particles(sc);
}

/* (C, C) has a model; (A, C) and (B, C) only have other laws set. */
static void setup_c_partial(scene *sc)
{
    add_c_particles(sc);
    const demill_id A = sc->mat[0], B = sc->mat[1], C = sc->mat[2];
    set_model(sc->w, C, C, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION,
              DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_NONE);
    DM_OK(sc->w, demill_pair_set(sc->w, A, C, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_VISCOUS));
    DM_OK(sc->w, demill_pair_set(sc->w, B, C, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_COULOMB));
    DM_OK(sc->w, demill_pair_set(sc->w, B, C, DEMILL_PAIR_FRICTION, 0.2));
}

/* Every pair but (B, C) has a model. */
static void setup_c_one_missing(scene *sc)
{
    add_c_particles(sc);
    set_model(sc->w, sc->mat[2], sc->mat[2], DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE,
              DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_NONE);
    set_model(sc->w, sc->mat[0], sc->mat[2], DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE,
              DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_NONE);
}

/* A second wall of material C, which has no model with A or B. */
static void setup_c_wall(scene *sc)
{
    DM_OK(sc->w, demill_material_create(sc->w, &sc->mat[2]));
    sc->nmat = 3;
    const double p[3] = {-0.5, 0, 0}, n[3] = {1, 0, 0};
    DM_OK(sc->w, demill_wall_add_plane(sc->w, sc->mat[2], p, n, &sc->wall[sc->nwall]));
    sc->nwall++;
}

static void fix_c_models(scene *sc)
{
    for (int a = 0; a < 3; a++)
        DM_OK(sc->w, demill_pair_set(sc->w, sc->mat[a], sc->mat[2], DEMILL_PAIR_NORMAL,
                                     DEMILL_NORMAL_LINEAR));
}

/* Stepping, and suggesting a time step, need every model. */
static void bad_without_model(scene *sc)
{
    static const uint64_t steps[] = {1, 0, 1000};
    for (int k = 0; k < 3; k++) {
        ctx(sc, "world_step(%llu) without a contact model", (unsigned long long)steps[k]);
        BAD(sc, DEMILL_ERR_NO_CONTACT_MODEL, demill_world_step(sc->w, steps[k]), "model");
    }
    double dt;
    ctx(sc, "world_suggest_time_step without a contact model");
    BAD(sc, DEMILL_ERR_NO_CONTACT_MODEL,
        demill_world_suggest_time_step(sc->w, 1.0, 0, &dt, NULL, NULL), "model");
}

START_TEST(no_contact_model)
{
    both_dims(setup_c_no_pairs, bad_without_model, fix_c_models);
    both_dims(setup_c_partial, bad_without_model, fix_c_models);
    both_dims(setup_c_one_missing, bad_without_model, fix_c_models);
}
END_TEST

START_TEST(no_contact_model_with_wall)
{
    both_dims(setup_c_wall, bad_without_model, fix_c_models);
}
END_TEST

/* Material A rigid: its particles touch each other and its wall. */
static void setup_rigid_a(scene *sc)
{
    DM_OK(sc->w, demill_material_set(sc->w, sc->mat[0], DEMILL_MATERIAL_RIGID, 1));
}

static void fix_rigid_a(scene *sc)
{
    DM_OK(sc->w, demill_material_set(sc->w, sc->mat[0], DEMILL_MATERIAL_RIGID, 0));
}

/* A lone particle of a rigid material C, which needs no model with itself,
 * and a far wall of a rigid material D: C and D may touch. */
static void setup_rigid_c_d(scene *sc)
{
    demill_world *w = sc->w;
    DM_OK(w, demill_material_create(w, &sc->mat[2]));
    DM_OK(w, demill_material_create(w, &sc->mat[3]));
    sc->nmat = 4;
    const demill_id A = sc->mat[0], B = sc->mat[1], C = sc->mat[2], D = sc->mat[3];
    add_one(sc, C, 0.3, 0.3, 0.0, RAD);
    const double p[3] = {-0.5, 0, 0}, n[3] = {1, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, D, p, n, &sc->wall[sc->nwall]));
    sc->nwall++;
    const demill_id soft[2] = {A, B};
    for (int k = 0; k < 2; k++)
        for (int q = 2; q < 4; q++)
            DM_OK(w, demill_pair_set(w, soft[k], sc->mat[q], DEMILL_PAIR_NORMAL,
                                     DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, C, D, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_material_set(w, C, DEMILL_MATERIAL_RIGID, 1));
    DM_OK(w, demill_material_set(w, D, DEMILL_MATERIAL_RIGID, 1));
}

static void fix_rigid_d(scene *sc)
{
    DM_OK(sc->w, demill_material_set(sc->w, sc->mat[3], DEMILL_MATERIAL_RIGID, 0));
}

/* Stepping, and suggesting a time step, refuse two rigid materials that may
 * touch, whatever their model. */
static void bad_rigid_pair(scene *sc)
{
    static const uint64_t steps[] = {1, 0, 1000};
    for (int k = 0; k < 3; k++) {
        ctx(sc, "world_step(%llu) with two rigid materials", (unsigned long long)steps[k]);
        BAD(sc, DEMILL_ERR_NO_CONTACT_MODEL, demill_world_step(sc->w, steps[k]), "rigid",
            "deformable");
    }
    double dt;
    ctx(sc, "world_suggest_time_step with two rigid materials");
    BAD(sc, DEMILL_ERR_NO_CONTACT_MODEL,
        demill_world_suggest_time_step(sc->w, 1.0, 0, &dt, NULL, NULL), "rigid", "deformable");
}

/* JKR cohesion on B's linear pair with itself. */
static void setup_jkr_linear(scene *sc)
{
    DM_OK(sc->w, demill_pair_set(sc->w, sc->mat[1], sc->mat[1], DEMILL_PAIR_COHESION,
                                 DEMILL_COHESION_JKR));
}

static void fix_jkr_linear(scene *sc)
{
    DM_OK(sc->w, demill_pair_set(sc->w, sc->mat[1], sc->mat[1], DEMILL_PAIR_COHESION,
                                 DEMILL_COHESION_NONE));
}

/* JKR is a law of Hertz contacts: stepping refuses it with another. */
static void bad_jkr_linear(scene *sc)
{
    ctx(sc, "world_step with JKR on a linear pair");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_world_step(sc->w, 1), "JKR", "HERTZ");
    double dt;
    ctx(sc, "world_suggest_time_step with JKR on a linear pair");
    BAD(sc, DEMILL_ERR_INVALID_VALUE,
        demill_world_suggest_time_step(sc->w, 1.0, 0, &dt, NULL, NULL), "JKR", "HERTZ");
}

START_TEST(jkr_needs_hertz)
{
    both_dims(setup_jkr_linear, bad_jkr_linear, fix_jkr_linear);
}
END_TEST

START_TEST(rigid_pairs)
{
    both_dims(setup_rigid_a, bad_rigid_pair, fix_rigid_a);
    both_dims(setup_rigid_c_d, bad_rigid_pair, fix_rigid_d);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Time-step suggestion                                                       */

static void bad_suggest(scene *sc)
{
    demill_world *w = sc->w;
    double dt, crit, tc;
    ctx(sc, "suggest_time_step into NULL");
    BAD(sc, DEMILL_ERR_NULL_POINTER,
        demill_world_suggest_time_step(w, 1.0, 0, NULL, &crit, &tc), "suggested");
    for (int k = 0; k < 3; k++) {
        ctx(sc, "suggest_time_step impact_speed %g", nonfinite[k]);
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_world_suggest_time_step(w, nonfinite[k], 0, &dt, &crit, &tc),
            "impact_speed", NONFINITE);
        ctx(sc, "suggest_time_step steps_per_contact %g", nonfinite[k]);
        BAD(sc, DEMILL_ERR_NOT_FINITE,
            demill_world_suggest_time_step(w, 1.0, nonfinite[k], &dt, &crit, &tc),
            "steps_per_contact", NONFINITE);
    }
    static const double speeds[] = {-1e-9, -1.0, -1e300};
    for (int k = 0; k < 3; k++) {
        ctx(sc, "suggest_time_step impact_speed %g", speeds[k]);
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_world_suggest_time_step(w, speeds[k], 0, &dt, &crit, &tc), "impact_speed");
    }
    static const double steps[] = {0.5, 1e-300, -1.0, -50.0};
    for (int k = 0; k < 4; k++) {
        ctx(sc, "suggest_time_step steps_per_contact %g", steps[k]);
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_world_suggest_time_step(w, 1.0, steps[k], &dt, &crit, &tc),
            "steps_per_contact");
    }
}

START_TEST(suggest_time_step)
{
    both_dims(NULL, bad_suggest, NULL);
}
END_TEST

static int32_t never_called(void *user, uint64_t done, uint64_t total, double time, double rate)
{
    (void)user, (void)done, (void)total, (void)time, (void)rate;
    ck_abort_msg("a progress callback that failed to be set was called");
    return 1;
}

static void bad_progress(scene *sc)
{
    ctx(sc, "set_progress every 0");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_world_set_progress(sc->w, never_called, sc, 0),
        "every_steps");
}

START_TEST(progress_callback)
{
    both_dims(NULL, bad_progress, NULL);
}
END_TEST

static void bad_vtk(scene *sc)
{
    demill_world *w = sc->w;
    demill_vtk_series *series;
    ctx(sc, "vtk writers with NULL");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_vtk_write_particles(w, NULL), "path");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_vtk_write_walls(w, NULL), "path");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_vtk_series_open(w, NULL, &series), "prefix");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_vtk_series_open(w, "x", NULL), "out");
    BAD(sc, DEMILL_ERR_NULL_POINTER, demill_vtk_series_write(w, NULL), "series");
    ctx(sc, "vtk series prefix without a name");
    BAD(sc, DEMILL_ERR_INVALID_VALUE, demill_vtk_series_open(w, "out/", &series), "prefix");
    ctx(sc, "vtk files in a missing directory");
    BAD(sc, DEMILL_ERR_IO, demill_vtk_write_particles(w, "/nonexistent-demill/p.vtu"),
        "/nonexistent-demill/p.vtu", "no such file");
    BAD(sc, DEMILL_ERR_IO, demill_vtk_write_walls(w, "/nonexistent-demill/w.vtp"),
        "/nonexistent-demill/w.vtp", "no such file");
    BAD(sc, DEMILL_ERR_IO, demill_vtk_series_open(w, "/nonexistent-demill/s", &series),
        "/nonexistent-demill/s.pvd", "no such file");
}

START_TEST(vtk_output)
{
    both_dims(NULL, bad_vtk, NULL);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* NULL worlds and world creation                                             */

START_TEST(null_world_and_create)
{
    demill_world *keep;
    ck_assert_int_eq(demill_world_create(3, &keep), DEMILL_OK);
    static const int32_t dims[] = {1, 4, 0, -1, 100};
    for (size_t k = 0; k < sizeof dims / sizeof dims[0]; k++) {
        demill_world *w = keep;
        ck_assert_int_eq(demill_world_create(dims[k], &w), DEMILL_ERR_INVALID_VALUE);
        ck_assert_msg(w == NULL, "dimension %d: *out not set to NULL", (int)dims[k]);
    }
    ck_assert_int_eq(demill_world_create(3, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_world_create(2, NULL), DEMILL_ERR_NULL_POINTER);

    const char *e1 = demill_world_last_error(NULL), *e2 = demill_world_last_error(NULL);
    ck_assert_ptr_nonnull(e1);
    ck_assert_msg(e1[0] != '\0', "demill_world_last_error(NULL) is empty");
    ck_assert_str_eq(e1, e2);

    /* every function that takes a world, with otherwise valid arguments */
    demill_id m, p, wl, ids[1];
    DM_OK(keep, demill_material_create(keep, &m));
    DM_OK(keep, demill_pair_set(keep, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    double x[3] = {0, 0.1, 0}, r = 0.01, v[3] = {0, 0, 0}, d = 0;
    DM_OK(keep, demill_particles_add(keep, m, 1, x, &r, NULL, 0, &p));
    const double pt[3] = {0, 0, 0}, nrm[3] = {0, 1, 0};
    DM_OK(keep, demill_wall_add_plane(keep, m, pt, nrm, &wl));
    size_t cnt = 0;
    demill_id id = 0;
    demill_world *const N = NULL;
    demill_snapshot *snap = NULL, *snap_out = NULL;
    DM_OK(keep, demill_snapshot_take(keep, &snap));
    unsigned char bytes[64] = {0};
    demill_vtk_series *series = NULL;
    const struct {
        const char *name;
        demill_status got;
    } calls[] = {
        {"world_set", demill_world_set(N, DEMILL_WORLD_TIME_STEP, 1e-5)},
        {"world_get", demill_world_get(N, DEMILL_WORLD_TIME_STEP, &d)},
        {"world_step", demill_world_step(N, 1)},
        {"material_create", demill_material_create(N, &id)},
        {"material_set", demill_material_set(N, m, DEMILL_MATERIAL_DENSITY, 1000)},
        {"material_get", demill_material_get(N, m, DEMILL_MATERIAL_DENSITY, &d)},
        {"pair_set", demill_pair_set(N, m, m, DEMILL_PAIR_NORMAL, 1)},
        {"pair_get", demill_pair_get(N, m, m, DEMILL_PAIR_NORMAL, &d)},
        {"particles_add", demill_particles_add(N, m, 1, x, &r, NULL, 0, ids)},
        {"particles_remove", demill_particles_remove(N, 1, &p)},
        {"particles_read", demill_particles_read(N, DEMILL_PARTICLE_POSITION, x, 1, &cnt)},
        {"particles_read_ids", demill_particles_read_ids(N, DEMILL_PARTICLE_ID, ids, 1, &cnt)},
        {"particles_write", demill_particles_write(N, DEMILL_PARTICLE_VELOCITY, v, 1)},
        {"particle_get", demill_particle_get(N, p, DEMILL_PARTICLE_POSITION, x)},
        {"particle_set", demill_particle_set(N, p, DEMILL_PARTICLE_VELOCITY, v)},
        {"wall_add_plane", demill_wall_add_plane(N, m, pt, nrm, &id)},
        {"wall_remove", demill_wall_remove(N, wl)},
        {"wall_set_motion", demill_wall_set_motion(N, wl, v, v, pt)},
        {"wall_get", demill_wall_get(N, wl, DEMILL_WALL_POINT, x)},
        {"contacts_read", demill_contacts_read(N, DEMILL_CONTACT_OVERLAP, x, 1, &cnt)},
        {"contacts_read_ids", demill_contacts_read_ids(N, ids, ids, 1, &cnt)},
        {"world_energy", demill_world_energy(N, DEMILL_ENERGY_TOTAL, &d)},
        {"world_suggest_time_step", demill_world_suggest_time_step(N, 1.0, 0, &d, NULL, NULL)},
        {"snapshot_take", demill_snapshot_take(N, &snap_out)},
        {"snapshot_restore", demill_snapshot_restore(N, snap)},
        {"world_save", demill_world_save(N, "demill-null-world.ckpt")},
        {"world_load", demill_world_load(N, "demill-null-world.ckpt")},
        {"world_save_buffer", demill_world_save_buffer(N, bytes, sizeof bytes, &cnt)},
        {"world_load_buffer", demill_world_load_buffer(N, bytes, sizeof bytes)},
        {"world_ids", demill_world_ids(N, DEMILL_KIND_MATERIAL, ids, 1, &cnt)},
        {"world_set_progress", demill_world_set_progress(N, NULL, NULL, 1)},
        {"vtk_write_particles", demill_vtk_write_particles(N, "p.vtu")},
        {"vtk_write_walls", demill_vtk_write_walls(N, "w.vtp")},
        {"vtk_series_open", demill_vtk_series_open(N, "s", &series)},
        {"vtk_series_write", demill_vtk_series_write(N, series)},
    };
    for (size_t k = 0; k < sizeof calls / sizeof calls[0]; k++)
        ck_assert_msg(calls[k].got == DEMILL_ERR_NULL_POINTER,
                      "demill_%s(NULL, ...) returned %d (%s), expected %d", calls[k].name,
                      (int)calls[k].got, demill_strerror(calls[k].got), DEMILL_ERR_NULL_POINTER);
    demill_world_destroy(NULL);
    demill_snapshot_free(snap);
    demill_snapshot_free(NULL);
    /* the real world was not touched by any of it */
    DM_OK(keep, demill_world_get(keep, DEMILL_WORLD_PARTICLE_COUNT, &d));
    ck_assert(d == 1.0);
    DM_OK(keep, demill_particle_get(keep, p, DEMILL_PARTICLE_POSITION, x));
    ck_assert(x[0] == 0 && x[1] == 0.1 && x[2] == 0);
    DM_OK(keep, demill_world_step(keep, 1));
    demill_world_destroy(keep);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Cases where the library's code is checked against one function's own      */
/* documentation (kept apart so that a failure here is reported on its own)  */

/* common.h: a value for a choice that is not a whole number gives
 * DEMILL_ERR_INVALID_VALUE, for demill_world_set and demill_pair_set alike. */
static void bad_non_whole_choice(scene *sc)
{
    static const double values[] = {1.5, 1.0000001, 0.25};
    for (int k = 0; k < 3; k++) {
        ctx(sc, "world.integrator = %.9g", values[k]);
        BAD(sc, DEMILL_ERR_INVALID_VALUE,
            demill_world_set(sc->w, DEMILL_WORLD_INTEGRATOR, values[k]), "world.integrator");
        for (int32_t key = DEMILL_PAIR_NORMAL; key <= DEMILL_PAIR_COHESION; key++) {
            ctx(sc, "pair law %d = %.9g", (int)key, values[k]);
            BAD(sc, DEMILL_ERR_INVALID_VALUE,
                demill_pair_set(sc->w, sc->mat[0], sc->mat[1], key, values[k]),
                demill_param_name(key));
        }
    }
}

START_TEST(non_whole_choice)
{
    both_dims(NULL, bad_non_whole_choice, NULL);
}
END_TEST

/* particles.h: flags are "0 or DEMILL_ADD_NO_OVERLAP; other bits give
 * DEMILL_ERR_UNKNOWN_KEY". */
static void bad_flags(scene *sc)
{
    double pos[15], rad[5], vel[15];
    demill_id ids[5];
    far_batch(sc, pos, rad, vel);
    static const uint32_t flags[] = {2, 3, 0x80000000u, 0xffffffffu};
    for (int k = 0; k < 4; k++) {
        ctx(sc, "particles_add flags 0x%x", (unsigned)flags[k]);
        BAD(sc, DEMILL_ERR_UNKNOWN_KEY,
            demill_particles_add(sc->w, sc->mat[0], 5, pos, rad, vel, flags[k], ids), "flag");
    }
}

START_TEST(particles_add_unknown_flags)
{
    both_dims(NULL, bad_flags, NULL);
}
END_TEST

/* particles.h: DEMILL_PARTICLE_ANGLE is for 2D worlds only; reading it in 3D
 * fails with DEMILL_ERR_DIMENSION, as demill_particles_read and
 * demill_particle_get document. */
static void bad_angle_read(scene *sc)
{
    const size_t n = pcount(sc);
    double *buf = calloc(n + 1, sizeof *buf), out[3] = {0, 0, 0};
    ck_assert_ptr_nonnull(buf);
    size_t cnt;
    ctx(sc, "reading the angle in 3D");
    BAD(sc, DEMILL_ERR_DIMENSION, demill_particles_read(sc->w, DEMILL_PARTICLE_ANGLE, buf, n, &cnt),
        "angle|2D");
    BAD(sc, DEMILL_ERR_DIMENSION,
        demill_particle_get(sc->w, sc->pid[0], DEMILL_PARTICLE_ANGLE, out), "angle|2D");
    free(buf);
}

START_TEST(angle_read_in_3d)
{
    char first[2048] = "";
    int failures = run_twins(3, NULL, bad_angle_read, NULL, first, sizeof first);
    ck_assert_msg(failures == 0, "%d failure(s) (all listed on stderr); first: %s", failures,
                  first);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("bad_input");
    TCase *tc = tcase_create("contract");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, null_world_and_create);
    tcase_add_test(tc, world_parameters);
    tcase_add_test(tc, material_parameters);
    tcase_add_test(tc, pair_parameters);
    tcase_add_test(tc, particles_add_values);
    tcase_add_test(tc, particles_add_overlap);
    tcase_add_test(tc, particles_add_overlap_allowed_without_flag);
    tcase_add_test(tc, particles_write_values);
    tcase_add_test(tc, particle_set_values);
    tcase_add_test(tc, wall_values);
    tcase_add_test(tc, body_values);
    tcase_add_test(tc, clump_values);
    tcase_add_test(tc, mesh_template_values);
    tcase_add_test(tc, finite_wall_values);
    tcase_add_test(tc, mesh_values);
    tcase_add_test(tc, wall_loads_values);
    tcase_add_test(tc, removed_handles);
    tcase_add_test(tc, foreign_handles);
    tcase_add_test(tc, wrong_kind_and_none_handles);
    tcase_add_test(tc, particles_remove_duplicates);
    tcase_add_test(tc, reads);
    tcase_add_test(tc, no_contact_model);
    tcase_add_test(tc, no_contact_model_with_wall);
    tcase_add_test(tc, rigid_pairs);
    tcase_add_test(tc, jkr_needs_hertz);
    tcase_add_test(tc, suggest_time_step);
    tcase_add_test(tc, progress_callback);
    tcase_add_test(tc, vtk_output);
    suite_add_tcase(s, tc);
    TCase *doc = tcase_create("documented_codes");
    tcase_set_timeout(doc, 600);
    tcase_add_test(doc, non_whole_choice);
    tcase_add_test(doc, particles_add_unknown_flags);
    tcase_add_test(doc, angle_read_in_3d);
    suite_add_tcase(s, doc);
    return dm_test_run(s);
}
