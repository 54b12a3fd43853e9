/* results.c: the layout of a force evaluation's per-pair results
 * (dm_results): pair ids and the chunks the kernels work through. */
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "physics/contact/kernels.h"

/* Chunks of the lists: a bucket of n candidates has ceil(n / DM_CHUNK). */
static uint32_t count_chunks(const demill_world *w)
{
    uint32_t c = 0;
    for (int k = 0; k < w->nkern; k++)
        c += (w->pp.b[k].n + DM_CHUNK - 1) / DM_CHUNK + (w->pw.b[k].n + DM_CHUNK - 1) / DM_CHUNK;
    return c;
}

/* Makes room for the results of the current lists; -1 when out of memory. */
int dm_results_reserve(demill_world *w)
{
    dm_results *q = &w->res;
    const int S = w->dim + 2 * dm_wdim(w);
    size_t n = 0;
    for (int k = 0; k < w->nkern; k++)
        n += (size_t)w->pp.b[k].n + w->pw.b[k].n;
    q->valid = false;
    if (n > UINT32_MAX)
        return -1;
    if (n > q->cap) {
        size_t cap = dm_grown_capacity(q->cap, n);
        void **const arrays[] = {(void **)&q->out, (void **)&q->list};
        const size_t sizes[] = {(size_t)S * sizeof(double), sizeof(uint32_t)};
        if (dm_grow_arrays(arrays, sizes, 2, cap))
            return -1;
        q->cap = (uint32_t)cap;
    }
    if (w->p.n > q->cap_particles) {
        size_t cap = dm_grown_capacity(q->cap_particles, w->p.n);
        void **const arrays[] = {(void **)&q->lo};
        const size_t sizes[] = {sizeof(uint32_t)};
        if (dm_grow_arrays(arrays, sizes, 1, cap))
            return -1;
        q->cap_particles = (uint32_t)cap;
    }
    const uint32_t nchunks = count_chunks(w);
    if (nchunks > q->cap_chunks) {
        size_t cap = dm_grown_capacity(q->cap_chunks, nchunks);
        void **const arrays[] = {(void **)&q->chunks, (void **)&q->chunk_tally,
                                 (void **)&q->chunk_contacts, (void **)&q->chunk_listed};
        const size_t sizes[] = {sizeof(dm_chunkref), sizeof(dm_tally), sizeof(uint32_t),
                                sizeof(uint32_t)};
        if (dm_grow_arrays(arrays, sizes, 4, cap))
            return -1;
        q->cap_chunks = (uint32_t)cap;
    }
    return 0;
}

/* Runs body for every pair p of every chunk r of q, of bucket b, with its
 * particles i and j (i again for a particle-wall pair). */
#define DM_FOR_CHUNK_PAIRS(q, w, body)                                                            \
    for (uint32_t c_ = 0; c_ < (q)->nchunks; c_++) {                                              \
        dm_chunkref *r = &(q)->chunks[c_];                                                        \
        const dm_bucket *b = r->walls ? &(w)->pw.b[r->kernel] : &(w)->pp.b[r->kernel];           \
        const uint32_t k1 = b->n - r->k0 < DM_CHUNK ? b->n : r->k0 + DM_CHUNK;                    \
        for (uint32_t p = r->k0; p < k1; p++) {                                                   \
            const uint32_t i = b->i[p], j = r->walls ? i : b->j[p];                               \
            body                                                                                  \
        }                                                                                         \
    }

/* Which chunks sum which particles' forces (dm_results.lo; forces.c): for
 * every particle the first particle of the first chunk with one of its
 * pairs (the chunks' i0 grow with their pair ids; a particle without pairs
 * its own index), and for every chunk the least of that over its pairs'
 * particles, and its last particle. */
void dm_results_reach(demill_world *w)
{
    dm_results *q = &w->res;
    uint32_t *restrict lo = q->lo;
    for (uint32_t p = 0; p < w->p.n; p++)
        lo[p] = p;
    DM_FOR_CHUNK_PAIRS(q, w, {
        lo[i] = r->i0 < lo[i] ? r->i0 : lo[i];
        lo[j] = r->i0 < lo[j] ? r->i0 : lo[j];
    })
    for (uint32_t c = 0; c < q->nchunks; c++) {
        q->chunks[c].lo = UINT32_MAX;
        q->chunks[c].hi = 0;
    }
    DM_FOR_CHUNK_PAIRS(q, w, {
        const uint32_t l = lo[i] < lo[j] ? lo[i] : lo[j];
        r->lo = l < r->lo ? l : r->lo;
        r->hi = j > r->hi ? j : r->hi;
    })
    q->reach_valid = true;
}

/* Numbers the pairs and lists the chunks, no pair with a result. Needs the
 * room of the last dm_results_reserve(), which the lists only shrink from. */
void dm_results_layout(demill_world *w)
{
    dm_results *q = &w->res;
    uint32_t id = 0, c = 0;
    for (int side = 0; side < 2; side++) {
        if (side)
            q->npp = id;
        for (int k = 0; k < w->nkern; k++) {
            dm_bucket *b = side ? &w->pw.b[k] : &w->pp.b[k];
            b->base = id;
            b->chunk0 = c;
            b->span = 0;
            for (uint32_t p = 0; !side && p < b->n; p++)
                if (b->j[p] - b->i[p] > b->span)
                    b->span = b->j[p] - b->i[p];
            id += b->n;
            for (uint32_t k0 = 0; k0 < b->n; k0 += DM_CHUNK)
                q->chunks[c++] = (dm_chunkref){k0, (uint16_t)k, (uint16_t)side, b->i[k0], 0, 0};
        }
    }
    q->n = id;
    q->nchunks = c;
    if (c) /* chunk_listed is NULL before the first chunk */
        memset(q->chunk_listed, 0, c * sizeof *q->chunk_listed);
    q->valid = true;
    q->reach_valid = false;
}

void dm_results_free(demill_world *w)
{
    dm_results *q = &w->res;
    free(q->out);
    free(q->list);
    free(q->chunks);
    free(q->chunk_tally);
    free(q->chunk_contacts);
    free(q->chunk_listed);
    free(q->lo);
}
