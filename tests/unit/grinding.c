/* grinding.c: the grinding object (include/demill/grinding.h) against
 * numbers derived without it:
 * - the population balance conserves mass (Austin, Klimpel and Luckie 1984:
 *   every column of the batch grinding equation's matrix sums to zero) to
 *   1e-12 after each of 300 short runs;
 * - one breaking class decays as e^(-S t);
 * - ten classes with constant rates and appearance follow Reid's (1965, A
 *   solution to the batch grinding equation) closed form, computed here;
 * - the JKMRC relation t10 = A (1 - exp(-b E_cs)) and the t-family's
 *   monotone cubic interpolation reproduce the table's own points and a
 *   value worked by hand below;
 * - Tavares and King's breakage probability is 1/2 at the median fracture
 *   energy, and grows with repeated impacts (damage);
 * - the fraction passing and P80 of a two-class product, worked by hand;
 * - the specific energy power × time / mass;
 * - rates from an impact spectrum: impacts of lognormally distributed
 *   energy on particles of lognormally distributed fracture energy break
 *   at the rate of the integral worked below in closed form, and the
 *   appearance function is the breakage-weighted mean of the model's
 *   columns at each bin's energy;
 * - rates with damage: a sequence of identical impacts breaks particles at
 *   the rate that Tavares and King's (2002) damage model gives in closed
 *   form for a damage exponent of 2.5, worked below;
 * - rates extended below the classes that have them by Austin's size
 *   dependence (Austin, Klimpel and Luckie 1984): a fit to rates made from
 *   the law recovers its parameters, and the finer classes follow it;
 * - every bad input gives its code and leaves the object as it was. */
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define G_OK(g, call)                                                                              \
    do {                                                                                           \
        demill_status s_ = (call);                                                                 \
        ck_assert_msg(s_ == DEMILL_OK, "%s -> %d (%s): %s", #call, (int)s_, demill_strerror(s_), \
                      demill_grinding_last_error(g));                                              \
    } while (0)

/* A t-family table made up for the tests (rows t10, t2, t4, t25, t50, t75,
 * in %): the t2 column 30, 50, 65 at t10 = 10, 20, 30. */
static const double table[18] = {10, 30, 18, 4.5, 2.5, 2.0, 20, 50, 33, 9.0, 5.0, 4.0,
                                 30, 65, 46, 13.5, 7.5, 6.0};

/* Austin's normalised cumulative breakage function B(x) = φ x^γ + (1 - φ)
 * x^β (x the size relative to the parent class's lower limit) turned into
 * b_ij on a √2 series: b_ij = B_{i-j} - B_{i-j+1}, the sink taking the rest. */
static void austin_b(int n, double *b)
{
    const double phi = 0.6, gam = 0.9, beta = 4.0, r = 1.0 / sqrt(2.0);
    memset(b, 0, sizeof(double) * (size_t)(n * n));
    for (int j = 0; j < n - 1; j++)
        for (int i = j + 1; i < n; i++) {
            double xu = pow(r, i - j - 1), xl = pow(r, i - j);
            double bu = phi * pow(xu, gam) + (1 - phi) * pow(xu, beta);
            double bl = i == n - 1 ? 0.0 : phi * pow(xl, gam) + (1 - phi) * pow(xl, beta);
            b[i * n + j] = bu - bl;
        }
}

static double sum(const double *x, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s += x[i];
    return s;
}

START_TEST(mass_is_conserved)
{
    enum { N = 12 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.01, N, &g), DEMILL_OK);
    double feed[N] = {0}, s[N], b[N * N], m[N];
    feed[0] = 3.0;
    feed[1] = 1.25;
    for (int i = 0; i < N; i++)
        s[i] = i == N - 1 ? 0.0 : 2.0 * pow(0.7, i); /* 2 down to 0.04 1/s */
    austin_b(N, b);
    G_OK(g, demill_grinding_set_feed(g, N, feed));
    G_OK(g, demill_grinding_set_rates(g, N, s));
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    for (int k = 0; k < 300; k++) {
        G_OK(g, demill_grinding_run(g, 0.01 * (1 + k % 7)));
        G_OK(g, demill_grinding_product(g, m, N, NULL));
        ck_assert_msg(fabs(sum(m, N) - 4.25) <= 1e-12 * 4.25, "run %d: mass %.17g, fed 4.25", k,
                      sum(m, N));
    }
    /* and over one long run, where the matrix is scaled and squared */
    G_OK(g, demill_grinding_run(g, 3600.0));
    G_OK(g, demill_grinding_product(g, m, N, NULL));
    ck_assert_msg(fabs(sum(m, N) - 4.25) <= 1e-12 * 4.25, "mass %.17g", sum(m, N));
    ck_assert(fabs(m[N - 1] - 4.25) < 1e-9); /* an hour: all in the sink */
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(one_class_decays_exponentially)
{
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.01, 2, &g), DEMILL_OK);
    double feed[2] = {1, 0}, s[2] = {0.3, 0}, b[4] = {0, 0, 1, 0}, m[2];
    G_OK(g, demill_grinding_set_feed(g, 2, feed));
    G_OK(g, demill_grinding_set_rates(g, 2, s));
    G_OK(g, demill_grinding_set_appearance(g, 4, b));
    for (int k = 1; k <= 20; k++) {
        G_OK(g, demill_grinding_run(g, 0.5 * k)); /* t = 0.25 k (k + 1) */
        double t;
        G_OK(g, demill_grinding_time(g, &t));
        ck_assert(fabs(t - 0.25 * k * (k + 1)) < 1e-12);
        G_OK(g, demill_grinding_product(g, m, 2, NULL));
        ck_assert_msg(fabs(m[0] - exp(-0.3 * t)) <= 1e-6, "t = %g: w = %.12g, e^-St = %.12g", t,
                      m[0], exp(-0.3 * t));
    }
    demill_grinding_destroy(g);
}
END_TEST

