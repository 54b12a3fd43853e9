/* checkpoint.c: snapshots, checkpoints and the listing of a world's ids
 * (demill/state.h).
 *
 * A snapshot is a deep copy of the world made by dm_state_copy() (snapshot.c).
 * A checkpoint is the same state as bytes: a 32-byte header (magic
 * "DEMILLCK", format version, a byte-order mark, the payload's size and its
 * CRC-32, the writing library's version), then the payload, field after field
 * in fixed widths and the writer's byte order, in tagged sections. One
 * function, transfer(), walks the fields both to write and to read them, so
 * that the two can never disagree. A load reads into a scratch world, checks
 * every size while reading and every index and parameter afterwards, and
 * only then copies the result into the caller's world. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demill/insert.h"
#include "world/world.h"

/* ---- snapshots -------------------------------------------------------------- */

#define DM_SNAPSHOT_MAGIC 0x736e617073686f74u /* "snapshot" */

struct demill_snapshot {
    uint64_t magic;
    demill_world state;
};

DEMILL_API demill_status demill_snapshot_take(demill_world *w, demill_snapshot **out)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "snapshot_take: out is NULL");
    *out = NULL;
    demill_snapshot *snap = calloc(1, sizeof *snap);
    if (!snap || dm_state_copy(&snap->state, w)) {
        free(snap);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "snapshot_take: out of memory");
    }
    snap->magic = DM_SNAPSHOT_MAGIC;
    *out = snap;
    dm_clear_error(w);
    return DEMILL_OK;
}

/* Makes w's state a copy of src's, keeping what belongs to the host and the
 * world's identity (demill/state.h). */
static demill_status restore(demill_world *w, const demill_world *src)
{
    const uint64_t edits = w->base.edits;
    const int threads = w->base.threads;
    if (dm_state_restore(w, src))
        return DEMILL_ERR_OUT_OF_MEMORY;
    w->base.edits = edits;
    w->base.threads = threads;
    dm_clear_error(w);
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_snapshot_restore(demill_world *w, const demill_snapshot *snap)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!snap)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "snapshot_restore: snapshot is NULL");
    if (snap->magic != DM_SNAPSHOT_MAGIC)
        return dm_fail(w, DEMILL_ERR_INVALID_HANDLE,
                       "snapshot_restore: snapshot is not a live snapshot");
    if (restore(w, &snap->state))
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "snapshot_restore: out of memory");
    return DEMILL_OK;
}

DEMILL_API void demill_snapshot_free(demill_snapshot *snap)
{
    if (!snap || snap->magic != DM_SNAPSHOT_MAGIC)
        return;
    dm_state_free(&snap->state);
    snap->magic = 0;
    free(snap);
}

/* ---- the bytes of a state --------------------------------------------------- */

#define CK_MAGIC "DEMILLCK"
#define CK_FORMAT 7u          /* the format this library writes and the newest it reads;
                                 2 adds the impacts on an ore to the drum's spectrum,
                                 3 a material per part of the drum, the walls'
                                 meshes (section MESH), the feeds and outlets (FLOW),
                                 the finite walls, harmonic motion and surface
                                 velocity (WFIN), the bodies (BODY), the drum's
                                 translation (DRMV), the loads the walls record
                                 (LOAD); 4 the extended laws' dissipation terms
                                 (WRLD), the cohesion law, the number of fields
                                 per material and of values per material pair
                                 (MATS) and the number of contact lists (CONT);
                                 5 the 3D particles' orientations (ORNT), the
                                 clump templates and the clumps (CLMP); 6 the
                                 kernels' precision (WRLD); 7 whether the
                                 orientations are tracked (WRLD) */
#define CK_BYTE_ORDER 0x01020304u
#define CK_HEADER 32u

/* The walk over a state's fields, writing them out or reading them in. */
typedef struct io {
    bool reading;
    uint32_t format;   /* the format version read or written */
    uint8_t *buf;      /* writing: the bytes so far */
    size_t n, cap;
    const uint8_t *in; /* reading: the bytes still to read */
    size_t left;
    const char *section;  /* the section being walked */
    demill_status status; /* the first failure: OUT_OF_MEMORY, FORMAT or (writing a
                             state that is not finite) UNSTABLE */
    char why[200];        /* and what it was */
} io;

static void io_fail(io *s, demill_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static void io_fail(io *s, demill_status code, const char *fmt, ...)
{
    if (s->status)
        return;
    s->status = code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->why, sizeof s->why, fmt, ap);
    va_end(ap);
}

static void io_bytes(io *s, void *v, size_t bytes)
{
    if (s->status || !bytes)
        return;
    if (s->reading) {
        if (bytes > s->left) {
            io_fail(s, DEMILL_ERR_FORMAT, "truncated: %zu bytes short", bytes - s->left);
            return;
        }
        memcpy(v, s->in, bytes);
        s->in += bytes;
        s->left -= bytes;
        return;
    }
    if (bytes > s->cap - s->n) {
        size_t cap = dm_grown_capacity(s->cap, s->n + bytes);
        uint8_t *b = cap < s->n + bytes ? NULL : realloc(s->buf, cap);
        if (!b) {
            io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
            return;
        }
        s->buf = b;
        s->cap = cap;
    }
    memcpy(s->buf + s->n, v, bytes);
    s->n += bytes;
}

/* Checks that n doubles are finite, or NaN where nan_ok (the drum's "not
 * measured yet"): what is read must be, and what is written too, so that the
 * library never writes a checkpoint it would refuse to read. */
static void io_finite(io *s, const double *v, size_t n, bool nan_ok)
{
    for (size_t k = 0; k < n && !s->status; k++)
        if (!isfinite(v[k]) && !(nan_ok && isnan(v[k]))) {
            if (s->reading)
                io_fail(s, DEMILL_ERR_FORMAT, "section %s: a stored value is %g, not finite",
                        s->section, v[k]);
            else
                io_fail(s, DEMILL_ERR_UNSTABLE,
                        "section %s: a value is %g: the state is not finite (it diverged), "
                        "and a diverged state is not saved",
                        s->section, v[k]);
        }
}

static void io_f64(io *s, double *v, size_t n)
{
    io_bytes(s, v, n * sizeof *v);
    io_finite(s, v, n, false);
}

/* A double that may also be NaN, the drum's "not measured yet". */
static void io_f64_or_nan(io *s, double *v)
{
    io_bytes(s, v, sizeof *v);
    io_finite(s, v, 1, true);
}
static void io_u64(io *s, uint64_t *v) { io_bytes(s, v, sizeof *v); }
static void io_u32(io *s, uint32_t *v, size_t n) { io_bytes(s, v, n * sizeof *v); }

static void io_u16(io *s, uint16_t *v) { io_bytes(s, v, sizeof *v); }

static void io_int(io *s, int *v)
{
    int32_t t = (int32_t)*v;
    io_bytes(s, &t, sizeof t);
    *v = t;
}

static void io_bool(io *s, bool *v)
{
    uint8_t t = *v;
    io_bytes(s, &t, 1);
    if (s->reading && t > 1)
        io_fail(s, DEMILL_ERR_FORMAT, "a flag is %u, not 0 or 1", t);
    *v = t == 1;
}

/* A count read from the file may not exceed `most`; after a failure it is
 * 0, so that no loop runs over it. */
static void io_count(io *s, uint32_t *n, uint64_t most, const char *what)
{
    io_u32(s, n, 1);
    if (s->reading && !s->status && *n > most)
        io_fail(s, DEMILL_ERR_FORMAT, "%s: %u, at most %llu allowed", what, *n,
                (unsigned long long)most);
    if (s->status)
        *n = 0;
}

/* An array of count items of `size` bytes; reading allocates it (room for
 * `room` >= count items) after checking that the bytes are there. */
static void io_array(io *s, void *field, size_t count, size_t room, size_t size)
{
    void **p = field;
    if (s->reading) {
        if (s->status)
            return;
        if (count > s->left / size) {
            io_fail(s, DEMILL_ERR_FORMAT, "truncated: an array of %zu items does not fit", count);
            return;
        }
        *p = malloc(room ? room * size : 1);
        if (!*p) {
            io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
            return;
        }
    }
    io_bytes(s, *p, count * size);
}

/* An array of count doubles, each finite (room as io_array's). */
static void io_f64_array(io *s, double **field, size_t count, size_t room)
{
    io_array(s, field, count, room, sizeof **field);
    if (!s->status)
        io_finite(s, *field, count, false);
}

/* Before room for `count` structures read field by field is allocated: each
 * takes at least `least` bytes of the file. */
static void io_room(io *s, uint32_t count, size_t least, const char *what)
{
    if (s->reading && !s->status && count > s->left / least)
        io_fail(s, DEMILL_ERR_FORMAT, "truncated: %u %s cannot fit in %zu bytes", count, what,
                s->left);
}

/* A section starts with its four-letter name. */
static void io_section(io *s, const char *name)
{
    s->section = name;
    char got[4];
    memcpy(got, name, 4);
    io_bytes(s, got, 4);
    if (s->reading && !s->status && memcmp(got, name, 4))
        io_fail(s, DEMILL_ERR_FORMAT, "section %.4s expected, found other bytes", name);
}

static void transfer_handles(io *s, dm_handles *h, const char *what)
{
    io_count(s, &h->n, UINT32_MAX - 1, what);
    io_count(s, &h->nfree, h->n, what);
    if (s->reading)
        h->cap = h->n;
    io_array(s, &h->slot, h->n, h->n, sizeof *h->slot);
    io_array(s, &h->gen, h->n, h->n, sizeof *h->gen);
    io_array(s, &h->free, h->nfree, h->n, sizeof *h->free);
}

/* The orientations of a 3D world's n particles (section ORNT, from format 5
 * on): the arrays w, x, y, z, each quaternion of norm 1 to within 1e-12 (the
 * integrators keep it to round-off). An older file has none: its particles
 * start at (1, 0, 0, 0), as new ones do. */
