/* mill.c: small mills in 2D and 3D against what a mill must do.
 *
 * - At 10 % of critical speed the charge in a smooth drum rolls: its
 *   shoulder stays below 60° from the bottom and its toe at the bottom.
 * - Above critical speed (150 %), one layer of particles with high wall
 *   friction and lifters centrifuges: every particle stays on the shell (in
 *   the lifter zone) and turns round with the drum (balls may roll to and fro
 *   within their lifter compartment, so over a revolution each turns by the
 *   drum's angle within one lifter spacing).
 * - At 75 % of critical, in steady state (from the second revolution on), the
 *   mean power drawn equals ω M g x̄, the torque gravity exerts on the charge
 *   about the axis (the charge's angular momentum does not grow), and equals
 *   the rate at which the contacts dissipate energy (the charge's energy does
 *   not grow); both within 3 %.
 * The rolling regime needs a low filling: a rolling charge's surface is a
 * slope at the angle of repose β, so its shoulder sits at β plus half the
 * angle its segment spans, about 35° + 66° = 100° at 30 % filling but
 * 25° + 30° at 5 %. Monodisperse balls in a plane crystallise and are carried
 * up as a block, so the rolling charge is a 50/50 mix of two sizes.
 * Reduced sizes: a few hundred balls, so that the suite runs in seconds.
 */
#include <math.h>
#include <stdlib.h>

#include "testutil.h"

#define R_BALL 0.004 /* radius of the balls of the centrifuging and power tests */

typedef struct mill {
    demill_world *w;
    demill_id balls, liner, drum;
    int dim;
    double radius; /* of the shell */
} mill;

static double drum_get(const mill *m, int key)
{
    double v;
    DM_OK(m->w, demill_drum_get(m->w, m->drum, key, &v));
    return v;
}

/* Steel balls (Hertz, restitution 0.5, Mindlin friction μ) in a drum of the
 * same steel with the given wall friction and lifters, time step dt. */
