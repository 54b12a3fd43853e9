/* rolling.c: a spinning ball set on a rough floor starts to roll (docs/physics.md
 * §4), and rolling resistance stops a rolling ball (§5).
 *
 * A ball spinning at ω0 with no linear velocity, set on a rough floor, slides
 * while Coulomb friction μ m g acts at the contact. With k = I/(m R²) (2/5 for
 * a sphere, 1/2 for a disc) the slip speed R ω + v falls at μ g (1 + 1/k), so
 * rolling starts at t = R ω0 / (μ g (1 + 1/k)) with speed v = R ω0 k/(1 + k):
 * 2/7 R ω0 after 2 R ω0/(7 μ g) for a sphere, R ω0/3 after R ω0/(3 μ g) for a
 * disc.
 *
 * A ball rolling without slip at v0 against a constant rolling-resistance
 * torque μ_r R m g decelerates at μ_r g / (1 + k) ... from
 * (I + m R²) dω/dt = -μ_r R m g: a = μ_r g /(1 + k) = 5/7 μ_r g (sphere),
 * 2/3 μ_r g (disc), and stops after s = v0² / (2a).
 *
 * Every case runs with velocity Verlet (loop index 0) and with the iterative
 * refinement (1), whose iterates must advance the tangential spring once per
 * step: the accepted one only.
 */
#include <math.h>

#include "testutil.h"

#define G 9.81

typedef struct floor_scene {
    demill_world *w;
    demill_id mat, ball, floor;
    double r, m;
} floor_scene;

/* A ball of radius r resting (settled) on a floor at y = 0 in a world of
 * dimension dim; disc != 0 makes 2D particles discs of thickness r. */
static floor_scene floor_scene_make(int i, int dim, int disc, int tangential, double mu,
                                    double mu_r)
{
    floor_scene s = {0};
    s.r = 0.01;
    ck_assert_int_eq(demill_world_create(dim, &s.w), DEMILL_OK);
    demill_world *w = s.w;
    if (disc)
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, s.r));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-5));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                              i ? DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT
                                : DEMILL_INTEGRATOR_VELOCITY_VERLET));
    DM_OK(w, demill_material_create(w, &s.mat));
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_TANGENTIAL, tangential));
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_FRICTION, mu));
    if (mu_r > 0) {
        DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_ROLLING,
                                 DEMILL_ROLLING_CONSTANT_TORQUE));
        DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_ROLLING_FRICTION, mu_r));
    }
    double p[3] = {0, 0, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, s.mat, p, n, &s.floor));
    double x[3] = {0, s.r, 0};
    DM_OK(w, demill_particles_add(w, s.mat, 1, x, &s.r, NULL, 0, &s.ball));
    DM_OK(w, demill_world_step(w, 5000)); /* settle: 0.1 s, 70 contact times */
    s.m = dm_test_get(w, s.ball, DEMILL_PARTICLE_MASS, 0);
    return s;
}

/* Spinning ball set down: final speed and time to pure rolling. */
static void spin_to_roll(int i, int dim, int disc, int tangential)
{
    const double mu = 0.3, w0 = 50.0;
    floor_scene s = floor_scene_make(i, dim, disc, tangential, mu, 0.0);
    demill_world *w = s.w;
    const double k = dim == 2 && disc ? 0.5 : 0.4;
    const double v_roll = s.r * w0 * k / (1 + k), t_roll = s.r * w0 / (mu * G * (1 + 1 / k));
    double zero[3] = {0, 0, 0}, spin[3] = {0, 0, w0};
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_VELOCITY, zero));
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    double t0, dt, t_cross = -1, prev_slip = s.r * w0;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t0));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    const double threshold = 0.005 * s.r * w0;
    for (int k2 = 0; k2 < 3 * (int)(t_roll / dt); k2++) {
        DM_OK(w, demill_world_step(w, 1));
        /* slip speed of the contact point: v_x + ω_z R (contact at -R ŷ) */
        double slip = dm_test_get(w, s.ball, DEMILL_PARTICLE_VELOCITY, 0) +
                      dm_test_get(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2) * s.r;
        if (t_cross < 0 && slip < threshold) {
            double t;
            DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
            /* interpolate the crossing of the threshold, then extrapolate the
             * linear decrease to zero slip */
            double tc = t - dt * (threshold - slip) / (prev_slip - slip);
            t_cross = tc - t0 + threshold / (mu * G * (1 + 1 / k));
        }
        prev_slip = slip;
    }
    ck_assert_msg(t_cross > 0, "the ball never stopped slipping");
    DM_ASSERT_REL(t_cross, t_roll, 0.02);
    /* ω = +z with the contact below: friction drives the ball towards -x */
    DM_ASSERT_REL(dm_test_get(w, s.ball, DEMILL_PARTICLE_VELOCITY, 0), -v_roll, 0.02);
    DM_ASSERT_REL(dm_test_get(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), v_roll / s.r,
                  0.02);
    demill_world_destroy(w);
}

