/* api_ops.h: the encoding of the inputs of the API fuzz target
 * (tests/fuzz/api.c), shared with the program that writes its seeds
 * (api_seeds.c).
 *
 * An input is byte 0, the dimensions of the two worlds (bit 0 set: world 0 is
 * 2D, bit 1: world 1), then calls until the bytes run out (a call cut short
 * reads zeros). A call is an op byte (taken modulo FZ_OPS), a world byte
 * (FZ_WORLD_NULL: NULL, FZ_WORLD_FAKE: a pointer to memory that is not a
 * world, anything else: world (byte & 1)) and the op's arguments, read in
 * the order listed below with these readers:
 *   byte   one byte;
 *   num    a double: a byte below FZ_NUM_SCALED indexes the table of special
 *          values in api.c (0, -0, NaN, ±inf, 1e308, denormals, 0.01, ...);
 *          below FZ_NUM_RAW it is (signed next byte) × 2^(byte - 96); from
 *          FZ_NUM_RAW up the next 8 bytes are the double;
 *   count  a size: a byte below FZ_COUNT_TABLE is the count itself, the
 *          next ones index a table of large counts (SIZE_MAX, 2^32, ...) in
 *          api.c, the byte FZ_COUNT_RAW takes the next 8 bytes, and any
 *          other byte gives its low 4 bits;
 *   id     an id of the op's kind: a byte below FZ_ID_OTHER picks (modulo
 *          their number) one of the ids that demill_world_ids() lists in the
 *          call's world, up to FZ_ID_POOL one of the other world's, up to
 *          FZ_ID_SPECIAL (with the next byte) one of the harness's pool of
 *          ids seen before, removed ones among them; the next 8 bytes from
 *          FZ_ID_SPECIAL up give DEMILL_ID_NONE, 8 raw bytes, ~0, or the first
 *          listed id with its kind, generation, tag or index changed, and the
 *          rest the pool again (with the next byte);
 *   vec    3 nums;
 *   flags  one byte of bits, as each op says.
 */
#ifndef DEMILL_FUZZ_API_OPS_H
#define DEMILL_FUZZ_API_OPS_H

#include <stdint.h>

#include <demill.h>

#define FZ_WORLD_NULL 0xfe
#define FZ_WORLD_FAKE 0xff

#define FZ_NUM_SCALED 0x40
#define FZ_NUM_RAW 0x80

#define FZ_COUNT_TABLE 0x40
#define FZ_COUNT_RAW 0xff

#define FZ_ID_OTHER 0xc0
#define FZ_ID_POOL 0xe0
#define FZ_ID_SPECIAL 0xf0

/* The ops and their arguments. Choices marked "table" index a table below
 * (modulo its size) that holds the valid keys or fields followed by invalid
 * ones. Flag bits ask for NULL in place of a pointer (an out pointer, or an
 * in pointer). "capacity" is flags / 4 % 5 for a read of n items: n, n - 1,
 * 0, SIZE_MAX or n + 1 (the buffer always holds n + 1). */
