/* output.c: the pictures the mill example draws with cairo (the charge in
 * cross-section coloured by speed, the power draw against time and, with
 * --ore, the feed's and product's size distributions); its VTK files come
 * from the library (demill/vtk.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "mill.h"
#include "plot.h"

#define PI 3.14159265358979323846

/* The visible cross-section of lifter k in the world frame (4 corners):
 * centre line at its angle, from the shell inwards by its height, its width
 * at the shell (rectangular lifters, as the example makes them). */
static void lifter_corners(const drum_shape *d, int k, double xy[8])
{
    const double a = d->lifter_angle[k], ux = cos(a), uy = sin(a), tx = -uy, ty = ux;
    const double rb = d->radius, ri = d->radius - d->lifter_height;
    const double hw = 0.5 * d->lifter_width, rt[4][2] = {{ri, -hw}, {rb, -hw}, {rb, hw}, {ri, hw}};
    for (int c = 0; c < 4; c++) {
        xy[2 * c] = rt[c][0] * ux + rt[c][1] * tx;
        xy[2 * c + 1] = rt[c][0] * uy + rt[c][1] * ty;
    }
}

int drum_shape_read(demill_world *w, demill_id drum, drum_shape *d)
{
    double v[5];
    demill_status st = demill_world_get(w, DEMILL_WORLD_DIMENSION, &v[0]);
    const int32_t keys[4] = {DEMILL_DRUM_DIAMETER, DEMILL_DRUM_LENGTH, DEMILL_DRUM_ANGLE,
                             DEMILL_DRUM_LIFTER_COUNT};
    for (int k = 0; k < 4 && st == DEMILL_OK; k++)
        st = demill_drum_get(w, drum, keys[k], &v[k + 1]);
    if (st != DEMILL_OK || v[4] > 64) {
        fprintf(stderr, "cannot read the drum: %s\n", demill_world_last_error(w));
        return -1;
    }
    d->dim = (int)v[0];
    d->radius = 0.5 * v[1];
    d->length = v[2];
    d->angle = v[3];
    d->nlifters = (int)v[4];
    st = demill_drum_get(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, &d->lifter_height);
    if (st == DEMILL_OK)
        st = demill_drum_get(w, drum, DEMILL_DRUM_LIFTER_WIDTH, &d->lifter_width);
    for (int k = 0; k < d->nlifters && st == DEMILL_OK; k++)
        st = demill_drum_lifter_get(w, drum, (uint32_t)k, DEMILL_LIFTER_ANGLE, &d->lifter_angle[k]);
    if (st != DEMILL_OK) {
        fprintf(stderr, "cannot read the drum's lifters: %s\n", demill_world_last_error(w));
        return -1;
    }
    return 0;
}

int draw_charge(const char *path, demill_world *w, const drum_shape *d, const char *title)
{
    const int size = 900, top = 60, bar = 70;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(size + bar, size + top, 18, &s);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 20, 36);
    cairo_show_text(cr, title);
    /* world to picture: the drum fills the square below the title */
    const double scale = 0.46 * size / d->radius, cx = 0.5 * size, cy = top + 0.5 * size;
    cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
    cairo_arc(cr, cx, cy, d->radius * scale, 0, 2 * PI);
    cairo_fill(cr);
    double vmax;
    if (plot_particles(cr, w, cx, cy, scale, INFINITY, "mill", &vmax)) {
        cairo_destroy(cr);
        cairo_surface_destroy(s);
        return -1;
    }
    cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    for (int l = 0; l < d->nlifters; l++) {
        double xy[8];
        lifter_corners(d, l, xy);
        cairo_move_to(cr, cx + xy[0] * scale, cy - xy[1] * scale);
        for (int c = 1; c < 4; c++)
            cairo_line_to(cr, cx + xy[2 * c] * scale, cy - xy[2 * c + 1] * scale);
        cairo_close_path(cr);
        cairo_fill(cr);
    }
    cairo_set_line_width(cr, 4);
    cairo_arc(cr, cx, cy, d->radius * scale + 2, 0, 2 * PI);
    cairo_stroke(cr);
    plot_speed_bar(cr, size + 10, top + 60, size - 120, vmax);
    cairo_destroy(cr);
    return plot_save_png(s, path, "mill");
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int draw_power(const char *path, const double *t, const double *raw, size_t n, double mean,
               double mean_from, double mean_to)
{
    const int wd = 1000, ht = 520, l = 80, r = 30, tp = 50, bt = 60;
    if (n < 2) {
        fprintf(stderr, "mill: no power samples to draw\n");
        return -1;
    }
    /* the power averaged over `win` samples, so that impacts do not hide the
     * trend */
    const size_t win = 10;
    double *pw = malloc(n * sizeof *pw), acc = 0;
    if (!pw)
        return -1;
    for (size_t k = 0; k < n; k++) {
        acc += raw[k] - (k >= win ? raw[k - win] : 0);
        pw[k] = acc / (k + 1 < win ? k + 1 : win);
    }
    /* the vertical range covers all but the start-up transient: up to twice
     * the 99th percentile */
    double t0 = t[0], t1 = t[n - 1], p0 = 0, p1 = 0;
    double *sorted = malloc(n * sizeof *sorted);
    if (!sorted) {
        free(pw);
        return -1;
    }
    memcpy(sorted, pw, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, cmp_double);
    p1 = 2.0 * sorted[(size_t)(0.99 * (n - 1))];
    p0 = fmin(0.0, sorted[0]);
    free(sorted);
    p1 = p1 > p0 ? p1 : p0 + 1;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 13, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, t0, t1, p0, p1};
    char label[64];
    plot_ticks(cr, &a);
    plot_curve(cr, &a, t, pw, n, (const double[3]){0.13, 0.37, 0.66}, 1.2);
    if (isfinite(mean)) {
        cairo_set_source_rgb(cr, 0.85, 0.2, 0.1);
        cairo_set_line_width(cr, 2.5);
        cairo_move_to(cr, plot_px(&a, mean_from), plot_py(&a, mean));
        cairo_line_to(cr, plot_px(&a, mean_to), plot_py(&a, mean));
        cairo_stroke(cr);
        snprintf(label, sizeof label, "mean over the last revolution: %.2f W", mean);
        cairo_move_to(cr, plot_px(&a, mean_from), tp + 20);
        cairo_show_text(cr, label);
    }
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 30, "time [s]");
    cairo_move_to(cr, l, 32);
    cairo_show_text(cr, "power draw P = -T ω [W], running mean of 10 samples");
    cairo_destroy(cr);
    free(pw);
    return plot_save_png(s, path, "mill");
}

