/* spring_box.c: a body the particles move (demill/body.h), the example of
 * docs/geometry.md (The spring-mounted box): the box of a particle-damping
 * experiment, 42 × 24 × 42 mm inside, six plane walls attached to a body of
 * 0.3 kg on a spring of k = 9720 N/m along x (horizontal: it slides on a
 * frictionless guide, gravity along -y does not move it), undamped. It is
 * pulled 2 mm from its rest position and let go, twice: empty, when it
 * oscillates at its natural frequency √(k/m)/(2π) = 28.65 Hz with a
 * constant amplitude, and with steel balls inside, whose collisions with it
 * and each other take its energy. Writes displacement.csv (time, the box's
 * displacement empty and with balls) and spring-box.png (both against
 * time) to the output folder. Run `spring_box --help` for the options. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846
#define BOX_MASS 0.3
#define BOX_K 9720.0
#define PULL 0.002 /* m */

static void usage(FILE *f)
{
    fputs("usage: spring_box [options]\n"
          "Lets a spring-mounted box oscillate empty and with steel balls inside, and writes\n"
          "displacement.csv and spring-box.png to the output folder.\n\n"
          "  --balls N       balls of 3 mm diameter in the second run [300]\n"
          "  --time T        simulated time of each run, s [0.5]\n"
          "  --out DIR       output folder [spring-box-out]\n"
          "  --help          this text\n",
          f);
}

/* Runs the box for `time` from PULL away from rest, with `balls` balls
 * settled in it first, and records its displacement every 0.5 ms in s
 * (time in s, x in mm). */
static void run(size_t balls, double time, series *s)
{
    const double dt = 5e-6, half[3] = {0.021, 0.012, 0.021};
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "spring_box: cannot create a world\n");
        exit(EXIT_FAILURE);
    }
    example_world = w;
    demill_id steel, body, walls[6];
    check(demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt), "time step");
    check(demill_material_create(w, &steel), "demill_material_create");
    check(demill_material_set(w, steel, DEMILL_MATERIAL_DENSITY, 7800), "density");
    check(demill_material_set(w, steel, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e8), "modulus");
    check(demill_material_set(w, steel, DEMILL_MATERIAL_FRICTION, 0.3), "friction");
    check(demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law");
    check(demill_pair_set(w, steel, steel, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION),
          "damping");
    check(demill_pair_set(w, steel, steel, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN),
          "friction law");
    /* the six faces, facing the inside: face 2a + (s + 1)/2 is at s half[a]
     * on axis a */
    for (int f = 0; f < 6; f++) {
        const int a = f / 2;
        const double s = f % 2 ? 1.0 : -1.0;
        double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
        p[a] = s * half[a];
        n[a] = -s;
        check(demill_wall_add_plane(w, steel, p, n, &walls[f]), "a face of the box");
    }
    if (balls) { /* poured in and settled while the box is held */
        const double inside[6] = {-0.019, -0.010, -0.019, 0.019, 0.010, 0.019};
        const double sizes[2] = {0.003, 1.0};
        check(demill_fill_region(w, DEMILL_REGION_BOX, inside, 6, steel, DEMILL_SIZES_CLASSES,
                                 sizes, 2, DEMILL_FILL_COUNT, (double)balls, 7, NULL, 0, NULL),
              "filling the box");
        check(demill_world_settle(w, 0.5, 1e-9, NULL), "settling");
    }
    const double centre[3] = {0, 0, 0};
    check(demill_body_add(w, BOX_MASS, centre, DEMILL_BODY_AXIS_X, 0, &body), "demill_body_add");
    check(demill_body_set_spring(w, body, DEMILL_BODY_AXIS_X, BOX_K, 0, -PULL), "the spring");
    for (int f = 0; f < 6; f++)
        check(demill_body_attach_wall(w, body, walls[f]), "attaching a face");
    const uint64_t every = 100;
    for (uint64_t k = 0; k * every * dt <= time; k++) {
        double x[3];
        check(demill_body_get(w, body, DEMILL_BODY_POSITION, x), "demill_body_get");
        series_add(s, k * every * dt, 1e3 * (x[0] + PULL));
        check(demill_world_step(w, every), "stepping");
    }
    demill_world_destroy(w);
}

