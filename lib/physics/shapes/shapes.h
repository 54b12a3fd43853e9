/* shapes.h: the mass properties of rigid shapes made of overlapping spheres
 * (3D) or discs (2D), the groundwork of clumps: the mass, centre of mass and
 * inertia of a union of spheres or discs of one density (union.c), and the
 * principal moments and axes of an inertia tensor (eigen.c), and the
 * spheres that fill a closed triangle mesh (fit.c). Uses the base only;
 * nothing here knows a world, so a failure is a status code and a message
 * (static, or in the caller's buffer) for the caller to pass on (dm_fail). */
#ifndef DM_SHAPES_H
#define DM_SHAPES_H

#include <stddef.h>

#include "base/base.h"

/* The mass properties of a rigid body: its mass (kg), centre of mass (m) and
 * inertia tensor about the centre of mass in the frame of the input (kg m²). */
typedef struct dm_mass_props {
    double mass;
    double com[3];
    double inertia[3][3];
} dm_mass_props;

/* The mass properties of the union of n spheres (centres c, 3 n doubles,
 * radii r, n doubles) of one density rho (kg/m³), each point of space
 * counted once however many spheres cover it; a sphere inside another (or
 * equal to an earlier one) adds nothing. Two methods (union.c):
 *  - where no three spheres overlap pairwise, inclusion-exclusion with the
 *    closed-form moments of each lens, exact to round-off, in O(n²)
 *    operations and O(n) more per overlapping pair;
 *  - where three do, slices along z, each a union of discs weighed exactly
 *    by its power diagram, integrated by adaptive Gauss-Kronrod quadrature
 *    split where the slices change their make-up, to a requested 1e-13 of
 *    the spheres' summed volume V times the shape's size L to the power of
 *    each moment (V L for the centre of mass' moment, V L² for inertia).
 *    Measured (tests/unit/shapes.c): rows of 3 to 5 overlapping spheres
 *    within 5.5e-15 of their closed form, a 12-sphere cluster turned and
 *    moved within 3.6e-15 of the turned result. It takes about 0.005 s
 *    for 10 spheres, 0.1 s for 50 and 0.35 s for 100 (CPU time on one
 *    core; radii 0.6 to 1, centres uniform in an ellipsoid, each sphere
 *    meeting 6 to 11 others on average; denser clusters, each meeting up
 *    to 58, cost no more): meant for templates, built once.
 * Errors, with *out untouched and *why (if why is not NULL) set to a
 * static message:
 *  DEMILL_ERR_NULL_POINTER   c, r or out is NULL;
 *  DEMILL_ERR_NOT_FINITE     a centre, a radius or rho is NaN or infinite;
 *  DEMILL_ERR_INVALID_VALUE  n is 0, or a radius or rho is not positive;
 *  DEMILL_ERR_OUT_OF_MEMORY  the working lists of the second method (O(n)
 *                            doubles, and a list of O(n²) neighbours at
 *                            worst) could not be allocated. */
demill_status dm_spheres_union_mass(size_t n, const double *c, const double *r, double rho,
                                    dm_mass_props *out, const char **why);

/* The same for the union of n discs of a 2D world (centres c, 2 n doubles,
 * radii r) as dm_particle_mass() weighs a disc: with thickness t > 0 a
 * prism of that thickness (mass rho t area), with t = 0 the union of the
 * spheres of those centres and radii (mass rho volume). The results are the
 * mass *m, the centre of mass com (2 doubles) and the moment of inertia *i
 * about the axis through the centre of mass normal to the plane. With a
 * thickness exact to round-off whether or not three discs overlap pairwise
 * (inclusion-exclusion, or the discs' power diagram where three do);
 * without one as accurate as dm_spheres_union_mass(). The same errors (t
 * negative or not finite also DEMILL_ERR_INVALID_VALUE or
 * DEMILL_ERR_NOT_FINITE); nothing is written on failure. */
demill_status dm_discs_union_mass(size_t n, const double *c, const double *r, double rho,
                                  double t, double *m, double com[2], double *i,
                                  const char **why);

/* The eigenvalues and eigenvectors of the symmetric 3×3 matrix a (read, not
 * written, only its upper triangle a[j][k], j <= k; not const so that a
 * double[3][3] passes in C11 without a cast): val in increasing order,
 * vec[k] the unit eigenvector of val[k], the three right-handed
 * (vec[2] = vec[0] × vec[1]). Cyclic Jacobi rotations to round-off: the
 * eigenvalues within ten machine epsilons of the largest |eigenvalue|
 * (measured: at most 2.2e-15 of it, and |a v - λ v| at most 1.8e-15 of it,
 * over 1e5 random rotations of spectra (1, 1 to 7, 9), a third of them with
 * a repeated eigenvalue; tests/unit/shapes.c asks 1e-13). */
