/* clumps.c: clumps, rigid bodies of overlapping spheres (demill/clump.h),
 * against analytic solutions and conservation laws.
 *  - A clump of one sphere is that sphere: bouncing on a floor, rolling and
 *    hitting another ball (Hertz, restitution damping, Mindlin friction),
 *    its position, velocity and spin are the free sphere's to round-off
 *    (1e-9 of the motion's scale over 0.3 s; measured: see below).
 *  - The tennis-racket effect: a free asymmetric clump of three spheres,
 *    spun about its intermediate axis with a small component about its
 *    largest, flips: its spin about the intermediate axis changes sign
 *    every 2K(k)/λ, from the Jacobi elliptic solution of Euler's equations
 *    (Landau and Lifshitz 1976, Mechanics, 3rd ed., §37: for M² > 2E I₂,
 *    λ = √((I₃ − I₂)(M² − 2E I₁)/(I₁ I₂ I₃)),
 *    k² = (I₂ − I₁)(2E I₃ − M²)/((I₃ − I₂)(M² − 2E I₁)), Ω₂ ∝ sn(λt, k));
 *    over 1e6 steps the world angular momentum is kept to 1e-10 relative
 *    and the kinetic energy to 1e-6 (a symplectic splitting's energy error
 *    stays O(Δt²) for all time: Dullweber, Leimkuhler and McLachlan 1997).
 *  - A dumbbell of two spheres lying along an incline (gravity tilted by θ
 *    over a plane floor) stays when tan θ < μ and slides when tan θ > μ,
 *    accelerating at g (sin θ − μ cos θ) (Coulomb's law on a body that
 *    cannot roll: its two contacts share M g cos θ).
 *  - A flat clump dropped on a plane lands flat: every member touches and
 *    its orientation is kept (by symmetry the torques cancel); its members'
 *    orientations are its own.
 *  - The energy balance (DEMILL_ENERGY_TOTAL) closes to 1e-3 of the energy
 *    through in a turning drum charged with clumps, 2D and 3D.
 *  - That drum's clumps move bitwise the same on 1 and on 2 threads, and
 *    on from a snapshot restored into another world as in the world that
 *    took it, and on from a checkpoint loaded (format 5, which saves
 *    again as the same bytes). */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* The rotation matrix of the unit quaternion q (w, x, y, z), row-major. */
static void quat_matrix(const double q[4], double R[9])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    memcpy(R, m, sizeof m);
}

/* The complete elliptic integral of the first kind K(k) by the arithmetic-
 * geometric mean, K = π / (2 AGM(1, √(1 − k²))) (Abramowitz and Stegun
 * 1964, Handbook of Mathematical Functions, 17.6). */
static double elliptic_k(double k2)
{
    double a = 1.0, b = sqrt(1.0 - k2);
    for (int i = 0; i < 60 && fabs(a - b) > 1e-16 * a; i++) {
        const double m = 0.5 * (a + b);
        b = sqrt(a * b);
        a = m;
    }
    return M_PI / (2.0 * a);
}

/* Three spheres of radius R at the corners of a right triangle, no two
 * overlapping: distinct principal moments. */
#define RACKET_R 0.01
static const double racket_c[9] = {0, 0, 0, 3 * RACKET_R, 0, 0, 0, 2.2 * RACKET_R, 0};
static const double racket_r[3] = {RACKET_R, RACKET_R, 0.8 * RACKET_R};

