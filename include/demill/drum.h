/** @file demill/drum.h
 * @brief The mill drum (shell, end caps and lifter bars), its speed,
 * the charge that fills it, and what mill engineers read from it.
 *
 * The drum's axis is parallel to z, through its centre (the origin unless
 * moved: DEMILL_DRUM_CENTER_X ...); seen from +z a positive
 * speed turns it counter-clockwise, so at the bottom the shell moves towards
 * +x and the charge is lifted on the +x side. In a 2D world the drum is a
 * circle in the xy plane with lifter polygons. Angles are in radians; polar
 * angles of the drum frame are measured counter-clockwise from +x.
 *
 * Charge angles are measured at the axis from the downward vertical (6
 * o'clock), positive in the direction of rotation: the shoulder (where the
 * charge leaves the shell, on the rising side) is positive, the toe (where
 * it lands) negative. docs/mill.md defines each reported quantity.
 */
#ifndef DEMILL_DRUM_H
#define DEMILL_DRUM_H

#include "world.h"
#include "grinding.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Drum parameter keys (demill_drum_set(), demill_drum_get()). Keys 400-449
 *  describe the drum and can be set; 450-499 are measurements (read-only).
 *  Changing the geometry rebuilds the drum's walls at the current angle. */
enum {
    /** Inner diameter D of the shell, m, > 0. Default 0.3. */
    DEMILL_DRUM_DIAMETER = 400,
    /** Axial length, m (3D: flat end caps at z = ±length/2), > 0. Default 0.1. */
    DEMILL_DRUM_LENGTH = 401,
    /** Number of evenly spaced lifters (replaces all lifters), 0-64. Default 0. */
    DEMILL_DRUM_LIFTERS = 402,
    /** Height of the evenly spaced lifters above the shell, m, >= 0. Default 0.015. */
    DEMILL_DRUM_LIFTER_HEIGHT = 403,
    /** Width of the evenly spaced lifters at the shell, m, > 0. Default 0.015. */
    DEMILL_DRUM_LIFTER_WIDTH = 404,
    /** Face angle of the evenly spaced lifters, rad, in [0, 1.4]: the angle
     *  between the leading face and the radial direction (0: a rectangular
     *  bar). Default 0. */
    DEMILL_DRUM_LIFTER_FACE_ANGLE = 405,
    /** Polar angle of lifter 0 at drum angle 0, rad. Default 3π/2 (6 o'clock). */
    DEMILL_DRUM_LIFTER_PHASE = 406,
    /** Target speed in rad/s (the three speed keys are views of one value;
     *  a negative speed turns the drum clockwise). Default 0. */
    DEMILL_DRUM_SPEED = 410,
    /** Target speed in revolutions per minute. */
    DEMILL_DRUM_SPEED_RPM = 411,
    /** Target speed as a fraction of the critical speed ω_c (see
     *  DEMILL_DRUM_CRITICAL_SPEED). */
    DEMILL_DRUM_SPEED_FRACTION = 412,
    /** Time over which the speed ramps linearly from its current value to a
     *  new target, s, >= 0. Default 0 (a step). */
    DEMILL_DRUM_RAMP_TIME = 413,
    /** Particle diameter d in ω_c = √(2 g / (D - d)), m, >= 0. Default 0:
     *  the largest particle diameter in the world. A speed given as a
     *  fraction of critical is converted when it is set and again at the
     *  start of every run, so that it follows the charge. */
    DEMILL_DRUM_CRITICAL_DIAMETER = 414,
    /** Bulk porosity assumed by demill_drum_fill() for a fill by volume
     *  fraction, in [0, 0.9]. Default 0.4. */
    DEMILL_DRUM_FILL_POROSITY = 415,
    /** Steps between samples of the charge shape for the per-revolution means,
     *  >= 1. Default 100. */
    DEMILL_DRUM_SAMPLE_INTERVAL = 416,
    /** Whether the drum has its analytic shell and end caps, 1 or 0.
     *  Default 1. With 0 the drum's walls are only its analytic lifters, if
     *  any, and the walls attached to it (demill_drum_attach_wall()): a drum
     *  built from an STL of its shell, caps and lifters. The diameter stays
     *  the drum's: the critical speed, the charge-shape ring and the fill
     *  region use it. */
    DEMILL_DRUM_SHELL = 417,
    /** x of the drum's centre (the point of its axis midway between the
     *  caps), m. Reads where it is now; setting a component moves the drum
     *  there at once (every wall of the drum: shell, caps, lifters and the
     *  walls attached to it), its motion then going on from there.
     *  Default 0. Charge angles, the charge's centre of mass and the torque
     *  are taken about the centre. */
    DEMILL_DRUM_CENTER_X = 418,
    /** y of the drum's centre (see DEMILL_DRUM_CENTER_X), m. */
    DEMILL_DRUM_CENTER_Y = 419,
    /** z of the drum's centre (see DEMILL_DRUM_CENTER_X), m; 0 in 2D. */
    DEMILL_DRUM_CENTER_Z = 420,
    /** x of the drum's steady translation velocity, m/s: the centre moves
     *  at it, the axis keeping its direction. Default 0. The drum's power
     *  and energy in count the work of the force on it, -F·v, beside that
     *  of the torque. */
    DEMILL_DRUM_VELOCITY_X = 421,
    /** y of the drum's steady velocity (see DEMILL_DRUM_VELOCITY_X), m/s. */
    DEMILL_DRUM_VELOCITY_Y = 422,
    /** z of the drum's steady velocity, m/s; 0 in 2D. */
    DEMILL_DRUM_VELOCITY_Z = 423,
    /** x of the amplitude vector a of the drum's harmonic translation, m:
     *  its centre moves by a sin(2π f t' + φ) on top of the steady motion
     *  (f: DEMILL_DRUM_VIBRATION_FREQUENCY, φ: DEMILL_DRUM_VIBRATION_PHASE,
     *  t' the time since the motion was last set). Default 0. Setting any
     *  of the motion keys (418-428) restarts t' from now with the centre
     *  where it is, so the drum does not jump (its velocity may). */
    DEMILL_DRUM_VIBRATION_X = 424,
    /** y of the vibration's amplitude vector (see DEMILL_DRUM_VIBRATION_X), m. */
    DEMILL_DRUM_VIBRATION_Y = 425,
    /** z of the vibration's amplitude vector, m; 0 in 2D. */
    DEMILL_DRUM_VIBRATION_Z = 426,
    /** Frequency f of the drum's harmonic translation, Hz, >= 0 (0: none).
     *  Default 0. */
    DEMILL_DRUM_VIBRATION_FREQUENCY = 427,
    /** Phase φ of the drum's harmonic translation, rad. Default 0. */
    DEMILL_DRUM_VIBRATION_PHASE = 428,

