/* mesh.c: triangle-mesh walls (3D) and polyline walls (2D) (docs/geometry.md,
 * Triangle meshes and polylines).
 *
 * - A flat triangulated floor is the plane y = 0: a sphere pressed onto it,
 *   bouncing off it (restitution 0.5) and sliding on it with a spring-slider
 *   tangential law (whose history must follow the sphere from triangle to
 *   triangle) feels at every step the force it feels on the analytic plane,
 *   within a relative 1e-12, starting above a vertex shared by six
 *   triangles, above an edge and inside a face; with velocity Verlet and
 *   with the iterative refinement. The same for a polyline against a 2D plane.
 * - A sphere rolling without slip across that floor keeps its speed: no
 *   tangential force acts on a ball rolling at its lever arm's speed
 *   (v = ω (r - δ/2) at the equilibrium overlap δ = m g / k), so any change
 *   is the mesh's: at most 1e-9 m/s per edge crossed.
 * - Contacts with a convex ridge and a convex apex point from the nearest
 *   point of the edge or vertex to the centre, with overlap r - distance
 *   (hand-derived numbers), in 3D and 2D; a concave corner of two faces gives
 *   two contacts, one per face.
 * - One triangle 2 m across under 5 mm balls and a floor of triangles smaller
 *   than the balls both carry the balls' weight N m g at rest, and the list of
 *   candidates holds only the triangles within reach of each ball.
 * - A checkpoint and a snapshot of a scene with a moving mesh reproduce the
 *   run bitwise; 1 and 2 threads give the same bits.
 */
#include <stdlib.h>
#include <string.h>

#include "physics/state/state.h"
#include "testutil.h"

#define R 0.01   /* ball radius, m */
#define H 0.01   /* floor cell, m */
#define CELLS 10 /* floor cells along x and z, from -0.05 m */
#define K 1e5    /* linear normal stiffness, N/m */

/* A world with gravity, the given integrator and one material whose pair
 * has a linear spring with restitution damping and a spring-slider. */
static demill_world *floor_world(int dim, int refine, demill_id *mat)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-5));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                              refine ? DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT
                                     : DEMILL_INTEGRATOR_VELOCITY_VERLET));
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_FRICTION, 0.3));
    return w;
}

/* The floor y = 0 as a plane (mesh 0) or as the triangulated grid (3D) or
 * a polyline of CELLS segments (2D). */
static void add_floor(demill_world *w, int dim, demill_id mat, int mesh)
{
    demill_id id;
    if (!mesh) {
        const double p[3] = {0, 0, 0}, n[3] = {0, 1, 0};
        DM_OK(w, demill_wall_add_plane(w, mat, p, n, &id));
        return;
    }
    if (dim == 2) {
        double pts[3 * (CELLS + 1)] = {0};
        for (int i = 0; i <= CELLS; i++)
            pts[3 * i] = -0.05 + i * H;
        DM_OK(w, demill_wall_add_polyline(w, mat, CELLS + 1, pts, 0, &id));
        return;
    }
    double v[3 * (CELLS + 1) * (CELLS + 1)];
    uint32_t t[6 * CELLS * CELLS];
    dm_test_floor_grid(CELLS, H, -0.05, v, t);
    DM_OK(w, demill_wall_add_mesh(w, mat, (CELLS + 1) * (CELLS + 1), v, 2 * CELLS * CELLS, t, &id));
}

