/* rolling_spring.c: the elastic-plastic spring-dashpot rolling resistance,
 * DEMILL_ROLLING_SPRING (type C of Ai, Chen, Rotter and Ooi 2011,
 * "Assessment of rolling resistance models in discrete element
 * simulations"; docs/physics.md, Rolling spring-dashpot).
 *
 * A ball of radius R, mass m and moment of inertia I = k m R² (k = 2/5 for
 * a sphere, 1/2 for a disc) on a floor tilted by β (gravity turned by β),
 * rolling without slip: its contact point sits at the lever arm a = R - δ/2
 * below its centre (δ = m g cos β / k_n, the static overlap of the linear
 * contact), so v = a ω, and
 *     m dv/dt = m g sin β - F_t,   I dω/dt = a F_t - M_r.
 * Once the rolling spring is fully mobilised its torque is the limit
 * M_r = μ_r R F_n = μ_r R m g cos β (R* = R against a wall) and the dashpot
 * is off (Ai et al.'s rule), so the ball accelerates at
 *     dv/dt = g (sin β - μ_r cos β R/a) / (1 + I/(m a²)),
 * the constant-torque model's rate (to 1e-6; velocity Verlet integrates a
 * constant acceleration exactly, and the measured one is within 3e-13 of
 * it); it rolls only if the limit is below
 * the torque needed to hold it, m g sin β a ≥ μ_r R m g cos β, i.e. for
 * tan β above μ_r (R/a = 1 + 1e-4 here). Below that the spring holds the
 * ball: after it has settled it moves less than 1e-9 m in 1 s, where the
 * constant-torque model, regularised near ω = 0, creeps (by 1e-4 m here).
 *
 * Rocking: on a level floor, turned by θ and displaced by x, the ball feels
 * the tangential spring k_t on the slip s = x + a θ of its contact point
 * and the rolling spring k_r on θ:
 *     m x'' = -k_t (x + a θ),   I θ'' = -a k_t (x + a θ) - k_r θ,
 * whose slow mode (the rocking) has ω² the smaller root of
 *     m I ω⁴ - (m (k_t a² + k_r) + I k_t) ω² + k_t k_r = 0
 * (ω² -> k_r/(I + m a²) for a rigid tangential spring) and x = -k_t a θ /
 * (k_t - m ω²): started in that mode the ball rocks at that period, within
 * 1e-4 (2e-6 measured), with Ai et al.'s default k_r = 2.25 k_n μ_r² R*²
 * and with a k_r set for the pair.
 *
 * Energy: in a box of colliding, rolling particles the balance closes to
 * 1e-3 of the energy that went through (1e-4 measured; 2D and 3D), the
 * spring's energy is in DEMILL_ENERGY_ELASTIC_ROLLING, the dashpot's loss in
 * DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS and the spring's slip in
 * DEMILL_ENERGY_DISSIPATED_ROLLING; the dashpot's term is 0 when its ratio
 * η_r is 0, and every rolling term is 0 with the constant-torque law (or
 * none). A checkpoint and a snapshot carry the springs: their copies run on
 * to the same bits.
 *
 * The ball's cases run with velocity Verlet and with the iterative
 * refinement, to the same tolerances.
 */
#include <math.h>
#include <stdlib.h>

#include "testutil.h"

#define G 9.81
#define R 0.01

/* The integrator of the ball's tests: velocity Verlet (loop index 0) or the
 * iterative refinement (1), whose iterates must advance the rolling spring
 * once per step, as the tangential one. */
static int integrator(int i)
{
    return i ? DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT : DEMILL_INTEGRATOR_VELOCITY_VERLET;
}

typedef struct ramp {
    demill_world *w;
    demill_id mat, ball;
    double m, kn, a; /* mass, normal stiffness, lever arm R - δ/2 */
} ramp;

/* A ball of radius R on the floor y = 0 under gravity turned by beta about
 * z (so that the floor is an incline), settled for `settle` steps of 2e-5 s;
 * disc: a 2D disc of thickness R; rolling: the law with μ_r = 0.1 and the
 * given dashpot ratio; friction 1 (no slip). */
