/* checkpoint_v1.c: a checkpoint of format 1, written before the drum's
 * impact counters were appended to its collision spectrum (format 2),
 * still loads with its spectrum, and the world steps on from it.
 *
 * The fixture data/checkpoint-v1-spectrum.bin (17,691 bytes) was written by
 * the library at commit 665c1e5, the last whose checkpoints are of format 1,
 * built on its own outside this repository. Its program: a 3D world, one
 * steel material (density 7800, friction 0.5; Hertz, restitution damping,
 * Mindlin), a drum of diameter 0.08 m and length 0.024 m with 3 lifters of
 * that material, filled with 14 balls of 12 mm (DEMILL_SIZES_CLASSES
 * {0.012, 1}, DEMILL_FILL_COUNT 14, seed 1), 20,000 steps of the default
 * 1e-5 s for the balls to fall, the speed set to 75 % of critical, the
 * spectrum started with one size class and 16 bins from 1e-6 to 0.1 J
 * (demill_drum_spectrum_start(w, drum, 0, NULL, 16, 1e-6, 0.1)), 500 steps,
 * then demill_world_save(). SAVED_COUNTS are the 48 counters that library's
 * demill_drum_spectrum() read just before the save (3 rows of 16: the
 * pairs of the one class, its collisions with the shell, with the lifters).
 *
 * Checked: the file is of format 1 (its header), today's library loads it,
 * demill_drum_spectrum() reads the same 48 counters, the drum records no
 * impacts (format 1 has none: DEMILL_ERR_INVALID_VALUE), 500 more steps run
 * and leave every counter at least what it was (counters only count up),
 * and the world saves and reloads in today's format, 4. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define NCOUNTERS 48

static const uint64_t SAVED_COUNTS[NCOUNTERS] = {
    2, 1, 0, 0, 1, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, /* ball-ball */
    0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, /* ball-shell */
    1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, /* ball-lifter */
};

static const char *fixture(void)
{
    return DEMILL_TEST_DATA "/checkpoint-v1-spectrum.bin";
}

START_TEST(format_1_loads_with_its_spectrum)
{
    dm_test_checkpoint_format(fixture(), 1);

    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_load(w, fixture()));
    demill_id drum;
    size_t n;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, &drum, 1, &n));
    ck_assert_uint_eq(n, 1);
    double steps, particles;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &steps));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &particles));
    ck_assert_double_eq(steps, 20500);
    ck_assert_double_eq(particles, 14);

    uint64_t counts[NCOUNTERS + 1];
    DM_OK(w, demill_drum_spectrum(w, drum, counts, NCOUNTERS + 1, &n));
    ck_assert_uint_eq(n, NCOUNTERS);
    for (size_t i = 0; i < NCOUNTERS; i++)
        ck_assert_msg(counts[i] == SAVED_COUNTS[i], "counter %zu: %llu, saved %llu", i,
                      (unsigned long long)counts[i], (unsigned long long)SAVED_COUNTS[i]);
    ck_assert_int_eq(demill_drum_impacts(w, drum, NULL, 0, &n, NULL), DEMILL_ERR_INVALID_VALUE);

    DM_OK(w, demill_world_step(w, 500));
    uint64_t after[NCOUNTERS];
    DM_OK(w, demill_drum_spectrum(w, drum, after, NCOUNTERS, &n));
    for (size_t i = 0; i < NCOUNTERS; i++)
        ck_assert_msg(after[i] >= counts[i], "counter %zu went down from %llu to %llu", i,
                      (unsigned long long)counts[i], (unsigned long long)after[i]);

    uint32_t format;
    demill_world *v = dm_test_reloaded(w, &format);
    ck_assert_uint_gt(format, 1); /* saved again in this library's format, a newer one */
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_DRUM, &drum, 1, &n)); /* the same drum in world v */
    DM_OK(v, demill_drum_spectrum(v, drum, counts, NCOUNTERS, &n));
    ck_assert(!memcmp(counts, after, sizeof after));
    demill_world_destroy(v);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("checkpoint_v1");
    TCase *tc = tcase_create("format_1");
    tcase_add_test(tc, format_1_loads_with_its_spectrum);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
