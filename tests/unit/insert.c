/* insert.c: fills, feeds and outlets of demill/insert.h against numbers
 * derived by hand.
 *
 * What this suite proves:
 *  - Wide size distributions fill the drum completely: Bond's standard ball
 *    charge (Bond 1961, "Crushing and grinding calculations", Brit. Chem.
 *    Eng. 6: 43 balls of 36.8 mm, 67 of 29.7, 10 of 25.4, 71 of 19.1 and 94
 *    of 15.5, 285 in all, about 20.1 kg of steel) in his 305 × 305 mm test
 *    mill, and a charge of 10 and 20 mm balls, half and half by mass (3996:
 *    the 1 : 8 ratio of their masses makes it 444 and 3552), in a 0.3 m drum.
 *    Every class gets its count, no two particles overlap (every pair is
 *    checked) and every particle lies inside the drum; the mass fractions are
 *    those asked for within one particle of the class.
 *  - A box and a cylinder filled to a solid fraction hold that fraction of
 *    their volume (to one particle), every particle inside them.
 *  - A feed of ṁ into empty space (no walls, gravity on) has inserted ṁ t
 *    within one particle's mass at every sampled time, and reports the rest
 *    as its deficit.
 *  - An outlet below a falling stream removes every particle that crosses
 *    it: none is left below, and counted + present = inserted, in number
 *    exactly and in mass to rounding; the size classes count the feed's two
 *    sizes apart. Its intervals end in one step however far below the
 *    clock's resolution they are (1e-300 s, 1 ns at t = 1e8 s).
 *  - Bad input (a feed rate <= 0, a NaN or empty region, an unknown region
 *    or distribution, a half-space to fill) is refused with its code and
 *    leaves the world's checkpoint bytes as they were.
 *  - A checkpoint and a snapshot taken mid-run with a feed and an outlet
 *    carry them: the runs continue bit for bit as the original. */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* A 3D world with gravity, steel (7800 kg/m³) with a linear undamped
 * contact, and a drum of the given size when diameter > 0. */
static demill_world *steel_world(double diameter, double length, demill_id *m, demill_id *drum)
{
    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, m));
    DM_OK(w, demill_material_set(w, *m, DEMILL_MATERIAL_DENSITY, 7800));
    DM_OK(w, demill_pair_set(w, *m, *m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    if (diameter > 0) {
        DM_OK(w, demill_drum_create(w, *m, drum));
        DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_DIAMETER, diameter));
        DM_OK(w, demill_drum_set(w, *drum, DEMILL_DRUM_LENGTH, length));
    }
    return w;
}

typedef struct charge {
    size_t n;
    double *x, *r, *m;
} charge;

static charge read_charge(demill_world *w)
{
    charge c = {0};
    size_t n;
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, NULL, 0, &n));
    c.n = n;
    c.x = malloc(3 * (n + 1) * sizeof *c.x);
    c.r = malloc((n + 1) * sizeof *c.r);
    c.m = malloc((n + 1) * sizeof *c.m);
    ck_assert(c.x && c.r && c.m);
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, c.x, n, &n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_RADIUS, c.r, n, &n));
    DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_MASS, c.m, n, &n));
    return c;
}

static void free_charge(charge *c)
{
    free(c->x);
    free(c->r);
    free(c->m);
}

/* Fills a drum with discrete classes (diameter, count) by count, and checks
 * counts, overlaps, the drum's walls and the mass fractions. */
