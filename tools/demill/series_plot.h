/* series_plot.h: pictures: [series] of the demill runner: every column of the
 * time series but the time drawn against the time, one panel each, with its
 * name and unit (docs/scene-files.md). */
#ifndef SERIES_PLOT_H
#define SERIES_PLOT_H

#include <stddef.h>

/* One panel: the quantity's name, its unit ("1" for a pure number) and its
 * n values at the times of the plot. */
typedef struct series_panel {
    const char *name, *unit;
    const double *y;
} series_panel;

/* Draws series.png into the folder dir: the np panels stacked, sharing the
 * time axis t (n samples, s), under the title. 0, or -1 with a message on
 * stderr. */
int series_plot(const char *dir, const char *title, const double *t, size_t n,
                const series_panel *p, size_t np);

#endif
