/* law.h: the contact force law of one contact, composed of a normal law, a
 * damping law, a tangential law, a rolling law and a cohesion law
 * (docs/physics.md §2-5).
 *
 * dm_law() is written once and specialised by the compiler: the kernels call
 * it with compile-time constant law choices and dimension, so a part that is
 * switched off costs nothing. Queries call it with run-time choices.
 *
 * Conventions: body a and body b (a particle or a wall), unit normal n from a
 * to b, overlap delta > 0 (or, for a cohesive contact that exists, above
 * -dm_law_range()), relative velocity of b with respect to a at the
 * contact point vc, relative angular velocity wrel = ω_a - ω_b. The law
 * returns the normal force magnitude fn on b along n, the tangential force
 * ft on b and the rolling torque mr on a; a receives -(fn n + ft) and b
 * receives -mr.
 */
#ifndef DM_LAW_H
#define DM_LAW_H

#include <math.h>

#include "physics/contact/plastic.h"
#include "physics/contact/cohesion.h"
#include "physics/state/state.h"

#define DM_INLINE static inline __attribute__((always_inline))

typedef struct dm_law_out {
    double fn;    /* normal force on b along n */
    double fel;   /* its elastic part */
    double ft[3]; /* tangential force on b (D components) */
    double mr[3]; /* rolling torque on a (W components) */
    /* energy dissipated over the step, by mechanism (see dm_tally) */
    double diss_normal, diss_tangential, diss_friction, diss_rolling;
    /* the extended laws' (dm_tally) */
    double diss_plastic, diss_rolling_viscous, work_cohesion;
} dm_law_out;

/* The laws that only the generic kernel runs (see DM_FAST_KERNELS). */
DM_INLINE int dm_law_extended(int normal, int rolling, int cohesion)
{
    return normal > DEMILL_NORMAL_HERTZ || rolling > DEMILL_ROLLING_CONSTANT_TORQUE ||
           cohesion != DEMILL_COHESION_NONE;
}

DM_INLINE void dm_tally_add(dm_tally *to, const dm_tally *from)
{
    to->diss_normal += from->diss_normal;
    to->diss_tangential += from->diss_tangential;
    to->diss_friction += from->diss_friction;
    to->diss_rolling += from->diss_rolling;
    to->wall_work += from->wall_work;
    to->diss_plastic += from->diss_plastic;
    to->diss_rolling_viscous += from->diss_rolling_viscous;
    to->work_cohesion += from->work_cohesion;
    to->diss_local += from->diss_local;
}

/* History doubles of the tangential spring's displacement (a vector in 3D,
 * which changes sign when the pair's order flips; a scalar in 2D). */
DM_INLINE int dm_law_spring_size(int tangential, int dim)
{
    if (tangential == DEMILL_TANGENTIAL_SPRING || tangential == DEMILL_TANGENTIAL_MINDLIN)
        return dim == 3 ? 3 : 1;
    return 0;
}

/* History doubles of the tangential law: the displacement, and for Mindlin
 * the spring energy of the last step. Mindlin's k_t follows δ, so its spring
 * gains or loses energy without tangential work (in LIGGGHTS as here); the
 * energy tally books that change exactly, so that the balance closes. */
DM_INLINE int dm_law_tangential_size(int tangential, int dim)
{
    return dm_law_spring_size(tangential, dim) + (tangential == DEMILL_TANGENTIAL_MINDLIN);
}

/* Boundary corrections keep a collision second-order accurate in Δt where
 * the contact force switches on or off abruptly. Entry (any dashpot): the
 * dashpot force of the first sample in contact is weighted so that its
 * impulse equals the force's integral from the moment of contact, for an
 * onset growing as age^p (p = 0 for the linear dashpot's jump, 1/4 for the
 * Tsuji dashpot); the spring starts from zero and is left alone, so that
 * elastic collisions keep Verlet's energy behaviour. Which sample is the
 * first is known, not estimated: the pair was apart at the last step (its
 * touch flag is off); only the age within the step is estimated, from the
 * overlap, and held to [0, Δt]. (An estimate cannot decide it: the
 * refinement's later iterates carry the contact's own deceleration in
 * their end velocity, so that a contact that began just after the last
 * sample looked older than a step and lost its entry impulse, which made
 * e up to 1.7 % high at e = 0.5 and 10 % at e = 0.1.) Exit (linear
 * dashpot, whose force jumps where δ reaches 0): the impulse the last sample
 * in contact missed or added is applied when the contact is found to have
 * ended, from the last normal force and overlap kept in the history. */
