/* repose.h: outputs.repose of the demill runner: the angle of repose of
 * the heap the particles form about a vertical axis (y up), from the
 * heap's surface profile (examples/common/heap.h), in summary.txt and
 * repose.png (docs/scene-files.md). */
#ifndef REPOSE_H
#define REPOSE_H

#include <stdio.h>

#include "scene.h"

/* Measures the heap of s's world now, writes its angle, height and fit to
 * the summary `sum` as key = value lines and draws repose.png in the
 * folder `dir`: 0, or -1 with a message on stderr. */
int repose_report(const scene *s, FILE *sum, const char *dir);

#endif
