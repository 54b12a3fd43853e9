/* plastic.c: the elasto-plastic normal laws (docs/physics.md, "Elasto-plastic
 * normal laws") against closed forms and independent quadratures.
 *
 * The laws' force-overlap relations (lib/physics/contact/plastic.h) drive a
 * head-on impact of a mass m* integrated at 20,000 steps per contact, so
 * that the integrator's error is far below the tolerances:
 * - Thornton (1997): the coefficient of restitution against impact speed,
 *   his closed form e(v_y/v) for v > v_y, v_y from (1/2) m* v_y² = 2/5 F_y δ_y
 *   (the elastic work to yield); e = 1 below v_y; the kinetic energy lost
 *   equals the booked plastic work;
 * - Walton and Braun (1986): e = √(k1/k2), and the loss equals the loop area
 *   (1/2) k1 δ_max² (1 - k1/k2) with δ_max = v √(m* / k1);
 * - the multi-path law of Li, Gao, Zhang and Liu (2018): the elastic limit
 *   f_y = π³ R*² (1.6 σ_y)³/(6 E*²) and δ_y = (0.8 π σ_y/E*)² R* (their eqs.
 *   5-7 with Johnson's p_0 = 1.6 σ_y), and the loss per impact equal to the
 *   loop integral of their eq. 11, here by Simpson's rule over the loading
 *   and unloading curves (independent of the closed form the law books);
 * - infinite yield is Hertz bit for bit.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/contact/plastic.h"
#include "testutil.h"

/* A law as a function of the overlap and the history. */
typedef void (*law_fn)(const void *ctx, double delta, double dmax_old, double onset_old,
                       dm_plastic_out *o);

typedef struct thornton_ctx {
    double e_star, rstar, py;
} thornton_ctx;

static void thornton_law(const void *ctx, double delta, double dmax_old, double onset_old,
                         dm_plastic_out *o)
{
    (void)onset_old;
    const thornton_ctx *c = ctx;
    dm_thornton(c->e_star, c->rstar, c->py, delta, dmax_old, o);
}

typedef struct wb_ctx {
    double k1, r;
} wb_ctx;

static void wb_law(const void *ctx, double delta, double dmax_old, double onset_old,
                   dm_plastic_out *o)
{
    (void)onset_old;
    const wb_ctx *c = ctx;
    dm_walton_braun(c->k1, c->r, delta, dmax_old, o);
}

typedef struct paths_ctx {
    double e_star, rstar, py;
    dm_paths_fit fit;
} paths_ctx;

static void paths_law(const void *ctx, double delta, double dmax_old, double onset_old,
                      dm_plastic_out *o)
{
    const paths_ctx *c = ctx;
    dm_plastic_paths(c->e_star, c->rstar, c->py, &c->fit, delta, dmax_old, onset_old, o);
}

/* An impact of mass m at speed v0 on the law, velocity Verlet with step dt
 * from first touch until the force has let go on the way out. */
typedef struct impact {
    double e;      /* rebound speed / v0 */
    double lost;   /* kinetic energy lost */
    double booked; /* plastic work the law booked */
    double dmax;   /* largest overlap */
} impact;

static impact run_impact(law_fn law, const void *ctx, double m, double v0, double dt)
{
    double d = 0.0, v = v0, dmax = 0.0, booked = 0.0;
    dm_plastic_out o = {0};
    for (long k = 0; k < 100000000L; k++) {
        const double f = d > 0.0 ? o.f : 0.0;
        v -= 0.5 * dt * f / m;
        d += dt * v;
        if (d <= 0.0 && v < 0.0)
            break;
        law(ctx, d, dmax, o.onset, &o);
        booked += o.diss;
        dmax = o.dmax;
        v -= 0.5 * dt * o.f / m;
        if (o.f == 0.0 && v < 0.0 && d < dmax)
            break; /* unloaded past the residual overlap: free flight */
    }
    return (impact){-v / v0, 0.5 * m * (v0 * v0 - v * v), booked, dmax};
}

/* ---- Thornton ---------------------------------------------------------- */

/* A 10 mm sphere of density 2500 on a rigid wall (R* = R, m* = m), E* 1e9 Pa,
 * limiting pressure 5e6 Pa. */
static const double th_r = 0.01, th_rho = 2500, th_e = 1e9, th_py = 5e6;

static double th_mass(void)
{
    return 4.0 / 3.0 * M_PI * pow(th_r, 3) * th_rho;
}

/* The yield speed from the elastic work to yield, 2/5 F_y δ_y, with
 * δ_y = R* (π py/(2E*))² and F_y = π³ py³ R*²/(6 E*²) written out (Thornton
 * 1997; for a sphere on a wall it is his 1.56 √(py⁵/(E*⁴ ρ))). */
static double th_vy(void)
{
    const double s = M_PI * th_py / (2 * th_e), dy = th_r * s * s;
    const double fy = pow(M_PI, 3) * pow(th_py, 3) * th_r * th_r / (6 * th_e * th_e);
    return sqrt(2 * 0.4 * fy * dy / th_mass());
}

/* Thornton's closed form for v > v_y, x = v_y/v. */
static double th_e_closed(double x)
{
    return sqrt(6 * sqrt(3.0) / 5) * sqrt(1 - x * x / 6) *
           pow(x / (x + 2 * sqrt(6.0 / 5 - x * x / 5)), 0.25);
}

/* A step of 1/20,000 of the elastic (Hertz) contact time at speed v,
 * 2.94324 δ_max/v (Johnson 1985, §11.4), which is longer than the plastic one. */
