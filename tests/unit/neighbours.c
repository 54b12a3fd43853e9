/* neighbours.c: the cell-grid neighbour build against an all-pairs oracle.
 *
 * On random polydisperse sets (radii spread 10:1) in 2D and 3D, the lists
 * must hold exactly the pairs an O(N²) loop finds within the interaction
 * distance r_i + r_j + skin, each once, in the bucket of its material pair's
 * kernel; the particle-wall lists exactly the particles within r + skin of
 * each wall (a finite wall's included, though its bounding sphere holds
 * them all). Contact histories must follow their pairs through the re-sort
 * of particles by cell (the 3D spring vector changing sign when the pair's
 * order flips), and particle ids must keep naming the same particles.
 * Internal test: it links the static library and reads the lists directly.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/contact/law.h"
#include "world/world.h"
#include "testutil.h"

static double urand(void)
{
    return rand() / (double)RAND_MAX;
}

/* A world of n particles with radii in [rmin, 10 rmin], centres uniform in a
 * box of edge `edge`, two materials m (with different kernels; the pair of the
 * two with the rolling spring) and two planes,
 * and in 3D a cylinder about the box's z axis, as wide and long as it. */
static demill_world *random_world(int dim, int n, double edge, demill_id *ids, demill_id *m)
{
    demill_world *w;
    demill_id wall;
    ck_assert_int_eq(demill_world_create(dim, &w), DEMILL_OK);
    for (int k = 0; k < 2; k++)
        DM_OK(w, demill_material_create(w, &m[k]));
    DM_OK(w, demill_pair_set(w, m[0], m[0], DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, m[1], m[1], DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    DM_OK(w, demill_pair_set(w, m[0], m[1], DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR));
    for (int a = 0; a < 2; a++)
        for (int b = a; b < 2; b++)
            DM_OK(w, demill_pair_set(w, m[a], m[b], DEMILL_PAIR_TANGENTIAL,
                                     a == b ? DEMILL_TANGENTIAL_SPRING : DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_pair_set(w, m[0], m[1], DEMILL_PAIR_ROLLING, DEMILL_ROLLING_SPRING));
    double p0[3] = {0, 0, 0}, n0[3] = {0, 1, 0}, p1[3] = {0, 0, 0}, n1[3] = {1, -1, 0};
    DM_OK(w, demill_wall_add_plane(w, m[0], p0, n0, &wall));
    DM_OK(w, demill_wall_add_plane(w, m[1], p1, n1, &wall));
    if (dim == 3) { /* a finite wall about the particles, as a silo's is */
        const double base[3] = {edge / 2, edge / 2, 0}, z[3] = {0, 0, 1};
        DM_OK(w, demill_wall_add_cylinder(w, m[1], base, z, edge / 2, edge, DEMILL_CAPS_NONE,
                                          &wall));
    }
    const double rmin = 0.001;
    for (int i = 0; i < n; i++) {
        double x[3] = {0, 0, 0}, r = rmin * (1 + 9 * urand() * urand());
        for (int c = 0; c < dim; c++)
            x[c] = edge * urand();
        DM_OK(w, demill_particles_add(w, m[i % 2], 1, x, &r, NULL, 0, &ids[i]));
    }
    return w;
}

/* Every listed pair, as handle-index pairs (lo, hi) with its kernel. */
typedef struct pair_key {
    uint32_t a, b;
    int kernel;
} pair_key;

static int cmp_key(const void *x, const void *y)
{
    const pair_key *p = x, *q = y;
    if (p->a != q->a)
        return p->a < q->a ? -1 : 1;
    if (p->b != q->b)
        return p->b < q->b ? -1 : 1;
    return 0;
}

static void check_lists(demill_world *w)
{
    const dm_particles *P = &w->p;
    const int D = w->dim;
    const uint32_t n = P->n;
    size_t listed = 0, cap = 1024;
    pair_key *got = malloc(cap * sizeof *got);
    for (int k = 0; k < DM_KERNELS; k++) {
        const dm_bucket *b = &w->pp.b[k];
        for (uint32_t p = 0; p < b->n; p++) {
            ck_assert_msg(b->i[p] < b->j[p], "pair listed with i >= j");
            if (listed == cap)
                got = realloc(got, (cap *= 2) * sizeof *got);
            uint32_t hi = P->hid[b->i[p]], hj = P->hid[b->j[p]];
            got[listed++] = (pair_key){hi < hj ? hi : hj, hi < hj ? hj : hi, k};
        }
    }
    size_t want_n = 0, wcap = 1024;
    pair_key *want = malloc(wcap * sizeof *want);
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            double r2 = 0, reach = P->r[i] + P->r[j] + w->skin;
            for (int c = 0; c < D; c++)
                r2 += (P->x[D * j + c] - P->x[D * i + c]) * (P->x[D * j + c] - P->x[D * i + c]);
            if (r2 >= reach * reach)
                continue;
            if (want_n == wcap)
                want = realloc(want, (wcap *= 2) * sizeof *want);
            uint32_t hi = P->hid[i], hj = P->hid[j];
            int kernel = w->ptab[P->mat[i] * w->nmat_tab + P->mat[j]].kernel;
            want[want_n++] = (pair_key){hi < hj ? hi : hj, hi < hj ? hj : hi, kernel};
        }
    qsort(got, listed, sizeof *got, cmp_key);
    qsort(want, want_n, sizeof *want, cmp_key);
    ck_assert_msg(want_n > n / 2, "the oracle found only %zu pairs: test too sparse", want_n);
    ck_assert_msg(listed == want_n, "%zu pairs listed, the oracle finds %zu", listed, want_n);
    for (size_t k = 0; k < listed; k++) {
        ck_assert_msg(got[k].a == want[k].a && got[k].b == want[k].b,
                      "pair %zu differs from the oracle", k);
        ck_assert_int_eq(got[k].kernel, want[k].kernel);
    }
    free(got);
    free(want);

    /* walls: exactly the particles within r + skin of each wall */
    size_t wall_listed = 0, wall_want = 0;
    for (int k = 0; k < DM_KERNELS; k++)
        wall_listed += w->pw.b[k].n;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t k = 0; k < w->nwalls; k++) {
            int close = dm_wall_distance(&w->walls[k], P->x + D * i, D) < P->r[i] + w->skin;
            wall_want += close;
            int found = 0;
            for (int q = 0; q < DM_KERNELS && !found; q++)
                for (uint32_t p = 0; p < w->pw.b[q].n; p++)
                    found |= w->pw.b[q].i[p] == i && w->pw.b[q].j[p] == k;
            ck_assert_msg(found == close, "particle %u and wall %u: listed %d, within reach %d", i,
                          k, found, close);
        }
    ck_assert_uint_eq(wall_listed, wall_want);
}

START_TEST(grid_matches_all_pairs)
{
    srand(42);
    for (int dim = 2; dim <= 3; dim++)
        for (int trial = 0; trial < 3; trial++) {
            const int n = 600;
            demill_id ids[600], mats[2];
            /* dense enough that many pairs are near, at several skins */
            demill_world *w = random_world(dim, n, dim == 3 ? 0.04 : 0.15, ids, mats);
            DM_OK(w, demill_world_set(w, DEMILL_WORLD_SKIN, 0.05 + 0.5 * trial));
            DM_OK(w, dm_resolve_pairs(w, true));
            DM_OK(w, dm_nlist_build(w));
            check_lists(w);
            /* after removing a third and moving the rest, a new build agrees too */
            DM_OK(w, demill_particles_remove(w, n / 3, ids));
            double *x = malloc(3 * (size_t)w->p.n * sizeof *x);
            size_t count;
            DM_OK(w, demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, w->p.n, &count));
            for (size_t k = 0; k < dim * count; k++)
                if (k % 3 < (size_t)dim)
                    x[k] += 0.002 * (urand() - 0.5);
            DM_OK(w, demill_particles_write(w, DEMILL_PARTICLE_POSITION, x, count));
            DM_OK(w, dm_nlist_build(w));
            check_lists(w);
            free(x);
            demill_world_destroy(w);
        }
}
END_TEST

