/* drum_parts.c: parts of the drum beyond its analytic walls: lifters from a
 * cross-section profile (demill_drum_add_profile), finite walls attached
 * to the drum (demill_drum_attach_wall), and the drum's translation
 * (DEMILL_DRUM_CENTER_*, _VELOCITY_*, _VIBRATION_*).
 *
 * - Eight straight lifters given as one lifter's open profile, repeated 8
 *   times, against the drum's 8 analytic lifters of the same section
 *   (DEMILL_DRUM_LIFTERS), in 3D and in 2D, with the drum at angle 0 and
 *   turned by 1 rad: a ball pressed 1e-4 m into each lifter's leading face
 *   and one into its top feels k delta along the face's normal (linear
 *   law, hand-derived) on both to 1e-10, the same force on both to 1e-12
 *   of k delta at angle 0 (1e-11 turned), the drum's torque the same
 *   within those bounds, its force (the sum of the 16) within 16 times.
 * - A disc, a capped cylinder (its side and a cap) and a rectangle attached
 *   to a drum turning at 100 rad/s, after 1 rad: a ball pressed 1e-4 m into
 *   each where the drum's rotation has carried it feels k delta along the
 *   face's normal turned by the drum's angle (1e-9), the drum's force is
 *   minus their sum and its torque the sum of their moments about the axis,
 *   and the wall's velocity at each contact point is omega z x r (rigid
 *   rotation about the axis, to 1e-12).
 * - A checkpoint and a snapshot of the turning and translating drum with its
 *   finite walls run on bitwise; removing the drum removes them with their
 *   caps.
 * - A drum lifted at 0.5 m/s with a ball resting on its shell: the ball
 *   keeps its place in the drum (1e-12 m), the drum's energy in is m g v t
 *   (1e-6), as is the world's wall work, and the total energy stays put to
 *   1e-6 of it. A drum shaken up and down (1 mm, 5 Hz) for two periods: its
 *   energy in, -F.v summed, is the work of moving the ball rigidly with it,
 *   m g y + m v^2/2, to 1e-3 of its peak (measured: 1.0e-4), the world's
 *   account the same, and the balance closes to 1e-3 (measured: 7.9e-5).
 * - Bad input (NaN points, too few points, a point outside the shell, a
 *   segment of zero length, a harmonic motion for an attached wall, a NaN
 *   drum velocity, a motion along z in 2D) is refused with its code, the
 *   world unchanged (its checkpoint bytes). */
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

/* One lifter's exposed faces as an open profile at polar angle a: from the
 * shell up its trailing face, across its top, down its leading face to the
 * shell; in (radius, tangential offset) the analytic lifter's section
 * (lib/physics/mill/drum.c) with the part sunk into the shell left out. */
static void lifter_profile(double a, double xy[8])
{
    const double hw = 0.5 * W, rs = sqrt(R_DRUM * R_DRUM - hw * hw), ri = R_DRUM - H;
    const double rt[4][2] = {{rs, -hw}, {ri, -hw}, {ri, hw}, {rs, hw}};
    for (int k = 0; k < 4; k++) {
        xy[2 * k] = rt[k][0] * cos(a) - rt[k][1] * sin(a);
        xy[2 * k + 1] = rt[k][0] * sin(a) + rt[k][1] * cos(a);
    }
}

/* The 8 lifters, analytic (profile 0) or from one profile, pressed by two
 * balls each: one DELTA into the leading face half-way up, one DELTA into
 * the top. Writes the balls' forces (2 NLIFT x 3), the drum's torque and
 * force. */
