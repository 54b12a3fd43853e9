/* mill.c: the main job of libdemill: a laboratory ball mill.
 *
 * By default a 3D mill of the drum3d scene's geometry and materials (a
 * 0.3 m x 0.1 m drum with eight 15 mm lifters, steel balls, Hertz-Mindlin
 * contacts with restitution 0.5 and friction 0.5) charged with balls of
 * 5 mm radius to the drum3d charge's mass, settled for 0.3 s and turned for
 * two revolutions at 75 % of critical speed. --scene drum3d and --scene
 * drum2d run the canonical scenes exactly, as docs/scenes.md defines them. Writes a time series, a
 * summary, VTK files for ParaView and two pictures to the output folder;
 * progress goes to stderr. With --ore FILE, ore joins the charge and the
 * mill also writes the product of grinding it (ore.c). With --shape FILE
 * the charge is clumps of the spheres the file gives (shape.c) instead of
 * balls, at random orientations, to the same mass or filling. Run
 * `mill --help` for the options.
 */
#define _POSIX_C_SOURCE 200809L /* isatty */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "drum_plot.h"
#include "mill.h"
#include "run.h"

#define PI 3.14159265358979323846

typedef struct options {
    const char *scene, *out, *ore, *shape;
    double grind_minutes;
    int dim, lifters, threads;
    double diameter, length, speed, fill, radius, lifter_height, revolutions, dt, vtk_every;
    size_t particles; /* scenes: a fixed packing */
    double site_radius;
    double mass;      /* default charge mass when no --fill is given */
} options;

static void usage(FILE *f)
{
    fputs("usage: mill [options]\n"
          "Simulates a ball mill with libdemill and writes mill.csv, summary.txt, VTK files,\n"
          "charge.png and power.png to the output folder.\n\n"
          "  --scene NAME         default (a laboratory mill), drum3d or drum2d (the canonical\n"
          "                       scenes of docs/scenes.md, exactly; geometry options then not\n"
          "                       allowed)\n"
          "  --dim 2|3            2D (spheres moving in a plane) or 3D [3]\n"
          "  --diameter D         inner drum diameter, m [0.3]\n"
          "  --length L           drum length, m (3D) [0.1]\n"
          "  --speed PCT          speed, % of critical [75]\n"
          "  --fill PCT           bulk filling, % of the drum volume (bed porosity 40 %, in 2D\n"
          "                       20 %) [3D: 8.82 kg of balls, the drum3d charge; 2D: 30]\n"
          "  --lifters N          number of lifters [8]\n"
          "  --lifter-height H    lifter height and width, m [0.015]\n"
          "  --radius R           ball radius, m [0.005]\n"
          "  --revolutions N      revolutions to run after settling [2]\n"
          "  --time-step DT       s [1e-5]\n"
          "  --vtk-every T        seconds between VTK frames, 0 for none [0.1]\n"
          "  --threads N          threads; the results are the same for any number [1]\n"
          "  --out DIR            output folder [mill-out]\n"
          "  --ore FILE           add ore to the charge (the file's format: docs/grinding.md),\n"
          "                       record its impacts over the last revolution, and from them\n"
          "                       grind it: writes product.csv and product.png, and P80 and\n"
          "                       kWh/t to summary.txt. The coupling is one way: the DEM charge\n"
          "                       keeps its balls and its ore at the feed's sizes\n"
          "  --grind-minutes M    grinding time of the product with --ore, minutes [10]\n"
          "  --shape FILE         charge clumps instead of balls: rigid bodies of the spheres\n"
          "                       the file gives, one a line, \"x y z r\" in m ('#' comments;\n"
          "                       2D: z = 0), e.g. examples/mill/dumbbell.txt; filled at random\n"
          "                       orientations to the same mass (or --fill); not with --radius\n"
          "  --help               this text\n",
          f);
}

