/* state.c: snapshots and checkpoints bring a world back exactly, and bad
 * checkpoints are refused without harm.
 *
 * Restart: a run of 2n steps and a run of n steps, a checkpoint, a load in a
 * new process (this program run again, on 2 threads where the library has
 * threads) and n more steps must end in bitwise the same state. "The same
 * state" is checked twice: the final checkpoints, which hold every field of
 * the state, are byte for byte equal, and so are the positions, velocities,
 * spins, forces and energy terms read through the API. The scenes exercise
 * every part of the state: a 3D mill with lifters turning up to speed over a
 * ramp, Hertz-Mindlin contacts with rolling friction, a collision spectrum
 * and particles removed (free handles); a 2D box of discs with a moving
 * piston wall, linear contacts, on each of the three integrators; finite
 * walls of every kind (a capped cylinder, an annulus, a rectangle, a cone)
 * in harmonic, rigid and belt motion, with balls thrown at each; the same
 * box as a body on a spring and a damper, driven, with a floor of fixed
 * discs (velocity Verlet); clumps of two templates among spheres in a box
 * (3D, velocity Verlet) and dumbbells of discs (2D, symplectic Euler), with
 * a clump removed and its slot taken again, and another removed; their
 * clumps' fields are compared too.
 *
 * Snapshots: restoring a snapshot and stepping repeats the first run
 * bitwise, in the same world and in another one (of the other dimension,
 * which the snapshot replaces), and ids from demill_world_ids() name the
 * restored objects.
 *
 * Refusal: every shorter prefix of a checkpoint, every single corrupted byte
 * (the checksum), a foreign file, a newer format version, another byte
 * order, trailing bytes and missing or unwritable files each give their
 * documented code with a message naming the problem, and leave the world
 * bitwise as it was. Byte flips behind a repaired checksum (which reach the
 * checks of sizes, indices and parameters) give DEMILL_OK or
 * DEMILL_ERR_FORMAT and never a crash; a world loaded from such a file
 * steps. Clump records the API would not make (a template that does not
 * exist, a quaternion not of norm 1 or not finite, a member that is no
 * particle, is another clump's or unlike its sphere, a template of no
 * spheres, a wrong count) are refused with a message naming them. (tests/fuzz/ runs the loader under libFuzzer for longer.)
 */
#define _POSIX_C_SOURCE 200809L /* getpid */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "crc32.h"
#include "testutil.h"

static const char *self; /* this program, run again as the new process */

/* ------------------------------------------------------------------------ */
/* Scenes                                                                     */

/* A 3D mill: 8 lifters of the balls' steel in a liner shell, 5 and 6 mm balls filled to 25 %, a few removed, a
 * spectrum recorded, turning up to 75 % of critical over a 0.05 s ramp. */
static demill_world *mill3d(int integrator)
{
    demill_world *w;
    demill_id balls, liner, drum;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    dm_test_mill_materials(w, &balls, &liner);
    const demill_id mats[2] = {balls, liner};
    for (int k = 0; k < 2; k++) {
        DM_OK(w, demill_pair_set(w, balls, mats[k], DEMILL_PAIR_ROLLING,
                                 DEMILL_ROLLING_CONSTANT_TORQUE));
        DM_OK(w, demill_pair_set(w, balls, mats[k], DEMILL_PAIR_ROLLING_FRICTION, 0.05));
    }
    DM_OK(w, demill_drum_create(w, liner, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.1));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.03));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 8));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_HEIGHT, 0.008));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_WIDTH, 0.008));
    DM_OK(w, demill_drum_set_material(w, drum, DEMILL_DRUM_PART_LIFTERS, balls));
    const double sizes[4] = {0.005, 0.5, 0.006, 0.5};
    demill_id ids[2000];
    size_t added;
    DM_OK(w, demill_drum_fill(w, drum, balls, DEMILL_SIZES_CLASSES, sizes, 4,
                              DEMILL_FILL_FRACTION, 0.25, 11, ids, 2000, &added));
    ck_assert_msg(added > 200, "only %zu balls", added);
    const demill_id gone[3] = {ids[3], ids[40], ids[41]};
    DM_OK(w, demill_particles_remove(w, 3, gone));
    const double edges[2] = {0.0055, 0.0058};
    DM_OK(w, demill_drum_spectrum_start(w, drum, 2, edges, 20, 1e-9, 1e-3));
    DM_OK(w, demill_drum_impacts_start(w, drum, balls, 0.012, 4, 30, 1e-6, 1e2));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_RAMP_TIME, 0.05));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    return w;
}

/* A 2D box of 3 mm discs (linear, restitution damping, Coulomb friction)
 * under gravity, pressed by a piston wall moving down at 0.2 m/s. */
static demill_world *box2d(int integrator)
{
    demill_world *w;
    demill_id m, wall;
    ck_assert_int_eq(demill_world_create(2, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR, integrator));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_DISC_THICKNESS, 0.01));
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_SPRING));
    const double walls[4][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {0.1, 0, -1, 0}, {0, 0.12, 0, -1}};
    for (int k = 0; k < 4; k++) {
        const double pt[3] = {walls[k][0], walls[k][1], 0}, n[3] = {walls[k][2], walls[k][3], 0};
        DM_OK(w, demill_wall_add_plane(w, m, pt, n, &wall));
    }
    const double v[3] = {0, -0.2, 0};
    DM_OK(w, demill_wall_set_motion(w, wall, v, NULL, NULL));
    enum { N = 120 };
    double x[3 * N] = {0}, r[N];
    for (int k = 0; k < N; k++) {
        x[3 * k] = 0.006 + 0.0085 * (k % 10) + 0.001 * (k / 10 % 2);
        x[3 * k + 1] = 0.005 + 0.0085 * (k / 10);
        r[k] = 0.003 + 0.0004 * (k % 3);
    }
    DM_OK(w, demill_particles_add(w, m, N, x, r, NULL, DEMILL_ADD_NO_OVERLAP, NULL));
    return w;
}

/* The 2D box of discs, its walls attached to a body on a spring and a
 * damper, driven at 20 Hz, its bottom row of discs fixed (a rough floor). */
static demill_world *box2d_body(void)
{
    demill_world *w = box2d(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_id walls[4], body;
    size_t n;
    const double centre[3] = {0.05, 0.06, 0}, force[3] = {0, 9.72, 0}, zero[3] = {0, 0, 0};
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, walls, 4, &n));
    DM_OK(w, demill_wall_set_motion(w, walls[3], zero, NULL, NULL));
    DM_OK(w, demill_body_add(w, 0.3, centre, DEMILL_BODY_AXIS_Y, 0, &body));
    DM_OK(w, demill_body_set_spring(w, body, DEMILL_BODY_AXIS_Y, 9720, 2.0, 0.06));
    DM_OK(w, demill_body_set_force(w, body, force, 20.0, 0.5));
    for (int k = 0; k < 4; k++)
        DM_OK(w, demill_body_attach_wall(w, body, walls[k]));
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_ID, NULL, 0, &n));
    demill_id *all = malloc(n * sizeof *all);
    ck_assert_ptr_nonnull(all);
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_ID, all, n, NULL));
    const double one = 1.0;
    for (int k = 0; k < 10; k++) /* the bottom row */
        DM_OK(w, demill_particle_set(w, all[k], DEMILL_PARTICLE_FIXED, &one));
    free(all);
    return w;
}

