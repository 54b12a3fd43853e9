/* api_seeds.c: writes the starting inputs of the API fuzzer (api.c) into a
 * directory, in the encoding of api_ops.h: a ball dropped on a plane and
 * stepped with each integrator, snapshot and checkpoint round trips; a small
 * 3D mill with lifters, a fill, files and VTK output;
 * a 2D box of discs with a moving wall, the progress callback stopping a
 * long run, a settle and bulk writes; and the ids of one world used on the
 * other; the impacts on a mill's balls recorded and turned into the rates
 * of a grinding object, which grinds; and a grinding object on its own,
 * from rates and an appearance typed in, a model's, and an impact spectrum
 * typed in; walls of every kind, shaken, turning and with a belt; a mill
 * with a part of its own material, an attached lifter mesh and a region
 * fill; a box fill, a feed and an outlet; a 2D spring-mounted body under
 * discs in a polyline box, one of them fixed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api_ops.h"

#define COUNT(a) (sizeof(a) / sizeof(a)[0])

static unsigned char input[2048];
static size_t len;

static void byte(unsigned v)
{
    if (len == sizeof input) {
        fprintf(stderr, "api_seeds: a seed is longer than %zu bytes\n", sizeof input);
        exit(1);
    }
    input[len++] = (unsigned char)v;
}

static void op(int code, int world)
{
    byte((unsigned)code);
    byte((unsigned)world);
}

static void raw(uint64_t v)
{
    for (int k = 0; k < 8; k++)
        byte((unsigned)(v >> (8 * k)) & 0xff);
}

static void num(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    byte(FZ_NUM_RAW);
    raw(bits);
}

static void vec(double x, double y, double z)
{
    num(x);
    num(y);
    num(z);
}

static void count(uint64_t n)
{
    if (n < FZ_COUNT_TABLE) {
        byte((unsigned)n);
        return;
    }
    byte(FZ_COUNT_RAW);
    raw(n);
}

/* The index of `value` in one of the tables of api_ops.h. */
static unsigned in_table(const int32_t *table, size_t n, int32_t value)
{
    for (size_t k = 0; k < n; k++)
        if (table[k] == value)
            return (unsigned)k;
    fprintf(stderr, "api_seeds: %d is in no table\n", (int)value);
    exit(1);
}
#define KEY(table, value) byte(in_table(table, COUNT(table), value))

/* The k-th id of the call's world that demill_world_ids() lists. */
static void own(unsigned k)
{
    byte(k);
}

static void start(int dims)
{
    len = 0;
    byte((unsigned)dims);
}

static void finish(const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/seed-%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(input, 1, len, f) != len || fclose(f))
        exit((perror(path), 1));
}

/* Material 0 of world w: density, and a contact model for it with itself. */
static void material(int w, double density, int normal, int tangential)
{
    op(FZ_MATERIAL_CREATE, w), byte(0);
    op(FZ_MATERIAL_SET, w), own(0), KEY(fz_material_keys, DEMILL_MATERIAL_DENSITY), num(density);
    op(FZ_PAIR_SET, w), own(0), own(0), KEY(fz_pair_keys, DEMILL_PAIR_NORMAL), num(normal);
    op(FZ_PAIR_SET, w), own(0), own(0), KEY(fz_pair_keys, DEMILL_PAIR_DAMPING),
        num(DEMILL_DAMPING_RESTITUTION);
    op(FZ_PAIR_SET, w), own(0), own(0), KEY(fz_pair_keys, DEMILL_PAIR_TANGENTIAL), num(tangential);
}

static void world_set(int w, int32_t key, double value)
{
    op(FZ_WORLD_SET, w), KEY(fz_world_keys, key), num(value);
}

static void step(int w, uint64_t steps)
{
    op(FZ_STEP, w), count(steps);
}

/* A ball dropped on a plane, stepped with each integrator, kept as a
 * snapshot and as a checkpoint loaded into the other world. */
