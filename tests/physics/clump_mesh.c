/* clump_mesh.c: clump templates made from a closed triangle mesh
 * (demill_clump_template_from_mesh(), demill_clump_template_from_stl()),
 * against numbers derived here another way.
 *
 * What this suite proves:
 *  - A sphere of radius R tessellated as an icosphere (1280 triangles) and
 *    filled with one sphere gives the template of the polytope's largest
 *    inscribed ball. The icosphere is convex and symmetric under the
 *    icosahedral group, so that ball is centred at the sphere's centre, of
 *    radius r_in, the least distance from the centre to a face's plane
 *    (computed here), R - r_in the tessellation error. The template's mass
 *    is rho (4/3) pi r³ of its sphere's radius r to round-off, r within a
 *    tenth of the tessellation error below r_in (the fit places its ball to
 *    about 1e-4 of a grid cube, a hundred times closer at this grid), so
 *    the mass is the inscribed sphere's, rho (4/3) pi R³, to within
 *    3 (R - r_in) / R; its centre of mass is the sphere's centre, its three
 *    principal moments (2/5) m r². The fit it keeps: the mesh's volume
 *    against tetrahedra from the centre, the volume error
 *    1 - (4/3) pi r³ / V, and the largest distance from the mesh's surface
 *    to the ball, that of the farthest corner |v - c| - r (a convex
 *    function is largest over a polytope at a corner, and the fit's sample
 *    holds the corners), each to 1e-12; the grid's cube, the bounding
 *    box's longest side over `cells`.
 *  - An ellipsoid (semi-axes 10, 7 and 5 mm, the icosphere scaled) filled
 *    with N = 5, 10, 20 and 40 spheres: the volume error falls with N and
 *    the template's mass rises towards rho V, V = (4/3) pi a b c, staying
 *    below rho times the mesh's volume (the polytope lies inside the
 *    ellipsoid, and the spheres inside the polytope). Each sphere, read
 *    back with demill_clump_template_spheres() and taken to the mesh's
 *    frame by the template's centre and axes, touches the surface from
 *    inside: its radius is its centre's least distance to the faces'
 *    planes (the distance to a convex polytope's surface from inside), to
 *    1e-12 of R. The same spheres given to demill_clump_template_add() make
 *    a template of the same mass and principal moments to 1e-12: a mesh
 *    template's mass properties are its union's, as any template's.
 *  - An STL file, ASCII and binary, of a mesh whose coordinates are
 *    floats (so that both formats hold them exactly) gives bitwise the
 *    template the arrays give: every field and every sphere.
 *  - An open mesh (one triangle taken away), as arrays and as an STL file,
 *    is refused with DEMILL_ERR_INVALID_VALUE, the message saying that the
 *    mesh is not closed (and naming the file), and no template is made.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "meshes.h"
#include "stl_write.h"
#include "testutil.h"

static const double R0 = 0.01;                 /* m */
static const double P0[3] = {0.3, -0.2, 0.15}; /* shapes placed away from the origin */
static const double RHO = 2700.0;              /* kg/m³ */
#define CELLS 48

/* A 3D world whose material has density RHO, in *mat. */
static demill_world *world(demill_id *mat)
{
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, mat);
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, RHO));
    return w;
}

static double field(demill_world *w, demill_id t, int32_t f)
{
    double v[9];
    DM_OK(w, demill_clump_template_get(w, t, f, v));
    return v[0];
}

/* The template's n spheres in the frame it was made in: x = c + Σ b_i a_i
 * (c its centre of mass, a_i its principal axes, b the body-frame centre),
 * into x (3 n doubles) and r. */