static void check_drum_charge(double diameter, double length, size_t ncls, const double *d,
                              const double *count)
{
    demill_id m, drum;
    demill_world *w = steel_world(diameter, length, &m, &drum);
    double params[16], total = 0.0, n = 0.0;
    for (size_t k = 0; k < ncls; k++) {
        params[2 * k] = d[k];
        params[2 * k + 1] = count[k] * d[k] * d[k] * d[k]; /* the mass, to a common factor */
        total += params[2 * k + 1];
        n += count[k];
    }
    size_t added;
    DM_OK(w, demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, params, 2 * ncls,
                              DEMILL_FILL_COUNT, n, 7, NULL, 0, &added));
    ck_assert_uint_eq(added, (size_t)n);
    charge c = read_charge(w);
    ck_assert_uint_eq(c.n, (size_t)n);
    dm_test_check_no_overlap(c.n, c.x, c.r, NULL);
    double mass = 0.0, cls_mass[8] = {0};
    size_t got[8] = {0};
    for (size_t i = 0; i < c.n; i++) {
        const double *x = c.x + 3 * i, R = 0.5 * diameter - c.r[i];
        ck_assert_msg(x[0] * x[0] + x[1] * x[1] <= R * R && fabs(x[2]) <= 0.5 * length - c.r[i],
                      "particle %zu is not inside the drum", i);
        size_t k = 0;
        while (k < ncls && fabs(2.0 * c.r[i] - d[k]) > 1e-12)
            k++;
        ck_assert(k < ncls);
        got[k]++;
        cls_mass[k] += c.m[i];
        mass += c.m[i];
    }
    for (size_t k = 0; k < ncls; k++) {
        ck_assert_uint_eq(got[k], (size_t)count[k]);
        const double one = 7800 * M_PI / 6 * d[k] * d[k] * d[k];
        ck_assert_msg(fabs(cls_mass[k] / mass - params[2 * k + 1] / total) * mass <= one,
                      "class %zu: mass fraction %g, asked %g", k, cls_mass[k] / mass,
                      params[2 * k + 1] / total);
    }
    free_charge(&c);
    demill_world_destroy(w);
}

START_TEST(bond_charge_fits)
{
    const double d[5] = {0.0368, 0.0297, 0.0254, 0.0191, 0.0155}, n[5] = {43, 67, 10, 71, 94};
    check_drum_charge(0.305, 0.305, 5, d, n);
    /* Bond's stated mass of the charge, 20.125 kg: these sizes make it 20.08 kg */
    double mass = 0.0;
    for (int k = 0; k < 5; k++)
        mass += n[k] * 7800 * M_PI / 6 * d[k] * d[k] * d[k];
    DM_ASSERT_REL(mass, 20.125, 0.005);
}
END_TEST

START_TEST(two_sizes_half_and_half_fit)
{
    const double d[2] = {0.02, 0.01}, n[2] = {444, 3552};
    check_drum_charge(0.3, 0.3, 2, d, n);
}
END_TEST

/* A box and a cylinder filled to 20 % solid: the particles' volume is 0.2 of
 * the region's within one particle (8 mm balls: 2.68e-7 m³), all inside. */
START_TEST(region_fill_fraction)
{
    demill_id m;
    demill_world *w = steel_world(0, 0, &m, NULL);
    const double box[6] = {-0.05, 0.0, -0.05, 0.05, 0.1, 0.05};
    const double cyl[7] = {0.3, 0.0, 0.0, 0.3, 0.12, 0.0, 0.05};
    const double sizes[2] = {0.008, 1.0}, v1 = M_PI / 6 * 0.008 * 0.008 * 0.008;
    const double volume[2] = {0.1 * 0.1 * 0.1, M_PI * 0.05 * 0.05 * 0.12};
    size_t n[2];
    DM_OK(w, demill_fill_region(w, DEMILL_REGION_BOX, box, 6, m, DEMILL_SIZES_CLASSES, sizes, 2,
                                DEMILL_FILL_FRACTION, 0.2, 1, NULL, 0, &n[0]));
    DM_OK(w, demill_fill_region(w, DEMILL_REGION_CYLINDER, cyl, 7, m, DEMILL_SIZES_CLASSES, sizes,
                                2, DEMILL_FILL_FRACTION, 0.2, 2, NULL, 0, &n[1]));
    charge c = read_charge(w);
    ck_assert_uint_eq(c.n, n[0] + n[1]);
    for (int k = 0; k < 2; k++)
        ck_assert_msg(fabs((double)n[k] * v1 - 0.2 * volume[k]) <= v1, "region %d: %zu balls", k,
                      n[k]);
    dm_test_check_no_overlap(c.n, c.x, c.r, NULL);
    for (size_t i = 0; i < c.n; i++) {
        const double *x = c.x + 3 * i, r = c.r[i];
        if (i < n[0])
            for (int k = 0; k < 3; k++)
                ck_assert(x[k] - r >= box[k] && x[k] + r <= box[3 + k]);
        else
            ck_assert((x[0] - 0.3) * (x[0] - 0.3) + x[2] * x[2] <= (0.05 - r) * (0.05 - r) &&
                      x[1] >= r && x[1] <= 0.12 - r);
    }
    free_charge(&c);
    demill_world_destroy(w);
}
END_TEST

