/* vtkxml.c: writing VTK XML files with one block of raw appended data
 * (write_file): the XML header names each data array with its offset into
 * the block, which follows as each array's byte count (UInt64) and bytes. The
 * arrays are described by a table of columns, and their bytes come from a
 * function of the caller's. Errors name the file and the system's reason. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/status.h"
#include "physics/io/io.h"

demill_status dm_out_open(demill_world *w, dm_out_file *o, const char *path)
{
    o->path = path;
    o->err = 0;
    o->f = fopen(path, "wb");
    if (!o->f)
        return dm_fail(w, DEMILL_ERR_IO, "vtk: cannot open %s for writing: %s", path,
                       strerror(errno));
    return DEMILL_OK;
}

void dm_out_bytes(dm_out_file *o, const void *data, size_t bytes)
{
    if (bytes && fwrite(data, 1, bytes, o->f) != bytes && !o->err)
        o->err = errno ? errno : EIO;
}

void dm_out_printf(dm_out_file *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (vfprintf(o->f, fmt, ap) < 0 && !o->err)
        o->err = errno ? errno : EIO;
    va_end(ap);
}

/* Text for an XML attribute value, escaped. */
void dm_out_attribute(dm_out_file *o, const char *s, size_t len)
{
    for (size_t k = 0; k < len; k++)
        switch (s[k]) {
        case '&': dm_out_printf(o, "&amp;"); break;
        case '<': dm_out_printf(o, "&lt;"); break;
        case '>': dm_out_printf(o, "&gt;"); break;
        case '"': dm_out_printf(o, "&quot;"); break;
        default: dm_out_bytes(o, s + k, 1);
        }
}

/* Closes the file; any failure since it was opened is reported with the
 * system's reason. */
demill_status dm_out_close(demill_world *w, dm_out_file *o)
{
    if (fclose(o->f) && !o->err)
        o->err = errno ? errno : EIO;
    if (o->err)
        return dm_fail(w, DEMILL_ERR_IO, "vtk: cannot write %s: %s", o->path, strerror(o->err));
    return DEMILL_OK;
}

static size_t type_size(const char *type)
{
    return !strcmp(type, "Int32") ? 4 : !strcmp(type, "UInt8") ? 1 : 8;
}

static size_t column_bytes(const dm_column *c)
{
    return c->tuples * (size_t)c->comps * type_size(c->type);
}

const char *dm_vtk_byte_order(void)
{
    const uint16_t one = 1;
    uint8_t first;
    memcpy(&first, &one, 1);
    return first ? "LittleEndian" : "BigEndian";
}

/* Writes a VTK XML file of the given type (UnstructuredGrid, PolyData) with
 * the world's time as field data and one piece with the given attributes
 * and columns (at least one). */
demill_status dm_vtk_write_file(demill_world *w, const char *path, const char *type,
                                const char *piece, const dm_column *cols, int ncols,
                                dm_column_fn bytes_of, void *ctx)
{
    size_t largest = 0;
    for (int k = 0; k < ncols; k++)
        largest = column_bytes(&cols[k]) > largest ? column_bytes(&cols[k]) : largest;
    void *scratch = malloc(largest ? largest : 1);
    if (!scratch)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk: out of memory writing %s", path);
    dm_out_file o;
    demill_status s = dm_out_open(w, &o, path);
    if (s) {
        free(scratch);
        return s;
    }
    const uint64_t time_bytes = sizeof w->time;
    dm_out_printf(&o,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"%s\" version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
               "<%s>\n<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" "
               "NumberOfTuples=\"1\" format=\"appended\" offset=\"0\"/>\n</FieldData>\n"
               "<Piece %s>\n",
               type, dm_vtk_byte_order(), type, piece);
    uint64_t offset = sizeof time_bytes + time_bytes;
    for (int k = 0; k < ncols; k++) {
        const dm_column *c = &cols[k];
        if (!k || strcmp(c->section, cols[k - 1].section)) {
            if (k)
                dm_out_printf(&o, "</%s>\n", cols[k - 1].section);
            dm_out_printf(&o, "<%s>\n", c->section);
        }
        dm_out_printf(&o,
                   "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
                   "format=\"appended\" offset=\"%llu\"/>\n",
                   c->type, c->name, c->comps, (unsigned long long)offset);
        offset += sizeof(uint64_t) + column_bytes(c);
    }
    dm_out_printf(&o, "</%s>\n</Piece>\n</%s>\n<AppendedData encoding=\"raw\">\n_",
               cols[ncols - 1].section, type);
    dm_out_bytes(&o, &time_bytes, sizeof time_bytes);
    dm_out_bytes(&o, &w->time, sizeof w->time);
    for (int k = 0; k < ncols && !o.err; k++) {
        const uint64_t n = column_bytes(&cols[k]);
        dm_out_bytes(&o, &n, sizeof n);
        dm_out_bytes(&o, bytes_of(w, ctx, k, scratch), n);
    }
    dm_out_printf(&o, "\n</AppendedData>\n</VTKFile>\n");
    free(scratch);
    return dm_out_close(w, &o);
}
