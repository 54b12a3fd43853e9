/* single.c: the single-precision contact kernels (world.single_precision).
 *
 * The kernels round each contact's kinematics to float and run the law in
 * float (docs/design.md, Contact kernels; docs/accuracy.md, Single
 * precision). What must hold:
 *
 * - A binary impact gives the analytic restitution and Hertz duration
 *   within the tolerances tests/physics/collision.c holds double to (the
 *   classic spring-dashpot's e; Johnson 1985, Contact Mechanics §11.4, for
 *   Hertz), and within float's round-off of the double kernels' own
 *   answer: the rebound is the sum of about 50 impulses (Δt = t_c/50), each
 *   the law's force rounded a few times (say 3) to float's unit round-off
 *   u = 2^-24 = 6.0e-8. Errors of one sign all along would give
 *   50 × 3 u = 9e-6 of the rebound; independent ones, √50 × 3 u = 1.3e-6.
 *   Held to 2e-6 (measured: at most 5.7e-8, about u, on every case).
 * - The energy balance closes in a turning mill (Hertz, Mindlin, Tsuji
 *   damping, constant-torque rolling resistance): the drum's work goes into
 *   kinetic, potential and stored energy and the dissipation by mechanism,
 *   each contact's share of which the float law computes. In double the
 *   balance (DEMILL_ENERGY_TOTAL) strays by the integration error of the
 *   time step, 5.5e-4 of the drum's work W here; float's round-off adds a
 *   few u of each contact's energy per step in no particular direction,
 *   orders below it. So the single run's balance must stray by no more than
 *   1.1 times the double run's (and that by no more than 1e-3 W), whose
 *   trajectory is another (the flow is chaotic) with the same step.
 * - Runs on 1 and 2 threads give bitwise the same state, as in double
 *   (tests/physics/threads.c): the float path changes the arithmetic, not
 *   the order of the sums.
 * - The precision is kept by snapshots and checkpoints (format 6).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define PHASES 8

/* The rebound of two spheres in double and in single precision from entry
 * phase p, Verlet at dt, material m's pair with itself. */
static void collide_both(demill_world *w, demill_id m, double r, double v0, double dt, int p,
                         dm_collision *dbl, dm_collision *sgl)
{
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_SINGLE_PRECISION, 0));
    *dbl = dm_test_collide(w, m, r, v0, dt, (p + 0.5) / PHASES, 0.0);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_SINGLE_PRECISION, 1));
    *sgl = dm_test_collide(w, m, r, v0, dt, (p + 0.5) / PHASES, 0.0);
}

/* The linear spring-dashpot at e = 0.5 (clamped, the default): e within 1 %
 * of the analytic value, as in double, and within 2e-6 of double's. */
START_TEST(linear_restitution_in_single)
{
    for (int dim = 2; dim <= 3; dim++) {
        demill_id m;
        demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.5));
        const double r = 0.005, k = 5e4, e = 0.5;
        const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * 2500;
        const double l = log(e), xi = -l / sqrt(M_PI * M_PI + l * l);
        const double tc = M_PI / (sqrt(k / mstar) * sqrt(1 - xi * xi));
        for (int p = 0; p < PHASES; p++) {
            dm_collision d, s;
            collide_both(w, m, r, 1.0, tc / 50, p, &d, &s);
            DM_ASSERT_REL(s.restitution, e, 0.01);
            DM_ASSERT_REL(s.restitution, d.restitution, 2e-6);
            ck_assert_msg(s.restitution != d.restitution,
                          "%dD phase %d: single gave double's e to the bit (%.17g): is it on?",
                          dim, p, s.restitution);
        }
        demill_world_destroy(w);
    }
}
END_TEST

/* Hertz with Tsuji's damping at e = 0.5 (2 % as collision.c), and elastic
 * Hertz: the duration within 2 % of 2.94324 δ_max / v, e within 1 % of 1. */
START_TEST(hertz_impact_in_single)
{
    for (int dim = 2; dim <= 3; dim++) {
        const double r = 0.003, estar = 1e8 / (2 * (1 - 0.09)), v0 = 1.0;
        const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * 2500;
        const double dmax = pow(15 * mstar * v0 * v0 / (16 * estar * sqrt(r / 2)), 0.4);
        const double tc = 2.94324 * dmax / v0;
        for (int damped = 0; damped <= 1; damped++) {
            demill_id m;
            demill_world *w = dm_test_world(
                dim, DEMILL_NORMAL_HERTZ, damped ? DEMILL_DAMPING_RESTITUTION : DEMILL_DAMPING_NONE,
                &m);
            DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.5));
            for (int p = 0; p < PHASES; p++) {
                dm_collision d, s;
                collide_both(w, m, r, v0, tc / 50, p, &d, &s);
                DM_ASSERT_REL(s.restitution, damped ? 0.5 : 1.0, damped ? 0.02 : 0.01);
                DM_ASSERT_REL(s.restitution, d.restitution, 2e-6);
                if (!damped) {
                    DM_ASSERT_REL(s.duration, tc, 0.02);
                    DM_ASSERT_REL(s.max_overlap, dmax, 0.02);
                    DM_ASSERT_REL(s.duration, d.duration, 2e-6);
                }
            }
            demill_world_destroy(w);
        }
    }
}
END_TEST

