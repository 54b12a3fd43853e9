/* drum.c: the mill drum (docs/physics.md §7): its walls (shell, end caps,
 * lifters) built from a few numbers, its speed in rad/s, rpm or as a
 * fraction of critical with an optional ramp, and what mill engineers read
 * from it (power, lifter loads, charge shape) with means over whole
 * revolutions. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/params.h"
#include "base/status.h"
#include "physics/contact/contact.h"
#include "physics/geometry/geometry.h"
#include "physics/mill/mill.h"

#define TWO_PI (2.0 * DM_PI)

/* ---- speed ------------------------------------------------------------------ */

/* The drum's speed at `time` and (through theta) its angle: the speed moves
 * linearly from omega_from to omega_to over ramp seconds from t_set, and
 * the angle is its exact integral. */
double dm_drum_omega_at(const dm_drum *d, double time, double *theta)
{
    const double tau = time - d->t_set;
    if (d->ramp > 0.0 && tau < d->ramp) {
        const double a = (d->omega_to - d->omega_from) / d->ramp;
        *theta = d->theta_set + d->omega_from * tau + 0.5 * a * tau * tau;
        return d->omega_from + a * tau;
    }
    *theta = d->theta_set + 0.5 * (d->omega_from + d->omega_to) * d->ramp +
             d->omega_to * (tau - d->ramp);
    return d->omega_to;
}

/* Critical speed √(2 g / (D - d)), with d the set critical diameter or the
 * largest particle diameter in the world; NaN when D <= d or g = 0. */
double dm_drum_critical_speed(const demill_world *w)
{
    const dm_drum *d = &w->drum;
    double dia = d->crit_diameter;
    if (dia <= 0.0)
        for (uint32_t i = 0; i < w->p.n; i++)
            dia = fmax(dia, 2.0 * w->p.r[i]);
    const double g = dm_gravity_magnitude(w);
    if (d->diameter <= dia || g == 0.0)
        return NAN;
    return sqrt(2.0 * g / (d->diameter - dia));
}

/* The target speed in rad/s that the speed key and value ask for; NaN for a
 * fraction of an undefined critical speed. */
double dm_drum_target_speed(const demill_world *w)
{
    const dm_drum *d = &w->drum;
    switch (d->speed_key) {
    case DEMILL_DRUM_SPEED_RPM: return d->speed_value * TWO_PI / 60.0;
    case DEMILL_DRUM_SPEED_FRACTION:
        return d->speed_value == 0.0 ? 0.0 : d->speed_value * dm_drum_critical_speed(w);
    default: return d->speed_value;
    }
}

/* The drum's centre at `time` and its velocity: a steady motion and a
 * harmonic one from t_move on. */
static void centre_at(const dm_drum *d, double time, double c[3], double v[3])
{
    const double tau = time - d->t_move, om = 2.0 * DM_PI * d->vib_freq;
    const double s = sin(om * tau + d->vib_phase), ds = om * cos(om * tau + d->vib_phase);
    for (int k = 0; k < 3; k++) {
        c[k] = d->centre_set[k] + d->velocity[k] * tau + d->vib_amp[k] * s;
        v[k] = d->velocity[k] + d->vib_amp[k] * ds;
    }
}

/* Moves the drum to `time` (its angle and speed, its centre and velocity),
 * then every wall: the drum's walls turn and move with it. */
void dm_drum_advance(demill_world *w, double time)
{
    dm_drum *d = &w->drum;
    if (d->alive) {
        d->omega = dm_drum_omega_at(d, time, &d->theta);
        centre_at(d, time, d->centre, d->vcentre);
    }
    dm_walls_advance(w, time);
}

/* Sets a translation key (DEMILL_DRUM_CENTER_X .. _VIBRATION_PHASE): the
 * motion restarts now from where the centre is (or is put, for a centre
 * key), and the drum's walls follow. */