    /** Critical speed ω_c = √(2 g / (D - d)), rad/s, with g the magnitude of
     *  the gravity vector. */
    DEMILL_DRUM_CRITICAL_SPEED = 450,
    /** Current speed, rad/s (differs from the target during a ramp). */
    DEMILL_DRUM_CURRENT_SPEED = 451,
    /** Angle the drum has turned since creation, rad. */
    DEMILL_DRUM_ANGLE = 452,
    /** Completed revolutions since the drum was first set turning (whole
     *  number). */
    DEMILL_DRUM_REVOLUTIONS = 453,
    /** z-torque the particles exert on the drum (shell, caps and lifters)
     *  about its axis at the last force evaluation, N m. */
    DEMILL_DRUM_TORQUE = 454,
    /** Power draw P = -T_z ω - F·v at the last force evaluation (T_z the
     *  torque about the axis through the centre, F the force on the drum,
     *  v the centre's velocity: 0 unless the drum translates), W. */
    DEMILL_DRUM_POWER = 455,
    /** Mean power draw over the last completed revolution, W (NaN before the
     *  first). */
    DEMILL_DRUM_POWER_MEAN = 456,
    /** Power estimate from the charge's centre of mass, M g x_cm ω (M the
     *  mass of all particles, x_cm measured towards the rising side), W. */
    DEMILL_DRUM_POWER_CM = 457,
    /** Mean of DEMILL_DRUM_POWER_CM over the last completed revolution, W
     *  (NaN before the first). */
    DEMILL_DRUM_POWER_CM_MEAN = 458,
    /** Toe angle of the charge at the current state, rad (NaN without a
     *  charge). */
    DEMILL_DRUM_TOE_ANGLE = 459,
    /** Shoulder angle of the charge at the current state, rad (NaN without a
     *  charge). */
    DEMILL_DRUM_SHOULDER_ANGLE = 460,
    /** Angle of the charge's centre of mass at the current state, rad (NaN
     *  without a charge). */
    DEMILL_DRUM_COM_ANGLE = 461,
    /** Mean of DEMILL_DRUM_TOE_ANGLE over the samples of the last completed
     *  revolution, rad. */
    DEMILL_DRUM_TOE_ANGLE_MEAN = 462,
    /** Mean of DEMILL_DRUM_SHOULDER_ANGLE over the samples of the last
     *  completed revolution, rad. */
    DEMILL_DRUM_SHOULDER_ANGLE_MEAN = 463,
    /** Mean of DEMILL_DRUM_COM_ANGLE over the samples of the last completed
     *  revolution, rad. */
    DEMILL_DRUM_COM_ANGLE_MEAN = 464,
    /** Energy the drum has put into the charge since creation (work of the
     *  contact forces on the drum's walls, with sign reversed), J. */
    DEMILL_DRUM_ENERGY_IN = 465,
    /** Energy dissipated in contacts of particles with the drum since
     *  creation, J. */
    DEMILL_DRUM_ENERGY_DISSIPATED = 466,
    /** Mean dissipation rate of the whole world (all contacts) over the last
     *  completed revolution, W (NaN before the first). */
    DEMILL_DRUM_DISSIPATION_MEAN = 467,
    /** Number of lifters. */
    DEMILL_DRUM_LIFTER_COUNT = 468,
    /** x component of the force the particles exert on the drum (shell,
     *  caps and lifters) at the last force evaluation, N: with the y and z
     *  components, the load the drum's bearings carry from the charge. */
    DEMILL_DRUM_FORCE_X = 469,
    /** y component of the force on the drum (see DEMILL_DRUM_FORCE_X), N. */
    DEMILL_DRUM_FORCE_Y = 470,
    /** z component of the force on the drum (see DEMILL_DRUM_FORCE_X), N. */
    DEMILL_DRUM_FORCE_Z = 471,
    /** x of the drum centre's velocity now, steady and harmonic, m/s. */
    DEMILL_DRUM_CURRENT_VELOCITY_X = 472,
    /** y of the drum centre's velocity now, m/s. */
    DEMILL_DRUM_CURRENT_VELOCITY_Y = 473,
    /** z of the drum centre's velocity now, m/s. */
    DEMILL_DRUM_CURRENT_VELOCITY_Z = 474
};

