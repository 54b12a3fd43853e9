/* watchdog.c: the stability watchdog (DEMILL_WORLD_WATCHDOG).
 *
 * A box of particles on a linear spring k, of mass m each, is stable with
 * the explicit integrators for Δt < 2/ω, ω = √(k/m*) with m* = m/2 between
 * particles (the stiffest mode of one contact). At 1.5 times that the
 * motion grows without bound, which the watchdog must report as
 * DEMILL_ERR_UNSTABLE, leaving the world at the state of its last check
 * (compared bitwise with a twin world stepped to that time without the
 * watchdog), from which the run continues at a stable step. At 0.5 times
 * the limit the same scene runs with no report and no energy gain beyond the
 * integrator's bounded error. Without the watchdog the 1.5 times run is left
 * to blow up silently, which is what the watchdog is for.
 */
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

START_TEST(unstable_step_is_reported_and_undone)
{
    scene s = make(1), twin = make(0);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1.5 * s.dt_crit));
    DM_OK(twin.w, demill_world_set(twin.w, DEMILL_WORLD_TIME_STEP, 1.5 * s.dt_crit));
    demill_status st = demill_world_step(w, 100000);
    ck_assert_msg(st == DEMILL_ERR_UNSTABLE, "step gave %d: %s", (int)st,
                  demill_world_last_error(w));
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(strstr(msg, "particle 0x") && strstr(msg, "time step is too large") &&
                      strstr(msg, "back at t ="),
                  "message: %s", msg);
    /* back at a check: a whole number of intervals, the same state as a twin
     * stepped there without the watchdog */
    double steps;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &steps));
    ck_assert_msg(fmod(steps, 50) == 0, "back at step %g", steps);
    ck_assert_msg(steps < 100000, "back at step %g", steps);
    DM_OK(twin.w, demill_world_step(twin.w, (uint64_t)steps));
    for (int i = 0; i < N; i++)
        for (int f = DEMILL_PARTICLE_POSITION; f <= DEMILL_PARTICLE_VELOCITY; f++) {
            double a[3], b[3];
            DM_OK(w, demill_particle_get(w, s.ids[i], f, a));
            DM_OK(twin.w, demill_particle_get(twin.w, twin.ids[i], f, b));
            ck_assert_msg(!memcmp(a, b, sizeof a), "particle %d field %d differs", i, f);
        }
    /* the caller lowers the time step and carries on */
    const double e0 = total_energy(w);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 0.02 * s.dt_crit));
    DM_OK(w, demill_world_step(w, 5000));
    DM_ASSERT_REL(total_energy(w), e0, 0.05);
    demill_world_destroy(w);
    demill_world_destroy(twin.w);
}
END_TEST

START_TEST(without_watchdog_it_blows_up_silently)
{
    scene s = make(0);
    DM_OK(s.w, demill_world_set(s.w, DEMILL_WORLD_TIME_STEP, 1.5 * s.dt_crit));
    const double e0 = total_energy(s.w);
    DM_OK(s.w, demill_world_step(s.w, 3000));
    const double e1 = total_energy(s.w);
    ck_assert_msg(!(e1 < 10 * e0), "energy %g -> %g: the scene did not blow up", e0, e1);
    demill_world_destroy(s.w);
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
    tcase_add_test(tc, unstable_step_is_reported_and_undone);
    tcase_add_test(tc, without_watchdog_it_blows_up_silently);
    tcase_add_test(tc, stable_steps_pass);
    tcase_add_test(tc, deep_overlap_is_reported);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
