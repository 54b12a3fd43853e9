/* union.c: the mass, centre of mass and inertia of a union of overlapping
 * spheres (3D) or discs (2D) of one density, overlaps counted once.
 *
 * Two methods. Where no three balls overlap pairwise, inclusion-exclusion
 * (the union's measure is the sum of the balls' less the sum of the pairwise
 * intersections, plus the triple ones, ...), as Avis, Bhattacharya and Imai
 * (1988), "Computing the volume of the union of spheres", The Visual
 * Computer 3, 323-328, begin, with every term in closed form. Two
 * overlapping balls meet in a lens, two caps back to back on the plane
 * x = a = (d² + R² - r²)/(2 d) along the line of centres; a cap or a whole
 * ball is a slab x0 <= x <= x1 of a ball cut by planes normal to an axis,
 * whose volume and first and second moments are polynomial integrals over
 * its circular cross-sections (3D) or chords (2D), written out in slab().
 * Balls inside another are dropped first; with no triple term needed the
 * result is exact to round-off.
 *
 * Where three balls overlap pairwise, the power diagram (Aurenhammer (1987),
 * "Power diagrams: properties, algorithms, and applications", SIAM J.
 * Comput. 16, 78-96): the cell of disc i, the points whose power
 * |p - c_i|² - r_i² is the least of all the discs', is a convex polygon, and
 * the union is the disjoint union of each disc's part in its own cell. A
 * disc's cell is a square about it clipped by the half-planes of the discs
 * it meets (power_cell()), and the moments of a disc cut by a convex polygon
 * are exact: an integrand f homogeneous of degree k about the disc's centre
 * integrates over a region D as ∮ f (p × dp)/(k + 2) round its boundary
 * (the divergence theorem with Euler's identity for homogeneous functions,
 * as Lasserre (1998), "Integration on a convex polytope", Proc. Amer. Math.
 * Soc. 126, 2433-2441, uses it), which a fan of triangles from the centre
 * over the polygon's edges, each cut by the circle, writes in closed form
 * (disc_polygon()). That weighs discs with a thickness exactly. Spheres
 * (and discs without a thickness, spheres centred in a plane) are weighed
 * slice by slice (Cavalieri): a slice z = const of the union of spheres is a
 * union of discs, weighed exactly as above, and its moments are integrated
 * over z by adaptive Gauss-Kronrod quadrature (G7-K15, Piessens, de
 * Doncker-Kapenga, Ueberhuber and Kahaner (1983), QUADPACK, Springer). The
 * slices' moments are analytic in z between the heights where the slice
 * changes its make-up: a sphere's top and bottom, where two spheres'
 * circle of intersection is highest and lowest (two circles of the slice
 * touch) and where three spheres' surfaces meet (three circles of the slice
 * pass through one point), those two kinds counted only on the union's
 * surface (breaks()). The quadrature splits there, and the substitution
 * z = (a + b)/2 - (b - a) cos(θ)/2 on each piece [a, b] turns the
 * square-root behaviour of the moments at its ends ((z - a)^(1/2) where
 * circles touch or appear) into functions analytic in θ (Davis and
 * Rabinowitz (1984), Methods of Numerical Integration, 2nd ed., Academic
 * Press, on changes of variable at end-point singularities), so that G7-K15
 * converges fast. Each piece is halved in θ until the Kronrod and Gauss
 * sums agree to 1e-13 of the union's scale (the balls' summed volume times
 * its size to the power of the moment) in proportion to the piece's share
 * of the range.
 *
 * Moments are taken about the mean of the centres, which keeps the
 * round-off of the shift to the centre of mass at the size of the shape,
 * not of its position. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* Whether the input can be weighed (centres of dim coordinates): DEMILL_OK,
 * or the code of the first fault found and its message in *why. */
