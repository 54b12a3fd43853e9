/* output.c: the pictures the mill example draws with cairo (the charge in
 * cross-section coloured by speed, the power draw against time and, with
 * --ore, the feed's and product's size distributions); its VTK files come
 * from the library (demill/vtk.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "mill.h"

#define PI 3.14159265358979323846

/* Reads a field of every particle (3 or 1 doubles each); the caller frees
 * it. */
static double *read_field(demill_world *w, int field, size_t *n)
{
    demill_particles_read(w, field, NULL, 0, n);
    double *out = malloc((*n ? *n : 1) * 3 * sizeof *out);
    if (out && demill_particles_read(w, field, out, *n, n) != DEMILL_OK) {
        free(out);
        out = NULL;
    }
    return out;
}

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

/* ---- pictures ------------------------------------------------------------------- */

/* A perceptually even colour map (viridis, 5 stops) for t in [0, 1]. */
static void colour(double t, double rgb[3])
{
    static const double stops[5][3] = {{0.267, 0.005, 0.329},
                                       {0.229, 0.322, 0.546},
                                       {0.128, 0.567, 0.551},
                                       {0.369, 0.789, 0.383},
                                       {0.993, 0.906, 0.144}};
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const double x = t * 4;
    const int k = x >= 4 ? 3 : (int)x;
    for (int c = 0; c < 3; c++)
        rgb[c] = stops[k][c] + (x - k) * (stops[k + 1][c] - stops[k][c]);
}

static int save_png(cairo_surface_t *s, const char *path)
{
    cairo_status_t st = cairo_surface_write_to_png(s, path);
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "mill: cannot write %s: %s\n", path, cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

/* A white canvas of wd × ht pixels for a picture, with the pictures' font at
 * font_size and lines 1 pixel wide. */
static cairo_t *canvas(int wd, int ht, double font_size, cairo_surface_t **s)
{
    *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, wd, ht);
    cairo_t *cr = cairo_create(*s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, font_size);
    cairo_set_line_width(cr, 1);
    return cr;
}

typedef struct drawn {
    double x, y, z, r, speed;
} drawn;

static int cmp_depth(const void *a, const void *b)
{
    const drawn *p = a, *q = b;
    return (p->z > q->z) - (p->z < q->z);
}

int draw_charge(const char *path, demill_world *w, const drum_shape *d, const char *title)
{
    const int size = 900, top = 60, bar = 70;
    size_t n;
    double *x = read_field(w, DEMILL_PARTICLE_POSITION, &n);
    double *v = read_field(w, DEMILL_PARTICLE_VELOCITY, &n);
    double *r = read_field(w, DEMILL_PARTICLE_RADIUS, &n);
    drawn *p = malloc((n ? n : 1) * sizeof *p);
    if (!x || !v || !r || !p) {
        free(x);
        free(v);
        free(r);
        free(p);
        fprintf(stderr, "mill: cannot read the particles for %s\n", path);
        return -1;
    }
    double vmax = 1e-9;
    for (size_t k = 0; k < n; k++) {
        p[k] = (drawn){x[3 * k], x[3 * k + 1], x[3 * k + 2], r[k],
                       hypot(hypot(v[3 * k], v[3 * k + 1]), v[3 * k + 2])};
        vmax = fmax(vmax, p[k].speed);
    }
    qsort(p, n, sizeof *p, cmp_depth); /* far (-z) first, near last */
    cairo_surface_t *s;
    cairo_t *cr = canvas(size + bar, size + top, 18, &s);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 20, 36);
    cairo_show_text(cr, title);
    /* world to picture: the drum fills the square below the title */
    const double scale = 0.46 * size / d->radius, cx = 0.5 * size, cy = top + 0.5 * size;
    cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
    cairo_arc(cr, cx, cy, d->radius * scale, 0, 2 * PI);
    cairo_fill(cr);
    for (size_t k = 0; k < n; k++) {
        double rgb[3];
        colour(p[k].speed / vmax, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_arc(cr, cx + p[k].x * scale, cy - p[k].y * scale, p[k].r * scale, 0, 2 * PI);
        cairo_fill(cr);
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
    /* colour bar */
    const double bx = size + 10, by = top + 60, bh = size - 120;
    for (int k = 0; k < (int)bh; k++) {
        double rgb[3];
        colour(1.0 - k / bh, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_rectangle(cr, bx, by + k, 20, 1);
        cairo_fill(cr);
    }
    char label[64];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 14);
    snprintf(label, sizeof label, "%.2f m/s", vmax);
    cairo_move_to(cr, bx - 10, by - 10);
    cairo_show_text(cr, label);
    cairo_move_to(cr, bx, by + bh + 20);
    cairo_show_text(cr, "0");
    cairo_move_to(cr, bx - 5, by + bh + 40);
    cairo_show_text(cr, "speed");
    cairo_destroy(cr);
    free(x);
    free(v);
    free(r);
    free(p);
    return save_png(s, path);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* A round number near span/5 for axis ticks. */
static double tick_step(double span)
{
    const double raw = span / 5, mag = pow(10, floor(log10(raw))), f = raw / mag;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

/* A grid line from (x0, y0) to (x1, y1) and its label at (lx, ly). */
static void plot_grid(cairo_t *cr, double x0, double y0, double x1, double y1, double lx,
                      double ly, const char *label)
{
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, lx, ly);
    cairo_show_text(cr, label);
}

/* The frame of the plot area (left l, top tp, w × h) and the x axis's
 * title, centred about x_title_at at the bottom of a canvas ht high. */
static void plot_frame(cairo_t *cr, double l, double tp, double w, double h, double ht,
                       double x_title_at, const char *x_title)
{
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.5);
    cairo_rectangle(cr, l, tp, w, h);
    cairo_stroke(cr);
    cairo_set_font_size(cr, 15);
    cairo_move_to(cr, x_title_at, ht - 15);
    cairo_show_text(cr, x_title);
}

int draw_power(const char *path, const double *t, const double *pw, size_t n, double mean,
               double mean_from, double mean_to)
{
    const int wd = 1000, ht = 520, l = 80, r = 30, tp = 50, bt = 60;
    if (n < 2) {
        fprintf(stderr, "mill: no power samples to draw\n");
        return -1;
    }
    /* the vertical range covers all but the start-up transient: up to twice
     * the 99th percentile */
    double t0 = t[0], t1 = t[n - 1], p0 = 0, p1 = 0;
    double *sorted = malloc(n * sizeof *sorted);
    if (!sorted)
        return -1;
    memcpy(sorted, pw, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, cmp_double);
    p1 = 2.0 * sorted[(size_t)(0.99 * (n - 1))];
    p0 = fmin(0.0, sorted[0]);
    free(sorted);
    p1 = p1 > p0 ? p1 : p0 + 1;
    cairo_surface_t *s;
    cairo_t *cr = canvas(wd, ht, 13, &s);
    const double sx = (wd - l - r) / (t1 - t0), sy = (ht - tp - bt) / (p1 - p0);
#define PX(tt) (l + ((tt) - t0) * sx)
#define PY(pp) (ht - bt - ((pp) - p0) * sy)
    char label[64];
    const double dtk = tick_step(t1 - t0), dpk = tick_step(p1 - p0);
    for (double tk = ceil(t0 / dtk) * dtk; tk <= t1 + 1e-12; tk += dtk) {
        snprintf(label, sizeof label, "%g", tk);
        plot_grid(cr, PX(tk), tp, PX(tk), ht - bt, PX(tk) - 8, ht - bt + 18, label);
    }
    for (double pk = ceil(p0 / dpk) * dpk; pk <= p1 + 1e-12; pk += dpk) {
        snprintf(label, sizeof label, "%g", pk);
        plot_grid(cr, l, PY(pk), wd - r, PY(pk), l - 45, PY(pk) + 4, label);
    }
    cairo_save(cr);
    cairo_rectangle(cr, l, tp, wd - l - r, ht - tp - bt);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.13, 0.37, 0.66);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, PX(t[0]), PY(pw[0]));
    for (size_t k = 1; k < n; k++)
        cairo_line_to(cr, PX(t[k]), PY(pw[k]));
    cairo_stroke(cr);
    cairo_restore(cr);
    if (isfinite(mean)) {
        cairo_set_source_rgb(cr, 0.85, 0.2, 0.1);
        cairo_set_line_width(cr, 2.5);
        cairo_move_to(cr, PX(mean_from), PY(mean));
        cairo_line_to(cr, PX(mean_to), PY(mean));
        cairo_stroke(cr);
        snprintf(label, sizeof label, "mean over the last revolution: %.2f W", mean);
        cairo_move_to(cr, PX(mean_from), tp + 20);
        cairo_show_text(cr, label);
    }
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 30, "time [s]");
    cairo_move_to(cr, l, 32);
    cairo_show_text(cr, "power draw P = -T ω [W], 10 ms running mean");
