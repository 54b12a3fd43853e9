/* clumps.c: what the demill program reports of a scene's clumps (clumps.h):
 * the templates with their fits and counts, and the charge's mass and
 * centre of mass with each clump counted once, at its own centre of mass. */
#include <math.h>
#include <stdlib.h>

#include "clumps.h"

demill_status clumps_charge(demill_world *w, double *mass, double centre[3])
{
    double count, m = 0, mx[3] = {0, 0, 0};
    size_t nc = 0, got;
    demill_status st = demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &count);
    const size_t n = st == DEMILL_OK ? (size_t)count : 0;
    if (st == DEMILL_OK)
        st = demill_world_ids(w, DEMILL_KIND_CLUMP, NULL, 0, &nc);
    double *x = malloc((3 * n + 1) * sizeof *x), *pm = malloc((n + 1) * sizeof *pm);
    demill_id *of = malloc((n + 1) * sizeof *of), *clump = malloc((nc + 1) * sizeof *clump);
    if (st == DEMILL_OK && (!x || !pm || !of || !clump))
        st = DEMILL_ERR_OUT_OF_MEMORY;
    if (st == DEMILL_OK && n) {
        if ((st = demill_particles_read(w, DEMILL_PARTICLE_POSITION, x, n, &got)) == DEMILL_OK &&
            (st = demill_particles_read(w, DEMILL_PARTICLE_MASS, pm, n, &got)) == DEMILL_OK)
            st = demill_particles_read_ids(w, DEMILL_PARTICLE_CLUMP, of, n, &got);
        for (size_t k = 0; st == DEMILL_OK && k < n; k++)
            if (of[k] == DEMILL_ID_NONE) {
                m += pm[k];
                for (int j = 0; j < 3; j++)
                    mx[j] += pm[k] * x[3 * k + j];
            }
    }
    if (st == DEMILL_OK && nc)
        st = demill_world_ids(w, DEMILL_KIND_CLUMP, clump, nc, &got);
    for (size_t k = 0; st == DEMILL_OK && k < nc; k++) {
        double cm, cx[3];
        if ((st = demill_clump_get(w, clump[k], DEMILL_CLUMP_MASS, &cm)) == DEMILL_OK &&
            (st = demill_clump_get(w, clump[k], DEMILL_CLUMP_POSITION, cx)) == DEMILL_OK) {
            m += cm;
            for (int j = 0; j < 3; j++)
                mx[j] += cm * cx[j];
        }
    }
    free(x);
    free(pm);
    free(of);
    free(clump);
    *mass = m;
    for (int j = 0; j < 3; j++)
        centre[j] = m > 0 ? mx[j] / m : NAN;
    return st;
}

/* A template's field, NaN if it cannot be read. */
static double field(const scene *s, size_t k, int32_t key)
{
    double v[9];
    return demill_clump_template_get(s->w, s->tmpl[k], key, v) == DEMILL_OK ? v[0] : NAN;
}

/* Whether template k was made from a mesh (it has a fit). */
static int from_mesh(const scene *s, size_t k)
{
    double v;
    return demill_clump_template_get(s->w, s->tmpl[k], DEMILL_TEMPLATE_MESH_VOLUME, &v) ==
           DEMILL_OK;
}

void clumps_report(const scene *s, FILE *f)
{
    if (!s->ntmpl)
        return;
    size_t nc = 0;
    double mass = 0;
    demill_world_ids(s->w, DEMILL_KIND_CLUMP, NULL, 0, &nc);
    demill_id *clump = malloc((nc + 1) * sizeof *clump);
    if (clump && demill_world_ids(s->w, DEMILL_KIND_CLUMP, clump, nc, &nc) == DEMILL_OK)
        for (size_t k = 0; k < nc; k++) {
            double m;
            if (demill_clump_get(s->w, clump[k], DEMILL_CLUMP_MASS, &m) == DEMILL_OK)
                mass += m;
        }
    free(clump);
    fprintf(f, "clumps = %zu\nclumps_mass_kg = %.17g\n", nc, mass);
    for (size_t k = 0; k < s->ntmpl; k++) {
        const char *name = s->tmplname[k];
        fprintf(f, "template_%s_spheres = %.0f\ntemplate_%s_mass_kg = %.17g\n"
                   "template_%s_volume_m3 = %.17g\n",
                name, field(s, k, DEMILL_TEMPLATE_COUNT), name, field(s, k, DEMILL_TEMPLATE_MASS),
                name, field(s, k, DEMILL_TEMPLATE_VOLUME));
        if (s->tmpl_counted)
            fprintf(f, "template_%s_clumps = %zu\n", name, s->tmpl_clumps[k]);
        if (from_mesh(s, k))
            fprintf(f, "template_%s_mesh_volume_m3 = %.17g\ntemplate_%s_fit_volume_error = %.6g\n"
                       "template_%s_fit_deviation_out_m = %.6g\n"
                       "template_%s_fit_deviation_in_m = %.6g\ntemplate_%s_fit_cell_m = %.6g\n",
                    name, field(s, k, DEMILL_TEMPLATE_MESH_VOLUME), name,
                    field(s, k, DEMILL_TEMPLATE_FIT_VOLUME_ERROR), name,
                    field(s, k, DEMILL_TEMPLATE_FIT_DEVIATION_OUT), name,
                    field(s, k, DEMILL_TEMPLATE_FIT_DEVIATION_IN), name,
                    field(s, k, DEMILL_TEMPLATE_FIT_CELL));
    }
}

void clumps_print(const scene *s, FILE *f)
{
    for (size_t k = 0; k < s->ntmpl; k++) {
        fprintf(f, "demill: template %s: %.0f spheres, %.4g g", s->tmplname[k],
                field(s, k, DEMILL_TEMPLATE_COUNT), 1e3 * field(s, k, DEMILL_TEMPLATE_MASS));
        if (s->tmpl_counted)
            fprintf(f, ", %zu clumps", s->tmpl_clumps[k]);
        if (from_mesh(s, k))
            fprintf(f, "; fit of its mesh (%.4g cm^3): volume error %.3f, deviation out %.3g mm, "
                       "in %.3g mm, cells of %.3g mm",
                    1e6 * field(s, k, DEMILL_TEMPLATE_MESH_VOLUME),
                    field(s, k, DEMILL_TEMPLATE_FIT_VOLUME_ERROR),
                    1e3 * field(s, k, DEMILL_TEMPLATE_FIT_DEVIATION_OUT),
                    1e3 * field(s, k, DEMILL_TEMPLATE_FIT_DEVIATION_IN),
                    1e3 * field(s, k, DEMILL_TEMPLATE_FIT_CELL));
        fputc('\n', f);
    }
}
