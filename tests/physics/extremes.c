/* extremes.c: numerical stability at the extremes (issue 5). Each case
 * passes by staying accurate against an independent number, or (where the
 * case says so) by the watchdog reporting DEMILL_ERR_UNSTABLE; never by
 * silent garbage. Time steps come from demill_world_suggest_time_step().
 *
 * - Stiffness 1e3 to 1e12 N/m, restitution 0.01 and 0.999, radii 1e-6 m to
 *   1 m, a collision 1e4 m from the origin: binary collisions against the
 *   set restitution (the linear law's exact e, see collision.c; Hertz's
 *   damping is calibrated to e as well), and the Hertz overlap
 *   δ_max = (15 m* v²/(16 E* √R*))^(2/5).
 * - Friction 0 and 10, rolling friction 0 and 1: a ball on a floor (see
 *   rolling.c): without friction a spinning ball keeps its spin and does not
 *   move; with μ = 10 it rolls at 2/7 R ω0; without rolling resistance a
 *   rolling ball keeps its speed; with μ_r = 1 it stops after
 *   v0²/(2 · 5/7 μ_r g).
 * - Mass ratio 1e4 (a 108 mm ball among 5 mm ore) in a mill, and drum speeds
 *   of 0, 100 % and 300 % of critical: the energy balance (DEMILL_ENERGY_TOTAL:
 *   kinetic + potential + elastic + dissipated - wall work) stays constant
 *   to 1 % of the energy dissipated.
 * - A pile settling: 1e4 discs in 25 rows for 2e4 steps (1e5 for 1e5 steps
 *   with DEMILL_LONG_TESTS=1): the mechanical energy never rises above its start
 *   (by more than the balance's second-order error, 1e-3 of the energy
 *   dissipated), and at the end the kinetic energy is no more than it was
 *   halfway (no creeping gain).
 */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define G 9.81

/* The suggested time step at impact speed v, 50 steps per contact. */
static double suggested(demill_world *w, double v)
{
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, v, 0, &dt, NULL, NULL));
    return dt;
}

/* A binary collision at the suggested step, with a probe pair of particles
 * added and removed to make the suggestion. */
static dm_collision collide_at_suggested(demill_world *w, demill_id m, double r, double v,
                                         double offset)
{
    double x[3] = {offset, 0, 0};
    demill_id probe;
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &probe));
    const double dt = suggested(w, v);
    DM_OK(w, demill_particles_remove(w, 1, &probe));
    return dm_test_collide(w, m, r, v, dt, 0.5, offset);
}

START_TEST(stiffness_range)
{
    const double ks[] = {1e3, 1e6, 1e9, 1e12};
    for (int k = 0; k < 4; k++) {
        demill_id m;
        demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, ks[k]));
        const dm_collision o = collide_at_suggested(w, m, 0.005, 1.0, 0.0);
        DM_ASSERT_REL(o.restitution, 0.5, 0.01);
        demill_world_destroy(w);
    }
}
END_TEST

START_TEST(restitution_extremes)
{
    const double es[] = {0.01, 0.999};
    for (int normal = DEMILL_NORMAL_LINEAR; normal <= DEMILL_NORMAL_HERTZ; normal++)
        for (int k = 0; k < 2; k++) {
            demill_id m;
            demill_world *w = dm_test_world(3, normal, DEMILL_DAMPING_RESTITUTION, &m);
            DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, es[k]));
            const dm_collision o = collide_at_suggested(w, m, 0.005, 1.0, 0.0);
            /* 1 % of e, or 1e-3 of the impact speed where e is tiny */
            ck_assert_msg(fabs(o.restitution - es[k]) <= fmax(0.01 * es[k], 1e-3),
                          "normal law %d: e = %.6f, expected %g", normal, o.restitution, es[k]);
            demill_world_destroy(w);
        }
}
END_TEST

START_TEST(radius_extremes)
{
    const double radii[] = {1e-6, 1.0};
    for (int k = 0; k < 2; k++) {
        demill_id m;
        demill_world *w = dm_test_world(3, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, &m);
        const double r = radii[k], v = 0.1, estar = 1e8 / (2 * (1 - 0.09));
        const double mstar = 0.5 * 4.0 / 3.0 * M_PI * r * r * r * 2500;
        const double dmax = pow(15 * mstar * v * v / (16 * estar * sqrt(r / 2)), 0.4);
        const dm_collision o = collide_at_suggested(w, m, r, v, 0.0);
        DM_ASSERT_REL(o.restitution, 1.0, 0.01);
        DM_ASSERT_REL(o.max_overlap, dmax, 0.02);
        demill_world_destroy(w);
    }
}
END_TEST

/* 1e4 m from the origin positions carry about 2e-12 m of round-off, 1e-7
 * of the overlap: the collision is the one at the origin. */