static double norm3(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* Starts of the floor runs: above the vertex at the origin (six triangles in
 * 3D, two segments in 2D), above the middle of an edge, inside a face. */
static const double starts[3][2] = {{0.0, 0.0}, {0.5 * H, 0.0}, {0.3 * H, 0.7 * H}};

/* The ball dropped from 0.5 mm above the floor with a sideways velocity, on
 * the plane and on the mesh side by side: force and torque at every step. */
static void floor_run(int dim, int refine, int start)
{
    demill_world *w[2];
    demill_id mat[2], ball[2];
    for (int m = 0; m < 2; m++) {
        w[m] = floor_world(dim, refine, &mat[m]);
        add_floor(w[m], dim, mat[m], m);
        const double x[3] = {starts[start][0], R + 5e-4, dim == 3 ? starts[start][1] : 0.0};
        const double r = R, v[3] = {0.3, -0.4, dim == 3 ? 0.2 : 0.0};
        DM_OK(w[m], demill_particles_add(w[m], mat[m], 1, x, &r, v, 0, &ball[m]));
    }
    double fbig = 0.0;
    for (int step = 0; step < 20000; step++) {
        double f[2][3], t[2][3];
        for (int m = 0; m < 2; m++) {
            DM_OK(w[m], demill_world_step(w[m], 1));
            DM_OK(w[m], demill_particle_get(w[m], ball[m], DEMILL_PARTICLE_FORCE, f[m]));
            DM_OK(w[m], demill_particle_get(w[m], ball[m], DEMILL_PARTICLE_TORQUE, t[m]));
        }
        const double df[3] = {f[1][0] - f[0][0], f[1][1] - f[0][1], f[1][2] - f[0][2]};
        const double dt[3] = {t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
        const double rel = norm3(df) / norm3(f[0]);
        ck_assert_msg(rel <= 1e-12 && norm3(dt) <= 1e-12 * R * norm3(f[0]),
                      "dim %d, integrator %d, start %d, step %d: force (%.17g, %.17g, %.17g) "
                      "on the mesh, (%.17g, %.17g, %.17g) on the plane",
                      dim, refine, start, step, f[1][0], f[1][1], f[1][2], f[0][0], f[0][1],
                      f[0][2]);
        fbig = fmax(fbig, norm3(f[0]));
    }
    /* the ball did press, bounce and slide: the floor pushed harder than its weight */
    double m;
    DM_OK(w[0], demill_particle_get(w[0], ball[0], DEMILL_PARTICLE_MASS, &m));
    ck_assert_msg(fbig > 10.0 * m * 9.81, "the ball never hit the floor (%g N)", fbig);
    for (int k = 0; k < 2; k++)
        demill_world_destroy(w[k]);
}

START_TEST(floor_as_plane)
{
    const int dim = 2 + _i / 6, refine = _i / 3 % 2, start = _i % 3;
    floor_run(dim, refine, start);
}
END_TEST

/* A ball rolling without slip across the floor, diagonally through cells,
 * edges and vertices' neighbourhoods: its speed stays v0 within 1e-9 m/s
 * per edge crossed. */
START_TEST(rolling_keeps_speed)
{
    const int dim = 2 + _i;
    demill_id mat, ball;
    demill_world *w = floor_world(dim, 0, &mat);
    add_floor(w, dim, mat, 1);
    const double r = R, v0 = 0.5;
    double x[3] = {-0.04, R, dim == 3 ? -0.037 : 0.0};
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    double m;
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_MASS, &m));
    const double delta = m * 9.81 / K, arm = R - 0.5 * delta;
    x[1] = R - delta; /* at rest on the spring */
    const double dir[3] = {dim == 3 ? 0.8 : 1.0, 0.0, dim == 3 ? 0.6 : 0.0};
    const double v[3] = {v0 * dir[0], 0.0, v0 * dir[2]};
    /* ω × (-arm ŷ) = -v: ω = (v_z, 0, -v_x) / arm */
    const double om[3] = {dim == 3 ? v[2] / arm : 0.0, 0.0, -v[0] / arm};
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_POSITION, x));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_VELOCITY, v));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, om));
    const int steps = 14000; /* 7 cm */
    double worst = 0.0, p[3];
    for (int s = 0; s < steps; s++) {
        DM_OK(w, demill_world_step(w, 1));
        double u[3];
        DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_VELOCITY, u));
        worst = fmax(worst, fabs(norm3(u) - v0));
    }
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, p));
    /* edges crossed: grid lines along x and z, and (3D) the diagonals x - z = const */
    double crossed = floor((p[0] + 0.05) / H) - floor((x[0] + 0.05) / H);
    if (dim == 3)
        crossed += floor((p[2] + 0.05) / H) - floor((x[2] + 0.05) / H) +
                   fabs(floor((p[0] - p[2]) / H) - floor((x[0] - x[2]) / H));
    ck_assert_msg(crossed >= 6, "only %g edges crossed", crossed);
    ck_assert_msg(worst <= 1e-9 * crossed, "speed changed by %g m/s over %g edges", worst,
                  crossed);
    demill_world_destroy(w);
}
END_TEST

