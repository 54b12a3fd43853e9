/* material.c: materials and the user's per-pair choices (resolved into the
 * kernels' constants by lib/physics/contact/pairs.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

static const dm_material default_material = {
    .density = 2500, .youngs = 1e8, .poisson = 0.3, .stiffness = 1e5,
    .restitution = 0.5, .friction = 0.5, .rolling_friction = 0, .yield_stress = 0,
    .local_damping = 0, .rigid = 0, .surface_energy = 0};

DEMILL_API demill_status demill_material_create(demill_world *w, demill_id *out)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!out)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "material_create: out is NULL");
    if (w->nmat >= DM_MAX_MATERIALS)
        return dm_fail(w, DEMILL_ERR_INVALID_VALUE, "material_create: at most %d materials",
                       DM_MAX_MATERIALS);
    w->mats[w->nmat] = default_material;
    *out = dm_material_id(w, w->nmat);
    w->nmat++;
    w->ptab_dirty = true;
    dm_changed(w);
    return DEMILL_OK;
}

static double *material_field(dm_material *m, int32_t key)
{
    switch (key) {
    case DEMILL_MATERIAL_DENSITY: return &m->density;
    case DEMILL_MATERIAL_YOUNGS_MODULUS: return &m->youngs;
    case DEMILL_MATERIAL_POISSON_RATIO: return &m->poisson;
    case DEMILL_MATERIAL_STIFFNESS: return &m->stiffness;
    case DEMILL_MATERIAL_RESTITUTION: return &m->restitution;
    case DEMILL_MATERIAL_FRICTION: return &m->friction;
    case DEMILL_MATERIAL_ROLLING_FRICTION: return &m->rolling_friction;
    case DEMILL_MATERIAL_YIELD_STRESS: return &m->yield_stress;
    case DEMILL_MATERIAL_LOCAL_DAMPING: return &m->local_damping;
    case DEMILL_MATERIAL_RIGID: return &m->rigid;
    case DEMILL_MATERIAL_SURFACE_ENERGY: return &m->surface_energy;
    default: return NULL;
    }
}

demill_status dm_particle_mass_checked(demill_world *w, uint32_t mat, double r, const char *who,
                                       double *m, double *inv_i)
{
    dm_particle_mass(w, mat, r, m, inv_i);
    if (isfinite(*m) && *m > 0.0 && isfinite(1.0 / *m) && isfinite(*inv_i) && *inv_i > 0.0)
        return DEMILL_OK;
    return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                   "%s: radius %g m with density %g kg/m^3 gives mass %g kg and inverse moment "
                   "of inertia %g: they must be finite and positive, and so must their "
                   "inverses",
                   who, r, w->mats[mat].density, *m, *inv_i);
}

demill_status dm_masses_update(demill_world *w, uint32_t mat, const char *who)
{
    dm_particles *p = &w->p;
    demill_status s = DEMILL_OK;
    for (uint32_t k = 0; k < w->ntemplates; k++)
        if (mat == DM_ALL_MATERIALS || w->templates[k].material == mat)
            return dm_fail(w, DEMILL_ERR_INVALID_VALUE,
                           "%s: clump template 0x%llx weighed its spheres with it when it was "
                           "made; it cannot change while the world has clump templates",
                           who, (unsigned long long)dm_template_id(w, k));
    for (uint32_t i = 0; i < p->n && !s; i++)
        if (mat == DM_ALL_MATERIALS || p->mat[i] == mat) {
            double m, inv_i;
            s = dm_particle_mass_checked(w, p->mat[i], p->r[i], who, &m, &inv_i);
        }
    if (s)
        return s;
    for (uint32_t i = 0; i < p->n; i++)
        if (mat == DM_ALL_MATERIALS || p->mat[i] == mat)
            dm_particle_set_mass(w, i, dm_particle_fixed(p, i));
    return DEMILL_OK;
}

DEMILL_API demill_status demill_material_set(demill_world *w, demill_id material, int32_t key,
                                             double value)
{
    uint32_t mi;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mi);
    if (s)
        return s;
    double *field = material_field(&w->mats[mi], key);
    if (!field)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "material_set: %d is not a material key",
                       (int)key);
    if ((s = dm_check_value(w, key, value)))
        return s;
    const double old = *field;
    *field = value;
    if (key == DEMILL_MATERIAL_DENSITY && (s = dm_masses_update(w, mi, "material.density"))) {
        *field = old;
        return s;
    }
    w->ptab_dirty = true;
    w->forces_valid = false;
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_material_get(const demill_world *cw, demill_id material,
                                             int32_t key, double *value)
{
    demill_world *w = (demill_world *)cw;
    uint32_t mi;
    demill_status s = dm_enter(w, material, DEMILL_KIND_MATERIAL, "material", &mi);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "material_get: value is NULL");
    double *field = material_field(&w->mats[mi], key);
    if (!field)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "material_get: %d is not a material key",
                       (int)key);
    *value = *field;
    return DEMILL_OK;
}

/* ---- pairs --------------------------------------------------------------- */