enum {
    FZ_WORLD_RECREATE,   /* byte (bit 0: 2D): destroy the world and create it anew */
    FZ_WORLD_CREATE_BAD, /* byte (dimension table), flags (1: out NULL) */
    FZ_WORLD_SET,        /* byte (key table), num */
    FZ_WORLD_GET,        /* byte (key table), flags (1: value NULL) */
    FZ_MATERIAL_CREATE,  /* flags (1: out NULL) */
    FZ_MATERIAL_SET,     /* id, byte (key table), num */
    FZ_MATERIAL_GET,     /* id, byte (key table), flags (1: value NULL) */
    FZ_PAIR_SET,         /* id, id, byte (key table), num */
    FZ_PAIR_GET,         /* id, id, byte (key table), flags (1: value NULL) */
    /* id (material), flags: bits 0-1 the layout, 2-3 the flags argument
     * (0, NO_OVERLAP, 2, 0x80000001), 4 ids NULL, 5 velocities NULL, 6 z = 0
     * in layout 1 / radii NULL in layout 2; then by layout:
     * 0 a lattice: byte (n - 1, modulo 16), vec (corner), num (radius),
     *   vec (velocity of all);
     * 1 every value hostile: byte (n - 1, modulo 4), n × (vec, num, vec);
     * 2 NULL positions or radii: count (n);
     * 3 a lattice as 0 with one value replaced: then byte (which), num */
    FZ_PARTICLES_ADD,
    /* byte: from 0x80 up, ids NULL and a count follows; else (byte % 9) ids */
    FZ_PARTICLES_REMOVE,
    FZ_PARTICLES_READ,     /* byte (field table), flags (1 out NULL, 2 count NULL, capacity) */
    FZ_PARTICLES_READ_IDS, /* byte (field table), flags as for FZ_PARTICLES_READ */
    /* byte (field table), flags: 1 in NULL; bits 1-2: n is the count, one
     * less, one more or 0; bits 3-4: the values as read, one of them
     * replaced (byte: which, num), all one num, or every one a num */
    FZ_PARTICLES_WRITE,
    FZ_PARTICLE_GET, /* id, byte (field table), flags (1: out NULL) */
    /* id, byte (field table), flags (1: in NULL), then with flag 2 one
     * component replaced (byte: which, num), else vec */
    FZ_PARTICLE_SET,
    /* id (material), flags (1 point NULL, 2 normal NULL, 4 out NULL, 8 z = 0
     * in 2D), vec (point), vec (normal) */
    FZ_WALL_ADD,
    FZ_WALL_REMOVE, /* id */
    /* id, flags (1, 2, 4: velocity, angular velocity, centre NULL; 8: what a
     * 2D world refuses set to 0), vec, vec, vec */
    FZ_WALL_MOTION,
    FZ_WALL_GET,          /* id, byte (field table), flags (1: out NULL) */
    FZ_CONTACTS_READ,     /* byte (field table), flags as for FZ_PARTICLES_READ */
    FZ_CONTACTS_READ_IDS, /* flags (1 a NULL, 2 count NULL, 16 b NULL, capacity) */
    FZ_ENERGY,            /* byte (term table), flags (1: value NULL) */
    FZ_DRUM_CREATE,       /* id (material), flags (1: out NULL) */
    FZ_DRUM_REMOVE,       /* id */
    FZ_DRUM_SET,          /* id, byte (key table), num */
    FZ_DRUM_GET,          /* id, byte (key table), flags (1: value NULL) */
    FZ_DRUM_ADD_LIFTER,   /* id, num (angle), num (height), num (width), num (face angle) */
    FZ_DRUM_LIFTER_GET,   /* id, count (index), byte (field table), flags (1: out NULL) */
    /* id (drum), id (material), byte (distribution table), flags (1 params
     * NULL with a count of them, 2 ids NULL, bits 2-3 capacity 0, 1, 8 or
     * 512), byte (nparams, modulo 9) or count, nparams × num, byte (target
     * table), num (value), byte (seed) */
    FZ_DRUM_FILL,
    /* id, flags (1 edges NULL with a count of them, 2 e_max just above e_min),
     * byte (nedges, modulo 9) or count, nedges × num, count (nbins), num
     * (e_min), num (e_max, unless flag 2) */
    FZ_SPECTRUM_START,
    FZ_SPECTRUM_READ, /* id, flags (1 counts NULL, 2 count NULL, capacity) */
    FZ_STEP,          /* count (steps) */
    FZ_SETTLE,        /* num (max time), num (energy per particle), flags (1: settled NULL) */
    /* num (impact speed), num (steps per contact), flags (1, 2, 4: the
     * suggestion, stability limit, contact time NULL) */
    FZ_SUGGEST,
    FZ_SUGGEST_APPLY,    /* num, num: suggest a time step and set it */
    FZ_SNAPSHOT_TAKE,    /* byte (slot, bit 0), flags (1: out NULL) */
    FZ_SNAPSHOT_RESTORE, /* byte (0, 1 a slot; 2 NULL; 3 not a snapshot) */
    FZ_SNAPSHOT_FREE,    /* byte (slot, bit 0) */
    /* byte (source world, bit 0), flags: % 4 the size asked with the
     * exact capacity, one byte short, NULL buffer, NULL buffer and size;
     * / 4 % 5 loaded intact, truncated (count), with a byte changed (count:
     * where, byte: xor), from NULL, with size 0 */
    FZ_BUFFER_TRANSFER,
    FZ_FILE_SAVE,     /* byte (path table) */
    FZ_FILE_LOAD,     /* byte (path table) */
    /* flags (1 fn NULL, 2 fn reads the world), count (every_steps), byte
     * (the report of a call at which fn stops the run; 0: never) */
    FZ_PROGRESS,
    FZ_IDS,           /* byte (kind table), flags as for FZ_PARTICLES_READ */
    FZ_VTK_PARTICLES, /* byte (path table) */
    FZ_VTK_WALLS,     /* byte (path table) */
    /* byte (0 open, 1 write, 2 close, 3 write to NULL), byte (prefix table),
     * flags (1: out NULL) */
    FZ_VTK_SERIES,
    /* 2 bytes (a key or field, signed), byte (the world of
     * demill_world_last_error: NULL, fake or a world), 8 bytes (an id): the
     * functions that take no world */
    FZ_STATELESS,
    /* id (drum), id (material), num (top size), count (classes), count
     * (nbins), num (e_min), num (e_max) */
    FZ_IMPACTS_START,
    /* id (drum), flags (1 counts NULL, 2 count NULL, 16 time NULL, capacity) */
    FZ_IMPACTS_READ,
    FZ_IMPACTS_PARTICLES, /* id (drum), flags (1 particles NULL, 2 count NULL, capacity) */
    /* The harness's grinding object (one per input; none until created).
     * byte (the object passed: 0 to 3 the live one, 4 NULL, 5 memory that
     * is no object, 6 a world), byte (the call, modulo FZ_GRIND_CALLS),
     * then the call's arguments as listed there. The world byte of the op
     * names the world of demill_grinding_rates_from_drum() and is unused
     * by the others. */
    FZ_GRINDING,
    /* Meshes, polylines and STL (3D meshes, 2D polylines; the world's
     * dimension is not enforced: the library must refuse the other).
     * id (material), flags (1 vertices NULL with a count of them, 2
     * triangles NULL with a count of them, 4 out NULL, 8 a box: vec
     * (corner), num (side); else byte (vertices - 1, modulo 8), that many
     * vecs, byte (triangles, modulo 9), 3 bytes (indices, 0xff: UINT32_MAX)
     * per triangle) */
    FZ_WALL_ADD_MESH,
    /* id (material), flags (1 points NULL with a count of them, 2 out NULL,
     * 4 z = 0, 8 a square: vec (corner), num (side); else byte (points,
     * modulo 9), that many vecs), byte (closed table) */
    FZ_WALL_ADD_POLYLINE,
    /* id (material), flags (1 bytes NULL with a count, 2 transform NULL, 4
     * out NULL, 8 binary, else ASCII; 16 the transform typed, else the
     * identity; 32 the bytes cut short: count), byte (triangles - 1, modulo
     * 4), 3 vecs per triangle, num (scale), 12 nums (with flag 16), count
     * (with flag 32), count (with flag 1) */
    FZ_WALL_ADD_STL,
    FZ_WALL_MESH_INFO, /* id (wall), flags (1 vertices NULL, 2 elements NULL) */
    /* id (material), byte (0 cylinder, 1 cone, 2 disc, 3 rectangle),
     * flags (1 point NULL, 2 axis or normal NULL, 4 out NULL, 8 direction
     * NULL), vec (point or centre), vec (axis or normal), then: cylinder
     * num (radius), num (length), byte (caps table); cone num, num (radii),
     * num (length), byte (caps table); disc num (outer), num (inner);
     * rectangle vec (direction), num (half width), num (half height) */
    FZ_WALL_ADD_FINITE,
    /* id (wall), byte (mode table), flags (1 axis NULL, 2 the axis made
     * what a 2D world takes), vec (axis), num (amplitude), num (frequency),
     * num (phase) */
    FZ_WALL_HARMONIC,
    FZ_WALL_SURFACE_VELOCITY, /* id (wall), flags (1 NULL, 2 z = 0), vec */
    /* id (drum), byte (part table), flags (1 read it with
     * demill_drum_get_material, 2 its out NULL), id (material, unless
     * flag 1) */
    FZ_DRUM_MATERIAL,
    FZ_DRUM_ATTACH_WALL, /* id (drum), id (wall), byte (part table) */
    /* A region (region table), read as byte (way): way % 4: 0 typed, byte
     * (params, modulo 9) nums; 1 a template from vec (corner) and num
     * (size): a box of that side, a cylinder along y of that length and
     * half of it as radius, the half-space below the plane y = corner_y, the
     * drum (none); 2 params NULL with a count; 3 a template with one value
     * replaced: byte (which), num; with way & 4, z = 0 (templates).
     * Sizes (distribution table), read as byte (way): way % 4: 0 typed,
     * byte (params, modulo 9) nums; 1 one class: num (diameter); 2 a range:
     * num (d): {d, 3, d / 2, d}; 3 params NULL with a count.
     * region, id (material), sizes, byte (target table), num (value), byte
     * (seed), flags (1 ids NULL, bits 1-2 capacity 0, 1, 8 or 512) */
    FZ_FILL_REGION,
    /* region, id (material), sizes, num (mass rate), flags (1 velocity
     * NULL, 2 out NULL, 4 z = 0), vec (velocity), num (start), num (stop),
     * byte (seed) */
    FZ_FEED_CREATE,
    FZ_FEED_REMOVE, /* id (feed) */
    FZ_FEED_READ,   /* id (feed), flags (1 mass NULL, 2 count NULL, 4 deficit NULL) */
    /* region, flags (1 edges NULL with a count of them, 2 out NULL), byte
     * (edges, modulo 33) nums, num (interval) */
    FZ_OUTLET_CREATE,
    FZ_OUTLET_REMOVE, /* id (outlet) */
    /* id (outlet), flags (1 counts NULL, 2 masses NULL, 32 nclasses NULL,
     * 64 last NULL, capacity) */
    FZ_OUTLET_READ,
    /* num (mass), vec (centre), byte (free axes, the low 4 bits), byte
     * (body flag table), flags (1 centre NULL, 2 out NULL, 4 z = 0) */
    FZ_BODY_ADD,
    FZ_BODY_REMOVE, /* id (body) */
    /* id (body), byte (axis table), num (stiffness), num (damping), num (rest) */
    FZ_BODY_SPRING,
    /* id (body), flags (1 amplitude NULL, 2 z = 0), vec (amplitude), num
     * (frequency), num (phase) */
    FZ_BODY_FORCE,
    FZ_BODY_ATTACH_WALL, /* id (body), id (wall) */
    FZ_BODY_GET,         /* id (body), byte (field table), flags (1: out NULL) */
    FZ_BODY_ENERGY,      /* id (body), byte (term table), flags (1: value NULL) */
    FZ_OPS
};

