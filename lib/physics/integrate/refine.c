/* refine.c: the iterative refinement integrator of Katnov (2020, §2.3 and
 * §2.9; docs/physics.md §8, which shows that, converged, it is the
 * linear-acceleration method of Newmark 1959).
 *
 * A step from t to t + Δt predicts the state with a Taylor step that has a
 * jerk b, the rate of change of the acceleration over the step:
 *   x = x_n + v_n Δt + a_n Δt²/2 + b Δt³/6,   v = v_n + a_n Δt + b Δt²/2,
 * and likewise for the angular velocity (and the 2D angle). The first
 * iterate takes b = 0; each later one takes b = (a_(k-1) - a_n)/Δt from the
 * forces evaluated at the previous iterate. The step ends when every
 * acceleration component of the iterate, a_k, differs by at most
 * ε_a (|a_k| + ā) from the a_(k-1) its jerk was made from, ā being the mean
 * magnitude at the start of the step (plus |g|; for angular accelerations
 * plus ā over the mean radius); or after the set number of force
 * evaluations. The first iterate is compared with a_n (which made b = 0) to
 * round-off only: one evaluation suffices where nothing changes over the
 * step (free flight), and every other step iterates, so that it stays
 * second order whatever ε_a. The accepted state is the last one evaluated,
 * so that the forces kept for the next step are those of the state reached.
 * A step that stops at the limit unconverged takes its end velocities from
 * those forces, v = v_n + Δt (a_n + a_k)/2, not from the a_(k-1) its
 * positions were made with: every force sample then gives its impulse once,
 * half in each of the steps next to it, as in a converged step. Where the
 * iterates do not converge at all this matters: a contact that begins just
 * before the end of a step has no fixed point (the dashpot's force jumps at
 * contact, so that the iterate in contact makes a jerk that takes the next
 * one out of contact, and so on), and the step kept half a step's impulse
 * of a force its state did not have, or lost one, by the parity of the
 * limit (e up to 3.4 % off at e = 0.1, 0.7 % at e = 0.5).
 *
 * Contact histories: each iterate's evaluation advances the tangential
 * springs by the displacement of that iterate, v̄ Δt with the mean velocity
 * v̄ = (x - x_n)/Δt, and the dashpots see the predicted end velocity. Every
 * iterate starts from the histories, touch flags (and energy tallies) of the
 * start of the step, restored from a copy, so that only the accepted
 * iterate's update remains, and so that the law knows a contact's first
 * sample by its flag (off: apart at the last step) in every iterate: an
 * estimate from the iterate's overlap and end velocity, which already
 * carries the contact's deceleration, would not tell it. Neighbour lists
 * are rebuilt only at the start of a step, so that the copy stays valid:
 * when an iterate leaves the lists' reach, the lists are rebuilt at the
 * start of the step and the iterations start again; an iterate that leaves
 * the reach of lists built at the start of its own step (more than half
 * the skin in one step) has gone wrong, and the step is given up. The
 * particle arrays of the start of the step trade places with the world's
 * instead of being copied. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/status.h"
#include "base/threads.h"
#include "physics/broadphase/broadphase.h"
#include "physics/contact/contact.h"
#include "physics/integrate/integrate.h"
#include "physics/state/orient.h"
#include "physics/mill/mill.h"

#define DM_INLINE static inline __attribute__((always_inline))

/* The tolerance of the first iterate (b = 0) against the accelerations at
 * the start of the step: round-off only, so that one evaluation suffices
 * only where nothing changed (free flight); anything else iterates, which
 * keeps the step second order at any ε_a. */
#define DM_FIRST_EPS (64 * DBL_EPSILON)

static void swap(double **a, double **b)
{
    double *t = *a;
    *a = *b;
    *b = t;
}

/* Gives the refinement arrays the capacity of the particle arrays, with
 * which they trade places. */
static int reserve(demill_world *w)
{
    dm_refine *R = &w->refine;
    const uint32_t cap = w->p.cap;
    if (R->cap == cap)
        return 0;
    const size_t D = (size_t)w->dim * sizeof(double), W = (size_t)dm_wdim(w) * sizeof(double);
    void **const arrays[] = {(void **)&R->xn, (void **)&R->vn, (void **)&R->fn,
                             (void **)&R->fprev, (void **)&R->wn, (void **)&R->tn,
                             (void **)&R->tprev, (void **)&R->thn, (void **)&R->qn[0],
                             (void **)&R->qn[1], (void **)&R->qn[2], (void **)&R->qn[3]};
    const size_t Q = w->dim == 3 ? sizeof(double) : 0; /* each orientation array */
    const size_t sizes[] = {D, D, D, D, W, W, W, sizeof(double), Q, Q, Q, Q};
    if (dm_grow_arrays(arrays, sizes, sizeof sizes / sizeof sizes[0], cap))
        return -1;
    R->cap = cap;
    return 0;
}

