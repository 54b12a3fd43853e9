/* handles.h: generation-counted ids, the handle tables behind them, and the
 * world tags that keep the ids of two live worlds apart. */
#ifndef DM_HANDLES_H
#define DM_HANDLES_H

#include "base/base.h"

/* Bits 63..52 world tag, 51..48 kind, 47..32 generation, 31..0 index. */
#define DM_ID_INDEX(id) ((uint32_t)((id) & 0xffffffffu))
#define DM_ID_GEN(id) ((uint16_t)(((id) >> 32) & 0xffffu))
#define DM_ID_KIND(id) ((int)(((id) >> 48) & 0xfu))
#define DM_ID_TAG(id) ((uint16_t)(((id) >> 52) & 0xfffu))
demill_id dm_id_make(uint16_t tag, int kind, uint16_t gen, uint32_t index);

#define DM_WORLD_TAGS 4096    /* live worlds at most: each has its own tag */
#define DM_GEN_LAST UINT16_MAX /* the last generation of a handle or drum id */
/* Claims a tag no live world has (-1: all are taken), and gives it back. */
int dm_tag_claim(uint16_t *tag);
void dm_tag_release(uint16_t tag);

/* A table of generation-counted handles mapping to storage slots. */
typedef struct dm_handles {
    uint32_t *slot; /* handle index -> storage index, DM_FREE if unused */
    uint16_t *gen;  /* generation of each handle index */
    uint32_t *free; /* stack of free handle indices */
    uint32_t nfree, n, cap; /* n: handle indices ever issued */
} dm_handles;

int dm_handles_reserve(dm_handles *h, uint32_t extra);
uint32_t dm_handles_issue(dm_handles *h, uint32_t slot);
void dm_handles_release(dm_handles *h, uint32_t index);
void dm_handles_free(dm_handles *h);

#endif /* DM_HANDLES_H */