/* The calls of FZ_GRINDING. "values" are n values for an object of C
 * classes: flags bits 0-1 n = C (C² for the appearance), one less, one
 * more or 0; bit 2 NULL; bits 3-4 the values: each a num, all one num,
 * the harness's valid ones (feed all 1, rates i + 1 with the sink 0, an
 * appearance that puts all of a class into the next), or those with one
 * replaced (byte: which, num). */
enum {
    FZ_GRIND_CREATE,     /* num (top size), count (classes), flags (1: out NULL) */
    FZ_GRIND_FEED,       /* flags, values */
    FZ_GRIND_RATES,      /* flags, values */
    FZ_GRIND_APPEARANCE, /* flags, values */
    /* byte (bit 0 Tavares and King, else JKMRC; bit 1 table NULL, bits 2-3
     * rows 6, 1, 2 or 101 of the harness's table), 2 nums (JKMRC: A, b)
     * or 8 nums (Tavares and King: e_inf, d0, phi, sigma, emax_ratio,
     * gamma, a', b') */
    FZ_GRIND_MODEL,
    FZ_GRIND_APPEARANCE_ENERGY, /* num (energy) */
    /* byte (classes: C, C - 1, C + 1 or 0), byte (bins, modulo 5), flags
     * (1 edges NULL, 2 counts NULL, 4 particles NULL, 8 edges from num
     * (e0) up by 10×, 16 counts all from one num), bins + 1 nums (edges,
     * unless flag 8), classes × bins nums (counts, unless flag 16) or one
     * num, classes nums (particles), num (time) */
    FZ_GRIND_FROM_IMPACTS,
    FZ_GRIND_FROM_DRUM, /* id (drum) */
    FZ_GRIND_RUN,       /* num (time) */
    /* byte (0 product, 1 passing, 2 size passing, 3 time, 4 sizes, 5
     * rates, 6 appearance, 7 t10, 8 tn, 9 broken fraction, 10 specific
     * energy), flags (1 out NULL, capacity for the arrays), then by the
     * read: passing num (size); size passing num (fraction); t10 num
     * (size), num (energy); tn num (t10); broken fraction num (size), num
     * (energy), count (impacts); specific energy num (power), num (mass) */
    FZ_GRIND_READ,
    FZ_GRIND_CALLS
};

