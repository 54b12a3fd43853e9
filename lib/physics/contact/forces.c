/* forces.c: one force evaluation (gravity, every contact bucket through its
 * kernel) and the read-only walk over contacts that queries use. */
#include <math.h>
#include <string.h>

#include "base/threads.h"
#include "physics/contact/kernels.h"

/* Kernel indices (DM_FAST_KERNELS, DM_KERNELS): the fast kernels' first,
 * with the normal law outermost, then damping, tangential and rolling; then
 * the extended kernels', every law in the same order and cohesion last. */
int dm_kernel_index(dm_laws l, bool generic)
{
    if (!generic && !dm_law_extended(l.normal, l.rolling, l.cohesion))
        return (((l.normal - 1) * DM_DAMPING_LAWS + l.damping) * DM_TANGENTIAL_LAWS +
                l.tangential) * 2 + l.rolling;
    return DM_FAST_KERNELS +
           ((((l.normal - 1) * DM_DAMPING_LAWS + l.damping) * DM_TANGENTIAL_LAWS + l.tangential) *
                DM_ROLLING_LAWS + l.rolling) * DM_COHESION_LAWS + l.cohesion;
}

dm_laws dm_kernel_laws(int kernel)
{
    dm_laws l;
    if (kernel < DM_FAST_KERNELS) {
        l.rolling = kernel % 2;
        l.tangential = kernel / 2 % DM_TANGENTIAL_LAWS;
        l.damping = kernel / (2 * DM_TANGENTIAL_LAWS) % DM_DAMPING_LAWS;
        l.normal = kernel / (2 * DM_TANGENTIAL_LAWS * DM_DAMPING_LAWS) + 1;
        l.cohesion = DEMILL_COHESION_NONE;
        return l;
    }
    int k = kernel - DM_FAST_KERNELS;
    l.cohesion = k % DM_COHESION_LAWS;
    k /= DM_COHESION_LAWS;
    l.rolling = k % DM_ROLLING_LAWS;
    k /= DM_ROLLING_LAWS;
    l.tangential = k % DM_TANGENTIAL_LAWS;
    k /= DM_TANGENTIAL_LAWS;
    l.damping = k % DM_DAMPING_LAWS;
    l.normal = k / DM_DAMPING_LAWS + 1;
    return l;
}

double dm_kernel_flip(int kernel, int dim, int slot)
{
    return dm_law_flip(dm_kernel_laws(kernel), dim, slot);
}

int dm_kernel_hist_size(int kernel, int dim)
{
    dm_laws l = dm_kernel_laws(kernel);
    return dm_law_hist_size(l.normal, l.damping, l.tangential, l.rolling, dim);
}

/* The weights m g and zero torques of particles p0 .. p1-1, where their
 * sums start. */
DM_INLINE void init_forces(const int D, demill_world *w, uint32_t p0, uint32_t p1)
{
    const int W = D == 3 ? 3 : 1;
    dm_particles *P = &w->p;
    const double *restrict m = P->m;
    double *restrict f = P->f, *restrict tq = P->t;
    const double g[3] = {w->g[0], w->g[1], w->g[2]};
    for (size_t i = p0; i < p1; i++) { /* size_t: a uint32_t D i may wrap, which stops GCC */
        for (int c = 0; c < D; c++)
            f[D * i + c] = m[i] * g[c];
        for (int c = 0; c < W; c++)
            tq[W * i + c] = 0.0;
    }
}

/* The sums of the particles of range p0 .. p1-1 that the chunks did not
 * take as they went, those with a pair in a chunk of an earlier range
 * (lo[p] < p0; the chunks have set their weights): the results of their
 * pairs in pair-id order, which is the order of a walk through the chunks'
 * lists of pairs with results. The walk starts at the first pair that can
 * reach p0 (j - i is at most the bucket's span). */
