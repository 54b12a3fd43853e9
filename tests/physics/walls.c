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
 * Mindlin friction) has the plane's force history to 1e-12. */
#include <math.h>
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
    return s;
}

int main(void)
{
    return dm_test_run(walls_suite());
}