void dm_drum_set_motion(demill_world *w, int32_t key, double value)
{
    dm_drum *d = &w->drum;
    double c[3], v[3];
    centre_at(d, w->time, c, v);
    if (key >= DEMILL_DRUM_CENTER_X && key <= DEMILL_DRUM_CENTER_Z)
        c[key - DEMILL_DRUM_CENTER_X] = value;
    else if (key >= DEMILL_DRUM_VELOCITY_X && key <= DEMILL_DRUM_VELOCITY_Z)
        d->velocity[key - DEMILL_DRUM_VELOCITY_X] = value;
    else if (key >= DEMILL_DRUM_VIBRATION_X && key <= DEMILL_DRUM_VIBRATION_Z)
        d->vib_amp[key - DEMILL_DRUM_VIBRATION_X] = value;
    else if (key == DEMILL_DRUM_VIBRATION_FREQUENCY)
        d->vib_freq = value;
    else
        d->vib_phase = value;
    d->t_move = w->time;
    const double s = sin(d->vib_phase);
    for (int k = 0; k < 3; k++)
        d->centre_set[k] = c[k] - d->vib_amp[k] * s;
    dm_drum_advance(w, w->time);
}

static void revolution_reset(demill_world *w);

/* Starts moving towards `target` from the current speed at the current time;
 * the first time the drum is set turning, its revolutions start counting
 * from here. The walls take the new speed at once. */
void dm_drum_retarget(demill_world *w, double target)
{
    dm_drum *d = &w->drum;
    double theta;
    const double omega = dm_drum_omega_at(d, w->time, &theta);
    d->t_set = w->time;
    d->theta_set = theta;
    d->omega_from = omega;
    d->omega_to = target;
    if (isnan(d->theta_start) && target != 0.0) {
        d->theta_start = theta;
        revolution_reset(w);
    }
    dm_drum_advance(w, w->time);
}

/* Before a run: a speed given as a fraction of critical follows the charge
 * (its largest particle may have changed since the speed was set). */
demill_status dm_drum_prepare(demill_world *w)
{
    dm_drum *d = &w->drum;
    if (!d->alive || d->speed_key != DEMILL_DRUM_SPEED_FRACTION)
        return DEMILL_OK;
    const double target = dm_drum_target_speed(w);
    if (!isfinite(target))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum: the critical speed is undefined (no gravity, or the largest "
                       "particle is as wide as the drum)");
    if (target != d->omega_to)
        dm_drum_retarget(w, target);
    return DEMILL_OK;
}

/* ---- walls -------------------------------------------------------------------- */

/* Cross-section of a lifter in the drum frame, counter-clockwise: its centre
 * line at polar angle a, height h above the shell of radius R, width wd at
 * the shell, the leading face (on the side of positive rotation) inclined by
 * `face` from the radial direction. The base is sunk into the shell so that
 * no corner of it is exposed. */
static int lifter_polygon(const dm_lifter_spec *l, double R, double *poly)
{
    const double ux = cos(l->angle), uy = sin(l->angle), tx = -uy, ty = ux;
    const double rb = R + l->width + l->height, ri = R - l->height, hw = 0.5 * l->width;
    const double tf = tan(l->face);
    /* (radius, tangential offset) of the four corners */
    const double rt[4][2] = {
        {ri, -hw}, {rb, -hw}, {rb, hw + (rb - R) * tf}, {ri, hw - l->height * tf}};
    for (int k = 0; k < 4; k++) {
        poly[2 * k] = rt[k][0] * ux + rt[k][1] * tx;
        poly[2 * k + 1] = rt[k][0] * uy + rt[k][1] * ty;
    }
    return 4;
}

void dm_drum_walls_remove(demill_world *w)
{
    dm_drum *d = &w->drum;
    for (uint32_t k = 0; k < d->nwall; k++) {
        dm_wall *wall = &w->walls[d->wall_slot[k]];
        dm_clist_drop_wall(w, d->wall_slot[k]);
        w->mat_walls[wall->material]--;
        wall->kind = 0;
    }
    d->nwall = 0;
}

static dm_wall *drum_wall_new(demill_world *w, int kind, int part)
{
    dm_drum *d = &w->drum;
    uint32_t slot = dm_wall_slot_alloc(w);
    dm_wall *wall = &w->walls[slot];
    wall->kind = kind;
    wall->drum_part = part;
    wall->handle = DM_FREE;
    wall->material = d->material[part - 1];
    wall->lifter = -1;
    w->mat_walls[wall->material]++;
    d->wall_slot[d->nwall++] = slot;
    return wall;
}

/* Rebuilds the drum's walls from its description, at the current angle (the
 * walls attached to it stay as they are). Fails (changing nothing) only when memory runs out. */
