/* threads.c: the thread count does not change the results.
 *
 * Every sum the library takes over contacts is taken per particle in the
 * order of its pairs, whatever ranges the threads work on (docs/design.md),
 * so a run on 1, 2 or 3 threads must give bitwise the same particle state,
 * contact forces, energies and drum torque, and a run repeated on the same
 * thread count must give the same state again. The scenes are small turning
 * mills in 2D and 3D, large enough (a few thousand balls) that the particle
 * ranges, the neighbour search and the contact chunks are split between
 * threads, and long enough to rebuild the neighbour lists many times.
 * The iterative refinement is checked too (2D): its
 * convergence test counts particles, and its mean accelerations are summed
 * in particle order, so that it iterates alike on any thread count.
 * Without OpenMP world.threads > 1 is DEMILL_ERR_UNSUPPORTED; the test then
 * checks run-to-run reproducibility on one thread.
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define STEPS 15000 /* 0.15 s: the charge has fallen into a bed */

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

/* A 3D or 2D mill at 75 % of critical with 5 and 6 mm steel balls (Hertz,
 * Mindlin, restitution 0.5), filled to 30 %, run `steps` steps with
 * `integrator` on `threads`; 0 when the library has no threads. */
static int run(int dim, int integrator, uint64_t steps, int threads, outcome *o)
{
    demill_world *w;
    demill_id balls, liner, drum;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    const demill_status st = demill_world_set(w, DEMILL_WORLD_THREADS, threads);
    if (st == DEMILL_ERR_UNSUPPORTED) {
        demill_world_destroy(w);
        return 0;
    }
    DM_OK(w, st);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    dm_test_mill_materials(w, &balls, &liner);
    DM_OK(w, demill_drum_create(w, liner, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, dim == 3 ? 0.2 : 0.7));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.06));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 8));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, 0.01));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_WIDTH, 0.01));
    const double sizes[4] = {0.005, 0.5, 0.006, 0.5};
    DM_OK(w, demill_drum_fill(w, drum, balls, DEMILL_SIZES_CLASSES, sizes, 4,
                              DEMILL_FILL_FRACTION, 0.3, 7, NULL, 0, NULL));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    DM_OK(w, demill_world_step(w, steps));

    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, NULL, 0, &o->n));
    ck_assert_msg(o->n > 2048, "%zu balls: too few to split between threads", o->n);
    for (int f = 0; f < 5; f++) {
        o->fields[f] = malloc(3 * o->n * sizeof(double));
        ck_assert_ptr_nonnull(o->fields[f]);
        DM_OK(w, demill_particles_read(w, fields[f], o->fields[f], o->n, NULL));
    }
    for (int e = 0; e < 10; e++)
        DM_OK(w, demill_world_energy(w, e + 1, &o->energy[e]));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_TORQUE, &o->torque));
    double rebuilds;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS, &rebuilds));
    o->rebuilds = (uint64_t)rebuilds;
    double contacts;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &contacts));
    o->contacts = (uint64_t)contacts;
    demill_world_destroy(w);
    return 1;
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

static void check(int dim, int integrator, uint64_t steps)
{
    outcome one, again;
    ck_assert(run(dim, integrator, steps, 1, &one));
    ck_assert_msg(one.rebuilds > 20, "only %llu neighbour builds",
                  (unsigned long long)one.rebuilds);
    ck_assert_msg(one.contacts > one.n / 2, "only %llu contacts among %zu balls",
                  (unsigned long long)one.contacts, one.n);
    ck_assert(run(dim, integrator, steps, 1, &again));
    same(&one, &again, "1 thread, run twice");
    release(&again);
    for (int threads = 2; threads <= 3; threads++) {
        outcome many, repeat;
        if (!run(dim, integrator, steps, threads, &many))
            break; /* built without OpenMP */
        same(&one, &many, threads == 2 ? "2 threads against 1" : "3 threads against 1");
        ck_assert(run(dim, integrator, steps, threads, &repeat));
        same(&many, &repeat, "the same thread count, run twice");
        release(&many);
        release(&repeat);
    }
    release(&one);
}

START_TEST(same_results_on_any_thread_count_3d)
{
    check(3, DEMILL_INTEGRATOR_VELOCITY_VERLET, STEPS);
}
END_TEST

START_TEST(same_results_on_any_thread_count_2d)
{
    check(2, DEMILL_INTEGRATOR_VELOCITY_VERLET, STEPS);
}
END_TEST

START_TEST(same_results_on_any_thread_count_refinement)
{
    check(2, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT, STEPS);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("determinism");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, same_results_on_any_thread_count_3d);
    tcase_add_test(tc, same_results_on_any_thread_count_2d);
    tcase_add_test(tc, same_results_on_any_thread_count_refinement);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