static size_t spheres_in_frame(demill_world *w, demill_id t, double *x, double *r, size_t cap)
{
    size_t n;
    DM_OK(w, demill_clump_template_spheres(w, t, NULL, NULL, 0, &n));
    ck_assert_uint_le(n, cap);
    double *b = malloc(3 * n * sizeof *b), c[3], a[9];
    ck_assert_ptr_nonnull(b);
    DM_OK(w, demill_clump_template_spheres(w, t, b, r, n, &n));
    DM_OK(w, demill_clump_template_get(w, t, DEMILL_TEMPLATE_CENTRE, c));
    DM_OK(w, demill_clump_template_get(w, t, DEMILL_TEMPLATE_PRINCIPAL_AXES, a));
    for (size_t k = 0; k < n; k++)
        for (int j = 0; j < 3; j++)
            x[3 * k + j] = c[j] + b[3 * k] * a[j] + b[3 * k + 1] * a[3 + j] +
                           b[3 * k + 2] * a[6 + j];
    free(b);
    return n;
}

START_TEST(test_sphere_one)
{
    const double s[3] = {R0, R0, R0};
    dm_test_mesh m = dm_test_icosphere(3, s, P0);
    ck_assert_uint_eq(m.nt, 1280);
    double *pl = dm_test_mesh_planes(&m);
    const double r_in = dm_test_convex_depth(pl, m.nt, P0), tess = R0 - r_in;
    demill_id mat, t;
    demill_world *w = world(&mat);
    DM_OK(w, demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 1, CELLS, &t));
    ck_assert_double_eq(field(w, t, DEMILL_TEMPLATE_COUNT), 1.0);
    double c[3], r;
    spheres_in_frame(w, t, c, &r, 1);
    const double mass = field(w, t, DEMILL_TEMPLATE_MASS), ball = 4.0 / 3.0 * M_PI * RHO;
    printf("sphere, N = 1: r_in = %.9g m, tessellation error %.3g of R; r - r_in = %.3g of R; "
           "mass %.9g kg, %.3g of the inscribed sphere's from it (3 (R - r_in) / R = %.3g)\n",
           r_in, tess / R0, (r - r_in) / R0, mass, mass / (ball * R0 * R0 * R0) - 1.0,
           3.0 * tess / R0);
    ck_assert(r <= r_in * (1.0 + 1e-12) && r >= r_in - 0.1 * tess);
    DM_ASSERT_REL(mass, ball * r * r * r, 1e-12);
    ck_assert(fabs(mass - ball * R0 * R0 * R0) <= 3.0 * tess / R0 * ball * R0 * R0 * R0);
    double com[3], mom[3];
    DM_OK(w, demill_clump_template_get(w, t, DEMILL_TEMPLATE_CENTRE, com));
    DM_OK(w, demill_clump_template_get(w, t, DEMILL_TEMPLATE_PRINCIPAL_MOMENTS, mom));
    ck_assert(dm_test_dist3(com, P0) <= 0.1 * tess);
    for (int a = 0; a < 3; a++)
        DM_ASSERT_REL(mom[a], 0.4 * mass * r * r, 1e-12);
    /* the fit */
    const double v = dm_test_mesh_volume(&m, P0);
    double far = 0.0, lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < m.nv; k++) {
        far = fmax(far, dm_test_dist3(m.v + 3 * k, c) - r);
        for (int a = 0; a < 3; a++)
            lo = fmin(lo, m.v[3 * k + a] - P0[a]), hi = fmax(hi, m.v[3 * k + a] - P0[a]);
    }
    const double err = field(w, t, DEMILL_TEMPLATE_FIT_VOLUME_ERROR);
    printf("  mesh volume %.9g m^3 (tetrahedra %.9g), volume error %.9g (1 - ball / V = %.9g), "
           "deviations out %.4g (corners %.4g), in %.4g of R\n",
           field(w, t, DEMILL_TEMPLATE_MESH_VOLUME), v, err,
           1.0 - 4.0 / 3.0 * M_PI * r * r * r / v,
           field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_OUT) / R0, far / R0,
           field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_IN) / R0);
    DM_ASSERT_REL(field(w, t, DEMILL_TEMPLATE_MESH_VOLUME), v, 1e-12);
    ck_assert(fabs(err - (1.0 - 4.0 / 3.0 * M_PI * r * r * r / v)) <= 1e-12);
    DM_ASSERT_REL(field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_OUT), far, 1e-12);
    DM_ASSERT_REL(field(w, t, DEMILL_TEMPLATE_FIT_CELL), (hi - lo) / CELLS, 1e-12);
    /* from the ball to the mesh: at most the tessellation error */
    ck_assert(field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_IN) <= tess);
    free(pl);
    dm_test_mesh_free(&m);
    demill_world_destroy(w);
}
END_TEST

