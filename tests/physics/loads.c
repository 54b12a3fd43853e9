/* loads.c: the loads walls record per element (docs/geometry.md, Wall
 * loads): normal force, its time integral and the shear work.
 *
 * - A sphere of mass m resting on a triangulated floor (above a vertex
 *   shared by six triangles, above an edge, inside a face) or on a polyline
 *   (2D; above a vertex, inside a segment), placed at its equilibrium
 *   overlap m g / k: the elements' normal forces sum to m g and their
 *   integrals over T = 1000 steps to m g T, within a relative 1e-9 (statics,
 *   Newton's third law), all of it on one element (one contact); with
 *   velocity Verlet and with the iterative refinement (which evaluates the
 *   forces several times a step, and must record them once).
 * - The same sphere resting on the floor of a can (a cylinder of radius
 *   0.05 m and length 0.1 m capped at its start): the can records it as one
 *   patch with its cap, m g within 1e-9, of area 2π r L + π r² (1e-12).
 * - A sphere launched at v0 without spin on a triangulated floor with
 *   Coulomb friction μ slides until it rolls. With the contact's lever arm
 *   a = R − δ/2 (δ = m g / k) and I = 2/5 m R², friction μ m g slows it,
 *   dv/dt = −μ g, and spins it up, dω/dt = μ m g a / I, so the slip speed
 *   s = v − ω a falls at ds/dt = −μ g (1 + 5 a²/(2 R²)) until it is 0 at
 *   t1 = v0 / (μ g (1 + 5 a²/(2 R²))); the distance slid relative to the
 *   floor's surface is ∫ s dt = v0 t1 / 2 and the friction work μ m g v0 t1 / 2
 *   = m v0² / (2 (1 + 5 a²/(2 R²))), which for a = R is m v0²/7 (the kinetic
 *   energy lost, ½ m v0² − ½ m (5/7 v0)² (1 + 2/5); the classical result,
 *   e.g. Routh 1860, A Treatise on the Dynamics of a System of Rigid
 *   Bodies). The floor's shear work matches it within 1e-3.
 * - A sphere at rest dropped onto a belt (a plane with surface velocity u):
 *   in the belt's frame it is the sphere above launched at −u, so the shear
 *   work, taken with the slip velocity relative to the belt's surface, is
 *   the same m u² / (2 (1 + 5 a²/(2 R²))) within 1e-3; with the particle's
 *   own velocity it would be the kinetic energy it gains, 2/49 m u².
 * - Recording changes nothing of the motion (bitwise); stopping forgets
 *   the loads; a wrong element count is refused.
 * - A checkpoint and a snapshot carry the loads of a mesh box turning with
 *   1100 balls in it bitwise, and 1 and 2 threads record the same bits.
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define R 0.01     /* ball radius, m */
#define H 0.01     /* floor cell, m */
#define CELLS 10   /* floor cells along x and z, from -0.05 m */
#define K 1e5      /* linear normal stiffness, N/m */
#define MU 0.3     /* friction coefficient */
#define DT 1e-5    /* time step, s */
#define RHO 7800.0 /* density, kg/m³ */
#define G 9.81     /* the world's default gravity, m/s² */

/* A world of the given dimension, one material whose pair has a linear
 * spring with restitution damping and a spring-slider of friction MU. */
static demill_world *loads_world(int dim, int threads, demill_id *mat)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, DT));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_THREADS, threads));
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, RHO));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_FRICTION, MU));
    return w;
}

/* The floor y = 0: the triangulated grid (3D) or a polyline of CELLS
 * segments (2D); its number of elements in *n. */