static void ball_on_plane(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_WALL_ADD, 0), own(0), byte(0), vec(0, 0, 0), vec(0, 1, 0);
    op(FZ_PARTICLES_ADD, 0), own(0), byte(0), byte(0), vec(0, 0.012, 0), num(0.01), vec(0, -0.5, 0);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 200);
    op(FZ_CONTACTS_READ, 0), KEY(fz_contact_fields, DEMILL_CONTACT_OVERLAP), byte(0);
    world_set(0, DEMILL_WORLD_INTEGRATOR, DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    step(0, 100);
    world_set(0, DEMILL_WORLD_INTEGRATOR, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT);
    step(0, 100);
    op(FZ_SNAPSHOT_TAKE, 0), byte(0), byte(0);
    step(0, 50);
    op(FZ_SNAPSHOT_RESTORE, 0), byte(0);
    op(FZ_BUFFER_TRANSFER, 1), byte(0), byte(0);
    step(1, 50);
    op(FZ_PARTICLE_GET, 0), own(0), KEY(fz_particle_fields, DEMILL_PARTICLE_POSITION), byte(0);
    op(FZ_ENERGY, 0), KEY(fz_energy_terms, DEMILL_ENERGY_TOTAL), byte(0);
    op(FZ_PARTICLES_REMOVE, 0), byte(1), own(0);
    op(FZ_PARTICLE_GET, 0), byte(FZ_ID_POOL), byte(0),
        KEY(fz_particle_fields, DEMILL_PARTICLE_POSITION), byte(0);
    finish(dir, "ball-on-plane");
}

/* A small mill: a drum with lifters filled with 16 balls, a few hundred
 * steps at 80 % of critical speed, its readings, files and VTK output; the
 * checkpoint file loaded into the other world. */
static void small_mill(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_PAIR_SET, 0), own(0), own(0), KEY(fz_pair_keys, DEMILL_PAIR_ROLLING),
        num(DEMILL_ROLLING_CONSTANT_TORQUE);
    op(FZ_DRUM_CREATE, 0), own(0), byte(0);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_DIAMETER), num(0.05);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_LENGTH), num(0.012);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_LIFTERS), num(3);
    op(FZ_DRUM_FILL, 0), own(0), own(0), KEY(fz_distributions, DEMILL_SIZES_CLASSES),
        byte(2 | 4 * 3), byte(2), num(0.006), num(1), KEY(fz_fill_targets, DEMILL_FILL_COUNT),
        num(16), byte(1);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_SPEED_FRACTION), num(0.8);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 250);
    step(0, 250);
    op(FZ_DRUM_GET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_POWER), byte(0);
    op(FZ_DRUM_GET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_TOE_ANGLE), byte(0);
    op(FZ_DRUM_LIFTER_GET, 0), own(0), count(0), KEY(fz_lifter_fields, DEMILL_LIFTER_FORCE),
        byte(0);
    op(FZ_CONTACTS_READ_IDS, 0), byte(0);
    op(FZ_VTK_PARTICLES, 0), byte(0);
    op(FZ_VTK_WALLS, 0), byte(0);
    op(FZ_FILE_SAVE, 0), byte(0);
    op(FZ_FILE_LOAD, 1), byte(0);
    step(1, 100);
    op(FZ_DRUM_ADD_LIFTER, 1), own(0), num(1.0), num(0.004), num(0.004), num(0.3);
    op(FZ_DRUM_REMOVE, 0), own(0);
    finish(dir, "small-mill");
}

/* A 2D box of 12 discs with a moving side wall: the progress callback
 * stops a run of 2^64 - 1 steps, then a settle, bulk writes and the other
 * world's ids. */
