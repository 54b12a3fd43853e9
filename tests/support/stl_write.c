/* stl_write.c: STL files written by the tests and the fuzzer's seeds
 * (stl_write.h). */
#include "stl_write.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* clang-format off */
const double dm_test_cube[12 * 9] = {
    0, 0, 0,  0, 1, 0,  1, 1, 0,    0, 0, 0,  1, 1, 0,  1, 0, 0,  /* z = 0, normal -z */
    0, 0, 1,  1, 0, 1,  1, 1, 1,    0, 0, 1,  1, 1, 1,  0, 1, 1,  /* z = 1, +z */
    0, 0, 0,  1, 0, 0,  1, 0, 1,    0, 0, 0,  1, 0, 1,  0, 0, 1,  /* y = 0, -y */
    0, 1, 0,  0, 1, 1,  1, 1, 1,    0, 1, 0,  1, 1, 1,  1, 1, 0,  /* y = 1, +y */
    0, 0, 0,  0, 0, 1,  0, 1, 1,    0, 0, 0,  0, 1, 1,  0, 1, 0,  /* x = 0, -x */
    1, 0, 0,  1, 1, 0,  1, 1, 1,    1, 0, 0,  1, 1, 1,  1, 0, 1,  /* x = 1, +x */
};
/* clang-format on */

/* The unit right-hand normal of triangle t (0 when it has no area). */
static void normal(const double *t, int flip, double n[3])
{
    const double e[2][3] = {{t[3] - t[0], t[4] - t[1], t[5] - t[2]},
                            {t[6] - t[0], t[7] - t[1], t[8] - t[2]}};
    n[0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
    n[1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
    n[2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++)
        n[i] = len > 0 ? (flip ? -n[i] : n[i]) / len : 0;
}

uint8_t *dm_test_stl_ascii(const char *name, const double *c, size_t nt, const int *flip,
                           size_t *size)
{
    const size_t cap = 64 + 2 * strlen(name) + nt * 512;
    char *b = malloc(cap);
    if (!b)
        exit(1);
    size_t n = (size_t)snprintf(b, cap, "solid %s\n", name);
    for (size_t k = 0; k < nt; k++) {
        const double *t = c + 9 * k;
        double nrm[3];
        normal(t, flip && flip[k], nrm);
        n += (size_t)snprintf(b + n, cap - n, "  facet normal %.17g %.17g %.17g\n    outer loop\n",
                              nrm[0], nrm[1], nrm[2]);
        for (int j = 0; j < 3; j++)
            n += (size_t)snprintf(b + n, cap - n, "      vertex %.17g %.17g %.17g\n", t[3 * j],
                                  t[3 * j + 1], t[3 * j + 2]);
        n += (size_t)snprintf(b + n, cap - n, "    endloop\n  endfacet\n");
    }
    n += (size_t)snprintf(b + n, cap - n, "endsolid %s\n", name);
    *size = n;
    return (uint8_t *)b;
}

static void put_f32(uint8_t *b, double v)
{
    const float f = (float)v;
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    for (int k = 0; k < 4; k++)
        b[k] = (uint8_t)(u >> 8 * k);
}

uint8_t *dm_test_stl_binary(const char *header, const double *c, size_t nt, const int *flip,
                            size_t *size)
{
    *size = 84 + 50 * nt;
    uint8_t *b = calloc(1, *size);
    if (!b)
        exit(1);
    memcpy(b, header, strlen(header) < 80 ? strlen(header) : 80);
    for (int k = 0; k < 4; k++)
        b[80 + k] = (uint8_t)(nt >> 8 * k);
    for (size_t k = 0; k < nt; k++) {
        uint8_t *rec = b + 84 + 50 * k;
        double nrm[3];
        normal(c + 9 * k, flip && flip[k], nrm);
        for (int j = 0; j < 3; j++)
            put_f32(rec + 4 * j, nrm[j]);
        for (int j = 0; j < 9; j++)
            put_f32(rec + 12 + 4 * j, c[9 * k + j]);
    }
    return b;
}
