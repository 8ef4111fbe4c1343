/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The mesh of a stored solution, resampled to another number of intervals. */
#ifndef CABLE_SOLUTION_MESH_H
#define CABLE_SOLUTION_MESH_H

#include "cable/cable_solution.h"

/* mesh[0..ntst]: s's mesh density resampled to ntst intervals (linear in the
 * interval index), as a restart on another NTST keeps it; mesh[0] = 0 and
 * mesh[ntst] = 1 exactly. */
void solution_mesh_resample(const cable_solution *s, int ntst, double *mesh);

#endif
