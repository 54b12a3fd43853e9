/* integrate.c: time stepping (docs/physics.md §8) behind one interface,
 * dm_integrate(): velocity Verlet (default), symplectic Euler and the
 * iterative refinement (refine.c). Each step
 * moves the particles, advances the walls, rebuilds the neighbour lists when
 * the skin is used up, evaluates the forces of the new state and adds them
 * to the loads the walls record. Bodies
 * (bodies.c) and clumps (clumps.c) take the same half steps as the
 * particles, and the clumps then put their members in place.
 *
 * Velocity Verlet here differs from the usual DEM form in one respect: the
 * dashpots and friction see the predicted end-of-step velocity v + a Δt rather
 * than the half-step velocity. The half-step form treats the dashpot as an
 * explicit Euler step and over-damps by the factor (1 + ξ ω Δt), a first-order
 * error (10 % in the restitution at e = 0.1 and 50 steps per contact); the
 * predicted form is second order. The tangential spring still accumulates
 * the exact relative displacement of the step, from the half-step velocity.
 *
 * Local damping (DEMILL_MATERIAL_LOCAL_DAMPING) changes the forces of each
 * step's evaluation before the particles move with them (local_damping());
 * a world without it does not reach that code. */
#include <math.h>
#include <string.h>

#include "base/status.h"
#include "base/threads.h"
#include "physics/bodies/bodies.h"
#include "physics/clumps/clumps.h"
#include "physics/broadphase/broadphase.h"
#include "physics/contact/contact.h"
#include "physics/integrate/integrate.h"
#include "physics/state/orient.h"
#include "physics/mill/mill.h"

#define DM_INLINE static inline __attribute__((always_inline))

/* The larger of a and b >= 0 as bit patterns, which order as the values
 * do: a maximum that vectorises. */
DM_INLINE uint64_t max_bits(uint64_t a, double b)
{
    uint64_t u;
    memcpy(&u, &b, sizeof u);
    return u > a ? u : a;
}

DM_INLINE double from_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* What the loops below need, and what they return per range (dm_parallel):
 * the largest squared displacement since the last neighbour build, as bits.
 * finish: each range first takes the sums of its particles that the last
 * force evaluation left (dm_forces_finish()); gravity: the drift also sets
 * each particle's force to its weight m g and its torque to 0 once it has
 * used them, the start of the next force evaluation's sums
 * (DM_FORCES_PRESET), while the block is in cache. */
typedef struct step_args {
    double dt, h, hth, g[3]; /* hth: the time the orientations turn by (0: they do not) */
    int kick, rotation, finish, gravity; /* rotation: the loops also spin */
    uint64_t worst[DM_MAX_THREADS];
} step_args;

/* The passes below run over a range's particles in blocks of BLOCK, each
 * pass a loop of its own over the flat component arrays (component c of
 * particle i at D i + c), with the per-particle factors 1/m and 1/I spread
 * to every component first (spread()): unit-stride loops, which GCC
 * vectorises without shuffles, where a loop over particles and their D
 * components vectorises into shuffles of every array (3 in 3D). A block's
 * arrays (a few KB each) stay in L1 from pass to pass. Each loop is a
 * function of its own with restrict arguments, as turn()'s are: with
 * restrict pointers taken from P as locals of an inlined loop, GCC 12
 * wanted more run-time alias checks than it makes and left the loop
 * scalar. The arithmetic is the same, operation for operation, as a loop
 * over particles and components: the results do not change. */
#define BLOCK 128

#define DM_FLAT __attribute__((noinline)) DM_VECTOR_CLONES static void

/* out[C k + c] = a[k] for particles k < n: a per-particle value for each of
 * its C components. */
