/* union.c: the mass, centre of mass and inertia of a union of overlapping
 * spheres (3D) or discs (2D) of one density, overlaps counted once.
 *
 * Method: inclusion-exclusion (the union's measure is the sum of the balls'
 * less the sum of the pairwise intersections, plus the triple ones, ...),
 * as Avis, Bhattacharya and Imai (1988), "Computing the volume of the union
 * of spheres", The Visual Computer 3, 323-328, begin, with every term in
 * closed form. Two overlapping balls meet in a lens, two caps back to back
 * on the plane x = a = (d² + R² - r²)/(2 d) along the line of centres; a cap
 * or a whole ball is a slab x0 <= x <= x1 of a ball cut by planes normal to
 * an axis, whose volume and first and second moments are polynomial
 * integrals over its circular cross-sections (3D) or chords (2D), written
 * out in slab(). Balls inside another are dropped first; three balls that
 * overlap pairwise are refused, so that no triple term is needed and the
 * result is exact to round-off. Moments are taken about the mean of the
 * centres, which keeps the round-off of the shift to the centre of mass at
 * the size of the shape, not of its position. */
#include <math.h>

#include "physics/shapes/shapes.h"

/* Raw moments about the reference point: volume (area), first moment and
 * second moment ∫ x xᵀ. */
typedef struct moments {
    double m0, m1[3], m2[3][3];
} moments;

/* The slab x0 <= x <= x1 (-R <= x0 <= x1 <= R) of the ball of radius R
 * centred at the origin, cut normal to the x axis, in dimension dim: s[0]
 * its volume (area), s[1] = ∫ x, s[2] = ∫ x², s[3] = ∫ y² (= ∫ z² in 3D).
 * 3D, cross-section a disc of radius ρ, ρ² = R² - x²: dV = π ρ² dx and
 * ∫∫ y² over the disc = π ρ⁴/4. 2D, a chord of half-length h = √(R² - x²):
 * dA = 2 h dx and ∫ y² over the chord = 2 h³/3; with the standard integrals
 * ∫ h dx = (x h + R² asin(x/R))/2, ∫ x h dx = -h³/3,
 * ∫ x² h dx = x (2x² - R²) h/8 + R⁴ asin(x/R)/8 and
 * ∫ h³ dx = x (5R² - 2x²) h/8 + 3R⁴ asin(x/R)/8 (Gradshteyn and Ryzhik (2007),
 * Table of Integrals, Series, and Products, 2.271-2.272). */
static void slab(int dim, double R, double x0, double x1, double s[4])
{
    double R2 = R * R, F[2][4], x[2] = {x0, x1};
    for (int k = 0; k < 2; k++) {
        double u = x[k], u2 = u * u;
        if (dim == 3) {
            F[k][0] = DM_PI * (R2 * u - u2 * u / 3.0);
            F[k][1] = DM_PI * (R2 * u2 / 2.0 - u2 * u2 / 4.0);
            F[k][2] = DM_PI * (R2 * u2 * u / 3.0 - u2 * u2 * u / 5.0);
            F[k][3] = DM_PI / 4.0 * (R2 * R2 * u - 2.0 * R2 * u2 * u / 3.0 + u2 * u2 * u / 5.0);
        } else {
            double h = sqrt(fmax(R2 - u2, 0.0)), as = asin(fmin(fmax(u / R, -1.0), 1.0));
            F[k][0] = u * h + R2 * as;
            F[k][1] = -2.0 / 3.0 * h * h * h;
            F[k][2] = u * (2.0 * u2 - R2) * h / 4.0 + R2 * R2 * as / 4.0;
            F[k][3] = (u * (5.0 * R2 - 2.0 * u2) * h + 3.0 * R2 * R2 * as) / 12.0;
        }
    }
    for (int j = 0; j < 4; j++)
        s[j] = F[1][j] - F[0][j];
}

/* Adds sign times the moments of a slab s (slab()) of the ball centred at c
 * (relative to the reference point) whose cutting axis is the unit vector e. */
