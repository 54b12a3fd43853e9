/* fit.c: a clump template from a closed triangle mesh: N overlapping
 * spheres that fill it, and how well their union fits it (volume error,
 * largest surface deviations both ways).
 *
 * Method: a greedy choice of maximal inscribed balls on the interior
 * distance field, as Angelidakis, Nadimi, Otsubo and Utili (2021), "CLUMP:
 * A Code Library to generate Universal Multi-sphere Particles", SoftwareX
 * 15, 100735, fill a voxel image with the largest balls first, but choosing
 * each ball for the volume it adds rather than for its size:
 *  1. The mesh is laid on a grid of cubes (`cells` along the longest side of
 *     its bounding box); a cube centre is inside when a line along z through
 *     it crosses the surface an odd number of times below it, each crossing
 *     decided on the triangles' corners as computed the same way by the two
 *     triangles of an edge, ties broken by a symbolic shift of the line
 *     (Edelsbrunner and Mücke (1990), "Simulation of Simplicity", ACM Trans.
 *     Graphics 9, 66-104), so that a line through an edge or a corner counts
 *     once.
 *  2. Every inside centre x has the exact distance d(x) to the surface (an
 *     AABB tree of the triangles and the closest point on a triangle,
 *     Ericson (2005), Real-Time Collision Detection, §5.1.5 and §6): the
 *     ball (x, d(x)) is inscribed. The candidates are the centres near the
 *     medial axis, those from which no neighbouring centre is farther from
 *     the surface by 0.8 of the step to it: elsewhere d grows at nearly the
 *     full rate in some direction, and every inscribed ball lies inside a
 *     maximal one, centred on the medial axis (Blum (1967), "A
 *     transformation for extracting new descriptors of shape").
 *  3. Balls are chosen one at a time, each the candidate that adds the most
 *     volume, estimated as its volume less the cube volume h³ for each
 *     covered inside centre in it (exact for the first ball), with lazy
 *     re-evaluation of a priority queue of the gains, which can only fall
 *     as the union grows (Minoux (1978), "Accelerated greedy algorithms for
 *     maximizing submodular set functions", Lecture Notes in Control and
 *     Information Sciences 7, 234-243): the greedy rule, which for the
 *     coverage of a set comes within 1 - 1/e of the best choice of N
 *     (Nemhauser, Wolsey and Fisher (1978), "An analysis of approximations
 *     for maximizing submodular set functions - I", Math. Programming 14,
 *     265-294). The chosen centre is then moved off the grid by a compass
 *     search (26 directions, steps h/2 down to h/2^14, each within the
 *     ball, so the centre stays inside) for the largest gain, the radius
 *     always the exact distance to the surface: the first ball becomes the
 *     largest inscribed ball to about 1e-4 h.
 * Chosen over the clustered overlapping sphere algorithm (Garcia, Latham,
 * Xiang and Harrison (2009), "A clustered overlapping sphere algorithm to
 * represent real particles in discrete element modelling", Géotechnique 59,
 * 779-784) and the method of Ferellec and McDowell (2010), "A method to
 * model realistic particle shape and inertia in DEM", Granular Matter 12,
 * 459-467, because it takes N itself rather than tolerances that set N,
 * is deterministic (no random surface points), and never lets a sphere
 * out of the mesh, so that a clump touches nothing its shape would not.
 *
 * The fit: since every ball is inscribed, the union lies inside the mesh
 * and the symmetric difference is the mesh's volume (exact, by the
 * divergence theorem over the triangles) less the union's, which is
 * integrated exactly along z over columns of side h/4 (intervals merged),
 * its resolution error taken as the change from columns of side h/2. The
 * deviations are the largest distances from a sample of the mesh's surface
 * (a lattice on each triangle, spacing at most h/4) to the union, a bound
 * of the sampling error the lattice's longest edge (the distance is
 * 1-Lipschitz), and from a sample of the union's surface (a Fibonacci
 * lattice on each sphere, González (2010), "Measurement of areas on a
 * sphere using Fibonacci and latitude-longitude lattices", Math. Geosci.
 * 42, 49-64, and points on each circle where two spheres meet, spacing
 * about h/2, those inside another sphere left out) to the mesh. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/shapes/shapes.h"

#define FLAT 1e-12      /* a triangle's height under this of its longest edge: zero area */
#define LEAF 4          /* triangles per leaf of the tree, at most */
#define STACK 64        /* more than the depth + 1 of a median-split tree of 2^32 triangles */
#define RIDGE 0.8       /* a centre is off the medial axis if d grows by this per step */
#define SEARCH_LEVELS 14 /* the compass search's step halvings, from h/2 */
#define SEARCH_MOVES 1000 /* its moves at one step length, at most (8 seen) */

typedef struct node {
    double lo[3], hi[3];
    uint32_t first, count; /* a leaf: its triangles order[first..first+count) */
    uint32_t child;        /* not a leaf (count 0): its children child, child + 1 */
} node;

/* Everything the fit works with. */
typedef struct fit {
    const double *v;
    const uint32_t *tri;
    size_t nv, nt;
    node *tree;
    uint32_t *order, nnodes;
    int n[3];          /* cubes along x, y, z */
    double o[3], h;    /* the grid's corner and cube side */
    uint8_t *state;    /* per cube: 0 outside, 1 inside, 2 inside and covered */
    double *d;         /* per cube: the distance from its centre to the surface (inside) */
    int32_t *cum;      /* per column (n[2] + 1 each): covered cubes below each z index */
    char *err;
    size_t errlen;
} fit;