static void pressed_lifters(int dim, int turned, int profile, double *f, double *torque,
                            double force[3])
{
    demill_id mat, drum;
    demill_world *w = drum_world(dim, &mat, &drum);
    double phase;
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_LIFTER_PHASE, &phase));
    if (profile) {
        double xy[8];
        demill_id wall;
        lifter_profile(phase, xy);
        DM_OK(w, demill_drum_add_profile(w, drum, mat, DEMILL_DRUM_PART_LIFTERS, 4, xy, 0, NLIFT,
                                         &wall));
    } else {
        DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, NLIFT));
    }
    const double theta = turned ? turn(w, drum) : 0.0;
    double x[2 * NLIFT * 3], r[2 * NLIFT];
    for (int k = 0; k < NLIFT; k++) {
        const double a = phase + theta + 2 * M_PI * k / NLIFT, u[2] = {cos(a), sin(a)},
                     t[2] = {-sin(a), cos(a)};
        /* (radius, tangential offset): the leading face is at +W/2 */
        const double rt[2][2] = {{R_DRUM - 0.5 * H, 0.5 * W + BALL - DELTA},
                                 {R_DRUM - H - BALL + DELTA, 0.0}};
        for (int q = 0; q < 2; q++) {
            double *p = x + 3 * (2 * k + q);
            p[0] = rt[q][0] * u[0] + rt[q][1] * t[0];
            p[1] = rt[q][0] * u[1] + rt[q][1] * t[1];
            p[2] = dim == 3 ? 0.01 : 0.0;
            r[2 * k + q] = BALL;
        }
    }
    demill_id ids[2 * NLIFT];
    DM_OK(w, demill_particles_add(w, mat, 2 * NLIFT, x, r, NULL, 0, ids));
    DM_OK(w, demill_world_step(w, 0)); /* (forces at the current state) */
    for (int k = 0; k < 2 * NLIFT; k++)
        DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_FORCE, f + 3 * k));
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_TORQUE, torque));
    for (int c = 0; c < 3; c++)
        DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_FORCE_X + c, &force[c]));
    /* each ball feels k delta along the face's outward normal: the lifter's
     * tangential direction t (leading face), or -u (top) */
    for (int k = 0; k < NLIFT; k++) {
        const double a = phase + theta + 2 * M_PI * k / NLIFT;
        const double want[2][2] = {{-sin(a), cos(a)}, {-cos(a), -sin(a)}};
        for (int q = 0; q < 2; q++)
            for (int c = 0; c < 2; c++)
                ck_assert_msg(fabs(f[3 * (2 * k + q) + c] - K * DELTA * want[q][c]) <=
                                  1e-10 * K * DELTA,
                              "%dD, %s, lifter %d, %s: force[%d] = %.17g, expected %.17g", dim,
                              profile ? "profile" : "analytic", k, q ? "top" : "face", c,
                              f[3 * (2 * k + q) + c], K * DELTA * want[q][c]);
    }
    demill_world_destroy(w);
}

static void lifters_from_a_profile(int dim)
{
    for (int turned = 0; turned < 2; turned++) {
        double f[2][2 * NLIFT * 3], torque[2], force[2][3];
        for (int profile = 0; profile < 2; profile++)
            pressed_lifters(dim, turned, profile, f[profile], &torque[profile], force[profile]);
        /* the faces' places agree to a few ulps of their coordinates, one
         * ulp (2.8e-17 m at 0.15 m) being 2.8e-13 of delta: the same to
         * 1e-12 at angle 0; turned by 1 rad, where the drum's rotation and
         * the lifters' are rounded on different paths, to 1e-11 */
        const double tol = turned ? 1e-11 : 1e-12;
        for (int k = 0; k < 2 * NLIFT * 3; k++)
            ck_assert_msg(fabs(f[1][k] - f[0][k]) <= tol * K * DELTA,
                          "%dD, turned %d: ball %d, component %d: profile %.17g, analytic %.17g",
                          dim, turned, k / 3, k % 3, f[1][k], f[0][k]);
        /* the 16 forces' moments, each (R - h/2) k delta or 0 about the axis */
        DM_ASSERT_REL(torque[0], -NLIFT * (R_DRUM - 0.5 * H) * K * DELTA, 1e-10);
        ck_assert_msg(fabs(torque[1] - torque[0]) <= tol * fabs(torque[0]),
                      "%dD: torque %.17g, analytic %.17g", dim, torque[1], torque[0]);
        /* (the sum of 16 forces, each within 1e-12 k delta) */
        for (int c = 0; c < 3; c++)
            ck_assert_msg(fabs(force[1][c] - force[0][c]) <= 2 * NLIFT * tol * K * DELTA,
                          "%dD: force[%d] %.17g, analytic %.17g", dim, c, force[1][c],
                          force[0][c]);
    }
}

START_TEST(lifters_from_a_profile_3d)
{
    lifters_from_a_profile(3);
}
END_TEST

START_TEST(lifters_from_a_profile_2d)
{
    lifters_from_a_profile(2);
}
END_TEST

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

/* The copy's drum has the energy in of the original's; its three finite
 * walls are still attached, and go with the drum, caps and all. */