static int parse_options(int argc, char **argv, options *o)
{
    *o = (options){.scene = "default", .out = "mill-out", .grind_minutes = 10, .dim = 3, .lifters = 8, .threads = 1,
                   .diameter = 0.3, .length = 0.1, .speed = 75, .fill = 0, .radius = 0.005,
                   .lifter_height = 0.015, .revolutions = 2, .dt = 1e-5, .vtk_every = 0.1,
                   .mass = 10000 * 8.8216e-4};
    int geometry = 0, radius_given = 0;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = option_value(argc, argv, &k, usage);
        if (!v)
            return -1;
        double x;
        if (!strcmp(a, "--scene")) {
            o->scene = v;
        } else if (!strcmp(a, "--out")) {
            o->out = v;
        } else if (!strcmp(a, "--ore")) {
            o->ore = v;
        } else if (!strcmp(a, "--shape")) {
            o->shape = v;
            geometry = 1;
        } else if (!strcmp(a, "--grind-minutes")) {
            if (parse_number(a, v, 1e-6, 1e6, &o->grind_minutes))
                return -1;
        } else if (!strcmp(a, "--dim")) {
            if (parse_number(a, v, 2, 3, &x) || (x != 2 && x != 3)) {
                fprintf(stderr, "mill: --dim takes 2 or 3\n");
                return -1;
            }
            o->dim = (int)x;
            geometry = 1;
        } else if (!strcmp(a, "--revolutions")) {
            if (parse_number(a, v, 1, 1000, &x))
                return -1;
            o->revolutions = floor(x);
        } else if (!strcmp(a, "--threads")) {
            if (parse_number(a, v, 1, 1024, &x))
                return -1;
            if (x != floor(x)) {
                fprintf(stderr, "mill: --threads takes a whole number\n");
                return -1;
            }
            o->threads = (int)x;
        } else if (!strcmp(a, "--vtk-every")) {
            if (parse_number(a, v, 0, 1e6, &o->vtk_every))
                return -1;
        } else if (!strcmp(a, "--time-step")) {
            if (parse_number(a, v, 1e-9, 1e-2, &o->dt))
                return -1;
        } else {
            struct {
                const char *name;
                double *dst, lo, hi;
            } num[] = {{"--diameter", &o->diameter, 1e-3, 100},
                       {"--length", &o->length, 1e-4, 100},
                       {"--speed", &o->speed, 0, 300},
                       {"--fill", &o->fill, 0.1, 90},
                       {"--lifter-height", &o->lifter_height, 0, 10},
                       {"--radius", &o->radius, 1e-5, 1}};
            size_t j = 0;
            while (j < sizeof num / sizeof num[0] && strcmp(a, num[j].name))
                j++;
            if (j < sizeof num / sizeof num[0]) {
                if (parse_number(a, v, num[j].lo, num[j].hi, num[j].dst))
                    return -1;
                radius_given |= num[j].dst == &o->radius;
            } else if (!strcmp(a, "--lifters")) {
                if (parse_number(a, v, 0, 64, &x))
                    return -1;
                o->lifters = (int)x;
            } else {
                fprintf(stderr, "mill: unknown option %s (see mill --help)\n", a);
                return -1;
            }
            geometry = 1;
        }
    }
    if (o->shape && radius_given) {
        fprintf(stderr, "mill: --radius sets the balls' size; with --shape the file gives the "
                        "spheres' sizes\n");
        return -1;
    }
    if (strcmp(o->scene, "default")) {
        if (geometry) {
            fprintf(stderr, "mill: --scene %s is fixed (docs/scenes.md); only --revolutions, "
                            "--vtk-every, --threads, --out, --ore and --grind-minutes may be given "
                            "with it\n",
                    o->scene);
            return -1;
        }
        o->radius = 0.003;
        o->speed = 75;
        if (!strcmp(o->scene, "drum3d")) {
            o->particles = 10000;
            o->site_radius = 0.131;
        } else if (!strcmp(o->scene, "drum2d")) {
            o->dim = 2;
            o->diameter = 1.0;
            o->lifter_height = 0.03;
            o->particles = 8000;
            o->site_radius = 0.466;
        } else {
            fprintf(stderr, "mill: unknown scene %s (default, drum3d or drum2d)\n", o->scene);
            return -1;
        }
    }
    return 0;
}

static double drum_value(demill_world *w, demill_id d, int key)
{
    double v;
    check(demill_drum_get(w, d, key, &v), "demill_drum_get");
    return v;
}

static double world_energy(demill_world *w, int term)
{
    double v;
    check(demill_world_energy(w, term, &v), "demill_world_energy");
    return v;
}

