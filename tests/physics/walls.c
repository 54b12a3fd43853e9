/* walls.c: finite walls (cylinders, cones, discs and annuli, rectangles)
 * against numbers worked out by hand or from mechanics.
 *
 * Closest points: a sphere of radius r = 0.01 m held at a hand-placed
 * position near a wall, with the linear law without damping (k = 5e4 N/m:
 * two default materials in series) and no gravity, feels F = k (r - d) m,
 * where d is its centre's distance from the nearest point of the surface and
 * m the unit vector from that point to the centre. Positions are chosen so
 * that d and m are exact decimals (3-4-5 and 2-3-6-7 triangles): the face
 * of a cylinder from inside and outside, an open rim from both sides, a
 * cap, the inner corner of a capped cylinder (two contacts, side and cap),
 * its convex rim (one contact, never two), a cone's face and apex, an
 * annulus's faces and both rims, a rectangle's face, edge and corner.
 *
 * Contact quality: on a face, a finite wall is the plane through it, so a
 * sphere bouncing onto it with sliding (Hertz, restitution damping,
 * Mindlin friction) has the plane's force history to 1e-12.
 *
 * Dynamics, each derived where it is tested: a ball rolling inside a
 * horizontal cylinder (the period of a rolling pendulum), a ball coming to
 * rest in a cone (its height from the geometry and the Hertz overlap), a
 * ball on a vibrating floor (lift-off where the floor's acceleration
 * reaches -g) and a ball dragged by a belt (rolling without slip, the
 * belt's work in the energy account). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "testutil.h"

#define TOL 1e-12

static const double R = 0.01;  /* m, sphere radius */
static const double KN = 5e4;  /* N/m, two default materials in series */

/* A world without gravity, the linear law without damping or friction. */
static demill_world *linear_world(demill_id *m)
{
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, m);
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_NONE));
    return w;
}

/* The force on a sphere of radius R at (x, y, z) from the world's walls. */
static void force_at(demill_world *w, demill_id m, double x, double y, double z, double f[3])
{
    const double p[3] = {x, y, z};
    const double r = R;
    demill_id id;
    DM_OK(w, demill_particles_add(w, m, 1, p, &r, NULL, 0, &id));
    DM_OK(w, demill_world_step(w, 0));
    DM_OK(w, demill_particle_get(w, id, DEMILL_PARTICLE_FORCE, f));
    DM_OK(w, demill_particles_remove(w, 1, &id));
}

/* The force at (x, y, z) is k (r - d) times the unit vector (mx, my, mz)
 * (from the surface to the centre) scaled by 1/ml. */
static void expect_at(int line, demill_world *w, demill_id m, double x, double y, double z,
                      double d, double mx, double my, double mz, double ml)
{
    double f[3];
    force_at(w, m, x, y, z, f);
    const double mag = KN * (R - d), want[3] = {mag * mx / ml, mag * my / ml, mag * mz / ml};
    for (int c = 0; c < 3; c++)
        ck_assert_msg(fabs(f[c] - want[c]) <= 1e-10 * mag,
                      "line %d: F[%d] = %.15g, expected %.15g", line, c, f[c], want[c]);
}
#define EXPECT_AT(...) expect_at(__LINE__, __VA_ARGS__)

/* ---- closest points ------------------------------------------------------ */

/* Cylinder R_c = 0.1 about z from z = 0 to 0.2, open. */
START_TEST(cylinder_open)
{
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 2};
    DM_OK(w, demill_wall_add_cylinder(w, m, o, z, 0.1, 0.2, DEMILL_CAPS_NONE, &wall));
    EXPECT_AT(w, m, 0.1 - 0.009, 0, 0.1, 0.009, -1, 0, 0, 1);   /* inside, face */
    EXPECT_AT(w, m, 0, 0.1 + 0.008, 0.05, 0.008, 0, 1, 0, 1);   /* outside, face */
    EXPECT_AT(w, m, 0.103, 0, 0.204, 0.005, 0.6, 0, 0.8, 1);    /* rim, outside */
    EXPECT_AT(w, m, 0.097, 0, 0.204, 0.005, -0.6, 0, 0.8, 1);   /* rim, inside */
    EXPECT_AT(w, m, 0, -0.097, -0.004, 0.005, 0, 0.6, -0.8, 1); /* the other rim */
    double f[3];
    force_at(w, m, 0, 0, 0.2 + 0.001, f); /* on the axis past the open end: nothing */
    ck_assert(f[0] == 0 && f[1] == 0 && f[2] == 0);
    demill_world_destroy(w);
}
END_TEST