START_TEST(far_from_origin)
{
    demill_id m;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
    const dm_collision here = collide_at_suggested(w, m, 0.005, 1.0, 0.0);
    const dm_collision far = collide_at_suggested(w, m, 0.005, 1.0, 1e4);
    DM_ASSERT_REL(far.restitution, 0.5, 0.01);
    ck_assert_msg(fabs(far.restitution - here.restitution) < 1e-5, "e = %.9f here, %.9f far",
                  here.restitution, far.restitution);
    demill_world_destroy(w);
}
END_TEST

/* A 1 cm ball on a floor with friction mu, rolling friction mu_r. */
static demill_world *ball_on_floor(double mu, double mu_r, demill_id *ball)
{
    demill_world *w;
    demill_id m, floor;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_FRICTION, mu));
    if (mu_r > 0) {
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, mu_r));
    }
    double p[3] = {0, 0, 0}, n[3] = {0, 1, 0}, x[3] = {0, 0.01, 0}, r = 0.01;
    DM_OK(w, demill_wall_add_plane(w, m, p, n, &floor));
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, ball));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, suggested(w, 0.1)));
    double dt;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    DM_OK(w, demill_world_step(w, (uint64_t)(0.1 / dt))); /* settle */
    return w;
}

static void run_for(demill_world *w, double seconds)
{
    double dt;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    DM_OK(w, demill_world_step(w, (uint64_t)(seconds / dt)));
}

START_TEST(friction_extremes)
{
    const double w0 = 50.0, r = 0.01;
    double spin[3] = {0, 0, w0}, zero[3] = {0, 0, 0};
    demill_id b;
    /* μ = 0: the spin stays, the ball stays */
    demill_world *w = ball_on_floor(0.0, 0.0, &b);
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_VELOCITY, zero));
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    run_for(w, 0.2);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), w0, 1e-12);
    ck_assert(fabs(dm_test_get(w, b, DEMILL_PARTICLE_VELOCITY, 0)) < 1e-12);
    demill_world_destroy(w);
    /* μ = 10: rolls at 2/7 R ω0 */
    w = ball_on_floor(10.0, 0.0, &b);
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_VELOCITY, zero));
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    run_for(w, 0.05);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_VELOCITY, 0), -2.0 / 7.0 * r * w0, 0.02);
    demill_world_destroy(w);
}
END_TEST

START_TEST(rolling_friction_extremes)
{
    const double v0 = 0.5, r = 0.01;
    double vel[3] = {v0, 0, 0}, spin[3] = {0, 0, -v0 / r};
    demill_id b;
    /* μ_r = 0: rolls on at v0 */
    demill_world *w = ball_on_floor(0.5, 0.0, &b);
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_VELOCITY, vel));
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    run_for(w, 0.2);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_VELOCITY, 0), v0, 1e-3);
    demill_world_destroy(w);
    /* μ_r = 1 (and μ = 10 so that it cannot slip): stops after v0²/(2 a) */
    w = ball_on_floor(10.0, 1.0, &b);
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_VELOCITY, vel));
    DM_OK(w, demill_particle_set(w, b, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    const double x0 = dm_test_get(w, b, DEMILL_PARTICLE_POSITION, 0), a = 5.0 / 7.0 * G;
    run_for(w, 2 * v0 / a);
    ck_assert(fabs(dm_test_get(w, b, DEMILL_PARTICLE_VELOCITY, 0)) < 1e-3 * v0);
    DM_ASSERT_REL(dm_test_get(w, b, DEMILL_PARTICLE_POSITION, 0) - x0, v0 * v0 / (2 * a), 0.05);
    demill_world_destroy(w);
}
END_TEST

/* A 2D or 3D mill of steel; big > 0 adds one ball of that radius first. */
static demill_world *mill(int dim, double big, double ore_r, uint32_t count, double fraction,
                          double youngs, demill_id *drum)
{
    demill_world *w;
    demill_id steel;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &steel));
    DM_OK(w, demill_material_set(w, steel, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, steel, DEMILL_MATERIAL_YOUNGS_MODULUS, youngs));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_drum_create(w, steel, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, 0.3));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, 2.2 * fmax(big, ore_r)));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTERS, 6));
    if (big > 0) {
        double x[3] = {0, -0.15 + 0.016 + big, 0}; /* above the lifters */
        demill_id ball;
        DM_OK(w, demill_particles_add(w, steel, 1, x, &big, NULL, DEMILL_ADD_NO_OVERLAP, &ball));
    }
    const double sizes[2] = {2 * ore_r, 1.0};
    DM_OK(w, demill_drum_fill(w, *drum, steel, DEMILL_SIZES_CLASSES, sizes, 2, DEMILL_FILL_COUNT,
                              count, 42, NULL, 0, NULL));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SPEED_FRACTION, fraction));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, suggested(w, 0)));
    return w;
}

/* The balance over `seconds`: constant to 1 % of the energy dissipated. */
static void balance_holds(demill_world *w, double seconds)
{
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double d0 = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED);
    run_for(w, seconds);
    const double e1 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double d1 = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED);
    ck_assert_msg(d1 > d0, "nothing was dissipated");
    ck_assert_msg(fabs(e1 - e0) <= 0.01 * (d1 - d0), "balance %g -> %g J, %g J dissipated", e0, e1,
                  d1 - d0);
}

