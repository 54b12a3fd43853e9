/* drum.c: the mill drum of demill/drum.h against hand-derived numbers.
 *
 * What this suite proves:
 *  - Contact geometry of the drum's walls is exact, for spheres (3D) and
 *    discs (2D): the cylindrical shell anywhere on the circle, both end caps
 *    and the shell-cap edge (3D), a lifter's inner face, both side faces, its
 *    inner corners (closest point the vertex, normal along the diagonal), an
 *    inclined leading face (normal perpendicular to it) and its top corner,
 *    and the concave corners where a lifter face meets the shell (one particle,
 *    two contacts); also after the drum has turned, at the lifter's new polar
 *    angle. Overlap, normal and contact point of every contact are checked, and
 *    that the second body is the drum (kind DEMILL_KIND_DRUM).
 *  - Speed: rad/s, rpm and fraction of critical are views of one target; the
 *    critical speed √(2 g/(D - d)) follows |g|, the largest particle and the
 *    critical-diameter override; a ramp raises the current speed linearly and
 *    the drum angle is its exact integral; revolutions count completed turns.
 *  - An empty drum draws exactly zero torque and power, and its mean power over
 *    a revolution is NaN before the first revolution and exactly 0 after.
 *  - Filling: a count target is met exactly, a mass target within one largest
 *    particle, the mass fractions of discrete classes within one particle,
 *    Rosin-Rammler and normal distributions stay in [d_min, d_max] and put the
 *    right share of mass below a given size, a bulk-filling target gives the
 *    right solid volume (3D) or area (2D) including the lifters' cross-section;
 *    no particle overlaps another or a wall; a fill is reproducible from its
 *    seed; a second fill avoids the first; a charge that does not fit and bad
 *    arguments give their documented codes and add nothing.
 *  - Collision spectrum: one head-on collision is counted once, in the row of
 *    the two size classes and the bin of (1 - e²) ½ m* v²; a particle thrown at
 *    the shell or at a lifter is counted in its class's shell or lifter row;
 *    the counter layout has (C(C+1)/2 + 2C) × nbins counters; a short buffer
 *    and a read before any start give their codes.
 *  - Lifter loads: the force on a lifter is equal and opposite to the contact
 *    force on the particle touching it (pressed against a side face, and resting
 *    on the inner face under gravity), and the drum torque is its moment.
 *
 * Conventions (demill/query.h, demill/drum.h): contact normal n from the
 * particle (body a) into the wall (body b); contact point = centre +
 * (R - δ/2) n. Lifter geometry: centre line at polar angle α, radial unit
 * u = (cos α, sin α), tangential t = (-sin α, cos α); a point is written in
 * lifter coordinates (ρ, τ) as x = ρ u + τ t. The inner face is at ρ = R_drum - h,
 * the side faces at τ = ±w/2 at the shell, the leading (+t) face inclined by
 * the face angle f: τ = w/2 + (ρ - R_drum) tan f, meeting the inner face at
 * τ = w/2 - h tan f. At α = 3π/2 (6 o'clock): u = (0, -1), t = (1, 0), so
 * (ρ, τ) is the point (τ, -ρ).
 *
 * Common geometry scene: drum D = 0.3 m (R_drum = 0.15), length 0.1 m (end
 * caps at z = ±0.05), one lifter at α = 3π/2, height h = 0.015, width
 * w = 0.015 (half width 0.0075; inner face at ρ = 0.135), face angle 0 or
 * 0.5 rad; particle radius r = 0.005 m, overlap δ = 1e-4 m; gravity 0; linear
 * contact law without damping.
 *
 * Tolerances of the geometry: positions are of order 0.15 m and carry round-off
 * of a few 1e-17 m (cos(3π/2) itself is 1.8e-16, not 0), so overlaps and
 * contact points are checked to 1e-12 × R_drum = 1.5e-13 m (a factor ~1e3 above
 * the round-off), and unit normals to 1e-12 absolute (their round-off is the
 * position round-off over the distance of at least r - δ = 4.9e-3 m from the
 * closest point, below 1e-14).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define TOL 1e-12
#define MAXC 8 /* contacts a geometry case can have */

static const double DRUM_D = 0.3;   /* m */
static const double DRUM_R = 0.15;  /* m */
static const double DRUM_L = 0.1;   /* m */
static const double LIFT_H = 0.015; /* m */
static const double LIFT_W = 0.015; /* m */
static const double RP = 0.005;     /* particle radius, m */
static const double DELTA = 1e-4;   /* overlap, m */
static const double RHO = 2500.0;   /* default density, kg/m³ */
static const double KN = 5e4;       /* series stiffness of two default materials, N/m */

#define SIX_OCLOCK (1.5 * M_PI)

static double sphere_mass(double r)
{
    return 4.0 / 3.0 * M_PI * r * r * r * RHO;
}

/* |got - want| <= tol, with the caller's line. */
#define NEAR(got, want, tol)                                                                      \
    do {                                                                                          \
        double g_ = (got), w_ = (want), t_ = (tol);                                               \
        ck_assert_msg(fabs(g_ - w_) <= t_, "line %d: %s = %.17g, expected %.17g (within %.3g)",   \
                      __LINE__, #got, g_, w_, t_);                                                \
    } while (0)

static double drum_get(demill_world *w, demill_id drum, int key)
{
    double v = NAN;
    DM_OK(w, demill_drum_get(w, drum, key, &v));
    return v;
}

static double world_get(demill_world *w, int key)
{
    double v = NAN;
    DM_OK(w, demill_world_get(w, key, &v));
    return v;
}

/* ---- scenes ------------------------------------------------------------ */

typedef struct scene {
    demill_world *w;
    demill_id mat, wallmat, drum;
    int dim;
} scene;

/* A world without gravity, a particle material and a drum material with the
 * linear law (given damping) for every pair, and a default drum (D = 0.3,
 * L = 0.1, no lifters). */
static scene drum_scene(int dim, int damping)
{
    scene s;
    s.dim = dim;
    s.w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, damping, &s.mat);
    DM_OK(s.w, demill_material_create(s.w, &s.wallmat));
    DM_OK(s.w, demill_pair_set(s.w, s.mat, s.wallmat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(s.w, demill_pair_set(s.w, s.mat, s.wallmat, DEMILL_PAIR_DAMPING, damping));
    DM_OK(s.w, demill_pair_set(s.w, s.wallmat, s.wallmat, DEMILL_PAIR_NORMAL,
                               DEMILL_NORMAL_LINEAR));
    DM_OK(s.w, demill_drum_create(s.w, s.wallmat, &s.drum));
    ck_assert_int_eq(demill_id_kind(s.drum), DEMILL_KIND_DRUM);
    ck_assert(drum_get(s.w, s.drum, DEMILL_DRUM_DIAMETER) == DRUM_D);
    ck_assert(drum_get(s.w, s.drum, DEMILL_DRUM_LENGTH) == DRUM_L);
    return s;
}

/* The geometry scene: the default drum with one lifter at 6 o'clock, height
 * and width 0.015, the given face angle. */
static scene lifter_scene(int dim, double face)
{
    scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
    DM_OK(s.w, demill_drum_add_lifter(s.w, s.drum, SIX_OCLOCK, LIFT_H, LIFT_W, face));
    ck_assert(drum_get(s.w, s.drum, DEMILL_DRUM_LIFTER_COUNT) == 1.0);
    return s;
}

/* (ρ, τ) of the lifter at polar angle a to x, y (z = 0). */
static void lift_xy(double a, double rho, double tau, double out[3])
{
    out[0] = rho * cos(a) - tau * sin(a);
    out[1] = rho * sin(a) + tau * cos(a);
    out[2] = 0.0;
}

/* ---- contact checks ----------------------------------------------------- */

typedef struct expect {
    double n[3];  /* normal from the particle into the wall */
    double delta; /* overlap */
} expect;

/* Adds a particle of radius r at c, evaluates the forces without moving
 * (step 0), and checks that its contacts are exactly the expected ones (in any
 * order): overlap, normal, contact point c + (r - δ/2) n, body a the particle
 * and body b the drum. Removes the particle again. */
static void check_contacts_at(int line, const scene *s, const double c[3], double r, int nexp,
                              const expect *e)
{
    demill_world *w = s->w;
    demill_id p;
    DM_OK(w, demill_particles_add(w, s->mat, 1, c, &r, NULL, 0, &p));
    DM_OK(w, demill_world_step(w, 0));
    double nrm[3 * MAXC], pt[3 * MAXC], ov[MAXC];
    demill_id a[MAXC], b[MAXC];
    size_t n = 0;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL, NULL, 0, &n));
    ck_assert_msg(n == (size_t)nexp, "line %d: %zu contacts, expected %d", line, n, nexp);
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL, nrm, MAXC, &n));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_POINT, pt, MAXC, &n));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, ov, MAXC, &n));
    DM_OK(w, demill_contacts_read_ids(w, a, b, MAXC, &n));
    int used[MAXC] = {0};
    for (int k = 0; k < nexp; k++) {
        size_t best = n;
        double bd = -2.0;
        for (size_t j = 0; j < n; j++) {
            double d = 0.0;
            for (int q = 0; q < 3; q++)
                d += nrm[3 * j + q] * e[k].n[q];
            if (!used[j] && d > bd) {
                bd = d;
                best = j;
            }
        }
        ck_assert(best < n);
        used[best] = 1;
        for (int q = 0; q < 3; q++) {
            ck_assert_msg(fabs(nrm[3 * best + q] - e[k].n[q]) <= TOL,
                          "line %d, contact %d: normal[%d] = %.17g, expected %.17g", line, k, q,
                          nrm[3 * best + q], e[k].n[q]);
            const double want = c[q] + (r - 0.5 * e[k].delta) * e[k].n[q];
            ck_assert_msg(fabs(pt[3 * best + q] - want) <= TOL * DRUM_R,
                          "line %d, contact %d: point[%d] = %.17g, expected %.17g", line, k, q,
                          pt[3 * best + q], want);
        }
        ck_assert_msg(fabs(ov[best] - e[k].delta) <= TOL * DRUM_R,
                      "line %d, contact %d: overlap %.17g, expected %.17g", line, k, ov[best],
                      e[k].delta);
        ck_assert_msg(a[best] == p, "line %d: body a is not the particle", line);
        ck_assert_msg(b[best] == s->drum, "line %d: body b is not the drum", line);
        ck_assert_int_eq(demill_id_kind(b[best]), DEMILL_KIND_DRUM);
    }
    DM_OK(w, demill_particles_remove(w, 1, &p));
}
#define CHECK_CONTACTS(...) check_contacts_at(__LINE__, __VA_ARGS__)

/* One expected contact with normal (x, y, z) and overlap DELTA. */
static expect ex(double x, double y, double z)
{
    expect e = {{x, y, z}, DELTA};
    return e;
}

/* A particle touching the shell with overlap DELTA at polar angle phi (and
 * height z): centre (R_drum - r + δ)(cos φ, sin φ) = 0.1451 (cos φ, sin φ),
 * normal (cos φ, sin φ, 0). */
static void shell_case(const scene *s, double phi, double z)
{
    const double rc = DRUM_R - RP + DELTA; /* 0.1451 */
    double c[3] = {rc * cos(phi), rc * sin(phi), z};
    expect e = ex(cos(phi), sin(phi), 0.0);
    CHECK_CONTACTS(s, c, RP, 1, &e);
}

/* ---- 1. contact geometry -------------------------------------------------- */

/* Shell: a particle anywhere on the circle touches only the shell: at
 * φ = 1 rad, at the top (φ = π/2: centre (0, 0.1451), point (0, 0.15005)) and
 * right beside the lifter, φ = 3π/2 + 0.1: centre 0.1451 (sin 0.1, -cos 0.1) =
 * (0.014486, -0.144378), 0.006986 m from the lifter's leading face
 * x = 0.0075, more than r = 0.005, so one contact. In 3D also the end caps:
 * centre (0.01, 0.02, ±(0.05 - r + δ)) = (0.01, 0.02, ±0.0451), normal
 * (0, 0, ±1), point z = ±0.05005; and the shell-cap edge: centre at φ = π/4,
 * radius 0.1451, z = 0.0451 touches both, two contacts of overlap δ with
 * normals (cos π/4, sin π/4, 0) and (0, 0, 1). */
