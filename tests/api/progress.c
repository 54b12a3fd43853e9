/* progress.c: the progress callback (demill_world_set_progress).
 *
 * The scene is a small mill that exercises every part of a step: 3D, a
 * drum with lifters turning at half its critical speed, a plane wall below
 * it, gravity, and 48 balls with Hertz-Mindlin contacts (so rotation is
 * integrated), starting in free fall so that contacts form during the test.
 * Checked:
 *  - the reports of steps = 1000, every 300 are steps_done = 300, 600, 900,
 *    1000 with steps_total 1000, the world's time (k Δt to round-off, and
 *    bitwise the time of a twin run of k steps), a positive rate and the
 *    user's pointer; a multiple (600 = 2 × 300) is reported once, a short
 *    run (100) once at its end, a run of 0 steps never;
 *  - a callback that returns nonzero at 600 stops the run there with
 *    DEMILL_ERR_INTERRUPTED, a message naming the step, and the world at
 *    step 600; stepping the remaining 400 gives bitwise the state of an
 *    uninterrupted run of 1000 steps without a callback (positions,
 *    velocities, angular velocities, forces), for all three integrators and
 *    with the watchdog checking in between; a nonzero return at the end is
 *    ignored;
 *  - a callback that changes the world (a particle's velocity) gives what
 *    the same change between two calls gives, bitwise;
 *  - a run the watchdog finds unstable returns DEMILL_ERR_UNSTABLE with the
 *    world at the same last good state as without a callback;
 *  - NULL removes the callback; every_steps = 0 with a callback is
 *    DEMILL_ERR_INVALID_VALUE and keeps the callback that was set; a NULL
 *    world is DEMILL_ERR_NULL_POINTER (tests/api/bad_input.c has the rest).
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define NP 48
#define MAX_REPORTS 16

typedef struct report {
    uint64_t done, total;
    double time, rate;
    void *user;
} report;

/* What a callback saw, and what it should do. */
typedef struct recorder {
    report r[MAX_REPORTS];
    int n;
    int stop_at;           /* return nonzero at this report (1-based), 0: never */
    demill_world *w;       /* for change_velocity */
    demill_id particle;
} recorder;

static int32_t record(void *user, uint64_t done, uint64_t total, double time, double rate)
{
    recorder *rec = user;
    ck_assert_int_lt(rec->n, MAX_REPORTS);
    rec->r[rec->n++] = (report){done, total, time, rate, user};
    return rec->n == rec->stop_at;
}

static const double new_velocity[3] = {0.3, -0.2, 0.1};

static int32_t change_velocity(void *user, uint64_t done, uint64_t total, double time,
                               double rate)
{
    recorder *rec = user;
    record(user, done, total, time, rate);
    if (rec->n == 1)
        DM_OK(rec->w, demill_particle_set(rec->w, rec->particle, DEMILL_PARTICLE_VELOCITY,
                                          new_velocity));
    return 0;
}

typedef struct scene {
    demill_world *w;
    demill_id ids[NP];
} scene;

static scene make(int integrator)
{
    scene s;
    demill_id steel, drum, floor;
    ck_assert_int_eq(demill_world_create(3, &s.w), DEMILL_OK);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-5));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG_INTERVAL, 250));
    DM_OK(w, demill_material_create(w, &steel));
    DM_OK(w, demill_material_set(w, steel, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, steel, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e8));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_drum_create(w, steel, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.1));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.03));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, 0.008));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 4));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.5));
    const double p[3] = {0, -0.2, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, steel, p, n, &floor));
    double x[3 * NP], r[NP], v[3 * NP];
    for (int i = 0; i < NP; i++) {
        x[3 * i] = -0.021 + 0.0084 * (i % 6);
        x[3 * i + 1] = -0.03 + 0.0084 * (i / 6 % 4);
        x[3 * i + 2] = i < 24 ? -0.005 : 0.005;
        r[i] = 0.004 - 0.0001 * (i % 5);
        v[3 * i] = 0.05 * (i % 3 - 1);
        v[3 * i + 1] = -0.3;
        v[3 * i + 2] = 0.02 * (i % 2);
    }
    DM_OK(w, demill_particles_add(w, steel, NP, x, r, v, DEMILL_ADD_NO_OVERLAP, s.ids));
    return s;
}

/* Every particle's position, velocity, angular velocity and force, in id
 * order (12 doubles each). */
