/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Structured direct solver for the collocation Newton matrix of colloc_jac.h.
 *
 * Algorithm (doc/linear-algebra.md has the full account, costs and the
 * stability argument):
 *  1. augmentation: copies of u(0) and of the free parameters are carried
 *     along the mesh, and every dense row (integral conditions, arclength) is
 *     replaced by running sums, one per mesh interval.  Each new unknown gets an
 *     identity "copy"/"accumulate" equation, so the boundary conditions become
 *     separated (all at the last mesh point) and the dense rows local;
 *  2. local condensation: in each interval, the (ncol-1)*ndim interior-node
 *     unknowns are eliminated from the interval's own rows (collocation rows and
 *     its running-sum rows) by LU with partial pivoting on the tall block
 *     (LAPACK dgetrf), leaving ndim+nint+1 rows on the mesh-point unknowns;
 *  3. the reduced, augmented system is banded: banded LU with partial
 *     pivoting, LAPACK's dgbtf2 algorithm on the band's nonzeros (abd_band.h).
 * The whole is Gaussian elimination with partial pivoting on the augmented
 * matrix in a fixed column order: no product of interval blocks is formed.
 *
 * A solver is allocated for one set of sizes and reused; factor and solve do
 * not allocate.  A solver is not safe for concurrent use by several threads
 * (solve writes into the solver's workspace). */
#ifndef CABLE_ABD_SOLVER_H
#define CABLE_ABD_SOLVER_H

#include "colloc_jac.h"

/* Return codes (0 ok, > 0 recoverable, < 0 error). */
enum {
  ABD_OK = 0,
  ABD_SINGULAR = 1,          /* factor: a pivot is exactly zero (J is singular) */
  ABD_NOT_CONVERGED = 2,     /* smallest_sv: maxit reached before tol */
  ABD_ERR_SIZE = -1,         /* J's sizes differ from the solver's, or bad argument */
  ABD_ERR_NOT_FACTORED = -2, /* solve/det/sv before a successful factor */
  ABD_ERR_NONFINITE = -3,    /* J holds a NaN or an infinity */
  ABD_ERR_LAPACK = -4,       /* LAPACK rejected an argument (internal error) */
  ABD_ERR_MEM = -5           /* allocation failed (smallest_sv workspace only) */
};

typedef struct abd_solver abd_solver;

/* NULL on bad sizes (the same rules as colloc_jac_alloc) or out of memory. */
abd_solver *abd_solver_alloc(int ndim, int ntst, int ncol, int nfpr, int nbc, int nint);
void abd_solver_free(abd_solver *s);                 /* NULL is a no-op */

/* Factor J.  0 ok; ABD_SINGULAR (> 0) when J is exactly singular (the
 * factorisation is complete and det reports sign 0; solves are refused);
 * < 0 error. */
int abd_solver_factor(abd_solver *s, const colloc_jac *J);

/* The same, and the first stage of the solves J x = b for the k <= 
 * ABD_SOLVE_BLOCK right-hand sides B (k vectors of length n, one after the
 * other) while each interval's factors are in cache: the next
 * abd_solver_solve / _solve_many with exactly those k vectors (compared bit
 * for bit) skips that stage and gives bit for bit the result it gives
 * otherwise.  Any solve uses the preparation up (doc/engine.md: the solve
 * after it a third faster on the NTST 150 knot, tests/bench_factor_solve).
 * k = 0 is abd_solver_factor; k out of range: ABD_ERR_SIZE. */
int abd_solver_factor_prepared(abd_solver *s, const colloc_jac *J, const double *B, int k);

/* J x = b: x holds b (length n, equation order of colloc_jac.h) on entry and
 * the solution (unknown order) on return.  0 ok; ABD_SINGULAR when the last
 * factorisation found J singular (x untouched); < 0 when not factored. */
int abd_solver_solve(const abd_solver *s, double *x);

/* J^T x = b, same conventions (b indexed by unknowns, x by equations). */
int abd_solver_solve_transpose(const abd_solver *s, double *x);

/* The same for k right-hand sides at once (X: k vectors of length n, one
 * after the other), in blocks of ABD_SOLVE_BLOCK: each interval's factors
 * are read from memory once per block (the solves stream all of them, about
 * 12 MB at NTST 150, NDIM 21, NCOL 4).  Every vector's result is bit for
 * bit that of abd_solver_solve / abd_solver_solve_transpose. */
#define ABD_SOLVE_BLOCK 2
int abd_solver_solve_many(const abd_solver *s, double *X, int k);
int abd_solver_solve_transpose_many(const abd_solver *s, double *X, int k);

/* Sign (+1, -1; 0 if singular or not factored) and log|det J| of the original
 * matrix J, in the row/column order of colloc_jac.h. */
void abd_solver_det(const abd_solver *s, int *sign, double *logabs);

/* Element growth of the last factorisation: max |U| / max |augmented matrix|
 * over both stages (local and banded).  Partial pivoting keeps it O(1) in
 * practice; a large value flags a loss of accuracy (doc/linear-algebra.md). */
double abd_solver_growth(const abd_solver *s);

/* Threads for the per-interval stages of factor and the solves (local
 * condensation, its application to right-hand sides, back-substitution) on
 * a team owned by the solver (cable_team.h); the banded stage is
 * sequential.  Each interval's arithmetic is the same whichever thread does
 * it and every reduction runs in interval order, so the results are
 * identical, bit for bit, for every thread count.  Default 1.  The BLAS must
 * be sequential inside the team (cable_blas_single_thread).  Returns 0, or
 * ABD_ERR_MEM when the threads cannot be created (the solver then runs on
 * one thread). */
int abd_solver_set_threads(abd_solver *s, int nthreads);
int abd_solver_threads(const abd_solver *s);
/* The same with the caller's team t (not NULL), which the solver uses and
 * never frees: t outlives the solver; one team may serve several solvers
 * that run one after another (the engine handle's). */
void abd_solver_use_team(abd_solver *s, struct cable_team *t);
/* The solver's thread team (NULL: one thread), for per-interval work that
 * goes with its solves (colloc_jac_matvec_team); used by one thread at a time
 * like the solver. */
struct cable_team *abd_solver_team(const abd_solver *s);

/* Unknowns n of the original system. */
int abd_solver_size(const abd_solver *s);

/* Lower and upper bandwidths of the reduced, augmented banded system. */
void abd_solver_bandwidths(const abd_solver *s, int *kl, int *ku);

/* Memory held by the solver, in doubles and in ints. */
void abd_solver_space(const abd_solver *s, long *ndoubles, long *nints);

/* The k smallest singular values of J and their right singular vectors, by
 * block inverse (subspace) iteration on (J^T J)^{-1} using the factorisation
 * of J (s must have been factored with this J, returning 0).
 *   sv[k]      ascending: sv[0] is the smallest;
 *   vecs[n*k]  column i (vecs + i*n) is the unit right singular vector of sv[i].
 * Each iteration applies J^{-1} J^{-T} to an orthonormal n x k block, then a
 * Rayleigh-Ritz step: the SVD of J V gives Ritz values sigma_i, right vectors
 * v_i and left vectors u_i with J v_i = sigma_i u_i exactly.
 * Convergence criterion: for every i,
 *     ||J^T u_i - sigma_i v_i||_2 <= tol * ||J||_F.
 * Then some singular value of J lies within that residual of sigma_i
 * (a backward error of tol relative to ||J||_F), and the error in sigma_i is
 * of second order in the residual when sigma_i is separated from the rest.
 * The rate of convergence is (sigma_i / sigma_{k+1})^2 per iteration.
 * tol below ~ n * DBL_EPSILON cannot be met in floating point.
 * Returns 0 converged, ABD_NOT_CONVERGED (> 0) after maxit iterations (sv and
 * vecs then hold the last estimates), < 0 error.  Allocates its workspace on
 * first use (and when k grows); it is not a hot-loop routine. */
int abd_solver_smallest_sv(abd_solver *s, const colloc_jac *J, int k, double *sv, double *vecs, int maxit,
                           double tol);

/* The same with a start block and the left vectors: start[n*k] (NULL: the
 * fixed start of abd_solver_smallest_sv) is the first block, e.g. the right
 * singular vectors of a nearby matrix (warm start: then one or two
 * iterations usually meet tol); uvecs[n*k] (NULL: not wanted) receives the
 * unit left singular vectors u_i (J v_i ~ sv[i] u_i); *iters (NULL: not
 * wanted) the iterations made.  A start block of dependent columns falls
 * back to the fixed start. */
int abd_solver_smallest_svd(abd_solver *s, const colloc_jac *J, int k, const double *start, double *sv, double *vecs,
                            double *uvecs, int maxit, double tol, int *iters);

#endif
