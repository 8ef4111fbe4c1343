/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Block storage of the Newton matrix of the collocation system, as assembled by
 * the collocation code and consumed by the structured solver (abd_solver) or,
 * after conversion, by KLU.
 *
 * Unknowns (global order, n = ndim*(ntst*ncol+1) + nfpr):
 *   u at node k (0..ncol) of interval j, component i:  (j*ncol + k)*ndim + i
 *     (node ncol of interval j is node 0 of interval j+1: the mesh point)
 *   free parameter p:                                   ndim*(ntst*ncol+1) + p
 * Equations (global order, same count n):
 *   collocation row r (0..ncol*ndim-1) of interval j:  j*ncol*ndim + r
 *   boundary condition b (0..nbc-1):                   ntst*ncol*ndim + b
 *   dense row d (0..nint): integral conditions, then the arclength equation last:
 *                                                      ntst*ncol*ndim + nbc + d
 * Blocks (all column-major):
 *   coll  interval j: (ncol*ndim) x ((ncol+1)*ndim + nfpr), ld = ncol*ndim;
 *         columns: the ncol+1 nodes of the interval, then the free parameters
 *   bc    nbc x (2*ndim + nfpr), ld = nbc; columns: u(0), u(1), parameters
 *   dense interval j: (nint+1) x ((ncol+1)*ndim), ld = nint+1: the contribution
 *         of interval j's nodes; contributions of two intervals to a shared
 *         mesh point add up
 *   dense_par (nint+1) x nfpr, ld = nint+1
 */
#ifndef CABLE_COLLOC_JAC_H
#define CABLE_COLLOC_JAC_H

#include <stddef.h>

#include "cable_team.h"

typedef struct colloc_jac {
  int ndim, ntst, ncol, nfpr, nbc, nint;
  int n;                 /* unknowns = equations */
  int ndense;            /* nint + 1 */
  size_t coll_stride;    /* doubles between consecutive coll blocks */
  size_t dense_stride;   /* doubles between consecutive dense blocks */
  double *coll;
  double *bc;
  double *dense;
  double *dense_par;
} colloc_jac;

colloc_jac *colloc_jac_alloc(int ndim, int ntst, int ncol, int nfpr, int nbc, int nint);
void colloc_jac_free(colloc_jac *J);                 /* NULL is a no-op */
void colloc_jac_zero(colloc_jac *J);

static inline double *colloc_jac_coll_block(const colloc_jac *J, int j) { return J->coll + (size_t)j * J->coll_stride; }
static inline double *colloc_jac_dense_block(const colloc_jac *J, int j) { return J->dense + (size_t)j * J->dense_stride; }

/* y = J x (length n each). */
void colloc_jac_matvec(const colloc_jac *J, const double *x, double *y);
/* y = J^T x; CABLE_SUCCESS, or CABLE_ERR_ALLOC (its work space). */
int colloc_jac_matvec_transpose(const colloc_jac *J, const double *x, double *y);
/* The same for k vectors at once: X, Y hold k vectors of length n one after
 * the other; each block of J is read once for all of them, and every vector's
 * result is bit for bit that of the single-vector call. */
void colloc_jac_matvec_many(const colloc_jac *J, int k, const double *X, double *Y);
int colloc_jac_matvec_transpose_many(const colloc_jac *J, int k, const double *X, double *Y);
/* J x and J X with the collocation rows of the intervals shared out over a
 * thread team (cable_team.h; NULL: the calling thread): the same results, bit
 * for bit, for every team size, and the same as the calls above. */
void colloc_jac_matvec_team(const colloc_jac *J, cable_team *team, const double *x, double *y);
void colloc_jac_matvec_many_team(const colloc_jac *J, cable_team *team, int k, const double *X, double *Y);
/* Y = J X and YT = J^T XT (k vectors each) in one pass over the collocation
 * blocks, on the team: each interval's block is read once for both products
 * (and for its sum of squares into sumsq[j] when sumsq is not NULL: the
 * 4-way sum of abd_solver.c's ||J||_F).  The transposed contributions go to
 * scratch (colloc_jac_pair_scratch doubles) and are added in interval order
 * afterwards, so Y is bit for bit colloc_jac_matvec_many_team's and YT
 * colloc_jac_matvec_transpose_many's (both add each interval's contribution,
 * computed with beta = 0, in the same order: a BLAS may add a dot product to
 * y in parts; tests/test_threads.c compares them), for every team size. */
size_t colloc_jac_pair_scratch(const colloc_jac *J, int k);
void colloc_jac_matvec_pair_team(const colloc_jac *J, cable_team *team, int k, const double *X, double *Y,
                                 const double *XT, double *YT, double *scratch, double *sumsq);
/* Dense n x n column-major copy (tests and small problems). */
void colloc_jac_to_dense(const colloc_jac *J, double *A);

#endif