/* The distance from x to the segment a-b (3 components). */
static double segment_distance(const double *x, const double *a, const double *b)
{
    double ab[3], ax[3], l2 = 0.0, t = 0.0, d2 = 0.0;
    for (int c = 0; c < 3; c++) {
        ab[c] = b[c] - a[c];
        ax[c] = x[c] - a[c];
        l2 += ab[c] * ab[c];
        t += ab[c] * ax[c];
    }
    t = t <= 0.0 ? 0.0 : t >= l2 ? 1.0 : t / l2;
    for (int c = 0; c < 3; c++)
        d2 += (ax[c] - t * ab[c]) * (ax[c] - t * ab[c]);
    return sqrt(d2);
}

/* The distance from x to the triangle a, b, c: to its plane when x projects
 * inside it, else to the nearest of its edges. */
static double triangle_distance(const double *x, const double *a, const double *b,
                                const double *c)
{
    const double *v[3] = {a, b, c};
    double u[3], w[3], n[3], nn = 0.0, h = 0.0;
    for (int k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        w[k] = c[k] - a[k];
    }
    for (int k = 0; k < 3; k++) {
        n[k] = u[(k + 1) % 3] * w[(k + 2) % 3] - u[(k + 2) % 3] * w[(k + 1) % 3];
        nn += n[k] * n[k];
    }
    for (int k = 0; k < 3; k++)
        h += n[k] * (x[k] - a[k]) / sqrt(nn);
    int inside = 1;
    for (int e = 0; e < 3; e++) { /* x on the inner side of each edge's plane through n */
        const double *p = v[e], *q = v[(e + 1) % 3];
        double s = 0.0;
        for (int k = 0; k < 3; k++) {
            const double ek = q[(k + 1) % 3] - p[(k + 1) % 3], el = q[(k + 2) % 3] - p[(k + 2) % 3];
            s += (ek * n[(k + 2) % 3] - el * n[(k + 1) % 3]) * (x[k] - p[k]);
        }
        inside &= s <= 0.0;
    }
    if (inside)
        return fabs(h);
    return fmin(segment_distance(x, a, b),
                fmin(segment_distance(x, b, c), segment_distance(x, c, a)));
}

