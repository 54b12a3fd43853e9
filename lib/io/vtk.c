/* vtk.c: VTK XML output for ParaView (include/demill/vtk.h): the particles
 * as an unstructured grid of vertices (.vtu), the walls and the drum as
 * polygonal data (.vtp), and time series of both (.pvd).
 *
 * Every file is written the same way (write_file): the XML header names each
 * data array with its offset into one block of raw appended data, which
 * follows as each array's byte count (UInt64) and bytes. The arrays are
 * described by a table of columns, and their bytes come from a function of
 * the file's kind. Nothing in the world changes: particles are read through
 * the public read functions (in id order), walls from their current
 * geometry. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/internal.h"

#define SHELL_SEGMENTS 120                          /* of the drum's circle */
#define CLIP_MAX (4 * DM_MAX_POLY + SHELL_SEGMENTS) /* vertices of a clipped lifter */

/* ---- files ------------------------------------------------------------------ */

/* A file being written; err keeps the errno of the first failure. */
typedef struct out_file {
    FILE *f;
    const char *path;
    int err;
} out_file;

static demill_status out_open(demill_world *w, out_file *o, const char *path)
{
    o->path = path;
    o->err = 0;
    o->f = fopen(path, "wb");
    if (!o->f)
        return dm_fail(w, DEMILL_ERR_IO, "vtk: cannot open %s for writing: %s", path,
                       strerror(errno));
    return DEMILL_OK;
}

