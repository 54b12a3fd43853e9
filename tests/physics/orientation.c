/* orientation.c: the orientation of 3D particles (DEMILL_PARTICLE_ORIENTATION,
 * docs/shapes.md, Orientation) and the angle of 2D ones.
 *
 * A body turning at a constant angular velocity ω about a fixed unit axis n
 * has, after a time t, turned by the rotation of angle |ω| t about n, whose
 * quaternion is (cos(|ω| t/2), sin(|ω| t/2) n) (Hamilton's rotation
 * quaternion; e.g. Kuipers 1999, "Quaternions and Rotation Sequences",
 * §5.2); from q0 the orientation is that quaternion times q0. A sphere
 * without torque keeps its ω, so this is its exact motion: each step's
 * increment is the exact exponential map (to its series' 2.8e-17), so the
 * error is round-off, some 1e-16 per step. A 2D disc's angle is likewise
 * θ0 + ω t.
 *
 * Every integrator runs each case (loop index: velocity Verlet, symplectic
 * Euler, the iterative refinement).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static const int integrators[3] = {DEMILL_INTEGRATOR_VELOCITY_VERLET,
                                   DEMILL_INTEGRATOR_SYMPLECTIC_EULER,
                                   DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT};

/* A world without gravity and one free sphere (or disc) of radius 0.01 m at
 * the origin, with a friction law, stepped by integrator index i at time
 * step dt; *ball receives its id. */
static demill_world *one_ball(int i, int dim, double dt, demill_id *ball)
{
    demill_id mat;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrators[i]));
    /* a friction law: without one the world integrates no rotation at all */
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double x[3] = {0, 0, 0}, r = 0.01;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, ball));
    return w;
}

/* a ⊗ b, quaternions w, x, y, z. */
static void quat_mul(const double *a, const double *b, double *out)
{
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* Spins two spheres 1 m apart about the axis (1, -2, 3)/√14 from q0, at
 * |ω| = 50 and 5000 rad/s for 5000 steps of 1e-4 s, and compares each with
 * the analytic rotation. The first turns 25 rad by the series (|ω| Δt/2 =
 * 2.5e-3), the second 2500 rad by libm's sine and cosine (0.25): both in one
 * loop over the particles, which blends the two. */
static void spin_about_axis(int i, double tol)
{
    const double dt = 1e-4, speeds[2] = {50.0, 5000.0};
    const int steps = 5000;
    demill_id ball[2], mat;
    demill_world *w = one_ball(i, 3, dt, &ball[0]);
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_MATERIAL, &mat, 1, NULL));
    const double x1[3] = {1.0, 0, 0}, r = 0.01;
    DM_OK(w, demill_particles_add(w, mat, 1, x1, &r, NULL, 0, &ball[1]));
    const double s14 = sqrt(14.0), n[3] = {1 / s14, -2 / s14, 3 / s14};
    const double q0[4] = {0.5, 0.5, -0.5, 0.5};
    for (int k = 0; k < 2; k++) {
        const double om[3] = {speeds[k] * n[0], speeds[k] * n[1], speeds[k] * n[2]};
        DM_OK(w, demill_particle_set(w, ball[k], DEMILL_PARTICLE_ANGULAR_VELOCITY, om));
        DM_OK(w, demill_particle_set(w, ball[k], DEMILL_PARTICLE_ORIENTATION, q0));
    }
    DM_OK(w, demill_world_step(w, (uint64_t)steps));
    for (int k = 0; k < 2; k++) {
        const double half = 0.5 * speeds[k] * steps * dt; /* not the clock's sum of steps */
        const double turn[4] = {cos(half), sin(half) * n[0], sin(half) * n[1],
                                sin(half) * n[2]};
        double want[4], got[4];
        quat_mul(turn, q0, want);
        DM_OK(w, demill_particle_get(w, ball[k], DEMILL_PARTICLE_ORIENTATION, got));
        for (int c = 0; c < 4; c++)
            ck_assert_msg(fabs(got[c] - want[c]) <= tol,
                          "integrator %d, |w| dt = %g: q[%d] = %.17g, expected %.17g (off %.3g)",
                          i, speeds[k] * dt, c, got[c], want[c], fabs(got[c] - want[c]));
    }
    demill_world_destroy(w);
}

START_TEST(sphere_spin_turns_by_omega_t)
{
    spin_about_axis(_i, 1e-12);
}
END_TEST