static double th_dt(double v)
{
    const double m = th_mass();
    const double dm = pow(15 * m * v * v / (16 * th_e * sqrt(th_r)), 0.4);
    return 2.94324 * dm / v / 20000;
}

START_TEST(thornton_restitution)
{
    const thornton_ctx c = {th_e, th_r, th_py};
    const double vy = th_vy(), m = th_mass();
    ck_assert(vy > 1e-3 && vy < 1e-2);
    /* below yield: elastic, e = 1 */
    const double below[] = {0.1, 0.5, 0.99};
    for (int k = 0; k < 3; k++) {
        const double v = below[k] * vy;
        impact o = run_impact(thornton_law, &c, m, v, th_dt(v));
        DM_ASSERT_REL(o.e, 1.0, 1e-9);
        ck_assert(o.booked == 0.0);
    }
    /* above: e(v) from e = 0.93 (2 v_y) down to 0.21 (1000 v_y) */
    const double above[] = {1.01, 2, 10, 100, 1000};
    for (int k = 0; k < 5; k++) {
        const double v = above[k] * vy;
        impact o = run_impact(thornton_law, &c, m, v, th_dt(v));
        DM_ASSERT_REL(o.e, th_e_closed(1 / above[k]), 1e-5);
        DM_ASSERT_REL(o.booked, o.lost, 1e-5);
    }
}
END_TEST

/* Reloading follows the unloading curve up to δ_max, then the loading line
 * again: the force at a point of the loading line is the same whether it was
 * reached directly or after an unload to half δ_max and a reload; the
 * plastic work is booked once. */
START_TEST(thornton_reload)
{
    const thornton_ctx c = {th_e, th_r, th_py};
    double dy, fy;
    dm_plastic_yield(th_e, th_r, th_py, &dy, &fy);
    dm_plastic_out a, b;
    dm_thornton(c.e_star, c.rstar, c.py, 20 * dy, 0.0, &a);
    dm_thornton(c.e_star, c.rstar, c.py, 10 * dy, a.dmax, &b); /* unload */
    ck_assert(b.diss == 0.0 && b.f < a.f && b.dmax == a.dmax);
    DM_ASSERT_REL(b.stored, 0.4 * b.f * (10 * dy - a.dres), 1e-12);
    dm_thornton(c.e_star, c.rstar, c.py, 20 * dy, b.dmax, &b); /* reload to δ_max */
    DM_ASSERT_REL(b.f, a.f, 1e-12);
    dm_thornton(c.e_star, c.rstar, c.py, 30 * dy, b.dmax, &b); /* and on */
    /* F = F_y + π py R* (δ - δ_y) */
    DM_ASSERT_REL(b.f, fy + M_PI * th_py * th_r * 29 * dy, 1e-12);
    DM_ASSERT_REL(a.diss + b.diss, dm_thornton_spent(th_e, th_r, th_py, 30 * dy), 1e-12);
}
END_TEST

/* ---- Walton and Braun ------------------------------------------------------ */

START_TEST(walton_braun_restitution_and_loop)
{
    const double m = 0.01, k1 = 1e5, v = 1.0;
    const double es[] = {1.0, 0.9, 0.5, 0.1, 0.01, 0.0};
    for (int k = 0; k < 6; k++) {
        const wb_ctx c = {k1, es[k] * es[k]};
        const double tc = M_PI * sqrt(m / k1); /* the loading half period bounds the contact */
        impact o = run_impact(wb_law, &c, m, v, tc / 20000);
        const double dmax = v * sqrt(m / k1);
        /* within 1e-6; at e = 0 the integrator's last half kick at the
         * turning point remains, about π/20,000 */
        ck_assert_msg(fabs(o.e - es[k]) <= (es[k] > 0 ? 1e-6 : 2e-4), "e = %.9g, expected %.9g",
                      o.e, es[k]);
        const double loop = 0.5 * k1 * dmax * dmax * (1 - es[k] * es[k]);
        ck_assert_msg(fabs(o.booked - loop) <= 1e-6 * 0.5 * m * v * v, "booked %.9g, loop %.9g",
                      o.booked, loop);
        ck_assert_msg(fabs(o.lost - loop) <= 1e-6 * 0.5 * m * v * v, "lost %.9g, loop %.9g",
                      o.lost, loop);
    }
}
END_TEST

/* ---- the multi-path law ------------------------------------------------------ */

/* Two aluminium spheres of 5 mm (E = 70 GPa, ν = 0.33, ρ = 2700, as in Li
 * et al. 2018), R* = 2.5 mm, m* half a sphere's mass; σ_y = 100 MPa (their
 * text gives none); their aluminium fit P(R*) = 54.95 - 2889 R* + 88478 R*²
 * (eq. 9) with H = 1 (not in the text). */
static paths_ctx al_ctx(void)
{
    const double e = 70e9, nu = 0.33, sy = 100e6;
    return (paths_ctx){e / (2 * (1 - nu * nu)), 2.5e-3, 1.6 * sy, {54.95, -2889, 88478, 1.0}};
}

static double al_mass(void)
{
    return 0.5 * 4.0 / 3.0 * M_PI * pow(5e-3, 3) * 2700;
}

/* Their elastic limit (eqs. 5-7): with a fit below Hertz past it (P = 2,
 * H = 1: f_y (1 + 2u) against Hertz's f_y (1 + u)³), path 1 ends at
 * (δ_y, f_y) and path 2 starts there. */
