/* walls.c: walls with prescribed motion (docs/physics.md §7): their exact
 * kinematics and the contact geometry of each particle-wall candidate.
 * A wall attached to a body (bodies/bodies.c) takes its pose from the body.
 * Kinds: planes (free walls, and the drum's end caps), the inside of the
 * drum's cylindrical shell, prisms with a convex polygonal cross-section
 * (the lifters), triangle meshes and polylines (mesh.c), and the finite
 * walls: surfaces of revolution of a segment (finite cylinders, cones, discs
 * and annuli, the caps of cylinders) and rectangles. Each kind contributes
 * one closest-point function (dm_wall_closest). Free walls move by their
 * own rigid or harmonic motion, and their surfaces may move along themselves
 * (belts); the drum's walls turn with the drum. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "physics/geometry/geometry.h"

/* Rotation matrix for angle |om| t about om (Rodrigues). */
static void rotation(const double om[3], double t, double R[9])
{
    double a = sqrt(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]);
    double th = a * t;
    memset(R, 0, 9 * sizeof *R);
    R[0] = R[4] = R[8] = 1.0;
    if (a == 0.0 || th == 0.0)
        return;
    double k[3] = {om[0] / a, om[1] / a, om[2] / a}, s = sin(th), c = 1.0 - cos(th);
    R[0] = 1 - c * (k[1] * k[1] + k[2] * k[2]);
    R[4] = 1 - c * (k[0] * k[0] + k[2] * k[2]);
    R[8] = 1 - c * (k[0] * k[0] + k[1] * k[1]);
    R[1] = -s * k[2] + c * k[0] * k[1];
    R[3] = s * k[2] + c * k[0] * k[1];
    R[2] = s * k[1] + c * k[0] * k[2];
    R[6] = -s * k[1] + c * k[0] * k[2];
    R[5] = -s * k[0] + c * k[1] * k[2];
    R[7] = s * k[0] + c * k[1] * k[2];
}

static void mat_vec(const double R[9], const double v[3], double out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = R[3 * r] * v[0] + R[3 * r + 1] * v[1] + R[3 * r + 2] * v[2];
}

/* The pose of a wall in harmonic motion at `time`: displaced from its
 * reference by s = A sin(2πf(t - t_h) + φ) along the axis, or turned by the
 * angle s about it through c0; vel or omega is ds/dt along the axis. */
static void harmonic_pose(dm_wall *wall, double time)
{
    const double w = 2.0 * DM_PI * wall->h_freq, ph = w * (time - wall->h_t0) + wall->h_phase;
    const double s = wall->h_amp * sin(ph), ds = wall->h_amp * w * cos(ph);
    const int turn = wall->harmonic == DM_HARMONIC_ROTATE;
    const double angle[3] = {s * wall->h_axis[0], s * wall->h_axis[1], s * wall->h_axis[2]};
    rotation(angle, turn ? 1.0 : 0.0, wall->rot);
    for (int c = 0; c < 3; c++) {
        wall->c[c] = wall->c0[c] + (turn ? 0.0 : s * wall->h_axis[c]);
        wall->vel[c] = turn ? 0.0 : ds * wall->h_axis[c];
        wall->omega[c] = turn ? ds * wall->h_axis[c] : 0.0;
    }
}

void dm_wall_at(dm_wall *wall, double time)
{
    double tau = time - wall->t0, d[3], rd[3];
    if (wall->harmonic) {
        harmonic_pose(wall, time);
    } else {
        rotation(wall->omega, tau, wall->rot);
        for (int c = 0; c < 3; c++)
            wall->c[c] = wall->c0[c] + wall->vel[c] * tau;
    }
    for (int c = 0; c < 3; c++)
        d[c] = wall->p0[c] - wall->c0[c];
    mat_vec(wall->rot, d, rd);
    mat_vec(wall->rot, wall->n0, wall->n);
    for (int c = 0; c < 3; c++)
        wall->p[c] = wall->c[c] + rd[c];
}

/* Makes the wall's current geometry its reference at time t0 (a rigid
 * motion unchanged; a harmonic one ends, the wall at rest where it is),
 * keeping the skin bound relative to the last build. */