int main(int argc, char **argv)
{
    example_program = "mill";
    options o;
    if (parse_options(argc, argv, &o))
        return EXIT_FAILURE;
    if (demill_check_version(DEMILL_VERSION_NUMBER) != DEMILL_OK) {
        fprintf(stderr, "mill: built with libdemill %s headers, running with %s\n",
                DEMILL_VERSION_STRING, demill_version_string());
        return EXIT_FAILURE;
    }
    ore_def ore;
    if (o.ore && ore_read(o.ore, &ore))
        return EXIT_FAILURE;
    shape_def spheres;
    if (o.shape && shape_read(o.shape, &spheres))
        return EXIT_FAILURE;
    if (example_make_dir(o.out))
        return EXIT_FAILURE;
    const double t_wall0 = now();

    /* the world, its steel, and the drum */
    const drum_geometry geo = {o.dim, o.dt, o.diameter, o.length, o.lifters, o.lifter_height};
    demill_world *w;
    demill_id steel, drum;
    if (scene_world(&geo, &w, &steel, &drum))
        return EXIT_FAILURE;
    example_world = w;
    check(demill_world_set(w, DEMILL_WORLD_THREADS, o.threads), "--threads");

    /* the charge */
    size_t n, clumps = 0;
    double clump_mass = 0.0;
    if (o.particles) {
        const scene_def sd = {o.dim, o.particles, o.site_radius, 15, -0.046};
        double *pos = malloc(3 * o.particles * sizeof *pos), *rad = malloc(o.particles * sizeof *rad);
        if (!pos || !rad || scene_packing(&sd, pos)) {
            fprintf(stderr, "mill: cannot build the %s packing\n", o.scene);
            return EXIT_FAILURE;
        }
        for (size_t k = 0; k < o.particles; k++)
            rad[k] = o.radius;
        check(demill_particles_add(w, steel, o.particles, pos, rad, NULL, DEMILL_ADD_NO_OVERLAP,
                                   NULL),
              "adding the charge");
        free(pos);
        free(rad);
        n = o.particles;
    } else {
        const double sizes[2] = {2 * o.radius, 1.0};
        if (o.dim == 2)
            check(demill_drum_set(w, drum, DEMILL_DRUM_FILL_POROSITY, 0.2), "porosity");
        /* 3D: the drum3d charge's mass unless a filling is given; 2D: 30 % */
        const double fill = o.fill > 0 ? o.fill : o.dim == 2 ? 30 : 0;
        const int32_t target = fill > 0 ? DEMILL_FILL_FRACTION : DEMILL_FILL_MASS;
        const double value = fill > 0 ? fill / 100 : o.mass;
        if (o.shape) {
            demill_id tmpl;
            check(demill_clump_template_add(w, steel, spheres.n, spheres.centres, spheres.radii, &tmpl),
                  "the clump template of --shape");
            check(demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_MASS, &clump_mass),
                  "the template's mass");
            check(demill_clump_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, tmpl, target, value,
                                           1, NULL, 0, &clumps),
                  "filling the drum with clumps");
            n = clumps * spheres.n;
        } else {
            check(demill_drum_fill(w, drum, steel, DEMILL_SIZES_CLASSES, sizes, 2, target, value,
                                   1, NULL, 0, &n),
                  "filling the drum");
        }
    }
    /* the charge's mass: the clumps', or the sum of the balls' (a member
     * reads its clump's mass) */
    double mass = clumps * clump_mass;
    if (!clumps) {
        double *m = malloc(n * sizeof *m);
        size_t count;
        check(demill_particles_read(w, DEMILL_PARTICLE_MASS, m, n, &count), "masses");
        for (size_t k = 0; k < n; k++)
            mass += m[k];
        free(m);
    }
    /* the ore, after the balls have been weighed */
    demill_id ore_mat = 0;
    size_t n_ore = 0;
    if (o.ore && ore_add(w, steel, drum, &ore, &ore_mat, &n_ore))
        return EXIT_FAILURE;

    /* settle 0.3 s at rest, then turn */
    const double settle = 0.3;
    const double omega_c = drum_value(w, drum, DEMILL_DRUM_CRITICAL_SPEED);
    const double omega = o.speed / 100 * omega_c, period = omega > 0 ? 2 * PI / omega : 0;
    const uint64_t sample = (uint64_t)fmax(1, round(1e-3 / o.dt));
    const uint64_t vtk_steps = o.vtk_every > 0 ? (uint64_t)fmax(1, round(o.vtk_every / o.dt)) : 0;
    const double total_time = settle + (period > 0 ? o.revolutions * period : 1.0);
    const uint64_t total_steps = (uint64_t)ceil(total_time / o.dt);
    char what[128];
    if (clumps)
        snprintf(what, sizeof what, "%zu clumps of %zu spheres", clumps, spheres.n);
    else
        snprintf(what, sizeof what, "%zu balls", n);
    fprintf(stderr, "mill: %s, %dD, %s (%.3f kg) and %zu ore particles in a %.3f m drum, %d "
                    "lifters, %.0f %% of critical (%.4f rad/s), %.0f revolutions, about %llu steps\n",
            o.scene, o.dim, what, mass, n_ore, o.diameter, o.lifters, o.speed, omega, o.revolutions,
            (unsigned long long)total_steps);

    char path[4096];
    FILE *csv = output_open(o.out, "mill.csv");
    fprintf(csv, "time_s,torque_Nm,power_W,power_cm_W,kinetic_J,dissipated_J,toe_deg,"
                 "shoulder_deg,com_deg,revolutions\n");
    series rows = {0}, turns = {0}; /* time, power; time, revolutions */
    demill_vtk_series *series = NULL;
    if (vtk_steps) {
        snprintf(path, sizeof path, "%s/mill", o.out);
        check(demill_vtk_series_open(w, path, &series), "demill_vtk_series_open");
    }

    uint64_t steps = 0, frame_step = UINT64_MAX;
    double t = 0, contacts_sum = 0, t_rev_start = NAN, t_rev_end = NAN;
    int contact_samples = 0, turning = 0;
    const double t_step0 = now();
    const int tty = isatty(fileno(stderr));
    progress_bar bar = {.w = w, .drum = drum, .total = total_steps, .particles = n + n_ore,
                    .last = t_step0, .every = tty ? 0.25 : 10.0, .tty = tty};
    check(demill_world_set_progress(w, progress_show, &bar, sample), "demill_world_set_progress");
    while (period > 0 ? drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS) < o.revolutions
                      : t < total_time) {
        if (!turning && t >= settle - 0.5 * o.dt) {
            check(demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, o.speed / 100), "speed");
            turning = bar.turning = 1;
        }
        check(demill_world_step(w, sample), "step");
        steps += sample;
        bar.done = steps;
        check(demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        /* the measurement revolution is the last one */
        const uint64_t rev = (uint64_t)drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS);
        if (turning && isnan(t_rev_start) && rev + 1 >= (uint64_t)o.revolutions) {
            t_rev_start = t;
            if (o.ore && ore_record(w, drum, ore_mat, &ore))
                return EXIT_FAILURE;
        }
        if (rev >= (uint64_t)o.revolutions)
            t_rev_end = t;
        /* contacts per particle over the measurement revolution, every 1000 steps */
        if (!isnan(t_rev_start) && steps % 1000 < sample) {
            double c;
            check(demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &c), "contacts");
            contacts_sum += 2 * c / n;
            contact_samples++;
        }
        const double power = drum_value(w, drum, DEMILL_DRUM_POWER);
        fprintf(csv, "%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%.2f,%.2f,%.2f,%llu\n", t,
                drum_value(w, drum, DEMILL_DRUM_TORQUE) + 0.0, power + 0.0,
                drum_value(w, drum, DEMILL_DRUM_POWER_CM) + 0.0,
                world_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                    world_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL),
                world_energy(w, DEMILL_ENERGY_DISSIPATED),
                drum_value(w, drum, DEMILL_DRUM_TOE_ANGLE) * 180 / PI,
                drum_value(w, drum, DEMILL_DRUM_SHOULDER_ANGLE) * 180 / PI,
                drum_value(w, drum, DEMILL_DRUM_COM_ANGLE) * 180 / PI, (unsigned long long)rev);
        series_add(&rows, t, power);
        series_add(&turns, t, (double)rev);
        if (vtk_steps && steps % vtk_steps < sample) {
            check(demill_vtk_series_write(w, series), "demill_vtk_series_write");
            frame_step = steps;
        }
    }
    const double t_step1 = now();
    check(demill_world_set_progress(w, NULL, NULL, 0), "demill_world_set_progress");
    bar.total = steps; /* the last line: 100 % */
    bar.last = -INFINITY;
    progress_show(&bar, 0, 0, t, bar.rate);
    if (tty)
        fputc('\n', stderr);
    output_close(csv, "mill.csv");
    if (series && frame_step != steps) /* the final state */
        check(demill_vtk_series_write(w, series), "demill_vtk_series_write");
    demill_vtk_series_close(series);

    /* pictures, series, summary */
    drum_shape shape;
    if (drum_shape_read(w, drum, &shape))
        return EXIT_FAILURE;
    const double mean_power = drum_value(w, drum, DEMILL_DRUM_POWER_MEAN);
    char title[256];
    snprintf(title, sizeof title, "libdemill %s mill, %dD: %s, %.0f %% of critical, t = %.2f s, mean power %.2f W",
             o.scene, o.dim, what, o.speed, t, mean_power);
    snprintf(path, sizeof path, "%s/charge.png", o.out);
    if (draw_charge(path, w, &shape, title, "mill"))
        return EXIT_FAILURE;
    snprintf(path, sizeof path, "%s/power.png", o.out);
    const power_trace trace = {rows.a, rows.b, turns.b, rows.n, settle, mean_power,
                               isnan(t_rev_start) ? 0 : t_rev_start, isnan(t_rev_end) ? t : t_rev_end};
    if (draw_power(path, &trace, "mill"))
        return EXIT_FAILURE;
    ore_result ground;
    if (o.ore) {
        if (ore_grind(w, drum, &ore, o.grind_minutes, mean_power, &ground))
            return EXIT_FAILURE;
        snprintf(path, sizeof path, "%s/product.csv", o.out);
        if (ore_write_csv(path, &ground))
            return EXIT_FAILURE;
        snprintf(title, sizeof title,
                 "libdemill %s mill: %.4g kg of ore ground %.4g min at %.2f W, %.3g kWh/t",
                 o.scene, ore.mass, o.grind_minutes, mean_power, ground.kwh_t);
        snprintf(path, sizeof path, "%s/product.png", o.out);
        if (draw_product(path, &ground, title))
            return EXIT_FAILURE;
    }
    FILE *sum = output_open(o.out, "summary.txt");
    const double wall = now() - t_wall0;
    fprintf(sum, "scene = %s\ndim = %d\nparticles = %zu\nmass_kg = %.6g\ndiameter_m = %g\n"
                 "length_m = %g\nlifters = %d\nspeed_fraction_critical = %.6g\n"
                 "speed_rad_s = %.6g\ncritical_speed_rad_s = %.6g\nrevolutions = %.0f\n"
                 "mean_power_W = %.6g\nmean_power_cm_W = %.6g\nmean_dissipation_W = %.6g\n"
                 "toe_deg = %.2f\nshoulder_deg = %.2f\ncom_deg = %.2f\n"
                 "contacts_per_particle = %.4f\nsteps = %llu\ntime_step_s = %g\n"
                 "simulated_s = %.6g\nwall_s = %.2f\nparticle_steps_per_s = %.4g\n",
            o.scene, o.dim, n, mass, o.diameter, o.length, o.lifters, o.speed / 100, omega, omega_c,
            drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS), mean_power,
            drum_value(w, drum, DEMILL_DRUM_POWER_CM_MEAN),
            drum_value(w, drum, DEMILL_DRUM_DISSIPATION_MEAN),
            drum_value(w, drum, DEMILL_DRUM_TOE_ANGLE_MEAN) * 180 / PI,
            drum_value(w, drum, DEMILL_DRUM_SHOULDER_ANGLE_MEAN) * 180 / PI,
            drum_value(w, drum, DEMILL_DRUM_COM_ANGLE_MEAN) * 180 / PI,
            contact_samples ? contacts_sum / contact_samples : NAN, (unsigned long long)steps,
            o.dt, t, wall, steps * (double)(n + n_ore) / (t_step1 - t_step0));
    if (clumps)
        fprintf(sum, "shape = %s\nclumps = %zu\nspheres_per_clump = %zu\n", o.shape, clumps,
                spheres.n);
    if (o.ore)
        fprintf(sum, "ore_particles = %zu\nore_mass_kg = %.6g\ngrind_minutes = %.6g\n"
                     "F80_m = %.6g\nP80_m = %.6g\nspecific_energy_kWh_t = %.6g\n"
                     "bond_work_index_kWh_t = %.6g\nbond_specific_energy_kWh_t = %.6g\n",
                n_ore, ore.mass, o.grind_minutes, ground.f80, ground.p80, ground.kwh_t, ore.bond_wi,
                ground.bond_kwh_t);
    output_close(sum, "summary.txt");
    printf("mill: done in %.1f s. Mean power over the last revolution %.2f W (from the centre of "
           "mass %.2f W);\n      toe %.1f°, shoulder %.1f°; results in %s/\n",
           wall, mean_power, drum_value(w, drum, DEMILL_DRUM_POWER_CM_MEAN),
           drum_value(w, drum, DEMILL_DRUM_TOE_ANGLE_MEAN) * 180 / PI,
           drum_value(w, drum, DEMILL_DRUM_SHOULDER_ANGLE_MEAN) * 180 / PI, o.out);
    series_free(&rows);
    series_free(&turns);
    demill_world_destroy(w);
    return EXIT_SUCCESS;
}
