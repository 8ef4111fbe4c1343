/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The Morse index of a solution of a variational boundary-value problem: the
 * number of negative eigenvalues of the second variation of the action on the
 * variations that keep the constraints to first order (doc/stability.md).
 * The problem declares its variational structure in cable_problem.variational. */
#ifndef CABLE_STABILITY_H
#define CABLE_STABILITY_H

#include "cable/cable_api.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"

#define CABLE_STAB_NEIG 8   /* smallest eigenvalues reported */

typedef struct cable_stab_result {
  int index;        /* eigenvalues below -tau: the Morse index */
  int nzero;        /* eigenvalues in [-tau, tau] (a fold, a branch point, an unremoved symmetry) */
  int nbasis;       /* N: the Ritz space's dimension before the constraints */
  int ndof;         /* N minus the rank of the linearised constraints */
  int neig;         /* entries of eig: min(CABLE_STAB_NEIG, ndof) */
  double eig[CABLE_STAB_NEIG];  /* the smallest eigenvalues (L2 mass form), ascending */
  double tau;       /* the zero tolerance, 1e3 eps max |sigma| */
} cable_stab_result;

/* The index of sol, a solution of pb, by the Ritz method of doc/stability.md
 * S2: continuous piecewise polynomials of degree `degree` (1..10) on sol's mesh
 * with every interval cut into `refine` (>= 1) equal pieces.  CABLE_SUCCESS,
 * or a negative status with err: CABLE_ERR_NULL, CABLE_ERR_INPUT (pb is not
 * variational, bad sizes), CABLE_ERR_CALLBACK (a callback failed),
 * CABLE_ERR_ALLOC, CABLE_ERR_LINSOLVE (LAPACK failed). */
CABLE_API int cable_stability_index(const cable_problem *pb, const cable_solution *sol, int refine,
                                    int degree, cable_stab_result *res, cable_error *err);

#endif
