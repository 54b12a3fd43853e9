/* shear.h: outputs.shear of the demill runner: a direct shear test (ASTM
 * D3080). Each run samples the shear stress, the normal stress and the
 * lid's rise against the shear displacement and reports the peak and
 * residual shear stresses (summary.txt, shear.csv, shear.png); a sweep over
 * the normal load fits the Mohr-Coulomb lines through its runs' points
 * (shear_box.txt, shear_stress.png, mohr_coulomb.png in the sweep's
 * folder; docs/scene-files.md). */
#ifndef SHEAR_H
#define SHEAR_H

#include <stdio.h>

#include "run.h"
#include "scene.h"

/* A run's samples: the shear stress (Pa), the normal stress on the lid
 * (Pa) and the lid's rise since the shear started (m), each against the
 * shear displacement (m); the lid's height when the shear starts. */
typedef struct shear_trace {
    series tau, sigma, rise;
    double lid0;
} shear_trace;

/* Samples s's world at time t: before the shear starts, only the lid's
 * height. */
void shear_sample(const scene *s, shear_trace *tr, double t);

/* Writes the peak and residual shear stresses, the normal stress and the
 * friction angles to the summary `sum` as key = value lines, the curve
 * averaged over outputs.shear.bin to shear.csv and draws it to shear.png
 * in the folder `dir`: 0, or -1 with a message on stderr. */
int shear_report(const scene *s, const shear_trace *tr, FILE *sum, const char *dir);

/* After a sweep of n runs into the folders dirs[k] with the summaries
 * sums[k] (summary.txt's text), when they are shear tests: the
 * Mohr-Coulomb lines through their peak and their residual points, in
 * shear_box.txt, with shear_stress.png (every run's curve) and
 * mohr_coulomb.png in the folder `out`, and a line on stdout. 0 (also when
 * the runs are no shear tests, fewer than 2 or more than 16), or -1 with
 * a message on stderr. */
int shear_sweep_report(const char *out, char *const *dirs, char *const *sums, size_t n);

/* Frees the trace's series. */
void shear_trace_free(shear_trace *tr);

#endif
