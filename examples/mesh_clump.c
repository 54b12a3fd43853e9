/* mesh_clump.c: clump templates that fill a rock's closed mesh with 5, 10,
 * 20 and 40 spheres, the example of docs/shapes.md (Shapes from a mesh).
 *
 * The rock (rock/rock.stl, written by rock/make_stl.py: a perturbed
 * icosphere cut by six planes, 1280 triangles, about 60 x 42 x 30 mm, in
 * millimetres) is read with demill_clump_template_from_stl at scale 0.001,
 * once for each number of spheres, on a grid of 64 cubes along its longest
 * side (--cells). The program prints a table of the fits: the spheres
 * placed, the volume error, the largest deviations from the mesh's surface
 * to the spheres' union and back, the template's mass (density 2700 kg/m³)
 * and the CPU time each template took. It draws mesh-clump.png in the
 * output folder: the mesh seen along the file's z axis, its facets shaded
 * by their slope to a light, then for each N the mesh's silhouette, in
 * grey, and the spheres over it, the nearest drawn last, read with
 * demill_clump_template_spheres and taken back to the file's frame by the
 * template's centre and principal axes. To draw the silhouette the program
 * reads the file's triangles itself (ASCII or binary STL, without the
 * library's checks). Run `mesh_clump --help` for the options.
 */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <demill.h>

#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846
#define DENSITY 2700.0 /* kg/m³, a rock's */
#define SCALE 0.001    /* the file is in millimetres */
#define RUNS 4

static const size_t spheres[RUNS] = {5, 10, 20, 40};

typedef struct options {
    const char *out, *stl;
    double cells;
} options;

static void usage(FILE *f)
{
    fputs("usage: mesh_clump [options]\n"
          "Fills a rock's closed mesh (an STL file in millimetres) with 5, 10, 20 and 40\n"
          "spheres as clump templates, prints the fits and draws mesh-clump.png in the\n"
          "output folder.\n\n"
          "  --stl FILE        the rock [" ROCK_STL "]\n"
          "  --cells N         the fit's grid cubes along the longest side, 4 to 256 [64]\n"
          "  --out DIR         output folder [mesh-clump-out]\n"
          "  --help            this text\n",
          f);
}

static int parse_options(int argc, char **argv, options *o)
{
    *o = (options){.out = "mesh-clump-out", .stl = ROCK_STL, .cells = 64};
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v)
            return -1;
        if (!strcmp(a, "--stl"))
            o->stl = v;
        else if (!strcmp(a, "--out"))
            o->out = v;
        else if (!strcmp(a, "--cells")) {
            if (parse_number(a, v, 4, 256, &o->cells))
                return -1;
        } else {
            fprintf(stderr, "mesh_clump: unknown option %s (--help lists them)\n", a);
            return -1;
        }
    }
    return 0;
}

/* The file's triangles as corners (9 doubles each, mm), for the picture:
 * an ASCII file's "vertex x y z" lines, or a binary file's records. NULL
 * with a message when the file cannot be read. */
static double *read_corners(const char *path, size_t *nt)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        perror(path);
        return NULL;
    }
    char head[84];
    const size_t got = fread(head, 1, sizeof head, f);
    double *c = NULL;
    size_t n = 0, cap = 0;
    if (got >= 5 && !memcmp(head, "solid", 5) && memchr(head, '\n', got)) {
        rewind(f);
        char line[256];
        while (fgets(line, sizeof line, f)) {
            double x[3];
            if (sscanf(line, " vertex %lf %lf %lf", &x[0], &x[1], &x[2]) != 3)
                continue;
            if (n == cap) {
                cap = cap ? 2 * cap : 3072;
                double *g = realloc(c, 3 * cap * sizeof *c);
                if (!g)
                    break;
                c = g;
            }
            memcpy(c + 3 * n++, x, sizeof x);
        }
        n /= 3;
    } else if (got == sizeof head) {
        uint32_t count = 0;
        for (int k = 3; k >= 0; k--)
            count = count << 8 | (uint8_t)head[80 + k];
        c = malloc((count ? count : 1) * 9 * sizeof *c);
        unsigned char rec[50];
        while (c && n < count && fread(rec, 1, sizeof rec, f) == sizeof rec) {
            for (int j = 0; j < 9; j++) {
                uint32_t u = 0;
                for (int k = 3; k >= 0; k--)
                    u = u << 8 | rec[12 + 4 * j + k];
                float v;
                memcpy(&v, &u, sizeof v);
                c[9 * n + j] = v;
            }
            n++;
        }
    }
    fclose(f);
    if (!n) {
        fprintf(stderr, "mesh_clump: %s: no triangles to draw\n", path);
        free(c);
        return NULL;
    }
    *nt = n;
    return c;
}

/* A sphere as drawn: its centre in the file's frame (mm) and radius. */
typedef struct ball {
    double x[3], r;
} ball;

