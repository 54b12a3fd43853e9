/* testutil.c: helpers shared by the test suites. */
#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

void dm_test_mill_materials(demill_world *w, demill_id *balls, demill_id *liner)
{
    DM_OK(w, demill_material_create(w, balls));
    DM_OK(w, demill_material_create(w, liner));
    const demill_id mats[2] = {*balls, *liner};
    for (int k = 0; k < 2; k++) {
        DM_OK(w, demill_material_set(w, mats[k], DEMILL_MATERIAL_DENSITY, 7800));
        DM_OK(w, demill_pair_set(w, *balls, mats[k], DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
        DM_OK(w, demill_pair_set(w, *balls, mats[k], DEMILL_PAIR_DAMPING,
                                 DEMILL_DAMPING_RESTITUTION));
        DM_OK(w, demill_pair_set(w, *balls, mats[k], DEMILL_PAIR_TANGENTIAL,
                                 DEMILL_TANGENTIAL_MINDLIN));
    }
}

void dm_test_mill(demill_world *w, demill_id balls, demill_id liner, double diameter,
                  double length, double lifter, demill_id *drum)
{
    DM_OK(w, demill_drum_create(w, liner, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, diameter));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, length));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTERS, 8));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_HEIGHT, lifter));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_WIDTH, lifter));
    const double sizes[4] = {0.005, 0.5, 0.006, 0.5};
    DM_OK(w, demill_drum_fill(w, *drum, balls, DEMILL_SIZES_CLASSES, sizes, 4,
                              DEMILL_FILL_FRACTION, 0.3, 7, NULL, 0, NULL));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
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

double dm_test_energy(demill_world *w, int term)
{
    double e;
    DM_OK(w, demill_world_energy(w, term, &e));
    return e;
}

/* Steps a collision of sphere ids[0] (radius r) with sphere ids[1] (wall = 0)
 * or with the plane x = 0 (wall = 1), head-on along x at relative speed v0
 * from a gap, and measures it (see dm_collision); the rebound ratio is the
 * relative velocity along x afterwards over v0. */
static dm_collision measure(demill_world *w, const demill_id *ids, int wall, double r, double v0,
                            double dt, double gap)
{
    dm_collision o = {0, 0, 0};
    double prev = -gap, t_in = -1, t_out = -1;
    for (int k = 1; k < 100000 && t_out < 0; k++) {
        DM_OK(w, demill_world_step(w, 1));
        const double x0 = dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 0);
        const double d =
            wall ? r - x0 : 2 * r - (dm_test_get(w, ids[1], DEMILL_PARTICLE_POSITION, 0) - x0);
        if (d > o.max_overlap)
            o.max_overlap = d;
        if (prev <= 0 && d > 0)
            t_in = (k - 1 + -prev / (d - prev)) * dt;
        if (prev > 0 && d <= 0)
            t_out = (k - 1 + prev / (prev - d)) * dt;
        prev = d;
    }
    ck_assert_msg(t_in >= 0 && t_out > t_in, "the collision did not complete");
    DM_OK(w, demill_world_step(w, 5)); /* separated: velocities are final */
    const double va = dm_test_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, 0);
    const double vb = wall ? 0.0 : dm_test_get(w, ids[1], DEMILL_PARTICLE_VELOCITY, 0);
    o.restitution = (wall ? va : vb - va) / v0;
    o.duration = t_out - t_in;
    return o;
}

dm_collision dm_test_collide(demill_world *w, demill_id mat, double r, double v0, double dt,
                             double phase, double offset)
{
    const double gap = (3.0 + phase) * v0 * dt;
    double x[6] = {offset - r - gap / 2, 0, 0, offset + r + gap / 2, 0, 0};
    double v[6] = {v0 / 2, 0, 0, -v0 / 2, 0, 0};
    double rr[2] = {r, r};
    demill_id ids[2];
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_particles_add(w, mat, 2, x, rr, v, 0, ids));
    const dm_collision o = measure(w, ids, 0, r, v0, dt, gap);
    DM_OK(w, demill_particles_remove(w, 2, ids));
    return o;
}

