/* heap.h: the angle of repose of an axisymmetric heap from its particles,
 * shared by examples/repose_clumps and the demill runner's outputs.repose
 * (docs/scene-files.md). The heap's surface profile h(ρ) is the highest
 * particle top in each ring about the axis; the angle is that of the
 * least-squares line through the profile's points on the flank, those 20 %
 * to 80 % of the way from a base height (the top of one layer on the
 * floor) up to the summit, leaving out the rounded summit and the toe where
 * a single layer runs out. */
#ifndef HEAP_H
#define HEAP_H

#include <stddef.h>

#define HEAP_RINGS 128

/* A heap's surface profile and its fit. */
typedef struct heap_profile {
    int n;                                  /* rings holding a particle */
    double rho[HEAP_RINGS], h[HEAP_RINGS];  /* their middles and highest tops, m */
    double hmax;                            /* the summit, m */
    double slope, icept;                    /* the fit: h = icept + slope ρ */
    double angle;                           /* atan(-slope), degrees; NAN with < 2 points */
    int nfit;                               /* the points fitted */
} heap_profile;

/* The profile and fit of the n particles whose distances from the axis are
 * rho[k] and whose tops are top[k] above the floor (m), in rings of width
 * `ring` from the axis out (particles past HEAP_RINGS rings left out), the
 * flank measured from the height `base`. */
void heap_fit(const double *rho, const double *top, size_t n, double ring, double base,
              heap_profile *p);

#endif
