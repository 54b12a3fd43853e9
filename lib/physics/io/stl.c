/* stl.c: the STL reader: the bytes of an STL file, ASCII or binary, into a
 * welded triangle mesh (vertices, and triangles as three vertex indices),
 * scaled and placed by an affine transform, for the mesh walls. The format
 * is that of 3D Systems (1989), StereoLithography Interface Specification:
 * binary, an 80-byte header, a little-endian uint32 count and 50 bytes a
 * triangle (normal and three corners as float32, a 2-byte attribute);
 * ASCII, "solid name", then per triangle "facet normal nx ny nz", "outer
 * loop", three "vertex x y z", "endloop", "endfacet", and "endsolid name".
 * Every way a file can be wrong is an error that names the triangle and
 * its line or byte; nothing stays allocated after one. */
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "physics/io/io.h"

#define HEADER 84    /* binary: the 80-byte header and the count */
#define RECORD 50    /* binary: bytes of a triangle */
#define NUMBER_MAX 64 /* ASCII: characters of the longest number read */

_Static_assert(sizeof(float) == 4, "binary STL holds IEEE 754 single precision");

/* The file's triangles as they are read. */
typedef struct reader {
    double a[9], t[3], scale; /* x' = a (scale x) + t */
    int mirror;               /* det a < 0: each triangle's corners 2 and 3 swapped */
    int ascii;
    double *c;                /* 9 per triangle: its corners, transformed */
    size_t *at;               /* ASCII: per triangle, the line of its "facet" */
    size_t nt, cap;
    uint32_t flipped;
    char *err;
    size_t errlen;
} reader;

static demill_status fail(reader *r, demill_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static demill_status fail(reader *r, demill_status code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->err, r->errlen, fmt, ap);
    va_end(ap);
    return code;
}

/* n items of size bytes, or NULL (also when n * size would overflow). */
static void *alloc_items(size_t n, size_t size)
{
    return n > SIZE_MAX / size ? NULL : malloc(n ? n * size : 1);
}

/* Where triangle k (from 0) is, for a message: its number from 1 and its
 * line (ASCII) or the byte its record starts at (binary). */
static void where(const reader *r, size_t k, char *buf, size_t n)
{
    if (r->ascii)
        snprintf(buf, n, "triangle %zu (line %zu)", k + 1, r->at[k]);
    else
        snprintf(buf, n, "triangle %zu (byte %zu)", k + 1, (size_t)HEADER + RECORD * k);
}

/* ASCII: room for one more triangle (binary files have theirs allocated at
 * once). */
static demill_status room(reader *r, size_t line)
{
    if (r->nt < r->cap)
        return DEMILL_OK;
    if (r->nt == DM_STL_MAX_TRIANGLES)
        return fail(r, DEMILL_ERR_FORMAT, "line %zu: more than %lu triangles, the most a mesh may have",
                    line, (unsigned long)DM_STL_MAX_TRIANGLES);
    const size_t cap = dm_grown_capacity(r->cap, r->nt + 1);
    void **arrays[2] = {(void **)&r->c, (void **)&r->at};
    const size_t sizes[2] = {9 * sizeof(double), sizeof(size_t)};
    if (cap > SIZE_MAX / sizes[0] || dm_grow_arrays(arrays, sizes, 2, cap))
        return fail(r, DEMILL_ERR_OUT_OF_MEMORY, "out of memory reading %zu triangles", r->nt + 1);
    r->cap = cap;
    return DEMILL_OK;
}

/* The number (from 1) in the file of the triangle's stored corner j. */
static int file_corner(const reader *r, int j)
{
    return (r->mirror && j ? 3 - j : j) + 1;
}

/* Adds a triangle: its normal n and corners p (x, y, z each) as the file
 * has them, and where it is (at: the line of each corner, or the byte of
 * the record). Counts it as flipped when n points against the winding. */
