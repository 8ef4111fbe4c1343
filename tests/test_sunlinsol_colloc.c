/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The SUNDIALS wrappers: SUNMat_Colloc, SUNLinSol_Colloc and the KLU
 * reference path (colloc_sparse) give the direct abd_solver's solutions to
 * round-off, and KINSOL drives both to the known root of a nonlinear system
 * with the collocation block structure.
 *
 * Tolerances: two backward-stable solutions of J x = b differ by at most
 * SOLVE_C * n * eps * kappa_inf relatively (kappa_inf from LAPACK dgecon;
 * SOLVE_C = 4 as in test_abd_solver.c).  Matrix-vector products summed in a
 * different order differ by at most n * eps * ||J||_inf * ||x||_inf. */
#include "abd_solver.h"
#include "colloc_jac.h"
#include "colloc_sparse.h"
#include "harness.h"
#include "sunlinsol_colloc.h"
#include "sunmatrix_colloc.h"

#include <float.h>
#include <kinsol/kinsol.h>
#include <lapacke.h>
#include <nvector/nvector_serial.h>
#include <stdint.h>
#include <string.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#define SOLVE_C 4.0
/* KINSOL stopping tolerance on max|F| (F is O(1)-scaled): far above the
 * round-off floor n*eps*||J||*||x|| ~ 1e-13 of the residual evaluation. */
#define KIN_FTOL 1e-11
/* Cubic term of the nonlinear test system: small enough that Newton from
 * x* + 0.05 * perturbation converges to x*. */
#define CUBIC 0.05

typedef struct {
  uint64_t s;
} rng;

static double rng_uniform(rng *g)
{
  g->s = g->s * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
  return (double)(g->s >> 11) * 0x1.0p-52 - 1.0;
}

static void jac_random(colloc_jac *J, rng *g)
{
  size_t len[4] = {(size_t)J->ntst * J->coll_stride, (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr),
                   (size_t)J->ntst * J->dense_stride, (size_t)J->ndense * (size_t)J->nfpr};
  double *v[4] = {J->coll, J->bc, J->dense, J->dense_par};
  for (int b = 0; b < 4; b++)
    for (size_t i = 0; i < len[b]; i++) v[b][i] = rng_uniform(g);
}

static void jac_copy(const colloc_jac *S, colloc_jac *D)
{
  memcpy(D->coll, S->coll, (size_t)S->ntst * S->coll_stride * sizeof(double));
  memcpy(D->bc, S->bc, (size_t)S->nbc * (size_t)(2 * S->ndim + S->nfpr) * sizeof(double));
  memcpy(D->dense, S->dense, (size_t)S->ntst * S->dense_stride * sizeof(double));
  memcpy(D->dense_par, S->dense_par, (size_t)S->ndense * (size_t)S->nfpr * sizeof(double));
}

static double diff_inf(const double *x, const double *y, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(x[i] - y[i]));
  return m;
}

static double norm_inf(const double *x, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(x[i]));
  return m;
}

/* kappa_inf and ||J||_inf of J by dense LAPACK. */
static void dense_cond(const colloc_jac *J, double *kappa, double *anorm)
{
  int n = J->n;
  double *A = malloc((size_t)n * (size_t)n * sizeof(double));
  lapack_int *ipiv = malloc((size_t)n * sizeof(lapack_int));
  colloc_jac_to_dense(J, A);
  *anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, 'I', n, n, A, n);
  double rcond = 0.0;
  if (LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, A, n, ipiv) == 0) LAPACKE_dgecon(LAPACK_COL_MAJOR, 'I', n, A, n, *anorm, &rcond);
  *kappa = rcond > 0 ? 1.0 / rcond : (double)INFINITY;
  free(A);
  free(ipiv);
}

