/* kernels.h: the contact loops, specialised per dimension and contact model.
 *
 * A kernel is one loop over a bucket of candidate pairs that share a
 * combination of laws. kernels2.c and kernels3.c instantiate every
 * combination for their dimension through DM_FOR_EACH_KERNEL; forces.c picks
 * the kernel of each bucket, so the loops contain no branch on options and
 * no indirect call.
 */
#ifndef DM_KERNELS_H
#define DM_KERNELS_H

#include "law.h"

typedef struct dm_kernel_args {
    demill_world *w;
    dm_bucket *b;
    uint32_t geom_offset; /* walls: index of the bucket's first pair in w->wg */
    const double *vp, *wp; /* velocities the dashpots see (see dm_law) */
    double dt_hist, reach;
    int tally;
    dm_tally *t;
    uint32_t contacts; /* out: pairs in contact */
} dm_kernel_args;

typedef void (*dm_kernel_fn)(dm_kernel_args *a);

/* Kernel order: normal (linear, Hertz) outermost, then damping (3),
 * tangential (4), rolling (2); see dm_kernel_index(). */
#define DM_FOR_RL(X, D, NL, DL, TL) X(D, NL, DL, TL, 0) X(D, NL, DL, TL, 1)
#define DM_FOR_TL(X, D, NL, DL)                                                                   \
    DM_FOR_RL(X, D, NL, DL, 0) DM_FOR_RL(X, D, NL, DL, 1) DM_FOR_RL(X, D, NL, DL, 2)             \
        DM_FOR_RL(X, D, NL, DL, 3)
#define DM_FOR_DL(X, D, NL) DM_FOR_TL(X, D, NL, 0) DM_FOR_TL(X, D, NL, 1) DM_FOR_TL(X, D, NL, 2)
#define DM_FOR_EACH_KERNEL(X, D) DM_FOR_DL(X, D, 1) DM_FOR_DL(X, D, 2)

/* 2D: the z component of a × b, and ω ẑ × n. */
DM_INLINE void dm_spin_cross_n(const int D, const double *om, const double *n, double *out)
{
    if (D == 3) {
        out[0] = om[1] * n[2] - om[2] * n[1];
        out[1] = om[2] * n[0] - om[0] * n[2];
        out[2] = om[0] * n[1] - om[1] * n[0];
    } else {
        out[0] = -om[0] * n[1];
        out[1] = om[0] * n[0];
    }
}

/* n × f: 3 components in 3D, the z component in 2D. */
DM_INLINE void dm_n_cross(const int D, const double *n, const double *f, double *out)
{
    if (D == 3) {
        out[0] = n[1] * f[2] - n[2] * f[1];
        out[1] = n[2] * f[0] - n[0] * f[2];
        out[2] = n[0] * f[1] - n[1] * f[0];
    } else {
        out[0] = n[0] * f[1] - n[1] * f[0];
    }
}

/* Kinematics of one contact: normal, overlap, lever arms and the relative
 * motion at the contact point. */
typedef struct dm_kin {
    double n[3], delta, ai, aj, vc[3], dc[3], wrel[3], rstar, mstar;
} dm_kin;

/* Relative velocity of b with respect to a at the contact point, from linear
 * velocities va, vb and the lever-arm-weighted spin sum s = a_a ω_a + a_b ω_b. */
DM_INLINE void dm_contact_velocity(const int D, const int SPIN, const double *va,
                                   const double *vb, const double *s, const double *n,
                                   double *out)
{
    for (int c = 0; c < D; c++)
        out[c] = vb[c] - va[c];
    if (SPIN) {
        double sw[3];
        dm_spin_cross_n(D, s, n, sw);
        for (int c = 0; c < D; c++)
            out[c] -= sw[c];
    }
}

/* Particle-particle kinematics; returns 0 when i and j do not touch, with
 * *r2 the squared distance. SPIN: include rotation in the contact velocities;
 * ROLL: compute wrel. vp, wp: the velocities the dashpots see. */
