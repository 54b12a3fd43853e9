/* conveyor.c: outputs.conveyor of the demill runner (conveyor.h): the
 * belt's and the chute's forces along the belt sampled through the run,
 * the steady mass flow, resistance and power against the momentum the belt
 * gives the fed particles, the time series and the picture. */
#include <math.h>
#include <stdlib.h>

#include <cairo.h>

#include "conveyor.h"
#include "plot.h"

#define PI 3.14159265358979323846

static double along(const double f[3], const double u[3])
{
    return f[0] * u[0] + f[1] * u[1] + f[2] * u[2];
}

/* The particles' force on the belt: on every wall whose surface moves
 * (the belt's walls, scene.c), N. */
static void belt_force(demill_world *w, double f[3])
{
    size_t n;
    f[0] = f[1] = f[2] = 0;
    check(demill_world_ids(w, DEMILL_KIND_WALL, NULL, 0, &n), "the walls");
    demill_id *id = malloc((n ? n : 1) * sizeof *id);
    if (!id) {
        fprintf(stderr, "demill: out of memory\n");
        exit(EXIT_FAILURE);
    }
    check(demill_world_ids(w, DEMILL_KIND_WALL, id, n, &n), "the walls");
    for (size_t k = 0; k < n; k++) {
        double u[3], fk[3];
        check(demill_wall_get(w, id[k], DEMILL_WALL_SURFACE_VELOCITY, u), "a wall");
        if (u[0] == 0 && u[1] == 0 && u[2] == 0)
            continue;
        check(demill_wall_get(w, id[k], DEMILL_WALL_FORCE, fk), "the belt's force");
        for (int c = 0; c < 3; c++)
            f[c] += fk[c];
    }
    free(id);
}

void conveyor_sample(const scene *s, conveyor_trace *tr, double t)
{
    const scene_quantity out = {.name = "the conveyor's outlet", .body = -1,
                                .outlet = s->conveyor_outlet};
    double m, fb[3], fc[3] = {0, 0, 0};
    check(scene_quantity_read(s, &out, &m), out.name);
    belt_force(s->w, fb);
    if (s->conveyor_chute >= 0)
        check(demill_body_get(s->w, s->body[s->conveyor_chute], DEMILL_BODY_FORCE_PARTICLES, fc),
              "the chute's force");
    /* the particles' forces on the belt and the chute; the belt's
     * resistance is the one against its motion, the chute's push on the
     * particles the reaction of theirs on it */
    series_add(&tr->mass, t, m);
    series_add(&tr->belt, t, -along(fb, s->belt_dir));
    series_add(&tr->chute, t, -along(fc, s->belt_dir));
}

void conveyor_free(conveyor_trace *tr)
{
    series_free(&tr->mass);
    series_free(&tr->belt);
    series_free(&tr->chute);
}

/* The steady state over the samples from..n-1: the outlet's rate (the
 * least-squares slope of its mass against time), the means of the belt's
 * resistance over the whole window and its two halves, and of the chute's
 * push. */
typedef struct steady_state {
    size_t from, n;
    double rate, belt, belt_half[2], chute;
} steady_state;

static double mean_of(const double *b, size_t from, size_t to)
{
    double m = 0;
    for (size_t k = from; k < to; k++)
        m += b[k];
    return to > from ? m / (double)(to - from) : NAN;
}

static steady_state steady_of(const scene *s, const conveyor_trace *tr)
{
    steady_state st = {0, 0, NAN, NAN, {NAN, NAN}, NAN};
    const double *t = tr->mass.a;
    while (st.from < tr->mass.n && t[st.from] < s->conveyor_from - 0.5 * s->dt)
        st.from++;
    st.n = tr->mass.n - st.from;
    if (st.n < 3)
        return st;
    double mt = mean_of(t, st.from, tr->mass.n), mm = mean_of(tr->mass.b, st.from, tr->mass.n);
    double stt = 0, stm = 0;
    for (size_t k = st.from; k < tr->mass.n; k++) {
        stt += (t[k] - mt) * (t[k] - mt);
        stm += (t[k] - mt) * (tr->mass.b[k] - mm);
    }
    const size_t mid = st.from + st.n / 2;
    st.rate = stm / stt;
    st.belt = mean_of(tr->belt.b, st.from, tr->belt.n);
    st.belt_half[0] = mean_of(tr->belt.b, st.from, mid);
    st.belt_half[1] = mean_of(tr->belt.b, mid, tr->belt.n);
    st.chute = mean_of(tr->chute.b, st.from, tr->chute.n);
    return st;
}