/** Parts of the drum, each with a material of its own
 *  (demill_drum_set_material()). */
enum {
    DEMILL_DRUM_PART_SHELL = 1,  /**< the cylindrical shell */
    DEMILL_DRUM_PART_CAPS = 2,   /**< the two flat end caps (3D only) */
    DEMILL_DRUM_PART_LIFTERS = 3 /**< every lifter */
};

/** Lifter fields (demill_drum_lifter_get()). */
enum {
    /** Force the particles exert on the lifter at the last force
     *  evaluation, N (3 doubles). */
    DEMILL_LIFTER_FORCE = 1,
    /** Mean of DEMILL_LIFTER_FORCE over the last completed revolution, N
     *  (3 doubles). */
    DEMILL_LIFTER_FORCE_MEAN = 2,
    /** Largest force magnitude since creation, N (1 double). */
    DEMILL_LIFTER_FORCE_PEAK = 3,
    /** Energy dissipated in contacts with the lifter since creation, J
     *  (1 double): what the lifter's impacts took out of the charge. */
    DEMILL_LIFTER_ENERGY = 4,
    /** Current polar angle of the lifter's centre line, rad (1 double). */
    DEMILL_LIFTER_ANGLE = 5
};

/** Size distributions for demill_drum_fill(). Sizes are diameters, m. */
enum {
    /** Discrete classes. params: n pairs (diameter, mass fraction); the
     *  fractions are normalised. */
    DEMILL_SIZES_CLASSES = 1,
    /** Rosin-Rammler by mass, F(d) = 1 - exp(-(d/d63)^n). params:
     *  d63, n, d_min, d_max (the distribution is truncated to [d_min, d_max]). */
    DEMILL_SIZES_ROSIN_RAMMLER = 2,
    /** Normal by mass. params: mean, standard deviation, d_min, d_max. */
    DEMILL_SIZES_NORMAL = 3
};

