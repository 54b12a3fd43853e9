/* state.h: the world's state, the data every module above the base reads
 * and writes: struct demill_world and the structs it is made of, each
 * marked with the module that owns it. Types only, and the functions of the
 * state module itself (the particle store, lib/physics/state/particles.c);
 * each module's functions are declared in its own header. Nothing here is
 * visible to users; internal symbols are prefixed dm_. */
#ifndef DM_STATE_H
#define DM_STATE_H

#include "base/base.h"
#include <math.h>

#include "base/handles.h"
#include "base/random.h"

#define DM_MAX_MATERIALS 256

/* ---- materials and pairs (the world's API; resolved by contact/pairs.c) ---- */
typedef struct dm_material {
    double density, youngs, poisson, stiffness, restitution, friction, rolling_friction;
    double yield_stress; /* 0: does not yield */
    double local_damping; /* α of local damping (integrate/integrate.c) */
    double rigid; /* DEMILL_MATERIAL_RIGID: 1 rigid, 0 deformable */
    double surface_energy; /* DEMILL_MATERIAL_SURFACE_ENERGY, J/m² */
} dm_material;

/* Derived pair keys the user may override; bit i of dm_pair_user.set. */
enum {
    DM_PK_RESTITUTION, DM_PK_FRICTION, DM_PK_ROLLING_FRICTION, DM_PK_NORMAL_STIFFNESS,
    DM_PK_VISCOUS, DM_PK_KT_RATIO, DM_PK_CT_FACTOR, DM_PK_COULOMB_REG, DM_PK_ROLLING_REG,
    DM_PK_CLAMP, DM_PK_YIELD_PRESSURE, DM_PK_FIT_C0, DM_PK_FIT_C1, DM_PK_FIT_C2, DM_PK_FIT_H,
    DM_PK_ROLLING_STIFFNESS, DM_PK_ROLLING_DAMPING,
    /* cohesion's */
    DM_PK_ADHESION_WORK, DM_PK_LIQUID_VOLUME, DM_PK_SURFACE_TENSION, DM_PK_CONTACT_ANGLE,
    DM_PK_COUNT
};
/* The keys checkpoints of formats 1 to 3 hold (4 says how many it holds). */
#define DM_PK_COUNT_V2 10

/* What the user chose for one material pair (a <= b). */
typedef struct dm_pair_user {
    uint32_t a, b;
    int32_t normal, damping, tangential, rolling, cohesion;
    double value[DM_PK_COUNT];
    uint32_t set; /* bit mask of DM_PK_* overridden */
} dm_pair_user;

/* The five laws of a contact model, and the kernel they compile to. */
typedef struct dm_laws {
    int normal, damping, tangential, rolling, cohesion;
} dm_laws;

/* The number of choices of each law (DEMILL_NORMAL_* ... DEMILL_COHESION_*,
 * demill/material.h), none included. */
#define DM_NORMAL_LAWS 6
#define DM_DAMPING_LAWS 3
#define DM_TANGENTIAL_LAWS 4
#define DM_ROLLING_LAWS 3
#define DM_COHESION_LAWS 3
/* Kernels: the fast ones, one compiled kernel per combination of the linear
 * or Hertz normal law, any damping and tangential law, no or constant-torque
 * rolling resistance and no cohesion (kernel indices 0 .. DM_FAST_KERNELS - 1,
 * which checkpoints keep); then every combination of every law (the
 * extended kernels, served by one generic kernel per dimension: see
 * contact/kernels.h). */
#define DM_FAST_KERNELS (2 * DM_DAMPING_LAWS * DM_TANGENTIAL_LAWS * 2)
#define DM_KERNELS                                                                                \
    (DM_FAST_KERNELS + (DM_NORMAL_LAWS - 1) * DM_DAMPING_LAWS * DM_TANGENTIAL_LAWS *              \
                           DM_ROLLING_LAWS * DM_COHESION_LAWS)
#define DM_MAX_HIST 16 /* history doubles per contact, at most (contact/law.h + event slot) */
/* Resolved constants of one material pair, read by the contact kernels. */
typedef struct dm_pairparam {
    int kernel;          /* -1: no model */
    int clamp;           /* 1: F_n >= 0 */
    double kn;           /* linear normal stiffness */
    double e_star;       /* E* (Hertz), 4/3 E* √R* δ^{3/2} */
    double g8;           /* 8 G* (Mindlin) */
    double cn;           /* viscous damping coefficient */
    double dcoef;        /* restitution damping: 2ξ (linear) or 2√(5/6)ξ (Hertz) */
    double kt;           /* linear tangential stiffness */
    double ct_factor;
    double mu, mu_r;
    double coul_reg, roll_reg; /* regularisation factors */
    double restitution, xi;
    double py;           /* limiting contact pressure of the plastic laws (∞: no yield) */
    double fit[4];       /* the multi-path law's c0, c1, c2 and H (contact/plastic.h) */
    double kr;           /* rolling spring's stiffness (0: 2.25 S μ_r² R*² per contact) */
    double eta_r;        /* rolling dashpot's damping ratio */
    /* cohesion (contact/cohesion.h): JKR's work of adhesion; the liquid
     * bridge's surface tension, contact angle and volume */
    double adhesion, surface_tension, contact_angle, liquid_volume;
} dm_pairparam;