static void transfer_orientations(io *s, dm_particles *P, size_t n)
{
    if (s->format < 5) {
        for (int c = 0; c < 4 && s->reading && !s->status; c++) {
            P->q[c] = malloc(n ? n * sizeof *P->q[c] : 1);
            if (!P->q[c]) {
                io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
                return;
            }
            for (size_t i = 0; i < n; i++)
                P->q[c][i] = c == 0 ? 1.0 : 0.0;
        }
        return;
    }
    io_section(s, "ORNT");
    for (int c = 0; c < 4; c++)
        io_f64_array(s, &P->q[c], n, n);
    for (size_t i = 0; i < n && s->reading && !s->status; i++) {
        double q[4];
        dm_quat_get(P->q, (uint32_t)i, q);
        const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (!(fabs(n2 - 1.0) <= 1e-12))
            io_fail(s, DEMILL_ERR_FORMAT, "particle %zu: orientation of norm %.17g, not 1", i,
                    sqrt(n2));
    }
}

static void transfer_wall(io *s, dm_wall *wl)
{
    io_u32(s, &wl->handle, 1);
    io_u32(s, &wl->material, 1);
    io_int(s, &wl->kind);
    io_int(s, &wl->drum_part);
    io_int(s, &wl->lifter);
    io_f64(s, &wl->radius, 1);
    io_int(s, &wl->npoly);
    double *const f[] = {wl->poly, wl->cpoly, wl->cedge, wl->bc0, wl->bc, &wl->brad, &wl->reach,
                         wl->p0, wl->n0, wl->c0, wl->vel, wl->omega, &wl->t0, wl->p, wl->n,
                         wl->c, wl->rot, wl->c_build, wl->rot_build, wl->force, wl->torque,
                         &wl->dissipated};
    const size_t len[] = {2 * DM_MAX_POLY, 2 * DM_MAX_POLY, 4 * DM_MAX_POLY, 2, 2, 1, 1, 3, 3, 3,
                          3, 3, 1, 3, 3, 3, 9, 3, 9, 3, 3, 1};
    for (size_t k = 0; k < sizeof len / sizeof *len; k++)
        io_f64(s, f[k], len[k]);
}

/* A wall's finite shape, its caps, its harmonic motion and its surface
 * velocity (format 3). */
static void transfer_wall_finite(io *s, dm_wall *wl)
{
    io_int(s, &wl->own);
    io_u32(s, &wl->parent, 1);
    io_u32(s, wl->parts, 2);
    io_int(s, &wl->harmonic);
    io_int(s, &wl->surface);
    double *const f[] = {wl->seg,   wl->nb,     wl->e0,      &wl->bh,   wl->h_axis,
                         &wl->h_amp, &wl->h_freq, &wl->h_phase, &wl->h_t0, wl->surf0};
    const size_t len[] = {4, 4, 3, 1, 3, 1, 1, 1, 1, 3};
    for (size_t k = 0; k < sizeof len / sizeof *len; k++)
        io_f64(s, f[k], len[k]);
}

static void transfer_drum(io *s, dm_drum *d, int dim)
{
    io_bool(s, &d->alive);
    if (s->format >= 3) {
        io_u32(s, d->material, 3);
        io_bool(s, &d->shell);
    } else { /* one material for the whole drum, and its shell */
        io_u32(s, d->material, 1);
        d->material[1] = d->material[2] = d->material[0];
        d->shell = true;
    }
    io_f64(s, &d->diameter, 1);
    io_f64(s, &d->length, 1);
    io_f64(s, &d->porosity, 1);
    io_u32(s, &d->even_count, 1);
    io_f64(s, &d->lifter_h, 1);
    io_f64(s, &d->lifter_w, 1);
    io_f64(s, &d->lifter_face, 1);
    io_f64(s, &d->lifter_phase, 1);
    io_count(s, &d->nlifters, DM_MAX_LIFTERS, "drum lifters");
    for (uint32_t k = 0; k < d->nlifters && !s->status; k++) {
        dm_lifter_spec *l = &d->lifters[k];
        double *const f[] = {&l->angle, &l->height, &l->width, &l->face};
        for (int q = 0; q < 4; q++)
            io_f64(s, f[q], 1);
    }
    io_count(s, &d->nwall, d->nlifters + (dim == 3 ? 3 : 1), "drum walls");
    io_u32(s, d->wall_slot, d->nwall);
    io_int(s, &d->speed_key);
    /* (NULL: a value that is NaN until measured, next in `unknown`) */
    double *const f[] = {&d->speed_value, &d->ramp, &d->crit_diameter, &d->t_set,
                         &d->theta_set, &d->omega_from, &d->omega_to, &d->theta, &d->omega,
                         NULL, &d->torque, &d->power, &d->energy_in,
                         &d->energy_dissipated, d->lifter_peak, d->lifter_energy, NULL,
                         NULL, NULL, NULL, &d->lifter_force_mean[0][0], &d->rev.t0,
                         &d->rev.energy_in, &d->rev.power_cm_sum, &d->rev.dissipated0,
                         d->rev.shape_sum, &d->rev.lifter_impulse[0][0]};
    const size_t len[] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, DM_MAX_LIFTERS,
                          DM_MAX_LIFTERS, 1, 1, 1, 3, 3 * DM_MAX_LIFTERS, 1, 1, 1, 1, 3,
                          3 * DM_MAX_LIFTERS};
    double *const unknown[] = {&d->theta_start, &d->mean_power, &d->mean_power_cm,
                               &d->mean_dissipation, d->mean_shape};
    for (size_t k = 0, u = 0; k < sizeof len / sizeof *len; k++) {
        if (f[k]) {
            io_f64(s, f[k], len[k]);
            continue;
        }
        for (size_t q = 0; q < len[k]; q++)
            io_f64_or_nan(s, unknown[u] + q);
        u++;
    }
    io_u32(s, &d->sample_interval, 1);
    io_u64(s, &d->samples_due);
    io_u64(s, &d->revolutions);
    io_u32(s, &d->rev.power_cm_count, 1);
    io_u32(s, d->rev.shape_count, 3);

    dm_spectrum *sp = &d->spectrum;
    bool on = sp->counts != NULL;
    io_bool(s, &on);
    if (!on)
        return;
    io_count(s, &sp->nclasses, 64, "spectrum size classes");
    io_count(s, &sp->nbins, 10000, "spectrum energy bins");
    if (s->reading && !s->status && (!sp->nclasses || !sp->nbins))
        io_fail(s, DEMILL_ERR_FORMAT, "a spectrum without classes or bins");
    if (s->status)
        return;
    io_f64(s, &sp->log_min, 1);
    io_f64(s, &sp->log_span, 1);
    io_f64_array(s, &sp->edges, sp->nclasses - 1, sp->nclasses - 1);
    if (s->format >= 2) {
        io_u32(s, &sp->ore, 1);
        if (sp->ore) {
            io_count(s, &sp->ore_classes, 200, "impact size classes");
            io_count(s, &sp->ore_bins, 10000, "impact energy bins");
            io_f64(s, &sp->ore_top, 1);
            io_f64(s, &sp->ore_log_min, 1);
            io_f64(s, &sp->ore_log_span, 1);
            io_f64(s, &sp->ore_t0, 1);
        }
    }
    if (s->status)
        return;
    const size_t counters = dm_spectrum_counters(sp);
    io_array(s, &sp->counts, counters, counters, sizeof *sp->counts);
}

/* A time that may be infinite (a feed's stop), but not NaN. */
static void io_time(io *s, double *v)
{
    io_bytes(s, v, sizeof *v);
    if (!s->status && isnan(*v))
        io_fail(s, s->reading ? DEMILL_ERR_FORMAT : DEMILL_ERR_UNSTABLE,
                "section %s: a time is NaN", s->section);
}

static void transfer_region(io *s, dm_region *r)
{
    io_int(s, &r->kind);
    io_f64(s, r->p, 7);
}

/* The feeds and outlets (format 3). */
static void transfer_flows(io *s, dm_flows *f)
{
    io_section(s, "FLOW");
    io_count(s, &f->nfeeds, DM_MAX_FEEDS, "feeds");
    io_count(s, &f->noutlets, DM_MAX_OUTLETS, "outlets");
    io_u32(s, &f->live, 1);
    io_f64(s, &f->energy, 1);
    for (uint32_t k = 0; k < f->nfeeds && !s->status; k++) {
        dm_feed *e = &f->feeds[k];
        io_bool(s, &e->id.alive);
        io_u16(s, &e->id.gen);
        io_u32(s, &e->material, 1);
        transfer_region(s, &e->region);
        io_count(s, &e->sizes.n, DM_SIZE_CLASSES, "feed size classes");
        io_f64(s, e->sizes.lo, DM_SIZE_CLASSES);
        io_f64(s, e->sizes.hi, DM_SIZE_CLASSES);
        io_f64(s, e->sizes.fraction, DM_SIZE_CLASSES);
        io_f64(s, e->number, DM_SIZE_CLASSES);
        io_f64(s, &e->rate, 1);
        io_f64(s, e->vel, 3);
        io_f64(s, &e->t_start, 1);
        io_time(s, &e->t_stop);
        for (int q = 0; q < 4; q++)
            io_u64(s, &e->rng.s[q]);
        io_f64(s, &e->next_d, 1);
        io_f64(s, &e->mass, 1);
        io_u64(s, &e->count);
    }
    for (uint32_t k = 0; k < f->noutlets && !s->status; k++) {
        dm_outlet *o = &f->outlets[k];
        io_bool(s, &o->id.alive);
        io_u16(s, &o->id.gen);
        transfer_region(s, &o->region);
        io_count(s, &o->nedges, DM_OUTLET_CLASSES - 1, "outlet class edges");
        io_f64(s, o->edges, DM_OUTLET_CLASSES - 1);
        for (int q = 0; q < DM_OUTLET_CLASSES; q++)
            io_u64(s, &o->count[q]);
        io_f64(s, o->mass, DM_OUTLET_CLASSES);
        double *const v[] = {&o->interval, &o->t_next, &o->interval_mass, &o->last_mass};
        for (int q = 0; q < 4; q++)
            io_f64(s, v[q], 1);
        io_u64(s, &o->interval_count);
        io_u64(s, &o->last_count);
    }
}