static void finite_walls_attached(demill_world *w, demill_world *v, int way, void *ctx)
{
    (void)way;
    const demill_id drum = *(const demill_id *)ctx;
    demill_id d, found[4];
    size_t nd, nw;
    double energy0, energy1;
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_DRUM, &d, 1, &nd));
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_WALL, found, 4, &nw));
    ck_assert_uint_eq(nw, 3); /* the cylinder's caps have no ids */
    DM_OK(w, demill_drum_get(w, drum, DEMILL_DRUM_ENERGY_IN, &energy0));
    DM_OK(v, demill_drum_get(v, d, DEMILL_DRUM_ENERGY_IN, &energy1));
    ck_assert(energy0 != 0.0 && energy0 == energy1);
    for (size_t k = 0; k < nw; k++) /* still attached */
        ck_assert_int_eq(demill_drum_attach_wall(v, d, found[k], DEMILL_DRUM_PART_SHELL),
                         DEMILL_ERR_INVALID_VALUE);
    DM_OK(v, demill_drum_remove(v, d));
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_WALL, NULL, 0, &nw));
    ck_assert_uint_eq(nw, 0);
    for (uint32_t k = 0; k < v->nwalls; k++)
        ck_assert_int_eq(v->walls[k].kind, 0);
}

START_TEST(checkpoint_and_snapshot_carry_finite_walls)
{
    demill_id drum, walls[3], ids[4];
    double want[4][3], theta;
    demill_world *w = finite_pressed(&drum, walls, ids, want, &theta);
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 3.0));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VELOCITY_X, 0.01)); /* and it translates */
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VIBRATION_Y, 1e-3));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VIBRATION_FREQUENCY, 5.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_world_step(w, 300));
    dm_test_copies_run_on(w, 500, finite_walls_attached, &drum);
    demill_world_destroy(w);
}
END_TEST

/* ---- a drum that translates ------------------------------------------------------ */

#define G 9.81

static double drum_value(demill_world *w, demill_id drum, int key)
{
    double v;
    DM_OK(w, demill_drum_get(w, drum, key, &v));
    return v;
}

/* A ball of radius 0.01 (linear law, restitution 0.5) resting on the
 * bottom of a standing drum 0.3 m across under gravity, placed at its
 * equilibrium overlap m g / k and settled for 0.05 s (14 periods of the
 * contact, which damp any remainder by 0.5^28). */
static demill_world *ball_at_rest(demill_id *drum, demill_id *ball, double *mass)
{
    demill_id mat;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &mat);
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, K));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -G));
    DM_OK(w, demill_drum_create(w, mat, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, 2 * R_DRUM));
    const double r = 0.01, m = 7800 * 4.0 / 3.0 * M_PI * r * r * r;
    const double x[3] = {0, -(R_DRUM - r + m * G / K), 0};
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, NULL, 0, ball));
    DM_OK(w, demill_world_step(w, 5000));
    *mass = m;
    return w;
}

/* The ball's position relative to the drum's centre. */
static void relative(demill_world *w, demill_id drum, demill_id ball, double out[3])
{
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, out));
    for (int c = 0; c < 3; c++)
        out[c] -= drum_value(w, drum, DEMILL_DRUM_CENTER_X + c);
}

START_TEST(a_drum_lifted_at_constant_speed)
{
    /* the drum and the ball go up at v = 0.5 m/s for 0.1 s: the ball stays
     * where it was in the drum, the drum does the work m g v t of lifting
     * it (the force it carries, m g, times the distance), the world's
     * account (the walls' work) says the same, and the total energy stays
     * put */
    demill_id drum, ball;
    double m;
    demill_world *w = ball_at_rest(&drum, &ball, &m);
    const double v = 0.5, vel[3] = {0, v, 0}, t = 0.1;
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VELOCITY_Y, v));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_VELOCITY, vel));
    double rel0[3], rel1[3];
    relative(w, drum, ball, rel0);
    const double in0 = drum_value(w, drum, DEMILL_DRUM_ENERGY_IN);
    const double work0 = dm_test_energy(w, DEMILL_ENERGY_WALL_WORK);
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    DM_OK(w, demill_world_step(w, 10000));
    relative(w, drum, ball, rel1);
    for (int c = 0; c < 3; c++)
        ck_assert_msg(fabs(rel1[c] - rel0[c]) <= 1e-12, "the ball moved by %g m in the drum",
                      rel1[c] - rel0[c]);
    DM_ASSERT_REL(drum_value(w, drum, DEMILL_DRUM_CENTER_Y), v * t, 1e-9);
    DM_ASSERT_REL(drum_value(w, drum, DEMILL_DRUM_CURRENT_VELOCITY_Y), v, 1e-15);
    const double lift = m * G * v * t, in = drum_value(w, drum, DEMILL_DRUM_ENERGY_IN) - in0;
    DM_ASSERT_REL(in, lift, 1e-6);
    DM_ASSERT_REL(dm_test_energy(w, DEMILL_ENERGY_WALL_WORK) - work0, in, 1e-9);
    DM_ASSERT_REL(drum_value(w, drum, DEMILL_DRUM_POWER), m * G * v, 1e-6);
    ck_assert_msg(fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0) <= 1e-6 * lift,
                  "the balance is off by %g J of %g J", dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0,
                  lift);
    demill_world_destroy(w);
}
END_TEST

