/* directions.c: two-body direction tests worked out by hand (as Katnov 2020,
 * §2.10, checked his model; docs/physics.md lists the reference).
 *
 * What this suite proves: for two-body situations whose answer can be worked
 * out by hand (docs/physics.md §2-7), the library gives forces, torques and spins
 * of the right sign AND the right magnitude, in 2D and in 3D: head-on
 * repulsion along the line of centres; the normal dashpot adding to or
 * subtracting from the repulsion, with and without the clamp F_n >= 0;
 * friction between a spinning and a resting sphere (gear-like counter-spin,
 * the spinning one slows); sliding versus rolling contact of two spinning
 * spheres; sliding on, spinning on and rolling on a plane wall, up to the
 * final rolling state given by angular momentum about the contact point;
 * rolling resistance on a floor and between two balls; walls that translate
 * along their plane and rotate about a centre (including the torque the
 * particle exerts back on the wall); unequal radii (torques follow the true
 * lever arms R_i - δ/2, not R*; Newton's third law); contacts along oblique
 * normals; spins about x, y and z in 3D; the spring-slider's first step; and
 * a particle settling on a floor under gravity. Every test also reads its
 * contacts through demill_contacts_read() and checks that they add up to the
 * per-particle totals (a second, independent view of the same forces).
 *
 * Conventions (docs/physics.md notation, demill/query.h): n points from body a to
 * body b; forces in the contact view are those b exerts on a. Relative
 * velocity at the contact point v_c = (v_b + ω_b × r_b) - (v_a + ω_a × r_a)
 * with lever arms r_a = (R_a - δ/2) n, r_b = -(R_b - δ/2) n. Friction on b is
 * -F v_t/|v_t|, on a the opposite. Torque on a body = lever arm × force.
 *
 * Common scene unless a test says otherwise: spheres of radius R = 0.01 m and
 * density ρ = 2500 kg/m³, so m = 4/3 π R³ ρ = 1.0471976e-2 kg and
 * I = 2/5 m R² = 4.1887902e-7 kg m² (also in 2D, where particles are spheres
 * held in the plane); default material stiffness 1e5 N/m, so the pair's
 * series stiffness is k = 1e5·1e5/2e5 = 5e4 N/m (walls are made of the same
 * material, so particle-wall contacts have the same k); overlap δ = 1e-4 m,
 * so F_n = k δ = 5 N; friction μ = 0.5 (the default of both materials), so
 * μ F_n = 2.5 N; lever arm a = R - δ/2 = 9.95e-3 m. No gravity unless stated.
 * The Coulomb law's regularisation is γ = √(m* k) (factor 1, header
 * material.h): 16.18 N s/m between two equal spheres (m* = m/2), 22.88 N s/m
 * against a wall (m* = m), so friction is saturated at μ F_n for slips above
 * 0.155 m/s and 0.109 m/s; the spins used (ω = 100 rad/s, surface speed
 * about 1 m/s) are far above that.
 *
 * Tolerances: a single force evaluation is checked to 1e-12 relative to the
 * scale of the force or torque involved. The inputs are exact to round-off:
 * the overlap δ = 1e-4 is the difference of centre distances of order 2e-2
 * that carry errors of a few 1e-18 m, i.e. a relative error of order 1e-14
 * in δ and in everything proportional to it; 1e-12 leaves a factor 100 for
 * the few further operations. Components expected to be zero are checked
 * against the same absolute bound (1e-12 × the scale). Multi-step tests state
 * their own tolerance where they are written.
 */
#include <math.h>
#include <stddef.h>

#include "testutil.h"

#define TOL 1e-12
#define MAXC 8 /* contacts a test can have */

static const double R = 0.01;     /* m */
static const double RHO = 2500.0; /* kg/m³ */
static const double KN = 5e4;     /* N/m, series stiffness of two default materials */
static const double DELTA = 1e-4; /* m */
static const double MU = 0.5;     /* default friction */
static const double W0 = 100.0;   /* rad/s, the spin used for sliding contacts */

static double sphere_mass(double r)
{
    return 4.0 / 3.0 * M_PI * r * r * r * RHO;
}

static double sphere_inertia(double r)
{
    return 0.4 * sphere_mass(r) * r * r;
}

/* ---- scene helpers ----------------------------------------------------- */

/* A world without gravity, the linear law without damping and the given
 * tangential and rolling laws for the one material. */
static demill_world *scene(int dim, int tangential, int rolling, demill_id *m)
{
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, m);
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_TANGENTIAL, tangential));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_ROLLING, rolling));
    return w;
}

static demill_id add(demill_world *w, demill_id m, double x, double y, double z, double r)
{
    double p[3] = {x, y, z};
    demill_id id = DEMILL_ID_NONE;
    DM_OK(w, demill_particles_add(w, m, 1, p, &r, NULL, 0, &id));
    DM_ASSERT_REL(dm_test_get(w, id, DEMILL_PARTICLE_MASS, 0), sphere_mass(r), 1e-14);
    return id;
}

static void set3(demill_world *w, demill_id p, int field, double x, double y, double z)
{
    double v[3] = {x, y, z};
    DM_OK(w, demill_particle_set(w, p, field, v));
}

/* A plane wall through `point` facing `normal` (not necessarily unit). */
static demill_id plane(demill_world *w, demill_id m, double px, double py, double pz, double nx,
                       double ny, double nz)
{
    double p[3] = {px, py, pz}, n[3] = {nx, ny, nz};
    demill_id id = DEMILL_ID_NONE;
    DM_OK(w, demill_wall_add_plane(w, m, p, n, &id));
    return id;
}

/* The floor y = 0, particles above it. */
static demill_id floor_wall(demill_world *w, demill_id m)
{
    return plane(w, m, 0, 0, 0, 0, 1, 0);
}

/* Evaluates the forces at the current state without moving anything. */
static void eval(demill_world *w)
{
    DM_OK(w, demill_world_step(w, 0));
}

/* ---- checks ------------------------------------------------------------ */

/* |got_c - want_c| <= tol × scale for each of the three components; line:
 * the caller's line, for the message. */
static void expect_vec_at(int line, const char *what, const double got[3], double x, double y,
                          double z, double scale, double tol)
{
    const double want[3] = {x, y, z};
    for (int c = 0; c < 3; c++)
        ck_assert_msg(fabs(got[c] - want[c]) <= tol * scale,
                      "line %d: %s[%d] = %.12g, expected %.12g (within %.3g)", line, what, c,
                      got[c], want[c], tol * scale);
}
#define expect_vec(...) expect_vec_at(__LINE__, __VA_ARGS__)

/* A particle's vector field against (x, y, z), to TOL × scale. */
#define EXPECT_P(w, p, field, x, y, z, scale)                                                   \
    do {                                                                                          \
        double g3_[3];                                                                            \
        DM_OK(w, demill_particle_get(w, p, field, g3_));                                          \
        expect_vec(#p " " #field, g3_, x, y, z, scale, TOL);                                      \
    } while (0)

/* A wall's vector field against (x, y, z), to TOL × scale. */
#define EXPECT_W(w, wall, field, x, y, z, scale)                                                \
    do {                                                                                          \
        double g3_[3];                                                                            \
        DM_OK(w, demill_wall_get(w, wall, field, g3_));                                           \
        expect_vec(#wall " " #field, g3_, x, y, z, scale, TOL);                                   \
    } while (0)

static size_t contact_count(demill_world *w)
{
    size_t n = 0;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL, NULL, 0, &n));
    return n;
}

/* Field `field` of contact k (1 or 3 doubles into out[3]). */
static void contact_get(demill_world *w, int field, size_t k, double out[3])
{
    double buf[3 * MAXC];
    size_t n = 0;
    DM_OK(w, demill_contacts_read(w, field, buf, MAXC, &n));
    ck_assert_msg(k < n, "contact %zu of %zu", k, n);
    int sz = demill_contact_field_size(field);
    out[0] = out[1] = out[2] = 0.0;
    for (int c = 0; c < sz; c++)
        out[c] = buf[(size_t)sz * k + (size_t)c];
}

