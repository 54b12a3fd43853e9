/* restitution.c: the damping ratio that gives a required coefficient of
 * restitution (docs/physics.md §3).
 *
 * For the linear spring-dashpot x'' + 2ξx' + x = 0 (time in units of 1/ω0),
 * x(0) = 0, x'(0) = 1, the rebound velocity is the restitution e(ξ). Without a
 * clamp the contact ends at x = 0 and e = exp(-πξ/√(1-ξ²)), inverted in closed
 * form. With the clamp (F_n >= 0) the particles separate when the force
 * x + 2ξx' reaches zero; e(ξ) is then given by the closed forms below and
 * inverted by bisection (it decreases monotonically from 1 to 0).
 *
 * The Hertz law with the Tsuji-type damping c = 2√(5/6) ξ √(m* S_n) has the
 * same e(ξ) as the linear law, clamped or not (checked numerically to 1e-7
 * and by tests/physics), so one ratio serves both laws.
 */
#include <math.h>

#include "physics/contact/contact.h"

/* Rebound velocity of the clamped linear collision with damping ratio xi. */
static double clamped_restitution(double xi)
{
    if (xi < 1.0 - 1e-9) {
        double w = sqrt(1.0 - xi * xi);
        /* force zero: (1 - 2ξ²) sin θ + 2ξw cos θ = 0, first root θ = wτ > 0 */
        double th = DM_PI - atan2(2.0 * xi * w, 1.0 - 2.0 * xi * xi);
        double tau = th / w;
        return -exp(-xi * tau) * (cos(th) - xi * sin(th) / w);
    }
    if (xi <= 1.0 + 1e-9)
        return exp(-2.0); /* critical: x = τe^{-τ}, force zero at τ = 2 */
    double s = sqrt(xi * xi - 1.0);
    double tau = atanh(2.0 * xi * s / (2.0 * xi * xi - 1.0)) / s;
    return -exp(-xi * tau) * (cosh(s * tau) - xi * sinh(s * tau) / s);
}

double dm_damping_ratio(double e, int clamp)
{
    if (e >= 1.0)
        return 0.0;
    if (e <= 0.0) /* unclamped: critical damping, e(1) = 0; clamped: e > 0 for any finite ξ */
        return clamp ? INFINITY : 1.0;
    if (!clamp) {
        double l = log(e);
        return -l / sqrt(DM_PI * DM_PI + l * l);
    }
    double lo = 0.0, hi = 1.0;
    while (clamped_restitution(hi) > e && hi < 1e12)
        hi *= 2.0;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
        double mid = 0.5 * (lo + hi);
        if (clamped_restitution(mid) > e)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}
