/* dissipation.c: the six-way dissipation account with every mechanism on.
 *
 * A visco-elasto-plastic contact loses energy by six mechanisms (Li, Gao,
 * Zhang and Liu 2018, "Elasto-plastic contact modelling method for the
 * vibration and energy dissipation of particles"): normal viscous and
 * plastic, tangential viscous, sliding friction, rolling viscous and rolling
 * friction, each its own DEMILL_ENERGY_* term (7, 19, 8, 9, 20, 10); local
 * damping (21) and the work done against cohesion (22) join them. With every
 * law on at once, in a settling pile and in a turning mill, 2D and 3D, the
 * first law must hold: kinetic + potential + elastic + dissipated + work
 * against cohesion - wall work stays constant to 1e-3 of the energy that went
 * through (what was dissipated and done against cohesion, plus the initial
 * kinetic energy). Each dissipation term must stay non-negative (to the same
 * 1e-3: a running tally may dip by the account's own error), be positive
 * where its law is on, and be exactly 0 in a scene whose laws do not have
 * it.
 *
 * The laws, by pair: P-P Thornton (yield at 2e7 Pa) with a viscous dashpot,
 * Mindlin friction, the rolling spring and a liquid bridge; Q-Q Hertz with
 * the same dashpot, Mindlin, the rolling spring and JKR adhesion; P-Q Walton
 * and Braun with a tangential spring and the constant rolling torque; Q has
 * local damping. Time steps 1/100 of the shortest contact
 * (demill_world_suggest_time_step), where the tally's second-order error is
 * about 5e-4 of what is dissipated (docs/physics.md §10).
 */
#include <math.h>
#include <stdlib.h>

#include "testutil.h"

#define R 0.004 /* the largest radius, m */

/* the terms that dissipate, and their names */
static const int32_t lost[] = {DEMILL_ENERGY_DISSIPATED_NORMAL,
                               DEMILL_ENERGY_DISSIPATED_PLASTIC,
                               DEMILL_ENERGY_DISSIPATED_TANGENTIAL,
                               DEMILL_ENERGY_DISSIPATED_FRICTION,
                               DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS,
                               DEMILL_ENERGY_DISSIPATED_ROLLING,
                               DEMILL_ENERGY_DISSIPATED_LOCAL};
#define LOST ((int)(sizeof lost / sizeof *lost))

static void laws(demill_world *w, demill_id a, demill_id b, int normal, int damping,
                 int tangential, int rolling, int cohesion)
{
    const int32_t keys[] = {DEMILL_PAIR_NORMAL, DEMILL_PAIR_DAMPING, DEMILL_PAIR_TANGENTIAL,
                            DEMILL_PAIR_ROLLING, DEMILL_PAIR_COHESION};
    const int values[] = {normal, damping, tangential, rolling, cohesion};
    for (int k = 0; k < 5; k++)
        DM_OK(w, demill_pair_set(w, a, b, keys[k], values[k]));
}

/* Materials P (walls and half the particles) and Q with every mechanism
 * between them (above), or (all = 0) Hertz, restitution damping and Mindlin
 * friction alone. */
