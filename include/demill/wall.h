/** @file demill/wall.h
 * @brief Walls, bodies of infinite mass moved by a prescribed motion.
 *
 * A wall is not moved by the particles. Contact with a wall uses the contact
 * model of the pair (particle material, wall material) with R* = R and m* = m
 * of the particle. Walls are planes, triangle meshes (3D) and polylines (2D);
 * the drum of a mill (demill/drum.h) has walls of its own.
 */
#ifndef DEMILL_WALL_H
#define DEMILL_WALL_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Wall fields, read with demill_wall_get(). All are 3 doubles. */
enum {
    DEMILL_WALL_POINT = 1,            /**< a point on the plane, m (moves with the wall); of a mesh or polyline, where the origin of its coordinates is now */
    DEMILL_WALL_NORMAL = 2,           /**< unit normal, pointing to the side the particles are on; zero for a mesh or polyline */
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

/** Adds a triangle-mesh wall (3D worlds): a thin surface made of the given
 *  triangles, which particles touch from **both** sides (a chute, a hopper,
 *  a box of triangles: the winding of the triangles does not matter). The
 *  mesh is one rigid wall of one material. A sphere touching a flat or
 *  smooth region of the mesh feels one force, as on the true surface: one
 *  contact per local minimum of its distance to the mesh, found at a face,
 *  an edge or a vertex (docs/geometry.md); its contact history follows it
 *  from triangle to triangle. Triangles may be of any size, and edges may be
 *  shared by more than two triangles.
 *  The wall is at rest until demill_wall_set_motion() is called; its centre
 *  of rotation is the origin of the vertices' coordinates.
 *  @param world       the world.
 *  @param material    the wall's material.
 *  @param n_vertices  number of vertices.
 *  @param vertices    3 doubles (x, y, z) per vertex, m.
 *  @param n_triangles number of triangles, at least 1.
 *  @param triangles   3 vertex indices (from 0) per triangle.
 *  @param[out] out    receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_DIMENSION (a 2D world), DEMILL_ERR_NOT_FINITE (a
 *          vertex, named), DEMILL_ERR_INVALID_VALUE (no triangle, an index
 *          out of range or a triangle of zero area, named) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_mesh(demill_world *world, demill_id material,
                                              size_t n_vertices, const double *vertices,
                                              size_t n_triangles, const uint32_t *triangles,
                                              demill_id *out);

/** Adds a triangle-mesh wall (demill_wall_add_mesh()) from the bytes of an
 *  STL file, ASCII or binary (binary when the size is 84 + 50 n bytes).
 *  Each point x of the file is placed at A (scale x) + t, with `transform`
 *  = {A row by row, t} (12 doubles; NULL for none), so a CAD file in
 *  millimetres takes scale 0.001. Points exactly equal after that are one
 *  vertex, so the triangles of a closed or smooth surface share their edges.
 *  The facets' normals in the file are not used: a mesh is touched from
 *  both sides. docs/geometry.md lists what is read and each error.
 *  @param world     the world (3D).
 *  @param material  the wall's material.
 *  @param bytes     the file's bytes.
 *  @param size      their number.
 *  @param scale     the scale factor, finite and > 0.
 *  @param transform the affine placement after scaling, or NULL.
 *  @param[out] out  receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_DIMENSION (a 2D world), DEMILL_ERR_FORMAT (not a usable
 *          STL file: empty, foreign, truncated, malformed, a coordinate not
 *          finite, a triangle of zero area, no triangle; the message names
 *          the triangle and its line or byte), DEMILL_ERR_INVALID_VALUE (a
 *          scale or transform that is not finite, or a singular transform)
 *          or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_stl(demill_world *world, demill_id material,
                                             const void *bytes, size_t size, double scale,
                                             const double transform[12], demill_id *out);

/** Adds a triangle-mesh wall from an STL file (demill_wall_add_stl() on the
 *  file's bytes; messages start with the path).
 *  @param world     the world (3D).
 *  @param material  the wall's material.
 *  @param path      the file.
 *  @param scale     the scale factor, finite and > 0.
 *  @param transform the affine placement after scaling, or NULL.
 *  @param[out] out  receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_IO (the file cannot be read), or an error
 *          of demill_wall_add_stl(): DEMILL_ERR_INVALID_HANDLE,
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_DIMENSION, DEMILL_ERR_FORMAT,
 *          DEMILL_ERR_INVALID_VALUE or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_load_stl(demill_world *world, demill_id material,
                                              const char *path, double scale,
                                              const double transform[12], demill_id *out);

/** Adds a polyline wall (2D worlds): the segments between consecutive
 *  points, and from the last back to the first if `closed`. Like a mesh in
 *  3D (demill_wall_add_mesh()), it is a thin wall touched from both sides,
 *  with one contact per local minimum of the distance.
 *  The wall is at rest until demill_wall_set_motion() is called; its centre
 *  of rotation is the origin.
 *  @param world    the world.
 *  @param material the wall's material.
 *  @param n_points number of points: at least 2 (open) or 3 (closed).
 *  @param points   3 doubles per point, m, z = 0.
 *  @param closed   1: a closed loop; 0: an open line.
 *  @param[out] out receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_DIMENSION (a 3D world, or a point with z != 0),
 *          DEMILL_ERR_NOT_FINITE (a point, named), DEMILL_ERR_INVALID_VALUE
 *          (too few points, closed not 0 or 1, a segment of zero length,
 *          named) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_polyline(demill_world *world, demill_id material,
                                                  size_t n_points, const double *points,
                                                  int closed, demill_id *out);

/** The size of a mesh or polyline wall.
 *  @param world            the world.
 *  @param wall             the wall's id.
 *  @param[out] n_vertices  receives its number of vertices (points).
 *  @param[out] n_elements  receives its number of triangles (segments).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_INVALID_VALUE (the wall is not a mesh or a polyline). */
DEMILL_API demill_status demill_wall_mesh_info(const demill_world *world, demill_id wall,
                                               size_t *n_vertices, size_t *n_elements);

/** Removes a wall. Its id becomes invalid; contacts with it end.
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
 *          attached to the drum, demill_drum_attach_wall(), and turns with
 *          it). */
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
