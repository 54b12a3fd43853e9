/* plastic.h: the force-overlap relations of the elasto-plastic normal laws
 * (docs/physics.md, "Elasto-plastic normal laws"), as pure functions of the
 * overlap and the contact's history, with no world: Thornton (1997), Walton
 * and Braun (1986), and the multi-path law of Li, Gao, Zhang and Liu (2018).
 *
 * Each law's history is the largest overlap of the contact so far, δ_max
 * (0 for a new contact); everything else (the yield point, the residual
 * overlap, the unloading curve) follows from it and the pair's constants.
 * Loading past δ_max follows the law's loading curve; below δ_max the force
 * follows the unloading curve through (δ_max, F(δ_max)) down to the residual
 * overlap δ_r, where it is zero, and reloading follows the same curve back up
 * to δ_max. The plastic work of the contact is a function of δ_max alone (the
 * area of the loop loading to δ_max and unloading from it), so that the
 * dissipation of a step is that function's increase, never negative, and
 * the account closes with the elastic energy of the current unloading curve.
 */
#ifndef DM_PLASTIC_H
#define DM_PLASTIC_H

#include <math.h>

#include "physics/state/state.h"

#define DM_PLASTIC_INLINE static inline __attribute__((always_inline))

/* What a law gives for an overlap delta > 0 and the history dmax_old. */
typedef struct dm_plastic_out {
    double f;      /* normal force, >= 0 */
    double stiff;  /* the unloading curve's slope dF/dδ at delta: the contact's
                      stiffness for a small reversal */
    double dmax;   /* the new history: max(dmax_old, delta) */
    double dres;   /* the residual overlap of the current unloading curve */
    double stored; /* elastic energy of the current unloading curve at delta */
    double diss;   /* plastic work of the step: spent(dmax) - spent(dmax_old) */
    double onset;  /* the multi-path law: where its plastic loading begins
                      (history kept for the contact's life; 0 for the others) */
} dm_plastic_out;

/* Hertz's force 4/3 E* √R* δ^{3/2} (Hertz 1882; Johnson 1985), written as
 * dm_law() writes it, so that a law that stays elastic is Hertz bit for bit. */
DM_PLASTIC_INLINE double dm_hertz_force(double e_star, double rstar, double delta)
{
    return (4.0 / 3.0) * e_star * sqrt(rstar * delta) * delta;
}

/* The elastic branch (δ_max <= δ_y): Hertz. */
DM_PLASTIC_INLINE void dm_plastic_elastic(double e_star, double rstar, double delta,
                                          dm_plastic_out *o)
{
    const double sq = sqrt(rstar * delta);
    o->f = (4.0 / 3.0) * e_star * sq * delta;
    o->stiff = 2.0 * e_star * sq;
    o->dres = 0.0;
    o->stored = 0.4 * o->f * delta;
}

/* The yield point of a Hertz contact whose peak pressure p_0 = 2 E* a/(π R*)
 * (Johnson 1985, ch. 4) reaches the limiting pressure py: the contact radius
 * a_y = π R* py/(2 E*), δ_y = a_y²/R*, F_y the Hertz force at δ_y
 * (= π³ py³ R*²/(6 E*²)). With py = 1.6 σ_y, the onset of yield by the
 * Mises criterion (Johnson 1985, §6.1, for ν = 0.3), a_y = 0.8 π R* σ_y/E*,
 * eq. 7 of Li et al. (2018). py = ∞: δ_y = F_y = ∞. */
DM_PLASTIC_INLINE void dm_plastic_yield(double e_star, double rstar, double py, double *dy,
                                        double *fy)
{
    const double s = DM_PI * py / (2.0 * e_star);
    *dy = rstar * s * s;
    *fy = dm_hertz_force(e_star, rstar, *dy);
}

/* ---- Thornton (1997) -------------------------------------------------------
 * Thornton, C. (1997), "Coefficient of restitution for collinear collisions
 * of elastic-perfectly plastic spheres", J. Appl. Mech. 64:383-386. Hertz up
 * to δ_y; beyond it the pressure is capped at py, F = F_y + π py R* (δ - δ_y)
 * with contact radius a² = (2F + F_y)/(2π py); unloading is Hertzian with
 * the enlarged radius of curvature R_p = 4 E* a_max³/(3 F_max),
 * F = 4/3 E* √R_p (δ - δ_r)^{3/2}, which passes through (δ_max, F_max) when
 * δ_max - δ_r = 3 F_max/(4 E* a_max); so F = F_max ((δ - δ_r)/(δ_max -
 * δ_r))^{3/2} and its slope at δ_max is 2 E* a_max. */

