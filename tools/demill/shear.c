/* shear.c: outputs.shear of the demill runner (shear.h): the direct shear
 * test's samples, each run's peak and residual shear stress with its curve
 * and picture, and a sweep's Mohr-Coulomb lines with their pictures. */
#define _POSIX_C_SOURCE 200809L /* strdup */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "plot.h"
#include "shear.h"

#define PI 3.14159265358979323846
#define MAX_RUNS 16

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The unit vector against gravity (+y without gravity): the direction of
 * the normal load the particles bear and of the lid's rise. */
static void up_of(demill_world *w, double up[3])
{
    double g[3], n;
    for (int k = 0; k < 3; k++)
        check(demill_world_get(w, DEMILL_WORLD_GRAVITY_X + k, &g[k]), "gravity");
    n = sqrt(dot(g, g));
    for (int k = 0; k < 3; k++)
        up[k] = n > 0 ? -g[k] / n : k == 1;
}

static void body_field(const scene *s, int body, int32_t field, double v[3])
{
    check(demill_body_get(s->w, s->body[body], field, v), s->bodyname[body]);
}

void shear_sample(const scene *s, shear_trace *tr, double t)
{
    double up[3], v[3];
    up_of(s->w, up);
    body_field(s, s->lid, DEMILL_BODY_POSITION, v);
    const double h = dot(v, up);
    if (t < s->shear_start + 0.5 * s->dt) {
        tr->lid0 = h;
        return;
    }
    double force = 0;
    for (size_t k = 0; k < s->nheld; k++) {
        body_field(s, s->held[k], DEMILL_BODY_FORCE_PARTICLES, v);
        force += dot(v, s->shear_dir);
    }
    const double d = s->shear_speed * (t - s->shear_start);
    body_field(s, s->lid, DEMILL_BODY_FORCE_PARTICLES, v);
    series_add(&tr->tau, d, force / s->shear_area);
    series_add(&tr->sigma, d, dot(v, up) / s->shear_area);
    series_add(&tr->rise, d, h - tr->lid0);
}

void shear_trace_free(shear_trace *tr)
{
    series_free(&tr->tau);
    series_free(&tr->sigma);
    series_free(&tr->rise);
}

/* A curve averaged over bins of displacement: the mean displacement,
 * shear stress, normal stress and rise of the samples in each bin that
 * holds any. */
typedef struct curve {
    size_t n;
    double *d, *tau, *sigma, *rise;
} curve;

static void curve_free(curve *c)
{
    free(c->d);
    free(c->tau);
    free(c->sigma);
    free(c->rise);
    *c = (curve){0};
}

static int curve_of(const shear_trace *tr, double bin, curve *c)
{
    const size_t n = tr->tau.n, nb = n ? (size_t)(tr->tau.a[n - 1] / bin) + 1 : 0;
    size_t *count = calloc(nb + 1, sizeof *count);
    *c = (curve){0, calloc(nb + 1, sizeof(double)), calloc(nb + 1, sizeof(double)),
                 calloc(nb + 1, sizeof(double)), calloc(nb + 1, sizeof(double))};
    if (!count || !c->d || !c->tau || !c->sigma || !c->rise) {
        free(count);
        curve_free(c);
        fprintf(stderr, "demill: out of memory\n");
        return -1;
    }
    for (size_t k = 0; k < n; k++) {
        const size_t b = (size_t)(tr->tau.a[k] / bin);
        count[b]++;
        c->d[b] += tr->tau.a[k];
        c->tau[b] += tr->tau.b[k];
        c->sigma[b] += tr->sigma.b[k];
        c->rise[b] += tr->rise.b[k];
    }
    for (size_t b = 0; b < nb; b++)
        if (count[b]) {
            c->d[c->n] = c->d[b] / count[b];
            c->tau[c->n] = c->tau[b] / count[b];
            c->sigma[c->n] = c->sigma[b] / count[b];
            c->rise[c->n] = c->rise[b] / count[b];
            c->n++;
        }
    free(count);
    return 0;
}

