/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Banded LU with partial pivoting for the reduced system of abd_solver.c:
 * the algorithm, pivot choice and storage of LAPACK's unblocked dgbtf2
 * (doc/linear-algebra.md, "3. Banded LU of the mesh-point system"); what
 * differs is the work.
 *  - LAPACK runs its unblocked code on this system (block size 1 when
 *    KU <= 64) with one BLAS call (a daxpy inside dger) per column of every
 *    rank-one update: mostly call overhead on updates of about 45 x 90.
 *  - The augmented system is sparse inside its band: copy rows with two
 *    entries, the copies' columns zero in the condensed rows.  On the flat
 *    (7,2) knot at NTST 150 the factors hold 1.1e5 nonzeros in U and 0.9e5
 *    in L out of 6.5e5 and 3.2e5 band places.  An elimination step with a
 *    zero multiplier or a zero pivot-row entry changes nothing, so the
 *    update loops only over the nonzero multipliers and the nonzero entries
 *    of the pivot row.
 *  - The factors are kept compressed as they are made (U by rows: row j is
 *    final once it has been the pivot row; L by columns), so each solve
 *    touches only nonzeros.
 * Skipping an exact zero subtracts nothing: the factors are LAPACK's up to
 * the rounding of the remaining operations (fused multiply-adds in the BLAS),
 * the pivots the same unless two candidates tie to the last bit. */
#include "abd_band.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* The compressed factors' first capacity: a quarter of the band's places
 * (the flat (7,2) knot at NTST 150 fills 17 % of U's and 28 % of L's); they
 * grow by half as much again when a factorisation needs more
 * (abd_band_factor_upto), so after the first factorisations of a run none
 * allocates. */
#define ABD_BAND_FIRST_FILL 4

static size_t first_cap(size_t full)
{
  size_t c = full / ABD_BAND_FIRST_FILL + 1;
  return c < full ? c : full;
}

int abd_band_alloc(abd_band *f, int n, int kl, int ku)
{
  size_t nu = (size_t)n * (size_t)(kl + ku) + 1, nl = (size_t)n * (size_t)kl + 1;
  f->n = n;
  f->kl = kl;
  f->ku = ku;
  f->ring = n;
  f->umax = 0.0;
  f->oom = 0;
  f->ucap = first_cap(nu);
  f->lcap = first_cap(nl);
  f->ipiv = malloc((size_t)n * sizeof *f->ipiv);
  f->nzl = malloc(((size_t)kl + 1) * sizeof *f->nzl);
  f->ud = malloc((size_t)n * sizeof *f->ud);
  f->up = malloc(((size_t)n + 1) * sizeof *f->up);
  f->uc = malloc(f->ucap * sizeof *f->uc);
  f->uv = malloc(f->ucap * sizeof *f->uv);
  f->lp = malloc(((size_t)n + 1) * sizeof *f->lp);
  f->li = malloc(f->lcap * sizeof *f->li);
  f->lv = malloc(f->lcap * sizeof *f->lv);
  if (!f->ipiv || !f->nzl || !f->ud || !f->up || !f->uc || !f->uv || !f->lp || !f->li || !f->lv) return -1;
  return 0;
}

void abd_band_set_ring(abd_band *f, int ncols)
{
  if (ncols < f->kl + f->ku + 1) ncols = f->kl + f->ku + 1;
  f->ring = ncols < f->n ? ncols : f->n;
}

/* Room for `need` entries in a compressed factor (index and value arrays of
 * capacity *cap): grows by half; -1 when out of memory (the old arrays
 * stay valid). */
static int reserve(size_t need, size_t *cap, int **idx, double **val)
{
  if (need <= *cap) return 0;
  size_t c = *cap + *cap / 2;
  if (c < need) c = need;
  int *ni = realloc(*idx, c * sizeof *ni);
  if (!ni) return -1;
  *idx = ni;
  double *nv = realloc(*val, c * sizeof *nv);
  if (!nv) return -1;
  *val = nv;
  *cap = c;
  return 0;
}

void abd_band_free(abd_band *f)
{
  free(f->ipiv);
  free(f->nzl);
  free(f->ud);
  free(f->up);
  free(f->uc);
  free(f->uv);
  free(f->lp);
  free(f->li);
  free(f->lv);
  f->ipiv = f->nzl = f->up = f->uc = f->lp = f->li = NULL;
  f->ud = f->uv = f->lv = NULL;
}

void abd_band_factor_begin(abd_band *f)
{
  f->fj = 0;
  f->fnu = 0;
  f->fnl = 0;
  f->fju = 0;
  f->finfo = 0;
  f->umax = 0.0;
  f->oom = 0;
}

/* Storage column of band column c (the ring of abd_band_set_ring), and of
 * column c + d from c's slot sc (0 <= d < ring: no division). */
static size_t slot(const abd_band *f, int c) { return (size_t)(c < f->ring ? c : c % f->ring); }
static size_t slot_after(const abd_band *f, size_t sc, int d)
{
  size_t s = sc + (size_t)d;
  return s >= (size_t)f->ring ? s - (size_t)f->ring : s;
}