/* The peak of a Thornton contact loaded to dmax > δ_y: F_max, the contact
 * radius a_max and the unloading curve's span dmax - δ_r. */
DM_PLASTIC_INLINE void dm_thornton_peak(double e_star, double rstar, double py, double dy,
                                        double fy, double dmax, double *fmax, double *amax,
                                        double *span)
{
    *fmax = fy + DM_PI * py * rstar * (dmax - dy);
    *amax = sqrt((2.0 * *fmax + fy) / (2.0 * DM_PI * py));
    *span = 0.75 * *fmax / (e_star * *amax);
}

/* The plastic work of a Thornton contact loaded to dmax and unloaded: the
 * loading work (2/5 F_y δ_y + F_y Δ + π py R* Δ²/2, Δ = dmax - δ_y) less the
 * unloading curve's energy 2/5 F_max (dmax - δ_r); 0 below yield. */
DM_PLASTIC_INLINE double dm_thornton_spent(double e_star, double rstar, double py, double dmax)
{
    double dy, fy;
    dm_plastic_yield(e_star, rstar, py, &dy, &fy);
    double fmax, amax, span;
    dm_thornton_peak(e_star, rstar, py, dy, fy, dmax, &fmax, &amax, &span);
    const double x = dmax - dy;
    const double load = 0.4 * fy * dy + fy * x + 0.5 * DM_PI * py * rstar * x * x;
    const double spent = load - 0.4 * fmax * span;
    return dmax > dy ? spent : 0.0;
}

DM_PLASTIC_INLINE void dm_thornton(double e_star, double rstar, double py, double delta,
                                   double dmax_old, dm_plastic_out *o)
{
    double dy, fy;
    dm_plastic_yield(e_star, rstar, py, &dy, &fy);
    const double dmax = delta > dmax_old ? delta : dmax_old;
    o->dmax = dmax;
    o->onset = 0.0;
    o->diss = dm_thornton_spent(e_star, rstar, py, dmax) -
              dm_thornton_spent(e_star, rstar, py, dmax_old);
    if (dmax <= dy) {
        dm_plastic_elastic(e_star, rstar, delta, o);
        return;
    }
    double fmax, amax, span;
    dm_thornton_peak(e_star, rstar, py, dy, fy, dmax, &fmax, &amax, &span);
    o->dres = dmax - span;
    const double u = delta - o->dres;
    if (u <= 0.0) { /* unloaded below the residual overlap: apart in force */
        o->f = o->stiff = o->stored = 0.0;
        return;
    }
    const double q = u / span;
    /* on the loading line (delta = dmax) this is exactly fmax */
    o->f = delta >= dmax ? fmax : fmax * q * sqrt(q);
    o->stiff = 2.0 * e_star * amax * sqrt(q);
    o->stored = 0.4 * o->f * u;
}

/* ---- Walton and Braun (1986) ----------------------------------------------
 * Walton, O. R. and Braun, R. L. (1986), "Viscosity, granular-temperature,
 * and stress calculations for shearing assemblies of inelastic, frictional
 * disks", J. Rheol. 30:949-980: loading F = k1 δ, unloading and reloading
 * along the line of slope k2 through (δ_max, k1 δ_max), which reaches zero at
 * δ_r = δ_max (1 - k1/k2); reloading past δ_max continues on k1 δ. Here the
 * law takes r = k1/k2 = e² in [0, 1] (e the restitution of a collision,
 * e = √(k1/k2)); r = 0 unloads at once (k2 = ∞), r = 1 is the linear spring
 * k1 δ exactly. */

/* The loop area ½ k1 dmax² (1 - k1/k2). */
DM_PLASTIC_INLINE double dm_walton_braun_spent(double k1, double r, double dmax)
{
    return 0.5 * k1 * dmax * dmax * (1.0 - r);
}

DM_PLASTIC_INLINE void dm_walton_braun(double k1, double r, double delta, double dmax_old,
                                       dm_plastic_out *o)
{
    const double dmax = delta > dmax_old ? delta : dmax_old;
    o->dmax = dmax;
    o->onset = 0.0;
    o->dres = dmax * (1.0 - r);
    o->diss = dm_walton_braun_spent(k1, r, dmax) - dm_walton_braun_spent(k1, r, dmax_old);
    /* on the loading line exactly k1 δ; below it k2 (δ - δ_r), -∞ for
     * r = 0 (δ - δ_r < 0) */
    const double k2 = k1 / r;
    const double fu = delta >= dmax ? k1 * delta : k2 * (delta - o->dres);
    o->stiff = r > 0.0 ? k2 : k1; /* r = 0 unloads by a drop, not a spring */
    o->f = fu > 0.0 ? fu : 0.0;
    o->stored = 0.5 * o->f * o->f * r / k1; /* F²/(2 k2) */
}

