/* mesh.c: triangle-mesh walls (3D) and polyline walls (2D) (docs/geometry.md,
 * Triangle meshes and polylines): the mesh's data (normals, edges, the
 * elements incident to each edge and vertex, an AABB tree), its closest-point
 * tests with the contact rule that gives one contact per local minimum of the
 * distance, and the geometry pass over a particle range's mesh candidates,
 * which also carries a contact's history from element to element.
 *
 * A mesh is a thin surface touched from both sides. Its geometry is kept in
 * its own frame, placed in the wall's reference frame by frame_rot and
 * frame_off, which the wall's rigid pose then moves (geometry/walls.c): a
 * particle's centre is mapped back into the mesh's frame, where the tests
 * run, and the normal found is turned forward. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/geometry/geometry.h"

/* Regions of the closest point on an element: its interior (a face, or a
 * segment's inside), vertex k, or (triangles) edge k, from vertex k to k + 1. */
enum { REGION_FACE = 0, REGION_VERTEX = 1, REGION_EDGE = 4 };

#define BVH_LEAF 4     /* elements per leaf, at most */
#define BVH_STACK 128  /* deeper than a median-split tree of 2^32 elements */
#define FAR_CUBES 32768 /* cubes of the distance-bound grid, about */
#define FAR_FIELDS 11   /* the arrays in a mesh's block (fields()) */

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static const double *vert(const dm_trimesh *m, uint32_t k)
{
    return m->v + 3 * (size_t)k;
}

/* (x - v) · (u - v) for vertices v and u: computed the same way by every
 * element that has the edge (v, u), so that they agree on ties. */
static double vertex_dot(const dm_trimesh *m, uint32_t v, uint32_t u, const double *x)
{
    const double *a = vert(m, v), *b = vert(m, u);
    return (x[0] - a[0]) * (b[0] - a[0]) + (x[1] - a[1]) * (b[1] - a[1]) +
           (x[2] - a[2]) * (b[2] - a[2]);
}

/* Whether x lies outside edge k of triangle t, in the triangle's plane:
 * ((v_hi - v_lo) × (x - v_lo)) · n_t, with lo and hi the edge's vertices in
 * index order, so that two triangles with the same normal that share the edge
 * in opposite directions compute the same number and see it from opposite
 * sides; zero counts as outside for both. */