static void state(demill_world *w, double out[12 * NP])
{
    const int32_t fields[4] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                               DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_FORCE};
    size_t n;
    for (int f = 0; f < 4; f++) {
        DM_OK(w, demill_particles_read(w, fields[f], out + 3 * NP * f, NP, &n));
        ck_assert_uint_eq(n, NP);
    }
}

static void assert_same_state(demill_world *a, demill_world *b, const char *what)
{
    static double sa[12 * NP], sb[12 * NP];
    state(a, sa);
    state(b, sb);
    ck_assert_msg(!memcmp(sa, sb, sizeof sa), "%s: the states differ", what);
    double ta, tb;
    DM_OK(a, demill_world_get(a, DEMILL_WORLD_TIME, &ta));
    DM_OK(b, demill_world_get(b, DEMILL_WORLD_TIME, &tb));
    ck_assert_msg(ta == tb, "%s: time %.17g, expected %.17g", what, ta, tb);
}

static double world_value(demill_world *w, int32_t key)
{
    double v;
    DM_OK(w, demill_world_get(w, key, &v));
    return v;
}

START_TEST(reports)
{
    scene s = make(DEMILL_INTEGRATOR_VELOCITY_VERLET), twin = make(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_world *w = s.w;
    const double dt = world_value(w, DEMILL_WORLD_TIME_STEP);
    recorder rec = {.n = 0};
    DM_OK(w, demill_world_set_progress(w, record, &rec, 300));
    DM_OK(w, demill_world_step(w, 1000));
    const uint64_t want[4] = {300, 600, 900, 1000};
    ck_assert_int_eq(rec.n, 4);
    uint64_t twin_steps = 0;
    for (int k = 0; k < 4; k++) {
        const report *r = &rec.r[k];
        ck_assert_msg(r->done == want[k], "report %d: steps_done %llu, expected %llu", k,
                      (unsigned long long)r->done, (unsigned long long)want[k]);
        ck_assert_uint_eq(r->total, 1000);
        ck_assert_ptr_eq(r->user, &rec);
        ck_assert_msg(isfinite(r->rate) && r->rate > 0, "report %d: rate %g", k, r->rate);
        DM_ASSERT_REL(r->time, r->done * dt, 1e-12);
        DM_OK(twin.w, demill_world_step(twin.w, r->done - twin_steps));
        twin_steps = r->done;
        ck_assert_msg(r->time == world_value(twin.w, DEMILL_WORLD_TIME),
                      "report %d: time %.17g is not the world's time after %llu steps", k,
                      r->time, (unsigned long long)r->done);
    }
    ck_assert(world_value(w, DEMILL_WORLD_STEP_COUNT) == 1000);

    /* an exact multiple is reported once; a short run at its end; 0 steps never */
    const struct {
        uint64_t steps, every;
        int reports;
        uint64_t last;
    } runs[] = {{600, 300, 2, 600}, {100, 300, 1, 100}, {0, 300, 0, 0}, {7, 1, 7, 7}};
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        rec.n = 0;
        DM_OK(w, demill_world_set_progress(w, record, &rec, runs[k].every));
        DM_OK(w, demill_world_step(w, runs[k].steps));
        ck_assert_msg(rec.n == runs[k].reports, "steps %llu every %llu: %d reports, expected %d",
                      (unsigned long long)runs[k].steps, (unsigned long long)runs[k].every,
                      rec.n, runs[k].reports);
        if (rec.n)
            ck_assert_uint_eq(rec.r[rec.n - 1].done, runs[k].last);
    }

    /* NULL removes it (every_steps is then ignored) */
    rec.n = 0;
    DM_OK(w, demill_world_set_progress(w, NULL, &rec, 0));
    DM_OK(w, demill_world_step(w, 50));
    ck_assert_int_eq(rec.n, 0);
    demill_world_destroy(w);
    demill_world_destroy(twin.w);
}
END_TEST

static const int integrators[3] = {DEMILL_INTEGRATOR_VELOCITY_VERLET,
                                   DEMILL_INTEGRATOR_SYMPLECTIC_EULER,
                                   DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT};

