/** @file demill.h
 * @brief libdemill, discrete element simulation of granular material in
 * grinding mills and related scenes.
 *
 * This umbrella header is the whole public API; each part is documented in
 * its own header:
 *
 * | header              | content                                            |
 * |---------------------|----------------------------------------------------|
 * | demill/common.h     | version, status codes, ids, parameter metadata     |
 * | demill/world.h      | worlds: create, configure, step                    |
 * | demill/material.h   | materials and per-pair contact models              |
 * | demill/particles.h  | particles: add, remove, read, write                |
 * | demill/wall.h       | walls with prescribed motion                       |
 * | demill/body.h       | bodies the particles move: springs, dampers, force |
 * | demill/query.h      | contacts and energies                              |
 * | demill/drum.h       | the mill: drum, lifters, charge, power, spectrum   |
 * | demill/state.h      | snapshots, checkpoint files, listing a world's ids |
 * | demill/vtk.h        | output for ParaView: particles, walls, time series |
 * | demill/grinding.h   | ore breakage models, batch-grinding population balance |
 *
 * A minimal program:
 * @code
 *   demill_world *w;
 *   demill_id steel, ball;
 *   demill_world_create(3, &w);
 *   demill_material_create(w, &steel);
 *   demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ);
 *   double x[3] = {0, 0.1, 0}, r = 0.01;
 *   demill_particles_add(w, steel, 1, x, &r, NULL, 0, &ball);
 *   demill_world_step(w, 1000);
 *   demill_world_destroy(w);
 * @endcode
 */
#ifndef DEMILL_H
#define DEMILL_H

#include "demill/common.h"
#include "demill/world.h"
#include "demill/material.h"
#include "demill/particles.h"
#include "demill/wall.h"
#include "demill/body.h"
#include "demill/clump.h"
#include "demill/query.h"
#include "demill/drum.h"
#include "demill/insert.h"
#include "demill/state.h"
#include "demill/vtk.h"
#include "demill/grinding.h"

#endif /* DEMILL_H */
