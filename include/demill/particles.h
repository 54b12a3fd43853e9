/** @file demill/particles.h
 * @brief Adding, removing, reading and writing particles.
 *
 * Bulk functions move whole fields in and out as flat, caller-owned arrays of
 * doubles: a vector field takes 3 doubles per particle (x, y, z; in a 2D
 * world z is 0, and angular velocity has only its z component), a scalar
 * field 1, an orientation 4 (w, x, y, z). Bulk reads and writes use "id
 * order": the order in which demill_particles_read_ids() lists the
 * particles. That order changes only when particles are added or removed.
 */
#ifndef DEMILL_PARTICLES_H
#define DEMILL_PARTICLES_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Particle fields, for demill_particles_read(), demill_particles_write(),
 *  demill_particle_get() and demill_particle_set(). */
enum {
    DEMILL_PARTICLE_POSITION = 1,         /**< 3 doubles, m; read/write */
    DEMILL_PARTICLE_VELOCITY = 2,         /**< 3 doubles, m/s; read/write */
    DEMILL_PARTICLE_ANGULAR_VELOCITY = 3, /**< 3 doubles, rad/s; read/write (2D: x = y = 0) */
    DEMILL_PARTICLE_RADIUS = 4,           /**< 1 double, m, > 0; read/write (mass follows) */
    DEMILL_PARTICLE_MASS = 5,             /**< 1 double, kg; read-only (a clump's member: its clump's mass, which its contacts see) */
    DEMILL_PARTICLE_FORCE = 6,            /**< 3 doubles, N: total force (contacts, gravity and local damping, DEMILL_MATERIAL_LOCAL_DAMPING) at the last force evaluation; read-only */
    DEMILL_PARTICLE_TORQUE = 7,           /**< 3 doubles, N m: total torque (contacts and local damping) at the last force evaluation; read-only */
    DEMILL_PARTICLE_ANGLE = 8,            /**< 1 double, rad: 2D worlds only, rotation angle θ about z; read/write */
    /** 1 double, 0 or 1; read/write. A fixed particle (1) never moves: no
     *  force moves or turns it, gravity included, and its velocity and
     *  angular velocity are 0 (fixing a particle sets them to 0; writing
     *  them non-zero while it is fixed gives DEMILL_ERR_INVALID_VALUE). It
     *  touches the particles that move, as an infinitely heavy particle: the
     *  contact's reduced mass m* is the moving particle's mass. Two fixed
     *  particles do not touch, nor does a fixed particle touch a wall. For
     *  rough floors and walls made of particles. 0 makes it move again. */
    DEMILL_PARTICLE_FIXED = 9,
    /** 4 doubles (w, x, y, z): 3D worlds only, the orientation as a unit
     *  quaternion, turning the particle's body frame into the world frame
     *  (a vector b of the body is R(q) b in the world); read/write. A new
     *  particle starts at (1, 0, 0, 0); each step turns it by the angular
     *  velocity (docs/shapes.md, Orientation). A write is normalised (any
     *  non-zero multiple of a rotation's quaternion gives that rotation);
     *  a component that is not finite gives DEMILL_ERR_NOT_FINITE, all four
     *  0 DEMILL_ERR_INVALID_VALUE, a 2D world DEMILL_ERR_DIMENSION. */
    DEMILL_PARTICLE_ORIENTATION = 10
};

/** Id fields, for demill_particles_read_ids(). */
enum {
    DEMILL_PARTICLE_ID = 100,       /**< the particle's own id */
    DEMILL_PARTICLE_MATERIAL = 101, /**< the id of the particle's material */
    DEMILL_PARTICLE_CLUMP = 102     /**< the id of the clump it is a member of (demill/clump.h), DEMILL_ID_NONE for a particle of no clump */
};

/** Flags for demill_particles_add(). */
enum {
    /** Reject the whole batch with DEMILL_ERR_OVERLAP if any new particle
     *  overlaps an existing particle, another new particle or a wall. */
    DEMILL_ADD_NO_OVERLAP = 1u
};

/** The size of a particle field.
 *  @param field a DEMILL_PARTICLE_* field.
 *  @return the number of doubles per particle of the field (1, 3 or 4), or 0
 *          for an unknown field. */
DEMILL_API int32_t demill_particle_field_size(int32_t field);

