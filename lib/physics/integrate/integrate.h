/* integrate.h: time stepping: velocity Verlet, symplectic Euler
 * (integrate.c) and the iterative refinement (refine.c). Uses every physics
 * module below it. */
#ifndef DM_INTEGRATE_H
#define DM_INTEGRATE_H

#include "physics/state/state.h"

/* Makes the world ready to step: contact models resolved and complete, lists
 * built, forces of the current state known. Changes nothing physical. */
demill_status dm_prepare_step(demill_world *w);
/* `steps` steps of a prepared world with its integrator. */
demill_status dm_integrate(demill_world *w, uint64_t steps);
demill_status dm_refine_steps(demill_world *w, uint64_t steps);
void dm_refine_free(demill_world *w);

#endif /* DM_INTEGRATE_H */
