/* api.c: the fuzz target of the public API. Each input is a sequence of
 * calls (api_ops.h says how the bytes encode them) on two worlds, with
 * hostile arguments: NaN, ±inf, 0, -0, 1e308, 1e-308, denormals, huge
 * counts, NULL, removed and forged ids, ids of the other world, pointers that
 * are not worlds or snapshots. After every call the harness checks what the
 * API promises (demill/common.h, demill/state.h):
 *   - a call that fails leaves the world's state (its checkpoint bytes,
 *     demill_world_save_buffer) as it was; failed_change() has the rule
 *     for the documented exceptions (stepping stopped by the watchdog or
 *     the progress callback);
 *   - a call that changes nothing by its documentation (reads, saves,
 *     listings, VTK output, the progress callback) changes no byte;
 *   - a call never changes the other world (checked at the end of each
 *     input);
 *   - whatever the calls leave, save → load (into a scratch world) → save
 *     gives the same bytes, and the load succeeds (a state that is not
 *     finite, left by a run that diverged with the watchdog off, cannot be
 *     saved: such states are only told from finite ones);
 *   - no demill_world_step() or demill_world_settle() with the watchdog on
 *     returns DEMILL_OK with a non-finite position, velocity or angular
 *     velocity (read back through the API);
 *   - a call that names an object demill_world_ids() does not list in its
 *     world (removed, of the other world, forged, of the wrong kind) fails,
 *     and one that names only listed objects does not fail with
 *     DEMILL_ERR_INVALID_HANDLE;
 *   - a NULL world gives DEMILL_ERR_NULL_POINTER and a pointer that is not a
 *     world DEMILL_ERR_INVALID_HANDLE; a failure on a world leaves a message;
 *   - bulk reads give as many items as there are, particles_read_ids the
 *     order of demill_world_ids(), progress reports the steps and time the
 *     documentation says, parameter bounds hold their defaults;
 *   - a grinding object (demill/grinding.h, one per input) is as its reads
 *     (classes, rates, appearance, product, time, what its model gives)
 *     showed it before a call that fails or reads, a call on NULL or on
 *     what is not a live object fails as documented, a failure leaves a
 *     message, and demill_grinding_run() keeps the mass within 1e-9
 *     relative; no grinding call changes a world.
 * A violation prints what failed and aborts; DEMILL_FUZZ_TRACE=1 in the
 * environment prints every call with its arguments and status first.
 *
 * Calls that the library would take and run for long are left out
 * (capped_steps(), settle_cap(), fill_cap()): steps and particle counts stay
 * small so that an input runs in milliseconds, but a call that the library
 * must refuse (NaN, negative or huge arguments, NULL buffers with huge
 * counts, fills and settles beyond its limits) is always made.
 *
 * Built two ways, like checkpoint.c: with libFuzzer (tests/fuzz/run api) and
 * with replay.c, which CTest runs on tests/fuzz/corpus-api/. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <demill.h>

#include "api_ops.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define PARTICLES_MAX 512 /* per world: more are not added (steps stay fast) */
#define WALLS_MAX 16      /* walls per world (planes, meshes, finite walls) */
#define STEPS_MAX 256     /* steps a call may ask for (more if the progress callback stops it) */
#define BINS_MAX 64       /* spectrum bins asked for where 1..10000 would be accepted */
#define POOL 64           /* ids seen before, removed ones among them */
#define COUNT(a) (sizeof(a) / sizeof(a)[0])
#define PI 3.14159265358979323846

/* ---- harness state ------------------------------------------------------- */

/* A world's checkpoint, or none: a state that is not finite (a run that
 * diverged with the watchdog off) cannot be saved. */
typedef struct buf {
    unsigned char *b;
    size_t n, cap;
    bool diverged;
} buf;

typedef struct progress {
    demill_world *w;  /* the world it reports on */
    bool set;         /* a callback is set on it */
    uint64_t every;   /* steps between reports */
    uint32_t stop_at; /* the report of a call at which it stops the run (0: never) */
    bool read;        /* reads the world when called */
    uint32_t reports; /* reports during the current call */
} progress;

typedef struct listing {
    demill_id *id;
    size_t n, cap;
} listing;

static struct {
    const uint8_t *p;
    size_t n;
    demill_world *w[2], *scratch;
    listing list[2][8]; /* per world, per kind (DEMILL_KIND_*) */
    demill_id pool[POOL];
    size_t npool, pool_next;
    demill_snapshot *snap[2];
    demill_vtk_series *series;
    progress prog[2];
    buf before[2];    /* each world's checkpoint as the next call finds it */
    buf after, again; /* scratch */
    demill_grinding *g;     /* the grinding object, or none */
    buf gbefore, gafter;    /* its state before and after a call (grinding_state()) */
    char dir[64]; /* temporary directory for files */
    bool trace;
    unsigned long ops;
} F;

/* Memory that is not a world nor a snapshot (its first word is no magic). */
static uint64_t fake_object[64];

static void fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "api fuzz: call %lu: ", F.ops);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n(run the input with DEMILL_FUZZ_TRACE=1 to see the calls)\n");
    abort();
}

static void trace(const char *fmt, ...)
{
    if (!F.trace)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
}

/* ---- reading the input --------------------------------------------------- */

static uint8_t byte(void)
{
    if (!F.n)
        return 0;
    F.n--;
    return *F.p++;
}

static uint64_t raw64(void)
{
    uint64_t v = 0;
    for (int k = 0; k < 8; k++)
        v |= (uint64_t)byte() << (8 * k);
    return v;
}

static const double special[FZ_NUM_SCALED] = {
    0.0, -0.0, 1.0, -1.0, NAN, -NAN, INFINITY, -INFINITY,
    1e308, -1e308, DBL_MAX, 1e-308, DBL_MIN, 4.9406564584124654e-324, -4.9406564584124654e-324,
    1e300, -1e300, 1e-300, 1e15, 1e-15, 1e-9, 1e-6, 1e-5, 1e-4,
    0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2,
    0.3, 0.5, 0.75, 0.9, 2.0, 3.0, 4.0, 10.0,
    100.0, 1e3, 1e4, 1e5, 1e6, 1e8, 1e9, 1e30,
    2500.0, 7800.0, 9.81, -9.81, 0.25, 1.4, 64.0, 1e7,
    4.71238898038468986, 9223372036854775808.0, 0.49999999999999994, -0.001, -0.01, -0.1,
    4294967296.0, 18446744073709551616.0};

static double num(void)
{
    const uint8_t b = byte();
    if (b < FZ_NUM_SCALED)
        return special[b];
    if (b < FZ_NUM_RAW)
        return (double)(int8_t)byte() * ldexp(1.0, (int)b - 96);
    const uint64_t bits = raw64();
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static const uint64_t large_counts[] = {
    SIZE_MAX, SIZE_MAX - 1, SIZE_MAX / 2, SIZE_MAX / 2 + 1, UINT32_MAX, (uint64_t)UINT32_MAX + 1,
    UINT32_MAX - 1, UINT32_MAX / 4, 1u << 31, 65535, 65536, 4095, 4096, 10000, 10001, 1000000,
    1000000000, 64, 65, 100, 128, 256, 257, 500, 1000};

static uint64_t count(void)
{
    const uint8_t b = byte();
    if (b < FZ_COUNT_TABLE)
        return b;
    if (b == FZ_COUNT_RAW)
        return raw64();
    return b - FZ_COUNT_TABLE < (int)COUNT(large_counts) ? large_counts[b - FZ_COUNT_TABLE]
                                                         : (uint64_t)(b & 15);
}

static int32_t pick(const int32_t *table, size_t n)
{
    return table[byte() % n];
}

/* ---- ids ------------------------------------------------------------------ */

#define ID_TAG_SHIFT 52
#define ID_KIND_SHIFT 48
#define ID_GEN_SHIFT 32

static void pool_add(demill_id id)
{
    if (id == DEMILL_ID_NONE)
        return;
    for (size_t k = 0; k < F.npool; k++)
        if (F.pool[k] == id)
            return;
    F.pool[F.pool_next] = id;
    F.pool_next = (F.pool_next + 1) % POOL;
    if (F.npool < POOL)
        F.npool++;
}

static bool listed(int k, int kind, demill_id id)
{
    const listing *l = &F.list[k][kind];
    for (size_t i = 0; i < l->n; i++)
        if (l->id[i] == id)
            return true;
    return false;
}

static void list_world(int k)
{
    for (int kind = DEMILL_KIND_MATERIAL; kind <= DEMILL_KIND_BODY; kind++) {
        listing *l = &F.list[k][kind];
        size_t n;
        if (demill_world_ids(F.w[k], kind, NULL, 0, &n) != DEMILL_OK)
            fail("demill_world_ids(kind %d) refused to count: %s", kind,
                 demill_world_last_error(F.w[k]));
        if (n > l->cap) {
            demill_id *p = realloc(l->id, n * sizeof *p);
            if (!p)
                abort();
            l->id = p;
            l->cap = n;
        }
        if (demill_world_ids(F.w[k], kind, l->id, n, &l->n) != DEMILL_OK || l->n != n)
            fail("demill_world_ids(kind %d) did not list its %zu ids", kind, n);
    }
}

/* One of the call's world's listed ids of a kind (k < 0: none listed). */
static demill_id listed_id(int k, int kind, size_t i)
{
    if (k < 0 || !F.list[k][kind].n)
        return DEMILL_ID_NONE;
    return F.list[k][kind].id[i % F.list[k][kind].n];
}

/* An id for an argument of `kind` of a call on world k (-1: NULL or fake). */
static demill_id id_arg(int k, int kind)
{
    const uint8_t b = byte();
    if (b < FZ_ID_OTHER)
        return listed_id(k, kind, b);
    if (b < FZ_ID_POOL)
        return listed_id(k < 0 ? 0 : 1 - k, kind, b);
    if (b < FZ_ID_SPECIAL)
        return F.npool ? F.pool[(b + (size_t)byte()) % F.npool] : DEMILL_ID_NONE;
    const demill_id base = listed_id(k, kind, 0);
    switch (b - FZ_ID_SPECIAL) {
    case 0: return DEMILL_ID_NONE;
    case 1: return raw64();
    case 2: return ~(demill_id)0;
    case 3: /* the next kind */
        return (base & ~((demill_id)0xf << ID_KIND_SHIFT)) |
               (demill_id)(kind % DEMILL_KIND_BODY + 1) << ID_KIND_SHIFT;
    case 4: return base + ((demill_id)1 << ID_GEN_SHIFT);
    case 5: return base + ((demill_id)1 << ID_TAG_SHIFT);
    case 6: return base + 1;
    case 7: return base | 0xffffffffu;
    default: return F.npool ? F.pool[byte() % F.npool] : DEMILL_ID_NONE;
    }
}

/* ---- a call --------------------------------------------------------------- */

#define NAMED_MAX 16

typedef struct call {
    demill_world *w; /* the world passed: F.w[k], NULL or fake_object */
    int k;           /* 0 or 1, or -1 for NULL or fake */
    int dim;         /* its dimension (3 for NULL or fake) */
    size_t np;       /* its particles */
    demill_status st;
    bool worldless;  /* the op takes no world (or handles NULL and fake itself) */
    bool query;      /* documented to change nothing */
    bool replaces;   /* replaces the world (destroy and create) */
    bool stepping;   /* demill_world_step() or demill_world_settle() */
    bool one_run;    /* demill_world_step() */
    double steps_before; /* the world's step count before stepping */
    bool watchdog;   /* the watchdog was on */
    bool skipped;    /* capped: the call was not made */
    bool other_handle; /* may fail with DEMILL_ERR_INVALID_HANDLE for another reason */
    bool grinding_message; /* a failure may leave its message in the grinding object */
    int nnamed;
    demill_id named[NAMED_MAX];
    int named_kind[NAMED_MAX];
} call;

/* An id argument of the call, remembered for check_named(). */
static demill_id id_named(call *c, int kind)
{
    const demill_id id = id_arg(c->k, kind);
    if (c->nnamed < NAMED_MAX) {
        c->named[c->nnamed] = id;
        c->named_kind[c->nnamed++] = kind;
    }
    return id;
}

static double world_value(const call *c, int32_t key)
{
    double v = 0.0;
    if (c->k >= 0 && demill_world_get(c->w, key, &v) != DEMILL_OK)
        fail("demill_world_get(%d) failed on a live world", (int)key);
    return v;
}

/* Sets z to 0 in a 2D world where `zero` asks; otherwise a 2D world gets
 * the z the input gave, which the library must refuse unless it is 0. */
static void flat(const call *c, double *v, bool zero)
{
    if (c->dim == 2 && zero)
        v[2] = 0.0;
}

static void vec(double *v)
{
    for (int i = 0; i < 3; i++)
        v[i] = num();
}

static void trace_vec(const char *name, const double *v)
{
    if (v)
        trace("%s = {%.17g, %.17g, %.17g}", name, v[0], v[1], v[2]);
    else
        trace("%s = NULL", name);
}

/* A capacity for a read of n items: n, n - 1, 0, SIZE_MAX or n + 1 (the
 * buffer always holds n + 1). */
static size_t capacity(uint8_t flags, size_t n)
{
    switch ((flags >> 2) % 5) {
    case 0: return n;
    case 1: return n ? n - 1 : 0;
    case 2: return 0;
    case 3: return SIZE_MAX;
    default: return n + 1;
    }
}

static void *grab(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p)
        abort();
    return p;
}

/* ---- the ops -------------------------------------------------------------- */

static void op_world_recreate(call *c)
{
    const int dim = byte() & 1 ? 2 : 3;
    c->worldless = c->k < 0;
    c->replaces = true;
    trace("demill_world_destroy(w%d); demill_world_create(%d, &w%d)", c->k, dim, c->k);
    demill_world_destroy(c->w);
    if (c->k < 0)
        return;
    c->st = demill_world_create(dim, &F.w[c->k]);
    if (c->st != DEMILL_OK || !F.w[c->k])
        fail("demill_world_create(%d) gave %d", dim, (int)c->st);
    c->w = F.prog[c->k].w = F.w[c->k];
    F.prog[c->k].set = false;
}

static void op_world_create_bad(call *c)
{
    const int32_t dim = pick(fz_dimensions, COUNT(fz_dimensions));
    const bool null_out = byte() & 1;
    demill_world *w = (demill_world *)fake_object; /* a failure must set it to NULL */
    c->worldless = true;
    trace("demill_world_create(%d, %s)", (int)dim, null_out ? "NULL" : "&w");
    c->st = demill_world_create(dim, null_out ? NULL : &w);
    const demill_status want = null_out               ? DEMILL_ERR_NULL_POINTER
                               : dim == 2 || dim == 3 ? DEMILL_OK
                                                      : DEMILL_ERR_INVALID_VALUE;
    if (c->st != want || (!null_out && (c->st == DEMILL_OK) != (w != NULL)))
        fail("demill_world_create(%d, %s) gave %d and %s a world", (int)dim,
             null_out ? "NULL" : "&w", (int)c->st, w ? "set" : "did not set");
    if (!null_out)
        demill_world_destroy(w);
}

static void op_world_set(call *c)
{
    const int32_t key = pick(fz_world_keys, COUNT(fz_world_keys));
    const double v = num();
    trace("demill_world_set(w, %d, %.17g)", (int)key, v);
    c->st = demill_world_set(c->w, key, v);
}