/* Every contact of the world: count, overlaps and normal forces (on the
 * particle) into the arrays (room for 4). */
static size_t contacts(demill_world *w, double *overlap, double *fn)
{
    size_t n;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &n));
    ck_assert_uint_le(n, 4);
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, overlap, 4, &n));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, fn, 4, &n));
    return n;
}

/* A world without gravity, linear undamped contacts of stiffness K, a ball
 * at x at rest and the mesh or polyline given. */
static demill_world *static_scene(int dim, const double *x, size_t nv, const double *v, size_t nt,
                                  const uint32_t *t, int closed)
{
    demill_id mat, id, ball;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    if (dim == 3)
        DM_OK(w, demill_wall_add_mesh(w, mat, nv, v, nt, t, &id));
    else
        DM_OK(w, demill_wall_add_polyline(w, mat, nv, v, closed, &id));
    const double r = R;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    return w;
}

/* One contact, from point c (the nearest point of the feature) to the
 * centre x: overlap R - |x - c|, force K δ along (x - c)/|x - c|. */
static void one_contact(demill_world *w, const double *x, const double *c, const char *what)
{
    double ov[4], fn[12];
    ck_assert_msg(contacts(w, ov, fn) == 1, "%s: not one contact", what);
    const double d[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]}, dist = norm3(d);
    DM_ASSERT_REL(ov[0], R - dist, 1e-12);
    for (int k = 0; k < 3; k++)
        ck_assert_msg(fabs(fn[k] - K * (R - dist) * d[k] / dist) <= 1e-12 * K * R,
                      "%s: force component %d is %.17g, expected %.17g", what, k, fn[k],
                      K * (R - dist) * d[k] / dist);
}

