/* fill.c: size distributions, filling a region (the drum, a box, a
 * cylinder) with a charge drawn from one or with clumps of a template, and
 * letting a charge settle.
 *
 * A distribution is reduced to size classes with mass fractions: discrete
 * classes as given; Rosin-Rammler and normal distributions (by mass) as 32
 * classes of equal log-width between d_min and d_max, each particle's diameter
 * drawn log-uniformly within its class. Class k gets n_k ∝ f_k / m̄_k
 * particles (m̄_k the mean particle mass in the class), scaled to the target
 * count, mass or filling, rounded by largest remainder. The particles, in a
 * seeded random order, are placed by place.c: each at the lowest free place
 * among seeded random candidates in the region, clear of the walls and of
 * every particle. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "demill/clump.h"
#include "demill/insert.h"
#include "world/world.h"

#define PLACE_SETS 256 /* sets of candidate places a particle of a fill may try */

static double rosin_rammler_cdf(const double *p, double d)
{
    return 1.0 - exp(-pow(d / p[0], p[1]));
}

static double normal_cdf(const double *p, double d)
{
    return 0.5 * erfc(-(d - p[0]) / (p[1] * sqrt(2.0)));
}

demill_status dm_sizes_make(demill_world *w, const char *who, int32_t dist, const double *p,
                            size_t np, dm_sizes *out)
{
    dm_sizes c = {0};
    if (np && !p)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: params is NULL", who);
    for (size_t k = 0; k < np; k++)
        if (!isfinite(p[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: params[%zu] = %g is not finite", who, k,
                           p[k]);
    if (dist == DEMILL_SIZES_CLASSES) {
        if (np < 2 || np % 2 || np / 2 > DM_SIZE_CLASSES)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: classes need 1 to %d pairs (diameter, mass fraction), got %zu "
                           "numbers",
                           who, DM_SIZE_CLASSES, np);
        double sum = 0.0;
        for (size_t k = 0; k < np / 2; k++) {
            if (!(p[2 * k] > 0.0) || p[2 * k + 1] < 0.0)
                return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                               "%s: class %zu: diameter %g must be > 0 and mass fraction %g >= 0",
                               who, k, p[2 * k], p[2 * k + 1]);
            c.lo[k] = c.hi[k] = p[2 * k];
            c.fraction[k] = p[2 * k + 1];
            sum += p[2 * k + 1];
        }
        if (!(sum > 0.0))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: the mass fractions sum to 0", who);
        c.n = (uint32_t)(np / 2);
        for (uint32_t k = 0; k < c.n; k++)
            c.fraction[k] /= sum;
        *out = c;
        return DEMILL_OK;
    }
    if (dist != DEMILL_SIZES_ROSIN_RAMMLER && dist != DEMILL_SIZES_NORMAL)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%s: %d is not a size distribution", who,
                       (int)dist);
    if (np != 4)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: this distribution takes 4 parameters, got %zu", who, np);
    if (!(p[0] > 0.0) || !(p[1] > 0.0) || !(p[2] > 0.0) || !(p[3] > p[2]))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: need size > 0, spread > 0 and 0 < d_min < d_max (got %g, %g, %g, %g)",
                       who, p[0], p[1], p[2], p[3]);
    double (*cdf)(const double *, double) =
        dist == DEMILL_SIZES_ROSIN_RAMMLER ? rosin_rammler_cdf : normal_cdf;
    const double f0 = cdf(p, p[2]), span = cdf(p, p[3]) - f0, ratio = p[3] / p[2];
    if (!(span > 0.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the distribution has no mass between d_min and d_max", who);
    for (uint32_t k = 0; k < DM_SIZE_CLASSES; k++) {
        c.lo[k] = p[2] * pow(ratio, (double)k / DM_SIZE_CLASSES);
        c.hi[k] = p[2] * pow(ratio, (double)(k + 1) / DM_SIZE_CLASSES);
        c.fraction[k] = (cdf(p, c.hi[k]) - cdf(p, c.lo[k])) / span;
    }
    c.n = DM_SIZE_CLASSES;
    *out = c;
    return DEMILL_OK;
}

/* Mean of d^p over class k, d log-uniform in [lo, hi]. */
static double class_moment(const dm_sizes *s, uint32_t k, double p)
{
    if (s->hi[k] <= s->lo[k] * (1.0 + 1e-12))
        return pow(s->lo[k], p);
    return (pow(s->hi[k], p) - pow(s->lo[k], p)) / (p * log(s->hi[k] / s->lo[k]));
}

/* The mean particle mass of class k, material mat. */
static double class_mass(const demill_world *w, uint32_t mat, const dm_sizes *s, uint32_t k)
{
    double m1, inv_i;
    dm_particle_mass(w, mat, 0.5, &m1, &inv_i); /* the mass of a unit diameter */
    return m1 * class_moment(s, k, w->dim == 2 && w->disc_thickness > 0 ? 2.0 : 3.0);
}

void dm_sizes_numbers(const demill_world *w, uint32_t mat, const dm_sizes *s, double *number)
{
    for (uint32_t k = 0; k < s->n; k++)
        number[k] = s->fraction[k] / class_mass(w, mat, s, k);
}

double dm_sizes_draw(const dm_sizes *s, uint32_t k, dm_rng *rng)
{
    return s->lo[k] * pow(s->hi[k] / s->lo[k], dm_rng_uniform(rng));
}

demill_status dm_sizes_check_mass(demill_world *w, const char *who, uint32_t mat,
                                  const dm_sizes *s, const size_t *count)
{
    demill_status st = DEMILL_OK;
    for (uint32_t k = 0; k < s->n && !st; k++)
        if (!count || count[k]) {
            double m, inv_i;
            if (!(st = dm_particle_mass_checked(w, mat, 0.5 * s->lo[k], who, &m, &inv_i)))
                st = dm_particle_mass_checked(w, mat, 0.5 * s->hi[k], who, &m, &inv_i);
        }
    return st;
}

/* Bodies per class for the target in the region: ncls classes, class k of
 * relative number weight[k] (per unit mass of the whole), mass fraction
 * fraction[k] and mean volume (2D: area) size[k] a body, each body of
 * `members` particles, called `what` in messages. The counts are the target's share rounded by
 * largest remainder, so that a count target is met exactly. */
static demill_status target_counts(demill_world *w, const char *who, const dm_region *reg,
                                   int32_t target, double value, uint32_t ncls,
                                   const double *weight, const double *fraction,
                                   const double *size, size_t members, const char *what,
                                   size_t *count)
{
    double wsum = 0.0, mass = 0.0, measure = 0.0;
    for (uint32_t k = 0; k < ncls; k++) {
        wsum += weight[k];
        mass += fraction[k];
        measure += weight[k] * size[k];
    }
    double scale;
    switch (target) {
    case DEMILL_FILL_COUNT: scale = value / wsum; break;
    case DEMILL_FILL_MASS: scale = value / mass; break;
    case DEMILL_FILL_FRACTION:
        scale = value * dm_region_measure(w, reg) / measure;
        if (reg->kind == DEMILL_REGION_DRUM)
            scale *= 1.0 - w->drum.porosity;
        break;
    default: return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%s: %d is not a fill target", who, (int)target);
    }
    double want = scale * wsum, rem[DM_SIZE_CLASSES];
    const double most = ((double)(UINT32_MAX / 4) - (double)w->p.n) / (double)members;
    if (!(want <= most))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: the target asks for %.3g %ss; at most %.0f more can be added", who,
                       want, what, most);
    size_t total = 0;
    for (uint32_t k = 0; k < ncls; k++) {
        const double x = scale * weight[k];
        count[k] = (size_t)floor(x);
        rem[k] = x - floor(x);
        total += count[k];
    }
    for (uint32_t it = 0; it < ncls && (double)total + 0.5 < want; it++) {
        uint32_t best = 0;
        for (uint32_t k = 1; k < ncls; k++)
            if (rem[k] > rem[best])
                best = k;
        count[best]++;
        rem[best] = -1.0;
        total++;
    }
    return DEMILL_OK;
}

