/* law.h: the contact force law of one contact, composed of a normal law, a
 * damping law, a tangential law, a rolling law and a cohesion law
 * (docs/physics.md §2-5).
 *
 * dm_law() is written once and specialised by the compiler: the kernels call
 * it with compile-time constant law choices and dimension, so a part that is
 * switched off costs nothing. Queries call it with run-time choices.
 *
 * Conventions: body a and body b (a particle or a wall), unit normal n from a
 * to b, overlap delta > 0 (or, for a cohesive contact that exists, above
 * -dm_law_range()), relative velocity of b with respect to a at the
 * contact point vc, relative angular velocity wrel = ω_a - ω_b. The law
 * returns the normal force magnitude fn on b along n, the tangential force
 * ft on b and the rolling torque mr on a; a receives -(fn n + ft) and b
 * receives -mr.
 */
#ifndef DM_LAW_H
#define DM_LAW_H

#include <math.h>

#include "physics/contact/plastic.h"
#include "physics/contact/cohesion.h"
#include "physics/state/state.h"

#define DM_INLINE static inline __attribute__((always_inline))

/* The laws that only the generic kernel runs (see DM_FAST_KERNELS). */
DM_INLINE int dm_law_extended(int normal, int rolling, int cohesion)
{
    return normal > DEMILL_NORMAL_HERTZ || rolling > DEMILL_ROLLING_CONSTANT_TORQUE ||
           cohesion != DEMILL_COHESION_NONE;
}

DM_INLINE void dm_tally_add(dm_tally *to, const dm_tally *from)
{
    to->diss_normal += from->diss_normal;
    to->diss_tangential += from->diss_tangential;
    to->diss_friction += from->diss_friction;
    to->diss_rolling += from->diss_rolling;
    to->wall_work += from->wall_work;
    to->diss_plastic += from->diss_plastic;
    to->diss_rolling_viscous += from->diss_rolling_viscous;
    to->work_cohesion += from->work_cohesion;
    to->diss_local += from->diss_local;
}

/* History doubles of the tangential spring's displacement (a vector in 3D,
 * which changes sign when the pair's order flips; a scalar in 2D). */
DM_INLINE int dm_law_spring_size(int tangential, int dim)
{
    if (tangential == DEMILL_TANGENTIAL_SPRING || tangential == DEMILL_TANGENTIAL_MINDLIN)
        return dim == 3 ? 3 : 1;
    return 0;
}

/* History doubles of the tangential law: the displacement, and for Mindlin
 * the spring energy of the last step. Mindlin's k_t follows δ, so its spring
 * gains or loses energy without tangential work (in LIGGGHTS as here); the
 * energy tally books that change exactly, so that the balance closes. */
DM_INLINE int dm_law_tangential_size(int tangential, int dim)
{
    return dm_law_spring_size(tangential, dim) + (tangential == DEMILL_TANGENTIAL_MINDLIN);
}

/* Boundary corrections keep a collision second-order accurate in Δt where
 * the contact force switches on or off abruptly. Entry (any dashpot): the
 * dashpot force of the first sample in contact is weighted so that its
 * impulse equals the force's integral from the moment of contact, for an
 * onset growing as age^p (p = 0 for the linear dashpot's jump, 1/4 for the
 * Tsuji dashpot); the spring starts from zero and is left alone, so that
 * elastic collisions keep Verlet's energy behaviour. Which sample is the
 * first is known, not estimated: the pair was apart at the last step (its
 * touch flag is off); only the age within the step is estimated, from the
 * overlap, and held to [0, Δt]. (An estimate cannot decide it: the
 * refinement's later iterates carry the contact's own deceleration in
 * their end velocity, so that a contact that began just after the last
 * sample looked older than a step and lost its entry impulse, which made
 * e up to 1.7 % high at e = 0.5 and 10 % at e = 0.1.) Exit (linear
 * dashpot, whose force jumps where δ reaches 0): the impulse the last sample
 * in contact missed or added is applied when the contact is found to have
 * ended, from the last normal force and overlap kept in the history. */
