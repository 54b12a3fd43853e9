/* repose_clumps.c: the angle of repose of a heap of dumbbells against a
 * heap of spheres (docs/shapes.md, The angle of repose of clumps).
 *
 * The same material (rock: 2700 kg/m³, E = 5e7 Pa, ν = 0.25, restitution
 * 0.5, friction 0.5, Hertz-Mindlin, no rolling friction) in two heaps: N
 * spheres of radius r, and N/2 dumbbells of two spheres of radius r whose
 * centres are r apart (clumps). Each charge is filled at rest into a
 * cylinder of radius 12 r standing on a rough floor (a square lattice of
 * fixed spheres of radius r, 2r apart, within 44 r of the axis, on a
 * plane), and the cylinder is
 * lifted at once: there is no wall, the column collapses into a heap as the
 * run starts. The run ends when the heap is at rest (no particle faster
 * than 10 mm/s, looked at every 20 ms after the first 0.2 s) or after
 * 1.5 s.
 *
 * The angle: the heap is axisymmetric, so each particle's top, y + r, is
 * taken against its distance from the axis, ρ = √(x² + z²). The surface
 * profile h(ρ) is the highest top in each ring of width 2r; the angle is
 * that of the least-squares line through the profile's points on the flank,
 * θ = atan(-slope): those 20 % to 80 % of the way from the top of one layer
 * lying in the floor's hollows, (1 + √2) r, to the summit (the rounded
 * summit and the toe, where a single layer runs out, left out; heap.h,
 * which the demill runner's outputs.repose shares). Writes
 * repose-clumps.png (both profiles with their fitted lines) to --out, and
 * prints the angles.
 *
 * usage: repose_clumps [--particles N] [--out DIR] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "heap.h"
#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846
#define R 0.002 /* the spheres' radius, m */
#define RINGS 64 /* the picture's rings */

/* A heap: its particles' (ρ, top) and its surface profile and fit. */
typedef struct heap {
    size_t n;
    double *rho, *top;
    heap_profile p;
} heap;

static void usage(FILE *f)
{
    fputs("usage: repose_clumps [--particles N] [--out DIR]\n"
          "Pours N spheres, and N/2 dumbbells of the same spheres, into heaps on a rough floor\n"
          "and measures their angles of repose; writes repose-clumps.png to DIR [.].\n"
          "  --particles N   spheres in each heap, even [1000]\n",
          f);
}

/* The world: gravity, the rock, a plane floor and its fixed spheres. */
static demill_world *make_world(demill_id *rock)
{
    demill_world *w;
    check(demill_world_create(3, &w), "demill_world_create");
    example_world = w;
    check(demill_material_create(w, rock), "material");
    const demill_id m = *rock;
    check(demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 2700), "density");
    check(demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, 5e7), "Young's modulus");
    check(demill_material_set(w, m, DEMILL_MATERIAL_POISSON_RATIO, 0.25), "Poisson ratio");
    check(demill_material_set(w, m, DEMILL_MATERIAL_RESTITUTION, 0.5), "restitution");
    check(demill_material_set(w, m, DEMILL_MATERIAL_FRICTION, 0.5), "friction");
    check(demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law");
    check(demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION), "damping");
    check(demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN), "friction");
    const double origin[3] = {0, -R, 0}, up[3] = {0, 1, 0};
    demill_id plane;
    check(demill_wall_add_plane(w, m, origin, up, &plane), "floor");
    /* the rough floor: fixed spheres 2r apart within 44 r of the axis */
    const int span = 22;
    double *x = malloc(3 * (size_t)(2 * span + 1) * (2 * span + 1) * sizeof *x), *rad;
    size_t nf = 0;
    for (int i = -span; i <= span; i++)
        for (int k = -span; k <= span; k++)
            if (i * i + k * k <= span * span) {
                x[3 * nf] = 2 * R * i;
                x[3 * nf + 1] = 0;
                x[3 * nf + 2] = 2 * R * k;
                nf++;
            }
    rad = malloc(nf * sizeof *rad);
    demill_id *ids = malloc(nf * sizeof *ids);
    if (!x || !rad || !ids) {
        fprintf(stderr, "repose_clumps: out of memory\n");
        exit(EXIT_FAILURE);
    }
    for (size_t k = 0; k < nf; k++)
        rad[k] = R;
    check(demill_particles_add(w, m, nf, x, rad, NULL, 0, ids), "the floor's spheres");
    const double one = 1;
    for (size_t k = 0; k < nf; k++)
        check(demill_particle_set(w, ids[k], DEMILL_PARTICLE_FIXED, &one), "fixing the floor");
    free(x);
    free(rad);
    free(ids);
    double dt;
    /* 20 steps across a contact at 0.5 m/s: well within the stability
     * limit, and the heap's slow contacts are resolved */
    check(demill_world_suggest_time_step(w, 0.5, 20, &dt, NULL, NULL), "time step");
    check(demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt), "time step");
    return w;
}

