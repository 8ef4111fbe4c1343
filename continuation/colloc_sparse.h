/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The reference path LINSOLVER=klu: the Newton matrix of colloc_jac.h as a
 * SUNDIALS compressed-sparse-column matrix for SUNLinSol_KLU.
 *
 * The sparsity pattern is the full block structure (every entry of every
 * block, zero or not), so it is fixed for given sizes and KLU's symbolic
 * analysis can be reused across Newton steps. */
#ifndef CABLE_COLLOC_SPARSE_H
#define CABLE_COLLOC_SPARSE_H

#include <sundials/sundials_context.h>
#include <sundials/sundials_matrix.h>

#include "colloc_jac.h"

/* An n x n CSC SUNSparseMatrix with the block pattern of `pattern`'s sizes,
 * holding pattern's values.  NULL on allocation failure. */
SUNMatrix colloc_sparse_alloc(const colloc_jac *pattern, SUNContext ctx);

/* Copy J's values into csc (allocated by colloc_sparse_alloc for J's sizes).
 * 0 ok; -1 if csc is not a CSC matrix of J's order and pattern size. */
int colloc_sparse_fill(const colloc_jac *J, SUNMatrix csc);

/* Structural nonzeros of the block pattern. */
long colloc_sparse_nnz(const colloc_jac *J);

#endif