START_TEST(a_drum_shaken_up_and_down)
{
    /* the drum's centre at y = A cos(2 pi f t) - A (A = 1 mm, f = 5 Hz, peak
     * acceleration 0.99 m/s^2 < g: the ball stays on the shell) for two
     * periods: the work the drum does, -F.v summed, is what moving the ball
     * rigidly with the centre takes, m g y + m v^2 / 2 (analytic), to 1e-3
     * of its peak (the ball's spring gives a little), the world's account
     * says the same as the drum's, and the total energy stays put to 1e-3 of
     * the peak work */
    demill_id drum, ball;
    double m;
    demill_world *w = ball_at_rest(&drum, &ball, &m);
    const double A = 1e-3, f = 5.0, om = 2 * M_PI * f;
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VIBRATION_Y, A));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VIBRATION_PHASE, 0.5 * M_PI));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_VIBRATION_FREQUENCY, f));
    const double in0 = drum_value(w, drum, DEMILL_DRUM_ENERGY_IN);
    const double work0 = dm_test_energy(w, DEMILL_ENERGY_WALL_WORK);
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    double peak = 0, worst = 0, worst_e = 0, t;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    const double t0 = t, y0 = drum_value(w, drum, DEMILL_DRUM_CENTER_Y);
    for (int k = 0; k < 400; k++) { /* 0.4 s, every 1 ms */
        DM_OK(w, demill_world_step(w, 100));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
        const double y = A * cos(om * (t - t0)), vy = -A * om * sin(om * (t - t0));
        ck_assert_msg(fabs(drum_value(w, drum, DEMILL_DRUM_CENTER_Y) - y0 - (y - A)) <= 1e-15,
                      "t = %g: centre at %.17g, expected %.17g", t,
                      drum_value(w, drum, DEMILL_DRUM_CENTER_Y) - y0, y - A);
        const double rigid = m * G * (y - A) + 0.5 * m * vy * vy;
        const double in = drum_value(w, drum, DEMILL_DRUM_ENERGY_IN) - in0;
        peak = fmax(peak, fabs(rigid));
        worst = fmax(worst, fabs(in - rigid));
        worst_e = fmax(worst_e, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0));
        ck_assert_msg(fabs(dm_test_energy(w, DEMILL_ENERGY_WALL_WORK) - work0 - in) <=
                          1e-12 * peak + 1e-18,
                      "t = %g: the world's account %.17g, the drum's %.17g", t,
                      dm_test_energy(w, DEMILL_ENERGY_WALL_WORK) - work0, in);
    }
    printf("shaken drum: work off the rigid-body work by %.3g of its peak %.3g J, "
           "balance by %.3g\n", worst / peak, peak, worst_e / peak);
    ck_assert_msg(worst <= 1e-3 * peak, "work off by %g J of %g J", worst, peak);
    ck_assert_msg(worst_e <= 1e-3 * peak, "balance off by %g J of %g J", worst_e, peak);
    demill_world_destroy(w);
}
END_TEST

/* ---- bad input ------------------------------------------------------------------ */