/* Finite walls in every motion: a can (a cylinder capped below) vibrating
 * up and down whose surface moves as a belt, an orifice plate (annulus)
 * rocking about its axis, a tilted rectangle rocking about its normal and
 * a hopper (cone) turning, with balls thrown at each. */
static demill_world *walls3d(void)
{
    demill_world *w;
    demill_id balls, liner, can, plate, shelf, hopper;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    dm_test_mill_materials(w, &balls, &liner);
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0}, belt[3] = {0.5, 0, 0.2};
    const double ring[3] = {0, 0.06, 0}, top[3] = {0, 0.07, 0}, mid[3] = {0.01, 0.03, 0};
    const double tilt[3] = {0.3, 1, 0}, spin[3] = {0, 20, 0};
    DM_OK(w, demill_wall_add_cylinder(w, liner, o, y, 0.05, 0.1, DEMILL_CAPS_START, &can));
    DM_OK(w, demill_wall_set_harmonic(w, can, DEMILL_HARMONIC_TRANSLATION, y, 5e-4, 30, 0.3));
    DM_OK(w, demill_wall_set_surface_velocity(w, can, belt));
    DM_OK(w, demill_wall_add_disc(w, liner, ring, y, 0.05, 0.02, &plate));
    DM_OK(w, demill_wall_set_harmonic(w, plate, DEMILL_HARMONIC_ROTATION, y, 0.2, 10, 0));
    DM_OK(w, demill_wall_add_rectangle(w, liner, mid, tilt, x, 0.02, 0.02, &shelf));
    DM_OK(w, demill_wall_set_harmonic(w, shelf, DEMILL_HARMONIC_ROTATION, tilt, 0.1, 15, 1));
    DM_OK(w, demill_wall_add_cone(w, liner, top, y, 0.02, 0.05, 0.03, DEMILL_CAPS_NONE,
                                  &hopper));
    DM_OK(w, demill_wall_set_motion(w, hopper, NULL, spin, NULL));
    enum { N = 22 };
    double p[3 * N], v[3 * N], r[N];
    for (int k = 0; k < N; k++) {
        const double a = 2 * 3.14159265358979 * k / 6;
        r[k] = 0.004;
        v[3 * k] = v[3 * k + 2] = 0;
        v[3 * k + 1] = -0.3;
        if (k < 9) { /* on the can's floor */
            p[3 * k] = 0.012 * (k % 3 - 1) - 0.015;
            p[3 * k + 1] = 0.0042;
            p[3 * k + 2] = 0.012 * (k / 3 - 1);
        } else if (k < 15) { /* above the plate */
            p[3 * k] = 0.035 * cos(a);
            p[3 * k + 1] = 0.0655;
            p[3 * k + 2] = 0.035 * sin(a);
        } else if (k < 21) { /* in the hopper, thrown outwards */
            p[3 * k] = 0.026 * cos(a);
            p[3 * k + 1] = 0.085;
            p[3 * k + 2] = 0.026 * sin(a);
            v[3 * k] = 0.5 * cos(a);
            v[3 * k + 2] = 0.5 * sin(a);
        } else { /* onto the shelf */
            p[3 * k] = 0.01;
            p[3 * k + 1] = 0.0375;
            p[3 * k + 2] = 0;
        }
    }
    DM_OK(w, demill_particles_add(w, balls, N, p, r, v, DEMILL_ADD_NO_OVERLAP, NULL));
    return w;
}

/* Clumps (3D): a box of five planes holding 12 clumps of two templates, a
 * dumbbell of two overlapping spheres and an L of three, in turned
 * orientations and thrown, and 6 free spheres, on Hertz-Mindlin contacts
 * with rolling friction; one clump removed and another added in its slot
 * (a handle of a later generation), then one more removed (a free slot);
 * and a clump of a template made from a mesh, with its fit. */
static demill_world *clumps3d(void)
{
    demill_world *w;
    demill_id m, wall, tmpl[2], clump[12];
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 2500));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    const double planes[5][6] = {{0, 0, 0, 0, 1, 0},      {-0.03, 0, 0, 1, 0, 0},
                                 {0.03, 0, 0, -1, 0, 0},  {0, 0, -0.03, 0, 0, 1},
                                 {0, 0, 0.03, 0, 0, -1}};
    for (int k = 0; k < 5; k++)
        DM_OK(w, demill_wall_add_plane(w, m, planes[k], planes[k] + 3, &wall));
    const double r = 0.004, dumbbell[6] = {-0.7 * r, 0, 0, 0.7 * r, 0, 0};
    const double ell[9] = {0, 0, 0, 1.2 * r, 0, 0, 0, 1.2 * r, 0};
    const double rd[2] = {r, 0.8 * r}, rl[3] = {r, r, 0.9 * r};
    DM_OK(w, demill_clump_template_add(w, m, 2, dumbbell, rd, &tmpl[0]));
    DM_OK(w, demill_clump_template_add(w, m, 3, ell, rl, &tmpl[1]));
    /* and one from a mesh, whose fit the checkpoint keeps: a regular
     * octahedron 8 mm across filled with 2 spheres */
    const double a = 0.004, v[18] = {a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a};
    const uint32_t tri[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                              2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    demill_id rock, stone;
    DM_OK(w, demill_clump_template_from_mesh(w, m, 6, v, 8, tri, 2, 32, &rock));
    for (int k = 0; k < 12; k++) {
        const double x[3] = {-0.015 + 0.015 * (k % 3), 0.01 + 0.015 * (k / 6),
                             -0.01 + 0.02 * (k / 3 % 2)};
        const double q[4] = {1.0, 0.3 * (k % 4), -0.2 * (k % 3), 0.1 * k};
        const double v[3] = {0.2 * (k % 3 - 1), -0.1, 0.05 * (k % 2)}, om[3] = {k, -3, 2};
        DM_OK(w, demill_clump_add(w, tmpl[k % 2], x, q, &clump[k]));
        DM_OK(w, demill_clump_set(w, clump[k], DEMILL_CLUMP_VELOCITY, v));
        DM_OK(w, demill_clump_set(w, clump[k], DEMILL_CLUMP_ANGULAR_VELOCITY, om));
    }
    double p[3 * 6], rr[6];
    for (int k = 0; k < 6; k++) {
        p[3 * k] = -0.02 + 0.008 * k;
        p[3 * k + 1] = 0.045;
        p[3 * k + 2] = 0.0;
        rr[k] = 0.003;
    }
    DM_OK(w, demill_particles_add(w, m, 6, p, rr, NULL, 0, NULL));
    const double at[3] = {0.02, 0.045, 0.02};
    DM_OK(w, demill_clump_add(w, rock, at, NULL, &stone));
    DM_OK(w, demill_clump_remove(w, clump[4]));
    const double again[3] = {0, 0.05, 0.015};
    DM_OK(w, demill_clump_add(w, tmpl[1], again, NULL, &clump[4]));
    DM_OK(w, demill_clump_remove(w, clump[7]));
    double dt;
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 50, &dt, NULL, NULL));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    return w;
}

/* Clumps (2D): the box of box2d() with its piston still, 40 discs and 12
 * dumbbells of discs, on symplectic Euler, one dumbbell removed. */
