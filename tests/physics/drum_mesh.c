/* drum_mesh.c: a drum built from meshes attached to it (demill_drum_attach_wall,
 * DEMILL_DRUM_SHELL = 0), against the analytic drum.
 *
 * - A ball pressed 1e-4 m into a lifter's leading face, a box mesh attached
 *   as the drum's lifter, feels k delta (linear law, hand-derived) as on the
 *   analytic lifter of the same section, to 1e-10; the drum's force is the
 *   reaction and its torque the reaction's moment about the axis,
 *   -(R - h/2) k delta.
 * - Attaching a mesh at a drum angle of 1.234 rad leaves every vertex where
 *   it was (to 1e-15 m), and it then turns with the drum (each vertex turned
 *   by the drum's angle about the axis, to 1e-14 m).
 * - A small 3D mill (about 360 balls of 4 mm radius, drum 0.15 m across,
 *   6 lifters, 30 % filling, 75 % of critical) from the same settled charge:
 *   the analytic drum against the same drum from binary STLs of a 120-gon
 *   shell with fan caps (part shell) and of box lifters (part lifters): the mean power over revolutions 2 to 4
 *   within 2 %, the mean toe and shoulder angles within 2 degrees. The
 *   120-gon's flats lie R (1 - cos(pi/120)) = 26 um inside the circle, a
 *   hundredth of a ball radius.
 * - A checkpoint and a snapshot of a turning drum with an attached mesh and
 *   a ball on it run on bitwise as the world they came from (500 steps),
 *   the wall still attached.
 * - Bad attachments: clear errors, the world unchanged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics/geometry/geometry.h"
#include "stl_write.h"
#include "testutil.h"

#define K 1e5       /* linear normal stiffness, N/m */
#define DELTA 1e-4  /* the overlap pressed in, m */
#define R_DRUM 0.15 /* shell radius of the pressing tests, m */
#define H 0.02      /* lifter height, m */
#define W 0.02      /* lifter width, m */
#define LEN 0.1     /* drum length, m */

/* A growing triangle soup: 9 coordinates (3 corners) a triangle. */
typedef struct soup {
    double *c;
    size_t n, cap;
} soup;

static void tri(soup *s, const double *a, const double *b, const double *c)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 256;
        s->c = realloc(s->c, 9 * s->cap * sizeof *s->c);
        ck_assert(s->c);
    }
    double *t = s->c + 9 * s->n++;
    memcpy(t, a, 3 * sizeof *a);
    memcpy(t + 3, b, 3 * sizeof *b);
    memcpy(t + 6, c, 3 * sizeof *c);
}

static void quad(soup *s, const double *a, const double *b, const double *c, const double *d)
{
    tri(s, a, b, c);
    tri(s, a, c, d);
}

/* A box lifter at polar angle a, from radius R - h to R + w (sunk into the
 * shell, like the analytic lifter), w wide, along z over length l. */
static void box_lifter(soup *s, double a, double R, double h, double w, double l)
{
    const double u[2] = {cos(a), sin(a)}, t[2] = {-sin(a), cos(a)};
    const double rr[4] = {R - h, R + w, R + w, R - h}, tt[4] = {-0.5 * w, -0.5 * w, 0.5 * w, 0.5 * w};
    double p[8][3];
    for (int k = 0; k < 8; k++) {
        p[k][0] = rr[k % 4] * u[0] + tt[k % 4] * t[0];
        p[k][1] = rr[k % 4] * u[1] + tt[k % 4] * t[1];
        p[k][2] = k < 4 ? -0.5 * l : 0.5 * l;
    }
    for (int k = 0; k < 4; k++)
        quad(s, p[k], p[(k + 1) % 4], p[4 + (k + 1) % 4], p[4 + k]);
    quad(s, p[0], p[3], p[2], p[1]);
    quad(s, p[4], p[5], p[6], p[7]);
}

