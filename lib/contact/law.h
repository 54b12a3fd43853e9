/* law.h: the contact force law of one contact, composed of a normal law, a
 * damping law, a tangential law and a rolling law (PHYSICS.md §2-5).
 *
 * dm_law() is written once and specialised by the compiler: the kernels call
 * it with compile-time constant law choices and dimension, so a part that is
 * switched off costs nothing. Queries call it with run-time choices.
 *
 * Conventions: body a and body b (a particle or a wall), unit normal n from a
 * to b, overlap delta > 0, relative velocity of b with respect to a at the
 * contact point vc, relative angular velocity wrel = ω_a - ω_b. The law
 * returns the normal force magnitude fn on b along n, the tangential force
 * ft on b and the rolling torque mr on a; a receives -(fn n + ft) and b
 * receives -mr.
 */
#ifndef DM_LAW_H
#define DM_LAW_H

#include <math.h>

#include "../core/internal.h"

#define DM_INLINE static inline __attribute__((always_inline))

typedef struct dm_law_out {
    double fn;    /* normal force on b along n */
    double fel;   /* its elastic part */
    double ft[3]; /* tangential force on b (D components) */
    double mr[3]; /* rolling torque on a (W components) */
} dm_law_out;

DM_INLINE void dm_tally_add(dm_tally *to, const dm_tally *from)
{
    to->diss_normal += from->diss_normal;
    to->diss_tangential += from->diss_tangential;
    to->diss_friction += from->diss_friction;
    to->diss_rolling += from->diss_rolling;
    to->wall_work += from->wall_work;
}

/* History doubles of the tangential spring. */
DM_INLINE int dm_law_spring_size(int tangential, int dim)
{
    if (tangential == DEMILL_TANGENTIAL_SPRING || tangential == DEMILL_TANGENTIAL_MINDLIN)
        return dim == 3 ? 3 : 1;
    return 0;
}

/* Boundary corrections keep a collision second-order accurate in Δt where
 * the contact force switches on or off abruptly. Entry (any dashpot): the
 * first sample in contact is weighted so that its impulse equals the force's
 * integral from the moment of contact, for an onset growing as age^p (p = 0
 * for the linear dashpot's jump, 1/4 for the Tsuji dashpot, 1 and 3/2 for
 * the linear and Hertz springs). Exit (linear dashpot, whose force jumps
 * where δ reaches 0): the impulse the last sample in contact missed or added
 * is applied when the contact is found to have ended, from the last normal
 * force and overlap kept in the history. */
DM_INLINE int dm_law_entry(int damping)
{
    return damping != DEMILL_DAMPING_NONE;
}

DM_INLINE int dm_law_exit(int normal, int damping)
{
    return normal == DEMILL_NORMAL_LINEAR && damping != DEMILL_DAMPING_NONE;
}

/* History doubles per contact: the tangential spring, then (for laws with
 * the exit correction) the last normal force and overlap. */
DM_INLINE int dm_law_hist_size(int normal, int damping, int tangential, int dim)
{
    return dm_law_spring_size(tangential, dim) + 2 * dm_law_exit(normal, damping);
}

/* D: dimension; NL, DL, TL, RL: DEMILL_NORMAL_*, DEMILL_DAMPING_*,
 * DEMILL_TANGENTIAL_*, DEMILL_ROLLING_*. vc: relative velocity at the contact
 * point at the end of the step (drives dashpots and friction); dc: the rate
 * of relative displacement over the step (drives the tangential spring).
 * dt_hist: time the history advances by (0 for an evaluation that does not
 * advance time); the energy tally (when tally != 0) uses the same interval.
 * reach: how far past a force sample its impulse reaches, in steps (1/2
 * for velocity Verlet, whose kicks apply a sample half a step either side;
 * 1 for symplectic Euler, which applies it over the following step).
 * hist: the contact's history, updated in place. */
