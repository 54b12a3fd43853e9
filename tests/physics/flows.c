/* flows.c: particles fed onto a belt, and removed by outlets, against
 * conservation laws.
 *
 * Belt: a feed drops particles at zero horizontal speed onto a floor whose
 * surface moves at v along x; an outlet downstream removes them. At steady
 * state the belt's horizontal force is the particles' momentum flux, ṁ v.
 *
 * Outlets: one that removes a fixed particle takes its potential energy
 * out of the energy account, and nothing else. */
#include <stdio.h>

#include "testutil.h"

/* A world with its default gravity (9.81 m/s² along -y) and one material,
 * of which the walls are made too: density 2500 kg/m³, the given Young's
 * modulus, Hertz contacts with the given restitution, Mindlin friction mu
 * and, if mu_r > 0, constant-torque rolling resistance mu_r. */
static demill_world *flow_world(double youngs, double restitution, double mu, double mu_r,
                                demill_id *m)
{
    demill_world *w = NULL;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, m));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_DENSITY, 2500));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_YOUNGS_MODULUS, youngs));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_RESTITUTION, restitution));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_FRICTION, mu));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_ROLLING_FRICTION, mu_r));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    if (mu_r > 0)
        DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_ROLLING,
                                 DEMILL_ROLLING_CONSTANT_TORQUE));
    return w;
}

/* ---- belt -------------------------------------------------------------------- */

/* A belt: the floor y = 0 with its surface moving at v = 0.5 m/s along x,
 * under a feed that drops spheres of d = 10 mm (density 2500 kg/m³, E =
 * 10 MPa, restitution 0.3, friction 0.5, rolling friction 0.1) at rest from
 * 3 to 5 cm above it at ṁ = 0.25 kg/s (191 a second), and an outlet that
 * removes them where x > 0.5 m.
 *
 * Momentum balance along x of the particles: the belt is the only thing
 * that pushes them along x (gravity is along -y, there are no side walls),
 * they enter with no x momentum and leave at the belt's speed, so over a
 * window T, ∫ F_x dt = ΔP_x + v M_out, M_out the mass the outlet removed.
 * At steady state the particles' momentum ΔP_x changes by no more than a
 * few particles' m v, M_out = ṁ T, and the force the particles exert on the
 * belt averages -ṁ v = -0.125 N. They leave at v only because they stop
 * turning: a sphere dragged by the belt rolls without slip at about 2v/7
 * (tests/physics/walls.c, belt_drags_ball_to_rolling), and the rolling
 * friction brings its spin, and so its slip, to zero within v / (μ_r g) ≈
 * 0.5 s, about 0.15 m along the belt (without it the belt's force is 0.65
 * ṁ v: the spheres leave rolling at 0.33 m/s).
 *
 * Checked: after 2 s (the first particles reach the outlet after about
 * 1.2 s), the mean of the belt's force over 1 s (every step) is -ṁ v within
 * 5 %, and the means over the window's two halves agree within 5 %. */
START_TEST(belt_force_is_momentum_flux)
{
    const double d = 0.01, v = 0.5, rate = 0.25, dt = 2e-5;
    demill_id m, belt, feed, outlet;
    demill_world *w = flow_world(1e7, 0.3, 0.5, 0.1, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    const double o[3] = {0, 0, 0}, up[3] = {0, 1, 0}, u[3] = {v, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, m, o, up, &belt));
    DM_OK(w, demill_wall_set_surface_velocity(w, belt, u));
    const double box[6] = {-0.02, 0.03, -0.05, 0.02, 0.05, 0.05}, still[3] = {0, 0, 0};
    const double sizes[2] = {d, 1.0};
    DM_OK(w, demill_feed_create(w, DEMILL_REGION_BOX, box, 6, m, DEMILL_SIZES_CLASSES, sizes, 2,
                                rate, still, 0.0, INFINITY, 7, &feed));
    const double beyond[6] = {0.5, 0, 0, -1, 0, 0};
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, beyond, 6, 0, NULL, 0.1, &outlet));
    DM_OK(w, demill_world_step(w, (uint64_t)(2.0 / dt + 0.5)));
    const long n = (long)(1.0 / dt + 0.5);
    double sum[2] = {0, 0};
    for (long k = 0; k < n; k++) {
        double f[3];
        DM_OK(w, demill_world_step(w, 1));
        DM_OK(w, demill_wall_get(w, belt, DEMILL_WALL_FORCE, f));
        sum[2 * k >= n] += f[0];
    }
    const double f1 = sum[0] / (n / 2), f2 = sum[1] / (n - n / 2), mean = (sum[0] + sum[1]) / n;
    printf("belt: force %.5f N (halves %.5f and %.5f) against -m v = %.5f N: %+.2f %%\n", mean,
           f1, f2, -rate * v, 100 * (-mean - rate * v) / (rate * v));
    fflush(stdout);
    DM_ASSERT_REL(mean, -rate * v, 0.05);
    DM_ASSERT_REL(f2, f1, 0.05);
    demill_world_destroy(w);
}
END_TEST

/* ---- outlets and fixed particles ------------------------------------------- */

/* An outlet takes out of the energy account what a particle it removes
 * held: its kinetic energy (none, for a fixed particle, which neither moves
 * nor turns) and its potential energy -m g·x. A fixed particle of mass m at
 * y = -0.2 m in an outlet below y = -0.1 m is removed at the first step, and
 * DEMILL_ENERGY_FLOW, the energy brought in less that taken out, becomes
 * -(-m g·x) = m 9.81 × 0.2 J (gravity -9.81 along y), while the total
 * energy, which subtracts it from a potential energy that no longer counts
 * the particle, stays where it was. (The spin's share was computed as 1/2
 * ω² / I⁻¹, 0/0 for a fixed particle, and made both NaN.) */
START_TEST(outlet_removes_fixed_particle)
{
    demill_id m, ids[2], outlet;
    demill_world *w = flow_world(1e7, 0.5, 0.5, 0.0, &m);
    const double x[6] = {0, -0.2, 0, 0.5, 0, 0}, r[2] = {0.01, 0.01}, one = 1.0;
    DM_OK(w, demill_particles_add(w, m, 2, x, r, NULL, 0, ids));
    DM_OK(w, demill_particle_set(w, ids[0], DEMILL_PARTICLE_FIXED, &one));
    const double mass = dm_test_get(w, ids[0], DEMILL_PARTICLE_MASS, 0);
    const double below[6] = {0, -0.1, 0, 0, 1, 0};
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, below, 6, 0, NULL, 1.0, &outlet));
    double e0, e1, flow;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &e0));
    DM_OK(w, demill_world_step(w, 1));
    uint64_t count;
    DM_OK(w, demill_outlet_read(w, outlet, &count, NULL, 1, NULL, NULL));
    ck_assert_uint_eq(count, 1);
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_FLOW, &flow));
    DM_ASSERT_REL(flow, mass * 9.81 * 0.2, 1e-12);
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &e1));
    ck_assert_msg(fabs(e1 - e0) <= 1e-12 * mass * 9.81 * 0.2, "total %g J, %g J before", e1, e0);
    demill_world_destroy(w);
}
END_TEST

Suite *flows_suite(void);
Suite *flows_suite(void)
{
    Suite *s = suite_create("flows");
    TCase *tc = tcase_create("belt");
    tcase_add_test(tc, belt_force_is_momentum_flux);
    suite_add_tcase(s, tc);
    tc = tcase_create("outlets");
    tcase_add_test(tc, outlet_removes_fixed_particle);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return dm_test_run(flows_suite());
}
