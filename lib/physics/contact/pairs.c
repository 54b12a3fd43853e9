/* pairs.c: the resolution of materials and the user's per-pair choices into
 * the constants the contact kernels read (docs/physics.md §2-5). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/status.h"
#include "physics/contact/contact.h"
#include "physics/contact/law.h"

const dm_pair_user *dm_pair_find(const demill_world *w, uint32_t a, uint32_t b)
{
    if (a > b) {
        uint32_t t = a;
        a = b;
        b = t;
    }
    for (uint32_t k = 0; k < w->npairs; k++)
        if (w->pairs[k].a == a && w->pairs[k].b == b)
            return &w->pairs[k];
    return NULL;
}

/* The effective values of every derived key of pair (a, b). */
void dm_pair_values(const demill_world *w, uint32_t a, uint32_t b, dm_laws *laws,
                        double v[DM_PK_COUNT])
{
    const dm_material *ma = &w->mats[a], *mb = &w->mats[b];
    const dm_pair_user *u = dm_pair_find(w, a, b);
    v[DM_PK_RESTITUTION] = 0.5 * (ma->restitution + mb->restitution);
    v[DM_PK_FRICTION] = 0.5 * (ma->friction + mb->friction);
    v[DM_PK_ROLLING_FRICTION] = 0.5 * (ma->rolling_friction + mb->rolling_friction);
    /* in series; a rigid material's k is infinite, so the other's remains
     * (two rigid ones, which may not touch, as if deformable: see series()) */
    v[DM_PK_NORMAL_STIFFNESS] = ma->rigid == mb->rigid
                                    ? ma->stiffness * mb->stiffness / (ma->stiffness + mb->stiffness)
                                : ma->rigid ? mb->stiffness
                                            : ma->stiffness;
    v[DM_PK_VISCOUS] = 0;
    v[DM_PK_KT_RATIO] = 2.0 / 7.0;
    v[DM_PK_CT_FACTOR] = 1;
    v[DM_PK_COULOMB_REG] = 1;
    v[DM_PK_ROLLING_REG] = 1;
    v[DM_PK_CLAMP] = 1;
    /* the weaker material yields first; 0 is no yield */
    const double sa = ma->yield_stress, sb = mb->yield_stress;
    v[DM_PK_YIELD_PRESSURE] = 1.6 * (sa == 0.0 ? sb : sb == 0.0 ? sa : fmin(sa, sb));
    for (int k = 0; k < 4; k++) /* the multi-path fit's defaults (lib/base/params.c) */
        demill_param_bounds(DEMILL_PAIR_PLASTIC_FIT_C0 + k, NULL, NULL, &v[DM_PK_FIT_C0 + k]);
    v[DM_PK_ROLLING_STIFFNESS] = 0;
    v[DM_PK_ROLLING_DAMPING] = 0.3;
    /* the work of adhesion of two surfaces from their surface energies, by
     * the geometric-mean combining relation (Israelachvili 2011,
     * Intermolecular and Surface Forces, 3rd ed.): 2γ for one */
    v[DM_PK_ADHESION_WORK] = 2.0 * sqrt(ma->surface_energy * mb->surface_energy);
    v[DM_PK_LIQUID_VOLUME] = 1e-12;
    v[DM_PK_SURFACE_TENSION] = 0.072;
    v[DM_PK_CONTACT_ANGLE] = 0;
    *laws = (dm_laws){0, 0, 0, 0, 0};
    if (!u)
        return;
    *laws = (dm_laws){u->normal, u->damping, u->tangential, u->rolling, u->cohesion};
    for (int k = 0; k < DM_PK_COUNT; k++)
        if (u->set & (1u << k))
            v[k] = u->value[k];
}

double dm_material_compliance(const dm_material *m)
{
    return m->rigid != 0 ? 0.0 : (1 - m->poisson * m->poisson) / m->youngs;
}

/* The sum of two materials' compliances ca, cb (rigid: 0) in series. Two
 * rigid materials, which may not touch (dm_resolve_pairs() refuses them),
 * are summed as if deformable (ca, cb then the deformable values), so that
 * their pair's values stay finite and unused. */
static double series(const dm_material *ma, const dm_material *mb, double ca, double cb)
{
    const bool ra = ma->rigid != 0, rb = mb->rigid != 0;
    return ra == rb ? ca + cb : ra ? cb : ca;
}