/* ---- walls (geometry/walls.c) ------------------------------------------- */
/* A node of a mesh's bounding-volume hierarchy: the box of its elements; an
 * inner node's children are nodes first and first + 1, a leaf's elements
 * order[first .. first + count - 1]. */
typedef struct dm_bvh_node {
    double lo[3], hi[3];
    uint32_t first, count; /* count 0: an inner node */
} dm_bvh_node;

/* A triangle mesh (3D) or a polyline (2D) wall (geometry/mesh.c): elements
 * (triangles or segments) in the mesh's own frame, which frame_rot and
 * frame_off place in the wall's reference frame (X = frame_rot V + frame_off),
 * with what the contact rule needs: unit normals, the edges (triangles) and
 * the elements incident to each edge and vertex (CSR, in increasing element
 * order, so the first is the owner), and an AABB tree over the elements. */
typedef struct dm_trimesh {
    size_t bytes;           /* the one block holding the mesh and its arrays */
    int nel;                /* vertices per element: 3 (triangles) or 2 (segments) */
    uint32_t nv, nt, ne;    /* vertices, elements, edges (triangles only) */
    double *v;              /* 3 per vertex */
    uint32_t *el;           /* nel vertex indices per element */
    double *nrm;            /* 3 per element: unit normal (right hand; 2D: (e_y, -e_x)/|e|) */
    uint32_t *el_edge;      /* 3 per triangle: its edge from vertex k to k + 1 */
    uint32_t *edge_start, *edge_el; /* ne + 1, and the triangles incident to each edge */
    uint32_t *vert_start, *vert_el; /* nv + 1, and the elements incident to each vertex */
    dm_bvh_node *node;      /* the tree, node 0 its root */
    uint32_t nnodes;
    uint32_t *order;        /* elements in leaf order */
    double frame_rot[9], frame_off[3];
    double bs_centre[3], bs_radius; /* a sphere about every vertex, in the mesh's frame */
    /* a grid of cubes of side far_h over a box about the mesh, from corner
     * far_lo, with far_n cubes per axis (x fastest): per cube a lower bound
     * of the distance from its points to the mesh */
    float *far;
    uint32_t far_n[3];
    double far_lo[3], far_h;
} dm_trimesh;

#define DM_MAX_POLY 8 /* vertices of a lifter's cross-section, at most */

/* The loads a wall records (demill_wall_loads_start(); geometry/loads.c,
 * summed by contact/forces.c), per element: a mesh's triangle or a
 * polyline's segment, or the whole wall as one patch (with its caps). */
typedef struct dm_loads {
    uint32_t n;         /* elements */
    double interval;    /* time recorded since the reset, s */
    double steps;       /* steps recorded since the reset (a whole number) */
    double v[];         /* DM_LOADS per element: the normal force (N) at the step
                           numbered by the fourth (0 at any other step, so that a step
                           touches only the elements in contact), its time integral
                           (N s) and the shear work (J) since the reset */
} dm_loads;
#define DM_LOADS 4