static int nearer_last(const void *a, const void *b)
{
    const ball *p = a, *q = b;
    return (p->x[2] > q->x[2]) - (p->x[2] < q->x[2]);
}

/* Template t's spheres in the file's frame, mm: x = centre + Σ b_i a_i
 * over the body-frame centre b and the principal axes a_i, over SCALE;
 * *n of them, in a new array. */
static ball *file_frame_spheres(demill_world *w, demill_id t, size_t *n)
{
    check(demill_clump_template_spheres(w, t, NULL, NULL, 0, n), "counting the spheres");
    double *b = malloc(4 * *n * sizeof *b), c[3], a[9];
    ball *s = malloc(*n * sizeof *s);
    if (!b || !s) {
        fprintf(stderr, "mesh_clump: out of memory\n");
        exit(EXIT_FAILURE);
    }
    check(demill_clump_template_spheres(w, t, b, b + 3 * *n, *n, n), "reading the spheres");
    check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_CENTRE, c), "the centre");
    check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_PRINCIPAL_AXES, a), "the axes");
    for (size_t k = 0; k < *n; k++) {
        const double *p = b + 3 * k;
        for (int j = 0; j < 3; j++)
            s[k].x[j] = (c[j] + p[0] * a[j] + p[1] * a[3 + j] + p[2] * a[6 + j]) / SCALE;
        s[k].r = b[3 * *n + k] / SCALE;
    }
    free(b);
    return s;
}

/* A facet to draw: its corners and the depth of its centre. */
typedef struct facet {
    const double *p;
    double z;
} facet;

static int far_first(const void *a, const void *b)
{
    const facet *p = a, *q = b;
    return (p->z > q->z) - (p->z < q->z);
}

/* The nt triangles (corners c, mm) seen along z from +z, the facets that
 * face the viewer drawn far to near, each grey by Lambert's cosine law to a
 * light from the upper left; the file's point (x, y) at pixel
 * (cx + x scale, cy - y scale). */
static void draw_mesh(cairo_t *cr, const double *c, size_t nt, double cx, double cy, double scale)
{
    facet *f = malloc(nt * sizeof *f);
    if (!f)
        return;
    size_t n = 0;
    for (size_t t = 0; t < nt; t++) {
        const double *p = c + 9 * t;
        const double nz = (p[3] - p[0]) * (p[7] - p[1]) - (p[6] - p[0]) * (p[4] - p[1]);
        if (nz > 0)
            f[n++] = (facet){p, (p[2] + p[5] + p[8]) / 3};
    }
    qsort(f, n, sizeof *f, far_first);
    const double light[3] = {-0.45, 0.55, 0.70};
    for (size_t k = 0; k < n; k++) {
        const double *p = f[k].p;
        const double e[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]},
                     g[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
        const double nrm[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2],
                               e[0] * g[1] - e[1] * g[0]};
        const double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        const double lit = fmax(0, (nrm[0] * light[0] + nrm[1] * light[1] + nrm[2] * light[2]) /
                                       (len * sqrt(0.45 * 0.45 + 0.55 * 0.55 + 0.70 * 0.70)));
        const double grey = 0.30 + 0.62 * lit;
        for (int j = 0; j < 3; j++)
            (j ? cairo_line_to : cairo_move_to)(cr, cx + p[3 * j] * scale,
                                                cy - p[3 * j + 1] * scale);
        cairo_close_path(cr);
        cairo_set_source_rgb(cr, grey, grey, 0.97 * grey);
        cairo_fill_preserve(cr);
        cairo_set_line_width(cr, 0.5);
        cairo_stroke(cr); /* the same colour: no seams between the facets */
    }
    cairo_set_line_width(cr, 1);
    free(f);
}

/* One panel: the silhouette of the nt triangles (corners c, mm) seen along
 * z and the n spheres s over it, the file's point (x, y) at pixel
 * (cx + x scale, cy - y scale). */
static void draw_panel(cairo_t *cr, const double *c, size_t nt, ball *s, size_t n, double cx,
                       double cy, double scale)
{
    /* every triangle counter-clockwise on the page, so that the winding
     * rule fills their union without seams */
    for (size_t t = 0; t < nt; t++) {
        const double *p = c + 9 * t;
        const double area = (p[3] - p[0]) * (p[7] - p[1]) - (p[6] - p[0]) * (p[4] - p[1]);
        const int order[2][3] = {{0, 1, 2}, {0, 2, 1}};
        const int *o = order[area < 0];
        for (int j = 0; j < 3; j++) {
            const double *q = p + 3 * o[j];
            (j ? cairo_line_to : cairo_move_to)(cr, cx + q[0] * scale, cy - q[1] * scale);
        }
        cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_set_source_rgb(cr, 0.80, 0.80, 0.80);
    cairo_fill(cr);
    qsort(s, n, sizeof *s, nearer_last);
    double lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < n; k++)
        lo = fmin(lo, s[k].x[2]), hi = fmax(hi, s[k].x[2]);
    for (size_t k = 0; k < n; k++) {
        double rgb[3];
        plot_colour(hi > lo ? 0.15 + 0.7 * (s[k].x[2] - lo) / (hi - lo) : 0.5, rgb);
        cairo_arc(cr, cx + s[k].x[0] * scale, cy - s[k].x[1] * scale, s[k].r * scale, 0, 2 * PI);
        cairo_set_source_rgba(cr, rgb[0], rgb[1], rgb[2], 0.6);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.15 * rgb[0], 0.15 * rgb[1], 0.15 * rgb[2]);
        cairo_stroke(cr);
    }
}

