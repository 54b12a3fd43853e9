/* shapes_fit.c: the spheres that fill a closed triangle mesh
 * (lib/physics/shapes/fit.c) against numbers derived here another way.
 *
 * What this suite proves:
 *  - A sphere of radius R tessellated as an icosphere (an icosahedron's
 *    faces split in four three times, the new corners pushed out to the
 *    sphere: 1280 triangles) and fitted with one sphere gives its largest
 *    inscribed ball. The icosphere is a convex polytope symmetric under the
 *    icosahedral group, so its largest inscribed ball is centred at the
 *    sphere's centre (the set of such centres is convex and invariant, so
 *    holds the group's fixed point), of radius r_in, the least distance
 *    from the centre to a face's plane; the tessellation error is R - r_in.
 *    The fit's centre and radius are within a tenth of it, and never beyond
 *    r_in. Its reported volume error is 1 - (4/3)π r³ / V, V the
 *    polytope's volume as tetrahedra from the centre; its deviation from
 *    the mesh's surface is that of the farthest corner, |v - c| - r (a
 *    convex function is largest over a polytope at a corner, and the sample
 *    holds the corners); its deviation from the ball's surface is the
 *    largest over a latitude-longitude sample of the sphere of the least
 *    distance to the faces' planes (the distance to a convex polytope's
 *    surface from inside).
 *  - Two spheres of radius R whose centres are 1.2 R apart (a dumbbell, a
 *    surface of revolution) fitted with two spheres give the two centres
 *    within a tenth of the grid's cube, each radius at least that of the
 *    largest ball about the centre less a tenth of a cube and at most the
 *    depth of the fit's centre (the least distance to its bulb's faces'
 *    planes), and the union's volume agrees with that of
 *    the two balls and their lens (dm_spheres_union_mass(), exact) within
 *    the stated resolution error.
 *  - Lines of the grid through a mesh's corners and along its edges count
 *    each crossing once: a regular octahedron |x| + |y| + |z| <= 32.5 on a
 *    grid of 65 unit cubes, whose centres are the integer points (exact in
 *    floating point), has inside it the centres with |i| + |j| + |k| <= 32,
 *    counted here (45825), and a unit cube on 64 cubes (the lines along its
 *    faces' diagonals) all 64³; their largest inscribed balls, of radius
 *    32.5/sqrt(3) and 1/2 about the centre, come out to 1e-4 of a cube.
 *  - For an ellipsoid (the icosphere scaled to semi-axes 10, 7 and 5 mm)
 *    and a box (14 x 14 x 10 mm, 12 triangles) the volume error falls as
 *    N = 5, 20, 50, and agrees with a Monte Carlo estimate (2e5 points in
 *    the bounding box, inside the convex mesh when inside every face's
 *    plane) within four standard errors and the resolution error; no point
 *    of the union is outside the mesh. The same for a shape that is not
 *    convex, a tripod of seven 4 mm cubes (a corner and two along each
 *    axis, 60 triangles: the faces of the cubes not shared), a point inside
 *    it when inside one of the cubes.
 *  - The same input gives bitwise the same spheres.
 *  - An open mesh (one triangle removed), a flipped triangle, a mesh inside
 *    out, N = 0, a NaN vertex, a zero-area triangle, an index out of range,
 *    too few cells and a NULL array are refused with their codes and a
 *    message, and nothing is written.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/random.h"
#include "physics/shapes/shapes.h"
#include "meshes.h"
#include "testutil.h"

static const double R0 = 0.01;                 /* m */
static const double P0[3] = {0.3, -0.2, 0.15}; /* shapes placed away from the origin */
#define CELLS 48

typedef dm_test_mesh mesh;

/* The surface of revolution about the z axis through p of the profile
 * (rho[k], z[k]), k = 0..n, from a pole (rho 0) down to a pole, in
 * segments around. */
static mesh revolve(const double *rho, const double *z, int n, int segments, const double p[3])
{
    mesh m = {0};
    uint32_t *ring = malloc((size_t)(n + 1) * segments * sizeof *ring);
    for (int k = 0; k <= n; k++)
        for (int j = 0; j < segments; j++) {
            const double phi = 2.0 * M_PI * j / segments;
            const double x[3] = {p[0] + rho[k] * cos(phi), p[1] + rho[k] * sin(phi), p[2] + z[k]};
            const double pole[3] = {p[0], p[1], p[2] + z[k]};
            ring[k * segments + j] = dm_test_mesh_vertex(&m, k == 0 || k == n ? pole : x);
        }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < segments; j++) {
            const int j1 = (j + 1) % segments;
            const uint32_t a = ring[k * segments + j], b = ring[(k + 1) * segments + j],
                           c = ring[(k + 1) * segments + j1], d = ring[k * segments + j1];
            if (k < n - 1)
                dm_test_mesh_triangle(&m, a, b, c); /* down, then around: outwards */
            if (k > 0)
                dm_test_mesh_triangle(&m, a, c, d);
        }
    free(ring);
    return m;
}

