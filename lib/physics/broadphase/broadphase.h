/* broadphase.h: the neighbour build, which sorts the particles by cell and
 * fills the contact lists (nlist.c). Uses the base, the state, the geometry
 * and the contact lists. */
#ifndef DM_BROADPHASE_H
#define DM_BROADPHASE_H

#include "physics/state/state.h"

demill_status dm_nlist_build(demill_world *w);
/* Whether the lists are used up: some particle moved max_disp2 (squared)
 * since the build is over half the skin, or a wall so far a gap could close. */
bool dm_nlist_needs_rebuild(const demill_world *w, double max_disp2);
/* Sizes the build's per-particle scratch for n particles (0; -1 when out of memory). */
int dm_grid_reserve(dm_grid *g, uint32_t n);
void dm_nlist_free(demill_world *w);

#endif /* DM_BROADPHASE_H */
