/* grinding.c: the grinding object's API (include/demill/grinding.h): its
 * life, its size classes, feed, rates and appearance function, the ore
 * breakage models and the runs of the population balance. Each function
 * checks all its arguments before it changes anything. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/status.h"
#include "grinding/grinding.h"

/* The base keeps a message for anything that begins with a dm_base; its
 * functions name that a world. */
static demill_world *as_world(const demill_grinding *g)
{
    return (demill_world *)(void *)(uintptr_t)g;
}

static demill_status check(const demill_grinding *g)
{
    if (!g)
        return DEMILL_ERR_NULL_POINTER;
    if (g->base.magic != DM_GRINDING_MAGIC)
        return DEMILL_ERR_INVALID_HANDLE;
    return DEMILL_OK;
}

#define CHECK(g)                                                                                   \
    do {                                                                                           \
        demill_status c_ = check(g);                                                               \
        if (c_)                                                                                    \
            return c_;                                                                             \
    } while (0)

#define FAIL(g, code, ...) dm_fail(as_world(g), code, __VA_ARGS__)

static void ok(const demill_grinding *g)
{
    dm_clear_error(as_world(g));
}

double dm_class_limit(const demill_grinding *g, uint32_t i)
{
    return g->top * pow(2.0, -0.5 * i);
}

/* Checks that n values are finite; names the first that is not. */
static demill_status finite_all(const demill_grinding *g, const char *what, size_t n,
                                const double *x)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s[%zu] is %g", what, k, x[k]);
    return DEMILL_OK;
}

/* Copies n doubles out in the NULL-asks-the-count pattern. */
static demill_status read_out(const demill_grinding *g, const char *what, const double *src,
                              size_t n, double *out, size_t capacity, size_t *count)
{
    if (!out && !count)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: both the buffer and count are NULL", what);
    if (count)
        *count = n;
    if (out) {
        if (capacity < n)
            return FAIL(g, DEMILL_ERR_BUFFER_TOO_SMALL, "%s: the buffer holds %zu, %zu needed",
                        what, capacity, n);
        memcpy(out, src, n * sizeof *out);
    }
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_create(double top_size, uint32_t classes,
                                                demill_grinding **out)
{
    if (!out)
        return DEMILL_ERR_NULL_POINTER;
    *out = NULL;
    if (!isfinite(top_size))
        return DEMILL_ERR_NOT_FINITE;
    if (!(top_size > 0) || classes < 2 || classes > DM_GRINDING_MAX_CLASSES)
        return DEMILL_ERR_INVALID_VALUE;
    demill_grinding *g = calloc(1, sizeof *g);
    size_t n = classes;
    if (g) {
        g->mass = calloc(n, sizeof *g->mass);
        g->s = calloc(n, sizeof *g->s);
        g->b = calloc(n * n, sizeof *g->b);
    }
    if (!g || !g->mass || !g->s || !g->b) {
        if (g) {
            free(g->mass);
            free(g->s);
            free(g->b);
        }
        free(g);
        return DEMILL_ERR_OUT_OF_MEMORY;
    }
    g->base.magic = DM_GRINDING_MAGIC;
    g->n = classes;
    g->top = top_size;
    *out = g;
    return DEMILL_OK;
}

DEMILL_API void demill_grinding_destroy(demill_grinding *g)
{
    if (check(g))
        return;
    g->base.magic = 0;
    free(g->mass);
    free(g->s);
    free(g->b);
    free(g->ore.table);
    free(g);
}

DEMILL_API const char *demill_grinding_last_error(const demill_grinding *g)
{
    if (!g)
        return "grinding object is NULL";
    if (g->base.magic != DM_GRINDING_MAGIC)
        return "not a demill grinding object (destroyed or never created)";
    return g->base.error;
}

DEMILL_API demill_status demill_grinding_sizes(const demill_grinding *g, double *limits,
                                               size_t capacity, size_t *count)
{
    CHECK(g);
    double lim[DM_GRINDING_MAX_CLASSES + 1];
    for (uint32_t i = 0; i < g->n; i++)
        lim[i] = dm_class_limit(g, i);
    lim[g->n] = 0.0;
    return read_out(g, "demill_grinding_sizes", lim, g->n + 1u, limits, capacity, count);
}

/* Checks that n is the number of classes (or its square) and the values are
 * there and finite. */
static demill_status check_array(const demill_grinding *g, const char *what, size_t n,
                                 size_t want, const double *x)
{
    if (!x)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: the values are NULL", what);
    if (n != want)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: %zu values given, %zu needed", what, n,
                    want);
    return finite_all(g, what, n, x);
}