void dm_refine_free(demill_world *w)
{
    dm_refine *R = &w->refine;
    free(R->xn);
    free(R->vn);
    free(R->fn);
    free(R->fprev);
    free(R->wn);
    free(R->tn);
    free(R->tprev);
    free(R->thn);
    for (int c = 0; c < 4; c++)
        free(R->qn[c]);
    free(R->hist);
    free(R->on);
    free(R->wall_diss);
    free(R->spectrum);
    memset(R, 0, sizeof *R);
}

/* Trades the start-of-step arrays with the world's: afterwards the refinement
 * holds x_n, v_n, F_n (and ω_n, T_n, θ_n or q_n when the orientations are
 * tracked) and the world's arrays are free for the iterates. Calling it again
 * trades them back. */
static void trade(demill_world *w)
{
    dm_particles *P = &w->p;
    dm_refine *R = &w->refine;
    swap(&P->x, &R->xn);
    swap(&P->v, &R->vn);
    swap(&P->f, &R->fn);
    if (w->rotation) {
        swap(&P->w, &R->wn);
        swap(&P->t, &R->tn);
        if (w->orient && w->dim == 2)
            swap(&P->theta, &R->thn);
        if (w->orient && w->dim == 3)
            for (int c = 0; c < 4; c++)
                swap(&P->q[c], &R->qn[c]);
    }
}

/* ---- the contact state of the start of the step ------------------------- */

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    void *q = realloc(*p, dm_grown_capacity(*cap, need) * size);
    if (!q)
        return -1;
    *p = q;
    *cap = dm_grown_capacity(*cap, need);
    return 0;
}

/* Copies (save) or puts back the histories and touch flags of every bucket,
 * the energy tallies and the collision-spectrum counters. */
static void contacts_copy(demill_world *w, int save)
{
    dm_refine *R = &w->refine;
    size_t h = 0, o = 0;
    for (int side = 0; side < 2; side++)
        for (int k = 0; k < w->nkern; k++) {
            dm_bucket *b = side ? &w->pw.b[k] : &w->pp.b[k];
            const size_t nh = (size_t)b->n * (size_t)b->hs;
            if (!b->n)
                continue; /* (nothing to copy, and maybe no room allocated at all) */
            if (save) {
                if (nh)
                    memcpy(R->hist + h, b->hist, nh * sizeof *b->hist);
                memcpy(R->on + o, b->on, b->n);
            } else {
                if (nh)
                    memcpy(b->hist, R->hist + h, nh * sizeof *b->hist);
                memcpy(b->on, R->on + o, b->n);
            }
            h += nh;
            o += b->n;
        }
    for (uint32_t k = 0; k < w->nwalls; k++)
        if (save)
            R->wall_diss[k] = w->walls[k].dissipated;
        else
            w->walls[k].dissipated = R->wall_diss[k];
    const dm_spectrum *sp = &w->drum.spectrum;
    const size_t nc = sp->counts ? dm_spectrum_counters(sp) * sizeof *sp->counts : 0;
    if (save) {
        R->tally = w->tally;
        if (nc)
            memcpy(R->spectrum, sp->counts, nc);
    } else {
        w->tally = R->tally;
        if (nc)
            memcpy(sp->counts, R->spectrum, nc);
    }
}

static int contacts_save(demill_world *w)
{
    dm_refine *R = &w->refine;
    size_t nh = 0, no = 0;
    for (int side = 0; side < 2; side++)
        for (int k = 0; k < w->nkern; k++) {
            const dm_bucket *b = side ? &w->pw.b[k] : &w->pp.b[k];
            nh += (size_t)b->n * (size_t)b->hs;
            no += b->n;
        }
    const dm_spectrum *sp = &w->drum.spectrum;
    size_t cap_walls = R->cap_walls;
    if (grow((void **)&R->hist, &R->cap_hist, nh, sizeof *R->hist) ||
        grow((void **)&R->on, &R->cap_on, no, 1) ||
        grow((void **)&R->wall_diss, &cap_walls, w->nwalls, sizeof *R->wall_diss) ||
        grow((void **)&R->spectrum, &R->cap_spectrum,
             sp->counts ? dm_spectrum_counters(sp) : 0, sizeof *R->spectrum))
        return -1;
    R->cap_walls = (uint32_t)cap_walls;
    contacts_copy(w, 1);
    return 0;
}

