/* base.h: the ground floor of the library, which every layer may use: the
 * public API's types, a few constants, and the part of a world the base
 * layer keeps (dm_base). Nothing in lib/base uses anything above it: a world
 * is an opaque pointer here, whose first member is its dm_base. */
#ifndef DM_BASE_H
#define DM_BASE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "demill.h"

#define DM_FREE UINT32_MAX
#define DM_PI 3.14159265358979323846

/* The hot loops (contact kernels, integration) are also built for AVX2
 * (x86-64-v3) and AVX-512 (x86-64-v4) on x86-64, the best version chosen
 * when the library loads. */
#ifdef DEMILL_HAVE_TARGET_CLONES
#define DM_VECTOR_CLONES                                                                          \
    __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define DM_VECTOR_CLONES
#endif

/* A function whose loops GCC must not vectorise: loops that read a few
 * doubles of each of many particles, through an index array or with a
 * stride, whose vectorised form (no gather instruction under GCC's generic
 * tuning: each index extracted from a vector, each double inserted into
 * one) measured slower than plain loads (docs/benchmarks.md, Fifth round).
 * Empty under clang, which may vectorise them, with the same results. */
#if defined(__GNUC__) && !defined(__clang__)
#define DM_SCALAR_LOOPS __attribute__((optimize("no-tree-vectorize")))
#else
#define DM_SCALAR_LOOPS
#endif

#define DM_WORLD_MAGIC 0x64656d696c6cu /* "demill" */

/* What the base layer keeps for a world, at its start (struct demill_world
 * in lib/physics/state/state.h begins with it): how a world is told from
 * other memory, its last error message, its clock in steps, the count of
 * calls that may have changed it, and its worker threads. */
typedef struct dm_pool dm_pool;
typedef struct dm_base {
    uint64_t magic;   /* DM_WORLD_MAGIC while the world lives */
    uint64_t steps;   /* steps taken */
    uint64_t edits;   /* calls that may have changed the world (dm_changed) */
    int threads;      /* threads the loops run on (world.threads) */
    dm_pool *pool;    /* their workers, started by dm_parallel (threads.c) */
    char error[1024]; /* the last error's message */
} dm_base;

/* A world's dm_base: a pointer to a struct, converted, points to its first
 * member (C11 6.7.2.1). */
static inline dm_base *dm_base_of(demill_world *w)
{
    return (dm_base *)(void *)w;
}

static inline const dm_base *dm_base_of_const(const demill_world *w)
{
    return (const dm_base *)(const void *)w;
}

#endif /* DM_BASE_H */
