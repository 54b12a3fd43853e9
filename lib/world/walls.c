/* walls.c: the walls' API: adding planes, triangle meshes and polylines,
 * and finite walls (cylinders, cones, discs, rectangles; a capped
 * cylinder's caps are walls of their own, without an id, that follow it),
 * moving them (rigidly, harmonically, their surfaces along themselves),
 * removing them, reading their state and recording their loads
 * (lib/physics/geometry/walls.c computes their motion and their distances,
 * lib/physics/geometry/mesh.c the meshes', lib/physics/geometry/loads.c
 * keeps their loads). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/io/io.h"
#include "world/world.h"

static demill_status check_vec3(demill_world *w, const double *v, const char *what, int flat)
{
    for (int c = 0; c < 3; c++)
        if (!isfinite(v[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s[%d] = %g is not finite", what, c, v[c]);
    if (flat && v[2] != 0.0)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s has z = %g but the world is 2D", what, v[2]);
    return DEMILL_OK;
}

/* A direction: finite (z = 0 when flat), not zero; u receives it scaled to
 * unit length (by its largest component first, so that no length
 * overflows). */
static demill_status direction(demill_world *w, const char *fn, const double *v, const char *what,
                               int flat, double u[3])
{
    demill_status s = check_vec3(w, v, what, flat);
    if (s)
        return s;
    double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (big == 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %s has zero length", fn, what);
    for (int c = 0; c < 3; c++)
        u[c] = v[c] / big;
    double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int c = 0; c < 3; c++)
        u[c] /= len;
    return DEMILL_OK;
}

/* The checks every wall constructor starts with: the material, the point
 * and the direction (a normal or an axis) and out; finite walls only in 3D. */
static demill_status wall_enter(demill_world *w, const char *fn, demill_id material, int finite,
                                const double *point, const double *dir, const char *dir_name,
                                demill_id *out, uint32_t *mat, double u[3])
{
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", mat);
    if (s)
        return s;
    if (!point || !dir || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: %s is NULL", fn,
                       !point ? "point" : !dir ? dir_name : "out");
    if (finite && w->dim != 3)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s: finite walls are 3D only", fn);
    const int flat = w->dim == 2;
    if ((s = check_vec3(w, point, "point", flat)))
        return s;
    return direction(w, fn, dir, dir_name, flat, u);
}

/* Checks that a length is finite and positive (zero allowed with `zero`). */
static demill_status check_length(demill_world *w, const char *fn, double v, const char *what,
                                  int zero)
{
    if (!isfinite(v))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: %s = %g is not finite", fn, what, v);
    if (v < 0.0 || (v == 0.0 && !zero))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %s = %g must be %s", fn, what, v,
                       zero ? "at least 0" : "positive");
    return DEMILL_OK;
}

/* Takes n wall slots (a wall and its caps) as walls of `kind` of material
 * mat through `point` along the unit vector u, at rest: all, or none when
 * out of memory. The first gets a handle, the others are its caps. */
