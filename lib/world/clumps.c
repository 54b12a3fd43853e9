/* clumps.c: the clumps' API (demill/clump.h): templates from spheres with
 * the mass properties of their union (physics/shapes), or from the spheres
 * that fill a closed mesh (its arrays, or an STL file read by physics/io)
 * with the fit kept, clumps added, removed, read and written, their members
 * listed (lib/physics/clumps/ moves them). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/io/io.h"
#include "world/world.h"

DEMILL_API int32_t demill_clump_template_field_size(int32_t field)
{
    switch (field) {
    case DEMILL_TEMPLATE_MASS:
    case DEMILL_TEMPLATE_VOLUME:
    case DEMILL_TEMPLATE_COUNT:
    case DEMILL_TEMPLATE_MESH_VOLUME:
    case DEMILL_TEMPLATE_FIT_VOLUME_ERROR:
    case DEMILL_TEMPLATE_FIT_DEVIATION_OUT:
    case DEMILL_TEMPLATE_FIT_DEVIATION_IN:
    case DEMILL_TEMPLATE_FIT_CELL: return 1;
    case DEMILL_TEMPLATE_CENTRE:
    case DEMILL_TEMPLATE_PRINCIPAL_MOMENTS: return 3;
    case DEMILL_TEMPLATE_PRINCIPAL_AXES: return 9;
    default: return 0;
    }
}

DEMILL_API int32_t demill_clump_field_size(int32_t field)
{
    switch (field) {
    case DEMILL_CLUMP_MASS: return 1;
    case DEMILL_CLUMP_ORIENTATION: return 4;
    case DEMILL_CLUMP_POSITION:
    case DEMILL_CLUMP_VELOCITY:
    case DEMILL_CLUMP_ANGULAR_VELOCITY:
    case DEMILL_CLUMP_ANGULAR_MOMENTUM:
    case DEMILL_CLUMP_FORCE:
    case DEMILL_CLUMP_TORQUE: return 3;
    default: return 0;
    }
}

/* Makes room for one more template with n members (-1: out of memory). */
static int template_reserve(demill_world *w, size_t n)
{
    if (w->ntemplates == w->cap_templates) {
        size_t cap = dm_grown_capacity(w->cap_templates, (size_t)w->ntemplates + 1);
        void **const arrays[] = {(void **)&w->templates};
        const size_t sizes[] = {sizeof *w->templates};
        if (cap > UINT32_MAX - 1 || dm_grow_arrays(arrays, sizes, 1, cap))
            return -1;
        w->cap_templates = (uint32_t)cap;
    }
    const size_t need = (size_t)w->ntmem + n;
    if (need > w->cap_tmem) {
        size_t cap = dm_grown_capacity(w->cap_tmem, need);
        void **const arrays[] = {(void **)&w->tmem};
        const size_t sizes[] = {DM_TMEM * sizeof *w->tmem};
        if (cap > UINT32_MAX || dm_grow_arrays(arrays, sizes, 1, cap))
            return -1;
        w->cap_tmem = (uint32_t)cap;
    }
    return 0;
}

/* The mass properties of the union of the template's spheres (discs in 2D,
 * weighed as dm_particle_mass() weighs one) of density rho: the mass, the
 * centre of mass (3 doubles), the principal moments increasing and the
 * principal axes as rows (2D: 0, 0, I_z and the identity). */