typedef struct dm_wall {
    uint32_t handle;       /* handle index (DM_FREE for the drum's walls) */
    uint32_t material;     /* material slot */
    int kind;              /* DM_WALL_*, 0 for a free slot */
    int drum_part;         /* DM_PART_*: which part of the drum, or DM_PART_NONE */
    int lifter;            /* lifter index for DM_PART_LIFTER */
    double radius;         /* DM_WALL_SHELL: inner radius */
    int npoly;             /* DM_WALL_PRISM: convex cross-section, counter-clockwise, */
    double poly[2 * DM_MAX_POLY];  /* in the drum frame (at drum angle 0) */
    double cpoly[2 * DM_MAX_POLY]; /* and at the current angle, with per edge k (from */
    double cedge[4 * DM_MAX_POLY]; /* vertex k to k + 1) its outward unit normal and */
                                   /* its vector over its squared length */
    double bc0[2], bc[2], brad;    /* circle about the section: centre in the drum
                                      frame, at the current angle, radius */
    double reach;          /* largest distance of the wall's surface from its centre of
                              rotation that can move (0: the rotation does not move it) */
    /* reference geometry at time t0 and motion */
    double p0[3], n0[3], c0[3];
    double vel[3], omega[3];
    double t0;
    /* current geometry (at world time) */
    double p[3], n[3], c[3];
    double rot[9];         /* rotation since t0 */
    /* geometry at the last neighbour build, for the skin criterion */
    double c_build[3], rot_build[9];
    /* results of the last force evaluation */
    double force[3], torque[3];
    double dissipated;     /* energy dissipated in contacts with the wall (tally) */
    /* a wall attached to a body (bodies/bodies.c) moves with it: its pose is
     * its reference (p0, n0, c0) shifted by the body's motion since body_ref */
    uint32_t body;         /* body slot + 1; 0: not attached */
    double body_ref[3];    /* the body's position when the wall was attached */
    dm_trimesh *mesh;      /* DM_WALL_MESH: its mesh (owned), else NULL */
    /* finite walls (DM_WALL_REVOLVED, DM_WALL_RECT), thin surfaces given in
     * the reference frame about the point p0 and the unit axis or normal n0 */
    double seg[4];         /* REVOLVED: the meridian segment turned about the axis,
                              from (rho, h) = (seg[0], seg[1]) to (seg[2], seg[3]);
                              RECT: half-widths along e0 and along n0 × e0 */
    double nb[4];          /* REVOLVED: at each end, the direction (rho, h) in which
                              the face sharing it (a cap) leaves it; 0 0: none */
    int own;               /* REVOLVED: bit k: end k is a rim of this face */
    double e0[3];          /* RECT: unit in-plane direction, reference frame */
    double bh;             /* bounding sphere: centre p + bh n, radius brad */
    uint32_t parent;       /* a cap: slot + 1 of the wall it closes; 0: none */
    uint32_t parts[2];     /* slots + 1 of its caps; 0: none */
    /* harmonic motion (replaces the rigid motion while set) and surface velocity */
    int harmonic;          /* DM_HARMONIC_*, 0: the rigid motion of vel and omega */
    double h_axis[3], h_amp, h_freq, h_phase, h_t0;
    int surface;           /* 1: surf0 is set */
    double surf0[3];       /* surface velocity, reference frame */
    dm_loads *loads;       /* the loads it records (owned), NULL: none */
} dm_wall;

/* Wall kinds: a plane (half-space), the inside of a cylindrical shell about
 * the z axis, a prism along z with a convex polygonal cross-section, a
 * triangle mesh (3D) or polyline (2D), a thin surface touched from both
 * sides; the finite walls, thin surfaces too: the surface swept by a segment
 * turned about an axis (finite cylinder, cone, disc, annulus, cap), a
 * rectangle. */
enum {
    DM_WALL_PLANE = 1, DM_WALL_SHELL = 2, DM_WALL_PRISM = 3, DM_WALL_MESH = 4,
    DM_WALL_REVOLVED = 5, DM_WALL_RECT = 6
};
/* Harmonic motions: the centre moves along h_axis, or the wall turns about it. */
enum { DM_HARMONIC_TRANSLATE = 1, DM_HARMONIC_ROTATE = 2 };
/* The drum's parts, numbered as DEMILL_DRUM_PART_* */
enum { DM_PART_NONE = 0, DM_PART_SHELL = 1, DM_PART_CAP = 2, DM_PART_LIFTER = 3 };
/* Whether a wall of the drum is one a user attached to it (it keeps its own
 * handle, demill_drum_attach_wall), or a cap of one, rather than one the
 * drum built. */
static inline bool dm_wall_attached(const dm_wall *wall)
{
    return wall->drum_part && (wall->handle != DM_FREE || wall->parent);
}

/* ---- bodies (bodies/bodies.c) -------------------------------------------- */
/* A rigid body moved by the particles on its walls, springs and dampers to
 * the ground per axis, gravity and an external force F0 sin(2π f t + φ);
 * it translates along its free axes (bit a: axis a), without rotation. */
typedef struct dm_body {
    uint32_t handle;       /* handle index; DM_FREE for a free slot */
    int free_axes;         /* bit mask of the axes it moves along */
    int gravity;           /* 1: gravity acts on it */
    double mass;
    double x[3], v[3];     /* position of its centre and velocity */
    double vp[3];          /* the velocity its walls show the contacts (velocity
                              Verlet: the predicted end-of-step velocity) */
    double k[3], c[3], rest[3]; /* per axis: spring stiffness, damping, rest position */
    double f0[3], freq, phase;  /* external force: amplitude, frequency, phase */
    /* energy tallies: the position and the external and damper forces at the
     * last force evaluation (trapezoidal rule), the external force's work and
     * the dampers' dissipation since the body was added */
    double x_tally[3], fe_tally[3], fd_tally[3];
    double work, dissipated;
} dm_body;

/* ---- clumps (clumps/clumps.c) ------------------------------------------- */
/* A clump template: a rigid shape of n spheres (discs in 2D) of one
 * material, kept in its principal frame: member k's offset from the centre
 * of mass along the principal axes and its radius are tmem[4 (first + k)
 * .. + 3]. 2D: the frame is the input's, shifted to the centre of mass
 * (a 2D world turns only about z). */