START_TEST(geometry_shell_and_caps)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        shell_case(&s, 1.0, 0.0);
        shell_case(&s, 0.5 * M_PI, 0.0);
        shell_case(&s, SIX_OCLOCK + 0.1, 0.0);
        shell_case(&s, 0.0, 0.0);
        shell_case(&s, M_PI, 0.0);
        if (dim == 3) {
            const double zc = 0.5 * DRUM_L - RP + DELTA; /* 0.0451 */
            double top[3] = {0.01, 0.02, zc}, bottom[3] = {0.01, 0.02, -zc};
            expect up = ex(0, 0, 1), down = ex(0, 0, -1);
            CHECK_CONTACTS(&s, top, RP, 1, &up);
            CHECK_CONTACTS(&s, bottom, RP, 1, &down);
            const double rc = DRUM_R - RP + DELTA, q = 0.25 * M_PI;
            double edge[3] = {rc * cos(q), rc * sin(q), zc};
            expect two[2] = {ex(cos(q), sin(q), 0), ex(0, 0, 1)};
            CHECK_CONTACTS(&s, edge, RP, 2, two);
            /* a shell contact away from z = 0 is still radial */
            shell_case(&s, 2.0, -0.03);
        }
        demill_world_destroy(s.w);
    }
}
END_TEST

/* The rectangular lifter (face angle 0) at 6 o'clock, in lifter coordinates
 * (ρ, τ) and as points (τ, -ρ):
 *  - inner face ρ = 0.135: centre ρ = 0.135 - (r - δ) = 0.1301, τ = 0.002:
 *    (0.002, -0.1301); normal u = (0, -1); point (0.002, -0.13505). The shell
 *    is 0.15 - 0.1301 = 0.0199 > r away.
 *  - trailing face τ = -0.0075: centre τ = -0.0075 - 0.0049 = -0.0124,
 *    ρ = 0.142 (between 0.135 and 0.15): (-0.0124, -0.142); normal t = (1, 0);
 *    point (-0.00745, -0.142). Its distance from the axis is
 *    √(0.0124² + 0.142²) = 0.14254, 0.00746 > r from the shell.
 *  - leading face τ = +0.0075: the mirror image, (0.0124, -0.142), normal -t.
 *  - inner corners (0.135, ∓0.0075): the centre on the diagonal away from the
 *    bar, corner + (r - δ) b with b the bisector of the outward normals of
 *    the two faces, (-1, ∓1)/√2 in (ρ, τ); the closest point is the vertex, the
 *    normal -b: at the trailing corner (-0.0075, -0.135) the centre is
 *    (-0.0075 - 0.0049/√2, -0.135 + 0.0049/√2) = (-0.010965, -0.131535) and
 *    the normal (1, -1)/√2; at the leading corner (0.0075, -0.135) the normal
 *    is (-1, -1)/√2.
 *  - concave corner of the trailing face and the shell: τ = -0.0124 (r - δ
 *    outside the face) and |centre| = 0.15 - 0.0049 = 0.1451, so
 *    ρ = √(0.1451² - 0.0124²) = √0.02090025 = 0.144569; two contacts of
 *    overlap δ: the face (normal t) and the shell (normal centre / 0.1451).
 *    The foot on the face, (-0.0075, -0.144569), lies between the inner face
 *    and the shell. Same on the leading side with τ = +0.0124.
 * In 2D and in 3D (z = 0, far from the caps). */
static void rectangular_cases(const scene *s, double a)
{
    const double ri = DRUM_R - LIFT_H, hw = 0.5 * LIFT_W, g = RP - DELTA;
    double c[3], n[3];
    expect e;
    /* inner face */
    lift_xy(a, ri - g, 0.002, c);
    lift_xy(a, 1.0, 0.0, n);
    e = ex(n[0], n[1], 0);
    CHECK_CONTACTS(s, c, RP, 1, &e);
    lift_xy(a, ri - g, -0.0074, c); /* near the trailing end of the face */
    CHECK_CONTACTS(s, c, RP, 1, &e);
    /* trailing and leading side faces */
    for (int side = -1; side <= 1; side += 2) {
        lift_xy(a, 0.142, side * (hw + g), c);
        lift_xy(a, 0.0, -side, n);
        e = ex(n[0], n[1], 0);
        CHECK_CONTACTS(s, c, RP, 1, &e);
        lift_xy(a, 0.1375, side * (hw + g), c); /* nearer the inner corner */
        CHECK_CONTACTS(s, c, RP, 1, &e);
    }
    /* inner corners: b = (-1, side)/√2 in (ρ, τ) */
    for (int side = -1; side <= 1; side += 2) {
        const double s2 = sqrt(0.5);
        lift_xy(a, ri - g * s2, side * (hw + g * s2), c);
        lift_xy(a, s2, -side * s2, n);
        e = ex(n[0], n[1], 0);
        CHECK_CONTACTS(s, c, RP, 1, &e);
    }
    /* concave corners with the shell: two contacts */
    for (int side = -1; side <= 1; side += 2) {
        const double rc = DRUM_R - g, tau = side * (hw + g), rho = sqrt(rc * rc - tau * tau);
        lift_xy(a, rho, tau, c);
        lift_xy(a, 0.0, -side, n);
        expect two[2] = {ex(n[0], n[1], 0), ex(c[0] / rc, c[1] / rc, 0)};
        CHECK_CONTACTS(s, c, RP, 2, two);
    }
}

START_TEST(geometry_rectangular_lifter)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        /* the hand-computed points of the comment, at 6 o'clock exactly */
        double c1[3] = {0.002, -0.1301, 0};
        expect e1 = ex(0, -1, 0);
        CHECK_CONTACTS(&s, c1, RP, 1, &e1);
        double c2[3] = {-0.0124, -0.142, 0};
        expect e2 = ex(1, 0, 0);
        CHECK_CONTACTS(&s, c2, RP, 1, &e2);
        double c3[3] = {0.0124, -0.142, 0};
        expect e3 = ex(-1, 0, 0);
        CHECK_CONTACTS(&s, c3, RP, 1, &e3);
        rectangular_cases(&s, SIX_OCLOCK);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* The lifter with face angle f = 0.5 rad at 6 o'clock: tan f = 0.54630249,
 * the leading face τ = 0.0075 + (ρ - 0.15) tan f meets the inner face at
 * τ_v = 0.0075 - 0.015 tan f = -0.00069454; its outward normal is
 * (-sin f, cos f) in (ρ, τ), i.e. (cos f, sin f) = (0.877583, 0.479426) at
 * 6 o'clock (it faces +x and slightly up).
 *  - inclined face: foot at ρ = 0.1425, τ = 0.0075 (1 - tan f) = 0.00340273,
 *    the point (0.00340273, -0.1425); centre = foot + (r - δ)(cos f, sin f) =
 *    (0.00770288, -0.14015081); normal -(cos f, sin f); point = foot -
 *    (δ/2)(cos f, sin f). The other faces are behind it (inner face:
 *    -0.14015 < -0.135), and the shell is 0.15 - 0.14036 = 0.0096 > r away.
 *  - top leading corner (ρ, τ) = (0.135, -0.00069454): the bisector of the
 *    outward normals (-1, 0) and (-sin f, cos f) is at angle
 *    (π + π/2 + f)/2 = 3π/4 + 0.25 in (ρ, τ), b = (-0.860066, 0.510184); the
 *    centre is vertex + (r - δ) b, the normal -b.
 *  - concave corner of the inclined face and the shell: centre (ρ, τ) at
 *    distance r - δ outside the face, τ = tan f ρ + k with
 *    k = 0.0075 - 0.15 tan f + (r - δ)/cos f, and |centre| = 0.1451, so ρ is
 *    the positive root of (1 + tan² f) ρ² + 2 k tan f ρ + k² - 0.1451² = 0;
 *    two contacts: the face (normal (sin f, -cos f) in (ρ, τ)) and the shell.
 *  - the trailing face, its corner and the inner face (τ = -0.004, inside
 *    [-0.0075, -0.00069]) are those of the rectangular bar. */
START_TEST(geometry_inclined_lifter)
{
    const double f = 0.5, tf = tan(f), hw = 0.5 * LIFT_W, ri = DRUM_R - LIFT_H, g = RP - DELTA;
    const double a = SIX_OCLOCK;
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, f);
        double c[3], n[3];
        expect e;
        /* inclined face, hand-computed at 6 o'clock */
        const double foot[2] = {hw * (1 - tf), -0.1425};
        c[0] = foot[0] + g * cos(f);
        c[1] = foot[1] + g * sin(f);
        c[2] = 0.0;
        NEAR(c[0], 0.00770288, 1e-8);
        NEAR(c[1], -0.14015081, 1e-8);
        e = ex(-cos(f), -sin(f), 0);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        /* the same from lifter coordinates, nearer the top */
        lift_xy(a, 0.137, hw + (0.137 - DRUM_R) * tf, c);
        c[0] += g * cos(f);
        c[1] += g * sin(f);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        /* top leading corner */
        const double tv = hw - LIFT_H * tf, ang = 0.75 * M_PI + 0.5 * f;
        NEAR(tv, -0.00069454, 1e-8);
        NEAR(cos(ang), -0.860066, 1e-6);
        NEAR(sin(ang), 0.510184, 1e-6);
        lift_xy(a, ri + g * cos(ang), tv + g * sin(ang), c);
        lift_xy(a, -cos(ang), -sin(ang), n);
        e = ex(n[0], n[1], 0);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        /* concave corner of the inclined face and the shell */
        const double rc = DRUM_R - g, k = hw - DRUM_R * tf + g / cos(f);
        const double qa = 1 + tf * tf, qb = 2 * k * tf, qc = k * k - rc * rc;
        const double rho = (-qb + sqrt(qb * qb - 4 * qa * qc)) / (2 * qa), tau = tf * rho + k;
        lift_xy(a, rho, tau, c);
        NEAR(hypot(c[0], c[1]), rc, 1e-15);
        lift_xy(a, sin(f), -cos(f), n);
        expect two[2] = {ex(n[0], n[1], 0), ex(c[0] / rc, c[1] / rc, 0)};
        CHECK_CONTACTS(&s, c, RP, 2, two);
        /* the trailing side: unchanged by the face angle */
        lift_xy(a, 0.142, -(hw + g), c);
        e = ex(1, 0, 0);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        const double s2 = sqrt(0.5);
        lift_xy(a, ri - g * s2, -(hw + g * s2), c);
        e = ex(s2, -s2, 0);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        /* the (narrower) inner face */
        lift_xy(a, ri - g, -0.004, c);
        e = ex(0, -1, 0);
        CHECK_CONTACTS(&s, c, RP, 1, &e);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* The drum turned: speed ω = 2 rad/s from t = 0 (no ramp), time step 1e-3 s,
 * 250 steps: angle θ = ω t = 2 × 0.25 = 0.5 rad, the lifter's polar angle
 * 3π/2 + 0.5 = 5.21238898. At that angle every case of the rectangular bar
 * (inner face, side faces, inner corners, concave corners) holds in the turned
 * lifter coordinates, and a particle at the old place of the inner face
 * (0.002, -0.1301) touches nothing (the lifter has moved 0.5 × 0.135 = 0.0675
 * m away). Shell contacts are unchanged. Tolerance of the angles: the time is
 * the sum of 250 steps of 1e-3 s, exact to ~1e-16 s. */
START_TEST(geometry_turned_drum)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        DM_OK(s.w, demill_world_set(s.w, DEMILL_WORLD_TIME_STEP, 1e-3));
        DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_SPEED, 2.0));
        DM_OK(s.w, demill_world_step(s.w, 250));
        const double theta = 0.5;
        NEAR(drum_get(s.w, s.drum, DEMILL_DRUM_ANGLE), theta, 1e-14);
        double la = NAN;
        DM_OK(s.w, demill_drum_lifter_get(s.w, s.drum, 0, DEMILL_LIFTER_ANGLE, &la));
        NEAR(la, SIX_OCLOCK + theta, 1e-14);
        rectangular_cases(&s, SIX_OCLOCK + theta);
        double old[3] = {0.002, -0.1301, 0};
        CHECK_CONTACTS(&s, old, RP, 0, NULL);
        shell_case(&s, 1.0, 0.0);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* ---- 2. speed ----------------------------------------------------------- */