static demill_id mesh_floor(demill_world *w, int dim, demill_id mat, size_t *n)
{
    demill_id id;
    if (dim == 2) {
        double pts[3 * (CELLS + 1)] = {0};
        for (int i = 0; i <= CELLS; i++)
            pts[3 * i] = -0.05 + i * H;
        DM_OK(w, demill_wall_add_polyline(w, mat, CELLS + 1, pts, 0, &id));
        *n = CELLS;
        return id;
    }
    double v[3 * (CELLS + 1) * (CELLS + 1)];
    uint32_t t[6 * CELLS * CELLS];
    dm_test_floor_grid(CELLS, H, -0.05, v, t);
    DM_OK(w, demill_wall_add_mesh(w, mat, (CELLS + 1) * (CELLS + 1), v, 2 * CELLS * CELLS, t, &id));
    *n = 2 * CELLS * CELLS;
    return id;
}

/* The mass of a ball, and its overlap at rest on a floor. */
static double ball_mass(void)
{
    return RHO * 4.0 / 3.0 * M_PI * R * R * R;
}

static double rest_overlap(void)
{
    return ball_mass() * G / K;
}

/* The friction work of a ball launched at v0 without spin until it rolls
 * (see the top of the file). */
static double slide_work(double v0)
{
    const double a = R - 0.5 * rest_overlap();
    return ball_mass() * v0 * v0 / (2.0 * (1.0 + 2.5 * a * a / (R * R)));
}

typedef struct loads {
    size_t n;
    double *normal, *impulse, *shear, *area, interval;
} loads;

static loads read_loads(demill_world *w, demill_id wall, size_t n)
{
    loads l = {.n = n};
    double **const a[] = {&l.normal, &l.impulse, &l.shear, &l.area};
    for (int k = 0; k < 4; k++)
        ck_assert_ptr_nonnull(*a[k] = malloc(n * sizeof **a[k]));
    DM_OK(w, demill_wall_loads(w, wall, n, l.normal, l.impulse, l.shear, l.area, &l.interval));
    return l;
}

static void free_loads(loads *l)
{
    free(l->normal);
    free(l->impulse);
    free(l->shear);
    free(l->area);
}

static double sum(const double *v, size_t n)
{
    double s = 0.0;
    for (size_t k = 0; k < n; k++)
        s += v[k];
    return s;
}

/* Starts of the resting sphere: 3D above the vertex at the origin (six
 * triangles), above the middle of an edge, inside a face; 2D above a
 * vertex and inside a segment. */
static const double starts[5][3] = {{0.0, 0.0, 3}, {0.5 * H, 0.0, 3}, {0.3 * H, 0.7 * H, 3},
                                    {0.0, 0.0, 2}, {0.5 * H, 0.0, 2}};

START_TEST(resting_sphere)
{
    const int start = _i % 5, dim = (int)starts[start][2];
    demill_id mat, ball;
    demill_world *w = loads_world(dim, 1, &mat);
    if (_i >= 5)
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                                  DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT));
    size_t n;
    const demill_id floor = mesh_floor(w, dim, mat, &n);
    const double x[3] = {starts[start][0], R - rest_overlap(), dim == 3 ? starts[start][1] : 0.0};
    const double r = R;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    DM_OK(w, demill_wall_loads_start(w, floor));
    const int steps = 1000;
    DM_OK(w, demill_world_step(w, steps));
    loads l = read_loads(w, floor, n);
    const double mg = ball_mass() * G, T = steps * DT;
    DM_ASSERT_REL(l.interval, T, 1e-12);
    DM_ASSERT_REL(sum(l.normal, n), mg, 1e-9);
    DM_ASSERT_REL(sum(l.impulse, n), mg * T, 1e-9);
    size_t loaded = 0;
    for (size_t e = 0; e < n; e++)
        loaded += l.normal[e] != 0.0;
    ck_assert_uint_eq(loaded, 1);
    /* the elements' areas: H²/2 per triangle, H per segment */
    DM_ASSERT_REL(l.area[n - 1], dim == 3 ? 0.5 * H * H : H, 1e-12);
    free_loads(&l);
    demill_world_destroy(w);
}
END_TEST

