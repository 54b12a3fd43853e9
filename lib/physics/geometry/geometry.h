/* geometry.h: walls with prescribed rigid motion or moved by a body, and
 * the contact geometry of particle-wall candidates (walls.c). Uses the base
 * and the state. */
#ifndef DM_GEOMETRY_H
#define DM_GEOMETRY_H

#include "physics/state/state.h"

/* A free wall slot (cleared), growing the array if needed; DM_FREE when out
 * of memory. */
uint32_t dm_wall_slot_alloc(demill_world *w);
/* A free wall's current geometry at `time` from its reference and motion. */
void dm_wall_at(dm_wall *wall, double time);
/* Makes the wall's current geometry its reference at time t0 (motion
 * unchanged), keeping the skin bound relative to the last build. */
void dm_wall_rebase(dm_wall *wall, double now, double t0);
/* Moves every wall to `time`; the drum's walls to the drum's current angle
 * and speed (moved first: dm_drum_advance). */
void dm_walls_advance(demill_world *w, double time);
/* Moves the world's clock to `time` without moving the walls. */
void dm_walls_retime(demill_world *w, double time);
/* A body's wall (wall->body): its pose and velocity from the body's. */
void dm_wall_at_body(const demill_world *w, dm_wall *wall);
/* Attaches a wall at rest to body `slot`, its current pose the reference the
 * body moves; detaches it, leaving it at rest where it is. */
void dm_wall_attach(demill_world *w, dm_wall *wall, uint32_t slot);
void dm_wall_detach(demill_world *w, dm_wall *wall);

/* Signed distance of x from the wall's surface (positive on the particle
 * side), and the unit normal from x into the wall. */
double dm_wall_closest(const dm_wall *wall, const double *x, int dim, double *normal);
double dm_wall_distance(const dm_wall *wall, const double *x, int dim);
/* A lower bound of dm_wall_distance(), cheaper. */
double dm_wall_distance_bound(const dm_wall *wall, const double *x, int dim);
/* The walls' largest shift since the last neighbour build, and the mark of
 * that build. */
double dm_walls_max_shift(const demill_world *w);
void dm_walls_mark_built(demill_world *w);

/* The geometry of the particle-wall candidates (dm_wgeom): room for every
 * candidate, one bucket's candidates p0 .. p1 - 1 (from index g0), or all. */
int dm_wgeom_reserve(demill_world *w);
void dm_wgeom_range(demill_world *w, const dm_bucket *b, uint32_t g0, uint32_t p0, uint32_t p1);
void dm_wgeom_update(demill_world *w);

#endif /* DM_GEOMETRY_H */
