/* fill.c: filling the drum with a charge drawn from a size distribution, and
 * letting it settle.
 *
 * A distribution is reduced to size classes with mass fractions: discrete
 * classes as given; Rosin-Rammler and normal distributions (by mass) as 32
 * classes of equal log-width between d_min and d_max, each particle's diameter
 * drawn log-uniformly within its class. Class k gets n_k ∝ f_k / m̄_k
 * particles (m̄_k the mean particle mass in the class), scaled to the target
 * count, mass or bulk filling. The particles, in a seeded random order, take
 * the lowest free sites of a lattice of spacing d_max (1 + 2 j) inside the
 * drum, each moved by a seeded jitter of up to j d_max per coordinate, so no
 * two new particles can touch; a site is skipped where its particle would
 * touch a wall or a particle already in the world. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

#define FINE_CLASSES 32
#define JITTER 0.02 /* per coordinate, as a fraction of the largest diameter */
#define MAX_SITES 1073741824.0 /* lattice sites, at most: 2^30, a few minutes' scan */

typedef struct size_class {
    double lo, hi;   /* diameter range (lo = hi for a discrete class) */
    double fraction; /* of the mass */
} size_class;

static double rosin_rammler_cdf(const double *p, double d)
{
    return 1.0 - exp(-pow(d / p[0], p[1]));
}

static double normal_cdf(const double *p, double d)
{
    return 0.5 * erfc(-(d - p[0]) / (p[1] * sqrt(2.0)));
}

/* Checks the distribution and turns it into classes; returns the count. */
static demill_status make_classes(demill_world *w, int32_t dist, const double *p, size_t np,
                                  size_class *cls, size_t *ncls)
{
    for (size_t k = 0; k < np; k++)
        if (!isfinite(p[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "drum_fill: params[%zu] = %g is not finite",
                           k, p[k]);
    if (dist == DEMILL_SIZES_CLASSES) {
        if (np < 2 || np % 2 || np / 2 > FINE_CLASSES)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "drum_fill: classes need 1 to %d pairs (diameter, mass fraction), got "
                           "%zu numbers",
                           FINE_CLASSES, np);
        double sum = 0.0;
        for (size_t k = 0; k < np / 2; k++) {
            if (!(p[2 * k] > 0.0) || p[2 * k + 1] < 0.0)
                return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                               "drum_fill: class %zu: diameter %g must be > 0 and mass fraction "
                               "%g >= 0",
                               k, p[2 * k], p[2 * k + 1]);
            cls[k] = (size_class){p[2 * k], p[2 * k], p[2 * k + 1]};
            sum += p[2 * k + 1];
        }
        if (!(sum > 0.0))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_fill: the mass fractions sum to 0");
        *ncls = np / 2;
        for (size_t k = 0; k < *ncls; k++)
            cls[k].fraction /= sum;
        return DEMILL_OK;
    }
    if (dist != DEMILL_SIZES_ROSIN_RAMMLER && dist != DEMILL_SIZES_NORMAL)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "drum_fill: %d is not a size distribution",
                       (int)dist);
    if (np != 4)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: this distribution takes 4 parameters, got %zu", np);
    if (!(p[0] > 0.0) || !(p[1] > 0.0) || !(p[2] > 0.0) || !(p[3] > p[2]))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: need size > 0, spread > 0 and 0 < d_min < d_max (got %g, %g, "
                       "%g, %g)",
                       p[0], p[1], p[2], p[3]);
    double (*cdf)(const double *, double) =
        dist == DEMILL_SIZES_ROSIN_RAMMLER ? rosin_rammler_cdf : normal_cdf;
    const double f0 = cdf(p, p[2]), span = cdf(p, p[3]) - f0, ratio = p[3] / p[2];
    if (!(span > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: the distribution has no mass between d_min and d_max");
    for (size_t k = 0; k < FINE_CLASSES; k++) {
        const double lo = p[2] * pow(ratio, (double)k / FINE_CLASSES);
        const double hi = p[2] * pow(ratio, (double)(k + 1) / FINE_CLASSES);
        cls[k] = (size_class){lo, hi, (cdf(p, hi) - cdf(p, lo)) / span};
    }
    *ncls = FINE_CLASSES;
    return DEMILL_OK;
}

/* Mean of d^p over a class, d log-uniform in [lo, hi]. */
static double class_moment(const size_class *c, double p)
{
    if (c->hi <= c->lo * (1.0 + 1e-12))
        return pow(c->lo, p);
    return (pow(c->hi, p) - pow(c->lo, p)) / (p * log(c->hi / c->lo));
}

/* Volume (3D) or cross-section area (2D) of a particle of unit diameter,
 * times d^3 or d^2; and the drum's free inner volume or area. */
static double solid_measure(const demill_world *w, const size_class *c)
{
    return w->dim == 3 ? DM_PI / 6.0 * class_moment(c, 3.0) : DM_PI / 4.0 * class_moment(c, 2.0);
}

static double drum_capacity(const demill_world *w)
{
    const dm_drum *d = &w->drum;
    const double R = 0.5 * d->diameter;
    double area = DM_PI * R * R;
    for (uint32_t k = 0; k < d->nlifters; k++) {
        const dm_lifter_spec *l = &d->lifters[k];
        area -= l->height * (l->width - 0.5 * l->height * tan(l->face));
    }
    return w->dim == 3 ? area * d->length : area;
}

/* Particles per class for the target; returns the total. */
static demill_status class_counts(demill_world *w, uint32_t mat, const size_class *cls,
                                  size_t ncls, int32_t target, double value, size_t *count)
{
    double weight[FINE_CLASSES], wsum = 0.0, mass = 0.0, measure = 0.0, m1, inv_i;
    dm_particle_mass(w, mat, 0.5, &m1, &inv_i); /* the mass of a unit diameter */
    const double mass_power = w->dim == 2 && w->disc_thickness > 0 ? 2.0 : 3.0;
    for (size_t k = 0; k < ncls; k++) {
        const double mean_mass = m1 * class_moment(&cls[k], mass_power);
        weight[k] = cls[k].fraction / mean_mass;
        wsum += weight[k];
        mass += weight[k] * mean_mass;
        measure += weight[k] * solid_measure(w, &cls[k]);
    }
    double scale;
    switch (target) {
    case DEMILL_FILL_COUNT: scale = value / wsum; break;
    case DEMILL_FILL_MASS: scale = value / mass; break;
    case DEMILL_FILL_FRACTION:
        scale = value * drum_capacity(w) * (1.0 - w->drum.porosity) / measure;
        break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "drum_fill: %d is not a fill target", (int)target);
    }
    /* largest remainder, so that a count target is met exactly */
    double want = scale * wsum, rem[FINE_CLASSES];
    const double most = (double)(UINT32_MAX / 4) - (double)w->p.n;
    if (!(want <= most))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: the target asks for %.3g particles; at most %.0f more can be "
                       "added",
                       want, most);
    size_t total = 0;
    for (size_t k = 0; k < ncls; k++) {
        const double x = scale * weight[k];
        count[k] = (size_t)floor(x);
        rem[k] = x - floor(x);
        total += count[k];
    }
    for (size_t it = 0; it < ncls && (double)total + 0.5 < want; it++) {
        size_t best = 0;
        for (size_t k = 1; k < ncls; k++)
            if (rem[k] > rem[best])
                best = k;
        count[best]++;
        rem[best] = -1.0;
        total++;
    }
    return DEMILL_OK;
}

