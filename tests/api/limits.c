/* limits.c: calls that ask for too much end at once with an error and
 * change nothing, and ids never name the wrong object.
 *
 * Calls that never returned: stepping or settling once the clock can no
 * longer advance (t = 1e15 s with Δt = 0.05 s: t + Δt == t), and filling a
 * drum with more particles than can exist (a count of 1e20 or 1e308, a mass
 * of 1e30 kg, balls of 1 nm at a fraction of 0.3). Each must return
 * DEMILL_ERR_INVALID_VALUE with a message, the world unchanged; ten balls of
 * 1 nm in a 0.3 m drum, which fit, are placed at once.
 *
 * Radii whose mass underflows to 0 (r = 1e-110 m: 4/3 π r³ ρ ~ 1e-326 kg),
 * overflows (r = 1e103 m) or whose inverse moment of inertia overflows
 * (r = 1e-100 m: 2/5 m r² ~ 1e-497) are refused, as are a density and a
 * disc thickness that would give an existing particle such a mass.
 *
 * A material stiffness or Young's modulus so small that a pair's series
 * stiffness k_a k_b / (k_a + k_b) or E* underflows to 0 (4e-317, found by
 * the API fuzzer: the pair's stiffness read 0, which demill_pair_set
 * refuses, and the checkpoint did not reload) is refused; the smallest
 * accepted, 1e-100, gives a pair 5e-101 and a checkpoint that reloads.
 *
 * Ids (demill/common.h): no two live worlds accept each other's ids (the
 * world tag has 12 bits: 4096 worlds, the 4097th is refused while they all
 * live); a handle whose 16-bit generation would wrap round is retired, so
 * that an id removed 65,536 reuses earlier is still refused; a world makes
 * at most 65,535 drums.
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* The call fails with `code` and a message that contains `word`. */
#define REFUSED(w, code, call, word)                                                              \
    do {                                                                                          \
        const demill_status s_ = (call);                                                          \
        ck_assert_msg(s_ == (code), "%s -> %d: %s", #call, (int)s_, demill_world_last_error(w));  \
        ck_assert_msg(strstr(demill_world_last_error(w), (word)), "%s: message \"%s\"", #call,    \
                      demill_world_last_error(w));                                                \
    } while (0)

static double world_value(demill_world *w, int32_t key)
{
    double v;
    DM_OK(w, demill_world_get(w, key, &v));
    return v;
}

START_TEST(clock_that_cannot_advance)
{
    demill_id m, p;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double x[3] = {0, 0, 0}, r = 0.01;
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &p));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME, 1e15));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 0.05));
    REFUSED(w, DEMILL_ERR_INVALID_VALUE, demill_world_step(w, 1), "does not advance the clock");
    int32_t settled = 7;
    REFUSED(w, DEMILL_ERR_INVALID_VALUE, demill_world_settle(w, 1.0, 0.0, &settled),
            "does not advance the clock");
    ck_assert(world_value(w, DEMILL_WORLD_STEP_COUNT) == 0);
    /* a time step the clock resolves runs */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 0.5));
    DM_OK(w, demill_world_settle(w, 1.0, 1e9, &settled));
    ck_assert(settled == 1);
    demill_world_destroy(w);
}
END_TEST

