/* nlist.c: the neighbour build (docs/physics.md §9). Particles are sorted by cell
 * of a uniform grid, then every pair closer than the sum of radii plus the
 * skin is listed once (i < j in storage order) in the bucket of its contact
 * kernel, with the history of contacts that were already touching carried
 * over; members of one clump are never paired. Cost O(N); the lists stay
 * valid until some particle has moved half the skin (or a wall has moved so
 * far that a gap could close). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/status.h"
#include "base/threads.h"
#include "physics/broadphase/broadphase.h"
#include "physics/contact/contact.h"
#include "physics/geometry/geometry.h"

/* Makes room for n pairs in a bucket (walls: with their mesh elements). */
static int bucket_reserve(dm_bucket *b, uint32_t n, int walls)
{
    if (n <= b->cap)
        return 0;
    size_t cap = dm_grown_capacity(b->cap, n);
    void **const arrays[] = {(void **)&b->i, (void **)&b->j, (void **)&b->on, (void **)&b->hist,
                             (void **)&b->t};
    const size_t sizes[] = {sizeof(uint32_t), sizeof(uint32_t), sizeof(uint8_t),
                            (size_t)b->hs * sizeof(double), sizeof(uint32_t)};
    /* the history too where the kernel keeps none (then a byte): the kernels
     * offset its pointer by 0 for every pair, undefined on NULL */
    if (cap > UINT32_MAX || dm_grow_arrays(arrays, sizes, walls ? 5 : 4, cap))
        return -1;
    b->cap = (uint32_t)cap;
    return 0;
}

void dm_nlist_free(demill_world *w)
{
    dm_grid *g = &w->grid;
    free(g->cell_start);
    free(g->cell_of);
    free(g->order);
    free(g->inv);
    free(g->row);
    free(g->scratch);
    free(g->ci);
    free(g->cj);
    free(g->ct);
    free(g->ck);
    free(g->ch);
    for (int t = 0; t < g->npb; t++) {
        free(g->pb[t].i);
        free(g->pb[t].j);
        free(g->pb[t].t);
        free(g->pb[t].k);
        free(g->pb[t].walls);
    }
    free(g->pb);
    free(w->wg.nrm);
    free(w->wg.delta);
    free(w->wg.vw);
    free(w->wg.cp);
    free(w->wg.lost);
}

/* Sizes the per-particle scratch for n particles. */
int dm_grid_reserve(dm_grid *g, uint32_t n)
{
    if (n + 1 <= g->cap)
        return 0;
    size_t cap = dm_grown_capacity(g->cap, (size_t)n + 1);
    void **const arrays[] = {(void **)&g->cell_of, (void **)&g->order, (void **)&g->inv,
                             (void **)&g->row, (void **)&g->scratch};
    const size_t sizes[] = {sizeof(uint32_t), sizeof(uint32_t), sizeof(uint32_t),
                            sizeof(uint32_t), 3 * sizeof(double)};
    if (dm_grow_arrays(arrays, sizes, 5, cap))
        return -1;
    g->cap = (uint32_t)cap;
    return 0;
}

/* Remembers every contact that is on, in storage indices. */
static int carry_collect(demill_world *w)
{
    dm_grid *g = &w->grid;
    size_t off = 0; /* where the next history goes in g->ch */
    g->nc = 0;
    for (int side = 0; side < 2; side++) {
        const dm_clist *l = side ? &w->pw : &w->pp;
        for (int k = 0; k < w->nkern; k++) {
            const dm_bucket *b = &l->b[k];
            g->chs[k + side * DM_KERNELS] = (uint8_t)b->hs;
            for (uint32_t p = 0; p < b->n; p++) {
                if (!b->on[p])
                    continue;
                const double *h = b->hist + (size_t)b->hs * p;
                if (g->nc == g->ccap) {
                    size_t cap = dm_grown_capacity(g->ccap, (size_t)g->nc + 1);
                    void **const arrays[] = {(void **)&g->ci, (void **)&g->cj, (void **)&g->ck,
                                             (void **)&g->ch, (void **)&g->ct};
                    const size_t sizes[] = {sizeof(uint32_t), sizeof(uint32_t), sizeof(uint16_t),
                                            DM_MAX_HIST * sizeof(double), sizeof(uint32_t)};
                    if (cap > UINT32_MAX || dm_grow_arrays(arrays, sizes, 5, cap))
                        return -1;
                    g->ccap = (uint32_t)cap;
                }
                g->ci[g->nc] = b->i[p];
                g->cj[g->nc] = b->j[p];
                g->ct[g->nc] = side ? b->t[p] : 0;
                g->ck[g->nc] = (uint16_t)(k + side * DM_KERNELS);
                /* packed, so that the restore reads as few cache lines as
                 * the lists hold; a loop rather than memcpy, whose call
                 * costs more than the few doubles it moves */
                for (int c = 0; c < b->hs; c++)
                    g->ch[off + c] = h[c];
                off += (size_t)b->hs;
                g->nc++;
            }
        }
    }
    return 0;
}