static demill_status add(reader *r, const double n[3], const double p[9], const size_t at[3])
{
    const size_t k = r->nt;
    char here[64];
    for (int j = 0; j < 9; j++)
        if (!isfinite(p[j])) {
            if (r->ascii)
                return fail(r, DEMILL_ERR_FORMAT, "line %zu: triangle %zu, corner %d: %s coordinate",
                            at[j / 3], k + 1, j / 3 + 1, isnan(p[j]) ? "a NaN" : "an infinite");
            return fail(r, DEMILL_ERR_FORMAT, "triangle %zu (byte %zu), corner %d: %s coordinate",
                        k + 1, at[0], j / 3 + 1, isnan(p[j]) ? "a NaN" : "an infinite");
        }
    const double e[2][3] = {{p[3] - p[0], p[4] - p[1], p[5] - p[2]},
                            {p[6] - p[0], p[7] - p[1], p[8] - p[2]}};
    const double side = n[0] * (e[0][1] * e[1][2] - e[0][2] * e[1][1]) +
                        n[1] * (e[0][2] * e[1][0] - e[0][0] * e[1][2]) +
                        n[2] * (e[0][0] * e[1][1] - e[0][1] * e[1][0]);
    r->flipped += side < 0;
    double *q = r->c + 9 * k;
    for (int j = 0; j < 3; j++) {
        const double *x = p + 3 * (file_corner(r, j) - 1);
        for (int i = 0; i < 3; i++) {
            double s = r->t[i];
            for (int m = 0; m < 3; m++)
                s += r->a[3 * i + m] * (r->scale * x[m]);
            q[3 * j + i] = s + 0.0; /* -0 as +0, which it equals */
            if (!isfinite(s)) {
                where(r, k, here, sizeof here);
                return fail(r, DEMILL_ERR_FORMAT,
                            "%s, corner %d: not finite after the scale and transform", here,
                            file_corner(r, j));
            }
        }
    }
    r->nt = k + 1;
    return DEMILL_OK;
}

