/* drum.c: the mill drum's API: making, changing and removing a drum and
 * reading what mill engineers read from it (lib/physics/mill/drum.c does the
 * work; docs/physics.md §7). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

#define TWO_PI (2.0 * DM_PI)
/* The most points and copies a profile (demill_drum_add_profile) takes. */
#define DM_MAX_PROFILE_POINTS 65536
#define DM_MAX_PROFILE_COPIES 1024

static double param_default(int32_t key)
{
    double v = 0.0;
    demill_param_bounds(key, NULL, NULL, &v);
    return v;
}

DEMILL_API demill_status demill_drum_create(demill_world *w, demill_id material, demill_id *out)
{
    uint32_t mat;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_create: out is NULL");
    if (w->drum.alive)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_create: the world has a drum already");
    if (w->drum_gen == DM_GEN_LAST)
        return dm_fail(w, DEMILL_ERR_LIMIT,
                       "drum_create: this world has made %u drums, the most a world can (each "
                       "needs an id of its own)",
                       (unsigned)DM_GEN_LAST);
    dm_drum saved = w->drum;
    dm_drum *d = &w->drum;
    memset(d, 0, sizeof *d);
    d->material[0] = d->material[1] = d->material[2] = mat;
    d->diameter = param_default(DEMILL_DRUM_DIAMETER);
    d->length = param_default(DEMILL_DRUM_LENGTH);
    d->lifter_h = param_default(DEMILL_DRUM_LIFTER_HEIGHT);
    d->lifter_w = param_default(DEMILL_DRUM_LIFTER_WIDTH);
    d->lifter_face = param_default(DEMILL_DRUM_LIFTER_FACE_ANGLE);
    d->lifter_phase = param_default(DEMILL_DRUM_LIFTER_PHASE);
    d->porosity = param_default(DEMILL_DRUM_FILL_POROSITY);
    d->shell = param_default(DEMILL_DRUM_SHELL) != 0.0;
    d->sample_interval = (uint32_t)param_default(DEMILL_DRUM_SAMPLE_INTERVAL);
    d->speed_key = DEMILL_DRUM_SPEED;
    d->t_set = w->time;
    d->theta_start = NAN;
    d->mean_power = d->mean_power_cm = d->mean_dissipation = NAN;
    for (int k = 0; k < 3; k++)
        d->mean_shape[k] = NAN;
    d->alive = true;
    if ((s = dm_drum_walls_build(w))) {
        w->drum = saved;
        return s;
    }
    *out = dm_drum_id(w);
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_remove(demill_world *w, demill_id drum)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    dm_drum_walls_remove(w);
    for (uint32_t k = 0; k < w->nwalls; k++) /* (a capped wall's release frees its caps) */
        if (w->walls[k].kind && dm_wall_attached(&w->walls[k]) && !w->walls[k].parent)
            dm_wall_release(w, k);
    dm_spectrum_free(w);
    w->drum.alive = false;
    w->drum_gen++;
    w->events = false;
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_set(demill_world *w, demill_id drum, int32_t key,
                                         double value)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    if (key < 400 || key > 499)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "drum_set: %d is not a drum key", (int)key);
    if ((s = dm_check_value(w, key, value)))
        return s;
    dm_drum *d = &w->drum, saved = *d;
    bool rebuild = false;
    switch (key) {
    case DEMILL_DRUM_DIAMETER: d->diameter = value; rebuild = true; break;
    case DEMILL_DRUM_LENGTH: d->length = value; rebuild = true; break;
    case DEMILL_DRUM_SHELL: d->shell = value != 0.0; rebuild = true; break;
    case DEMILL_DRUM_LIFTERS: dm_drum_even_lifters(d, (uint32_t)value); rebuild = true; break;
    case DEMILL_DRUM_LIFTER_HEIGHT: d->lifter_h = value; rebuild = true; break;
    case DEMILL_DRUM_LIFTER_WIDTH: d->lifter_w = value; rebuild = true; break;
    case DEMILL_DRUM_LIFTER_FACE_ANGLE: d->lifter_face = value; rebuild = true; break;
    case DEMILL_DRUM_LIFTER_PHASE: d->lifter_phase = value; rebuild = true; break;
    case DEMILL_DRUM_SPEED:
    case DEMILL_DRUM_SPEED_RPM:
    case DEMILL_DRUM_SPEED_FRACTION: {
        d->speed_key = key;
        d->speed_value = value;
        const double target = dm_drum_target_speed(w);
        if (!isfinite(target)) {
            *d = saved;
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "drum: a speed as a fraction of critical needs gravity and a drum "
                           "wider than its largest particle");
        }
        dm_drum_retarget(w, target);
        break;
    }
    case DEMILL_DRUM_RAMP_TIME:
        dm_drum_retarget(w, d->omega_to); /* the ramp applies to the next change */
        d->ramp = value;
        break;
    case DEMILL_DRUM_CRITICAL_DIAMETER: d->crit_diameter = value; break;
    case DEMILL_DRUM_FILL_POROSITY: d->porosity = value; break;
    case DEMILL_DRUM_SAMPLE_INTERVAL: d->sample_interval = (uint32_t)value; break;
    default: /* the translation keys */
        if (w->dim == 2 && value != 0.0 &&
            (key == DEMILL_DRUM_CENTER_Z || key == DEMILL_DRUM_VELOCITY_Z ||
             key == DEMILL_DRUM_VIBRATION_Z))
            return dm_fail(w, DEMILL_ERR_DIMENSION, "drum_set: %s = %g in a 2D world",
                           demill_param_name(key), value);
        dm_drum_set_motion(w, key, value);
    }
    if (rebuild) {
        if (key != DEMILL_DRUM_DIAMETER && key != DEMILL_DRUM_LENGTH && key != DEMILL_DRUM_LIFTERS &&
            key != DEMILL_DRUM_SHELL && d->even_count)
            dm_drum_even_lifters(d, d->even_count);
        for (uint32_t k = 0; k < d->nlifters && !s; k++)
            s = dm_drum_check_lifter(w, &d->lifters[k], d->diameter);
        if (s || (s = dm_drum_walls_build(w))) {
            *d = saved;
            return s;
        }
    }
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_add_lifter(demill_world *w, demill_id drum, double angle,
                                                double height, double width, double face_angle)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    dm_drum *d = &w->drum, saved = *d;
    const dm_lifter_spec l = {angle, height, width, face_angle};
    if ((s = dm_drum_check_lifter(w, &l, d->diameter)))
        return s;
    if (d->nlifters == DM_MAX_LIFTERS)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_add_lifter: at most %d lifters",
                       DM_MAX_LIFTERS);
    d->lifters[d->nlifters++] = l;
    d->even_count = 0;
    if ((s = dm_drum_walls_build(w))) {
        *d = saved;
        return s;
    }
    dm_changed(w);
    return DEMILL_OK;
}