/* A contact list: its kernel's history slots, and one more for the
 * collision spectrum while one is recorded (events); after the spectrum was
 * started or stopped the lists keep their old layout until they are rebuilt
 * (valid false). */
static void transfer_bucket(io *s, dm_bucket *b, int kernel, int dim, bool events, bool valid)
{
    io_count(s, &b->n, UINT32_MAX, "contact list length");
    uint32_t hs = (uint32_t)b->hs;
    io_u32(s, &hs, 1);
    const uint32_t base = (uint32_t)dm_kernel_hist_size(kernel, dim);
    if (s->reading && !s->status && (valid ? hs != base + events : hs < base || hs > base + 1))
        io_fail(s, DEMILL_ERR_FORMAT, "contact list %d keeps %u history values, not %u", kernel,
                hs, base + events);
    if (s->reading) {
        b->hs = (int)hs;
        b->kernel = kernel;
        b->cap = b->n;
    }
    io_array(s, &b->i, b->n, b->n, sizeof *b->i);
    io_array(s, &b->j, b->n, b->n, sizeof *b->j);
    io_array(s, &b->on, b->n, b->n, sizeof *b->on);
    io_f64_array(s, &b->hist, (size_t)b->n * hs, (size_t)b->n * hs);
}

/* The meshes of the mesh walls (their vertices, elements and frame; the rest
 * is built again from them, as when they were added) and the mesh element
 * of every particle-wall pair; before format 3, no mesh and elements 0. */
static void transfer_meshes(io *s, demill_world *w)
{
    if (s->format < 3) {
        for (int k = 0; k < DM_KERNELS && s->reading && !s->status; k++) {
            dm_bucket *b = &w->pw.b[k];
            if (!(b->t = calloc(b->n ? b->n : 1, sizeof *b->t)))
                io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
        }
        return;
    }
    io_section(s, "MESH");
    for (uint32_t k = 0; k < w->nwalls && !s->status; k++) {
        dm_wall *wl = &w->walls[k];
        if (wl->kind != DM_WALL_MESH)
            continue;
        dm_trimesh none = {.nel = w->dim}, *m = s->reading ? &none : wl->mesh;
        uint32_t nel = (uint32_t)m->nel;
        io_u32(s, &nel, 1);
        if (s->reading && !s->status && nel != (uint32_t)w->dim)
            io_fail(s, DEMILL_ERR_FORMAT, "wall %u: a mesh of %u-vertex elements in a %dD world",
                    k, nel, w->dim);
        io_count(s, &m->nv, UINT32_MAX, "mesh vertices");
        io_count(s, &m->nt, UINT32_MAX / 3, "mesh elements");
        if (s->reading && !s->status && !m->nt)
            io_fail(s, DEMILL_ERR_FORMAT, "wall %u: a mesh without elements", k);
        io_f64_array(s, &m->v, 3 * (size_t)m->nv, 3 * (size_t)m->nv);
        io_array(s, &m->el, (size_t)nel * m->nt, (size_t)nel * m->nt, sizeof *m->el);
        io_f64(s, m->frame_rot, 9);
        io_f64(s, m->frame_off, 3);
        if (!s->reading)
            continue;
        for (size_t q = 0; q < (size_t)nel * m->nt && !s->status; q++)
            if (m->el[q] >= m->nv)
                io_fail(s, DEMILL_ERR_FORMAT, "wall %u: element %zu names vertex %u of %u", k,
                        q / nel, m->el[q], m->nv);
        for (size_t t = 0; t < m->nt && !s->status; t++)
            if (dm_trimesh_degenerate((int)nel, m->v, m->el, t))
                io_fail(s, DEMILL_ERR_FORMAT, "wall %u: element %zu is degenerate", k, t);
        if (!s->status && !(wl->mesh = dm_trimesh_build((int)nel, m->nv, m->v, m->nt, m->el)))
            io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
        if (!s->status) {
            memcpy(wl->mesh->frame_rot, m->frame_rot, sizeof m->frame_rot);
            memcpy(wl->mesh->frame_off, m->frame_off, sizeof m->frame_off);
        }
        free(m->v);
        free(m->el);
    }
    for (int k = 0; k < DM_KERNELS && !s->status; k++) {
        dm_bucket *b = &w->pw.b[k];
        io_array(s, &b->t, b->n, b->n, sizeof *b->t);
    }
}

/* The bodies, and which walls are attached to which body. */
static void transfer_bodies(io *s, demill_world *w)
{
    /* the lengths of a body's arrays of doubles, in the order of f[] below */
    static const size_t len[] = {1, 3, 3, 3, 3, 3, 3, 3, 1, 1, 3, 3, 3, 1, 1};
    size_t doubles = 0;
    for (size_t q = 0; q < sizeof len / sizeof *len; q++)
        doubles += len[q];
    io_count(s, &w->nbodies, UINT32_MAX - 1, "body slots");
    /* a body's record: its handle, free axes and gravity flag, its doubles */
    io_room(s, w->nbodies, 3 * sizeof(int32_t) + doubles * sizeof(double), "bodies");
    io_array(s, &w->bodies, 0, w->nbodies, sizeof *w->bodies);
    if (s->reading && !s->status) {
        w->cap_bodies = w->nbodies;
        memset(w->bodies, 0, w->nbodies * sizeof *w->bodies);
    }
    for (uint32_t k = 0; k < w->nbodies && !s->status; k++) {
        dm_body *b = &w->bodies[k];
        io_u32(s, &b->handle, 1);
        io_int(s, &b->free_axes);
        io_int(s, &b->gravity);
        double *const f[] = {&b->mass, b->x,     b->v,       b->vp,       b->k,
                             b->c,     b->rest,  b->f0,      &b->freq,    &b->phase,
                             b->x_tally, b->fe_tally, b->fd_tally, &b->work, &b->dissipated};
        for (size_t q = 0; q < sizeof len / sizeof *len; q++)
            io_f64(s, f[q], len[q]);
    }
    transfer_handles(s, &w->bh, "body handles");
    for (uint32_t k = 0; k < w->nwalls && !s->status; k++) {
        io_u32(s, &w->walls[k].body, 1);
        io_f64(s, w->walls[k].body_ref, 3);
    }
}

/* The loads the walls record (format 3): per wall slot its number of
 * elements (0: it records none), then the time and the steps recorded and
 * DM_LOADS values per element. Only a wall with an id records, for as many
 * elements as it has. */
static void transfer_loads(io *s, demill_world *w)
{
    io_section(s, "LOAD");
    for (uint32_t k = 0; k < w->nwalls && !s->status; k++) {
        dm_wall *wl = &w->walls[k];
        uint32_t n = wl->loads ? wl->loads->n : 0;
        io_u32(s, &n, 1);
        if (!n || s->status)
            continue;
        if (s->reading) {
            if (!wl->kind || wl->handle == DM_FREE || n != dm_loads_elements(wl)) {
                io_fail(s, DEMILL_ERR_FORMAT, "wall %u: loads of %u elements on a wall %s", k,
                        n, wl->kind && wl->handle != DM_FREE ? "of another size" : "without an id");
                return;
            }
            if (s->left / (DM_LOADS * sizeof(double)) < n) {
                io_fail(s, DEMILL_ERR_FORMAT, "wall %u: loads of %u elements in %zu bytes", k, n,
                        s->left);
                return;
            }
            if (!(wl->loads = dm_loads_new(n))) {
                io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
                return;
            }
        }
        io_f64(s, &wl->loads->interval, 1);
        io_f64(s, &wl->loads->steps, 1);
        io_f64(s, wl->loads->v, DM_LOADS * (size_t)n);
        if (s->reading && !s->status && !(wl->loads->interval >= 0.0 && wl->loads->steps >= 0.0))
            io_fail(s, DEMILL_ERR_FORMAT, "wall %u: loads recorded over %g s in %g steps", k,
                    wl->loads->interval, wl->loads->steps);
    }
}

/* The clump templates and the clumps (section CLMP, from format 5 on; an
 * older file has none). A template: its material, spheres and place in
 * tmem, mass, inverse mass, volume, principal moments, axes and centre, and
 * for one made from a mesh the mesh's volume, the fit's deviations and its
 * cube side (0 for a template of spheres); then
 * the spheres' offsets and radii. A clump slot: its handle, and for a live
 * clump its template, its place in cmem and its motion (position, velocity,
 * orientation, angle, angular momentum and velocity, the velocities the
 * dashpots see); a free slot holds nothing else (a new clump overwrites
 * it). Then the members' particle handles and the clumps' handles. Which
 * particle is whose member is not stored: check_clumps() derives it. */
