/* kernels.c: the tables of the contact kernels' slices, by dimension (and
 * precision: the single-precision slices, DEMILL_WORLD_SINGLE_PRECISION), in
 * kernel order (dm_kernel_index()), through which dm_kernel() picks a
 * chunk's kernel. The slices themselves are compiled one per file, in
 * kernels/ (see DM_KERNEL_SLICE in kernels.h). */
#include "physics/contact/kernels.h"

/* Declared hidden, as they are defined (-fvisibility=hidden), so that a
 * slice defined nowhere fails the link of the shared library rather than
 * its loading. */
#define DECLARE_SLICE(D, NL, DL)                                                                  \
    extern __attribute__((visibility("hidden"))) const dm_kernel_slice dm_kernels_##D##_##NL##_##DL;
#define SLICE_ENTRY(D, NL, DL) &dm_kernels_##D##_##NL##_##DL,

#define DECLARE_SINGLE(D, NL, DL)                                                                 \
    extern __attribute__((visibility("hidden"))) const dm_kernel_slice                            \
        dm_kernels_single_##D##_##NL##_##DL;
#define SINGLE_ENTRY(D, NL, DL) &dm_kernels_single_##D##_##NL##_##DL,

DM_FOR_EACH_SLICE(DECLARE_SLICE, 2)
DM_FOR_EACH_SLICE(DECLARE_SLICE, 3)
DM_FOR_EACH_SLICE(DECLARE_SINGLE, 2)
DM_FOR_EACH_SLICE(DECLARE_SINGLE, 3)

/* Unsized, so that a list of slices other than DM_SLICES long conflicts
 * with the declaration in kernels.h. */
const dm_kernel_slice *const dm_kernels2[] = {DM_FOR_EACH_SLICE(SLICE_ENTRY, 2)};
const dm_kernel_slice *const dm_kernels3[] = {DM_FOR_EACH_SLICE(SLICE_ENTRY, 3)};
const dm_kernel_slice *const dm_kernels2_single[] = {DM_FOR_EACH_SLICE(SINGLE_ENTRY, 2)};
const dm_kernel_slice *const dm_kernels3_single[] = {DM_FOR_EACH_SLICE(SINGLE_ENTRY, 3)};
