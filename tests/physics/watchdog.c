/* watchdog.c: the stability watchdog (DEMILL_WORLD_WATCHDOG).
 *
 * A box of particles on a linear spring k, of mass m each, is stable with
 * the explicit integrators for Δt < 2/ω, ω = √(k/m*) with m* = m/2 between
 * particles (the stiffest mode of one contact). Beyond that limit the
 * watchdog refuses to start the run, naming the pair and the limit, and
 * changes nothing. Within it, a scene whose contacts act together can still
 * be unstable: a chain of particles pressed between two walls has a mode
 * √2 times faster than one pair's (testutil.h), so at 0.9 of the pair limit
 * its motion grows without bound, which the watchdog must report as
 * DEMILL_ERR_UNSTABLE, leaving the world at the state of its last check
 * (compared bitwise with a twin world stepped to that time without the
 * watchdog), from which the run continues at a stable step; a call that
 * finds the failure never goes back past its own start, however long ago
 * the last check was, and no call returns DEMILL_OK on a state that fails
 * the checks. At 0.5 times the limit the box runs with no report and no
 * energy gain beyond the integrator's bounded error. Without the watchdog
 * the chain is left to blow up, but a call still fails once the state is not
 * finite.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define N 64

typedef struct scene {
    demill_world *w;
    demill_id ids[N];
    double dt_crit;
} scene;

/* N particles of radius 5 mm on a jittered grid in a box of four walls, no
 * gravity, random speeds of about 1 m/s; elastic linear contacts. */
static scene make(int watchdog)
{
    scene s;
    ck_assert_int_eq(demill_world_create(2, &s.w), DEMILL_OK);
    demill_world *w = s.w;
    demill_id m;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG, watchdog));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG_INTERVAL, 50));
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_NONE));
    const double r = 0.005, L = 0.2;
    const double planes[4][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {L, L, 0, -1}, {L, L, -1, 0}};
    for (int k = 0; k < 4; k++) {
        double p[3] = {planes[k][0], planes[k][1], 0}, n[3] = {planes[k][2], planes[k][3], 0};
        demill_id wall;
        DM_OK(w, demill_wall_add_plane(w, m, p, n, &wall));
    }
    double x[3 * N], v[3 * N], rad[N];
    srand(7);
    for (int i = 0; i < N; i++) {
        x[3 * i] = L * (i % 8 + 0.5) / 8;
        x[3 * i + 1] = L * (i / 8 + 0.5) / 8;
        x[3 * i + 2] = 0;
        v[3 * i] = 2.0 * rand() / RAND_MAX - 1.0;
        v[3 * i + 1] = 2.0 * rand() / RAND_MAX - 1.0;
        v[3 * i + 2] = 0;
        rad[i] = r;
    }
    DM_OK(w, demill_particles_add(w, m, N, x, rad, v, 0, s.ids));
    double k, mass = dm_test_get(w, s.ids[0], DEMILL_PARTICLE_MASS, 0);
    DM_OK(w, demill_pair_get(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, &k));
    s.dt_crit = 2.0 / sqrt(k / (mass / 2));
    double dt, crit; /* the limit the library states is the same */
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 0, &dt, &crit, NULL));
    DM_ASSERT_REL(crit, s.dt_crit, 1e-12);
    return s;
}

static double total_energy(demill_world *w)
{
    double e;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &e));
    return e;
}

/* The particles' positions and velocities of two worlds are bitwise equal. */
static void assert_same(demill_world *a, demill_world *b, const demill_id *ia,
                        const demill_id *ib, int n, const char *what)
{
    for (int i = 0; i < n; i++)
        for (int f = DEMILL_PARTICLE_POSITION; f <= DEMILL_PARTICLE_VELOCITY; f++) {
            double x[3], y[3];
            DM_OK(a, demill_particle_get(a, ia[i], f, x));
            DM_OK(b, demill_particle_get(b, ib[i], f, y));
            ck_assert_msg(!memcmp(x, y, sizeof x), "%s: particle %d field %d differs", what, i, f);
        }
}

static double step_count(demill_world *w)
{
    double steps;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &steps));
    return steps;
}

/* Beyond one pair's limit the run does not start: the message names the
 * pair and the limit, 2/ω to the printed digits, and nothing changes. */
