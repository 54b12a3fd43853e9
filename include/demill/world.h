/* demill/world.h: creating, configuring and stepping a simulation world. */
#ifndef DEMILL_WORLD_H
#define DEMILL_WORLD_H

#include "common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An opaque simulation world. It owns its materials, particles and walls;
 *  nothing is shared between worlds. */
typedef struct demill_world demill_world;

/** Integrators, the values of DEMILL_WORLD_INTEGRATOR. */
enum {
    /** Velocity Verlet (kick-drift-kick), second order; contact forces see
     *  the half-step velocities. The default. */
    DEMILL_INTEGRATOR_VELOCITY_VERLET = 1,
    /** Symplectic (semi-implicit) Euler: v += a dt, then x += v dt. First
     *  order, cheapest. */
    DEMILL_INTEGRATOR_SYMPLECTIC_EULER = 2
};

/** World parameter keys, used with demill_world_set() and demill_world_get().
 *  Keys 100-149 can be set; keys 150-199 are read-only. */
enum {
    /** Time step Δt in s, > 0. Default 1e-5. */
    DEMILL_WORLD_TIME_STEP = 100,
    /** Gravity vector components in m/s². Default (0, -9.81, 0). In a 2D
     *  world the z component must stay 0. */
    DEMILL_WORLD_GRAVITY_X = 101,
    DEMILL_WORLD_GRAVITY_Y = 102,
    DEMILL_WORLD_GRAVITY_Z = 103,
    /** DEMILL_INTEGRATOR_*. Default DEMILL_INTEGRATOR_VELOCITY_VERLET. */
    DEMILL_WORLD_INTEGRATOR = 104,
    /** Verlet skin of the neighbour list as a fraction of the largest particle
     *  radius, in [0.01, 10]. Larger skins rebuild less often but test more
     *  pairs; results do not depend on it beyond round-off. Default 0.3. */
    DEMILL_WORLD_SKIN = 105,
    /** 2D worlds only: 0 (default) makes particles spheres constrained to the
     *  plane (m = 4/3 π R³ ρ, I = 2/5 m R²); a positive thickness t in m makes
     *  them discs (m = π R² t ρ, I = 1/2 m R²). Changing it recomputes the
     *  masses of all particles. */
    DEMILL_WORLD_DISC_THICKNESS = 106,
    /** 1 (default) tallies dissipated energy and wall work during steps (see
     *  demill_world_energy()); 0 skips that work. */
    DEMILL_WORLD_ENERGY_TRACKING = 107,
    /** Simulated time in s. Settable, e.g. to continue a run. */
    DEMILL_WORLD_TIME = 108,
    /** Threads that stepping uses, a whole number in [0, 1024]; 0 takes
     *  OpenMP's default (OMP_NUM_THREADS, or one per core). Default 1.
     *  Results are bitwise the same for every thread count. More than one
     *  needs a library built with OpenMP (DEMILL_ERR_UNSUPPORTED otherwise);
     *  getting the key gives the number in use. */
    DEMILL_WORLD_THREADS = 109,

    /** 2 or 3. */
    DEMILL_WORLD_DIMENSION = 150,
    /** Number of steps taken since creation. */
    DEMILL_WORLD_STEP_COUNT = 151,
    /** Number of particles. */
    DEMILL_WORLD_PARTICLE_COUNT = 152,
    /** Particle-particle contacts (overlap > 0) at the last force evaluation. */
    DEMILL_WORLD_CONTACT_COUNT = 153,
    /** Particle-wall contacts (overlap > 0) at the last force evaluation. */
    DEMILL_WORLD_WALL_CONTACT_COUNT = 154,
    /** Number of neighbour-list rebuilds since creation. */
    DEMILL_WORLD_NEIGHBOUR_REBUILDS = 155
};

/** Creates an empty world of the given dimension (2 or 3) with default
 *  parameters: gravity (0, -9.81, 0), time step 1e-5 s, velocity Verlet.
 *  @param dimension 2 or 3.
 *  @param out receives the world; set to NULL on failure.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_INVALID_VALUE (bad
 *          dimension) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_world_create(int32_t dimension, demill_world **out);

/** Frees a world and everything it owns. NULL is ignored. Ids of the world
 *  become meaningless. */
