/* local_damping.c: local (non-viscous) damping, DEMILL_MATERIAL_LOCAL_DAMPING
 * (Cundall 1987, "Distinct element models of rock and soil structure";
 * docs/physics.md, Local damping).
 *
 * The oscillator. A ball pressed between two parallel planes (linear
 * undamped contacts of stiffness k, each pressed in by δ0, no gravity) feels
 * -2 k x when displaced by |x| < δ0 along their normal: a mass on a linear
 * spring of stiffness K = 2k. With local damping F_d = -α |F| sign(v) it
 * moves as m x'' = -K x - α K |x| sign(v). Over a quarter cycle in which
 * the ball moves towards the centre (x v < 0) the damping force points along
 * F, m x'' = -K (1 - α) x; over one in which it moves away (x v > 0) it points
 * against F, m x'' = -K (1 + α) x. Each quarter is a quarter of a harmonic
 * oscillation, so the speed at the centre is ω A with ω² = K (1 - α)/m on
 * the way in from amplitude A, and the next amplitude B on the way out
 * follows from the same speed with ω² = K (1 + α)/m:
 *     K (1 - α) A² = K (1 + α) B²,   B/A = √((1 - α)/(1 + α)),
 * a fixed ratio per half cycle, (1 - α)/(1 + α) per cycle, whatever the
 * amplitude (unlike viscous damping's e^{-ξωT}, it does not depend on the
 * time either). The peak speeds, at x = 0, fall by the same ratio. The
 * same holds for a spin: a ball between the planes with tangential springs
 * k_t (no dashpot, friction that never slips) turned by θ feels the torque
 * -2 k_t R² θ and no force, a torsional spring, which local damping of the
 * torque opposes likewise. Both are checked in 2D and 3D, with velocity
 * Verlet and symplectic Euler, for α from 0.05 to 0.7, within 1 % per
 * cycle, and the energy account (kinetic + elastic + dissipated by local
 * damping) stays constant.
 *
 * The pile. Discs dropped into a box come to rest sooner with local damping
 * (α = 0.7) than with contact damping alone (restitution 0.5): fewer steps
 * to bring the kinetic energy below 1e-4 of the potential energy they lost,
 * and the whole account (with friction, rolling and spin) still closes to
 * 1e-3 of that energy.
 *
 * The iterative refinement does not integrate local damping: stepping with
 * it is refused with a message naming the key. A checkpoint and a snapshot
 * carry α and the energy it took: their copies run on to the same bits.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define R 0.01      /* the ball's radius, m */
#define DELTA0 1e-3 /* each plane's preload overlap, m */
#define STEPS 4000  /* steps per period */

/* A ball between the planes x = ±(R - δ0) in a world of dimension dim
 * without gravity, linear undamped contacts (the default pair stiffness,
 * k = 5e4 N/m), with local damping α; spin: tangential springs without
 * dashpot and friction 1e3. Δt = 1/4000 of the oscillation's period. */
static demill_world *pressed_ball(int dim, int integrator, double alpha, int spin,
                                  demill_id *ball, double *period)
{
    demill_world *w;
    demill_id mat, wall;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    double g[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++)
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_X + c, g[c]));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    DM_OK(w, demill_material_create(w, &mat));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_LOCAL_DAMPING, alpha));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    if (spin) {
        DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
        DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR, 0.0));
        DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_FRICTION, 1e3));
    }
    for (int side = -1; side <= 1; side += 2) {
        double p[3] = {side * (R - DELTA0), 0, 0}, n[3] = {-side, 0, 0};
        DM_OK(w, demill_wall_add_plane(w, mat, p, n, &wall));
    }
    double x[3] = {0, 0, 0}, r = R;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, ball));
    double k, m, ratio;
    DM_OK(w, demill_pair_get(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, &k));
    DM_OK(w, demill_pair_get(w, mat, mat, DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, &ratio));
    m = dm_test_get(w, *ball, DEMILL_PARTICLE_MASS, 0);
    /* translation: K = 2k; spin: 2 k_t R² over I = 2/5 m R², so 5 k_t / m */
    const double omega2 = spin ? 5.0 * ratio * k / m : 2.0 * k / m;
    *period = 2.0 * M_PI / sqrt(omega2);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, *period / STEPS));
    return w;
}

/* Runs the oscillator for `cycles` periods from displacement a0 (or spin
 * w0), recording the extrema of the displacement (or of the spin, whose
 * peaks fall by the same ratio) by a parabola through the three samples
 * about each; checks the ratio over each full cycle against
 * (1 - α)/(1 + α) and the energy account along the way. */