/* Contact k against (x, y, z), to TOL × scale. */
#define EXPECT_C(w, k, field, x, y, z, scale)                                                   \
    do {                                                                                          \
        double g3_[3];                                                                            \
        contact_get(w, field, k, g3_);                                                            \
        expect_vec("contact " #k " " #field, g3_, x, y, z, scale, TOL);                          \
    } while (0)

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The second view: for every particle, gravity m g plus the forces of its
 * contacts as read by demill_contacts_read() (b exerts F = F_n + F_t on a, a
 * exerts -F on b; torques (contact point - centre) × force, plus the
 * rolling torque M_r on a and -M_r on b) must equal the per-particle totals
 * DEMILL_PARTICLE_FORCE and DEMILL_PARTICLE_TORQUE of the last evaluation.
 * fscale, tscale: the force and torque scales of the test. */
static void check_contact_view(demill_world *w, double fscale, double tscale)
{
    double pt[3 * MAXC], fn[3 * MAXC], ft[3 * MAXC], mr[3 * MAXC];
    demill_id ca[MAXC], cb[MAXC];
    size_t nc = 0, k;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_POINT, pt, MAXC, &nc));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_NORMAL_FORCE, fn, MAXC, &k));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_TANGENTIAL_FORCE, ft, MAXC, &k));
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_ROLLING_TORQUE, mr, MAXC, &k));
    DM_OK(w, demill_contacts_read_ids(w, ca, cb, MAXC, &k));
    ck_assert(k == nc);
    double g[3];
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_X, &g[0]));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Y, &g[1]));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Z, &g[2]));
    demill_id ids[MAXC];
    size_t np = 0;
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_ID, ids, MAXC, &np));
    for (size_t p = 0; p < np; p++) {
        double x[3], f[3], t[3], m = dm_test_get(w, ids[p], DEMILL_PARTICLE_MASS, 0);
        double sf[3] = {m * g[0], m * g[1], m * g[2]}, st[3] = {0, 0, 0};
        DM_OK(w, demill_particle_get(w, ids[p], DEMILL_PARTICLE_POSITION, x));
        DM_OK(w, demill_particle_get(w, ids[p], DEMILL_PARTICLE_FORCE, f));
        DM_OK(w, demill_particle_get(w, ids[p], DEMILL_PARTICLE_TORQUE, t));
        for (size_t c = 0; c < nc; c++) {
            double sign = ca[c] == ids[p] ? 1.0 : cb[c] == ids[p] ? -1.0 : 0.0;
            if (sign == 0.0)
                continue;
            double fc[3], arm[3], tc[3];
            for (int d = 0; d < 3; d++) {
                fc[d] = sign * (fn[3 * c + d] + ft[3 * c + d]);
                arm[d] = pt[3 * c + d] - x[d];
            }
            cross(arm, fc, tc);
            for (int d = 0; d < 3; d++) {
                sf[d] += fc[d];
                st[d] += tc[d] + sign * mr[3 * c + d];
            }
        }
        expect_vec("contact view: force", f, sf[0], sf[1], sf[2], fscale, TOL);
        expect_vec("contact view: torque", t, st[0], st[1], st[2], tscale, TOL);
    }
}

/* ======================================================================== */
/* 1. Head-on contact: repulsion along the line of centres.
 *
 * Linear law, no damping, frictionless. a at the origin, b at (2R - δ) x̂:
 * n = x̂ (from a to b), overlap δ = 1e-4, |F_n| = k δ = 5e4 · 1e-4 = 5 N.
 * Repulsion: F_a = -k δ x̂ = (-5, 0, 0) N, F_b = (+5, 0, 0) N. The approach
 * speeds (+1 and -1 m/s) change nothing without a dashpot. The force passes
 * through both centres: no torque. Contact view: one contact, normal x̂,
 * overlap δ, point x_a + (R - δ/2) n = (9.95e-3, 0, 0), normal force on a
 * (-5, 0, 0), no tangential force.
 * Second placement, b below a at -(2R - δ) ŷ: n = -ŷ, F_a = (0, +5, 0) N,
 * F_b = (0, -5, 0) N. */
START_TEST(head_on_repulsion)
{
    const int dim = _i;
    const double F = KN * DELTA, arm = R - DELTA / 2;
    for (int placement = 0; placement < 2; placement++) {
        demill_id m;
        demill_world *w = scene(dim, DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_NONE, &m);
        const double nx = placement ? 0.0 : 1.0, ny = placement ? -1.0 : 0.0;
        demill_id a = add(w, m, 0, 0, 0, R);
        demill_id b = add(w, m, nx * (2 * R - DELTA), ny * (2 * R - DELTA), 0, R);
        set3(w, a, DEMILL_PARTICLE_VELOCITY, nx, ny, 0);
        set3(w, b, DEMILL_PARTICLE_VELOCITY, -nx, -ny, 0);
        eval(w);
        EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F * nx, -F * ny, 0, F);
        EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F * nx, F * ny, 0, F);
        EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, 0, F * arm);
        EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, 0, F * arm);
        ck_assert_uint_eq(contact_count(w), 1);
        EXPECT_C(w, 0, DEMILL_CONTACT_OVERLAP, DELTA, 0, 0, DELTA);
        /* the contact's a may be either particle: orient by its normal */
        double n[3];
        contact_get(w, DEMILL_CONTACT_NORMAL, 0, n);
        const double s = n[0] * nx + n[1] * ny; /* +1 if a is the contact's a */
        expect_vec("normal", n, s * nx, s * ny, 0, 1, TOL);
        /* seen from either particle the point is a n from the origin */
        EXPECT_C(w, 0, DEMILL_CONTACT_POINT, arm * nx, arm * ny, 0, R);
        EXPECT_C(w, 0, DEMILL_CONTACT_NORMAL_FORCE, -s * F * nx, -s * F * ny, 0, F);
        EXPECT_C(w, 0, DEMILL_CONTACT_TANGENTIAL_FORCE, 0, 0, 0, F);
        check_contact_view(w, F, F * arm);
        demill_world_destroy(w);
    }
}
END_TEST

/* 2. Head-on Hertz contact of unequal spheres.
 *
 * R_a = 0.01, R_b = 0.02, b at (R_a + R_b - δ) x̂. R* = R_a R_b/(R_a + R_b)
 * = 6.6667e-3 m; E* = 1/(2 (1 - ν²)/E) = 1e8/1.82 = 5.4945e7 Pa (default
 * E = 1e8, ν = 0.3 for both); F = 4/3 E* √R* δ^{3/2} = 5.9817 N.
 * F_a = -F x̂, F_b = +F x̂: equal and opposite, the total is zero (Newton's
 * third law) although the masses differ 8-fold. */
START_TEST(hertz_unequal_head_on)
{
    const int dim = _i;
    demill_id m;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, &m);
    const double ra = 0.01, rb = 0.02, rs = ra * rb / (ra + rb);
    const double estar = 1e8 / (2 * (1 - 0.3 * 0.3));
    const double F = 4.0 / 3.0 * estar * sqrt(rs) * DELTA * sqrt(DELTA);
    demill_id a = add(w, m, 0, 0, 0, ra);
    demill_id b = add(w, m, ra + rb - DELTA, 0, 0, rb);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, 0, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, 0, 0, F);
    double fa[3], fb[3];
    DM_OK(w, demill_particle_get(w, a, DEMILL_PARTICLE_FORCE, fa));
    DM_OK(w, demill_particle_get(w, b, DEMILL_PARTICLE_FORCE, fb));
    expect_vec("F_a + F_b", (double[3]){fa[0] + fb[0], fa[1] + fb[1], fa[2] + fb[2]}, 0, 0, 0, F,
               TOL);
    check_contact_view(w, F, F * rb);
    demill_world_destroy(w);
}
END_TEST

/* 3. Approach with a dashpot: damping adds to the repulsion.
 *
 * Viscous damping c_n = 100 N s/m. a at rest, b approaching at u = 0.02 m/s
 * (v_b = -u x̂). v_c·n = -u < 0. The normal force on b along n is
 * k δ - c_n (v_c·n) = 5 + 2 = 7 N: F_a = (-7, 0, 0), F_b = (+7, 0, 0) N. */
START_TEST(approach_damping_adds_repulsion)
{
    const int dim = _i;
    demill_id m;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, &m);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_VISCOUS_DAMPING, 100.0));
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, b, DEMILL_PARTICLE_VELOCITY, -0.02, 0, 0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -7.0, 0, 0, 7.0);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, 7.0, 0, 0, 7.0);
    check_contact_view(w, 7.0, 7.0 * R);
    demill_world_destroy(w);
}
END_TEST