static int outside_edge(const dm_trimesh *m, uint32_t t, int k, const double *x)
{
    const uint32_t a = m->el[3 * t + k], b = m->el[3 * t + (k + 1) % 3];
    const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    const double *p = vert(m, lo), *q = vert(m, hi), *n = m->nrm + 3 * t;
    const double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double r[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const double g[3] = {e[1] * r[2] - e[2] * r[1], e[2] * r[0] - e[0] * r[2],
                         e[0] * r[1] - e[1] * r[0]};
    const double s = dot3(g, n);
    return (a == lo ? s : -s) <= 0.0;
}

/* The signed distance from x to element t's plane (its line in 2D), a lower
 * bound of the distance to the element. */
static double plane_distance(const dm_trimesh *m, uint32_t t, const double *x)
{
    const double *a = vert(m, m->el[(size_t)m->nel * t]), *nt = m->nrm + 3 * (size_t)t;
    return (x[0] - a[0]) * nt[0] + (x[1] - a[1]) * nt[1] + (x[2] - a[2]) * nt[2];
}

/* The region of element t that holds the closest point to x: Ericson (2005),
 * Real-Time Collision Detection, §5.1.5 (triangles) and §5.1.2 (segments),
 * the vertices' regions first, then the edges', then the interior; each test
 * written on quantities its neighbours across an edge or vertex compute
 * identically (vertex_dot, outside_edge). */
static int element_region(const dm_trimesh *m, uint32_t t, const double *x)
{
    const uint32_t *e = m->el + (size_t)m->nel * t;
    if (m->nel == 2) {
        if (vertex_dot(m, e[0], e[1], x) <= 0.0)
            return REGION_VERTEX;
        if (vertex_dot(m, e[1], e[0], x) <= 0.0)
            return REGION_VERTEX + 1;
        return REGION_FACE;
    }
    double fwd[3], back[3]; /* at vertex k: along edge k, and back along edge k - 1 */
    for (int k = 0; k < 3; k++) {
        fwd[k] = vertex_dot(m, e[k], e[(k + 1) % 3], x);
        back[k] = vertex_dot(m, e[k], e[(k + 2) % 3], x);
        if (fwd[k] <= 0.0 && back[k] <= 0.0)
            return REGION_VERTEX + k;
    }
    for (int k = 0; k < 3; k++)
        if (fwd[k] > 0.0 && back[(k + 1) % 3] > 0.0 && outside_edge(m, t, k, x))
            return REGION_EDGE + k;
    return REGION_FACE;
}

/* Unsigned distance from x to element t and the unit normal from x towards
 * its closest point; returns the region. */
static int element_closest(const dm_trimesh *m, uint32_t t, const double *x, double *dist,
                           double *n)
{
    const int region = element_region(m, t, x);
    const uint32_t *e = m->el + (size_t)m->nel * t;
    const double *nt = m->nrm + 3 * t;
    if (region == REGION_FACE) {
        const double d = plane_distance(m, t, x);
        for (int c = 0; c < 3; c++)
            n[c] = d >= 0.0 ? -nt[c] : nt[c];
        *dist = fabs(d);
        return region;
    }
    double c[3];
    if (region >= REGION_EDGE) {
        const int k = region - REGION_EDGE;
        const uint32_t a = e[k], b = e[(k + 1) % 3];
        const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
        const double *p = vert(m, lo), *q = vert(m, hi);
        const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double s = vertex_dot(m, lo, hi, x) / dot3(u, u);
        for (int d = 0; d < 3; d++)
            c[d] = p[d] + s * u[d];
    } else {
        memcpy(c, vert(m, e[region - REGION_VERTEX]), sizeof c);
    }
    const double d[3] = {c[0] - x[0], c[1] - x[1], c[2] - x[2]};
    const double len = sqrt(dot3(d, d));
    *dist = len;
    for (int q = 0; q < 3; q++) /* the centre on the element: its normal will do */
        n[q] = len > 0.0 ? d[q] / len : -nt[q];
    return region;
}

/* The element's vertex or edge of a region, as a vertex or edge index. */
static uint32_t feature_of(const dm_trimesh *m, uint32_t t, int region)
{
    if (region >= REGION_EDGE && m->nel == 3)
        return m->el_edge[3 * t + region - REGION_EDGE];
    return m->el[(size_t)m->nel * t + region - REGION_VERTEX];
}

/* The contact rule: the closest point of element t to x is a contact if it
 * lies inside t, or on an edge (vertex) that t owns (the lowest-index element
 * incident to it) and every element incident to that edge (vertex) has its
 * own closest point there, so that each local minimum of the distance from x
 * to the mesh is one contact. Returns whether it is, with the distance and
 * the normal as element_closest(). */
static int element_contact(const dm_trimesh *m, uint32_t t, const double *x, double *dist,
                           double *n)
{
    const int region = element_closest(m, t, x, dist, n);
    if (region == REGION_FACE)
        return 1;
    const int edge = region >= REGION_EDGE && m->nel == 3;
    const uint32_t f = feature_of(m, t, region);
    const uint32_t *start = edge ? m->edge_start : m->vert_start;
    const uint32_t *inc = edge ? m->edge_el : m->vert_el;
    if (inc[start[f]] != t)
        return 0;
    for (uint32_t q = start[f] + 1; q < start[f + 1]; q++) {
        const int r = element_region(m, inc[q], x);
        if (r == REGION_FACE || (r >= REGION_EDGE) != edge || feature_of(m, inc[q], r) != f)
            return 0;
    }
    return 1;
}

/* ---- building ----------------------------------------------------------------- */

/* The element's normal, unit (triangles: (b - a) × (c - a); segments:
 * (e_y, -e_x) of e = b - a); returns the relative size of the unnormalised
 * normal, |(b - a) × (c - a)| / (|b - a|² + |c - a|²) (segments: 1), 0 for a
 * degenerate element. */
static double element_normal(int nel, const double *v, const uint32_t *el, size_t t, double *n)
{
    const double *a = v + 3 * (size_t)el[nel * t], *b = v + 3 * (size_t)el[nel * t + 1];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double g[3], scale;
    if (nel == 2) {
        g[0] = u[1];
        g[1] = -u[0];
        g[2] = 0.0;
        scale = 1.0;
    } else {
        const double *c = v + 3 * (size_t)el[nel * t + 2];
        const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        g[0] = u[1] * w[2] - u[2] * w[1];
        g[1] = u[2] * w[0] - u[0] * w[2];
        g[2] = u[0] * w[1] - u[1] * w[0];
        scale = dot3(u, u) + dot3(w, w);
    }
    const double len = sqrt(dot3(g, g));
    for (int c = 0; c < 3; c++)
        n[c] = len > 0.0 ? g[c] / len : 0.0;
    const double rel = nel == 2 ? (len > 0.0) : len / scale;
    return isfinite(rel) ? rel : 0.0;
}

int dm_trimesh_degenerate(int nel, const double *v, const uint32_t *el, size_t t)
{
    double n[3];
    /* a triangle whose area is round-off of its sides' lengths has no normal */
    return element_normal(nel, v, el, t, n) <= 64.0 * DBL_EPSILON;
}

/* Pointer field k of a mesh (of 10, in its one block), and its element size. */
static void **fields(dm_trimesh *m, size_t *size, int k)
{
    void **const f[] = {(void **)&m->v,          (void **)&m->el,         (void **)&m->nrm,
                        (void **)&m->el_edge,    (void **)&m->edge_start, (void **)&m->edge_el,
                        (void **)&m->vert_start, (void **)&m->vert_el,    (void **)&m->node,
                        (void **)&m->order,      (void **)&m->far};
    const size_t s[] = {sizeof(double),   sizeof(uint32_t), sizeof(double),   sizeof(uint32_t),
                        sizeof(uint32_t), sizeof(uint32_t), sizeof(uint32_t), sizeof(uint32_t),
                        sizeof(dm_bvh_node), sizeof(uint32_t), sizeof(float)};
    *size = s[k];
    return f[k];
}

static size_t round8(size_t n)
{
    return (n + 7) / 8 * 8;
}

typedef struct edge_key {
    uint32_t lo, hi, t;
} edge_key;

static int edge_cmp(const void *pa, const void *pb)
{
    const edge_key *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

/* Elements order[lo .. hi - 1] with their boxes' centres along axis ax
 * split so that those before mid are not above those after (quickselect,
 * ties by element index, so that the tree does not depend on the library
 * qsort uses). */
static double centre_of(const dm_trimesh *m, uint32_t t, int ax)
{
    const uint32_t *e = m->el + (size_t)m->nel * t;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < m->nel; k++) {
        lo = fmin(lo, m->v[3 * (size_t)e[k] + ax]);
        hi = fmax(hi, m->v[3 * (size_t)e[k] + ax]);
    }
    return 0.5 * (lo + hi);
}

static int before(const dm_trimesh *m, uint32_t a, uint32_t b, int ax)
{
    const double ca = centre_of(m, a, ax), cb = centre_of(m, b, ax);
    return ca < cb || (ca == cb && a < b);
}

static void select_mid(const dm_trimesh *m, uint32_t *o, uint32_t lo, uint32_t hi, uint32_t mid,
                       int ax)
{
    while (hi - lo > 1) {
        const uint32_t pivot = o[lo + (hi - lo - 1) / 2]; /* not the last: j < hi - 1 */
        uint32_t i = lo, j = hi - 1;
        for (;;) { /* Hoare's partition around the pivot */
            while (before(m, o[i], pivot, ax))
                i++;
            while (before(m, pivot, o[j], ax))
                j--;
            if (i >= j)
                break;
            const uint32_t s = o[i];
            o[i] = o[j];
            o[j] = s;
            i++;
            j--;
        }
        if (mid <= j)
            hi = j + 1;
        else
            lo = j + 1;
    }
}

static void element_box(const dm_trimesh *m, uint32_t t, double *lo, double *hi)
{
    const uint32_t *e = m->el + (size_t)m->nel * t;
    for (int k = 0; k < m->nel; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], m->v[3 * (size_t)e[k] + c]);
            hi[c] = fmax(hi[c], m->v[3 * (size_t)e[k] + c]);
        }
}

