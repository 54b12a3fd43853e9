/* spectrum.c: the collision energy spectrum, the input of breakage and
 * population-balance models. Every contact carries the energy dissipated in
 * it since it began (an extra history slot while a spectrum is recorded);
 * when the contact ends, the kernel counts that energy here, in a
 * logarithmic bin of the row of its two size classes, or of its size class
 * and kind of drum wall. While the impacts on an ore are recorded too, each
 * collision of an ore particle also counts as one impact on it, of the
 * specific energy it absorbed, in a bin of its size class. The drum's API
 * starts and reads them (lib/world/spectrum.c). */
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

uint32_t dm_spectrum_ore_class(const dm_spectrum *sp, double diameter)
{
    const uint32_t last = sp->ore_classes - 1;
    if (!(diameter < sp->ore_top))
        return 0;
    double x = 2.0 * log2(sp->ore_top / diameter);
    uint32_t k = x >= last ? last : (uint32_t)x;
    /* the limits as the grinding object has them, top/√2^k, decide */
    while (k > 0 && diameter > sp->ore_top * pow(2.0, -0.5 * k))
        k--;
    while (k < last && !(diameter > sp->ore_top * pow(2.0, -0.5 * (k + 1))))
        k++;
    return k;
}

/* Counts one impact on ore particle i that absorbed `energy`, J: in its
 * size class, in the logarithmic bin of energy / mass, J/kg. */
static void ore_impact(demill_world *w, uint32_t i, double energy)
{
    const dm_spectrum *sp = &w->drum.spectrum;
    const uint32_t k = dm_spectrum_ore_class(sp, 2.0 * w->p.r[i]);
    double x = (log10(energy / dm_particle_share(w, i)) - sp->ore_log_min) / sp->ore_log_span * sp->ore_bins;
    uint32_t bin = x < 0.0 ? 0 : x >= sp->ore_bins ? sp->ore_bins - 1 : (uint32_t)x;
    uint64_t *count =
        &sp->counts[dm_spectrum_collision_counters(sp) + (size_t)k * sp->ore_bins + bin];
    __atomic_fetch_add(count, 1, __ATOMIC_RELAXED); /* contacts end on every thread */
}

void dm_spectrum_record(demill_world *w, uint32_t i, uint32_t j, int wall, double energy)
{
    const dm_spectrum *sp = &w->drum.spectrum;
    if (!sp->counts || !(energy > 0.0))
        return;
    const uint32_t C = sp->nclasses, a = size_class(sp, 2.0 * w->p.r[i]);
    const dm_wall *wl = wall >= 0 ? &w->walls[wall] : NULL;
    uint32_t row = UINT32_MAX;
    if (!wl) {
        uint32_t b = size_class(sp, 2.0 * w->p.r[j]);
        uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
        row = lo * C - lo * (lo - 1) / 2 + (hi - lo);
    } else if (wl->drum_part) {
        int kind = wl->drum_part == DM_PART_LIFTER ? DEMILL_SPECTRUM_LIFTER : DEMILL_SPECTRUM_SHELL;
        row = C * (C + 1) / 2 + (uint32_t)kind * C + a;
    }
    if (row != UINT32_MAX) {
        double x = (log10(energy) - sp->log_min) / sp->log_span * sp->nbins;
        uint32_t bin = x < 0.0 ? 0 : x >= sp->nbins ? sp->nbins - 1 : (uint32_t)x;
        uint64_t *count = &sp->counts[(size_t)row * sp->nbins + bin];
        __atomic_fetch_add(count, 1, __ATOMIC_RELAXED); /* contacts end on every thread */
    }
    if (!sp->ore)
        return;
    const uint32_t ore = sp->ore - 1, mi = w->p.mat[i], mj = wl ? wl->material : w->p.mat[j];
    if (mi != ore && (wl || mj != ore))
        return;
    /* the energy is shared between the two bodies by their compliances (a
     * rigid one takes none) */
    const double ci = dm_material_compliance(&w->mats[mi]),
                 cj = dm_material_compliance(&w->mats[mj]);
    if (mi == ore)
        ore_impact(w, i, energy * ci / (ci + cj));
    if (!wl && mj == ore)
        ore_impact(w, j, energy * cj / (ci + cj));
}

size_t dm_spectrum_collision_counters(const dm_spectrum *sp)
{
    const size_t C = sp->nclasses;
    return (C * (C + 1) / 2 + 2 * C) * sp->nbins;
}

size_t dm_spectrum_counters(const dm_spectrum *sp)
{
    return dm_spectrum_collision_counters(sp) + (size_t)sp->ore_classes * sp->ore_bins;
}

void dm_spectrum_free(demill_world *w)
{
    free(w->drum.spectrum.edges);
    free(w->drum.spectrum.counts);
    memset(&w->drum.spectrum, 0, sizeof w->drum.spectrum);
}