START_TEST(paths_elastic_limit)
{
    paths_ctx c = al_ctx();
    c.fit = (dm_paths_fit){2.0, 0.0, 0.0, 1.0};
    const double sy = c.py / 1.6;
    const double dy = pow(0.8 * M_PI * sy / c.e_star, 2) * c.rstar;
    const double fy = pow(M_PI, 3) * c.rstar * c.rstar * pow(1.6 * sy, 3) / (6 * c.e_star * c.e_star);
    /* a_y = 0.8 π R σ_y/E (their eq. 7) and a² = R δ */
    DM_ASSERT_REL(sqrt(c.rstar * dy), 0.8 * M_PI * c.rstar * sy / c.e_star, 1e-12);
    dm_plastic_out o;
    dm_plastic_paths(c.e_star, c.rstar, c.py, &c.fit, dy * (1 - 1e-12), 0.0, 0.0, &o);
    ck_assert(o.diss == 0.0 && o.dres == 0.0); /* path 1 */
    DM_ASSERT_REL(o.onset, dy, 1e-12);
    DM_ASSERT_REL(o.f, fy, 1e-9);
    dm_plastic_paths(c.e_star, c.rstar, c.py, &c.fit, dy * (1 + 1e-6), 0.0, 0.0, &o);
    ck_assert(o.diss > 0.0 && o.dres > 0.0); /* path 2 */
    DM_ASSERT_REL(o.f, fy, 1e-6);
    /* path 2 at a = 2 a_y (δ = 4 δ_y): f_y (1 + P) */
    dm_plastic_paths(c.e_star, c.rstar, c.py, &c.fit, 4 * dy, 0.0, 0.0, &o);
    DM_ASSERT_REL(o.f, 3 * fy, 1e-12);
}
END_TEST

/* The paper's aluminium fit, P = 54.95 - 2889 R* + 88478 R*² (eq. 9), is
 * above Hertz past δ_y for H = 1: the loading stays on Hertz up to where
 * they meet, f_y (1 + P u) = f_y (1 + u)³, u² + 3u + 3 - P = 0,
 * u_x = (√(4P - 3) - 3)/2 (for P > 3), and the fit goes on from there. */
START_TEST(paths_onset)
{
    const paths_ctx c = al_ctx();
    double dy, fy;
    dm_plastic_yield(c.e_star, c.rstar, c.py, &dy, &fy);
    const double p = 54.95 - 2889 * c.rstar + 88478 * c.rstar * c.rstar;
    const double ux = (sqrt(4 * p - 3) - 3) / 2, dx = dy * (1 + ux) * (1 + ux);
    ck_assert(ux > 5 && ux < 6);
    dm_plastic_out o;
    dm_plastic_paths(c.e_star, c.rstar, c.py, &c.fit, 1.5 * dy, 0.0, 0.0, &o);
    DM_ASSERT_REL(o.onset, dx, 1e-12);
    ck_assert(o.diss == 0.0 && o.dres == 0.0);
    DM_ASSERT_REL(o.f, dm_hertz_force(c.e_star, c.rstar, 1.5 * dy), 1e-15);
    dm_plastic_paths(c.e_star, c.rstar, c.py, &c.fit, 1.1 * dx, 0.0, o.onset, &o);
    ck_assert(o.diss > 0.0 && o.dres > 0.0);
    DM_ASSERT_REL(o.f, fy * (1 + p * (sqrt(1.1 * dx / dy) - 1)), 1e-12);
    /* H = 2: u² P = (1 + u)³ - 1 has two roots, and the fit is below Hertz
     * before the first: the onset is the second, where u³ - (P - 3) u² + 3u
     * = 0, u = ((P - 3) + √((P - 3)² - 12))/2 */
    paths_ctx c2 = c;
    c2.fit.h = 2.0;
    const double u2 = ((p - 3) + sqrt((p - 3) * (p - 3) - 12)) / 2;
    dm_plastic_paths(c2.e_star, c2.rstar, c2.py, &c2.fit, 1.5 * dy, 0.0, 0.0, &o);
    DM_ASSERT_REL(o.onset, dy * (1 + u2) * (1 + u2), 1e-12);
}
END_TEST

/* ∫ f over [a, b] by Simpson's rule on n (even) intervals: loading (dmax 0:
 * each point a new maximum) or unloading from dmax. */
static double simpson(const paths_ctx *c, double onset, double a, double b, double dmax, int n)
{
    const double h = (b - a) / n;
    double s = 0.0;
    for (int k = 0; k <= n; k++) {
        dm_plastic_out o;
        const double x = a + k * h;
        paths_law(c, x, dmax > 0 ? dmax : x, onset, &o);
        s += (k == 0 || k == n ? 1 : k % 2 ? 4 : 2) * o.f;
    }
    return s * h / 3;
}

/* The loss per impact against the loop integral of eq. 11 by quadrature,
 * for fits above and below Hertz past δ_y, at 1 m/s (e about 0.3-0.8). */