/* ---- binary ---------------------------------------------------------------------- */
static uint32_t le32(const uint8_t *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static double f32(const uint8_t *b)
{
    const uint32_t u = le32(b);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static demill_status read_binary(reader *r, const uint8_t *b, uint32_t n)
{
    r->c = alloc_items((size_t)n * 9, sizeof(double));
    if (!r->c)
        return fail(r, DEMILL_ERR_OUT_OF_MEMORY, "out of memory reading %lu triangles",
                    (unsigned long)n);
    r->cap = n;
    for (size_t k = 0; k < n; k++) {
        const uint8_t *rec = b + HEADER + RECORD * k;
        double nrm[3], p[9];
        for (int j = 0; j < 3; j++)
            nrm[j] = f32(rec + 4 * j);
        for (int j = 0; j < 9; j++)
            p[j] = f32(rec + 12 + 4 * j);
        const size_t at[3] = {HEADER + RECORD * k, 0, 0};
        const demill_status st = add(r, nrm, p, at);
        if (st)
            return st;
    }
    return DEMILL_OK;
}

/* ---- ASCII ----------------------------------------------------------------------- */
/* Words separated by white space, with the line each starts on. */
typedef struct lexer {
    const uint8_t *b;
    size_t n, i, line;
    const uint8_t *word; /* the current word, len bytes (0: the end of the file) */
    size_t len, word_line;
} lexer;

static int white(uint8_t c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

static void next(lexer *x)
{
    for (; x->i < x->n && white(x->b[x->i]); x->i++)
        x->line += x->b[x->i] == '\n';
    x->word = x->b + x->i;
    x->word_line = x->line;
    while (x->i < x->n && !white(x->b[x->i]))
        x->i++;
    x->len = (size_t)(x->b + x->i - x->word);
}

/* Skips the rest of the line (a solid's name). */
static void rest_of_line(lexer *x)
{
    while (x->i < x->n && x->b[x->i] != '\n')
        x->i++;
}

static int lower(uint8_t c)
{
    return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

/* Whether the current word is w (lower case), in any case. */
static int is(const lexer *x, const char *w)
{
    size_t k = 0;
    for (; k < x->len && w[k]; k++)
        if (lower(x->word[k]) != w[k])
            return 0;
    return k == x->len && !w[k];
}

/* "line L: expected WHAT, found 'WORD'" (or "found the end of the file"). */
static demill_status expected(reader *r, const lexer *x, const char *what)
{
    if (!x->len)
        return fail(r, DEMILL_ERR_FORMAT, "line %zu: expected %s, found the end of the file",
                    x->word_line, what);
    char shown[28];
    size_t k = 0;
    for (; k < x->len && k < 24; k++)
        shown[k] = x->word[k] >= 0x20 && x->word[k] < 0x7f ? (char)x->word[k] : '?';
    strcpy(shown + k, x->len > 24 ? "..." : "");
    return fail(r, DEMILL_ERR_FORMAT, "line %zu: expected %s, found '%s'", x->word_line, what,
                shown);
}

static demill_status word(reader *r, lexer *x, const char *w)
{
    next(x);
    if (is(x, w))
        return DEMILL_OK;
    char what[16];
    snprintf(what, sizeof what, "'%s'", w);
    return expected(r, x, what);
}

/* Whether the word is a decimal number ([sign] digits [. digits] [e [sign]
 * digits], digits on at least one side of the point), nan or inf(inity):
 * what C's printf writes, and nothing else strtod would take (hex, a
 * locale's decimal comma). */
static int numeral(const lexer *x)
{
    const uint8_t *s = x->word, *end = s + x->len;
    if (s < end && (*s == '+' || *s == '-'))
        s++;
    lexer rest = *x;
    rest.word = s;
    rest.len = (size_t)(end - s);
    if (is(&rest, "nan") || is(&rest, "inf") || is(&rest, "infinity"))
        return 1;
    size_t digits = 0;
    for (; s < end && *s >= '0' && *s <= '9'; s++)
        digits++;
    if (s < end && *s == '.')
        for (s++; s < end && *s >= '0' && *s <= '9'; s++)
            digits++;
    if (!digits)
        return 0;
    if (s < end && lower(*s) == 'e') {
        s++;
        if (s < end && (*s == '+' || *s == '-'))
            s++;
        if (s == end || *s < '0' || *s > '9')
            return 0;
        while (s < end && *s >= '0' && *s <= '9')
            s++;
    }
    return s == end;
}

/* The next word as a number (which may be NaN or infinite). */
static demill_status number(reader *r, lexer *x, double *v)
{
    next(x);
    if (!x->len || x->len >= NUMBER_MAX || !numeral(x))
        return expected(r, x, "a number");
    /* strtod reads the locale's decimal point: the host may have set one */
    char buf[NUMBER_MAX];
    const char point = localeconv()->decimal_point[0];
    for (size_t k = 0; k < x->len; k++)
        buf[k] = x->word[k] == '.' ? point : (char)x->word[k];
    buf[x->len] = 0;
    *v = strtod(buf, NULL);
    return DEMILL_OK;
}

/* One "facet ... endfacet", its "facet" read. */
static demill_status facet(reader *r, lexer *x)
{
    const size_t line = x->word_line;
    double n[3], p[9];
    size_t at[3];
    demill_status st = room(r, line);
    if (!st)
        st = word(r, x, "normal");
    for (int j = 0; j < 3 && !st; j++)
        st = number(r, x, &n[j]);
    if (!st)
        st = word(r, x, "outer");
    if (!st)
        st = word(r, x, "loop");
    for (int j = 0; j < 3 && !st; j++) {
        st = word(r, x, "vertex");
        at[j] = x->word_line;
        for (int i = 0; i < 3 && !st; i++)
            st = number(r, x, &p[3 * j + i]);
    }
    if (!st)
        st = word(r, x, "endloop");
    if (!st)
        st = word(r, x, "endfacet");
    if (st)
        return st;
    r->at[r->nt] = line;
    return add(r, n, p, at);
}

static demill_status read_ascii(reader *r, const uint8_t *b, size_t size)
{
    lexer x = {.b = b, .n = size, .line = 1};
    next(&x); /* "solid", checked by the caller */
    for (;;) {
        rest_of_line(&x);
        for (next(&x); !is(&x, "endsolid"); next(&x)) {
            if (!is(&x, "facet"))
                return expected(r, &x, "'facet' or 'endsolid'");
            const demill_status st = facet(r, &x);
            if (st)
                return st;
        }
        rest_of_line(&x);
        next(&x);
        if (!x.len)
            return DEMILL_OK;
        if (!is(&x, "solid"))
            return expected(r, &x, "'solid' or the end of the file");
    }
}

/* ---- the whole file -------------------------------------------------------------- */
/* Whether the bytes are text: no control character but white space. */
static int text(const uint8_t *b, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if ((b[k] < 0x20 && !white(b[k])) || b[k] == 0x7f)
            return 0;
    return 1;
}

/* A point of the welding sort: its coordinates and its corner. */
typedef struct key {
    double x[3];
    uint32_t corner;
} key;

static int same_point(const key *a, const key *b)
{
    return a->x[0] == b->x[0] && a->x[1] == b->x[1] && a->x[2] == b->x[2];
}

static int key_order(const void *pa, const void *pb)
{
    const key *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a->x[i] != b->x[i])
            return a->x[i] < b->x[i] ? -1 : 1;
    return (a->corner > b->corner) - (a->corner < b->corner);
}

/* Welds the corners: equal points are one vertex, numbered in the order of
 * their first corner; r->c becomes the vertices (moved down in place). */
static demill_status weld(reader *r, dm_stl_mesh *out)
{
    const size_t nc = 3 * r->nt;
    key *k = alloc_items(nc, sizeof *k);
    uint32_t *tri = alloc_items(nc, sizeof *tri);
    if (!k || !tri) {
        free(k);
        free(tri);
        return fail(r, DEMILL_ERR_OUT_OF_MEMORY, "out of memory welding %zu triangles", r->nt);
    }
    for (size_t c = 0; c < nc; c++) {
        memcpy(k[c].x, r->c + 3 * c, sizeof k[c].x);
        k[c].corner = (uint32_t)c;
    }
    qsort(k, nc, sizeof *k, key_order);
    /* each corner points to the first corner at its point */
    for (size_t g = 0, h; g < nc; g = h)
        for (h = g; h < nc && same_point(&k[h], &k[g]); h++)
            tri[k[h].corner] = k[g].corner;
    free(k);
    uint32_t nv = 0;
    for (size_t c = 0; c < nc; c++)
        if (tri[c] == c) {
            memmove(r->c + 3 * (size_t)nv, r->c + 3 * c, 3 * sizeof(double));
            tri[c] = nv++;
        } else {
            tri[c] = tri[tri[c]];
        }
    double *v = realloc(r->c, 3 * sizeof(double) * nv);
    out->v = v ? v : r->c;
    r->c = NULL;
    out->tri = tri;
    out->nv = nv;
    out->nt = (uint32_t)r->nt;
    out->flipped = r->flipped;
    return DEMILL_OK;
}

/* The first triangle of zero area: two corners at one vertex, or a height
 * under DM_STL_FLAT of the longest edge (|e1 x e2| = longest edge x height,
 * the edges scaled by their largest coordinate so that nothing overflows
 * or underflows). */
static demill_status check_areas(reader *r, const dm_stl_mesh *m)
{
    char here[64];
    for (size_t k = 0; k < m->nt; k++) {
        const uint32_t *t = m->tri + 3 * k;
        for (int j = 0; j < 3; j++)
            if (t[j] == t[(j + 1) % 3]) {
                const double *x = m->v + 3 * (size_t)t[j];
                const int c0 = file_corner(r, j), c1 = file_corner(r, (j + 1) % 3);
                where(r, k, here, sizeof here);
                return fail(r, DEMILL_ERR_FORMAT,
                            "%s has zero area: corners %d and %d are the same point (%g, %g, %g)",
                            here, c0 < c1 ? c0 : c1, c0 < c1 ? c1 : c0, x[0], x[1], x[2]);
            }
        const double *a = m->v + 3 * (size_t)t[0], *b = m->v + 3 * (size_t)t[1],
                     *c = m->v + 3 * (size_t)t[2];
        double e[3][3], s = 0;
        for (int i = 0; i < 3; i++) {
            e[0][i] = b[i] - a[i];
            e[1][i] = c[i] - a[i];
            e[2][i] = c[i] - b[i];
            for (int j = 0; j < 3; j++)
                s = fmax(s, fabs(e[j][i]));
        }
        where(r, k, here, sizeof here);
        if (!isfinite(s))
            return fail(r, DEMILL_ERR_FORMAT, "%s: its edges are too long for a double", here);
        double longest = 0;
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 3; i++)
                e[j][i] /= s;
            longest = fmax(longest, e[j][0] * e[j][0] + e[j][1] * e[j][1] + e[j][2] * e[j][2]);
        }
        const double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                             e[0][2] * e[1][0] - e[0][0] * e[1][2],
                             e[0][0] * e[1][1] - e[0][1] * e[1][0]};
        if (sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) <= DM_STL_FLAT * longest)
            return fail(r, DEMILL_ERR_FORMAT,
                        "%s has zero area: its corners are in a line (height under %g of its "
                        "longest edge)",
                        here, DM_STL_FLAT);
    }
    return DEMILL_OK;
}