/* Reid (1965): with distinct rates, w_i(t) = sum_{j<=i} a_ij e^(-S_j t),
 * a_ij = 1/(S_i - S_j) sum_{k=j}^{i-1} S_k b_ik a_kj for j < i and
 * a_ii = w_i(0) - sum_{j<i} a_ij. */
static void reid(int n, const double *s, const double *b, const double *w0, double t, double *w)
{
    double *a = calloc((size_t)(n * n), sizeof *a);
    for (int i = 0; i < n; i++) {
        double off = 0;
        for (int j = 0; j < i; j++) {
            double x = 0;
            for (int k = j; k < i; k++)
                x += s[k] * b[i * n + k] * a[k * n + j];
            a[i * n + j] = x / (s[i] - s[j]);
            off += a[i * n + j];
        }
        a[i * n + i] = w0[i] - off;
    }
    for (int i = 0; i < n; i++) {
        w[i] = 0;
        for (int j = 0; j <= i; j++)
            w[i] += a[i * n + j] * exp(-s[j] * t);
    }
    free(a);
}

START_TEST(reid_closed_form)
{
    enum { N = 10 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.004, N, &g), DEMILL_OK);
    double feed[N] = {0.5, 0.3, 0.2}, s[N], b[N * N], m[N], w[N];
    for (int i = 0; i < N; i++)
        s[i] = i == N - 1 ? 0.0 : 0.05 * pow(0.75, i); /* distinct, 1/s */
    austin_b(N, b);
    G_OK(g, demill_grinding_set_feed(g, N, feed));
    G_OK(g, demill_grinding_set_rates(g, N, s));
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    double t = 0;
    const double steps[4] = {7.5, 30, 60, 240};
    for (int k = 0; k < 4; k++) {
        G_OK(g, demill_grinding_run(g, steps[k]));
        t += steps[k];
        G_OK(g, demill_grinding_product(g, m, N, NULL));
        reid(N, s, b, feed, t, w);
        for (int i = 0; i < N; i++)
            ck_assert_msg(fabs(m[i] - w[i]) <= 1e-6, "t = %g, class %d: %.12g, Reid %.12g", t, i,
                          m[i], w[i]);
    }
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(t10_and_t_family)
{
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.01, 8, &g), DEMILL_OK);
    G_OK(g, demill_grinding_set_jk(g, 60, 1.2, 3, table));
    /* E_cs = 1 kWh/t = 3600 J/kg: t10 = 60 (1 - e^-1.2) = 41.928347285 % */
    double t10;
    G_OK(g, demill_grinding_t10(g, 0.01, 3600, &t10));
    ck_assert_msg(fabs(t10 - 41.928347285) < 1e-8, "t10 = %.12g", t10);
    G_OK(g, demill_grinding_t10(g, 0.01, 0, &t10));
    ck_assert(t10 == 0);
    /* the table's own points */
    double tn[5];
    for (int r = 0; r < 3; r++) {
        G_OK(g, demill_grinding_tn(g, table[r * 6], tn));
        for (int k = 0; k < 5; k++)
            ck_assert_msg(fabs(tn[k] - table[r * 6 + 1 + k]) < 1e-12, "row %d col %d: %g", r, k,
                          tn[k]);
    }
    /* t2 at t10 = 15, by hand: secants δ0 = (50 - 30)/10 = 2, δ1 = 1.5; the
     * slope at t10 = 20 the weighted harmonic mean 60/(30/2 + 30/1.5) =
     * 1.7142857, at t10 = 10 ((2·10 + 10)·2 - 10·1.5)/20 = 2.25; the cubic
     * Hermite at the middle: 30/2 + 50/2 + 10 (2.25 - 1.7142857)/8 =
     * 40.669642857 %. Below the first row the first row scales: at t10 = 5,
     * t2 = 15 %. */
    G_OK(g, demill_grinding_tn(g, 15, tn));
    ck_assert_msg(fabs(tn[0] - 40.669642857) < 1e-8, "t2(15) = %.12g", tn[0]);
    G_OK(g, demill_grinding_tn(g, 5, tn));
    ck_assert(fabs(tn[0] - 15) < 1e-12 && fabs(tn[4] - 1.0) < 1e-12);
    ck_assert_int_eq(demill_grinding_tn(g, 31, tn), DEMILL_ERR_INVALID_VALUE);
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(appearance_from_the_model)
{
    enum { N = 14 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.02, N, &g), DEMILL_OK);
    G_OK(g, demill_grinding_set_jk(g, 60, 1.2, 3, table));
    G_OK(g, demill_grinding_set_appearance_energy(g, 900)); /* 0.25 kWh/t: t10 15.55 % */
    double b[N * N];
    G_OK(g, demill_grinding_appearance(g, b, N * N, NULL));
    for (int j = 0; j < N - 1; j++) {
        double s = 0;
        for (int i = j + 1; i < N; i++) {
            ck_assert(b[i * N + j] >= 0);
            s += b[i * N + j];
        }
        ck_assert_msg(fabs(s - 1) < 1e-12, "column %d sums to %.15g", j, s);
    }
    /* The model's appearance is accepted back as a user's. */
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    /* t10 = 60 (1 - e^-0.3) % = 15.551289 % is in the table's scaled range;
     * 40 kWh/t gives 59.5 %, beyond its last row, 30 %. */
    ck_assert_int_eq(demill_grinding_set_appearance_energy(g, 40 * 3600.0),
                     DEMILL_ERR_INVALID_VALUE);
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(tavares_king)
{
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.02, 8, &g), DEMILL_OK);
    /* E∞ 100 J/kg, d0 5 mm, φ 1: E50(5 mm) = 200 J/kg */
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 0, 5, 50, 1, 3, table));
    double f, f5, f50;
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 200, 1, &f));
    ck_assert_msg(fabs(f - 0.5) < 1e-12, "P(E50) = %.15g", f);
    /* ln(400/200)/0.8 = 0.866434 standard deviations: Φ = 0.806880 */
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 400, 1, &f));
    ck_assert_msg(fabs(f - 0.5 * erfc(-log(2.0) / 0.8 / sqrt(2.0))) < 1e-12, "P = %.15g", f);
    /* truncated at Emax = 3 E50: E' = E Emax/(Emax - E), E50' = 1.5 E50 */
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 3, 5, 50, 1, 3, table));
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 200, 1, &f));
    ck_assert(fabs(f - 0.5) < 1e-12);
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 100, 1, &f));
    double z = log((100 * 600.0 / 500) / (200 * 600.0 / 400)) / 0.8;
    ck_assert(fabs(f - 0.5 * erfc(-z / sqrt(2.0))) < 1e-12);
    /* repeated impacts weaken the survivors: more break, never all at once */
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 100, 5, &f5));
    G_OK(g, demill_grinding_broken_fraction(g, 0.005, 100, 50, &f50));
    ck_assert_msg(f < f5 && f5 < f50 && f50 <= 1, "%g %g %g", f, f5, f50);
    /* t10 = A'(1 - exp(-b' E/E50)): at E = E50, 50 (1 - e^-1) = 31.606028 % */
    double t10;
    G_OK(g, demill_grinding_t10(g, 0.005, 200, &t10));
    ck_assert(fabs(t10 - 50 * (1 - exp(-1.0))) < 1e-12);
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(passing_p80_and_energy)
{
    enum { N = 8 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.008, N, &g), DEMILL_OK);
    double limits[N + 1];
    size_t count;
    G_OK(g, demill_grinding_sizes(g, limits, N + 1, &count));
    ck_assert_uint_eq(count, N + 1);
    ck_assert(fabs(limits[2] - 0.004) < 1e-18 && limits[N] == 0);
    double feed[N] = {0, 0, 1, 0, 1, 0, 0, 0};
    G_OK(g, demill_grinding_set_feed(g, N, feed));
    /* half the mass finer than limit 3 (class 4), all finer than limit 2 */
    double f, x;
    G_OK(g, demill_grinding_passing(g, limits[3], &f));
    ck_assert(fabs(f - 0.5) < 1e-15);
    G_OK(g, demill_grinding_passing(g, limits[0], &f));
    ck_assert(fabs(f - 1) < 1e-15);
    /* P80: 0.8 lies 0.6 of the way from 0.5 to 1 across class 2, in ln x:
     * limit3 · √2^0.6 */
    G_OK(g, demill_grinding_size_passing(g, 0.8, &x));
    ck_assert_msg(fabs(x - limits[3] * pow(2.0, 0.3)) < 1e-15, "P80 %g", x);
    G_OK(g, demill_grinding_passing(g, x, &f));
    ck_assert(fabs(f - 0.8) < 1e-14);
    /* 100 W for 600 s on 5 kg: 12000 J/kg = 3.3333 kWh/t */
    double s[N] = {0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0}, b[N * N], e;
    austin_b(N, b);
    G_OK(g, demill_grinding_set_rates(g, N, s));
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    G_OK(g, demill_grinding_run(g, 600));
    G_OK(g, demill_grinding_specific_energy(g, 100, 5, &e));
    ck_assert(fabs(e - 100.0 * 600 / 5 / 3600) < 1e-12);
    demill_grinding_destroy(g);
}
END_TEST