/* A box from lo to hi, 12 triangles wound outwards. */
static mesh box(const double lo[3], const double hi[3])
{
    mesh m = {0};
    for (int k = 0; k < 8; k++) {
        const double x[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
        dm_test_mesh_vertex(&m, x);
    }
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++) {
        dm_test_mesh_triangle(&m, q[f][0], q[f][1], q[f][2]);
        dm_test_mesh_triangle(&m, q[f][0], q[f][2], q[f][3]);
    }
    return m;
}

static demill_status fit(const mesh *m, size_t n, int cells, double *c, double *r,
                         dm_fit_report *rep, char *err)
{
    return dm_spheres_fit_mesh(m->nv, m->v, m->nt, m->t, n, cells, c, r, rep, err, 256);
}

START_TEST(test_sphere_one)
{
    const double s[3] = {R0, R0, R0};
    mesh m = dm_test_icosphere(3, s, P0);
    ck_assert_uint_eq(m.nt, 1280);
    double r_in = INFINITY;
    for (size_t t = 0; t < m.nt; t++) {
        double n[3];
        r_in = fmin(r_in, dm_test_mesh_plane(&m, t, n) - (n[0] * P0[0] + n[1] * P0[1] + n[2] * P0[2]));
    }
    const double tess = R0 - r_in;
    double c[3], r;
    dm_fit_report rep;
    char err[256];
    ck_assert_int_eq(fit(&m, 1, CELLS, c, &r, &rep, err), DEMILL_OK);
    printf("sphere, N = 1: r_in %.9g, tessellation error %.3g of R; r - r_in = %.3g of R, "
           "|c - p| = %.3g of R\n",
           r_in, tess / R0, (r - r_in) / R0, dm_test_dist3(c, P0) / R0);
    ck_assert_uint_eq(rep.n, 1);
    ck_assert(r <= r_in * (1.0 + 1e-12));
    ck_assert(r >= r_in - 0.1 * tess);
    ck_assert(dm_test_dist3(c, P0) <= 0.1 * tess);
    /* the volume error of one ball in the polytope */
    const double v = dm_test_mesh_volume(&m, P0), want = 1.0 - 4.0 / 3.0 * M_PI * r * r * r / v;
    printf("  volume error %.6g (exact %.6g, resolution error %.2g)\n", rep.volume_error, want,
           rep.volume_error_tol);
    DM_ASSERT_REL(rep.volume, v, 1e-12);
    ck_assert(fabs(rep.volume_error - want) <= rep.volume_error_tol + 1e-12);
    /* from the mesh to the ball: the farthest corner */
    double far = 0.0;
    for (size_t k = 0; k < m.nv; k++)
        far = fmax(far, dm_test_dist3(m.v + 3 * k, c) - r);
    DM_ASSERT_REL(rep.deviation_out, far, 1e-12);
    /* from the ball to the mesh: the deepest point of the ball's surface */
    double deep = 0.0, *pl = dm_test_mesh_planes(&m);
    for (int i = 0; i < 200; i++)
        for (int j = 0; j < 400; j++) {
            const double th = M_PI * (i + 0.5) / 200, ph = 2.0 * M_PI * j / 400;
            const double x[3] = {c[0] + r * sin(th) * cos(ph), c[1] + r * sin(th) * sin(ph),
                                 c[2] + r * cos(th)};
            deep = fmax(deep, dm_test_convex_depth(pl, m.nt, x));
        }
    printf("  deviations: out %.4g (corners %.4g), in %.4g (sampled here %.4g, spacing %.2g), "
           "of R\n",
           rep.deviation_out / R0, far / R0, rep.deviation_in / R0, deep / R0,
           rep.deviation_in_tol / R0);
    ck_assert(fabs(rep.deviation_in - deep) <= rep.deviation_in_tol);
    DM_ASSERT_REL(rep.size, cbrt(6.0 * v / M_PI), 1e-12);
    free(pl);
    dm_test_mesh_free(&m);
}
END_TEST

