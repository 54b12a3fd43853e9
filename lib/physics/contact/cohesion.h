/* cohesion.h: the cohesive forces of a contact (docs/physics.md, Cohesion):
 * JKR adhesion of elastic spheres and the capillary force of a liquid
 * bridge, as closed forms without iteration, for the contact law (law.h).
 *
 * Conventions as in law.h: overlap δ (negative: a gap s = -δ), reduced
 * radius R*, effective modulus E*; a force is positive when it pushes the
 * bodies apart, so that cohesive forces are negative. */
#ifndef DM_COHESION_H
#define DM_COHESION_H

#include <math.h>

#include "base/base.h"

#define DM_COHESION_INLINE static inline __attribute__((always_inline))

/* JKR (Johnson, Kendall and Roberts 1971, Surface energy and the contact of
 * elastic solids, Proc. R. Soc. Lond. A 324, 301-313), work of adhesion w:
 * the contact radius a gives the overlap and the force
 *   δ = a²/R* − √(2π w a/E*),   F = 4E* a³/(3R*) − √(8π w E* a³).
 * The overlap is smallest, δ_c = −(3/4) (π² w² R* / E*²)^{1/3}, at
 * a_c = (R* / 4 √(2π w/E*))^{2/3}; there the contact breaks when pulled apart.
 *
 * a(δ) on the stable branch (a >= a_c), for δ >= δ_c, in closed form: with
 * x = √a, δ(a) is the quartic x⁴ − R* c x − R* δ = 0, c = √(2π w/E*), whose
 * Ferrari resolvent y³ + P y + Q = 0 (P = R* δ, Q = −R*² c²/8) has one real
 * root while δ > δ_c (its discriminant Q²/4 + P³/27 is 0 exactly at δ_c).
 * Cardano's root y = u + v, u = ∛(−Q/2 + √(Q²/4 + P³/27)), v = −P/(3u),
 * is taken as y = −Q/(u² − uv + v²), which cancels nothing for either sign
 * of P; then x = (√(2y) + √(4√D − 2y))/2 with D = u² − uv + v² (the
 * quartic's larger root, since −p/√(2y) = 2√D for p = −R* c), and a = x².
 * Against the parametric form, a(δ(a)) returns a to 1.0e-15 relative for
 * a >= 2 a_c, 4.8e-14 from 1.01 a_c and 3.4e-12 from 1.0001 a_c (3.1e-8 at
 * δ_c itself): a(δ) has a square-root branch point at a_c, where the
 * rounding of δ is amplified, not an error of the method
 * (tests/physics/cohesion.c). For w = 0 it is Hertz's √(R* δ) (and 0 for
 * δ <= 0). */
DM_COHESION_INLINE double dm_jkr_radius(double delta, double rstar, double e_star, double w)
{
    const double p3 = rstar * delta / 3.0, q = -rstar * rstar * DM_PI * w / (4.0 * e_star);
    const double s = -0.5 * q, disc = s * s + p3 * p3 * p3;
    const double u = cbrt(s + sqrt(disc > 0.0 ? disc : 0.0));
    const double ue = u > 0.0 ? u : 1.0, v = -p3 / ue;
    const double d = ue * ue - ue * v + v * v, y = -q / d;
    const double r = 4.0 * sqrt(d) - 2.0 * y, x = 0.5 * (sqrt(2.0 * y) + sqrt(r > 0.0 ? r : 0.0));
    return u > 0.0 ? x * x : 0.0;
}

/* The JKR force of contact radius a: its Hertz part 4E* a³/(3R*) and its
 * adhesive part −√(8π w E* a³) (both written to *hertz and *adhesive). */
DM_COHESION_INLINE void dm_jkr_force(double a, double rstar, double e_star, double w,
                                     double *hertz, double *adhesive)
{
    const double a3 = a * a * a;
    *hertz = 4.0 * e_star * a3 / (3.0 * rstar);
    *adhesive = -sqrt(8.0 * DM_PI * w * e_star * a3);
}

/* The gap −δ_c = (3/4) (π² w² R* / E*²)^{1/3} at which a JKR contact breaks. */
DM_COHESION_INLINE double dm_jkr_reach(double rstar, double e_star, double w)
{
    return 0.75 * cbrt(DM_PI * DM_PI * w * w * rstar / (e_star * e_star));
}

/* JKR's pull-off force (3/2) π w R*, the largest pull a contact holds under
 * load control (Johnson, Kendall and Roberts 1971). */
DM_COHESION_INLINE double dm_jkr_pull_off(double rstar, double w)
{
    return 1.5 * DM_PI * w * rstar;
}

/* The capillary force of a liquid bridge of volume V, surface tension γ and
 * contact angle θ at gap s >= 0 (Willett, Adams, Johnson and Seville 2000,
 * Capillary bridges between two spherical bodies, Langmuir 16, 9396-9405,
 * their closed form for equal spheres of radius R):
 *   F = −2π R γ cos θ / (1 + 2.1 S + 10.0 S²),  S = (s/2) √(R/V),
 * with R = 2R*, the radius of equal spheres of the same reduced radius (the
 * Derjaguin approximation, which they found accurate for small bridges
 * between unequal spheres), so that at contact F = −4π R* γ cos θ: 2π R γ
 * cos θ between equal spheres, 4π R γ cos θ for a sphere on a plane. */
DM_COHESION_INLINE double dm_capillary_force(double gap, double rstar, double gamma, double theta,
                                             double volume)
{
    const double r = 2.0 * rstar, sn = 0.5 * gap * sqrt(r / volume);
    return -2.0 * DM_PI * r * gamma * cos(theta) / (1.0 + sn * (2.1 + 10.0 * sn));
}

/* The gap at which a liquid bridge of volume V and contact angle θ (rad)
 * ruptures, s_c = (1 + θ/2) V^{1/3} (Lian, Thornton and Adams 1993, A
 * theoretical study of the liquid bridge forces between two rigid
 * spherical bodies, J. Colloid Interface Sci. 161, 138-147). */
DM_COHESION_INLINE double dm_capillary_reach(double theta, double volume)
{
    return (1.0 + 0.5 * theta) * cbrt(volume);
}

#endif /* DM_COHESION_H */