#define DM_SPREAD(C)                                                                              \
    DM_FLAT spread##C(const double *restrict a, double *restrict out, size_t n)                  \
    {                                                                                             \
        for (size_t k = 0; k < n; k++)                                                            \
            for (int c = 0; c < C; c++)                                                           \
                out[C * k + c] = a[k];                                                            \
    }                                                                                             \
    /* f[C k + c] = m[k] g[c], t[W k ..] = 0 (W = 3 in 3D, else 1): the weights of n          \
     * particles, their torques 0 */                                                             \
    DM_FLAT weigh##C(const double *restrict m, const double *restrict g, double *restrict f,     \
                     double *restrict t, size_t n)                                                \
    {                                                                                             \
        for (size_t k = 0; k < n; k++) {                                                          \
            for (int c = 0; c < C; c++)                                                           \
                f[C * k + c] = m[k] * g[c];                                                       \
            for (int c = 0; c < (C == 3 ? 3 : 1); c++)                                            \
                t[(C == 3 ? 3 : 1) * k + c] = 0.0;                                                \
        }                                                                                         \
    }                                                                                             \
    /* The largest of n particles' squared displacements |d|², from their squared components dd \
     * (summed in component order, as a loop over components would), with worst, as bits. */   \
    __attribute__((noinline)) DM_VECTOR_CLONES static uint64_t farthest##C(                      \
        const double *restrict dd, uint64_t worst, size_t n)                                      \
    {                                                                                             \
        for (size_t k = 0; k < n; k++) {                                                          \
            double d2 = 0.0;                                                                      \
            for (int c = 0; c < C; c++)                                                           \
                d2 += dd[C * k + c];                                                              \
            worst = max_bits(worst, d2);                                                          \
        }                                                                                         \
        return worst;                                                                             \
    }
DM_SPREAD(2)
DM_SPREAD(3)

/* Velocity Verlet's first half, after the second half of the step before
 * when KICK is set (the forces have not changed in between), over n
 * components: v += dt/2 a; then vp = v + dt a (the end-of-step velocity the
 * dashpots see), v += dt/2 a, x += dt v; dd = (x - x0)², the squared
 * displacement since the last neighbour build. im: 1/m spread. */
#define DM_VERLET_FLAT(KICK)                                                                      \
    DM_FLAT verlet_flat##KICK(double *restrict x, double *restrict v, double *restrict vp,       \
                              const double *restrict f, const double *restrict im,                \
                              const double *restrict x0, double *restrict dd, double dt,          \
                              double h, size_t n)                                                 \
    {                                                                                             \
        for (size_t e = 0; e < n; e++) {                                                          \
            const double acc = f[e] * im[e];                                                      \
            double vc = v[e];                                                                     \
            if (KICK)                                                                             \
                vc += h * acc;                                                                    \
            vp[e] = vc + dt * acc;                                                                \
            vc += h * acc;                                                                        \
            v[e] = vc;                                                                            \
            x[e] += dt * vc;                                                                      \
            const double d = x[e] - x0[e];                                                        \
            dd[e] = d * d;                                                                        \
        }                                                                                         \
    }
DM_VERLET_FLAT(0)
DM_VERLET_FLAT(1)

/* Symplectic Euler over n components: v += dt a, x += dt v, dd as above. */
DM_FLAT euler_flat(double *restrict x, double *restrict v, const double *restrict f,
                   const double *restrict im, const double *restrict x0, double *restrict dd,
                   double dt, size_t n)
{
    for (size_t e = 0; e < n; e++) {
        v[e] += dt * f[e] * im[e];
        x[e] += dt * v[e];
        const double d = x[e] - x0[e];
        dd[e] = d * d;
    }
}

/* Velocity Verlet's second half over n components: v += h a. */
DM_FLAT kick_flat(double *restrict v, const double *restrict f, const double *restrict im,
                  double h, size_t n)
{
    for (size_t e = 0; e < n; e++)
        v[e] += h * (f[e] * im[e]);
}

/* The rotational half steps over n components, ii: 1/I spread: with KICK,
 * first ω += h α (the second half of the step before); with PREDICT,
 * wp = ω + 2h α; then ω += h α. */
#define DM_SPIN_FLAT(KICK, PREDICT)                                                               \
    DM_FLAT spin_flat##KICK##PREDICT(double *restrict om, double *restrict wp,                   \
                                     const double *restrict t, const double *restrict ii,         \
                                     double h, size_t n)                                          \
    {                                                                                             \
        for (size_t e = 0; e < n; e++) {                                                          \
            const double al = t[e] * ii[e];                                                       \
            double o = om[e];                                                                     \
            if (KICK)                                                                             \
                o += h * al;                                                                      \
            if (PREDICT)                                                                          \
                wp[e] = o + 2.0 * h * al;                                                         \
            om[e] = o + h * al;                                                                   \
        }                                                                                         \
    }