int draw_product(const char *path, const ore_result *r, const char *title)
{
    const int wd = 1000, ht = 560, l = 80, r_ = 30, tp = 60, bt = 60;
    /* the log size axis over the classes' limits but the sink's 0 */
    const double lx0 = log10(r->limits[r->n - 1]), lx1 = log10(r->limits[0]);
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 13, &s);
    const plot_area a = {l, tp, wd - l - r_, ht - tp - bt, lx0, lx1, 0, 100};
    char label[96];
    /* decades and 2, 5 within them, in mm */
    for (double dec = floor(lx0); dec <= lx1; dec += 1)
        for (int m = 1; m <= 5; m += m == 1 ? 1 : 3) {
            const double lx = dec + log10(m);
            if (lx < lx0 - 1e-9 || lx > lx1 + 1e-9)
                continue;
            snprintf(label, sizeof label, "%g", 1e3 * pow(10, lx));
            plot_grid(cr, plot_px(&a, lx), tp, plot_px(&a, lx), ht - bt, plot_px(&a, lx) - 8,
                      ht - bt + 18, label);
        }
    for (int pk = 0; pk <= 100; pk += 20) {
        snprintf(label, sizeof label, "%d", pk);
        plot_grid(cr, l, plot_py(&a, pk), wd - r_, plot_py(&a, pk), l - 35, plot_py(&a, pk) + 4,
                  label);
    }
    /* the curves through (upper limit, passing) of every class but the sink */
    const double colour[2][3] = {{0.45, 0.45, 0.45}, {0.13, 0.37, 0.66}};
    for (int c = 0; c < 2; c++) {
        const double *p = c ? r->product_passing : r->feed_passing;
        cairo_set_source_rgb(cr, colour[c][0], colour[c][1], colour[c][2]);
        cairo_set_line_width(cr, 2.2);
        for (uint32_t k = 0; k < r->n; k++) {
            const double x = plot_px(&a, log10(r->limits[k])), y = plot_py(&a, 100 * p[k]);
            if (k == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        cairo_stroke(cr);
        cairo_move_to(cr, l + 20, tp + 22 + 20 * c);
        snprintf(label, sizeof label, c ? "product: P80 %.3g mm" : "feed: F80 %.3g mm",
                 1e3 * (c ? r->p80 : r->f80));
        cairo_show_text(cr, label);
    }
    plot_frame(cr, l, tp, wd - l - r_, ht - tp - bt, ht, wd / 2 - 40, "size [mm], log scale");
    cairo_move_to(cr, l, 25);
    cairo_show_text(cr, title);
    cairo_move_to(cr, l, 47);
    cairo_show_text(cr, "cumulative mass passing [%]");
    cairo_destroy(cr);
    return plot_save_png(s, path, "mill");
}
