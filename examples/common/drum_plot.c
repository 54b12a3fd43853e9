/* drum_plot.c: the pictures of a turning drum shared by the mill example and
 * the demill runner (drum_plot.h): the charge in cross-section with its toe,
 * shoulder, rotation and length scale, and the power draw against time with
 * its revolutions and start-up transient. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "drum_plot.h"
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
    if (st == DEMILL_OK)
        st = demill_drum_get(w, drum, DEMILL_DRUM_SPEED, &d->speed);
    if (st == DEMILL_OK)
        st = demill_drum_get(w, drum, DEMILL_DRUM_TOE_ANGLE_MEAN, &d->toe);
    if (st == DEMILL_OK)
        st = demill_drum_get(w, drum, DEMILL_DRUM_SHOULDER_ANGLE_MEAN, &d->shoulder);
    d->toe_mean = !isnan(d->toe) && !isnan(d->shoulder);
    if (st == DEMILL_OK && !d->toe_mean)
        st = demill_drum_get(w, drum, DEMILL_DRUM_TOE_ANGLE, &d->toe);
    if (st == DEMILL_OK && !d->toe_mean)
        st = demill_drum_get(w, drum, DEMILL_DRUM_SHOULDER_ANGLE, &d->shoulder);
    if (st != DEMILL_OK) {
        fprintf(stderr, "cannot read the drum's lifters, speed or charge: %s\n",
                demill_world_last_error(w));
        return -1;
    }
    return 0;
}

/* Text at (x, y) on a white box, its left end there (align 0), its right
 * end (align 1) or its centre (align 0.5). */
static void boxed_text(cairo_t *cr, double x, double y, double align, const char *text)
{
    cairo_text_extents_t e;
    cairo_text_extents(cr, text, &e);
    x -= align * e.x_advance;
    cairo_save(cr);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, x - 3, y + e.y_bearing - 3, e.x_advance + 6, e.height + 6);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text);
}

/* The line from the drum's centre (cx, cy) to the shell (rp pixels) at
 * charge angle phi (from the downward vertical, positive in the direction s
 * = ±1 of rotation, counter-clockwise for s = 1), labelled at 0.7 of the
 * way out. */
static void charge_line(cairo_t *cr, double cx, double cy, double rp, double phi, double s,
                        const char *label)
{
    const double ux = s * sin(phi), uy = -cos(phi); /* world direction, y up */
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, cx, cy);
    cairo_line_to(cr, cx + ux * rp, cy - uy * rp);
    cairo_stroke(cr);
    boxed_text(cr, cx + 0.7 * ux * rp, cy - 0.7 * uy * rp + 6, 0.5, label);
}

/* An arc of radius rp about (cx, cy) from the world angle a0 over a span
 * (rad, positive counter-clockwise) with an arrow head at its end. */
static void rotation_arrow(cairo_t *cr, double cx, double cy, double rp, double a0, double span)
{
    const int n = 32;
    cairo_set_line_width(cr, 3);
    for (int k = 0; k <= n; k++) {
        const double a = a0 + span * k / n;
        const double x = cx + rp * cos(a), y = cy - rp * sin(a);
        if (k == 0)
            cairo_move_to(cr, x, y);
        else
            cairo_line_to(cr, x, y);
    }
    cairo_stroke(cr);
    /* the head: along the arc's tangent at its end */
    const double a1 = a0 + span, sgn = span > 0 ? 1 : -1;
    const double ex = cx + rp * cos(a1), ey = cy - rp * sin(a1);
    const double tx = -sin(a1) * sgn, ty = -cos(a1) * sgn; /* pixel tangent */
    const double nx = -ty, ny = tx, len = 16, half = 7;
    cairo_move_to(cr, ex + tx * len, ey + ty * len);
    cairo_line_to(cr, ex + nx * half, ey + ny * half);
    cairo_line_to(cr, ex - nx * half, ey - ny * half);
    cairo_close_path(cr);
    cairo_fill(cr);
}