static void box2d(const char *dir)
{
    start(1);
    material(0, 2500, DEMILL_NORMAL_LINEAR, DEMILL_TANGENTIAL_SPRING);
    op(FZ_WALL_ADD, 0), own(0), byte(8), vec(0, 0, 0), vec(0, 1, 0);
    op(FZ_WALL_ADD, 0), own(0), byte(8), vec(0, 0, 0), vec(1, 0, 0);
    op(FZ_WALL_MOTION, 0), own(1), byte(8 | 2 | 4), vec(0.1, 0, 0), vec(0, 0, 0), vec(0, 0, 0);
    op(FZ_PARTICLES_ADD, 0), own(0), byte(0), byte(11), vec(0.01, 0.005, 0), num(0.004),
        vec(0, 0, 0);
    world_set(0, DEMILL_WORLD_DISC_THICKNESS, 0.01);
    op(FZ_PROGRESS, 0), byte(2), count(10), byte(3);
    step(0, UINT64_MAX);
    op(FZ_PROGRESS, 0), byte(1), count(0), byte(0);
    step(0, 100);
    op(FZ_SETTLE, 0), num(5e-4), num(0), byte(0);
    op(FZ_PARTICLES_WRITE, 0), KEY(fz_particle_fields, DEMILL_PARTICLE_RADIUS), byte(2 << 3),
        num(0.0045);
    op(FZ_PARTICLES_READ_IDS, 0), KEY(fz_id_fields, DEMILL_PARTICLE_ID), byte(0);
    world_set(0, DEMILL_WORLD_INTEGRATOR, DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT);
    step(0, 20);
    /* world 1 (3D) named by world 0's ids, and the other way round */
    op(FZ_PARTICLE_GET, 1), byte(FZ_ID_OTHER), KEY(fz_particle_fields, DEMILL_PARTICLE_POSITION),
        byte(0);
    op(FZ_MATERIAL_CREATE, 1), byte(0);
    op(FZ_PARTICLES_ADD, 0), byte(FZ_ID_OTHER), byte(0), byte(0), vec(0.1, 0.1, 0), num(0.004),
        vec(0, 0, 0);
    op(FZ_IDS, 0), KEY(fz_kinds, DEMILL_KIND_PARTICLE), byte(0);
    finish(dir, "box2d");
}

/* A call of FZ_GRINDING on the live object. */
static void grind(int code, int world)
{
    op(FZ_GRINDING, world), byte(0), byte((unsigned)code);
}

/* Tavares and King's model for the ores of the seeds: E50 about 0.012 J/kg
 * at 5 mm, so that the little mill's impacts break some balls. */
static void tavares(void)
{
    grind(FZ_GRIND_MODEL, 0), byte(1), num(0.01), num(0.001), num(1), num(0.8), num(0), num(3),
        num(55), num(0.5);
}

/* The small mill's balls as an ore: their impacts recorded over 400 steps,
 * read, and turned into a grinding object's rates, which grinds them. */
static void mill_impacts(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_DRUM_CREATE, 0), own(0), byte(0);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_DIAMETER), num(0.05);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_LENGTH), num(0.012);
    op(FZ_DRUM_FILL, 0), own(0), own(0), KEY(fz_distributions, DEMILL_SIZES_CLASSES),
        byte(2 | 4 * 3), byte(2), num(0.006), num(1), KEY(fz_fill_targets, DEMILL_FILL_COUNT),
        num(16), byte(1);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_SPEED_FRACTION), num(0.8);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    op(FZ_SPECTRUM_START, 0), own(0), byte(1), count(0), count(8), num(1e-9), num(1e-2);
    op(FZ_IMPACTS_START, 0), own(0), own(0), num(0.008), count(4), count(8), num(0.01), num(1);
    step(0, 200);
    step(0, 200);
    op(FZ_IMPACTS_READ, 0), own(0), byte(0);
    op(FZ_IMPACTS_PARTICLES, 0), own(0), byte(0);
    grind(FZ_GRIND_CREATE, 0), num(0.008), count(4), byte(0);
    tavares();
    grind(FZ_GRIND_FROM_DRUM, 0), own(0);
    grind(FZ_GRIND_FEED, 0), byte(2 << 3);
    grind(FZ_GRIND_RUN, 0), num(10);
    grind(FZ_GRIND_READ, 0), byte(0), byte(0);
    grind(FZ_GRIND_READ, 0), byte(1), byte(0), num(0.004);
    grind(FZ_GRIND_READ, 0), byte(2), byte(0), num(0.8);
    op(FZ_BUFFER_TRANSFER, 1), byte(0), byte(0);
    op(FZ_IMPACTS_READ, 1), own(0), byte(0);
    grind(FZ_GRIND_FROM_DRUM, 1), own(0);
    finish(dir, "mill-impacts");
}

/* A grinding object alone: rates and an appearance typed in, a run, its
 * product; then the JKMRC and Tavares and King models, an appearance at
 * one energy, rates from a typed-in impact spectrum, and runs again. */