/* Particles per class of a size distribution for the target in the region. */
static demill_status class_counts(demill_world *w, const char *who, uint32_t mat,
                                  const dm_sizes *cls, const dm_region *reg, int32_t target,
                                  double value, size_t *count)
{
    double weight[DM_SIZE_CLASSES], size[DM_SIZE_CLASSES];
    dm_sizes_numbers(w, mat, cls, weight);
    for (uint32_t k = 0; k < cls->n; k++)
        size[k] = w->dim == 3 ? DM_PI / 6.0 * class_moment(cls, k, 3.0)
                              : DM_PI / 4.0 * class_moment(cls, k, 2.0);
    return target_counts(w, who, reg, target, value, cls->n, weight, cls->fraction, size, 1,
                         "particle", count);
}

/* The checks of a fill's target value. */
static demill_status check_value(demill_world *w, const char *who, int32_t target, double value)
{
    if (!isfinite(value))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: target value %g is not finite", who, value);
    if (!(value > 0.0) || (target == DEMILL_FILL_FRACTION && value > 1.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: target value %g must be > 0 (and at most 1 for a fraction)", who,
                       value);
    return DEMILL_OK;
}

/* The checks of a fill's count n of `what`s against the ids' buffer. */
static demill_status check_count(demill_world *w, const char *who, const char *what, size_t n,
                                 demill_id *ids, size_t capacity, size_t *added)
{
    if (added)
        *added = 0;
    if (n == 0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: the target asks for no %s", who, what);
    if (ids && capacity < n) {
        if (added)
            *added = n; /* what the buffer must hold */
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "%s: capacity %zu, %zu %ss", who,
                       capacity, n, what);
    }
    return DEMILL_OK;
}

/* The fill of demill_fill_region() and demill_drum_fill(), in a checked
 * region with a checked material. */
static demill_status fill(demill_world *w, const char *who, const dm_region *reg, uint32_t mat,
                          int32_t distribution, const double *params, size_t nparams,
                          int32_t target, double value, uint64_t seed, demill_id *ids,
                          size_t capacity, size_t *added)
{
    dm_sizes cls;
    size_t per_class[DM_SIZE_CLASSES] = {0};
    demill_status s;
    if ((s = check_value(w, who, target, value)) ||
        (s = dm_sizes_make(w, who, distribution, params, nparams, &cls)) ||
        (s = class_counts(w, who, mat, &cls, reg, target, value, per_class)))
        return s;
    size_t n = 0;
    for (uint32_t k = 0; k < cls.n; k++)
        n += per_class[k];
    if ((s = check_count(w, who, "particle", n, ids, capacity, added)) ||
        (s = dm_sizes_check_mass(w, who, mat, &cls, per_class)))
        return s;
    double *rad = malloc(n * sizeof *rad), *pos = malloc(3 * n * sizeof *pos);
    if (!rad || !pos) {
        free(rad);
        free(pos);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", who);
    }
    /* radii, then a seeded shuffle so that sizes are mixed */
    dm_rng rng;
    dm_rng_seed(&rng, seed);
    size_t m = 0;
    for (uint32_t k = 0; k < cls.n; k++)
        for (size_t q = 0; q < per_class[k]; q++)
            rad[m++] = 0.5 * dm_sizes_draw(&cls, k, &rng);
    for (size_t k = n - 1; k > 0; k--) {
        size_t j = (size_t)(dm_rng_uniform(&rng) * (double)(k + 1));
        double t = rad[k];
        rad[k] = rad[j];
        rad[j] = t;
    }
    size_t placed;
    if (!(s = dm_place(w, reg, n, rad, NULL, PLACE_SETS, &rng, pos, NULL, &placed)) && placed < n)
        s = dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                    "%s: only %zu of %zu particles fit in the region: no free place for a "
                    "particle of diameter %g m among %d candidates",
                    who, placed, n, 2.0 * rad[placed], 16 * PLACE_SETS);
    if (!s)
        s = dm_particles_append(w, mat, n, pos, rad, NULL, ids);
    free(rad);
    free(pos);
    if (!s) {
        if (added)
            *added = n;
        dm_changed(w);
    }
    return s;
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
    const dm_region reg = {.kind = DEMILL_REGION_DRUM};
    return fill(w, "drum_fill", &reg, mat, distribution, params, nparams, target, value, seed,
                ids, capacity, added);
}

