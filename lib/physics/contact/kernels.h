/* kernels.h: the contact loops, specialised per dimension and contact model.
 *
 * A kernel works through one chunk of a bucket of candidate pairs that share
 * a combination of laws. The files of kernels/ instantiate them, a slice of
 * 8 combinations each (DM_KERNEL_SLICE: one dimension, normal law and
 * damping law), so that the slices compile in parallel; kernels.c gathers
 * the slices into the tables through which forces.c picks the kernel of
 * each chunk (dm_kernel()), so the loops contain no branch on options and
 * no indirect call. The kinematics loops, which depend on few of the
 * choices, are compiled once for all kernels, in kinematics.c.
 *
 * Those are the fast kernels (DM_FAST_KERNELS). Every other combination of
 * laws (an elasto-plastic normal law, the rolling spring, cohesion) runs
 * the generic kernel of its dimension (kernels/generic.c): the same passes
 * and the same dm_law(), with the bucket's laws as run-time values, so that
 * the laws a scene does not use cost the fast kernels nothing.
 */
#ifndef DM_KERNELS_H
#define DM_KERNELS_H

#include "physics/contact/contact.h"
#include "physics/contact/law.h"
#include "physics/geometry/geometry.h"

typedef struct dm_kernel_args {
    demill_world *w;
    dm_bucket *b;
    uint32_t k0;           /* the chunk: candidates k0 .. k0 + DM_CHUNK - 1 of b */
    uint32_t geom_offset;  /* walls: index of the bucket's first pair in w->wg */
    const double *vp, *wp; /* velocities the dashpots see (see dm_law) */
    double dt_hist, reach;
    int tally;
    int direct;            /* 1: also add the results to the particles' sums; 0: those
                              of the particles p for which dm_direct() says so */
    const uint32_t *lo;    /* w->res.lo, and the range that runs the chunk: */
    uint32_t begin, end;   /* particles begin .. end - 1 (forces.c) */
    dm_tally t;            /* out: the chunk's dissipation */
    uint32_t contacts;     /* out: pairs in contact */
    uint32_t listed;       /* out: pairs with a result, listed in w->res.list */
} dm_kernel_args;

typedef void (*dm_kernel_fn)(dm_kernel_args *a);

/* Kernel order (dm_kernel_index()): normal (linear, Hertz) outermost, then
 * damping (3), tangential (4), rolling (2). A slice is the 8 kernels of one
 * dimension, normal law and damping law, listed by DM_FOR_TL; a dimension's
 * 6 slices are listed by DM_FOR_EACH_SLICE. */
#define DM_FOR_RL(X, D, NL, DL, TL) X(D, NL, DL, TL, 0) X(D, NL, DL, TL, 1)
#define DM_FOR_TL(X, D, NL, DL)                                                                   \
    DM_FOR_RL(X, D, NL, DL, 0) DM_FOR_RL(X, D, NL, DL, 1) DM_FOR_RL(X, D, NL, DL, 2)             \
        DM_FOR_RL(X, D, NL, DL, 3)
#define DM_FOR_DL(X, D, NL) X(D, NL, 0) X(D, NL, 1) X(D, NL, 2)
#define DM_FOR_EACH_SLICE(X, D) DM_FOR_DL(X, D, 1) DM_FOR_DL(X, D, 2)
#define DM_SLICE_KERNELS 8
#define DM_SLICES (DM_FAST_KERNELS / DM_SLICE_KERNELS)

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

/* Kinematics of one contact: normal, overlap, lever arms and the relative
 * motion at the contact point. */