/* The same cylinder closed at its end z = 0.2. */
START_TEST(cylinder_capped)
{
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1};
    DM_OK(w, demill_wall_add_cylinder(w, m, o, z, 0.1, 0.2, DEMILL_CAPS_END, &wall));
    EXPECT_AT(w, m, 0.05, 0, 0.2 - 0.007, 0.007, 0, 0, -1, 1); /* the cap from inside */
    EXPECT_AT(w, m, 0.05, 0, 0.2 + 0.007, 0.007, 0, 0, 1, 1);  /* from outside */
    EXPECT_AT(w, m, 0.103, 0, 0.204, 0.005, 0.6, 0, 0.8, 1);   /* the convex rim: once */
    /* over the cap near the rim: the cap alone (the rim is 0.00906 away) */
    EXPECT_AT(w, m, 0.099, 0, 0.209, 0.009, 0, 0, 1, 1);
    /* the inner corner: the side (d = 0.009) and the cap (d = 0.007) */
    double f[3];
    force_at(w, m, 0.1 - 0.009, 0, 0.2 - 0.007, f);
    const double want[3] = {-KN * 0.001, 0, -KN * 0.003};
    for (int c = 0; c < 3; c++)
        ck_assert_msg(fabs(f[c] - want[c]) <= 1e-10 * KN * 0.003, "corner F[%d] = %.15g", c,
                      f[c]);
    /* the open end keeps its rim, from inside */
    EXPECT_AT(w, m, 0.097, 0, -0.004, 0.005, -0.6, 0, -0.8, 1);
    demill_world_destroy(w);
}
END_TEST

/* A cone of half-angle 45°, apex at the origin, radius 0.1 at z = 0.1. */
START_TEST(cone_face_and_apex)
{
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1}, s = sqrt(0.5);
    DM_OK(w, demill_wall_add_cone(w, m, o, z, 0.0, 0.1, 0.1, DEMILL_CAPS_NONE, &wall));
    /* inside, 0.008 from the face point (0.05, 0, 0.05) along the inward normal */
    EXPECT_AT(w, m, 0.05 - 0.008 * s, 0, 0.05 + 0.008 * s, 0.008, -1, 0, 1, sqrt(2.0));
    /* outside */
    EXPECT_AT(w, m, 0, 0.05 + 0.006 * s, 0.05 - 0.006 * s, 0.006, 0, 1, -1, sqrt(2.0));
    /* below the apex */
    EXPECT_AT(w, m, 0, 0, -0.006, 0.006, 0, 0, -1, 1);
    demill_world_destroy(w);
}
END_TEST

/* An annulus about the origin, normal z, radii 0.05 and 0.1. */
START_TEST(annulus_faces_and_rims)
{
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1};
    DM_OK(w, demill_wall_add_disc(w, m, o, z, 0.1, 0.05, &wall));
    EXPECT_AT(w, m, 0.07, 0, 0.006, 0.006, 0, 0, 1, 1);       /* above */
    EXPECT_AT(w, m, 0, 0.07, -0.006, 0.006, 0, 0, -1, 1);     /* below */
    EXPECT_AT(w, m, 0.047, 0, 0.004, 0.005, -0.6, 0, 0.8, 1); /* the hole's rim */
    EXPECT_AT(w, m, 0.103, 0, -0.004, 0.005, 0.6, 0, -0.8, 1); /* the outer rim */
    double f[3];
    force_at(w, m, 0, 0, 0, f); /* in the middle of the hole */
    ck_assert(f[0] == 0 && f[1] == 0 && f[2] == 0);
    demill_world_destroy(w);
}
END_TEST

/* A rectangle about the origin, normal y, half-widths 0.1 along x and 0.05
 * along y × x = -z. */
