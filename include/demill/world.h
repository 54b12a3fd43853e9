/** @file demill/world.h
 * @brief Creating, configuring and stepping a simulation world. */
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
    /** Velocity Verlet (kick-drift-kick), second order; dashpots and
     *  friction see the predicted end-of-step velocity (docs/physics.md §8).
     *  The default. */
    DEMILL_INTEGRATOR_VELOCITY_VERLET = 1,
    /** Symplectic (semi-implicit) Euler: v += a dt, then x += v dt. First
     *  order, cheapest. */
    DEMILL_INTEGRATOR_SYMPLECTIC_EULER = 2,
    /** The iterative refinement of Katnov (2020; docs/physics.md §8): a
     *  Taylor step with jerk, x += v Δt + a Δt²/2 + b Δt³/6,
     *  v += a Δt + b Δt²/2, whose jerk
     *  b = (a(t+Δt) - a(t))/Δt is refined by evaluating the forces again
     *  at the predicted state until the accelerations of successive
     *  iterates agree to DEMILL_WORLD_REFINE_TOLERANCE, or
     *  DEMILL_WORLD_REFINE_MAX_ITERATIONS force evaluations were made.
     *  Converged, it is the implicit linear-acceleration method (Newmark
     *  1959, β = 1/6, γ = 1/2): second order, stable up to ω Δt = 2√3 where
     *  Verlet is stable up to 2. Each iteration costs a force evaluation;
     *  only the accepted iterate advances the contact histories and the
     *  energy tallies. See docs/accuracy.md for what it buys. */
    DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT = 3
};

/** World parameter keys, used with demill_world_set() and demill_world_get().
 *  Keys 100-149 can be set; keys 150-199 are read-only. */
