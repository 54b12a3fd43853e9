/* kernels2.c: the 2D instances of every contact kernel (see kernels.h). */
#include "physics/contact/kernels.h"

DM_FOR_EACH_KERNEL(DM_DEFINE_KERNELS, 2)

const dm_kernel_fn dm_pp_kernels2[DM_KERNELS] = {DM_FOR_EACH_KERNEL(DM_PP_ENTRY, 2)};
const dm_kernel_fn dm_pw_kernels2[DM_KERNELS] = {DM_FOR_EACH_KERNEL(DM_PW_ENTRY, 2)};
