/* mill.h: the parts of the mill example (mill.c: options and run; scene.c:
 * the canonical drums; output.c: the --ore picture; ore.c: --ore; shape.c:
 * the clumps of --shape; the charge and power pictures are
 * examples/common/drum_plot.h). */
#ifndef MILL_H
#define MILL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <demill.h>

/* A packing as docs/scenes.md defines it: lattice sites of spacing 6.3 mm with
 * x² + y² <= site_radius², in `layers` layers from z0 (3D), the lowest
 * `particles` of them, jittered with Python's random.Random(12345). */
typedef struct scene_def {
    int dim;
    size_t particles;
    double site_radius;
    long layers;
    double z0;
} scene_def;

/* Positions (3 per particle) of the packing; 0, or -1 on failure. */
int scene_packing(const scene_def *s, double *pos);

/* A drum of the scenes' kind: geometry, evenly spaced square lifters. */
typedef struct drum_geometry {
    int dim;
    double time_step, diameter, length;
    int lifters;
    double lifter_size;
} drum_geometry;

/* Creates the world of the scenes: steel balls and liner (7800 kg/m³,
 * E = 1e8 Pa, ν = 0.3, restitution 0.5, friction 0.5; Hertz-Mindlin with
 * Tsuji damping, no force clamp, as LIGGGHTS without limitForce) and the
 * drum. 0, or -1 with a message on stderr. */
int scene_world(const drum_geometry *g, demill_world **w, demill_id *steel, demill_id *drum);

/* The ore of --ore (ore.c): read from a file (docs/grinding.md, mill --ore). */
#define ORE_MAX_FEED 32
#define ORE_MAX_ROWS 100
typedef struct ore_def {
    double density, youngs, poisson; /* the DEM material */
    double mass;                     /* kg of ore in the charge */
    size_t nfeed;
    double feed[2 * ORE_MAX_FEED];   /* (diameter m, mass fraction) pairs */
    double top;                      /* the grinding classes: below top, m, */
    uint32_t classes;                /* this many */
    double tk[8];                    /* Tavares and King: E∞ d0 φ σ Emax/E50 γ A' b' */
    size_t rows;
    double table[6 * ORE_MAX_ROWS];  /* t-family: t10 t2 t4 t25 t50 t75 */
    double bond_wi;                  /* Bond work index, kWh/t; 0 if not given */
    int damage;                      /* rates with the damage of the grinding time's impacts */
    int extend;                      /* Austin's rates below the DEM's classes: 0 no, 1 yes */
    int fit_alpha;                   /* with alpha fitted, or given in austin[0] */
    double austin[3];                /* alpha, mu (m), Lambda */
} ore_def;

/* What the grinding gave (ore_grind, ore_write_csv). */
typedef struct ore_result {
    uint32_t n;
    double limits[201], rates[200], feed[200], product[200];
    double feed_passing[200], product_passing[200]; /* at each class's upper limit */
    double f80, p80, kwh_t, bond_kwh_t;
    double austin[2]; /* A (1/s) and alpha of Austin's rates below the DEM's, if extended */
} ore_result;

/* Each returns 0, or -1 with a message on stderr. */
int ore_read(const char *path, ore_def *ore);
/* Adds the ore material (the balls' contact laws) and fills its mass. */
int ore_add(demill_world *w, demill_id steel, demill_id drum, const ore_def *ore, demill_id *mat,
            size_t *added);
/* Starts recording the impacts on the ore. */
int ore_record(demill_world *w, demill_id drum, demill_id mat, const ore_def *ore);
/* Rates from the impacts, the batch grinding for `minutes`, P80 and kWh/t
 * at the mean `power`, W. */
int ore_grind(demill_world *w, demill_id drum, const ore_def *ore, double minutes, double power,
              ore_result *out);
int ore_write_csv(const char *path, const ore_result *r);
int draw_product(const char *path, const ore_result *r, const char *title);

/* The clump template of --shape (shape.c): spheres read from a file. */
#define SHAPE_MAX_SPHERES 256
typedef struct shape_def {
    size_t n;
    double centres[3 * SHAPE_MAX_SPHERES], radii[SHAPE_MAX_SPHERES];
} shape_def;

/* Reads "x y z r" lines (m; '#' comments); 0, or -1 with a message on
 * stderr. */
int shape_read(const char *path, shape_def *s);

#endif
