/** @file demill/wall.h
 * @brief Walls, bodies of infinite mass moved by a prescribed motion.
 *
 * A wall is not moved by the particles, unless it is attached to a body
 * (demill/body.h), which they move. Contact with a wall uses the contact
 * model of the pair (particle material, wall material) with R* = R and m* = m
 * of the particle. The drum of a mill joins these walls in a later version.
 */
#ifndef DEMILL_WALL_H
#define DEMILL_WALL_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Wall fields, read with demill_wall_get(). All are 3 doubles. */
enum {
    DEMILL_WALL_POINT = 1,            /**< a point on the plane, m (moves with the wall) */
    DEMILL_WALL_NORMAL = 2,           /**< unit normal, pointing to the side the particles are on */
    DEMILL_WALL_CENTRE = 3,           /**< centre of rotation, m (moves with the wall's velocity) */
    DEMILL_WALL_VELOCITY = 4,         /**< velocity of the centre, m/s */
    DEMILL_WALL_ANGULAR_VELOCITY = 5, /**< angular velocity about the centre, rad/s */
    DEMILL_WALL_FORCE = 6,            /**< force the particles exert on the wall at the last force evaluation, N */
    DEMILL_WALL_TORQUE = 7            /**< torque the particles exert on the wall about its centre, N m */
};

/** Adds a plane wall: the boundary of the solid half-space behind `point`,
 *  facing `normal` (which need not be of unit length). A particle is in
 *  contact when its centre is closer than its radius to the plane, or behind
 *  it. In a 2D world the plane is a line: z components must be 0.
 *  The wall is at rest until demill_wall_set_motion() is called; its centre of
 *  rotation is `point`.
 *  @param world    the world.
 *  @param material the wall's material.
 *  @param point    a point on the plane, m.
 *  @param normal   the plane's normal, towards the particles' side.
 *  @param[out] out receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (zero normal),
 *          DEMILL_ERR_DIMENSION or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_plane(demill_world *world, demill_id material,
                                               const double point[3], const double normal[3],
                                               demill_id *out);

/** Removes a wall. Its id becomes invalid; contacts with it end; a wall
 *  attached to a body leaves it.
 *  @param world the world.
 *  @param wall  the wall's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_wall_remove(demill_world *world, demill_id wall);

/** Sets the wall's rigid motion from now on: its centre of rotation is
 *  `centre` and moves with `velocity`, and the wall turns about it with
 *  `angular_velocity`. Any pointer may be NULL: NULL velocity or angular
 *  velocity means zero, NULL centre keeps the current centre. Positions are
 *  advanced exactly (no drift) from the moment of this call. In 2D, velocity
 *  and centre must have z = 0 and the angular velocity only a z component.
 *  @param world            the world.
 *  @param wall             the wall's id.
 *  @param velocity         velocity of the centre, m/s, or NULL for 0.
 *  @param angular_velocity angular velocity about the centre, rad/s, or NULL
 *                          for 0.
 *  @param centre           the centre of rotation, m, or NULL to keep it.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_DIMENSION or DEMILL_ERR_INVALID_VALUE (the wall is
 *          attached to a body, demill_body_attach_wall(), and moves with it). */
DEMILL_API demill_status demill_wall_set_motion(demill_world *world, demill_id wall,
                                                const double velocity[3],
                                                const double angular_velocity[3],
                                                const double centre[3]);

/** Reads a wall field.
 *  @param world    the world.
 *  @param wall     the wall's id.
 *  @param field    a DEMILL_WALL_* field.
 *  @param[out] out receives the field's 3 doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_wall_get(const demill_world *world, demill_id wall,
                                         int32_t field, double *out);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_WALL_H */
