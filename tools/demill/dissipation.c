/* dissipation.c: outputs.dissipation of the demill runner (dissipation.h):
 * the energy account's terms over a window, the mechanisms' shares, the
 * balance that checks them, and the picture of a sweep's shares. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "dissipation.h"
#include "plot.h"

#define PI 3.14159265358979323846

/* The mechanisms, in the order of Li, Gao, Zhang and Liu (2018),
 * Elasto-plastic contact modelling method for the vibration and energy
 * dissipation of particles: normal plastic, normal viscous, tangential
 * viscous, rolling viscous, sliding friction, rolling friction; then local
 * damping, which completes DEMILL_ENERGY_DISSIPATED. */
static const int32_t mechanisms[] = {
    DEMILL_ENERGY_DISSIPATED_PLASTIC,         DEMILL_ENERGY_DISSIPATED_NORMAL,
    DEMILL_ENERGY_DISSIPATED_TANGENTIAL,      DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS,
    DEMILL_ENERGY_DISSIPATED_FRICTION,        DEMILL_ENERGY_DISSIPATED_ROLLING,
    DEMILL_ENERGY_DISSIPATED_LOCAL};
#define NMECH (sizeof mechanisms / sizeof mechanisms[0])

/* The energies stored in the particles, their contacts and the bodies. */
static const int32_t stored[] = {
    DEMILL_ENERGY_KINETIC_TRANSLATIONAL, DEMILL_ENERGY_KINETIC_ROTATIONAL,
    DEMILL_ENERGY_POTENTIAL,             DEMILL_ENERGY_ELASTIC_NORMAL,
    DEMILL_ENERGY_ELASTIC_TANGENTIAL,    DEMILL_ENERGY_ELASTIC_ROLLING,
    DEMILL_ENERGY_BODY_KINETIC,          DEMILL_ENERGY_BODY_ELASTIC,
    DEMILL_ENERGY_BODY_POTENTIAL};

void dissipation_sample(const scene *s, double t, dissipation_track *d)
{
    double *v = d->started ? d->last : d->first;
    for (int32_t k = 0; k < DISSIPATION_TERMS; k++)
        if (demill_world_energy(s->w, k + 1, &v[k]) != DEMILL_OK)
            v[k] = NAN;
    if (!d->started) {
        d->from = t;
        memcpy(d->last, d->first, sizeof d->last);
    }
    d->started = 1;
    d->to = t;
}

/* The change of a term over the window. */
static double change(const dissipation_track *d, int32_t term)
{
    return d->last[term - 1] - d->first[term - 1];
}

void dissipation_report(const dissipation_track *d, FILE *sum)
{
    const double total = change(d, DEMILL_ENERGY_DISSIPATED);
    fprintf(sum, "dissipation_from_s = %.6g\ndissipation_to_s = %.6g\n", d->from, d->to);
    for (size_t k = 0; k < NMECH; k++) {
        const char *name = scene_energy_name(mechanisms[k]) + strlen("dissipated_");
        const double e = change(d, mechanisms[k]);
        fprintf(sum, "dissipated_%s_J = %.6g\ndissipation_share_%s = %.6g\n", name, e, name,
                total > 0 ? e / total : NAN);
    }
    /* the balance (demill/query.h, DEMILL_ENERGY_TOTAL): the work the
     * bodies' forces, the moving walls and the feeds put in, less the
     * change of the stored energies, the bodies' dampers' loss and the work
     * against cohesion, is what the contacts dissipated */
    const double input = change(d, DEMILL_ENERGY_BODY_WORK) + change(d, DEMILL_ENERGY_WALL_WORK) +
                         change(d, DEMILL_ENERGY_FLOW);
    double loss = input - change(d, DEMILL_ENERGY_BODY_DISSIPATED) - change(d, DEMILL_ENERGY_COHESION);
    for (size_t k = 0; k < sizeof stored / sizeof stored[0]; k++)
        loss -= change(d, stored[k]);
    fprintf(sum, "dissipated_J = %.6g\ninput_work_J = %.6g\nbalance_loss_J = %.6g\n", total, input,
            loss);
}