DM_INLINE int dm_law_entry(int damping)
{
    return damping != DEMILL_DAMPING_NONE;
}

DM_INLINE int dm_law_exit(int normal, int damping)
{
    return normal == DEMILL_NORMAL_LINEAR && damping != DEMILL_DAMPING_NONE;
}

/* History doubles of the normal law's own state (plastic laws) and of the
 * rolling law (its spring). Cohesion keeps none: whether a bond holds is
 * whether its contact is on. */
DM_INLINE int dm_law_normal_size(int normal)
{
    return dm_plastic_hist_size(normal);
}

/* The rolling spring's (DEMILL_ROLLING_SPRING): its torque on a (a vector
 * in 3D, a scalar in 2D; it changes sign when the pair's order flips), then
 * its energy at the last step, which k_r (following k_n) may have changed
 * since, as Mindlin's. */
DM_INLINE int dm_law_rolling_size(int rolling, int dim)
{
    return rolling == DEMILL_ROLLING_SPRING ? (dim == 3 ? 3 : 1) + 1 : 0;
}

/* A contact's history, in this order: the tangential law's, then (for laws
 * with the exit correction) the last normal force and overlap, then the
 * normal law's and the rolling law's; where each starts, and the doubles in
 * all. */
DM_INLINE int dm_law_off_normal(int normal, int damping, int tangential, int dim)
{
    return dm_law_tangential_size(tangential, dim) + 2 * dm_law_exit(normal, damping);
}

DM_INLINE int dm_law_off_rolling(int normal, int damping, int tangential, int dim)
{
    return dm_law_off_normal(normal, damping, tangential, dim) + dm_law_normal_size(normal);
}

DM_INLINE int dm_law_hist_size(int normal, int damping, int tangential, int rolling, int dim)
{
    return dm_law_off_rolling(normal, damping, tangential, dim) +
           dm_law_rolling_size(rolling, dim);
}

/* The factor on history slot `slot` of a particle-particle contact of laws
 * l whose two particles trade places in storage order (a becomes b): -1 for
 * what turns with the pair, the 3D tangential spring (the 2D one is a
 * scalar along a tangent that turns with n) and the rolling spring's torque
 * on a; 1 for the rest. */
DM_INLINE double dm_law_flip(dm_laws l, int dim, int slot)
{
    const int r0 = dm_law_off_rolling(l.normal, l.damping, l.tangential, dim);
    const int spring = slot < dm_law_spring_size(l.tangential, dim) && dim == 3;
    const int torque = l.rolling == DEMILL_ROLLING_SPRING && slot >= r0 &&
                       slot < r0 + (dim == 3 ? 3 : 1);
    return spring || torque ? -1.0 : 1.0;
}

/* How far apart (as a negative overlap) a pair whose contact exists still
 * interacts (cohesion's reach), 0 for a law without cohesion: the JKR neck
 * breaks at δ_c, the liquid bridge at its rupture distance (cohesion.h).
 * Whether the contact exists is the pair's `on` flag: set when it touches
 * (δ > 0), kept while it is within this range, carried over neighbour
 * rebuilds, refinement iterates and checkpoints, so that cohesion needs no
 * history of its own. */
DM_INLINE double dm_law_range(int cohesion, const dm_pairparam *pp, double rstar)
{
    if (cohesion == DEMILL_COHESION_JKR)
        return dm_jkr_reach(rstar, pp->e_star, pp->adhesion);
    if (cohesion == DEMILL_COHESION_CAPILLARY)
        return dm_capillary_reach(pp->contact_angle, pp->liquid_volume);
    return 0.0;
}