/** What a fill's target value means. */
enum {
    /** Number of particles. */
    DEMILL_FILL_COUNT = 1,
    /** Mass, kg. */
    DEMILL_FILL_MASS = 2,
    /** Bulk filling J: the fraction of the drum's inner volume (in 2D its
     *  area) the settled charge occupies, with the bulk porosity of
     *  DEMILL_DRUM_FILL_POROSITY. */
    DEMILL_FILL_FRACTION = 3
};

/** Kinds of wall in the collision spectrum (demill_drum_spectrum()). */
enum {
    DEMILL_SPECTRUM_SHELL = 0, /**< shell and end caps */
    DEMILL_SPECTRUM_LIFTER = 1 /**< lifters */
};

/** Creates a drum of the given wall material with default geometry (see the
 *  DEMILL_DRUM_* keys). A world has at most one drum.
 *  @param world    the world.
 *  @param material the material of the drum's walls.
 *  @param[out] out receives the drum's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_INVALID_VALUE (a drum exists), DEMILL_ERR_OUT_OF_MEMORY
 *          or DEMILL_ERR_LIMIT (the world has made 65535 drums, each with an
 *          id of its own). */
DEMILL_API demill_status demill_drum_create(demill_world *world, demill_id material,
                                            demill_id *out);

/** Removes the drum and its walls. Its id becomes invalid.
 *  @param world the world.
 *  @param drum  the drum's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_drum_remove(demill_world *world, demill_id drum);

/** Sets a drum parameter (keys 400-449). Speed keys set the target speed
 *  from now on (reached after DEMILL_DRUM_RAMP_TIME).
 *  @param world the world.
 *  @param drum  the drum's id.
 *  @param key   a settable DEMILL_DRUM_* key (400-449).
 *  @param value the new value, in the key's unit.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (out of bounds; lifters that do not fit),
 *          DEMILL_ERR_DIMENSION (a z component of the drum's motion other
 *          than 0 in a 2D world) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_set(demill_world *world, demill_id drum, int32_t key,
                                         double value);

/** Reads a drum parameter or measurement.
 *  @param world      the world.
 *  @param drum       the drum's id.
 *  @param key        any DEMILL_DRUM_* key (400-499).
 *  @param[out] value receives the value.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_drum_get(demill_world *world, demill_id drum, int32_t key,
                                         double *value);

/** Gives a part of the drum a material of its own: rubber lifters in a
 *  steel shell, say. demill_drum_create() gives every part its material.
 *  Contacts with the part's walls start afresh (their history is dropped),
 *  as the pair of materials, and with it the contact model, changes.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @param part     the part, DEMILL_DRUM_PART_*.
 *  @param material the part's new material.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY (no
 *          such part) or DEMILL_ERR_DIMENSION (the caps of a 2D drum). */
DEMILL_API demill_status demill_drum_set_material(demill_world *world, demill_id drum,
                                                  int32_t part, demill_id material);

/** Reads the material of a part of the drum.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @param part     the part, DEMILL_DRUM_PART_*.
 *  @param[out] out receives the material's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_UNKNOWN_KEY or DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_drum_get_material(demill_world *world, demill_id drum,
                                                  int32_t part, demill_id *out);

/** Makes a wall (a mesh, a polyline, a plane or a finite wall: cylinder,
 *  cone, disc or rectangle, a capped wall with its caps) a part of the
 *  drum: from now on it turns and moves with the drum, its own motion
 *  (rigid or harmonic) replaced. Its geometry is taken where it is now, at the drum's
 *  current angle, so nothing jumps; a surface velocity turns with it.
 *  It counts in everything the drum reports: torque, power, the force on
 *  the drum, energy in and dissipated, the collision spectrum's row of its
 *  part (shell and caps, or lifters) and, as part DEMILL_DRUM_PART_LIFTERS,
 *  the charge shape (a lifter mesh's depth, the drum's radius less its
 *  vertices' smallest distance from the axis, widens the ring next to the
 *  shell as the tallest lifter's height does). It is not one of the
 *  analytic lifters of demill_drum_lifter_get(). It keeps its own material
 *  and its id: demill_wall_remove() removes it, demill_wall_set_motion()
 *  refuses it, and demill_drum_remove() removes it with the drum. VTK
 *  output draws it with the drum's part.
 *  @param world the world.
 *  @param drum  the drum's id.
 *  @param wall  the wall's id (of this world, not yet attached).
 *  @param part  the part it becomes, DEMILL_DRUM_PART_*.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (a drum or wall id that is
 *          not valid in this world, the drum's id given as the wall),
 *          DEMILL_ERR_UNKNOWN_KEY (no such part), DEMILL_ERR_DIMENSION (the
 *          caps of a 2D drum) or DEMILL_ERR_INVALID_VALUE (the wall is
 *          attached already, to the drum or to a body). */
