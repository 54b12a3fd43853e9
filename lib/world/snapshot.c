/* snapshot.c: a deep copy of a world's state, for the watchdog's last good
 * state (watchdog.c), snapshots and checkpoints (checkpoint.c).
 *
 * The copy holds everything a world is: parameters, materials and pairs,
 * particles in storage order, handles, walls with their meshes, bodies,
 * clumps and their templates, the drum, the contact lists with their
 * histories, tallies and counters. It leaves out what is derived
 * again before use (the neighbour grid's scratch, the per-pair results, the
 * wall-contact geometry, the refinement's scratch): the destination keeps its
 * own of those, and its results are marked stale; dm_state_restore() makes
 * them big enough for the copied lists. The destination keeps its progress
 * callback too: it is the host's, not state. */
#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

/* One buffer to copy: where its pointer lives in the new state, and its
 * size. */
typedef struct buffer {
    void **field;
    size_t bytes;
} buffer;

/* particles 20, handles 4 × 3, pairs, table, walls, bodies, clumps 4, spectrum 2, buckets 5
 * each */
#define MAX_BUFFERS (20 + 12 + 4 + 4 + 2 + 2 * DM_KERNELS * 5)

/* The buffers of state s (its pointers and sizes), into b; returns how many. */
static size_t buffers_of(demill_world *s, buffer *b)
{
    const size_t D = (size_t)s->dim, W = (size_t)dm_wdim(s), n = s->p.cap;
    const size_t nm = s->nmat_tab ? s->nmat_tab : 1;
    dm_particles *P = &s->p;
    size_t k = 0;
#define ADD(f, size) (b[k++] = (buffer){(void **)&(f), (size)})
    ADD(P->x, n * D * sizeof(double));
    ADD(P->v, n * D * sizeof(double));
    ADD(P->f, n * D * sizeof(double));
    ADD(P->x0, n * D * sizeof(double));
    ADD(P->vp, n * D * sizeof(double));
    ADD(P->w, n * W * sizeof(double));
    ADD(P->t, n * W * sizeof(double));
    ADD(P->wp, n * W * sizeof(double));
    ADD(P->theta, n * sizeof(double));
    for (int c = 0; c < 4; c++) /* empty in 2D */
        ADD(P->q[c], n * (dm_qdim(s) ? sizeof(double) : 0));
    ADD(P->r, n * sizeof(double));
    ADD(P->m, n * sizeof(double));
    ADD(P->im, n * sizeof(double));
    ADD(P->iinv, n * sizeof(double));
    ADD(P->mat, n * sizeof(uint16_t));
    ADD(P->hid, n * sizeof(uint32_t));
    ADD(P->clump, n * sizeof(uint32_t));
    dm_handles *h[4] = {&s->ph, &s->wh, &s->bh, &s->clh};
    for (int c = 0; c < 4; c++) {
        ADD(h[c]->slot, h[c]->cap * sizeof(uint32_t));
        ADD(h[c]->gen, h[c]->cap * sizeof(uint16_t));
        ADD(h[c]->free, h[c]->cap * sizeof(uint32_t));
    }
    ADD(s->pairs, s->cap_pairs * sizeof *s->pairs);
    ADD(s->ptab, nm * nm * sizeof *s->ptab);
    ADD(s->walls, s->cap_walls * sizeof *s->walls);
    ADD(s->bodies, s->cap_bodies * sizeof *s->bodies);
    ADD(s->templates, s->cap_templates * sizeof *s->templates);
    ADD(s->tmem, (size_t)s->cap_tmem * DM_TMEM * sizeof *s->tmem);
    ADD(s->clumps, s->cap_clumps * sizeof *s->clumps);
    ADD(s->cmem, s->cap_cmem * sizeof *s->cmem);
    dm_spectrum *sp = &s->drum.spectrum;
    ADD(sp->edges, (sp->nclasses ? sp->nclasses - 1 : 0) * sizeof(double));
    ADD(sp->counts, (sp->counts ? dm_spectrum_counters(sp) : 0) * sizeof(uint64_t));
    for (int side = 0; side < 2; side++)
        for (int q = 0; q < DM_KERNELS; q++) {
            dm_bucket *bk = side ? &s->pw.b[q] : &s->pp.b[q];
            ADD(bk->i, bk->cap * sizeof(uint32_t));
            ADD(bk->j, bk->cap * sizeof(uint32_t));
            ADD(bk->t, (bk->t ? bk->cap : 0) * sizeof(uint32_t));
            ADD(bk->on, bk->cap);
            ADD(bk->hist, bk->cap * (size_t)bk->hs * sizeof(double));
        }
#undef ADD
    assert(k <= MAX_BUFFERS);
    return k;
}

