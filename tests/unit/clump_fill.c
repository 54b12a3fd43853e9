/* clump_fill.c: filling a region with clumps of a template
 * (demill_clump_fill_region(), demill/clump.h) against numbers derived by
 * hand.
 *
 * What this suite proves:
 *  - A drum with free balls already in it, filled with dumbbells (two
 *    spheres of radius r whose centres are r apart) by count, holds that many
 *    clumps; no member overlaps a member of another clump or a free ball
 *    (every pair checked), and every member lies inside the drum's shell and
 *    caps.
 *  - A mass target gives the nearest whole number of clumps: 37.3 clumps'
 *    mass gives 37. A box filled to a solid fraction holds that fraction of
 *    its volume in clumps to within one clump, the dumbbell's volume from
 *    the lens formula (two spheres less their lens, pi (4r + d)(2r - d)^2 /
 *    12; 2D: two discs less theirs, 2 r^2 acos(d / 2r) - (d / 2)
 *    sqrt(4r^2 - d^2)).
 *  - The same call on two like worlds gives the same clumps, bitwise.
 *  - The orientations are uniform on the rotations: over 2000 clumps the
 *    world directions of the body x and y axes have means within 4 standard
 *    errors of 0 and second moments within 4 of 1/3 (off the diagonal: 0),
 *    a uniform unit vector u having var u_i = 1/3, var u_i^2 = 1/5 - 1/9 =
 *    4/45 and var u_i u_j = 1/15. In 2D every orientation is a turn about z
 *    and the angles' mean cosine and sine are within 4 standard errors
 *    (sqrt(1/2n)) of 0.
 *  - A fill that cannot fit, a bad template, region or target, is refused
 *    and leaves the world's particles as they were, and no clump.
 *  - A member counts its own part of its clump's mass where a mass is a
 *    share of the charge: a drum charged with clumps of one sphere reports
 *    the toe, shoulder, centre-of-mass angle and power from the centre of
 *    mass of the same spheres (to 1e-9); with dumbbells the power from the
 *    centre of mass is -omega sum M (X x g)_z over the clumps (to 1e-12),
 *    not twice it. */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define R 0.005 /* the dumbbell's sphere radius, m; centres R apart */

/* A world (dim 2 or 3) with gravity along -y, steel (7800 kg/m^3) with a
 * linear contact, and a dumbbell template. */
static demill_world *dumbbell_world(int dim, demill_id *mat, demill_id *tmpl)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    const double c[6] = {-0.5 * R, 0, 0, 0.5 * R, 0, 0}, r[2] = {R, R};
    DM_OK(w, demill_clump_template_add(w, *mat, 2, c, r, tmpl));
    return w;
}

/* The particles' positions, radii and clumps. */
typedef struct members {
    size_t n;
    double *x, *r;
    demill_id *clump;
} members;

static members read_members(demill_world *w)
{
    members m = {0};
    size_t n;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, NULL, 0, &n));
    m.n = n;
    m.x = malloc(3 * (n + 1) * sizeof *m.x);
    m.r = malloc((n + 1) * sizeof *m.r);
    m.clump = malloc((n + 1) * sizeof *m.clump);
    ck_assert(m.x && m.r && m.clump);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, m.x, n, &n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, m.r, n, &n));
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_CLUMP, m.clump, n, &n));
    return m;
}

static void free_members(members *m)
{
    free(m->x);
    free(m->r);
    free(m->clump);
}

