/* watchdog.c: the stability watchdog (docs/physics.md §8): steps in
 * stretches of world.watchdog_interval, checks the state after each, and
 * keeps a copy of the last state that passed, to which the world returns
 * when a check fails.
 *
 * The checks, in order:
 *  - positions, velocities and angular velocities are finite;
 *  - no contact overlaps by more than world.watchdog_overlap of its smaller
 *    radius (a wall counts as infinitely large);
 *  - energy is not created. With energy tracking on (the default) the
 *    balance kinetic + potential + elastic + dissipated - wall work - the
 *    energy feeds brought in net of what outlets took out may not
 *    have grown since the run started by more than a quarter of the energy
 *    that went through the system since (the largest kinetic + elastic
 *    energy and the range of potential energy seen at checks, the energy
 *    dissipated and the work of the walls): the integrators' own errors are
 *    far smaller than that at any stable step, an instability soon far
 *    larger. With tracking off, the kinetic energy may be at most twice what
 *    the last checked state could supply (its kinetic and elastic energy,
 *    the potential energy released and the drum's work since); where walls
 *    other than the drum move, nothing measures their work and this check
 *    is left out.
 * The end of every call is checked too, so that no call returns DEMILL_OK
 * on a state that fails them. A copy of the state is not taken
 * at every call: a failure found in a call whose start is later than the
 * last copy puts that copy back and steps it on to where the call started,
 * which gives the call's starting state bitwise (the integrators give the
 * same state however a run is split), so that a failure never undoes a call
 * that succeeded. A fresh copy is taken when a run starts after the world
 * was changed through the API (dm_changed), so that a failure never undoes
 * the caller's own changes either. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

void dm_watch_free(demill_world *w)
{
    if (w->watch.good) {
        dm_state_free(w->watch.good);
        free(w->watch.good);
    }
    memset(&w->watch, 0, sizeof w->watch);
}

/* The energies of the current state; 0 with *unknown set when walls other
 * than the drum's move and nothing tallies their work. */
static demill_status energies(demill_world *w, dm_watch_energy *e, int *unknown)
{
    double t[DM_ENERGIES];
    demill_status s = dm_energies(w, 1, t);
    const dm_tally *y = &w->tally;
    const double *b = t + DM_E_BODY;
    e->kinetic = t[DM_E_KT] + t[DM_E_KR] + b[DM_BODY_KINETIC];
    e->potential = t[DM_E_POT] + b[DM_BODY_POTENTIAL];
    e->elastic = t[DM_E_NORMAL] + t[DM_E_TANGENTIAL] + t[DM_E_ROLLING] + b[DM_BODY_ELASTIC];
    /* the work against cohesion, which may be negative, is spent as
     * dissipation is */
    e->dissipated = dm_tally_dissipated(y) + y->work_cohesion + b[DM_BODY_DISSIPATED];
    e->work = (w->energy_tracking ? y->wall_work : w->drum.alive ? w->drum.energy_in : 0.0) +
              w->flows.energy + b[DM_BODY_WORK];
    *unknown = 0;
    for (uint32_t k = 0; k < w->nwalls && !w->energy_tracking; k++) {
        const dm_wall *wall = &w->walls[k];
        if (wall->kind && !wall->drum_part)
            for (int c = 0; c < 3; c++)
                *unknown |= wall->vel[c] != 0.0 || wall->omega[c] != 0.0 || wall->harmonic ||
                            wall->surface;
    }
    return s;
}

/* Copies the current state, whose energies are e, as the last good one;
 * start: it also starts a run (the energy balance is measured from here). */
static demill_status take(demill_world *w, int start, const dm_watch_energy *e)
{
    dm_watch *g = &w->watch;
    if (!g->good && !(g->good = calloc(1, sizeof *g->good)))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory copying the state");
    if (dm_state_copy(g->good, w))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY,
                       "out of memory copying the state for the watchdog");
    g->last = *e;
    if (start) {
        g->start = *e;
        g->peak = 0.0;
        g->pmin = g->pmax = e->potential;
    }
    g->peak = fmax(g->peak, e->kinetic + e->elastic);
    g->pmin = fmin(g->pmin, e->potential);
    g->pmax = fmax(g->pmax, e->potential);
    g->edits = w->base.edits;
    return DEMILL_OK;
}

/* ---- the checks ------------------------------------------------------------ */

/* A check that failed: what, about which particle, and the likely cause. */
typedef struct verdict {
    char what[200];
    uint32_t particle;
    const char *cause;
} verdict;

/* The particle's position and velocities are finite (NaN and infinity
 * propagate into the sum). */
