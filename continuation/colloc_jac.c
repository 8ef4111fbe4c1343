/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Block storage of the collocation Newton matrix: allocation and the few
 * products the solvers and the tests need.  The layout is fixed by
 * colloc_jac.h; this file only walks it. */
#include "colloc_jac.h"

#include "cable/cable_status.h"

#include <cblas.h>
#include <stdlib.h>
#include <string.h>

colloc_jac *colloc_jac_alloc(int ndim, int ntst, int ncol, int nfpr, int nbc, int nint)
{
  /* The Newton matrix is square: ntst*ncol*ndim collocation rows plus nbc
   * boundary rows plus nint+1 dense rows must match the unknowns. */
  if (ndim < 1 || ntst < 1 || ncol < 1 || nfpr < 0 || nbc < 0 || nint < 0) return NULL;
  if (nbc + nint + 1 != ndim + nfpr) return NULL;

  colloc_jac *J = calloc(1, sizeof *J);
  if (!J) return NULL;
  J->ndim = ndim;
  J->ntst = ntst;
  J->ncol = ncol;
  J->nfpr = nfpr;
  J->nbc = nbc;
  J->nint = nint;
  J->ndense = nint + 1;
  J->n = ndim * (ntst * ncol + 1) + nfpr;
  J->coll_stride = (size_t)(ncol * ndim) * (size_t)((ncol + 1) * ndim + nfpr);
  J->dense_stride = (size_t)J->ndense * (size_t)((ncol + 1) * ndim);

  /* calloc(0) may return NULL: allocate at least one double per array. */
  size_t ncoll = (size_t)ntst * J->coll_stride;
  size_t nbcv = (size_t)nbc * (size_t)(2 * ndim + nfpr);
  size_t ndns = (size_t)ntst * J->dense_stride;
  size_t npar = (size_t)J->ndense * (size_t)nfpr;
  J->coll = calloc(ncoll ? ncoll : 1, sizeof(double));
  J->bc = calloc(nbcv ? nbcv : 1, sizeof(double));
  J->dense = calloc(ndns ? ndns : 1, sizeof(double));
  J->dense_par = calloc(npar ? npar : 1, sizeof(double));
  if (!J->coll || !J->bc || !J->dense || !J->dense_par) {
    colloc_jac_free(J);
    return NULL;
  }
  return J;
}

void colloc_jac_free(colloc_jac *J)
{
  if (!J) return;
  free(J->coll);
  free(J->bc);
  free(J->dense);
  free(J->dense_par);
  free(J);
}

void colloc_jac_zero(colloc_jac *J)
{
  memset(J->coll, 0, (size_t)J->ntst * J->coll_stride * sizeof(double));
  memset(J->bc, 0, (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr) * sizeof(double));
  memset(J->dense, 0, (size_t)J->ntst * J->dense_stride * sizeof(double));
  memset(J->dense_par, 0, (size_t)J->ndense * (size_t)J->nfpr * sizeof(double));
}

/* Offsets of the unknowns of colloc_jac.h. */
static size_t jac_node(const colloc_jac *J, int j) { return (size_t)(j * J->ncol) * (size_t)J->ndim; }
static size_t jac_par(const colloc_jac *J) { return (size_t)J->ndim * (size_t)(J->ntst * J->ncol + 1); }
static size_t jac_bc_row(const colloc_jac *J) { return (size_t)J->ntst * (size_t)(J->ncol * J->ndim); }

/* The interval loops run over the vectors inside each interval, so that a
 * block is read from memory once for all k vectors; every vector sees the
 * same operations in the same order as alone. */
typedef struct {
  const colloc_jac *J;
  int k;
  const double *X;
  double *Y;
} matvec_ctx;

/* The collocation rows of interval j for the k vectors: they read only the
 * interval's nodes and the parameters and write only the interval's rows. */
static void matvec_interval(void *p, int j)
{
  const matvec_ctx *c = p;
  const colloc_jac *J = c->J;
  const int nd = J->ndim, nc = J->ncol, nf = J->nfpr;
  const int nr = nc * nd, nn = (nc + 1) * nd;
  const size_t n = (size_t)J->n;
  const double *C = colloc_jac_coll_block(J, j);
  for (int v = 0; v < c->k; v++) {
    const double *x = c->X + (size_t)v * n, *pv = x + jac_par(J);
    double *yj = c->Y + (size_t)v * n + (size_t)j * (size_t)nr;
    /* The ncol+1 nodes of interval j are contiguous in x. */
    cblas_dgemv(CblasColMajor, CblasNoTrans, nr, nn, 1.0, C, nr, x + jac_node(J, j), 1, 0.0, yj, 1);
    if (nf > 0)
      cblas_dgemv(CblasColMajor, CblasNoTrans, nr, nf, 1.0, C + (size_t)nn * (size_t)nr, nr, pv, 1, 1.0, yj, 1);
  }
}

