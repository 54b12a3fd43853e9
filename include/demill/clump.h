/** @file demill/clump.h
 * @brief Clumps: rigid bodies made of overlapping spheres (discs in 2D).
 *
 * A clump template is a rigid shape of n spheres of one material; its mass,
 * centre of mass and inertia are those of the union of the spheres, each
 * point counted once however many spheres cover it. A clump is a body of
 * that shape placed in the world. Its spheres, its members, are particles
 * (ids of kind DEMILL_KIND_PARTICLE, read with the particle API): they
 * touch other particles and walls with the pair's contact model, the
 * contact's reduced mass m* being the clump's mass, and the forces and
 * torques on them move the clump, which carries them along. Members of one
 * clump never touch each other. A clump translates with the world's
 * integrator and turns by Euler's equations in its principal frame, with a
 * splitting that keeps the angular momentum of a free body (Dullweber,
 * Leimkuhler and McLachlan 1997); its energies join the kinetic and
 * potential terms of demill_world_energy(). docs/shapes.md, Clumps,
 * describes them.
 *
 * A template can also be made from a closed triangle mesh, or the STL file
 * of one, filled with spheres (demill_clump_template_from_mesh(),
 * demill_clump_template_from_stl()), the fit kept with it (docs/shapes.md,
 * Shapes from a mesh).
 *
 * Snapshots and checkpoints (demill/state.h) hold templates (with their
 * fit) and clumps bit for bit. What clumps do not do yet: the iterative
 * refinement refuses a world with clumps (DEMILL_ERR_INVALID_VALUE from
 * demill_world_step()), local damping leaves members alone, and outlets do
 * not remove members.
 */
#ifndef DEMILL_CLUMP_H
#define DEMILL_CLUMP_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Template fields, read with demill_clump_template_get(). */
enum {
    DEMILL_TEMPLATE_MASS = 1,              /**< 1 double, kg */
    DEMILL_TEMPLATE_VOLUME = 2,            /**< 1 double: the mass over the density, m³ (2D: the discs' area times the world's disc thickness, or the spheres' volume when it is 0) */
    DEMILL_TEMPLATE_CENTRE = 3,            /**< 3 doubles: the centre of mass in the frame of the centres given, m */
    /** 3 doubles, kg m²: the principal moments of inertia, increasing. 2D:
     *  0, 0 and the moment about z through the centre of mass (a 2D world
     *  turns only about z). */
    DEMILL_TEMPLATE_PRINCIPAL_MOMENTS = 4,
    /** 9 doubles: the three principal axes, unit vectors in the frame of the
     *  centres given, in the order of the moments, right-handed. They are
     *  the clump's body axes: a clump of orientation (1, 0, 0, 0) has them
     *  along x, y and z. 2D: x, y and z. */
    DEMILL_TEMPLATE_PRINCIPAL_AXES = 5,
    DEMILL_TEMPLATE_COUNT = 6,             /**< 1 double: the number of spheres */
    /* The fit of a template made from a mesh (demill_clump_template_from_mesh(),
     * demill_clump_template_from_stl()); reading one of a template made from
     * spheres is DEMILL_ERR_INVALID_VALUE. */
    DEMILL_TEMPLATE_MESH_VOLUME = 7,       /**< 1 double: the mesh's volume, m³ (mesh templates) */
    /** 1 double: (V_mesh - V_union) / V_mesh, the fraction of the mesh's
     *  volume the spheres leave out (their union lies inside the mesh, so
     *  this is their symmetric difference over V_mesh); V_union is the
     *  template's volume, DEMILL_TEMPLATE_VOLUME (mesh templates). */
    DEMILL_TEMPLATE_FIT_VOLUME_ERROR = 8,
    /** 1 double: the largest distance from a point of the mesh's surface to
     *  the union of the spheres, m, over a lattice on each triangle of
     *  spacing at most DEMILL_TEMPLATE_FIT_CELL / 4: the true largest
     *  distance exceeds it by at most that spacing (mesh templates). */
    DEMILL_TEMPLATE_FIT_DEVIATION_OUT = 9,
    /** 1 double: the largest distance from a point of the union's surface
     *  to the mesh's surface, m, over a sample of the spheres' surfaces of
     *  spacing about DEMILL_TEMPLATE_FIT_CELL / 2, which may miss about that
     *  much (an estimate, not a bound) (mesh templates). */
    DEMILL_TEMPLATE_FIT_DEVIATION_IN = 10,
    /** 1 double: the side of the fit's grid cubes, m: the longest side of the
     *  mesh's bounding box over `cells` (mesh templates). */
    DEMILL_TEMPLATE_FIT_CELL = 11
};