START_TEST(torque_free_sphere_keeps_unit_norm)
{
    demill_id ball;
    demill_world *w = one_ball(_i, 3, 1e-4, &ball);
    const double om[3] = {300.0, -700.0, 500.0}; /* |ω| Δt/2 = 0.046 */
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, om));
    DM_OK(w, demill_world_step(w, 1000000));
    double q[4];
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_ORIENTATION, q));
    const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    ck_assert_msg(fabs(norm - 1.0) <= 1e-14, "|q| - 1 = %.3g after 1e6 steps", norm - 1.0);
    demill_world_destroy(w);
}
END_TEST

START_TEST(disc_angle_is_omega_t)
{
    demill_id ball;
    demill_world *w = one_ball(_i, 2, 1e-4, &ball);
    const double om[3] = {0, 0, -37.0}, th0 = 0.3;
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, om));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGLE, &th0));
    DM_OK(w, demill_world_step(w, 10000));
    double t, th;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_ANGLE, &th));
    ck_assert_msg(fabs(th - (th0 + om[2] * t)) <= 1e-12, "angle %.17g, expected %.17g", th,
                  th0 + om[2] * t);
    double q[4];
    ck_assert_int_eq(demill_particle_get(w, ball, DEMILL_PARTICLE_ORIENTATION, q),
                     DEMILL_ERR_DIMENSION);
    ck_assert_int_eq(demill_particle_set(w, ball, DEMILL_PARTICLE_ORIENTATION, q),
                     DEMILL_ERR_DIMENSION);
    demill_world_destroy(w);
}
END_TEST

START_TEST(orientation_set_get_round_trip)
{
    demill_id ball;
    demill_world *w = one_ball(0, 3, 1e-4, &ball);
    ck_assert_int_eq(demill_particle_field_size(DEMILL_PARTICLE_ORIENTATION), 4);
    double q[4];
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_ORIENTATION, q));
    const double identity[4] = {1, 0, 0, 0};
    ck_assert(!memcmp(q, identity, sizeof q)); /* a new particle */
    /* a unit quaternion whose components are exact comes back bitwise */
    const double unit[4] = {0.5, -0.5, 0.5, 0.5};
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ORIENTATION, unit));
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_ORIENTATION, q));
    ck_assert(!memcmp(q, unit, sizeof q));
    /* any multiple is normalised: (1, 2, 3, 4)/√30, at scales that would
     * overflow or underflow a plain sum of squares */
    const double scales[3] = {7.0, 1e300, 1e-310};
    for (int k = 0; k < 3; k++) {
        const double in[4] = {scales[k], 2 * scales[k], 3 * scales[k], 4 * scales[k]};
        DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_ORIENTATION, in, 1));
        DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, q, 1, NULL));
        for (int c = 0; c < 4; c++)
            ck_assert_msg(fabs(q[c] - (c + 1) / sqrt(30.0)) <= 4e-16,
                          "scale %g: q[%d] = %.17g, expected %.17g", scales[k], c, q[c],
                          (c + 1) / sqrt(30.0));
    }
    demill_world_destroy(w);
}
END_TEST

START_TEST(orientation_bad_values_refused)
{
    demill_id mat, ids[2];
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    const double x[6] = {0, 0, 0, 1, 0, 0}, r[2] = {0.01, 0.01};
    DM_OK(w, demill_particles_add(w, mat, 2, x, r, NULL, 0, ids));
    const double set[8] = {0, 1, 0, 0, 0, 0, 1, 0};
    DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_ORIENTATION, set, 2));
    const double bad[4][4] = {
        {0, 0, 0, 0}, {NAN, 0, 0, 1}, {1, INFINITY, 0, 0}, {1, 0, 0, -INFINITY}};
    const demill_status want[4] = {DEMILL_ERR_INVALID_VALUE, DEMILL_ERR_NOT_FINITE,
                                   DEMILL_ERR_NOT_FINITE, DEMILL_ERR_NOT_FINITE};
    for (int k = 0; k < 4; k++) {
        ck_assert_int_eq(demill_particle_set(w, ids[1], DEMILL_PARTICLE_ORIENTATION, bad[k]),
                         want[k]);
        ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "orientation"));
        /* a batch whose second quaternion is bad changes neither */
        const double batch[8] = {1, 0, 0, 0, bad[k][0], bad[k][1], bad[k][2], bad[k][3]};
        ck_assert_int_eq(demill_particles_write(w, DEMILL_PARTICLE_ORIENTATION, batch, 2),
                         want[k]);
        double got[8];
        DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, got, 2, NULL));
        ck_assert(!memcmp(got, set, sizeof got));
    }
    demill_world_destroy(w);
}
END_TEST