START_TEST(time_step_beyond_a_pair_limit_is_refused)
{
    scene s = make(1);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1.5 * s.dt_crit));
    double before[3], after[3];
    DM_OK(w, demill_particle_get(w, s.ids[5], DEMILL_PARTICLE_POSITION, before));
    ck_assert_int_eq(demill_world_step(w, 100), DEMILL_ERR_UNSTABLE);
    char limit[160];
    snprintf(limit, sizeof limit, "largest stable time step of their normal spring and "
                                  "dashpot, %.6g s",
             s.dt_crit);
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(strstr(msg, limit) && strstr(msg, "particle-particle"), "message: %s", msg);
    DM_OK(w, demill_particle_get(w, s.ids[5], DEMILL_PARTICLE_POSITION, after));
    ck_assert(!memcmp(before, after, sizeof before) && step_count(w) == 0);
    /* within the limit it runs */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 0.5 * s.dt_crit));
    DM_OK(w, demill_world_step(w, 100));
    demill_world_destroy(w);
}
END_TEST

#define CHAIN 10

START_TEST(unstable_step_is_reported_and_undone)
{
    demill_id ids[CHAIN], twin_ids[CHAIN];
    demill_world *w = dm_test_chain(CHAIN, 0.9, ids), *twin = dm_test_chain(CHAIN, 0.9, twin_ids);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG_INTERVAL, 50));
    DM_OK(twin, demill_world_set(twin, DEMILL_WORLD_WATCHDOG, 0));
    demill_status st = demill_world_step(w, 100000);
    ck_assert_msg(st == DEMILL_ERR_UNSTABLE, "step gave %d: %s", (int)st,
                  demill_world_last_error(w));
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(strstr(msg, "particle 0x") && strstr(msg, "time step is too large") &&
                      strstr(msg, "back at t ="),
                  "message: %s", msg);
    /* back at a check: a whole number of intervals, the same state as a twin
     * stepped there without the watchdog */
    const double steps = step_count(w);
    ck_assert_msg(fmod(steps, 50) == 0 && steps < 100000, "back at step %g", steps);
    DM_OK(twin, demill_world_step(twin, (uint64_t)steps));
    assert_same(w, twin, ids, twin_ids, CHAIN, "back at the last check");
    /* the caller lowers the time step and carries on */
    const double e0 = total_energy(w);
    double dt;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 0.05 * dt));
    DM_OK(w, demill_world_step(w, 5000));
    DM_ASSERT_REL(total_energy(w), e0, 0.05);
    demill_world_destroy(w);
    demill_world_destroy(twin);
}
END_TEST

/* Calls of one step each, far fewer than the 500 steps between checks:
 * every call that returns DEMILL_OK leaves finite positions and velocities
 * and no energy created (beyond the integrator's error), and the call that
 * finds the failure puts the world back where it started, not at the last
 * check, bitwise as a twin stepped as many steps without the watchdog. */
START_TEST(rollback_never_passes_the_call_start)
{
    demill_id ids[CHAIN], twin_ids[CHAIN];
    demill_world *w = dm_test_chain(CHAIN, 0.9, ids), *twin = dm_test_chain(CHAIN, 0.9, twin_ids);
    DM_OK(twin, demill_world_set(twin, DEMILL_WORLD_WATCHDOG, 0));
    const double e0 = total_energy(w);
    int calls = 0;
    demill_status st;
    while ((st = demill_world_step(w, 1)) == DEMILL_OK) {
        calls++;
        ck_assert_msg(calls < 500, "the chain has not blown up in %d steps", calls);
        for (int i = 0; i < CHAIN; i++)
            for (int c = 0; c < 2; c++) {
                ck_assert(isfinite(dm_test_get(w, ids[i], DEMILL_PARTICLE_POSITION, c)));
                ck_assert(isfinite(dm_test_get(w, ids[i], DEMILL_PARTICLE_VELOCITY, c)));
            }
        ck_assert_msg(total_energy(w) < 5 * e0, "call %d returned OK with %g J of %g", calls,
                      total_energy(w), e0);
    }
    ck_assert_int_eq(st, DEMILL_ERR_UNSTABLE);
    ck_assert_msg(calls >= 2, "failed after %d calls", calls); /* past the last check */
    ck_assert_msg(strstr(demill_world_last_error(w), "where this call started"), "message: %s",
                  demill_world_last_error(w));
    ck_assert_msg(step_count(w) == calls, "back at step %g after %d calls", step_count(w), calls);
    DM_OK(twin, demill_world_step(twin, (uint64_t)calls));
    assert_same(w, twin, ids, twin_ids, CHAIN, "back at the start of the failing call");
    demill_world_destroy(w);
    demill_world_destroy(twin);
}
END_TEST

