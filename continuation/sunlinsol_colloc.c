/* SPDX-License-Identifier: GPL-3.0-or-later */
/* SUNLinearSolver ops over abd_solver (see sunlinsol_colloc.h). */
#include "sunlinsol_colloc.h"

#include <stdlib.h>
#include <string.h>

#include "sunmatrix_colloc.h"

typedef struct {
  abd_solver *solver;
  sunindextype last_flag; /* abd_solver code of the last setup/solve */
  int last_unit;          /* SUNLinSol_Colloc_SolveLastUnit: on */
  double *pair;           /* [2n] (b, e_last): the expected right-hand sides until the setup,
                             then the last solve's two vectors, solved in place */
  int expected;           /* pair holds SUNLinSol_Colloc_ExpectRhs's b for the next setup */
  unsigned long setups;   /* setups so far */
  unsigned long unit_of;  /* the setup whose factorisation solved pair's e_last (0: none) */
} colloc_ls_content;

/* pair (allocated on first use) = (b, e_last); -1 when out of memory. */
static int pair_fill(colloc_ls_content *c, const double *b)
{
  const size_t n = (size_t)abd_solver_size(c->solver);
  if (!c->pair && !(c->pair = malloc(2 * n * sizeof(double)))) return -1;
  memcpy(c->pair, b, n * sizeof(double));
  memset(c->pair + n, 0, n * sizeof(double));
  c->pair[2 * n - 1] = 1.0;
  return 0;
}

static colloc_ls_content *colloc_ls_content_of(SUNLinearSolver S);

static SUNLinearSolver_Type colloc_ls_gettype(SUNLinearSolver S)
{
  (void)S;
  return SUNLINEARSOLVER_DIRECT;
}

static SUNLinearSolver_ID colloc_ls_getid(SUNLinearSolver S)
{
  (void)S;
  return SUNLINEARSOLVER_CUSTOM;
}

static int colloc_ls_initialize(SUNLinearSolver S)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_MEM_NULL;
  c->last_flag = 0;
  return SUNLS_SUCCESS;
}

static int colloc_ls_setup(SUNLinearSolver S, SUNMatrix A)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_MEM_NULL;
  const colloc_jac *J = SUNMat_Colloc_Jac(A);
  if (!J) {
    c->last_flag = ABD_ERR_SIZE;
    return SUNLS_ILL_INPUT;
  }
  /* the expected right-hand sides' first solve stage with the factorisation */
  int rc = c->expected ? abd_solver_factor_prepared(c->solver, J, c->pair, c->last_unit ? 2 : 1)
                       : abd_solver_factor(c->solver, J);
  c->expected = 0;
  c->last_flag = rc;
  c->setups++; /* a new matrix: the last e_last solution is stale, whatever rc */
  if (rc == ABD_OK) return SUNLS_SUCCESS;
  return rc > 0 ? SUNLS_LUFACT_FAIL : SUNLS_PACKAGE_FAIL_UNREC;
}

static int colloc_ls_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype tol)
{
  (void)A;
  (void)tol; /* a direct solver: tol does not apply */
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_MEM_NULL;
  if (N_VGetLength(x) != abd_solver_size(c->solver) || N_VGetLength(b) != abd_solver_size(c->solver))
    return SUNLS_ILL_INPUT;
  N_VScale(1.0, b, x);
  double *xd = N_VGetArrayPointer(x);
  if (!xd) return SUNLS_MEM_FAIL;
  int rc;
  c->unit_of = 0;
  if (c->last_unit && pair_fill(c, xd) == 0) {
    /* b and e_last in one pass over the factors: each vector's result is
       bit for bit that of its own solve (abd_solver_solve_many) */
    rc = abd_solver_solve_many(c->solver, c->pair, 2);
    if (rc == ABD_OK) {
      memcpy(xd, c->pair, (size_t)abd_solver_size(c->solver) * sizeof(double));
      c->unit_of = c->setups;
    }
  } else {
    rc = abd_solver_solve(c->solver, xd);
  }
  c->last_flag = rc;
  if (rc == ABD_OK) return SUNLS_SUCCESS;
  return rc > 0 ? SUNLS_LUFACT_FAIL : SUNLS_PACKAGE_FAIL_UNREC;
}