/** Clump fields, for demill_clump_get() and demill_clump_set(). */
enum {
    DEMILL_CLUMP_POSITION = 1,         /**< 3 doubles: the centre of mass, m; read/write */
    /** 4 doubles (w, x, y, z): the unit quaternion that turns the body axes
     *  (DEMILL_TEMPLATE_PRINCIPAL_AXES) onto the world's; read/write (a
     *  written one is normalised; 2D: a turn about z, x = y = 0). */
    DEMILL_CLUMP_ORIENTATION = 2,
    DEMILL_CLUMP_VELOCITY = 3,         /**< 3 doubles: of the centre of mass, m/s; read/write */
    DEMILL_CLUMP_ANGULAR_VELOCITY = 4, /**< 3 doubles, world frame, rad/s; read/write (2D: x = y = 0) */
    DEMILL_CLUMP_ANGULAR_MOMENTUM = 5, /**< 3 doubles: about the centre of mass, world frame, kg m²/s; read-only */
    DEMILL_CLUMP_FORCE = 6,            /**< 3 doubles: the total force (contacts and gravity) at the last force evaluation, N; read-only */
    DEMILL_CLUMP_TORQUE = 7,           /**< 3 doubles: the total torque about the centre of mass at the last force evaluation, N m; read-only */
    DEMILL_CLUMP_MASS = 8              /**< 1 double, kg; read-only */
};

/** The size of a template field.
 *  @param field a DEMILL_TEMPLATE_* field.
 *  @return the number of doubles of the field (1, 3 or 9), or 0 for an
 *          unknown field. */
DEMILL_API int32_t demill_clump_template_field_size(int32_t field);

/** The size of a clump field.
 *  @param field a DEMILL_CLUMP_* field.
 *  @return the number of doubles of the field (1, 3 or 4), or 0 for an
 *          unknown field. */
DEMILL_API int32_t demill_clump_field_size(int32_t field);

/** Adds a clump template: a rigid shape of n spheres (2D: discs, z = 0) of
 *  one material, whose mass properties are those of the union of the
 *  spheres (exact to round-off where no three spheres overlap pairwise,
 *  else to 1e-13 of the spheres' volume times the shape's size to the
 *  power of each moment). The material's density and, in 2D, the
 *  world's disc thickness are read now: neither can change afterwards
 *  (demill_material_set() and demill_world_set() refuse it). Templates are
 *  never removed.
 *  @param world    the world.
 *  @param material the spheres' material.
 *  @param n        the number of spheres, >= 1.
 *  @param centres  3 n doubles: the spheres' centres, m, in any frame.
 *  @param radii    n doubles: their radii, m, > 0.
 *  @param[out] out receives the template's id (of kind
 *                  DEMILL_KIND_TEMPLATE).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (material),
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE (a centre or a
 *          radius), DEMILL_ERR_INVALID_VALUE (n = 0, a radius <= 0, or a
 *          mass or principal moment that is not finite and positive, nor
 *          its inverse),
 *          DEMILL_ERR_DIMENSION (a centre with z != 0 in a 2D world) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_clump_template_add(demill_world *world, demill_id material,
                                                   size_t n, const double *centres,
                                                   const double *radii, demill_id *out);

/** Reads a template field.
 *  @param world    the world.
 *  @param tmpl     the template's id.
 *  @param field    a DEMILL_TEMPLATE_* field.
 *  @param[out] out receives the field's doubles
 *                  (demill_clump_template_field_size()).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NULL_POINTER or DEMILL_ERR_INVALID_VALUE (a field of
 *          the fit of a template not made from a mesh). */
DEMILL_API demill_status demill_clump_template_get(const demill_world *world, demill_id tmpl,
                                                   int32_t field, double *out);

