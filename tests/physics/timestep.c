/* timestep.c: demill_world_suggest_time_step() against numbers derived by
 * hand from the rule in demill/world.h (docs/physics.md §8), and against a
 * collision run at the step it suggests.
 *
 * The expected numbers are computed here from the definitions only: masses
 * 4/3 π r³ ρ (π r² t ρ for discs), series stiffness k_a k_b/(k_a + k_b),
 * E* = 1/((1-ν_a²)/E_a + (1-ν_b²)/E_b), m* and R* of the pair (a wall:
 * m* = m, R* = r); the comments give them rounded and say which pair of the
 * scene has the shortest contact.
 *  - Linear law: ω = √(k_n/m*), contact π/ω, stability limit
 *    (2/ω)(√(1 + 4ξ²) − 2ξ) (the central difference method's limit with
 *    twice the damping ratio, demill/world.h), suggested
 *    min(contact/steps, 0.2 · limit); equal to 1e-12 relative. The pairs
 *    are unclamped, so that the damping ratio of restitution e has the
 *    closed form ξ = −ln e/√(π² + ln² e).
 *  - Hertz law: contact 2.87 (m*²/(R* E*² v))^(1/5) (Johnson §11.4, the
 *    2.94324 δ_max/v of collision.c with δ_max written out), stability limit
 *    from S = 2 E* √(R* δ_max) with the Tsuji dashpot's ratio √(5/6) ξ, and
 *    0.2 of the Rayleigh time π R √(ρ/G)/(0.1631 ν + 0.8766),
 *    G = E/(2(1+ν)).
 *  - The other modes of a contact: a tangential spring k_t moves the
 *    contact points against m_t = 2/7 m* (the spheres' spins take part:
 *    1/m_t = 1/m_a + 1/m_b + R_a²/I_a + R_b²/I_b), ω_t = √(k_t/m_t); the
 *    regularised Coulomb law is a dashpot √(m* k_n) on m_t, limit
 *    m_t/√(m* k_n).
 *  - Restitution 0: critical damping (ξ = 1) unclamped; clamped, no time
 *    step integrates it, which the call says.
 *  - A head-on collision of two equal spheres run at the suggested step (50
 *    steps per contact) rebounds with the set restitution within 1 %,
 *    measured as in collision.c over 8 entry phases (worst measured: 0.54 %
 *    at e = 0.1, 0.16 % at e = 0.5, 0.03 % at e = 0.9).
 *  - impact_speed = 0: the documented estimate max(1 m/s, 2 |v|_max,
 *    √(2 g H), 2 × rim speed at the drum's target speed), checked by equality
 *    with a call given that speed.
 *  - Bad arguments give their documented codes with a message naming the
 *    argument, write nothing, and a successful call changes no result.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define REL 1e-12
#define G 9.81

typedef struct suggestion {
    double dt, critical, contact;
} suggestion;

static suggestion suggest(demill_world *w, double v, double steps)
{
    suggestion s = {0, 0, 0};
    DM_OK(w, demill_world_suggest_time_step(w, v, steps, &s.dt, &s.critical, &s.contact));
    return s;
}

static void assert_suggestion(suggestion got, suggestion want)
{
    DM_ASSERT_REL(got.dt, want.dt, REL);
    DM_ASSERT_REL(got.critical, want.critical, REL);
    DM_ASSERT_REL(got.contact, want.contact, REL);
}

static double sphere_mass(double r, double rho)
{
    return 4.0 / 3.0 * M_PI * r * r * r * rho;
}

static demill_id add(demill_world *w, demill_id mat, double x, double y, double z, double r)
{
    const double p[3] = {x, y, z};
    demill_id id;
    DM_OK(w, demill_particles_add(w, mat, 1, p, &r, NULL, 0, &id));
    return id;
}

/* The pair (a, b): `normal` law, unclamped restitution damping. */
static void set_law(demill_world *w, demill_id a, demill_id b, int normal)
{
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_NORMAL, normal));
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, a, b, DEMILL_PAIR_CLAMP_NORMAL, 0));
}

