/* threads.c: the thread count does not change the results.
 *
 * Every sum the library takes over contacts is taken per particle in the
 * order of its pairs, whatever ranges the threads work on and whichever
 * thread runs a range (docs/design.md, Threads), so a run on 1, 2 or 3
 * threads must give bitwise the same particle state, contact forces,
 * energies and drum torque, and a run repeated on the same thread count
 * must give the same state again. The scenes are small turning mills in 2D
 * and 3D, large enough (3,000-4,000 balls) that the particle ranges, the
 * neighbour search and the contact chunks are split between threads. Each
 * is filled and settled into a bed once, on one thread; the runs compared
 * start from that state (a snapshot) and are 1,500 steps long, enough for
 * many neighbour rebuilds with about one contact per ball.
 *
 * A world on several threads measures, as it steps, whether sharing its
 * loops out pays, and runs them on the calling thread alone (each loop one
 * range, as on one thread) when it does not (lib/base/threads.c). Its first
 * comparison is on a fixed schedule: the loops are shared for the first
 * 1,000 steps after the workers start, then for 200 steps more, and then
 * they run alone for 200 steps, whatever the machine's load. So each first
 * run on 2 and 3 threads goes through both ways, and a repeated run, on the
 * same workers, through a later part of the schedule; the results must not
 * change. The iterative refinement is checked too (2D): its convergence
 * test counts particles, and its mean accelerations are summed in particle
 * order, so that it iterates alike on any thread count.
 *
 * A world's workers through its life: the thread count changed between
 * steps (workers ended and started again) and a checkpoint loaded into a
 * world with workers must not change the results either.
 *
 * With DEMILL_LONG_TESTS=1 the runs compared also go the whole way from the
 * fill, 15,000 steps each (the charge falling, then in a bed), as the
 * suite did before it was shortened.
 *
 * Without threads world.threads > 1 is DEMILL_ERR_UNSUPPORTED; the test then
 * checks run-to-run reproducibility on one thread.
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define SETTLE 8000 /* 0.08 s from the fill: the charge has fallen into a bed */
#define STEPS 1500  /* the runs compared: past steps 1,200-1,400, which run alone */
#define LONG_STEPS 15000

/* What a run leaves: every particle field, the energies and the torque. */
typedef struct outcome {
    size_t n;
    double *fields[5];
    double energy[10], torque;
    uint64_t rebuilds, contacts;
} outcome;

static const int32_t fields[5] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                                  DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_FORCE,
                                  DEMILL_PARTICLE_TORQUE};

static double get(demill_world *w, int32_t key)
{
    double v;
    DM_OK(w, demill_world_get(w, key, &v));
    return v;
}

/* A 3D or 2D mill at 75 % of critical with 5 and 6 mm steel balls (Hertz,
 * Mindlin, restitution 0.5), filled to 30 %, on one thread, stepped
 * `settle` steps. */
static demill_world *mill(int dim, uint64_t settle, demill_id *drum)
{
    demill_world *w;
    demill_id balls, liner;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    dm_test_mill_materials(w, &balls, &liner);
    dm_test_mill(w, balls, liner, dim == 3 ? 0.2 : 0.7, 0.06, 0.01, drum);
    DM_OK(w, demill_world_step(w, settle));
    return w;
}

static void collect(demill_world *w, demill_id drum, outcome *o);

/* From `start`, `steps` steps with `integrator` on `threads`; 0 when the
 * library has no threads. */
static int run(demill_world *w, demill_id drum, const demill_snapshot *start, int integrator,
               uint64_t steps, int threads, outcome *o)
{
    const demill_status st = demill_world_set(w, DEMILL_WORLD_THREADS, threads);
    if (st == DEMILL_ERR_UNSUPPORTED)
        return 0;
    DM_OK(w, st);
    DM_OK(w, demill_snapshot_restore(w, start)); /* (keeps the thread count) */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    const double rebuilds = get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS);
    DM_OK(w, demill_world_step(w, steps));
    collect(w, drum, o);
    o->rebuilds = (uint64_t)(get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS) - rebuilds);
    return 1;
}

/* The world's state as it is now (all but the rebuilds). */
static void collect(demill_world *w, demill_id drum, outcome *o)
{
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, NULL, 0, &o->n));
    for (int f = 0; f < 5; f++) {
        o->fields[f] = malloc(3 * o->n * sizeof(double));
        ck_assert_ptr_nonnull(o->fields[f]);
        DM_OK(w, demill_particles_read(w, fields[f], o->fields[f], o->n, NULL));
    }
    for (int e = 0; e < 10; e++)
        DM_OK(w, demill_world_energy(w, e + 1, &o->energy[e]));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_TORQUE, &o->torque));
    o->contacts = (uint64_t)get(w, DEMILL_WORLD_CONTACT_COUNT);
}

static void release(outcome *o)
{
    for (int f = 0; f < 5; f++)
        free(o->fields[f]);
}

/* Bitwise equality of two outcomes (memcmp: -0.0 and 0.0 differ too). */
static void same(const outcome *a, const outcome *b, const char *what)
{
    ck_assert_uint_eq(a->n, b->n);
    for (int f = 0; f < 5; f++)
        for (size_t k = 0; k < 3 * a->n; k++)
            ck_assert_msg(!memcmp(&a->fields[f][k], &b->fields[f][k], sizeof(double)),
                          "%s: field %d of particle %zu differs: %.17g vs %.17g", what,
                          (int)fields[f], k / 3, a->fields[f][k], b->fields[f][k]);
    for (int e = 0; e < 10; e++)
        ck_assert_msg(!memcmp(&a->energy[e], &b->energy[e], sizeof(double)),
                      "%s: energy term %d differs: %.17g vs %.17g", what, e + 1, a->energy[e],
                      b->energy[e]);
    ck_assert_msg(!memcmp(&a->torque, &b->torque, sizeof(double)),
                  "%s: torque differs: %.17g vs %.17g", what, a->torque, b->torque);
}

