/* particles.c: adding, removing, reading and writing particles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

/* ---- validation ---------------------------------------------------------- */

/* `who` names the particle in messages, e.g. "particle 3". */
static demill_status check_vec(demill_world *w, const double *v, const char *what,
                               const char *who, int z_must_be_zero)
{
    for (int c = 0; c < 3; c++)
        if (!isfinite(v[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: %s[%d] = %g is not finite", who, what,
                           c, v[c]);
    if (z_must_be_zero && v[2] != 0.0)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "%s: %s has z = %g but the world is 2D (z must be 0)", who, what, v[2]);
    return DEMILL_OK;
}

/* A radius > 0 that gives a particle of material mat a mass and moment of
 * inertia that are finite and positive, as are their inverses. */
static demill_status check_radius(demill_world *w, uint32_t mat, double r, const char *who)
{
    if (!isfinite(r))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: radius %g is not finite", who, r);
    if (!(r > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: radius %g must be > 0", who, r);
    double m, inv_i;
    return dm_particle_mass_checked(w, mat, r, who, &m, &inv_i);
}

/* Overlap test of a batch against the world, itself (each particle against
 * the earlier ones) and the walls. Returns DEMILL_OK or DEMILL_ERR_OVERLAP
 * with a message naming both bodies. */
static demill_status check_overlaps(demill_world *w, size_t n, const double *pos,
                                    const double *radii)
{
    double rmax = 0.0, depth;
    for (size_t k = 0; k < n; k++)
        rmax = fmax(rmax, radii[k]);
    dm_sphere_index ix;
    if (dm_spheres_build(&ix, w, n, pos, radii, rmax))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "particles_add: out of memory");
    const uint32_t nold = w->p.n;
    demill_status s = DEMILL_OK;
    for (size_t k = 0; k < n && !s; k++) {
        const double *xk = pos + 3 * k;
        int64_t o = dm_spheres_find(&ix, xk, radii[k], nold + (uint32_t)k, &depth);
        uint32_t wk;
        if (o >= 0 && (uint32_t)o < nold)
            s = dm_fail(w, DEMILL_ERR_OVERLAP,
                        "particle %zu of the batch overlaps existing particle 0x%llx by %g m", k,
                        (unsigned long long)dm_particle_id(w, (uint32_t)o), depth);
        else if (o >= 0)
            s = dm_fail(w, DEMILL_ERR_OVERLAP,
                        "particle %zu of the batch overlaps particle %zu of the batch by %g m", k,
                        (size_t)o - nold, depth);
        else if ((wk = dm_wall_overlap(w, xk, radii[k], &depth)) != DM_FREE)
            s = dm_fail(w, DEMILL_ERR_OVERLAP, "particle %zu of the batch overlaps %s 0x%llx by %g m",
                        k, w->walls[wk].drum_part ? "the drum" : "wall",
                        (unsigned long long)dm_wall_id(w, wk), depth);
    }
    dm_spheres_free(&ix);
    return s;
}

/* ---- add / remove ---------------------------------------------------------- */

DEMILL_API demill_status demill_particles_add(demill_world *w, demill_id material, size_t n,
                                              const double *positions, const double *radii,
                                              const double *velocities, uint32_t flags,
                                              demill_id *ids)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (flags & ~(uint32_t)DEMILL_ADD_NO_OVERLAP)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "particles_add: unknown flags 0x%x",
                       (unsigned)flags);
    if (n == 0) {
        dm_changed(w);
        return DEMILL_OK;
    }
    if (!positions || !radii)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particles_add: %s is NULL",
                       positions ? "radii" : "positions");
    const int flat = w->dim == 2;
    for (size_t k = 0; k < n; k++) {
        char who[48];
        snprintf(who, sizeof who, "particle %zu of the batch", k);
        if ((s = check_vec(w, positions + 3 * k, "position", who, flat)) ||
            (s = check_radius(w, mat, radii[k], who)) ||
            (velocities && (s = check_vec(w, velocities + 3 * k, "velocity", who, flat))))
            return s;
    }
    if (n > UINT32_MAX - 2 - (uint64_t)w->p.n)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "particles_add: too many particles");
    if ((flags & DEMILL_ADD_NO_OVERLAP) && (s = check_overlaps(w, n, positions, radii)))
        return s;
    if ((s = dm_particles_append(w, mat, n, positions, radii, velocities, ids)))
        return s;
    dm_changed(w);
    return DEMILL_OK;
}

/* Appends n valid particles of material slot mat (positions and velocities
 * 3 doubles each; velocities may be NULL). Fails only when memory runs out,
 * and then adds nothing. */