/* The keys, fields and choices an op picks from ("table" above): the valid
 * ones, then invalid ones. */
static const int32_t fz_world_keys[] = {
    DEMILL_WORLD_TIME_STEP, DEMILL_WORLD_GRAVITY_X, DEMILL_WORLD_GRAVITY_Y, DEMILL_WORLD_GRAVITY_Z,
    DEMILL_WORLD_INTEGRATOR, DEMILL_WORLD_SKIN, DEMILL_WORLD_DISC_THICKNESS,
    DEMILL_WORLD_ENERGY_TRACKING, DEMILL_WORLD_TIME, DEMILL_WORLD_THREADS,
    DEMILL_WORLD_REFINE_TOLERANCE, DEMILL_WORLD_REFINE_MAX_ITERATIONS, DEMILL_WORLD_WATCHDOG,
    DEMILL_WORLD_WATCHDOG_OVERLAP, DEMILL_WORLD_WATCHDOG_INTERVAL,
    DEMILL_WORLD_SINGLE_PRECISION, DEMILL_WORLD_ORIENTATION_TRACKING, DEMILL_WORLD_DIMENSION,
    DEMILL_WORLD_STEP_COUNT, DEMILL_WORLD_PARTICLE_COUNT, DEMILL_WORLD_CONTACT_COUNT,
    DEMILL_WORLD_WALL_CONTACT_COUNT, DEMILL_WORLD_NEIGHBOUR_REBUILDS,
    DEMILL_WORLD_REFINE_ITERATIONS, DEMILL_WORLD_FORCE_EVALUATIONS,
    DEMILL_WORLD_REFINE_UNCONVERGED, 0, 99, 117, 149, 159, 199, 200, -1, INT32_MAX, INT32_MIN};