START_TEST(test_ellipsoid)
{
    const double s[3] = {R0, 0.7 * R0, 0.5 * R0};
    dm_test_mesh m = dm_test_icosphere(3, s, P0);
    double *pl = dm_test_mesh_planes(&m);
    const double v_ell = 4.0 / 3.0 * M_PI * s[0] * s[1] * s[2], v_mesh = dm_test_mesh_volume(&m, P0);
    printf("ellipsoid: V = %.9g m^3, the mesh's %.9g (%.4f of V)\n", v_ell, v_mesh,
           v_mesh / v_ell);
    demill_id mat;
    demill_world *w = world(&mat);
    static const size_t ns[4] = {5, 10, 20, 40};
    double last_err = 1.0, last_mass = 0.0;
    for (int q = 0; q < 4; q++) {
        demill_id t, again;
        DM_OK(w, demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, ns[q], CELLS, &t));
        double x[3 * 40], r[40];
        const size_t n = spheres_in_frame(w, t, x, r, 40);
        ck_assert_uint_eq(n, ns[q]);
        double gap = 0.0; /* the largest |r - depth| */
        for (size_t k = 0; k < n; k++)
            gap = fmax(gap, fabs(r[k] - dm_test_convex_depth(pl, m.nt, x + 3 * k)));
        const double mass = field(w, t, DEMILL_TEMPLATE_MASS);
        const double err = field(w, t, DEMILL_TEMPLATE_FIT_VOLUME_ERROR);
        printf("  N = %2zu: volume error %.4f, mass %.5f of rho V, deviations out %.3f, in "
               "%.3f of a; |r - depth| <= %.2g of a\n",
               n, err, mass / (RHO * v_ell), field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_OUT) / R0,
               field(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_IN) / R0, gap / R0);
        ck_assert(gap <= 1e-12 * R0);
        ck_assert(err < last_err && mass > last_mass);
        ck_assert(mass < RHO * v_mesh && v_mesh < v_ell);
        DM_ASSERT_REL(field(w, t, DEMILL_TEMPLATE_MESH_VOLUME), v_mesh, 1e-12);
        /* the same spheres as a template of spheres */
        DM_OK(w, demill_clump_template_add(w, mat, n, x, r, &again));
        double m1[3], m2[3];
        DM_OK(w, demill_clump_template_get(w, t, DEMILL_TEMPLATE_PRINCIPAL_MOMENTS, m1));
        DM_OK(w, demill_clump_template_get(w, again, DEMILL_TEMPLATE_PRINCIPAL_MOMENTS, m2));
        DM_ASSERT_REL(field(w, again, DEMILL_TEMPLATE_MASS), mass, 1e-12);
        for (int a = 0; a < 3; a++)
            DM_ASSERT_REL(m2[a], m1[a], 1e-12);
        last_err = err;
        last_mass = mass;
    }
    free(pl);
    dm_test_mesh_free(&m);
    demill_world_destroy(w);
}
END_TEST

/* Asserts that templates a and b of world w are bitwise the same: every
 * field and every sphere. */
