/** @file demill/body.h
 * @brief Bodies: rigid bodies with mass that the particles move.
 *
 * A body is a rigid object of mass m that translates along its free axes
 * (rotation is not modelled), pushed by the particles on the walls attached
 * to it, tied to the ground by a spring and a damper per axis, pulled by
 * gravity (unless added with DEMILL_BODY_NO_GRAVITY) and driven by an
 * external force F(t) = F0 sin(2π f t + φ):
 *
 *     m ẍ_a = F_particles,a − k_a (x_a − rest_a) − c_a ẋ_a + F0_a sin(2π f t + φ) + m g_a
 *
 * along each free axis a. A wall attached to a body moves with it (its
 * velocity is the body's); contacts with it use the contact model of the
 * pair (particle material, wall material) with R* = R and m* = m of the
 * particle, as with any wall. A body steps with the world's integrator,
 * velocity Verlet or symplectic Euler (the iterative refinement refuses a
 * world with bodies), and joins the energy account (demill_world_energy():
 * DEMILL_ENERGY_BODY_*). docs/geometry.md, Bodies, describes them.
 */
#ifndef DEMILL_BODY_H
#define DEMILL_BODY_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Axes of a body: bits of the free-axes mask of demill_body_add(), and the
 *  axis of demill_body_set_spring(). */
enum {
    DEMILL_BODY_AXIS_X = 1, /**< the x axis */
    DEMILL_BODY_AXIS_Y = 2, /**< the y axis */
    DEMILL_BODY_AXIS_Z = 4  /**< the z axis (3D worlds only) */
};

/** Flags for demill_body_add(). */
enum {
    /** Gravity does not act on the body (by default it does, as on the
     *  particles: m g). */
    DEMILL_BODY_NO_GRAVITY = 1u
};

/** Body fields, read with demill_body_get(). All are 3 doubles. */
enum {
    DEMILL_BODY_POSITION = 1,        /**< the body's centre, m */
    DEMILL_BODY_VELOCITY = 2,        /**< its velocity, m/s */
    DEMILL_BODY_FORCE_PARTICLES = 3, /**< force of the particles on its walls at the last force evaluation, N */
    DEMILL_BODY_FORCE_SPRING = 4,    /**< force of its springs, -k (x - rest) along its free axes, N */
    DEMILL_BODY_FORCE_DAMPER = 5,    /**< force of its dampers, -c v along its free axes (v: the velocity its walls show the contacts), N */
    DEMILL_BODY_FORCE_EXTERNAL = 6   /**< the external force F0 sin(2π f t + φ) at the world's time, N */
};

/** Adds a body at rest, with no spring, damper, external force or wall.
 *  @param world     the world.
 *  @param mass      its mass, kg, finite and > 0.
 *  @param centre    its centre, m (the position DEMILL_BODY_POSITION reports
 *                   and springs pull towards their rest positions).
 *  @param free_axes the axes it moves along: a combination of
 *                   DEMILL_BODY_AXIS_* (0: it does not move; it still
 *                   measures the particles' force); z only in 3D.
 *  @param flags     0 or DEMILL_BODY_NO_GRAVITY; other bits give
 *                   DEMILL_ERR_UNKNOWN_KEY.
 *  @param[out] out  receives the body's id (of kind DEMILL_KIND_BODY).
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE (mass
 *          or centre), DEMILL_ERR_INVALID_VALUE (mass <= 0),
 *          DEMILL_ERR_UNKNOWN_KEY (free_axes or flags with unknown bits),
 *          DEMILL_ERR_DIMENSION (z free, or centre with z != 0, in a 2D
 *          world) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_body_add(demill_world *world, double mass, const double centre[3],
                                         int32_t free_axes, uint32_t flags, demill_id *out);

/** Removes a body. Its walls stay where it left them, at rest; its id
 *  becomes invalid, and its energies leave the world's account.
 *  @param world the world.
 *  @param body  the body's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_body_remove(demill_world *world, demill_id body);

/** Sets the spring and the damper that tie the body to the ground along one
 *  of its free axes: a force -stiffness (x - rest) - damping v along it.
 *  Both start at 0.
 *  @param world     the world.
 *  @param body      the body's id.
 *  @param axis      one DEMILL_BODY_AXIS_* (a free axis of the body).
 *  @param stiffness N/m, finite and >= 0.
 *  @param damping   N s/m, finite and >= 0.
 *  @param rest      the position of the body's centre along the axis at
 *                   which the spring is relaxed, m, finite.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY
 *          (axis is not one DEMILL_BODY_AXIS_*), DEMILL_ERR_DIMENSION (z in
 *          a 2D world), DEMILL_ERR_NOT_FINITE or DEMILL_ERR_INVALID_VALUE
 *          (stiffness or damping < 0, or the axis is not free). */
DEMILL_API demill_status demill_body_set_spring(demill_world *world, demill_id body, int32_t axis,
                                                double stiffness, double damping, double rest);

/** Sets the external force on the body, F(t) = amplitude sin(2π frequency t
 *  + phase), t the world's time (DEMILL_WORLD_TIME). It acts along the
 *  body's free axes. A zero amplitude removes it.
 *  @param world     the world.
 *  @param body      the body's id.
 *  @param amplitude 3 doubles, N, finite (z = 0 in a 2D world).
 *  @param frequency Hz, finite and >= 0.
 *  @param phase     rad, finite.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (frequency < 0)
 *          or DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_body_set_force(demill_world *world, demill_id body,
                                               const double amplitude[3], double frequency,
                                               double phase);

/** Attaches a wall to the body: from now on the wall moves with the body,
 *  keeping its place relative to the body's centre, and its contact forces
 *  push the body.
 *  @param world the world.
 *  @param body  the body's id.
 *  @param wall  a wall's id (demill_wall_add_plane()), at rest and attached
 *               to no body; the drum's walls cannot be attached.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (body or wall, or the
 *          drum's id) or DEMILL_ERR_INVALID_VALUE (the wall is attached to a
 *          body already, or moves: demill_wall_set_motion()). */
DEMILL_API demill_status demill_body_attach_wall(demill_world *world, demill_id body,
                                                 demill_id wall);

/** Reads a body field.
 *  @param world    the world.
 *  @param body     the body's id.
 *  @param field    a DEMILL_BODY_* field.
 *  @param[out] out receives the field's 3 doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_body_get(const demill_world *world, demill_id body, int32_t field,
                                         double *out);

/** Reads one energy term of one body: DEMILL_ENERGY_BODY_KINETIC,
 *  _ELASTIC, _POTENTIAL, _DISSIPATED or _WORK (demill/query.h), which
 *  demill_world_energy() sums over the bodies.
 *  @param world      the world.
 *  @param body       the body's id.
 *  @param term       a DEMILL_ENERGY_BODY_* term.
 *  @param[out] value receives the energy, J.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_body_energy(const demill_world *world, demill_id body,
                                            int32_t term, double *value);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_BODY_H */