/* Puts carried histories back into the new lists (a longer new layout
 * keeps the zeros of its new slots). Pairs are listed in increasing i, so a
 * row index finds (i, j) among i's few pairs; a particle-wall contact
 * matches on the mesh element too. */
static void carry_restore(demill_world *w)
{
    dm_grid *g = &w->grid;
    const uint32_t n = w->p.n;
    for (int side = 0; side < 2; side++) {
        dm_clist *l = side ? &w->pw : &w->pp;
        for (int k = 0; k < w->nkern; k++) {
            dm_bucket *b = &l->b[k];
            if (!b->n)
                continue;
            uint16_t key = (uint16_t)(k + side * DM_KERNELS);
            int have = 0;
            for (uint32_t c = 0; c < g->nc && !have; c++)
                have = g->ck[c] == key;
            if (!have)
                continue;
            double flip[DM_MAX_HIST]; /* on each slot when the pair's order flips */
            for (int d = 0; d < b->hs; d++)
                flip[d] = dm_kernel_flip(k, w->dim, d);
            const int hs = b->hs < g->chs[key] ? b->hs : g->chs[key];
            size_t off = 0;
            uint32_t p = 0;
            for (uint32_t i = 0; i <= n; i++) {
                g->row[i] = p;
                while (p < b->n && b->i[p] == i)
                    p++;
            }
            for (uint32_t c = 0; c < g->nc; off += g->chs[g->ck[c]], c++) {
                if (g->ck[c] != key)
                    continue;
                uint32_t i = g->inv[g->ci[c]], j = side ? g->cj[c] : g->inv[g->cj[c]];
                const bool swap = !side && i > j;
                if (swap) {
                    uint32_t t = i;
                    i = j;
                    j = t;
                }
                for (uint32_t q = g->row[i]; q < g->row[i + 1]; q++)
                    if (b->j[q] == j && (!side || b->t[q] == g->ct[c])) {
                        b->on[q] = 1;
                        double *h = b->hist + (size_t)b->hs * q;
                        for (int d = 0; d < hs; d++)
                            h[d] = (swap ? flip[d] : 1.0) * g->ch[off + d];
                        break;
                    }
            }
        }
    }
}

/* The forward half of the 3x3(x3) stencil as rows along x: (dy, dz), each
 * row the cells x-1..x+1, whose particles are contiguous in storage order;
 * the first is the particle's own row, from the particle itself to cell x+1. */