static void oscillator(int dim, int integrator, double alpha, int spin)
{
    demill_id ball;
    double period;
    demill_world *w = pressed_ball(dim, integrator, alpha, spin, &ball, &period);
    const int field = spin ? DEMILL_PARTICLE_ANGULAR_VELOCITY : DEMILL_PARTICLE_POSITION;
    const int comp = spin ? 2 : 0;
    double set[3] = {0, 0, 0};
    set[comp] = spin ? 20.0 : 0.5 * DELTA0;
    const double rest = dm_test_energy(w, DEMILL_ENERGY_TOTAL); /* the preloaded planes' */
    DM_OK(w, demill_particle_set(w, ball, field, set));
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL), osc = e0 - rest;
    const double want = (1 - alpha) / (1 + alpha);
    double peaks[16], s[3] = {0, 0, 0}, worst = 0;
    int npeaks = 0;
    const int steps = 5 * STEPS;
    for (int k = 0; k < steps && npeaks < 16; k++) {
        DM_OK(w, demill_world_step(w, 1));
        s[0] = s[1];
        s[1] = s[2];
        s[2] = dm_test_get(w, ball, field, comp);
        if (k >= 2 && fabs(s[1]) >= fabs(s[0]) && fabs(s[1]) > fabs(s[2])) {
            /* the vertex of the parabola through the three samples */
            const double d1 = 0.5 * (s[2] - s[0]), d2 = s[2] - 2 * s[1] + s[0];
            peaks[npeaks++] = fabs(s[1] - 0.5 * d1 * d1 / d2);
        }
        if (k % 40 == 0)
            worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0));
    }
    ck_assert_msg(npeaks >= 5, "%dD alpha %g spin %d: %d peaks only", dim, alpha, spin, npeaks);
    for (int p = 2; p < npeaks; p++)
        ck_assert_msg(fabs(peaks[p] / peaks[p - 2] - want) <= 0.01 * want,
                      "%dD integrator %d alpha %g %s: cycle ratio %.6f at peak %d, expected "
                      "(1 - a)/(1 + a) = %.6f",
                      dim, integrator, alpha, spin ? "spin" : "translation",
                      peaks[p] / peaks[p - 2], p, want);
    /* the energy went into local damping, and the account holds */
    const double lost = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL);
    ck_assert_msg(alpha == 0 || lost > 0.5 * osc, "local damping took %g J of %g J", lost, osc);
    ck_assert_double_eq(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_NORMAL), 0.0);
    double terms = lost;
    for (int t = DEMILL_ENERGY_DISSIPATED_NORMAL; t <= DEMILL_ENERGY_DISSIPATED_ROLLING; t++)
        terms += dm_test_energy(w, t);
    ck_assert_msg(fabs(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED) - terms) <= 1e-12 * terms,
                  "DEMILL_ENERGY_DISSIPATED %g J, its terms %g J",
                  dm_test_energy(w, DEMILL_ENERGY_DISSIPATED), terms);
    /* velocity Verlet's energy error is second order (7e-4 of the spin's
     * energy here, 1/4 of that at twice the steps, with or without local
     * damping); symplectic Euler's first order: it conserves a modified
     * energy that differs from the true one by up to ω Δt / 2 of it (Hairer,
     * Lubich and Wanner 2006, Geometric Numerical Integration, ch. IX), 8e-4
     * at 4000 steps per period. Symplectic Euler's spin is left out: it
     * books dissipation in the undamped tangential spring that does not
     * happen (4.5 % of the spin's energy over 5 periods at 2000 steps per
     * period, first order in Δt, without local damping too), which is the
     * spring's account, not local damping's. */
    const double tol = integrator == DEMILL_INTEGRATOR_SYMPLECTIC_EULER ? 2 * M_PI / STEPS : 1e-3;
    if (!spin || integrator == DEMILL_INTEGRATOR_VELOCITY_VERLET)
        ck_assert_msg(worst <= tol * osc, "%dD integrator %d alpha %g: balance off by %.3g of %g J",
                  dim, integrator, alpha, worst / osc, osc);
    demill_world_destroy(w);
}

START_TEST(oscillator_amplitude_ratio)
{
    static const double alphas[] = {0.05, 0.3, 0.7};
    for (int dim = 2; dim <= 3; dim++)
        for (int a = 0; a < 3; a++) {
            oscillator(dim, DEMILL_INTEGRATOR_VELOCITY_VERLET, alphas[a], 0);
            oscillator(dim, DEMILL_INTEGRATOR_SYMPLECTIC_EULER, alphas[a], 0);
        }
}
END_TEST

START_TEST(torsion_amplitude_ratio)
{
    static const double alphas[] = {0.05, 0.3, 0.7};
    for (int dim = 2; dim <= 3; dim++)
        for (int a = 0; a < 3; a++) {
            oscillator(dim, DEMILL_INTEGRATOR_VELOCITY_VERLET, alphas[a], 1);
            oscillator(dim, DEMILL_INTEGRATOR_SYMPLECTIC_EULER, alphas[a], 1);
        }
}
END_TEST

/* Without local damping the oscillator keeps its amplitude, and the term
 * stays 0. */
START_TEST(off_is_zero)
{
    demill_id ball;
    double period;
    demill_world *w = pressed_ball(3, DEMILL_INTEGRATOR_VELOCITY_VERLET, 0.0, 0, &ball, &period);
    double x[3] = {0.5 * DELTA0, 0, 0};
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_POSITION, x));
    DM_OK(w, demill_world_step(w, 2 * STEPS));
    DM_ASSERT_REL(dm_test_get(w, ball, DEMILL_PARTICLE_POSITION, 0), 0.5 * DELTA0, 1e-4);
    ck_assert_double_eq(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL), 0.0);
    demill_world_destroy(w);
}
END_TEST