static demill_status union_mass(demill_world *w, const char *fn, size_t n, const double *c,
                                const double *r, double rho, double *mass, double com[3],
                                double moments[3], double axes[9])
{
    const char *why = NULL;
    demill_status s;
    memset(com, 0, 3 * sizeof *com);
    memset(axes, 0, 9 * sizeof *axes);
    if (w->dim == 3) {
        dm_mass_props mp;
        if ((s = dm_spheres_union_mass(n, c, r, rho, &mp, &why)))
            return dm_fail(w, s, "%s: %s", fn, why);
        double vec[3][3];
        dm_sym3_eigen(mp.inertia, moments, vec);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                axes[3 * a + b] = vec[a][b];
        *mass = mp.mass;
        memcpy(com, mp.com, 3 * sizeof *com);
        return DEMILL_OK;
    }
    double *c2 = malloc(2 * n * sizeof *c2);
    if (!c2)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    for (size_t k = 0; k < n; k++) {
        c2[2 * k] = c[3 * k];
        c2[2 * k + 1] = c[3 * k + 1];
    }
    s = dm_discs_union_mass(n, c2, r, rho, w->disc_thickness, mass, com, &moments[2], &why);
    free(c2);
    if (s)
        return dm_fail(w, s, "%s: %s", fn, why);
    moments[0] = moments[1] = 0.0;
    axes[0] = axes[4] = axes[8] = 1.0;
    return DEMILL_OK;
}

/* Adds the template of the n spheres (centres, radii: checked) of material
 * slot mat, weighed as their union, in *out; fit: the fit of the mesh they
 * were made from, or NULL. `fn` starts the messages. */
static demill_status add_template(demill_world *w, uint32_t mat, const char *fn, size_t n,
                                  const double *centres, const double *radii,
                                  const dm_fit_report *fit, demill_id *out)
{
    const double rho = w->mats[mat].density;
    double mass, com[3], moments[3], axes[9];
    demill_status s;
    if ((s = union_mass(w, fn, n, centres, radii, rho, &mass, com, moments, axes)))
        return s;
    const double mi = w->dim == 3 ? moments[0] : moments[2];
    if (!(mass > 0.0) || !isfinite(mass) || !(mi > 0.0) || !isfinite(moments[2]) ||
        !isfinite(1.0 / mass) || !isfinite(1.0 / mi))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the union has mass %g kg and principal moments "
                       "(%g, %g, %g) kg m^2: they must be finite and positive, and so must "
                       "their inverses",
                       fn, mass, moments[0], moments[1], moments[2]);
    if (template_reserve(w, n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    dm_template *t = &w->templates[w->ntemplates];
    memset(t, 0, sizeof *t);
    t->material = mat;
    t->n = (uint32_t)n;
    t->first = w->ntmem;
    t->mass = mass;
    t->im = 1.0 / mass;
    t->volume = mass / rho;
    memcpy(t->inertia, moments, sizeof t->inertia);
    memcpy(t->axes, axes, sizeof t->axes);
    memcpy(t->centre, com, sizeof t->centre);
    if (fit) {
        t->mesh_volume = fit->volume;
        t->deviation_out = fit->deviation_out;
        t->deviation_in = fit->deviation_in;
        t->cell = fit->h;
    }
    for (size_t k = 0; k < n; k++) { /* each centre in the principal frame */
        double *b = w->tmem + DM_TMEM * (w->ntmem + k), d[3];
        for (int c = 0; c < 3; c++)
            d[c] = centres[3 * k + c] - com[c];
        for (int a = 0; a < 3; a++)
            b[a] = axes[3 * a] * d[0] + axes[3 * a + 1] * d[1] + axes[3 * a + 2] * d[2];
        b[3] = radii[k];
    }
    w->ntmem += (uint32_t)n;
    dm_template_set_rpow(w, t);
    *out = dm_template_id(w, w->ntemplates++);
    dm_changed(w);
    return DEMILL_OK;
}

/* Whether a template of n more spheres fits the template store's uint32
 * counts. */
static int too_many_spheres(const demill_world *w, size_t n)
{
    return n > UINT32_MAX - 2 - (uint64_t)w->ntmem;
}

DEMILL_API demill_status demill_clump_template_add(demill_world *w, demill_id material, size_t n,
                                                   const double *centres, const double *radii,
                                                   demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!centres || !radii || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_template_add: %s is NULL",
                       !centres ? "centres" : !radii ? "radii" : "out");
    if (n == 0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "clump_template_add: n = 0 spheres");
    if (too_many_spheres(w, n))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "clump_template_add: too many spheres");
    for (size_t k = 0; k < n; k++) {
        for (int c = 0; c < 3; c++)
            if (!isfinite(centres[3 * k + c]))
                return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                               "clump_template_add: centre %zu has %c = %g, not finite", k,
                               "xyz"[c], centres[3 * k + c]);
        if (w->dim == 2 && centres[3 * k + 2] != 0.0)
            return dm_fail(w, DEMILL_ERR_DIMENSION,
                           "clump_template_add: centre %zu has z = %g but the world is 2D", k,
                           centres[3 * k + 2]);
        if (!isfinite(radii[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                           "clump_template_add: radius %zu = %g is not finite", k, radii[k]);
        if (!(radii[k] > 0.0))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "clump_template_add: radius %zu = %g must be > 0", k, radii[k]);
    }
    return add_template(w, mat, "clump_template_add", n, centres, radii, NULL, out);
}