/* Everything a grinding object shows, to compare before and after a call. */
typedef struct view {
    double mass[6], rates[6], b[36], time, t10, tn[5], limits[7];
    double damage_time;
    char error_kind;
} view;

static view look(demill_grinding *g)
{
    view v;
    memset(&v, 0, sizeof v);
    ck_assert_int_eq(demill_grinding_product(g, v.mass, 6, NULL), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_rates(g, v.rates, 6, NULL), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_appearance(g, v.b, 36, NULL), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_time(g, &v.time), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_t10(g, 0.01, 5000, &v.t10), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_tn(g, 12, v.tn), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_sizes(g, v.limits, 7, NULL), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_damage_time(g, &v.damage_time), DEMILL_OK);
    return v;
}

#define REFUSED(g, call, code)                                                                     \
    do {                                                                                           \
        view before_ = look(g);                                                                    \
        demill_status s_ = (call);                                                                 \
        ck_assert_msg(s_ == (code), "%s -> %d, expected %d", #call, (int)s_, (int)(code));         \
        ck_assert_msg(demill_grinding_last_error(g)[0] != '\0', "%s: no message", #call);          \
        view after_ = look(g);                                                                     \
        ck_assert_msg(memcmp(&before_, &after_, sizeof before_) == 0, "%s changed the object",     \
                      #call);                                                                      \
    } while (0)

START_TEST(bad_input_changes_nothing)
{
    enum { N = 6 };
    demill_grinding *g, *none = NULL;
    const double nan = NAN, inf = INFINITY;
    ck_assert_int_eq(demill_grinding_create(0.01, N, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_grinding_create(-1, N, &none), DEMILL_ERR_INVALID_VALUE);
    ck_assert_ptr_null(none);
    ck_assert_int_eq(demill_grinding_create(nan, N, &none), DEMILL_ERR_NOT_FINITE);
    ck_assert_int_eq(demill_grinding_create(0.01, 1, &none), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_grinding_run(NULL, 1), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_grinding_create(0.01, N, &g), DEMILL_OK);
    double feed[N] = {1, 2, 0, 0, 0, 0}, s[N] = {0.1, 0.08, 0.06, 0.04, 0.02, 0}, b[N * N];
    austin_b(N, b);
    /* no feed yet */
    double x;
    ck_assert_int_eq(demill_grinding_run(g, 1), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_grinding_size_passing(g, 0.8, &x), DEMILL_ERR_INVALID_VALUE);
    ck_assert_int_eq(demill_grinding_t10(g, 0.01, 1, &x), DEMILL_ERR_INVALID_VALUE); /* no model */
    G_OK(g, demill_grinding_set_feed(g, N, feed));
    G_OK(g, demill_grinding_set_rates(g, N, s));
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    G_OK(g, demill_grinding_set_jk(g, 55, 0.9, 3, table));
    G_OK(g, demill_grinding_run(g, 2));

    /* breakage model parameters: negative A or b, A above 100, NaN */
    REFUSED(g, demill_grinding_set_jk(g, -1, 0.9, 3, table), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_jk(g, 55, -0.1, 3, table), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_jk(g, 100.5, 0.9, 3, table), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_jk(g, nan, 0.9, 3, table), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_set_jk(g, 55, inf, 3, table), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 3, NULL), DEMILL_ERR_NULL_POINTER);
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 1, table), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_tavares(g, 100, 0.005, 1, -0.8, 0, 5, 50, 1, 3, table),
            DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 0.5, 5, 50, 1, 3, table),
            DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 0, 5, 101, 1, 3, table),
            DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_tavares(g, 100, nan, 1, 0.8, 0, 5, 50, 1, 3, table),
            DEMILL_ERR_NOT_FINITE);
    /* tables: t10 above 100 %, rows out of order, a row not monotone, NaN */
    double bad[18];
    memcpy(bad, table, sizeof bad);
    bad[12] = 101;
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 3, bad), DEMILL_ERR_INVALID_VALUE);
    memcpy(bad, table, sizeof bad);
    bad[6] = 35; /* t10 rows 10, 35, 30 */
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 3, bad), DEMILL_ERR_INVALID_VALUE);
    memcpy(bad, table, sizeof bad);
    bad[9] = 25; /* t25 above t10 */
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 3, bad), DEMILL_ERR_INVALID_VALUE);
    memcpy(bad, table, sizeof bad);
    bad[4] = nan;
    REFUSED(g, demill_grinding_set_jk(g, 55, 0.9, 3, bad), DEMILL_ERR_NOT_FINITE);

    /* feed: negative, zero in all, NaN, wrong count */
    double f2[N];
    memcpy(f2, feed, sizeof f2);
    f2[1] = -1;
    REFUSED(g, demill_grinding_set_feed(g, N, f2), DEMILL_ERR_INVALID_VALUE);
    memset(f2, 0, sizeof f2);
    REFUSED(g, demill_grinding_set_feed(g, N, f2), DEMILL_ERR_INVALID_VALUE);
    f2[0] = nan;
    REFUSED(g, demill_grinding_set_feed(g, N, f2), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_set_feed(g, N - 1, feed), DEMILL_ERR_INVALID_VALUE);
    /* rates: negative, the sink's not 0, inf */
    double s2[N];
    memcpy(s2, s, sizeof s2);
    s2[2] = -0.1;
    REFUSED(g, demill_grinding_set_rates(g, N, s2), DEMILL_ERR_INVALID_VALUE);
    memcpy(s2, s, sizeof s2);
    s2[N - 1] = 0.01;
    REFUSED(g, demill_grinding_set_rates(g, N, s2), DEMILL_ERR_INVALID_VALUE);
    s2[0] = inf;
    REFUSED(g, demill_grinding_set_rates(g, N, s2), DEMILL_ERR_NOT_FINITE);
    /* appearance: a column summing to 1 + 1e-8, mass going to a coarser
     * class (classes out of order), a negative value, NaN */
    double b2[N * N];
    memcpy(b2, b, sizeof b2);
    b2[3 * N + 1] += 1e-8;
    REFUSED(g, demill_grinding_set_appearance(g, N * N, b2), DEMILL_ERR_INVALID_VALUE);
    memcpy(b2, b, sizeof b2);
    b2[1 * N + 2] = 0.1;
    b2[5 * N + 2] -= 0.1;
    REFUSED(g, demill_grinding_set_appearance(g, N * N, b2), DEMILL_ERR_INVALID_VALUE);
    memcpy(b2, b, sizeof b2);
    b2[4 * N + 1] = -b2[4 * N + 1];
    REFUSED(g, demill_grinding_set_appearance(g, N * N, b2), DEMILL_ERR_INVALID_VALUE);
    b2[4 * N + 1] = nan;
    REFUSED(g, demill_grinding_set_appearance(g, N * N, b2), DEMILL_ERR_NOT_FINITE);
    /* times: 0, negative, NaN, inf */
    REFUSED(g, demill_grinding_run(g, 0), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_run(g, -5), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_run(g, nan), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_run(g, inf), DEMILL_ERR_NOT_FINITE);
    /* queries */
    REFUSED(g, demill_grinding_passing(g, 1e-9, &x), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_size_passing(g, 1.5, &x), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_size_passing(g, nan, &x), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_specific_energy(g, -1, 1, &x), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_specific_energy(g, 1, 0, &x), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_broken_fraction(g, 0.01, 10, 1, &x), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_appearance_energy(g, 0), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_product(g, f2, N - 1, NULL), DEMILL_ERR_BUFFER_TOO_SMALL);
    /* damage times below 0 or NaN */
    REFUSED(g, demill_grinding_set_damage_time(g, -1), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_set_damage_time(g, nan), DEMILL_ERR_NOT_FINITE);
    REFUSED(g, demill_grinding_damage_time(g, NULL), DEMILL_ERR_NULL_POINTER);
    /* Austin's extension: mu < 0, Lambda <= 0 with a mu, NaN */
    REFUSED(g, demill_grinding_extend_rates(g, 1, 0, -0.001, 3, NULL), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_extend_rates(g, 1, 0, 0.001, 0, NULL), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_extend_rates(g, 0, nan, 0, 0, NULL), DEMILL_ERR_NOT_FINITE);
    /* a world is not a grinding object */
    demill_world *w;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    ck_assert_int_eq(demill_grinding_run((demill_grinding *)(void *)w, 1),
                     DEMILL_ERR_INVALID_HANDLE);
    demill_world_destroy(w);
    demill_grinding_destroy(g);
}
END_TEST