/* Element (i, j) (0-based) of the band matrix: ab[slot(j) * ldab + kl + ku + i - j]. */
void abd_band_factor_upto(abd_band *f, double *ab, int ldab, int jend)
{
  const int n = f->n, kl = f->kl, kv = f->kl + f->ku;
  int info = f->finfo, nu = f->fnu, nl = f->fnl;
  double umax = f->umax;
  int ju = f->fju; /* last column reached by the updates so far */
  if (jend > n) jend = n;
  if (f->oom) return;
  for (int j = f->fj; j < jend; j++) {
    const size_t sj = slot(f, j);
    double *cj = ab + sj * (size_t)ldab + kv; /* cj[i] = A(j + i, j) */
    const int km = kl < n - 1 - j ? kl : n - 1 - j;
    f->up[j] = nu;
    f->lp[j] = nl;
    int jp = 0;
    double big = fabs(cj[0]);
    for (int i = 1; i <= km; i++)
      if (fabs(cj[i]) > big) {
        big = fabs(cj[i]);
        jp = i;
      }
    f->ipiv[j] = j + jp;
    f->ud[j] = cj[jp];
    if (cj[jp] == 0.0) {
      if (info == 0) info = j + 1;
      /* row j is not a pivot row: clear what it holds right of j (its
         entries reach column j + ku, or ju after fill) */
      const int lastc = j + f->ku < n - 1 ? j + f->ku : n - 1;
      for (int c = j + 1; c <= (ju > lastc ? ju : lastc); c++) ab[slot_after(f, sj, c - j) * (size_t)ldab + (size_t)(kv - c + j)] = 0.0;
      memset(cj, 0, ((size_t)km + 1) * sizeof *cj);
      continue;
    }
    if (big > umax) umax = big;
    const int last = j + f->ku + jp < n - 1 ? j + f->ku + jp : n - 1;
    if (last > ju) ju = last;
    if (jp != 0)
      for (int c = j; c <= ju; c++) { /* rows j and j + jp in columns j..ju */
        double *col = ab + slot_after(f, sj, c - j) * (size_t)ldab + kv - c; /* col[i] = A(i, c) */
        double t = col[j];
        col[j] = col[j + jp];
        col[j + jp] = t;
      }
    /* room for row j of U and column j of L */
    if (reserve((size_t)nu + (size_t)(ju - j), &f->ucap, &f->uc, &f->uv) != 0 ||
        reserve((size_t)nl + (size_t)km, &f->lcap, &f->li, &f->lv) != 0) {
      f->oom = 1;
      f->fj = j;
      f->fnu = nu;
      f->fnl = nl;
      return;
    }
    const double rp = 1.0 / cj[0];
    int *nz = f->nzl, nnz = 0;
    for (int i = 1; i <= km; i++) {
      cj[i] *= rp;
      if (cj[i] != 0.0) {
        nz[nnz++] = i;
        f->li[nl] = j + i;
        f->lv[nl++] = cj[i];
      }
    }
    for (int c = j + 1; c <= ju; c++) {
      double *a = ab + slot_after(f, sj, c - j) * (size_t)ldab + kv - c + j; /* a[i] = A(j + i, c) */
      const double u = a[0];
      a[0] = 0.0; /* row j of U is taken out (the zero invariant, abd_band.h) */
      if (u == 0.0) continue;
      f->uc[nu] = c;
      f->uv[nu++] = u;
      if (fabs(u) > umax) umax = fabs(u);
      /* only the rows with a nonzero multiplier are written (the dense
         loop runs when every row of the window has one): abd_band.h's
         promise to concurrent writers of the other rows */
      if (nnz == km)
        for (int i = 1; i <= km; i++) a[i] -= cj[i] * u;
      else
        for (int t = 0; t < nnz; t++) a[nz[t]] -= cj[nz[t]] * u;
    }
    memset(cj, 0, ((size_t)km + 1) * sizeof *cj); /* the pivot and L's column j are taken out */
  }
  if (jend > f->fj) f->fj = jend;
  f->up[f->fj] = nu;
  f->lp[f->fj] = nl;
  f->fnu = nu;
  f->fnl = nl;
  f->fju = ju;
  f->finfo = info;
  f->umax = umax;
}

int abd_band_factor_end(abd_band *f, double *ab, int ldab)
{
  abd_band_factor_upto(f, ab, ldab, f->n);
  return f->oom ? -1 : f->finfo;
}

int abd_band_factor(abd_band *f, double *ab, int ldab)
{
  abd_band_factor_begin(f);
  return abd_band_factor_end(f, ab, ldab);
}

void abd_band_solve(const abd_band *f, double *b)
{
  const int n = f->n;
  /* b <- L^{-1} P b, column by column (LAPACK's dgbtrs order) */
  for (int j = 0; j < n; j++) {
    const int p = f->ipiv[j];
    if (p != j) {
      double t = b[p];
      b[p] = b[j];
      b[j] = t;
    }
    const double bj = b[j];
    if (bj == 0.0) continue;
    for (int k = f->lp[j]; k < f->lp[j + 1]; k++) b[f->li[k]] -= f->lv[k] * bj;
  }
  /* U x = b by rows, from the last */
  for (int j = n - 1; j >= 0; j--) {
    double t = b[j];
    for (int k = f->up[j]; k < f->up[j + 1]; k++) t -= f->uv[k] * b[f->uc[k]];
    b[j] = t / f->ud[j];
  }
}

void abd_band_solve_transpose(const abd_band *f, double *b)
{
  const int n = f->n;
  /* U^T: forward; row j of U is column j of U^T */
  for (int j = 0; j < n; j++) {
    const double bj = b[j] / f->ud[j];
    b[j] = bj;
    if (bj == 0.0) continue;
    for (int k = f->up[j]; k < f->up[j + 1]; k++) b[f->uc[k]] -= f->uv[k] * bj;
  }
  /* L^T then P^T, backwards */
  for (int j = n - 1; j >= 0; j--) {
    double t = b[j];
    for (int k = f->lp[j]; k < f->lp[j + 1]; k++) t -= f->lv[k] * b[f->li[k]];
    b[j] = t;
    const int p = f->ipiv[j];
    if (p != j) {
      double s = b[p];
      b[p] = b[j];
      b[j] = s;
    }
  }
}