/* 4. Receding contact with a dashpot: damping reduces the repulsion.
 *
 * As test 3 but b recedes at u = 0.02 m/s (v_b = +u x̂), v_c·n = +u:
 * k δ - c_n u = 5 - 2 = 3 N, still repulsive: F_a = (-3, 0, 0),
 * F_b = (+3, 0, 0) N, with the clamp on or off (nothing to clamp). */
START_TEST(receding_damping_reduces_repulsion)
{
    const int dim = _i;
    for (int clamp = 0; clamp <= 1; clamp++) {
        demill_id m;
        demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_VISCOUS_DAMPING, 100.0));
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, clamp));
        demill_id a = add(w, m, 0, 0, 0, R);
        demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
        set3(w, b, DEMILL_PARTICLE_VELOCITY, 0.02, 0, 0);
        eval(w);
        EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -3.0, 0, 0, 3.0);
        EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, 3.0, 0, 0, 3.0);
        check_contact_view(w, 3.0, 3.0 * R);
        demill_world_destroy(w);
    }
}
END_TEST

/* 5. Fast recession with DEMILL_PAIR_CLAMP_NORMAL = 1 (default): never a pull.
 *
 * c_n = 100 N s/m, b recedes at u = 0.1 m/s: k δ - c_n u = 5 - 10 = -5 N
 * would pull; the clamp makes it 0. Both particles feel no force at all, the
 * contact still exists (δ > 0) and reports a zero normal force. */
START_TEST(receding_clamped_never_pulls)
{
    const int dim = _i;
    demill_id m;
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, &m);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_VISCOUS_DAMPING, 100.0));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, 1));
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, b, DEMILL_PARTICLE_VELOCITY, 0.1, 0, 0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, 0, 0, 0, 5.0);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, 0, 0, 0, 5.0);
    ck_assert_uint_eq(contact_count(w), 1);
    EXPECT_C(w, 0, DEMILL_CONTACT_NORMAL_FORCE, 0, 0, 0, 5.0);
    check_contact_view(w, 5.0, 5.0 * R);
    demill_world_destroy(w);
}
END_TEST

/* 6. Fast recession with DEMILL_PAIR_CLAMP_NORMAL = 0: the force pulls.
 *
 * (i) Viscous c_n = 100 N s/m, u = 0.1 m/s: k δ - c_n u = -5 N, attractive:
 *     a is pulled towards b, F_a = (+5, 0, 0), F_b = (-5, 0, 0) N.
 * (ii) Damping from restitution e = 0.5 without the clamp (the classic
 *     model, docs/physics.md §3): ξ = -ln e/√(π² + ln² e) = 0.21545,
 *     m* = m/2, c_n = 2 ξ √(m* k) = 6.9722 N s/m; u = 1 m/s:
 *     F = k δ - c_n u = 5 - 6.9722 = -1.9722 N, again a pull. */
START_TEST(receding_unclamped_pulls)
{
    const int dim = _i;
    for (int law = 0; law < 2; law++) {
        demill_id m;
        demill_world *w = dm_test_world(
            dim, DEMILL_NORMAL_LINEAR, law ? DEMILL_DAMPING_RESTITUTION : DEMILL_DAMPING_VISCOUS, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, 0));
        double u = 0.1, c = 100.0;
        if (law) {
            const double e = 0.5, l = log(e), xi = -l / sqrt(M_PI * M_PI + l * l);
            DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, e));
            c = 2 * xi * sqrt(sphere_mass(R) / 2 * KN);
            u = 1.0;
        } else {
            DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_VISCOUS_DAMPING, c));
        }
        const double fn = KN * DELTA - c * u; /* < 0 */
        ck_assert(fn < 0);
        demill_id a = add(w, m, 0, 0, 0, R);
        demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
        set3(w, b, DEMILL_PARTICLE_VELOCITY, u, 0, 0);
        eval(w);
        EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -fn, 0, 0, fabs(fn));
        EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, fn, 0, 0, fabs(fn));
        check_contact_view(w, fabs(fn), fabs(fn) * R);
        demill_world_destroy(w);
    }
}
END_TEST

/* 7. A spinning sphere touching one at rest: friction acts like a gear.
 *
 * Coulomb friction. a at the origin spins ω_a = W0 ẑ (W0 = 100 rad/s,
 * counter-clockwise), b at (2R - δ) x̂ at rest. n = x̂, r_a = a x̂.
 * v_c = -ω_a × r_a = -W0 a (ẑ × x̂) = -W0 a ŷ (0.995 m/s, saturated):
 * friction on b = +μ k δ ŷ, on a = -μ k δ ŷ (a's surface moves +ŷ at the
 * contact and is held back).
 * F_a = (-k δ, -μ k δ, 0) = (-5, -2.5, 0) N; F_b = (5, 2.5, 0) N.
 * T_a = a x̂ × (-μ k δ ŷ) = -a μ k δ ẑ = -2.4875e-2 ẑ N m: opposes ω_a (a slows).
 * T_b = (-a x̂) × (μ k δ ŷ) = -a μ k δ ẑ: b is spun clockwise, opposite to a,
 * like a meshing gear. Contact view: tangential force on a (0, -2.5, 0). */
START_TEST(spinning_drives_partner_like_gear)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, -f, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, f, 0, F);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    demill_id ca;
    size_t n;
    DM_OK(w, demill_contacts_read_ids(w, &ca, NULL, 1, &n));
    const double s = ca == a ? 1.0 : -1.0;
    EXPECT_C(w, 0, DEMILL_CONTACT_TANGENTIAL_FORCE, 0, -s * f, 0, F);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 8. The gear of test 7 over two steps (velocity Verlet, Δt = 1e-5 s).
 *
 * Angular acceleration of both: -a μ k δ / I = -0.024875/4.1888e-7
 * = -5.9385e4 rad/s², so after t = 2Δt: ω_a = W0 - 1.1877 rad/s (slowed),
 * ω_b = -1.1877 rad/s (spun the other way). Linear: v_b,y = +μ k δ/m · t
 * = +4.7746e-3 m/s, v_a,y = -4.7746e-3 m/s. Tolerance 1 % on the changes:
 * the particles separate by ½ (2 k δ/m) t² = 1.9e-7 m in that time, which
 * lowers δ and thus the friction by at most 0.2 %; the slip (1 m/s) stays
 * far above the regularisation limit, so friction stays at μ k δ. */
START_TEST(gear_steps)
{
    const int dim = _i;
    const double dt = 1e-5, t = 2 * dt, F = KN * DELTA, arm = R - DELTA / 2;
    const double alpha = arm * MU * F / sphere_inertia(R), acc = MU * F / sphere_mass(R);
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    DM_OK(w, demill_world_step(w, 2));
    DM_ASSERT_REL(dm_test_get(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2) - W0, -alpha * t, 0.01);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), -alpha * t, 0.01);
    DM_ASSERT_REL(dm_test_get(w, a, DEMILL_PARTICLE_VELOCITY, 1), -acc * t, 0.01);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_VELOCITY, 1), acc * t, 0.01);
    demill_world_destroy(w);
}
END_TEST

/* 9. Two equal spheres spinning the same way: a sliding contact.
 *
 * ω_a = ω_b = W0 ẑ, b at (2R - δ) x̂. v_c = ω_b × r_b - ω_a × r_a
 * = -a W0 ŷ - a W0 ŷ = -2 a W0 ŷ: the surfaces rub in opposite directions.
 * Friction μ k δ: on a -2.5 ŷ N, on b +2.5 ŷ N. Torques
 * T_a = a x̂ × (-μ k δ ŷ) = -a μ k δ ẑ and T_b = (-a x̂) × (μ k δ ŷ) = -a μ k δ ẑ:
 * both oppose their (positive) spins, both slow down. */
START_TEST(same_spin_slides)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    set3(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, -f, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, f, 0, F);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 10. Two equal spheres spinning opposite ways: a rolling contact.
 *
 * ω_a = W0 ẑ, ω_b = -W0 ẑ: v_c = -a (ω_a + ω_b) ŷ = 0 (the surfaces move
 * together, like meshing gears). No friction, no torque: the forces are the
 * pure normal pair (∓5, 0, 0) N. */