/* A world without gravity with one material whose pair has the `normal`
 * law, unclamped (set_law). */
static demill_world *world(int dim, int normal, demill_id *m)
{
    demill_world *w = dm_test_world(dim, normal, DEMILL_DAMPING_RESTITUTION, m);
    set_law(w, *m, *m, normal);
    return w;
}

/* The unclamped damping ratio of restitution e. */
static double xi_of(double e)
{
    return -log(e) / sqrt(M_PI * M_PI + log(e) * log(e));
}

/* The stability limit of a mode ω with damping ratio ξ. */
static double limit(double omega, double xi)
{
    return 2.0 / omega * (sqrt(1.0 + 4.0 * xi * xi) - 2.0 * xi);
}

#define XI_HALF xi_of(0.5) /* the default restitution's: 0.2155 */

/* ---- linear law ------------------------------------------------------------ */

/* Linear pair of reduced mass m* and stiffness k at `steps` per contact. */
static suggestion linear_expected(double mstar, double k, double steps)
{
    const double omega = sqrt(k / mstar), crit = limit(omega, XI_HALF);
    const suggestion s = {fmin(M_PI / omega / steps, 0.2 * crit), crit, M_PI / omega};
    return s;
}

/* Material A: ρ 2500, k 1e5, particles of radius 4 and 6 mm; material B:
 * ρ 7800, k 2e5, radius 2 and 3 mm; all pairs linear, no gravity. */
static demill_world *linear_scene(demill_id *A, demill_id *B)
{
    demill_world *w = world(3, DEMILL_NORMAL_LINEAR, A);
    DM_OK(w, demill_material_create(w, B));
    DM_OK(w, demill_material_set(w, *B, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, *B, DEMILL_MATERIAL_STIFFNESS, 2e5));
    set_law(w, *B, *B, DEMILL_NORMAL_LINEAR);
    set_law(w, *A, *B, DEMILL_NORMAL_LINEAR);
    add(w, *A, 0.0, 0.0, 0.0, 0.006);
    add(w, *A, 0.1, 0.0, 0.0, 0.004);
    add(w, *B, 0.2, 0.0, 0.0, 0.003);
    add(w, *B, 0.3, 0.0, 0.0, 0.002);
    return w;
}

/* The lightest particles: m_A = 4/3 π (4 mm)³ 2500 = 6.7021e-4 kg,
 * m_B = 4/3 π (2 mm)³ 7800 = 2.6138e-4 kg. Pairs (m*, k, m* / k):
 *   AA 3.3510e-4, 5e4,      6.702e-9
 *   AB 1.8804e-4, 6.6667e4, 2.821e-9
 *   BB 1.3069e-4, 1e5,      1.307e-9  <- shortest: ω = 2.7662e4 /s,
 * contact π/ω = 1.1357e-4 s, limit 0.658 · 2/ω = 4.757e-5 s (ξ = 0.2155),
 * suggested π/(50 ω) = 2.2714e-6 s. At 5 steps per contact π/(5ω) = 0.63/ω
 * exceeds 0.2 · limit = 0.263/ω, which is then taken. Pair AB made as stiff as 1e6 N/m has m* / k = 1.880e-10
 * and becomes the shortest. */
START_TEST(linear_lightest_pair)
{
    demill_id A, B;
    demill_world *w = linear_scene(&A, &B);
    const double mA = sphere_mass(0.004, 2500), mB = sphere_mass(0.002, 7800);
    const double mBB = mB / 2, mAB = mA * mB / (mA + mB);
    assert_suggestion(suggest(w, 1.0, 0), linear_expected(mBB, 1e5, 50));
    assert_suggestion(suggest(w, 1.0, 50), linear_expected(mBB, 1e5, 50));
    assert_suggestion(suggest(w, 7.0, 50), linear_expected(mBB, 1e5, 50)); /* no v in it */
    const suggestion five = suggest(w, 1.0, 5);
    assert_suggestion(five, linear_expected(mBB, 1e5, 5));
    DM_ASSERT_REL(five.dt, 0.2 * five.critical, REL);

    DM_OK(w, demill_pair_set(w, A, B, DEMILL_PAIR_NORMAL_STIFFNESS, 1e6));
    assert_suggestion(suggest(w, 1.0, 0), linear_expected(mAB, 1e6, 50));
    demill_world_destroy(w);
}
END_TEST

