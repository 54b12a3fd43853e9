/* stl.c: the STL reader (lib/physics/io/stl.c) on files the test writes.
 *
 * The unit cube, written as ASCII and as binary STL (tests/support/
 * stl_write.c, from a table of its 12 triangles), must come back as its
 * 8 corners and 12 triangles, each triangle's right-hand normal pointing
 * away from the centre, and its volume by the divergence theorem,
 * V = (1/6) sum a . (b x c) over the triangles (a, b, c) of a closed
 * surface wound counter-clockwise from outside (Gauss; e.g. Zhang and Chen
 * 2001, Efficient feature extraction for 2D/3D objects in mesh
 * representation), must be 1 and its area 6. Under a scale s and a
 * transform x -> A x + t the volume must be det(A) s^3 (an affine map
 * scales every volume by its determinant), and under a mirror (det < 0)
 * the winding must be reversed so the volume stays positive. Welding must
 * join exactly equal points only. Every bad input must give its error
 * naming the triangle or line, with nothing left in the mesh.
 * Internal test: it links the static library and calls the reader.
 *
 * Through the API, demill_wall_add_stl() and demill_wall_load_stl() make a
 * mesh wall of the cube scaled to 0.1 m: 8 vertices and 12 triangles, and a
 * ball of radius 0.01 m pressed by 1e-4 m onto its floor (y = 0) from
 * inside, away from edges, feels k δ = 1e5 × 1e-4 = 10 N along +y, as on a
 * plane; a bad file is refused with its path and triangle named, and the
 * world keeps its walls. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/io/io.h"
#include "stl_write.h"
#include "testutil.h"

/* The volume by the divergence theorem and the area of a mesh. */
static void volume_area(const dm_stl_mesh *m, double *volume, double *area)
{
    *volume = *area = 0;
    for (uint32_t k = 0; k < m->nt; k++) {
        const double *a = m->v + 3 * m->tri[3 * k], *b = m->v + 3 * m->tri[3 * k + 1],
                     *c = m->v + 3 * m->tri[3 * k + 2];
        *volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        const double e[2][3] = {{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                                {c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
        const double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                             e[0][2] * e[1][0] - e[0][0] * e[1][2],
                             e[0][0] * e[1][1] - e[0][1] * e[1][0]};
        *area += sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
    }
}

/* Every triangle's right-hand normal points away from centre. */
static void check_outward(const dm_stl_mesh *m, const double centre[3])
{
    for (uint32_t k = 0; k < m->nt; k++) {
        const double *a = m->v + 3 * m->tri[3 * k], *b = m->v + 3 * m->tri[3 * k + 1],
                     *c = m->v + 3 * m->tri[3 * k + 2];
        const double e[2][3] = {{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                                {c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
        const double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                             e[0][2] * e[1][0] - e[0][0] * e[1][2],
                             e[0][0] * e[1][1] - e[0][1] * e[1][0]};
        double out = 0;
        for (int i = 0; i < 3; i++)
            out += n[i] * ((a[i] + b[i] + c[i]) / 3 - centre[i]);
        ck_assert_msg(out > 0, "triangle %u points inwards", k);
    }
}

/* The mesh is the unit cube mapped by x -> A (s x) + t: its 8 corners once
 * each, 12 triangles wound outwards, volume |det A| s^3. */
static void check_cube(const dm_stl_mesh *m, double s, const double xf[12])
{
    static const double id[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    const double *A = xf ? xf : id;
    ck_assert_uint_eq(m->nv, 8);
    ck_assert_uint_eq(m->nt, 12);
    int seen[8] = {0};
    for (int corner = 0; corner < 8; corner++) {
        const double x[3] = {s * (corner & 1), s * (corner >> 1 & 1), s * (corner >> 2 & 1)};
        double y[3];
        for (int i = 0; i < 3; i++)
            y[i] = A[3 * i] * x[0] + A[3 * i + 1] * x[1] + A[3 * i + 2] * x[2] + A[9 + i];
        int found = 0;
        for (uint32_t v = 0; v < m->nv; v++)
            if (m->v[3 * v] == y[0] && m->v[3 * v + 1] == y[1] && m->v[3 * v + 2] == y[2])
                found++, seen[v]++;
        ck_assert_msg(found == 1, "corner (%g, %g, %g) found %d times", y[0], y[1], y[2], found);
    }
    for (uint32_t k = 0; k < 3 * m->nt; k++)
        ck_assert_uint_lt(m->tri[k], m->nv);
    const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                       A[2] * (A[3] * A[7] - A[4] * A[6]);
    double volume, area;
    volume_area(m, &volume, &area);
    DM_ASSERT_REL(volume, fabs(det) * s * s * s, 1e-14);
    double centre[3];
    for (int i = 0; i < 3; i++)
        centre[i] = A[3 * i] * s / 2 + A[3 * i + 1] * s / 2 + A[3 * i + 2] * s / 2 + A[9 + i];
    check_outward(m, centre);
}

static demill_status parse(const void *b, size_t n, double s, const double *xf, dm_stl_mesh *m,
                           char *err)
{
    return dm_stl_parse(b, n, s, xf, m, err, 256);
}

START_TEST(test_ascii_cube)
{
    size_t n;
    uint8_t *b = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &n);
    dm_stl_mesh m;
    char err[256];
    ck_assert_int_eq(parse(b, n, 1, NULL, &m, err), DEMILL_OK);
    check_cube(&m, 1, NULL);
    double volume, area;
    volume_area(&m, &volume, &area);
    ck_assert_double_eq_tol(volume, 1, 1e-15);
    ck_assert_double_eq(area, 6);
    ck_assert_uint_eq(m.flipped, 0);
    /* vertices in the order of their first corner: the first triangle's */
    const double first[9] = {0, 0, 0, 0, 1, 0, 1, 1, 0};
    ck_assert_mem_eq(m.v, first, sizeof first);
    ck_assert_uint_eq(m.tri[0], 0);
    ck_assert_uint_eq(m.tri[1], 1);
    ck_assert_uint_eq(m.tri[2], 2);
    dm_stl_free(&m);
    ck_assert_ptr_null(m.v);
    free(b);
}
END_TEST

START_TEST(test_binary_cube)
{
    /* a binary header may start with "solid": the size tells it apart */
    const char *headers[2] = {"binary cube", "solid cube, written as binary"};
    for (int h = 0; h < 2; h++) {
        size_t n;
        uint8_t *b = dm_test_stl_binary(headers[h], dm_test_cube, 12, NULL, &n);
        ck_assert_uint_eq(n, 84 + 50 * 12);
        dm_stl_mesh m;
        char err[256];
        ck_assert_msg(parse(b, n, 1, NULL, &m, err) == DEMILL_OK, "%s", err);
        check_cube(&m, 1, NULL);
        ck_assert_uint_eq(m.flipped, 0);
        dm_stl_free(&m);
        free(b);
    }
}
END_TEST

/* Scale 0.5 and a shear-stretch of determinant 6 with a translation: the
 * volume 6 x 0.5^3 = 0.75. */
START_TEST(test_transform)
{
    const double xf[12] = {2, 1, 0, 0, 3, 0, 0, 0, 1, 1, 2, 3};
    for (int binary = 0; binary < 2; binary++) {
        size_t n;
        uint8_t *b = binary ? dm_test_stl_binary("", dm_test_cube, 12, NULL, &n)
                            : dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &n);
        dm_stl_mesh m;
        char err[256];
        ck_assert_int_eq(parse(b, n, 0.5, xf, &m, err), DEMILL_OK);
        check_cube(&m, 0.5, xf);
        double volume, area;
        volume_area(&m, &volume, &area);
        ck_assert_double_eq_tol(volume, 0.75, 1e-15);
        /* the file's (1, 1, 1): A (0.5, 0.5, 0.5) + t */
        int found = 0;
        for (uint32_t v = 0; v < m.nv; v++)
            found += m.v[3 * v] == 2.5 && m.v[3 * v + 1] == 3.5 && m.v[3 * v + 2] == 3.5;
        ck_assert_int_eq(found, 1);
        dm_stl_free(&m);
        free(b);
    }
}
END_TEST

/* Scale 2 and the reflection that swaps x and y (det -1): the corners
 * mirrored, the winding reversed so that it still points out (volume +8,
 * not -8). */
START_TEST(test_mirror)
{
    const double xf[12] = {0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0};
    size_t n;
    uint8_t *b = dm_test_stl_binary("", dm_test_cube, 12, NULL, &n);
    dm_stl_mesh m;
    char err[256];
    ck_assert_int_eq(parse(b, n, 2, xf, &m, err), DEMILL_OK);
    check_cube(&m, 2, xf);
    double volume, area;
    volume_area(&m, &volume, &area);
    ck_assert_double_eq_tol(volume, 8, 1e-14);
    ck_assert_uint_eq(m.flipped, 0);
    dm_stl_free(&m);
    free(b);
}
END_TEST

/* Points weld when exactly equal after the transform (-0 equals 0, and is
 * kept as 0: with a translation of -0, the file's -0 stays -0), not when
 * one unit in the last place apart. */
START_TEST(test_weld_exact)
{
    const double ulp = nextafter(1.0, 2.0);
    const double c[3][9] = {
        {-0.0, -0.0, -0.0, 1, 0, 0, 0, 1, 0},
        {1, 0, 0, 1, 1, 0, 0, 1, -0.0},
        {ulp, 0, 0, 1, 1, -0.0, -0.0, 1, 0},
    };
    size_t n;
    uint8_t *b = dm_test_stl_ascii("two", c[0], 3, NULL, &n);
    dm_stl_mesh m;
    char err[256];
    const double xf[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, -0.0, -0.0, -0.0};
    ck_assert_int_eq(parse(b, n, 1, xf, &m, err), DEMILL_OK);
    ck_assert_uint_eq(m.nt, 3);
    ck_assert_uint_eq(m.nv, 5); /* 0, x, y, x + y, and x one ulp further */
    const uint32_t tri[9] = {0, 1, 2, 1, 3, 2, 4, 3, 2};
    ck_assert_mem_eq(m.tri, tri, sizeof tri);
    ck_assert_double_eq(m.v[3 * 4], ulp);
    for (uint32_t k = 0; k < 3 * m.nv; k++)
        ck_assert_msg(!signbit(m.v[k]), "coordinate %u is -0", k);
    dm_stl_free(&m);
    free(b);
}
END_TEST

/* A facet whose normal in the file disagrees with its winding is counted,
 * not refused; the winding is kept. */
START_TEST(test_flipped_normal)
{
    int flip[12] = {0};
    flip[3] = flip[7] = 1;
    for (int binary = 0; binary < 2; binary++) {
        size_t n;
        uint8_t *b = binary ? dm_test_stl_binary("", dm_test_cube, 12, flip, &n)
                            : dm_test_stl_ascii("cube", dm_test_cube, 12, flip, &n);
        dm_stl_mesh m;
        char err[256];
        ck_assert_int_eq(parse(b, n, 1, NULL, &m, err), DEMILL_OK);
        check_cube(&m, 1, NULL);
        ck_assert_uint_eq(m.flipped, 2);
        dm_stl_free(&m);
        free(b);
    }
}
END_TEST

/* What exporters write: upper case keywords, CR LF, a byte-order mark,
 * blank lines first, two solids, no name, no final newline. */
START_TEST(test_ascii_variants)
{
    size_t n;
    uint8_t *b = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &n);
    char *s = malloc(4 * n + 64), *o = s;
    o += sprintf(o, "\xef\xbb\xbf\r\n\r\n");
    for (int copy = 0; copy < 2; copy++)
        for (size_t k = 0; k < n; k++) {
            if (b[k] == '\n')
                *o++ = '\r';
            *o++ = (char)(copy ? toupper(b[k]) : b[k]);
        }
    o -= 2; /* no final CR LF */
    dm_stl_mesh m;
    char err[256];
    ck_assert_msg(parse(s, (size_t)(o - s), 1, NULL, &m, err) == DEMILL_OK, "%s", err);
    ck_assert_uint_eq(m.nv, 8); /* the same cube twice */
    ck_assert_uint_eq(m.nt, 24);
    dm_stl_free(&m);
    const char *bare = "solid\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 "
                       "vertex 0 1 0 endloop endfacet endsolid";
    ck_assert_int_eq(parse(bare, strlen(bare), 1, NULL, &m, err), DEMILL_OK);
    ck_assert_uint_eq(m.nt, 1);
    ck_assert_uint_eq(m.flipped, 0);
    dm_stl_free(&m);
    free(s);
    free(b);
}
END_TEST

/* Parsing fails with code and a message that contains want; the mesh is
 * left empty. */
static void check_error(const void *b, size_t n, double s, const double *xf, demill_status code,
                        const char *want)
{
    dm_stl_mesh m;
    char err[256] = "";
    const demill_status st = parse(b, n, s, xf, &m, err);
    ck_assert_msg(st == code, "status %d, expected %d (%s)", (int)st, (int)code, err);
    ck_assert_msg(strstr(err, want), "message \"%s\" lacks \"%s\"", err, want);
    ck_assert_ptr_null(m.v);
    ck_assert_ptr_null(m.tri);
    ck_assert_uint_eq(m.nv, 0);
    ck_assert_uint_eq(m.nt, 0);
}

/* The cube in ASCII with line `line` (from 1) replaced by text. */
static char *ascii_cube_with(int line, const char *text, size_t *size)
{
    size_t n;
    uint8_t *b = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &n);
    char *s = malloc(n + strlen(text) + 2), *o = s;
    int l = 1;
    for (size_t k = 0; k < n; k++) {
        if (l == line) {
            o += sprintf(o, "%s\n", text);
            while (b[k] != '\n')
                k++;
            l++;
            continue;
        }
        l += b[k] == '\n';
        *o++ = (char)b[k];
    }
    free(b);
    *size = (size_t)(o - s);
    return s;
}

/* The cube in ASCII: facet k (from 0) on lines 2 + 7k ("facet normal") to
 * 8 + 7k ("endfacet"), its corners on lines 4 + 7k to 6 + 7k. */
START_TEST(test_ascii_errors)
{
    size_t n;
    char *s = ascii_cube_with(17, "    outer lop", &n);
    check_error(s, n, 1, NULL, DEMILL_ERR_FORMAT, "line 17: expected 'loop', found 'lop'");
    free(s);
    s = ascii_cube_with(19, "      vertex 1,5 0 0", &n);
    check_error(s, n, 1, NULL, DEMILL_ERR_FORMAT, "line 19: expected a number, found '1,5'");
    free(s);
    s = ascii_cube_with(20, "      vertex 1 1 0 vertex 1 1 1", &n);
    check_error(s, n, 1, NULL, DEMILL_ERR_FORMAT, "line 20: expected 'endloop', found 'vertex'");
    free(s);
    s = ascii_cube_with(19, "      vertex 1 nan 0", &n);
    check_error(s, n, 1, NULL, DEMILL_ERR_FORMAT, "line 19: triangle 3, corner 2: a NaN coordinate");
    free(s);
    s = ascii_cube_with(41, "      vertex 1 1 -1e999", &n);
    check_error(s, n, 1, NULL, DEMILL_ERR_FORMAT,
                "line 41: triangle 6, corner 3: an infinite coordinate");
    free(s);
    /* truncated inside the 6th facet, and before endsolid */
    uint8_t *b = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &n);
    size_t cut = 0;
    for (int line = 1; line < 41; cut++)
        line += b[cut] == '\n';
    check_error(b, cut, 1, NULL, DEMILL_ERR_FORMAT,
                "line 41: expected 'vertex', found the end of the file");
    check_error(b, n - strlen("endsolid cube\n"), 1, NULL, DEMILL_ERR_FORMAT,
                "line 86: expected 'facet' or 'endsolid', found the end of the file");
    const char *tail = "solid a\nendsolid a\nfacet";
    check_error(tail, strlen(tail), 1, NULL, DEMILL_ERR_FORMAT,
                "line 3: expected 'solid' or the end of the file, found 'facet'");
    const char *empty = "solid empty\nendsolid empty\n";
    check_error(empty, strlen(empty), 1, NULL, DEMILL_ERR_FORMAT, "ASCII STL without triangles");
    free(b);
}
END_TEST

