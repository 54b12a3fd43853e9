/* stl.c: the fuzz target of the STL reader (dm_stl_parse, lib/physics/io/stl.c).
 *
 * The first byte of an input chooses how the rest is used:
 *   bit 0 clear: as a whole file (reaches the choice of format, the ASCII
 *         grammar and the binary size check);
 *   bit 0 set:   as binary triangle records behind an 80-byte header and
 *         the count of whole records there are (reaches the checks of every
 *         triangle, which a random count would almost never let through);
 *   bits 1-2:    the placement: none; scale 1e-3 with a rotation and a
 *         translation; scale 2 with a mirror; scale 1e300 (overflow).
 * Every parse must return DEMILL_OK or DEMILL_ERR_FORMAT with a message,
 * never crash, leak or touch memory it should not (run under
 * AddressSanitizer and UBSan); a mesh it returns must have 1 to
 * DM_STL_MAX_TRIANGLES triangles, at most 3 vertices a triangle, every
 * index below the vertex count and three different ones a triangle, every
 * coordinate finite and no -0, and no two vertices at one point (welded).
 *
 * Built two ways, as the checkpoint target is: with clang's libFuzzer
 * (tests/fuzz/run stl) and with a plain main() (replay.c), which CTest runs
 * on the committed corpus in tests/fuzz/corpus-stl/. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/io/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int point_order(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a[i] != b[i])
            return a[i] < b[i] ? -1 : 1;
    return 0;
}

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "stl fuzz: %s\n", what);
        abort();
    }
}

/* The mesh is what dm_stl_parse promises. */
static void check_mesh(const dm_stl_mesh *m)
{
    check(m->nt >= 1 && m->nt <= DM_STL_MAX_TRIANGLES, "triangle count");
    check(m->nv >= 3 && m->nv <= 3 * (size_t)m->nt, "vertex count");
    check(m->flipped <= m->nt, "flipped count");
    for (size_t k = 0; k < m->nt; k++) {
        const uint32_t *t = m->tri + 3 * k;
        check(t[0] < m->nv && t[1] < m->nv && t[2] < m->nv, "index out of range");
        check(t[0] != t[1] && t[1] != t[2] && t[2] != t[0], "two corners at one vertex");
    }
    double *v = malloc(3 * sizeof(double) * m->nv);
    check(v != NULL, "out of memory");
    memcpy(v, m->v, 3 * sizeof(double) * m->nv);
    for (size_t k = 0; k < 3 * (size_t)m->nv; k++)
        check(isfinite(v[k]) && !(v[k] == 0 && signbit(v[k])), "coordinate not finite, or -0");
    qsort(v, m->nv, 3 * sizeof(double), point_order);
    for (size_t k = 1; k < m->nv; k++)
        check(point_order(v + 3 * (k - 1), v + 3 * k) != 0, "two vertices at one point");
    free(v);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const double scales[4] = {1, 1e-3, 2, 1e300};
    static const double xfs[4][12] = {
        {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
        {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1, 0.25, -1.5, 3}, /* 53.13 degrees about z */
        {-1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
        {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
    };
    if (size == 0)
        return 0;
    const int records = data[0] & 1, place = data[0] >> 1 & 3;
    const size_t count = records ? (size - 1) / 50 : 0;
    const size_t n = records ? 84 + 50 * count : size - 1;
    uint8_t *b = malloc(n ? n : 1);
    check(b != NULL, "out of memory");
    if (records) {
        memset(b, ' ', 80);
        for (int k = 0; k < 4; k++)
            b[80 + k] = (uint8_t)(count >> 8 * k);
        memcpy(b + 84, data + 1, 50 * count);
    } else {
        memcpy(b, data + 1, n);
    }
    dm_stl_mesh m;
    char err[256] = "";
    const demill_status st = dm_stl_parse(b, n, scales[place], xfs[place], &m, err, sizeof err);
    if (st == DEMILL_OK) {
        check_mesh(&m);
        dm_stl_free(&m);
    } else {
        if (st != DEMILL_ERR_FORMAT)
            fprintf(stderr, "parse gave %d: %s\n", (int)st, err);
        check(st == DEMILL_ERR_FORMAT, "status other than OK or FORMAT");
        check(err[0] != 0, "no message");
        check(m.v == NULL && m.tri == NULL && m.nt == 0, "mesh not empty after an error");
    }
    free(b);
    return 0;
}