/* A plane wall of material C (k 1e3) meets A and B with series stiffness
 * about 990 and 995 N/m and m* = m: m* / k = 6.8e-7 and 2.6e-7, far longer than
 * BB, so the answer stays BB's. Made stiff, pair (B, C) at 1e7 N/m has
 * m* / k = m_B/1e7 = 2.6138e-11 and sets the step: ω = √(1e7/m_B) =
 * 1.9560e5 /s. A drum of material C in place of the plane does the same. */
START_TEST(linear_wall_stiffness)
{
    demill_id A, B, C, plane, drum;
    demill_world *w = linear_scene(&A, &B);
    const suggestion alone = suggest(w, 1.0, 0);
    DM_OK(w, demill_material_create(w, &C));
    DM_OK(w, demill_material_set(w, C, DEMILL_MATERIAL_STIFFNESS, 1e3));
    set_law(w, A, C, DEMILL_NORMAL_LINEAR);
    set_law(w, B, C, DEMILL_NORMAL_LINEAR);
    const double p[3] = {0, -1, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, C, p, n, &plane));
    const suggestion soft = suggest(w, 1.0, 0);
    ck_assert(soft.dt == alone.dt && soft.critical == alone.critical &&
              soft.contact == alone.contact);

    const double mB = sphere_mass(0.002, 7800);
    DM_OK(w, demill_pair_set(w, B, C, DEMILL_PAIR_NORMAL_STIFFNESS, 1e7));
    const suggestion stiff = suggest(w, 1.0, 0);
    assert_suggestion(stiff, linear_expected(mB, 1e7, 50));

    DM_OK(w, demill_wall_remove(w, plane));
    assert_suggestion(suggest(w, 1.0, 0), alone);
    DM_OK(w, demill_drum_create(w, C, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 2.0));
    assert_suggestion(suggest(w, 1.0, 0), stiff);
    demill_world_destroy(w);
}
END_TEST

/* 2D discs of thickness 1 cm: m = π (5 mm)² 0.01 m 2500 = 1.9635e-3 kg,
 * m* = 9.8175e-4 kg, k = 5e4: ω = 7136.5 /s, contact 4.4021e-4 s. */
START_TEST(linear_discs)
{
    demill_id m;
    demill_world *w = world(2, DEMILL_NORMAL_LINEAR, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, 0.01));
    add(w, m, 0, 0, 0, 0.005);
    const double mass = M_PI * 0.005 * 0.005 * 0.01 * 2500;
    assert_suggestion(suggest(w, 1.0, 0), linear_expected(mass / 2, 5e4, 50));
    demill_world_destroy(w);
}
END_TEST

/* ---- Hertz law ----------------------------------------------------------- */

/* Hertz pair of m*, R*, E* at speed v. */
static void hertz_pair(double mstar, double rstar, double estar, double v, double steps,
                       suggestion *s)
{
    const double delta = pow(15 * mstar * v * v / (16 * estar * sqrt(rstar)), 0.4);
    const double omega = sqrt(2 * estar * sqrt(rstar * delta) / mstar);
    s->contact = 2.87 * pow(mstar * mstar / (rstar * estar * estar * v), 0.2);
    s->critical = limit(omega, sqrt(5.0 / 6.0) * XI_HALF);
    s->dt = fmin(s->contact / steps, 0.2 * s->critical);
}

static double rayleigh(double r, double rho, double E, double nu)
{
    return M_PI * r * sqrt(rho / (E / (2 * (1 + nu)))) / (0.1631 * nu + 0.8766);
}

