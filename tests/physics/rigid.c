/* rigid.c: rigid materials (DEMILL_MATERIAL_RIGID) against the analytic
 * impact of a deformable sphere on a rigid plane.
 *
 * A pair of a rigid and a deformable material takes its elastic constants
 * from the deformable one alone: 1/E* = (1 - ν²)/E, k_n = k (docs/physics.md
 * §2, Rigid materials). The rigid material's own modulus and stiffness are
 * set to absurd values (1 Pa and 1 N/m, or 1e30), so that any use of them
 * would show. Independent numbers:
 *  - Hertz, undamped (Johnson 1985, Contact Mechanics §11.4): the impact of a
 *    sphere of mass m and radius R on a rigid plane at speed v lasts
 *    t_c = 2.868 (m²/(R E*² v))^{1/5} with E* = E/(1 - ν²) of the sphere
 *    (2.868 = 2.94324 (15/16)^{2/5}), and rebounds at v (e = 1);
 *  - linear spring-dashpot (the classic unclamped model): with
 *    ξ = -ln e/√(π² + ln² e) the sphere rebounds at e v after
 *    π/(ω √(1 - ξ²)), ω = √(k/m), k the sphere material's stiffness;
 *  - Hertz with the restitution dashpot: e exactly as asked (the library's
 *    ξ(e), docs/physics.md §3), to the 0.5 % that tests/physics/entry.c
 *    holds every impact to at 50 steps per contact;
 *  - a rigid sphere keeps the mass of its density, 4/3 π R³ ρ, and its
 *    impact on a deformable plane is the same as the deformable sphere's on
 *    a rigid one, with the plane's E* (the same formula);
 *  - demill_world_suggest_time_step() gives the Hertz duration of the pair's
 *    E* (its constant 2.87: within 0.1 % of 2.868), and no Rayleigh-time
 *    bound from a rigid particle (whose stored modulus 1e30 would make that
 *    bound 1e-14 s).
 * Each impact starts half a step from a sample (phase 0.5) at 50 steps per
 * contact, in 2D and 3D, on a plane and on a mesh (a polyline in 2D);
 * velocity Verlet.
 */
#include <math.h>

#include "testutil.h"

static const double R = 0.005, RHO = 2500, E = 1e8, NU = 0.3, V0 = 1.0;

/* The Hertz duration of an impact at V0 of mass m, radius r, modulus e_star. */
static double hertz_time(double m, double r, double e_star)
{
    return 2.868 * pow(m * m / (r * e_star * e_star * V0), 0.2);
}

/* A world of dimension dim without gravity: a deformable material *soft
 * (E, NU, RHO) and a rigid material *hard (modulus and stiffness `junk`),
 * with the given laws for (soft, hard) and a normal law for (soft, soft),
 * which a lone particle needs. */
static demill_world *two_materials(int dim, int normal, int damping, double junk,
                                   demill_id *soft, demill_id *hard)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0));
    DM_OK(w, demill_material_create(w, soft));
    DM_OK(w, demill_material_create(w, hard));
    DM_OK(w, demill_material_set(w, *soft, DEMILL_MATERIAL_DENSITY, RHO));
    DM_OK(w, demill_material_set(w, *soft, DEMILL_MATERIAL_YOUNGS_MODULUS, E));
    DM_OK(w, demill_material_set(w, *soft, DEMILL_MATERIAL_POISSON_RATIO, NU));
    DM_OK(w, demill_material_set(w, *hard, DEMILL_MATERIAL_RIGID, 1));
    DM_OK(w, demill_material_set(w, *hard, DEMILL_MATERIAL_YOUNGS_MODULUS, junk));
    DM_OK(w, demill_material_set(w, *hard, DEMILL_MATERIAL_POISSON_RATIO, 0.45));
    DM_OK(w, demill_material_set(w, *hard, DEMILL_MATERIAL_STIFFNESS, junk));
    DM_OK(w, demill_pair_set(w, *soft, *hard, DEMILL_PAIR_NORMAL, normal));
    DM_OK(w, demill_pair_set(w, *soft, *hard, DEMILL_PAIR_DAMPING, damping));
    DM_OK(w, demill_pair_set(w, *soft, *soft, DEMILL_PAIR_NORMAL, normal));
    return w;
}