/* The AABB tree over the elements, top down by median split along the
 * longest axis of the node's box (Ericson 2005, §6.2). */
static void bvh_build(dm_trimesh *m)
{
    typedef struct job {
        uint32_t node, lo, hi;
    } job;
    job stack[BVH_STACK];
    int top = 0;
    m->nnodes = 1;
    stack[top++] = (job){0, 0, m->nt};
    while (top) {
        const job j = stack[--top];
        dm_bvh_node *nd = &m->node[j.node];
        for (int c = 0; c < 3; c++) {
            nd->lo[c] = HUGE_VAL;
            nd->hi[c] = -HUGE_VAL;
        }
        for (uint32_t q = j.lo; q < j.hi; q++)
            element_box(m, m->order[q], nd->lo, nd->hi);
        if (j.hi - j.lo <= BVH_LEAF) {
            nd->first = j.lo;
            nd->count = j.hi - j.lo;
            continue;
        }
        int ax = 0;
        for (int c = 1; c < 3; c++)
            if (nd->hi[c] - nd->lo[c] > nd->hi[ax] - nd->lo[ax])
                ax = c;
        const uint32_t mid = j.lo + (j.hi - j.lo) / 2;
        select_mid(m, m->order, j.lo, j.hi, mid, ax);
        nd->first = m->nnodes;
        nd->count = 0;
        m->nnodes += 2;
        stack[top++] = (job){nd->first + 1, mid, j.hi};
        stack[top++] = (job){nd->first, j.lo, mid};
    }
}