START_TEST(test_binary_errors)
{
    size_t n;
    uint8_t *b = dm_test_stl_binary("solid cube", dm_test_cube, 12, NULL, &n);
    /* cut, or too long, even with a header starting "solid" */
    check_error(b, n - 10, 1, NULL, DEMILL_ERR_FORMAT,
                "truncated binary STL: 12 triangles need 684 bytes, the file has 674");
    uint8_t *longer = calloc(1, n + 5);
    memcpy(longer, b, n);
    check_error(longer, n + 5, 1, NULL, DEMILL_ERR_FORMAT,
                "corrupt binary STL: 12 triangles need 684 bytes, the file has 689");
    free(longer);
    /* NaN and infinite corners */
    const float nan = NAN, inf = -INFINITY;
    uint8_t *bad = malloc(n);
    memcpy(bad, b, n);
    memcpy(bad + 84 + 50 * 4 + 12 + 4, &nan, 4); /* triangle 5, corner 1, y */
    check_error(bad, n, 1, NULL, DEMILL_ERR_FORMAT,
                "triangle 5 (byte 284), corner 1: a NaN coordinate");
    memcpy(bad, b, n);
    memcpy(bad + 84 + 50 * 11 + 12 + 24 + 8, &inf, 4); /* triangle 12, corner 3, z */
    check_error(bad, n, 1, NULL, DEMILL_ERR_FORMAT,
                "triangle 12 (byte 634), corner 3: an infinite coordinate");
    /* no triangles, and more than the limit */
    memset(bad, 0, 84);
    check_error(bad, 84, 1, NULL, DEMILL_ERR_FORMAT, "binary STL without triangles");
    const uint32_t over = DM_STL_MAX_TRIANGLES + 1;
    for (int k = 0; k < 4; k++)
        bad[80 + k] = (uint8_t)(over >> 8 * k);
    check_error(bad, n, 1, NULL, DEMILL_ERR_FORMAT,
                "binary STL of 268435457 triangles: more than 268435456");
    free(bad);
    free(b);
}
END_TEST