START_TEST(hertz_sphere_on_rigid_plane)
{
    const int dim = 2 + _i;
    demill_id soft, hard;
    demill_world *w =
        two_materials(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, 1.0, &soft, &hard);
    const double m = 4.0 / 3.0 * M_PI * R * R * R * RHO;
    const double tc = hertz_time(m, R, E / (1 - NU * NU));
    const dm_collision o = dm_test_bounce_on(w, soft, hard, R, V0, tc / 50, 0.5);
    DM_ASSERT_REL(o.duration, tc, 0.01);
    DM_ASSERT_REL(o.restitution, 1.0, 1e-4);
    demill_world_destroy(w);
}
END_TEST

START_TEST(restitution_on_rigid_plane)
{
    const int dim = 2 + _i;
    const double e = 0.5, m = 4.0 / 3.0 * M_PI * R * R * R * RHO;
    for (int normal = DEMILL_NORMAL_LINEAR; normal <= DEMILL_NORMAL_HERTZ; normal++) {
        demill_id soft, hard;
        demill_world *w =
            two_materials(dim, normal, DEMILL_DAMPING_RESTITUTION, 1.0, &soft, &hard);
        DM_OK(w, demill_pair_set(w, soft, hard, DEMILL_PAIR_RESTITUTION, e));
        DM_OK(w, demill_pair_set(w, soft, hard, DEMILL_PAIR_CLAMP_NORMAL, 0));
        double k, k_soft;
        DM_OK(w, demill_pair_get(w, soft, hard, DEMILL_PAIR_NORMAL_STIFFNESS, &k));
        DM_OK(w, demill_material_get(w, soft, DEMILL_MATERIAL_STIFFNESS, &k_soft));
        ck_assert_double_eq(k, k_soft);
        const double l = log(e), xi = -l / sqrt(M_PI * M_PI + l * l);
        const double tc = normal == DEMILL_NORMAL_LINEAR
                              ? M_PI / (sqrt(k_soft / m) * sqrt(1 - xi * xi))
                              : hertz_time(m, R, E / (1 - NU * NU));
        const dm_collision o = dm_test_bounce_on(w, soft, hard, R, V0, tc / 50, 0.5);
        DM_ASSERT_REL(o.restitution, e, 0.005);
        if (normal == DEMILL_NORMAL_LINEAR)
            DM_ASSERT_REL(o.duration, tc, 0.01);
        demill_world_destroy(w);
    }
}
END_TEST

/* The same impact on a rigid mesh (3D: a floor of 4 x 4 squares, each two
 * triangles, the sphere over a face's inside) or polyline (2D: three
 * segments): the wall's geometry does not change the pair's constants. */
START_TEST(hertz_sphere_on_rigid_mesh)
{
    const int dim = 2 + _i;
    demill_id soft, hard, wall, ball;
    demill_world *w =
        two_materials(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, 1.0, &soft, &hard);
    if (dim == 3) {
        double v[3 * 25];
        uint32_t t[6 * 16];
        dm_test_floor_grid(4, 0.01, -0.02, v, t);
        DM_OK(w, demill_wall_add_mesh(w, hard, 25, v, 32, t, &wall));
    } else {
        const double pts[12] = {-0.02, 0, 0, -0.004, 0, 0, 0.003, 0, 0, 0.02, 0, 0};
        DM_OK(w, demill_wall_add_polyline(w, hard, 4, pts, 0, &wall));
    }
    const double m = 4.0 / 3.0 * M_PI * R * R * R * RHO;
    const double tc = hertz_time(m, R, E / (1 - NU * NU)), dt = tc / 50, gap = 3.5 * V0 * dt;
    double x[3] = {0.0023, R + gap, dim == 3 ? 0.0061 : 0.0}, v[3] = {0, -V0, 0};
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_particles_add(w, soft, 1, x, (double[]){R}, v, 0, &ball));
    double t_in = -1, t_out = -1, prev = -gap;
    for (int k = 1; k <= 200 && t_out < 0; k++) {
        DM_OK(w, demill_world_step(w, 1));
        const double d = R - dm_test_get(w, ball, DEMILL_PARTICLE_POSITION, 1);
        if (prev <= 0 && d > 0)
            t_in = k - 1 - prev / (d - prev);
        if (prev > 0 && d <= 0)
            t_out = k - 1 + prev / (prev - d);
        prev = d;
    }
    ck_assert_msg(t_in > 0 && t_out > t_in, "the ball did not bounce");
    DM_ASSERT_REL((t_out - t_in) * dt, tc, 0.01);
    DM_ASSERT_REL(dm_test_get(w, ball, DEMILL_PARTICLE_VELOCITY, 1), V0, 1e-4);
    demill_world_destroy(w);
}
END_TEST