DM_INLINE int dm_pp_kin(const int D, const int SPIN, const int ROLL, const dm_particles *P,
                        const double *vp, const double *wp, uint32_t i, uint32_t j, dm_kin *k,
                        double *r2out)
{
    const int W = D == 3 ? 3 : 1;
    const double *x = P->x, *v = P->v, *om = P->w, *rad = P->r;
    double d[3], r2 = 0.0;
    for (int c = 0; c < D; c++) {
        d[c] = x[D * j + c] - x[D * i + c];
        r2 += d[c] * d[c];
    }
    const double sum = rad[i] + rad[j];
    *r2out = r2;
    if (r2 >= sum * sum)
        return 0;
    const double dist = sqrt(r2);
    if (dist > 0.0) {
        const double inv = 1.0 / dist;
        for (int c = 0; c < D; c++)
            k->n[c] = d[c] * inv;
    } else {
        for (int c = 0; c < D; c++)
            k->n[c] = c == 0;
    }
    k->delta = sum - dist;
    k->ai = rad[i] - 0.5 * k->delta;
    k->aj = rad[j] - 0.5 * k->delta;
    double s[3] = {0.0, 0.0, 0.0}, sp[3] = {0.0, 0.0, 0.0};
    if (SPIN)
        for (int c = 0; c < W; c++) {
            s[c] = k->ai * om[W * i + c] + k->aj * om[W * j + c];
            sp[c] = k->ai * wp[W * i + c] + k->aj * wp[W * j + c];
        }
    dm_contact_velocity(D, SPIN, v + D * i, v + D * j, s, k->n, k->dc);
    dm_contact_velocity(D, SPIN, vp + D * i, vp + D * j, sp, k->n, k->vc);
    for (int c = 0; c < 3; c++)
        k->wrel[c] = 0.0;
    if (ROLL)
        for (int c = 0; c < W; c++)
            k->wrel[c] = wp[W * i + c] - wp[W * j + c];
    k->rstar = rad[i] * rad[j] / sum;
    k->mstar = P->m[i] * P->m[j] / (P->m[i] + P->m[j]);
    return 1;
}

/* Particle-wall kinematics from the candidate's geometry gk; returns 0 when
 * the particle does not touch the wall. */
DM_INLINE int dm_pw_kin(const int D, const int SPIN, const int ROLL, const dm_particles *P,
                        const double *vp, const double *wp, const dm_wgeom *g, uint32_t gk,
                        uint32_t i, const dm_wall *wall, dm_kin *k)
{
    const int W = D == 3 ? 3 : 1;
    const double *om = P->w;
    k->delta = g->delta[gk];
    if (k->delta <= 0.0)
        return 0;
    for (int c = 0; c < D; c++)
        k->n[c] = g->nrm[D * gk + c];
    k->ai = P->r[i] - 0.5 * k->delta;
    k->aj = 0.0;
    double s[3] = {0.0, 0.0, 0.0}, sp[3] = {0.0, 0.0, 0.0};
    if (SPIN)
        for (int c = 0; c < W; c++) {
            s[c] = k->ai * om[W * i + c];
            sp[c] = k->ai * wp[W * i + c];
        }
    dm_contact_velocity(D, SPIN, P->v + D * i, g->vw + D * gk, s, k->n, k->dc);
    dm_contact_velocity(D, SPIN, vp + D * i, g->vw + D * gk, sp, k->n, k->vc);
    for (int c = 0; c < 3; c++)
        k->wrel[c] = 0.0;
    if (ROLL)
        for (int c = 0; c < W; c++)
            k->wrel[c] = wp[W * i + c] - wall->omega[D == 3 ? c : 2];
    k->rstar = P->r[i];
    k->mstar = P->m[i];
    return 1;
}

/* A contact with the exit correction found apart (dm_law_exit): returns the
 * force along n on b that applies the impulse its last sample in contact
 * missed or added, the exit time found by interpolating the overlap, and
 * forgets the contact. hb: the two boundary slots of its history. */
DM_INLINE double dm_exit_force(double *hb, double delta_now, double reach,
                               const dm_pairparam *pp)
{
    const double d_last = hb[1];
    /* what jumps to zero where δ reaches 0: the dashpot part of the last
     * force, never pulling when the normal force is clamped */
    double jump = hb[0] - pp->kn * d_last;
    if (pp->clamp && jump < 0.0)
        jump = 0.0;
    hb[0] = hb[1] = 0.0;
    return jump * (d_last / (d_last - delta_now) - reach);
}

