/* bodies.c: bodies moved by the particles (demill/body.h) and fixed
 * particles (DEMILL_PARTICLE_FIXED), against analytic solutions and the
 * energy balance.
 *
 * The reference scene is the spring-mounted box of a particle-damping
 * experiment: a box of 42 × 42 × 24 mm made of six plane walls, of mass
 * 0.3 kg, on a spring of k = 9720 N/m along one axis and driven by a force
 * of amplitude 9.72 N. Its natural frequency is f_n = √(k/m)/(2π) = 28.7 Hz.
 * The numbers checked:
 *  - the empty box, displaced and let go, oscillates at f_n: its period over
 *    100 cycles within 1e-4 (velocity Verlet's frequency error, (ωΔt)²/24,
 *    is 1e-7 here: Hairer, Lubich and Wanner 2003, Geometric numerical
 *    integration illustrated by the Störmer-Verlet method);
 *  - undamped, its energy ½ m v² + ½ k x² stays within 1e-6 over those 100
 *    periods (Verlet's energy error is bounded by (ωΔt)²/4 = 2e-7 of it at
 *    Δt = 5 µs, the same source);
 *  - with a damper of ratio ζ = 0.05 and driven at f = 20 Hz, its steady
 *    amplitude is F0 / √((k − m Ω²)² + (c Ω)²), Ω = 2π f (the steady state of
 *    the driven damped oscillator: Thomson and Dahleh 1998, Theory of
 *    Vibration with Applications, §3.1), within 1e-4; the external force's
 *    work minus the damper's dissipation is the change of the box's energy
 *    (a conservation law) within 1e-6 of that work;
 *  - with 300 balls inside, driven at 20 Hz, the world's energy balance
 *    (DEMILL_ENERGY_TOTAL: particles, contacts, box, spring, damper and the
 *    external force's work) closes within 1e-3 of the energy that went
 *    through it.
 * Fixed particles:
 *  - a ball hitting a fixed ball head-on rebounds with the restitution of the
 *    pair and its contact lasts π / (√(k/m*) √(1 − ξ²)) with m* the moving
 *    ball's own mass, as against an infinitely heavy ball (the classic linear
 *    spring-dashpot, as in collision.c), not m/2 as against a free one;
 *  - a ball dropped on a floor of fixed balls in a square lattice comes to
 *    rest in a pocket, its centre √(4r² − s²/2) above theirs (s the spacing:
 *    it touches four), while the floor's positions, velocities and spins stay
 *    bitwise what they were and the floor's balls, which overlap, never form
 *    contacts with each other.
 * Walls of the other kinds:
 *  - a mesh, a rectangle and an open cylinder attached to a body move with
 *    it and stay where it leaves them when it is removed (a ball pressed
 *    into them feels the force of the same wall added there: bitwise once
 *    the body is removed);
 *  - a wall of the drum, a capped finite wall and a wall in harmonic motion
 *    are refused, the world unchanged. */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define BOX_MASS 0.3
#define BOX_K 9720.0
#define BOX_F0 9.72
#define BOX_X 0.021  /* half sizes of the box, m */
#define BOX_Y 0.012
#define BOX_Z 0.021

/* A world without gravity, one material (linear, restitution damping e, no
 * friction), and the box centred at the origin as a body free along y, on
 * the spring k (rest position rest), without gravity on it. */
static demill_world *box_world(double dt, double rest, demill_id *mat, demill_id *body)
{
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, mat);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    const double c0[3] = {0, 0, 0};
    DM_OK(w, demill_body_add(w, BOX_MASS, c0, DEMILL_BODY_AXIS_Y, DEMILL_BODY_NO_GRAVITY, body));
    DM_OK(w, demill_body_set_spring(w, *body, DEMILL_BODY_AXIS_Y, BOX_K, 0.0, rest));
    const double half[3] = {BOX_X, BOX_Y, BOX_Z};
    for (int a = 0; a < 3; a++)
        for (int s = -1; s <= 1; s += 2) {
            double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            p[a] = s * half[a];
            n[a] = -s; /* facing the inside */
            demill_id wall;
            DM_OK(w, demill_wall_add_plane(w, *mat, p, n, &wall));
            DM_OK(w, demill_body_attach_wall(w, *body, wall));
        }
    return w;
}