START_TEST(drum_by_count_with_balls)
{
    demill_id mat, tmpl, drum;
    demill_world *w = dumbbell_world(3, &mat, &tmpl);
    const double D = 0.2, L = 0.1;
    DM_OK(w, demill_drum_create(w, mat, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, D));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, L));
    const double balls[2] = {0.012, 1.0};
    size_t added;
    DM_OK(w, demill_drum_fill(w, drum, mat, DEMILL_SIZES_CLASSES, balls, 2, DEMILL_FILL_COUNT,
                              100, 3, NULL, 0, &added));
    ck_assert_uint_eq(added, 100);
    demill_id ids[400];
    DM_OK(w, demill_clump_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, tmpl, DEMILL_FILL_COUNT,
                                      400, 5, ids, 400, &added));
    ck_assert_uint_eq(added, 400);
    size_t nclumps;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_CLUMP, NULL, 0, &nclumps));
    ck_assert_uint_eq(nclumps, 400);
    members m = read_members(w);
    ck_assert_uint_eq(m.n, 100 + 2 * 400);
    dm_test_check_no_overlap(m.n, m.x, m.r, m.clump);
    size_t outside = 0, in_clumps = 0;
    for (size_t i = 0; i < m.n; i++) {
        const double *x = m.x + 3 * i, Rr = 0.5 * D - m.r[i];
        outside += !(x[0] * x[0] + x[1] * x[1] <= Rr * Rr && fabs(x[2]) <= 0.5 * L - m.r[i]);
        in_clumps += m.clump[i] != DEMILL_ID_NONE;
    }
    ck_assert_msg(!outside, "%zu members are not inside the drum", outside);
    ck_assert_uint_eq(in_clumps, 800);
    /* the ids given are the clumps', of two members each */
    for (int k = 0; k < 400; k++) {
        size_t count;
        DM_OK(w, demill_clump_members(w, ids[k], NULL, 0, &count));
        ck_assert_uint_eq(count, 2);
    }
    free_members(&m);
    demill_world_destroy(w);
}
END_TEST

/* The volume of a dumbbell: two spheres of radius R, centres R apart, less
 * their lens (pi (4r + d)(2r - d)^2 / 12). */
static double dumbbell_volume(void)
{
    const double d = R;
    return 2.0 * 4.0 / 3.0 * M_PI * R * R * R -
           M_PI * (4.0 * R + d) * (2.0 * R - d) * (2.0 * R - d) / 12.0;
}

/* The area of a 2D dumbbell: two discs less their lens. */
static double dumbbell_area(void)
{
    const double d = R;
    return 2.0 * M_PI * R * R -
           (2.0 * R * R * acos(d / (2.0 * R)) - 0.5 * d * sqrt(4.0 * R * R - d * d));
}

START_TEST(mass_and_fraction_targets)
{
    demill_id mat, tmpl;
    for (int dim = 2; dim <= 3; dim++) {
        demill_world *w = dumbbell_world(dim, &mat, &tmpl);
        double M, V;
        DM_OK(w, demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_MASS, &M));
        DM_OK(w, demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_VOLUME, &V));
        if (dim == 3)
            DM_ASSERT_REL(V, dumbbell_volume(), 1e-12);
        const double box[6] = {0, 0, 0, 0.1, 0.1, dim == 3 ? 0.1 : 0};
        size_t added;
        DM_OK(w, demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl, DEMILL_FILL_MASS,
                                          37.3 * M, 1, NULL, 0, &added));
        ck_assert_uint_eq(added, 37);
        /* a fraction 0.2 of the box: its volume (area) over the clump's */
        const double phi = 0.2, measure = dim == 3 ? 1e-3 : 1e-2;
        const double one = dim == 3 ? dumbbell_volume() : dumbbell_area();
        const double want = phi * measure / one;
        demill_id tmpl2;
        demill_world *w2 = dumbbell_world(dim, &mat, &tmpl2);
        DM_OK(w2, demill_clump_fill_region(w2, DEMILL_REGION_BOX, box, 6, tmpl2,
                                           DEMILL_FILL_FRACTION, phi, 1, NULL, 0, &added));
        ck_assert_msg(fabs((double)added - want) <= 1.0, "%dD: %zu clumps for %.2f", dim, added,
                      want);
        members m = read_members(w2);
        dm_test_check_no_overlap(m.n, m.x, m.r, m.clump);
        size_t outside = 0;
        for (size_t i = 0; i < m.n; i++)
            for (int c = 0; c < dim; c++)
                outside += m.x[3 * i + c] - m.r[i] < box[c] || m.x[3 * i + c] + m.r[i] > box[3 + c];
        ck_assert_msg(!outside, "%dD: %zu members stick out of the box", dim, outside);
        free_members(&m);
        demill_world_destroy(w);
        demill_world_destroy(w2);
    }
}
END_TEST