void dm_wall_rebase(dm_wall *wall, double now, double t0)
{
    dm_wall_at(wall, now);
    if (wall->mesh)
        dm_mesh_rebase(wall);
    if (wall->harmonic) {
        wall->harmonic = 0;
        memset(wall->vel, 0, sizeof wall->vel);
        memset(wall->omega, 0, sizeof wall->omega);
    }
    double rb[9], v[3];
    mat_vec(wall->rot, wall->e0, v);
    memcpy(wall->e0, v, sizeof v);
    mat_vec(wall->rot, wall->surf0, v);
    memcpy(wall->surf0, v, sizeof v);
    memcpy(rb, wall->rot_build, sizeof rb);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            /* rot_build := rot_build · rot^T, as rot restarts from identity */
            double sum = 0.0;
            for (int k = 0; k < 3; k++)
                sum += rb[3 * r + k] * wall->rot[3 * c + k];
            wall->rot_build[3 * r + c] = sum;
        }
    memcpy(wall->p0, wall->p, sizeof wall->p);
    memcpy(wall->n0, wall->n, sizeof wall->n);
    memcpy(wall->c0, wall->c, sizeof wall->c);
    wall->t0 = t0;
    dm_wall_at(wall, t0);
}

/* Moves the world's clock to `time` without moving the walls: a harmonic
 * motion keeps its phase (a body's walls do not follow the clock but their
 * body). */
void dm_walls_retime(demill_world *w, double time)
{
    for (uint32_t k = 0; k < w->nwalls; k++) {
        dm_wall *wall = &w->walls[k];
        if (!wall->kind || wall->drum_part || wall->body)
            continue;
        if (wall->harmonic)
            wall->h_t0 += time - w->time;
        else
            dm_wall_rebase(wall, w->time, time);
    }
}

/* A wall attached to a body: its reference shifted by the body's
 * displacement since it was attached, moving with the body's velocity
 * (bodies translate: rot stays the identity). */
void dm_wall_at_body(const demill_world *w, dm_wall *wall)
{
    const dm_body *b = &w->bodies[wall->body - 1];
    for (int c = 0; c < 3; c++) {
        const double d = b->x[c] - wall->body_ref[c];
        wall->c[c] = wall->c0[c] + d;
        wall->p[c] = wall->p0[c] + d;
        wall->n[c] = wall->n0[c];
        wall->vel[c] = b->vp[c];
        wall->omega[c] = 0.0;
    }
    memset(wall->rot, 0, sizeof wall->rot);
    wall->rot[0] = wall->rot[4] = wall->rot[8] = 1.0;
}

/* Attaches a wall at rest to body `slot`: its current pose becomes its
 * reference, which the body moves from now on. */
void dm_wall_attach_body(demill_world *w, dm_wall *wall, uint32_t slot)
{
    dm_wall_rebase(wall, w->time, w->time);
    wall->body = slot + 1;
    memcpy(wall->body_ref, w->bodies[slot].x, sizeof wall->body_ref);
    dm_wall_at_body(w, wall);
}

/* Detaches a wall from its body: it stays where the body left it, at rest. */
void dm_wall_detach_body(demill_world *w, dm_wall *wall)
{
    if (wall->mesh)
        dm_mesh_rebase(wall); /* its frame follows before c0 becomes c */
    memcpy(wall->p0, wall->p, sizeof wall->p);
    memcpy(wall->n0, wall->n, sizeof wall->n);
    memcpy(wall->c0, wall->c, sizeof wall->c);
    memset(wall->vel, 0, sizeof wall->vel);
    memset(wall->body_ref, 0, sizeof wall->body_ref);
    wall->body = 0;
    wall->t0 = w->time;
    dm_wall_at(wall, w->time);
}

/* A drum wall at drum angle theta, turning at omega about the drum's axis
 * (along z through its centre `centre`, which moves at `vel`). A prism's
 * section (cpoly, cedge, bc) is kept about the centre. */