DEMILL_API demill_status demill_grinding_set_feed(demill_grinding *g, size_t n, const double *mass)
{
    CHECK(g);
    demill_status st = check_array(g, "feed", n, g->n, mass);
    if (st)
        return st;
    double total = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (mass[i] < 0)
            return FAIL(g, DEMILL_ERR_INVALID_VALUE, "feed[%zu] is %g, below 0", i, mass[i]);
        total += mass[i];
    }
    if (!(total > 0) || !isfinite(total))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "the feed's masses sum to %g, not a positive mass",
                    total);
    memcpy(g->mass, mass, n * sizeof *mass);
    g->total = total;
    g->time = 0.0;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_set_rates(demill_grinding *g, size_t n,
                                                   const double *rates)
{
    CHECK(g);
    demill_status st = check_array(g, "rates", n, g->n, rates);
    if (st)
        return st;
    for (size_t i = 0; i < n; i++)
        if (rates[i] < 0)
            return FAIL(g, DEMILL_ERR_INVALID_VALUE, "rates[%zu] is %g 1/s, below 0", i,
                        rates[i]);
    if (rates[n - 1] != 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "rates[%zu] is %g 1/s: the last class is the sink and does not break", n - 1,
                    rates[n - 1]);
    memcpy(g->s, rates, n * sizeof *rates);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_rates(const demill_grinding *g, double *rates,
                                               size_t capacity, size_t *count)
{
    CHECK(g);
    return read_out(g, "demill_grinding_rates", g->s, g->n, rates, capacity, count);
}

DEMILL_API demill_status demill_grinding_set_appearance(demill_grinding *g, size_t n,
                                                        const double *b)
{
    CHECK(g);
    size_t c = g->n;
    demill_status st = check_array(g, "appearance", n, c * c, b);
    if (st)
        return st;
    for (size_t j = 0; j < c; j++) {
        double sum = 0.0;
        for (size_t i = 0; i < c; i++) {
            double x = b[i * c + j];
            if (x < 0 || x > 1)
                return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                            "appearance b[%zu][%zu] is %g, not a fraction in [0, 1]", i, j, x);
            if ((i <= j || j == c - 1) && x != 0)
                return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                            "appearance b[%zu][%zu] is %g: broken mass must leave its class for "
                            "finer ones, and the sink (class %zu) does not break",
                            i, j, x, c - 1);
            sum += x;
        }
        if (j < c - 1 && fabs(sum - 1.0) > 1e-9)
            return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                        "appearance column %zu sums to %.12g, not 1 (within 1e-9)", j, sum);
    }
    memcpy(g->b, b, n * sizeof *b);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_appearance(const demill_grinding *g, double *b,
                                                    size_t capacity, size_t *count)
{
    CHECK(g);
    return read_out(g, "demill_grinding_appearance", g->b, (size_t)g->n * g->n, b, capacity,
                    count);
}

/* Checks a model's t-family table and installs the model: the one place
 * that replaces g->ore. */
