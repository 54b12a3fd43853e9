/* janssen.h: outputs.janssen of the demill runner: a silo's wall stress by
 * depth, from the contact forces on its side in bands of height, the
 * vertical stress from the force balance of the column above each band, and
 * the floor's stress, set against Janssen's (1895) profile with the stress
 * ratio K, the mobilised wall friction and the bulk density measured in a
 * zone of the column; summary.txt, silo.csv and silo.png
 * (docs/scene-files.md). */
#ifndef JANSSEN_H
#define JANSSEN_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* The sums over the samples of the window (per band: its index k holds the
 * heights [k, k + 1) band above the floor). */
typedef struct janssen_acc {
    size_t nb, samples;
    double *normal;   /* the normal force of the particles on the band of the side, N */
    double *shear;    /* the side's force on the particles in the band along up (friction), N */
    double *vertical; /* the force across the band's middle height: the weight of the
                         particles above less the side's support above, N */
    double floor;     /* the floor's force on the particles along up, N */
    double weight;    /* the weight of the particles in the silo, N */
    double zone_mass; /* the mass of the particles whose centres lie in the zone, kg */
} janssen_acc;

/* Adds the state of s's world to the sums: 0, or -1 with a message on
 * stderr (a read failed, or out of memory). */
int janssen_sample(const scene *s, janssen_acc *a);

/* Writes the measured and predicted stresses to the summary `sum` as key =
 * value lines, the profile to silo.csv and the picture silo.png in the
 * folder `dir`: 0, or -1 with a message on stderr. */
int janssen_report(const scene *s, const janssen_acc *a, FILE *sum, const char *dir);

void janssen_free(janssen_acc *a);

#endif