static void out_bytes(out_file *o, const void *data, size_t bytes)
{
    if (bytes && fwrite(data, 1, bytes, o->f) != bytes && !o->err)
        o->err = errno ? errno : EIO;
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void out_printf(out_file *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (vfprintf(o->f, fmt, ap) < 0 && !o->err)
        o->err = errno ? errno : EIO;
    va_end(ap);
}

/* Text for an XML attribute value, escaped. */
static void out_attribute(out_file *o, const char *s, size_t len)
{
    for (size_t k = 0; k < len; k++)
        switch (s[k]) {
        case '&': out_printf(o, "&amp;"); break;
        case '<': out_printf(o, "&lt;"); break;
        case '>': out_printf(o, "&gt;"); break;
        case '"': out_printf(o, "&quot;"); break;
        default: out_bytes(o, s + k, 1);
        }
}

/* Closes the file; any failure since it was opened is reported with the
 * system's reason. */
static demill_status out_close(demill_world *w, out_file *o)
{
    if (fclose(o->f) && !o->err)
        o->err = errno ? errno : EIO;
    if (o->err)
        return dm_fail(w, DEMILL_ERR_IO, "vtk: cannot write %s: %s", o->path, strerror(o->err));
    return DEMILL_OK;
}

/* ---- VTK XML with raw appended data -------------------------------------------- */

/* One data array: the element it belongs to (a new one starts when it
 * differs from the previous column's), its name, VTK type, components and
 * tuples. */
typedef struct column {
    const char *section, *name, *type;
    int comps;
    size_t tuples;
} column;

/* The bytes of column k, in scratch (room for the largest column) or
 * wherever they are. */
typedef const void *(*column_fn)(demill_world *w, void *ctx, int k, void *scratch);

static size_t type_size(const char *type)
{
    return !strcmp(type, "Int32") ? 4 : !strcmp(type, "UInt8") ? 1 : 8;
}

static size_t column_bytes(const column *c)
{
    return c->tuples * (size_t)c->comps * type_size(c->type);
}

static const char *byte_order(void)
{
    const uint16_t one = 1;
    uint8_t first;
    memcpy(&first, &one, 1);
    return first ? "LittleEndian" : "BigEndian";
}

/* Writes a VTK XML file of the given type (UnstructuredGrid, PolyData) with
 * the world's time as field data and one piece with the given attributes
 * and columns (at least one). */
static demill_status write_file(demill_world *w, const char *path, const char *type,
                                const char *piece, const column *cols, int ncols,
                                column_fn bytes_of, void *ctx)
{
    size_t largest = 0;
    for (int k = 0; k < ncols; k++)
        largest = column_bytes(&cols[k]) > largest ? column_bytes(&cols[k]) : largest;
    void *scratch = malloc(largest ? largest : 1);
    if (!scratch)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk: out of memory writing %s", path);
    out_file o;
    demill_status s = out_open(w, &o, path);
    if (s) {
        free(scratch);
        return s;
    }
    const uint64_t time_bytes = sizeof w->time;
    out_printf(&o,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"%s\" version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
               "<%s>\n<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" "
               "NumberOfTuples=\"1\" format=\"appended\" offset=\"0\"/>\n</FieldData>\n"
               "<Piece %s>\n",
               type, byte_order(), type, piece);
    uint64_t offset = sizeof time_bytes + time_bytes;
    for (int k = 0; k < ncols; k++) {
        const column *c = &cols[k];
        if (!k || strcmp(c->section, cols[k - 1].section)) {
            if (k)
                out_printf(&o, "</%s>\n", cols[k - 1].section);
            out_printf(&o, "<%s>\n", c->section);
        }
        out_printf(&o,
                   "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
                   "format=\"appended\" offset=\"%llu\"/>\n",
                   c->type, c->name, c->comps, (unsigned long long)offset);
        offset += sizeof(uint64_t) + column_bytes(c);
    }
    out_printf(&o, "</%s>\n</Piece>\n</%s>\n<AppendedData encoding=\"raw\">\n_",
               cols[ncols - 1].section, type);
    out_bytes(&o, &time_bytes, sizeof time_bytes);
    out_bytes(&o, &w->time, sizeof w->time);
    for (int k = 0; k < ncols && !o.err; k++) {
        const uint64_t n = column_bytes(&cols[k]);
        out_bytes(&o, &n, sizeof n);
        out_bytes(&o, bytes_of(w, ctx, k, scratch), n);
    }
    out_printf(&o, "\n</AppendedData>\n</VTKFile>\n");
    free(scratch);
    return out_close(w, &o);
}

/* ---- particles ---------------------------------------------------------------- */

enum {
    P_ID, P_RADIUS, P_MASS, P_MATERIAL, P_VELOCITY, P_ANGULAR_VELOCITY, P_FORCE, P_TORQUE,
    P_ANGLE, P_POINTS, P_CONNECTIVITY, P_OFFSETS, P_TYPES, P_COLUMNS
};

/* The particle field behind each column that is one, 0 for the others. */
static const int32_t particle_field[P_COLUMNS] = {
    [P_RADIUS] = DEMILL_PARTICLE_RADIUS,
    [P_MASS] = DEMILL_PARTICLE_MASS,
    [P_VELOCITY] = DEMILL_PARTICLE_VELOCITY,
    [P_ANGULAR_VELOCITY] = DEMILL_PARTICLE_ANGULAR_VELOCITY,
    [P_FORCE] = DEMILL_PARTICLE_FORCE,
    [P_TORQUE] = DEMILL_PARTICLE_TORQUE,
    [P_ANGLE] = DEMILL_PARTICLE_ANGLE,
    [P_POINTS] = DEMILL_PARTICLE_POSITION};

/* ctx: the column numbers (P_*) of the file's columns. */
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
    static const column all[P_COLUMNS] = {
        [P_ID] = {"PointData", "id", "UInt64", 1, 0},
        [P_RADIUS] = {"PointData", "radius", "Float64", 1, 0},
        [P_MASS] = {"PointData", "mass", "Float64", 1, 0},
        [P_MATERIAL] = {"PointData", "material", "Int32", 1, 0},
        [P_VELOCITY] = {"PointData", "velocity", "Float64", 3, 0},
        [P_ANGULAR_VELOCITY] = {"PointData", "angular_velocity", "Float64", 3, 0},
        [P_FORCE] = {"PointData", "force", "Float64", 3, 0},
        [P_TORQUE] = {"PointData", "torque", "Float64", 3, 0},
        [P_ANGLE] = {"PointData", "angle", "Float64", 1, 0},
        [P_POINTS] = {"Points", "Points", "Float64", 3, 0},
        [P_CONNECTIVITY] = {"Cells", "connectivity", "Int64", 1, 0},
        [P_OFFSETS] = {"Cells", "offsets", "Int64", 1, 0},
        [P_TYPES] = {"Cells", "types", "UInt8", 1, 0}};
    column cols[P_COLUMNS];
    int which[P_COLUMNS], ncols = 0;
    for (int k = 0; k < P_COLUMNS; k++)
        if (k != P_ANGLE || w->dim == 2) {
            which[ncols] = k;
            cols[ncols] = all[k];
            cols[ncols++].tuples = n;
        }
    char piece[96];
    snprintf(piece, sizeof piece, "NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\"", n, n);
    return write_file(w, path, "UnstructuredGrid", piece, cols, ncols, particle_bytes, which);
}