/* A shell of n flat sides (vertices at radius R) and fan caps at z = ±l/2. */
static void shell(soup *s, int n, double R, double l)
{
    const double top[3] = {0, 0, 0.5 * l}, bottom[3] = {0, 0, -0.5 * l};
    for (int k = 0; k < n; k++) {
        const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
        const double p0[3] = {R * cos(a0), R * sin(a0), -0.5 * l};
        const double p1[3] = {R * cos(a1), R * sin(a1), -0.5 * l};
        const double q0[3] = {p0[0], p0[1], 0.5 * l}, q1[3] = {p1[0], p1[1], 0.5 * l};
        quad(s, p0, p1, q1, q0);
        tri(s, bottom, p1, p0);
        tri(s, top, q0, q1);
    }
}

/* The soup as a binary STL file in memory, loaded as a wall. */
static demill_id stl_wall(demill_world *w, demill_id mat, const soup *s)
{
    size_t size;
    uint8_t *bytes = dm_test_stl_binary("drum", s->c, s->n, NULL, &size);
    demill_id id;
    DM_OK(w, demill_wall_add_stl(w, mat, bytes, size, 1.0, NULL, &id));
    free(bytes);
    return id;
}

/* The soup as a mesh wall of exact doubles (3 vertices a triangle). */
static demill_id mesh_wall(demill_world *w, demill_id mat, const soup *s)
{
    uint32_t *el = malloc(3 * s->n * sizeof *el);
    ck_assert(el);
    for (size_t k = 0; k < 3 * s->n; k++)
        el[k] = (uint32_t)k;
    demill_id id;
    DM_OK(w, demill_wall_add_mesh(w, mat, 3 * s->n, s->c, s->n, el, &id));
    free(el);
    return id;
}

/* A world without gravity, linear undamped contacts, a drum 0.3 m across
 * without its analytic shell, and a ball of radius 0.01 pressed DELTA into
 * the leading face (x = w/2) of a lifter at 6 o'clock, half-way up it: the
 * analytic lifter (mesh 0) or a box mesh attached as the drum's lifter. */
static demill_world *pressed(int mesh, demill_id *drum, demill_id *ball, demill_id *wall)
{
    demill_id mat;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    DM_OK(w, demill_drum_create(w, mat, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SHELL, 0));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, 2 * R_DRUM));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, LEN));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_HEIGHT, H));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_WIDTH, W));
    if (mesh) {
        soup s = {0};
        box_lifter(&s, 1.5 * M_PI, R_DRUM, H, W, LEN);
        *wall = mesh_wall(w, mat, &s);
        free(s.c);
        DM_OK(w, demill_drum_attach_wall(w, *drum, *wall, DEMILL_DRUM_PART_LIFTERS));
    } else {
        DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTERS, 1));
    }
    const double r = 0.01, x[3] = {0.5 * W + r - DELTA, -(R_DRUM - 0.5 * H), 0.01};
    demill_id b;
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, ball ? ball : &b));
    DM_OK(w, demill_world_step(w, 0)); /* (forces at the current state) */
    return w;
}

START_TEST(pressed_on_a_mesh_lifter)
{
    double f[2][3], torque[2], force[2][3];
    for (int mesh = 0; mesh < 2; mesh++) {
        demill_id drum, ball, wall = 0;
        demill_world *w = pressed(mesh, &drum, &ball, &wall);
        DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_FORCE, f[mesh]));
        DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_TORQUE, &torque[mesh]));
        for (int c = 0; c < 3; c++)
            DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_FORCE_X + c, &force[mesh][c]));
        demill_world_destroy(w);
    }
    for (int mesh = 0; mesh < 2; mesh++) {
        /* k delta along +x on the ball; its reaction on the drum; the
         * reaction's moment about the axis, at y = -(R - h/2) */
        DM_ASSERT_REL(f[mesh][0], K * DELTA, 1e-10);
        ck_assert_msg(fabs(f[mesh][1]) < 1e-10 * K * DELTA && fabs(f[mesh][2]) < 1e-10 * K * DELTA,
                      "mesh %d: force (%g, %g, %g)", mesh, f[mesh][0], f[mesh][1], f[mesh][2]);
        DM_ASSERT_REL(force[mesh][0], -K * DELTA, 1e-10);
        DM_ASSERT_REL(torque[mesh], -(R_DRUM - 0.5 * H) * K * DELTA, 1e-10);
    }
    for (int c = 0; c < 3; c++)
        ck_assert_msg(fabs(f[1][c] - f[0][c]) <= 1e-10 * K * DELTA,
                      "component %d: mesh %.17g, analytic %.17g", c, f[1][c], f[0][c]);
}
END_TEST

