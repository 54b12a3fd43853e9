/* main.c: the `demill` program: runs a scene file (docs/scene-files.md),
 * with overrides (--set), sweeps over one key's values and restarts from a
 * checkpoint; writes a time series, a summary, VTK files, pictures and a
 * checkpoint to the output folder, with the progress bar of the mill
 * example (examples/common/run.c) and its pictures (examples/mill/output.c). */
#define _POSIX_C_SOURCE 200809L /* isatty, strdup */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "clumps.h"
#include "conveyor.h"
#include "discharge.h"
#include "dissipation.h"
#include "repose.h"
#include "series_plot.h"
#include "drum_plot.h"
#include "janssen.h"
#include "plot.h"
#include "run.h"
#include "scene.h"
#include "shear.h"

#define PI 3.14159265358979323846
#define MAX_SETS 64
#define MAX_SWEEP 256

static void usage(FILE *f)
{
    fputs("usage: demill run SCENE.yaml [--out DIR] [--set KEY=VALUE]...\n"
          "       demill run --restart DIR/checkpoint [--out DIR] [--set KEY=VALUE]...\n"
          "       demill check SCENE.yaml [--set KEY=VALUE]...\n"
          "       demill keys\n"
          "Runs a libdemill scene file (docs/scene-files.md). `demill run --help` for the\n"
          "options; `check` reads the file and reports its first error without running;\n"
          "`keys` prints the tables of every key (docs/scene-files.md).\n",
          f);
}

static void usage_run(FILE *f)
{
    fputs("usage: demill run SCENE.yaml [options]\n"
          "       demill run --restart DIR/checkpoint [options]\n"
          "Builds the scene's world and runs it until its stop condition, writing to the\n"
          "output folder: scene.yaml (the scene as run), the time series, summary.txt,\n"
          "VTK files, pictures and `checkpoint` (the final state).\n\n"
          "  --out DIR            output folder [the scene's name without .yaml, e.g. mill;\n"
          "                       with --restart: DIR/restart]\n"
          "  --set KEY=VALUE      overrides the scene's entry at the dotted path KEY (a number\n"
          "                       indexes a list: particles.0.mass=5); VALUE is YAML, e.g.\n"
          "                       [0, -9.81, 0]. A comma list (drum.speed_fraction=0.6,0.7)\n"
          "                       runs a sweep: one folder per value, OUT/KEY=VALUE, and a\n"
          "                       table OUT/sweep.csv of their summaries. Repeatable; one\n"
          "                       key may be swept\n"
          "  --restart FILE       go on from the checkpoint FILE written by a run, with the\n"
          "                       scene.yaml beside it; only the world, materials, pairs,\n"
          "                       drum, outputs and stop may be changed with --set\n"
          "  --help               this text\n",
          f);
}

/* ---- one run ---------------------------------------------------------------- */

typedef struct run_args {
    const char *scene_path;  /* the scene file, or the checkpoint's scene.yaml */
    const char *restart;     /* the checkpoint, or NULL */
    const char *out;
    const char *set[MAX_SETS];
    size_t nset;
} run_args;

static void folder_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, len, ".");
    else
        snprintf(dir, len, "%.*s", (int)(slash - path) + (slash == path), path);
}

/* Reads the scene and applies the overrides: the tree, or NULL with a message. */
static tree *read_scene(const run_args *a)
{
    char err[1024];
    tree *t;
    if (tree_parse_file(a->scene_path, &t, err, sizeof err)) {
        fprintf(stderr, "demill: %s\n", err);
        return NULL;
    }
    for (size_t k = 0; k < a->nset; k++) {
        const char *eq = strchr(a->set[k], '=');
        char path[512];
        if (!eq || eq == a->set[k] || (size_t)(eq - a->set[k]) >= sizeof path) {
            fprintf(stderr, "demill: --set %s: expected KEY=VALUE\n", a->set[k]);
            tree_free(t);
            return NULL;
        }
        snprintf(path, sizeof path, "%.*s", (int)(eq - a->set[k]), a->set[k]);
        if (tree_set(t, path, eq + 1, err, sizeof err)) {
            fprintf(stderr, "demill: %s\n", err);
            tree_free(t);
            return NULL;
        }
    }
    return t;
}

static double drum_value(demill_world *w, demill_id d, int32_t key)
{
    double v;
    check(demill_drum_get(w, d, key, &v), "demill_drum_get");
    return v;
}

/* The power each size class draws: Σ over the contacts of the drum's
 * surfaces with a particle of the class of F·v_wall + T_roll·Ω, the force
 * F and rolling torque T_roll the drum exerts on the particle and v_wall
 * the velocity of the drum's surface at the contact point (its centre's
 * velocity plus Ω × r). Summed over the classes it is the drum's power
 * P = -T_z Ω - F_drum·v (DEMILL_DRUM_POWER), contact by contact. Class k
 * holds the diameters below edges[k], the last class the rest. */