static demill_status fail(fit *f, demill_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static demill_status fail(fit *f, demill_status code, const char *fmt, ...)
{
    if (f->errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(f->err, f->errlen, fmt, ap);
        va_end(ap);
    }
    return code;
}

static const double *vtx(const fit *f, size_t t, int j)
{
    return f->v + 3 * (size_t)f->tri[3 * t + j];
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub(const double *a, const double *b, double *out)
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}

static void cross(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* ---- the mesh's checks ---------------------------------------------------------- */
/* An edge as a triangle runs it. */
typedef struct edge {
    uint32_t lo, hi; /* its vertices, lo < hi */
    uint32_t t;      /* the triangle */
    int forward;     /* the triangle runs it from lo to hi */
} edge;

static int edge_order(const void *pa, const void *pb)
{
    const edge *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

/* The triangles' corners: finite, indices in range, no zero area. */
static demill_status check_triangles(fit *f)
{
    for (size_t k = 0; k < 3 * f->nv; k++)
        if (!isfinite(f->v[k]))
            return fail(f, DEMILL_ERR_NOT_FINITE, "vertex %zu has %s coordinate", k / 3,
                        isnan(f->v[k]) ? "a NaN" : "an infinite");
    for (size_t t = 0; t < f->nt; t++) {
        const uint32_t *c = f->tri + 3 * t;
        for (int j = 0; j < 3; j++)
            if (c[j] >= f->nv)
                return fail(f, DEMILL_ERR_INVALID_VALUE,
                            "triangle %zu: corner %d is vertex %u, but there are %zu vertices", t,
                            j, c[j], f->nv);
        for (int j = 0; j < 3; j++)
            if (c[j] == c[(j + 1) % 3])
                return fail(f, DEMILL_ERR_INVALID_VALUE,
                            "triangle %zu has zero area: two corners are vertex %u", t, c[j]);
        double e[3][3], longest2 = 0.0, n[3];
        for (int j = 0; j < 3; j++) {
            sub(vtx(f, t, (j + 1) % 3), vtx(f, t, j), e[j]);
            longest2 = fmax(longest2, dot(e[j], e[j]));
        }
        cross(e[0], e[2], n);
        if (!(sqrt(dot(n, n)) > FLAT * longest2)) /* |n| = height x longest edge */
            return fail(f, DEMILL_ERR_INVALID_VALUE,
                        "triangle %zu has zero area: its corners are in a line", t);
    }
    return DEMILL_OK;
}

/* Every edge shared by exactly two triangles that run it opposite ways. */
static demill_status check_closed(fit *f)
{
    const size_t ne = 3 * f->nt;
    edge *e = malloc(ne * sizeof *e);
    if (!e)
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory checking %zu triangles", f->nt);
    for (size_t t = 0; t < f->nt; t++)
        for (int j = 0; j < 3; j++) {
            const uint32_t a = f->tri[3 * t + j], b = f->tri[3 * t + (j + 1) % 3];
            e[3 * t + j] = (edge){a < b ? a : b, a < b ? b : a, (uint32_t)t, a < b};
        }
    qsort(e, ne, sizeof *e, edge_order);
    demill_status st = DEMILL_OK;
    for (size_t g = 0, k; g < ne && st == DEMILL_OK; g = k) {
        for (k = g; k < ne && e[k].lo == e[g].lo && e[k].hi == e[g].hi; k++)
            ;
        if (k - g != 2)
            st = fail(f, DEMILL_ERR_INVALID_VALUE,
                      "the mesh is not closed: the edge between vertices %u and %u belongs to "
                      "%zu triangle%s (triangle %u%s), not 2",
                      e[g].lo, e[g].hi, k - g, k - g == 1 ? "" : "s", e[g].t,
                      k - g == 1 ? "" : " and others");
        else if (e[g].forward == e[g + 1].forward)
            st = fail(f, DEMILL_ERR_INVALID_VALUE,
                      "the mesh is not consistently oriented: triangles %u and %u both run "
                      "from vertex %u to vertex %u",
                      e[g].t, e[g + 1].t, e[g].forward ? e[g].lo : e[g].hi,
                      e[g].forward ? e[g].hi : e[g].lo);
    }
    free(e);
    return st;
}

/* The volume the closed mesh encloses: the sum of the signed volumes of the
 * tetrahedra from a point (the first vertex, for round-off) to each triangle
 * (the divergence theorem), positive when the triangles wind
 * counter-clockwise seen from outside. */
static double mesh_volume(const fit *f)
{
    double vol = 0.0;
    for (size_t t = 0; t < f->nt; t++) {
        double a[3], b[3], c[3], n[3];
        sub(vtx(f, t, 0), f->v, a);
        sub(vtx(f, t, 1), f->v, b);
        sub(vtx(f, t, 2), f->v, c);
        cross(b, c, n);
        vol += dot(a, n);
    }
    return vol / 6.0;
}

/* ---- distance to the surface ----------------------------------------------------- */
/* The squared distance from p to triangle t: Ericson (2005), §5.1.5, the
 * closest point found by the Voronoi region of p. */
static double tri_dist2(const fit *f, size_t t, const double *p)
{
    const double *a = vtx(f, t, 0), *b = vtx(f, t, 1), *c = vtx(f, t, 2);
    double ab[3], ac[3], ap[3], bp[3], cp[3], q[3], e[3];
    sub(b, a, ab);
    sub(c, a, ac);
    sub(p, a, ap);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0)
        return dot(ap, ap);
    sub(p, b, bp);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3)
        return dot(bp, bp);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double s = d1 / (d1 - d3);
        for (int k = 0; k < 3; k++)
            e[k] = ap[k] - s * ab[k];
        return dot(e, e);
    }
    sub(p, c, cp);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6)
        return dot(cp, cp);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double s = d2 / (d2 - d6);
        for (int k = 0; k < 3; k++)
            e[k] = ap[k] - s * ac[k];
        return dot(e, e);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int k = 0; k < 3; k++)
            e[k] = bp[k] - s * (c[k] - b[k]);
        return dot(e, e);
    }
    const double den = 1.0 / (va + vb + vc), s = vb * den, u = vc * den;
    for (int k = 0; k < 3; k++)
        q[k] = ap[k] - s * ab[k] - u * ac[k];
    return dot(q, q);
}