/* The rigid sphere of rigid_sphere_on_plane, with the impact's bounds. */
typedef struct rigid_ball {
    demill_world *w;
    demill_id soft, hard, ball;
    double m, tc;
} rigid_ball;

/* A rigid ball of density 7800 (its stored modulus 1e30) moving at V0
 * towards a plane of the deformable material, starting half a step from a
 * sample at 50 steps per contact; no model for the ball's material with
 * itself, which a lone rigid particle does not need. */
static rigid_ball rigid_ball_scene(int dim)
{
    rigid_ball s;
    s.w = two_materials(dim, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, 1e30, &s.soft, &s.hard);
    DM_OK(s.w, demill_material_set(s.w, s.hard, DEMILL_MATERIAL_DENSITY, 7800));
    s.m = 4.0 / 3.0 * M_PI * R * R * R * 7800;
    s.tc = hertz_time(s.m, R, E / (1 - NU * NU));
    const double dt = s.tc / 50, gap = 3.5 * V0 * dt;
    double x[3] = {R + gap, 0, 0}, v[3] = {-V0, 0, 0}, origin[3] = {0, 0, 0}, n[3] = {1, 0, 0};
    demill_id plane;
    DM_OK(s.w, demill_world_set(s.w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(s.w, demill_wall_add_plane(s.w, s.soft, origin, n, &plane));
    DM_OK(s.w, demill_particles_add(s.w, s.hard, 1, x, (double[]){R}, v, 0, &s.ball));
    return s;
}

START_TEST(rigid_sphere_on_plane)
{
    rigid_ball s = rigid_ball_scene(2 + _i);
    DM_ASSERT_REL(dm_test_get(s.w, s.ball, DEMILL_PARTICLE_MASS, 0), s.m, 1e-15);
    double suggested, critical, contact;
    DM_OK(s.w, demill_world_suggest_time_step(s.w, V0, 50, &suggested, &critical, &contact));
    DM_ASSERT_REL(contact, s.tc, 0.001);
    DM_ASSERT_REL(suggested, fmin(contact / 50, 0.2 * critical), 1e-15);
    /* the bounce: in contact while x < R, out at speed V0 */
    double t_in = -1, t_out = -1, prev = 0;
    for (int k = 1; k <= 200 && t_out < 0; k++) {
        DM_OK(s.w, demill_world_step(s.w, 1));
        const double d = R - dm_test_get(s.w, s.ball, DEMILL_PARTICLE_POSITION, 0);
        if (k > 1 && prev <= 0 && d > 0)
            t_in = k - 1 - prev / (d - prev);
        if (prev > 0 && d <= 0)
            t_out = k - 1 + prev / (prev - d);
        prev = d;
    }
    ck_assert_msg(t_in > 0 && t_out > t_in, "the ball did not bounce");
    DM_ASSERT_REL((t_out - t_in) * s.tc / 50, s.tc, 0.01);
    DM_ASSERT_REL(dm_test_get(s.w, s.ball, DEMILL_PARTICLE_VELOCITY, 0), V0, 1e-4);
    demill_world_destroy(s.w);
}
END_TEST

/* A checkpoint and a snapshot carry the material's rigidity: the copies
 * bounce as the original does, bit for bit. */
START_TEST(rigid_survives_copies)
{
    rigid_ball s = rigid_ball_scene(3);
    dm_test_copies_run_on(s.w, 80, NULL, NULL);
    DM_ASSERT_REL(dm_test_get(s.w, s.ball, DEMILL_PARTICLE_VELOCITY, 0), V0, 1e-4);
    demill_world_destroy(s.w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("rigid");
    TCase *tc = tcase_create("rigid");
    tcase_add_loop_test(tc, hertz_sphere_on_rigid_plane, 0, 2);
    tcase_add_loop_test(tc, restitution_on_rigid_plane, 0, 2);
    tcase_add_loop_test(tc, hertz_sphere_on_rigid_mesh, 0, 2);
    tcase_add_loop_test(tc, rigid_sphere_on_plane, 0, 2);
    tcase_add_test(tc, rigid_survives_copies);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