static void power_by_class(demill_world *w, demill_id drum, const double *edges, size_t nedges,
                           double *power)
{
    size_t n = 0;
    for (size_t k = 0; k <= nedges; k++)
        power[k] = 0;
    check(demill_contacts_read_ids(w, NULL, NULL, 0, &n), "demill_contacts_read_ids");
    if (!n)
        return;
    demill_id *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    double *pt = malloc(3 * n * sizeof *pt), *fn = malloc(3 * n * sizeof *fn),
           *ft = malloc(3 * n * sizeof *ft), *tr = malloc(3 * n * sizeof *tr);
    if (!a || !b || !pt || !fn || !ft || !tr) {
        fprintf(stderr, "demill: out of memory\n");
        exit(EXIT_FAILURE);
    }
    size_t got;
    check(demill_contacts_read_ids(w, a, b, n, &got), "demill_contacts_read_ids");
    check(demill_contacts_read(w, DEMILL_CONTACT_POINT, pt, n, &got), "demill_contacts_read");
    check(demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, fn, n, &got), "demill_contacts_read");
    check(demill_contacts_read(w, DEMILL_CONTACT_TANGENTIAL_FORCE, ft, n, &got),
          "demill_contacts_read");
    check(demill_contacts_read(w, DEMILL_CONTACT_ROLLING_TORQUE, tr, n, &got),
          "demill_contacts_read");
    const double omega = drum_value(w, drum, DEMILL_DRUM_CURRENT_SPEED);
    const double c[3] = {drum_value(w, drum, DEMILL_DRUM_CENTER_X),
                         drum_value(w, drum, DEMILL_DRUM_CENTER_Y),
                         drum_value(w, drum, DEMILL_DRUM_CENTER_Z)};
    const double v[3] = {drum_value(w, drum, DEMILL_DRUM_CURRENT_VELOCITY_X),
                         drum_value(w, drum, DEMILL_DRUM_CURRENT_VELOCITY_Y),
                         drum_value(w, drum, DEMILL_DRUM_CURRENT_VELOCITY_Z)};
    for (size_t k = 0; k < n; k++) {
        if (b[k] != drum)
            continue;
        double r;
        check(demill_particle_get(w, a[k], DEMILL_PARTICLE_RADIUS, &r), "demill_particle_get");
        size_t cls = 0;
        while (cls < nedges && !(2 * r < edges[cls]))
            cls++;
        const double x = pt[3 * k] - c[0], y = pt[3 * k + 1] - c[1];
        const double vw[3] = {v[0] - omega * y, v[1] + omega * x, v[2]};
        double p = omega * tr[3 * k + 2];
        for (int j = 0; j < 3; j++)
            p += (fn[3 * k + j] + ft[3 * k + j]) * vw[j];
        power[cls] += p;
    }
    free(a);
    free(b);
    free(pt);
    free(fn);
    free(ft);
    free(tr);
}

/* Whether any particle's centre is inside the region of a stop.empty. */
static int region_holds_any(demill_world *w, size_t n, int32_t kind, const double *r, int dim)
{
    if (!n)
        return 0;
    double *x = malloc(3 * n * sizeof *x);
    size_t got;
    if (!x) {
        fprintf(stderr, "demill: out of memory\n");
        exit(EXIT_FAILURE);
    }
    check(demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, n, &got), "positions");
    int any = 0;
    for (size_t k = 0; k < got && !any; k++)
        any = scene_region_contains(kind, r, dim, x + 3 * k);
    free(x);
    return any;
}

/* A quantity of the scene (a column, the steady stop's). */
static double quantity(const scene *s, const scene_quantity *q)
{
    double v;
    check(scene_quantity_read(s, q, &v), q->name);
    return v;
}

/* The mean of the samples q->b[from .. from + win). */
static double window_mean(const series *q, size_t from, size_t win)
{
    double m = 0;
    for (size_t k = from; k < from + win; k++)
        m += q->b[k];
    return m / win;
}

/* Whether the last 2 × win samples' two halves have means within tol
 * (relative) of each other. */
static int steady(const series *q, size_t win, double tol)
{
    if (!win || q->n < 2 * win)
        return 0;
    const double a = window_mean(q, q->n - 2 * win, win), b = window_mean(q, q->n - win, win);
    return fabs(b - a) <= tol * fabs(b);
}

/* pictures: series: every column but the world's time against the time
 * (series_plot.c). 0, or -1 with a message on stderr. */
