/* generic.c: the generic contact kernels, one per dimension for particle-
 * particle and one for particle-wall pairs, which serve every combination of
 * laws outside the fast kernels' (DM_FAST_KERNELS; see kernels.h): the fast
 * kernels' passes and dm_law(), with the laws of the chunk's bucket as
 * run-time values. */
#include "physics/contact/kernels.h"

#define GENERIC_KERNELS(D)                                                                        \
    static void laws_##D(dm_chunk *ch, uint32_t lanes, const dm_pairparam *tab, double dt_hist,  \
                         double reach, dm_laws l)                                                 \
    {                                                                                             \
        dm_chunk_laws(D, l.normal, l.damping, l.tangential, l.rolling, l.cohesion, ch, lanes,     \
                      tab, dt_hist, reach);                                                       \
    }                                                                                             \
    static void pp_##D(dm_kernel_args *a)                                                         \
    {                                                                                             \
        const dm_laws l = dm_kernel_laws(a->b->kernel);                                           \
        dm_pp_chunk(D, l.normal, l.damping, l.tangential, l.rolling, l.cohesion, laws_##D, NULL,  \
                    a);                                                                           \
    }                                                                                             \
    static void pw_##D(dm_kernel_args *a)                                                         \
    {                                                                                             \
        const dm_laws l = dm_kernel_laws(a->b->kernel);                                           \
        dm_pw_chunk(D, l.normal, l.damping, l.tangential, l.rolling, l.cohesion, laws_##D, NULL,  \
                    a);                                                                           \
    }

GENERIC_KERNELS(2)
GENERIC_KERNELS(3)

const dm_kernel_fn dm_generic_pp[2] = {pp_2, pp_3}, dm_generic_pw[2] = {pw_2, pw_3};
