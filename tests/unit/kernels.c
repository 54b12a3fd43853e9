/* kernels.c: the generic contact kernel against the fast ones.
 *
 * Every combination of laws outside the fast kernels' runs the generic
 * kernel of its dimension: the fast kernels' passes and the same dm_law(),
 * with the laws as run-time values. Run on a combination that a fast kernel
 * has, it must therefore give that kernel's results bit for bit (the build
 * contracts no multiply-add, so vectorised and scalar code round alike):
 * positions, velocities and every energy term after 0.06 s of a 3D
 * tumbling mesh box and 0.01 s of a 2D box of discs, for combinations that together
 * take every normal, damping, tangential and rolling law. Internal test: it
 * switches the world to the generic kernels (demill_world.generic_kernels).
 */
#include <stdlib.h>
#include <string.h>

#include "world/world.h"
#include "testutil.h"

/* normal, damping, tangential, rolling */
static const int combos[][4] = {
    {DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, DEMILL_TANGENTIAL_NONE, DEMILL_ROLLING_NONE},
    {DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_VISCOUS, DEMILL_TANGENTIAL_SPRING,
     DEMILL_ROLLING_CONSTANT_TORQUE},
    {DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_COULOMB,
     DEMILL_ROLLING_NONE},
    {DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_MINDLIN,
     DEMILL_ROLLING_CONSTANT_TORQUE},
    {DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_VISCOUS, DEMILL_TANGENTIAL_COULOMB,
     DEMILL_ROLLING_CONSTANT_TORQUE},
    {DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, DEMILL_TANGENTIAL_SPRING, DEMILL_ROLLING_NONE},
};
#define COMBOS ((int)(sizeof combos / sizeof *combos))

/* A 2D box of four planes, 0.1 m wide, with 300 discs moving about in it. */
static void disc_box(demill_world *w, demill_id mat)
{
    const double p[4][3] = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, {0, 0, 0}};
    const double n[4][3] = {{0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
    demill_id wall;
    for (int k = 0; k < 4; k++)
        DM_OK(w, demill_wall_add_plane(w, mat, p[k], n[k], &wall));
    enum { N = 300 };
    double x[3 * N] = {0}, v[3 * N] = {0}, r[N];
    for (int k = 0; k < N; k++) {
        x[3 * k] = 0.005 + 0.0045 * (k % 20) + 0.0005 * (k / 20 % 2);
        x[3 * k + 1] = 0.005 + 0.0045 * (k / 20);
        v[3 * k] = 0.3 * sin(k);
        v[3 * k + 1] = 0.3 * cos(3 * k);
        r[k] = 0.0018 + 0.0002 * (k % 3);
    }
    DM_OK(w, demill_particles_add(w, mat, N, x, r, v, 0, NULL));
}

/* A scene of dimension dim with laws l, on the fast kernels or the generic
 * one, run for a while; its positions and velocities, then every energy term. */
static double *run(int dim, const int *l, bool generic, size_t *len)
{
    demill_world *w;
    demill_id mat, box;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    w->generic_kernels = generic;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_ENERGY_TRACKING, 1));
    DM_OK(w, demill_material_create(w, &mat));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e7));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_STIFFNESS, 2e4));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_ROLLING_FRICTION, 0.05));
    const int32_t keys[4] = {DEMILL_PAIR_NORMAL, DEMILL_PAIR_DAMPING, DEMILL_PAIR_TANGENTIAL,
                             DEMILL_PAIR_ROLLING};
    for (int k = 0; k < 4; k++)
        DM_OK(w, demill_pair_set(w, mat, mat, keys[k], l[k]));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_VISCOUS_DAMPING, 0.05));
    if (dim == 3)
        dm_test_tumbling_box(w, mat, &box);
    else
        disc_box(w, mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-5));
    DM_OK(w, demill_world_step(w, dim == 3 ? 6000 : 1000)); /* the balls land */
    /* the run took the kernels asked for, and its particles met */
    ck_assert(generic ? w->nkern > DM_FAST_KERNELS : w->nkern <= DM_FAST_KERNELS);
    ck_assert_uint_gt(w->ncontacts + w->nwall_contacts, 0);
    size_t n;
    double *s = dm_test_state(w, &n);
    enum { TERMS = DEMILL_ENERGY_ELASTIC_ROLLING };
    s = realloc(s, (6 * n + TERMS) * sizeof *s);
    ck_assert_ptr_nonnull(s);
    for (int t = 1; t <= TERMS; t++)
        DM_OK(w, demill_world_energy(w, t, &s[6 * n + t - 1]));
    *len = 6 * n + TERMS;
    demill_world_destroy(w);
    return s;
}

START_TEST(generic_is_fast_bitwise)
{
    const int dim = _i < COMBOS ? 3 : 2;
    const int *l = combos[_i % COMBOS];
    size_t na, nb;
    double *fast = run(dim, l, false, &na), *generic = run(dim, l, true, &nb);
    ck_assert_uint_eq(na, nb);
    for (size_t k = 0; k < na; k++)
        ck_assert_msg(!memcmp(&fast[k], &generic[k], sizeof *fast),
                      "%dD laws %d %d %d %d: value %zu of %zu: fast %.17g, generic %.17g", dim,
                      l[0], l[1], l[2], l[3], k, na, fast[k], generic[k]);
    free(fast);
    free(generic);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("kernels");
    TCase *tc = tcase_create("generic");
    tcase_add_loop_test(tc, generic_is_fast_bitwise, 0, 2 * COMBOS);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