/* The squared distance from p to box b (ternaries, not fmax: this and
 * span() are the hot loops, and the finite inputs need no NaN rule). */
static double box_dist2(const node *b, const double *p)
{
    double s = 0.0;
    for (int k = 0; k < 3; k++) {
        const double e = p[k] < b->lo[k] ? b->lo[k] - p[k] : p[k] > b->hi[k] ? p[k] - b->hi[k] : 0.0;
        s += e * e;
    }
    return s;
}

/* Reorders order[lo..hi] so that the triangle at m has its centroid's
 * coordinate a where sorting would put it, none before it greater, none
 * after it less: Hoare's FIND as Wirth (1976), Algorithms + Data
 * Structures = Programs, writes it. */
static void select_at(uint32_t *order, long lo, long hi, long m, const double *centroid, int a)
{
    while (lo < hi) {
        const double pivot = centroid[3 * order[m] + a];
        long i = lo, j = hi;
        do {
            while (centroid[3 * order[i] + a] < pivot)
                i++;
            while (pivot < centroid[3 * order[j] + a])
                j--;
            if (i <= j) {
                const uint32_t t = order[i];
                order[i++] = order[j];
                order[j--] = t;
            }
        } while (i <= j);
        if (j < m)
            lo = i;
        if (m < i)
            hi = j;
    }
}

/* Builds node k over order[first..first+count): split in halves at the
 * median of the triangles' centroids along their widest axis, so that the
 * tree is at most log2(count / LEAF) + 1 deep. */
static void build(fit *f, uint32_t k, uint32_t first, uint32_t count, const double *centroid)
{
    node *b = f->tree + k;
    double clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int a = 0; a < 3; a++)
        b->lo[a] = INFINITY, b->hi[a] = -INFINITY;
    for (uint32_t i = first; i < first + count; i++)
        for (int j = 0; j < 3; j++)
            for (int a = 0; a < 3; a++) {
                const double x = vtx(f, f->order[i], j)[a], c = centroid[3 * f->order[i] + a];
                b->lo[a] = fmin(b->lo[a], x), b->hi[a] = fmax(b->hi[a], x);
                clo[a] = fmin(clo[a], c), chi[a] = fmax(chi[a], c);
            }
    if (count <= LEAF) {
        b->first = first, b->count = count, b->child = 0;
        return;
    }
    int axis = 0;
    for (int a = 1; a < 3; a++)
        if (chi[a] - clo[a] > chi[axis] - clo[axis])
            axis = a;
    const uint32_t half = count / 2;
    select_at(f->order, first, (long)first + count - 1, (long)first + half, centroid, axis);
    b->count = 0;
    b->child = f->nnodes;
    f->nnodes += 2;
    build(f, b->child, first, half, centroid);
    build(f, b->child + 1, first + half, count - half, centroid);
}

static demill_status build_tree(fit *f)
{
    double *centroid = malloc(3 * f->nt * sizeof *centroid);
    f->order = malloc(f->nt * sizeof *f->order);
    f->tree = malloc(2 * f->nt * sizeof *f->tree);
    if (!centroid || !f->order || !f->tree) {
        free(centroid);
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory indexing %zu triangles", f->nt);
    }
    for (size_t t = 0; t < f->nt; t++) {
        f->order[t] = (uint32_t)t;
        for (int a = 0; a < 3; a++)
            centroid[3 * t + a] = (vtx(f, t, 0)[a] + vtx(f, t, 1)[a] + vtx(f, t, 2)[a]) / 3.0;
    }
    f->nnodes = 1;
    build(f, 0, 0, (uint32_t)f->nt, centroid);
    free(centroid);
    return DEMILL_OK;
}