/* The edges of the triangles and the triangles incident to each (CSR);
 * scratch: 3 nt keys. */
static void build_edges(dm_trimesh *m, edge_key *key)
{
    const size_t n3 = 3 * (size_t)m->nt;
    for (size_t q = 0; q < n3; q++) {
        const uint32_t t = (uint32_t)(q / 3), k = (uint32_t)(q % 3);
        const uint32_t a = m->el[3 * t + k], b = m->el[3 * t + (k + 1) % 3];
        key[q] = (edge_key){a < b ? a : b, a < b ? b : a, t};
    }
    qsort(key, n3, sizeof *key, edge_cmp);
    m->ne = 0;
    for (size_t q = 0; q < n3; q++) {
        if (!q || key[q].lo != key[q - 1].lo || key[q].hi != key[q - 1].hi)
            m->edge_start[m->ne++] = (uint32_t)q;
        m->edge_el[q] = key[q].t;
        const uint32_t t = key[q].t;
        for (int k = 0; k < 3; k++) {
            const uint32_t a = m->el[3 * t + k], b = m->el[3 * t + (k + 1) % 3];
            if ((a < b ? a : b) == key[q].lo && (a < b ? b : a) == key[q].hi)
                m->el_edge[3 * t + k] = m->ne - 1;
        }
    }
    m->edge_start[m->ne] = (uint32_t)n3;
}

static double trimesh_nearest(const dm_trimesh *m, const double *x, double *n);

/* The distance-bound grid over the box lo .. hi of the vertices, widened by a
 * twentieth of its largest side (a flat mesh's box has no thickness): about
 * FAR_CUBES cubes, one layer across the plane of a polyline. Returns the
 * number of cubes. */
static size_t far_grid(dm_trimesh *g, int nel, const double *lo, const double *hi)
{
    const int axes = nel == 3 ? 3 : 2;
    double side[3], span = 0.0;
    for (int c = 0; c < 3; c++)
        span = fmax(span, hi[c] - lo[c]);
    double volume = 1.0;
    for (int c = 0; c < axes; c++) {
        side[c] = hi[c] - lo[c] + 0.1 * span;
        volume *= side[c];
    }
    g->far_h = pow(volume / FAR_CUBES, 1.0 / axes);
    size_t cubes = 1;
    for (int c = 0; c < 3; c++) {
        const double wide = c < axes ? side[c] : 0.0;
        g->far_n[c] = c < axes ? (uint32_t)fmax(1.0, ceil(wide / g->far_h)) : 1;
        g->far_lo[c] = 0.5 * (lo[c] + hi[c]) - 0.5 * g->far_n[c] * g->far_h;
        cubes *= g->far_n[c];
    }
    return cubes;
}

/* Each cube's bound: the distance from its centre to the mesh less its half
 * diagonal (triangle inequality), rounded down to a float. */
static void far_fill(dm_trimesh *m)
{
    const double h = m->far_h, half = 0.5 * sqrt(3.0) * h;
    size_t q = 0;
    for (uint32_t z = 0; z < m->far_n[2]; z++)
        for (uint32_t y = 0; y < m->far_n[1]; y++)
            for (uint32_t x = 0; x < m->far_n[0]; x++, q++) {
                const double c[3] = {m->far_lo[0] + (x + 0.5) * h, m->far_lo[1] + (y + 0.5) * h,
                                     m->far_lo[2] + (z + 0.5) * h};
                double n[3];
                const double bound = fmax(0.0, trimesh_nearest(m, c, n) - half);
                float f = (float)bound;
                m->far[q] = (double)f > bound ? nextafterf(f, 0.0f) : f;
            }
}

/* Whether the grid shows x (in the mesh's frame) farther than reach from
 * every element. */