DM_SPIN_FLAT(0, 0)
DM_SPIN_FLAT(0, 1)
DM_SPIN_FLAT(1, 1)

/* 2D: θ += hth ω over n particles. */
DM_FLAT angle_flat(double *restrict theta, const double *restrict om, double hth, size_t n)
{
    for (size_t i = 0; i < n; i++)
        theta[i] += hth * om[i];
}

/* Turns the orientations (the four arrays qw, qx, qy, qz) of particles i0
 * to i1 - 1 by k ω (ω: 3 per particle), as dm_quat_turn() (orient.h) does
 * each, in two passes: one without branches, which vectorises, turns the
 * particles whose angle the series takes and leaves the others as they were
 * (a blend of bit patterns); a second, taken only if the first met such a
 * particle, turns those with libm. A function of its own, whose restrict
 * arguments tell GCC that the arrays do not overlap: inlined, the loop does
 * not vectorise. */
DM_VECTOR_CLONES __attribute__((noinline)) static void
turn(double *restrict qw, double *restrict qx, double *restrict qy, double *restrict qz,
     const double *restrict om, double k, uint32_t i0, uint32_t i1)
{
    uint64_t far = 0;
    for (size_t i = i0; i < i1; i++) { /* size_t: a uint32_t 3 i may wrap, which stops GCC */
        const double hx = 0.5 * k * om[3 * i], hy = 0.5 * k * om[3 * i + 1],
                     hz = 0.5 * k * om[3 * i + 2];
        const double a2 = hx * hx + hy * hy + hz * hz;
        const uint64_t keep = (uint64_t)0 - (uint64_t)(a2 <= DM_QUAT_SERIES_A2); /* all ones */
        far |= ~keep;
        double c, s, n[4] = {qw[i], qx[i], qy[i], qz[i]};
        dm_quat_series(a2, &c, &s);
        dm_quat_mul_turn(n, c, s, hx, hy, hz);
        double *const d[4] = {qw, qx, qy, qz};
        for (int j = 0; j < 4; j++) {
            uint64_t un, uq;
            memcpy(&un, &n[j], sizeof un);
            memcpy(&uq, &d[j][i], sizeof uq);
            uq = (un & keep) | (uq & ~keep);
            memcpy(&d[j][i], &uq, sizeof uq);
        }
    }
    if (!far)
        return;
    for (uint32_t i = i0; i < i1; i++) {
        const double hx = 0.5 * k * om[3 * i], hy = 0.5 * k * om[3 * i + 1],
                     hz = 0.5 * k * om[3 * i + 2];
        if (hx * hx + hy * hy + hz * hz > DM_QUAT_SERIES_A2) {
            double q[4] = {qw[i], qx[i], qy[i], qz[i]};
            dm_quat_turn(q, om + 3 * (size_t)i, k);
            qw[i] = q[0], qx[i] = q[1], qy[i] = q[2], qz[i] = q[3];
        }
    }
}

/* The kinds of pass over a block: velocity Verlet's first half (with the
 * second half of the step before when a->kick), symplectic Euler's step,
 * and velocity Verlet's last second half (a kick alone). */
enum { VERLET, EULER, KICK };

/* One pass of kind `kind` over particles i0 .. i1 - 1 < i0 + BLOCK; returns
 * the largest squared displacement since the last neighbour build (bits)
 * with worst. The rotational half steps take the same kicks (spin: with
 * predict, wp = ω + 2h α; θ or the orientation turned by hth ω after). */