static void transfer_clumps(io *s, demill_world *w)
{
    if (s->format < 5)
        return;
    io_section(s, "CLMP");
    io_count(s, &w->ntemplates, UINT32_MAX - 1, "clump templates");
    io_count(s, &w->ntmem, UINT32_MAX, "template spheres");
    /* a template's record: 3 counts, 22 doubles */
    io_room(s, w->ntemplates, 3 * sizeof(uint32_t) + 22 * sizeof(double), "clump templates");
    io_array(s, &w->templates, 0, w->ntemplates, sizeof *w->templates);
    if (s->reading && !s->status) {
        w->cap_templates = w->ntemplates;
        memset(w->templates, 0, w->ntemplates * sizeof *w->templates);
    }
    for (uint32_t k = 0; k < w->ntemplates && !s->status; k++) {
        dm_template *t = &w->templates[k];
        io_u32(s, &t->material, 1);
        io_u32(s, &t->n, 1);
        io_u32(s, &t->first, 1);
        double *const f[] = {&t->mass,        &t->im,          &t->volume,
                             t->inertia,      t->axes,         t->centre,
                             &t->mesh_volume, &t->deviation_out, &t->deviation_in,
                             &t->cell};
        const size_t len[] = {1, 1, 1, 3, 9, 3, 1, 1, 1, 1};
        for (size_t q = 0; q < sizeof len / sizeof *len; q++)
            io_f64(s, f[q], len[q]);
    }
    if (s->reading)
        w->cap_tmem = w->ntmem;
    io_f64_array(s, &w->tmem, DM_TMEM * (size_t)w->ntmem, DM_TMEM * (size_t)w->ntmem);
    for (uint32_t k = 0; k < w->ntemplates && s->reading && !s->status; k++)
        dm_template_set_rpow(w, &w->templates[k]); /* derived, not stored */
    io_count(s, &w->nclumps, UINT32_MAX - 1, "clump slots");
    io_count(s, &w->live_clumps, w->nclumps, "live clumps");
    io_count(s, &w->ncmem, UINT32_MAX, "clump members");
    io_room(s, w->nclumps, sizeof(uint32_t), "clump slots");
    io_array(s, &w->clumps, 0, w->nclumps, sizeof *w->clumps);
    if (s->reading && !s->status) {
        w->cap_clumps = w->nclumps;
        memset(w->clumps, 0, w->nclumps * sizeof *w->clumps);
    }
    for (uint32_t k = 0; k < w->nclumps && !s->status; k++) {
        dm_clump *c = &w->clumps[k];
        io_u32(s, &c->handle, 1);
        if (c->handle == DM_FREE)
            continue;
        io_u32(s, &c->tmpl, 1);
        io_u32(s, &c->first, 1);
        double *const f[] = {c->x, c->v, c->q, &c->theta, c->L, c->om, c->vp, c->wp};
        const size_t len[] = {3, 3, 4, 1, 3, 3, 3, 3};
        for (size_t q = 0; q < sizeof len / sizeof *len; q++)
            io_f64(s, f[q], len[q]);
    }
    if (s->reading)
        w->cap_cmem = w->ncmem;
    io_array(s, &w->cmem, w->ncmem, w->ncmem, sizeof *w->cmem);
    transfer_handles(s, &w->clh, "clump handles");
}

/* Walks every field of state w. Reading, w starts zeroed (with its pointers
 * NULL) and the arrays are allocated as they are read. */
static void transfer(io *s, demill_world *w)
{
    io_section(s, "WRLD");
    uint32_t dim = (uint32_t)w->dim;
    io_u32(s, &dim, 1);
    if (s->reading && !s->status && dim != 2 && dim != 3)
        io_fail(s, DEMILL_ERR_FORMAT, "dimension %u, not 2 or 3", dim);
    if (s->status)
        return;
    if (s->reading)
        w->dim = (int)dim;
    const size_t D = dim, W = dim == 3 ? 3 : 1;
    io_f64(s, &w->dt, 1);
    io_f64(s, &w->time, 1);
    io_f64(s, w->g, 3);
    io_u64(s, &w->base.steps);
    io_u64(s, &w->rebuilds);
    io_int(s, &w->integrator);
    io_f64(s, &w->skin_fraction, 1);
    io_f64(s, &w->disc_thickness, 1);
    io_int(s, &w->energy_tracking);
    io_f64(s, &w->refine_tol, 1);
    io_int(s, &w->refine_max);
    io_u32(s, &w->iterations_last, 1);
    io_u64(s, &w->force_evals);
    io_u64(s, &w->unconverged);
    io_int(s, &w->watchdog);
    io_f64(s, &w->watch_overlap, 1);
    io_u32(s, &w->watch_interval, 1);
    if (s->format >= 6)
        io_bool(s, &w->single);
    if (s->format >= 7)
        io_bool(s, &w->orient);
    else /* earlier libraries always tracked them */
        w->orient = true;
    io_bool(s, &w->nlist_valid);
    io_bool(s, &w->forces_valid);
    io_bool(s, &w->events);
    io_f64(s, &w->skin, 1);
    io_u32(s, &w->ncontacts, 1);
    io_u32(s, &w->nwall_contacts, 1);
    io_f64(s, w->grid.lo, 3);
    io_f64(s, w->grid.hi, 3);
    dm_tally *ty = &w->tally;
    double *const tally[] = {&ty->diss_normal,  &ty->diss_tangential,      &ty->diss_friction,
                             &ty->diss_rolling, &ty->wall_work,            &ty->diss_plastic,
                             &ty->diss_rolling_viscous, &ty->work_cohesion, &ty->diss_local};
    for (int k = 0; k < (s->format < 4 ? 5 : 9); k++)
        io_f64(s, tally[k], 1);

    io_section(s, "MATS");
    io_count(s, &w->nmat, DM_MAX_MATERIALS, "materials");
    /* how many fields a material has and how many values a pair (format 4
     * writes them, so that a key appended since still reads an older file:
     * the fields a file lacks are 0, the pair values unset) */
    enum { MAT_FIELDS = 11 };
    uint32_t mfields = MAT_FIELDS, pkeys = DM_PK_COUNT;
    if (s->format >= 4) {
        io_count(s, &mfields, MAT_FIELDS, "fields per material");
        io_count(s, &pkeys, DM_PK_COUNT, "values per material pair");
    } else {
        mfields = 7;
        pkeys = DM_PK_COUNT_V2;
    }
    for (uint32_t k = 0; k < w->nmat && !s->status; k++) {
        dm_material *m = &w->mats[k];
        double *const f[MAT_FIELDS] = {&m->density,     &m->youngs,   &m->poisson,
                                       &m->stiffness,   &m->restitution, &m->friction,
                                       &m->rolling_friction, &m->yield_stress,
                                       &m->local_damping, &m->rigid, &m->surface_energy};
        for (uint32_t q = 0; q < MAT_FIELDS; q++) {
            if (s->reading)
                *f[q] = 0.0;
            if (q < mfields)
                io_f64(s, f[q], 1);
        }
    }
    io_count(s, &w->npairs, (uint64_t)w->nmat * (w->nmat + 1) / 2, "material pairs");
    if (s->reading)
        w->cap_pairs = w->npairs;
    io_room(s, w->npairs, 100, "material pairs");
    io_array(s, &w->pairs, 0, w->npairs, sizeof *w->pairs);
    for (uint32_t k = 0; k < w->npairs && !s->status; k++) {
        dm_pair_user *u = &w->pairs[k];
        if (s->reading) /* what older formats do not hold: none, and unset */
            memset(u, 0, sizeof *u);
        io_u32(s, &u->a, 1);
        io_u32(s, &u->b, 1);
        int *const law[] = {&u->normal, &u->damping, &u->tangential, &u->rolling,
                            &u->cohesion};
        for (int l = 0; l < (s->format < 4 ? 4 : 5); l++)
            io_int(s, law[l]);
        io_f64(s, u->value, pkeys);
        io_u32(s, &u->set, 1);
        if (s->reading && !s->status && (uint64_t)u->set >> pkeys)
            io_fail(s, DEMILL_ERR_FORMAT, "material pair %u overrides keys beyond its %u values",
                    k, pkeys);
    }

    io_section(s, "PART");
    dm_particles *P = &w->p;
    io_count(s, &P->n, UINT32_MAX - 1, "particles");
    if (s->reading)
        P->cap = P->n;
    const size_t n = P->n;
    double **const vec[] = {&P->x, &P->v, &P->f, &P->x0, &P->vp, &P->w, &P->t, &P->wp,
                            &P->theta, &P->r, &P->m, &P->im, &P->iinv};
    const size_t per[] = {D, D, D, D, D, W, W, W, 1, 1, 1, 1, 1};
    for (size_t k = 0; k < sizeof per / sizeof *per; k++)
        io_f64_array(s, vec[k], n * per[k], n * per[k]);
    io_array(s, &P->mat, n, n, sizeof *P->mat);
    io_array(s, &P->hid, n, n, sizeof *P->hid);
    if (s->reading && !s->status && !(P->clump = calloc(n ? n : 1, sizeof *P->clump)))
        io_fail(s, DEMILL_ERR_OUT_OF_MEMORY, "out of memory"); /* no clumps: every particle free */
    transfer_handles(s, &w->ph, "particle handles");
    if (w->dim == 3)
        transfer_orientations(s, P, n);

    io_section(s, "WALL");
    io_count(s, &w->nwalls, UINT32_MAX - 1, "wall slots");
    io_room(s, w->nwalls, 1000, "walls");
    io_array(s, &w->walls, 0, w->nwalls, sizeof *w->walls);
    if (s->reading && !s->status) {
        w->cap_walls = w->nwalls;
        memset(w->walls, 0, w->nwalls * sizeof *w->walls);
    }
    for (uint32_t k = 0; k < w->nwalls && !s->status; k++)
        transfer_wall(s, &w->walls[k]);
    transfer_handles(s, &w->wh, "wall handles");
    if (s->format >= 3) {
        io_section(s, "WFIN");
        for (uint32_t k = 0; k < w->nwalls && !s->status; k++)
            transfer_wall_finite(s, &w->walls[k]);
    }

    io_section(s, "DRUM");
    io_u16(s, &w->drum_gen);
    transfer_drum(s, &w->drum, w->dim);
    if (s->format >= 3) { /* the drum's translation */
        dm_drum *d = &w->drum;
        io_section(s, "DRMV");
        double *const f[] = {d->centre_set, d->velocity, d->vib_amp, &d->vib_freq,
                             &d->vib_phase, &d->t_move, d->centre, d->vcentre};
        const size_t len[] = {3, 3, 3, 1, 1, 1, 3, 3};
        for (size_t k = 0; k < sizeof len / sizeof *len; k++)
            io_f64(s, f[k], len[k]);
    }

    io_section(s, "CONT");
    /* the lists of the kernels up to the last that holds pairs (before
     * format 4, of the fast ones, which were all there were); the others
     * are empty */
    uint32_t lists = DM_FAST_KERNELS;
    if (s->format >= 4) {
        /* from the lists themselves, not from w->nkern, which a resolve of
         * the pair table changes without changing the world */
        for (lists = s->reading ? 0 : DM_KERNELS; lists > DM_FAST_KERNELS &&
                                                  !w->pp.b[lists - 1].n && !w->pw.b[lists - 1].n;)
            lists--;
        io_count(s, &lists, DM_KERNELS, "contact lists");
    }
    for (int side = 0; side < 2; side++)
        for (int k = 0; k < (int)lists; k++)
            transfer_bucket(s, side ? &w->pw.b[k] : &w->pp.b[k], k, w->dim, w->events,
                            w->nlist_valid);
    for (int side = 0; side < 2 && s->reading; side++)
        for (int k = (int)lists; k < DM_KERNELS; k++) { /* empty, in their layout */
            dm_bucket *b = side ? &w->pw.b[k] : &w->pp.b[k];
            b->kernel = k;
            b->hs = dm_kernel_hist_size(k, w->dim) + w->events;
        }
    if (s->reading) /* every list may hold pairs until the pair table is resolved */
        w->nkern = (int)lists;
    transfer_meshes(s, w);
    if (s->format >= 3)
        transfer_flows(s, &w->flows);
    if (s->format >= 3) {
        io_section(s, "BODY");
        transfer_bodies(s, w);
        transfer_loads(s, w);
    }
    transfer_clumps(s, w);
    io_section(s, "END.");
}

