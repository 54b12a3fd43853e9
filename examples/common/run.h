/* run.h: what the example programs share besides pictures (plot.h): their
 * messages' prefix, numbers from the command line, a check of every library
 * call, the wall clock, the progress bar and a growing time series. */
#ifndef RUN_H
#define RUN_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <demill.h>

/* The program's name, which starts its messages, and the world whose last
 * error check() reports; main sets both. */
extern const char *example_program;

/* Makes the folder path unless it exists: 0, or -1 with a message
 * "PROGRAM: cannot make PATH: ..." on stderr. */
int example_make_dir(const char *path);
extern demill_world *example_world;

/* The value of option argv[*k], which *k then indexes: for --help or -h,
 * prints the usage to stdout and exits; NULL, with a message, when the value
 * is missing. */
const char *option_value(int argc, char **argv, int *k, void (*usage)(FILE *));

/* Reads the number of option `opt` from `text` into *out: 0, or -1 with a
 * message when it is not a number in [lo, hi]. */
int parse_number(const char *opt, const char *text, double lo, double hi, double *out);

/* Exits the program with a message naming the call (`what`) and the world's
 * last error unless s is DEMILL_OK. */
void check(demill_status s, const char *what);

/* Opens the file `name` in the folder `dir` for writing; exits the program
 * with a message when it cannot. */
FILE *output_open(const char *dir, const char *name);

/* Closes a file output_open() opened; exits the program with a message
 * naming it when it could not be written. */
void output_close(FILE *f, const char *name);

/* The monotonic wall clock, s. */
double now(void);

/* The progress bar of a run, drawn by the library's progress callback
 * (demill_world_set_progress(), with progress_show() and the bar as its
 * user pointer): on a terminal a line that updates itself 4 times a second,
 * otherwise a line every 10 s, with the revolutions of the drum if there is
 * one (drum not DEMILL_ID_NONE) and none shown otherwise. The
 * caller sets the fields; progress_show() keeps rate and last. */
typedef struct progress_bar {
    demill_world *w;
    demill_id drum;
    uint64_t done, total; /* steps of the whole run: before this call, all */
    size_t particles;
    double rate;          /* steps per second, smoothed */
    double last, every;   /* wall time of the last line, s; and between lines */
    int tty, turning;
} progress_bar;

/* The callback: draws the bar `user` (a progress_bar) if it is time to;
 * returns 0 (never stops the run). */
int32_t progress_show(void *user, uint64_t steps_done, uint64_t steps_total, double time,
                      double steps_per_second);

/* A time series of two columns that grows as rows are added. */
typedef struct series {
    size_t n, cap;
    double *a, *b;
} series;

/* Appends a row (a, b); exits the program with a message when out of
 * memory. */
void series_add(series *s, double a, double b);

/* Frees the series' columns. */
void series_free(series *s);

#endif
