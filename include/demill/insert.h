/** @file demill/insert.h
 * @brief Putting particles in and taking them out: filling a region with a
 * size distribution, feeds that insert particles over time at a mass rate,
 * and outlets that remove and count the particles that reach them.
 *
 * A region is given as a kind (DEMILL_REGION_*) and an array of doubles, as
 * everywhere in this API no struct crosses it. Sizes are drawn from the
 * distributions of demill_drum_fill() (DEMILL_SIZES_*, in demill/drum.h).
 * Feeds and outlets act at the end of each step, in the order they were
 * created (outlets first, then feeds); they are carried by snapshots and
 * checkpoints, and their results, like everything else, do not depend on the
 * number of threads. A world without feeds and outlets steps as before, at
 * no cost. docs/geometry.md describes them.
 */
#ifndef DEMILL_INSERT_H
#define DEMILL_INSERT_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Kinds of region. In a 2D world every z coordinate of a region must be 0
 *  and its section by the plane z = 0 is used. */
enum {
    /** An axis-aligned box. 6 params: the corners x_lo, y_lo, z_lo, x_hi,
     *  y_hi, z_hi, with lo < hi in every coordinate the world has (in 2D,
     *  z_lo = z_hi = 0: a rectangle). */
    DEMILL_REGION_BOX = 1,
    /** A solid cylinder. 7 params: the centres of its two end faces (3 + 3)
     *  and its radius, > 0; the centres differ. In 2D the axis lies in the
     *  plane and the region is the rectangle around it. */
    DEMILL_REGION_CYLINDER = 2,
    /** The half-space behind a plane, below it when the normal points up.
     *  6 params: a point on the plane and the normal (not of zero length),
     *  which points out of the region. Unbounded: for outlets only. */
    DEMILL_REGION_HALF_SPACE = 3,
    /** The inside of the world's drum (no params); for fills and feeds its
     *  shell, caps and lifters are walls that new particles keep clear of. */
    DEMILL_REGION_DRUM = 4
};

/** Fills a region with particles of one material: sizes from a distribution
 *  (DEMILL_SIZES_*, with `params`), as many as the target (DEMILL_FILL_*,
 *  `value`) asks. Each whole particle lies inside the region, clear of the
 *  walls and of every particle there, the new ones included. Particles are
 *  placed one at a time in a seeded random order of sizes: each takes the
 *  lowest (along gravity, or along -y without gravity) free place among 16
 *  seeded random candidate places in the region, with further sets of 16
 *  tried while none is free, up to 4096 candidates. A grid with a level per
 *  octave of size finds the neighbours of a candidate, so that a
 *  distribution as wide as 10 to 1 in diameter costs about what one size
 *  does. The charge depends only on the arguments, the region, the walls
 *  and the particles already present: the same call gives the same charge.
 *  Then let it settle (demill_world_settle()).
 *
 *  For DEMILL_FILL_FRACTION the value is, in the drum, its bulk filling J
 *  (as demill_drum_fill()); in a box or a cylinder, the fraction of the
 *  region's volume (in 2D its area) that the particles themselves occupy.
 *  @param world        the world.
 *  @param region       the region, DEMILL_REGION_* (not a half-space).
 *  @param region_params the region's parameters (see DEMILL_REGION_*).
 *  @param nregion      the number of doubles in region_params.
 *  @param material     the particles' material.
 *  @param distribution the size distribution, DEMILL_SIZES_*.
 *  @param params       the distribution's parameters (see DEMILL_SIZES_*).
 *  @param nparams      the number of doubles in params.
 *  @param target       what `value` means, DEMILL_FILL_*.
 *  @param value        how many particles: a count, a mass or a fraction.
 *  @param seed         seed of the random sizes, order and places.
 *  @param[out] ids     receives the ids of the new particles (may be NULL).
 *  @param capacity     how many ids `ids` can hold.
 *  @param[out] added   receives the number of particles added (0 on failure;
 *                      on DEMILL_ERR_BUFFER_TOO_SMALL the number ids must
 *                      hold); may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_UNKNOWN_KEY (region, distribution or target),
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_DIMENSION (a region with z in a
 *          2D world), DEMILL_ERR_INVALID_VALUE (an empty or unbounded region,
 *          the drum's region without a drum; bad distribution or target; a
 *          target of more particles than a world holds, about 1.07e9; the
 *          charge does not fit: nothing is added),
 *          DEMILL_ERR_BUFFER_TOO_SMALL or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_fill_region(demill_world *world, int32_t region,
                                            const double *region_params, size_t nregion,
                                            demill_id material, int32_t distribution,
                                            const double *params, size_t nparams, int32_t target,
                                            double value, uint64_t seed, demill_id *ids,
                                            size_t capacity, size_t *added);

/** Creates a feed: from t_start to t_stop (world time, s) it inserts
 *  particles of one material into a region at a mass rate, with sizes drawn
 *  from a distribution (by mass, as demill_drum_fill()), each with the given
 *  velocity and no spin. At the end of every step it owes
 *  rate × (min(t, t_stop) - t_start) kg in all; while the next particle's
 *  mass fits in what it owes, it places that particle as demill_fill_region()
 *  does (the whole particle in the region, clear of walls and particles).
 *  Where no place is free it tries again at the next step, and the mass
 *  owed but not inserted is its deficit (demill_feed_read()). A world holds
 *  at most 16 feeds at once.
 *  @param world        the world.
 *  @param region       the region, DEMILL_REGION_* (not a half-space).
 *  @param region_params the region's parameters.
 *  @param nregion      the number of doubles in region_params.
 *  @param material     the particles' material.
 *  @param distribution the size distribution, DEMILL_SIZES_*.
 *  @param params       the distribution's parameters.
 *  @param nparams      the number of doubles in params.
 *  @param mass_rate    kg/s, > 0.
 *  @param velocity     the new particles' velocity, m/s (3 doubles, z = 0 in
 *                      2D).
 *  @param t_start      when the feed starts, s.
 *  @param t_stop       when it stops, s, > t_start (may be INFINITY).
 *  @param seed         seed of its sizes and places.
 *  @param[out] out     receives the feed's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_UNKNOWN_KEY (region or distribution),
 *          DEMILL_ERR_NOT_FINITE (a region, distribution, rate, velocity or
 *          start that is not finite), DEMILL_ERR_DIMENSION,
 *          DEMILL_ERR_INVALID_VALUE (rate <= 0, t_stop <= t_start, an empty
 *          or unbounded region, a bad distribution, a particle of the
 *          largest size that cannot fit in the region) or DEMILL_ERR_LIMIT
 *          (16 feeds). */