/* Balls filled into a box 5 cm above a floor are placed at rest: a settle
 * must let them fall and come to rest rather than stop at its first look (1
 * ms in, when their kinetic energy, ½ m (g t)² = 1.0e-7 J each, is still below
 * the threshold). At rest the floor carries their weight (static
 * equilibrium) and the lowest ball lies on it. */
START_TEST(settle_waits_for_the_fall)
{
    demill_id m, floor;
    demill_world *w = steel_world(0, 0, &m, NULL);
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_RESTITUTION, 0.3));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_COULOMB));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_FRICTION, 0.5));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING_FRICTION, 0.1));
    const double o[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, m, o, up, &floor));
    const double box[6] = {-0.02, 0.05, -0.02, 0.02, 0.1, 0.02}, sizes[2] = {0.008, 1.0};
    size_t n;
    DM_OK(w, demill_fill_region(w, DEMILL_REGION_BOX, box, 6, m, DEMILL_SIZES_CLASSES, sizes, 2,
                                DEMILL_FILL_COUNT, 20, 4, NULL, 0, &n));
    ck_assert_uint_eq(n, 20);
    double dt, critical, contact;
    DM_OK(w, demill_world_suggest_time_step(w, 1.0, 1, &dt, &critical, &contact));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt));
    int32_t settled = 0;
    DM_OK(w, demill_world_settle(w, 5.0, 1e-6, &settled));
    ck_assert(settled);
    charge c = read_charge(w);
    double weight = 0.0, low = INFINITY, f[3];
    for (size_t i = 0; i < c.n; i++) {
        weight += c.m[i] * 9.81;
        low = fmin(low, c.x[3 * i + 1] - c.r[i]);
    }
    DM_OK(w, demill_wall_get(w, floor, DEMILL_WALL_FORCE, f));
    ck_assert_msg(fabs(-f[1] - weight) <= 1e-3 * weight, "floor %g N, weight %g N", -f[1],
                  weight);
    ck_assert_msg(low < 1e-4, "the lowest ball is %g m above the floor", low);
    free_charge(&c);
    demill_world_destroy(w);
}
END_TEST

/* A feed of 5 and 7 mm steel balls (half and half by mass) at 2 kg/s into a
 * box in empty space; outlets optional. */
static const double feed_box[6] = {-0.05, 0.0, -0.05, 0.05, 0.05, 0.05};
static const double feed_sizes[4] = {0.005, 0.5, 0.007, 0.5};
static const double feed_rate = 2.0, m_large = 7800 * M_PI / 6 * 0.007 * 0.007 * 0.007;

static demill_id add_feed(demill_world *w, demill_id m)
{
    const double v0[3] = {0, -0.5, 0};
    demill_id feed;
    DM_OK(w, demill_feed_create(w, DEMILL_REGION_BOX, feed_box, 6, m, DEMILL_SIZES_CLASSES,
                                feed_sizes, 4, feed_rate, v0, 0.0, INFINITY, 3, &feed));
    return feed;
}

START_TEST(feed_inserts_its_rate)
{
    demill_id m;
    demill_world *w = steel_world(0, 0, &m, NULL);
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-5));
    const demill_id feed = add_feed(w, m);
    for (int k = 1; k <= 20; k++) {
        DM_OK(w, demill_world_step(w, 1000));
        double t, mass, deficit, present = 0.0;
        uint64_t count;
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &t));
        DM_OK(w, demill_feed_read(w, feed, &mass, &count, &deficit));
        ck_assert_msg(mass <= feed_rate * t && feed_rate * t - mass < m_large,
                      "t = %g s: %g kg inserted, %g owed", t, mass, feed_rate * t);
        ck_assert(fabs(deficit - (feed_rate * t - mass)) <= 1e-12);
        charge c = read_charge(w);
        ck_assert_uint_eq(c.n, count);
        for (size_t i = 0; i < c.n; i++)
            present += c.m[i];
        DM_ASSERT_REL(present, mass, 1e-12);
        free_charge(&c);
    }
    demill_world_destroy(w);
}
END_TEST