static double body_y(demill_world *w, demill_id body, int field)
{
    double v[3];
    DM_OK(w, demill_body_get(w, body, field, v));
    return v[1];
}

START_TEST(free_oscillation)
{
    const double dt = 5e-6, x0 = 1e-3;
    const double omega = sqrt(BOX_K / BOX_MASS), period = 2 * M_PI / omega;
    ck_assert(fabs(1 / period - 28.7) < 0.06); /* the scene's natural frequency, 28.65 Hz */
    demill_id mat, body;
    demill_world *w = box_world(dt, -x0, &mat, &body); /* released 1 mm from rest */
    const double e0 = 0.5 * BOX_K * x0 * x0;
    DM_ASSERT_REL(dm_test_energy(w, DEMILL_ENERGY_TOTAL), e0, 1e-15);
    /* sampled every 10 steps (350 samples a period): at a crossing the
     * sine's curvature vanishes, so linear interpolation errs in the third
     * order, about 1e-9 of a period */
    const long samples = lround(100.5 * period / (10 * dt));
    double prev = x0, first = -1, last = -1, worst = 0;
    int crossings = 0;
    for (long k = 1; k <= samples; k++) {
        DM_OK(w, demill_world_step(w, 10));
        const double y = body_y(w, body, DEMILL_BODY_POSITION) + x0;
        if (prev < 0 && y >= 0) { /* upward through the rest position */
            const double t = (k - 1 + -prev / (y - prev)) * 10 * dt;
            if (first < 0)
                first = t;
            last = t;
            crossings++;
        }
        prev = y;
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0));
    }
    ck_assert_int_eq(crossings, 100);
    DM_ASSERT_REL((last - first) / (crossings - 1), period, 1e-4);
    ck_assert_msg(worst <= 1e-6 * e0, "energy drifted by %g of %g", worst / e0, e0);
    double ek, es;
    DM_OK(w, demill_body_energy(w, body, DEMILL_ENERGY_BODY_KINETIC, &ek));
    DM_OK(w, demill_body_energy(w, body, DEMILL_ENERGY_BODY_ELASTIC, &es));
    DM_ASSERT_REL(ek + es, e0, 1e-6);
    demill_world_destroy(w);
}
END_TEST

START_TEST(driven_steady_amplitude)
{
    const double dt = 1e-5, f = 20.0, zeta = 0.05, Om = 2 * M_PI * f;
    const double c = 2 * zeta * sqrt(BOX_K * BOX_MASS);
    const double amp = BOX_F0 / sqrt(pow(BOX_K - BOX_MASS * Om * Om, 2) + pow(c * Om, 2));
    demill_id mat, body;
    demill_world *w = box_world(dt, 0.0, &mat, &body);
    DM_OK(w, demill_body_set_spring(w, body, DEMILL_BODY_AXIS_Y, BOX_K, c, 0.0));
    const double f0[3] = {0, BOX_F0, 0};
    DM_OK(w, demill_body_set_force(w, body, f0, f, 0.0));
    /* the transient decays as exp(-ζ ω t): 1.5 s leaves 1e-6 of it */
    DM_OK(w, demill_world_step(w, 150000));
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 50000; k++) { /* 10 periods */
        DM_OK(w, demill_world_step(w, 1));
        const double y = body_y(w, body, DEMILL_BODY_POSITION);
        lo = fmin(lo, y);
        hi = fmax(hi, y);
    }
    DM_ASSERT_REL(0.5 * (hi - lo), amp, 1e-4);
    const double work = dm_test_energy(w, DEMILL_ENERGY_BODY_WORK);
    const double change = dm_test_energy(w, DEMILL_ENERGY_BODY_KINETIC) +
                          dm_test_energy(w, DEMILL_ENERGY_BODY_ELASTIC) +
                          dm_test_energy(w, DEMILL_ENERGY_BODY_DISSIPATED);
    ck_assert(work > 0);
    ck_assert_msg(fabs(work - change) <= 1e-6 * work,
                  "work %.9g, energy gained and dissipated %.9g", work, change);
    ck_assert(fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL)) <= 1e-6 * work);
    demill_world_destroy(w);
}
END_TEST