static int far_from_mesh(const dm_trimesh *m, const double *x, double reach)
{
    size_t q = 0;
    for (int c = 2; c >= 0; c--) {
        const double u = (x[c] - m->far_lo[c]) / m->far_h;
        if (!(u >= 0.0 && u < m->far_n[c]))
            return 0;
        q = q * m->far_n[c] + (size_t)u;
    }
    return m->far[q] >= reach;
}

dm_trimesh *dm_trimesh_build(int nel, uint32_t nv, const double *v, uint32_t nt,
                             const uint32_t *el)
{
    const size_t n3 = (size_t)nel * nt, tri = nel == 3 ? 3 * (size_t)nt : 0;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t k = 0; k < nv; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], v[3 * (size_t)k + c]);
            hi[c] = fmax(hi[c], v[3 * (size_t)k + c]);
        }
    dm_trimesh grid;
    const size_t cubes = far_grid(&grid, nel, lo, hi);
    const size_t count[] = {3 * (size_t)nv, n3,  3 * (size_t)nt,      tri,
                            tri + 1,        tri, (size_t)nv + 1,      n3,
                            2 * (size_t)nt, nt,  cubes};
    size_t bytes = round8(sizeof(dm_trimesh)), size;
    for (int k = 0; k < FAR_FIELDS; k++) {
        dm_trimesh probe;
        fields(&probe, &size, k);
        bytes += round8(count[k] * size);
    }
    dm_trimesh *m = calloc(1, bytes);
    edge_key *key = tri ? malloc(tri * sizeof *key) : NULL;
    if (!m || (tri && !key)) {
        free(m);
        free(key);
        return NULL;
    }
    m->bytes = bytes;
    char *at = (char *)m + round8(sizeof *m);
    for (int k = 0; k < FAR_FIELDS; k++) {
        void **f = fields(m, &size, k);
        *f = at;
        at += round8(count[k] * size);
    }
    m->nel = nel;
    m->nv = nv;
    m->nt = nt;
    memcpy(m->v, v, 3 * (size_t)nv * sizeof *v);
    memcpy(m->el, el, n3 * sizeof *el);
    for (uint32_t t = 0; t < nt; t++) {
        element_normal(nel, v, el, t, m->nrm + 3 * (size_t)t);
        m->order[t] = t;
    }
    if (tri)
        build_edges(m, key);
    free(key);
    for (size_t q = 0; q < n3; q++)
        m->vert_start[el[q] + 1]++;
    for (uint32_t k = 0; k < nv; k++)
        m->vert_start[k + 1] += m->vert_start[k];
    for (size_t q = 0; q < n3; q++) /* in increasing element order; vert_start shifts by one */
        m->vert_el[m->vert_start[el[q]]++] = (uint32_t)(q / (size_t)nel);
    for (uint32_t k = nv; k > 0; k--)
        m->vert_start[k] = m->vert_start[k - 1];
    m->vert_start[0] = 0;
    bvh_build(m);
    memcpy(m->far_n, grid.far_n, sizeof grid.far_n);
    memcpy(m->far_lo, grid.far_lo, sizeof grid.far_lo);
    m->far_h = grid.far_h;
    far_fill(m);
    double r2 = 0.0;
    for (int c = 0; c < 3; c++) {
        m->bs_centre[c] = 0.5 * (lo[c] + hi[c]);
        r2 += 0.25 * (hi[c] - lo[c]) * (hi[c] - lo[c]);
    }
    m->bs_radius = sqrt(r2);
    m->frame_rot[0] = m->frame_rot[4] = m->frame_rot[8] = 1.0;
    return m;
}

dm_trimesh *dm_trimesh_copy(const dm_trimesh *src)
{
    dm_trimesh *m = malloc(src->bytes);
    if (!m)
        return NULL;
    memcpy(m, src, src->bytes);
    size_t size;
    for (int k = 0; k < FAR_FIELDS; k++) {
        void **f = fields(m, &size, k);
        *f = (char *)m + ((const char *)*f - (const char *)src);
    }
    return m;
}

void dm_trimesh_free(dm_trimesh *m)
{
    free(m);
}

void dm_walls_free_owned(demill_world *w)
{
    for (uint32_t k = 0; k < w->nwalls; k++) {
        dm_trimesh_free(w->walls[k].mesh);
        w->walls[k].mesh = NULL;
        dm_loads_free(w->walls[k].loads);
        w->walls[k].loads = NULL;
    }
}

/* ---- queries ------------------------------------------------------------------ */