static const int32_t fz_material_keys[] = {
    DEMILL_MATERIAL_DENSITY, DEMILL_MATERIAL_YOUNGS_MODULUS, DEMILL_MATERIAL_POISSON_RATIO,
    DEMILL_MATERIAL_STIFFNESS, DEMILL_MATERIAL_RESTITUTION, DEMILL_MATERIAL_FRICTION,
    DEMILL_MATERIAL_ROLLING_FRICTION, 199, 207, 100, 300, -1};
static const int32_t fz_pair_keys[] = {
    DEMILL_PAIR_NORMAL, DEMILL_PAIR_DAMPING, DEMILL_PAIR_TANGENTIAL, DEMILL_PAIR_ROLLING,
    DEMILL_PAIR_RESTITUTION, DEMILL_PAIR_FRICTION, DEMILL_PAIR_ROLLING_FRICTION,
    DEMILL_PAIR_NORMAL_STIFFNESS, DEMILL_PAIR_VISCOUS_DAMPING,
    DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO, DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR,
    DEMILL_PAIR_COULOMB_REGULARISATION, DEMILL_PAIR_ROLLING_REGULARISATION,
    DEMILL_PAIR_CLAMP_NORMAL, 304, 309, 320, 200, -1};
static const int32_t fz_drum_keys[] = {
    DEMILL_DRUM_DIAMETER, DEMILL_DRUM_LENGTH, DEMILL_DRUM_LIFTERS, DEMILL_DRUM_LIFTER_HEIGHT,
    DEMILL_DRUM_LIFTER_WIDTH, DEMILL_DRUM_LIFTER_FACE_ANGLE, DEMILL_DRUM_LIFTER_PHASE,
    DEMILL_DRUM_SPEED, DEMILL_DRUM_SPEED_RPM, DEMILL_DRUM_SPEED_FRACTION, DEMILL_DRUM_RAMP_TIME,
    DEMILL_DRUM_CRITICAL_DIAMETER, DEMILL_DRUM_FILL_POROSITY, DEMILL_DRUM_SAMPLE_INTERVAL,
    DEMILL_DRUM_CRITICAL_SPEED, DEMILL_DRUM_CURRENT_SPEED, DEMILL_DRUM_ANGLE,
    DEMILL_DRUM_REVOLUTIONS, DEMILL_DRUM_TORQUE, DEMILL_DRUM_POWER, DEMILL_DRUM_POWER_MEAN,
    DEMILL_DRUM_POWER_CM, DEMILL_DRUM_POWER_CM_MEAN, DEMILL_DRUM_TOE_ANGLE,
    DEMILL_DRUM_SHOULDER_ANGLE, DEMILL_DRUM_COM_ANGLE, DEMILL_DRUM_TOE_ANGLE_MEAN,
    DEMILL_DRUM_SHOULDER_ANGLE_MEAN, DEMILL_DRUM_COM_ANGLE_MEAN, DEMILL_DRUM_ENERGY_IN,
    DEMILL_DRUM_ENERGY_DISSIPATED, DEMILL_DRUM_DISSIPATION_MEAN, DEMILL_DRUM_LIFTER_COUNT, 399,
    407, 417, 449, 469, 500, 100, -1};