/* The orientations of w and copy, bitwise. */
static void same_orientations(demill_world *w, demill_world *copy, int way, void *ctx)
{
    size_t n;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, NULL, 0, &n));
    double *a = malloc(8 * n * sizeof *a);
    ck_assert(a);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, a, n, NULL));
    DM_OK(copy, demill_particles_read(copy, DEMILL_PARTICLE_ORIENTATION, a + 4 * n, n, NULL));
    ck_assert_msg(!memcmp(a, a + 4 * n, 4 * n * sizeof *a), "%s: the orientations differ",
                  way ? "snapshot" : "checkpoint");
    /* they turned: friction spun the balls */
    ck_assert_msg(fabs(a[0]) < 0.999, "q = (%g, %g, %g, %g): the ball did not turn", a[0], a[1],
                  a[2], a[3]);
    (void)ctx;
}

/* Three balls of material *mat thrown spinning onto a rough floor, with
 * gravity, stepped by integrator index i. */
static demill_world *balls_on_floor(int i, demill_id *mat)
{
    demill_id floor, ids[3];
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-5));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrators[i]));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_FRICTION, 0.5));
    const double p[3] = {0, 0, 0}, nrm[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, *mat, p, nrm, &floor));
    const double x[9] = {0, 0.0101, 0, 0.05, 0.012, 0, -0.05, 0.0105, 0.02};
    const double r[3] = {0.01, 0.01, 0.01}, v[9] = {0.3, 0, 0, -0.2, 0, 0.1, 0, -0.1, 0.2};
    DM_OK(w, demill_particles_add(w, *mat, 3, x, r, v, 0, ids));
    const double om[9] = {0, 0, 40, 20, 0, -30, 0, 0, 0};
    DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_ANGULAR_VELOCITY, om, 3));
    return w;
}

START_TEST(orientation_carried_by_checkpoint_and_snapshot)
{
    demill_id mat;
    demill_world *w = balls_on_floor(_i, &mat);
    DM_OK(w, demill_world_step(w, 2000));
    dm_test_copies_run_on(w, 2000, same_orientations, NULL);
    demill_world_destroy(w);
}
END_TEST

/* World.orientation_tracking (DEMILL_WORLD_ORIENTATION_TRACKING) off: a
 * sphere's orientation enters no force, so three balls thrown spinning onto
 * a rough floor, with a clump of the racket's three spheres beside them,
 * move bitwise as they do with it on; the balls keep the orientation they
 * were given, where with it on friction turns them; the clump turns either
 * way, the same to the bit; and a checkpoint and a snapshot keep the
 * setting. Each integrator (the iterative refinement without the clump,
 * which it does not integrate). */
static const double racket_c[9] = {0, 0, 0, 0.03, 0, 0, 0, 0.022, 0};
static const double racket_r[3] = {0.01, 0.01, 0.008};

static demill_world *rough_floor(int i, int tracking, demill_id *clump)
{
    demill_id mat, tmpl;
    demill_world *w = balls_on_floor(i, &mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_ORIENTATION_TRACKING, tracking));
    const double q0[12] = {0.5, 0.5, -0.5, 0.5, 0.6, 0, 0.8, 0, 0, 0, 0, 1};
    DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_ORIENTATION, q0, 3));
    if (integrators[i] == DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT)
        return w; /* which integrates no clumps */
    DM_OK(w, demill_clump_template_add(w, mat, 3, racket_c, racket_r, &tmpl));
    const double at[3] = {0.1, 0.05, 0}, spin[3] = {3, -5, 8};
    DM_OK(w, demill_clump_add(w, tmpl, at, NULL, clump));
    DM_OK(w, demill_clump_set(w, *clump, DEMILL_CLUMP_ANGULAR_VELOCITY, spin));
    return w;
}

/* The checkpoint and snapshot copies of a world with tracking off keep it. */
static void copy_keeps_tracking_off(demill_world *w, demill_world *copy, int way, void *ctx)
{
    double tracking = -1.0;
    DM_OK(copy, demill_world_get(copy, DEMILL_WORLD_ORIENTATION_TRACKING, &tracking));
    ck_assert_msg(tracking == 0.0, "%s: world.orientation_tracking = %g",
                  way ? "snapshot" : "checkpoint", tracking);
    (void)w, (void)ctx;
}

