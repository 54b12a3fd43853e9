/* alloc.h: growing sets of parallel arrays, all or none. */
#ifndef DM_ALLOC_H
#define DM_ALLOC_H

#include <stddef.h>

/* Grows every arrays[k] (of element size sizes[k]) to cap elements; on
 * failure (0) none has moved. */
int dm_grow_arrays(void **const *arrays, const size_t *sizes, size_t n, size_t cap);
/* A capacity of at least need, grown geometrically from cap. */
size_t dm_grown_capacity(size_t cap, size_t need);

#endif /* DM_ALLOC_H */
