/* energy.c: the energy account of docs/physics.md §10 and the contact queries,
 * both read from the current state without changing it. */
#include <string.h>

#include "world/world.h"

/* Brings the contact lists and wall geometry up to date for a query. Only
 * internal order may change; the physical state does not. */
static demill_status prepare_query(demill_world *w)
{
    demill_status s = dm_resolve_pairs(w, false);
    if (s)
        return s;
    if (!w->nlist_valid && (s = dm_nlist_build(w)))
        return s;
    dm_wgeom_update(w);
    return DEMILL_OK;
}

static void add_stored(void *ctx, const dm_contact_eval *c)
{
    double *e = ctx;
    e[DM_E_NORMAL] += c->e_normal;
    e[DM_E_TANGENTIAL] += c->e_tangential;
    e[DM_E_ROLLING] += c->e_rolling;
}

/* The energies of the current state (DM_E_*): kinetic and potential (of the
 * free particles and of the clumps, whose members count only as theirs)
 * and, with stored, the elastic energy of the contacts' springs (left 0
 * otherwise); then the bodies' energies, each summed over the bodies. */
demill_status dm_energies(demill_world *w, int stored, double e[DM_ENERGIES])
{
    const dm_particles *P = &w->p;
    const int D = w->dim, W = D == 3 ? 3 : 1;
    memset(e, 0, DM_ENERGIES * sizeof *e);
    for (uint32_t k = 0; k < w->nbodies; k++) {
        double b[DM_BODY_ENERGIES];
        if (!dm_body_live(w, k))
            continue;
        dm_body_energies(w, k, b);
        for (int q = 0; q < DM_BODY_ENERGIES; q++)
            e[DM_E_BODY + q] += b[q];
    }
    for (uint32_t k = 0; k < w->nclumps; k++) {
        double kt, kr, pot;
        if (!dm_clump_live(w, k))
            continue;
        dm_clump_energies(w, k, &kt, &kr, &pot);
        e[DM_E_KT] += kt;
        e[DM_E_KR] += kr;
        e[DM_E_POT] += pot;
    }
    for (uint32_t i = 0; i < P->n; i++) {
        if (P->clump[i]) /* its clump's energies hold it */
            continue;
        for (int c = 0; c < D; c++) {
            e[0] += 0.5 * P->m[i] * P->v[D * i + c] * P->v[D * i + c];
            e[2] -= P->m[i] * w->g[c] * P->x[D * i + c];
        }
        e[1] += dm_particle_spin_energy(P, i, W);
    }
    demill_status s = DEMILL_OK;
    if (stored && !(s = prepare_query(w)))
        dm_contacts_visit(w, 0, add_stored, e);
    return s;
}

DEMILL_API demill_status demill_world_energy(demill_world *w, int32_t term, double *value)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!value)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "world_energy: value is NULL");
    if (term < DEMILL_ENERGY_KINETIC_TRANSLATIONAL || term > DEMILL_ENERGY_ELASTIC_ROLLING)
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "world_energy: %d is not an energy term",
                       (int)term);
    double e[DM_ENERGIES];
    if ((s = dm_energies(w, term == DEMILL_ENERGY_ELASTIC_NORMAL ||
                                term == DEMILL_ENERGY_ELASTIC_TANGENTIAL ||
                                term == DEMILL_ENERGY_ELASTIC_ROLLING ||
                                term == DEMILL_ENERGY_TOTAL,
                         e)))
        return s;
    const double *body = e + DM_E_BODY;
    const dm_tally *t = &w->tally;
    const double diss = dm_tally_dissipated(t);
    switch (term) {
    case DEMILL_ENERGY_KINETIC_TRANSLATIONAL: *value = e[DM_E_KT]; break;
    case DEMILL_ENERGY_KINETIC_ROTATIONAL: *value = e[DM_E_KR]; break;
    case DEMILL_ENERGY_POTENTIAL: *value = e[DM_E_POT]; break;
    case DEMILL_ENERGY_ELASTIC_NORMAL: *value = e[DM_E_NORMAL]; break;
    case DEMILL_ENERGY_ELASTIC_TANGENTIAL: *value = e[DM_E_TANGENTIAL]; break;
    case DEMILL_ENERGY_ELASTIC_ROLLING: *value = e[DM_E_ROLLING]; break;
    case DEMILL_ENERGY_WALL_WORK: *value = t->wall_work; break;
    case DEMILL_ENERGY_DISSIPATED_NORMAL: *value = t->diss_normal; break;
    case DEMILL_ENERGY_DISSIPATED_TANGENTIAL: *value = t->diss_tangential; break;
    case DEMILL_ENERGY_DISSIPATED_FRICTION: *value = t->diss_friction; break;
    case DEMILL_ENERGY_DISSIPATED_ROLLING: *value = t->diss_rolling; break;
    case DEMILL_ENERGY_DISSIPATED_PLASTIC: *value = t->diss_plastic; break;
    case DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS: *value = t->diss_rolling_viscous; break;
    case DEMILL_ENERGY_DISSIPATED_LOCAL: *value = t->diss_local; break;
    case DEMILL_ENERGY_COHESION: *value = t->work_cohesion; break;
    case DEMILL_ENERGY_DISSIPATED: *value = diss; break;
    case DEMILL_ENERGY_FLOW: *value = w->flows.energy; break;
    case DEMILL_ENERGY_TOTAL: {
        double sum = diss + t->work_cohesion - t->wall_work - w->flows.energy +
                     body[DM_BODY_KINETIC] + body[DM_BODY_ELASTIC] + body[DM_BODY_POTENTIAL] +
                     body[DM_BODY_DISSIPATED] - body[DM_BODY_WORK];
        for (int k = DM_E_KT; k < DM_E_BODY; k++)
            sum += e[k];
        *value = sum;
        break;
    }
    default: *value = body[term - DEMILL_ENERGY_BODY_KINETIC];
    }
    dm_clear_error(w);
    return DEMILL_OK;
}