static demill_status check(int dim, size_t n, const double *c, const double *r, double rho,
                           const char **why)
{
    static const char *const msg[] = {
        "no spheres", "a centre or a radius is not finite", "a radius is not positive",
        "the density is not finite", "the density is not positive"};
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
    if (bad >= 0 && why)
        *why = msg[bad];
    return st;
}

/* Whether three kept balls overlap pairwise, so that inclusion-exclusion
 * would need triple terms. */
static int triple(int dim, size_t n, const double *c, const double *r)
{
    for (size_t i = 0; i < n; i++) {
        if (dropped(dim, n, c, r, i))
            continue;
        for (size_t j = i + 1; j < n; j++) {
            if (!lens(dim, c, r, i, j) || dropped(dim, n, c, r, j))
                continue;
            for (size_t k = j + 1; k < n; k++)
                if (lens(dim, c, r, i, k) && lens(dim, c, r, j, k) && !dropped(dim, n, c, r, k))
                    return 1;
        }
    }
    return 0;
}

/* The raw moments of the union about ref in dimension dim (2: discs of
 * unit thickness) by inclusion-exclusion, after check() and where no
 * triple(), the centres given with dc <= dim coordinates each (the others
 * 0). */
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

/* The kept balls of a union (none inside another) for the power diagram
 * and the slices: centres about the reference point (z = 0 for discs),
 * radii, and for each ball the kept balls it overlaps, nb[first[i]] to
 * nb[first[i + 1] - 1]; the discs of the slice being weighed (centres sc,
 * radii sr, 0 for a ball the slice misses); room for a power cell. */
typedef struct ballset {
    size_t n, *first, *nb;
    double *c, *r, *sc, *sr, (*poly)[2], (*tmp)[2];
} ballset;

static void ballset_free(ballset *b)
{
    free(b->first);
    free(b->nb);
    free(b->c);
    free(b->r);
    free(b->sc);
    free(b->sr);
    free(b->poly);
    free(b->tmp);
}

/* Fills b with the kept balls of the input (dc coordinates per centre) about
 * ref, the slice discs their equators; 0 if out of memory (b then freed). */
static int ballset_make(ballset *b, int dc, size_t n, const double *c, const double *r,
                        const double ref[3])
{
    *b = (ballset){0};
    b->c = malloc(3 * n * sizeof *b->c);
    b->r = malloc(n * sizeof *b->r);
    b->first = malloc((n + 1) * sizeof *b->first);
    b->sc = malloc(2 * n * sizeof *b->sc);
    b->sr = malloc(n * sizeof *b->sr);
    b->poly = malloc((n + 4) * sizeof *b->poly);
    b->tmp = malloc((n + 4) * sizeof *b->tmp);
    if (!b->c || !b->r || !b->first || !b->sc || !b->sr || !b->poly || !b->tmp) {
        ballset_free(b);
        return 0;
    }
    for (size_t i = 0; i < n; i++) {
        if (dropped(dc, n, c, r, i))
            continue;
        size_t k = b->n++;
        for (int j = 0; j < 3; j++)
            b->c[3 * k + j] = j < dc ? c[dc * i + j] - ref[j] : 0.0;
        b->r[k] = r[i];
    }
    /* Neighbour lists: count, then fill. */
    size_t pairs = 0;
    for (size_t i = 0; i < b->n; i++)
        for (size_t j = 0; j < b->n; j++)
            pairs += j != i && lens(3, b->c, b->r, i, j);
    b->nb = malloc((pairs ? pairs : 1) * sizeof *b->nb);
    if (!b->nb) {
        ballset_free(b);
        return 0;
    }
    b->first[0] = 0;
    for (size_t i = 0; i < b->n; i++) {
        b->first[i + 1] = b->first[i];
        for (size_t j = 0; j < b->n; j++)
            if (j != i && lens(3, b->c, b->r, i, j))
                b->nb[b->first[i + 1]++] = j;
        b->sc[2 * i] = b->c[3 * i];
        b->sc[2 * i + 1] = b->c[3 * i + 1];
        b->sr[i] = b->r[i];
    }
    return 1;
}

