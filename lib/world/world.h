/* world.h: the world layer, on top: the public entry points and the
 * orchestration of a step, of queries and of saving and loading. It may use
 * every module below (all included here); nothing below uses it. These are
 * the functions the world's own files share. */
#ifndef DM_WORLD_H
#define DM_WORLD_H

#include "base/alloc.h"
#include "base/handles.h"
#include "base/params.h"
#include "base/random.h"
#include "base/status.h"
#include "base/threads.h"
#include "physics/bodies/bodies.h"
#include "physics/broadphase/broadphase.h"
#include "physics/clumps/clumps.h"
#include "physics/contact/contact.h"
#include "physics/geometry/geometry.h"
#include "physics/integrate/integrate.h"
#include "physics/mill/mill.h"
#include "physics/shapes/shapes.h"
#include "physics/state/state.h"

/* ---- ids (ids.c) --------------------------------------------------------------- */
/* Checks that `id` names a live object of `kind` in world w and returns its
 * storage slot (particles: storage index; walls: wall slot; materials:
 * index). `what` names the argument in the error message. */
demill_status dm_resolve(const demill_world *w, demill_id id, int kind, const char *what,
                         uint32_t *slot);
/* The entry check of an API function that names an object: the world is a
 * live world and id names a live object of `kind` in it. */
demill_status dm_enter(const demill_world *w, demill_id id, int kind, const char *what,
                       uint32_t *slot);
demill_id dm_particle_id(const demill_world *w, uint32_t storage);
/* The id of a wall slot: the wall's own id, the drum's for its walls, a
 * capped wall's for its caps. */
demill_id dm_wall_id(const demill_world *w, uint32_t wall_slot);
/* Removes the user's wall in this slot (its contacts, handle and mesh). */
void dm_wall_release(demill_world *w, uint32_t slot);
/* Adds a mesh wall of material slot mat: nt elements of nel vertices (3:
 * triangles, 2: segments) over nv vertices (3 doubles each), after checking
 * them all (finite, indices in range, none degenerate); what: the calling
 * function's name, element: what an element is called in its messages. */
demill_status dm_walls_add_mesh(demill_world *w, uint32_t mat, int nel, size_t nv,
                                const double *v, size_t nt, const uint32_t *el, const char *what,
                                const char *element, demill_id *out);
demill_id dm_material_id(const demill_world *w, uint32_t material);
demill_id dm_drum_id(const demill_world *w);
demill_id dm_body_id(const demill_world *w, uint32_t slot);
demill_id dm_clump_id(const demill_world *w, uint32_t slot);
demill_id dm_template_id(const demill_world *w, uint32_t index);
demill_id dm_feed_id(const demill_world *w, uint32_t slot);
demill_id dm_outlet_id(const demill_world *w, uint32_t slot);

/* ---- clumps (clumps.c) ---------------------------------------------------------- */
/* Makes room for `count` more clumps of n members each: their slots,
 * handles and members (-1: out of memory, nothing else changed but
 * capacities). */
int dm_clumps_reserve(demill_world *w, size_t count, size_t n);
/* Adds a clump of template slot tk at rest at its centre of mass `position`
 * turned by the unit quaternion q, in room made by dm_clumps_reserve(), and
 * returns its id. */
demill_id dm_clump_insert(demill_world *w, uint32_t tk, const double position[3],
                          const double q[4]);

/* ---- particles (particles.c, material.c) ------------------------------------------ */
demill_status dm_particles_append(demill_world *w, uint32_t mat, size_t n, const double *positions,
                                  const double *radii, const double *velocities, demill_id *ids);
/* As dm_particle_mass(), and DEMILL_ERR_INVALID_VALUE with a message naming
 * `who` unless the mass, the moment of inertia and their inverses are all
 * finite and positive. */
demill_status dm_particle_mass_checked(demill_world *w, uint32_t mat, double r, const char *who,
                                       double *m, double *inv_i);
/* After a change of what masses depend on (a material's density, the disc
 * thickness): the masses of the particles of material mat (DM_ALL_MATERIALS:
 * of every particle) computed again, if every one passes
 * dm_particle_mass_checked(); otherwise its error, and no mass changed.
 * Refused while a clump template weighed with them exists. */
#define DM_ALL_MATERIALS UINT32_MAX
demill_status dm_masses_update(demill_world *w, uint32_t mat, const char *who);
/* Removes the particles whose entry of map (one per particle, from
 * w->grid.inv) is DM_FREE, keeping the others' order and contacts. */
void dm_particles_compact(demill_world *w, uint32_t *map);

/* ---- overlaps of new particles (overlap.c) ----------------------------------------- */
typedef struct dm_sphere_entry {
    uint64_t key;
    uint32_t index;
} dm_sphere_entry;
typedef struct dm_sphere_index {
    int dim;
    size_t n;
    double h, *x, *r;
    dm_sphere_entry *e;
} dm_sphere_index;
int dm_spheres_build(dm_sphere_index *ix, const demill_world *w, size_t nextra,
                     const double *xextra, const double *rextra, double rquery);
void dm_spheres_free(dm_sphere_index *ix);
int64_t dm_spheres_find(const dm_sphere_index *ix, const double *x, double r, uint32_t limit,
                        double *depth);
uint32_t dm_wall_overlap(const demill_world *w, const double *x, double r, double *depth);

/* ---- size distributions (fill.c), regions (region.c), placing (place.c) ------------ */
/* Checks a distribution (DEMILL_SIZES_*) and turns it into classes; `who`
 * names the API function in messages. */