enum {
    /** Time step Δt in s, > 0. Default 1e-5. */
    DEMILL_WORLD_TIME_STEP = 100,
    /** Gravity vector, x component in m/s². Default 0. */
    DEMILL_WORLD_GRAVITY_X = 101,
    /** Gravity vector, y component in m/s². Default -9.81. */
    DEMILL_WORLD_GRAVITY_Y = 102,
    /** Gravity vector, z component in m/s². Default 0; in a 2D world it must
     *  stay 0. */
    DEMILL_WORLD_GRAVITY_Z = 103,
    /** The integrator, DEMILL_INTEGRATOR_*. Default
     *  DEMILL_INTEGRATOR_VELOCITY_VERLET. */
    DEMILL_WORLD_INTEGRATOR = 104,
    /** Verlet skin of the neighbour list as a fraction of the largest particle
     *  radius, in [0.01, 10]. Larger skins rebuild less often but test more
     *  pairs; results do not depend on it beyond round-off. Default 0.3. */
    DEMILL_WORLD_SKIN = 105,
    /** 2D worlds only: 0 (default) makes particles spheres constrained to the
     *  plane (m = 4/3 π R³ ρ, I = 2/5 m R²); a positive thickness t in m makes
     *  them discs (m = π R² t ρ, I = 1/2 m R²). Changing it recomputes the
     *  masses of all particles; a thickness that would make a mass or moment
     *  of inertia, or their inverse, not finite or 0 is refused. */
    DEMILL_WORLD_DISC_THICKNESS = 106,
    /** 1 (default) tallies dissipated energy and wall work during steps (see
     *  demill_world_energy()); 0 skips that work. */
    DEMILL_WORLD_ENERGY_TRACKING = 107,
    /** Simulated time in s. Settable, e.g. to continue a run. */
    DEMILL_WORLD_TIME = 108,
    /** Threads that stepping uses, a whole number in [0, 1024]; 0 takes
     *  OMP_NUM_THREADS if set, else one per processor the process may run
     *  on. Default 1. Results are bitwise the same for every thread count.
     *  More than one needs a library built with threads (DEMILL_ERR_UNSUPPORTED
     *  otherwise); getting the key gives the number in use. The library
     *  starts its own worker threads; a waiting one sleeps after about
     *  50 µs, and a world whose machine is too busy for the workers to help
     *  runs its loops on the calling thread alone. */
    DEMILL_WORLD_THREADS = 109,
    /** Iterative refinement: ε_a, the relative change of every acceleration
     *  component (translational and angular) between two iterates below
     *  which a step is accepted, in (0, 1]. The test is
     *  |a_k - a_(k-1)| <= ε_a (|a_k| + ā) per component, where ā is the
     *  mean magnitude over all particles at the start of the step (plus |g|;
     *  for angular accelerations plus ā over the mean radius), so that it
     *  stays meaningful where a is near 0. The first iterate is compared
     *  with the accelerations at the start of the step (from which its jerk,
     *  0, was made) to round-off only, so that a step over which nothing
     *  changes (free flight) takes one force evaluation and any other step
     *  at least two. Default 1e-4. */
    DEMILL_WORLD_REFINE_TOLERANCE = 110,
    /** Iterative refinement: force evaluations per step at most, a whole
     *  number in [1, 100]. A step that has not converged by then is accepted
     *  as it stands (counted in DEMILL_WORLD_REFINE_UNCONVERGED). Default 8. */
    DEMILL_WORLD_REFINE_MAX_ITERATIONS = 111,
    /** The stability watchdog, on (1, default) or off (0). When a run
     *  starts after the world was changed, it checks that the time step is
     *  within the stability limit of every pair of materials that can meet
     *  (see demill_world_suggest_time_step()); if not, demill_world_step()
     *  returns DEMILL_ERR_UNSTABLE naming the pair and the largest stable
     *  time step, and nothing changes. Every DEMILL_WORLD_WATCHDOG_INTERVAL
     *  steps, and at the end of every call, it checks that positions and
     *  velocities are finite, that no overlap exceeds
     *  DEMILL_WORLD_WATCHDOG_OVERLAP of the smaller radius, and that no
     *  energy is being created: with energy tracking on, the energy balance
     *  (DEMILL_ENERGY_TOTAL) may not grow by more than a quarter of the
     *  energy that went through the system since the run started; with it
     *  off, the kinetic energy may not outgrow twice what the last checked
     *  state, gravity and the drum could supply. When a check fails,
     *  demill_world_step() returns DEMILL_ERR_UNSTABLE with a message naming
     *  the particle, the time and the likely cause, and the world is put back
     *  to the last state that passed a check, or to where the failing call
     *  started if that is later: no call that returned DEMILL_OK is ever
     *  undone. (The last good state is kept as a copy, taken at every
     *  interval's check, which costs about as much memory as the particles
     *  and contacts; going back to a call's start steps that copy on again.)
     *  A run starting after the world was changed through the API starts
     *  from a fresh copy, so that a failure never undoes the caller's
     *  changes. Off, none of this is done, except that a call whose steps
     *  leave a position, velocity or spin that is not finite returns
     *  DEMILL_ERR_UNSTABLE, the world left where it diverged. */
    DEMILL_WORLD_WATCHDOG = 112,
    /** The watchdog's overlap limit as a fraction of the smaller radius of a
     *  contact, in (0, 1]. Default 0.25. */
    DEMILL_WORLD_WATCHDOG_OVERLAP = 113,
    /** Steps between the watchdog's checks, a whole number in [1, 1e6]; the
     *  state that passed the last check is what a failure returns to.
     *  Default 500 (on the drum3d benchmark the watchdog then costs under
     *  1 % of the run time; at 100, 4 %). */
    DEMILL_WORLD_WATCHDOG_INTERVAL = 114,
    /** 1 runs the contact kernels in single precision, 0 (default) in
     *  double. Positions, velocities, contact histories in storage and the
     *  sums of forces and energies stay double; the relative kinematics of
     *  each contact (normal, overlap, relative velocities, lever arms) are
     *  computed in double and rounded to float, and the contact law and its
     *  results (forces, torques, dissipation, the new history) are computed
     *  in float, twice as many contacts per vector instruction. Only the
     *  fast laws have single-precision kernels (linear or Hertz normal law,
     *  no or constant-torque rolling resistance, no cohesion): pairs with an
     *  elasto-plastic law, the rolling spring or cohesion stay in double.
     *  Results stay bitwise the same for every thread count, and snapshots
     *  and checkpoints keep the setting. What it costs in accuracy and gains
     *  in speed, and when to use it: docs/accuracy.md, Single precision. */
    DEMILL_WORLD_SINGLE_PRECISION = 115,
    /** 1 (default) turns each particle's orientation (DEMILL_PARTICLE_ORIENTATION;
     *  in 2D its angle) with its angular velocity at every step; 0 leaves the
     *  orientations of particles that are not members of a clump as they
     *  are. A sphere's or disc's orientation enters no force: contacts depend
     *  on its angular velocity, which is integrated either way, so positions,
     *  velocities and spins are bitwise the same with either setting, and 0
     *  saves the work of turning them (about 10 % of a step of the drum3d
     *  benchmark, docs/shapes.md) when nothing reads them. Clumps' orientations, which place their
     *  members, are always integrated. Snapshots and checkpoints keep the
     *  setting. */
    DEMILL_WORLD_ORIENTATION_TRACKING = 116,