/* ---- The multi-path law of Li, Gao, Zhang and Liu (2018) -------------------
 * Li Jian, Gao Wei, Zhang Yashuang and Liu Yunuo (2018), "Elasto-plastic
 * contact modelling method for the vibration and energy dissipation of
 * particles" (in Chinese), Journal of Northeastern University (Natural
 * Science) 39(8):1211-1216, §2 (their equation images are lost from the
 * text we read; docs/physics.md says what is reconstructed). Path 1: Hertz
 * to (δ_y, f_y) (their eqs. 4-7); paths 2 and 4, loading past it:
 * f = f_y + f_p (eq. 10), the plastic force a fitted function of R* and the
 * contact half-width a = √(R* δ) (a² = R δ, their text before eq. 7),
 * f_p = f_y P(R*) ((a - a_y)/a_y)^H, P(R*) = c0 + c1 R* + c2 R*² (eqs. 1-3,
 * 8-9; P taken as 0 where the fit goes negative); path 3, unloading and
 * reloading: Hertz's curve of the same E* and R* (the hardened contact)
 * through (δ_max, f_max), F = 4/3 E* √R* (δ - δ_r)^{3/2}. With
 * u = a/a_y - 1 = √(δ/δ_y) - 1, Hertz's force is f_y (1 + u)³ and the fit's
 * f_y (1 + P u^H): both depend on u alone.
 *
 * Our addition: a fit with P > 3 (H = 1) or H < 1 rises faster than Hertz
 * just past δ_y (the paper's aluminium fit has P = 48 at R* = 2.5 mm), and
 * Hertz's unloading curve through such a point would give back more work
 * than the loading took. The elasto-plastic contact is never stiffer than
 * the elastic one (the paper's Fig. 1), so the loading follows Hertz up to
 * the last point u_x where the fit meets it from above, δ_x = δ_y (1 + u_x)²
 * (u_x = 0 when the fit is below Hertz all the way: the paper's path 1 to
 * (δ_y, f_y) exactly), and the fit beyond. H < 3, so that Hertz's u³
 * overtakes the fit again. */

typedef struct dm_paths_fit {
    double c0, c1, c2; /* P(R*) = c0 + c1 R* + c2 R*² (1, 1/m, 1/m²) */
    double h;          /* the exponent H, in (0, 3) */
} dm_paths_fit;

DM_PLASTIC_INLINE double dm_paths_p(const dm_paths_fit *fit, double rstar)
{
    const double p = fit->c0 + (fit->c1 + fit->c2 * rstar) * rstar;
    return p > 0.0 ? p : 0.0;
}

/* ψ(u) = ((1 + u)³ - 1)/u^H - P: positive where the fit is below Hertz. */
DM_PLASTIC_INLINE double dm_paths_psi(double p, double h, double u)
{
    return 3.0 * pow(u, 1.0 - h) + 3.0 * pow(u, 2.0 - h) + pow(u, 3.0 - h) - p;
}

/* u_x, the last u where the fit meets Hertz from above (0 if it never is
 * above). u^H ψ' = 3(1 - H) + 3(2 - H) u + (3 - H) u² has one positive root
 * u_m for H > 1 (none for H <= 1, u_m = 0): ψ falls to its minimum at u_m
 * and rises beyond it, without bound for H < 3; so u_x is ψ's root past u_m
 * if ψ(u_m) < 0, found by bisection. A contact computes it once, at its
 * first sample. */
