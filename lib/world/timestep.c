/* timestep.c: the time step a scene needs (docs/physics.md §8): contact
 * durations and stability limits of the material pairs that can meet, and
 * the Rayleigh time of deformable Hertz materials; and the check, when stepping starts,
 * that the time step is within every pair's stability limit. */
#include <math.h>
#include <stdio.h>

#include "physics/contact/plastic.h"
#include "world/world.h"

#define DEFAULT_STEPS_PER_CONTACT 50.0
#define LIMIT_FRACTION 0.2 /* of the stability limit and of the Rayleigh time */

/* The largest step at which the integrators keep a contact mode of natural
 * frequency omega (0 for a dashpot alone) and damping rate beta = c/(2m)
 * stable: 2/(√(ω² + 4β²) + 2β), that is (2/ω)(√(1 + 4ξ²) − 2ξ) with
 * ξ = β/ω, and m/c for a dashpot alone. It is the central difference
 * method's limit (2/ω)(√(1 + ξ²) − ξ) (Belytschko, Liu & Moran 2000,
 * Nonlinear Finite Elements for Continua and Structures, §6.3) with twice
 * the damping, for two reasons: the library's velocity Verlet lets the
 * dashpots see the velocity predicted a whole step ahead, which acts as
 * twice the damping rate (this is exactly the limit of its amplification
 * matrix, for a linear spring-dashpot); and the first sample of a contact
 * carries up to 1.5 (Verlet) or 2 (symplectic Euler) times the dashpot's
 * impulse (the entry correction of contact/law.h), which at this limit
 * cannot turn an approach into a faster rebound. Symplectic Euler and the
 * iterative refinement are stable somewhat beyond it, and so is Verlet where
 * the normal force is clamped or the dashpot treated implicitly (unclamped
 * linear contacts): measured on a ball pressed on a floor, instability sets
 * in at 1.0 to 3.7 times this limit (docs/physics.md §8). */
static double mode_limit(double omega, double beta)
{
    return 2.0 / (sqrt(omega * omega + 4.0 * beta * beta) + 2.0 * beta);
}

/* The bodies of a pair as the contact sees them: reduced mass and radius,
 * the inverse of the mass the tangential force moves (the contact points
 * slide with the bodies' spins: 1/m_a + 1/m_b + R_a²/I_a + R_b²/I_b, 2/7 of
 * m* for two spheres), and the inverse inertia of their relative rotation. */
typedef struct pair_bodies {
    double mstar, rstar, inv_mt, inv_it;
} pair_bodies;

/* What a pair's contact needs of the time step, at impact speed v. */
typedef struct pair_needs {
    double contact; /* duration of an impact */
    double limit;   /* the stability limit: the smallest of its modes' */
    const char *mode; /* the mode that sets it */
} pair_needs;

