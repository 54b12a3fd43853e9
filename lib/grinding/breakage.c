/* breakage.c: the ore breakage models: the JKMRC drop-weight model's t10,
 * Tavares and King's fracture energy distribution with damage, the
 * t-family interpolation and the appearance function that follows from
 * them (docs/grinding.md, Breakage models). */
#include <math.h>
#include <stdio.h>

#include "grinding/grinding.h"

/* The relative sizes 1/n of the t-family's columns after t10: n = 2, 4,
 * 25, 50, 75 (column 0 of a table row is t10, n = 10). */
static const double tn_n[5] = {2, 4, 25, 50, 75};

int dm_tfamily_check(size_t rows, const double *table, char *why, size_t len)
{
    if (rows < 2 || rows > DM_TFAMILY_MAX_ROWS) {
        snprintf(why, len, "the t-family table has %zu rows, not 2 to %u", rows,
                 DM_TFAMILY_MAX_ROWS);
        return 1;
    }
    for (size_t r = 0; r < rows; r++) {
        const double *t = table + r * DM_TFAMILY_COLUMNS;
        /* in decreasing order of size: t2, t4, t10, t25, t50, t75 */
        const double ordered[6] = {t[1], t[2], t[0], t[3], t[4], t[5]};
        for (int c = 0; c < 6; c++) {
            if (!(ordered[c] > 0.0 && ordered[c] <= 100.0)) {
                snprintf(why, len, "t-family table row %zu: %g %% is not in (0, 100]", r,
                         ordered[c]);
                return 1;
            }
            if (c > 0 && ordered[c] > ordered[c - 1]) {
                snprintf(why, len,
                         "t-family table row %zu: the percentages passing must not grow as the "
                         "size falls (t2 >= t4 >= t10 >= t25 >= t50 >= t75)",
                         r);
                return 1;
            }
        }
        if (r > 0 && !(t[0] > t[-DM_TFAMILY_COLUMNS])) {
            snprintf(why, len, "t-family table row %zu: t10 %g %% does not increase on row %zu's",
                     r, t[0], r - 1);
            return 1;
        }
    }
    return 0;
}

/* Monotone piecewise cubic Hermite interpolation at xq of the knots
 * (x[k], y[k]), x increasing, read with strides sx and sy: the slopes at
 * the interior knots are the weighted harmonic means of Fritsch and Butland
 * (1984, A method for constructing local monotone piecewise cubic
 * interpolants), zero where the data turn, and the end slopes the
 * shape-preserving three-point formula, so that the interpolant is
 * monotone wherever the data are (Fritsch and Carlson 1980, Monotone
 * piecewise cubic interpolation). xq must lie in [x[0], x[n-1]]. */
static double pchip(const double *x, size_t sx, const double *y, size_t sy, size_t n, double xq)
{
#define X(k) x[(k) * sx]
#define Y(k) y[(k) * sy]
    size_t k = 0;
    while (k + 2 < n && xq > X(k + 1))
        k++;
    double h = X(k + 1) - X(k), delta = (Y(k + 1) - Y(k)) / h;
    if (n == 2)
        return Y(k) + delta * (xq - X(k));
    double d[2];
    for (int e = 0; e < 2; e++) {
        size_t m = k + (size_t)e; /* the knot whose slope is needed */
        if (m == 0 || m == n - 1) {
            /* one-sided: h0, d0 the end interval, h1, d1 the next */
            size_t a = m == 0 ? 0 : n - 2, b = m == 0 ? 1 : n - 3;
            double h0 = X(a + 1) - X(a), h1 = X(b + 1) - X(b);
            double d0 = (Y(a + 1) - Y(a)) / h0, d1 = (Y(b + 1) - Y(b)) / h1;
            double s = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
            if (s * d0 <= 0)
                s = 0;
            else if (d0 * d1 <= 0 && fabs(s) > fabs(3 * d0))
                s = 3 * d0;
            d[e] = s;
        } else {
            double h0 = X(m) - X(m - 1), h1 = X(m + 1) - X(m);
            double d0 = (Y(m) - Y(m - 1)) / h0, d1 = (Y(m + 1) - Y(m)) / h1;
            if (d0 * d1 <= 0) {
                d[e] = 0;
            } else {
                double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
                d[e] = (w1 + w2) / (w1 / d0 + w2 / d1);
            }
        }
    }
    double t = (xq - X(k)) / h, t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * Y(k) + (t3 - 2 * t2 + t) * h * d[0] +
           (-2 * t3 + 3 * t2) * Y(k + 1) + (t3 - t2) * h * d[1];
#undef X
#undef Y
}