static void op_world_get(call *c)
{
    const int32_t key = pick(fz_world_keys, COUNT(fz_world_keys));
    double v;
    const bool null_out = byte() & 1;
    c->query = true;
    trace("demill_world_get(w, %d, %s)", (int)key, null_out ? "NULL" : "&v");
    c->st = demill_world_get(c->w, key, null_out ? NULL : &v);
}

static void op_material_create(call *c)
{
    demill_id m = DEMILL_ID_NONE;
    const bool null_out = byte() & 1;
    trace("demill_material_create(w, %s)", null_out ? "NULL" : "&m");
    c->st = demill_material_create(c->w, null_out ? NULL : &m);
    pool_add(m);
}

static void op_material_set(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const int32_t key = pick(fz_material_keys, COUNT(fz_material_keys));
    const double v = num();
    trace("demill_material_set(w, 0x%llx, %d, %.17g)", (unsigned long long)m, (int)key, v);
    c->st = demill_material_set(c->w, m, key, v);
}

static void op_material_get(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const int32_t key = pick(fz_material_keys, COUNT(fz_material_keys));
    const bool null_out = byte() & 1;
    double v;
    c->query = true;
    trace("demill_material_get(w, 0x%llx, %d, %s)", (unsigned long long)m, (int)key,
          null_out ? "NULL" : "&v");
    c->st = demill_material_get(c->w, m, key, null_out ? NULL : &v);
}

static void op_pair_set(call *c)
{
    const demill_id a = id_named(c, DEMILL_KIND_MATERIAL), b = id_named(c, DEMILL_KIND_MATERIAL);
    const int32_t key = pick(fz_pair_keys, COUNT(fz_pair_keys));
    const double v = num();
    trace("demill_pair_set(w, 0x%llx, 0x%llx, %d, %.17g)", (unsigned long long)a,
          (unsigned long long)b, (int)key, v);
    c->st = demill_pair_set(c->w, a, b, key, v);
}

static void op_pair_get(call *c)
{
    const demill_id a = id_named(c, DEMILL_KIND_MATERIAL), b = id_named(c, DEMILL_KIND_MATERIAL);
    const int32_t key = pick(fz_pair_keys, COUNT(fz_pair_keys));
    const bool null_out = byte() & 1;
    double v;
    c->query = true;
    trace("demill_pair_get(w, 0x%llx, 0x%llx, %d, %s)", (unsigned long long)a,
          (unsigned long long)b, (int)key, null_out ? "NULL" : "&v");
    c->st = demill_pair_get(c->w, a, b, key, null_out ? NULL : &v);
}

/* n particles on a lattice of 4 × 4 × ... from `corner`, 2.5 radii apart. */
static void lattice(const call *c, size_t n, const double *corner, double r, double *x)
{
    const double a = isfinite(r) && r > 0.0 ? 2.5 * r : 0.01;
    for (size_t k = 0; k < n; k++) {
        const size_t q[3] = {k % 4, (k / 4) % 4, k / 16};
        for (int i = 0; i < 3; i++)
            x[3 * k + i] = corner[i] + a * (double)q[i];
        flat(c, x + 3 * k, true);
    }
}

static void op_particles_add(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const uint8_t f = byte();
    static const uint32_t add_flags[4] = {0, DEMILL_ADD_NO_OVERLAP, 2, 0x80000001u};
    const uint32_t flags = add_flags[(f >> 2) & 3];
    const int layout = f & 3;
    size_t n;
    double *x = NULL, *r = NULL, *v = NULL;
    demill_id *ids = NULL;
    if (layout == 2) {
        n = count();
        /* the other array holds one value whatever n says: the library must
         * stop at the NULL before it reads */
        if (f & 64)
            x = grab(3, sizeof *x);
        else
            r = grab(1, sizeof *r);
        trace("demill_particles_add(w, 0x%llx, %zu, %s, %s, NULL, 0x%x, NULL)",
              (unsigned long long)m, n, x ? "x" : "NULL", r ? "r" : "NULL", (unsigned)flags);
        c->st = demill_particles_add(c->w, m, n, x, r, NULL, flags, NULL);
        free(x);
        free(r);
        return;
    }
    n = layout == 1 ? 1 + byte() % 4 : 1 + byte() % 16;
    x = grab(3 * n, sizeof *x);
    r = grab(n, sizeof *r);
    v = grab(3 * n, sizeof *v);
    ids = grab(n, sizeof *ids);
    if (layout == 1) {
        for (size_t k = 0; k < n; k++) {
            vec(x + 3 * k);
            r[k] = num();
            vec(v + 3 * k);
            flat(c, x + 3 * k, f & 64);
            flat(c, v + 3 * k, f & 64);
        }
    } else {
        double corner[3], vel[3];
        vec(corner);
        const double radius = num();
        vec(vel);
        flat(c, vel, true);
        lattice(c, n, corner, radius, x);
        for (size_t k = 0; k < n; k++) {
            r[k] = radius;
            memcpy(v + 3 * k, vel, sizeof vel);
        }
        if (layout == 3) {
            const size_t which = byte() % (7 * n);
            double *slot = which < 3 * n   ? x + which
                           : which < 4 * n ? r + (which - 3 * n)
                                           : v + (which - 4 * n);
            *slot = num();
        }
    }
    if (c->np + n > PARTICLES_MAX) {
        c->skipped = true;
    } else {
        const bool no_v = f & 32, no_ids = f & 16;
        if (F.trace) {
            trace("demill_particles_add(w, 0x%llx, %zu, x, r, %s, 0x%x, %s) with",
                  (unsigned long long)m, n, no_v ? "NULL" : "v", (unsigned)flags,
                  no_ids ? "NULL" : "ids");
            for (size_t k = 0; k < n; k++) {
                trace("\n    ");
                trace_vec("x", x + 3 * k);
                trace(" r = %.17g ", r[k]);
                trace_vec("v", v + 3 * k);
            }
        }
        c->st = demill_particles_add(c->w, m, n, x, r, no_v ? NULL : v, flags, no_ids ? NULL : ids);
        for (size_t k = 0; c->st == DEMILL_OK && !no_ids && k < n && k < 4; k++)
            pool_add(ids[k]);
    }
    free(x);
    free(r);
    free(v);
    free(ids);
}

static void op_particles_remove(call *c)
{
    const uint8_t b = byte();
    if (b & 0x80) {
        const size_t n = count();
        trace("demill_particles_remove(w, %zu, NULL)", n);
        c->st = demill_particles_remove(c->w, n, NULL);
        return;
    }
    const size_t n = b % 9;
    demill_id ids[8];
    trace("demill_particles_remove(w, %zu, {", n);
    for (size_t k = 0; k < n; k++) {
        ids[k] = id_named(c, DEMILL_KIND_PARTICLE);
        trace(" 0x%llx", (unsigned long long)ids[k]);
    }
    trace(" })");
    c->st = demill_particles_remove(c->w, n, ids);
}

/* A bulk read: out of n + 1 items of `size` each, or NULL; returns the
 * count the call reported through *got (SIZE_MAX when not asked). */
static void check_count(const call *c, const char *what, bool asked, size_t got, size_t want)
{
    if (asked && (c->st == DEMILL_OK || c->st == DEMILL_ERR_BUFFER_TOO_SMALL) && got != want)
        fail("%s reported %zu items, there are %zu", what, got, want);
}

static void op_particles_read(call *c)
{
    const int32_t field = pick(fz_particle_fields, COUNT(fz_particle_fields));
    const uint8_t f = byte();
    const size_t cap = capacity(f, c->np);
    double *out = f & 1 ? NULL : grab(3 * (c->np + 1), sizeof *out);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_particles_read(w, %d, %s, %zu, %s)", (int)field, out ? "out" : "NULL", cap,
          f & 2 ? "NULL" : "&count");
    c->st = demill_particles_read(c->w, field, out, cap, f & 2 ? NULL : &got);
    check_count(c, "demill_particles_read", !(f & 2) && c->k >= 0, got, c->np);
    free(out);
}

static void op_particles_read_ids(call *c)
{
    const int32_t field = pick(fz_id_fields, COUNT(fz_id_fields));
    const uint8_t f = byte();
    const size_t cap = capacity(f, c->np);
    demill_id *out = f & 1 ? NULL : grab(c->np + 1, sizeof *out);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_particles_read_ids(w, %d, %s, %zu, %s)", (int)field, out ? "out" : "NULL", cap,
          f & 2 ? "NULL" : "&count");
    c->st = demill_particles_read_ids(c->w, field, out, cap, f & 2 ? NULL : &got);
    check_count(c, "demill_particles_read_ids", !(f & 2) && c->k >= 0, got, c->np);
    if (c->st == DEMILL_OK && out && field == DEMILL_PARTICLE_ID && c->np &&
        memcmp(out, F.list[c->k][DEMILL_KIND_PARTICLE].id, c->np * sizeof *out))
        fail("demill_particles_read_ids and demill_world_ids list the particles differently");
    free(out);
}

static void op_particles_write(call *c)
{
    const int32_t field = pick(fz_particle_fields, COUNT(fz_particle_fields));
    const uint8_t f = byte();
    const size_t counts[4] = {c->np, c->np ? c->np - 1 : 0, c->np + 1, 0};
    const size_t n = counts[(f >> 1) & 3];
    double *in = grab(3 * (n + 1), sizeof *in);
    const int size = demill_particle_field_size(field) ? demill_particle_field_size(field) : 3;
    size_t got;
    if (c->k >= 0)
        demill_particles_read(c->w, field, in, n, &got); /* as they are, where readable */
    switch ((f >> 3) & 3) {
    case 1: {
        const size_t at = byte() % (size * (n + 1)); /* before num(): the order is the input's */
        in[at] = num();
        break;
    }
    case 2: {
        const double v = num();
        for (size_t i = 0; i < size * n; i++)
            in[i] = v;
        break;
    }
    case 3:
        for (size_t i = 0; i < size * n && F.n; i++)
            in[i] = num();
        break;
    }
    trace("demill_particles_write(w, %d, %s, %zu)", (int)field, f & 1 ? "NULL" : "in", n);
    for (size_t i = 0; i < size * n && F.trace; i++)
        trace(" %.17g", in[i]);
    c->st = demill_particles_write(c->w, field, f & 1 ? NULL : in, n);
    free(in);
}

static void op_particle_get(call *c)
{
    const demill_id p = id_named(c, DEMILL_KIND_PARTICLE);
    const int32_t field = pick(fz_particle_fields, COUNT(fz_particle_fields));
    const bool null_out = byte() & 1;
    double v[3];
    c->query = true;
    trace("demill_particle_get(w, 0x%llx, %d, %s)", (unsigned long long)p, (int)field,
          null_out ? "NULL" : "v");
    c->st = demill_particle_get(c->w, p, field, null_out ? NULL : v);
}

static void op_particle_set(call *c)
{
    const demill_id p = id_named(c, DEMILL_KIND_PARTICLE);
    const int32_t field = pick(fz_particle_fields, COUNT(fz_particle_fields));
    const uint8_t f = byte();
    double v[3] = {0, 0, 0};
    if (c->k >= 0)
        demill_particle_get(c->w, p, field, v);
    if (f & 2) {
        const int at = byte() % 3; /* before num(): the order is the input's */
        v[at] = num();
    } else {
        vec(v);
    }
    trace("demill_particle_set(w, 0x%llx, %d, ", (unsigned long long)p, (int)field);
    trace_vec("in", f & 1 ? NULL : v);
    trace(")");
    c->st = demill_particle_set(c->w, p, field, f & 1 ? NULL : v);
}

/* Whether a world holds WALLS_MAX walls: more are not added (the call is
 * left out). */
static bool walls_full(call *c)
{
    c->skipped = c->k >= 0 && F.list[c->k][DEMILL_KIND_WALL].n >= WALLS_MAX;
    return c->skipped;
}

static void op_wall_add(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const uint8_t f = byte();
    double point[3], normal[3];
    vec(point);
    vec(normal);
    flat(c, point, f & 8);
    flat(c, normal, f & 8);
    demill_id wall = DEMILL_ID_NONE;
    if (walls_full(c))
        return;
    trace("demill_wall_add_plane(w, 0x%llx, ", (unsigned long long)m);
    trace_vec("point", f & 1 ? NULL : point);
    trace(", ");
    trace_vec("normal", f & 2 ? NULL : normal);
    trace(", %s)", f & 4 ? "NULL" : "&wall");
    c->st = demill_wall_add_plane(c->w, m, f & 1 ? NULL : point, f & 2 ? NULL : normal,
                                  f & 4 ? NULL : &wall);
    pool_add(wall);
}

static void op_wall_remove(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    trace("demill_wall_remove(w, 0x%llx)", (unsigned long long)wall);
    c->st = demill_wall_remove(c->w, wall);
}

static void op_wall_motion(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    const uint8_t f = byte();
    double v[3], omega[3], centre[3];
    vec(v);
    vec(omega);
    vec(centre);
    if (f & 8 && c->dim == 2) {
        v[2] = centre[2] = 0.0;
        omega[0] = omega[1] = 0.0;
    }
    trace("demill_wall_set_motion(w, 0x%llx, ", (unsigned long long)wall);
    trace_vec("velocity", f & 1 ? NULL : v);
    trace(", ");
    trace_vec("angular_velocity", f & 2 ? NULL : omega);
    trace(", ");
    trace_vec("centre", f & 4 ? NULL : centre);
    trace(")");
    c->st = demill_wall_set_motion(c->w, wall, f & 1 ? NULL : v, f & 2 ? NULL : omega,
                                   f & 4 ? NULL : centre);
}

static void op_wall_get(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    const int32_t field = pick(fz_wall_fields, COUNT(fz_wall_fields));
    const bool null_out = byte() & 1;
    double v[3];
    c->query = true;
    trace("demill_wall_get(w, 0x%llx, %d, %s)", (unsigned long long)wall, (int)field,
          null_out ? "NULL" : "v");
    c->st = demill_wall_get(c->w, wall, field, null_out ? NULL : v);
}

static void save(demill_world *w, buf *b, const char *what);
static bool same(const buf *a, const buf *b);

/* The number of contacts, asked as a user would (0 if the world cannot say),
 * to size the buffers of a read. The question (like one about the energy
 * stored in the contacts) may rebuild stale neighbour
 * lists, which changes the checkpoint (the storage order, the lists, the
 * count of rebuilds), so the state the call is compared with is taken again
 * after it: only the call itself is judged. */
static size_t contact_count(const call *c)
{
    size_t n = 0;
    if (c->k < 0 || demill_contacts_read(c->w, DEMILL_CONTACT_OVERLAP, NULL, 0, &n) != DEMILL_OK)
        n = 0;
    if (c->k >= 0)
        save(c->w, &F.before[c->k], "before the call");
    return n;
}

static void op_contacts_read(call *c)
{
    const int32_t field = pick(fz_contact_fields, COUNT(fz_contact_fields));
    const uint8_t f = byte();
    const size_t n = contact_count(c), cap = capacity(f, n);
    double *out = f & 1 ? NULL : grab(3 * (n + 1), sizeof *out);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_contacts_read(w, %d, %s, %zu, %s)", (int)field, out ? "out" : "NULL", cap,
          f & 2 ? "NULL" : "&count");
    c->st = demill_contacts_read(c->w, field, out, cap, f & 2 ? NULL : &got);
    check_count(c, "demill_contacts_read", !(f & 2) && c->k >= 0, got, n);
    free(out);
}

