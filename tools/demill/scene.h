/* scene.h: a scene file (docs/scene-files.md) checked and turned into a
 * world through the public API, with what the runner needs to run it:
 * when to turn the drum, when to stop and what to write. */
#ifndef DEMILL_SCENE_H
#define DEMILL_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include <demill.h>

#include "tree.h"

#define SCENE_MAX_MATERIALS 256
#define SCENE_MAX_COLUMNS 64
#define SCENE_MAX_EDGES 16
#define SCENE_MAX_OUTLETS 16
#define SCENE_MAX_BODIES 64
#define SCENE_MAX_TEMPLATES 64
#define SCENE_MAX_MOTIONS 16

/* A quantity of the time series or of a steady stop: a world or drum key
 * of the registry (key, body < 0, outlet < 0), a component of a body's
 * field, the mass or count an outlet has removed, or a component of the
 * particles' centre of mass. */
typedef struct scene_quantity {
    const char *name;  /* as the scene gives it; points into the tree */
    int32_t key;       /* DEMILL_WORLD_* or DEMILL_DRUM_*, or 0 */
    int body, comp;    /* the body's index, -1 for none; the component 0-2 */
    int32_t field;     /* DEMILL_BODY_* */
    int outlet;        /* the outlet's index, -1 for none */
    int outlet_count;  /* 1: the outlet's count of particles, 0: their mass */
    int centre;        /* 1: a component (comp) of the particles' centre of mass */
    int32_t energy;    /* a DEMILL_ENERGY_* term (energy.NAME), or 0 */
} scene_quantity;

/* A wall's motion (walls[].motion) from a time after the start: the
 * runner sets it (demill_wall_set_motion()) when the world's time comes. */
typedef struct scene_motion {
    demill_id wall;
    int index;      /* in walls */
    double start;   /* world time, s */
    double v[3][3]; /* velocity, angular velocity, centre */
    int given[3];   /* which of v were given (the others NULL) */
    int started;
} scene_motion;

/* A body's load (bodies.NAME.load): a constant force from a start time,
 * reached linearly over a ramp; the runner sets it at a sample when it
 * changes. */
typedef struct scene_load {
    int on;
    double force[3]; /* N */
    double start, ramp; /* world time and duration, s */
    double applied;     /* the fraction of the force the world has now */
} scene_load;

