/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "colloc_newton.h"

#include <kinsol/kinsol.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>

#include "cable/cable_status.h"
#include "colloc_jac.h"
#include "colloc_sparse.h"
#include "sunlinsol_colloc.h"
#include "sunmatrix_colloc.h"

/* Residual level (max-norm, relative to 1 + max|x|) below which KINSOL's
 * function-norm test alone declares convergence: far below what a step of
 * relative size EPSU leaves behind, so the step test normally decides. */
#define COLLOC_NEWTON_FNORM_REL 1.0e-13
/* After KINSOL's small-step exit the residual must be this small relative to
 * 1 + max|x|, or else the next Newton correction from the iterate must pass
 * the step test too (colloc_newton_solve): a small step with a large residual
 * and a large next correction is stagnation, not convergence. */
#define COLLOC_NEWTON_RES_ACCEPT 1.0e-6
/* KINSOL caps a Newton step at 1000 times the scaled start norm by default;
 * cable's steps are limited by ITNW and the continuation's step control, so
 * the cap is lifted to a value no step reaches. */
#define COLLOC_NEWTON_NO_STEP_CAP 1.0e300

struct colloc_newton {
  colloc_system *sys;            /* not owned */
  SUNContext ctx;
  void *kin;
  N_Vector x, uscale, fscale;
  N_Vector rhs, corr;            /* the residual and the next correction (converged_by_correction) */
  colloc_jac *J;
  SUNMatrix A;
  SUNLinearSolver LS;
  cable_linsolver kind;
  int itnw, nwtn;
  double eps;
  int iters;
  int nsetup;                    /* factorisations (Jacobian setups) in the last solve */
  int phase_start;               /* iterations before the current KINSol call */
  int last_setup_iter;           /* the iteration (1-based, whole solve) the last factorisation was made for */
  double resnorm;
  double *F;                     /* residual work vector */
  double *xfull;                 /* iterate after the full-Newton phase (chord fallback) */
  char msg[256];
};

static int kin_sysfn(N_Vector x, N_Vector F, void *data)
{
  colloc_newton *nw = data;
  int rc = colloc_system_residual(nw->sys, N_VGetArrayPointer(x), N_VGetArrayPointer(F));
  return rc == 0 ? 0 : (rc > 0 ? 1 : -1);
}

static int kin_jacfn(N_Vector x, N_Vector fx, SUNMatrix A, void *data, N_Vector t1, N_Vector t2)
{
  (void)t2;
  colloc_newton *nw = data;
  long nni = 0;
  KINGetNumNonlinSolvIters(nw->kin, &nni); /* the iteration this setup serves */
  nw->nsetup++;
  nw->last_setup_iter = nw->phase_start + (int)nni;
  int rc = colloc_system_jacobian(nw->sys, N_VGetArrayPointer(x), nw->J);
  if (rc != 0) return rc > 0 ? 1 : -1;
  if (nw->kind == CABLE_LINSOLVER_KLU) return colloc_sparse_fill(nw->J, A) == 0 ? 0 : -1;
  /* A wraps nw->J, which the call above overwrote entry by entry: KINSOL's
     zeroing before this call need not be carried out */
  SUNMat_Colloc_Filled(A);
  /* KINSOL's next solve is J p = -F(x) (a hint only: the solve checks) */
  N_VScale(-1.0, fx, t1);
  SUNLinSol_Colloc_ExpectRhs(nw->LS, N_VGetArrayPointer(t1));
  return 0;
}

static void kin_errfn(int code, const char *module, const char *function, char *msg, void *data)
{
  colloc_newton *nw = data;
  snprintf(nw->msg, sizeof nw->msg, "%s %s (%d): %s", module, function, code, msg);
}

