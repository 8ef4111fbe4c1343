/* Braid problems started from STPNT: the starting geometry comes from the
 * constants: TORUS=p ((p,2) torus knot for odd p, link for even p >= 2; the
 * two-ring start is refused: it is degenerate), HAND=1|-1, and PAR={...}
 * values of Delta, Ltot (knots) or L (links), T and the material constants. */
#ifndef CABLE_BRAID_RESOLVER_H
#define CABLE_BRAID_RESOLVER_H

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"

/* A runnable braid problem name ("braid_knot", "braid_knot_sym",
 * "braid_link") for a run from STPNT (from_stpnt = 1) with constants c: *pb
 * owns its prepared starting parameters until braid_problem_release.
 * CABLE_ERR_NOTFOUND without touching err when the name is not a braid
 * problem (or the run does not start from STPNT); another error with err. */
int braid_problem_prepare(const char *name, const cable_constants *c, int from_stpnt, const cable_problem **pb,
                          cable_error *err);
/* Frees a problem from braid_problem_prepare. */
void braid_problem_release(const cable_problem *pb);

#endif