static demill_status walls_new(demill_world *w, const char *fn, int kind, uint32_t mat,
                               const double *point, const double u[3], uint32_t n,
                               uint32_t *slots)
{
    if (dm_handles_reserve(&w->wh, 1) || dm_walls_reserve(w, n))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    for (uint32_t q = 0; q < n; q++) {
        slots[q] = dm_wall_slot_alloc(w);
        dm_wall *wall = &w->walls[slots[q]];
        wall->kind = kind;
        wall->material = mat;
        for (int c = 0; c < 3; c++) {
            wall->p0[c] = wall->c0[c] = point[c];
            wall->n0[c] = u[c];
        }
        wall->t0 = w->time;
        dm_wall_at(wall, w->time);
        memcpy(wall->c_build, wall->c, sizeof wall->c);
        memcpy(wall->rot_build, wall->rot, sizeof wall->rot);
        wall->handle = DM_FREE;
        if (q) {
            wall->parent = slots[0] + 1;
            w->walls[slots[0]].parts[q - 1] = slots[q] + 1;
        }
    }
    w->walls[slots[0]].handle = dm_handles_issue(&w->wh, slots[0]);
    w->mat_walls[mat]++;
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_add_plane(demill_world *w, demill_id material,
                                               const double point[3], const double normal[3],
                                               demill_id *out)
{
    uint32_t mat, slot;
    double u[3];
    demill_status s =
        wall_enter(w, "wall_add_plane", material, 0, point, normal, "normal", out, &mat, u);
    if (s || (s = walls_new(w, "wall_add_plane", DM_WALL_PLANE, mat, point, u, 1, &slot)))
        return s;
    *out = dm_wall_id(w, slot);
    return DEMILL_OK;
}

/* A face of revolution about the axis: the meridian segment from (r0, h0)
 * to (r1, h1); own: its ends that are rims of this face. */
static void revolved_face(dm_wall *wall, double r0, double h0, double r1, double h1, int own)
{
    const double seg[4] = {r0, h0, r1, h1};
    memcpy(wall->seg, seg, sizeof seg);
    wall->own = own;
    dm_wall_finite_bound(wall);
}

/* A cone, or with `cylinder` set a cylinder (radius_start = radius_end,
 * named radius), for the function fn. */
static demill_status add_revolved(demill_world *w, const char *fn, int cylinder,
                                  demill_id material, const double *point, const double *axis,
                                  double radius_start, double radius_end, double length,
                                  int32_t caps, demill_id *out)
{
    uint32_t mat, slots[3] = {0, 0, 0};
    double u[3];
    demill_status s = wall_enter(w, fn, material, 1, point, axis, "axis", out, &mat, u);
    if (s || (s = check_length(w, fn, radius_start, cylinder ? "radius" : "radius_start",
                               !cylinder)) ||
        (s = check_length(w, fn, radius_end, "radius_end", 1)) ||
        (s = check_length(w, fn, length, "length", 0)))
        return s;
    if (radius_start == 0.0 && radius_end == 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: both radii are 0", fn);
    if (caps & ~DEMILL_CAPS_BOTH)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: caps %d is not a DEMILL_CAPS_* value", fn,
                       (int)caps);
    const int closed[2] = {(caps & DEMILL_CAPS_START) && radius_start > 0.0,
                           (caps & DEMILL_CAPS_END) && radius_end > 0.0};
    if ((s = walls_new(w, fn, DM_WALL_REVOLVED, mat, point, u, 1 + closed[0] + closed[1], slots)))
        return s;
    dm_wall *side = &w->walls[slots[0]];
    revolved_face(side, radius_start, 0.0, radius_end, length, 3);
    const double radius[2] = {radius_start, radius_end}, h[2] = {0.0, length};
    for (int end = 0, q = 1; end < 2; end++) {
        if (!closed[end])
            continue;
        /* the cap leaves the rim towards the axis; the side owns the rim */
        side->nb[2 * end] = -1.0;
        revolved_face(&w->walls[slots[q++]], 0.0, h[end], radius[end], h[end], 1);
    }
    *out = dm_wall_id(w, slots[0]);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_add_cone(demill_world *w, demill_id material,
                                              const double point[3], const double axis[3],
                                              double radius_start, double radius_end,
                                              double length, int32_t caps, demill_id *out)
{
    return add_revolved(w, "wall_add_cone", 0, material, point, axis, radius_start, radius_end,
                        length, caps, out);
}

DEMILL_API demill_status demill_wall_add_cylinder(demill_world *w, demill_id material,
                                                  const double point[3], const double axis[3],
                                                  double radius, double length, int32_t caps,
                                                  demill_id *out)
{
    return add_revolved(w, "wall_add_cylinder", 1, material, point, axis, radius, radius, length,
                        caps, out);
}

DEMILL_API demill_status demill_wall_add_disc(demill_world *w, demill_id material,
                                              const double centre[3], const double normal[3],
                                              double outer_radius, double inner_radius,
                                              demill_id *out)
{
    const char *fn = "wall_add_disc";
    uint32_t mat, slot;
    double u[3];
    demill_status s = wall_enter(w, fn, material, 1, centre, normal, "normal", out, &mat, u);
    if (s || (s = check_length(w, fn, outer_radius, "outer_radius", 0)) ||
        (s = check_length(w, fn, inner_radius, "inner_radius", 1)))
        return s;
    if (inner_radius >= outer_radius)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: inner_radius %g is not smaller than outer_radius %g", fn,
                       inner_radius, outer_radius);
    if ((s = walls_new(w, fn, DM_WALL_REVOLVED, mat, centre, u, 1, &slot)))
        return s;
    revolved_face(&w->walls[slot], inner_radius, 0.0, outer_radius, 0.0, 3);
    *out = dm_wall_id(w, slot);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_add_rectangle(demill_world *w, demill_id material,
                                                   const double centre[3],
                                                   const double normal[3],
                                                   const double direction_[3],
                                                   double half_width, double half_height,
                                                   demill_id *out)
{
    const char *fn = "wall_add_rectangle";
    uint32_t mat, slot;
    double u[3], e[3];
    demill_status s = wall_enter(w, fn, material, 1, centre, normal, "normal", out, &mat, u);
    if (s)
        return s;
    if (!direction_)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: direction is NULL", fn);
    if ((s = direction(w, fn, direction_, "direction", 0, e)) ||
        (s = check_length(w, fn, half_width, "half_width", 0)) ||
        (s = check_length(w, fn, half_height, "half_height", 0)))
        return s;
    /* the direction's part in the plane, of unit length */
    const double en = e[0] * u[0] + e[1] * u[1] + e[2] * u[2];
    for (int c = 0; c < 3; c++)
        e[c] -= en * u[c];
    const double len = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    if (!(len > 1e-6))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: direction is parallel to the normal",
                       fn);
    if ((s = walls_new(w, fn, DM_WALL_RECT, mat, centre, u, 1, &slot)))
        return s;
    dm_wall *wall = &w->walls[slot];
    for (int c = 0; c < 3; c++)
        wall->e0[c] = e[c] / len;
    wall->seg[0] = half_width;
    wall->seg[1] = half_height;
    dm_wall_finite_bound(wall);
    *out = dm_wall_id(w, slot);
    return DEMILL_OK;
}

/* Gives a wall's caps its pose and motion: they share its frame and differ
 * only in their faces. */
static void sync_caps(demill_world *w, uint32_t slot)
{
    const dm_wall *wall = &w->walls[slot];
    for (int q = 0; q < 2; q++) {
        if (!wall->parts[q])
            continue;
        dm_wall *cap = &w->walls[wall->parts[q] - 1], keep = *cap;
        *cap = *wall;
        cap->handle = keep.handle;
        cap->parent = keep.parent;
        memset(cap->parts, 0, sizeof cap->parts);
        memcpy(cap->seg, keep.seg, sizeof cap->seg);
        memcpy(cap->nb, keep.nb, sizeof cap->nb);
        cap->own = keep.own;
        cap->bh = keep.bh;
        cap->brad = keep.brad;
        memcpy(cap->force, keep.force, sizeof cap->force);
        memcpy(cap->torque, keep.torque, sizeof cap->torque);
        cap->dissipated = keep.dissipated;
    }
}

/* Adds a mesh wall of nt elements of nel vertices (3: triangles, 2: segments)
 * over nv vertices, after checking them all. what: the function's name;
 * element: what an element is called in messages. */
demill_status dm_walls_add_mesh(demill_world *w, uint32_t mat, int nel, size_t nv, const double *v,
                              size_t nt, const uint32_t *el, const char *what,
                              const char *element, demill_id *out)
{
    for (size_t k = 0; k < 3 * nv; k++)
        if (!isfinite(v[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: vertex %zu has %c = %g, not finite",
                           what, k / 3, "xyz"[k % 3], v[k]);
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < nel; k++)
            if (el[(size_t)nel * t + k] >= nv)
                return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                               "%s: %s %zu names vertex %u, of %zu vertices", what, element, t,
                               el[(size_t)nel * t + k], nv);
    for (size_t t = 0; t < nt; t++)
        if (dm_trimesh_degenerate(nel, v, el, t))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %s %zu (vertices %u, %u%s) has %s",
                           what, element, t, el[(size_t)nel * t], el[(size_t)nel * t + 1],
                           nel == 3 ? ", ..." : "", nel == 3 ? "zero area" : "zero length");
    uint32_t slot;
    const double origin[3] = {0.0, 0.0, 0.0};
    dm_trimesh *m = dm_trimesh_build(nel, (uint32_t)nv, v, (uint32_t)nt, el);
    if (!m)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", what);
    demill_status s = walls_new(w, what, DM_WALL_MESH, mat, origin, origin, 1, &slot);
    if (s) {
        dm_trimesh_free(m);
        return s;
    }
    w->walls[slot].mesh = m;
    *out = dm_wall_id(w, slot);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_add_mesh(demill_world *w, demill_id material,
                                              size_t n_vertices, const double *vertices,
                                              size_t n_triangles, const uint32_t *triangles,
                                              demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!vertices || !triangles || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "wall_add_mesh: %s is NULL",
                       !vertices ? "vertices" : !triangles ? "triangles" : "out");
    if (w->dim != 3)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "wall_add_mesh: a triangle mesh needs a 3D world (demill_wall_add_polyline "
                       "in 2D)");
    if (n_triangles == 0 || n_triangles > UINT32_MAX / 3 || n_vertices > UINT32_MAX)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_add_mesh: %zu triangles over %zu vertices (1 to %u triangles, at "
                       "most %u vertices)",
                       n_triangles, n_vertices, UINT32_MAX / 3, UINT32_MAX);
    return dm_walls_add_mesh(w, mat, 3, n_vertices, vertices, n_triangles, triangles, "wall_add_mesh",
                    "triangle", out);
}