/* 108 mm and 5 mm balls of one steel: mass ratio (54/2.5)³ = 1.0e4. With a
 * Young's modulus of 1e10 Pa the big ball's weight (50 N) presses a small
 * ball in by 1 % of its radius (Hertz), and the run is accurate; with the
 * default 1e8 Pa it would press it in by 23 %, which the watchdog reports
 * as an overlap beyond its 25 % limit with the stiffness too low for the
 * loads. */
START_TEST(mass_ratio_in_mill)
{
    demill_id drum;
    demill_world *w = mill(3, 0.054, 0.0025, 300, 0.75, 1e10, &drum);
    balance_holds(w, 0.2);
    demill_world_destroy(w);
    w = mill(3, 0.054, 0.0025, 300, 0.75, 1e8, &drum);
    double dt;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    ck_assert_int_eq(demill_world_step(w, (uint64_t)(0.2 / dt)), DEMILL_ERR_UNSTABLE);
    ck_assert_msg(strstr(demill_world_last_error(w), "overlaps particle") &&
                      strstr(demill_world_last_error(w), "too low for the loads"),
                  "%s", demill_world_last_error(w));
    demill_world_destroy(w);
}
END_TEST

START_TEST(drum_speed_range)
{
    const double fractions[] = {0.0, 1.0, 3.0};
    for (int k = 0; k < 3; k++) {
        demill_id drum;
        demill_world *w = mill(2, 0.0, 0.004, 200, fractions[k], 1e8, &drum);
        balance_holds(w, 0.4);
        demill_world_destroy(w);
    }
}
END_TEST

START_TEST(pile_settles)
{
    const int long_run = getenv("DEMILL_LONG_TESTS") && atoi(getenv("DEMILL_LONG_TESTS"));
    const uint32_t n = long_run ? 100000 : 10000, side = n / 25; /* 25 rows */
    const uint64_t steps = long_run ? 100000 : 20000;
    demill_world *w;
    demill_id m, wall;
    ck_assert_int_eq(demill_world_create(2, &w), DEMILL_OK);
    if (demill_world_set(w, DEMILL_WORLD_THREADS, 2) != DEMILL_OK) /* built without threads */
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_THREADS, 1));
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double r = 0.002, L = side * 2.2 * r;
    const double planes[3][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {L, 0, -1, 0}};
    for (int k = 0; k < 3; k++) {
        double p[3] = {planes[k][0], planes[k][1], 0}, nrm[3] = {planes[k][2], planes[k][3], 0};
        DM_OK(w, demill_wall_add_plane(w, m, p, nrm, &wall));
    }
    double *x = malloc(3 * sizeof(double) * n), *rad = malloc(sizeof(double) * n);
    ck_assert(x && rad);
    srand(3);
    for (uint32_t i = 0; i < n; i++) {
        x[3 * i] = (i % side + 0.5) * 2.2 * r;
        x[3 * i + 1] = (i / side + 0.5) * 2.2 * r;
        x[3 * i + 2] = 0;
        rad[i] = r * (0.8 + 0.2 * rand() / RAND_MAX);
    }
    DM_OK(w, demill_particles_add(w, m, n, x, rad, NULL, 0, NULL));
    free(x);
    free(rad);
    double dt; /* 20 steps per contact: enough for a dissipative pile */
    DM_OK(w, demill_world_suggest_time_step(w, 0, 20, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    const double m0 =
        dm_test_energy(w, DEMILL_ENERGY_TOTAL) - dm_test_energy(w, DEMILL_ENERGY_DISSIPATED);
    double k_half = 0;
    for (int s = 1; s <= 20; s++) {
        DM_OK(w, demill_world_step(w, steps / 20));
        const double d = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED);
        const double mech = dm_test_energy(w, DEMILL_ENERGY_TOTAL) - d;
        /* up to the balance's second-order error, 1e-3 of what was dissipated,
         * and round-off */
        ck_assert_msg(mech <= m0 + 1e-3 * d + 1e-12 * fabs(m0), "mechanical energy rose from %.9g to %.9g J (%g J "
                      "dissipated)", m0, mech, d);
        if (s == 10)
            k_half = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                     dm_test_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL);
    }
    const double k_end = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                         dm_test_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL);
    ck_assert_msg(k_end <= k_half, "kinetic energy grew from %g to %g J", k_half, k_end);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("extremes");
    TCase *tc = tcase_create("extremes");
    tcase_add_test(tc, stiffness_range);
    tcase_add_test(tc, restitution_extremes);
    tcase_add_test(tc, radius_extremes);
    tcase_add_test(tc, far_from_origin);
    tcase_add_test(tc, friction_extremes);
    tcase_add_test(tc, rolling_friction_extremes);
    tcase_add_test(tc, mass_ratio_in_mill);
    tcase_add_test(tc, drum_speed_range);
    tcase_add_test(tc, pile_settles);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
