/* world.c: creating, configuring and destroying a world. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

static double param_default(int32_t key)
{
    double d = 0.0;
    demill_param_bounds(key, NULL, NULL, &d);
    return d;
}

DEMILL_API demill_status demill_world_create(int32_t dimension, demill_world **out)
{
    if (!out)
        return DEMILL_ERR_NULL_POINTER;
    *out = NULL;
    if (dimension != 2 && dimension != 3)
        return DEMILL_ERR_INVALID_VALUE;
    demill_world *w = calloc(1, sizeof *w);
    if (!w)
        return DEMILL_ERR_OUT_OF_MEMORY;
    if (dm_tag_claim(&w->tag)) {
        free(w);
        return DEMILL_ERR_LIMIT;
    }
    w->base.magic = DM_WORLD_MAGIC;
    w->dim = dimension;
    w->dt = param_default(DEMILL_WORLD_TIME_STEP);
    w->g[0] = param_default(DEMILL_WORLD_GRAVITY_X);
    w->g[1] = param_default(DEMILL_WORLD_GRAVITY_Y);
    w->g[2] = param_default(DEMILL_WORLD_GRAVITY_Z);
    w->integrator = (int)param_default(DEMILL_WORLD_INTEGRATOR);
    w->skin_fraction = param_default(DEMILL_WORLD_SKIN);
    w->energy_tracking = (int)param_default(DEMILL_WORLD_ENERGY_TRACKING);
    w->base.threads = (int)param_default(DEMILL_WORLD_THREADS);
    w->refine_tol = param_default(DEMILL_WORLD_REFINE_TOLERANCE);
    w->refine_max = (int)param_default(DEMILL_WORLD_REFINE_MAX_ITERATIONS);
    w->watchdog = (int)param_default(DEMILL_WORLD_WATCHDOG);
    w->watch_overlap = param_default(DEMILL_WORLD_WATCHDOG_OVERLAP);
    w->watch_interval = (uint32_t)param_default(DEMILL_WORLD_WATCHDOG_INTERVAL);
    w->single = param_default(DEMILL_WORLD_SINGLE_PRECISION) != 0.0;
    w->orient = param_default(DEMILL_WORLD_ORIENTATION_TRACKING) != 0.0;
    w->ptab_dirty = true;
    dm_clist_clear(w);
    *out = w;
    return DEMILL_OK;
}

DEMILL_API void demill_world_destroy(demill_world *w)
{
    if (dm_check_world(w))
        return;
    dm_threads_free(w);
    dm_particles_free(w);
    dm_clists_free(w);
    dm_nlist_free(w);
    dm_results_free(w);
    dm_spectrum_free(w);
    dm_refine_free(w);
    dm_watch_free(w);
    dm_handles_free(&w->wh);
    dm_handles_free(&w->bh);
    dm_handles_free(&w->clh);
    dm_walls_free_owned(w);
    free(w->walls);
    free(w->bodies);
    free(w->templates);
    free(w->tmem);
    free(w->clumps);
    free(w->cmem);
    free(w->pairs);
    free(w->ptab);
    dm_tag_release(w->tag);
    w->base.magic = 0;
    free(w);
}

/* The threads the loops run on: n, or for 0 OMP_NUM_THREADS or one per
 * processor (threads.c). */