demill_status dm_particles_append(demill_world *w, uint32_t mat, size_t n, const double *positions,
                                  const double *radii, const double *velocities, demill_id *ids)
{
    dm_particles *P = &w->p;
    if (dm_particles_reserve(w, P->n + (uint32_t)n) || dm_handles_reserve(&w->ph, (uint32_t)n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for %zu more particles", n);
    const int D = w->dim, W = dm_wdim(w);
    for (size_t k = 0; k < n; k++) {
        uint32_t i = P->n++;
        for (int c = 0; c < D; c++) {
            P->x[D * i + c] = positions[3 * k + c];
            P->x0[D * i + c] = positions[3 * k + c];
            P->v[D * i + c] = P->vp[D * i + c] = velocities ? velocities[3 * k + c] : 0.0;
            P->f[D * i + c] = 0.0;
        }
        for (int c = 0; c < W; c++)
            P->w[W * i + c] = P->wp[W * i + c] = P->t[W * i + c] = 0.0;
        P->theta[i] = 0.0;
        if (dm_qdim(w))
            dm_quat_put(P->q, i, (const double[4]){1.0, 0.0, 0.0, 0.0});
        P->r[i] = radii[k];
        P->mat[i] = (uint16_t)mat;
        P->clump[i] = 0;
        dm_particle_set_mass(w, i, false);
        P->hid[i] = dm_handles_issue(&w->ph, i);
        if (ids)
            ids[k] = dm_particle_id(w, i);
    }
    w->mat_particles[mat] += (uint32_t)n;
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    return DEMILL_OK;
}

/* Drops pairs of removed particles and renumbers the rest (order kept, so
 * the lists stay sorted and valid). */
static void clist_remap(dm_clist *l, const uint32_t *map, int walls)
{
    for (int k = 0; k < DM_KERNELS; k++) {
        dm_bucket *b = &l->b[k];
        uint32_t m = 0;
        for (uint32_t p = 0; p < b->n; p++) {
            uint32_t i = map[b->i[p]], j = walls ? b->j[p] : map[b->j[p]];
            if (i != DM_FREE && j != DM_FREE)
                dm_bucket_move(b, m++, p, i, j);
        }
        b->n = m;
    }
}

/* Removes the particles whose entry of map (one per particle, from
 * w->grid.inv) is DM_FREE, keeping the others' order and contacts. */
void dm_particles_compact(demill_world *w, uint32_t *map)
{
    dm_particles *P = &w->p;
    const int D = w->dim, W = dm_wdim(w);
    uint32_t m = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        if (map[i] == DM_FREE) {
            w->mat_particles[P->mat[i]]--;
            dm_handles_release(&w->ph, P->hid[i]);
            continue;
        }
        map[i] = m;
        if (m != i) {
            memcpy(P->x + D * m, P->x + D * i, D * sizeof *P->x);
            memcpy(P->x0 + D * m, P->x0 + D * i, D * sizeof *P->x);
            memcpy(P->v + D * m, P->v + D * i, D * sizeof *P->x);
            memcpy(P->vp + D * m, P->vp + D * i, D * sizeof *P->x);
            memcpy(P->f + D * m, P->f + D * i, D * sizeof *P->x);
            memcpy(P->w + W * m, P->w + W * i, W * sizeof *P->x);
            memcpy(P->wp + W * m, P->wp + W * i, W * sizeof *P->x);
            memcpy(P->t + W * m, P->t + W * i, W * sizeof *P->x);
            P->theta[m] = P->theta[i];
            for (int c = 0; c < dm_qdim(w); c++)
                P->q[c][m] = P->q[c][i];
            P->r[m] = P->r[i];
            P->m[m] = P->m[i];
            P->im[m] = P->im[i];
            P->iinv[m] = P->iinv[i];
            P->mat[m] = P->mat[i];
            P->hid[m] = P->hid[i];
            P->clump[m] = P->clump[i];
            w->ph.slot[P->hid[m]] = m;
        }
        m++;
    }
    P->n = m;
    clist_remap(&w->pp, map, 0);
    clist_remap(&w->pw, map, 1);
    w->res.valid = false;
    w->ptab_dirty = true;
    w->forces_valid = false;
}

DEMILL_API demill_status demill_particles_remove(demill_world *w, size_t n, const demill_id *ids)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (n == 0) {
        dm_changed(w);
        return DEMILL_OK;
    }
    if (!ids)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particles_remove: ids is NULL");
    dm_particles *P = &w->p;
    /* the neighbour build's scratch serves as the renumbering map */
    if (dm_grid_reserve(&w->grid, P->n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "particles_remove: out of memory");
    uint32_t *map = w->grid.inv;
    for (uint32_t i = 0; i < P->n; i++)
        map[i] = i;
    for (size_t k = 0; k < n; k++) {
        uint32_t slot;
        char what[48];
        snprintf(what, sizeof what, "ids[%zu]", k);
        if ((s = dm_resolve(w, ids[k], DEMILL_KIND_PARTICLE, what, &slot)))
            return s;
        if (map[slot] == DM_FREE)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "particles_remove: ids[%zu] is listed twice",
                           k);
        if (P->clump[slot])
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "particles_remove: ids[%zu] is a member of clump 0x%llx; remove the "
                           "clump (demill_clump_remove)",
                           k, (unsigned long long)dm_clump_id(w, P->clump[slot] - 1));
        map[slot] = DM_FREE;
    }
    dm_particles_compact(w, map);
    dm_changed(w);
    return DEMILL_OK;
}

