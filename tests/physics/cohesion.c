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
#include <stdio.h>
#include <stdlib.h>

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

/* ---- impacts ------------------------------------------------------------ */

/* A sphere of radius R (E = 1e8, ν = 0.3, ρ = 2500) hits a second one, or a
 * rigid plane, or a rigid mesh where two elements meet (3D: two triangles,
 * over their shared edge; 2D: two segments, over their shared point, so
 * that the elements that do not hold the contact must not pull too), head-on
 * at v0 without damping; cohesion forms at contact and pulls until it
 * breaks. Independent numbers:
 *  - at every sample, the force is the law's of the overlap sampled: JKR's
 *    F(a) with a(δ) found by bisection of the parametric δ(a) (not the
 *    library's closed form), or Hertz's 4/3 E* √R* δ^{3/2} plus Willett's
 *    capillary force; 0 before contact and after the break (δ <= δ_c, or the
 *    gap beyond (1 + θ/2) V^{1/3});
 *  - the energy the bond takes, W: JKR, −∫ F dδ over δ_c..0 on the way out
 *    (on the way in and for δ > 0 the branch is the same), by the
 *    parametric integral ∫ F(a) δ'(a) da = [8E* a⁵/(15R*²) − 4/(3R*)
 *    √(2π w E*) a^{7/2} + π w a²] from a_c to a(0); the bridge,
 *    ∫ F(s) ds over 0..s_c (its force in contact is constant, so that the
 *    compression gives back what it took), = F_0 (2/(k√35.59)) [atan((20 k
 *    s_c + 2.1)/√35.59) − atan(2.1/√35.59)] with k = (1/2)√(2R* / V);
 *    so the rebound speed is e v0, e = √(1 − 2W/(m* v0²));
 *  - the energy account: the work against cohesion (DEMILL_ENERGY_COHESION)
 *    is W once the bond has broken, and the balance DEMILL_ENERGY_TOTAL
 *    stays where it was. */
static const double R = 1e-3, RHO = 2500, E = 1e8, NU = 0.3;
/* How far beside a mesh's outer edge the sphere's centre passes: its normal
 * is then 17° off the x axis at contact. */
#define EDGE_OFFSET (0.3 * R)

typedef struct impact {
    /* wall: 0 none, 1 a plane, 2 a mesh (where two elements meet), 3 a mesh
     * (beside its outer edge); law: DEMILL_COHESION_* */
    int dim, wall, law;
    double youngs;       /* the spheres' E */
    int integrator;      /* DEMILL_INTEGRATOR_*, 0: the default */
    double rstar, mstar, estar, v0, dt;
    double w;                            /* JKR */
    double gamma, theta, volume;         /* the bridge */
} impact;

/* JKR: δ(a) and F(a). */
static double jkr_d(const impact *c, double a)
{
    return a * a / c->rstar - sqrt(2 * M_PI * c->w * a / c->estar);
}

static double jkr_f(const impact *c, double a)
{
    return 4 * c->estar * a * a * a / (3 * c->rstar) - sqrt(8 * M_PI * c->w * c->estar * a * a * a);
}

static double jkr_ac(const impact *c)
{
    return pow(c->rstar / 4 * sqrt(2 * M_PI * c->w / c->estar), 2.0 / 3.0);
}

/* a(δ) on the stable branch, by bisection on [a_c, ...]. */
static double jkr_a(const impact *c, double delta)
{
    double lo = jkr_ac(c), hi = lo;
    while (jkr_d(c, hi) < delta)
        hi *= 2;
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi);
        if (jkr_d(c, mid) < delta)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

static double jkr_work_integral(const impact *c, double a)
{
    return 8 * c->estar * pow(a, 5) / (15 * c->rstar * c->rstar) -
           4 / (3 * c->rstar) * sqrt(2 * M_PI * c->w * c->estar) * pow(a, 3.5) +
           M_PI * c->w * a * a;
}

/* The reach of the bond (as a gap), the force at overlap delta of a bond
 * that exists, and the energy W the bond takes. */
static double bond_reach(const impact *c)
{
    if (c->law == DEMILL_COHESION_JKR)
        return -jkr_d(c, jkr_ac(c));
    return (1 + c->theta / 2) * cbrt(c->volume);
}

