/* io.h: output files: VTK XML with raw appended data (vtkxml.c) and the
 * walls' surfaces to draw in them (surfaces.c); input files: STL meshes
 * (stl.c). Uses the base and the state. */
#ifndef DM_IO_H
#define DM_IO_H

#include <stdio.h>

#include "physics/state/state.h"

/* ---- files (vtkxml.c) -------------------------------------------------------------- */
/* A file being written; err keeps the errno of the first failure. */
typedef struct dm_out_file {
    FILE *f;
    const char *path;
    int err;
} dm_out_file;

demill_status dm_out_open(demill_world *w, dm_out_file *o, const char *path);
void dm_out_bytes(dm_out_file *o, const void *data, size_t bytes);
void dm_out_printf(dm_out_file *o, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Text for an XML attribute value, escaped. */
void dm_out_attribute(dm_out_file *o, const char *s, size_t len);
/* Closes the file; any failure since it was opened is reported with the
 * system's reason. */
demill_status dm_out_close(demill_world *w, dm_out_file *o);

/* ---- VTK XML with raw appended data (vtkxml.c) ---------------------------------------- */
/* One data array: the element it belongs to (a new one starts when it
 * differs from the previous column's), its name, VTK type, components and
 * tuples. */
typedef struct dm_column {
    const char *section, *name, *type;
    int comps;
    size_t tuples;
} dm_column;

/* The bytes of column k, in scratch (room for the largest column) or
 * wherever they are. */
typedef const void *(*dm_column_fn)(demill_world *w, void *ctx, int k, void *scratch);

/* "LittleEndian" or "BigEndian": this machine's. */
const char *dm_vtk_byte_order(void);
/* Writes a VTK XML file of the given type (UnstructuredGrid, PolyData) with
 * the world's time as field data and one piece with the given attributes
 * and columns (at least one). */
demill_status dm_vtk_write_file(demill_world *w, const char *path, const char *type,
                                const char *piece, const dm_column *cols, int ncols,
                                dm_column_fn bytes_of, void *ctx);

/* ---- the walls' surfaces (surfaces.c) -------------------------------------------------- */
/* Cells of one kind (lines or polygons): connectivity and end offsets. */
typedef struct dm_cells {
    int64_t *conn, *off;
    size_t nconn, n;
} dm_cells;

/* The walls' surfaces. Cell data run over the lines, then the polygons
 * (VTK's order); each cell names its wall by its slot. */
typedef struct dm_mesh {
    double *pt;            /* 3 per point */
    size_t npt;
    dm_cells line, poly;
    size_t nlines;         /* lines in all (from the count): where polygons start */
    uint64_t *wall;        /* per cell: the wall slot */
    uint32_t *element;     /* per cell: the mesh element it draws, 0 for other walls */
    int32_t *part, *lifter;
    uint64_t cur_wall;     /* of the wall being drawn */
    uint32_t cur_element;
    int32_t cur_part, cur_lifter;
} dm_mesh;

/* The walls' surfaces at the world's time (counted, then built into arrays
 * of those sizes); -1 when out of memory, with nothing to free. */
int dm_walls_mesh(const demill_world *w, dm_mesh *m);
void dm_mesh_free(dm_mesh *m);

/* ---- STL files (stl.c) ------------------------------------------------------------------ */
/* The most triangles a file may have. */
#define DM_STL_MAX_TRIANGLES (UINT32_C(1) << 28)
/* A triangle's height under this fraction of its longest edge: zero area. */
#define DM_STL_FLAT 1e-12

/* A welded triangle mesh read from an STL file. */
typedef struct dm_stl_mesh {
    double *v;        /* 3 per vertex: scaled and transformed, each point once */
    uint32_t *tri;    /* 3 per triangle: its corners' vertices in the file's winding
                       * (reversed by a mirroring transform, so it still says which
                       * side was outside) */
    uint32_t nv, nt;  /* vertices, triangles */
    uint32_t flipped; /* triangles whose normal in the file points against their winding */
} dm_stl_mesh;

/* Reads the size bytes of an ASCII or binary STL file into *out: each
 * point x of the file becomes A (scale x) + t, with xf = {A row by row, t}
 * (NULL: A = I, t = 0), and points exactly equal after that are one
 * vertex. Returns DEMILL_OK; DEMILL_ERR_FORMAT for input that is not a
 * usable STL file (empty, foreign, truncated, malformed, a coordinate not
 * finite, a zero-area triangle, no triangles or more than
 * DM_STL_MAX_TRIANGLES); DEMILL_ERR_INVALID_VALUE for a scale not finite
 * and positive or a transform not finite or singular;
 * DEMILL_ERR_OUT_OF_MEMORY. On an error err (errlen bytes, may be 0) says
 * what is wrong, naming the triangle (from 1) and its line or byte, and
 * *out is empty, with nothing to free. */
demill_status dm_stl_parse(const uint8_t *bytes, size_t size, double scale, const double xf[12],
                           dm_stl_mesh *out, char *err, size_t errlen);
/* Frees a mesh dm_stl_parse() made and empties it. */
void dm_stl_free(dm_stl_mesh *m);

#endif /* DM_IO_H */
