/* shapes.c: the mass properties of unions of spheres and discs
 * (lib/physics/shapes/union.c) and the symmetric eigen-solver
 * (lib/physics/shapes/eigen.c) against numbers derived here another way.
 *
 * What this suite proves:
 *  - Two spheres (a dumbbell, equal and unequal radii, overlapping and not)
 *    give the mass, centre of mass and inertia tensor of their union to
 *    1e-12 relative. The reference integrates the union directly along the
 *    line of centres as a solid of revolution (collinear(), for any number
 *    of balls on a line): the radius² of its cross-section at x is
 *    ρ²(x) = max_k (R_k² - (x - x_k)²), between the break points (the
 *    balls' ends and where two of these parabolas cross) that of one ball,
 *    a polynomial in x, so the volume π∫ρ², the axial moment π∫x ρ², the
 *    axial inertia (π/2)∫ρ⁴ (a disc's m ρ²/2) and the inertia about a
 *    perpendicular axis π∫(ρ⁴/4 + x² ρ²) (a disc's m ρ²/4, shifted by x) are
 *    integrals of polynomials, which the test takes exactly from their
 *    coefficients (the library instead subtracts the lens from the two balls).
 *  - The union's volume against the lens formula
 *    V = π (R + r - d)² (d² + 2dr - 3r² + 2dR + 6rR - 3R²)/(12 d)
 *    (e.g. Weisstein, "Sphere-Sphere Intersection", MathWorld):
 *    4π(R³ + r³)/3 - V.
 *  - Three spheres in an L (a corner sphere A and two arms B, C at distance d
 *    along orthogonal directions, B and C apart): since B and C do not meet,
 *    A ∪ B ∪ C = (A ∪ B) + (A ∪ C) - A, so every moment about a common point
 *    is the two dumbbells' less A's; overlapping and not, to 1e-12.
 *  - A sphere inside another adds nothing; N equal spheres at one point
 *    weigh as one (m = ρ 4πR³/3, I = 2mR²/5).
 *  - Discs (2D) with a thickness t: two discs against the circular-segment
 *    formulas (a segment beyond a chord at distance a from the centre, of
 *    half angle α = acos(a/R) and half chord b = R sin α, is a sector less
 *    the triangle of the centre and the chord: area R²α - ab, first moment
 *    along the axis 2(R³ sin α - b a²)/3 = 2b³/3, polar moment about the
 *    centre R⁴α/2 - (a b³/6 + b a³/2)); without a thickness the discs weigh
 *    as spheres (as dm_particle_mass() weighs one disc), against the
 *    dumbbell's slices.
 *  - Rows of three to five balls on a line, three of them or more
 *    overlapping pairwise (so weighed by slices and power diagrams, not by
 *    inclusion-exclusion), against collinear(), along a slanted axis and
 *    along z (where the slices' circles are concentric), to 1e-12 (they
 *    agree to 5.5e-15); the same rows of discs with a thickness against
 *    strips of circular segments, and without one against collinear().
 *  - A ball that lies in the union of two others adds nothing: a chain of
 *    six balls, each meeting only the next (inclusion-exclusion, exact),
 *    weighs the same with a ball across each lens, in neither ball but
 *    meeting both, and with a ball given twice; spheres, discs with and
 *    without a thickness, five random chains, to 1e-12.
 *  - A cluster of 12 spheres (and one of 12 discs with a thickness), centres
 *    uniform in a cube of side 2 R0, radii 0.5 to 1 R0, against a Monte
 *    Carlo estimate from 4e6 points (fixed seed): every raw moment within 4
 *    of its standard errors (1e-3 of the volume, 5e-4 to 8e-4 of V R0 and
 *    V R0² for the other moments; the measured deviations are within 2).
 *  - The same clusters turned by random rotations and moved: the mass the
 *    same, the centre of mass and the inertia tensor turned and moved, to
 *    1e-12 (they agree to 3.6e-15).
 *  - No sphere, a NaN centre and a radius <= 0 are refused with their codes
 *    and leave the output as it was.
 *  - The eigen-solver recovers known eigenvalues (distinct, and two equal)
 *    of a tensor turned by random rotations, to 1e-13 of the largest, and
 *    their axes to 1e-12 (for a repeated eigenvalue its plane), right-handed.
 *
 * Sizes: radii 10 mm, density 2700 kg/m³, shapes placed away from the origin
 * at p0 along a slanted axis, so that positions and orientations carry the
 * round-off of a real template. Centres are compared to 1e-12 of their
 * distance from the origin plus the size, inertia tensors element by element
 * to 1e-12 of their largest element.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/random.h"
#include "physics/shapes/shapes.h"
#include "testutil.h"

#define TOL 1e-12
static const double RHO = 2700.0; /* kg/m³ */
static const double R0 = 0.01;    /* m */
static const double P0[3] = {0.3, -0.2, 0.15};
/* Two orthonormal directions, not along the axes: (2,1,2)/3 and (1,2,-2)/3. */
static const double E1[3] = {2.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0};
static const double E2[3] = {1.0 / 3.0, 2.0 / 3.0, -2.0 / 3.0};

/* ∫ from a to b of the polynomial p[0] + p[1] x + ... + p[n-1] x^(n-1). */
static double pint(const double *p, int n, double a, double b)
{
    double s = 0.0;
    for (int k = n - 1; k >= 0; k--)
        s += p[k] * (pow(b, k + 1) - pow(a, k + 1)) / (k + 1);
    return s;
}

/* out = p q (degrees below np and nq). */
static void pmul(const double *p, int np, const double *q, int nq, double *out)
{
    for (int k = 0; k < np + nq - 1; k++)
        out[k] = 0.0;
    for (int j = 0; j < np; j++)
        for (int k = 0; k < nq; k++)
            out[j + k] += p[j] * q[k];
}

/* Adds the slices x0 <= x <= x1 of the ball of radius R centred at x = c on
 * the axis: s[0] += π∫ρ², s[1] += π∫x ρ², s[2] += (π/2)∫ρ⁴ and
 * s[3] += π∫(ρ⁴/4 + x² ρ²), with ρ² = R² - c² + 2c x - x². */