/* ---- read / write ---------------------------------------------------------- */

DEMILL_API int32_t demill_particle_field_size(int32_t field)
{
    switch (field) {
    case DEMILL_PARTICLE_POSITION:
    case DEMILL_PARTICLE_VELOCITY:
    case DEMILL_PARTICLE_ANGULAR_VELOCITY:
    case DEMILL_PARTICLE_FORCE:
    case DEMILL_PARTICLE_TORQUE: return 3;
    case DEMILL_PARTICLE_ORIENTATION: return 4;
    case DEMILL_PARTICLE_RADIUS:
    case DEMILL_PARTICLE_MASS:
    case DEMILL_PARTICLE_ANGLE:
    case DEMILL_PARTICLE_FIXED: return 1;
    default: return 0;
    }
}

static demill_status check_field(demill_world *w, int32_t field, int writing)
{
    if (!demill_particle_field_size(field))
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a particle field", (int)field);
    if (field == DEMILL_PARTICLE_ANGLE && w->dim == 3)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "the rotation angle exists only in 2D worlds");
    if (field == DEMILL_PARTICLE_ORIENTATION && w->dim == 2)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "the orientation quaternion exists only in 3D worlds (2D: "
                       "DEMILL_PARTICLE_ANGLE)");
    if (writing && (field == DEMILL_PARTICLE_MASS || field == DEMILL_PARTICLE_FORCE ||
                    field == DEMILL_PARTICLE_TORQUE))
        return dm_fail(w, DEMILL_ERR_READ_ONLY, "particle field %d is read-only", (int)field);
    return DEMILL_OK;
}

/* Copies storage slot i's field into out (1, 3 or 4 doubles). */
static void get_one(const demill_world *w, uint32_t i, int32_t field, double *out)
{
    const dm_particles *P = &w->p;
    const int D = w->dim, W = dm_wdim(w);
    const double *src = NULL;
    int nsrc = D;
    switch (field) {
    case DEMILL_PARTICLE_POSITION: src = P->x + D * i; break;
    case DEMILL_PARTICLE_VELOCITY: src = P->v + D * i; break;
    case DEMILL_PARTICLE_FORCE: src = P->f + D * i; break;
    case DEMILL_PARTICLE_ANGULAR_VELOCITY: src = P->w + W * i; nsrc = W; break;
    case DEMILL_PARTICLE_TORQUE: src = P->t + W * i; nsrc = W; break;
    case DEMILL_PARTICLE_RADIUS: out[0] = P->r[i]; return;
    case DEMILL_PARTICLE_MASS: out[0] = P->m[i]; return;
    case DEMILL_PARTICLE_ANGLE: out[0] = P->theta[i]; return;
    case DEMILL_PARTICLE_ORIENTATION: dm_quat_get(P->q, i, out); return;
    case DEMILL_PARTICLE_FIXED: out[0] = dm_particle_fixed(P, i); return;
    }
    out[0] = out[1] = out[2] = 0.0;
    if (nsrc == 1)
        out[2] = src[0]; /* 2D angular quantities are about z */
    else
        memcpy(out, src, (size_t)nsrc * sizeof *out);
}