/* One material (E 1e8, ν 0.3, ρ 2500), particles of radius 3 and 5 mm:
 * m* = 1.4137e-4 kg, R* = 1.5 mm, E* = 1e8/(2 · 0.91) = 5.4945e7 Pa.
 * At v = 1 m/s: δ_max = 8.27e-5 m, contact 2.43e-4 s, S = 3.87e4 N/m,
 * limit 0.681 · 2/ω = 8.24e-5 s; 0.2 of the Rayleigh time 8.21e-5 s is 1.64e-5 s,
 * above contact/50 = 4.87e-6 s, which is suggested. At v = 1 mm/s the
 * contact lasts 1000^(1/5) = 3.98 times longer, contact/50 = 1.94e-5 s, and
 * the Rayleigh bound 1.64e-5 s is taken. */
START_TEST(hertz_contact_and_rayleigh)
{
    demill_id m;
    demill_world *w = world(3, DEMILL_NORMAL_HERTZ, &m);
    add(w, m, 0, 0, 0, 0.005);
    add(w, m, 0.1, 0, 0, 0.003);
    const double r = 0.003, mstar = sphere_mass(r, 2500) / 2, estar = 1e8 / (2 * (1 - 0.09));
    const double tr = rayleigh(r, 2500, 1e8, 0.3);
    suggestion want;
    hertz_pair(mstar, r / 2, estar, 1.0, 50, &want);
    ck_assert(want.dt < 0.2 * tr);
    assert_suggestion(suggest(w, 1.0, 0), want);

    hertz_pair(mstar, r / 2, estar, 1e-3, 50, &want);
    ck_assert(0.2 * tr < want.dt);
    want.dt = 0.2 * tr;
    assert_suggestion(suggest(w, 1e-3, 0), want);
    demill_world_destroy(w);
}
END_TEST

/* A nearly rigid wall (E 1e12) against the 3 mm particle: m* = m = 2.8274e-4
 * kg, R* = 3 mm, E* = 1/(0.91/1e8 + 0.91/1e12) = 1.0988e8 Pa, so that
 * m*²/(R* E*²) is half the particle pair's and the contact (2.12e-4 s at
 * 1 m/s) is shorter by 2^(-1/5). */
START_TEST(hertz_stiff_wall)
{
    demill_id m, hard, wall;
    demill_world *w = world(3, DEMILL_NORMAL_HERTZ, &m);
    add(w, m, 0, 0, 0, 0.005);
    add(w, m, 0.1, 0, 0, 0.003);
    DM_OK(w, demill_material_create(w, &hard));
    DM_OK(w, demill_material_set(w, hard, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e12));
    set_law(w, m, hard, DEMILL_NORMAL_HERTZ);
    const double p[3] = {0, -1, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, hard, p, n, &wall));
    const double r = 0.003, mass = sphere_mass(r, 2500);
    const double estar = 1 / (0.91 / 1e8 + 0.91 / 1e12);
    suggestion want, pair;
    hertz_pair(mass, r, estar, 1.0, 50, &want);
    hertz_pair(mass / 2, r / 2, 1e8 / (2 * 0.91), 1.0, 50, &pair);
    ck_assert(want.contact < pair.contact);
    assert_suggestion(suggest(w, 1.0, 0), want);
    demill_world_destroy(w);
}
END_TEST

/* ---- a collision at the suggested step ------------------------------------ */

/* Two equal spheres of radius r, already in the world, set approaching
 * head-on along x at relative speed v0 from a gap that closes after
 * (3 + phase) steps; the rebound ratio as collision.c measures it. */
static double rebound(demill_world *w, const demill_id ids[2], double r, double v0, double dt,
                      double phase)
{
    const double gap = (3.0 + phase) * v0 * dt;
    const double xa[3] = {-r - gap / 2, 0, 0}, xb[3] = {r + gap / 2, 0, 0};
    const double va[3] = {v0 / 2, 0, 0}, vb[3] = {-v0 / 2, 0, 0};
    DM_OK(w, demill_particle_set(w, ids[0], DEMILL_PARTICLE_POSITION, xa));
    DM_OK(w, demill_particle_set(w, ids[1], DEMILL_PARTICLE_POSITION, xb));
    DM_OK(w, demill_particle_set(w, ids[0], DEMILL_PARTICLE_VELOCITY, va));
    DM_OK(w, demill_particle_set(w, ids[1], DEMILL_PARTICLE_VELOCITY, vb));
    double prev = -gap;
    int apart = 0;
    for (int k = 0; k < 100000 && !apart; k++) {
        DM_OK(w, demill_world_step(w, 1));
        const double d = 2 * r - (dm_test_get(w, ids[1], DEMILL_PARTICLE_POSITION, 0) -
                                  dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 0));
        apart = prev > 0 && d <= 0;
        prev = d;
    }
    ck_assert_msg(apart, "the collision did not complete");
    DM_OK(w, demill_world_step(w, 5)); /* separated: velocities are final */
    return (dm_test_get(w, ids[1], DEMILL_PARTICLE_VELOCITY, 0) -
            dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0)) /
           v0;
}

