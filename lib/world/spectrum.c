/* spectrum.c: the drum's collision energy spectrum and the impacts on an
 * ore's particles, started and read through the API (the contact kernels
 * count them: lib/physics/contact/spectrum.c), and the grinding rates that
 * follow from the impacts (through the grinding object's API). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

DEMILL_API demill_status demill_drum_spectrum_start(demill_world *w, demill_id drum,
                                                    size_t nedges, const double *edges,
                                                    uint32_t nbins, double e_min, double e_max)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    if (nedges && !edges)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_spectrum_start: edges is NULL");
    if (nedges > 63)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_spectrum_start: at most 63 edges");
    for (size_t k = 0; k < nedges; k++) {
        if (!isfinite(edges[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "drum_spectrum_start: edges[%zu] = %g", k,
                           edges[k]);
        if (!(edges[k] > 0.0) || (k && !(edges[k] > edges[k - 1])))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "drum_spectrum_start: edges[%zu] = %g must be positive and increasing",
                           k, edges[k]);
    }
    if (!isfinite(e_min) || !isfinite(e_max))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "drum_spectrum_start: energy range not finite");
    if (!(e_min > 0.0) || !(e_max > e_min))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_spectrum_start: energies need 0 < e_min < e_max (%g, %g)", e_min,
                       e_max);
    if (nbins < 1 || nbins > 10000)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_spectrum_start: nbins %u not in 1..10000",
                       nbins);
    dm_spectrum sp = {.nclasses = (uint32_t)nedges + 1, .nbins = nbins,
                      .log_min = log10(e_min), .log_span = log10(e_max) - log10(e_min)};
    if (!(sp.log_span > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_spectrum_start: e_max = %.17g is too close to e_min = %.17g for "
                       "their logarithms to differ",
                       e_max, e_min);
    sp.edges = malloc((nedges ? nedges : 1) * sizeof *sp.edges);
    sp.counts = calloc(dm_spectrum_counters(&sp), sizeof *sp.counts);
    if (!sp.edges || !sp.counts) {
        free(sp.edges);
        free(sp.counts);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "drum_spectrum_start: out of memory");
    }
    if (nedges)
        memcpy(sp.edges, edges, nedges * sizeof *edges);
    dm_spectrum_free(w);
    w->drum.spectrum = sp;
    if (!w->events) {
        /* contacts gain the slot that carries their energy: rebuild the
         * lists (histories are carried over) */
        w->events = true;
        w->nlist_valid = false;
    }
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_spectrum(demill_world *w, demill_id drum, uint64_t *counts,
                                              size_t capacity, size_t *count)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    const dm_spectrum *sp = &w->drum.spectrum;
    if (!sp->counts)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_spectrum: no spectrum was started");
    if (!counts && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_spectrum: counts and count are NULL");
    const size_t n = dm_spectrum_collision_counters(sp);
    if (count)
        *count = n;
    if (!counts)
        return DEMILL_OK;
    if (capacity < n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "drum_spectrum: capacity %zu, %zu counters",
                       capacity, n);
    memcpy(counts, sp->counts, n * sizeof *counts);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_impacts_start(demill_world *w, demill_id drum,
                                                   demill_id material, double top_size,
                                                   uint32_t classes, uint32_t nbins, double e_min,
                                                   double e_max)
{
    uint32_t slot, mat;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = dm_resolve(w, material, DEMILL_KIND_MATERIAL, "material", &mat)))
        return s;
    dm_spectrum *sp = &w->drum.spectrum;
    if (!sp->counts)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_impacts_start: no collision spectrum is recorded "
                       "(demill_drum_spectrum_start first)");
    if (!isfinite(top_size) || !isfinite(e_min) || !isfinite(e_max))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                       "drum_impacts_start: top size %g m, energies %g to %g J/kg", top_size,
                       e_min, e_max);
    if (!(top_size > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_impacts_start: top size %g m, not > 0",
                       top_size);
    if (classes < 2 || classes > 200)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_impacts_start: %u classes, not 2 to 200",
                       classes);
    if (nbins < 1 || nbins > 10000)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_impacts_start: nbins %u not in 1..10000",
                       nbins);
    const double log_min = log10(e_min), log_span = log10(e_max) - log_min;
    if (!(e_min > 0.0) || !(e_max > e_min) || !(log_span > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_impacts_start: energies need 0 < e_min < e_max with logarithms that "
                       "differ (%.17g, %.17g J/kg)",
                       e_min, e_max);
    const size_t collisions = dm_spectrum_collision_counters(sp);
    uint64_t *counts = calloc(collisions + (size_t)classes * nbins, sizeof *counts);
    if (!counts)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "drum_impacts_start: out of memory");
    memcpy(counts, sp->counts, collisions * sizeof *counts);
    free(sp->counts);
    sp->counts = counts;
    sp->ore = mat + 1;
    sp->ore_classes = classes;
    sp->ore_bins = nbins;
    sp->ore_top = top_size;
    sp->ore_log_min = log_min;
    sp->ore_log_span = log_span;
    sp->ore_t0 = w->time;
    dm_changed(w);
    return DEMILL_OK;
}