/* ---- pictures ------------------------------------------------------------------ */

static const double colours[][3] = {{0.13, 0.37, 0.66}, {0.85, 0.37, 0.1}, {0.2, 0.6, 0.25},
                                    {0.6, 0.3, 0.65},   {0.5, 0.5, 0.5},   {0.75, 0.6, 0.1}};
#define NCOLOURS (sizeof colours / sizeof colours[0])

/* The shear stress (kPa, top) and the lid's rise (mm, bottom) against the
 * shear displacement (mm) of n runs' curves, each with its normal stress
 * in the key, its peak marked; into dir/name. */
static int draw_curves(const char *dir, const char *name, const curve *c, size_t n)
{
    const int wd = 1000, ht = 820, l = 90, r = 30, tp = 60, h1 = 430, gap = 60, h2 = 190;
    double dmax = 0, tmax = 0, rlo = 0, rhi = 0;
    for (size_t k = 0; k < n; k++)
        for (size_t j = 0; j < c[k].n; j++) {
            dmax = fmax(dmax, 1e3 * c[k].d[j]);
            tmax = fmax(tmax, 1e-3 * c[k].tau[j]);
            rlo = fmin(rlo, 1e3 * c[k].rise[j]);
            rhi = fmax(rhi, 1e3 * c[k].rise[j]);
        }
    if (!(dmax > 0))
        dmax = 1;
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const plot_area top = {l, tp, wd - l - r, h1, 0, dmax, 0, tmax > 0 ? 1.25 * tmax : 1};
    const plot_area bot = {l, tp + h1 + gap, wd - l - r, h2, 0, dmax,
                           rlo - 0.1 * (rhi - rlo + 1e-3), rhi + 0.1 * (rhi - rlo + 1e-3)};
    char text[256];
    plot_ticks(cr, &top);
    plot_ticks(cr, &bot);
    for (size_t k = 0; k < n; k++) {
        const double *rgb = colours[k % NCOLOURS];
        double *dm = malloc(c[k].n * sizeof *dm), *t = malloc(c[k].n * sizeof *t),
               *rs = malloc(c[k].n * sizeof *rs), sig = 0;
        size_t peak = 0;
        if (!dm || !t || !rs) {
            free(dm);
            free(t);
            free(rs);
            fprintf(stderr, "demill: out of memory\n");
            return -1;
        }
        for (size_t j = 0; j < c[k].n; j++) {
            dm[j] = 1e3 * c[k].d[j];
            t[j] = 1e-3 * c[k].tau[j];
            rs[j] = 1e3 * c[k].rise[j];
            sig += c[k].sigma[j] / c[k].n;
            if (t[j] > t[peak])
                peak = j;
        }
        if (c[k].n) {
            plot_curve(cr, &top, dm, t, c[k].n, rgb, 2.2);
            plot_curve(cr, &bot, dm, rs, c[k].n, rgb, 2.2);
            cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
            cairo_arc(cr, plot_px(&top, dm[peak]), plot_py(&top, t[peak]), 5, 0, 2 * PI);
            cairo_fill(cr);
        }
        snprintf(text, sizeof text, "normal stress %.1f kPa: peak %.1f kPa at %.1f mm (dot)", 1e-3 * sig,
                 c[k].n ? t[peak] : NAN, c[k].n ? dm[peak] : NAN);
        plot_key(cr, l + 20, tp + 20 + 22 * k, rgb, 0, text);
        free(dm);
        free(t);
        free(rs);
    }
    plot_frame(cr, l, tp, wd - l - r, h1, ht, wd / 2 - 80, "shear displacement [mm]");
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.5);
    cairo_rectangle(cr, bot.l, bot.tp, bot.w, bot.h);
    cairo_stroke(cr);
    plot_y_title(cr, 28, tp + 0.5 * h1 + 80, "shear stress [kPa]");
    plot_y_title(cr, 28, bot.tp + 0.5 * h2 + 60, "lid's rise [mm]");
    cairo_move_to(cr, l, 32);
    cairo_show_text(cr, "Direct shear: shear stress (held half's force / area) and dilation "
                        "against the shear displacement");
    return plot_finish(cr, s, dir, name, "demill");
}

