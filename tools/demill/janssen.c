/* janssen.c: outputs.janssen of the demill runner (janssen.h): the forces
 * on a silo's side by bands of height and on its floor, summed over the
 * samples of a window, and Janssen's profile against them in summary.txt,
 * silo.csv and silo.png. */
#include <math.h>
#include <stdlib.h>

#include <cairo.h>

#include "janssen.h"
#include "plot.h"
#include "run.h"

#define PI 3.14159265358979323846

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The wall of index k in the scene's walls: the scene's walls are the
 * world's, in the order of the file (demill_world_ids()). */
static demill_id wall_id(const scene *s, int k)
{
    size_t n = 0;
    demill_id *ids;
    check(demill_world_ids(s->w, DEMILL_KIND_WALL, NULL, 0, &n), "demill_world_ids");
    if ((size_t)k >= n || !(ids = malloc(n * sizeof *ids)))
        return DEMILL_ID_NONE;
    check(demill_world_ids(s->w, DEMILL_KIND_WALL, ids, n, &n), "demill_world_ids");
    const demill_id id = ids[k];
    free(ids);
    return id;
}

/* The index of the half-band below a height: the heights above the middle
 * of band k are those whose index is at least k (-1 below the first
 * middle, clamped to nb - 1 at the top). */
static long half_index(double h, double band, size_t nb)
{
    const double j = floor(h / band - 0.5);
    return j < -1 ? -1 : j > (double)nb - 1 ? (long)nb - 1 : (long)j;
}

int janssen_sample(const scene *s, janssen_acc *a)
{
    const double *up = s->silo_up, *o = s->silo_point, b = s->silo_band;
    if (!a->nb) {
        a->nb = (size_t)ceil(s->silo_top / b);
        a->normal = calloc(a->nb, sizeof *a->normal);
        a->shear = calloc(a->nb, sizeof *a->shear);
        a->vertical = calloc(a->nb, sizeof *a->vertical);
    }
    double *above = calloc(a->nb + 1, sizeof *above), *support = calloc(a->nb + 1, sizeof *support);
    size_t n, nm, nc = 0;
    double *x = plot_read_field(s->w, DEMILL_PARTICLE_POSITION, &n);
    double *m = plot_read_field(s->w, DEMILL_PARTICLE_MASS, &nm);
    double g[3];
    for (int j = 0; j < 3; j++)
        check(demill_world_get(s->w, DEMILL_WORLD_GRAVITY_X + j, &g[j]), "gravity");
    const double gn = sqrt(dot3(g, g));
    check(demill_contacts_read_ids(s->w, NULL, NULL, 0, &nc), "demill_contacts_read_ids");
    const size_t cap = nc ? nc : 1;
    demill_id *cb = malloc(cap * sizeof *cb);
    double *pt = malloc(3 * cap * sizeof *pt), *fn = malloc(3 * cap * sizeof *fn),
           *ft = malloc(3 * cap * sizeof *ft);
    const demill_id side = wall_id(s, s->silo_wall), floor_wall = wall_id(s, s->silo_floor);
    int rc = 0;
    if (!a->normal || !a->shear || !a->vertical || !above || !support || !x || !m || !cb || !pt ||
        !fn || !ft || !side || !floor_wall) {
        fprintf(stderr, "demill: outputs.janssen: cannot read the particles, the contacts or "
                        "the walls\n");
        rc = -1;
        goto out;
    }
    /* the particles in the silo: their weight, the weight above each band's
     * middle (by their centres) and the mass in the zone */
    for (size_t k = 0; k < n && k < nm; k++) {
        double d[3], r2 = 0;
        for (int j = 0; j < 3; j++)
            d[j] = x[3 * k + j] - o[j];
        const double h = dot3(d, up);
        for (int j = 0; j < 3; j++)
            r2 += (d[j] - h * up[j]) * (d[j] - h * up[j]);
        if (h < 0 || r2 > s->silo_radius * s->silo_radius)
            continue;
        a->weight += m[k] * gn;
        above[half_index(h, b, a->nb) + 1] += m[k] * gn;
        if (h >= s->silo_zone[0] && h < s->silo_zone[1])
            a->zone_mass += m[k];
    }
    /* the contacts with the side, by the height of the contact point (a
     * particle's centre's, the side being vertical), and with the floor */
    if (nc) {
        size_t got;
        check(demill_contacts_read_ids(s->w, NULL, cb, nc, &got), "demill_contacts_read_ids");
        check(demill_contacts_read(s->w, DEMILL_CONTACT_POINT, pt, nc, &got), "demill_contacts_read");
        check(demill_contacts_read(s->w, DEMILL_CONTACT_NORMAL_FORCE, fn, nc, &got),
              "demill_contacts_read");
        check(demill_contacts_read(s->w, DEMILL_CONTACT_TANGENTIAL_FORCE, ft, nc, &got),
              "demill_contacts_read");
    }
    for (size_t k = 0; k < nc; k++) {
        const double *p = pt + 3 * k, *f_n = fn + 3 * k, *f_t = ft + 3 * k;
        const double along = dot3(f_n, up) + dot3(f_t, up);
        if (cb[k] == floor_wall) {
            a->floor += along;
            continue;
        }
        if (cb[k] != side)
            continue;
        double d[3], out[3], rn = 0;
        for (int j = 0; j < 3; j++)
            d[j] = p[j] - o[j];
        const double h = dot3(d, up);
        for (int j = 0; j < 3; j++) {
            out[j] = d[j] - h * up[j];
            rn += out[j] * out[j];
        }
        rn = sqrt(rn);
        if (h < 0 || !(rn > 0))
            continue;
        const size_t band = (size_t)fmin(floor(h / b), (double)a->nb - 1);
        /* the particle pushes the side outwards: the force on the particle
         * along the outward radius is minus the normal force on the side */
        a->normal[band] -= dot3(f_n, out) / rn;
        a->shear[band] += along;
        support[half_index(h, b, a->nb) + 1] += along;
    }
    /* the force across the middle of band k: what lies above it, by the
     * sums from the top down */
    for (size_t k = a->nb; k-- > 0;) {
        above[k] += above[k + 1];
        support[k] += support[k + 1];
    }
    for (size_t k = 0; k < a->nb; k++)
        a->vertical[k] += above[k + 1] - support[k + 1];
    a->samples++;
out:
    free(above);
    free(support);
    free(x);
    free(m);
    free(cb);
    free(pt);
    free(fn);
    free(ft);
    return rc;
}