/* Whether triangle t has its corners on the sphere of radius R0 about p. */
static int face_of(const mesh *m, size_t t, const double p[3])
{
    int on = 1;
    for (int j = 0; j < 3; j++)
        on = on && fabs(dm_test_dist3(m->v + 3 * m->t[3 * t + j], p) - R0) < 1e-12 * R0;
    return on;
}

START_TEST(test_dumbbell)
{
    /* the profile: the upper sphere from its pole to the neck circle at
     * z = 0, where the spheres (centres at z = +-D) meet, then the lower */
    enum { K = 32, SEG = 64 };
    const double D = 0.6 * R0, neck = acos(-D / R0); /* the neck's polar angle */
    double rho[2 * K + 1], z[2 * K + 1];
    for (int k = 0; k <= K; k++) {
        const double th = neck * k / K;
        rho[k] = rho[2 * K - k] = R0 * sin(th);
        z[k] = D + R0 * cos(th);
        z[2 * K - k] = -z[k];
    }
    rho[0] = rho[2 * K] = 0.0;
    z[K] = 0.0;
    mesh m = revolve(rho, z, 2 * K, SEG, P0);
    ck_assert(dm_test_mesh_volume(&m, P0) > 0.0);
    const double want[2][3] = {{P0[0], P0[1], P0[2] + D}, {P0[0], P0[1], P0[2] - D}};
    /* the largest ball about each bulb's centre: the least distance to the
     * planes of its faces (the other bulb's faces are farther, outside the
     * sphere); the largest inscribed ball near it may be a little larger,
     * its centre a little off (the bulb is not symmetric about it) */
    double r_in[2] = {INFINITY, INFINITY};
    for (int b = 0; b < 2; b++)
        for (size_t t = 0; t < m.nt; t++) {
            double n[3];
            const double off = dm_test_mesh_plane(&m, t, n);
            if (face_of(&m, t, want[b]))
                r_in[b] = fmin(r_in[b], off - (n[0] * want[b][0] + n[1] * want[b][1] +
                                               n[2] * want[b][2]));
        }
    double c[6], r[2];
    dm_fit_report rep;
    char err[256];
    ck_assert_int_eq(fit(&m, 2, CELLS, c, r, &rep, err), DEMILL_OK);
    ck_assert_uint_eq(rep.n, 2);
    const double h = 2.0 * (D + R0) / CELLS;
    for (int b = 0; b < 2; b++) {
        const int k = (c[2] > P0[2]) == (b == 0) ? 0 : 1; /* the ball in bulb b */
        printf("dumbbell, N = 2: bulb %d: |c - c_b| = %.3g h, r - r_in = %.3g h "
               "(r_in = %.6g R, h = %.4g R)\n",
               b, dm_test_dist3(c + 3 * k, want[b]) / h, (r[k] - r_in[b]) / h, r_in[b] / R0, h / R0);
        ck_assert(dm_test_dist3(c + 3 * k, want[b]) <= 0.1 * h);
        double below = INFINITY; /* inscribed: r at most the fit's centre's depth */
        for (size_t t = 0; t < m.nt; t++) {
            double n[3];
            const double off = dm_test_mesh_plane(&m, t, n);
            if (face_of(&m, t, want[b]))
                below = fmin(below, off - (n[0] * c[3 * k] + n[1] * c[3 * k + 1] +
                                           n[2] * c[3 * k + 2]));
        }
        ck_assert(r[k] <= below * (1.0 + 1e-12));
        ck_assert(r[k] >= r_in[b] - 0.1 * h);
    }
    dm_mass_props exact;
    ck_assert_int_eq(dm_spheres_union_mass(2, c, r, 1.0, &exact, NULL), DEMILL_OK);
    printf("  union volume %.9g, exact %.9g, resolution error %.2g of the mesh's\n",
           rep.union_volume, exact.mass, rep.volume_error_tol);
    ck_assert(fabs(rep.union_volume - exact.mass) <= rep.volume_error_tol * rep.volume);
    dm_test_mesh_free(&m);
}
END_TEST

/* Whether x is inside the convex mesh of the planes pl (as dm_test_mesh_planes() gives
 * them, nt of them). */
typedef struct convex {
    const double *pl;
    size_t nt;
} convex;

static int in_convex(const void *ctx, const double *x)
{
    const convex *cv = ctx;
    return dm_test_convex_depth(cv->pl, cv->nt, x) > 0.0;
}

