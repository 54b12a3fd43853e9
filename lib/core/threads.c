/* threads.c: running a loop over particles on the world's threads. */
#ifdef _OPENMP
#include <omp.h>
#endif

#include "internal.h"

/* Fewer particles than this per thread are not worth sharing out. */
#define MIN_PER_THREAD 512

int dm_threads_available(int requested)
{
#ifdef _OPENMP
    return requested ? requested : omp_get_max_threads();
#else
    return requested > 1 ? 0 : 1;
#endif
}

/* The number of ranges dm_parallel() splits [0, n) into. */
int dm_ranges(const demill_world *w, uint32_t n)
{
    const uint32_t most = n / MIN_PER_THREAD;
    return most <= 1 ? 1 : (uint32_t)w->threads < most ? w->threads : (int)most;
}

/* Calls fn(w, arg, t, begin, end) for ranges t = 0 .. ranges - 1 that split
 * [0, n) into equal parts, on the world's threads; returns the number of
 * ranges (at most DM_MAX_THREADS). Loops with results per range write them
 * to arg at index t, to be combined in range order. */
int dm_parallel(demill_world *w, uint32_t n, dm_range_fn fn, void *arg)
{
    const int ranges = dm_ranges(w, n);
    if (ranges == 1) {
        fn(w, arg, 0, 0, n);
        return 1;
    }
    DM_OMP("omp parallel for schedule(static) num_threads(ranges)")
    for (int t = 0; t < ranges; t++)
        fn(w, arg, t, (uint32_t)((uint64_t)n * t / ranges),
           (uint32_t)((uint64_t)n * (t + 1) / ranges));
    return ranges;
}