static demill_status set_ore(demill_grinding *g, const dm_ore *ore, size_t rows,
                             const double *table)
{
    if (!table)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "the t-family table is NULL");
    if (rows < 2 || rows > DM_TFAMILY_MAX_ROWS)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "the t-family table has %zu rows, not 2 to %u",
                    rows, DM_TFAMILY_MAX_ROWS);
    size_t n = rows * DM_TFAMILY_COLUMNS;
    demill_status st = finite_all(g, "t-family table", n, table);
    if (st)
        return st;
    char why[256];
    if (dm_tfamily_check(rows, table, why, sizeof why))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s", why);
    double *copy = malloc(n * sizeof *copy);
    if (!copy)
        return FAIL(g, DEMILL_ERR_OUT_OF_MEMORY, "no memory for the t-family table");
    memcpy(copy, table, n * sizeof *copy);
    free(g->ore.table);
    g->ore = *ore;
    g->ore.rows = rows;
    g->ore.table = copy;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_set_jk(demill_grinding *g, double a, double b,
                                                size_t rows, const double *table)
{
    CHECK(g);
    if (!isfinite(a) || !isfinite(b))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "JKMRC model: A = %g, b = %g", a, b);
    if (a < 0 || a > 100)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "JKMRC model: A = %g %%, not in [0, 100] (t10 is a percentage)", a);
    if (b < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "JKMRC model: b = %g t/kWh, below 0", b);
    dm_ore ore = {.model = DM_ORE_JK, .a = a, .b = b};
    return set_ore(g, &ore, rows, table);
}

DEMILL_API demill_status demill_grinding_set_tavares(demill_grinding *g, double e_inf, double d0,
                                                     double phi, double sigma, double emax_ratio,
                                                     double gamma, double a_prime,
                                                     double b_prime, size_t rows,
                                                     const double *table)
{
    CHECK(g);
    const double v[8] = {e_inf, d0, phi, sigma, emax_ratio, gamma, a_prime, b_prime};
    static const char *const name[8] = {"e_inf", "d0",    "phi",     "sigma",
                                        "emax_ratio", "gamma", "a_prime", "b_prime"};
    for (int k = 0; k < 8; k++)
        if (!isfinite(v[k]))
            return FAIL(g, DEMILL_ERR_NOT_FINITE, "Tavares and King model: %s is %g", name[k],
                        v[k]);
    for (int k = 0; k < 6; k++)
        if (k != 4 && !(v[k] > 0))
            return FAIL(g, DEMILL_ERR_INVALID_VALUE, "Tavares and King model: %s = %g, not > 0",
                        name[k], v[k]);
    if (emax_ratio != 0 && !(emax_ratio > 1))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "Tavares and King model: emax_ratio = %g, not > 1 (or 0 for no truncation)",
                    emax_ratio);
    if (a_prime < 0 || a_prime > 100)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "Tavares and King model: a_prime = %g %%, not in [0, 100]", a_prime);
    if (b_prime < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "Tavares and King model: b_prime = %g, below 0",
                    b_prime);
    dm_ore ore = {.model = DM_ORE_TAVARES,
                  .a = a_prime,
                  .b = b_prime,
                  .e_inf = e_inf,
                  .d0 = d0,
                  .phi = phi,
                  .sigma = sigma,
                  .emax_ratio = emax_ratio,
                  .gamma = gamma};
    return set_ore(g, &ore, rows, table);
}