/* ---- walls -------------------------------------------------------------------- */

/* Cells of one kind (lines or polygons): connectivity and end offsets. */
typedef struct cells {
    int64_t *conn, *off;
    size_t nconn, n;
} cells;

/* The walls' surfaces. Built twice by the same code: first with no arrays,
 * to count, then into arrays of those sizes. Cell data run over the lines,
 * then the polygons (VTK's order). */
typedef struct mesh {
    double *pt;            /* 3 per point */
    size_t npt;
    cells line, poly;
    size_t nlines;         /* lines in all (from the count): where polygons start */
    uint64_t *wall;        /* per cell */
    int32_t *part, *lifter;
    uint64_t cur_wall;     /* of the wall being drawn */
    int32_t cur_part, cur_lifter;
} mesh;

static size_t point(mesh *m, double x, double y, double z)
{
    if (m->pt) {
        m->pt[3 * m->npt] = x;
        m->pt[3 * m->npt + 1] = y;
        m->pt[3 * m->npt + 2] = z;
    }
    return m->npt++;
}

/* A cell of nv vertices; polygon: a polygon, else a polyline. */
static void cell(mesh *m, int polygon, const size_t *v, size_t nv)
{
    cells *c = polygon ? &m->poly : &m->line;
    if (c->conn) {
        for (size_t k = 0; k < nv; k++)
            c->conn[c->nconn + k] = (int64_t)v[k];
        c->off[c->n] = (int64_t)(c->nconn + nv);
        const size_t at = polygon ? m->nlines + c->n : c->n;
        m->wall[at] = m->cur_wall;
        m->part[at] = m->cur_part;
        m->lifter[at] = m->cur_lifter;
    }
    c->nconn += nv;
    c->n++;
}

/* The box around the scene: particles, the drum and the walls' points;
 * returns its centre and half diagonal (0.5 m if it has no extent). */
static double scene_box(const demill_world *w, double centre[3])
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    const int D = w->dim;
    for (uint32_t i = 0; i < w->p.n; i++)
        for (int c = 0; c < D; c++) {
            lo[c] = fmin(lo[c], w->p.x[D * i + c] - w->p.r[i]);
            hi[c] = fmax(hi[c], w->p.x[D * i + c] + w->p.r[i]);
        }
    if (w->drum.alive) {
        const double R = 0.5 * w->drum.diameter, L = D == 3 ? 0.5 * w->drum.length : 0.0;
        const double dlo[3] = {-R, -R, -L}, dhi[3] = {R, R, L};
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], dlo[c]);
            hi[c] = fmax(hi[c], dhi[c]);
        }
    }
    for (uint32_t k = 0; k < w->nwalls; k++)
        if (w->walls[k].kind == DM_WALL_PLANE && !w->walls[k].drum_part)
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], w->walls[k].p[c]);
                hi[c] = fmax(hi[c], w->walls[k].p[c]);
            }
    double d2 = 0.0;
    for (int c = 0; c < 3; c++) {
        if (D == 2 && c == 2)
            lo[c] = hi[c] = 0.0;
        centre[c] = 0.5 * (lo[c] + hi[c]);
        d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    }
    return d2 > 0.0 ? 0.5 * sqrt(d2) : 0.5;
}

/* A plane wall: the square (2D: segment) of half width h centred at the
 * point of the plane nearest `centre`, counter-clockwise about the normal. */