/* ---- checking what was read ------------------------------------------------- */

/* Feeds and outlets as their API makes them: a region the API would take,
 * sizes, rates and classes in their bounds, the live count right. */
static demill_status check_flows(demill_world *t)
{
    const dm_flows *f = &t->flows;
    uint32_t live = 0;
    for (uint32_t k = 0; k < f->nfeeds + f->noutlets; k++) {
        const bool feed = k < f->nfeeds;
        const dm_feed *e = feed ? &f->feeds[k] : NULL;
        const dm_outlet *o = feed ? NULL : &f->outlets[k - f->nfeeds];
        const dm_flow_slot id = feed ? e->id : o->id;
        const dm_region *r = feed ? &e->region : &o->region;
        dm_region parsed;
        bool ok = id.alive || id.gen > 0;
        live += id.alive;
        if (id.alive) {
            ok &= dm_region_parse(t, "checkpoint", r->kind, r->p,
                                  r->kind == DEMILL_REGION_DRUM ? 0
                                  : r->kind == DEMILL_REGION_CYLINDER ? 7 : 6,
                                  feed, &parsed) == DEMILL_OK;
            if (feed) {
                ok &= e->material < t->nmat && e->sizes.n >= 1 && e->rate > 0.0 &&
                      e->t_stop > e->t_start && e->next_d > 0.0 && e->mass >= 0.0;
                for (uint32_t q = 0; q < e->sizes.n; q++)
                    ok &= e->sizes.lo[q] > 0.0 && e->sizes.hi[q] >= e->sizes.lo[q] &&
                          e->number[q] >= 0.0 && e->number[q] <= 1.0;
            } else {
                ok &= o->interval > 0.0;
                for (uint32_t q = 0; q < o->nedges; q++)
                    ok &= o->edges[q] > (q ? o->edges[q - 1] : 0.0);
            }
        }
        if (!ok)
            return dm_fail(t, DEMILL_ERR_FORMAT, "%s %u is inconsistent", feed ? "feed" : "outlet",
                           feed ? k : k - f->nfeeds);
    }
    if (live != f->live)
        return dm_fail(t, DEMILL_ERR_FORMAT, "%u feeds and outlets alive, %u counted", live,
                       f->live);
    return DEMILL_OK;
}

/* Checks a value against the bounds demill_*_set() would check; read-only
 * keys pass. */
static demill_status check_param(demill_world *t, int32_t key, double value)
{
    demill_status s = dm_check_value(t, key, value);
    return s == DEMILL_ERR_READ_ONLY ? DEMILL_OK : s;
}

static demill_status check_params(demill_world *t)
{
    demill_status s;
    double v;
    for (int32_t key = 100; key < 150; key++)
        if (key != DEMILL_WORLD_THREADS && demill_param_name(key) &&
            demill_world_get(t, key, &v) == DEMILL_OK && (s = check_param(t, key, v)))
            return s;
    if (t->dim == 2 && t->g[2] != 0.0)
        return dm_fail(t, DEMILL_ERR_FORMAT, "a 2D world with gravity z = %g", t->g[2]);
    if (t->dim == 3 && t->disc_thickness != 0.0)
        return dm_fail(t, DEMILL_ERR_FORMAT, "a 3D world with a disc thickness");
    for (uint32_t m = 0; m < t->nmat; m++)
        for (int32_t key = 200; key < 300; key++)
            if (demill_param_name(key) &&
                (demill_material_get(t, dm_material_id(t, m), key, &v) == DEMILL_OK) &&
                (s = check_param(t, key, v)))
                return s;
    for (uint32_t k = 0; k < t->npairs; k++) {
        const dm_pair_user *u = &t->pairs[k];
        if (u->a > u->b || u->b >= t->nmat || dm_pair_find(t, u->a, u->b) != u)
            return dm_fail(t, DEMILL_ERR_FORMAT, "pair %u names materials %u and %u", k, u->a,
                           u->b);
        if (u->set >> DM_PK_COUNT)
            return dm_fail(t, DEMILL_ERR_FORMAT, "pair %u overrides unknown keys", k);
        const int law[] = {u->normal, u->damping, u->tangential, u->rolling, u->cohesion};
        for (int l = 0; l < 5; l++)
            if (law[l] && (s = check_param(t, DEMILL_PAIR_NORMAL + l, law[l])))
                return s;
        for (int32_t key = 300; key < 400; key++)
            if (demill_param_name(key) &&
                demill_pair_get(t, dm_material_id(t, u->a), dm_material_id(t, u->b), key, &v) ==
                    DEMILL_OK &&
                (s = check_param(t, key, v)))
                return s;
    }
    return DEMILL_OK;
}

/* Handles map one to one onto `live` objects; the free ones are listed once
 * each, and the others are retired (at their last generation). */
static demill_status check_handles(demill_world *t, const dm_handles *h, uint32_t live,
                                   const char *what)
{
    uint32_t used = 0;
    for (uint32_t k = 0; k < h->n; k++)
        used += h->slot[k] != DM_FREE;
    if (used != live || used + h->nfree > h->n)
        return dm_fail(t, DEMILL_ERR_FORMAT, "%s: %u in use and %u free of %u, for %u objects",
                       what, used, h->nfree, h->n, live);
    uint8_t *seen = calloc(h->n ? h->n : 1, 1);
    if (!seen)
        return dm_fail(t, DEMILL_ERR_OUT_OF_MEMORY, "out of memory checking %s", what);
    demill_status s = DEMILL_OK;
    for (uint32_t k = 0; k < h->nfree && !s; k++) {
        const uint32_t f = h->free[k];
        if (f >= h->n || h->slot[f] != DM_FREE || h->gen[f] == DM_GEN_LAST || seen[f]++)
            s = dm_fail(t, DEMILL_ERR_FORMAT, "%s: free list entry %u is %u", what, k, f);
    }
    for (uint32_t k = 0; k < h->n && !s; k++)
        if (h->slot[k] == DM_FREE && !seen[k] && h->gen[k] != DM_GEN_LAST)
            s = dm_fail(t, DEMILL_ERR_FORMAT, "%s: %u is neither in use, free nor retired", what,
                        k);
    free(seen);
    return s;
}

static bool all_finite(const double *v, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return false;
    return true;
}

static demill_status check_particles(demill_world *t)
{
    const dm_particles *P = &t->p;
    const size_t D = (size_t)t->dim, W = (size_t)dm_wdim(t);
    demill_status s = check_handles(t, &t->ph, P->n, "particle handles");
    if (s)
        return s;
    for (uint32_t i = 0; i < P->n; i++) {
        if (P->mat[i] >= t->nmat || P->hid[i] >= t->ph.n || t->ph.slot[P->hid[i]] != i)
            return dm_fail(t, DEMILL_ERR_FORMAT, "particle %u: material %u, handle %u", i,
                           P->mat[i], P->hid[i]);
        const double scalars[] = {P->r[i], P->m[i], P->im[i], P->iinv[i]};
        if (!all_finite(P->x + D * i, D) || !all_finite(P->v + D * i, D) ||
            !all_finite(P->w + W * i, W) || !all_finite(scalars, 4) || !(P->r[i] > 0) ||
            !(P->m[i] > 0) || P->im[i] < 0 || P->iinv[i] < 0)
            return dm_fail(t, DEMILL_ERR_FORMAT,
                           "particle %u: a position, velocity, radius or mass that is not "
                           "finite and positive",
                           i);
        /* a fixed particle: both inverses 0, at rest */
        bool rest = true;
        for (size_t c = 0; c < D; c++)
            rest &= P->v[D * i + c] == 0.0;
        for (size_t c = 0; c < W; c++)
            rest &= P->w[W * i + c] == 0.0;
        if ((P->im[i] == 0) != (P->iinv[i] == 0) || (P->im[i] == 0 && !rest))
            return dm_fail(t, DEMILL_ERR_FORMAT,
                           "particle %u: fixed in part (1/m %g, 1/I %g) or moving", i, P->im[i],
                           P->iinv[i]);
    }
    return DEMILL_OK;
}

/* A wall's finite shape, caps and motions are what the API makes: a unit
 * axis or normal (and a rectangle's unit direction in its plane); a cap
 * names a live wall that names it back, shares its kind and material; a
 * harmonic motion has a unit axis and a positive frequency; every value is
 * finite. */