/* The number after "\nKEY = " in a summary, or NAN. */
static double summary_value(const char *text, const char *key)
{
    char pat[128];
    snprintf(pat, sizeof pat, "\n%s = ", key);
    const char *at = strstr(text, pat);
    return at ? strtod(at + strlen(pat), NULL) : NAN;
}

int dissipation_draw_sweep(const char *dir, const char *key, char *const *values,
                           char *const *summaries, size_t n)
{
    if (n < 2 || isnan(summary_value(summaries[0], "dissipation_share_normal")))
        return 0;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    if (!x || !y) {
        free(x);
        free(y);
        fprintf(stderr, "demill: out of memory\n");
        return -1;
    }
    double x0 = INFINITY, x1 = -INFINITY;
    for (size_t r = 0; r < n; r++) {
        x[r] = strtod(values[r], NULL);
        x0 = fmin(x0, x[r]);
        x1 = fmax(x1, x[r]);
    }
    if (!(x1 > x0)) {
        free(x);
        free(y);
        return 0;
    }
    const int wd = 1000, ht = 600, l = 80, rt = 250, tp = 60, bt = 60;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const double pad = 0.05 * (x1 - x0);
    const plot_area a = {l, tp, wd - l - rt, ht - tp - bt, x0 - pad, x1 + pad, 0, 100};
    plot_ticks(cr, &a);
    static const double colours[NMECH][3] = {{0.55, 0.35, 0.2},  {0.13, 0.37, 0.66},
                                             {0.1, 0.6, 0.3},    {0.6, 0.3, 0.65},
                                             {0.85, 0.2, 0.1},   {0.9, 0.6, 0.1},
                                             {0.5, 0.5, 0.5}};
    static const char *const labels[NMECH] = {"normal plastic",  "normal viscous",
                                              "tangential viscous", "rolling viscous",
                                              "sliding friction", "rolling friction",
                                              "local damping"};
    int row = 0;
    for (size_t k = 0; k < NMECH; k++) {
        char name[96];
        snprintf(name, sizeof name, "dissipation_share_%s",
                 scene_energy_name(mechanisms[k]) + strlen("dissipated_"));
        for (size_t r = 0; r < n; r++)
            y[r] = 100 * summary_value(summaries[r], name);
        plot_curve(cr, &a, x, y, n, colours[k], 2.2);
        cairo_set_source_rgb(cr, colours[k][0], colours[k][1], colours[k][2]);
        for (size_t r = 0; r < n; r++)
            if (isfinite(y[r])) {
                cairo_arc(cr, plot_px(&a, x[r]), plot_py(&a, y[r]), 4, 0, 2 * PI);
                cairo_fill(cr);
            }
        /* the key, with the share's range over the sweep */
        double lo = INFINITY, hi = -INFINITY;
        for (size_t r = 0; r < n; r++) {
            lo = fmin(lo, y[r]);
            hi = fmax(hi, y[r]);
        }
        char text[128];
        const double ky = tp + 20 + 24 * row++;
        cairo_set_source_rgb(cr, colours[k][0], colours[k][1], colours[k][2]);
        cairo_rectangle(cr, wd - rt + 20, ky - 10, 24, 10);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        snprintf(text, sizeof text, "%s (%.0f-%.0f %%)", labels[k], lo, hi);
        cairo_move_to(cr, wd - rt + 52, ky);
        cairo_show_text(cr, text);
    }
    plot_frame(cr, l, tp, a.w, a.h, ht, l + 0.5 * a.w, key);
    plot_y_title(cr, 26, tp + 0.5 * a.h + 110, "share of the energy dissipated [%]");
    cairo_move_to(cr, l, 32);
    cairo_show_text(cr, "Each dissipation mechanism's share of the energy the contacts dissipated "
                        "over outputs.dissipation's window");
    free(x);
    free(y);
    return plot_finish(cr, s, dir, "dissipation.png", "demill");
}
