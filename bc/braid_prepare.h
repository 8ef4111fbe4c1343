/* SPDX-License-Identifier: GPL-3.0-or-later */
/* prepare/release of the braid problems (include/cable/cable_problem.h): a
 * run from STPNT gets an instance that owns its starting geometry, built from
 * the problem's keys TORUS=p ((p,2) torus knot for odd p, link for even
 * p >= 2; the two-ring start TORUS=0 is refused for links: it is degenerate)
 * and HAND=1|-1, and from PAR={...}: Delta, Ltot (knots) or L (links), T and
 * the material constants.  A restart gets the template itself. */
#ifndef CABLE_BRAID_PREPARE_H
#define CABLE_BRAID_PREPARE_H

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"

#define BRAID_NKEYS 2
/* TORUS and HAND */
extern const cable_problem_key braid_keys[BRAID_NKEYS];

int braid_prepare(const cable_problem *tmpl, const cable_constants *c, int from_stpnt, const cable_problem **pb,
                  cable_error *err);
void braid_release(const cable_problem *tmpl, const cable_problem *pb);

#endif