START_TEST(same_seed_same_clumps)
{
    demill_id mat, tmpl, tmpl2, tmpl3, a[300], b[300];
    demill_world *w1 = dumbbell_world(3, &mat, &tmpl), *w2 = dumbbell_world(3, &mat, &tmpl2);
    const double cyl[7] = {0, 0, 0, 0, 0.15, 0, 0.05};
    DM_OK(w1, demill_clump_fill_region(w1, DEMILL_REGION_CYLINDER, cyl, 7, tmpl,
                                       DEMILL_FILL_COUNT, 300, 42, a, 300, NULL));
    DM_OK(w2, demill_clump_fill_region(w2, DEMILL_REGION_CYLINDER, cyl, 7, tmpl2,
                                       DEMILL_FILL_COUNT, 300, 42, b, 300, NULL));
    size_t differ = 0;
    for (int k = 0; k < 300; k++)
        for (int f = DEMILL_CLUMP_POSITION; f <= DEMILL_CLUMP_ORIENTATION; f++) {
            double u[4], v[4];
            DM_OK(w1, demill_clump_get(w1, a[k], f, u));
            DM_OK(w2, demill_clump_get(w2, b[k], f, v));
            differ += memcmp(u, v, (size_t)demill_clump_field_size(f) * sizeof *u) != 0;
        }
    ck_assert_msg(!differ, "%zu fields differ", differ);
    /* and another seed gives other clumps */
    demill_world *w3 = dumbbell_world(3, &mat, &tmpl3);
    DM_OK(w3, demill_clump_fill_region(w3, DEMILL_REGION_CYLINDER, cyl, 7, tmpl3,
                                       DEMILL_FILL_COUNT, 300, 43, b, 300, NULL));
    double u[3], v[3];
    DM_OK(w1, demill_clump_get(w1, a[0], DEMILL_CLUMP_POSITION, u));
    DM_OK(w3, demill_clump_get(w3, b[0], DEMILL_CLUMP_POSITION, v));
    ck_assert(memcmp(u, v, sizeof u) != 0);
    demill_world_destroy(w1);
    demill_world_destroy(w2);
    demill_world_destroy(w3);
}
END_TEST

/* The rotation matrix of the unit quaternion q (w, x, y, z), row-major. */
static void quat_matrix(const double q[4], double Q[9])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    memcpy(Q, m, sizeof m);
}

START_TEST(orientations_uniform)
{
    enum { N = 2000 };
    demill_id mat, tmpl;
    demill_world *w = dumbbell_world(3, &mat, &tmpl);
    /* a wide box, so that candidates are seldom refused for their
     * orientation and the fill's choice hardly selects among them */
    const double box[6] = {-1, 0, -1, 1, 0.2, 1};
    demill_id *ids = malloc(N * sizeof *ids);
    ck_assert(ids);
    DM_OK(w, demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl, DEMILL_FILL_COUNT, N,
                                      9, ids, N, NULL));
    for (int axis = 0; axis < 2; axis++) {
        double mean[3] = {0}, second[3][3] = {{0}};
        for (int k = 0; k < N; k++) {
            double q[4], Q[9];
            DM_OK(w, demill_clump_get(w, ids[k], DEMILL_CLUMP_ORIENTATION, q));
            quat_matrix(q, Q);
            const double u[3] = {Q[axis], Q[3 + axis], Q[6 + axis]}; /* the body axis */
            for (int i = 0; i < 3; i++) {
                mean[i] += u[i] / N;
                for (int j = 0; j < 3; j++)
                    second[i][j] += u[i] * u[j] / N;
            }
        }
        for (int i = 0; i < 3; i++) {
            ck_assert_msg(fabs(mean[i]) <= 4.0 * sqrt(1.0 / 3.0 / N), "axis %d: mean[%d] = %g",
                          axis, i, mean[i]);
            for (int j = 0; j < 3; j++) {
                const double want = i == j ? 1.0 / 3.0 : 0.0,
                             sd = sqrt((i == j ? 4.0 / 45.0 : 1.0 / 15.0) / N);
                ck_assert_msg(fabs(second[i][j] - want) <= 4.0 * sd,
                              "axis %d: <u%d u%d> = %g, expected %g within %g", axis, i, j,
                              second[i][j], want, 4.0 * sd);
            }
        }
    }
    free(ids);
    demill_world_destroy(w);
    /* 2D: turns about z of uniform angle */
    w = dumbbell_world(2, &mat, &tmpl);
    const double rect[6] = {-1, 0, 0, 1, 0.2, 0};
    enum { N2 = 400 };
    demill_id ids2[N2];
    DM_OK(w, demill_clump_fill_region(w, DEMILL_REGION_BOX, rect, 6, tmpl, DEMILL_FILL_COUNT, N2,
                                      9, ids2, N2, NULL));
    double c = 0.0, s = 0.0;
    for (int k = 0; k < N2; k++) {
        double q[4];
        DM_OK(w, demill_clump_get(w, ids2[k], DEMILL_CLUMP_ORIENTATION, q));
        ck_assert(q[1] == 0.0 && q[2] == 0.0);
        const double th = 2.0 * atan2(q[3], q[0]);
        c += cos(th) / N2;
        s += sin(th) / N2;
    }
    ck_assert_msg(fabs(c) <= 4.0 * sqrt(0.5 / N2) && fabs(s) <= 4.0 * sqrt(0.5 / N2),
                  "mean cos %g, sin %g", c, s);
    demill_world_destroy(w);
}
END_TEST