/* Six layers of eight equal discs of radius 5 mm stacked in columns
 * 0.1 mm apart in a box whose side walls hold the bottom layer in place
 * (nearly elastic contacts: restitution 0.9, friction and rolling
 * resistance) drop onto each other and ring; returns the steps until their
 * kinetic energy (translational and rotational) is below 1e-6 of the
 * potential energy they lost, sampled every 200 steps, and checks the
 * account. */
static int pile_steps(double alpha)
{
    demill_world *w;
    demill_id mat, wall;
    ck_assert_int_eq(demill_world_create(2, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &mat));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_LOCAL_DAMPING, alpha));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_RESTITUTION, 0.9));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_ROLLING_FRICTION, 0.05));
    enum { COLS = 8, ROWS = 6, N = COLS * ROWS };
    const double r = 0.005, gap = 1e-4;
    const double planes[3][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {2 * r * COLS, 0, -1, 0}};
    for (int k = 0; k < 3; k++) {
        double p[3] = {planes[k][0], planes[k][1], 0}, n[3] = {planes[k][2], planes[k][3], 0};
        DM_OK(w, demill_wall_add_plane(w, mat, p, n, &wall));
    }
    double x[3 * N], rad[N];
    for (int i = 0; i < N; i++) {
        x[3 * i] = r + 2 * r * (i % COLS);
        x[3 * i + 1] = r + gap + (2 * r + gap) * (i / COLS);
        x[3 * i + 2] = 0;
        rad[i] = r;
    }
    DM_OK(w, demill_particles_add(w, mat, N, x, rad, NULL, 0, NULL));
    /* contact time π √(m* / k) = 3.6e-4 s: 100 steps */
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 3.6e-6));
    const double b0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double p0 = dm_test_energy(w, DEMILL_ENERGY_POTENTIAL);
    int steps = 0;
    double drop = 0.0, worst = 0.0;
    for (; steps < 200000; steps += 200) {
        DM_OK(w, demill_world_step(w, 200));
        drop = p0 - dm_test_energy(w, DEMILL_ENERGY_POTENTIAL);
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - b0));
        const double ke = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                          dm_test_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL);
        if (steps > 2000 && ke < 1e-6 * drop)
            break;
    }
    ck_assert_msg(worst <= 1e-3 * drop, "alpha %g: balance off by %.3g of %g J", alpha,
                  worst / drop, drop);
    ck_assert_msg((alpha > 0) == (dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL) > 0),
                  "alpha %g: local damping took %g J", alpha,
                  dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL));
    demill_world_destroy(w);
    return steps;
}

START_TEST(pile_settles_sooner)
{
    const int plain = pile_steps(0.0), damped = pile_steps(0.7);
    ck_assert_msg(damped < plain / 2, "settled in %d steps with local damping, %d without",
                  damped, plain);
}
END_TEST

/* A checkpoint and a snapshot carry local damping: the copies run on to
 * the same bits and the same energy dissipated. */
static void same_local_energy(demill_world *w, demill_world *copy, int way, void *ctx)
{
    (void)ctx;
    ck_assert_msg(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL) ==
                      dm_test_energy(copy, DEMILL_ENERGY_DISSIPATED_LOCAL),
                  "%s: local damping's energy differs", way ? "snapshot" : "checkpoint");
}

START_TEST(checkpoint_and_snapshot)
{
    demill_id ball;
    double period;
    demill_world *w = pressed_ball(3, DEMILL_INTEGRATOR_VELOCITY_VERLET, 0.3, 1, &ball, &period);
    double x[3] = {0.5 * DELTA0, 0, 0}, spin[3] = {5, 10, 20};
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_POSITION, x));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    DM_OK(w, demill_world_step(w, 1001));
    ck_assert(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED_LOCAL) > 0);
    dm_test_copies_run_on(w, 2000, same_local_energy, NULL);
    demill_world_destroy(w);
}
END_TEST

START_TEST(refinement_refused)
{
    demill_id ball;
    double period;
    demill_world *w = pressed_ball(3, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT, 0.2, 0, &ball,
                                   &period);
    ck_assert_int_eq(demill_world_step(w, 1), DEMILL_ERR_INVALID_VALUE);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "LOCAL_DAMPING"));
    double t;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    ck_assert_double_eq(t, 0.0);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("local_damping");
    TCase *tc = tcase_create("oscillator");
    tcase_add_test(tc, oscillator_amplitude_ratio);
    tcase_add_test(tc, torsion_amplitude_ratio);
    tcase_add_test(tc, off_is_zero);
    tcase_add_test(tc, refinement_refused);
    tcase_add_test(tc, checkpoint_and_snapshot);
    suite_add_tcase(s, tc);
    TCase *pile = tcase_create("pile");
    tcase_add_test(pile, pile_settles_sooner);
    suite_add_tcase(s, pile);
    return dm_test_run(s);
}