START_TEST(capped_can)
{
    const double o[3] = {0, 0, 0}, up[3] = {0, 1, 0}, rc = 0.05, L = 0.1;
    demill_id mat, can, ball;
    demill_world *w = loads_world(3, 1, &mat);
    DM_OK(w, demill_wall_add_cylinder(w, mat, o, up, rc, L, DEMILL_CAPS_START, &can));
    const double x[3] = {0.01, R - rest_overlap(), 0.005}, r = R;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    DM_OK(w, demill_wall_loads_start(w, can));
    DM_OK(w, demill_world_step(w, 1000));
    double normal, impulse, shear, area, interval;
    DM_OK(w, demill_wall_loads(w, can, 1, &normal, &impulse, &shear, &area, &interval));
    DM_ASSERT_REL(normal, ball_mass() * G, 1e-9);
    DM_ASSERT_REL(impulse, ball_mass() * G * interval, 1e-9);
    DM_ASSERT_REL(area, 2.0 * M_PI * rc * L + M_PI * rc * rc, 1e-12);
    demill_world_destroy(w);
}
END_TEST

/* A ball on the floor at its resting overlap, moving at v along x. */
static demill_id add_ball(demill_world *w, demill_id mat, double x0, double v)
{
    const double x[3] = {x0, R - rest_overlap(), 0.3 * H}, vel[3] = {v, 0, 0}, r = R;
    demill_id ball;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, vel, 0, &ball));
    return ball;
}

START_TEST(sliding_sphere)
{
    const double v0 = 0.5;
    demill_id mat[2], ball[2], floor[2];
    demill_world *w[2];
    size_t n;
    for (int k = 0; k < 2; k++) { /* k = 1 records; k = 0 does not */
        w[k] = loads_world(3, 1, &mat[k]);
        floor[k] = mesh_floor(w[k], 3, mat[k], &n);
        ball[k] = add_ball(w[k], mat[k], -0.03, v0);
        if (k)
            DM_OK(w[k], demill_wall_loads_start(w[k], floor[k]));
        /* sliding ends at t1 = 2 v0 / (7 μ g) = 0.049 s: run 0.06 s */
        DM_OK(w[k], demill_world_step(w[k], 6000));
    }
    double v[3], x[2][3];
    DM_OK(w[1], demill_particle_get(w[1], ball[1], DEMILL_PARTICLE_VELOCITY, v));
    DM_ASSERT_REL(v[0], 5.0 / 7.0 * v0, 1e-3); /* rolling */
    loads l = read_loads(w[1], floor[1], n);
    DM_ASSERT_REL(sum(l.shear, n), slide_work(v0), 1e-3);
    size_t touched = 0;
    for (size_t e = 0; e < n; e++)
        touched += l.shear[e] > 0.0;
    ck_assert_msg(touched > 2, "the ball slid over %zu triangles", touched);
    free_loads(&l);
    for (int k = 0; k < 2; k++)
        DM_OK(w[k], demill_particle_get(w[k], ball[k], DEMILL_PARTICLE_POSITION, x[k]));
    ck_assert(memcmp(x[0], x[1], sizeof x[0]) == 0);

    /* stopped, the loads are gone; a wrong count is refused */
    double one;
    ck_assert_int_eq(demill_wall_loads(w[1], floor[1], n + 1, &one, NULL, NULL, NULL, NULL),
                     DEMILL_ERR_INVALID_VALUE);
    DM_OK(w[1], demill_wall_loads_stop(w[1], floor[1]));
    ck_assert_int_eq(demill_wall_loads(w[1], floor[1], n, NULL, NULL, NULL, NULL, NULL),
                     DEMILL_ERR_INVALID_VALUE);
    for (int k = 0; k < 2; k++)
        demill_world_destroy(w[k]);
}
END_TEST