static void wall_at_drum(dm_wall *wall, double theta, double omega, const double centre[3],
                         const double vel[3])
{
    const double c = cos(theta), s = sin(theta);
    const double R[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    memcpy(wall->rot, R, sizeof R);
    memcpy(wall->c, centre, sizeof wall->c);
    memcpy(wall->vel, vel, sizeof wall->vel);
    wall->omega[0] = wall->omega[1] = 0.0;
    wall->omega[2] = omega;
    mat_vec(R, wall->p0, wall->p);
    mat_vec(R, wall->n0, wall->n);
    for (int k = 0; k < 3; k++)
        wall->p[k] += centre[k];
    const int n = wall->npoly;
    for (int k = 0; k < n; k++) {
        const double x = wall->poly[2 * k], y = wall->poly[2 * k + 1];
        wall->cpoly[2 * k] = c * x - s * y;
        wall->cpoly[2 * k + 1] = s * x + c * y;
    }
    for (int k = 0; k < n; k++) {
        const double *a = wall->cpoly + 2 * k, *b = wall->cpoly + 2 * ((k + 1) % n);
        const double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
        const double len = sqrt(l2);
        double *e = wall->cedge + 4 * k;
        e[0] = ey / len;
        e[1] = -ex / len;
        e[2] = ex / l2;
        e[3] = ey / l2;
    }
    wall->bc[0] = c * wall->bc0[0] - s * wall->bc0[1];
    wall->bc[1] = s * wall->bc0[0] + c * wall->bc0[1];
}

void dm_wall_attach(dm_wall *wall, int part, double now, const dm_drum *drum)
{
    dm_wall_rebase(wall, now, now); /* the reference is the wall where it is now */
    const double *centre = drum->centre;
    if (wall->mesh) {
        dm_mesh_into_drum(wall, drum->theta, centre);
        wall->reach = dm_mesh_axis_distance(wall, 1);
    }
    const double c = cos(drum->theta), s = sin(drum->theta);
    const double Rt[9] = {c, s, 0, -s, c, 0, 0, 0, 1}; /* back by the drum's angle */
    for (int k = 0; k < 3; k++) /* the point about the drum's centre */
        wall->p0[k] -= centre[k];
    double *const world[4] = {wall->p0, wall->n0, wall->e0, wall->surf0};
    for (int q = 0; q < 4; q++) {
        double v[3];
        mat_vec(Rt, world[q], v);
        memcpy(world[q], v, sizeof v);
    }
    memset(wall->c0, 0, sizeof wall->c0);
    wall->drum_part = part;
    wall->lifter = -1;
    wall_at_drum(wall, drum->theta, drum->omega, centre, drum->vcentre);
    memcpy(wall->c_build, wall->c, sizeof wall->c);
    memcpy(wall->rot_build, wall->rot, sizeof wall->rot);
}

/* Moves every wall to `time`; the drum's walls to the drum's angle and speed,
 * which the drum has been moved to (dm_drum_advance), and the bodies' walls
 * to their bodies' positions. */
void dm_walls_advance(demill_world *w, double time)
{
    const dm_drum *d = &w->drum;
    for (uint32_t k = 0; k < w->nwalls; k++) {
        dm_wall *wall = &w->walls[k];
        if (!wall->kind)
            continue;
        if (wall->drum_part)
            wall_at_drum(wall, d->theta, d->omega, d->centre, d->vcentre);
        else if (wall->body)
            dm_wall_at_body(w, wall);
        else
            dm_wall_at(wall, time);
    }
}

/* x in a free wall's reference frame, relative to its point: rot^T (x - c)
 * - (p0 - c0). For a wall that has not turned, with its point as its
 * centre, x - p as a plane computes it, bit for bit. */
static void to_reference(const dm_wall *wall, const double *x, double d[3])
{
    double r[3];
    for (int c = 0; c < 3; c++)
        r[c] = x[c] - wall->c[c];
    for (int c = 0; c < 3; c++)
        d[c] = wall->rot[c] * r[0] + wall->rot[3 + c] * r[1] + wall->rot[6 + c] * r[2] -
               (wall->p0[c] - wall->c0[c]);
}

void dm_perpendicular(const double n[3], double q[3])
{
    int a = 0;
    for (int k = 1; k < 3; k++)
        a = fabs(n[k]) < fabs(n[a]) ? k : a;
    double e[3] = {0.0, 0.0, 0.0};
    e[a] = 1.0;
    q[0] = n[1] * e[2] - n[2] * e[1];
    q[1] = n[2] * e[0] - n[0] * e[2];
    q[2] = n[0] * e[1] - n[1] * e[0];
    const double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    for (int k = 0; k < 3; k++)
        q[k] /= len;
}

/* The closest point of a surface of revolution (DM_WALL_REVOLVED): the
 * segment seg in the meridian half-plane (rho, h) of d about the axis n0,
 * turned about it. The surface's closest point to d lies in d's own
 * meridian half-plane (a point at another azimuth is farther), so the 3D
 * problem is the segment's closest point in that plane. An end of the
 * segment (a rim) is this face's only where its own bit is set and d lies
 * beyond the face (a cap) that shares it; elsewhere the face reports
 * DM_FACE_ELSEWHERE. Returns the distance; nl: the unit normal from d to
 * the closest point, reference frame. Exact in the faces: a face along h
 * (a cylinder) or along rho (a disc) gives the distance without round-off
 * beyond that of rho or h. */
static double revolved_closest(const dm_wall *wall, const double d[3], double nl[3])
{
    const double *e = wall->n0, *sg = wall->seg;
    const double h = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    double q[3] = {d[0] - h * e[0], d[1] - h * e[1], d[2] - h * e[2]};
    const double rho = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    if (rho > 0.0)
        for (int c = 0; c < 3; c++)
            q[c] /= rho;
    else
        dm_perpendicular(e, q);
    const double sx = sg[2] - sg[0], sy = sg[3] - sg[1], len = sqrt(sx * sx + sy * sy);
    const double mx = -sy / len, my = sx / len; /* the segment's unit normal */
    const double t = ((rho - sg[0]) * sx + (h - sg[1]) * sy) / (len * len);
    double dx, dy;
    if (t < 0.0 || t > 1.0) {
        const int end = t > 1.0;
        const double ex = sg[2 * end], ey = sg[2 * end + 1];
        dx = ex - rho;
        dy = ey - h;
        if (!(wall->own >> end & 1) || dx * wall->nb[2 * end] + dy * wall->nb[2 * end + 1] < 0.0) {
            for (int c = 0; c < 3; c++)
                nl[c] = mx * q[c] + my * e[c];
            return DM_FACE_ELSEWHERE;
        }
    } else { /* the foot of the perpendicular */
        const double pd = (rho - sg[0]) * mx + (h - sg[1]) * my;
        dx = -pd * mx;
        dy = -pd * my;
    }
    const double dist = sqrt(dx * dx + dy * dy);
    const double a = dist > 0.0 ? dx / dist : -mx, b = dist > 0.0 ? dy / dist : -my;
    for (int c = 0; c < 3; c++)
        nl[c] = a * q[c] + b * e[c];
    return dist;
}

/* The closest point of a rectangle (DM_WALL_RECT) about p0 with normal n0,
 * half-widths seg[0] along e0 and seg[1] along n0 × e0: the point of the
 * plane clamped to the rectangle (its face, an edge or a corner). Returns
 * the distance; nl: the unit normal from d to it, reference frame; over the
 * face exactly -n0 or n0, as a plane's. */
static double rect_closest(const dm_wall *wall, const double d[3], double nl[3])
{
    const double *n = wall->n0, *e = wall->e0;
    const double f[3] = {n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2],
                         n[0] * e[1] - n[1] * e[0]};
    const double u = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    const double v = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    const double wn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    const double du = fmin(fmax(u, -wall->seg[0]), wall->seg[0]) - u;
    const double dv = fmin(fmax(v, -wall->seg[1]), wall->seg[1]) - v;
    const double dist = sqrt(du * du + dv * dv + wn * wn);
    const double a = dist > 0.0 ? du / dist : 0.0, b = dist > 0.0 ? dv / dist : 0.0;
    const double c = dist > 0.0 ? -wn / dist : -1.0;
    for (int k = 0; k < 3; k++)
        nl[k] = a * e[k] + b * f[k] + c * n[k];
    return dist;
}