/* Pointer to the diagonal entry (i, i) of J inside the blocks. */
static double *jac_diag(colloc_jac *J, int i)
{
  const int nd = J->ndim, nc = J->ncol, nr = nc * nd, N = J->ntst, nb = J->nbc, nq = J->ndense;
  const int npar0 = nd * (N * nc + 1);
  if (i < N * nr) {
    int j = i / nr, r = i % nr; /* column i is column r of block j */
    return colloc_jac_coll_block(J, j) + (size_t)r * (size_t)nr + (size_t)r;
  }
  if (i < N * nr + nb) {
    int b = i - N * nr;
    int col = i < npar0 ? nd + (i - N * nr) : 2 * nd + (i - npar0);
    return J->bc + (size_t)col * (size_t)nb + (size_t)b;
  }
  int d = i - N * nr - nb;
  if (i < npar0) /* mesh point N: last interval's dense block, node ncol */
    return colloc_jac_dense_block(J, N - 1) + (size_t)(nc * nd + (i - N * nr)) * (size_t)nq + (size_t)d;
  return J->dense_par + (size_t)(i - npar0) * (size_t)nq + (size_t)d;
}

/* ---- nonlinear system F(x) = J0 x + CUBIC x.^3 - b for KINSOL ---------- */
typedef struct {
  const colloc_jac *J0;
  const double *b;
  int use_klu;
  colloc_jac *work; /* Jacobian blocks for the KLU path */
} nl_problem;

static int nl_func(N_Vector u, N_Vector f, void *data)
{
  const nl_problem *P = data;
  const double *x = N_VGetArrayPointer(u);
  double *F = N_VGetArrayPointer(f);
  colloc_jac_matvec(P->J0, x, F);
  for (int i = 0; i < P->J0->n; i++) F[i] += CUBIC * x[i] * x[i] * x[i] - P->b[i];
  return 0;
}

static void nl_jac_blocks(const nl_problem *P, const double *x, colloc_jac *J)
{
  jac_copy(P->J0, J);
  for (int i = 0; i < J->n; i++) *jac_diag(J, i) += 3.0 * CUBIC * x[i] * x[i];
}

static int nl_jac(N_Vector u, N_Vector fu, SUNMatrix Jm, void *data, N_Vector t1, N_Vector t2)
{
  (void)fu;
  (void)t1;
  (void)t2;
  nl_problem *P = data;
  const double *x = N_VGetArrayPointer(u);
  if (P->use_klu) {
    nl_jac_blocks(P, x, P->work);
    return colloc_sparse_fill(P->work, Jm) == 0 ? 0 : -1;
  }
  colloc_jac *J = SUNMat_Colloc_Jac(Jm);
  if (!J) return -1;
  nl_jac_blocks(P, x, J);
  return 0;
}

/* Solve with KINSOL (full Newton) from x0; returns KINSol's flag. */
static int kinsol_run(SUNContext ctx, nl_problem *P, SUNLinearSolver LS, SUNMatrix A, const double *x0, double *x,
                      long *nni)
{
  const int n = P->J0->n;
  N_Vector u = N_VNew_Serial(n, ctx), scale = N_VNew_Serial(n, ctx);
  memcpy(N_VGetArrayPointer(u), x0, (size_t)n * sizeof(double));
  N_VConst(1.0, scale);
  void *kin = KINCreate(ctx);
  KINInit(kin, nl_func, u);
  KINSetUserData(kin, P);
  KINSetFuncNormTol(kin, KIN_FTOL);
  KINSetScaledStepTol(kin, 1e-15);
  KINSetMaxSetupCalls(kin, 1);
  KINSetLinearSolver(kin, LS, A);
  KINSetJacFn(kin, nl_jac);
  int flag = KINSol(kin, u, KIN_NONE, scale, scale);
  KINGetNumNonlinSolvIters(kin, nni);
  memcpy(x, N_VGetArrayPointer(u), (size_t)n * sizeof(double));
  KINFree(&kin);
  N_VDestroy(u);
  N_VDestroy(scale);
  return flag;
}

