/* contact.h: contact laws and their kernels, the contact lists, the pair
 * table they read, one force evaluation and the walk over contacts that
 * queries use, and the collision spectrum the kernels count. Uses the base,
 * the state and the geometry (the particle-wall candidates' geometry). */
#ifndef DM_CONTACT_H
#define DM_CONTACT_H

#include "physics/state/state.h"

/* ---- kernels (forces.c) ------------------------------------------------------- */
/* The kernel of a combination of laws (generic: an extended kernel even for
 * laws a fast kernel has), and back; the history doubles per contact of a
 * kernel, and the factor on history slot `slot` of a particle-particle
 * contact whose particles trade places in storage order (dm_law_flip()). */
int dm_kernel_index(dm_laws laws, bool generic);
dm_laws dm_kernel_laws(int kernel);
int dm_kernel_hist_size(int kernel, int dim);
double dm_kernel_flip(int kernel, int dim, int slot);

/* ---- the pair table (pairs.c) ----------------------------------------------------- */
/* The user's choices for materials a and b, NULL for none. */
const dm_pair_user *dm_pair_find(const demill_world *w, uint32_t a, uint32_t b);
/* The effective laws and the value of every DM_PK_* key of pair (a, b). */
void dm_pair_values(const demill_world *w, uint32_t a, uint32_t b, dm_laws *laws,
                    double v[DM_PK_COUNT]);
/* A material's compliance (1 - ν²)/E, 0 for a rigid one. */
double dm_material_compliance(const dm_material *m);
/* The contact kernel of two materials' model, -1 for none. */
int dm_pair_kernel(const demill_world *w, uint32_t a, uint32_t b);
/* Rebuilds the resolved pair table if anything changed, and (if asked)
 * checks that every pair of materials that may touch has a model. Leaves
 * the world unchanged when it fails. */
demill_status dm_resolve_pairs(demill_world *w, bool require_models);
/* How far past touching the cohesive pairs that can meet interact, at
 * most, with particles of radius at most rmax (0 without cohesion): the
 * neighbour search's extra reach. */
double dm_cohesion_reach(const demill_world *w, double rmax);
/* The damping ratio ξ that gives restitution e (restitution.c). */
double dm_damping_ratio(double e, int clamp);

/* ---- the contact lists (lists.c) ---------------------------------------------------- */
/* Empties every list (a new layout of history, or new kernels). */
void dm_clist_clear(demill_world *w);
/* Drops the particle-wall pairs of one wall slot. */
void dm_clist_drop_wall(demill_world *w, uint32_t wall_slot);
/* Moves pair `from` of a bucket to slot `to` (to <= from) as pair (i, j). */
void dm_bucket_move(dm_bucket *b, uint32_t to, uint32_t from, uint32_t i, uint32_t j);
void dm_clists_free(demill_world *w);

/* ---- a force evaluation (forces.c, results.c) ----------------------------------------- */
int dm_results_reserve(demill_world *w);
void dm_results_layout(demill_world *w);
/* Which chunks sum which particles' forces when there are several ranges
 * (dm_results.lo, dm_chunkref.lo and hi), for the current layout. */
void dm_results_reach(demill_world *w);
void dm_results_free(demill_world *w);
/* dm_forces() options: */
#define DM_FORCES_PRESET 1 /* the forces already hold the particles' weights m g and the
                              torques 0 (the drift set them) */
#define DM_FORCES_DEFER 2  /* leave the sums the chunks do not take as they go, when there
                              are several ranges, to dm_forces_finish() on the same ranges
                              (w->res.pending: their number), which the next loop of the
                              same step has (dm_ranges() changes from step to step): until
                              then some particles' forces and torques are incomplete */
/* Gravity and every contact's force at the current state, the dashpots
 * seeing velocities vp, wp; dt_hist: the time over which springs grow;
 * options: DM_FORCES_*. */
void dm_forces(demill_world *w, const double *vp, const double *wp, double dt_hist, double reach,
               int tally, int options);
/* The sums a deferred dm_forces() left of particles p0 .. p1 - 1, one of
 * its w->res.pending ranges of dm_parallel(). */
void dm_forces_finish(demill_world *w, uint32_t p0, uint32_t p1);

/* After a step of dt whose forces dm_forces() has just evaluated, friction
 * seeing velocities vp, wp: the loads of the walls that record them
 * (geometry/loads.c, docs/geometry.md, Wall loads); nothing when none does. */
void dm_wall_loads_record(demill_world *w, const double *vp, const double *wp, double dt);

/* One contact as a query sees it: between particles i and j (storage
 * slots), or particle i and wall slot j (wall = 1). */
typedef struct dm_contact_eval {
    double point[3], normal[3], delta, fn[3], ft[3], mr[3];
    double e_normal, e_tangential, e_rolling;
    uint32_t i, j;
    int wall;
} dm_contact_eval;
typedef void (*dm_contact_visitor)(void *ctx, const dm_contact_eval *c);
/* Calls fn for every contact (overlap > 0) at the current state, without
 * changing the world's physical state; forces: with the contact's forces,
 * point and normal. The pair table must be resolved and the wall geometry
 * current (dm_wgeom_update). */
void dm_contacts_visit(demill_world *w, int forces, dm_contact_visitor fn, void *ctx);

/* ---- the collision spectrum (spectrum.c) ---------------------------------------------- */
/* Counts one collision that dissipated `energy`: particles i and j (storage
 * slots), or particle i and wall slot `wall` (j unused, wall >= 0; only the
 * drum's walls enter the collision spectrum, every wall the ore's impacts). */
void dm_spectrum_record(demill_world *w, uint32_t i, uint32_t j, int wall, double energy);
/* The number of counters of a spectrum: its collisions' and the ore's. */
size_t dm_spectrum_counters(const dm_spectrum *sp);
/* The number of the collisions' counters alone (the ore's come after). */
size_t dm_spectrum_collision_counters(const dm_spectrum *sp);
/* The ore size class of a diameter: k with top/√2^(k+1) < d <= top/√2^k,
 * 0 above the top, the last class below its limit. */
uint32_t dm_spectrum_ore_class(const dm_spectrum *sp, double diameter);
void dm_spectrum_free(demill_world *w);

#endif /* DM_CONTACT_H */