/* The distance from p to the mesh's surface. */
static double surface_dist(const fit *f, const double *p)
{
    uint32_t stack[STACK];
    int top = 0;
    double best = INFINITY;
    stack[top++] = 0;
    while (top) {
        const node *b = f->tree + stack[--top];
        if (box_dist2(b, p) >= best)
            continue;
        if (b->count) {
            for (uint32_t i = b->first; i < b->first + b->count; i++) {
                const double d2 = tri_dist2(f, f->order[i], p);
                best = d2 < best ? d2 : best;
            }
            continue;
        }
        const double d0 = box_dist2(f->tree + b->child, p), d1 = box_dist2(f->tree + b->child + 1, p);
        stack[top++] = b->child + (d0 < d1); /* the nearer child last, visited first */
        stack[top++] = b->child + (d0 >= d1);
    }
    return sqrt(best);
}

/* ---- the grid and what is inside ------------------------------------------------- */
static size_t cube(const fit *f, int i, int j, int k)
{
    return ((size_t)i * f->n[1] + j) * f->n[2] + k;
}

static double centre(const fit *f, int a, int i)
{
    return f->o[a] + (i + 0.5) * f->h;
}

/* The grid indices ijk and the centre x of cube q. */
static void cube_at(const fit *f, size_t q, int ijk[3], double x[3])
{
    ijk[0] = (int)(q / ((size_t)f->n[1] * f->n[2]));
    ijk[1] = (int)(q / f->n[2] % f->n[1]);
    ijk[2] = (int)(q % f->n[2]);
    for (int a = 0; a < 3; a++)
        x[a] = centre(f, a, ijk[a]);
}

/* The side of the projected edge from p to q (xy) on which the point x
 * lies, as +1 or -1: the orientation of (lo, hi, x) with lo and hi the two
 * corners in lexicographic order, computed the same way by both triangles
 * of the edge, and a zero decided as for x shifted by (ε, ε²) (Simulation
 * of Simplicity), which depends on the edge alone. */
static int side(const double *p, const double *q, const double *x)
{
    const int swap = p[0] > q[0] || (p[0] == q[0] && p[1] > q[1]);
    const double *lo = swap ? q : p, *hi = swap ? p : q;
    const double dx = hi[0] - lo[0], dy = hi[1] - lo[1];
    const double s = dx * (x[1] - lo[1]) - dy * (x[0] - lo[0]);
    const int sign = s > 0.0 ? 1 : s < 0.0 ? -1 : dy != 0.0 ? (dy > 0.0 ? -1 : 1) : 1;
    return swap ? -sign : sign;
}

/* Where the line along z through (x, y) crosses triangle t: 1 and its z in
 * *z, or 0. */
