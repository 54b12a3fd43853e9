/* 2d_linear_restitution.c: the 2D contact kernels of normal law DEMILL_NORMAL_LINEAR and
 * damping DEMILL_DAMPING_RESTITUTION, for every tangential and rolling law (see
 * DM_KERNEL_SLICE in kernels.h). */
#include "physics/contact/kernels.h"

DM_KERNEL_SLICE(2, 1, 2)