DEMILL_API void demill_world_destroy(demill_world *world);

/** The message of the last error reported by a function called on this world,
 *  naming the argument, particle or parameter at fault; "" if none. The
 *  string stays valid until the next call on the world. NULL or a pointer that
 *  is not a world gives a static message saying so. */
DEMILL_API const char *demill_world_last_error(const demill_world *world);

/** Sets a world parameter (DEMILL_WORLD_* keys below 150).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (out of bounds, or not a whole number for
 *          a choice) or DEMILL_ERR_DIMENSION (e.g. gravity z in 2D). */
DEMILL_API demill_status demill_world_set(demill_world *world, int32_t key, double value);

/** Reads a world parameter (any DEMILL_WORLD_* key) into *value.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_UNKNOWN_KEY. */
DEMILL_API demill_status demill_world_get(const demill_world *world, int32_t key, double *value);

/** Advances the world by `steps` time steps.
 *
 *  Before the first step every pair of materials in use (by particles or
 *  walls) must have a contact model (demill_pair_set() with
 *  DEMILL_PAIR_NORMAL); otherwise DEMILL_ERR_NO_CONTACT_MODEL is returned
 *  and nothing changes. `steps` = 0 only evaluates the forces at the current
 *  state (so that forces, torques, contacts and energies can be read).
 *
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NO_CONTACT_MODEL,
 *          DEMILL_ERR_INVALID_VALUE or DEMILL_ERR_OUT_OF_MEMORY. If memory
 *          runs out in the middle of a run, the world holds the state after
 *          the last completed step. */
DEMILL_API demill_status demill_world_step(demill_world *world, uint64_t steps);

/** Suggests a time step for the current scene (PHYSICS.md §8), from every
 *  pair of materials that can meet: particle materials with each other and
 *  with the materials of walls and drum, each taken with its lightest
 *  particle (smallest radius), so that m* and R* are the smallest the scene
 *  has. For a linear normal law, ω = √(k_n/m*), the contact lasts
 *  π/ω and the explicit integrators are stable for Δt < 2/ω. For a Hertz
 *  law the stiffness grows with the overlap: at the impact speed v the
 *  largest overlap is δ = (15 m* v² / (16 E* √R*))^(2/5), the contact lasts
 *  2.87 (m*² / (R* E*² v))^(1/5) and the stiffness 2 E* √(R* δ) sets
 *  the stability limit; the Rayleigh time π R √(ρ/G) / (0.1631 ν + 0.8766)
 *  of each particle material bounds the step too (0.2 of it, as is usual).
 *  The suggestion is the smallest of: contact time / steps_per_contact,
 *  0.2 Rayleigh time (Hertz) and 0.2 of the stability limit.
 *  @param impact_speed      the largest impact speed expected, m/s; 0 lets
 *                           the library estimate it from the scene (twice the
 *                           fastest particle, the speed of a fall through the
 *                           height of the scene, twice the drum's rim speed at
 *                           its set speed), with 1 m/s at least.
 *  @param steps_per_contact how finely to resolve the shortest contact, >= 1;
 *                           0 takes 50 (about 1 % in restitution with velocity
 *                           Verlet, see docs/physics.md §8).
 *  @param suggested         receives the suggested Δt, s.
 *  @param critical          receives the stability limit of the explicit
 *                           integrators, s (may be NULL).
 *  @param contact_time      receives the shortest contact duration, s (may be
 *                           NULL).
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (suggested), DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (a negative argument, or a world without
 *          particles) or DEMILL_ERR_NO_CONTACT_MODEL. Changes nothing. */
DEMILL_API demill_status demill_world_suggest_time_step(demill_world *world, double impact_speed,
                                                        double steps_per_contact,
                                                        double *suggested, double *critical,
                                                        double *contact_time);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_WORLD_H */