/* ---- one run ------------------------------------------------------------------- */

/* The contact friction and rolling friction of the first particle's
 * material with itself (NaN without particles). */
static void particle_friction(demill_world *w, double *mu, double *mu_r)
{
    size_t n = 0;
    *mu = *mu_r = NAN;
    check(demill_particles_read_ids(w, DEMILL_PARTICLE_MATERIAL, NULL, 0, &n), "materials");
    demill_id *m = n ? malloc(n * sizeof *m) : NULL;
    if (m && demill_particles_read_ids(w, DEMILL_PARTICLE_MATERIAL, m, n, &n) == DEMILL_OK) {
        check(demill_pair_get(w, m[0], m[0], DEMILL_PAIR_FRICTION, mu), "friction");
        check(demill_pair_get(w, m[0], m[0], DEMILL_PAIR_ROLLING_FRICTION, mu_r), "rolling friction");
    }
    free(m);
}

int shear_report(const scene *s, const shear_trace *tr, FILE *sum, const char *dir)
{
    curve c;
    const size_t n = tr->tau.n;
    if (!n) {
        fprintf(sum, "shear_samples = 0\n");
        fprintf(stderr, "demill: the run stopped before the shear started (%g s): no shear "
                        "results\n", s->shear_start);
        return 0;
    }
    if (curve_of(tr, s->shear_bin, &c))
        return -1;
    const double dmax = tr->tau.a[n - 1];
    double sig = 0, res = 0, peak = -INFINITY, dpeak = NAN, mu, mu_r;
    size_t nres = 0;
    for (size_t k = 0; k < n; k++) {
        sig += tr->sigma.b[k] / n;
        if (tr->tau.a[k] >= 0.75 * dmax) {
            res += tr->tau.b[k];
            nres++;
        }
    }
    res /= nres;
    for (size_t j = 0; j < c.n; j++)
        if (c.tau[j] > peak) {
            peak = c.tau[j];
            dpeak = c.d[j];
        }
    particle_friction(s->w, &mu, &mu_r);
    fprintf(sum,
            "shear_area_m2 = %.6g\nshear_speed_m_s = %.6g\nshear_displacement_m = %.6g\n"
            "shear_samples = %zu\nnormal_stress_Pa = %.6g\npeak_shear_stress_Pa = %.6g\n"
            "peak_displacement_m = %.6g\nresidual_shear_stress_Pa = %.6g\n"
            "peak_friction_deg = %.4g\nresidual_friction_deg = %.4g\nlid_rise_end_m = %.6g\n"
            "contact_friction = %.6g\ncontact_friction_deg = %.4g\nrolling_friction = %.6g\n",
            s->shear_area, s->shear_speed, dmax, n, sig, peak, dpeak, res,
            atan(peak / sig) * 180 / PI, atan(res / sig) * 180 / PI, c.n ? c.rise[c.n - 1] : NAN,
            mu, atan(mu) * 180 / PI, mu_r);
    int rc = 0;
    FILE *f = output_open(dir, "shear.csv");
    fprintf(f, "displacement_m,shear_stress_Pa,normal_stress_Pa,lid_rise_m\n");
    for (size_t j = 0; j < c.n; j++)
        fprintf(f, "%.9g,%.9g,%.9g,%.9g\n", c.d[j], c.tau[j], c.sigma[j], c.rise[j]);
    output_close(f, "shear.csv");
    if (c.n < 2)
        fprintf(stderr, "demill: %zu bins of the shear: no shear.png\n", c.n);
    else
        rc = draw_curves(dir, "shear.png", &c, 1);
    curve_free(&c);
    return rc;
}

