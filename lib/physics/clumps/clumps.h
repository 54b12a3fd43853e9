/* clumps.h: clumps, rigid bodies of overlapping spheres (discs in 2D) whose
 * members are particles (clumps.c): their members placed from their
 * motion, the forces and torques summed on them, their time stepping and
 * their energies. Uses the base and the state. */
#ifndef DM_CLUMPS_H
#define DM_CLUMPS_H

#include "physics/state/state.h"

/* Whether slot k holds a clump. */
static inline bool dm_clump_live(const demill_world *w, uint32_t k)
{
    return w->clumps[k].handle != DM_FREE;
}

/* The rotation matrix of the unit quaternion q = (w, x, y, z), row-major:
 * a body-frame vector b is R b in the world frame. */
void dm_quat_matrix(const double q[4], double R[9]);

/* Clump k's angular velocity (world frame) for angular momentum L (world
 * frame) at its orientation: R I⁻¹ Rᵀ L (2D: L_z / I_z). */
void dm_clump_omega(const demill_world *w, const dm_clump *c, const double L[3], double om[3]);

/* Places clump k's members from its motion: x_i = X + R b_i,
 * v_i = V + ω × (x_i − X), vp_i = Vp + ωp × (x_i − X), their angular
 * velocities ω and ωp and their orientation (3D: q; 2D: θ). Returns the
 * largest squared displacement of a member since the last neighbour
 * build. */
double dm_clump_place(demill_world *w, uint32_t k);

/* The force F and the torque T (about the centre of mass; 2D: T[2]) on
 * clump k at the last force evaluation: the members' contact forces and
 * torques and gravity on the clump's mass, summed in the members' order. */
void dm_clump_load(const demill_world *w, uint32_t k, double F[3], double T[3]);

/* The energies of clump k: kinetic of translation 1/2 M V², of rotation
 * 1/2 ω·L and potential -M g·X. */
void dm_clump_energies(const demill_world *w, uint32_t k, double *kt, double *kr,
                       double *pot);

/* The start of a step for every clump, as the particles' (integrate.c): with
 * verlet, velocity Verlet's first half (after the second half of the step
 * before when kick is set), else symplectic Euler's step; then the members
 * placed. Returns the largest squared displacement of a member since the
 * last neighbour build. */
double dm_clumps_drift(demill_world *w, double dt, int kick, int verlet);
/* Velocity Verlet's second half, at the end of a run: V += h F/M,
 * L += h T, and the members' velocities. */
void dm_clumps_kick(demill_world *w, double h);

#endif /* DM_CLUMPS_H */
