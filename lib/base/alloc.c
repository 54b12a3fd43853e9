/* alloc.c: growing the parallel arrays that hold per-particle and per-pair
 * data, all or nothing as far as the caller can tell. */
#include <stdlib.h>

#include "base/alloc.h"

/* Reallocates each of the n arrays *arrays[k] to hold cap elements of
 * sizes[k] bytes. Returns 0, or -1 when an allocation fails; arrays already
 * grown keep their contents and are merely larger, so the caller's state
 * stays valid either way. */
int dm_grow_arrays(void **const *arrays, const size_t *sizes, size_t n, size_t cap)
{
    for (size_t k = 0; k < n; k++) {
        /* never 0 bytes: realloc(p, 0) may free p and return NULL */
        const size_t bytes = cap * sizes[k];
        void *q = realloc(*arrays[k], bytes ? bytes : 1);
        if (!q)
            return -1;
        *arrays[k] = q;
    }
    return 0;
}

/* The capacity to grow to for `need` elements: doubling from `cap` (or 64). */
size_t dm_grown_capacity(size_t cap, size_t need)
{
    size_t c = cap ? cap : 64;
    while (c < need)
        c *= 2;
    return c;
}
