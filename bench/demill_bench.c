/* demill_bench.c: libdemill's side of the benchmark (bench/run). Builds a
 * canonical drum of docs/scenes.md (or the same drum scaled to another particle
 * count, the drum grown to keep the fill), settles it for 0.3 s, turns it at
 * 75 % of critical for 0.3 s, then times a window of steps on the moving
 * charge and prints one line:
 *
 *   bench scene=drum3d code=libdemill threads=1 particles=10000 steps=10000
 *   particle_steps_per_s=1.23e7 peak_rss_mb=42.0
 *
 * --scene drum3d-clumps is drum3d's drum with its 10,000 spheres as 5,000
 * dumbbells: clumps of two spheres of the scene's 3 mm radius whose centres
 * are 3 mm apart, filled into the drum by demill_clump_fill_region() (seed
 * 1; the lattice of the spheres does not hold them), the rate counted per
 * member sphere (particles = members).
 *
 * Energy tracking is off, as the peers do not tally energy, and so is
 * orientation tracking, as the peers do not turn the orientations of
 * spheres (--set world.orientation_tracking=1 turns it on). --dump-packing
 * writes the initial positions (x y z r per line) for the peers' inputs.
 * --set NAME=VALUE changes a parameter of the registry (demill_param_name())
 * of the world, the steel material or the steel-steel pair, to measure what
 * another contact law costs (e.g. --set pair.normal=3).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "../examples/mill/mill.h"

/* Under valgrind --tool=callgrind --instr-atstart=no, only the timed window
 * is instrumented, so that its instructions are counted without paying
 * callgrind's slowdown over the run-up. */
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* The process's peak resident set in KB: VmHWM, which starts afresh at exec
 * (getrusage's ru_maxrss does not on Linux: it would report the peak of the
 * process that forked us, e.g. bench/run's Python, if that was larger). */
static double peak_rss_kb(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    double kb = -1;
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "VmHWM:", 6))
            kb = atof(line + 6);
    if (f)
        fclose(f);
    if (kb < 0) {
        struct rusage ru;
        getrusage(RUSAGE_SELF, &ru);
        kb = (double)ru.ru_maxrss;
    }
    return kb;
}

static void usage(FILE *f)
{
    fputs("usage: demill_bench [options]\n"
          "  --scene drum3d|drum2d   the canonical scene [drum3d]; drum3d-clumps: drum3d with\n"
          "                          its spheres as half as many dumbbells (two 3 mm spheres\n"
          "                          3 mm apart), filled at random orientations\n"
          "  --particles N           scale the drum to N particles [the scene's]\n"
          "  --threads N             threads [1]\n"
          "  --steps N               timed steps [10000]\n"
          "  --settle S --rotate S   seconds before the timed window [0.3 0.3]\n"
          "  --fill                  drum3d: the spheres placed by demill_drum_fill() (seed 1),\n"
          "                          packed at rest at the bottom as drum3d-clumps' dumbbells\n"
          "                          are, instead of the scene's lattice\n"
          "  --energy                keep the energy tally on\n"
          "  --no-watchdog           switch the stability watchdog off\n"
          "  --mesh FILE.stl         the drum's shell, caps and lifters from this STL file\n"
          "                          (m), turning with the drum in place of its analytic\n"
          "                          walls (drum3d-mesh: bench/peers/peers.py stl drum3d)\n"
          "  --dump-packing FILE     write the initial packing (x y z r) and exit\n"
          "  --set NAME=VALUE        set a world.*, material.* (the steel's) or pair.*\n"
          "                          (steel-steel) parameter after the scene's (repeatable)\n",
          f);
}

static void fail(demill_world *w, demill_status s, const char *what)
{
    if (s != DEMILL_OK) {
        fprintf(stderr, "demill_bench: %s: %s (%s)\n", what, demill_strerror(s),
                demill_world_last_error(w));
        exit(EXIT_FAILURE);
    }
}

/* The key of a parameter named in the registry, or -1. */
static int32_t param_key(const char *name, size_t len)
{
    for (int32_t key = 0; key < 1000; key++) {
        const char *n = demill_param_name(key);
        if (n && strlen(n) == len && !strncmp(n, name, len))
            return key;
    }
    return -1;
}