static int particle_finite(const dm_particles *P, int D, uint32_t i)
{
    const int W = D == 3 ? 3 : 1;
    double sum = 0.0;
    for (int c = 0; c < D; c++)
        sum += P->x[D * i + c] * 0.0 + P->v[D * i + c] * 0.0;
    for (int c = 0; c < W; c++)
        sum += P->w[W * i + c] * 0.0;
    return sum == 0.0;
}

static int finite_check(const demill_world *w, verdict *v)
{
    const dm_particles *P = &w->p;
    for (uint32_t i = 0; i < P->n; i++) {
        if (!particle_finite(P, w->dim, i)) {
            snprintf(v->what, sizeof v->what, "the position or velocity is not finite");
            v->particle = i;
            v->cause = "the motion blew up: the time step is too large for the contact "
                       "stiffness (see demill_world_suggest_time_step())";
            return 1;
        }
    }
    return 0;
}

static int overlap_check(const demill_world *w, verdict *v)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    double worst = w->watch_overlap, depth = 0.0;
    uint32_t who = 0, other = DM_FREE;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pp.b[k];
        for (uint32_t p = 0; p < b->n; p++) {
            const uint32_t i = b->i[p], j = b->j[p];
            double d2 = 0.0;
            for (int c = 0; c < D; c++) {
                const double d = P->x[D * j + c] - P->x[D * i + c];
                d2 += d * d;
            }
            const double delta = P->r[i] + P->r[j] - sqrt(d2);
            const double ratio = delta / fmin(P->r[i], P->r[j]);
            if (ratio > worst) {
                worst = ratio;
                depth = delta;
                who = i;
                other = j;
            }
        }
    }
    uint32_t g0 = 0, wall = DM_FREE;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pw.b[k];
        for (uint32_t p = 0; p < b->n; p++) {
            const double ratio = w->wg.delta[g0 + p] / P->r[b->i[p]];
            if (ratio > worst) {
                worst = ratio;
                depth = w->wg.delta[g0 + p];
                who = b->i[p];
                other = DM_FREE;
                wall = b->j[p];
            }
        }
        g0 += b->n;
    }
    if (worst <= w->watch_overlap)
        return 0;
    if (other != DM_FREE)
        snprintf(v->what, sizeof v->what,
                 "it overlaps particle 0x%llx by %.3g m, %.0f %% of the smaller radius",
                 (unsigned long long)dm_particle_id(w, other), depth, 100.0 * worst);
    else
        snprintf(v->what, sizeof v->what,
                 "it overlaps wall 0x%llx by %.3g m, %.0f %% of its radius",
                 (unsigned long long)dm_wall_id(w, wall), depth, 100.0 * worst);
    v->particle = who;
    v->cause = "the time step is too large for the contact stiffness or the impact speeds "
               "(see demill_world_suggest_time_step()), or the stiffness too low for the "
               "loads";
    return 1;
}

/* e: the current energies; unknown: the walls' work is not known. */
static int energy_check(const demill_world *w, verdict *v, dm_watch_energy e, int unknown)
{
    const dm_watch *g = &w->watch;
    if (unknown)
        return 0;
    double grown, allowed;
    if (w->energy_tracking) {
        const dm_watch_energy *a = &g->start;
        grown = (e.kinetic + e.potential + e.elastic + e.dissipated - e.work) -
                (a->kinetic + a->potential + a->elastic + a->dissipated - a->work);
        allowed = 0.25 * (fmax(g->peak, e.kinetic + e.elastic) +
                          fmax(g->pmax, e.potential) - fmin(g->pmin, e.potential) +
                          (e.dissipated - a->dissipated) + fabs(e.work - a->work));
    } else {
        const dm_watch_energy *a = &g->last;
        grown = e.kinetic;
        allowed = 2.0 * (a->kinetic + a->elastic + fmax(0.0, a->potential - e.potential) +
                         fmax(0.0, e.work - a->work));
    }
    if (!(grown > allowed))
        return 0;
    const dm_particles *P = &w->p;
    const int D = w->dim;
    double fastest = -1.0;
    for (uint32_t i = 0; i < P->n; i++) {
        double v2 = 0.0;
        for (int c = 0; c < D; c++)
            v2 += P->v[D * i + c] * P->v[D * i + c];
        if (v2 > fastest) {
            fastest = v2;
            v->particle = i;
        }
    }
    snprintf(v->what, sizeof v->what,
             "%.4g J of energy appeared from nowhere (%.4g J allowed); it is the fastest "
             "particle, at %.3g m/s",
             grown, allowed, sqrt(fastest));
    v->cause = "energy is being created: the time step is too large for the contact stiffness "
               "(see demill_world_suggest_time_step())";
    return 1;
}