void dm_tfamily_at(const dm_ore *ore, double t10, double *tn)
{
    const double *t = ore->table;
    const size_t c = DM_TFAMILY_COLUMNS;
    /* Below the first row the first row's shape is kept, scaled with t10
     * (the t-family lines start at the origin: no breakage, no fines). */
    double scale = 1.0, at = t10;
    if (t10 < t[0]) {
        scale = t10 / t[0];
        at = t[0];
    }
    for (int k = 0; k < 5; k++)
        tn[k] = scale * pchip(t, c, t + 1 + k, c, ore->rows, at);
}

double dm_tk_e50(const dm_ore *ore, double d)
{
    return ore->e_inf * (1.0 + pow(ore->d0 / d, ore->phi));
}

double dm_ore_t10(const dm_ore *ore, double d, double e)
{
    if (ore->model == DM_ORE_JK)
        return ore->a * (1.0 - exp(-ore->b * e / 3600.0)); /* E_cs in kWh/t */
    return ore->a * (1.0 - exp(-ore->b * e / dm_tk_e50(ore, d)));
}

/* Tavares and King (1998): the fraction of particles of size d whose
 * fracture energy is at most e, an upper-truncated lognormal distribution:
 * P = Φ(ln(e'/E50')/σ), where x' = x Emax/(Emax - x) and
 * Emax = emax_ratio E50 (a plain lognormal when emax_ratio is 0). */
static double tk_cdf(const dm_ore *ore, double d, double e)
{
    double e50 = dm_tk_e50(ore, d);
    if (e <= 0)
        return 0.0;
    double z;
    if (ore->emax_ratio > 0) {
        double emax = ore->emax_ratio * e50;
        if (e >= emax)
            return 1.0;
        z = log((e * emax / (emax - e)) / (e50 * emax / (emax - e50))) / ore->sigma;
    } else {
        z = log(e / e50) / ore->sigma;
    }
    return 0.5 * erfc(-z / sqrt(2.0));
}

/* Tavares and King (2002, Modeling of particle fracture by repeated impacts
 * using continuum damage mechanics): an impact of specific energy e on a
 * particle of fracture energy em > e that survives leaves it the fracture
 * energy em (1 - D), the damage D the smallest root of
 * D = [2γ/(2γ - 5D + 5) · e/em]^(2γ/5). This is its inverse: the initial
 * fracture energy em that one impact of e damages down to `after` (>= e).
 * With em = after/(1 - D) the equation reads
 * D = [2γ (1 - D)/(2γ - 5D + 5) · e/after]^(2γ/5), whose right side falls
 * as D grows (from a positive value at D = 0 to 0 at D = 1), so it has one
 * root in (0, 1), found by bisection. */
static double tk_before(const dm_ore *ore, double e, double after)
{
    const double g = ore->gamma;
    double lo = 0.0, hi = 1.0, mid = 0.5;
    while (mid > lo && mid < hi) { /* down to adjacent doubles */
        double rhs = pow(2 * g * (1 - mid) / (2 * g - 5 * mid + 5) * e / after, 2 * g / 5);
        if (mid < rhs)
            lo = mid;
        else
            hi = mid;
        mid = 0.5 * (lo + hi);
    }
    return after / (1.0 - mid);
}

