/* 3d_linear_none_single.c: the 3D single-precision contact kernels of normal
 * law DEMILL_NORMAL_LINEAR and damping DEMILL_DAMPING_NONE, for every tangential and
 * rolling law (see DM_KERNEL_SLICE_SINGLE in kernels.h). */
#include "physics/contact/kernels.h"

DM_KERNEL_SLICE_SINGLE(3, 1, 0)