static bool finite_wall_ok(const demill_world *t, uint32_t k)
{
    const dm_wall *wl = &t->walls[k];
    const double v[] = {wl->bh, wl->h_amp, wl->h_freq, wl->h_phase, wl->h_t0};
    bool ok = all_finite(wl->seg, 4) && all_finite(wl->nb, 4) && all_finite(wl->e0, 3) &&
              all_finite(v, 5) && all_finite(wl->h_axis, 3) && all_finite(wl->surf0, 3) &&
              wl->own >= 0 && wl->own <= 3 && (wl->surface == 0 || wl->surface == 1) &&
              wl->harmonic >= 0 && wl->harmonic <= DM_HARMONIC_ROTATE;
    if (wl->harmonic) {
        const double *a = wl->h_axis;
        ok &= wl->h_freq > 0.0 && fabs(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - 1.0) < 1e-9;
    }
    const double *n = wl->n0, *e = wl->e0;
    const bool finite = wl->kind == DM_WALL_REVOLVED || wl->kind == DM_WALL_RECT;
    if (finite) /* a unit axis or normal, and a bounding sphere */
        ok &= all_finite(n, 3) && fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-9 &&
              isfinite(wl->brad) && wl->brad >= 0.0;
    if (wl->kind == DM_WALL_REVOLVED)
        ok &= wl->seg[0] >= 0.0 && wl->seg[2] >= 0.0 &&
              (wl->seg[0] != wl->seg[2] || wl->seg[1] != wl->seg[3]);
    if (wl->kind == DM_WALL_RECT) /* and a unit direction in its plane */
        ok &= wl->seg[0] > 0.0 && wl->seg[1] > 0.0 &&
              fabs(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] - 1.0) < 1e-9 &&
              fabs(e[0] * n[0] + e[1] * n[1] + e[2] * n[2]) < 1e-9;
    if (wl->parent) {
        const uint32_t p = wl->parent - 1;
        ok &= p < t->nwalls && p != k && t->walls[p].kind == wl->kind &&
              t->walls[p].material == wl->material && !t->walls[p].parent &&
              (t->walls[p].parts[0] == k + 1 || t->walls[p].parts[1] == k + 1) &&
              !wl->parts[0] && !wl->parts[1];
    }
    for (int q = 0; q < 2; q++) {
        const uint32_t c = wl->parts[q];
        ok &= !c || (c - 1 < t->nwalls && t->walls[c - 1].kind && t->walls[c - 1].parent == k + 1);
    }
    return ok;
}

static demill_status check_walls(demill_world *t)
{
    const dm_drum *d = &t->drum;
    uint32_t user = 0, drum = 0;
    for (uint32_t k = 0; k < t->nwalls; k++) {
        const dm_wall *wl = &t->walls[k];
        if (!wl->kind)
            continue;
        bool ok = wl->kind >= DM_WALL_PLANE && wl->kind <= DM_WALL_RECT &&
                  (wl->kind == DM_WALL_MESH) == (wl->mesh != NULL) &&
                  wl->material < t->nmat && wl->npoly >= 0 && wl->npoly <= DM_MAX_POLY &&
                  finite_wall_ok(t, k);
        if (dm_wall_attached(wl) && !wl->parent) { /* a user's wall, attached to the drum */
            user++;
            ok &= d->alive && wl->drum_part <= DM_PART_LIFTER && wl->lifter == -1 &&
                  (wl->drum_part != DM_PART_CAP || t->dim == 3) && wl->handle < t->wh.n &&
                  t->wh.slot[wl->handle] == k;
        } else if (wl->parent) { /* a cap, attached to the drum with its wall or not */
            ok &= wl->handle == DM_FREE && wl->parent - 1 < t->nwalls &&
                  wl->drum_part == t->walls[wl->parent - 1].drum_part &&
                  (!wl->drum_part || wl->lifter == -1);
        } else if (wl->drum_part) {
            drum++;
            bool listed = false;
            for (uint32_t q = 0; q < d->nwall; q++)
                listed |= d->wall_slot[q] == k;
            ok &= listed && wl->handle == DM_FREE && wl->drum_part <= DM_PART_LIFTER &&
                  wl->lifter >= (wl->drum_part == DM_PART_LIFTER ? 0 : -1) &&
                  wl->lifter < (int)d->nlifters;
        } else {
            user++;
            ok &= wl->handle < t->wh.n && t->wh.slot[wl->handle] == k;
        }
        if (!ok)
            return dm_fail(t, DEMILL_ERR_FORMAT, "wall slot %u is inconsistent", k);
    }
    bool materials = true;
    for (int q = 0; q < 3; q++)
        materials &= d->material[q] < t->nmat;
    if (drum != d->nwall || (d->nwall && (!d->alive || !materials)))
        return dm_fail(t, DEMILL_ERR_FORMAT, "the drum lists %u walls, %u found", d->nwall, drum);
    /* a drum's walls are its shell and its end caps (3D) if it has them, and
     * its lifters, in order */
    const uint32_t caps = t->dim == 3 ? 2 : 0, shell = d->shell ? 1 + caps : 0;
    if (d->alive && d->nwall != shell + d->nlifters)
        return dm_fail(t, DEMILL_ERR_FORMAT, "a drum of %u lifters with %u walls", d->nlifters,
                       d->nwall);
    for (uint32_t q = 0; q < d->nwall; q++) {
        const dm_wall *wl = &t->walls[d->wall_slot[q]];
        const bool ok = q < shell && q == 0 ? wl->drum_part == DM_PART_SHELL &&
                                                  wl->kind == DM_WALL_SHELL
                        : q < shell ? wl->drum_part == DM_PART_CAP && wl->kind == DM_WALL_PLANE
                                    : wl->drum_part == DM_PART_LIFTER &&
                                          wl->kind == DM_WALL_PRISM &&
                                          wl->lifter == (int)(q - shell);
        if (!ok || wl->material != d->material[wl->drum_part - 1])
            return dm_fail(t, DEMILL_ERR_FORMAT, "drum wall %u is not the part it should be", q);
    }
    for (uint32_t k = 0; k < t->wh.n; k++)
        if (t->wh.slot[k] != DM_FREE && t->wh.slot[k] >= t->nwalls)
            return dm_fail(t, DEMILL_ERR_FORMAT, "wall handle %u names slot %u", k,
                           t->wh.slot[k]);
    return check_handles(t, &t->wh, user, "wall handles");
}

/* Every body's values within the bounds demill_body_*() enforce, its
 * handle its own, and every wall attached to a live body and one that
 * demill_body_attach_wall() accepts (not the drum's, without caps, without
 * harmonic motion). */
static demill_status check_bodies(demill_world *t)
{
    uint32_t live = 0;
    const int axes = t->dim == 3 ? 7 : 3;
    for (uint32_t k = 0; k < t->nbodies; k++) {
        const dm_body *b = &t->bodies[k];
        if (b->handle == DM_FREE)
            continue;
        live++;
        bool ok = b->handle < t->bh.n && t->bh.slot[b->handle] == k && b->mass > 0 &&
                  (b->free_axes & ~axes) == 0 && (b->gravity == 0 || b->gravity == 1) &&
                  b->freq >= 0;
        for (int c = 0; c < 3; c++)
            ok &= b->k[c] >= 0 && b->c[c] >= 0 && (t->dim == 3 || c < 2 || b->f0[c] == 0);
        if (!ok)
            return dm_fail(t, DEMILL_ERR_FORMAT, "body slot %u is inconsistent", k);
    }
    for (uint32_t k = 0; k < t->bh.n; k++)
        if (t->bh.slot[k] != DM_FREE && t->bh.slot[k] >= t->nbodies)
            return dm_fail(t, DEMILL_ERR_FORMAT, "body handle %u names slot %u", k,
                           t->bh.slot[k]);
    for (uint32_t k = 0; k < t->nwalls; k++) {
        const dm_wall *wl = &t->walls[k];
        if (wl->body && (wl->body > t->nbodies || t->bodies[wl->body - 1].handle == DM_FREE ||
                         !wl->kind || wl->drum_part || wl->parent || wl->parts[0] ||
                         wl->parts[1] || wl->harmonic))
            return dm_fail(t, DEMILL_ERR_FORMAT, "wall slot %u is attached to body slot %u", k,
                           wl->body - 1);
    }
    return check_handles(t, &t->bh, live, "body handles");
}

static demill_status check_drum(demill_world *t)
{
    const dm_drum *d = &t->drum;
    if (d->alive) {
        demill_status s;
        double v;
        /* the speed as it was set; its other forms are derived, and may lie
         * outside their keys' bounds (or be NaN where the critical speed is
         * undefined) */
        const bool speed_key = d->speed_key == DEMILL_DRUM_SPEED ||
                               d->speed_key == DEMILL_DRUM_SPEED_RPM ||
                               d->speed_key == DEMILL_DRUM_SPEED_FRACTION;
        if (!speed_key || t->drum_gen == DM_GEN_LAST)
            return dm_fail(t, DEMILL_ERR_FORMAT, "drum: speed key %d, generation %u",
                           d->speed_key, (unsigned)t->drum_gen);
        if ((s = check_param(t, d->speed_key, d->speed_value)))
            return s;
        for (int32_t key = 400; key < 450; key++)
            if (key != DEMILL_DRUM_SPEED && key != DEMILL_DRUM_SPEED_RPM &&
                key != DEMILL_DRUM_SPEED_FRACTION && demill_param_name(key) &&
                demill_drum_get(t, dm_drum_id(t), key, &v) == DEMILL_OK &&
                (s = check_param(t, key, v)))
                return s;
        for (uint32_t k = 0; k < d->nlifters; k++)
            if ((s = dm_drum_check_lifter(t, &d->lifters[k], d->diameter)))
                return s;
        /* (the motion's keys are checked above, the centre's current value
         * with them) */
        if (!all_finite(d->centre_set, 3) || !isfinite(d->t_move) || !all_finite(d->vcentre, 3) ||
            (t->dim == 2 && (d->centre_set[2] != 0.0 || d->centre[2] != 0.0 ||
                             d->velocity[2] != 0.0 || d->vib_amp[2] != 0.0)))
            return dm_fail(t, DEMILL_ERR_FORMAT, "drum: its translation");
    }
    const dm_spectrum *sp = &d->spectrum;
    if (t->events != (sp->counts != NULL))
        return dm_fail(t, DEMILL_ERR_FORMAT, "the collision spectrum is half there");
    if (!sp->counts)
        return DEMILL_OK;
    bool ok = isfinite(sp->log_min) && isfinite(sp->log_span) && sp->log_span > 0;
    for (uint32_t k = 0; k + 1 < sp->nclasses; k++)
        ok &= isfinite(sp->edges[k]) && sp->edges[k] > 0 && (!k || sp->edges[k] > sp->edges[k - 1]);
    if (sp->ore)
        ok &= sp->ore <= t->nmat && sp->ore_classes >= 2 && sp->ore_bins >= 1 &&
              sp->ore_top > 0 && isfinite(sp->ore_log_min) && sp->ore_log_span > 0;
    return ok ? DEMILL_OK : dm_fail(t, DEMILL_ERR_FORMAT, "the collision spectrum's classes");
}