START_TEST(fills_that_cannot_be_made)
{
    demill_id m, drum;
    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_drum_create(w, m, &drum));
    const double balls[2] = {0.01, 1.0}, dust[2] = {1e-9, 1.0};
    const struct {
        const double *sizes;
        int32_t target;
        double value;
        const char *word;
    } cases[] = {
        {balls, DEMILL_FILL_COUNT, 1e20, "at most"},  {balls, DEMILL_FILL_COUNT, 1e308, "at most"},
        {balls, DEMILL_FILL_MASS, 1e30, "at most"},   {dust, DEMILL_FILL_FRACTION, 0.3, "at most"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        size_t added = 99;
        REFUSED(w, DEMILL_ERR_INVALID_VALUE,
                demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, cases[c].sizes, 2,
                                 cases[c].target, cases[c].value, 1, NULL, 0, &added),
                cases[c].word);
        ck_assert(world_value(w, DEMILL_WORLD_PARTICLE_COUNT) == 0);
    }
    /* what fits is made: ten grains of dust (the placement's grid is hashed,
     * so the drum's size against theirs costs nothing), and 100 balls */
    size_t added;
    DM_OK(w, demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, dust, 2, DEMILL_FILL_COUNT, 10, 1,
                              NULL, 0, &added));
    ck_assert_uint_eq(added, 10);
    DM_OK(w, demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, balls, 2, DEMILL_FILL_COUNT, 100,
                              1, NULL, 0, &added));
    ck_assert_uint_eq(added, 100);
    demill_world_destroy(w);
}
END_TEST

START_TEST(masses_not_finite_are_refused)
{
    demill_id m, p;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double x[3] = {0, 0, 0}, radii[3] = {1e-110, 1e103, 1e-100};
    for (int k = 0; k < 3; k++)
        REFUSED(w, DEMILL_ERR_INVALID_VALUE,
                demill_particles_add(w, m, 1, x, &radii[k], NULL, 0, &p), "mass");
    ck_assert(world_value(w, DEMILL_WORLD_PARTICLE_COUNT) == 0);
    const double huge = 1e60; /* m ~ 1e184 kg, I ~ 4e303 kg m²; at ρ = 1e30, I overflows */
    DM_OK(w, demill_particles_add(w, m, 1, x, &huge, NULL, 0, &p));
    const double mass = dm_test_get(w, p, DEMILL_PARTICLE_MASS, 0);
    for (int k = 0; k < 3; k++)
        REFUSED(w, DEMILL_ERR_INVALID_VALUE,
                demill_particle_set(w, p, DEMILL_PARTICLE_RADIUS, &radii[k]), "mass");
    REFUSED(w, DEMILL_ERR_INVALID_VALUE,
            demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 1e30), "material.density");
    ck_assert(dm_test_get(w, p, DEMILL_PARTICLE_MASS, 0) == mass);
    ck_assert(dm_test_get(w, p, DEMILL_PARTICLE_RADIUS, 0) == huge);
    double rho;
    DM_OK(w, demill_material_get(w, m, DEMILL_MATERIAL_DENSITY, &rho));
    ck_assert(rho == 2500);
    demill_world_destroy(w);
    /* discs of 10 µm 1e-300 m thick: I = m r²/2 ~ 4e-317 kg m², 1/I overflows */
    w = dm_test_world(2, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double small = 1e-5;
    DM_OK(w, demill_particles_add(w, m, 1, x, &small, NULL, 0, &p));
    REFUSED(w, DEMILL_ERR_INVALID_VALUE,
            demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, 1e-300), "world.disc_thickness");
    ck_assert(world_value(w, DEMILL_WORLD_DISC_THICKNESS) == 0);
    demill_world_destroy(w);
}
END_TEST

START_TEST(pair_values_stay_positive)
{
    demill_id m;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    static const int32_t keys[] = {DEMILL_MATERIAL_STIFFNESS, DEMILL_MATERIAL_YOUNGS_MODULUS};
    for (int k = 0; k < 2; k++) {
        REFUSED(w, DEMILL_ERR_INVALID_VALUE, demill_material_set(w, m, keys[k], 4.1e-317),
                k ? "material.youngs_modulus" : "material.stiffness");
        DM_OK(w, demill_material_set(w, m, keys[k], 1e-100));
    }
    double kn;
    DM_OK(w, demill_pair_get(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, &kn));
    ck_assert(kn == 5e-101);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    size_t n;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &n));
    void *buf = malloc(n);
    ck_assert(buf);
    DM_OK(w, demill_world_save_buffer(w, buf, n, &n));
    DM_OK(w, demill_world_load_buffer(w, buf, n));
    free(buf);
    demill_world_destroy(w);
}
END_TEST