/* Checks that a model is set and a size and an energy are usable. */
static demill_status check_model(const demill_grinding *g, const char *what, double size,
                                 double energy)
{
    if (!isfinite(size) || !isfinite(energy))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: size %g m, energy %g J/kg", what, size, energy);
    if (g->ore.model == DM_ORE_NONE)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: no breakage model set", what);
    if (!(size > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: size %g m, not > 0", what, size);
    if (energy < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: energy %g J/kg, below 0", what, energy);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_t10(const demill_grinding *g, double size, double energy,
                                             double *t10)
{
    CHECK(g);
    if (!t10)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "demill_grinding_t10: t10 is NULL");
    demill_status st = check_model(g, "demill_grinding_t10", size, energy);
    if (st)
        return st;
    *t10 = dm_ore_t10(&g->ore, size, energy);
    ok(g);
    return DEMILL_OK;
}

/* Checks that t10 is in the range where the table gives the t-family. */
static demill_status check_t10(const demill_grinding *g, const char *what, double t10)
{
    double last = g->ore.table[(g->ore.rows - 1) * DM_TFAMILY_COLUMNS];
    if (!(t10 > 0) || t10 > last)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: t10 = %g %% is outside (0, %g %%], the t-family table's range: extend "
                    "the table",
                    what, t10, last);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_tn(const demill_grinding *g, double t10, double *tn)
{
    CHECK(g);
    if (!tn)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "demill_grinding_tn: tn is NULL");
    if (!isfinite(t10))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "demill_grinding_tn: t10 is %g", t10);
    if (g->ore.model == DM_ORE_NONE)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "demill_grinding_tn: no breakage model set");
    demill_status st = check_t10(g, "demill_grinding_tn", t10);
    if (st)
        return st;
    dm_tfamily_at(&g->ore, t10, tn);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_broken_fraction(const demill_grinding *g, double size,
                                                         double energy, uint32_t impacts,
                                                         double *fraction)
{
    CHECK(g);
    if (!fraction)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "demill_grinding_broken_fraction: fraction is NULL");
    demill_status st = check_model(g, "demill_grinding_broken_fraction", size, energy);
    if (st)
        return st;
    if (g->ore.model != DM_ORE_TAVARES)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "demill_grinding_broken_fraction: the JKMRC model gives no probability of "
                    "breakage; set Tavares and King's");
    if (impacts < 1)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "demill_grinding_broken_fraction: 0 impacts, at least 1 needed");
    *fraction = dm_tk_broken(&g->ore, size, energy, impacts);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_set_appearance_energy(demill_grinding *g, double energy)
{
    CHECK(g);
    const char *what = "demill_grinding_set_appearance_energy";
    demill_status st = check_model(g, what, g->top, energy);
    if (st)
        return st;
    if (!(energy > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: energy %g J/kg, not > 0", what, energy);
    size_t n = g->n;
    double t10[DM_GRINDING_MAX_CLASSES];
    for (uint32_t j = 0; j + 1 < n; j++) {
        double parent = dm_class_limit(g, j) / pow(2.0, 0.25);
        t10[j] = dm_ore_t10(&g->ore, parent, energy);
        char where[96];
        snprintf(where, sizeof where, "%s, class %u", what, j);
        if ((st = check_t10(g, where, t10[j])))
            return st;
    }
    double *b = calloc(n * n, sizeof *b), col[DM_GRINDING_MAX_CLASSES];
    if (!b)
        return FAIL(g, DEMILL_ERR_OUT_OF_MEMORY, "%s: no memory", what);
    for (uint32_t j = 0; j + 1 < n; j++) {
        dm_appearance_column(g, j, t10[j], col);
        for (size_t i = 0; i < n; i++)
            b[i * n + j] = col[i];
    }
    memcpy(g->b, b, n * n * sizeof *b);
    free(b);
    ok(g);
    return DEMILL_OK;
}

#define DM_IMPACT_MAX_BINS 10000u
#define DM_DAMAGE_MAX_IMPACTS 1000000.0 /* per particle and bin in the damage time */

/* Checks the arguments of demill_grinding_rates_from_impacts(). */
static demill_status check_impacts(const demill_grinding *g, const char *what, size_t classes,
                                   size_t bins, const double *edges, const double *counts,
                                   const double *particles, double time)
{
    if (!edges || !counts || !particles)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: edges, counts or particles is NULL", what);
    if (classes != g->n)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: %zu classes given, the object has %u", what,
                    classes, g->n);
    if (bins < 1 || bins > DM_IMPACT_MAX_BINS)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: %zu energy bins, not 1 to %u", what, bins,
                    DM_IMPACT_MAX_BINS);
    demill_status st;
    if ((st = finite_all(g, "impact energy edges", bins + 1, edges)) ||
        (st = finite_all(g, "impact counts", classes * bins, counts)) ||
        (st = finite_all(g, "particles", classes, particles)))
        return st;
    if (!isfinite(time))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: time is %g", what, time);
    if (!(time > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: time %g s, not > 0", what, time);
    if (edges[0] < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: the first energy edge is %g J/kg, below 0",
                    what, edges[0]);
    for (size_t k = 0; k < bins; k++)
        if (!(edges[k + 1] > edges[k]))
            return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                        "%s: energy edge %zu (%g J/kg) is not above edge %zu (%g J/kg)", what,
                        k + 1, edges[k + 1], k, edges[k]);
    for (size_t i = 0; i < classes; i++) {
        if (particles[i] < 0)
            return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: particles[%zu] is %g, below 0", what, i,
                        particles[i]);
        double total = 0.0;
        for (size_t k = 0; k < bins; k++) {
            if (counts[i * bins + k] < 0)
                return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: counts[%zu] is %g, below 0", what,
                            i * bins + k, counts[i * bins + k]);
            total += counts[i * bins + k];
        }
        if (total > 0 && !(particles[i] > 0) && i + 1 < classes)
            return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                        "%s: class %zu has %g impacts but no particles to receive them", what, i,
                        total);
    }
    if (g->ore.model == DM_ORE_NONE)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: no breakage model set", what);
    if (g->ore.model != DM_ORE_TAVARES)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: the JKMRC model gives no probability that an impact breaks a particle; "
                    "set Tavares and King's",
                    what);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_rates_from_impacts(demill_grinding *g, size_t classes,
                                                            size_t bins, const double *edges,
                                                            const double *counts,
                                                            const double *particles, double time)
{
    CHECK(g);
    const char *what = "demill_grinding_rates_from_impacts";
    demill_status st = check_impacts(g, what, classes, bins, edges, counts, particles, time);
    if (st)
        return st;
    size_t n = g->n;
    double *s = calloc(n, sizeof *s), *b = calloc(n * n, sizeof *b), col[DM_GRINDING_MAX_CLASSES];
    if (!s || !b) {
        free(s);
        free(b);
        return FAIL(g, DEMILL_ERR_OUT_OF_MEMORY, "%s: no memory", what);
    }
    for (uint32_t j = 0; j + 1 < n; j++) {
        double size = dm_class_limit(g, j) / pow(2.0, 0.25); /* the geometric mean */
        for (size_t k = 0; k < bins; k++) {
            double c = counts[j * bins + k];
            if (c == 0)
                continue;
            double e = 0.5 * (edges[k] + edges[k + 1]), broken, survived;
            double lambda = c / (particles[j] * time); /* per particle and second */
            /* the bin's impacts break F_K of the particles within a sequence
             * of the K a particle receives in the damage time, over the time
             * of the impacts they survive to receive */
            double impacts = fmax(1.0, round(lambda * g->damage_time));
            if (impacts > DM_DAMAGE_MAX_IMPACTS) {
                free(s);
                free(b);
                return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                            "%s, class %u, energy %g J/kg: %.6g impacts per particle in the "
                            "damage time %g s, more than %g: shorten it",
                            what, j, e, impacts, g->damage_time, DM_DAMAGE_MAX_IMPACTS);
            }
            dm_tk_sequence(&g->ore, size, e, (uint32_t)impacts, &broken, &survived);
            double w = lambda * broken / survived;
            if (w == 0)
                continue;
            double t10 = dm_ore_t10(&g->ore, size, e);
            char where[128];
            snprintf(where, sizeof where, "%s, class %u, energy %g J/kg", what, j, e);
            if ((st = check_t10(g, where, t10))) {
                free(s);
                free(b);
                return st;
            }
            s[j] += w;
            dm_appearance_column(g, j, t10, col);
            for (size_t i = j + 1; i < n; i++)
                b[i * n + j] += w * col[i];
        }
        for (size_t i = j + 1; s[j] > 0 && i < n; i++)
            b[i * n + j] /= s[j];
    }
    memcpy(g->s, s, n * sizeof *s);
    memcpy(g->b, b, n * n * sizeof *b);
    free(s);
    free(b);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_set_damage_time(demill_grinding *g, double time)
{
    CHECK(g);
    const char *what = "demill_grinding_set_damage_time";
    if (!isfinite(time))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: time is %g", what, time);
    if (time < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: time %g s, below 0", what, time);
    g->damage_time = time;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_damage_time(const demill_grinding *g, double *time)
{
    CHECK(g);
    if (!time)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "demill_grinding_damage_time: time is NULL");
    *time = g->damage_time;
    ok(g);
    return DEMILL_OK;
}

/* Austin, Klimpel and Luckie (1984, Process Engineering of Size Reduction:
 * Ball Milling): the specific rate of breakage against size,
 * S(x) = A (x/x0)^α / (1 + (x/μ)^Λ), x0 = 1 mm; this is its logarithm less
 * ln A, with no maximum (a pure power law) when mu is 0. */
static double austin_log_shape(double x, double alpha, double mu, double big_lambda)
{
    double u = alpha * log(x / 1e-3);
    return mu > 0 ? u - log1p(pow(x / mu, big_lambda)) : u;
}

DEMILL_API demill_status demill_grinding_extend_rates(demill_grinding *g, int32_t fit_alpha,
                                                      double alpha, double mu, double big_lambda,
                                                      double *fitted)
{
    CHECK(g);
    const char *what = "demill_grinding_extend_rates";
    if (!isfinite(alpha) || !isfinite(mu) || !isfinite(big_lambda))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: alpha %g, mu %g m, Lambda %g", what, alpha, mu,
                    big_lambda);
    if (mu < 0 || (mu > 0 && !(big_lambda > 0)))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: mu %g m must be > 0 with Lambda %g > 0, or 0 for no maximum", what, mu,
                    big_lambda);
    const uint32_t n = g->n;
    uint32_t with = 0, finest = 0;
    for (uint32_t i = 0; i + 1 < n; i++)
        if (g->s[i] > 0) {
            with++;
            finest = i;
        }
    if (with == 0 || (fit_alpha && with < 2))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: %u classes have a rate; %s needs at least %d", what, with,
                    fit_alpha ? "fitting alpha" : "fitting A", fit_alpha ? 2 : 1);
    double sum = 0.0;
    for (uint32_t i = finest + 1; i < n; i++)
        sum += g->b[i * n + finest];
    if (fabs(sum - 1.0) > 1e-9)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: the appearance column of class %u, the finest with a rate, sums to %g, "
                    "not 1: set the appearance function first",
                    what, finest, sum);
    /* Least squares in the logarithms over the classes with a rate:
     * ln S_i = ln A + α ln(x_i/x0) - ln(1 + (x_i/μ)^Λ), x_i the class's
     * upper limit; for α, the slope of the regression line. */
    double su = 0, sv = 0, suu = 0, suv = 0;
    for (uint32_t i = 0; i + 1 < n; i++) {
        if (!(g->s[i] > 0))
            continue;
        double x = dm_class_limit(g, i), u = log(x / 1e-3);
        double v = log(g->s[i]) - austin_log_shape(x, 0.0, mu, big_lambda);
        su += u;
        sv += v;
        suu += u * u;
        suv += u * v;
    }
    if (fit_alpha)
        alpha = (suv - su * sv / with) / (suu - su * su / with);
    double log_a = (sv - alpha * su) / with;
    if (!isfinite(log_a) || !isfinite(alpha))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: the fit gives A = e^%g, alpha %g", what, log_a,
                    alpha);
    /* the finer classes: the law's rates, and the finest measured class's
     * appearance column shifted down by as many classes (a normalisable
     * breakage function, Austin et al. 1984), what would fall past the sink
     * into the sink */
    double *s = malloc(n * sizeof *s), *b = malloc((size_t)n * n * sizeof *b);
    if (!s || !b) {
        free(s);
        free(b);
        return FAIL(g, DEMILL_ERR_OUT_OF_MEMORY, "%s: no memory", what);
    }
    memcpy(s, g->s, n * sizeof *s);
    memcpy(b, g->b, (size_t)n * n * sizeof *b);
    for (uint32_t j = finest + 1; j + 1 < n; j++) {
        s[j] = exp(log_a + austin_log_shape(dm_class_limit(g, j), alpha, mu, big_lambda));
        uint32_t shift = j - finest;
        for (uint32_t i = 0; i < n; i++)
            b[i * n + j] = i > j && i + 1 < n ? g->b[(i - shift) * n + finest] : 0.0;
        double tail = 0.0;
        for (uint32_t r = n - 1 - shift; r < n; r++)
            tail += g->b[r * n + finest];
        b[(n - 1) * n + j] = tail;
    }
    memcpy(g->s, s, n * sizeof *s);
    memcpy(g->b, b, (size_t)n * n * sizeof *b);
    free(s);
    free(b);
    if (fitted) {
        fitted[0] = exp(log_a);
        fitted[1] = alpha;
    }
    ok(g);
    return DEMILL_OK;
}