START_TEST(bad_input_leaves_the_world_unchanged)
{
    demill_id drum, walls[3], ids[4], mat;
    double want[4][3], theta;
    demill_world *w = finite_pressed(&drum, walls, ids, want, &theta);
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, &mat, 1, NULL));
    size_t size, size1;
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    uint8_t *before = malloc(size), *after = malloc(size);
    ck_assert(before && after);
    DM_OK(w, demill_world_save_buffer(w, before, size, &size));
    const double ok[6] = {0.1, 0.0, 0.1, 0.01, 0.12, 0.01};
    const double nan[6] = {0.1, 0.0, NAN, 0.01, 0.12, 0.01};
    const double outside[6] = {0.1, 0.0, 0.16, 0.0, 0.12, 0.01};
    const double repeated[6] = {0.1, 0.0, 0.1, 0.01, 0.1, 0.01};
    const double closing[6] = {0.1, 0.0, 0.1, 0.01, 0.1, 0.0}; /* closed: back to the first */
    const struct {
        const double *xy;
        size_t n;
        int closed;
        uint32_t copies;
        int32_t part;
        demill_status want;
        const char *what;
    } cases[] = {
        {nan, 3, 0, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_NOT_FINITE, "point 1"},
        {ok, 1, 0, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "1 points"},
        {ok, 2, 1, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "a closed profile"},
        {outside, 3, 0, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "outside the shell"},
        {repeated, 3, 0, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE,
         "segment 1 (points 1 and 2) has zero length"},
        {closing, 3, 1, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE,
         "segment 2 (points 2 and 0) has zero length"},
        {ok, 3, 2, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "closed is 2"},
        {ok, 3, 0, 0, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "0 copies"},
        {ok, 3, 0, 1025, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_INVALID_VALUE, "1025 copies"},
        {ok, 3, 0, 1, 4, DEMILL_ERR_UNKNOWN_KEY, "not a part of the drum"},
        {NULL, 3, 0, 1, DEMILL_DRUM_PART_LIFTERS, DEMILL_ERR_NULL_POINTER, "points is NULL"},
    };
    demill_id out;
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        ck_assert_int_eq(demill_drum_add_profile(w, drum, mat, cases[k].part, cases[k].n,
                                                 cases[k].xy, cases[k].closed, cases[k].copies,
                                                 &out),
                         cases[k].want);
        ck_assert_msg(strstr(demill_world_last_error(w), cases[k].what), "case %zu: %s", k,
                      demill_world_last_error(w));
        DM_OK(w, demill_world_save_buffer(w, after, size, &size1));
        ck_assert_msg(size1 == size && memcmp(before, after, size) == 0,
                      "case %zu changed the world", k);
    }
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
    /* the drum's motion: not finite; along z in a 2D world */
    ck_assert_int_eq(demill_drum_set(w, drum, DEMILL_DRUM_VELOCITY_X, NAN), DEMILL_ERR_NOT_FINITE);
    DM_OK(w, demill_world_save_buffer(w, after, size, &size1));
    ck_assert_msg(size1 == size && memcmp(before, after, size) == 0, "a NaN velocity moved it");
    free(before);
    free(after);
    demill_world_destroy(w);
    demill_id mat2, drum2;
    w = drum_world(2, &mat2, &drum2);
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, &size));
    before = malloc(size);
    after = malloc(size);
    ck_assert(before && after);
    DM_OK(w, demill_world_save_buffer(w, before, size, &size));
    const int zkeys[3] = {DEMILL_DRUM_CENTER_Z, DEMILL_DRUM_VELOCITY_Z, DEMILL_DRUM_VIBRATION_Z};
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(demill_drum_set(w, drum2, zkeys[k], 0.1), DEMILL_ERR_DIMENSION);
        DM_OK(w, demill_world_save_buffer(w, after, size, &size1));
        ck_assert_msg(size1 == size && memcmp(before, after, size) == 0, "z key %d moved it",
                      zkeys[k]);
    }
    DM_OK(w, demill_drum_set(w, drum2, DEMILL_DRUM_CENTER_Z, 0.0));
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
    tcase_add_test(tc, lifters_from_a_profile_3d);
    tcase_add_test(tc, lifters_from_a_profile_2d);
    tcase_add_test(tc, finite_walls_turn_with_the_drum);
    tcase_add_test(tc, checkpoint_and_snapshot_carry_finite_walls);
    tcase_add_test(tc, a_drum_lifted_at_constant_speed);
    tcase_add_test(tc, a_drum_shaken_up_and_down);
    tcase_add_test(tc, bad_input_leaves_the_world_unchanged);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