int draw_charge(const char *path, demill_world *w, const drum_shape *d, const char *title,
                const char *program)
{
    const int size = 900, top = 60, bar = 70, foot = 70;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(size + bar, size + top + foot, 18, &s);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 20, 36);
    cairo_show_text(cr, title);
    /* world to picture: the drum fills the square below the title */
    const double scale = 0.44 * size / d->radius, cx = 0.5 * size, cy = top + 0.5 * size;
    const double rp = d->radius * scale;
    cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
    cairo_arc(cr, cx, cy, rp, 0, 2 * PI);
    cairo_fill(cr);
    double vmax;
    if (plot_particles(cr, w, cx, cy, scale, INFINITY, program, &vmax)) {
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
    cairo_arc(cr, cx, cy, rp + 2, 0, 2 * PI);
    cairo_stroke(cr);
    /* the downward vertical the angles are measured from, dashed */
    const double sense = d->speed < 0 ? -1 : 1;
    char label[160];
    cairo_set_font_size(cr, 16);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1.5);
    cairo_set_dash(cr, (const double[2]){6, 5}, 2, 0);
    cairo_move_to(cr, cx, cy);
    cairo_line_to(cr, cx, cy + rp);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    boxed_text(cr, cx, cy + 0.35 * rp, 0.5, "0°");
    /* toe and shoulder */
    cairo_set_source_rgb(cr, 0.8, 0.1, 0.1);
    if (!isnan(d->toe)) {
        snprintf(label, sizeof label, "toe %.1f°", d->toe * 180 / PI);
        charge_line(cr, cx, cy, rp, d->toe, sense, label);
    }
    if (!isnan(d->shoulder)) {
        snprintf(label, sizeof label, "shoulder %.1f°", d->shoulder * 180 / PI);
        charge_line(cr, cx, cy, rp, d->shoulder, sense, label);
    }
    cairo_arc(cr, cx, cy, 4, 0, 2 * PI);
    cairo_fill(cr);
    /* the rotation: an arrow over 40° about the upper left corner, outside
     * the shell */
    cairo_set_source_rgb(cr, 0.1, 0.3, 0.7);
    if (d->speed != 0) {
        const double mid = 0.75 * PI, span = sense * 40 * PI / 180;
        rotation_arrow(cr, cx, cy, rp + 30, mid - 0.5 * span, span);
        snprintf(label, sizeof label, "rotation, %.3g rad/s", fabs(d->speed));
        cairo_move_to(cr, 20, top + 22);
        cairo_show_text(cr, label);
    } else {
        cairo_move_to(cr, 20, top + 30);
        cairo_show_text(cr, "drum at rest");
    }
    /* the length scale: a round length near a fifth of the diameter */
    const double len = plot_tick_step(2 * d->radius), x0 = 30, y0 = top + size + 22;
    snprintf(label, sizeof label, "%g mm", len * 1e3);
    plot_scale_bar(cr, x0, y0, len * scale, 6, 3, label);
    /* what is drawn and how the angles are read */
    cairo_set_font_size(cr, 15);
    if (d->dim == 3)
        snprintf(label, sizeof label,
                 "Seen along the axis: every particle over the drum's length of %g m, "
                 "the nearest (+z) on top.",
                 d->length);
    else
        snprintf(label, sizeof label, "2D: the drum's whole cross-section.");
    cairo_move_to(cr, x0 + len * scale + 90, y0 + 6);
    cairo_show_text(cr, label);
    snprintf(label, sizeof label,
             "Angles from the downward vertical, positive with the rotation; toe and shoulder: %s.",
             d->toe_mean ? "means over the last revolution" : "the present state (no revolution done)");
    cairo_move_to(cr, x0, y0 + 34);
    cairo_show_text(cr, label);
    plot_speed_bar(cr, size + 10, top + 60, size - 120, vmax);
    cairo_destroy(cr);
    return plot_save_png(s, path, program);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* A shaded band of the plot from time x0 to x1 in the given colour, and
 * its key (a square of the colour and the label) at (kx, ky) above the
 * plot; returns where the next key may start. */
static double shade(cairo_t *cr, const plot_area *a, double x0, double x1, const double rgb[3],
                    const char *label, double kx, double ky)
{
    x0 = fmax(x0, a->x0);
    x1 = fmin(x1, a->x1);
    if (!(x1 > x0))
        return kx;
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_rectangle(cr, plot_px(a, x0), a->tp, plot_px(a, x1) - plot_px(a, x0), a->h);
    cairo_rectangle(cr, kx, ky - 10, 12, 12);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, kx, ky - 10, 12, 12);
    cairo_stroke(cr);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label, &e);
    cairo_move_to(cr, kx + 18, ky);
    cairo_show_text(cr, label);
    return kx + 18 + e.x_advance + 24;
}

