/* ids.c: the ids of a world's objects: checking an id an API call is given
 * and finding its object's storage slot, and the ids of stored objects. */
#include <string.h>

#include "world/world.h"

static const char *kind_name(int kind)
{
    switch (kind) {
    case DEMILL_KIND_MATERIAL: return "material";
    case DEMILL_KIND_PARTICLE: return "particle";
    case DEMILL_KIND_WALL: return "wall";
    case DEMILL_KIND_DRUM: return "drum";
    case DEMILL_KIND_FEED: return "feed";
    case DEMILL_KIND_OUTLET: return "outlet";
    case DEMILL_KIND_BODY: return "body";
    case DEMILL_KIND_TEMPLATE: return "clump template";
    case DEMILL_KIND_CLUMP: return "clump";
    default: return "unknown";
    }
}

/* The indefinite article of the kind's name: "an" outlet, "a" wall. */
static const char *article(int kind)
{
    return strchr("aeiou", kind_name(kind)[0]) ? "an" : "a";
}

/* Checks that `id` names a live object of `kind` in world w and returns its
 * storage slot (particles: storage index; walls: wall slot; bodies and
 * clumps: their slot; materials and clump templates: index).
 * `what` names the argument in the error message. */
demill_status dm_resolve(const demill_world *cw, demill_id id, int kind, const char *what,
                         uint32_t *slot)
{
    demill_world *w = (demill_world *)cw; /* the error message is mutable state */
    if (id == DEMILL_ID_NONE)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: DEMILL_ID_NONE is not %s %s id", what,
                       article(kind), kind_name(kind));
    if (DM_ID_KIND(id) != kind)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: id 0x%llx is %s %s id, expected %s %s id",
                       what, (unsigned long long)id, article(DM_ID_KIND(id)),
                       kind_name(DM_ID_KIND(id)), article(kind), kind_name(kind));
    if (DM_ID_TAG(id) != w->tag)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                       "%s: %s id 0x%llx belongs to another world", what, kind_name(kind),
                       (unsigned long long)id);
    uint32_t index = DM_ID_INDEX(id);
    if (kind == DEMILL_KIND_DRUM) {
        if (!w->drum.alive || index != 0 || DM_ID_GEN(id) != w->drum_gen)
            return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                           "%s: drum id 0x%llx was removed or never existed", what,
                           (unsigned long long)id);
        *slot = 0;
        return DEMILL_OK;
    }
    if (kind == DEMILL_KIND_MATERIAL || kind == DEMILL_KIND_TEMPLATE) {
        if (index >= (kind == DEMILL_KIND_MATERIAL ? w->nmat : w->ntemplates) ||
            DM_ID_GEN(id) != 0)
            return dm_fail(w, DEMILL_ERR_INVALID_HANDLE, "%s: no %s with id 0x%llx", what,
                           kind_name(kind), (unsigned long long)id);
        *slot = index;
        return DEMILL_OK;
    }
    if (kind == DEMILL_KIND_FEED || kind == DEMILL_KIND_OUTLET) {
        const dm_flows *f = &w->flows;
        const bool feed = kind == DEMILL_KIND_FEED;
        const dm_flow_slot *o = index >= (feed ? f->nfeeds : f->noutlets) ? NULL
                                : feed ? &f->feeds[index].id
                                       : &f->outlets[index].id;
        if (!o || !o->alive || o->gen != DM_ID_GEN(id))
            return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                           "%s: %s id 0x%llx was removed or never existed", what,
                           kind_name(kind), (unsigned long long)id);
        *slot = index;
        return DEMILL_OK;
    }
    const dm_handles *h = kind == DEMILL_KIND_PARTICLE ? &w->ph
                          : kind == DEMILL_KIND_BODY   ? &w->bh
                          : kind == DEMILL_KIND_CLUMP  ? &w->clh
                                                       : &w->wh;
    if (index >= h->n || h->slot[index] == DM_FREE || h->gen[index] != DM_ID_GEN(id))
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

/* The id of a wall slot: the wall's own id (also when attached to the drum),
 * the drum's for the walls it built, a capped wall's for its caps. */
demill_id dm_wall_id(const demill_world *w, uint32_t wall_slot)
{
    if (w->walls[wall_slot].drum_part && !dm_wall_attached(&w->walls[wall_slot]))
        return dm_drum_id(w);
    if (w->walls[wall_slot].parent)
        wall_slot = w->walls[wall_slot].parent - 1;
    uint32_t h = w->walls[wall_slot].handle;
    return dm_id_make(w->tag, DEMILL_KIND_WALL, w->wh.gen[h], h);
}

demill_id dm_body_id(const demill_world *w, uint32_t slot)
{
    uint32_t h = w->bodies[slot].handle;
    return dm_id_make(w->tag, DEMILL_KIND_BODY, w->bh.gen[h], h);
}

demill_id dm_clump_id(const demill_world *w, uint32_t slot)
{
    uint32_t h = w->clumps[slot].handle;
    return dm_id_make(w->tag, DEMILL_KIND_CLUMP, w->clh.gen[h], h);
}

demill_id dm_template_id(const demill_world *w, uint32_t index)
{
    return dm_id_make(w->tag, DEMILL_KIND_TEMPLATE, 0, index);
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