static demill_world *clumps2d(void)
{
    demill_world *w = box2d(DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    demill_id walls[4], mat, tmpl, clump[12];
    size_t n;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, walls, 4, &n));
    const double zero[3] = {0, 0, 0};
    DM_OK(w, demill_wall_set_motion(w, walls[3], zero, NULL, NULL));
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_MATERIAL, &mat, 1, &n));
    demill_id all[120];
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_PARTICLE, all, 120, &n));
    DM_OK(w, demill_particles_remove(w, 80, all + 40)); /* the upper rows */
    const double c[6] = {-0.002, 0, 0, 0.002, 0, 0}, radii[2] = {0.003, 0.0025};
    DM_OK(w, demill_clump_template_add(w, mat, 2, c, radii, &tmpl));
    for (int k = 0; k < 12; k++) {
        const double x[3] = {0.012 + 0.025 * (k % 4), 0.05 + 0.015 * (k / 4), 0};
        const double th = 0.5 * k, q[4] = {cos(0.5 * th), 0, 0, sin(0.5 * th)};
        const double v[3] = {0.1 * (k % 3 - 1), -0.2, 0}, om[3] = {0, 0, 5.0 - k};
        DM_OK(w, demill_clump_add(w, tmpl, x, q, &clump[k]));
        DM_OK(w, demill_clump_set(w, clump[k], DEMILL_CLUMP_VELOCITY, v));
        DM_OK(w, demill_clump_set(w, clump[k], DEMILL_CLUMP_ANGULAR_VELOCITY, om));
    }
    DM_OK(w, demill_clump_remove(w, clump[5]));
    return w;
}

static demill_world *scene(int which)
{
    static const int integrators[3] = {DEMILL_INTEGRATOR_VELOCITY_VERLET,
                                       DEMILL_INTEGRATOR_SYMPLECTIC_EULER,
                                       DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT};
    if (which == 4)
        return walls3d();
    if (which == 5)
        return box2d_body();
    if (which == 6)
        return clumps3d();
    if (which == 7)
        return clumps2d();
    return which == 0 ? mill3d(DEMILL_INTEGRATOR_VELOCITY_VERLET) : box2d(integrators[which - 1]);
}
#define SCENES 8
#define HALF 2500 /* n steps: 0.025 s, with many neighbour rebuilds and contacts */

/* ------------------------------------------------------------------------ */
/* Comparing states                                                           */

typedef struct bytes {
    unsigned char *b;
    size_t n;
} bytes;

static bytes checkpoint_of(demill_world *w)
{
    /* called in long loops: no passing assertion, which Check reports one by one */
    bytes c;
    if (demill_world_save_buffer(w, NULL, 0, &c.n) || !(c.b = malloc(c.n)) ||
        demill_world_save_buffer(w, c.b, c.n, &c.n))
        ck_abort_msg("saving to a buffer: %s", demill_world_last_error(w));
    return c;
}

static void same_bytes(bytes a, bytes b, const char *what)
{
    if (a.n != b.n)
        ck_abort_msg("%s: checkpoints of %zu and %zu bytes", what, a.n, b.n);
    if (memcmp(a.b, b.b, a.n)) {
        size_t k = 0;
        while (a.b[k] == b.b[k])
            k++;
        ck_abort_msg("%s: checkpoints differ from byte %zu of %zu", what, k, a.n);
    }
}

/* The state read through the API, compared bitwise. */
static void same_observed(demill_world *a, demill_world *b, const char *what)
{
    static const int32_t fields[5] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                                      DEMILL_PARTICLE_ANGULAR_VELOCITY, DEMILL_PARTICLE_FORCE,
                                      DEMILL_PARTICLE_TORQUE};
    size_t n, m;
    DM_OK(a, demill_particles_read(a, DEMILL_PARTICLE_POSITION, NULL, 0, &n));
    DM_OK(b, demill_particles_read(b, DEMILL_PARTICLE_POSITION, NULL, 0, &m));
    ck_assert_uint_eq(n, m);
    double *fa = malloc(3 * n * sizeof *fa), *fb = malloc(3 * n * sizeof *fb);
    ck_assert(fa && fb);
    for (int f = 0; f < 5; f++) {
        DM_OK(a, demill_particles_read(a, fields[f], fa, n, NULL));
        DM_OK(b, demill_particles_read(b, fields[f], fb, n, NULL));
        ck_assert_msg(!memcmp(fa, fb, 3 * n * sizeof *fa), "%s: particle field %d differs",
                      what, (int)fields[f]);
    }
    free(fa);
    free(fb);
    dm_test_check_same_clumps(a, b, what); /* the clumps, in slot order */
    for (int32_t e = DEMILL_ENERGY_KINETIC_TRANSLATIONAL; e <= DEMILL_ENERGY_ELASTIC_ROLLING;
         e++) {
        double ea, eb;
        DM_OK(a, demill_world_energy(a, e, &ea));
        DM_OK(b, demill_world_energy(b, e, &eb));
        ck_assert_msg(!memcmp(&ea, &eb, sizeof ea), "%s: energy %d: %.17g vs %.17g", what,
                      (int)e, ea, eb);
    }
}

/* ------------------------------------------------------------------------ */
/* Restart in a new process                                                   */

static char *temp_path(const char *name)
{
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char *p = malloc(strlen(dir) + strlen(name) + 32);
    ck_assert_ptr_nonnull(p);
    sprintf(p, "%s/demill-state-%ld-%s", dir, (long)getpid(), name);
    return p;
}

/* The second half, as a new process: load, step n on 2 threads, save. */
static int continue_run(const char *from, const char *to)
{
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK || demill_world_load(w, from) != DEMILL_OK)
        return fprintf(stderr, "load: %s\n", demill_world_last_error(w)), 1;
    demill_status st = demill_world_set(w, DEMILL_WORLD_THREADS, 2);
    if ((st != DEMILL_OK && st != DEMILL_ERR_UNSUPPORTED) ||
        demill_world_step(w, HALF) != DEMILL_OK || demill_world_save(w, to) != DEMILL_OK)
        return fprintf(stderr, "continue: %s\n", demill_world_last_error(w)), 1;
    demill_world_destroy(w);
    return 0;
}