static const int stencil_rows[5][2] = {{0, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};

#define SCAN_BLOCK 64

/* Room for one more pair in a range's buffer (0; -1 when out of memory). */
static __attribute__((noinline)) int pairbuf_grow(dm_pairbuf *pb)
{
    size_t cap = dm_grown_capacity(pb->cap, (size_t)pb->n + 1);
    void **const arrays[] = {(void **)&pb->i, (void **)&pb->j, (void **)&pb->k, (void **)&pb->t};
    const size_t sizes[] = {sizeof(uint32_t), sizeof(uint32_t), sizeof(uint16_t),
                            sizeof(uint32_t)};
    if (cap > UINT32_MAX || dm_grow_arrays(arrays, sizes, 4, cap)) {
        pb->failed = true;
        return -1;
    }
    pb->cap = (uint32_t)cap;
    return 0;
}

/* A pair of kernel k (plus DM_KERNELS for particle-wall pairs), with its
 * mesh element t (0 but for a mesh wall). */
static inline void pairbuf_push(dm_pairbuf *pb, uint32_t i, uint32_t j, uint32_t t, int k)
{
    if (pb->n == pb->cap && pairbuf_grow(pb))
        return;
    pb->i[pb->n] = i;
    pb->j[pb->n] = j;
    pb->t[pb->n] = t;
    pb->k[pb->n++] = (uint16_t)k;
    pb->next[k]++;
}

/* Lists the pairs of particle i with particles j0..j1-1 that are within
 * reach; with clumps, not those of two members of one clump (compiled for
 * each dimension D, and twice, so that a world without clumps pays nothing
 * for the test). */
static inline __attribute__((always_inline)) void
scan_row(const demill_world *w, dm_pairbuf *pb, uint32_t i, uint32_t j0, uint32_t j1,
         const int D, const bool clumps)
{
    const dm_particles *P = &w->p;
    const double *x = P->x, *r = P->r, *xi = P->x + D * i;
    const double ri = r[i] + w->skin + w->cohesion_reach;
    const dm_pairparam *row = w->ptab + P->mat[i] * w->nmat_tab;
    const bool fixed = dm_particle_fixed(P, i);
    const uint32_t clump = clumps ? P->clump[i] : 0;
    uint32_t near[SCAN_BLOCK];
    for (uint32_t b0 = j0; b0 < j1; b0 += SCAN_BLOCK) {
        const uint32_t b1 = j1 - b0 < SCAN_BLOCK ? j1 : b0 + SCAN_BLOCK;
        uint32_t m = 0;
        for (uint32_t j = b0; j < b1; j++) {
            double r2 = 0.0;
            for (int c = 0; c < D; c++) {
                const double d = x[D * j + c] - xi[c];
                r2 += d * d;
            }
            const double reach = ri + r[j];
            near[m] = j;
            m += r2 < reach * reach;
        }
        for (uint32_t q = 0; q < m; q++) {
            const int kern = row[P->mat[near[q]]].kernel;
            /* two fixed particles do not touch, nor two members of one clump */
            if (kern >= 0 && (!fixed || !dm_particle_fixed(P, near[q])) &&
                (!clumps || !clump || P->clump[near[q]] != clump))
                pairbuf_push(pb, i, near[q], 0, kern);
        }
    }
}

/* The pairs of a cell's particles b0..b1-1 with the rows lo[q]..hi[q]-1 of
 * the stencil (its own row from the particle on). */
static inline __attribute__((always_inline)) void
scan_cell(const demill_world *w, dm_pairbuf *pb, uint32_t b0, uint32_t b1, int nr,
          const uint32_t *lo, const uint32_t *hi, const int D, const bool clumps)
{
    for (uint32_t i = b0; i < b1; i++)
        for (int q = 0; q < nr; q++)
            scan_row(w, pb, i, q ? lo[q] : i + 1, hi[q], D, clumps);
}

/* A mesh element near a particle: a candidate pair (dm_mesh_near). */
typedef struct near_args {
    dm_pairbuf *pb;
    uint32_t i, wall;
    int k;
} near_args;

static void push_element(void *ctx, uint32_t t)
{
    const near_args *a = ctx;
    pairbuf_push(a->pb, a->i, a->wall, t, a->k);
}

/* Particles adjacent in storage, so near in space, whose wall candidates
 * are looked for together. */
#define WALL_BLOCK 32

/* The walls (slots, into `walls`, in increasing order) that some particle of
 * b0..b1-1 may be a candidate of: all but those that keep clear of the
 * particles' bounding box by more than the largest reach among them (a
 * lower bound of the test each particle then makes, so that the candidates
 * are the same). */
static uint32_t block_walls(const demill_world *w, uint32_t *walls, uint32_t b0, uint32_t b1,
                            double skin)
{
    const int D = w->dim;
    const double *x = w->p.x;
    double lo[3], hi[3], rmax = 0.0, finite = 0.0;
    for (int c = 0; c < D; c++)
        lo[c] = hi[c] = x[D * b0 + c];
    for (uint32_t i = b0; i < b1; i++) {
        for (int c = 0; c < D; c++) {
            const double xc = x[D * i + c];
            lo[c] = xc < lo[c] ? xc : lo[c];
            hi[c] = xc > hi[c] ? xc : hi[c];
            finite += xc - xc; /* NaN for an infinite or NaN coordinate */
        }
        rmax = w->p.r[i] > rmax ? w->p.r[i] : rmax;
    }
    const double reach = rmax + skin;
    uint32_t nw = 0;
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (wall->kind && !(finite == 0.0 && dm_wall_box_bound(wall, lo, hi, D) >= reach))
            walls[nw++] = k;
    }
    return nw;
}

