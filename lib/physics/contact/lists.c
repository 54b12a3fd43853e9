/* lists.c: the contact lists (dm_clist): pairs grouped by kernel with their
 * history, emptied, thinned and freed here; the neighbour build
 * (lib/physics/broadphase) fills them. */
#include <stdlib.h>
#include <string.h>

#include "physics/contact/contact.h"

/* Empties the lists; each bucket's history holds its kernel's slots and,
 * while a collision spectrum is recorded, the contact's dissipated energy. */
static void clist_empty(const demill_world *w, dm_clist *l)
{
    for (int k = 0; k < DM_KERNELS; k++) {
        dm_bucket *b = &l->b[k];
        const int hs = dm_kernel_hist_size(k, w->dim) + (w->events ? 1 : 0);
        if (hs != b->hs) { /* a new layout: the arrays are sized afresh */
            b->hs = hs;
            b->cap = 0;
        }
        b->kernel = k;
        b->n = 0;
    }
}

void dm_clist_clear(demill_world *w)
{
    clist_empty(w, &w->pp);
    clist_empty(w, &w->pw);
    w->res.valid = false;
}

/* Moves pair `from` of a bucket to slot `to` (to <= from) as pair (i, j). */
void dm_bucket_move(dm_bucket *b, uint32_t to, uint32_t from, uint32_t i, uint32_t j)
{
    b->i[to] = i;
    b->j[to] = j;
    if (b->t)
        b->t[to] = b->t[from];
    b->on[to] = b->on[from];
    memmove(b->hist + (size_t)b->hs * to, b->hist + (size_t)b->hs * from,
            (size_t)b->hs * sizeof *b->hist);
}

void dm_clist_drop_wall(demill_world *w, uint32_t wall_slot)
{
    for (int k = 0; k < DM_KERNELS; k++) {
        dm_bucket *b = &w->pw.b[k];
        uint32_t m = 0;
        for (uint32_t p = 0; p < b->n; p++)
            if (b->j[p] != wall_slot)
                dm_bucket_move(b, m++, p, b->i[p], b->j[p]);
        b->n = m;
    }
    w->res.valid = false;
}

static void clist_free(dm_clist *l)
{
    for (int k = 0; k < DM_KERNELS; k++) {
        free(l->b[k].i);
        free(l->b[k].j);
        free(l->b[k].t);
        free(l->b[k].hist);
        free(l->b[k].on);
    }
}

void dm_clists_free(demill_world *w)
{
    clist_free(&w->pp);
    clist_free(&w->pw);
}