START_TEST(refusals_leave_the_world)
{
    demill_id mat, tmpl, ball;
    demill_world *w = dumbbell_world(3, &mat, &tmpl);
    const double x[3] = {0.05, 0.05, 0.05}, r = 0.01;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    size_t n0, n1;
    double *before = dm_test_state(w, &n0);
    const double box[6] = {0, 0, 0, 0.1, 0.1, 0.1}, nan_box[6] = {0, 0, 0, NAN, 0.1, 0.1};
    size_t added = 99;
    demill_id few[3];
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl,
                                              DEMILL_FILL_COUNT, 1e5, 1, NULL, 0, &added),
                     DEMILL_ERR_INVALID_VALUE); /* does not fit */
    ck_assert_uint_eq(added, 0);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl,
                                              DEMILL_FILL_COUNT, 5, 1, few, 3, &added),
                     DEMILL_ERR_BUFFER_TOO_SMALL);
    ck_assert_uint_eq(added, 5);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, mat,
                                              DEMILL_FILL_COUNT, 5, 1, NULL, 0, NULL),
                     DEMILL_ERR_INVALID_HANDLE);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl, 99, 5, 1, NULL,
                                              0, NULL),
                     DEMILL_ERR_UNKNOWN_KEY);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, nan_box, 6, tmpl,
                                              DEMILL_FILL_COUNT, 5, 1, NULL, 0, NULL),
                     DEMILL_ERR_NOT_FINITE);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_BOX, box, 6, tmpl,
                                              DEMILL_FILL_FRACTION, 1.5, 1, NULL, 0, NULL),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_clump_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, tmpl,
                                              DEMILL_FILL_COUNT, 5, 1, NULL, 0, NULL),
                     DEMILL_ERR_INVALID_VALUE); /* no drum */
    double *after = dm_test_state(w, &n1);
    ck_assert(n0 == n1 && !memcmp(before, after, 6 * n0 * sizeof *before));
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_CLUMP, NULL, 0, &n1));
    ck_assert_uint_eq(n1, 0);
    free(before);
    free(after);
    demill_world_destroy(w);
}
END_TEST

/* A 3D drum 0.2 x 0.1 m turning at 75 % of critical speed in a world of
 * gravity, with the material's Hertz-Mindlin contacts. */
static demill_world *turning_drum(demill_id *mat, demill_id *tmpl, demill_id *drum)
{
    demill_world *w = dumbbell_world(3, mat, tmpl);
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_YOUNGS_MODULUS, 1e8));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_FRICTION, 0.5));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_drum_create(w, *mat, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, 0.2));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, 0.1));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    return w;
}

static double drum_get(demill_world *w, demill_id drum, int key)
{
    double v;
    DM_OK(w, demill_drum_get(w, drum, key, &v));
    return v;
}