/* Gravity (3, -4, 0): |g| = 5 m/s². Drum D = 0.3.
 *  - no particle: ω_c = √(2·5/0.3) = √33.333 = 5.77350269 rad/s;
 *  - one particle of diameter 0.02: ω_c = √(10/0.28) = 5.97614305;
 *  - speed 3 rad/s: rpm = 3·60/2π = 28.6478898, fraction 3/5.97614305 =
 *    0.501996; speed -3 the same with minus signs;
 *  - 30 rpm: ω = 30·2π/60 = π, fraction π/5.97614305 = 0.525689;
 *  - fraction 0.75: ω = 0.75·5.97614305 = 4.48210729, rpm = 42.8007;
 *  - critical diameter 0.05 overrides the particle: ω_c = √(10/0.25) = √40 =
 *    6.32455532; fraction 0.75 set then gives ω = 4.74341649; back to 0, the
 *    particle's diameter counts again. */
START_TEST(speed_views)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
        demill_world *w = s.w;
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_X, 3.0));
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -4.0));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CRITICAL_SPEED), sqrt(10.0 / 0.3), TOL);
        double x[3] = {0, 0, 0}, r = 0.01;
        DM_OK(w, demill_particles_add(w, s.mat, 1, x, &r, NULL, 0, NULL));
        const double wc = sqrt(10.0 / 0.28);
        DM_ASSERT_REL(wc, 5.97614305, 1e-8);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CRITICAL_SPEED), wc, TOL);

        for (int sign = -1; sign <= 1; sign += 2) {
            DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED, sign * 3.0));
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), sign * 3.0, TOL);
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_RPM), sign * 28.6478898, 1e-8);
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_RPM), sign * 90.0 / M_PI, TOL);
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_FRACTION), sign * 3.0 / wc, TOL);
        }

        DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED_RPM, 30.0));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), M_PI, TOL);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_RPM), 30.0, TOL);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_FRACTION), M_PI / wc, TOL);
        DM_ASSERT_REL(M_PI / wc, 0.525689, 1e-5);

        DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), 0.75 * wc, TOL);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), 4.48210729, 1e-8);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_RPM), 0.75 * wc * 60 / (2 * M_PI),
                      TOL);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_FRACTION), 0.75, TOL);

        DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_CRITICAL_DIAMETER, 0.05));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CRITICAL_SPEED), sqrt(40.0), TOL);
        DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), 0.75 * sqrt(40.0), TOL);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), 4.74341649, 1e-8);
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_FRACTION), 0.75, TOL);
        DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_CRITICAL_DIAMETER, 0.0));
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CRITICAL_SPEED), wc, TOL);
        demill_world_destroy(w);
    }
}
END_TEST

/* Ramp T = 0.1 s set before the speed, then target ω = 2 rad/s at t = 0:
 * α = 2/0.1 = 20 rad/s², ω(t) = 20 t and θ(t) = 10 t² during the ramp, then
 * θ = ½·2·0.1 + 2 (t - 0.1) = 0.1 + 2 (t - 0.1). Time step 1e-3 s:
 *  - at once: current speed 0, target 2, angle 0;
 *  - 40 steps (t = 0.04): ω = 0.8, θ = 10·0.0016 = 0.016;
 *  - 100 steps (t = 0.1): ω = 2, θ = 0.1;
 *  - 150 steps (t = 0.15): ω = 2, θ = 0.2.
 * Then a new target -1 rad/s at t = 0.15 ramps from 2 over 0.1 s:
 * α = -30 rad/s², ω = 2 - 30 τ, θ = 0.2 + 2τ - 15τ²:
 *  - τ = 0.05 (50 steps): ω = 0.5, θ = 0.2 + 0.1 - 0.0375 = 0.2625;
 *  - τ = 0.1: ω = -1, θ = 0.2 + ½(2 - 1)·0.1 = 0.25;
 *  - τ = 0.2: θ = 0.25 - 0.1 = 0.15.
 * The time is the sum of the steps, exact to ~1e-16 s per step; angles and
 * speeds are checked to 1e-12 absolute. */
START_TEST(speed_ramp_angle_is_exact_integral)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
        demill_world *w = s.w;
        const demill_id d = s.drum;
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-3));
        DM_OK(w, demill_drum_set(w, d, DEMILL_DRUM_RAMP_TIME, 0.1));
        DM_OK(w, demill_drum_set(w, d, DEMILL_DRUM_SPEED, 2.0));
        NEAR(drum_get(w, d, DEMILL_DRUM_CURRENT_SPEED), 0.0, 0.0);
        NEAR(drum_get(w, d, DEMILL_DRUM_SPEED), 2.0, 0.0);
        NEAR(drum_get(w, d, DEMILL_DRUM_ANGLE), 0.0, 0.0);
        struct {
            int steps;
            double omega, theta;
        } const plan[] = {{40, 0.8, 0.016}, {60, 2.0, 0.1}, {50, 2.0, 0.2}};
        for (int k = 0; k < 3; k++) {
            DM_OK(w, demill_world_step(w, (uint64_t)plan[k].steps));
            NEAR(drum_get(w, d, DEMILL_DRUM_CURRENT_SPEED), plan[k].omega, 1e-12);
            NEAR(drum_get(w, d, DEMILL_DRUM_ANGLE), plan[k].theta, 1e-12);
            NEAR(drum_get(w, d, DEMILL_DRUM_SPEED), 2.0, 0.0);
        }
        DM_OK(w, demill_drum_set(w, d, DEMILL_DRUM_SPEED, -1.0));
        NEAR(drum_get(w, d, DEMILL_DRUM_SPEED), -1.0, 0.0);
        struct {
            int steps;
            double omega, theta;
        } const back[] = {{50, 0.5, 0.2625}, {50, -1.0, 0.25}, {100, -1.0, 0.15}};
        for (int k = 0; k < 3; k++) {
            DM_OK(w, demill_world_step(w, (uint64_t)back[k].steps));
            NEAR(drum_get(w, d, DEMILL_DRUM_CURRENT_SPEED), back[k].omega, 1e-12);
            NEAR(drum_get(w, d, DEMILL_DRUM_ANGLE), back[k].theta, 1e-12);
        }
        demill_world_destroy(w);
    }
}
END_TEST

/* Revolutions: ω = 2π/1.0005 rad/s from t = 0 (no ramp), time step 1e-3 s:
 * after k steps the drum has turned k/1000.5 revolutions: 1000 steps 0.9995
 * (0 completed), 1001 steps 1.0005 (1 completed), 1010 steps 1.0095 (1),
 * 2000 steps 1.9990 (1), 2002 steps 2.0010 (2). The exact steps where a turn
 * completes are checked last, so that a lag of one step is reported as such. */
START_TEST(revolutions_count_completed_turns)
{
    scene s = drum_scene(3, DEMILL_DAMPING_NONE);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-3));
    DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED, 2 * M_PI / 1.0005));
    DM_OK(w, demill_world_step(w, 1000));
    NEAR(drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS), 0.0, 0.0);
    DM_OK(w, demill_world_step(w, 1));
    const double at1001 = drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS);
    DM_OK(w, demill_world_step(w, 9));
    NEAR(drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS), 1.0, 0.0);
    DM_OK(w, demill_world_step(w, 990));
    NEAR(drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS), 1.0, 0.0);
    DM_OK(w, demill_world_step(w, 2));
    const double at2002 = drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS);
    DM_OK(w, demill_world_step(w, 10));
    NEAR(drum_get(w, s.drum, DEMILL_DRUM_REVOLUTIONS), 2.0, 0.0);
    ck_assert_msg(at1001 == 1.0, "after 1.0005 turns (step 1001): %g revolutions, expected 1",
                  at1001);
    ck_assert_msg(at2002 == 2.0, "after 2.0010 turns (step 2002): %g revolutions, expected 2",
                  at2002);
    demill_world_destroy(w);
}
END_TEST

/* A new speed takes effect at once when there is no ramp (drum.h: "sets the
 * target speed from now on, reached after DEMILL_DRUM_RAMP_TIME" = 0): the
 * current speed is the target right after the call, and the power of a force
 * evaluation at the current state is -T ω with the new ω. Scene: a particle
 * pressed with δ = 1e-4 against the trailing face of the lifter at
 * 6 o'clock, centre (-0.0124, -0.142): the lifter is pushed with
 * k δ = 5e4·1e-4 = 5 N along +x at the contact point (-0.00745, -0.142), so
 * the drum feels T_z = x F_y - y F_x = 0.142·5 = 0.71 N m; at ω = 2 rad/s the
 * power is P = -T ω = -1.42 W. */
START_TEST(speed_change_takes_effect_at_once)
{
    scene s = lifter_scene(3, 0.0);
    demill_world *w = s.w;
    double c[3] = {-0.0124, -0.142, 0}, r = RP;
    DM_OK(w, demill_particles_add(w, s.mat, 1, c, &r, NULL, 0, NULL));
    DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED, 2.0));
    DM_OK(w, demill_world_step(w, 0));
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_TORQUE), 0.71, 1e-10);
    const double omega = drum_get(w, s.drum, DEMILL_DRUM_CURRENT_SPEED);
    const double power = drum_get(w, s.drum, DEMILL_DRUM_POWER);
    ck_assert_msg(fabs(omega - 2.0) <= 2.0 * TOL && fabs(power + 1.42) <= 1.42e-10,
                  "right after setting 2 rad/s without a ramp: current speed %g (expected 2), "
                  "power %g W (expected -1.42)",
                  omega, power);
    /* one real step later both are right */
    DM_OK(w, demill_world_step(w, 1));
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CURRENT_SPEED), 2.0, TOL);
    demill_world_destroy(w);
}
END_TEST

/* A speed given as a fraction of critical follows the charge (drum.h,
 * DEMILL_DRUM_CRITICAL_DIAMETER): set with no particle, ω = 0.5 √(2 g / D) =
 * 4.04351332 rad/s; once a ball of d = 0.08 m is added, the next run converts
 * the fraction again: 0.5 √(2 g / (D - d)) = 0.5 √(19.62 / 0.22) = 4.72180628,
 * reached at once (no ramp). */
START_TEST(fraction_follows_the_charge)
{
    scene s = drum_scene(3, DEMILL_DAMPING_NONE);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_SPEED_FRACTION, 0.5));
    const double target = 0.5 * sqrt(2 * 9.81 / 0.3);
    DM_ASSERT_REL(target, 4.04351332, 1e-8);
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), target, TOL);
    double x[3] = {0, 0, 0}, r = 0.04;
    DM_OK(w, demill_particles_add(w, s.mat, 1, x, &r, NULL, 0, NULL));
    DM_OK(w, demill_world_step(w, 1));
    const double followed = 0.5 * sqrt(2 * 9.81 / (0.3 - 0.08));
    DM_ASSERT_REL(followed, 4.72180628, 1e-8);
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED), followed, TOL);
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_CURRENT_SPEED), followed, TOL);
    DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_SPEED_FRACTION), 0.5, TOL);
    demill_world_destroy(w);
}
END_TEST

/* ---- 3. empty drum ------------------------------------------------------ */

/* No particles: nothing pushes on the drum, so torque, power, the centre-of-
 * mass power and the energy put in are exactly 0 at every step; with
 * ω = 2π/1.0005 rad/s and Δt = 1e-3 s the first revolution completes between
 * steps 1000 and 1001: the mean power is NaN at step 1000 and exactly 0 at step
 * 1010 (the energy put in over the revolution, 0, over its duration), as are
 * the centre-of-mass power mean and the dissipation mean. 2D and 3D. */