/* ---- the loops over particles -------------------------------------------- */

typedef struct refine_args {
    double dt, eps, abar, alphabar;
    const double *fprev, *tprev; /* converged: the forces and torques a_(k-1) came from */
    int jerk;     /* predict: take b from the last iterate's forces */
    int rotation;
    uint64_t worst[DM_MAX_THREADS]; /* predict: largest squared displacement, as bits */
    uint32_t bad[DM_MAX_THREADS];   /* converged: particles not converged */
} refine_args;

/* One component: from x_n, v_n, a_n and db = b Δt, the iterate's position,
 * its mean velocity over the step (vm) and its end velocity (ve). */
DM_INLINE void taylor(double dt, double xn, double vn, double an, double db, double *x,
                      double *vm, double *ve)
{
    *vm = vn + dt * (0.5 * an + db / 6.0);
    *x = xn + dt * *vm;
    *ve = vn + dt * (an + 0.5 * db);
}

/* The iterate: x, v (mean), vp (end); ω (mean), wp (end), θ or q. */
DM_INLINE void predict(const int D, demill_world *w, refine_args *a, int t, uint32_t i0,
                       uint32_t i1)
{
    const int W = D == 3 ? 3 : 1;
    dm_particles *P = &w->p;
    const dm_refine *R = &w->refine;
    double *restrict x = P->x, *restrict v = P->v, *restrict vp = P->vp;
    const double *restrict xn = R->xn, *restrict vn = R->vn, *restrict fn = R->fn;
    const double *restrict f = P->f, *restrict im = P->im, *restrict x0 = P->x0;
    const double dt = a->dt;
    const int jerk = a->jerk;
    double worst = 0.0;
    for (uint32_t i = i0; i < i1; i++) {
        double d2 = 0.0;
        for (int c = 0; c < D; c++) {
            const size_t q = (size_t)D * i + c;
            const double an = fn[q] * im[i], db = jerk ? (f[q] - fn[q]) * im[i] : 0.0;
            taylor(dt, xn[q], vn[q], an, db, &x[q], &v[q], &vp[q]);
            const double d = x[q] - x0[q];
            d2 += d * d;
        }
        worst = d2 > worst ? d2 : worst;
    }
    memcpy(&a->worst[t], &worst, sizeof worst);
    if (!a->rotation)
        return;
    double *restrict om = P->w, *restrict wp = P->wp, *restrict theta = P->theta;
    const double *restrict wn = R->wn, *restrict tn = R->tn, *restrict tq = P->t;
    const double *restrict thn = R->thn, *restrict ii = P->iinv;
    const int orient = w->orient; /* else θ or q stay as they are (trade()) */
    for (uint32_t i = i0; i < i1; i++) {
        double phi[3]; /* 3D: the rotation vector of the step, Δt times the mean ω */
        for (int c = 0; c < W; c++) {
            const size_t q = (size_t)W * i + c;
            const double an = tn[q] * ii[i], db = jerk ? (tq[q] - tn[q]) * ii[i] : 0.0;
            double th;
            taylor(dt, orient && D == 2 ? thn[i] : 0.0, wn[q], an, db, &th, &om[q], &wp[q]);
            if (orient && D == 2)
                theta[i] = th;
            else
                phi[c] = th;
        }
        if (orient && D == 3) {
            double q[4];
            dm_quat_get(R->qn, i, q);
            dm_quat_turn(q, phi, 1.0);
            dm_quat_put(P->q, i, q);
        }
    }
}

/* Counts the particles whose acceleration differs by more than ε_a (|a| + ā)
 * in a component from the one the iterate's jerk was made from (NaN counts
 * as different). */
