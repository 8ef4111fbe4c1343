/* SPDX-License-Identifier: GPL-3.0-or-later */
/* abd_band.c, the banded LU of the reduced system: against LAPACK's dgbtrf
 * and dgbtrs on random sparse band matrices, the factorisation in pieces
 * (abd_band_factor_upto, used by abd_solver.c's pipeline) against the
 * one-call factorisation bit for bit, and the zero invariant: the storage is
 * all zero after every factorisation, singular ones included, so that a
 * second matrix factored in the same storage gives the factors of a fresh
 * one; the ring storage (abd_band_set_ring: KL + KU + 1 storage columns,
 * each matrix column written just before the elimination reaches it) against
 * the full storage, bit for bit, and the compressed factors' growth from a
 * small first capacity. */
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "abd_band.h"
#include "harness.h"

enum { N = 80, KL = 6, KU = 9, LDAB = 2 * KL + KU + 1 };

static double *at(double *ab, int i, int j) { return ab + (size_t)j * LDAB + KL + KU + i - j; }

static unsigned long lcg(unsigned long *s)
{
  *s = *s * 6364136223846793005UL + 1442695040888963407UL;
  return *s >> 33;
}

/* A random band matrix with about a third of its band places exactly zero;
 * column zero_col (if >= 0) entirely zero (an exactly singular matrix). */
static void random_band(double *ab, unsigned long seed, int zero_col)
{
  memset(ab, 0, sizeof(double) * LDAB * N);
  for (int j = 0; j < N; j++)
    for (int i = j - KU; i <= j + KL; i++) {
      if (i < 0 || i >= N || j == zero_col) continue;
      if (lcg(&seed) % 3 == 0) continue;
      *at(ab, i, j) = (double)(lcg(&seed) % 2001) / 1000.0 - 1.0;
    }
}

static int all_zero(const double *ab)
{
  for (int i = 0; i < LDAB * N; i++)
    if (ab[i] != 0.0) return 0;
  return 1;
}

static int same_factors(const abd_band *a, const abd_band *b)
{
  if (memcmp(a->ipiv, b->ipiv, N * sizeof(int)) || memcmp(a->ud, b->ud, N * sizeof(double)) ||
      memcmp(a->up, b->up, (N + 1) * sizeof(int)) || memcmp(a->lp, b->lp, (N + 1) * sizeof(int)))
    return 0;
  int nu = a->up[N], nl = a->lp[N];
  return !memcmp(a->uc, b->uc, (size_t)nu * sizeof(int)) && !memcmp(a->uv, b->uv, (size_t)nu * sizeof(double)) &&
         !memcmp(a->li, b->li, (size_t)nl * sizeof(int)) && !memcmp(a->lv, b->lv, (size_t)nl * sizeof(double)) &&
         a->umax == b->umax;
}

static void test_against_lapack(void)
{
  double ab[LDAB * N], lab[LDAB * N], b[N], x[N], bt[N], xt[N];
  lapack_int ipiv[N];
  abd_band f;
  if (abd_band_alloc(&f, N, KL, KU) != 0) {
    test_true("abd_band_alloc", 0);
    return;
  }
  double worst = 0.0, worst_t = 0.0; /* error / (tolerance of the draw) */
  int pivots_same = 1, zero_after = 1;
  for (int trial = 0; trial < 20; trial++) {
    random_band(ab, 1000 + (unsigned long)trial, -1);
    memcpy(lab, ab, sizeof lab);
    unsigned long seed = 77 + (unsigned long)trial;
    for (int i = 0; i < N; i++) b[i] = (double)(lcg(&seed) % 1000) / 500.0 - 1.0;
    memcpy(x, b, sizeof x);
    memcpy(bt, b, sizeof bt);
    memcpy(xt, b, sizeof xt);
    /* 1-norm of A (band rows KL.. of the factorisation storage) for the condition number */
    double anorm = LAPACKE_dlangb(LAPACK_COL_MAJOR, '1', N, KL, KU, lab + KL, LDAB), rcond = 0.0;
    if (LAPACKE_dgbtrf(LAPACK_COL_MAJOR, N, N, KL, KU, lab, LDAB, ipiv) != 0) continue; /* singular draw */
    LAPACKE_dgbcon(LAPACK_COL_MAJOR, '1', N, KL, KU, lab, LDAB, ipiv, anorm, &rcond);
    /* two backward-stable solutions differ by at most about
       2 n eps cond_1(A) relative to |x|; the factor 10 covers the estimate
       of cond by dgbcon (within a factor 3 or so in practice) */
    const double tol = 10.0 * 2.0 * N * 2.220446049250313e-16 / rcond;
    LAPACKE_dgbtrs(LAPACK_COL_MAJOR, 'N', N, KL, KU, 1, lab, LDAB, ipiv, bt, N);
    test_int("abd_band_factor of a regular matrix", abd_band_factor(&f, ab, LDAB), 0);
    zero_after &= all_zero(ab);
    for (int i = 0; i < N; i++) pivots_same &= f.ipiv[i] == ipiv[i] - 1;
    abd_band_solve(&f, x);
    LAPACKE_dgbtrs(LAPACK_COL_MAJOR, 'T', N, KL, KU, 1, lab, LDAB, ipiv, b, N);
    abd_band_solve_transpose(&f, xt);
    double scale = 0.0;
    for (int i = 0; i < N; i++) scale = fmax(scale, fabs(bt[i]));
    double scale_t = 0.0;
    for (int i = 0; i < N; i++) scale_t = fmax(scale_t, fabs(b[i]));
    for (int i = 0; i < N; i++) {
      worst = fmax(worst, fabs(x[i] - bt[i]) / scale / tol);
      worst_t = fmax(worst_t, fabs(xt[i] - b[i]) / scale_t / tol);
    }
  }
  test_true("the row interchanges are LAPACK dgbtrf's (20 random sparse band matrices, n 80, kl 6, ku 9)", pivots_same);
  test_le("A x = b: max over the draws of (max |x - x_LAPACK| / max |x_LAPACK|) / (20 n eps cond_1(A))", worst, 1.0);
  test_le("A^T x = b: the same", worst_t, 1.0);
  test_true("the band storage is all zero after every factorisation", zero_after);
  abd_band_free(&f);
}