void colloc_newton_free(colloc_newton *nw)
{
  if (!nw) return;
  if (nw->kin) KINFree(&nw->kin);
  if (nw->LS) SUNLinSolFree(nw->LS);
  if (nw->A) SUNMatDestroy(nw->A);
  colloc_jac_free(nw->J);
  if (nw->x) N_VDestroy(nw->x);
  if (nw->uscale) N_VDestroy(nw->uscale);
  if (nw->fscale) N_VDestroy(nw->fscale);
  if (nw->rhs) N_VDestroy(nw->rhs);
  if (nw->corr) N_VDestroy(nw->corr);
  free(nw->F);
  free(nw->xfull);
  if (nw->ctx) SUNContext_Free(&nw->ctx);
  free(nw);
}

colloc_newton *colloc_newton_alloc(colloc_system *sys, const cable_constants *c, int *status)
{
  return colloc_newton_alloc_team(sys, c, NULL, status);
}

colloc_newton *colloc_newton_alloc_team(colloc_system *sys, const cable_constants *c, struct cable_team *t,
                                        int *status)
{
  *status = CABLE_ERR_ALLOC;
  colloc_newton *nw = calloc(1, sizeof *nw);
  if (!nw) return NULL;
  nw->sys = sys;
  nw->kind = c->linsolver;
  nw->itnw = c->itnw > 0 ? c->itnw : 1;
  nw->nwtn = c->nwtn > 0 ? c->nwtn : nw->itnw;
  nw->eps = fmin(c->epsu, c->epsl);
  sunindextype n = sys->n;
  if (SUNContext_Create(NULL, &nw->ctx) != 0) goto fail;
  nw->x = N_VNew_Serial(n, nw->ctx);
  nw->uscale = N_VNew_Serial(n, nw->ctx);
  nw->fscale = N_VNew_Serial(n, nw->ctx);
  nw->rhs = N_VNew_Serial(n, nw->ctx);
  nw->corr = N_VNew_Serial(n, nw->ctx);
  nw->F = malloc((size_t)n * sizeof *nw->F);
  nw->xfull = malloc((size_t)n * sizeof *nw->xfull);
  nw->J = colloc_jac_alloc(sys->ndim, sys->ntst, sys->ncol, sys->nfpr, sys->nbc, sys->nint);
  if (!nw->x || !nw->uscale || !nw->fscale || !nw->rhs || !nw->corr || !nw->F || !nw->xfull || !nw->J) goto fail;
  N_VConst(1.0, nw->fscale);
  if (nw->kind == CABLE_LINSOLVER_KLU) {
    nw->A = colloc_sparse_alloc(nw->J, nw->ctx);
    if (nw->A) nw->LS = SUNLinSol_KLU(nw->x, nw->A, nw->ctx);
  } else {
    nw->A = SUNMat_Colloc(nw->J, nw->ctx);
    if (nw->A) nw->LS = SUNLinSol_Colloc(nw->x, nw->A, nw->ctx);
    if (nw->LS && t) abd_solver_use_team(SUNLinSol_Colloc_Solver(nw->LS), t);
    else if (nw->LS) abd_solver_set_threads(SUNLinSol_Colloc_Solver(nw->LS), cable_threads(c));
    /* the continuation's tangent comes with every Newton solve
       (colloc_newton_tangent_unit); off when there is no room for it */
    if (nw->LS) SUNLinSol_Colloc_SolveLastUnit(nw->LS, 1);
  }
  if (!nw->A || !nw->LS) goto fail;
  nw->kin = KINCreate(nw->ctx);
  if (!nw->kin) goto fail;
  *status = CABLE_ERR_KINSOL;
  if (KINInit(nw->kin, kin_sysfn, nw->x) != KIN_SUCCESS) goto fail;
  if (KINSetUserData(nw->kin, nw) != KIN_SUCCESS) goto fail;
  if (KINSetErrHandlerFn(nw->kin, kin_errfn, nw) != KIN_SUCCESS) goto fail;
  if (KINSetLinearSolver(nw->kin, nw->LS, nw->A) != KIN_SUCCESS) goto fail;
  if (KINSetJacFn(nw->kin, kin_jacfn) != KIN_SUCCESS) goto fail;
  if (KINSetScaledStepTol(nw->kin, nw->eps) != KIN_SUCCESS) goto fail;
  /* AUTO's chord iterations keep the factorisation to ITNW: KINSOL's residual
     monitoring would re-factor when the residual falls slowly (measured: NWTN
     = 2 gave 3 factorisations on Bratu from u = 0) */
  if (KINSetNoResMon(nw->kin, SUNTRUE) != KIN_SUCCESS) goto fail;
  /* the Newton step is limited by ITNW and DS control, not by KINSOL's step cap */
  if (KINSetMaxNewtonStep(nw->kin, COLLOC_NEWTON_NO_STEP_CAP) != KIN_SUCCESS) goto fail;
  *status = CABLE_SUCCESS;
  return nw;
fail:
  colloc_newton_free(nw);
  return NULL;
}