START_TEST(restart_in_new_process_is_bitwise)
{
    demill_world *whole = scene(_i), *first = scene(_i), *loaded;
    DM_OK(whole, demill_world_step(whole, 2 * HALF));
    DM_OK(first, demill_world_step(first, HALF));
    char *mid = temp_path("mid.ckpt"), *end = temp_path("end.ckpt");
    DM_OK(first, demill_world_save(first, mid));
    char *cmd = malloc(strlen(self) + strlen(mid) + strlen(end) + 32);
    ck_assert_ptr_nonnull(cmd);
    sprintf(cmd, "'%s' continue '%s' '%s'", self, mid, end);
    ck_assert_msg(system(cmd) == 0, "the new process failed: %s", cmd);

    ck_assert_int_eq(demill_world_create(2, &loaded), DEMILL_OK);
    DM_OK(loaded, demill_world_load(loaded, end));
    bytes a = checkpoint_of(whole), b = checkpoint_of(loaded);
    same_bytes(a, b, "2n steps against n + save + load + n");
    same_observed(whole, loaded, "2n steps against n + save + load + n");
    /* and both go on alike */
    DM_OK(whole, demill_world_step(whole, 200));
    DM_OK(loaded, demill_world_step(loaded, 200));
    same_observed(whole, loaded, "200 steps more");
    double steps;
    DM_OK(loaded, demill_world_get(loaded, DEMILL_WORLD_STEP_COUNT, &steps));
    ck_assert(steps == 2 * HALF + 200);
    remove(mid);
    remove(end);
    free(a.b);
    free(b.b);
    free(cmd);
    free(mid);
    free(end);
    demill_world_destroy(whole);
    demill_world_destroy(first);
    demill_world_destroy(loaded);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Snapshots                                                                  */

START_TEST(snapshot_restores_bitwise)
{
    demill_world *w = scene(_i), *other;
    DM_OK(w, demill_world_step(w, 500));
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    bytes at_snap = checkpoint_of(w);
    DM_OK(w, demill_world_step(w, HALF));
    bytes first = checkpoint_of(w);

    DM_OK(w, demill_snapshot_restore(w, snap));
    bytes restored = checkpoint_of(w);
    same_bytes(at_snap, restored, "restored against taken");
    DM_OK(w, demill_world_step(w, HALF));
    bytes again = checkpoint_of(w);
    same_bytes(first, again, "the run repeated from the snapshot");

    /* into another world, of the other dimension, whose ids then name it */
    const int steel = _i == 0 || _i == 4; /* the 3D scenes of the mill's materials */
    const int dim = steel || _i == 6 ? 3 : 2;
    ck_assert_int_eq(demill_world_create(5 - dim, &other), DEMILL_OK);
    DM_OK(other, demill_snapshot_restore(other, snap));
    double d;
    DM_OK(other, demill_world_get(other, DEMILL_WORLD_DIMENSION, &d));
    ck_assert(d == dim);
    DM_OK(other, demill_world_step(other, HALF));
    same_observed(w, other, "the run repeated in another world");
    size_t nm, nd, nw, np;
    demill_id ids[8];
    DM_OK(other, demill_world_ids(other, DEMILL_KIND_MATERIAL, ids, 8, &nm));
    DM_OK(other, demill_world_ids(other, DEMILL_KIND_DRUM, NULL, 0, &nd));
    DM_OK(other, demill_world_ids(other, DEMILL_KIND_WALL, NULL, 0, &nw));
    DM_OK(other, demill_world_ids(other, DEMILL_KIND_PARTICLE, NULL, 0, &np));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &d));
    ck_assert_uint_eq(np, (size_t)d);
    ck_assert_uint_eq(nm, steel ? 2 : 1);
    ck_assert_uint_eq(nd, _i == 0 ? 1 : 0);
    ck_assert_uint_eq(nw, _i == 0 ? 0 : _i == 6 ? 5 : 4); /* a capped wall is one wall */
    double density;
    DM_OK(other, demill_material_get(other, ids[0], DEMILL_MATERIAL_DENSITY, &density));
    ck_assert(density == (steel ? 7800 : 2500));
    if (_i == 0) {
        demill_id drum, mine;
        DM_OK(other, demill_world_ids(other, DEMILL_KIND_DRUM, &drum, 1, NULL));
        DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, &mine, 1, NULL));
        double ta, tb;
        DM_OK(other, demill_drum_get(other, drum, DEMILL_DRUM_TORQUE, &tb));
        DM_OK(w, demill_drum_get(w, mine, DEMILL_DRUM_TORQUE, &ta));
        ck_assert(!memcmp(&ta, &tb, sizeof ta));
        /* each world's ids are its own */
        ck_assert_int_eq(demill_drum_get(other, mine, DEMILL_DRUM_TORQUE, &tb),
                         DEMILL_ERR_INVALID_HANDLE);
    }
    demill_snapshot_free(snap);
    free(at_snap.b);
    free(first.b);
    free(restored.b);
    free(again.b);
    demill_world_destroy(w);
    demill_world_destroy(other);
}
END_TEST

START_TEST(listing_ids)
{
    demill_world *w = box2d(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_id walls[4], one;
    size_t n;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, walls, 4, &n));
    ck_assert_uint_eq(n, 4);
    for (int k = 0; k < 4; k++)
        ck_assert_int_eq(demill_id_kind(walls[k]), DEMILL_KIND_WALL);
    DM_OK(w, demill_wall_remove(w, walls[1]));
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, NULL, 0, &n));
    ck_assert_uint_eq(n, 3);
    ck_assert_int_eq(demill_world_ids(w, DEMILL_KIND_WALL, walls, 2, &n),
                     DEMILL_ERR_BUFFER_TOO_SMALL);
    ck_assert_uint_eq(n, 3);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "capacity"));
    ck_assert_int_eq(demill_world_ids(w, 10, &one, 1, &n), DEMILL_ERR_UNKNOWN_KEY);
    for (int32_t kind = DEMILL_KIND_TEMPLATE; kind <= DEMILL_KIND_CLUMP; kind++) {
        DM_OK(w, demill_world_ids(w, kind, NULL, 0, &n));
        ck_assert_uint_eq(n, 0);
    }
    ck_assert_int_eq(demill_world_ids(w, DEMILL_KIND_NONE, &one, 1, &n), DEMILL_ERR_UNKNOWN_KEY);
    ck_assert_int_eq(demill_world_ids(w, DEMILL_KIND_DRUM, NULL, 0, NULL), DEMILL_ERR_NULL_POINTER);
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_DRUM, NULL, 0, &n));
    ck_assert_uint_eq(n, 0);
    demill_world_destroy(w);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Refusing bad checkpoints                                                   */

/* Loading `bad` fails with `code` and a message containing `word`, and the
 * world stays bitwise what `before` holds. */
static void refused(demill_world *w, bytes before, const unsigned char *bad, size_t n,
                    demill_status code, const char *word, const char *what)
{
    demill_status st = demill_world_load_buffer(w, bad, n);
    if (st != code)
        ck_abort_msg("%s: load gave %d (%s), expected %d", what, (int)st,
                     demill_world_last_error(w), (int)code);
    if (!strstr(demill_world_last_error(w), word))
        ck_abort_msg("%s: message \"%s\" lacks \"%s\"", what, demill_world_last_error(w), word);
    bytes now = checkpoint_of(w);
    same_bytes(before, now, what);
    free(now.b);
}

/* Writes `len` bytes of `patch` at offset `at` of a copy of the good
 * checkpoint (into scratch, good.n bytes), repairs its checksum, and checks
 * that loading it into w is refused with DEMILL_ERR_FORMAT and `word`,
 * leaving w's bytes as `before`. */
static void refused_patched(demill_world *w, bytes before, bytes good, unsigned char *scratch,
                            size_t at, const void *patch, size_t len, const char *word,
                            const char *what)
{
    memcpy(scratch, good.b, good.n);
    memcpy(scratch + at, patch, len);
    dm_test_ckpt_repair(scratch, good.n);
    refused(w, before, scratch, good.n, DEMILL_ERR_FORMAT, word, what);
}

/* Frees what a refusal test made: its two worlds, the good checkpoint, the
 * target's before loading, and the corrupted copy. */
static void release(demill_world *w, demill_world *target, bytes good, bytes before, void *bad)
{
    free(bad);
    free(good.b);
    free(before.b);
    demill_world_destroy(w);
    demill_world_destroy(target);
}