demill_status dm_sizes_make(demill_world *w, const char *who, int32_t dist, const double *p,
                            size_t np, dm_sizes *out);
/* The relative number of particles of each class in a unit of mass of
 * material mat (the fraction of the mass over the mean particle mass). */
void dm_sizes_numbers(const demill_world *w, uint32_t mat, const dm_sizes *s, double *number);
/* A diameter drawn from class k (log-uniform in it). */
double dm_sizes_draw(const dm_sizes *s, uint32_t k, dm_rng *rng);
/* DEMILL_OK unless a particle of the smallest or largest size of a class
 * with particles has a mass or inertia that is not finite and positive. */
demill_status dm_sizes_check_mass(demill_world *w, const char *who, uint32_t mat,
                                  const dm_sizes *s, const size_t *count);

/* Checks a region (DEMILL_REGION_*; bounded: not a half-space). */
demill_status dm_region_parse(demill_world *w, const char *who, int32_t kind, const double *p,
                              size_t np, bool bounded, dm_region *out);
/* Whether a sphere at x of radius m lies inside (m = 0: its centre). */
bool dm_region_contains(const demill_world *w, const dm_region *r, const double *x, double m);
void dm_region_bounds(const demill_world *w, const dm_region *r, double lo[3], double hi[3]);
/* The volume (in 2D the area) of a region; the drum's less its lifters. */
double dm_region_measure(const demill_world *w, const dm_region *r);
/* Whether a sphere of radius m fits in the region anywhere. */
bool dm_region_fits(const demill_world *w, const dm_region *r, double m);
/* A random centre (3 doubles) of a sphere of radius m inside the region,
 * uniform in the part of it whose sphere lies within band[0] <= x[axis] <=
 * band[1]; -1 when 64 tries found none. */
int dm_region_sample(const demill_world *w, const dm_region *r, dm_rng *rng, double m, int axis,
                     const double band[2], double *x);
/* A rigid shape for dm_place(): n spheres at mem (DM_TMEM doubles each: the
 * offset from the shape's centre in its body frame, the radius). */
typedef struct dm_shape {
    uint32_t n;
    const double *mem;
} dm_shape;
/* The radius of the smallest sphere about a shape's centre that holds it. */
double dm_shape_reach(const dm_shape *sh);
/* Places n spheres of the given radii (or, with a shape, n bodies of that
 * shape, radii unused) in turn in the region, clear of the walls, of the
 * world's particles and of each other, from the bottom up: each at the
 * lowest free place of a set of random candidates in a layer at the
 * region's bottom, the layer deepened by the sphere's diameter after each
 * set without a free place, up to `sets` sets; centres into pos (3 doubles
 * each). A body's candidates have random orientations (uniform on SO(3); in
 * 2D a uniform turn about z), each lies inside the region with its bounding
 * sphere (dm_shape_reach()) and is free when every member is; its
 * orientation goes into quat (4 doubles each; unused without a shape).
 * *placed: how many were placed (the first that found no place stops it).
 * Fails only when memory runs out. */
demill_status dm_place(demill_world *w, const dm_region *reg, size_t n, const double *radii,
                       const dm_shape *shape, uint32_t sets, dm_rng *rng, double *pos,
                       double *quat, size_t *placed);

/* ---- running (step.c, flows.c, progress.c, watchdog.c, timestep.c) ---------------------- */
/* dm_integrate(), with the outlets and feeds acting after every step while
 * the world has any. */
demill_status dm_advance(demill_world *w, uint64_t steps);
/* Steps a prepared world, under the watchdog when it is on. */
demill_status dm_run_steps(demill_world *w, uint64_t steps);
/* Runs `steps` steps of a prepared world, reporting to its callback. */
demill_status dm_progress_steps(demill_world *w, uint64_t steps);
demill_status dm_watched_steps(demill_world *w, uint64_t steps);
/* DEMILL_ERR_UNSTABLE unless every position, velocity and spin is finite. */
demill_status dm_check_finite(demill_world *w);
/* Reads the whole file at path into *bytes (malloc'd, *size bytes; the
 * caller frees it). Fails with DEMILL_ERR_IO or DEMILL_ERR_OUT_OF_MEMORY,
 * the message starting with fn and path. */
demill_status dm_read_file(demill_world *w, const char *fn, const char *path, uint8_t **bytes,
                           size_t *size);
void dm_watch_free(demill_world *w);
/* DEMILL_ERR_UNSTABLE, naming the pair, unless the time step is within the
 * stability limit of every pair of materials that can meet. */
demill_status dm_check_time_step(demill_world *w);

/* ---- the state kept aside (snapshot.c) and the energies (energy.c) ------------------- */
demill_status dm_state_copy(demill_world *dst, const demill_world *src);
demill_status dm_state_restore(demill_world *w, const demill_world *src);
void dm_state_free(demill_world *s);
/* The energies of the state (energy.c), by index: the particles' and the
 * clumps' kinetic (translational, rotational) and potential energy, the elastic energy
 * stored in the contacts' normal, tangential and rolling springs, then the
 * bodies' summed (DM_E_BODY + DM_BODY_*). */
enum { DM_E_KT, DM_E_KR, DM_E_POT, DM_E_NORMAL, DM_E_TANGENTIAL, DM_E_ROLLING, DM_E_BODY };
#define DM_ENERGIES (DM_E_BODY + DM_BODY_ENERGIES)
demill_status dm_energies(demill_world *w, int stored, double e[DM_ENERGIES]);

#endif /* DM_WORLD_H */