/* ---- a sweep ---------------------------------------------------------------------- */

/* The number after "\nkey = " in a summary, NaN if absent. */
static double summary_number(const char *sum, const char *key)
{
    char k[128];
    snprintf(k, sizeof k, "\n%s = ", key);
    const char *at = strstr(sum, k);
    return at ? strtod(at + strlen(k), NULL) : NAN;
}

/* Reads a run's shear.csv: 0, or -1 with a message. */
static int read_curve(const char *dir, curve *c)
{
    char path[4200], line[512];
    series dt = {0}, sr = {0}; /* displacement, shear stress; normal stress, rise */
    snprintf(path, sizeof path, "%s/shear.csv", dir);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "demill: cannot read %s\n", path);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        double v[4];
        if (sscanf(line, "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) == 4) {
            series_add(&dt, v[0], v[1]);
            series_add(&sr, v[2], v[3]);
        }
    }
    fclose(f);
    *c = (curve){dt.n, dt.a, dt.b, sr.a, sr.b};
    return 0;
}

/* The least-squares line tau = c + sigma tan(phi) through n points: phi in
 * degrees, c in Pa. */
static void mohr_coulomb(const double *sig, const double *tau, size_t n, double *phi, double *coh)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t k = 0; k < n; k++) {
        sx += sig[k];
        sy += tau[k];
        sxx += sig[k] * sig[k];
        sxy += sig[k] * tau[k];
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    *coh = (sy - slope * sx) / n;
    *phi = atan(slope) * 180 / PI;
}

/* tau against sigma (kPa): the runs' peak and residual points, the fitted
 * lines with their angles and cohesions, and the contact friction's line. */
static int draw_mohr(const char *out, const double *sig, const double *peak, const double *res,
                     size_t n, const double fit[4], double mu)
{
    const int wd = 900, ht = 700, l = 90, r = 30, tp = 60, bt = 60;
    double smax = 0, tmax = 0;
    for (size_t k = 0; k < n; k++) {
        smax = fmax(smax, 1e-3 * sig[k]);
        tmax = fmax(tmax, 1e-3 * peak[k]);
    }
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, 0, 1.15 * smax, 0, 1.3 * tmax};
    const double red[3] = {0.85, 0.2, 0.1}, blue[3] = {0.13, 0.37, 0.66}, grey[3] = {0.5, 0.5, 0.5};
    char text[256];
    plot_ticks(cr, &a);
    const double x[2] = {0, a.x1};
    const double yp[2] = {1e-3 * fit[1], 1e-3 * fit[1] + a.x1 * tan(fit[0] * PI / 180)};
    const double yr[2] = {1e-3 * fit[3], 1e-3 * fit[3] + a.x1 * tan(fit[2] * PI / 180)};
    const double ym[2] = {0, a.x1 * mu};
    plot_curve(cr, &a, x, yp, 2, red, 2);
    plot_curve(cr, &a, x, yr, 2, blue, 2);
    cairo_set_dash(cr, (const double[2]){8, 5}, 2, 0);
    if (isfinite(mu))
        plot_curve(cr, &a, x, ym, 2, grey, 2);
    cairo_set_dash(cr, NULL, 0, 0);
    for (size_t k = 0; k < n; k++) {
        cairo_set_source_rgb(cr, red[0], red[1], red[2]);
        cairo_arc(cr, plot_px(&a, 1e-3 * sig[k]), plot_py(&a, 1e-3 * peak[k]), 6, 0, 2 * PI);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, blue[0], blue[1], blue[2]);
        cairo_arc(cr, plot_px(&a, 1e-3 * sig[k]), plot_py(&a, 1e-3 * res[k]), 6, 0, 2 * PI);
        cairo_fill(cr);
    }
    snprintf(text, sizeof text, "peak (the curve's largest): phi = %.1f deg, c = %.2f kPa", fit[0],
             1e-3 * fit[1]);
    plot_key(cr, l + 20, tp + 20, red, 0, text);
    snprintf(text, sizeof text, "residual (mean over the last quarter): phi = %.1f deg, c = %.2f kPa",
             fit[2], 1e-3 * fit[3]);
    plot_key(cr, l + 20, tp + 42, blue, 0, text);
    if (isfinite(mu)) {
        snprintf(text, sizeof text, "contact friction: atan %.3g = %.1f deg", mu, atan(mu) * 180 / PI);
        plot_key(cr, l + 20, tp + 64, grey, 1, text);
    }
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 60, "normal stress [kPa]");
    plot_y_title(cr, 28, tp + 0.5 * (ht - tp - bt) + 70, "shear stress [kPa]");
    cairo_move_to(cr, l, 32);
    cairo_show_text(cr, "Direct shear: each run's peak and residual (dots), least-squares lines "
                        "tau = c + sigma tan phi");
    return plot_finish(cr, s, out, "mohr_coulomb.png", "demill");
}