/* A finite wall's closest point: x mapped into the reference frame, the
 * normal turned back with the wall. */
static double finite_closest(const dm_wall *wall, const double *x, double *normal)
{
    double d[3], nl[3];
    to_reference(wall, x, d);
    const double dist =
        wall->kind == DM_WALL_RECT ? rect_closest(wall, d, nl) : revolved_closest(wall, d, nl);
    mat_vec(wall->rot, nl, normal);
    return dist;
}

/* Signed distance of x from the wall's surface, positive on the particle
 * side (negative inside the solid), and the unit normal from x towards the
 * closest point of the surface (into the wall). For a prism and the shell
 * only x and y matter: they extend along z. A mesh and a finite wall are
 * thin surfaces that particles touch from either side: their distance is
 * never negative. */
double dm_wall_closest(const dm_wall *wall, const double *x, int dim, double *normal)
{
    normal[0] = normal[1] = normal[2] = 0.0;
    switch (wall->kind) {
    case DM_WALL_MESH: return dm_mesh_closest(wall, x, dim, normal);
    case DM_WALL_SHELL: { /* about the drum's axis, through its centre c */
        const double rx = x[0] - wall->c[0], ry = x[1] - wall->c[1], r = sqrt(rx * rx + ry * ry);
        if (r > 0.0) {
            normal[0] = rx / r;
            normal[1] = ry / r;
        } else {
            normal[0] = 1.0;
        }
        return wall->radius - r;
    }
    case DM_WALL_PRISM: {
        /* convex polygon, counter-clockwise, about the drum's centre c:
         * outside if beyond some edge */
        const int n = wall->npoly;
        const double *v = wall->cpoly, xc[2] = {x[0] - wall->c[0], x[1] - wall->c[1]};
        x = xc;
        double best_sep = -HUGE_VAL, best_n[2] = {0.0, 0.0}, best_d2 = HUGE_VAL;
        double best_c[2] = {0.0, 0.0};
        for (int k = 0; k < n; k++) {
            const double *e = wall->cedge + 4 * k;
            const double ax = v[2 * k], ay = v[2 * k + 1];
            const double bx = v[2 * ((k + 1) % n)], by = v[2 * ((k + 1) % n) + 1];
            const double rx = x[0] - ax, ry = x[1] - ay;
            const double sep = rx * e[0] + ry * e[1];
            if (sep > best_sep) {
                best_sep = sep;
                best_n[0] = e[0];
                best_n[1] = e[1];
            }
            /* closest point of the edge segment */
            double t = rx * e[2] + ry * e[3];
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            const double cx = ax + t * (bx - ax), cy = ay + t * (by - ay);
            const double d2 = (x[0] - cx) * (x[0] - cx) + (x[1] - cy) * (x[1] - cy);
            if (d2 < best_d2) {
                best_d2 = d2;
                best_c[0] = cx;
                best_c[1] = cy;
            }
        }
        if (best_sep <= 0.0) { /* inside: out through the nearest face */
            normal[0] = -best_n[0];
            normal[1] = -best_n[1];
            return best_sep;
        }
        const double d = sqrt(best_d2);
        normal[0] = (best_c[0] - x[0]) / d;
        normal[1] = (best_c[1] - x[1]) / d;
        return d;
    }
    case DM_WALL_REVOLVED:
    case DM_WALL_RECT: return finite_closest(wall, x, normal);
    default: {
        double d = 0.0;
        for (int c = 0; c < dim; c++) {
            d += (x[c] - wall->p[c]) * wall->n[c];
            normal[c] = -wall->n[c];
        }
        return d;
    }
    }
}