typedef struct search_args {
    int64_t nc[3];
    uint64_t ncells;
} search_args;

/* The first cell whose particles start at or after storage index p. */
static uint64_t first_cell(const uint32_t *start, uint64_t ncells, uint32_t p)
{
    uint64_t lo = 0, hi = ncells;
    while (lo < hi) {
        const uint64_t mid = lo + (hi - lo) / 2;
        if (start[mid] < p)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Range t of the search: the cells whose first particle lies in
 * [begin, end), every pair of their particles with a particle of the same or
 * a forward neighbour cell (i < j), then their particles' wall candidates.
 * Pairs come out in increasing i, so the ranges joined in order list them as
 * one range would. Compiled scalar (DM_SCALAR_LOOPS): the row scan, which
 * reads the positions with a stride of D doubles, is faster so. */
DM_SCALAR_LOOPS static void search_range(demill_world *w, void *arg, int t, uint32_t begin,
                                         uint32_t end)
{
    const search_args *a = arg;
    const int64_t *nc = a->nc;
    const uint32_t *start = w->grid.cell_start;
    dm_pairbuf *pb = &w->grid.pb[t];
    pb->n = 0;
    pb->failed = false;
    memset(pb->next, 0, sizeof pb->next);
    const int nrows = w->dim == 3 ? 5 : 2;
    const uint64_t c0 = first_cell(start, a->ncells, begin);
    uint64_t cell = c0;
    for (; cell < a->ncells && start[cell] < end; cell++) {
        const uint32_t b0 = start[cell], b1 = start[cell + 1];
        if (b0 == b1)
            continue;
        const int64_t cx = (int64_t)(cell % (uint64_t)nc[0]);
        const int64_t cy = (int64_t)(cell / (uint64_t)nc[0] % (uint64_t)nc[1]);
        const int64_t cz = (int64_t)(cell / ((uint64_t)nc[0] * (uint64_t)nc[1]));
        uint32_t lo[5], hi[5];
        int nr = 0;
        for (int q = 0; q < nrows; q++) {
            const int64_t y = cy + stencil_rows[q][0], z = cz + stencil_rows[q][1];
            if (y < 0 || y >= nc[1] || z >= nc[2])
                continue;
            const int64_t x0 = q == 0 || cx == 0 ? cx : cx - 1;
            const int64_t x1 = cx + 1 < nc[0] ? cx + 1 : cx;
            const uint64_t base = ((uint64_t)z * nc[1] + y) * nc[0];
            lo[nr] = start[base + x0];
            hi[nr++] = start[base + x1 + 1];
        }
        if (w->dim == 3 && !w->live_clumps)
            scan_cell(w, pb, b0, b1, nr, lo, hi, 3, false);
        else if (w->dim == 3)
            scan_cell(w, pb, b0, b1, nr, lo, hi, 3, true);
        else if (!w->live_clumps)
            scan_cell(w, pb, b0, b1, nr, lo, hi, 2, false);
        else
            scan_cell(w, pb, b0, b1, nr, lo, hi, 2, true);
    }

    const int D = w->dim;
    const dm_particles *P = &w->p;
    const dm_pairparam *tab = w->ptab;
    const uint32_t nm = w->nmat_tab;
    const double skin = w->skin + w->cohesion_reach;
    if (pb->wcap < w->nwalls) {
        uint32_t *walls = realloc(pb->walls, (size_t)w->nwalls * sizeof *walls);
        if (!walls) {
            pb->failed = true;
            return;
        }
        pb->walls = walls;
        pb->wcap = w->nwalls;
    }
    for (uint32_t b0 = start[c0], i1 = start[cell]; b0 < i1; b0 += WALL_BLOCK) {
        const uint32_t b1 = i1 - b0 < WALL_BLOCK ? i1 : b0 + WALL_BLOCK;
        const uint32_t nw = block_walls(w, pb->walls, b0, b1, skin);
        for (uint32_t i = b0; i < b1; i++)
            for (uint32_t q = 0; q < nw && !dm_particle_fixed(P, i); q++) {
                const uint32_t k = pb->walls[q];
                const dm_wall *wall = &w->walls[k];
                if (wall->kind == DM_WALL_MESH) { /* each element within reach */
                    const int kern = tab[P->mat[i] * nm + wall->material].kernel;
                    near_args na = {pb, i, k, kern + DM_KERNELS};
                    if (kern >= 0)
                        dm_mesh_near(wall, P->x + D * i, D, P->r[i] + skin, push_element, &na);
                    continue;
                }
                const double *x = P->x + D * i, reach = P->r[i] + skin;
                if (dm_wall_distance_bound(wall, x, D) >= reach)
                    continue;
                /* a finite wall's bounding sphere holds every particle it
                 * surrounds (in a silo, a can): of those, only the ones near its
                 * surface */
                if ((wall->kind == DM_WALL_REVOLVED || wall->kind == DM_WALL_RECT) &&
                    dm_wall_distance(wall, x, D) >= reach)
                    continue;
                const int kern = tab[P->mat[i] * nm + wall->material].kernel;
                if (kern >= 0)
                    pairbuf_push(pb, i, k, 0, kern + DM_KERNELS);
            }
    }
}

/* Range t's pairs into the buckets, at the places the counts of the ranges
 * before it leave free. */
static void place_range(demill_world *w, void *arg, int t, uint32_t begin, uint32_t end)
{
    (void)arg, (void)begin, (void)end;
    dm_pairbuf *pb = &w->grid.pb[t];
    for (uint32_t q = 0; q < pb->n; q++) {
        const int k = pb->k[q];
        dm_bucket *b = k < DM_KERNELS ? &w->pp.b[k] : &w->pw.b[k - DM_KERNELS];
        const uint32_t p = pb->next[k]++;
        b->i[p] = pb->i[q];
        b->j[p] = pb->j[q];
        if (b->t)
            b->t[p] = pb->t[q];
        b->on[p] = 0;
        for (int c = 0; c < b->hs; c++)
            b->hist[(size_t)b->hs * p + c] = 0.0;
    }
}

/* Every pair within reach, once (i < j for particle pairs), in the bucket of
 * its kernel, in increasing i, for any number of threads. */
static int pair_search(demill_world *w, const int64_t nc[3])
{
    dm_grid *g = &w->grid;
    const int want = dm_ranges(w, w->p.n);
    if (want > g->npb) {
        dm_pairbuf *pb = realloc(g->pb, (size_t)want * sizeof *pb);
        if (!pb)
            return -1;
        memset(pb + g->npb, 0, (size_t)(want - g->npb) * sizeof *pb);
        g->pb = pb;
        g->npb = want;
    }
    search_args a = {{nc[0], nc[1], nc[2]}, (uint64_t)nc[0] * nc[1] * nc[2]};
    const int ranges = dm_parallel(w, w->p.n, search_range, &a);
    for (int t = 0; t < ranges; t++)
        if (g->pb[t].failed)
            return -1;
    for (int k = 0; k < 2 * DM_KERNELS; k++) {
        dm_bucket *b = k < DM_KERNELS ? &w->pp.b[k] : &w->pw.b[k - DM_KERNELS];
        uint64_t total = 0;
        for (int t = 0; t < ranges; t++) {
            const uint32_t count = g->pb[t].next[k];
            g->pb[t].next[k] = (uint32_t)total;
            total += count;
        }
        if (total > UINT32_MAX || bucket_reserve(b, (uint32_t)total, k >= DM_KERNELS))
            return -1;
        b->n = (uint32_t)total;
    }
    dm_parallel(w, w->p.n, place_range, NULL);
    return 0;
}

demill_status dm_nlist_build(demill_world *w)
{
    const int D = w->dim;
    dm_particles *P = &w->p;
    dm_grid *g = &w->grid;
    const uint32_t n = P->n;

    if (dm_grid_reserve(g, n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory building neighbour lists");
    if (carry_collect(w))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory building neighbour lists");

    /* grid over the bounding box; cells at least as large as the largest
     * interaction distance, and not many more cells than particles */
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, rmax = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        for (int c = 0; c < D; c++) {
            double xc = P->x[D * i + c];
            if (i == 0 || xc < lo[c])
                lo[c] = xc;
            if (i == 0 || xc > hi[c])
                hi[c] = xc;
        }
        if (P->r[i] > rmax)
            rmax = P->r[i];
    }
    w->skin = w->skin_fraction * rmax;
    /* a cohesive contact that exists reaches past touching: its pairs are
     * listed that much further apart */
    w->cohesion_reach = dm_cohesion_reach(w, rmax);
    double h = 2.0 * rmax + w->skin + w->cohesion_reach;
    if (!(h > 0.0))
        h = 1.0;
    /* counted in doubles, so that particles spread over any finite distance
     * (up to the largest double, beyond which the span saturates) give a
     * grid that fits */
    double span[3] = {0, 0, 0};
    for (int c = 0; c < D; c++)
        span[c] = fmin(hi[c] - lo[c], DBL_MAX);
    for (;;) {
        double total = 1.0;
        for (int c = 0; c < D; c++)
            total *= floor(span[c] / h) + 1.0;
        if (total <= 4.0 * n + 64.0)
            break;
        h *= 1.5;
    }
    int64_t nc[3] = {1, 1, 1};
    for (int c = 0; c < D; c++)
        nc[c] = (int64_t)(span[c] / h) + 1;
    memcpy(g->lo, lo, sizeof lo);
    memcpy(g->hi, hi, sizeof hi);
    const uint64_t ncells = (uint64_t)nc[0] * nc[1] * nc[2];
    if (ncells + 1 > g->cap_cells) {
        uint32_t *cs = realloc(g->cell_start, (size_t)(ncells + 1) * sizeof *cs);
        if (!cs)
            return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory building the cell grid");
        g->cell_start = cs;
        g->cap_cells = ncells + 1;
    }

    /* counting sort by cell */
    const double inv_h = 1.0 / h;
    memset(g->cell_start, 0, (size_t)(ncells + 1) * sizeof *g->cell_start);
    for (uint32_t i = 0; i < n; i++) {
        uint64_t cell = 0, stride = 1;
        for (int c = 0; c < D; c++) {
            const double qd = (P->x[D * i + c] - lo[c]) * inv_h;
            const int64_t q = qd < (double)(nc[c] - 1) ? (int64_t)qd : nc[c] - 1;
            cell += (uint64_t)q * stride;
            stride *= (uint64_t)nc[c];
        }
        g->cell_of[i] = (uint32_t)cell;
        g->cell_start[cell + 1]++;
    }
    for (uint64_t c = 0; c < ncells; c++)
        g->cell_start[c + 1] += g->cell_start[c];
    for (uint32_t i = 0; i < n; i++)
        g->order[g->cell_start[g->cell_of[i]]++] = i;
    for (uint64_t c = ncells; c > 0; c--)
        g->cell_start[c] = g->cell_start[c - 1];
    g->cell_start[0] = 0;
    for (uint32_t k = 0; k < n; k++)
        g->inv[g->order[k]] = k;
    dm_particles_permute(w, g->order);

    /* pairs within reach, each once, into the bucket of their kernel */
    dm_clist_clear(w);
    if (pair_search(w, nc))
        goto oom;
    if (dm_wgeom_reserve(w) || dm_results_reserve(w))
        goto oom;
    carry_restore(w);
    if (n) /* a world that never had particles has no arrays */
        memcpy(P->x0, P->x, (size_t)D * n * sizeof *P->x);
    dm_walls_mark_built(w);
    w->rebuilds++;
    w->nlist_valid = true;
    return DEMILL_OK;
oom:
    dm_clist_clear(w);
    w->nlist_valid = false;
    return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory building contact lists");
}

bool dm_nlist_needs_rebuild(const demill_world *w, double max_disp2)
{
    if (!w->nlist_valid)
        return true;
    double d = sqrt(max_disp2), shift = dm_walls_max_shift(w);
    return d + (shift > d ? shift : d) > w->skin;
}