/* The mean period of the upward zero crossings of s, interpolated. */
static double period(const series *s)
{
    double first = NAN, last = NAN;
    int crossings = 0;
    for (size_t k = 1; k < s->n; k++)
        if (s->b[k - 1] < 0 && s->b[k] >= 0) {
            last = s->a[k - 1] + (s->a[k] - s->a[k - 1]) * -s->b[k - 1] / (s->b[k] - s->b[k - 1]);
            if (!crossings++)
                first = last;
        }
    return crossings > 1 ? (last - first) / (crossings - 1) : NAN;
}

/* The largest |x| over the last period of s. */
static double last_amplitude(const series *s, double t_period)
{
    double amp = 0;
    for (size_t k = 0; k < s->n; k++)
        if (s->a[k] >= s->a[s->n - 1] - t_period)
            amp = fmax(amp, fabs(s->b[k]));
    return amp;
}

int main(int argc, char **argv)
{
    example_program = "spring_box";
    const char *out = "spring-box-out";
    double balls = 300, time = 0.5;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v || (!strcmp(a, "--balls") && parse_number(a, v, 1, 2000, &balls)) ||
            (!strcmp(a, "--time") && parse_number(a, v, 0.05, 10, &time)))
            return EXIT_FAILURE;
        if (!strcmp(a, "--out"))
            out = v;
        else if (strcmp(a, "--balls") && strcmp(a, "--time")) {
            fprintf(stderr, "spring_box: unknown option %s (see spring_box --help)\n", a);
            return EXIT_FAILURE;
        }
    }
    if (example_make_dir(out))
        return EXIT_FAILURE;
    series empty = {0}, full = {0};
    run(0, time, &empty);
    run((size_t)balls, time, &full);
    const double f_n = sqrt(BOX_K / BOX_MASS) / (2 * PI), t_empty = period(&empty);
    FILE *csv = output_open(out, "displacement.csv");
    fprintf(csv, "time_s,empty_mm,with_balls_mm\n");
    for (size_t k = 0; k < empty.n; k++)
        fprintf(csv, "%.6f,%.9g,%.9g\n", empty.a[k], empty.b[k], full.b[k]);
    output_close(csv, "displacement.csv");

    cairo_surface_t *surface;
    cairo_t *cr = plot_canvas(1000, 520, 13, &surface);
    const plot_area a = {80, 70, 890, 390, 0, time, -1.1e3 * PULL, 1.1e3 * PULL};
    plot_ticks(cr, &a);
    const series *runs[2] = {&empty, &full};
    const double colours[2][3] = {{0.6, 0.6, 0.6}, {0.13, 0.37, 0.66}};
    char label[160];
    for (int c = 0; c < 2; c++) {
        plot_curve(cr, &a, runs[c]->a, runs[c]->b, runs[c]->n, colours[c], c ? 1.6 : 1.0);
        cairo_set_source_rgb(cr, colours[c][0], colours[c][1], colours[c][2]);
        if (c)
            snprintf(label, sizeof label, "with %.0f balls of 3 mm: amplitude %.2f mm after %g s",
                     balls, last_amplitude(&full, t_empty), time);
        else
            snprintf(label, sizeof label,
                     "empty: %.3f Hz (analytic √(k/m)/2π = %.3f Hz), amplitude %.2f mm after %g s",
                     1 / t_empty, f_n, last_amplitude(&empty, t_empty), time);
        cairo_move_to(cr, a.l + 10, a.tp - 28 + 16 * c);
        cairo_show_text(cr, label);
    }
    plot_frame(cr, a.l, a.tp, a.w, a.h, 520, a.l + a.w / 2 - 30, "time [s]");
    cairo_move_to(cr, a.l, 22);
    cairo_show_text(cr, "spring-mounted box (0.3 kg, k = 9720 N/m) let go 2 mm from rest: "
                        "displacement [mm]");
    if (plot_finish(cr, surface, out, "spring-box.png", "spring_box"))
        return EXIT_FAILURE;
    printf("spring_box: empty %.4f Hz (analytic %.4f Hz), amplitude %.3f mm after %g s; with %.0f "
           "balls %.3f mm; results in %s/\n",
           1 / t_empty, f_n, last_amplitude(&empty, t_empty), time, balls,
           last_amplitude(&full, t_empty), out);
    series_free(&empty);
    series_free(&full);
    return EXIT_SUCCESS;
}