/* Signed distance only (see dm_wall_closest). */
double dm_wall_distance(const dm_wall *wall, const double *x, int dim)
{
    double n[3];
    return dm_wall_closest(wall, x, dim, n);
}

/* The centre of a finite wall's bounding sphere, at the wall's pose. */
static void bound_centre(const dm_wall *wall, double b[3])
{
    for (int c = 0; c < 3; c++)
        b[c] = wall->p[c] + wall->bh * wall->n[c];
}

/* A lower bound of the signed distance of x from the wall's surface (see
 * dm_wall_closest), cheaper than the distance for a prism and a finite
 * wall: the distance from the circle or the sphere about it. */
double dm_wall_distance_bound(const dm_wall *wall, const double *x, int dim)
{
    if (wall->kind == DM_WALL_REVOLVED || wall->kind == DM_WALL_RECT) {
        double b[3], d2 = 0.0;
        bound_centre(wall, b);
        for (int c = 0; c < 3; c++)
            d2 += (x[c] - b[c]) * (x[c] - b[c]);
        return sqrt(d2) - wall->brad;
    }
    if (wall->kind != DM_WALL_PRISM)
        return dm_wall_distance(wall, x, dim);
    const double dx = x[0] - wall->c[0] - wall->bc[0], dy = x[1] - wall->c[1] - wall->bc[1];
    return sqrt(dx * dx + dy * dy) - wall->brad;
}