static double bond_force(const impact *c, double delta)
{
    if (c->law == DEMILL_COHESION_JKR)
        return jkr_f(c, jkr_a(c, delta));
    const double hertz = delta > 0 ? 4.0 / 3.0 * c->estar * sqrt(c->rstar) * pow(delta, 1.5) : 0;
    const double rw = 2 * c->rstar, f0 = 2 * M_PI * rw * c->gamma * cos(c->theta);
    const double sn = delta < 0 ? -delta / 2 * sqrt(rw / c->volume) : 0;
    return hertz - f0 / (1 + 2.1 * sn + 10.0 * sn * sn);
}

static double bond_work(const impact *c)
{
    if (c->law == DEMILL_COHESION_JKR)
        return jkr_work_integral(c, jkr_ac(c)) - jkr_work_integral(c, jkr_a(c, 0.0));
    const double rw = 2 * c->rstar, f0 = 2 * M_PI * rw * c->gamma * cos(c->theta);
    const double k = 0.5 * sqrt(rw / c->volume), q = sqrt(40 - 2.1 * 2.1);
    return f0 * 2 / (k * q) * (atan((20 * k * bond_reach(c) + 2.1) / q) - atan(2.1 / q));
}

/* The world of an impact: the sphere's material with itself (particle-
 * particle) or with a rigid plane's (particle-wall): Hertz, no damping, the
 * cohesion law; the spheres placed 3.5 steps of v0 apart. ids: the moving
 * sphere last. */
static demill_world *impact_world(impact *c, demill_id *ids, int *n)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(c->dim, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, c->dt));
    if (c->integrator)
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, c->integrator));
    demill_id ball, plate;
    DM_OK(w, demill_material_create(w, &ball));
    DM_OK(w, demill_material_create(w, &plate));
    DM_OK(w, demill_material_set(w, ball, DEMILL_MATERIAL_DENSITY, RHO));
    DM_OK(w, demill_material_set(w, ball, DEMILL_MATERIAL_YOUNGS_MODULUS, c->youngs));
    DM_OK(w, demill_material_set(w, ball, DEMILL_MATERIAL_POISSON_RATIO, NU));
    DM_OK(w, demill_material_set(w, plate, DEMILL_MATERIAL_RIGID, 1));
    const demill_id other = c->wall ? plate : ball;
    DM_OK(w, demill_pair_set(w, ball, ball, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_COHESION, c->law));
    if (c->law == DEMILL_COHESION_JKR) {
        DM_OK(w, demill_material_set(w, ball, DEMILL_MATERIAL_SURFACE_ENERGY, c->w / 2));
        double wab;
        DM_OK(w, demill_pair_get(w, ball, ball, DEMILL_PAIR_ADHESION_WORK, &wab));
        ck_assert_double_eq_tol(wab, c->w, 1e-15 * c->w); /* 2γ for one material */
        DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_ADHESION_WORK, c->w));
    } else {
        DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_SURFACE_TENSION, c->gamma));
        DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_CONTACT_ANGLE, c->theta));
        DM_OK(w, demill_pair_set(w, ball, other, DEMILL_PAIR_LIQUID_VOLUME, c->volume));
    }
    const double m = 4.0 / 3.0 * M_PI * R * R * R * RHO, gap = 3.5 * c->v0 * c->dt;
    if (c->wall) {
        c->rstar = R, c->mstar = m;
        const double origin[3] = {0, 0, 0}, normal[3] = {1, 0, 0};
        demill_id wall;
        if (c->wall == 1) {
            DM_OK(w, demill_wall_add_plane(w, plate, origin, normal, &wall));
        } else if (c->dim == 3) { /* two triangles in x = 0, meeting along y = z */
            const double v[12] = {0, -0.01, -0.01, 0, 0.01, -0.01, 0, 0.01, 0.01, 0, -0.01, 0.01};
            const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
            DM_OK(w, demill_wall_add_mesh(w, plate, 4, v, 2, t, &wall));
        } else { /* two segments along x = 0, meeting at y = 0.002 */
            const double p[9] = {0, -0.01, 0, 0, 0.002, 0, 0, 0.01, 0};
            DM_OK(w, demill_wall_add_polyline(w, plate, 3, p, 0, &wall));
        }
        /* over the mesh's shared edge, the polyline's shared point; or
         * beside the edge of a mesh that ends at y = 0 (its outer edge, its
         * last point in 2D) */
        if (c->wall == 3) {
            DM_OK(w, demill_wall_remove(w, wall));
            if (c->dim == 3) {
                const double v[12] = {0, -0.01, -0.01, 0, 0, -0.01, 0, 0, 0.01, 0, -0.01, 0.01};
                const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
                DM_OK(w, demill_wall_add_mesh(w, plate, 4, v, 2, t, &wall));
            } else {
                const double p[6] = {0, -0.01, 0, 0, 0, 0};
                DM_OK(w, demill_wall_add_polyline(w, plate, 2, p, 0, &wall));
            }
        }
        const double y = c->wall == 3 ? EDGE_OFFSET : 0.002;
        double x[3] = {(c->wall == 3 ? sqrt(R * R - y * y) : R) + gap, y, c->dim == 3 ? 0.002 : 0},
               v[3] = {-c->v0, 0, 0};
        DM_OK(w, demill_particles_add(w, ball, 1, x, (double[]){R}, v, 0, ids));
        *n = 1;
    } else {
        c->rstar = R / 2, c->mstar = m / 2;
        double x[6] = {-R - gap / 2, 0, 0, R + gap / 2, 0, 0};
        double v[6] = {c->v0 / 2, 0, 0, -c->v0 / 2, 0, 0}, r[2] = {R, R};
        DM_OK(w, demill_particles_add(w, ball, 2, x, r, v, 0, ids));
        *n = 2;
    }
    return w;
}