DM_INLINE void sum_forces(const int D, demill_world *w, uint32_t p0, uint32_t p1)
{
    const int W = D == 3 ? 3 : 1, S = D + 2 * W;
    dm_particles *P = &w->p;
    const dm_results *q = &w->res;
    const double *restrict out = q->out;
    const uint32_t *restrict lo = q->lo;
    double *restrict f = P->f, *restrict tq = P->t;
    for (int side = 0; side < 2; side++)
        for (int k = 0; k < w->nkern; k++) {
            const dm_bucket *b = side ? &w->pw.b[k] : &w->pp.b[k];
            const uint32_t *restrict bi = b->i, *restrict bj = b->j;
            const uint32_t lo_i = side || p0 < b->span ? (side ? p0 : 0) : p0 - b->span;
            uint32_t first = 0, last = b->n; /* the first pair with i >= lo_i */
            while (first < last) {
                const uint32_t mid = first + (last - first) / 2;
                if (bi[mid] < lo_i)
                    first = mid + 1;
                else
                    last = mid;
            }
            /* the chunks from there, through their lists of pairs with results */
            for (uint32_t k0 = first / DM_CHUNK * DM_CHUNK; k0 < b->n && bi[k0] < p1;
                 k0 += DM_CHUNK) {
                const uint32_t *list = q->list + b->base + k0;
                const uint32_t listed = q->chunk_listed[b->chunk0 + k0 / DM_CHUNK];
                for (uint32_t e = 0; e < listed; e++) {
                    const uint32_t p = list[e], i = bi[p], j = bj[p];
                    const double *o = out + (size_t)S * (b->base + p);
                    if (i >= p0 && i < p1 && lo[i] < p0)
                        dm_result_add(D, 1, 0, f, tq, i, j, o);
                    if (!side && j >= p0 && j < p1 && lo[j] < p0)
                        dm_result_add(D, 0, 1, f, tq, i, j, o);
                }
            }
        }
}

static void sum_forces_range(demill_world *w, void *arg, int t, uint32_t p0, uint32_t p1)
{
    (void)arg, (void)t;
    dm_forces_finish(w, p0, p1);
}

void dm_forces_finish(demill_world *w, uint32_t p0, uint32_t p1)
{
    if (w->dim == 3)
        sum_forces(3, w, p0, p1);
    else
        sum_forces(2, w, p0, p1);
}

/* What the walks over the walls' contacts below need. */
typedef struct wall_walk {
    int tally;
    double dt;
    dm_tally *t;
    const double *vp, *wp; /* the loads: the velocities friction saw */
} wall_walk;

typedef void (*wall_visit)(const int D, demill_world *w, const wall_walk *a,
                           const dm_bucket *b, uint32_t p, uint32_t pid, uint32_t gk);

/* Calls fn for every particle-wall pair with a result at the last force
 * evaluation (p: its index in bucket b, pid: its pair id, gk: its geometry's
 * index in w->wg), in pair-id order, which does not depend on the threads. */
DM_INLINE void walk_walls(const int D, demill_world *w, const wall_walk *a, wall_visit fn)
{
    const dm_results *q = &w->res;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pw.b[k];
        for (uint32_t k0 = 0; k0 < b->n; k0 += DM_CHUNK) {
            const uint32_t *list = q->list + b->base + k0;
            const uint32_t listed = q->chunk_listed[b->chunk0 + k0 / DM_CHUNK];
            for (uint32_t e = 0; e < listed; e++) {
                const uint32_t p = list[e], pid = b->base + p;
                fn(D, w, a, b, p, pid, pid - q->npp);
            }
        }
    }
}

/* One contact's share of its wall's force and torque (about its centre);
 * with tally, of its dissipation and the work it delivers over dt: the
 * force on the particle times the wall's velocity at the contact point,
 * its surface velocity included (sum_walls() takes a body's own motion out
 * of its walls' work). */
DM_INLINE void wall_sum(const int D, demill_world *w, const wall_walk *a, const dm_bucket *b,
                        uint32_t p, uint32_t pid, uint32_t gk)
{
    const int W = D == 3 ? 3 : 1, S = D + 2 * W;
    const dm_wgeom *g = &w->wg;
    dm_wall *wall = &w->walls[b->j[p]];
    const double *fw = w->res.out + (size_t)S * pid, *tw = fw + D + W;
    double arm[3] = {0.0, 0.0, 0.0}, f3[3] = {0.0, 0.0, 0.0}, work = 0.0;
    for (int c = 0; c < D; c++) {
        f3[c] = fw[c];
        wall->force[c] += fw[c];
        arm[c] = g->cp[D * gk + c] - wall->c[c];
        work -= fw[c] * g->vw[D * gk + c];
    }
    wall->torque[0] += arm[1] * f3[2] - arm[2] * f3[1];
    wall->torque[1] += arm[2] * f3[0] - arm[0] * f3[2];
    wall->torque[2] += arm[0] * f3[1] - arm[1] * f3[0];
    for (int c = 0; c < W; c++) {
        const int z = D == 3 ? c : 2;
        wall->torque[z] += tw[c];
        work -= tw[c] * wall->omega[z];
    }
    if (a->tally) {
        wall->dissipated += g->lost[gk];
        a->t->wall_work += work * a->dt;
    }
}

