/* hopper.c: a conical hopper from an STL file discharging through its
 * orifice, the example of docs/geometry.md (The hopper example).
 *
 * The hopper (hopper.stl, written by make_stl.py: a 30° cone from a 42 mm
 * orifice up to a bin of 120 mm diameter, in millimetres with z up, as CAD
 * writes it) is loaded with demill_wall_load_stl at scale 0.001 and turned
 * so that its axis is the world's y, against gravity. A disc closes the
 * orifice while demill_fill_region pours 6 mm glass beads into the bin and
 * they settle; then the disc is removed and an outlet (a half-space 30 mm
 * below the orifice) takes away and weighs every bead that falls out. The
 * run ends when the hopper is empty, when nothing has come out for 0.5 s
 * (a jammed orifice), or at the time limit. It writes to the output folder:
 * discharge.csv (time since opening, mass and number discharged),
 * summary.txt (the steady discharge rate, from a straight line fitted to
 * the mass discharged while it is between 20 % and 80 % of the final mass,
 * against Beverloo's correlation) and hopper.png (a slice through the axis
 * half-way through the discharge, the beads coloured by speed, beside the
 * discharge curve). Progress goes to stderr. Run `hopper --help` for the
 * options.
 *
 * The beads are soft (E = 5 MPa instead of glass's 60 GPa) so that a large
 * time step is stable: the 2500 beads settle and discharge in about 13 s of
 * one core.
 */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846

/* The hopper of hopper.stl (make_stl.py), in metres, with the orifice at
 * the origin and the axis along y. */
#define ORIFICE_RADIUS 0.021
#define BIN_RADIUS 0.060
#define HALF_ANGLE (30.0 * PI / 180.0)
#define BIN_HEIGHT 0.100
#define CONE_HEIGHT ((BIN_RADIUS - ORIFICE_RADIUS) / tan(HALF_ANGLE))

/* The beads: glass's density, a soft modulus. */
#define DENSITY 2500.0
#define YOUNGS 5e6
#define OUTLET_DEPTH 0.030 /* the outlet: everything this far below the orifice */

typedef struct options {
    const char *out, *stl, *walls;
    size_t particles;
    double diameter, time_limit, dt;
} options;

static void usage(FILE *f)
{
    fputs("usage: hopper [options]\n"
          "Discharges glass beads from a conical hopper given as an STL file and writes\n"
          "discharge.csv, summary.txt and hopper.png to the output folder.\n\n"
          "  --particles N     number of beads [2500]\n"
          "  --diameter D      bead diameter, m [0.006]\n"
          "  --time-limit T    longest discharge, s after opening the orifice [6]\n"
          "  --time-step DT    s [4e-5]\n"
          "  --stl FILE        the hopper, of hopper.stl's dimensions, which the gate, the\n"
          "                    fill and the pictures assume [" HOPPER_STL "]\n"
          "  --walls KIND      stl (the file) or analytic (the same hopper as a finite cone\n"
          "                    and cylinder, demill_wall_add_cone and _cylinder) [stl]\n"
          "  --out DIR         output folder [hopper-out]\n"
          "  --help            this text\n",
          f);
}

static int parse_options(int argc, char **argv, options *o)
{
    *o = (options){.out = "hopper-out", .stl = HOPPER_STL, .walls = "stl", .particles = 2500, .diameter = 0.006,
                   .time_limit = 6, .dt = 4e-5};
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v)
            return -1;
        double x = 0;
        int bad = 0;
        if (!strcmp(a, "--out")) {
            o->out = v;
        } else if (!strcmp(a, "--stl")) {
            o->stl = v;
        } else if (!strcmp(a, "--walls")) {
            o->walls = v;
            if (strcmp(v, "stl") && strcmp(v, "analytic")) {
                fprintf(stderr, "hopper: --walls takes stl or analytic\n");
                return -1;
            }
        } else if (!strcmp(a, "--particles")) {
            bad = parse_number(a, v, 1, 20000, &x);
            o->particles = (size_t)x;
        } else if (!strcmp(a, "--diameter")) {
            bad = parse_number(a, v, 0.002, 0.012, &o->diameter);
        } else if (!strcmp(a, "--time-limit")) {
            bad = parse_number(a, v, 0.01, 600, &o->time_limit);
        } else if (!strcmp(a, "--time-step")) {
            bad = parse_number(a, v, 1e-7, 1e-3, &o->dt);
        } else {
            fprintf(stderr, "hopper: unknown option %s (see hopper --help)\n", a);
            return -1;
        }
        if (bad)
            return -1;
    }
    return 0;
}