static const int32_t fz_particle_fields[] = {
    DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY, DEMILL_PARTICLE_ANGULAR_VELOCITY,
    DEMILL_PARTICLE_RADIUS, DEMILL_PARTICLE_MASS, DEMILL_PARTICLE_FORCE, DEMILL_PARTICLE_TORQUE,
    DEMILL_PARTICLE_ANGLE, 0, 9, DEMILL_PARTICLE_ID, DEMILL_PARTICLE_MATERIAL, -1};
static const int32_t fz_id_fields[] = {DEMILL_PARTICLE_ID, DEMILL_PARTICLE_MATERIAL,
                                    DEMILL_PARTICLE_POSITION, 99, 102, -1};
static const int32_t fz_wall_fields[] = {
    DEMILL_WALL_POINT, DEMILL_WALL_NORMAL, DEMILL_WALL_CENTRE, DEMILL_WALL_VELOCITY,
    DEMILL_WALL_ANGULAR_VELOCITY, DEMILL_WALL_FORCE, DEMILL_WALL_TORQUE, 0, 8, -1};
static const int32_t fz_contact_fields[] = {
    DEMILL_CONTACT_POINT, DEMILL_CONTACT_NORMAL, DEMILL_CONTACT_OVERLAP,
    DEMILL_CONTACT_NORMAL_FORCE, DEMILL_CONTACT_TANGENTIAL_FORCE, DEMILL_CONTACT_ROLLING_TORQUE,
    0, 7, -1};