/* The checks of both mesh templates before the mesh is read: the material
 * (its slot in *mat), the input (`what` names it) and out, a 3D world. */
static demill_status mesh_checks(demill_world *w, demill_id material, const char *fn,
                                 const void *input, const char *what, demill_id *out,
                                 uint32_t *mat)
{
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", mat);
    if (s)
        return s;
    if (!input || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: %s is NULL", fn, !input ? what : "out");
    if (w->dim != 3)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "%s: a template from a triangle mesh needs a 3D world", fn);
    return DEMILL_OK;
}

/* The template of up to n spheres that fill the mesh (nv vertices v, nt
 * triangles tri), of material slot mat; `name` (the path, or NULL) starts
 * the messages about the mesh after `fn`. */
static demill_status template_from_mesh(demill_world *w, uint32_t mat, const char *fn,
                                        const char *name, size_t nv, const double *v, size_t nt,
                                        const uint32_t *tri, size_t n, int cells, demill_id *out)
{
    const char *sep = name ? ": " : "";
    name = name ? name : "";
    if (too_many_spheres(w, n))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %s%stoo many spheres (%zu)", fn, name,
                       sep, n);
    double *c = malloc((n ? n : 1) * 4 * sizeof *c);
    if (!c)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: %s%sout of memory for %zu spheres", fn,
                       name, sep, n);
    double *r = c + 3 * n;
    dm_fit_report rep;
    char err[256];
    demill_status s = dm_spheres_fit_mesh(nv, v, nt, tri, n, cells, c, r, &rep, err, sizeof err);
    if (s)
        s = dm_fail(w, s, "%s: %s%s%s", fn, name, sep, err);
    else
        s = add_template(w, mat, fn, rep.n, c, r, &rep, out);
    free(c);
    return s;
}

DEMILL_API demill_status demill_clump_template_from_mesh(demill_world *w, demill_id material,
                                                         size_t n_vertices, const double *vertices,
                                                         size_t n_triangles,
                                                         const uint32_t *triangles, size_t n,
                                                         int cells, demill_id *out)
{
    const char *fn = "clump_template_from_mesh";
    uint32_t mat;
    demill_status s = mesh_checks(w, material, fn, vertices, "vertices", out, &mat);
    if (!s && !triangles)
        s = dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: triangles is NULL", fn);
    return s ? s
             : template_from_mesh(w, mat, fn, NULL, n_vertices, vertices, n_triangles, triangles,
                                  n, cells, out);
}

DEMILL_API demill_status demill_clump_template_from_stl(demill_world *w, demill_id material,
                                                        const char *path, double scale, size_t n,
                                                        int cells, demill_id *out)
{
    const char *fn = "clump_template_from_stl";
    uint32_t mat;
    demill_status s = mesh_checks(w, material, fn, path, "path", out, &mat);
    if (s)
        return s;
    uint8_t *b;
    size_t size;
    if ((s = dm_read_file(w, fn, path, &b, &size)))
        return s;
    dm_stl_mesh m;
    char err[256];
    s = dm_stl_parse(b, size, scale, NULL, &m, err, sizeof err);
    free(b);
    if (s)
        return dm_fail(w, s, "%s: %s: %s", fn, path, err);
    s = template_from_mesh(w, mat, fn, path, m.nv, m.v, m.nt, m.tri, n, cells, out);
    dm_stl_free(&m);
    return s;
}