typedef struct dm_template {
    uint32_t material, n, first;
    double mass, im;        /* mass and its inverse, 1/M */
    double volume;          /* mass / density */
    double inertia[3];      /* principal moments, increasing (2D: 0, 0, I_z) */
    double axes[9];         /* the principal axes in the input frame, one per row */
    double centre[3];       /* the centre of mass in the input frame */
    /* made from a mesh: its volume, the fit's largest deviations out and in
     * and the grid's cube side (all 0 for a template made from spheres) */
    double mesh_volume, deviation_out, deviation_in, cell;
    double rpow;            /* the sum of the spheres' r³ (2D: r²), for dm_particle_share() */
} dm_template;
#define DM_TMEM 4 /* doubles per template member: body-frame offset (3), radius */

/* A clump: a rigid body whose members are particles that follow it. Its
 * members' particle handles are cmem[first .. first + n - 1], n its
 * template's. */
typedef struct dm_clump {
    uint32_t handle;        /* handle index; DM_FREE for a free slot */
    uint32_t tmpl, first;
    double x[3], v[3];      /* centre of mass and its velocity */
    double q[4];            /* orientation (w, x, y, z): body frame to world */
    double theta;           /* 2D: the angle about z (q follows it) */
    double L[3];            /* angular momentum about the centre of mass, world frame
                               (2D: L[2]) */
    double om[3];           /* angular velocity, world frame */
    double vp[3], wp[3];    /* the velocities the dashpots see (velocity Verlet: the
                               predicted end-of-step ones) */
} dm_clump;

/* ---- particles (state/particles.c) ------------------------------------- */
/* Structure of arrays in storage order (sorted by cell at each neighbour
 * build). Vectors have D = dim components, angular ones W = 1 (2D) or 3. */
typedef struct dm_particles {
    uint32_t n, cap;
    double *x, *v, *f, *x0;  /* D per particle; x0: position at the last build */
    double *vp;              /* D: predicted end-of-step velocity (velocity Verlet) */
    double *w, *t, *wp;      /* W per particle: angular velocity, torque, predicted ω */
    double *theta;           /* 2D rotation angle */
    double *q[4];            /* 3D orientation, body to world frame: a unit quaternion
                              * as four arrays w, x, y, z (none in 2D), which the
                              * integrators' loops turn many at once */
    double *r, *m, *im, *iinv; /* radius, mass, 1/m, 1/I (both 0: a fixed particle) */
    uint16_t *mat;           /* material slot */
    uint32_t *hid;           /* handle index */
    uint32_t *clump;         /* the clump slot + 1 of a clump's member, 0: a free particle */
} dm_particles;

/* ---- contact lists (contact/lists.c; filled by broadphase/nlist.c) ------ */
/* Pairs (i < j in storage order) within the skin, grouped by kernel. */
typedef struct dm_bucket {
    int kernel;
    int hs;                  /* history doubles per pair */
    uint32_t n, cap;
    uint32_t *i, *j;         /* for walls: i = particle, j = wall slot */
    uint32_t *t;             /* walls only (NULL for particle pairs): the mesh element, 0
                                for other walls */
    double *hist;            /* zeros unless on */
    uint8_t *on;             /* 1: touching at the last step */
    uint32_t base;           /* pair id of the first pair (see dm_results) */
    uint32_t chunk0;         /* index of its first chunk */
    uint32_t span;           /* largest j - i of its particle pairs */
} dm_bucket;

typedef struct dm_clist {
    dm_bucket b[DM_KERNELS];
} dm_clist;

/* Scratch of the neighbour build, kept between builds so that a build
 * allocates only when the world has grown. */
/* The pairs one range of the neighbour search found, in the order found;
 * k is the kernel, plus DM_KERNELS for particle-wall pairs. */
typedef struct dm_pairbuf {
    uint32_t *i, *j, *t;               /* t: the mesh element of a particle-wall pair */
    uint16_t *k;
    uint32_t n, cap;
    bool failed;                       /* out of memory */
    uint32_t next[2 * DM_KERNELS];     /* count per kernel, then where the next goes */
    uint32_t *walls, wcap;             /* the walls a block of particles may reach */
} dm_pairbuf;

typedef struct dm_grid {
    uint32_t *cell_start;     /* ncells + 1 */
    size_t cap_cells;
    uint32_t *cell_of, *order, *inv, *row; /* per particle (row: n + 1) */
    uint32_t cap;
    double *scratch;          /* 4 doubles per particle */
    /* contacts whose history is carried over a build */
    uint32_t *ci, *cj, *ct;   /* ct: mesh element (particle-wall), else 0 */
    uint16_t *ck;             /* kernel (pp) or kernel + DM_KERNELS (pw) */
    double *ch;               /* their histories one after the other, room for DM_MAX_HIST
                                 doubles each */
    uint8_t chs[2 * DM_KERNELS]; /* the history size of each kernel's contacts in ch */
    uint32_t nc, ccap;
    double lo[3], hi[3];      /* particle bounding box at the last build */
    struct dm_pairbuf *pb;    /* pairs found by each range of the search */
    int npb;
} dm_grid;