DM_INLINE uint64_t block(const int D, const int kind, dm_particles *P, const step_args *a,
                         uint32_t i0, uint32_t i1, uint64_t worst)
{
    const int W = D == 3 ? 3 : 1;
    const size_t n = i1 - i0, e0 = (size_t)D * i0;
    double spread_[3 * BLOCK], dd[3 * BLOCK];
    (D == 3 ? spread3 : spread2)(P->im + i0, spread_, n);
    if (kind == VERLET) {
        (a->kick ? verlet_flat1 : verlet_flat0)(P->x + e0, P->v + e0, P->vp + e0, P->f + e0,
                                                spread_, P->x0 + e0, dd, a->dt, a->h, D * n);
        worst = (D == 3 ? farthest3 : farthest2)(dd, worst, n);
    } else if (kind == EULER) {
        euler_flat(P->x + e0, P->v + e0, P->f + e0, spread_, P->x0 + e0, dd, a->dt, D * n);
        worst = (D == 3 ? farthest3 : farthest2)(dd, worst, n);
    } else {
        kick_flat(P->v + e0, P->f + e0, spread_, a->h, D * n);
    }
    if (a->rotation) {
        const size_t w0 = (size_t)W * i0;
        const double *ii = P->iinv + i0;
        if (D == 3) {
            spread3(ii, spread_, n);
            ii = spread_;
        }
        (kind != VERLET ? spin_flat00
         : a->kick      ? spin_flat11
                        : spin_flat01)(P->w + w0, P->wp + w0, P->t + w0, ii, a->h, W * n);
        if (a->hth != 0.0 && D == 2)
            angle_flat(P->theta + i0, P->w + i0, a->hth, n);
        if (a->hth != 0.0 && D == 3)
            turn(P->q[0], P->q[1], P->q[2], P->q[3], P->w, a->hth, i0, i1);
    }
    if (a->gravity)
        (D == 3 ? weigh3 : weigh2)(P->m + i0, a->g, P->f + e0, P->t + (size_t)W * i0, n);
    return worst;
}

/* The passes for each dimension, as dm_parallel() ranges, block by block. */
#define DM_STEP_LOOPS(D)                                                                          \
    static void verlet_drift##D(demill_world *w, void *a, int t, uint32_t i0, uint32_t i1)       \
    {                                                                                             \
        step_args *s = a;                                                                         \
        uint64_t worst = 0;                                                                       \
        if (s->finish)                                                                            \
            dm_forces_finish(w, i0, i1);                                                          \
        for (uint32_t b = i0; b < i1; b += BLOCK)                                                 \
            worst = block(D, VERLET, &w->p, s, b, i1 - b < BLOCK ? i1 : b + BLOCK, worst);        \
        s->worst[t] = worst;                                                                      \
    }                                                                                             \
    static void euler_drift##D(demill_world *w, void *a, int t, uint32_t i0, uint32_t i1)        \
    {                                                                                             \
        step_args *s = a;                                                                         \
        uint64_t worst = 0;                                                                       \
        if (s->finish)                                                                            \
            dm_forces_finish(w, i0, i1);                                                          \
        for (uint32_t b = i0; b < i1; b += BLOCK)                                                 \
            worst = block(D, EULER, &w->p, s, b, i1 - b < BLOCK ? i1 : b + BLOCK, worst);         \
        s->worst[t] = worst;                                                                      \
    }                                                                                             \
    static void kick##D(demill_world *w, void *a, int t, uint32_t i0, uint32_t i1)               \
    {                                                                                             \
        (void)t;                                                                                  \
        if (((step_args *)a)->finish)                                                             \
            dm_forces_finish(w, i0, i1);                                                          \
        for (uint32_t b = i0; b < i1; b += BLOCK)                                                 \
            block(D, KICK, &w->p, a, b, i1 - b < BLOCK ? i1 : b + BLOCK, 0);                      \
    }
DM_STEP_LOOPS(2)
DM_STEP_LOOPS(3)

/* Runs a drift or kick loop, which first takes the sums the last
 * dm_forces() left to it, on the same ranges (DM_FORCES_DEFER); returns the
 * largest squared displacement. With a->gravity the forces are set to the
 * particles' weights as the loop goes: they are not the forces of the state
 * until the next dm_forces(). */
static double drift(demill_world *w, dm_range_fn fn, step_args *a)
{
    a->finish = w->res.pending != 0;
    const int ranges = dm_parallel(w, w->p.n, fn, a);
    w->res.pending = 0;
    if (a->finish || a->gravity)
        w->forces_valid = !a->gravity;
    uint64_t worst = 0;
    for (int t = 0; t < ranges; t++)
        worst = a->worst[t] > worst ? a->worst[t] : worst;
    return from_bits(worst);
}

