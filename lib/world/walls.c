/* walls.c: the walls' API: adding planes, triangle meshes and polylines,
 * moving and removing walls and reading their state
 * (lib/physics/geometry/walls.c computes their motion and their distances,
 * lib/physics/geometry/mesh.c the meshes'). */
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

DEMILL_API demill_status demill_wall_add_plane(demill_world *w, demill_id material,
                                               const double point[3], const double normal[3],
                                               demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!point || !normal || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "wall_add_plane: %s is NULL",
                       !point ? "point" : !normal ? "normal" : "out");
    const int flat = w->dim == 2;
    if ((s = check_vec3(w, point, "point", flat)) || (s = check_vec3(w, normal, "normal", flat)))
        return s;
    /* scale by the largest component first, so that no length overflows */
    double big = fmax(fabs(normal[0]), fmax(fabs(normal[1]), fabs(normal[2])));
    if (big == 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "wall_add_plane: normal has zero length");
    double u[3] = {normal[0] / big, normal[1] / big, normal[2] / big};
    double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    uint32_t slot;
    if (dm_handles_reserve(&w->wh, 1) || (slot = dm_wall_slot_alloc(w)) == DM_FREE)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "wall_add_plane: out of memory");
    dm_wall *wall = &w->walls[slot];
    memset(wall, 0, sizeof *wall);
    wall->kind = DM_WALL_PLANE;
    wall->material = mat;
    for (int c = 0; c < 3; c++) {
        wall->p0[c] = wall->c0[c] = point[c];
        wall->n0[c] = u[c] / len;
    }
    wall->t0 = w->time;
    dm_wall_at(wall, w->time);
    memcpy(wall->c_build, wall->c, sizeof wall->c);
    memcpy(wall->rot_build, wall->rot, sizeof wall->rot);
    wall->handle = dm_handles_issue(&w->wh, slot);
    w->mat_walls[mat]++;
    *out = dm_wall_id(w, slot);
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

/* Adds a mesh wall of nt elements of nel vertices (3: triangles, 2: segments)
 * over nv vertices, after checking them all. what: the function's name;
 * element: what an element is called in messages. */
static demill_status add_mesh(demill_world *w, uint32_t mat, int nel, size_t nv, const double *v,
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
    dm_trimesh *m = NULL;
    if (dm_handles_reserve(&w->wh, 1) ||
        !(m = dm_trimesh_build(nel, (uint32_t)nv, v, (uint32_t)nt, el)) ||
        (slot = dm_wall_slot_alloc(w)) == DM_FREE) {
        dm_trimesh_free(m);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", what);
    }
    dm_wall *wall = &w->walls[slot];
    wall->kind = DM_WALL_MESH;
    wall->material = mat;
    wall->mesh = m;
    wall->t0 = w->time;
    dm_wall_at(wall, w->time);
    memcpy(wall->c_build, wall->c, sizeof wall->c);
    memcpy(wall->rot_build, wall->rot, sizeof wall->rot);
    wall->handle = dm_handles_issue(&w->wh, slot);
    w->mat_walls[mat]++;
    *out = dm_wall_id(w, slot);
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    dm_changed(w);
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
    return add_mesh(w, mat, 3, n_vertices, vertices, n_triangles, triangles, "wall_add_mesh",
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
    s = add_mesh(w, mat, 2, n_points, points, nseg, seg, "wall_add_polyline", "segment", out);
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
    dm_clist_drop_wall(w, slot);
    dm_wall *wall = &w->walls[slot];
    w->mat_walls[wall->material]--;
    dm_handles_release(&w->wh, wall->handle);
    dm_trimesh_free(wall->mesh);
    wall->mesh = NULL;
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
    dm_wall_rebase(wall, w->time, w->time);
    for (int c = 0; c < 3; c++) {
        if (centre)
            wall->c0[c] = wall->c[c] = centre[c];
        wall->vel[c] = velocity ? velocity[c] : 0.0;
        wall->omega[c] = angular_velocity ? angular_velocity[c] : 0.0;
    }
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
    const double *src;
    switch (field) {
    case DEMILL_WALL_POINT: src = wall->p; break;
    case DEMILL_WALL_NORMAL: src = wall->n; break;
    case DEMILL_WALL_CENTRE: src = wall->c; break;
    case DEMILL_WALL_VELOCITY: src = wall->vel; break;
    case DEMILL_WALL_ANGULAR_VELOCITY: src = wall->omega; break;
    case DEMILL_WALL_FORCE: src = wall->force; break;
    case DEMILL_WALL_TORQUE: src = wall->torque; break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a wall field", (int)field);
    }
    memcpy(out, src, 3 * sizeof *out);
    return DEMILL_OK;
}