void colloc_jac_matvec_many(const colloc_jac *J, int k, const double *X, double *Y)
{
  colloc_jac_matvec_many_team(J, NULL, k, X, Y);
}

void colloc_jac_matvec_many_team(const colloc_jac *J, cable_team *team, int k, const double *X, double *Y)
{
  const int nd = J->ndim, nc = J->ncol, nf = J->nfpr, nb = J->nbc, nq = J->ndense;
  const int nn = (nc + 1) * nd;
  const size_t n = (size_t)J->n, rb = jac_bc_row(J);

  matvec_ctx ctx = {J, k, X, Y};
  cable_team_run(team, matvec_interval, &ctx, J->ntst);
  /* the boundary and dense rows: the dense rows sum over the intervals in
     interval order, on the calling thread */
  for (int v = 0; v < k; v++) {
    const double *x = X + (size_t)v * n, *p = x + jac_par(J);
    double *y = Y + (size_t)v * n;
    if (nb > 0) {
      double *yb = y + rb;
      cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nd, 1.0, J->bc, nb, x, 1, 0.0, yb, 1);
      cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nd, 1.0, J->bc + (size_t)nd * (size_t)nb, nb,
                  x + jac_node(J, J->ntst), 1, 1.0, yb, 1);
      if (nf > 0)
        cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nf, 1.0, J->bc + (size_t)(2 * nd) * (size_t)nb, nb, p, 1, 1.0,
                    yb, 1);
    }
    double *yd = y + rb + (size_t)nb;
    for (int d = 0; d < nq; d++) yd[d] = 0.0;
    for (int j = 0; j < J->ntst; j++)
      cblas_dgemv(CblasColMajor, CblasNoTrans, nq, nn, 1.0, colloc_jac_dense_block(J, j), nq, x + jac_node(J, j), 1,
                  1.0, yd, 1);
    if (nf > 0) cblas_dgemv(CblasColMajor, CblasNoTrans, nq, nf, 1.0, J->dense_par, nq, p, 1, 1.0, yd, 1);
  }
}

void colloc_jac_matvec(const colloc_jac *J, const double *x, double *y) { colloc_jac_matvec_many(J, 1, x, y); }

void colloc_jac_matvec_team(const colloc_jac *J, cable_team *team, const double *x, double *y)
{
  colloc_jac_matvec_many_team(J, team, 1, x, y);
}

/* Interval j's transposed contributions for one vector: C_j^T x_j (nodes,
 * then parameters) and D_j^T x_d into t (2 nn + nfpr doubles), each with
 * beta = 0.  The BLAS may add a column's dot product to y in parts (OpenBLAS's
 * dgemv_t kernel for AMD Zen does), so y + C^T x with beta = 1 need not be
 * y + t to the bit: both the single pass and the one-pass pair below add t. */
static void interval_transposed(const colloc_jac *J, int j, const double *x, double *t)
{
  const int nd = J->ndim, nc = J->ncol, nf = J->nfpr, nq = J->ndense, nb = J->nbc;
  const int nr = nc * nd, nn = (nc + 1) * nd;
  const double *C = colloc_jac_coll_block(J, j), *xd = x + jac_bc_row(J) + (size_t)nb;
  const double *xj = x + (size_t)j * (size_t)nr;
  cblas_dgemv(CblasColMajor, CblasTrans, nr, nn, 1.0, C, nr, xj, 1, 0.0, t, 1);
  if (nf > 0) cblas_dgemv(CblasColMajor, CblasTrans, nr, nf, 1.0, C + (size_t)nn * (size_t)nr, nr, xj, 1, 0.0, t + nn, 1);
  cblas_dgemv(CblasColMajor, CblasTrans, nq, nn, 1.0, colloc_jac_dense_block(J, j), nq, xd, 1, 0.0, t + nn + nf, 1);
}

/* y += interval j's contributions t (interval_transposed), in one order. */
static void add_interval(const colloc_jac *J, int j, const double *t, double *y)
{
  const int nf = J->nfpr, nn = (J->ncol + 1) * J->ndim;
  double *yn = y + jac_node(J, j), *p = y + jac_par(J);
  for (int i = 0; i < nn; i++) yn[i] += t[i];
  for (int q = 0; q < nf; q++) p[q] += t[nn + q];
  for (int i = 0; i < nn; i++) yn[i] += t[nn + nf + i];
}