typedef struct dm_kin {
    double n[3], delta, ai, aj, vc[3], dc[3], wrel[3], rstar, mstar;
    double wd[3], ir; /* the rolling spring's: ω_a - ω_b over the step, I_r */
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

/* Whether two particles whose radii sum to sum and whose centres are
 * √r2 apart touch: see dm_pp_touch(). */
DM_INLINE int dm_touches(double sum, double r2)
{
    return sum - sqrt(r2) > 0.0;
}

/* Whether particles i and j touch: whether their overlap, as dm_pp_kin()
 * computes it, r_i + r_j - √|d|², is > 0, as the law requires (law.h) and
 * as a wall's is (dm_pw_chunk). The test on the squares, |d|² < (r_i + r_j)²,
 * also passes the pairs whose distance rounds to r_i + r_j, an overlap of
 * exactly 0, at which the first sample's entry weight is infinite against a
 * dashpot force of 0: NaN. d receives x_j - x_i, *r2 its square. */
DM_INLINE int dm_pp_touch(const int D, const dm_particles *P, uint32_t i, uint32_t j, double *d,
                          double *r2)
{
    const double *x = P->x;
    double s = 0.0;
    for (int c = 0; c < D; c++) {
        d[c] = x[D * j + c] - x[D * i + c];
        s += d[c] * d[c];
    }
    *r2 = s;
    return dm_touches(P->r[i] + P->r[j], s);
}

/* Particle-particle kinematics of a touching pair, from d = x_j - x_i and
 * its square r2. SPIN: include rotation in the contact velocities; ROLL:
 * the rolling law, whose kinematics are computed (wrel for any, wd and ir
 * for the rolling spring). vp, wp: the velocities the dashpots see. */
DM_INLINE void dm_pp_kin(const int D, const int SPIN, const int ROLL, const dm_particles *P,
                         const double *vp, const double *wp, uint32_t i, uint32_t j,
                         const double *d, double r2, dm_kin *k)
{
    const int W = D == 3 ? 3 : 1;
    const double *v = P->v, *om = P->w, *rad = P->r;
    const double dist = sqrt(r2), inv = 1.0 / dist;
    for (int c = 0; c < D; c++) /* coincident centres: any normal will do */
        k->n[c] = dist > 0.0 ? d[c] * inv : c == 0;
    const double sum = rad[i] + rad[j];
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
    if (ROLL == DEMILL_ROLLING_SPRING) {
        /* 1/I_r = 1/(I_i + m_i r_i²) + 1/(I_j + m_j r_j²), each term
         * 1/I / (1 + m r² / I): 0 for a fixed particle */
        const double *ii = P->iinv, *m = P->m;
        const double si = ii[i] / (1.0 + m[i] * rad[i] * rad[i] * ii[i]);
        const double sj = ii[j] / (1.0 + m[j] * rad[j] * rad[j] * ii[j]);
        for (int c = 0; c < W; c++)
            k->wd[c] = om[W * i + c] - om[W * j + c];
        k->ir = si + sj > 0.0 ? 1.0 / (si + sj) : 0.0;
    }
    k->rstar = rad[i] * rad[j] / sum;
    /* 1/m* = 1/m_i + 1/m_j: against a fixed particle (1/m = 0) the moving
     * one's mass, without a branch */
    k->mstar = 1.0 / (P->im[i] + P->im[j]);
}

/* Particle-wall kinematics of a touching candidate, from its geometry gk. */
DM_INLINE void dm_pw_kin(const int D, const int SPIN, const int ROLL, const dm_particles *P,
                         const double *vp, const double *wp, const dm_wgeom *g, uint32_t gk,
                         uint32_t i, const dm_wall *wall, dm_kin *k)
{
    const int W = D == 3 ? 3 : 1;
    const double *om = P->w;
    k->delta = g->delta[gk];
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
    if (ROLL == DEMILL_ROLLING_SPRING) { /* I_r = I_i + m_i r_i² (see dm_pp_kin) */
        const double ii = P->iinv[i], mr2 = P->m[i] * P->r[i] * P->r[i];
        for (int c = 0; c < W; c++)
            k->wd[c] = om[W * i + c] - wall->omega[D == 3 ? c : 2];
        k->ir = ii > 0.0 ? (1.0 + mr2 * ii) / ii : 0.0;
    }
    k->rstar = P->r[i];
    k->mstar = P->m[i];
}

/* A contact with the exit correction found apart (dm_law_exit): returns the
 * force along n on b that applies the impulse its last sample in contact
 * missed or added, the exit time found by interpolating the overlap. hb:
 * the two boundary slots of its history. */
DM_INLINE double dm_exit_force(const double *hb, double delta_now, double reach,
                               const dm_pairparam *pp)
{
    const double d_last = hb[1];
    /* what jumps to zero where δ reaches 0: the dashpot part of the last
     * force, never pulling when the normal force is clamped */
    double jump = hb[0] - pp->kn * d_last;
    if (pp->clamp && jump < 0.0)
        jump = 0.0;
    return jump * (d_last / (d_last - delta_now) - reach);
}

/* A kernel works through a chunk of DM_CHUNK candidates in four passes:
 * the narrow phase finds the pairs that touch (and ends the contacts that
 * came apart); the kinematics of the touching pairs are gathered into the
 * chunk; the law, the same arithmetic for every touching pair with no
 * branch on the pair, runs as a vectorised loop, the same loop for
 * particle-particle and particle-wall pairs (which halves the code the
 * kernels compile to); the results, each pair's force and torques, are then
 * stored by pair id (dm_results) with the new histories, and summed per
 * particle afterwards. */
#define DM_CHUNK 128
#define DM_LANES 8 /* the law's loop runs over a multiple of this many pairs */
/* Energy terms of a pair per step: normal viscous, tangential viscous,
 * sliding friction, rolling friction, then the extended laws' plastic work,
 * rolling dashpot and work against cohesion (dm_law_out), which the fast
 * kernels do not touch. */
#define DM_DISS 7
#define DM_DISS_FAST 4

typedef struct dm_chunk {
    uint32_t touch[DM_CHUNK];          /* whether each candidate touches */
    uint32_t k[DM_CHUNK];              /* the touching pairs, indices in the bucket */
    uint32_t pp[DM_CHUNK];             /* and their entries in the pair table */
    uint32_t first[DM_CHUNK];          /* 1 if the pair was apart at the last step */
    double f[3][DM_CHUNK];             /* force on b */
    double ta[3][DM_CHUNK], tb[3][DM_CHUNK]; /* torques on a and b (W components) */
    double diss[DM_DISS][DM_CHUNK];    /* dissipation by mechanism (DM_DISS) */
    double h[DM_MAX_HIST][DM_CHUNK];   /* histories, then their new values */
    /* the kinematics of the touching pairs (dm_kin, by component) */
    double n[3][DM_CHUNK], delta[DM_CHUNK], ai[DM_CHUNK], aj[DM_CHUNK];
    double vc[3][DM_CHUNK], dc[3][DM_CHUNK], wrel[3][DM_CHUNK], rstar[DM_CHUNK], mstar[DM_CHUNK];
    double wd[3][DM_CHUNK], ir[DM_CHUNK]; /* the rolling spring's */
} dm_chunk;

/* Pair s's kinematics q into the chunk (ROLL: the rolling law, with wrel for
 * any and wd, ir for the rolling spring), and back. */
DM_INLINE void dm_kin_put(const int D, const int ROLL, dm_chunk *ch, uint32_t s, const dm_kin *q)
{
    for (int c = 0; c < D; c++) {
        ch->n[c][s] = q->n[c];
        ch->vc[c][s] = q->vc[c];
        ch->dc[c][s] = q->dc[c];
    }
    for (int c = 0; c < (ROLL ? (D == 3 ? 3 : 1) : 0); c++)
        ch->wrel[c][s] = q->wrel[c];
    for (int c = 0; c < (ROLL == DEMILL_ROLLING_SPRING ? (D == 3 ? 3 : 1) : 0); c++)
        ch->wd[c][s] = q->wd[c];
    if (ROLL == DEMILL_ROLLING_SPRING)
        ch->ir[s] = q->ir;
    ch->delta[s] = q->delta;
    ch->ai[s] = q->ai;
    ch->aj[s] = q->aj;
    ch->rstar[s] = q->rstar;
    ch->mstar[s] = q->mstar;
}

DM_INLINE void dm_kin_get(const int D, const int ROLL, const dm_chunk *ch, uint32_t s, dm_kin *q)
{
    for (int c = 0; c < D; c++) {
        q->n[c] = ch->n[c][s];
        q->vc[c] = ch->vc[c][s];
        q->dc[c] = ch->dc[c][s];
    }
    for (int c = 0; c < 3; c++)
        q->wrel[c] = 0.0;
    for (int c = 0; c < (ROLL ? (D == 3 ? 3 : 1) : 0); c++)
        q->wrel[c] = ch->wrel[c][s];
    for (int c = 0; c < (ROLL == DEMILL_ROLLING_SPRING ? (D == 3 ? 3 : 1) : 0); c++)
        q->wd[c] = ch->wd[c][s];
    q->ir = ROLL == DEMILL_ROLLING_SPRING ? ch->ir[s] : 0.0;
    q->delta = ch->delta[s];
    q->ai = ch->ai[s];
    q->aj = ch->aj[s];
    q->rstar = ch->rstar[s];
    q->mstar = ch->mstar[s];
}

/* Copies the histories of the chunk's m touching pairs into it, whether
 * each is a new contact (its touch flag off), and their entries in the pair
 * table (WALLS: the pairs of bucket b are particle-wall pairs); pads the
 * list with copies of its last pair to a whole number of vector lanes, which
 * the law's loop then needs no scalar remainder for. Returns the padded
 * length. */
DM_INLINE uint32_t dm_chunk_load(const int HSL, const int WALLS, const demill_world *w,
                                 const dm_bucket *b, dm_chunk *ch, uint32_t m)
{
    const uint16_t *mat = w->p.mat;
    for (uint32_t s = 0; s < m; s++) {
        const uint32_t k = ch->k[s], j = b->j[k];
        for (int c = 0; c < HSL; c++)
            ch->h[c][s] = b->hist[(size_t)b->hs * k + c];
        ch->first[s] = !b->on[k];
        ch->pp[s] = mat[b->i[k]] * w->nmat_tab + (WALLS ? w->walls[j].material : mat[j]);
    }
    const uint32_t padded = m ? (m + DM_LANES - 1) / DM_LANES * DM_LANES : 0;
    for (uint32_t s = m; s < padded; s++) {
        ch->k[s] = ch->k[m - 1];
        ch->pp[s] = ch->pp[m - 1];
        ch->first[s] = ch->first[m - 1];
        for (int c = 0; c < HSL; c++)
            ch->h[c][s] = ch->h[c][m - 1];
    }
    return padded;
}

/* The law for pair s of a chunk with kinematics q, from the history loaded
 * into the chunk, as a new contact if first (see dm_law); stores the force
 * on b, the torques on a (lever arm ai) and b (aj), the dissipation and the
 * new history. */
DM_INLINE void dm_chunk_law(const int D, const int NL, const int DL, const int TL, const int RL,
                            const int CL, const int HSL, dm_chunk *ch, uint32_t s,
                            const dm_pairparam *pp, const dm_kin *q, double dt_hist,
                            double reach, int first)
{
    const int W = D == 3 ? 3 : 1;
    double hin[DM_MAX_HIST], hout[DM_MAX_HIST];
    for (int c = 0; c < HSL; c++)
        hin[c] = ch->h[c][s];
    dm_law_out o;
    dm_law(D, NL, DL, TL, RL, CL, pp, q->n, q->delta, q->vc, q->dc, q->wrel, q->wd, q->ir,
           q->rstar, q->mstar, dt_hist, reach, first, hin, hout, &o);
    double f[3], ta[3], tb[3];
    dm_law_loads(D, q->n, q->ai, q->aj, &o, f, ta, tb);
    for (int c = 0; c < D; c++)
        ch->f[c][s] = f[c];
    for (int c = 0; c < W; c++) {
        ch->ta[c][s] = ta[c];
        ch->tb[c][s] = tb[c];
    }
    ch->diss[0][s] = o.diss_normal;
    ch->diss[1][s] = o.diss_tangential;
    ch->diss[2][s] = o.diss_friction;
    ch->diss[3][s] = o.diss_rolling;
    if (dm_law_extended(NL, RL, CL)) {
        ch->diss[4][s] = o.diss_plastic;
        ch->diss[5][s] = o.diss_rolling_viscous;
        ch->diss[6][s] = o.work_cohesion;
    }
    for (int c = 0; c < HSL; c++)
        ch->h[c][s] = hout[c];
}

/* Touching pair s of a chunk's result row o (see dm_result_add). */
DM_INLINE void dm_chunk_result(const int D, const dm_chunk *ch, uint32_t s, double *o)
{
    const int W = D == 3 ? 3 : 1;
    for (int c = 0; c < D; c++)
        o[c] = ch->f[c][s];
    for (int c = 0; c < W; c++) {
        o[D + c] = ch->ta[c][s];
        o[D + W + c] = ch->tb[c][s];
    }
}

/* Commits touching pair s of a chunk: its new history, the contact on (for
 * a step), its dissipation into the tally and the event slot (XL: with the
 * extended laws' terms). Returns the energy it dissipated over the step. */
DM_INLINE double dm_chunk_commit(const int HSL, const int EV, const int XL, const dm_chunk *ch,
                                 uint32_t s, double *h, uint8_t *on, int advance, int tally,
                                 dm_tally *t)
{
    double lost = 0.0;
    if (advance) {
        for (int c = 0; c < HSL; c++)
            h[c] = ch->h[c][s];
        *on = 1;
    }
    if (tally) {
        lost = ch->diss[0][s] + ch->diss[1][s] + ch->diss[2][s] + ch->diss[3][s];
        t->diss_normal += ch->diss[0][s];
        t->diss_tangential += ch->diss[1][s];
        t->diss_friction += ch->diss[2][s];
        t->diss_rolling += ch->diss[3][s];
        if (XL) {
            lost += ch->diss[4][s] + ch->diss[5][s];
            t->diss_plastic += ch->diss[4][s];
            t->diss_rolling_viscous += ch->diss[5][s];
            t->work_cohesion += ch->diss[6][s];
        }
        if (EV)
            h[HSL] += lost;
    }
    return lost;
}

/* A force fc n on b (and -fc n on a) with no torques, into out. */
DM_INLINE void dm_out_normal(const int D, double *out, double fc, const double *n)
{
    const int W = D == 3 ? 3 : 1;
    for (int c = 0; c < D; c++)
        out[c] = fc * n[c];
    for (int c = 0; c < 2 * W; c++)
        out[D + c] = 0.0;
}

/* Whether the chunk adds its results for particle p to p's sums as it goes
 * (when not all of them, a->direct): when p is in the range that runs the
 * chunk and every pair of p is in a chunk of that range, whose thread then
 * adds them all in pair-id order (forces.c). */
DM_INLINE int dm_direct(const dm_kernel_args *a, uint32_t p)
{
    return a->lo[p] >= a->begin && p < a->end;
}

/* A pair's result row o (S = D + 2W doubles: force on b, torques on a and on
 * b) added to the forces and torques of its particle a = i if A and b = j if
 * B, in the order and with the operations of forces.c's sums: chunk after
 * chunk in pair-id order on one thread, this gives them bit for bit. */
DM_INLINE void dm_result_add(const int D, const int A, const int B, double *restrict f,
                             double *restrict tq, uint32_t i, uint32_t j, const double *o)
{
    const int W = D == 3 ? 3 : 1;
    if (A) {
        for (int c = 0; c < D; c++)
            f[D * i + c] -= o[c];
        for (int c = 0; c < W; c++)
            tq[W * i + c] += o[D + c];
    }
    if (B) {
        for (int c = 0; c < D; c++)
            f[D * j + c] += o[c];
        for (int c = 0; c < W; c++)
            tq[W * j + c] += o[D + W + c];
    }
}

/* Particle pair k's result row o, stored, in a chunk that does not add all
 * its results itself (not a->direct): added to the sums of those of i and
 * j that it adds (dm_direct()), and listed, at *list, for the others' sums
 * (forces.c) unless both were; returns the number listed, 0 or 1. */
DM_INLINE uint32_t dm_result_give(const int D, const dm_kernel_args *a, double *restrict f,
                                  double *restrict tq, uint32_t i, uint32_t j, const double *o,
                                  uint32_t *list, uint32_t k)
{
    const int di = dm_direct(a, i), dj = dm_direct(a, j);
    if (di)
        dm_result_add(D, 1, 0, f, tq, i, j, o);
    if (dj)
        dm_result_add(D, 0, 1, f, tq, i, j, o);
    *list = k;
    return !(di & dj);
}

/* The kinematics of a chunk's first `lanes` touching pairs (ch->k) into the
 * chunk, for dimension D (index D == 3), particle-particle or particle-wall
 * pairs (index walls), with SPIN (index: the tangential law is not none) and
 * ROLL (the rolling law). They depend on nothing else, so that the kernels
 * of all normal, damping and tangential laws share them (kinematics.c).
 * lanes is a multiple of DM_LANES (dm_chunk_load()); the loops that take it
 * round it down to one all the same, which tells the compiler so and spares
 * them a remainder loop. */
typedef void (*dm_kin_fn)(const dm_kernel_args *a, dm_chunk *ch, uint32_t lanes);
extern const dm_kin_fn dm_kins[2][2][2][DM_ROLLING_LAWS];

/* The laws of a chunk's first `lanes` pairs, from the kinematics gathered
 * into it (the loop that dm_law_fn's kernels run), every pair as a
 * continuing contact: dm_chunk_entries() computes those sampled first
 * (ch->first) again with the entry correction (dm_law), which is kept out
 * of this loop, where every lane would pay for its square roots and
 * divisions, for the pair in tens of steps that needs it. */
DM_INLINE void dm_chunk_laws(const int D, const int NL, const int DL, const int TL,
                             const int RL, const int CL, dm_chunk *restrict ch, uint32_t lanes,
                             const dm_pairparam *restrict tab, double dt_hist, double reach)
{
    const int HSL = dm_law_hist_size(NL, DL, TL, RL, D);
    const uint32_t n = lanes / DM_LANES * DM_LANES; /* = lanes (see dm_kin_fn) */
    for (uint32_t s = 0; s < n; s++) {
        dm_kin q;
        dm_kin_get(D, RL, ch, s, &q);
        dm_chunk_law(D, NL, DL, TL, RL, CL, HSL, ch, s, &tab[ch->pp[s]], &q, dt_hist, reach, 0);
    }
}

/* After dm_chunk_laws(), for laws with an entry correction: the law again,
 * with it, for the chunk's pairs (of its m) sampled first, from their
 * histories as the bucket still holds them (hist, hs doubles a pair; the
 * law pass has overwritten the chunk's copies). The same operations as a
 * lane of the vectorised loop, compiled without contraction: the results
 * are those of a loop that applied it itself, bit for bit. */
DM_INLINE void dm_chunk_entries(const int D, const int NL, const int DL, const int TL,
                                const int RL, const int CL, dm_chunk *restrict ch, uint32_t m,
                                const double *restrict hist, int hs,
                                const dm_pairparam *restrict tab, double dt_hist, double reach)
{
    const int HSL = dm_law_hist_size(NL, DL, TL, RL, D);
    for (uint32_t s = 0; s < m && dm_law_entry(DL); s++) {
        if (!ch->first[s])
            continue;
        for (int c = 0; c < HSL; c++)
            ch->h[c][s] = hist[(size_t)hs * ch->k[s] + c];
        dm_kin q;
        dm_kin_get(D, RL, ch, s, &q);
        dm_chunk_law(D, NL, DL, TL, RL, CL, HSL, ch, s, &tab[ch->pp[s]], &q, dt_hist, reach, 1);
    }
}

/* A combination's chunk_laws, shared by its particle-particle and
 * particle-wall kernels; l: the laws, which only the generic kernel reads
 * (a fast kernel's are compiled in). */
typedef void (*dm_law_fn)(dm_chunk *ch, uint32_t lanes, const dm_pairparam *tab, double dt_hist,
                          double reach, dm_laws l);

/* ---- the single-precision path (DEMILL_WORLD_SINGLE_PRECISION) ----------
 * The fast kernels' kinematics and law passes in float: the kinematics are
 * computed in double from the particles' double positions and velocities
 * (so that the relative vectors and the overlap are differences of doubles)
 * and rounded as they are gathered into a float chunk; the law (dm_lawf)
 * runs on floats, twice the lanes of a vector; its results and the new
 * histories are widened into the double chunk, whose commit pass and the
 * sums into the particles are the double kernels'. Contact histories stay
 * double in storage (rounded to float each step they are used). */
typedef struct dm_chunkf {
    float f[3][DM_CHUNK];                   /* force on b */
    float ta[3][DM_CHUNK], tb[3][DM_CHUNK]; /* torques on a and b (W components) */
    float diss[DM_DISS_FAST][DM_CHUNK];     /* dissipation by mechanism */
    float h[DM_MAX_HIST][DM_CHUNK];         /* histories, then their new values */
    /* the kinematics of the touching pairs (dm_kin, by component) */
    float n[3][DM_CHUNK], delta[DM_CHUNK], ai[DM_CHUNK], aj[DM_CHUNK];
    float vc[3][DM_CHUNK], dc[3][DM_CHUNK], wrel[3][DM_CHUNK], rstar[DM_CHUNK], mstar[DM_CHUNK];
} dm_chunkf;

/* Pair s's kinematics q (computed in double) into the float chunk, rounded
 * (ROLL: the constant-torque rolling law's wrel too). */
DM_INLINE void dm_kin_putf(const int D, const int ROLL, dm_chunkf *cf, uint32_t s,
                           const dm_kin *q)
{
    for (int c = 0; c < D; c++) {
        cf->n[c][s] = (float)q->n[c];
        cf->vc[c][s] = (float)q->vc[c];
        cf->dc[c][s] = (float)q->dc[c];
    }
    for (int c = 0; c < (ROLL ? (D == 3 ? 3 : 1) : 0); c++)
        cf->wrel[c][s] = (float)q->wrel[c];
    cf->delta[s] = (float)q->delta;
    cf->ai[s] = (float)q->ai;
    cf->aj[s] = (float)q->aj;
    cf->rstar[s] = (float)q->rstar;
    cf->mstar[s] = (float)q->mstar;
}

/* The kinematics of the first `lanes` touching pairs of ch (ch->k) into cf,
 * as dm_kins (kinematics.c), for the fast kernels' rolling laws (none,
 * constant torque). */
typedef void (*dm_kinf_fn)(const dm_kernel_args *a, const dm_chunk *ch, dm_chunkf *cf,
                           uint32_t lanes);
extern const dm_kinf_fn dm_kinsf[2][2][2][2];

/* The float law of pair s of the chunk, from the kinematics and history in
 * cf and the pair entry in ch, as a new contact if first: what
 * dm_chunk_law() stores, in float. */
DM_INLINE void dm_chunk_lawf(const int D, const int NL, const int DL, const int TL, const int RL,
                             const dm_chunk *restrict ch, dm_chunkf *restrict cf, uint32_t s,
                             const dm_pairparam *restrict tab, float dt_hist, float reach,
                             int first)
{
    const int W = D == 3 ? 3 : 1, HSL = dm_law_hist_size(NL, DL, TL, RL, D);
    float nq[3] = {0.0f, 0.0f, 0.0f}, vc[3] = {0.0f, 0.0f, 0.0f}, dc[3] = {0.0f, 0.0f, 0.0f};
    float wrel[3] = {0.0f, 0.0f, 0.0f}, hin[DM_MAX_HIST], hout[DM_MAX_HIST];
    for (int c = 0; c < D; c++) {
        nq[c] = cf->n[c][s];
        vc[c] = cf->vc[c][s];
        dc[c] = cf->dc[c][s];
    }
    for (int c = 0; c < (RL ? W : 0); c++)
        wrel[c] = cf->wrel[c][s];
    for (int c = 0; c < HSL; c++)
        hin[c] = cf->h[c][s];
    dm_law_outf o;
    dm_lawf(D, NL, DL, TL, RL, DEMILL_COHESION_NONE, &tab[ch->pp[s]], nq, cf->delta[s], vc, dc,
            wrel, NULL, 0.0f, cf->rstar[s], cf->mstar[s], dt_hist, reach, first, hin, hout, &o);
    float f[3], ta[3], tb[3];
    dm_law_loadsf(D, nq, cf->ai[s], cf->aj[s], &o, f, ta, tb);
    for (int c = 0; c < D; c++)
        cf->f[c][s] = f[c];
    for (int c = 0; c < W; c++) {
        cf->ta[c][s] = ta[c];
        cf->tb[c][s] = tb[c];
    }
    cf->diss[0][s] = o.diss_normal;
    cf->diss[1][s] = o.diss_tangential;
    cf->diss[2][s] = o.diss_friction;
    cf->diss[3][s] = o.diss_rolling;
    for (int c = 0; c < HSL; c++)
        cf->h[c][s] = hout[c];
}

/* The float law of the chunk's first `lanes` pairs, every one as a
 * continuing contact (dm_chunk_single() computes those sampled first again:
 * see dm_chunk_laws). */
DM_INLINE void dm_chunk_lawsf(const int D, const int NL, const int DL, const int TL,
                              const int RL, const dm_chunk *restrict ch, dm_chunkf *restrict cf,
                              uint32_t lanes, const dm_pairparam *restrict tab, float dt_hist,
                              float reach)
{
    const uint32_t n = lanes / DM_LANES * DM_LANES; /* = lanes (see dm_kin_fn) */
    for (uint32_t s = 0; s < n; s++)
        dm_chunk_lawf(D, NL, DL, TL, RL, ch, cf, s, tab, dt_hist, reach, 0);
}

/* The kinematics and law passes of a chunk in float, for a fast kernel's
 * laws: the histories dm_chunk_load() put into ch rounded into a float
 * chunk, the float kinematics and law (the pairs sampled first again with
 * the entry correction), and the results of the m touching pairs widened
 * back into ch for the commit pass. walls: particle-wall pairs. */
DM_INLINE void dm_chunk_single(const int D, const int NL, const int DL, const int TL,
                               const int RL, const dm_kernel_args *a, dm_chunk *restrict ch,
                               uint32_t lanes, uint32_t m, int walls)
{
    const int W = D == 3 ? 3 : 1, HSL = dm_law_hist_size(NL, DL, TL, RL, D);
    dm_chunkf cf;
    for (int c = 0; c < HSL; c++)
        for (uint32_t s = 0; s < lanes; s++)
            cf.h[c][s] = (float)ch->h[c][s];
    dm_kinsf[D == 3][walls][TL != DEMILL_TANGENTIAL_NONE][RL](a, ch, &cf, lanes);
    dm_chunk_lawsf(D, NL, DL, TL, RL, ch, &cf, lanes, a->w->ptab, (float)a->dt_hist,
                   (float)a->reach);
    for (uint32_t s = 0; s < m && dm_law_entry(DL); s++) { /* the pairs sampled first */
        if (!ch->first[s])
            continue;
        for (int c = 0; c < HSL; c++) /* their histories, which the pass overwrote in cf */
            cf.h[c][s] = (float)ch->h[c][s];
        dm_chunk_lawf(D, NL, DL, TL, RL, ch, &cf, s, a->w->ptab, (float)a->dt_hist,
                      (float)a->reach, 1);
    }
    for (uint32_t s = 0; s < m; s++) {
        for (int c = 0; c < D; c++)
            ch->f[c][s] = cf.f[c][s];
        for (int c = 0; c < W; c++) {
            ch->ta[c][s] = cf.ta[c][s];
            ch->tb[c][s] = cf.tb[c][s];
        }
        for (int c = 0; c < DM_DISS_FAST; c++)
            ch->diss[c][s] = cf.diss[c][s];
        for (int c = 0; c < HSL; c++)
            ch->h[c][s] = cf.h[c][s];
    }
}

/* A combination's single-precision passes (dm_chunk_single), shared by its
 * particle-particle and particle-wall kernels. */
typedef void (*dm_single_fn)(const dm_kernel_args *a, dm_chunk *ch, uint32_t lanes, uint32_t m,
                             int walls);

/* The separations x_j - x_i of the candidates k0 .. k1 - 1 of a bucket with
 * particles bi, bj (k1 - k0 <= DM_CHUNK), component c of candidate k into
 * d[c][k - k0], and the sums of their radii into sum[k - k0]: the gathers
 * of the narrow phase, which then tests them (dm_touches()) in a vectorised
 * loop. This loop is compiled scalar (DM_SCALAR_LOOPS): the vectorised
 * one's emulated gathers of four doubles a particle took more time than
 * the plain loads and stores. */
void dm_pp_separations(int D, const dm_particles *P, const uint32_t *bi, const uint32_t *bj,
                       uint32_t k0, uint32_t k1, double (*d)[DM_CHUNK], double *sum);

/* Particle-particle chunk. */
DM_INLINE void dm_pp_chunk(const int D, const int NL, const int DL, const int TL, const int RL,
                           const int CL, dm_law_fn laws, dm_single_fn single, dm_kernel_args *a)
{
    const int S = D + 2 * (D == 3 ? 3 : 1);
    const int HSL = dm_law_hist_size(NL, DL, TL, RL, D), HSP = dm_law_tangential_size(TL, D);
    const int EXIT = dm_law_exit(NL, DL), XL = dm_law_extended(NL, RL, CL);
    const int SPIN = TL != DEMILL_TANGENTIAL_NONE;
    demill_world *w = a->w;
    const dm_particles *P = &w->p;
    const dm_bucket *b = a->b;
    const int EV = w->events, HS = b->hs; /* HS = HSL + EV: the event slot is last */
    const double *vp = a->vp;
    const uint16_t *restrict mat = w->p.mat;
    const dm_pairparam *tab = w->ptab;
    const uint32_t nm = w->nmat_tab, k0 = a->k0;
    const uint32_t k1 = b->n - k0 < DM_CHUNK ? b->n : k0 + DM_CHUNK;
    const uint32_t *restrict bi = b->i, *restrict bj = b->j;
    double *restrict hist = b->hist, *restrict out = w->res.out + (size_t)S * b->base;
    uint8_t *restrict on = b->on;
    const double dt_hist = a->dt_hist, reach = a->reach;
    const int tally = a->tally, advance = dt_hist > 0.0, direct = a->direct;
    double *restrict f = w->p.f, *restrict tq = w->p.t;
    dm_tally t = {0};
    dm_chunk ch;

    /* the narrow phase: the separations and sums of radii into the slots of
     * the kinematics (n, delta), which hold nothing yet, then the test */
    dm_pp_separations(D, P, bi, bj, k0, k1, ch.n, ch.delta);
    for (uint32_t s = 0; s < k1 - k0; s++) {
        double r2 = 0.0;
        for (int c = 0; c < D; c++)
            r2 += ch.n[c][s] * ch.n[c][s];
        uint32_t touch = (uint32_t)dm_touches(ch.delta[s], r2);
        if (CL != DEMILL_COHESION_NONE) { /* a contact that exists reaches further */
            const uint32_t k = k0 + s;
            const double ri = P->r[bi[k]], rj = P->r[bj[k]];
            const double far = ch.delta[s] + dm_law_range(CL, &tab[mat[bi[k]] * nm + mat[bj[k]]],
                                                          ri * rj / ch.delta[s]);
            touch |= on[k] & (r2 < far * far);
        }
        ch.touch[s] = touch;
    }
    uint32_t m = 0, listed = 0;
    uint32_t *restrict list = w->res.list + b->base + k0;
    for (uint32_t k = k0; k < k1; k++) {
        const uint32_t touch = ch.touch[k - k0];
        ch.k[m] = k;
        m += touch;
        if (touch | !on[k] | !advance)
            continue;
        /* the contact came apart during the step */
        const uint32_t i = bi[k], j = bj[k];
        double *h = hist + (size_t)HS * k;
        if (EXIT) {
            double d[3], r2, n[3];
            dm_pp_touch(D, P, i, j, d, &r2);
            const double dist = sqrt(r2);
            const double fc = dm_exit_force(h + HSP, P->r[i] + P->r[j] - dist, reach,
                                            &tab[mat[i] * nm + mat[j]]);
            double vn = 0.0;
            for (int c = 0; c < D; c++) {
                n[c] = d[c] / dist;
                vn += (vp[D * j + c] - vp[D * i + c]) * n[c];
            }
            dm_out_normal(D, out + (size_t)S * k, fc, n);
            if (direct)
                dm_result_add(D, 1, 1, f, tq, i, j, out + (size_t)S * k);
            else
                listed += dm_result_give(D, a, f, tq, i, j, out + (size_t)S * k, list + listed, k);
            if (tally) {
                t.diss_normal -= fc * vn * dt_hist;
                if (EV)
                    h[HSL] -= fc * vn * dt_hist;
            }
        }
        if (EV && h[HSL] > 0.0)
            dm_spectrum_record(w, i, j, -1, h[HSL]);
        for (int c = 0; c < HS; c++)
            h[c] = 0.0;
        on[k] = 0;
    }
    const uint32_t lanes = dm_chunk_load(HSL, 0, w, b, &ch, m);
    if (single) { /* the single-precision kernels' kinematics and law */
        single(a, &ch, lanes, m, 0);
    } else {
        const dm_laws l = {NL, DL, TL, RL, CL};
        dm_kins[D == 3][0][SPIN][RL](a, &ch, lanes);
        laws(&ch, lanes, tab, dt_hist, reach, l);
        dm_chunk_entries(D, NL, DL, TL, RL, CL, &ch, m, hist, HS, tab, dt_hist, reach);
    }
    for (uint32_t s = 0; s < m; s++) {
        const uint32_t k = ch.k[s];
        dm_chunk_commit(HSL, EV, XL, &ch, s, hist + (size_t)HS * k, on + k, advance, tally, &t);
        if (direct) {
            double o[9];
            dm_chunk_result(D, &ch, s, o);
            dm_result_add(D, 1, 1, f, tq, bi[k], bj[k], o);
        } else {
            dm_chunk_result(D, &ch, s, out + (size_t)S * k);
            listed += dm_result_give(D, a, f, tq, bi[k], bj[k], out + (size_t)S * k, list + listed,
                                     k);
        }
    }
    a->t = t;
    a->contacts = m;
    a->listed = listed;
}

/* Particle-wall chunk: the contact geometry of its candidates (into w->wg),
 * then the law. The walls' forces, torques and energies are summed
 * afterwards (forces.c), from out and the geometry's lost. */
DM_INLINE void dm_pw_chunk(const int D, const int NL, const int DL, const int TL, const int RL,
                           const int CL, dm_law_fn laws, dm_single_fn single, dm_kernel_args *a)
{
    const int S = D + 2 * (D == 3 ? 3 : 1);
    const int HSL = dm_law_hist_size(NL, DL, TL, RL, D), HSP = dm_law_tangential_size(TL, D);
    const int EXIT = dm_law_exit(NL, DL), XL = dm_law_extended(NL, RL, CL);
    const int SPIN = TL != DEMILL_TANGENTIAL_NONE;
    demill_world *w = a->w;
    const dm_bucket *b = a->b;
    const int EV = w->events, HS = b->hs; /* HS = HSL + EV: the event slot is last */
    const double *vp = a->vp;
    const uint16_t *restrict mat = w->p.mat;
    const dm_pairparam *tab = w->ptab;
    const uint32_t nm = w->nmat_tab, g0 = a->geom_offset, k0 = a->k0;
    const uint32_t k1 = b->n - k0 < DM_CHUNK ? b->n : k0 + DM_CHUNK;
    dm_wgeom *g = &w->wg;
    double *restrict hist = b->hist, *restrict out = w->res.out + (size_t)S * b->base;
    uint8_t *restrict on = b->on;
    const double dt_hist = a->dt_hist, reach = a->reach;
    const int tally = a->tally, advance = dt_hist > 0.0, direct = a->direct;
    double *restrict f = w->p.f, *restrict tq = w->p.t;
    dm_tally t = {0};
    dm_chunk ch;

    dm_wgeom_range(w, b, g0, k0, k1);
    uint32_t m = 0, listed = 0;
    uint32_t *restrict list = w->res.list + b->base + k0;
    for (uint32_t k = k0; k < k1; k++) {
        const uint32_t gk = g0 + k;
        uint32_t touch = g->delta[gk] > 0.0;
        if (CL != DEMILL_COHESION_NONE) /* a contact that exists reaches further */
            touch |= on[k] & (g->delta[gk] > -dm_law_range(CL, &tab[mat[b->i[k]] * nm +
                                                                    w->walls[b->j[k]].material],
                                                           w->p.r[b->i[k]]));
        ch.k[m] = k;
        m += touch;
        if (touch | !on[k] | !advance)
            continue;
        /* the contact came apart during the step */
        const uint32_t i = b->i[k];
        const dm_wall *wall = &w->walls[b->j[k]];
        double *h = hist + (size_t)HS * k;
        if (EXIT) {
            const double *n = g->nrm + D * gk;
            const double fc = dm_exit_force(h + HSP, g->delta[gk], reach,
                                            &tab[mat[i] * nm + wall->material]);
            double absorbed = 0.0;
            for (int c = 0; c < D; c++)
                absorbed += fc * n[c] * (vp[D * i + c] - g->vw[D * gk + c]);
            dm_out_normal(D, out + (size_t)S * k, fc, n);
            if (direct || dm_direct(a, i))
                dm_result_add(D, 1, 0, f, tq, i, 0, out + (size_t)S * k);
            list[listed++] = k;
            g->lost[gk] = absorbed * dt_hist;
            if (tally) {
                t.diss_normal += absorbed * dt_hist;
                if (EV)
                    h[HSL] += absorbed * dt_hist;
            }
        }
        if (EV && h[HSL] > 0.0)
            dm_spectrum_record(w, i, 0, (int)b->j[k], h[HSL]);
        for (int c = 0; c < HS; c++)
            h[c] = 0.0;
        on[k] = 0;
    }
    const uint32_t lanes = dm_chunk_load(HSL, 1, w, b, &ch, m);
    if (single) { /* the single-precision kernels' kinematics and law */
        single(a, &ch, lanes, m, 1);
    } else {
        const dm_laws l = {NL, DL, TL, RL, CL};
        dm_kins[D == 3][1][SPIN][RL](a, &ch, lanes);
        laws(&ch, lanes, tab, dt_hist, reach, l);
        dm_chunk_entries(D, NL, DL, TL, RL, CL, &ch, m, hist, HS, tab, dt_hist, reach);
    }
    for (uint32_t s = 0; s < m; s++) {
        const uint32_t k = ch.k[s];
        g->lost[g0 + k] = dm_chunk_commit(HSL, EV, XL, &ch, s, hist + (size_t)HS * k, on + k,
                                          advance, tally, &t);
        dm_chunk_result(D, &ch, s, out + (size_t)S * k);
        if (direct || dm_direct(a, b->i[k]))
            dm_result_add(D, 1, 0, f, tq, b->i[k], 0, out + (size_t)S * k);
        list[listed++] = k;
    }
    a->t = t;
    a->contacts = m;
    a->listed = listed;
}

/* The kernels of a slice, in kernel order, for particle-particle and
 * particle-wall pairs. */
typedef struct dm_kernel_slice {
    dm_kernel_fn pp[DM_SLICE_KERNELS], pw[DM_SLICE_KERNELS];
} dm_kernel_slice;

#define DM_DEFINE_KERNELS(D, NL, DL, TL, RL)                                                     \
    DM_VECTOR_CLONES __attribute__((noinline)) static void                                        \
        dm_laws_##D##_##NL##_##DL##_##TL##_##RL(dm_chunk *ch, uint32_t lanes,                     \
                                                const dm_pairparam *tab, double dt_hist,          \
                                                double reach, dm_laws l)                          \
    {                                                                                             \
        (void)l;                                                                                  \
        dm_chunk_laws(D, NL, DL, TL, RL, 0, ch, lanes, tab, dt_hist, reach);                      \
    }                                                                                             \
    DM_VECTOR_CLONES static void dm_pp_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)         \
    {                                                                                             \
        dm_pp_chunk(D, NL, DL, TL, RL, 0, dm_laws_##D##_##NL##_##DL##_##TL##_##RL, NULL, a);      \
    }                                                                                             \
    DM_VECTOR_CLONES static void dm_pw_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)         \
    {                                                                                             \
        dm_pw_chunk(D, NL, DL, TL, RL, 0, dm_laws_##D##_##NL##_##DL##_##TL##_##RL, NULL, a);      \
    }
#define DM_PP_ENTRY(D, NL, DL, TL, RL) dm_pp_##D##_##NL##_##DL##_##TL##_##RL,
#define DM_PW_ENTRY(D, NL, DL, TL, RL) dm_pw_##D##_##NL##_##DL##_##TL##_##RL,

/* The kernels of dimension D, normal law NL and damping law DL, for every
 * tangential and rolling law, and their table dm_kernels_D_NL_DL. Each of
 * the 12 slices is defined in a file of kernels/ of its own, named after
 * them (3d_hertz_restitution.c: D = 3, NL = DEMILL_NORMAL_HERTZ,
 * DL = DEMILL_DAMPING_RESTITUTION), so that they compile in parallel;
 * kernels.c gathers the tables, and a slice missing or defined twice fails
 * the link. The kernels are static: GCC 12 gives a function with
 * target_clones that is not static a resolver of default visibility, which
 * the shared library would export. */
#define DM_KERNEL_SLICE(D, NL, DL)                                                               \
    DM_FOR_TL(DM_DEFINE_KERNELS, D, NL, DL)                                                       \
    const dm_kernel_slice dm_kernels_##D##_##NL##_##DL = {                                        \
        {DM_FOR_TL(DM_PP_ENTRY, D, NL, DL)}, {DM_FOR_TL(DM_PW_ENTRY, D, NL, DL)}};

