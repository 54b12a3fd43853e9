/* 2d_hertz_restitution_single.c: the 2D single-precision contact kernels of normal
 * law DEMILL_NORMAL_HERTZ and damping DEMILL_DAMPING_RESTITUTION, for every tangential and
 * rolling law (see DM_KERNEL_SLICE_SINGLE in kernels.h). */
#include "physics/contact/kernels.h"

DM_KERNEL_SLICE_SINGLE(2, 2, 2)