static demill_status set_threads(demill_world *w, int n)
{
    int t = dm_threads_available(n);
    if (!t)
        return dm_fail(w, DEMILL_ERR_UNSUPPORTED,
                       "world.threads = %d: the library was built without threads", n);
    t = t < DM_MAX_THREADS ? t : DM_MAX_THREADS;
    if (t != w->base.threads)
        dm_threads_free(w); /* workers are started again for the new count */
    w->base.threads = t;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_world_set(demill_world *w, int32_t key, double value)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (key < 100 || key > 199)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "world_set: %d is not a world key", (int)key);
    if ((s = dm_check_value(w, key, value)))
        return s;
    switch (key) {
    case DEMILL_WORLD_TIME_STEP: w->dt = value; break;
    case DEMILL_WORLD_GRAVITY_X: w->g[0] = value; break;
    case DEMILL_WORLD_GRAVITY_Y: w->g[1] = value; break;
    case DEMILL_WORLD_GRAVITY_Z:
        if (w->dim == 2 && value != 0.0)
            return dm_fail(w, DEMILL_ERR_DIMENSION, "world.gravity_z must be 0 in a 2D world");
        w->g[2] = value;
        break;
    case DEMILL_WORLD_INTEGRATOR: w->integrator = (int)value; break;
    case DEMILL_WORLD_SKIN:
        w->skin_fraction = value;
        w->nlist_valid = false;
        break;
    case DEMILL_WORLD_DISC_THICKNESS:
        if (w->dim == 3)
            return dm_fail(w, DEMILL_ERR_DIMENSION, "world.disc_thickness applies to 2D worlds only");
    {
        const double old = w->disc_thickness;
        w->disc_thickness = value;
        if ((s = dm_masses_update(w, DM_ALL_MATERIALS, "world.disc_thickness"))) {
            w->disc_thickness = old;
            return s;
        }
        break;
    }
    case DEMILL_WORLD_ENERGY_TRACKING: w->energy_tracking = (int)value; break;
    case DEMILL_WORLD_SINGLE_PRECISION: w->single = value != 0.0; break;
    case DEMILL_WORLD_ORIENTATION_TRACKING: w->orient = value != 0.0; break;
    case DEMILL_WORLD_THREADS: /* changes no result */
        if ((s = set_threads(w, (int)value)))
            return s;
        dm_changed(w);
        return DEMILL_OK;
    case DEMILL_WORLD_REFINE_TOLERANCE: /* these affect the next steps only */
    case DEMILL_WORLD_REFINE_MAX_ITERATIONS:
    case DEMILL_WORLD_WATCHDOG:
    case DEMILL_WORLD_WATCHDOG_OVERLAP:
    case DEMILL_WORLD_WATCHDOG_INTERVAL:
        if (key == DEMILL_WORLD_REFINE_TOLERANCE)
            w->refine_tol = value;
        else if (key == DEMILL_WORLD_REFINE_MAX_ITERATIONS)
            w->refine_max = (int)value;
        else if (key == DEMILL_WORLD_WATCHDOG)
            w->watchdog = (int)value;
        else if (key == DEMILL_WORLD_WATCHDOG_OVERLAP)
            w->watch_overlap = value;
        else
            w->watch_interval = (uint32_t)value;
        dm_changed(w);
        return DEMILL_OK;
    case DEMILL_WORLD_TIME:
        dm_walls_retime(w, value);
        w->drum.t_set += value - w->time; /* the drum keeps its angle and speed, */
        w->drum.t_move += value - w->time; /* its centre and velocity */
        w->drum.rev.t0 += value - w->time;
        w->time = value;
        break;
    }
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_world_get(const demill_world *cw, int32_t key, double *value)
{
    demill_world *w = (demill_world *)cw;
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_get: value is NULL");
    switch (key) {
    case DEMILL_WORLD_TIME_STEP: *value = w->dt; break;
    case DEMILL_WORLD_GRAVITY_X: *value = w->g[0]; break;
    case DEMILL_WORLD_GRAVITY_Y: *value = w->g[1]; break;
    case DEMILL_WORLD_GRAVITY_Z: *value = w->g[2]; break;
    case DEMILL_WORLD_INTEGRATOR: *value = w->integrator; break;
    case DEMILL_WORLD_SKIN: *value = w->skin_fraction; break;
    case DEMILL_WORLD_DISC_THICKNESS: *value = w->disc_thickness; break;
    case DEMILL_WORLD_ENERGY_TRACKING: *value = w->energy_tracking; break;
    case DEMILL_WORLD_TIME: *value = w->time; break;
    case DEMILL_WORLD_THREADS: *value = w->base.threads; break;
    case DEMILL_WORLD_REFINE_TOLERANCE: *value = w->refine_tol; break;
    case DEMILL_WORLD_REFINE_MAX_ITERATIONS: *value = w->refine_max; break;
    case DEMILL_WORLD_WATCHDOG: *value = w->watchdog; break;
    case DEMILL_WORLD_WATCHDOG_OVERLAP: *value = w->watch_overlap; break;
    case DEMILL_WORLD_WATCHDOG_INTERVAL: *value = w->watch_interval; break;
    case DEMILL_WORLD_SINGLE_PRECISION: *value = w->single; break;
    case DEMILL_WORLD_ORIENTATION_TRACKING: *value = w->orient; break;
    case DEMILL_WORLD_DIMENSION: *value = w->dim; break;
    case DEMILL_WORLD_STEP_COUNT: *value = (double)w->base.steps; break;
    case DEMILL_WORLD_PARTICLE_COUNT: *value = w->p.n; break;
    case DEMILL_WORLD_CONTACT_COUNT: *value = w->ncontacts; break;
    case DEMILL_WORLD_WALL_CONTACT_COUNT: *value = w->nwall_contacts; break;
    case DEMILL_WORLD_NEIGHBOUR_REBUILDS: *value = (double)w->rebuilds; break;
    case DEMILL_WORLD_REFINE_ITERATIONS: *value = w->iterations_last; break;
    case DEMILL_WORLD_FORCE_EVALUATIONS: *value = (double)w->force_evals; break;
    case DEMILL_WORLD_REFINE_UNCONVERGED: *value = (double)w->unconverged; break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "world_get: %d is not a world key", (int)key);
    }
    return DEMILL_OK;
}