static int draw_series(const scene *s, const series *cols, const char *scene_path,
                       const char *dir)
{
    series_panel p[SCENE_MAX_COLUMNS];
    size_t np = 0;
    for (size_t k = 0; k < s->ncol; k++)
        if (s->col[k].key != DEMILL_WORLD_TIME)
            p[np++] = (series_panel){s->col[k].name, scene_quantity_unit(&s->col[k]), cols[k].b};
    if (!s->ncol || cols[0].n < 2 || !np) {
        fprintf(stderr, "demill: %zu samples of %zu columns: no series.png\n",
                s->ncol ? cols[0].n : 0, np);
        return 0;
    }
    char title[600];
    snprintf(title, sizeof title, "libdemill %s: the time series, one sample every %g s",
             scene_path, s->every);
    return series_plot(dir, title, cols[0].a, cols[0].n, p, np);
}

/* Runs one scene into a.out; the summary's text goes to *summary (the
 * caller frees it). 0, or -1 with a message on stderr. */
static int run_one(const run_args *a, char **summary)
{
    char err[1024], path[4096], dir[4096];
    tree *doc = read_scene(a);
    if (!doc)
        return -1;
    folder_of(a->scene_path, dir, sizeof dir);
    scene s = {0};
    if (a->restart) {
        if (demill_world_create(3, &s.w) != DEMILL_OK ||
            demill_world_load(s.w, a->restart) != DEMILL_OK) {
            fprintf(stderr, "demill: %s\n", s.w ? demill_world_last_error(s.w) : "no world");
            demill_world_destroy(s.w);
            tree_free(doc);
            return -1;
        }
    }
    if (scene_build(&s, doc, dir, a->restart ? SCENE_RESTART : SCENE_BUILD, err, sizeof err)) {
        fprintf(stderr, "demill: %s\n", err);
        if (a->restart)
            demill_world_destroy(s.w);
        tree_free(doc);
        return -1;
    }
    demill_world *w = s.w;
    example_world = w;
    if (example_make_dir(a->out))
        return -1;
    {
        FILE *f = output_open(a->out, "scene.yaml");
        fprintf(f, "# the scene as run by demill%s\n", a->restart ? " (restarted)" : "");
        tree_write(f, doc);
        output_close(f, "scene.yaml");
    }
    const double t_wall0 = now();
    const demill_id drum = s.drum;
    double t, critical = NAN, omega = 0, n_d;
    check(demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
    check(demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &n_d), "particles");
    const size_t n = (size_t)n_d;
    double mass, centre[3];
    check(clumps_charge(w, &mass, centre), "the charge's mass");
    if (drum) {
        critical = drum_value(w, drum, DEMILL_DRUM_CRITICAL_SPEED);
        omega = s.speed_key == DEMILL_DRUM_SPEED       ? s.speed_value
                : s.speed_key == DEMILL_DRUM_SPEED_RPM ? s.speed_value * 2 * PI / 60
                                                       : s.speed_value * critical;
    }
    const uint64_t chunk = (uint64_t)fmax(1, round(s.every / s.dt));
    const uint64_t vtk_steps = s.vtk_every > 0 ? (uint64_t)fmax(1, round(s.vtk_every / s.dt)) : 0;
    const uint64_t ckpt_steps =
        s.checkpoint_every > 0 ? (uint64_t)fmax(1, round(s.checkpoint_every / s.dt)) : 0;
    /* the steps to go, for the progress bar */
    double end = s.stop_time;
    if (!isnan(s.stop_revolutions) && omega != 0) {
        const double left = s.stop_revolutions - drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS);
        const double e = fmax(t, s.drum_start) + left * 2 * PI / fabs(omega);
        end = isnan(end) ? e : fmin(end, e);
    }
    const uint64_t total_steps = (uint64_t)fmax(1, ceil((end - t) / s.dt));
    fprintf(stderr, "demill: %s, %dD, %zu particles (%.4g kg), time step %g s, about %llu steps\n",
            a->scene_path, s.dim, n, mass, s.dt, (unsigned long long)total_steps);
    clumps_print(&s, stderr);

    FILE *csv = NULL;
    if (*s.csv_file) {
        csv = output_open(a->out, s.csv_file);
        for (size_t k = 0; k < s.ncol; k++)
            fprintf(csv, "%s%s", k ? "," : "", s.col[k].name);
        fputc('\n', csv);
    }
    demill_vtk_series *vtk = NULL;
    if (vtk_steps) {
        snprintf(path, sizeof path, "%s/scene", a->out);
        check(demill_vtk_series_open(w, path, &vtk), "demill_vtk_series_open");
    }
    series rows = {0}, turns = {0}; /* time, drum power; time, revolutions */
    double class_sum[SCENE_MAX_EDGES + 1] = {0}, class_now[SCENE_MAX_EDGES + 1];
    size_t class_samples = 0;
    double t_rev_start = NAN, t_rev_end = NAN;
    /* a restart goes on with the checkpoint's speed unless --set gives one */
    int turning = a->restart && drum && s.speed_key && t >= s.drum_start - 0.5 * s.dt;
    if (turning && s.speed_set)
        check(demill_drum_set(w, drum, s.speed_key, s.speed_value), "the drum's speed");
    series watched = {0}; /* the steady stop's quantity */
    series cols[SCENE_MAX_COLUMNS] = {{0}}; /* pictures: series: time and each column */
    /* outputs.discharge: time and the outlet's mass; time and the bed's
     * solid fraction; the particles' mean diameter and density now */
    series discharged = {0}, bulk = {0};
    const scene_quantity out_mass = {.name = "outlet mass", .body = -1,
                                     .outlet = s.discharge_outlet};
    double mean_diameter = NAN, density = NAN;
    conveyor_trace conveyor = {0}; /* outputs.conveyor: the outlet's mass, the belt's and chute's forces */
    janssen_acc silo = {0}; /* outputs.janssen: the sums over its window */
    /* outputs.amplitude: the least and largest values in its window */
    double amp_lo[SCENE_MAX_COLUMNS], amp_hi[SCENE_MAX_COLUMNS];
    for (size_t k = 0; k < s.namp; k++) {
        amp_lo[k] = INFINITY;
        amp_hi[k] = -INFINITY;
    }
    dissipation_track diss = {0}; /* outputs.dissipation */
    if (s.discharge_on && n) {
        size_t nm, nr;
        double *m = plot_read_field(w, DEMILL_PARTICLE_MASS, &nm);
        double *r = plot_read_field(w, DEMILL_PARTICLE_RADIUS, &nr);
        double sd = 0, sm = 0, sv = 0;
        for (size_t k = 0; m && r && k < nm && k < nr; k++) {
            sd += 2 * r[k];
            sm += m[k];
            sv += 4.0 / 3.0 * PI * r[k] * r[k] * r[k];
        }
        mean_diameter = sd / (double)nr;
        density = sm / sv;
        free(m);
        free(r);
    }
    shear_trace shear = {0}; /* outputs.shear */
    const size_t steady_win = s.steady_on ? (size_t)fmax(1, round(s.steady_window / s.every)) : 0;
    double emptied = NAN;
    uint64_t steps = 0;
    const double t_step0 = now();
    const int tty = isatty(fileno(stderr));
    progress_bar bar = {.w = w, .drum = drum, .total = total_steps, .particles = n,
                        .last = t_step0, .every = tty ? 0.25 : 10.0, .tty = tty,
                        .turning = turning};
    check(demill_world_set_progress(w, progress_show, &bar, chunk), "demill_world_set_progress");
    for (;;) {
        const double revs = drum ? drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS) : 0;
        if ((!isnan(s.stop_time) && t >= s.stop_time - 0.5 * s.dt) ||
            (!isnan(s.stop_revolutions) && revs >= s.stop_revolutions) ||
            (s.steady_on && steady(&watched, steady_win, s.steady_tolerance)))
            break;
        if (s.empty_kind && steps) {
            double count;
            check(demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &count), "particles");
            if (!region_holds_any(w, (size_t)count, s.empty_kind, s.empty_params, s.dim)) {
                emptied = t;
                break;
            }
        }
        if (drum && s.speed_key && !turning && t >= s.drum_start - 0.5 * s.dt) {
            check(demill_drum_set(w, drum, s.speed_key, s.speed_value), "the drum's speed");
            turning = bar.turning = 1;
        }
        for (size_t k = 0; k < s.nmotion; k++) {
            scene_motion *m = &s.motion[k];
            if (m->started || t < m->start - 0.5 * s.dt)
                continue;
            check(demill_wall_set_motion(w, m->wall, m->given[0] ? m->v[0] : NULL,
                                         m->given[1] ? m->v[1] : NULL, m->given[2] ? m->v[2] : NULL),
                  "a wall's motion");
            m->started = 1;
            if (s.shear_on && m->index == s.shear_wall)
                s.shear_start = t; /* the shear's displacement counts from here */
        }
        for (size_t k = 0; k < s.nbody; k++) {
            /* a load: F sin(2 pi 0 t + pi/2) = F, scaled up over its ramp;
             * set only when it changes (a change through the API restarts
             * the watchdog's energy balance) */
            scene_load *l = &s.load[k];
            const double f = t < l->start - 0.5 * s.dt ? 0
                             : l->ramp > 0               ? fmin(1, (t - l->start) / l->ramp)
                                                         : 1;
            const double amp[3] = {f * l->force[0], f * l->force[1], f * l->force[2]};
            if (l->on && f != l->applied)
                check(demill_body_set_force(w, s.body[k], amp, 0, 0.5 * PI), "a body's load");
            l->applied = f;
        }
        check(demill_world_step(w, chunk), "step");
        steps += chunk;
        bar.done = steps;
        check(demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        if (drum) {
            /* the measurement: the last revolution when the run stops by
             * revolutions, else all the time the drum turns */
            const double rev = drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS);
            if (turning && isnan(t_rev_start) &&
                (isnan(s.stop_revolutions) || rev + 1 >= s.stop_revolutions))
                t_rev_start = t;
            if (!isnan(s.stop_revolutions) && rev >= s.stop_revolutions)
                t_rev_end = t;
            series_add(&rows, t, drum_value(w, drum, DEMILL_DRUM_POWER));
            series_add(&turns, t, rev);
            if (s.nedges && !isnan(t_rev_start)) {
                power_by_class(w, drum, s.edges, s.nedges, class_now);
                for (size_t k = 0; k <= s.nedges; k++)
                    class_sum[k] += class_now[k];
                class_samples++;
            }
        }
        if (s.steady_on)
            series_add(&watched, t, quantity(&s, &s.steady));
        for (size_t k = 0; k < s.namp && t >= s.stop_time - s.amp_window - 0.5 * s.dt; k++) {
            const double v = quantity(&s, &s.amp[k]);
            amp_lo[k] = fmin(amp_lo[k], v);
            amp_hi[k] = fmax(amp_hi[k], v);
        }
        if (s.shear_on)
            shear_sample(&s, &shear, t);
        if (s.conveyor_on)
            conveyor_sample(&s, &conveyor, t);
        if (s.dissipation_on && t >= s.stop_time - s.dissipation_window - 0.5 * s.dt)
            dissipation_sample(&s, t, &diss);
        if (s.discharge_on) {
            series_add(&discharged, t, quantity(&s, &out_mass));
            series_add(&bulk, t, discharge_solid_fraction(&s));
        }
        if (s.janssen_on && t >= s.stop_time - s.silo_window - 0.5 * s.dt && janssen_sample(&s, &silo))
            return -1;
        if (csv) {
            for (size_t k = 0; k < s.ncol; k++)
                fprintf(csv, "%s%.9g", k ? "," : "", quantity(&s, &s.col[k]) + 0.0);
            fputc('\n', csv);
        }
        for (size_t k = 0; k < s.ncol && s.series_png; k++)
            series_add(&cols[k], t, quantity(&s, &s.col[k]));
        uint64_t step_count;
        {
            double sc;
            check(demill_world_get(w, DEMILL_WORLD_STEP_COUNT, &sc), "steps");
            step_count = (uint64_t)sc;
        }
        if (vtk_steps && step_count % vtk_steps < chunk)
            check(demill_vtk_series_write(w, vtk), "demill_vtk_series_write");
        if (ckpt_steps && step_count % ckpt_steps < chunk) {
            snprintf(path, sizeof path, "%s/checkpoint", a->out);
            check(demill_world_save(w, path), "demill_world_save");
        }
    }
    const double t_step1 = now();
    check(demill_world_set_progress(w, NULL, NULL, 0), "demill_world_set_progress");
    bar.total = steps ? steps : 1;
    bar.done = bar.total;
    bar.last = -INFINITY;
    progress_show(&bar, 0, 0, t, bar.rate);
    if (tty)
        fputc('\n', stderr);
    if (csv)
        output_close(csv, s.csv_file);
    if (vtk)
        check(demill_vtk_series_write(w, vtk), "demill_vtk_series_write");
    demill_vtk_series_close(vtk);
    snprintf(path, sizeof path, "%s/checkpoint", a->out);
    check(demill_world_save(w, path), "demill_world_save");

    /* the summary */
    char *text = NULL;
    size_t text_len = 0;
    FILE *sum = open_memstream(&text, &text_len);
    if (!sum) {
        fprintf(stderr, "demill: out of memory\n");
        return -1;
    }
    fprintf(sum, "scene = %s\ndim = %d\nparticles = %zu\nmass_kg = %.6g\nsteps = %llu\n"
                 "time_step_s = %g\nsimulated_s = %.6g\n",
            a->scene_path, s.dim, n, mass, (unsigned long long)steps, s.dt, t);
    clumps_report(&s, sum);
    const double mean_power = drum ? drum_value(w, drum, DEMILL_DRUM_POWER_MEAN) : NAN;
    if (drum) {
        fprintf(sum, "speed_rad_s = %.6g\ncritical_speed_rad_s = %.6g\n"
                     "speed_fraction_critical = %.6g\nrevolutions = %.0f\n"
                     "mean_power_W = %.6g\nmean_power_cm_W = %.6g\nmean_dissipation_W = %.6g\n"
                     "toe_deg = %.2f\nshoulder_deg = %.2f\ncom_deg = %.2f\n",
                omega, critical, omega / critical, drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS),
                mean_power, drum_value(w, drum, DEMILL_DRUM_POWER_CM_MEAN),
                drum_value(w, drum, DEMILL_DRUM_DISSIPATION_MEAN),
                drum_value(w, drum, DEMILL_DRUM_TOE_ANGLE_MEAN) * 180 / PI,
                drum_value(w, drum, DEMILL_DRUM_SHOULDER_ANGLE_MEAN) * 180 / PI,
                drum_value(w, drum, DEMILL_DRUM_COM_ANGLE_MEAN) * 180 / PI);
        if (s.nedges) {
            double total = 0;
            for (size_t k = 0; k <= s.nedges; k++)
                total += class_samples ? class_sum[k] / class_samples : NAN;
            for (size_t k = 0; k <= s.nedges; k++) {
                const double p = class_samples ? class_sum[k] / class_samples : NAN;
                if (k < s.nedges)
                    fprintf(sum, "class_%zu = diameter below %g m\n", k, s.edges[k]);
                else
                    fprintf(sum, "class_%zu = diameter %g m and above\n", k, s.edges[k - 1]);
                fprintf(sum, "class_%zu_power_W = %.6g\n", k, p);
                if (total != 0)
                    fprintf(sum, "class_%zu_power_share = %.4f\n", k, p / total);
            }
            fprintf(sum, "class_power_sum_W = %.6g\nclass_power_samples = %zu\n", total,
                    class_samples);
        }
    }
    for (size_t k = 0; k < s.noutlets; k++) {
        uint64_t counts[32];
        double masses[32], m = 0;
        size_t nc;
        unsigned long long c = 0;
        check(demill_outlet_read(w, s.outlet[k], counts, masses, 32, &nc, NULL), "an outlet");
        for (size_t j = 0; j < nc; j++) {
            c += counts[j];
            m += masses[j];
        }
        fprintf(sum, "outlet_%zu_particles = %llu\noutlet_%zu_mass_kg = %.6g\n", k, c, k, m);
    }
    {
        double end_count;
        check(demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &end_count), "particles");
        fprintf(sum, "particles_end = %.0f\n", end_count);
    }
    if (s.empty_kind)
        fprintf(sum, "emptied_s = %.6g\n", emptied);
    for (size_t k = 0; k < s.namp; k++)
        fprintf(sum, "amplitude_%s = %.6g\n", s.amp[k].name, 0.5 * (amp_hi[k] - amp_lo[k]));
    if (s.namp)
        fprintf(sum, "amplitude_window_s = %g\n", s.amp_window);
    if (s.dissipation_on)
        dissipation_report(&diss, sum);
    int rc = 0;
    if (s.discharge_on) {
        const discharge_trace trace = {discharged.a, discharged.b, bulk.b, discharged.n,
                                       mean_diameter, density};
        rc = discharge_report(&s, &trace, sum, a->out);
    }
    if (s.shear_on && shear_report(&s, &shear, sum, a->out))
        rc = -1;
    if (s.conveyor_on && conveyor_report(&s, &conveyor, sum, a->out))
        rc = -1;
    if (s.janssen_on && janssen_report(&s, &silo, sum, a->out))
        rc = -1;
    if (s.repose_on && repose_report(&s, sum, a->out))
        rc = -1;
    if (s.steady_on)
        fprintf(sum, "steady = %s\nsteady_mean = %.6g\n",
                steady(&watched, steady_win, s.steady_tolerance) ? "yes" : "no",
                watched.n >= steady_win ? window_mean(&watched, watched.n - steady_win, steady_win)
                                        : NAN);
    fprintf(sum, "wall_s = %.2f\nparticle_steps_per_s = %.4g\n", now() - t_wall0,
            steps * (double)n / (t_step1 - t_step0));
    fclose(sum);
    FILE *f = output_open(a->out, "summary.txt");
    fputs(text, f);
    output_close(f, "summary.txt");

    if (drum && (s.charge_png || s.power_png)) {
        drum_shape shape;
        char title[512];
        snprintf(title, sizeof title, "libdemill %s: %zu particles, %.0f %% of critical, t = %.2f s, mean power %.2f W",
                 a->scene_path, n, 100 * omega / critical, t, mean_power);
        snprintf(path, sizeof path, "%s/charge.png", a->out);
        if (s.charge_png && (drum_shape_read(w, drum, &shape) || draw_charge(path, w, &shape, title, "demill")))
            rc = -1;
        snprintf(path, sizeof path, "%s/power.png", a->out);
        if (s.power_png && rows.n < 2)
            fprintf(stderr, "demill: %zu sample of the power: no power.png\n", rows.n);
        else if (!rc && s.power_png) {
            const power_trace trace = {rows.a,     rows.b,     turns.b,
                                       rows.n,     s.drum_start, mean_power,
                                       isnan(t_rev_start) ? 0 : t_rev_start,
                                       isnan(t_rev_end) ? t : t_rev_end};
            if (draw_power(path, &trace, "demill"))
                rc = -1;
        }
    }
    if (s.series_png && draw_series(&s, cols, a->scene_path, a->out))
        rc = -1;
    printf("demill: done in %.1f s, t = %.4g s; results in %s/\n", now() - t_wall0, t, a->out);
    if (isfinite(mean_power))
        printf("        mean power over the last revolution %.4f W\n", mean_power);
    series_free(&rows);
    series_free(&turns);
    series_free(&watched);
    series_free(&discharged);
    series_free(&bulk);
    shear_trace_free(&shear);
    janssen_free(&silo);
    for (size_t k = 0; k < s.ncol; k++)
        series_free(&cols[k]);
    conveyor_free(&conveyor);
    demill_world_destroy(w);
    example_world = NULL;
    tree_free(doc);
    *summary = text;
    return rc;
}