DEMILL_API demill_status demill_clump_template_get(const demill_world *cw, demill_id id,
                                                   int32_t field, double *out)
{
    demill_world *w = (demill_world *)cw;
    uint32_t k;
    demill_status s = dm_enter(w, id, DEMILL_KIND_TEMPLATE, "template", &k);
    if (s)
        return s;
    if (!demill_clump_template_field_size(field))
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a template field", (int)field);
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_template_get: out is NULL");
    const dm_template *t = &w->templates[k];
    if (field >= DEMILL_TEMPLATE_MESH_VOLUME && !t->mesh_volume)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "clump_template_get: template field %d is of a fit, but the template "
                       "was made from spheres, not from a mesh",
                       (int)field);
    switch (field) {
    case DEMILL_TEMPLATE_MASS: out[0] = t->mass; break;
    case DEMILL_TEMPLATE_VOLUME: out[0] = t->volume; break;
    case DEMILL_TEMPLATE_COUNT: out[0] = t->n; break;
    case DEMILL_TEMPLATE_CENTRE: memcpy(out, t->centre, sizeof t->centre); break;
    case DEMILL_TEMPLATE_PRINCIPAL_MOMENTS: memcpy(out, t->inertia, sizeof t->inertia); break;
    case DEMILL_TEMPLATE_PRINCIPAL_AXES: memcpy(out, t->axes, sizeof t->axes); break;
    case DEMILL_TEMPLATE_MESH_VOLUME: out[0] = t->mesh_volume; break;
    case DEMILL_TEMPLATE_FIT_VOLUME_ERROR:
        out[0] = (t->mesh_volume - t->volume) / t->mesh_volume;
        break;
    case DEMILL_TEMPLATE_FIT_DEVIATION_OUT: out[0] = t->deviation_out; break;
    case DEMILL_TEMPLATE_FIT_DEVIATION_IN: out[0] = t->deviation_in; break;
    default: out[0] = t->cell;
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_clump_template_spheres(const demill_world *cw, demill_id id,
                                                       double *centres, double *radii,
                                                       size_t capacity, size_t *count)
{
    demill_world *w = (demill_world *)cw;
    uint32_t k;
    demill_status s = dm_enter(w, id, DEMILL_KIND_TEMPLATE, "template", &k);
    if (s)
        return s;
    if (!centres != !radii || (!centres && !count))
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_template_spheres: %s is NULL",
                       !centres ? (radii ? "centres" : "count (with centres and radii)")
                                : "radii");
    const dm_template *t = &w->templates[k];
    if (count)
        *count = t->n;
    if (!centres)
        return DEMILL_OK;
    if (capacity < t->n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL,
                       "clump_template_spheres: capacity %zu, %u spheres", capacity, t->n);
    for (uint32_t m = 0; m < t->n; m++) {
        const double *b = w->tmem + DM_TMEM * (size_t)(t->first + m);
        memcpy(centres + 3 * (size_t)m, b, 3 * sizeof *b);
        radii[m] = b[3];
    }
    return DEMILL_OK;
}

