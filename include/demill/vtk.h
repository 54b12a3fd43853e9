/** @file demill/vtk.h
 * @brief Output for ParaView and other VTK tools: the particles and the walls
 * as VTK XML files, one at a time or as a time series.
 *
 * Files are VTK XML (version 1.0) with their arrays in one block of raw
 * binary appended data (UInt64 headers, the machine's byte order, which the
 * file declares): exact, compact (205 bytes per 3D particle), and as fast
 * to write as the disc allows. ParaView and VTK's readers read them
 * (vtkXMLUnstructuredGridReader, vtkXMLPolyDataReader). ASCII with the 17
 * digits that make it exact would be three times the size and far slower
 * to write and read (every number through printf and strtod), base64 a
 * third larger than raw.
 *
 * The particle file (.vtu, an unstructured grid) has one vertex cell per
 * particle, at its centre, in id order (demill_particles_read_ids()), and
 * these point arrays:
 *
 * | array            | type    | content                                       |
 * |------------------|---------|-----------------------------------------------|
 * | id               | UInt64  | the particle's id                             |
 * | radius           | Float64 | m                                             |
 * | mass             | Float64 | kg                                            |
 * | material         | Int32   | the material's index: 0 for the first material the world created, 1 for the second, ... |
 * | clump            | Int64   | for a clump's member (demill/clump.h), the index of its clump's id, its low 32 bits (which stay the clump's for its life and differ between live clumps); -1 for a particle of no clump |
 * | velocity         | Float64 | 3 components, m/s                             |
 * | angular_velocity | Float64 | 3 components, rad/s (2D: x = y = 0)           |
 * | force            | Float64 | 3 components, N, as DEMILL_PARTICLE_FORCE     |
 * | torque           | Float64 | 3 components, N m, as DEMILL_PARTICLE_TORQUE  |
 * | angle            | Float64 | rad, 2D worlds only (DEMILL_PARTICLE_ANGLE)   |
 * | orientation      | Float64 | 4 components w, x, y, z, 3D worlds only (DEMILL_PARTICLE_ORIENTATION) |
 *
 * Forces and torques are those of the last force evaluation (after a step,
 * or demill_world_step(world, 0)); before any they are 0. In a 2D world
 * every z is 0. In ParaView, show the particles with the Point Gaussian
 * representation scaled by radius ("Scale By Array", Gaussian Radius 1), or
 * with Glyph (Sphere, Scale Array radius, Scale Factor 2). To see 3D
 * particles turn, use the 3D Glyphs representation (VTK's
 * vtkGlyph3DMapper) with Orient on, Orientation Mode Quaternion and
 * Orientation Vectors orientation: it takes a 4-component array as the
 * quaternion w, x, y, z, which is this array's order. A clump's members
 * have its orientation. Colour by clump to tell the clumps apart (with a
 * Threshold of clump from 0 up: the clumps alone).
 *
 * The wall file (.vtp, polygonal data) has the surfaces of the walls and of
 * the drum as they stand at the world's time:
 *   - a plane wall: in 3D a square, in 2D a line segment, centred at the
 *     point of the plane nearest the centre of the scene (the box around the
 *     particles, the drum and the walls' points) and as wide as the box's
 *     diagonal, so that it spans the scene (1 m wide for a scene of no
 *     extent);
 *   - the drum's shell: in 3D a cylinder of 120 quadrilaterals, in 2D a
 *     closed line of 120 segments, its vertices turning with the drum;
 *   - the drum's end caps (3D): a 120-sided polygon each;
 *   - each lifter: the part of its cross-section inside the shell (the
 *     library's lifter polygons reach into the shell), at its current angle;
 *     in 3D a prism along the drum's length (a quadrilateral per side and the
 *     section at each end), in 2D the section as a polygon.
 *
 * Polygons face the particles: their vertices run counter-clockwise seen
 * from the side the particles are on (for lifters, from outside them).
 * Each cell (polygon or line) carries three arrays of cell data:
 *
 * | array  | type   | content                                               |
 * |--------|--------|-------------------------------------------------------|
 * | wall   | UInt64 | the id of the wall, or of the drum for its parts      |
 * | part   | Int32  | 0 plane wall, 1 drum shell, 2 drum end cap, 3 lifter  |
 * | lifter | Int32  | the lifter's index, -1 for other parts                |
 *
 * Both files carry the world's time as field data (TimeValue).
 *
 * Writing changes nothing in the world (not even its last-error message,
 * unless it fails), so a frame may be written at any time, also from a
 * progress callback (demill_world_set_progress()).
 */