START_TEST(belt)
{
    const double u = 0.5, p[3] = {0, 0, 0}, up[3] = {0, 1, 0}, belt_v[3] = {u, 0, 0};
    demill_id mat, belt;
    demill_world *w = loads_world(3, 1, &mat);
    DM_OK(w, demill_wall_add_plane(w, mat, p, up, &belt));
    DM_OK(w, demill_wall_set_surface_velocity(w, belt, belt_v));
    add_ball(w, mat, 0.0, 0.0);
    DM_OK(w, demill_wall_loads_start(w, belt));
    DM_OK(w, demill_world_step(w, 6000));
    double normal, impulse, shear, area, interval;
    DM_OK(w, demill_wall_loads(w, belt, 1, &normal, &impulse, &shear, &area, &interval));
    DM_ASSERT_REL(shear, slide_work(u), 1e-3);
    DM_ASSERT_REL(normal, ball_mass() * G, 1e-6); /* rolling along at 2/7 u */
    ck_assert(isnan(area));
    demill_world_destroy(w);
}
END_TEST

#define NBOX DM_TEST_BOX_BALLS

/* A box of four walls and a floor, one mesh of 10 triangles turning about y
 * and z, with NBOX balls of 2.5-3.4 mm tumbling in it, recording its loads
 * from the start, after `steps` steps. */
static demill_world *box_scene(int threads, int steps, demill_id *box)
{
    demill_id mat;
    demill_world *w = loads_world(3, threads, &mat);
    dm_test_tumbling_box(w, mat, box);
    DM_OK(w, demill_wall_loads_start(w, *box));
    DM_OK(w, demill_world_step(w, (uint64_t)steps));
    return w;
}

/* The box's loads as one array: 3 per triangle, then the interval. */
static void box_loads(demill_world *w, demill_id box, double out[31])
{
    DM_OK(w, demill_wall_loads(w, box, 10, out, out + 10, out + 20, NULL, out + 30));
}

START_TEST(checkpoint_and_snapshot)
{
    demill_id box;
    demill_world *w = box_scene(1, 2000, &box);
    size_t size, n;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    void *buf = malloc(size);
    ck_assert_ptr_nonnull(buf);
    DM_OK(w, demill_world_save_buffer(w, buf, size, &size));
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, 1000));
    double a[31], b[31], c[31];
    box_loads(w, box, a);
    ck_assert_msg(sum(a + 10, 10) > 0.0 && sum(a + 20, 10) > 0.0, "no load on the box");

    demill_world *u;
    ck_assert_int_eq(demill_world_create(2, &u), DEMILL_OK);
    DM_OK(u, demill_world_load_buffer(u, buf, size));
    DM_OK(u, demill_world_step(u, 1000));
    DM_OK(u, demill_world_ids(u, DEMILL_KIND_WALL, &box, 1, &n));
    box_loads(u, box, b);
    ck_assert(memcmp(a, b, sizeof a) == 0);

    DM_OK(w, demill_snapshot_restore(w, snap));
    demill_snapshot_free(snap);
    DM_OK(w, demill_world_step(w, 1000));
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, &box, 1, &n));
    box_loads(w, box, c);
    ck_assert(memcmp(a, c, sizeof a) == 0);
    free(buf);
    demill_world_destroy(u);
    demill_world_destroy(w);
}
END_TEST

START_TEST(threads_bitwise)
{
    demill_id box[2];
    demill_world *one = box_scene(1, 2000, &box[0]), *two = box_scene(2, 2000, &box[1]);
    double a[31], b[31];
    box_loads(one, box[0], a);
    box_loads(two, box[1], b);
    ck_assert(memcmp(a, b, sizeof a) == 0);
    demill_world_destroy(one);
    demill_world_destroy(two);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("loads");
    TCase *tc = tcase_create("loads");
    tcase_add_loop_test(tc, resting_sphere, 0, 10);
    tcase_add_test(tc, capped_can);
    tcase_add_test(tc, sliding_sphere);
    tcase_add_test(tc, belt);
    tcase_add_test(tc, checkpoint_and_snapshot);
    tcase_add_test(tc, threads_bitwise);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