static void op_contacts_read_ids(call *c)
{
    const uint8_t f = byte();
    const size_t n = contact_count(c), cap = capacity(f, n);
    demill_id *a = f & 1 ? NULL : grab(n + 1, sizeof *a);
    demill_id *b = f & 16 ? NULL : grab(n + 1, sizeof *b);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_contacts_read_ids(w, %s, %s, %zu, %s)", a ? "a" : "NULL", b ? "b" : "NULL", cap,
          f & 2 ? "NULL" : "&count");
    c->st = demill_contacts_read_ids(c->w, a, b, cap, f & 2 ? NULL : &got);
    check_count(c, "demill_contacts_read_ids", !(f & 2) && c->k >= 0, got, n);
    if (c->st == DEMILL_OK && n) {
        if (a)
            pool_add(a[0]);
        if (b)
            pool_add(b[n - 1]);
    }
    free(a);
    free(b);
}

static void op_energy(call *c)
{
    const int32_t term = pick(fz_energy_terms, COUNT(fz_energy_terms));
    const bool null_out = byte() & 1;
    double v;
    contact_count(c); /* the stored energies are a question about the contacts too */
    c->query = true;
    trace("demill_world_energy(w, %d, %s)", (int)term, null_out ? "NULL" : "&v");
    c->st = demill_world_energy(c->w, term, null_out ? NULL : &v);
}

static void op_drum_create(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const bool null_out = byte() & 1;
    demill_id d = DEMILL_ID_NONE;
    trace("demill_drum_create(w, 0x%llx, %s)", (unsigned long long)m, null_out ? "NULL" : "&d");
    c->st = demill_drum_create(c->w, m, null_out ? NULL : &d);
    pool_add(d);
}

static void op_drum_remove(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    trace("demill_drum_remove(w, 0x%llx)", (unsigned long long)d);
    c->st = demill_drum_remove(c->w, d);
}

static void op_drum_set(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const int32_t key = pick(fz_drum_keys, COUNT(fz_drum_keys));
    const double v = num();
    trace("demill_drum_set(w, 0x%llx, %d, %.17g)", (unsigned long long)d, (int)key, v);
    c->st = demill_drum_set(c->w, d, key, v);
}

static void op_drum_get(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const int32_t key = pick(fz_drum_keys, COUNT(fz_drum_keys));
    const bool null_out = byte() & 1;
    double v;
    c->query = true;
    trace("demill_drum_get(w, 0x%llx, %d, %s)", (unsigned long long)d, (int)key,
          null_out ? "NULL" : "&v");
    c->st = demill_drum_get(c->w, d, key, null_out ? NULL : &v);
}

static void op_drum_add_lifter(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const double angle = num(), height = num(), width = num(), face = num();
    trace("demill_drum_add_lifter(w, 0x%llx, %.17g, %.17g, %.17g, %.17g)", (unsigned long long)d,
          angle, height, width, face);
    c->st = demill_drum_add_lifter(c->w, d, angle, height, width, face);
}

static void op_drum_lifter_get(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const uint32_t index = (uint32_t)count();
    const int32_t field = pick(fz_lifter_fields, COUNT(fz_lifter_fields));
    const bool null_out = byte() & 1;
    double v[3];
    c->query = true;
    trace("demill_drum_lifter_get(w, 0x%llx, %u, %d, %s)", (unsigned long long)d, (unsigned)index,
          (int)field, null_out ? "NULL" : "v");
    c->st = demill_drum_lifter_get(c->w, d, index, field, null_out ? NULL : v);
}

/* The sites of the lattice a fill places particles of largest diameter d
 * on (spacing 1.04 d; demill_drum_fill()), with the spacing a. */
static double fill_sites(const call *c, double D, double L, double a)
{
    const double xy = 2.0 * floor(0.5 * D / a) + 1.0;
    return xy * xy * (c->dim == 3 ? 2.0 * floor(0.5 * L / a) + 1.0 : 1.0);
}

/* Volume (2D: area) and mass of a particle of diameter d. */
static double fill_measure(const call *c, double d)
{
    return c->dim == 3 ? PI / 6.0 * d * d * d : PI / 4.0 * d * d;
}

static double fill_mass(const call *c, double rho, double d)
{
    const double t = world_value(c, DEMILL_WORLD_DISC_THICKNESS);
    return rho * (c->dim == 2 && t > 0.0 ? PI / 4.0 * d * d * t : PI / 6.0 * d * d * d);
}

/* The smallest and largest diameter a distribution's params name; false
 * if they name none (the library must refuse them). */
static bool size_range(int32_t dist, const double *p, size_t np, double *dmin, double *dmax)
{
    *dmin = INFINITY;
    *dmax = 0.0;
    if (!p)
        return false;
    if (dist == DEMILL_SIZES_CLASSES) {
        for (size_t k = 0; k + 1 < np; k += 2)
            if (p[k] > 0.0 && isfinite(p[k])) {
                *dmin = fmin(*dmin, p[k]);
                *dmax = fmax(*dmax, p[k]);
            }
    } else if (np == 4 && p[2] > 0.0 && p[3] > p[2] && isfinite(p[3])) {
        *dmin = p[2];
        *dmax = p[3];
    }
    return *dmax > 0.0;
}

/* Whether the harness leaves out a fill that the library would take and
 * that would place more than a few hundred particles or search more than
 * 10^5 lattice sites, which takes long. Bounds come from the smallest and
 * largest diameter the distribution names, the drum and the density. A fill
 * the library must refuse is always made: bad arguments, and targets beyond
 * what a world holds or lattices beyond 2^30 sites (demill_drum_fill()),
 * which once ran for days. */
static bool fill_cap(const call *c, demill_id drum, demill_id mat, int32_t dist, const double *p,
                     size_t np, int32_t target, double value)
{
    double D, L, rho, porosity;
    if (c->k < 0 || !p || !isfinite(value) || !(value > 0.0) ||
        demill_drum_get(c->w, drum, DEMILL_DRUM_DIAMETER, &D) ||
        demill_drum_get(c->w, drum, DEMILL_DRUM_LENGTH, &L) ||
        demill_drum_get(c->w, drum, DEMILL_DRUM_FILL_POROSITY, &porosity) ||
        demill_material_get(c->w, mat, DEMILL_MATERIAL_DENSITY, &rho))
        return false;
    double dmin, dmax;
    if (!size_range(dist, p, np, &dmin, &dmax))
        return false;
    const double capacity = PI / 4.0 * D * D * (c->dim == 3 ? L : 1.0);
    const double fewest = target == DEMILL_FILL_MASS ? value / fill_mass(c, rho, dmax)
                          : target == DEMILL_FILL_FRACTION
                              ? value * capacity * (1.0 - porosity) / fill_measure(c, dmax)
                              : value;
    if (fill_sites(c, D, L, 1.1 * dmax) > 0x1p30 || fewest > 1.01 * (UINT32_MAX / 4))
        return false;
    const double most = 40.0 + (target == DEMILL_FILL_MASS ? value / fill_mass(c, rho, dmin)
                                : target == DEMILL_FILL_FRACTION
                                    ? value * capacity / fill_measure(c, dmin)
                                    : value);
    return !(fill_sites(c, D, L, dmin) <= 1e5) || !(most + (double)c->np <= PARTICLES_MAX);
}

static void op_drum_fill(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM), m = id_named(c, DEMILL_KIND_MATERIAL);
    const int32_t dist = pick(fz_distributions, COUNT(fz_distributions));
    const uint8_t f = byte();
    double params[8];
    size_t np;
    if (f & 1) {
        np = count();
    } else {
        np = byte() % 9;
        for (size_t k = 0; k < np; k++)
            params[k] = num();
    }
    const int32_t target = pick(fz_fill_targets, COUNT(fz_fill_targets));
    const double value = num();
    const uint64_t seed = byte();
    static const size_t caps[4] = {0, 1, 8, PARTICLES_MAX};
    demill_id ids[PARTICLES_MAX];
    const size_t cap = caps[(f >> 2) & 3];
    size_t added = SIZE_MAX;
    if (fill_cap(c, d, m, dist, f & 1 ? NULL : params, np, target, value)) {
        c->skipped = true;
        return;
    }
    trace("demill_drum_fill(w, 0x%llx, 0x%llx, %d, ", (unsigned long long)d, (unsigned long long)m,
          (int)dist);
    for (size_t k = 0; !(f & 1) && k < np; k++)
        trace("%s%.17g", k ? ", " : "{", params[k]);
    trace("%s, %zu, %d, %.17g, %llu, %s, %zu, &added)", f & 1 ? "NULL" : np ? "}" : "{}", np,
          (int)target, value, (unsigned long long)seed, f & 2 ? "NULL" : "ids", cap);
    c->st = demill_drum_fill(c->w, d, m, dist, f & 1 ? NULL : params, np, target, value, seed,
                             f & 2 ? NULL : ids, cap, &added);
    if (c->st == DEMILL_OK && !(f & 2) && added)
        pool_add(ids[0]);
}

static void op_spectrum_start(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const uint8_t f = byte();
    double edges[8];
    size_t ne;
    if (f & 1) {
        ne = count();
    } else {
        ne = byte() % 9;
        for (size_t k = 0; k < ne; k++)
            edges[k] = num();
    }
    uint64_t bins = count();
    if (bins > BINS_MAX && bins <= 10000)
        bins %= BINS_MAX + 1;
    const double e_min = num(), e_max = f & 2 ? nextafter(e_min, INFINITY) : num();
    trace("demill_drum_spectrum_start(w, 0x%llx, %zu, ", (unsigned long long)d, ne);
    for (size_t k = 0; !(f & 1) && k < ne; k++)
        trace("%s%.17g", k ? ", " : "{", edges[k]);
    trace("%s, %llu, %.17g, %.17g)", f & 1 ? "NULL" : ne ? "}" : "{}", (unsigned long long)bins,
          e_min, e_max);
    c->st = demill_drum_spectrum_start(c->w, d, ne, f & 1 ? NULL : edges, (uint32_t)bins, e_min,
                                       e_max);
}

/* A drum's counters read through `read` (demill_drum_spectrum() and the
 * like), with a buffer, a capacity and a count as the next byte asks;
 * returns the buffer (NULL if none was passed; the caller frees it), with
 * the count the library gave before into *n and the capacity into *cap. */
typedef demill_status (*counters_fn)(demill_world *, demill_id, uint64_t *, size_t, size_t *);
static uint64_t *read_counters(call *c, const char *name, counters_fn read, size_t *n,
                               size_t *cap)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const uint8_t f = byte();
    *n = 0;
    if (c->k >= 0 && read(c->w, d, NULL, 0, n) != DEMILL_OK)
        *n = 0;
    *cap = capacity(f, *n);
    uint64_t *out = f & 1 ? NULL : grab(*n + 1, sizeof *out);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("%s(w, 0x%llx, %s, %zu, %s)", name, (unsigned long long)d, out ? "out" : "NULL", *cap,
          f & 2 ? "NULL" : "&count");
    c->st = read(c->w, d, out, *cap, f & 2 ? NULL : &got);
    check_count(c, name, !(f & 2) && *n, got, *n);
    return out;
}

static void op_spectrum_read(call *c)
{
    size_t n, cap;
    free(read_counters(c, "demill_drum_spectrum", demill_drum_spectrum, &n, &cap));
}

/* The steps the harness asks for: up to STEPS_MAX, or more when the progress
 * callback will stop the run within STEPS_MAX steps. */
static uint64_t capped_steps(const call *c, uint64_t steps)
{
    const progress *p = c->k >= 0 ? &F.prog[c->k] : NULL;
    if (steps <= STEPS_MAX || !p || (p->set && p->stop_at && p->every <= STEPS_MAX / p->stop_at))
        return steps;
    return steps % (STEPS_MAX + 1);
}

/* Whether a world's feeds have filled it beyond twice PARTICLES_MAX: it is
 * no longer stepped (the call is left out). A feed inserts a bounded number
 * of particles (feed_cap()) unless its material is made lighter after. */
static bool feeds_full(call *c)
{
    c->skipped = c->k >= 0 && F.list[c->k][DEMILL_KIND_FEED].n && c->np > 2 * PARTICLES_MAX;
    return c->skipped;
}

static void op_step(call *c)
{
    const uint64_t steps = capped_steps(c, count());
    c->stepping = c->one_run = true;
    c->watchdog = world_value(c, DEMILL_WORLD_WATCHDOG) != 0.0;
    c->steps_before = world_value(c, DEMILL_WORLD_STEP_COUNT);
    if (feeds_full(c))
        return;
    trace("demill_world_step(w, %llu)", (unsigned long long)steps);
    c->st = demill_world_step(c->w, steps);
}

/* Whether the harness leaves out a settle the library would take and run
 * for more than 64 steps. One it must refuse is always made: bad arguments,
 * more than 1e18 steps, a clock the time step no longer advances
 * (demill_world_settle(); a settle at t = 1e15 s once never returned). */
static bool settle_cap(const call *c, double max_time)
{
    if (c->k < 0 || !isfinite(max_time) || !(max_time > 0.0))
        return false;
    const double steps = max_time / world_value(c, DEMILL_WORLD_TIME_STEP);
    return steps > 64.0 && steps < 1e18;
}

static void op_settle(call *c)
{
    const double max_time = num(), e = num();
    const bool null_out = byte() & 1;
    int32_t settled;
    c->stepping = true;
    c->watchdog = world_value(c, DEMILL_WORLD_WATCHDOG) != 0.0;
    c->steps_before = world_value(c, DEMILL_WORLD_STEP_COUNT);
    if (settle_cap(c, max_time)) {
        c->skipped = true;
        return;
    }
    if (feeds_full(c))
        return;
    trace("demill_world_settle(w, %.17g, %.17g, %s)", max_time, e, null_out ? "NULL" : "&settled");
    c->st = demill_world_settle(c->w, max_time, e, null_out ? NULL : &settled);
}

static void op_suggest(call *c)
{
    const double v = num(), spc = num();
    const uint8_t f = byte();
    double dt, crit, contact;
    c->query = true;
    trace("demill_world_suggest_time_step(w, %.17g, %.17g, %s, %s, %s)", v, spc,
          f & 1 ? "NULL" : "&dt", f & 2 ? "NULL" : "&critical", f & 4 ? "NULL" : "&contact");
    c->st = demill_world_suggest_time_step(c->w, v, spc, f & 1 ? NULL : &dt, f & 2 ? NULL : &crit,
                                           f & 4 ? NULL : &contact);
    if (c->st == DEMILL_OK && !(f & 7) && !(dt > 0.0 && dt <= crit && isfinite(contact)))
        fail("suggested time step %.17g with stability limit %.17g and contact time %.17g", dt,
             crit, contact);
}

static void op_suggest_apply(call *c)
{
    const double v = num(), spc = num();
    double dt;
    trace("demill_world_suggest_time_step(w, %.17g, %.17g, &dt, NULL, NULL)", v, spc);
    c->st = demill_world_suggest_time_step(c->w, v, spc, &dt, NULL, NULL);
    if (c->st != DEMILL_OK)
        return;
    trace(" = 0; demill_world_set(w, DEMILL_WORLD_TIME_STEP, %.17g)", dt);
    c->st = demill_world_set(c->w, DEMILL_WORLD_TIME_STEP, dt);
}