START_TEST(empty_drum_draws_no_power)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
        demill_world *w = s.w;
        const demill_id d = s.drum;
        DM_OK(w, demill_drum_set(w, d, DEMILL_DRUM_LIFTERS, 4));
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-3));
        DM_OK(w, demill_drum_set(w, d, DEMILL_DRUM_SPEED, 2 * M_PI / 1.0005));
        ck_assert(isnan(drum_get(w, d, DEMILL_DRUM_POWER_MEAN)));
        for (int k = 0; k < 10; k++) {
            DM_OK(w, demill_world_step(w, 100));
            ck_assert(drum_get(w, d, DEMILL_DRUM_TORQUE) == 0.0);
            ck_assert(drum_get(w, d, DEMILL_DRUM_POWER) == 0.0);
            ck_assert(drum_get(w, d, DEMILL_DRUM_POWER_CM) == 0.0);
            ck_assert(drum_get(w, d, DEMILL_DRUM_ENERGY_IN) == 0.0);
        }
        ck_assert(isnan(drum_get(w, d, DEMILL_DRUM_POWER_MEAN)));
        ck_assert(isnan(drum_get(w, d, DEMILL_DRUM_POWER_CM_MEAN)));
        DM_OK(w, demill_world_step(w, 10));
        NEAR(drum_get(w, d, DEMILL_DRUM_REVOLUTIONS), 1.0, 0.0);
        ck_assert(drum_get(w, d, DEMILL_DRUM_POWER_MEAN) == 0.0);
        ck_assert(drum_get(w, d, DEMILL_DRUM_POWER_CM_MEAN) == 0.0);
        ck_assert(drum_get(w, d, DEMILL_DRUM_DISSIPATION_MEAN) == 0.0);
        ck_assert(drum_get(w, d, DEMILL_DRUM_TORQUE) == 0.0);
        ck_assert(drum_get(w, d, DEMILL_DRUM_POWER) == 0.0);
        demill_world_destroy(w);
    }
}
END_TEST

/* ---- 4. filling ---------------------------------------------------------- */

typedef struct lifter_geom {
    double angle, h, w, face;
} lifter_geom;

typedef struct drum_geom {
    double R, L;
    int nl;
    lifter_geom l[8];
} drum_geom;

/* Signed distance from (x, y) to the lifter prism (negative inside), worked
 * out independently of the library from the description in drum.h: in lifter
 * coordinates the bar is the convex quadrilateral (ri, -w/2), (2R, -w/2),
 * (2R, w/2 + R tan f), (ri, w/2 - h tan f) (its base continued well behind
 * the shell, which changes nothing inside the drum), counter-clockwise in the
 * (ρ, τ) plane. */
static double lifter_distance(const lifter_geom *l, double R, double x, double y)
{
    const double rho = x * cos(l->angle) + y * sin(l->angle);
    const double tau = -x * sin(l->angle) + y * cos(l->angle);
    const double tf = tan(l->face), hw = 0.5 * l->w, ri = R - l->h;
    const double v[4][2] = {{ri, -hw}, {2 * R, -hw}, {2 * R, hw + R * tf}, {ri, hw - l->h * tf}};
    int inside = 1;
    double best = INFINITY;
    for (int k = 0; k < 4; k++) {
        const double *p = v[k], *q = v[(k + 1) % 4];
        const double ex_ = q[0] - p[0], ey_ = q[1] - p[1];
        const double dx = rho - p[0], dy = tau - p[1];
        if (ex_ * dy - ey_ * dx < 0.0)
            inside = 0;
        double s = (dx * ex_ + dy * ey_) / (ex_ * ex_ + ey_ * ey_);
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        best = fmin(best, hypot(dx - s * ex_, dy - s * ey_));
    }
    return inside ? -best : best;
}

/* Reads positions (3 per particle) and radii; returns the count. */
static size_t read_charge(demill_world *w, double **x, double **r)
{
    size_t n = 0;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, NULL, 0, &n));
    *x = malloc((n ? n : 1) * 3 * sizeof **x);
    *r = malloc((n ? n : 1) * sizeof **r);
    ck_assert(*x && *r);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, *x, n, &n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, *r, n, &n));
    return n;
}

/* No particle overlaps another (all pairs: distance >= r_i + r_j), the shell
 * (√(x² + y²) + r <= R), an end cap (|z| + r <= L/2, 3D) or a lifter
 * (distance to its prism >= r); and the library sees no contact before any
 * step. */
static void check_charge_clear(demill_world *w, int dim, const drum_geom *g)
{
    double *x, *r;
    const size_t n = read_charge(w, &x, &r);
    for (size_t i = 0; i < n; i++) {
        const double *xi = x + 3 * i;
        ck_assert_msg(hypot(xi[0], xi[1]) + r[i] <= g->R, "particle %zu overlaps the shell", i);
        if (dim == 3)
            ck_assert_msg(fabs(xi[2]) + r[i] <= 0.5 * g->L, "particle %zu overlaps a cap", i);
        else
            ck_assert(xi[2] == 0.0);
        for (int k = 0; k < g->nl; k++)
            ck_assert_msg(lifter_distance(&g->l[k], g->R, xi[0], xi[1]) >= r[i],
                          "particle %zu overlaps lifter %d", i, k);
        for (size_t j = 0; j < i; j++) {
            const double *xj = x + 3 * j;
            const double dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
            const double sum = r[i] + r[j];
            ck_assert_msg(dx * dx + dy * dy + dz * dz >= sum * sum,
                          "particles %zu and %zu overlap", j, i);
        }
    }
    free(x);
    free(r);
    size_t nc = 99;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &nc));
    ck_assert_msg(nc == 0, "%zu contacts in a fresh fill", nc);
}

/* The fill scene: a drum of diameter D and length L with nl evenly spaced
 * lifters of height h, width wd and face angle f (phase 3π/2: at 3π/2, then
 * every 2π/nl), and its geometry for check_charge_clear(). */
static scene fill_scene(int dim, double D, double L, int nl, double h, double wd, double f,
                        drum_geom *g)
{
    scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_DIAMETER, D));
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_LENGTH, L));
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_LIFTERS, nl));
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_LIFTER_HEIGHT, h));
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_LIFTER_WIDTH, wd));
    DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_LIFTER_FACE_ANGLE, f));
    ck_assert(drum_get(s.w, s.drum, DEMILL_DRUM_LIFTER_COUNT) == nl);
    g->R = 0.5 * D;
    g->L = L;
    g->nl = nl;
    for (int k = 0; k < nl; k++)
        g->l[k] = (lifter_geom){SIX_OCLOCK + 2 * M_PI * k / nl, h, wd, f};
    return s;
}

static size_t particle_count(demill_world *w)
{
    return (size_t)world_get(w, DEMILL_WORLD_PARTICLE_COUNT);
}

/* Count targets are met exactly: 100 particles of one class; 201 of two
 * classes (0.01 m, 0.02 m; mass fractions 0.5, 0.5), where the per-class
 * shares 201 × (8/9, 1/9) = (178.67, 22.33) must be rounded so that they add
 * up to 201; 257 from a Rosin-Rammler distribution (32 classes, each rounded).
 * The returned ids are those of the world's new particles. Each charge is
 * clear of the walls (4 lifters of 0.015 × 0.015) and of itself. The drum is
 * 0.3 × 0.1 in 3D and 0.6 wide in 2D (a 0.3 circle has only about
 * (0.3/0.0208)² π/4 = 163 lattice sites of spacing 1.04 × 0.02). */
START_TEST(fill_count_is_exact)
{
    drum_geom g;
    /* the independent lifter distance on points of the geometry tests: inner
     * face and trailing face at r - δ = 0.0049, inside the bar 0.005 below the
     * inner face (the side faces are 0.0075 away), and 5 mm diagonally
     * (3, 4) off the trailing inner corner */
    const lifter_geom l0 = {SIX_OCLOCK, 0.015, 0.015, 0.0};
    NEAR(lifter_distance(&l0, 0.15, 0.002, -0.1301), 0.0049, 1e-15);
    NEAR(lifter_distance(&l0, 0.15, -0.0124, -0.142), 0.0049, 1e-15);
    NEAR(lifter_distance(&l0, 0.15, 0.0, -0.14), -0.005, 1e-15);
    NEAR(lifter_distance(&l0, 0.15, -0.0105, -0.131), 0.005, 1e-15);
    struct {
        int dist;
        double params[4];
        size_t np, count;
    } const cases[] = {
        {DEMILL_SIZES_CLASSES, {0.02, 1.0}, 2, 100},
        {DEMILL_SIZES_CLASSES, {0.01, 0.5, 0.02, 0.5}, 4, 201},
        {DEMILL_SIZES_ROSIN_RAMMLER, {0.01, 3.0, 0.006, 0.016}, 4, 257},
    };
    for (int dim = 2; dim <= 3; dim++)
        for (int k = 0; k < 3; k++) {
            scene s = fill_scene(dim, dim == 3 ? 0.3 : 0.6, 0.1, 4, 0.015, 0.015, 0.0, &g);
            demill_id ids[300], listed[300];
            size_t added = 0, n = 0;
            DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, cases[k].dist, cases[k].params,
                                        cases[k].np, DEMILL_FILL_COUNT, (double)cases[k].count, 7,
                                        ids, 300, &added));
            ck_assert_uint_eq(added, cases[k].count);
            ck_assert_uint_eq(particle_count(s.w), cases[k].count);
            DM_OK(s.w, demill_particles_read_ids(s.w, DEMILL_PARTICLE_ID, listed, 300, &n));
            ck_assert_uint_eq(n, cases[k].count);
            for (size_t i = 0; i < n; i++) {
                int found = 0;
                for (size_t j = 0; j < n && !found; j++)
                    found = listed[j] == ids[i];
                ck_assert_msg(found, "returned id %zu is not a particle of the world", i);
            }
            check_charge_clear(s.w, dim, &g);
            demill_world_destroy(s.w);
        }
}
END_TEST

/* Mass target M = 0.5 kg of two classes (d = 0.01, fraction 0.3) and (0.02,
 * 0.7); particle masses m1 = π/6·0.01³·2500 = 1.30900e-3 kg and
 * m2 = π/6·0.02³·2500 = 1.04720e-2 kg; exact shares 0.15/m1 = 114.59 and
 * 0.35/m2 = 33.42 particles, rounded to whole particles: each class count n_k
 * = x_k + e_k with |e_k| < 1. So
 *  - total mass M' = M + Σ e_k m_k: with two classes and rounding to the
 *    nearest total, |M' - M| < m2, one largest particle;
 *  - class mass M_k - f_k M' = (1 - f_k) e_k m_k - f_k Σ_{j≠k} e_j m_j, less
 *    than m2 in size: each class's fraction is within one largest particle
 *    (m2/M') of the requested one.
 * Largest remainder: floors 114 + 33 = 147 < 148.01, so the larger remainder
 * (0.59, class 0) gets one more: 115 and 33. In 2D (spheres held in the
 * plane) the masses are the same; the 2D drum is 0.6 wide to hold the 148
 * particles on its lattice. */
START_TEST(fill_mass_classes)
{
    drum_geom g;
    for (int dim = 2; dim <= 3; dim++) {
        scene s = fill_scene(dim, 0.3, 0.1, 4, 0.015, 0.015, 0.0, &g);
        if (dim == 2)
            DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_DIAMETER, 0.6));
        g.R = dim == 2 ? 0.3 : 0.15;
        const double params[4] = {0.01, 0.3, 0.02, 0.7}, M = 0.5;
        const double m1 = sphere_mass(0.005), m2 = sphere_mass(0.01);
        DM_ASSERT_REL(m1, 1.30900e-3, 1e-5);
        DM_ASSERT_REL(m2, 1.04720e-2, 1e-5);
        size_t added = 0;
        DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, params, 4,
                                    DEMILL_FILL_MASS, M, 11, NULL, 0, &added));
        double *x, *r, *m;
        const size_t n = read_charge(s.w, &x, &r);
        ck_assert_uint_eq(n, added);
        m = malloc(n * sizeof *m);
        DM_OK(s.w, demill_particles_read(s.w, DEMILL_PARTICLE_MASS, m, n, NULL));
        double mass[2] = {0, 0};
        size_t count[2] = {0, 0};
        for (size_t i = 0; i < n; i++) {
            ck_assert(r[i] == 0.005 || r[i] == 0.01);
            const int k = r[i] == 0.01;
            mass[k] += m[i];
            count[k]++;
        }
        const double total = mass[0] + mass[1];
        ck_assert_msg(fabs(total - M) < m2, "mass %g, target %g", total, M);
        ck_assert_msg(fabs(mass[0] - 0.3 * total) < m2, "class 0: %g of %g", mass[0], total);
        ck_assert_msg(fabs(mass[1] - 0.7 * total) < m2, "class 1: %g of %g", mass[1], total);
        ck_assert_uint_eq(count[0], 115);
        ck_assert_uint_eq(count[1], 33);
        free(x);
        free(r);
        free(m);
        check_charge_clear(s.w, dim, &g);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* Mass fraction below diameter `cut` and the diameter range of the charge. */