static int crossing(const fit *f, size_t t, const double *x, double *z)
{
    const double *a = vtx(f, t, 0), *b = vtx(f, t, 1), *c = vtx(f, t, 2);
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (area == 0.0)
        return 0; /* parallel to the line: its neighbours decide */
    const int want = area > 0.0 ? 1 : -1;
    if (side(a, b, x) != want || side(b, c, x) != want || side(c, a, x) != want)
        return 0;
    const double u = ((x[0] - a[0]) * (c[1] - a[1]) - (x[1] - a[1]) * (c[0] - a[0])) / area;
    const double w = ((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / area;
    *z = a[2] + u * (b[2] - a[2]) + w * (c[2] - a[2]);
    return 1;
}

/* The columns (i0..i1, j0..j1) whose lines may cross triangle t. */
static void columns_of(const fit *f, size_t t, int *i0, int *i1, int *j0, int *j1)
{
    int *lo[2] = {i0, j0}, *hi[2] = {i1, j1};
    for (int a = 0; a < 2; a++) {
        const double m = fmin(fmin(vtx(f, t, 0)[a], vtx(f, t, 1)[a]), vtx(f, t, 2)[a]);
        const double M = fmax(fmax(vtx(f, t, 0)[a], vtx(f, t, 1)[a]), vtx(f, t, 2)[a]);
        *lo[a] = (int)fmax(floor((m - f->o[a]) / f->h - 0.5), 0.0);
        *hi[a] = (int)fmin(ceil((M - f->o[a]) / f->h - 0.5), f->n[a] - 1.0);
    }
}

static int by_value(const void *pa, const void *pb)
{
    const double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* state[] from the crossings of each column's line: inside where an odd
 * number of them lie below the cube's centre. */
static demill_status mark_inside(fit *f)
{
    const size_t ncol = (size_t)f->n[0] * f->n[1];
    size_t *start = calloc(ncol + 1, sizeof *start);
    if (!start)
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for %zu columns", ncol);
    double *z = NULL;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t t = 0; t < f->nt; t++) {
            int i0, i1, j0, j1;
            columns_of(f, t, &i0, &i1, &j0, &j1);
            for (int i = i0; i <= i1; i++)
                for (int j = j0; j <= j1; j++) {
                    const double x[2] = {centre(f, 0, i), centre(f, 1, j)};
                    double zc;
                    if (!crossing(f, t, x, &zc))
                        continue;
                    const size_t col = (size_t)i * f->n[1] + j;
                    if (pass)
                        z[start[col]++] = zc;
                    else
                        start[col + 1]++;
                }
        }
        if (pass)
            break;
        for (size_t c = 0; c < ncol; c++)
            start[c + 1] += start[c];
        z = malloc((start[ncol] ? start[ncol] : 1) * sizeof *z);
        if (!z) {
            const size_t need = start[ncol];
            free(start);
            return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for %zu crossings", need);
        }
    }
    /* the second pass moved each start to its column's end */
    for (size_t c = 0, from = 0; c < ncol; c++) {
        const size_t to = start[c];
        qsort(z + from, to - from, sizeof *z, by_value);
        const int i = (int)(c / f->n[1]), j = (int)(c % f->n[1]);
        size_t below = from;
        for (int k = 0; k < f->n[2]; k++) {
            const double zk = centre(f, 2, k);
            while (below < to && z[below] < zk)
                below++;
            f->state[cube(f, i, j, k)] = (below - from) % 2;
        }
        from = to;
    }
    free(z);
    free(start);
    return DEMILL_OK;
}

/* ---- the greedy choice ----------------------------------------------------------- */
/* The grid indices lo..hi of the centres within [x - r, x + r] along axis a. */
static void span(const fit *f, int a, double x, double r, int *lo, int *hi)
{
    const double l = ceil((x - r - f->o[a]) / f->h - 0.5), u = floor((x + r - f->o[a]) / f->h - 0.5);
    *lo = l > 0.0 ? (int)l : 0;
    *hi = u < f->n[a] - 1.0 ? (int)u : f->n[a] - 1;
}

/* The covered inside centres in the ball (c, r), by columns. */
static long covered_in(const fit *f, const double *c, double r)
{
    long n = 0;
    int i0, i1;
    span(f, 0, c[0], r, &i0, &i1);
    for (int i = i0; i <= i1; i++) {
        const double dx = centre(f, 0, i) - c[0], rx2 = r * r - dx * dx;
        if (rx2 < 0.0)
            continue;
        int j0, j1;
        span(f, 1, c[1], sqrt(rx2), &j0, &j1);
        for (int j = j0; j <= j1; j++) {
            const double dy = centre(f, 1, j) - c[1], rz2 = rx2 - dy * dy;
            if (rz2 < 0.0)
                continue;
            int k0, k1;
            span(f, 2, c[2], sqrt(rz2), &k0, &k1);
            if (k1 < k0)
                continue;
            const int32_t *cum = f->cum + ((size_t)i * f->n[1] + j) * (f->n[2] + 1);
            n += cum[k1 + 1] - cum[k0];
        }
    }
    return n;
}

/* The volume the ball (c, r) would add: its own less h³ per covered centre. */
static double gain(const fit *f, const double *c, double r)
{
    return 4.0 / 3.0 * DM_PI * r * r * r - f->h * f->h * f->h * (double)covered_in(f, c, r);
}

/* Marks the inside centres in the ball (c, r) covered. */
static void cover(fit *f, const double *c, double r)
{
    int i0, i1, j0, j1, k0, k1;
    span(f, 0, c[0], r, &i0, &i1);
    span(f, 1, c[1], r, &j0, &j1);
    span(f, 2, c[2], r, &k0, &k1);
    for (int i = i0; i <= i1; i++)
        for (int j = j0; j <= j1; j++) {
            int touched = 0;
            for (int k = k0; k <= k1; k++) {
                const double x[3] = {centre(f, 0, i), centre(f, 1, j), centre(f, 2, k)};
                double e[3];
                sub(x, c, e);
                if (f->state[cube(f, i, j, k)] == 1 && dot(e, e) <= r * r)
                    f->state[cube(f, i, j, k)] = 2, touched = 1;
            }
            if (!touched)
                continue;
            int32_t *cum = f->cum + ((size_t)i * f->n[1] + j) * (f->n[2] + 1);
            for (int k = 0; k < f->n[2]; k++)
                cum[k + 1] = cum[k] + (f->state[cube(f, i, j, k)] == 2);
        }
}

/* The 26 unit vectors towards a cube's neighbours. */
static void directions(double u[26][3])
{
    int m = 0;
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            for (int c = -1; c <= 1; c++) {
                if (!a && !b && !c)
                    continue;
                const double len = sqrt((double)(a * a + b * b + c * c));
                u[m][0] = a / len, u[m][1] = b / len, u[m][2] = c / len;
                m++;
            }
}

/* Moves the centre c (radius *r, gain *g) by a compass search for a larger
 * gain, each step shorter than the radius so that the centre stays inside. */
static void refine(const fit *f, double *c, double *r, double *g)
{
    double u[26][3];
    directions(u);
    double s = 0.5 * f->h;
    for (int level = 0; level <= SEARCH_LEVELS; level++, s *= 0.5)
        for (int moves = 0; moves < SEARCH_MOVES; moves++) {
            double best[3], br = 0.0, bg = *g;
            for (int m = 0; m < 26; m++) {
                if (s >= *r)
                    break;
                double x[3];
                for (int a = 0; a < 3; a++)
                    x[a] = c[a] + s * u[m][a];
                const double rx = surface_dist(f, x), gx = gain(f, x, rx);
                if (gx > bg)
                    memcpy(best, x, sizeof best), br = rx, bg = gx;
            }
            if (bg == *g)
                break;
            memcpy(c, best, sizeof best);
            *r = br;
            *g = bg;
        }
}

/* A max-heap of candidates by gain, ties to the lower cube index. */
typedef struct entry {
    double key;
    size_t cube;
} entry;

static int above(const entry *a, const entry *b)
{
    return a->key > b->key || (a->key == b->key && a->cube < b->cube);
}

static void heap_down(entry *e, size_t n, size_t k)
{
    for (;;) {
        size_t m = k, l = 2 * k + 1;
        if (l < n && above(&e[l], &e[m]))
            m = l;
        if (l + 1 < n && above(&e[l + 1], &e[m]))
            m = l + 1;
        if (m == k)
            return;
        const entry s = e[k];
        e[k] = e[m], e[m] = s, k = m;
    }
}

/* Whether cube q is a candidate: inside, and no neighbour's centre farther
 * from the surface by RIDGE of the step to it. */
static int on_ridge(const fit *f, size_t q)
{
    if (!f->state[q])
        return 0;
    int ijk[3];
    double x[3];
    cube_at(f, q, ijk, x);
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            for (int e = -1; e <= 1; e++) {
                const int i = ijk[0] + a, j = ijk[1] + b, k = ijk[2] + e;
                if ((!a && !b && !e) || i < 0 || j < 0 || k < 0 || i >= f->n[0] ||
                    j >= f->n[1] || k >= f->n[2])
                    continue;
                const size_t p = cube(f, i, j, k);
                if (f->state[p] && f->d[p] - f->d[q] >= RIDGE * f->h * sqrt(a * a + b * b + e * e))
                    return 0;
            }
    return 1;
}

/* The distances, the candidates near the medial axis, and the greedy
 * choice of up to ns balls into c and r; *placed says how many. */
static demill_status choose(fit *f, size_t ns, double *c, double *r, size_t *placed)
{
    const size_t ncube = (size_t)f->n[0] * f->n[1] * f->n[2];
    for (size_t q = 0; q < ncube; q++)
        if (f->state[q]) {
            int ijk[3];
            double x[3];
            cube_at(f, q, ijk, x);
            f->d[q] = surface_dist(f, x);
        }
    size_t nh = 0;
    for (size_t q = 0; q < ncube; q++)
        nh += on_ridge(f, q);
    entry *heap = malloc((nh ? nh : 1) * sizeof *heap);
    if (!heap)
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for %zu candidates", nh);
    nh = 0;
    for (size_t q = 0; q < ncube; q++)
        if (on_ridge(f, q))
            heap[nh++] = (entry){4.0 / 3.0 * DM_PI * f->d[q] * f->d[q] * f->d[q], q};
    for (size_t k = nh / 2; k-- > 0;)
        heap_down(heap, nh, k);
    size_t n = 0;
    while (n < ns && nh) {
        const size_t q = heap[0].cube;
        int ijk[3];
        double x[3], rx = f->d[q];
        cube_at(f, q, ijk, x);
        double g = gain(f, x, rx);
        if (!(g > 0.0)) { /* adds nothing now, nor will later */
            heap[0] = heap[--nh];
            heap_down(heap, nh, 0);
            continue;
        }
        heap[0].key = g;
        heap_down(heap, nh, 0);
        if (heap[0].cube != q) /* another may add more: look again */
            continue;
        heap[0] = heap[--nh];
        heap_down(heap, nh, 0);
        refine(f, x, &rx, &g);
        memcpy(c + 3 * n, x, sizeof x);
        r[n++] = rx;
        cover(f, x, rx);
    }
    free(heap);
    *placed = n;
    return DEMILL_OK;
}

/* ---- the fit's errors ------------------------------------------------------------ */
typedef struct interval {
    double lo, hi;
} interval;

static int by_start(const void *pa, const void *pb)
{
    const interval *a = pa, *b = pb;
    return (a->lo > b->lo) - (a->lo < b->lo);
}

/* The volume of the union of the n balls (c, r), integrated exactly along z
 * over square columns of side s laid from lo (xy) (the length of the
 * union of the balls' chords through each column's centre); buf holds n
 * intervals. */
static double union_volume(size_t n, const double *c, const double *r, const double *lo,
                           const int *cols, double s, interval *buf)
{
    double vol = 0.0;
    for (int i = 0; i < cols[0]; i++)
        for (int j = 0; j < cols[1]; j++) {
            const double x = lo[0] + (i + 0.5) * s, y = lo[1] + (j + 0.5) * s;
            size_t m = 0;
            for (size_t b = 0; b < n; b++) {
                const double dx = x - c[3 * b], dy = y - c[3 * b + 1];
                const double t2 = r[b] * r[b] - dx * dx - dy * dy;
                if (t2 > 0.0)
                    buf[m++] = (interval){c[3 * b + 2] - sqrt(t2), c[3 * b + 2] + sqrt(t2)};
            }
            qsort(buf, m, sizeof *buf, by_start);
            double len = 0.0;
            for (size_t k = 0, e; k < m; k = e) {
                double hi = buf[k].hi;
                for (e = k + 1; e < m && buf[e].lo <= hi; e++)
                    hi = fmax(hi, buf[e].hi);
                len += hi - buf[k].lo;
            }
            vol += len;
        }
    return vol * s * s;
}

/* Whether x lies strictly inside one of the balls (c, r) other than skip and
 * skip2. */
static int in_other(size_t n, const double *c, const double *r, size_t skip, size_t skip2,
                    const double *x)
{
    for (size_t b = 0; b < n; b++) {
        double e[3];
        sub(x, c + 3 * b, e);
        if (b != skip && b != skip2 && dot(e, e) < r[b] * r[b])
            return 1;
    }
    return 0;
}

/* The largest distance from the mesh's surface to the union of the balls,
 * over a lattice of spacing at most s on each triangle; *tol the lattice's
 * longest edge, which bounds what the sample can miss. */
static double deviation_out(const fit *f, size_t n, const double *c, const double *r, double s,
                            double *tol)
{
    double worst = 0.0;
    *tol = 0.0;
    for (size_t t = 0; t < f->nt; t++) {
        const double *a = vtx(f, t, 0), *b = vtx(f, t, 1), *cc = vtx(f, t, 2);
        double e[3][3], longest = 0.0;
        sub(b, a, e[0]);
        sub(cc, a, e[1]);
        sub(cc, b, e[2]);
        for (int k = 0; k < 3; k++)
            longest = fmax(longest, sqrt(dot(e[k], e[k])));
        const int m = (int)ceil(longest / s);
        *tol = fmax(*tol, longest / m);
        for (int i = 0; i <= m; i++)
            for (int j = 0; i + j <= m; j++) {
                double x[3], near = INFINITY;
                for (int k = 0; k < 3; k++)
                    x[k] = a[k] + (i * e[0][k] + j * e[1][k]) / m;
                for (size_t q = 0; q < n; q++) {
                    double y[3];
                    sub(x, c + 3 * q, y);
                    near = fmin(near, sqrt(dot(y, y)) - r[q]);
                }
                worst = fmax(worst, near);
            }
    }
    return worst;
}

/* The largest distance from the union's surface to the mesh's, over a
 * Fibonacci lattice on each sphere and points on each circle where two
 * meet, spacing about s, those inside another ball left out; *tol the
 * largest spacing used. */
static double deviation_in(const fit *f, size_t n, const double *c, const double *r, double s,
                           double *tol)
{
    const double golden = DM_PI * (3.0 - sqrt(5.0)); /* the golden angle */
    double worst = 0.0;
    *tol = 0.0;
    for (size_t b = 0; b < n; b++) {
        const double want = ceil(4.0 * DM_PI * r[b] * r[b] / (s * s));
        const long k = (long)fmin(fmax(want, 64.0), 65536.0);
        *tol = fmax(*tol, r[b] * sqrt(4.0 * DM_PI / k));
        for (long p = 0; p < k; p++) {
            const double z = 1.0 - (2.0 * p + 1.0) / k, rho = sqrt(1.0 - z * z);
            const double x[3] = {c[3 * b] + r[b] * rho * cos(golden * p),
                                 c[3 * b + 1] + r[b] * rho * sin(golden * p),
                                 c[3 * b + 2] + r[b] * z};
            if (!in_other(n, c, r, b, b, x))
                worst = fmax(worst, surface_dist(f, x));
        }
        for (size_t q = b + 1; q < n; q++) {
            double e[3];
            sub(c + 3 * q, c + 3 * b, e);
            const double dist = sqrt(dot(e, e));
            if (!(dist < r[b] + r[q]) || dist <= fabs(r[b] - r[q]))
                continue; /* apart, or one inside the other: no circle */
            const double a = (dist * dist + r[b] * r[b] - r[q] * r[q]) / (2.0 * dist);
            const double rho = sqrt(fmax(r[b] * r[b] - a * a, 0.0));
            double u[3] = {e[0] / dist, e[1] / dist, e[2] / dist}, p1[3], p2[3];
            const double any[3] = {fabs(u[0]) < 0.6 ? 1.0 : 0.0, fabs(u[0]) < 0.6 ? 0.0 : 1.0, 0.0};
            cross(u, any, p1);
            const double l1 = sqrt(dot(p1, p1));
            for (int k = 0; k < 3; k++)
                p1[k] /= l1;
            cross(u, p1, p2);
            const long m = (long)fmin(fmax(ceil(2.0 * DM_PI * rho / s), 16.0), 4096.0);
            *tol = fmax(*tol, 2.0 * DM_PI * rho / m);
            for (long p = 0; p < m; p++) {
                const double phi = 2.0 * DM_PI * p / m;
                double x[3];
                for (int k = 0; k < 3; k++)
                    x[k] = c[3 * b + k] + a * u[k] + rho * (cos(phi) * p1[k] + sin(phi) * p2[k]);
                if (!in_other(n, c, r, b, q, x))
                    worst = fmax(worst, surface_dist(f, x));
            }
        }
    }
    return worst;
}

/* The report of the n balls (c, r) fitted to a mesh of volume vol. */
static demill_status report(fit *f, size_t n, const double *c, const double *r, double vol,
                            dm_fit_report *rep)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t b = 0; b < n; b++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fmin(lo[a], c[3 * b + a] - r[b]);
            hi[a] = fmax(hi[a], c[3 * b + a] + r[b]);
        }
    interval *buf = malloc(n * sizeof *buf);
    if (!buf)
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for %zu spheres", n);
    double u[2];
    for (int level = 0; level < 2; level++) {
        const double s = f->h / (2 << level); /* h/2, then h/4 */
        const int cols[2] = {(int)ceil((hi[0] - lo[0]) / s), (int)ceil((hi[1] - lo[1]) / s)};
        u[level] = union_volume(n, c, r, lo, cols, s, buf);
    }
    free(buf);
    rep->n = n;
    rep->volume = vol;
    rep->union_volume = u[1];
    rep->volume_error = (vol - u[1]) / vol;
    rep->volume_error_tol = fabs(u[1] - u[0]) / vol;
    rep->size = cbrt(6.0 * vol / DM_PI);
    rep->deviation_out = deviation_out(f, n, c, r, 0.25 * f->h, &rep->deviation_out_tol);
    rep->deviation_in = deviation_in(f, n, c, r, 0.5 * f->h, &rep->deviation_in_tol);
    for (int a = 0; a < 3; a++)
        rep->cells[a] = f->n[a];
    rep->h = f->h;
    rep->inside = 0;
    for (size_t q = 0; q < (size_t)f->n[0] * f->n[1] * f->n[2]; q++)
        rep->inside += f->state[q] != 0;
    return DEMILL_OK;
}