START_TEST(opposite_spin_rolls)
{
    const int dim = _i;
    const double F = KN * DELTA, arm = R - DELTA / 2;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    set3(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, -W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, 0, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, 0, 0, F);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, 0, arm * F);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, 0, arm * F);
    EXPECT_C(w, 0, DEMILL_CONTACT_TANGENTIAL_FORCE, 0, 0, 0, F);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 11. Sliding along a floor: friction opposes the motion and spins the
 * particle up in the rolling sense.
 *
 * Floor y = 0 (normal +ŷ), particle at (0, R - δ, 0), n = -ŷ (particle to
 * wall), r = -a ŷ, ω = 0.
 * (i) v = 1 m/s x̂: v_c = 0 - v = -x̂ (saturated). Friction on the particle
 *     -μ k δ x̂; normal +k δ ŷ: F = (-2.5, 5, 0) N. T = (-a ŷ) × (-μ k δ x̂)
 *     = a μ k δ (ŷ × x̂) = -a μ k δ ẑ: negative spin, which is the rolling
 *     sense for motion along +x (rolling needs v + ω × r = 0, ω_z = -v/a).
 *     The wall receives the opposite: (+2.5, -5, 0) N.
 * (ii) v = 0.01 m/s x̂, below the regularisation limit: friction
 *     γ |v_t| = √(m k) · 0.01 = 0.22882 N, still against the motion.
 * (iii) 3D: v = (1, 0, 1)/√2 m/s: friction -μ k δ (1, 0, 1)/√2, torque
 *     (-a ŷ) × F_t = a μ k δ/√2 (ŷ × x̂ + ŷ × ẑ) = a μ k δ (1, 0, -1)/√2, which
 *     is along ŷ × v, the rolling spin for that motion. */
START_TEST(sliding_on_floor)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    const double gamma = sqrt(sphere_mass(R) * KN);
    for (int c = 0; c < (dim == 3 ? 3 : 2); c++) {
        demill_id m;
        demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
        demill_id fl = floor_wall(w, m);
        demill_id p = add(w, m, 0, R - DELTA, 0, R);
        if (c == 0) {
            set3(w, p, DEMILL_PARTICLE_VELOCITY, 1.0, 0, 0);
            eval(w);
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -f, F, 0, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
            EXPECT_W(w, fl, DEMILL_WALL_FORCE, f, -F, 0, F);
        } else if (c == 1) {
            const double fr = gamma * 0.01;
            ck_assert(fr < f);
            set3(w, p, DEMILL_PARTICLE_VELOCITY, 0.01, 0, 0);
            eval(w);
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -fr, F, 0, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * fr, arm * f);
        } else {
            const double s = 1 / sqrt(2.0);
            set3(w, p, DEMILL_PARTICLE_VELOCITY, s, 0, s);
            eval(w);
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -f * s, F, -f * s, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, arm * f * s, 0, -arm * f * s, arm * f);
        }
        check_contact_view(w, F, F * arm);
        demill_world_destroy(w);
    }
}
END_TEST

/* Gravity along -ŷ that exactly balances the floor's k δ, so δ and the
 * normal force stay constant while a particle moves along the floor. */
static void balance_on_floor(demill_world *w)
{
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -KN * DELTA / sphere_mass(R)));
}

/* 12. A sphere thrown sliding onto a floor spins up and ends up rolling.
 *
 * Floor, particle at (0, R - δ, 0) with v = v0 x̂ (v0 = 1 m/s), ω = 0, and
 * gravity g' = k δ/m along -ŷ so that the normal force stays k δ (δ fixed).
 * While it slides, friction is the constant μ k δ against the motion and the
 * torque the constant -a μ k δ ẑ (test 11), so after N = 20 steps
 * (t = 2e-4 s; Verlet is exact for constant forces):
 *   v_x = v0 - μ k δ/m t = 0.95225 m/s, ω_z = -a μ k δ/I t = -11.877 rad/s
 * (the slip v_x + ω_z a = 0.834 m/s is still saturated). Checked to 1e-10.
 * Friction then acts at the contact point only (the normal force passes
 * through it), so the angular momentum about the contact point,
 * L = I ω_z - m a v_x, is conserved (each kick changes I ω_z by a F_t Δt/2
 * and m a v_x by the same amount). Rolling ends the slip: v_x + ω_z a = 0.
 * Hence -m a v0 = -(I/a + m a) v_f:
 *   v_f = m a² v0/(I + m a²) = 0.71224 m/s (≈ 5/7 v0), ω_f = -v_f/a.
 * The slip disappears after about 1.2 ms at the cap, then decays with the
 * regularisation (rate γ (1/m + a²/I) ≈ 7.6e3 /s); after 6 ms it is below
 * 1e-15 of its start, so v_f and ω_f are checked to 1e-9 (round-off only). */
START_TEST(sliding_spins_up_then_rolls)
{
    const int dim = _i;
    const double dt = 1e-5, F = KN * DELTA, arm = R - DELTA / 2, v0 = 1.0;
    const double m_ = sphere_mass(R), I = sphere_inertia(R);
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    balance_on_floor(w);
    floor_wall(w, m);
    demill_id p = add(w, m, 0, R - DELTA, 0, R);
    set3(w, p, DEMILL_PARTICLE_VELOCITY, v0, 0, 0);
    DM_OK(w, demill_world_step(w, 20));
    const double t = 20 * dt;
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_VELOCITY, 0), v0 - MU * F / m_ * t, 1e-10);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), -arm * MU * F / I * t,
                  1e-10);
    DM_OK(w, demill_world_step(w, 580));
    const double vf = m_ * arm * arm * v0 / (I + m_ * arm * arm);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_VELOCITY, 0), vf, 1e-9);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), -vf / arm, 1e-9);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_POSITION, 1), R - DELTA, 1e-12);
    demill_world_destroy(w);
}
END_TEST

/* 13. A sphere spinning on a floor with no linear velocity starts to move.
 *
 * Floor, particle at (0, R - δ, 0), v = 0, ω = W0 ẑ (counter-clockwise).
 * Contact point velocity ω × r = W0 ẑ × (-a ŷ) = +W0 a x̂ (0.995 m/s):
 * friction on the particle -μ k δ x̂. The particle starts to move along
 * ω × (centre - contact point) = W0 ẑ × a ŷ = -W0 a x̂, i.e. along -x:
 * F = (-2.5, 5, 0) N, and T = (-a ŷ) × (-μ k δ x̂) = -a μ k δ ẑ opposes the
 * spin. With gravity balancing k δ (as in test 12), angular momentum about
 * the contact point, I ω_z - m a v_x = I W0, is conserved, and the sphere
 * ends rolling (v_x = -ω_z a): ω_f = I W0/(I + m a²) (≈ 2/7 W0),
 * v_f = -a ω_f = -0.28633 m/s. Checked to 1e-9 after 6 ms (see test 12). */
START_TEST(spinning_on_floor_starts_to_roll)
{
    const int dim = _i;
    const double dt = 1e-5, F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    const double m_ = sphere_mass(R), I = sphere_inertia(R);
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    floor_wall(w, m);
    demill_id p = add(w, m, 0, R - DELTA, 0, R);
    set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -f, F, 0, F);
    EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    check_contact_view(w, F, F * arm);
    balance_on_floor(w);
    DM_OK(w, demill_world_step(w, 600));
    const double wf = I * W0 / (I + m_ * arm * arm);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), wf, 1e-9);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_VELOCITY, 0), -arm * wf, 1e-9);
    ck_assert(dm_test_get(w, p, DEMILL_PARTICLE_POSITION, 0) < 0);
    demill_world_destroy(w);
}
END_TEST

/* 14. 3D: spins about x, y and z on a floor (normal ŷ).
 *
 * Particle at (0, R - δ, 0), v = 0, r = -a ŷ from the centre to the contact.
 * - ω = W0 x̂: contact point velocity ω × r = -W0 a (x̂ × ŷ) = -W0 a ẑ;
 *   friction +μ k δ ẑ: the sphere starts along +z = ω × (a ŷ) direction;
 *   T = (-a ŷ) × (μ k δ ẑ) = -a μ k δ x̂ opposes the spin.
 * - ω = W0 ŷ (about the normal, drilling): ω × r = 0, no friction, no
 *   torque (no twisting resistance in these laws): F = (0, 5, 0) N.
 * - ω = W0 ẑ: as test 13, F = (-μ k δ, k δ, 0), T = -a μ k δ ẑ. */