START_TEST(outlet_conserves_particles)
{
    demill_id m, outlet;
    demill_world *w = steel_world(0, 0, &m, NULL);
    const demill_id feed = add_feed(w, m);
    const double below[6] = {0, -0.2, 0, 0, 1, 0}, edge = 0.006;
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, below, 6, 1, &edge, 0.05, &outlet));
    DM_OK(w, demill_world_step(w, 30000)); /* 0.3 s: the stream has crossed y = -0.2 */
    double mass, out_mass[2], last[3], present = 0.0;
    uint64_t count, out_count[2];
    size_t ncls;
    DM_OK(w, demill_feed_read(w, feed, &mass, &count, NULL));
    DM_OK(w, demill_outlet_read(w, outlet, out_count, out_mass, 2, &ncls, last));
    ck_assert_uint_eq(ncls, 2);
    charge c = read_charge(w);
    for (size_t i = 0; i < c.n; i++) {
        ck_assert_msg(c.x[3 * i + 1] > -0.2, "particle %zu below the outlet's plane", i);
        present += c.m[i];
    }
    ck_assert(out_count[0] > 0 && out_count[1] > 0);
    ck_assert_uint_eq(out_count[0] + out_count[1] + c.n, count);
    DM_ASSERT_REL(out_mass[0] + out_mass[1] + present, mass, 1e-12);
    /* the classes: 5 mm balls below the 6 mm edge, 7 mm above */
    DM_ASSERT_REL(out_mass[0], out_count[0] * 7800 * M_PI / 6 * 0.005 * 0.005 * 0.005, 1e-12);
    DM_ASSERT_REL(out_mass[1], out_count[1] * m_large, 1e-12);
    /* the last interval of 0.05 s ended at 0.3 s; at steady state it took
     * out what the feed put in over 0.05 s, within a few particles */
    DM_ASSERT_REL(last[2], 0.3, 1e-9);
    ck_assert_msg(fabs(last[0] - feed_rate * 0.05) < 0.2 * feed_rate * 0.05,
                  "last interval %g kg", last[0]);
    free_charge(&c);
    demill_world_destroy(w);
}
END_TEST

/* An outlet's intervals end as they should when they are far below the
 * clock's resolution. A ball taken out in the first step is the last
 * interval's (m = 7800 π/6 d³, 1 ball, ending at 1 ms). Then outlets of
 * 1e-300 s, and of 1 ns with the clock set to 1e8 s (where t + 1 ns = t),
 * are stepped: each step returns (one never did: the intervals were ended
 * one at a time, t_next + interval staying t_next) with every outlet's
 * last interval empty (the ball is gone) and ended no later than now. */
START_TEST(outlet_intervals_below_the_clock_resolution)
{
    demill_id m, ball, outlet[3];
    demill_world *w = steel_world(0, 0, &m, NULL);
    const double x[3] = {0, 0, 0}, r = 0.005, box[6] = {-0.01, -0.01, -0.01, 0.01, 0.01, 0.01};
    DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &ball));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-5));
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_BOX, box, 6, 0, NULL, 1e-3, &outlet[0]));
    DM_OK(w, demill_world_step(w, 101));
    double last[3];
    DM_OK(w, demill_outlet_read(w, outlet[0], NULL, NULL, 0, NULL, last));
    DM_ASSERT_REL(last[0], 7800 * M_PI / 6 * 0.01 * 0.01 * 0.01, 1e-12);
    ck_assert(last[1] == 1.0);
    DM_ASSERT_REL(last[2], 1e-3, 1e-12);

    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_BOX, box, 6, 0, NULL, 1e-300, &outlet[1]));
    DM_OK(w, demill_world_step(w, 2));
    DM_OK(w, demill_world_set(w, DEMILL_WORLD_TIME, 1e8));
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_BOX, box, 6, 0, NULL, 1e-9, &outlet[2]));
    for (int k = 0; k < 3; k++) {
        double now;
        DM_OK(w, demill_world_step(w, 1));
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &now));
        for (int q = 0; q < 3; q++) {
            DM_OK(w, demill_outlet_read(w, outlet[q], NULL, NULL, 0, NULL, last));
            ck_assert_msg(last[0] == 0.0 && last[1] == 0.0 && last[2] <= now,
                          "outlet %d: %g kg, %g balls, ended at %.17g s, now %.17g s", q, last[0],
                          last[1], last[2], now);
        }
    }
    demill_world_destroy(w);
}
END_TEST