START_TEST(balls_in_box_energy_balance)
{
    const double dt = 1e-5, r = 0.0015;
    demill_id mat, body;
    demill_world *w = box_world(dt, 0.0, &mat, &body);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_STIFFNESS, 2e3));
    DM_OK(w, demill_material_set(w, mat, DEMILL_MATERIAL_FRICTION, 0.3));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_RESTITUTION, 0.5));
    DM_OK(w, demill_pair_set(w, mat, mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double f0[3] = {0, BOX_F0, 0};
    DM_OK(w, demill_body_set_force(w, body, f0, 20.0, 0.0));
    double x[900], rad[300];
    int n = 0;
    for (int l = 0; l < 3; l++)
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++, n++) {
                x[3 * n] = (i - 4.5) * 0.0038 + 0.0002 * l;
                x[3 * n + 1] = -BOX_Y + r + 0.0005 + l * 0.0045;
                x[3 * n + 2] = (j - 4.5) * 0.0038 - 0.0001 * l;
                rad[n] = r;
            }
    DM_OK(w, demill_particles_add(w, mat, 300, x, rad, NULL, DEMILL_ADD_NO_OVERLAP, NULL));
    const double total0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    double through = 0, worst = 0;
    for (int k = 0; k < 60; k++) { /* 0.3 s, 6 periods of the drive */
        DM_OK(w, demill_world_step(w, 500));
        const double total = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
        worst = fmax(worst, fabs(total - total0));
        through = fmax(through, fabs(dm_test_energy(w, DEMILL_ENERGY_BODY_WORK)) +
                                    dm_test_energy(w, DEMILL_ENERGY_DISSIPATED));
    }
    double fp[3];
    DM_OK(w, demill_body_get(w, body, DEMILL_BODY_FORCE_PARTICLES, fp));
    ck_assert_msg(dm_test_energy(w, DEMILL_ENERGY_DISSIPATED) > 0.05 * through,
                  "the balls barely touched the box");
    ck_assert_msg(worst <= 1e-3 * through, "the balance moved by %g J, %g of the %g J through it",
                  worst, worst / through, through);
    demill_world_destroy(w);
}
END_TEST

/* ---- fixed particles ------------------------------------------------------- */

START_TEST(hit_on_fixed_ball)
{
    for (int dim = 2; dim <= 3; dim++) {
        demill_id m;
        demill_world *w =
            dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
        const double e = 0.5;
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, e));
        DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_CLAMP_NORMAL, 0));
        const double r = 0.005, k = 5e4; /* default stiffness 1e5 in series */
        double mass;
        const double x[6] = {0, 0, 0, 1, 0, 0};
        demill_id ids[2];
        const double rr[2] = {r, r};
        DM_OK(w, demill_particles_add(w, m, 2, x, rr, NULL, 0, ids));
        DM_OK(w, demill_particle_get(w, ids[0], DEMILL_PARTICLE_MASS, &mass));
        DM_OK(w, demill_particles_remove(w, 2, ids));
        const double l = log(e), xi = -l / sqrt(M_PI * M_PI + l * l);
        const double tc = M_PI / (sqrt(k / mass) * sqrt(1 - xi * xi));
        for (int p = 0; p < 8; p++) {
            const dm_collision o = dm_test_hit_fixed(w, m, r, 1.0, tc / 50, (p + 0.5) / 8);
            DM_ASSERT_REL(o.restitution, e, 0.01);
            DM_ASSERT_REL(o.duration, tc, 0.02);
        }
        demill_world_destroy(w);
    }
}
END_TEST