/* The squared distance from x to a node's box. */
static double box_dist2(const dm_bvh_node *nd, const double *x)
{
    double s = 0.0;
    for (int c = 0; c < 3; c++) {
        const double below = nd->lo[c] - x[c], above = x[c] - nd->hi[c];
        const double d = below > 0.0 ? below : above > 0.0 ? above : 0.0; /* (no libm call) */
        s += d * d;
    }
    return s;
}

void dm_trimesh_near(const dm_trimesh *m, const double *x, double reach, dm_near_fn fn,
                     void *ctx)
{
    if (far_from_mesh(m, x, reach))
        return;
    uint32_t stack[BVH_STACK];
    int top = 0;
    stack[top++] = 0;
    const double r2 = reach * reach;
    while (top) {
        const dm_bvh_node *nd = &m->node[stack[--top]];
        if (!(box_dist2(nd, x) < r2))
            continue;
        if (!nd->count) {
            stack[top++] = nd->first + 1;
            stack[top++] = nd->first;
            continue;
        }
        for (uint32_t q = nd->first; q < nd->first + nd->count; q++) {
            const uint32_t t = m->order[q];
            double d, n[3];
            if (!(fabs(plane_distance(m, t, x)) < reach))
                continue; /* no nearer than its plane */
            element_closest(m, t, x, &d, n);
            if (d < reach)
                fn(ctx, t);
        }
    }
}

/* The nearest point of the mesh to x: its unsigned distance and the unit
 * normal towards it (branch and bound over the tree). */
static double trimesh_nearest(const dm_trimesh *m, const double *x, double *n)
{
    uint32_t stack[BVH_STACK];
    int top = 0;
    double best = HUGE_VAL;
    stack[top++] = 0;
    while (top) {
        const dm_bvh_node *nd = &m->node[stack[--top]];
        if (!(box_dist2(nd, x) < best * best))
            continue;
        if (!nd->count) {
            stack[top++] = nd->first + 1;
            stack[top++] = nd->first;
            continue;
        }
        for (uint32_t q = nd->first; q < nd->first + nd->count; q++) {
            double d, nq[3];
            element_closest(m, m->order[q], x, &d, nq);
            if (d < best) {
                best = d;
                memcpy(n, nq, sizeof nq);
            }
        }
    }
    return best;
}

/* ---- the mesh in the world ------------------------------------------------------- */

/* x (D components) in the mesh's frame: V = B^T (c0 + rot^T (x - c) - b). */
static void to_mesh(const dm_wall *wall, const double *x, int D, double *V)
{
    const dm_trimesh *m = wall->mesh;
    const double *R = wall->rot, *B = m->frame_rot;
    double d[3] = {0.0, 0.0, 0.0}, X[3];
    for (int c = 0; c < D; c++)
        d[c] = x[c] - wall->c[c];
    for (int r = 0; r < 3; r++)
        X[r] = wall->c0[r] + (R[r] * d[0] + R[3 + r] * d[1] + R[6 + r] * d[2]) - m->frame_off[r];
    for (int r = 0; r < 3; r++)
        V[r] = B[r] * X[0] + B[3 + r] * X[1] + B[6 + r] * X[2];
}

/* A direction of the mesh's frame in the world: rot B n. */
static void to_world(const dm_wall *wall, const double *n, double *out)
{
    const double *R = wall->rot, *B = wall->mesh->frame_rot;
    double u[3];
    for (int r = 0; r < 3; r++)
        u[r] = B[3 * r] * n[0] + B[3 * r + 1] * n[1] + B[3 * r + 2] * n[2];
    for (int r = 0; r < 3; r++)
        out[r] = R[3 * r] * u[0] + R[3 * r + 1] * u[1] + R[3 * r + 2] * u[2];
}

double dm_mesh_closest(const dm_wall *wall, const double *x, int dim, double *normal)
{
    double V[3], n[3];
    to_mesh(wall, x, dim, V);
    const double d = trimesh_nearest(wall->mesh, V, n);
    to_world(wall, n, normal);
    return d;
}

void dm_mesh_near(const dm_wall *wall, const double *x, int dim, double reach, dm_near_fn fn,
                  void *ctx)
{
    double V[3];
    to_mesh(wall, x, dim, V);
    dm_trimesh_near(wall->mesh, V, reach, fn, ctx);
}