void janssen_free(janssen_acc *a)
{
    free(a->normal);
    free(a->shear);
    free(a->vertical);
    *a = (janssen_acc){0};
}

/* What the report draws: per band its depth and stresses, and the model. */
typedef struct profile {
    size_t n;                /* the bands below the surface */
    double *depth, *wall, *vertical;
    double fill, k, rho_g, g, length, sat, floor_stress;
    double zone_depth[2];
} profile;

/* Janssen (1895), Versuche über Getreidedruck in Silozellen: the mean
 * vertical stress at depth z, sigma_v = rho_b g D / (4 mu_w K) (1 -
 * exp(-4 mu_w K z / D)), rho_b g the bulk weight per volume and D / (4 mu_w
 * K) the length over which it saturates. */
static double janssen(double sat, double length, double z)
{
    return sat * -expm1(-z / length);
}

/* A key's line, its marker (a point or a line, dashed if asked) at (kx, ky). */
static void key_line(cairo_t *cr, double kx, double ky, const double rgb[3], int dashed, int dot,
                     const char *text)
{
    if (!dot) {
        plot_key(cr, kx, ky, rgb, dashed, text);
        return;
    }
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_arc(cr, kx + 15, ky, 4, 0, 2 * PI);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, kx + 38, ky + 4);
    cairo_show_text(cr, text);
}

static void points(cairo_t *cr, const plot_area *a, const double *x, const double *y, size_t n,
                   const double rgb[3], double radius)
{
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    for (size_t k = 0; k < n; k++) {
        cairo_arc(cr, plot_px(a, x[k]), plot_py(a, y[k]), radius, 0, 2 * PI);
        cairo_fill(cr);
    }
}

