/* forces.c: one force evaluation (gravity, every contact bucket through its
 * kernel) and the read-only walk over contacts that queries use. */
#include <string.h>

#include "kernels.h"

int dm_kernel_index(dm_laws l)
{
    return (((l.normal - 1) * 3 + l.damping) * 4 + l.tangential) * 2 + l.rolling;
}

dm_laws dm_kernel_laws(int kernel)
{
    dm_laws l;
    l.rolling = kernel % 2;
    l.tangential = kernel / 2 % 4;
    l.damping = kernel / 8 % 3;
    l.normal = kernel / 24 + 1;
    return l;
}

int dm_kernel_spring_size(int kernel, int dim)
{
    return dm_law_spring_size(dm_kernel_laws(kernel).tangential, dim);
}

int dm_kernel_hist_size(int kernel, int dim)
{
    dm_laws l = dm_kernel_laws(kernel);
    return dm_law_hist_size(l.normal, l.damping, l.tangential, dim);
}

/* Evaluates all forces and torques at the current state. dt_hist > 0 advances
 * the contact histories by that time (a real step); tally adds the step's
 * dissipation and wall work to the world's energy account. vp, wp: the
 * velocities dashpots and friction see; reach: how far past a sample its impulse
 * reaches, in steps (see dm_law). */
void dm_forces(demill_world *w, const double *vp, const double *wp, double dt_hist, double reach,
               int tally)
{
    const int D = w->dim, W = D == 3 ? 3 : 1;
    dm_particles *P = &w->p;
    for (uint32_t i = 0; i < P->n; i++) {
        for (int c = 0; c < D; c++)
            P->f[D * i + c] = P->m[i] * w->g[c];
        for (int c = 0; c < W; c++)
            P->t[W * i + c] = 0.0;
    }
    for (uint32_t k = 0; k < w->nwalls; k++) {
        memset(w->walls[k].force, 0, sizeof w->walls[k].force);
        memset(w->walls[k].torque, 0, sizeof w->walls[k].torque);
    }
    const dm_kernel_fn *pp = D == 3 ? dm_pp_kernels3 : dm_pp_kernels2;
    const dm_kernel_fn *pw = D == 3 ? dm_pw_kernels3 : dm_pw_kernels2;
    dm_tally t = {0};
    dm_kernel_args a = {.w = w, .vp = vp, .wp = wp, .dt_hist = dt_hist, .reach = reach,
                        .tally = tally, .t = &t};
    w->ncontacts = 0;
    for (int k = 0; k < DM_KERNELS; k++) {
        if (!w->pp.b[k].n)
            continue;
        a.b = &w->pp.b[k];
        pp[k](&a);
        w->ncontacts += a.contacts;
    }
    dm_wgeom_update(w);
    w->nwall_contacts = 0;
    for (int k = 0; k < DM_KERNELS; k++) {
        if (w->pw.b[k].n) {
            a.b = &w->pw.b[k];
            pw[k](&a);
            w->nwall_contacts += a.contacts;
        }
        a.geom_offset += w->pw.b[k].n;
    }
    if (tally)
        dm_tally_add(&w->tally, &t);
    w->forces_valid = true;
}

/* Fills a contact record from the kinematics and the law's output, as seen
 * from body a (forces on a). */
static void contact_record(int dim, dm_laws l, const dm_pairparam *pp, const dm_kin *q,
                           const double *xa, const double *hist, dm_contact_eval *e)
{
    double h[DM_MAX_HIST];
    dm_law_out o;
    dm_law(dim, l.normal, l.damping, l.tangential, l.rolling, pp, q->n, q->delta, q->vc, q->dc,
           q->wrel, q->rstar, q->mstar, 0.0, 0.0, hist, h, &o);
    memset(e->point, 0, sizeof e->point);
    memset(e->normal, 0, sizeof e->normal);
    memset(e->fn, 0, sizeof e->fn);
    memset(e->ft, 0, sizeof e->ft);
    memset(e->mr, 0, sizeof e->mr);
    for (int c = 0; c < dim; c++) {
        e->point[c] = xa[c] + q->ai * q->n[c];
        e->normal[c] = q->n[c];
        e->fn[c] = -o.fn * q->n[c];
        e->ft[c] = -o.ft[c];
    }
    if (dim == 3)
        memcpy(e->mr, o.mr, sizeof e->mr);
    else
        e->mr[2] = o.mr[0];
    e->delta = q->delta;
    dm_law_stored(dim, l.normal, l.tangential, pp, q->delta, q->rstar, hist, &e->e_normal,
                  &e->e_tangential);
}

/* Calls fn for every contact (overlap > 0) at the current state, without
 * changing the world's physical state. The pair table must be resolved and
 * the wall geometry current (dm_wgeom_update). */
void dm_contacts_visit(demill_world *w, dm_contact_visitor fn, void *ctx)
{
    const int D = w->dim;
    const dm_particles *P = &w->p;
    dm_contact_eval e;
    for (int k = 0; k < DM_KERNELS; k++) {
        const dm_bucket *b = &w->pp.b[k];
        dm_laws l = dm_kernel_laws(k);
        for (uint32_t p = 0; p < b->n; p++) {
            uint32_t i = b->i[p], j = b->j[p];
            double d[3], r2;
            if (!dm_pp_touch(D, P, i, j, d, &r2))
                continue;
            dm_kin q;
            dm_pp_kin(D, l.tangential != 0, l.rolling, P, P->v, P->w, i, j, d, r2, &q);
            const dm_pairparam *pp = &w->ptab[P->mat[i] * w->nmat_tab + P->mat[j]];
            contact_record(D, l, pp, &q, P->x + D * i, b->hist + (size_t)b->hs * p, &e);
            e.a = dm_particle_id(w, i);
            e.b = dm_particle_id(w, j);
            fn(ctx, &e);
        }
    }
    uint32_t g0 = 0;
    for (int k = 0; k < DM_KERNELS; k++) {
        const dm_bucket *b = &w->pw.b[k];
        dm_laws l = dm_kernel_laws(k);
        for (uint32_t p = 0; p < b->n; p++) {
            uint32_t i = b->i[p];
            const dm_wall *wall = &w->walls[b->j[p]];
            if (!(w->wg.delta[g0 + p] > 0.0))
                continue;
            dm_kin q;
            dm_pw_kin(D, l.tangential != 0, l.rolling, P, P->v, P->w, &w->wg, g0 + p, i, wall, &q);
            const dm_pairparam *pp = &w->ptab[P->mat[i] * w->nmat_tab + wall->material];
            contact_record(D, l, pp, &q, P->x + D * i, b->hist + (size_t)b->hs * p, &e);
            e.a = dm_particle_id(w, i);
            e.b = dm_wall_id(w, b->j[p]);
            fn(ctx, &e);
        }
        g0 += b->n;
    }
}