START_TEST(ball_on_rough_floor)
{
    demill_id m;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.3));
    const double r = 0.005, s = 0.0098; /* the floor's balls overlap by 0.2 mm */
    double x[78], rad[26];
    demill_id ids[26];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            const int q = 5 * i + j;
            x[3 * q] = (i - 2) * s;
            x[3 * q + 1] = 0.0;
            x[3 * q + 2] = (j - 2) * s;
            rad[q] = r;
        }
    x[75] = 0.5 * s; /* over the pocket of four */
    x[76] = 0.02;
    x[77] = 0.5 * s;
    rad[25] = r;
    DM_OK(w, demill_particles_add(w, m, 26, x, rad, NULL, 0, ids));
    const double one = 1.0;
    for (int q = 0; q < 25; q++)
        DM_OK(w, demill_particle_set(w, ids[q], DEMILL_PARTICLE_FIXED, &one));
    double before[3][75], after[3][75];
    const int fields[3] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                           DEMILL_PARTICLE_ANGULAR_VELOCITY};
    for (int f = 0; f < 3; f++)
        for (int q = 0; q < 25; q++)
            DM_OK(w, demill_particle_get(w, ids[q], fields[f], before[f] + 3 * q));
    /* The fixed balls neither turn nor move, so the rotational energy is the
     * ball's own 1/2 I ω², I = 2/5 m r², here of a spin of 10 rad/s (which
     * nothing couples to its fall: the contacts have no friction). */
    const double spin[3] = {0, 0, 10}, mb = dm_test_get(w, ids[25], DEMILL_PARTICLE_MASS, 0);
    double rot;
    DM_OK(w, demill_particle_set(w, ids[25], DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL, &rot));
    DM_ASSERT_REL(rot, 0.5 * 0.4 * mb * r * r * 100, 1e-12);
    size_t contacts = 1;
    for (int k = 0; k < 50; k++) { /* 0.5 s */
        DM_OK(w, demill_world_step(w, 1000));
        size_t c;
        DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &c));
        ck_assert_uint_le(c, 4); /* only the ball's with the floor */
        contacts = c;
    }
    ck_assert_uint_eq(contacts, 4);
    for (int f = 0; f < 3; f++)
        for (int q = 0; q < 25; q++)
            DM_OK(w, demill_particle_get(w, ids[q], fields[f], after[f] + 3 * q));
    ck_assert(!memcmp(before, after, sizeof before));
    double fixed;
    DM_OK(w, demill_particle_get(w, ids[0], DEMILL_PARTICLE_FIXED, &fixed));
    ck_assert(fixed == 1.0);
    DM_OK(w, demill_particle_get(w, ids[25], DEMILL_PARTICLE_FIXED, &fixed));
    ck_assert(fixed == 0.0);
    DM_ASSERT_REL(dm_test_get(w, ids[25], DEMILL_PARTICLE_POSITION, 1),
                  sqrt(4 * r * r - s * s / 2), 1e-3);
    ck_assert(fabs(dm_test_get(w, ids[25], DEMILL_PARTICLE_VELOCITY, 1)) < 1e-4);
    demill_world_destroy(w);
}
END_TEST

/* The checkpoint of w, to compare the world before and after a refused call. */
static unsigned char *saved(demill_world *w, size_t *n)
{
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, n));
    unsigned char *b = malloc(*n);
    ck_assert_ptr_nonnull(b);
    DM_OK(w, demill_world_save_buffer(w, b, *n, n));
    return b;
}