static void same_template(demill_world *w, demill_id a, demill_id b, const char *what)
{
    for (int32_t f = DEMILL_TEMPLATE_MASS; f <= DEMILL_TEMPLATE_FIT_CELL; f++) {
        double x[9], y[9];
        const int size = demill_clump_template_field_size(f);
        DM_OK(w, demill_clump_template_get(w, a, f, x));
        DM_OK(w, demill_clump_template_get(w, b, f, y));
        ck_assert_msg(!memcmp(x, y, (size_t)size * sizeof *x), "%s: template field %d differs",
                      what, (int)f);
    }
    size_t n, nb;
    DM_OK(w, demill_clump_template_spheres(w, a, NULL, NULL, 0, &n));
    DM_OK(w, demill_clump_template_spheres(w, b, NULL, NULL, 0, &nb));
    ck_assert_uint_eq(n, nb);
    double *c = malloc(8 * n * sizeof *c);
    ck_assert_ptr_nonnull(c);
    DM_OK(w, demill_clump_template_spheres(w, a, c, c + 3 * n, n, &n));
    DM_OK(w, demill_clump_template_spheres(w, b, c + 4 * n, c + 7 * n, n, &n));
    ck_assert_msg(!memcmp(c, c + 4 * n, 4 * n * sizeof *c), "%s: the spheres differ", what);
    free(c);
}

START_TEST(test_stl_same)
{
    const double s[3] = {R0, 0.8 * R0, 0.6 * R0};
    dm_test_mesh m = dm_test_icosphere(2, s, P0);
    for (size_t k = 0; k < 3 * m.nv; k++) /* floats, which binary STL holds exactly */
        m.v[k] = (float)m.v[k];
    double *corners = dm_test_mesh_corners(&m);
    size_t na, nb;
    uint8_t *ascii = dm_test_stl_ascii("ellipsoid", corners, m.nt, NULL, &na);
    uint8_t *binary = dm_test_stl_binary("ellipsoid", corners, m.nt, NULL, &nb);
    char *pa = dm_test_temp_file("ascii.stl", ascii, na),
         *pb = dm_test_temp_file("binary.stl", binary, nb);
    demill_id mat, t, ta, tb;
    demill_world *w = world(&mat);
    DM_OK(w, demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 12, 32, &t));
    DM_OK(w, demill_clump_template_from_stl(w, mat, pa, 1.0, 12, 32, &ta));
    DM_OK(w, demill_clump_template_from_stl(w, mat, pb, 1.0, 12, 32, &tb));
    same_template(w, t, ta, "ASCII STL");
    same_template(w, t, tb, "binary STL");
    printf("STL: 320 triangles, 12 spheres: mass %.9g kg from the arrays, an ASCII and a binary "
           "STL file, bitwise\n",
           field(w, t, DEMILL_TEMPLATE_MASS));
    remove(pa);
    remove(pb);
    free(pa);
    free(pb);
    free(ascii);
    free(binary);
    free(corners);
    dm_test_mesh_free(&m);
    demill_world_destroy(w);
}
END_TEST

START_TEST(test_open_refused)
{
    const double s[3] = {R0, R0, R0};
    dm_test_mesh m = dm_test_icosphere(1, s, P0);
    m.nt--; /* a hole */
    double *corners = dm_test_mesh_corners(&m);
    size_t size;
    uint8_t *ascii = dm_test_stl_ascii("open", corners, m.nt, NULL, &size);
    char *path = dm_test_temp_file("open.stl", ascii, size);
    demill_id mat, t = 42;
    demill_world *w = world(&mat);
    ck_assert_int_eq(demill_clump_template_from_mesh(w, mat, m.nv, m.v, m.nt, m.t, 5, 16, &t),
                     DEMILL_ERR_INVALID_VALUE);
    printf("open mesh: %s\n", demill_world_last_error(w));
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "not closed"));
    ck_assert_int_eq(demill_clump_template_from_stl(w, mat, path, 1.0, 5, 16, &t),
                     DEMILL_ERR_INVALID_VALUE);
    printf("open STL: %s\n", demill_world_last_error(w));
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "not closed"));
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), path));
    size_t n = 1;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_TEMPLATE, NULL, 0, &n));
    ck_assert_uint_eq(n, 0);
    ck_assert_uint_eq(t, 42);
    remove(path);
    free(path);
    free(ascii);
    free(corners);
    dm_test_mesh_free(&m);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("physics_clump_mesh");
    TCase *tc = tcase_create("clump_mesh");
    tcase_add_test(tc, test_sphere_one);
    tcase_add_test(tc, test_ellipsoid);
    tcase_add_test(tc, test_stl_same);
    tcase_add_test(tc, test_open_refused);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