/* The overlap and the force on the right-hand sphere along the normal
 * (+x, or from the mesh's edge to the centre). */
static void sample(const impact *c, demill_world *w, const demill_id *ids, int n, double *delta,
                   double *f)
{
    const double xr = dm_test_get(w, ids[n - 1], DEMILL_PARTICLE_POSITION, 0);
    *delta = c->wall ? R - xr : 2 * R - (xr - dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 0));
    *f = dm_test_get(w, ids[n - 1], DEMILL_PARTICLE_FORCE, 0);
    if (c->wall == 3) {
        const double y = dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 1), d = hypot(xr, y);
        *delta = R - d;
        *f = (*f * xr + dm_test_get(w, ids[0], DEMILL_PARTICLE_FORCE, 1) * y) / d;
    }
}

typedef struct impact_result {
    double e, fmin, work, total0, total1;
    int steps;
} impact_result;

/* Runs an impact until the bond has broken and the spheres are 10 steps
 * apart, checking every sample's force; returns what it measured. */
static impact_result impact_run(impact *c)
{
    demill_id ids[2];
    int n;
    demill_world *w = impact_world(c, ids, &n);
    impact_result o = {0, 0, 0, 0, 0, 0};
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &o.total0));
    const double reach = bond_reach(c), fscale = fabs(bond_force(c, 0.0));
    int bond = 0, after = 0;
    for (o.steps = 1; o.steps < 200000 && after < 10; o.steps++) {
        DM_OK(w, demill_world_step(w, 1));
        double delta, f;
        sample(c, w, ids, n, &delta, &f);
        bond = delta > 0 || (bond && delta > -reach);
        const double want = bond ? bond_force(c, delta) : 0.0;
        ck_assert_msg(fabs(f - want) <= 1e-9 * fscale,
                      "step %d, overlap %.9g m (reach %.9g m): force %.12g N, expected %.12g N",
                      o.steps, delta, reach, f, want);
        o.fmin = fmin(o.fmin, f);
        after = !bond && delta < 0 && f == 0.0 ? after + 1 : 0;
    }
    ck_assert_int_eq(after, 10);
    const double vr = dm_test_get(w, ids[n - 1], DEMILL_PARTICLE_VELOCITY, 0);
    const double vl = c->wall ? 0.0 : dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0);
    o.e = c->wall == 3 ? hypot(vr, dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 1)) / c->v0
                       : (vr - vl) / c->v0;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_COHESION, &o.work));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &o.total1));
    demill_world_destroy(w);
    return o;
}

/* The duration of a Hertz impact at v0 (Johnson 1985, Contact Mechanics
 * §11.4), which the time step resolves. */
static double hertz_time(const impact *c)
{
    return 2.868 * pow(c->mstar * c->mstar / (c->rstar * c->estar * c->estar * c->v0), 0.2);
}

/* JKR: spheres of 1 mm of modulus E with work of adhesion w, at an
 * approach speed whose kinetic energy m* v0²/2 is twice what the bond takes
 * (e = 1/√2). */