void dm_sym3_eigen(double a[3][3], double val[3], double vec[3][3]);

/* The fit of a clump template to a closed mesh (dm_spheres_fit_mesh()). The
 * spheres are inscribed, so their union lies inside the mesh and the
 * symmetric difference of the two is volume - union_volume. Lengths in the
 * mesh's unit (m); a deviation as a fraction of the shape's size is
 * deviation / size. */
typedef struct dm_fit_report {
    size_t n;                /* spheres placed: those asked for, fewer only when no
                              * candidate would add volume (the grid's inside centres
                              * are covered) */
    double volume;           /* the mesh's volume, exact to round-off */
    double union_volume;     /* the spheres' union's volume */
    double volume_error;     /* (volume - union_volume) / volume: the symmetric difference
                              * over the mesh's volume */
    double volume_error_tol; /* its resolution error: the change of the union's volume
                              * from columns of side h/2 to h/4, over the mesh's volume */
    double size;             /* the shape's size: the diameter of the sphere of its volume */
    double deviation_out;    /* largest distance from a point of the mesh's surface to the
                              * union */
    double deviation_out_tol;  /* what the sample can miss: the true largest distance is
                                * within deviation_out + deviation_out_tol */
    double deviation_in;     /* largest distance from a point of the union's surface to the
                              * mesh's surface */
    double deviation_in_tol; /* the spacing of its sample (about h/2; an estimate of
                              * what it can miss, not a bound) */
    int cells[3];            /* the grid's cubes along x, y, z */
    double h;                /* their side */
    size_t inside;           /* cube centres inside the mesh (inside h³ estimates its
                              * volume) */
} dm_fit_report;

#define DM_FIT_CELLS_MIN 4
#define DM_FIT_CELLS_MAX 256

/* Fills the closed triangle mesh of nv vertices v (3 doubles each) and nt
 * triangles tri (3 vertex indices each, from 0, wound counter-clockwise
 * seen from outside, as dm_stl_parse() gives them) with up to nspheres
 * overlapping inscribed spheres, chosen greedily for the volume each adds
 * from the maximal inscribed balls centred on a grid of cubes of side
 * h = (the bounding box's longest side) / cells (fit.c says how and cites
 * the method). Writes the first rep->n centres (3 doubles each) and radii
 * and the fit's report *rep. Deterministic: the same input gives the same
 * output, bitwise. The grid takes 13 bytes a cube, and 16 more a candidate
 * centre, near the medial axis (cells³ cubes for a cube-shaped box: 3.4 MB
 * at cells = 64, 220 MB at the most, 256); the time grows with the cubes,
 * the triangles (log) and the spheres: measured on one core, 0.8 s for an
 * ellipsoid of 1280 triangles, 50 spheres and cells = 64, 5.2 s with
 * cells = 128.
 * Errors, with nothing written but err:
 *  DEMILL_ERR_NULL_POINTER   v, tri, centres, radii or rep is NULL;
 *  DEMILL_ERR_NOT_FINITE     a vertex is NaN or infinite;
 *  DEMILL_ERR_INVALID_VALUE  nspheres is 0; cells is not from DM_FIT_CELLS_MIN
 *                            to DM_FIT_CELLS_MAX; fewer than 4 triangles, or
 *                            more than UINT32_MAX / 3 triangles or vertices; a
 *                            corner's index is not below nv; a triangle has
 *                            zero area (two corners the same vertex, or a
 *                            height under 1e-12 of its longest edge); the
 *                            mesh is not closed (an edge not shared by
 *                            exactly two triangles) or not consistently
 *                            oriented (two triangles run an edge the same
 *                            way); it encloses no volume or a negative one
 *                            (flat, or inside out); no cube centre is
 *                            inside it (cells too few for a thin shape);
 *  DEMILL_ERR_OUT_OF_MEMORY.
 * err (errlen bytes; NULL when errlen is 0) says what is wrong, naming the
 * vertex, triangle (from 0) or edge; it is emptied on success. */
demill_status dm_spheres_fit_mesh(size_t nv, const double *v, size_t nt, const uint32_t *tri,
                                  size_t nspheres, int cells, double *centres, double *radii,
                                  dm_fit_report *rep, char *err, size_t errlen);

#endif
