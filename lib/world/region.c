/* region.c: the regions of space that fills, feeds and outlets name
 * (DEMILL_REGION_*, demill/insert.h): checking what the API was given, and
 * whether a sphere lies inside, the region's size, bounding box and random
 * points in it. */
#include <math.h>
#include <string.h>

#include "demill/insert.h"
#include "world/world.h"

/* The number of doubles each kind takes. */
static size_t region_params(int32_t kind)
{
    switch (kind) {
    case DEMILL_REGION_BOX: return 6;
    case DEMILL_REGION_CYLINDER: return 7;
    case DEMILL_REGION_HALF_SPACE: return 6;
    case DEMILL_REGION_DRUM: return 0;
    default: return SIZE_MAX;
    }
}

demill_status dm_region_parse(demill_world *w, const char *who, int32_t kind, const double *p,
                              size_t np, bool bounded, dm_region *out)
{
    const size_t want = region_params(kind);
    if (want == SIZE_MAX)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%s: %d is not a kind of region", who,
                       (int)kind);
    if (np != want)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "%s: this region takes %zu parameters, got %zu",
                       who, want, np);
    if (np && !p)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "%s: region_params is NULL", who);
    for (size_t k = 0; k < np; k++)
        if (!isfinite(p[k]))
            return dm_fail(w, DEMILL_ERR_NOT_FINITE, "%s: region_params[%zu] = %g is not finite",
                           who, k, p[k]);
    if (bounded && kind == DEMILL_REGION_HALF_SPACE)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "%s: a half-space is unbounded; it can only be an outlet", who);
    const int D = w->dim;
    dm_region r = {.kind = kind};
    memcpy(r.p, p, np * sizeof *p);
    if (D == 2)
        for (size_t k = 2; k < 6 && k < np; k += 3)
            if (p[k] != 0.0)
                return dm_fail(w, DEMILL_ERR_DIMENSION,
                               "%s: region_params[%zu] = %g is a z coordinate in a 2D world", who,
                               k, p[k]);
    switch (kind) {
    case DEMILL_REGION_BOX:
        for (int c = 0; c < D; c++)
            if (!(p[c] < p[3 + c]))
                return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                               "%s: the box is empty: its %c range is [%g, %g]", who, "xyz"[c],
                               p[c], p[3 + c]);
        break;
    case DEMILL_REGION_CYLINDER: {
        double len2 = 0.0;
        for (int c = 0; c < 3; c++)
            len2 += (p[3 + c] - p[c]) * (p[3 + c] - p[c]);
        if (!(p[6] > 0.0) || !(len2 > 0.0))
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: the cylinder is empty: radius %g, length %g", who, p[6],
                           sqrt(len2));
        break;
    }
    case DEMILL_REGION_HALF_SPACE: {
        const double big = fmax(fabs(p[3]), fmax(fabs(p[4]), fabs(p[5])));
        if (big == 0.0)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: the half-space's normal has zero length", who);
        double len = 0.0;
        for (int c = 0; c < 3; c++)
            len += (p[3 + c] / big) * (p[3 + c] / big);
        for (int c = 0; c < 3; c++)
            r.p[3 + c] = p[3 + c] / big / sqrt(len);
        break;
    }
    default:
        if (!w->drum.alive)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: the region is the drum, but the world has no drum", who);
    }
    *out = r;
    return DEMILL_OK;
}

/* A cylinder's axis: unit vector u and length. */
static double cylinder_axis(const dm_region *r, double u[3])
{
    double len = 0.0;
    for (int c = 0; c < 3; c++) {
        u[c] = r->p[3 + c] - r->p[c];
        len += u[c] * u[c];
    }
    len = sqrt(len);
    for (int c = 0; c < 3; c++)
        u[c] /= len;
    return len;
}

bool dm_region_contains(const demill_world *w, const dm_region *r, const double *x, double m)
{
    const int D = w->dim;
    const double *p = r->p;
    switch (r->kind) {
    case DEMILL_REGION_BOX:
        for (int c = 0; c < D; c++)
            if (!(x[c] - m >= p[c] && x[c] + m <= p[3 + c]))
                return false;
        return true;
    case DEMILL_REGION_CYLINDER: {
        double u[3], d[3], t = 0.0, q2 = 0.0;
        const double len = cylinder_axis(r, u);
        for (int c = 0; c < 3; c++) {
            d[c] = (c < D ? x[c] : 0.0) - p[c];
            t += d[c] * u[c];
        }
        for (int c = 0; c < 3; c++)
            q2 += (d[c] - t * u[c]) * (d[c] - t * u[c]);
        return t >= m && t <= len - m && m <= p[6] && q2 <= (p[6] - m) * (p[6] - m);
    }
    case DEMILL_REGION_HALF_SPACE: {
        double s = 0.0;
        for (int c = 0; c < D; c++)
            s += (x[c] - p[c]) * p[3 + c];
        return s <= -m;
    }
    default: { /* about the drum's centre */
        const double R = 0.5 * w->drum.diameter - m, *c = w->drum.centre;
        const double dx = x[0] - c[0], dy = x[1] - c[1];
        return R >= 0.0 && dx * dx + dy * dy <= R * R &&
               (D == 2 || fabs(x[2] - c[2]) <= 0.5 * w->drum.length - m);
    }
    }
}