/* A mesh wall's candidates are exactly the (particle, element) pairs within
 * r + skin, by brute force over every element: in 3D a rough height field of
 * 2 x 20 x 20 triangles across a box of random particles, most of them far
 * from it, in 2D a zigzag polyline. */
START_TEST(mesh_candidates_match_all_elements)
{
    srand(7);
    for (int dim = 2; dim <= 3; dim++) {
        const int n = 600, g = 21;
        demill_id ids[600], wall, mats[2];
        demill_world *w = random_world(dim, n, dim == 3 ? 0.04 : 0.15, ids, mats);
        const double edge = dim == 3 ? 0.04 : 0.15;
        double *v = malloc(3 * g * g * sizeof *v);
        uint32_t *tri = malloc(6 * (g - 1) * (g - 1) * sizeof *tri);
        size_t nv = 0, nt = 0;
        if (dim == 3) {
            for (int a = 0; a < g; a++)
                for (int b = 0; b < g; b++, nv++) {
                    v[3 * nv] = edge * a / (g - 1);
                    v[3 * nv + 1] = 0.5 * edge + 0.004 * (urand() - 0.5);
                    v[3 * nv + 2] = edge * b / (g - 1);
                }
            for (int a = 0; a + 1 < g; a++)
                for (int b = 0; b + 1 < g; b++) {
                    const uint32_t q = (uint32_t)(a * g + b);
                    const uint32_t t6[6] = {q, q + 1, q + g, q + 1, q + g + 1, q + g};
                    memcpy(tri + 3 * nt, t6, sizeof t6);
                    nt += 2;
                }
            DM_OK(w, demill_wall_add_mesh(w, mats[1], nv, v, nt, tri, &wall));
        } else {
            for (int a = 0; a < g; a++, nv++) {
                v[3 * nv] = edge * a / (g - 1);
                v[3 * nv + 1] = 0.5 * edge + 0.01 * (a % 2) + 0.002 * urand();
                v[3 * nv + 2] = 0.0;
            }
            nt = nv - 1;
            DM_OK(w, demill_wall_add_polyline(w, mats[1], nv, v, 0, &wall));
        }
        DM_OK(w, demill_world_set(w, DEMILL_WORLD_SKIN, 0.5));
        DM_OK(w, dm_resolve_pairs(w, true));
        DM_OK(w, dm_nlist_build(w));
        const dm_particles *P = &w->p;
        const uint32_t slot = w->nwalls - 1;
        size_t want = 0, got = 0;
        char *listed = calloc((size_t)P->n * nt, 1);
        for (int k = 0; k < DM_KERNELS; k++)
            for (uint32_t p = 0; p < w->pw.b[k].n; p++)
                if (w->pw.b[k].j[p] == slot) {
                    got++;
                    listed[w->pw.b[k].i[p] * nt + w->pw.b[k].t[p]] = 1;
                }
        for (uint32_t i = 0; i < P->n; i++) {
            double x[3] = {P->x[dim * i], P->x[dim * i + 1], dim == 3 ? P->x[dim * i + 2] : 0.0};
            for (size_t t = 0; t < nt; t++) {
                const double d =
                    dim == 3 ? triangle_distance(x, v + 3 * tri[3 * t], v + 3 * tri[3 * t + 1],
                                                 v + 3 * tri[3 * t + 2])
                             : segment_distance(x, v + 3 * t, v + 3 * (t + 1));
                const int close = d < P->r[i] + w->skin;
                const int found = listed[i * nt + t];
                ck_assert_msg(found == close,
                              "%dD: particle %u and element %zu at %g (reach %g): listed %d",
                              dim, i, t, d, P->r[i] + w->skin, found);
                want += close;
            }
        }
        ck_assert_msg(want > 20 && want < (size_t)n * nt / 20,
                      "%dD: %zu candidates: the test must have near and far particles", dim,
                      want);
        ck_assert_uint_eq(got, want);
        free(listed);
        free(v);
        free(tri);
        demill_world_destroy(w);
    }
}
END_TEST