/* A small scene: a few particles touching a wall and each other. */
static demill_world *small(void)
{
    demill_world *w = box2d(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    demill_id ids[120];
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_PARTICLE, ids, 120, NULL));
    DM_OK(w, demill_particles_remove(w, 100, ids + 10));
    DM_OK(w, demill_world_step(w, 300));
    return w;
}

START_TEST(truncated_and_corrupt_checkpoints_are_refused)
{
    demill_world *w = small(), *target = box2d(DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    DM_OK(target, demill_world_step(target, 10));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    unsigned char *bad = malloc(good.n + 8);
    ck_assert_ptr_nonnull(bad);

    for (size_t n = 0; n < good.n; n++)
        refused(target, before, good.b, n, DEMILL_ERR_FORMAT,
                n < 32 ? "not a libdemill checkpoint" : "truncated", "a prefix");
    for (size_t k = 0; k < good.n; k++) {
        if (k >= 28 && k < 32)
            continue; /* the writer's version, for messages only */
        memcpy(bad, good.b, good.n);
        bad[k] ^= 0x5a;
        const char *word = k < 8 ? "not a libdemill" : k < 12 ? "format version" : k < 16 ? "byte order"
                         : k < 24 ? "bytes of data" : "checksum";
        refused(target, before, bad, good.n, DEMILL_ERR_FORMAT, k >= 32 ? "corrupt" : word,
                "a corrupted byte");
    }
    memcpy(bad, good.b, good.n);
    uint32_t newer; /* the format after the one this library writes */
    memcpy(&newer, good.b + 8, 4);
    newer++;
    memcpy(bad + 8, &newer, 4);
    char word[32];
    snprintf(word, sizeof word, "format version %u", (unsigned)newer);
    refused(target, before, bad, good.n, DEMILL_ERR_FORMAT, word, "a newer format");
    memcpy(bad, good.b, good.n);
    memcpy(bad + good.n, "trailing", 8);
    refused(target, before, bad, good.n + 8, DEMILL_ERR_FORMAT, "trailing", "trailing bytes");
    const char *xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">";
    refused(target, before, (const unsigned char *)xml, strlen(xml), DEMILL_ERR_FORMAT,
            "starting \"<?xml ve\"", "a VTK file");

    /* the good one still loads, and then equals its source */
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    same_observed(w, target, "loaded");
    release(w, target, good, before, bad);
}
END_TEST

/* Where the len bytes at v stand in a checkpoint's payload, which holds
 * them exactly once. */
static size_t unique_offset(bytes b, const void *v, size_t len)
{
    size_t at = 0, found = 0;
    for (size_t k = DM_TEST_CKPT_HEADER; k + len <= b.n; k++)
        if (!memcmp(b.b + k, v, len)) {
            at = k;
            found++;
        }
    ck_assert_uint_eq(found, 1);
    return at;
}

/* Byte flips of w's checkpoint from byte `from` on (1, 7 and 8 bits),
 * behind a repaired checksum, loaded into a new world: DEMILL_OK or
 * DEMILL_ERR_FORMAT, the world unchanged by a refusal and able to step
 * after a load; at least `most` of each. */
static void flips_never_crash(demill_world *w, size_t from, size_t most)
{
    demill_world *target;
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    bytes bad = {malloc(good.n), good.n};
    ck_assert_ptr_nonnull(bad.b);
    size_t loaded = 0, refused_count = 0;
    static const unsigned char flips[3] = {0x01, 0x80, 0xff};
    for (size_t k = from; k < good.n; k++)
        for (int f = 0; f < 3; f++) {
            memcpy(bad.b, good.b, good.n);
            bad.b[k] ^= flips[f];
            dm_test_ckpt_repair(bad.b, bad.n);
            const demill_status st = demill_world_load_buffer(target, bad.b, bad.n);
            if (st != DEMILL_OK && st != DEMILL_ERR_FORMAT)
                ck_abort_msg("byte %zu ^ 0x%02x: load gave %d: %s", k, flips[f], (int)st,
                             demill_world_last_error(target));
            if (st == DEMILL_OK) {
                loaded++;
                /* what was accepted is a world that can run (the watchdog may
                 * object to what a flipped bit made of a position or a time
                 * step, but nothing may crash) */
                const demill_status s2 = demill_world_step(target, 20);
                if (s2 < DEMILL_OK || s2 > DEMILL_ERR_INTERRUPTED)
                    ck_abort_msg("byte %zu: stepping gave %d", k, (int)s2);
                if (demill_world_load_buffer(target, before.b, before.n))
                    ck_abort_msg("reloading: %s", demill_world_last_error(target));
            } else {
                refused_count++;
                bytes now = checkpoint_of(target);
                same_bytes(before, now, "after a refused load");
                free(now.b);
            }
        }
    ck_assert_msg(refused_count > most && loaded > most, "%zu refused, %zu loaded",
                  refused_count, loaded);
    free(bad.b);
    free(good.b);
    free(before.b);
    demill_world_destroy(target);
}

START_TEST(corruption_behind_a_repaired_checksum_never_crashes)
{
    demill_world *w = small();
    flips_never_crash(w, DM_TEST_CKPT_HEADER, 100);
    demill_world_destroy(w);
}
END_TEST

/* The same for the section of a world's clumps (after 100 steps of
 * clumps3d()), byte by byte. */
START_TEST(clump_bytes_flipped_never_crash)
{
    demill_world *w = clumps3d();
    DM_OK(w, demill_world_step(w, 100));
    bytes b = checkpoint_of(w);
    const size_t at = unique_offset(b, "CLMP", 4);
    free(b.b);
    flips_never_crash(w, at, 100);
    demill_world_destroy(w);
}
END_TEST

/* A checkpoint is held to the bounds the API holds a drum to: a drum value
 * or a lifter that demill_drum_set() or demill_drum_add_lifter() would
 * refuse, written into a checkpoint behind a repaired checksum, is refused
 * on load (before, the charge-shape measurement read such a lifter as
 * spanning more than the whole circle, out of its bins). */
START_TEST(drum_values_the_api_refuses_are_refused)
{
    demill_world *w, *target;
    demill_id liner, drum;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &liner));
    DM_OK(w, demill_drum_create(w, liner, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.1));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_FILL_POROSITY, 0.377));
    const double width = 0.0123;
    DM_OK(w, demill_drum_add_lifter(w, drum, 0.3, 0.0071, width, 0.0));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    /* each value is in the payload once; put there what the API refuses */
    const struct {
        double value, bad;
        const char *word;
    } cases[] = {
        {width, 0.2, "lifter width 0.2 m exceeds the diameter"},
        {width, -1.0, "drum.lifter_width"},
        {width, NAN, "not finite"},
        {0.0071, 0.06, "reaches the axis"},
        {0.377, 1.5, "drum.fill_porosity"},
    };
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const size_t at = unique_offset(good, &cases[c].value, 8);
        refused_patched(target, before, good, bad, at, &cases[c].bad, 8, cases[c].word,
                        cases[c].word);
    }
    /* unchanged, it loads */
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    release(w, target, good, before, bad);
}
END_TEST

/* A checkpoint's clumps are held to what the API makes of them: a clump of
 * a template that does not exist, of an orientation that is not a unit
 * quaternion or not finite, a member that is no particle, a member of two
 * clumps, a member unlike its template's sphere, a template of no spheres,
 * a count of live clumps that is not the clumps', each written into the
 * checkpoint of clumps3d() behind a repaired checksum, is refused on load
 * with a message that names it. */