START_TEST(convex_edge_and_vertex)
{
    /* a ridge along z at y = 0, faces falling at 45° to y = -1 (x = ±1): a
     * centre at (3, 9) mm is in the ridge's region (between the faces'
     * normals (∓1, 1)/√2), its nearest point (0, 0, z) */
    const double ridge[] = {-1, -1, -1, 0, 0, -1, 1, -1, -1, -1, -1, 1, 0, 0, 1, 1, -1, 1};
    const uint32_t rt[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
    const double x[3] = {0.003, 0.009, 0.0002}, c[3] = {0, 0, 0.0002};
    demill_world *w = static_scene(3, x, 6, ridge, 4, rt, 0);
    one_contact(w, x, c, "ridge");
    demill_world_destroy(w);
    /* a pyramid, apex at the origin over corners (±1, -1, ±1): a centre at
     * (2, 9, 1) mm is in the apex's region (its dot product with every edge
     * (±1, -1, ±1) is negative) */
    const double pyr[] = {0, 0, 0, 1, -1, 1, -1, -1, 1, -1, -1, -1, 1, -1, -1};
    const uint32_t pt[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
    const double y[3] = {0.002, 0.009, 0.001}, o[3] = {0, 0, 0};
    w = static_scene(3, y, 5, pyr, 4, pt, 0);
    one_contact(w, y, o, "apex");
    demill_world_destroy(w);
    /* 2D: a roof (-1, -1) - (0, 0) - (1, -1); the disc at (3, 9) mm touches its peak */
    const double roof[] = {-1, -1, 0, 0, 0, 0, 1, -1, 0};
    const double z[3] = {0.003, 0.009, 0};
    w = static_scene(2, z, 3, roof, 2, NULL, 0);
    one_contact(w, z, o, "2D peak");
    demill_world_destroy(w);
}
END_TEST

START_TEST(concave_corner)
{
    /* the floor y = 0 (x >= 0) and the wall x = 0 (y >= 0), each two
     * triangles: a ball at (8, 9) mm touches both, overlaps 2 and 1 mm */
    const double v[] = {0, 0, -1, 0, 0, 1, 1, 0, 1, 1, 0, -1, 0, 1, 1, 0, 1, -1};
    const uint32_t t[] = {0, 1, 2, 0, 2, 3, 0, 5, 4, 0, 4, 1};
    const double x[3] = {0.008, 0.009, 0.0};
    demill_world *w = static_scene(3, x, 6, v, 4, t, 0);
    double ov[4], fn[12];
    ck_assert_uint_eq(contacts(w, ov, fn), 2);
    const double sum[3] = {fn[0] + fn[3], fn[1] + fn[4], fn[2] + fn[5]};
    ck_assert(fabs(sum[0] - K * 0.002) <= 1e-9 && fabs(sum[1] - K * 0.001) <= 1e-9 &&
              fabs(sum[2]) <= 1e-12);
    demill_world_destroy(w);
    /* 2D: the corner of an L polyline (0, 1) - (0, 0) - (1, 0) */
    const double l[] = {0, 1, 0, 0, 0, 0, 1, 0, 0};
    w = static_scene(2, x, 3, l, 2, NULL, 0);
    ck_assert_uint_eq(contacts(w, ov, fn), 2);
    ck_assert(fabs(fn[0] + fn[3] - K * 0.002) <= 1e-9 && fabs(fn[1] + fn[4] - K * 0.001) <= 1e-9);
    demill_world_destroy(w);
}
END_TEST

/* The particle-wall candidates of a world. */
static uint32_t candidates(const demill_world *w)
{
    uint32_t n = 0;
    for (int k = 0; k < DM_KERNELS; k++)
        n += w->pw.b[k].n;
    return n;
}

/* 25 balls of 5 mm on a 5 × 5 lattice 12 mm apart settle on a floor of nt
 * triangles (3D) and rest: the floor carries 25 m g (the force on the
 * balls, read from the wall), and there are at most `most` candidates. */
static void carry_balls(size_t nv, const double *v, size_t nt, const uint32_t *t, uint32_t most)
{
    demill_id mat, floor, ids[25];
    demill_world *w = floor_world(3, 0, &mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 5e-6));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_NONE));
    DM_OK(w, demill_wall_add_mesh(w, mat, nv, v, nt, t, &floor));
    double x[75], r[25];
    for (int k = 0; k < 25; k++) {
        x[3 * k] = 0.012 * (k % 5) - 0.024 + 0.0011;
        x[3 * k + 1] = 0.0052;
        x[3 * k + 2] = 0.012 * (k / 5) - 0.024 + 0.0007;
        r[k] = 0.005;
    }
    DM_OK(w, demill_particles_add(w, mat, 25, x, r, NULL, 0, ids));
    DM_OK(w, demill_world_step(w, 20000)); /* 0.1 s: 40 periods of the bounce, damped */
    double m, f[3];
    DM_OK(w, demill_particle_get(w, ids[0], DEMILL_PARTICLE_MASS, &m));
    DM_OK(w, demill_wall_get(w, floor, DEMILL_WALL_FORCE, f));
    DM_ASSERT_REL(-f[1], 25 * m * 9.81, 1e-6);
    ck_assert_msg(candidates(w) <= most, "%u candidates, at most %u expected", candidates(w),
                  most);
    demill_world_destroy(w);
}