/* Marks every listed contact's history with a value derived from the pair's
 * handles (and the contact on), rebuilds after a shuffle of the storage
 * order, and checks that each value followed its pair. */
START_TEST(history_follows_pairs)
{
    srand(7);
    for (int dim = 2; dim <= 3; dim++) {
        demill_id ids[400], mats[2];
        demill_world *w = random_world(dim, 400, dim == 3 ? 0.03 : 0.1, ids, mats);
        DM_OK(w, dm_resolve_pairs(w, true));
        DM_OK(w, dm_nlist_build(w));
        const dm_particles *P = &w->p;
        size_t marked = 0;
        pair_key *before = malloc(40000 * sizeof *before);
        for (int k = 0; k < DM_KERNELS; k++) {
            dm_bucket *b = &w->pp.b[k];
            for (uint32_t p = 0; p < b->n; p++) {
                uint32_t hi = P->hid[b->i[p]], hj = P->hid[b->j[p]];
                for (int c = 0; c < b->hs; c++)
                    b->hist[(size_t)b->hs * p + c] = 1000.0 * hi + hj + 0.25 * c;
                b->on[p] = 1;
                if (b->hs && marked < 40000)
                    before[marked++] = (pair_key){hi < hj ? hi : hj, hi < hj ? hj : hi, k};
            }
        }
        qsort(before, marked, sizeof *before, cmp_key);
        ck_assert_msg(marked > 100, "only %zu contacts with history", marked);
        /* move every particle by a small amount so that the cell order changes
         * but no pair leaves the lists */
        for (uint32_t i = 0; i < w->p.n; i++)
            for (int c = 0; c < dim; c++)
                w->p.x[dim * i + c] += 0.2 * w->skin * (urand() - 0.5);
        DM_OK(w, dm_nlist_build(w));
        size_t checked = 0;
        for (int k = 0; k < DM_KERNELS; k++) {
            dm_bucket *b = &w->pp.b[k];
            const dm_laws l = dm_kernel_laws(k);
            const int spring = dm_law_spring_size(l.tangential, dim);
            const int r0 = l.rolling == DEMILL_ROLLING_SPRING
                               ? dm_law_off_rolling(l.normal, l.damping, l.tangential, dim)
                               : -1;
            for (uint32_t p = 0; p < b->n; p++) {
                uint32_t hi = P->hid[b->i[p]], hj = P->hid[b->j[p]];
                pair_key key = {hi < hj ? hi : hj, hi < hj ? hj : hi, k};
                int was_listed = bsearch(&key, before, marked, sizeof *before, cmp_key) != NULL;
                if (b->hs)
                    ck_assert_int_eq(b->on[p], was_listed);
                for (int c = 0; c < b->hs; c++) {
                    double v = b->hist[(size_t)b->hs * p + c];
                    if (!was_listed) { /* a pair that came into reach starts afresh */
                        ck_assert_msg(v == 0.0, "new pair (%u, %u) has history %g", hi, hj, v);
                        continue;
                    }
                    double same = 1000.0 * hi + hj + 0.25 * c, swapped = 1000.0 * hj + hi + 0.25 * c;
                    /* a pair whose order flipped carries the other mark; its
                     * 3D spring vector is negated, and the rolling spring's
                     * torque on a (which becomes the torque on b) */
                    const int turns = (c < spring && dim == 3) ||
                                      (r0 >= 0 && c >= r0 && c < r0 + (dim == 3 ? 3 : 1));
                    double flipped = turns ? -swapped : swapped;
                    ck_assert_msg(v == same || v == flipped,
                                  "pair (%u, %u) slot %d carries %g, expected %g or %g", hi, hj, c,
                                  v, same, flipped);
                    checked++;
                }
            }
        }
        ck_assert_msg(checked > 100, "only %zu history values checked", checked);
        free(before);
        /* ids still name the particles they named */
        double r;
        for (int k = 0; k < 400; k += 37) {
            DM_OK(w, demill_particle_get(w, ids[k], DEMILL_PARTICLE_RADIUS, &r));
            uint32_t slot;
            DM_OK(w, dm_resolve(w, ids[k], DEMILL_KIND_PARTICLE, "id", &slot));
            ck_assert(P->hid[slot] == (uint32_t)(ids[k] & 0xffffffffu));
            ck_assert(r == P->r[slot]);
        }
        demill_world_destroy(w);
    }
}
END_TEST