/* Local damping (Cundall 1987, "Distinct element models of rock and soil
 * structure"; as in Itasca's PFC; docs/physics.md, Local damping): each
 * component of the force F and the torque M of a particle whose material has
 * α > 0 is opposed by α |F_c| (α |M_c|) against the sign of its velocity
 * (angular velocity) component, F_c += -α |F_c| sign(v_c). v and ω are the
 * velocities the step moved with: the half-step velocity before the forces'
 * time (velocity Verlet) or the last step's (symplectic Euler), as PFC's
 * central differences use v(t - Δt/2). Fixed particles are left alone.
 *
 * The energy it takes out is booked as -Δt F_d·(v + Δt/2 a) (and the same
 * for the spin), a the damped acceleration: with either integrator that is
 * exactly the change of kinetic energy the force F_d makes over the kicks it
 * enters (velocity Verlet's two half kicks from v(t - Δt/2) to v(t + Δt/2),
 * symplectic Euler's step from v to v + Δt a). Clumps' members are left
 * alone too (their clump moves them: local damping does not act on clumps
 * yet). Serial, in storage order, so
 * that the sum does not depend on the threads; a world with local damping
 * is a quasi-static one, whose cost the contacts dominate. */
static double local_damping(demill_world *w)
{
    const int D = w->dim, W = dm_wdim(w);
    dm_particles *P = &w->p;
    const double dt = w->dt, h = 0.5 * w->dt;
    double work = 0.0;
    for (uint32_t i = 0; i < P->n; i++) {
        const double alpha = w->mats[P->mat[i]].local_damping;
        if (alpha == 0.0 || dm_particle_fixed(P, i) || P->clump[i])
            continue;
        for (int c = 0; c < D; c++) {
            const double f = P->f[D * i + c], v = P->v[D * i + c];
            const double fd = v > 0.0 ? -alpha * fabs(f) : v < 0.0 ? alpha * fabs(f) : 0.0;
            P->f[D * i + c] = f + fd;
            work += fd * (v + h * (f + fd) * P->im[i]);
        }
        if (!w->rotation)
            continue;
        for (int c = 0; c < W; c++) {
            const double t = P->t[W * i + c], o = P->w[W * i + c];
            const double td = o > 0.0 ? -alpha * fabs(t) : o < 0.0 ? alpha * fabs(t) : 0.0;
            P->t[W * i + c] = t + td;
            work += td * (o + h * (t + td) * P->iinv[i]);
        }
    }
    return -work * dt;
}

/* The end of every step: the clock, the walls, the lists and the forces of
 * the new state. */
static demill_status finish_step(demill_world *w, double max_disp2, const double *vp,
                                 const double *wp, double reach, int options)
{
    w->time += w->dt;
    w->base.steps++;
    w->iterations_last = 1;
    w->force_evals++;
    dm_drum_advance(w, w->time);
    if (dm_nlist_needs_rebuild(w, max_disp2)) {
        demill_status s = dm_nlist_build(w);
        if (s)
            return s;
    }
    if (w->local_damping) /* which reads every force at once */
        options &= ~DM_FORCES_DEFER;
    dm_forces(w, vp, wp, w->dt, reach, w->energy_tracking || w->events, options);
    if (w->local_damping) {
        const double lost = local_damping(w);
        if (w->energy_tracking || w->events)
            w->tally.diss_local += lost;
    }
    dm_wall_loads_record(w, vp, wp, w->dt);
    dm_drum_measure(w);
    return DEMILL_OK;
}

/* The step_args of an integrator's drift, with half step h: the drift
 * sets the forces to the weights unless the clumps still need the members'
 * forces after it (dm_clumps_drift). */
static step_args step_args_of(const demill_world *w, double h)
{
    return (step_args){.dt = w->dt, .h = h, .hth = w->orient ? w->dt : 0.0,
                       .g = {w->g[0], w->g[1], w->g[2]},
                       .rotation = w->rotation, .gravity = !w->live_clumps};
}