START_TEST(rectangle_face_edge_corner)
{
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    const double o[3] = {0, 0, 0}, y[3] = {0, 3, 0}, x[3] = {2, 1, 0};
    DM_OK(w, demill_wall_add_rectangle(w, m, o, y, x, 0.1, 0.05, &wall));
    EXPECT_AT(w, m, 0.02, 0.007, 0.01, 0.007, 0, 1, 0, 1);     /* face, above */
    EXPECT_AT(w, m, 0.02, -0.007, -0.04, 0.007, 0, -1, 0, 1);  /* face, below */
    EXPECT_AT(w, m, 0.103, 0.004, 0, 0.005, 0.6, 0.8, 0, 1);   /* the edge x = 0.1 */
    EXPECT_AT(w, m, 0, -0.004, -0.053, 0.005, 0, -0.8, -0.6, 1); /* the edge z = -0.05 */
    EXPECT_AT(w, m, 0.102, 0.003, 0.056, 0.007, 2, 3, 6, 7);   /* the corner (0.1, 0, 0.05) */
    demill_world_destroy(w);
}
END_TEST

/* ---- contact quality: a face is the plane through it --------------------- */

/* A steel ball (mill materials: Hertz, restitution damping, Mindlin friction)
 * of radius R starts at x0 with velocity v0 towards a wall, 300 steps of
 * 1e-6 s; its force at every step, into f (3 per step). */
static void bounce(int kind, const double x0[3], const double v0[3], double *f)
{
    demill_world *w = NULL;
    demill_id balls, liner, wall, ball;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-6));
    dm_test_mill_materials(w, &balls, &liner);
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, mx[3] = {-1, 0, 0}, px[3] = {0.1, 0, 0};
    const double x[3] = {1, 0, 0}, z[3] = {0, 0, 1};
    switch (kind) {
    case 0: DM_OK(w, demill_wall_add_plane(w, liner, o, y, &wall)); break;
    case 1: DM_OK(w, demill_wall_add_rectangle(w, liner, o, y, x, 0.1, 0.1, &wall)); break;
    case 2: DM_OK(w, demill_wall_add_disc(w, liner, o, y, 0.1, 0.0, &wall)); break;
    case 3: /* the cap at the cylinder's start */
        DM_OK(w, demill_wall_add_cylinder(w, liner, o, y, 0.1, 0.2, DEMILL_CAPS_START, &wall));
        break;
    case 4: DM_OK(w, demill_wall_add_plane(w, liner, px, mx, &wall)); break;
    default: /* the inside of the cylinder's side at x = 0.1 */
        DM_OK(w, demill_wall_add_cylinder(w, liner, o, z, 0.1, 0.2, DEMILL_CAPS_NONE, &wall));
    }
    const double r = R;
    DM_OK(w, demill_particles_add(w, balls, 1, x0, &r, v0, 0, &ball));
    for (int k = 0; k < 300; k++) {
        DM_OK(w, demill_world_step(w, 1));
        DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_FORCE, f + 3 * k));
    }
    demill_world_destroy(w);
}

/* The force histories of a bounce with sliding on a rectangle, a disc, a
 * cylinder's cap and the inside of its side against the plane through the
 * face: the same to 1e-12 of the largest force, and a collision happened. */
START_TEST(faces_are_planes)
{
    double *plane = malloc(2 * 900 * sizeof *plane), *face = plane + 900;
    const double xf[3] = {0.02, R + 2e-6, 0.03}, vf[3] = {0.3, -1.0, 0.2};
    const double xs[3] = {0.1 - R - 2e-6, 0.0, 0.1}, vs[3] = {1.0, 0.0, 0.3};
    for (int kind = 1; kind <= 5; kind++) {
        if (kind == 1 || kind == 5)
            bounce(kind == 1 ? 0 : 4, kind == 1 ? xf : xs, kind == 1 ? vf : vs, plane);
        if (kind == 4)
            continue;
        bounce(kind, kind == 5 ? xs : xf, kind == 5 ? vs : vf, face);
        double big = 0.0, diff = 0.0;
        for (int k = 0; k < 900; k++) {
            big = fmax(big, fabs(plane[k]));
            diff = fmax(diff, fabs(face[k] - plane[k]));
        }
        ck_assert_msg(big > 10.0, "kind %d: no collision (largest force %g N)", kind, big);
        ck_assert_msg(diff <= TOL * big, "kind %d: force differs by %g N of %g N", kind, diff,
                      big);
    }
    free(plane);
}
END_TEST