static ramp ramp_make(int i, int dim, int disc, int rolling, double beta, double eta,
                      int settle)
{
    ramp s = {0};
    ck_assert_int_eq(demill_world_create(dim, &s.w), DEMILL_OK);
    demill_world *w = s.w;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator(i)));
    if (disc)
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, R));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_X, G * sin(beta)));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -G * cos(beta)));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-5));
    DM_OK(w, demill_material_create(w, &s.mat));
    const demill_id m = s.mat;
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_FRICTION, 1.0));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, rolling));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, 0.1));
    if (rolling == DEMILL_ROLLING_SPRING)
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_DAMPING_RATIO, eta));
    double p[3] = {0, 0, 0}, n[3] = {0, 1, 0}, x[3] = {0, R, 0}, r = R;
    demill_id floor;
    DM_OK(w, demill_wall_add_plane(w, m, p, n, &floor));
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &s.ball));
    s.m = dm_test_get(w, s.ball, DEMILL_PARTICLE_MASS, 0);
    DM_OK(w, demill_pair_get(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, &s.kn));
    s.a = R - 0.5 * s.m * G * cos(beta) / s.kn;
    DM_OK(w, demill_world_step(w, (uint64_t)settle));
    return s;
}

/* Above the threshold (tan β = 0.3 > μ_r): the acceleration over 0.1 s
 * after 0.05 s of rolling. */
static void rolls(int i, int dim, int disc)
{
    const double beta = atan(0.3), mu_r = 0.1, k = disc ? 0.5 : 0.4;
    ramp s = ramp_make(i, dim, disc, DEMILL_ROLLING_SPRING, beta, 0.3, 2500);
    const double want = G * (sin(beta) - mu_r * cos(beta) * R / s.a) /
                        (1 + k * R * R / (s.a * s.a));
    const double v1 = dm_test_get(s.w, s.ball, DEMILL_PARTICLE_VELOCITY, 0);
    DM_OK(s.w, demill_world_step(s.w, 5000));
    const double v2 = dm_test_get(s.w, s.ball, DEMILL_PARTICLE_VELOCITY, 0);
    DM_ASSERT_REL((v2 - v1) / 0.1, want, 1e-6);
    /* fully mobilised: the spring slips, the dashpot is off */
    ck_assert(dm_test_energy(s.w, DEMILL_ENERGY_DISSIPATED_ROLLING) > 0);
    demill_world_destroy(s.w);
}

START_TEST(incline_rolls_above_threshold)
{
    rolls(_i, 3, 0);
    rolls(_i, 2, 0);
    rolls(_i, 2, 1);
}
END_TEST

/* Below the threshold (tan β = 0.05 < μ_r): how far the ball moves in 1 s
 * after 0.5 s of settling. */
static double creep(int i, int dim, int disc, int rolling)
{
    ramp s = ramp_make(i, dim, disc, rolling, atan(0.05), 0.3, 25000);
    const double x0 = dm_test_get(s.w, s.ball, DEMILL_PARTICLE_POSITION, 0);
    DM_OK(s.w, demill_world_step(s.w, 50000));
    const double moved = fabs(dm_test_get(s.w, s.ball, DEMILL_PARTICLE_POSITION, 0) - x0);
    demill_world_destroy(s.w);
    return moved;
}

START_TEST(incline_holds_below_threshold)
{
    const int dims[3][2] = {{3, 0}, {2, 0}, {2, 1}};
    for (int c = 0; c < 3; c++) {
        const double held = creep(_i, dims[c][0], dims[c][1], DEMILL_ROLLING_SPRING);
        ck_assert_msg(held < 1e-9, "%dD%s: the ball moved %g m in 1 s", dims[c][0],
                      dims[c][1] ? " disc" : "", held);
    }
    const double crept = creep(_i, 3, 0, DEMILL_ROLLING_CONSTANT_TORQUE);
    ck_assert_msg(crept > 1e-6, "the constant torque held the ball too (%g m)", crept);
}
END_TEST

/* The rocking period on a level floor, from the slow mode (see the top);
 * kr: the pair's k_r, 0 for Ai et al.'s default. */