demill_world *dm_test_chain(int n, double fraction, demill_id *ids)
{
    demill_id m, wall;
    demill_world *w = dm_test_world(2, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &m);
    const double r = 0.005, gap = 2.0 * r - 0.01 * r;
    double *x = calloc(3 * (size_t)n, sizeof *x), *v = calloc(3 * (size_t)n, sizeof *v),
           *rad = calloc((size_t)n, sizeof *rad);
    ck_assert(x && v && rad);
    for (int i = 0; i < n; i++) {
        x[3 * i] = (r - 0.01 * r) + i * gap;
        v[3 * i] = i % 2 ? 0.01 : -0.01;
        rad[i] = r;
    }
    DM_OK(w, demill_particles_add(w, m, (size_t)n, x, rad, v, 0, ids));
    const double p0[3] = {0, 0, 0}, n0[3] = {1, 0, 0};
    const double p1[3] = {x[3 * (n - 1)] + r - 0.01 * r, 0, 0}, n1[3] = {-1, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, m, p0, n0, &wall));
    DM_OK(w, demill_wall_add_plane(w, m, p1, n1, &wall));
    double k;
    DM_OK(w, demill_pair_get(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, &k));
    const double mstar = dm_test_get(w, ids[0], DEMILL_PARTICLE_MASS, 0) / 2;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, fraction * 2.0 / sqrt(k / mstar)));
    free(x);
    free(v);
    free(rad);
    return w;
}

dm_collision dm_test_bounce(demill_world *w, demill_id mat, double r, double v0, double dt,
                            double phase)
{
    return dm_test_bounce_on(w, mat, mat, r, v0, dt, phase);
}

dm_collision dm_test_bounce_on(demill_world *w, demill_id mat, demill_id wall_mat, double r,
                               double v0, double dt, double phase)
{
    const double gap = (3.0 + phase) * v0 * dt;
    double x[3] = {r + gap, 0, 0}, v[3] = {-v0, 0, 0}, origin[3] = {0, 0, 0}, n[3] = {1, 0, 0};
    demill_id ids[1], plane;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_wall_add_plane(w, wall_mat, origin, n, &plane));
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, v, 0, ids));
    const dm_collision o = measure(w, ids, 1, r, v0, dt, gap);
    DM_OK(w, demill_particles_remove(w, 1, ids));
    DM_OK(w, demill_wall_remove(w, plane));
    return o;
}

dm_collision dm_test_hit_fixed(demill_world *w, demill_id mat, double r, double v0, double dt,
                               double phase)
{
    const double gap = (3.0 + phase) * v0 * dt, one = 1.0;
    double x[6] = {-r - gap, 0, 0, r, 0, 0}, v[6] = {v0, 0, 0, 0, 0, 0}, rr[2] = {r, r};
    demill_id ids[2];
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_particles_add(w, mat, 2, x, rr, v, 0, ids));
    DM_OK(w, demill_particle_set(w, ids[1], DEMILL_PARTICLE_FIXED, &one));
    const dm_collision o = measure(w, ids, 0, r, v0, dt, gap);
    DM_OK(w, demill_particles_remove(w, 2, ids));
    return o;
}

void dm_test_floor_grid(int cells, double h, double x0, double *v, uint32_t *t)
{
    const int n = cells + 1;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double *p = v + 3 * (i * n + j);
            p[0] = x0 + i * h;
            p[1] = 0.0;
            p[2] = x0 + j * h;
        }
    for (int i = 0; i < cells; i++)
        for (int j = 0; j < cells; j++) {
            const uint32_t a = (uint32_t)(i * n + j), b = a + (uint32_t)n, c = b + 1, d = a + 1;
            uint32_t *q = t + 6 * (i * cells + j);
            q[0] = a, q[1] = b, q[2] = c;
            q[3] = a, q[4] = c, q[5] = d;
        }
}

void dm_test_tumbling_box(demill_world *w, demill_id mat, demill_id *box)
{
    const double a = 0.05;
    const double v[] = {-a, 0, -a, a, 0, -a, a, 0, a, -a, 0, a,
                        -a, 2 * a, -a, a, 2 * a, -a, a, 2 * a, a, -a, 2 * a, a};
    const uint32_t t[] = {0, 1, 2, 0, 2, 3, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                          2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    DM_OK(w, demill_wall_add_mesh(w, mat, 8, v, 10, t, box));
    const double om[3] = {0, 3.0, 0.5};
    DM_OK(w, demill_wall_set_motion(w, *box, NULL, om, NULL));
    enum { N = DM_TEST_BOX_BALLS };
    double *x = malloc(3 * N * sizeof *x), r[N];
    ck_assert_ptr_nonnull(x);
    for (int k = 0; k < N; k++) {
        x[3 * k] = 0.008 * (k % 11 - 5) + 0.001 * (k % 2);
        x[3 * k + 1] = 0.006 + 0.008 * (k / 110);
        x[3 * k + 2] = 0.008 * (k / 11 % 10) - 0.036;
        r[k] = 0.0025 + 0.0003 * (k % 4);
    }
    DM_OK(w, demill_particles_add(w, mat, N, x, r, NULL, 0, NULL));
    free(x);
}

double *dm_test_state(demill_world *w, size_t *n)
{
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, NULL, 0, n));
    double *x = malloc(6 * *n * sizeof *x);
    ck_assert(x);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, 3 * *n, n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_VELOCITY, x + 3 * *n, 3 * *n, n));
    return x;
}

