/* clumps.c: the motion of clumps, rigid bodies of overlapping spheres (discs
 * in 2D) whose members are particles (docs/shapes.md, Clumps).
 *
 * The members are particles to the neighbour search and the contact
 * kernels. They carry their clump's mass and inverse mass (so that a
 * contact's reduced mass is the clump's, as LIGGGHTS's multisphere takes
 * the body's mass for its members' contacts) and the inverse of the mean of
 * its principal moments; the particle integrator moves them like any
 * particle, and then the clump's step puts every member back where its
 * clump is, with its clump's velocities.
 *
 * Translation uses the world's integrator. Rotation in 3D is the symplectic
 * splitting of Dullweber, Leimkuhler and McLachlan (1997), "Symplectic
 * splitting methods for rigid body molecular dynamics", J. Chem. Phys. 107,
 * 5840 (the NO_SQUISH scheme of Miller et al. (2002), "Symplectic
 * quaternion scheme for biophysical molecular dynamics", J. Chem. Phys. 116,
 * 8649, is the same splitting in quaternions): a half kick of the world
 * angular momentum L by the torque, the free rotation over the step split
 * into exact rotations about the body axes, x and y by half the step, z by
 * the whole, y and x by half again, then the other half kick. Each free
 * rotation keeps L in the world frame exactly, so L is stored in the world
 * frame and only the orientation q moves: a free body keeps its L to the
 * last bit, and its energy, a symplectic map's, within O(Δt²) for all time.
 * In 2D the clump turns about z: L = I_z ω, θ += Δt ω. */
#include <math.h>
#include <string.h>

#include "physics/clumps/clumps.h"
#include "physics/state/orient.h"

void dm_quat_matrix(const double q[4], double R[9])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1.0 - 2.0 * (y * y + z * z);
    R[1] = 2.0 * (x * y - w * z);
    R[2] = 2.0 * (x * z + w * y);
    R[3] = 2.0 * (x * y + w * z);
    R[4] = 1.0 - 2.0 * (x * x + z * z);
    R[5] = 2.0 * (y * z - w * x);
    R[6] = 2.0 * (x * z - w * y);
    R[7] = 2.0 * (y * z + w * x);
    R[8] = 1.0 - 2.0 * (x * x + y * y);
}

/* A member's offset from its clump's centre of mass in the world frame,
 * R b, from its offset b in the principal frame. */
static void lever(const double R[9], const double *b, double r[3])
{
    for (int a = 0; a < 3; a++)
        r[a] = R[3 * a] * b[0] + R[3 * a + 1] * b[1] + R[3 * a + 2] * b[2];
}

static const dm_template *template_of(const demill_world *w, const dm_clump *c)
{
    return &w->templates[c->tmpl];
}

void dm_clump_omega(const demill_world *w, const dm_clump *c, const double L[3], double om[3])
{
    const dm_template *t = template_of(w, c);
    if (w->dim == 2) {
        om[0] = om[1] = 0.0;
        om[2] = L[2] / t->inertia[2];
        return;
    }
    double R[9], pi[3];
    dm_quat_matrix(c->q, R);
    for (int a = 0; a < 3; a++) /* the body frame's: Rᵀ L / I */
        pi[a] = (R[a] * L[0] + R[3 + a] * L[1] + R[6 + a] * L[2]) / t->inertia[a];
    for (int a = 0; a < 3; a++)
        om[a] = R[3 * a] * pi[0] + R[3 * a + 1] * pi[1] + R[3 * a + 2] * pi[2];
}

double dm_clump_place(demill_world *w, uint32_t k)
{
    const int D = w->dim, W = dm_wdim(w);
    dm_particles *P = &w->p;
    const dm_clump *c = &w->clumps[k];
    const dm_template *t = template_of(w, c);
    double R[9];
    dm_quat_matrix(c->q, R);
    double worst = 0.0;
    for (uint32_t m = 0; m < t->n; m++) {
        const uint32_t i = w->ph.slot[w->cmem[c->first + m]];
        const double *b = w->tmem + DM_TMEM * (size_t)(t->first + m);
        double r[3], d2 = 0.0;
        lever(R, b, r);
        const double wr[3] = {c->om[1] * r[2] - c->om[2] * r[1],
                              c->om[2] * r[0] - c->om[0] * r[2],
                              c->om[0] * r[1] - c->om[1] * r[0]};
        const double pr[3] = {c->wp[1] * r[2] - c->wp[2] * r[1],
                              c->wp[2] * r[0] - c->wp[0] * r[2],
                              c->wp[0] * r[1] - c->wp[1] * r[0]};
        for (int a = 0; a < D; a++) {
            P->x[D * i + a] = c->x[a] + r[a];
            P->v[D * i + a] = c->v[a] + wr[a];
            P->vp[D * i + a] = c->vp[a] + pr[a];
            const double d = P->x[D * i + a] - P->x0[D * i + a];
            d2 += d * d;
        }
        for (int a = 0; a < W; a++) {
            P->w[W * i + a] = c->om[3 - W + a];
            P->wp[W * i + a] = c->wp[3 - W + a];
        }
        if (D == 2)
            P->theta[i] = c->theta;
        else /* a member's body frame is its clump's */
            dm_quat_put(P->q, i, c->q);
        worst = fmax(worst, d2);
    }
    return worst;
}