/* The wall slot of a wall id: its handle's slot. */
static const dm_wall *wall_of(demill_world *w, demill_id id)
{
    return &w->walls[w->wh.slot[(uint32_t)id]];
}

START_TEST(attaching_moves_nothing)
{
    demill_id mat, drum, wall;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_drum_create(w, mat, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 1.234 / 0.01)); /* 1.234 rad in 0.01 s */
    DM_OK(w, demill_world_step(w, 1000));
    double theta;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ANGLE, &theta));
    DM_ASSERT_REL(theta, 1.234, 1e-9);
    soup s = {0};
    box_lifter(&s, 0.3, R_DRUM, H, W, LEN);
    wall = mesh_wall(w, mat, &s);
    const double spin[3] = {0.1, 0.2, 0.3}, centre[3] = {0.01, 0.02, 0.03};
    DM_OK(w, demill_wall_set_motion(w, wall, NULL, spin, centre));
    DM_OK(w, demill_world_step(w, 100)); /* its own motion turns it a little */
    const dm_wall *wl = wall_of(w, wall);
    const uint32_t nv = wl->mesh->nv;
    double *before = malloc(3 * nv * sizeof *before);
    ck_assert(before);
    for (uint32_t k = 0; k < nv; k++)
        dm_mesh_vertex_at(wl, k, before + 3 * k);
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ANGLE, &theta));
    DM_OK(w, demill_drum_attach_wall(w, drum, wall, DEMILL_DRUM_PART_LIFTERS));
    wl = wall_of(w, wall);
    for (uint32_t k = 0; k < 3 * nv; k += 3) {
        double x[3];
        dm_mesh_vertex_at(wl, k / 3, x);
        for (int c = 0; c < 3; c++)
            ck_assert_msg(fabs(x[c] - before[k + c]) <= 1e-15, "vertex %u moved by %g m", k / 3,
                          x[c] - before[k + c]);
    }
    /* then it turns with the drum: each vertex by the drum's angle */
    DM_OK(w, demill_world_step(w, 500));
    double theta1;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ANGLE, &theta1));
    const double c = cos(theta1 - theta), sn = sin(theta1 - theta);
    ck_assert_msg(theta1 - theta > 0.1, "turned %g rad", theta1 - theta);
    for (uint32_t k = 0; k < nv; k++) {
        double x[3];
        dm_mesh_vertex_at(wl, k, x);
        const double *b = before + 3 * k;
        const double want[3] = {c * b[0] - sn * b[1], sn * b[0] + c * b[1], b[2]};
        for (int q = 0; q < 3; q++)
            ck_assert_msg(fabs(x[q] - want[q]) <= 1e-14, "vertex %u: %.17g, turned %.17g", k, x[q],
                          want[q]);
    }
    free(before);
    free(s.c);
    demill_world_destroy(w);
}
END_TEST

/* The copy's drum has the energy in of the original's, and its wall is
 * still attached: a second attachment is refused. */
static void mesh_attached(demill_world *w, demill_world *v, int way, void *ctx)
{
    (void)way;
    const demill_id drum = *(const demill_id *)ctx;
    demill_id ids[2];
    size_t nd;
    double energy0, energy1;
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_DRUM, ids, 1, &nd));
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_WALL, ids + 1, 1, &nd));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ENERGY_IN, &energy0));
    DM_OK(v, demill_drum_get(v, ids[0], DEMILL_DRUM_ENERGY_IN, &energy1));
    ck_assert(energy0 != 0.0 && energy0 == energy1);
    ck_assert_int_eq(demill_drum_attach_wall(v, ids[0], ids[1], DEMILL_DRUM_PART_SHELL),
                     DEMILL_ERR_INVALID_VALUE);
}

START_TEST(checkpoint_and_snapshot_carry_the_attachment)
{
    demill_id drum, wall;
    demill_world *w = pressed(1, &drum, NULL, &wall); /* the ball on the lifter mesh */
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 3.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_world_step(w, 300));
    dm_test_copies_run_on(w, 500, mesh_attached, &drum);
    demill_world_destroy(w);
}
END_TEST

