/* geometry.h: walls with prescribed rigid motion, and the contact geometry
 * of particle-wall candidates (walls.c). Uses the base and the state. */
#ifndef DM_GEOMETRY_H
#define DM_GEOMETRY_H

#include "physics/state/state.h"

/* A free wall slot (cleared), growing the array if needed; DM_FREE when out
 * of memory. */
uint32_t dm_wall_slot_alloc(demill_world *w);
/* Room for `more` walls beyond the slots in use (0; -1 when out of memory). */
int dm_walls_reserve(demill_world *w, uint32_t more);
/* A free wall's current geometry at `time` from its reference and its rigid
 * or harmonic motion. */
void dm_wall_at(dm_wall *wall, double time);
/* Makes the wall's current geometry its reference at time t0 (a rigid
 * motion unchanged; a harmonic one ends), keeping the skin bound relative to
 * the last build. */
void dm_wall_rebase(dm_wall *wall, double now, double t0);
/* Moves every wall to `time`; the drum's walls to the drum's current angle
 * and speed (moved first: dm_drum_advance). */
void dm_walls_advance(demill_world *w, double time);
/* Moves the world's clock to `time` without moving the walls. */
void dm_walls_retime(demill_world *w, double time);

/* Signed distance of x from the wall's surface (positive on the particle
 * side), and the unit normal from x into the wall. */
double dm_wall_closest(const dm_wall *wall, const double *x, int dim, double *normal);
double dm_wall_distance(const dm_wall *wall, const double *x, int dim);
/* A lower bound of dm_wall_distance(), cheaper. */
double dm_wall_distance_bound(const dm_wall *wall, const double *x, int dim);
/* Sets a finite wall's bounding sphere (bh, brad) from its shape. */
void dm_wall_finite_bound(dm_wall *wall);
/* The walls' largest shift since the last neighbour build, and the mark of
 * that build. */
double dm_walls_max_shift(const demill_world *w);
void dm_walls_mark_built(demill_world *w);

/* The wall's surface velocity now (its reference one turned with it). */
void dm_wall_surface_velocity(const dm_wall *wall, double u[3]);

/* The geometry of the particle-wall candidates (dm_wgeom): room for every
 * candidate, one bucket's candidates p0 .. p1 - 1 (from index g0), or all. */
int dm_wgeom_reserve(demill_world *w);
void dm_wgeom_range(demill_world *w, const dm_bucket *b, uint32_t g0, uint32_t p0, uint32_t p1);
void dm_wgeom_update(demill_world *w);

#endif /* DM_GEOMETRY_H */