/* The options of a step's force evaluation after a drift with a: the
 * forces preset to the weights if it set them, and the sums the chunks
 * leave deferred to the next drift or kick if there is one. */
static int forces_options(const step_args *a, int next)
{
    return (a->gravity ? DM_FORCES_PRESET : 0) | (next ? DM_FORCES_DEFER : 0);
}

/* Velocity Verlet; within one call the second half of each step is done
 * together with the first half of the next. */
static demill_status verlet(demill_world *w, uint64_t steps)
{
    const int d3 = w->dim == 3;
    dm_particles *P = &w->p;
    step_args a = step_args_of(w, 0.5 * w->dt);
    if (!steps)
        return DEMILL_OK;
    for (uint64_t s = 0; s < steps; s++) {
        a.kick = s > 0;
        double d2 = drift(w, d3 ? verlet_drift3 : verlet_drift2, &a);
        if (w->live_clumps)
            d2 = fmax(d2, dm_clumps_drift(w, w->dt, a.kick, 1));
        if (w->nbodies)
            dm_bodies_drift(w, w->dt, a.kick, 1);
        demill_status st = finish_step(w, d2, P->vp, P->wp, 0.5, forces_options(&a, 1));
        if (st)
            return st;
    }
    a.kick = a.gravity = 0;
    a.hth = 0.0;
    drift(w, d3 ? kick3 : kick2, &a);
    if (w->live_clumps)
        dm_clumps_kick(w, a.h);
    if (w->nbodies)
        dm_bodies_kick(w, a.h);
    return DEMILL_OK;
}

static demill_status euler(demill_world *w, uint64_t steps)
{
    const int d3 = w->dim == 3;
    dm_particles *P = &w->p;
    step_args a = step_args_of(w, w->dt);
    for (uint64_t s = 0; s < steps; s++) {
        double d2 = drift(w, d3 ? euler_drift3 : euler_drift2, &a);
        if (w->live_clumps)
            d2 = fmax(d2, dm_clumps_drift(w, w->dt, 0, 0));
        if (w->nbodies)
            dm_bodies_drift(w, w->dt, 0, 0);
        demill_status st = finish_step(w, d2, P->v, P->w, 1.0, forces_options(&a, s + 1 < steps));
        if (st)
            return st;
    }
    return DEMILL_OK;
}

/* Makes the world ready to step: contact models resolved and complete, lists
 * built, forces of the current state known. Changes nothing physical. */
demill_status dm_prepare_step(demill_world *w)
{
    if (w->time + w->dt == w->time)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_step: at t = %.17g s a time step of %g s does not advance the "
                       "clock; set world.time nearer 0",
                       w->time, w->dt);
    uint32_t bodies = 0;
    for (uint32_t k = 0; k < w->nbodies; k++)
        bodies += dm_body_live(w, k);
    if (bodies && w->integrator == DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_step: the iterative refinement does not integrate bodies (the "
                       "world has %u); use velocity Verlet or symplectic Euler",
                       bodies);
    if (w->live_clumps && w->integrator == DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_step: the iterative refinement does not integrate clumps (the "
                       "world has %u); use velocity Verlet or symplectic Euler",
                       w->live_clumps);
    demill_status s = dm_resolve_pairs(w, true);
    if (s)
        return s;
    if (w->local_damping && w->integrator == DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_step: the iterative refinement does not integrate local damping "
                       "(DEMILL_MATERIAL_LOCAL_DAMPING > 0 for a material with particles); use "
                       "velocity Verlet or symplectic Euler");
    if ((s = dm_drum_prepare(w)))
        return s;
    if (!w->nlist_valid && (s = dm_nlist_build(w)))
        return s;
    if (!w->forces_valid)
        dm_forces(w, w->p.v, w->p.w, 0.0, 0.0, 0, 0);
    return DEMILL_OK;
}

demill_status dm_integrate(demill_world *w, uint64_t steps)
{
    switch (w->integrator) {
    case DEMILL_INTEGRATOR_SYMPLECTIC_EULER: return euler(w, steps);
    case DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT: return dm_refine_steps(w, steps);
    default: return verlet(w, steps);
    }
}