START_TEST(tracking_off_changes_no_motion)
{
    demill_id c_on, c_off;
    demill_world *on = rough_floor(_i, 1, &c_on), *off = rough_floor(_i, 0, &c_off);
    double q0[24], q_on[24], q_off[24], om_on[18], om_off[18], cq_on[4], cq_off[4];
    size_t n;
    DM_OK(off, demill_particles_read(off, DEMILL_PARTICLE_ORIENTATION, q0, 6, &n));
    const int clumps = integrators[_i] != DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT;
    ck_assert_uint_eq(n, clumps ? 6 : 3); /* 3 balls, the clump's 3 members */
    DM_OK(on, demill_world_step(on, 3000));
    DM_OK(off, demill_world_step(off, 3000));
    double *s_on = dm_test_state(on, &n), *s_off = dm_test_state(off, &n);
    ck_assert_msg(!memcmp(s_on, s_off, 6 * n * sizeof *s_on), "positions or velocities differ");
    DM_OK(on, demill_particles_read(on, DEMILL_PARTICLE_ANGULAR_VELOCITY, om_on, 6, NULL));
    DM_OK(off, demill_particles_read(off, DEMILL_PARTICLE_ANGULAR_VELOCITY, om_off, 6, NULL));
    ck_assert_msg(!memcmp(om_on, om_off, 3 * n * sizeof *om_on), "angular velocities differ");
    DM_OK(on, demill_particles_read(on, DEMILL_PARTICLE_ORIENTATION, q_on, 6, NULL));
    DM_OK(off, demill_particles_read(off, DEMILL_PARTICLE_ORIENTATION, q_off, 6, NULL));
    for (int b = 0; b < 3; b++) {
        double dot = 0.0;
        for (int c = 0; c < 4; c++)
            dot += q_on[4 * b + c] * q0[4 * b + c];
        ck_assert_msg(fabs(dot) < 0.99, "ball %d did not turn with tracking on (q·q0 = %g)", b,
                      dot);
    }
    ck_assert_msg(!memcmp(q_off, q0, 12 * sizeof *q0), "a ball turned with tracking off");
    /* the clump, and its members, turned the same either way */
    if (clumps) {
        ck_assert_msg(!memcmp(q_on + 12, q_off + 12, 12 * sizeof *q_on), "the members differ");
        DM_OK(on, demill_clump_get(on, c_on, DEMILL_CLUMP_ORIENTATION, cq_on));
        DM_OK(off, demill_clump_get(off, c_off, DEMILL_CLUMP_ORIENTATION, cq_off));
        ck_assert_msg(!memcmp(cq_on, cq_off, sizeof cq_on), "the clump's orientation differs");
        ck_assert_msg(fabs(cq_off[0]) < 0.99, "the clump did not turn: q = (%g, %g, %g, %g)",
                      cq_off[0], cq_off[1], cq_off[2], cq_off[3]);
    }
    dm_test_copies_run_on(off, 500, copy_keeps_tracking_off, NULL);
    free(s_on);
    free(s_off);
    demill_world_destroy(on);
    demill_world_destroy(off);
}
END_TEST

/* 2D: a disc's angle stays as set with tracking off, spinning or not. */
START_TEST(tracking_off_keeps_disc_angle)
{
    demill_id ball;
    demill_world *w = one_ball(_i, 2, 1e-4, &ball);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_ORIENTATION_TRACKING, 0));
    const double om[3] = {0, 0, 30}, theta = 0.25;
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, om));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGLE, &theta));
    DM_OK(w, demill_world_step(w, 1000));
    ck_assert_double_eq(dm_test_get(w, ball, DEMILL_PARTICLE_ANGLE, 0), theta);
    ck_assert_double_eq(dm_test_get(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), 30.0);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("orientation");
    TCase *tc = tcase_create("orientation");
    tcase_add_loop_test(tc, sphere_spin_turns_by_omega_t, 0, 3);
    tcase_add_loop_test(tc, torque_free_sphere_keeps_unit_norm, 0, 3);
    tcase_add_loop_test(tc, disc_angle_is_omega_t, 0, 3);
    tcase_add_test(tc, orientation_set_get_round_trip);
    tcase_add_test(tc, orientation_bad_values_refused);
    tcase_add_loop_test(tc, orientation_carried_by_checkpoint_and_snapshot, 0, 3);
    tcase_add_loop_test(tc, tracking_off_changes_no_motion, 0, 3);
    tcase_add_loop_test(tc, tracking_off_keeps_disc_angle, 0, 3);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