/* ---- the whole fit --------------------------------------------------------------- */
/* Lays the grid on the mesh's bounding box: cells cubes along its longest
 * side, as many of that size as cover each other side, centred on it. */
static demill_status lay_grid(fit *f, int cells)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < f->nv; k++)
        for (int a = 0; a < 3; a++)
            lo[a] = fmin(lo[a], f->v[3 * k + a]), hi[a] = fmax(hi[a], f->v[3 * k + a]);
    f->h = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]) / cells;
    for (int a = 0; a < 3; a++) {
        f->n[a] = (int)fmin(fmax(ceil((hi[a] - lo[a]) / f->h), 1.0), cells);
        f->o[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * f->n[a] * f->h;
    }
    const size_t ncube = (size_t)f->n[0] * f->n[1] * f->n[2];
    f->state = calloc(ncube, 1);
    f->d = malloc(ncube * sizeof *f->d);
    f->cum = calloc((size_t)f->n[0] * f->n[1] * (f->n[2] + 1), sizeof *f->cum);
    if (!f->state || !f->d || !f->cum)
        return fail(f, DEMILL_ERR_OUT_OF_MEMORY, "out of memory for a grid of %d x %d x %d cubes",
                    f->n[0], f->n[1], f->n[2]);
    return DEMILL_OK;
}