static void op_snapshot_take(call *c)
{
    const int slot = byte() & 1;
    const bool null_out = byte() & 1;
    demill_snapshot *s = NULL;
    c->query = true;
    trace("demill_snapshot_take(w, %s)", null_out ? "NULL" : "&snap");
    c->st = demill_snapshot_take(c->w, null_out ? NULL : &s);
    if (s) {
        demill_snapshot_free(F.snap[slot]);
        F.snap[slot] = s;
    }
}

static void op_snapshot_restore(call *c)
{
    const int which = byte() & 3;
    const demill_snapshot *s = which < 2    ? F.snap[which]
                               : which == 2 ? NULL
                                            : (demill_snapshot *)fake_object;
    c->other_handle = which == 3;
    trace("demill_snapshot_restore(w, %s)", which == 3 ? "fake" : s ? "snap" : "NULL");
    c->st = demill_snapshot_restore(c->w, s);
}

static void op_snapshot_free(call *c)
{
    const int slot = byte() & 1;
    c->worldless = true;
    trace("demill_snapshot_free(snap%d)", slot);
    demill_snapshot_free(F.snap[slot]);
    F.snap[slot] = NULL;
}

static void op_buffer_transfer(call *c)
{
    const int j = byte() & 1;
    const uint8_t f = byte();
    buf *src = &F.again;
    save(F.w[j], src, "source");
    if (src->diverged) {
        c->skipped = true;
        return;
    }
    unsigned char *shorter = grab(src->n, 1);
    /* the size asked four ways; the checks of each */
    size_t size = SIZE_MAX;
    demill_status st;
    switch (f & 3) {
    case 1: st = demill_world_save_buffer(F.w[j], shorter, src->n - 1, &size); break;
    case 2: st = demill_world_save_buffer(F.w[j], NULL, 0, &size); break;
    case 3: st = demill_world_save_buffer(F.w[j], NULL, 0, NULL); break;
    default: st = demill_world_save_buffer(F.w[j], src->b, src->n, &size); break;
    }
    static const demill_status want[4] = {DEMILL_OK, DEMILL_ERR_BUFFER_TOO_SMALL, DEMILL_OK,
                                          DEMILL_ERR_NULL_POINTER};
    free(shorter);
    if (st != want[f & 3] || ((f & 3) != 3 && size != src->n))
        fail("demill_world_save_buffer (way %d) gave %d and size %zu for %zu bytes", f & 3,
             (int)st, size, src->n);
    size_t n = src->n;
    const void *b = src->b;
    switch ((f >> 2) % 5) {
    case 1: n = count() % (n + 1); break;
    case 2: {
        const size_t at = count() % n;
        src->b[at] ^= byte() | 1;
        break;
    }
    case 3: b = NULL; break;
    case 4: n = 0; break;
    }
    trace("demill_world_load_buffer(w, checkpoint of w%d%s, %zu)", j,
          (f >> 2) % 5 == 2 ? " with a byte changed" : "", n);
    c->st = demill_world_load_buffer(c->w, b, n);
    if ((f >> 2) % 5 == 0 && c->k >= 0 && c->st != DEMILL_OK)
        fail("demill_world_load_buffer refused a checkpoint the library wrote: %s",
             demill_world_last_error(c->w));
}

static const char *path(uint8_t b, const char *name)
{
    static char p[128];
    switch (b % 6) {
    case 0: snprintf(p, sizeof p, "%s/%s", F.dir, name); return p;
    case 1: return NULL;
    case 2: return "";
    case 3: return "/nonexistent-directory/file";
    case 4: return F.dir; /* a directory */
    default: snprintf(p, sizeof p, "%s/garbage", F.dir); return p;
    }
}

static void op_file_save(call *c)
{
    const char *p = path(byte(), "checkpoint");
    c->query = true;
    trace("demill_world_save(w, \"%s\")", p ? p : "(NULL)");
    c->st = demill_world_save(c->w, p);
}

static void op_file_load(call *c)
{
    const char *p = path(byte(), "checkpoint");
    trace("demill_world_load(w, \"%s\")", p ? p : "(NULL)");
    c->st = demill_world_load(c->w, p);
}

static int32_t on_progress(void *user, uint64_t done, uint64_t total, double time, double rate)
{
    progress *p = user;
    p->reports++;
    double t = NAN;
    demill_world_get(p->w, DEMILL_WORLD_TIME, &t);
    if (!done || done > total || (done % p->every && done != total) || t != time ||
        !(rate >= 0.0 && rate < INFINITY))
        fail("progress report %llu of %llu steps (every %llu) at t = %.17g (world: %.17g), "
             "%g steps/s",
             (unsigned long long)done, (unsigned long long)total, (unsigned long long)p->every,
             time, t, rate);
    if (p->read) {
        size_t n;
        demill_particles_read(p->w, DEMILL_PARTICLE_VELOCITY, NULL, 0, &n);
    }
    return p->stop_at && p->reports >= p->stop_at;
}

static void op_progress(call *c)
{
    const uint8_t f = byte();
    const uint64_t every = count();
    const uint32_t stop_at = byte();
    progress *p = &F.prog[c->k < 0 ? 0 : c->k];
    c->query = true; /* the callback is not part of the state */
    trace("demill_world_set_progress(w, %s, p, %llu) stopping at report %u", f & 1 ? "NULL" : "fn",
          (unsigned long long)every, (unsigned)stop_at);
    c->st = demill_world_set_progress(c->w, f & 1 ? NULL : on_progress, p, every);
    if (c->st == DEMILL_OK && c->k >= 0) {
        p->set = !(f & 1);
        p->every = every;
        p->stop_at = stop_at;
        p->read = f & 2;
    }
}

static void op_ids(call *c)
{
    const int32_t kind = pick(fz_kinds, COUNT(fz_kinds));
    const uint8_t f = byte();
    const size_t n = c->k >= 0 && kind >= DEMILL_KIND_MATERIAL && kind <= DEMILL_KIND_BODY
                         ? F.list[c->k][kind].n : 0;
    const size_t cap = capacity(f, n);
    demill_id *out = f & 1 ? NULL : grab(n + 1, sizeof *out);
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_world_ids(w, %d, %s, %zu, %s)", (int)kind, out ? "out" : "NULL", cap,
          f & 2 ? "NULL" : "&count");
    c->st = demill_world_ids(c->w, kind, out, cap, f & 2 ? NULL : &got);
    check_count(c, "demill_world_ids", !(f & 2) && c->k >= 0, got, n);
    free(out);
}

static void op_vtk_particles(call *c)
{
    const char *p = path(byte(), "particles.vtu");
    c->query = true;
    trace("demill_vtk_write_particles(w, \"%s\")", p ? p : "(NULL)");
    c->st = demill_vtk_write_particles(c->w, p);
}

static void op_vtk_walls(call *c)
{
    const char *p = path(byte(), "walls.vtp");
    c->query = true;
    trace("demill_vtk_write_walls(w, \"%s\")", p ? p : "(NULL)");
    c->st = demill_vtk_write_walls(c->w, p);
}

static void op_vtk_series(call *c)
{
    const int action = byte() & 3;
    const char *p = path(byte(), "series");
    const bool null_out = byte() & 1;
    c->query = true;
    switch (action) {
    case 0: {
        demill_vtk_series *s = NULL;
        trace("demill_vtk_series_open(w, \"%s\", %s)", p ? p : "(NULL)", null_out ? "NULL" : "&s");
        c->st = demill_vtk_series_open(c->w, p, null_out ? NULL : &s);
        if (s) {
            demill_vtk_series_close(F.series);
            F.series = s;
        }
        break;
    }
    case 1:
    case 3:
        trace("demill_vtk_series_write(w, %s)", action == 3 || !F.series ? "NULL" : "series");
        c->st = demill_vtk_series_write(c->w, action == 3 ? NULL : F.series);
        break;
    default:
        c->worldless = true;
        trace("demill_vtk_series_close(series)");
        demill_vtk_series_close(F.series);
        F.series = NULL;
    }
}

/* The functions that take no world, and demill_world_last_error(). */
static void op_stateless(call *c)
{
    const uint8_t low = byte(); /* in a statement of its own: the order is the input's */
    const int32_t key = (int32_t)(int16_t)(low | byte() << 8);
    const uint8_t b = byte();
    const demill_id id = raw64();
    c->worldless = true;
    trace("the functions without a world on %d, %u, 0x%llx", (int)key, (unsigned)b,
          (unsigned long long)id);
    double lo = NAN, hi = NAN, def = NAN;
    const demill_status st = demill_param_bounds(key, &lo, &hi, &def);
    const char *name = demill_param_name(key), *unit = demill_param_unit(key);
    if ((st == DEMILL_OK) != (name != NULL) || (st == DEMILL_OK) != (unit != NULL) ||
        (st == DEMILL_OK && !(lo <= def && def <= hi)) ||
        (st != DEMILL_OK && st != DEMILL_ERR_UNKNOWN_KEY))
        fail("parameter %d: bounds %d [%g, %g] default %g, name %s, unit %s", (int)key, (int)st,
             lo, hi, def, name ? name : "NULL", unit ? unit : "NULL");
    if (demill_param_bounds(key, NULL, NULL, NULL) != st)
        fail("demill_param_bounds(%d) with NULL outputs gave another status", (int)key);
    const int kind = demill_id_kind(id);
    if (kind < DEMILL_KIND_NONE || kind > DEMILL_KIND_CLUMP)
        fail("demill_id_kind(0x%llx) = %d", (unsigned long long)id, kind);
    const int32_t ps = demill_particle_field_size(key), cs = demill_contact_field_size(key);
    if ((ps != 0 && ps != 1 && ps != 3) || (cs != 0 && cs != 1 && cs != 3))
        fail("field sizes %d, %d for field %d", (int)ps, (int)cs, (int)key);
    if (!demill_strerror(key) || !demill_strerror((int32_t)id) || !demill_version_string())
        fail("a static string is NULL");
    const uint32_t v = (uint32_t)id;
    const demill_status cv = demill_check_version(v);
    if (cv != DEMILL_OK && cv != DEMILL_ERR_VERSION)
        fail("demill_check_version(%u) = %d", (unsigned)v, (int)cv);
    if (demill_check_version(demill_version_number()) != DEMILL_OK)
        fail("the library is not compatible with itself");
    const demill_world *w = b % 3 == 0   ? NULL
                            : b % 3 == 1 ? (demill_world *)fake_object
                                         : F.w[b & 1];
    if (!demill_world_last_error(w))
        fail("demill_world_last_error gave NULL");
}

/* ---- the drum's impacts and a grinding object ------------------------------ */

static void op_impacts_start(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM), m = id_named(c, DEMILL_KIND_MATERIAL);
    const double top = num();
    const uint64_t classes = count();
    uint64_t bins = count();
    if (bins > BINS_MAX && bins <= 10000)
        bins %= BINS_MAX + 1;
    const double e_min = num(), e_max = num();
    trace("demill_drum_impacts_start(w, 0x%llx, 0x%llx, %.17g, %llu, %llu, %.17g, %.17g)",
          (unsigned long long)d, (unsigned long long)m, top, (unsigned long long)classes,
          (unsigned long long)bins, e_min, e_max);
    c->st = demill_drum_impacts_start(c->w, d, m, top, (uint32_t)classes, (uint32_t)bins, e_min,
                                      e_max);
    if (c->st == DEMILL_OK && (classes < 2 || classes > 200 || bins < 1 || bins > 10000))
        fail("demill_drum_impacts_start took %llu classes and %llu bins",
             (unsigned long long)classes, (unsigned long long)bins);
}

static void op_impacts_read(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const uint8_t f = byte();
    size_t n = 0;
    if (c->k >= 0 && demill_drum_impacts(c->w, d, NULL, 0, &n, NULL) != DEMILL_OK)
        n = 0;
    const size_t cap = capacity(f, n);
    uint64_t *out = f & 1 ? NULL : grab(n + 1, sizeof *out);
    size_t got = SIZE_MAX;
    double time = NAN;
    c->query = true;
    trace("demill_drum_impacts(w, 0x%llx, %s, %zu, %s, %s)", (unsigned long long)d,
          out ? "out" : "NULL", cap, f & 2 ? "NULL" : "&count", f & 16 ? "NULL" : "&time");
    c->st = demill_drum_impacts(c->w, d, out, cap, f & 2 ? NULL : &got, f & 16 ? NULL : &time);
    check_count(c, "demill_drum_impacts", !(f & 2) && n, got, n);
    if (c->st == DEMILL_OK && !(f & 16) && !(time >= 0.0 && isfinite(time)))
        fail("demill_drum_impacts gave the time %g", time);
    free(out);
}

static void op_impacts_particles(call *c)
{
    size_t n, cap;
    uint64_t *out = read_counters(c, "demill_drum_impacts_particles",
                                  demill_drum_impacts_particles, &n, &cap);
    if (c->st == DEMILL_OK && out && cap >= n) {
        uint64_t sum = 0;
        for (size_t i = 0; i < n; i++)
            sum += out[i];
        if (sum > c->np)
            fail("demill_drum_impacts_particles counted %llu particles of %zu",
                 (unsigned long long)sum, c->np);
    }
    free(out);
}

/* Everything a grinding object tells through its reads, to compare its
 * states: its classes, rates, appearance, product and time, and what its
 * model gives (status and values) at a few points. */
static void grinding_state(demill_grinding *g, buf *b)
{
    b->n = 0;
    b->diverged = false;
    if (!g)
        return;
    size_t nc = 0, nb = 0, got;
    demill_grinding_rates(g, NULL, 0, &nc);
    demill_grinding_appearance(g, NULL, 0, &nb);
    const size_t len = (4 * nc + nb + 24) * sizeof(double);
    if (len > b->cap) {
        unsigned char *p = realloc(b->b, len);
        if (!p)
            abort();
        b->b = p;
        b->cap = len;
    }
    memset(b->b, 0, len); /* a read that fails writes nothing: compare zeros, not leftovers */
    double *v = (double *)b->b, *end = v;
    demill_grinding_sizes(g, end, nc + 1, &got), end += nc + 1;
    demill_grinding_rates(g, end, nc, &got), end += nc;
    demill_grinding_appearance(g, end, nb, &got), end += nb;
    demill_grinding_product(g, end, nc, &got), end += nc;
    demill_grinding_time(g, end++);
    const double top = v[0];
    end[0] = demill_grinding_t10(g, top / 2, 100.0, end + 1);
    end += 2;
    end[0] = demill_grinding_tn(g, 20.0, end + 1);
    end += 6;
    end[0] = demill_grinding_broken_fraction(g, top / 2, 100.0, 3, end + 1);
    end += 2;
    end[0] = demill_grinding_passing(g, top / 4, end + 1);
    end += 2;
    b->n = (size_t)((unsigned char *)end - b->b);
}

static size_t grinding_classes(void)
{
    size_t n = 0;
    if (F.g)
        demill_grinding_rates(F.g, NULL, 0, &n);
    return n;
}

/* The values of FZ_GRIND_FEED, _RATES and _APPEARANCE (api_ops.h): returns
 * the array (NULL if the flags ask) and sets *n to their number. */