DM_INLINE int dm_law_entry(int damping)
{
    return damping != DEMILL_DAMPING_NONE;
}

DM_INLINE int dm_law_exit(int normal, int damping)
{
    return normal == DEMILL_NORMAL_LINEAR && damping != DEMILL_DAMPING_NONE;
}

/* History doubles of the normal law's own state (plastic laws) and of the
 * rolling law (its spring). Cohesion keeps none: whether a bond holds is
 * whether its contact is on. */
DM_INLINE int dm_law_normal_size(int normal)
{
    return dm_plastic_hist_size(normal);
}

/* The rolling spring's (DEMILL_ROLLING_SPRING): its torque on a (a vector
 * in 3D, a scalar in 2D; it changes sign when the pair's order flips), then
 * its energy at the last step, which k_r (following k_n) may have changed
 * since, as Mindlin's. */
DM_INLINE int dm_law_rolling_size(int rolling, int dim)
{
    return rolling == DEMILL_ROLLING_SPRING ? (dim == 3 ? 3 : 1) + 1 : 0;
}

/* A contact's history, in this order: the tangential law's, then (for laws
 * with the exit correction) the last normal force and overlap, then the
 * normal law's and the rolling law's; where each starts, and the doubles in
 * all. */
DM_INLINE int dm_law_off_normal(int normal, int damping, int tangential, int dim)
{
    return dm_law_tangential_size(tangential, dim) + 2 * dm_law_exit(normal, damping);
}

DM_INLINE int dm_law_off_rolling(int normal, int damping, int tangential, int dim)
{
    return dm_law_off_normal(normal, damping, tangential, dim) + dm_law_normal_size(normal);
}

DM_INLINE int dm_law_hist_size(int normal, int damping, int tangential, int rolling, int dim)
{
    return dm_law_off_rolling(normal, damping, tangential, dim) +
           dm_law_rolling_size(rolling, dim);
}

/* The factor on history slot `slot` of a particle-particle contact of laws
 * l whose two particles trade places in storage order (a becomes b): -1 for
 * what turns with the pair, the 3D tangential spring (the 2D one is a
 * scalar along a tangent that turns with n) and the rolling spring's torque
 * on a; 1 for the rest. */
DM_INLINE double dm_law_flip(dm_laws l, int dim, int slot)
{
    const int r0 = dm_law_off_rolling(l.normal, l.damping, l.tangential, dim);
    const int spring = slot < dm_law_spring_size(l.tangential, dim) && dim == 3;
    const int torque = l.rolling == DEMILL_ROLLING_SPRING && slot >= r0 &&
                       slot < r0 + (dim == 3 ? 3 : 1);
    return spring || torque ? -1.0 : 1.0;
}

/* How far apart (as a negative overlap) a pair whose contact exists still
 * interacts (cohesion's reach), 0 for a law without cohesion: the JKR neck
 * breaks at δ_c, the liquid bridge at its rupture distance (cohesion.h).
 * Whether the contact exists is the pair's `on` flag: set when it touches
 * (δ > 0), kept while it is within this range, carried over neighbour
 * rebuilds, refinement iterates and checkpoints, so that cohesion needs no
 * history of its own. */
DM_INLINE double dm_law_range(int cohesion, const dm_pairparam *pp, double rstar)
{
    if (cohesion == DEMILL_COHESION_JKR)
        return dm_jkr_reach(rstar, pp->e_star, pp->adhesion);
    if (cohesion == DEMILL_COHESION_CAPILLARY)
        return dm_capillary_reach(pp->contact_angle, pp->liquid_volume);
    return 0.0;
}

/* D: dimension; NL, DL, TL, RL, CL: DEMILL_NORMAL_*, DEMILL_DAMPING_*,
 * DEMILL_TANGENTIAL_*, DEMILL_ROLLING_*, DEMILL_COHESION_* (compile-time
 * constants in the fast kernels, run-time values in the generic one).
 * delta: the overlap, negative for a cohesive contact across a gap. vc:
 * relative velocity at the contact point at the end of the step (drives
 * dashpots and friction); dc: the rate
 * of relative displacement over the step (drives the tangential spring).
 * wrel: ω_a - ω_b at the end of the step (the rolling laws' dashpots and
 * constant torque); wd: ω_a - ω_b over the step (the rolling spring); ir:
 * the pair's moment of inertia about the contact for rolling (the rolling
 * dashpot; wd and ir are read only by DEMILL_ROLLING_SPRING).
 * dt_hist: time the history advances by (0 for an evaluation that does not
 * advance time, which leaves the history as it was); the dissipation in o
 * is over the same interval. reach: how far past a force sample its impulse
 * reaches, in steps (1/2 for velocity Verlet, whose kicks apply a sample
 * half a step either side; 1 for symplectic Euler, which applies it over the
 * following step). first: nonzero if the pair was apart at the last step,
 * so that this sample is the contact's first (the entry correction).
 * hin: the contact's history (zeros for a new contact); hout receives its
 * new value (dm_law_hist_size doubles).
 *
 * The law has no branches that depend on the contact: every choice selects
 * between values computed for both outcomes, so that the kernels' loops
 * over contacts vectorise. Values computed for the outcome not taken may be
 * infinite or NaN; they are discarded. */