static demill_status run(fit *f, size_t ns, int cells, double *c, double *r, dm_fit_report *rep)
{
    demill_status st;
    if ((st = check_triangles(f)) || (st = check_closed(f)))
        return st;
    const double vol = mesh_volume(f);
    if (!(vol > 0.0))
        return fail(f, DEMILL_ERR_INVALID_VALUE,
                    "the mesh encloses a volume of %g: it is %s (its triangles must wind "
                    "counter-clockwise seen from outside)",
                    vol, vol < 0.0 ? "inside out" : "flat");
    if ((st = build_tree(f)) || (st = lay_grid(f, cells)) || (st = mark_inside(f)))
        return st;
    size_t placed = 0;
    if ((st = choose(f, ns, c, r, &placed)))
        return st;
    if (!placed)
        return fail(f, DEMILL_ERR_INVALID_VALUE,
                    "no centre of the grid's %d x %d x %d cubes lies inside the mesh: more cells "
                    "are needed",
                    f->n[0], f->n[1], f->n[2]);
    return report(f, placed, c, r, vol, rep);
}

demill_status dm_spheres_fit_mesh(size_t nv, const double *v, size_t nt, const uint32_t *tri,
                                  size_t nspheres, int cells, double *centres, double *radii,
                                  dm_fit_report *rep, char *err, size_t errlen)
{
    fit f = {.v = v, .tri = tri, .nv = nv, .nt = nt, .err = err, .errlen = err ? errlen : 0};
    if (f.errlen)
        err[0] = '\0';
    if (!v || !tri || !centres || !radii || !rep)
        return fail(&f, DEMILL_ERR_NULL_POINTER, "a required pointer is NULL");
    if (nspheres == 0)
        return fail(&f, DEMILL_ERR_INVALID_VALUE, "no spheres asked for");
    if (nspheres > SIZE_MAX / (3 * sizeof(double)))
        return fail(&f, DEMILL_ERR_OUT_OF_MEMORY, "%zu spheres do not fit in memory", nspheres);
    if (cells < DM_FIT_CELLS_MIN || cells > DM_FIT_CELLS_MAX)
        return fail(&f, DEMILL_ERR_INVALID_VALUE, "%d cells: must be from %d to %d", cells,
                    DM_FIT_CELLS_MIN, DM_FIT_CELLS_MAX);
    if (nt < 4 || nt > UINT32_MAX / 3 || nv > UINT32_MAX)
        return fail(&f, DEMILL_ERR_INVALID_VALUE,
                    "%zu triangles and %zu vertices: a closed mesh has at least 4 triangles, "
                    "this fit at most %u of each",
                    nt, nv, (unsigned)(UINT32_MAX / 3));
    double *c = malloc(3 * nspheres * sizeof *c), *r = malloc(nspheres * sizeof *r);
    dm_fit_report out;
    demill_status st = c && r ? run(&f, nspheres, cells, c, r, &out)
                              : fail(&f, DEMILL_ERR_OUT_OF_MEMORY,
                                     "out of memory for %zu spheres", nspheres);
    if (st == DEMILL_OK) {
        memcpy(centres, c, 3 * out.n * sizeof *c);
        memcpy(radii, r, out.n * sizeof *r);
        *rep = out;
    }
    free(c);
    free(r);
    free(f.tree);
    free(f.order);
    free(f.state);
    free(f.d);
    free(f.cum);
    return st;
}