/** Adds a clump template that fills a closed triangle mesh (3D worlds), such
 *  as a scanned rock's, with up to n overlapping spheres of one material,
 *  and keeps the fit (DEMILL_TEMPLATE_MESH_VOLUME, _FIT_VOLUME_ERROR,
 *  _FIT_DEVIATION_OUT, _FIT_DEVIATION_IN, _FIT_CELL). The mesh is laid on
 *  a grid of cubes, `cells` along the longest side of its bounding box;
 *  the spheres are inscribed balls about the cubes' centres near the
 *  mesh's medial axis, chosen one at a time for the volume each adds to
 *  their union, then each moved off the grid for more (docs/shapes.md,
 *  Shapes from a mesh, cites the method). Every sphere lies inside the
 *  mesh. The template is then the one demill_clump_template_add() makes
 *  of those spheres: its mass and inertia are the union's, what the
 *  contacts see, less than the mesh's by the volume error (for the mesh's
 *  mass, give the spheres a material whose density is the true one over 1
 *  minus the volume error). Its frame is the mesh's. The same mesh gives
 *  the same template, bitwise. The fit takes about 13 bytes a cube (3.4 MB
 *  at cells = 64 for a mesh as wide as long as high); a rock of 1280
 *  triangles took 0.16 to 0.51 s of CPU for 5 to 40 spheres at cells = 64,
 *  1.1 to 2.0 s at 128 (docs/shapes.md, Shapes from a mesh).
 *  @param world       the world (3D).
 *  @param material    the spheres' material.
 *  @param n_vertices  number of vertices.
 *  @param vertices    3 doubles (x, y, z) per vertex, m.
 *  @param n_triangles number of triangles, at least 4.
 *  @param triangles   3 vertex indices (from 0) per triangle, wound
 *                     counter-clockwise seen from outside (as in STL
 *                     files). The mesh must be closed (every edge shared
 *                     by exactly two triangles, which run it in opposite
 *                     ways) and without triangles of zero area.
 *  @param n           the number of spheres, >= 1; fewer are placed only
 *                     when no more would add volume (the grid's inside
 *                     centres are all covered): DEMILL_TEMPLATE_COUNT says
 *                     how many.
 *  @param cells       the grid's cubes along the longest side of the
 *                     mesh's bounding box, from 4 to 256: 64 is a good
 *                     default; more fit finer detail, at cells³ the memory
 *                     and time.
 *  @param[out] out    receives the template's id (of kind
 *                     DEMILL_KIND_TEMPLATE).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (material),
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_DIMENSION (a 2D world),
 *          DEMILL_ERR_NOT_FINITE (a vertex, named),
 *          DEMILL_ERR_INVALID_VALUE (n = 0 or too many spheres; cells out
 *          of range; fewer than 4 triangles; an index out of range or a
 *          triangle of zero area, named; a mesh that is not closed or not
 *          consistently wound, naming the edge, or inside out; no cube
 *          centre inside the mesh; a union whose mass or moments are not
 *          finite and positive) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_clump_template_from_mesh(demill_world *world, demill_id material,
                                                         size_t n_vertices, const double *vertices,
                                                         size_t n_triangles,
                                                         const uint32_t *triangles, size_t n,
                                                         int cells, demill_id *out);

/** Adds a clump template that fills the closed mesh of an STL file, ASCII
 *  or binary, with up to n spheres (demill_clump_template_from_mesh()).
 *  The file is read as demill_wall_load_stl() reads it: each point x of the
 *  file is at scale x (a file in millimetres takes scale 0.001), points
 *  exactly equal are one vertex, and the facets' normals are not used (the
 *  triangles' winding says which side is outside). Messages start with the
 *  path.
 *  @param world    the world (3D).
 *  @param material the spheres' material.
 *  @param path     the file.
 *  @param scale    the scale factor, finite and > 0.
 *  @param n        the number of spheres, >= 1.
 *  @param cells    the grid's cubes along the longest side, from 4 to 256
 *                  (64 is a good default).
 *  @param[out] out receives the template's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (material),
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_DIMENSION (a 2D world),
 *          DEMILL_ERR_IO (the file cannot be read), DEMILL_ERR_FORMAT (not
 *          a usable STL file: empty, foreign, truncated, malformed, a
 *          coordinate not finite, a triangle of zero area, no triangle;
 *          the message names the triangle and its line or byte),
 *          DEMILL_ERR_INVALID_VALUE (a scale that is not finite and
 *          positive, or any refusal of
 *          demill_clump_template_from_mesh(): n, cells, a mesh that is not
 *          closed, ...) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_clump_template_from_stl(demill_world *world, demill_id material,
                                                        const char *path, double scale, size_t n,
                                                        int cells, demill_id *out);

/** Lists a template's spheres in its body frame, the principal frame in
 *  which clumps carry them: sphere k of a clump of orientation q at X is
 *  at X + R(q) b_k. A point b of the body frame is at
 *  c + b_0 a_0 + b_1 a_1 + b_2 a_2 in the frame the template was made in
 *  (c = DEMILL_TEMPLATE_CENTRE, a_i the rows of
 *  DEMILL_TEMPLATE_PRINCIPAL_AXES). In the template's order: that of the
 *  centres given, or for a mesh template the order the fit chose them in.
 *  @param world    the world.
 *  @param tmpl     the template's id.
 *  @param centres  3 capacity doubles: the body-frame centres b_k, m (2D:
 *                  z = 0); NULL, with radii NULL, to ask the count.
 *  @param radii    capacity doubles: the radii, m.
 *  @param capacity spheres the buffers hold.
 *  @param count    receives the number of spheres (may be NULL if centres
 *                  and radii are not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER
 *          (one of centres and radii NULL, or both and count)
 *          or DEMILL_ERR_BUFFER_TOO_SMALL (nothing written, *count set). */