DM_INLINE void dm_law(const int D, const int NL, const int DL, const int TL, const int RL,
                      const int CL, const dm_pairparam *pp, const double *n, double delta,
                      const double *vc, const double *dc, const double *wrel, const double *wd,
                      double ir, double rstar, double mstar, double dt_hist, double reach,
                      int first, const double *hin, double *hout, dm_law_out *o)
{
    const int W = D == 3 ? 3 : 1;
    const int advance = dt_hist > 0.0;
    /* cohesion (docs/physics.md, Cohesion): a contact that exists may be
     * apart, δ < 0; the solids' laws see the overlap δ⁺ = max(δ, 0), and a
     * liquid bridge across a gap touches nothing solid */
    const double dsol = CL != DEMILL_COHESION_NONE && delta < 0.0 ? 0.0 : delta;
    const int solid = CL != DEMILL_COHESION_CAPILLARY || delta > 0.0;

    /* normal law (§2): elastic force and contact stiffness S = dF/dδ */
    double fel, stiff, sq = 0.0, plastic = 0.0;
    if (NL == DEMILL_NORMAL_LINEAR) {
        fel = pp->kn * dsol;
        stiff = pp->kn;
    } else if (dm_normal_plastic(NL)) {
        /* the elasto-plastic laws (contact/plastic.h): the force on the
         * current branch, its unloading slope for S, the step's plastic
         * work; the history δ_max (and the multi-path law's onset). They
         * branch on the contact's state: only the generic kernel runs them */
        const int HN = dm_law_off_normal(NL, DL, TL, D);
        dm_plastic_out po;
        dm_plastic_law(NL, pp, rstar, dsol, hin + HN, &po);
        fel = po.f;
        stiff = po.stiff;
        sq = sqrt(rstar * dsol);
        plastic = advance ? po.diss : 0.0;
        hout[HN] = advance ? po.dmax : hin[HN];
        if (NL == DEMILL_NORMAL_PLASTIC_PATHS)
            hout[HN + 1] = advance ? po.onset : hin[HN + 1];
    } else {
        sq = sqrt(rstar * dsol);
        fel = (4.0 / 3.0) * pp->e_star * sq * dsol;
        stiff = 2.0 * pp->e_star * sq;
    }
    /* the cohesive force: JKR's force of the contact radius a(δ) less the
     * Hertz force of δ⁺ (whose energy is stored as Hertz's), the contact's
     * stiffness then 2E* a and Mindlin's √(R* δ) its radius a (Thornton and
     * Yin 1991); or the bridge's attraction at the gap */
    double fcoh = 0.0;
    if (CL == DEMILL_COHESION_JKR) {
        const double a = dm_jkr_radius(delta, rstar, pp->e_star, pp->adhesion);
        double fh, fad;
        dm_jkr_force(a, rstar, pp->e_star, pp->adhesion, &fh, &fad);
        fcoh = fh + fad - fel;
        sq = a;
        stiff = 2.0 * pp->e_star * a;
    }
    if (CL == DEMILL_COHESION_CAPILLARY)
        fcoh = dm_capillary_force(dsol - delta, rstar, pp->surface_tension, pp->contact_angle,
                                  pp->liquid_volume);
    double vn = 0.0;
    for (int c = 0; c < D; c++)
        vn += vc[c] * n[c];

    /* normal damping (§3) */
    double cn = 0.0, root_ms = 0.0;
    if (DL == DEMILL_DAMPING_VISCOUS)
        cn = pp->cn;
    if (DL == DEMILL_DAMPING_RESTITUTION) {
        root_ms = sqrt(mstar * stiff);
        cn = pp->dcoef * root_ms;
    }
    if (CL == DEMILL_COHESION_CAPILLARY)
        cn = solid ? cn : 0.0;
    const int HT = dm_law_tangential_size(TL, D); /* exit slots: last force, overlap */
    double vnd = vn; /* the normal velocity the dashpot sees */
    if (dm_law_exit(NL, DL)) {
        /* unclamped, in a continuing contact: the contact's own force
         * change over the step, implicitly: v = v_pred + h (F_new -
         * F_last)/m*, F_new = k δ - c v, with h the part of the step the
         * integrator's second kick covers */
        const double hm = (1.0 - reach) * dt_hist / mstar;
        const double implicit = (vn + hm * (fel - hin[HT])) / (1.0 + hm * cn);
        vnd = (!pp->clamp & (hin[HT + 1] > 0.0)) ? implicit : vn;
    }
    double fn = fel - cn * vnd;
    fn = (pp->clamp & (fn < 0.0)) ? 0.0 : fn;
    const double fn_now = fn;
    if (dm_law_entry(DL)) {
        /* first sample of an approaching contact: its age from the overlap
         * under the current deceleration, at most a step, then the
         * onset-exponent weight (see above): the impulse from contact to
         * the end of the sample's window, ∫ (t/age)^p dt over
         * [0, age + reach Δt], divided by Δt */
        const double va = -vn, dec = fn / mstar;
        /* δ = va age + dec age²/2 (va the speed at the sample, after the
         * deceleration), solved for the root that is stable for dec -> 0 */
        const double est = 2.0 * delta / (va + sqrt(va * va + 2.0 * dec * delta));
        const double a = (est < dt_hist ? est : dt_hist) / dt_hist, e = a + reach; /* steps */
        const int lin = NL == DEMILL_NORMAL_LINEAR || NL == DEMILL_NORMAL_WALTON_BRAUN;
        const double w_d = lin ? e : 0.8 * e * sqrt(sqrt(e / a));
        const int young = advance & first & (va > 0.0);
        fn = young ? fel + w_d * (fn - fel) : fn;
    }
    if (dm_law_exit(NL, DL)) {
        hout[HT] = advance ? fn_now : hin[HT];
        hout[HT + 1] = advance ? dsol : hin[HT + 1];
    }
    /* the cohesive force joins after the clamp, which keeps the dashpot from
     * pulling but not the cohesion; the work done against it is booked
     * apart. Friction and rolling resistance are capped by the solids'
     * load: the contact force, or for JKR its sum with twice the pull-off
     * force (Thornton and Yin 1991), positive while the neck holds. */
    const double load =
        CL == DEMILL_COHESION_JKR ? fn + fcoh + 2.0 * dm_jkr_pull_off(rstar, pp->adhesion) : fn;
    o->fn = CL != DEMILL_COHESION_NONE ? fn + fcoh : fn;
    o->fel = fel;
    o->diss_normal = -(fn - fel) * vnd * dt_hist;
    o->diss_tangential = o->diss_friction = o->diss_rolling = 0.0;
    o->diss_plastic = plastic;
    o->diss_rolling_viscous = 0.0;
    o->work_cohesion = -fcoh * vn * dt_hist;

    /* tangential law (§4) */
    double vt[3], dt_rate[3], dn = 0.0;
    for (int c = 0; c < D; c++) {
        vt[c] = vc[c] - vn * n[c];
        dn += dc[c] * n[c];
        o->ft[c] = 0.0;
    }
    for (int c = 0; c < D; c++)
        dt_rate[c] = dc[c] - dn * n[c];
    const double cap = pp->mu * fabs(load);
    if (TL == DEMILL_TANGENTIAL_COULOMB) {
        double vt2 = 0.0;
        for (int c = 0; c < D; c++)
            vt2 += vt[c] * vt[c];
        if (DL != DEMILL_DAMPING_RESTITUTION)
            root_ms = sqrt(mstar * stiff);
        const double vtm = sqrt(vt2), fr = pp->coul_reg * root_ms * vtm;
        const int slip = fr > cap;
        const double fm = slip ? cap : fr, scale = vt2 > 0.0 ? fm / vtm : 0.0;
        for (int c = 0; c < D; c++)
            o->ft[c] = -scale * vt[c];
        const double lost = fm * vtm * dt_hist;
        o->diss_friction = slip ? lost : 0.0;
        o->diss_tangential = slip ? 0.0 : lost;
    }
    if (TL == DEMILL_TANGENTIAL_SPRING || TL == DEMILL_TANGENTIAL_MINDLIN) {
        double kt;
        if (TL == DEMILL_TANGENTIAL_SPRING) {
            kt = pp->kt;
        } else {
            if (NL == DEMILL_NORMAL_LINEAR)
                sq = sqrt(rstar * delta);
            kt = pp->g8 * sq;
        }
        double ct = 0.0;
        if (DL == DEMILL_DAMPING_VISCOUS)
            ct = pp->ct_factor * pp->cn;
        if (DL == DEMILL_DAMPING_RESTITUTION)
            ct = pp->ct_factor * pp->dcoef * sqrt(mstar * kt);
        /* spring displacement: accumulate the step's relative displacement,
         * rotated into the tangent plane by removing its normal part (as
         * LIGGGHTS does; in 2D it is a scalar along t = (-n_y, n_x), which
         * turns with the contact by construction). The spring and dashpot
         * force together is capped at μ|F_n|; on slip the spring is reset to
         * carry the capped force. Dissipation is the work the contact absorbs
         * (the force times the velocity at the sample, over the step: the
         * impulse window in which the integrator applies it) less the change
         * of spring energy, so that the spring itself books no loss. */
        const int NS = D == 3 ? 3 : 1;
        double xi[3], ds[3], ftr[3], vtl[3], e_old = 0.0;
        if (D == 3) {
            for (int c = 0; c < 3; c++) {
                ds[c] = dt_rate[c] * dt_hist;
                vtl[c] = vt[c];
            }
        } else {
            const double tx = -n[1], ty = n[0];
            ds[0] = (dt_rate[0] * tx + dt_rate[1] * ty) * dt_hist;
            vtl[0] = vt[0] * tx + vt[1] * ty;
        }
        double xn = 0.0;
        for (int c = 0; c < NS; c++) {
            e_old += hin[c] * hin[c];
            xi[c] = hin[c] + ds[c];
            if (D == 3)
                xn += xi[c] * n[c];
        }
        double f2 = 0.0;
        for (int c = 0; c < NS; c++) {
            if (D == 3)
                xi[c] -= xn * n[c];
            ftr[c] = -kt * xi[c] - ct * vtl[c];
            f2 += ftr[c] * ftr[c];
        }
        const int slip = f2 > cap * cap;
        const double scale = slip ? cap / sqrt(f2) : 1.0, ikt = 1.0 / kt;
        double work = 0.0, e_new = 0.0;
        for (int c = 0; c < NS; c++) {
            ftr[c] *= scale;
            xi[c] = slip ? -ftr[c] * ikt : xi[c];
            if (CL == DEMILL_COHESION_CAPILLARY) /* across a gap the spring lets go */
                xi[c] = solid ? xi[c] : 0.0;
            work -= ftr[c] * vtl[c] * dt_hist;
            e_new += xi[c] * xi[c];
            hout[c] = advance ? xi[c] : hin[c];
        }
        /* spring energies before and after the step; Mindlin's previous one
         * was stored, with the previous k_t */
        e_new *= 0.5 * kt;
        e_old = TL == DEMILL_TANGENTIAL_MINDLIN ? hin[NS] : 0.5 * kt * e_old;
        if (TL == DEMILL_TANGENTIAL_MINDLIN)
            hout[NS] = advance ? e_new : hin[NS];
        const double lost = work - (e_new - e_old);
        o->diss_friction = slip ? lost : 0.0;
        o->diss_tangential = slip ? 0.0 : lost;
        if (D == 3) {
            for (int c = 0; c < 3; c++)
                o->ft[c] = ftr[c];
        } else {
            o->ft[0] = -n[1] * ftr[0];
            o->ft[1] = n[0] * ftr[0];
        }
    }

    /* rolling resistance (§5): constant torque, regularised near ω_rel = 0 */
    for (int c = 0; c < W; c++)
        o->mr[c] = 0.0;
    if (RL == DEMILL_ROLLING_CONSTANT_TORQUE) {
        double w2 = 0.0;
        for (int c = 0; c < W; c++)
            w2 += wrel[c] * wrel[c];
        const double wm = sqrt(w2);
        const double mr = pp->roll_reg * rstar * rstar * sqrt(mstar * stiff) * wm;
        const double mcap = pp->mu_r * rstar * fabs(load);
        const double mm = mr > mcap ? mcap : mr, scale = w2 > 0.0 ? mm / wm : 0.0;
        for (int c = 0; c < W; c++)
            o->mr[c] = -scale * wrel[c];
        o->diss_rolling = mm * wm * dt_hist;
    }
    if (RL == DEMILL_ROLLING_SPRING) {
        /* the elastic-plastic spring-dashpot (type C of Ai et al. 2011): the
         * spring's torque on a, M_k, accumulates -k_r Δθ_r, Δθ_r the step's
         * relative rotation without its twist about n; the torque kept from
         * the last step is turned into the current tangent plane by removing
         * its normal part (as the tangential spring is). |M_k| is capped at
         * μ_r R* |F_n|; below the cap the dashpot adds -c_r ω_r, at the cap
         * (full mobilisation) it is off (Ai et al.'s f = 0). The spring's
         * loss, its work less the change of its energy |M_k|²/(2 k_r), is
         * rolling friction (it is the slip at the cap); the dashpot's is the
         * rolling viscous term. */
        const int HR = dm_law_off_rolling(NL, DL, TL, D);
        const double kr = pp->kr > 0.0 ? pp->kr : 2.25 * stiff * pp->mu_r * pp->mu_r * rstar * rstar;
        const double cr = pp->eta_r * 2.0 * sqrt(ir * kr), half_ikr = kr > 0.0 ? 0.5 / kr : 0.0;
        double twist = 0.0, twist_p = 0.0, mn = 0.0, mk[3], wt[3], m2 = 0.0;
        if (D == 3)
            for (int c = 0; c < 3; c++) {
                twist += wd[c] * n[c];
                twist_p += wrel[c] * n[c];
                mn += hin[HR + c] * n[c];
            }
        for (int c = 0; c < W; c++) {
            const double nc = D == 3 ? n[c] : 0.0;
            wt[c] = wrel[c] - twist_p * nc;
            mk[c] = hin[HR + c] - mn * nc - kr * (wd[c] - twist * nc) * dt_hist;
            m2 += mk[c] * mk[c];
        }
        const double mcap = pp->mu_r * rstar * fabs(fn);
        const int full = m2 > mcap * mcap;
        const double scale = full ? mcap / sqrt(m2) : 1.0, c_on = full ? 0.0 : cr;
        double work_k = 0.0, work_d = 0.0, e_new = 0.0;
        for (int c = 0; c < W; c++) {
            mk[c] *= scale;
            const double md = -c_on * wt[c];
            o->mr[c] = mk[c] + md;
            work_k -= mk[c] * wt[c] * dt_hist;
            work_d -= md * wt[c] * dt_hist;
            e_new += mk[c] * mk[c];
            hout[HR + c] = advance ? mk[c] : hin[HR + c];
        }
        e_new *= half_ikr;
        hout[HR + W] = advance ? e_new : hin[HR + W];
        o->diss_rolling = advance ? work_k - (e_new - hin[HR + W]) : 0.0;
        o->diss_rolling_viscous = work_d;
    }
}