/* Without the watchdog nothing stops a run blowing up, but once its state
 * is no longer finite every call says so. One particle pressed between two
 * walls (a chain of one) at 1.5 times its limit gains energy at every step
 * in contact, and the faster it goes the more often it meets a wall. */
START_TEST(without_watchdog_only_a_state_not_finite_fails)
{
    demill_id ids[1];
    demill_world *w = dm_test_chain(1, 1.5, ids);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG, 0));
    const double e0 = total_energy(w);
    demill_status st;
    int calls = 0;
    double grown = 0.0;
    while ((st = demill_world_step(w, 10)) == DEMILL_OK && ++calls < 10000)
        grown = fmax(grown, total_energy(w) / e0);
    ck_assert_int_eq(st, DEMILL_ERR_UNSTABLE);
    ck_assert_msg(grown > 1e6, "energy grew %g times only", grown);
    ck_assert_msg(strstr(demill_world_last_error(w), "not finite") &&
                      strstr(demill_world_last_error(w), "watchdog off"),
                  "message: %s", demill_world_last_error(w));
    int finite = 1;
    finite &= isfinite(dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 0)) &&
              isfinite(dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0));
    ck_assert_msg(!finite, "the failure left a finite state");
    ck_assert_int_eq(demill_world_step(w, 1), DEMILL_ERR_UNSTABLE);
    demill_world_destroy(w);
}
END_TEST

/* At half the limit nothing is reported and the energy of the elastic gas
 * stays bounded (Verlet's shadow energy: no drift). At 0.9 of the pair limit
 * a particle pressed between two others (stiffest mode ω² = 3k/m, √1.5 above
 * the pair's) is already unstable: the run either stays bounded or is
 * reported, never silently wrong. */
START_TEST(stable_steps_pass)
{
    const double fractions[] = {0.5, 0.9};
    for (int k = 0; k < 2; k++) {
        scene s = make(1);
        DM_OK(s.w, demill_world_set(s.w, DEMILL_WORLD_TIME_STEP, fractions[k] * s.dt_crit));
        const double e0 = total_energy(s.w);
        const demill_status st = demill_world_step(s.w, 20000);
        ck_assert_msg(st == DEMILL_OK || (k == 1 && st == DEMILL_ERR_UNSTABLE),
                      "at %g of the limit: %s", fractions[k], demill_world_last_error(s.w));
        const double e1 = total_energy(s.w);
        ck_assert_msg(fabs(e1 - e0) < 0.5 * e0, "at %g of the limit: energy %g -> %g",
                      fractions[k], e0, e1);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* The overlap limit: two particles created overlapping by 60 % with a soft
 * spring stay beyond 25 % of their radius, which the first check reports
 * (naming both), returning the world to where the run started. */
START_TEST(deep_overlap_is_reported)
{
    demill_world *w;
    demill_id m, ids[2];
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, 1e-3));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG_INTERVAL, 100));
    const double r = 0.01, x[6] = {0, 0, 0, 1.4 * r, 0, 0}, rad[2] = {r, r};
    DM_OK(w, demill_particles_add(w, m, 2, x, rad, NULL, 0, ids));
    ck_assert_int_eq(demill_world_step(w, 200), DEMILL_ERR_UNSTABLE);
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(strstr(msg, "overlaps particle") && strstr(msg, "% of the smaller radius"),
                  "message: %s", msg);
    double t;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    ck_assert_double_eq(t, 0.0);
    /* a limit that allows it lets the run go on */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG_OVERLAP, 1.0));
    DM_OK(w, demill_world_step(w, 200));
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("watchdog");
    TCase *tc = tcase_create("watchdog");
    tcase_add_test(tc, time_step_beyond_a_pair_limit_is_refused);
    tcase_add_test(tc, unstable_step_is_reported_and_undone);
    tcase_add_test(tc, rollback_never_passes_the_call_start);
    tcase_add_test(tc, without_watchdog_only_a_state_not_finite_fails);
    tcase_add_test(tc, stable_steps_pass);
    tcase_add_test(tc, deep_overlap_is_reported);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