static sunindextype colloc_ls_lastflag(SUNLinearSolver S)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  return c ? c->last_flag : SUNLS_MEM_NULL;
}

static int colloc_ls_space(SUNLinearSolver S, long int *lrw, long int *liw)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_MEM_NULL;
  abd_solver_space(c->solver, lrw, liw);
  return SUNLS_SUCCESS;
}

static int colloc_ls_free(SUNLinearSolver S)
{
  if (!S) return SUNLS_SUCCESS;
  colloc_ls_content *c = S->content;
  if (c) {
    abd_solver_free(c->solver);
    free(c->pair);
    free(c);
    S->content = NULL;
  }
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

/* Our solvers are recognised by their free op (SUNLINEARSOLVER_CUSTOM alone
 * does not say whose custom solver it is). */
static colloc_ls_content *colloc_ls_content_of(SUNLinearSolver S)
{
  if (!S || !S->ops || S->ops->free != colloc_ls_free) return NULL;
  return S->content;
}

SUNLinearSolver SUNLinSol_Colloc(N_Vector y, SUNMatrix A, SUNContext ctx)
{
  const colloc_jac *J = SUNMat_Colloc_Jac(A);
  if (!y || !J || !ctx || N_VGetLength(y) != J->n) return NULL;
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return NULL;
  colloc_ls_content *c = calloc(1, sizeof *c);
  if (!c) {
    SUNLinSolFreeEmpty(S);
    return NULL;
  }
  S->content = c;
  S->ops->gettype = colloc_ls_gettype;
  S->ops->getid = colloc_ls_getid;
  S->ops->initialize = colloc_ls_initialize;
  S->ops->setup = colloc_ls_setup;
  S->ops->solve = colloc_ls_solve;
  S->ops->lastflag = colloc_ls_lastflag;
  S->ops->space = colloc_ls_space;
  S->ops->free = colloc_ls_free;
  c->solver = abd_solver_alloc(J->ndim, J->ntst, J->ncol, J->nfpr, J->nbc, J->nint);
  if (!c->solver) {
    colloc_ls_free(S);
    return NULL;
  }
  return S;
}

int SUNLinSol_Colloc_Det(SUNLinearSolver S, int *sign, double *logabs)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_ILL_INPUT;
  abd_solver_det(c->solver, sign, logabs);
  return SUNLS_SUCCESS;
}

abd_solver *SUNLinSol_Colloc_Solver(SUNLinearSolver S)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  return c ? c->solver : NULL;
}

int SUNLinSol_Colloc_SolveLastUnit(SUNLinearSolver S, int on)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_ILL_INPUT;
  const size_t n = (size_t)abd_solver_size(c->solver);
  c->unit_of = 0;
  c->last_unit = 0;
  if (on && !c->pair && !(c->pair = calloc(2 * n, sizeof(double)))) return SUNLS_MEM_FAIL;
  c->last_unit = on != 0;
  return SUNLS_SUCCESS;
}

const double *SUNLinSol_Colloc_LastUnitSolution(SUNLinearSolver S)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c || c->unit_of == 0 || c->unit_of != c->setups || c->last_flag != ABD_OK) return NULL;
  return c->pair + abd_solver_size(c->solver);
}

int SUNLinSol_Colloc_ExpectRhs(SUNLinearSolver S, const double *b)
{
  colloc_ls_content *c = colloc_ls_content_of(S);
  if (!c) return SUNLS_ILL_INPUT;
  c->unit_of = 0; /* pair is overwritten */
  c->expected = pair_fill(c, b) == 0;
  return c->expected ? SUNLS_SUCCESS : SUNLS_MEM_FAIL;
}
