/* belt.c: a conveyor belt fed by a feed, the example of docs/geometry.md
 * (The belt example): a rectangle 0.6 m long and 0.3 m wide whose surface
 * moves at 1 m/s along x (demill_wall_set_surface_velocity), a feed that
 * drops 8 mm ore particles at 0.5 kg/s from a box above its tail
 * (demill_feed_create, at rest), and an outlet under the head that takes
 * away what falls off (demill_outlet_create). Every particle the belt
 * carries is brought from rest to the belt's speed, so once the stream is
 * steady the particles push the belt back along x with the force ṁ v (the
 * momentum they gain per second). Writes belt.csv (time, the belt's
 * horizontal force over each 10 ms, mass fed and discharged) and belt.png
 * (the particles seen from the side coloured by speed, over the force
 * against time) to the output folder. Run `belt --help` for the options. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846
#define SPEED 1.0 /* m/s */
#define RATE 0.5  /* kg/s */
#define TAIL (-0.05)
#define HEAD 0.55 /* the belt's ends along x, m */
#define HALF_WIDTH 0.15

static void usage(FILE *f)
{
    fputs("usage: belt [options]\n"
          "Feeds particles onto a moving belt and writes belt.csv and belt.png to the\n"
          "output folder.\n\n"
          "  --time T        simulated time, s; the force is averaged over its last 40 % [2.5]\n"
          "  --out DIR       output folder [belt-out]\n"
          "  --help          this text\n",
          f);
}

/* The side view (x right, y up) of the particles and the belt, in the
 * canvas's top part: seen along -z, the far ones first. */
static void draw_side(cairo_t *cr, demill_world *w, double t)
{
    const double scale = 1500, cx = 80 - TAIL * scale, cy = 230;
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 4);
    cairo_move_to(cr, cx + TAIL * scale, cy + 2);
    cairo_line_to(cr, cx + HEAD * scale, cy + 2);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1);
    cairo_set_dash(cr, (const double[]){6, 4}, 2, 0);
    cairo_rectangle(cr, cx - 0.03 * scale, cy - 0.09 * scale, 0.06 * scale, 0.06 * scale);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    double vmax;
    cairo_save(cr); /* what falls off the head stays above the plot */
    cairo_rectangle(cr, 0, 60, 1110, 290);
    cairo_clip(cr);
    if (plot_particles(cr, w, cx, cy, scale, INFINITY, "belt", &vmax))
        exit(EXIT_FAILURE);
    cairo_restore(cr);
    char label[96];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 14);
    cairo_move_to(cr, cx - 0.03 * scale, cy - 0.09 * scale - 8);
    cairo_show_text(cr, "feed");
    snprintf(label, sizeof label, "belt, %.1f m/s →", SPEED);
    cairo_move_to(cr, cx + 0.2 * scale, cy + 24);
    cairo_show_text(cr, label);
    snprintf(label, sizeof label, "seen from the side at t = %.2f s", t);
    cairo_move_to(cr, 40, 50);
    cairo_show_text(cr, label);
    plot_speed_bar(cr, 1130, 80, 200, vmax);
}