static double max_abs(const double *v, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
  return m;
}

/* One KINSol call: at most maxit iterations, a new factorisation every
 * msbset; reuse = 1 keeps the previous call's factorisation for the first
 * iteration (KINSetNoInitSetup: without it KINSol factors on entry, which
 * made NWTN + 1 factorisations before any chord iteration).  KINSOL still
 * factors once more when a chord step passes the step test with an old
 * factorisation (KINStop retries the iteration with a fresh one before it
 * accepts a small step), so a solve that ends by the step test after chord
 * iterations makes NWTN + 1 factorisations, and its last step is a full
 * Newton step. */
static int kin_phase(colloc_newton *nw, int maxit, long msbset, int reuse, int *iters)
{
  long nni = 0;
  nw->phase_start = *iters;
  KINSetNumMaxIters(nw->kin, maxit);
  KINSetMaxSetupCalls(nw->kin, msbset);
  KINSetNoInitSetup(nw->kin, reuse ? SUNTRUE : SUNFALSE);
  int flag = KINSol(nw->kin, nw->x, KIN_NONE, nw->uscale, nw->fscale);
  KINGetNumNonlinSolvIters(nw->kin, &nni);
  *iters += (int)nni;
  return flag;
}

/* After KINSOL's small-step exit with a residual above COLLOC_NEWTON_RES_ACCEPT:
 * 1 when the next Newton correction from the iterate xv (residual nw->F),
 * solved with the last factorisation, passes the step test as well
 * (|dx_i| / (1 + |x_i|) <= min(EPSU, EPSL) for every i, AUTO's convergence
 * test).  The residual's size depends on the equations' scale (FUNC's
 * 1/epsilon in a singularly perturbed problem makes a converged iterate's
 * residual large, AUTO's demo spb: doc/auto-users.md), the correction's does
 * not; a stagnated iterate has a large next correction. */
static int converged_by_correction(colloc_newton *nw, const double *xv, int n)
{
  memcpy(N_VGetArrayPointer(nw->rhs), nw->F, (size_t)n * sizeof *nw->F);
  if (SUNLinSolSolve(nw->LS, nw->A, nw->corr, nw->rhs, 0.0) != SUNLS_SUCCESS) return 0;
  const double *d = N_VGetArrayPointer(nw->corr);
  for (int i = 0; i < n; i++)
    if (!(fabs(d[i]) <= nw->eps * (1.0 + fabs(xv[i])))) return 0;
  return 1;
}