/** Adds n particles of one material. In a 2D world z components must be 0.
 *  @param world      the world.
 *  @param material   the particles' material.
 *  @param n          number of particles (0 is allowed and does nothing).
 *  @param positions  3n doubles: centres in m.
 *  @param radii      n doubles: radii in m, > 0, such that the particle's
 *                    mass and moment of inertia and their inverses are
 *                    finite and positive (in doubles: about 1e-100 m to
 *                    1e60 m at the density of steel).
 *  @param velocities 3n doubles in m/s, or NULL for rest.
 *  @param flags      0 or DEMILL_ADD_NO_OVERLAP; other bits give
 *                    DEMILL_ERR_UNKNOWN_KEY.
 *  @param[out] ids   n ids written on success, or NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE,
 *          DEMILL_ERR_UNKNOWN_KEY (flags), DEMILL_ERR_DIMENSION,
 *          DEMILL_ERR_OVERLAP or DEMILL_ERR_OUT_OF_MEMORY. On failure no
 *          particle is added and the
 *          message names the first offending particle by its index in the
 *          batch. */
DEMILL_API demill_status demill_particles_add(demill_world *world, demill_id material, size_t n,
                                              const double *positions, const double *radii,
                                              const double *velocities, uint32_t flags,
                                              demill_id *ids);

/** Removes n particles. Their ids become invalid; contacts with them end.
 *  On failure nothing is removed.
 *  @param world the world.
 *  @param n     the number of ids.
 *  @param ids   n particle ids.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (the message names the first
 *          bad id), DEMILL_ERR_INVALID_VALUE (an id listed twice, or a
 *          member of a clump: demill_clump_remove() removes it with its
 *          clump), DEMILL_ERR_NULL_POINTER or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_particles_remove(demill_world *world, size_t n,
                                                 const demill_id *ids);

/** Reads a field of every particle, in id order, into out.
 *  @param world       the world.
 *  @param field       a DEMILL_PARTICLE_* field.
 *  @param[out] out    capacity × field size doubles, or NULL to ask the count.
 *  @param capacity    number of particles out can hold.
 *  @param[out] count  receives the number of particles (may be NULL if out is
 *                     not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_DIMENSION (the angle in a 3D world, the orientation
 *          in a 2D one),
 *          DEMILL_ERR_NULL_POINTER or DEMILL_ERR_BUFFER_TOO_SMALL (nothing
 *          written, *count set). */
DEMILL_API demill_status demill_particles_read(const demill_world *world, int32_t field,
                                               double *out, size_t capacity, size_t *count);

/** Reads the ids or the material ids of every particle, in id order (this
 *  function defines id order).
 *  @param world       the world.
 *  @param field       DEMILL_PARTICLE_ID, DEMILL_PARTICLE_MATERIAL or
 *                     DEMILL_PARTICLE_CLUMP.
 *  @param[out] out    capacity ids, or NULL to ask the count.
 *  @param capacity    number of particles out can hold.
 *  @param[out] count  receives the number of particles (may be NULL if out is
 *                     not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NULL_POINTER or DEMILL_ERR_BUFFER_TOO_SMALL (nothing
 *          written, *count set). */
DEMILL_API demill_status demill_particles_read_ids(const demill_world *world, int32_t field,
                                                   demill_id *out, size_t capacity,
                                                   size_t *count);

/** Writes a field of every particle, in id order. Values are checked first;
 *  on failure nothing is written and the message names the first bad
 *  particle by its position in id order.
 *  @param world the world.
 *  @param field a writable DEMILL_PARTICLE_* field.
 *  @param in    n × field size doubles.
 *  @param n     the number of particles in `in`; must equal the number of
 *               particles of the world. A radius must give a mass and a
 *               moment of inertia that are finite and positive, as are
 *               their inverses (see demill_particles_add()).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (a bad value, n
 *          is not the number of particles, or the world has clumps, whose
 *          members only their clump moves: demill_clump_set()) or
 *          DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_particles_write(demill_world *world, int32_t field,
                                                const double *in, size_t n);

/** Reads one particle's field.
 *  @param world     the world.
 *  @param particle  the particle's id.
 *  @param field     a DEMILL_PARTICLE_* field.
 *  @param[out] out  receives the field's 1, 3 or 4 doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_DIMENSION (the angle in a 3D world, the orientation
 *          in a 2D one) or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_particle_get(const demill_world *world, demill_id particle,
                                             int32_t field, double *out);

/** Writes one particle's field. The value is checked first; on failure
 *  nothing is written.
 *  @param world    the world.
 *  @param particle the particle's id.
 *  @param field    a writable DEMILL_PARTICLE_* field.
 *  @param in       the field's 1, 3 or 4 doubles (a radius as for
 *                  demill_particles_write()).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (a bad value, or
 *          the particle is a member of a clump, which moves it:
 *          demill_clump_set()) or DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_particle_set(demill_world *world, demill_id particle,
                                             int32_t field, const double *in);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_PARTICLES_H */
