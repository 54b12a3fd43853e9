/* dissipation.h: outputs.dissipation of the demill runner: the energy each
 * dissipation mechanism of the contacts took over the last window before
 * stop.time and its share of their total, beside the loss the energy
 * balance gives over the same window (the work put in less the change of
 * the stored energies), in summary.txt; and, for a sweep, the shares
 * against the swept value in dissipation.png (docs/scene-files.md). */
#ifndef DISSIPATION_H
#define DISSIPATION_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* The energy terms at the window's first and last samples. */
#define DISSIPATION_TERMS 23
typedef struct dissipation_track {
    int started;
    double from, to;
    double first[DISSIPATION_TERMS], last[DISSIPATION_TERMS];
} dissipation_track;

/* Records the world's energy terms at time t, a sample in the window. */
void dissipation_sample(const scene *s, double t, dissipation_track *d);

/* Writes the window, each mechanism's dissipated energy and share, their
 * total and the balance's loss to the summary `sum` as key = value lines. */
void dissipation_report(const dissipation_track *d, FILE *sum);

/* When the sweep's summaries have the shares, draws them against the swept
 * key's values (numbers) into dissipation.png in `dir`: 0 (also when they
 * have none), or -1 with a message on stderr. */
int dissipation_draw_sweep(const char *dir, const char *key, char *const *values,
                           char *const *summaries, size_t n);

#endif