demill_status dm_drum_walls_build(demill_world *w)
{
    dm_drum *d = &w->drum;
    const uint32_t need = (d->shell ? 1 + (w->dim == 3 ? 2 : 0) : 0) + d->nlifters;
    /* make room first so that the build cannot fail half-way */
    if (w->nwalls + need > w->cap_walls) {
        uint32_t cap = w->cap_walls ? w->cap_walls : 16;
        while (cap < w->nwalls + need)
            cap *= 2;
        dm_wall *nw = realloc(w->walls, cap * sizeof *nw);
        if (!nw)
            return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "drum: out of memory for its walls");
        w->walls = nw;
        w->cap_walls = cap;
    }
    dm_drum_walls_remove(w);
    const double R = 0.5 * d->diameter;
    if (d->shell)
        drum_wall_new(w, DM_WALL_SHELL, DM_PART_SHELL)->radius = R;
    if (w->dim == 3 && d->shell)
        for (int side = 0; side < 2; side++) {
            dm_wall *cap = drum_wall_new(w, DM_WALL_PLANE, DM_PART_CAP);
            cap->p0[2] = side ? 0.5 * d->length : -0.5 * d->length;
            cap->n0[2] = side ? -1.0 : 1.0;
        }
    for (uint32_t k = 0; k < d->nlifters; k++) {
        dm_wall *lw = drum_wall_new(w, DM_WALL_PRISM, DM_PART_LIFTER);
        lw->lifter = (int)k;
        lw->npoly = lifter_polygon(&d->lifters[k], R, lw->poly);
        for (int v = 0; v < lw->npoly; v++) {
            lw->reach = fmax(lw->reach, hypot(lw->poly[2 * v], lw->poly[2 * v + 1]));
            lw->bc0[0] += lw->poly[2 * v] / lw->npoly;
            lw->bc0[1] += lw->poly[2 * v + 1] / lw->npoly;
        }
        for (int v = 0; v < lw->npoly; v++)
            lw->brad = fmax(lw->brad, hypot(lw->poly[2 * v] - lw->bc0[0],
                                            lw->poly[2 * v + 1] - lw->bc0[1]));
    }
    dm_drum_advance(w, w->time);
    for (uint32_t k = 0; k < d->nwall; k++) {
        dm_wall *wall = &w->walls[d->wall_slot[k]];
        memcpy(wall->c_build, wall->c, sizeof wall->c);
        memcpy(wall->rot_build, wall->rot, sizeof wall->rot);
    }
    w->ptab_dirty = true;
    w->nlist_valid = false;
    w->forces_valid = false;
    return DEMILL_OK;
}

/* n evenly spaced lifters of the current height, width, face angle and
 * phase. */
void dm_drum_even_lifters(dm_drum *d, uint32_t n)
{
    d->even_count = n;
    d->nlifters = n;
    for (uint32_t k = 0; k < n; k++)
        d->lifters[k] = (dm_lifter_spec){d->lifter_phase + TWO_PI * k / n, d->lifter_h,
                                         d->lifter_w, d->lifter_face};
}

demill_status dm_drum_check_lifter(demill_world *w, const dm_lifter_spec *l, double diameter)
{
    const double v[4] = {l->angle, l->height, l->width, l->face};
    static const char *names[4] = {"angle", "height", "width", "face_angle"};
    for (int k = 0; k < 4; k++)
        if (!isfinite(v[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "drum: lifter %s = %g is not finite",
                           names[k], v[k]);
    demill_status s;
    if ((s = dm_check_value(w, DEMILL_DRUM_LIFTER_HEIGHT, l->height)) ||
        (s = dm_check_value(w, DEMILL_DRUM_LIFTER_WIDTH, l->width)) ||
        (s = dm_check_value(w, DEMILL_DRUM_LIFTER_FACE_ANGLE, l->face)))
        return s;
    if (l->height >= 0.5 * diameter)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum: lifter height %g m reaches the axis of a drum of diameter %g m",
                       l->height, diameter);
    if (l->width >= diameter)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum: lifter width %g m exceeds the diameter",
                       l->width);
    if (l->height * tan(l->face) >= l->width)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum: a lifter %g m high and %g m wide cannot have a face angle of %g rad "
                       "(its top would vanish)",
                       l->height, l->width, l->face);
    return DEMILL_OK;
}

/* ---- measurements -------------------------------------------------------------- */

/* The load on the drum's walls and on those attached to it. */
double dm_drum_load(const demill_world *w, double *force)
{
    double t = 0.0, f[3] = {0.0, 0.0, 0.0};
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind || !wall->drum_part)
            continue;
        t += wall->torque[2];
        for (int c = 0; c < 3; c++)
            f[c] += wall->force[c];
    }
    if (force)
        memcpy(force, f, sizeof f);
    return t;
}