/* Two spheres of material m and radius r, far apart, with restitution e
 * for the pair, and the world's time step set to the one it suggests for
 * impacts at v0, 50 steps per contact; returns that step. */
static double two_at_suggested_step(demill_world *w, demill_id m, double e, double r, double v0,
                                    demill_id ids[2])
{
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, e));
    const double x[6] = {-1, 0, 0, 1, 0, 0}, rr[2] = {r, r};
    DM_OK(w, demill_particles_add(w, m, 2, x, rr, NULL, 0, ids));
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, v0, 50, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    return dt;
}

START_TEST(linear_collision_at_suggested_step)
{
    static const double restitutions[] = {0.1, 0.5, 0.9};
    const double r = 0.005, v0 = 1.0;
    for (int k = 0; k < 3; k++) {
        demill_id m, ids[2];
        demill_world *w = world(3, DEMILL_NORMAL_LINEAR, &m);
        const double dt = two_at_suggested_step(w, m, restitutions[k], r, v0, ids);
        for (int p = 0; p < 8; p++)
            DM_ASSERT_REL(rebound(w, ids, r, v0, dt, (p + 0.5) / 8), restitutions[k], 0.01);
        demill_world_destroy(w);
    }
}
END_TEST

/* ---- damping and the other modes of a contact --------------------------------- */

/* One material (k 5e4, ρ 2500) and one particle of radius 5 mm: m* = m/2 =
 * 6.545e-4 kg, ω = √(k/m*) = 8740 /s. Each case sets the pair's laws and
 * compares the stated limit with the hand-derived one. */
START_TEST(damped_and_tangential_limits)
{
    demill_id m;
    demill_world *w = world(3, DEMILL_NORMAL_LINEAR, &m);
    add(w, m, 0, 0, 0, 0.005);
    const double mstar = sphere_mass(0.005, 2500) / 2, k = 5e4, omega = sqrt(k / mstar);
    const double mt = 2.0 / 7.0 * mstar; /* the contact points' mass with spins */
    /* restitution 0.01, then 0: critical damping */
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.01));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, limit(omega, xi_of(0.01)), REL);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.0));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, limit(omega, 1.0), REL);
    /* viscous c_n = 2: ξ = c_n/(2 √(m* k)) = 0.1563 */
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_VISCOUS));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_VISCOUS_DAMPING, 2.0));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, limit(omega, 2.0 / (2 * sqrt(mstar * k))), REL);
    /* undamped, a tangential spring k_t = 2 k on m_t: ω_t = √7 ω */
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_NONE));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, 2.0));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, 2.0 / sqrt(2 * k / mt), REL);
    /* the regularised Coulomb law: the dashpot √(m* k) on m_t */
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_COULOMB));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, mt / sqrt(mstar * k), REL);
    /* rolling resistance alone: the dashpot R*² √(m* k) on the relative
     * rotation, 1/I_rel = 2/(2/5 m r²), limit I_rel/c_r = 1.6/ω */
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_NONE));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    DM_ASSERT_REL(suggest(w, 1, 0).critical, 1.6 / omega, REL);
    demill_world_destroy(w);
}
END_TEST

/* Restitution 0 with the clamped normal law would need infinite damping:
 * the suggestion and the step both say so, and change nothing. */