/* The heap's particles (the floor's left out), its profile and its fit. */
static void measure(demill_world *w, heap *h)
{
    size_t n;
    double *x = plot_read_field(w, DEMILL_PARTICLE_POSITION, &n);
    double *fixed = plot_read_field(w, DEMILL_PARTICLE_FIXED, &n);
    if (!x || !fixed) {
        fprintf(stderr, "repose_clumps: cannot read the particles\n");
        exit(EXIT_FAILURE);
    }
    h->rho = malloc(n * sizeof *h->rho);
    h->top = malloc(n * sizeof *h->top);
    h->n = 0;
    for (size_t k = 0; k < n; k++) {
        if (fixed[k] != 0 || !(x[3 * k + 1] > 0)) /* the floor, and any fallen off it */
            continue;
        h->rho[h->n] = hypot(x[3 * k], x[3 * k + 2]);
        h->top[h->n++] = x[3 * k + 1] + R;
    }
    free(x);
    free(fixed);
    /* the flank counted from the top of one layer in the floor's hollows,
     * (1 + √2) r */
    heap_fit(h->rho, h->top, h->n, 2 * R, (1 + sqrt(2.0)) * R, &h->p);
}

/* The largest speed of a particle, m/s. */
static double fastest(demill_world *w)
{
    size_t n;
    double *v = plot_read_field(w, DEMILL_PARTICLE_VELOCITY, &n), vmax = 0;
    if (!v) {
        fprintf(stderr, "repose_clumps: cannot read the particles\n");
        exit(EXIT_FAILURE);
    }
    for (size_t k = 0; k < n; k++)
        vmax = fmax(vmax, sqrt(v[3 * k] * v[3 * k] + v[3 * k + 1] * v[3 * k + 1] +
                               v[3 * k + 2] * v[3 * k + 2]));
    free(v);
    return vmax;
}

/* Pours one heap: N spheres (clumps = 0) or N/2 dumbbells. */
static void pour(long n, int clumps, heap *h)
{
    demill_id rock;
    demill_world *w = make_world(&rock);
    /* the column: radius 12 r, from the floor's top up */
    const double column[7] = {0, R, 0, 0, 0.5, 0, 12 * R};
    size_t added;
    if (clumps) {
        const double c[6] = {-0.5 * R, 0, 0, 0.5 * R, 0, 0}, r[2] = {R, R};
        demill_id tmpl;
        check(demill_clump_template_add(w, rock, 2, c, r, &tmpl), "dumbbell");
        check(demill_clump_fill_region(w, DEMILL_REGION_CYLINDER, column, 7, tmpl,
                                       DEMILL_FILL_COUNT, (double)(n / 2), 1, NULL, 0, &added),
              "filling the column with dumbbells");
    } else {
        const double sizes[2] = {2 * R, 1};
        check(demill_fill_region(w, DEMILL_REGION_CYLINDER, column, 7, rock, DEMILL_SIZES_CLASSES,
                                 sizes, 2, DEMILL_FILL_COUNT, (double)n, 1, NULL, 0, &added),
              "filling the column with spheres");
    }
    const double t0 = now();
    double t = 0, dt;
    int settled = 0;
    check(demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt), "time step");
    while (!settled && t < 1.5) {
        check(demill_world_step(w, (uint64_t)ceil(0.02 / dt)), "the collapse");
        check(demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        settled = t > 0.2 && fastest(w) < 1e-2;
    }
    measure(w, h);
    printf("repose_clumps: %ld %s: at rest%s after %.2f s (%.0f s of wall time), heap %.1f mm "
           "high, angle of repose %.1f deg (%d rings fitted)\n",
           clumps ? n / 2 : n, clumps ? "dumbbells" : "spheres", settled ? "" : " (not quite)", t,
           now() - t0, 1e3 * h->p.hmax, h->p.angle, h->p.nfit);
    demill_world_destroy(w);
    example_world = NULL;
}