int shear_sweep_report(const char *out, char *const *dirs, char *const *sums, size_t n)
{
    double sig[MAX_RUNS], peak[MAX_RUNS], res[MAX_RUNS], fit[4];
    curve c[MAX_RUNS];
    if (n < 2 || isnan(summary_number(sums[0], "peak_shear_stress_Pa")))
        return 0;
    if (n > MAX_RUNS) {
        fprintf(stderr, "demill: a sweep of %zu shear tests: the Mohr-Coulomb fit takes at most %d\n",
                n, MAX_RUNS);
        return 0;
    }
    for (size_t k = 0; k < n; k++) {
        sig[k] = summary_number(sums[k], "normal_stress_Pa");
        peak[k] = summary_number(sums[k], "peak_shear_stress_Pa");
        res[k] = summary_number(sums[k], "residual_shear_stress_Pa");
    }
    const double mu = summary_number(sums[0], "contact_friction");
    mohr_coulomb(sig, peak, n, &fit[0], &fit[1]);
    mohr_coulomb(sig, res, n, &fit[2], &fit[3]);
    FILE *f = output_open(out, "shear_box.txt");
    fprintf(f, "runs = %zu\n", n);
    for (size_t k = 0; k < n; k++)
        fprintf(f, "run_%zu = %s\nrun_%zu_normal_stress_Pa = %.6g\nrun_%zu_peak_shear_stress_Pa = %.6g\n"
                   "run_%zu_residual_shear_stress_Pa = %.6g\n",
                k, dirs[k], k, sig[k], k, peak[k], k, res[k]);
    fprintf(f, "peak_friction_deg = %.4f\npeak_cohesion_Pa = %.6g\nresidual_friction_deg = %.4f\n"
               "residual_cohesion_Pa = %.6g\ncontact_friction_deg = %.4f\n",
            fit[0], fit[1], fit[2], fit[3], atan(mu) * 180 / PI);
    output_close(f, "shear_box.txt");
    printf("demill: Mohr-Coulomb: peak %.2f deg (c %.3g Pa), residual %.2f deg (c %.3g Pa); "
           "%s/shear_box.txt\n",
           fit[0], fit[1], fit[2], fit[3], out);
    int rc = 0;
    for (size_t k = 0; k < n; k++)
        c[k] = (curve){0};
    for (size_t k = 0; k < n && !rc; k++)
        rc = read_curve(dirs[k], &c[k]);
    if (!rc)
        rc = draw_curves(out, "shear_stress.png", c, n);
    for (size_t k = 0; k < n; k++)
        curve_free(&c[k]);
    return rc || draw_mohr(out, sig, peak, res, n, fit, mu);
}
