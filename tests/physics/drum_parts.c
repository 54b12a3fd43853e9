/* drum_parts.c: parts of the drum beyond its analytic walls: finite walls
 * attached to the drum (demill_drum_attach_wall).
 *
 * - A disc, a capped cylinder (its side and a cap) and a rectangle attached
 *   to a drum turning at 100 rad/s, after 1 rad: a ball pressed 1e-4 m into
 *   each where the drum's rotation has carried it feels k delta along the
 *   face's normal turned by the drum's angle (1e-9), the drum's force is
 *   minus their sum and its torque the sum of their moments about the axis,
 *   and the wall's velocity at each contact point is omega z x r (rigid
 *   rotation about the axis, to 1e-12).
 * - A checkpoint and a snapshot of the turning drum with its finite walls run
 *   on bitwise; removing the drum removes them with their caps.
 * - Bad input (a harmonic motion for an attached wall) is refused with its
 *   code, the world unchanged (its checkpoint bytes). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "world/world.h"

#define K 1e5       /* linear normal stiffness, N/m */
#define DELTA 1e-4  /* the overlap pressed in, m */
#define R_DRUM 0.15 /* shell radius, m */
#define H 0.02      /* lifter height, m */
#define W 0.02      /* lifter width, m */
#define LEN 0.1     /* drum length, m */
#define BALL 0.005  /* ball radius, m */
#define NLIFT 8
#define OMEGA 100.0 /* drum speed of the turned cases, rad/s */

/* A world without gravity, linear undamped contacts of stiffness K and a
 * drum 0.3 m across, standing. */
static demill_world *drum_world(int dim, demill_id *mat, demill_id *drum)
{
    demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, mat);
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    DM_OK(w, demill_drum_create(w, *mat, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, 2 * R_DRUM));
    if (dim == 3)
        DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, LEN));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_HEIGHT, H));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LIFTER_WIDTH, W));
    return w;
}

/* Turns the drum by 1 rad (1000 steps of 1e-5 s at 100 rad/s) and stops it
 * there. */
static double turn(demill_world *w, demill_id drum)
{
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, OMEGA));
    DM_OK(w, demill_world_step(w, 1000));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 0.0));
    double theta;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ANGLE, &theta));
    DM_ASSERT_REL(theta, 1.0, 1e-9);
    return theta;
}

/* ---- finite walls attached to the drum ------------------------------------------ */

/* The drum turning at OMEGA with a disc (centre (0.08, 0, 0), normal z,
 * radius 0.02), a cylinder with both caps (axis z from (-0.08, 0, -0.02),
 * radius 0.01, length 0.04) and a rectangle (centre (0, 0.08, 0), normal x,
 * 0.02 along z, 0.01 along y) attached at angle 0, then turned by 1 rad;
 * balls pressed DELTA into the disc's top, the cylinder's side (at -x) and
 * top cap, and the rectangle's +x face, where the rotation has carried
 * them. want: the unit normal of each face (from the wall to its ball). */