DEMILL_API demill_status demill_drum_attach_wall(demill_world *world, demill_id drum,
                                                 demill_id wall, int32_t part);

/** Adds lifters or liners to the drum from their cross-section: a polyline
 *  of `n_points` points (x, y) in the drum's frame at drum angle 0 (about
 *  its axis, polar angles as for demill_drum_add_lifter()),
 *  open or closed (the last point joined to the first), repeated
 *  `copies` times about the axis, copy k turned by 2πk/copies
 *  counter-clockwise: one lifter's profile makes `copies` evenly spaced
 *  lifters. In 3D each segment is extruded along the axis over the drum's
 *  length (z from -length/2 to length/2) into two triangles, in 2D it is a
 *  segment. The result is one mesh (3D) or polyline (2D) wall of the given
 *  material, attached to the drum as part `part` at its current angle
 *  (demill_drum_attach_wall(): it turns with the drum, counts in its
 *  torque, power, force and energy, and as part DEMILL_DRUM_PART_LIFTERS
 *  in the charge shape); its id is a wall's, for demill_wall_remove().
 *  The surface is thin and touched from either side, as a mesh's is: an
 *  open profile need only trace the faces the charge can reach. Changing
 *  the drum's diameter or length later does not change it.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @param material the wall's material.
 *  @param part     the part it becomes, DEMILL_DRUM_PART_*.
 *  @param n_points the number of points: 2 to 65536 (open), 3 to 65536
 *                  (closed).
 *  @param points   2 n_points doubles, x and y of each point, m: finite,
 *                  at most the drum's radius from the axis (a point on
 *                  the shell is inside), no two consecutive points equal.
 *  @param closed   1: the last point is joined to the first; 0: not.
 *  @param copies   the number of copies about the axis, 1 to 1024.
 *  @param[out] out receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (drum or material),
 *          DEMILL_ERR_UNKNOWN_KEY (no such part), DEMILL_ERR_DIMENSION (the
 *          caps of a 2D drum), DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE (a point that is not finite),
 *          DEMILL_ERR_INVALID_VALUE (closed not 0 or 1, too few or too
 *          many points, copies out of range, a point outside the shell, a
 *          segment of zero length) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_add_profile(demill_world *world, demill_id drum,
                                                 demill_id material, int32_t part,
                                                 size_t n_points, const double *points,
                                                 int closed, uint32_t copies, demill_id *out);

/** Adds one lifter to the drum.
 *  @param world      the world.
 *  @param drum       the drum's id.
 *  @param angle      polar angle of the lifter's centre line, rad (drum
 *                    frame, at drum angle 0).
 *  @param height     height above the shell, m, >= 0.
 *  @param width      width at the shell, m, > 0.
 *  @param face_angle inclination of the leading face from the radial
 *                    direction, rad, in [0, 1.4].
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (out of range, or more than 64 lifters)
 *          or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_add_lifter(demill_world *world, demill_id drum,
                                                double angle, double height, double width,
                                                double face_angle);

/** Reads a field of one lifter.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @param index    the lifter's index, from 0 to DEMILL_DRUM_LIFTER_COUNT - 1.
 *  @param field    a DEMILL_LIFTER_* field.
 *  @param[out] out receives the field's 1 or 3 doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_INVALID_VALUE
 *          (no such lifter), DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_drum_lifter_get(demill_world *world, demill_id drum,
                                                uint32_t index, int32_t field, double *out);

/** Fills the drum with particles of one material: sizes from a distribution
 *  (DEMILL_SIZES_*, with `params`), as many as the target (DEMILL_FILL_*,
 *  `value`) asks. It is demill_fill_region() (demill/insert.h) with the
 *  region DEMILL_REGION_DRUM: particles are placed one at a time, in a
 *  seeded random order of sizes, each at the lowest free place among random
 *  candidates in a layer that rises from the bottom of the drum as it fills,
 *  clear of the walls and of every particle already there, so that wide
 *  size distributions (a 50/50 charge of 10 and 20 mm balls, the 285 balls
 *  of Bond's test) fill as readily as one size. The placement depends only
 *  on the arguments, the drum and the particles already present, so the
 *  same call gives the same charge. Call it once per material (balls, then
 *  ore), then let the charge settle (demill_world_settle()).
 *  @param world        the world.
 *  @param drum         the drum's id.
 *  @param material     the particles' material.
 *  @param distribution the size distribution, DEMILL_SIZES_*.
 *  @param params       the distribution's parameters (see DEMILL_SIZES_*).
 *  @param nparams      the number of doubles in params.
 *  @param target       what `value` means, DEMILL_FILL_*.
 *  @param value        how many particles: a count, a mass or a fraction.
 *  @param seed         seed of the random sizes, order and jitter.
 *  @param[out] ids     receives the ids of the new particles (may be NULL).
 *  @param capacity     how many ids `ids` can hold.
 *  @param[out] added   receives the number of particles added (0 on failure;
 *                      on DEMILL_ERR_BUFFER_TOO_SMALL the number ids must
 *                      hold); may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_UNKNOWN_KEY, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (bad distribution or target; a target
 *          of more particles than a world holds, about 1.07e9; the charge
 *          does not fit: nothing is added),
 *          DEMILL_ERR_BUFFER_TOO_SMALL or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_fill(demill_world *world, demill_id drum, demill_id material,
                                          int32_t distribution, const double *params,
                                          size_t nparams, int32_t target, double value,
                                          uint64_t seed, demill_id *ids, size_t capacity,
                                          size_t *added);

/** Starts recording a collision energy spectrum: the energy dissipated in
 *  each collision (a contact, from touch to release), counted in `nbins`
 *  logarithmic bins from e_min to e_max J (below and above go to the first
 *  and last bin), per pair of particle size classes and per size class
 *  against the shell and against the lifters. Size classes are given by
 *  `nedges` increasing diameters: class k holds diameters below edge k (the
 *  last class everything above the last edge), so there are nedges + 1
 *  classes. Memory is fixed: (C(C+1)/2 + 2C) × nbins counters for C classes.
 *  Recording costs a history slot per contact; calling again restarts it.
 *  @param world  the world.
 *  @param drum   the drum's id.
 *  @param nedges the number of size class edges.
 *  @param edges  nedges increasing diameters, m.
 *  @param nbins  the number of energy bins, 1 to 10000.
 *  @param e_min  the lower edge of the first bin, J, > 0.
 *  @param e_max  the upper edge of the last bin, J, > e_min, far enough above
 *                it that log10(e_max) > log10(e_min).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_spectrum_start(demill_world *world, demill_id drum,
                                                    size_t nedges, const double *edges,
                                                    uint32_t nbins, double e_min, double e_max);

/** Reads the spectrum's counts: rows of nbins counters, first the particle
 *  pairs (class a <= class b, in the order (0,0), (0,1), ..., (1,1), ...),
 *  then for each class its collisions with the shell, then for each class
 *  with the lifters.
 *  @param world       the world.
 *  @param drum        the drum's id.
 *  @param[out] counts capacity counters, or NULL to ask the count.
 *  @param capacity    number of counters `counts` can hold.
 *  @param[out] count  receives the number of counters (may be NULL if counts
 *                     is not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_INVALID_VALUE (no spectrum started) or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_drum_spectrum(demill_world *world, demill_id drum,
                                              uint64_t *counts, size_t capacity, size_t *count);

/** Starts recording the impacts on the particles of one ore material,
 *  beside the drum's collision spectrum, which must be recording
 *  (demill_drum_spectrum_start(); starting that again ends this recording
 *  too). Each collision of an ore particle (a contact, from touch to
 *  release), with a particle or with any wall, counts as one impact on it,
 *  of the specific energy it absorbed: the energy dissipated in the
 *  collision times its share of the two bodies' compliances (1 − ν²)/E
 *  (Young's modulus E and Poisson ratio ν of each body's material; a wall's
 *  is its material's), divided by its mass. Two ore particles that collide
 *  each count an impact. Impacts are counted per size class of the
 *  particle, the classes of a grinding object (demill/grinding.h): class
 *  k < classes − 1 holds diameters in (top/√2^(k+1), top/√2^k] (larger
 *  ones go to class 0), the last everything finer; and per bin of specific
 *  energy, `nbins` logarithmic bins from e_min to e_max J/kg (below and
 *  above go to the first and last bin). Calling it again restarts the
 *  impacts, the collision spectrum's counts kept. Memory: classes × nbins
 *  counters; a run that does not record costs nothing more.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @param material the ore's material.
 *  @param top_size the upper limit of class 0, m, > 0.
 *  @param classes  the number of classes, 2 to 200.
 *  @param nbins    the number of energy bins, 1 to 10000.
 *  @param e_min    the lower edge of the first bin, J/kg, > 0.
 *  @param e_max    the upper edge of the last bin, J/kg, > e_min, with
 *                  log10(e_max) > log10(e_min).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (no collision spectrum recording, or a
 *          value out of range) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_drum_impacts_start(demill_world *world, demill_id drum,
                                                   demill_id material, double top_size,
                                                   uint32_t classes, uint32_t nbins, double e_min,
                                                   double e_max);

/** Reads the impacts on the ore's particles: a row of nbins counts per size
 *  class, class 0 first, and the time over which they were recorded.
 *  @param world       the world.
 *  @param drum        the drum's id.
 *  @param[out] counts capacity counters, or NULL to ask the count.
 *  @param capacity    the number of counters `counts` can hold.
 *  @param[out] count  receives classes × nbins (may be NULL if counts is
 *                     not).
 *  @param[out] time   receives the simulated time since the recording
 *                     started, s; may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_INVALID_VALUE (no impacts recorded) or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_drum_impacts(demill_world *world, demill_id drum, uint64_t *counts,
                                             size_t capacity, size_t *count, double *time);

/** The number of the ore's particles in each size class of the impacts'
 *  recording, now (the charge keeps its sizes: particles do not break in
 *  the DEM).
 *  @param world          the world.
 *  @param drum           the drum's id.
 *  @param[out] particles capacity counts, or NULL to ask the count.
 *  @param capacity       the number of counts `particles` can hold.
 *  @param[out] count     receives the number of classes (may be NULL if
 *                        particles is not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_INVALID_VALUE (no impacts recorded) or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_drum_impacts_particles(demill_world *world, demill_id drum,
                                                       uint64_t *particles, size_t capacity,
                                                       size_t *count);

/** Sets a grinding object's rates and appearance function from the impacts
 *  a drum recorded: demill_grinding_rates_from_impacts() with the drum's
 *  counts, its bins' edges (J/kg), the ore's particles per class and the
 *  recorded time. The recording's classes must be the object's (the same
 *  top size and number of classes). Errors of the world and the drum write
 *  the world's message; those of the grinding object and of its rates the
 *  object's (demill_grinding_last_error()).
 *  @param grinding the grinding object, with Tavares and King's model.
 *  @param world    the world.
 *  @param drum     the drum's id.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER or DEMILL_ERR_INVALID_HANDLE
 *          (grinding or world), DEMILL_ERR_INVALID_VALUE (no impacts
 *          recorded, classes that do not match, no time recorded, or an
 *          error of demill_grinding_rates_from_impacts()) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_grinding_rates_from_drum(demill_grinding *grinding,
                                                         demill_world *world, demill_id drum);

/** Steps the world until the charge has settled: until the kinetic energy per
 *  particle is below `energy_per_particle` and no larger than at the check
 *  before (the energy is looked at every millisecond of simulated time, so
 *  particles placed at rest and starting to fall do not count as settled),
 *  or `max_time` of simulated time has passed.
 *  @param world               the world.
 *  @param max_time            the longest time to step, s, >= 0.
 *  @param energy_per_particle the kinetic energy per particle that counts as
 *                             settled, J, >= 0.
 *  @param[out] settled        receives 1 if the charge settled, 0 if the
 *                             time ran out; may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (negative arguments, or max_time more
 *          than 1e18 time steps), and what demill_world_step() returns:
 *          DEMILL_ERR_NO_CONTACT_MODEL, DEMILL_ERR_INVALID_VALUE (the clock
 *          cannot advance), DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_UNSTABLE.
 *          The steps are counted, so that the call always ends. */
DEMILL_API demill_status demill_world_settle(demill_world *world, double max_time,
                                             double energy_per_particle, int32_t *settled);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_DRUM_H */