/* Reads and checks the scene of a.scene_path with a's overrides, running
 * nothing (SCENE_CHECK): 0, or -1 with a message on stderr. */
static int check_scene(const run_args *a)
{
    tree *t = read_scene(a);
    char err[1024], dir[4096];
    scene s = {0};
    if (!t)
        return -1;
    folder_of(a->scene_path, dir, sizeof dir);
    const int bad = scene_build(&s, t, dir, SCENE_CHECK, err, sizeof err);
    if (bad)
        fprintf(stderr, "demill: %s\n", err);
    demill_world_destroy(s.w);
    tree_free(t);
    return bad;
}

/* ---- sweeps ------------------------------------------------------------------ */

/* A --set whose value is a comma list at the top level (not [..] or {..}). */
static int is_sweep(const char *set)
{
    const char *eq = strchr(set, '=');
    return eq && eq[1] != '[' && eq[1] != '{' && eq[1] != '"' && eq[1] != '\'' && strchr(eq, ',');
}

static int run_sweep(run_args *a, size_t which)
{
    const char *set = a->set[which], *eq = strchr(set, '=');
    char *values = strdup(eq + 1), *save = NULL;
    const char *base_out = a->out;
    char *sums[MAX_SWEEP];
    char *vals[MAX_SWEEP], *dirs[MAX_SWEEP];
    size_t nv = 0;
    int rc = 0;
    if (!values)
        return -1;
    /* every value checked before any runs (a restart's scene is checked
     * against its checkpoint as each run starts) */
    for (char *v = strtok_r(values, ",", &save); v && !a->restart; v = strtok_r(NULL, ",", &save)) {
        char one[4096];
        snprintf(one, sizeof one, "%.*s=%s", (int)(eq - set), set, v);
        run_args b = *a;
        b.set[which] = one;
        if (check_scene(&b)) {
            free(values);
            return -1;
        }
    }
    strcpy(values, eq + 1);
    if (example_make_dir(base_out)) {
        free(values);
        return -1;
    }
    for (char *v = strtok_r(values, ",", &save); v && nv < MAX_SWEEP; v = strtok_r(NULL, ",", &save)) {
        char one[4096], out[4096];
        snprintf(one, sizeof one, "%.*s=%s", (int)(eq - set), set, v);
        snprintf(out, sizeof out, "%s/%.*s=%s", base_out, (int)(eq - set), set, v);
        run_args b = *a;
        b.set[which] = one;
        b.out = out;
        fprintf(stderr, "demill: sweep %.*s = %s\n", (int)(eq - set), set, v);
        sums[nv] = NULL;
        vals[nv] = v;
        if (run_one(&b, &sums[nv]) || !(dirs[nv] = strdup(out))) {
            free(sums[nv]);
            rc = -1;
            break;
        }
        nv++;
    }
    if (!rc) {
        /* the table: the sweep's value, then every number of the first run's
         * summary but the timings, looked up by name in each run's */
        FILE *f = output_open(base_out, "sweep.csv");
        char *keys = strdup(sums[0]), *ls = NULL;
        const char *col[256];
        size_t ncol = 0;
        for (char *line = strtok_r(keys, "\n", &ls); line && ncol < 256; line = strtok_r(NULL, "\n", &ls)) {
            char *sep = strstr(line, " = "), *end;
            if (!sep)
                continue;
            strtod(sep + 3, &end);
            *sep = '\0';
            if (!*end && end != sep + 3 && strcmp(line, "wall_s") && strcmp(line, "particle_steps_per_s"))
                col[ncol++] = line;
        }
        fprintf(f, "%.*s", (int)(eq - set), set);
        for (size_t k = 0; k < ncol; k++)
            fprintf(f, ",%s", col[k]);
        fputc('\n', f);
        for (size_t r = 0; r < nv; r++) {
            fprintf(f, "%s", vals[r]);
            for (size_t k = 0; k < ncol; k++) {
                char key[256];
                snprintf(key, sizeof key, "\n%s = ", col[k]);
                const char *at = strstr(sums[r], key); /* the first line is the scene's name */
                const size_t len = at ? strcspn(at + strlen(key), "\n") : 0;
                fprintf(f, ",%.*s", (int)len, at ? at + strlen(key) : "");
            }
            fputc('\n', f);
        }
        free(keys);
        output_close(f, "sweep.csv");
        char swept[256];
        snprintf(swept, sizeof swept, "%.*s", (int)(eq - set), set);
        if (dissipation_draw_sweep(base_out, swept, vals, sums, nv))
            rc = -1;
        printf("demill: sweep of %zu runs; table in %s/sweep.csv\n", nv, base_out);
        rc = shear_sweep_report(base_out, dirs, sums, nv);
    }
    for (size_t k = 0; k < nv; k++) {
        free(sums[k]);
        free(dirs[k]);
    }
    free(values);
    return rc;
}