START_TEST(interrupt_and_go_on)
{
    const int integrator = integrators[_i];
    scene s = make(integrator), twin = make(integrator);
    demill_world *w = s.w;
    recorder rec = {.stop_at = 2};
    DM_OK(w, demill_world_set_progress(w, record, &rec, 300));
    ck_assert_int_eq(demill_world_step(w, 1000), DEMILL_ERR_INTERRUPTED);
    ck_assert_int_eq(rec.n, 2);
    ck_assert_uint_eq(rec.r[1].done, 600);
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(strstr(msg, "600") && strstr(msg, "progress callback"),
                  "message \"%s\" does not say where the run stopped", msg);
    ck_assert(world_value(w, DEMILL_WORLD_STEP_COUNT) == 600);
    ck_assert(world_value(w, DEMILL_WORLD_TIME) == rec.r[1].time);

    /* the rest of the run, still reporting; the end ignores a stop */
    rec.n = 0;
    rec.stop_at = 2;
    DM_OK(w, demill_world_step(w, 400));
    ck_assert_int_eq(rec.n, 2);
    ck_assert_uint_eq(rec.r[1].done, 400);
    DM_OK(twin.w, demill_world_step(twin.w, 1000));
    assert_same_state(w, twin.w, "interrupted at 600 and stepped 400 more");
    demill_world_destroy(w);
    demill_world_destroy(twin.w);
}
END_TEST

START_TEST(callback_changes_the_world)
{
    scene s = make(DEMILL_INTEGRATOR_VELOCITY_VERLET), twin = make(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_world *w = s.w;
    recorder rec = {.w = w, .particle = s.ids[5]};
    DM_OK(w, demill_world_set_progress(w, change_velocity, &rec, 300));
    DM_OK(w, demill_world_step(w, 1000));
    ck_assert_int_eq(rec.n, 4);
    DM_OK(twin.w, demill_world_step(twin.w, 300));
    DM_OK(twin.w, demill_particle_set(twin.w, twin.ids[5], DEMILL_PARTICLE_VELOCITY, new_velocity));
    DM_OK(twin.w, demill_world_step(twin.w, 700));
    assert_same_state(w, twin.w, "a velocity set by the callback at step 300");
    demill_world_destroy(w);
    demill_world_destroy(twin.w);
}
END_TEST

/* A chain of particles pressed between two walls at 0.9 of one pair's
 * stability limit blows up (testutil.h): the watchdog reports it at a check,
 * with or without a callback, and puts the world back at the same state. */
START_TEST(unstable_run_with_callback)
{
    enum { N = 10 };
    demill_id ids[N], twin_ids[N];
    demill_world *w = dm_test_chain(N, 0.9, ids), *twin = dm_test_chain(N, 0.9, twin_ids);
    recorder rec = {.n = 0};
    DM_OK(w, demill_world_set_progress(w, record, &rec, 1));
    for (int k = 0; k < 2; k++) {
        demill_world *x = k ? twin : w;
        DM_OK(x, demill_world_set(x, DEMILL_WORLD_WATCHDOG_INTERVAL, 25));
        ck_assert_int_eq(demill_world_step(x, 5000), DEMILL_ERR_UNSTABLE);
    }
    ck_assert_int_gt(rec.n, 0);
    ck_assert_int_lt(rec.n, 5000);
    ck_assert(world_value(w, DEMILL_WORLD_STEP_COUNT) ==
              world_value(twin, DEMILL_WORLD_STEP_COUNT));
    for (int i = 0; i < N; i++)
        for (int f = DEMILL_PARTICLE_POSITION; f <= DEMILL_PARTICLE_VELOCITY; f++) {
            double a[3], b[3];
            DM_OK(w, demill_particle_get(w, ids[i], f, a));
            DM_OK(twin, demill_particle_get(twin, twin_ids[i], f, b));
            ck_assert_msg(!memcmp(a, b, sizeof a), "particle %d field %d differs", i, f);
        }
    demill_world_destroy(w);
    demill_world_destroy(twin);
}
END_TEST

START_TEST(bad_arguments)
{
    scene s = make(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_world *w = s.w;
    recorder rec = {.n = 0}, other = {.n = 0};
    ck_assert_int_eq(demill_world_set_progress(NULL, record, &rec, 10), DEMILL_ERR_NULL_POINTER);
    DM_OK(w, demill_world_set_progress(w, record, &rec, 10));
    ck_assert_int_eq(demill_world_set_progress(w, record, &other, 0), DEMILL_ERR_INVALID_VALUE);
    ck_assert_msg(strstr(demill_world_last_error(w), "every_steps"), "message \"%s\"",
                  demill_world_last_error(w));
    DM_OK(w, demill_world_step(w, 20)); /* the first callback stays */
    ck_assert_int_eq(rec.n, 2);
    ck_assert_int_eq(other.n, 0);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("progress");
    TCase *tc = tcase_create("progress");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, reports);
    tcase_add_loop_test(tc, interrupt_and_go_on, 0, 3);
    tcase_add_test(tc, callback_changes_the_world);
    tcase_add_test(tc, unstable_run_with_callback);
    tcase_add_test(tc, bad_arguments);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
