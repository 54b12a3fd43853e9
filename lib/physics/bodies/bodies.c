/* bodies.c: rigid bodies moved by the particles (docs/physics.md §7, Bodies):
 * the forces on a body, its time stepping with the world's integrator, and
 * its energies. A body of mass m translates along its free axes a under
 *
 *     m ẍ_a = F_particles,a − k_a (x_a − x_rest,a) − c_a ẋ_a + F0_a sin(2π f t + φ) + m g_a,
 *
 * the forces of the particles on its walls being those of the last force
 * evaluation, as a particle's are. Its walls take their pose from it
 * (geometry/walls.c). The energy tallies integrate the external force's work
 * and the dampers' dissipation by the trapezoidal rule over each step's
 * displacement, which is what velocity Verlet's kinetic energy follows
 * (Hairer, Lubich and Wanner 2003, Geometric numerical integration
 * illustrated by the Störmer-Verlet method), so that the balance closes to
 * the integrator's own bounded error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/bodies/bodies.h"

void dm_body_forces_now(const demill_world *w, uint32_t slot, dm_body_forces *f)
{
    const dm_body *b = &w->bodies[slot];
    memset(f, 0, sizeof *f);
    for (uint32_t k = 0; k < w->nwalls; k++)
        if (w->walls[k].kind && w->walls[k].body == slot + 1)
            for (int c = 0; c < 3; c++)
                f->particles[c] += w->walls[k].force[c];
    const double s = sin(2.0 * DM_PI * b->freq * w->time + b->phase);
    for (int c = 0; c < 3; c++) {
        if (b->free_axes >> c & 1) {
            f->spring[c] = -b->k[c] * (b->x[c] - b->rest[c]);
            f->damper[c] = -b->c[c] * b->vp[c];
        }
        f->external[c] = b->f0[c] * s;
        f->gravity[c] = b->gravity ? b->mass * w->g[c] : 0.0;
    }
}

void dm_body_energies(const demill_world *w, uint32_t slot, double e[DM_BODY_ENERGIES])
{
    const dm_body *b = &w->bodies[slot];
    memset(e, 0, DM_BODY_ENERGIES * sizeof *e);
    for (int c = 0; c < 3; c++) {
        const double d = b->x[c] - b->rest[c];
        e[DM_BODY_KINETIC] += 0.5 * b->mass * b->v[c] * b->v[c];
        if (b->free_axes >> c & 1)
            e[DM_BODY_ELASTIC] += 0.5 * b->k[c] * d * d;
        if (b->gravity)
            e[DM_BODY_POTENTIAL] -= b->mass * w->g[c] * b->x[c];
    }
    e[DM_BODY_DISSIPATED] = b->dissipated;
    e[DM_BODY_WORK] = b->work;
}

/* The acceleration of body b at the current state (0 along the axes it is
 * not free on); tallies the work of its external force and its dampers over
 * the displacement since the last evaluation. */
static void acceleration(demill_world *w, uint32_t slot, double acc[3])
{
    dm_body *b = &w->bodies[slot];
    dm_body_forces f;
    dm_body_forces_now(w, slot, &f);
    for (int c = 0; c < 3; c++) {
        const double dx = b->x[c] - b->x_tally[c];
        b->work += 0.5 * (b->fe_tally[c] + f.external[c]) * dx;
        b->dissipated -= 0.5 * (b->fd_tally[c] + f.damper[c]) * dx;
        b->x_tally[c] = b->x[c];
        b->fe_tally[c] = f.external[c];
        b->fd_tally[c] = f.damper[c];
        const double sum = f.particles[c] + f.spring[c] + f.damper[c] + f.external[c] +
                           f.gravity[c];
        acc[c] = b->free_axes >> c & 1 ? sum / b->mass : 0.0;
    }
}

void dm_bodies_drift(demill_world *w, double dt, int kick, int verlet)
{
    const double h = 0.5 * dt;
    for (uint32_t k = 0; k < w->nbodies; k++) {
        if (!dm_body_live(w, k))
            continue;
        dm_body *b = &w->bodies[k];
        double a[3];
        acceleration(w, k, a);
        for (int c = 0; c < 3; c++) {
            if (verlet) {
                if (kick)
                    b->v[c] += h * a[c];
                b->vp[c] = b->v[c] + dt * a[c];
                b->v[c] += h * a[c];
            } else {
                b->v[c] += dt * a[c];
                b->vp[c] = b->v[c];
            }
            b->x[c] += dt * b->v[c];
        }
    }
}

void dm_bodies_kick(demill_world *w, double h)
{
    for (uint32_t k = 0; k < w->nbodies; k++) {
        if (!dm_body_live(w, k))
            continue;
        dm_body *b = &w->bodies[k];
        double a[3];
        acceleration(w, k, a);
        for (int c = 0; c < 3; c++)
            b->v[c] += h * a[c];
    }
}

uint32_t dm_body_slot_alloc(demill_world *w)
{
    uint32_t slot = 0;
    while (slot < w->nbodies && dm_body_live(w, slot))
        slot++;
    if (slot == w->cap_bodies) {
        uint32_t cap = w->cap_bodies ? 2 * w->cap_bodies : 4;
        dm_body *nb = realloc(w->bodies, cap * sizeof *nb);
        if (!nb)
            return DM_FREE;
        w->bodies = nb;
        w->cap_bodies = cap;
    }
    memset(&w->bodies[slot], 0, sizeof w->bodies[slot]);
    w->bodies[slot].handle = DM_FREE;
    if (slot == w->nbodies)
        w->nbodies++;
    return slot;
}