START_TEST(tennis_racket_flips)
{
    demill_id mat, tmpl, clump;
    demill_world *w = dm_test_world(3, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_NONE, &mat);
    DM_OK(w, demill_clump_template_add(w, mat, 3, racket_c, racket_r, &tmpl));
    double I[3];
    DM_OK(w, demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_PRINCIPAL_MOMENTS, I));
    ck_assert(I[0] < I[1] && I[1] < I[2]);
    const double at[3] = {0, 0, 0};
    DM_OK(w, demill_clump_add(w, tmpl, at, NULL, &clump));
    /* body axes along x, y, z: spin 10 rad/s about y (intermediate) and a
     * little about z (largest), so that M² > 2 E I₂ */
    const double om0[3] = {0, 10.0, 0.1}, dt = 5e-5;
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_clump_set(w, clump, DEMILL_CLUMP_ANGULAR_VELOCITY, om0));
    const double M2 = I[1] * I[1] * om0[1] * om0[1] + I[2] * I[2] * om0[2] * om0[2];
    const double E2 = I[1] * om0[1] * om0[1] + I[2] * om0[2] * om0[2]; /* 2E */
    const double lambda = sqrt((I[2] - I[1]) * (M2 - E2 * I[0]) / (I[0] * I[1] * I[2]));
    const double k2 = (I[1] - I[0]) * (E2 * I[2] - M2) / ((I[2] - I[1]) * (M2 - E2 * I[0]));
    const double half = 2.0 * elliptic_k(k2) / lambda; /* between flips */

    double L0[3], ke0;
    DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_ANGULAR_MOMENTUM, L0));
    DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL, &ke0));
    DM_ASSERT_REL(ke0, 0.5 * E2, 1e-12);
    const long steps = 1000000, chunk = 10;
    double last = 0.0, t_prev = 0.0, first = -1.0, latest = -1.0, worst_ke = 0.0;
    int flips = 0;
    for (long s = 0; s <= steps; s += chunk) {
        if (s)
            DM_OK(w, demill_world_step(w, (uint64_t)chunk));
        double q[4], L[3], R[9], t;
        DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_ORIENTATION, q));
        DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_ANGULAR_MOMENTUM, L));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
        quat_matrix(q, R);
        const double pi2 = R[1] * L[0] + R[4] * L[1] + R[7] * L[2]; /* body y */
        if (s && (pi2 > 0) != (last > 0)) { /* a flip, its time interpolated */
            const double tf = t_prev + (t - t_prev) * last / (last - pi2);
            if (first < 0)
                first = tf;
            latest = tf;
            flips++;
        }
        last = pi2;
        t_prev = t;
        if (s % 100000 == 0) {
            double ke;
            DM_OK(w, demill_world_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL, &ke));
            worst_ke = fmax(worst_ke, fabs(ke - ke0) / ke0);
            for (int a = 0; a < 3; a++)
                ck_assert_msg(fabs(L[a] - L0[a]) <= 1e-10 * sqrt(M2), "L[%d] %.17g from %.17g",
                              a, L[a], L0[a]);
        }
    }
    const double measured = (latest - first) / (flips - 1);
    ck_assert_int_ge(flips, (int)(steps * dt / half) - 1);
    DM_ASSERT_REL(measured, half, 1e-6);
    ck_assert_msg(worst_ke <= 1e-6, "kinetic energy off by %g", worst_ke);
    demill_world_destroy(w);
}
END_TEST

/* A steel world with gravity, Hertz contacts, restitution damping and
 * Mindlin friction, with a floor at y = 0 if asked. */
static demill_world *steel_world(int dim, int floor, demill_id *mat)
{
    demill_world *w = NULL;
    DM_OK(w, demill_world_create(dim, &w));
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_RESTITUTION, 0.6));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_FRICTION, 0.4));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    const double origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    demill_id wall;
    if (floor)
        DM_OK(w, demill_wall_add_plane(w, *mat, origin, up, &wall));
    return w;
}