int colloc_newton_solve(colloc_newton *nw, double *x)
{
  colloc_system *sys = nw->sys;
  int n = sys->n;
  double *xv = N_VGetArrayPointer(nw->x), *us = N_VGetArrayPointer(nw->uscale);
  memcpy(xv, x, (size_t)n * sizeof *x);
  for (int i = 0; i < n; i++) us[i] = 1.0 / (1.0 + fabs(x[i]));
  double scale = 1.0 + max_abs(x, n);
  KINSetFuncNormTol(nw->kin, COLLOC_NEWTON_FNORM_REL * scale);
  nw->msg[0] = '\0';
  nw->iters = 0;
  nw->nsetup = 0;
  nw->last_setup_iter = 0;
  sys->last_callback = 0;
  /* AUTO's NWTN: full Newton (a factorisation per iteration) for the first
     NWTN iterations, then the chord method with the last factorisation */
  int full = nw->nwtn < nw->itnw ? nw->nwtn : nw->itnw;
  int flag = kin_phase(nw, full, 1, 0, &nw->iters);
  if (flag == KIN_MAXITER_REACHED && nw->itnw > full) {
    memcpy(nw->xfull, xv, (size_t)n * sizeof *xv);
    flag = kin_phase(nw, nw->itnw - full, nw->itnw, 1, &nw->iters);
    if (flag < 0 && sys->last_callback >= 0) {
      /* The chord method with a Jacobian from a poor iterate can fail where
         Newton converges (a perturbed start: knot72-thin1e-4-n of the stress
         grid).  Finish from where the full phase ended with full Newton for
         the same number of iterations, before the caller halves the step. */
      memcpy(xv, nw->xfull, (size_t)n * sizeof *xv);
      flag = kin_phase(nw, nw->itnw - full, 1, 0, &nw->iters);
    }
  }
  int rc = colloc_system_residual(sys, xv, nw->F);
  nw->resnorm = rc == 0 ? max_abs(nw->F, n) : HUGE_VAL;
  if (flag < 0 || rc != 0) {
    if (sys->last_callback < 0) return CABLE_ERR_CALLBACK;
    if (sys->last_callback > 0) return CABLE_ERR_RECOVERABLE;
    if (!nw->msg[0]) snprintf(nw->msg, sizeof nw->msg, "KINSOL flag %d", flag);
    return CABLE_ERR_NEWTON;
  }
  if (nw->resnorm > COLLOC_NEWTON_RES_ACCEPT * (1.0 + max_abs(xv, n)) && !converged_by_correction(nw, xv, n)) {
    snprintf(nw->msg, sizeof nw->msg, "Newton stagnated: residual %.3e after %d iterations",
             nw->resnorm, nw->iters);
    return CABLE_ERR_NEWTON;
  }
  memcpy(x, xv, (size_t)n * sizeof *x);
  return CABLE_SUCCESS;
}

int colloc_newton_iterations(const colloc_newton *nw) { return nw->iters; }
int colloc_newton_setups(const colloc_newton *nw) { return nw->nsetup; }
double colloc_newton_residual(const colloc_newton *nw) { return nw->resnorm; }
const char *colloc_newton_message(const colloc_newton *nw) { return nw->msg; }

int colloc_newton_factorization(colloc_newton *nw, struct abd_solver **abd, colloc_jac **J)
{
  /* only a factorisation made for the last iteration is at the last iterate
     but one; after chord iterations it is older by more than the tolerance */
  if (nw->kind != CABLE_LINSOLVER_CONDENSE || nw->iters < 1 || nw->last_setup_iter != nw->iters) return -1;
  *abd = SUNLinSol_Colloc_Solver(nw->LS);
  *J = nw->J;
  return *abd ? 0 : -1;
}

int colloc_newton_storage(colloc_newton *nw, struct abd_solver **abd, colloc_jac **J)
{
  if (nw->kind != CABLE_LINSOLVER_CONDENSE) return -1;
  *abd = SUNLinSol_Colloc_Solver(nw->LS);
  *J = nw->J;
  return *abd ? 0 : -1;
}

/* the last factorisation is no longer the last solve's (nw->iters >= 0) */
void colloc_newton_forget(colloc_newton *nw) { nw->last_setup_iter = -1; }

const double *colloc_newton_tangent_unit(colloc_newton *nw)
{
  struct abd_solver *abd;
  colloc_jac *J;
  if (colloc_newton_factorization(nw, &abd, &J) != 0) return NULL;
  return SUNLinSol_Colloc_LastUnitSolution(nw->LS);
}