/* Particle-particle loop. */
DM_INLINE void dm_pp_loop(const int D, const int NL, const int DL, const int TL, const int RL,
                          dm_kernel_args *a)
{
    const int W = D == 3 ? 3 : 1;
    const int HSL = dm_law_hist_size(NL, DL, TL, D), HSP = dm_law_tangential_size(TL, D);
    const int EXIT = dm_law_exit(NL, DL);
    const int SPIN = TL != DEMILL_TANGENTIAL_NONE;
    demill_world *w = a->w;
    const dm_particles *P = &w->p;
    const dm_bucket *b = a->b;
    const int EV = w->events, HS = b->hs; /* HS = HSL + EV: the event slot is last */
    double *restrict f = w->p.f, *restrict tq = w->p.t;
    const double *vp = a->vp, *wp = a->wp;
    const uint16_t *restrict mat = w->p.mat;
    const dm_pairparam *tab = w->ptab;
    const uint32_t nm = w->nmat_tab, np = b->n;
    const uint32_t *restrict bi = b->i, *restrict bj = b->j;
    double *restrict hist = b->hist;
    const double dt_hist = a->dt_hist, reach = a->reach;
    const int tally = a->tally;
    dm_tally t = {0};
    uint32_t contacts = 0;

    for (uint32_t k = 0; k < np; k++) {
        const uint32_t i = bi[k], j = bj[k];
        double *h = hist + (size_t)HS * k;
        dm_kin q;
        double r2;
        if (!dm_pp_kin(D, SPIN, RL, P, vp, wp, i, j, &q, &r2)) {
            if (EXIT) {
                if (dt_hist == 0.0)
                    continue; /* keep the history for the next real step */
                if (h[HSP + 1] > 0.0) {
                    const double dist = sqrt(r2);
                    const double fc = dm_exit_force(h + HSP, P->r[i] + P->r[j] - dist, reach,
                                                    &tab[mat[i] * nm + mat[j]]);
                    double vn = 0.0;
                    for (int c = 0; c < D; c++) {
                        const double nc = (P->x[D * j + c] - P->x[D * i + c]) / dist;
                        f[D * i + c] -= fc * nc;
                        f[D * j + c] += fc * nc;
                        vn += (vp[D * j + c] - vp[D * i + c]) * nc;
                    }
                    if (tally) {
                        t.diss_normal -= fc * vn * dt_hist;
                        if (EV)
                            h[HSL] -= fc * vn * dt_hist;
                    }
                }
            }
            if (EV && h[HSL] > 0.0)
                dm_spectrum_record(w, i, j, -1, h[HSL]);
            for (int c = 0; c < HS; c++)
                h[c] = 0.0;
            continue;
        }
        contacts++;
        const dm_pairparam *pp = &tab[mat[i] * nm + mat[j]];
        dm_law_out o;
        dm_tally lt = {0};
        dm_law(D, NL, DL, TL, RL, pp, q.n, q.delta, q.vc, q.dc, q.wrel, q.rstar, q.mstar, dt_hist,
               reach, tally, h, &o, &lt);
        if (tally) {
            dm_tally_add(&t, &lt);
            if (EV)
                h[HSL] += dm_tally_dissipated(&lt);
        }
        for (int c = 0; c < D; c++) {
            const double fc = o.fn * q.n[c] + o.ft[c];
            f[D * i + c] -= fc;
            f[D * j + c] += fc;
        }
        if (SPIN) {
            double nf[3];
            dm_n_cross(D, q.n, o.ft, nf);
            for (int c = 0; c < W; c++) {
                tq[W * i + c] -= q.ai * nf[c];
                tq[W * j + c] -= q.aj * nf[c];
            }
        }
        if (RL)
            for (int c = 0; c < W; c++) {
                tq[W * i + c] += o.mr[c];
                tq[W * j + c] -= o.mr[c];
            }
    }
    a->contacts = contacts;
    if (tally)
        dm_tally_add(a->t, &t);
}