DM_INLINE void converged(const int D, demill_world *w, refine_args *a, int t, uint32_t i0,
                         uint32_t i1)
{
    const int W = D == 3 ? 3 : 1;
    const dm_particles *P = &w->p;
    const double *restrict f = P->f, *restrict fp = a->fprev, *restrict im = P->im;
    const double *restrict tq = P->t, *restrict tp = a->tprev, *restrict ii = P->iinv;
    const double eps = a->eps, abar = a->abar, alphabar = a->alphabar;
    uint32_t bad = 0;
    for (uint32_t i = i0; i < i1; i++) {
        int ok = 1;
        for (int c = 0; c < D; c++) {
            const size_t q = (size_t)D * i + c;
            const double ak = f[q] * im[i];
            ok &= fabs(ak - fp[q] * im[i]) <= eps * (fabs(ak) + abar);
        }
        if (a->rotation)
            for (int c = 0; c < W; c++) {
                const size_t q = (size_t)W * i + c;
                const double ak = tq[q] * ii[i];
                ok &= fabs(ak - tp[q] * ii[i]) <= eps * (fabs(ak) + alphabar);
            }
        bad += !ok;
    }
    a->bad[t] = bad;
}

/* An unconverged step: the end velocities (and angular velocities) from the
 * forces it keeps, v = v_n + Δt (a_n + a_k)/2, instead of from the a_(k-1)
 * its jerk came from (see the top of the file). */
DM_INLINE void trapezoid(const int D, demill_world *w, refine_args *a, uint32_t i0, uint32_t i1)
{
    const int W = D == 3 ? 3 : 1;
    dm_particles *P = &w->p;
    const dm_refine *R = &w->refine;
    double *restrict vp = P->vp;
    const double *restrict vn = R->vn, *restrict fn = R->fn, *restrict f = P->f;
    const double *restrict im = P->im;
    const double h = 0.5 * a->dt;
    for (uint32_t i = i0; i < i1; i++)
        for (int c = 0; c < D; c++) {
            const size_t q = (size_t)D * i + c;
            vp[q] = vn[q] + h * (fn[q] + f[q]) * im[i];
        }
    if (!a->rotation)
        return;
    double *restrict wp = P->wp;
    const double *restrict wn = R->wn, *restrict tn = R->tn, *restrict tq = P->t;
    const double *restrict ii = P->iinv;
    for (uint32_t i = i0; i < i1; i++)
        for (int c = 0; c < W; c++) {
            const size_t q = (size_t)W * i + c;
            wp[q] = wn[q] + h * (tn[q] + tq[q]) * ii[i];
        }
}

#define DM_REFINE_LOOPS(D)                                                                        \
    DM_VECTOR_CLONES static void predict##D(demill_world *w, void *a, int t, uint32_t i0,         \
                                            uint32_t i1)                                          \
    {                                                                                             \
        predict(D, w, a, t, i0, i1);                                                              \
    }                                                                                             \
    static void converged##D(demill_world *w, void *a, int t, uint32_t i0, uint32_t i1)           \
    {                                                                                             \
        converged(D, w, a, t, i0, i1);                                                            \
    }                                                                                             \
    static void trapezoid##D(demill_world *w, void *a, int t, uint32_t i0, uint32_t i1)           \
    {                                                                                             \
        (void)t;                                                                                  \
        trapezoid(D, w, a, i0, i1);                                                               \
    }
DM_REFINE_LOOPS(2)
DM_REFINE_LOOPS(3)

/* The iterate from the current jerk; returns its largest squared
 * displacement since the last neighbour build. */
static double iterate(demill_world *w, refine_args *a)
{
    const int ranges = dm_parallel(w, w->p.n, w->dim == 3 ? predict3 : predict2, a);
    double worst = 0.0;
    for (int t = 0; t < ranges; t++) {
        double d;
        memcpy(&d, &a->worst[t], sizeof d);
        worst = d > worst ? d : worst;
    }
    return worst;
}

/* The mean magnitudes of the accelerations at the start of the step, summed
 * in particle order so that they do not depend on the thread count. */
static void mean_accelerations(const demill_world *w, refine_args *a)
{
    const int D = w->dim, W = D == 3 ? 3 : 1;
    const dm_particles *P = &w->p;
    double sa = 0.0, sw = 0.0, sr = 0.0;
    for (uint32_t i = 0; i < P->n; i++) {
        double a2 = 0.0, w2 = 0.0;
        sr += P->r[i];
        for (int c = 0; c < D; c++)
            a2 += P->f[D * i + c] * P->f[D * i + c];
        sa += sqrt(a2) * P->im[i];
        if (a->rotation) {
            for (int c = 0; c < W; c++)
                w2 += P->t[W * i + c] * P->t[W * i + c];
            sw += sqrt(w2) * P->iinv[i];
        }
    }
    const double g = dm_gravity_magnitude(w);
    a->abar = g + (P->n ? sa / P->n : 0.0);
    /* an angular acceleration α turns the surface at α r: ā / r̄ is the
     * angular scale of ā, which keeps the test meaningful where every α is
     * round-off (a ball rolling freely) */
    a->alphabar = P->n ? (sw + a->abar * P->n / sr) / P->n : 0.0;
}