START_TEST(paths_loop_integral)
{
    const dm_paths_fit fits[] = {{54.95, -2889, 88478, 1.0}, /* theirs, with H = 1 */
                                 {54.95, -2889, 88478, 0.5},
                                 {2.0, 0.0, 0.0, 1.0},
                                 {2.0, 0.0, 0.0, 2.0}};
    for (int k = 0; k < 4; k++) {
        paths_ctx c = al_ctx();
        c.fit = fits[k];
        const double m = al_mass(), v = 1.0;
        /* 1/20,000 of the elastic contact time bounds the step */
        const double dm = pow(15 * m * v * v / (16 * c.e_star * sqrt(c.rstar)), 0.4);
        impact o = run_impact(paths_law, &c, m, v, 2.94324 * dm / v / 20000);
        dm_plastic_out top;
        paths_law(&c, o.dmax, o.dmax, 0.0, &top);
        ck_assert_msg(o.dmax > top.onset && o.e > 0.0 && o.e < 1.0, "fit %d: e = %g", k, o.e);
        /* the loop OABC: loading from 0 (path 1 to δ_x, path 2 on), less the
         * unloading curve from δ_max down to δ_r */
        const double load = simpson(&c, top.onset, 0, top.onset, 0, 2000) +
                            simpson(&c, top.onset, top.onset, o.dmax, 0, 200000);
        const double unload = simpson(&c, top.onset, top.dres, o.dmax, o.dmax, 2000);
        DM_ASSERT_REL(o.lost, load - unload, 1e-6);
        DM_ASSERT_REL(o.booked, load - unload, 1e-6);
    }
}
END_TEST

/* The plastic work grows with δ_max (no step books a negative loss), for
 * fits above and below Hertz and exponents across (0, 3). */
START_TEST(paths_work_grows)
{
    const double hs[] = {0.3, 1.0, 2.0, 2.9}, ps[] = {0.5, 3.0, 48.0, 1e4};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            paths_ctx c = al_ctx();
            c.fit = (dm_paths_fit){ps[j], 0, 0, hs[i]};
            double dy, fy, dmax = 0, onset = 0;
            dm_plastic_yield(c.e_star, c.rstar, c.py, &dy, &fy);
            for (double d = 0.1 * dy; d < 1e6 * dy; d *= 1.01) {
                dm_plastic_out o;
                paths_law(&c, d, dmax, onset, &o);
                ck_assert_msg(o.diss >= -1e-15 * o.stored, "H %g P %g δ/δ_y %g: %g", hs[i],
                              ps[j], d / dy, o.diss);
                ck_assert(o.dres >= 0.0 && o.dres < d);
                dmax = o.dmax;
                onset = o.onset;
            }
        }
}
END_TEST

/* ---- infinite yield ----------------------------------------------------------- */

START_TEST(infinite_yield_is_hertz)
{
    const double e = 1e9, r = 0.004;
    const dm_paths_fit fit = {54.95, -2889, 88478, 1.0};
    double dmax = 0.0, onset = 0.0;
    for (int k = 1; k < 200; k++) {
        /* load, unload, reload, each time a little further */
        const double d = 1e-6 * (1 + 5 * (1 - cos(M_PI * k / 25)) + k / 50.0);
        dm_plastic_out a, b;
        dm_thornton(e, r, INFINITY, d, dmax, &a);
        dm_plastic_paths(e, r, INFINITY, &fit, d, dmax, onset, &b);
        onset = b.onset;
        const double hertz = (4.0 / 3.0) * e * sqrt(r * d) * d;
        ck_assert_msg(a.f == hertz && b.f == hertz, "%.17g %.17g %.17g", a.f, b.f, hertz);
        ck_assert(a.diss == 0.0 && b.diss == 0.0 && a.dres == 0.0 && b.dres == 0.0);
        dmax = a.dmax;
    }
}
END_TEST

/* ---- what the time step sees -------------------------------------------------- */

/* dm_plastic_impact(): δ_max where the loading work equals the impact
 * energy, the unloading slope there, and twice the shorter phase. Thornton
 * at 10 v_y: F_max = F_y √(6/(5x²) - 1/5) (the energy balance above),
 * δ_max = δ_y + (F_max - F_y)/(π p_y R*), slope 2 E* a_max; Walton and Braun:
 * δ_max = v √(m* / k1), slope k2 = k1/e², and the unloading half period
 * doubled, π √(m* / k2); the multi-path law: the lone impact's δ_max. */
START_TEST(impact_for_the_time_step)
{
    dm_pairparam pp = {0};
    pp.e_star = th_e;
    pp.py = th_py;
    double dmax, stiff, contact, dy, fy;
    const double m = th_mass(), x = 0.1, v = th_vy() / x;
    dm_plastic_impact(DEMILL_NORMAL_THORNTON, &pp, th_r, m, v, &dmax, &stiff, &contact);
    dm_plastic_yield(th_e, th_r, th_py, &dy, &fy);
    const double fmax = fy * sqrt(6 / (5 * x * x) - 0.2);
    DM_ASSERT_REL(dmax, dy + (fmax - fy) / (M_PI * th_py * th_r), 1e-12);
    DM_ASSERT_REL(stiff, 2 * th_e * sqrt((2 * fmax + fy) / (2 * M_PI * th_py)), 1e-12);
    ck_assert(contact > 0 && contact < 2.94324 * dmax / v);

    pp.kn = 1e5;
    pp.restitution = 0.5;
    const double mw = 0.01;
    dm_plastic_impact(DEMILL_NORMAL_WALTON_BRAUN, &pp, 0.01, mw, 1.0, &dmax, &stiff, &contact);
    DM_ASSERT_REL(dmax, sqrt(mw / 1e5), 1e-12);
    DM_ASSERT_REL(stiff, 4e5, 1e-15);
    DM_ASSERT_REL(contact, M_PI * sqrt(mw / 4e5), 1e-12);

    const paths_ctx c = al_ctx();
    pp.e_star = c.e_star;
    pp.py = c.py;
    const double fit[4] = {c.fit.c0, c.fit.c1, c.fit.c2, c.fit.h};
    for (int k = 0; k < 4; k++)
        pp.fit[k] = fit[k];
    const double dm = pow(15 * al_mass() / (16 * c.e_star * sqrt(c.rstar)), 0.4);
    impact o = run_impact(paths_law, &c, al_mass(), 1.0, 2.94324 * dm / 20000);
    dm_plastic_impact(DEMILL_NORMAL_PLASTIC_PATHS, &pp, c.rstar, al_mass(), 1.0, &dmax, &stiff,
                      &contact);
    DM_ASSERT_REL(dmax, o.dmax, 1e-6);
}
END_TEST

