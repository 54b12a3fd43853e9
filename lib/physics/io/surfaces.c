/* surfaces.c: the walls' surfaces as points, lines (2D) and polygons (3D)
 * for drawing: a plane as a patch about the scene, a mesh's triangles and a
 * polyline's segments where the wall is now, the finite walls (cylinders,
 * cones, discs, caps: rings of quadrilaterals; rectangles) at their pose,
 * the drum's shell, caps and lifters (clipped to the shell) at the drum's
 * angle. Built twice by the
 * same code: first with no arrays, to count, then into arrays of those
 * sizes. */
#include <math.h>
#include <stdlib.h>

#include "physics/geometry/geometry.h"
#include "physics/io/io.h"

#define SHELL_SEGMENTS 120                          /* of the drum's circle */
#define CLIP_MAX (4 * DM_MAX_POLY + SHELL_SEGMENTS) /* vertices of a clipped lifter */

static size_t point(dm_mesh *m, double x, double y, double z)
{
    if (m->pt) {
        m->pt[3 * m->npt] = x;
        m->pt[3 * m->npt + 1] = y;
        m->pt[3 * m->npt + 2] = z;
    }
    return m->npt++;
}

/* A cell of nv vertices; polygon: a polygon, else a polyline. */
static void cell(dm_mesh *m, int polygon, const size_t *v, size_t nv)
{
    dm_cells *c = polygon ? &m->poly : &m->line;
    if (c->conn) {
        for (size_t k = 0; k < nv; k++)
            c->conn[c->nconn + k] = (int64_t)v[k];
        c->off[c->n] = (int64_t)(c->nconn + nv);
        const size_t at = polygon ? m->nlines + c->n : c->n;
        m->wall[at] = m->cur_wall;
        m->element[at] = m->cur_element;
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

/* Two unit vectors u, v with (u, v, n) right-handed, n a unit vector. */
static void frame_about(const double n[3], double u[3], double v[3])
{
    dm_perpendicular(n, u);
    v[0] = n[1] * u[2] - n[2] * u[1];
    v[1] = n[2] * u[0] - n[0] * u[2];
    v[2] = n[0] * u[1] - n[1] * u[0];
}

/* A plane wall: the square (2D: segment) of half width h centred at the
 * point of the plane nearest `centre`, counter-clockwise about the normal. */
static void plane_patch(dm_mesh *m, const dm_wall *wall, int dim, const double centre[3], double h)
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
    double u[3], t[3];
    frame_about(n, u, t);
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
static size_t ring(dm_mesh *m, const dm_drum *d, double R, double z)
{
    const size_t first = m->npt;
    for (int k = 0; k < SHELL_SEGMENTS; k++) {
        const double a = d->theta + 2.0 * DM_PI * k / SHELL_SEGMENTS;
        point(m, d->centre[0] + R * cos(a), d->centre[1] + R * sin(a), z);
    }
    return first;
}

/* The shell: 3D quadrilaterals facing the axis; 2D a closed line. */
static void shell(dm_mesh *m, const demill_world *w)
{
    const double R = 0.5 * w->drum.diameter;
    size_t v[SHELL_SEGMENTS + 1];
    if (w->dim == 2) {
        const size_t r0 = ring(m, &w->drum, R, 0.0);
        for (int k = 0; k <= SHELL_SEGMENTS; k++)
            v[k] = r0 + (size_t)(k % SHELL_SEGMENTS);
        cell(m, 0, v, SHELL_SEGMENTS + 1);
        return;
    }
    const double L = 0.5 * w->drum.length, zc = w->drum.centre[2];
    const size_t r0 = ring(m, &w->drum, R, zc - L), r1 = ring(m, &w->drum, R, zc + L);
    for (int k = 0; k < SHELL_SEGMENTS; k++) {
        const size_t k1 = (size_t)((k + 1) % SHELL_SEGMENTS);
        const size_t q[4] = {r0 + (size_t)k, r1 + (size_t)k, r1 + k1, r0 + k1};
        cell(m, 1, q, 4);
    }
}

/* An end cap: the disc of the shell, counter-clockwise about its normal. */
static void end_cap(dm_mesh *m, const demill_world *w, const dm_wall *cap)
{
    const size_t r0 = ring(m, &w->drum, 0.5 * w->drum.diameter, cap->p[2]);
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
static void lifter(dm_mesh *m, const demill_world *w, const dm_wall *wall)
{
    double sec[2 * CLIP_MAX];
    const int n = clip_to_shell(wall->cpoly, wall->npoly, 0.5 * w->drum.diameter, sec);
    size_t v[CLIP_MAX];
    if (!n)
        return;
    const double *c = wall->c; /* the section is about the drum's centre */
    if (w->dim == 2) {
        for (int k = 0; k < n; k++)
            v[k] = point(m, c[0] + sec[2 * k], c[1] + sec[2 * k + 1], 0.0);
        cell(m, 1, v, (size_t)n);
        return;
    }
    const double L = 0.5 * w->drum.length;
    const size_t b0 = m->npt;
    for (int k = 0; k < n; k++)
        point(m, c[0] + sec[2 * k], c[1] + sec[2 * k + 1], c[2] - L);
    for (int k = 0; k < n; k++)
        point(m, c[0] + sec[2 * k], c[1] + sec[2 * k + 1], c[2] + L);
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

/* A mesh wall: its triangles (3D) or segments (2D) where it is now. */
static void mesh_surface(dm_mesh *m, const dm_wall *wall)
{
    const dm_trimesh *t = wall->mesh;
    const size_t first = m->npt;
    for (uint32_t k = 0; k < t->nv; k++) {
        double x[3];
        dm_mesh_vertex_at(wall, k, x);
        point(m, x[0], x[1], x[2]);
    }
    for (uint32_t e = 0; e < t->nt; e++) {
        size_t v[3];
        m->cur_element = e;
        for (int k = 0; k < t->nel; k++)
            v[k] = first + t->el[(size_t)t->nel * e + k];
        cell(m, t->nel == 3, v, (size_t)t->nel);
    }
}


/* A surface of revolution at its pose: quadrilaterals between the circles
 * of its segment's two ends (triangles where one is a point). */
static void revolved(dm_mesh *m, const dm_wall *wall)
{
    double u[3], v[3];
    frame_about(wall->n, u, v);
    size_t first[2];
    for (int end = 0; end < 2; end++) {
        const double rho = wall->seg[2 * end], h = wall->seg[2 * end + 1];
        first[end] = m->npt;
        for (int k = 0; k < SHELL_SEGMENTS; k++) {
            const double a = 2.0 * DM_PI * k / SHELL_SEGMENTS, ca = rho * cos(a), sa = rho * sin(a);
            point(m, wall->p[0] + ca * u[0] + sa * v[0] + h * wall->n[0],
                  wall->p[1] + ca * u[1] + sa * v[1] + h * wall->n[1],
                  wall->p[2] + ca * u[2] + sa * v[2] + h * wall->n[2]);
        }
    }
    for (int k = 0; k < SHELL_SEGMENTS; k++) {
        const size_t k1 = (size_t)((k + 1) % SHELL_SEGMENTS);
        const size_t q[4] = {first[0] + (size_t)k, first[0] + k1, first[1] + k1,
                             first[1] + (size_t)k};
        if (wall->seg[0] == 0.0)
            cell(m, 1, q + 1, 3);
        else if (wall->seg[2] == 0.0)
            cell(m, 1, q, 3);
        else
            cell(m, 1, q, 4);
    }
}

/* A rectangle at its pose, counter-clockwise about its normal. */
static void rectangle(dm_mesh *m, const dm_wall *wall)
{
    double e[3], f[3];
    for (int r = 0; r < 3; r++)
        e[r] = wall->rot[3 * r] * wall->e0[0] + wall->rot[3 * r + 1] * wall->e0[1] +
               wall->rot[3 * r + 2] * wall->e0[2];
    const double *n = wall->n;
    f[0] = n[1] * e[2] - n[2] * e[1];
    f[1] = n[2] * e[0] - n[0] * e[2];
    f[2] = n[0] * e[1] - n[1] * e[0];
    static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    size_t q[4];
    for (int k = 0; k < 4; k++) {
        const double a = corner[k][0] * wall->seg[0], b = corner[k][1] * wall->seg[1];
        q[k] = point(m, wall->p[0] + a * e[0] + b * f[0], wall->p[1] + a * e[1] + b * f[1],
                     wall->p[2] + a * e[2] + b * f[2]);
    }
    cell(m, 1, q, 4);
}

static void walls_mesh(dm_mesh *m, const demill_world *w)
{
    double centre[3];
    const double h = scene_box(w, centre);
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind)
            continue;
        m->cur_wall = k;
        m->cur_element = 0;
        m->cur_part = wall->drum_part;
        m->cur_lifter = wall->drum_part == DM_PART_LIFTER ? wall->lifter : -1;
        switch (dm_wall_attached(wall) ? DM_PART_NONE : wall->drum_part) {
        case DM_PART_SHELL: shell(m, w); break;
        case DM_PART_CAP: end_cap(m, w, wall); break;
        case DM_PART_LIFTER: lifter(m, w, wall); break;
        default:
            if (wall->mesh)
                mesh_surface(m, wall);
            else if (wall->kind == DM_WALL_REVOLVED)
                revolved(m, wall);
            else if (wall->kind == DM_WALL_RECT)
                rectangle(m, wall);
            else
                plane_patch(m, wall, w->dim, centre, h);
        }
    }
}

int dm_walls_mesh(const demill_world *w, dm_mesh *out)
{
    dm_mesh count = {0};
    walls_mesh(&count, w);
    const size_t ncells = count.line.n + count.poly.n;
    dm_mesh m = {.nlines = count.line.n};
    m.pt = malloc((count.npt ? count.npt : 1) * 3 * sizeof *m.pt);
    m.line.conn = malloc((count.line.nconn + count.poly.nconn + 1) * sizeof *m.line.conn);
    m.line.off = malloc((ncells + 1) * sizeof *m.line.off);
    m.wall = malloc((ncells + 1) * sizeof *m.wall);
    m.element = malloc((ncells + 1) * sizeof *m.element);
    m.part = malloc((ncells + 1) * sizeof *m.part);
    m.lifter = malloc((ncells + 1) * sizeof *m.lifter);
    if (!(m.pt && m.line.conn && m.line.off && m.wall && m.element && m.part && m.lifter)) {
        dm_mesh_free(&m);
        return -1;
    }
    m.poly.conn = m.line.conn + count.line.nconn;
    m.poly.off = m.line.off + count.line.n;
    walls_mesh(&m, w);
    *out = m;
    return 0;
}

void dm_mesh_free(dm_mesh *m)
{
    free(m->pt);
    free(m->line.conn);
    free(m->line.off);
    free(m->wall);
    free(m->element);
    free(m->part);
    free(m->lifter);
}