START_TEST(one_sphere_clump_is_the_sphere)
{
    const int dim = _i ? 2 : 3;
    const double r = 0.005, a0[3] = {0, 0.02, 0}, b0[3] = {0.06, 0.005, 0};
    const double va[3] = {0.8, 0, 0}, spin[3] = {0, 0, 30}; /* backspin: it skids, then rolls */
    demill_id mat, a, b, clump, tmpl, ids[2];
    demill_world *ref = steel_world(dim, 1, &mat);
    const double x[6] = {a0[0], a0[1], a0[2], b0[0], b0[1], b0[2]}, radii[2] = {r, r};
    DM_OK(ref, demill_particles_add(ref, mat, 2, x, radii, NULL, 0, ids));
    DM_OK(ref, demill_particle_set(ref, ids[0], DEMILL_PARTICLE_VELOCITY, va));
    DM_OK(ref, demill_particle_set(ref, ids[0], DEMILL_PARTICLE_ANGULAR_VELOCITY, spin));
    demill_world *w = steel_world(dim, 1, &mat);
    const double centre[3] = {0.3, -0.2, 0};
    DM_OK(w, demill_clump_template_add(w, mat, 1, centre, &r, &tmpl));
    DM_OK(w, demill_clump_add(w, tmpl, a0, NULL, &clump));
    DM_OK(w, demill_particles_add(w, mat, 1, b0, &r, NULL, 0, &b));
    DM_OK(w, demill_clump_set(w, clump, DEMILL_CLUMP_VELOCITY, va));
    DM_OK(w, demill_clump_set(w, clump, DEMILL_CLUMP_ANGULAR_VELOCITY, spin));
    size_t n;
    DM_OK(w, demill_clump_members(w, clump, &a, 1, &n));
    ck_assert_uint_eq(n, 1);
    double worst = 0.0;
    for (int k = 0; k < 300; k++) { /* 0.3 s */
        DM_OK(ref, demill_world_step(ref, 100));
        DM_OK(w, demill_world_step(w, 100));
        const int fields[3] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                               DEMILL_PARTICLE_ANGULAR_VELOCITY};
        const double scale[3] = {r, 1.0, 1.0 / r}; /* m, m/s, rad/s */
        for (int f = 0; f < 3; f++)
            for (int c = 0; c < 3; c++) {
                const double pa = dm_test_get(ref, ids[0], fields[f], c);
                const double qa = dm_test_get(w, a, fields[f], c);
                const double pb = dm_test_get(ref, ids[1], fields[f], c);
                const double qb = dm_test_get(w, b, fields[f], c);
                worst = fmax(worst, fmax(fabs(pa - qa), fabs(pb - qb)) / scale[f]);
            }
    }
    double xb[3];
    DM_OK(w, demill_particle_get(w, b, DEMILL_PARTICLE_POSITION, xb));
    ck_assert_msg(xb[0] - b0[0] > 0.01, "the ball was not hit"); /* it moves 44.5 mm */
    ck_assert_msg(worst <= 1e-10, "the clump is off the sphere by %g", worst);
    demill_world_destroy(ref);
    demill_world_destroy(w);
}
END_TEST

/* A world with gravity g tilted by theta from -y towards +x over a floor
 * y = 0 (an incline seen from its own frame), linear contacts with
 * restitution damping and the tangential spring of friction mu. */
static demill_world *incline(double theta, double mu, demill_id *mat)
{
    demill_world *w = NULL;
    DM_OK(w, demill_world_create(3, &w));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_X, 9.81 * sin(theta)));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -9.81 * cos(theta)));
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_DENSITY, 2500));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_STIFFNESS, 1e5));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_RESTITUTION, 0.2));
    DM_OK(w, demill_material_set(w, *mat, DEMILL_MATERIAL_FRICTION, mu));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    demill_id floor;
    DM_OK(w, demill_wall_add_plane(w, *mat, origin, up, &floor));
    return w;
}

START_TEST(dumbbell_on_incline)
{
    /* two overlapping spheres along the slope (x): the dumbbell cannot roll
     * down, only slide; theta 0.2 degrees either side of atan(mu) */
    const double r = 0.005, mu = 0.5, c[6] = {0, 0, 0, 1.5 * r, 0, 0}, radii[2] = {r, r};
    const double theta = atan(mu) + (_i ? 0.2 : -0.2) * M_PI / 180.0;
    demill_id mat, tmpl, clump;
    demill_world *w = incline(theta, mu, &mat);
    DM_OK(w, demill_clump_template_add(w, mat, 2, c, radii, &tmpl));
    const double at[3] = {0, r, 0}; /* the body axis along the line of centres: x */
    DM_OK(w, demill_clump_add(w, tmpl, at, NULL, &clump));
    double dt, wc, v1[3], v2[3], t1, t2;
    DM_OK(w, demill_world_suggest_time_step(w, 0.1, 0, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    DM_OK(w, demill_world_step(w, (uint64_t)(0.1 / dt))); /* settled on its two contacts */
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &wc));
    ck_assert_double_eq(wc, 2);
    DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_VELOCITY, v1));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t1));
    DM_OK(w, demill_world_step(w, (uint64_t)(0.3 / dt)));
    DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_VELOCITY, v2));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t2));
    const double a = (v2[0] - v1[0]) / (t2 - t1);
    const double want = 9.81 * (sin(theta) - mu * cos(theta));
    if (_i)
        DM_ASSERT_REL(a, want, 1e-6);
    else
        ck_assert_msg(fabs(v2[0]) < 1e-6, "below the threshold it slides at %g m/s", v2[0]);
    demill_world_destroy(w);
}
END_TEST

/* The unit quaternion of a rotation matrix R (row-major, det 1): Shepperd
 * (1978), "Quaternion from rotation matrix", J. Guidance and Control 1, 223. */
