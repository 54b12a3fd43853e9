/* walls.c: the walls' API: adding planes, moving and removing walls and
 * reading their state (lib/physics/geometry/walls.c computes their motion
 * and their distances). */
#include <math.h>
#include <string.h>

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

DEMILL_API demill_status demill_wall_remove(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_WALL, "wall", &slot);
    if (s)
        return s;
    dm_clist_drop_wall(w, slot);
    dm_wall *wall = &w->walls[slot];
    w->mat_walls[wall->material]--;
    dm_handles_release(&w->wh, wall->handle);
    wall->kind = 0;
    w->ptab_dirty = true;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
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