static double mass_below(demill_world *w, double cut, double *dlo, double *dhi)
{
    double *x, *r, *m;
    const size_t n = read_charge(w, &x, &r);
    m = malloc(n * sizeof *m);
    ck_assert(m != NULL);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_MASS, m, n, NULL));
    double below = 0, total = 0;
    *dlo = INFINITY;
    *dhi = 0;
    for (size_t i = 0; i < n; i++) {
        const double d = 2 * r[i];
        *dlo = fmin(*dlo, d);
        *dhi = fmax(*dhi, d);
        total += m[i];
        if (d < cut)
            below += m[i];
    }
    free(x);
    free(r);
    free(m);
    return below / total;
}

/* Rosin-Rammler F(d) = 1 - exp(-(d/d63)^n) with d63 = 0.01, n = 8, truncated
 * to [0.005, 0.02]; mass target 1 kg (about 1060 particles) in a drum of
 * diameter 0.4 and length 0.1 (no lifters). The mass below d63 should be the
 * truncated F(d63) = (F(0.01) - F(0.005))/(F(0.02) - F(0.005)) =
 * (0.6321206 - 0.0038986)/(1 - 0.0038986) = 0.6306808, within 0.14 % of the
 * untruncated 1 - 1/e = 63.2 %. The 32 classes of the fill have equal
 * log-width (ratio 4^(1/32)), so d63 = 0.005 × 4^(16/32) is a class edge and
 * the discretisation itself adds no error in expectation. What remains:
 * (1) every class count is rounded by less than one particle (a particle
 * below d63 weighs at most 1.3e-3 kg = 0.13 % of the total; the 16 rounding
 * errors are of random sign, about 0.13 % × √(16/12) = 0.15 % together) and
 * (2) the diameters within a class are random (mass spread ±7 % in a class,
 * about 0.1 % on the 700 particles below d63). Tolerance 0.01 (1 percentage
 * point), about 5 standard deviations. Every diameter lies in
 * [0.005, 0.02] (the upper end up to round-off 1e-12 of the class edge
 * d_min·(d_max/d_min)). */
START_TEST(fill_rosin_rammler)
{
    drum_geom g;
    scene s = fill_scene(3, 0.4, 0.1, 0, 0.015, 0.015, 0.0, &g);
    const double p[4] = {0.01, 8.0, 0.005, 0.02};
    DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_ROSIN_RAMMLER, p, 4,
                                DEMILL_FILL_MASS, 1.0, 3, NULL, 0, NULL));
    const double F = (exp(-pow(0.5, 8.0)) - exp(-1.0)) / (exp(-pow(0.5, 8.0)) - exp(-256.0));
    DM_ASSERT_REL(F, 0.6306808, 1e-6);
    double lo, hi;
    const double frac = mass_below(s.w, 0.01, &lo, &hi);
    ck_assert_msg(lo >= 0.005 && hi <= 0.02 * (1 + 1e-12), "diameters in [%g, %g]", lo, hi);
    NEAR(frac, F, 0.01);
    NEAR(frac, 1 - exp(-1.0), 0.0115);
    check_charge_clear(s.w, 3, &g);
    demill_world_destroy(s.w);
}
END_TEST

/* Normal by mass, mean 0.01, standard deviation 0.001, truncated to
 * [0.01/1.3, 0.013] = [0.0076923, 0.013] (whose geometric middle is the mean,
 * so the mean is the edge between classes 15 and 16). Mass target 1 kg (about
 * 800 particles), drum 0.4 × 0.1. Mass below the mean: (Φ(0) - Φ(-2.30769))
 * / (Φ(3) - Φ(-2.30769)) = (0.5 - 0.0105081)/(0.9986501 - 0.0105081) =
 * 0.4953659. Tolerance 0.01 as for Rosin-Rammler. */
START_TEST(fill_normal)
{
    drum_geom g;
    scene s = fill_scene(3, 0.4, 0.1, 0, 0.015, 0.015, 0.0, &g);
    const double dmin = 0.01 / 1.3, p[4] = {0.01, 0.001, dmin, 0.013};
    DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_NORMAL, p, 4, DEMILL_FILL_MASS,
                                1.0, 5, NULL, 0, NULL));
    const double phi_lo = 0.5 * erfc((0.01 - dmin) / 0.001 / sqrt(2.0));
    const double phi_hi = 0.5 * erfc(-3.0 / sqrt(2.0));
    const double F = (0.5 - phi_lo) / (phi_hi - phi_lo);
    DM_ASSERT_REL(F, 0.4953659, 1e-6);
    double lo, hi;
    const double frac = mass_below(s.w, 0.01, &lo, &hi);
    ck_assert_msg(lo >= dmin && hi <= 0.013 * (1 + 1e-12), "diameters in [%g, %g]", lo, hi);
    NEAR(frac, F, 0.01);
    check_charge_clear(s.w, 3, &g);
    demill_world_destroy(s.w);
}
END_TEST

/* Bulk filling J = 0.2 with the default porosity 0.4, in the drum D = 0.3
 * (R = 0.15), L = 0.1, with 4 lifters h = w = 0.04, face angle 0.5
 * (tan = 0.54630249): a lifter's cross-section is h (w - h tan f/2) =
 * 0.04 (0.04 - 0.0109260498) = 1.16295801e-3 m², so the inner area is
 * π 0.15² - 4·1.16295801e-3 = 0.0706858347 - 0.0046518320 = 0.0660340027 m²
 * (a rectangular-bar formula h w would give 0.0642858 instead).
 *  - 3D: V = 0.0660340027 × 0.1 = 6.60340027e-3 m³; solid volume
 *    J V (1 - 0.4) = 7.92408032e-4 m³; particles of d = 0.01 (π/6·1e-6 =
 *    5.23598776e-7 m³): 1513.4 of them, so Σ π/6 d³ within one particle's
 *    volume of the target (the h w formula would be 40 particles off).
 *  - 2D: solid area 0.2·0.6·0.0660340027 = 7.92408032e-3 m²; particles of
 *    d = 0.005 (π r² = 1.96349541e-5 m²): 403.6 of them; within one particle's
 *    area (the h w formula: 10.7 particles off). */
START_TEST(fill_fraction)
{
    drum_geom g;
    const double f = 0.5, h = 0.04, wd = 0.04;
    const double area = M_PI * 0.15 * 0.15 - 4 * h * (wd - 0.5 * h * tan(f));
    DM_ASSERT_REL(area, 0.0660340027, 1e-9);
    for (int dim = 2; dim <= 3; dim++) {
        scene s = fill_scene(dim, 0.3, 0.1, 4, h, wd, f, &g);
        const double d = dim == 3 ? 0.01 : 0.005, cls[2] = {d, 1.0};
        DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 2,
                                    DEMILL_FILL_FRACTION, 0.2, 13, NULL, 0, NULL));
        const double target = 0.2 * 0.6 * (dim == 3 ? area * 0.1 : area);
        const double one = dim == 3 ? M_PI / 6 * d * d * d : M_PI / 4 * d * d;
        double *x, *r, solid = 0;
        const size_t n = read_charge(s.w, &x, &r);
        for (size_t i = 0; i < n; i++)
            solid += dim == 3 ? 4.0 / 3.0 * M_PI * r[i] * r[i] * r[i] : M_PI * r[i] * r[i];
        free(x);
        free(r);
        ck_assert_msg(fabs(solid - target) <= one,
                      "%dD: solid %.9g, target %.9g (%zu particles of %.9g)", dim, solid, target,
                      n, one);
        check_charge_clear(s.w, dim, &g);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* Fills a fresh fill scene (D = 0.3, 4 lifters) with 150 particles of two
 * classes from `seed`; returns positions and radii. */
static size_t seeded_fill(int dim, uint64_t seed, double **x, double **r)
{
    drum_geom g;
    scene s = fill_scene(dim, 0.3, 0.1, 4, 0.015, 0.015, 0.0, &g);
    const double cls[4] = {0.01, 0.4, 0.016, 0.6};
    DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 4,
                                DEMILL_FILL_COUNT, 150, seed, NULL, 0, NULL));
    const size_t n = read_charge(s.w, x, r);
    demill_world_destroy(s.w);
    return n;
}

/* The same call on a fresh identical world gives bitwise identical positions
 * and radii; another seed gives other positions (the jitter differs) and,
 * with two classes shuffled, another order of radii. */
START_TEST(fill_is_reproducible_from_seed)
{
    for (int dim = 2; dim <= 3; dim++) {
        double *x1, *r1, *x2, *r2, *x3, *r3;
        const size_t n1 = seeded_fill(dim, 42, &x1, &r1);
        const size_t n2 = seeded_fill(dim, 42, &x2, &r2);
        const size_t n3 = seeded_fill(dim, 43, &x3, &r3);
        ck_assert_uint_eq(n1, 150);
        ck_assert_uint_eq(n2, 150);
        ck_assert_uint_eq(n3, 150);
        ck_assert(memcmp(x1, x2, 3 * n1 * sizeof *x1) == 0);
        ck_assert(memcmp(r1, r2, n1 * sizeof *r1) == 0);
        ck_assert(memcmp(x1, x3, 3 * n1 * sizeof *x1) != 0);
        ck_assert(memcmp(r1, r3, n1 * sizeof *r1) != 0);
        free(x1);
        free(r1);
        free(x2);
        free(r2);
        free(x3);
        free(r3);
    }
}
END_TEST

/* Balls then ore: 40 balls of d = 0.03 of one material, then 400 ore
 * particles of d = 0.008 of another: the second fill avoids the first (no
 * pair overlaps, nothing touches a wall), both materials are there in the
 * requested numbers. */