/* Φ, the standard normal distribution function. */
static double phi_n(double z)
{
    return 0.5 * erfc(-z / sqrt(2.0));
}

START_TEST(rates_from_impacts)
{
    enum { N = 8, BINS = 4000 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.02, N, &g), DEMILL_OK);
    /* E∞ 100 J/kg, d0 5 mm, φ 1, σ 0.8, A' 30 % (t10 stays in the table) */
    const double sigma = 0.8, spread = 0.6, time = 2.0;
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, sigma, 0, 5, 30, 1, 3, table));
    /* Class i: C_i = 1000 (i + 1) impacts on N_i = 10 + i particles in 2 s,
     * their specific energies lognormal, median m_i = 50 (i + 1) J/kg and
     * spread 0.6 in ln E; the counts of 4000 logarithmic bins from 0.01 to
     * 1e5 J/kg are C_i times the distribution's mass in each. */
    static double edges[BINS + 1], counts[N * BINS];
    double particles[N];
    for (int k = 0; k <= BINS; k++)
        edges[k] = 0.01 * pow(1e7, (double)k / BINS);
    for (int i = 0; i < N; i++) {
        double c = 1000.0 * (i + 1), m = 50.0 * (i + 1);
        particles[i] = 10 + i;
        for (int k = 0; k < BINS; k++)
            counts[i * BINS + k] =
                c * (phi_n(log(edges[k + 1] / m) / spread) - phi_n(log(edges[k] / m) / spread));
    }
    G_OK(g, demill_grinding_rates_from_impacts(g, N, BINS, edges, counts, particles, time));
    double s[N];
    G_OK(g, demill_grinding_rates(g, s, N, NULL));
    /* By hand: an impact of energy E breaks a particle of fracture energy
     * E_f <= E. With ln E ~ N(ln m, s²) and ln E_f ~ N(ln E50, σ²)
     * independent, ln E_f - ln E ~ N(ln E50 - ln m, σ² + s²), so
     * P(break) = Φ(ln(m/E50) / √(σ² + s²)), and S_i = C_i/(N_i T) P, with
     * E50 = E∞ (1 + d0/d) at the class's geometric mean size d. */
    for (int i = 0; i < N - 1; i++) {
        double d = 0.02 * pow(2.0, -0.5 * i - 0.25), e50 = 100.0 * (1.0 + 0.005 / d);
        double p = phi_n(log(50.0 * (i + 1) / e50) / sqrt(sigma * sigma + spread * spread));
        double want = 1000.0 * (i + 1) / ((10 + i) * time) * p;
        ck_assert_msg(fabs(s[i] - want) <= 1e-5 * want, "S_%d = %.10g 1/s, by hand %.10g", i,
                      s[i], want);
    }
    ck_assert(s[N - 1] == 0.0); /* the sink does not break */

    /* Appearance: impacts in two bins only, at 150 and 400 J/kg (the bins'
     * midpoints), on class j. Column j is the mean of the model's columns
     * at those two energies (demill_grinding_set_appearance_energy on a
     * second object), weighted by each bin's breakage rate c/(N T) Φ(ln(E/E50)/σ). */
    double e2[3] = {100, 200, 600}, c2[N * 2] = {0}, b[N * N], b1[N * N], b2[N * N];
    demill_grinding *h;
    ck_assert_int_eq(demill_grinding_create(0.02, N, &h), DEMILL_OK);
    G_OK(h, demill_grinding_set_tavares(h, 100, 0.005, 1, sigma, 0, 5, 30, 1, 3, table));
    G_OK(h, demill_grinding_set_appearance_energy(h, 150));
    G_OK(h, demill_grinding_appearance(h, b1, N * N, NULL));
    G_OK(h, demill_grinding_set_appearance_energy(h, 400));
    G_OK(h, demill_grinding_appearance(h, b2, N * N, NULL));
    for (int j = 0; j < N; j++) {
        c2[j * 2] = 30;
        c2[j * 2 + 1] = 10;
    }
    G_OK(g, demill_grinding_rates_from_impacts(g, N, 2, e2, c2, particles, time));
    G_OK(g, demill_grinding_appearance(g, b, N * N, NULL));
    for (int j = 0; j < N - 1; j++) {
        double d = 0.02 * pow(2.0, -0.5 * j - 0.25), e50 = 100.0 * (1.0 + 0.005 / d);
        double w1 = 30 * phi_n(log(150 / e50) / sigma), w2 = 10 * phi_n(log(400 / e50) / sigma);
        double sum = 0;
        for (int i = 0; i < N; i++) {
            double want = (w1 * b1[i * N + j] + w2 * b2[i * N + j]) / (w1 + w2);
            ck_assert_msg(fabs(b[i * N + j] - want) <= 1e-14, "b[%d][%d] = %.15g, by hand %.15g",
                          i, j, b[i * N + j], want);
            sum += b[i * N + j];
        }
        ck_assert_msg(fabs(sum - 1) <= 1e-12, "column %d sums to %.15g", j, sum);
    }
    /* the rates and appearance are accepted back as a user's */
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    demill_grinding_destroy(h);
    demill_grinding_destroy(g);
}
END_TEST

