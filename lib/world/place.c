/* place.c: placing new particles in a region without overlap, for fills
 * and feeds (demill/insert.h) and fills of clumps (demill/clump.h). Random
 * sequential addition from the bottom up: each particle (or clump) in turn
 * takes the lowest free place among a set of 16 seeded random candidates
 * drawn in a window below a front that rises from the region's bottom as
 * the sets find no free place; a clump's candidate has a random orientation
 * too, and is free when every member is. The spheres already
 * there (the world's particles near the region and the new ones) are kept
 * in a hashed grid with one level per octave of radius, each level's cells
 * as wide as twice its largest diameter, so that a query finds a sphere's
 * neighbours of every size in a few cells whatever the spread of sizes; a
 * level whose cells around a query outnumber its spheres is scanned
 * instead. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

#define CANDIDATES 16 /* candidate places per set */
#define LEVELS 64
#define NONE UINT32_MAX

typedef struct cell {
    int64_t c[3];
    int32_t level;
    uint32_t head; /* NONE: an empty slot of the table */
} cell;

typedef struct grid {
    int dim;
    size_t n, cap;
    double *x, *r;       /* 3 per sphere, 1 */
    uint32_t *next;      /* the next sphere of its cell */
    uint32_t *lnext;     /* and of its level */
    cell *table;
    size_t mask;         /* table size - 1 */
    double r0;           /* level k holds radii in [r0 2^k, r0 2^(k+1)) */
    uint32_t lhead[LEVELS], lcount[LEVELS];
} grid;

static int level_of(const grid *g, double r)
{
    int e;
    frexp(r / g->r0, &e); /* r / r0 in [2^(e-1), 2^e) */
    return e < 1 ? 0 : e > LEVELS ? LEVELS - 1 : e - 1;
}

/* The cell width of level k: twice its largest diameter. */
static double cell_width(const grid *g, int k)
{
    return 4.0 * ldexp(g->r0, k + 1);
}

static int64_t cell_coord(double x, double h)
{
    return (int64_t)fmax(-0x1p62, fmin(floor(x / h), 0x1p62));
}

static size_t cell_hash(const int64_t c[3], int32_t level)
{
    uint64_t z = (uint64_t)c[0] * 0x9e3779b97f4a7c15u ^ (uint64_t)c[1] * 0xc2b2ae3d27d4eb4fu ^
                 (uint64_t)c[2] * 0x165667b19e3779f9u ^ (uint64_t)level * 0x27d4eb2f165667c5u;
    z ^= z >> 31;
    z *= 0xbf58476d1ce4e5b9u;
    return (size_t)(z ^ (z >> 29));
}

/* The table slot of a cell: its own, or the empty one where it would go. */
static cell *cell_slot(const grid *g, const int64_t c[3], int32_t level)
{
    for (size_t k = cell_hash(c, level) & g->mask;; k = (k + 1) & g->mask) {
        cell *e = &g->table[k];
        if (e->head == NONE ||
            (e->level == level && e->c[0] == c[0] && e->c[1] == c[1] && e->c[2] == c[2]))
            return e;
    }
}

/* Room for cap spheres, the smallest of radius r0. */
static int grid_init(grid *g, int dim, size_t cap, double r0)
{
    memset(g, 0, sizeof *g);
    g->dim = dim;
    g->cap = cap;
    g->r0 = r0;
    size_t size = 16;
    while (size < 2 * cap)
        size *= 2;
    g->mask = size - 1;
    g->x = malloc(3 * (cap ? cap : 1) * sizeof *g->x);
    g->r = malloc((cap ? cap : 1) * sizeof *g->r);
    g->next = malloc((cap ? cap : 1) * sizeof *g->next);
    g->lnext = malloc((cap ? cap : 1) * sizeof *g->lnext);
    g->table = malloc(size * sizeof *g->table);
    if (!g->x || !g->r || !g->next || !g->lnext || !g->table)
        return -1;
    for (size_t k = 0; k < size; k++)
        g->table[k].head = NONE;
    for (int k = 0; k < LEVELS; k++)
        g->lhead[k] = NONE;
    return 0;
}

static void grid_free(grid *g)
{
    free(g->x);
    free(g->r);
    free(g->next);
    free(g->lnext);
    free(g->table);
}

