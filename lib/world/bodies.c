/* bodies.c: the bodies' API (demill/body.h): adding and removing bodies,
 * their springs, dampers and external force, attaching walls, and reading
 * their state and energies (lib/physics/bodies/ steps them). */
#include <math.h>
#include <string.h>

#include "world/world.h"

static demill_status check_finite(demill_world *w, const double *v, int n, const char *what)
{
    for (int c = 0; c < n; c++)
        if (!isfinite(v[c]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s[%d] = %g is not finite", what, c, v[c]);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_add(demill_world *w, double mass, const double centre[3],
                                         int32_t free_axes, uint32_t flags, demill_id *out)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!centre || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "body_add: %s is NULL",
                       !centre ? "centre" : "out");
    if (!isfinite(mass))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "body_add: mass %g is not finite", mass);
    if (!(mass > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "body_add: mass %g is not > 0", mass);
    if ((s = check_finite(w, centre, 3, "body_add: centre")))
        return s;
    if (free_axes & ~(DEMILL_BODY_AXIS_X | DEMILL_BODY_AXIS_Y | DEMILL_BODY_AXIS_Z))
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY,
                       "body_add: free_axes 0x%x has bits that name no axis", (unsigned)free_axes);
    if (flags & ~DEMILL_BODY_NO_GRAVITY)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "body_add: unknown flags 0x%x",
                       (unsigned)flags);
    if (w->dim == 2 && (free_axes & DEMILL_BODY_AXIS_Z || centre[2] != 0.0))
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "body_add: the world is 2D: z cannot be free and the centre's z must "
                       "be 0");
    uint32_t slot;
    if (dm_handles_reserve(&w->bh, 1) || (slot = dm_body_slot_alloc(w)) == DM_FREE)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "body_add: out of memory");
    dm_body *b = &w->bodies[slot];
    b->free_axes = free_axes;
    b->gravity = !(flags & DEMILL_BODY_NO_GRAVITY);
    b->mass = mass;
    memcpy(b->x, centre, sizeof b->x);
    memcpy(b->rest, centre, sizeof b->rest);
    memcpy(b->x_tally, centre, sizeof b->x_tally);
    b->handle = dm_handles_issue(&w->bh, slot);
    *out = dm_body_id(w, slot);
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_remove(demill_world *w, demill_id id)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s)
        return s;
    for (uint32_t k = 0; k < w->nwalls; k++)
        if (w->walls[k].kind && w->walls[k].body == slot + 1)
            dm_wall_detach_body(w, &w->walls[k]);
    dm_handles_release(&w->bh, w->bodies[slot].handle);
    w->bodies[slot].handle = DM_FREE;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