static double *grinding_values(uint8_t f, int what, size_t *n)
{
    const size_t nc = grinding_classes(), want = what == FZ_GRIND_APPEARANCE ? nc * nc : nc;
    static const int delta[4] = {0, -1, 1, 0};
    *n = (f & 3) == 3 ? 0 : want + (size_t)delta[f & 3];
    if (!want && (f & 3) == 1)
        *n = 0;
    if (f & 4)
        return NULL;
    double *v = grab(*n + 1, sizeof *v);
    const int fill = (f >> 3) & 3;
    const double one = fill == 1 ? num() : 0.0;
    for (size_t i = 0; i < *n; i++) {
        if (fill == 0)
            v[i] = num();
        else if (fill == 1)
            v[i] = one;
        else if (what == FZ_GRIND_FEED)
            v[i] = 1.0;
        else if (what == FZ_GRIND_RATES)
            v[i] = i + 1 < nc ? (double)(i + 1) : 0.0;
        else /* b[r * nc + col]: all of class col into class col + 1 */
            v[i] = nc && i / nc == i % nc + 1 && i % nc + 1 < nc ? 1.0 : 0.0;
    }
    if (fill == 3 && *n) {
        const size_t which = byte() % *n;
        v[which] = num();
    }
    return v;
}

/* A t-family table of 6 rows (t10, t2, t4, t25, t50, t75), then rows that
 * break its rules, for FZ_GRIND_MODEL: rows 6 valid, 1 too few, 2 valid,
 * 101 too many (the array holds 101). */
static double tfamily[101 * 6];

static void init_tfamily(void)
{
    static const double rows[6][6] = {
        {1, 4, 2.5, 0.4, 0.2, 0.15}, {10, 32, 19, 4.5, 2.5, 1.8}, {20, 55, 36, 9, 5, 3.6},
        {30, 72, 52, 14, 8, 5.6},    {45, 88, 72, 22, 12, 8.5},   {60, 97, 88, 31, 18, 13}};
    for (size_t i = 0; i < 101; i++)
        for (int j = 0; j < 6; j++)
            tfamily[6 * i + j] = rows[i % 6][j];
}

static void op_grinding(call *c)
{
    const uint8_t which = byte() % 7, what = byte() % FZ_GRIND_CALLS;
    demill_grinding *g = which < 4    ? F.g
                         : which == 4 ? NULL
                         : which == 5 ? (demill_grinding *)fake_object
                                      : (demill_grinding *)F.w[0];
    const bool live = which < 4 && F.g;
    c->worldless = what != FZ_GRIND_FROM_DRUM;
    c->query = true; /* no grinding call changes a world */
    grinding_state(F.g, &F.gbefore);
    bool reads = false;
    double mass_before = 0.0;
    if (what == FZ_GRIND_RUN && live) {
        size_t n = grinding_classes(), got;
        double *p = grab(n, sizeof *p);
        demill_grinding_product(F.g, p, n, &got);
        for (size_t i = 0; i < n; i++)
            mass_before += p[i];
        free(p);
    }
    trace("grinding %s: ", which < 4 ? (F.g ? "g" : "g (none)") : which == 4 ? "NULL"
                           : which == 5 ? "fake" : "a world");
    switch (what) {
    case FZ_GRIND_CREATE: {
        const double top = num();
        const uint64_t classes = count();
        const bool null_out = byte() & 1;
        demill_grinding *out = (demill_grinding *)fake_object;
        trace("demill_grinding_create(%.17g, %llu, %s)", top, (unsigned long long)classes,
              null_out ? "NULL" : "&g");
        c->st = demill_grinding_create(top, (uint32_t)classes, null_out ? NULL : &out);
        if (c->st == DEMILL_OK && (classes < 2 || classes > 200 || !(top > 0.0)))
            fail("demill_grinding_create took %.17g, %llu", top, (unsigned long long)classes);
        if (!null_out && (c->st == DEMILL_OK) != (out != NULL))
            fail("demill_grinding_create gave %d and %s an object", (int)c->st,
                 out ? "set" : "did not set");
        if (c->st == DEMILL_OK) {
            demill_grinding_destroy(F.g);
            F.g = out;
            trace(" = 0\n");
            return;
        }
        break;
    }
    case FZ_GRIND_FEED:
    case FZ_GRIND_RATES:
    case FZ_GRIND_APPEARANCE: {
        size_t n;
        const uint8_t f = byte();
        double *v = grinding_values(f, what, &n);
        trace("demill_grinding_set_%s(g, %zu, %s)",
              what == FZ_GRIND_FEED ? "feed" : what == FZ_GRIND_RATES ? "rates" : "appearance", n,
              v ? "v" : "NULL");
        c->st = what == FZ_GRIND_FEED    ? demill_grinding_set_feed(g, n, v)
                : what == FZ_GRIND_RATES ? demill_grinding_set_rates(g, n, v)
                                         : demill_grinding_set_appearance(g, n, v);
        free(v);
        break;
    }
    case FZ_GRIND_MODEL: {
        static const size_t nrows[4] = {6, 1, 2, 101};
        const uint8_t f = byte();
        const size_t rows = nrows[(f >> 2) & 3];
        const double *table = f & 2 ? NULL : tfamily;
        if (f & 1) {
            double p[8];
            for (int i = 0; i < 8; i++)
                p[i] = num();
            trace("demill_grinding_set_tavares(g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, "
                  "%.17g, %.17g, %zu, %s)",
                  p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], rows, table ? "t" : "NULL");
            c->st = demill_grinding_set_tavares(g, p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7],
                                                rows, table);
        } else {
            const double a = num(), b = num();
            trace("demill_grinding_set_jk(g, %.17g, %.17g, %zu, %s)", a, b, rows,
                  table ? "t" : "NULL");
            c->st = demill_grinding_set_jk(g, a, b, rows, table);
        }
        break;
    }
    case FZ_GRIND_APPEARANCE_ENERGY: {
        const double e = num();
        trace("demill_grinding_set_appearance_energy(g, %.17g)", e);
        c->st = demill_grinding_set_appearance_energy(g, e);
        break;
    }
    case FZ_GRIND_FROM_IMPACTS: {
        static const int delta[4] = {0, -1, 1, 0};
        const uint8_t cb = byte(), bins = byte() % 5, f = byte();
        const size_t nc = grinding_classes();
        const size_t classes = (cb & 3) == 3 || (!nc && (cb & 3) == 1)
                                   ? 0 : nc + (size_t)delta[cb & 3];
        double *edges = grab(bins + 1u, sizeof(double));
        double *counts = grab(classes * bins + 1, sizeof(double));
        double *parts = grab(classes + 1, sizeof(double));
        if (f & 8) {
            const double e0 = num();
            for (size_t k = 0; k <= bins; k++)
                edges[k] = e0 * pow(10.0, (double)k);
        } else {
            for (size_t k = 0; k <= bins; k++)
                edges[k] = num();
        }
        const double all = f & 16 ? num() : 0.0;
        for (size_t k = 0; k < classes * bins; k++)
            counts[k] = f & 16 ? all : num();
        for (size_t k = 0; k < classes; k++)
            parts[k] = num();
        const double time = num();
        trace("demill_grinding_rates_from_impacts(g, %zu, %u, %s, %s, %s, %.17g)", classes,
              (unsigned)bins, f & 1 ? "NULL" : "edges", f & 2 ? "NULL" : "counts",
              f & 4 ? "NULL" : "particles", time);
        c->st = demill_grinding_rates_from_impacts(g, classes, bins, f & 1 ? NULL : edges,
                                                   f & 2 ? NULL : counts, f & 4 ? NULL : parts,
                                                   time);
        free(edges);
        free(counts);
        free(parts);
        break;
    }
    case FZ_GRIND_FROM_DRUM: {
        const demill_id d = id_named(c, DEMILL_KIND_DRUM);
        if (!live && c->k < 0) { /* two bad objects: the status is the order of the checks' */
            c->skipped = true;
            return;
        }
        c->other_handle = !live;
        c->grinding_message = true;
        trace("demill_grinding_rates_from_drum(g, w, 0x%llx)", (unsigned long long)d);
        c->st = demill_grinding_rates_from_drum(g, c->w, d);
        break;
    }
    case FZ_GRIND_RUN: {
        const double t = num();
        trace("demill_grinding_run(g, %.17g)", t);
        c->st = demill_grinding_run(g, t);
        break;
    }
    default: {
        const uint8_t r = byte() % 11, f = byte();
        const bool null_out = f & 1;
        const size_t nc = grinding_classes();
        const size_t n = r == 4 ? nc + 1 : r == 6 ? nc * nc : nc;
        double *out = grab(n + 6, sizeof *out);
        double *o = null_out ? NULL : out;
        const size_t cap = capacity(f, n);
        size_t got;
        double x, y;
        reads = true;
        switch (r) {
        case 0: c->st = demill_grinding_product(g, o, cap, &got); break;
        case 1: x = num(), c->st = demill_grinding_passing(g, x, o); break;
        case 2: x = num(), c->st = demill_grinding_size_passing(g, x, o); break;
        case 3: c->st = demill_grinding_time(g, o); break;
        case 4: c->st = demill_grinding_sizes(g, o, cap, &got); break;
        case 5: c->st = demill_grinding_rates(g, o, cap, &got); break;
        case 6: c->st = demill_grinding_appearance(g, o, cap, &got); break;
        case 7: x = num(), y = num(), c->st = demill_grinding_t10(g, x, y, o); break;
        case 8: x = num(), c->st = demill_grinding_tn(g, x, o); break;
        case 9:
            x = num(), y = num();
            c->st = demill_grinding_broken_fraction(g, x, y, (uint32_t)count(), o);
            break;
        default: x = num(), y = num(), c->st = demill_grinding_specific_energy(g, x, y, o);
        }
        trace("grinding read %d (%s, capacity %zu)", (int)r, o ? "out" : "NULL", cap);
        if (c->st == DEMILL_OK && (r == 1 || r == 9) && !(out[0] >= 0.0 && out[0] <= 1.0))
            fail("grinding read %d gave the fraction %.17g", (int)r, out[0]);
        if (c->st == DEMILL_OK && r == 2 && !(out[0] > 0.0 && isfinite(out[0])))
            fail("demill_grinding_size_passing gave the size %.17g", out[0]);
        free(out);
    }
    }
    if (live && c->st != DEMILL_OK && what != FZ_GRIND_CREATE) {
        const char *msg = demill_grinding_last_error(F.g);
        trace(" {%s}", msg);
        if (!*msg && (what != FZ_GRIND_FROM_DRUM || (c->k >= 0 && !*demill_world_last_error(c->w))))
            fail("a grinding call failed with %d and left no message", (int)c->st);
    }
    if (!live && c->st != DEMILL_OK && what != FZ_GRIND_CREATE) {
        const demill_status want = g ? DEMILL_ERR_INVALID_HANDLE : DEMILL_ERR_NULL_POINTER;
        if (c->st != want && what != FZ_GRIND_FROM_DRUM)
            fail("a grinding call on a %s object gave %d, not %d", g ? "bad" : "NULL",
                 (int)c->st, (int)want);
    }
    if (!live && c->st == DEMILL_OK && what != FZ_GRIND_CREATE)
        fail("a grinding call on a %s object succeeded", g ? "bad" : "NULL");
    grinding_state(F.g, &F.gafter);
    if ((c->st != DEMILL_OK || reads) && !same(&F.gbefore, &F.gafter))
        fail("a grinding call that %s changed the object (status %d)",
             reads ? "reads" : "failed", (int)c->st);
    if (what == FZ_GRIND_RUN && c->st == DEMILL_OK) {
        size_t n = grinding_classes(), got;
        double *p = grab(n, sizeof *p), mass = 0.0;
        demill_grinding_product(F.g, p, n, &got);
        for (size_t i = 0; i < n; i++)
            mass += p[i];
        free(p);
        if (!(fabs(mass - mass_before) <= 1e-9 * mass_before))
            fail("demill_grinding_run changed the mass from %.17g to %.17g", mass_before, mass);
    }
}

/* ---- geometry, flows and bodies --------------------------------------------- */

#define BODIES_MAX 16      /* bodies per world */
#define FEED_PARTICLES 128 /* particles a feed may insert in its life (at its creation's density) */

static void trace_points(const double *v, size_t n)
{
    for (size_t k = 0; k < n && F.trace; k++) {
        trace("\n    ");
        trace_vec("p", v + 3 * k);
    }
}

static void op_wall_add_mesh(call *c)
{
    /* a box's 12 triangles on its 8 corners (corner k has bit i of k set
     * where its coordinate i is the far one) */
    static const uint8_t box[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6},
                                       {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5},
                                       {0, 1, 5}, {0, 5, 4}, {2, 3, 7}, {2, 7, 6}};
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const uint8_t f = byte();
    double v[3 * 8];
    uint32_t t[3 * 12];
    size_t nv, nt;
    if (f & 8) {
        double corner[3];
        vec(corner);
        const double side = num();
        nv = 8;
        nt = 12;
        for (size_t k = 0; k < 8; k++)
            for (int i = 0; i < 3; i++)
                v[3 * k + i] = corner[i] + (k >> i & 1 ? side : 0.0);
        for (size_t k = 0; k < 3 * 12; k++)
            t[k] = box[k / 3][k % 3];
    } else {
        nv = 1 + byte() % 8;
        for (size_t k = 0; k < nv; k++)
            vec(v + 3 * k);
        nt = byte() % 9;
        for (size_t k = 0; k < 3 * nt; k++) {
            const uint8_t b = byte();
            t[k] = b == 0xff ? UINT32_MAX : b;
        }
    }
    const size_t nv_real = nv, nt_real = nt;
    if (f & 1)
        nv = count();
    if (f & 2)
        nt = count();
    if (walls_full(c))
        return;
    demill_id wall = DEMILL_ID_NONE;
    trace("demill_wall_add_mesh(w, 0x%llx, %zu, %s, %zu, %s, %s) with", (unsigned long long)m, nv,
          f & 1 ? "NULL" : "v", nt, f & 2 ? "NULL" : "t", f & 4 ? "NULL" : "&wall");
    trace_points(v, nv_real);
    for (size_t k = 0; k < 3 * nt_real && F.trace; k++)
        trace("%s%u", k % 3 ? " " : "\n    t ", (unsigned)t[k]);
    c->st = demill_wall_add_mesh(c->w, m, nv, f & 1 ? NULL : v, nt, f & 2 ? NULL : t,
                                 f & 4 ? NULL : &wall);
    pool_add(wall);
}

static void op_wall_add_polyline(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const uint8_t f = byte();
    double v[3 * 8];
    size_t n;
    if (f & 8) {
        double corner[3];
        vec(corner);
        const double side = num();
        n = 4;
        for (size_t k = 0; k < 4; k++) {
            v[3 * k] = corner[0] + ((k + 1) & 2 ? side : 0.0);
            v[3 * k + 1] = corner[1] + (k & 2 ? side : 0.0);
            v[3 * k + 2] = corner[2];
        }
    } else {
        n = byte() % 9;
        for (size_t k = 0; k < n; k++)
            vec(v + 3 * k);
    }
    for (size_t k = 0; k < n; k++)
        flat(c, v + 3 * k, f & 4);
    const size_t n_real = n;
    if (f & 1)
        n = count();
    const int32_t closed = pick(fz_closed, COUNT(fz_closed));
    if (walls_full(c))
        return;
    demill_id wall = DEMILL_ID_NONE;
    trace("demill_wall_add_polyline(w, 0x%llx, %zu, %s, %d, %s) with", (unsigned long long)m, n,
          f & 1 ? "NULL" : "p", (int)closed, f & 2 ? "NULL" : "&wall");
    trace_points(v, n_real);
    c->st = demill_wall_add_polyline(c->w, m, n, f & 1 ? NULL : v, closed, f & 2 ? NULL : &wall);
    pool_add(wall);
}