static void grinding_alone(const char *dir)
{
    start(0);
    grind(FZ_GRIND_CREATE, 0), num(0.01), count(6), byte(0);
    grind(FZ_GRIND_FEED, 0), byte(2 << 3);
    grind(FZ_GRIND_RATES, 0), byte(2 << 3);
    grind(FZ_GRIND_APPEARANCE, 0), byte(2 << 3);
    grind(FZ_GRIND_RUN, 0), num(0.5);
    grind(FZ_GRIND_READ, 0), byte(0), byte(0);
    grind(FZ_GRIND_READ, 0), byte(2), byte(0), num(0.8);
    grind(FZ_GRIND_MODEL, 0), byte(0), num(50), num(1);
    grind(FZ_GRIND_APPEARANCE_ENERGY, 0), num(3600);
    grind(FZ_GRIND_RUN, 0), num(2);
    grind(FZ_GRIND_READ, 0), byte(7), byte(0), num(0.005), num(3600);
    tavares();
    grind(FZ_GRIND_READ, 0), byte(9), byte(0), num(0.005), num(0.02), count(3);
    /* 6 classes, 2 bins from 0.01 J/kg up by 10×, one impact per particle
     * and bin, a particle per class, 1 s */
    grind(FZ_GRIND_FROM_IMPACTS, 0), byte(0), byte(2), byte(8 | 16), num(0.01), num(1);
    for (int i = 0; i < 6; i++)
        num(1);
    num(1);
    grind(FZ_GRIND_RUN, 0), num(5);
    grind(FZ_GRIND_READ, 0), byte(1), byte(0), num(0.002);
    grind(FZ_GRIND_READ, 0), byte(10), byte(0), num(100), num(2);
    finish(dir, "grinding");
}

/* Walls of every kind in a 3D world: a box of triangles around 8 balls
 * with a finite cylinder, cone, disc and rectangle inside it, the box
 * shaken (harmonic translation), a belt on the rectangle, two STL floors
 * (ASCII and binary), the cylinder turning back and forth; a snapshot and
 * a checkpoint of it all. */
static void geometry3d(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_WALL_ADD_MESH, 0), own(0), byte(8), vec(-0.05, -0.05, -0.05), num(0.1);
    op(FZ_PARTICLES_ADD, 0), own(0), byte(0), byte(7), vec(-0.02, -0.02, -0.02), num(0.005),
        vec(0.1, 0, 0);
    op(FZ_WALL_ADD_FINITE, 0), own(0), byte(0), byte(0), vec(0, -0.03, 0), vec(0, 1, 0),
        num(0.04), num(0.06), KEY(fz_caps, DEMILL_CAPS_NONE);
    op(FZ_WALL_ADD_FINITE, 0), own(0), byte(1), byte(0), vec(0, 0.02, 0), vec(0, 1, 0),
        num(0.04), num(0.01), num(0.02), KEY(fz_caps, DEMILL_CAPS_END);
    op(FZ_WALL_ADD_FINITE, 0), own(0), byte(2), byte(0), vec(0, -0.04, 0), vec(0, 1, 0),
        num(0.03), num(0.005);
    op(FZ_WALL_ADD_FINITE, 0), own(0), byte(3), byte(0), vec(0, -0.045, 0), vec(0, 1, 0),
        vec(1, 0, 0), num(0.03), num(0.03);
    op(FZ_WALL_HARMONIC, 0), own(0), KEY(fz_harmonic_modes, DEMILL_HARMONIC_TRANSLATION), byte(0),
        vec(0, 1, 0), num(0.001), num(10), num(0);
    op(FZ_WALL_SURFACE_VELOCITY, 0), own(4), byte(0), vec(0.1, 0, 0);
    op(FZ_WALL_MESH_INFO, 0), own(0), byte(0);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 200);
    op(FZ_WALL_ADD_STL, 0), own(0), byte(0), byte(1), vec(-0.05, -0.048, -0.05),
        vec(0.05, -0.048, -0.05), vec(0.05, -0.048, 0.05), vec(-0.05, -0.048, -0.05),
        vec(0.05, -0.048, 0.05), vec(-0.05, -0.048, 0.05), num(1);
    op(FZ_WALL_ADD_STL, 0), own(0), byte(8), byte(0), vec(-0.05, -0.049, -0.05),
        vec(0.05, -0.049, -0.05), vec(0, -0.049, 0.05), num(1);
    op(FZ_WALL_HARMONIC, 0), own(1), KEY(fz_harmonic_modes, DEMILL_HARMONIC_ROTATION), byte(0),
        vec(0, 1, 0), num(0.1), num(5), num(0.5);
    step(0, 100);
    op(FZ_SNAPSHOT_TAKE, 0), byte(0), byte(0);
    step(0, 50);
    op(FZ_SNAPSHOT_RESTORE, 0), byte(0);
    op(FZ_BUFFER_TRANSFER, 1), byte(0), byte(0);
    step(1, 50);
    op(FZ_WALL_REMOVE, 0), own(2);
    step(0, 20);
    finish(dir, "geometry3d");
}

