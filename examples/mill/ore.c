/* ore.c: the mill's --ore option: an ore file read, the ore added to the
 * ball charge, its impacts recorded over the measured revolution, and from
 * them the grinding rates (optionally with the damage of the grinding
 * time's impacts, and Austin's rates for the classes below the feed's),
 * the population balance over --grind-minutes and the product
 * (product.csv, and P80 and kWh/t for summary.txt). The DEM charge keeps
 * its balls and ore sizes: the coupling is one way. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mill.h"

/* Reads n numbers after a keyword; 0, or -1. */
static int numbers(const char *rest, int n, double *out)
{
    char *end;
    for (int k = 0; k < n; k++) {
        out[k] = strtod(rest, &end);
        if (end == rest || !isfinite(out[k]))
            return -1;
        rest = end;
    }
    while (*rest == ' ' || *rest == '\t' || *rest == '\r' || *rest == '\n')
        rest++;
    return *rest ? -1 : 0;
}

int ore_read(const char *path, ore_def *ore)
{
    *ore = (ore_def){.density = 0};
    FILE *f = fopen(path, "r");
    if (!f) {
        perror(path);
        return -1;
    }
    char line[1024];
    int lineno = 0, bad = 0, have_model = 0, have_size = 0;
    while (!bad && fgets(line, sizeof line, f)) {
        lineno++;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        char key[64];
        int used = 0;
        if (sscanf(line, " %63s%n", key, &used) != 1)
            continue; /* blank or comment */
        const char *rest = line + used;
        double v[8] = {0};
        if (!strcmp(key, "density") || !strcmp(key, "youngs_modulus") ||
            !strcmp(key, "poisson_ratio") || !strcmp(key, "mass") ||
            !strcmp(key, "bond_work_index")) {
            bad = numbers(rest, 1, v);
            double *dst = !strcmp(key, "density")          ? &ore->density
                          : !strcmp(key, "youngs_modulus") ? &ore->youngs
                          : !strcmp(key, "poisson_ratio")  ? &ore->poisson
                          : !strcmp(key, "mass")           ? &ore->mass
                                                           : &ore->bond_wi;
            *dst = v[0];
        } else if (!strcmp(key, "classes")) {
            bad = numbers(rest, 2, v) || v[1] < 2 || v[1] > 200 || v[1] != floor(v[1]);
            ore->top = v[0];
            ore->classes = (uint32_t)v[1];
            have_size = 1;
        } else if (!strcmp(key, "feed")) {
            bad = numbers(rest, 2, v) || ore->nfeed == ORE_MAX_FEED;
            if (!bad) {
                ore->feed[2 * ore->nfeed] = v[0];
                ore->feed[2 * ore->nfeed + 1] = v[1];
                ore->nfeed++;
            }
        } else if (!strcmp(key, "tavares_king")) {
            bad = numbers(rest, 8, ore->tk);
            have_model = 1;
        } else if (!strcmp(key, "damage")) {
            bad = numbers(rest, 1, v) || (v[0] != 0 && v[0] != 1);
            ore->damage = v[0] == 1;
        } else if (!strcmp(key, "austin_rates")) {
            /* alpha (or the word fit), mu, Lambda */
            while (*rest == ' ' || *rest == '\t')
                rest++;
            ore->fit_alpha = !strncmp(rest, "fit", 3);
            if (ore->fit_alpha)
                bad = numbers(rest + 3, 2, ore->austin + 1);
            else
                bad = numbers(rest, 3, ore->austin);
            ore->extend = 1;
        } else if (!strcmp(key, "t_family")) {
            bad = numbers(rest, 6, v) || ore->rows == ORE_MAX_ROWS;
            if (!bad)
                memcpy(ore->table + 6 * ore->rows++, v, sizeof(double) * 6);
        } else {
            fprintf(stderr, "mill: %s:%d: unknown key %s\n", path, lineno, key);
            fclose(f);
            return -1;
        }
    }
    fclose(f);
    if (bad) {
        fprintf(stderr, "mill: %s:%d: expected the numbers of the key (docs/grinding.md, mill --ore)\n",
                path, lineno);
        return -1;
    }
    if (!have_model || !have_size || !ore->nfeed || ore->rows < 2 || !(ore->density > 0) ||
        !(ore->youngs > 0) || !(ore->mass > 0)) {
        fprintf(stderr, "mill: %s: needs density, youngs_modulus, mass, classes, at least one "
                        "feed line, tavares_king and two t_family rows\n",
                path);
        return -1;
    }
    return 0;
}

/* Stops the mill with the message of a failed call. */
static int failed(demill_status s, const char *what, demill_world *w, demill_grinding *g)
{
    if (s == DEMILL_OK)
        return 0;
    const char *msg = g && *demill_grinding_last_error(g) ? demill_grinding_last_error(g)
                      : w                                  ? demill_world_last_error(w)
                                                           : "";
    fprintf(stderr, "mill: %s failed: %s: %s\n", what, demill_strerror(s), msg);
    return -1;
}

