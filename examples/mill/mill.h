/* mill.h: the parts of the mill example (mill.c: options and run; scene.c:
 * the canonical drums; output.c: pictures). */
#ifndef MILL_H
#define MILL_H

#include <stddef.h>
#include <stdio.h>

#include <demill.h>

/* A packing as docs/scenes.md defines it: lattice sites of spacing 6.3 mm with
 * x² + y² <= site_radius², in `layers` layers from z0 (3D), the lowest
 * `particles` of them, jittered with Python's random.Random(12345). */
typedef struct scene_def {
    int dim;
    size_t particles;
    double site_radius;
    long layers;
    double z0;
} scene_def;

/* Positions (3 per particle) of the packing; 0, or -1 on failure. */
int scene_packing(const scene_def *s, double *pos);

/* A drum of the scenes' kind: geometry, evenly spaced square lifters. */
typedef struct drum_geometry {
    int dim;
    double time_step, diameter, length;
    int lifters;
    double lifter_size;
} drum_geometry;

/* Creates the world of the scenes: steel balls and liner (7800 kg/m³,
 * E = 1e8 Pa, ν = 0.3, restitution 0.5, friction 0.5; Hertz-Mindlin with
 * Tsuji damping, no force clamp, as LIGGGHTS without limitForce) and the
 * drum. 0, or -1 with a message on stderr. */
int scene_world(const drum_geometry *g, demill_world **w, demill_id *steel, demill_id *drum);

/* What the drawing needs of the drum. */
typedef struct drum_shape {
    int dim;
    double radius, length, angle;
    int nlifters;
    double lifter_angle[64], lifter_height, lifter_width;
} drum_shape;

/* Pictures; each returns 0 or -1 (with a message on stderr). */
int draw_charge(const char *path, demill_world *w, const drum_shape *d, const char *title);
int draw_power(const char *path, const double *t, const double *p, size_t n, double mean,
               double mean_from, double mean_to);

#endif