DM_INLINE void dm_law(const int D, const int NL, const int DL, const int TL, const int RL,
                      const dm_pairparam *pp, const double *n, double delta, const double *vc,
                      const double *dc, const double *wrel, double rstar, double mstar,
                      double dt_hist, double reach, const int tally, double *hist, dm_law_out *o,
                      dm_tally *t)
{
    const int W = D == 3 ? 3 : 1;

    /* normal law (§2): elastic force and contact stiffness S = dF/dδ */
    double fel, stiff, sq = 0.0;
    if (NL == DEMILL_NORMAL_LINEAR) {
        fel = pp->kn * delta;
        stiff = pp->kn;
    } else {
        sq = sqrt(rstar * delta);
        fel = (4.0 / 3.0) * pp->e_star * sq * delta;
        stiff = 2.0 * pp->e_star * sq;
    }
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
    double fn = fel - cn * vn;
    if (dm_law_entry(DL) && dt_hist > 0.0) {
        /* first sample of a new contact: age from the overlap under the
         * current deceleration, then onset-exponent weights (see above) */
        const double va = -vn;
        if (va > 0.0 && delta < va * dt_hist) {
            const double dec = fn / mstar;
            double age = delta / va;
            if (dec > 0.0)
                age = (sqrt(va * va + 2.0 * dec * delta) - va) / dec;
            if (age < dt_hist) {
                const double a = age / dt_hist, e = a + reach; /* in steps */
                double w_el, w_d;
                if (NL == DEMILL_NORMAL_LINEAR) {
                    w_el = e * e / (2.0 * a);
                    w_d = e;
                } else {
                    w_el = e * e * sqrt(e) / (2.5 * a * sqrt(a));
                    w_d = e * sqrt(sqrt(e)) / (1.25 * sqrt(sqrt(a)));
                }
                fn = w_el * fel + w_d * (fn - fel);
            }
        }
    }
    if (pp->clamp && fn < 0.0)
        fn = 0.0;
    if (dm_law_exit(NL, DL) && dt_hist > 0.0) {
        hist[dm_law_spring_size(TL, D)] = fn;
        hist[dm_law_spring_size(TL, D) + 1] = delta;
    }
    o->fn = fn;
    o->fel = fel;
    if (tally)
        t->diss_normal -= (fn - fel) * vn * dt_hist;

    /* tangential law (§4) */
    double vt[3], dt_rate[3], dn = 0.0;
    for (int c = 0; c < D; c++) {
        vt[c] = vc[c] - vn * n[c];
        dn += dc[c] * n[c];
        o->ft[c] = 0.0;
    }
    for (int c = 0; c < D; c++)
        dt_rate[c] = dc[c] - dn * n[c];
    const double cap = pp->mu * fabs(fn);
    if (TL == DEMILL_TANGENTIAL_COULOMB) {
        double vt2 = 0.0;
        for (int c = 0; c < D; c++)
            vt2 += vt[c] * vt[c];
        if (vt2 > 0.0) {
            if (DL != DEMILL_DAMPING_RESTITUTION)
                root_ms = sqrt(mstar * stiff);
            double vtm = sqrt(vt2), fm = pp->coul_reg * root_ms * vtm;
            int slip = fm > cap;
            if (slip)
                fm = cap;
            for (int c = 0; c < D; c++)
                o->ft[c] = -fm * vt[c] / vtm;
            if (tally) {
                if (slip)
                    t->diss_friction += fm * vtm * dt_hist;
                else
                    t->diss_tangential += fm * vtm * dt_hist;
            }
        }
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
        if (D == 3) {
            /* spring displacement: accumulate, then rotate into the tangent
             * plane by removing its normal part (as LIGGGHTS does) */
            double xi[3], xn = 0.0;
            for (int c = 0; c < 3; c++) {
                xi[c] = hist[c] + dt_rate[c] * dt_hist;
                xn += xi[c] * n[c];
            }
            double x2 = 0.0;
            for (int c = 0; c < 3; c++) {
                xi[c] -= xn * n[c];
                x2 += xi[c] * xi[c];
            }
            if (tally)
                t->diss_tangential += 0.5 * kt * xn * xn;
            double fs2 = kt * kt * x2;
            if (fs2 > cap * cap) {
                /* slip: the spring is shortened so that it carries the cap */
                double ratio = cap / sqrt(fs2);
                if (tally)
                    t->diss_friction += 0.5 * kt * x2 * (1.0 - ratio * ratio);
                for (int c = 0; c < 3; c++) {
                    xi[c] *= ratio;
                    o->ft[c] = -kt * xi[c];
                }
            } else {
                double vt2 = 0.0;
                for (int c = 0; c < 3; c++) {
                    o->ft[c] = -kt * xi[c] - ct * vt[c];
                    vt2 += vt[c] * vt[c];
                }
                if (tally)
                    t->diss_tangential += ct * vt2 * dt_hist;
            }
            for (int c = 0; c < 3; c++)
                hist[c] = xi[c];
        } else {
            /* 2D: the displacement is a scalar along t = (-n_y, n_x), which
             * turns with the contact by construction */
            double tx = -n[1], ty = n[0];
            double vts = vt[0] * tx + vt[1] * ty;
            double s = hist[0] + (dt_rate[0] * tx + dt_rate[1] * ty) * dt_hist, fs = -kt * s, ftm;
            if (fs * fs > cap * cap) {
                double ratio = cap / fabs(fs);
                if (tally)
                    t->diss_friction += 0.5 * kt * s * s * (1.0 - ratio * ratio);
                s *= ratio;
                ftm = -kt * s;
            } else {
                ftm = fs - ct * vts;
                if (tally)
                    t->diss_tangential += ct * vts * vts * dt_hist;
            }
            hist[0] = s;
            o->ft[0] = ftm * tx;
            o->ft[1] = ftm * ty;
        }
    }

    /* rolling resistance (§5): constant torque, regularised near ω_rel = 0 */
    for (int c = 0; c < W; c++)
        o->mr[c] = 0.0;
    if (RL == DEMILL_ROLLING_CONSTANT_TORQUE) {
        double w2 = 0.0;
        for (int c = 0; c < W; c++)
            w2 += wrel[c] * wrel[c];
        if (w2 > 0.0) {
            double wm = sqrt(w2);
            double mm = pp->roll_reg * rstar * rstar * sqrt(mstar * stiff) * wm;
            double mcap = pp->mu_r * rstar * fabs(fn);
            if (mm > mcap)
                mm = mcap;
            for (int c = 0; c < W; c++)
                o->mr[c] = -mm * wrel[c] / wm;
            if (tally)
                t->diss_rolling += mm * wm * dt_hist;
        }
    }
}

/* Elastic energy stored in a contact: normal spring and tangential spring. */
DM_INLINE void dm_law_stored(int dim, int NL, int TL, const dm_pairparam *pp, double delta,
                             double rstar, const double *hist, double *e_normal,
                             double *e_tangential)
{
    if (NL == DEMILL_NORMAL_LINEAR)
        *e_normal = 0.5 * pp->kn * delta * delta;
    else
        *e_normal = 8.0 / 15.0 * pp->e_star * sqrt(rstar * delta) * delta * delta;
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
