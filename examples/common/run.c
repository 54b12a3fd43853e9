/* run.c: what the example programs share besides pictures (run.h). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "run.h"

const char *example_program = "example";
demill_world *example_world;

const char *option_value(int argc, char **argv, int *k, void (*usage)(FILE *))
{
    const char *a = argv[*k];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
        usage(stdout);
        exit(EXIT_SUCCESS);
    }
    if (*k + 1 >= argc) {
        fprintf(stderr, "%s: %s needs a value (see %s --help)\n", example_program, a,
                example_program);
        return NULL;
    }
    return argv[++*k];
}

int parse_number(const char *opt, const char *text, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    const double v = strtod(text, &end);
    if (errno || end == text || *end || !(v >= lo && v <= hi)) {
        fprintf(stderr, "%s: %s %s: expected a number in [%g, %g]\n", example_program, opt, text,
                lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

void check(demill_status s, const char *what)
{
    if (s != DEMILL_OK) {
        fprintf(stderr, "%s: %s failed: %s: %s\n", example_program, what, demill_strerror(s),
                demill_world_last_error(example_world));
        exit(EXIT_FAILURE);
    }
}

FILE *output_open(const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "%s: ", example_program);
        perror(path);
        exit(EXIT_FAILURE);
    }
    return f;
}

void output_close(FILE *f, const char *name)
{
    if (fclose(f)) {
        fprintf(stderr, "%s: error writing %s\n", example_program, name);
        exit(EXIT_FAILURE);
    }
}

double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

void series_add(series *s, double a, double b)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 1024;
        double *na = realloc(s->a, s->cap * sizeof *na), *nb = realloc(s->b, s->cap * sizeof *nb);
        if (!na || !nb) {
            fprintf(stderr, "%s: out of memory\n", example_program);
            exit(EXIT_FAILURE);
        }
        s->a = na;
        s->b = nb;
    }
    s->a[s->n] = a;
    s->b[s->n++] = b;
}

void series_free(series *s)
{
    free(s->a);
    free(s->b);
    *s = (series){0};
}

int32_t progress_show(void *user, uint64_t steps_done, uint64_t steps_total, double time,
                      double steps_per_second)
{
    progress_bar *p = user;
    (void)steps_total;
    p->rate = p->rate > 0 ? 0.9 * p->rate + 0.1 * steps_per_second : steps_per_second;
    const double t_wall = now();
    if (t_wall - p->last < p->every)
        return 0;
    p->last = t_wall;
    const uint64_t done = p->done + steps_done, left = done < p->total ? p->total - done : 0;
    const double frac = (double)(p->total - left) / p->total;
    const double eta = p->rate > 0 ? left / p->rate : 0;
    char bar[31];
    const int filled = (int)(frac * 30);
    for (int k = 0; k < 30; k++)
        bar[k] = k < filled ? '#' : '.';
    bar[30] = '\0';
    double angle = 0.0;
    char turns[40] = ""; /* a scene without a drum has no revolutions to show */
    if (p->turning)
        demill_drum_get(p->w, p->drum, DEMILL_DRUM_ANGLE, &angle);
    if (p->drum)
        snprintf(turns, sizeof turns, "  revolution %.2f", angle / (2 * 3.14159265358979323846));
    fprintf(stderr, "%s%s: [%s] %3.0f %%  t = %.3f s%s  %.2f M particle-steps/s  ETA %2d:%02d%s",
            p->tty ? "\r" : "", example_program, bar, 100 * frac, time, turns,
            p->rate * p->particles / 1e6, (int)(eta / 60), (int)fmod(eta, 60),
            p->tty ? "  " : "\n");
    return 0;
}

int example_make_dir(const char *path)
{
    if (mkdir(path, 0777) && errno != EEXIST) {
        fprintf(stderr, "%s: cannot make %s: %s\n", example_program, path, strerror(errno));
        return -1;
    }
    return 0;
}