static demill_world *finite_pressed(demill_id *drum, demill_id walls[3], demill_id ids[4],
                                    double want[4][3], double *theta)
{
    demill_id mat;
    demill_world *w = drum_world(3, &mat, drum);
    const double z[3] = {0, 0, 1}, xh[3] = {1, 0, 0};
    const double disc_c[3] = {0.08, 0, 0}, cyl_p[3] = {-0.08, 0, -0.02}, rect_c[3] = {0, 0.08, 0};
    DM_OK(w, demill_wall_add_disc(w, mat, disc_c, z, 0.02, 0.0, &walls[0]));
    DM_OK(w, demill_wall_add_cylinder(w, mat, cyl_p, z, 0.01, 0.04, DEMILL_CAPS_BOTH, &walls[1]));
    DM_OK(w, demill_wall_add_rectangle(w, mat, rect_c, xh, z, 0.02, 0.01, &walls[2]));
    for (int k = 0; k < 3; k++)
        DM_OK(w, demill_drum_attach_wall(w, *drum, walls[k], DEMILL_DRUM_PART_LIFTERS));
    *theta = turn(w, *drum);
    const double c = cos(*theta), s = sin(*theta);
    /* at drum angle 0: the balls' centres and the faces' normals */
    const double x0[4][3] = {{0.085, 0.003, BALL - DELTA},
                             {-0.08 - 0.01 - BALL + DELTA, 0.0, 0.0},
                             {-0.078, 0.001, 0.02 + BALL - DELTA},
                             {BALL - DELTA, 0.085, 0.004}};
    const double n0[4][3] = {{0, 0, 1}, {-1, 0, 0}, {0, 0, 1}, {1, 0, 0}};
    double x[12], r[4];
    for (int k = 0; k < 4; k++) {
        x[3 * k] = c * x0[k][0] - s * x0[k][1];
        x[3 * k + 1] = s * x0[k][0] + c * x0[k][1];
        x[3 * k + 2] = x0[k][2];
        want[k][0] = c * n0[k][0] - s * n0[k][1];
        want[k][1] = s * n0[k][0] + c * n0[k][1];
        want[k][2] = n0[k][2];
        r[k] = BALL;
    }
    DM_OK(w, demill_particles_add(w, mat, 4, x, r, NULL, 0, ids));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SPEED, OMEGA)); /* turning again, from here */
    DM_OK(w, demill_world_step(w, 0));
    return w;
}

START_TEST(finite_walls_turn_with_the_drum)
{
    demill_id drum, walls[3], ids[4];
    double want[4][3], theta;
    demill_world *w = finite_pressed(&drum, walls, ids, want, &theta);
    double sum[3] = {0, 0, 0}, moment = 0.0;
    for (int k = 0; k < 4; k++) {
        double f[3], x[3];
        DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_FORCE, f));
        DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_POSITION, x));
        for (int c = 0; c < 3; c++) {
            ck_assert_msg(fabs(f[c] - K * DELTA * want[k][c]) <= 1e-9 * K * DELTA,
                          "ball %d: force[%d] = %.17g, expected %.17g", k, c, f[c],
                          K * DELTA * want[k][c]);
            sum[c] += f[c];
        }
        /* the force acts at the contact point, r - delta/2 from the centre
         * towards the wall: its moment about the axis */
        const double arm = BALL - 0.5 * DELTA;
        const double cp[2] = {x[0] - arm * want[k][0], x[1] - arm * want[k][1]};
        moment += cp[0] * f[1] - cp[1] * f[0];
    }
    double torque, force[3];
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_TORQUE, &torque));
    for (int c = 0; c < 3; c++) {
        DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_FORCE_X + c, &force[c]));
        ck_assert_msg(fabs(force[c] + sum[c]) <= 1e-12 * K * DELTA, "drum force[%d] %.17g, %.17g",
                      c, force[c], -sum[c]);
    }
    ck_assert_msg(fabs(torque + moment) <= 1e-12 * K * DELTA, "drum torque %.17g, expected %.17g",
                  torque, -moment);
    /* the wall's velocity at each contact point: omega z x cp */
    int touching = 0;
    uint32_t g0 = 0;
    for (int b = 0; b < DM_KERNELS; b++) {
        const dm_bucket *bk = &w->pw.b[b];
        for (uint32_t p = 0; p < bk->n; p++) {
            const uint32_t q = g0 + p;
            if (w->wg.delta[q] <= 0.0)
                continue;
            const double *cp = w->wg.cp + 3 * q, *vw = w->wg.vw + 3 * q;
            const double expect[3] = {-OMEGA * cp[1], OMEGA * cp[0], 0.0};
            for (int c = 0; c < 3; c++)
                ck_assert_msg(fabs(vw[c] - expect[c]) <= 1e-12 * OMEGA * hypot(cp[0], cp[1]),
                              "contact %u: wall velocity[%d] %.17g, omega x r %.17g", q, c, vw[c],
                              expect[c]);
            touching++;
        }
        g0 += bk->n;
    }
    ck_assert_int_eq(touching, 4);
    demill_world_destroy(w);
}
END_TEST