static int draw_silo(const char *dir, const profile *p, double diameter, double mu)
{
    const int wd = 1000, ht = 620, l = 90, r = 30, tp = 60, bt = 60, m = 200;
    double ymax = 1.15 * p->floor_stress;
    for (size_t k = 0; k < p->n; k++)
        ymax = fmax(ymax, 1.15 * fmax(p->wall[k], p->vertical[k]));
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 14, &s);
    const plot_area a = {l, tp, wd - l - r, ht - tp - bt, 0, 1.02 * p->fill, 0, ymax};
    const double blue[3] = {0.13, 0.37, 0.66}, red[3] = {0.85, 0.2, 0.1},
                 green[3] = {0.1, 0.55, 0.2}, grey[3] = {0.5, 0.5, 0.5},
                 lblue[3] = {0.55, 0.7, 0.9}, black[3] = {0, 0, 0};
    double zx[201], wy[201], vy[201], hy[2] = {0, p->rho_g * p->fill}, hx[2] = {0, p->fill};
    char key[200];
    /* the zone where K, mu_w and rho_b are measured, shaded */
    cairo_set_source_rgb(cr, 0.93, 0.95, 1.0);
    cairo_rectangle(cr, plot_px(&a, p->zone_depth[0]), tp,
                    plot_px(&a, p->zone_depth[1]) - plot_px(&a, p->zone_depth[0]), a.h);
    cairo_fill(cr);
    plot_ticks(cr, &a);
    for (int k = 0; k <= m; k++) {
        zx[k] = p->fill * k / m;
        vy[k] = janssen(p->sat, p->length, zx[k]);
        wy[k] = p->k * vy[k];
    }
    cairo_set_dash(cr, (const double[2]){8, 5}, 2, 0);
    plot_curve(cr, &a, hx, hy, 2, grey, 2.2);
    cairo_set_dash(cr, NULL, 0, 0);
    plot_curve(cr, &a, zx, vy, (size_t)m + 1, green, 2.2);
    plot_curve(cr, &a, zx, wy, (size_t)m + 1, red, 2.5);
    points(cr, &a, p->depth, p->vertical, p->n, lblue, 3);
    points(cr, &a, p->depth, p->wall, p->n, blue, 4.5);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, plot_px(&a, p->fill) - 6, plot_py(&a, p->floor_stress) - 6, 12, 12);
    cairo_fill(cr);
    const double kx = l + 20;
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, kx - 8, tp + 6, 640, 138);
    cairo_fill(cr);
    key_line(cr, kx, tp + 20, blue, 0, 1, "simulated wall normal stress, by bands of height");
    snprintf(key, sizeof key, "Janssen's wall stress K σ_v: K = %.3f and μ_w = %.3f measured in the shaded zone",
             p->k, mu);
    key_line(cr, kx, tp + 42, red, 0, 0, key);
    key_line(cr, kx, tp + 64, lblue, 0, 1, "simulated vertical stress σ_v: the weight above less the wall's support, over the area");
    snprintf(key, sizeof key, "Janssen's σ_v = ρ_b g D/(4 μ_w K) (1 − exp(−4 μ_w K z/D)), saturating at %.0f Pa", p->sat);
    key_line(cr, kx, tp + 86, green, 0, 0, key);
    snprintf(key, sizeof key, "hydrostatic ρ_b g z: a liquid of the bulk density, ρ_b = %.0f kg/m³",
             p->rho_g / p->g);
    key_line(cr, kx, tp + 108, grey, 1, 0, key);
    cairo_rectangle(cr, kx + 9, tp + 124, 12, 12);
    cairo_fill(cr);
    snprintf(key, sizeof key, "the floor's stress: %.0f Pa; Janssen's at the floor: %.0f Pa",
             p->floor_stress, janssen(p->sat, p->length, p->fill));
    cairo_move_to(cr, kx + 38, tp + 134);
    cairo_show_text(cr, key);
    plot_frame(cr, l, tp, wd - l - r, ht - tp - bt, ht, wd / 2 - 110,
               "depth below the surface z [m]");
    plot_y_title(cr, 28, tp + 0.5 * a.h + 60, "stress [Pa]");
    cairo_set_source_rgb(cr, black[0], black[1], black[2]);
    cairo_move_to(cr, l, 32);
    snprintf(key, sizeof key,
             "A silo of %.0f mm filled %.0f mm deep: stresses against depth, and Janssen's (1895) profile",
             1e3 * diameter, 1e3 * p->fill);
    cairo_show_text(cr, key);
    return plot_finish(cr, s, dir, "silo.png", "demill");
}