/* Clips the convex polygon in (nv vertices, anticlockwise) to the
 * half-plane n·p <= h into out (Sutherland and Hodgman (1974), "Reentrant
 * polygon clipping", Comm. ACM 17, 32-42); returns out's vertex count, at
 * most nv + 1. */
static int clip(const double (*in)[2], int nv, const double n[2], double h, double (*out)[2])
{
    int m = 0;
    for (int k = 0; k < nv; k++) {
        const double *p = in[k], *q = in[(k + 1) % nv];
        double fp = n[0] * p[0] + n[1] * p[1] - h, fq = n[0] * q[0] + n[1] * q[1] - h;
        if (fp <= 0.0) {
            out[m][0] = p[0];
            out[m++][1] = p[1];
        }
        if ((fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0)) {
            double t = fp / (fp - fq);
            out[m][0] = p[0] + t * (q[0] - p[0]);
            out[m++][1] = p[1] + t * (q[1] - p[1]);
        }
    }
    return m;
}

/* The power cell of slice disc i about its centre, cut to a square of
 * half-side twice its radius, in b->poly; returns its vertex count, 0 when
 * the disc has no part of the union of its own (the cell misses it). Only
 * the discs that meet disc i can bound its part: a point of disc i outside
 * disc j has a negative power for i and a positive one for j. Of two equal
 * discs at one point the first keeps the cell. */
static int power_cell(ballset *b, size_t i)
{
    double ri = b->sr[i], L = 2.0 * ri, *ci = b->sc + 2 * i;
    double sq[4][2] = {{-L, -L}, {L, -L}, {L, L}, {-L, L}};
    memcpy(b->poly, sq, sizeof sq);
    int nv = 4;
    for (size_t k = b->first[i]; k < b->first[i + 1]; k++) {
        size_t j = b->nb[k];
        double rj = b->sr[j];
        if (!(rj > 0.0))
            continue;
        double n[2] = {b->sc[2 * j] - ci[0], b->sc[2 * j + 1] - ci[1]};
        double d2 = n[0] * n[0] + n[1] * n[1];
        if (d2 >= (ri + rj) * (ri + rj))
            continue;
        /* Disc i's side of the radical line: |p|² - ri² <= |p - n|² - rj². */
        double h = 0.5 * (d2 + ri * ri - rj * rj), d = sqrt(d2);
        if (d2 == 0.0) {
            if (ri < rj || (ri == rj && j < i))
                return 0;
            continue;
        }
        if (h >= ri * d)
            continue;
        if (h <= -ri * d)
            return 0;
        nv = clip((const double (*)[2])b->poly, nv, n, h, b->tmp);
        double(*t)[2] = b->poly;
        b->poly = b->tmp;
        b->tmp = t;
        if (nv == 0)
            return 0;
    }
    return nv;
}

/* Adds to s (area, ∫x, ∫y, ∫x², ∫y², ∫xy about the origin) the sector of
 * the disc of radius R at the origin between the directions of a and b
 * (signed, less than half a turn): with f = ρ^k g(θ) homogeneous of degree
 * k, ∫ f = R^(k+2)/(k+2) ∫ g dθ, the angular integrals of 1, cos θ,
 * sin θ, cos² θ, sin² θ and sin θ cos θ in closed form. */
static void sector(double R, const double a[2], const double b[2], double s[6])
{
    double la = sqrt(a[0] * a[0] + a[1] * a[1]), lb = sqrt(b[0] * b[0] + b[1] * b[1]);
    double u[2] = {a[0] / la, a[1] / la}, v[2] = {b[0] / lb, b[1] / lb};
    double phi = atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]);
    double R2 = R * R, w = 0.5 * (v[0] * v[1] - u[0] * u[1]);
    s[0] += 0.5 * R2 * phi;
    s[1] += R2 * R / 3.0 * (v[1] - u[1]);
    s[2] += R2 * R / 3.0 * (u[0] - v[0]);
    s[3] += 0.25 * R2 * R2 * (0.5 * phi + w);
    s[4] += 0.25 * R2 * R2 * (0.5 * phi - w);
    s[5] += 0.125 * R2 * R2 * (v[1] * v[1] - u[1] * u[1]);
}