/* ---- dynamics -------------------------------------------------------------- */

/* A world with gravity g along -y, the mill's steel materials (balls and
 * liner: Hertz, restitution damping, Mindlin friction) and time step dt. */
static demill_world *steel_world(double dt, demill_id *balls, demill_id *liner)
{
    demill_world *w = NULL;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    dm_test_mill_materials(w, balls, liner);
    return w;
}

static double gravity(demill_world *w)
{
    double g;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Y, &g));
    return -g;
}

/* A ball of radius r = 0.01 rolling without slip inside a horizontal
 * cylinder of radius Rc = 0.1, let go at rest 0.05 rad from the bottom:
 * its centre moves on the circle of radius L = Rc - r at speed L θ', and
 * rolling spins it at ω = L θ' / r, so its energy is 1/2 m L² θ'² (1 + I /
 * (m r²)) - m g L cos θ with I = 2/5 m r²: a pendulum of length L whose
 * inertia is 7/5 of a point mass's, T = 2π √(7 L / (5 g)) (small amplitude;
 * the amplitude's correction, θ0²/16 = 1.6e-4, is within the tolerance). The
 * period is measured between the first and the fourth crossing of the
 * bottom (x = 0, interpolated in time), over 1.5 periods, to 0.2 %. */
START_TEST(ball_rolls_in_cylinder)
{
    const double dt = 2e-5, Rc = 0.1, r = R, th = 0.05;
    demill_id balls, liner, wall, ball;
    demill_world *w = steel_world(dt, &balls, &liner);
    const double o[3] = {0, 0, -0.05}, z[3] = {0, 0, 1};
    DM_OK(w, demill_wall_add_cylinder(w, liner, o, z, Rc, 0.1, DEMILL_CAPS_NONE, &wall));
    const double L = Rc - r, x0[3] = {L * sin(th), -L * cos(th), 0};
    DM_OK(w, demill_particles_add(w, balls, 1, x0, &r, NULL, 0, &ball));
    const double g = gravity(w), T = 2 * M_PI * sqrt(7 * L / (5 * g));
    double t_cross[4], x_prev = x0[0];
    int n = 0;
    for (long k = 1; n < 4 && k < (long)(3 * T / dt); k++) {
        DM_OK(w, demill_world_step(w, 1));
        const double x = dm_test_get(w, ball, DEMILL_PARTICLE_POSITION, 0);
        if ((x < 0) != (x_prev < 0))
            t_cross[n++] = (k - 1 + x_prev / (x_prev - x)) * dt;
        x_prev = x;
    }
    ck_assert_int_eq(n, 4);
    const double period = 2.0 / 3.0 * (t_cross[3] - t_cross[0]);
    DM_ASSERT_REL(period, T, 2e-3);
    demill_world_destroy(w);
}
END_TEST

/* A ball of radius r in a cone of half-angle α = 30° (apex down, no
 * orifice) touches it along a circle when its centre is on the axis at
 * r / sin α = 2r above the apex (geometry). A thin wall touches a particle
 * at one point, so near the axis the ball is held by one side at a time,
 * with the force F = m g / sin α whose vertical part carries its weight,
 * and sinks by its Hertz overlap δ = (F / (4/3 E* √r))^(2/3) (E* = E / (2 (1
 * - ν²)) for two equal materials) over sin α. Dropped off the axis, it
 * comes to rest on it (within 1e-6 m, speed below 1e-3 m/s) at the height
 * 2r less between 0 and 1.1 δ / sin α. */