    /** The world's dimension, 2 or 3. */
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
    DEMILL_WORLD_NEIGHBOUR_REBUILDS = 155,
    /** Force evaluations the last step took (1 except for the iterative
     *  refinement). */
    DEMILL_WORLD_REFINE_ITERATIONS = 156,
    /** Force evaluations made by steps since creation. */
    DEMILL_WORLD_FORCE_EVALUATIONS = 157,
    /** Iterative refinement: steps since creation that reached
     *  DEMILL_WORLD_REFINE_MAX_ITERATIONS without converging. */
    DEMILL_WORLD_REFINE_UNCONVERGED = 158
};

/** Creates an empty world of the given dimension (2 or 3) with default
 *  parameters: gravity (0, -9.81, 0), time step 1e-5 s, velocity Verlet.
 *  @param dimension 2 or 3.
 *  @param[out] out  receives the world; set to NULL on failure.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_INVALID_VALUE (bad
 *          dimension), DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_LIMIT (4096
 *          worlds are alive: each has its own tag in its ids). */
DEMILL_API demill_status demill_world_create(int32_t dimension, demill_world **out);

/** Frees a world and everything it owns. Ids of the world become
 *  meaningless.
 *  @param world the world to free; NULL is ignored. */
DEMILL_API void demill_world_destroy(demill_world *world);

/** The message of the last error reported by a function called on this
 *  world.
 *  @param world the world, or NULL.
 *  @return the message, naming the argument, particle or parameter at fault;
 *          "" if none. The string stays valid until the next call on the
 *          world. NULL or a pointer that is not a world gives a static
 *          message saying so; never NULL. */
DEMILL_API const char *demill_world_last_error(const demill_world *world);

/** Sets a world parameter.
 *  @param world the world.
 *  @param key   a settable DEMILL_WORLD_* key (below 150).
 *  @param value the new value, in the key's unit (demill_param_unit()).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (out of bounds, not a whole number for
 *          a choice, or the disc thickness of a world with clump templates,
 *          demill/clump.h), DEMILL_ERR_DIMENSION (e.g. gravity z in 2D) or
 *          DEMILL_ERR_UNSUPPORTED (more than one thread in a library built
 *          without threads). */
DEMILL_API demill_status demill_world_set(demill_world *world, int32_t key, double value);

/** Reads a world parameter.
 *  @param world      the world.
 *  @param key        any DEMILL_WORLD_* key.
 *  @param[out] value receives the value.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_UNKNOWN_KEY. */
DEMILL_API demill_status demill_world_get(const demill_world *world, int32_t key, double *value);