int main(int argc, char **argv)
{
    example_program = "belt";
    const char *out = "belt-out";
    double time = 2.5;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v || (!strcmp(a, "--time") && parse_number(a, v, 0.1, 60, &time)))
            return EXIT_FAILURE;
        if (!strcmp(a, "--out"))
            out = v;
        else if (strcmp(a, "--time")) {
            fprintf(stderr, "belt: unknown option %s (see belt --help)\n", a);
            return EXIT_FAILURE;
        }
    }
    if (example_make_dir(out))
        return EXIT_FAILURE;
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "belt: cannot create a world\n");
        return EXIT_FAILURE;
    }
    example_world = w;
    const double dt = 4e-5;
    demill_id ore, belt, feed, outlet;
    check(demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt), "time step");
    check(demill_material_create(w, &ore), "demill_material_create");
    check(demill_material_set(w, ore, DEMILL_MATERIAL_DENSITY, 2600), "density");
    check(demill_material_set(w, ore, DEMILL_MATERIAL_YOUNGS_MODULUS, 5e6), "modulus");
    check(demill_material_set(w, ore, DEMILL_MATERIAL_RESTITUTION, 0.3), "restitution");
    check(demill_material_set(w, ore, DEMILL_MATERIAL_FRICTION, 0.6), "friction");
    check(demill_material_set(w, ore, DEMILL_MATERIAL_ROLLING_FRICTION, 0.2), "rolling friction");
    check(demill_pair_set(w, ore, ore, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law");
    check(demill_pair_set(w, ore, ore, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION), "damping");
    check(demill_pair_set(w, ore, ore, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN),
          "friction law");
    check(demill_pair_set(w, ore, ore, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE),
          "rolling law");
    const double centre[3] = {0.5 * (TAIL + HEAD), 0, 0}, up[3] = {0, 1, 0}, along[3] = {1, 0, 0};
    const double u[3] = {SPEED, 0, 0}, rest[3] = {0, 0, 0}, sizes[2] = {0.008, 1.0};
    check(demill_wall_add_rectangle(w, ore, centre, up, along, 0.5 * (HEAD - TAIL), HALF_WIDTH,
                                    &belt),
          "the belt");
    check(demill_wall_set_surface_velocity(w, belt, u), "the belt's speed");
    const double hopper[6] = {-0.03, 0.03, -0.03, 0.03, 0.09, 0.03};
    check(demill_feed_create(w, DEMILL_REGION_BOX, hopper, 6, ore, DEMILL_SIZES_CLASSES, sizes, 2,
                             RATE, rest, 0, INFINITY, 3, &feed),
          "the feed");
    const double below[6] = {0, -0.1, 0, 0, 1, 0};
    check(demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, below, 6, 0, NULL, 0.01, &outlet),
          "the outlet");

    /* the belt's horizontal force, averaged over every step of 10 ms, and
     * over the last 40 % of the run, when the stream is steady */
    const double from = 0.6 * time;
    const uint64_t window = (uint64_t)lround(0.01 / dt);
    FILE *csv = output_open(out, "belt.csv");
    fprintf(csv, "time_s,belt_force_x_N,fed_kg,discharged_kg\n");
    series force = {0};
    double mean = 0, t = 0;
    size_t steady = 0;
    const double t0 = now();
    while (t < time - 0.5 * dt) {
        double sum = 0, f[3];
        for (uint64_t k = 0; k < window; k++) {
            check(demill_world_step(w, 1), "stepping");
            check(demill_wall_get(w, belt, DEMILL_WALL_FORCE, f), "the belt's force");
            sum += f[0];
        }
        check(demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        double fed, gone;
        check(demill_feed_read(w, feed, &fed, NULL, NULL), "demill_feed_read");
        check(demill_outlet_read(w, outlet, NULL, &gone, 1, NULL, NULL), "demill_outlet_read");
        series_add(&force, t, sum / window);
        fprintf(csv, "%.4f,%.6g,%.6g,%.6g\n", t, sum / window, fed, gone);
        if (t > from) {
            mean += sum / window;
            steady++;
        }
        if (fmod(t + 1e-9, 0.25) < 0.01)
            fprintf(stderr, "belt: t = %.2f s, %.3f kg fed, %.3f kg off the belt, %.1f s so far\n",
                    t, fed, gone, now() - t0);
    }
    output_close(csv, "belt.csv");
    mean /= steady;

    cairo_surface_t *surface;
    cairo_t *cr = plot_canvas(1200, 760, 18, &surface);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 40, 26);
    cairo_show_text(cr, "libdemill belt: 8 mm particles fed at 0.5 kg/s onto a belt moving at 1 m/s");
    draw_side(cr, w, t);
    const plot_area a = {110, 380, 1050, 310, 0, time, -2 * RATE * SPEED, 0.5 * RATE * SPEED};
    cairo_set_font_size(cr, 13);
    plot_ticks(cr, &a);
    plot_curve(cr, &a, force.a, force.b, force.n, (const double[3]){0.13, 0.37, 0.66}, 1.2);
    const double tx[2] = {0, time}, mv[2] = {-RATE * SPEED, -RATE * SPEED};
    const double mean_x[2] = {from, time}, mean_y[2] = {mean, mean};
    plot_curve(cr, &a, tx, mv, 2, (const double[3]){0.5, 0.5, 0.5}, 1.5);
    plot_curve(cr, &a, mean_x, mean_y, 2, (const double[3]){0.85, 0.2, 0.1}, 2.5);
    char label[128];
    snprintf(label, sizeof label,
             "mean from %.1f s (red): %.4f N;  -ṁ v (grey) = %.4f N;  ratio %.3f", from, mean,
             -RATE * SPEED, mean / (-RATE * SPEED));
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, a.l + 15, a.tp + 22);
    cairo_show_text(cr, label);
    plot_frame(cr, a.l, a.tp, a.w, a.h, 760, a.l + a.w / 2 - 30, "time [s]");
    cairo_move_to(cr, a.l, a.tp - 12);
    cairo_show_text(cr, "the particles' force on the belt along x [N], 10 ms means");
    if (plot_finish(cr, surface, out, "belt.png", "belt"))
        return EXIT_FAILURE;
    printf("belt: mean force on the belt along x from %.1f to %.1f s %.4f N; -ṁ v = %.4f N "
           "(ratio %.3f); results in %s/\n",
           from, t, mean, -RATE * SPEED, mean / (-RATE * SPEED), out);
    series_free(&force);
    demill_world_destroy(w);
    return EXIT_SUCCESS;
}