/* The power the drum delivers to the charge, -(T_z ω + F·v), from the
 * torque and the force the charge exerts on it. */
double dm_drum_power(const dm_drum *d, double torque, const double force[3])
{
    return -(torque * d->omega + force[0] * d->vcentre[0] + force[1] * d->vcentre[1] +
             force[2] * d->vcentre[2]);
}

/* Power from the charge's centre of mass: the torque gravity exerts on the
 * charge about the axis, T_g = (M x_cm × g)_z, is balanced by the drum in the
 * mean, so the drum delivers P = -ω T_g (x_cm about the drum's centre). */
double dm_drum_power_cm(const demill_world *w, double omega)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    double mx = 0.0, my = 0.0;
    const double *c = w->drum.centre;
    for (uint32_t i = 0; i < P->n; i++) {
        const double m = dm_particle_share(w, i);
        mx += m * (P->x[D * i] - c[0]);
        my += m * (P->x[D * i + 1] - c[1]);
    }
    return -omega * (mx * w->g[1] - my * w->g[0]);
}

static double total_dissipated(const demill_world *w)
{
    return dm_tally_dissipated(&w->tally);
}

static void revolution_reset(demill_world *w)
{
    dm_drum *d = &w->drum;
    memset(&d->rev, 0, sizeof d->rev);
    d->rev.t0 = w->time;
    d->rev.dissipated0 = total_dissipated(w);
}

/* After every step: the drum's power and lifter loads into the running
 * totals and the current revolution, charge-shape samples, and the means of
 * a revolution when it completes. */
void dm_drum_measure(demill_world *w)
{
    dm_drum *d = &w->drum;
    if (!d->alive)
        return;
    const double dt = w->dt;
    double f[3];
    d->torque = dm_drum_load(w, f);
    d->power = dm_drum_power(d, d->torque, f);
    d->energy_in += d->power * dt;
    d->energy_dissipated = 0.0;
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (!wall->kind || !wall->drum_part)
            continue;
        d->energy_dissipated += wall->dissipated;
        if (wall->lifter < 0) /* not one of the analytic lifters */
            continue;
        const int l = wall->lifter;
        d->lifter_energy[l] = wall->dissipated;
        d->lifter_peak[l] = fmax(d->lifter_peak[l], sqrt(wall->force[0] * wall->force[0] +
                                                         wall->force[1] * wall->force[1] +
                                                         wall->force[2] * wall->force[2]));
        for (int c = 0; c < 3; c++)
            d->rev.lifter_impulse[l][c] += wall->force[c] * dt;
    }
    if (isnan(d->theta_start))
        return; /* not turning yet */
    d->rev.energy_in += d->power * dt;
    if (w->base.steps >= d->samples_due) {
        d->samples_due = w->base.steps + d->sample_interval;
        double shape[3];
        dm_charge_shape(w, shape);
        for (int k = 0; k < 3; k++)
            if (isfinite(shape[k])) {
                d->rev.shape_sum[k] += shape[k];
                d->rev.shape_count[k]++;
            }
        d->rev.power_cm_sum += dm_drum_power_cm(w, d->omega);
        d->rev.power_cm_count++;
    }
    /* whole turns since the start, counted in doubles (at any finite speed
     * a drum may turn more times than an integer holds) */
    const double turns = floor(fabs(d->theta - d->theta_start) / TWO_PI);
    if (turns > (double)d->revolutions) {
        const double span = w->time - d->rev.t0;
        d->revolutions = turns < 0x1p64 ? (uint64_t)turns : UINT64_MAX;
        d->mean_power = d->rev.energy_in / span;
        d->mean_power_cm =
            d->rev.power_cm_count ? d->rev.power_cm_sum / d->rev.power_cm_count : NAN;
        d->mean_dissipation = (total_dissipated(w) - d->rev.dissipated0) / span;
        for (int k = 0; k < 3; k++)
            d->mean_shape[k] =
                d->rev.shape_count[k] ? d->rev.shape_sum[k] / d->rev.shape_count[k] : NAN;
        for (uint32_t l = 0; l < d->nlifters; l++)
            for (int c = 0; c < 3; c++)
                d->lifter_force_mean[l][c] = d->rev.lifter_impulse[l][c] / span;
        revolution_reset(w);
    }
}
