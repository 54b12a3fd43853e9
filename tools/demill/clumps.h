/* clumps.h: what the demill program reports of a scene's clumps (their
 * templates, with the fit of a template made from a mesh, and how many
 * clumps of each the scene's fills added) and the charge's mass and centre
 * of mass with each clump counted once. */
#ifndef DEMILL_CLUMPS_H
#define DEMILL_CLUMPS_H

#include <stdio.h>

#include "scene.h"

/* The particles' total mass (kg) and centre of mass (m; z 0 in 2D): a free
 * particle with its own mass, a clump once, its mass (DEMILL_CLUMP_MASS) at
 * its centre of mass; a member's DEMILL_PARTICLE_MASS, its whole clump's,
 * is not summed. The centre is NaN without particles. DEMILL_OK or the
 * API's status. */
demill_status clumps_charge(demill_world *w, double *mass, double centre[3]);

/* summary.txt's lines of the clumps (`key = value`): `clumps` and
 * `clumps_mass_kg`, and for each template `template_NAME_spheres`,
 * `_mass_kg`, `_volume_m3`, `_clumps` (not on a restart) and for one made
 * from a mesh its fit, `_mesh_volume_m3`, `_fit_volume_error`,
 * `_fit_deviation_out_m`, `_fit_deviation_in_m` and `_fit_cell_m`. Nothing
 * for a scene without templates. */
void clumps_report(const scene *s, FILE *f);

/* A line per template for the terminal: its spheres and mass, and the fit of
 * one made from a mesh. */
void clumps_print(const scene *s, FILE *f);

#endif
