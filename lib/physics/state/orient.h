/* orient.h: the turn of a 3D particle's orientation quaternion by its
 * angular velocity over a step (docs/shapes.md, Orientation), shared by the
 * integrators of integrate.c and refine.c and by the clumps' turns. */
#ifndef DM_ORIENT_H
#define DM_ORIENT_H

#include <math.h>

/* The turn q <- exp(phi / 2) ⊗ q of the unit quaternion q (w, x, y, z; body
 * to world frame) by the rotation vector phi = ω Δt, ω the world-frame
 * angular velocity over the step: the exponential map of the rotation
 * increment (Omelyan 1998, "On the numerical integration of motion for rigid
 * polyatomics: the modified quaternion approach"; Rozmanov & Kusalik 2010,
 * "Robust rotational-velocity-Verlet integration methods"). With the half
 * angle a = |phi| / 2 (hx, hy, hz = phi / 2, a2 = a²), exp(phi / 2) =
 * (cos a, sin(a)/a phi/2); c = cos a and s = sin(a)/a are given. The product
 * is followed by one Newton step towards |q| = 1, q <- q (3 - |q|²)/2, which
 * takes a norm error ε to about 3ε²/4: round-off does not accumulate. The
 * increment is exact for a constant axis, so a spin about a fixed axis turns
 * by ω t to round-off. */
static inline __attribute__((always_inline)) void dm_quat_mul_turn(double q[4], double c, double s,
                                                                   double hx, double hy, double hz)
{
    const double ew = c, ex = s * hx, ey = s * hy, ez = s * hz;
    const double qw = q[0], qx = q[1], qy = q[2], qz = q[3];
    const double nw = ew * qw - ex * qx - ey * qy - ez * qz;
    const double nx = ew * qx + ex * qw + ey * qz - ez * qy;
    const double ny = ew * qy - ex * qz + ey * qw + ez * qx;
    const double nz = ew * qz + ex * qy - ey * qx + ez * qw;
    const double g = 0.5 * (3.0 - (nw * nw + nx * nx + ny * ny + nz * nz));
    q[0] = g * nw;
    q[1] = g * nx;
    q[2] = g * ny;
    q[3] = g * nz;
}

/* The largest half angle² the series below take: there the truncation is
 * below a¹⁰/10! = 2.8e-17, under round-off. */
#define DM_QUAT_SERIES_A2 0.01

/* cos a and sin(a)/a from their Taylor series in a² to a⁸ (no square root
 * and no call, so that a loop of them vectorises). */
static inline __attribute__((always_inline)) void dm_quat_series(double a2, double *c, double *s)
{
    *c = 1.0 + a2 * (-1.0 / 2 + a2 * (1.0 / 24 + a2 * (-1.0 / 720 + a2 * (1.0 / 40320))));
    *s = 1.0 + a2 * (-1.0 / 6 + a2 * (1.0 / 120 + a2 * (-1.0 / 5040 + a2 * (1.0 / 362880))));
}

/* Turns the orientation q (4 doubles) by phi = k ω (ω: 3 doubles), whatever
 * the angle: the series while a² <= DM_QUAT_SERIES_A2, libm beyond. */
static inline void dm_quat_turn(double *restrict q, const double *restrict om, double k)
{
    const double hx = 0.5 * k * om[0], hy = 0.5 * k * om[1], hz = 0.5 * k * om[2];
    const double a2 = hx * hx + hy * hy + hz * hz;
    double c, s;
    if (a2 <= DM_QUAT_SERIES_A2) {
        dm_quat_series(a2, &c, &s);
    } else {
        const double a = sqrt(a2);
        c = cos(a);
        s = sin(a) / a;
    }
    dm_quat_mul_turn(q, c, s, hx, hy, hz);
}

#endif