/* D: dimension; NL, DL, TL, RL, CL: DEMILL_NORMAL_*, DEMILL_DAMPING_*,
 * DEMILL_TANGENTIAL_*, DEMILL_ROLLING_*, DEMILL_COHESION_* (compile-time
 * constants in the fast kernels, run-time values in the generic one).
 * delta: the overlap, negative for a cohesive contact across a gap. vc:
 * relative velocity at the contact point at the end of the step (drives
 * dashpots and friction); dc: the rate
 * of relative displacement over the step (drives the tangential spring).
 * wrel: ω_a - ω_b at the end of the step (the rolling laws' dashpots and
 * constant torque); wd: ω_a - ω_b over the step (the rolling spring); ir:
 * the pair's moment of inertia about the contact for rolling (the rolling
 * dashpot; wd and ir are read only by DEMILL_ROLLING_SPRING).
 * dt_hist: time the history advances by (0 for an evaluation that does not
 * advance time, which leaves the history as it was); the dissipation in o
 * is over the same interval. reach: how far past a force sample its impulse
 * reaches, in steps (1/2 for velocity Verlet, whose kicks apply a sample
 * half a step either side; 1 for symplectic Euler, which applies it over the
 * following step). first: nonzero if the pair was apart at the last step,
 * so that this sample is the contact's first (the entry correction).
 * hin: the contact's history (zeros for a new contact); hout receives its
 * new value (dm_law_hist_size doubles); o, the forces and dissipation
 * (dm_law_out). The body is law_body.h, which dm_lawf() below shares.
 *
 * The law has no branches that depend on the contact: every choice selects
 * between values computed for both outcomes, so that the kernels' loops
 * over contacts vectorise. Values computed for the outcome not taken may be
 * infinite or NaN; they are discarded. */
#define DM_REAL double
#define DM_LAW_NAME dm_law
#define DM_LAW_OUT dm_law_out
#define DM_LAW_LOADS dm_law_loads
#define DM_SQRT sqrt
#define DM_FABS fabs
#include "physics/contact/law_body.h"

/* The same law in single precision (law_body.h): float arguments, history
 * and output, for the fast laws (linear or Hertz, no or constant-torque
 * rolling resistance, no cohesion) that the single-precision kernels run. */
#define DM_REAL float
#define DM_LAW_NAME dm_lawf
#define DM_LAW_OUT dm_law_outf
#define DM_LAW_LOADS dm_law_loadsf
#define DM_SQRT sqrtf
#define DM_FABS fabsf
#include "physics/contact/law_body.h"

/* Elastic energy stored in a contact of laws l with history hist: normal,
 * tangential and rolling springs. */
DM_INLINE void dm_law_stored(int dim, dm_laws l, const dm_pairparam *pp, double delta,
                             double rstar, const double *hist, double *e_normal,
                             double *e_tangential, double *e_rolling)
{
    const int NL = l.normal, TL = l.tangential;
    *e_rolling = l.rolling == DEMILL_ROLLING_SPRING
                     ? hist[dm_law_off_rolling(NL, l.damping, TL, dim) + (dim == 3 ? 3 : 1)]
                     : 0.0;
    if (NL == DEMILL_NORMAL_LINEAR) {
        *e_normal = 0.5 * pp->kn * delta * delta;
    } else if (dm_normal_plastic(NL)) { /* the current unloading curve's */
        dm_plastic_out po;
        dm_plastic_law(NL, pp, rstar, delta, hist + dm_law_off_normal(NL, l.damping, TL, dim), &po);
        *e_normal = po.stored;
    } else {
        *e_normal = 8.0 / 15.0 * pp->e_star * sqrt(rstar * delta) * delta * delta;
    }
    *e_tangential = 0.0;
    if (TL == DEMILL_TANGENTIAL_SPRING || TL == DEMILL_TANGENTIAL_MINDLIN) {
        double kt = TL == DEMILL_TANGENTIAL_SPRING ? pp->kt : pp->g8 * sqrt(rstar * delta);
        double x2 = 0.0;
        for (int c = 0; c < (dim == 3 ? 3 : 1); c++)
            x2 += hist[c] * hist[c];
        *e_tangential = 0.5 * kt * x2;
    }
}

#endif /* DM_LAW_H */