/* The single-precision kernels of a combination (dm_chunk_single), and a
 * slice of them, dm_kernels_single_D_NL_DL, each in a file of kernels/ of
 * its own (3d_hertz_restitution_single.c), as the double slices. */
#define DM_DEFINE_SINGLE(D, NL, DL, TL, RL)                                                      \
    DM_VECTOR_CLONES __attribute__((noinline)) static void                                        \
        dm_single_##D##_##NL##_##DL##_##TL##_##RL(const dm_kernel_args *a, dm_chunk *ch,          \
                                                  uint32_t lanes, uint32_t m, int walls)          \
    {                                                                                             \
        dm_chunk_single(D, NL, DL, TL, RL, a, ch, lanes, m, walls);                               \
    }                                                                                             \
    DM_VECTOR_CLONES static void dm_ppf_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)        \
    {                                                                                             \
        dm_pp_chunk(D, NL, DL, TL, RL, 0, NULL, dm_single_##D##_##NL##_##DL##_##TL##_##RL, a);    \
    }                                                                                             \
    DM_VECTOR_CLONES static void dm_pwf_##D##_##NL##_##DL##_##TL##_##RL(dm_kernel_args *a)        \
    {                                                                                             \
        dm_pw_chunk(D, NL, DL, TL, RL, 0, NULL, dm_single_##D##_##NL##_##DL##_##TL##_##RL, a);    \
    }
#define DM_PPF_ENTRY(D, NL, DL, TL, RL) dm_ppf_##D##_##NL##_##DL##_##TL##_##RL,
#define DM_PWF_ENTRY(D, NL, DL, TL, RL) dm_pwf_##D##_##NL##_##DL##_##TL##_##RL,
#define DM_KERNEL_SLICE_SINGLE(D, NL, DL)                                                        \
    DM_FOR_TL(DM_DEFINE_SINGLE, D, NL, DL)                                                        \
    const dm_kernel_slice dm_kernels_single_##D##_##NL##_##DL = {                                 \
        {DM_FOR_TL(DM_PPF_ENTRY, D, NL, DL)}, {DM_FOR_TL(DM_PWF_ENTRY, D, NL, DL)}};

/* Every slice of a dimension, in kernel order (kernels.c), in double and in
 * single precision. */
extern const dm_kernel_slice *const dm_kernels2[DM_SLICES], *const dm_kernels3[DM_SLICES];
extern const dm_kernel_slice *const dm_kernels2_single[DM_SLICES],
    *const dm_kernels3_single[DM_SLICES];

/* The generic kernels of dimension 2 and 3 (kernels/generic.c), which read
 * the laws of their bucket's kernel. */
extern const dm_kernel_fn dm_generic_pp[2], dm_generic_pw[2];

/* The kernel of a chunk of dimension D: a particle-wall one if walls, else
 * a particle-particle one, of the combination kernel (dm_kernel_index());
 * single: a fast kernel in single precision (the generic kernel has none,
 * and runs in double). */
DM_INLINE dm_kernel_fn dm_kernel(const int D, int walls, int kernel, int single)
{
    if (kernel >= DM_FAST_KERNELS)
        return (walls ? dm_generic_pw : dm_generic_pp)[D == 3];
    const dm_kernel_slice *const *slices =
        single ? (D == 3 ? dm_kernels3_single : dm_kernels2_single)
               : (D == 3 ? dm_kernels3 : dm_kernels2);
    const dm_kernel_slice *s = slices[kernel / DM_SLICE_KERNELS];
    return (walls ? s->pw : s->pp)[kernel % DM_SLICE_KERNELS];
}

#endif /* DM_KERNELS_H */