START_TEST(live_worlds_never_share_ids)
{
    enum { MOST = 4096 };
    demill_world **worlds = calloc(MOST + 1, sizeof *worlds);
    demill_id *mats = calloc(MOST + 1, sizeof *mats);
    ck_assert(worlds && mats);
    for (int k = 0; k < MOST; k++) {
        ck_assert_int_eq(demill_world_create(2, &worlds[k]), DEMILL_OK);
        DM_OK(worlds[k], demill_material_create(worlds[k], &mats[k]));
    }
    ck_assert_int_eq(demill_world_create(2, &worlds[MOST]), DEMILL_ERR_LIMIT);
    ck_assert_ptr_null(worlds[MOST]);
    /* every world refuses its neighbours' ids, the last the first's */
    for (int k = 0; k < MOST; k++) {
        demill_world *w = worlds[k];
        double v;
        REFUSED(w, DEMILL_ERR_INVALID_HANDLE,
                demill_material_get(w, mats[(k + 1) % MOST], DEMILL_MATERIAL_DENSITY, &v),
                "another world");
    }
    /* a world destroyed makes room for one more */
    demill_world_destroy(worlds[7]);
    ck_assert_int_eq(demill_world_create(2, &worlds[7]), DEMILL_OK);
    for (int k = 0; k < MOST; k++)
        demill_world_destroy(worlds[k]);
    free(worlds);
    free(mats);
}
END_TEST

START_TEST(generations_never_wrap)
{
    demill_id m, first, p, wall_first, wall;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double x[3] = {0, 0, 0}, r = 0.01, n[3] = {0, 1, 0};
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &first));
    DM_OK(w, demill_particles_remove(w, 1, &first));
    DM_OK(w, demill_wall_add_plane(w, m, x, n, &wall_first));
    DM_OK(w, demill_wall_remove(w, wall_first));
    for (int k = 0; k < 70000; k++) {
        DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &p));
        ck_assert(p != first);
        REFUSED(w, DEMILL_ERR_INVALID_HANDLE,
                demill_particle_set(w, first, DEMILL_PARTICLE_RADIUS, &r), "removed");
        DM_OK(w, demill_particles_remove(w, 1, &p));
        DM_OK(w, demill_wall_add_plane(w, m, x, n, &wall));
        ck_assert(wall != wall_first);
        DM_OK(w, demill_wall_remove(w, wall));
    }
    demill_world_destroy(w);
}
END_TEST

START_TEST(drums_are_counted)
{
    demill_id m, drum, first;
    demill_world *w;
    ck_assert_int_eq(demill_world_create(2, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_drum_create(w, m, &first));
    DM_OK(w, demill_drum_remove(w, first));
    for (int k = 1; k < 65535; k++) {
        DM_OK(w, demill_drum_create(w, m, &drum));
        ck_assert(drum != first);
        DM_OK(w, demill_drum_remove(w, drum));
    }
    REFUSED(w, DEMILL_ERR_LIMIT, demill_drum_create(w, m, &drum), "65535 drums");
    double v;
    REFUSED(w, DEMILL_ERR_INVALID_HANDLE, demill_drum_get(w, first, DEMILL_DRUM_DIAMETER, &v),
            "removed");
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("limits");
    TCase *tc = tcase_create("limits");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, clock_that_cannot_advance);
    tcase_add_test(tc, fills_that_cannot_be_made);
    tcase_add_test(tc, masses_not_finite_are_refused);
    tcase_add_test(tc, pair_values_stay_positive);
    tcase_add_test(tc, live_worlds_never_share_ids);
    tcase_add_test(tc, generations_never_wrap);
    tcase_add_test(tc, drums_are_counted);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
