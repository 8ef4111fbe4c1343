/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Banded LU with partial pivoting of the reduced system of abd_solver
 * (abd_band.c): LAPACK's dgbtf2 algorithm, pivot choice and band storage,
 * working only on the nonzeros of the sparse band and keeping the factors
 * in compressed form for the solves.  Not safe for concurrent use. */
#ifndef CABLE_ABD_BAND_H
#define CABLE_ABD_BAND_H

#include <stddef.h>

typedef struct abd_band {
  int n, kl, ku;
  int ring;           /* columns of the band storage (abd_band_set_ring; n: all of them) */
  size_t ucap, lcap;  /* capacity of uc/uv and li/lv, grown by the factorisation */
  int oom;            /* the factorisation in progress ran out of memory */
  int *ipiv;          /* [n] 0-based row interchanges */
  int *nzl;           /* [kl + 1] work */
  double *ud;         /* [n] diagonal of U */
  int *up, *uc;       /* U's strict upper part by rows: row j's entries up[j]..up[j+1]-1, columns uc[] */
  double *uv;
  int *lp, *li;       /* L's multipliers by columns: column j's entries lp[j]..lp[j+1]-1, rows li[] */
  double *lv;
  double umax;        /* max |U| of the last factorisation (so far) */
  int fj, fnu, fnl, fju, finfo; /* a factorisation in progress: next column, U and L entries
                                   so far, last column updated, first zero pivot + 1 */
} abd_band;

/* 0, or -1 when out of memory (then abd_band_free is still safe).  The
 * compressed factors start at a quarter of the band's places and grow (by
 * half) when a factorisation fills more: the first factorisations of a run
 * may allocate, later ones of the same matrix structure do not. */
int abd_band_alloc(abd_band *f, int n, int kl, int ku);
void abd_band_free(abd_band *f);

/* Band storage as a ring of ncols columns (ncols >= kl + ku + 1; default and
 * ncols >= n: one storage column per matrix column): column c lives in
 * storage column c mod ncols.  The caller keeps at most ncols consecutive
 * columns alive at once (not yet eliminated, or written ahead of the
 * elimination): column c may be written only when the elimination has passed
 * column c - ncols, whose storage it has left zero (abd_solver.c bounds its
 * pipeline's lookahead for this).  The factors are the same bits. */
void abd_band_set_ring(abd_band *f, int ncols);

/* Factor the n x n band matrix with kl sub- and ku superdiagonals held in
 * LAPACK's band storage for factorisation (ldab >= 2 kl + ku + 1; element
 * (i, j) at ab[j * ldab + kl + ku + i - j]; every place of the storage that
 * is not an entry of A's band zero on entry, the top kl rows included).
 * The factors go to f, and the factorisation takes every entry out of ab as
 * it is used: on return all of ab is zero (some places may hold -0.0, which
 * acts as 0 in every operation here), ready for the next matrix without a
 * clearing pass (abd_solver.c saved 12 MB of memset per factorisation on the
 * NTST 150 knot).  Returns 0, or j + 1 when U(j, j) is exactly zero (the
 * first such j; the factorisation runs to the end, as LAPACK's; solves with
 * such a factorisation are not allowed). */
int abd_band_factor(abd_band *f, double *ab, int ldab);
/* (it returns -1 when the compressed factors could not grow: out of memory) */

/* The same factorisation in pieces, for a caller that fills the matrix
 * while it is being factored: begin, then upto(jend) any number of times
 * with increasing jend (columns fj..jend-1 are eliminated), then end (the
 * remaining columns; its return value is abd_band_factor's).  Eliminating
 * column j reads and clears column j's rows j..j+kl, swaps row j with the
 * pivot row, updates the rows with a nonzero multiplier and clears row j;
 * so of a row below j that is exactly zero in columns 0..j only the entry in
 * column j is touched, and another thread may meanwhile write its entries
 * right of column j (abd_solver.c's pipeline).  The pieces give the factors of the one-call
 * version, bit for bit. */
void abd_band_factor_begin(abd_band *f);
void abd_band_factor_upto(abd_band *f, double *ab, int ldab, int jend);
int abd_band_factor_end(abd_band *f, double *ab, int ldab);

/* A x = b and A^T x = b with the factors (b holds x on return). */
void abd_band_solve(const abd_band *f, double *b);
void abd_band_solve_transpose(const abd_band *f, double *b);

#endif