START_TEST(rates_from_impacts_refused)
{
    enum { N = 6 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.01, N, &g), DEMILL_OK);
    double e[3] = {0, 100, 300}, c[N * 2] = {5, 1, 4, 2, 3, 3, 2, 4, 1, 5, 9, 9};
    double np[N] = {10, 10, 10, 10, 10, 0}; /* the sink's impacts are not used */
    /* no model, then the JKMRC model, which gives no breakage probability */
    ck_assert_int_eq(demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 1),
                     DEMILL_ERR_INVALID_VALUE);
    G_OK(g, demill_grinding_set_jk(g, 55, 0.9, 3, table));
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 1), DEMILL_ERR_INVALID_VALUE);
    demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 1);
    ck_assert_ptr_nonnull(strstr(demill_grinding_last_error(g), "JKMRC"));
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 0, 5, 30, 1, 3, table));
    G_OK(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 1));
    /* wrong class count, no bins, NULL, time <= 0 or NaN, edges out of
     * order, a negative count, impacts on a class without particles */
    REFUSED(g, demill_grinding_rates_from_impacts(g, N - 1, 2, e, c, np, 1),
            DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 0, e, c, np, 1), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, NULL, c, np, 1),
            DEMILL_ERR_NULL_POINTER);
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 0), DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, np, NAN), DEMILL_ERR_NOT_FINITE);
    double bad_e[3] = {0, 300, 100}, bad_c[N * 2], bad_np[N] = {10, 0, 10, 10, 10, 0};
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, bad_e, c, np, 1),
            DEMILL_ERR_INVALID_VALUE);
    memcpy(bad_c, c, sizeof bad_c);
    bad_c[3] = -1;
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, bad_c, np, 1),
            DEMILL_ERR_INVALID_VALUE);
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, bad_np, 1),
            DEMILL_ERR_INVALID_VALUE);
    /* a damage time in which a bin gives a particle more than 1e6 impacts
     * (class 0's first bin: 5 impacts on 10 particles in 1 s, 0.5 per
     * particle and second, 5e6 in 1e7 s) */
    G_OK(g, demill_grinding_set_damage_time(g, 1e7));
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, e, c, np, 1), DEMILL_ERR_INVALID_VALUE);
    G_OK(g, demill_grinding_set_damage_time(g, 0));
    /* a breaking bin whose t10 is beyond the table (A' 60 %, last row 30 %) */
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, 0.8, 0, 5, 60, 1, 3, table));
    double hot[3] = {0, 1e4, 1e5};
    REFUSED(g, demill_grinding_rates_from_impacts(g, N, 2, hot, c, np, 1),
            DEMILL_ERR_INVALID_VALUE);
    demill_grinding_destroy(g);
}
END_TEST

