/* checkpoint_v3.c: a checkpoint of format 3, written before the extended
 * laws added their dissipation terms, the cohesion law and the count of
 * contact lists (format 4), still loads with its energy account and its
 * material pairs, and the world steps on from it.
 *
 * The fixture data/checkpoint-v3-laws.bin (8,551 bytes) was written by the
 * library at commit df9b337, the last whose checkpoints are of format 3,
 * built on its own outside this repository. Its program: a 3D world, a
 * material of density 7800 with itself on Hertz, restitution damping,
 * Mindlin and constant-torque rolling with the pair's restitution 0.7 and
 * rolling friction 0.05, and with a second material (of a floor, the plane
 * y = 0) on the unclamped linear law; 5 balls of 4 to 6 mm at (0.02 i,
 * 0.01 + 0.005 i, 0) moving at (±0.1, -0.2, 0.05 i) m/s; 20,000 steps of
 * the default 1e-5 s; then demill_world_save(). SAVED are the normal,
 * tangential, friction and rolling dissipation and the wall work that
 * library's demill_world_energy() gave just before the save.
 *
 * Checked: the file is of format 3, today's library loads it with the same
 * energy terms (and 0 for the terms format 3 does not hold), the pairs'
 * laws and values, its particles at orientation (1, 0, 0, 0) (format 3
 * holds none), steps on (the balls turn), and saves and reloads in today's
 * format, orientations bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static const int TERMS[5] = {DEMILL_ENERGY_DISSIPATED_NORMAL, DEMILL_ENERGY_DISSIPATED_TANGENTIAL,
                             DEMILL_ENERGY_DISSIPATED_FRICTION, DEMILL_ENERGY_DISSIPATED_ROLLING,
                             DEMILL_ENERGY_WALL_WORK};
static const double SAVED[5] = {0.00040158358160356534, 6.6748582068288661e-05,
                                0.00055839566584069296, 3.3639396853486516e-05, 0};

static const char *fixture(void)
{
    return DEMILL_TEST_DATA "/checkpoint-v3-laws.bin";
}

static double pair_value(demill_world *w, demill_id a, demill_id b, int key)
{
    double v;
    DM_OK(w, demill_pair_get(w, a, b, key, &v));
    return v;
}

START_TEST(format_3_loads_with_its_account_and_pairs)
{
    dm_test_checkpoint_format(fixture(), 3);

    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_load(w, fixture()));
    double steps, particles;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &steps));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &particles));
    ck_assert_double_eq(steps, 20000);
    ck_assert_double_eq(particles, 5);
    for (int k = 0; k < 5; k++) {
        double e;
        DM_OK(w, demill_world_energy(w, TERMS[k], &e));
        ck_assert_msg(e == SAVED[k], "term %d: %.17g, saved %.17g", TERMS[k], e, SAVED[k]);
    }
    double plastic;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC, &plastic));
    ck_assert(plastic == 0.0);
    double q[2][5 * 4];
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, q[0], 5, NULL));
    for (int k = 0; k < 5; k++)
        ck_assert(q[0][4 * k] == 1.0 && q[0][4 * k + 1] == 0.0 && q[0][4 * k + 2] == 0.0 &&
                  q[0][4 * k + 3] == 0.0);

    demill_id mats[2];
    size_t n;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, mats, 2, &n));
    ck_assert_uint_eq(n, 2);
    const demill_id m = mats[0], o = mats[1];
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_NORMAL) == DEMILL_NORMAL_HERTZ);
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_ROLLING) == DEMILL_ROLLING_CONSTANT_TORQUE);
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_COHESION) == DEMILL_COHESION_NONE);
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_RESTITUTION) == 0.7);
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_ROLLING_FRICTION) == 0.05);
    ck_assert(pair_value(w, m, m, DEMILL_PAIR_YIELD_PRESSURE) == 0.0);
    ck_assert(pair_value(w, m, o, DEMILL_PAIR_NORMAL) == DEMILL_NORMAL_LINEAR);
    ck_assert(pair_value(w, m, o, DEMILL_PAIR_CLAMP_NORMAL) == 0.0);

    DM_OK(w, demill_world_step(w, 1000));
    double after;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED_NORMAL, &after));
    ck_assert(after >= SAVED[0]);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_ORIENTATION, q[0], 5, NULL));
    double turned = 0.0; /* the largest |x|, |y|, |z| */
    for (int k = 0; k < 5; k++)
        for (int c = 1; c < 4; c++)
            turned = fmax(turned, fabs(q[0][4 * k + c]));
    ck_assert_msg(turned > 1e-6, "no ball turned (%g)", turned);
    uint32_t format;
    demill_world *v = dm_test_reloaded(w, &format);
    ck_assert_uint_gt(format, 3);
    double again;
    DM_OK(v, demill_world_energy(v, DEMILL_ENERGY_DISSIPATED_NORMAL, &again));
    ck_assert(again == after);
    DM_OK(v, demill_particles_read(v, DEMILL_PARTICLE_ORIENTATION, q[1], 5, NULL));
    ck_assert(!memcmp(q[0], q[1], sizeof q[0]));
    demill_world_destroy(v);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("checkpoint_v3");
    TCase *tc = tcase_create("format_3");
    tcase_add_test(tc, format_3_loads_with_its_account_and_pairs);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