/* Adds to s the signed triangle of the origin, a and b: along the edge
 * p = a + t (b - a), p × dp = (a × b) dt, so ∫ f = (a × b)/(k + 2) ∫₀¹ f dt
 * (the polygon moments of Steger (1996), "On the calculation of arbitrary
 * moments of polygons", TU München FGBV-96-05). */
static void triangle(const double a[2], const double b[2], double s[6])
{
    double w = a[0] * b[1] - a[1] * b[0];
    s[0] += w / 2.0;
    s[1] += w * (a[0] + b[0]) / 6.0;
    s[2] += w * (a[1] + b[1]) / 6.0;
    s[3] += w * (a[0] * a[0] + a[0] * b[0] + b[0] * b[0]) / 12.0;
    s[4] += w * (a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) / 12.0;
    s[5] += w * (2.0 * (a[0] * a[1] + b[0] * b[1]) + a[0] * b[1] + b[0] * a[1]) / 24.0;
}

/* The moments s (as sector()'s) of the disc of radius R at the origin cut
 * by the convex polygon p (nv vertices, anticlockwise), by the fan of
 * signed triangles from the origin over the polygon's edges, each cut by
 * the circle: an edge's part inside the disc adds its triangle, a part
 * outside the sector it subtends (every ray to it leaves the disc first). */
static void disc_polygon(double R, const double (*p)[2], int nv, double s[6])
{
    memset(s, 0, 6 * sizeof *s);
    for (int k = 0; k < nv; k++) {
        const double *a = p[k], *b = p[(k + 1) % nv];
        double e[2] = {b[0] - a[0], b[1] - a[1]};
        double A = e[0] * e[0] + e[1] * e[1], B = a[0] * e[0] + a[1] * e[1];
        double C = a[0] * a[0] + a[1] * a[1] - R * R, disc = B * B - A * C;
        if (A == 0.0)
            continue;
        double t0 = 1.0, t1 = 1.0; /* the part inside, t0 <= t <= t1 */
        if (disc > 0.0) {
            double q = sqrt(disc);
            t0 = fmin(fmax((-B - q) / A, 0.0), 1.0);
            t1 = fmin(fmax((-B + q) / A, 0.0), 1.0);
        }
        double u[2] = {a[0] + t0 * e[0], a[1] + t0 * e[1]};
        double v[2] = {a[0] + t1 * e[0], a[1] + t1 * e[1]};
        if (t0 > 0.0)
            sector(R, a, u, s);
        if (t1 > t0)
            triangle(u, v, s);
        if (t1 < 1.0)
            sector(R, v, b, s);
    }
}

/* The moments s (area, ∫x, ∫y, ∫x², ∫y², ∫xy about the reference point)
 * of the union of the slice discs of b: each disc's part in its power cell,
 * shifted from its centre. */
static void slice_moments(ballset *b, double s[6])
{
    memset(s, 0, 6 * sizeof *s);
    for (size_t i = 0; i < b->n; i++) {
        if (!(b->sr[i] > 0.0))
            continue;
        int nv = power_cell(b, i);
        if (nv == 0)
            continue;
        double q[6], x = b->sc[2 * i], y = b->sc[2 * i + 1];
        disc_polygon(b->sr[i], (const double (*)[2])b->poly, nv, q);
        s[0] += q[0];
        s[1] += q[1] + x * q[0];
        s[2] += q[2] + y * q[0];
        s[3] += q[3] + 2.0 * x * q[1] + x * x * q[0];
        s[4] += q[4] + 2.0 * y * q[2] + y * y * q[0];
        s[5] += q[5] + x * q[2] + y * q[1] + x * y * q[0];
    }
}

