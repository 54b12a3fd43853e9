/** @file demill/wall.h
 * @brief Walls, bodies of infinite mass moved by a prescribed motion.
 *
 * A wall is not moved by the particles, unless it is attached to a body
 * (demill/body.h), which they move. Contact with a wall uses the contact
 * model of the pair (particle material, wall material) with R* = R and m* = m
 * of the particle. Walls are planes, triangle meshes (3D) and polylines (2D),
 * and in 3D the finite walls; the drum of a mill (demill/drum.h) has walls
 * of its own.
 *
 * A plane is the boundary of a half-space. The finite walls (cylinders,
 * cones, discs and annuli, rectangles; 3D worlds only) are thin surfaces
 * that particles touch from either side, at the exact closest point of the
 * surface, its rims and edges included: a particle beyond a rim or an edge
 * is pushed from the nearest point of the rim. A particle touches a wall at
 * one point, except a capped cylinder or cone, whose side and caps are
 * touched separately (a particle in the inner corner of a closed can feels
 * the floor and the side); the rim is the side's.
 */
#ifndef DEMILL_WALL_H
#define DEMILL_WALL_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Wall fields, read with demill_wall_get(). All are 3 doubles. For a
 *  finite wall, the point is its centre or the start of its axis and the
 *  normal its unit normal or axis; a capped wall's force and torque include
 *  its caps'. */
enum {
    DEMILL_WALL_POINT = 1,            /**< a point on the plane, m (moves with the wall); of a mesh or polyline, where the origin of its coordinates is now */
    DEMILL_WALL_NORMAL = 2,           /**< unit normal, pointing to the side the particles are on; zero for a mesh or polyline */
    DEMILL_WALL_CENTRE = 3,           /**< centre of rotation, m (moves with the wall's velocity) */
    DEMILL_WALL_VELOCITY = 4,         /**< velocity of the centre, m/s */
    DEMILL_WALL_ANGULAR_VELOCITY = 5, /**< angular velocity about the centre, rad/s */
    DEMILL_WALL_FORCE = 6,            /**< force the particles exert on the wall at the last force evaluation, N */
    DEMILL_WALL_TORQUE = 7,           /**< torque the particles exert on the wall about its centre, N m */
    DEMILL_WALL_SURFACE_VELOCITY = 8  /**< the surface's velocity along itself (demill_wall_set_surface_velocity()), m/s */
};

/** Caps of demill_wall_add_cylinder() and demill_wall_add_cone(): which
 *  ends are closed by a cap, a disc joined to the rim (flags, or'ed). */
enum {
    DEMILL_CAPS_NONE = 0,  /**< no cap: a tube open at both ends */
    DEMILL_CAPS_START = 1, /**< a cap at `point`, the start of the axis */
    DEMILL_CAPS_END = 2,   /**< a cap at `point` + `length` × axis */
    DEMILL_CAPS_BOTH = 3   /**< both: a closed can */
};