/* The world's checkpoint bytes. */
static unsigned char *state_bytes(demill_world *w, size_t *n)
{
    DM_OK(w, demill_world_save_buffer(w, NULL, 0, n));
    unsigned char *b = malloc(*n);
    ck_assert(b);
    DM_OK(w, demill_world_save_buffer(w, b, *n, n));
    return b;
}

START_TEST(bad_input_changes_nothing)
{
    demill_id m, id;
    demill_world *w = steel_world(0, 0, &m, NULL);
    add_feed(w, m);
    size_t n0, n1;
    unsigned char *before = state_bytes(w, &n0);
    const double v0[3] = {0, 0, 0}, nan_box[6] = {0, 0, 0, NAN, 1, 1};
    const double empty_box[6] = {0, 0, 0, 1, 0, 1}, flat_cyl[7] = {0, 0, 0, 0, 1, 0, 0};
    const double half[6] = {0, 0, 0, 0, 1, 0}, zero_normal[6] = {0, 0, 0, 0, 0, 0};
    const struct {
        const double *region;
        size_t nregion;
        int32_t kind, dist;
        double rate;
        demill_status want;
    } feeds[] = {
        {feed_box, 6, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, 0.0, DEMILL_ERR_INVALID_VALUE},
        {feed_box, 6, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, -1.0, DEMILL_ERR_INVALID_VALUE},
        {feed_box, 6, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, NAN, DEMILL_ERR_NOT_FINITE},
        {nan_box, 6, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_NOT_FINITE},
        {empty_box, 6, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_INVALID_VALUE},
        {flat_cyl, 7, DEMILL_REGION_CYLINDER, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_INVALID_VALUE},
        {feed_box, 5, DEMILL_REGION_BOX, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_INVALID_VALUE},
        {half, 6, DEMILL_REGION_HALF_SPACE, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_INVALID_VALUE},
        {feed_box, 6, 99, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_UNKNOWN_KEY},
        {feed_box, 6, DEMILL_REGION_DRUM, DEMILL_SIZES_CLASSES, 1.0, DEMILL_ERR_INVALID_VALUE},
        {feed_box, 6, DEMILL_REGION_BOX, 42, 1.0, DEMILL_ERR_UNKNOWN_KEY},
    };
    for (size_t k = 0; k < sizeof feeds / sizeof *feeds; k++) {
        demill_status s = demill_feed_create(w, feeds[k].kind, feeds[k].region, feeds[k].nregion,
                                             m, feeds[k].dist, feed_sizes, 4, feeds[k].rate, v0,
                                             0.0, 1.0, 1, &id);
        ck_assert_msg(s == feeds[k].want, "feed %zu: %d, expected %d (%s)", k, (int)s,
                      (int)feeds[k].want, demill_world_last_error(w));
        ck_assert(strlen(demill_world_last_error(w)) > 0);
    }
    ck_assert_int_eq(demill_fill_region(w, DEMILL_REGION_HALF_SPACE, half, 6, m,
                                        DEMILL_SIZES_CLASSES, feed_sizes, 4, DEMILL_FILL_COUNT,
                                        10, 1, NULL, 0, NULL),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_fill_region(w, DEMILL_REGION_BOX, nan_box, 6, m, DEMILL_SIZES_CLASSES,
                                        feed_sizes, 4, DEMILL_FILL_COUNT, 10, 1, NULL, 0, NULL),
                     DEMILL_ERR_NOT_FINITE);
    ck_assert_int_eq(demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, zero_normal, 6, 0, NULL,
                                          1.0, &id),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_outlet_create(w, DEMILL_REGION_BOX, empty_box, 6, 0, NULL, 1.0, &id),
                     DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_outlet_create(w, DEMILL_REGION_BOX, feed_box, 6, 0, NULL, 0.0, &id),
                     DEMILL_ERR_INVALID_VALUE);
    unsigned char *after = state_bytes(w, &n1);
    ck_assert_uint_eq(n0, n1);
    ck_assert(memcmp(before, after, n0) == 0);
    free(before);
    free(after);
    demill_world_destroy(w);
}
END_TEST