/* The smallest |d| over the interval a..b of d. */
static double least_abs(double a, double b)
{
    return a > 0.0 ? a : b < 0.0 ? -b : 0.0;
}

/* A lower bound of dm_wall_distance_bound() at every point of the box lo..hi
 * (finite). It runs the same operations in the same order on the box's
 * nearest corner (or on 0 where the box spans the centre): each is monotone
 * in its operands in floating point (a difference, a product by a constant
 * or by itself, a sum, a square root), so the rounded bound at any point of
 * the box is at least the rounded bound here. */
double dm_wall_box_bound(const dm_wall *wall, const double *lo, const double *hi, int dim)
{
    switch (wall->kind) {
    case DM_WALL_PLANE: {
        double d = 0.0;
        for (int c = 0; c < dim; c++) {
            const double a = (lo[c] - wall->p[c]) * wall->n[c],
                         b = (hi[c] - wall->p[c]) * wall->n[c];
            d += a < b ? a : b;
        }
        return d;
    }
    case DM_WALL_SHELL: {
        const double rx = fmax(fabs(lo[0] - wall->c[0]), fabs(hi[0] - wall->c[0]));
        const double ry = fmax(fabs(lo[1] - wall->c[1]), fabs(hi[1] - wall->c[1]));
        return wall->radius - sqrt(rx * rx + ry * ry);
    }
    case DM_WALL_PRISM: {
        const double dx = least_abs(lo[0] - wall->c[0] - wall->bc[0],
                                    hi[0] - wall->c[0] - wall->bc[0]);
        const double dy = least_abs(lo[1] - wall->c[1] - wall->bc[1],
                                    hi[1] - wall->c[1] - wall->bc[1]);
        return sqrt(dx * dx + dy * dy) - wall->brad;
    }
    case DM_WALL_REVOLVED:
    case DM_WALL_RECT: {
        if (dim != 3)
            break;
        double b[3], d2 = 0.0;
        bound_centre(wall, b);
        for (int c = 0; c < 3; c++) {
            const double d = least_abs(lo[c] - b[c], hi[c] - b[c]);
            d2 += d * d;
        }
        return sqrt(d2) - wall->brad;
    }
    }
    return -HUGE_VAL;
}

/* A finite wall's bounding sphere (bh, brad) from its shape: about the
 * middle of the segment's heights, or the rectangle's centre. */
void dm_wall_finite_bound(dm_wall *wall)
{
    const double *s = wall->seg;
    if (wall->kind == DM_WALL_RECT) {
        wall->bh = 0.0;
        wall->brad = sqrt(s[0] * s[0] + s[1] * s[1]);
        return;
    }
    const double half = 0.5 * fabs(s[3] - s[1]), rho = fmax(s[0], s[2]);
    wall->bh = 0.5 * (s[1] + s[3]);
    wall->brad = sqrt(rho * rho + half * half);
}

void dm_walls_mark_built(demill_world *w)
{
    for (uint32_t k = 0; k < w->nwalls; k++) {
        memcpy(w->walls[k].c_build, w->walls[k].c, sizeof w->walls[k].c);
        memcpy(w->walls[k].rot_build, w->walls[k].rot, sizeof w->walls[k].rot);
    }
}