DEMILL_API demill_status demill_clump_template_spheres(const demill_world *world, demill_id tmpl,
                                                       double *centres, double *radii,
                                                       size_t capacity, size_t *count);

/** Adds a clump of a template at rest: its spheres become particles, at
 *  x_i = position + R(orientation) b_i, b_i the sphere's place in the
 *  principal frame. No overlap with what is already there is checked.
 *  @param world       the world.
 *  @param tmpl        the template's id.
 *  @param position    3 doubles: the centre of mass, m (2D: z = 0).
 *  @param orientation 4 doubles (w, x, y, z), normalised here; NULL: the
 *                     identity, the body axes along x, y and z (2D: a turn
 *                     about z, x = y = 0).
 *  @param[out] out    receives the clump's id (of kind DEMILL_KIND_CLUMP).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (tmpl),
 *          DEMILL_ERR_NULL_POINTER (position or out), DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (an orientation of norm 0, or too many
 *          particles), DEMILL_ERR_DIMENSION (2D: z != 0, or an orientation
 *          that is not a turn about z) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_clump_add(demill_world *world, demill_id tmpl,
                                          const double position[3], const double orientation[4],
                                          demill_id *out);

/** Removes a clump and its members; their ids become invalid.
 *  @param world the world.
 *  @param clump the clump's id.
 *  @return DEMILL_OK or DEMILL_ERR_INVALID_HANDLE. */
DEMILL_API demill_status demill_clump_remove(demill_world *world, demill_id clump);

/** Reads a clump field.
 *  @param world    the world.
 *  @param clump    the clump's id.
 *  @param field    a DEMILL_CLUMP_* field.
 *  @param[out] out receives the field's doubles (demill_clump_field_size()).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY or
 *          DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_clump_get(const demill_world *world, demill_id clump,
                                          int32_t field, double *out);

/** Writes a clump field, and moves its members with it: the position, the
 *  orientation (the angular velocity is kept; the angular momentum
 *  follows), the velocity or the angular velocity (the angular momentum
 *  follows).
 *  @param world the world.
 *  @param clump the clump's id.
 *  @param field DEMILL_CLUMP_POSITION, _ORIENTATION, _VELOCITY or
 *               _ANGULAR_VELOCITY.
 *  @param in    the field's doubles.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_READ_ONLY, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (an orientation
 *          of norm 0) or DEMILL_ERR_DIMENSION (2D: a position or velocity
 *          with z != 0, an angular velocity with x or y != 0, an
 *          orientation that is not a turn about z). */
DEMILL_API demill_status demill_clump_set(demill_world *world, demill_id clump, int32_t field,
                                          const double *in);