/* The drum's part, checked: its index in dm_drum.material. */
static demill_status drum_part(demill_world *w, int32_t part, const char *fn, int *index)
{
    if (part < DEMILL_DRUM_PART_SHELL || part > DEMILL_DRUM_PART_LIFTERS)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%s: %d is not a part of the drum", fn,
                       (int)part);
    if (part == DEMILL_DRUM_PART_CAPS && w->dim == 2)
        return dm_fail(w, DEMILL_ERR_DIMENSION, "%s: a 2D drum has no end caps", fn);
    *index = part - 1;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_set_material(demill_world *w, demill_id drum, int32_t part,
                                                  demill_id material)
{
    uint32_t slot, mat;
    int q = 0;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat)) ||
        (s = drum_part(w, part, "drum_set_material", &q)))
        return s;
    dm_drum *d = &w->drum;
    d->material[q] = mat;
    for (uint32_t k = 0; k < d->nwall; k++) {
        dm_wall *wall = &w->walls[d->wall_slot[k]];
        if (wall->drum_part != part || wall->material == mat)
            continue;
        dm_clist_drop_wall(w, d->wall_slot[k]);
        w->mat_walls[wall->material]--;
        w->mat_walls[mat]++;
        wall->material = mat;
        w->ptab_dirty = true;
        w->nlist_valid = false;
        w->forces_valid = false;
    }
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_attach_wall(demill_world *w, demill_id drum, demill_id wall,
                                                 int32_t part)
{
    uint32_t slot, wslot;
    int q = 0;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = dm_enter(w, wall, DEMILL_KIND_WALL, "wall", &wslot)) ||
        (s = drum_part(w, part, "drum_attach_wall", &q)))
        return s;
    dm_wall *wl = &w->walls[wslot];
    if (wl->drum_part)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_attach_wall: the wall is attached to the drum already");
    if (wl->body)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_attach_wall: the wall is attached to body 0x%llx and moves with it",
                       (unsigned long long)dm_body_id(w, wl->body - 1));
    dm_wall_attach(wl, part, w->time, &w->drum);
    for (int q = 0; q < 2; q++) /* a capped wall's caps, which share its pose */
        if (wl->parts[q])
            dm_wall_attach(&w->walls[wl->parts[q] - 1], part, w->time, &w->drum);
    w->nlist_valid = false;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