START_TEST(ball_rests_in_cone)
{
    const double dt = 1e-5, r = R, sin_a = 0.5, tan_a = tan(M_PI / 6);
    demill_id balls, liner, wall, ball;
    demill_world *w = steel_world(dt, &balls, &liner);
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_cone(w, liner, o, y, 0.0, 0.1 * tan_a, 0.1, DEMILL_CAPS_NONE,
                                  &wall));
    const double x0[3] = {0.004, 0.03, 0.002};
    DM_OK(w, demill_particles_add(w, balls, 1, x0, &r, NULL, 0, &ball));
    DM_OK(w, demill_world_step(w, 100000));
    double e, nu, x[3], v[3];
    DM_OK(w, demill_material_get(w, liner, DEMILL_MATERIAL_YOUNGS_MODULUS, &e));
    DM_OK(w, demill_material_get(w, liner, DEMILL_MATERIAL_POISSON_RATIO, &nu));
    const double m = dm_test_get(w, ball, DEMILL_PARTICLE_MASS, 0);
    const double load = m * gravity(w) / sin_a, estar = e / (2 * (1 - nu * nu));
    const double delta = pow(load / (4.0 / 3.0 * estar * sqrt(r)), 2.0 / 3.0);
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, x));
    DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_VELOCITY, v));
    const double sink = 2 * r - x[1];
    ck_assert_msg(sink >= 0 && sink <= 1.1 * delta / sin_a, "sank %g m, δ / sin α = %g m", sink,
                  delta / sin_a);
    ck_assert_msg(hypot(x[0], x[2]) < 1e-6, "%g m off the axis", hypot(x[0], x[2]));
    ck_assert_msg(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) < 1e-3, "still moving");
    demill_world_destroy(w);
}
END_TEST

/* A floor vibrating as A sin(2πft) along y (f = 20 Hz) under a ball
 * resting on it, moving with it (velocity 2πfA at t = 0). The ball stays on
 * while the floor's largest downward acceleration A (2πf)² is below g;
 * above g it leaves where the floor's acceleration -A (2πf)² sin(2πft)
 * first reaches -g, t* = asin(g / (A (2πf)²)) / (2πf). The contact is a
 * stiff linear spring (k = 1e7 N/m, no damping, the ball placed at its
 * equilibrium overlap m g / k): it follows the load m (g + a) with the
 * oscillation the floor's jerk starts at t = 0, of amplitude m A (2πf)³ /
 * (k ω), ω = √(k / m), so the force reaches 0 within 1 / (ω cos(2πf t*))
 * of t*. Returns the time of the first step without contact, or -1. */
static double lift_off(double accel_ratio, double *window)
{
    const double dt = 2e-6, f = 20.0, r = R, om = 2 * M_PI * f, k = 1e7;
    demill_id mat, wall, ball;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL_STIFFNESS, k));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_NONE));
    const double g = 9.81, a = accel_ratio * g / (om * om);
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, x0[3] = {0, r, 0};
    DM_OK(w, demill_wall_add_plane(w, mat, o, y, &wall));
    DM_OK(w, demill_particles_add(w, mat, 1, x0, &r, NULL, 0, &ball));
    const double m = dm_test_get(w, ball, DEMILL_PARTICLE_MASS, 0);
    const double x1[3] = {0, r - m * g / k, 0}, v0[3] = {0, a * om, 0};
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_POSITION, x1));
    DM_OK(w, demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_TRANSLATION, y, a, f, 0.0));
    DM_OK(w, demill_particle_set(w, ball, DEMILL_PARTICLE_VELOCITY, v0));
    *window = accel_ratio > 1 ? 1 / (sqrt(k / m) * cos(asin(1 / accel_ratio))) : 0;
    double t = -1;
    for (long n = 1; n <= (long)(1 / (f * dt)); n++) {
        DM_OK(w, demill_world_step(w, 1));
        double c;
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &c));
        if (c == 0) {
            t = n * dt;
            break;
        }
    }
    demill_world_destroy(w);
    return t;
}

START_TEST(vibrating_floor)
{
    const double om = 2 * M_PI * 20.0, dt = 2e-6;
    double window;
    ck_assert_msg(lift_off(0.9, &window) < 0, "the ball left a floor vibrating at 0.9 g");
    const double t = lift_off(2.0, &window), want = asin(0.5) / om;
    ck_assert_msg(fabs(t - want) <= window + dt, "left at %g s, expected %g s within %g s", t,
                  want, window + dt);
}
END_TEST

