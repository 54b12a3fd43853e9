/* threads.h: the world's own worker threads, and loops over particles
 * shared out on them. */
#ifndef DM_THREADS_H
#define DM_THREADS_H

#include "base/base.h"

#define DM_MAX_THREADS 1024 /* the most threads, and the most ranges of a loop */
typedef void (*dm_range_fn)(demill_world *w, void *arg, int t, uint32_t begin, uint32_t end);
/* The threads a world may have when it asks for `requested`. */
int dm_threads_available(int requested);
/* Stops the world's workers (they start again when a loop is shared out). */
void dm_threads_free(demill_world *w);
/* The number of ranges dm_parallel() splits [0, n) into. */
int dm_ranges(const demill_world *w, uint32_t n);
/* Runs fn over [0, n) in dm_ranges() ranges; returns the number of ranges. */
int dm_parallel(demill_world *w, uint32_t n, dm_range_fn fn, void *arg);

#endif /* DM_THREADS_H */