DM_PLASTIC_INLINE double dm_paths_onset(double p, double h)
{
    double lo = 0.0;
    if (h > 1.0) {
        const double a = 3.0 - h, b = 3.0 * (2.0 - h), c = 3.0 * (1.0 - h);
        const double s = sqrt(b * b - 4.0 * a * c);
        lo = b >= 0.0 ? 2.0 * c / (-b - s) : (-b + s) / (2.0 * a);
    }
    if (!(dm_paths_psi(p, h, lo) < 0.0))
        return 0.0;
    double hi = lo > 0.0 ? 2.0 * lo : 1.0;
    while (dm_paths_psi(p, h, hi) < 0.0 && hi < 1e300)
        hi *= 2.0;
    for (int k = 0; k < 2100 && hi - lo > 1e-15 * hi; k++) {
        const double mid = lo + 0.5 * (hi - lo);
        if (dm_paths_psi(p, h, mid) < 0.0)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

/* The contact's constants: the yield point, P and the onset δ_x (dx_old, or
 * computed if 0: a new contact). */
typedef struct dm_paths_state {
    double dy, fy, p, h, ux, dx;
} dm_paths_state;

DM_PLASTIC_INLINE dm_paths_state dm_paths_setup(double e_star, double rstar, double py,
                                                const dm_paths_fit *fit, double dx_old)
{
    dm_paths_state c;
    dm_plastic_yield(e_star, rstar, py, &c.dy, &c.fy);
    c.p = dm_paths_p(fit, rstar);
    c.h = fit->h;
    c.ux = dx_old > 0.0 ? sqrt(dx_old / c.dy) - 1.0 : dm_paths_onset(c.p, c.h);
    c.dx = dx_old > 0.0 ? dx_old : c.dy * (1.0 + c.ux) * (1.0 + c.ux);
    return c;
}

/* The fit's force at u, and the loading work to dmax > δ_x: Hertz's
 * 2/5 F(δ_x) δ_x, then the fit's, with δ = δ_y (1 + u)²,
 * dδ = 2 δ_y (1 + u) du: f_y δ_y (1 + u)² + 2 f_y P δ_y (u^{H+1}/(H+1) +
 * u^{H+2}/(H+2)) between u_x and u (the first part of their eq. 11). */
DM_PLASTIC_INLINE double dm_paths_fit_force(const dm_paths_state *c, double u)
{
    return c->fy * (1.0 + c->p * pow(u, c->h));
}

DM_PLASTIC_INLINE double dm_paths_fit_work(const dm_paths_state *c, double u)
{
    const double w = pow(u, c->h + 1.0);
    return c->fy * c->dy * ((1.0 + u) * (1.0 + u) +
                            2.0 * c->p * (w / (c->h + 1.0) + w * u / (c->h + 2.0)));
}

/* How far below the peak Hertz's curve of E*, R* through f_max reaches 0. */
DM_PLASTIC_INLINE double dm_paths_span(double e_star, double rstar, double fmax)
{
    const double s = 0.75 * fmax / e_star;
    return cbrt(s * s / rstar);
}

/* The plastic work to dmax (their eq. 11: the area OABC): the loading work
 * less the unloading curve's energy 2/5 f_max (dmax - δ_r); 0 up to δ_x. */
DM_PLASTIC_INLINE double dm_paths_spent(double e_star, double rstar, const dm_paths_state *c,
                                        double dmax)
{
    const double u = sqrt(dmax / c->dy) - 1.0, fmax = dm_paths_fit_force(c, u);
    const double load = 0.4 * dm_hertz_force(e_star, rstar, c->dx) * c->dx +
                        dm_paths_fit_work(c, u) - dm_paths_fit_work(c, c->ux);
    const double spent = load - 0.4 * fmax * dm_paths_span(e_star, rstar, fmax);
    return dmax > c->dx ? spent : 0.0;
}

/* dx_old: the contact's onset δ_x from its history, 0 for a new contact;
 * o->onset receives it. */
DM_PLASTIC_INLINE void dm_plastic_paths(double e_star, double rstar, double py,
                                        const dm_paths_fit *fit, double delta, double dmax_old,
                                        double dx_old, dm_plastic_out *o)
{
    const dm_paths_state c = dm_paths_setup(e_star, rstar, py, fit, dx_old);
    const double dmax = delta > dmax_old ? delta : dmax_old;
    o->dmax = dmax;
    o->onset = c.dx;
    o->diss = dm_paths_spent(e_star, rstar, &c, dmax) - dm_paths_spent(e_star, rstar, &c, dmax_old);
    if (dmax <= c.dx) { /* path 1 */
        dm_plastic_elastic(e_star, rstar, delta, o);
        return;
    }
    const double fmax = dm_paths_fit_force(&c, sqrt(dmax / c.dy) - 1.0);
    o->dres = dmax - dm_paths_span(e_star, rstar, fmax);
    const double x = delta - o->dres;
    if (x <= 0.0) {
        o->f = o->stiff = o->stored = 0.0;
        return;
    }
    const double sq = sqrt(rstar * x);
    /* paths 2 and 4 (delta = dmax): exactly fmax; path 3: Hertz from δ_r */
    o->f = delta >= dmax ? fmax : (4.0 / 3.0) * e_star * sq * x;
    o->stiff = 2.0 * e_star * sq;
    o->stored = 0.4 * o->f * x;
}

/* ---- the laws by choice, for the contact law and the time step ------------- */

/* Whether normal law NL is one of these, and the history doubles it keeps:
 * δ_max, and the multi-path law's onset δ_x. */
DM_PLASTIC_INLINE int dm_normal_plastic(int NL)
{
    return NL == DEMILL_NORMAL_THORNTON || NL == DEMILL_NORMAL_WALTON_BRAUN ||
           NL == DEMILL_NORMAL_PLASTIC_PATHS;
}

/* Whether normal law NL is Hertz's or grows from it (the laws whose
 * particles' Rayleigh waves bound the time step). */
DM_PLASTIC_INLINE int dm_normal_hertzian(int NL)
{
    return NL == DEMILL_NORMAL_HERTZ || NL == DEMILL_NORMAL_THORNTON ||
           NL == DEMILL_NORMAL_PLASTIC_PATHS;
}

DM_PLASTIC_INLINE int dm_plastic_hist_size(int NL)
{
    return NL == DEMILL_NORMAL_PLASTIC_PATHS ? 2 : dm_normal_plastic(NL);
}

/* Plastic law NL of pair pp at overlap delta > 0, from the contact's
 * history hin (dm_plastic_hist_size(NL) doubles, zeros for a new contact).
 * Walton and Braun's k1 is the pair's linear stiffness and k1/k2 the square
 * of its restitution. */
DM_PLASTIC_INLINE void dm_plastic_law(int NL, const dm_pairparam *pp, double rstar,
                                      double delta, const double *hin, dm_plastic_out *o)
{
    if (NL == DEMILL_NORMAL_THORNTON) {
        dm_thornton(pp->e_star, rstar, pp->py, delta, hin[0], o);
    } else if (NL == DEMILL_NORMAL_WALTON_BRAUN) {
        dm_walton_braun(pp->kn, pp->restitution * pp->restitution, delta, hin[0], o);
    } else {
        const dm_paths_fit fit = {pp->fit[0], pp->fit[1], pp->fit[2], pp->fit[3]};
        dm_plastic_paths(pp->e_star, rstar, pp->py, &fit, delta, hin[0], hin[1], o);
    }
}

/* What the time step needs of a head-on impact at speed v > 0 with reduced
 * mass mstar on plastic law NL: its largest overlap δ_max, the largest
 * stiffness of the contact, the
 * unloading curve's slope at δ_max (steeper than any loading slope: the
 * loading curves are never stiffer than Hertz's, nor Thornton's than
 * 2 E* a_y), and its duration, twice the shorter of the loading and the
 * unloading phases, each taken as half an elastic impact on its own curve:
 * shape δ/v with shape 2.94324 for a Hertzian curve (Johnson 1985, §11.4) and
 * π for a linear one. δ_max is where the loading work, the plastic work plus
 * the energy the unloading curve stores, equals ½ m* v², by bisection. */
DM_PLASTIC_INLINE void dm_plastic_impact(int NL, const dm_pairparam *pp, double rstar,
                                         double mstar, double v, double *dmax,
                                         double *stiff, double *contact)
{
    const double energy = 0.5 * mstar * v * v;
    double h[2] = {0.0, 0.0};
    dm_plastic_out o;
    dm_plastic_law(NL, pp, rstar, 1e-300, h, &o);
    h[1] = o.onset; /* the multi-path law's, found once */
    double lo = 0.0, hi = 1e-12;
    for (int k = 0; k < 2000; k++) {
        dm_plastic_law(NL, pp, rstar, hi, h, &o);
        if (o.diss + o.stored >= energy || hi > 1e30)
            break;
        lo = hi;
        hi *= 2.0;
    }
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; k++) {
        const double mid = lo + 0.5 * (hi - lo);
        dm_plastic_law(NL, pp, rstar, mid, h, &o);
        if (o.diss + o.stored < energy)
            lo = mid;
        else
            hi = mid;
    }
    dm_plastic_law(NL, pp, rstar, hi, h, &o);
    const double shape = NL == DEMILL_NORMAL_WALTON_BRAUN ? DM_PI : 2.94324;
    const double rebound = sqrt(2.0 * o.stored / mstar); /* 0: a dead stop (e = 0) */
    *dmax = hi;
    *stiff = o.stiff;
    *contact = shape * fmin(hi / v, (hi - o.dres) / rebound);
}

#endif /* DM_PLASTIC_H */
