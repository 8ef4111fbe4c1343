/* SUNLinearSolver ops over abd_solver (see sunlinsol_colloc.h). */
#include "sunlinsol_colloc.h"

#include <stdlib.h>

#include "sunmatrix_colloc.h"

typedef struct {
  abd_solver *solver;
  sunindextype last_flag; /* abd_solver code of the last setup/solve */
} colloc_ls_content;

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
  int rc = abd_solver_factor(c->solver, J);
  c->last_flag = rc;
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
  int rc = abd_solver_solve(c->solver, xd);
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