START_TEST(test_not_stl)
{
    check_error("", 0, 1, NULL, DEMILL_ERR_FORMAT, "empty");
    const char *obj = "# a Wavefront OBJ file\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                      "v 0 0 1\nv 1 0 1\nf 4 5 6\n";
    char want[64];
    snprintf(want, sizeof want, "not an STL file (%zu bytes starting \"# a Wavefront OB\")",
             strlen(obj));
    check_error(obj, strlen(obj), 1, NULL, DEMILL_ERR_FORMAT, want);
    const uint8_t png[16] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H'};
    check_error(png, sizeof png, 1, NULL, DEMILL_ERR_FORMAT, "not an STL file (16 bytes");
    check_error("solid", 5, 1, NULL, DEMILL_ERR_FORMAT,
                "line 1: expected 'facet' or 'endsolid', found the end of the file");
}
END_TEST

/* Zero area after welding: two corners at one point, or corners in a line:
 * a height under 1e-12 of the longest edge (DM_STL_FLAT) is zero area, one
 * of 1e-10 is not. */
START_TEST(test_zero_area)
{
    const double same[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 2, 0, 0, 0, 0, 0}};
    size_t n;
    uint8_t *b = dm_test_stl_ascii("z", same[0], 2, NULL, &n);
    check_error(b, n, 1, NULL, DEMILL_ERR_FORMAT,
                "triangle 2 (line 9) has zero area: corners 1 and 3 are the same point (0, 0, 0)");
    free(b);
    double line[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 1, 1, 2, 2, 2}};
    b = dm_test_stl_binary("", line[0], 2, NULL, &n);
    check_error(b, n, 1, NULL, DEMILL_ERR_FORMAT,
                "triangle 2 (byte 134) has zero area: its corners are in a line");
    free(b);
    for (int k = 0; k < 2; k++) {
        const double h = k ? 1e-10 : 1e-13; /* height, the longest edge 1 */
        const double thin[9] = {0, 0, 0, 1, 0, 0, 0.5, h, 0};
        b = dm_test_stl_ascii("thin", thin, 1, NULL, &n);
        dm_stl_mesh m;
        char err[256];
        ck_assert_int_eq(parse(b, n, 1, NULL, &m, err), k ? DEMILL_OK : DEMILL_ERR_FORMAT);
        dm_stl_free(&m);
        free(b);
    }
}
END_TEST

