/* SPDX-License-Identifier: GPL-3.0-or-later */
/* CSC copy of the collocation Newton matrix (see colloc_sparse.h).  One walk
 * over the unknowns writes the pattern and the values together, so the
 * pattern of alloc and of fill cannot disagree. */
#include "colloc_sparse.h"

#include <sunmatrix/sunmatrix_sparse.h>

long colloc_sparse_nnz(const colloc_jac *J)
{
  const long nr = (long)J->ncol * J->ndim, nq = J->ndense, nb = J->nbc, N = J->ntst;
  long nnz = N * (long)(J->ncol - 1) * J->ndim * (nr + nq);        /* interior nodes */
  nnz += (long)J->ndim * ((N + 1) * (2 * nr + nq) - 2 * nr + 2 * nb); /* mesh points */
  nnz += (long)J->nfpr * (N * nr + nb + nq);                        /* parameters */
  return nnz;
}

/* Write column pointers, row indices and values of J into the arrays. */
static void colloc_sparse_walk(const colloc_jac *J, sunindextype *colptr, sunindextype *rowind, double *val)
{
  const int nd = J->ndim, nc = J->ncol, nq = J->ndense, nb = J->nbc, N = J->ntst, nf = J->nfpr;
  const int nr = nc * nd;
  const sunindextype rb = (sunindextype)N * nr, rd = rb + nb;
  sunindextype z = 0, col = 0;

  for (int jj = 0; jj <= N; jj++) {
    /* mesh point jj */
    for (int i = 0; i < nd; i++) {
      colptr[col++] = z;
      if (jj > 0) {
        const double *C = colloc_jac_coll_block(J, jj - 1);
        for (int r = 0; r < nr; r++, z++) {
          rowind[z] = (sunindextype)(jj - 1) * nr + r;
          val[z] = C[(size_t)(nc * nd + i) * (size_t)nr + (size_t)r];
        }
      }
      if (jj < N) {
        const double *C = colloc_jac_coll_block(J, jj);
        for (int r = 0; r < nr; r++, z++) {
          rowind[z] = (sunindextype)jj * nr + r;
          val[z] = C[(size_t)i * (size_t)nr + (size_t)r];
        }
      }
      if (jj == 0 || jj == N) {
        const double *B = J->bc + (size_t)(jj == 0 ? i : nd + i) * (size_t)nb;
        for (int b = 0; b < nb; b++, z++) {
          rowind[z] = rb + b;
          val[z] = B[b];
        }
      }
      for (int d = 0; d < nq; d++, z++) {
        double v = 0.0;
        if (jj > 0) v += colloc_jac_dense_block(J, jj - 1)[(size_t)(nc * nd + i) * (size_t)nq + (size_t)d];
        if (jj < N) v += colloc_jac_dense_block(J, jj)[(size_t)i * (size_t)nq + (size_t)d];
        rowind[z] = rd + d;
        val[z] = v;
      }
    }
    if (jj == N) break;
    /* interior nodes of interval jj */
    const double *C = colloc_jac_coll_block(J, jj), *D = colloc_jac_dense_block(J, jj);
    for (int c = nd; c < nc * nd; c++) {
      colptr[col++] = z;
      for (int r = 0; r < nr; r++, z++) {
        rowind[z] = (sunindextype)jj * nr + r;
        val[z] = C[(size_t)c * (size_t)nr + (size_t)r];
      }
      for (int d = 0; d < nq; d++, z++) {
        rowind[z] = rd + d;
        val[z] = D[(size_t)c * (size_t)nq + (size_t)d];
      }
    }
  }
  for (int p = 0; p < nf; p++) {
    colptr[col++] = z;
    for (int j = 0; j < N; j++) {
      const double *C = colloc_jac_coll_block(J, j) + (size_t)((nc + 1) * nd + p) * (size_t)nr;
      for (int r = 0; r < nr; r++, z++) {
        rowind[z] = (sunindextype)j * nr + r;
        val[z] = C[r];
      }
    }
    for (int b = 0; b < nb; b++, z++) {
      rowind[z] = rb + b;
      val[z] = J->bc[(size_t)(2 * nd + p) * (size_t)nb + (size_t)b];
    }
    for (int d = 0; d < nq; d++, z++) {
      rowind[z] = rd + d;
      val[z] = J->dense_par[(size_t)p * (size_t)nq + (size_t)d];
    }
  }
  colptr[col] = z;
}

SUNMatrix colloc_sparse_alloc(const colloc_jac *pattern, SUNContext ctx)
{
  if (!pattern || !ctx) return NULL;
  SUNMatrix A = SUNSparseMatrix(pattern->n, pattern->n, (sunindextype)colloc_sparse_nnz(pattern), CSC_MAT, ctx);
  if (!A) return NULL;
  colloc_sparse_walk(pattern, SUNSparseMatrix_IndexPointers(A), SUNSparseMatrix_IndexValues(A), SUNSparseMatrix_Data(A));
  return A;
}

int colloc_sparse_fill(const colloc_jac *J, SUNMatrix csc)
{
  if (!J || !csc || SUNMatGetID(csc) != SUNMATRIX_SPARSE || SUNSparseMatrix_SparseType(csc) != CSC_MAT ||
      SUNSparseMatrix_Rows(csc) != J->n || SUNSparseMatrix_Columns(csc) != J->n ||
      SUNSparseMatrix_NNZ(csc) != (sunindextype)colloc_sparse_nnz(J))
    return -1;
  colloc_sparse_walk(J, SUNSparseMatrix_IndexPointers(csc), SUNSparseMatrix_IndexValues(csc), SUNSparseMatrix_Data(csc));
  return 0;
}