static void materials(demill_world *w, int all, demill_id *p, demill_id *q)
{
    DM_OK(w, demill_material_create(w, p));
    DM_OK(w, demill_material_create(w, q));
    demill_id m[2] = {*p, *q};
    for (int k = 0; k < 2; k++) {
        DM_OK(w, demill_material_set(w, m[k], DEMILL_MATERIAL_DENSITY, 2700));
        DM_OK(w, demill_material_set(w, m[k], DEMILL_MATERIAL_YOUNGS_MODULUS, 5e7));
        DM_OK(w, demill_material_set(w, m[k], DEMILL_MATERIAL_STIFFNESS, 2e4));
        DM_OK(w, demill_material_set(w, m[k], DEMILL_MATERIAL_FRICTION, 0.3));
        DM_OK(w, demill_material_set(w, m[k], DEMILL_MATERIAL_ROLLING_FRICTION, 0.05));
    }
    if (!all) {
        for (int a = 0; a < 2; a++)
            for (int b = a; b < 2; b++)
                laws(w, m[a], m[b], DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION,
                     DEMILL_TANGENTIAL_MINDLIN, DEMILL_ROLLING_CONSTANT_TORQUE,
                     DEMILL_COHESION_NONE);
        return;
    }
    DM_OK(w, demill_material_set(w, *p, DEMILL_MATERIAL_YIELD_STRESS, 2e7 / 1.6));
    DM_OK(w, demill_material_set(w, *q, DEMILL_MATERIAL_LOCAL_DAMPING, 0.05));
    DM_OK(w, demill_material_set(w, *q, DEMILL_MATERIAL_SURFACE_ENERGY, 0.05));
    laws(w, *p, *p, DEMILL_NORMAL_THORNTON, DEMILL_DAMPING_VISCOUS, DEMILL_TANGENTIAL_MINDLIN,
         DEMILL_ROLLING_SPRING, DEMILL_COHESION_CAPILLARY);
    laws(w, *q, *q, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_VISCOUS, DEMILL_TANGENTIAL_MINDLIN,
         DEMILL_ROLLING_SPRING, DEMILL_COHESION_JKR);
    laws(w, *p, *q, DEMILL_NORMAL_WALTON_BRAUN, DEMILL_DAMPING_VISCOUS,
         DEMILL_TANGENTIAL_SPRING, DEMILL_ROLLING_CONSTANT_TORQUE, DEMILL_COHESION_NONE);
    for (int a = 0; a < 2; a++)
        for (int b = a; b < 2; b++)
            DM_OK(w, demill_pair_set(w, m[a], m[b], DEMILL_PAIR_VISCOUS_DAMPING, 0.02));
    DM_OK(w, demill_pair_set(w, *p, *p, DEMILL_PAIR_LIQUID_VOLUME, 1e-10));
}

/* n particles of radii 0.6-1 R, alternately of p and q, on a lattice of
 * spacing 3R with `row` to a row (and row² to a layer in 3D) from x0,
 * moving at up to 0.5 m/s. */
static void charge(demill_world *w, int dim, int n, int row, const double *x0, demill_id p,
                   demill_id q)
{
    srand(7);
    for (int k = 0; k < n; k++) {
        const int cell[3] = {k % row, dim == 3 ? k / row % row : k / row, k / (row * row)};
        double x[3] = {0, 0, 0}, v[3] = {0, 0, 0};
        for (int c = 0; c < dim; c++) {
            x[c] = x0[c] + 3 * R * cell[c];
            v[c] = 0.5 * (2.0 * rand() / RAND_MAX - 1.0);
        }
        const double r = R * (0.6 + 0.4 * rand() / RAND_MAX);
        DM_OK(w, demill_particles_add(w, k % 2 ? q : p, 1, x, &r, v, 0, NULL));
    }
}

/* Runs w for `samples` × `steps` and checks the account (above); all: every
 * mechanism is on. */
