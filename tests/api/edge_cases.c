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
 *   the particle arrays, which such a world never allocated).
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

int main(void)
{
    Suite *s = suite_create("edge_cases");
    TCase *tc = tcase_create("edge_cases");
    tcase_add_loop_test(tc, empty_world_steps, 0, 2);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