/* Fits N = 5, 20, 50 spheres to the mesh m and checks that the volume error
 * falls and agrees with a Monte Carlo estimate, the points' inside told by
 * inside(ctx, x). */
static void falls(const char *name, const mesh *m, int (*inside)(const void *, const double *),
                  const void *ctx)
{
    static const size_t ns[3] = {5, 20, 50};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < m->nv; k++)
        for (int a = 0; a < 3; a++)
            lo[a] = fmin(lo[a], m->v[3 * k + a]), hi[a] = fmax(hi[a], m->v[3 * k + a]);
    enum { POINTS = 200000 };
    double *x = malloc(3 * POINTS * sizeof *x);
    char *in = malloc(POINTS);
    dm_rng rng;
    dm_rng_seed(&rng, 17);
    long in_mesh = 0;
    for (int k = 0; k < POINTS; k++) {
        for (int a = 0; a < 3; a++)
            x[3 * k + a] = lo[a] + (hi[a] - lo[a]) * dm_rng_uniform(&rng);
        in[k] = (char)inside(ctx, x + 3 * k);
        in_mesh += in[k];
    }
    double last = 1.0;
    for (int q = 0; q < 3; q++) {
        double c[150], r[50];
        dm_fit_report rep;
        char err[256];
        ck_assert_int_eq(fit(m, ns[q], CELLS, c, r, &rep, err), DEMILL_OK);
        ck_assert_uint_eq(rep.n, ns[q]);
        long missed = 0, outside = 0;
        for (int k = 0; k < POINTS; k++) {
            int in_union = 0;
            for (size_t b = 0; b < rep.n && !in_union; b++)
                in_union = dm_test_dist3(x + 3 * k, c + 3 * b) < r[b];
            missed += in[k] && !in_union;
            outside += in_union && !in[k];
        }
        const double p = (double)missed / in_mesh, se = sqrt(p * (1.0 - p) / in_mesh);
        printf("%s, N = %zu: volume error %.4f (Monte Carlo %.4f +- %.4f, resolution %.1e), "
               "deviations out %.3f, in %.3f of the size\n",
               name, ns[q], rep.volume_error, p, se, rep.volume_error_tol,
               rep.deviation_out / rep.size, rep.deviation_in / rep.size);
        ck_assert_int_eq(outside, 0);
        ck_assert(fabs(rep.volume_error - p) <= 4.0 * se + rep.volume_error_tol);
        ck_assert(rep.volume_error < last);
        last = rep.volume_error;
    }
    free(x);
    free(in);
}

START_TEST(test_ellipsoid)
{
    const double s[3] = {R0, 0.7 * R0, 0.5 * R0};
    mesh m = dm_test_icosphere(3, s, P0);
    const convex cv = {dm_test_mesh_planes(&m), m.nt};
    falls("ellipsoid", &m, in_convex, &cv);
    free((void *)cv.pl);
    dm_test_mesh_free(&m);
}
END_TEST

START_TEST(test_box)
{
    const double lo[3] = {P0[0] - 0.7 * R0, P0[1] - 0.7 * R0, P0[2] - 0.5 * R0},
                 hi[3] = {P0[0] + 0.7 * R0, P0[1] + 0.7 * R0, P0[2] + 0.5 * R0};
    mesh m = box(lo, hi);
    const convex cv = {dm_test_mesh_planes(&m), m.nt};
    falls("box", &m, in_convex, &cv);
    free((void *)cv.pl);
    dm_test_mesh_free(&m);
}
END_TEST

/* A tripod of seven cubes of side TRIPOD from P0: one at the corner and
 * two along each axis from it. */
#define TRIPOD (0.4 * R0)
static const int LEGS[7][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0},
                               {0, 2, 0}, {0, 0, 1}, {0, 0, 2}};

static int tripod_has(int i, int j, int k)
{
    for (int c = 0; c < 7; c++)
        if (LEGS[c][0] == i && LEGS[c][1] == j && LEGS[c][2] == k)
            return 1;
    return 0;
}

static int in_tripod(const void *ctx, const double *x)
{
    (void)ctx;
    return tripod_has((int)floor((x[0] - P0[0]) / TRIPOD), (int)floor((x[1] - P0[1]) / TRIPOD),
                      (int)floor((x[2] - P0[2]) / TRIPOD));
}

/* The tripod's surface: every face of a cube whose neighbour across it is
 * not in the tripod, two triangles wound outwards as box() winds them. */
