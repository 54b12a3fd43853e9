/* step.c: demill_world_step(): a run prepared, then stepped under the
 * progress callback and the watchdog when they are set (the steps
 * themselves: lib/physics/integrate, with feeds and outlets: flows.c). */
#include "world/world.h"

/* Steps a prepared world, under the watchdog when it is on; without it, a
 * run that leaves the state not finite still fails (where it is). */
demill_status dm_run_steps(demill_world *w, uint64_t steps)
{
    if (w->watchdog)
        return dm_watched_steps(w, steps);
    demill_status s = dm_advance(w, steps);
    return s || !steps ? s : dm_check_finite(w);
}

DEMILL_API demill_status demill_world_step(demill_world *w, uint64_t steps)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    w->watch.call_start = w->base.steps;
    if ((s = dm_prepare_step(w)) ||
        (s = w->progress.fn ? dm_progress_steps(w, steps) : dm_run_steps(w, steps)))
        return s;
    dm_clear_error(w);
    return DEMILL_OK;
}
