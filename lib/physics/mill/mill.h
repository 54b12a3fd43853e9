/* mill.h: the mill drum: its walls built from a few numbers, its speed, and
 * its measurements (drum.c), and the charge's shape (shape.c). Uses the
 * base, the state, the geometry and the contact lists. */
#ifndef DM_MILL_H
#define DM_MILL_H

#include "physics/state/state.h"

/* The drum's speed at `time` and (through theta) its angle. */
double dm_drum_omega_at(const dm_drum *d, double time, double *theta);
/* Moves the drum to `time`, then every wall (the drum's walls turn with it). */
void dm_drum_advance(demill_world *w, double time);
/* Sets one of the drum's translation keys (DEMILL_DRUM_CENTER_X ..
 * DEMILL_DRUM_VIBRATION_PHASE), the motion restarting now from where the
 * centre is. */
void dm_drum_set_motion(demill_world *w, int32_t key, double value);
/* The power the drum delivers, -(T_z ω + F·v), from the torque about its
 * axis and the force on it. */
double dm_drum_power(const dm_drum *d, double torque, const double force[3]);
/* Critical speed √(2 g / (D - d)); NaN when undefined. */
double dm_drum_critical_speed(const demill_world *w);
/* The target speed in rad/s the speed key and value ask for; NaN for a
 * fraction of an undefined critical speed. */
double dm_drum_target_speed(const demill_world *w);
/* Starts moving towards `target` from the current speed at the current time. */
void dm_drum_retarget(demill_world *w, double target);
/* Before a run: a speed given as a fraction of critical follows the charge. */
demill_status dm_drum_prepare(demill_world *w);

/* The drum's walls (shell, caps in 3D, lifters) from its numbers, replacing
 * the old ones; removed. */
demill_status dm_drum_walls_build(demill_world *w);
void dm_drum_walls_remove(demill_world *w);
/* n lifters evenly spaced, of the drum's lifter dimensions. */
void dm_drum_even_lifters(dm_drum *d, uint32_t n);
/* Whether a lifter is valid in a drum of this diameter, as
 * demill_drum_add_lifter() checks it: finite, its height, width and face
 * angle within their keys' bounds, not reaching the axis, not wider than the
 * drum, with a top left by its face angle. */
demill_status dm_drum_check_lifter(demill_world *w, const dm_lifter_spec *l, double diameter);

/* After a force evaluation: torque, power, lifter loads, and the means of
 * completed revolutions. */
void dm_drum_measure(demill_world *w);
/* The load the particles put on the drum's walls: returns the z-torque
 * about the axis and, when force is not NULL, stores the force. */
double dm_drum_load(const demill_world *w, double *force);
/* The power from the charge's centre of mass at speed omega. */
double dm_drum_power_cm(const demill_world *w, double omega);
/* The charge's toe, shoulder and centre-of-mass angles (shape.c). */
void dm_charge_shape(const demill_world *w, double angles[3]);

#endif /* DM_MILL_H */