/* A double as a float of an STL file: beyond the floats, infinite. */
static float stl_float(double x)
{
    return isfinite(x) && fabs(x) > FLT_MAX ? (float)copysign(INFINITY, x) : (float)x;
}

static void op_wall_add_stl(call *c)
{
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const uint8_t f = byte();
    const size_t nt = 1 + byte() % 4;
    double v[4 * 9];
    for (size_t k = 0; k < 3 * nt; k++)
        vec(v + 3 * k);
    const double scale = num();
    double transform[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    for (int i = 0; i < 12 && f & 16; i++)
        transform[i] = num();
    static unsigned char bytes[2048];
    size_t size;
    if (f & 8) {
        memset(bytes, 0, 84);
        for (int i = 0; i < 4; i++)
            bytes[80 + i] = (unsigned char)(nt >> (8 * i));
        size = 84;
        for (size_t k = 0; k < nt; k++) {
            memset(bytes + size, 0, 50);
            for (int i = 0; i < 9; i++) {
                const float x = stl_float(v[9 * k + i]);
                memcpy(bytes + size + 12 + 4 * i, &x, 4);
            }
            size += 50;
        }
    } else {
        int at = snprintf((char *)bytes, sizeof bytes, "solid fuzz\n");
        for (size_t k = 0; k < nt; k++) {
            at += snprintf((char *)bytes + at, sizeof bytes - at,
                           "facet normal 0 0 0\nouter loop\n");
            for (int i = 0; i < 3; i++)
                at += snprintf((char *)bytes + at, sizeof bytes - at, "vertex %.17g %.17g %.17g\n",
                               v[9 * k + 3 * i], v[9 * k + 3 * i + 1], v[9 * k + 3 * i + 2]);
            at += snprintf((char *)bytes + at, sizeof bytes - at, "endloop\nendfacet\n");
        }
        at += snprintf((char *)bytes + at, sizeof bytes - at, "endsolid fuzz\n");
        size = (size_t)at;
    }
    if (f & 32)
        size = count() % (size + 1);
    if (f & 1)
        size = count();
    if (walls_full(c))
        return;
    demill_id wall = DEMILL_ID_NONE;
    trace("demill_wall_add_stl(w, 0x%llx, %s, %zu, %.17g, %s, %s) with the %s triangles",
          (unsigned long long)m, f & 1 ? "NULL" : "bytes", size, scale,
          f & 2 ? "NULL" : f & 16 ? "typed" : "identity", f & 4 ? "NULL" : "&wall",
          f & 8 ? "binary" : "ASCII");
    trace_points(v, 3 * nt);
    c->st = demill_wall_add_stl(c->w, m, f & 1 ? NULL : bytes, size, scale,
                                f & 2 ? NULL : transform, f & 4 ? NULL : &wall);
    pool_add(wall);
}

static void op_wall_mesh_info(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    const uint8_t f = byte();
    size_t nv = SIZE_MAX, ne = SIZE_MAX;
    c->query = true;
    trace("demill_wall_mesh_info(w, 0x%llx, %s, %s)", (unsigned long long)wall,
          f & 1 ? "NULL" : "&nv", f & 2 ? "NULL" : "&ne");
    c->st = demill_wall_mesh_info(c->w, wall, f & 1 ? NULL : &nv, f & 2 ? NULL : &ne);
    if (c->st == DEMILL_OK && ((!(f & 1) && nv < 2) || (!(f & 2) && (ne < 1 || ne == SIZE_MAX))))
        fail("demill_wall_mesh_info gave %zu vertices and %zu elements", nv, ne);
}

static void op_wall_add_finite(call *c)
{
    static const char *const names[4] = {"cylinder", "cone", "disc", "rectangle"};
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    const int kind = byte() % 4;
    const uint8_t f = byte();
    double p[3], a[3], dir[3] = {0, 0, 0}, r1 = 0.0, r2 = 0.0, len = 0.0;
    int32_t caps = 0;
    vec(p);
    vec(a);
    switch (kind) {
    case 0:
        r1 = num();
        len = num();
        caps = pick(fz_caps, COUNT(fz_caps));
        break;
    case 1:
        r1 = num();
        r2 = num();
        len = num();
        caps = pick(fz_caps, COUNT(fz_caps));
        break;
    case 2:
        r1 = num();
        r2 = num();
        break;
    default:
        vec(dir);
        r1 = num();
        r2 = num();
    }
    if (walls_full(c))
        return;
    const double *point = f & 1 ? NULL : p, *axis = f & 2 ? NULL : a, *d = f & 8 ? NULL : dir;
    demill_id wall = DEMILL_ID_NONE, *out = f & 4 ? NULL : &wall;
    trace("demill_wall_add_%s(w, 0x%llx, ", names[kind], (unsigned long long)m);
    trace_vec("point", point);
    trace(", ");
    trace_vec("axis", axis);
    trace(", ");
    if (kind == 3) {
        trace_vec("direction", d);
        trace(", ");
    }
    trace("%.17g, %.17g, %.17g, caps %d, %s)", r1, r2, len, (int)caps, out ? "&wall" : "NULL");
    switch (kind) {
    case 0: c->st = demill_wall_add_cylinder(c->w, m, point, axis, r1, len, caps, out); break;
    case 1: c->st = demill_wall_add_cone(c->w, m, point, axis, r1, r2, len, caps, out); break;
    case 2: c->st = demill_wall_add_disc(c->w, m, point, axis, r1, r2, out); break;
    default: c->st = demill_wall_add_rectangle(c->w, m, point, axis, d, r1, r2, out);
    }
    pool_add(wall);
}

static void op_wall_harmonic(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    const int32_t mode = pick(fz_harmonic_modes, COUNT(fz_harmonic_modes));
    const uint8_t f = byte();
    double axis[3];
    vec(axis);
    const double amplitude = num(), frequency = num(), phase = num();
    if (f & 2 && c->dim == 2) {
        if (mode == DEMILL_HARMONIC_ROTATION)
            axis[0] = axis[1] = 0.0;
        else
            axis[2] = 0.0;
    }
    trace("demill_wall_set_harmonic(w, 0x%llx, %d, ", (unsigned long long)wall, (int)mode);
    trace_vec("axis", f & 1 ? NULL : axis);
    trace(", %.17g, %.17g, %.17g)", amplitude, frequency, phase);
    c->st = demill_wall_set_harmonic(c->w, wall, mode, f & 1 ? NULL : axis, amplitude, frequency,
                                     phase);
}

static void op_wall_surface_velocity(call *c)
{
    const demill_id wall = id_named(c, DEMILL_KIND_WALL);
    const uint8_t f = byte();
    double v[3];
    vec(v);
    flat(c, v, f & 2);
    trace("demill_wall_set_surface_velocity(w, 0x%llx, ", (unsigned long long)wall);
    trace_vec("velocity", f & 1 ? NULL : v);
    trace(")");
    c->st = demill_wall_set_surface_velocity(c->w, wall, f & 1 ? NULL : v);
}

static void op_drum_material(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM);
    const int32_t part = pick(fz_drum_parts, COUNT(fz_drum_parts));
    const uint8_t f = byte();
    if (f & 1) {
        demill_id m = DEMILL_ID_NONE;
        c->query = true;
        trace("demill_drum_get_material(w, 0x%llx, %d, %s)", (unsigned long long)d, (int)part,
              f & 2 ? "NULL" : "&m");
        c->st = demill_drum_get_material(c->w, d, part, f & 2 ? NULL : &m);
        if (c->st == DEMILL_OK && !(f & 2) && !listed(c->k, DEMILL_KIND_MATERIAL, m))
            fail("demill_drum_get_material gave 0x%llx, which names no material of the world",
                 (unsigned long long)m);
        return;
    }
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    trace("demill_drum_set_material(w, 0x%llx, %d, 0x%llx)", (unsigned long long)d, (int)part,
          (unsigned long long)m);
    c->st = demill_drum_set_material(c->w, d, part, m);
}

static void op_drum_attach_wall(call *c)
{
    const demill_id d = id_named(c, DEMILL_KIND_DRUM), wall = id_named(c, DEMILL_KIND_WALL);
    const int32_t part = pick(fz_drum_parts, COUNT(fz_drum_parts));
    trace("demill_drum_attach_wall(w, 0x%llx, 0x%llx, %d)", (unsigned long long)d,
          (unsigned long long)wall, (int)part);
    c->st = demill_drum_attach_wall(c->w, d, wall, part);
}

/* A region of demill/insert.h as an op reads it (api_ops.h, FZ_FILL_REGION). */
typedef struct region {
    int32_t kind;
    double p[8];
    size_t n;
    bool null;
} region;

static void region_arg(const call *c, region *r)
{
    r->kind = pick(fz_regions, COUNT(fz_regions));
    const uint8_t way = byte();
    r->null = (way & 3) == 2;
    r->n = 0;
    if ((way & 3) == 0) {
        r->n = byte() % 9;
        for (size_t k = 0; k < r->n; k++)
            r->p[k] = num();
        return;
    }
    if (r->null) {
        r->n = count();
        return;
    }
    double x[3];
    vec(x);
    const double s = num();
    flat(c, x, way & 4);
    const bool plane = c->dim == 2 && way & 4;
    double *p = r->p;
    memcpy(p, x, sizeof x);
    switch (r->kind) {
    case DEMILL_REGION_DRUM: break;
    case DEMILL_REGION_CYLINDER:
        p[3] = x[0], p[4] = x[1] + s, p[5] = x[2], p[6] = 0.5 * s;
        r->n = 7;
        break;
    case DEMILL_REGION_HALF_SPACE:
        p[3] = 0.0, p[4] = 1.0, p[5] = 0.0;
        r->n = 6;
        break;
    default: /* a box, also for the kinds there are not */
        p[3] = x[0] + s, p[4] = x[1] + s, p[5] = plane ? x[2] : x[2] + s;
        r->n = 6;
    }
    if ((way & 3) == 3 && r->n) {
        const size_t at = byte() % r->n; /* before num(): the order is the input's */
        p[at] = num();
    }
}

static void trace_region(const region *r)
{
    trace("region %d ", (int)r->kind);
    for (size_t k = 0; !r->null && k < r->n; k++)
        trace("%s%.17g", k ? ", " : "{", r->p[k]);
    trace("%s, %zu", r->null ? "NULL" : r->n ? "}" : "{}", r->n);
}

/* The volume (2D: area) of a region a fill or a feed can use; NaN where
 * the library must refuse it. */
static double region_measure(const call *c, const region *r)
{
    const double *p = r->p;
    if (r->null)
        return NAN;
    if (r->kind == DEMILL_REGION_BOX && r->n == 6)
        return (p[3] - p[0]) * (p[4] - p[1]) * (c->dim == 3 ? p[5] - p[2] : 1.0);
    if (r->kind == DEMILL_REGION_CYLINDER && r->n == 7) {
        const double len = sqrt((p[3] - p[0]) * (p[3] - p[0]) + (p[4] - p[1]) * (p[4] - p[1]) +
                                (p[5] - p[2]) * (p[5] - p[2]));
        return c->dim == 3 ? PI * p[6] * p[6] * len : 2.0 * p[6] * len;
    }
    double D, L;
    if (r->kind == DEMILL_REGION_DRUM && c->k >= 0 &&
        !demill_drum_get(c->w, listed_id(c->k, DEMILL_KIND_DRUM, 0), DEMILL_DRUM_DIAMETER, &D) &&
        !demill_drum_get(c->w, listed_id(c->k, DEMILL_KIND_DRUM, 0), DEMILL_DRUM_LENGTH, &L))
        return PI / 4.0 * D * D * (c->dim == 3 ? L : 1.0);
    return NAN;
}

/* Sizes of a distribution as an op reads them (api_ops.h, FZ_FILL_REGION). */
typedef struct sizes {
    int32_t dist;
    double p[8];
    size_t n;
    bool null;
} sizes;

static void sizes_arg(sizes *z)
{
    z->dist = pick(fz_distributions, COUNT(fz_distributions));
    const uint8_t way = byte();
    z->null = false;
    switch (way & 3) {
    case 0:
        z->n = byte() % 9;
        for (size_t k = 0; k < z->n; k++)
            z->p[k] = num();
        break;
    case 1:
        z->p[0] = num();
        z->p[1] = 1.0;
        z->n = 2;
        break;
    case 2: {
        const double d = num();
        z->p[0] = 0.75 * d;
        z->p[1] = z->dist == DEMILL_SIZES_NORMAL ? 0.25 * d : 3.0;
        z->p[2] = 0.5 * d;
        z->p[3] = d;
        z->n = 4;
        break;
    }
    default:
        z->null = true;
        z->n = count();
    }
}

static void trace_sizes(const sizes *z)
{
    trace("distribution %d ", (int)z->dist);
    for (size_t k = 0; !z->null && k < z->n; k++)
        trace("%s%.17g", k ? ", " : "{", z->p[k]);
    trace("%s, %zu", z->null ? "NULL" : z->n ? "}" : "{}", z->n);
}

/* Whether the harness leaves out a fill of a region that the library would
 * take and that could place more particles than a world may hold here (as
 * fill_cap() for the drum); a fill it must refuse is always made. */
static bool region_fill_cap(const call *c, const region *r, demill_id mat, const sizes *z,
                            int32_t target, double value)
{
    double rho, dmin, dmax;
    const double measure = region_measure(c, r);
    if (c->k < 0 || z->null || !isfinite(value) || !(value > 0.0) || !(measure > 0.0) ||
        (target != DEMILL_FILL_COUNT && target != DEMILL_FILL_MASS &&
         target != DEMILL_FILL_FRACTION) ||
        !size_range(z->dist, z->p, z->n, &dmin, &dmax) ||
        demill_material_get(c->w, mat, DEMILL_MATERIAL_DENSITY, &rho))
        return false;
    const double fewest = target == DEMILL_FILL_MASS       ? value / fill_mass(c, rho, dmax)
                          : target == DEMILL_FILL_FRACTION ? value * measure / fill_measure(c, dmax)
                                                           : value;
    if (fewest > 1.01 * (UINT32_MAX / 4))
        return false;
    const double most = 40.0 + (target == DEMILL_FILL_MASS ? value / fill_mass(c, rho, dmin)
                                : target == DEMILL_FILL_FRACTION
                                    ? value * measure / fill_measure(c, dmin)
                                    : value);
    return !(most + (double)c->np <= PARTICLES_MAX);
}

static void op_fill_region(call *c)
{
    region r;
    sizes z;
    region_arg(c, &r);
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    sizes_arg(&z);
    const int32_t target = pick(fz_fill_targets, COUNT(fz_fill_targets));
    const double value = num();
    const uint64_t seed = byte();
    const uint8_t f = byte();
    static const size_t caps[4] = {0, 1, 8, PARTICLES_MAX};
    demill_id ids[PARTICLES_MAX];
    const size_t cap = caps[(f >> 1) & 3];
    size_t added = SIZE_MAX;
    if (region_fill_cap(c, &r, m, &z, target, value)) {
        c->skipped = true;
        return;
    }
    trace("demill_fill_region(w, ");
    trace_region(&r);
    trace(", 0x%llx, ", (unsigned long long)m);
    trace_sizes(&z);
    trace(", %d, %.17g, %llu, %s, %zu, &added)", (int)target, value, (unsigned long long)seed,
          f & 1 ? "NULL" : "ids", cap);
    c->st = demill_fill_region(c->w, r.kind, r.null ? NULL : r.p, r.n, m, z.dist,
                               z.null ? NULL : z.p, z.n, target, value, seed, f & 1 ? NULL : ids,
                               cap, &added);
    if (c->st == DEMILL_OK && !(f & 1) && added)
        pool_add(ids[0]);
}

