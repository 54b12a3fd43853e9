/* vtk.c: VTK XML output for ParaView (include/demill/vtk.h): the particles
 * as an unstructured grid of vertices (.vtu), the walls and the drum as
 * polygonal data (.vtp), and time series of both (.pvd). Every file is
 * written by lib/physics/io (the format, and the walls' surfaces). Nothing
 * in the world changes: particles are read through the public read
 * functions (in id order), walls from their current geometry. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/io/io.h"
#include "world/world.h"

/* ---- particles ---------------------------------------------------------------- */

enum {
    P_ID, P_RADIUS, P_MASS, P_MATERIAL, P_CLUMP, P_VELOCITY, P_ANGULAR_VELOCITY, P_FORCE, P_TORQUE,
    P_ANGLE, P_ORIENTATION, P_POINTS, P_CONNECTIVITY, P_OFFSETS, P_TYPES, P_COLUMNS
};

/* The particle field behind each dm_column that is one, 0 for the others. */
static const int32_t particle_field[P_COLUMNS] = {
    [P_RADIUS] = DEMILL_PARTICLE_RADIUS,
    [P_MASS] = DEMILL_PARTICLE_MASS,
    [P_VELOCITY] = DEMILL_PARTICLE_VELOCITY,
    [P_ANGULAR_VELOCITY] = DEMILL_PARTICLE_ANGULAR_VELOCITY,
    [P_FORCE] = DEMILL_PARTICLE_FORCE,
    [P_TORQUE] = DEMILL_PARTICLE_TORQUE,
    [P_ANGLE] = DEMILL_PARTICLE_ANGLE,
    [P_ORIENTATION] = DEMILL_PARTICLE_ORIENTATION,
    [P_POINTS] = DEMILL_PARTICLE_POSITION};

/* ctx: the dm_column numbers (P_*) of the file's columns. */
static const void *particle_bytes(demill_world *w, void *ctx, int k, void *scratch)
{
    const int col = ((const int *)ctx)[k];
    const size_t n = w->p.n;
    size_t count;
    if (particle_field[col]) {
        /* cannot fail: a field of this world, and room for every particle */
        (void)demill_particles_read(w, particle_field[col], scratch, n, &count);
        return scratch;
    }
    if (col == P_ID) {
        (void)demill_particles_read_ids(w, DEMILL_PARTICLE_ID, scratch, n, &count);
        return scratch;
    }
    if (col == P_MATERIAL) { /* the material's slot is its index, in id order */
        int32_t *out = scratch;
        for (uint32_t h = 0; h < w->ph.n; h++)
            if (w->ph.slot[h] != DM_FREE)
                *out++ = w->p.mat[w->ph.slot[h]];
        return scratch;
    }
    if (col == P_CLUMP) { /* the index of the clump's id (its handle), -1: none */
        int64_t *out = scratch;
        for (uint32_t h = 0; h < w->ph.n; h++)
            if (w->ph.slot[h] != DM_FREE) {
                const uint32_t c = w->p.clump[w->ph.slot[h]];
                *out++ = c ? (int64_t)w->clumps[c - 1].handle : -1;
            }
        return scratch;
    }
    if (col == P_TYPES) {
        memset(scratch, 1, n); /* VTK_VERTEX */
        return scratch;
    }
    int64_t *out = scratch; /* connectivity k, end offsets k + 1 */
    for (size_t i = 0; i < n; i++)
        out[i] = (int64_t)i + (col == P_OFFSETS);
    return scratch;
}