/* An STL file's bytes as a mesh wall; `name` (the path, or "STL bytes")
 * starts the messages of a bad file. */
static demill_status add_stl(demill_world *w, demill_id material, const char *fn,
                             const char *name, const void *bytes, size_t size, double scale,
                             const double *xf, demill_id *out)
{
    dm_stl_mesh m;
    char err[256];
    demill_status s = dm_stl_parse(bytes, size, scale, xf, &m, err, sizeof err);
    if (s)
        return dm_fail(w, s, "%s: %s: %s", fn, name, err);
    s = demill_wall_add_mesh(w, material, m.nv, m.v, m.nt, m.tri, out);
    dm_stl_free(&m);
    return s;
}

/* The checks every STL call makes before reading a byte. */
static demill_status stl_checks(demill_world *w, demill_id material, const char *fn,
                                const void *input, const char *what, demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!input || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: %s is NULL", fn, !input ? what : "out");
    if (w->dim != 3)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s: a triangle mesh needs a 3D world", fn);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_add_stl(demill_world *w, demill_id material,
                                             const void *bytes, size_t size, double scale,
                                             const double transform[12], demill_id *out)
{
    demill_status s = stl_checks(w, material, "wall_add_stl", bytes, "bytes", out);
    return s ? s
             : add_stl(w, material, "wall_add_stl", "STL bytes", bytes, size, scale, transform,
                       out);
}