START_TEST(floor_spin_axes_3d)
{
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    for (int axis = 0; axis < 3; axis++) {
        demill_id m;
        demill_world *w = scene(3, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
        floor_wall(w, m);
        demill_id p = add(w, m, 0, R - DELTA, 0, R);
        set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, axis == 0 ? W0 : 0, axis == 1 ? W0 : 0,
             axis == 2 ? W0 : 0);
        eval(w);
        if (axis == 0) {
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, f, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, -arm * f, 0, 0, arm * f);
        } else if (axis == 1) {
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, 0, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, 0, arm * f);
        } else {
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -f, F, 0, F);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
        }
        check_contact_view(w, F, F * arm);
        demill_world_destroy(w);
    }
}
END_TEST

/* 15. A sphere rolling without slip has no friction force.
 *
 * Floor, particle at (0, R - δ, 0), v = V x̂ (V = 1 m/s) and ω = -V/a ẑ with
 * the true lever arm a = R - δ/2: the contact point moves at
 * v + ω × r = V x̂ + (-V/a) ẑ × (-a ŷ) = V x̂ - V x̂ = 0. No slip, no
 * friction, no torque: F = (0, k δ, 0). (With the lever arm R instead of a
 * the slip would be V δ/(2a) = 5e-3 m/s and the friction 0.23 N, which the
 * 1e-12 bound would catch.) 3D also rolls along z: v = V ẑ,
 * ω = V/a x̂, ω × r = -V ẑ. */
START_TEST(rolling_without_slip_no_friction)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2, V = 1.0;
    for (int dir = 0; dir < (dim == 3 ? 2 : 1); dir++) {
        demill_id m;
        demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
        floor_wall(w, m);
        demill_id p = add(w, m, 0, R - DELTA, 0, R);
        if (dir == 0) {
            set3(w, p, DEMILL_PARTICLE_VELOCITY, V, 0, 0);
            set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, -V / arm);
        } else {
            set3(w, p, DEMILL_PARTICLE_VELOCITY, 0, 0, V);
            set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, V / arm, 0, 0);
        }
        eval(w);
        EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, 0, f);
        EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, 0, arm * f);
        EXPECT_C(w, 0, DEMILL_CONTACT_TANGENTIAL_FORCE, 0, 0, 0, f);
        check_contact_view(w, F, F * arm);
        demill_world_destroy(w);
    }
}
END_TEST

/* 16. Rolling resistance on a floor opposes the spin.
 *
 * Constant-torque law, μ_r = 0.1 for the pair; R* = R against a wall,
 * m* = m. The cap is μ_r R k δ = 0.1 · 0.01 · 5 = 5e-3 N m; the
 * regularisation γ_r = R*² √(m* k) = 2.2882e-3 N m s.
 * (i) Frictionless, v = 0, ω = 50 ẑ rad/s (γ_r ω = 0.23 > cap): the torque
 *     is -5e-3 ẑ N m, the force only the normal (0, 5, 0) N.
 * (ii) ω = -50 ẑ: +5e-3 ẑ N m (it always opposes the spin).
 * (iii) ω = 0.5 ẑ, below the cap: -γ_r · 0.5 = -1.1441e-3 ẑ N m.
 * (iv) Coulomb friction too, rolling without slip along +x
 *     (v = 0.5 x̂, ω = -0.5/a ẑ): no friction (test 15), the torque is the
 *     rolling resistance alone, +5e-3 ẑ N m, against the roll.
 * The contact view reports the torque as DEMILL_CONTACT_ROLLING_TORQUE. */
START_TEST(rolling_resistance_on_floor)
{
    const int dim = _i;
    const double F = KN * DELTA, mur = 0.1, cap = mur * R * F, arm = R - DELTA / 2;
    const double gr = R * R * sqrt(sphere_mass(R) * KN);
    const double spins[4] = {50.0, -50.0, 0.5, -0.5 / arm};
    const double want[4] = {-cap, cap, -gr * 0.5, cap};
    for (int c = 0; c < 4; c++) {
        demill_id m;
        demill_world *w = scene(dim, c == 3 ? DEMILL_TANGENTIAL_COULOMB : DEMILL_TANGENTIAL_NONE,
                                DEMILL_ROLLING_CONSTANT_TORQUE, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, mur));
        floor_wall(w, m);
        demill_id p = add(w, m, 0, R - DELTA, 0, R);
        set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, spins[c]);
        if (c == 3)
            set3(w, p, DEMILL_PARTICLE_VELOCITY, 0.5, 0, 0);
        eval(w);
        EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, 0, F);
        EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, want[c], cap);
        EXPECT_C(w, 0, DEMILL_CONTACT_ROLLING_TORQUE, 0, 0, want[c], cap);
        check_contact_view(w, F, cap);
        demill_world_destroy(w);
    }
}
END_TEST

/* 17. Rolling resistance between two balls opposes their relative spin.
 *
 * Frictionless, μ_r = 0.1, two equal balls (b at (2R - δ) x̂): R* = R/2,
 * cap μ_r R* k δ = 2.5e-3 N m, γ_r = R*² √(m* k) = 4.05e-4 N m s with
 * m* = m/2, so |ω_rel| >= 50 rad/s is saturated. ω_rel = ω_a - ω_b; a gets
 * -cap ω_rel/|ω_rel|, b the opposite.
 * (i) a spins W = 50 ẑ, b at rest: T_a = -2.5e-3 ẑ (slows a),
 *     T_b = +2.5e-3 ẑ (drags b along with a's spin).
 * (ii) both spin 50 ẑ (the sliding pair of test 9): ω_rel = 0, no rolling
 *     torque at all.
 * (iii) a 50 ẑ, b -50 ẑ (the rolling pair of test 10): ω_rel = 100 ẑ,
 *     T_a = -2.5e-3 ẑ, T_b = +2.5e-3 ẑ: each torque opposes its own spin. */
START_TEST(rolling_resistance_between_balls)
{
    const int dim = _i;
    const double F = KN * DELTA, mur = 0.1, cap = mur * (R / 2) * F, arm = R - DELTA / 2;
    const double wb[3] = {0.0, 50.0, -50.0}, ta[3] = {-cap, 0.0, -cap};
    for (int c = 0; c < 3; c++) {
        demill_id m;
        demill_world *w = scene(dim, DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_CONSTANT_TORQUE, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, mur));
        demill_id a = add(w, m, 0, 0, 0, R);
        demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
        set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, 50.0);
        set3(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, wb[c]);
        eval(w);
        EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, ta[c], cap);
        EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -ta[c], cap);
        EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, 0, 0, F);
        EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, 0, 0, F);
        check_contact_view(w, F, cap + arm * F);
        demill_world_destroy(w);
    }
}
END_TEST

/* 18. 3D: rolling resistance about an oblique axis.
 *
 * μ_r = 0.1, frictionless. ê = (2, -1, 2)/3 (unit).
 * (i) On the floor, ω = 50 ê: T = -μ_r R k δ ê = -5e-3 ê N m (exactly
 *     antiparallel to the spin, whatever its axis).
 * (ii) Ball a (ω_a = 50 ê) on ball b (ω_b = 20 ê), b at (2R - δ) x̂:
 *     ω_rel = 30 ê (saturated, γ_r · 30 = 0.024 > 2.5e-3): T_a = -2.5e-3 ê,
 *     T_b = +2.5e-3 ê N m. */
START_TEST(rolling_resistance_oblique_axis_3d)
{
    const double F = KN * DELTA, mur = 0.1, e[3] = {2.0 / 3, -1.0 / 3, 2.0 / 3};
    for (int c = 0; c < 2; c++) {
        demill_id m;
        demill_world *w = scene(3, DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_CONSTANT_TORQUE, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, mur));
        if (c == 0) {
            const double cap = mur * R * F;
            floor_wall(w, m);
            demill_id p = add(w, m, 0, R - DELTA, 0, R);
            set3(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 50 * e[0], 50 * e[1], 50 * e[2]);
            eval(w);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, -cap * e[0], -cap * e[1], -cap * e[2], cap);
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, 0, F);
            check_contact_view(w, F, cap);
        } else {
            const double cap = mur * R / 2 * F;
            demill_id a = add(w, m, 0, 0, 0, R);
            demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
            set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 50 * e[0], 50 * e[1], 50 * e[2]);
            set3(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 20 * e[0], 20 * e[1], 20 * e[2]);
            eval(w);
            EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, -cap * e[0], -cap * e[1], -cap * e[2], cap);
            EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, cap * e[0], cap * e[1], cap * e[2], cap);
            check_contact_view(w, F, cap);
        }
        demill_world_destroy(w);
    }
}
END_TEST