START_TEST(bad_attachments)
{
    demill_id drum, wall, plane, other_drum, other_wall, mat;
    demill_world *w = pressed(1, &drum, NULL, &wall);
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, &mat, 1, NULL));
    const double o[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, mat, o, up, &plane));
    demill_id om;
    demill_world *v = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &om);
    DM_OK(v, demill_drum_create(v, om, &other_drum));
    DM_OK(v, demill_wall_add_plane(v, om, o, up, &other_wall));
    size_t size, size1;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    uint8_t *before = malloc(size), *after = malloc(size);
    ck_assert(before && after);
    DM_OK(w, demill_world_save_buffer(w, before, size, &size));
    const struct {
        demill_id drum, wall;
        int32_t part;
        demill_status want;
        const char *what;
    } cases[] = {
        {drum, drum, DEMILL_DRUM_PART_SHELL, DEMILL_ERR_INVALID_HANDLE, "wall"},
        {drum, wall, DEMILL_DRUM_PART_SHELL, DEMILL_ERR_INVALID_VALUE, "attached to the drum already"},
        {drum, plane, 4, DEMILL_ERR_UNKNOWN_KEY, "not a part of the drum"},
        {drum, plane, 0, DEMILL_ERR_UNKNOWN_KEY, "not a part of the drum"},
        {drum, other_wall, DEMILL_DRUM_PART_SHELL, DEMILL_ERR_INVALID_HANDLE, "wall"},
        {other_drum, plane, DEMILL_DRUM_PART_SHELL, DEMILL_ERR_INVALID_HANDLE, "drum"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        ck_assert_int_eq(demill_drum_attach_wall(w, cases[k].drum, cases[k].wall, cases[k].part),
                         cases[k].want);
        ck_assert_msg(strstr(demill_world_last_error(w), cases[k].what), "case %zu: %s", k,
                      demill_world_last_error(w));
        DM_OK(w, demill_world_save_buffer(w, after, size, &size1));
        ck_assert_msg(size1 == size && memcmp(before, after, size) == 0,
                      "case %zu changed the world", k);
    }
    ck_assert_int_eq(demill_wall_set_motion(w, wall, up, NULL, NULL), DEMILL_ERR_INVALID_VALUE);
    /* removing the drum removes its attached wall; removing the wall works */
    DM_OK(w, demill_wall_remove(w, plane));
    DM_OK(w, demill_drum_remove(w, drum));
    ck_assert_int_eq(demill_wall_remove(w, wall), DEMILL_ERR_INVALID_HANDLE);
    free(before);
    free(after);
    demill_world_destroy(v);
    demill_world_destroy(w);
}
END_TEST

/* ---- the mill ---------------------------------------------------------------- */

#define MILL_D 0.15
#define MILL_L 0.03
#define MILL_LIFTER 0.006
#define MILL_LIFTERS 6
#define MILL_BALL 0.004

static double drum_value(demill_world *w, demill_id drum, int key)
{
    double v;
    DM_OK(w, demill_drum_get(w, drum, key, &v));
    return v;
}

/* The physics_mill power test's mill (tests/physics/mill.c): steel balls of
 * 4 mm radius, μ 0.5 with each other and the liner, 30 % filling, settled. */
static demill_world *mill_settled(demill_id *drum, demill_id *liner)
{
    demill_world *w;
    demill_id balls;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-5));
    dm_test_mill_materials(w, &balls, liner);
    DM_OK(w, demill_pair_set(w, balls, balls, DEMILL_PAIR_FRICTION, 0.5));
    DM_OK(w, demill_pair_set(w, balls, *liner, DEMILL_PAIR_FRICTION, 0.5));
    DM_OK(w, demill_drum_create(w, *liner, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, MILL_D));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, MILL_L));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_HEIGHT, MILL_LIFTER));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_WIDTH, MILL_LIFTER));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTERS, MILL_LIFTERS));
    const double sizes[2] = {2 * MILL_BALL, 1.0};
    DM_OK(w, demill_drum_fill(w, *drum, balls, DEMILL_SIZES_CLASSES, sizes, 2,
                              DEMILL_FILL_FRACTION, 0.3, 42, NULL, 0, NULL));
    DM_OK(w, demill_world_step(w, 15000));
    return w;
}