/* The index of one axis bit (DEMILL_BODY_AXIS_*), checked. */
static demill_status axis_index(demill_world *w, int32_t axis, int *c)
{
    switch (axis) {
    case DEMILL_BODY_AXIS_X: *c = 0; break;
    case DEMILL_BODY_AXIS_Y: *c = 1; break;
    case DEMILL_BODY_AXIS_Z: *c = 2; break;
    default:
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "body_set_spring: %d is not an axis",
                       (int)axis);
    }
    if (*c == 2 && w->dim == 2)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "body_set_spring: no z axis in a 2D world");
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_set_spring(demill_world *w, demill_id id, int32_t axis,
                                                double stiffness, double damping, double rest)
{
    uint32_t slot;
    int c;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s || (s = axis_index(w, axis, &c)))
        return s;
    const double v[3] = {stiffness, damping, rest};
    if ((s = check_finite(w, v, 3, "body_set_spring: (stiffness, damping, rest)")))
        return s;
    if (stiffness < 0.0 || damping < 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_set_spring: stiffness %g and damping %g must be >= 0", stiffness,
                       damping);
    dm_body *b = &w->bodies[slot];
    if (!(b->free_axes & axis))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_set_spring: the body does not move along axis %c (free axes 0x%x)",
                       "xyz"[c], (unsigned)b->free_axes);
    b->k[c] = stiffness;
    b->c[c] = damping;
    b->rest[c] = rest;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_set_force(demill_world *w, demill_id id,
                                               const double amplitude[3], double frequency,
                                               double phase)
{
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s)
        return s;
    if (!amplitude)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "body_set_force: amplitude is NULL");
    const double v[2] = {frequency, phase};
    if ((s = check_finite(w, amplitude, 3, "body_set_force: amplitude")) ||
        (s = check_finite(w, v, 2, "body_set_force: (frequency, phase)")))
        return s;
    if (frequency < 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "body_set_force: frequency %g is < 0",
                       frequency);
    if (w->dim == 2 && amplitude[2] != 0.0)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "body_set_force: amplitude has z = %g but the world is 2D", amplitude[2]);
    dm_body *b = &w->bodies[slot];
    memcpy(b->f0, amplitude, sizeof b->f0);
    b->freq = frequency;
    b->phase = phase;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_attach_wall(demill_world *w, demill_id id, demill_id wall_id)
{
    uint32_t slot, ws;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s || (s = dm_resolve(w, wall_id, DEMILL_KIND_WALL, "wall", &ws)))
        return s;
    dm_wall *wall = &w->walls[ws];
    if (wall->body)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_attach_wall: wall 0x%llx is attached to body 0x%llx already",
                       (unsigned long long)wall_id,
                       (unsigned long long)dm_body_id(w, wall->body - 1));
    if (wall->drum_part)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_attach_wall: wall 0x%llx is attached to the drum and turns with "
                       "it; it cannot also move with a body",
                       (unsigned long long)wall_id);
    if (wall->parts[0] || wall->parts[1])
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_attach_wall: wall 0x%llx is a finite wall with caps, which a "
                       "body does not move; attach a wall without caps",
                       (unsigned long long)wall_id);
    if (wall->harmonic)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "body_attach_wall: wall 0x%llx moves harmonically "
                       "(demill_wall_set_harmonic); only a wall at rest can be attached",
                       (unsigned long long)wall_id);
    for (int c = 0; c < 3; c++)
        if (wall->vel[c] != 0.0 || wall->omega[c] != 0.0)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "body_attach_wall: wall 0x%llx moves (demill_wall_set_motion); "
                           "only a wall at rest can be attached",
                           (unsigned long long)wall_id);
    dm_wall_attach_body(w, wall, slot);
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_get(const demill_world *cw, demill_id id, int32_t field,
                                         double *out)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "body_get: out is NULL");
    const dm_body *b = &w->bodies[slot];
    dm_body_forces f;
    dm_body_forces_now(w, slot, &f);
    const double *src;
    switch (field) {
    case DEMILL_BODY_POSITION: src = b->x; break;
    case DEMILL_BODY_VELOCITY: src = b->v; break;
    case DEMILL_BODY_FORCE_PARTICLES: src = f.particles; break;
    case DEMILL_BODY_FORCE_SPRING: src = f.spring; break;
    case DEMILL_BODY_FORCE_DAMPER: src = f.damper; break;
    case DEMILL_BODY_FORCE_EXTERNAL: src = f.external; break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a body field", (int)field);
    }
    memcpy(out, src, 3 * sizeof *out);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_body_energy(const demill_world *cw, demill_id id, int32_t term,
                                            double *value)
{
    demill_world *w = (demill_world *)cw;
    uint32_t slot;
    demill_status s = dm_enter(w, id, DEMILL_KIND_BODY, "body", &slot);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "body_energy: value is NULL");
    if (term < DEMILL_ENERGY_BODY_KINETIC || term > DEMILL_ENERGY_BODY_WORK)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "body_energy: %d is not a body's energy term",
                       (int)term);
    double e[DM_BODY_ENERGIES];
    dm_body_energies(w, slot, e);
    *value = e[term - DEMILL_ENERGY_BODY_KINETIC];
    return DEMILL_OK;
}