/* demill_body_attach_wall() refuses, with a message naming the reason and
 * the world left as it was: a wall attached to the drum, a finite wall with
 * caps (its caps would not follow) and a wall in harmonic motion; a body's
 * wall cannot be given a harmonic motion or be attached to the drum. */
START_TEST(attach_refuses_walls_it_cannot_move)
{
    demill_id mat, body, drum, plane, can, shaker;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &mat);
    const double c[3] = {0, 0, 0}, p[3] = {0, 0.2, 0}, y[3] = {0, 1, 0}, o[3] = {0.5, 0, 0};
    DM_OK(w, demill_body_add(w, 1.0, c, DEMILL_BODY_AXIS_Y, 0, &body));
    DM_OK(w, demill_drum_create(w, mat, &drum));
    DM_OK(w, demill_wall_add_plane(w, mat, p, y, &plane));
    DM_OK(w, demill_drum_attach_wall(w, drum, plane, DEMILL_DRUM_PART_SHELL));
    DM_OK(w, demill_wall_add_cylinder(w, mat, o, y, 0.05, 0.1, DEMILL_CAPS_BOTH, &can));
    DM_OK(w, demill_wall_add_plane(w, mat, c, y, &shaker));
    DM_OK(w, demill_wall_set_harmonic(w, shaker, DEMILL_HARMONIC_TRANSLATION, y, 1e-3, 20, 0));
    const struct {
        demill_id wall;
        const char *word;
    } cases[3] = {{plane, "drum"}, {can, "caps"}, {shaker, "harmonic"}};
    for (int k = 0; k < 3; k++) {
        size_t n0, n1;
        unsigned char *before = saved(w, &n0);
        ck_assert_int_eq(demill_body_attach_wall(w, body, cases[k].wall),
                         DEMILL_ERR_INVALID_VALUE);
        ck_assert_msg(strstr(demill_world_last_error(w), cases[k].word), "%s",
                      demill_world_last_error(w));
        unsigned char *after = saved(w, &n1);
        ck_assert(n0 == n1 && memcmp(before, after, n0) == 0);
        free(before);
        free(after);
    }
    /* and once attached, a wall cannot be given a harmonic motion */
    demill_id free_wall;
    DM_OK(w, demill_wall_add_plane(w, mat, o, y, &free_wall));
    DM_OK(w, demill_body_attach_wall(w, body, free_wall));
    ck_assert_int_eq(demill_wall_set_harmonic(w, free_wall, DEMILL_HARMONIC_TRANSLATION, y, 1e-3,
                                              20, 0),
                     DEMILL_ERR_INVALID_VALUE);
    /* nor be attached to the drum */
    ck_assert_int_eq(demill_drum_attach_wall(w, drum, free_wall, DEMILL_DRUM_PART_SHELL),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert(strstr(demill_world_last_error(w), "body"));
    demill_world_destroy(w);
}
END_TEST

/* A floor y = y0 (kind 0: a mesh of two triangles, 1: a rectangle, 2: an
 * open cylinder's side seen from inside, its axis along x at height y0 +
 * 0.1) of material mat. */
static demill_id add_floor(demill_world *w, demill_id mat, int kind, double y0)
{
    demill_id id;
    if (kind == 0) {
        const double v[12] = {-0.1, y0, -0.1, 0.1, y0, -0.1, 0.1, y0, 0.1, -0.1, y0, 0.1};
        const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        DM_OK(w, demill_wall_add_mesh(w, mat, 4, v, 2, t, &id));
    } else if (kind == 1) {
        const double c[3] = {0, y0, 0}, n[3] = {0, 1, 0}, e[3] = {1, 0, 0};
        DM_OK(w, demill_wall_add_rectangle(w, mat, c, n, e, 0.1, 0.1, &id));
    } else {
        const double p[3] = {-0.1, y0 + 0.1, 0}, x[3] = {1, 0, 0};
        DM_OK(w, demill_wall_add_cylinder(w, mat, p, x, 0.1, 0.2, DEMILL_CAPS_NONE, &id));
    }
    return id;
}