/* Geometry of the particle-wall candidates for the law kernels. */
typedef struct dm_wgeom {
    uint32_t cap;
    double *nrm;   /* D: unit normal from particle into the wall */
    double *delta; /* overlap (<= 0: no contact) */
    double *vw;    /* D: wall velocity at the contact point */
    double *cp;    /* D: contact point */
    double *lost;  /* energy dissipated in the contact over the step (tally) */
} dm_wgeom;

/* Energy tallies: dissipation by mechanism and work done by walls. */
typedef struct dm_tally {
    double diss_normal, diss_tangential, diss_friction, diss_rolling, wall_work;
    /* the extended laws' (docs/physics.md): plastic work, the rolling
     * dashpot's, and the work done against cohesive forces */
    double diss_plastic, diss_rolling_viscous, work_cohesion;
    double diss_local; /* local damping's, booked by the integrator */
} dm_tally;

/* The energy a tally's contacts dissipated, every mechanism summed. */
static inline double dm_tally_dissipated(const dm_tally *t)
{
    return t->diss_normal + t->diss_tangential + t->diss_friction + t->diss_rolling +
           t->diss_plastic + t->diss_rolling_viscous + t->diss_local;
}

/* A chunk of candidates that one kernel call works through (forces.c). */
typedef struct dm_chunkref {
    uint32_t k0;     /* first candidate */
    uint16_t kernel; /* bucket */
    uint16_t walls;  /* 1: of the particle-wall lists */
    uint32_t i0;     /* particle of the first candidate: the range that runs it */
    uint32_t lo, hi; /* the least dm_results.lo and the last particle of its pairs */
} dm_chunkref;

/* The results of a force evaluation per pair, and what sums them. Pair ids
 * number the particle-particle buckets in kernel order, then the
 * particle-wall ones. Every particle's sum is taken in pair-id order, so
 * that no sum depends on how the work was shared among threads
 * (forces.c): by the chunks as they go for the particles all of whose
 * pairs are in chunks of the particle's own range; for the others, the
 * kernels store each pair's force and torques by pair id and list it, and
 * the range sums them afterwards. */
typedef struct dm_results {
    uint32_t n, npp, cap;   /* pairs, of them particle-particle, room */
    double *out;            /* S = D + 2W per pair: force on b, torques on a and on b */
    uint32_t *list;         /* per chunk, from its first pair's id: its pairs with a
                               result in out (indices in the bucket): those that came
                               apart, then those touching, each in bucket order; of
                               particle pairs, only those not summed as they went */
    dm_chunkref *chunks;    /* in pair-id order */
    dm_tally *chunk_tally;  /* per chunk: dissipation, */
    uint32_t *chunk_contacts; /* pairs in contact, */
    uint32_t *chunk_listed;   /* and pairs in its list */
    uint32_t nchunks, cap_chunks;
    uint32_t *lo;           /* per particle: the first particle (i0) of the first chunk
                               with one of its pairs; a range [begin, end) runs every
                               chunk of particle p < end if lo[p] >= begin (forces.c) */
    uint32_t cap_particles;
    bool valid;             /* matches the lists */
    bool reach_valid;       /* lo and the chunks' lo, hi match them too */
    int pending;            /* the ranges whose sums dm_forces() left to its caller,
                               or 0 (contact.h, DM_FORCES_DEFER) */
} dm_results;

/* ---- the mill (mill/drum.c; its spectrum counted by contact/spectrum.c) --- */
#define DM_MAX_LIFTERS 64
#define DM_SHAPE_BINS 72 /* 5° bins of the charge-shape analysis */

typedef struct dm_lifter_spec {
    double angle, height, width, face;
} dm_lifter_spec;

/* Per-revolution accumulators; when a revolution completes they become the
 * reported means. */
typedef struct dm_drum_rev {
    double t0, energy_in, power_cm_sum, dissipated0;
    uint32_t power_cm_count;
    double shape_sum[3];
    uint32_t shape_count[3];
    double lifter_impulse[DM_MAX_LIFTERS][3];
} dm_drum_rev;

typedef struct dm_spectrum {
    uint32_t nclasses, nbins;
    double *edges;          /* nclasses - 1 increasing diameters */
    double log_min, log_span;
    uint64_t *counts;       /* rows × nbins, then the ore's impacts */
    /* The impacts on particles of one ore material (demill_drum_impacts_start):
     * ore_classes × ore_bins counters after the collisions' in counts. */
    uint32_t ore;           /* the ore's material slot + 1; 0: not recorded */
    uint32_t ore_classes, ore_bins;
    double ore_top;         /* √2 size classes below this diameter, m */
    double ore_log_min, ore_log_span; /* log10 of the bins' range, J/kg */
    double ore_t0;          /* the world's time when the recording started */
} dm_spectrum;

