/* Banded LU with partial pivoting of the reduced system of abd_solver
 * (abd_band.c): LAPACK's dgbtf2 algorithm, pivot choice and band storage,
 * working only on the nonzeros of the sparse band and keeping the factors
 * in compressed form for the solves.  Not safe for concurrent use. */
#ifndef CABLE_ABD_BAND_H
#define CABLE_ABD_BAND_H

typedef struct abd_band {
  int n, kl, ku;
  int *ipiv;          /* [n] 0-based row interchanges */
  int *nzl;           /* [kl + 1] work */
  double *ud;         /* [n] diagonal of U */
  int *up, *uc;       /* U's strict upper part by rows: row j's entries up[j]..up[j+1]-1, columns uc[] */
  double *uv;
  int *lp, *li;       /* L's multipliers by columns: column j's entries lp[j]..lp[j+1]-1, rows li[] */
  double *lv;
  double umax;        /* max |U| of the last factorisation */
} abd_band;

/* 0, or -1 when out of memory (then abd_band_free is still safe). */
int abd_band_alloc(abd_band *f, int n, int kl, int ku);
void abd_band_free(abd_band *f);

/* Factor the n x n band matrix with kl sub- and ku superdiagonals held in
 * LAPACK's band storage for factorisation (ldab >= 2 kl + ku + 1; element
 * (i, j) at ab[j * ldab + kl + ku + i - j]; the top kl rows zero on entry);
 * ab is overwritten.  Returns 0, or j + 1 when U(j, j) is exactly zero (the
 * first such j; the factorisation runs to the end, as LAPACK's; solves with
 * such a factorisation are not allowed). */
int abd_band_factor(abd_band *f, double *ab, int ldab);

/* A x = b and A^T x = b with the factors (b holds x on return). */
void abd_band_solve(const abd_band *f, double *b);
void abd_band_solve_transpose(const abd_band *f, double *b);

#endif