/* Puts the world back at its last good state, or where the current call
 * started if that is later, with a message saying why. */
static demill_status fail_back(demill_world *w, const char *why)
{
    char msg[sizeof w->base.error];
    snprintf(msg, sizeof msg, "%s", why);
    const double t_bad = w->time;
    dm_watch *g = &w->watch;
    if (dm_state_restore(w, g->good))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY,
                       "%s; and out of memory putting back the last good state", msg);
    const char *where = "the last state that passed a check";
    if (w->base.steps < g->call_start) {
        /* step the copy on to the call's start; the steps it retakes all
         * succeeded before */
        demill_status s;
        dm_watch_energy e;
        int unknown;
        if ((s = dm_prepare_step(w)) || (s = dm_advance(w, g->call_start - w->base.steps)) ||
            (s = energies(w, &e, &unknown)) || (s = take(w, 1, &e)))
            return dm_fail(w, s, "%s; and going back to where this call started failed: %s",
                           msg, w->base.error);
        g->countdown = w->watch_interval;
        where = "where this call started";
    }
    return dm_fail(w, DEMILL_ERR_UNSTABLE,
                   "watchdog at t = %.9g s: %s. The world is back at t = %.9g s (step %llu), %s.",
                   t_bad, msg, w->time, (unsigned long long)w->base.steps, where);
}

/* The failure a verdict describes, the world put back. */
static demill_status report(demill_world *w, const verdict *v)
{
    char why[sizeof w->base.error];
    const dm_particles *P = &w->p;
    const int D = w->dim;
    snprintf(why, sizeof why, "particle 0x%llx at (%.6g, %.6g, %.6g): %s; likely cause: %s",
             (unsigned long long)dm_particle_id(w, v->particle), P->x[D * v->particle],
             P->x[D * v->particle + 1], D == 3 ? P->x[D * v->particle + 2] : 0.0, v->what,
             v->cause);
    return fail_back(w, why);
}

/* The checks; e receives the current energies, for take(). */
static demill_status check(demill_world *w, dm_watch_energy *e)
{
    verdict v = {.particle = DM_FREE};
    int unknown;
    demill_status s = energies(w, e, &unknown);
    if (s)
        return s;
    if (!finite_check(w, &v) && !overlap_check(w, &v) && !energy_check(w, &v, *e, unknown))
        return DEMILL_OK;
    return report(w, &v);
}

demill_status dm_check_finite(demill_world *w)
{
    verdict v = {.particle = DM_FREE};
    if (!finite_check(w, &v))
        return DEMILL_OK;
    const double *x = w->p.x + (size_t)w->dim * v.particle;
    return dm_fail(w, DEMILL_ERR_UNSTABLE,
                   "world_step at t = %.9g s: particle 0x%llx at (%.6g, %.6g, %.6g): %s; likely "
                   "cause: %s. With the watchdog off (world.watchdog = 0) the world is left "
                   "where it diverged: put back a snapshot or checkpoint",
                   w->time, (unsigned long long)dm_particle_id(w, v.particle), x[0], x[1],
                   w->dim == 3 ? x[2] : 0.0, v.what, v.cause);
}

/* Steps with the watchdog: in stretches that end at its checks, and a check
 * at the end (which takes no copy). */
demill_status dm_watched_steps(demill_world *w, uint64_t steps)
{
    dm_watch *g = &w->watch;
    demill_status s;
    dm_watch_energy e;
    int unknown;
    if (steps && g->stepped != w->base.edits + 1) { /* a run starts after a change */
        if ((s = dm_check_time_step(w)))
            return s;
        g->stepped = w->base.edits + 1;
    }
    if (!g->good || g->edits != w->base.edits) {
        if ((s = energies(w, &e, &unknown)) || (s = take(w, 1, &e)))
            return s;
        g->countdown = w->watch_interval;
    }
    const int any = steps > 0;
    while (steps) {
        const uint64_t n = steps < g->countdown ? steps : g->countdown;
        if ((s = dm_advance(w, n)))
            return s == DEMILL_ERR_UNSTABLE ? fail_back(w, w->base.error) : s;
        steps -= n;
        g->countdown -= (uint32_t)n;
        if (g->countdown)
            continue;
        g->countdown = w->watch_interval;
        if ((s = check(w, &e)) || (s = take(w, 0, &e)))
            return s;
    }
    return any && g->countdown != w->watch_interval ? check(w, &e) : DEMILL_OK;
}