/* The entry check of the impact readers: a drum that records impacts. */
static demill_status impacts_enter(demill_world *w, demill_id drum, const char *what)
{
    uint32_t slot;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s)
        return s;
    if (!w->drum.spectrum.ore)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: no impacts are recorded (demill_drum_impacts_start)", what);
    return DEMILL_OK;
}

/* Copies n counters out in the NULL-asks-the-count pattern. */
static demill_status read_counters(demill_world *w, const char *what, const uint64_t *src,
                                   size_t n, uint64_t *out, size_t capacity, size_t *count)
{
    if (!out && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: the buffer and count are NULL", what);
    if (count)
        *count = n;
    if (!out)
        return DEMILL_OK;
    if (capacity < n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "%s: capacity %zu, %zu values", what,
                       capacity, n);
    memcpy(out, src, n * sizeof *out);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_impacts(demill_world *w, demill_id drum, uint64_t *counts,
                                             size_t capacity, size_t *count, double *time)
{
    demill_status s = impacts_enter(w, drum, "drum_impacts");
    if (s)
        return s;
    const dm_spectrum *sp = &w->drum.spectrum;
    const size_t n = (size_t)sp->ore_classes * sp->ore_bins;
    if ((s = read_counters(w, "drum_impacts", sp->counts + dm_spectrum_collision_counters(sp), n,
                           counts, capacity, count)))
        return s;
    if (time)
        *time = w->time - sp->ore_t0;
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_impacts_particles(demill_world *w, demill_id drum,
                                                       uint64_t *particles, size_t capacity,
                                                       size_t *count)
{
    const char *what = "drum_impacts_particles";
    demill_status s = impacts_enter(w, drum, what);
    if (s)
        return s;
    const dm_spectrum *sp = &w->drum.spectrum;
    uint64_t n[200] = {0};
    for (uint32_t i = 0; i < w->p.n; i++)
        if (w->p.mat[i] == sp->ore - 1)
            n[dm_spectrum_ore_class(sp, 2.0 * w->p.r[i])]++;
    return read_counters(w, what, n, sp->ore_classes, particles, capacity, count);
}

DEMILL_API demill_status demill_grinding_rates_from_drum(demill_grinding *g, demill_world *w,
                                                         demill_id drum)
{
    const char *what = "grinding_rates_from_drum";
    size_t n = 0;
    demill_status s = demill_grinding_sizes(g, NULL, 0, &n);
    if (s)
        return s;
    if ((s = impacts_enter(w, drum, what)))
        return s;
    const dm_spectrum *sp = &w->drum.spectrum;
    double limits[201];
    demill_grinding_sizes(g, limits, 201, NULL);
    if (n - 1 != sp->ore_classes || limits[0] != sp->ore_top)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the drum records %u classes below %g m, the grinding object has %zu "
                       "below %g m",
                       what, sp->ore_classes, sp->ore_top, n - 1, limits[0]);
    const uint32_t C = sp->ore_classes, B = sp->ore_bins;
    double *edges = malloc((B + 1) * sizeof *edges), *counts = malloc((size_t)C * B * sizeof *counts);
    double particles[200];
    uint64_t np[200];
    if (!edges || !counts) {
        free(edges);
        free(counts);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", what);
    }
    for (uint32_t k = 0; k <= B; k++)
        edges[k] = pow(10.0, sp->ore_log_min + sp->ore_log_span * k / B);
    const uint64_t *c = sp->counts + dm_spectrum_collision_counters(sp);
    for (size_t k = 0; k < (size_t)C * B; k++)
        counts[k] = (double)c[k];
    demill_drum_impacts_particles(w, drum, np, 200, NULL);
    for (uint32_t i = 0; i < C; i++)
        particles[i] = (double)np[i];
    double time = w->time - sp->ore_t0;
    if (!(time > 0.0))
        s = dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: no time has passed since the impacts began",
                    what);
    else
        s = demill_grinding_rates_from_impacts(g, C, B, edges, counts, particles, time);
    free(edges);
    free(counts);
    return s;
}