DEMILL_API demill_status demill_wall_load_stl(demill_world *w, demill_id material,
                                              const char *path, double scale,
                                              const double transform[12], demill_id *out)
{
    demill_status s = stl_checks(w, material, "wall_load_stl", path, "path", out);
    if (s)
        return s;
    uint8_t *b;
    size_t n;
    if ((s = dm_read_file(w, "wall_load_stl", path, &b, &n)))
        return s;
    s = add_stl(w, material, "wall_load_stl", path, b, n, scale, transform, out);
    free(b);
    return s;
}

DEMILL_API demill_status demill_wall_add_polyline(demill_world *w, demill_id material,
                                                  size_t n_points, const double *points,
                                                  int closed, demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!points || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "wall_add_polyline: %s is NULL",
                       !points ? "points" : "out");
    if (w->dim != 2)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "wall_add_polyline: a polyline needs a 2D world (demill_wall_add_mesh in "
                       "3D)");
    if (closed != 0 && closed != 1)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "wall_add_polyline: closed is %d, not 0 or 1",
                       closed);
    if (n_points < (closed ? 3u : 2u) || n_points > UINT32_MAX / 2)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_add_polyline: %zu points (%s polyline needs %d to %u)", n_points,
                       closed ? "a closed" : "an open", closed ? 3 : 2, UINT32_MAX / 2);
    for (size_t k = 0; k < n_points; k++)
        if (points[3 * k + 2] != 0.0)
            return dm_fail(w, DEMILL_ERR_DIMENSION,
                           "wall_add_polyline: point %zu has z = %g but the world is 2D", k,
                           points[3 * k + 2]);
    const size_t nseg = closed ? n_points : n_points - 1;
    uint32_t *seg = malloc(2 * nseg * sizeof *seg);
    if (!seg)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "wall_add_polyline: out of memory");
    for (size_t k = 0; k < nseg; k++) {
        seg[2 * k] = (uint32_t)k;
        seg[2 * k + 1] = (uint32_t)((k + 1) % n_points);
    }
    s = dm_walls_add_mesh(w, mat, 2, n_points, points, nseg, seg, "wall_add_polyline", "segment", out);
    free(seg);
    return s;
}