static void add_slab(moments *M, int dim, double sign, const double c[3], const double e[3],
                     const double s[4])
{
    M->m0 += sign * s[0];
    for (int j = 0; j < dim; j++) {
        M->m1[j] += sign * (s[0] * c[j] + s[1] * e[j]);
        for (int k = 0; k < dim; k++) {
            double ee = e[j] * e[k];
            M->m2[j][k] += sign * (s[2] * ee + s[3] * ((j == k) - ee) +
                                   s[1] * (c[j] * e[k] + e[j] * c[k]) + s[0] * c[j] * c[k]);
        }
    }
}

static double dist(int dim, const double *a, const double *b)
{
    double d2 = 0.0;
    for (int j = 0; j < dim; j++)
        d2 += (b[j] - a[j]) * (b[j] - a[j]);
    return sqrt(d2);
}

/* Whether ball i lies inside ball j (j != i) and is dropped for it: inside
 * and smaller, or the same ball given again after j. */
static int inside(int dim, const double *c, const double *r, size_t i, size_t j)
{
    double d = dist(dim, c + dim * i, c + dim * j);
    return d + r[i] <= r[j] && (r[i] < r[j] || d > 0.0 || j < i);
}

static int dropped(int dim, size_t n, const double *c, const double *r, size_t i)
{
    for (size_t j = 0; j < n; j++)
        if (j != i && inside(dim, c, r, i, j))
            return 1;
    return 0;
}

/* Whether the kept balls i and j overlap in a lens of positive volume. */
static int lens(int dim, const double *c, const double *r, size_t i, size_t j)
{
    return dist(dim, c + dim * i, c + dim * j) < r[i] + r[j];
}

/* Whether a union can be weighed (centres of dim coordinates): DEMILL_OK,
 * or the code of the first fault found and its message in *why. */
static demill_status check(int dim, size_t n, const double *c, const double *r, double rho,
                           const char **why)
{
    static const char *const msg[] = {
        "no spheres", "a centre or a radius is not finite", "a radius is not positive",
        "the density is not finite", "the density is not positive",
        "three of the spheres (discs) overlap pairwise: the union of three overlapping "
        "spheres is not yet supported"};
    int bad = -1;
    demill_status st = DEMILL_OK;
    if (n == 0)
        bad = 0, st = DEMILL_ERR_INVALID_VALUE;
    for (size_t i = 0; i < n && bad < 0; i++) {
        int finite = isfinite(r[i]);
        for (int j = 0; j < dim; j++)
            finite = finite && isfinite(c[dim * i + j]);
        if (!finite)
            bad = 1, st = DEMILL_ERR_NOT_FINITE;
        else if (!(r[i] > 0.0))
            bad = 2, st = DEMILL_ERR_INVALID_VALUE;
    }
    if (bad < 0 && !isfinite(rho))
        bad = 3, st = DEMILL_ERR_NOT_FINITE;
    else if (bad < 0 && !(rho > 0.0))
        bad = 4, st = DEMILL_ERR_INVALID_VALUE;
    for (size_t i = 0; i < n && bad < 0; i++) {
        if (dropped(dim, n, c, r, i))
            continue;
        for (size_t j = i + 1; j < n && bad < 0; j++) {
            if (!lens(dim, c, r, i, j) || dropped(dim, n, c, r, j))
                continue;
            for (size_t k = j + 1; k < n && bad < 0; k++)
                if (lens(dim, c, r, i, k) && lens(dim, c, r, j, k) && !dropped(dim, n, c, r, k))
                    bad = 5, st = DEMILL_ERR_INVALID_VALUE;
        }
    }
    if (bad >= 0 && why)
        *why = msg[bad];
    return st;
}

/* The raw moments of the union about ref in dimension dim (2: discs of
 * unit thickness), after check(), the centres given with dc <= dim
 * coordinates each (the others 0). */