/* Applies one --set NAME=VALUE to the world, the steel or its pair. */
static void set_param(demill_world *w, demill_id steel, const char *arg)
{
    const char *eq = strchr(arg, '=');
    const int32_t key = eq ? param_key(arg, (size_t)(eq - arg)) : -1;
    if (key < 0) {
        fprintf(stderr, "demill_bench: --set %s: not NAME=VALUE with a parameter's name\n", arg);
        exit(EXIT_FAILURE);
    }
    const double v = atof(eq + 1);
    demill_status s;
    if (!strncmp(arg, "world.", 6))
        s = demill_world_set(w, key, v);
    else if (!strncmp(arg, "material.", 9))
        s = demill_material_set(w, steel, key, v);
    else
        s = demill_pair_set(w, steel, steel, key, v);
    fail(w, s, arg);
}

int main(int argc, char **argv)
{
    const char *scene = "drum3d", *dump = NULL, *mesh = NULL;
    long particles = 0, threads = 1, steps = 10000;
    double settle = 0.3, rotate = 0.3;
    int energy = 0, watchdog = 1, nsets = 0, filled = 0;
    const char *sets[64];
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = k + 1 < argc ? argv[k + 1] : NULL;
        if (!strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_SUCCESS;
        } else if (!strcmp(a, "--energy")) {
            energy = 1;
        } else if (!strcmp(a, "--fill")) {
            filled = 1;
        } else if (!strcmp(a, "--no-watchdog")) {
            watchdog = 0;
        } else if (!v) {
            fprintf(stderr, "demill_bench: %s needs a value\n", a);
            return EXIT_FAILURE;
        } else if (!strcmp(a, "--set") && nsets < 64) {
            sets[nsets++] = argv[++k];
        } else if (!strcmp(a, "--scene")) {
            scene = argv[++k];
        } else if (!strcmp(a, "--mesh")) {
            mesh = argv[++k];
        } else if (!strcmp(a, "--dump-packing")) {
            dump = argv[++k];
        } else if (!strcmp(a, "--particles")) {
            particles = atol(argv[++k]);
        } else if (!strcmp(a, "--threads")) {
            threads = atol(argv[++k]);
        } else if (!strcmp(a, "--steps")) {
            steps = atol(argv[++k]);
        } else if (!strcmp(a, "--settle")) {
            settle = atof(argv[++k]);
        } else if (!strcmp(a, "--rotate")) {
            rotate = atof(argv[++k]);
        } else {
            usage(stderr);
            return EXIT_FAILURE;
        }
    }
    const int clumps = !strcmp(scene, "drum3d-clumps");
    const int is3d = clumps || !strcmp(scene, "drum3d");
    if ((mesh || dump) && clumps) {
        fprintf(stderr, "demill_bench: drum3d-clumps takes no --mesh or --dump-packing\n");
        return EXIT_FAILURE;
    }
    if (filled && (!is3d || clumps || mesh || dump)) {
        fprintf(stderr, "demill_bench: --fill is for drum3d (drum3d-clumps is always filled)\n");
        return EXIT_FAILURE;
    }
    if (clumps && particles % 2) {
        fprintf(stderr, "demill_bench: drum3d-clumps needs an even --particles\n");
        return EXIT_FAILURE;
    }
    if (mesh && !is3d) {
        fprintf(stderr, "demill_bench: --mesh needs --scene drum3d\n");
        return EXIT_FAILURE;
    }
    if (!is3d && strcmp(scene, "drum2d")) {
        fprintf(stderr, "demill_bench: unknown scene %s\n", scene);
        return EXIT_FAILURE;
    }
    const long n0 = is3d ? 10000 : 8000;
    if (particles <= 0)
        particles = n0;
    if (threads < 1 || steps < 1) {
        fprintf(stderr, "demill_bench: --threads and --steps must be positive\n");
        return EXIT_FAILURE;
    }
    /* the scene, or the same drum grown by s in every length to hold
     * `particles` at the same fill */
    const double s = is3d ? cbrt((double)particles / n0) : sqrt((double)particles / n0);
    const double a = 0.0063;
    drum_geometry geo = {is3d ? 3 : 2, 1e-5, (is3d ? 0.3 : 1.0) * s, 0.1 * s, 8,
                         (is3d ? 0.015 : 0.03) * s};
    scene_def sd = {is3d ? 3 : 2, (size_t)particles, (is3d ? 0.131 : 0.466) * s, 15, -0.046};
    if (particles != n0) { /* layers centred in the grown length */
        sd.layers = (long)floor((geo.length - 0.008) / a) + 1;
        sd.z0 = -0.5 * a * (sd.layers - 1);
    }
    double *pos = malloc(3 * (size_t)particles * sizeof *pos);
    double *rad = malloc((size_t)particles * sizeof *rad);
    if (!pos || !rad || scene_packing(&sd, pos)) {
        fprintf(stderr, "demill_bench: cannot pack %ld particles\n", particles);
        return EXIT_FAILURE;
    }
    for (long k = 0; k < particles; k++)
        rad[k] = 0.003;
    if (dump) {
        FILE *f = fopen(dump, "w");
        if (!f) {
            perror(dump);
            return EXIT_FAILURE;
        }
        for (long k = 0; k < particles; k++)
            fprintf(f, "%.17g %.17g %.17g %.17g\n", pos[3 * k], pos[3 * k + 1], pos[3 * k + 2],
                    rad[k]);
        return fclose(f) ? EXIT_FAILURE : EXIT_SUCCESS;
    }
    demill_world *w;
    demill_id steel, drum;
    if (scene_world(&geo, &w, &steel, &drum))
        return EXIT_FAILURE;
    if (mesh) { /* the drum's surfaces from the mesh alone */
        demill_id wall;
        fail(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 0), "lifters");
        fail(w, demill_drum_set(w, drum, DEMILL_DRUM_SHELL, 0), "shell");
        fail(w, demill_wall_load_stl(w, steel, mesh, 1.0, NULL, &wall), "mesh");
        fail(w, demill_drum_attach_wall(w, drum, wall, DEMILL_DRUM_PART_SHELL), "mesh");
    }
    fail(w, demill_world_set(w, DEMILL_WORLD_ORIENTATION_TRACKING, 0), "orientation tracking");
    for (int k = 0; k < nsets; k++)
        set_param(w, steel, sets[k]);
    fail(w, demill_world_set(w, DEMILL_WORLD_THREADS, (double)threads), "threads");
    fail(w, demill_world_set(w, DEMILL_WORLD_ENERGY_TRACKING, energy), "energy tracking");
    fail(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG, watchdog), "watchdog");
    if (clumps) {
        const double c[6] = {-0.0015, 0, 0, 0.0015, 0, 0}, r[2] = {0.003, 0.003};
        demill_id tmpl;
        fail(w, demill_clump_template_add(w, steel, 2, c, r, &tmpl), "dumbbell");
        fail(w, demill_clump_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, tmpl, DEMILL_FILL_COUNT,
                                         (double)(particles / 2), 1, NULL, 0, NULL),
             "charge");
    } else if (filled) {
        const double sizes[2] = {0.006, 1.0};
        fail(w, demill_drum_fill(w, drum, steel, DEMILL_SIZES_CLASSES, sizes, 2, DEMILL_FILL_COUNT,
                                 (double)particles, 1, NULL, 0, NULL),
             "charge");
    } else {
        fail(w, demill_particles_add(w, steel, (size_t)particles, pos, rad, NULL, 0, NULL),
             "charge");
    }
    free(pos);
    free(rad);
    fprintf(stderr, "demill_bench: %s, %ld particles, %ld threads: settling %g s, turning %g s, "
                    "then timing %ld steps\n",
            mesh ? "drum3d-mesh" : filled ? "drum3d-fill" : scene, particles, threads, settle, rotate,
            steps);
    fail(w, demill_world_step(w, (uint64_t)llround(settle / geo.time_step)), "settling");
    fail(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75), "speed");
    fail(w, demill_world_step(w, (uint64_t)llround(rotate / geo.time_step)), "turning");
    CALLGRIND_START_INSTRUMENTATION;
    const double t0 = now();
    fail(w, demill_world_step(w, (uint64_t)steps), "the timed window");
    const double t1 = now();
    CALLGRIND_STOP_INSTRUMENTATION;
    double contacts, wall_contacts, rebuilds;
    fail(w, demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &contacts), "contacts");
    fail(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &wall_contacts), "contacts");
    fail(w, demill_world_get(w, DEMILL_WORLD_NEIGHBOUR_REBUILDS, &rebuilds), "rebuilds");
    fprintf(stderr, "demill_bench: at the end, %.3f particle contacts and %.3f wall contacts per "
                    "particle; %.0f neighbour builds in all\n",
            contacts / particles, wall_contacts / particles, rebuilds);
    printf("bench scene=%s code=libdemill threads=%ld particles=%ld steps=%ld "
           "particle_steps_per_s=%.3g peak_rss_mb=%.1f\n",
           mesh ? "drum3d-mesh" : filled ? "drum3d-fill" : scene, threads, particles, steps,
           (double)particles * steps / (t1 - t0),
           peak_rss_kb() / 1024.0);
    demill_world_destroy(w);
    return EXIT_SUCCESS;
}