/* The most any wall's surface can have moved, near the particles, since the
 * last neighbour build: |Δc| + θ × reach, the reach of a free plane being the
 * distance from its centre to the far corner of the particles' box (widened
 * by the skin), of a lifter its outermost vertex, of a mesh a sphere about
 * it (turning with the drum: its farthest vertex from the axis), of a finite
 * wall the far side of its bounding sphere, and zero for the shell and end
 * caps, which the drum's rotation does not move. A harmonic motion moves the
 * pose (c and rot) as a rigid one does, so the same bound sees it. */
double dm_walls_max_shift(const demill_world *w)
{
    double worst = 0.0;
    const dm_grid *g = &w->grid;
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind)
            continue;
        double dc2 = 0.0, reach = wall->reach;
        for (int c = 0; c < 3; c++) {
            double d = wall->c[c] - wall->c_build[c];
            dc2 += d * d;
        }
        if (wall->kind == DM_WALL_PLANE && (!wall->drum_part || dm_wall_attached(wall))) {
            double reach2 = 0.0;
            for (int c = 0; c < 3; c++) {
                double far =
                    fmax(fabs(g->lo[c] - wall->c[c]), fabs(g->hi[c] - wall->c[c])) + w->skin;
                reach2 += far * far;
            }
            reach = sqrt(reach2);
        } else if (wall->kind == DM_WALL_REVOLVED || wall->kind == DM_WALL_RECT) {
            double b[3], reach2 = 0.0;
            bound_centre(wall, b);
            for (int c = 0; c < 3; c++)
                reach2 += (b[c] - wall->c[c]) * (b[c] - wall->c[c]);
            reach = sqrt(reach2) + wall->brad;
        }
        if (wall->mesh && !wall->drum_part) /* (turning with the drum: its axial reach) */
            reach = dm_mesh_reach(wall);
        /* angle of rot · rot_build^T from its trace */
        double tr = 0.0;
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                tr += wall->rot[3 * r + c] * wall->rot_build[3 * r + c];
        double cosang = fmin(1.0, fmax(-1.0, 0.5 * (tr - 1.0)));
        double shift = sqrt(dc2) + (reach > 0.0 ? acos(cosang) * reach : 0.0);
        if (shift > worst)
            worst = shift;
    }
    return worst;
}

/* Makes room for the geometry of every particle-wall candidate. */
int dm_wgeom_reserve(demill_world *w)
{
    dm_wgeom *g = &w->wg;
    uint32_t total = 0;
    for (int k = 0; k < w->nkern; k++)
        total += w->pw.b[k].n;
    if (total <= g->cap)
        return 0;
    size_t cap = dm_grown_capacity(g->cap, total);
    void **const arrays[] = {(void **)&g->nrm, (void **)&g->vw, (void **)&g->cp,
                             (void **)&g->delta, (void **)&g->lost};
    const size_t sizes[] = {3 * sizeof(double), 3 * sizeof(double), 3 * sizeof(double),
                            sizeof(double), sizeof(double)};
    if (dm_grow_arrays(arrays, sizes, 5, cap))
        return -1;
    g->cap = (uint32_t)cap;
    return 0;
}

void dm_wall_surface_velocity(const dm_wall *wall, double u[3])
{
    mat_vec(wall->rot, wall->surf0, u);
}

/* Adds to the wall velocity vw at a contact of normal n the part of the
 * wall's surface velocity (turned with the wall) tangent to the surface. */
static inline void add_surface_velocity(const dm_wall *wall, int D, const double *n, double *vw)
{
    double u[3], un = 0.0;
    dm_wall_surface_velocity(wall, u);
    for (int c = 0; c < D; c++)
        un += u[c] * n[c];
    for (int c = 0; c < D; c++)
        vw[c] += u[c] - un * n[c];
}

/* Stores the geometry of wall candidate q of a particle at x of radius r:
 * overlap delta, unit normal n from the particle into the wall, and from
 * them the contact point and the wall's velocity there, with the surface's
 * own velocity along itself (static, so that dm_wgeom_range() inlines it: a
 * library's exported function is not). */
