/* particles.c: the particle store: its arrays (structure of arrays) grown,
 * reordered by the neighbour sort and freed, and the masses of particles. */
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "physics/state/state.h"

/* Grows every particle array to hold `need` particles. On failure the arrays
 * keep their contents (some may be larger, which is harmless). */
int dm_particles_reserve(demill_world *w, uint32_t need)
{
    dm_particles *P = &w->p;
    if (need <= P->cap)
        return 0;
    size_t cap = dm_grown_capacity(P->cap, need);
    if (cap > UINT32_MAX)
        cap = need;
    const size_t D = (size_t)w->dim * sizeof(double), W = (size_t)dm_wdim(w) * sizeof(double),
                 Q = w->dim == 3 ? sizeof(double) : 0; /* each orientation array */
    void **const arrays[] = {(void **)&P->x,  (void **)&P->v,     (void **)&P->f,
                             (void **)&P->x0, (void **)&P->vp,    (void **)&P->wp,
                             (void **)&P->w,  (void **)&P->t,     (void **)&P->theta,
                             (void **)&P->r,  (void **)&P->m,     (void **)&P->im,
                             (void **)&P->iinv, (void **)&P->mat, (void **)&P->hid,
                             (void **)&P->q[0], (void **)&P->q[1], (void **)&P->q[2],
                             (void **)&P->q[3], (void **)&P->clump};
    const size_t sizes[] = {D, D, D, D, D, W, W, W, sizeof(double), sizeof(double),
                            sizeof(double), sizeof(double), sizeof(double), sizeof(uint16_t),
                            sizeof(uint32_t), Q, Q, Q, Q, sizeof(uint32_t)};
    if (dm_grow_arrays(arrays, sizes, sizeof sizes / sizeof sizes[0], cap))
        return -1;
    P->cap = (uint32_t)cap;
    return 0;
}

void dm_particles_free(demill_world *w)
{
    dm_particles *P = &w->p;
    free(P->x);
    free(P->v);
    free(P->f);
    free(P->x0);
    free(P->vp);
    free(P->wp);
    free(P->w);
    free(P->t);
    free(P->theta);
    for (int c = 0; c < 4; c++)
        free(P->q[c]);
    free(P->r);
    free(P->m);
    free(P->im);
    free(P->iinv);
    free(P->mat);
    free(P->hid);
    free(P->clump);
    dm_handles_free(&w->ph);
}

/* Reorders an array of n records of `size` doubles (a constant where
 * inlined, so that a record moves as that many doubles), through s. */
static inline __attribute__((always_inline)) void
permute_records(double *a, double *s, const uint32_t *order, uint32_t n, const int size)
{
    for (uint32_t k = 0; k < n; k++)
        for (int c = 0; c < size; c++)
            s[(size_t)size * k + c] = a[(size_t)size * order[k] + c];
    memcpy(a, s, (size_t)size * n * sizeof *s);
}

/* The same for records of 1, 2 or 3 doubles. */
static void permute_doubles(double *a, double *s, const uint32_t *order, uint32_t n, int size)
{
    if (size == 3)
        permute_records(a, s, order, n, 3);
    else if (size == 2)
        permute_records(a, s, order, n, 2);
    else
        permute_records(a, s, order, n, 1);
}

/* Reorders storage so that new slot k holds old slot order[k]. */
void dm_particles_permute(demill_world *w, const uint32_t *order)
{
    dm_particles *P = &w->p;
    const uint32_t n = P->n;
    const int D = w->dim, W = dm_wdim(w);
    if (n == 0) /* nothing to move, and a world that never had particles has no arrays */
        return;
    double *s = w->grid.scratch;
    double *vec[] = {P->x, P->v, P->f, P->vp};
    for (size_t a = 0; a < 4; a++)
        permute_doubles(vec[a], s, order, n, D);
    double *ang[] = {P->w, P->t, P->wp};
    for (size_t a = 0; a < 3; a++)
        permute_doubles(ang[a], s, order, n, W);
    double *sc[] = {P->theta, P->r, P->m, P->im, P->iinv, P->q[0], P->q[1], P->q[2], P->q[3]};
    for (size_t a = 0; a < (w->dim == 3 ? 9u : 5u); a++)
        permute_doubles(sc[a], s, order, n, 1);
    uint16_t *m16 = (uint16_t *)s;
    for (uint32_t k = 0; k < n; k++)
        m16[k] = P->mat[order[k]];
    memcpy(P->mat, m16, n * sizeof *m16);
    uint32_t *h32 = (uint32_t *)s;
    uint32_t *u32[] = {P->hid, P->clump};
    /* without clumps every clump slot is 0, and stays so unmoved */
    for (size_t a = 0; a < (w->live_clumps ? 2u : 1u); a++) {
        for (uint32_t k = 0; k < n; k++)
            h32[k] = u32[a][order[k]];
        memcpy(u32[a], h32, n * sizeof *h32);
    }
    for (uint32_t k = 0; k < n; k++)
        w->ph.slot[P->hid[k]] = k;
}

void dm_particle_mass(const demill_world *w, uint32_t mat, double r, double *m, double *inv_i)
{
    double rho = w->mats[mat].density, mass, inertia;
    if (w->dim == 2 && w->disc_thickness > 0) {
        mass = DM_PI * r * r * w->disc_thickness * rho;
        inertia = 0.5 * mass * r * r;
    } else {
        mass = 4.0 / 3.0 * DM_PI * r * r * r * rho;
        inertia = 0.4 * mass * r * r;
    }
    *m = mass;
    *inv_i = 1.0 / inertia;
}

/* Sets particle i's mass from its material and radius, and its inverse mass
 * and moment of inertia: 0 for a fixed particle, which no force moves. */
void dm_particle_set_mass(demill_world *w, uint32_t i, bool fixed)
{
    dm_particles *P = &w->p;
    dm_particle_mass(w, P->mat[i], P->r[i], &P->m[i], &P->iinv[i]);
    P->im[i] = 1.0 / P->m[i];
    if (fixed)
        P->im[i] = P->iinv[i] = 0.0;
}