/* ---- in a world ------------------------------------------------------------ */

/* A world without gravity with one material of E = 1 GPa, ν = 0.3,
 * ρ = 2500 and yield stress sy (0: none), its pair with itself on normal
 * law nl without damping, and the integrator of loop index i (velocity
 * Verlet, the iterative refinement). */
static demill_world *plastic_world(int dim, int nl, double sy, int i, demill_id *m)
{
    demill_world *w = dm_test_world(dim, nl, DEMILL_DAMPING_NONE, m);
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e9));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_YIELD_STRESS, sy));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                              i ? DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT
                                : DEMILL_INTEGRATOR_VELOCITY_VERLET));
    return w;
}

/* The world's suggested step for impacts at v (50 steps per contact) of
 * two spheres of radius r and material mat (placed far apart for the
 * question, and removed). */
static double suggested(demill_world *w, demill_id mat, double r, double v)
{
    const double x[6] = {-1, 0, 0, 1, 0, 0}, rr[2] = {r, r};
    demill_id ids[2];
    DM_OK(w, demill_particles_add(w, mat, 2, x, rr, NULL, 0, ids));
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, v, 0, &dt, NULL, NULL));
    DM_OK(w, demill_particles_remove(w, 2, ids));
    return dt;
}

#define PHASES 4
static const double sy_world = 1e7, r_world = 0.005;

/* Thornton's e in a world: two spheres (R* = R/2, m* = m/2) and a sphere on a
 * plane of the same material (R* = R, m* = m), 2D and 3D, at the suggested
 * step from 4 entry phases: against the closed form within 1 % above v_y,
 * with p_y = 1.6 σ_y; below it e = 1 within Verlet's accuracy for an elastic
 * Hertz impact (1e-4: collision.c measures 4e-5) and no plastic work. */
START_TEST(thornton_in_a_world)
{
    const double nu = 0.3, e_star = 1e9 / (2 * (1 - nu * nu)), py = 1.6 * sy_world;
    const double m = 4.0 / 3.0 * M_PI * pow(r_world, 3) * 2500;
    for (int dim = 2; dim <= 3; dim++)
        for (int wall = 0; wall < 2; wall++) {
            const double rstar = wall ? r_world : r_world / 2, mstar = wall ? m : m / 2;
            const double s = M_PI * py / (2 * e_star), dy = rstar * s * s;
            const double fy = pow(M_PI, 3) * py * py * py * rstar * rstar / (6 * e_star * e_star);
            const double vy = sqrt(4 * fy * dy / (5 * mstar));
            const double ratios[] = {0.5, 2, 10, 100};
            for (int k = 0; k < 4; k++) {
                demill_id mat;
                demill_world *w = plastic_world(dim, DEMILL_NORMAL_THORNTON, sy_world, _i, &mat);
                const double v = ratios[k] * vy, dt = suggested(w, mat, r_world, v);
                for (int p = 0; p < PHASES; p++) {
                    const double before = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC);
                    const double ph = (p + 0.5) / PHASES;
                    dm_collision o = wall ? dm_test_bounce(w, mat, r_world, v, dt, ph)
                                          : dm_test_collide(w, mat, r_world, v, dt, ph, 0.0);
                    const double spent =
                        dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC) - before;
                    if (ratios[k] < 1) {
                        DM_ASSERT_REL(o.restitution, 1.0, 1e-4);
                        ck_assert(spent == 0.0);
                    } else {
                        DM_ASSERT_REL(o.restitution, th_e_closed(1 / ratios[k]), 0.01);
                        /* the kinetic energy lost is the plastic work */
                        const double e = o.restitution;
                        DM_ASSERT_REL(spent, 0.5 * mstar * v * v * (1 - e * e), 0.01);
                    }
                }
                demill_world_destroy(w);
            }
        }
}
END_TEST

/* Walton and Braun in a world: e = √(k1/k2) within 0.5 %, and the plastic
 * work booked equals the loop area ½ k1 δ_max² (1 - e²) = ½ m* v² (1 - e²)
 * (δ_max = v √(m* / k1)) within 0.5 %; two spheres and a sphere on a plane,
 * 2D and 3D. */