void dm_mesh_vertex_at(const dm_wall *wall, uint32_t k, double *out)
{
    const dm_trimesh *m = wall->mesh;
    const double *B = m->frame_rot, *v = vert(m, k);
    double d[3];
    for (int r = 0; r < 3; r++)
        d[r] = B[3 * r] * v[0] + B[3 * r + 1] * v[1] + B[3 * r + 2] * v[2] + m->frame_off[r] -
               wall->c0[r];
    for (int r = 0; r < 3; r++)
        out[r] = wall->c[r] + wall->rot[3 * r] * d[0] + wall->rot[3 * r + 1] * d[1] +
                 wall->rot[3 * r + 2] * d[2];
}

double dm_mesh_reach(const dm_wall *wall)
{
    const dm_trimesh *m = wall->mesh;
    const double *B = m->frame_rot, *s = m->bs_centre;
    double d2 = 0.0;
    for (int r = 0; r < 3; r++) {
        const double d = B[3 * r] * s[0] + B[3 * r + 1] * s[1] + B[3 * r + 2] * s[2] +
                         m->frame_off[r] - wall->c0[r];
        d2 += d * d;
    }
    return sqrt(d2) + m->bs_radius;
}

/* Before the wall's current pose becomes its reference (dm_wall_rebase): the
 * mesh's frame follows, B := rot B, b := c + rot (b - c0). */
void dm_mesh_rebase(dm_wall *wall)
{
    dm_trimesh *m = wall->mesh;
    const double *R = wall->rot;
    double B[9], b[3], d[3];
    for (int r = 0; r < 3; r++) {
        d[r] = m->frame_off[r] - wall->c0[r];
        for (int c = 0; c < 3; c++)
            B[3 * r + c] = R[3 * r] * m->frame_rot[c] + R[3 * r + 1] * m->frame_rot[3 + c] +
                           R[3 * r + 2] * m->frame_rot[6 + c];
    }
    for (int r = 0; r < 3; r++)
        b[r] = wall->c[r] + R[3 * r] * d[0] + R[3 * r + 1] * d[1] + R[3 * r + 2] * d[2];
    memcpy(m->frame_rot, B, sizeof B);
    memcpy(m->frame_off, b, sizeof b);
}

void dm_mesh_into_drum(dm_wall *wall, double theta, const double centre[3])
{
    dm_trimesh *m = wall->mesh; /* X = B V + b in the world */
    const double c = cos(theta), s = sin(theta);
    double B[9], b[3], o[3];
    for (int col = 0; col < 3; col++) { /* B := R(theta)^T B */
        const double *F = m->frame_rot;
        B[col] = c * F[col] + s * F[3 + col];
        B[3 + col] = -s * F[col] + c * F[3 + col];
        B[6 + col] = F[6 + col];
    }
    for (int k = 0; k < 3; k++) /* b := R(theta)^T (b - centre) */
        o[k] = m->frame_off[k] - centre[k];
    b[0] = c * o[0] + s * o[1];
    b[1] = -s * o[0] + c * o[1];
    b[2] = o[2];
    memcpy(m->frame_rot, B, sizeof B);
    memcpy(m->frame_off, b, sizeof b);
}

/* Vertex k of a mesh attached to the drum in the drum's frame: B V + b. */
static void drum_frame_vertex(const dm_wall *wall, uint32_t k, double *out)
{
    const dm_trimesh *m = wall->mesh;
    const double *B = m->frame_rot, *v = vert(m, k);
    for (int r = 0; r < 3; r++)
        out[r] = B[3 * r] * v[0] + B[3 * r + 1] * v[1] + B[3 * r + 2] * v[2] + m->frame_off[r];
}

double dm_mesh_axis_distance(const dm_wall *wall, int far)
{
    double best = far ? 0.0 : HUGE_VAL, x[3];
    for (uint32_t k = 0; k < wall->mesh->nv; k++) {
        drum_frame_vertex(wall, k, x);
        const double r = hypot(x[0], x[1]);
        best = far ? fmax(best, r) : fmin(best, r);
    }
    return best;
}

double dm_mesh_widest_angle(const dm_wall *wall)
{
    const dm_trimesh *m = wall->mesh;
    double widest = 0.0;
    for (uint32_t t = 0; t < m->nt; t++) {
        double phi[3], x[3];
        for (int k = 0; k < m->nel; k++) {
            drum_frame_vertex(wall, m->el[(size_t)m->nel * t + k], x);
            phi[k] = atan2(x[1], x[0]);
        }
        for (int a = 0; a < m->nel; a++)
            for (int b = a + 1; b < m->nel; b++)
                widest = fmax(widest, fabs(remainder(phi[a] - phi[b], 2.0 * DM_PI)));
    }
    return widest;
}

/* ---- the geometry pass ----------------------------------------------------------- */

