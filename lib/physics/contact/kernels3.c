/* kernels3.c: the 3D instances of every contact kernel (see kernels.h). */
#include "physics/contact/kernels.h"

DM_FOR_EACH_KERNEL(DM_DEFINE_KERNELS, 3)

const dm_kernel_fn dm_pp_kernels3[DM_KERNELS] = {DM_FOR_EACH_KERNEL(DM_PP_ENTRY, 3)};
const dm_kernel_fn dm_pw_kernels3[DM_KERNELS] = {DM_FOR_EACH_KERNEL(DM_PW_ENTRY, 3)};