/* The mill settled `settle` steps, then `steps` steps with `integrator` on
 * 1, 1, 2, 2, 3 and 3 threads, compared. */
static void check(int dim, int integrator, uint64_t settle, uint64_t steps)
{
    demill_id drum;
    demill_world *w = mill(dim, settle, &drum);
    demill_snapshot *start;
    DM_OK(w, demill_snapshot_take(w, &start));
    outcome one, again;
    ck_assert(run(w, drum, start, integrator, steps, 1, &one));
    ck_assert_msg(one.n > 2048, "%zu balls: too few to split between threads", one.n);
    ck_assert_msg(one.rebuilds >= 4, "only %llu neighbour builds",
                  (unsigned long long)one.rebuilds);
    ck_assert_msg(one.contacts > one.n / 2, "only %llu contacts among %zu balls",
                  (unsigned long long)one.contacts, one.n);
    ck_assert(run(w, drum, start, integrator, steps, 1, &again));
    same(&one, &again, "1 thread, run twice");
    release(&again);
    for (int threads = 2; threads <= 3; threads++) {
        outcome many, repeat;
        if (!run(w, drum, start, integrator, steps, threads, &many))
            break; /* built without threads */
        same(&one, &many, threads == 2 ? "2 threads against 1" : "3 threads against 1");
        ck_assert(run(w, drum, start, integrator, steps, threads, &repeat));
        same(&many, &repeat, "the same thread count, run twice");
        release(&many);
        release(&repeat);
    }
    release(&one);
    demill_snapshot_free(start);
    demill_world_destroy(w);
}

START_TEST(same_results_on_any_thread_count_3d)
{
    check(3, DEMILL_INTEGRATOR_VELOCITY_VERLET, SETTLE, STEPS);
}
END_TEST

START_TEST(same_results_on_any_thread_count_2d)
{
    check(2, DEMILL_INTEGRATOR_VELOCITY_VERLET, SETTLE, STEPS);
}
END_TEST

START_TEST(same_results_on_any_thread_count_refinement)
{
    check(2, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT, SETTLE, STEPS);
}
END_TEST

/* A world's workers through its life: 600 steps on one thread against the
 * same 600 steps on 2 threads (200), a checkpoint of that state loaded back
 * into the world, whose workers go on, after 50 steps that the load undoes,
 * then 3 threads (200: new workers), 1 (100: none) and 2 again (100). */
START_TEST(same_results_when_the_threads_change)
{
    demill_id drum;
    demill_world *w = mill(2, SETTLE, &drum);
    demill_snapshot *start;
    DM_OK(w, demill_snapshot_take(w, &start));
    outcome one, changed;
    ck_assert(run(w, drum, start, DEMILL_INTEGRATOR_VELOCITY_VERLET, 600, 1, &one));
    if (run(w, drum, start, DEMILL_INTEGRATOR_VELOCITY_VERLET, 200, 2, &changed)) {
        release(&changed);
        size_t size;
        DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
        void *checkpoint = malloc(size);
        ck_assert_ptr_nonnull(checkpoint);
        DM_OK(w, demill_world_save_buffer(w, checkpoint, size, NULL));
        DM_OK(w, demill_world_step(w, 50));
        DM_OK(w, demill_world_load_buffer(w, checkpoint, size));
        free(checkpoint);
        static const int threads[3] = {3, 1, 2};
        static const uint64_t steps[3] = {200, 100, 100};
        for (int k = 0; k < 3; k++) {
            DM_OK(w, demill_world_set(w, DEMILL_WORLD_THREADS, threads[k]));
            DM_OK(w, demill_world_step(w, steps[k]));
        }
        collect(w, drum, &changed);
        same(&one, &changed, "threads changed on the way, and a checkpoint loaded");
        release(&changed);
    }
    release(&one);
    demill_snapshot_free(start);
    demill_world_destroy(w);
}
END_TEST

/* DEMILL_LONG_TESTS=1: every thread count the whole way from the fill. */
START_TEST(same_results_from_the_fill)
{
    static const int dims[3] = {3, 2, 2};
    static const int integrators[3] = {DEMILL_INTEGRATOR_VELOCITY_VERLET,
                                       DEMILL_INTEGRATOR_VELOCITY_VERLET,
                                       DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT};
    check(dims[_i], integrators[_i], 0, LONG_STEPS);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("determinism");
    tcase_set_timeout(tc, 300); /* as tests/CMakeLists.txt, for runs outside CTest */
    tcase_add_test(tc, same_results_on_any_thread_count_3d);
    tcase_add_test(tc, same_results_on_any_thread_count_2d);
    tcase_add_test(tc, same_results_on_any_thread_count_refinement);
    tcase_add_test(tc, same_results_when_the_threads_change);
    suite_add_tcase(s, tc);
    if (getenv("DEMILL_LONG_TESTS") && atoi(getenv("DEMILL_LONG_TESTS"))) {
        TCase *full = tcase_create("from the fill");
        tcase_set_timeout(full, 1800);
        tcase_add_loop_test(full, same_results_from_the_fill, 0, 3);
        suite_add_tcase(s, full);
    }
    return dm_test_run(s);
}