/* A position or velocity: finite, and z = 0 in 2D. */
static demill_status check_vec(demill_world *w, const double *v, const char *who,
                               const char *what)
{
    for (int c = 0; c < 3; c++)
        if (!isfinite(v[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: %s[%d] = %g is not finite", who, what,
                           c, v[c]);
    if (w->dim == 2 && v[2] != 0.0)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s: %s has z = %g but the world is 2D", who,
                       what, v[2]);
    return DEMILL_OK;
}

/* An orientation, normalised into q: finite, of norm > 0 and in 2D a turn
 * about z. */
static demill_status check_orientation(demill_world *w, const double *in, const char *who,
                                       double q[4])
{
    double n2 = 0.0;
    for (int c = 0; c < 4; c++) {
        if (!isfinite(in[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: orientation[%d] = %g is not finite",
                           who, c, in[c]);
        n2 += in[c] * in[c];
    }
    const double n = sqrt(n2);
    if (!(n > 0.0) || !isfinite(n))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: orientation (%g, %g, %g, %g) has no direction (norm %g)", who, in[0],
                       in[1], in[2], in[3], n);
    if (w->dim == 2 && (in[1] != 0.0 || in[2] != 0.0))
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "%s: orientation (%g, %g, %g, %g) is not a turn about z, as a 2D world "
                       "needs (x = y = 0)",
                       who, in[0], in[1], in[2], in[3]);
    for (int c = 0; c < 4; c++)
        q[c] = in[c] / n;
    return DEMILL_OK;
}

/* Sets clump c's orientation to the unit quaternion q (2D: its angle too). */
static void set_orientation(demill_world *w, dm_clump *c, const double q[4])
{
    memcpy(c->q, q, sizeof c->q);
    if (w->dim == 2)
        c->theta = 2.0 * atan2(q[3], q[0]);
}

/* Sets clump c's angular velocity om (world frame) and its angular
 * momentum L = R I Rᵀ ω at its orientation (2D: I_z ω_z). */
static void set_spin(demill_world *w, dm_clump *c, const double om[3])
{
    const dm_template *t = &w->templates[c->tmpl];
    memcpy(c->om, om, sizeof c->om);
    if (w->dim == 2) {
        c->L[0] = c->L[1] = 0.0;
        c->L[2] = t->inertia[2] * om[2];
        return;
    }
    double R[9], pi[3];
    dm_quat_matrix(c->q, R);
    for (int a = 0; a < 3; a++)
        pi[a] = t->inertia[a] * (R[a] * om[0] + R[3 + a] * om[1] + R[6 + a] * om[2]);
    for (int a = 0; a < 3; a++)
        c->L[a] = R[3 * a] * pi[0] + R[3 * a + 1] * pi[1] + R[3 * a + 2] * pi[2];
}

/* After a change of clump k's motion made through the API: its members
 * follow, the velocities the dashpots see are its own. */
static void moved(demill_world *w, uint32_t k)
{
    dm_clump *c = &w->clumps[k];
    memcpy(c->vp, c->v, sizeof c->vp);
    memcpy(c->wp, c->om, sizeof c->wp);
    dm_clump_place(w, k);
    w->forces_valid = false;
}

int dm_clumps_reserve(demill_world *w, size_t count, size_t n)
{
    const size_t slots = (size_t)w->nclumps + count, members = count * n;
    if (slots > w->cap_clumps) {
        size_t cap = dm_grown_capacity(w->cap_clumps, slots);
        void **const arrays[] = {(void **)&w->clumps};
        const size_t sizes[] = {sizeof *w->clumps};
        if (cap > UINT32_MAX - 1 || dm_grow_arrays(arrays, sizes, 1, cap))
            return -1;
        w->cap_clumps = (uint32_t)cap;
    }
    const size_t need = (size_t)w->ncmem + members;
    if (need > w->cap_cmem) {
        size_t cap = dm_grown_capacity(w->cap_cmem, need);
        void **const arrays[] = {(void **)&w->cmem};
        const size_t sizes[] = {sizeof *w->cmem};
        if (cap > UINT32_MAX || dm_grow_arrays(arrays, sizes, 1, cap))
            return -1;
        w->cap_cmem = (uint32_t)cap;
    }
    return dm_handles_reserve(&w->clh, (uint32_t)count) ||
                   dm_particles_reserve(w, w->p.n + (uint32_t)members) ||
                   dm_handles_reserve(&w->ph, (uint32_t)members)
               ? -1
               : 0;
}

demill_id dm_clump_insert(demill_world *w, uint32_t tk, const double position[3],
                          const double q[4])
{
    uint32_t slot = w->nclumps;
    for (uint32_t k = 0; k < w->nclumps && w->live_clumps < w->nclumps; k++)
        if (!dm_clump_live(w, k)) { /* a removed clump's */
            slot = k;
            break;
        }
    const dm_template *t = &w->templates[tk];
    dm_clump *c = &w->clumps[slot];
    memset(c, 0, sizeof *c);
    c->tmpl = tk;
    c->first = w->ncmem;
    memcpy(c->x, position, sizeof c->x);
    set_orientation(w, c, q);
    /* the members, as particles at the clump's centre, then placed */
    dm_particles *P = &w->p;
    const uint32_t i0 = P->n;
    for (uint32_t m = 0; m < t->n; m++) {
        const double *b = w->tmem + DM_TMEM * (size_t)(t->first + m);
        dm_particles_append(w, t->material, 1, position, b + 3, NULL, NULL);
        const uint32_t i = i0 + m;
        P->clump[i] = slot + 1;
        P->m[i] = t->mass;
        P->im[i] = t->im;
        /* the inverse of the mean principal moment (2D: of I_z), which the
         * rolling spring's inertia reads */
        P->iinv[i] = w->dim == 3 ? 3.0 / (t->inertia[0] + t->inertia[1] + t->inertia[2])
                                 : 1.0 / t->inertia[2];
        w->cmem[w->ncmem++] = P->hid[i];
    }
    if (slot == w->nclumps)
        w->nclumps++;
    w->live_clumps++;
    c->handle = dm_handles_issue(&w->clh, slot);
    moved(w, slot);
    dm_changed(w);
    return dm_clump_id(w, slot);
}

DEMILL_API demill_status demill_clump_add(demill_world *w, demill_id tmpl,
                                          const double position[3], const double orientation[4],
                                          demill_id *out)
{
    uint32_t tk;
    demill_status s = dm_enter(w, tmpl, DEMILL_KIND_TEMPLATE, "template", &tk);
    if (s)
        return s;
    if (!position || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_add: %s is NULL",
                       !position ? "position" : "out");
    double q[4] = {1.0, 0.0, 0.0, 0.0};
    if ((s = check_vec(w, position, "clump_add", "position")) ||
        (orientation && (s = check_orientation(w, orientation, "clump_add", q))))
        return s;
    const dm_template *t = &w->templates[tk];
    if (t->n > UINT32_MAX - 2 - (uint64_t)w->p.n || w->ncmem > UINT32_MAX - t->n)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "clump_add: too many particles");
    if (dm_clumps_reserve(w, 1, t->n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "clump_add: out of memory");
    *out = dm_clump_insert(w, tk, position, q);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_clump_remove(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_CLUMP, "clump", &slot);
    if (s)
        return s;
    dm_particles *P = &w->p;
    /* the neighbour build's scratch serves as the renumbering map */
    if (dm_grid_reserve(&w->grid, P->n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "clump_remove: out of memory");
    dm_clump *c = &w->clumps[slot];
    const uint32_t n = w->templates[c->tmpl].n, first = c->first;
    uint32_t *map = w->grid.inv;
    for (uint32_t i = 0; i < P->n; i++)
        map[i] = P->clump[i] == slot + 1 ? DM_FREE : i;
    dm_particles_compact(w, map);
    /* its members' handles leave the list, the later clumps' move down */
    memmove(w->cmem + first, w->cmem + first + n, (w->ncmem - first - n) * sizeof *w->cmem);
    w->ncmem -= n;
    for (uint32_t k = 0; k < w->nclumps; k++)
        if (dm_clump_live(w, k) && w->clumps[k].first > first)
            w->clumps[k].first -= n;
    dm_handles_release(&w->clh, c->handle);
    c->handle = DM_FREE;
    w->live_clumps--;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_clump_get(const demill_world *cw, demill_id id, int32_t field,
                                          double *out)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_CLUMP, "clump", &slot);
    if (s)
        return s;
    const int size = demill_clump_field_size(field);
    if (!size)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a clump field", (int)field);
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_get: out is NULL");
    const dm_clump *c = &w->clumps[slot];
    double load[2][3];
    const double *src;
    switch (field) {
    case DEMILL_CLUMP_POSITION: src = c->x; break;
    case DEMILL_CLUMP_ORIENTATION: src = c->q; break;
    case DEMILL_CLUMP_VELOCITY: src = c->v; break;
    case DEMILL_CLUMP_ANGULAR_VELOCITY: src = c->om; break;
    case DEMILL_CLUMP_ANGULAR_MOMENTUM: src = c->L; break;
    case DEMILL_CLUMP_MASS: src = &w->templates[c->tmpl].mass; break;
    default:
        dm_clump_load(w, slot, load[0], load[1]);
        src = load[field == DEMILL_CLUMP_TORQUE];
    }
    memcpy(out, src, (size_t)size * sizeof *out);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_clump_set(demill_world *w, demill_id id, int32_t field,
                                          const double *in)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_CLUMP, "clump", &slot);
    if (s)
        return s;
    if (!demill_clump_field_size(field))
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a clump field", (int)field);
    if (field == DEMILL_CLUMP_ANGULAR_MOMENTUM || field == DEMILL_CLUMP_FORCE ||
        field == DEMILL_CLUMP_TORQUE || field == DEMILL_CLUMP_MASS)
        return dm_fail(w, DEMILL_ERR_READ_ONLY, "clump field %d is read-only", (int)field);
    if (!in)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_set: in is NULL");
    dm_clump *c = &w->clumps[slot];
    double q[4], om[3];
    switch (field) {
    case DEMILL_CLUMP_ORIENTATION:
        if ((s = check_orientation(w, in, "clump_set", q)))
            return s;
        memcpy(om, c->om, sizeof om);
        set_orientation(w, c, q);
        set_spin(w, c, om);
        w->nlist_valid = false;
        break;
    case DEMILL_CLUMP_ANGULAR_VELOCITY:
        for (int a = 0; a < 3; a++)
            if (!isfinite(in[a]))
                return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                               "clump_set: angular velocity[%d] = %g is not finite", a, in[a]);
        if (w->dim == 2 && (in[0] != 0.0 || in[1] != 0.0))
            return dm_fail(w, DEMILL_ERR_DIMENSION,
                           "clump_set: angular velocity has x or y components but the world is "
                           "2D (only z is allowed)");
        set_spin(w, c, in);
        break;
    default: /* the position or the velocity */
        if ((s = check_vec(w, in, "clump_set",
                           field == DEMILL_CLUMP_POSITION ? "position" : "velocity")))
            return s;
        memcpy(field == DEMILL_CLUMP_POSITION ? c->x : c->v, in, sizeof c->x);
        if (field == DEMILL_CLUMP_POSITION)
            w->nlist_valid = false;
    }
    moved(w, slot);
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_clump_members(const demill_world *cw, demill_id id,
                                              demill_id *ids, size_t capacity, size_t *count)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_CLUMP, "clump", &slot);
    if (s)
        return s;
    if (!ids && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "clump_members: ids and count are both NULL");
    const dm_clump *c = &w->clumps[slot];
    const uint32_t n = w->templates[c->tmpl].n;
    if (count)
        *count = n;
    if (!ids)
        return DEMILL_OK;
    if (capacity < n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "clump_members: capacity %zu, %u members",
                       capacity, n);
    for (uint32_t m = 0; m < n; m++)
        ids[m] = dm_particle_id(w, w->ph.slot[w->cmem[c->first + m]]);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_particle_clump(const demill_world *cw, demill_id particle,
                                               demill_id *clump)
{
    demill_world *w = (demill_world *)cw;
    uint32_t i;
    demill_status s = dm_enter(w, particle, DEMILL_KIND_PARTICLE, "particle", &i);
    if (s)
        return s;
    if (!clump)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particle_clump: clump is NULL");
    *clump = w->p.clump[i] ? dm_clump_id(w, w->p.clump[i] - 1) : DEMILL_ID_NONE;
    return DEMILL_OK;
}
