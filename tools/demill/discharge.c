/* discharge.c: outputs.discharge of the demill runner (discharge.h): the
 * bed's solid fraction, the steady rate fitted to the discharged mass, the
 * correlations, and the picture of the discharge. */
#include <math.h>
#include <stdlib.h>

#include <cairo.h>

#include "discharge.h"
#include "plot.h"

#define PI 3.14159265358979323846

double discharge_solid_fraction(const scene *s)
{
    const double *r = s->bulk_params;
    double volume;
    if (s->bulk_kind == DEMILL_REGION_BOX)
        volume = (r[3] - r[0]) * (r[4] - r[1]) * (r[5] - r[2]);
    else
        volume = PI * r[6] * r[6] * sqrt(pow(r[3] - r[0], 2) + pow(r[4] - r[1], 2) + pow(r[5] - r[2], 2));
    size_t n, nr;
    double *x = plot_read_field(s->w, DEMILL_PARTICLE_POSITION, &n);
    double *rad = plot_read_field(s->w, DEMILL_PARTICLE_RADIUS, &nr);
    double solid = 0;
    for (size_t k = 0; x && rad && k < n && k < nr; k++)
        if (scene_region_contains(s->bulk_kind, r, 3, x + 3 * k))
            solid += 4.0 / 3.0 * PI * pow(rad[k], 3);
    free(x);
    free(rad);
    return solid / volume;
}

/* The least-squares line through the samples whose mass is within [lo, hi]:
 * its slope (NaN with fewer than 3 samples), intercept, first and last
 * times, and the solid fraction at the first (the bed then still fills the
 * bulk region, flowing steadily). */
typedef struct fit {
    double slope, intercept, phi, from, to;
    size_t n;
} fit;

static fit fit_window(const discharge_trace *tr, double lo, double hi)
{
    double st = 0, sm = 0, stt = 0, stm = 0;
    fit f = {NAN, NAN, NAN, NAN, NAN, 0};
    for (size_t k = 0; k < tr->n; k++) {
        if (tr->mass[k] < lo || tr->mass[k] > hi)
            continue;
        if (!f.n) {
            f.from = tr->t[k];
            f.phi = tr->phi[k];
        }
        f.to = tr->t[k];
        st += tr->t[k];
        sm += tr->mass[k];
        stt += tr->t[k] * tr->t[k];
        stm += tr->t[k] * tr->mass[k];
        f.n++;
    }
    if (f.n >= 3) {
        const double m = (double)f.n;
        f.slope = (m * stm - st * sm) / (m * stt - st * st);
        f.intercept = (sm - f.slope * st) / m;
    }
    return f;
}