static void matrix_quat(const double R[9], double q[4])
{
    const double tr = R[0] + R[4] + R[8];
    if (tr > 0) {
        const double s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s;
        q[1] = (R[7] - R[5]) / s;
        q[2] = (R[2] - R[6]) / s;
        q[3] = (R[3] - R[1]) / s;
        return;
    }
    int i = R[0] > R[4] ? (R[0] > R[8] ? 0 : 2) : (R[4] > R[8] ? 1 : 2);
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double s = 2.0 * sqrt(1.0 + R[4 * i] - R[4 * j] - R[4 * k]);
    q[0] = (R[3 * k + j] - R[3 * j + k]) / s;
    q[1 + i] = 0.25 * s;
    q[1 + j] = (R[3 * j + i] + R[3 * i + j]) / s;
    q[1 + k] = (R[3 * k + i] + R[3 * i + k]) / s;
}

START_TEST(lands_flat)
{
    /* three equal spheres at the corners of an equilateral triangle in a
     * horizontal plane, dropped from 10 mm onto a floor */
    const double r = 0.005, s = 2.2 * r, h = s * sqrt(3.0) / 2.0;
    const double c[9] = {0, 0, 0, s, 0, 0, 0.5 * s, 0, h}, radii[3] = {r, r, r};
    demill_id mat, tmpl, clump, ids[3];
    demill_world *w = steel_world(3, 1, &mat);
    DM_OK(w, demill_clump_template_add(w, mat, 3, c, radii, &tmpl));
    /* the orientation that puts the spheres as given: R = Aᵀ, A's rows the
     * principal axes in the frame of c */
    double A[9], R[9], q0[4], at[3];
    DM_OK(w, demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_PRINCIPAL_AXES, A));
    DM_OK(w, demill_clump_template_get(w, tmpl, DEMILL_TEMPLATE_CENTRE, at));
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            R[3 * a + b] = A[3 * b + a];
    matrix_quat(R, q0);
    at[1] = r + 0.01;
    DM_OK(w, demill_clump_add(w, tmpl, at, q0, &clump));
    size_t n;
    DM_OK(w, demill_clump_members(w, clump, ids, 3, &n));
    for (int k = 0; k < 3; k++) /* placed as given */
        for (int a = 0; a < 3; a++)
            ck_assert_msg(fabs(dm_test_get(w, ids[k], DEMILL_PARTICLE_POSITION, a) -
                               (c[3 * k + a] + (a == 1 ? r + 0.01 : 0))) < 1e-15,
                          "member %d coordinate %d", k, a);
    DM_OK(w, demill_world_step(w, 30000)); /* 0.3 s: it falls, bounces and settles */
    double wc, q[4], v[3];
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &wc));
    DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_ORIENTATION, q));
    DM_OK(w, demill_clump_get(w, clump, DEMILL_CLUMP_VELOCITY, v));
    double turn = 0.0, spread = 0.0;
    for (int a = 0; a < 4; a++)
        turn = fmax(turn, fabs(q[a] - q0[a]));
    for (int k = 1; k < 3; k++)
        spread = fmax(spread, fabs(dm_test_get(w, ids[k], DEMILL_PARTICLE_POSITION, 1) -
                                   dm_test_get(w, ids[0], DEMILL_PARTICLE_POSITION, 1)));
    ck_assert_double_eq(wc, 3);
    ck_assert_msg(turn < 1e-12, "the orientation moved by %g", turn);
    for (int k = 0; k < 3; k++) { /* a member's body frame is its clump's */
        double qm[4];
        DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_ORIENTATION, qm));
        for (int a = 0; a < 4; a++)
            ck_assert_double_eq(qm[a], q[a]);
    }
    ck_assert_msg(spread < 1e-15, "the members' heights differ by %g m", spread);
    demill_world_destroy(w);
}
END_TEST

/* A drum 0.2 m across with 4 lifters at 75 % of critical speed, charged
 * with 32 (2D) or 60 (3D) dumbbells of two overlapping spheres and as many
 * free spheres, on a lattice about its centre, in random orientations,
 * thrown at up to 0.5 m/s; the time step 1/100 of a contact at 1 m/s. */