START_TEST(restitution_zero_clamped)
{
    demill_id m;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
    add(w, m, 0, 0, 0, 0.005);
    add(w, m, 0.1, 0, 0, 0.005);
    DM_OK(w, demill_material_set(w, m, DEMILL_MATERIAL_RESTITUTION, 0.0));
    double dt = -1;
    ck_assert_int_eq(demill_world_suggest_time_step(w, 1, 0, &dt, NULL, NULL),
                     DEMILL_ERR_UNSTABLE);
    ck_assert(dt == -1);
    ck_assert_msg(strstr(demill_world_last_error(w), "restitution 0") &&
                      strstr(demill_world_last_error(w), "no time step"),
                  "%s", demill_world_last_error(w));
    ck_assert_int_eq(demill_world_step(w, 10), DEMILL_ERR_UNSTABLE);
    ck_assert_msg(strstr(demill_world_last_error(w), "exceeds the largest stable time step"),
                  "%s", demill_world_last_error(w));
    double t;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    ck_assert(t == 0.0);
    demill_world_destroy(w);
}
END_TEST

/* Small restitutions, clamped (the default), at the suggested step are
 * what was asked for, within 0.002 (measured: 1.5e-4 at most). At the step
 * for 50 steps per contact alone, t_c/50 = 0.063/ω, the dashpot of e = 0.001
 * (ξ = 15.8) is beyond its stability limit 0.032/ω: the linear law rebounded
 * faster than it came and Hertz gave e = 0.26 before the limit was known.
 * Unclamped, e = 0 is critical damping: the two spheres stay together. */
START_TEST(small_restitution_at_suggested_step)
{
    static const double restitutions[] = {0.01, 0.001};
    const double r = 0.005, v0 = 1.0;
    for (int normal = DEMILL_NORMAL_LINEAR; normal <= DEMILL_NORMAL_HERTZ; normal++)
        for (int k = 0; k < 2; k++) {
            demill_id m, ids[2];
            demill_world *w = dm_test_world(3, normal, DEMILL_DAMPING_RESTITUTION, &m);
            const double dt = two_at_suggested_step(w, m, restitutions[k], r, v0, ids);
            for (int p = 0; p < 4; p++) {
                const double e = rebound(w, ids, r, v0, dt, (p + 0.5) / 4);
                ck_assert_msg(fabs(e - restitutions[k]) < 0.002, "law %d, e = %g: %g", normal,
                              restitutions[k], e);
            }
            demill_world_destroy(w);
        }
    demill_id m, ids[2];
    demill_world *w = world(3, DEMILL_NORMAL_LINEAR, &m);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.0));
    const double x[6] = {-r - 1e-5, 0, 0, r + 1e-5, 0, 0}, v[6] = {0.5, 0, 0, -0.5, 0, 0};
    const double rr[2] = {r, r};
    DM_OK(w, demill_particles_add(w, m, 2, x, rr, v, 0, ids));
    double dt, contact;
    DM_OK(w, demill_world_suggest_time_step(w, v0, 50, &dt, NULL, &contact));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_world_step(w, (uint64_t)(5 * contact / dt)));
    const double dv = dm_test_get(w, ids[1], DEMILL_PARTICLE_VELOCITY, 0) -
                      dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0);
    const double gap = dm_test_get(w, ids[1], DEMILL_PARTICLE_POSITION, 0) -
                       dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 0) - 2 * r;
    ck_assert_msg(fabs(dv) < 1e-3 * v0 && gap < 0.0, "e = 0: relative speed %g, gap %g", dv,
                  gap);
    demill_world_destroy(w);
}
END_TEST

/* ---- the impact speed estimate --------------------------------------------- */

/* The estimate is the v that, given, yields the same suggestion (Hertz: every
 * number depends on v). */
static void assert_estimate(demill_world *w, double v)
{
    assert_suggestion(suggest(w, 0.0, 0), suggest(w, v, 0));
}

/* Gravity 9.81 m/s² along -y, a particle at rest at y = 0 and one at
 * y = 1 m: √(2 g H) = 4.429 m/s above 2 × 0.5 m/s of the faller; at 5 m/s
 * twice its speed, 10 m/s, is taken; without gravity and motion, 1 m/s. */