/* The particles seen from the side (along -z) coloured by speed, with the
 * colour bar and a scale, in the canvas's band from y = top, ht high. */
static int draw_side(cairo_t *cr, const scene *s, double top, double ht, double t)
{
    size_t n;
    double *x = plot_read_field(s->w, DEMILL_PARTICLE_POSITION, &n);
    if (!x)
        return -1;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (size_t k = 0; k < n; k++) {
        x0 = fmin(x0, x[3 * k]);
        x1 = fmax(x1, x[3 * k]);
        y0 = fmin(y0, x[3 * k + 1]);
        y1 = fmax(y1, x[3 * k + 1]);
    }
    free(x);
    const double left = 60, width = 940, pad = 0.02;
    if (!n)
        x0 = y0 = 0, x1 = y1 = 1;
    const double scale = fmin(width / (x1 - x0 + 2 * pad), (ht - 70) / (y1 - y0 + 2 * pad));
    const double cx = left - (x0 - pad) * scale, cy = top + 40 + (y1 + pad) * scale;
    double vmax = 0;
    char label[160];
    cairo_save(cr);
    cairo_rectangle(cr, 0, top + 30, left + width + 10, ht - 30);
    cairo_clip(cr);
    const int bad = plot_particles(cr, s->w, cx, cy, scale, INFINITY, "demill", &vmax);
    cairo_restore(cr);
    if (bad)
        return -1;
    plot_speed_bar(cr, left + width + 40, top + 60, ht - 140, vmax);
    /* a scale of a round length near a fifth of the width */
    const double len = plot_tick_step(width / scale), sy = top + ht - 12;
    snprintf(label, sizeof label, "%g m", len);
    plot_scale_bar(cr, left, sy, len * scale, 5, 2, label);
    snprintf(label, sizeof label,
             "The particles at t = %.2f s seen from the side (along -z), coloured by speed; "
             "the belt moves at %.2f m/s to the right",
             t, s->belt_speed);
    cairo_move_to(cr, left, top + 20);
    cairo_show_text(cr, label);
    return 0;
}

/* The belt's resistance against time, averaged over 50 ms, with the
 * chute's push, the window's mean and the momentum balance, in the band
 * from y = top, ht high. */
static void draw_force(cairo_t *cr, const scene *s, const conveyor_trace *tr,
                       const steady_state *st, double v_in, double balance, double top, double ht,
                       double wd)
{
    const size_t n = tr->belt.n;
    const double *t = tr->belt.a;
    const size_t win = (size_t)fmax(1, round(0.05 / s->every));
    double *belt = malloc(n * sizeof *belt), *chute = malloc(n * sizeof *chute);
    if (!belt || !chute) {
        fprintf(stderr, "demill: out of memory\n");
        exit(EXIT_FAILURE);
    }
    double lo = 0, hi = fmax(balance, 0);
    for (size_t k = 0; k < n; k++) {
        const size_t from = k + 1 >= win ? k + 1 - win : 0;
        belt[k] = mean_of(tr->belt.b, from, k + 1);
        chute[k] = mean_of(tr->chute.b, from, k + 1);
        lo = fmin(lo, fmin(belt[k], chute[k]));
        hi = fmax(hi, fmax(belt[k], chute[k]));
    }
    const double l = 90, r = 30;
    const plot_area a = {l, top, wd - l - r, ht - 60, t[0], t[n - 1], lo, lo + 1.35 * (hi - lo)};
    const double t0 = t[st->from], t1 = t[n - 1];
    char key[200];
    cairo_set_source_rgb(cr, 0.93, 0.95, 1.0);
    cairo_rectangle(cr, plot_px(&a, t0), top, plot_px(&a, t1) - plot_px(&a, t0), a.h);
    cairo_fill(cr);
    plot_ticks(cr, &a);
    const double blue[3] = {0.13, 0.37, 0.66}, grey[3] = {0.55, 0.55, 0.55};
    plot_curve(cr, &a, t, chute, n, grey, 1.5);
    plot_curve(cr, &a, t, belt, n, blue, 2);
    const double kx = l + 20;
    snprintf(key, sizeof key, "belt's resistance over the window (shaded), mean: %.4f N", st->belt);
    plot_line_key(cr, &a, t0, st->belt, 0, t0, t1,
                  (const double[3]){0.85, 0.2, 0.1}, 0, kx, top + 20, key);
    snprintf(key, sizeof key,
             "momentum balance m' (v - v_in) = %.4f kg/s x (%.3f - %.3f) m/s = %.4f N",
             st->rate, s->belt_speed, v_in, balance);
    plot_line_key(cr, &a, t0, balance, 0, t[0], t1, (const double[3]){0.1, 0.55, 0.2}, 1, kx,
                  top + 42, key);
    cairo_set_source_rgb(cr, blue[0], blue[1], blue[2]);
    cairo_move_to(cr, kx + 38, top + 68);
    cairo_show_text(cr, "the particles' force on the belt against its motion, mean over 50 ms");
    cairo_set_source_rgb(cr, grey[0], grey[1], grey[2]);
    cairo_move_to(cr, kx + 38, top + 88);
    cairo_show_text(cr, "the chute's push on the particles along the belt, mean over 50 ms");
    plot_frame(cr, l, top, a.w, a.h, top + ht, wd / 2 - 30, "time t [s]");
    plot_y_title(cr, 28, top + 0.5 * a.h + 100, "force along the belt [N]");
    free(belt);
    free(chute);
}