/* ---- contacts ------------------------------------------------------------------ */

DEMILL_API int32_t demill_contact_field_size(int32_t field)
{
    switch (field) {
    case DEMILL_CONTACT_POINT:
    case DEMILL_CONTACT_NORMAL:
    case DEMILL_CONTACT_NORMAL_FORCE:
    case DEMILL_CONTACT_TANGENTIAL_FORCE:
    case DEMILL_CONTACT_ROLLING_TORQUE: return 3;
    case DEMILL_CONTACT_OVERLAP: return 1;
    default: return 0;
    }
}

typedef struct fill_ctx {
    const demill_world *w;
    size_t n;
    int32_t field;
    double *out;
    demill_id *a, *b;
} fill_ctx;

static void fill(void *ctx, const dm_contact_eval *c)
{
    fill_ctx *f = ctx;
    size_t k = f->n++;
    if (f->a)
        f->a[k] = dm_particle_id(f->w, c->i);
    if (f->b)
        f->b[k] = c->wall ? dm_wall_id(f->w, c->j) : dm_particle_id(f->w, c->j);
    if (!f->out)
        return;
    const double *src = NULL;
    switch (f->field) {
    case DEMILL_CONTACT_POINT: src = c->point; break;
    case DEMILL_CONTACT_NORMAL: src = c->normal; break;
    case DEMILL_CONTACT_NORMAL_FORCE: src = c->fn; break;
    case DEMILL_CONTACT_TANGENTIAL_FORCE: src = c->ft; break;
    case DEMILL_CONTACT_ROLLING_TORQUE: src = c->mr; break;
    default: f->out[k] = c->delta; return;
    }
    memcpy(f->out + 3 * k, src, 3 * sizeof *src);
}

/* Counts the contacts, then (if the caller's buffers hold them all) fills
 * them in a second walk. */
static demill_status read_contacts(demill_world *w, fill_ctx *f, size_t capacity, size_t *count)
{
    demill_status s = prepare_query(w);
    if (s)
        return s;
    fill_ctx counter = {.w = w};
    dm_contacts_visit(w, 0, fill, &counter);
    if (count)
        *count = counter.n;
    if (!f->out && !f->a && !f->b)
        return DEMILL_OK;
    if (capacity < counter.n)
        return dm_fail(w, DEMILL_ERR_BUFFER_TOO_SMALL, "capacity %zu, %zu contacts", capacity,
                       counter.n);
    dm_contacts_visit(w, f->out != NULL, fill, f);
    dm_clear_error(w);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_contacts_read(demill_world *w, int32_t field, double *out,
                                              size_t capacity, size_t *count)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!demill_contact_field_size(field))
        return dm_fail(w, DEMILL_ERR_UNKNOWN_KEY, "%d is not a contact field", (int)field);
    if (!out && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "contacts_read: out and count are both NULL");
    fill_ctx f = {.w = w, .field = field, .out = out};
    return read_contacts(w, &f, capacity, count);
}

DEMILL_API demill_status demill_contacts_read_ids(demill_world *w, demill_id *a, demill_id *b,
                                                  size_t capacity, size_t *count)
{
    demill_status s = dm_check_world(w);
    if (s)
        return s;
    if (!a && !b && !count)
        return dm_fail(w, DEMILL_ERR_NULL_POINTER, "contacts_read_ids: every pointer is NULL");
    fill_ctx f = {.w = w, .a = a, .b = b};
    return read_contacts(w, &f, capacity, count);
}