/* Tavares and King (2002): with the damage exponent γ = 2.5 the damage
 * equation D = [2γ/(2γ - 5D + 5) · E/Em]^(2γ/5) is D = E/(Em (2 - D)),
 * whose smallest root is D = 1 - √(1 - E/Em); the energy an impact leaves,
 * Em (1 - D) = √(Em² - E Em), is t when Em = (E + √(E² + 4t²))/2. So the
 * initial fracture energies below which particles break within k impacts
 * of E are E_1 = E, E_(k+1) = (E + √(E² + 4 E_k²))/2, and the fraction
 * broken within k impacts is F_k = Φ(ln(E_k/E50)/σ). A bin of λ impacts
 * per particle and second breaks, in a sequence of K, F_K of them over the
 * sum_{m<K} (1 - F_m) impacts a particle survives to receive (F_0 = 0):
 * S = λ F_K / sum_{m<K} (1 - F_m), K = λ t_d the impacts in the damage
 * time. */
static double damage_rate(double lambda, double e, double e50, double sigma, int impacts,
                          double *broken)
{
    double t = e, survived = 1.0, f = phi_n(log(t / e50) / sigma);
    for (int k = 1; k < impacts; k++) {
        survived += 1.0 - f;
        t = 0.5 * (e + sqrt(e * e + 4 * t * t));
        f = phi_n(log(t / e50) / sigma);
    }
    *broken = f;
    return lambda * f / survived;
}

