/* repose.c: outputs.repose of the demill runner (repose.h): the heap's
 * particles about its axis, its profile and fit (heap.h), and the picture
 * of the profile with the fitted line. */
#include <math.h>
#include <stdlib.h>

#include <cairo.h>

#include "heap.h"
#include "plot.h"
#include "repose.h"

#define PI 3.14159265358979323846

static int draw_repose(const char *dir, const double *rho, const double *top, size_t n,
                       const heap_profile *p, double base, double ring)
{
    const int wd = 1000, ht = 560, l = 80, r = 30, tp = 60, bt = 60;
    double rmax = 0;
    for (int q = 0; q < p->n; q++)
        rmax = fmax(rmax, p->rho[q]);
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, 0, 1e3 * (rmax + ring), 0,
                         1e3 * 1.3 * p->hmax};
    plot_ticks(cr, &a);
    /* every particle's top, then the profile, the fitted flank and the line */
    cairo_set_source_rgb(cr, 0.78, 0.78, 0.78);
    for (size_t k = 0; k < n; k++)
        if (1e3 * rho[k] <= a.x1) {
            cairo_arc(cr, plot_px(&a, 1e3 * rho[k]), plot_py(&a, 1e3 * top[k]), 1.2, 0, 2 * PI);
            cairo_fill(cr);
        }
    const double rise = p->hmax - base;
    for (int q = 0; q < p->n; q++) {
        const int fitted = p->h[q] >= base + 0.2 * rise && p->h[q] <= base + 0.8 * rise;
        cairo_set_source_rgb(cr, 0.13, 0.37, 0.66);
        cairo_arc(cr, plot_px(&a, 1e3 * p->rho[q]), plot_py(&a, 1e3 * p->h[q]), 4, 0, 2 * PI);
        if (fitted)
            cairo_fill(cr);
        else
            cairo_stroke(cr);
    }
    const double red[3] = {0.85, 0.2, 0.1};
    if (isfinite(p->angle)) {
        const double fx[2] = {0, -1e3 * p->icept / p->slope}, fy[2] = {1e3 * p->icept, 0};
        plot_curve(cr, &a, fx, fy, 2, red, 2);
    }
    char text[256];
    const double kx = wd - r - 430;
    cairo_set_source_rgb(cr, red[0], red[1], red[2]);
    snprintf(text, sizeof text, "angle of repose %.1f deg (least squares, %d points)", p->angle,
             p->nfit);
    cairo_move_to(cr, kx, tp + 24);
    cairo_show_text(cr, text);
    cairo_set_source_rgb(cr, 0.13, 0.37, 0.66);
    snprintf(text, sizeof text, "highest top in each %.1f mm ring (filled: fitted)", 1e3 * ring);
    cairo_move_to(cr, kx, tp + 46);
    cairo_show_text(cr, text);
    cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
    cairo_move_to(cr, kx, tp + 68);
    cairo_show_text(cr, "every particle's top");
    cairo_set_source_rgb(cr, 0, 0, 0);
    plot_frame(cr, l, tp, a.w, a.h, ht, l + 0.5 * a.w - 80, "distance from the heap's axis [mm]");
    plot_y_title(cr, 26, tp + 0.5 * a.h + 90, "height above the floor [mm]");
    cairo_move_to(cr, l, 32);
    snprintf(text, sizeof text,
             "The heap's surface profile; the line is fitted where it is 20-80 %% of the way from "
             "one layer (%.1f mm) to the summit",
             1e3 * base);
    cairo_show_text(cr, text);
    return plot_finish(cr, s, dir, "repose.png", "demill");
}

int repose_report(const scene *s, FILE *sum, const char *dir)
{
    size_t n, nr, nv;
    double *x = plot_read_field(s->w, DEMILL_PARTICLE_POSITION, &n);
    double *rad = plot_read_field(s->w, DEMILL_PARTICLE_RADIUS, &nr);
    double *v = plot_read_field(s->w, DEMILL_PARTICLE_VELOCITY, &nv);
    double *rho = malloc((n ? n : 1) * sizeof *rho), *top = malloc((n ? n : 1) * sizeof *top);
    if (!x || !rad || !v || !rho || !top || nr != n || nv != n) {
        fprintf(stderr, "demill: cannot read the particles for outputs.repose\n");
        free(x);
        free(rad);
        free(v);
        free(rho);
        free(top);
        return -1;
    }
    /* the particles on the floor (none fallen below it), their mean
     * diameter and the fastest one's speed */
    const double *c = s->repose_centre;
    size_t m = 0;
    double diameter = 0, fastest = 0;
    for (size_t k = 0; k < n; k++) {
        fastest = fmax(fastest, sqrt(v[3 * k] * v[3 * k] + v[3 * k + 1] * v[3 * k + 1] +
                                     v[3 * k + 2] * v[3 * k + 2]));
        if (!(x[3 * k + 1] > c[1]))
            continue;
        rho[m] = hypot(x[3 * k] - c[0], x[3 * k + 2] - c[2]);
        top[m++] = x[3 * k + 1] + rad[k] - c[1];
        diameter += 2 * rad[k];
    }
    diameter = m ? diameter / (double)m : NAN;
    /* the rings one diameter wide unless given; the flank counted from the
     * top of one layer on a flat floor, one diameter */
    const double ring = s->repose_ring > 0 ? s->repose_ring : diameter;
    heap_profile p;
    heap_fit(rho, top, m, ring, diameter, &p);
    fprintf(sum,
            "repose_angle_deg = %.4g\nrepose_height_m = %.6g\nrepose_fit_points = %d\n"
            "repose_ring_m = %.6g\nrepose_base_m = %.6g\nrepose_particles = %zu\n"
            "repose_fastest_m_s = %.4g\n",
            p.angle, p.hmax, p.nfit, ring, diameter, m, fastest);
    int rc = 0;
    if (p.nfit < 2)
        fprintf(stderr, "demill: %d points on the heap's flank: no angle of repose\n", p.nfit);
    if (m && isfinite(diameter))
        rc = draw_repose(dir, rho, top, m, &p, diameter, ring);
    free(x);
    free(rad);
    free(v);
    free(rho);
    free(top);
    return rc;
}