int janssen_report(const scene *s, const janssen_acc *a, FILE *sum, const char *dir)
{
    if (!a->samples) {
        fprintf(stderr, "demill: outputs.janssen: no sample in the window\n");
        return -1;
    }
    double g[3];
    for (int j = 0; j < 3; j++)
        demill_world_get(s->w, DEMILL_WORLD_GRAVITY_X + j, &g[j]);
    const double n = (double)a->samples, b = s->silo_band, gn = sqrt(dot3(g, g));
    const double dia = 2 * s->silo_radius, area = PI * s->silo_radius * s->silo_radius;
    const double strip = PI * dia * b, *z = s->silo_zone;
    /* in the zone, the bands that lie wholly in it: the mobilised wall
     * friction (the side's support over its normal force) and K (the wall's
     * normal stress over the vertical stress, ratio of their sums) */
    double sn = 0, st = 0, sh = 0, sv = 0;
    for (size_t k = 0; k < a->nb; k++)
        if (k * b >= z[0] - 1e-12 && (k + 1) * b <= z[1] + 1e-12) {
            sn += a->normal[k];
            st += a->shear[k];
            sh += a->normal[k] / strip;
            sv += a->vertical[k] / area;
        }
    const double mu = sn > 0 ? st / sn : NAN, kr = sv > 0 ? sh / sv : NAN;
    const double rho = a->zone_mass / n / (area * (z[1] - z[0]));
    const double fill = a->weight / n / gn / (rho * area);
    const double length = dia / (4 * mu * kr), sat = rho * gn * length;
    const double floor_stress = a->floor / n / area, pred = janssen(sat, length, fill);
    double support = 0;
    for (size_t k = 0; k < a->nb; k++)
        support += a->shear[k] / n;
    /* the bands below the surface */
    profile p = {.fill = fill, .k = kr, .rho_g = rho * gn, .g = gn, .length = length, .sat = sat,
                 .floor_stress = floor_stress, .zone_depth = {fill - z[1], fill - z[0]}};
    p.depth = malloc(a->nb * sizeof *p.depth);
    p.wall = malloc(a->nb * sizeof *p.wall);
    p.vertical = malloc(a->nb * sizeof *p.vertical);
    if (!p.depth || !p.wall || !p.vertical) {
        fprintf(stderr, "demill: out of memory\n");
        free(p.depth);
        free(p.wall);
        free(p.vertical);
        return -1;
    }
    FILE *csv = output_open(dir, "silo.csv");
    fputs("height_m,depth_m,wall_normal_Pa,wall_shear_Pa,vertical_Pa,janssen_vertical_Pa,"
          "janssen_wall_Pa,hydrostatic_Pa\n",
          csv);
    double dev = 0;
    for (size_t k = 0; k < a->nb && (k + 0.5) * b < fill; k++) {
        const double y = (k + 0.5) * b, d = fill - y, jv = janssen(sat, length, d);
        p.depth[p.n] = d;
        p.wall[p.n] = a->normal[k] / n / strip;
        p.vertical[p.n] = a->vertical[k] / n / area;
        fprintf(csv, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", y, d, p.wall[p.n],
                a->shear[k] / n / strip, p.vertical[p.n], jv, kr * jv, rho * gn * d);
        dev += pow((p.wall[p.n] - kr * jv) / (kr * sat), 2);
        p.n++;
    }
    output_close(csv, "silo.csv");
    fprintf(sum,
            "janssen_samples = %zu\nsilo_diameter_m = %.6g\nbulk_density_kg_m3 = %.6g\n"
            "fill_height_m = %.6g\nwall_friction_mobilised = %.4f\nstress_ratio_K = %.4f\n"
            "janssen_length_m = %.6g\njanssen_saturation_Pa = %.6g\n"
            "janssen_wall_saturation_Pa = %.6g\nfloor_stress_Pa = %.6g\njanssen_floor_Pa = %.6g\n"
            "floor_over_janssen = %.4f\nhydrostatic_floor_Pa = %.6g\n"
            "wall_profile_rms_over_saturation = %.4f\nweight_N = %.6g\nfloor_force_N = %.6g\n"
            "wall_support_N = %.6g\n",
            a->samples, dia, rho, fill, mu, kr, length, sat, kr * sat, floor_stress, pred,
            floor_stress / pred, rho * gn * fill, p.n ? sqrt(dev / p.n) : NAN, a->weight / n,
            a->floor / n, support);
    int rc = 0;
    if (p.n && isfinite(sat) && sat > 0)
        rc = draw_silo(dir, &p, dia, mu);
    else
        fprintf(stderr, "demill: outputs.janssen: no friction or no vertical stress in the zone "
                        "yet: no silo.png\n");
    free(p.depth);
    free(p.wall);
    free(p.vertical);
    return rc;
}