START_TEST(estimate_falling_particle)
{
    demill_id m;
    demill_world *w = world(3, DEMILL_NORMAL_HERTZ, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -G));
    add(w, m, 0, 0, 0, 0.003);
    const demill_id faller = add(w, m, 0, 1.0, 0, 0.003);
    const double slow[3] = {0, -0.5, 0}, fast[3] = {3, -4, 0};
    DM_OK(w, demill_particle_set(w, faller, DEMILL_PARTICLE_VELOCITY, slow));
    assert_estimate(w, sqrt(2 * G * 1.0));
    DM_OK(w, demill_particle_set(w, faller, DEMILL_PARTICLE_VELOCITY, fast));
    assert_estimate(w, 10.0);

    const double rest[3] = {0, 0, 0};
    DM_OK(w, demill_particle_set(w, faller, DEMILL_PARTICLE_VELOCITY, rest));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0));
    assert_estimate(w, 1.0);
    demill_world_destroy(w);
}
END_TEST

/* A drum of diameter 0.3 m with two particles at rest near its bottom (a
 * span of 1 cm): the fall through the drum, √(2 g 0.3) = 2.426 m/s; at a
 * target of 120 rpm (reached only after a 10 s ramp) twice the rim speed,
 * ω D = 4π · 0.3 = 3.770 m/s; at 1.4 of critical, ω_c = √(2 g/(D - d)) with
 * d the largest particle diameter 6 mm, 1.4 ω_c D = 3.467 m/s. */
START_TEST(estimate_drum)
{
    demill_id m, drum;
    demill_world *w = world(3, DEMILL_NORMAL_HERTZ, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -G));
    DM_OK(w, demill_drum_create(w, m, &drum));
    add(w, m, 0, -0.14, 0, 0.003);
    add(w, m, 0.05, -0.13, 0, 0.003);
    assert_estimate(w, sqrt(2 * G * 0.3));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_RAMP_TIME, 10));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_RPM, 120));
    assert_estimate(w, 4 * M_PI * 0.3);
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 1.4));
    assert_estimate(w, 1.4 * sqrt(2 * G / (0.3 - 0.006)) * 0.3);
    demill_world_destroy(w);
}
END_TEST

/* ---- errors and side effects ------------------------------------------------ */

/* The call fails with `code`, leaves a message that mentions `needle`, and
 * writes none of its outputs. */
static void assert_fails(demill_world *w, demill_status code, const char *needle, double v,
                         double steps, int null_suggested)
{
    double out[3] = {-1, -1, -1};
    const demill_status s = demill_world_suggest_time_step(
        w, v, steps, null_suggested ? NULL : &out[0], &out[1], &out[2]);
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(s == code, "v %g, steps %g: %d (%s), expected %d", v, steps, (int)s, msg,
                  (int)code);
    ck_assert_msg(strstr(msg, needle), "message \"%s\" does not name %s", msg, needle);
    ck_assert(out[0] == -1 && out[1] == -1 && out[2] == -1);
}