int main(int argc, char **argv)
{
    example_program = "mesh_clump";
    options o;
    if (parse_options(argc, argv, &o))
        return EXIT_FAILURE;
    if (example_make_dir(o.out))
        return EXIT_FAILURE;
    size_t nt;
    double *corners = read_corners(o.stl, &nt);
    if (!corners)
        return EXIT_FAILURE;
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "mesh_clump: cannot create a world\n");
        return EXIT_FAILURE;
    }
    example_world = w;
    demill_id rock;
    check(demill_material_create(w, &rock), "demill_material_create");
    check(demill_material_set(w, rock, DEMILL_MATERIAL_DENSITY, DENSITY), "the density");

    /* the picture: one panel per N, the same scale for all, the rock's
     * bounding box (seen along z) centred in each */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < 3 * nt; k++)
        for (int j = 0; j < 2; j++)
            lo[j] = fmin(lo[j], corners[3 * k + j]), hi[j] = fmax(hi[j], corners[3 * k + j]);
    const double panel = 400, top = 90, scale = 0.85 * panel / fmax(hi[0] - lo[0], hi[1] - lo[1]);
    const int height = (int)(top + scale * (hi[1] - lo[1]) + 60);
    cairo_surface_t *surface;
    cairo_t *cr = plot_canvas((int)((RUNS + 1) * panel), height, 18, &surface);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 20, 30);
    const char *slash = strrchr(o.stl, '/');
    char title[256];
    snprintf(title, sizeof title,
             "%s (%zu triangles) and the templates of N spheres that fill it, seen along z "
             "(the nearer spheres lighter)",
             slash ? slash + 1 : o.stl, nt);
    cairo_show_text(cr, title);
    draw_mesh(cr, corners, nt, panel / 2 - scale * (lo[0] + hi[0]) / 2, top + scale * hi[1],
              scale);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, 20, 65);
    cairo_show_text(cr, "the mesh");

    printf("%s: %zu triangles, %d cubes along the longest side\n", o.stl, nt, (int)o.cells);
    double mesh_volume = 0;
    printf("| N | volume error | deviation out, mm | deviation in, mm | mass, g | CPU time, s |\n"
           "|---|---|---|---|---|---|\n");
    for (int q = 0; q < RUNS; q++) {
        demill_id t;
        const clock_t c0 = clock();
        check(demill_clump_template_from_stl(w, rock, o.stl, SCALE, spheres[q], (int)o.cells, &t),
              "demill_clump_template_from_stl");
        const double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        double err, out, in, mass, count;
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_MESH_VOLUME, &mesh_volume), "fit");
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_FIT_VOLUME_ERROR, &err), "fit");
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_OUT, &out), "fit");
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_FIT_DEVIATION_IN, &in), "fit");
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_MASS, &mass), "mass");
        check(demill_clump_template_get(w, t, DEMILL_TEMPLATE_COUNT, &count), "count");
        printf("| %.0f | %.3f | %.2f | %.2f | %.2f | %.2f |\n", count, err, out / SCALE, in / SCALE,
               1e3 * mass, cpu);
        size_t n;
        ball *s = file_frame_spheres(w, t, &n);
        const double cx = (q + 1) * panel + panel / 2 - scale * (lo[0] + hi[0]) / 2,
                     cy = top + scale * hi[1];
        draw_panel(cr, corners, nt, s, n, cx, cy, scale);
        free(s);
        char label[128];
        snprintf(label, sizeof label, "N = %.0f: volume error %.3f", count, err);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, (q + 1) * panel + 20, 65);
        cairo_show_text(cr, label);
    }
    printf("mesh volume %.1f mm^3, the rock's mass %.2f g\n", mesh_volume / (SCALE * SCALE * SCALE),
           1e3 * DENSITY * mesh_volume);
    /* a scale bar of 10 mm */
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, 20, height - 25);
    cairo_line_to(cr, 20 + 10 * scale, height - 25);
    cairo_stroke(cr);
    cairo_move_to(cr, 30 + 10 * scale, height - 19);
    cairo_show_text(cr, "10 mm");
    free(corners);
    demill_world_destroy(w);
    return plot_finish(cr, surface, o.out, "mesh-clump.png", "mesh_clump") ? EXIT_FAILURE
                                                                          : EXIT_SUCCESS;
}