static int draw_discharge(const char *dir, const discharge_trace *tr, const fit *f,
                          const double beverloo[2], double orifice)
{
    const int wd = 1000, ht = 560, l = 90, r = 30, tp = 60, bt = 60;
    const double mmax = tr->mass[tr->n - 1] > 0 ? 1.1 * tr->mass[tr->n - 1] : 1;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, tr->t[0], tr->t[tr->n - 1], 0, mmax};
    char key[160];
    /* the fit's window, shaded */
    cairo_set_source_rgb(cr, 0.93, 0.95, 1.0);
    cairo_rectangle(cr, plot_px(&a, f->from), tp, plot_px(&a, f->to) - plot_px(&a, f->from), a.h);
    cairo_fill(cr);
    plot_ticks(cr, &a);
    plot_curve(cr, &a, tr->t, tr->mass, tr->n, (const double[3]){0.13, 0.37, 0.66}, 2.5);
    /* the lines through the fit's middle */
    const double tc = 0.5 * (f->from + f->to), mc = f->intercept + f->slope * tc;
    const double t0 = tr->t[0], t1 = tr->t[tr->n - 1], kx = l + 20;
    snprintf(key, sizeof key, "simulated: %.4f kg/s, fitted where 20-80 %% of the mass is out (shaded)",
             f->slope);
    plot_line_key(cr, &a, tc, mc, f->slope, f->from, f->to, (const double[3]){0.85, 0.2, 0.1}, 0,
                  kx, tp + 20, key);
    snprintf(key, sizeof key, "Beverloo with Rose and Tanaka's hopper factor: %.4f kg/s", beverloo[1]);
    plot_line_key(cr, &a, tc, mc, beverloo[1], t0, t1, (const double[3]){0.1, 0.55, 0.2}, 1, kx,
                  tp + 42, key);
    snprintf(key, sizeof key, "Beverloo, flat bottom: %.4f kg/s", beverloo[0]);
    plot_line_key(cr, &a, tc, mc, beverloo[0], t0, t1, (const double[3]){0.5, 0.5, 0.5}, 1, kx,
                  tp + 64, key);
    cairo_set_source_rgb(cr, 0.13, 0.37, 0.66);
    cairo_move_to(cr, kx + 38, tp + 90);
    cairo_show_text(cr, "mass discharged through the outlet");
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 30, "time t [s]");
    plot_y_title(cr, 28, tp + 0.5 * a.h + 90, "mass discharged [kg]");
    cairo_move_to(cr, l, 32);
    snprintf(key, sizeof key,
             "Discharge of %.2f mm particles through a %.1f mm orifice; the lines pass through "
             "the fit's middle",
             1e3 * tr->diameter, 1e3 * orifice);
    cairo_show_text(cr, key);
    return plot_finish(cr, s, dir, "discharge.png", "demill");
}

int discharge_report(const scene *s, const discharge_trace *tr, FILE *sum, const char *dir)
{
    double g[3];
    for (int k = 0; k < 3; k++)
        demill_world_get(s->w, DEMILL_WORLD_GRAVITY_X + k, &g[k]);
    const double total = tr->n ? tr->mass[tr->n - 1] : 0;
    const fit f = fit_window(tr, 0.2 * total, 0.8 * total);
    /* Beverloo, Leniger and van de Velde (1961), The flow of granular
     * solids through orifices: W = C rho_b sqrt(g) (D0 - k d)^(5/2), C =
     * 0.58, k = 1.5, for a flat bottom; Rose and Tanaka (1956), Rate of
     * discharge of granular materials from bins and hoppers: times F = (tan
     * theta tan phi_d)^-0.35 for a hopper of half-angle theta below 90° -
     * phi_d, phi_d the stagnant zone's angle to the horizontal over a flat
     * bottom (F = 1 otherwise). */
    const double rho_b = f.phi * tr->density, gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double flat = 0.58 * rho_b * sqrt(gn) * pow(fmax(0, s->orifice - 1.5 * tr->diameter), 2.5);
    const double factor = s->half_angle < 0.5 * PI - s->stagnant_angle
                              ? pow(tan(s->half_angle) * tan(s->stagnant_angle), -0.35)
                              : 1.0;
    const double beverloo[2] = {flat, flat * factor};
    fprintf(sum,
            "discharged_kg = %.6g\ndischarge_rate_kg_s = %.6g\ndischarge_fit_from_s = %.6g\n"
            "discharge_fit_to_s = %.6g\ndischarge_fit_samples = %zu\nbulk_solid_fraction = %.4f\n"
            "particle_diameter_m = %.6g\nparticle_density_kg_m3 = %.6g\n"
            "beverloo_flat_kg_s = %.6g\nrose_tanaka_factor = %.4f\nbeverloo_hopper_kg_s = %.6g\n"
            "rate_over_beverloo_hopper = %.4f\n",
            total, f.slope, f.from, f.to, f.n, f.phi, tr->diameter, tr->density, beverloo[0], factor,
            beverloo[1], f.slope / beverloo[1]);
    if (f.n < 3) {
        fprintf(stderr, "demill: %zu samples between 20 and 80 %% of the discharged mass: no rate "
                        "and no discharge.png\n",
                f.n);
        return 0;
    }
    return draw_discharge(dir, tr, &f, beverloo, s->orifice);
}