/** Advances the world by a number of time steps.
 *
 *  Before the first step every pair of materials in use (by particles or
 *  walls) must have a contact model (demill_pair_set() with
 *  DEMILL_PAIR_NORMAL); otherwise DEMILL_ERR_NO_CONTACT_MODEL is returned
 *  and nothing changes. `steps` = 0 only evaluates the forces at the current
 *  state (so that forces, torques, contacts and energies can be read).
 *
 *  With a progress callback set (demill_world_set_progress()), the call
 *  reports to it as it goes, and the callback may stop it.
 *
 *  @param world the world.
 *  @param steps the number of steps of DEMILL_WORLD_TIME_STEP to take.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NO_CONTACT_MODEL,
 *          DEMILL_ERR_INVALID_VALUE (also: the world's time is so large that
 *          a time step does not advance it, the iterative refinement is
 *          chosen in a world with bodies or clumps, or a pair that may touch combines
 *          an elasto-plastic normal law with DEMILL_DAMPING_RESTITUTION),
 *          DEMILL_ERR_OUT_OF_MEMORY,
 *          DEMILL_ERR_UNSTABLE or DEMILL_ERR_INTERRUPTED. If memory runs out
 *          in the middle of a run, the world holds the state after the last
 *          completed step. On DEMILL_ERR_UNSTABLE (see DEMILL_WORLD_WATCHDOG)
 *          the time step exceeds a pair's stability limit and nothing
 *          changed, or a check failed and the world holds the last state
 *          that passed it or the state this call started from; the message
 *          names the pair and the limit, or the particle, the time and the
 *          likely cause; the caller may lower the time step and step again.
 *          With the watchdog off it means the state is no longer finite, and
 *          the world is left so. No call returns DEMILL_OK with a position,
 *          velocity or spin that is not finite. On DEMILL_ERR_INTERRUPTED (the progress callback
 *          asked to stop) the world holds the state after the step it was
 *          called at, a valid state from which stepping may go on; the
 *          message says at which step and time the run stopped. */
DEMILL_API demill_status demill_world_step(demill_world *world, uint64_t steps);

/** A progress callback (see demill_world_set_progress()).
 *  @param user_data        the pointer given with the callback.
 *  @param steps_done       steps done so far by the current call of
 *                          demill_world_step().
 *  @param steps_total      steps that call was asked for.
 *  @param time             the world's simulated time now, s.
 *  @param steps_per_second steps_done over the wall-clock time since the call
 *                          began (a monotonic clock); 0 if that clock has not
 *                          advanced.
 *  @return 0 to go on; anything else stops the run after this step, and
 *          demill_world_step() returns DEMILL_ERR_INTERRUPTED. */
typedef int32_t (*demill_progress_fn)(void *user_data, uint64_t steps_done, uint64_t steps_total,
                                      double time, double steps_per_second);

/** Sets or removes the world's progress callback, so that a host program can
 *  show how a long run goes and stop it.
 *
 *  During every call of demill_world_step(world, steps) (and so of
 *  demill_world_settle(), which steps in runs of 1 ms of simulated time),
 *  fn is called after each `every_steps` steps of that call, with
 *  steps_done = every_steps, 2 every_steps, ..., and once more at the end
 *  (steps_done = steps_total) unless the last of those was the end. A call
 *  with steps = 0, or one that fails, does not report its end. If fn returns
 *  nonzero before the end, the run stops there: demill_world_step() returns
 *  DEMILL_ERR_INTERRUPTED and the world holds the state after that step,
 *  which is not a failure (nothing is put back) and from which the run can
 *  go on: stepping it the remaining steps gives bitwise the state the whole
 *  run would have reached. A nonzero return at the end has nothing left to
 *  stop and is ignored. The steps are run in stretches between reports, so
 *  a callback costs one call per every_steps steps; without one, nothing.
 *  The watchdog (DEMILL_WORLD_WATCHDOG) is unaffected: it checks at the
 *  same steps, and DEMILL_ERR_UNSTABLE behaves as without a callback.
 *
 *  fn is called between two steps, with the world in the state it has
 *  between two calls of demill_world_step(). It is meant to read the world:
 *  any function that does not change it may be called (demill_world_get(),
 *  demill_particles_read(), demill_drum_get(), demill_world_energy(),
 *  demill_vtk_write_particles(), demill_vtk_series_write(), ...). A call
 *  that changes the world is allowed too and takes effect from the next
 *  step, as if the run had been split into two calls there (a change that
 *  leaves the world unable to step, e.g. particles of a material without a
 *  contact model, ends the run with that error). fn must not destroy the
 *  world, and should not step it: a nested run would report to fn as well.
 *  A change of the callback itself applies from the next call of
 *  demill_world_step(). The callback is not part of the simulated state:
 *  the watchdog's return to a good state keeps the current callback.
 *
 *  @param world       the world.
 *  @param fn          the callback, or NULL to remove it (then user_data and
 *                     every_steps are ignored).
 *  @param user_data   passed to fn as it is; may be NULL.
 *  @param every_steps steps between reports, >= 1 (with a non-NULL fn).
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_VALUE (every_steps = 0 with a
 *          non-NULL fn; the callback is left as it was). */