/* A drum's shell, end caps and 8 lifters (prisms) about particles spread
 * over its inside: each wall's list holds exactly the particles that the
 * per-particle test keeps (its distance bound within r + skin, for a
 * lifter the distance from the circle about its section), so that testing
 * blocks of particles first by their box (dm_wall_box_bound) drops none. */
START_TEST(drum_walls_match_per_particle_test)
{
    srand(7);
    for (int dim = 2; dim <= 3; dim++) {
        demill_id m, drum, id;
        demill_world *w = dm_test_world(dim, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, &m);
        DM_OK(w, demill_drum_create(w, m, &drum));
        DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 8));
        const uint32_t n = 1500;
        for (uint32_t i = 0; i < n; i++) { /* uniform over the section, the length in 3D */
            const double rho = 0.15 * sqrt(urand()), phi = 2 * M_PI * urand();
            double x[3] = {rho * cos(phi), rho * sin(phi), dim == 3 ? 0.1 * (urand() - 0.5) : 0};
            const double r = 0.002 * (1 + urand());
            DM_OK(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &id));
        }
        DM_OK(w, dm_resolve_pairs(w, true));
        DM_OK(w, dm_nlist_build(w));
        const dm_particles *P = &w->p;
        const int D = w->dim;
        size_t listed = 0, want = 0;
        for (int k = 0; k < DM_KERNELS; k++)
            listed += w->pw.b[k].n;
        for (uint32_t i = 0; i < n; i++)
            for (uint32_t k = 0; k < w->nwalls; k++) {
                const int kept = w->walls[k].kind &&
                                 dm_wall_distance_bound(&w->walls[k], P->x + D * i, D) <
                                     P->r[i] + w->skin;
                want += kept;
                int found = 0;
                for (int q = 0; q < DM_KERNELS && !found; q++)
                    for (uint32_t p = 0; p < w->pw.b[q].n; p++)
                        found |= w->pw.b[q].i[p] == i && w->pw.b[q].j[p] == k;
                ck_assert_msg(found == kept, "%dD: particle %u and wall %u: listed %d, kept %d",
                              dim, i, k, found, kept);
            }
        ck_assert_uint_eq(listed, want);
        /* the shell, the lifters and in 3D the caps each have candidates */
        ck_assert_msg(want > n / 10, "only %zu wall candidates: test too sparse", want);
        demill_world_destroy(w);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("neighbours");
    TCase *tc = tcase_create("grid");
    tcase_add_test(tc, grid_matches_all_pairs);
    tcase_add_test(tc, history_follows_pairs);
    tcase_add_test(tc, mesh_candidates_match_all_elements);
    tcase_add_test(tc, drum_walls_match_per_particle_test);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