/* 19. A wall moving along its own plane (a belt) drags a particle with it.
 *
 * Floor with velocity U x̂ (U = 1 m/s, parallel to the plane, so δ does not
 * change), particle at rest at (0, R - δ, 0). v_c = U x̂ - 0 (saturated):
 * friction on the wall -μ k δ x̂, on the particle +μ k δ x̂: F = (2.5, 5, 0) N;
 * T = (-a ŷ) × (μ k δ x̂) = +a μ k δ ẑ: the particle spins so that its bottom
 * follows the belt. The wall receives (-2.5, -5, 0) N.
 * Stepping with gravity balancing k δ: friction acts at the contact point,
 * so I ω_z - m a v_x stays 0 (its initial value). The slip ends when the
 * particle's bottom moves with the belt, v_x + ω_z a = U, so
 * v_f = U I/(I + m a²) = 0.28776 m/s (≈ 2/7 U, dragged forward) and
 * ω_f = (U - v_f)/a > 0; checked to 1e-9 after 6 ms (see test 12). The wall's
 * point has moved by U t exactly (prescribed motion). */
START_TEST(moving_wall_drags_particle)
{
    const int dim = _i;
    const double dt = 1e-5, F = KN * DELTA, f = MU * F, arm = R - DELTA / 2, U = 1.0;
    const double m_ = sphere_mass(R), I = sphere_inertia(R);
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    demill_id fl = floor_wall(w, m);
    DM_OK(w, demill_wall_set_motion(w, fl, (double[3]){U, 0, 0}, NULL, NULL));
    demill_id p = add(w, m, 0, R - DELTA, 0, R);
    eval(w);
    EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, f, F, 0, F);
    EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, arm * f, arm * f);
    EXPECT_W(w, fl, DEMILL_WALL_FORCE, -f, -F, 0, F);
    check_contact_view(w, F, F * arm);
    balance_on_floor(w);
    DM_OK(w, demill_world_step(w, 600));
    const double vf = U * I / (I + m_ * arm * arm);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_VELOCITY, 0), vf, 1e-9);
    DM_ASSERT_REL(dm_test_get(w, p, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), (U - vf) / arm, 1e-9);
    double wp[3];
    DM_OK(w, demill_wall_get(w, fl, DEMILL_WALL_POINT, wp));
    DM_ASSERT_REL(wp[0], U * 600 * dt, 1e-12);
    demill_world_destroy(w);
}
END_TEST

/* 20. A wall rotating about a centre (a piece of a mill drum) carries a
 * particle along and is braked by it.
 *
 * Floor y = 0 rotating with Ω = 10 ẑ rad/s (counter-clockwise) about the
 * centre c = (0, L, 0), L = 0.1 m, which is on the particle's side: the
 * particle at (0, R - δ, 0) lies between the wall and the axis, as a charge
 * inside a drum. Contact point x_c = (0, -δ/2, 0) (half the overlap into the
 * wall). Wall velocity there: Ω ẑ × (x_c - c) = Ω ẑ × (-(L + δ/2) ŷ)
 * = Ω (L + δ/2) x̂ = 1.0005 m/s: the bottom of a counter-clockwise drum moves
 * towards +x (the rising side). Friction on the particle +μ k δ x̂:
 * F = (2.5, 5, 0) N; T = (-a ŷ) × (μ k δ x̂) = +a μ k δ ẑ, the particle turns
 * the same way as the drum. The wall receives F_w = (-2.5, -5, 0) N and,
 * about its centre, T_w = (x_c - c) × F_w = -(L + δ/2) ŷ × (-μ k δ x̂)
 * = -(L + δ/2) μ k δ ẑ = -0.250125 ẑ N m: it opposes Ω, so the drive must
 * supply power T·Ω > 0 (the mill's torque sign). */
START_TEST(rotating_wall_drum)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2, L = 0.1, Om = 10.0;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id fl = floor_wall(w, m);
    DM_OK(w, demill_wall_set_motion(w, fl, NULL, (double[3]){0, 0, Om}, (double[3]){0, L, 0}));
    demill_id p = add(w, m, 0, R - DELTA, 0, R);
    eval(w);
    EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, f, F, 0, F);
    EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, arm * f, arm * f);
    EXPECT_W(w, fl, DEMILL_WALL_FORCE, -f, -F, 0, F);
    EXPECT_W(w, fl, DEMILL_WALL_TORQUE, 0, 0, -(L + DELTA / 2) * f, L * F);
    EXPECT_C(w, 0, DEMILL_CONTACT_POINT, 0, -DELTA / 2, 0, R);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 21. 3D: a turntable (floor rotating about its own normal).
 *
 * Floor y = 0 rotating with Ω = 10 ŷ about the origin; particle at rest at
 * (L, R - δ, 0), L = 0.1 m; contact point x_c = (L, -δ/2, 0). Wall velocity
 * there Ω ŷ × x_c = Ω L (ŷ × x̂) = -Ω L ẑ (1 m/s): friction on the particle
 * -μ k δ ẑ (carried round with the table): F = (0, 5, -2.5) N;
 * T = (-a ŷ) × (-μ k δ ẑ) = a μ k δ (ŷ × ẑ) = +a μ k δ x̂, turning the
 * particle's bottom towards -z with the table. The plane itself does not
 * move. The wall receives F_w = (0, -k δ, μ k δ) and, about the origin,
 * T_w = x_c × F_w = (-δ/2 · μ k δ, -L μ k δ, -L k δ): its y component
 * -0.25 N m opposes Ω. */
START_TEST(turntable_3d)
{
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2, L = 0.1, Om = 10.0;
    demill_id m;
    demill_world *w = scene(3, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id fl = floor_wall(w, m);
    DM_OK(w, demill_wall_set_motion(w, fl, NULL, (double[3]){0, Om, 0}, (double[3]){0, 0, 0}));
    demill_id p = add(w, m, L, R - DELTA, 0, R);
    eval(w);
    EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, F, -f, F);
    EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, arm * f, 0, 0, arm * f);
    EXPECT_W(w, fl, DEMILL_WALL_FORCE, 0, -F, f, F);
    EXPECT_W(w, fl, DEMILL_WALL_TORQUE, -DELTA / 2 * f, -L * f, -L * F, L * F);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 22. Unequal radii: torques follow the true lever arms, forces are equal
 * and opposite.
 *
 * R_a = 0.01, R_b = 0.03 m, b at (R_a + R_b - δ) x̂, a spins W0 ẑ, b at rest.
 * v_c = -(R_a - δ/2) W0 ŷ (0.995 m/s; m* = m_a m_b/(m_a + m_b) = 27/28 m_a,
 * γ = √(m* k) = 22.5 N s/m, saturated). As in test 7:
 * F_a = (-k δ, -μ k δ, 0) = -F_b, so F_a + F_b = 0 (no gravity).
 * T_a = -(R_a - δ/2) μ k δ ẑ = -2.4875e-2 ẑ N m,
 * T_b = -(R_b - δ/2) μ k δ ẑ = -7.4875e-2 ẑ N m: the ratio is
 * (R_b - δ/2)/(R_a - δ/2) = 3.0101, not 1 as an R* lever arm for both
 * bodies (rejected in docs/physics.md §4) would give.
 * Contact point: x_a + (R_a - δ/2) x̂. */
START_TEST(unequal_radii_lever_arms)
{
    const int dim = _i;
    const double ra = 0.01, rb = 0.03, F = KN * DELTA, f = MU * F;
    const double arma = ra - DELTA / 2, armb = rb - DELTA / 2;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, ra);
    demill_id b = add(w, m, ra + rb - DELTA, 0, 0, rb);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, -f, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, f, 0, F);
    double fa[3], fb[3];
    DM_OK(w, demill_particle_get(w, a, DEMILL_PARTICLE_FORCE, fa));
    DM_OK(w, demill_particle_get(w, b, DEMILL_PARTICLE_FORCE, fb));
    expect_vec("F_a + F_b", (double[3]){fa[0] + fb[0], fa[1] + fb[1], fa[2] + fb[2]}, 0, 0, 0, F,
               TOL);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, -arma * f, armb * f);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -armb * f, armb * f);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_TORQUE, 2) /
                      dm_test_get(w, a, DEMILL_PARTICLE_TORQUE, 2),
                  armb / arma, TOL);
    EXPECT_C(w, 0, DEMILL_CONTACT_POINT, arma, 0, 0, rb);
    check_contact_view(w, F, F * rb);
    demill_world_destroy(w);
}
END_TEST