/* E* and G* (docs/physics.md, notation), a rigid material's compliance 0. */
static void elastic_moduli(const dm_material *ma, const dm_material *mb, double *e_star,
                           double *g_star)
{
    *e_star = 1.0 / series(ma, mb, (1 - ma->poisson * ma->poisson) / ma->youngs,
                           (1 - mb->poisson * mb->poisson) / mb->youngs);
    *g_star = 1.0 / series(ma, mb, 2 * (2 - ma->poisson) * (1 + ma->poisson) / ma->youngs,
                           2 * (2 - mb->poisson) * (1 + mb->poisson) / mb->youngs);
}

static int laws_kernel(const demill_world *w, dm_laws laws)
{
    return laws.normal == DEMILL_NORMAL_NONE ? -1 : dm_kernel_index(laws, w->generic_kernels);
}

int dm_pair_kernel(const demill_world *w, uint32_t a, uint32_t b)
{
    dm_laws laws;
    double v[DM_PK_COUNT];
    dm_pair_values(w, a, b, &laws, v);
    return laws_kernel(w, laws);
}

static void pair_resolve(const demill_world *w, uint32_t a, uint32_t b, dm_pairparam *pp)
{
    dm_laws laws;
    double v[DM_PK_COUNT], g_star;
    dm_pair_values(w, a, b, &laws, v);
    memset(pp, 0, sizeof *pp);
    pp->kernel = laws_kernel(w, laws);
    pp->clamp = v[DM_PK_CLAMP] != 0;
    pp->kn = v[DM_PK_NORMAL_STIFFNESS];
    elastic_moduli(&w->mats[a], &w->mats[b], &pp->e_star, &g_star);
    pp->g8 = 8.0 * g_star;
    pp->cn = v[DM_PK_VISCOUS];
    pp->restitution = v[DM_PK_RESTITUTION];
    pp->xi = dm_damping_ratio(pp->restitution, pp->clamp);
    pp->dcoef = (laws.normal == DEMILL_NORMAL_HERTZ ? 2.0 * sqrt(5.0 / 6.0) : 2.0) * pp->xi;
    pp->kt = v[DM_PK_KT_RATIO] * pp->kn;
    pp->ct_factor = v[DM_PK_CT_FACTOR];
    pp->mu = v[DM_PK_FRICTION];
    pp->mu_r = v[DM_PK_ROLLING_FRICTION];
    pp->coul_reg = v[DM_PK_COULOMB_REG];
    pp->roll_reg = v[DM_PK_ROLLING_REG];
    pp->py = v[DM_PK_YIELD_PRESSURE] > 0.0 ? v[DM_PK_YIELD_PRESSURE] : INFINITY;
    for (int k = 0; k < 4; k++)
        pp->fit[k] = v[DM_PK_FIT_C0 + k];
    pp->kr = v[DM_PK_ROLLING_STIFFNESS];
    pp->eta_r = v[DM_PK_ROLLING_DAMPING];
    pp->adhesion = v[DM_PK_ADHESION_WORK];
    pp->liquid_volume = v[DM_PK_LIQUID_VOLUME];
    pp->surface_tension = v[DM_PK_SURFACE_TENSION];
    pp->contact_angle = v[DM_PK_CONTACT_ANGLE];
}

/* Rebuilds the resolved pair table if anything changed, and (if asked)
 * checks that every pair of materials that may touch has a model. Leaves
 * the world unchanged when it fails. */