static const int32_t fz_energy_terms[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
                                       14, 15, 16, 17, 18, 0, 19, -1};
static const int32_t fz_lifter_fields[] = {DEMILL_LIFTER_FORCE, DEMILL_LIFTER_FORCE_MEAN,
                                        DEMILL_LIFTER_FORCE_PEAK, DEMILL_LIFTER_ENERGY,
                                        DEMILL_LIFTER_ANGLE, 0, 6, -1};
static const int32_t fz_distributions[] = {DEMILL_SIZES_CLASSES, DEMILL_SIZES_ROSIN_RAMMLER,
                                        DEMILL_SIZES_NORMAL, 0, 4, -1};
static const int32_t fz_fill_targets[] = {DEMILL_FILL_COUNT, DEMILL_FILL_MASS, DEMILL_FILL_FRACTION,
                                       0, 4, -1};
static const int32_t fz_kinds[] = {DEMILL_KIND_MATERIAL, DEMILL_KIND_PARTICLE, DEMILL_KIND_WALL,
                                DEMILL_KIND_DRUM, DEMILL_KIND_FEED, DEMILL_KIND_OUTLET,
                                DEMILL_KIND_BODY, DEMILL_KIND_NONE, 8, -1};
static const int32_t fz_closed[] = {0, 1, 2, -1};
static const int32_t fz_caps[] = {DEMILL_CAPS_NONE, DEMILL_CAPS_START, DEMILL_CAPS_END,
                               DEMILL_CAPS_BOTH, 4, -1};
static const int32_t fz_harmonic_modes[] = {DEMILL_HARMONIC_TRANSLATION, DEMILL_HARMONIC_ROTATION,
                                         0, 3, -1};
static const int32_t fz_drum_parts[] = {DEMILL_DRUM_PART_SHELL, DEMILL_DRUM_PART_CAPS,
                                     DEMILL_DRUM_PART_LIFTERS, 0, 4, -1};
static const int32_t fz_regions[] = {DEMILL_REGION_BOX, DEMILL_REGION_CYLINDER,
                                  DEMILL_REGION_HALF_SPACE, DEMILL_REGION_DRUM, 0, 5, -1};
static const int32_t fz_body_flags[] = {0, DEMILL_BODY_NO_GRAVITY, 2, INT32_MIN};
static const int32_t fz_body_axes[] = {DEMILL_BODY_AXIS_X, DEMILL_BODY_AXIS_Y, DEMILL_BODY_AXIS_Z,
                                    0, 3, 8, -1};
static const int32_t fz_body_fields[] = {
    DEMILL_BODY_POSITION, DEMILL_BODY_VELOCITY, DEMILL_BODY_FORCE_PARTICLES,
    DEMILL_BODY_FORCE_SPRING, DEMILL_BODY_FORCE_DAMPER, DEMILL_BODY_FORCE_EXTERNAL, 0, 7, -1};
static const int32_t fz_body_terms[] = {
    DEMILL_ENERGY_BODY_KINETIC, DEMILL_ENERGY_BODY_ELASTIC, DEMILL_ENERGY_BODY_POTENTIAL,
    DEMILL_ENERGY_BODY_DISSIPATED, DEMILL_ENERGY_BODY_WORK, DEMILL_ENERGY_KINETIC_TRANSLATIONAL,
    DEMILL_ENERGY_TOTAL, 19, -1};
static const int32_t fz_dimensions[] = {2, 3, 0, 1, 4, -1, INT32_MAX, INT32_MIN};

#endif