/* The work of the bodies' motion through their walls over dt, -F·v dt
 * summed over their walls (F the wall's force, v its body's velocity). */
static double bodies_wall_work(const demill_world *w, double dt)
{
    double work = 0.0;
    for (uint32_t k = 0; k < w->nwalls; k++) {
        const dm_wall *wall = &w->walls[k];
        if (wall->kind && wall->body)
            for (int c = 0; c < 3; c++)
                work -= wall->force[c] * wall->vel[c] * dt;
    }
    return work;
}

/* The walls' forces and torques from their contacts' results, in pair-id
 * order; with tally, their dissipation and the work they deliver over dt.
 * A body's walls move with the body's velocity (and do not turn): the work
 * of that motion moves the body's own energy, which the account holds
 * (bodies.c), so only the rest, their surface velocity's, comes from
 * outside: the motion's share, Σ f·v dt over the wall's contacts (f the
 * force on the particle), -F·v dt (bodies_wall_work()), is taken out. */
DM_INLINE void sum_walls(const int D, demill_world *w, int tally, double dt, dm_tally *t)
{
    for (uint32_t k = 0; k < w->nwalls; k++) {
        memset(w->walls[k].force, 0, sizeof w->walls[k].force);
        memset(w->walls[k].torque, 0, sizeof w->walls[k].torque);
    }
    const wall_walk a = {.tally = tally, .dt = dt, .t = t};
    walk_walls(D, w, &a, wall_sum);
    if (tally && w->nbodies)
        t->wall_work -= bodies_wall_work(w, dt);
}

/* One contact's share of the loads of the element it touches, if its wall
 * (a cap's: the wall it closes) records them: its normal force F·n (F the
 * force on the wall, n the normal into it) now, F·n dt, and the power of its
 * tangential force F_t = F − (F·n) n against the slip velocity, the velocity
 * of the wall's surface relative to the particle's surface at the contact
 * point (the wall's rigid and surface velocity, the particle's velocity and
 * spin: what friction saw), |F_t · v| dt. */
DM_INLINE void wall_load(const int D, demill_world *w, const wall_walk *a, const dm_bucket *b,
                         uint32_t p, uint32_t pid, uint32_t gk)
{
    const int S = D + 2 * (D == 3 ? 3 : 1);
    const dm_wall *wall = &w->walls[b->j[p]];
    const dm_wall *owner = wall->parent ? &w->walls[wall->parent - 1] : wall;
    if (!owner->loads)
        return;
    dm_loads *l = owner->loads;
    double *v = l->v + DM_LOADS * (size_t)(owner->mesh ? b->t[p] : 0);
    const double *f = w->res.out + (size_t)S * pid, *n = w->wg.nrm + D * gk;
    dm_kin q;
    dm_pw_kin(D, 1, 0, &w->p, a->vp, a->wp, &w->wg, gk, b->i[p], wall, &q);
    double fn = 0.0, power = 0.0;
    for (int c = 0; c < D; c++)
        fn += f[c] * n[c];
    for (int c = 0; c < D; c++)
        power += (f[c] - fn * n[c]) * q.vc[c];
    if (v[3] != l->steps) { /* the element's first contact of the step */
        v[0] = 0.0;
        v[3] = l->steps;
    }
    v[0] += fn;
    v[1] += fn * a->dt;
    v[2] += fabs(power) * a->dt;
}

void dm_wall_loads_record(demill_world *w, const double *vp, const double *wp, double dt)
{
    int any = 0;
    for (uint32_t k = 0; k < w->nwalls; k++) { /* one test per wall */
        dm_loads *l = w->walls[k].loads;
        if (!l)
            continue;
        any = 1;
        l->interval += dt;
        l->steps += 1.0;
    }
    if (!any)
        return;
    const wall_walk a = {.dt = dt, .vp = vp, .wp = wp};
    if (w->dim == 3)
        walk_walls(3, w, &a, wall_load);
    else
        walk_walls(2, w, &a, wall_load);
}