/* Positions in id order, and the feed's and outlet's totals. */
static void check_same(demill_world *a, demill_world *b)
{
    size_t na, nb;
    DM_OK(a, demill_particles_read(a, DEMILL_PARTICLE_POSITION, NULL, 0, &na));
    DM_OK(b, demill_particles_read(b, DEMILL_PARTICLE_POSITION, NULL, 0, &nb));
    ck_assert_uint_eq(na, nb);
    double *xa = malloc(3 * (na + 1) * sizeof *xa), *xb = malloc(3 * (na + 1) * sizeof *xb);
    ck_assert(xa && xb);
    DM_OK(a, demill_particles_read(a, DEMILL_PARTICLE_POSITION, xa, na, &na));
    DM_OK(b, demill_particles_read(b, DEMILL_PARTICLE_POSITION, xb, nb, &nb));
    ck_assert(memcmp(xa, xb, 3 * na * sizeof *xa) == 0);
    free(xa);
    free(xb);
    demill_id fa, fb, oa, ob;
    size_t k;
    DM_OK(a, demill_world_ids(a, DEMILL_KIND_FEED, &fa, 1, &k));
    DM_OK(b, demill_world_ids(b, DEMILL_KIND_FEED, &fb, 1, &k));
    DM_OK(a, demill_world_ids(a, DEMILL_KIND_OUTLET, &oa, 1, &k));
    DM_OK(b, demill_world_ids(b, DEMILL_KIND_OUTLET, &ob, 1, &k));
    double ma, mb, la[3], lb[3];
    uint64_t ca, cb, ka[2], kb[2];
    DM_OK(a, demill_feed_read(a, fa, &ma, &ca, NULL));
    DM_OK(b, demill_feed_read(b, fb, &mb, &cb, NULL));
    ck_assert(ma == mb && ca == cb && ca > 0);
    DM_OK(a, demill_outlet_read(a, oa, ka, NULL, 2, NULL, la));
    DM_OK(b, demill_outlet_read(b, ob, kb, NULL, 2, NULL, lb));
    ck_assert(ka[0] == kb[0] && ka[1] == kb[1] && ka[0] + ka[1] > 0);
    ck_assert(memcmp(la, lb, sizeof la) == 0);
}

START_TEST(checkpoint_and_snapshot_carry_feeds)
{
    demill_id m, outlet;
    demill_world *w = steel_world(0, 0, &m, NULL);
    add_feed(w, m);
    const double below[6] = {0, -0.1, 0, 0, 1, 0}, edge = 0.006;
    DM_OK(w, demill_outlet_create(w, DEMILL_REGION_HALF_SPACE, below, 6, 1, &edge, 0.02, &outlet));
    DM_OK(w, demill_world_step(w, 20000));
    size_t n;
    unsigned char *bytes = state_bytes(w, &n);
    demill_snapshot *snap;
    DM_OK(w, demill_snapshot_take(w, &snap));
    DM_OK(w, demill_world_step(w, 10000));
    demill_world *c, *d;
    ck_assert_int_eq(demill_world_create(3, &c), DEMILL_OK);
    ck_assert_int_eq(demill_world_create(3, &d), DEMILL_OK);
    DM_OK(c, demill_world_load_buffer(c, bytes, n));
    DM_OK(d, demill_snapshot_restore(d, snap));
    DM_OK(c, demill_world_step(c, 10000));
    DM_OK(d, demill_world_step(d, 10000));
    check_same(w, c);
    check_same(w, d);
    demill_snapshot_free(snap);
    free(bytes);
    demill_world_destroy(c);
    demill_world_destroy(d);
    demill_world_destroy(w);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("insert");
    TCase *t = tcase_create("insert");
    tcase_add_test(t, bond_charge_fits);
    tcase_add_test(t, two_sizes_half_and_half_fit);
    tcase_add_test(t, region_fill_fraction);
    tcase_add_test(t, settle_waits_for_the_fall);
    tcase_add_test(t, feed_inserts_its_rate);
    tcase_add_test(t, outlet_conserves_particles);
    tcase_add_test(t, outlet_intervals_below_the_clock_resolution);
    tcase_add_test(t, bad_input_changes_nothing);
    tcase_add_test(t, checkpoint_and_snapshot_carry_feeds);
    suite_add_tcase(s, t);
    return dm_test_run(s);
}