static demill_world *clump_drum(int dim)
{
    const int n = dim == 3 ? 60 : 32, row = dim == 3 ? 5 : 8;
    const double r = 0.004, c[6] = {-0.7 * r, 0, 0, 0.7 * r, 0, 0}, radii[2] = {r, 0.8 * r};
    demill_id mat, tmpl, drum, clump;
    demill_world *w = steel_world(dim, 0, &mat);
    DM_OK(w, demill_drum_create(w, mat, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.2));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.1));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 4));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, 0.01));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_WIDTH, 0.01));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    DM_OK(w, demill_clump_template_add(w, mat, 2, c, radii, &tmpl));
    srand(11);
    for (int k = 0; k < 2 * n; k++) {
        const int cell[3] = {k % row, k / row % row, dim == 3 ? k / (row * row) : 0};
        double x[3] = {0, 0, 0}, v[3] = {0, 0, 0}, om[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
        for (int a = 0; a < dim; a++) {
            x[a] = (cell[a] - 0.5 * (row - 1)) * 4.2 * r;
            v[a] = 0.5 * (2.0 * rand() / RAND_MAX - 1.0);
        }
        if (dim == 3) {
            for (int a = 0; a < 4; a++)
                q[a] = 2.0 * rand() / RAND_MAX - 1.0;
            om[0] = 20.0 * rand() / RAND_MAX - 10.0;
        } else {
            const double th = 2.0 * M_PI * rand() / RAND_MAX;
            q[0] = cos(0.5 * th);
            q[3] = sin(0.5 * th);
        }
        om[2] = 20.0 * rand() / RAND_MAX - 10.0;
        if (k % 2) {
            DM_OK(w, demill_particles_add(w, mat, 1, x, &r, v, 0, NULL));
            continue;
        }
        DM_OK(w, demill_clump_add(w, tmpl, x, q, &clump));
        DM_OK(w, demill_clump_set(w, clump, DEMILL_CLUMP_VELOCITY, v));
        DM_OK(w, demill_clump_set(w, clump, DEMILL_CLUMP_ANGULAR_VELOCITY, om));
    }
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 100, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    return w;
}

START_TEST(drum_energy_balance)
{
    /* the account of energy.c and dissipation.c */
    const int dim = _i ? 3 : 2;
    demill_world *w = clump_drum(dim);
    const double e0 = dm_test_energy(w, DEMILL_ENERGY_TOTAL);
    const double k0 = dm_test_energy(w, DEMILL_ENERGY_KINETIC_TRANSLATIONAL) +
                      dm_test_energy(w, DEMILL_ENERGY_KINETIC_ROTATIONAL);
    double worst = 0.0;
    for (int k = 0; k < 40; k++) {
        DM_OK(w, demill_world_step(w, 1000));
        worst = fmax(worst, fabs(dm_test_energy(w, DEMILL_ENERGY_TOTAL) - e0));
    }
    const double through = dm_test_energy(w, DEMILL_ENERGY_DISSIPATED) + k0 +
                           fabs(dm_test_energy(w, DEMILL_ENERGY_WALL_WORK));
    ck_assert_msg(dm_test_energy(w, DEMILL_ENERGY_WALL_WORK) > 0.1 * through,
                  "the drum did little work: %g J", dm_test_energy(w, DEMILL_ENERGY_WALL_WORK));
    ck_assert_msg(worst <= 1e-3 * through, "the balance strayed by %.3g of %.3g J",
                  worst / through, through);
    demill_world_destroy(w);
}
END_TEST

START_TEST(threads_change_nothing)
{
    /* the 3D drum of clumps on 1 and on 2 threads over 1,500 steps (past
     * the pool's first comparison, so that 2 threads run both ways): every
     * position and velocity bitwise the same */
    demill_world *w[2];
    double *state[2];
    size_t n[2];
    for (int k = 0; k < 2; k++) {
        w[k] = clump_drum(3);
        DM_OK(w[k], demill_world_set(w[k], DEMILL_WORLD_THREADS, k + 1));
        DM_OK(w[k], demill_world_step(w[k], 1500));
        state[k] = dm_test_state(w[k], &n[k]);
    }
    ck_assert_uint_eq(n[0], n[1]);
    ck_assert_uint_eq(n[0], 180);
    for (size_t i = 0; i < 6 * n[0]; i++)
        ck_assert_msg(memcmp(&state[0][i], &state[1][i], sizeof(double)) == 0,
                      "value %zu: %.17g on 1 thread, %.17g on 2", i, state[0][i], state[1][i]);
    for (int k = 0; k < 2; k++) {
        free(state[k]);
        demill_world_destroy(w[k]);
    }
}
END_TEST

/* Every clump's fields of worlds a and b, in slot order, bitwise equal. */
static void same_clumps(demill_world *a, demill_world *b, int way, void *ctx)
{
    (void)ctx;
    dm_test_check_same_clumps(a, b, way ? "snapshot" : "checkpoint");
}