typedef struct chunk_args {
    const double *vp, *wp;
    double dt_hist, reach;
    int tally, preset, one; /* one: the only range */
} chunk_args;

/* The chunks whose first pair belongs to a particle of [begin, end), after
 * the weights of the range's particles (unless preset). They add their
 * results to the sums of the range's particles all of whose pairs are in
 * the range's chunks as they go, in pair-id order (on one range, every
 * particle's): a chunk's all of them (direct) when it holds no pair of
 * another particle (dm_direct()). SINGLE: with the single-precision kernels
 * (a constant, so that the choice costs the loop nothing). */
static inline void run_chunks(const int D, const int SINGLE, demill_world *w,
                              const chunk_args *ca, uint32_t begin, uint32_t end)
{
    dm_results *q = &w->res;
    if (!ca->preset)
        init_forces(D, w, begin, end);
    for (uint32_t c = 0; c < q->nchunks; c++) {
        const dm_chunkref r = q->chunks[c];
        if (r.i0 < begin || r.i0 >= end)
            continue;
        dm_bucket *b = r.walls ? &w->pw.b[r.kernel] : &w->pp.b[r.kernel];
        dm_kernel_args a = {.w = w, .b = b, .k0 = r.k0, .geom_offset = b->base - q->npp,
                            .vp = ca->vp, .wp = ca->wp, .dt_hist = ca->dt_hist,
                            .reach = ca->reach, .tally = ca->tally,
                            .direct = ca->one || (r.lo >= begin && r.hi < end), .lo = q->lo,
                            .begin = begin, .end = end};
        dm_kernel(D, r.walls, r.kernel, SINGLE)(&a);
        q->chunk_tally[c] = a.t;
        q->chunk_contacts[c] = a.contacts;
        q->chunk_listed[c] = a.listed;
    }
}

/* The geometry of a range's mesh candidates, before any chunk runs: a
 * contact that moves on to another element of a mesh carries its history
 * there, and the two may lie in chunks that run on different threads. */
static void mesh_range(demill_world *w, void *a, int t, uint32_t begin, uint32_t end)
{
    (void)t;
    const chunk_args *ca = a;
    dm_wgeom_meshes(w, begin, end, ca->dt_hist > 0.0);
}

#define RUN_CHUNKS(D, SINGLE, NAME)                                                               \
    static void NAME(demill_world *w, void *a, int t, uint32_t begin, uint32_t end)               \
    {                                                                                             \
        (void)t;                                                                                  \
        run_chunks(D, SINGLE, w, a, begin, end);                                                  \
    }
RUN_CHUNKS(2, 0, run_chunks2)
RUN_CHUNKS(3, 0, run_chunks3)
RUN_CHUNKS(2, 1, run_chunks2_single)
RUN_CHUNKS(3, 1, run_chunks3_single)

/* Evaluates all forces and torques at the current state (options:
 * DM_FORCES_*, contact.h). dt_hist > 0 advances
 * the contact histories by that time (a real step); tally adds the step's
 * dissipation and wall work to the world's energy account. vp, wp: the
 * velocities dashpots and friction see; reach: how far past a sample its impulse
 * reaches, in steps (see dm_law). The chunks of pairs, then the sums they
 * leave (unless deferred), run on w->base.threads threads; every sum is taken
 * in an order that does not depend on them. */
void dm_forces(demill_world *w, const double *vp, const double *wp, double dt_hist, double reach,
               int tally, int options)
{
    const int D = w->dim;
    dm_results *q = &w->res;
    if (!q->valid)
        dm_results_layout(w);
    const uint32_t n = w->p.n;
    /* the chunks add their results to the sums of most particles while they
     * are in cache; the ranges sum the others' afterwards */
    const int ranges = dm_ranges(w, n);
    chunk_args ca = {.vp = vp, .wp = wp, .dt_hist = dt_hist, .reach = reach, .tally = tally,
                     .preset = options & DM_FORCES_PRESET, .one = ranges == 1};
    if (ranges > 1 && !q->reach_valid)
        dm_results_reach(w);
    if (dm_walls_have_mesh(w))
        dm_parallel(w, n, mesh_range, &ca);
    if (w->single)
        dm_parallel(w, n, D == 3 ? run_chunks3_single : run_chunks2_single, &ca);
    else
        dm_parallel(w, n, D == 3 ? run_chunks3 : run_chunks2, &ca);
    const uint32_t nchunks = q->nchunks;
    dm_tally t = {0};
    w->ncontacts = w->nwall_contacts = 0;
    for (uint32_t c = 0; c < nchunks; c++) {
        if (q->chunks[c].walls)
            w->nwall_contacts += q->chunk_contacts[c];
        else
            w->ncontacts += q->chunk_contacts[c];
        if (tally)
            dm_tally_add(&t, &q->chunk_tally[c]);
    }
    q->pending = 0;
    if (ranges > 1 && (options & DM_FORCES_DEFER))
        q->pending = ranges;
    else if (ranges > 1)
        dm_parallel(w, n, sum_forces_range, NULL);
    if (D == 3)
        sum_walls(3, w, tally, dt_hist, &t);
    else
        sum_walls(2, w, tally, dt_hist, &t);
    if (tally)
        dm_tally_add(&w->tally, &t);
    w->forces_valid = !q->pending;
}