typedef struct dm_drum {
    bool alive;
    uint32_t material[3];   /* material slot of each part: shell, caps, lifters
                               (index DM_PART_* - 1) */
    double diameter, length, porosity;
    bool shell;             /* the analytic shell and caps (DEMILL_DRUM_SHELL) */
    /* the evenly spaced lifters, and the lifters in use */
    uint32_t even_count;
    double lifter_h, lifter_w, lifter_face, lifter_phase;
    uint32_t nlifters;
    dm_lifter_spec lifters[DM_MAX_LIFTERS];
    /* walls: shell, caps (3D), lifters, in wall slots */
    uint32_t wall_slot[DM_MAX_LIFTERS + 3];
    uint32_t nwall;
    /* speed: a target given as rad/s, rpm or fraction of critical, reached
     * linearly over ramp from the speed at t_set */
    int speed_key;
    double speed_value, ramp, crit_diameter;
    double t_set, theta_set, omega_from, omega_to;
    double theta, omega;    /* at world time */
    /* translation: the centre at time t is centre_set + velocity (t - t_move)
     * + vib_amp sin(2π vib_freq (t - t_move) + vib_phase) */
    double centre_set[3], velocity[3], vib_amp[3], vib_freq, vib_phase, t_move;
    double centre[3], vcentre[3]; /* the centre and its velocity at world time */
    double theta_start;     /* angle when it first turned; NaN before */
    uint32_t sample_interval;
    uint64_t samples_due;   /* step count at the next charge-shape sample */
    /* measurements of the last force evaluation and running totals */
    double torque, power, energy_in, energy_dissipated;
    double lifter_peak[DM_MAX_LIFTERS], lifter_energy[DM_MAX_LIFTERS];
    /* the last completed revolution */
    uint64_t revolutions;
    double mean_power, mean_power_cm, mean_dissipation, mean_shape[3];
    double lifter_force_mean[DM_MAX_LIFTERS][3];
    dm_drum_rev rev;
    dm_spectrum spectrum;
} dm_drum;

/* ---- iterative refinement (integrate/refine.c) ---------------------------- */
/* The state at the start of a step, which every iterate predicts from, and
 * the contact state that each further iterate starts from again. The
 * particle arrays trade places with the world's (no copies): during a step
 * xn, vn, fn, wn, tn, thn hold the start of the step and fprev, tprev the
 * previous iterate's forces and torques. */
typedef struct dm_refine {
    uint32_t cap;                  /* particles the arrays hold */
    double *xn, *vn, *fn, *fprev;  /* D per particle */
    double *wn, *tn, *tprev;       /* W per particle */
    double *thn;                   /* 2D angle */
    double *qn[4];                 /* 3D orientation (w, x, y, z) */
    double *hist;                  /* every bucket's history, bucket after bucket */
    uint8_t *on;                   /* and touch flags */
    size_t cap_hist, cap_on;
    double *wall_diss;             /* walls' dissipation tallies */
    uint32_t cap_walls;
    uint64_t *spectrum;            /* collision-spectrum counters */
    size_t cap_spectrum;
    dm_tally tally;
} dm_refine;

/* ---- the watchdog (the world layer's: world/watchdog.c) ---------------------- */
/* Energies of a state: kinetic, potential, elastic, dissipated (tallied) and
 * the work walls did so far (tallied, or the drum's measured). */
typedef struct dm_watch_energy {
    double kinetic, potential, elastic, dissipated, work;
} dm_watch_energy;

typedef struct dm_watch {
    struct demill_world *good; /* the last state that passed, NULL until taken */
    uint64_t edits;            /* the world's edits when it was taken */
    uint64_t call_start;       /* the step count when the current call started */
    uint64_t stepped;          /* the world's edits + 1 when the time step was last found
                                  within every pair's stability limit (0: never) */
    uint32_t countdown;        /* steps to the next check */
    dm_watch_energy start, last; /* at the start of the run and at the last check */
    double peak, pmin, pmax;     /* since the start: largest kinetic + elastic energy,
                                    smallest and largest potential energy */
} dm_watch;

/* ---- progress reporting (the world layer's: world/progress.c) ---------------- */
/* The host's callback (demill_world_set_progress). Not part of the simulated
 * state: a copy of the state (dm_state_copy) leaves the destination's. */
typedef struct dm_progress {
    demill_progress_fn fn;  /* NULL: none */
    void *user;
    uint64_t every;         /* steps between reports */
} dm_progress;

/* ---- regions, feeds and outlets (the world layer's: world/region.c, world/flows.c) ---- */
#define DM_SIZE_CLASSES 32   /* size classes of a distribution, at most */
#define DM_MAX_FEEDS 16
#define DM_MAX_OUTLETS 16
#define DM_OUTLET_CLASSES 32 /* size classes an outlet counts, at most */

/* A region of space (DEMILL_REGION_*) and its parameters as the API gave them. */
typedef struct dm_region {
    int kind;
    double p[7];
} dm_region;

/* A size distribution as classes: diameters in [lo, hi] (log-uniform within
 * a class; lo = hi for a discrete size) and mass fractions summing to 1. */