int ore_add(demill_world *w, demill_id steel, demill_id drum, const ore_def *ore, demill_id *mat,
            size_t *added)
{
    demill_id m;
    demill_status s = demill_material_create(w, &m);
    const char *what = "ore material";
#define STEP(call, name)                                                                           \
    if (s == DEMILL_OK) {                                                                          \
        s = (call);                                                                                \
        what = (name);                                                                             \
    }
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, ore->density), "ore density")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, ore->youngs), "ore modulus")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_POISSON_RATIO, ore->poisson), "ore Poisson")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_RESTITUTION, 0.5), "ore restitution")
    STEP(demill_material_set(w, m, DEMILL_MATERIAL_FRICTION, 0.5), "ore friction")
    /* the balls' contact laws for ore-ore and ore-steel pairs */
    for (int k = 0; k < 2; k++) {
        const demill_id other = k ? steel : m;
        STEP(demill_pair_set(w, m, other, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law")
        STEP(demill_pair_set(w, m, other, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION),
             "damping")
        STEP(demill_pair_set(w, m, other, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN),
             "friction law")
        STEP(demill_pair_set(w, m, other, DEMILL_PAIR_CLAMP_NORMAL, 0), "clamp")
    }
    STEP(demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, ore->feed, 2 * ore->nfeed,
                          DEMILL_FILL_MASS, ore->mass, 2, NULL, 0, added),
         "filling the ore")
#undef STEP
    *mat = m;
    return failed(s, what, w, NULL);
}

int ore_record(demill_world *w, demill_id drum, demill_id mat, const ore_def *ore)
{
    /* the collision spectrum, which the impacts ride on, in one row of one
     * bin; the impacts in 20 bins a decade from 1e-5 to 1e3 J/kg */
    demill_status s = demill_drum_spectrum_start(w, drum, 0, NULL, 1, 1e-12, 1.0);
    if (s == DEMILL_OK)
        s = demill_drum_impacts_start(w, drum, mat, ore->top, ore->classes, 160, 1e-5, 1e3);
    return failed(s, "recording the impacts", w, NULL);
}

int ore_grind(demill_world *w, demill_id drum, const ore_def *ore, double minutes, double power,
              ore_result *out)
{
    demill_grinding *g = NULL;
    demill_status s = demill_grinding_create(ore->top, ore->classes, &g);
    if (failed(s, "demill_grinding_create", NULL, NULL))
        return -1;
    const uint32_t n = ore->classes;
    double limits[201];
    out->n = n;
    s = demill_grinding_sizes(g, limits, 201, NULL);
    memcpy(out->limits, limits, (n + 1) * sizeof *limits);
    /* the feed: each feed size's mass in its class */
    memset(out->feed, 0, sizeof out->feed);
    for (size_t k = 0; k < ore->nfeed; k++) {
        const double d = ore->feed[2 * k];
        uint32_t c = 0;
        while (c + 1 < n && !(d > limits[c + 1]))
            c++;
        out->feed[c] += ore->feed[2 * k + 1];
    }
    double total = 0;
    for (uint32_t c = 0; c < n; c++)
        total += out->feed[c];
    for (uint32_t c = 0; c < n; c++)
        out->feed[c] *= ore->mass / total;
    if (s == DEMILL_OK)
        s = demill_grinding_set_feed(g, n, out->feed);
    if (s == DEMILL_OK)
        s = demill_grinding_size_passing(g, 0.8, &out->f80);
    if (s == DEMILL_OK)
        s = demill_grinding_set_tavares(g, ore->tk[0], ore->tk[1], ore->tk[2], ore->tk[3],
                                        ore->tk[4], ore->tk[5], ore->tk[6], ore->tk[7], ore->rows,
                                        ore->table);
    if (s == DEMILL_OK)
        s = demill_grinding_set_damage_time(g, ore->damage ? 60 * minutes : 0);
    if (s == DEMILL_OK)
        s = demill_grinding_rates_from_drum(g, w, drum);
    if (s == DEMILL_OK && ore->extend)
        s = demill_grinding_extend_rates(g, ore->fit_alpha, ore->austin[0], ore->austin[1],
                                         ore->austin[2], out->austin);
    if (s == DEMILL_OK)
        s = demill_grinding_rates(g, out->rates, n, NULL);
    if (s == DEMILL_OK)
        s = demill_grinding_run(g, 60 * minutes);
    if (s == DEMILL_OK)
        s = demill_grinding_product(g, out->product, n, NULL);
    if (s == DEMILL_OK)
        s = demill_grinding_size_passing(g, 0.8, &out->p80);
    if (s == DEMILL_OK)
        s = demill_grinding_specific_energy(g, power, ore->mass, &out->kwh_t);
    int bad = failed(s, "grinding", w, g);
    demill_grinding_destroy(g);
    if (bad)
        return -1;
    /* cumulative passing at each class's upper limit: the mass in it and
     * every finer class */
    double fin = 0, pin = 0, pt = 0;
    for (uint32_t c = 0; c < n; c++)
        pt += out->product[c];
    for (int c = (int)n - 1; c >= 0; c--) {
        fin += out->feed[c];
        pin += out->product[c];
        out->feed_passing[c] = fin / ore->mass;
        out->product_passing[c] = pin / pt;
    }
    /* Bond's law, W = 10 W_i (1/√P80 - 1/√F80), sizes in µm (Bond 1961) */
    out->bond_kwh_t = ore->bond_wi > 0 ? 10 * ore->bond_wi * (1 / sqrt(out->p80 * 1e6) -
                                                             1 / sqrt(out->f80 * 1e6))
                                       : NAN;
    return 0;
}

int ore_write_csv(const char *path, const ore_result *r)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        return -1;
    }
    fprintf(f, "class,upper_m,lower_m,rate_1_per_s,feed_kg,product_kg,feed_passing,"
               "product_passing\n");
    for (uint32_t c = 0; c < r->n; c++)
        fprintf(f, "%u,%.6g,%.6g,%.6g,%.17g,%.17g,%.6f,%.6f\n", c, r->limits[c], r->limits[c + 1],
                r->rates[c], r->feed[c], r->product[c], r->feed_passing[c],
                r->product_passing[c]);
    if (fclose(f)) {
        fprintf(stderr, "mill: error writing %s\n", path);
        return -1;
    }
    return 0;
}
