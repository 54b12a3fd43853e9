/* spectrum.c: the collision energy spectrum, the input of breakage and
 * population-balance models. Every contact carries the energy dissipated in
 * it since it began (an extra history slot while a spectrum is recorded);
 * when the contact ends, the kernel counts that energy here, in a
 * logarithmic bin of the row of its two size classes, or of its size class
 * and kind of drum wall. The drum's API starts and reads it
 * (lib/world/spectrum.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/contact/contact.h"

static uint32_t size_class(const dm_spectrum *sp, double diameter)
{
    uint32_t lo = 0, hi = sp->nclasses - 1; /* the first edge above the diameter */
    while (lo < hi) {
        uint32_t mid = (lo + hi) / 2;
        if (diameter < sp->edges[mid])
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* Counts one collision: particles i and j (storage slots), or particle i and
 * a wall of the given DEMILL_SPECTRUM_* kind (j unused, kind >= 0). */
void dm_spectrum_record(demill_world *w, uint32_t i, uint32_t j, int wall_kind, double energy)
{
    const dm_spectrum *sp = &w->drum.spectrum;
    if (!sp->counts || !(energy > 0.0))
        return;
    const uint32_t C = sp->nclasses, a = size_class(sp, 2.0 * w->p.r[i]);
    uint32_t row;
    if (wall_kind < 0) {
        uint32_t b = size_class(sp, 2.0 * w->p.r[j]);
        uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
        row = lo * C - lo * (lo - 1) / 2 + (hi - lo);
    } else {
        row = C * (C + 1) / 2 + (uint32_t)wall_kind * C + a;
    }
    double x = (log10(energy) - sp->log_min) / sp->log_span * sp->nbins;
    uint32_t bin = x < 0.0 ? 0 : x >= sp->nbins ? sp->nbins - 1 : (uint32_t)x;
    uint64_t *count = &w->drum.spectrum.counts[(size_t)row * sp->nbins + bin];
    __atomic_fetch_add(count, 1, __ATOMIC_RELAXED); /* contacts end on every thread */
}

/* The number of counters of a spectrum. */
size_t dm_spectrum_counters(const dm_spectrum *sp)
{
    const size_t C = sp->nclasses;
    return (C * (C + 1) / 2 + 2 * C) * sp->nbins;
}

void dm_spectrum_free(demill_world *w)
{
    free(w->drum.spectrum.edges);
    free(w->drum.spectrum.counts);
    memset(&w->drum.spectrum, 0, sizeof w->drum.spectrum);
}