static void test_pieces_and_reuse(void)
{
  double ab[LDAB * N], ab2[LDAB * N];
  abd_band one, pieces, fresh;
  if (abd_band_alloc(&one, N, KL, KU) || abd_band_alloc(&pieces, N, KL, KU) || abd_band_alloc(&fresh, N, KL, KU)) {
    test_true("abd_band_alloc", 0);
    return;
  }
  int same = 1, zero = 1;
  for (int trial = 0; trial < 10; trial++) {
    random_band(ab, 500 + (unsigned long)trial, trial % 3 == 0 ? 17 + trial : -1);
    memcpy(ab2, ab, sizeof ab2);
    int info1 = abd_band_factor(&one, ab, LDAB);
    abd_band_factor_begin(&pieces);
    static const int cuts[] = {0, 1, 7, 7, 30, 31, 79};
    for (size_t c = 0; c < sizeof cuts / sizeof cuts[0]; c++) abd_band_factor_upto(&pieces, ab2, LDAB, cuts[c]);
    int info2 = abd_band_factor_end(&pieces, ab2, LDAB);
    same &= info1 == info2 && (info1 != 0 || same_factors(&one, &pieces));
    zero &= all_zero(ab) && all_zero(ab2);
  }
  test_true("factored in pieces (cuts 0, 1, 7, 7, 30, 31, 79): the same factors and info as in one call, bit for "
            "bit (10 matrices, 4 exactly singular)", same);
  test_true("the storage is all zero afterwards, singular matrices included", zero);

  /* a regular matrix factored in storage that last held a singular one:
     the factors of the same matrix in fresh storage */
  double used[LDAB * N], clean[LDAB * N];
  random_band(used, 9, 40);
  int infos = abd_band_factor(&one, used, LDAB);
  test_true("the singular draw is found singular (info = first zero pivot + 1 > 0)", infos > 0);
  random_band(clean, 10, -1);
  memcpy(used, clean, sizeof used);
  int ia = abd_band_factor(&one, used, LDAB), ib = abd_band_factor(&fresh, clean, LDAB);
  test_true("after a singular factorisation, the next matrix gets the factors of fresh storage, bit for bit",
            ia == 0 && ib == 0 && same_factors(&one, &fresh));
  abd_band_free(&one);
  abd_band_free(&pieces);
  abd_band_free(&fresh);
}

/* The ring: storage of R = KL + KU + 1 columns; matrix column c is copied in
 * before the elimination of column c - KL - KU (which may reach it), once
 * column c - R has been eliminated and left its storage zero. */
static void test_ring(void)
{
  enum { R = KL + KU + 1 };
  double ab[LDAB * N], full[LDAB * N], ring[LDAB * R];
  abd_band one, rf;
  if (abd_band_alloc(&one, N, KL, KU) || abd_band_alloc(&rf, N, KL, KU)) {
    test_true("abd_band_alloc", 0);
    return;
  }
  abd_band_set_ring(&rf, R);
  int same = 1, zero = 1, grew = 0;
  size_t cap0 = rf.ucap + rf.lcap;
  memset(ring, 0, sizeof ring);
  for (int trial = 0; trial < 10; trial++) {
    random_band(ab, 900 + (unsigned long)trial, trial % 4 == 1 ? 23 + trial : -1);
    memcpy(full, ab, sizeof full);
    int info1 = abd_band_factor(&one, full, LDAB);
    abd_band_factor_begin(&rf);
    int written = 0;
    for (int jend = 1; jend <= N; jend++) {
      for (; written < N && written < jend + KL + KU; written++)
        memcpy(ring + (size_t)(written % R) * LDAB, ab + (size_t)written * LDAB, LDAB * sizeof(double));
      abd_band_factor_upto(&rf, ring, LDAB, jend);
    }
    int info2 = abd_band_factor_end(&rf, ring, LDAB);
    same &= info1 == info2 && (info1 != 0 || same_factors(&one, &rf));
    for (int i = 0; i < LDAB * R; i++) zero &= ring[i] == 0.0;
  }
  grew = rf.ucap + rf.lcap > cap0;
  test_true("ring storage of KL + KU + 1 columns: the factors and info of the full storage, bit for bit "
            "(10 matrices, 3 exactly singular), and the ring is all zero afterwards", same && zero);
  test_true("the compressed factors grew from their first capacity (a quarter of the band) as needed", grew);
  abd_band_free(&one);
  abd_band_free(&rf);
}

int main(void)
{
  test_against_lapack();
  test_pieces_and_reuse();
  test_ring();
  return test_summary();
}