/* A charge of clumps of one sphere is the same charge as those spheres:
 * the drum reports the same toe, shoulder and centre of mass angles and
 * power from the centre of mass, after 0.05 s of turning (a one-sphere
 * clump moves as its sphere to round-off: physics_clumps). */
START_TEST(one_sphere_clumps_are_spheres)
{
    demill_id mat, tmpl, drum, mat2, tmpl2, drum2, one;
    demill_world *w = turning_drum(&mat, &tmpl, &drum), *w2 = turning_drum(&mat2, &tmpl2, &drum2);
    const double ball[2] = {0.012, 1.0}, at[3] = {0, 0, 0}, r = 0.006;
    size_t n;
    DM_OK(w, demill_drum_fill(w, drum, mat, DEMILL_SIZES_CLASSES, ball, 2, DEMILL_FILL_COUNT, 300,
                              2, NULL, 0, &n));
    double *x = malloc(3 * n * sizeof *x);
    ck_assert(x);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, n, &n));
    DM_OK(w2, demill_clump_template_add(w2, mat2, 1, at, &r, &one));
    for (size_t k = 0; k < n; k++) {
        demill_id c;
        DM_OK(w2, demill_clump_add(w2, one, x + 3 * k, NULL, &c));
    }
    free(x);
    DM_OK(w, demill_world_step(w, 5000));
    DM_OK(w2, demill_world_step(w2, 5000));
    const int keys[4] = {DEMILL_DRUM_TOE_ANGLE, DEMILL_DRUM_SHOULDER_ANGLE, DEMILL_DRUM_COM_ANGLE,
                         DEMILL_DRUM_POWER_CM};
    for (int k = 0; k < 4; k++) {
        const double a = drum_get(w, drum, keys[k]), b = drum_get(w2, drum2, keys[k]);
        ck_assert_msg(fabs(a - b) <= 1e-9 * fabs(a), "drum key %d: spheres %.17g, clumps %.17g",
                      keys[k], a, b);
    }
    demill_world_destroy(w);
    demill_world_destroy(w2);
}
END_TEST

/* Dumbbells (two equal spheres: a member's share is half its clump's mass,
 * and the members' mean place is the clump's centre of mass) in a turning
 * drum: the power from the centre of mass, -omega (M x_cm x g)_z summed
 * over the charge, is the clumps' own, summed from their masses and centres
 * (DEMILL_CLUMP_MASS, _POSITION), to round-off; a member's own mass counted
 * as the whole clump's would double it. */
START_TEST(dumbbells_weigh_their_mass)
{
    demill_id mat, tmpl, drum, ids[200];
    demill_world *w = turning_drum(&mat, &tmpl, &drum);
    DM_OK(w, demill_clump_fill_region(w, DEMILL_REGION_DRUM, NULL, 0, tmpl, DEMILL_FILL_COUNT,
                                      200, 4, ids, 200, NULL));
    DM_OK(w, demill_world_step(w, 3000));
    double g[2], torque = 0.0, mass = 0.0;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_X, &g[0]));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Y, &g[1]));
    for (int k = 0; k < 200; k++) {
        double m, X[3];
        DM_OK(w, demill_clump_get(w, ids[k], DEMILL_CLUMP_MASS, &m));
        DM_OK(w, demill_clump_get(w, ids[k], DEMILL_CLUMP_POSITION, X));
        torque += m * (X[0] * g[1] - X[1] * g[0]); /* about the drum's axis, z */
        mass += m;
    }
    const double omega = drum_get(w, drum, DEMILL_DRUM_CURRENT_SPEED);
    ck_assert(omega > 0.0);
    DM_ASSERT_REL(drum_get(w, drum, DEMILL_DRUM_POWER_CM), -omega * torque, 1e-12);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("clump_fill");
    TCase *tc = tcase_create("clump_fill");
    tcase_add_test(tc, drum_by_count_with_balls);
    tcase_add_test(tc, mass_and_fraction_targets);
    tcase_add_test(tc, same_seed_same_clumps);
    tcase_add_test(tc, orientations_uniform);
    tcase_add_test(tc, refusals_leave_the_world);
    tcase_add_test(tc, one_sphere_clumps_are_spheres);
    tcase_add_test(tc, dumbbells_weigh_their_mass);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
