/* edge_cases.c: calls at the edges of what the API accepts, where the
 * library had undefined behaviour, found by the sanitizers
 * (tests/sanitize/run builds the suite with clang's AddressSanitizer and
 * UBSan, which stop at the first report) and by the API fuzzer
 * (tests/fuzz/api.c). Each case also checks its result against a number
 * derived by hand:
 *
 * - a world without particles steps: every step adds Δt to the time, and a
 *   drum turning at ω has turned ω t (demill/drum.h: the motion is exact);
 *   its neighbour lists are built over no particles (a zero-length copy from
 *   the particle arrays, which such a world never allocated);
 * - contacts of a law that keeps no history (linear spring, no damping, no
 *   friction): at rest with an overlap δ the force is k_n δ, k_n the series
 *   stiffness k k / (k + k) = k/2 of two equal materials (demill/material.h),
 *   particle on particle and particle on wall; a head-on collision of two
 *   equal spheres lasts half a period of the spring, π √(m* / k_n) with
 *   m* = m/2, and rebounds with e = 1 (the undamped linear oscillator:
 *   Pöschel & Schwager 2005, Computational Granular Dynamics). Such a
 *   law's history array was never allocated, and the kernels added 0 to its
 *   NULL;
 * - particles 1e300 m from the origin, added with DEMILL_ADD_NO_OVERLAP or
 *   present when the drum is filled: two at the same point overlap, two
 *   1e300 m apart do not. The overlap search's cell index was the position
 *   over the cell size converted to a 64-bit integer, which overflows;
 * - a pair parameter as large as its bound (1e30) reads back as set: every
 *   value was converted to an int, wanted only for the laws' choices;
 * - demill_world_ids() lists no drum in a world without one, whatever
 *   walls it has: it listed the walls instead, beyond the caller's count;
 * - the drum's region of a fill, a feed or an outlet with NULL for its
 *   (no) params: a fill of 10 balls places them inside the drum. The
 *   params were copied from NULL with length 0.
 */
#include "testutil.h"

START_TEST(empty_world_steps)
{
    const int dim = 2 + _i;
    demill_id m, drum;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, &m);
    const double dt = 1e-5, omega = 2.0;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_world_step(w, 100));
    double t, steps, contacts;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &steps));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &contacts));
    DM_ASSERT_REL(t, 100 * dt, 1e-12);
    ck_assert(steps == 100 && contacts == 0);

    DM_OK(w, demill_drum_create(w, m, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 4));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, omega));
    DM_OK(w, demill_world_step(w, 1000));
    double angle, power;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ANGLE, &angle));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_POWER, &power));
    DM_ASSERT_REL(angle, omega * 1000 * dt, 1e-9);
    ck_assert_msg(power == 0.0, "an empty drum draws %g W", power);
    demill_world_destroy(w);
}
END_TEST

/* The magnitude of a 3-vector. */
static double norm(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

START_TEST(contacts_without_history)
{
    const int dim = 2 + _i;
    demill_id m, ids[3], floor;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double r = 0.005, delta = 1e-4, k = 1e5, kn = k / 2, rho = 2500;
    /* a pair overlapping by delta, and a particle on a floor by delta */
    const double x[9] = {0, 0.1, 0, 2 * r - delta, 0.1, 0, 0.05, r - delta, 0};
    const double radii[3] = {r, r, r}, origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, m, origin, up, &floor));
    DM_OK(w, demill_particles_add(w, m, 3, x, radii, NULL, 0, ids));
    DM_OK(w, demill_world_step(w, 0));
    size_t n;
    double f[6], overlap[2];
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, f, 2, &n));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, overlap, 2, &n));
    ck_assert_uint_eq(n, 2);
    for (int c = 0; c < 2; c++) {
        DM_ASSERT_REL(overlap[c], delta, 1e-9);
        DM_ASSERT_REL(norm(f + 3 * c), kn * delta, 1e-9);
    }
    double fp[3];
    DM_OK(w, demill_particle_get(w, ids[2], DEMILL_PARTICLE_FORCE, fp));
    DM_ASSERT_REL(fp[1], kn * delta, 1e-9);
    DM_OK(w, demill_particles_remove(w, 3, ids));
    DM_OK(w, demill_wall_remove(w, floor)); /* the collision is on the x axis, at y = 0 */

    const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * rho; /* 2D: spheres in a plane */
    const double tc = M_PI * sqrt(mstar / kn);
    for (int p = 0; p < 4; p++) {
        dm_collision o = dm_test_collide(w, m, r, 1.0, tc / 50, (p + 0.5) / 4, 0.0);
        DM_ASSERT_REL(o.restitution, 1.0, 0.01);
        DM_ASSERT_REL(o.duration, tc, 0.02);
    }
    demill_world_destroy(w);
}
END_TEST