/* A mill whose lifters are of a second material and which has a lifter of
 * one triangle attached, filled through demill_fill_region's drum region,
 * run, then without its analytic shell. */
static void drum_parts(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_MATERIAL_CREATE, 0), byte(0);
    op(FZ_PAIR_SET, 0), own(0), own(1), KEY(fz_pair_keys, DEMILL_PAIR_NORMAL),
        num(DEMILL_NORMAL_HERTZ);
    op(FZ_PAIR_SET, 0), own(0), own(1), KEY(fz_pair_keys, DEMILL_PAIR_DAMPING),
        num(DEMILL_DAMPING_RESTITUTION);
    op(FZ_DRUM_CREATE, 0), own(0), byte(0);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_DIAMETER), num(0.05);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_LENGTH), num(0.012);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_LIFTERS), num(3);
    op(FZ_DRUM_MATERIAL, 0), own(0), KEY(fz_drum_parts, DEMILL_DRUM_PART_LIFTERS), byte(0),
        own(1);
    op(FZ_DRUM_MATERIAL, 0), own(0), KEY(fz_drum_parts, DEMILL_DRUM_PART_SHELL), byte(1);
    op(FZ_WALL_ADD_MESH, 0), own(0), byte(0), byte(2), vec(0, -0.024, -0.006), vec(0, -0.018, 0),
        vec(0, -0.024, 0.006), byte(1), byte(0), byte(1), byte(2);
    op(FZ_DRUM_ATTACH_WALL, 0), own(0), own(0), KEY(fz_drum_parts, DEMILL_DRUM_PART_LIFTERS);
    op(FZ_FILL_REGION, 0), KEY(fz_regions, DEMILL_REGION_DRUM), byte(1), vec(0, 0, 0), num(0),
        own(0), KEY(fz_distributions, DEMILL_SIZES_CLASSES), byte(1), num(0.006),
        KEY(fz_fill_targets, DEMILL_FILL_COUNT), num(16), byte(1), byte(6);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_SPEED_FRACTION), num(0.8);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 250);
    step(0, 250);
    op(FZ_DRUM_GET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_POWER), byte(0);
    op(FZ_DRUM_SET, 0), own(0), KEY(fz_drum_keys, DEMILL_DRUM_SHELL), num(0);
    step(0, 20);
    finish(dir, "drum-parts");
}

/* Balls on a floor from a box fill, a feed pouring more from above for
 * 5 ms and an outlet taking those that reach the floor, in two size
 * classes; their readings, a checkpoint, and both removed. */