START_TEST(test_bad_placement)
{
    size_t n;
    uint8_t *b = dm_test_stl_binary("", dm_test_cube, 12, NULL, &n);
    check_error(b, n, 0, NULL, DEMILL_ERR_INVALID_VALUE, "scale 0: must be finite and positive");
    check_error(b, n, -1, NULL, DEMILL_ERR_INVALID_VALUE, "scale -1");
    check_error(b, n, NAN, NULL, DEMILL_ERR_INVALID_VALUE, "scale nan");
    double xf[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, INFINITY};
    check_error(b, n, 1, xf, DEMILL_ERR_INVALID_VALUE, "transform element 11 is not finite");
    const double flat[12] = {1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0};
    check_error(b, n, 1, flat, DEMILL_ERR_INVALID_VALUE, "singular (determinant 0)");
    /* finite coordinates that overflow once scaled */
    xf[0] = xf[4] = xf[8] = 10;
    xf[11] = 0;
    check_error(b, n, 1e308, xf, DEMILL_ERR_FORMAT,
                "triangle 1 (byte 84), corner 2: not finite after the scale and transform");
    free(b);
}
END_TEST

/* The number of walls of w. */
static size_t wall_count(demill_world *w)
{
    size_t n = 0;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, NULL, 0, &n));
    return n;
}