static void plane_patch(mesh *m, const dm_wall *wall, int dim, const double centre[3], double h)
{
    const double *n = wall->n, *p = wall->p;
    double q = 0.0, c[3];
    for (int k = 0; k < 3; k++)
        q += (centre[k] - p[k]) * n[k];
    for (int k = 0; k < 3; k++)
        c[k] = centre[k] - q * n[k];
    if (dim == 2) {
        const size_t v[2] = {point(m, c[0] + h * n[1], c[1] - h * n[0], 0.0),
                             point(m, c[0] - h * n[1], c[1] + h * n[0], 0.0)};
        cell(m, 0, v, 2);
        return;
    }
    /* u: across the axis along which n is smallest; v = n × u */
    int a = 0;
    for (int k = 1; k < 3; k++)
        a = fabs(n[k]) < fabs(n[a]) ? k : a;
    double u[3] = {0, 0, 0}, e[3] = {0, 0, 0}, t[3];
    e[a] = 1.0;
    u[0] = n[1] * e[2] - n[2] * e[1];
    u[1] = n[2] * e[0] - n[0] * e[2];
    u[2] = n[0] * e[1] - n[1] * e[0];
    const double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= len;
    t[0] = n[1] * u[2] - n[2] * u[1];
    t[1] = n[2] * u[0] - n[0] * u[2];
    t[2] = n[0] * u[1] - n[1] * u[0];
    static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    size_t v[4];
    for (int k = 0; k < 4; k++)
        v[k] = point(m, c[0] + h * (corner[k][0] * u[0] + corner[k][1] * t[0]),
                     c[1] + h * (corner[k][0] * u[1] + corner[k][1] * t[1]),
                     c[2] + h * (corner[k][0] * u[2] + corner[k][1] * t[2]));
    cell(m, 1, v, 4);
}

/* Points of the drum's circle of radius R at height z, turned with the drum;
 * returns the first. */
static size_t ring(mesh *m, double R, double theta, double z)
{
    const size_t first = m->npt;
    for (int k = 0; k < SHELL_SEGMENTS; k++) {
        const double a = theta + 2.0 * DM_PI * k / SHELL_SEGMENTS;
        point(m, R * cos(a), R * sin(a), z);
    }
    return first;
}

/* The shell: 3D quadrilaterals facing the axis; 2D a closed line. */
static void shell(mesh *m, const demill_world *w)
{
    const double R = 0.5 * w->drum.diameter, th = w->drum.theta;
    size_t v[SHELL_SEGMENTS + 1];
    if (w->dim == 2) {
        const size_t r0 = ring(m, R, th, 0.0);
        for (int k = 0; k <= SHELL_SEGMENTS; k++)
            v[k] = r0 + (size_t)(k % SHELL_SEGMENTS);
        cell(m, 0, v, SHELL_SEGMENTS + 1);
        return;
    }
    const double L = 0.5 * w->drum.length;
    const size_t r0 = ring(m, R, th, -L), r1 = ring(m, R, th, L);
    for (int k = 0; k < SHELL_SEGMENTS; k++) {
        const size_t k1 = (size_t)((k + 1) % SHELL_SEGMENTS);
        const size_t q[4] = {r0 + (size_t)k, r1 + (size_t)k, r1 + k1, r0 + k1};
        cell(m, 1, q, 4);
    }
}

/* An end cap: the disc of the shell, counter-clockwise about its normal. */
static void end_cap(mesh *m, const demill_world *w, const dm_wall *cap)
{
    const size_t r0 = ring(m, 0.5 * w->drum.diameter, w->drum.theta, cap->p[2]);
    size_t v[SHELL_SEGMENTS];
    for (int k = 0; k < SHELL_SEGMENTS; k++)
        v[k] = r0 + (size_t)(cap->n[2] > 0.0 ? k : SHELL_SEGMENTS - 1 - k);
    cell(m, 1, v, SHELL_SEGMENTS);
}

/* Points of the circle of radius R strictly between polar angles a0 and a1
 * (counter-clockwise), no further apart than a shell segment; into out
 * (2 per point), returns how many. */
static int arc(double R, double a0, double a1, double *out)
{
    double span = fmod(a1 - a0, 2.0 * DM_PI);
    span += span < 0.0 ? 2.0 * DM_PI : 0.0;
    const int n = (int)ceil(span / (2.0 * DM_PI / SHELL_SEGMENTS));
    for (int k = 1; k < n; k++) {
        out[2 * k - 2] = R * cos(a0 + span * k / n);
        out[2 * k - 1] = R * sin(a0 + span * k / n);
    }
    return n > 1 ? n - 1 : 0;
}