/* ---- the command line ---------------------------------------------------------- */

static int parse_run(int argc, char **argv, run_args *a, int check_only)
{
    static char scene_copy[4096], out_copy[4096];
    *a = (run_args){0};
    for (int k = 0; k < argc; k++) {
        const char *o = argv[k];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            usage_run(stdout);
            exit(EXIT_SUCCESS);
        }
        if (!strcmp(o, "--out") || !strcmp(o, "--set") || (!check_only && !strcmp(o, "--restart"))) {
            if (k + 1 >= argc) {
                fprintf(stderr, "demill: %s needs a value\n", o);
                return -1;
            }
            const char *v = argv[++k];
            if (!strcmp(o, "--out"))
                a->out = v;
            else if (!strcmp(o, "--restart"))
                a->restart = v;
            else if (a->nset == MAX_SETS) {
                fprintf(stderr, "demill: at most %d --set\n", MAX_SETS);
                return -1;
            } else {
                a->set[a->nset++] = v;
            }
        } else if (o[0] == '-' || a->scene_path) {
            fprintf(stderr, "demill: unknown option %s (see demill run --help)\n", o);
            return -1;
        } else {
            a->scene_path = o;
        }
    }
    if (!!a->scene_path == !!a->restart) {
        fprintf(stderr, "demill: give a scene file or --restart CHECKPOINT (see demill run --help)\n");
        return -1;
    }
    if (a->restart) {
        char dir[3800];
        folder_of(a->restart, dir, sizeof dir);
        snprintf(scene_copy, sizeof scene_copy, "%s/scene.yaml", dir);
        a->scene_path = scene_copy;
        if (!a->out) {
            snprintf(out_copy, sizeof out_copy, "%s/restart", dir);
            a->out = out_copy;
        }
    } else if (!a->out) {
        const char *base = strrchr(a->scene_path, '/');
        base = base ? base + 1 : a->scene_path;
        const size_t len = strlen(base);
        snprintf(out_copy, sizeof out_copy, "%.*s", (int)(len > 5 && !strcmp(base + len - 5, ".yaml") ? len - 5 : len), base);
        a->out = out_copy;
    }
    return 0;
}