/* The quantities integrated over z: the slice z's moments (s) and z s[0],
 * z s[1], z s[2], z² s[0], for the raw moments of the union of spheres. */
enum { NQ = 10 };

static void integrand(ballset *b, double z, double f[NQ])
{
    for (size_t i = 0; i < b->n; i++) {
        double dz = z - b->c[3 * i + 2], h2 = b->r[i] * b->r[i] - dz * dz;
        b->sr[i] = h2 > 0.0 ? sqrt(h2) : 0.0;
    }
    slice_moments(b, f);
    f[6] = z * f[0];
    f[7] = z * f[1];
    f[8] = z * f[2];
    f[9] = z * z * f[0];
}

/* The 15-point Kronrod rule and its embedded 7-point Gauss rule on [-1, 1]
 * (QUADPACK's qk15): nodes ±XK[k], Kronrod weights WK[k], and the Gauss
 * weights WG[k] of the nodes ±XK[2k + 1]. */
static const double XK[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
static const double WK[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double WG[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/* Adds to F the integrals over z of the piece [za, zb] between θ0 and θ1
 * (z = (za + zb)/2 - (zb - za) cos(θ)/2): G7-K15, halved until
 * |K15 - G7| <= tol (per quantity) times the part's share (θ1 - θ0)/π of
 * the piece's tolerance, or after 40 halvings. */
static void integrate(ballset *b, double za, double zb, double t0, double t1, const double tol[NQ],
                      int depth, double F[NQ])
{
    double K[NQ] = {0}, G[NQ] = {0}, f[NQ], mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
    for (int k = 0; k < 15; k++) { /* nodes -XK[0] .. -XK[7] = 0 .. XK[0] */
        int j = k < 8 ? k : 14 - k;
        double t = mid + (k < 8 ? -1.0 : 1.0) * half * XK[j];
        double jac = 0.5 * (zb - za) * sin(t) * half;
        integrand(b, 0.5 * (za + zb) - 0.5 * (zb - za) * cos(t), f);
        for (int q = 0; q < NQ; q++) {
            K[q] += WK[j] * jac * f[q];
            if (j % 2 == 1)
                G[q] += WG[j / 2] * jac * f[q];
        }
    }
    int ok = depth >= 40;
    if (!ok) {
        ok = 1;
        for (int q = 0; q < NQ; q++)
            ok = ok && fabs(K[q] - G[q]) <= tol[q] * (t1 - t0) / DM_PI;
    }
    if (ok) {
        for (int q = 0; q < NQ; q++)
            F[q] += K[q];
        return;
    }
    integrate(b, za, zb, t0, mid, tol, depth + 1, F);
    integrate(b, za, zb, mid, t1, tol, depth + 1, F);
}

/* A growing list of heights. */
typedef struct zlist {
    double *z;
    size_t n, cap;
} zlist;

static int push(zlist *l, double z)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        double *g = realloc(l->z, cap * sizeof *g);
        if (!g)
            return 0;
        l->z = g;
        l->cap = cap;
    }
    l->z[l->n++] = z;
    return 1;
}

/* Whether the point p (on the surface of ball i) lies inside a ball other
 * than i, j and k, so not on the union's surface; only the balls that meet
 * ball i can hold it. */
static int covered(const ballset *b, const double p[3], size_t i, size_t j, size_t k)
{
    for (size_t m = b->first[i]; m < b->first[i + 1]; m++) {
        size_t q = b->nb[m];
        if (q == j || q == k)
            continue;
        double d2 = 0.0, rq = b->r[q];
        for (int x = 0; x < 3; x++)
            d2 += (p[x] - b->c[3 * q + x]) * (p[x] - b->c[3 * q + x]);
        if (d2 < rq * rq * (1.0 - 1e-12))
            return 1;
    }
    return 0;
}

static int push_point(zlist *l, const ballset *b, const double p[3], size_t i, size_t j, size_t k)
{
    return covered(b, p, i, j, k) || push(l, p[2]);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The heights where the slices of the union change their make-up, sorted
 * into l: every sphere's top and bottom; the highest and lowest points of
 * the circle where spheres i and j meet (centre m = c_i + a e, e the unit
 * vector from c_i to c_j, a = (d² + r_i² - r_j²)/(2d), radius
 * h = √(r_i² - a²); its steepest direction in its plane u ∝ ẑ - e_z e);
 * the points where that circle, p = m + h (cos t u + sin t v), meets
 * sphere k: with q = m - c_k, (q·u) cos t + (q·v) sin t =
 * (r_k² - |q|² - h²)/(2h). The last two kinds only where no other ball
 * covers them. 0 if out of memory. */
static int breaks(const ballset *b, zlist *l)
{
    for (size_t i = 0; i < b->n; i++)
        if (!push(l, b->c[3 * i + 2] - b->r[i]) || !push(l, b->c[3 * i + 2] + b->r[i]))
            return 0;
    for (size_t i = 0; i < b->n; i++) {
        const double *ci = b->c + 3 * i;
        for (size_t s = b->first[i]; s < b->first[i + 1]; s++) {
            size_t j = b->nb[s];
            if (j < i)
                continue;
            const double *cj = b->c + 3 * j;
            double d = dist(3, ci, cj), e[3], m[3], u[3], v[3];
            double a = (d * d + b->r[i] * b->r[i] - b->r[j] * b->r[j]) / (2.0 * d);
            double h = sqrt(fmax(b->r[i] * b->r[i] - a * a, 0.0));
            for (int x = 0; x < 3; x++) {
                e[x] = (cj[x] - ci[x]) / d;
                m[x] = ci[x] + a * e[x];
            }
            /* u: the circle's steepest direction, or x's when it lies
             * level; v = e × u. */
            int up = 1.0 - e[2] * e[2] > 1e-16 ? 2 : 0;
            double un = sqrt(1.0 - e[up] * e[up]);
            for (int x = 0; x < 3; x++)
                u[x] = ((x == up) - e[up] * e[x]) / un;
            v[0] = e[1] * u[2] - e[2] * u[1];
            v[1] = e[2] * u[0] - e[0] * u[2];
            v[2] = e[0] * u[1] - e[1] * u[0];
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double p[3] = {m[0] + sgn * h * u[0], m[1] + sgn * h * u[1], m[2] + sgn * h * u[2]};
                if (!push_point(l, b, p, i, j, j))
                    return 0;
            }
            for (size_t s2 = b->first[i]; s2 < b->first[i + 1]; s2++) {
                size_t k = b->nb[s2];
                if (k <= j || !lens(3, b->c, b->r, j, k))
                    continue;
                double q[3], q2 = 0.0, A = 0.0, B = 0.0;
                for (int x = 0; x < 3; x++) {
                    q[x] = m[x] - b->c[3 * k + x];
                    q2 += q[x] * q[x];
                    A += q[x] * u[x];
                    B += q[x] * v[x];
                }
                double C = (b->r[k] * b->r[k] - q2 - h * h) / (2.0 * h), rr = hypot(A, B);
                if (!(rr > 0.0) || fabs(C) > rr)
                    continue;
                double t0 = atan2(B, A), dt = acos(C / rr);
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    double cs = cos(t0 + sgn * dt), sn = sin(t0 + sgn * dt), p[3];
                    for (int x = 0; x < 3; x++)
                        p[x] = m[x] + h * (cs * u[x] + sn * v[x]);
                    if (!push_point(l, b, p, i, j, k))
                        return 0;
                }
            }
        }
    }
    qsort(l->z, l->n, sizeof *l->z, by_value);
    return 1;
}