DEMILL_API demill_status demill_fill_region(demill_world *w, int32_t region,
                                            const double *region_params, size_t nregion,
                                            demill_id material, int32_t distribution,
                                            const double *params, size_t nparams, int32_t target,
                                            double value, uint64_t seed, demill_id *ids,
                                            size_t capacity, size_t *added)
{
    uint32_t mat;
    dm_region reg;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mat);
    if (s || (s = dm_region_parse(w, "fill_region", region, region_params, nregion, true, &reg)))
        return s;
    return fill(w, "fill_region", &reg, mat, distribution, params, nparams, target, value, seed,
                ids, capacity, added);
}

/* The area of the union of a 2D template's discs, for a fill's fraction. */
static demill_status template_area(demill_world *w, const dm_template *t, double *area)
{
    double *c = malloc(2 * t->n * sizeof *c), *r = malloc(t->n * sizeof *r), com[2], inertia;
    const char *why = NULL;
    demill_status s = DEMILL_ERR_OUT_OF_MEMORY;
    if (c && r) {
        for (uint32_t m = 0; m < t->n; m++) {
            const double *b = w->tmem + DM_TMEM * (size_t)(t->first + m);
            c[2 * m] = b[0];
            c[2 * m + 1] = b[1];
            r[m] = b[3];
        }
        s = dm_discs_union_mass(t->n, c, r, 1.0, 1.0, area, com, &inertia, &why);
    }
    free(c);
    free(r);
    return s ? dm_fail(w, s, "clump_fill_region: %s", why ? why : "out of memory") : DEMILL_OK;
}