START_TEST(fill_second_material_avoids_first)
{
    drum_geom g;
    for (int dim = 2; dim <= 3; dim++) {
        scene s = fill_scene(dim, 0.3, 0.1, 4, 0.015, 0.015, 0.0, &g);
        if (dim == 2) {
            DM_OK(s.w, demill_drum_set(s.w, s.drum, DEMILL_DRUM_DIAMETER, 0.6));
            g.R = 0.3;
        }
        demill_id ore;
        DM_OK(s.w, demill_material_create(s.w, &ore));
        DM_OK(s.w, demill_pair_set(s.w, ore, ore, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        DM_OK(s.w, demill_pair_set(s.w, ore, s.mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        DM_OK(s.w, demill_pair_set(s.w, ore, s.wallmat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        const double balls[2] = {0.03, 1.0}, fines[2] = {0.008, 1.0};
        DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, balls, 2,
                                    DEMILL_FILL_COUNT, 40, 1, NULL, 0, NULL));
        DM_OK(s.w, demill_drum_fill(s.w, s.drum, ore, DEMILL_SIZES_CLASSES, fines, 2,
                                    DEMILL_FILL_COUNT, 400, 1, NULL, 0, NULL));
        ck_assert_uint_eq(particle_count(s.w), 440);
        demill_id mats[440];
        size_t n = 0, nore = 0;
        DM_OK(s.w, demill_particles_read_ids(s.w, DEMILL_PARTICLE_MATERIAL, mats, 440, &n));
        for (size_t i = 0; i < n; i++)
            nore += mats[i] == ore;
        ck_assert_uint_eq(nore, 400);
        check_charge_clear(s.w, dim, &g);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* A charge that does not fit: 100000 particles of d = 0.02 in the 0.3 × 0.1
 * drum (whose volume holds fewer than 7.1e-3/8e-6 ≈ 900 such cubes) returns
 * DEMILL_ERR_INVALID_VALUE and adds nothing: the 30 particles of an earlier
 * fill stay the only ones, with their positions. *added, "the number of
 * particles added", may not claim any. */
START_TEST(fill_that_does_not_fit_adds_nothing)
{
    drum_geom g;
    for (int dim = 2; dim <= 3; dim++) {
        scene s = fill_scene(dim, 0.3, 0.1, 4, 0.015, 0.015, 0.0, &g);
        const double cls[2] = {0.02, 1.0};
        DM_OK(s.w, demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 2,
                                    DEMILL_FILL_COUNT, 30, 1, NULL, 0, NULL));
        double *x0, *r0, *x1, *r1;
        const size_t n0 = read_charge(s.w, &x0, &r0);
        size_t added = 12345;
        ck_assert_int_eq(demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 2,
                                          DEMILL_FILL_COUNT, 100000, 2, NULL, 0, NULL),
                         DEMILL_ERR_INVALID_VALUE);
        const size_t n1 = read_charge(s.w, &x1, &r1);
        ck_assert_uint_eq(n0, 30);
        ck_assert_uint_eq(n1, 30);
        ck_assert(memcmp(x0, x1, 3 * n0 * sizeof *x0) == 0);
        ck_assert(memcmp(r0, r1, n0 * sizeof *r0) == 0);
        free(x0);
        free(r0);
        free(x1);
        free(r1);
        ck_assert_int_eq(demill_drum_fill(s.w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 2,
                                          DEMILL_FILL_COUNT, 100000, 2, NULL, 0, &added),
                         DEMILL_ERR_INVALID_VALUE);
        ck_assert_uint_eq(particle_count(s.w), 30);
        ck_assert_msg(added == 0 || added == 12345,
                      "%dD: a fill that added nothing reports %zu particles added", dim, added);
        demill_world_destroy(s.w);
    }
}
END_TEST

/* Bad arguments give their documented codes (drum.h, common.h: a
 * non-finite value DEMILL_ERR_NOT_FINITE, an unknown choice
 * DEMILL_ERR_UNKNOWN_KEY, an out-of-range value DEMILL_ERR_INVALID_VALUE,
 * NULL params DEMILL_ERR_NULL_POINTER, a short id buffer
 * DEMILL_ERR_BUFFER_TOO_SMALL) and add nothing. */
START_TEST(fill_bad_arguments)
{
    drum_geom g;
    scene s = fill_scene(3, 0.3, 0.1, 4, 0.015, 0.015, 0.0, &g);
    demill_world *w = s.w;
    const double cls[2] = {0.01, 1.0}, odd[3] = {0.01, 1.0, 0.02};
    const double rr[4] = {0.01, 3.0, 0.005, 0.02}, rr_nan[4] = {0.01, NAN, 0.005, 0.02};
    const double rr_swapped[4] = {0.01, 3.0, 0.02, 0.005}, rr_equal[4] = {0.01, 3.0, 0.01, 0.01};
    const double cls_neg[2] = {-0.01, 1.0}, cls_negf[2] = {0.01, -1.0};
    demill_id ids[4];
    struct {
        int dist;
        const double *p;
        size_t np;
        int target;
        double value;
        demill_id *ids;
        size_t cap;
        demill_status want;
    } const cases[] = {
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_COUNT, NAN, NULL, 0, DEMILL_ERR_NOT_FINITE},
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_MASS, INFINITY, NULL, 0,
         DEMILL_ERR_NOT_FINITE},
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_COUNT, -5, NULL, 0, DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_MASS, 0, NULL, 0, DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_FRACTION, 1.5, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {7, cls, 2, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_UNKNOWN_KEY},
        {0, cls, 2, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_UNKNOWN_KEY},
        {DEMILL_SIZES_CLASSES, cls, 2, 9, 10, NULL, 0, DEMILL_ERR_UNKNOWN_KEY},
        {DEMILL_SIZES_CLASSES, odd, 3, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_CLASSES, cls, 0, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_ROSIN_RAMMLER, rr, 3, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_NORMAL, odd, 3, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_ROSIN_RAMMLER, rr_swapped, 4, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_ROSIN_RAMMLER, rr_equal, 4, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_NORMAL, rr_swapped, 4, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_ROSIN_RAMMLER, rr_nan, 4, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_NOT_FINITE},
        {DEMILL_SIZES_CLASSES, cls_neg, 2, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_CLASSES, cls_negf, 2, DEMILL_FILL_COUNT, 10, NULL, 0,
         DEMILL_ERR_INVALID_VALUE},
        {DEMILL_SIZES_CLASSES, NULL, 2, DEMILL_FILL_COUNT, 10, NULL, 0, DEMILL_ERR_NULL_POINTER},
        {DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_COUNT, 10, ids, 4,
         DEMILL_ERR_BUFFER_TOO_SMALL},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        demill_status st = demill_drum_fill(w, s.drum, s.mat, cases[k].dist, cases[k].p,
                                            cases[k].np, cases[k].target, cases[k].value, 1,
                                            cases[k].ids, cases[k].cap, NULL);
        ck_assert_msg(st == cases[k].want, "case %zu: status %d, expected %d (%s)", k, (int)st,
                      (int)cases[k].want, demill_world_last_error(w));
        ck_assert_msg(particle_count(w) == 0, "case %zu added particles", k);
    }
    /* and a good call still works */
    DM_OK(w, demill_drum_fill(w, s.drum, s.mat, DEMILL_SIZES_CLASSES, cls, 2, DEMILL_FILL_COUNT,
                              4, 1, ids, 4, NULL));
    ck_assert_uint_eq(particle_count(w), 4);
    demill_world_destroy(w);
}
END_TEST

/* ---- 5. collision spectrum ------------------------------------------------ */

/* Layout: with nedges edges there are C = nedges + 1 classes and
 * (C(C+1)/2 + 2C) × nbins counters: nedges 0 → C = 1, 3 rows; 2 → C = 3,
 * 6 + 6 = 12 rows; 3 → C = 4, 10 + 8 = 18 rows. Reading before any start
 * gives DEMILL_ERR_INVALID_VALUE, a buffer one counter short
 * DEMILL_ERR_BUFFER_TOO_SMALL (with the count set). */
START_TEST(spectrum_layout_and_errors)
{
    scene s = drum_scene(3, DEMILL_DAMPING_RESTITUTION);
    demill_world *w = s.w;
    uint64_t buf[256];
    size_t n = 0;
    ck_assert_int_eq(demill_drum_spectrum(w, s.drum, buf, 256, &n), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_drum_spectrum(w, s.drum, NULL, 0, &n), DEMILL_ERR_INVALID_VALUE);
    const double edges[3] = {0.005, 0.01, 0.02};
    struct {
        size_t nedges;
        uint32_t nbins;
        size_t want;
    } const cases[] = {{0, 5, 3 * 5}, {2, 8, 12 * 8}, {3, 10, 18 * 10}, {1, 1, 7}};
    for (int k = 0; k < 4; k++) {
        DM_OK(w, demill_drum_spectrum_start(w, s.drum, cases[k].nedges, edges, cases[k].nbins,
                                            1e-6, 1e-2));
        DM_OK(w, demill_drum_spectrum(w, s.drum, NULL, 0, &n));
        ck_assert_uint_eq(n, cases[k].want);
        n = 0;
        ck_assert_int_eq(demill_drum_spectrum(w, s.drum, buf, cases[k].want - 1, &n),
                         DEMILL_ERR_BUFFER_TOO_SMALL);
        ck_assert_uint_eq(n, cases[k].want);
        memset(buf, 0xff, sizeof buf);
        DM_OK(w, demill_drum_spectrum(w, s.drum, buf, cases[k].want, &n));
        for (size_t i = 0; i < n; i++)
            ck_assert(buf[i] == 0);
    }
    demill_world_destroy(w);
}
END_TEST

#define NBINS 8
#define NCOUNTERS (12 * NBINS)

static void read_spectrum(const scene *s, uint64_t out[NCOUNTERS])
{
    size_t n = 0;
    DM_OK(s->w, demill_drum_spectrum(s->w, s->drum, out, NCOUNTERS, &n));
    ck_assert_uint_eq(n, NCOUNTERS);
}

/* Every counter is 0 except the listed (index, count) pairs. */
static void expect_spectrum(const scene *s, int nexp, const int *index, const uint64_t *count)
{
    uint64_t c[NCOUNTERS];
    read_spectrum(s, c);
    for (int i = 0; i < NCOUNTERS; i++) {
        uint64_t want = 0;
        for (int k = 0; k < nexp; k++)
            if (index[k] == i)
                want = count[k];
        ck_assert_msg(c[i] == want, "counter %d (row %d, bin %d) = %llu, expected %llu", i,
                      i / NBINS, i % NBINS, (unsigned long long)c[i], (unsigned long long)want);
    }
}

/* The drum of the collision tests: diameter 2 m (R = 1), length 0.5, no
 * gravity, the linear law with restitution damping e = 0.5 for particle
 * pairs and particle-drum pairs. */
static scene collision_scene(void)
{
    scene s = drum_scene(3, DEMILL_DAMPING_RESTITUTION);
    demill_world *w = s.w;
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_pair_set(w, s.mat, s.wallmat, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_DIAMETER, 2.0));
    DM_OK(w, demill_drum_set(w, s.drum, DEMILL_DRUM_LENGTH, 0.5));
    return s;
}

/* A drum of diameter 2 m (R = 1), length 0.5, one lifter (h = w = 0.015) at
 * 6 o'clock, no gravity, linear law with restitution damping e = 0.5 and the
 * default clamp for particle pairs and particle-drum pairs (k = 5e4 N/m in
 * both). Spectrum: edges {0.008, 0.015} → classes 0 (d < 0.008), 1
 * (0.008 <= d < 0.015), 2 (d >= 0.015), C = 3; rows (0,0) 0, (0,1) 1,
 * (0,2) 2, (1,1) 3, (1,2) 4, (2,2) 5, shell 6-8, lifter 9-11; 8 bins of half
 * a decade from 1e-6 to 1e-2 J (bin b covers 10^(-6 + b/2) to
 * 10^(-5.5 + b/2)).
 *  1. Particles of d = 0.01 (m1 = 1.30899694e-3 kg, class 1) and d = 0.02
 *     (m2 = 8 m1 = 1.04719755e-2 kg, class 2) approach head-on at 1 m/s:
 *     m* = 8/9 m1 = 1.16355283e-3 kg, dissipated (1 - 0.25)·½ m* v² =
 *     4.36332e-4 J, log10 = -3.3602: row 4, bin 5 (3.16e-4 to 1e-3 J).
 *  2. A particle of d = 0.01 thrown at the shell at 1 m/s (m* = m1):
 *     0.375 m1 = 4.90874e-4 J, log10 = -3.3090: shell row of class 1 = 7,
 *     bin 5.
 *  3. A particle of d = 0.02 thrown down on the lifter's inner face (y =
 *     -0.985) at 1 m/s: 0.375 m2 = 3.92699e-3 J, log10 = -2.4059: lifter row of
 *     class 2 = 11, bin 7 (3.16e-3 to 1e-2 J).
 * The restitution of a binary collision is exact to about 1 % at the ~50
 * steps per contact used here (suite physics_collision), so the energies are
 * good to about 2 % and lie well inside their bins (the nearest edge is 24 %
 * away); the world's dissipated energy is also checked against them to 3 %.
 * Each collision is counted exactly once, and only when it ends. */
START_TEST(spectrum_counts_collisions)
{
    scene s = collision_scene();
    demill_world *w = s.w;
    DM_OK(w, demill_drum_add_lifter(w, s.drum, SIX_OCLOCK, LIFT_H, LIFT_W, 0.0));
    const double edges[2] = {0.008, 0.015};
    DM_OK(w, demill_drum_spectrum_start(w, s.drum, 2, edges, NBINS, 1e-6, 1e-2));
    expect_spectrum(&s, 0, NULL, NULL);

    const double m1 = sphere_mass(0.005), m2 = sphere_mass(0.01), ms = m1 * m2 / (m1 + m2);
    DM_ASSERT_REL(ms, 1.16355283e-3, 1e-8);
    const double e_pair = 0.375 * ms, e_shell = 0.375 * m1, e_lifter = 0.375 * m2;
    double diss = 0.0;

    /* 1. pair: gap 1 mm closes in 1 ms = 100 steps; contact ~50 steps */
    double x[6] = {-0.0055, 0, 0, 0.0105, 0, 0}, v[6] = {0.5, 0, 0, -0.5, 0, 0};
    double r[2] = {0.005, 0.01};
    demill_id pair[2];
    DM_OK(w, demill_particles_add(w, s.mat, 2, x, r, v, 0, pair));
    DM_OK(w, demill_world_step(w, 120));
    ck_assert(world_get(w, DEMILL_WORLD_CONTACT_COUNT) == 1.0); /* in contact: not yet counted */
    expect_spectrum(&s, 0, NULL, NULL);
    DM_OK(w, demill_world_step(w, 280));
    ck_assert(world_get(w, DEMILL_WORLD_CONTACT_COUNT) == 0.0);
    int idx[3] = {4 * NBINS + 5, 7 * NBINS + 5, 11 * NBINS + 7};
    uint64_t one[3] = {1, 1, 1};
    expect_spectrum(&s, 1, idx, one);
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &diss));
    DM_ASSERT_REL(diss, e_pair, 0.03);
    DM_OK(w, demill_particles_remove(w, 2, pair));

    /* 2. shell: centre at x = 1 - 0.005 - 0.001 */
    double xs[3] = {0.994, 0, 0}, vs[3] = {1, 0, 0}, rs = 0.005;
    demill_id ps;
    DM_OK(w, demill_particles_add(w, s.mat, 1, xs, &rs, vs, 0, &ps));
    DM_OK(w, demill_world_step(w, 400));
    ck_assert(world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT) == 0.0);
    expect_spectrum(&s, 2, idx, one);
    double diss2 = 0.0;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &diss2));
    DM_ASSERT_REL(diss2 - diss, e_shell, 0.03);
    DM_OK(w, demill_particles_remove(w, 1, &ps));

    /* 3. lifter: centre at y = -0.985 + 0.01 + 0.001 = -0.974 */
    double xl[3] = {0, -0.974, 0}, vl[3] = {0, -1, 0}, rl = 0.01;
    demill_id pl;
    DM_OK(w, demill_particles_add(w, s.mat, 1, xl, &rl, vl, 0, &pl));
    DM_OK(w, demill_world_step(w, 600));
    ck_assert(world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT) == 0.0);
    ck_assert(dm_test_get(w, pl, DEMILL_PARTICLE_VELOCITY, 1) > 0.0); /* it bounced */
    expect_spectrum(&s, 3, idx, one);
    double diss3 = 0.0;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &diss3));
    DM_ASSERT_REL(diss3 - diss2, e_lifter, 0.03);
    double le = NAN;
    DM_OK(w, demill_drum_lifter_get(w, s.drum, 0, DEMILL_LIFTER_ENERGY, &le));
    DM_ASSERT_REL(le, diss3 - diss2, 1e-9);
    demill_world_destroy(w);
}
END_TEST