/* 23. Oblique contact along the diagonal n = (1, 1, 0)/√2.
 *
 * a at the origin spinning W0 ẑ, b at (2R - δ) n at rest. Normal pair along
 * n: -k δ n on a. a's surface at the contact moves ω_a × a n = W0 a t with
 * t = ẑ × n = (-1, 1, 0)/√2 (saturated), so friction on a is -μ k δ t, on b
 * +μ k δ t:
 *   F_a = -k δ n - μ k δ t = (k δ/√2)(-1 + μ, -1 - μ, 0) = (-1.7678, -5.3033, 0) N,
 *   F_b = -F_a.
 * T_a = a n × (-μ k δ t) = -a μ k δ (n × t) = -a μ k δ ẑ (n × t = ẑ), and
 * T_b = (-a n) × (μ k δ t) = -a μ k δ ẑ: the gear of test 7, rotated by 45°.
 * Contact view: normal n, point a n. */
START_TEST(oblique_contact_diagonal)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2, s = 1 / sqrt(2.0);
    const double d = (2 * R - DELTA) * s;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, d, d, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, (-F + f) * s, (-F - f) * s, 0, F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, (F - f) * s, (F + f) * s, 0, F);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    demill_id ca;
    size_t n;
    DM_OK(w, demill_contacts_read_ids(w, &ca, NULL, 1, &n));
    const double sg = ca == a ? 1.0 : -1.0;
    EXPECT_C(w, 0, DEMILL_CONTACT_NORMAL, sg * s, sg * s, 0, 1);
    EXPECT_C(w, 0, DEMILL_CONTACT_POINT, arm * s, arm * s, 0, R);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 24. 3D: oblique contact along the body diagonal n = (1, 1, 1)/√3.
 *
 * a at the origin spinning W0 ẑ, b at (2R - δ) n at rest. a's surface at the
 * contact moves W0 a ẑ × n = W0 a (-1, 1, 0)/√3, magnitude W0 a √(2/3)
 * (0.81 m/s, saturated), direction t = (-1, 1, 0)/√2 (⊥ n). Friction on a
 * -μ k δ t: F_a = -k δ n - μ k δ t, F_b = -F_a.
 * n × t = (-1, -1, 2)/√6, so T_a = a n × (-μ k δ t) = a μ k δ (1, 1, -2)/√6
 * and T_b = (-a n) × (μ k δ t) = the same. Their z parts,
 * -2 a μ k δ/√6 < 0, slow a and counter-spin b; the x, y parts show that the
 * torque is not parallel to the spin when the contact is off its equator. */
START_TEST(oblique_contact_body_diagonal_3d)
{
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    const double s3 = 1 / sqrt(3.0), s2 = 1 / sqrt(2.0), s6 = 1 / sqrt(6.0);
    const double d = (2 * R - DELTA) * s3;
    demill_id m;
    demill_world *w = scene(3, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, d, d, d, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    const double fa[3] = {-F * s3 + f * s2, -F * s3 - f * s2, -F * s3};
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, fa[0], fa[1], fa[2], F);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, -fa[0], -fa[1], -fa[2], F);
    const double tq = arm * f * s6;
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, tq, tq, -2 * tq, arm * f);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, tq, tq, -2 * tq, arm * f);
    EXPECT_C(w, 0, DEMILL_CONTACT_OVERLAP, DELTA, 0, 0, DELTA);
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 25. 3D: a ball spinning about x, y or z against a ball at rest on the x
 * axis (n = x̂).
 * Friction on a is -μ k δ (ê × n) for a spin ω_a = W0 ê, and the torques
 * T_a = T_b = -a μ k δ (ê - (ê·n) n):
 * - ê = x̂ (spin about the line of centres): ê × n = 0, no friction, no
 *   torque, only the normal pair.
 * - ê = ŷ: ŷ × x̂ = -ẑ, friction on a +μ k δ ẑ, on b -μ k δ ẑ;
 *   T_a = a x̂ × μ k δ ẑ = -a μ k δ ŷ, T_b = (-a x̂) × (-μ k δ ẑ) = -a μ k δ ŷ.
 * - ê = ẑ: friction on a -μ k δ ŷ, T_a = T_b = -a μ k δ ẑ (test 7). */
START_TEST(pair_spin_axes_3d)
{
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    for (int axis = 0; axis < 3; axis++) {
        demill_id m;
        demill_world *w = scene(3, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
        demill_id a = add(w, m, 0, 0, 0, R);
        demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
        const double e[3] = {axis == 0, axis == 1, axis == 2};
        set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, W0 * e[0], W0 * e[1], W0 * e[2]);
        eval(w);
        /* friction on a: -f (ê × x̂) = -f (0, e_z, -e_y) */
        EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -F, -f * e[2], f * e[1], F);
        EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, F, f * e[2], -f * e[1], F);
        EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, -arm * f * e[1], -arm * f * e[2], arm * f);
        EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, -arm * f * e[1], -arm * f * e[2], arm * f);
        check_contact_view(w, F, F * arm);
        demill_world_destroy(w);
    }
}
END_TEST

/* 26. Sliding along an oblique wall.
 *
 * Plane through the origin with normal n̂ = (1, 1, 0)/√2 in 2D and
 * (1, 1, 1)/√3 in 3D (passed unnormalised); particle centre at (R - δ) n̂,
 * sliding with v = V t, t = (1, -1, 0)/√2 (in the plane), V = 1 m/s.
 * Normal force +k δ n̂ (away from the wall), friction -μ k δ t (against the
 * motion); the lever arm to the contact is -a n̂, so
 * T = (-a n̂) × (-μ k δ t) = a μ k δ (n̂ × t): 2D n̂ × t = -ẑ, 3D
 * n̂ × t = (1, 1, -2)/√6, in both cases along n̂ × v, the spin of rolling
 * along v on that wall. */
START_TEST(oblique_wall_sliding)
{
    const int dim = _i;
    const double F = KN * DELTA, f = MU * F, arm = R - DELTA / 2;
    const double s = dim == 3 ? 1 / sqrt(3.0) : 1 / sqrt(2.0), s2 = 1 / sqrt(2.0);
    const double nz = dim == 3 ? s : 0.0;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_COULOMB, DEMILL_ROLLING_NONE, &m);
    plane(w, m, 0, 0, 0, 1, 1, dim == 3 ? 1 : 0);
    const double c = R - DELTA;
    demill_id p = add(w, m, c * s, c * s, c * nz, R);
    set3(w, p, DEMILL_PARTICLE_VELOCITY, s2, -s2, 0);
    eval(w);
    EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, F * s - f * s2, F * s + f * s2, F * nz, F);
    if (dim == 2) {
        EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -arm * f, arm * f);
    } else {
        const double s6 = 1 / sqrt(6.0);
        EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, arm * f * s6, arm * f * s6, -2 * arm * f * s6,
                 arm * f);
    }
    check_contact_view(w, F, F * arm);
    demill_world_destroy(w);
}
END_TEST

/* 27. Gravity pulls a particle onto a floor; at rest the contact force
 * balances m g.
 *
 * Gravity (0, -9.81, 0), damping from restitution e = 0.1 (clamped default),
 * particle released at rest just touching the floor (centre at y = R). It
 * settles where the contact force equals its weight m g = 0.102731 N:
 * linear: δ = m g/k = 2.0546e-6 m; Hertz: 4/3 E* √R δ^{3/2} = m g,
 * δ = (3 m g/(4 E* √R))^{2/3} with E* = E/(2 (1 - ν²)) = 5.4945e7 Pa.
 * The contact's normal force on the particle is +m g ŷ, the total force is
 * zero and the wall carries -m g ŷ. Damping ratio ξ ≈ 0.6 at natural
 * frequencies of 1600-2200 rad/s: after 40 ms the oscillation has decayed by
 * e^-38 or more, so all this is checked to 1e-9 (of m g, or of δ). */