static void slices(double R, double c, double x0, double x1, double s[4])
{
    if (x1 <= x0)
        return;
    double r2[3] = {R * R - c * c, 2.0 * c, -1.0}, x[2] = {0, 1}, xr2[4], r4[5], x2r2[5];
    double x2[3] = {0, 0, 1};
    pmul(x, 2, r2, 3, xr2);
    pmul(r2, 3, r2, 3, r4);
    pmul(x2, 3, r2, 3, x2r2);
    s[0] += M_PI * pint(r2, 3, x0, x1);
    s[1] += M_PI * pint(xr2, 4, x0, x1);
    s[2] += M_PI / 2.0 * pint(r4, 5, x0, x1);
    s[3] += M_PI * (pint(r4, 5, x0, x1) / 4.0 + pint(x2r2, 5, x0, x1));
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The break points of the union of n balls (or discs) centred on an axis
 * at x[k], radii R[k], sorted into br (room for 2n + n(n - 1)/2 values;
 * returns their count): the balls' ends x_k ± R_k and where two balls'
 * squared cross-section radii R_k² - (x - x_k)² cross, at
 * x = (R_j² - R_k² + x_k² - x_j²)/(2 (x_k - x_j)). Between two break points
 * one ball has the widest cross-section throughout. */
static int axis_breaks(int n, const double *x, const double *R, double *br)
{
    int nb = 0;
    for (int k = 0; k < n; k++) {
        br[nb++] = x[k] - R[k];
        br[nb++] = x[k] + R[k];
        for (int j = 0; j < k; j++)
            if (x[j] != x[k])
                br[nb++] = (R[j] * R[j] - R[k] * R[k] + x[k] * x[k] - x[j] * x[j]) /
                           (2.0 * (x[k] - x[j]));
    }
    qsort(br, (size_t)nb, sizeof *br, by_value);
    return nb;
}

/* The ball with the widest cross-section at x, or -1 if none reaches x. */
static int widest(int n, const double *x, const double *R, double at)
{
    int best = -1;
    double w = 0.0;
    for (int k = 0; k < n; k++) {
        double r2 = R[k] * R[k] - (at - x[k]) * (at - x[k]);
        if (r2 > w)
            w = r2, best = k;
    }
    return best;
}

/* The mass properties of the union of n balls centred on the line p + x u
 * (u a unit vector) at x[k], radii R[k] (n <= 8), by slices along u: the
 * union is a solid of revolution whose cross-section radius² is
 * ρ²(x) = max_k (R_k² - (x - x_k)²), between break points the slices of
 * one ball (piecewise spherical caps). */
static dm_mass_props collinear(const double p[3], const double u[3], int n, const double *x,
                               const double *R)
{
    double br[44], s[4] = {0};
    int nb = axis_breaks(n, x, R, br);
    for (int k = 0; k + 1 < nb; k++) {
        int w = widest(n, x, R, 0.5 * (br[k] + br[k + 1]));
        if (w >= 0)
            slices(R[w], x[w], br[k], br[k + 1], s);
    }
    double m = RHO * s[0], xc = s[1] / s[0];
    double iax = RHO * s[2], iperp = RHO * s[3] - m * xc * xc;
    dm_mass_props q = {.mass = m};
    for (int j = 0; j < 3; j++) {
        q.com[j] = p[j] + xc * u[j];
        for (int k = 0; k < 3; k++)
            q.inertia[j][k] = iax * u[j] * u[k] + iperp * ((j == k) - u[j] * u[k]);
    }
    return q;
}

/* The union of the ball of radius R at p and the ball of radius r at
 * p + d u. */
static dm_mass_props dumbbell(const double p[3], const double u[3], double R, double r, double d)
{
    return collinear(p, u, 2, (double[2]){0.0, d}, (double[2]){R, r});
}

/* The inertia of q about the point o (parallel axes), times sign, added to
 * io; sign m and sign m (c - o) to m and mc. About a point of the shape, not
 * the origin, so that the shifts lose no digits to its distance. */
static void add_about(const dm_mass_props *q, const double o[3], double sign, double *m,
                      double mc[3], double io[3][3])
{
    double c[3] = {q->com[0] - o[0], q->com[1] - o[1], q->com[2] - o[2]};
    double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    *m += sign * q->mass;
    for (int j = 0; j < 3; j++) {
        mc[j] += sign * q->mass * c[j];
        for (int k = 0; k < 3; k++)
            io[j][k] += sign * (q->inertia[j][k] + q->mass * ((j == k) * c2 - c[j] * c[k]));
    }
}

/* The mass properties of mass m, first moment mc and inertia io about o. */
static dm_mass_props from_point(const double o[3], double m, const double mc[3], double io[3][3])
{
    dm_mass_props q = {.mass = m};
    double c[3] = {mc[0] / m, mc[1] / m, mc[2] / m};
    double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    for (int j = 0; j < 3; j++) {
        q.com[j] = o[j] + c[j];
        for (int k = 0; k < 3; k++)
            q.inertia[j][k] = io[j][k] - m * ((j == k) * c2 - c[j] * c[k]);
    }
    return q;
}

static void assert_props(const dm_mass_props *got, const dm_mass_props *want, double size)
{
    DM_ASSERT_REL(got->mass, want->mass, TOL);
    double cn = sqrt(want->com[0] * want->com[0] + want->com[1] * want->com[1] +
                     want->com[2] * want->com[2]),
           imax = 0.0;
    for (int j = 0; j < 3; j++)
        ck_assert_msg(fabs(got->com[j] - want->com[j]) <= TOL * (cn + size),
                      "com[%d] = %.15g, expected %.15g", j, got->com[j], want->com[j]);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            imax = fmax(imax, fabs(want->inertia[j][k]));
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            ck_assert_msg(fabs(got->inertia[j][k] - want->inertia[j][k]) <= TOL * imax,
                          "I[%d][%d] = %.15g, expected %.15g", j, k, got->inertia[j][k],
                          want->inertia[j][k]);
}

/* The library's union of the balls (R at p, r at p + d u). */
static dm_mass_props lib_two(const double p[3], const double u[3], double R, double r, double d)
{
    double c[6], rad[2] = {R, r};
    for (int j = 0; j < 3; j++) {
        c[j] = p[j];
        c[3 + j] = p[j] + d * u[j];
    }
    dm_mass_props q;
    const char *why = NULL;
    ck_assert_int_eq(dm_spheres_union_mass(2, c, rad, RHO, &q, &why), DEMILL_OK);
    return q;
}

START_TEST(test_dumbbell)
{
    /* Equal and unequal radii; apart (d > R + r), touching, overlapping a
     * little and much, and the smaller centre inside the larger ball. */
    const double cases[][2] = {{1.0, 3.0}, {1.0, 2.0},  {1.0, 1.9}, {1.0, 1.2},
                               {1.0, 0.3}, {0.6, 1.5},  {0.6, 0.9}, {0.6, 0.5}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double r = cases[k][0] * R0, d = cases[k][1] * R0;
        dm_mass_props got = lib_two(P0, E1, R0, r, d), want = dumbbell(P0, E1, R0, r, d);
        assert_props(&got, &want, R0);
        /* The same from the other end (the larger ball second). */
        double p[3] = {P0[0] + d * E1[0], P0[1] + d * E1[1], P0[2] + d * E1[2]};
        double mu[3] = {-E1[0], -E1[1], -E1[2]};
        got = lib_two(p, mu, r, R0, d);
        assert_props(&got, &want, R0);
    }
    /* Apart, the parallel-axis theorem: m = ρ 4π(R³ + r³)/3, the centre of
     * mass at m2 d/(m1 + m2) from the first, I_perp = Σ 2 m_i R_i²/5 +
     * m1 m2 d²/(m1 + m2). */
    double r = 0.6 * R0, d = 3.0 * R0;
    double m1 = RHO * 4.0 / 3.0 * M_PI * R0 * R0 * R0, m2 = RHO * 4.0 / 3.0 * M_PI * r * r * r;
    double iax = 0.4 * (m1 * R0 * R0 + m2 * r * r), iperp = iax + m1 * m2 * d * d / (m1 + m2);
    dm_mass_props got = lib_two(P0, E1, R0, r, d), want = {.mass = m1 + m2};
    for (int j = 0; j < 3; j++) {
        want.com[j] = P0[j] + m2 * d / (m1 + m2) * E1[j];
        for (int k = 0; k < 3; k++)
            want.inertia[j][k] = iax * E1[j] * E1[k] + iperp * ((j == k) - E1[j] * E1[k]);
    }
    assert_props(&got, &want, R0);
}
END_TEST

START_TEST(test_lens_volume)
{
    const double cases[][2] = {{1.0, 1.0}, {1.0, 1.9}, {0.7, 0.5}, {0.7, 1.6}, {0.3, 0.8}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double R = R0, r = cases[k][0] * R0, d = cases[k][1] * R0;
        double lens = M_PI * (R + r - d) * (R + r - d) *
                      (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) /
                      (12 * d);
        double v = 4.0 / 3.0 * M_PI * (R * R * R + r * r * r) - lens;
        DM_ASSERT_REL(lib_two(P0, E2, R, r, d).mass, RHO * v, TOL);
    }
}
END_TEST

/* The L of three balls of radius R0: A at P0, B at P0 + d E1, C at P0 + d E2. */
static void check_l(double d)
{
    double c[9], rad[3] = {R0, R0, R0};
    for (int j = 0; j < 3; j++) {
        c[j] = P0[j];
        c[3 + j] = P0[j] + d * E1[j];
        c[6 + j] = P0[j] + d * E2[j];
    }
    dm_mass_props got, ab = dumbbell(P0, E1, R0, R0, d), ac = dumbbell(P0, E2, R0, R0, d);
    dm_mass_props a = {.mass = RHO * 4.0 / 3.0 * M_PI * R0 * R0 * R0};
    for (int j = 0; j < 3; j++) {
        a.com[j] = P0[j];
        a.inertia[j][j] = 0.4 * a.mass * R0 * R0;
    }
    double m = 0.0, mc[3] = {0}, io[3][3] = {{0}};
    add_about(&ab, P0, 1.0, &m, mc, io);
    add_about(&ac, P0, 1.0, &m, mc, io);
    add_about(&a, P0, -1.0, &m, mc, io);
    dm_mass_props want = from_point(P0, m, mc, io);
    ck_assert_int_eq(dm_spheres_union_mass(3, c, rad, RHO, &got, NULL), DEMILL_OK);
    assert_props(&got, &want, R0);
    /* Any order of the spheres. */
    double c2[9], rad2[3] = {R0, R0, R0};
    memcpy(c2, c + 3, 6 * sizeof *c);
    memcpy(c2 + 6, c, 3 * sizeof *c);
    ck_assert_int_eq(dm_spheres_union_mass(3, c2, rad2, RHO, &got, NULL), DEMILL_OK);
    assert_props(&got, &want, R0);
}

START_TEST(test_l)
{
    check_l(1.5 * R0); /* A meets B and C; B and C 2.12 R apart */
    check_l(2.5 * R0); /* apart */
}
END_TEST

START_TEST(test_inside_and_repeated)
{
    dm_mass_props one = {.mass = RHO * 4.0 / 3.0 * M_PI * R0 * R0 * R0}, got;
    for (int j = 0; j < 3; j++) {
        one.com[j] = P0[j];
        one.inertia[j][j] = 0.4 * one.mass * R0 * R0;
    }
    /* A small sphere inside, touching the big one from inside, and one in
     * the middle. */
    double c[9], r[3] = {0.4 * R0, R0, 0.2 * R0};
    for (int j = 0; j < 3; j++) {
        c[j] = P0[j] + 0.6 * R0 * E2[j];
        c[3 + j] = P0[j];
        c[6 + j] = P0[j];
    }
    ck_assert_int_eq(dm_spheres_union_mass(3, c, r, RHO, &got, NULL), DEMILL_OK);
    assert_props(&got, &one, R0);
    /* Five equal spheres at one point. */
    double c5[15], r5[5];
    for (int k = 0; k < 5; k++) {
        memcpy(c5 + 3 * k, P0, sizeof P0);
        r5[k] = R0;
    }
    ck_assert_int_eq(dm_spheres_union_mass(5, c5, r5, RHO, &got, NULL), DEMILL_OK);
    assert_props(&got, &one, R0);
}
END_TEST

/* Circular segment of the disc of radius R beyond the chord at signed
 * distance a from its centre: area, first moment along the axis and polar
 * moment about the centre (sector less triangle, see the top). */
static void segment(double R, double a, double s[3])
{
    double al = acos(a / R), b = R * sin(al);
    s[0] = R * R * al - a * b;
    s[1] = 2.0 / 3.0 * (R * R * R * sin(al) - b * a * a);
    s[2] = R * R * R * R * al / 2.0 - (a * b * b * b / 6.0 + b * a * a * a / 2.0);
}

START_TEST(test_discs)
{
    const double t = 0.005; /* m */
    const double cases[][2] = {{1.0, 1.2}, {1.0, 1.9}, {0.6, 0.9}, {0.6, 0.5}, {0.6, 3.0}};
    const double u[2] = {0.6, -0.8};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double R = R0, r = cases[k][0] * R0, d = cases[k][1] * R0;
        /* Along the axis from the first centre: each disc, less the lens
         * (disc 1's segment beyond x = a and disc 2's beyond its chord at
         * d - a from its centre, towards disc 1) when they meet. */
        double A = M_PI * (R * R + r * r), Sx = M_PI * r * r * d;
        double J = M_PI * R * R * R * R / 2.0 + M_PI * r * r * r * r / 2.0 + M_PI * r * r * d * d;
        if (d < R + r) {
            double a = (d * d + R * R - r * r) / (2.0 * d), s1[3], s2[3];
            segment(R, a, s1);
            segment(r, d - a, s2);
            A -= s1[0] + s2[0];
            Sx -= s1[1] + (s2[0] * d - s2[1]);
            J -= s1[2] + (s2[2] - 2.0 * d * s2[1] + s2[0] * d * d);
        }
        double xc = Sx / A, m, com[2], i;
        double c[4] = {P0[0], P0[1], P0[0] + d * u[0], P0[1] + d * u[1]}, rad[2] = {R, r};
        ck_assert_int_eq(dm_discs_union_mass(2, c, rad, RHO, t, &m, com, &i, NULL), DEMILL_OK);
        DM_ASSERT_REL(m, RHO * t * A, TOL);
        DM_ASSERT_REL(i, RHO * t * (J - A * xc * xc), TOL);
        for (int j = 0; j < 2; j++)
            ck_assert(fabs(com[j] - (P0[j] + xc * u[j])) <= TOL * (1.0 + R0));
        /* Without a thickness: spheres, the dumbbell's inertia normal to
         * its axis. */
        double u3[3] = {u[0], u[1], 0.0};
        dm_mass_props want = dumbbell((double[3]){P0[0], P0[1], 0.0}, u3, R, r, d);
        ck_assert_int_eq(dm_discs_union_mass(2, c, rad, RHO, 0.0, &m, com, &i, NULL), DEMILL_OK);
        DM_ASSERT_REL(m, want.mass, TOL);
        DM_ASSERT_REL(i, want.inertia[2][2], TOL);
        for (int j = 0; j < 2; j++)
            ck_assert(fabs(com[j] - want.com[j]) <= TOL * (1.0 + R0));
    }
    /* Three equal discs at one point and one inside: one disc, m = ρ t π R²,
     * I = m R²/2. */
    double c[8] = {P0[0], P0[1], P0[0], P0[1], P0[0], P0[1], P0[0] + 0.3 * R0, P0[1]};
    double rad[4] = {R0, R0, R0, 0.5 * R0}, m, com[2], i, m1 = RHO * t * M_PI * R0 * R0;
    ck_assert_int_eq(dm_discs_union_mass(4, c, rad, RHO, t, &m, com, &i, NULL), DEMILL_OK);
    DM_ASSERT_REL(m, m1, TOL);
    DM_ASSERT_REL(i, 0.5 * m1 * R0 * R0, TOL);
    DM_ASSERT_REL(com[0], P0[0], TOL);
    DM_ASSERT_REL(com[1], P0[1], TOL);
}
END_TEST

