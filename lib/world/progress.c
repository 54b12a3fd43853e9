/* progress.c: the progress callback (demill_world_set_progress). A run with
 * a callback is a series of ordinary runs (dm_run_steps, under the watchdog
 * when it is on) of the callback's interval, with a report after each. The
 * integrators give bitwise the same state however a run is split, and the
 * watchdog's countdown carries over from one stretch to the next, so the
 * reports change nothing. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <time.h>

#include "world/world.h"

DEMILL_API demill_status demill_world_set_progress(demill_world *w, demill_progress_fn fn,
                                                   void *user_data, uint64_t every_steps)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (fn && !every_steps)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_set_progress: every_steps must be >= 1 with a callback");
    w->progress = fn ? (dm_progress){fn, user_data, every_steps} : (dm_progress){0};
    dm_changed(w);
    return DEMILL_OK;
}

static double seconds_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0->tv_sec) + 1e-9 * (double)(t.tv_nsec - t0->tv_nsec);
}

/* Runs `steps` steps of a prepared world, reporting to its callback. */
demill_status dm_progress_steps(demill_world *w, uint64_t steps)
{
    const dm_progress p = w->progress; /* a change made by the callback waits for the next run */
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (uint64_t done = 0; done < steps;) {
        const uint64_t n = steps - done < p.every ? steps - done : p.every;
        demill_status s = dm_run_steps(w, n);
        if (s)
            return s;
        done += n;
        const double wall = seconds_since(&t0);
        const uint64_t edits = w->base.edits;
        const int32_t stop = p.fn(p.user, done, steps, w->time, wall > 0.0 ? done / wall : 0.0);
        if (done == steps)
            break;
        if (stop)
            return dm_fail(w, DEMILL_ERR_INTERRUPTED,
                           "world_step: the progress callback stopped the run after %llu of "
                           "its %llu steps, at the world's step %llu, t = %.9g s",
                           (unsigned long long)done, (unsigned long long)steps,
                           (unsigned long long)w->base.steps, w->time);
        /* the callback changed the world: the rest is a new run */
        if (w->base.edits != edits && (s = dm_prepare_step(w)))
            return s;
    }
    return DEMILL_OK;
}