static void account(demill_world *w, const char *what, int samples, uint64_t steps, int all)
{
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 100, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_ENERGY_TRACKING, 1));
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double k0 = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                      dm_test_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL);
    double worst = 0, low[LOST];
    for (int t = 0; t < LOST; t++)
        low[t] = 0.0;
    for (int s = 0; s < samples; s++) {
        DM_OK(w, demill_world_step(w, steps));
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0));
        for (int t = 0; t < LOST; t++)
            low[t] = fmin(low[t], dm_test_energy(w, lost[t]));
    }
    const double through = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED) +
                           fabs(dm_test_energy(w, DEMILL_ENERGY_COHESION)) + k0 +
                           fabs(dm_test_energy(w, DEMILL_ENERGY_WALL_WORK));
    /* non-negative: a running tally may dip below 0 by the account's own
     * error (the spring-slider books its loss as work less the change of its
     * spring's energy, second order in the step), never by more */
    for (int t = 0; t < LOST; t++)
        ck_assert_msg(low[t] >= -1e-3 * through, "%s: term %d fell to %.3g J (%.3g of %.3g J)",
                      what, (int)lost[t], low[t], low[t] / through, through);
    ck_assert_msg(worst <= 1e-3 * through, "%s: the balance strayed by %.3g of %.3g J", what,
                  worst / through, through);
    for (int t = 0; t < LOST; t++) {
        const double e = dm_test_energy(w, lost[t]);
        if (all)
            ck_assert_msg(e > 0.0, "%s: term %d dissipated nothing", what, (int)lost[t]);
        else if (lost[t] == DEMILL_ENERGY_DISSIPATED_PLASTIC ||
                 lost[t] == DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS ||
                 lost[t] == DEMILL_ENERGY_DISSIPATED_LOCAL)
            ck_assert_msg(e == 0.0, "%s: term %d is %.3g J with its law off", what,
                          (int)lost[t], e);
    }
    const double cohesion = dm_test_energy(w, DEMILL_ENERGY_COHESION);
    const double rolling = dm_test_energy(w, DEMILL_ENERGY_ELASTIC_ROLLING);
    ck_assert_msg(all ? cohesion != 0.0 : cohesion == 0.0, "%s: work against cohesion %.3g J",
                  what, cohesion);
    ck_assert_msg(all ? rolling >= 0.0 : rolling == 0.0, "%s: rolling springs hold %.3g J", what,
                  rolling);
}

/* A box of planes, 0.1 m wide, 64 (2D) or 150 (3D) particles thrown about
 * in it settle into a pile. */
static void pile(int dim, int all)
{
    demill_world *w;
    demill_id p, q, wall;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    materials(w, all, &p, &q);
    for (int a = 0; a < dim; a++)
        for (int side = 0; side < 2; side++) {
            double x[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            x[a] = side ? 0.1 : 0.0;
            n[a] = side ? -1 : 1;
            DM_OK(w, demill_wall_add_plane(w, p, x, n, &wall));
        }
    const double x0[3] = {0.01, 0.01, 0.01};
    charge(w, dim, dim == 3 ? 150 : 64, dim == 3 ? 6 : 8, x0, p, q);
    const char *what[2][2] = {{"2D pile, laws off", "2D pile"}, {"3D pile, laws off", "3D pile"}};
    account(w, what[dim == 3][all], 20, 1000, all);
    demill_world_destroy(w);
}

/* A drum 0.2 m across with 4 lifters, turning at 75 % of critical speed,
 * 81 (2D) or 150 (3D) particles tumbling in it. */
static void mill(int dim)
{
    demill_world *w;
    demill_id p, q, drum;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    materials(w, 1, &p, &q);
    DM_OK(w, demill_drum_create(w, p, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.2));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.04));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 4));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, 0.01));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_WIDTH, 0.01));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    const double x0[3] = {-0.048, -0.05, -0.012};
    charge(w, dim, dim == 3 ? 150 : 81, dim == 3 ? 8 : 9, x0, p, q);
    account(w, dim == 3 ? "3D mill" : "2D mill", 60, 1000, 1);
    demill_world_destroy(w);
}

START_TEST(pile_every_mechanism)
{
    pile(2 + _i, 1);
}
END_TEST

START_TEST(mill_every_mechanism)
{
    mill(2 + _i);
}
END_TEST

START_TEST(terms_zero_when_off)
{
    pile(2 + _i, 0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("dissipation");
    TCase *tc = tcase_create("six-way");
    tcase_set_timeout(tc, 600);
    tcase_add_loop_test(tc, pile_every_mechanism, 0, 2);
    tcase_add_loop_test(tc, mill_every_mechanism, 0, 2);
    tcase_add_loop_test(tc, terms_zero_when_off, 0, 2);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
