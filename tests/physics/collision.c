/* collision.c: binary collisions against analytic solutions.
 *
 * Linear spring-dashpot (docs/physics.md §2-3): with damping ratio
 * ξ = -ln e / √(π² + ln² e) the rebound velocity is e times the approach
 * velocity and the contact lasts π/ω_d, ω_d = √(k/m*) √(1-ξ²) (the classic
 * unclamped model). Hertz (Johnson, Contact Mechanics §11.4): maximum overlap
 * δ_max = (15 m* v² / (16 E* √R*))^{2/5} and duration
 * t_c = 2 δ_max/v ∫₀¹ dx/√(1 - x^{5/2}) = 2.94324 δ_max/v.
 * Each case runs at Δt = t_c/50 and from several entry phases (the fraction of
 * a step by which the particles meet), so that no lucky alignment of the
 * contact with the step grid is tested; and with each integrator of
 * second order: velocity Verlet (loop index 0) and the iterative refinement
 * at its default tolerance (1).
 */
#include <math.h>
#include <stdlib.h>

#include "testutil.h"

#define PHASES 8

static const double restitutions[] = {0.1, 0.5, 0.9};

/* dm_test_world() with the integrator of loop index i. */
static demill_world *world_for(int i, int dim, int normal, int damping, demill_id *m)
{
    demill_world *w = dm_test_world(dim, normal, damping, m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                              i ? DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT
                                : DEMILL_INTEGRATOR_VELOCITY_VERLET));
    return w;
}

/* Linear law: e within e_tol, duration within dur_tol (unless 0). */
static void linear_case(int i, int dim, double e, int clamp, double dur_tol, double e_tol)
{
    demill_id m;
    demill_world *w = world_for(i, dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, e));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, clamp));
    const double r = 0.005, rho = 2500, k = 5e4; /* default stiffness 1e5 in series */
    const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * rho;
    const double l = log(e), xi = -l / sqrt(M_PI * M_PI + l * l);
    const double tc = M_PI / (sqrt(k / mstar) * sqrt(1 - xi * xi));
    for (int p = 0; p < PHASES; p++) {
        dm_collision o = dm_test_collide(w, m, r, 1.0, tc / 50, (p + 0.5) / PHASES, 0.0);
        DM_ASSERT_REL(o.restitution, e, e_tol);
        if (dur_tol > 0)
            DM_ASSERT_REL(o.duration, tc, dur_tol);
    }
    demill_world_destroy(w);
}

START_TEST(linear_restitution_and_duration)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int k = 0; k < 3; k++)
            linear_case(_i, dim, restitutions[k], 0, 0.02, 0.01);
}
END_TEST

/* The default (clamped: the normal force never pulls) model keeps the exact
 * restitution; its contact is not a half period, so only e is checked. The
 * refinement integrator misses more where the clamped force has its kink:
 * at e = 0.1 the worst entry phase is 1.35 % off (the mean over phases
 * 0.48 %), so it is held to 2 %. (It was 4.8 % at phase 1/16 while the
 * refinement took the first sample of a contact that began early in a step
 * for an older one and lost its entry impulse; tests/physics/entry.c.) */
START_TEST(linear_clamped_restitution)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int k = 0; k < 3; k++)
            linear_case(_i, dim, restitutions[k], 1, 0.0, _i ? 0.02 : 0.01);
}
END_TEST

/* ∫₀¹ dx/√(1 - x^{5/2}) by the substitution x = 1 - s², which removes the
 * end-point singularity (the integrand tends to 2/√(5/2) as s → 0), and
 * Simpson's rule. */
static double hertz_integral(void)
{
    const int n = 20000;
    double sum = 0;
    for (int i = 0; i <= n; i++) {
        double s = (double)i / n;
        double f = i == 0 ? 2.0 / sqrt(2.5) : 2.0 * s / sqrt(1.0 - pow(1.0 - s * s, 2.5));
        sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * f;
    }
    return sum / (3.0 * n);
}

START_TEST(hertz_elastic_impact)
{
    const double integral = hertz_integral();
    ck_assert_msg(fabs(2 * integral - 2.94324) < 1e-4, "Hertz integral %g", integral);
    for (int dim = 2; dim <= 3; dim++) {
        demill_id m;
        demill_world *w = world_for(_i, dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, &m);
        const double r = 0.003, rho = 2500, E = 1e8, nu = 0.3, v0 = 1.0;
        const double estar = E / (2 * (1 - nu * nu)), rstar = r / 2;
        const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * rho;
        const double dmax = pow(15 * mstar * v0 * v0 / (16 * estar * sqrt(rstar)), 0.4);
        const double tc = 2 * integral * dmax / v0;
        for (int p = 0; p < PHASES; p++) {
            dm_collision o = dm_test_collide(w, m, r, v0, tc / 50, (p + 0.5) / PHASES, 0.0);
            DM_ASSERT_REL(o.max_overlap, dmax, 0.02);
            DM_ASSERT_REL(o.duration, tc, 0.02);
            DM_ASSERT_REL(o.restitution, 1.0, 0.01);
        }
        demill_world_destroy(w);
    }
}
END_TEST

START_TEST(hertz_restitution)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int clamp = 0; clamp <= 1; clamp++)
            for (int k = 0; k < 3; k++) {
                demill_id m;
                demill_world *w =
                    world_for(_i, dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, &m);
                DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, restitutions[k]));
                DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, clamp));
                /* Δt = 1/50 of the undamped Hertz contact time */
                const double r = 0.003, estar = 1e8 / (2 * (1 - 0.09));
                const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * 2500;
                const double dmax = pow(15 * mstar / (16 * estar * sqrt(r / 2)), 0.4);
                for (int p = 0; p < PHASES; p++) {
                    dm_collision o = dm_test_collide(w, m, r, 1.0, 2.94324 * dmax / 50,
                                                     (p + 0.5) / PHASES, 0.0);
                    DM_ASSERT_REL(o.restitution, restitutions[k], 0.02);
                }
                demill_world_destroy(w);
            }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("collision");
    TCase *tc = tcase_create("binary");
    tcase_add_loop_test(tc, linear_restitution_and_duration, 0, 2);
    tcase_add_loop_test(tc, linear_clamped_restitution, 0, 2);
    tcase_add_loop_test(tc, hertz_elastic_impact, 0, 2);
    tcase_add_loop_test(tc, hertz_restitution, 0, 2);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