/* One panel: the particles' tops against ρ, the profile and the fit. */
static void panel(cairo_t *cr, const plot_area *a, const heap *h, const char *title)
{
    plot_ticks(cr, a);
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.75);
    for (size_t k = 0; k < h->n; k++) {
        cairo_arc(cr, plot_px(a, 1e3 * h->rho[k]), plot_py(a, 1e3 * h->top[k]), 1.2, 0, 2 * PI);
        cairo_fill(cr);
    }
    double pr[HEAP_RINGS], ph[HEAP_RINGS];
    for (int q = 0; q < h->p.n; q++) {
        pr[q] = 1e3 * h->p.rho[q];
        ph[q] = 1e3 * h->p.h[q];
    }
    const double blue[3] = {0.13, 0.35, 0.65}, red[3] = {0.8, 0.15, 0.1};
    plot_curve(cr, a, pr, ph, (size_t)h->p.n, blue, 2);
    const double fx[2] = {a->x0, a->x1},
                 fy[2] = {1e3 * h->p.icept + h->p.slope * a->x0,
                          1e3 * h->p.icept + h->p.slope * a->x1};
    plot_curve(cr, a, fx, fy, 2, red, 2);
    char text[128];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, a->l + 10, a->tp + 20);
    cairo_show_text(cr, title);
    snprintf(text, sizeof text, "angle of repose %.1f deg", h->p.angle);
    cairo_set_source_rgb(cr, red[0], red[1], red[2]);
    cairo_move_to(cr, a->l + 10, a->tp + 40);
    cairo_show_text(cr, text);
}

int main(int argc, char **argv)
{
    example_program = "repose_clumps";
    long n = 1000;
    const char *out = ".";
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        double x;
        if (!v)
            return EXIT_FAILURE;
        if (!strcmp(a, "--particles")) {
            if (parse_number(a, v, 2, 1e6, &x))
                return EXIT_FAILURE;
            n = 2 * (long)(x / 2);
        } else if (!strcmp(a, "--out")) {
            out = v;
        } else {
            fprintf(stderr, "repose_clumps: unknown option %s\n", a);
            return EXIT_FAILURE;
        }
    }
    heap spheres, dumbbells;
    pour(n, 0, &spheres);
    pour(n, 1, &dumbbells);
    cairo_surface_t *s;
    const int wd = 1200, ht = 520;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const double hm = 1e3 * fmax(spheres.p.hmax, dumbbells.p.hmax) * 1.15;
    const double rm = 1e3 * 2 * R * RINGS * 0.6;
    plot_area left = {70, 30, 500, 420, 0, rm, 0, hm}, right = left;
    right.l = 670;
    char title[128];
    snprintf(title, sizeof title, "%ld spheres", n);
    panel(cr, &left, &spheres, title);
    plot_frame(cr, left.l, left.tp, left.w, left.h, ht, left.l + 0.5 * left.w,
               "distance from the axis (mm)");
    snprintf(title, sizeof title, "%ld dumbbells (two of those spheres, r apart)", n / 2);
    panel(cr, &right, &dumbbells, title);
    plot_frame(cr, right.l, right.tp, right.w, right.h, ht, right.l + 0.5 * right.w,
               "distance from the axis (mm)");
    if (plot_finish(cr, s, out, "repose-clumps.png", example_program))
        return EXIT_FAILURE;
    printf("repose_clumps: spheres %.1f deg, dumbbells %.1f deg\n", spheres.p.angle,
           dumbbells.p.angle);
    free(spheres.rho);
    free(spheres.top);
    free(dumbbells.rho);
    free(dumbbells.top);
    return EXIT_SUCCESS;
}