DEMILL_API demill_status demill_vtk_write_particles(demill_world *w, const char *path)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!path)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "vtk_write_particles: path is NULL");
    const size_t n = w->p.n;
    static const dm_column all[P_COLUMNS] = {
        [P_ID] = {"PointData", "id", "UInt64", 1, 0},
        [P_RADIUS] = {"PointData", "radius", "Float64", 1, 0},
        [P_MASS] = {"PointData", "mass", "Float64", 1, 0},
        [P_MATERIAL] = {"PointData", "material", "Int32", 1, 0},
        [P_CLUMP] = {"PointData", "clump", "Int64", 1, 0},
        [P_VELOCITY] = {"PointData", "velocity", "Float64", 3, 0},
        [P_ANGULAR_VELOCITY] = {"PointData", "angular_velocity", "Float64", 3, 0},
        [P_FORCE] = {"PointData", "force", "Float64", 3, 0},
        [P_TORQUE] = {"PointData", "torque", "Float64", 3, 0},
        [P_ANGLE] = {"PointData", "angle", "Float64", 1, 0},
        [P_ORIENTATION] = {"PointData", "orientation", "Float64", 4, 0},
        [P_POINTS] = {"Points", "Points", "Float64", 3, 0},
        [P_CONNECTIVITY] = {"Cells", "connectivity", "Int64", 1, 0},
        [P_OFFSETS] = {"Cells", "offsets", "Int64", 1, 0},
        [P_TYPES] = {"Cells", "types", "UInt8", 1, 0}};
    dm_column cols[P_COLUMNS];
    int which[P_COLUMNS], ncols = 0;
    for (int k = 0; k < P_COLUMNS; k++)
        if ((k != P_ANGLE || w->dim == 2) && (k != P_ORIENTATION || w->dim == 3)) {
            which[ncols] = k;
            cols[ncols] = all[k];
            cols[ncols++].tuples = n;
        }
    char piece[96];
    snprintf(piece, sizeof piece, "NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\"", n, n);
    return dm_vtk_write_file(w, path, "UnstructuredGrid", piece, cols, ncols, particle_bytes, which);
}

/* ---- walls -------------------------------------------------------------------- */

enum {
    W_WALL, W_PART, W_LIFTER, W_NORMAL, W_PRESSURE, W_SHEAR, W_POINTS, W_LINE_CONN, W_LINE_OFF,
    W_POLY_CONN, W_POLY_OFF, W_COLUMNS
};

/* The surfaces, and the recorded loads of their cells (NULL when no wall
 * records any). */
typedef struct wall_file {
    dm_mesh m;
    double *loads; /* 3 per cell: normal force, mean pressure, shear work */
} wall_file;

/* ctx: the columns' W_* numbers, then the wall_file (see demill_vtk_write_walls). */
typedef struct wall_ctx {
    const int *which;
    const wall_file *f;
} wall_ctx;

static const void *wall_bytes(demill_world *w, void *ctx, int k, void *scratch)
{
    const wall_ctx *c = ctx;
    const dm_mesh *m = &c->f->m;
    const int col = c->which[k];
    (void)w;
    if (col >= W_NORMAL && col <= W_SHEAR) {
        const size_t ncells = m->line.n + m->poly.n;
        double *out = scratch;
        for (size_t q = 0; q < ncells; q++)
            out[q] = c->f->loads[3 * q + (size_t)(col - W_NORMAL)];
        return scratch;
    }
    const void *arrays[W_COLUMNS] = {
        [W_WALL] = m->wall,          [W_PART] = m->part,          [W_LIFTER] = m->lifter,
        [W_POINTS] = m->pt,          [W_LINE_CONN] = m->line.conn, [W_LINE_OFF] = m->line.off,
        [W_POLY_CONN] = m->poly.conn, [W_POLY_OFF] = m->poly.off};
    return arrays[col];
}

/* The loads of each cell of the walls' surfaces, from the wall that records
 * them (a cap's: the wall it closes) and the element the cell draws: the
 * normal force at the last step, the mean pressure over the time recorded
 * (the normal force's integral over the element's area and the time) and
 * the shear work; NaN for the cells of walls that record none. Leaves
 * f->loads NULL when no wall records any; -1 when out of memory. */