int main(void)
{
  SUNContext ctx;
  if (SUNContext_Create(NULL, &ctx) != 0) {
    printf("FAIL SUNContext_Create\n");
    return EXIT_FAILURE;
  }
  const int nd = 4, N = 8, nc = 3, nf = 2, nint = 1, nb = nd + nf - nint - 1;
  colloc_jac *J = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
  const int n = J->n;
  rng g = {2024};
  jac_random(J, &g);
  double kappa, anorm;
  dense_cond(J, &kappa, &anorm);
  const double tol_x = SOLVE_C * n * DBL_EPSILON * kappa;
  printf("  n %d kappa_inf %.3g\n", n, kappa);

  double *b = malloc((size_t)n * sizeof(double)), *xd = malloc((size_t)n * sizeof(double));
  double *t = malloc((size_t)n * sizeof(double));
  for (int i = 0; i < n; i++) b[i] = rng_uniform(&g);
  abd_solver *s = abd_solver_alloc(nd, N, nc, nf, nb, nint);
  test_int("direct abd_solver factor", abd_solver_factor(s, J), ABD_OK);
  memcpy(xd, b, (size_t)n * sizeof(double));
  abd_solver_solve(s, xd);

  N_Vector vb = N_VNew_Serial(n, ctx), vx = N_VNew_Serial(n, ctx);
  memcpy(N_VGetArrayPointer(vb), b, (size_t)n * sizeof(double));

  /* ---- SUNMatrix ---- */
  SUNMatrix A = SUNMat_Colloc(J, ctx);
  test_true("SUNMat_Colloc created", A != NULL);
  test_int("SUNMatGetID is SUNMATRIX_CUSTOM", SUNMatGetID(A), SUNMATRIX_CUSTOM);
  test_true("SUNMat_Colloc_Jac returns the wrapped blocks", SUNMat_Colloc_Jac(A) == J);
  test_int("SUNMatMatvec returns 0", SUNMatMatvec(A, vb, vx), SUNMAT_SUCCESS);
  colloc_jac_matvec(J, b, t);
  test_le("SUNMatMatvec equals colloc_jac_matvec", diff_inf(N_VGetArrayPointer(vx), t, n), 0.0);
  long lrw, liw;
  SUNMatSpace(A, &lrw, &liw);
  test_int("SUNMatSpace: doubles of the blocks",
           lrw, (long)((size_t)N * (J->coll_stride + J->dense_stride)) + (long)nb * (2 * nd + nf) + (long)(nint + 1) * nf);
  SUNMatrix B = SUNMatClone(A);
  colloc_jac *JB = SUNMat_Colloc_Jac(B);
  test_true("SUNMatClone: new blocks of the same sizes", JB && JB != J && JB->n == n && JB->ntst == N);
  if (JB) {
    jac_copy(J, JB);
    /* the zeroing is deferred: SUNMat_Colloc_Filled after a zero keeps what
       was written meanwhile, an access without it sees zeros */
    test_int("SUNMatZero on the clone returns 0", SUNMatZero(B), SUNMAT_SUCCESS);
    SUNMat_Colloc_Filled(B);
    test_true("SUNMatZero then SUNMat_Colloc_Filled keeps the entries written",
              SUNMat_Colloc_Jac(B) == JB && JB->coll[0] == J->coll[0] && JB->bc[0] == J->bc[0]);
    test_int("SUNMatZero on the clone returns 0", SUNMatZero(B), SUNMAT_SUCCESS);
    test_true("SUNMat_Colloc_Jac after SUNMatZero: the same blocks", SUNMat_Colloc_Jac(B) == JB);
    double mx = 0.0;
    for (size_t i = 0; i < (size_t)N * JB->coll_stride; i++) mx = fmax(mx, fabs(JB->coll[i]));
    for (size_t i = 0; i < (size_t)N * JB->dense_stride; i++) mx = fmax(mx, fabs(JB->dense[i]));
    for (size_t i = 0; i < (size_t)nb * (2 * nd + nf); i++) mx = fmax(mx, fabs(JB->bc[i]));
    for (size_t i = 0; i < (size_t)(nint + 1) * nf; i++) mx = fmax(mx, fabs(JB->dense_par[i]));
    test_abs("SUNMatZero zeroes every block", mx, 0.0, 0.0);
  }
  SUNMatDestroy(B); /* frees the clone's own blocks (valgrind checks) */
  test_true("SUNMat_Colloc(NULL) is NULL", SUNMat_Colloc(NULL, ctx) == NULL);

  /* ---- SUNLinSol_Colloc ---- */
  SUNLinearSolver LS = SUNLinSol_Colloc(vb, A, ctx);
  test_true("SUNLinSol_Colloc created", LS != NULL);
  test_int("gettype DIRECT", SUNLinSolGetType(LS), SUNLINEARSOLVER_DIRECT);
  test_int("getid CUSTOM", SUNLinSolGetID(LS), SUNLINEARSOLVER_CUSTOM);
  test_int("initialize", SUNLinSolInitialize(LS), SUNLS_SUCCESS);
  test_int("setup", SUNLinSolSetup(LS, A), SUNLS_SUCCESS);
  test_int("lastflag after setup", (long)SUNLinSolLastFlag(LS), ABD_OK);
  test_int("solve", SUNLinSolSolve(LS, A, vx, vb, 0.0), SUNLS_SUCCESS);
  test_le("SUNLinSol_Colloc solution vs direct abd_solver (rel, tol 4 n eps kappa)",
          diff_inf(N_VGetArrayPointer(vx), xd, n) / norm_inf(xd, n), tol_x);
  int sg, sg2;
  double la, la2;
  test_int("SUNLinSol_Colloc_Det returns 0", SUNLinSol_Colloc_Det(LS, &sg, &la), SUNLS_SUCCESS);
  abd_solver_det(s, &sg2, &la2);
  test_int("det sign via the SUNLinearSolver = direct", sg, sg2);
  test_abs("log|det| via the SUNLinearSolver = direct", la, la2, 0.0);
  test_true("SUNLinSol_Colloc_Solver exposes the abd_solver", SUNLinSol_Colloc_Solver(LS) != NULL);
  test_int("SUNLinSolSpace returns 0", SUNLinSolSpace(LS, &lrw, &liw), SUNLS_SUCCESS);
  test_true("SUNLinSolSpace: at least the local blocks", lrw >= (long)N * (nc * nd + nint + 1) * (nc - 1) * nd);

  /* ---- KLU reference path ---- */
  SUNMatrix C = colloc_sparse_alloc(J, ctx);
  test_true("colloc_sparse_alloc", C != NULL);
  {
    /* structural nonzeros = the nonzeros of the dense copy of a random J */
    double *D = malloc((size_t)n * (size_t)n * sizeof(double));
    colloc_jac_to_dense(J, D);
    long nz = 0;
    for (size_t i = 0; i < (size_t)n * (size_t)n; i++) nz += D[i] != 0.0;
    free(D);
    test_int("CSC nnz = nonzeros of the dense matrix", (long)SUNSparseMatrix_NNZ(C), nz);
  }
  SUNMatMatvec(C, vb, vx);
  test_le("CSC matvec vs colloc_jac_matvec (tol n eps ||J|| ||x||)", diff_inf(N_VGetArrayPointer(vx), t, n),
          n * DBL_EPSILON * anorm * norm_inf(b, n));
  SUNLinearSolver LK = SUNLinSol_KLU(vb, C, ctx);
  SUNLinSolInitialize(LK);
  test_int("KLU setup", SUNLinSolSetup(LK, C), SUNLS_SUCCESS);
  test_int("KLU solve", SUNLinSolSolve(LK, C, vx, vb, 0.0), SUNLS_SUCCESS);
  test_le("KLU solution vs direct abd_solver (rel, tol 4 n eps kappa)",
          diff_inf(N_VGetArrayPointer(vx), xd, n) / norm_inf(xd, n), tol_x);

  /* new values, same pattern: fill, refactor, solve, against a fresh direct solve */
  jac_random(J, &g);
  dense_cond(J, &kappa, &anorm);
  test_int("colloc_sparse_fill", colloc_sparse_fill(J, C), 0);
  test_int("direct factor (new values)", abd_solver_factor(s, J), ABD_OK);
  memcpy(xd, b, (size_t)n * sizeof(double));
  abd_solver_solve(s, xd);
  test_int("KLU setup (new values)", SUNLinSolSetup(LK, C), SUNLS_SUCCESS);
  SUNLinSolSolve(LK, C, vx, vb, 0.0);
  test_le("KLU vs direct, new values (rel, tol 4 n eps kappa)", diff_inf(N_VGetArrayPointer(vx), xd, n) / norm_inf(xd, n),
          SOLVE_C * n * DBL_EPSILON * kappa);
  SUNLinSolSetup(LS, A);
  SUNLinSolSolve(LS, A, vx, vb, 0.0);
  test_le("SUNLinSol_Colloc vs direct, new values", diff_inf(N_VGetArrayPointer(vx), xd, n) / norm_inf(xd, n),
          SOLVE_C * n * DBL_EPSILON * kappa);

  /* ---- the tangent along with the solve, and the expected right-hand side ---- */
  {
    double *x_plain = malloc((size_t)n * sizeof(double)), *e = calloc((size_t)n, sizeof(double));
    memcpy(x_plain, N_VGetArrayPointer(vx), (size_t)n * sizeof(double)); /* the plain LS solve of b above */
    e[n - 1] = 1.0;
    abd_solver_solve(s, e); /* s holds the factors of the same J: e_last's solution */
    test_true("LastUnitSolution is NULL while SolveLastUnit is off", SUNLinSol_Colloc_LastUnitSolution(LS) == NULL);
    test_int("SolveLastUnit on", SUNLinSol_Colloc_SolveLastUnit(LS, 1), SUNLS_SUCCESS);
    test_true("LastUnitSolution is NULL before a solve", SUNLinSol_Colloc_LastUnitSolution(LS) == NULL);
    for (int expect = 0; expect <= 2; expect++) {
      /* 0: no hint; 1: the hint is b; 2: the hint is not b (the solve checks) */
      if (expect == 1) test_int("ExpectRhs(b)", SUNLinSol_Colloc_ExpectRhs(LS, b), SUNLS_SUCCESS);
      if (expect == 2) test_int("ExpectRhs(other)", SUNLinSol_Colloc_ExpectRhs(LS, t), SUNLS_SUCCESS);
      SUNLinSolSetup(LS, A);
      test_int("solve with the tangent along", SUNLinSolSolve(LS, A, vx, vb, 0.0), SUNLS_SUCCESS);
      const double *u = SUNLinSol_Colloc_LastUnitSolution(LS);
      test_true(expect == 0   ? "no hint: x and the e_last solution equal the plain solves bit for bit"
                : expect == 1 ? "hint b: x and the e_last solution equal the plain solves bit for bit"
                              : "wrong hint: x and the e_last solution equal the plain solves bit for bit",
                u && memcmp(N_VGetArrayPointer(vx), x_plain, (size_t)n * sizeof(double)) == 0 &&
                    memcmp(u, e, (size_t)n * sizeof(double)) == 0);
    }
    SUNLinSolSetup(LS, A);
    test_true("LastUnitSolution is NULL after a new setup without a solve",
              SUNLinSol_Colloc_LastUnitSolution(LS) == NULL);
    test_int("SolveLastUnit off", SUNLinSol_Colloc_SolveLastUnit(LS, 0), SUNLS_SUCCESS);
    SUNLinSolSolve(LS, A, vx, vb, 0.0);
    test_true("off: no e_last solution", SUNLinSol_Colloc_LastUnitSolution(LS) == NULL);
    free(x_plain);
    free(e);
  }

  /* ---- error paths ---- */
  colloc_jac *J2 = colloc_jac_alloc(nd, N + 1, nc, nf, nb, nint);
  test_int("colloc_sparse_fill with J of other sizes: -1", colloc_sparse_fill(J2, C), -1);
  test_int("colloc_sparse_fill into a non-sparse matrix: -1", colloc_sparse_fill(J, A), -1);
  test_true("SUNMat_Colloc_Jac of a CSC matrix is NULL", SUNMat_Colloc_Jac(C) == NULL);
  test_int("SUNLinSol_Colloc_Det of a KLU solver: SUNLS_ILL_INPUT", SUNLinSol_Colloc_Det(LK, &sg, &la), SUNLS_ILL_INPUT);
  test_true("SUNLinSol_Colloc_Solver of a KLU solver is NULL", SUNLinSol_Colloc_Solver(LK) == NULL);
  test_int("SolveLastUnit on a KLU solver: SUNLS_ILL_INPUT", SUNLinSol_Colloc_SolveLastUnit(LK, 1), SUNLS_ILL_INPUT);
  test_int("ExpectRhs on a KLU solver: SUNLS_ILL_INPUT", SUNLinSol_Colloc_ExpectRhs(LK, b), SUNLS_ILL_INPUT);
  test_true("LastUnitSolution of a KLU solver is NULL", SUNLinSol_Colloc_LastUnitSolution(LK) == NULL);
  test_int("SUNLinSol_Colloc setup with a CSC matrix: SUNLS_ILL_INPUT", SUNLinSolSetup(LS, C), SUNLS_ILL_INPUT);
  N_Vector vshort = N_VNew_Serial(n - 1, ctx);
  test_true("SUNLinSol_Colloc with a template of wrong length is NULL", SUNLinSol_Colloc(vshort, A, ctx) == NULL);
  test_true("SUNLinSol_Colloc with a CSC matrix is NULL", SUNLinSol_Colloc(vb, C, ctx) == NULL);
  SUNMatrix A2 = SUNMat_Colloc(J2, ctx);
  test_int("SUNLinSol_Colloc setup with a matrix of other sizes: SUNLS_PACKAGE_FAIL_UNREC", SUNLinSolSetup(LS, A2),
           SUNLS_PACKAGE_FAIL_UNREC);
  test_int("lastflag: ABD_ERR_SIZE", (long)SUNLinSolLastFlag(LS), ABD_ERR_SIZE);
  test_int("solve after a failed setup: SUNLS_PACKAGE_FAIL_UNREC", SUNLinSolSolve(LS, A, vx, vb, 0.0),
           SUNLS_PACKAGE_FAIL_UNREC);
  SUNMatDestroy(A2);
  N_VDestroy(vshort);

  /* singular matrix: recoverable setup failure */
  for (int j = 0; j < N; j++)
    for (int r = 0; r < nc * nd; r++) colloc_jac_coll_block(J, j)[(size_t)((nc + 1) * nd) * (nc * nd) + r] = 0.0;
  for (int q = 0; q < nb; q++) J->bc[(size_t)(2 * nd) * nb + q] = 0.0;
  for (int d = 0; d <= nint; d++) J->dense_par[d] = 0.0;
  test_int("singular matrix: setup returns SUNLS_LUFACT_FAIL", SUNLinSolSetup(LS, A), SUNLS_LUFACT_FAIL);
  test_int("singular matrix: lastflag ABD_SINGULAR", (long)SUNLinSolLastFlag(LS), ABD_SINGULAR);
  SUNLinSol_Colloc_Det(LS, &sg, &la);
  test_int("singular matrix: det sign 0", sg, 0);
  test_int("singular matrix: solve refused (SUNLS_LUFACT_FAIL)", SUNLinSolSolve(LS, A, vx, vb, 0.0), SUNLS_LUFACT_FAIL);

  /* ---- KINSOL drives both linear solvers to the known root x* ---- */
  {
    colloc_jac *J0 = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
    colloc_jac *Jk = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
    colloc_jac *Jstar = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
    jac_random(J0, &g);
    double *xs = malloc((size_t)n * sizeof(double)), *rhs = malloc((size_t)n * sizeof(double));
    double *x0 = malloc((size_t)n * sizeof(double)), *x1 = malloc((size_t)n * sizeof(double));
    double *x2 = malloc((size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) xs[i] = rng_uniform(&g);
    colloc_jac_matvec(J0, xs, rhs);
    for (int i = 0; i < n; i++) rhs[i] += CUBIC * xs[i] * xs[i] * xs[i];
    for (int i = 0; i < n; i++) x0[i] = xs[i] + 0.05 * rng_uniform(&g);
    nl_problem P = {J0, rhs, 0, Jk};
    /* ||x - x*|| <= ||F'(x*)^{-1}|| ||F(x)|| to first order */
    nl_jac_blocks(&P, xs, Jstar);
    double kap, an;
    dense_cond(Jstar, &kap, &an);
    const double tol_root = 2.0 * (kap / an) * KIN_FTOL;

    colloc_jac *Jc = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
    SUNMatrix Ac = SUNMat_Colloc(Jc, ctx);
    SUNLinearSolver Lc = SUNLinSol_Colloc(vb, Ac, ctx);
    long it1 = 0, it2 = 0;
    int f1 = kinsol_run(ctx, &P, Lc, Ac, x0, x1, &it1);
    printf("  KINSOL + SUNLinSol_Colloc: flag %d, %ld iterations\n", f1, it1);
    test_true("KINSOL + SUNLinSol_Colloc converges (KIN_SUCCESS)", f1 == KIN_SUCCESS);
    test_le("KINSOL + SUNLinSol_Colloc: |x - x*| (tol 2 ||J^-1|| ftol)", diff_inf(x1, xs, n), tol_root);

    P.use_klu = 1;
    nl_jac_blocks(&P, x0, Jk);
    SUNMatrix Ck = colloc_sparse_alloc(Jk, ctx);
    SUNLinearSolver Lk = SUNLinSol_KLU(vb, Ck, ctx);
    int f2 = kinsol_run(ctx, &P, Lk, Ck, x0, x2, &it2);
    printf("  KINSOL + KLU: flag %d, %ld iterations\n", f2, it2);
    test_true("KINSOL + KLU converges", f2 == KIN_SUCCESS);
    test_le("KINSOL + KLU: |x - x*|", diff_inf(x2, xs, n), tol_root);
    test_int("same Newton iteration count with both linear solvers", it1, it2);
    test_le("KINSOL roots with SUNLinSol_Colloc and KLU agree (tol 2 tol_root)", diff_inf(x1, x2, n), 2.0 * tol_root);

    SUNLinSolFree(Lc);
    SUNMatDestroy(Ac);
    colloc_jac_free(Jc);
    SUNLinSolFree(Lk);
    SUNMatDestroy(Ck);
    colloc_jac_free(J0);
    colloc_jac_free(Jk);
    colloc_jac_free(Jstar);
    free(xs);
    free(rhs);
    free(x0);
    free(x1);
    free(x2);
  }

  SUNLinSolFree(LS);
  SUNLinSolFree(LK);
  SUNMatDestroy(A);
  SUNMatDestroy(C);
  N_VDestroy(vb);
  N_VDestroy(vx);
  colloc_jac_free(J);
  colloc_jac_free(J2);
  abd_solver_free(s);
  free(b);
  free(xd);
  free(t);
  SUNContext_Free(&ctx);
  return test_summary();
}
