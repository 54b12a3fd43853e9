/* meshes.h: closed triangle meshes the tests build (icospheres scaled per
 * axis, and any mesh put together vertex by vertex), and STL files of them
 * written to temporary files. */
#ifndef DEMILL_TEST_MESHES_H
#define DEMILL_TEST_MESHES_H

#include <stddef.h>
#include <stdint.h>

/* A triangle mesh: nv vertices v (3 doubles each), nt triangles t (3 vertex
 * indices each). */
typedef struct dm_test_mesh {
    double *v;
    uint32_t *t;
    size_t nv, nt;
} dm_test_mesh;

void dm_test_mesh_free(dm_test_mesh *m);

/* The index of vertex x, added if no vertex is bitwise equal to it. */
uint32_t dm_test_mesh_vertex(dm_test_mesh *m, const double x[3]);

/* Adds the triangle of vertices a, b, c. */
void dm_test_mesh_triangle(dm_test_mesh *m, uint32_t a, uint32_t b, uint32_t c);

/* An icosphere of the unit sphere (an icosahedron's faces split in four
 * `level` times, the new corners pushed out to the sphere: 20 4^level
 * triangles, wound counter-clockwise seen from outside), then scaled by s
 * (per axis) and moved to p. Its vertices are numbered in the order the
 * triangles first use them, corner by corner, as an STL reader welding
 * its corners numbers them. */
dm_test_mesh dm_test_icosphere(int level, const double s[3], const double p[3]);

/* |a - b| for points of 3 doubles. */
double dm_test_dist3(const double *a, const double *b);

/* Triangle t's unit outward normal n and plane offset (n . x = offset on
 * it), returned. */
double dm_test_mesh_plane(const dm_test_mesh *m, size_t t, double n[3]);

/* The planes of the faces of mesh m (normal and offset, 4 doubles each,
 * as dm_test_mesh_plane() gives them), in a new array (free it); exits if
 * out of memory. */
double *dm_test_mesh_planes(const dm_test_mesh *m);

/* The least distance from x to the planes (4 doubles each, as
 * dm_test_mesh_planes() gives them) of the nt faces of a convex mesh: from
 * inside, the distance to its surface (negative outside). */
double dm_test_convex_depth(const double *planes, size_t nt, const double x[3]);

/* The volume of the closed mesh m, as the sum of the tetrahedra from p to
 * its faces. */
double dm_test_mesh_volume(const dm_test_mesh *m, const double p[3]);

/* The mesh's triangles as corners, 9 doubles each (for stl_write.h), in a
 * new array (free it). */
double *dm_test_mesh_corners(const dm_test_mesh *m);

/* Writes size bytes to a new temporary file named after `name` and returns
 * its path (free it; remove the file); exits on failure. */
char *dm_test_temp_file(const char *name, const void *bytes, size_t size);

#endif