void dm_test_copies_run_on(demill_world *w, uint64_t steps, dm_test_copy_fn check, void *ctx)
{
    size_t size, n0, n1;
    unsigned char *bytes = dm_test_save(w, &size);
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, steps));
    double *ref = dm_test_state(w, &n0);
    for (int way = 0; way < 2; way++) {
        demill_world *v;
        ck_assert_int_eq(demill_world_create(3, &v), DEMILL_OK);
        if (way)
            DM_OK(v, demill_snapshot_restore(v, snap));
        else
            DM_OK(v, demill_world_load_buffer(v, bytes, size));
        DM_OK(v, demill_world_step(v, steps));
        double *got = dm_test_state(v, &n1);
        ck_assert_uint_eq(n0, n1);
        ck_assert_msg(memcmp(ref, got, 6 * n0 * sizeof *ref) == 0, "%s: the run differs",
                      way ? "snapshot" : "checkpoint");
        if (check)
            check(w, v, way, ctx);
        free(got);
        demill_world_destroy(v);
    }
    free(ref);
    free(bytes);
    demill_snapshot_free(snap);
}

/* The format of the checkpoint whose first 12 bytes are head. */
static uint32_t checkpoint_format(const unsigned char *head)
{
    ck_assert(!memcmp(head, "DEMILLCK", 8));
    return head[8] | head[9] << 8 | head[10] << 16 | (uint32_t)head[11] << 24;
}

void dm_test_checkpoint_format(const char *path, uint32_t format)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    unsigned char head[12];
    ck_assert_uint_eq(fread(head, 1, sizeof head, f), sizeof head);
    fclose(f);
    ck_assert_uint_eq(checkpoint_format(head), format);
}

unsigned char *dm_test_save(demill_world *w, size_t *n)
{
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, n));
    unsigned char *b = malloc(*n);
    ck_assert_ptr_nonnull(b);
    DM_OK(w, demill_world_save_buffer(w, b, *n, n));
    return b;
}

demill_world *dm_test_reloaded(demill_world *w, uint32_t *format)
{
    size_t n;
    unsigned char *b = dm_test_save(w, &n);
    *format = checkpoint_format(b);
    demill_world *v;
    ck_assert_int_eq(demill_world_create(3, &v), DEMILL_OK);
    DM_OK(v, demill_world_load_buffer(v, b, n));
    free(b);
    return v;
}

void dm_test_check_no_overlap(size_t n, const double *x, const double *r, const demill_id *clump)
{
    size_t bad = 0, bi = 0, bj = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            if (clump && clump[i] != DEMILL_ID_NONE && clump[i] == clump[j])
                continue;
            double d2 = 0.0;
            for (int k = 0; k < 3; k++)
                d2 += (x[3 * i + k] - x[3 * j + k]) * (x[3 * i + k] - x[3 * j + k]);
            const double s = r[i] + r[j];
            if (d2 < s * s && !bad++) {
                bi = i;
                bj = j;
            }
        }
    ck_assert_msg(!bad, "%zu pairs overlap, the first particles %zu and %zu", bad, bi, bj);
}

void dm_test_check_same_clumps(demill_world *a, demill_world *b, const char *what)
{
    demill_id ca[128], cb[128];
    size_t na, nb;
    DM_OK(a, demill_world_ids(a, DEMILL_KIND_CLUMP, ca, 128, &na));
    DM_OK(b, demill_world_ids(b, DEMILL_KIND_CLUMP, cb, 128, &nb));
    ck_assert_uint_eq(na, nb);
    for (size_t k = 0; k < na; k++)
        for (int32_t f = DEMILL_CLUMP_POSITION; f <= DEMILL_CLUMP_MASS; f++) {
            double va[4], vb[4];
            DM_OK(a, demill_clump_get(a, ca[k], f, va));
            DM_OK(b, demill_clump_get(b, cb[k], f, vb));
            ck_assert_msg(!memcmp(va, vb, (size_t)demill_clump_field_size(f) * sizeof *va),
                          "%s: clump %zu's field %d differs", what, k, (int)f);
        }
}
