/* flows.c: feeds and outlets (demill/insert.h), the particles that enter and
 * leave a world while it runs. Their API, and dm_advance(), which steps a
 * world one step at a time while it has any, letting the outlets remove and
 * the feeds insert particles at the end of each step; without them it is
 * dm_integrate() itself. */
#include <math.h>
#include <string.h>

#include "demill/insert.h"
#include "world/world.h"

#define FEED_SETS 4 /* sets of candidate places a fed particle tries per step */

/* ---- ids --------------------------------------------------------------------- */

/* A free slot of a table of `max` feeds or outlets (each `stride` bytes,
 * starting with its dm_flow_slot) of which the first `used` have been used;
 * DM_FREE when all are alive or retired. */
static uint32_t free_slot(const void *table, size_t stride, uint32_t used, uint32_t max)
{
    for (uint32_t k = 0; k < max; k++) {
        const dm_flow_slot *f = (const dm_flow_slot *)((const char *)table + k * stride);
        if (k >= used || (!f->alive && f->gen != DM_GEN_LAST))
            return k;
    }
    return DM_FREE;
}

demill_id dm_feed_id(const demill_world *w, uint32_t slot)
{
    return dm_id_make(w->tag, DEMILL_KIND_FEED, w->flows.feeds[slot].id.gen, slot);
}

demill_id dm_outlet_id(const demill_world *w, uint32_t slot)
{
    return dm_id_make(w->tag, DEMILL_KIND_OUTLET, w->flows.outlets[slot].id.gen, slot);
}

/* ---- feeds ------------------------------------------------------------------- */

static double particle_mass(const demill_world *w, uint32_t mat, double d)
{
    double m, inv_i;
    dm_particle_mass(w, mat, 0.5 * d, &m, &inv_i);
    return m;
}

/* The diameter of the next particle of a feed: a class by its share of the
 * number, then a size in it. */
static double feed_draw(dm_feed *f)
{
    const double u = dm_rng_uniform(&f->rng);
    uint32_t k = 0;
    while (k + 1 < f->sizes.n && !(u < f->number[k]))
        k++;
    return dm_sizes_draw(&f->sizes, k, &f->rng);
}