/* The checks of demill_drum_add_profile()'s points: finite, inside the
 * shell, no segment of zero length. */
static demill_status profile_check(demill_world *w, size_t n, const double *xy, int closed)
{
    const char *fn = "drum_add_profile";
    const double R = 0.5 * w->drum.diameter;
    for (size_t k = 0; k < n; k++) {
        const double x = xy[2 * k], y = xy[2 * k + 1];
        if (!isfinite(x) || !isfinite(y))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: point %zu (%g, %g) is not finite", fn,
                           k, x, y);
        /* (a point computed on the shell may lie an ulp or two beyond it) */
        if (hypot(x, y) > R * (1.0 + 1e-12))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: point %zu (%g, %g) lies %g m from the axis, outside the shell "
                           "of radius %g m",
                           fn, k, x, y, hypot(x, y), R);
    }
    const size_t nseg = closed ? n : n - 1;
    for (size_t k = 0; k < nseg; k++) {
        const size_t j = (k + 1) % n;
        if (xy[2 * k] == xy[2 * j] && xy[2 * k + 1] == xy[2 * j + 1])
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: segment %zu (points %zu and %zu) has zero length", fn, k, k, j);
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_add_profile(demill_world *w, demill_id drum,
                                                 demill_id material, int32_t part,
                                                 size_t n_points, const double *points,
                                                 int closed, uint32_t copies, demill_id *out)
{
    const char *fn = "drum_add_profile";
    uint32_t slot, mat;
    int q = 0;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat)) ||
        (s = drum_part(w, part, fn, &q)))
        return s;
    if (!points || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: %s is NULL", fn, !points ? "points" : "out");
    if (closed != 0 && closed != 1)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: closed is %d, not 0 or 1", fn, closed);
    if (n_points < (closed ? 3u : 2u) || n_points > DM_MAX_PROFILE_POINTS)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: %zu points (%s profile needs %d to %d)", fn, n_points,
                       closed ? "a closed" : "an open", closed ? 3 : 2, DM_MAX_PROFILE_POINTS);
    if (copies < 1 || copies > DM_MAX_PROFILE_COPIES)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %u copies (1 to %d)", fn, copies,
                       DM_MAX_PROFILE_COPIES);
    if ((s = profile_check(w, n_points, points, closed)))
        return s;
    /* each copy's points where they are now (at the drum's angle), twice in
     * 3D: at both ends of the drum, joined by two triangles a segment */
    const int D = w->dim, ends = D == 3 ? 2 : 1, nel = D == 3 ? 3 : 2;
    const size_t nseg = closed ? n_points : n_points - 1, nv = copies * n_points * ends;
    const size_t nt = copies * nseg * (D == 3 ? 2 : 1);
    double *v = malloc(3 * nv * sizeof *v);
    uint32_t *el = malloc((size_t)nel * nt * sizeof *el);
    if (!v || !el) {
        free(v);
        free(el);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", fn);
    }
    const dm_drum *d = &w->drum;
    size_t iv = 0, it = 0;
    for (uint32_t c = 0; c < copies; c++) {
        const double a = d->theta + TWO_PI * c / copies, ca = cos(a), sa = sin(a);
        const size_t first = iv;
        for (int e = 0; e < ends; e++)
            for (size_t k = 0; k < n_points; k++, iv++) {
                const double x = points[2 * k], y = points[2 * k + 1];
                v[3 * iv] = d->centre[0] + (ca * x - sa * y);
                v[3 * iv + 1] = d->centre[1] + (sa * x + ca * y);
                v[3 * iv + 2] = d->centre[2] + (D == 3 ? (e ? 0.5 : -0.5) * d->length : 0.0);
            }
        for (size_t k = 0; k < nseg; k++) {
            const uint32_t p0 = (uint32_t)(first + k), p1 = (uint32_t)(first + (k + 1) % n_points);
            if (D == 2) {
                el[2 * it] = p0;
                el[2 * it + 1] = p1;
                it++;
                continue;
            }
            const uint32_t q0 = p0 + (uint32_t)n_points, q1 = p1 + (uint32_t)n_points;
            const uint32_t tri[6] = {p0, p1, q1, p0, q1, q0};
            memcpy(el + 3 * it, tri, sizeof tri);
            it += 2;
        }
    }
    demill_id id;
    uint32_t ws;
    s = dm_walls_add_mesh(w, mat, nel, nv, v, nt, el, fn, D == 3 ? "triangle" : "segment", &id);
    free(v);
    free(el);
    if (s || (s = dm_resolve(w, id, DEMILL_KIND_WALL, "wall", &ws)))
        return s;
    dm_wall_attach(&w->walls[ws], part, w->time, d);
    *out = id;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_get_material(demill_world *w, demill_id drum, int32_t part,
                                                  demill_id *out)
{
    uint32_t slot;
    int q = 0;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = drum_part(w, part, "drum_get_material", &q)))
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_get_material: out is NULL");
    *out = dm_material_id(w, w->drum.material[q]);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_get(demill_world *w, demill_id drum, int32_t key,
                                         double *value)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_get: value is NULL");
    const dm_drum *d = &w->drum;
    double shape[3];
    switch (key) {
    case DEMILL_DRUM_DIAMETER: *value = d->diameter; break;
    case DEMILL_DRUM_LENGTH: *value = d->length; break;
    case DEMILL_DRUM_SHELL: *value = d->shell; break;
    case DEMILL_DRUM_LIFTERS:
    case DEMILL_DRUM_LIFTER_COUNT: *value = d->nlifters; break;
    case DEMILL_DRUM_LIFTER_HEIGHT: *value = d->lifter_h; break;
    case DEMILL_DRUM_LIFTER_WIDTH: *value = d->lifter_w; break;
    case DEMILL_DRUM_LIFTER_FACE_ANGLE: *value = d->lifter_face; break;
    case DEMILL_DRUM_LIFTER_PHASE: *value = d->lifter_phase; break;
    case DEMILL_DRUM_SPEED: *value = d->omega_to; break;
    case DEMILL_DRUM_SPEED_RPM: *value = d->omega_to * 60.0 / TWO_PI; break;
    case DEMILL_DRUM_SPEED_FRACTION: *value = d->omega_to / dm_drum_critical_speed(w); break;
    case DEMILL_DRUM_RAMP_TIME: *value = d->ramp; break;
    case DEMILL_DRUM_CRITICAL_DIAMETER: *value = d->crit_diameter; break;
    case DEMILL_DRUM_FILL_POROSITY: *value = d->porosity; break;
    case DEMILL_DRUM_SAMPLE_INTERVAL: *value = d->sample_interval; break;
    case DEMILL_DRUM_CRITICAL_SPEED: *value = dm_drum_critical_speed(w); break;
    case DEMILL_DRUM_CURRENT_SPEED: *value = d->omega; break;
    case DEMILL_DRUM_ANGLE: *value = d->theta; break;
    case DEMILL_DRUM_REVOLUTIONS: *value = (double)d->revolutions; break;
    case DEMILL_DRUM_TORQUE: *value = dm_drum_load(w, NULL); break;
    case DEMILL_DRUM_POWER: {
        double f[3];
        const double t = dm_drum_load(w, f);
        *value = dm_drum_power(d, t, f);
        break;
    }
    case DEMILL_DRUM_CENTER_X:
    case DEMILL_DRUM_CENTER_Y:
    case DEMILL_DRUM_CENTER_Z: *value = d->centre[key - DEMILL_DRUM_CENTER_X]; break;
    case DEMILL_DRUM_VELOCITY_X:
    case DEMILL_DRUM_VELOCITY_Y:
    case DEMILL_DRUM_VELOCITY_Z: *value = d->velocity[key - DEMILL_DRUM_VELOCITY_X]; break;
    case DEMILL_DRUM_VIBRATION_X:
    case DEMILL_DRUM_VIBRATION_Y:
    case DEMILL_DRUM_VIBRATION_Z: *value = d->vib_amp[key - DEMILL_DRUM_VIBRATION_X]; break;
    case DEMILL_DRUM_VIBRATION_FREQUENCY: *value = d->vib_freq; break;
    case DEMILL_DRUM_VIBRATION_PHASE: *value = d->vib_phase; break;
    case DEMILL_DRUM_CURRENT_VELOCITY_X:
    case DEMILL_DRUM_CURRENT_VELOCITY_Y:
    case DEMILL_DRUM_CURRENT_VELOCITY_Z:
        *value = d->vcentre[key - DEMILL_DRUM_CURRENT_VELOCITY_X];
        break;
    case DEMILL_DRUM_POWER_MEAN: *value = d->mean_power; break;
    case DEMILL_DRUM_POWER_CM: *value = dm_drum_power_cm(w, d->omega); break;
    case DEMILL_DRUM_POWER_CM_MEAN: *value = d->mean_power_cm; break;
    case DEMILL_DRUM_TOE_ANGLE:
    case DEMILL_DRUM_SHOULDER_ANGLE:
    case DEMILL_DRUM_COM_ANGLE:
        dm_charge_shape(w, shape);
        *value = shape[key - DEMILL_DRUM_TOE_ANGLE];
        break;
    case DEMILL_DRUM_TOE_ANGLE_MEAN:
    case DEMILL_DRUM_SHOULDER_ANGLE_MEAN:
    case DEMILL_DRUM_COM_ANGLE_MEAN: *value = d->mean_shape[key - DEMILL_DRUM_TOE_ANGLE_MEAN]; break;
    case DEMILL_DRUM_ENERGY_IN: *value = d->energy_in; break;
    case DEMILL_DRUM_ENERGY_DISSIPATED: *value = d->energy_dissipated; break;
    case DEMILL_DRUM_DISSIPATION_MEAN: *value = d->mean_dissipation; break;
    case DEMILL_DRUM_FORCE_X:
    case DEMILL_DRUM_FORCE_Y:
    case DEMILL_DRUM_FORCE_Z: {
        double f[3];
        dm_drum_load(w, f);
        *value = f[key - DEMILL_DRUM_FORCE_X];
        break;
    }
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "drum_get: %d is not a drum key", (int)key);
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_lifter_get(demill_world *w, demill_id drum, uint32_t index,
                                                int32_t field, double *out)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_lifter_get: out is NULL");
    const dm_drum *d = &w->drum;
    if (index >= d->nlifters)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_lifter_get: lifter %u of %u", index,
                       d->nlifters);
    const dm_wall *wall = NULL;
    for (uint32_t k = 0; k < d->nwall; k++)
        if (w->walls[d->wall_slot[k]].lifter == (int)index)
            wall = &w->walls[d->wall_slot[k]];
    double theta;
    switch (field) {
    case DEMILL_LIFTER_FORCE: memcpy(out, wall->force, 3 * sizeof *out); break;
    case DEMILL_LIFTER_FORCE_MEAN: memcpy(out, d->lifter_force_mean[index], 3 * sizeof *out); break;
    case DEMILL_LIFTER_FORCE_PEAK: out[0] = d->lifter_peak[index]; break;
    case DEMILL_LIFTER_ENERGY: out[0] = d->lifter_energy[index]; break;
    case DEMILL_LIFTER_ANGLE:
        dm_drum_omega_at(d, w->time, &theta);
        out[0] = d->lifters[index].angle + theta;
        break;
    default:
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "drum_lifter_get: %d is not a lifter field",
                       (int)field);
    }
    return DEMILL_OK;
}