static mill mill_make(int dim, double diameter, uint32_t lifters, double lifter_size, double mu,
                      double wall_friction, double dt)
{
    mill m = {0};
    m.dim = dim;
    m.radius = 0.5 * diameter;
    ck_assert_int_eq(demill_world_create(dim, &m.w), DEMILL_OK);
    demill_world *w = m.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_material_create(w, &m.balls));
    DM_OK(w, demill_material_create(w, &m.liner));
    const demill_id mats[2] = {m.balls, m.liner};
    for (int k = 0; k < 2; k++) {
        DM_OK(w, demill_material_set(w, mats[k], DEMILL_MATERIAL_DENSITY, 7800));
        DM_OK(w, demill_pair_set(w, m.balls, mats[k], DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
        DM_OK(w, demill_pair_set(w, m.balls, mats[k], DEMILL_PAIR_DAMPING,
                                 DEMILL_DAMPING_RESTITUTION));
        DM_OK(w, demill_pair_set(w, m.balls, mats[k], DEMILL_PAIR_TANGENTIAL,
                                 DEMILL_TANGENTIAL_MINDLIN));
    }
    DM_OK(w, demill_pair_set(w, m.balls, m.balls, DEMILL_PAIR_FRICTION, mu));
    DM_OK(w, demill_pair_set(w, m.balls, m.liner, DEMILL_PAIR_FRICTION, wall_friction));
    DM_OK(w, demill_drum_create(w, m.liner, &m.drum));
    DM_OK(w, demill_drum_set(w, m.drum, DEMILL_DRUM_DIAMETER, diameter));
    DM_OK(w, demill_drum_set(w, m.drum, DEMILL_DRUM_LENGTH, 0.03));
    DM_OK(w, demill_drum_set(w, m.drum, DEMILL_DRUM_LIFTER_HEIGHT, lifter_size));
    DM_OK(w, demill_drum_set(w, m.drum, DEMILL_DRUM_LIFTER_WIDTH, lifter_size));
    DM_OK(w, demill_drum_set(w, m.drum, DEMILL_DRUM_LIFTERS, lifters));
    return m;
}

/* A charge of bulk filling J from size classes (diameter, mass fraction
 * pairs), settled for 0.3 s. */
static void mill_fill(mill *m, const double *classes, size_t nclasses, double filling)
{
    if (m->dim == 2) /* a bed in the plane packs denser */
        DM_OK(m->w, demill_drum_set(m->w, m->drum, DEMILL_DRUM_FILL_POROSITY, 0.2));
    DM_OK(m->w, demill_drum_fill(m->w, m->drum, m->balls, DEMILL_SIZES_CLASSES, classes,
                                 2 * nclasses, DEMILL_FILL_FRACTION, filling, 42, NULL, 0, NULL));
    double dt;
    DM_OK(m->w, demill_world_get(m->w, DEMILL_WORLD_TIME_STEP, &dt));
    DM_OK(m->w, demill_world_step(m->w, (uint64_t)(0.3 / dt)));
}

/* Steps until the drum has turned `angle` more radians. */
static void turn(mill *m, double angle)
{
    const double end = drum_get(m, DEMILL_DRUM_ANGLE) + angle;
    while (drum_get(m, DEMILL_DRUM_ANGLE) < end)
        DM_OK(m->w, demill_world_step(m->w, 100));
}

static void rolls(int dim)
{
    /* 4 and 6 mm balls, μ = 0.3, in a smooth drum, filled to 5 % */
    mill m = mill_make(dim, dim == 3 ? 0.15 : 0.2, 0, 0.005, 0.3, 0.3, 1.25e-5);
    const double sizes[4] = {0.004, 0.5, 0.006, 0.5};
    mill_fill(&m, sizes, 2, 0.05);
    DM_OK(m.w, demill_drum_set(m.w, m.drum, DEMILL_DRUM_SPEED_FRACTION, 0.1));
    /* turn past the angle of repose, then sample the charge for 0.4 rad */
    turn(&m, 1.2);
    double shoulder = 0, toe = 0;
    const int samples = 20;
    for (int s = 0; s < samples; s++) {
        turn(&m, 0.02);
        shoulder += drum_get(&m, DEMILL_DRUM_SHOULDER_ANGLE) / samples;
        toe += drum_get(&m, DEMILL_DRUM_TOE_ANGLE) / samples;
    }
    ck_assert_msg(shoulder < M_PI / 3, "%dD at 10 %% critical: shoulder %.1f° (rolling: < 60°)",
                  dim, shoulder * 180 / M_PI);
    ck_assert_msg(toe > -M_PI / 2 && toe < 0, "%dD at 10 %% critical: toe %.1f° (at the bottom)",
                  dim, toe * 180 / M_PI);
    demill_world_destroy(m.w);
}

START_TEST(rolling_at_ten_percent_critical)
{
    rolls(2);
    rolls(3);
}
END_TEST

/* One layer of balls along the bottom of the shell, the drum brought to
 * 150 % of critical over one second. */
START_TEST(centrifuging_at_one_and_a_half_critical)
{
    const double lifter = 0.006, dt = 2e-5;
    mill m = mill_make(2, 0.2, 8, lifter, 0.5, 1.0, dt);
    const int n = 16;
    double pos[3 * 16], rad[16];
    for (int k = 0; k < n; k++) { /* touching the shell, 2.2 radii apart */
        const double phi = 1.5 * M_PI + (k - 0.5 * (n - 1)) * 2.2 * R_BALL / m.radius;
        const double r = m.radius - R_BALL - 1e-6;
        pos[3 * k] = r * cos(phi);
        pos[3 * k + 1] = r * sin(phi);
        pos[3 * k + 2] = 0;
        rad[k] = R_BALL;
    }
    /* lifters at 6 o'clock and ± 45° leave room: drop the balls that would
     * touch one, keeping one layer */
    demill_id ids[16];
    size_t placed = 0;
    for (int k = 0; k < n; k++)
        if (demill_particles_add(m.w, m.balls, 1, pos + 3 * k, rad + k, NULL,
                                 DEMILL_ADD_NO_OVERLAP, &ids[placed]) == DEMILL_OK)
            placed++;
    ck_assert_msg(placed >= 10, "only %zu balls fit on the shell", placed);
    DM_OK(m.w, demill_world_step(m.w, (uint64_t)(0.1 / dt)));
    DM_OK(m.w, demill_drum_set(m.w, m.drum, DEMILL_DRUM_RAMP_TIME, 1.0));
    DM_OK(m.w, demill_drum_set(m.w, m.drum, DEMILL_DRUM_SPEED_FRACTION, 1.5));
    DM_OK(m.w, demill_world_step(m.w, (uint64_t)(1.1 / dt)));
    const double omega = drum_get(&m, DEMILL_DRUM_CURRENT_SPEED);
    DM_ASSERT_REL(omega, 1.5 * drum_get(&m, DEMILL_DRUM_CRITICAL_SPEED), 1e-12);
    /* over a whole revolution, every ball stays within the lifter zone and
     * turns round with the drum */
    const double inner = m.radius - lifter - 2 * R_BALL;
    double turned[16] = {0}, last[16];
    for (size_t k = 0; k < placed; k++) {
        double x[3];
        DM_OK(m.w, demill_particle_get(m.w, ids[k], DEMILL_PARTICLE_POSITION, x));
        last[k] = atan2(x[1], x[0]);
    }
    for (int s = 0; s < 72; s++) {
        turn(&m, 2 * M_PI / 72);
        for (size_t k = 0; k < placed; k++) {
            double x[3];
            DM_OK(m.w, demill_particle_get(m.w, ids[k], DEMILL_PARTICLE_POSITION, x));
            const double r = hypot(x[0], x[1]), phi = atan2(x[1], x[0]);
            ck_assert_msg(r > inner, "ball %zu left the shell: r = %g m (shell %g m)", k, r,
                          m.radius);
            turned[k] += remainder(phi - last[k], 2 * M_PI);
            last[k] = phi;
        }
    }
    for (size_t k = 0; k < placed; k++)
        ck_assert_msg(fabs(turned[k] - 2 * M_PI) < 2 * M_PI / 8,
                      "ball %zu turned %.1f° while the drum turned 360°", k,
                      turned[k] * 180 / M_PI);
    demill_world_destroy(m.w);
}
END_TEST

/* Steady state at 75 %: per-revolution means of the power drawn (from the
 * torque on the drum), of ω M g x̄ and of the dissipation rate, over
 * revolutions 2 to 4. */
static void power_balance(int dim)
{
    mill m = mill_make(dim, dim == 3 ? 0.15 : 0.2, 6, 0.006, 0.5, 0.5, 2e-5);
    const double sizes[2] = {2 * R_BALL, 1.0};
    mill_fill(&m, sizes, 1, 0.3);
    DM_OK(m.w, demill_drum_set(m.w, m.drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    double power = 0, power_cm = 0, dissipation = 0;
    for (int rev = 1; rev <= 4; rev++) {
        while (drum_get(&m, DEMILL_DRUM_REVOLUTIONS) < rev)
            DM_OK(m.w, demill_world_step(m.w, 100));
        if (rev == 1)
            continue; /* the first revolution brings the charge into steady state */
        power += drum_get(&m, DEMILL_DRUM_POWER_MEAN) / 3;
        power_cm += drum_get(&m, DEMILL_DRUM_POWER_CM_MEAN) / 3;
        dissipation += drum_get(&m, DEMILL_DRUM_DISSIPATION_MEAN) / 3;
    }
    ck_assert_msg(power > 0, "%dD: the drum draws no power (%g W)", dim, power);
    ck_assert_msg(fabs(power_cm - power) < 0.03 * power,
                  "%dD: power %.4f W, ω M g x̄ %.4f W: differ by more than 3 %%", dim, power,
                  power_cm);
    ck_assert_msg(fabs(dissipation - power) < 0.03 * power,
                  "%dD: power %.4f W, dissipation %.4f W: differ by more than 3 %%", dim, power,
                  dissipation);
    demill_world_destroy(m.w);
}

START_TEST(power_balance_2d)
{
    power_balance(2);
}
END_TEST

START_TEST(power_balance_3d)
{
    power_balance(3);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("mill");
    TCase *tc = tcase_create("regimes");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, rolling_at_ten_percent_critical);
    tcase_add_test(tc, centrifuging_at_one_and_a_half_critical);
    tcase_add_test(tc, power_balance_2d);
    tcase_add_test(tc, power_balance_3d);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
