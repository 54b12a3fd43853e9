/* testutil.h: helpers shared by the test suites. */
#ifndef DEMILL_TESTUTIL_H
#define DEMILL_TESTUTIL_H

#include <check.h>
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <demill.h>

/* A floor of cells × cells squares of side h from (x0, 0, x0) in the plane
 * y = 0, each cut by the same diagonal into two triangles, so that an inner
 * vertex is shared by six; into v (3 (cells + 1)² doubles, 3 per vertex) and
 * t (6 cells² indices, 3 per triangle). */
void dm_test_floor_grid(int cells, double h, double x0, double *v, uint32_t *t);

/* A box of four walls and a floor, one mesh of 10 triangles (0.1 m wide and
 * high, open at the top, its floor at y = 0), turning at 3 rad/s about y
 * and 0.5 rad/s about z, with DM_TEST_BOX_BALLS balls of 2.5-3.4 mm of
 * material mat in it (enough for two particle ranges on two threads);
 * the box's id in *box. */
#define DM_TEST_BOX_BALLS 1100
void dm_test_tumbling_box(demill_world *w, demill_id mat, demill_id *box);

/* Every particle's position, then every velocity (3D), in id order, in a
 * new array of 6 n doubles (free it). */
double *dm_test_state(demill_world *w, size_t *n);

/* Saves world w to checkpoint bytes and to a snapshot, steps it `steps`,
 * and for each copy (way 0: the checkpoint loaded, 1: the snapshot
 * restored, into new 3D worlds) steps the copy the same and asserts every
 * position and velocity bitwise equal to w's, then calls check(w, copy,
 * way, ctx) (may be NULL) before destroying the copy. */
typedef void (*dm_test_copy_fn)(demill_world *w, demill_world *copy, int way, void *ctx);
void dm_test_copies_run_on(demill_world *w, uint64_t steps, dm_test_copy_fn check, void *ctx);

/* Asserts that the file at path is a checkpoint of the given format (its
 * header: "DEMILLCK" and the format, little-endian). */
void dm_test_checkpoint_format(const char *path, uint32_t format);

/* World w saved to checkpoint bytes, in a new array of *n bytes (free it). */
unsigned char *dm_test_save(demill_world *w, size_t *n);

/* A new 3D world loaded from a checkpoint of w (destroy it), and in *format
 * the format the checkpoint was written in. */
demill_world *dm_test_reloaded(demill_world *w, uint32_t *format);

/* Fails the test with the world's message unless the call returns DEMILL_OK. */
#define DM_OK(world, call)                                                                         \
    do {                                                                                           \
        demill_status s_ = (call);                                                                 \
        ck_assert_msg(s_ == DEMILL_OK, "%s -> %d (%s): %s", #call, (int)s_, demill_strerror(s_), \
                      demill_world_last_error(world));                                             \
    } while (0)

/* Asserts |got - want| <= tol * |want|. */
#define DM_ASSERT_REL(got, want, tol)                                                              \
    do {                                                                                           \
        double g_ = (got), w_ = (want), t_ = (tol);                                                \
        ck_assert_msg(fabs(g_ - w_) <= t_ * fabs(w_), "%s = %.9g, expected %.9g within %.3g%%",  \
                      #got, g_, w_, 100.0 * t_);                                                   \
    } while (0)

/* A world without gravity (dim 2 or 3) and one material with the given
 * normal and damping laws for the pair (m, m). */
demill_world *dm_test_world(int dim, int normal, int damping, demill_id *material);

/* The materials of a steel ball mill: balls and liner, both of density
 * 7800, with Hertz contact, restitution damping and Mindlin friction for
 * ball-ball and ball-liner (the liner-liner pair has no model). */
void dm_test_mill_materials(demill_world *w, demill_id *balls, demill_id *liner);

/* A drum of liner of the given diameter and length with 8 lifters of
 * height and width `lifter`, filled to 30 % with 5 and 6 mm balls (half
 * the volume each, seed 7), set turning at 75 % of critical. */
void dm_test_mill(demill_world *w, demill_id balls, demill_id liner, double diameter,
                  double length, double lifter, demill_id *drum);

/* Runs a Check suite and returns the process exit status. */
int dm_test_run(Suite *s);

/* One double field of a particle (component c). */
double dm_test_get(demill_world *w, demill_id p, int field, int c);

/* One term of the world's energy account (DEMILL_ENERGY_*). */
double dm_test_energy(demill_world *w, int term);

/* A binary collision: rebound ratio, duration, largest overlap. */
typedef struct dm_collision {
    double restitution, duration, max_overlap;
} dm_collision;

/* Two equal spheres of material mat and radius r, centred about x = offset,
 * approach head-on along x at relative speed v0 from a gap that closes after
 * (3 + phase) steps of dt; returns the measured rebound ratio, the duration
 * (entry and exit times interpolated linearly between samples) and the
 * largest overlap. The particles are removed afterwards. */
dm_collision dm_test_collide(demill_world *w, demill_id mat, double r, double v0, double dt,
                             double phase, double offset);

/* A chain of n particles of radius 5 mm in a row along x between two plane
 * walls, each pressed into the next by 1 % of its radius, in a 2D world
 * without gravity; linear undamped contacts (k 5e4 N/m), the particles
 * moving ±1 cm/s alternately. The time step is `fraction` of the stability
 * limit of one pair, 2/ω with ω = √(k/m*), m* = m/2, which the library
 * checks when stepping starts. The chain's highest mode, the particles
 * moving against both neighbours, has ω_max = 2 √(k/m) sin(nπ/(2(n+1))),
 * nearly √2 times the pair's (Kittel 2005, Introduction to Solid State
 * Physics, ch. 4): between 1/√2 and 1 of the pair limit the run passes the
 * check and then blows up. ids receives the particles' ids. */
demill_world *dm_test_chain(int n, double fraction, demill_id *ids);

/* A sphere of material mat and radius r approaches the plane x = 0 (added
 * with material mat, its normal +x) head-on at speed v0 from a gap that
 * closes after (3 + phase) steps of dt; returns what dm_test_collide()
 * returns. The sphere and the plane are removed afterwards. */
dm_collision dm_test_bounce(demill_world *w, demill_id mat, double r, double v0, double dt,
                            double phase);
/* The same with a plane of material wall_mat. */
dm_collision dm_test_bounce_on(demill_world *w, demill_id mat, demill_id wall_mat, double r,
                               double v0, double dt, double phase);

/* A sphere of material mat and radius r moving at v0 along x hits a fixed
 * sphere of the same size and material head-on, from a gap that closes
 * after (3 + phase) steps of dt; returns what dm_test_collide() returns.
 * Both are removed afterwards. */
dm_collision dm_test_hit_fixed(demill_world *w, demill_id mat, double r, double v0, double dt,
                               double phase);

/* Asserts that no two of the n spheres (centres x, 3 doubles each, radii r)
 * overlap, except members of one clump (clump: each sphere's clump id,
 * DEMILL_ID_NONE for a free one; NULL: no clumps). Every pair is checked,
 * with one assertion at the end (each costs Check a write). */
void dm_test_check_no_overlap(size_t n, const double *x, const double *r, const demill_id *clump);

/* Asserts that worlds a and b hold as many clumps (at most 128) and that
 * every field of each, in slot order, is bitwise the same; what names the
 * comparison in a failure's message. */
void dm_test_check_same_clumps(demill_world *a, demill_world *b, const char *what);

#endif