/* The total mass and number of the particles in the world. */
static double particle_mass(demill_world *w, size_t *n)
{
    double *m = plot_read_field(w, DEMILL_PARTICLE_MASS, n), sum = 0;
    if (!m) {
        fprintf(stderr, "hopper: cannot read the particles' masses\n");
        exit(EXIT_FAILURE);
    }
    for (size_t k = 0; k < *n; k++)
        sum += m[k];
    free(m);
    return sum;
}

/* The solid fraction of the settled bed: the volume of the beads whose
 * centres lie in a cylinder on the axis, from 15 to 45 mm above the orifice
 * and 25 mm in radius (inside the cone, whose radius there is 29.7 mm and
 * more), over the cylinder's volume. */
static double solid_fraction(demill_world *w)
{
    const double y0 = 0.015, y1 = 0.045, rc = 0.025;
    size_t n;
    double *x = plot_read_field(w, DEMILL_PARTICLE_POSITION, &n);
    double *r = plot_read_field(w, DEMILL_PARTICLE_RADIUS, &n), v = 0;
    for (size_t k = 0; x && r && k < n; k++)
        if (x[3 * k + 1] >= y0 && x[3 * k + 1] < y1 && hypot(x[3 * k], x[3 * k + 2]) < rc)
            v += 4.0 / 3.0 * PI * r[k] * r[k] * r[k];
    free(x);
    free(r);
    return v / (PI * rc * rc * (y1 - y0));
}

/* The least-squares line m = a + rate t through the (t[k], m[k]) with
 * lo <= m[k] <= hi: returns the rate and sets *a and the first and last
 * such times; NAN with fewer than 3 such points. */
static double fitted_rate(const double *t, const double *m, size_t n, double lo, double hi,
                          double *a, double *t_from, double *t_to)
{
    double st = 0, sm = 0, stt = 0, stm = 0;
    size_t c = 0;
    for (size_t k = 0; k < n; k++)
        if (m[k] >= lo && m[k] <= hi) {
            *t_to = t[k];
            if (!c)
                *t_from = t[k];
            st += t[k];
            sm += m[k];
            stt += t[k] * t[k];
            stm += t[k] * m[k];
            c++;
        }
    const double rate = c < 3 ? NAN : (c * stm - st * sm) / (c * stt - st * st);
    *a = (sm - rate * st) / c;
    return rate;
}

/* Left panel of the picture: the beads the plane z = 0 through the axis cuts
 * (their centres within a radius of it) coloured by speed, and the hopper's
 * section by that plane. */
static void draw_slice(cairo_t *cr, demill_world *w, double d, double t)
{
    const double scale = 2600, cx = 340, cy = 560; /* pixels per m; the orifice's pixel */
    double vmax;
    if (plot_particles(cr, w, cx, cy, scale, 0.5 * d, "hopper", &vmax))
        exit(EXIT_FAILURE);
    const double rim[3][2] = {{ORIFICE_RADIUS, 0},
                              {BIN_RADIUS, CONE_HEIGHT},
                              {BIN_RADIUS, CONE_HEIGHT + BIN_HEIGHT}};
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 3);
    for (int side = -1; side <= 1; side += 2) {
        cairo_move_to(cr, cx + side * rim[0][0] * scale, cy - rim[0][1] * scale);
        for (int k = 1; k < 3; k++)
            cairo_line_to(cr, cx + side * rim[k][0] * scale, cy - rim[k][1] * scale);
        cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0.85, 0.2, 0.1);
    cairo_set_line_width(cr, 1);
    cairo_set_dash(cr, (const double[]){6, 4}, 2, 0);
    cairo_move_to(cr, cx - 0.1 * scale, cy + OUTLET_DEPTH * scale);
    cairo_line_to(cr, cx + 0.1 * scale, cy + OUTLET_DEPTH * scale);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_font_size(cr, 13);
    cairo_move_to(cr, cx + 0.04 * scale, cy + OUTLET_DEPTH * scale - 6);
    cairo_show_text(cr, "outlet");
    char label[96];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 15);
    snprintf(label, sizeof label, "the beads the plane z = 0 cuts, %.2f s after opening", t);
    cairo_move_to(cr, 40, 70);
    cairo_show_text(cr, label);
    plot_speed_bar(cr, 660, 140, 400, vmax);
}