void dm_tk_sequence(const dm_ore *ore, double d, double e, uint32_t impacts, double *broken,
                    double *survived)
{
    if (e <= 0) {
        *broken = 0.0;
        *survived = impacts;
        return;
    }
    /* A particle breaks within k impacts if its initial fracture energy is
     * below the threshold t_k: t_1 = e, and t_{k+1} the initial energy that
     * the first impact damages down to t_k. F_k = P(t_k) is the fraction
     * broken within k impacts; a particle receives impact m + 1 if the m
     * before left it whole, with probability 1 - F_m (F_0 = 0), so it
     * receives sum_{m=0}^{K-1} (1 - F_m) of the K impacts on average. */
    double t = e, f = tk_cdf(ore, d, e), s = 1.0; /* f = F_1, s = 1 - F_0 */
    uint32_t k = 1;
    while (k < impacts && f < 1.0) {
        double next = tk_before(ore, e, t);
        if (next - t <= 1e-14 * t) { /* the threshold no longer moves: F stays f */
            s += (double)(impacts - k) * (1.0 - f);
            break;
        }
        s += 1.0 - f;
        t = next;
        f = tk_cdf(ore, d, t);
        k++;
    }
    *broken = f;
    *survived = s;
}

double dm_tk_broken(const dm_ore *ore, double d, double e, uint32_t impacts)
{
    double broken, survived;
    dm_tk_sequence(ore, d, e, impacts, &broken, &survived);
    return broken;
}

/* The fragments' cumulative fraction passing relative size r = x/parent,
 * from the t-values: ln P against ln r by monotone piecewise cubic
 * interpolation through (1, 100 %), (1/2, t2), (1/4, t4), (1/10, t10),
 * (1/25, t25), (1/50, t50), (1/75, t75); finer than 1/75 the straight line
 * of the last interval in these coordinates (a power law). */
static double fragment_passing(const double *u, const double *v, double r)
{
    if (r >= 1.0)
        return 1.0;
    double ur = log(r);
    if (ur < u[0])
        return exp(v[0] + (v[1] - v[0]) / (u[1] - u[0]) * (ur - u[0])) / 100.0;
    return exp(pchip(u, 1, v, 1, 7, ur)) / 100.0;
}

void dm_appearance_column(const demill_grinding *g, uint32_t j, double t10, double *col)
{
    double tn[5];
    dm_tfamily_at(&g->ore, t10, tn);
    /* knots in increasing relative size: 1/75, 1/50, 1/25, 1/10, 1/4, 1/2, 1 */
    double p[7] = {tn[4], tn[3], tn[2], t10, tn[1], tn[0], 100.0};
    for (int k = 5; k >= 0; k--) /* passing cannot grow as the size falls */
        if (p[k] > p[k + 1])
            p[k] = p[k + 1];
    double u[7] = {-log(tn_n[4]), -log(tn_n[3]), -log(tn_n[2]), -log(10.0), -log(tn_n[1]),
                   -log(tn_n[0]), 0.0};
    double v[7];
    for (int k = 0; k < 7; k++)
        v[k] = log(p[k]);
    /* the parent: the geometric mean of class j's limits */
    double parent = dm_class_limit(g, j) / pow(2.0, 0.25);
    /* B(i): the fragments' fraction finer than class i's upper limit; what
     * stays in class j is not broken out of it, so the rest is divided by
     * B(j + 1), the mass that leaves. */
    double leave = fragment_passing(u, v, dm_class_limit(g, j + 1) / parent);
    for (uint32_t i = 0; i <= j; i++)
        col[i] = 0.0;
    for (uint32_t i = j + 1; i < g->n; i++) {
        double upper = fragment_passing(u, v, dm_class_limit(g, i) / parent);
        double lower = i + 1 < g->n ? fragment_passing(u, v, dm_class_limit(g, i + 1) / parent)
                                    : 0.0;
        col[i] = (upper - lower) / leave;
    }
}