/* Particle-wall loop over the geometry computed by dm_wgeom_update(). */
DM_INLINE void dm_pw_loop(const int D, const int NL, const int DL, const int TL, const int RL,
                          dm_kernel_args *a)
{
    const int W = D == 3 ? 3 : 1;
    const int HSL = dm_law_hist_size(NL, DL, TL, D), HSP = dm_law_tangential_size(TL, D);
    const int EXIT = dm_law_exit(NL, DL);
    const int SPIN = TL != DEMILL_TANGENTIAL_NONE;
    demill_world *w = a->w;
    const dm_particles *P = &w->p;
    const dm_bucket *b = a->b;
    const int EV = w->events, HS = b->hs; /* HS = HSL + EV: the event slot is last */
    double *restrict f = w->p.f, *restrict tq = w->p.t;
    const double *vp = a->vp, *wp = a->wp;
    const uint16_t *restrict mat = w->p.mat;
    const dm_pairparam *tab = w->ptab;
    const uint32_t nm = w->nmat_tab, np = b->n, g0 = a->geom_offset;
    const dm_wgeom *g = &w->wg;
    const double dt_hist = a->dt_hist, reach = a->reach;
    const int tally = a->tally;
    dm_tally t = {0};
    uint32_t contacts = 0;

    for (uint32_t k = 0; k < np; k++) {
        const uint32_t i = b->i[k], gk = g0 + k;
        double *h = b->hist + (size_t)HS * k;
        dm_wall *wall = &w->walls[b->j[k]];
        dm_kin q;
        if (!dm_pw_kin(D, SPIN, RL, P, vp, wp, g, gk, i, wall, &q)) {
            if (EXIT) {
                if (dt_hist == 0.0)
                    continue; /* keep the history for the next real step */
                if (h[HSP + 1] > 0.0) {
                    const double fc = dm_exit_force(h + HSP, g->delta[gk], reach,
                                                    &tab[mat[i] * nm + wall->material]);
                    double absorbed = 0.0, delivered = 0.0;
                    for (int c = 0; c < D; c++) {
                        const double fw = fc * g->nrm[D * gk + c];
                        f[D * i + c] -= fw;
                        wall->force[c] += fw;
                        absorbed += fw * (vp[D * i + c] - g->vw[D * gk + c]);
                        delivered -= fw * g->vw[D * gk + c];
                    }
                    if (tally) {
                        t.diss_normal += absorbed * dt_hist;
                        t.wall_work += delivered * dt_hist;
                        wall->dissipated += absorbed * dt_hist;
                        if (EV)
                            h[HSL] += absorbed * dt_hist;
                    }
                }
            }
            if (EV && h[HSL] > 0.0 && wall->drum_part)
                dm_spectrum_record(w, i, 0,
                                   wall->drum_part == DM_PART_LIFTER ? DEMILL_SPECTRUM_LIFTER
                                                                     : DEMILL_SPECTRUM_SHELL,
                                   h[HSL]);
            for (int c = 0; c < HS; c++)
                h[c] = 0.0;
            continue;
        }
        contacts++;
        const dm_pairparam *pp = &tab[mat[i] * nm + wall->material];
        dm_law_out o;
        dm_tally lt = {0};
        dm_law(D, NL, DL, TL, RL, pp, q.n, q.delta, q.vc, q.dc, q.wrel, q.rstar, q.mstar, dt_hist,
               reach, tally, h, &o, &lt);
        if (tally) {
            const double lost = dm_tally_dissipated(&lt);
            dm_tally_add(&t, &lt);
            wall->dissipated += lost;
            if (EV)
                h[HSL] += lost;
        }
        double fw[3] = {0.0, 0.0, 0.0}, arm[3] = {0.0, 0.0, 0.0};
        for (int c = 0; c < D; c++) {
            fw[c] = o.fn * q.n[c] + o.ft[c];
            f[D * i + c] -= fw[c];
            wall->force[c] += fw[c];
            arm[c] = g->cp[D * gk + c] - wall->c[c];
        }
        /* torque on the wall about its centre: arm × F, minus the rolling
         * torque on the particle */
        wall->torque[0] += arm[1] * fw[2] - arm[2] * fw[1];
        wall->torque[1] += arm[2] * fw[0] - arm[0] * fw[2];
        wall->torque[2] += arm[0] * fw[1] - arm[1] * fw[0];
        if (SPIN) {
            double nf[3];
            dm_n_cross(D, q.n, o.ft, nf);
            for (int c = 0; c < W; c++)
                tq[W * i + c] -= q.ai * nf[c];
        }
        if (RL)
            for (int c = 0; c < W; c++) {
                tq[W * i + c] += o.mr[c];
                wall->torque[D == 3 ? c : 2] -= o.mr[c];
            }
        if (tally) {
            /* power the wall delivers: -F·v_wall(contact) + M_r·Ω_wall */
            double pw = 0.0;
            for (int c = 0; c < D; c++)
                pw -= fw[c] * g->vw[D * gk + c];
            if (RL)
                for (int c = 0; c < W; c++)
                    pw += o.mr[c] * wall->omega[D == 3 ? c : 2];
            t.wall_work += pw * dt_hist;
        }
    }
    a->contacts = contacts;
    if (tally)
        dm_tally_add(a->t, &t);
}

#define DM_DEFINE_KERNELS(D, NL, DL, TL, RL)                                                     \
    static void dm_pp_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)                          \
    {                                                                                             \
        dm_pp_loop(D, NL, DL, TL, RL, a);                                                         \
    }                                                                                             \
    static void dm_pw_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)                          \
    {                                                                                             \
        dm_pw_loop(D, NL, DL, TL, RL, a);                                                         \
    }
#define DM_PP_ENTRY(D, NL, DL, TL, RL) dm_pp_##D##_##NL##_##DL##_##TL##_##RL,
#define DM_PW_ENTRY(D, NL, DL, TL, RL) dm_pw_##D##_##NL##_##DL##_##TL##_##RL,

extern const dm_kernel_fn dm_pp_kernels2[DM_KERNELS], dm_pw_kernels2[DM_KERNELS];
extern const dm_kernel_fn dm_pp_kernels3[DM_KERNELS], dm_pw_kernels3[DM_KERNELS];

#endif /* DM_KERNELS_H */
