/* plot.h: the cairo drawing the example programs share (the mill, the
 * hopper, the spring-mounted box): a canvas, PNG output, the colour map,
 * particles coloured by speed with their colour bar, and the frame, grid,
 * ticks and curves of an x-y plot. */
#ifndef PLOT_H
#define PLOT_H

#include <stddef.h>

#include <cairo.h>

#include <demill.h>

/* A white canvas of wd × ht pixels for a picture, with the pictures' font at
 * font_size and lines 1 pixel wide; *s receives its surface. */
cairo_t *plot_canvas(int wd, int ht, double font_size, cairo_surface_t **s);

/* Writes the surface to a PNG file and destroys it: 0, or -1 with a message
 * "PROGRAM: cannot write PATH: ..." on stderr. */
int plot_save_png(cairo_surface_t *s, const char *path, const char *program);

/* Ends the drawing cr on the surface s and writes the surface to the PNG
 * file `name` in the folder `dir` (plot_save_png()). */
int plot_finish(cairo_t *cr, cairo_surface_t *s, const char *dir, const char *name,
                const char *program);

/* A perceptually even colour map (viridis, 5 stops) for t in [0, 1]. */
void plot_colour(double t, double rgb[3]);

/* Reads a field of every particle (3 or 1 doubles each) into a new array
 * the caller frees, its count in *n; NULL on failure. */
double *plot_read_field(demill_world *w, int field, size_t *n);

/* Draws the particles seen along -z, the farthest first, as discs coloured
 * by speed (0 to the largest speed, which *vmax receives): a particle at
 * (x, y) is drawn at pixel (cx + x scale, cy - y scale). Only those with
 * |z| <= zmax are drawn (INFINITY: all). 0, or -1 with a message on stderr
 * when the particles cannot be read. */
int plot_particles(cairo_t *cr, demill_world *w, double cx, double cy, double scale, double zmax,
                   const char *program, double *vmax);

/* The vertical colour bar of the speeds 0 to vmax (m/s), bh pixels high with
 * its top left corner at (bx, by). */
void plot_speed_bar(cairo_t *cr, double bx, double by, double bh, double vmax);

/* A round number near span/5 for axis ticks. */
double plot_tick_step(double span);

/* A grid line from (x0, y0) to (x1, y1) and its label at (lx, ly). */
void plot_grid(cairo_t *cr, double x0, double y0, double x1, double y1, double lx, double ly,
               const char *label);

/* The frame of the plot area (left l, top tp, w × h) and the x axis's
 * title, centred about x_title_at at the bottom of a canvas ht high. */
void plot_frame(cairo_t *cr, double l, double tp, double w, double h, double ht,
                double x_title_at, const char *x_title);

/* An x-y plot's area on the canvas (left, top, width, height in pixels) and
 * the ranges of its axes. */
typedef struct plot_area {
    double l, tp, w, h;
    double x0, x1, y0, y1;
} plot_area;

/* The pixel of an x and of a y value. */
double plot_px(const plot_area *a, double x);
double plot_py(const plot_area *a, double y);

/* The grid lines at round values of both axes, labelled with their values. */
void plot_ticks(cairo_t *cr, const plot_area *a);

/* The curve through (x[k], y[k]), k < n, clipped to the area, in the given
 * colour and width. */
void plot_curve(cairo_t *cr, const plot_area *a, const double *x, const double *y, size_t n,
                const double rgb[3], double width);

/* The straight line through (xc, yc) with the given slope over [x0, x1],
 * clipped to the area, 2.2 pixels wide in a colour, dashed if asked, and
 * its key at (kx, ky): a stroke of 30 pixels and the text after it. */
/* A length scale: a bar `length` pixels long from (x0, y0) with end ticks
 * of `tick` pixels either side, `width` pixels thick, and its label after
 * it. */
void plot_scale_bar(cairo_t *cr, double x0, double y0, double length, double tick, double width,
                    const char *label);

/* Text along the y axis, read from the bottom up, starting at (x, y). */
void plot_y_title(cairo_t *cr, double x, double y, const char *text);

/* A legend's key at (kx, ky): a short line 30 pixels long in the given
 * colour (dashed if asked) and its text after it. */
void plot_key(cairo_t *cr, double kx, double ky, const double rgb[3], int dashed,
              const char *text);

void plot_line_key(cairo_t *cr, const plot_area *a, double xc, double yc, double slope, double x0,
                   double x1, const double rgb[3], int dashed, double kx, double ky,
                   const char *key);

#endif