START_TEST(test_refused)
{
    dm_mass_props q, before;
    memset(&q, 0x5a, sizeof q);
    before = q;
    double c[9] = {0, 0, 0, R0, 0, 0, 0.5 * R0, R0, 0}, r[3] = {R0, R0, R0};
    const char *why = NULL;
    ck_assert_int_eq(dm_spheres_union_mass(0, c, r, RHO, &q, &why), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(dm_spheres_union_mass(1, NULL, r, RHO, &q, &why), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(dm_spheres_union_mass(2, c, r, -1.0, &q, &why), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(dm_spheres_union_mass(2, c, r, NAN, &q, &why), DEMILL_ERR_NOT_FINITE);
    c[4] = NAN;
    ck_assert_int_eq(dm_spheres_union_mass(2, c, r, RHO, &q, &why), DEMILL_ERR_NOT_FINITE);
    ck_assert_ptr_nonnull(strstr(why, "finite"));
    c[4] = 0.0;
    r[1] = 0.0;
    ck_assert_int_eq(dm_spheres_union_mass(2, c, r, RHO, &q, &why), DEMILL_ERR_INVALID_VALUE);
    ck_assert_ptr_nonnull(strstr(why, "radius"));
    ck_assert(memcmp(&q, &before, sizeof q) == 0);
    double m = 7.0, com[2] = {7.0, 7.0}, i = 7.0;
    ck_assert_int_eq(dm_discs_union_mass(2, c, r, RHO, 0.01, &m, com, &i, &why),
                     DEMILL_ERR_INVALID_VALUE);
    r[1] = R0;
    ck_assert_int_eq(dm_discs_union_mass(2, c, r, RHO, -0.01, &m, com, &i, &why),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(dm_discs_union_mass(2, c, r, RHO, NAN, &m, com, &i, &why),
                     DEMILL_ERR_NOT_FINITE);
    ck_assert(m == 7.0 && com[0] == 7.0 && com[1] == 7.0 && i == 7.0);
}
END_TEST

/* A random rotation matrix (rows q[k] its axes), from a random unit
 * quaternion (Shoemake (1992), "Uniform random rotations", Graphics Gems III). */
static void random_rotation(double q[3][3])
{
    double u1 = rand() / (double)RAND_MAX, u2 = rand() / (double)RAND_MAX,
           u3 = rand() / (double)RAND_MAX;
    double w = sqrt(1 - u1) * sin(2 * M_PI * u2), x = sqrt(1 - u1) * cos(2 * M_PI * u2),
           y = sqrt(u1) * sin(2 * M_PI * u3), z = sqrt(u1) * cos(2 * M_PI * u3);
    double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                      {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                      {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    memcpy(q, m, sizeof m);
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

START_TEST(test_eigen)
{
    srand(17);
    const double spectra[][3] = {{1.0, 2.0, 5.0}, {2.0, 2.0, 5.0}, {1.0, 4.0, 4.0}, {3.0, 3.0, 3.0},
                                 {1e-3, 0.7, 1.0}};
    for (int rep = 0; rep < 200; rep++) {
        const double *l = spectra[rep % 5];
        double scale = 1e-6, q[3][3], a[3][3], val[3], vec[3][3];
        random_rotation(q);
        /* a = Σ λ_k q_k q_kᵀ: eigenpairs (λ_k, q_k). */
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                a[j][k] = scale * (l[0] * q[0][j] * q[0][k] + l[1] * q[1][j] * q[1][k] +
                                   l[2] * q[2][j] * q[2][k]);
        dm_sym3_eigen(a, val, vec);
        for (int k = 0; k < 3; k++)
            ck_assert_msg(fabs(val[k] - scale * l[k]) <= 1e-13 * scale * l[2],
                          "eigenvalue %d: %.17g against %.17g", k, val[k] / scale, l[k]);
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                ck_assert(fabs(dot(vec[j], vec[k]) - (j == k)) <= 1e-13);
        /* Right-handed. */
        double cr[3] = {vec[0][1] * vec[1][2] - vec[0][2] * vec[1][1],
                        vec[0][2] * vec[1][0] - vec[0][0] * vec[1][2],
                        vec[0][0] * vec[1][1] - vec[0][1] * vec[1][0]};
        ck_assert(dot(cr, vec[2]) > 1.0 - 1e-13);
        /* A distinct eigenvalue's axis is q_k up to sign; a repeated one's
         * lies in its eigenspace (no component along the other axes). */
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                if (l[j] != l[k])
                    ck_assert_msg(fabs(dot(vec[k], q[j])) <= 1e-12, "axis %d leaks into %d: %g",
                                  k, j, dot(vec[k], q[j]));
    }
    /* A diagonal tensor is its own answer. */
    double a[3][3] = {{3, 0, 0}, {0, 1, 0}, {0, 0, 2}}, val[3], vec[3][3];
    dm_sym3_eigen(a, val, vec);
    ck_assert(val[0] == 1.0 && val[1] == 2.0 && val[2] == 3.0);
    ck_assert(fabs(vec[0][1]) == 1.0 && fabs(vec[1][2]) == 1.0 && fabs(vec[2][0]) == 1.0);
}
END_TEST

/* The library's union of n balls on the line p + x u (x[k], R[k]). */
static dm_mass_props lib_line(const double p[3], const double u[3], int n, const double *x,
                              const double *R)
{
    double c[24];
    for (int k = 0; k < n; k++)
        for (int j = 0; j < 3; j++)
            c[3 * k + j] = p[j] + x[k] * u[j];
    dm_mass_props q;
    const char *why = NULL;
    ck_assert_int_eq(dm_spheres_union_mass((size_t)n, c, R, RHO, &q, &why), DEMILL_OK);
    return q;
}

/* Rows of balls along an axis (positions and radii in units of R0), each
 * with three or more that overlap pairwise: three equal, three unequal with
 * the middle one the smallest and the largest, four where the outer two
 * meet past a small middle one, and five of a tapering chain. */
static const struct row {
    int n;
    double x[5], r[5];
} ROWS[] = {{3, {0.0, 1.0, 2.0}, {1.0, 1.0, 1.0}},
            {3, {0.0, 0.9, 1.7}, {1.0, 0.4, 0.8}},
            {3, {0.0, 0.8, 1.4}, {0.7, 1.0, 0.6}},
            {4, {0.0, 0.7, 0.9, 1.6}, {1.0, 0.3, 0.5, 0.9}},
            {5, {0.0, 0.5, 1.1, 1.8, 2.3}, {0.9, 1.0, 0.8, 0.6, 0.5}}};

START_TEST(test_collinear)
{
    /* Along a slanted axis, and along z, where the spheres' circles of
     * intersection lie level and the slices' circles are concentric. */
    const double z[3] = {0.0, 0.0, 1.0};
    for (size_t k = 0; k < sizeof ROWS / sizeof ROWS[0]; k++) {
        double x[5], R[5];
        for (int j = 0; j < ROWS[k].n; j++)
            x[j] = ROWS[k].x[j] * R0, R[j] = ROWS[k].r[j] * R0;
        dm_mass_props got = lib_line(P0, E1, ROWS[k].n, x, R);
        dm_mass_props want = collinear(P0, E1, ROWS[k].n, x, R);
        assert_props(&got, &want, R0);
        got = lib_line(P0, z, ROWS[k].n, x, R);
        want = collinear(P0, z, ROWS[k].n, x, R);
        assert_props(&got, &want, R0);
    }
}
END_TEST

/* Adds to s (area, first moment along the axis, polar moment about the
 * axis' origin) the part x0 <= x <= x1 of the disc of radius R centred at
 * x = c on the axis: the segment beyond x0 less the segment beyond x1
 * (segment(), about the disc's centre), shifted along the axis. */
static void strip(double R, double c, double x0, double x1, double s[3])
{
    double a[3], b[3];
    segment(R, fmin(fmax(x0 - c, -R), R), a);
    segment(R, fmin(fmax(x1 - c, -R), R), b);
    double A = a[0] - b[0], S = a[1] - b[1], J = a[2] - b[2];
    s[0] += A;
    s[1] += S + c * A;
    s[2] += J + 2.0 * c * S + c * c * A;
}

START_TEST(test_collinear_discs)
{
    /* Discs on the line P0 + x u of the plane, with a thickness against
     * circular segments, and without one against the spheres' slices. */
    const double t = 0.005, u[2] = {0.6, -0.8}, u3[3] = {0.6, -0.8, 0.0};
    const double p3[3] = {P0[0], P0[1], 0.0};
    for (size_t k = 0; k < sizeof ROWS / sizeof ROWS[0]; k++) {
        int n = ROWS[k].n;
        double x[5], R[5], c[10], br[40], s[3] = {0}, m, com[2], i;
        for (int j = 0; j < n; j++) {
            x[j] = ROWS[k].x[j] * R0, R[j] = ROWS[k].r[j] * R0;
            c[2 * j] = P0[0] + x[j] * u[0];
            c[2 * j + 1] = P0[1] + x[j] * u[1];
        }
        int nb = axis_breaks(n, x, R, br);
        for (int q = 0; q + 1 < nb; q++) {
            int w = widest(n, x, R, 0.5 * (br[q] + br[q + 1]));
            if (w >= 0)
                strip(R[w], x[w], br[q], br[q + 1], s);
        }
        double xc = s[1] / s[0];
        ck_assert_int_eq(dm_discs_union_mass((size_t)n, c, R, RHO, t, &m, com, &i, NULL),
                         DEMILL_OK);
        DM_ASSERT_REL(m, RHO * t * s[0], TOL);
        DM_ASSERT_REL(i, RHO * t * (s[2] - s[0] * xc * xc), TOL);
        for (int j = 0; j < 2; j++)
            ck_assert(fabs(com[j] - (P0[j] + xc * u[j])) <= TOL * (1.0 + R0));
        dm_mass_props want = collinear(p3, u3, n, x, R);
        ck_assert_int_eq(dm_discs_union_mass((size_t)n, c, R, RHO, 0.0, &m, com, &i, NULL),
                         DEMILL_OK);
        DM_ASSERT_REL(m, want.mass, TOL);
        DM_ASSERT_REL(i, want.inertia[2][2], TOL);
        for (int j = 0; j < 2; j++)
            ck_assert(fabs(com[j] - want.com[j]) <= TOL * (1.0 + R0));
    }
}
END_TEST

/* A chain of NCHAIN balls in dimension dim from P0, each meeting the next
 * and no other (radii 0.6 to 1 R0, random directions from the seed), and
 * after them a ball across each lens: centred at the lens' centre m on the
 * line of centres, with a radius s halfway between the largest that lies
 * inside one of the two balls, max(r_k - a, r_(k+1) - (d - a)), and the
 * radius h of their circle of intersection. A point at distance ≤ h from m
 * is within r of the centre on its side of the radical plane (the farthest,
 * at distance √(a² + h²) = r, lie on the circle), so the ball lies in the
 * union of the two and adds nothing, though it meets both and lies in
 * neither: three balls that overlap pairwise. Returns the ball count,
 * 2 NCHAIN - 1. */
enum { NCHAIN = 6 };

static int chain(int dim, dm_rng *g, double *c, double *r)
{
    for (;;) {
        int ok = 1;
        for (int j = 0; j < dim; j++)
            c[j] = P0[j];
        r[0] = R0 * (0.6 + 0.4 * dm_rng_uniform(g));
        for (int k = 1; k < NCHAIN && ok; k++) {
            double e[3] = {0}, n2 = 0.0;
            for (int j = 0; j < dim; j++) {
                e[j] = dm_rng_uniform(g) - 0.5;
                n2 += e[j] * e[j];
            }
            r[k] = R0 * (0.6 + 0.4 * dm_rng_uniform(g));
            double d = (0.6 + 0.3 * dm_rng_uniform(g)) * (r[k - 1] + r[k]);
            double a = (d * d + r[k - 1] * r[k - 1] - r[k] * r[k]) / (2.0 * d);
            double h = sqrt(r[k - 1] * r[k - 1] - a * a);
            ok = n2 > 0.01 && a > 0.0 && d - a > 0.0;
            for (int j = 0; j < dim; j++) {
                c[dim * k + j] = c[dim * (k - 1) + j] + d * e[j] / sqrt(n2);
                c[dim * (NCHAIN + k - 1) + j] = c[dim * (k - 1) + j] + a * e[j] / sqrt(n2);
            }
            r[NCHAIN + k - 1] = 0.5 * (fmax(r[k - 1] - a, r[k] - (d - a)) + h);
            for (int q = 0; q + 1 < k && ok; q++) {
                double d2 = 0.0;
                for (int j = 0; j < dim; j++)
                    d2 += (c[dim * k + j] - c[dim * q + j]) * (c[dim * k + j] - c[dim * q + j]);
                ok = sqrt(d2) > r[k] + r[q];
            }
        }
        if (ok)
            return 2 * NCHAIN - 1;
    }
}

START_TEST(test_inside_union)
{
    /* The chain alone has no three balls that overlap pairwise and is
     * weighed by inclusion-exclusion, exact (test_dumbbell, test_l); with
     * the balls across its lenses, and one of its balls given twice, the
     * union and so every moment are the same. */
    dm_rng g;
    dm_rng_seed(&g, 17);
    for (int rep = 0; rep < 5; rep++) {
        double c[3 * 2 * NCHAIN], r[2 * NCHAIN];
        int n = chain(3, &g, c, r);
        memcpy(c + 3 * n, c + 6, 3 * sizeof *c);
        r[n] = r[2];
        dm_mass_props want, got;
        ck_assert_int_eq(dm_spheres_union_mass(NCHAIN, c, r, RHO, &want, NULL), DEMILL_OK);
        ck_assert_int_eq(dm_spheres_union_mass((size_t)n + 1, c, r, RHO, &got, NULL), DEMILL_OK);
        assert_props(&got, &want, R0);
        /* Discs, with a thickness and without. */
        n = chain(2, &g, c, r);
        for (int k = 0; k < 2; k++) {
            double t = k ? 0.0 : 0.005, m[2], com[2][2], i[2];
            ck_assert_int_eq(dm_discs_union_mass(NCHAIN, c, r, RHO, t, m, com[0], i, NULL),
                             DEMILL_OK);
            ck_assert_int_eq(
                dm_discs_union_mass((size_t)n, c, r, RHO, t, m + 1, com[1], i + 1, NULL),
                DEMILL_OK);
            DM_ASSERT_REL(m[1], m[0], TOL);
            DM_ASSERT_REL(i[1], i[0], TOL);
            for (int j = 0; j < 2; j++)
                ck_assert(fabs(com[1][j] - com[0][j]) <= TOL * (1.0 + R0));
        }
    }
}
END_TEST

/* NCLUSTER balls in dimension dim, radii 0.5 to 1 R0, centres uniform in
 * the cube (square) of side 2 R0 at P0: dozens of overlapping pairs and
 * triples. */
enum { NCLUSTER = 12 };

static void cluster(int dim, dm_rng *g, double *c, double *r)
{
    for (int k = 0; k < NCLUSTER; k++) {
        for (int j = 0; j < dim; j++)
            c[dim * k + j] = P0[j] + 2.0 * R0 * (dm_rng_uniform(g) - 0.5);
        r[k] = R0 * (0.5 + 0.5 * dm_rng_uniform(g));
    }
}

/* Monte Carlo estimates of the raw moments of the union of n balls in
 * dimension dim about the point o, by N points uniform in the box o ± h:
 * q[0] the measure, q[1 + j] ∫x_j, then ∫x_j x_k (j <= k) in the order
 * 00, 01, 02, 11, 12, 22 (3D) or 00, 01, 11 (2D); sd their standard
 * errors (the sample standard deviation of each point's value over √N). */
static void monte_carlo(int dim, int n, const double *c, const double *r, const double *o,
                        double h, long N, dm_rng *g, double *q, double *sd)
{
    int nq = dim == 3 ? 10 : 6;
    double box = pow(2.0 * h, dim), sum[10] = {0}, sum2[10] = {0};
    for (long s = 0; s < N; s++) {
        double x[3];
        for (int j = 0; j < dim; j++)
            x[j] = h * (2.0 * dm_rng_uniform(g) - 1.0);
        int in = 0;
        for (int k = 0; k < n && !in; k++) {
            double d2 = 0.0;
            for (int j = 0; j < dim; j++)
                d2 += (o[j] + x[j] - c[dim * k + j]) * (o[j] + x[j] - c[dim * k + j]);
            in = d2 < r[k] * r[k];
        }
        if (!in)
            continue;
        double f[10] = {1.0};
        int m = 1;
        for (int j = 0; j < dim; j++)
            f[m++] = x[j];
        for (int j = 0; j < dim; j++)
            for (int k = j; k < dim; k++)
                f[m++] = x[j] * x[k];
        for (int k = 0; k < nq; k++) {
            sum[k] += f[k];
            sum2[k] += f[k] * f[k];
        }
    }
    for (int k = 0; k < nq; k++) {
        double mean = sum[k] / (double)N, var = sum2[k] / (double)N - mean * mean;
        q[k] = box * mean;
        sd[k] = box * sqrt(var / (double)N);
    }
}

/* The raw moments (as monte_carlo()'s) about o of the measure v, centre of
 * mass com and second moment about it C. */
static void raw_moments(int dim, double v, const double *com, double C[3][3], const double *o,
                        double *q)
{
    double x[3];
    int m = 1;
    q[0] = v;
    for (int j = 0; j < dim; j++) {
        x[j] = com[j] - o[j];
        q[m++] = v * x[j];
    }
    for (int j = 0; j < dim; j++)
        for (int k = j; k < dim; k++)
            q[m++] = C[j][k] + v * x[j] * x[k];
}

START_TEST(test_monte_carlo)
{
    /* A cluster of 12 spheres against 4e6 random points in the cube
     * P0 ± 2 R0 that holds it, every raw moment about P0 within 4 standard
     * errors; the second moment about the centre of mass from the inertia
     * tensor, C = ((tr I/2) 1 - I)/ρ. Then 12 discs with a thickness in the
     * square P0 ± 2 R0: the area, the first moments and the polar moment
     * about P0, I_zz/(ρ t) + A |com - P0|², whose Monte Carlo estimate is
     * the sum of those of ∫x² and ∫y². */
    dm_rng g;
    dm_rng_seed(&g, 2026);
    double c[3 * NCLUSTER], r[NCLUSTER], q[10], sd[10], want[10], h = 2.0 * R0;
    cluster(3, &g, c, r);
    dm_mass_props p;
    ck_assert_int_eq(dm_spheres_union_mass(NCLUSTER, c, r, RHO, &p, NULL), DEMILL_OK);
    double C[3][3], tr = (p.inertia[0][0] + p.inertia[1][1] + p.inertia[2][2]) / 2.0;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            C[j][k] = ((j == k) * tr - p.inertia[j][k]) / RHO;
    raw_moments(3, p.mass / RHO, p.com, C, P0, want);
    monte_carlo(3, NCLUSTER, c, r, P0, h, 4000000, &g, q, sd);
    for (int k = 0; k < 10; k++)
        ck_assert_msg(fabs(want[k] - q[k]) <= 4.0 * sd[k],
                      "moment %d: %.9g, Monte Carlo %.9g ± %.2g", k, want[k], q[k], sd[k]);
    double m, com[2], i, t = 0.005;
    cluster(2, &g, c, r);
    ck_assert_int_eq(dm_discs_union_mass(NCLUSTER, c, r, RHO, t, &m, com, &i, NULL), DEMILL_OK);
    monte_carlo(2, NCLUSTER, c, r, P0, h, 4000000, &g, q, sd);
    double a = m / (RHO * t), x = com[0] - P0[0], y = com[1] - P0[1];
    double polar = i / (RHO * t) + a * (x * x + y * y);
    DM_ASSERT_REL(a, q[0], 4.0 * sd[0] / q[0]);
    ck_assert(fabs(a * x - q[1]) <= 4.0 * sd[1]);
    ck_assert(fabs(a * y - q[2]) <= 4.0 * sd[2]);
    /* The polar moment's error: its two parts' errors added. */
    ck_assert(fabs(polar - (q[3] + q[5])) <= 4.0 * (sd[3] + sd[5]));
}
END_TEST

START_TEST(test_moved)
{
    /* A cluster turned by a random rotation Q and moved by T: the mass the
     * same, the centre of mass Q com + T and the inertia Q I Qᵀ, to 1e-12;
     * discs turned in their plane likewise. */
    dm_rng g;
    dm_rng_seed(&g, 99);
    srand(99);
    for (int rep = 0; rep < 4; rep++) {
        double c[3 * NCLUSTER], c2[3 * NCLUSTER], r[NCLUSTER], q[3][3], T[3] = {0.02, -0.5, 0.7};
        cluster(3, &g, c, r);
        random_rotation(q);
        for (int k = 0; k < NCLUSTER; k++)
            for (int j = 0; j < 3; j++)
                c2[3 * k + j] = T[j] + dot(q[j], c + 3 * k);
        dm_mass_props a, b, want;
        ck_assert_int_eq(dm_spheres_union_mass(NCLUSTER, c, r, RHO, &a, NULL), DEMILL_OK);
        ck_assert_int_eq(dm_spheres_union_mass(NCLUSTER, c2, r, RHO, &b, NULL), DEMILL_OK);
        want.mass = a.mass;
        for (int j = 0; j < 3; j++) {
            want.com[j] = T[j] + dot(q[j], a.com);
            for (int k = 0; k < 3; k++) {
                want.inertia[j][k] = 0.0;
                for (int l = 0; l < 3; l++)
                    for (int n = 0; n < 3; n++)
                        want.inertia[j][k] += q[j][l] * a.inertia[l][n] * q[k][n];
            }
        }
        assert_props(&b, &want, R0);
        /* Discs: turned by the angle of the rotation's first row. */
        double ct = q[0][0] / hypot(q[0][0], q[0][1]), st = q[0][1] / hypot(q[0][0], q[0][1]);
        cluster(2, &g, c, r);
        for (int k = 0; k < NCLUSTER; k++) {
            c2[2 * k] = T[0] + ct * c[2 * k] - st * c[2 * k + 1];
            c2[2 * k + 1] = T[1] + st * c[2 * k] + ct * c[2 * k + 1];
        }
        for (int k = 0; k < 2; k++) {
            double t = k ? 0.0 : 0.005, m[2], com[2][2], i[2];
            ck_assert_int_eq(dm_discs_union_mass(NCLUSTER, c, r, RHO, t, m, com[0], i, NULL),
                             DEMILL_OK);
            ck_assert_int_eq(dm_discs_union_mass(NCLUSTER, c2, r, RHO, t, m + 1, com[1], i + 1,
                                                 NULL),
                             DEMILL_OK);
            DM_ASSERT_REL(m[1], m[0], TOL);
            DM_ASSERT_REL(i[1], i[0], TOL);
            double x = T[0] + ct * com[0][0] - st * com[0][1];
            double y = T[1] + st * com[0][0] + ct * com[0][1];
            ck_assert(fabs(com[1][0] - x) <= TOL * (1.0 + R0));
            ck_assert(fabs(com[1][1] - y) <= TOL * (1.0 + R0));
        }
    }
}
END_TEST

START_TEST(test_l_principal)
{
    /* The principal moments of the overlapping L rebuild its tensor. */
    double c[9], rad[3] = {R0, R0, R0}, val[3], vec[3][3];
    for (int j = 0; j < 3; j++) {
        c[j] = P0[j];
        c[3 + j] = P0[j] + 1.5 * R0 * E1[j];
        c[6 + j] = P0[j] + 1.5 * R0 * E2[j];
    }
    dm_mass_props q;
    ck_assert_int_eq(dm_spheres_union_mass(3, c, rad, RHO, &q, NULL), DEMILL_OK);
    dm_sym3_eigen(q.inertia, val, vec);
    /* By symmetry about the plane through A and the L's bisector normal to
     * E1 - E2, one axis is (E1 - E2)/√2. */
    double b[3] = {(E1[0] - E2[0]) / sqrt(2.0), (E1[1] - E2[1]) / sqrt(2.0),
                   (E1[2] - E2[2]) / sqrt(2.0)};
    int found = 0;
    for (int k = 0; k < 3; k++)
        found += fabs(fabs(dot(vec[k], b)) - 1.0) <= 1e-12;
    ck_assert_int_eq(found, 1);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++) {
            double s = 0.0;
            for (int n = 0; n < 3; n++)
                s += val[n] * vec[n][j] * vec[n][k];
            ck_assert(fabs(s - q.inertia[j][k]) <= 1e-13 * val[2]);
        }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("shapes");
    TCase *tc = tcase_create("shapes");
    tcase_add_test(tc, test_dumbbell);
    tcase_add_test(tc, test_lens_volume);
    tcase_add_test(tc, test_l);
    tcase_add_test(tc, test_inside_and_repeated);
    tcase_add_test(tc, test_discs);
    tcase_add_test(tc, test_refused);
    tcase_add_test(tc, test_eigen);
    tcase_add_test(tc, test_l_principal);
    tcase_add_test(tc, test_collinear);
    tcase_add_test(tc, test_collinear_discs);
    tcase_add_test(tc, test_inside_union);
    tcase_add_test(tc, test_monte_carlo);
    tcase_add_test(tc, test_moved);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
