/* shape.c: the clump template of mill --shape, read from a text file of
 * spheres: one sphere a line, "x y z r" in metres (the centre and the
 * radius, in any frame: the library finds the centre of mass and the
 * principal axes), '#' starting a comment; in 2D every z must be 0. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mill.h"

int shape_read(const char *path, shape_def *s)
{
    s->n = 0;
    FILE *f = fopen(path, "r");
    if (!f) {
        perror(path);
        return -1;
    }
    char line[1024];
    int lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        double v[4];
        int used = 0;
        char extra;
        const int got = sscanf(line, " %lf %lf %lf %lf %n", &v[0], &v[1], &v[2], &v[3], &used);
        if (got == EOF || (got == 0 && sscanf(line, " %c", &extra) != 1))
            continue; /* blank or comment */
        if (got != 4 || line[used] != '\0') {
            fprintf(stderr, "%s:%d: expected \"x y z r\" (four numbers, m)\n", path, lineno);
            fclose(f);
            return -1;
        }
        if (s->n == SHAPE_MAX_SPHERES) {
            fprintf(stderr, "%s:%d: more than %d spheres\n", path, lineno, SHAPE_MAX_SPHERES);
            fclose(f);
            return -1;
        }
        memcpy(s->centres + 3 * s->n, v, 3 * sizeof *v);
        s->radii[s->n++] = v[3];
    }
    fclose(f);
    if (!s->n) {
        fprintf(stderr, "%s: no sphere\n", path);
        return -1;
    }
    return 0;
}