#ifndef DEMILL_VTK_H
#define DEMILL_VTK_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A time series being written (demill_vtk_series_open()). */
typedef struct demill_vtk_series demill_vtk_series;

/** Writes every particle of the world to a VTK XML unstructured grid file
 *  (.vtu; see the top of this header for its arrays).
 *  @param world the world (not changed).
 *  @param path the file to write, replaced if it exists.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (path),
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_IO (the file cannot be
 *          opened or written in full; the message names the file and gives
 *          the system's reason; a partly written file may remain). */
DEMILL_API demill_status demill_vtk_write_particles(demill_world *world, const char *path);

/** Writes the walls and the drum (shell, end caps, lifters at their current
 *  angle) to a VTK XML polygonal data file (.vtp; see the top of this header
 *  for its cells and arrays). A world without walls gives a valid file with
 *  no cells.
 *  @param world the world (not changed).
 *  @param path  the file to write, replaced if it exists.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (path),
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_IO (as for
 *          demill_vtk_write_particles()). */
DEMILL_API demill_status demill_vtk_write_walls(demill_world *world, const char *path);

/** Starts a time series for ParaView. With prefix "out/mill" the series is
 *  the collection file out/mill.pvd and, for frame k = 0, 1, 2, ...,
 *  out/mill_particles_k.vtu and out/mill_walls_k.vtp with k written in six
 *  digits (000000, 000001, ...; more when needed). The .pvd lists each
 *  frame's two files as parts 0 ("particles") and 1 ("walls") at the frame's
 *  time, with file names relative to itself; open it in ParaView. It is
 *  written now, empty, and rewritten after every frame (to out/mill.pvd.tmp,
 *  which then replaces it), so that it lists every frame written in full
 *  even if the program stops at any moment. The directory must exist; existing
 *  files of the same names are replaced. The series holds only its names
 *  and the frames' times; it may be written from any world.
 *  @param world  the world (not changed); it only holds the last-error
 *                message.
 *  @param prefix the path of the files without their endings; its last
 *                part (after the last '/') must not be empty.
 *  @param out    receives the series (NULL on failure); free it with
 *                demill_vtk_series_close().
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (prefix or out),
 *          DEMILL_ERR_INVALID_VALUE (the prefix ends in '/' or is empty),
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_IO (the .pvd cannot be
 *          written). */
DEMILL_API demill_status demill_vtk_series_open(demill_world *world, const char *prefix,
                                                demill_vtk_series **out);

/** Writes one frame of the series at the world's current time: its particles
 *  (demill_vtk_write_particles()) and its walls (demill_vtk_write_walls()),
 *  then rewrites the .pvd with the frame added. Frames should come at
 *  increasing times, as ParaView orders them by time. If it fails, the
 *  frame is not added (the .pvd stays as it was) and the next frame reuses
 *  its number.
 *  @param world  the world (not changed).
 *  @param series the series.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (series),
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_IO. */
DEMILL_API demill_status demill_vtk_series_write(demill_world *world, demill_vtk_series *series);

/** Frees a series. Its files stay complete as they are (the .pvd is up to
 *  date after every frame, so there is nothing left to write). NULL is
 *  ignored.
 *  @param series the series, or NULL. */
DEMILL_API void demill_vtk_series_close(demill_vtk_series *series);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_VTK_H */