START_TEST(no_overlap_far_away)
{
    const int dim = 2 + _i;
    demill_id m;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, &m);
    const double r = 0.01, far[3] = {1e300, 0, 0}, other[3] = {-1e300, 1e300, 0};
    DM_OK(w, demill_particles_add(w, m, 1, far, &r, NULL, DEMILL_ADD_NO_OVERLAP, NULL));
    ck_assert_int_eq(demill_particles_add(w, m, 1, far, &r, NULL, DEMILL_ADD_NO_OVERLAP, NULL),
                     DEMILL_ERR_OVERLAP);
    DM_OK(w, demill_particles_add(w, m, 1, other, &r, NULL, DEMILL_ADD_NO_OVERLAP, NULL));
    const double pair[6] = {1e300, -1e300, 0, 1e300, -1e300, 0}, radii[2] = {r, r};
    ck_assert_int_eq(demill_particles_add(w, m, 2, pair, radii, NULL, DEMILL_ADD_NO_OVERLAP, NULL),
                     DEMILL_ERR_OVERLAP);

    /* a fill places its charge in the drum, clear of the far particles */
    demill_id drum;
    const double sizes[2] = {0.02, 1};
    size_t added;
    DM_OK(w, demill_drum_create(w, m, &drum));
    DM_OK(w, demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, sizes, 2, DEMILL_FILL_COUNT, 10,
                              1, NULL, 0, &added));
    double count;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &count));
    ck_assert(added == 10 && count == 12);
    demill_world_destroy(w);
}
END_TEST

START_TEST(large_pair_values)
{
    demill_id m;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, &m);
    const int32_t keys[2] = {DEMILL_PAIR_NORMAL_STIFFNESS, DEMILL_PAIR_VISCOUS_DAMPING};
    for (int k = 0; k < 2; k++) {
        double hi, v;
        ck_assert_int_eq(demill_param_bounds(keys[k], NULL, &hi, NULL), DEMILL_OK);
        ck_assert(hi == 1e30);
        DM_OK(w, demill_pair_set(w, m, m, keys[k], hi));
        DM_OK(w, demill_pair_get(w, m, m, keys[k], &v));
        ck_assert(v == hi);
    }
    demill_world_destroy(w);
}
END_TEST

START_TEST(ids_of_no_drum)
{
    demill_id m, walls[2], drum, out[4] = {1, 2, 3, 4};
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double origin[3] = {0, 0, 0}, normals[2][3] = {{0, 1, 0}, {1, 0, 0}};
    for (int k = 0; k < 2; k++)
        DM_OK(w, demill_wall_add_plane(w, m, origin, normals[k], &walls[k]));
    for (int pass = 0; pass < 2; pass++) { /* never a drum, then one removed */
        size_t n = 99;
        DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, out, 4, &n));
        ck_assert_uint_eq(n, 0);
        for (int k = 0; k < 4; k++)
            ck_assert_msg(out[k] == (demill_id)k + 1, "out[%d] = 0x%llx was written", k,
                          (unsigned long long)out[k]);
        DM_OK(w, demill_drum_create(w, m, &drum));
        DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, out, 1, &n));
        ck_assert(n == 1 && out[0] == drum);
        DM_OK(w, demill_drum_remove(w, drum));
        out[0] = 1;
    }
    demill_world_destroy(w);
}
END_TEST

/* The drum's region takes no params, and NULL for them: a fill of 10
 * balls places 10, each inside the drum (its distance from the axis at
 * most R - r, |z| at most L/2 - r), and a feed and an outlet are made.
 * The region's params were copied from NULL with length 0. */
START_TEST(drum_region_without_params)
{
    demill_id m, drum, ids[10], feed, outlet;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    DM_OK(w, demill_drum_create(w, m, &drum));
    double D, L;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_DIAMETER, &D));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_LENGTH, &L));
    const double d = 0.02, sizes[2] = {d, 1.0}, v[3] = {0, 0, 0};
    size_t added = 0;
    DM_OK(w, demill_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, m, DEMILL_SIZES_CLASSES, sizes, 2,
                                DEMILL_FILL_COUNT, 10, 1, ids, 10, &added));
    ck_assert_uint_eq(added, 10);
    for (int k = 0; k < 10; k++) {
        double x[3];
        DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_POSITION, x));
        ck_assert_msg(hypot(x[0], x[1]) <= 0.5 * (D - d) && fabs(x[2]) <= 0.5 * (L - d),
                      "ball %d at (%g, %g, %g) is not inside the drum", k, x[0], x[1], x[2]);
    }
    DM_OK(w, demill_feed_create(w, DEMILL_REGION_DRUM, NULL, 0, m, DEMILL_SIZES_CLASSES, sizes, 2,
                                1.0, v, 0.0, 1.0, 1, &feed));
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_DRUM, NULL, 0, 0, NULL, 1.0, &outlet));
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("edge_cases");
    TCase *tc = tcase_create("edge_cases");
    tcase_add_loop_test(tc, empty_world_steps, 0, 2);
    tcase_add_loop_test(tc, contacts_without_history, 0, 2);
    tcase_add_loop_test(tc, no_overlap_far_away, 0, 2);
    tcase_add_test(tc, large_pair_values);
    tcase_add_test(tc, ids_of_no_drum);
    tcase_add_test(tc, drum_region_without_params);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
