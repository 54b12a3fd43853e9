/* heap.c: the surface profile of an axisymmetric heap and the angle of
 * repose from it (heap.h). */
#include <math.h>

#include "heap.h"

#define PI 3.14159265358979323846

void heap_fit(const double *rho, const double *top, size_t n, double ring, double base,
              heap_profile *p)
{
    double highest[HEAP_RINGS];
    for (int b = 0; b < HEAP_RINGS; b++)
        highest[b] = -INFINITY;
    for (size_t k = 0; k < n; k++) {
        const double b = floor(rho[k] / ring);
        if (b < HEAP_RINGS)
            highest[(int)b] = fmax(highest[(int)b], top[k]);
    }
    p->n = 0;
    p->hmax = 0;
    for (int b = 0; b < HEAP_RINGS; b++)
        if (highest[b] > 0) {
            p->rho[p->n] = (b + 0.5) * ring;
            p->h[p->n++] = highest[b];
            p->hmax = fmax(p->hmax, highest[b]);
        }
    const double rise = p->hmax - base;
    double s1 = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int q = 0; q < p->n; q++) {
        const double u = p->rho[q], v = p->h[q];
        if (v < base + 0.2 * rise || v > base + 0.8 * rise)
            continue;
        s1++;
        sx += u;
        sy += v;
        sxx += u * u;
        sxy += u * v;
    }
    p->nfit = (int)s1;
    p->slope = s1 >= 2 ? (s1 * sxy - sx * sy) / (s1 * sxx - sx * sx) : NAN;
    p->icept = (sy - p->slope * sx) / s1;
    p->angle = atan(-p->slope) * 180 / PI;
}
