/* balance.c: the batch-grinding population balance (Austin, Klimpel and
 * Luckie 1984, Process Engineering of Size Reduction: Ball Milling),
 * dw/dt = A w with A_jj = -S_j and A_ij = b_ij S_j (i > j), advanced
 * exactly over a time with constant rates by the matrix exponential, and
 * the product's fraction passing a size (docs/grinding.md, Population
 * balance). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grinding/grinding.h"

/* c = a b for lower triangular n × n matrices (row-major). */
static void lower_mul(size_t n, const double *a, const double *b, double *c)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double s = 0.0;
            for (size_t k = j; k <= i; k++)
                s += a[i * n + k] * b[k * n + j];
            c[i * n + j] = s; /* 0 above the diagonal (empty sum) */
        }
}

/* exp(M) of a lower triangular M by scaling and squaring with the [13/13]
 * Padé approximant (Higham 2005, The scaling and squaring method for the
 * matrix exponential revisited): M is scaled by 2^-s so that its 1-norm is
 * at most θ13 = 5.37, where the approximant's backward error is below the
 * unit roundoff of double precision, and the result squared s times. The
 * denominator V - U is lower triangular, so the Padé quotient is a forward
 * substitution. m is overwritten; r receives exp(M). */
static demill_status lower_expm(size_t n, double *m, double *r)
{
    static const double c[14] = {64764752532480000.0, 32382376266240000.0, 7771770303897600.0,
                                 1187353796428800.0,  129060195264000.0,   10559470521600.0,
                                 670442572800.0,      33522128640.0,       1323241920.0,
                                 40840800.0,          960960.0,            16380.0,
                                 182.0,               1.0};
    const double theta13 = 5.371920351148152;
    size_t nn = n * n;
    double *buf = malloc(6 * nn * sizeof *buf);
    if (!buf)
        return DEMILL_ERR_OUT_OF_MEMORY;
    double *a2 = buf, *a4 = a2 + nn, *a6 = a4 + nn, *u = a6 + nn, *v = u + nn, *t = v + nn;

    double norm = 0.0;
    for (size_t j = 0; j < n; j++) {
        double col = 0.0;
        for (size_t i = j; i < n; i++)
            col += fabs(m[i * n + j]);
        norm = col > norm ? col : norm;
    }
    int s = norm > theta13 ? (int)ceil(log2(norm / theta13)) : 0;
    double scale = ldexp(1.0, -s);
    for (size_t k = 0; k < nn; k++)
        m[k] *= scale;

    lower_mul(n, m, m, a2);
    lower_mul(n, a2, a2, a4);
    lower_mul(n, a4, a2, a6);
    /* U = M [A6 (c13 A6 + c11 A4 + c9 A2) + c7 A6 + c5 A4 + c3 A2 + c1 I]
     * V =    A6 (c12 A6 + c10 A4 + c8 A2) + c6 A6 + c4 A4 + c2 A2 + c0 I */
    for (size_t k = 0; k < nn; k++)
        t[k] = c[13] * a6[k] + c[11] * a4[k] + c[9] * a2[k];
    lower_mul(n, a6, t, u);
    for (size_t k = 0; k < nn; k++)
        u[k] += c[7] * a6[k] + c[5] * a4[k] + c[3] * a2[k];
    for (size_t i = 0; i < n; i++)
        u[i * n + i] += c[1];
    lower_mul(n, m, u, t); /* t = U */
    for (size_t k = 0; k < nn; k++)
        u[k] = c[12] * a6[k] + c[10] * a4[k] + c[8] * a2[k];
    lower_mul(n, a6, u, v);
    for (size_t k = 0; k < nn; k++)
        v[k] += c[6] * a6[k] + c[4] * a4[k] + c[2] * a2[k];
    for (size_t i = 0; i < n; i++)
        v[i * n + i] += c[0];
    /* (V - U) R = V + U, column by column, forward substitution */
    for (size_t k = 0; k < nn; k++) {
        double vk = v[k];
        v[k] = vk - t[k];
        u[k] = vk + t[k];
    }
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++) {
            double x = u[i * n + j];
            for (size_t k = j; k < i; k++)
                x -= v[i * n + k] * r[k * n + j];
            r[i * n + j] = i < j ? 0.0 : x / v[i * n + i];
        }
    for (int k = 0; k < s; k++) {
        lower_mul(n, r, r, t);
        memcpy(r, t, nn * sizeof *r);
    }
    free(buf);
    return DEMILL_OK;
}

demill_status dm_balance_advance(const demill_grinding *g, double time, double *mass)
{
    size_t n = g->n, nn = n * n;
    double *m = malloc(2 * nn * sizeof *m);
    if (!m)
        return DEMILL_ERR_OUT_OF_MEMORY;
    double *r = m + nn;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            m[i * n + j] = i == j ? -g->s[j] * time : i > j ? g->b[i * n + j] * g->s[j] * time : 0.0;
    demill_status st = lower_expm(n, m, r);
    if (st == DEMILL_OK) {
        double *w = m; /* the scratch of M is free again */
        for (size_t i = 0; i < n; i++) {
            double x = 0.0;
            for (size_t j = 0; j <= i; j++)
                x += r[i * n + j] * mass[j];
            w[i] = x;
        }
        memcpy(mass, w, n * sizeof *mass);
    }
    free(m);
    return st;
}

/* F(i): the fraction of the product finer than class i's upper limit. */
static double finer(const demill_grinding *g, uint32_t i)
{
    double s = 0.0;
    for (uint32_t k = i; k < g->n; k++)
        s += g->mass[k];
    return s / g->total;
}

double dm_balance_passing(const demill_grinding *g, double x)
{
    if (x >= g->top)
        return 1.0;
    /* class i (i < n - 1) spans [limit(i + 1), limit(i)]: linear in ln x */
    uint32_t i = 0;
    while (i + 2 < g->n && x < dm_class_limit(g, i + 1))
        i++;
    double lo = dm_class_limit(g, i + 1), f_lo = finer(g, i + 1), f_hi = finer(g, i);
    double frac = log(x / lo) / log(sqrt(2.0));
    return f_lo + (f_hi - f_lo) * frac;
}

double dm_balance_size(const demill_grinding *g, double f)
{
    double f_lo = finer(g, g->n - 1);
    if (f <= f_lo)
        return f == f_lo ? dm_class_limit(g, g->n - 1) : -1.0;
    for (uint32_t i = g->n - 1; i-- > 0;) {
        double f_hi = finer(g, i);
        if (f_hi >= f)
            return dm_class_limit(g, i + 1) * pow(sqrt(2.0), (f - f_lo) / (f_hi - f_lo));
        f_lo = f_hi;
    }
    return g->top; /* f above the whole (rounding): the top size */
}