/* The raw moments about ref of the union of spheres (centres of dc
 * coordinates, the others 0) by slices along z; 0 if out of memory. */
static int sliced_moments(int dc, size_t n, const double *c, const double *r,
                          const double ref[3], moments *M)
{
    ballset b;
    zlist l = {0};
    if (!ballset_make(&b, dc, n, c, r, ref))
        return 0;
    if (!breaks(&b, &l)) {
        ballset_free(&b);
        free(l.z);
        return 0;
    }
    /* Tolerances: 1e-13 of the balls' summed volume V times the size L of
     * the shape about ref to the power of each quantity's length. */
    static const int power[NQ] = {0, 1, 1, 2, 2, 2, 1, 2, 2, 2};
    double V = 0.0, L = 0.0, F[NQ] = {0}, span = l.z[l.n - 1] - l.z[0];
    for (size_t i = 0; i < b.n; i++) {
        V += 4.0 / 3.0 * DM_PI * b.r[i] * b.r[i] * b.r[i];
        L = fmax(L, sqrt(b.c[3 * i] * b.c[3 * i] + b.c[3 * i + 1] * b.c[3 * i + 1] +
                         b.c[3 * i + 2] * b.c[3 * i + 2]) + b.r[i]);
    }
    double za = l.z[0];
    for (size_t k = 1; k < l.n; k++) {
        double zb = l.z[k];
        if (zb - za <= 1e-14 * span && k + 1 < l.n)
            continue; /* one break, as far as the quadrature can tell */
        if (!(zb > za))
            continue;
        double ptol[NQ];
        for (int q = 0; q < NQ; q++)
            ptol[q] = 1e-13 * V * pow(L, power[q]) * (zb - za) / span;
        integrate(&b, za, zb, 0.0, DM_PI, ptol, 0, F);
        za = zb;
    }
    *M = (moments){.m0 = F[0], .m1 = {F[1], F[2], F[6]}};
    double m2[3][3] = {{F[3], F[5], F[7]}, {F[5], F[4], F[8]}, {F[7], F[8], F[9]}};
    memcpy(M->m2, m2, sizeof m2);
    ballset_free(&b);
    free(l.z);
    return 1;
}