DEMILL_API demill_status demill_drum_fill(demill_world *w, demill_id drum, demill_id material,
                                          int32_t distribution, const double *params,
                                          size_t nparams, int32_t target, double value,
                                          uint64_t seed, demill_id *ids, size_t capacity,
                                          size_t *added)
{
    uint32_t slot, mat;
    demill_status s = dm_enter(w, drum, DEMILL_KIND_DRUM, "drum", &slot);
    if (s || (s = dm_resolve(w, material, DEMILL_KIND_MATERIAL, "material", &mat)))
        return s;
    if (nparams && !params)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "drum_fill: params is NULL");
    if (!isfinite(value))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "drum_fill: target value %g is not finite", value);
    if (!(value > 0.0) || (target == DEMILL_FILL_FRACTION && value > 1.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: target value %g must be > 0 (and at most 1 for a fraction)",
                       value);
    size_class cls[FINE_CLASSES];
    size_t ncls = 0, per_class[FINE_CLASSES] = {0};
    if ((s = make_classes(w, distribution, params, nparams, cls, &ncls)) ||
        (s = class_counts(w, mat, cls, ncls, target, value, per_class)))
        return s;
    size_t n = 0;
    double dmax = 0.0;
    for (size_t k = 0; k < ncls; k++) {
        n += per_class[k];
        if (per_class[k])
            dmax = fmax(dmax, cls[k].hi);
    }
    if (added)
        *added = 0;
    if (n == 0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "drum_fill: the target asks for no particle");
    if (ids && capacity < n) {
        if (added)
            *added = n; /* what the buffer must hold */
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "drum_fill: capacity %zu, %zu particles",
                       capacity, n);
    }
    /* the smallest and largest particles have a finite mass and inertia */
    for (size_t k = 0; k < ncls; k++)
        if (per_class[k]) {
            double m, inv_i;
            if ((s = dm_particle_mass_checked(w, mat, 0.5 * cls[k].lo, "drum_fill", &m, &inv_i)) ||
                (s = dm_particle_mass_checked(w, mat, 0.5 * cls[k].hi, "drum_fill", &m, &inv_i)))
                return s;
        }
    /* the lattice the particles are placed on, whose sites the placement
     * may visit all of */
    const dm_drum *d = &w->drum;
    const int D = w->dim;
    const double jit = JITTER * dmax, a = dmax + 2.0 * jit, R = 0.5 * d->diameter;
    const double zh = D == 3 ? 0.5 * d->length : 0.0;
    const double sites = (2.0 * floor(R / a) + 1.0) * (2.0 * floor(R / a) + 1.0) *
                         (2.0 * floor(zh / a) + 1.0);
    if (!(sites <= MAX_SITES))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: particles of diameter %g m are too small for this drum: the "
                       "lattice they are placed on would have %.3g sites, at most %.3g",
                       dmax, sites, MAX_SITES);

    double *diam = malloc(n * sizeof *diam), *pos = malloc(3 * n * sizeof *pos);
    dm_sphere_index ix = {0};
    if (!diam || !pos || dm_spheres_build(&ix, w, 0, NULL, NULL, 0.5 * dmax)) {
        free(diam);
        free(pos);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "drum_fill: out of memory");
    }
    /* diameters, then a seeded shuffle so that sizes are mixed */
    dm_rng rng;
    dm_rng_seed(&rng, seed);
    size_t m = 0;
    for (size_t k = 0; k < ncls; k++)
        for (size_t q = 0; q < per_class[k]; q++)
            diam[m++] = cls[k].lo * pow(cls[k].hi / cls[k].lo, dm_rng_uniform(&rng));
    for (size_t k = n - 1; k > 0; k--) {
        size_t j = (size_t)(dm_rng_uniform(&rng) * (double)(k + 1));
        double t = diam[k];
        diam[k] = diam[j];
        diam[j] = t;
    }
    /* lattice sites from the bottom up: y, then x, then z */
    const long nxy = (long)floor(R / a), nz = D == 3 ? (long)floor(zh / a) : 0;
    size_t placed = 0;
    for (long iy = -nxy; iy <= nxy && placed < n; iy++)
        for (long ix_ = -nxy; ix_ <= nxy && placed < n; ix_++)
            for (long iz = -nz; iz <= nz && placed < n; iz++) {
                double x[3] = {ix_ * a, iy * a, iz * a};
                for (int c = 0; c < D; c++)
                    x[c] += jit * (2.0 * dm_rng_uniform(&rng) - 1.0);
                const double r = 0.5 * diam[placed];
                double depth;
                if (x[0] * x[0] + x[1] * x[1] >= R * R ||
                    dm_wall_overlap(w, x, r, &depth) != DM_FREE ||
                    dm_spheres_find(&ix, x, r, (uint32_t)ix.n, &depth) >= 0)
                    continue;
                memcpy(pos + 3 * placed, x, sizeof x);
                placed++;
            }
    dm_spheres_free(&ix);
    if (placed < n) {
        free(diam);
        free(pos);
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "drum_fill: only %zu of %zu particles fit in the drum (lattice spacing %g m)",
                       placed, n, a);
    }
    for (size_t k = 0; k < n; k++)
        diam[k] *= 0.5; /* radii */
    s = dm_particles_append(w, mat, n, pos, diam, NULL, ids);
    free(diam);
    free(pos);
    if (!s) {
        if (added)
            *added = n;
        dm_changed(w);
    }
    return s;
}