/* The part of a convex polygon (n vertices, counter-clockwise) inside the
 * circle of radius R about the axis, counter-clockwise, its stretches along
 * the circle following the shell's segments; into out (CLIP_MAX points),
 * returns the vertex count, 0 if no vertex is inside. */
static int clip_to_shell(const double *poly, int n, double R, double *out)
{
    int start = -1;
    for (int k = n - 1; k >= 0; k--)
        if (poly[2 * k] * poly[2 * k] + poly[2 * k + 1] * poly[2 * k + 1] < R * R)
            start = k;
    if (start < 0)
        return 0;
    int m = 0;
    double exit_angle = 0.0; /* where the boundary last left the circle */
    for (int j = 0; j < n; j++) {
        const double *a = poly + 2 * ((start + j) % n), *b = poly + 2 * ((start + j + 1) % n);
        const double d[2] = {b[0] - a[0], b[1] - a[1]};
        const double A = d[0] * d[0] + d[1] * d[1], B = a[0] * d[0] + a[1] * d[1];
        const double C = a[0] * a[0] + a[1] * a[1] - R * R;
        const double disc = B * B - A * C;
        const int in_a = C <= 0.0, in_b = b[0] * b[0] + b[1] * b[1] <= R * R;
        /* the crossings a + t d: entering at t1, leaving at t2 (within the
         * edge, also where round-off puts them a little beyond) */
        const double root = disc > 0.0 ? sqrt(disc) : 0.0;
        const double t1 = fmin(fmax((-B - root) / A, 0.0), 1.0);
        const double t2 = fmin(fmax((-B + root) / A, 0.0), 1.0);
        const int dips = !in_a && !in_b && disc > 0.0 && t1 > 0.0 && t2 < 1.0;
        const int enters = !in_a && (in_b || dips), leaves = !in_b && (in_a || dips);
        if (in_a) {
            out[2 * m] = a[0];
            out[2 * m + 1] = a[1];
            m++;
        }
        if (enters) {
            const double x = a[0] + t1 * d[0], y = a[1] + t1 * d[1];
            m += arc(R, exit_angle, atan2(y, x), out + 2 * m);
            out[2 * m] = x;
            out[2 * m + 1] = y;
            m++;
        }
        if (leaves) {
            const double x = a[0] + t2 * d[0], y = a[1] + t2 * d[1];
            out[2 * m] = x;
            out[2 * m + 1] = y;
            m++;
            exit_angle = atan2(y, x);
        }
    }
    return m;
}

/* A lifter: its section inside the shell, in 3D as a prism along the drum. */
static void lifter(mesh *m, const demill_world *w, const dm_wall *wall)
{
    double sec[2 * CLIP_MAX];
    const int n = clip_to_shell(wall->cpoly, wall->npoly, 0.5 * w->drum.diameter, sec);
    size_t v[CLIP_MAX];
    if (!n)
        return;
    if (w->dim == 2) {
        for (int k = 0; k < n; k++)
            v[k] = point(m, sec[2 * k], sec[2 * k + 1], 0.0);
        cell(m, 1, v, (size_t)n);
        return;
    }
    const double L = 0.5 * w->drum.length;
    const size_t b0 = m->npt;
    for (int k = 0; k < n; k++)
        point(m, sec[2 * k], sec[2 * k + 1], -L);
    for (int k = 0; k < n; k++)
        point(m, sec[2 * k], sec[2 * k + 1], L);
    for (int k = 0; k < n; k++) { /* sides, facing out of the lifter */
        const size_t k1 = (size_t)((k + 1) % n);
        const size_t q[4] = {b0 + (size_t)k, b0 + k1, b0 + (size_t)n + k1, b0 + (size_t)(n + k)};
        cell(m, 1, q, 4);
    }
    for (int k = 0; k < n; k++) /* the far end, then the near end reversed */
        v[k] = b0 + (size_t)(n + k);
    cell(m, 1, v, (size_t)n);
    for (int k = 0; k < n; k++)
        v[k] = b0 + (size_t)(n - 1 - k);
    cell(m, 1, v, (size_t)n);
}