/* The raw moments about ref of the union of discs (centres of 2
 * coordinates) of unit thickness by the power diagram; 0 if out of memory. */
static int power_moments(size_t n, const double *c, const double *r, const double ref[3],
                         moments *M)
{
    ballset b;
    double s[6];
    if (!ballset_make(&b, 2, n, c, r, ref))
        return 0;
    slice_moments(&b, s);
    *M = (moments){.m0 = s[0], .m1 = {s[1], s[2], 0.0}};
    M->m2[0][0] = s[3];
    M->m2[1][1] = s[4];
    M->m2[0][1] = M->m2[1][0] = s[5];
    ballset_free(&b);
    return 1;
}

static demill_status out_of_memory(const char **why)
{
    if (why)
        *why = "out of memory for the union's working lists";
    return DEMILL_ERR_OUT_OF_MEMORY;
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
    if (!triple(3, n, c, r))
        union_moments(3, 3, n, c, r, ref, &M);
    else if (!sliced_moments(3, n, c, r, ref, &M))
        return out_of_memory(why);
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
    int ie = !triple(2, n, c, r);
    if (t > 0.0) {
        if (ie)
            union_moments(2, 2, n, c, r, ref, &M);
        else if (!power_moments(n, c, r, ref, &M))
            return out_of_memory(why);
        mass_props(&M, ref, rho * t, &p);
    } else { /* spheres centred in the plane z = 0 */
        if (ie)
            union_moments(3, 2, n, c, r, ref, &M);
        else if (!sliced_moments(2, n, c, r, ref, &M))
            return out_of_memory(why);
        mass_props(&M, ref, rho, &p);
    }
    *m = p.mass;
    com[0] = p.com[0];
    com[1] = p.com[1];
    *i = p.inertia[2][2];
    return DEMILL_OK;
}