int draw_power(const char *path, const power_trace *tr, const char *program)
{
    const int wd = 1000, ht = 540, l = 90, r = 30, tp = 60, bt = 60;
    const size_t n = tr->n;
    const double *t = tr->t, *raw = tr->p;
    if (n < 2) {
        fprintf(stderr, "%s: no power samples to draw\n", program);
        return -1;
    }
    /* the power averaged over `win` samples, so that impacts do not hide the
     * trend */
    const size_t win = 10;
    double *pw = malloc(n * sizeof *pw), acc = 0;
    double *sorted = malloc(n * sizeof *sorted);
    if (!pw || !sorted) {
        free(pw);
        free(sorted);
        fprintf(stderr, "%s: out of memory\n", program);
        return -1;
    }
    for (size_t k = 0; k < n; k++) {
        acc += raw[k] - (k >= win ? raw[k - win] : 0);
        pw[k] = acc / (k + 1 < win ? k + 1 : win);
    }
    /* the vertical range covers all but the start-up's spikes: up to twice
     * the 99th percentile */
    memcpy(sorted, pw, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, cmp_double);
    double p1 = 2.0 * sorted[(size_t)(0.99 * (n - 1))];
    const double p0 = fmin(0.0, sorted[0]);
    free(sorted);
    p1 = p1 > p0 ? p1 : p0 + 1;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 13, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, t[0], t[n - 1], p0, p1};
    char label[128];
    /* the start-up transient: at rest, then turning before the measured
     * revolution */
    const double measured = isfinite(tr->mean) ? tr->mean_from : t[n - 1];
    double kx = l;
    snprintf(label, sizeof label, "drum at rest, settling (to %.3g s)", tr->start);
    kx = shade(cr, &a, t[0], fmin(tr->start, measured), (const double[3]){0.88, 0.88, 0.88}, label,
               kx, tp - 10);
    shade(cr, &a, fmax(tr->start, t[0]), measured, (const double[3]){1.0, 0.91, 0.78},
          "turning, start-up transient (not in the mean)", kx, tp - 10);
    plot_ticks(cr, &a);
    /* where each revolution ends */
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_dash(cr, (const double[2]){5, 4}, 2, 0);
    for (size_t k = 1; tr->rev && k < n; k++)
        if (floor(tr->rev[k]) > floor(tr->rev[k - 1])) {
            const double x = plot_px(&a, t[k]);
            cairo_move_to(cr, x, tp);
            cairo_line_to(cr, x, tp + a.h);
            cairo_stroke(cr);
            snprintf(label, sizeof label, "revolution %.0f ends", floor(tr->rev[k]));
            cairo_text_extents_t e;
            cairo_text_extents(cr, label, &e);
            cairo_move_to(cr, x - e.x_advance - 4, tp + 16);
            cairo_show_text(cr, label);
        }
    cairo_set_dash(cr, NULL, 0, 0);
    plot_curve(cr, &a, t, pw, n, (const double[3]){0.13, 0.37, 0.66}, 1.2);
    if (isfinite(tr->mean)) {
        cairo_set_source_rgb(cr, 0.85, 0.2, 0.1);
        cairo_set_line_width(cr, 2.5);
        cairo_move_to(cr, plot_px(&a, tr->mean_from), plot_py(&a, tr->mean));
        cairo_line_to(cr, plot_px(&a, tr->mean_to), plot_py(&a, tr->mean));
        cairo_stroke(cr);
        snprintf(label, sizeof label, "mean over the last revolution: %.2f W", tr->mean);
        cairo_move_to(cr, plot_px(&a, tr->mean_from) + 6, tp + 36);
        cairo_show_text(cr, label);
    }
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 30, "time t [s]");
    /* the vertical axis's title, turned to read upwards */
    plot_y_title(cr, 24, tp + 0.5 * a.h + 80, "power draw P = -T ω [W]");
    cairo_move_to(cr, l, 24);
    cairo_show_text(cr, "Power drawn by the drum (torque T of the charge on it, speed ω), "
                        "running mean of 10 samples");
    cairo_destroy(cr);
    free(pw);
    return plot_save_png(s, path, program);
}