DEMILL_API demill_status demill_clump_fill_region(demill_world *w, int32_t region,
                                                  const double *region_params, size_t nregion,
                                                  demill_id tmpl, int32_t target, double value,
                                                  uint64_t seed, demill_id *ids,
                                                  size_t capacity, size_t *added)
{
    static const char who[] = "clump_fill_region";
    uint32_t tk;
    dm_region reg;
    demill_status s = dm_enter(w, tmpl, DEMILL_KIND_TEMPLATE, "template", &tk);
    if (s || (s = dm_region_parse(w, who, region, region_params, nregion, true, &reg)) ||
        (s = check_value(w, who, target, value)))
        return s;
    const dm_template *t = &w->templates[tk];
    double size = t->volume, weight = 1.0 / t->mass, fraction = 1.0;
    if (w->dim == 2 && target == DEMILL_FILL_FRACTION && (s = template_area(w, t, &size)))
        return s;
    size_t n = 0;
    if ((s = target_counts(w, who, &reg, target, value, 1, &weight, &fraction, &size, t->n,
                           "clump", &n)) ||
        (s = check_count(w, who, "clump", n, ids, capacity, added)))
        return s;
    const dm_shape shape = {.n = t->n, .mem = w->tmem + DM_TMEM * (size_t)t->first};
    double *pos = malloc(3 * n * sizeof *pos), *quat = malloc(4 * n * sizeof *quat);
    if (!pos || !quat || dm_clumps_reserve(w, n, t->n)) {
        free(pos);
        free(quat);
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: out of memory", who);
    }
    dm_rng rng;
    dm_rng_seed(&rng, seed);
    size_t placed;
    if (!(s = dm_place(w, &reg, n, NULL, &shape, PLACE_SETS, &rng, pos, quat, &placed)) &&
        placed < n)
        s = dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                    "%s: only %zu of %zu clumps fit in the region: no free place among %d "
                    "candidates",
                    who, placed, n, 16 * PLACE_SETS);
    for (size_t k = 0; k < n && !s; k++) {
        const demill_id id = dm_clump_insert(w, tk, pos + 3 * k, quat + 4 * k);
        if (ids)
            ids[k] = id;
    }
    free(pos);
    free(quat);
    if (!s && added)
        *added = n;
    return s;
}

/* The particles' translational kinetic energy (a clump's member with its
 * own part of its clump's mass). */
static double translational_energy(const demill_world *w)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    double ke = 0.0;
    for (uint32_t i = 0; i < P->n; i++)
        for (int c = 0; c < D; c++)
            ke += 0.5 * dm_particle_share(w, i) * P->v[D * i + c] * P->v[D * i + c];
    return ke;
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
    int32_t calm = 0;
    /* settled: low and no longer rising, so that particles placed at rest
     * and starting to fall do not count */
    double before = translational_energy(w);
    for (uint64_t left = (uint64_t)steps; !calm && left;) {
        const uint64_t n = left < chunk ? left : chunk;
        if ((s = demill_world_step(w, n)))
            return s;
        left -= n;
        const double ke = translational_energy(w);
        calm = w->p.n == 0 || (ke / w->p.n <= energy_per_particle && ke <= before);
        before = ke;
    }
    if (settled)
        *settled = calm;
    dm_changed(w);
    return DEMILL_OK;
}