/* y += the boundary and dense rows' transposed contributions. */
static void add_end_rows_transposed(const colloc_jac *J, const double *x, double *y)
{
  const int nd = J->ndim, nf = J->nfpr, nb = J->nbc, nq = J->ndense;
  const size_t rb = jac_bc_row(J);
  const double *xd = x + rb + (size_t)nb;
  double *p = y + jac_par(J);
  if (nb > 0) {
    const double *xb = x + rb;
    cblas_dgemv(CblasColMajor, CblasTrans, nb, nd, 1.0, J->bc, nb, xb, 1, 1.0, y, 1);
    cblas_dgemv(CblasColMajor, CblasTrans, nb, nd, 1.0, J->bc + (size_t)nd * (size_t)nb, nb, xb, 1, 1.0,
                y + jac_node(J, J->ntst), 1);
    if (nf > 0)
      cblas_dgemv(CblasColMajor, CblasTrans, nb, nf, 1.0, J->bc + (size_t)(2 * nd) * (size_t)nb, nb, xb, 1, 1.0, p,
                  1);
  }
  if (nf > 0) cblas_dgemv(CblasColMajor, CblasTrans, nq, nf, 1.0, J->dense_par, nq, xd, 1, 1.0, p, 1);
}

int colloc_jac_matvec_transpose_many(const colloc_jac *J, int k, const double *X, double *Y)
{
  const size_t n = (size_t)J->n, per = colloc_jac_pair_scratch(J, 1) / (size_t)J->ntst;
  double *t = malloc(per * sizeof *t);
  if (!t) return CABLE_ERR_ALLOC;
  memset(Y, 0, (size_t)k * n * sizeof(double));
  for (int j = 0; j < J->ntst; j++)
    for (int v = 0; v < k; v++) {
      interval_transposed(J, j, X + (size_t)v * n, t);
      add_interval(J, j, t, Y + (size_t)v * n);
    }
  for (int v = 0; v < k; v++) add_end_rows_transposed(J, X + (size_t)v * n, Y + (size_t)v * n);
  free(t);
  return CABLE_SUCCESS;
}

size_t colloc_jac_pair_scratch(const colloc_jac *J, int k)
{
  const size_t nn = (size_t)(J->ncol + 1) * (size_t)J->ndim;
  return (size_t)J->ntst * (size_t)k * (2 * nn + (size_t)J->nfpr);
}

typedef struct {
  matvec_ctx mv;
  const double *XT;
  double *scratch, *sumsq;
} pair_ctx;

/* Interval j: its rows of J X (matvec_interval), its transposed
 * contributions C_j^T xt_j (nodes, then parameters) and D_j^T xt_d into
 * scratch, and its block's sum of squares. */
static void pair_interval(void *p, int j)
{
  const pair_ctx *c = p;
  const colloc_jac *J = c->mv.J;
  const int nn = (J->ncol + 1) * J->ndim;
  const size_t n = (size_t)J->n, per = 2 * (size_t)nn + (size_t)J->nfpr;
  const double *C = colloc_jac_coll_block(J, j);
  if (c->sumsq) {
    const size_t len = J->coll_stride;
    double q[4] = {0, 0, 0, 0};
    size_t i = 0;
    for (; i + 4 <= len; i += 4)
      for (int t = 0; t < 4; t++) q[t] += C[i + t] * C[i + t];
    for (; i < len; i++) q[0] += C[i] * C[i];
    c->sumsq[j] = (q[0] + q[1]) + (q[2] + q[3]);
  }
  matvec_interval((void *)&c->mv, j);
  for (int v = 0; v < c->mv.k; v++)
    interval_transposed(J, j, c->XT + (size_t)v * n, c->scratch + ((size_t)j * (size_t)c->mv.k + (size_t)v) * per);
}