START_TEST(test_wall_from_stl)
{
    demill_id mat, wall, again;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, 1e5));
    size_t n, nv, nt;
    uint8_t *bin = dm_test_stl_binary("cube", dm_test_cube, 12, NULL, &n);
    DM_OK(w, demill_wall_add_stl(w, mat, bin, n, 0.1, NULL, &wall));
    DM_OK(w, demill_wall_mesh_info(w, wall, &nv, &nt));
    ck_assert_uint_eq(nv, 8);
    ck_assert_uint_eq(nt, 12);
    const double x[3] = {0.05, 0.01 - 1e-4, 0.05}, r = 0.01;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, NULL));
    DM_OK(w, demill_world_step(w, 0));
    double f[3];
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_FORCE, f));
    ck_assert_msg(fabs(f[0]) < 1e-12 && fabs(f[1] + 10.0) < 1e-9 && fabs(f[2]) < 1e-12,
                  "force on the floor (%g, %g, %g), expected (0, -10, 0)", f[0], f[1], f[2]);

    char path[] = "/tmp/demill-stl-XXXXXX";
    const int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    FILE *file = fdopen(fd, "wb");
    size_t na;
    uint8_t *ascii = dm_test_stl_ascii("cube", dm_test_cube, 12, NULL, &na);
    ck_assert_uint_eq(fwrite(ascii, 1, na, file), na);
    fclose(file);
    const double shift[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1.0, 0, 0};
    DM_OK(w, demill_wall_load_stl(w, mat, path, 0.1, shift, &again));
    DM_OK(w, demill_wall_mesh_info(w, again, &nv, &nt));
    ck_assert_uint_eq(nv + nt, 20);
    ck_assert_uint_eq(wall_count(w), 2);

    /* refused, the world keeping its two walls */
    bin[84 + 50 * 3 + 12] = 0xff; /* triangle 4's first x: a NaN */
    bin[84 + 50 * 3 + 15] = 0x7f;
    bin[84 + 50 * 3 + 14] = 0xff;
    ck_assert_int_eq(demill_wall_add_stl(w, mat, bin, n, 0.1, NULL, &again), DEMILL_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "triangle 4"));
    ascii[0] = 'X';
    file = fopen(path, "wb");
    ck_assert_uint_eq(fwrite(ascii, 1, na, file), na);
    fclose(file);
    ck_assert_int_eq(demill_wall_load_stl(w, mat, path, 0.1, NULL, &again), DEMILL_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), path));
    remove(path);
    ck_assert_int_eq(demill_wall_load_stl(w, mat, path, 0.1, NULL, &again), DEMILL_ERR_IO);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), path));
    ck_assert_int_eq(demill_wall_add_stl(w, mat, ascii, na, -1.0, NULL, &again),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_wall_load_stl(w, mat, NULL, 0.1, NULL, &again),
                     DEMILL_ERR_NULL_POINTER);
    ck_assert_uint_eq(wall_count(w), 2);
    demill_world_destroy(w);

    demill_world *flat = dm_test_world(2, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    ck_assert_int_eq(demill_wall_add_stl(flat, mat, bin, n, 0.1, NULL, &again),
                     DEMILL_ERR_DIMENSION);
    demill_world_destroy(flat);
    free(bin);
    free(ascii);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("stl");
    TCase *tc = tcase_create("stl");
    tcase_add_test(tc, test_ascii_cube);
    tcase_add_test(tc, test_binary_cube);
    tcase_add_test(tc, test_transform);
    tcase_add_test(tc, test_mirror);
    tcase_add_test(tc, test_weld_exact);
    tcase_add_test(tc, test_flipped_normal);
    tcase_add_test(tc, test_ascii_variants);
    tcase_add_test(tc, test_ascii_errors);
    tcase_add_test(tc, test_binary_errors);
    tcase_add_test(tc, test_not_stl);
    tcase_add_test(tc, test_zero_area);
    tcase_add_test(tc, test_bad_placement);
    tcase_add_test(tc, test_wall_from_stl);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
