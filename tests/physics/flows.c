/* flows.c: particles that enter and leave a world (feeds and outlets),
 * against conservation laws. */

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
    TCase *tc = tcase_create("outlets");
    tcase_add_test(tc, outlet_removes_fixed_particle);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return dm_test_run(flows_suite());
}