DEMILL_API demill_status demill_feed_create(demill_world *world, int32_t region,
                                            const double *region_params, size_t nregion,
                                            demill_id material, int32_t distribution,
                                            const double *params, size_t nparams,
                                            double mass_rate, const double velocity[3],
                                            double t_start, double t_stop, uint64_t seed,
                                            demill_id *out);

/** Removes a feed; the particles it inserted stay. Its id becomes invalid.
 *  @param world the world.
 *  @param feed  the feed's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_feed_remove(demill_world *world, demill_id feed);

/** Reads a feed's totals. Any output may be NULL.
 *  @param world        the world.
 *  @param feed         the feed's id.
 *  @param[out] mass    the mass inserted so far, kg.
 *  @param[out] count   the number of particles inserted so far.
 *  @param[out] deficit the mass owed so far but not inserted, kg: less than
 *                      one particle's mass while the region has room.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_feed_read(demill_world *world, demill_id feed, double *mass,
                                          uint64_t *count, double *deficit);

/** Creates an outlet: at the end of every step, the particles whose centre
 *  is inside the region are removed and counted, by number and mass, in
 *  size classes of diameter: class k holds diameters below edges[k] (and at
 *  or above edges[k - 1]), the last class everything from the last edge up,
 *  so there are nedges + 1 classes. Besides the running totals it keeps the
 *  mass and number removed over the last completed interval of `interval`
 *  seconds (intervals counted from the outlet's creation). A world holds at
 *  most 16 outlets at once.
 *  @param world         the world.
 *  @param region        the region, DEMILL_REGION_*.
 *  @param region_params the region's parameters.
 *  @param nregion       the number of doubles in region_params.
 *  @param nedges        the number of class edges, 0 to 31.
 *  @param edges         nedges increasing diameters > 0, m (may be NULL
 *                       when nedges is 0).
 *  @param interval      the interval of the rate, s, > 0.
 *  @param[out] out      receives the outlet's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_UNKNOWN_KEY (region), DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_DIMENSION, DEMILL_ERR_INVALID_VALUE (an empty region,
 *          edges not increasing and > 0, more than 31 edges, interval <= 0)
 *          or DEMILL_ERR_LIMIT (16 outlets). */
DEMILL_API demill_status demill_outlet_create(demill_world *world, int32_t region,
                                              const double *region_params, size_t nregion,
                                              size_t nedges, const double *edges,
                                              double interval, demill_id *out);

/** Removes an outlet. Its id becomes invalid.
 *  @param world  the world.
 *  @param outlet the outlet's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_outlet_remove(demill_world *world, demill_id outlet);

/** Reads what an outlet has removed, per size class: counts and masses
 *  since its creation, and over the last completed interval. Any of the
 *  arrays may be NULL; those given hold `capacity` values.
 *  @param world         the world.
 *  @param outlet        the outlet's id.
 *  @param[out] counts   the number removed per class.
 *  @param[out] masses   the mass removed per class, kg.
 *  @param capacity      how many classes the arrays hold.
 *  @param[out] nclasses receives the number of classes (nedges + 1); may be
 *                       NULL.
 *  @param[out] last     receives the mass (kg) and number removed over the
 *                       last completed interval, and the interval's end
 *                       time, s (3 doubles; zeros before the first interval
 *                       ends); may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE or
 *          DEMILL_ERR_BUFFER_TOO_SMALL (capacity below the classes, with
 *          arrays given; *nclasses is set). */
DEMILL_API demill_status demill_outlet_read(demill_world *world, demill_id outlet,
                                            uint64_t *counts, double *masses, size_t capacity,
                                            size_t *nclasses, double last[3]);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_INSERT_H */