static void rocking(int i, int dim, int disc, double kr_set)
{
    const double mu_r = 0.1, k = disc ? 0.5 : 0.4;
    ramp s = ramp_make(i, dim, disc, DEMILL_ROLLING_SPRING, 0.0, 0.0, 5000);
    demill_world *w = s.w;
    DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR, 0.0));
    if (kr_set > 0)
        DM_OK(w, demill_pair_set(w, s.mat, s.mat, DEMILL_PAIR_ROLLING_STIFFNESS, kr_set));
    double ratio;
    DM_OK(w, demill_pair_get(w, s.mat, s.mat, DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, &ratio));
    const double kt = ratio * s.kn, m = s.m, I = k * m * R * R, a = s.a;
    const double kr = kr_set > 0 ? kr_set : 2.25 * s.kn * mu_r * mu_r * R * R;
    const double b = m * (kt * a * a + kr) + I * kt;
    const double om2 = (b - sqrt(b * b - 4 * m * I * kt * kr)) / (2 * m * I);
    const double period = 2 * M_PI / sqrt(om2), w0 = 0.02;
    double v[3] = {-kt * a / (kt - m * om2) * w0, 0, 0}, spin[3] = {0, 0, w0};
    /* x' = v, θ' = ω_z (ω_z > 0 turns the contact point, below, towards
     * +x: s' = x' + a θ') */
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_VELOCITY, v));
    DM_OK(w, demill_particle_set(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    double dt, prev = w0, t = 0, first = -1, last = -1;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    int crossings = 0;
    for (int q = 0; q < (int)(5.2 * period / dt); q++) {
        DM_OK(w, demill_world_step(w, 1));
        t += dt;
        const double now = dm_test_get(w, s.ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2);
        if ((prev > 0) != (now > 0)) { /* a zero crossing, interpolated */
            const double tc = t - dt * now / (now - prev);
            if (first < 0)
                first = tc;
            last = tc;
            crossings++;
        }
        prev = now;
    }
    ck_assert_msg(crossings >= 9, "%d crossings", crossings);
    DM_ASSERT_REL(2 * (last - first) / (crossings - 1), period, 1e-4);
    /* below mobilisation: no slip, so no rolling friction */
    ck_assert(dm_test_energy(w, DEMILL_ENERGY_ELASTIC_ROLLING) >= 0);
    demill_world_destroy(w);
}

START_TEST(rocking_period)
{
    rocking(_i, 3, 0, 0.0);
    rocking(_i, 3, 0, 0.05);
    rocking(_i, 2, 0, 0.0);
    rocking(_i, 2, 1, 0.0);
}
END_TEST

/* A box of plane walls with particles of radius 4-6 mm thrown about at up
 * to 1 m/s under gravity, linear contacts with restitution damping,
 * tangential springs and the given rolling law (μ_r 0.1, dashpot ratio
 * eta), 100 steps per contact time. */
static demill_world *box(int dim, int rolling, double eta)
{
    demill_world *w;
    demill_id m, wall;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, rolling));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, 0.1));
    if (rolling == DEMILL_ROLLING_SPRING)
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_DAMPING_RATIO, eta));
    const double L = 0.08;
    for (int c = 0; c < dim; c++)
        for (int side = 0; side < 2; side++) {
            double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            p[c] = side ? L : 0;
            n[c] = side ? -1 : 1;
            DM_OK(w, demill_wall_add_plane(w, m, p, n, &wall));
        }
    enum { N = 60 };
    const int n = dim == 3 ? N : 36; /* 6 x 3 x 4 less 12, or 6 x 6 */
    double x[3 * N], v[3 * N], r[N];
    srand(777);
    for (int i = 0; i < n; i++) {
        const int ijk[3] = {i % 6, dim == 3 ? i / 6 % 3 : i / 6, dim == 3 ? i / 18 : 0};
        for (int c = 0; c < 3; c++) {
            x[3 * i + c] = c < dim ? 0.008 + 0.013 * ijk[c] : 0.0;
            v[3 * i + c] = c < dim ? 2.0 * rand() / RAND_MAX - 1.0 : 0.0;
        }
        r[i] = 0.004 + 0.002 * rand() / (double)RAND_MAX;
    }
    DM_OK(w, demill_particles_add(w, m, (size_t)n, x, r, v, DEMILL_ADD_NO_OVERLAP, NULL));
    /* contact time π √(m* / k) of the smallest pair, 1.5e-4 s */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1.5e-6));
    return w;
}