/* A ball at rest on a belt (a floor whose surface moves at v = 1 m/s along
 * x) is dragged by friction until it rolls without slip. Friction F at the
 * contact point, the lever arm a = r - δ/2 below the centre (δ: the Hertz
 * overlap under the ball's weight, (m g / (4/3 E* √r))^(2/3)), gives it
 * momentum J = ∫F dt and spin ω = a J / I about z; it rolls once the
 * contact point moves with the belt, v_x + a ω = v, so with I = 2/5 m r²:
 * v_x = v / (1 + 5/2 (a/r)²), nearly 2v/7, and a ω = v - v_x (in the
 * belt's frame the ball moves at v_x - v, nearly -5v/7). The belt does the
 * work J v = m v_x v while it slips: the ball's kinetic energy and as much
 * again dissipated by friction. Checked: the speeds to 1e-5, the belt's
 * work in the energy account to 1e-3, and the account's balance (total
 * energy minus the walls' work constant) to 1e-6 of that work. The same
 * with the belt attached to a body held still (free along no axis), whose
 * surface velocity's work is the belt's drive, from outside the world like
 * a free wall's (it was counted nowhere: the work 0, the balance off by
 * all of it). And with the body free along x on a spring (k = 100 N/m),
 * which friction pulls back while the ball slips: the body's motion then
 * moves energy between the ball and the body, within the account, and
 * only the surface velocity's work comes from outside; the speeds are no
 * longer the fixed belt's, the balance is checked as before. */
static void belt_drags_ball(int on_body)
{
    const double dt = 1e-5, r = R, v = 1.0;
    demill_id balls, liner, wall, ball, body;
    demill_world *w = steel_world(dt, &balls, &liner);
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, x0[3] = {0, r, 0}, u[3] = {v, 0, 0};
    DM_OK(w, demill_wall_add_plane(w, liner, o, y, &wall));
    if (on_body) {
        const int free = on_body == 2 ? DEMILL_BODY_AXIS_X : 0;
        DM_OK(w, demill_body_add(w, 10.0, o, free, 0, &body));
        if (free)
            DM_OK(w, demill_body_set_spring(w, body, DEMILL_BODY_AXIS_X, 100.0, 0.0, 0.0));
        DM_OK(w, demill_body_attach_wall(w, body, wall));
    }
    DM_OK(w, demill_particles_add(w, balls, 1, x0, &r, NULL, 0, &ball));
    DM_OK(w, demill_world_step(w, 20000)); /* settles */
    DM_OK(w, demill_wall_set_surface_velocity(w, wall, u));
    double e0, work0, e1, work1, got[3];
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &e0));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_WALL_WORK, &work0));
    DM_OK(w, demill_world_step(w, 30000));
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_SURFACE_VELOCITY, got));
    ck_assert(got[0] == v && got[1] == 0 && got[2] == 0);
    double e, nu;
    DM_OK(w, demill_material_get(w, liner, DEMILL_MATERIAL_YOUNGS_MODULUS, &e));
    DM_OK(w, demill_material_get(w, liner, DEMILL_MATERIAL_POISSON_RATIO, &nu));
    const double m = dm_test_get(w, ball, DEMILL_PARTICLE_MASS, 0);
    const double delta = pow(m * gravity(w) / (4.0 / 3.0 * e / (2 * (1 - nu * nu)) * sqrt(r)),
                             2.0 / 3.0);
    const double a = r - delta / 2, vx = v / (1 + 2.5 * (a / r) * (a / r));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_TOTAL, &e1));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_WALL_WORK, &work1));
    const double work = work1 - work0;
    printf("belt (%s): work %.6e J, m v_x v %.6e J, balance %+.3e J\n",
           on_body == 2 ? "on a sprung body" : on_body ? "on a held body" : "free", work,
           m * vx * v, e1 - e0);
    if (on_body < 2) {
        DM_ASSERT_REL(dm_test_get(w, ball, DEMILL_PARTICLE_VELOCITY, 0), vx, 1e-5);
        DM_ASSERT_REL(a * dm_test_get(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2), v - vx,
                      1e-5);
        DM_ASSERT_REL(work, m * vx * v, 1e-3);
    }
    ck_assert_msg(fabs(e1 - e0) <= 1e-6 * work, "balance %g J of the work %g J", e1 - e0, work);
    demill_world_destroy(w);
}