START_TEST(sphere_spin_to_roll_3d)
{
    spin_to_roll(_i, 3, 0, DEMILL_TANGENTIAL_SPRING);
    spin_to_roll(_i, 3, 0, DEMILL_TANGENTIAL_COULOMB);
    spin_to_roll(_i, 3, 0, DEMILL_TANGENTIAL_MINDLIN);
}
END_TEST

START_TEST(sphere_spin_to_roll_2d)
{
    spin_to_roll(_i, 2, 0, DEMILL_TANGENTIAL_SPRING);
    spin_to_roll(_i, 2, 0, DEMILL_TANGENTIAL_COULOMB);
}
END_TEST

START_TEST(disc_spin_to_roll_2d)
{
    spin_to_roll(_i, 2, 1, DEMILL_TANGENTIAL_SPRING);
    spin_to_roll(_i, 2, 1, DEMILL_TANGENTIAL_COULOMB);
}
END_TEST

/* Rolling ball against constant rolling resistance: stopping distance. */
static void roll_to_stop(int i, int dim, int disc)
{
    const double mu_r = 0.05, v0 = 0.5;
    floor_scene s = floor_scene_make(i, dim, disc, DEMILL_TANGENTIAL_SPRING, 0.5, mu_r);
    demill_world *w = s.w;
    const double k = dim == 2 && disc ? 0.5 : 0.4;
    const double dist = v0 * v0 / (2 * mu_r * G / (1 + k));
    double vel[3] = {v0, 0, 0}, spin[3] = {0, 0, -v0 / s.r};
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_VELOCITY, vel));
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    const double x0 = dm_test_get(w, s.ball, DEMILL_PARTICLE_POSITION, 0);
    double dt;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    const double t_stop = v0 / (mu_r * G / (1 + k));
    DM_OK(w, demill_world_step(w, (uint64_t)(1.2 * t_stop / dt)));
    /* stopped: no further motion */
    ck_assert_msg(fabs(dm_test_get(w, s.ball, DEMILL_PARTICLE_VELOCITY, 0)) < 1e-3 * v0,
                  "the ball still moves at %g m/s",
                  dm_test_get(w, s.ball, DEMILL_PARTICLE_VELOCITY, 0));
    DM_ASSERT_REL(dm_test_get(w, s.ball, DEMILL_PARTICLE_POSITION, 0) - x0, dist, 0.02);
    demill_world_destroy(w);
}

START_TEST(rolling_resistance_stopping_distance)
{
    roll_to_stop(_i, 3, 0);
    roll_to_stop(_i, 2, 0);
    roll_to_stop(_i, 2, 1);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("rolling");
    TCase *tc = tcase_create("floor");
    tcase_add_loop_test(tc, sphere_spin_to_roll_3d, 0, 2);
    tcase_add_loop_test(tc, sphere_spin_to_roll_2d, 0, 2);
    tcase_add_loop_test(tc, disc_spin_to_roll_2d, 0, 2);
    tcase_add_loop_test(tc, rolling_resistance_stopping_distance, 0, 2);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