void dm_clump_load(const demill_world *w, uint32_t k, double F[3], double T[3])
{
    const int D = w->dim, W = dm_wdim(w);
    const dm_particles *P = &w->p;
    const dm_clump *c = &w->clumps[k];
    const dm_template *t = template_of(w, c);
    /* each member's force holds gravity on its mass, the clump's (see the
     * top): the clump's gravity is counted once, and no member's gravity
     * turns it (gravity acts at the centre of mass) */
    double mg[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < D; a++)
        mg[a] = t->mass * w->g[a];
    for (int a = 0; a < 3; a++)
        F[a] = T[a] = 0.0;
    /* the lever arms R b_i of the clump's pose, not the members' positions,
     * which the particles' drift has moved on when the step starts */
    double R[9];
    dm_quat_matrix(c->q, R);
    for (uint32_t m = 0; m < t->n; m++) {
        const uint32_t i = w->ph.slot[w->cmem[c->first + m]];
        const double *b = w->tmem + DM_TMEM * (size_t)(t->first + m);
        double r[3], f[3] = {0.0, 0.0, 0.0};
        lever(R, b, r);
        for (int a = 0; a < D; a++) {
            F[a] += P->f[D * i + a];
            f[a] = P->f[D * i + a] - mg[a];
        }
        T[2] += r[0] * f[1] - r[1] * f[0] + P->t[W * i + W - 1];
        if (W == 3) {
            T[0] += r[1] * f[2] - r[2] * f[1] + P->t[W * i];
            T[1] += r[2] * f[0] - r[0] * f[2] + P->t[W * i + 1];
        }
    }
    for (int a = 0; a < D; a++)
        F[a] -= (double)(t->n - 1) * mg[a];
}

void dm_clump_energies(const demill_world *w, uint32_t k, double *kt, double *kr, double *pot)
{
    const dm_clump *c = &w->clumps[k];
    const double M = template_of(w, c)->mass;
    *kt = *kr = *pot = 0.0;
    for (int a = 0; a < w->dim; a++) {
        *kt += 0.5 * M * c->v[a] * c->v[a];
        *pot -= M * w->g[a] * c->x[a];
    }
    for (int a = 0; a < 3; a++)
        *kr += 0.5 * c->om[a] * c->L[a];
}

/* sin and cos of a (half a turn's angle): from the series of orient.h while
 * a² <= DM_QUAT_SERIES_A2 (every turn of a stable step), from libm beyond. */
static void half_angle(double a, double *s, double *c)
{
    const double a2 = a * a;
    if (a2 <= DM_QUAT_SERIES_A2) {
        double sa;
        dm_quat_series(a2, c, &sa);
        *s = sa * a;
    } else {
        *s = sin(a);
        *c = cos(a);
    }
}

/* q ← q ⊗ (co, s e_a), co = cos φ/2 and s = sin φ/2: a turn by φ about body
 * axis a. */
static void turn(double q[4], int a, double s, double co)
{
    double p[3] = {0.0, 0.0, 0.0};
    p[a] = s;
    const double w = q[0], v[3] = {q[1], q[2], q[3]};
    q[0] = w * co - (v[0] * p[0] + v[1] * p[1] + v[2] * p[2]);
    q[1] = w * p[0] + co * v[0] + v[1] * p[2] - v[2] * p[1];
    q[2] = w * p[1] + co * v[1] + v[2] * p[0] - v[0] * p[2];
    q[3] = w * p[2] + co * v[2] + v[0] * p[1] - v[1] * p[0];
}