static inline void wgeom_store(dm_wgeom *g, int D, uint32_t q, const double *x, double r,
                               const dm_wall *wall, double delta, const double *n)
{
    double *nrm = g->nrm + D * q, *cp = g->cp + D * q, *vw = g->vw + D * q;
    g->delta[q] = delta;
    double arm = r - 0.5 * delta, rel[3] = {0.0, 0.0, 0.0};
    for (int c = 0; c < D; c++) {
        nrm[c] = n[c];
        cp[c] = x[c] + arm * nrm[c];
        rel[c] = cp[c] - wall->c[c];
    }
    const double *om = wall->omega;
    double spin[3] = {om[1] * rel[2] - om[2] * rel[1], om[2] * rel[0] - om[0] * rel[2],
                      om[0] * rel[1] - om[1] * rel[0]};
    for (int c = 0; c < D; c++)
        vw[c] = wall->vel[c] + spin[c];
    if (wall->surface)
        add_surface_velocity(wall, D, nrm, vw);
}

void dm_wgeom_store(demill_world *w, uint32_t q, uint32_t i, const dm_wall *wall, double delta,
                    const double *n)
{
    wgeom_store(&w->wg, w->dim, q, w->p.x + w->dim * i, w->p.r[i], wall, delta, n);
}

/* Contact geometry of candidates p0 .. p1-1 of a particle-wall bucket whose
 * first candidate has index g0 in w->wg (room reserved by the neighbour
 * build), but for mesh candidates: dm_wgeom_meshes() has done those. Compiled
 * for each dimension D, so that wgeom_store()'s loops over the components
 * are unrolled rather than counted at run time. */
static inline __attribute__((always_inline)) void wgeom_range(const int D, demill_world *w,
                                                              const dm_bucket *b, uint32_t g0,
                                                              uint32_t p0, uint32_t p1)
{
    dm_wgeom *g = &w->wg;
    const dm_particles *P = &w->p;
    for (uint32_t p = p0; p < p1; p++) {
        const uint32_t i = b->i[p];
        const dm_wall *wall = &w->walls[b->j[p]];
        if (wall->mesh)
            continue;
        const double *x = P->x + D * i;
        double n[3];
        const double delta = P->r[i] - dm_wall_closest(wall, x, D, n);
        wgeom_store(g, D, g0 + p, x, P->r[i], wall, delta, n);
    }
}

void dm_wgeom_range(demill_world *w, const dm_bucket *b, uint32_t g0, uint32_t p0, uint32_t p1)
{
    if (w->dim == 3)
        wgeom_range(3, w, b, g0, p0, p1);
    else
        wgeom_range(2, w, b, g0, p0, p1);
}

/* Contact geometry of every particle-wall candidate, in bucket order. */
void dm_wgeom_update(demill_world *w)
{
    uint32_t g0 = 0;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pw.b[k];
        dm_wgeom_range(w, b, g0, 0, b->n);
        g0 += b->n;
    }
    if (dm_walls_have_mesh(w))
        dm_wgeom_meshes(w, 0, w->p.n, 0);
}

/* Room for `more` walls beyond the slots in use (0; -1 when out of memory,
 * the walls unchanged), so that as many dm_wall_slot_alloc() calls succeed. */
int dm_walls_reserve(demill_world *w, uint32_t more)
{
    if (w->nwalls + more <= w->cap_walls)
        return 0;
    uint32_t cap = w->cap_walls ? 2 * w->cap_walls : 16;
    cap = cap < w->nwalls + more ? w->nwalls + more : cap;
    dm_wall *nw = realloc(w->walls, cap * sizeof *nw);
    if (!nw)
        return -1;
    w->walls = nw;
    w->cap_walls = cap;
    return 0;
}

/* A free wall slot (cleared), growing the array if needed; DM_FREE when out
 * of memory. */
uint32_t dm_wall_slot_alloc(demill_world *w)
{
    uint32_t slot = 0;
    while (slot < w->nwalls && w->walls[slot].kind)
        slot++;
    if (slot == w->cap_walls) {
        uint32_t cap = w->cap_walls ? 2 * w->cap_walls : 16;
        dm_wall *nw = realloc(w->walls, cap * sizeof *nw);
        if (!nw)
            return DM_FREE;
        w->walls = nw;
        w->cap_walls = cap;
    }
    memset(&w->walls[slot], 0, sizeof w->walls[slot]);
    if (slot == w->nwalls)
        w->nwalls++;
    return slot;
}