START_TEST(walton_braun_in_a_world)
{
    const double m = 4.0 / 3.0 * M_PI * pow(r_world, 3) * 2500, v = 1.0;
    const double es[] = {0.9, 0.5, 0.1};
    for (int dim = 2; dim <= 3; dim++)
        for (int wall = 0; wall < 2; wall++)
            for (int k = 0; k < 3; k++) {
                demill_id mat;
                demill_world *w = plastic_world(dim, DEMILL_NORMAL_WALTON_BRAUN, 0, _i, &mat);
                DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_RESTITUTION, es[k]));
                const double mstar = wall ? m : m / 2, dt = suggested(w, mat, r_world, v);
                for (int p = 0; p < PHASES; p++) {
                    const double before = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC);
                    const double ph = (p + 0.5) / PHASES;
                    dm_collision o = wall ? dm_test_bounce(w, mat, r_world, v, dt, ph)
                                          : dm_test_collide(w, mat, r_world, v, dt, ph, 0.0);
                    const double spent =
                        dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC) - before;
                    DM_ASSERT_REL(o.restitution, es[k], 0.005);
                    DM_ASSERT_REL(spent, 0.5 * mstar * v * v * (1 - es[k] * es[k]), 0.005);
                }
                demill_world_destroy(w);
            }
}
END_TEST

/* The multi-path law in a world, with the aluminium of Li et al. (2018) and
 * σ_y = 100 MPa at 1 m/s: the plastic work of an impact equals the loop
 * integral (Simpson's rule over the law's loading and unloading curves to the
 * impact's δ_max, found by bisection on the loading work) within 1 %. */
START_TEST(paths_in_a_world)
{
    const paths_ctx c = al_ctx();
    const double r = 5e-3, v = 1.0, m = 4.0 / 3.0 * M_PI * r * r * r * 2700;
    for (int dim = 2; dim <= 3; dim++)
        for (int wall = 0; wall < 2; wall++) {
            demill_id mat;
            demill_world *w = plastic_world(dim, DEMILL_NORMAL_PLASTIC_PATHS, c.py / 1.6, _i, &mat);
            DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_YOUNGS_MODULUS, 70e9));
            DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_POISSON_RATIO, 0.33));
            DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_DENSITY, 2700));
            paths_ctx cw = c;
            cw.rstar = wall ? r : r / 2;
            cw.e_star = 70e9 / (2 * (1 - 0.33 * 0.33));
            const double mstar = wall ? m : m / 2, dt = suggested(w, mat, r_world, v);
            /* δ_max: the loading work (the integral of the loading curve) is ½ m* v² */
            dm_plastic_out top;
            paths_law(&cw, 1e-300, 1e-300, 0.0, &top);
            const double onset = top.onset;
            double lo = 0, hi = 1e-3;
            for (int k = 0; k < 100; k++) {
                const double mid = 0.5 * (lo + hi);
                const double work = simpson(&cw, onset, 0, fmin(mid, onset), 0, 2000) +
                                    (mid > onset ? simpson(&cw, onset, onset, mid, 0, 20000) : 0);
                if (work < 0.5 * mstar * v * v)
                    lo = mid;
                else
                    hi = mid;
            }
            paths_law(&cw, hi, hi, onset, &top);
            const double load = 0.5 * mstar * v * v;
            const double loop = load - simpson(&cw, onset, top.dres, hi, hi, 2000);
            for (int p = 0; p < PHASES; p++) {
                const double before = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC);
                const double ph = (p + 0.5) / PHASES;
                dm_collision o = wall ? dm_test_bounce(w, mat, r, v, dt, ph)
                                      : dm_test_collide(w, mat, r, v, dt, ph, 0.0);
                const double spent = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC) - before;
                DM_ASSERT_REL(spent, loop, 0.01);
                DM_ASSERT_REL(0.5 * mstar * v * v * (1 - o.restitution * o.restitution), loop, 0.01);
            }
            demill_world_destroy(w);
        }
}
END_TEST

/* A box 6 cm wide of plane walls, open at the top, with 40 spheres of 4-5 mm
 * on a lattice, moving at random up to 0.5 m/s under gravity, of one
 * material on normal law nl with viscous damping c_n = 0.05 N s/m and
 * friction on a linear spring (not Mindlin's: its k_t follows δ, so that
 * its spring energy is not a potential and its tally may dip below 0,
 * docs/physics.md §10); σ_y as given. */
static demill_world *pile(int dim, int nl, double sy, demill_id *mat)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e9));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_YIELD_STRESS, sy));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, nl));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_VISCOUS));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_VISCOUS_DAMPING, 0.05));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double side = 0.06;
    for (int a = 0; a < dim; a++)
        for (int s = 0; s < (a == 1 ? 1 : 2); s++) {
            double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            p[a] = s ? side : 0;
            n[a] = s ? -1 : 1;
            demill_id wall;
            DM_OK(w, demill_wall_add_plane(w, *mat, p, n, &wall));
        }
    /* 16 (3D: 4 × 4) or 5 (2D) per layer, 11 mm apart, layer on layer */
    srand(2024);
    const int per = dim == 3 ? 16 : 5;
    double x[3 * 40], v[3 * 40], r[40];
    for (int i = 0; i < 40; i++) {
        const int k = i % per;
        x[3 * i] = 0.0075 + (dim == 3 ? k % 4 : k) * 0.011;
        x[3 * i + 1] = 0.0075 + i / per * 0.011;
        x[3 * i + 2] = dim == 3 ? 0.0075 + k / 4 * 0.011 : 0;
        for (int c = 0; c < 3; c++)
            v[3 * i + c] = c < dim ? rand() / (double)RAND_MAX - 0.5 : 0;
        r[i] = 0.004 + 0.001 * rand() / (double)RAND_MAX;
    }
    demill_id first;
    DM_OK(w, demill_particles_add(w, *mat, 40, x, r, v, DEMILL_ADD_NO_OVERLAP, &first));
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, 0, 0, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt / 2));
    return w;
}