START_TEST(damage_in_the_rates)
{
    enum { N = 6 };
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.02, N, &g), DEMILL_OK);
    const double sigma = 0.8, time = 2.0;
    G_OK(g, demill_grinding_set_tavares(g, 100, 0.005, 1, sigma, 0, 2.5, 30, 1, 3, table));
    /* one bin, 100-140 J/kg (E = 120 J/kg), 500 impacts on 10 particles of
     * each class in 2 s: λ = 25 impacts per particle and second */
    double edges[2] = {100, 140}, counts[N] = {500, 500, 500, 500, 500, 0}, particles[N];
    for (int i = 0; i < N; i++)
        particles[i] = 10;
    double td;
    G_OK(g, demill_grinding_damage_time(g, &td));
    ck_assert(td == 0); /* the default: single impacts */
    const int impacts[3] = {1, 20, 400}; /* λ t_d for t_d = 0 (K = 1), 0.8 and 16 s */
    const double damage_time[3] = {0, 0.8, 16};
    double s[3][N];
    for (int c = 0; c < 3; c++) {
        G_OK(g, demill_grinding_set_damage_time(g, damage_time[c]));
        G_OK(g, demill_grinding_rates_from_impacts(g, N, 1, edges, counts, particles, time));
        G_OK(g, demill_grinding_rates(g, s[c], N, NULL));
        for (int i = 0; i < N - 1; i++) {
            double d = 0.02 * pow(2.0, -0.5 * i - 0.25), e50 = 100.0 * (1.0 + 0.005 / d), f, fb;
            double want = damage_rate(25.0, 120.0, e50, sigma, impacts[c], &f);
            ck_assert_msg(fabs(s[c][i] - want) <= 1e-10 * want,
                          "K = %d, class %d: S = %.15g 1/s, by hand %.15g", impacts[c], i,
                          s[c][i], want);
            G_OK(g, demill_grinding_broken_fraction(g, d, 120.0, (uint32_t)impacts[c], &fb));
            ck_assert_msg(fabs(fb - f) <= 1e-12, "K = %d, class %d: F = %.15g, by hand %.15g",
                          impacts[c], i, fb, f);
        }
    }
    /* K = 1 is the single-impact rate λ Φ(ln(E/E50)/σ) (class 0: E50 =
     * 100 (1 + 5/16.82) J/kg = 129.7 J/kg); 400 impacts break all but
     * 1e-6 of class 0 (E_400 = 24,219 J/kg), so that S is λ over the mean
     * number of impacts to fracture */
    double e50 = 100.0 * (1.0 + 0.005 / (0.02 * pow(2.0, -0.25))), f400;
    ck_assert(fabs(s[0][0] - 25.0 * phi_n(log(120.0 / e50) / sigma)) <= 1e-12 * s[0][0]);
    damage_rate(25.0, 120.0, e50, sigma, 400, &f400);
    ck_assert_msg(f400 > 1 - 1e-6, "F_400 = %.15g", f400);
    demill_grinding_destroy(g);
}
END_TEST

/* Austin, Klimpel and Luckie (1984): S(x) = A (x/x0)^α / (1 + (x/μ)^Λ),
 * x0 = 1 mm, at the classes' upper limits. */
static double austin_s(double x, double a, double alpha, double mu, double big_lambda)
{
    double s = a * pow(x / 1e-3, alpha);
    return mu > 0 ? s / (1 + pow(x / mu, big_lambda)) : s;
}