static impact jkr_case(int dim, int wall, double youngs, double w)
{
    impact c = {.dim = dim, .wall = wall, .law = DEMILL_COHESION_JKR, .youngs = youngs, .w = w};
    c.rstar = wall ? R : R / 2;
    c.mstar = 4.0 / 3.0 * M_PI * R * R * R * RHO / (wall ? 1 : 2);
    c.estar = youngs / (2 * (1 - NU * NU)) * (wall ? 2 : 1);
    c.v0 = sqrt(4 * bond_work(&c) / c.mstar);
    /* 200 steps across the neck's reach at v0, and across a Hertz impact */
    c.dt = fmin(bond_reach(&c) / c.v0, hertz_time(&c)) / 200;
    return c;
}

START_TEST(jkr_impact)
{
    impact c = jkr_case(2 + _i / 4, _i % 4, E, 0.1); /* glass-like */
    const impact_result o = impact_run(&c);
    DM_ASSERT_REL(o.fmin, -dm_jkr_pull_off(c.rstar, c.w), 0.01);
    DM_ASSERT_REL(o.e, sqrt(0.5), 0.005);
    DM_ASSERT_REL(o.work, bond_work(&c), 0.01);
    ck_assert_msg(fabs(o.total1 - o.total0) <= 1e-3 * bond_work(&c),
                  "the balance moved by %g J (the bond took %g J)", o.total1 - o.total0,
                  bond_work(&c));
}
END_TEST

/* The bridge: water (γ = 0.072 N/m) at θ = 0.3 rad, V = 1e-12 m³ (reach
 * (1 + θ/2) V^{1/3} = 115 µm); m* v0²/2 twice what it takes. */
static impact capillary_case(int dim, int wall)
{
    impact c = {.dim = dim, .wall = wall, .law = DEMILL_COHESION_CAPILLARY, .youngs = E,
                .gamma = 0.072, .theta = 0.3, .volume = 1e-12};
    c.rstar = wall ? R : R / 2;
    c.mstar = 4.0 / 3.0 * M_PI * R * R * R * RHO / (wall ? 1 : 2);
    c.estar = E / (2 * (1 - NU * NU)) * (wall ? 2 : 1);
    c.v0 = sqrt(4 * bond_work(&c) / c.mstar);
    c.dt = fmin(bond_reach(&c) / c.v0, hertz_time(&c)) / 200;
    return c;
}

START_TEST(capillary_impact)
{
    impact c = capillary_case(2 + _i / 4, _i % 4);
    const impact_result o = impact_run(&c);
    DM_ASSERT_REL(o.e, sqrt(0.5), 0.005);
    DM_ASSERT_REL(o.work, bond_work(&c), 0.01);
    ck_assert_msg(fabs(o.total1 - o.total0) <= 1e-3 * bond_work(&c),
                  "the balance moved by %g J (the bond took %g J)", o.total1 - o.total0,
                  bond_work(&c));
}
END_TEST

/* The same impacts (3D, two spheres and on the plane) with the iterative
 * refinement, whose iterates restore the contacts' `on` flags with their
 * histories, and symplectic Euler: the same forces, rebound and energy
 * (Euler's balance, first order, to 5e-3 of the bond's energy: measured
 * 3.1e-3 for JKR and 2.3e-3 for the bridge at 200 steps across the reach;
 * the refinement's to 1e-3 as Verlet's). */
START_TEST(impacts_other_integrators)
{
    static const int integrators[] = {DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT,
                                      DEMILL_INTEGRATOR_SYMPLECTIC_EULER};
    for (int k = 0; k < 2; k++)
        for (int wall = 0; wall < 2; wall++) {
            impact c = _i ? capillary_case(3, wall) : jkr_case(3, wall, E, 0.1);
            c.integrator = integrators[k];
            const impact_result o = impact_run(&c);
            DM_ASSERT_REL(o.e, sqrt(0.5), 0.005);
            DM_ASSERT_REL(o.work, bond_work(&c), 0.01);
            const double tol = c.integrator == DEMILL_INTEGRATOR_SYMPLECTIC_EULER ? 5e-3 : 1e-3;
            ck_assert_msg(fabs(o.total1 - o.total0) <= tol * bond_work(&c),
                          "integrator %d: the balance moved by %g J (the bond took %g J)",
                          c.integrator, o.total1 - o.total0, bond_work(&c));
        }
}
END_TEST

