/* handles.c: generation-counted ids, the handle tables behind them, and the
 * world tags that keep the ids of two live worlds apart. */
#include <stdatomic.h>
#include <stdlib.h>

#include "base/handles.h"

demill_id dm_id_make(uint16_t tag, int kind, uint16_t gen, uint32_t index)
{
    return ((uint64_t)(tag & 0xfffu) << 52) | ((uint64_t)kind << 48) | ((uint64_t)gen << 32) |
           index;
}

DEMILL_API int32_t demill_id_kind(demill_id id)
{
    int k = DM_ID_KIND(id);
    return k >= DEMILL_KIND_MATERIAL && k <= DEMILL_KIND_CLUMP ? k : DEMILL_KIND_NONE;
}

/* ---- world tags ------------------------------------------------------------ */
/* A world's ids carry its 12-bit tag. The tags of live worlds are marked in
 * a bitmap, the only state the library shares between worlds, so that no two
 * live worlds ever share one; new worlds take the tags round-robin, so that a
 * destroyed world's tag is given out again only after all the others. */
static atomic_uint_fast64_t tags_in_use[DM_WORLD_TAGS / 64];
static atomic_uint tag_cursor;

int dm_tag_claim(uint16_t *tag)
{
    const unsigned start = atomic_fetch_add(&tag_cursor, 1u);
    for (unsigned k = 0; k < DM_WORLD_TAGS; k++) {
        const unsigned t = (start + k) % DM_WORLD_TAGS;
        const uint_fast64_t bit = (uint_fast64_t)1 << (t % 64);
        if (!(atomic_fetch_or(&tags_in_use[t / 64], bit) & bit)) {
            *tag = (uint16_t)t;
            return 0;
        }
    }
    return -1;
}

void dm_tag_release(uint16_t tag)
{
    atomic_fetch_and(&tags_in_use[tag / 64], ~((uint_fast64_t)1 << (tag % 64)));
}

/* ---- handle tables ------------------------------------------------------------ */

/* Grows the table so that `extra` more handles can be issued without
 * allocating. Returns 0 on success; on failure the table is unchanged. */
int dm_handles_reserve(dm_handles *h, uint32_t extra)
{
    uint64_t need = (uint64_t)h->n + extra;
    if (extra <= h->nfree || need <= h->cap)
        return 0;
    if (need > UINT32_MAX - 1)
        return -1;
    uint32_t cap = h->cap ? h->cap : 64;
    while (cap < need)
        cap = cap > UINT32_MAX / 2 ? UINT32_MAX - 1 : cap * 2;
    uint32_t *slot = realloc(h->slot, (size_t)cap * sizeof *slot);
    if (!slot)
        return -1;
    h->slot = slot;
    uint16_t *gen = realloc(h->gen, (size_t)cap * sizeof *gen);
    if (!gen)
        return -1;
    h->gen = gen;
    uint32_t *fr = realloc(h->free, (size_t)cap * sizeof *fr);
    if (!fr)
        return -1;
    h->free = fr;
    h->cap = cap;
    return 0;
}

/* Issues a handle pointing at `slot` (capacity must have been reserved). */
uint32_t dm_handles_issue(dm_handles *h, uint32_t slot)
{
    uint32_t index;
    if (h->nfree) {
        index = h->free[--h->nfree];
    } else {
        index = h->n++;
        h->gen[index] = 0;
    }
    h->slot[index] = slot;
    return index;
}

/* Releases a handle; its generation moves on so old ids stop matching. A
 * handle whose generation would wrap round is retired instead: it is never
 * issued again, so that no id ever names two objects. */
void dm_handles_release(dm_handles *h, uint32_t index)
{
    h->slot[index] = DM_FREE;
    if (h->gen[index] == DM_GEN_LAST)
        return;
    h->gen[index]++;
    h->free[h->nfree++] = index;
}

void dm_handles_free(dm_handles *h)
{
    free(h->slot);
    free(h->gen);
    free(h->free);
}
