/* conveyor.h: outputs.conveyor of the demill runner: a belt conveyor's
 * steady mass flow, the power its belt draws and the particles'
 * resistance on it, against the momentum balance F = m' (v - v_in), in
 * summary.txt, conveyor.csv and conveyor.png (docs/scene-files.md). */
#ifndef CONVEYOR_H
#define CONVEYOR_H

#include <stdio.h>

#include "run.h"
#include "scene.h"

/* The samples of a run: against time (s), the mass the outlet has removed
 * (kg), the work the belt has done on the particles (J: the energy
 * account's moving walls' work, the belt's alone) and the chute's push on
 * the particles along the belt (N, 0 without a chute). */
typedef struct conveyor_trace {
    series mass, work, chute;
} conveyor_trace;

/* Records a sample of the scene's world at time t. */
void conveyor_sample(const scene *s, conveyor_trace *tr, double t);

/* Writes the mass flow, the belt's power (its work over the window over
 * the window's length) and force (that power over the belt's speed) and
 * the momentum balance over the window from s->conveyor_from to the end to
 * the summary `sum` as key = value lines, the time series to conveyor.csv
 * and the picture conveyor.png in the folder `dir`: 0, or -1 with a
 * message on stderr. */
int conveyor_report(const scene *s, const conveyor_trace *tr, FILE *sum, const char *dir);

/* Frees the trace's series. */
void conveyor_free(conveyor_trace *tr);

#endif