/** Lists a clump's members, the particles of its spheres, in the
 *  template's order.
 *  @param world    the world.
 *  @param clump    the clump's id.
 *  @param ids      capacity ids, or NULL to ask the count.
 *  @param capacity ids the buffer holds.
 *  @param count    receives the number of members (may be NULL if ids is
 *                  not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER
 *          (ids and count both NULL) or DEMILL_ERR_BUFFER_TOO_SMALL
 *          (nothing written, *count set). */
DEMILL_API demill_status demill_clump_members(const demill_world *world, demill_id clump,
                                              demill_id *ids, size_t capacity, size_t *count);

/** Fills a region with clumps of a template, as demill_fill_region()
 *  (demill/insert.h) fills one with spheres: as many as the target asks,
 *  each placed whole inside the region (its bounding sphere about the
 *  centre of mass inside), every member clear of the walls, of the
 *  particles already there (free spheres and other clumps' members) and of
 *  the new clumps' members. Clumps are placed one at a time, each at the
 *  lowest free place among 16 seeded random candidates, with further sets
 *  of 16 tried while none is free, up to 4096; each candidate has its own
 *  random orientation, uniform on the rotations (Shoemake 1992, "Uniform
 *  random rotations"; 2D: a turn about z by an angle uniform in [0, 2 pi)).
 *  The clumps are at rest. The same call on the same world gives the same
 *  clumps, bitwise. Then let them settle (demill_world_settle()).
 *
 *  The target (DEMILL_FILL_* of demill/drum.h): DEMILL_FILL_COUNT, the
 *  number of clumps; DEMILL_FILL_MASS, the mass, in whole clumps (the
 *  nearest number); DEMILL_FILL_FRACTION, in the drum its bulk filling J
 *  (as demill_drum_fill()), in a box or a cylinder the fraction of its
 *  volume (2D: area) that the clumps occupy (the union of their spheres).
 *  @param world         the world.
 *  @param region        the region, DEMILL_REGION_* of demill/insert.h (not a
 *                       half-space; DEMILL_REGION_DRUM: the drum's inside).
 *  @param region_params the region's parameters.
 *  @param nregion       the number of doubles in region_params.
 *  @param tmpl          the template's id.
 *  @param target        what `value` means, DEMILL_FILL_*.
 *  @param value         how many clumps: a count, a mass or a fraction.
 *  @param seed          seed of the random places and orientations.
 *  @param[out] ids      receives the ids of the new clumps (may be NULL).
 *  @param capacity      how many ids `ids` can hold.
 *  @param[out] added    receives the number of clumps added (0 on failure;
 *                       on DEMILL_ERR_BUFFER_TOO_SMALL the number ids must
 *                       hold); may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE (tmpl),
 *          DEMILL_ERR_NULL_POINTER (region_params), DEMILL_ERR_UNKNOWN_KEY
 *          (region or target), DEMILL_ERR_NOT_FINITE, DEMILL_ERR_DIMENSION
 *          (a region with z in a 2D world), DEMILL_ERR_INVALID_VALUE (an
 *          empty or unbounded region, the drum's region without a drum, a
 *          value <= 0 or a fraction > 1, a target of no clump or of more
 *          members than a world holds, about 1.07e9; the clumps do not fit:
 *          nothing is added), DEMILL_ERR_BUFFER_TOO_SMALL or
 *          DEMILL_ERR_OUT_OF_MEMORY. On failure nothing is added. */
DEMILL_API demill_status demill_clump_fill_region(demill_world *world, int32_t region,
                                                  const double *region_params, size_t nregion,
                                                  demill_id tmpl, int32_t target, double value,
                                                  uint64_t seed, demill_id *ids,
                                                  size_t capacity, size_t *added);

/** The clump a particle belongs to (also the field DEMILL_PARTICLE_CLUMP of
 *  demill_particles_read_ids()).
 *  @param world     the world.
 *  @param particle  a particle's id.
 *  @param[out] clump receives its clump's id, DEMILL_ID_NONE for a particle
 *                   of no clump.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE or DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_particle_clump(const demill_world *world, demill_id particle,
                                               demill_id *clump);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_CLUMP_H */
