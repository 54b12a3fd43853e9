/* io.h: output files: VTK XML with raw appended data (vtkxml.c) and the
 * walls' surfaces to draw in them (surfaces.c). Uses the base and the state. */
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
    int32_t *part, *lifter;
    uint64_t cur_wall;     /* of the wall being drawn */
    int32_t cur_part, cur_lifter;
} dm_mesh;

/* The walls' surfaces at the world's time (counted, then built into arrays
 * of those sizes); -1 when out of memory, with nothing to free. */
int dm_walls_mesh(const demill_world *w, dm_mesh *m);
void dm_mesh_free(dm_mesh *m);

#endif /* DM_IO_H */
