/* geometry.h: walls with prescribed rigid motion or moved by a body, and
 * the contact geometry of particle-wall candidates (walls.c). Uses the base
 * and the state. */
#ifndef DM_GEOMETRY_H
#define DM_GEOMETRY_H

#include "physics/state/state.h"

/* The distance a wall's face (a finite wall's, a mesh's element) reports
 * where another face owns the closest point (a cap beyond its rim, the
 * cylinder's rim over a cap, the element that holds a mesh contact): far
 * beyond any particle's reach, cohesion's included, and small enough that
 * the contact point and the wall velocity there, which are computed from
 * it, keep their precision (dm_wgeom_range). */
#define DM_FACE_ELSEWHERE 1e6

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
/* Makes a free wall part `part` (DM_PART_*) of the drum (at its current
 * angle, speed, centre and velocity): its geometry at `now` mapped into the
 * drum's frame, so that it does not move, and from then on turning and
 * moving with the drum. */
void dm_wall_attach(dm_wall *wall, int part, double now, const dm_drum *drum);
/* Moves the world's clock to `time` without moving the walls. */
void dm_walls_retime(demill_world *w, double time);
/* A body's wall (wall->body): its pose and velocity from the body's. */
void dm_wall_at_body(const demill_world *w, dm_wall *wall);
/* Attaches a wall at rest to body `slot`, its current pose the reference the
 * body moves; detaches it, leaving it at rest where it is. */
void dm_wall_attach_body(demill_world *w, dm_wall *wall, uint32_t slot);
void dm_wall_detach_body(demill_world *w, dm_wall *wall);

/* Signed distance of x from the wall's surface (positive on the particle
 * side), and the unit normal from x into the wall. */
double dm_wall_closest(const dm_wall *wall, const double *x, int dim, double *normal);

/* A unit vector q perpendicular to the unit vector n (n crossed with the
 * coordinate axis least aligned with it). */
void dm_perpendicular(const double n[3], double q[3]);

double dm_wall_distance(const dm_wall *wall, const double *x, int dim);
/* A lower bound of dm_wall_distance(), cheaper. */
double dm_wall_distance_bound(const dm_wall *wall, const double *x, int dim);
/* A lower bound of dm_wall_distance_bound() at every point of the box lo..hi
 * (dim components, finite), exact in floating point; -HUGE_VAL for a mesh. */
double dm_wall_box_bound(const dm_wall *wall, const double *lo, const double *hi, int dim);
/* Sets a finite wall's bounding sphere (bh, brad) from its shape. */
void dm_wall_finite_bound(dm_wall *wall);
/* The walls' largest shift since the last neighbour build, and the mark of
 * that build. */
double dm_walls_max_shift(const demill_world *w);
void dm_walls_mark_built(demill_world *w);

/* The wall's surface velocity now (its reference one turned with it). */
void dm_wall_surface_velocity(const dm_wall *wall, double u[3]);

/* The geometry of the particle-wall candidates (dm_wgeom): room for every
 * candidate, one bucket's candidates p0 .. p1 - 1 (from index g0) but for
 * those of meshes (dm_wgeom_meshes), or all. */
int dm_wgeom_reserve(demill_world *w);
void dm_wgeom_range(demill_world *w, const dm_bucket *b, uint32_t g0, uint32_t p0, uint32_t p1);
void dm_wgeom_update(demill_world *w);

/* Stores the geometry of wall candidate q (index in w->wg) of particle i:
 * overlap delta, unit normal n from the particle into the wall, and from
 * them the contact point and the wall's velocity there. */
void dm_wgeom_store(demill_world *w, uint32_t q, uint32_t i, const dm_wall *wall, double delta,
                    const double *n);

/* ---- triangle meshes and polylines (mesh.c) ------------------------------------- */
/* Whether element t (nel = 3: a triangle, 2: a segment, indices into v, 3
 * doubles per vertex) has no area (length) to speak of. */
int dm_trimesh_degenerate(int nel, const double *v, const uint32_t *el, size_t t);
/* A mesh of nt elements over nv vertices (valid: finite, indices in range,
 * no degenerate element), in one block; NULL when out of memory. */
dm_trimesh *dm_trimesh_build(int nel, uint32_t nv, const double *v, uint32_t nt,
                             const uint32_t *el);
dm_trimesh *dm_trimesh_copy(const dm_trimesh *m);
void dm_trimesh_free(dm_trimesh *m);
/* Frees the meshes and the recorded loads of every wall slot (the walls
 * themselves stay). */
void dm_walls_free_owned(demill_world *w);
/* Calls fn(ctx, t) for every element t closer than reach to x (the mesh's
 * frame), in the tree's order. */
typedef void (*dm_near_fn)(void *ctx, uint32_t t);
void dm_trimesh_near(const dm_trimesh *m, const double *x, double reach, dm_near_fn fn,
                     void *ctx);
/* The same for a mesh wall and a point x of the world. */
void dm_mesh_near(const dm_wall *wall, const double *x, int dim, double reach, dm_near_fn fn,
                  void *ctx);
/* The unsigned distance from x to a mesh wall, and the unit normal towards it. */
double dm_mesh_closest(const dm_wall *wall, const double *x, int dim, double *normal);
/* Vertex k of a mesh wall where it is now. */
void dm_mesh_vertex_at(const dm_wall *wall, uint32_t k, double *out);
/* The largest distance of the mesh from the wall's centre of rotation, or more. */
double dm_mesh_reach(const dm_wall *wall);
/* Before a mesh wall's current pose becomes its reference (dm_wall_rebase). */
void dm_mesh_rebase(dm_wall *wall);
/* A mesh wall at rest in its reference (rebased: dm_wall_rebase) placed by
 * its frame in the frame of a drum at angle theta about its centre (the
 * wall's pose then being the drum's: c0 = 0). */
void dm_mesh_into_drum(dm_wall *wall, double theta, const double centre[3]);
/* The smallest (far = 0) or largest (far = 1) distance of a mesh wall
 * attached to the drum (its frame the drum's) from the drum's axis. */
double dm_mesh_axis_distance(const dm_wall *wall, int far);
/* The widest angle about the drum's axis one element of a mesh wall
 * attached to the drum spans. */
double dm_mesh_widest_angle(const dm_wall *wall);
/* Whether the world has a mesh wall. */
int dm_walls_have_mesh(const demill_world *w);
/* The geometry of the mesh candidates of particles begin .. end - 1 (the
 * contact rule of docs/geometry.md); carry: a contact that moves on to
 * another element takes its history along (a force evaluation that advances
 * the histories). */
void dm_wgeom_meshes(demill_world *w, uint32_t begin, uint32_t end, int carry);

/* ---- recorded loads (loads.c) ----------------------------------------------------- */
/* The elements a wall's loads are kept for: a mesh's triangles or a
 * polyline's segments, else 1 (the wall as one patch, with its caps). */
uint32_t dm_loads_elements(const dm_wall *wall);
/* Loads of n elements, all 0; NULL when out of memory. */
dm_loads *dm_loads_new(uint32_t n);
dm_loads *dm_loads_copy(const dm_loads *l);
void dm_loads_free(dm_loads *l);
/* Element e's normal force at the last step recorded. */
double dm_loads_normal(const dm_loads *l, uint32_t e);
/* The area of element e of the wall in slot `slot` (m²; a polyline's
 * segment: its length, m): a triangle's, a segment's, a finite wall's with
 * its caps; NaN for a plane. */
double dm_loads_area(const demill_world *w, uint32_t slot, uint32_t e);

#endif /* DM_GEOMETRY_H */