DEMILL_API demill_status demill_wall_mesh_info(const demill_world *cw, demill_id id,
                                               size_t *n_vertices, size_t *n_elements)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    if (!n_vertices || !n_elements)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "wall_mesh_info: %s is NULL",
                       !n_vertices ? "n_vertices" : "n_elements");
    const dm_trimesh *m = w->walls[slot].mesh;
    if (!m)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_mesh_info: the wall is not a mesh or a polyline");
    *n_vertices = m->nv;
    *n_elements = m->nt;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_remove(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    dm_wall_release(w, slot);
    w->ptab_dirty = true;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

void dm_wall_release(demill_world *w, uint32_t slot)
{
    dm_wall *wall = &w->walls[slot];
    for (int q = 0; q < 2; q++)
        if (wall->parts[q]) {
            dm_clist_drop_wall(w, wall->parts[q] - 1);
            w->walls[wall->parts[q] - 1].kind = 0;
        }
    dm_clist_drop_wall(w, slot);
    w->mat_walls[wall->material]--;
    dm_handles_release(&w->wh, wall->handle);
    dm_trimesh_free(wall->mesh);
    wall->mesh = NULL;
    dm_loads_free(wall->loads);
    wall->loads = NULL;
    wall->kind = 0;
}

DEMILL_API demill_status demill_wall_set_motion(demill_world *w, demill_id id,
                                                const double velocity[3],
                                                const double angular_velocity[3],
                                                const double centre[3])
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    const int flat = w->dim == 2;
    if ((velocity && (s = check_vec3(w, velocity, "velocity", flat))) ||
        (centre && (s = check_vec3(w, centre, "centre", flat))) ||
        (angular_velocity && (s = check_vec3(w, angular_velocity, "angular_velocity", 0))))
        return s;
    if (flat && angular_velocity && (angular_velocity[0] != 0.0 || angular_velocity[1] != 0.0))
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "angular_velocity has x or y components but the world is 2D");
    dm_wall *wall = &w->walls[slot];
    if (wall->drum_part)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_set_motion: the wall is attached to the drum and turns with it");
    if (wall->body)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_set_motion: the wall is attached to body 0x%llx and moves with it",
                       (unsigned long long)dm_body_id(w, wall->body - 1));
    dm_wall_rebase(wall, w->time, w->time);
    for (int c = 0; c < 3; c++) {
        if (centre)
            wall->c0[c] = wall->c[c] = centre[c];
        wall->vel[c] = velocity ? velocity[c] : 0.0;
        wall->omega[c] = angular_velocity ? angular_velocity[c] : 0.0;
    }
    sync_caps(w, slot);
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_set_harmonic(demill_world *w, demill_id id, int32_t mode,
                                                  const double axis[3], double amplitude,
                                                  double frequency, double phase)
{
    const char *fn = "wall_set_harmonic";
    uint32_t slot;
    double u[3];
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    if (mode != DEMILL_HARMONIC_TRANSLATION && mode != DEMILL_HARMONIC_ROTATION)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%s: mode %d is not a DEMILL_HARMONIC_* mode",
                       fn, (int)mode);
    if (!axis)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: axis is NULL", fn);
    const int flat = w->dim == 2, turn = mode == DEMILL_HARMONIC_ROTATION;
    if ((s = direction(w, fn, axis, "axis", flat && !turn, u)))
        return s;
    if (flat && turn && (u[0] != 0.0 || u[1] != 0.0))
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s: a 2D world turns about z only", fn);
    const double v[3] = {amplitude, frequency, phase};
    const char *name[3] = {"amplitude", "frequency", "phase"};
    for (int k = 0; k < 3; k++)
        if (!isfinite(v[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: %s = %g is not finite", fn, name[k],
                           v[k]);
    if (!(frequency > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: frequency = %g must be positive", fn,
                       frequency);
    dm_wall *wall = &w->walls[slot];
    if (wall->drum_part)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the wall is attached to the drum and turns with it", fn);
    if (wall->body)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the wall is attached to body 0x%llx and moves with it", fn,
                       (unsigned long long)dm_body_id(w, wall->body - 1));
    dm_wall_rebase(wall, w->time, w->time);
    wall->harmonic = mode == DEMILL_HARMONIC_ROTATION ? DM_HARMONIC_ROTATE : DM_HARMONIC_TRANSLATE;
    memcpy(wall->h_axis, u, sizeof u);
    wall->h_amp = amplitude;
    wall->h_freq = frequency;
    wall->h_phase = phase;
    wall->h_t0 = w->time;
    dm_wall_at(wall, w->time);
    sync_caps(w, slot);
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_set_surface_velocity(demill_world *w, demill_id id,
                                                          const double velocity[3])
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s || (velocity && (s = check_vec3(w, velocity, "velocity", w->dim == 2))))
        return s;
    dm_wall *wall = &w->walls[slot];
    /* stored in the reference frame, so that it turns with the wall */
    for (int c = 0; c < 3; c++)
        wall->surf0[c] = velocity ? wall->rot[0 + c] * velocity[0] +
                                        wall->rot[3 + c] * velocity[1] +
                                        wall->rot[6 + c] * velocity[2]
                                  : 0.0;
    wall->surface = velocity && (velocity[0] != 0.0 || velocity[1] != 0.0 || velocity[2] != 0.0);
    sync_caps(w, slot);
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_get(const demill_world *cw, demill_id id, int32_t field,
                                         double *out)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "wall_get: out is NULL");
    const dm_wall *wall = &w->walls[slot];
    if (field == DEMILL_WALL_FORCE || field == DEMILL_WALL_TORQUE) { /* with its caps' */
        const int torque = field == DEMILL_WALL_TORQUE;
        memcpy(out, torque ? wall->torque : wall->force, 3 * sizeof *out);
        for (int q = 0; q < 2; q++)
            for (int c = 0; c < 3 && wall->parts[q]; c++) {
                const dm_wall *cap = &w->walls[wall->parts[q] - 1];
                out[c] += torque ? cap->torque[c] : cap->force[c];
            }
        return DEMILL_OK;
    }
    double surface[3];
    dm_wall_surface_velocity(wall, surface);
    const double *src;
    switch (field) {
    case DEMILL_WALL_POINT: src = wall->p; break;
    case DEMILL_WALL_NORMAL: src = wall->n; break;
    case DEMILL_WALL_CENTRE: src = wall->c; break;
    case DEMILL_WALL_VELOCITY: src = wall->vel; break;
    case DEMILL_WALL_ANGULAR_VELOCITY: src = wall->omega; break;
    case DEMILL_WALL_SURFACE_VELOCITY: src = surface; break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a wall field", (int)field);
    }
    memcpy(out, src, 3 * sizeof *out);
    return DEMILL_OK;
}

