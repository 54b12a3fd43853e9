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
 * the largest squared displacement since the last neighbour build, as bits. */
typedef struct step_args {
    double dt, h, hth;
    int kick, predict, rotation; /* rotation: the loops also do spin() */
    uint64_t worst[DM_MAX_THREADS];
} step_args;

/* Velocity Verlet's first half, after the second half of the step before
 * when kick is set (the forces have not changed in between): v += dt/2 a;
 * then vp = v + dt a (the end-of-step velocity the dashpots see), v += dt/2 a,
 * x += dt v. Returns the largest squared displacement since the last
 * neighbour build, as bits. The arrays come in as restrict arguments of a
 * function of its own (verlet_move2(), verlet_move3()), as turn()'s do:
 * with restrict pointers taken from P as locals of the inlined loop, GCC 12
 * wanted more run-time alias checks than it makes (six arrays) and left
 * the loop scalar. */
DM_INLINE uint64_t verlet_drift(const int D, double *restrict x, double *restrict v,
                                double *restrict vp, const double *restrict f,
                                const double *restrict im, const double *restrict x0, double dt,
                                double h, int kick, uint32_t i0, uint32_t i1)
{
    uint64_t worst = 0;
    for (size_t i = i0; i < i1; i++) {
        double d2 = 0.0;
        for (int c = 0; c < D; c++) {
            const double acc = f[D * i + c] * im[i];
            double vc = v[D * i + c];
            if (kick)
                vc += h * acc;
            vp[D * i + c] = vc + dt * acc;
            vc += h * acc;
            v[D * i + c] = vc;
            x[D * i + c] += dt * vc;
            const double d = x[D * i + c] - x0[D * i + c];
            d2 += d * d;
        }
        worst = max_bits(worst, d2);
    }
    return worst;
}

#define DM_VERLET_MOVE(D)                                                                         \
    DM_VECTOR_CLONES __attribute__((noinline)) static uint64_t verlet_move##D(                    \
        double *restrict x, double *restrict v, double *restrict vp, const double *restrict f,    \
        const double *restrict im, const double *restrict x0, double dt, double h, int kick,      \
        uint32_t i0, uint32_t i1)                                                                 \
    {                                                                                             \
        return verlet_drift(D, x, v, vp, f, im, x0, dt, h, kick, i0, i1);                         \
    }
DM_VERLET_MOVE(2)
DM_VERLET_MOVE(3)

/* Symplectic Euler: v += dt a, x += dt v. */
DM_INLINE void euler_drift(const int D, dm_particles *P, const step_args *a, uint32_t i0,
                           uint32_t i1, uint64_t *worst_out)
{
    double *restrict x = P->x, *restrict v = P->v;
    const double *restrict f = P->f, *restrict im = P->im, *restrict x0 = P->x0;
    const double dt = a->dt;
    uint64_t worst = 0;
    for (size_t i = i0; i < i1; i++) {
        double d2 = 0.0;
        for (int c = 0; c < D; c++) {
            v[D * i + c] += dt * f[D * i + c] * im[i];
            x[D * i + c] += dt * v[D * i + c];
            const double d = x[D * i + c] - x0[D * i + c];
            d2 += d * d;
        }
        worst = max_bits(worst, d2);
    }
    *worst_out = worst;
}