START_TEST(snapshot_restores_clumps)
{
    /* the drum of clumps with a rod of 20 spheres added below the charge,
     * after 200 steps, a snapshot taken, 300 steps; the snapshot restored
     * into a new world of the other dimension, 300 steps: every position,
     * velocity and clump field bitwise the same. (The snapshot held the
     * first quarter of the templates' spheres only, 16 of the 22 here, so
     * that the restored rod read offsets and radii from beyond it.) */
    const int dim = _i ? 3 : 2;
    demill_world *w = clump_drum(dim), *v;
    demill_id mat, rod, clump;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, &mat, 1, NULL));
    double c[3 * 20] = {0}, r[20];
    for (int k = 0; k < 20; k++) {
        c[3 * k] = 0.003 * k;
        r[k] = 0.002;
    }
    DM_OK(w, demill_clump_template_add(w, mat, 20, c, r, &rod));
    const double at[3] = {0, -0.075, 0};
    DM_OK(w, demill_clump_add(w, rod, at, NULL, &clump));
    DM_OK(w, demill_world_step(w, 200));
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, 300));
    ck_assert_int_eq(demill_world_create(5 - dim, &v), DEMILL_OK);
    DM_OK(v, demill_snapshot_restore(v, snap));
    demill_snapshot_free(snap);
    DM_OK(v, demill_world_step(v, 300));
    size_t n[2];
    double *a = dm_test_state(w, &n[0]), *b = dm_test_state(v, &n[1]);
    ck_assert_uint_eq(n[0], n[1]);
    ck_assert_msg(!memcmp(a, b, 6 * n[0] * sizeof *a), "the restored run differs");
    same_clumps(w, v, 1, NULL);
    free(a);
    free(b);
    demill_world_destroy(v);
    demill_world_destroy(w);
}
END_TEST

START_TEST(checkpoint_continues_bitwise)
{
    /* the drum of clumps after 300 steps, saved to a checkpoint (format 7)
     * that loads into a world whose own checkpoint is the same bytes; the
     * checkpoint and a snapshot each loaded into a new world and stepped
     * 500 steps: every position, velocity and clump field bitwise the
     * unbroken run's */
    const int dim = _i ? 3 : 2;
    demill_world *w = clump_drum(dim);
    DM_OK(w, demill_world_step(w, 300));
    uint32_t format;
    demill_world *v = dm_test_reloaded(w, &format);
    ck_assert_uint_eq(format, 7);
    size_t na, nb;
    unsigned char *a = dm_test_save(w, &na), *b = dm_test_save(v, &nb);
    ck_assert_uint_eq(na, nb);
    ck_assert_msg(!memcmp(a, b, na), "the reloaded world saves other bytes");
    free(a);
    free(b);
    /* the drum's centre of mass weighs each member by its share of its
     * clump's mass, from its template's sum of r³ (r²), which a load derives
     * from the spheres: one step on, the same angle, bitwise */
    demill_id drum[2];
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, &drum[0], 1, NULL));
    DM_OK(v, demill_world_ids(v, DEMILL_KIND_DRUM, &drum[1], 1, NULL));
    DM_OK(w, demill_world_step(w, 1));
    DM_OK(v, demill_world_step(v, 1));
    double angle[2];
    DM_OK(w, demill_drum_get(w, drum[0], DEMILL_DRUM_COM_ANGLE, &angle[0]));
    DM_OK(v, demill_drum_get(v, drum[1], DEMILL_DRUM_COM_ANGLE, &angle[1]));
    ck_assert_msg(isfinite(angle[0]) && !memcmp(&angle[0], &angle[1], sizeof *angle),
                  "centre of mass at %.17g deg, reloaded %.17g deg", angle[0], angle[1]);
    demill_world_destroy(v);
    dm_test_copies_run_on(w, 500, same_clumps, NULL);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("clumps");
    TCase *tc = tcase_create("clumps");
    tcase_add_test(tc, tennis_racket_flips);
    tcase_add_loop_test(tc, one_sphere_clump_is_the_sphere, 0, 2);
    tcase_add_loop_test(tc, dumbbell_on_incline, 0, 2);
    tcase_add_test(tc, lands_flat);
    tcase_add_loop_test(tc, drum_energy_balance, 0, 2);
    tcase_add_test(tc, threads_change_nothing);
    tcase_add_loop_test(tc, snapshot_restores_clumps, 0, 2);
    tcase_add_loop_test(tc, checkpoint_continues_bitwise, 0, 2);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
