/* overlap.c: finding whether a sphere placed somewhere would overlap a
 * particle already in the world, another sphere of a batch being placed, or
 * a wall. Used where particles are placed (demill_particles_add with
 * DEMILL_ADD_NO_OVERLAP, demill_drum_fill), not in the time step. Spheres are
 * sorted by cell of a grid as coarse as the widest possible overlap, so a
 * query looks at the 3^D cells around a point. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

static int cmp_entry(const void *a, const void *b)
{
    const dm_sphere_entry *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->index > y->index) - (x->index < y->index);
}

static uint64_t cell_key(const int64_t q[3])
{
    return ((uint64_t)(q[0] & 0x1fffff) << 42) | ((uint64_t)(q[1] & 0x1fffff) << 21) |
           (uint64_t)(q[2] & 0x1fffff);
}

/* The cell of a point. Coordinates beyond 2^62 cells are held at 2^62, which
 * loses no overlap: there the spacing of doubles is far wider than a cell,
 * so two spheres that overlap have that coordinate equal, and so their
 * cells. (Converting the unclamped quotient would overflow int64.) */
static void cell_of(const dm_sphere_index *ix, const double *x, int64_t q[3])
{
    q[0] = q[1] = q[2] = 0;
    for (int c = 0; c < ix->dim; c++)
        q[c] = (int64_t)fmax(-0x1p62, fmin(floor(x[c] / ix->h), 0x1p62));
}

/* Indexes the world's particles (indices 0 .. n-1) followed by `nextra`
 * further spheres (3 doubles per centre), for queries of spheres no larger
 * than rquery. Returns 0, or -1 when out of memory. */
int dm_spheres_build(dm_sphere_index *ix, const demill_world *w, size_t nextra,
                     const double *xextra, const double *rextra, double rquery)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    memset(ix, 0, sizeof *ix);
    ix->dim = D;
    ix->n = P->n + nextra;
    ix->x = malloc((ix->n ? ix->n : 1) * 3 * sizeof *ix->x);
    ix->r = malloc((ix->n ? ix->n : 1) * sizeof *ix->r);
    ix->e = malloc((ix->n ? ix->n : 1) * sizeof *ix->e);
    if (!ix->x || !ix->r || !ix->e) {
        dm_spheres_free(ix);
        return -1;
    }
    double rmax = rquery;
    for (size_t k = 0; k < ix->n; k++) {
        for (int c = 0; c < 3; c++)
            ix->x[3 * k + c] = k < P->n ? (c < D ? P->x[D * k + c] : 0.0) : xextra[3 * (k - P->n) + c];
        ix->r[k] = k < P->n ? P->r[k] : rextra[k - P->n];
        rmax = fmax(rmax, ix->r[k]);
    }
    ix->h = rmax + rquery > 0.0 ? rmax + rquery : 1.0;
    for (size_t k = 0; k < ix->n; k++) {
        int64_t q[3];
        cell_of(ix, ix->x + 3 * k, q);
        ix->e[k] = (dm_sphere_entry){cell_key(q), (uint32_t)k};
    }
    qsort(ix->e, ix->n, sizeof *ix->e, cmp_entry);
    return 0;
}

void dm_spheres_free(dm_sphere_index *ix)
{
    free(ix->x);
    free(ix->r);
    free(ix->e);
    memset(ix, 0, sizeof *ix);
}

/* The first indexed sphere with index below `limit` that a sphere at x of
 * radius r overlaps, with the overlap depth; -1 if none. */
int64_t dm_spheres_find(const dm_sphere_index *ix, const double *x, double r, uint32_t limit,
                        double *depth)
{
    int64_t q0[3];
    cell_of(ix, x, q0);
    const int span = ix->dim == 3 ? 1 : 0;
    for (int dz = -span; dz <= span; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                int64_t q[3] = {q0[0] + dx, q0[1] + dy, q0[2] + dz};
                const uint64_t key = cell_key(q);
                size_t lo = 0, hi = ix->n;
                while (lo < hi) {
                    size_t mid = (lo + hi) / 2;
                    if (ix->e[mid].key < key)
                        lo = mid + 1;
                    else
                        hi = mid;
                }
                for (size_t m = lo; m < ix->n && ix->e[m].key == key; m++) {
                    const uint32_t o = ix->e[m].index;
                    if (o >= limit)
                        continue;
                    double r2 = 0.0;
                    for (int c = 0; c < ix->dim; c++)
                        r2 += (x[c] - ix->x[3 * o + c]) * (x[c] - ix->x[3 * o + c]);
                    const double sum = r + ix->r[o];
                    if (r2 < sum * sum) {
                        *depth = sum - sqrt(r2);
                        return o;
                    }
                }
            }
    return -1;
}

/* The first wall a sphere at x of radius r overlaps, with the overlap depth;
 * DM_FREE if none. */
uint32_t dm_wall_overlap(const demill_world *w, const double *x, double r, double *depth)
{
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind)
            continue;
        const double d = dm_wall_distance(wall, x, w->dim);
        if (d < r) {
            *depth = r - d;
            return k;
        }
    }
    return DM_FREE;
}