void dm_state_free(demill_world *s)
{
    if (s->walls)
        dm_walls_free_owned(s);
    buffer b[MAX_BUFFERS];
    const size_t nb = buffers_of(s, b);
    for (size_t k = 0; k < nb; k++) {
        free(*b[k].field);
        *b[k].field = NULL;
    }
}

/* Makes dst's state a copy of src's. A buffer of dst of the size of src's
 * is reused (the watchdog's copy, taken again and again of a world whose
 * arrays keep their sizes, then costs no allocation and no second copy at
 * once), but for the walls', which receive the copies of the meshes; the
 * others are allocated and filled first, and the reused ones only when
 * everything is there, so that if memory runs out dst is left as it was. */
demill_status dm_state_copy(demill_world *dst, const demill_world *src)
{
    demill_world n = *src, old = *dst;
    buffer nb[MAX_BUFFERS], ob[MAX_BUFFERS];
    const void *from[MAX_BUFFERS];
    const size_t count = buffers_of(&n, nb);
    buffers_of(&old, ob); /* the same buffers, in the same order */
    size_t k = 0;
    for (; k < count; k++) {
        from[k] = *nb[k].field;
        *nb[k].field = NULL;
        if (!from[k])
            continue;
        const bool reuse = *ob[k].field && ob[k].bytes == nb[k].bytes &&
                           nb[k].field != (void **)&n.walls;
        void *to = reuse ? *ob[k].field : malloc(nb[k].bytes ? nb[k].bytes : 1);
        if (!to)
            break;
        if (!reuse)
            memcpy(to, from[k], nb[k].bytes);
        *nb[k].field = to;
    }
    uint32_t meshes = 0; /* the walls' meshes and loads, each its own block */
    bool lost = k < count;
    for (; !lost && meshes < n.nwalls; meshes++) {
        const dm_trimesh *m = src->walls[meshes].mesh;
        const dm_loads *l = src->walls[meshes].loads;
        n.walls[meshes].mesh = m ? dm_trimesh_copy(m) : NULL;
        n.walls[meshes].loads = l ? dm_loads_copy(l) : NULL;
        lost = (m && !n.walls[meshes].mesh) || (l && !n.walls[meshes].loads);
    }
    if (lost) {
        for (uint32_t q = 0; q < meshes; q++) {
            dm_trimesh_free(n.walls[q].mesh);
            dm_loads_free(n.walls[q].loads);
        }
        for (size_t q = 0; q < k; q++)
            if (*nb[q].field != *ob[q].field)
                free(*nb[q].field);
        return DEMILL_ERR_OUT_OF_MEMORY;
    }
    for (k = 0; k < count; k++)
        if (from[k] && *nb[k].field == *ob[k].field) { /* reused: no longer old's */
            memcpy(*nb[k].field, from[k], nb[k].bytes);
            *ob[k].field = NULL;
        }
    dm_state_free(&old);
    n.base.magic = dst->base.magic;
    n.tag = dst->tag; /* the world's identity: its ids stay its own */
    n.grid = dst->grid; /* scratch, but for the box of the last build */
    memcpy(n.grid.lo, src->grid.lo, sizeof n.grid.lo);
    memcpy(n.grid.hi, src->grid.hi, sizeof n.grid.hi);
    n.res = dst->res;
    n.res.valid = false;
    n.wg = dst->wg;
    n.refine = dst->refine;
    n.watch = dst->watch;
    const bool same_dim = dst->dim == src->dim;
    n.progress = dst->progress;
    n.base.pool = dst->base.pool; /* the destination's own threads */
    *dst = n;
    if (!same_dim) { /* the scratch is laid out for a dimension: start it afresh */
        dm_results_free(dst);
        memset(&dst->res, 0, sizeof dst->res);
        dm_refine_free(dst); /* (which leaves it zeroed) */
    }
    return DEMILL_OK;
}

/* Makes the live world w's state a copy of src's (which may come from
 * another world, a snapshot or a checkpoint). */
demill_status dm_state_restore(demill_world *w, const demill_world *src)
{
    if (dm_state_copy(w, src))
        return DEMILL_ERR_OUT_OF_MEMORY;
    /* the next step uses the copied lists without a build, which is what
     * makes room for their results and wall geometry; without the room the
     * lists are built afresh */
    if (dm_wgeom_reserve(w) || dm_results_reserve(w))
        w->nlist_valid = false;
    return DEMILL_OK;
}