demill_status dm_resolve_pairs(demill_world *w, bool require_models)
{
    if (require_models) {
        for (uint32_t a = 0; a < w->nmat; a++) {
            if (!w->mat_particles[a])
                continue;
            for (uint32_t b = 0; b < w->nmat; b++) {
                if (!w->mat_particles[b] && !w->mat_walls[b])
                    continue;
                const char *kind =
                    w->mat_walls[b] && !w->mat_particles[b] ? "particle-wall" : "particle-particle";
                if (w->mats[a].rigid != 0 && w->mats[b].rigid != 0) {
                    /* no finite stiffness: refused if they can touch, and
                     * needs no model if they cannot (a lone particle of a
                     * rigid material without walls of it) */
                    if (w->mat_walls[b] || w->mat_particles[b] > (b == a))
                        return dm_fail(w, DEMILL_ERR_NO_CONTACT_MODEL,
                                       "materials %u and %u (%s) are both rigid "
                                       "(DEMILL_MATERIAL_RIGID): their contact has no finite "
                                       "stiffness; make one of them deformable",
                                       a, b, kind);
                    continue;
                }
                const dm_pair_user *u = dm_pair_find(w, a, b);
                if (!u || u->normal == DEMILL_NORMAL_NONE)
                    return dm_fail(w, DEMILL_ERR_NO_CONTACT_MODEL,
                                   "no contact model for materials %u and %u (%s): set "
                                   "DEMILL_PAIR_NORMAL with demill_pair_set()",
                                   a, b, kind);
                static const char *const plastic[] = {"THORNTON", "WALTON_BRAUN",
                                                      "PLASTIC_PATHS"};
                if (dm_normal_plastic(u->normal) && u->damping == DEMILL_DAMPING_RESTITUTION)
                    return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                                   "materials %u and %u: the plastic normal law DEMILL_NORMAL_%s "
                                   "dissipates on its own, and DEMILL_DAMPING_RESTITUTION, "
                                   "derived for an elastic law, would rebound below the "
                                   "restitution asked for: use DEMILL_DAMPING_NONE or "
                                   "DEMILL_DAMPING_VISCOUS",
                                   a, b, plastic[u->normal - DEMILL_NORMAL_THORNTON]);
                if (u->cohesion == DEMILL_COHESION_JKR && u->normal != DEMILL_NORMAL_HERTZ)
                    return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                                   "materials %u and %u (%s): JKR cohesion is a law of Hertz "
                                   "contacts; set DEMILL_PAIR_NORMAL to DEMILL_NORMAL_HERTZ",
                                   a, b, kind);
            }
        }
    }
    if (!w->ptab_dirty && w->nmat_tab == w->nmat)
        return DEMILL_OK;
    uint32_t nm = w->nmat;
    dm_pairparam *tab = malloc((size_t)(nm ? nm : 1) * (nm ? nm : 1) * sizeof *tab);
    if (!tab)
        return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "out of memory resolving contact models");
    bool rotation = false, kernels_changed = false;
    int nkern = 0;
    for (uint32_t a = 0; a < nm; a++)
        for (uint32_t b = 0; b < nm; b++) {
            dm_pairparam *pp = &tab[a * nm + b];
            pair_resolve(w, a, b, pp);
            nkern = pp->kernel >= nkern ? pp->kernel + 1 : nkern;
            if (pp->kernel >= 0 && w->mat_particles[a] && (w->mat_particles[b] || w->mat_walls[b])) {
                dm_laws l = dm_kernel_laws(pp->kernel);
                rotation |= l.tangential != DEMILL_TANGENTIAL_NONE || l.rolling != DEMILL_ROLLING_NONE;
            }
            if (a < w->nmat_tab && b < w->nmat_tab &&
                w->ptab[a * w->nmat_tab + b].kernel != pp->kernel)
                kernels_changed = true;
        }
    bool local_damping = false;
    for (uint32_t a = 0; a < nm; a++)
        local_damping |= w->mat_particles[a] && w->mats[a].local_damping > 0.0;
    free(w->ptab);
    w->ptab = tab;
    w->nmat_tab = nm;
    w->ptab_dirty = false;
    w->rotation = rotation;
    w->nkern = nkern;
    w->local_damping = local_damping;
    if (kernels_changed) {
        /* contact lists are grouped by kernel: start them afresh */
        dm_clist_clear(w);
        w->nlist_valid = false;
    } else if (dm_cohesion_reach(w, w->skin / w->skin_fraction) >
               w->cohesion_reach * (1.0 + 1e-12)) {
        /* cohesion reaches further than the lists were built for (at the
         * largest radius then, skin / skin fraction): build them again,
         * carrying the contacts over */
        w->nlist_valid = false;
    }
    return DEMILL_OK;
}

double dm_cohesion_reach(const demill_world *w, double rmax)
{
    double reach = 0.0;
    const uint32_t nm = w->nmat_tab;
    for (uint32_t a = 0; a < nm; a++)
        for (uint32_t b = 0; b < nm; b++) {
            const dm_pairparam *pp = &w->ptab[a * nm + b];
            if (pp->kernel < 0 || !w->mat_particles[a] ||
                !(w->mat_particles[b] || w->mat_walls[b]))
                continue;
            /* JKR's reach grows with R*, which is at most the largest radius */
            const double r = dm_law_range(dm_kernel_laws(pp->kernel).cohesion, pp, rmax);
            reach = r > reach ? r : reach;
        }
    return reach;
}
