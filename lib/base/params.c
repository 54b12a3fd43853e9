/* params.c: names, units, bounds and defaults of every parameter key, and the
 * checks every setter applies before it changes anything. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "base/params.h"
#include "base/status.h"

enum { OPEN_LO = 1, OPEN_HI = 2, WHOLE = 4, READ_ONLY = 8 };

typedef struct param_info {
    int32_t key;
    const char *name, *unit;
    double lo, hi, def;
    int flags;
} param_info;

static const param_info params[] = {
    {DEMILL_WORLD_TIME_STEP, "world.time_step", "s", 0, 1, 1e-5, OPEN_LO},
    {DEMILL_WORLD_GRAVITY_X, "world.gravity_x", "m/s^2", -1e6, 1e6, 0, 0},
    {DEMILL_WORLD_GRAVITY_Y, "world.gravity_y", "m/s^2", -1e6, 1e6, -9.81, 0},
    {DEMILL_WORLD_GRAVITY_Z, "world.gravity_z", "m/s^2", -1e6, 1e6, 0, 0},
    {DEMILL_WORLD_INTEGRATOR, "world.integrator", "enum", 1, 3, 1, WHOLE},
    {DEMILL_WORLD_SKIN, "world.skin", "1", 0.01, 10, 0.3, 0},
    {DEMILL_WORLD_DISC_THICKNESS, "world.disc_thickness", "m", 0, 1e6, 0, 0},
    {DEMILL_WORLD_ENERGY_TRACKING, "world.energy_tracking", "bool", 0, 1, 1, WHOLE},
    {DEMILL_WORLD_TIME, "world.time", "s", -1e300, 1e300, 0, 0},
    {DEMILL_WORLD_THREADS, "world.threads", "1", 0, 1024, 1, WHOLE},
    {DEMILL_WORLD_REFINE_TOLERANCE, "world.refine_tolerance", "1", 0, 1, 1e-4, OPEN_LO},
    {DEMILL_WORLD_REFINE_MAX_ITERATIONS, "world.refine_max_iterations", "1", 1, 100, 8, WHOLE},
    {DEMILL_WORLD_WATCHDOG, "world.watchdog", "bool", 0, 1, 1, WHOLE},
    {DEMILL_WORLD_WATCHDOG_OVERLAP, "world.watchdog_overlap", "1", 0, 1, 0.25, OPEN_LO},
    {DEMILL_WORLD_WATCHDOG_INTERVAL, "world.watchdog_interval", "1", 1, 1e6, 500, WHOLE},
    {DEMILL_WORLD_SINGLE_PRECISION, "world.single_precision", "bool", 0, 1, 0, WHOLE},
    {DEMILL_WORLD_ORIENTATION_TRACKING, "world.orientation_tracking", "bool", 0, 1, 1, WHOLE},
    {DEMILL_WORLD_DIMENSION, "world.dimension", "1", 2, 3, 3, WHOLE | READ_ONLY},
    {DEMILL_WORLD_STEP_COUNT, "world.step_count", "1", 0, 1.8e19, 0, WHOLE | READ_ONLY},
    {DEMILL_WORLD_PARTICLE_COUNT, "world.particle_count", "1", 0, 4.3e9, 0, WHOLE | READ_ONLY},
    {DEMILL_WORLD_CONTACT_COUNT, "world.contact_count", "1", 0, 1.8e19, 0, WHOLE | READ_ONLY},
    {DEMILL_WORLD_WALL_CONTACT_COUNT, "world.wall_contact_count", "1", 0, 1.8e19, 0,
     WHOLE | READ_ONLY},
    {DEMILL_WORLD_NEIGHBOUR_REBUILDS, "world.neighbour_rebuilds", "1", 0, 1.8e19, 0,
     WHOLE | READ_ONLY},
    {DEMILL_WORLD_REFINE_ITERATIONS, "world.refine_iterations", "1", 0, 100, 0, WHOLE | READ_ONLY},
    {DEMILL_WORLD_FORCE_EVALUATIONS, "world.force_evaluations", "1", 0, 1.8e19, 0,
     WHOLE | READ_ONLY},
    {DEMILL_WORLD_REFINE_UNCONVERGED, "world.refine_unconverged", "1", 0, 1.8e19, 0,
     WHOLE | READ_ONLY},

    {DEMILL_MATERIAL_DENSITY, "material.density", "kg/m^3", 0, 1e30, 2500, OPEN_LO},
    {DEMILL_MATERIAL_YOUNGS_MODULUS, "material.youngs_modulus", "Pa", 1e-100, 1e30, 1e8, 0},
    {DEMILL_MATERIAL_POISSON_RATIO, "material.poisson_ratio", "1", 0, 0.5, 0.3, OPEN_HI},
    {DEMILL_MATERIAL_STIFFNESS, "material.stiffness", "N/m", 1e-100, 1e30, 1e5, 0},
    {DEMILL_MATERIAL_RESTITUTION, "material.restitution", "1", 0, 1, 0.5, 0},
    {DEMILL_MATERIAL_FRICTION, "material.friction", "1", 0, 1e6, 0.5, 0},
    {DEMILL_MATERIAL_ROLLING_FRICTION, "material.rolling_friction", "1", 0, 1e6, 0, 0},
    {DEMILL_MATERIAL_YIELD_STRESS, "material.yield_stress", "Pa", 0, 1e30, 0, 0},
    {DEMILL_MATERIAL_LOCAL_DAMPING, "material.local_damping", "1", 0, 1, 0, OPEN_HI},
    {DEMILL_MATERIAL_RIGID, "material.rigid", "bool", 0, 1, 0, WHOLE},
    {DEMILL_MATERIAL_SURFACE_ENERGY, "material.surface_energy", "J/m^2", 0, 1e6, 0, 0},

    {DEMILL_PAIR_NORMAL, "pair.normal", "enum", 0, 5, 0, WHOLE},
    {DEMILL_PAIR_DAMPING, "pair.damping", "enum", 0, 2, 0, WHOLE},
    {DEMILL_PAIR_TANGENTIAL, "pair.tangential", "enum", 0, 3, 0, WHOLE},
    {DEMILL_PAIR_ROLLING, "pair.rolling", "enum", 0, 2, 0, WHOLE},
    {DEMILL_PAIR_COHESION, "pair.cohesion", "enum", 0, 2, 0, WHOLE},
    {DEMILL_PAIR_RESTITUTION, "pair.restitution", "1", 0, 1, 0.5, 0},
    {DEMILL_PAIR_FRICTION, "pair.friction", "1", 0, 1e6, 0.5, 0},
    {DEMILL_PAIR_ROLLING_FRICTION, "pair.rolling_friction", "1", 0, 1e6, 0, 0},
    {DEMILL_PAIR_NORMAL_STIFFNESS, "pair.normal_stiffness", "N/m", 0, 1e30, 5e4, OPEN_LO},
    {DEMILL_PAIR_VISCOUS_DAMPING, "pair.viscous_damping", "N s/m", 0, 1e30, 0, 0},
    {DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, "pair.tangential_stiffness_ratio", "1", 0, 1e6,
     2.0 / 7.0, OPEN_LO},
    {DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR, "pair.tangential_damping_factor", "1", 0, 1e6, 1, 0},
    {DEMILL_PAIR_COULOMB_REGULARISATION, "pair.coulomb_regularisation", "1", 0, 1e6, 1, OPEN_LO},
    {DEMILL_PAIR_ROLLING_REGULARISATION, "pair.rolling_regularisation", "1", 0, 1e6, 1, OPEN_LO},
    {DEMILL_PAIR_CLAMP_NORMAL, "pair.clamp_normal", "bool", 0, 1, 1, WHOLE},
    {DEMILL_PAIR_YIELD_PRESSURE, "pair.yield_pressure", "Pa", 0, 1e30, 0, 0},
    {DEMILL_PAIR_PLASTIC_FIT_C0, "pair.plastic_fit_c0", "1", -1e30, 1e30, 54.95, 0},
    {DEMILL_PAIR_PLASTIC_FIT_C1, "pair.plastic_fit_c1", "1/m", -1e30, 1e30, -2889, 0},
    {DEMILL_PAIR_PLASTIC_FIT_C2, "pair.plastic_fit_c2", "1/m^2", -1e30, 1e30, 88478, 0},
    {DEMILL_PAIR_PLASTIC_FIT_EXPONENT, "pair.plastic_fit_exponent", "1", 0, 3, 1,
     OPEN_LO | OPEN_HI},
    {DEMILL_PAIR_ROLLING_STIFFNESS, "pair.rolling_stiffness", "N m/rad", 0, 1e30, 0, 0},
    {DEMILL_PAIR_ROLLING_DAMPING_RATIO, "pair.rolling_damping_ratio", "1", 0, 1e6, 0.3, 0},
    {DEMILL_PAIR_ADHESION_WORK, "pair.adhesion_work", "J/m^2", 0, 1e6, 0, 0},
    {DEMILL_PAIR_LIQUID_VOLUME, "pair.liquid_volume", "m^3", 0, 1, 1e-12, OPEN_LO},
    {DEMILL_PAIR_SURFACE_TENSION, "pair.surface_tension", "N/m", 0, 1e6, 0.072, 0},
    {DEMILL_PAIR_CONTACT_ANGLE, "pair.contact_angle", "rad", 0, 1.57079632679489662, 0, 0},

    {DEMILL_DRUM_DIAMETER, "drum.diameter", "m", 0, 1e6, 0.3, OPEN_LO},
    {DEMILL_DRUM_LENGTH, "drum.length", "m", 0, 1e6, 0.1, OPEN_LO},
    {DEMILL_DRUM_LIFTERS, "drum.lifters", "1", 0, 64, 0, WHOLE},
    {DEMILL_DRUM_LIFTER_HEIGHT, "drum.lifter_height", "m", 0, 1e6, 0.015, 0},
    {DEMILL_DRUM_LIFTER_WIDTH, "drum.lifter_width", "m", 0, 1e6, 0.015, OPEN_LO},
    {DEMILL_DRUM_LIFTER_FACE_ANGLE, "drum.lifter_face_angle", "rad", 0, 1.4, 0, 0},
    {DEMILL_DRUM_LIFTER_PHASE, "drum.lifter_phase", "rad", -1e6, 1e6, 4.71238898038468986, 0},
    {DEMILL_DRUM_SPEED, "drum.speed", "rad/s", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_SPEED_RPM, "drum.speed_rpm", "1/min", -1e7, 1e7, 0, 0},
    {DEMILL_DRUM_SPEED_FRACTION, "drum.speed_fraction", "1", -100, 100, 0, 0},
    {DEMILL_DRUM_RAMP_TIME, "drum.ramp_time", "s", 0, 1e9, 0, 0},
    {DEMILL_DRUM_CRITICAL_DIAMETER, "drum.critical_diameter", "m", 0, 1e6, 0, 0},
    {DEMILL_DRUM_FILL_POROSITY, "drum.fill_porosity", "1", 0, 0.9, 0.4, 0},
    {DEMILL_DRUM_SAMPLE_INTERVAL, "drum.sample_interval", "1", 1, 1e9, 100, WHOLE},
    {DEMILL_DRUM_SHELL, "drum.shell", "1", 0, 1, 1, WHOLE},
    {DEMILL_DRUM_CENTER_X, "drum.center_x", "m", -1e9, 1e9, 0, 0},
    {DEMILL_DRUM_CENTER_Y, "drum.center_y", "m", -1e9, 1e9, 0, 0},
    {DEMILL_DRUM_CENTER_Z, "drum.center_z", "m", -1e9, 1e9, 0, 0},
    {DEMILL_DRUM_VELOCITY_X, "drum.velocity_x", "m/s", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VELOCITY_Y, "drum.velocity_y", "m/s", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VELOCITY_Z, "drum.velocity_z", "m/s", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VIBRATION_X, "drum.vibration_x", "m", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VIBRATION_Y, "drum.vibration_y", "m", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VIBRATION_Z, "drum.vibration_z", "m", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_VIBRATION_FREQUENCY, "drum.vibration_frequency", "Hz", 0, 1e9, 0, 0},
    {DEMILL_DRUM_VIBRATION_PHASE, "drum.vibration_phase", "rad", -1e6, 1e6, 0, 0},
    {DEMILL_DRUM_CRITICAL_SPEED, "drum.critical_speed", "rad/s", 0, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_CURRENT_SPEED, "drum.current_speed", "rad/s", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_ANGLE, "drum.angle", "rad", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_REVOLUTIONS, "drum.revolutions", "1", 0, 1.8e19, 0, WHOLE | READ_ONLY},
    {DEMILL_DRUM_TORQUE, "drum.torque", "N m", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_POWER, "drum.power", "W", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_POWER_MEAN, "drum.power_mean", "W", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_POWER_CM, "drum.power_cm", "W", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_POWER_CM_MEAN, "drum.power_cm_mean", "W", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_TOE_ANGLE, "drum.toe_angle", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_SHOULDER_ANGLE, "drum.shoulder_angle", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_COM_ANGLE, "drum.com_angle", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_TOE_ANGLE_MEAN, "drum.toe_angle_mean", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_SHOULDER_ANGLE_MEAN, "drum.shoulder_angle_mean", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_COM_ANGLE_MEAN, "drum.com_angle_mean", "rad", -7, 7, 0, READ_ONLY},
    {DEMILL_DRUM_ENERGY_IN, "drum.energy_in", "J", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_ENERGY_DISSIPATED, "drum.energy_dissipated", "J", 0, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_DISSIPATION_MEAN, "drum.dissipation_mean", "W", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_LIFTER_COUNT, "drum.lifter_count", "1", 0, 64, 0, WHOLE | READ_ONLY},
    {DEMILL_DRUM_FORCE_X, "drum.force_x", "N", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_FORCE_Y, "drum.force_y", "N", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_FORCE_Z, "drum.force_z", "N", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_CURRENT_VELOCITY_X, "drum.current_velocity_x", "m/s", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_CURRENT_VELOCITY_Y, "drum.current_velocity_y", "m/s", -1e300, 1e300, 0, READ_ONLY},
    {DEMILL_DRUM_CURRENT_VELOCITY_Z, "drum.current_velocity_z", "m/s", -1e300, 1e300, 0, READ_ONLY},
};

static const param_info *find(int32_t key)
{
    for (size_t i = 0; i < sizeof params / sizeof params[0]; i++)
        if (params[i].key == key)
            return &params[i];
    return NULL;
}

DEMILL_API const char *demill_param_name(int32_t key)
{
    const param_info *p = find(key);
    return p ? p->name : NULL;
}

DEMILL_API const char *demill_param_unit(int32_t key)
{
    const param_info *p = find(key);
    return p ? p->unit : NULL;
}

DEMILL_API demill_status demill_param_bounds(int32_t key, double *lo, double *hi,
                                             double *default_value)
{
    const param_info *p = find(key);
    if (!p)
        return DEMILL_ERR_UNKNOWN_KEY;
    if (lo)
        *lo = p->flags & OPEN_LO ? nextafter(p->lo, HUGE_VAL) : p->lo;
    if (hi)
        *hi = p->flags & OPEN_HI ? nextafter(p->hi, -HUGE_VAL) : p->hi;
    if (default_value)
        *default_value = p->def;
    return DEMILL_OK;
}

/* Checks a value for a settable key: known, writable, finite, in bounds and
 * whole where a choice is expected. Sets the world's message on failure. */
demill_status dm_check_value(demill_world *w, int32_t key, double value)
{
    const param_info *p = find(key);
    if (!p)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "unknown parameter key %d", (int)key);
    if (p->flags & READ_ONLY)
        return dm_fail(w, DEMILL_ERR_READ_ONLY, "%s is read-only", p->name);
    if (!isfinite(value))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: value %g is not finite", p->name, value);
    bool below = p->flags & OPEN_LO ? value <= p->lo : value < p->lo;
    bool above = p->flags & OPEN_HI ? value >= p->hi : value > p->hi;
    if (p->flags & WHOLE && value != floor(value))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %.17g is not a whole number", p->name,
                       value);
    if (p->flags & WHOLE && (below || above))
        return dm_fail(w, strcmp(p->unit, "enum") ? DEMILL_ERR_INVALID_VALUE : DEMILL_ERR_UNKNOWN_KEY,
                       "%s: %.17g is not one of the allowed values %g..%g", p->name, value, p->lo,
                       p->hi);
    if (below || above)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: %.17g is outside %s%g, %g%s", p->name,
                       value, p->flags & OPEN_LO ? "(" : "[", p->lo, p->hi,
                       p->flags & OPEN_HI ? ")" : "]");
    return DEMILL_OK;
}