static int cell_loads(const demill_world *w, wall_file *f)
{
    const size_t ncells = f->m.line.n + f->m.poly.n;
    int any = 0;
    for (uint32_t k = 0; k < w->nwalls; k++)
        any |= w->walls[k].loads != NULL;
    if (!any)
        return 0;
    if (!(f->loads = malloc((3 * ncells + 1) * sizeof *f->loads)))
        return -1;
    for (size_t q = 0; q < ncells; q++) {
        const uint32_t slot = (uint32_t)f->m.wall[q], parent = w->walls[slot].parent;
        const uint32_t owner = parent ? parent - 1 : slot, e = f->m.element[q];
        const dm_loads *l = w->walls[owner].loads;
        double *out = f->loads + 3 * q;
        if (!l) {
            out[0] = out[1] = out[2] = NAN;
            continue;
        }
        out[0] = dm_loads_normal(l, e);
        out[1] = l->v[DM_LOADS * (size_t)e + 1] / (dm_loads_area(w, owner, e) * l->interval);
        out[2] = l->v[DM_LOADS * (size_t)e + 2];
    }
    return 0;
}

DEMILL_API demill_status demill_vtk_write_walls(demill_world *w, const char *path)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!path)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "vtk_write_walls: path is NULL");
    wall_file f = {.loads = NULL};
    if (dm_walls_mesh(w, &f.m))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk: out of memory writing %s", path);
    dm_mesh *m = &f.m;
    if (cell_loads(w, &f)) {
        dm_mesh_free(m);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk: out of memory writing %s", path);
    }
    const size_t ncells = m->line.n + m->poly.n;
    for (size_t c = 0; c < ncells; c++) /* the walls' ids, of their slots */
        m->wall[c] = dm_wall_id(w, (uint32_t)m->wall[c]);
    const dm_column all[W_COLUMNS] = {
        [W_WALL] = {"CellData", "wall", "UInt64", 1, ncells},
        [W_PART] = {"CellData", "part", "Int32", 1, ncells},
        [W_LIFTER] = {"CellData", "lifter", "Int32", 1, ncells},
        [W_NORMAL] = {"CellData", "normal_force", "Float64", 1, ncells},
        [W_PRESSURE] = {"CellData", "mean_pressure", "Float64", 1, ncells},
        [W_SHEAR] = {"CellData", "shear_work", "Float64", 1, ncells},
        [W_POINTS] = {"Points", "Points", "Float64", 3, m->npt},
        [W_LINE_CONN] = {"Lines", "connectivity", "Int64", 1, m->line.nconn},
        [W_LINE_OFF] = {"Lines", "offsets", "Int64", 1, m->line.n},
        [W_POLY_CONN] = {"Polys", "connectivity", "Int64", 1, m->poly.nconn},
        [W_POLY_OFF] = {"Polys", "offsets", "Int64", 1, m->poly.n}};
    dm_column cols[W_COLUMNS];
    int which[W_COLUMNS], ncols = 0;
    for (int k = 0; k < W_COLUMNS; k++)
        if (f.loads || k < W_NORMAL || k > W_SHEAR) {
            which[ncols] = k;
            cols[ncols++] = all[k];
        }
    char piece[160];
    snprintf(piece, sizeof piece,
             "NumberOfPoints=\"%zu\" NumberOfVerts=\"0\" NumberOfLines=\"%zu\" "
             "NumberOfStrips=\"0\" NumberOfPolys=\"%zu\"",
             m->npt, m->line.n, m->poly.n);
    const wall_ctx ctx = {which, &f};
    s = dm_vtk_write_file(w, path, "PolyData", piece, cols, ncols, wall_bytes, (void *)&ctx);
    free(f.loads);
    dm_mesh_free(m);
    return s;
}

/* ---- time series -------------------------------------------------------------- */

#define ENDING_ROOM 48 /* "_particles_", up to 20 digits, ".vtu" */

struct demill_vtk_series {
    char *pvd, *tmp;    /* prefix.pvd, and prefix.pvd.tmp that replaces it */
    char *frame;        /* the prefix, with room for a frame file's ending */
    size_t prefix_len;
    size_t base;        /* where the prefix's last part starts: names in the .pvd */
    double *time;       /* of each frame */
    uint64_t n, cap;
};

static const char *const frame_kind[2] = {"particles", "walls"};