/* Right panel: the mass discharged against time, the fitted line over its
 * window, and the correlations' rates. */
static void draw_curve(cairo_t *cr, const double *t, const double *m, size_t n, double rate,
                       double t_from, double t_to, double fit_at, double t_slice,
                       const double beverloo[2])
{
    double mmax = 1e-9;
    for (size_t k = 0; k < n; k++)
        mmax = fmax(mmax, m[k]);
    const plot_area a = {820, 110, 540, 500, 0, fmax(t[n - 1], 1e-3), 0, 1.1 * mmax};
    plot_ticks(cr, &a);
    plot_curve(cr, &a, t, m, n, (const double[3]){0.13, 0.37, 0.66}, 2);
    char label[128];
    if (isfinite(rate)) {
        const double fx[2] = {t_from, t_to}, fy[2] = {fit_at + rate * t_from, fit_at + rate * t_to};
        plot_curve(cr, &a, fx, fy, 2, (const double[3]){0.85, 0.2, 0.1}, 3);
    }
    cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
    cairo_set_dash(cr, (const double[]){4, 4}, 2, 0);
    cairo_move_to(cr, plot_px(&a, t_slice), a.tp);
    cairo_line_to(cr, plot_px(&a, t_slice), a.tp + a.h);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 14);
    const char *lines[3] = {"steady rate (fit, red): %.3f kg/s", "Beverloo, flat bottom: %.3f kg/s",
                            "with Rose & Tanaka's factor: %.3f kg/s"};
    const double values[3] = {rate, beverloo[0], beverloo[1]};
    for (int k = 0; k < 3; k++) {
        snprintf(label, sizeof label, lines[k], values[k]);
        cairo_move_to(cr, a.l + 15, a.tp + 25 + 20 * k);
        cairo_show_text(cr, label);
    }
    plot_frame(cr, a.l, a.tp, a.w, a.h, 680, a.l + a.w / 2 - 90, "time since opening [s]");
    cairo_move_to(cr, a.l, 90);
    cairo_show_text(cr, "mass discharged [kg]");
}

