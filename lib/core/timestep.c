/* timestep.c: the time step a scene needs (docs/physics.md §8): contact durations
 * and stability limits of the material pairs that can meet, and the Rayleigh
 * time of Hertz materials. */
#include <math.h>

#include "internal.h"

#define DEFAULT_STEPS_PER_CONTACT 50.0
#define LIMIT_FRACTION 0.2 /* of the stability limit and of the Rayleigh time */

/* The smallest of each bound over the pairs seen so far. */
typedef struct step_bounds {
    double suggested, critical, contact;
} step_bounds;

/* Takes in one pair of reduced mass m* and radius R* meeting at speed v. */
static void pair_bounds(const dm_pairparam *pp, double mstar, double rstar, double v,
                        double steps, step_bounds *b)
{
    double omega, contact;
    if (dm_kernel_laws(pp->kernel).normal == DEMILL_NORMAL_HERTZ) {
        /* Johnson §11.4: the largest overlap and the duration of an elastic
         * impact; the stiffness dF/dδ at that overlap */
        const double es = pp->e_star;
        const double delta = pow(15.0 * mstar * v * v / (16.0 * es * sqrt(rstar)), 0.4);
        contact = 2.87 * pow(mstar * mstar / (rstar * es * es * v), 0.2);
        omega = sqrt(2.0 * es * sqrt(rstar * delta) / mstar);
    } else {
        omega = sqrt(pp->kn / mstar);
        contact = DM_PI / omega;
    }
    const double limit = 2.0 / omega;
    b->critical = fmin(b->critical, limit);
    b->contact = fmin(b->contact, contact);
    b->suggested = fmin(b->suggested, fmin(contact / steps, LIMIT_FRACTION * limit));
}

/* π R √(ρ/G) / (0.1631 ν + 0.8766), G = E / (2 (1 + ν)). */
static double rayleigh_time(const dm_material *m, double r)
{
    const double g = m->youngs / (2.0 * (1.0 + m->poisson));
    return DM_PI * r * sqrt(m->density / g) / (0.1631 * m->poisson + 0.8766);
}

/* The largest impact speed to expect: twice the fastest particle, a fall
 * through the height of the scene along gravity (the particle centres' span,
 * or the drum's diameter if larger), twice the drum's rim speed at its target
 * speed; 1 m/s at least. */
static double estimated_impact_speed(const demill_world *w)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    double v2 = 0.0, lo = INFINITY, hi = -INFINITY; /* lo, hi: of x·g, m²/s² */
    for (uint32_t i = 0; i < P->n; i++) {
        double s2 = 0.0, xg = 0.0;
        for (int c = 0; c < D; c++) {
            s2 += P->v[D * i + c] * P->v[D * i + c];
            xg += P->x[D * i + c] * w->g[c];
        }
        v2 = fmax(v2, s2);
        lo = fmin(lo, xg);
        hi = fmax(hi, xg);
    }
    double v = fmax(1.0, 2.0 * sqrt(v2));
    double gh = hi - lo; /* g H */
    const dm_drum *d = &w->drum;
    if (d->alive) {
        const double g = dm_gravity_magnitude(w);
        gh = fmax(gh, g * d->diameter);
        const double omega = dm_drum_target_speed(w);
        if (isfinite(omega))
            v = fmax(v, fabs(omega) * d->diameter);
    }
    return fmax(v, sqrt(2.0 * gh));
}

DEMILL_API demill_status demill_world_suggest_time_step(demill_world *w, double impact_speed,
                                                        double steps_per_contact,
                                                        double *suggested, double *critical,
                                                        double *contact_time)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!suggested)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_suggest_time_step: suggested is NULL");
    if (!isfinite(impact_speed))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                       "world_suggest_time_step: impact_speed %g is not finite", impact_speed);
    if (!isfinite(steps_per_contact))
        return dm_fail(w, DEMILL_ERR_NOT_FINITE,
                       "world_suggest_time_step: steps_per_contact %g is not finite",
                       steps_per_contact);
    if (impact_speed < 0.0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_suggest_time_step: impact_speed %g must be >= 0 (0: estimated "
                       "from the scene)",
                       impact_speed);
    if (steps_per_contact != 0.0 && !(steps_per_contact >= 1.0))
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_suggest_time_step: steps_per_contact %g must be >= 1 (0: %g)",
                       steps_per_contact, DEFAULT_STEPS_PER_CONTACT);
    const dm_particles *P = &w->p;
    if (P->n == 0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_suggest_time_step: the world has no particles");
    if ((s = dm_resolve_pairs(w, true)))
        return s;

    const uint32_t nm = w->nmat;
    double rmin[DM_MAX_MATERIALS], mass[DM_MAX_MATERIALS], inv_i;
    for (uint32_t a = 0; a < nm; a++)
        rmin[a] = INFINITY;
    for (uint32_t i = 0; i < P->n; i++)
        rmin[P->mat[i]] = fmin(rmin[P->mat[i]], P->r[i]);
    for (uint32_t a = 0; a < nm; a++)
        if (w->mat_particles[a])
            dm_particle_mass(w, a, rmin[a], &mass[a], &inv_i);

    const double v = impact_speed > 0.0 ? impact_speed : estimated_impact_speed(w);
    const double steps = steps_per_contact > 0.0 ? steps_per_contact : DEFAULT_STEPS_PER_CONTACT;
    step_bounds b = {INFINITY, INFINITY, INFINITY};
    /* each particle pair is taken twice, as (a, b) and (b, a), with the same
     * result, so that every particle material sees all its pairs */
    for (uint32_t a = 0; a < nm; a++) {
        if (!w->mat_particles[a])
            continue;
        bool hertz = false;
        for (uint32_t c = 0; c < nm; c++) {
            const dm_pairparam *pp = &w->ptab[a * nm + c];
            if (w->mat_particles[c])
                pair_bounds(pp, mass[a] * mass[c] / (mass[a] + mass[c]),
                            rmin[a] * rmin[c] / (rmin[a] + rmin[c]), v, steps, &b);
            if (w->mat_walls[c])
                pair_bounds(pp, mass[a], rmin[a], v, steps, &b);
            hertz |= (w->mat_particles[c] || w->mat_walls[c]) &&
                     dm_kernel_laws(pp->kernel).normal == DEMILL_NORMAL_HERTZ;
        }
        if (hertz)
            b.suggested = fmin(b.suggested, LIMIT_FRACTION * rayleigh_time(&w->mats[a], rmin[a]));
    }
    *suggested = b.suggested;
    if (critical)
        *critical = b.critical;
    if (contact_time)
        *contact_time = b.contact;
    dm_clear_error(w);
    return DEMILL_OK;
}