static demill_status check_feed(const demill_grinding *g, const char *what)
{
    if (!(g->total > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: no feed set (demill_grinding_set_feed)",
                    what);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_run(demill_grinding *g, double time)
{
    CHECK(g);
    if (!isfinite(time))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "demill_grinding_run: time is %g", time);
    if (!(time > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "demill_grinding_run: time %g s, not > 0", time);
    demill_status st = check_feed(g, "demill_grinding_run");
    if (st)
        return st;
    if ((st = dm_balance_advance(g, time, g->mass)))
        return FAIL(g, st, "demill_grinding_run: no memory for %u classes", g->n);
    g->time += time;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_time(const demill_grinding *g, double *time)
{
    CHECK(g);
    if (!time)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "demill_grinding_time: time is NULL");
    *time = g->time;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_product(const demill_grinding *g, double *mass,
                                                 size_t capacity, size_t *count)
{
    CHECK(g);
    return read_out(g, "demill_grinding_product", g->mass, g->n, mass, capacity, count);
}

DEMILL_API demill_status demill_grinding_passing(const demill_grinding *g, double size,
                                                 double *fraction)
{
    CHECK(g);
    const char *what = "demill_grinding_passing";
    if (!fraction)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: fraction is NULL", what);
    if (!isfinite(size))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: size is %g", what, size);
    demill_status st = check_feed(g, what);
    if (st)
        return st;
    double sink = dm_class_limit(g, g->n - 1);
    if (size < sink)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: size %g m is below the finest class limit, %g m, where the "
                    "distribution is not known",
                    what, size, sink);
    *fraction = dm_balance_passing(g, size);
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_size_passing(const demill_grinding *g, double fraction,
                                                      double *size)
{
    CHECK(g);
    const char *what = "demill_grinding_size_passing";
    if (!size)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: size is NULL", what);
    if (!isfinite(fraction))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: fraction is %g", what, fraction);
    if (!(fraction > 0) || fraction > 1)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE, "%s: fraction %g, not in (0, 1]", what,
                    fraction);
    demill_status st = check_feed(g, what);
    if (st)
        return st;
    double x = dm_balance_size(g, fraction);
    if (x < 0)
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: the finest class (below %g m) alone holds more than %g of the mass, so "
                    "the size is not known: add classes",
                    what, dm_class_limit(g, g->n - 1), fraction);
    *size = x;
    ok(g);
    return DEMILL_OK;
}

DEMILL_API demill_status demill_grinding_specific_energy(const demill_grinding *g, double power,
                                                         double ore_mass, double *kwh_t)
{
    CHECK(g);
    const char *what = "demill_grinding_specific_energy";
    if (!kwh_t)
        return FAIL(g, DEMILL_ERR_NULL_POINTER, "%s: kwh_t is NULL", what);
    if (!isfinite(power) || !isfinite(ore_mass))
        return FAIL(g, DEMILL_ERR_NOT_FINITE, "%s: power %g W, ore mass %g kg", what, power,
                    ore_mass);
    if (power < 0 || !(ore_mass > 0))
        return FAIL(g, DEMILL_ERR_INVALID_VALUE,
                    "%s: power %g W must be >= 0 and the ore mass %g kg > 0", what, power,
                    ore_mass);
    *kwh_t = power * g->time / ore_mass / 3600.0; /* J/kg to kWh/t: 1 kWh/t = 3600 J/kg */
    ok(g);
    return DEMILL_OK;
}