int conveyor_report(const scene *s, const conveyor_trace *tr, FILE *sum, const char *dir)
{
    const steady_state st = steady_of(s, tr);
    /* The momentum balance of the particles along the belt's motion u:
     * they come in from the feed with the velocity v_feed, the chute and
     * the belt push them, and they leave through the outlet, which they
     * reach in free flight from the belt's end at its speed v. Steady,
     * F_belt + F_chute = m' (v - v_feed), so the belt's resistance is
     * F_belt = m' (v - v_in) with v_in = v_feed + F_chute / m', the
     * velocity along the belt with which the chute delivers them: the
     * acceleration resistance of DIN 22101 (2011), Continuous conveyors -
     * Belt conveyors for loose bulk materials - Basis for calculation and
     * dimensioning. */
    const double v_in = s->feed_along + st.chute / st.rate;
    const double balance = st.rate * (s->belt_speed - v_in);
    fprintf(sum,
            "conveyor_window_from_s = %.6g\nconveyor_window_to_s = %.6g\n"
            "conveyor_window_samples = %zu\nbelt_speed_m_s = %.6g\nfeed_rate_kg_s = %.6g\n"
            "mass_flow_kg_s = %.6g\nbelt_force_N = %.6g\nbelt_force_first_half_N = %.6g\n"
            "belt_force_second_half_N = %.6g\nbelt_power_W = %.6g\nchute_force_N = %.6g\n"
            "feed_velocity_m_s = %.6g\nlanding_velocity_m_s = %.6g\nmomentum_balance_N = %.6g\n"
            "belt_force_over_balance = %.4f\n",
            st.n ? tr->mass.a[st.from] : NAN, tr->mass.n ? tr->mass.a[tr->mass.n - 1] : NAN, st.n,
            s->belt_speed, s->feed_rate, st.rate, st.belt, st.belt_half[0], st.belt_half[1],
            st.belt * s->belt_speed, st.chute, s->feed_along, v_in, balance, st.belt / balance);
    FILE *f = output_open(dir, "conveyor.csv");
    fputs("time_s,discharged_kg,belt_force_N,belt_power_W,chute_force_N\n", f);
    for (size_t k = 0; k < tr->mass.n; k++)
        fprintf(f, "%.6g,%.9g,%.9g,%.9g,%.9g\n", tr->mass.a[k], tr->mass.b[k], tr->belt.b[k] + 0.0,
                tr->belt.b[k] * s->belt_speed + 0.0, tr->chute.b[k] + 0.0);
    output_close(f, "conveyor.csv");
    if (st.n < 3) {
        fprintf(stderr, "demill: %zu samples from %g s on: no steady state and no conveyor.png\n",
                st.n, s->conveyor_from);
        return 0;
    }
    const double wd = 1100, side = 440, plot = 420;
    cairo_surface_t *surface;
    cairo_t *cr = plot_canvas((int)wd, (int)(side + plot + 60), 14, &surface);
    char title[256];
    snprintf(title, sizeof title,
             "Belt conveyor at %.2f m/s carrying %.3f kg/s: resistance %.3f N, power %.3f W",
             s->belt_speed, st.rate, st.belt, st.belt * s->belt_speed);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 16);
    cairo_move_to(cr, 60, 28);
    cairo_show_text(cr, title);
    cairo_set_font_size(cr, 14);
    if (draw_side(cr, s, 40, side, tr->mass.a[tr->mass.n - 1])) {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
        return -1;
    }
    draw_force(cr, s, tr, &st, v_in, balance, side + 70, plot, wd);
    return plot_finish(cr, surface, dir, "conveyor.png", "demill");
}