START_TEST(huge_and_tiny_triangles)
{
    /* one triangle 2 m across: one candidate per ball */
    const double big[] = {-1, 0, -1, 1, 0, -1, 0, 0, 1.5};
    const uint32_t bt[] = {0, 1, 2};
    carry_balls(3, big, 1, bt, 25);
    /* 1 mm cells (triangles of 0.5 mm²), 100 × 100 of them (20,000
     * triangles): a ball reaches the triangles within r + skin (skin 0.1 r
     * by default) of its centre, a disc of radius below 5.5 mm at the
     * floor: π 5.5² / 0.5 < 191 triangles whole, and those cut by its rim,
     * fewer than its perimeter 2π 5.5 mm over 1 mm times 4 */
    const int cells = 100;
    double *v = malloc(3 * sizeof *v * (cells + 1) * (cells + 1));
    uint32_t *t = malloc(6 * sizeof *t * cells * cells);
    ck_assert(v && t);
    dm_test_floor_grid(cells, 0.001, -0.05, v, t);
    carry_balls((size_t)(cells + 1) * (cells + 1), v, 2 * (size_t)cells * cells, t,
                25 * (191 + 139));
    free(v);
    free(t);
}
END_TEST

#define NBOX DM_TEST_BOX_BALLS

/* A box of four walls and a floor, one mesh of 10 triangles, turning about
 * y and z, with NBOX balls of 2.5-3.4 mm tumbling in it. */
static demill_world *box_scene(int threads)
{
    demill_id mat, box;
    demill_world *w = floor_world(3, 0, &mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_THREADS, threads));
    dm_test_tumbling_box(w, mat, &box);
    DM_OK(w, demill_world_step(w, 2000));
    return w;
}

static double *positions(demill_world *w)
{
    double *out = malloc(3 * NBOX * sizeof *out);
    ck_assert_ptr_nonnull(out);
    size_t n;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, out, NBOX, &n));
    return out;
}

START_TEST(checkpoint_and_snapshot)
{
    demill_world *w = box_scene(1);
    size_t size, n;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    void *buf = malloc(size);
    ck_assert_ptr_nonnull(buf);
    DM_OK(w, demill_world_save_buffer(w, buf, size, &size));
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, 2000));
    double fa[3], fb[3];
    demill_id wall;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, &wall, 1, &n));
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_FORCE, fa));
    ck_assert_msg(norm3(fa) > 0.0, "no ball touches the box");
    double *a = positions(w);

    demill_world *u;
    ck_assert_int_eq(demill_world_create(2, &u), DEMILL_OK);
    DM_OK(u, demill_world_load_buffer(u, buf, size));
    DM_OK(u, demill_world_step(u, 2000));
    DM_OK(u, demill_world_ids(u, DEMILL_KIND_WALL, &wall, 1, &n));
    DM_OK(u, demill_wall_get(u, wall, DEMILL_WALL_FORCE, fb));
    double *b = positions(u);
    ck_assert(memcmp(a, b, 3 * NBOX * sizeof *a) == 0 && memcmp(fa, fb, sizeof fa) == 0);

    DM_OK(w, demill_snapshot_restore(w, snap));
    demill_snapshot_free(snap);
    DM_OK(w, demill_world_step(w, 2000));
    double *c = positions(w);
    ck_assert(memcmp(a, c, 3 * NBOX * sizeof *a) == 0);
    free(a);
    free(b);
    free(c);
    free(buf);
    demill_world_destroy(u);
    demill_world_destroy(w);
}
END_TEST

START_TEST(threads_bitwise)
{
    demill_world *one = box_scene(1), *two = box_scene(2);
    double *a = positions(one), *b = positions(two);
    ck_assert(memcmp(a, b, 3 * NBOX * sizeof *a) == 0);
    free(a);
    free(b);
    demill_world_destroy(one);
    demill_world_destroy(two);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("mesh");
    TCase *tc = tcase_create("mesh");
    tcase_add_loop_test(tc, floor_as_plane, 0, 12);
    tcase_add_loop_test(tc, rolling_keeps_speed, 0, 2);
    tcase_add_test(tc, convex_edge_and_vertex);
    tcase_add_test(tc, concave_corner);
    tcase_add_test(tc, huge_and_tiny_triangles);
    tcase_add_test(tc, checkpoint_and_snapshot);
    tcase_add_test(tc, threads_bitwise);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
