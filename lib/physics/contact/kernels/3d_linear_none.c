/* 3d_linear_none.c: the 3D contact kernels of normal law DEMILL_NORMAL_LINEAR and
 * damping DEMILL_DAMPING_NONE, for every tangential and rolling law (see
 * DM_KERNEL_SLICE in kernels.h). */
#include "physics/contact/kernels.h"

DM_KERNEL_SLICE(3, 1, 0)
