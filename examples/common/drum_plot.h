/* drum_plot.h: the pictures of a turning drum that the mill example and the
 * demill runner share: the charge in cross-section (charge.png) with its toe
 * and shoulder, the direction of rotation, a length scale and what part of
 * the charge it shows, and the power draw against time (power.png) with its
 * revolutions and start-up transient marked. */
#ifndef DRUM_PLOT_H
#define DRUM_PLOT_H

#include <stddef.h>

#include <demill.h>

/* What the drawing needs of the drum. */
typedef struct drum_shape {
    int dim;
    double radius, length, angle;
    int nlifters;
    double lifter_angle[64], lifter_height, lifter_width;
    /* the drum's speed (rad/s, positive counter-clockwise seen along -z) and
     * the charge's toe and shoulder angles (rad, from the downward vertical,
     * positive in the direction of rotation: demill/drum.h); toe_mean is 1
     * when they are the means over the last completed revolution (what the
     * summaries report), 0 when no revolution is complete and they are the
     * present state's */
    double speed, toe, shoulder;
    int toe_mean;
} drum_shape;

/* Reads what the drawing needs of the drum from the world: 0, or -1 with a
 * message on stderr. */
int drum_shape_read(demill_world *w, demill_id drum, drum_shape *d);

/* Draws the charge seen along the drum's axis (-z) to the PNG file `path`:
 * the particles coloured by speed, the lifters and shell, lines from the
 * centre to the toe and shoulder labelled with their angles, an arrow in the
 * direction of rotation, a length scale and a caption saying which particles
 * are drawn. `program` names the caller in messages. 0, or -1 with a message
 * on stderr. */
int draw_charge(const char *path, demill_world *w, const drum_shape *d, const char *title,
                const char *program);

/* The power samples and their marks for draw_power(): time t[k] (s), power
 * p[k] (W) and the drum's completed revolutions rev[k] at n samples; the
 * drum starts turning at `start` (s); `mean` (W, NaN: none) is the mean
 * power over [mean_from, mean_to] (s). */
typedef struct power_trace {
    const double *t, *p, *rev;
    size_t n;
    double start, mean, mean_from, mean_to;
} power_trace;

/* Draws the power against time to the PNG file `path`, averaged over 10
 * samples so that impacts do not hide the trend: both axes titled with
 * their units, a dashed line where each revolution ends, the start-up
 * transient (at rest, then turning before the measured revolution) shaded
 * and labelled, and the mean over the measured span. 0, or -1 with a
 * message on stderr. */
int draw_power(const char *path, const power_trace *tr, const char *program);

#endif