static void balance(int dim)
{
    demill_world *w = box(dim, DEMILL_ROLLING_SPRING, 0.3);
    const double b0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double p0 = dm_test_energy(w, DEMILL_ENERGY_POTENTIAL);
    const double in = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL);
    double worst = 0, through = in;
    for (int s = 0; s < 40; s++) {
        DM_OK(w, demill_world_step(w, 2000));
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - b0));
        through = fmax(through, in + p0 - dm_test_energy(w, DEMILL_ENERGY_POTENTIAL));
    }
    const double viscous = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS);
    const double slip = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_ROLLING);
    ck_assert_msg(viscous > 0 && slip > 0, "%dD: rolling dashpot %g J, slip %g J", dim, viscous,
                  slip);
    ck_assert_msg(worst <= 1e-3 * through, "%dD: balance off by %.3g of %g J", dim,
                  worst / through, through);
    demill_world_destroy(w);
}

START_TEST(energy_balance)
{
    balance(2);
    balance(3);
}
END_TEST

/* Each rolling term is 0 when its law is off. */
START_TEST(terms_zero_when_off)
{
    struct {
        int rolling;
        double eta;
    } cases[3] = {{DEMILL_ROLLING_SPRING, 0.0},
                  {DEMILL_ROLLING_CONSTANT_TORQUE, 0.3},
                  {DEMILL_ROLLING_NONE, 0.3}};
    for (int c = 0; c < 3; c++) {
        demill_world *w = box(3, cases[c].rolling, cases[c].eta);
        DM_OK(w, demill_world_step(w, 20000));
        ck_assert_double_eq(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS), 0.0);
        if (cases[c].rolling != DEMILL_ROLLING_SPRING)
            ck_assert_double_eq(dm_test_energy(w, DEMILL_ENERGY_ELASTIC_ROLLING), 0.0);
        if (cases[c].rolling == DEMILL_ROLLING_NONE)
            ck_assert_double_eq(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_ROLLING), 0.0);
        demill_world_destroy(w);
    }
}
END_TEST

/* Two balls held on the incline, the lower one pressed by the upper (a
 * particle-particle and two particle-wall springs loaded), and the box. */
START_TEST(checkpoint_and_snapshot)
{
    ramp s = ramp_make(0, 3, 0, DEMILL_ROLLING_SPRING, atan(0.05), 0.3, 0);
    double x[3] = {2 * R, R, 0}, r = R;
    DM_OK(s.w, demill_particles_add(s.w, s.mat, 1, x, &r, NULL, 0, NULL));
    DM_OK(s.w, demill_world_step(s.w, 10000));
    ck_assert(dm_test_energy(s.w, DEMILL_ENERGY_ELASTIC_ROLLING) > 0);
    dm_test_copies_run_on(s.w, 3000, NULL, NULL);
    demill_world_destroy(s.w);
    demill_world *w = box(3, DEMILL_ROLLING_SPRING, 0.3);
    DM_OK(w, demill_world_step(w, 3000));
    dm_test_copies_run_on(w, 3000, NULL, NULL);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("rolling_spring");
    TCase *tc = tcase_create("ball");
    tcase_add_loop_test(tc, incline_rolls_above_threshold, 0, 2);
    tcase_add_loop_test(tc, incline_holds_below_threshold, 0, 2);
    tcase_add_loop_test(tc, rocking_period, 0, 2);
    suite_add_tcase(s, tc);
    TCase *bx = tcase_create("box");
    tcase_add_test(bx, energy_balance);
    tcase_add_test(bx, terms_zero_when_off);
    tcase_add_test(bx, checkpoint_and_snapshot);
    suite_add_tcase(s, bx);
    return dm_test_run(s);
}