DEMILL_API demill_status demill_world_settle(demill_world *w, double max_time,
                                             double energy_per_particle, int32_t *settled)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!isfinite(max_time) || !isfinite(energy_per_particle))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "world_settle: arguments must be finite");
    if (max_time < 0.0 || energy_per_particle < 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "world_settle: arguments must be >= 0");
    /* counted in steps, so that the call ends whatever the clock's
     * resolution; the energy is looked at every millisecond */
    const double steps = ceil(max_time / w->dt);
    if (!(steps < 1e18))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_settle: max_time %g s is %.3g steps of %g s, too many", max_time,
                       steps, w->dt);
    const uint64_t chunk = (uint64_t)fmax(1.0, ceil(1e-3 / w->dt));
    const dm_particles *P = &w->p;
    const int D = w->dim;
    int32_t calm = 0;
    for (uint64_t left = (uint64_t)steps; !calm && left;) {
        const uint64_t n = left < chunk ? left : chunk;
        if ((s = demill_world_step(w, n)))
            return s;
        left -= n;
        double ke = 0.0;
        for (uint32_t i = 0; i < P->n; i++)
            for (int c = 0; c < D; c++)
                ke += 0.5 * P->m[i] * P->v[D * i + c] * P->v[D * i + c];
        calm = P->n == 0 || ke / P->n <= energy_per_particle;
    }
    if (settled)
        *settled = calm;
    dm_changed(w);
    return DEMILL_OK;
}