/* Whether the harness leaves out a feed the library would take that could
 * insert more than FEED_PARTICLES particles in its life (at the density of
 * its material now: one made lighter later inserts more, which stepping
 * bounds, feeds_full()). */
static bool feed_cap(const call *c, demill_id mat, const sizes *z, double rate, double start,
                     double stop)
{
    double rho, dmin, dmax;
    if (c->k < 0 || !isfinite(rate) || !(rate > 0.0) || !isfinite(start) || !(stop > start) ||
        z->null || !size_range(z->dist, z->p, z->n, &dmin, &dmax) ||
        demill_material_get(c->w, mat, DEMILL_MATERIAL_DENSITY, &rho))
        return false;
    return !(rate * (stop - start) / fill_mass(c, rho, dmin) <= FEED_PARTICLES);
}

static void op_feed_create(call *c)
{
    region r;
    sizes z;
    region_arg(c, &r);
    const demill_id m = id_named(c, DEMILL_KIND_MATERIAL);
    sizes_arg(&z);
    const double rate = num();
    const uint8_t f = byte();
    double v[3];
    vec(v);
    flat(c, v, f & 4);
    const double start = num(), stop = num();
    const uint64_t seed = byte();
    if (feed_cap(c, m, &z, rate, start, stop)) {
        c->skipped = true;
        return;
    }
    demill_id feed = DEMILL_ID_NONE;
    trace("demill_feed_create(w, ");
    trace_region(&r);
    trace(", 0x%llx, ", (unsigned long long)m);
    trace_sizes(&z);
    trace(", %.17g, ", rate);
    trace_vec("velocity", f & 1 ? NULL : v);
    trace(", %.17g, %.17g, %llu, %s)", start, stop, (unsigned long long)seed,
          f & 2 ? "NULL" : "&feed");
    c->st = demill_feed_create(c->w, r.kind, r.null ? NULL : r.p, r.n, m, z.dist,
                               z.null ? NULL : z.p, z.n, rate, f & 1 ? NULL : v, start, stop, seed,
                               f & 2 ? NULL : &feed);
    pool_add(feed);
}

static void op_feed_remove(call *c)
{
    const demill_id feed = id_named(c, DEMILL_KIND_FEED);
    trace("demill_feed_remove(w, 0x%llx)", (unsigned long long)feed);
    c->st = demill_feed_remove(c->w, feed);
}

static void op_feed_read(call *c)
{
    const demill_id feed = id_named(c, DEMILL_KIND_FEED);
    const uint8_t f = byte();
    double mass = 0.0, deficit = 0.0;
    uint64_t n = 0;
    c->query = true;
    trace("demill_feed_read(w, 0x%llx, %s, %s, %s)", (unsigned long long)feed,
          f & 1 ? "NULL" : "&mass", f & 2 ? "NULL" : "&count", f & 4 ? "NULL" : "&deficit");
    c->st = demill_feed_read(c->w, feed, f & 1 ? NULL : &mass, f & 2 ? NULL : &n,
                             f & 4 ? NULL : &deficit);
    if (c->st == DEMILL_OK && !(mass >= 0.0 && isfinite(mass) && deficit >= 0.0 &&
                                isfinite(deficit) && (n > 0 || mass == 0.0 || f & 2)))
        fail("demill_feed_read gave the mass %.17g of %llu particles and the deficit %.17g", mass,
             (unsigned long long)n, deficit);
}

static void op_outlet_create(call *c)
{
    region r;
    region_arg(c, &r);
    const uint8_t f = byte();
    double edges[32];
    size_t ne;
    if (f & 1) {
        ne = count();
    } else {
        ne = byte() % 33;
        for (size_t k = 0; k < ne; k++)
            edges[k] = num();
    }
    const double interval = num();
    demill_id outlet = DEMILL_ID_NONE;
    trace("demill_outlet_create(w, ");
    trace_region(&r);
    trace(", %zu, ", ne);
    for (size_t k = 0; !(f & 1) && k < ne; k++)
        trace("%s%.17g", k ? ", " : "{", edges[k]);
    trace("%s, %.17g, %s)", f & 1 ? "NULL" : ne ? "}" : "{}", interval, f & 2 ? "NULL" : "&o");
    c->st = demill_outlet_create(c->w, r.kind, r.null ? NULL : r.p, r.n, ne, f & 1 ? NULL : edges,
                                 interval, f & 2 ? NULL : &outlet);
    pool_add(outlet);
}

static void op_outlet_remove(call *c)
{
    const demill_id outlet = id_named(c, DEMILL_KIND_OUTLET);
    trace("demill_outlet_remove(w, 0x%llx)", (unsigned long long)outlet);
    c->st = demill_outlet_remove(c->w, outlet);
}

static void op_outlet_read(call *c)
{
    const demill_id outlet = id_named(c, DEMILL_KIND_OUTLET);
    const uint8_t f = byte();
    size_t n = 0;
    if (c->k >= 0 && demill_outlet_read(c->w, outlet, NULL, NULL, 0, &n, NULL) != DEMILL_OK)
        n = 0;
    const size_t cap = capacity(f, n);
    uint64_t *counts = f & 1 ? NULL : grab(n + 1, sizeof *counts);
    double *masses = f & 2 ? NULL : grab(n + 1, sizeof *masses), last[3] = {0, 0, 0};
    size_t got = SIZE_MAX;
    c->query = true;
    trace("demill_outlet_read(w, 0x%llx, %s, %s, %zu, %s, %s)", (unsigned long long)outlet,
          counts ? "counts" : "NULL", masses ? "masses" : "NULL", cap, f & 32 ? "NULL" : "&n",
          f & 64 ? "NULL" : "last");
    c->st = demill_outlet_read(c->w, outlet, counts, masses, cap, f & 32 ? NULL : &got,
                               f & 64 ? NULL : last);
    check_count(c, "demill_outlet_read", !(f & 32) && n, got, n);
    if (c->st == DEMILL_OK && (n < 1 || n > 32))
        fail("an outlet has %zu classes", n);
    for (int i = 0; c->st == DEMILL_OK && i < 3; i++)
        if (!(last[i] >= 0.0 && isfinite(last[i])))
            fail("demill_outlet_read gave the last interval's value %d = %.17g", i, last[i]);
    free(counts);
    free(masses);
}

static void op_body_add(call *c)
{
    const double mass = num();
    double x[3];
    vec(x);
    const int32_t axes = byte() & 15;
    const uint32_t flags = (uint32_t)pick(fz_body_flags, COUNT(fz_body_flags));
    const uint8_t f = byte();
    flat(c, x, f & 4);
    if (c->k >= 0 && F.list[c->k][DEMILL_KIND_BODY].n >= BODIES_MAX) {
        c->skipped = true;
        return;
    }
    demill_id body = DEMILL_ID_NONE;
    trace("demill_body_add(w, %.17g, ", mass);
    trace_vec("centre", f & 1 ? NULL : x);
    trace(", %d, 0x%x, %s)", (int)axes, (unsigned)flags, f & 2 ? "NULL" : "&body");
    c->st = demill_body_add(c->w, mass, f & 1 ? NULL : x, axes, flags, f & 2 ? NULL : &body);
    pool_add(body);
}

static void op_body_remove(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY);
    trace("demill_body_remove(w, 0x%llx)", (unsigned long long)body);
    c->st = demill_body_remove(c->w, body);
}

static void op_body_spring(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY);
    const int32_t axis = pick(fz_body_axes, COUNT(fz_body_axes));
    const double k = num(), damping = num(), rest = num();
    trace("demill_body_set_spring(w, 0x%llx, %d, %.17g, %.17g, %.17g)", (unsigned long long)body,
          (int)axis, k, damping, rest);
    c->st = demill_body_set_spring(c->w, body, axis, k, damping, rest);
}

static void op_body_force(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY);
    const uint8_t f = byte();
    double a[3];
    vec(a);
    flat(c, a, f & 2);
    const double frequency = num(), phase = num();
    trace("demill_body_set_force(w, 0x%llx, ", (unsigned long long)body);
    trace_vec("amplitude", f & 1 ? NULL : a);
    trace(", %.17g, %.17g)", frequency, phase);
    c->st = demill_body_set_force(c->w, body, f & 1 ? NULL : a, frequency, phase);
}

static void op_body_attach_wall(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY), wall = id_named(c, DEMILL_KIND_WALL);
    trace("demill_body_attach_wall(w, 0x%llx, 0x%llx)", (unsigned long long)body,
          (unsigned long long)wall);
    c->st = demill_body_attach_wall(c->w, body, wall);
}

static void op_body_get(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY);
    const int32_t field = pick(fz_body_fields, COUNT(fz_body_fields));
    const bool null_out = byte() & 1;
    double v[3];
    c->query = true;
    trace("demill_body_get(w, 0x%llx, %d, %s)", (unsigned long long)body, (int)field,
          null_out ? "NULL" : "v");
    c->st = demill_body_get(c->w, body, field, null_out ? NULL : v);
}

static void op_body_energy(call *c)
{
    const demill_id body = id_named(c, DEMILL_KIND_BODY);
    const int32_t term = pick(fz_body_terms, COUNT(fz_body_terms));
    const bool null_out = byte() & 1;
    double v = 0.0;
    c->query = true;
    trace("demill_body_energy(w, 0x%llx, %d, %s)", (unsigned long long)body, (int)term,
          null_out ? "NULL" : "&v");
    c->st = demill_body_energy(c->w, body, term, null_out ? NULL : &v);
    if (c->st == DEMILL_OK && !isfinite(v))
        fail("demill_body_energy(%d) gave %.17g", (int)term, v);
}

static void (*const ops[FZ_OPS])(call *) = {
    [FZ_WORLD_RECREATE] = op_world_recreate,
    [FZ_WORLD_CREATE_BAD] = op_world_create_bad,
    [FZ_WORLD_SET] = op_world_set,
    [FZ_WORLD_GET] = op_world_get,
    [FZ_MATERIAL_CREATE] = op_material_create,
    [FZ_MATERIAL_SET] = op_material_set,
    [FZ_MATERIAL_GET] = op_material_get,
    [FZ_PAIR_SET] = op_pair_set,
    [FZ_PAIR_GET] = op_pair_get,
    [FZ_PARTICLES_ADD] = op_particles_add,
    [FZ_PARTICLES_REMOVE] = op_particles_remove,
    [FZ_PARTICLES_READ] = op_particles_read,
    [FZ_PARTICLES_READ_IDS] = op_particles_read_ids,
    [FZ_PARTICLES_WRITE] = op_particles_write,
    [FZ_PARTICLE_GET] = op_particle_get,
    [FZ_PARTICLE_SET] = op_particle_set,
    [FZ_WALL_ADD] = op_wall_add,
    [FZ_WALL_REMOVE] = op_wall_remove,
    [FZ_WALL_MOTION] = op_wall_motion,
    [FZ_WALL_GET] = op_wall_get,
    [FZ_CONTACTS_READ] = op_contacts_read,
    [FZ_CONTACTS_READ_IDS] = op_contacts_read_ids,
    [FZ_ENERGY] = op_energy,
    [FZ_DRUM_CREATE] = op_drum_create,
    [FZ_DRUM_REMOVE] = op_drum_remove,
    [FZ_DRUM_SET] = op_drum_set,
    [FZ_DRUM_GET] = op_drum_get,
    [FZ_DRUM_ADD_LIFTER] = op_drum_add_lifter,
    [FZ_DRUM_LIFTER_GET] = op_drum_lifter_get,
    [FZ_DRUM_FILL] = op_drum_fill,
    [FZ_SPECTRUM_START] = op_spectrum_start,
    [FZ_SPECTRUM_READ] = op_spectrum_read,
    [FZ_STEP] = op_step,
    [FZ_SETTLE] = op_settle,
    [FZ_SUGGEST] = op_suggest,
    [FZ_SUGGEST_APPLY] = op_suggest_apply,
    [FZ_SNAPSHOT_TAKE] = op_snapshot_take,
    [FZ_SNAPSHOT_RESTORE] = op_snapshot_restore,
    [FZ_SNAPSHOT_FREE] = op_snapshot_free,
    [FZ_BUFFER_TRANSFER] = op_buffer_transfer,
    [FZ_FILE_SAVE] = op_file_save,
    [FZ_FILE_LOAD] = op_file_load,
    [FZ_PROGRESS] = op_progress,
    [FZ_IDS] = op_ids,
    [FZ_VTK_PARTICLES] = op_vtk_particles,
    [FZ_VTK_WALLS] = op_vtk_walls,
    [FZ_VTK_SERIES] = op_vtk_series,
    [FZ_STATELESS] = op_stateless,
    [FZ_IMPACTS_START] = op_impacts_start,
    [FZ_IMPACTS_READ] = op_impacts_read,
    [FZ_IMPACTS_PARTICLES] = op_impacts_particles,
    [FZ_GRINDING] = op_grinding,
    [FZ_WALL_ADD_MESH] = op_wall_add_mesh,
    [FZ_WALL_ADD_POLYLINE] = op_wall_add_polyline,
    [FZ_WALL_ADD_STL] = op_wall_add_stl,
    [FZ_WALL_MESH_INFO] = op_wall_mesh_info,
    [FZ_WALL_ADD_FINITE] = op_wall_add_finite,
    [FZ_WALL_HARMONIC] = op_wall_harmonic,
    [FZ_WALL_SURFACE_VELOCITY] = op_wall_surface_velocity,
    [FZ_DRUM_MATERIAL] = op_drum_material,
    [FZ_DRUM_ATTACH_WALL] = op_drum_attach_wall,
    [FZ_FILL_REGION] = op_fill_region,
    [FZ_FEED_CREATE] = op_feed_create,
    [FZ_FEED_REMOVE] = op_feed_remove,
    [FZ_FEED_READ] = op_feed_read,
    [FZ_OUTLET_CREATE] = op_outlet_create,
    [FZ_OUTLET_REMOVE] = op_outlet_remove,
    [FZ_OUTLET_READ] = op_outlet_read,
    [FZ_BODY_ADD] = op_body_add,
    [FZ_BODY_REMOVE] = op_body_remove,
    [FZ_BODY_SPRING] = op_body_spring,
    [FZ_BODY_FORCE] = op_body_force,
    [FZ_BODY_ATTACH_WALL] = op_body_attach_wall,
    [FZ_BODY_GET] = op_body_get,
    [FZ_BODY_ENERGY] = op_body_energy,
};

/* ---- the checks after a call ------------------------------------------------ */

/* The rule for a call that failed and changed the world, in one place so
 * that it follows the documentation. Only stepping (demill_world_step(),
 * demill_world_settle()) may, when it is stopped: by the watchdog
 * (DEMILL_ERR_UNSTABLE), the world is back at the last state that passed a
 * check, which is not before the call began (the caller's work stays); by
 * the progress callback (DEMILL_ERR_INTERRUPTED), it holds the state after
 * the step the callback stopped it at, for demill_world_step() the
 * callback's every_steps times its reports. Every other failure leaves no
 * trace. Returns NULL where the change is allowed, else what is wrong. */