/* Templates as demill_clump_template_add() makes them: one after the other
 * in tmem, of at least one sphere of positive radius, of a live material,
 * their mass, inverse mass and volume as computed from each other and the
 * density, their principal moments positive (2D: 0, 0, I_z), their axes
 * orthonormal and right-handed (2D: x, y, z), the spheres in the plane in
 * 2D, and a fit's figures not negative. */
static demill_status check_templates(demill_world *t)
{
    uint64_t first = 0;
    for (uint32_t k = 0; k < t->ntemplates; k++) {
        const dm_template *tp = &t->templates[k];
        const double *I = tp->inertia, *a = tp->axes;
        if (!tp->n)
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump template %u has no spheres", k);
        bool ok = tp->first == first && (uint64_t)tp->first + tp->n <= t->ntmem &&
                  tp->material < t->nmat && tp->mass > 0.0 && tp->im == 1.0 / tp->mass &&
                  tp->volume == tp->mass / t->mats[tp->material].density &&
                  tp->mesh_volume >= 0.0 && tp->deviation_out >= 0.0 &&
                  tp->deviation_in >= 0.0 && tp->cell >= 0.0;
        if (t->dim == 3) {
            for (int c = 0; c < 3; c++)
                ok &= I[c] > 0.0 && isfinite(1.0 / I[c]);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    ok &= fabs(a[3 * i] * a[3 * j] + a[3 * i + 1] * a[3 * j + 1] +
                               a[3 * i + 2] * a[3 * j + 2] - (i == j)) < 1e-9;
            const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) -
                               a[1] * (a[3] * a[8] - a[5] * a[6]) +
                               a[2] * (a[3] * a[7] - a[4] * a[6]);
            ok &= det > 0.0;
        } else {
            ok &= I[0] == 0.0 && I[1] == 0.0 && I[2] > 0.0 && isfinite(1.0 / I[2]) &&
                  tp->centre[2] == 0.0;
            for (int c = 0; c < 9; c++)
                ok &= a[c] == (c % 4 == 0);
        }
        for (uint32_t m = 0; ok && m < tp->n; m++) {
            const double *b = t->tmem + DM_TMEM * ((size_t)tp->first + m);
            ok &= b[3] > 0.0 && (t->dim == 3 || b[2] == 0.0);
        }
        if (!ok)
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump template %u is inconsistent", k);
        first += tp->n;
    }
    if (first != t->ntmem)
        return dm_fail(t, DEMILL_ERR_FORMAT, "clump templates hold %llu spheres, %u stored",
                       (unsigned long long)first, t->ntmem);
    return DEMILL_OK;
}

/* The clumps as the API leaves them: each live clump's handle its own, of
 * a template that exists, of unit orientation (to 1e-12, as the
 * particles'), in 2D in the plane and turning about z; its members, its
 * template's count of them in cmem, live particles of its template's
 * material and radii, with its mass and inertia, each the member of no
 * other clump; the live clumps' members all of cmem. Marks each member
 * with its clump (P->clump, which checkpoints do not store). */
static demill_status check_clumps(demill_world *t)
{
    dm_particles *P = &t->p;
    uint32_t live = 0;
    uint64_t members = 0;
    for (uint32_t k = 0; k < t->nclumps; k++) {
        const dm_clump *c = &t->clumps[k];
        if (c->handle == DM_FREE)
            continue;
        live++;
        if (c->handle >= t->clh.n || t->clh.slot[c->handle] != k || c->tmpl >= t->ntemplates)
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump %u: handle %u, template %u of %u", k,
                           c->handle, c->tmpl, t->ntemplates);
        const dm_template *tp = &t->templates[c->tmpl];
        const double *q = c->q;
        const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (!(fabs(n2 - 1.0) <= 1e-12))
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump %u: orientation of norm %.17g, not 1", k,
                           sqrt(n2));
        if (t->dim == 2 && (q[1] != 0.0 || q[2] != 0.0 || c->x[2] != 0.0 || c->v[2] != 0.0 ||
                            c->vp[2] != 0.0 || c->L[0] != 0.0 || c->L[1] != 0.0 ||
                            c->om[0] != 0.0 || c->om[1] != 0.0 || c->wp[0] != 0.0 ||
                            c->wp[1] != 0.0))
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump %u: a motion out of the plane of a 2D world",
                           k);
        if ((uint64_t)c->first + tp->n > t->ncmem)
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump %u: members %u to %llu of %u", k, c->first,
                           (unsigned long long)c->first + tp->n, t->ncmem);
        members += tp->n;
        const double iinv = t->dim == 3 ? 3.0 / (tp->inertia[0] + tp->inertia[1] + tp->inertia[2])
                                        : 1.0 / tp->inertia[2];
        for (uint32_t m = 0; m < tp->n; m++) {
            const uint32_t h = t->cmem[c->first + m];
            const uint32_t i = h < t->ph.n ? t->ph.slot[h] : DM_FREE;
            if (i == DM_FREE)
                return dm_fail(t, DEMILL_ERR_FORMAT, "clump %u: member %u is not a particle", k, m);
            if (P->clump[i])
                return dm_fail(t, DEMILL_ERR_FORMAT,
                               "clump %u: member %u is a member of clump %u too", k, m,
                               P->clump[i] - 1);
            const double r = t->tmem[DM_TMEM * ((size_t)tp->first + m) + 3];
            if (P->mat[i] != tp->material || P->r[i] != r || P->m[i] != tp->mass ||
                P->im[i] != tp->im || P->iinv[i] != iinv)
                return dm_fail(t, DEMILL_ERR_FORMAT,
                               "clump %u: member %u has another material, radius or mass than "
                               "its template's",
                               k, m);
            P->clump[i] = k + 1;
        }
    }
    if (live != t->live_clumps || members != t->ncmem)
        return dm_fail(t, DEMILL_ERR_FORMAT, "%u clumps of %llu members, %u and %u stored", live,
                       (unsigned long long)members, t->live_clumps, t->ncmem);
    for (uint32_t k = 0; k < t->clh.n; k++)
        if (t->clh.slot[k] != DM_FREE && t->clh.slot[k] >= t->nclumps)
            return dm_fail(t, DEMILL_ERR_FORMAT, "clump handle %u names slot %u", k,
                           t->clh.slot[k]);
    return check_handles(t, &t->clh, live, "clump handles");
}

/* Every listed pair joins live objects, in the list of its contact model,
 * sorted by first particle. */
static demill_status check_contacts(demill_world *t)
{
    const dm_particles *P = &t->p;
    for (int side = 0; side < 2; side++)
        for (int k = 0; k < DM_KERNELS; k++) {
            const dm_bucket *b = side ? &t->pw.b[k] : &t->pp.b[k];
            for (uint32_t q = 0; q < b->n; q++) {
                const uint32_t i = b->i[q], j = b->j[q];
                bool ok = i < P->n && (!q || b->i[q - 1] <= i) && b->on[q] <= 1;
                if (ok && !side) /* (never two members of one clump) */
                    ok = j < P->n && i < j && dm_pair_kernel(t, P->mat[i], P->mat[j]) == k &&
                         (!P->clump[i] || P->clump[i] != P->clump[j]);
                else if (ok)
                    ok = j < t->nwalls && t->walls[j].kind &&
                         dm_pair_kernel(t, P->mat[i], t->walls[j].material) == k &&
                         b->t[q] < (t->walls[j].mesh ? t->walls[j].mesh->nt : 1);
                if (!ok)
                    return dm_fail(t, DEMILL_ERR_FORMAT, "%s contact %u of list %d joins %u and %u",
                                   side ? "particle-wall" : "particle-particle", q, k, i, j);
            }
        }
    return DEMILL_OK;
}

/* ---- checkpoints ------------------------------------------------------------ */