void colloc_jac_matvec_pair_team(const colloc_jac *J, cable_team *team, int k, const double *X, double *Y,
                                 const double *XT, double *YT, double *scratch, double *sumsq)
{
  const int nd = J->ndim, nc = J->ncol, nf = J->nfpr, nb = J->nbc, nq = J->ndense;
  const int nn = (nc + 1) * nd;
  const size_t n = (size_t)J->n, rb = jac_bc_row(J), per = 2 * (size_t)nn + (size_t)nf;
  pair_ctx pc = {{J, k, X, Y}, XT, scratch, sumsq};
  cable_team_run(team, pair_interval, &pc, J->ntst);
  /* J X: the boundary and dense rows, as colloc_jac_matvec_many_team */
  for (int v = 0; v < k; v++) {
    const double *x = X + (size_t)v * n, *p = x + jac_par(J);
    double *y = Y + (size_t)v * n;
    if (nb > 0) {
      double *yb = y + rb;
      cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nd, 1.0, J->bc, nb, x, 1, 0.0, yb, 1);
      cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nd, 1.0, J->bc + (size_t)nd * (size_t)nb, nb,
                  x + jac_node(J, J->ntst), 1, 1.0, yb, 1);
      if (nf > 0)
        cblas_dgemv(CblasColMajor, CblasNoTrans, nb, nf, 1.0, J->bc + (size_t)(2 * nd) * (size_t)nb, nb, p, 1, 1.0,
                    yb, 1);
    }
    double *yd = y + rb + (size_t)nb;
    for (int d = 0; d < nq; d++) yd[d] = 0.0;
    for (int j = 0; j < J->ntst; j++)
      cblas_dgemv(CblasColMajor, CblasNoTrans, nq, nn, 1.0, colloc_jac_dense_block(J, j), nq, x + jac_node(J, j), 1,
                  1.0, yd, 1);
    if (nf > 0) cblas_dgemv(CblasColMajor, CblasNoTrans, nq, nf, 1.0, J->dense_par, nq, p, 1, 1.0, yd, 1);
  }
  /* J^T XT: the intervals' contributions in interval order (as
     colloc_jac_matvec_transpose_many adds them), then the end rows */
  memset(YT, 0, (size_t)k * n * sizeof(double));
  for (int j = 0; j < J->ntst; j++)
    for (int v = 0; v < k; v++)
      add_interval(J, j, scratch + ((size_t)j * (size_t)k + (size_t)v) * per, YT + (size_t)v * n);
  for (int v = 0; v < k; v++) add_end_rows_transposed(J, XT + (size_t)v * n, YT + (size_t)v * n);
}

int colloc_jac_matvec_transpose(const colloc_jac *J, const double *x, double *y)
{
  return colloc_jac_matvec_transpose_many(J, 1, x, y);
}

void colloc_jac_to_dense(const colloc_jac *J, double *A)
{
  const int nd = J->ndim, nc = J->ncol, nf = J->nfpr, nb = J->nbc, nq = J->ndense;
  const int nr = nc * nd, nn = (nc + 1) * nd;
  const size_t n = (size_t)J->n, pc = jac_par(J), rb = jac_bc_row(J), rd = rb + (size_t)nb;

  memset(A, 0, n * n * sizeof(double));
  for (int j = 0; j < J->ntst; j++) {
    const double *C = colloc_jac_coll_block(J, j);
    const double *D = colloc_jac_dense_block(J, j);
    const size_t r0 = (size_t)j * (size_t)nr, c0 = jac_node(J, j);
    for (int c = 0; c < nn; c++) {
      for (int r = 0; r < nr; r++) A[(c0 + (size_t)c) * n + r0 + (size_t)r] += C[(size_t)c * (size_t)nr + (size_t)r];
      for (int d = 0; d < nq; d++) A[(c0 + (size_t)c) * n + rd + (size_t)d] += D[(size_t)c * (size_t)nq + (size_t)d];
    }
    for (int q = 0; q < nf; q++)
      for (int r = 0; r < nr; r++)
        A[(pc + (size_t)q) * n + r0 + (size_t)r] += C[(size_t)(nn + q) * (size_t)nr + (size_t)r];
  }
  const size_t cN = jac_node(J, J->ntst);
  for (int b = 0; b < nb; b++) {
    for (int i = 0; i < nd; i++) {
      A[(size_t)i * n + rb + (size_t)b] += J->bc[(size_t)i * (size_t)nb + (size_t)b];
      A[(cN + (size_t)i) * n + rb + (size_t)b] += J->bc[(size_t)(nd + i) * (size_t)nb + (size_t)b];
    }
    for (int q = 0; q < nf; q++) A[(pc + (size_t)q) * n + rb + (size_t)b] += J->bc[(size_t)(2 * nd + q) * (size_t)nb + (size_t)b];
  }
  for (int d = 0; d < nq; d++)
    for (int q = 0; q < nf; q++) A[(pc + (size_t)q) * n + rd + (size_t)d] += J->dense_par[(size_t)q * (size_t)nq + (size_t)d];
}
