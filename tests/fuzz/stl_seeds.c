/* stl_seeds.c: writes the starting inputs of the STL fuzzer (stl.c) into a
 * directory: the unit cube as ASCII and as binary (its header starting
 * "solid"), as bare triangle records, under each placement, and the bad
 * cases the reader must refuse: a NaN, an infinite, a collinear and a
 * repeated corner, a misspelt keyword, a file cut inside a facet and a
 * binary file cut short. The first byte of each is the mode (see stl.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stl_write.h"

static const char *dir;

static void write_seed(const char *name, uint8_t mode, const uint8_t *b, size_t n)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/seed-%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(&mode, 1, 1, f) != 1 || fwrite(b, 1, n, f) != n || fclose(f))
        exit((perror(path), 1));
}

/* The cube with triangle 2's corners replaced by corners. */
static void bad_cube(const char *name, const double corners[9])
{
    double c[12 * 9];
    memcpy(c, dm_test_cube, sizeof c);
    memcpy(c + 9, corners, sizeof(double) * 9);
    size_t n;
    uint8_t *b = dm_test_stl_ascii("bad", c, 12, NULL, &n);
    char full[64];
    snprintf(full, sizeof full, "ascii-%s", name);
    write_seed(full, 0, b, n);
    free(b);
    b = dm_test_stl_binary("", c, 12, NULL, &n);
    snprintf(full, sizeof full, "records-%s", name);
    write_seed(full, 1, b + 84, n - 84);
    free(b);
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return fprintf(stderr, "usage: %s DIR\n", argv[0]), 2;
    dir = argv[1];
    size_t na, nb;
    uint8_t *a = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &na);
    uint8_t *b = dm_test_stl_binary("solid cube", dm_test_cube, 12, NULL, &nb);
    static const char *place[4] = {"", "-rotated", "-mirrored", "-overflow"};
    for (uint8_t p = 0; p < 4; p++) {
        char name[64];
        snprintf(name, sizeof name, "ascii-cube%s", place[p]);
        write_seed(name, (uint8_t)(2 * p), a, na);
        snprintf(name, sizeof name, "binary-cube%s", place[p]);
        write_seed(name, (uint8_t)(2 * p), b, nb);
        snprintf(name, sizeof name, "records-cube%s", place[p]);
        write_seed(name, (uint8_t)(2 * p + 1), b + 84, nb - 84);
    }
    write_seed("binary-truncated", 0, b, nb - 7);
    char *cut = strstr((char *)a, "outer loop\n      vertex 0 0 1");
    write_seed("ascii-cut", 0, a, (size_t)(cut - (char *)a) + 18);
    char *typo = malloc(na);
    memcpy(typo, a, na);
    memcpy(strstr(typo, "endloop"), "endlop ", 7);
    write_seed("ascii-typo", 0, (uint8_t *)typo, na);
    free(typo);
    const char *empty = "solid empty\nendsolid empty\n";
    write_seed("ascii-empty", 0, (const uint8_t *)empty, strlen(empty));
    const double nan_corner[9] = {0, 0, 0, 1, 1, 0, 1, 0, NAN};
    const double inf_corner[9] = {0, 0, 0, 1, 1, 0, 1, 0, INFINITY};
    const double in_line[9] = {0, 0, 0, 0.5, 0.5, 0, 1, 1, 0};
    const double repeated[9] = {0, 0, 0, 1, 1, 0, 0, 0, 0};
    bad_cube("nan", nan_corner);
    bad_cube("inf", inf_corner);
    bad_cube("line", in_line);
    bad_cube("repeated", repeated);
    free(a);
    free(b);
    return 0;
}
