/* plot.c: the cairo drawing the example programs share (plot.h): canvas,
 * PNG output, colour map, particles coloured by speed, and the parts of an
 * x-y plot. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "plot.h"

#define PI 3.14159265358979323846

cairo_t *plot_canvas(int wd, int ht, double font_size, cairo_surface_t **s)
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

int plot_save_png(cairo_surface_t *s, const char *path, const char *program)
{
    cairo_status_t st = cairo_surface_write_to_png(s, path);
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "%s: cannot write %s: %s\n", program, path, cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

int plot_finish(cairo_t *cr, cairo_surface_t *s, const char *dir, const char *name,
                const char *program)
{
    cairo_destroy(cr);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return plot_save_png(s, path, program);
}

void plot_colour(double t, double rgb[3])
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

double *plot_read_field(demill_world *w, int field, size_t *n)
{
    demill_particles_read(w, field, NULL, 0, n);
    double *out = malloc((*n ? *n : 1) * 3 * sizeof *out);
    if (out && demill_particles_read(w, field, out, *n, n) != DEMILL_OK) {
        free(out);
        out = NULL;
    }
    return out;
}

typedef struct drawn {
    double x, y, z, r, speed;
} drawn;

static int cmp_depth(const void *a, const void *b)
{
    const drawn *p = a, *q = b;
    return (p->z > q->z) - (p->z < q->z);
}

int plot_particles(cairo_t *cr, demill_world *w, double cx, double cy, double scale, double zmax,
                   const char *program, double *vmax)
{
    size_t n;
    double *x = plot_read_field(w, DEMILL_PARTICLE_POSITION, &n);
    double *v = plot_read_field(w, DEMILL_PARTICLE_VELOCITY, &n);
    double *r = plot_read_field(w, DEMILL_PARTICLE_RADIUS, &n);
    drawn *p = malloc((n ? n : 1) * sizeof *p);
    const int status = x && v && r && p ? 0 : -1;
    *vmax = 1e-9;
    if (status) {
        fprintf(stderr, "%s: cannot read the particles to draw them\n", program);
        n = 0;
    }
    size_t m = 0;
    for (size_t k = 0; k < n; k++) {
        const double speed = hypot(hypot(v[3 * k], v[3 * k + 1]), v[3 * k + 2]);
        *vmax = fmax(*vmax, speed);
        if (fabs(x[3 * k + 2]) <= zmax)
            p[m++] = (drawn){x[3 * k], x[3 * k + 1], x[3 * k + 2], r[k], speed};
    }
    if (m)
        qsort(p, m, sizeof *p, cmp_depth); /* far (-z) first, near last */
    for (size_t k = 0; k < m; k++) {
        double rgb[3];
        plot_colour(p[k].speed / *vmax, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_arc(cr, cx + p[k].x * scale, cy - p[k].y * scale, p[k].r * scale, 0, 2 * PI);
        cairo_fill(cr);
    }
    free(x);
    free(v);
    free(r);
    free(p);
    return status;
}

void plot_speed_bar(cairo_t *cr, double bx, double by, double bh, double vmax)
{
    for (int k = 0; k < (int)bh; k++) {
        double rgb[3];
        plot_colour(1.0 - k / bh, rgb);
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
}

double plot_tick_step(double span)
{
    const double raw = span / 5, mag = pow(10, floor(log10(raw))), f = raw / mag;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

void plot_grid(cairo_t *cr, double x0, double y0, double x1, double y1, double lx, double ly,
               const char *label)
{
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, lx, ly);
    cairo_show_text(cr, label);
}

void plot_frame(cairo_t *cr, double l, double tp, double w, double h, double ht,
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

double plot_px(const plot_area *a, double x)
{
    return a->l + (x - a->x0) * (a->w / (a->x1 - a->x0));
}

double plot_py(const plot_area *a, double y)
{
    return a->tp + a->h - (y - a->y0) * (a->h / (a->y1 - a->y0));
}

void plot_ticks(cairo_t *cr, const plot_area *a)
{
    char label[64];
    const double bottom = a->tp + a->h, right = a->l + a->w;
    const double dx = plot_tick_step(a->x1 - a->x0), dy = plot_tick_step(a->y1 - a->y0);
    /* (a value within 1e-9 of a step from 0 is 0, not the -5.55e-17 the sum
     * of steps may leave) */
    for (double x = ceil(a->x0 / dx) * dx; x <= a->x1 + 1e-12; x += dx) {
        snprintf(label, sizeof label, "%g", fabs(x) < 1e-9 * dx ? 0.0 : x);
        plot_grid(cr, plot_px(a, x), a->tp, plot_px(a, x), bottom, plot_px(a, x) - 8, bottom + 18,
                  label);
    }
    for (double y = ceil(a->y0 / dy) * dy; y <= a->y1 + 1e-12; y += dy) {
        snprintf(label, sizeof label, "%g", fabs(y) < 1e-9 * dy ? 0.0 : y);
        cairo_text_extents_t e; /* right-aligned, clear of the frame */
        cairo_text_extents(cr, label, &e);
        plot_grid(cr, a->l, plot_py(a, y), right, plot_py(a, y), a->l - 8 - e.x_advance,
                  plot_py(a, y) + 4, label);
    }
}

void plot_curve(cairo_t *cr, const plot_area *a, const double *x, const double *y, size_t n,
                const double rgb[3], double width)
{
    cairo_save(cr);
    cairo_rectangle(cr, a->l, a->tp, a->w, a->h);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, width);
    cairo_move_to(cr, plot_px(a, x[0]), plot_py(a, y[0]));
    for (size_t k = 1; k < n; k++)
        cairo_line_to(cr, plot_px(a, x[k]), plot_py(a, y[k]));
    cairo_stroke(cr);
    cairo_restore(cr);
}

void plot_line_key(cairo_t *cr, const plot_area *a, double xc, double yc, double slope, double x0,
                   double x1, const double rgb[3], int dashed, double kx, double ky,
                   const char *key)
{
    const double x[2] = {x0, x1}, y[2] = {yc + slope * (x0 - xc), yc + slope * (x1 - xc)};
    if (dashed)
        cairo_set_dash(cr, (const double[2]){8, 5}, 2, 0);
    plot_curve(cr, a, x, y, 2, rgb, 2.2);
    cairo_set_dash(cr, NULL, 0, 0);
    plot_key(cr, kx, ky, rgb, dashed, key);
}

void plot_scale_bar(cairo_t *cr, double x0, double y0, double length, double tick, double width,
                    const char *label)
{
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, width);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x0 + length, y0);
    cairo_move_to(cr, x0, y0 - tick);
    cairo_line_to(cr, x0, y0 + tick);
    cairo_move_to(cr, x0 + length, y0 - tick);
    cairo_line_to(cr, x0 + length, y0 + tick);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, x0 + length + 10, y0 + tick);
    cairo_show_text(cr, label);
}

void plot_y_title(cairo_t *cr, double x, double y, const char *text)
{
    cairo_save(cr);
    cairo_move_to(cr, x, y);
    cairo_rotate(cr, -0.5 * PI);
    cairo_show_text(cr, text);
    cairo_restore(cr);
}

void plot_key(cairo_t *cr, double kx, double ky, const double rgb[3], int dashed,
              const char *text)
{
    if (dashed)
        cairo_set_dash(cr, (const double[2]){8, 5}, 2, 0);
    cairo_move_to(cr, kx, ky);
    cairo_line_to(cr, kx + 30, ky);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, 2.2);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, kx + 38, ky + 4);
    cairo_show_text(cr, text);
}
