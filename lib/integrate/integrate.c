/* integrate.c: time stepping (PHYSICS.md §8) behind one interface,
 * dm_integrate(): velocity Verlet (default) and symplectic Euler. Each step
 * moves the particles, advances the walls, rebuilds the neighbour lists when
 * the skin is used up, and evaluates the forces of the new state.
 *
 * Velocity Verlet here differs from the usual DEM form in one respect: the
 * dashpots and friction see the predicted end-of-step velocity v + a Δt rather
 * than the half-step velocity. The half-step form treats the dashpot as an
 * explicit Euler step and over-damps by the factor (1 + ξ ω Δt), a first-order
 * error (10 % in the restitution at e = 0.1 and 50 steps per contact); the
 * predicted form is second order. The tangential spring still accumulates
 * the exact relative displacement of the step, from the half-step velocity. */
#include <string.h>

#include "../core/internal.h"

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

/* Velocity Verlet's first half, after the second half of the step before
 * when kick is set (the forces have not changed in between): v += dt/2 a;
 * then vp = v + dt a (the end-of-step velocity the dashpots see), v += dt/2 a,
 * x += dt v. Returns the largest squared displacement since the last
 * neighbour build. */
DM_INLINE double verlet_drift(const int D, dm_particles *P, double dt, const int kick)
{
    double *restrict x = P->x, *restrict v = P->v, *restrict vp = P->vp;
    const double *restrict f = P->f, *restrict im = P->im, *restrict x0 = P->x0;
    const double h = 0.5 * dt;
    uint64_t worst = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        double d2 = 0.0;
        for (int c = 0; c < D; c++) {
            const double a = f[D * i + c] * im[i];
            double vc = v[D * i + c];
            if (kick)
                vc += h * a;
            vp[D * i + c] = vc + dt * a;
            vc += h * a;
            v[D * i + c] = vc;
            x[D * i + c] += dt * vc;
            const double d = x[D * i + c] - x0[D * i + c];
            d2 += d * d;
        }
        worst = max_bits(worst, d2);
    }
    return from_bits(worst);
}

/* Symplectic Euler: v += dt a, x += dt v. Returns as verlet_drift(). */
DM_INLINE double euler_drift(const int D, dm_particles *P, double dt)
{
    double *restrict x = P->x, *restrict v = P->v;
    const double *restrict f = P->f, *restrict im = P->im, *restrict x0 = P->x0;
    uint64_t worst = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        double d2 = 0.0;
        for (int c = 0; c < D; c++) {
            v[D * i + c] += dt * f[D * i + c] * im[i];
            x[D * i + c] += dt * v[D * i + c];
            const double d = x[D * i + c] - x0[D * i + c];
            d2 += d * d;
        }
        worst = max_bits(worst, d2);
    }
    return from_bits(worst);
}

/* Velocity Verlet's second half: v += h a. */
DM_INLINE void kick(const int D, dm_particles *P, double h)
{
    double *restrict v = P->v;
    const double *restrict f = P->f, *restrict im = P->im;
    for (uint32_t i = 0; i < P->n; i++)
        for (int c = 0; c < D; c++)
            v[D * i + c] += h * (f[D * i + c] * im[i]);
}

/* The rotational half steps: with kick, first ω += h α (the second half of
 * the step before); with predict, wp = ω + 2h α; then ω += h α, and in 2D
 * θ += hth ω. */
DM_INLINE void spin(const int D, dm_particles *P, double h, const int kick, const int predict,
                    double hth)
{
    const int W = D == 3 ? 3 : 1;
    double *restrict om = P->w, *restrict wp = P->wp;
    const double *restrict t = P->t, *restrict ii = P->iinv;
    for (uint32_t i = 0; i < P->n; i++)
        for (int c = 0; c < W; c++) {
            const double al = t[W * i + c] * ii[i];
            double o = om[W * i + c];
            if (kick)
                o += h * al;
            if (predict)
                wp[W * i + c] = o + 2.0 * h * al;
            om[W * i + c] = o + h * al;
        }
    if (D == 2 && hth != 0.0)
        for (uint32_t i = 0; i < P->n; i++)
            P->theta[i] += hth * om[i];
}

/* The end of every step: the clock, the walls, the lists and the forces of
 * the new state. */
static demill_status finish_step(demill_world *w, double max_disp2, const double *vp,
                                 const double *wp, double reach)
{
    w->time += w->dt;
    w->steps++;
    dm_walls_advance(w, w->time);
    if (dm_nlist_needs_rebuild(w, max_disp2)) {
        demill_status s = dm_nlist_build(w);
        if (s)
            return s;
    }
    dm_forces(w, vp, wp, w->dt, reach, w->energy_tracking || w->events);
    dm_drum_measure(w);
    return DEMILL_OK;
}

/* Velocity Verlet; within one call the second half of each step is done
 * together with the first half of the next. */
DM_INLINE demill_status verlet(const int D, demill_world *w, uint64_t steps)
{
    dm_particles *P = &w->p;
    const double dt = w->dt, h = 0.5 * dt;
    if (!steps)
        return DEMILL_OK;
    for (uint64_t s = 0; s < steps; s++) {
        const double d2 = s ? verlet_drift(D, P, dt, 1) : verlet_drift(D, P, dt, 0);
        if (w->rotation) {
            if (s)
                spin(D, P, h, 1, 1, dt);
            else
                spin(D, P, h, 0, 1, dt);
        }
        demill_status st = finish_step(w, d2, P->vp, P->wp, 0.5);
        if (st)
            return st;
    }
    kick(D, P, h);
    if (w->rotation)
        spin(D, P, h, 0, 0, 0.0);
    return DEMILL_OK;
}

DM_INLINE demill_status euler(const int D, demill_world *w, uint64_t steps)
{
    dm_particles *P = &w->p;
    for (uint64_t s = 0; s < steps; s++) {
        const double dt = w->dt;
        double d2 = euler_drift(D, P, dt);
        if (w->rotation)
            spin(D, P, dt, 0, 0, dt);
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
    demill_status s = dm_resolve_pairs(w, true);
    if (s || (s = dm_drum_prepare(w)))
        return s;
    if (!w->nlist_valid && (s = dm_nlist_build(w)))
        return s;
    if (!w->forces_valid)
        dm_forces(w, w->p.v, w->p.w, 0.0, 0.0, 0);
    return DEMILL_OK;
}

/* (static: a cloned function with external linkage would be exported) */
DM_VECTOR_CLONES static demill_status integrate(demill_world *w, uint64_t steps)
{
    if (w->integrator == DEMILL_INTEGRATOR_SYMPLECTIC_EULER)
        return w->dim == 3 ? euler(3, w, steps) : euler(2, w, steps);
    return w->dim == 3 ? verlet(3, w, steps) : verlet(2, w, steps);
}

demill_status dm_integrate(demill_world *w, uint64_t steps)
{
    return integrate(w, steps);
}

DEMILL_API demill_status demill_world_step(demill_world *w, uint64_t steps)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if ((s = dm_prepare_step(w)) || (s = dm_integrate(w, steps)))
        return s;
    dm_clear_error(w);
    return DEMILL_OK;
}