DEMILL_API demill_status demill_feed_create(demill_world *w, int32_t region,
                                            const double *region_params, size_t nregion,
                                            demill_id material, int32_t distribution,
                                            const double *params, size_t nparams,
                                            double mass_rate, const double velocity[3],
                                            double t_start, double t_stop, uint64_t seed,
                                            demill_id *out)
{
    uint32_t mat;
    dm_feed f = {0};
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s ||
        (s = dm_region_parse(w, "feed_create", region, region_params, nregion, true, &f.region)) ||
        (s = dm_sizes_make(w, "feed_create", distribution, params, nparams, &f.sizes)))
        return s;
    if (!velocity || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "feed_create: %s is NULL",
                       !velocity ? "velocity" : "out");
    const double vals[] = {mass_rate, velocity[0], velocity[1], velocity[2], t_start};
    for (size_t k = 0; k < sizeof vals / sizeof *vals; k++)
        if (!isfinite(vals[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                           "feed_create: the %s %g is not finite",
                           k == 0 ? "mass rate" : k < 4 ? "velocity component" : "start time",
                           vals[k]);
    if (w->dim == 2 && velocity[2] != 0.0)
        return dm_fail(w, DEMILL_ERR_DIMENSION,
                       "feed_create: the velocity has z = %g but the world is 2D", velocity[2]);
    if (!(mass_rate > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "feed_create: the mass rate %g must be > 0",
                       mass_rate);
    if (!(t_stop > t_start))
        return dm_fail(w, isnan(t_stop) ? DEMILL_ERR_NOT_FINITE : DEMILL_ERR_INVALID_VALUE,
                       "feed_create: the stop time %g must be after the start time %g", t_stop,
                       t_start);
    double dmax = 0.0;
    for (uint32_t k = 0; k < f.sizes.n; k++)
        if (f.sizes.fraction[k] > 0.0)
            dmax = fmax(dmax, f.sizes.hi[k]);
    if (!dm_region_fits(w, &f.region, 0.5 * dmax))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "feed_create: a particle of diameter %g m does not fit in the region",
                       dmax);
    if ((s = dm_sizes_check_mass(w, "feed_create", mat, &f.sizes, NULL)))
        return s;
    dm_flows *fl = &w->flows;
    const uint32_t slot = free_slot(fl->feeds, sizeof(dm_feed), fl->nfeeds, DM_MAX_FEEDS);
    if (slot == DM_FREE)
        return dm_fail(w, DEMILL_ERR_LIMIT, "feed_create: the world has %d feeds, the most it "
                       "can hold", DM_MAX_FEEDS);
    /* the classes' cumulative shares of the number of particles */
    double sum = 0.0;
    dm_sizes_numbers(w, mat, &f.sizes, f.number);
    for (uint32_t k = 0; k < f.sizes.n; k++)
        f.number[k] = sum += f.number[k];
    for (uint32_t k = 0; k < f.sizes.n; k++)
        f.number[k] /= sum;
    f.id = (dm_flow_slot){true, slot < fl->nfeeds ? fl->feeds[slot].id.gen : 0};
    f.material = mat;
    f.rate = mass_rate;
    memcpy(f.vel, velocity, sizeof f.vel);
    f.t_start = t_start;
    f.t_stop = t_stop;
    dm_rng_seed(&f.rng, seed);
    f.next_d = feed_draw(&f);
    fl->feeds[slot] = f;
    if (slot >= fl->nfeeds)
        fl->nfeeds = slot + 1;
    fl->live++;
    *out = dm_feed_id(w, slot);
    dm_changed(w);
    return DEMILL_OK;
}

/* Ends a feed's or an outlet's life: its id becomes invalid, its slot free. */
static void release(demill_world *w, dm_flow_slot *id)
{
    id->alive = false;
    id->gen++;
    w->flows.live--;
    dm_changed(w);
}

DEMILL_API demill_status demill_feed_remove(demill_world *w, demill_id feed)
{
    uint32_t slot;
    demill_status s = dm_enter(w, feed, DEMILL_KIND_FEED, "feed", &slot);
    if (s)
        return s;
    release(w, &w->flows.feeds[slot].id);
    return DEMILL_OK;
}

/* The mass a feed owes by the world's time, in all. */
static double feed_owed(const demill_world *w, const dm_feed *f)
{
    const double t = fmin(w->time, f->t_stop) - f->t_start;
    return t > 0.0 ? f->rate * t : 0.0;
}

DEMILL_API demill_status demill_feed_read(demill_world *w, demill_id feed, double *mass,
                                          uint64_t *count, double *deficit)
{
    uint32_t slot;
    demill_status s = dm_enter(w, feed, DEMILL_KIND_FEED, "feed", &slot);
    if (s)
        return s;
    const dm_feed *f = &w->flows.feeds[slot];
    if (mass)
        *mass = f->mass;
    if (count)
        *count = f->count;
    if (deficit)
        *deficit = fmax(0.0, feed_owed(w, f) - f->mass);
    dm_clear_error(w);
    return DEMILL_OK;
}

/* Inserts what a feed owes and has room for; *added counts the particles. */
static demill_status feed_act(demill_world *w, dm_feed *f, size_t *added)
{
    const double owed = feed_owed(w, f);
    enum { BATCH = 256 };
    double rad[BATCH], pos[3 * BATCH], vel[3 * BATCH];
    size_t n = 0;
    double mass = f->mass, d = f->next_d;
    while (n < BATCH && mass + particle_mass(w, f->material, d) <= owed) {
        rad[n++] = 0.5 * d;
        mass += particle_mass(w, f->material, d);
        d = feed_draw(f);
    }
    if (!n)
        return DEMILL_OK;
    size_t placed;
    demill_status s = dm_place(w, &f->region, n, rad, NULL, FEED_SETS, &f->rng, pos, NULL, &placed);
    if (s || !placed)
        return s;
    for (size_t k = 0; k < placed; k++)
        memcpy(vel + 3 * k, f->vel, sizeof f->vel);
    if ((s = dm_particles_append(w, f->material, placed, pos, rad, vel, NULL)))
        return s;
    /* the first particle that found no place is tried again at the next step */
    f->next_d = placed < n ? 2.0 * rad[placed] : d;
    const int D = w->dim;
    for (size_t k = 0; k < placed; k++) {
        const double m = particle_mass(w, f->material, 2.0 * rad[k]);
        f->mass += m;
        for (int c = 0; c < D; c++)
            w->flows.energy += 0.5 * m * f->vel[c] * f->vel[c] - m * w->g[c] * pos[3 * k + c];
    }
    f->count += placed;
    *added += placed;
    return DEMILL_OK;
}

/* ---- outlets ----------------------------------------------------------------- */

DEMILL_API demill_status demill_outlet_create(demill_world *w, int32_t region,
                                              const double *region_params, size_t nregion,
                                              size_t nedges, const double *edges,
                                              double interval, demill_id *out)
{
    dm_outlet o = {0};
    demill_status s = dm_check_world(w);
    if (s ||
        (s = dm_region_parse(w, "outlet_create", region, region_params, nregion, false, &o.region)))
        return s;
    if ((nedges && !edges) || !out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "outlet_create: %s is NULL",
                       !out ? "out" : "edges");
    if (nedges > DM_OUTLET_CLASSES - 1)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "outlet_create: %zu class edges, at most %d",
                       nedges, DM_OUTLET_CLASSES - 1);
    for (size_t k = 0; k < nedges; k++) {
        if (!isfinite(edges[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "outlet_create: edges[%zu] = %g is not finite",
                           k, edges[k]);
        if (!(edges[k] > (k ? edges[k - 1] : 0.0)))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "outlet_create: edges[%zu] = %g must be > 0 and above the edge before",
                           k, edges[k]);
        o.edges[k] = edges[k];
    }
    if (!isfinite(interval))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "outlet_create: the interval %g is not finite",
                       interval);
    if (!(interval > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "outlet_create: the interval %g must be > 0",
                       interval);
    dm_flows *fl = &w->flows;
    const uint32_t slot = free_slot(fl->outlets, sizeof(dm_outlet), fl->noutlets,
                                    DM_MAX_OUTLETS);
    if (slot == DM_FREE)
        return dm_fail(w, DEMILL_ERR_LIMIT,
                       "outlet_create: the world has %d outlets, the most it can hold",
                       DM_MAX_OUTLETS);
    o.id = (dm_flow_slot){true, slot < fl->noutlets ? fl->outlets[slot].id.gen : 0};
    o.nedges = (uint32_t)nedges;
    o.interval = interval;
    o.t_next = w->time + interval;
    fl->outlets[slot] = o;
    if (slot >= fl->noutlets)
        fl->noutlets = slot + 1;
    fl->live++;
    *out = dm_outlet_id(w, slot);
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_outlet_remove(demill_world *w, demill_id outlet)
{
    uint32_t slot;
    demill_status s = dm_enter(w, outlet, DEMILL_KIND_OUTLET, "outlet", &slot);
    if (s)
        return s;
    release(w, &w->flows.outlets[slot].id);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_outlet_read(demill_world *w, demill_id outlet, uint64_t *counts,
                                            double *masses, size_t capacity, size_t *nclasses,
                                            double last[3])
{
    uint32_t slot;
    demill_status s = dm_enter(w, outlet, DEMILL_KIND_OUTLET, "outlet", &slot);
    if (s)
        return s;
    const dm_outlet *o = &w->flows.outlets[slot];
    const size_t nc = o->nedges + 1;
    if (nclasses)
        *nclasses = nc;
    if ((counts || masses) && capacity < nc)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "outlet_read: capacity %zu, %zu classes",
                       capacity, nc);
    if (counts)
        memcpy(counts, o->count, nc * sizeof *counts);
    if (masses)
        memcpy(masses, o->mass, nc * sizeof *masses);
    if (last) {
        last[0] = o->last_mass;
        last[1] = (double)o->last_count;
        last[2] = o->t_next - o->interval > w->time ? 0.0 : o->t_next - o->interval;
    }
    dm_clear_error(w);
    return DEMILL_OK;
}

/* Ends the intervals of an outlet that ended by `time`: the first of them
 * holds what was counted since the last, any later ones nothing. Counted
 * at once, not one by one, so that an interval far below the clock's
 * resolution (1e-300 s, or 1 ns at t = 1e8 s, where t + 1 ns = t) takes
 * no more time than another (one by one, t_next + interval stayed t_next:
 * a step never returned); such an interval ends at the next step. */
static void close_intervals(dm_outlet *o, double time)
{
    if (!(time >= o->t_next))
        return;
    const double ended = floor((time - o->t_next) / o->interval) + 1.0;
    o->last_mass = ended > 1.0 ? 0.0 : o->interval_mass;
    o->last_count = ended > 1.0 ? 0 : o->interval_count;
    o->interval_mass = 0.0;
    o->interval_count = 0;
    o->t_next += ended * o->interval;
    if (!(o->t_next > time && isfinite(o->t_next)))
        o->t_next = nextafter(time, INFINITY);
}

/* The particles whose centres are in an outlet, removed and counted (each
 * by the first outlet it is in); *removed counts them. Clumps' members are
 * left alone (outlets do not remove clumps yet). */
static demill_status outlets_act(demill_world *w, size_t *removed)
{
    dm_flows *fl = &w->flows;
    dm_particles *P = &w->p;
    const int D = w->dim, W = dm_wdim(w);
    for (uint32_t q = 0; q < fl->noutlets; q++)
        if (fl->outlets[q].id.alive)
            close_intervals(&fl->outlets[q], w->time);
    uint32_t *map = NULL;
    for (uint32_t i = 0; i < P->n; i++) {
        if (P->clump[i])
            continue;
        double x[3] = {0, 0, 0};
        memcpy(x, P->x + (size_t)D * i, (size_t)D * sizeof *x);
        uint32_t q = 0;
        while (q < fl->noutlets &&
               !(fl->outlets[q].id.alive && dm_region_contains(w, &fl->outlets[q].region, x, 0.0)))
            q++;
        if (q == fl->noutlets)
            continue;
        if (!map) {
            if (dm_grid_reserve(&w->grid, P->n))
                return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "outlets: out of memory");
            map = w->grid.inv;
            for (uint32_t k = 0; k < P->n; k++)
                map[k] = k;
        }
        map[i] = DM_FREE;
        dm_outlet *o = &fl->outlets[q];
        const double d = 2.0 * P->r[i], m = P->m[i];
        uint32_t k = 0;
        while (k < o->nedges && !(d < o->edges[k]))
            k++;
        o->count[k]++;
        o->mass[k] += m;
        o->interval_count++;
        o->interval_mass += m;
        for (int c = 0; c < D; c++)
            fl->energy -= 0.5 * m * P->v[D * i + c] * P->v[D * i + c] - m * w->g[c] * x[c];
        fl->energy -= dm_particle_spin_energy(P, i, W);
        ++*removed;
    }
    if (map)
        dm_particles_compact(w, map);
    return DEMILL_OK;
}

/* ---- stepping ---------------------------------------------------------------- */

demill_status dm_advance(demill_world *w, uint64_t steps)
{
    if (!w->flows.live)
        return dm_integrate(w, steps);
    dm_flows *fl = &w->flows;
    for (uint64_t k = 0; k < steps; k++) {
        size_t changed = 0;
        demill_status s = dm_integrate(w, 1);
        if (s || (s = outlets_act(w, &changed)))
            return s;
        for (uint32_t q = 0; q < fl->nfeeds && !s; q++)
            if (fl->feeds[q].id.alive)
                s = feed_act(w, &fl->feeds[q], &changed);
        if (s || (changed && (s = dm_prepare_step(w))))
            return s;
    }
    return DEMILL_OK;
}
