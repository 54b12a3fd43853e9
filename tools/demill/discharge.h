/* discharge.h: outputs.discharge of the demill runner: an outlet's steady
 * discharge rate, fitted over the middle of the discharge, against Beverloo's
 * correlation for the orifice with Rose and Tanaka's factor for a conical
 * hopper, in summary.txt and discharge.png (docs/scene-files.md). */
#ifndef DISCHARGE_H
#define DISCHARGE_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* The solid fraction in s's bulk region now: the volume of the particles
 * whose centres lie in it over the region's volume. */
double discharge_solid_fraction(const scene *s);

/* The samples of a discharge: time t (s), the mass the outlet has removed
 * (kg) and the bulk region's solid fraction at n samples, and the
 * particles' mean diameter (m) and density (kg/m³) at the start. */
typedef struct discharge_trace {
    const double *t, *mass, *phi;
    size_t n;
    double diameter, density;
} discharge_trace;

/* Writes the rate and the correlations to the summary `sum` as key = value
 * lines and draws discharge.png in the folder `dir`: 0, or -1 with a
 * message on stderr. */
int discharge_report(const scene *s, const discharge_trace *tr, FILE *sum, const char *dir);

#endif
