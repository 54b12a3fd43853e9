/* kinematics.c: the contact kernels' kinematics loops (dm_kins, see
 * kernels.h), one per dimension, kind of pair, SPIN and rolling law: the 24
 * loops that the kernels share, compiled once rather than in every kernel
 * (those of the rolling spring serve the generic kernel only); and the 16
 * loops of the single-precision kernels (dm_kinsf), which round the same
 * kinematics into a float chunk; and the particle-particle narrow phase's
 * gathers (dm_pp_separations), which every kernel shares too. */
#include "physics/contact/kernels.h"

/* dm_pp_separations() for dimension D. */
DM_INLINE void pp_separations(const int D, const dm_particles *P, const uint32_t *restrict bi,
                              const uint32_t *restrict bj, uint32_t k0, uint32_t k1,
                              double (*restrict d)[DM_CHUNK], double *restrict sum)
{
    const double *restrict x = P->x, *restrict r = P->r;
    for (uint32_t k = k0; k < k1; k++) {
        const uint32_t i = bi[k], j = bj[k];
        for (int c = 0; c < D; c++)
            d[c][k - k0] = x[D * j + c] - x[D * i + c];
        sum[k - k0] = r[i] + r[j];
    }
}

DM_SCALAR_LOOPS void dm_pp_separations(int D, const dm_particles *P, const uint32_t *bi,
                                       const uint32_t *bj, uint32_t k0, uint32_t k1,
                                       double (*d)[DM_CHUNK], double *sum)
{
    if (D == 3)
        pp_separations(3, P, bi, bj, k0, k1, d, sum);
    else
        pp_separations(2, P, bi, bj, k0, k1, d, sum);
}

/* Particle-particle pairs: the separation again (the narrow phase kept only
 * whether they touch), then the kinematics of the chunk's pairs ks, into
 * the chunk ch or (F: the single-precision kernels') rounded into the float
 * chunk cf. */
DM_INLINE void pp_kins(const int D, const int SPIN, const int ROLL, const int F,
                       const dm_kernel_args *a, const uint32_t *restrict ks,
                       dm_chunk *restrict ch, dm_chunkf *restrict cf, uint32_t lanes)
{
    const dm_particles *P = &a->w->p;
    const double *vp = a->vp, *wp = a->wp;
    const uint32_t *restrict bi = a->b->i, *restrict bj = a->b->j;
    const uint32_t n = lanes / DM_LANES * DM_LANES; /* see dm_kin_fn */
    for (uint32_t s = 0; s < n; s++) {
        const uint32_t k = ks[s], i = bi[k], j = bj[k];
        double d[3], r2;
        dm_pp_touch(D, P, i, j, d, &r2);
        dm_kin q;
        dm_pp_kin(D, SPIN, ROLL, P, vp, wp, i, j, d, r2, &q);
        if (F)
            dm_kin_putf(D, ROLL, cf, s, &q);
        else
            dm_kin_put(D, ROLL, ch, s, &q);
    }
}

/* Particle-wall pairs, from the contact geometry of the bucket's candidates
 * (w->wg, from a->geom_offset on), into ch or (F) cf as pp_kins(). */
DM_INLINE void pw_kins(const int D, const int SPIN, const int ROLL, const int F,
                       const dm_kernel_args *a, const uint32_t *restrict ks,
                       dm_chunk *restrict ch, dm_chunkf *restrict cf, uint32_t lanes)
{
    const demill_world *w = a->w;
    const double *vp = a->vp, *wp = a->wp;
    const uint32_t *restrict bi = a->b->i, *restrict bj = a->b->j;
    const uint32_t g0 = a->geom_offset, n = lanes / DM_LANES * DM_LANES; /* see dm_kin_fn */
    for (uint32_t s = 0; s < n; s++) {
        const uint32_t k = ks[s];
        dm_kin q;
        dm_pw_kin(D, SPIN, ROLL, &w->p, vp, wp, &w->wg, g0 + k, bi[k], &w->walls[bj[k]], &q);
        if (F)
            dm_kin_putf(D, ROLL, cf, s, &q);
        else
            dm_kin_put(D, ROLL, ch, s, &q);
    }
}

#define KINS(D, SPIN, ROLL)                                                                       \
    DM_VECTOR_CLONES static void pp_kins_##D##_##SPIN##_##ROLL(const dm_kernel_args *a,           \
                                                               dm_chunk *ch, uint32_t lanes)      \
    {                                                                                             \
        pp_kins(D, SPIN, ROLL, 0, a, ch->k, ch, NULL, lanes);                                     \
    }                                                                                             \
    DM_VECTOR_CLONES static void pw_kins_##D##_##SPIN##_##ROLL(const dm_kernel_args *a,           \
                                                               dm_chunk *ch, uint32_t lanes)      \
    {                                                                                             \
        pw_kins(D, SPIN, ROLL, 0, a, ch->k, ch, NULL, lanes);                                     \
    }
#define KINS_D(D) KINS(D, 0, 0) KINS(D, 0, 1) KINS(D, 0, 2) KINS(D, 1, 0) KINS(D, 1, 1) KINS(D, 1, 2)
KINS_D(2)
KINS_D(3)

#define ROW(D, PAIRS)                                                                             \
    {{PAIRS##_kins_##D##_0_0, PAIRS##_kins_##D##_0_1, PAIRS##_kins_##D##_0_2},                    \
     {PAIRS##_kins_##D##_1_0, PAIRS##_kins_##D##_1_1, PAIRS##_kins_##D##_1_2}}
const dm_kin_fn dm_kins[2][2][2][DM_ROLLING_LAWS] = {{ROW(2, pp), ROW(2, pw)},
                                                     {ROW(3, pp), ROW(3, pw)}};

/* ---- the single-precision kernels' (dm_kinsf): the same kinematics, in
 * double, rounded into the float chunk cf (dm_kin_putf) ---- */
#define KINSF(D, SPIN, ROLL)                                                                      \
    DM_VECTOR_CLONES static void pp_kinsf_##D##_##SPIN##_##ROLL(                                  \
        const dm_kernel_args *a, const dm_chunk *ch, dm_chunkf *cf, uint32_t lanes)               \
    {                                                                                             \
        pp_kins(D, SPIN, ROLL, 1, a, ch->k, NULL, cf, lanes);                                     \
    }                                                                                             \
    DM_VECTOR_CLONES static void pw_kinsf_##D##_##SPIN##_##ROLL(                                  \
        const dm_kernel_args *a, const dm_chunk *ch, dm_chunkf *cf, uint32_t lanes)               \
    {                                                                                             \
        pw_kins(D, SPIN, ROLL, 1, a, ch->k, NULL, cf, lanes);                                     \
    }
#define KINSF_D(D) KINSF(D, 0, 0) KINSF(D, 0, 1) KINSF(D, 1, 0) KINSF(D, 1, 1)
KINSF_D(2)
KINSF_D(3)

#define ROWF(D, PAIRS)                                                                            \
    {{PAIRS##_kinsf_##D##_0_0, PAIRS##_kinsf_##D##_0_1},                                          \
     {PAIRS##_kinsf_##D##_1_0, PAIRS##_kinsf_##D##_1_1}}
const dm_kinf_fn dm_kinsf[2][2][2][2] = {{ROWF(2, pp), ROWF(2, pw)}, {ROWF(3, pp), ROWF(3, pw)}};