/* The free rotation of a 3D clump over dt at constant world angular
 * momentum (the splitting of the top): the body-frame angular momentum
 * π = Rᵀ L turns by -φ about axis a while q turns by φ = τ π_a / I_a, which
 * keeps R π = L. */
static void free_rotation(const dm_template *t, dm_clump *c, double dt)
{
    static const int axis[5] = {0, 1, 2, 1, 0};
    static const double part[5] = {0.5, 0.5, 1.0, 0.5, 0.5};
    double R[9], pi[3];
    dm_quat_matrix(c->q, R);
    for (int a = 0; a < 3; a++)
        pi[a] = R[a] * c->L[0] + R[3 + a] * c->L[1] + R[6 + a] * c->L[2];
    for (int s = 0; s < 5; s++) {
        const int a = axis[s], b = (a + 1) % 3, e = (a + 2) % 3;
        const double phi = part[s] * dt * pi[a] / t->inertia[a];
        double sh, ch; /* of φ/2; those of φ by the double angle */
        half_angle(0.5 * phi, &sh, &ch);
        turn(c->q, a, sh, ch);
        const double co = 1.0 - 2.0 * sh * sh, si = 2.0 * sh * ch, pb = pi[b], pe = pi[e];
        pi[b] = co * pb + si * pe;
        pi[e] = -si * pb + co * pe;
    }
    const double n = sqrt(c->q[0] * c->q[0] + c->q[1] * c->q[1] + c->q[2] * c->q[2] +
                          c->q[3] * c->q[3]);
    for (int a = 0; a < 4; a++)
        c->q[a] /= n;
}

/* Turns clump c by dt at its angular momentum: 3D the free rotation, 2D
 * θ += dt L/I_z. */
static void rotate(const demill_world *w, dm_clump *c, double dt)
{
    const dm_template *t = template_of(w, c);
    if (w->dim == 3) {
        free_rotation(t, c, dt);
        return;
    }
    c->theta += dt * c->L[2] / t->inertia[2];
    c->q[0] = cos(0.5 * c->theta);
    c->q[1] = c->q[2] = 0.0;
    c->q[3] = sin(0.5 * c->theta);
}

double dm_clumps_drift(demill_world *w, double dt, int kick, int verlet)
{
    const double h = verlet ? 0.5 * dt : dt;
    double worst = 0.0;
    for (uint32_t k = 0; k < w->nclumps; k++) {
        if (!dm_clump_live(w, k))
            continue;
        dm_clump *c = &w->clumps[k];
        const double im = template_of(w, c)->im;
        double F[3], T[3], Lp[3];
        dm_clump_load(w, k, F, T);
        for (int a = 0; a < 3; a++) { /* the particles' arithmetic (integrate.c) */
            if (verlet) {
                const double acc = F[a] * im;
                if (kick)
                    c->v[a] += h * acc;
                c->vp[a] = c->v[a] + dt * acc;
                c->v[a] += h * acc;
            } else {
                c->v[a] += dt * F[a] * im;
            }
            c->x[a] += dt * c->v[a];
            if (kick)
                c->L[a] += h * T[a];
            c->L[a] += h * T[a];
        }
        rotate(w, c, dt);
        dm_clump_omega(w, c, c->L, c->om);
        if (verlet) {
            for (int a = 0; a < 3; a++)
                Lp[a] = c->L[a] + h * T[a];
            dm_clump_omega(w, c, Lp, c->wp);
        } else { /* symplectic Euler's dashpots see the new velocities */
            memcpy(c->vp, c->v, sizeof c->vp);
            memcpy(c->wp, c->om, sizeof c->wp);
        }
        worst = fmax(worst, dm_clump_place(w, k));
    }
    return worst;
}

void dm_clumps_kick(demill_world *w, double h)
{
    for (uint32_t k = 0; k < w->nclumps; k++) {
        if (!dm_clump_live(w, k))
            continue;
        dm_clump *c = &w->clumps[k];
        const double im = template_of(w, c)->im;
        double F[3], T[3];
        dm_clump_load(w, k, F, T);
        for (int a = 0; a < 3; a++) {
            c->v[a] += h * (F[a] * im);
            c->L[a] += h * T[a];
        }
        dm_clump_omega(w, c, c->L, c->om);
        memcpy(c->vp, c->v, sizeof c->vp);
        memcpy(c->wp, c->om, sizeof c->wp);
        dm_clump_place(w, k);
    }
}