/* Gives up a step: the world goes back to the start of the step (arrays,
 * walls; the histories are already back) and its forces are evaluated again
 * before the next step. */
static demill_status abort_step(demill_world *w, double d2)
{
    trade(w);
    dm_drum_advance(w, w->time);
    w->forces_valid = false;
    return dm_fail(w, DEMILL_ERR_UNSTABLE,
                   "iterative refinement at t = %.9g s: an iterate moved a particle by %g m "
                   "from where the neighbour lists were built at the start of the step, more "
                   "than half their skin (%g m); the time step is too large for the stiffness "
                   "or the speeds",
                   w->time, sqrt(d2), w->skin);
}

/* The iterations of a step from b = 0; returns 1 if an iterate left the
 * neighbour lists' reach (histories and tallies are then back at the start
 * of the step), with its displacement in *d2. */
static int iterations(demill_world *w, refine_args *a, int *k, int *done, double *d2)
{
    dm_particles *P = &w->p;
    dm_refine *R = &w->refine;
    const int tally = w->energy_tracking || w->events, most = w->refine_max;
    const double eps = a->eps;
    a->jerk = 0;
    if (dm_nlist_needs_rebuild(w, *d2 = iterate(w, a)))
        return 1;
    for (*k = 1;; ++*k) {
        a->fprev = R->fn;
        a->tprev = R->tn;
        a->eps = *k == 1 ? DM_FIRST_EPS : eps;
        if (*k > 1) {
            a->jerk = 1;
            const int out = dm_nlist_needs_rebuild(w, *d2 = iterate(w, a));
            contacts_copy(w, 0);
            if (out)
                return 1;
            swap(&P->f, &R->fprev);
            swap(&P->t, &R->tprev);
            a->fprev = R->fprev;
            a->tprev = R->tprev;
        }
        dm_forces(w, P->vp, P->wp, w->dt, 0.5, tally, 0);
        const int ranges = dm_parallel(w, P->n, w->dim == 3 ? converged3 : converged2, a);
        uint32_t bad = 0;
        for (int t = 0; t < ranges; t++)
            bad += a->bad[t];
        *done = bad == 0;
        a->eps = eps;
        if (*done || *k >= most)
            return 0;
    }
}

static demill_status refine_step(demill_world *w)
{
    dm_particles *P = &w->p;
    refine_args a = {.dt = w->dt, .eps = w->refine_tol, .rotation = w->rotation};
    if (reserve(w) || (w->refine_max > 1 && contacts_save(w)))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory in the refinement integrator");
    mean_accelerations(w, &a);
    dm_drum_advance(w, w->time + w->dt);
    trade(w);
    int k = 0, done = 0;
    double d2;
    if (iterations(w, &a, &k, &done, &d2)) {
        /* rebuild the lists at the start of the step, and start again */
        trade(w);
        demill_status s = dm_nlist_build(w);
        if (!s && w->refine_max > 1 && contacts_save(w))
            s = dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory in the refinement integrator");
        if (s) {
            dm_drum_advance(w, w->time);
            return s;
        }
        trade(w);
        if (iterations(w, &a, &k, &done, &d2))
            return abort_step(w, d2);
    }
    if (!done)
        dm_parallel(w, P->n, w->dim == 3 ? trapezoid3 : trapezoid2, &a);
    swap(&P->v, &P->vp); /* the accepted state moves with its end velocities */
    if (w->rotation)
        swap(&P->w, &P->wp);
    dm_wall_loads_record(w, P->v, P->w, w->dt); /* once, from the accepted iterate */
    w->iterations_last = (uint32_t)k;
    w->force_evals += (uint64_t)k;
    w->unconverged += !done;
    w->time += w->dt;
    w->base.steps++;
    dm_drum_measure(w);
    return DEMILL_OK;
}

demill_status dm_refine_steps(demill_world *w, uint64_t steps)
{
    for (uint64_t s = 0; s < steps; s++) {
        demill_status st = refine_step(w);
        if (st)
            return st;
    }
    return DEMILL_OK;
}