#undef PX
#undef PY
    cairo_destroy(cr);
    return save_png(s, path);
}

int draw_product(const char *path, const ore_result *r, const char *title)
{
    const int wd = 1000, ht = 560, l = 80, r_ = 30, tp = 60, bt = 60;
    /* the log size axis over the classes' limits but the sink's 0 */
    const double lx0 = log10(r->limits[r->n - 1]), lx1 = log10(r->limits[0]);
    cairo_surface_t *s;
    cairo_t *cr = canvas(wd, ht, 13, &s);
    const double sx = (wd - l - r_) / (lx1 - lx0), sy = (ht - tp - bt) / 100.0;
#define PX(lx) (l + ((lx) - lx0) * sx)
#define PY(pp) (ht - bt - (pp) * sy)
    char label[96];
    /* decades and 2, 5 within them, in mm */
    for (double dec = floor(lx0); dec <= lx1; dec += 1)
        for (int m = 1; m <= 5; m += m == 1 ? 1 : 3) {
            const double lx = dec + log10(m);
            if (lx < lx0 - 1e-9 || lx > lx1 + 1e-9)
                continue;
            snprintf(label, sizeof label, "%g", 1e3 * pow(10, lx));
            plot_grid(cr, PX(lx), tp, PX(lx), ht - bt, PX(lx) - 8, ht - bt + 18, label);
        }
    for (int pk = 0; pk <= 100; pk += 20) {
        snprintf(label, sizeof label, "%d", pk);
        plot_grid(cr, l, PY(pk), wd - r_, PY(pk), l - 35, PY(pk) + 4, label);
    }
    /* the curves through (upper limit, passing) of every class but the sink */
    const double colour[2][3] = {{0.45, 0.45, 0.45}, {0.13, 0.37, 0.66}};
    for (int c = 0; c < 2; c++) {
        const double *p = c ? r->product_passing : r->feed_passing;
        cairo_set_source_rgb(cr, colour[c][0], colour[c][1], colour[c][2]);
        cairo_set_line_width(cr, 2.2);
        for (uint32_t k = 0; k < r->n; k++) {
            const double x = PX(log10(r->limits[k])), y = PY(100 * p[k]);
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
#undef PX
#undef PY
    cairo_destroy(cr);
    return save_png(s, path);
}