/* The y force on floor of a ball of radius 0.01 m whose centre is at
 * height y, after one step. */
static double press(demill_world *w, demill_id mat, demill_id floor, double y)
{
    const double r = 0.01, x[3] = {0.003, y, 0.002}, v[3] = {0, 0, 0};
    DM_OK(w, demill_particles_add(w, mat, 1, x, &r, v, 0, NULL));
    DM_OK(w, demill_world_step(w, 1));
    double f[3];
    DM_OK(w, demill_wall_get(w, floor, DEMILL_WALL_FORCE, f));
    return f[1];
}

/* A mesh, a rectangle and an open cylinder attached to a body move with it,
 * and stay where it left them when it is removed: a ball pressed 1e-4 m into
 * them feels the force it feels from the same wall added where the body has
 * put it. */
START_TEST(finite_and_mesh_walls_follow_the_body)
{
    for (int kind = 0; kind < 3; kind++) {
        for (int removed = 0; removed < 2; removed++) {
            demill_id mat, body, floor, ref_mat;
            demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
            const double c[3] = {0, 0, 0};
            DM_OK(w, demill_body_add(w, 1e4, c, DEMILL_BODY_AXIS_Y, DEMILL_BODY_NO_GRAVITY,
                                     &body));
            DM_OK(w, demill_body_set_spring(w, body, DEMILL_BODY_AXIS_Y, 1e8, 0.0, 0.03));
            floor = add_floor(w, mat, kind, 0.0);
            DM_OK(w, demill_body_attach_wall(w, body, floor));
            DM_OK(w, demill_world_step(w, 200));
            double x[3], v[3], dt;
            DM_OK(w, demill_body_get(w, body, DEMILL_BODY_POSITION, x));
            DM_OK(w, demill_body_get(w, body, DEMILL_BODY_VELOCITY, v));
            DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
            ck_assert(x[1] > 1e-4); /* it has moved */
            double ball = x[1] + 0.01 - 1e-4;
            if (removed) {
                DM_OK(w, demill_body_remove(w, body));
            } else {
                DM_OK(w, demill_body_set_spring(w, body, DEMILL_BODY_AXIS_Y, 0.0, 0.0, 0.0));
                ball += v[1] * dt; /* where the floor will be at the step's forces */
            }
            const double got = press(w, mat, floor, ball);
            double y0 = x[1];
            if (!removed) { /* where the floor was at the step's forces */
                double x1[3];
                DM_OK(w, demill_body_get(w, body, DEMILL_BODY_POSITION, x1));
                y0 = x1[1];
            }
            demill_world *ref = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE,
                                              &ref_mat);
            const demill_id ref_floor = add_floor(ref, ref_mat, kind, y0);
            const double want = press(ref, ref_mat, ref_floor, ball);
            ck_assert_msg(want < 0 && got < 0, "kind %d: forces %g %g", kind, got, want);
            /* removed: the same floor, bit for bit; attached: the ball's first
             * kick saw the floor a step's travel (6e-6 m) lower than the
             * reference does, which moves the ball by 1.4e-9 m */
            DM_ASSERT_REL(got, want, removed ? 1e-12 : 1e-4);
            demill_world_destroy(ref);
            demill_world_destroy(w);
        }
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("bodies");
    TCase *tc = tcase_create("bodies");
    tcase_add_test(tc, free_oscillation);
    tcase_add_test(tc, driven_steady_amplitude);
    tcase_add_test(tc, balls_in_box_energy_balance);
    tcase_add_test(tc, hit_on_fixed_ball);
    tcase_add_test(tc, ball_on_rough_floor);
    tcase_add_test(tc, attach_refuses_walls_it_cannot_move);
    tcase_add_test(tc, finite_and_mesh_walls_follow_the_body);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