static pair_needs pair_analysis(const dm_pairparam *pp, const pair_bodies *b, double v)
{
    const dm_laws laws = dm_kernel_laws(pp->kernel);
    const double ms = b->mstar, mt = 1.0 / b->inv_mt;
    pair_needs n;
    /* the normal spring's stiffness S (for Hertz, at the largest overlap of
     * an elastic impact at v, Johnson 1985, Contact Mechanics §11.4), the
     * impact's duration and √(R* δ_max), which Mindlin's k_t follows */
    double stiff, sq;
    if (dm_normal_plastic(laws.normal)) {
        /* the unloading curve's slope at δ_max, and twice the shorter of
         * the loading and unloading phases (contact/plastic.h) */
        double delta;
        dm_plastic_impact(laws.normal, pp, b->rstar, ms, v, &delta, &stiff, &n.contact);
        sq = sqrt(b->rstar * delta);
    } else if (laws.normal == DEMILL_NORMAL_HERTZ) {
        const double es = pp->e_star;
        const double delta = pow(15.0 * ms * v * v / (16.0 * es * sqrt(b->rstar)), 0.4);
        n.contact = 2.87 * pow(ms * ms / (b->rstar * es * es * v), 0.2);
        sq = sqrt(b->rstar * delta);
        stiff = 2.0 * es * sq;
    } else {
        stiff = pp->kn;
        n.contact = DM_PI / sqrt(stiff / ms);
        sq = sqrt(b->rstar * v * sqrt(ms / stiff));
    }
    /* normal spring and dashpot */
    double cn = 0.0;
    if (laws.damping == DEMILL_DAMPING_VISCOUS)
        cn = pp->cn;
    if (laws.damping == DEMILL_DAMPING_RESTITUTION)
        cn = pp->dcoef * sqrt(ms * stiff);
    n.limit = mode_limit(sqrt(stiff / ms), 0.5 * cn / ms);
    n.mode = "normal spring and dashpot";
    /* tangential spring and dashpot, or the regularised Coulomb dashpot */
    double lt = INFINITY;
    if (laws.tangential == DEMILL_TANGENTIAL_SPRING ||
        laws.tangential == DEMILL_TANGENTIAL_MINDLIN) {
        const double kt = laws.tangential == DEMILL_TANGENTIAL_SPRING ? pp->kt : pp->g8 * sq;
        double ct = 0.0;
        if (laws.damping == DEMILL_DAMPING_VISCOUS)
            ct = pp->ct_factor * pp->cn;
        if (laws.damping == DEMILL_DAMPING_RESTITUTION)
            ct = pp->ct_factor * pp->dcoef * sqrt(ms * kt);
        lt = mode_limit(sqrt(kt / mt), 0.5 * ct / mt);
    }
    if (laws.tangential == DEMILL_TANGENTIAL_COULOMB)
        lt = mode_limit(0.0, 0.5 * pp->coul_reg * sqrt(ms * stiff) / mt);
    if (lt < n.limit) {
        n.limit = lt;
        n.mode = "tangential spring and dashpot";
    }
    /* the rolling resistance's regularising dashpot */
    if (laws.rolling == DEMILL_ROLLING_CONSTANT_TORQUE) {
        const double cr = pp->roll_reg * b->rstar * b->rstar * sqrt(ms * stiff);
        const double lr = mode_limit(0.0, 0.5 * cr * b->inv_it);
        if (lr < n.limit) {
            n.limit = lr;
            n.mode = "rolling resistance";
        }
    }
    return n;
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

/* Each particle material with its smallest particle: radius, mass and
 * inverse moment of inertia (rmin INFINITY for a material without
 * particles). */
typedef struct smallest {
    double r[DM_MAX_MATERIALS], m[DM_MAX_MATERIALS], iinv[DM_MAX_MATERIALS];
} smallest;

static void smallest_particles(const demill_world *w, smallest *sm)
{
    const dm_particles *P = &w->p;
    for (uint32_t a = 0; a < w->nmat; a++)
        sm->r[a] = INFINITY;
    for (uint32_t i = 0; i < P->n; i++)
        sm->r[P->mat[i]] = fmin(sm->r[P->mat[i]], P->r[i]);
    for (uint32_t a = 0; a < w->nmat; a++)
        if (w->mat_particles[a])
            dm_particle_mass(w, a, sm->r[a], &sm->m[a], &sm->iinv[a]);
}

/* A pair of a particle material a with particle material c or (wall) with
 * a wall of material c. */
static pair_bodies bodies(const smallest *sm, uint32_t a, uint32_t c, int wall)
{
    const double ra = sm->r[a], ma = sm->m[a], ia = sm->iinv[a];
    if (wall)
        return (pair_bodies){ma, ra, 1.0 / ma + ra * ra * ia, ia};
    const double rc = sm->r[c], mc = sm->m[c], ic = sm->iinv[c];
    return (pair_bodies){ma * mc / (ma + mc), ra * rc / (ra + rc),
                         1.0 / ma + 1.0 / mc + ra * ra * ia + rc * rc * ic, ia + ic};
}

/* Calls fn for every pair of materials that can meet: each pair of
 * particle materials that have particles, and each particle material with
 * each material of a wall, but not two rigid ones (dm_resolve_pairs() has
 * made sure that they cannot touch); only_now: leaving out a material's pair with
 * itself while it has a single particle. Returns the first nonzero result
 * of fn. */
typedef int (*pair_fn)(demill_world *w, void *ctx, uint32_t a, uint32_t c, int wall,
                       const pair_needs *n);

static int each_pair(demill_world *w, const smallest *sm, double v, int only_now, pair_fn fn,
                     void *ctx)
{
    const uint32_t nm = w->nmat;
    for (uint32_t a = 0; a < nm; a++) {
        if (!w->mat_particles[a])
            continue;
        for (uint32_t c = 0; c < nm; c++)
            for (int wall = 0; wall < 2; wall++) {
                if (!(wall ? w->mat_walls[c] : w->mat_particles[c]) ||
                    (only_now && !wall && c == a && w->mat_particles[a] < 2) ||
                    (w->mats[a].rigid != 0 && w->mats[c].rigid != 0))
                    continue;
                const pair_bodies b = bodies(sm, a, c, wall);
                const pair_needs n = pair_analysis(&w->ptab[a * nm + c], &b, v);
                const int r = fn(w, ctx, a, c, wall, &n);
                if (r)
                    return r;
            }
    }
    return 0;
}

/* Pair (a, c) cannot be stepped: at the world's time step (step: 1), or at
 * any time step (its limit is 0). */
static demill_status unstable_pair(demill_world *w, const char *call, uint32_t a, uint32_t c,
                                   int wall, const pair_needs *n, int step)
{
    const dm_pairparam *pp = &w->ptab[a * w->nmat + c];
    const char *hint = pp->restitution == 0.0 && pp->clamp &&
                               dm_kernel_laws(pp->kernel).damping == DEMILL_DAMPING_RESTITUTION
                           ? ": restitution 0 with the clamped normal law needs infinite "
                             "damping; unclamp it (DEMILL_PAIR_CLAMP_NORMAL = 0), where e = 0 "
                             "is critical damping, or set e > 0"
                           : "";
    char what[160];
    if (step)
        snprintf(what, sizeof what,
                 "the time step %g s exceeds the largest stable time step of their %s, %.6g s",
                 w->dt, n->mode, n->limit);
    else
        snprintf(what, sizeof what, "no time step integrates their %s stably", n->mode);
    return dm_fail(w, DEMILL_ERR_UNSTABLE, "%s: materials 0x%llx and 0x%llx (%s): %s%s", call,
                   (unsigned long long)dm_material_id(w, a),
                   (unsigned long long)dm_material_id(w, c),
                   wall ? "particle-wall" : "particle-particle", what, hint);
}

/* ---- the suggestion ------------------------------------------------------------ */

typedef struct step_bounds {
    double suggested, critical, contact, steps;
    uint32_t a, c; /* the pair with the smallest limit */
    int wall;
    pair_needs worst;
} step_bounds;

static int take_bounds(demill_world *w, void *ctx, uint32_t a, uint32_t c, int wall,
                       const pair_needs *n)
{
    (void)w;
    step_bounds *b = ctx;
    if (!(n->limit >= b->critical)) {
        b->critical = n->limit;
        b->worst = *n;
        b->a = a;
        b->c = c;
        b->wall = wall;
    }
    b->contact = fmin(b->contact, n->contact);
    b->suggested = fmin(b->suggested, fmin(n->contact / b->steps, LIMIT_FRACTION * n->limit));
    return 0;
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
    if (w->p.n == 0)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                       "world_suggest_time_step: the world has no particles");
    if ((s = dm_resolve_pairs(w, true)))
        return s;

    smallest sm;
    smallest_particles(w, &sm);
    const double v = impact_speed > 0.0 ? impact_speed : estimated_impact_speed(w);
    step_bounds b = {.suggested = INFINITY, .critical = INFINITY, .contact = INFINITY,
                     .steps = steps_per_contact > 0.0 ? steps_per_contact
                                                      : DEFAULT_STEPS_PER_CONTACT};
    each_pair(w, &sm, v, 0, take_bounds, &b);
    if (!(b.critical > 0.0))
        return unstable_pair(w, "world_suggest_time_step", b.a, b.c, b.wall, &b.worst, 0);
    for (uint32_t a = 0; a < w->nmat; a++) {
        bool hertz = false;
        for (uint32_t c = 0; c < w->nmat && w->mat_particles[a]; c++)
            hertz |= (w->mat_particles[c] || w->mat_walls[c]) &&
                     dm_normal_hertzian(dm_kernel_laws(w->ptab[a * w->nmat + c].kernel).normal);
        if (hertz && w->mats[a].rigid == 0) /* a rigid particle carries no elastic wave */
            b.suggested = fmin(b.suggested, LIMIT_FRACTION * rayleigh_time(&w->mats[a], sm.r[a]));
    }
    *suggested = b.suggested;
    if (critical)
        *critical = b.critical;
    if (contact_time)
        *contact_time = b.contact;
    dm_clear_error(w);
    return DEMILL_OK;
}

/* ---- the check when stepping starts ---------------------------------------------- */

static int beyond_limit(demill_world *w, void *ctx, uint32_t a, uint32_t c, int wall,
                        const pair_needs *n)
{
    (void)ctx;
    if (w->dt <= n->limit)
        return 0;
    unstable_pair(w, "world_step", a, c, wall, n, 1);
    return 1;
}

demill_status dm_check_time_step(demill_world *w)
{
    smallest sm;
    smallest_particles(w, &sm);
    return each_pair(w, &sm, estimated_impact_speed(w), 1, beyond_limit, NULL)
               ? DEMILL_ERR_UNSTABLE
               : DEMILL_OK;
}