/* Checks the scale and transform and sets them in r. */
static demill_status placement(reader *r, double scale, const double xf[12])
{
    static const double identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    if (!(isfinite(scale) && scale > 0))
        return fail(r, DEMILL_ERR_INVALID_VALUE, "scale %g: must be finite and positive", scale);
    if (!xf)
        xf = identity;
    for (int k = 0; k < 12; k++)
        if (!isfinite(xf[k]))
            return fail(r, DEMILL_ERR_INVALID_VALUE, "transform element %d is not finite", k);
    memcpy(r->a, xf, sizeof r->a);
    memcpy(r->t, xf + 9, sizeof r->t);
    r->scale = scale;
    const double *a = r->a;
    const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                       a[2] * (a[3] * a[7] - a[4] * a[6]);
    /* |det| <= the product of the rows' lengths (Hadamard's inequality) */
    double rows = 1;
    for (int i = 0; i < 3; i++)
        rows *= sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]);
    if (!(fabs(det) > DM_STL_FLAT * rows))
        return fail(r, DEMILL_ERR_INVALID_VALUE,
                    "the transform's 3x3 part is singular (determinant %g)", det);
    r->mirror = det < 0;
    return DEMILL_OK;
}

/* Which kind of file the bytes are, and its triangles into r. */
static demill_status read_file(reader *r, const uint8_t *b, size_t size)
{
    if (!size)
        return fail(r, DEMILL_ERR_FORMAT, "empty: no STL data");
    const uint32_t n = size >= HEADER ? le32(b + 80) : 0;
    const int binary = size >= HEADER && (uint64_t)size == HEADER + (uint64_t)RECORD * n;
    if (!binary) {
        const size_t skip = size >= 3 && !memcmp(b, "\xef\xbb\xbf", 3) ? 3 : 0; /* UTF-8 mark */
        lexer x = {.b = b + skip, .n = size - skip, .line = 1};
        next(&x);
        const int is_text = text(b + skip, size - skip);
        if (is_text && is(&x, "solid")) {
            r->ascii = 1;
            const demill_status st = read_ascii(r, b + skip, size - skip);
            if (!st && !r->nt)
                return fail(r, DEMILL_ERR_FORMAT, "ASCII STL without triangles");
            return st;
        }
        if (size < HEADER || is_text) {
            char start[20];
            size_t k = 0;
            for (; k < size && k < 16; k++)
                start[k] = b[k] >= 0x20 && b[k] < 0x7f ? (char)b[k] : '.';
            start[k] = 0;
            return fail(r, DEMILL_ERR_FORMAT,
                        "not an STL file (%zu bytes starting \"%s\"): neither text starting "
                        "with 'solid' nor a binary STL (84 bytes at least)",
                        size, start);
        }
    }
    if (n > DM_STL_MAX_TRIANGLES)
        return fail(r, DEMILL_ERR_FORMAT,
                    "binary STL of %lu triangles: more than %lu, the most a mesh may have",
                    (unsigned long)n, (unsigned long)DM_STL_MAX_TRIANGLES);
    if (!binary)
        return fail(r, DEMILL_ERR_FORMAT,
                    "%s binary STL: %lu triangles need %llu bytes, the file has %zu",
                    (uint64_t)size < HEADER + (uint64_t)RECORD * n ? "truncated" : "corrupt",
                    (unsigned long)n, (unsigned long long)(HEADER + (uint64_t)RECORD * n), size);
    if (!n)
        return fail(r, DEMILL_ERR_FORMAT, "binary STL without triangles");
    return read_binary(r, b, n);
}

demill_status dm_stl_parse(const uint8_t *bytes, size_t size, double scale, const double xf[12],
                           dm_stl_mesh *out, char *err, size_t errlen)
{
    reader r = {.err = err, .errlen = errlen};
    memset(out, 0, sizeof *out);
    demill_status st = placement(&r, scale, xf);
    if (!st)
        st = read_file(&r, bytes, size);
    if (!st)
        st = weld(&r, out);
    if (!st && (st = check_areas(&r, out)))
        dm_stl_free(out);
    free(r.c);
    free(r.at);
    return st;
}

void dm_stl_free(dm_stl_mesh *m)
{
    free(m->v);
    free(m->tri);
    memset(m, 0, sizeof *m);
}