static const int plastic_laws[] = {DEMILL_NORMAL_THORNTON, DEMILL_NORMAL_WALTON_BRAUN,
                                   DEMILL_NORMAL_PLASTIC_PATHS};

/* The first law with every term: a pile settling on each plastic law, with
 * a dashpot and friction, keeps DEMILL_ENERGY_TOTAL within 1e-3 of
 * the energy that went through it (the initial kinetic energy plus all that
 * was dissipated) over 0.05 s at 100 steps per contact; plastic work is
 * booked, and no term is negative. */
START_TEST(pile_energy_balance)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int k = 0; k < 3; k++) {
            demill_id mat;
            demill_world *w = pile(dim, plastic_laws[k], 1e6, &mat);
            const double total0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
            const double kin0 = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL);
            double dt;
            DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
            DM_OK(w, demill_world_step(w, (uint64_t)(0.05 / dt)));
            const double through = kin0 + dm_test_energy(w, DEMILL_ENERGY_DISSIPATED);
            const double drift = dm_test_energy(w, DEMILL_ENERGY_TOTAL) - total0;
            ck_assert_msg(fabs(drift) <= 1e-3 * through, "dim %d law %d: drift %g of %g", dim,
                          plastic_laws[k], drift, through);
            const double plastic = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC);
            ck_assert_msg(plastic > 1e-3 * through, "dim %d law %d: plastic %g of %g", dim,
                          plastic_laws[k], plastic, through);
            for (int t = DEMILL_ENERGY_DISSIPATED_NORMAL; t <= DEMILL_ENERGY_DISSIPATED; t++)
                ck_assert_msg(dm_test_energy(w, t) >= 0.0, "dim %d law %d: term %d = %g", dim,
                              plastic_laws[k], t, dm_test_energy(w, t));
            ck_assert(dm_test_energy(w, DEMILL_ENERGY_ELASTIC_NORMAL) >= 0.0);
            demill_world_destroy(w);
        }
}
END_TEST

/* Infinite yield is Hertz bit for bit: the same pile on Thornton's and the
 * multi-path law with no yield stress (0) and with σ_y = 1e30 Pa steps to
 * the same positions and velocities as on Hertz's law, 2D and 3D, and books
 * no plastic work. */
START_TEST(no_yield_is_hertz)
{
    for (int dim = 2; dim <= 3; dim++) {
        demill_id mh;
        demill_world *hertz = pile(dim, DEMILL_NORMAL_HERTZ, 0, &mh);
        double dt;
        DM_OK(hertz, demill_world_get(hertz, DEMILL_WORLD_TIME_STEP, &dt));
        DM_OK(hertz, demill_world_step(hertz, 3000));
        size_t n;
        double *want = dm_test_state(hertz, &n);
        const double sys[] = {0, 1e30};
        for (int k = 0; k < 2; k++)
            for (int j = 0; j < 2; j++) {
                demill_id mp;
                const int nl = k ? DEMILL_NORMAL_PLASTIC_PATHS : DEMILL_NORMAL_THORNTON;
                demill_world *w = pile(dim, nl, sys[j], &mp);
                DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
                DM_OK(w, demill_world_step(w, 3000));
                size_t m;
                double *got = dm_test_state(w, &m);
                ck_assert(m == n);
                for (size_t q = 0; q < 6 * n; q++)
                    ck_assert_msg(got[q] == want[q], "dim %d law %d σ_y %g: value %zu %.17g, "
                                  "Hertz %.17g", dim, nl, sys[j], q, got[q], want[q]);
                ck_assert(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC) == 0.0);
                free(got);
                demill_world_destroy(w);
            }
        free(want);
        demill_world_destroy(hertz);
    }
}
END_TEST

/* The extremes of Walton and Braun's e: e = 1 is the linear spring bit for
 * bit (the pile on both laws, undamped: no dashpot, so that the laws'
 * entry corrections play no part), and e = 0 stops a head-on impact dead:
 * what rebounds is the integrator's last half kick at the turning point
 * (about π/100 of v at 50 steps per loading, π √(m* / k1)), and the whole
 * impact energy is plastic work, within 0.5 %. */
