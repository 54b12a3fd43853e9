/* scene.c: the canonical drums of docs/scenes.md, packed exactly as defined
 * there (drum3d: 15 layers from z = -0.046 m): a lattice of spacing 6.3 mm,
 * the lowest N sites inside the drum (sorted by y, then x, then z index),
 * each coordinate jittered by ±0.1 mm with Python's random.Random(12345). Python's generator is the Mersenne
 * Twister MT19937 seeded through init_by_array; it is reproduced here so that
 * the packing, and the peers' input files made from it, are identical. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "mill.h"

/* ---- MT19937 as Python's random module uses it -------------------------- */

typedef struct mt19937 {
    uint32_t mt[624];
    int index;
} mt19937;

static void mt_init(mt19937 *g, uint32_t seed)
{
    g->mt[0] = seed;
    for (int i = 1; i < 624; i++)
        g->mt[i] = 1812433253u * (g->mt[i - 1] ^ (g->mt[i - 1] >> 30)) + (uint32_t)i;
    g->index = 624;
}

/* Python's random.seed(n) for a non-negative int n < 2^32: init_by_array
 * with the one-word key [n]. */
static void mt_seed_python(mt19937 *g, uint32_t n)
{
    const uint32_t key[1] = {n};
    const int len = 1;
    mt_init(g, 19650218u);
    int i = 1, j = 0;
    for (int k = 624 > len ? 624 : len; k; k--) {
        g->mt[i] = (g->mt[i] ^ ((g->mt[i - 1] ^ (g->mt[i - 1] >> 30)) * 1664525u)) + key[j] + (uint32_t)j;
        i++;
        j++;
        if (i >= 624) {
            g->mt[0] = g->mt[623];
            i = 1;
        }
        if (j >= len)
            j = 0;
    }
    for (int k = 623; k; k--) {
        g->mt[i] = (g->mt[i] ^ ((g->mt[i - 1] ^ (g->mt[i - 1] >> 30)) * 1566083941u)) - (uint32_t)i;
        i++;
        if (i >= 624) {
            g->mt[0] = g->mt[623];
            i = 1;
        }
    }
    g->mt[0] = 0x80000000u;
    g->index = 624;
}

static uint32_t mt_next(mt19937 *g)
{
    if (g->index >= 624) {
        for (int k = 0; k < 624; k++) {
            uint32_t y = (g->mt[k] & 0x80000000u) | (g->mt[(k + 1) % 624] & 0x7fffffffu);
            g->mt[k] = g->mt[(k + 397) % 624] ^ (y >> 1) ^ (y & 1u ? 0x9908b0dfu : 0u);
        }
        g->index = 0;
    }
    uint32_t y = g->mt[g->index++];
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680u;
    y ^= (y << 15) & 0xefc60000u;
    return y ^ (y >> 18);
}

/* random.random(): 53 bits from two draws. */
static double mt_random(mt19937 *g)
{
    uint32_t a = mt_next(g) >> 5, b = mt_next(g) >> 6;
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}

/* ---- the lattice ------------------------------------------------------------ */

typedef struct site {
    long j, i, k; /* y, x, z indices */
} site;

static int cmp_site(const void *a, const void *b)
{
    const site *p = a, *q = b;
    if (p->j != q->j)
        return p->j < q->j ? -1 : 1;
    if (p->i != q->i)
        return p->i < q->i ? -1 : 1;
    return (p->k > q->k) - (p->k < q->k);
}

int scene_packing(const scene_def *s, double *pos)
{
    const double a = 0.0063, jitter = 1e-4;
    const long span = (long)(s->site_radius / a) + 1;
    const long layers = s->dim == 3 ? s->layers : 1;
    site *sites = malloc((size_t)(2 * span + 1) * (size_t)(2 * span + 1) * (size_t)layers * sizeof *sites);
    if (!sites)
        return -1;
    size_t n = 0;
    for (long j = -span; j <= span; j++)
        for (long i = -span; i <= span; i++)
            if ((i * a) * (i * a) + (j * a) * (j * a) <= s->site_radius * s->site_radius)
                for (long k = 0; k < layers; k++)
                    sites[n++] = (site){j, i, k};
    if (n < s->particles) {
        free(sites);
        return -1;
    }
    qsort(sites, n, sizeof *sites, cmp_site);
    mt19937 g;
    mt_seed_python(&g, 12345);
    for (size_t p = 0; p < s->particles; p++) {
        const double base[3] = {sites[p].i * a, sites[p].j * a,
                                s->dim == 3 ? s->z0 + sites[p].k * a : 0.0};
        for (int c = 0; c < 3; c++)
            /* base + random.uniform(-jitter, jitter), in Python's arithmetic */
            pos[3 * p + c] = c < s->dim ? base[c] + (-jitter + (jitter - -jitter) * mt_random(&g)) : 0.0;
    }
    free(sites);
    return 0;
}

/* ---- the world ------------------------------------------------------------------- */

int scene_world(const drum_geometry *g, demill_world **out, demill_id *steel, demill_id *drum)
{
    demill_world *w;
    if (demill_world_create(g->dim, &w) != DEMILL_OK) {
        fprintf(stderr, "cannot create a world\n");
        return -1;
    }
    /* in order: the first failure stops the chain */
    demill_status s = demill_material_create(w, steel);
    const char *what = "material";
    const demill_id m = *steel;
#define STEP(call, name)                                                                           \
    if (s == DEMILL_OK) {                                                                          \
        s = (call);                                                                                \
        what = (name);                                                                             \
    }
    STEP(demill_world_set(w, DEMILL_WORLD_TIME_STEP, g->time_step), "time step")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 7800), "density")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e8), "Young's modulus")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_POISSON_RATIO, 0.3), "Poisson ratio")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_RESTITUTION, 0.5), "restitution")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_FRICTION, 0.5), "friction")
    STEP(demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law")
    STEP(demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION), "damping")
    STEP(demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN), "friction law")
    STEP(demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, 0), "clamp")
    STEP(demill_drum_create(w, m, drum), "drum")
    STEP(demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, g->diameter), "diameter")
    STEP(demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, g->length), "length")
    STEP(demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_HEIGHT, g->lifter_size), "lifter height")
    STEP(demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_WIDTH, g->lifter_size), "lifter width")
    STEP(demill_drum_set(w, *drum, DEMILL_DRUM_LIFTERS, g->lifters), "lifters")
#undef STEP
    if (s != DEMILL_OK) {
        fprintf(stderr, "setting up the %s failed: %s\n", what, demill_world_last_error(w));
        demill_world_destroy(w);
        return -1;
    }
    *out = w;
    return 0;
}
