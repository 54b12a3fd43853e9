/* orient.h: the turn of a 3D particle's orientation quaternion by its angular
 * velocity over a step (docs/shapes.md, Orientation), shared by the
 * integrators of integrate.c and refine.c. */
#ifndef DM_ORIENT_H
#define DM_ORIENT_H

/* Turns the unit quaternion q (w, x, y, z; body to world frame) by the
 * rotation vector phi = ω Δt, ω the world-frame angular velocity over the
 * step: q <- exp(phi / 2) ⊗ q, the exponential map of the rotation increment
 * (Omelyan 1998, "On the numerical integration of motion for rigid
 * polyatomics: the modified quaternion approach"; Rozmanov & Kusalik 2010,
 * "Robust rotational-velocity-Verlet integration methods"). With the half
 * angle a = |phi| / 2, exp(phi / 2) = (cos a, sin(a)/a phi/2). Both are even
 * in a and are taken from their Taylor series in a² to a⁸ while a² <= 0.01
 * (truncation below a¹⁰/10! = 2.8e-17, under round-off; no square root and no
 * call), from libm beyond. The increment is exact for a constant axis, so a
 * spin about a fixed axis turns by ω t to round-off. The product is followed
 * by one Newton step towards |q| = 1, q <- q (3 - |q|²)/2, which takes a
 * norm error ε to about 3ε²/4: round-off does not accumulate. */
static inline __attribute__((always_inline)) void dm_quat_turn(double *restrict q,
                                                               const double *restrict phi)
{
    const double hx = 0.5 * phi[0], hy = 0.5 * phi[1], hz = 0.5 * phi[2];
    const double a2 = hx * hx + hy * hy + hz * hz;
    double c, s; /* cos a and sin(a)/a */
    if (a2 <= 0.01) {
        c = 1.0 + a2 * (-1.0 / 2 + a2 * (1.0 / 24 + a2 * (-1.0 / 720 + a2 * (1.0 / 40320))));
        s = 1.0 + a2 * (-1.0 / 6 + a2 * (1.0 / 120 + a2 * (-1.0 / 5040 + a2 * (1.0 / 362880))));
    } else {
        const double a = sqrt(a2);
        c = cos(a);
        s = sin(a) / a;
    }
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

#endif