/* Impacts on an ore. The scene of spectrum_counts_collisions (linear law,
 * restitution e = 0.5, no gravity, drum of diameter 2 m), its particles'
 * material the ore: E = 5e10 Pa, ν = 0.25, compliance (1 - ν²)/E =
 * 1.875e-11 1/Pa; the drum's E = 2e11 Pa, ν = 0.3, 4.55e-12 1/Pa (the
 * linear law does not use them). A collision dissipates
 * ΔE = ½ m* v² (1 - e²) = 0.375 m* v²; its bodies absorb shares in
 * proportion to their compliances.
 *  1. Ore particles of d = 0.01 (m1) and d = 0.02 (m2 = 8 m1) head-on at
 *     1 m/s: m* = 8/9 m1, each absorbs ½ ΔE: 0.375 · 8/9 · ½ = 0.166667 J/kg
 *     for the small one, 0.020833 J/kg for the large one.
 *  2. An ore particle of d = 0.01 thrown at the shell at 1 m/s: ΔE =
 *     0.375 m1, its share 1.875/(1.875 + 0.455) = 0.804721: 0.301770 J/kg
 *     (half of ΔE would be 0.1875 J/kg, all of it 0.375 J/kg).
 * Classes below 0.03 m, 5 of them: limits 0.03, 0.02121, 0.015, 0.01061,
 * 0.0075 m, so d = 0.02 is in class 1 and d = 0.01 in class 3. Bins of a
 * hundredth of a decade (2.3 %) from 1e-3 to 10 J/kg: each impact lands in
 * the bin of its share of the collision's dissipated energy as the world
 * reports it (DEMILL_ENERGY_DISSIPATED), which is also within 3 % of ΔE
 * above (the restitution is exact to about 1 % at ~50 steps a contact). */
static uint32_t impact_bin(double specific)
{
    return (uint32_t)floor((log10(specific) + 3.0) * 100.0);
}

START_TEST(impacts_split_and_binned)
{
    enum { C = 5, B = 400 };
    scene s = collision_scene();
    demill_world *w = s.w;
    DM_OK(w, demill_material_set(w, s.mat, DEMILL_MATERIAL_YOUNGS_MODULUS, 5e10));
    DM_OK(w, demill_material_set(w, s.mat, DEMILL_MATERIAL_POISSON_RATIO, 0.25));
    DM_OK(w, demill_material_set(w, s.wallmat, DEMILL_MATERIAL_YOUNGS_MODULUS, 2e11));
    DM_OK(w, demill_material_set(w, s.wallmat, DEMILL_MATERIAL_POISSON_RATIO, 0.3));
    uint64_t counts[C * B], np[C];
    double t = 0;
    ck_assert_int_eq(demill_drum_impacts_start(w, s.drum, s.mat, 0.03, C, B, 1e-3, 10),
                     DEMILL_ERR_INVALID_VALUE); /* no collision spectrum yet */
    ck_assert_int_eq(demill_drum_impacts(w, s.drum, counts, C * B, NULL, &t),
                     DEMILL_ERR_INVALID_VALUE);
    DM_OK(w, demill_drum_spectrum_start(w, s.drum, 0, NULL, 4, 1e-6, 1e-2));
    DM_OK(w, demill_drum_impacts_start(w, s.drum, s.mat, 0.03, C, B, 1e-3, 10));

    const double m1 = sphere_mass(0.005), m2 = sphere_mass(0.01), ms = m1 * m2 / (m1 + m2);
    const double share = 1.875e-11 / (1.875e-11 + 0.91 / 2e11);
    DM_ASSERT_REL(share, 0.804721, 1e-6);
    double x[6] = {-0.0055, 0, 0, 0.0105, 0, 0}, v[6] = {0.5, 0, 0, -0.5, 0, 0};
    double r[2] = {0.005, 0.01}, diss = 0, diss2 = 0;
    demill_id pair[2];
    DM_OK(w, demill_particles_add(w, s.mat, 2, x, r, v, 0, pair));
    DM_OK(w, demill_world_step(w, 400));
    ck_assert(world_get(w, DEMILL_WORLD_CONTACT_COUNT) == 0.0);
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &diss));
    DM_ASSERT_REL(diss, 0.375 * ms, 0.03);
    DM_OK(w, demill_drum_impacts_particles(w, s.drum, np, C, NULL));
    ck_assert(np[0] == 0 && np[1] == 1 && np[2] == 0 && np[3] == 1 && np[4] == 0);
    /* (the pair, 9 mm apart and parting, meets nothing more) */

    double xs[3] = {0.994, 0, 0}, vs[3] = {1, 0, 0}, rs = 0.005;
    demill_id ps;
    DM_OK(w, demill_particles_add(w, s.mat, 1, xs, &rs, vs, 0, &ps));
    DM_OK(w, demill_world_step(w, 400));
    ck_assert(world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT) == 0.0);
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &diss2));
    DM_ASSERT_REL(diss2 - diss, 0.375 * m1, 0.03);

    size_t n = 0;
    DM_OK(w, demill_drum_impacts(w, s.drum, counts, C * B, &n, &t));
    ck_assert_uint_eq(n, C * B);
    DM_ASSERT_REL(t, 800 * world_get(w, DEMILL_WORLD_TIME_STEP), 1e-12);
    const uint32_t small = 3 * B + impact_bin(0.5 * diss / m1);
    const uint32_t large = 1 * B + impact_bin(0.5 * diss / m2);
    const uint32_t shell = 3 * B + impact_bin(share * (diss2 - diss) / m1);
    ck_assert_uint_eq(impact_bin(0.5 * diss / m1), impact_bin(0.5 * 0.375 * ms / m1));
    ck_assert_uint_ne(shell, 3 * B + impact_bin(0.5 * (diss2 - diss) / m1));
    for (uint32_t k = 0; k < C * B; k++) {
        uint64_t want = (k == small) + (k == large) + (k == shell);
        ck_assert_msg(counts[k] == want, "class %u bin %u: %llu impacts, expected %llu", k / B,
                      k % B, (unsigned long long)counts[k], (unsigned long long)want);
    }
    DM_OK(w, demill_drum_impacts_particles(w, s.drum, np, C, NULL));
    ck_assert(np[1] == 1 && np[3] == 2 && np[0] + np[2] + np[4] == 0);

    /* The grinding rates from the drum are those of the counts read back. */
    static const double table[18] = {10, 30, 18, 4.5, 2.5, 2.0, 20, 50, 33, 9.0, 5.0, 4.0,
                                     30, 65, 46, 13.5, 7.5, 6.0};
    demill_grinding *g, *h;
    ck_assert_int_eq(demill_grinding_create(0.03, C, &g), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_create(0.03, C, &h), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_set_tavares(g, 0.2, 0.005, 1, 0.8, 0, 5, 30, 1, 3, table),
                     DEMILL_OK);
    ck_assert_int_eq(demill_grinding_set_tavares(h, 0.2, 0.005, 1, 0.8, 0, 5, 30, 1, 3, table),
                     DEMILL_OK);
    ck_assert_int_eq(demill_grinding_rates_from_drum(g, w, s.drum), DEMILL_OK);
    double edges[B + 1], dc[C * B], dn[C], sg[C], sh[C];
    for (int k = 0; k <= B; k++)
        edges[k] = pow(10.0, -3.0 + 4.0 * k / B);
    for (int k = 0; k < C * B; k++)
        dc[k] = (double)counts[k];
    for (int i = 0; i < C; i++)
        dn[i] = (double)np[i];
    ck_assert_int_eq(demill_grinding_rates_from_impacts(h, C, B, edges, dc, dn, t), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_rates(g, sg, C, NULL), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_rates(h, sh, C, NULL), DEMILL_OK);
    for (int i = 0; i < C; i++)
        DM_ASSERT_REL(sg[i], sh[i], 1e-12);
    ck_assert(sg[3] > 0 && sg[0] == 0);
    demill_grinding_destroy(h);
    /* classes that do not match the recording's */
    ck_assert_int_eq(demill_grinding_create(0.03, C + 1, &h), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_set_tavares(h, 0.2, 0.005, 1, 0.8, 0, 5, 30, 1, 3, table),
                     DEMILL_OK);
    ck_assert_int_eq(demill_grinding_rates_from_drum(h, w, s.drum), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_grinding_rates_from_drum(NULL, w, s.drum), DEMILL_ERR_NULL_POINTER);
    demill_grinding_destroy(h);
    demill_grinding_destroy(g);
    /* restarting the collision spectrum ends the impacts' recording */
    DM_OK(w, demill_drum_spectrum_start(w, s.drum, 0, NULL, 4, 1e-6, 1e-2));
    ck_assert_int_eq(demill_drum_impacts(w, s.drum, NULL, 0, &n, NULL), DEMILL_ERR_INVALID_VALUE);
    demill_world_destroy(w);
}
END_TEST

/* ---- 6. lifter loads ------------------------------------------------------ */