START_TEST(gravity_settles_on_floor)
{
    const int dim = _i;
    const double g = 9.81, mg = sphere_mass(R) * g;
    for (int law = 0; law < 2; law++) {
        demill_id m;
        demill_world *w = dm_test_world(dim, law ? DEMILL_NORMAL_HERTZ : DEMILL_NORMAL_LINEAR,
                                        DEMILL_DAMPING_RESTITUTION, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.1));
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -g));
        demill_id fl = floor_wall(w, m);
        demill_id p = add(w, m, 0, R, 0, R);
        DM_OK(w, demill_world_step(w, 4000));
        const double estar = 1e8 / (2 * (1 - 0.3 * 0.3));
        const double deq = law ? pow(3 * mg / (4 * estar * sqrt(R)), 2.0 / 3.0) : mg / KN;
        double f[3], fn[3], fw[3], d[3];
        DM_OK(w, demill_particle_get(w, p, DEMILL_PARTICLE_FORCE, f));
        expect_vec("total force at rest", f, 0, 0, 0, mg, 1e-9);
        ck_assert_uint_eq(contact_count(w), 1);
        contact_get(w, DEMILL_CONTACT_NORMAL_FORCE, 0, fn);
        expect_vec("contact normal force", fn, 0, mg, 0, mg, 1e-9);
        contact_get(w, DEMILL_CONTACT_OVERLAP, 0, d);
        DM_ASSERT_REL(d[0], deq, 1e-9);
        DM_OK(w, demill_wall_get(w, fl, DEMILL_WALL_FORCE, fw));
        expect_vec("wall force", fw, 0, -mg, 0, mg, 1e-9);
        demill_world_destroy(w);
    }
}
END_TEST

/* 28. Spring-slider, particle on a wall: the first step's tangential force
 * is k_t v_t Δt against the slip.
 *
 * Linear spring-slider (k_t = 2/7 k = 14285.7 N/m, default ratio), no
 * damping (so no tangential dashpot), floor, particle at (0, R - δ, 0)
 * moving at v = V x̂ (V = 0.1 m/s), ω = 0, no gravity. At the start the
 * spring is unstretched: no tangential force, no torque, so the half-step
 * velocity is still V x̂ and the spin 0. Over one step Δt = 1e-5 s the contact
 * slides by V Δt, so the force on the particle is -k_t V Δt x̂
 * = -1.42857e-2 N (well below μ k δ). Torque r × F with r = -a' ŷ,
 * a' = R - δ'/2 (δ' the overlap after the step, read from the position):
 * (-a' ŷ) × (-k_t V Δt x̂) = -a' k_t V Δt ẑ (rolling sense, as in test 11).
 * 3D also slides along z: force -k_t V Δt ẑ, torque
 * (-a' ŷ) × (-k_t V Δt ẑ) = +a' k_t V Δt x̂. */
START_TEST(spring_slider_first_step_on_wall)
{
    const int dim = _i;
    const double dt = 1e-5, V = 0.1, kt = 2.0 / 7.0 * KN, ft = kt * V * dt;
    for (int dir = 0; dir < (dim == 3 ? 2 : 1); dir++) {
        demill_id m;
        demill_world *w = scene(dim, DEMILL_TANGENTIAL_SPRING, DEMILL_ROLLING_NONE, &m);
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
        floor_wall(w, m);
        demill_id p = add(w, m, 0, R - DELTA, 0, R);
        set3(w, p, DEMILL_PARTICLE_VELOCITY, dir ? 0 : V, 0, dir ? V : 0);
        eval(w);
        EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, KN * DELTA, 0, KN * DELTA);
        EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, 0, R * ft);
        DM_OK(w, demill_world_step(w, 1));
        const double d1 = R - dm_test_get(w, p, DEMILL_PARTICLE_POSITION, 1), a1 = R - d1 / 2;
        if (dir == 0) {
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, -ft, KN * d1, 0, KN * DELTA);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, 0, 0, -a1 * ft, R * ft);
        } else {
            EXPECT_P(w, p, DEMILL_PARTICLE_FORCE, 0, KN * d1, -ft, KN * DELTA);
            EXPECT_P(w, p, DEMILL_PARTICLE_TORQUE, a1 * ft, 0, 0, R * ft);
        }
        demill_world_destroy(w);
    }
}
END_TEST

/* 29. Spring-slider between two balls: the first step.
 *
 * As test 7 (a spins W0 ẑ, b at rest at (2R - δ) x̂) with the linear
 * spring-slider instead of Coulomb. At the start the spring is unstretched:
 * only the normal pair acts, no torque, so a's half-step spin is still W0
 * and the tangential velocities are still 0. During the step the contact
 * slides by v_c Δt = -a' W0 Δt ŷ (a' = R - δ'/2, δ' the overlap after the
 * step, from the positions), so the spring force on b is
 * -k_t ξ = +k_t a' W0 Δt ŷ (0.142 N, below μ k δ), on a the opposite, and
 * T_a = T_b = -a' k_t a' W0 Δt ẑ (the gear directions of test 7). */
START_TEST(spring_slider_first_step_pair)
{
    const int dim = _i;
    const double dt = 1e-5, kt = 2.0 / 7.0 * KN;
    demill_id m;
    demill_world *w = scene(dim, DEMILL_TANGENTIAL_SPRING, DEMILL_ROLLING_NONE, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    demill_id a = add(w, m, 0, 0, 0, R);
    demill_id b = add(w, m, 2 * R - DELTA, 0, 0, R);
    set3(w, a, DEMILL_PARTICLE_ANGULAR_VELOCITY, 0, 0, W0);
    eval(w);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, 0, KN * DELTA * R);
    DM_OK(w, demill_world_step(w, 1));
    const double d1 = 2 * R - (dm_test_get(w, b, DEMILL_PARTICLE_POSITION, 0) -
                               dm_test_get(w, a, DEMILL_PARTICLE_POSITION, 0));
    const double a1 = R - d1 / 2, ft = kt * a1 * W0 * dt;
    EXPECT_P(w, a, DEMILL_PARTICLE_FORCE, -KN * d1, -ft, 0, KN * DELTA);
    EXPECT_P(w, b, DEMILL_PARTICLE_FORCE, KN * d1, ft, 0, KN * DELTA);
    EXPECT_P(w, a, DEMILL_PARTICLE_TORQUE, 0, 0, -a1 * ft, R * ft);
    EXPECT_P(w, b, DEMILL_PARTICLE_TORQUE, 0, 0, -a1 * ft, R * ft);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("directions");
    TCase *tc = tcase_create("two_body");
    /* loop tests run with _i = 2 (2D world) and _i = 3 (3D world) */
    tcase_add_loop_test(tc, head_on_repulsion, 2, 4);
    tcase_add_loop_test(tc, hertz_unequal_head_on, 2, 4);
    tcase_add_loop_test(tc, approach_damping_adds_repulsion, 2, 4);
    tcase_add_loop_test(tc, receding_damping_reduces_repulsion, 2, 4);
    tcase_add_loop_test(tc, receding_clamped_never_pulls, 2, 4);
    tcase_add_loop_test(tc, receding_unclamped_pulls, 2, 4);
    tcase_add_loop_test(tc, spinning_drives_partner_like_gear, 2, 4);
    tcase_add_loop_test(tc, gear_steps, 2, 4);
    tcase_add_loop_test(tc, same_spin_slides, 2, 4);
    tcase_add_loop_test(tc, opposite_spin_rolls, 2, 4);
    tcase_add_loop_test(tc, sliding_on_floor, 2, 4);
    tcase_add_loop_test(tc, sliding_spins_up_then_rolls, 2, 4);
    tcase_add_loop_test(tc, spinning_on_floor_starts_to_roll, 2, 4);
    tcase_add_test(tc, floor_spin_axes_3d);
    tcase_add_loop_test(tc, rolling_without_slip_no_friction, 2, 4);
    tcase_add_loop_test(tc, rolling_resistance_on_floor, 2, 4);
    tcase_add_loop_test(tc, rolling_resistance_between_balls, 2, 4);
    tcase_add_test(tc, rolling_resistance_oblique_axis_3d);
    tcase_add_loop_test(tc, moving_wall_drags_particle, 2, 4);
    tcase_add_loop_test(tc, rotating_wall_drum, 2, 4);
    tcase_add_test(tc, turntable_3d);
    tcase_add_loop_test(tc, unequal_radii_lever_arms, 2, 4);
    tcase_add_loop_test(tc, oblique_contact_diagonal, 2, 4);
    tcase_add_test(tc, oblique_contact_body_diagonal_3d);
    tcase_add_test(tc, pair_spin_axes_3d);
    tcase_add_loop_test(tc, oblique_wall_sliding, 2, 4);
    tcase_add_loop_test(tc, gravity_settles_on_floor, 2, 4);
    tcase_add_loop_test(tc, spring_slider_first_step_on_wall, 2, 4);
    tcase_add_loop_test(tc, spring_slider_first_step_pair, 2, 4);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