/* Elastic energy stored in a contact of laws l with history hist: normal,
 * tangential and rolling springs. */
DM_INLINE void dm_law_stored(int dim, dm_laws l, const dm_pairparam *pp, double delta,
                             double rstar, const double *hist, double *e_normal,
                             double *e_tangential, double *e_rolling)
{
    const int NL = l.normal, TL = l.tangential;
    *e_rolling = l.rolling == DEMILL_ROLLING_SPRING
                     ? hist[dm_law_off_rolling(NL, l.damping, TL, dim) + (dim == 3 ? 3 : 1)]
                     : 0.0;
    if (NL == DEMILL_NORMAL_LINEAR) {
        *e_normal = 0.5 * pp->kn * delta * delta;
    } else if (dm_normal_plastic(NL)) { /* the current unloading curve's */
        dm_plastic_out po;
        dm_plastic_law(NL, pp, rstar, delta, hist + dm_law_off_normal(NL, l.damping, TL, dim), &po);
        *e_normal = po.stored;
    } else {
        *e_normal = 8.0 / 15.0 * pp->e_star * sqrt(rstar * delta) * delta * delta;
    }
    *e_tangential = 0.0;
    if (TL == DEMILL_TANGENTIAL_SPRING || TL == DEMILL_TANGENTIAL_MINDLIN) {
        double kt = TL == DEMILL_TANGENTIAL_SPRING ? pp->kt : pp->g8 * sqrt(rstar * delta);
        double x2 = 0.0;
        for (int c = 0; c < (dim == 3 ? 3 : 1); c++)
            x2 += hist[c] * hist[c];
        *e_tangential = 0.5 * kt * x2;
    }
}

#endif /* DM_LAW_H */