typedef struct dm_sizes {
    uint32_t n;
    double lo[DM_SIZE_CLASSES], hi[DM_SIZE_CLASSES], fraction[DM_SIZE_CLASSES];
} dm_sizes;

/* The slot of a feed or an outlet: alive, and the generation of its id
 * (DM_GEN_LAST: retired). */
typedef struct dm_flow_slot {
    bool alive;
    uint16_t gen;
} dm_flow_slot;

/* A feed: particles of one material inserted into a region at a mass rate. */
typedef struct dm_feed {
    dm_flow_slot id;
    uint32_t material;
    dm_region region;
    dm_sizes sizes;
    double number[DM_SIZE_CLASSES]; /* cumulative number fractions of the classes */
    double rate, vel[3], t_start, t_stop;
    dm_rng rng;             /* sizes and positions */
    double next_d;          /* diameter of the next particle to insert */
    double mass;            /* inserted so far, kg */
    uint64_t count;
} dm_feed;

/* An outlet: particles whose centre is in its region are removed at the end
 * of a step and counted per size class. */
typedef struct dm_outlet {
    dm_flow_slot id;
    dm_region region;
    uint32_t nedges;        /* classes: nedges + 1 */
    double edges[DM_OUTLET_CLASSES - 1];
    uint64_t count[DM_OUTLET_CLASSES];
    double mass[DM_OUTLET_CLASSES];
    double interval;        /* of the rate, s */
    double t_next;          /* the end of the current interval */
    double interval_mass, last_mass; /* removed in the current and the last interval */
    uint64_t interval_count, last_count;
} dm_outlet;

typedef struct dm_flows {
    uint32_t nfeeds, noutlets; /* slots in use or retired: the ids' indices */
    uint32_t live;             /* feeds and outlets alive */
    dm_feed feeds[DM_MAX_FEEDS];
    dm_outlet outlets[DM_MAX_OUTLETS];
    double energy;          /* kinetic and potential energy brought in by feeds less
                               what outlets took out, J */
} dm_flows;

/* ---- the world ------------------------------------------------------------- */
struct demill_world {
    dm_base base;           /* first: the base layer's part (lib/base/base.h) */
    uint16_t tag;
    int dim;
    double dt, time, g[3];
    uint64_t rebuilds;
    int integrator;
    double skin_fraction;
    double disc_thickness;
    int energy_tracking;
    double refine_tol;      /* iterative refinement: ε_a */
    int refine_max;         /* and force evaluations per step at most */
    uint32_t iterations_last;     /* force evaluations of the last step */
    uint64_t force_evals, unconverged;
    dm_refine refine;
    int watchdog;           /* world.watchdog, and its limits */
    double watch_overlap;
    uint32_t watch_interval;
    dm_watch watch;
    dm_progress progress;

    /* materials */
    dm_material mats[DM_MAX_MATERIALS];
    uint32_t nmat;
    uint32_t mat_particles[DM_MAX_MATERIALS]; /* particles per material */
    uint32_t mat_walls[DM_MAX_MATERIALS];     /* walls per material */
    dm_pair_user *pairs;
    uint32_t npairs, cap_pairs;
    dm_pairparam *ptab;      /* nmat_tab × nmat_tab, resolved */
    uint32_t nmat_tab;
    bool ptab_dirty;
    bool rotation;           /* some law in use needs rotational DOF */
    int nkern;               /* 1 + the largest kernel in the pair table: buckets past it
                                are empty, and loops over buckets stop there */
    double cohesion_reach;   /* how far past touching a cohesive pair may still
                                interact: the neighbour search reaches that far more */
    bool generic_kernels;    /* tests only: every combination runs the generic kernel */
    bool single;             /* DEMILL_WORLD_SINGLE_PRECISION: the fast kernels in float */
    bool orient;             /* DEMILL_WORLD_ORIENTATION_TRACKING: the steps turn the
                                free particles' orientations */
    bool local_damping;      /* some particle's material has local damping */

    /* particles */
    dm_particles p;
    dm_handles ph;

    /* walls */
    dm_wall *walls;
    uint32_t nwalls, cap_walls;
    dm_handles wh;

    /* bodies moved by the particles */
    dm_body *bodies;
    uint32_t nbodies, cap_bodies; /* slots in use (some may be free), room */
    dm_handles bh;

    /* clump templates (never removed: ids by index, as materials) and clumps */
    dm_template *templates;
    uint32_t ntemplates, cap_templates;
    double *tmem;            /* DM_TMEM doubles per member of every template */
    uint32_t ntmem, cap_tmem;
    dm_clump *clumps;
    uint32_t nclumps, cap_clumps; /* slots in use (some may be free), room */
    uint32_t live_clumps;
    uint32_t *cmem;          /* the members' particle handles of every clump */
    uint32_t ncmem, cap_cmem;
    dm_handles clh;

    /* the mill drum (at most one) */
    dm_drum drum;
    uint16_t drum_gen;      /* generation of the drum id: drums removed so far
                               (DM_GEN_LAST: no further drum can be made) */