/* The CRC-32 of ISO 3309 / zlib (reflected polynomial 0xEDB88320). */
static uint32_t crc32_of(const uint8_t *p, size_t n)
{
    uint32_t table[256];
    for (uint32_t k = 0; k < 256; k++) {
        uint32_t c = k;
        for (int b = 0; b < 8; b++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[k] = c;
    }
    uint32_t c = 0xFFFFFFFFu;
    for (size_t k = 0; k < n; k++)
        c = table[(c ^ p[k]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

/* The checkpoint of w, in a new buffer (*bytes of it). */
static demill_status encode(demill_world *w, uint8_t **out, size_t *bytes)
{
    io s = {.reading = false, .format = CK_FORMAT};
    uint8_t header[CK_HEADER] = {0};
    io_bytes(&s, header, sizeof header);
    transfer(&s, w);
    if (s.status) {
        free(s.buf);
        return dm_fail(w, s.status, "checkpoint: %s", s.why);
    }
    const uint32_t format = CK_FORMAT, order = CK_BYTE_ORDER, version = demill_version_number();
    const uint64_t payload = s.n - CK_HEADER;
    const uint32_t crc = crc32_of(s.buf + CK_HEADER, payload);
    memcpy(s.buf, CK_MAGIC, 8);
    memcpy(s.buf + 8, &format, 4);
    memcpy(s.buf + 12, &order, 4);
    memcpy(s.buf + 16, &payload, 8);
    memcpy(s.buf + 24, &crc, 4);
    memcpy(s.buf + 28, &version, 4);
    *out = s.buf;
    *bytes = s.n;
    return DEMILL_OK;
}

/* Reads a checkpoint into the new state t, checking everything. */
static demill_status decode(demill_world *t, const uint8_t *b, size_t size)
{
    if (size < CK_HEADER || memcmp(b, CK_MAGIC, 8)) {
        char start[9] = {0};
        for (size_t k = 0; k < 8 && k < size; k++)
            start[k] = b[k] >= 32 && b[k] < 127 ? (char)b[k] : '.';
        return dm_fail(t, DEMILL_ERR_FORMAT,
                       "not a libdemill checkpoint (%zu bytes, starting \"%s\")", size, start);
    }
    uint32_t format, order, crc, version;
    uint64_t payload;
    memcpy(&format, b + 8, 4);
    memcpy(&order, b + 12, 4);
    memcpy(&payload, b + 16, 8);
    memcpy(&crc, b + 24, 4);
    memcpy(&version, b + 28, 4);
    if (order != CK_BYTE_ORDER)
        return dm_fail(t, DEMILL_ERR_FORMAT,
                       "written on a machine of another byte order (mark 0x%08x)", order);
    if (format == 0 || format > CK_FORMAT)
        return dm_fail(t, DEMILL_ERR_FORMAT,
                       "format version %u (written by libdemill %u.%u.%u); this library reads "
                       "versions 1 to %u",
                       format, version / 10000, version / 100 % 100, version % 100, CK_FORMAT);
    if (payload != size - CK_HEADER)
        return dm_fail(t, DEMILL_ERR_FORMAT, "%s: the header says %llu bytes of data, there are %zu",
                       payload > size - CK_HEADER ? "truncated" : "trailing bytes",
                       (unsigned long long)payload, size - CK_HEADER);
    const uint32_t sum = crc32_of(b + CK_HEADER, payload);
    if (sum != crc)
        return dm_fail(t, DEMILL_ERR_FORMAT, "corrupt: checksum 0x%08x, the header says 0x%08x",
                       sum, crc);
    io s = {.reading = true, .format = format, .in = b + CK_HEADER, .left = payload};
    transfer(&s, t);
    if (!s.status && s.left)
        io_fail(&s, DEMILL_ERR_FORMAT, "%zu bytes after the end", s.left);
    if (s.status)
        return dm_fail(t, s.status, "%s", s.why);
    demill_status st;
    if ((st = check_params(t)) || (st = check_particles(t)) || (st = check_templates(t)) ||
        (st = check_clumps(t)) || (st = check_walls(t)) || (st = check_bodies(t)) ||
        (st = check_drum(t)) || (st = check_contacts(t)) || (st = check_flows(t)))
        return st == DEMILL_ERR_OUT_OF_MEMORY ? st : DEMILL_ERR_FORMAT;
    for (uint32_t i = 0; i < t->p.n; i++)
        t->mat_particles[t->p.mat[i]]++;
    for (uint32_t k = 0; k < t->nwalls; k++)
        if (t->walls[k].kind)
            t->mat_walls[t->walls[k].material]++;
    t->ptab_dirty = true;
    return DEMILL_OK;
}

static demill_status load(demill_world *w, const uint8_t *b, size_t size, const char *source)
{
    demill_world *t = calloc(1, sizeof *t);
    if (!t)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", source);
    t->base.magic = DM_WORLD_MAGIC; /* for the checks, which report through it */
    demill_status s = decode(t, b, size);
    if (s == DEMILL_OK && restore(w, t))
        s = dm_fail(t, DEMILL_ERR_OUT_OF_MEMORY, "out of memory");
    if (s)
        dm_fail(w, s, "%s: %s", source, t->base.error);
    dm_state_free(t);
    free(t);
    return s;
}

DEMILL_API demill_status demill_world_save_buffer(demill_world *w, void *buffer,
                                                  size_t capacity, size_t *size)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!buffer && !size)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_save_buffer: buffer and size are NULL");
    uint8_t *bytes;
    size_t n;
    if ((s = encode(w, &bytes, &n)))
        return s;
    if (size)
        *size = n;
    if (buffer && capacity < n)
        s = dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL,
                    "world_save_buffer: the checkpoint takes %zu bytes, the buffer %zu", n,
                    capacity);
    else if (buffer)
        memcpy(buffer, bytes, n);
    free(bytes);
    if (!s)
        dm_clear_error(w);
    return s;
}

DEMILL_API demill_status demill_world_load_buffer(demill_world *w, const void *buffer,
                                                  size_t size)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!buffer)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_load_buffer: buffer is NULL");
    return load(w, buffer, size, "checkpoint buffer");
}

DEMILL_API demill_status demill_world_save(demill_world *w, const char *path)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!path)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_save: path is NULL");
    uint8_t *bytes;
    size_t n;
    if ((s = encode(w, &bytes, &n)))
        return s;
    const size_t len = strlen(path);
    char *part = malloc(len + 6);
    if (!part) {
        free(bytes);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "world_save: out of memory");
    }
    memcpy(part, path, len);
    memcpy(part + len, ".part", 6);
    errno = 0;
    FILE *f = fopen(part, "wb");
    bool ok = f && fwrite(bytes, 1, n, f) == n;
    if (f)
        ok &= !fclose(f);
    ok = ok && !rename(part, path);
    if (!ok) {
        const int e = errno;
        remove(part);
        s = dm_fail(w, DEMILL_ERR_IO, "world_save: %s: %s", path,
                    e ? strerror(e) : "write failed");
    } else {
        dm_clear_error(w);
    }
    free(part);
    free(bytes);
    return s;
}

DEMILL_API demill_status demill_world_load(demill_world *w, const char *path)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!path)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_load: path is NULL");
    uint8_t *b;
    size_t n;
    if ((s = dm_read_file(w, "world_load", path, &b, &n)))
        return s;
    s = load(w, b, n, path);
    free(b);
    return s;
}

/* ---- listing ids ------------------------------------------------------------ */

/* A wall with an id of its own: free, or attached to the drum. */
static bool user_wall(const dm_wall *wall)
{
    return wall->kind && !wall->parent && (!wall->drum_part || dm_wall_attached(wall));
}

DEMILL_API demill_status demill_world_ids(const demill_world *cw, int32_t kind, demill_id *out,
                                          size_t capacity, size_t *count)
{
    demill_world *w = (demill_world *)cw;
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (kind == DEMILL_KIND_PARTICLE)
        return demill_particles_read_ids(w, DEMILL_PARTICLE_ID, out, capacity, count);
    if (kind < DEMILL_KIND_MATERIAL || kind > DEMILL_KIND_CLUMP)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "world_ids: %d is not a kind of object",
                       (int)kind);
    if (!out && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_ids: out and count are both NULL");
    size_t n = 0;
    if (kind == DEMILL_KIND_MATERIAL)
        n = w->nmat;
    else if (kind == DEMILL_KIND_DRUM)
        n = w->drum.alive;
    else if (kind == DEMILL_KIND_FEED)
        for (uint32_t k = 0; k < w->flows.nfeeds; k++)
            n += w->flows.feeds[k].id.alive;
    else if (kind == DEMILL_KIND_OUTLET)
        for (uint32_t k = 0; k < w->flows.noutlets; k++)
            n += w->flows.outlets[k].id.alive;
    else if (kind == DEMILL_KIND_BODY)
        for (uint32_t k = 0; k < w->nbodies; k++)
            n += dm_body_live(w, k);
    else if (kind == DEMILL_KIND_TEMPLATE)
        n = w->ntemplates;
    else if (kind == DEMILL_KIND_CLUMP)
        n = w->live_clumps;
    else
        for (uint32_t k = 0; k < w->nwalls; k++)
            n += user_wall(&w->walls[k]);
    if (count)
        *count = n;
    if (!out)
        return DEMILL_OK;
    if (capacity < n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "world_ids: capacity %zu, %zu objects",
                       capacity, n);
    if (kind == DEMILL_KIND_MATERIAL) {
        for (uint32_t m = 0; m < w->nmat; m++)
            out[m] = dm_material_id(w, m);
    } else if (kind == DEMILL_KIND_WALL) {
        for (uint32_t k = 0, q = 0; k < w->nwalls; k++)
            if (user_wall(&w->walls[k]))
                out[q++] = dm_wall_id(w, k);
    } else if (kind == DEMILL_KIND_FEED) {
        for (uint32_t k = 0, q = 0; k < w->flows.nfeeds; k++)
            if (w->flows.feeds[k].id.alive)
                out[q++] = dm_feed_id(w, k);
    } else if (kind == DEMILL_KIND_OUTLET) {
        for (uint32_t k = 0, q = 0; k < w->flows.noutlets; k++)
            if (w->flows.outlets[k].id.alive)
                out[q++] = dm_outlet_id(w, k);
    } else if (kind == DEMILL_KIND_BODY) {
        for (uint32_t k = 0, q = 0; k < w->nbodies; k++)
            if (dm_body_live(w, k))
                out[q++] = dm_body_id(w, k);
    } else if (kind == DEMILL_KIND_TEMPLATE) {
        for (uint32_t k = 0; k < w->ntemplates; k++)
            out[k] = dm_template_id(w, k);
    } else if (kind == DEMILL_KIND_CLUMP) {
        for (uint32_t k = 0, q = 0; k < w->nclumps; k++)
            if (dm_clump_live(w, k))
                out[q++] = dm_clump_id(w, k);
    } else if (n) { /* the drum */
        out[0] = dm_drum_id(w);
    }
    return DEMILL_OK;
}