static mesh tripod(void)
{
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    static const int across[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0},
                                     {0, 1, 0},  {-1, 0, 0}, {1, 0, 0}};
    mesh m = {0};
    for (int c = 0; c < 7; c++)
        for (int f = 0; f < 6; f++) {
            const int *l = LEGS[c];
            if (tripod_has(l[0] + across[f][0], l[1] + across[f][1], l[2] + across[f][2]))
                continue;
            uint32_t v[4];
            for (int k = 0; k < 4; k++) {
                const int corner = q[f][k];
                const double x[3] = {P0[0] + TRIPOD * (l[0] + (corner & 1)),
                                     P0[1] + TRIPOD * (l[1] + (corner >> 1 & 1)),
                                     P0[2] + TRIPOD * (l[2] + (corner >> 2 & 1))};
                v[k] = dm_test_mesh_vertex(&m, x);
            }
            dm_test_mesh_triangle(&m, v[0], v[1], v[2]);
            dm_test_mesh_triangle(&m, v[0], v[2], v[3]);
        }
    return m;
}

START_TEST(test_tripod)
{
    mesh m = tripod();
    ck_assert_uint_eq(m.nt, 2 * (7 * 6 - 2 * 6)); /* 6 shared faces hidden on both sides */
    DM_ASSERT_REL(dm_test_mesh_volume(&m, P0), 7.0 * TRIPOD * TRIPOD * TRIPOD, 1e-12);
    falls("tripod", &m, in_tripod, NULL);
    dm_test_mesh_free(&m);
}
END_TEST

/* A regular octahedron with corners at +-a on the axes (8 triangles). */
static mesh octahedron(double a)
{
    mesh m = {0};
    const double p[6][3] = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
    for (int k = 0; k < 6; k++)
        dm_test_mesh_vertex(&m, p[k]);
    static const int f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int k = 0; k < 8; k++)
        dm_test_mesh_triangle(&m, f[k][0], f[k][1], f[k][2]);
    return m;
}

START_TEST(test_grid_lines_on_edges)
{
    double c[3], r;
    dm_fit_report rep;
    char err[256];
    /* the octahedron |x| + |y| + |z| <= 32.5 on 65 cubes of side 1: the
     * cube centres are the integer points, exactly, and the lines along z
     * through them pass through its corners and along its edges' shadows */
    mesh m = octahedron(32.5);
    ck_assert_int_eq(fit(&m, 1, 65, c, &r, &rep, err), DEMILL_OK);
    ck_assert(rep.h == 1.0 && rep.cells[0] == 65 && rep.cells[2] == 65);
    size_t want = 0;
    for (int i = -32; i <= 32; i++)
        for (int j = -32; j <= 32; j++)
            for (int k = -32; k <= 32; k++)
                want += abs(i) + abs(j) + abs(k) <= 32;
    printf("octahedron: %zu centres inside (%zu wanted), r = %.17g (a/sqrt(3) = %.17g)\n",
           rep.inside, want, r, 32.5 / sqrt(3.0));
    ck_assert_uint_eq(rep.inside, want);
    /* its largest inscribed ball: centred, of radius a/sqrt(3) */
    ck_assert(fabs(r - 32.5 / sqrt(3.0)) <= 1e-4 * rep.h && dm_test_dist3(c, (double[3]){0}) <= 1e-4 * rep.h);
    dm_test_mesh_free(&m);
    /* the unit cube on 64 cubes: the lines run along its faces' diagonals */
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, mid[3] = {0.5, 0.5, 0.5};
    m = box(lo, hi);
    ck_assert_int_eq(fit(&m, 1, 64, c, &r, &rep, err), DEMILL_OK);
    ck_assert_uint_eq(rep.inside, 64 * 64 * 64);
    printf("cube: r = %.17g, volume error %.9f (1 - pi/6 = %.9f)\n", r, rep.volume_error,
           1.0 - M_PI / 6.0);
    ck_assert(fabs(r - 0.5) <= 1e-4 * rep.h && dm_test_dist3(c, mid) <= 1e-4 * rep.h);
    ck_assert(fabs(rep.volume_error - (1.0 - 4.0 / 3.0 * M_PI * r * r * r)) <=
              rep.volume_error_tol);
    dm_test_mesh_free(&m);
}
END_TEST