/* Velocity Verlet's second half: v += h a. */
DM_INLINE void kick(const int D, dm_particles *P, const step_args *a, uint32_t i0, uint32_t i1)
{
    double *restrict v = P->v;
    const double *restrict f = P->f, *restrict im = P->im;
    const double h = a->h;
    for (size_t i = i0; i < i1; i++)
        for (int c = 0; c < D; c++)
            v[D * i + c] += h * (f[D * i + c] * im[i]);
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

/* The rotational half steps: with kick, first ω += h α (the second half of
 * the step before); with predict, wp = ω + 2h α; then ω += h α, and in 2D
 * θ += hth ω, in 3D the orientation turned by hth ω (orient.h) when hth is
 * not 0. */
DM_INLINE void spin(const int D, dm_particles *P, const step_args *a, uint32_t i0, uint32_t i1)
{
    const int W = D == 3 ? 3 : 1;
    double *restrict om = P->w, *restrict wp = P->wp, *restrict theta = P->theta;
    const double *restrict t = P->t, *restrict ii = P->iinv;
    const double h = a->h, hth = a->hth;
    const int kick = a->kick, predict = a->predict;
    for (size_t i = i0; i < i1; i++) {
        for (int c = 0; c < W; c++) {
            const double al = t[W * i + c] * ii[i];
            double o = om[W * i + c];
            if (kick)
                o += h * al;
            if (predict)
                wp[W * i + c] = o + 2.0 * h * al;
            om[W * i + c] = o + h * al;
        }
        if (D == 2)
            theta[i] += hth * om[i];
    }
    if (D == 3 && hth != 0.0)
        turn(P->q[0], P->q[1], P->q[2], P->q[3], om, hth, i0, i1);
}

/* The loops for each dimension, as dm_parallel() ranges. */
#define DM_STEP_LOOPS(D)                                                                          \
    DM_VECTOR_CLONES static void verlet_drift##D(demill_world *w, void *a, int t, uint32_t i0,    \
                                                 uint32_t i1)                                     \
    {                                                                                             \
        step_args *s = a;                                                                         \
        dm_particles *P = &w->p;                                                                  \
        s->worst[t] = verlet_move##D(P->x, P->v, P->vp, P->f, P->im, P->x0, s->dt, s->h, s->kick, \
                                     i0, i1);                                                     \
        if (s->rotation)                                                                          \
            spin(D, &w->p, s, i0, i1);                                                            \
    }                                                                                             \
    DM_VECTOR_CLONES static void euler_drift##D(demill_world *w, void *a, int t, uint32_t i0,     \
                                                uint32_t i1)                                      \
    {                                                                                             \
        step_args *s = a;                                                                         \
        euler_drift(D, &w->p, s, i0, i1, &s->worst[t]);                                           \
        if (s->rotation)                                                                          \
            spin(D, &w->p, s, i0, i1);                                                            \
    }                                                                                             \
    DM_VECTOR_CLONES static void kick##D(demill_world *w, void *a, int t, uint32_t i0,            \
                                         uint32_t i1)                                             \
    {                                                                                             \
        const step_args *s = a;                                                                   \
        (void)t;                                                                                  \
        kick(D, &w->p, s, i0, i1);                                                                \
        if (s->rotation)                                                                          \
            spin(D, &w->p, s, i0, i1);                                                            \
    }
DM_STEP_LOOPS(2)
DM_STEP_LOOPS(3)

/* Runs a drift loop; returns the largest squared displacement. */
static double drift(demill_world *w, dm_range_fn fn, step_args *a)
{
    const int ranges = dm_parallel(w, w->p.n, fn, a);
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
                                 const double *wp, double reach)
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
    dm_forces(w, vp, wp, w->dt, reach, w->energy_tracking || w->events);
    if (w->local_damping) {
        const double lost = local_damping(w);
        if (w->energy_tracking || w->events)
            w->tally.diss_local += lost;
    }
    dm_wall_loads_record(w, vp, wp, w->dt);
    dm_drum_measure(w);
    return DEMILL_OK;
}

/* Velocity Verlet; within one call the second half of each step is done
 * together with the first half of the next. */
static demill_status verlet(demill_world *w, uint64_t steps)
{
    const int d3 = w->dim == 3;
    dm_particles *P = &w->p;
    step_args a = {.dt = w->dt, .h = 0.5 * w->dt, .hth = w->dt, .predict = 1,
                   .rotation = w->rotation};
    if (!steps)
        return DEMILL_OK;
    for (uint64_t s = 0; s < steps; s++) {
        a.kick = s > 0;
        double d2 = drift(w, d3 ? verlet_drift3 : verlet_drift2, &a);
        if (w->live_clumps)
            d2 = fmax(d2, dm_clumps_drift(w, w->dt, a.kick, 1));
        if (w->nbodies)
            dm_bodies_drift(w, w->dt, a.kick, 1);
        demill_status st = finish_step(w, d2, P->vp, P->wp, 0.5);
        if (st)
            return st;
    }
    a.kick = a.predict = 0;
    a.hth = 0.0;
    dm_parallel(w, P->n, d3 ? kick3 : kick2, &a);
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
    step_args a = {.dt = w->dt, .h = w->dt, .hth = w->dt, .rotation = w->rotation};
    for (uint64_t s = 0; s < steps; s++) {
        double d2 = drift(w, d3 ? euler_drift3 : euler_drift2, &a);
        if (w->live_clumps)
            d2 = fmax(d2, dm_clumps_drift(w, w->dt, 0, 0));
        if (w->nbodies)
            dm_bodies_drift(w, w->dt, 0, 0);
        demill_status st = finish_step(w, d2, P->v, P->w, 1.0);
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
        dm_forces(w, w->p.v, w->p.w, 0.0, 0.0, 0);
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