/* The path of a frame's file: part 0 particles, 1 walls. */
static const char *frame_path(demill_vtk_series *sr, int part, uint64_t frame)
{
    snprintf(sr->frame + sr->prefix_len, ENDING_ROOM, "_%s_%06llu.%s", frame_kind[part],
             (unsigned long long)frame, part ? "vtp" : "vtu");
    return sr->frame;
}

/* Writes the .pvd listing the first n frames: to the temporary file, which
 * then replaces it. */
static demill_status series_pvd(demill_world *w, demill_vtk_series *sr, uint64_t n)
{
    dm_out_file o;
    demill_status s = dm_out_open(w, &o, sr->tmp);
    if (s)
        return s;
    dm_out_printf(&o, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
                   "byte_order=\"%s\">\n<Collection>\n",
               dm_vtk_byte_order());
    for (uint64_t f = 0; f < n; f++)
        for (int part = 0; part < 2; part++) {
            const char *name = frame_path(sr, part, f) + sr->base;
            dm_out_printf(&o, "<DataSet timestep=\"%.17g\" part=\"%d\" name=\"%s\" file=\"",
                       sr->time[f], part, frame_kind[part]);
            dm_out_attribute(&o, name, strlen(name));
            dm_out_printf(&o, "\"/>\n");
        }
    dm_out_printf(&o, "</Collection>\n</VTKFile>\n");
    if (!(s = dm_out_close(w, &o)) && rename(sr->tmp, sr->pvd))
        s = dm_fail(w, DEMILL_ERR_IO, "vtk: cannot replace %s with %s: %s", sr->pvd, sr->tmp,
                    strerror(errno));
    if (s)
        remove(sr->tmp);
    return s;
}

DEMILL_API void demill_vtk_series_close(demill_vtk_series *sr)
{
    if (!sr)
        return;
    free(sr->pvd);
    free(sr->tmp);
    free(sr->frame);
    free(sr->time);
    free(sr);
}

DEMILL_API demill_status demill_vtk_series_open(demill_world *w, const char *prefix,
                                                demill_vtk_series **out)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!prefix || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "vtk_series_open: %s is NULL",
                       prefix ? "out" : "prefix");
    *out = NULL;
    const size_t len = strlen(prefix);
    if (!len || prefix[len - 1] == '/')
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "vtk_series_open: prefix \"%s\" has no file name part after its "
                       "directory (e.g. \"out/mill\")",
                       prefix);
    demill_vtk_series *sr = calloc(1, sizeof *sr);
    if (sr) {
        sr->pvd = malloc(len + sizeof ".pvd");
        sr->tmp = malloc(len + sizeof ".pvd.tmp");
        sr->frame = malloc(len + ENDING_ROOM);
    }
    if (!sr || !sr->pvd || !sr->tmp || !sr->frame) {
        demill_vtk_series_close(sr);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk_series_open: out of memory");
    }
    memcpy(sr->frame, prefix, len + 1);
    snprintf(sr->pvd, len + sizeof ".pvd", "%s.pvd", prefix);
    snprintf(sr->tmp, len + sizeof ".pvd.tmp", "%s.pvd.tmp", prefix);
    sr->prefix_len = len;
    const char *slash = strrchr(prefix, '/');
    sr->base = slash ? (size_t)(slash - prefix) + 1 : 0;
    if ((s = series_pvd(w, sr, 0))) {
        demill_vtk_series_close(sr);
        return s;
    }
    *out = sr;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_vtk_series_write(demill_world *w, demill_vtk_series *sr)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!sr)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "vtk_series_write: series is NULL");
    if (sr->n == sr->cap) {
        const uint64_t cap = sr->cap ? 2 * sr->cap : 64;
        double *t = realloc(sr->time, cap * sizeof *t);
        if (!t)
            return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk_series_write: out of memory");
        sr->time = t;
        sr->cap = cap;
    }
    if ((s = demill_vtk_write_particles(w, frame_path(sr, 0, sr->n))) ||
        (s = demill_vtk_write_walls(w, frame_path(sr, 1, sr->n))))
        return s;
    sr->time[sr->n] = w->time;
    if ((s = series_pvd(w, sr, sr->n + 1)))
        return s;
    sr->n++;
    return DEMILL_OK;
}