START_TEST(bad_arguments)
{
    double dt;
    ck_assert_int_eq(demill_world_suggest_time_step(NULL, 1, 0, &dt, NULL, NULL),
                     DEMILL_ERR_NULL_POINTER);
    demill_id m, other;
    demill_world *w = world(3, DEMILL_NORMAL_LINEAR, &m);
    assert_fails(w, DEMILL_ERR_INVALID_VALUE, "no particles", 1, 0, 0);
    add(w, m, 0, 0, 0, 0.003);
    assert_fails(w, DEMILL_ERR_NULL_POINTER, "suggested", 1, 0, 1);
    assert_fails(w, DEMILL_ERR_NOT_FINITE, "impact_speed", NAN, 0, 0);
    assert_fails(w, DEMILL_ERR_NOT_FINITE, "impact_speed", INFINITY, 0, 0);
    assert_fails(w, DEMILL_ERR_NOT_FINITE, "steps_per_contact", 1, NAN, 0);
    assert_fails(w, DEMILL_ERR_NOT_FINITE, "steps_per_contact", 1, -INFINITY, 0);
    assert_fails(w, DEMILL_ERR_INVALID_VALUE, "impact_speed", -1e-9, 0, 0);
    assert_fails(w, DEMILL_ERR_INVALID_VALUE, "steps_per_contact", 1, 0.5, 0);
    assert_fails(w, DEMILL_ERR_INVALID_VALUE, "steps_per_contact", 1, -50, 0);

    /* a material with particles and no model with m; then one used by a wall */
    DM_OK(w, demill_material_create(w, &other));
    add(w, other, 0.1, 0, 0, 0.003);
    assert_fails(w, DEMILL_ERR_NO_CONTACT_MODEL, "model", 1, 0, 0);
    set_law(w, m, other, DEMILL_NORMAL_LINEAR);
    set_law(w, other, other, DEMILL_NORMAL_LINEAR);
    demill_id bare, wall;
    DM_OK(w, demill_material_create(w, &bare));
    const double p[3] = {0, -1, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, bare, p, n, &wall));
    assert_fails(w, DEMILL_ERR_NO_CONTACT_MODEL, "particle-wall", 1, 0, 0);

    /* the message stays until a call succeeds, which clears it */
    ck_assert(strstr(demill_world_last_error(w), "particle-wall"));
    DM_OK(w, demill_wall_remove(w, wall));
    DM_OK(w, demill_world_suggest_time_step(w, 1, 0, &dt, NULL, NULL));
    ck_assert_str_eq(demill_world_last_error(w), "");
    ck_assert(dt > 0);
    demill_world_destroy(w);
}
END_TEST

/* Two identical worlds stepped alike, one asked for a suggestion after its
 * contact model changed (so that the query resolves the pair table, and the
 * contact lists start afresh as they would at the next step): their particles
 * stay bitwise equal. */
static demill_world *twin(demill_id *m)
{
    demill_world *w = world(3, DEMILL_NORMAL_HERTZ, m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -G));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    demill_id wall;
    const double p[3] = {0, 0, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, *m, p, n, &wall));
    for (int k = 0; k < 6; k++)
        add(w, *m, 0.007 * k - 0.02, 0.003 + 0.002 * k, 0.001 * k, 0.003);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-6));
    DM_OK(w, demill_world_step(w, 2000));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    return w;
}

START_TEST(changes_nothing)
{
    demill_id ma, mb;
    demill_world *a = twin(&ma), *b = twin(&mb);
    suggest(a, 0, 0);
    DM_OK(a, demill_world_step(a, 2000));
    DM_OK(b, demill_world_step(b, 2000));
    double xa[18], xb[18], va[18], vb[18];
    size_t n;
    DM_OK(a, demill_particles_read(a, DEMILL_PARTICLE_POSITION, xa, 6, &n));
    DM_OK(b, demill_particles_read(b, DEMILL_PARTICLE_POSITION, xb, 6, &n));
    DM_OK(a, demill_particles_read(a, DEMILL_PARTICLE_VELOCITY, va, 6, &n));
    DM_OK(b, demill_particles_read(b, DEMILL_PARTICLE_VELOCITY, vb, 6, &n));
    ck_assert(!memcmp(xa, xb, sizeof xa) && !memcmp(va, vb, sizeof va));
    demill_world_destroy(a);
    demill_world_destroy(b);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("timestep");
    TCase *tc = tcase_create("suggest");
    tcase_add_test(tc, linear_lightest_pair);
    tcase_add_test(tc, linear_wall_stiffness);
    tcase_add_test(tc, linear_discs);
    tcase_add_test(tc, hertz_contact_and_rayleigh);
    tcase_add_test(tc, hertz_stiff_wall);
    tcase_add_test(tc, linear_collision_at_suggested_step);
    tcase_add_test(tc, damped_and_tangential_limits);
    tcase_add_test(tc, restitution_zero_clamped);
    tcase_add_test(tc, small_restitution_at_suggested_step);
    tcase_add_test(tc, estimate_falling_particle);
    tcase_add_test(tc, estimate_drum);
    tcase_add_test(tc, bad_arguments);
    tcase_add_test(tc, changes_nothing);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