int main(int argc, char **argv)
{
    example_program = "hopper";
    options o;
    if (parse_options(argc, argv, &o))
        return EXIT_FAILURE;
    if (example_make_dir(o.out))
        return EXIT_FAILURE;
    const double t_wall0 = now();
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "hopper: cannot create a world\n");
        return EXIT_FAILURE;
    }
    example_world = w;
    demill_id glass, hopper, gate, outlet;
    check(demill_world_set(w, DEMILL_WORLD_TIME_STEP, o.dt), "--time-step");
    check(demill_material_create(w, &glass), "demill_material_create");
    const struct {
        int key;
        double value;
    } props[] = {{DEMILL_MATERIAL_DENSITY, DENSITY},     {DEMILL_MATERIAL_YOUNGS_MODULUS, YOUNGS},
                 {DEMILL_MATERIAL_POISSON_RATIO, 0.3},   {DEMILL_MATERIAL_RESTITUTION, 0.5},
                 {DEMILL_MATERIAL_FRICTION, 0.5}};
    for (size_t k = 0; k < sizeof props / sizeof props[0]; k++)
        check(demill_material_set(w, glass, props[k].key, props[k].value), "demill_material_set");
    check(demill_pair_set(w, glass, glass, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law");
    check(demill_pair_set(w, glass, glass, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION),
          "damping");
    check(demill_pair_set(w, glass, glass, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN),
          "friction law");

    /* the hopper, described for the messages, the picture and the summary */
    const double origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    char walls[256];
    if (!strcmp(o.walls, "stl")) {
        /* millimetres, z up in the file; here metres, y up: (x, y, z) ->
         * (x, z, -y), a quarter turn about x */
        const double z_up_to_y_up[12] = {1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 0};
        check(demill_wall_load_stl(w, glass, o.stl, 0.001, z_up_to_y_up, &hopper),
              "loading the hopper");
        size_t nv, nt;
        check(demill_wall_mesh_info(w, hopper, &nv, &nt), "demill_wall_mesh_info");
        const char *slash = strrchr(o.stl, '/');
        snprintf(walls, sizeof walls, "%s, %zu triangles", slash ? slash + 1 : o.stl, nt);
    } else {
        const double top[3] = {0, CONE_HEIGHT, 0};
        demill_id bin;
        check(demill_wall_add_cone(w, glass, origin, up, ORIFICE_RADIUS, BIN_RADIUS, CONE_HEIGHT,
                                   DEMILL_CAPS_NONE, &hopper),
              "the cone");
        check(demill_wall_add_cylinder(w, glass, top, up, BIN_RADIUS, BIN_HEIGHT, DEMILL_CAPS_NONE,
                                       &bin),
              "the bin");
        snprintf(walls, sizeof walls, "a finite cone and cylinder");
    }
    check(demill_wall_add_disc(w, glass, origin, up, ORIFICE_RADIUS + 0.005, 0, &gate),
          "closing the orifice");

    /* pour the beads into the bin and let them settle */
    const double bin[7] = {0, CONE_HEIGHT + 0.002, 0, 0, CONE_HEIGHT + BIN_HEIGHT - 0.002, 0,
                           BIN_RADIUS - 0.002};
    const double sizes[2] = {o.diameter, 1.0};
    size_t n0;
    check(demill_fill_region(w, DEMILL_REGION_CYLINDER, bin, 7, glass, DEMILL_SIZES_CLASSES, sizes,
                             2, DEMILL_FILL_COUNT, (double)o.particles, 1, NULL, 0, &n0),
          "filling the bin");
    const double bead_mass = DENSITY * PI * pow(o.diameter, 3) / 6;
    fprintf(stderr, "hopper: %s; %zu beads of %.0f mm poured into the bin\n", walls, n0,
            1e3 * o.diameter);
    int32_t settled; /* the fall into the cone, then until the beads are at rest */
    check(demill_world_step(w, (uint64_t)ceil(0.25 / o.dt)), "pouring");
    check(demill_world_settle(w, 2.0, 1e-3 * bead_mass * 9.81 * o.diameter, &settled), "settling");
    double t_open;
    check(demill_world_get(w, DEMILL_WORLD_TIME, &t_open), "time");
    const double phi = solid_fraction(w);
    size_t n_start;
    const double m_start = particle_mass(w, &n_start);
    fprintf(stderr, "hopper: %s after %.2f s: %zu beads, %.4f kg, solid fraction %.3f near the "
                    "orifice; opening it\n",
            settled ? "settled" : "not settled", t_open, n_start, m_start, phi);

    /* open the orifice; the outlet weighs what falls out */
    check(demill_wall_remove(w, gate), "opening the orifice");
    const double below[6] = {0, -OUTLET_DEPTH, 0, 0, 1, 0}, sample_every = 0.005;
    check(demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, below, 6, 0, NULL, sample_every,
                               &outlet),
          "demill_outlet_create");
    FILE *csv = output_open(o.out, "discharge.csv");
    fprintf(csv, "time_s,mass_kg,count\n0,0,0\n");
    series curve = {0}; /* time since opening, mass discharged */
    series_add(&curve, 0, 0);
    cairo_surface_t *surface;
    cairo_t *cr = plot_canvas(1400, 680, 18, &surface);
    const uint64_t chunk = (uint64_t)fmax(1, round(sample_every / o.dt));
    double t = 0, m_out = 0, t_last_out = 0, t_slice = NAN, t_print = 0;
    uint64_t count = 0, steps = 0;
    while (count < n_start && t < o.time_limit && t - t_last_out < 0.5) {
        check(demill_world_step(w, chunk), "stepping");
        steps += chunk;
        double now_t;
        check(demill_world_get(w, DEMILL_WORLD_TIME, &now_t), "time");
        t = now_t - t_open;
        const double m_before = m_out;
        check(demill_outlet_read(w, outlet, &count, &m_out, 1, NULL, NULL), "demill_outlet_read");
        if (m_out > m_before)
            t_last_out = t;
        fprintf(csv, "%.6f,%.10g,%llu\n", t, m_out, (unsigned long long)count);
        series_add(&curve, t, m_out);
        if (isnan(t_slice) && 2 * m_out >= m_start) {
            t_slice = t;
            draw_slice(cr, w, o.diameter, t);
        }
        if (t >= t_print) {
            fprintf(stderr, "hopper: t = %.2f s after opening, %llu of %zu beads out (%.4f kg), "
                            "%.1f s so far\n",
                    t, (unsigned long long)count, n_start, m_out, now() - t_wall0);
            t_print += 0.25;
        }
    }
    output_close(csv, "discharge.csv");
    if (isnan(t_slice)) { /* less than half came out: the last state */
        t_slice = t;
        draw_slice(cr, w, o.diameter, t);
    }
    size_t n_end;
    const double m_end = particle_mass(w, &n_end);
    const char *ended = count == n_start           ? "empty"
                        : t - t_last_out >= 0.5     ? "jammed (nothing out for 0.5 s)"
                                                    : "time limit";

    /* the steady rate against Beverloo, Leniger and van de Velde (1961): W =
     * C rho_b sqrt(g) (D0 - k d)^(5/2), C = 0.58, k = 1.5, for a flat
     * bottom; Rose and Tanaka (1956) multiply it by (tan theta tan
     * phi_d)^-0.35 for a hopper of half-angle theta steeper than 90° -
     * phi_d, phi_d the angle of the stagnant zone's boundary to the
     * horizontal in a flat-bottomed bin, here 45°. */
    double t_from = NAN, t_to = NAN, fit_at;
    const double rate =
        fitted_rate(curve.a, curve.b, curve.n, 0.2 * m_out, 0.8 * m_out, &fit_at, &t_from, &t_to);
    const double d0 = 2 * ORIFICE_RADIUS, rho_b = phi * DENSITY;
    const double w_flat = 0.58 * rho_b * sqrt(9.81) * pow(d0 - 1.5 * o.diameter, 2.5);
    const double phi_d = 45.0 * PI / 180.0;
    const double beverloo[2] = {w_flat, w_flat * pow(tan(HALF_ANGLE) * tan(phi_d), -0.35)};
    draw_curve(cr, curve.a, curve.b, curve.n, rate, t_from, t_to, fit_at, t_slice, beverloo);
    char title[512];
    snprintf(title, sizeof title, "libdemill hopper (%s): %zu beads of %.0f mm, orifice %.0f mm",
             walls, n_start, 1e3 * o.diameter, 1e3 * d0);
    cairo_set_font_size(cr, 18);
    cairo_move_to(cr, 40, 36);
    cairo_show_text(cr, title);
    if (plot_finish(cr, surface, o.out, "hopper.png", "hopper"))
        return EXIT_FAILURE;

    FILE *sum = output_open(o.out, "summary.txt");
    const double wall = now() - t_wall0;
    fprintf(sum,
            "hopper = %s\nbead_diameter_m = %g\nbead_density_kg_m3 = %g\n"
            "orifice_diameter_m = %g\nhalf_angle_deg = %g\ninitial_particles = %zu\n"
            "initial_mass_kg = %.17g\nsolid_fraction = %.4f\nended = %s\n"
            "discharge_time_s = %.6g\ndischarged_particles = %llu\ndischarged_mass_kg = %.17g\n"
            "remaining_particles = %zu\nremaining_mass_kg = %.17g\nfit_window_s = %.4f %.4f\n"
            "steady_rate_kg_s = %.6g\nbeverloo_flat_kg_s = %.6g\nbeverloo_rose_tanaka_kg_s = %.6g\n"
            "time_step_s = %g\nsteps = %llu\nwall_s = %.2f\n",
            walls, o.diameter, DENSITY, d0, HALF_ANGLE * 180 / PI, n_start, m_start, phi,
            ended, t, (unsigned long long)count, m_out, n_end, m_end, t_from, t_to, rate,
            beverloo[0], beverloo[1], o.dt, (unsigned long long)steps, wall);
    output_close(sum, "summary.txt");
    printf("hopper: %s after %.2f s: %llu beads out (%.4f kg), %zu left; steady rate %.4f kg/s "
           "(Beverloo %.4f, with Rose & Tanaka's factor %.4f); %.1f s; results in %s/\n",
           ended, t, (unsigned long long)count, m_out, n_end, rate, beverloo[0], beverloo[1], wall,
           o.out);
    series_free(&curve);
    demill_world_destroy(w);
    return EXIT_SUCCESS;
}