static void flows(const char *dir)
{
    start(0);
    material(0, 7800, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    op(FZ_WALL_ADD, 0), own(0), byte(0), vec(0, 0, 0), vec(0, 1, 0);
    op(FZ_FILL_REGION, 0), KEY(fz_regions, DEMILL_REGION_BOX), byte(1), vec(-0.02, 0.01, -0.02),
        num(0.04), own(0), KEY(fz_distributions, DEMILL_SIZES_CLASSES), byte(1), num(0.006),
        KEY(fz_fill_targets, DEMILL_FILL_COUNT), num(20), byte(3), byte(6);
    op(FZ_FEED_CREATE, 0), KEY(fz_regions, DEMILL_REGION_BOX), byte(1), vec(-0.02, 0.06, -0.02),
        num(0.03), own(0), KEY(fz_distributions, DEMILL_SIZES_ROSIN_RAMMLER), byte(2), num(0.006),
        num(1), byte(0), vec(0, -0.5, 0), num(0), num(0.005), byte(7);
    op(FZ_OUTLET_CREATE, 0), KEY(fz_regions, DEMILL_REGION_HALF_SPACE), byte(1),
        vec(0, 0.0035, 0), num(0), byte(0), byte(2), num(0.004), num(0.005), num(0.001);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 250);
    step(0, 250);
    op(FZ_FEED_READ, 0), own(0), byte(0);
    op(FZ_OUTLET_READ, 0), own(0), byte(0);
    op(FZ_ENERGY, 0), KEY(fz_energy_terms, DEMILL_ENERGY_FLOW), byte(0);
    op(FZ_BUFFER_TRANSFER, 1), byte(0), byte(0);
    step(1, 100);
    op(FZ_FEED_REMOVE, 0), own(0);
    op(FZ_OUTLET_REMOVE, 0), own(0);
    step(0, 10);
    finish(dir, "flows");
}

/* A 2D box of discs whose floor is a wall on a spring-mounted body driven
 * by a sine force, inside a closed square polyline, one disc fixed; the
 * body's readings, a belt on the floor, a checkpoint file into the other
 * world, and the body removed. */
static void bodies2d(const char *dir)
{
    start(1);
    material(0, 2500, DEMILL_NORMAL_LINEAR, DEMILL_TANGENTIAL_SPRING);
    world_set(0, DEMILL_WORLD_DISC_THICKNESS, 0.01);
    op(FZ_BODY_ADD, 0), num(1), vec(0, 0, 0), byte(DEMILL_BODY_AXIS_Y), KEY(fz_body_flags, 0),
        byte(0);
    op(FZ_WALL_ADD, 0), own(0), byte(8), vec(0, 0, 0), vec(0, 1, 0);
    op(FZ_BODY_ATTACH_WALL, 0), own(0), own(0);
    op(FZ_BODY_SPRING, 0), own(0), KEY(fz_body_axes, DEMILL_BODY_AXIS_Y), num(1e4), num(10),
        num(0);
    op(FZ_BODY_FORCE, 0), own(0), byte(2), vec(0, 1, 0), num(20), num(0);
    op(FZ_WALL_ADD_POLYLINE, 0), own(0), byte(8 | 4), vec(-0.05, -0.01, 0), num(0.1),
        KEY(fz_closed, 1);
    op(FZ_PARTICLES_ADD, 0), own(0), byte(0), byte(11), vec(-0.02, 0.01, 0), num(0.004),
        vec(0, 0, 0);
    op(FZ_PARTICLE_SET, 0), own(0), KEY(fz_particle_fields, DEMILL_PARTICLE_FIXED), byte(0),
        vec(1, 0, 0);
    op(FZ_SUGGEST_APPLY, 0), num(0), num(0);
    step(0, 200);
    step(0, 200);
    op(FZ_BODY_GET, 0), own(0), KEY(fz_body_fields, DEMILL_BODY_POSITION), byte(0);
    op(FZ_BODY_ENERGY, 0), own(0), KEY(fz_body_terms, DEMILL_ENERGY_BODY_ELASTIC), byte(0);
    op(FZ_WALL_MESH_INFO, 0), own(1), byte(0);
    op(FZ_WALL_SURFACE_VELOCITY, 0), own(0), byte(2), vec(0.1, 0, 0);
    op(FZ_FILE_SAVE, 0), byte(0);
    op(FZ_FILE_LOAD, 1), byte(0);
    step(1, 50);
    op(FZ_BODY_REMOVE, 0), own(0);
    step(0, 10);
    finish(dir, "bodies2d");
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return fprintf(stderr, "usage: api_seeds DIRECTORY\n"), 2;
    ball_on_plane(argv[1]);
    small_mill(argv[1]);
    box2d(argv[1]);
    mill_impacts(argv[1]);
    grinding_alone(argv[1]);
    geometry3d(argv[1]);
    drum_parts(argv[1]);
    flows(argv[1]);
    bodies2d(argv[1]);
    return 0;
}