int main(int argc, char **argv)
{
    example_program = "demill";
    if (demill_check_version(DEMILL_VERSION_NUMBER) != DEMILL_OK) {
        fprintf(stderr, "demill: built with libdemill %s headers, running with %s\n",
                DEMILL_VERSION_STRING, demill_version_string());
        return EXIT_FAILURE;
    }
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_FAILURE : EXIT_SUCCESS;
    }
    if (!strcmp(argv[1], "keys")) {
        scene_list_keys(stdout);
        return EXIT_SUCCESS;
    }
    const int check_only = !strcmp(argv[1], "check");
    if (strcmp(argv[1], "run") && !check_only) {
        fprintf(stderr, "demill: unknown command %s (run, check or keys; see demill --help)\n",
                argv[1]);
        return EXIT_FAILURE;
    }
    run_args a;
    if (parse_run(argc - 2, argv + 2, &a, check_only))
        return EXIT_FAILURE;
    if (check_only) {
        if (check_scene(&a))
            return EXIT_FAILURE;
        printf("demill: %s is a valid scene\n", a.scene_path);
        return EXIT_SUCCESS;
    }
    size_t sweep = MAX_SETS;
    for (size_t k = 0; k < a.nset; k++)
        if (is_sweep(a.set[k])) {
            if (sweep != MAX_SETS) {
                fprintf(stderr, "demill: one key may be swept at a time (%s and %s)\n",
                        a.set[sweep], a.set[k]);
                return EXIT_FAILURE;
            }
            sweep = k;
        }
    if (sweep != MAX_SETS)
        return run_sweep(&a, sweep) ? EXIT_FAILURE : EXIT_SUCCESS;
    char *summary = NULL;
    const int rc = run_one(&a, &summary);
    free(summary);
    return rc ? EXIT_FAILURE : EXIT_SUCCESS;
}