START_TEST(test_deterministic)
{
    const double s[3] = {R0, 0.7 * R0, 0.5 * R0};
    mesh m = dm_test_icosphere(2, s, P0);
    double c[2][60], r[2][20];
    dm_fit_report rep[2];
    char err[256];
    for (int k = 0; k < 2; k++)
        ck_assert_int_eq(fit(&m, 20, 32, c[k], r[k], &rep[k], err), DEMILL_OK);
    ck_assert(!memcmp(c[0], c[1], sizeof c[0]) && !memcmp(r[0], r[1], sizeof r[0]));
    ck_assert(rep[0].n == rep[1].n && rep[0].union_volume == rep[1].union_volume &&
              rep[0].deviation_out == rep[1].deviation_out &&
              rep[0].deviation_in == rep[1].deviation_in);
    dm_test_mesh_free(&m);
}
END_TEST

/* Asserts that fitting m fails with code and a message holding `says`, and
 * writes nothing. */
static void refused(const mesh *m, size_t n, int cells, demill_status code, const char *says)
{
    double c[6], r[2], c0[6], r0[2];
    dm_fit_report rep, rep0;
    char err[256];
    memset(c, 0x5a, sizeof c), memset(r, 0x5a, sizeof r), memset(&rep, 0x5a, sizeof rep);
    memcpy(c0, c, sizeof c), memcpy(r0, r, sizeof r), memcpy(&rep0, &rep, sizeof rep);
    const demill_status st = fit(m, n, cells, c, r, &rep, err);
    ck_assert_msg(st == code, "%s: got %d (%s), wanted %d", says, (int)st, err, (int)code);
    ck_assert_msg(strstr(err, says), "'%s' does not say '%s'", err, says);
    ck_assert(!memcmp(c, c0, sizeof c) && !memcmp(r, r0, sizeof r));
    ck_assert(!memcmp(&rep, &rep0, sizeof rep));
}

START_TEST(test_refused)
{
    const double s[3] = {R0, R0, R0};
    mesh m = dm_test_icosphere(1, s, P0);
    refused(&m, 0, CELLS, DEMILL_ERR_INVALID_VALUE, "no spheres");
    refused(&m, 1, 3, DEMILL_ERR_INVALID_VALUE, "cells");
    m.nt--; /* the last triangle removed */
    refused(&m, 1, CELLS, DEMILL_ERR_INVALID_VALUE, "not closed");
    m.nt++;
    uint32_t *t = m.t + 3 * 7, keep;
    const uint32_t t1 = t[1];
    for (int way = 0; way < 3; way++) /* triangle 7 flipped, then the others, then all back */
        for (size_t k = 0; k < m.nt; k++)
            if ((way == 0) == (k == 7) || way == 2) {
                keep = m.t[3 * k + 1], m.t[3 * k + 1] = m.t[3 * k + 2], m.t[3 * k + 2] = keep;
                if (way == 0)
                    refused(&m, 1, CELLS, DEMILL_ERR_INVALID_VALUE, "not consistently oriented");
                else if (way == 1 && k == m.nt - 1)
                    refused(&m, 1, CELLS, DEMILL_ERR_INVALID_VALUE, "inside out");
            }
    t[1] = t[0];
    refused(&m, 1, CELLS, DEMILL_ERR_INVALID_VALUE, "zero area");
    t[1] = (uint32_t)m.nv;
    refused(&m, 1, CELLS, DEMILL_ERR_INVALID_VALUE, "vertices");
    t[1] = t1;
    const double x = m.v[4];
    m.v[4] = NAN;
    refused(&m, 1, CELLS, DEMILL_ERR_NOT_FINITE, "NaN");
    m.v[4] = x;
    double c[3], r;
    dm_fit_report rep;
    char err[256];
    ck_assert_int_eq(dm_spheres_fit_mesh(m.nv, NULL, m.nt, m.t, 1, CELLS, c, &r, &rep, NULL, 0),
                     DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(fit(&m, 1, CELLS, c, &r, &rep, err), DEMILL_OK);
    ck_assert_str_eq(err, "");
    dm_test_mesh_free(&m);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("shapes_fit");
    TCase *tc = tcase_create("shapes_fit");
    tcase_add_test(tc, test_sphere_one);
    tcase_add_test(tc, test_dumbbell);
    tcase_add_test(tc, test_ellipsoid);
    tcase_add_test(tc, test_box);
    tcase_add_test(tc, test_tripod);
    tcase_add_test(tc, test_grid_lines_on_edges);
    tcase_add_test(tc, test_deterministic);
    tcase_add_test(tc, test_refused);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
