/* 3d_hertz_restitution.c: the 3D contact kernels of normal law DEMILL_NORMAL_HERTZ and
 * damping DEMILL_DAMPING_RESTITUTION, for every tangential and rolling law (see
 * DM_KERNEL_SLICE in kernels.h). */
#include "physics/contact/kernels.h"

DM_KERNEL_SLICE(3, 2, 2)
