/* bodies.h: rigid bodies moved by the particles on their walls, tied to the
 * ground by springs and dampers and driven by an external force
 * (bodies.c): their forces, their time stepping and their energies. Uses
 * the base, the state and the geometry. */
#ifndef DM_BODIES_H
#define DM_BODIES_H

#include "physics/state/state.h"

/* The forces on a body at the current state: of the particles on its walls
 * (at the last force evaluation), of its springs and dampers (along its
 * free axes, the dampers seeing the velocity its walls show the contacts),
 * the external force at the world's time and gravity (if it acts on it). */
typedef struct dm_body_forces {
    double particles[3], spring[3], damper[3], external[3], gravity[3];
} dm_body_forces;
void dm_body_forces_now(const demill_world *w, uint32_t slot, dm_body_forces *f);

/* The energies of a body, in this order: kinetic, elastic (springs),
 * potential (gravity, zero at the origin), dissipated by its dampers and
 * the work of its external force (both since it was added). */
enum { DM_BODY_KINETIC, DM_BODY_ELASTIC, DM_BODY_POTENTIAL, DM_BODY_DISSIPATED, DM_BODY_WORK,
       DM_BODY_ENERGIES };
void dm_body_energies(const demill_world *w, uint32_t slot, double e[DM_BODY_ENERGIES]);

/* Whether slot holds a body. */
static inline bool dm_body_live(const demill_world *w, uint32_t slot)
{
    return w->bodies[slot].handle != DM_FREE;
}

/* The start of a step for every body, as the particles' (integrate.c): with
 * verlet, velocity Verlet's first half (after the second half of the step
 * before when kick is set), else symplectic Euler's step. */
void dm_bodies_drift(demill_world *w, double dt, int kick, int verlet);
/* Velocity Verlet's second half, v += h a, at the end of a run. */
void dm_bodies_kick(demill_world *w, double h);

/* A free body slot (cleared, at rest, its handle DM_FREE), growing the array
 * if needed; DM_FREE when out of memory. */
uint32_t dm_body_slot_alloc(demill_world *w);

#endif /* DM_BODIES_H */