/* ---- recorded loads (docs/geometry.md, Wall loads) ---------------------------------- */

DEMILL_API demill_status demill_wall_loads_start(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    dm_wall *wall = &w->walls[slot];
    dm_loads *l = dm_loads_new(dm_loads_elements(wall));
    if (!l)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "wall_loads_start: out of memory");
    dm_loads_free(wall->loads);
    wall->loads = l;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_loads_stop(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    dm_loads_free(w->walls[slot].loads);
    w->walls[slot].loads = NULL;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_wall_loads(const demill_world *cw, demill_id id, size_t n,
                                           double *normal, double *impulse, double *shear_work,
                                           double *area, double *interval)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    const dm_loads *l = w->walls[slot].loads;
    if (!l)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_loads: the wall records no loads (demill_wall_loads_start first)");
    if (n != l->n)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "wall_loads: n = %zu, but the wall keeps its loads for %u element%s", n,
                       l->n, l->n == 1 ? "" : "s");
    for (size_t e = 0; e < n && normal; e++)
        normal[e] = dm_loads_normal(l, (uint32_t)e);
    for (size_t e = 0; e < n && impulse; e++)
        impulse[e] = l->v[DM_LOADS * e + 1];
    for (size_t e = 0; e < n && shear_work; e++)
        shear_work[e] = l->v[DM_LOADS * e + 2];
    for (size_t e = 0; e < n && area; e++)
        area[e] = dm_loads_area(w, slot, (uint32_t)e);
    if (interval)
        *interval = l->interval;
    return DEMILL_OK;
}