/** Modes of demill_wall_set_harmonic(). */
enum {
    DEMILL_HARMONIC_TRANSLATION = 1, /**< the wall moves along the axis */
    DEMILL_HARMONIC_ROTATION = 2     /**< the wall turns about the axis through its centre */
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

/** Adds a finite cone or frustum (a hopper): the surface of revolution
 *  about the axis from `point` that has radius `radius_start` at `point`
 *  and `radius_end` at `point` + `length` × axis (unit axis), the radius
 *  varying linearly between; one radius may be 0 (a cone's apex). A thin
 *  surface, touched from inside and outside; with `caps` its ends are
 *  closed by caps (an end of radius 0 needs none). Its point is `point`, its
 *  normal the unit axis, its centre of rotation `point`. 3D worlds only.
 *  @param world        the world.
 *  @param material     the wall's material.
 *  @param point        the start of the axis, m.
 *  @param axis         the axis's direction (need not be of unit length).
 *  @param radius_start radius at the start, m (>= 0).
 *  @param radius_end   radius at the end, m (>= 0, not both 0).
 *  @param length       distance from start to end along the axis, m (> 0).
 *  @param caps         DEMILL_CAPS_NONE, DEMILL_CAPS_START,
 *                      DEMILL_CAPS_END or DEMILL_CAPS_BOTH.
 *  @param[out] out     receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (zero axis, a
 *          negative radius, both radii 0, length not positive, unknown
 *          caps), DEMILL_ERR_DIMENSION (a 2D world) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_cone(demill_world *world, demill_id material,
                                              const double point[3], const double axis[3],
                                              double radius_start, double radius_end,
                                              double length, int32_t caps, demill_id *out);

/** Adds a finite cylinder of `radius` about the axis from `point` to
 *  `point` + `length` × axis (unit axis): demill_wall_add_cone() with both
 *  radii equal. A thin surface, touched from inside and outside, open or
 *  closed by caps at either end. 3D worlds only.
 *  @param world    the world.
 *  @param material the wall's material.
 *  @param point    the start of the axis, m.
 *  @param axis     the axis's direction (need not be of unit length).
 *  @param radius   the radius, m (> 0).
 *  @param length   the length along the axis, m (> 0).
 *  @param caps     DEMILL_CAPS_NONE, DEMILL_CAPS_START,
 *                  DEMILL_CAPS_END or DEMILL_CAPS_BOTH.
 *  @param[out] out receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (zero axis,
 *          radius or length not positive, unknown caps),
 *          DEMILL_ERR_DIMENSION (a 2D world) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_cylinder(demill_world *world, demill_id material,
                                                  const double point[3], const double axis[3],
                                                  double radius, double length, int32_t caps,
                                                  demill_id *out);

/** Adds a disc, or with `inner_radius` > 0 an annulus (an orifice plate):
 *  the points of the plane through `centre` normal to `normal` whose
 *  distance from `centre` lies between `inner_radius` and `outer_radius`.
 *  A thin surface touched from both sides; both rims are edges. Its point
 *  and centre of rotation are `centre`, its normal the unit normal. 3D
 *  worlds only.
 *  @param world        the world.
 *  @param material     the wall's material.
 *  @param centre       the centre, m.
 *  @param normal       the plane's normal (need not be of unit length).
 *  @param outer_radius the outer radius, m (> 0).
 *  @param inner_radius the hole's radius, m (0 for a full disc, below
 *                      outer_radius).
 *  @param[out] out     receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (zero normal, a
 *          radius not positive, inner >= outer), DEMILL_ERR_DIMENSION (a 2D
 *          world) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_disc(demill_world *world, demill_id material,
                                              const double centre[3], const double normal[3],
                                              double outer_radius, double inner_radius,
                                              demill_id *out);

/** Adds a rectangle patch: the points centre + a u + b v of the plane
 *  through `centre` normal to `normal`, |a| <= half_width, |b| <=
 *  half_height, where u is the unit part of `direction` in the plane and v
 *  = n × u. A thin surface touched from both sides; its edges and corners
 *  push from their nearest point. Its point and centre of rotation are
 *  `centre`, its normal the unit normal. 3D worlds only.
 *  @param world       the world.
 *  @param material    the wall's material.
 *  @param centre      the centre, m.
 *  @param normal      the plane's normal (need not be of unit length).
 *  @param direction   the direction of the half-width in the plane (its
 *                     part along the normal is ignored).
 *  @param half_width  half the extent along u, m (> 0).
 *  @param half_height half the extent along v, m (> 0).
 *  @param[out] out    receives the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (zero normal or
 *          direction, a direction parallel to the normal, a half-width not
 *          positive), DEMILL_ERR_DIMENSION (a 2D world) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_add_rectangle(demill_world *world, demill_id material,
                                                   const double centre[3],
                                                   const double normal[3],
                                                   const double direction[3],
                                                   double half_width, double half_height,
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

/** Removes a wall. Its id becomes invalid; contacts with it end; a wall
 *  attached to a body leaves it.
 *  @param world the world.
 *  @param wall  the wall's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_wall_remove(demill_world *world, demill_id wall);

/** Sets the wall's rigid motion from now on (in place of a harmonic motion,
 *  demill_wall_set_harmonic()): its centre of rotation is
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
 *          it, or to a body, demill_body_attach_wall(), and moves with it). */
DEMILL_API demill_status demill_wall_set_motion(demill_world *world, demill_id wall,
                                                const double velocity[3],
                                                const double angular_velocity[3],
                                                const double centre[3]);

/** Sets a harmonic motion from now on, in place of any other motion: with
 *  s(t) = amplitude × sin(2π × frequency × t + phase), t the world's time
 *  since this call, the wall's centre moves by s along `axis`
 *  (DEMILL_HARMONIC_TRANSLATION, amplitude in m), or the wall turns by the
 *  angle s about `axis` through its centre (DEMILL_HARMONIC_ROTATION,
 *  amplitude in rad). The wall's pose at this call is the pose at s = 0
 *  (with a phase whose sine is not 0, the wall moves to s(0) at once).
 *  Positions are exact at every time (no drift), and the contacts see the
 *  exact velocity ds/dt. demill_wall_set_motion() ends it, the wall staying
 *  where it is. In 2D a translation's axis must have z = 0 and a rotation's
 *  be along z.
 *  @param world     the world.
 *  @param wall      the wall's id.
 *  @param mode      DEMILL_HARMONIC_TRANSLATION or DEMILL_HARMONIC_ROTATION.
 *  @param axis      the direction of the motion or of the rotation's axis
 *                   (need not be of unit length).
 *  @param amplitude the amplitude, m or rad.
 *  @param frequency the frequency, Hz (> 0).
 *  @param phase     the phase at this call, rad.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY (mode),
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (zero axis, frequency not positive;
 *          the wall is attached to the drum or to a body and moves with it)
 *          or DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_wall_set_harmonic(demill_world *world, demill_id wall,
                                                  int32_t mode, const double axis[3],
                                                  double amplitude, double frequency,
                                                  double phase);

/** Sets the velocity with which the wall's surface moves along itself (a
 *  conveyor belt), while its geometry stays put: at a contact, the part of
 *  `velocity` tangent to the surface there is added to the wall's velocity.
 *  The velocity is given in the wall's current orientation and turns with
 *  the wall afterwards. Any wall kind; the wall's work on the particles
 *  counts in the energy account.
 *  @param world    the world.
 *  @param wall     the wall's id.
 *  @param velocity the surface velocity, m/s, or NULL for 0 (in 2D z = 0).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_DIMENSION. */
DEMILL_API demill_status demill_wall_set_surface_velocity(demill_world *world, demill_id wall,
                                                          const double velocity[3]);

/** Reads a wall field.
 *  @param world    the world.
 *  @param wall     the wall's id.
 *  @param field    a DEMILL_WALL_* field.
 *  @param[out] out receives the field's 3 doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_wall_get(const demill_world *world, demill_id wall,
                                         int32_t field, double *out);

/** Starts recording the loads on a wall, for pressure and liner-wear maps
 *  (docs/geometry.md, Wall loads), from zero: per element, a mesh's
 *  triangle or a polyline's segment, or for any other wall the wall as one
 *  patch (a capped cylinder or cone with its caps), after every step: the
 *  normal force on the element at that step (the sum over its contacts of
 *  F·n, N), its time integral since the start (N s: the mean pressure over
 *  the interval is the integral over the element's area and the interval),
 *  and the shear work ∫ |F_t · v_slip| dt (J), the input of Archard-type
 *  wear models, with v_slip the velocity of the wall's surface relative to
 *  the particle's surface at the contact point (the wall's motion and
 *  surface velocity, the particle's velocity and spin). A contact at a
 *  mesh's edge or vertex counts for the one triangle that holds it. Off by
 *  default: a wall that does not record costs nothing. Called again, it
 *  starts again from zero. Snapshots and checkpoints carry the loads; they
 *  are the same bits for any thread count.
 *  @param world the world.
 *  @param wall  the wall's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_wall_loads_start(demill_world *world, demill_id wall);

/** Stops recording a wall's loads and forgets them (nothing happens if it
 *  records none).
 *  @param world the world.
 *  @param wall  the wall's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_wall_loads_stop(demill_world *world, demill_id wall);

/** Reads the loads a wall has recorded since demill_wall_loads_start(), per
 *  element: n is the number of its triangles or segments
 *  (demill_wall_mesh_info()), 1 for any other wall. Each array receives n
 *  values, element after element; any of them may be NULL.
 *  @param world           the world.
 *  @param wall            the wall's id.
 *  @param n               the number of elements.
 *  @param[out] normal     the normal force on each element at the last
 *                         step, N (0 before the first).
 *  @param[out] impulse    its integral over the time recorded, N s.
 *  @param[out] shear_work the shear work on it over that time, J.
 *  @param[out] area       its area, m² (a polyline's segment: its length,
 *                         m, so that the pressure is a load per length;
 *                         NaN for a plane, which has no bounded area).
 *  @param[out] interval   the time recorded, s (one value).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE or DEMILL_ERR_INVALID_VALUE
 *          (the wall records no loads, or n is not its number of
 *          elements). */
DEMILL_API demill_status demill_wall_loads(const demill_world *world, demill_id wall, size_t n,
                                           double *normal, double *impulse, double *shear_work,
                                           double *area, double *interval);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_WALL_H */