static void grid_add(grid *g, const double *x, double r)
{
    const uint32_t i = (uint32_t)g->n++;
    memcpy(g->x + 3 * i, x, 3 * sizeof *x);
    g->r[i] = r;
    const int k = level_of(g, r);
    const double h = cell_width(g, k);
    int64_t c[3] = {0, 0, 0};
    for (int d = 0; d < g->dim; d++)
        c[d] = cell_coord(x[d], h);
    cell *e = cell_slot(g, c, k);
    if (e->head == NONE) {
        memcpy(e->c, c, sizeof c);
        e->level = k;
    }
    g->next[i] = e->head;
    e->head = i;
    g->lnext[i] = g->lhead[k];
    g->lhead[k] = i;
    g->lcount[k]++;
}

static bool touches(const grid *g, const double *x, double r, uint32_t o)
{
    double d2 = 0.0;
    for (int d = 0; d < g->dim; d++)
        d2 += (x[d] - g->x[3 * o + d]) * (x[d] - g->x[3 * o + d]);
    const double s = r + g->r[o];
    return d2 < s * s;
}

/* Whether a sphere at x of radius r overlaps a sphere of the grid. */
static bool grid_overlaps(const grid *g, const double *x, double r)
{
    for (int k = 0; k < LEVELS; k++) {
        if (!g->lcount[k])
            continue;
        const double h = cell_width(g, k), reach = r + ldexp(g->r0, k + 1);
        int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
        double cells = 1.0;
        for (int d = 0; d < g->dim; d++) {
            lo[d] = cell_coord(x[d] - reach, h);
            hi[d] = cell_coord(x[d] + reach, h);
            cells *= (double)(hi[d] - lo[d]) + 1.0;
        }
        if (cells > g->lcount[k]) {
            for (uint32_t o = g->lhead[k]; o != NONE; o = g->lnext[o])
                if (touches(g, x, r, o))
                    return true;
            continue;
        }
        int64_t c[3];
        for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
            for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
                for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++)
                    for (uint32_t o = cell_slot(g, c, k)->head; o != NONE; o = g->next[o])
                        if (touches(g, x, r, o))
                            return true;
    }
    return false;
}

/* Whether a sphere at x of radius r is free: clear of every sphere of the
 * grid and of every wall. */
static bool is_free(const demill_world *w, const grid *g, const double *x, double r)
{
    double depth;
    return !grid_overlaps(g, x, r) && dm_wall_overlap(w, x, r, &depth) == DM_FREE;
}

/* A uniformly random orientation (w, x, y, z): in 3D uniform on SO(3) by
 * Shoemake (1992), "Uniform random rotations", Graphics Gems III, 124-132;
 * in 2D a turn about z by an angle uniform in [0, 2 pi). */
static void random_turn(int dim, dm_rng *rng, double q[4])
{
    if (dim == 2) {
        const double half = DM_PI * dm_rng_uniform(rng);
        q[0] = cos(half);
        q[1] = q[2] = 0.0;
        q[3] = sin(half);
        return;
    }
    const double u1 = dm_rng_uniform(rng), a = 2.0 * DM_PI * dm_rng_uniform(rng),
                 b = 2.0 * DM_PI * dm_rng_uniform(rng);
    const double s1 = sqrt(1.0 - u1), s2 = sqrt(u1);
    q[0] = s2 * cos(b);
    q[1] = s1 * sin(a);
    q[2] = s1 * cos(a);
    q[3] = s2 * sin(b);
}

/* The centres of a shape's members placed at x turned by q: 3 doubles
 * each into out. */
static void members_at(const dm_shape *sh, const double *x, const double *q, double *out)
{
    double R[9];
    dm_quat_matrix(q, R);
    for (uint32_t m = 0; m < sh->n; m++) {
        const double *b = sh->mem + DM_TMEM * (size_t)m;
        for (int a = 0; a < 3; a++)
            out[3 * m + a] = x[a] + R[3 * a] * b[0] + R[3 * a + 1] * b[1] + R[3 * a + 2] * b[2];
    }
}

double dm_shape_reach(const dm_shape *sh)
{
    double reach = 0.0;
    for (uint32_t m = 0; m < sh->n; m++) {
        const double *b = sh->mem + DM_TMEM * (size_t)m;
        reach = fmax(reach, sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) + b[3]);
    }
    return reach;
}