static void walls_mesh(mesh *m, const demill_world *w)
{
    double centre[3];
    const double h = scene_box(w, centre);
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind)
            continue;
        m->cur_wall = dm_wall_id(w, k);
        m->cur_part = wall->drum_part;
        m->cur_lifter = wall->drum_part == DM_PART_LIFTER ? wall->lifter : -1;
        switch (wall->drum_part) {
        case DM_PART_SHELL: shell(m, w); break;
        case DM_PART_CAP: end_cap(m, w, wall); break;
        case DM_PART_LIFTER: lifter(m, w, wall); break;
        default: plane_patch(m, wall, w->dim, centre, h);
        }
    }
}

enum {
    W_WALL, W_PART, W_LIFTER, W_POINTS, W_LINE_CONN, W_LINE_OFF, W_POLY_CONN, W_POLY_OFF,
    W_COLUMNS
};

static const void *wall_bytes(demill_world *w, void *ctx, int k, void *scratch)
{
    const mesh *m = ctx;
    (void)w;
    (void)scratch;
    const void *arrays[W_COLUMNS] = {m->wall,      m->part,     m->lifter,    m->pt,
                                     m->line.conn, m->line.off, m->poly.conn, m->poly.off};
    return arrays[k];
}

DEMILL_API demill_status demill_vtk_write_walls(demill_world *w, const char *path)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!path)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "vtk_write_walls: path is NULL");
    mesh count = {0};
    walls_mesh(&count, w);
    const size_t ncells = count.line.n + count.poly.n;
    mesh m = {.nlines = count.line.n};
    m.pt = malloc((count.npt ? count.npt : 1) * 3 * sizeof *m.pt);
    m.line.conn = malloc((count.line.nconn + count.poly.nconn + 1) * sizeof *m.line.conn);
    m.line.off = malloc((ncells + 1) * sizeof *m.line.off);
    m.wall = malloc((ncells + 1) * sizeof *m.wall);
    m.part = malloc((ncells + 1) * sizeof *m.part);
    m.lifter = malloc((ncells + 1) * sizeof *m.lifter);
    if (m.pt && m.line.conn && m.line.off && m.wall && m.part && m.lifter) {
        m.poly.conn = m.line.conn + count.line.nconn;
        m.poly.off = m.line.off + count.line.n;
        walls_mesh(&m, w);
        const column cols[W_COLUMNS] = {{"CellData", "wall", "UInt64", 1, ncells},
                                        {"CellData", "part", "Int32", 1, ncells},
                                        {"CellData", "lifter", "Int32", 1, ncells},
                                        {"Points", "Points", "Float64", 3, m.npt},
                                        {"Lines", "connectivity", "Int64", 1, m.line.nconn},
                                        {"Lines", "offsets", "Int64", 1, m.line.n},
                                        {"Polys", "connectivity", "Int64", 1, m.poly.nconn},
                                        {"Polys", "offsets", "Int64", 1, m.poly.n}};
        char piece[160];
        snprintf(piece, sizeof piece,
                 "NumberOfPoints=\"%zu\" NumberOfVerts=\"0\" NumberOfLines=\"%zu\" "
                 "NumberOfStrips=\"0\" NumberOfPolys=\"%zu\"",
                 m.npt, m.line.n, m.poly.n);
        s = write_file(w, path, "PolyData", piece, cols, W_COLUMNS, wall_bytes, &m);
    } else {
        s = dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "vtk: out of memory writing %s", path);
    }
    free(m.pt);
    free(m.line.conn);
    free(m.line.off);
    free(m.wall);
    free(m.part);
    free(m.lifter);
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
    out_file o;
    demill_status s = out_open(w, &o, sr->tmp);
    if (s)
        return s;
    out_printf(&o, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
                   "byte_order=\"%s\">\n<Collection>\n",
               byte_order());
    for (uint64_t f = 0; f < n; f++)
        for (int part = 0; part < 2; part++) {
            const char *name = frame_path(sr, part, f) + sr->base;
            out_printf(&o, "<DataSet timestep=\"%.17g\" part=\"%d\" name=\"%s\" file=\"",
                       sr->time[f], part, frame_kind[part]);
            out_attribute(&o, name, strlen(name));
            out_printf(&o, "\"/>\n");
        }
    out_printf(&o, "</Collection>\n</VTKFile>\n");
    if (!(s = out_close(w, &o)) && rename(sr->tmp, sr->pvd))
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