static const char *failed_change(const call *c)
{
    if (!c->stepping || (c->st != DEMILL_ERR_UNSTABLE && c->st != DEMILL_ERR_INTERRUPTED))
        return "a call that failed changed the world";
    const double steps = world_value(c, DEMILL_WORLD_STEP_COUNT);
    if (c->st == DEMILL_ERR_UNSTABLE && steps < c->steps_before)
        return "the watchdog put the world back to before the call";
    const progress *p = &F.prog[c->k];
    if (c->st == DEMILL_ERR_INTERRUPTED && c->one_run &&
        steps != c->steps_before + (double)p->every * p->reports)
        return "the progress callback stopped the run elsewhere than after its last report";
    return NULL;
}

static void save(demill_world *w, buf *b, const char *what)
{
    size_t n;
    demill_status st = demill_world_save_buffer(w, NULL, 0, &n);
    b->diverged = st == DEMILL_ERR_UNSTABLE;
    if (b->diverged) {
        b->n = 0;
        return;
    }
    if (st == DEMILL_OK && n > b->cap) {
        unsigned char *p = realloc(b->b, n);
        if (!p)
            abort();
        b->b = p;
        b->cap = n;
    }
    if (st == DEMILL_OK)
        st = demill_world_save_buffer(w, b->b, n, &b->n);
    if (st != DEMILL_OK)
        fail("demill_world_save_buffer (%s) gave %d: %s", what, (int)st,
             demill_world_last_error(w));
}

/* Two states are the same if their checkpoints are; two that cannot be
 * saved cannot be told apart. */
static bool same(const buf *a, const buf *b)
{
    return a->diverged == b->diverged && a->n == b->n && (!a->n || !memcmp(a->b, b->b, a->n));
}

/* The first byte at which two checkpoints differ, for messages. */
static size_t first_difference(const buf *a, const buf *b)
{
    size_t i = 0;
    while (i < a->n && i < b->n && a->b[i] == b->b[i])
        i++;
    return i;
}

/* save → load → save gives the same bytes, and the load succeeds. */
static void check_round_trip(const buf *saved)
{
    if (saved->diverged)
        return;
    const demill_status st = demill_world_load_buffer(F.scratch, saved->b, saved->n);
    if (st != DEMILL_OK)
        fail("the library refused to load a checkpoint it wrote (%zu bytes): %d: %s", saved->n,
             (int)st, demill_world_last_error(F.scratch));
    save(F.scratch, &F.again, "after a load");
    if (!same(saved, &F.again))
        fail("save, load, save gave other bytes (%zu and %zu bytes, first difference at %zu)",
             saved->n, F.again.n, first_difference(saved, &F.again));
}

/* A bound on the particles' kinetic and potential energies from what they
 * read back, Σ m (|v|² + r² |ω|² + |g| |x|): above 1e300 a term may
 * overflow with no fault (a velocity of 1e224 m/s is accepted, and its
 * ½ m v² is infinite). */
static double energy_bound(const call *c, size_t n)
{
    double *m = grab(n, sizeof *m), *r = grab(n, sizeof *r), *v = grab(3 * n, sizeof *v),
           *w = grab(3 * n, sizeof *w), *x = grab(3 * n, sizeof *x), sum = 0.0;
    const double g = hypot(hypot(world_value(c, DEMILL_WORLD_GRAVITY_X),
                                 world_value(c, DEMILL_WORLD_GRAVITY_Y)),
                           world_value(c, DEMILL_WORLD_GRAVITY_Z));
    size_t got;
    demill_particles_read(c->w, DEMILL_PARTICLE_MASS, m, n, &got);
    demill_particles_read(c->w, DEMILL_PARTICLE_RADIUS, r, n, &got);
    demill_particles_read(c->w, DEMILL_PARTICLE_VELOCITY, v, n, &got);
    demill_particles_read(c->w, DEMILL_PARTICLE_ANGULAR_VELOCITY, w, n, &got);
    demill_particles_read(c->w, DEMILL_PARTICLE_POSITION, x, n, &got);
    for (size_t i = 0; i < n; i++) {
        const double *vi = v + 3 * i, *wi = w + 3 * i, *xi = x + 3 * i;
        sum += m[i] * (vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2] +
                       r[i] * r[i] * (wi[0] * wi[0] + wi[1] * wi[1] + wi[2] * wi[2]) +
                       g * hypot(hypot(xi[0], xi[1]), xi[2]));
    }
    free(m);
    free(r);
    free(v);
    free(w);
    free(x);
    return sum;
}

/* Positions, velocities and angular velocities are finite, and so are the
 * bodies' positions and velocities; the energy account's terms (but those
 * stored in the contacts, whose reading may bring the neighbour lists up to
 * date and so change the state) are not NaN, and the particles' kinetic and
 * potential energies are finite unless energy_bound() says they may not
 * be. */
static void check_finite(const call *c)
{
    static const int32_t terms[] = {
        DEMILL_ENERGY_KINETIC_TRANSLATIONAL, DEMILL_ENERGY_KINETIC_ROTATIONAL,
        DEMILL_ENERGY_POTENTIAL, DEMILL_ENERGY_WALL_WORK, DEMILL_ENERGY_DISSIPATED,
        DEMILL_ENERGY_FLOW, DEMILL_ENERGY_BODY_KINETIC, DEMILL_ENERGY_BODY_ELASTIC,
        DEMILL_ENERGY_BODY_POTENTIAL, DEMILL_ENERGY_BODY_DISSIPATED, DEMILL_ENERGY_BODY_WORK};
    const size_t n = (size_t)world_value(c, DEMILL_WORLD_PARTICLE_COUNT);
    const double bound = energy_bound(c, n);
    for (size_t t = 0; t < COUNT(terms); t++) {
        double e;
        if (demill_world_energy(c->w, terms[t], &e) == DEMILL_OK &&
            (isnan(e) || (!isfinite(e) && t < 3 && bound < 1e300)))
            fail("stepping returned DEMILL_OK with the watchdog on, and energy term %d = %g "
                 "(the particles' energies are below %g)",
                 (int)terms[t], e, bound);
    }
    const listing *bodies = &F.list[c->k][DEMILL_KIND_BODY];
    for (size_t b = 0; b < bodies->n; b++)
        for (int32_t field = DEMILL_BODY_POSITION; field <= DEMILL_BODY_VELOCITY; field++) {
            double v[3];
            if (demill_body_get(c->w, bodies->id[b], field, v) != DEMILL_OK)
                fail("demill_body_get failed on a listed body after a step");
            if (!isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2]))
                fail("stepping returned DEMILL_OK with the watchdog on, and body %zu has field %d "
                     "= {%g, %g, %g}", b, (int)field, v[0], v[1], v[2]);
        }
    static const int32_t fields[3] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                                      DEMILL_PARTICLE_ANGULAR_VELOCITY};
    double *v = grab(3 * n, sizeof *v);
    for (int f = 0; f < 3; f++) {
        size_t got;
        if (demill_particles_read(c->w, fields[f], v, n, &got) != DEMILL_OK)
            fail("demill_particles_read failed after a step");
        for (size_t i = 0; i < 3 * n; i++)
            if (!isfinite(v[i]))
                fail("stepping returned DEMILL_OK with the watchdog on, and particle %zu (id "
                     "order) has field %d component %zu = %g",
                     i / 3, (int)fields[f], i % 3, v[i]);
    }
    free(v);
}

static const char *const kind_names[8] = {"",     "material", "particle", "wall",
                                          "drum", "feed",     "outlet",   "body"};

/* The ids a call named: refused unless listed, not refused as bad handles
 * if all are. */
static void check_named(const call *c)
{
    bool all_listed = true;
    for (int i = 0; i < c->nnamed; i++) {
        const bool ok = listed(c->k, c->named_kind[i], c->named[i]);
        all_listed &= ok;
        if (!ok && c->st == DEMILL_OK)
            fail("the call accepted id 0x%llx, which names no %s of its world",
                 (unsigned long long)c->named[i], kind_names[c->named_kind[i]]);
    }
    if (all_listed && !c->other_handle && c->st == DEMILL_ERR_INVALID_HANDLE)
        fail("DEMILL_ERR_INVALID_HANDLE for ids that are all live: %s",
             demill_world_last_error(c->w));
}

/* Lists world k anew after a call changed it; ids no longer listed join the
 * pool as removed ids (a few per call). */
static void relist(int k)
{
    demill_id old[DEMILL_KIND_BODY][8];
    size_t nold[DEMILL_KIND_BODY];
    for (int kind = DEMILL_KIND_MATERIAL; kind <= DEMILL_KIND_BODY; kind++) {
        const listing *l = &F.list[k][kind];
        nold[kind - 1] = l->n < 8 ? l->n : 8;
        for (size_t i = 0; i < nold[kind - 1]; i++)
            old[kind - 1][i] = l->id[(i * l->n) / nold[kind - 1]]; /* spread over the list */
    }
    list_world(k);
    for (int kind = DEMILL_KIND_MATERIAL; kind <= DEMILL_KIND_BODY; kind++)
        for (size_t i = 0; i < nold[kind - 1]; i++)
            if (!listed(k, kind, old[kind - 1][i]))
                pool_add(old[kind - 1][i]);
}

static void run_call(void)
{
    const uint8_t op = byte() % FZ_OPS, wb = byte();
    call c = {.k = wb == FZ_WORLD_NULL || wb == FZ_WORLD_FAKE ? -1 : wb & 1, .dim = 3};
    c.w = wb == FZ_WORLD_NULL ? NULL : wb == FZ_WORLD_FAKE ? (demill_world *)fake_object : F.w[c.k];
    if (c.k >= 0) {
        c.dim = (int)world_value(&c, DEMILL_WORLD_DIMENSION);
        c.np = F.list[c.k][DEMILL_KIND_PARTICLE].n;
    }
    F.ops++;
    F.prog[0].reports = F.prog[1].reports = 0;
    trace("%lu: w%d: ", F.ops, c.k);
    ops[op](&c);
    if (c.skipped) {
        trace("left out (capped)\n");
        return;
    }
    const bool message = c.st && c.k >= 0 && !c.worldless;
    trace(" = %d%s%s\n", (int)c.st, message ? ": " : "",
          message ? demill_world_last_error(c.w) : "");
    if (!c.worldless && c.k < 0) {
        const demill_status want = c.w ? DEMILL_ERR_INVALID_HANDLE : DEMILL_ERR_NULL_POINTER;
        if (c.st != want)
            fail("a call on a %s world gave %d, not %d", c.w ? "fake" : "NULL", (int)c.st,
                 (int)want);
    }
    if (!c.worldless && c.k >= 0) {
        if (c.st != DEMILL_OK && !c.grinding_message && !*demill_world_last_error(c.w))
            fail("the call failed with %d and left no message", (int)c.st);
        check_named(&c);
    }
    if (c.k < 0) /* no world to change (the end of the input checks both) */
        return;
    const int k = c.k;
    save(F.w[k], &F.after, "after the call");
    const bool changed = !same(&F.before[k], &F.after);
    if (changed) {
        if (c.query)
            fail("a call documented to change nothing changed the world (status %d)", (int)c.st);
        const char *wrong = c.st != DEMILL_OK && !c.replaces ? failed_change(&c) : NULL;
        if (wrong)
            fail("%s: status %d (%s), first difference at byte %zu of %zu", wrong, (int)c.st,
                 demill_world_last_error(c.w), first_difference(&F.before[k], &F.after), F.after.n);
        check_round_trip(&F.after);
        const buf now = F.after; /* the state the next call on the world starts from */
        F.after = F.before[k];
        F.before[k] = now;
    }
    if (c.stepping && c.st == DEMILL_OK && c.watchdog)
        check_finite(&c);
    if (changed || c.replaces)
        relist(k);
}

/* Each world is as the last call on it left it: no call changed the other
 * world, and none on no world changed either. (Checked once per input: it
 * would double the cost of a call.) */
static void check_untouched(void)
{
    for (int k = 0; k < 2; k++) {
        save(F.w[k], &F.after, "at the end");
        if (!same(&F.before[k], &F.after))
            fail("world %d changed in a call on another world or on none (first difference at "
                 "byte %zu)", k, first_difference(&F.before[k], &F.after));
    }
}

/* ---- the entry point ------------------------------------------------------- */

static void cleanup(void)
{
    static const char *names[] = {"checkpoint", "checkpoint.part", "particles.vtu", "walls.vtp",
                                  "garbage"};
    char p[128];
    for (size_t k = 0; k < COUNT(names); k++) {
        snprintf(p, sizeof p, "%s/%s", F.dir, names[k]);
        remove(p);
    }
    /* the series opened at the paths path() gives: "DIR/series",
     * "DIR/garbage", and the directory's own path, whose files are the
     * directory's siblings */
    static const char *in[] = {"/series", "/garbage", ""};
    for (size_t s = 0; s < COUNT(in); s++) {
        char prefix[96];
        snprintf(prefix, sizeof prefix, "%s%s", F.dir, in[s]);
        snprintf(p, sizeof p, "%s.pvd", prefix);
        remove(p);
        snprintf(p, sizeof p, "%s.pvd.tmp", prefix);
        remove(p);
        for (int k = 0; k < 1000; k++) {
            snprintf(p, sizeof p, "%s_particles_%06d.vtu", prefix, k);
            remove(p);
            snprintf(p, sizeof p, "%s_walls_%06d.vtp", prefix, k);
            remove(p);
        }
    }
    rmdir(F.dir);
}

static void setup(void)
{
    F.trace = getenv("DEMILL_FUZZ_TRACE") != NULL;
    init_tfamily();
    if (demill_world_create(3, &F.scratch) != DEMILL_OK)
        abort();
    const char *tmp = getenv("TMPDIR");
    snprintf(F.dir, sizeof F.dir, "%s/demill-fuzz-XXXXXX", tmp && strlen(tmp) < 32 ? tmp : "/tmp");
    if (!mkdtemp(F.dir))
        abort();
    atexit(cleanup);
    char p[128];
    snprintf(p, sizeof p, "%s/garbage", F.dir);
    FILE *f = fopen(p, "wb");
    if (!f || fputs("DEMILLCK but not a checkpoint", f) < 0 || fclose(f))
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!F.scratch)
        setup();
    if (size == 0)
        return 0;
    F.p = data + 1;
    F.n = size - 1;
    F.ops = 0;
    for (int k = 0; k < 2; k++) {
        if (demill_world_create(data[0] >> k & 1 ? 2 : 3, &F.w[k]) != DEMILL_OK)
            abort();
        F.prog[k] = (progress){.w = F.w[k]};
        list_world(k);
        save(F.w[k], &F.before[k], "of a new world");
    }
    trace("input of %zu bytes: w0 %dD, w1 %dD\n", size, data[0] & 1 ? 2 : 3, data[0] & 2 ? 2 : 3);
    while (F.n)
        run_call();
    check_untouched();
    for (int k = 0; k < 2; k++) {
        demill_world_destroy(F.w[k]);
        F.w[k] = NULL;
        demill_snapshot_free(F.snap[k]);
        F.snap[k] = NULL;
    }
    demill_vtk_series_close(F.series);
    F.series = NULL;
    demill_grinding_destroy(F.g);
    F.g = NULL;
    F.npool = F.pool_next = 0;
    return 0;
}