START_TEST(belt_drags_ball_to_rolling)
{
    belt_drags_ball(0);
}
END_TEST

START_TEST(belt_on_body_drags_ball_to_rolling)
{
    belt_drags_ball(1);
    belt_drags_ball(2);
}
END_TEST

/* A rectangle rocking about the axis z through its centre, s(t) = A
 * sin(2πft + φ) (t the world's clock): after n steps its normal is (0, 1,
 * 0) turned by s(t) about z, exactly (no drift: 1e-15 after 10,000 steps),
 * its angular
 * velocity 2πfA cos(2πft + φ) along z, its centre fixed; a surface
 * velocity set when it had turned by s(t1) turns with it. */
START_TEST(harmonic_rotation_is_exact)
{
    const double dt = 1e-4, A = 0.3, f = 7.0, ph = 0.4, om = 2 * M_PI * f;
    demill_id m, wall;
    demill_world *w = linear_world(&m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    const double c[3] = {0.1, 0.2, 0.3}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0}, z[3] = {0, 0, 2};
    const double u[3] = {0.5, 0, 0};
    DM_OK(w, demill_wall_add_rectangle(w, m, c, y, x, 0.1, 0.1, &wall));
    DM_OK(w, demill_wall_set_harmonic(w, wall, DEMILL_HARMONIC_ROTATION, z, A, f, ph));
    double t1, t;
    DM_OK(w, demill_world_step(w, 1000));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t1));
    const double s1 = A * sin(om * t1 + ph);
    DM_OK(w, demill_wall_set_surface_velocity(w, wall, u));
    DM_OK(w, demill_world_step(w, 9000));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
    const double s = A * sin(om * t + ph);
    double n[3], wv[3], cc[3], us[3];
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_NORMAL, n));
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_ANGULAR_VELOCITY, wv));
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_CENTRE, cc));
    DM_OK(w, demill_wall_get(w, wall, DEMILL_WALL_SURFACE_VELOCITY, us));
    const double want_n[3] = {-sin(s), cos(s), 0}, want_w[3] = {0, 0, A * om * cos(om * t + ph)};
    const double want_u[3] = {0.5 * cos(s - s1), 0.5 * sin(s - s1), 0};
    for (int k = 0; k < 3; k++) {
        ck_assert_msg(fabs(n[k] - want_n[k]) <= 1e-15, "n[%d] = %.17g, want %.17g", k, n[k],
                      want_n[k]);
        ck_assert_msg(fabs(wv[k] - want_w[k]) <= 1e-12, "omega[%d] = %.17g", k, wv[k]);
        ck_assert(cc[k] == c[k]);
        ck_assert_msg(fabs(us[k] - want_u[k]) <= 1e-15, "u[%d] = %.17g", k, us[k]);
    }
    demill_world_destroy(w);
}
END_TEST

Suite *walls_suite(void);
Suite *walls_suite(void)
{
    Suite *s = suite_create("walls");
    TCase *tc = tcase_create("closest");
    tcase_add_test(tc, cylinder_open);
    tcase_add_test(tc, cylinder_capped);
    tcase_add_test(tc, cone_face_and_apex);
    tcase_add_test(tc, annulus_faces_and_rims);
    tcase_add_test(tc, rectangle_face_edge_corner);
    tcase_add_test(tc, faces_are_planes);
    suite_add_tcase(s, tc);
    tc = tcase_create("dynamics");
    tcase_add_test(tc, ball_rolls_in_cylinder);
    tcase_add_test(tc, ball_rests_in_cone);
    tcase_add_test(tc, vibrating_floor);
    tcase_add_test(tc, belt_drags_ball_to_rolling);
    tcase_add_test(tc, belt_on_body_drags_ball_to_rolling);
    tcase_add_test(tc, harmonic_rotation_is_exact);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return dm_test_run(walls_suite());
}