demill_status dm_place(demill_world *w, const dm_region *reg, size_t n, const double *radii,
                       const dm_shape *shape, uint32_t sets, dm_rng *rng, double *pos,
                       double *quat, size_t *placed)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    *placed = 0;
    if (!n)
        return DEMILL_OK;
    /* a clump's members count as spheres of the grid; rmax bounds a body */
    const size_t per = shape ? shape->n : 1;
    const double reach = shape ? dm_shape_reach(shape) : 0.0;
    double rmin = INFINITY, rmax = 0.0, lo[3], hi[3];
    for (size_t k = 0; k < (shape ? shape->n : n); k++) {
        const double r = shape ? shape->mem[DM_TMEM * k + 3] : radii[k];
        rmin = fmin(rmin, r);
        rmax = fmax(rmax, shape ? reach : r);
    }
    /* the world's particles that a new one could touch: their centres
     * within their radius and the largest new one of the region's box */
    dm_region_bounds(w, reg, lo, hi);
    uint32_t *near = malloc((P->n ? P->n : 1) * sizeof *near);
    double *mx = malloc(3 * per * sizeof *mx);
    if (!near || !mx) {
        free(near);
        free(mx);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory placing particles");
    }
    size_t nnear = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        bool in = true;
        for (int c = 0; c < D && in; c++) {
            const double x = P->x[D * i + c], m = P->r[i] + rmax;
            in = x >= lo[c] - m && x <= hi[c] + m;
        }
        if (in) {
            near[nnear++] = i;
            rmin = fmin(rmin, P->r[i]);
        }
    }
    grid g;
    if (grid_init(&g, D, nnear + n * per, rmin)) {
        grid_free(&g);
        free(near);
        free(mx);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory placing particles");
    }
    for (size_t q = 0; q < nnear; q++) {
        double x[3] = {0, 0, 0};
        memcpy(x, P->x + (size_t)D * near[q], (size_t)D * sizeof *x);
        grid_add(&g, x, P->r[near[q]]);
    }
    free(near);
    /* The bottom is where gravity points along the axis nearest to it
     * (-y without gravity). Candidates are drawn in a window below a front
     * that starts at the bottom and rises each time a set of candidates
     * finds no free place: by the height that the particle's volume at a
     * solid fraction of 1/2 takes in the region's mean cross-section,
     * doubled at each further set without a place for the same particle
     * (a clump's volume taken as its bounding sphere's). */
    int axis = 1;
    for (int c = 0; c < D; c++)
        if (fabs(w->g[c]) > fabs(w->g[axis]))
            axis = c;
    const double up = w->g[axis] > 0.0 ? -1.0 : 1.0, thick = 4.0 * rmax;
    const double height = hi[axis] - lo[axis], section = dm_region_measure(w, reg) / height;
    double front = fmin(thick, height);
    for (size_t k = 0; k < n; k++) {
        const double r = shape ? reach : radii[k];
        double rise = 2.0 * (D == 3 ? 4.0 / 3.0 * DM_PI * r * r * r : DM_PI * r * r) / section;
        bool done = false;
        for (uint32_t set = 0; set < sets && !done; set++) {
            if (set) {
                front = fmin(front + rise, height);
                rise *= 2.0;
            }
            const double a = fmax(0.0, front - 3.0 * thick);
            const double band[2] = {up > 0.0 ? lo[axis] + a : hi[axis] - front,
                                    up > 0.0 ? lo[axis] + front : hi[axis] - a};
            double cand[CANDIDATES][7]; /* the centre, and a clump's orientation */
            int nc = 0;
            for (int q = 0; q < CANDIDATES; q++) {
                double x[7] = {0};
                if (dm_region_sample(w, reg, rng, r, axis, band, x))
                    continue;
                if (shape)
                    random_turn(D, rng, x + 3);
                /* into the order of height, lowest first */
                int at = nc++;
                while (at > 0 && up * cand[at - 1][axis] > up * x[axis]) {
                    memcpy(cand[at], cand[at - 1], sizeof x);
                    at--;
                }
                memcpy(cand[at], x, sizeof x);
            }
            for (int q = 0; q < nc && !done; q++) {
                if (shape)
                    members_at(shape, cand[q], cand[q] + 3, mx);
                else
                    memcpy(mx, cand[q], 3 * sizeof *mx);
                done = true;
                for (size_t m = 0; m < per && done; m++)
                    done = is_free(w, &g, mx + 3 * m, shape ? shape->mem[DM_TMEM * m + 3] : r);
                if (!done)
                    continue;
                memcpy(pos + 3 * k, cand[q], 3 * sizeof *pos);
                if (shape)
                    memcpy(quat + 4 * k, cand[q] + 3, 4 * sizeof *quat);
                for (size_t m = 0; m < per; m++)
                    grid_add(&g, mx + 3 * m, shape ? shape->mem[DM_TMEM * m + 3] : r);
            }
        }
        if (!done)
            break;
        *placed = k + 1;
    }
    grid_free(&g);
    free(mx);
    return DEMILL_OK;
}