/* Whether a bond exists is the contact's `on` flag, carried over neighbour
 * rebuilds and kept by checkpoints and snapshots: an impact whose lists are
 * rebuilt before every step (setting the skin asks for it) with a skin of
 * 1 % of the radius, 10 µm, less than the bond's reach (so that the
 * neighbour search must reach further for it), runs bit for bit as one whose
 * lists are never rebuilt (skin 10 radii); and a checkpoint and a snapshot
 * taken while the spheres are apart but bonded run on as the original does,
 * bit for bit (through the break). The JKR spheres are soft and sticky
 * (E = 1e6 Pa, w = 1 J/m²: reach 19 µm between two, 15 µm on the plane);
 * the bridge's reach is 115 µm. */
static double *impact_trace(impact *c, int rebuild, uint64_t *rebuilds, int copies)
{
    demill_id ids[2];
    int n;
    demill_world *w = impact_world(c, ids, &n);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_SKIN, rebuild ? 0.01 : 10.0));
    const double reach = bond_reach(c);
    const int steps = (int)(4 * reach / (c->v0 * c->dt)) + 2 * (int)(hertz_time(c) / c->dt);
    double *trace = malloc(4 * (size_t)steps * sizeof *trace);
    ck_assert_ptr_nonnull(trace);
    int bonded_apart = 0;
    for (int k = 0; k < steps; k++) {
        if (rebuild)
            DM_OK(w, demill_world_set(w, DEMILL_WORLD_SKIN, 0.01));
        DM_OK(w, demill_world_step(w, 1));
        double delta, f;
        sample(c, w, ids, n, &delta, &f);
        trace[4 * k] = dm_test_get(w, ids[n - 1], DEMILL_PARTICLE_POSITION, 0);
        trace[4 * k + 1] = dm_test_get(w, ids[n - 1], DEMILL_PARTICLE_VELOCITY, 0);
        trace[4 * k + 2] = f;
        trace[4 * k + 3] = delta;
        if (copies && !bonded_apart && delta < -0.5 * reach && f < 0.0) {
            bonded_apart = 1;
            dm_test_copies_run_on(w, (uint64_t)(reach / (c->v0 * c->dt)), NULL, NULL);
        }
    }
    ck_assert(!copies || bonded_apart);
    double nb;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS, &nb));
    *rebuilds = (uint64_t)nb;
    demill_world_destroy(w);
    return trace;
}

START_TEST(bond_survives_rebuilds_and_copies)
{
    impact c = _i / 2 ? capillary_case(3, _i % 2) : jkr_case(3, _i % 2, 1e6, 1.0);
    ck_assert(bond_reach(&c) > 0.01 * R);
    uint64_t often, never;
    double *a = impact_trace(&c, 1, &often, 0);
    double *b = impact_trace(&c, 0, &never, 0);
    const int steps = (int)(4 * bond_reach(&c) / (c.v0 * c.dt)) + 2 * (int)(hertz_time(&c) / c.dt);
    ck_assert_msg(often >= (uint64_t)steps && never == 1, "rebuilds: %llu and %llu",
                  (unsigned long long)often,
                  (unsigned long long)never);
    for (int k = 0; k < 4 * steps; k++)
        ck_assert_msg(a[k] == b[k], "step %d, value %d: %.17g with rebuilds, %.17g without",
                      k / 4, k % 4, a[k], b[k]);
    int apart_bonded = 0;
    for (int k = 0; k < steps; k++)
        apart_bonded |= a[4 * k + 3] < -0.5 * bond_reach(&c) && a[4 * k + 2] < 0.0;
    ck_assert_msg(apart_bonded, "the bond never held across a gap");
    free(impact_trace(&c, 0, &never, 1));
    free(a);
    free(b);
}
END_TEST

/* A bridge's volume raised eightfold while it holds a sphere across a gap
 * to a mesh (3D, over the shared edge): its reach doubles, the lists are
 * built again at the next step (the mesh resolves its elements as far as
 * the reach), and the bridge holds, with the force of the new volume, to
 * its new rupture distance, beyond the old one. */