START_TEST(walton_braun_extremes)
{
    for (int dim = 2; dim <= 3; dim++) {
        demill_world *worlds[2];
        double *states[2], dt0 = 0;
        size_t n[2];
        for (int k = 0; k < 2; k++) { /* at the linear law's step */
            demill_id mat;
            worlds[k] = pile(dim, k ? DEMILL_NORMAL_WALTON_BRAUN : DEMILL_NORMAL_LINEAR, 0, &mat);
            DM_OK(worlds[k], demill_pair_set(worlds[k], mat, mat, DEMILL_PAIR_RESTITUTION, 1));
            DM_OK(worlds[k], demill_pair_set(worlds[k], mat, mat, DEMILL_PAIR_DAMPING,
                                             DEMILL_DAMPING_NONE));
            if (k)
                DM_OK(worlds[k], demill_world_set(worlds[k], DEMILL_WORLD_TIME_STEP, dt0));
            else
                DM_OK(worlds[k], demill_world_get(worlds[k], DEMILL_WORLD_TIME_STEP, &dt0));
            DM_OK(worlds[k], demill_world_step(worlds[k], 3000));
            states[k] = dm_test_state(worlds[k], &n[k]);
        }
        ck_assert(n[0] == n[1]);
        ck_assert(memcmp(states[0], states[1], 6 * n[0] * sizeof *states[0]) == 0);
        ck_assert(dm_test_energy(worlds[1], DEMILL_ENERGY_DISSIPATED_PLASTIC) == 0.0);
        for (int k = 0; k < 2; k++) {
            free(states[k]);
            demill_world_destroy(worlds[k]);
        }

        demill_id mat;
        demill_world *w = plastic_world(dim, DEMILL_NORMAL_WALTON_BRAUN, 0, 0, &mat);
        DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_RESTITUTION, 0));
        const double v = 1.0, dt = suggested(w, mat, r_world, v);
        const double x[6] = {-r_world - 3 * v * dt, 0, 0, r_world, 0, 0}, rr[2] = {r_world, r_world};
        const double vel[6] = {v, 0, 0, 0, 0, 0};
        demill_id ids[2];
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
        DM_OK(w, demill_particles_add(w, mat, 2, x, rr, vel, 0, ids));
        DM_OK(w, demill_world_step(w, 200));
        const double m = 4.0 / 3.0 * M_PI * pow(r_world, 3) * 2500;
        const double rel = dm_test_get(w, ids[1], DEMILL_PARTICLE_VELOCITY, 0) -
                           dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0);
        ck_assert_msg(fabs(rel) < 0.05 * v, "dim %d: rebound %g m/s", dim, rel);
        DM_ASSERT_REL(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC), 0.5 * (m / 2) * v * v,
                      0.005);
        demill_world_destroy(w);
    }
}
END_TEST

/* A checkpoint and a snapshot taken in the middle of the pile's plastic
 * contacts carry their histories: the copies step on bitwise (3D). */
START_TEST(plastic_checkpoint)
{
    for (int k = 0; k < 3; k++) {
        demill_id mat;
        demill_world *w = pile(3, plastic_laws[k], 1e6, &mat);
        DM_OK(w, demill_world_step(w, 10000));
        ck_assert(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC) > 0.0);
        dm_test_copies_run_on(w, 2000, NULL, NULL);
        demill_world_destroy(w);
    }
}
END_TEST

/* Restitution damping with a plastic law is refused when stepping starts,
 * and the world is left as it was. */
START_TEST(restitution_damping_refused)
{
    for (int k = 0; k < 3; k++) {
        demill_id mat;
        demill_world *w = pile(3, plastic_laws[k], 1e6, &mat);
        DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
        size_t n;
        double *before = dm_test_state(w, &n);
        ck_assert_int_eq(demill_world_step(w, 1), DEMILL_ERR_INVALID_VALUE);
        ck_assert(strstr(demill_world_last_error(w), "DEMILL_DAMPING_RESTITUTION"));
        double *after = dm_test_state(w, &n);
        ck_assert(memcmp(before, after, 6 * n * sizeof *before) == 0);
        free(before);
        free(after);
        demill_world_destroy(w);
    }
}
END_TEST

/* The suggested and critical steps of a Walton-Braun pair follow its
 * unloading stiffness k2 = k1/e²: critical 2 √(m* / k2), contact
 * π √(m* / k2) (the unloading half period doubled; the loading one,
 * π √(m* / k1), is longer), with m* = m/2 of the material's pair with
 * itself, the lightest (against the wall m* = m). */
START_TEST(walton_braun_time_step)
{
    demill_id mat;
    demill_world *w = plastic_world(3, DEMILL_NORMAL_WALTON_BRAUN, 0, 0, &mat);
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_RESTITUTION, 0.25));
    const double x[3] = {0.1, 0.1, 0.1}, r = 0.004, o[3] = {0, 0, 0}, nrm[3] = {0, 1, 0};
    demill_id id, wall;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &id));
    DM_OK(w, demill_wall_add_plane(w, mat, o, nrm, &wall));
    const double m = 4.0 / 3.0 * M_PI * r * r * r * 2500, k2 = 5e4 / 0.0625; /* k1 1e5 in series */
    double dt, critical, contact;
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 0, &dt, &critical, &contact));
    DM_ASSERT_REL(critical, 2 * sqrt(m / 2 / k2), 1e-12);
    DM_ASSERT_REL(contact, M_PI * sqrt(m / 2 / k2), 1e-9);
    DM_ASSERT_REL(dt, fmin(contact / 50, 0.2 * critical), 1e-12);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("plastic");
    TCase *tc = tcase_create("laws");
    tcase_add_test(tc, thornton_restitution);
    tcase_add_test(tc, thornton_reload);
    tcase_add_test(tc, walton_braun_restitution_and_loop);
    tcase_add_test(tc, paths_elastic_limit);
    tcase_add_test(tc, paths_onset);
    tcase_add_test(tc, paths_loop_integral);
    tcase_add_test(tc, paths_work_grows);
    tcase_add_test(tc, infinite_yield_is_hertz);
    tcase_add_test(tc, impact_for_the_time_step);
    TCase *tw = tcase_create("world");
    tcase_add_loop_test(tw, thornton_in_a_world, 0, 2);
    tcase_add_loop_test(tw, walton_braun_in_a_world, 0, 2);
    tcase_add_loop_test(tw, paths_in_a_world, 0, 2);
    tcase_add_test(tw, pile_energy_balance);
    tcase_add_test(tw, no_yield_is_hertz);
    tcase_add_test(tw, walton_braun_extremes);
    tcase_add_test(tw, plastic_checkpoint);
    tcase_add_test(tw, restitution_damping_refused);
    tcase_add_test(tw, walton_braun_time_step);
    suite_add_tcase(s, tw);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