DEMILL_API demill_status demill_world_set_progress(demill_world *world, demill_progress_fn fn,
                                                   void *user_data, uint64_t every_steps);

/** Suggests a time step for the current scene (docs/physics.md §8), from
 *  every pair of materials that can meet: particle materials with each other
 *  and with the materials of walls and drum, each taken with its lightest
 *  particle (smallest radius), so that m* and R* are the smallest the scene
 *  has. For a linear normal law, ω = √(k_n/m*) and the contact lasts π/ω.
 *  For a Hertz law the stiffness grows with the overlap: at the impact speed
 *  v the largest overlap is δ = (15 m* v² / (16 E* √R*))^(2/5), the contact
 *  lasts 2.87 (m*² / (R* E*² v))^(1/5) and the stiffness S = 2 E* √(R* δ)
 *  gives ω = √(S/m*); the Rayleigh time π R √(ρ/G) / (0.1631 ν + 0.8766)
 *  of each particle material (Li, Xu and Thornton 2005) bounds the step too
 *  (0.2 of it, as is usual).
 *  The stability limit of a pair is the smallest over its contact's modes
 *  of 2/(√(ω² + 4β²) + 2β), β = c/(2m) the damping rate of the mode's
 *  dashpot c (2/ω undamped; about 1/(2ξω) for a heavy damping ratio ξ):
 *  the normal spring and dashpot on m*; the tangential spring k_t and its
 *  dashpot, or the regularised Coulomb dashpot, on the mass the contact
 *  points move with their spins (1/m_a + 1/m_b + R_a²/I_a + R_b²/I_b, 2/7
 *  of m* for spheres); the rolling resistance's dashpot on the relative
 *  rotation. The suggestion is the smallest of: contact time /
 *  steps_per_contact, 0.2 Rayleigh time (Hertz) and 0.2 of the stability
 *  limit. With the watchdog on, demill_world_step() refuses a time step
 *  beyond the stability limit of a pair that can meet.
 *  @param world             the world.
 *  @param impact_speed      the largest impact speed expected, m/s; 0 lets
 *                           the library estimate it from the scene (twice the
 *                           fastest particle, the speed of a fall through the
 *                           height of the scene, twice the drum's rim speed at
 *                           its set speed), with 1 m/s at least.
 *  @param steps_per_contact how finely to resolve the shortest contact, >= 1;
 *                           0 takes 50 (about 1 % in restitution with velocity
 *                           Verlet, see docs/physics.md §8).
 *  @param[out] suggested    receives the suggested Δt, s.
 *  @param[out] critical     receives the smallest stability limit, s (may
 *                           be NULL).
 *  @param[out] contact_time receives the shortest contact duration, s (may be
 *                           NULL).
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (suggested), DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (a negative argument, a world without
 *          particles, or an elasto-plastic normal law with
 *          DEMILL_DAMPING_RESTITUTION), DEMILL_ERR_NO_CONTACT_MODEL, DEMILL_ERR_UNSTABLE (no
 *          time step integrates a pair: restitution 0 with the clamped normal
 *          law) or DEMILL_ERR_OUT_OF_MEMORY. Changes nothing. */
DEMILL_API demill_status demill_world_suggest_time_step(demill_world *world, double impact_speed,
                                                        double steps_per_contact,
                                                        double *suggested, double *critical,
                                                        double *contact_time);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_WORLD_H */
