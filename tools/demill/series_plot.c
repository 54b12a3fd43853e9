/* series_plot.c: pictures: [series] of the demill runner: the time series'
 * columns against the time, one panel each, sharing the time axis. */
#include <math.h>
#include <stdio.h>

#include "plot.h"
#include "series_plot.h"

#define PI 3.14159265358979323846

/* The range of y over n samples, widened where it is flat so that a constant
 * still gets an axis; NaNs are skipped. */
static void range_of(const double *y, size_t n, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t k = 0; k < n; k++)
        if (isfinite(y[k])) {
            *lo = fmin(*lo, y[k]);
            *hi = fmax(*hi, y[k]);
        }
    if (!(*lo <= *hi)) {
        *lo = -1;
        *hi = 1;
    }
    const double pad = *hi > *lo ? 0.06 * (*hi - *lo) : fmax(1e-12, 0.1 * fabs(*lo));
    *lo -= pad;
    *hi += pad;
}

int series_plot(const char *dir, const char *title, const double *t, size_t n,
                const series_panel *p, size_t np)
{
    const int wd = 1000, l = 110, r = 30, tp = 70, bt = 64, ph = 190, gap = 44;
    const int ht = tp + (int)np * ph + (int)(np ? np - 1 : 0) * gap + bt;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    char text[300];
    for (size_t k = 0; k < np; k++) {
        const double top = tp + (double)k * (ph + gap);
        plot_area a = {l, top, wd - l - r, ph, t[0], n > 1 ? t[n - 1] : t[0] + 1, 0, 0};
        range_of(p[k].y, n, &a.y0, &a.y1);
        plot_ticks(cr, &a);
        plot_curve(cr, &a, t, p[k].y, n, (const double[3]){0.13, 0.37, 0.66}, 1.6);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1.5);
        cairo_rectangle(cr, a.l, a.tp, a.w, a.h);
        cairo_stroke(cr);
        cairo_move_to(cr, l, top - 10);
        cairo_show_text(cr, p[k].name);
        /* the unit as the y axis's title; "1" is a pure number */
        snprintf(text, sizeof text, "[%s]", p[k].unit && *p[k].unit ? p[k].unit : "1");
        cairo_text_extents_t e;
        cairo_text_extents(cr, text, &e);
        plot_y_title(cr, 24, top + 0.5 * ph + 0.5 * e.width, text);
    }
    const double last = tp + (double)(np ? np - 1 : 0) * (ph + gap);
    plot_frame(cr, l, last, wd - l - r, ph, ht, wd / 2 - 30, "time t [s]");
    cairo_move_to(cr, l, 28);
    cairo_show_text(cr, title);
    return plot_finish(cr, s, dir, "series.png", "demill");
}
