/* meshes.c: closed triangle meshes the tests build, and temporary files
 * (meshes.h). */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */

#include "meshes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void dm_test_mesh_free(dm_test_mesh *m)
{
    free(m->v);
    free(m->t);
    memset(m, 0, sizeof *m);
}

/* realloc, or exit. */
static void *grow(void *p, size_t bytes)
{
    void *q = realloc(p, bytes);
    if (!q) {
        fprintf(stderr, "meshes: out of memory\n");
        exit(1);
    }
    return q;
}

uint32_t dm_test_mesh_vertex(dm_test_mesh *m, const double x[3])
{
    for (size_t k = 0; k < m->nv; k++)
        if (!memcmp(m->v + 3 * k, x, 3 * sizeof *x))
            return (uint32_t)k;
    m->v = grow(m->v, 3 * (m->nv + 1) * sizeof *m->v);
    memcpy(m->v + 3 * m->nv, x, 3 * sizeof *x);
    return (uint32_t)m->nv++;
}

void dm_test_mesh_triangle(dm_test_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    m->t = grow(m->t, 3 * (m->nt + 1) * sizeof *m->t);
    m->t[3 * m->nt] = a, m->t[3 * m->nt + 1] = b, m->t[3 * m->nt + 2] = c;
    m->nt++;
}

/* x pushed out to the unit sphere. */
static void unit(double x[3])
{
    const double l = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (int k = 0; k < 3; k++)
        x[k] /= l;
}

/* The triangle (a, b, c) of the unit sphere split `level` more times. */
static void split(dm_test_mesh *m, const double *a, const double *b, const double *c, int level)
{
    if (!level) { /* the corners numbered in their order */
        const uint32_t ia = dm_test_mesh_vertex(m, a), ib = dm_test_mesh_vertex(m, b),
                       ic = dm_test_mesh_vertex(m, c);
        dm_test_mesh_triangle(m, ia, ib, ic);
        return;
    }
    double ab[3], bc[3], ca[3];
    for (int k = 0; k < 3; k++) /* the same sums, bitwise, from both triangles of an edge */
        ab[k] = a[k] + b[k], bc[k] = b[k] + c[k], ca[k] = c[k] + a[k];
    unit(ab), unit(bc), unit(ca);
    split(m, a, ab, ca, level - 1);
    split(m, ab, b, bc, level - 1);
    split(m, ca, bc, c, level - 1);
    split(m, ab, bc, ca, level - 1);
}

dm_test_mesh dm_test_icosphere(int level, const double s[3], const double p[3])
{
    const double g = (1.0 + sqrt(5.0)) / 2.0;
    double c[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    static const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int k = 0; k < 12; k++)
        unit(c[k]);
    dm_test_mesh m = {0};
    for (int k = 0; k < 20; k++)
        split(&m, c[f[k][0]], c[f[k][1]], c[f[k][2]], level);
    for (size_t k = 0; k < m.nv; k++)
        for (int a = 0; a < 3; a++)
            m.v[3 * k + a] = p[a] + s[a] * m.v[3 * k + a];
    return m;
}

double *dm_test_mesh_corners(const dm_test_mesh *m)
{
    double *c = grow(NULL, 9 * m->nt * sizeof *c);
    for (size_t t = 0; t < m->nt; t++)
        for (int j = 0; j < 3; j++)
            memcpy(c + 9 * t + 3 * j, m->v + 3 * (size_t)m->t[3 * t + j], 3 * sizeof *c);
    return c;
}

char *dm_test_temp_file(const char *name, const void *bytes, size_t size)
{
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char *path = grow(NULL, strlen(dir) + strlen(name) + 32);
    sprintf(path, "%s/demill-%s-XXXXXX", dir, name);
    const int fd = mkstemp(path);
    FILE *f = fd < 0 ? NULL : fdopen(fd, "wb");
    if (!f || fwrite(bytes, 1, size, f) != size || fclose(f)) {
        fprintf(stderr, "meshes: cannot write %s\n", path);
        exit(1);
    }
    return path;
}

double dm_test_dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

double dm_test_mesh_plane(const dm_test_mesh *m, size_t t, double n[3])
{
    const double *a = m->v + 3 * m->t[3 * t], *b = m->v + 3 * m->t[3 * t + 1],
                 *c = m->v + 3 * m->t[3 * t + 2];
    const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = e[1] * f[2] - e[2] * f[1], n[1] = e[2] * f[0] - e[0] * f[2];
    n[2] = e[0] * f[1] - e[1] * f[0];
    const double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++)
        n[k] /= l;
    return n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
}

double *dm_test_mesh_planes(const dm_test_mesh *m)
{
    double *p = grow(NULL, 4 * m->nt * sizeof *p);
    for (size_t t = 0; t < m->nt; t++)
        p[4 * t + 3] = dm_test_mesh_plane(m, t, p + 4 * t);
    return p;
}

double dm_test_convex_depth(const double *planes, size_t nt, const double x[3])
{
    double d = INFINITY;
    for (size_t t = 0; t < nt; t++) {
        const double *p = planes + 4 * t;
        d = fmin(d, p[3] - (p[0] * x[0] + p[1] * x[1] + p[2] * x[2]));
    }
    return d;
}

double dm_test_mesh_volume(const dm_test_mesh *m, const double p[3])
{
    double v = 0.0;
    for (size_t t = 0; t < m->nt; t++) {
        double x[3][3];
        for (int j = 0; j < 3; j++)
            for (int a = 0; a < 3; a++)
                x[j][a] = m->v[3 * m->t[3 * t + j] + a] - p[a];
        v += x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) -
             x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
             x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
    }
    return v / 6.0;
}
