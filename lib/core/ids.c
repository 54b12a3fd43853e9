/* ids.c: generation-counted ids, the handle tables behind them, and the
 * world tags that keep the ids of two live worlds apart. */
#include <stdatomic.h>
#include <stdlib.h>

#include "internal.h"

#define ID_INDEX(id) ((uint32_t)((id) & 0xffffffffu))
#define ID_GEN(id) ((uint16_t)(((id) >> 32) & 0xffffu))
#define ID_KIND(id) ((int)(((id) >> 48) & 0xfu))
#define ID_TAG(id) ((uint16_t)(((id) >> 52) & 0xfffu))

demill_id dm_id_make(uint16_t tag, int kind, uint16_t gen, uint32_t index)
{
    return ((uint64_t)(tag & 0xfffu) << 52) | ((uint64_t)kind << 48) | ((uint64_t)gen << 32) |
           index;
}

DEMILL_API int32_t demill_id_kind(demill_id id)
{
    int k = ID_KIND(id);
    return k >= DEMILL_KIND_MATERIAL && k <= DEMILL_KIND_DRUM ? k : DEMILL_KIND_NONE;
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

static const char *kind_name(int kind)
{
    switch (kind) {
    case DEMILL_KIND_MATERIAL: return "material";
    case DEMILL_KIND_PARTICLE: return "particle";
    case DEMILL_KIND_WALL: return "wall";
    case DEMILL_KIND_DRUM: return "drum";
    default: return "unknown";
    }
}

/* Checks that `id` names a live object of `kind` in world w and returns its
 * storage slot (particles: storage index; walls: wall slot; materials: index).
 * `what` names the argument in the error message. */
demill_status dm_resolve(const demill_world *cw, demill_id id, int kind, const char *what,
                         uint32_t *slot)
{
    demill_world *w = (demill_world *)cw; /* the error message is mutable state */
    if (id == DEMILL_ID_NONE)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: DEMILL_ID_NONE is not a %s id", what,
                       kind_name(kind));
    if (ID_KIND(id) != kind)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: id 0x%llx is a %s id, expected a %s id",
                       what, (unsigned long long)id, kind_name(ID_KIND(id)), kind_name(kind));
    if (ID_TAG(id) != w->tag)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                       "%s: %s id 0x%llx belongs to another world", what, kind_name(kind),
                       (unsigned long long)id);
    uint32_t index = ID_INDEX(id);
    if (kind == DEMILL_KIND_DRUM) {
        if (!w->drum.alive || index != 0 || ID_GEN(id) != w->drum_gen)
            return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                           "%s: drum id 0x%llx was removed or never existed", what,
                           (unsigned long long)id);
        *slot = 0;
        return DEMILL_OK;
    }
    if (kind == DEMILL_KIND_MATERIAL) {
        if (index >= w->nmat || ID_GEN(id) != 0)
            return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: no material with id 0x%llx", what,
                           (unsigned long long)id);
        *slot = index;
        return DEMILL_OK;
    }
    const dm_handles *h = kind == DEMILL_KIND_PARTICLE ? &w->ph : &w->wh;
    if (index >= h->n || h->slot[index] == DM_FREE || h->gen[index] != ID_GEN(id))
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                       "%s: %s id 0x%llx was removed or never existed", what, kind_name(kind),
                       (unsigned long long)id);
    *slot = h->slot[index];
    return DEMILL_OK;
}

demill_id dm_particle_id(const demill_world *w, uint32_t storage)
{
    uint32_t h = w->p.hid[storage];
    return dm_id_make(w->tag, DEMILL_KIND_PARTICLE, w->ph.gen[h], h);
}

/* The id of a wall slot: the wall's own id, or the drum's for its walls. */
demill_id dm_wall_id(const demill_world *w, uint32_t wall_slot)
{
    if (w->walls[wall_slot].drum_part)
        return dm_drum_id(w);
    uint32_t h = w->walls[wall_slot].handle;
    return dm_id_make(w->tag, DEMILL_KIND_WALL, w->wh.gen[h], h);
}

demill_id dm_drum_id(const demill_world *w)
{
    return dm_id_make(w->tag, DEMILL_KIND_DRUM, w->drum_gen, 0);
}

demill_id dm_material_id(const demill_world *w, uint32_t material)
{
    return dm_id_make(w->tag, DEMILL_KIND_MATERIAL, 0, material);
}

/* The entry check of an API function that names an object: the world is a
 * live world and id names a live object of `kind` in it. */
demill_status dm_enter(const demill_world *w, demill_id id, int kind, const char *what,
                       uint32_t *slot)
{
    demill_status s = dm_check_world(w);
    return s ? s : dm_resolve(w, id, kind, what, slot);
}