static void union_moments(int dim, int dc, size_t n, const double *c, const double *r,
                          const double *ref, moments *M)
{
    *M = (moments){0};
    for (size_t i = 0; i < n; i++) {
        if (dropped(dc, n, c, r, i))
            continue;
        double ci[3] = {0}, ex[3] = {1, 0, 0}, s[4];
        for (int k = 0; k < dc; k++)
            ci[k] = c[dc * i + k] - ref[k];
        slab(dim, r[i], -r[i], r[i], s);
        add_slab(M, dim, 1.0, ci, ex, s);
        for (size_t j = i + 1; j < n; j++) {
            if (!lens(dc, c, r, i, j) || dropped(dc, n, c, r, j))
                continue;
            /* The lens: ball i beyond x = a, ball j short of it, along the
             * axis e from centre i to centre j. */
            double cj[3] = {0}, e[3] = {0}, d = dist(dc, c + dc * i, c + dc * j);
            for (int k = 0; k < dc; k++) {
                cj[k] = c[dc * j + k] - ref[k];
                e[k] = (c[dc * j + k] - c[dc * i + k]) / d;
            }
            double a = (d * d + r[i] * r[i] - r[j] * r[j]) / (2.0 * d);
            slab(dim, r[i], fmin(fmax(a, -r[i]), r[i]), r[i], s);
            add_slab(M, dim, -1.0, ci, e, s);
            slab(dim, r[j], -r[j], fmin(fmax(a - d, -r[j]), r[j]), s);
            add_slab(M, dim, -1.0, cj, e, s);
        }
    }
}

/* The mean of the n centres. */
static void mean_centre(int dim, size_t n, const double *c, double ref[3])
{
    ref[0] = ref[1] = ref[2] = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < dim; k++)
            ref[k] += c[dim * i + k] / (double)n;
}

/* The mass properties of moments M about ref, of density rho: the second
 * moment about the centre of mass C = M2 - M1 M1ᵀ/M0 and I = rho (tr C 1 - C). */
static void mass_props(const moments *M, const double ref[3], double rho, dm_mass_props *out)
{
    double C[3][3], tr = 0.0;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            C[j][k] = M->m2[j][k] - M->m1[j] * M->m1[k] / M->m0;
    for (int j = 0; j < 3; j++)
        tr += C[j][j];
    out->mass = rho * M->m0;
    for (int j = 0; j < 3; j++) {
        out->com[j] = ref[j] + M->m1[j] / M->m0;
        for (int k = 0; k < 3; k++)
            out->inertia[j][k] = rho * ((j == k) * tr - C[j][k]);
    }
}

demill_status dm_spheres_union_mass(size_t n, const double *c, const double *r, double rho,
                                    dm_mass_props *out, const char **why)
{
    if (!c || !r || !out) {
        if (why)
            *why = "a required pointer is NULL";
        return DEMILL_ERR_NULL_POINTER;
    }
    demill_status st = check(3, n, c, r, rho, why);
    if (st != DEMILL_OK)
        return st;
    double ref[3];
    moments M;
    mean_centre(3, n, c, ref);
    union_moments(3, 3, n, c, r, ref, &M);
    mass_props(&M, ref, rho, out);
    return DEMILL_OK;
}

demill_status dm_discs_union_mass(size_t n, const double *c, const double *r, double rho,
                                  double t, double *m, double com[2], double *i,
                                  const char **why)
{
    if (!c || !r || !m || !com || !i) {
        if (why)
            *why = "a required pointer is NULL";
        return DEMILL_ERR_NULL_POINTER;
    }
    if (!(t >= 0.0)) {
        if (why)
            *why = isnan(t) ? "the thickness is not finite" : "the thickness is negative";
        return isnan(t) ? DEMILL_ERR_NOT_FINITE : DEMILL_ERR_INVALID_VALUE;
    }
    if (!isfinite(t)) {
        if (why)
            *why = "the thickness is not finite";
        return DEMILL_ERR_NOT_FINITE;
    }
    demill_status st = check(2, n, c, r, rho, why);
    if (st != DEMILL_OK)
        return st;
    double ref[3];
    moments M;
    dm_mass_props p;
    mean_centre(2, n, c, ref);
    if (t > 0.0) {
        union_moments(2, 2, n, c, r, ref, &M);
        mass_props(&M, ref, rho * t, &p);
    } else { /* spheres centred in the plane z = 0 */
        union_moments(3, 2, n, c, r, ref, &M);
        mass_props(&M, ref, rho, &p);
    }
    *m = p.mass;
    com[0] = p.com[0];
    com[1] = p.com[1];
    *i = p.inertia[2][2];
    return DEMILL_OK;
}