START_TEST(clump_records_the_api_would_not_make_are_refused)
{
    demill_world *w = clumps3d(), *target;
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    /* the layout of section CLMP (lib/world/checkpoint.c, transfer_clumps()):
     * its name, the counts of templates (3) and of their spheres (7); each
     * template's 3 32-bit fields (the second its number of spheres) and 22
     * doubles; 4 doubles per sphere; the counts of clump slots (13), live
     * clumps (12) and members; each slot's handle, and for a live clump its
     * template and first member (32 bits each) and 23 doubles, the fourth
     * to seventh its orientation; then the members' particle handles */
    const size_t clmp = unique_offset(good, "CLMP", 4), tmpl0 = clmp + 12;
    const size_t counts = tmpl0 + 3 * (12 + 22 * 8) + 7 * 32, slot0 = counts + 12;
    const size_t q0 = slot0 + 12 + 6 * 8, cmem = slot0 + 12 * (12 + 23 * 8) + 4;
    uint32_t member[2];
    memcpy(member, good.b + cmem, sizeof member); /* clump 0's two */
    /* a free sphere's handle: the index bits of its id */
    demill_id ids[64], owner[64];
    size_t n;
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_ID, ids, 64, &n));
    DM_OK(w, demill_particles_read_ids(w, DEMILL_PARTICLE_CLUMP, owner, 64, &n));
    uint32_t sphere = 0;
    while (owner[sphere] != DEMILL_ID_NONE)
        sphere++;
    sphere = (uint32_t)(ids[sphere] & 0xFFFFFFFFu);
    const uint32_t seven = 7, none = 1000, zero = 0, thirteen = 13;
    const double off = 0.9, nan = NAN;
    const struct {
        size_t at;
        const void *patch;
        size_t len;
        const char *word;
    } cases[] = {
        {slot0 + 4, &seven, 4, "template 7 of 3"},
        {q0, &off, 8, "orientation of norm"},
        {q0 + 8, &nan, 8, "not finite"},
        {cmem, &none, 4, "member 0 is not a particle"},
        {cmem + 4, &member[0], 4, "member 1 is a member of clump 0 too"},
        {cmem, &sphere, 4, "another material, radius or mass"},
        {tmpl0 + 4, &zero, 4, "clump template 0 has no spheres"},
        {counts + 4, &thirteen, 4, "12 clumps"},
    };
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        refused_patched(target, before, good, bad, cases[c].at, cases[c].patch, cases[c].len,
                        cases[c].word, cases[c].word);
    /* unchanged, it loads */
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    release(w, target, good, before, bad);
}
END_TEST

/* A checkpoint is held to the bounds the API holds a finite wall and its
 * motion to: a cone's radius below 0, a rectangle's half-width that is not
 * finite, a harmonic frequency below 0 or not finite, written behind a
 * repaired checksum, are refused on load. */
START_TEST(finite_wall_values_the_api_refuses_are_refused)
{
    demill_world *w, *target;
    demill_id m, cone, rect;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0};
    const double radius = 0.0789, half = 0.0321, freq = 13.7;
    DM_OK(w, demill_wall_add_cone(w, m, o, y, 0.0456, radius, 0.1, DEMILL_CAPS_START, &cone));
    DM_OK(w, demill_wall_add_rectangle(w, m, o, y, x, half, 0.0123, &rect));
    DM_OK(w, demill_wall_set_harmonic(w, rect, DEMILL_HARMONIC_ROTATION, x, 0.1, freq, 0));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    const struct {
        double value, bad;
        const char *word;
    } cases[] = {{radius, -0.01, "inconsistent"},
                 {half, NAN, "not finite"},
                 {freq, -2.0, "inconsistent"},
                 {freq, INFINITY, "not finite"}};
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const size_t at = unique_offset(good, &cases[c].value, 8);
        refused_patched(target, before, good, bad, at, &cases[c].bad, 8, cases[c].word,
                        "a finite wall");
    }
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    release(w, target, good, before, bad);
}
END_TEST

/* The loads a wall records (section LOAD: per wall slot its element count,
 * then the time and the steps recorded and 4 values per element) are held
 * to what demill_wall_loads_start() makes: a count that is not the wall's
 * number of elements, a negative or NaN time, written behind a repaired
 * checksum, are refused. */
START_TEST(wall_loads_the_api_would_not_make_are_refused)
{
    demill_world *w, *target;
    demill_id m, rect;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0};
    DM_OK(w, demill_wall_add_rectangle(w, m, o, y, x, 0.1, 0.1, &rect)); /* wall slot 0 */
    DM_OK(w, demill_wall_loads_start(w, rect));
    DM_OK(w, demill_world_step(w, 10));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    const size_t at = unique_offset(good, "LOAD", 4);
    const uint32_t two = 2, many = 0x7fffffffu;
    const double negative = -1.0, nan = NAN;
    const struct {
        size_t offset;
        const void *bad;
        size_t len;
        const char *word;
    } cases[] = {{4, &two, 4, "another size"},
                 {4, &many, 4, "another size"},
                 {8, &negative, 8, "recorded over -1 s"},
                 {8, &nan, 8, "not finite"}};
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        refused_patched(target, before, good, bad, at + cases[c].offset, cases[c].bad,
                        cases[c].len, cases[c].word, "wall loads");
    }
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    release(w, target, good, before, bad);
}
END_TEST

/* The drum's recording of impacts on an ore (checkpoint format 2) is held
 * to finite values as demill_drum_impacts_start() is: a top size, energy
 * span or start time that is not finite, written behind a repaired checksum,
 * is refused, so that the recorded time and the rates from the drum cannot
 * load as NaN. The four values follow each other in the payload: top size,
 * log10 of the lowest energy, the span of the logarithms, the start time. */
START_TEST(impact_recordings_not_finite_are_refused)
{
    demill_world *w, *target;
    demill_id ore, drum;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &ore));
    DM_OK(w, demill_drum_create(w, ore, &drum));
    DM_OK(w, demill_drum_spectrum_start(w, drum, 0, NULL, 4, 1e-6, 1e-2));
    const double top = 0.0123, log_min = log10(1e-3), log_span = log10(10.0) - log_min;
    DM_OK(w, demill_drum_impacts_start(w, drum, ore, top, 5, 8, 1e-3, 10.0));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    const double run[3] = {top, log_min, log_span};
    const size_t at = unique_offset(good, run, sizeof run);
    ck_assert_uint_le(at + 32, good.n);
    const struct {
        size_t offset;
        double bad;
    } cases[] = {{0, INFINITY}, {16, INFINITY}, {24, NAN}, {24, -INFINITY}};
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        refused_patched(target, before, good, bad, at + cases[c].offset, &cases[c].bad, 8,
                        "not finite", "impacts");
    }
    /* unchanged, it loads */
    DM_OK(target, demill_world_load_buffer(target, good.b, good.n));
    release(w, target, good, before, bad);
}
END_TEST

/* The state of an empty world (no particle room at all) restored into a
 * world whose refinement integrator has room for particles: the room shrinks
 * to none (before, shrinking it to 0 bytes freed it and reported running out
 * of memory, and the next step with particles used what was freed), and the
 * world then steps, empty and with particles again: a ball falls freely,
 * y = y0 - g t^2 / 2 (the refinement is exact for constant forces). */