START_TEST(rates_extended_below)
{
    enum { N = 12, MEASURED = 4 };
    const double a = 0.02, alpha = 1.2, mu = 0.004, big_lambda = 3;
    demill_grinding *g;
    ck_assert_int_eq(demill_grinding_create(0.01, N, &g), DEMILL_OK);
    double s[N] = {0}, b[N * N], fitted[2], s2[N], b2[N * N];
    for (int i = 0; i < MEASURED; i++) /* the classes the DEM charge holds */
        s[i] = austin_s(0.01 * pow(2.0, -0.5 * i), a, alpha, mu, big_lambda);
    austin_b(N, b);
    double feed[N] = {1, 1};
    G_OK(g, demill_grinding_set_feed(g, N, feed));
    G_OK(g, demill_grinding_set_rates(g, N, s));
    G_OK(g, demill_grinding_set_appearance(g, N * N, b));
    for (int fit = 1; fit >= 0; fit--) {
        G_OK(g, demill_grinding_set_rates(g, N, s));
        G_OK(g, demill_grinding_set_appearance(g, N * N, b));
        G_OK(g, demill_grinding_extend_rates(g, fit, fit ? 0.0 : alpha, mu, big_lambda, fitted));
        ck_assert_msg(fabs(fitted[0] - a) <= 1e-12 * a && fabs(fitted[1] - alpha) <= 1e-12,
                      "fit %d: A %.15g 1/s, alpha %.15g", fit, fitted[0], fitted[1]);
        G_OK(g, demill_grinding_rates(g, s2, N, NULL));
        G_OK(g, demill_grinding_appearance(g, b2, N * N, NULL));
        for (int i = 0; i < N - 1; i++) {
            double want = austin_s(0.01 * pow(2.0, -0.5 * i), a, alpha, mu, big_lambda);
            ck_assert_msg(fabs(s2[i] - want) <= 1e-12 * want, "S_%d = %.15g, the law %.15g", i,
                          s2[i], want);
        }
        ck_assert(s2[N - 1] == 0);
        /* each new column is the last measured one's, shifted down */
        for (int j = MEASURED; j < N - 1; j++) {
            int shift = j - (MEASURED - 1);
            double tail = 0;
            for (int r = N - 1 - shift; r < N; r++)
                tail += b[r * N + MEASURED - 1];
            for (int i = 0; i < N - 1; i++) {
                double want = i > j ? b[(i - shift) * N + MEASURED - 1] : 0.0;
                ck_assert(b2[i * N + j] == want);
            }
            ck_assert(fabs(b2[(N - 1) * N + j] - tail) <= 1e-15);
        }
        /* a whole appearance function, accepted back; the mass is kept */
        G_OK(g, demill_grinding_set_appearance(g, N * N, b2));
        G_OK(g, demill_grinding_run(g, 600));
        double m[N];
        G_OK(g, demill_grinding_product(g, m, N, NULL));
        ck_assert(fabs(sum(m, N) - 2) <= 1e-12 * 2);
    }
    /* a power law (no maximum) through two classes: α = ln(S1/S0)/ln(x1/x0) */
    double s3[N] = {0.01, 0.01 * pow(2.0, -0.5 * 0.9)};
    G_OK(g, demill_grinding_set_rates(g, N, s3));
    G_OK(g, demill_grinding_extend_rates(g, 1, 0, 0, 0, fitted));
    ck_assert(fabs(fitted[1] - 0.9) <= 1e-12);
    G_OK(g, demill_grinding_rates(g, s2, N, NULL));
    ck_assert(fabs(s2[7] - 0.01 * pow(2.0, -0.5 * 0.9 * 7)) <= 1e-14);
    /* one class with a rate is not enough to fit α; none is nothing to extend */
    double s4[N] = {0.01};
    G_OK(g, demill_grinding_set_rates(g, N, s4));
    ck_assert_int_eq(demill_grinding_extend_rates(g, 1, 0, 0, 0, NULL), DEMILL_ERR_INVALID_VALUE);
    G_OK(g, demill_grinding_rates(g, s2, N, NULL));
    ck_assert(memcmp(s2, s4, sizeof s4) == 0); /* refused, unchanged */
    G_OK(g, demill_grinding_extend_rates(g, 0, 1.0, 0, 0, NULL));
    double s5[N] = {0};
    G_OK(g, demill_grinding_set_rates(g, N, s5));
    ck_assert_int_eq(demill_grinding_extend_rates(g, 0, 1.0, 0, 0, NULL), DEMILL_ERR_INVALID_VALUE);
    demill_grinding_destroy(g);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("grinding");
    TCase *tc = tcase_create("grinding");
    tcase_add_test(tc, mass_is_conserved);
    tcase_add_test(tc, one_class_decays_exponentially);
    tcase_add_test(tc, reid_closed_form);
    tcase_add_test(tc, t10_and_t_family);
    tcase_add_test(tc, appearance_from_the_model);
    tcase_add_test(tc, tavares_king);
    tcase_add_test(tc, passing_p80_and_energy);
    tcase_add_test(tc, bad_input_changes_nothing);
    tcase_add_test(tc, rates_from_impacts);
    tcase_add_test(tc, rates_from_impacts_refused);
    tcase_add_test(tc, damage_in_the_rates);
    tcase_add_test(tc, rates_extended_below);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
