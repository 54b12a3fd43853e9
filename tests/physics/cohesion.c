/* cohesion.c: JKR adhesion and capillary bridges (docs/physics.md,
 * Cohesion) against their published closed forms.
 *
 * The closed forms (lib/physics/contact/cohesion.h):
 *  - JKR (Johnson, Kendall and Roberts 1971): the contact radius a(δ) that
 *    the library solves for in closed form is checked against the
 *    parametric form δ(a) = a²/R* − √(2π w a/E*) it inverts; the force
 *    F(a) = 4E* a³/(3R*) − √(8π w E* a³) has its minimum, the pull-off force
 *    −(3/2) π w R*, at a_p = (9π w R*²/(8E*))^{1/3} (dF/da = 0), and at the
 *    break δ_c = −(3/4)(π² w² R* / E*²)^{1/3} it is 5/9 of it (both JKR's);
 *    with w = 0, a = √(R* δ) (Hertz).
 *  - The capillary bridge (Willett, Adams, Johnson and Seville 2000): at
 *    contact 2π R γ cos θ between equal spheres of radius R; the rupture
 *    distance (1 + θ/2) V^{1/3} (Lian, Thornton and Adams 1993).
 */
#include <math.h>

#include "physics/contact/cohesion.h"
#include "testutil.h"

/* A glass-like pair: spheres of 1 mm diameter (R* = 0.25 mm), E = 1e8 Pa,
 * ν = 0.3, work of adhesion 0.1 J/m². */
static const double RS = 2.5e-4, ES = 1e8 / (2 * (1 - 0.09)), WA = 0.1;

static double jkr_delta(double a)
{
    return a * a / RS - sqrt(2 * M_PI * WA * a / ES);
}

START_TEST(jkr_radius_inverts_the_parametric_form)
{
    const double ac = pow(RS / 4 * sqrt(2 * M_PI * WA / ES), 2.0 / 3.0);
    /* the break: δ(a_c) is δ_c, and the radius there a_c */
    DM_ASSERT_REL(jkr_delta(ac), -dm_jkr_reach(RS, ES, WA), 1e-14);
    DM_ASSERT_REL(dm_jkr_radius(-dm_jkr_reach(RS, ES, WA), RS, ES, WA), ac, 1e-6);
    /* a from 1.0001 a_c to 1e4 a_c: the error is rounding, amplified near
     * the branch point a_c by 1/√(a/a_c − 1) */
    static const struct {
        double from, to, tol;
    } bands[] = {{1.0001, 1.01, 1e-10}, {1.01, 2, 1e-12}, {2, 1e4, 1e-14}};
    for (size_t b = 0; b < sizeof bands / sizeof bands[0]; b++)
        for (int k = 0; k <= 1000; k++) {
            const double a = ac * bands[b].from * pow(bands[b].to / bands[b].from, k / 1000.0);
            const double got = dm_jkr_radius(jkr_delta(a), RS, ES, WA);
            ck_assert_msg(fabs(got / a - 1) <= bands[b].tol, "a = %.17g a_c: a(δ(a)) = %.17g a_c",
                          a / ac, got / ac);
        }
    /* w = 0: Hertz */
    for (int k = 0; k <= 12; k++) {
        const double delta = RS * pow(10.0, -k);
        DM_ASSERT_REL(dm_jkr_radius(delta, RS, ES, 0.0), sqrt(RS * delta), 1e-15);
    }
    ck_assert_double_eq(dm_jkr_radius(0.0, RS, ES, 0.0), 0.0);
    ck_assert_double_eq(dm_jkr_radius(-1e-9, RS, ES, 0.0), 0.0);
}
END_TEST

START_TEST(jkr_pull_off_and_break)
{
    const double ap = cbrt(9 * M_PI * WA * RS * RS / (8 * ES)), fc = 1.5 * M_PI * WA * RS;
    double h, ad;
    dm_jkr_force(ap, RS, ES, WA, &h, &ad);
    DM_ASSERT_REL(h + ad, -fc, 1e-14);
    DM_ASSERT_REL(dm_jkr_pull_off(RS, WA), fc, 1e-15);
    /* at the radius the overlap of the pull-off gives back */
    const double a = dm_jkr_radius(jkr_delta(ap), RS, ES, WA);
    dm_jkr_force(a, RS, ES, WA, &h, &ad);
    DM_ASSERT_REL(h + ad, -fc, 1e-12);
    const double ac = dm_jkr_radius(-dm_jkr_reach(RS, ES, WA), RS, ES, WA);
    dm_jkr_force(ac, RS, ES, WA, &h, &ad);
    DM_ASSERT_REL(h + ad, -5.0 / 9.0 * fc, 1e-6);
}
END_TEST

START_TEST(capillary_closed_form)
{
    const double r = 1e-3, gamma = 0.072, theta = 0.3, v = 1e-12;
    /* equal spheres (R* = r/2) and a sphere on a plane (R* = r) at contact */
    DM_ASSERT_REL(dm_capillary_force(0.0, r / 2, gamma, theta, v), -2 * M_PI * r * gamma * cos(theta),
                  1e-15);
    DM_ASSERT_REL(dm_capillary_force(0.0, r, gamma, theta, v), -4 * M_PI * r * gamma * cos(theta),
                  1e-15);
    /* at S = (s/2) √(R/V) = 1: 1/(1 + 2.1 + 10) of the force at contact */
    DM_ASSERT_REL(dm_capillary_force(2 * sqrt(v / r), r / 2, gamma, theta, v),
                  -2 * M_PI * r * gamma * cos(theta) / 13.1, 1e-15);
    DM_ASSERT_REL(dm_capillary_reach(theta, v), 1.15 * 1e-4, 1e-15);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("cohesion");
    TCase *tc = tcase_create("closed_forms");
    tcase_add_test(tc, jkr_radius_inverts_the_parametric_form);
    tcase_add_test(tc, jkr_pull_off_and_break);
    tcase_add_test(tc, capillary_closed_form);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