/* A 3D mill of 5 and 6 mm steel balls (Hertz, Mindlin, e = 0.5, rolling
 * friction 0.05) at 75 % of critical, filled to 30 % (about 1,300 balls:
 * more than two ranges of 512, so that 2 threads split the work), settled
 * `settle` steps in the given precision. */
static demill_world *mill(int single, uint64_t settle, demill_id *drum)
{
    demill_world *w;
    demill_id balls, liner;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_SINGLE_PRECISION, single));
    dm_test_mill_materials(w, &balls, &liner);
    DM_OK(w, demill_pair_set(w, balls, balls, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    DM_OK(w, demill_pair_set(w, balls, balls, DEMILL_PAIR_ROLLING_FRICTION, 0.05));
    dm_test_mill(w, balls, liner, 0.16, 0.04, 0.008, drum);
    DM_OK(w, demill_world_step(w, settle));
    return w;
}

/* The balance's largest change over 20,000 steps (0.2 s) of the turning
 * mill, as a fraction of the drum's work over them. */
static double balance_stray(int single)
{
    demill_id drum;
    demill_world *w = mill(single, 5000, &drum);
    const double b0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double w0 = dm_test_energy(w, DEMILL_ENERGY_WALL_WORK);
    double worst = 0;
    for (int s = 0; s < 40; s++) {
        DM_OK(w, demill_world_step(w, 500));
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - b0));
    }
    const double work = dm_test_energy(w, DEMILL_ENERGY_WALL_WORK) - w0;
    ck_assert_msg(work > 0, "the drum did no work (%g J)", work);
    demill_world_destroy(w);
    return worst / work;
}

START_TEST(mill_energy_balance_in_single)
{
    const double dbl = balance_stray(0), sgl = balance_stray(1);
    ck_assert_msg(dbl < 1e-3, "double: the balance strayed by %.3g of the drum's work", dbl);
    ck_assert_msg(sgl < 1.1 * dbl, "single: the balance strayed by %.3g of the drum's work, "
                  "double by %.3g", sgl, dbl);
}
END_TEST

/* Every particle's position, velocity, angular velocity, force and torque
 * and the energy terms 1 to 12 after `steps` steps from snapshot start on
 * `threads` threads, in one array (free it); 0 without threads. */
static double *run_on(demill_world *w, const demill_snapshot *start, int threads, size_t *len)
{
    const demill_status st = demill_world_set(w, DEMILL_WORLD_THREADS, threads);
    if (st == DEMILL_ERR_UNSUPPORTED)
        return NULL;
    DM_OK(w, st);
    DM_OK(w, demill_snapshot_restore(w, start));
    DM_OK(w, demill_world_step(w, 1500));
    static const int32_t fields[5] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                                      DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_FORCE,
                                      DEMILL_PARTICLE_TORQUE};
    size_t n;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, NULL, 0, &n));
    ck_assert_msg(n > 2 * 512, "%zu balls: too few for 2 ranges of 512", n);
    *len = 15 * n + 12;
    double *o = malloc(*len * sizeof *o);
    ck_assert_ptr_nonnull(o);
    for (int f = 0; f < 5; f++)
        DM_OK(w, demill_particles_read(w, fields[f], o + 3 * n * f, n, NULL));
    for (int e = 0; e < 12; e++)
        o[15 * n + e] = dm_test_energy(w, e + 1);
    return o;
}

/* 1,500 steps: past the first comparison of shared and unshared loops
 * (steps 1,200-1,400 run alone, lib/base/threads.c), as threads.c. */
START_TEST(threads_bitwise_in_single)
{
    demill_id drum;
    demill_world *w = mill(1, 3000, &drum);
    demill_snapshot *start;
    DM_OK(w, demill_snapshot_take(w, &start));
    size_t n1, n2;
    double *one = run_on(w, start, 1, &n1), *two = run_on(w, start, 2, &n2);
    if (two) {
        ck_assert_uint_eq(n1, n2);
        ck_assert_msg(!memcmp(one, two, n1 * sizeof *one),
                      "single precision: 1 and 2 threads differ");
    }
    free(one);
    free(two);
    demill_snapshot_free(start);
    demill_world_destroy(w);
}
END_TEST

/* The precision is part of the state: a checkpoint loaded and a snapshot
 * restored step on bitwise as the world they came from, in single
 * precision (a copy that ran double would differ at the first contact). */
static void copy_is_single(demill_world *w, demill_world *copy, int way, void *ctx)
{
    (void)w, (void)ctx;
    double single;
    DM_OK(copy, demill_world_get(copy, DEMILL_WORLD_SINGLE_PRECISION, &single));
    ck_assert_msg(single == 1.0, "%s: world.single_precision = %g",
                  way ? "snapshot" : "checkpoint", single);
}

START_TEST(copies_keep_single)
{
    demill_id drum;
    demill_world *w = mill(1, 1000, &drum);
    dm_test_copies_run_on(w, 500, copy_is_single, NULL);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("single");
    TCase *tc = tcase_create("single");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, linear_restitution_in_single);
    tcase_add_test(tc, hertz_impact_in_single);
    tcase_add_test(tc, mill_energy_balance_in_single);
    tcase_add_test(tc, threads_bitwise_in_single);
    tcase_add_test(tc, copies_keep_single);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