/* Replaces the analytic shell, caps and lifters by one STL of them all. */
static void mill_to_mesh(demill_world *w, demill_id drum, demill_id liner)
{
    soup s = {0}, l = {0};
    shell(&s, 120, 0.5 * MILL_D, MILL_L);
    double phase;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_LIFTER_PHASE, &phase));
    const double theta = drum_value(w, drum, DEMILL_DRUM_ANGLE);
    for (int k = 0; k < MILL_LIFTERS; k++)
        box_lifter(&l, phase + theta + 2 * M_PI * k / MILL_LIFTERS, 0.5 * MILL_D, MILL_LIFTER,
                   MILL_LIFTER, MILL_L);
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 0));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SHELL, 0));
    DM_OK(w, demill_drum_attach_wall(w, drum, stl_wall(w, liner, &s), DEMILL_DRUM_PART_SHELL));
    DM_OK(w, demill_drum_attach_wall(w, drum, stl_wall(w, liner, &l), DEMILL_DRUM_PART_LIFTERS));
    free(s.c);
    free(l.c);
}

/* Mean power, toe and shoulder over revolutions 2 to 4 at 75 % critical. */
static void mill_means(demill_world *w, demill_id drum, double out[3])
{
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    const int keys[3] = {DEMILL_DRUM_POWER_MEAN, DEMILL_DRUM_TOE_ANGLE_MEAN,
                         DEMILL_DRUM_SHOULDER_ANGLE_MEAN};
    out[0] = out[1] = out[2] = 0;
    const double rev0 = drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS);
    for (int rev = 1; rev <= 4; rev++) {
        while (drum_value(w, drum, DEMILL_DRUM_REVOLUTIONS) < rev0 + rev)
            DM_OK(w, demill_world_step(w, 100));
        for (int q = 0; q < 3 && rev > 1; q++)
            out[q] += drum_value(w, drum, keys[q]) / 3;
    }
}

START_TEST(mill_from_stl_against_analytic)
{
    demill_id drum, liner;
    demill_world *w = mill_settled(&drum, &liner);
    size_t size;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    void *bytes = malloc(size);
    ck_assert(bytes);
    DM_OK(w, demill_world_save_buffer(w, bytes, size, &size));
    double analytic[3], meshed[3];
    mill_means(w, drum, analytic);
    DM_OK(w, demill_world_load_buffer(w, bytes, size));
    free(bytes);
    mill_to_mesh(w, drum, liner);
    mill_means(w, drum, meshed);
    printf("mill: power %.5f W (analytic %.5f W), toe %.2f (%.2f) deg, shoulder %.2f (%.2f) "
           "deg\n",
           meshed[0], analytic[0], meshed[1] * 180 / M_PI, analytic[1] * 180 / M_PI,
           meshed[2] * 180 / M_PI, analytic[2] * 180 / M_PI);
    ck_assert_msg(analytic[0] > 0, "no power drawn (%g W)", analytic[0]);
    ck_assert_msg(fabs(meshed[0] - analytic[0]) <= 0.02 * analytic[0],
                  "power: mesh %.5f W, analytic %.5f W", meshed[0], analytic[0]);
    for (int q = 1; q < 3; q++)
        ck_assert_msg(fabs(meshed[q] - analytic[q]) <= 2 * M_PI / 180,
                      "%s: mesh %.2f deg, analytic %.2f deg", q == 1 ? "toe" : "shoulder",
                      meshed[q] * 180 / M_PI, analytic[q] * 180 / M_PI);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("drum_mesh");
    TCase *tc = tcase_create("drum_mesh");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, pressed_on_a_mesh_lifter);
    tcase_add_test(tc, attaching_moves_nothing);
    tcase_add_test(tc, checkpoint_and_snapshot_carry_the_attachment);
    tcase_add_test(tc, bad_attachments);
    tcase_add_test(tc, mill_from_stl_against_analytic);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
