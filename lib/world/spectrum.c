/* spectrum.c: the drum's collision energy spectrum, started and read through
 * the API (the contact kernels count it: lib/physics/contact/spectrum.c). */
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
    const size_t n = dm_spectrum_counters(sp);
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
