/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A SUNDIALS SUNMatrix (SUNMATRIX_CUSTOM) around the block storage of
 * colloc_jac.h, so that KINSOL can hand the Newton matrix to the structured
 * linear solver (sunlinsol_colloc.h).
 *
 * Ops: getid, clone, destroy, zero, matvec, space.  copy/scaleadd/scaleaddi
 * are not provided: KINSOL's matrix-based interface with a user Jacobian
 * function does not call them. */
#ifndef CABLE_SUNMATRIX_COLLOC_H
#define CABLE_SUNMATRIX_COLLOC_H

#include <sundials/sundials_matrix.h>

#include "colloc_jac.h"

/* Wrap J (not owned: the caller frees J after SUNMatDestroy).  NULL if J or
 * ctx is NULL or on allocation failure.  SUNMatClone of the result allocates
 * a new colloc_jac of the same sizes, owned (and freed) by the clone. */
SUNMatrix SUNMat_Colloc(colloc_jac *J, SUNContext ctx);

/* The wrapped blocks; NULL if A is not a SUNMat_Colloc matrix.  The zero op
 * only marks the matrix; this access carries the zeroing out when it is
 * still pending, so every reader sees a zeroed matrix. */
colloc_jac *SUNMat_Colloc_Jac(SUNMatrix A);

/* Says that every entry of A's blocks has been overwritten since the last
 * zero (e.g. by colloc_system_jacobian): a pending zeroing is dropped. */
void SUNMat_Colloc_Filled(SUNMatrix A);

#endif
