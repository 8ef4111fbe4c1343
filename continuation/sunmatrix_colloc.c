/* SPDX-License-Identifier: GPL-3.0-or-later */
/* SUNMatrix ops over colloc_jac (see sunmatrix_colloc.h). */
#include "sunmatrix_colloc.h"

#include <stdlib.h>

typedef struct {
  colloc_jac *J;
  int owned; /* 1: allocated by clone, freed by destroy */
  int zero_pending; /* zero was called and nothing has been written since */
} colloc_mat_content;

static SUNMatrix_ID colloc_mat_getid(SUNMatrix A)
{
  (void)A;
  return SUNMATRIX_CUSTOM;
}

static void colloc_mat_destroy(SUNMatrix A)
{
  if (!A) return;
  colloc_mat_content *c = A->content;
  if (c && c->owned) colloc_jac_free(c->J);
  free(c);
  A->content = NULL;
  SUNMatFreeEmpty(A);
}

static SUNMatrix colloc_mat_wrap(colloc_jac *J, int owned, SUNContext ctx);

static SUNMatrix colloc_mat_clone(SUNMatrix A)
{
  const colloc_jac *J = SUNMat_Colloc_Jac(A);
  if (!J) return NULL;
  colloc_jac *K = colloc_jac_alloc(J->ndim, J->ntst, J->ncol, J->nfpr, J->nbc, J->nint);
  if (!K) return NULL;
  SUNMatrix B = colloc_mat_wrap(K, 1, A->sunctx);
  if (!B) colloc_jac_free(K);
  return B;
}

/* KINSOL zeroes the matrix before every call of the Jacobian function, which
 * overwrites every entry: the zeroing (a pass over 11 MB at NTST 150, NDIM 21,
 * NCOL 4) is deferred to the next access through SUNMat_Colloc_Jac and
 * dropped when SUNMat_Colloc_Filled says the matrix was rewritten first. */
static int colloc_mat_zero(SUNMatrix A)
{
  if (!SUNMat_Colloc_Jac(A)) return SUNMAT_ILL_INPUT;
  ((colloc_mat_content *)A->content)->zero_pending = 1;
  return SUNMAT_SUCCESS;
}

static int colloc_mat_matvec(SUNMatrix A, N_Vector x, N_Vector y)
{
  const colloc_jac *J = SUNMat_Colloc_Jac(A);
  if (!J || N_VGetLength(x) != J->n || N_VGetLength(y) != J->n) return SUNMAT_ILL_INPUT;
  const double *xd = N_VGetArrayPointer(x);
  double *yd = N_VGetArrayPointer(y);
  if (!xd || !yd) return SUNMAT_ILL_INPUT;
  colloc_jac_matvec(J, xd, yd);
  return SUNMAT_SUCCESS;
}

static int colloc_mat_space(SUNMatrix A, long int *lrw, long int *liw)
{
  const colloc_jac *J = SUNMat_Colloc_Jac(A);
  if (!J) return SUNMAT_ILL_INPUT;
  *lrw = (long)((size_t)J->ntst * (J->coll_stride + J->dense_stride) + (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr) +
                (size_t)J->ndense * (size_t)J->nfpr);
  *liw = 8;
  return SUNMAT_SUCCESS;
}

static SUNMatrix colloc_mat_wrap(colloc_jac *J, int owned, SUNContext ctx)
{
  SUNMatrix A = SUNMatNewEmpty(ctx);
  if (!A) return NULL;
  colloc_mat_content *c = malloc(sizeof *c);
  if (!c) {
    SUNMatFreeEmpty(A);
    return NULL;
  }
  c->J = J;
  c->owned = owned;
  c->zero_pending = 0;
  A->content = c;
  A->ops->getid = colloc_mat_getid;
  A->ops->clone = colloc_mat_clone;
  A->ops->destroy = colloc_mat_destroy;
  A->ops->zero = colloc_mat_zero;
  A->ops->matvec = colloc_mat_matvec;
  A->ops->space = colloc_mat_space;
  return A;
}

SUNMatrix SUNMat_Colloc(colloc_jac *J, SUNContext ctx)
{
  if (!J || !ctx) return NULL;
  return colloc_mat_wrap(J, 0, ctx);
}

colloc_jac *SUNMat_Colloc_Jac(SUNMatrix A)
{
  /* Our matrices are recognised by their destroy op: SUNMATRIX_CUSTOM alone
   * does not say whose custom matrix it is. */
  if (!A || !A->ops || A->ops->destroy != colloc_mat_destroy || !A->content) return NULL;
  colloc_mat_content *c = A->content;
  if (c->zero_pending) colloc_jac_zero(c->J);
  c->zero_pending = 0;
  return c->J;
}

void SUNMat_Colloc_Filled(SUNMatrix A)
{
  if (A && A->ops && A->ops->destroy == colloc_mat_destroy && A->content)
    ((colloc_mat_content *)A->content)->zero_pending = 0;
}