/* A particle pressed with δ = 1e-4 against the trailing face of the lifter at
 * 6 o'clock (centre (-0.0124, -0.142), no gravity, drum at rest): the contact
 * force on the particle is -k δ n = -5e4·1e-4·(1, 0, 0) = (-5, 0, 0) N, the
 * lifter feels (5, 0, 0) N, equal and opposite, which is also minus the
 * particle's total force. The contact point is (-0.00745, -0.142), so the
 * drum torque is x F_y - y F_x = 0.142·5 = 0.71 N m, and the power at rest
 * is 0. Same in 2D. Force tolerance: δ is exact to ~1e-17 m, i.e. 1e-13
 * relative, checked to 1e-10 × 5 N. */
START_TEST(lifter_force_pressed_particle)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        demill_world *w = s.w;
        double c[3] = {-0.0124, -0.142, 0}, r = RP;
        demill_id p;
        DM_OK(w, demill_particles_add(w, s.mat, 1, c, &r, NULL, 0, &p));
        DM_OK(w, demill_world_step(w, 0));
        double fn[3 * MAXC], lf[3], pf[3];
        size_t n = 0;
        DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, fn, MAXC, &n));
        ck_assert_uint_eq(n, 1);
        DM_OK(w, demill_drum_lifter_get(w, s.drum, 0, DEMILL_LIFTER_FORCE, lf));
        DM_OK(w, demill_particle_get(w, p, DEMILL_PARTICLE_FORCE, pf));
        const double want[3] = {KN * DELTA, 0, 0};
        for (int q = 0; q < 3; q++) {
            NEAR(lf[q], want[q], 1e-10 * 5);
            NEAR(fn[q], -want[q], 1e-10 * 5);
            NEAR(lf[q], -fn[q], 1e-12 * 5);
            NEAR(pf[q], -lf[q], 1e-12 * 5);
        }
        DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_TORQUE), 0.71, 1e-10);
        ck_assert(drum_get(w, s.drum, DEMILL_DRUM_POWER) == 0.0);
        demill_world_destroy(w);
    }
}
END_TEST

/* A particle resting on the lifter's inner face at 6 o'clock under gravity
 * g = 9.81: weight W = m g = 1.30899694e-3·9.81 = 1.28412600e-2 N, at
 * equilibrium overlap δ = W/k = 2.56825e-7 m, centre (0.003, -0.135 + r - δ).
 * The lifter carries (0, -W, 0), equal and opposite to the contact force on
 * the particle (0, +W, 0); the particle's total force is 0; the drum torque
 * is x_cp F_y = 0.003·(-W) = -3.85238e-5 N m. After 200 steps at rest the
 * load is unchanged and its peak is W. δ is recovered from positions of
 * order 0.13 m to ~1e-17 m, i.e. 1e-10 relative: tolerance 1e-8 relative. */
START_TEST(lifter_force_resting_particle)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        demill_world *w = s.w;
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
        const double m = sphere_mass(RP), W = m * 9.81, d = W / KN;
        DM_ASSERT_REL(W, 1.28412600e-2, 1e-8);
        double c[3] = {0.003, -(DRUM_R - LIFT_H) + RP - d, 0}, r = RP;
        demill_id p;
        DM_OK(w, demill_particles_add(w, s.mat, 1, c, &r, NULL, 0, &p));
        for (int round = 0; round < 2; round++) {
            DM_OK(w, demill_world_step(w, round ? 200 : 0));
            double fn[3 * MAXC], lf[3], pf[3];
            size_t n = 0;
            DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, fn, MAXC, &n));
            ck_assert_uint_eq(n, 1);
            DM_OK(w, demill_drum_lifter_get(w, s.drum, 0, DEMILL_LIFTER_FORCE, lf));
            DM_OK(w, demill_particle_get(w, p, DEMILL_PARTICLE_FORCE, pf));
            NEAR(lf[0], 0.0, 1e-8 * W);
            DM_ASSERT_REL(lf[1], -W, 1e-8);
            NEAR(lf[2], 0.0, 0.0);
            for (int q = 0; q < 3; q++) {
                NEAR(fn[q], -lf[q], 1e-12 * W);
                NEAR(pf[q], 0.0, 1e-8 * W);
            }
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_TORQUE), -0.003 * W, 1e-8);
            DM_ASSERT_REL(drum_get(w, s.drum, DEMILL_DRUM_FORCE_Y), -W, 1e-8);
        }
        double peak = NAN;
        DM_OK(w, demill_drum_lifter_get(w, s.drum, 0, DEMILL_LIFTER_FORCE_PEAK, &peak));
        DM_ASSERT_REL(peak, W, 1e-8);
        demill_world_destroy(w);
    }
}
END_TEST

/* Parts of the drum with materials of their own. The lifters (and in 3D
 * the end caps) get a second material whose pair with the particles has the
 * linear stiffness 2 KN, the shell keeps KN. Particles pressed by DELTA onto
 * the lifter's leading face (as in lifter_force_pressed_particle), onto the
 * shell at 12 o'clock and onto the +z cap at the axis feel 2 KN DELTA, KN
 * DELTA and 2 KN DELTA, each along the wall's inward normal: the force on
 * the drum is (2 KN DELTA, KN DELTA, 2 KN DELTA) in 3D (z = 0 in 2D), the
 * sum of the three by Newton's third law. */
START_TEST(part_materials)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = lifter_scene(dim, 0.0);
        demill_world *w = s.w;
        demill_id hard, got;
        DM_OK(w, demill_material_create(w, &hard));
        DM_OK(w, demill_pair_set(w, s.mat, hard, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        DM_OK(w, demill_pair_set(w, s.mat, hard, DEMILL_PAIR_NORMAL_STIFFNESS, 2 * KN));
        DM_OK(w, demill_pair_set(w, hard, hard, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        for (int32_t part = DEMILL_DRUM_PART_SHELL; part <= DEMILL_DRUM_PART_LIFTERS; part++) {
            if (dim == 2 && part == DEMILL_DRUM_PART_CAPS) {
                ck_assert_int_eq(demill_drum_set_material(w, s.drum, part, hard),
                                 DEMILL_ERR_DIMENSION);
                ck_assert_int_eq(demill_drum_get_material(w, s.drum, part, &got),
                                 DEMILL_ERR_DIMENSION);
                continue;
            }
            DM_OK(w, demill_drum_get_material(w, s.drum, part, &got));
            ck_assert(got == s.wallmat);
            if (part != DEMILL_DRUM_PART_SHELL)
                DM_OK(w, demill_drum_set_material(w, s.drum, part, hard));
        }
        ck_assert_int_eq(demill_drum_set_material(w, s.drum, 0, hard), DEMILL_ERR_UNKNOWN_KEY);
        ck_assert_int_eq(demill_drum_set_material(w, s.drum, 4, hard), DEMILL_ERR_UNKNOWN_KEY);
        ck_assert_int_eq(demill_drum_set_material(w, s.drum, 1, s.drum),
                         DEMILL_ERR_INVALID_HANDLE);
        ck_assert_int_eq(demill_drum_get_material(w, s.drum, 1, NULL), DEMILL_ERR_NULL_POINTER);
        DM_OK(w, demill_drum_get_material(w, s.drum, DEMILL_DRUM_PART_LIFTERS, &got));
        ck_assert(got == hard);

        const double half = 0.5 * DRUM_L;
        double c[9] = {-0.0124, -0.142, 0, 0, DRUM_R - RP + DELTA, 0, 0, 0, half - RP + DELTA};
        double r[3] = {RP, RP, RP};
        DM_OK(w, demill_particles_add(w, s.mat, dim == 3 ? 3 : 2, c, r, NULL, 0, NULL));
        DM_OK(w, demill_world_step(w, 0));
        double lf[3];
        DM_OK(w, demill_drum_lifter_get(w, s.drum, 0, DEMILL_LIFTER_FORCE, lf));
        DM_ASSERT_REL(lf[0], 2 * KN * DELTA, 1e-10);
        const double want[3] = {2 * KN * DELTA, KN * DELTA, dim == 3 ? 2 * KN * DELTA : 0.0};
        for (int q = 0; q < 3; q++)
            NEAR(drum_get(w, s.drum, DEMILL_DRUM_FORCE_X + q), want[q], 1e-10 * KN * DELTA);
        demill_world_destroy(w);
    }
}
END_TEST

/* The charge angles of a charge of balls and fines, at rest (the angles are
 * read from positions). One ball of d = 10 mm at radius 0.14 m in the middle
 * of each 5° bin from φ = -40° to 120° (32 bins), in the default drum (R =
 * 0.15, no lifters: the ring is 0.13 < r < 0.15), and 20 fines of d = 1 mm in
 * each of the 6 bins from 0° to 30°. The balls fill the ring from -40° to
 * 120°, which is the charge: toe -40°, shoulder 120°. Counted by number the
 * six bins of fines (21 each) would set the threshold at 10.5 and the charge
 * would be 0° to 30°; by volume each of them holds 1.02 balls. */
START_TEST(charge_angles_weigh_by_volume)
{
    for (int dim = 2; dim <= 3; dim++) {
        scene s = drum_scene(dim, DEMILL_DAMPING_NONE);
        demill_world *w = s.w;
        const double deg = M_PI / 180.0;
        double x[3 * (32 + 120)] = {0}, r[32 + 120];
        int n = 0;
        for (int k = 0; k < 32; k++, n++) {
            const double phi = (-37.5 + 5.0 * k) * deg;
            x[3 * n] = 0.14 * sin(phi);
            x[3 * n + 1] = -0.14 * cos(phi);
            r[n] = 0.005;
        }
        for (int b = 0; b < 6; b++)
            for (int k = 0; k < 20; k++, n++) { /* 5 angles x 4 radii, 2 mm apart */
                const double phi = (5.0 * b + 0.5 + 1.0 * (k % 5)) * deg, rho = 0.132 + 0.002 * (k / 5);
                x[3 * n] = rho * sin(phi);
                x[3 * n + 1] = -rho * cos(phi);
                r[n] = 0.0005;
            }
        DM_OK(w, demill_particles_add(w, s.mat, (size_t)n, x, r, NULL, 0, NULL));
        NEAR(drum_get(w, s.drum, DEMILL_DRUM_TOE_ANGLE), -40.0 * deg, 1e-12);
        NEAR(drum_get(w, s.drum, DEMILL_DRUM_SHOULDER_ANGLE), 120.0 * deg, 1e-12);
        demill_world_destroy(w);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("drum");
    TCase *geo = tcase_create("geometry");
    tcase_add_test(geo, geometry_shell_and_caps);
    tcase_add_test(geo, geometry_rectangular_lifter);
    tcase_add_test(geo, geometry_inclined_lifter);
    tcase_add_test(geo, geometry_turned_drum);
    tcase_add_test(geo, charge_angles_weigh_by_volume);
    suite_add_tcase(s, geo);
    TCase *speed = tcase_create("speed");
    tcase_add_test(speed, speed_views);
    tcase_add_test(speed, speed_ramp_angle_is_exact_integral);
    tcase_add_test(speed, revolutions_count_completed_turns);
    tcase_add_test(speed, speed_change_takes_effect_at_once);
    tcase_add_test(speed, fraction_follows_the_charge);
    tcase_add_test(speed, empty_drum_draws_no_power);
    suite_add_tcase(s, speed);
    TCase *fill = tcase_create("fill");
    tcase_add_test(fill, fill_count_is_exact);
    tcase_add_test(fill, fill_mass_classes);
    tcase_add_test(fill, fill_rosin_rammler);
    tcase_add_test(fill, fill_normal);
    tcase_add_test(fill, fill_fraction);
    tcase_add_test(fill, fill_is_reproducible_from_seed);
    tcase_add_test(fill, fill_second_material_avoids_first);
    tcase_add_test(fill, fill_that_does_not_fit_adds_nothing);
    tcase_add_test(fill, fill_bad_arguments);
    suite_add_tcase(s, fill);
    TCase *spec = tcase_create("spectrum");
    tcase_add_test(spec, spectrum_layout_and_errors);
    tcase_add_test(spec, spectrum_counts_collisions);
    tcase_add_test(spec, impacts_split_and_binned);
    suite_add_tcase(s, spec);
    TCase *lift = tcase_create("lifter");
    tcase_add_test(lift, lifter_force_pressed_particle);
    tcase_add_test(lift, lifter_force_resting_particle);
    tcase_add_test(lift, part_materials);

    suite_add_tcase(s, lift);
    return dm_test_run(s);
}