static int pair_key_index(int32_t key)
{
    switch (key) {
    case DEMILL_PAIR_RESTITUTION: return DM_PK_RESTITUTION;
    case DEMILL_PAIR_FRICTION: return DM_PK_FRICTION;
    case DEMILL_PAIR_ROLLING_FRICTION: return DM_PK_ROLLING_FRICTION;
    case DEMILL_PAIR_NORMAL_STIFFNESS: return DM_PK_NORMAL_STIFFNESS;
    case DEMILL_PAIR_VISCOUS_DAMPING: return DM_PK_VISCOUS;
    case DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO: return DM_PK_KT_RATIO;
    case DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR: return DM_PK_CT_FACTOR;
    case DEMILL_PAIR_COULOMB_REGULARISATION: return DM_PK_COULOMB_REG;
    case DEMILL_PAIR_ROLLING_REGULARISATION: return DM_PK_ROLLING_REG;
    case DEMILL_PAIR_CLAMP_NORMAL: return DM_PK_CLAMP;
    case DEMILL_PAIR_YIELD_PRESSURE: return DM_PK_YIELD_PRESSURE;
    case DEMILL_PAIR_PLASTIC_FIT_C0: return DM_PK_FIT_C0;
    case DEMILL_PAIR_PLASTIC_FIT_C1: return DM_PK_FIT_C1;
    case DEMILL_PAIR_PLASTIC_FIT_C2: return DM_PK_FIT_C2;
    case DEMILL_PAIR_PLASTIC_FIT_EXPONENT: return DM_PK_FIT_H;
    case DEMILL_PAIR_ROLLING_STIFFNESS: return DM_PK_ROLLING_STIFFNESS;
    case DEMILL_PAIR_ROLLING_DAMPING_RATIO: return DM_PK_ROLLING_DAMPING;
    case DEMILL_PAIR_ADHESION_WORK: return DM_PK_ADHESION_WORK;
    case DEMILL_PAIR_LIQUID_VOLUME: return DM_PK_LIQUID_VOLUME;
    case DEMILL_PAIR_SURFACE_TENSION: return DM_PK_SURFACE_TENSION;
    case DEMILL_PAIR_CONTACT_ANGLE: return DM_PK_CONTACT_ANGLE;
    default: return -1;
    }
}

/* The entry check of the pair functions: a live world and two materials. */
static demill_status enter_pair(const demill_world *w, demill_id a, demill_id b, uint32_t *ma,
                                uint32_t *mb)
{
    demill_status s = dm_enter(w, a, DEMILL_KIND_MATERIAL, "a", ma);
    return s ? s : dm_resolve(w, b, DEMILL_KIND_MATERIAL, "b", mb);
}

DEMILL_API demill_status demill_pair_set(demill_world *w, demill_id a, demill_id b, int32_t key,
                                         double value)
{
    uint32_t ma, mb;
    demill_status s = enter_pair(w, a, b, &ma, &mb);
    if (s)
        return s;
    int pk = pair_key_index(key);
    bool law = key >= DEMILL_PAIR_NORMAL && key <= DEMILL_PAIR_COHESION;
    if (pk < 0 && !law)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "pair_set: %d is not a pair key", (int)key);
    if ((s = dm_check_value(w, key, value)))
        return s;
    dm_pair_user *u = (dm_pair_user *)dm_pair_find(w, ma, mb);
    if (!u) {
        if (w->npairs == w->cap_pairs) {
            uint32_t cap = w->cap_pairs ? 2 * w->cap_pairs : 8;
            dm_pair_user *np = realloc(w->pairs, cap * sizeof *np);
            if (!np)
                return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "pair_set: out of memory");
            w->pairs = np;
            w->cap_pairs = cap;
        }
        u = &w->pairs[w->npairs++];
        memset(u, 0, sizeof *u);
        u->a = ma < mb ? ma : mb;
        u->b = ma < mb ? mb : ma;
    }
    const int kernel = dm_pair_kernel(w, ma, mb);
    switch (key) { /* a law is a small whole number (checked); other values need not fit an int */
    case DEMILL_PAIR_NORMAL: u->normal = (int32_t)value; break;
    case DEMILL_PAIR_DAMPING: u->damping = (int32_t)value; break;
    case DEMILL_PAIR_TANGENTIAL: u->tangential = (int32_t)value; break;
    case DEMILL_PAIR_ROLLING: u->rolling = (int32_t)value; break;
    case DEMILL_PAIR_COHESION: u->cohesion = (int32_t)value; break;
    default:
        u->value[pk] = value;
        u->set |= 1u << pk;
    }
    w->ptab_dirty = true;
    w->forces_valid = false;
    if (dm_pair_kernel(w, ma, mb) != kernel) {
        /* the contact lists are grouped by kernel: start them afresh now, as
         * the next step would, so that no state holds a contact in the list
         * of a law its pair no longer has (the checkpoint loader refuses it) */
        dm_clist_clear(w);
        w->nlist_valid = false;
    }
    dm_changed(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_pair_get(const demill_world *cw, demill_id a, demill_id b,
                                         int32_t key, double *value)
{
    demill_world *w = (demill_world *)cw;
    uint32_t ma, mb;
    demill_status s = enter_pair(w, a, b, &ma, &mb);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "pair_get: value is NULL");
    dm_laws laws;
    double v[DM_PK_COUNT];
    dm_pair_values(w, ma, mb, &laws, v);
    int pk = pair_key_index(key);
    switch (key) {
    case DEMILL_PAIR_NORMAL: *value = laws.normal; break;
    case DEMILL_PAIR_DAMPING: *value = laws.damping; break;
    case DEMILL_PAIR_TANGENTIAL: *value = laws.tangential; break;
    case DEMILL_PAIR_ROLLING: *value = laws.rolling; break;
    case DEMILL_PAIR_COHESION: *value = laws.cohesion; break;
    default:
        if (pk < 0)
            return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "pair_get: %d is not a pair key",
                           (int)key);
        *value = v[pk];
    }
    return DEMILL_OK;
}