/* A fixed particle's velocity or angular velocity can only be 0. */
static demill_status check_at_rest(demill_world *w, uint32_t i, const double *in,
                                   const char *what, const char *who)
{
    if (dm_particle_fixed(&w->p, i) && (in[0] != 0.0 || in[1] != 0.0 || in[2] != 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the particle is fixed; its %s can only be 0", who, what);
    return DEMILL_OK;
}

/* The largest magnitude of q's 4 components, by which it is scaled before
 * its norm is taken, so that no square overflows or underflows. */
static double quaternion_scale(const double *q)
{
    double m = 0.0;
    for (int c = 0; c < 4; c++)
        m = fabs(q[c]) > m ? fabs(q[c]) : m;
    return m;
}

/* An orientation to write: 4 finite doubles, not all 0. */
static demill_status check_quaternion(demill_world *w, const double *q, const char *who)
{
    for (int c = 0; c < 4; c++)
        if (!isfinite(q[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                           "%s: orientation (%g, %g, %g, %g) is not finite", who, q[0], q[1],
                           q[2], q[3]);
    if (quaternion_scale(q) == 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: orientation (0, 0, 0, 0) is no rotation; a unit quaternion (w, x, "
                       "y, z) is expected, e.g. (1, 0, 0, 0)",
                       who);
    return DEMILL_OK;
}

/* A value for `field` of the particle in storage slot i. */
static demill_status check_one(demill_world *w, uint32_t i, int32_t field, const double *in,
                               const char *who)
{
    const int flat = w->dim == 2;
    demill_status s;
    if (w->p.clump[i])
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the particle is a member of clump 0x%llx, which moves it; set the "
                       "clump (demill_clump_set)",
                       who, (unsigned long long)dm_clump_id(w, w->p.clump[i] - 1));
    switch (field) {
    case DEMILL_PARTICLE_POSITION: return check_vec(w, in, "position", who, flat);
    case DEMILL_PARTICLE_VELOCITY:
        if ((s = check_vec(w, in, "velocity", who, flat)))
            return s;
        return check_at_rest(w, i, in, "velocity", who);
    case DEMILL_PARTICLE_ANGULAR_VELOCITY:
        if ((s = check_vec(w, in, "angular velocity", who, 0)))
            return s;
        if (flat && (in[0] != 0.0 || in[1] != 0.0))
            return dm_fail(w, DEMILL_ERR_DIMENSION,
                           "%s: angular velocity has x or y components but the world is 2D "
                           "(only z is allowed)",
                           who);
        return check_at_rest(w, i, in, "angular velocity", who);
    case DEMILL_PARTICLE_RADIUS: return check_radius(w, w->p.mat[i], in[0], who);
    case DEMILL_PARTICLE_FIXED:
        if (!isfinite(in[0]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: fixed = %g is not finite", who, in[0]);
        if (in[0] != 0.0 && in[0] != 1.0)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: fixed = %g, not 0 or 1", who,
                           in[0]);
        return DEMILL_OK;
    case DEMILL_PARTICLE_ORIENTATION: return check_quaternion(w, in, who);
    default:
        if (!isfinite(in[0]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: angle %g is not finite", who, in[0]);
        return DEMILL_OK;
    }
}

static void set_one(demill_world *w, uint32_t i, int32_t field, const double *in)
{
    dm_particles *P = &w->p;
    const int D = w->dim, W = dm_wdim(w);
    switch (field) {
    case DEMILL_PARTICLE_POSITION:
        memcpy(P->x + D * i, in, (size_t)D * sizeof *in);
        w->nlist_valid = false;
        break;
    case DEMILL_PARTICLE_VELOCITY: memcpy(P->v + D * i, in, (size_t)D * sizeof *in); break;
    case DEMILL_PARTICLE_ANGULAR_VELOCITY:
        memcpy(P->w + W * i, W == 3 ? in : in + 2, (size_t)W * sizeof *in);
        break;
    case DEMILL_PARTICLE_RADIUS:
        P->r[i] = in[0];
        dm_particle_set_mass(w, i, dm_particle_fixed(P, i));
        w->nlist_valid = false;
        break;
    case DEMILL_PARTICLE_ANGLE: P->theta[i] = in[0]; break;
    case DEMILL_PARTICLE_ORIENTATION: { /* normalised */
        const double m = quaternion_scale(in);
        double n2 = 0.0;
        for (int c = 0; c < 4; c++)
            n2 += (in[c] / m) * (in[c] / m);
        const double n = sqrt(n2);
        for (int c = 0; c < 4; c++)
            P->q[c][i] = in[c] / m / n;
        break;
    }
    case DEMILL_PARTICLE_FIXED:
        if (in[0] != 0.0) { /* at rest, for good */
            memset(P->v + D * i, 0, (size_t)D * sizeof *P->v);
            memset(P->vp + D * i, 0, (size_t)D * sizeof *P->vp);
            memset(P->w + W * i, 0, (size_t)W * sizeof *P->w);
            memset(P->wp + W * i, 0, (size_t)W * sizeof *P->wp);
        }
        dm_particle_set_mass(w, i, in[0] != 0.0);
        w->nlist_valid = false; /* the pairs it may have change */
        break;
    }
    w->forces_valid = false;
}

DEMILL_API demill_status demill_particles_read(const demill_world *cw, int32_t field, double *out,
                                               size_t capacity, size_t *count)
{
    demill_world *w = (demill_world *)cw;
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if ((s = check_field(w, field, 0)))
        return s;
    if (!out && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particles_read: out and count are both NULL");
    if (count)
        *count = w->p.n;
    if (!out)
        return DEMILL_OK;
    if (capacity < w->p.n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL,
                       "particles_read: capacity %zu, %u particles", capacity, w->p.n);
    const int size = demill_particle_field_size(field);
    size_t k = 0;
    for (uint32_t h = 0; h < w->ph.n; h++) {
        uint32_t i = w->ph.slot[h];
        if (i == DM_FREE)
            continue;
        double v[4];
        get_one(w, i, field, v);
        memcpy(out + (size_t)size * k++, v, (size_t)size * sizeof *v);
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_particles_read_ids(const demill_world *cw, int32_t field,
                                                   demill_id *out, size_t capacity, size_t *count)
{
    demill_world *w = (demill_world *)cw;
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (field != DEMILL_PARTICLE_ID && field != DEMILL_PARTICLE_MATERIAL &&
        field != DEMILL_PARTICLE_CLUMP)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a particle id field", (int)field);
    if (!out && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER,
                       "particles_read_ids: out and count are both NULL");
    if (count)
        *count = w->p.n;
    if (!out)
        return DEMILL_OK;
    if (capacity < w->p.n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL,
                       "particles_read_ids: capacity %zu, %u particles", capacity, w->p.n);
    size_t k = 0;
    for (uint32_t h = 0; h < w->ph.n; h++) {
        uint32_t i = w->ph.slot[h];
        if (i == DM_FREE)
            continue;
        const uint32_t c = w->p.clump[i];
        out[k++] = field == DEMILL_PARTICLE_ID         ? dm_particle_id(w, i)
                   : field == DEMILL_PARTICLE_MATERIAL ? dm_material_id(w, w->p.mat[i])
                   : c                                 ? dm_clump_id(w, c - 1)
                                                       : DEMILL_ID_NONE;
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_particles_write(demill_world *w, int32_t field, const double *in,
                                                size_t n)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if ((s = check_field(w, field, 1)))
        return s;
    if (n != w->p.n)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "particles_write: n = %zu but the world has %u particles", n, w->p.n);
    if (n && !in)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particles_write: in is NULL");
    const int size = demill_particle_field_size(field);
    size_t k = 0;
    for (uint32_t h = 0; h < w->ph.n; h++) {
        const uint32_t i = w->ph.slot[h];
        if (i == DM_FREE)
            continue;
        char who[48];
        snprintf(who, sizeof who, "particle %zu (in id order)", k);
        if ((s = check_one(w, i, field, in + (size_t)size * k++, who)))
            return s;
    }
    k = 0;
    for (uint32_t h = 0; h < w->ph.n; h++) {
        uint32_t i = w->ph.slot[h];
        if (i != DM_FREE)
            set_one(w, i, field, in + (size_t)size * k++);
    }
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_particle_get(const demill_world *cw, demill_id particle,
                                             int32_t field, double *out)
{
    demill_world *w = (demill_world *)cw;
    uint32_t i;
    demill_status s = dm_enter(w, particle, DEMILL_KIND_PARTICLE, "particle", &i);
    if (s || (s = check_field(w, field, 0)))
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particle_get: out is NULL");
    double v[4];
    get_one(w, i, field, v);
    memcpy(out, v, (size_t)demill_particle_field_size(field) * sizeof *v);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_particle_set(demill_world *w, demill_id particle, int32_t field,
                                             const double *in)
{
    uint32_t i;
    demill_status s = dm_enter(w, particle, DEMILL_KIND_PARTICLE, "particle", &i);
    if (s || (s = check_field(w, field, 1)))
        return s;
    if (!in)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "particle_set: in is NULL");
    char who[48];
    snprintf(who, sizeof who, "particle 0x%llx", (unsigned long long)particle);
    if ((s = check_one(w, i, field, in, who)))
        return s;
    set_one(w, i, field, in);
    dm_changed(w);
    return DEMILL_OK;
}