typedef struct scene {
    demill_world *w;
    int dim;
    double dt;
    size_t nmat;
    const char *matname[SCENE_MAX_MATERIALS]; /* point into the tree */
    demill_id mat[SCENE_MAX_MATERIALS];
    demill_id drum;             /* DEMILL_ID_NONE without a drum */
    size_t nbody;
    const char *bodyname[SCENE_MAX_BODIES]; /* point into the tree */
    demill_id body[SCENE_MAX_BODIES];
    scene_load load[SCENE_MAX_BODIES];
    double drum_start;          /* world time at which the drum's speed is set, s */
    int32_t speed_key;          /* the drum's speed key given, 0 for none */
    double speed_value;
    int speed_set;              /* the speed was given with --set */
    size_t noutlets;            /* the outlets made, or the checkpoint's on a restart */
    demill_id outlet[SCENE_MAX_OUTLETS];
    double stop_time, stop_revolutions; /* NAN when not given */
    int32_t empty_kind;         /* stop when this region holds no particle: DEMILL_REGION_BOX or
                                   _CYLINDER, 0 for none */
    double empty_params[7];
    int steady_on;              /* stop when this quantity is steady: */
    scene_quantity steady;
    double steady_window, steady_tolerance; /* two windows' means within tolerance (relative) */
    double every;               /* s between samples (time series, stop checks) */
    char csv_file[256];         /* "" for none */
    size_t ncol;
    scene_quantity col[SCENE_MAX_COLUMNS];
    double vtk_every, checkpoint_every; /* s, 0 for none */
    int charge_png, power_png;
    int series_png;             /* pictures: series: the columns against time */
    size_t nedges;              /* power by size class: nedges + 1 classes */
    double edges[SCENE_MAX_EDGES];
    int discharge_on;           /* outputs.discharge: an outlet's rate against Beverloo's */
    int discharge_outlet;       /* the outlet's index */
    double orifice;             /* the orifice's diameter, m */
    double half_angle;          /* the hopper's half-angle from the vertical, rad (pi/2: flat) */
    double stagnant_angle;      /* a flat bottom's stagnant zone to the horizontal, rad */
    int32_t bulk_kind;          /* where the bed's solid fraction is measured: DEMILL_REGION_BOX
                                   or _CYLINDER */
    double bulk_params[7];
    size_t namp;                /* outputs.amplitude: half the peak-to-peak of these */
    scene_quantity amp[SCENE_MAX_COLUMNS];
    double amp_window;          /* over the last amp_window s before stop.time */
    int dissipation_on;         /* outputs.dissipation: each mechanism's share of the energy */
    double dissipation_window;  /* dissipated over the last window s before stop.time */
    int repose_on;              /* outputs.repose: the angle of repose of a heap */
    double repose_centre[3];    /* a point of the heap's vertical axis on the floor, m */
    double repose_ring;         /* the rings' width, m (0: the particles' mean diameter) */
    size_t ntmpl;               /* templates: the clump templates, by name */
    const char *tmplname[SCENE_MAX_TEMPLATES]; /* point into the tree */
    demill_id tmpl[SCENE_MAX_TEMPLATES]; /* DEMILL_ID_NONE in SCENE_CHECK */
    size_t tmpl_clumps[SCENE_MAX_TEMPLATES]; /* the clumps of each the fills added */
    int tmpl_counted;           /* tmpl_clumps is known (not on a restart) */
    size_t nmotion;             /* walls' motions that start late (not on a restart) */
    scene_motion motion[SCENE_MAX_MOTIONS];
    int shear_on;               /* outputs.shear: a direct shear test (shear.h) */
    int shear_wall;             /* the index in walls of the moving half */
    double shear_dir[3];        /* the unit direction of its motion */
    double shear_speed, shear_start; /* its speed (m/s) and when it starts (s) */
    size_t nheld;               /* the bodies whose force along shear_dir is the shear force */
    int held[SCENE_MAX_BODIES];
    int lid;                    /* the body that loads the sample */
    double shear_area;          /* the shear plane's area, m^2 */
    double shear_bin;           /* the displacement over which the curve is averaged, m */
    int conveyor_on;            /* outputs.conveyor: a belt's resistance against the momentum
                                   balance */
    int conveyor_chute;         /* the body holding the chute (-1: none) */
    int conveyor_outlet;        /* the outlet's index */
    double belt_dir[3], belt_speed; /* the belt walls' surface velocity: its direction, its m/s */
    double feed_rate, feed_along; /* the feed's kg/s and its velocity along the belt, m/s */
    double conveyor_from;       /* the steady window's start, s */
    int janssen_on;             /* outputs.janssen: a silo's wall stress by depth against Janssen's */
    int silo_wall, silo_floor;  /* the indices in walls of the silo's side (a cylinder) and floor */
    double silo_point[3];       /* a point of the side's axis at the floor's level, m */
    double silo_up[3];          /* the axis's unit direction against gravity */
    double silo_radius, silo_top; /* the side's radius and its top's height above the floor, m */
    double silo_band;           /* the height of the bands of the wall's profile, m */
    double silo_zone[2];        /* the heights above the floor where K, mu_w and rho_b are measured */
    double silo_window;         /* samples over the last silo_window s before stop.time */
} scene;

/* What scene_build() does with the world. */
enum {
    SCENE_BUILD = 0,   /* a new world from the file */
    SCENE_CHECK = 1,   /* check everything, build the world's settings, materials, pairs, drum
                          and bodies, but read no file and add no template, particle, wall,
                          feed or outlet (demill check, sweeps before they run, the fuzz
                          target) */
    SCENE_RESTART = 2  /* s->w holds a loaded checkpoint: map the file's names to its ids and
                          apply only the entries set on the command line (--set) */
};

/* Whether the point p is inside the region of kind DEMILL_REGION_BOX (its
 * dim first coordinates) or DEMILL_REGION_CYLINDER with parameters r (as
 * stop.empty and outputs.discharge.bulk_region give them). */
int scene_region_contains(int32_t kind, const double *r, int dim, const double p[3]);

/* Checks the scene `root` (read from a file in folder `dir`, against which
 * its relative paths are taken) and builds it: 0, or -1 with a message
 * "FILE:LINE: KEY: what was wrong" in err and no world left (except in
 * SCENE_RESTART mode, where s->w stays the caller's). */
int scene_build(scene *s, const tree *root, const char *dir, int mode, char *err, size_t errlen);

/* The unit of a quantity, in SI ("1" for a pure number). */
const char *scene_quantity_unit(const scene_quantity *q);

/* The value of a quantity in the scene's world: DEMILL_OK or the API's
 * status. */
demill_status scene_quantity_read(const scene *s, const scene_quantity *q, double *value);

/* The name of a DEMILL_ENERGY_* term as a quantity, without its prefix
 * "energy." (dissipated_normal), or NULL for none. */
const char *scene_energy_name(int32_t term);

/* The tables of the keys a scene file takes from the parameter registry
 * (world, materials, pairs, drum: unit, allowed values, default), in
 * Markdown, as docs/scene-files.md has them (`demill keys`). */
void scene_list_keys(FILE *f);

#endif