int dm_walls_have_mesh(const demill_world *w)
{
    for (uint32_t k = 0; k < w->nwalls; k++)
        if (w->walls[k].kind == DM_WALL_MESH)
            return 1;
    return 0;
}

/* The distance from particle i's centre to candidate p's element. */
static double candidate_distance(const demill_world *w, const dm_bucket *b, uint32_t p)
{
    const dm_wall *wall = &w->walls[b->j[p]];
    double V[3], d, n[3];
    to_mesh(wall, w->p.x + w->dim * b->i[p], w->dim, V);
    element_closest(wall->mesh, b->t[p], V, &d, n);
    return d;
}

/* Candidates p0 .. p1 - 1 of a bucket are particle i's with one mesh: a
 * contact that starts (valid, off) takes the history of one that ends while
 * still overlapping (on, no longer valid), the nearest to the centre if
 * several, the first in the list on a tie: the contact has moved on to
 * another element. */
static void carry_group(demill_world *w, dm_bucket *b, uint32_t g0, uint32_t p0, uint32_t p1)
{
    const dm_wgeom *g = &w->wg;
    const double r = w->p.r[b->i[p0]];
    for (uint32_t p = p0; p < p1; p++) {
        if (!(g->delta[g0 + p] > 0.0) || b->on[p])
            continue;
        uint32_t from = p1;
        double best = r;
        for (uint32_t q = p0; q < p1; q++) {
            if (!b->on[q] || g->delta[g0 + q] > 0.0)
                continue;
            const double d = candidate_distance(w, b, q);
            if (d < best) {
                best = d;
                from = q;
            }
        }
        if (from == p1)
            continue;
        const size_t hs = (size_t)b->hs;
        memcpy(b->hist + hs * p, b->hist + hs * from, hs * sizeof *b->hist);
        memset(b->hist + hs * from, 0, hs * sizeof *b->hist);
        b->on[p] = 1;
        b->on[from] = 0;
    }
}

void dm_wgeom_meshes(demill_world *w, uint32_t begin, uint32_t end, int carry)
{
    const int D = w->dim;
    uint32_t g0 = 0;
    for (int k = 0; k < w->nkern; g0 += w->pw.b[k].n, k++) {
        dm_bucket *b = &w->pw.b[k];
        uint32_t p = 0, hi = b->n; /* the first candidate of particle begin */
        while (p < hi) {
            const uint32_t mid = p + (hi - p) / 2;
            if (b->i[mid] < begin)
                p = mid + 1;
            else
                hi = mid;
        }
        while (p < b->n && b->i[p] < end) {
            const uint32_t i = b->i[p], j = b->j[p], p0 = p;
            const dm_wall *wall = &w->walls[j];
            const double r = w->p.r[i];
            double V[3];
            if (wall->kind == DM_WALL_MESH)
                to_mesh(wall, w->p.x + D * i, D, V);
            for (; p < b->n && b->i[p] == i && b->j[p] == j; p++) {
                if (wall->kind != DM_WALL_MESH)
                    continue;
                const dm_trimesh *m = wall->mesh;
                double d, nm[3];
                /* an element no nearer than its plane's distance: most candidates, within
                 * the skin but not touching, end here, before the contact rule */
                const double *nt = m->nrm + 3 * (size_t)b->t[p];
                const double h = plane_distance(m, b->t[p], V);
                int valid = 0;
                if (fabs(h) >= r + w->cohesion_reach) {
                    d = fabs(h);
                    for (int c = 0; c < 3; c++)
                        nm[c] = h >= 0.0 ? -nt[c] : nt[c];
                } else {
                    valid = element_contact(m, b->t[p], V, &d, nm);
                }
                /* an element that is not the contact: none, and for a
                 * cohesive pair, which may interact apart, far apart */
                const double delta = r - d,
                             stored = valid ? delta
                                      : delta > 0.0 ? 0.0
                                      : w->cohesion_reach > 0.0 ? -DM_FACE_ELSEWHERE
                                                                : delta;
                if (!(stored > 0.0) && !b->on[p]) {
                    /* apart, and apart before: the forces read only its overlap */
                    w->wg.delta[g0 + p] = stored;
                    continue;
                }
                double n[3];
                to_world(wall, nm, n);
                dm_wgeom_store(w, g0 + p, i, wall, stored, n);
            }
            if (carry && wall->kind == DM_WALL_MESH && p - p0 > 1)
                carry_group(w, b, g0, p0, p);
        }
    }
}
