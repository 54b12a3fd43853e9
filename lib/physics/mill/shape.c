/* shape.c: the charge's toe, shoulder and centre-of-mass angles, computed
 * from the particle positions by the reference rule of docs/scenes.md.
 *
 * Angles φ are measured at the axis from the downward vertical, positive in
 * the direction of rotation. The particles in the ring R - h - 2d < r < R next
 * to the shell (h the tallest lifter, or the deepest lifter mesh attached to
 * the drum: R less its vertices' smallest distance from the axis; d the
 * largest particle diameter) are
 * summed in 5° bins of φ, each by its volume relative to the largest
 * particle's ((r/r_max)³, in 2D its area (r/r_max)²), so that a bin holds how
 * much of the ring is solid: exactly a count, as in the reference rule, when
 * the particles are all of one size, and not ruled by the fines when they are
 * not (fine ore gathered in a few bins would set the threshold by count and
 * leave only those bins as the charge). A bin belongs to the charge if its
 * fill is at least half the median of the ten fullest bins; the largest run
 * of consecutive charge bins (around the circle) is the charge, its lower
 * edge the toe and its upper edge the shoulder. A lifter takes room from its
 * bins, which with coarse particles can drop them below the threshold and
 * cut the charge in pieces, so gaps no wider than a lifter (in bins; a
 * lifter mesh's width is the arc at R of the widest angle one of its
 * triangles spans about the axis) with
 * charge bins on both sides count as charge; for fine charges this changes
 * nothing. The centre-of-mass angle is φ of the mass-weighted centre of all
 * particles. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "physics/geometry/geometry.h"
#include "physics/mill/mill.h"

static int cmp_desc(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* φ of a point: atan2(s x, -y), s = +1 for counter-clockwise rotation. */
static double charge_angle(double x, double y, double s)
{
    return atan2(s * x, -y);
}

void dm_charge_shape(const demill_world *w, double angles[3])
{
    const dm_drum *d = &w->drum;
    const dm_particles *P = &w->p;
    const int D = w->dim;
    angles[0] = angles[1] = angles[2] = NAN;
    if (!d->alive || P->n == 0)
        return;
    const double s = (d->omega != 0.0 ? d->omega : d->omega_to) < 0.0 ? -1.0 : 1.0;
    double hmax = 0.0, dmax = 0.0, mx = 0.0, my = 0.0, mass = 0.0;
    for (uint32_t k = 0; k < d->nlifters; k++)
        hmax = fmax(hmax, d->lifters[k].height);
    for (uint32_t k = 0; k < w->nwalls; k++) { /* lifters attached as meshes: their depth */
        const dm_wall *wall = &w->walls[k];
        if (wall->kind && wall->mesh && wall->drum_part == DM_PART_LIFTER)
            hmax = fmax(hmax, 0.5 * d->diameter - dm_mesh_axis_distance(wall, 0));
    }
    const double *c = d->centre; /* positions about the drum's centre */
    for (uint32_t i = 0; i < P->n; i++) {
        dmax = fmax(dmax, 2.0 * P->r[i]);
        const double m = dm_particle_share(w, i);
        mx += m * (P->x[D * i] - c[0]);
        my += m * (P->x[D * i + 1] - c[1]);
        mass += m;
    }
    angles[2] = charge_angle(mx / mass, my / mass, s);

    const double R = 0.5 * d->diameter, inner = R - hmax - 2.0 * dmax, rmax = 0.5 * dmax;
    double bins[DM_SHAPE_BINS] = {0}, sorted[DM_SHAPE_BINS];
    const double width = 2.0 * DM_PI / DM_SHAPE_BINS;
    for (uint32_t i = 0; i < P->n; i++) {
        const double x = P->x[D * i] - c[0], y = P->x[D * i + 1] - c[1], r = sqrt(x * x + y * y);
        if (!(r > inner && r < R)) /* (also a particle flown off to inf or NaN) */
            continue;
        int b = (int)floor((charge_angle(x, y, s) + DM_PI) / width);
        const double q = P->r[i] / rmax, size = D == 3 ? q * q * q : q * q;
        bins[b < 0 ? 0 : b >= DM_SHAPE_BINS ? DM_SHAPE_BINS - 1 : b] += size;
    }
    memcpy(sorted, bins, sizeof bins);
    qsort(sorted, DM_SHAPE_BINS, sizeof *sorted, cmp_desc);
    const double threshold = 0.5 * 0.5 * (sorted[4] + sorted[5]);
    if (sorted[0] == 0)
        return;
    bool charge[DM_SHAPE_BINS], raw[DM_SHAPE_BINS];
    for (int b = 0; b < DM_SHAPE_BINS; b++)
        raw[b] = charge[b] = bins[b] > 0 && bins[b] >= threshold;
    double lifter_width = 0.0;
    for (uint32_t k = 0; k < d->nlifters; k++)
        lifter_width = fmax(lifter_width, d->lifters[k].width);
    for (uint32_t k = 0; k < w->nwalls; k++) { /* a lifter mesh: its widest element's arc */
        const dm_wall *wall = &w->walls[k];
        if (wall->kind && wall->mesh && wall->drum_part == DM_PART_LIFTER)
            lifter_width = fmax(lifter_width, R * dm_mesh_widest_angle(wall));
    }
    const int gap = (int)ceil(lifter_width / R / width);
    for (int b = 0; b < DM_SHAPE_BINS; b++) {
        if (raw[b])
            continue;
        bool left = false, right = false;
        for (int k = 1; k <= gap; k++) {
            left |= raw[(b - k + DM_SHAPE_BINS) % DM_SHAPE_BINS];
            right |= raw[(b + k) % DM_SHAPE_BINS];
        }
        charge[b] = left && right;
    }
    /* the longest circular run of charge bins */
    int best_start = -1, best_len = 0;
    for (int start = 0; start < DM_SHAPE_BINS; start++) {
        if (!charge[start] || charge[(start + DM_SHAPE_BINS - 1) % DM_SHAPE_BINS])
            continue; /* not the first bin of a run */
        int len = 0;
        while (len < DM_SHAPE_BINS && charge[(start + len) % DM_SHAPE_BINS])
            len++;
        if (len > best_len) {
            best_len = len;
            best_start = start;
        }
    }
    if (best_start < 0) { /* every bin is charge: a ring all round */
        best_start = 0;
        best_len = DM_SHAPE_BINS;
    }
    angles[0] = -DM_PI + best_start * width;
    angles[1] = angles[0] + best_len * width;
    if (angles[1] > DM_PI + 1e-12) { /* a run across the top (φ = ±180°) */
        angles[0] -= 2.0 * DM_PI;
        angles[1] -= 2.0 * DM_PI;
    }
}