START_TEST(longer_reach_mid_bond)
{
    impact c = capillary_case(3, 2);
    demill_id ids[1];
    int n, raised = 0, beyond = 0;
    demill_world *w = impact_world(&c, ids, &n);
    int bond = 0;
    for (int k = 0; k < 100000; k++) {
        double nb0, nb1, delta, f;
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS, &nb0));
        DM_OK(w, demill_world_step(w, 1));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS, &nb1));
        if (raised == 1) {
            ck_assert_msg(nb1 == nb0 + 1, "no rebuild after the reach grew");
            raised = 2;
        }
        sample(&c, w, ids, n, &delta, &f);
        const double reach = bond_reach(&c);
        bond = delta > 0 || (bond && delta > -reach);
        const double want = bond ? bond_force(&c, delta) : 0.0;
        ck_assert_msg(fabs(f - want) <= 1e-9 * fabs(bond_force(&c, 0.0)),
                      "step %d, overlap %.9g m: force %.12g N, expected %.12g N", k, delta, f,
                      want);
        beyond |= raised && bond && delta < -0.6 * reach; /* beyond the old reach */
        if (!raised && bond && delta < -0.5 * reach) {
            demill_id mats[2]; /* the ball's and the plate's, in order of creation */
            size_t nm;
            DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, mats, 2, &nm));
            c.volume *= 8;
            DM_OK(w, demill_pair_set(w, mats[0], mats[1], DEMILL_PAIR_LIQUID_VOLUME, c.volume));
            raised = 1;
        }
        if (!bond && delta < -reach)
            break;
    }
    ck_assert(raised == 2 && beyond);
    demill_world_destroy(w);
}
END_TEST

/* A pile of 27 spheres (3D; 9 discs' worth of spheres in 2D) dropped on a
 * plane with every law on: Hertz, restitution damping (e = 0.5), Mindlin
 * friction (μ = 0.5), constant-torque rolling resistance (μ_r = 0.05) and
 * cohesion, for 0.1 s: the balance DEMILL_ENERGY_TOTAL stays within 1e-3 of
 * the energy that went through (every dissipation term and the work
 * against cohesion, in magnitude), and every term is finite. */
START_TEST(pile_balance)
{
    const int dim = 2 + _i / 2, law = _i % 2 ? DEMILL_COHESION_CAPILLARY : DEMILL_COHESION_JKR;
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    demill_id m;
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, RHO));
    DM_OK(w, demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, E));
    DM_OK(w, demill_material_set(w, m, DEMILL_MATERIAL_SURFACE_ENERGY, 0.05));
    const int laws[][2] = {{DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ},
                           {DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION},
                           {DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN},
                           {DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE},
                           {DEMILL_PAIR_COHESION, law}};
    for (int k = 0; k < 5; k++)
        DM_OK(w, demill_pair_set(w, m, m, laws[k][0], laws[k][1]));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, 0.05));
    const double origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    demill_id floor;
    DM_OK(w, demill_wall_add_plane(w, m, origin, up, &floor));
    double x[81], r[27];
    int n = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < (dim == 3 ? 3 : 1); k++, n++) {
                x[3 * n] = 2.1 * R * i + 0.1 * R * j;
                x[3 * n + 1] = R * (1.5 + 2.2 * j);
                x[3 * n + 2] = dim == 3 ? 2.1 * R * k - 0.1 * R * i : 0.0;
                r[n] = R;
            }
    DM_OK(w, demill_particles_add(w, m, (size_t)n, x, r, NULL, 0, NULL));
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, 0, 0, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    double total0, total1, dissipated, cohesion;
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &total0));
    double through = 0.0;
    for (double t = 0; t < 0.1; t += 1000 * dt) {
        double before;
        DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_COHESION, &before));
        DM_OK(w, demill_world_step(w, 1000));
        DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_COHESION, &cohesion));
        through += fabs(cohesion - before);
    }
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &total1));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &dissipated));
    through += dissipated;
    ck_assert(isfinite(total1) && dissipated > 0.0 && through > dissipated);
    ck_assert_msg(fabs(total1 - total0) <= 1e-3 * through,
                  "the balance moved by %g J of %g J through (%g dissipated)", total1 - total0,
                  through, dissipated);
    demill_world_destroy(w);
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
    TCase *ti = tcase_create("impacts");
    tcase_add_loop_test(ti, jkr_impact, 0, 8);
    tcase_add_loop_test(ti, capillary_impact, 0, 8);
    tcase_add_loop_test(ti, impacts_other_integrators, 0, 2);
    tcase_add_loop_test(ti, bond_survives_rebuilds_and_copies, 0, 4);
    tcase_add_test(ti, longer_reach_mid_bond);
    tcase_add_loop_test(ti, pile_balance, 0, 4);
    suite_add_tcase(s, ti);
    return dm_test_run(s);
}