START_TEST(empty_state_into_a_refining_world)
{
    demill_world *w, *empty;
    demill_id steel, ball;
    for (int kind = 0; kind < 2; kind++) { /* 0: snapshot, 1: checkpoint */
        ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
        ck_assert_int_eq(demill_world_create(3, &empty), DEMILL_OK);
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_INTEGRATOR,
                                  DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT));
        DM_OK(empty, demill_world_set(empty, DEMILL_WORLD_INTEGRATOR,
                                      DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT));
        DM_OK(w, demill_material_create(w, &steel));
        DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        const double x[3] = {0, 1, 0}, r = 0.01;
        DM_OK(w, demill_particles_add(w, steel, 1, x, &r, NULL, 0, &ball));
        DM_OK(w, demill_world_step(w, 10));
        if (kind == 0) {
            demill_snapshot *snap;
            DM_OK(empty, demill_snapshot_take(empty, &snap));
            DM_OK(w, demill_snapshot_restore(w, snap));
            demill_snapshot_free(snap);
        } else {
            bytes b = checkpoint_of(empty);
            DM_OK(w, demill_world_load_buffer(w, b.b, b.n));
            free(b.b);
        }
        DM_OK(w, demill_world_step(w, 10));
        DM_OK(w, demill_material_create(w, &steel));
        DM_OK(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
        DM_OK(w, demill_particles_add(w, steel, 1, x, &r, NULL, 0, &ball));
        double dt, t0, t1, y[3], gy;
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t0));
        DM_OK(w, demill_world_step(w, 1000));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t1));
        DM_OK(w, demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, y));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Y, &gy));
        const double t = t1 - t0, expect = 1.0 + 0.5 * gy * t * t;
        ck_assert_double_eq_tol(t, 1000 * dt, 1e-12);
        ck_assert_double_eq_tol(y[1], expect, 1e-12);
        demill_world_destroy(w);
        demill_world_destroy(empty);
    }
}
END_TEST

START_TEST(file_errors)
{
    demill_world *w = small();
    bytes before = checkpoint_of(w);
    ck_assert_int_eq(demill_world_load(w, "/nonexistent/demill.ckpt"), DEMILL_ERR_IO);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "/nonexistent/demill.ckpt"));
    ck_assert_int_eq(demill_world_save(w, "/nonexistent/demill.ckpt"), DEMILL_ERR_IO);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "/nonexistent/demill.ckpt"));
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "No such file"));
    ck_assert_int_eq(demill_world_load(w, "/"), DEMILL_ERR_IO); /* a directory */

    char *path = temp_path("text");
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs("x y z\n1 2 3\n", f);
    fclose(f);
    ck_assert_int_eq(demill_world_load(w, path), DEMILL_ERR_FORMAT);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), path));
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "not a libdemill checkpoint"));
    /* saving over it replaces it whole */
    DM_OK(w, demill_world_save(w, path));
    DM_OK(w, demill_world_load(w, path));
    bytes after = checkpoint_of(w);
    same_bytes(before, after, "saved and loaded");
    remove(path);

    ck_assert_int_eq(demill_world_save(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_world_load(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_world_load_buffer(w, NULL, 10), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_world_save_buffer(w, NULL, 0, NULL), DEMILL_ERR_NULL_POINTER);
    size_t n = 0;
    unsigned char tiny[16];
    ck_assert_int_eq(demill_world_save_buffer(w, tiny, sizeof tiny, &n),
                     DEMILL_ERR_BUFFER_TOO_SMALL);
    ck_assert_uint_eq(n, before.n);
    ck_assert_int_eq(demill_snapshot_take(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_snapshot_restore(w, NULL), DEMILL_ERR_NULL_POINTER);
    uint64_t fake[64] = {0};
    ck_assert_int_eq(demill_snapshot_restore(w, (const demill_snapshot *)fake),
                     DEMILL_ERR_INVALID_HANDLE);
    bytes end = checkpoint_of(w);
    same_bytes(before, end, "after the failed calls");
    free(before.b);
    free(after.b);
    free(end.b);
    free(path);
    demill_world_destroy(w);
}
END_TEST

/* ------------------------------------------------------------------------ */
/* Whatever the API accepts, a checkpoint brings back                          */

/* Saves w, loads that into a new world and saves again: the load succeeds
 * and the two checkpoints are the same bytes. */
static void round_trip(demill_world *w, const char *what)
{
    demill_world *copy;
    ck_assert_int_eq(demill_world_create(3, &copy), DEMILL_OK);
    bytes a = checkpoint_of(w);
    if (demill_world_load_buffer(copy, a.b, a.n))
        ck_abort_msg("%s: the checkpoint does not load: %s", what, demill_world_last_error(copy));
    bytes b = checkpoint_of(copy);
    same_bytes(a, b, what);
    free(a.b);
    free(b.b);
    demill_world_destroy(copy);
}

/* A 3D world with gravity g (along -y), a material with a Hertz model and a
 * drum of diameter `diameter` turning at `speed` rad/s. */
static demill_world *drum_world(double g, double diameter, double speed, demill_id *mat,
                                demill_id *drum)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, -g));
    DM_OK(w, demill_material_create(w, mat));
    DM_OK(w, demill_pair_set(w, *mat, *mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_drum_create(w, *mat, drum));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, diameter));
    DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_SPEED, speed));
    return w;
}

/* States that calls accepted and the loader refused: a body in a world
 * without walls; contacts formed and then their pair's law changed; a
 * spectrum started
 * but not yet stepped (its contact lists still without the spectrum's
 * slot); a drum whose critical speed is undefined (no gravity, or a
 * particle as wide as the drum), so that its speed as a fraction of
 * critical reads NaN; a drum turning far above its critical speed (a
 * fraction beyond that key's bounds); a particle handle used so often that
 * it was retired. And the spectrum range of one ulp that the library took
 * and later could not read is now refused when given. */