void dm_region_bounds(const demill_world *w, const dm_region *r, double lo[3], double hi[3])
{
    const double *p = r->p;
    switch (r->kind) {
    case DEMILL_REGION_BOX:
        memcpy(lo, p, 3 * sizeof *lo);
        memcpy(hi, p + 3, 3 * sizeof *hi);
        break;
    case DEMILL_REGION_CYLINDER: {
        double u[3];
        cylinder_axis(r, u);
        for (int c = 0; c < 3; c++) {
            const double e = p[6] * sqrt(fmax(0.0, 1.0 - u[c] * u[c]));
            lo[c] = fmin(p[c], p[3 + c]) - e;
            hi[c] = fmax(p[c], p[3 + c]) + e;
        }
        break;
    }
    case DEMILL_REGION_HALF_SPACE:
        for (int c = 0; c < 3; c++) {
            lo[c] = -INFINITY;
            hi[c] = INFINITY;
        }
        break;
    default: {
        const double R = 0.5 * w->drum.diameter, h = 0.5 * w->drum.length;
        const double e[3] = {R, R, h}, *c = w->drum.centre;
        for (int k = 0; k < 3; k++) {
            lo[k] = c[k] - e[k];
            hi[k] = c[k] + e[k];
        }
    }
    }
    if (w->dim == 2)
        lo[2] = hi[2] = 0.0;
}

double dm_region_measure(const demill_world *w, const dm_region *r)
{
    const double *p = r->p;
    const int D = w->dim;
    switch (r->kind) {
    case DEMILL_REGION_BOX: {
        double v = 1.0;
        for (int c = 0; c < D; c++)
            v *= p[3 + c] - p[c];
        return v;
    }
    case DEMILL_REGION_CYLINDER: {
        double u[3];
        const double len = cylinder_axis(r, u);
        return D == 3 ? DM_PI * p[6] * p[6] * len : 2.0 * p[6] * len;
    }
    case DEMILL_REGION_HALF_SPACE: return INFINITY;
    default: {
        /* the drum's free inner volume (in 2D its area): the circle less the
         * lifters' sections */
        const dm_drum *d = &w->drum;
        const double R = 0.5 * d->diameter;
        double area = DM_PI * R * R;
        for (uint32_t k = 0; k < d->nlifters; k++) {
            const dm_lifter_spec *l = &d->lifters[k];
            area -= l->height * (l->width - 0.5 * l->height * tan(l->face));
        }
        return D == 3 ? area * d->length : area;
    }
    }
}

bool dm_region_fits(const demill_world *w, const dm_region *r, double m)
{
    const double *p = r->p;
    switch (r->kind) {
    case DEMILL_REGION_BOX:
        for (int c = 0; c < w->dim; c++)
            if (p[3 + c] - p[c] < 2.0 * m)
                return false;
        return true;
    case DEMILL_REGION_CYLINDER: {
        double u[3];
        return cylinder_axis(r, u) >= 2.0 * m && p[6] >= m;
    }
    case DEMILL_REGION_HALF_SPACE: return true;
    default:
        return 0.5 * w->drum.diameter >= m && (w->dim == 2 || w->drum.length >= 2.0 * m);
    }
}

int dm_region_sample(const demill_world *w, const dm_region *r, dm_rng *rng, double m, int axis,
                     const double band[2], double *x)
{
    double lo[3], hi[3];
    dm_region_bounds(w, r, lo, hi);
    lo[axis] = fmax(lo[axis], band[0]);
    hi[axis] = fmin(hi[axis], band[1]);
    for (int attempt = 0; attempt < 64; attempt++) {
        x[0] = x[1] = x[2] = 0.0;
        for (int c = 0; c < w->dim; c++) {
            const double a = lo[c] + m, b = hi[c] - m;
            x[c] = b > a ? a + (b - a) * dm_rng_uniform(rng) : 0.5 * (lo[c] + hi[c]);
        }
        if (dm_region_contains(w, r, x, m))
            return 0;
    }
    return -1;
}