    /* contacts */
    dm_clist pp, pw;
    dm_results res;
    dm_wgeom wg;
    dm_grid grid;
    bool nlist_valid;        /* pair lists match the particles and walls */
    bool forces_valid;       /* f, t hold the forces of the current state */
    double skin;             /* absolute skin of the current lists */
    uint32_t ncontacts, nwall_contacts;

    dm_tally tally;
    bool events;            /* contacts keep their dissipated energy (spectrum) */

    dm_flows flows;         /* feeds and outlets */
};

/* |g| */
static inline double dm_gravity_magnitude(const demill_world *w)
{
    return sqrt(w->g[0] * w->g[0] + w->g[1] * w->g[1] + w->g[2] * w->g[2]);
}

/* Components of an angular quantity: 1 in 2D, 3 in 3D. */
static inline int dm_wdim(const demill_world *w)
{
    return w->dim == 3 ? 3 : 1;
}

/* Components of an orientation: 4 in 3D (a quaternion), 0 in 2D (the angle
 * theta stands for it). */
static inline int dm_qdim(const demill_world *w)
{
    return w->dim == 3 ? 4 : 0;
}

/* Particle i's orientation (3D) into q (w, x, y, z), and from q. */
static inline void dm_quat_get(double *const qa[4], uint32_t i, double q[4])
{
    for (int c = 0; c < 4; c++)
        q[c] = qa[c][i];
}

static inline void dm_quat_put(double *const qa[4], uint32_t i, const double q[4])
{
    for (int c = 0; c < 4; c++)
        qa[c][i] = q[c];
}

/* ---- the particle store (particles.c) ----------------------------------------- */
/* Grows every particle array to hold `need` particles (0; -1 when out of
 * memory, the arrays keeping their contents). */
int dm_particles_reserve(demill_world *w, uint32_t need);
/* Reorders every per-particle array by order (new index k holds old order[k])
 * and updates the handles. */
void dm_particles_permute(demill_world *w, const uint32_t *order);
void dm_particles_free(demill_world *w);
/* The mass and the inverse moment of inertia of a particle of material mat
 * and radius r (a sphere, or in 2D a disc of the world's thickness). */
void dm_particle_mass(const demill_world *w, uint32_t mat, double r, double *m, double *inv_i);
/* Sets particle i's mass from its material and radius, and its inverse mass
 * and moment of inertia: 0 for a fixed particle, which no force moves. */
void dm_particle_set_mass(demill_world *w, uint32_t i, bool fixed);
/* Whether particle i is fixed (its inverse mass is 0). */
static inline bool dm_particle_fixed(const dm_particles *P, uint32_t i)
{
    return P->im[i] == 0.0;
}

/* r³ in 3D, r² in 2D: what a clump member's share of its clump's mass goes
 * by. */
static inline double dm_radius_power(const demill_world *w, double r)
{
    return w->dim == 3 ? r * r * r : r * r;
}

/* Particle i's own part of the charge's mass: a free particle's mass; a
 * clump's member carries its clump's whole mass M in P->m (the m* of its
 * contacts), and owns M r_i³ / Σ r_k³ of it (2D: r², the sum over its
 * template's spheres), so that a clump's members add up to M and a clump of
 * one sphere owns M. For a mass that is a share of the charge (its centre
 * of mass and shape, the settling's kinetic energy, the ore's energy per
 * unit mass), not for a contact's inertia. */
static inline double dm_particle_share(const demill_world *w, uint32_t i)
{
    const dm_particles *P = &w->p;
    if (!P->clump[i])
        return P->m[i];
    const dm_template *t = &w->templates[w->clumps[P->clump[i] - 1].tmpl];
    return P->m[i] * (dm_radius_power(w, P->r[i]) / t->rpow);
}

/* Sets template t's rpow from its spheres in tmem (their radii at
 * DM_TMEM k + 3), those of them that lie within tmem. */
static inline void dm_template_set_rpow(const demill_world *w, dm_template *t)
{
    t->rpow = 0.0;
    for (uint64_t m = t->first; m < (uint64_t)t->first + t->n && m < w->ntmem; m++)
        t->rpow += dm_radius_power(w, w->tmem[DM_TMEM * m + 3]);
}

/* The kinetic energy of particle i's spin, 1/2 I ω² over its W components
 * of ω: 0 for a fixed particle, which does not turn (its inverse moment of
 * inertia is 0, so that 1/2 ω² / I⁻¹ would be 0/0). */
static inline double dm_particle_spin_energy(const dm_particles *P, uint32_t i, int W)
{
    if (dm_particle_fixed(P, i))
        return 0.0;
    double w2 = 0.0;
    for (int c = 0; c < W; c++)
        w2 += P->w[W * i + c] * P->w[W * i + c];
    return 0.5 * w2 / P->iinv[i];
}

#endif /* DM_STATE_H */
