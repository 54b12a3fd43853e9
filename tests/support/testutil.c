/* testutil.c: helpers shared by the test suites. */
#include "testutil.h"

#include <stdlib.h>

demill_world *dm_test_world(int dim, int normal, int damping, demill_id *material)
{
    demill_world *w = NULL;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_material_create(w, material));
    DM_OK(w, demill_pair_set(w, *material, *material, DEMILL_PAIR_NORMAL, normal));
    DM_OK(w, demill_pair_set(w, *material, *material, DEMILL_PAIR_DAMPING, damping));
    return w;
}

int dm_test_run(Suite *s)
{
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}

double dm_test_get(demill_world *w, demill_id p, int field, int c)
{
    double v[3] = {0, 0, 0};
    DM_OK(w, demill_particle_get(w, p, field, v));
    return v[c];
}