/* Every particle's position and velocity, in id order. */
static double *state_of(demill_world *w, size_t *n)
{
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, NULL, 0, n));
    double *x = malloc(6 * *n * sizeof *x);
    ck_assert(x);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, 3 * *n, n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_VELOCITY, x + 3 * *n, 3 * *n, n));
    return x;
}

START_TEST(checkpoint_and_snapshot_carry_finite_walls)
{
    demill_id drum, walls[3], ids[4];
    double want[4][3], theta;
    demill_world *w = finite_pressed(&drum, walls, ids, want, &theta);
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 3.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_world_step(w, 300));
    size_t size, n0, n1;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    void *bytes = malloc(size);
    ck_assert(bytes);
    DM_OK(w, demill_world_save_buffer(w, bytes, size, &size));
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, 500));
    double *ref = state_of(w, &n0), energy0;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ENERGY_IN, &energy0));
    ck_assert(energy0 != 0.0);
    for (int way = 0; way < 2; way++) {
        demill_world *v;
        ck_assert_int_eq(demill_world_create(3, &v), DEMILL_OK);
        if (way)
            DM_OK(v, demill_snapshot_restore(v, snap));
        else
            DM_OK(v, demill_world_load_buffer(v, bytes, size));
        demill_id d, found[4];
        size_t nd, nw;
        DM_OK(v, demill_world_ids(v, DEMILL_KIND_DRUM, &d, 1, &nd));
        DM_OK(v, demill_world_ids(v, DEMILL_KIND_WALL, found, 4, &nw));
        ck_assert_uint_eq(nw, 3); /* the cylinder's caps have no ids */
        DM_OK(v, demill_world_step(v, 500));
        double *got = state_of(v, &n1), energy1;
        DM_OK(v, demill_drum_get(v, d, DEMILL_DRUM_ENERGY_IN, &energy1));
        ck_assert_uint_eq(n0, n1);
        ck_assert_msg(memcmp(ref, got, 6 * n0 * sizeof *ref) == 0 && energy0 == energy1,
                      "%s: the run differs", way ? "snapshot" : "checkpoint");
        for (size_t k = 0; k < nw; k++) /* still attached */
            ck_assert_int_eq(demill_drum_attach_wall(v, d, found[k], DEMILL_DRUM_PART_SHELL),
                             DEMILL_ERR_INVALID_VALUE);
        /* the drum takes them with it, caps and all */
        DM_OK(v, demill_drum_remove(v, d));
        DM_OK(v, demill_world_ids(v, DEMILL_KIND_WALL, NULL, 0, &nw));
        ck_assert_uint_eq(nw, 0);
        for (uint32_t k = 0; k < v->nwalls; k++)
            ck_assert_int_eq(v->walls[k].kind, 0);
        free(got);
        demill_world_destroy(v);
    }
    free(ref);
    free(bytes);
    demill_snapshot_free(snap);
    demill_world_destroy(w);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------ */

START_TEST(bad_input_leaves_the_world_unchanged)
{
    demill_id drum, walls[3], ids[4];
    double want[4][3], theta;
    demill_world *w = finite_pressed(&drum, walls, ids, want, &theta);
    size_t size, size1;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    uint8_t *before = malloc(size), *after = malloc(size);
    ck_assert(before && after);
    DM_OK(w, demill_world_save_buffer(w, before, size, &size));
    /* an attached wall's motion is the drum's */
    const double axis[3] = {1, 0, 0};
    ck_assert_int_eq(demill_wall_set_harmonic(w, walls[1], DEMILL_HARMONIC_TRANSLATION, axis,
                                              0.01, 10.0, 0.0),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_msg(strstr(demill_world_last_error(w), "attached to the drum"), "%s",
                  demill_world_last_error(w));
    DM_OK(w, demill_world_save_buffer(w, after, size, &size1));
    ck_assert_msg(size1 == size && memcmp(before, after, size) == 0,
                  "wall_set_harmonic changed the world");
    free(before);
    free(after);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("drum_parts");
    TCase *tc = tcase_create("drum_parts");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, finite_walls_turn_with_the_drum);
    tcase_add_test(tc, checkpoint_and_snapshot_carry_finite_walls);
    tcase_add_test(tc, bad_input_leaves_the_world_unchanged);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
