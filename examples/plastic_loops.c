/* plastic_loops.c: the force-overlap loops of the elasto-plastic normal laws
 * (docs/physics.md, "Elasto-plastic normal laws"), the picture of that
 * section. A sphere of 5 mm radius, so heavy (density 1e20 kg/m³) that its
 * contact force does not slow it, is driven against a plane at a set speed:
 * in to an overlap of 1, out to 0.5, in again to 1.6, and out until it
 * leaves (in units of a reference overlap, 50 times the yield overlap δ_y
 * of Thornton's and the multi-path law at σ_y = 10 MPa, E = 1 GPa), so that
 * the contact loads, unloads, reloads along its unloading curve and loads on
 * past its old peak. Every step records the overlap and the normal force
 * (demill_contacts_read()). Writes loops.csv (law, overlap in µm, force in
 * N) and plastic-loops.png (the three laws side by side) to the output
 * folder, and prints each law's plastic work (DEMILL_ENERGY_DISSIPATED_PLASTIC)
 * with its residual overlap. Run `plastic_loops --help` for the options. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846
#define R 0.005          /* m */
#define E_MODULUS 1e9    /* Pa */
#define NU 0.3
#define SIGMA_Y 1e7      /* Pa */
#define STEPS 400        /* per leg of the path */

static void usage(FILE *f)
{
    fputs("usage: plastic_loops [options]\n"
          "Drives a sphere into a plane and out again on each elasto-plastic normal law, and\n"
          "writes loops.csv and plastic-loops.png to the output folder.\n\n"
          "  --out DIR       output folder [plastic-loops-out]\n"
          "  --help          this text\n",
          f);
}

static const int laws[3] = {DEMILL_NORMAL_THORNTON, DEMILL_NORMAL_WALTON_BRAUN,
                            DEMILL_NORMAL_PLASTIC_PATHS};
static const char *const names[3] = {"Thornton (1997)", "Walton and Braun (1986), e = 0.5",
                                     "Li, Gao, Zhang and Liu (2018), H = 1"};

/* Runs law k along the path (overlaps in units of ref), recording
 * (overlap µm, force N) in s; *plastic receives the plastic work booked. */
static void run(int k, double ref, series *s, double *plastic)
{
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "plastic_loops: cannot create a world\n");
        exit(EXIT_FAILURE);
    }
    example_world = w;
    demill_id m, plane, ball;
    check(demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0), "gravity");
    check(demill_material_create(w, &m), "demill_material_create");
    check(demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 1e20), "density");
    check(demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, E_MODULUS), "modulus");
    check(demill_material_set(w, m, DEMILL_MATERIAL_POISSON_RATIO, NU), "Poisson ratio");
    check(demill_material_set(w, m, DEMILL_MATERIAL_YIELD_STRESS, SIGMA_Y), "yield stress");
    /* Walton and Braun: k1 = 2e6 N/m in series with itself, e = 0.5 */
    check(demill_material_set(w, m, DEMILL_MATERIAL_STIFFNESS, 2e6), "stiffness");
    check(demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, laws[k]), "normal law");
    check(demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.5), "restitution");
    const double origin[3] = {0, 0, 0}, up[3] = {1, 0, 0};
    check(demill_wall_add_plane(w, m, origin, up, &plane), "plane");
    const double x[3] = {R, 0, 0}, v0[3] = {0, 0, 0}, r = R;
    check(demill_particles_add(w, m, 1, x, &r, v0, 0, &ball), "the sphere");
    /* the legs of the path: to 1, back to 0.5, to 1.6, and out */
    const double ends[4] = {1.0, 0.5, 1.6, -0.1}, speed = 1e-3;
    double at = 0.0;
    for (int leg = 0; leg < 4; leg++) {
        const double span = (ends[leg] - at) * ref, dt = fabs(span) / (speed * STEPS);
        const double v[3] = {-copysign(speed, span), 0, 0};
        check(demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt), "time step");
        check(demill_particle_set(w, ball, DEMILL_PARTICLE_VELOCITY, v), "velocity");
        for (int q = 0; q < STEPS; q++) {
            check(demill_world_step(w, 1), "stepping");
            size_t n;
            double d = 0, f[3] = {0, 0, 0};
            check(demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, &d, 1, &n), "overlap");
            if (n)
                check(demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, f, 1, &n), "force");
            series_add(s, 1e6 * (n ? d : 0.0), fabs(f[0]));
        }
        at = ends[leg];
    }
    check(demill_world_energy(w, DEMILL_ENERGY_DISSIPATED_PLASTIC, plastic), "energy");
    demill_world_destroy(w);
}

int main(int argc, char **argv)
{
    example_program = "plastic_loops";
    const char *out = "plastic-loops-out";
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v)
            return EXIT_FAILURE;
        if (!strcmp(a, "--out")) {
            out = v;
        } else {
            fprintf(stderr, "plastic_loops: unknown option %s (see plastic_loops --help)\n", a);
            return EXIT_FAILURE;
        }
    }
    if (example_make_dir(out))
        return EXIT_FAILURE;
    /* δ_y = R* (π p_y/(2 E*))² with p_y = 1.6 σ_y, R* = R and
     * E* = E/(2 (1 - ν²)) (a sphere on a plane of its own material) */
    const double e_star = E_MODULUS / (2 * (1 - NU * NU)), s = PI * 1.6 * SIGMA_Y / (2 * e_star);
    const double ref = 50 * R * s * s;
    series loops[3] = {{0}};
    double plastic[3];
    FILE *csv = output_open(out, "loops.csv");
    fprintf(csv, "law,overlap_um,force_N\n");
    for (int k = 0; k < 3; k++) {
        run(k, ref, &loops[k], &plastic[k]);
        for (size_t q = 0; q < loops[k].n; q++)
            fprintf(csv, "%d,%.9g,%.9g\n", laws[k], loops[k].a[q], loops[k].b[q]);
        printf("plastic_loops: %s: plastic work %.4g J\n", names[k], plastic[k]);
    }
    output_close(csv, "loops.csv");

    cairo_surface_t *surface;
    const int wd = 1320, ht = 460;
    cairo_t *cr = plot_canvas(wd, ht, 13, &surface);
    const double colour[3] = {0.13, 0.37, 0.66};
    for (int k = 0; k < 3; k++) {
        double fmax = 0;
        for (size_t q = 0; q < loops[k].n; q++)
            fmax = fmax > loops[k].b[q] ? fmax : loops[k].b[q];
        const double l = 70 + k * 430;
        cairo_set_font_size(cr, 13);
        const plot_area a = {l, 60, 340, 330, 0, 1.7e6 * ref, 0, 1.1 * fmax};
        plot_ticks(cr, &a);
        plot_curve(cr, &a, loops[k].a, loops[k].b, loops[k].n, colour, 1.6);
        plot_frame(cr, a.l, a.tp, a.w, a.h, ht, a.l + a.w / 2 - 50, "overlap [µm]");
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, a.l, 30);
        cairo_show_text(cr, names[k]);
        char label[80];
        snprintf(label, sizeof label, "normal force [N]; plastic work %.3g mJ", 1e3 * plastic[k]);
        cairo_move_to(cr, a.l, 48);
        cairo_show_text(cr, label);
    }
    if (plot_finish(cr, surface, out, "plastic-loops.png", "plastic_loops"))
        return EXIT_FAILURE;
    for (int k = 0; k < 3; k++)
        series_free(&loops[k]);
    printf("plastic_loops: results in %s/\n", out);
    return EXIT_SUCCESS;
}