START_TEST(accepted_states_reload)
{
    demill_world *w = mill3d(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    round_trip(w, "a spectrum started, no step since");
    DM_OK(w, demill_world_step(w, 10));
    round_trip(w, "a spectrum started, stepped");
    demill_world_destroy(w);

    demill_id m, drum, p;
    w = drum_world(0.0, 0.3, 5.0, &m, &drum);
    round_trip(w, "a drum without gravity");
    demill_world_destroy(w);
    w = drum_world(9.81, 0.1, 3.0, &m, &drum);
    const double centre[3] = {0, 0, 0}, r = 0.05;
    DM_OK(w, demill_particles_add(w, m, 1, centre, &r, NULL, 0, &p));
    round_trip(w, "a particle as wide as the drum");
    demill_world_destroy(w);
    w = drum_world(9.81, 0.3, 1000.0, &m, &drum);
    round_trip(w, "a drum at 122 times its critical speed");

    bytes before = checkpoint_of(w);
    const double e_min = 1e-6, e_max = nextafter(e_min, 1.0);
    ck_assert_int_eq(demill_drum_spectrum_start(w, drum, 0, NULL, 10, e_min, e_max),
                     DEMILL_ERR_INVALID_VALUE);
    bytes after = checkpoint_of(w);
    same_bytes(before, after, "a refused spectrum range");
    free(before.b);
    free(after.b);

    const double x[3] = {0, -0.1, 0}, rs = 0.002;
    for (int k = 0; k < 65537; k++) {
        DM_OK(w, demill_particles_add(w, m, 1, x, &rs, NULL, 0, &p));
        DM_OK(w, demill_particles_remove(w, 1, &p));
    }
    round_trip(w, "a retired particle handle");
    demill_world_destroy(w);

    /* two balls pressed together, then their damping law changed
     * (restitution to none): their contact was left in the list of the old
     * law until the next step, which the loader refused */
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    const double pressed[6] = {0, 0, 0, 0.019, 0, 0}, radii[2] = {0.01, 0.01};
    demill_id balls[2];
    DM_OK(w, demill_particles_add(w, m, 2, pressed, radii, NULL, 0, balls));
    DM_OK(w, demill_world_step(w, 1));
    size_t ncontacts;
    DM_OK(w, demill_contacts_read(w, DEMILL_CONTACT_OVERLAP, NULL, 0, &ncontacts));
    ck_assert_uint_eq(ncontacts, 1);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_NONE));
    round_trip(w, "a pair's damping law changed, no step since");
    demill_world_destroy(w);

    /* a body is 292 bytes of checkpoint (3 32-bit fields and 35 doubles);
     * the loader wanted 400 bytes left per body, which a world with few
     * walls after its bodies does not have */
    const double origin[3] = {0, 0, 0};
    demill_id body;
    for (int dim = 2; dim <= 3; dim++) {
        ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
        DM_OK(w, demill_body_add(w, 1.0, origin, DEMILL_BODY_AXIS_Y, 0, &body));
        round_trip(w, dim == 2 ? "a body without walls in 2D" : "a body without walls in 3D");
        demill_world_destroy(w);
    }
}
END_TEST

/* A checkpoint is a function of the state alone: two worlds that made the
 * same calls, one on 1 thread and one on 2, with the heap left holding
 * another world's data, save the same bytes. Before, the velocities
 * predicted for the end of a step were left as the heap had them for new
 * particles (symplectic Euler never writes them). */
START_TEST(checkpoint_bytes_depend_on_state_only)
{
    demill_world *x = box2d(DEMILL_INTEGRATOR_VELOCITY_VERLET);
    DM_OK(x, demill_world_step(x, 50));
    demill_world_destroy(x); /* its arrays go back to the heap, full of data */
    demill_world *a = box2d(DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    demill_world *b = box2d(DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    const demill_status t = demill_world_set(b, DEMILL_WORLD_THREADS, 2);
    ck_assert(t == DEMILL_OK || t == DEMILL_ERR_UNSUPPORTED);
    bytes ca = checkpoint_of(a), cb = checkpoint_of(b);
    same_bytes(ca, cb, "new particles");
    free(ca.b);
    free(cb.b);
    DM_OK(a, demill_world_step(a, 100));
    DM_OK(b, demill_world_step(b, 100));
    ca = checkpoint_of(a);
    cb = checkpoint_of(b);
    same_bytes(ca, cb, "after 100 steps of symplectic Euler");
    free(ca.b);
    free(cb.b);
    demill_world_destroy(a);
    demill_world_destroy(b);
}
END_TEST

/* A stored value that is not finite (a particle's angle or a wall's
 * velocity here, which the loader did not look at) is refused behind a valid checksum; and
 * a world whose state diverged (with the watchdog off) is not saved. */
START_TEST(values_not_finite_are_refused)
{
    demill_world *w = small(), *target;
    ck_assert_int_eq(demill_world_create(3, &target), DEMILL_OK);
    /* values found once in the checkpoint: a particle's 2D angle and the
     * piston wall's velocity */
    demill_id ids[20], walls[4];
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_PARTICLE, ids, 20, NULL));
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, walls, 4, NULL));
    const double angle = 1.2345678, v[3] = {0, -0.2345678, 0};
    DM_OK(w, demill_particle_set(w, ids[3], DEMILL_PARTICLE_ANGLE, &angle));
    DM_OK(w, demill_wall_set_motion(w, walls[3], v, NULL, NULL));
    bytes good = checkpoint_of(w), before = checkpoint_of(target);
    const double values[2] = {angle, v[1]}, bad_values[2] = {NAN, -INFINITY};
    unsigned char *bad = malloc(good.n);
    ck_assert_ptr_nonnull(bad);
    for (int c = 0; c < 2; c++) {
        size_t at = 0, found = 0;
        for (size_t k = 32; k + 8 <= good.n; k++)
            if (!memcmp(good.b + k, &values[c], 8)) {
                at = k;
                found++;
            }
        ck_assert_uint_eq(found, 1);
        refused_patched(target, before, good, bad, at, &bad_values[c], 8, "not finite",
                        "a value");
    }
    release(w, target, good, before, bad);

    demill_id one;
    w = dm_test_chain(1, 1.5, &one);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_WATCHDOG, 0));
    demill_status st;
    for (int k = 0; k < 10000 && (st = demill_world_step(w, 10)) == DEMILL_OK; k++)
        ;
    ck_assert_int_eq(st, DEMILL_ERR_UNSTABLE);
    size_t n = 0;
    ck_assert_int_eq(demill_world_save_buffer(w, NULL, 0, &n), DEMILL_ERR_UNSTABLE);
    ck_assert_msg(n == 0 && strstr(demill_world_last_error(w), "not finite"), "%zu: %s", n,
                  demill_world_last_error(w));
    demill_world_destroy(w);
}
END_TEST

int main(int argc, char **argv)
{
    self = argv[0];
    if (argc == 4 && !strcmp(argv[1], "continue"))
        return continue_run(argv[2], argv[3]);
    Suite *s = suite_create("state");
    /* one case per test, so that CK_RUN_CASE can pick one */
    const struct {
        const char *name;
        const TTest *test;
        int loops;
    } tests[] = {
        {"restart", restart_in_new_process_is_bitwise, SCENES},
        {"snapshot", snapshot_restores_bitwise, SCENES},
        {"ids", listing_ids, 1},
        {"refused", truncated_and_corrupt_checkpoints_are_refused, 1},
        {"repaired", corruption_behind_a_repaired_checksum_never_crashes, 1},
        {"clump_flips", clump_bytes_flipped_never_crash, 1},
        {"clumps", clump_records_the_api_would_not_make_are_refused, 1},
        {"drum", drum_values_the_api_refuses_are_refused, 1},
        {"impacts", impact_recordings_not_finite_are_refused, 1},
        {"finite_walls", finite_wall_values_the_api_refuses_are_refused, 1},
        {"wall_loads", wall_loads_the_api_would_not_make_are_refused, 1},
        {"empty", empty_state_into_a_refining_world, 1},
        {"files", file_errors, 1},
        {"accepted", accepted_states_reload, 1},
        {"state_only", checkpoint_bytes_depend_on_state_only, 1},
        {"not_finite", values_not_finite_are_refused, 1},
    };
    for (size_t k = 0; k < sizeof tests / sizeof tests[0]; k++) {
        TCase *tc = tcase_create(tests[k].name);
        tcase_set_timeout(tc, 600);
        tcase_add_loop_test(tc, tests[k].test, 0, tests[k].loops);
        suite_add_tcase(s, tc);
    }
    return dm_test_run(s);
}