/* Fills a contact record from the kinematics and the law's output, as seen
 * from body a (forces on a); without forces, only the overlap and the
 * stored energies. */
static void contact_record(int dim, dm_laws l, const dm_pairparam *pp, const dm_kin *q,
                           const double *xa, const double *hist, int forces, dm_contact_eval *e)
{
    e->delta = q->delta;
    dm_law_stored(dim, l, pp, q->delta, q->rstar, hist, &e->e_normal, &e->e_tangential,
                  &e->e_rolling);
    if (!forces)
        return;
    double h[DM_MAX_HIST];
    dm_law_out o;
    dm_law(dim, l.normal, l.damping, l.tangential, l.rolling, l.cohesion, pp, q->n, q->delta,
           q->vc, q->dc, q->wrel, q->wd, q->ir, q->rstar, q->mstar, 0.0, 0.0, 0, hist, h, &o);
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
}

/* Calls fn for every contact (overlap > 0) at the current state, without
 * changing the world's physical state; forces: with the contact's forces,
 * point and normal (otherwise only its bodies, overlap and stored energies
 * are given). The pair table must be resolved and the wall geometry current
 * (dm_wgeom_update). */
void dm_contacts_visit(demill_world *w, int forces, dm_contact_visitor fn, void *ctx)
{
    const int D = w->dim;
    const dm_particles *P = &w->p;
    dm_contact_eval e;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pp.b[k];
        dm_laws l = dm_kernel_laws(k);
        for (uint32_t p = 0; p < b->n; p++) {
            uint32_t i = b->i[p], j = b->j[p];
            double d[3], r2;
            if (!dm_pp_touch(D, P, i, j, d, &r2))
                continue;
            dm_kin q = {.delta = P->r[i] + P->r[j] - sqrt(r2),
                        .rstar = P->r[i] * P->r[j] / (P->r[i] + P->r[j])};
            if (forces)
                dm_pp_kin(D, l.tangential != 0, l.rolling, P, P->v, P->w, i, j, d, r2, &q);
            const dm_pairparam *pp = &w->ptab[P->mat[i] * w->nmat_tab + P->mat[j]];
            contact_record(D, l, pp, &q, P->x + D * i, b->hist + (size_t)b->hs * p, forces, &e);
            e.i = i;
            e.j = j;
            e.wall = 0;
            fn(ctx, &e);
        }
    }
    uint32_t g0 = 0;
    for (int k = 0; k < w->nkern; k++) {
        const dm_bucket *b = &w->pw.b[k];
        dm_laws l = dm_kernel_laws(k);
        for (uint32_t p = 0; p < b->n; p++) {
            uint32_t i = b->i[p];
            const dm_wall *wall = &w->walls[b->j[p]];
            if (!(w->wg.delta[g0 + p] > 0.0))
                continue;
            dm_kin q = {.delta = w->wg.delta[g0 + p], .rstar = P->r[i]};
            if (forces)
                dm_pw_kin(D, l.tangential != 0, l.rolling, P, P->v, P->w, &w->wg, g0 + p, i, wall,
                          &q);
            const dm_pairparam *pp = &w->ptab[P->mat[i] * w->nmat_tab + wall->material];
            contact_record(D, l, pp, &q, P->x + D * i, b->hist + (size_t)b->hs * p, forces, &e);
            e.i = i;
            e.j = b->j[p];
            e.wall = 1;
            fn(ctx, &e);
        }
        g0 += b->n;
    }
}
