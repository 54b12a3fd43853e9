/* conveyor.h: outputs.conveyor of the demill runner: a belt conveyor's
 * steady mass flow, the particles' resistance on the belt and the power
 * it draws, against the momentum balance F = m' (v - v_in), in
 * summary.txt, conveyor.csv and conveyor.png (docs/scene-files.md). */
#ifndef CONVEYOR_H
#define CONVEYOR_H

#include <stdio.h>

#include "run.h"
#include "scene.h"

/* The samples of a run: against time (s), the mass the outlet has removed
 * (kg), the belt's resistance (the particles' force on the belt's walls
 * against its motion, N) and the chute's push on the particles along the
 * belt (N, 0 without a chute). */
typedef struct conveyor_trace {
    series mass, belt, chute;
} conveyor_trace;

/* Records a sample of the scene's world at time t. */
void conveyor_sample(const scene *s, conveyor_trace *tr, double t);

/* Writes the mass flow, the belt's resistance and power and the momentum
 * balance over the window from s->conveyor_from to the end to the summary
 * `sum` as key = value lines, the time series to conveyor.csv and the
 * picture conveyor.png in the folder `dir`: 0, or -1 with a message on
 * stderr. */
int conveyor_report(const scene *s, const conveyor_trace *tr, FILE *sum, const char *dir);

/* Frees the trace's series. */
void conveyor_free(conveyor_trace *tr);

#endif
