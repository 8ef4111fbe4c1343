/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Tangents, determinant signs and singular values of the extended Newton matrix. */
#include <math.h>
#include <string.h>

#include "cont_impl.h"

/* Inverse iteration for the smallest singular values: at most this many
 * sweeps, stopping when the singular triplets' residuals
 * max(|J v - s u|, |J^T u - s v|) fall below CONT_SV_RTOL |J|_F.
 * Convergence is linear with ratio sigma_k / sigma_{k+1}, fast near a branch
 * point where the ratio is small; the estimates only steer root finding and
 * sign tests, so a modest tolerance suffices. */
#define CONT_SV_MAXIT 12
#define CONT_SV_RTOL 1.0e-6

int cont_factor_at(cable_cont *cc, const double *x, double *logdet, int *sign)
{
  int rc = colloc_system_jacobian(cc->sys, x, cc->J);
  if (cc->linalg_shared) colloc_newton_forget(cc->nw); /* its matrix is overwritten */
  if (rc != 0) return rc > 0 ? CABLE_ERR_RECOVERABLE : CABLE_ERR_CALLBACK;
  rc = abd_solver_factor(cc->abd, cc->J);
  /* the Newton solver's factorisation is gone (shared storage) */
  if (cc->linalg_shared) colloc_newton_forget(cc->nw);
  if (rc != 0) return CABLE_ERR_LINSOLVE;
  if (sign) abd_solver_det(cc->abd, sign, logdet);
  return CABLE_SUCCESS;
}

void cont_normalize(cable_cont *cc, double *v)
{
  double nrm = sqrt(colloc_system_inner(cc->sys, v, v));
  if (nrm > 0)
    for (int i = 0; i < cc->n; i++) v[i] /= nrm;
}

int cont_smallest_sv(cable_cont *cc, int k, double *sv, double *vecs)
{
  return abd_solver_smallest_sv(cc->abd, cc->J, k, sv, vecs, CONT_SV_MAXIT, CONT_SV_RTOL);
}

/* Tangent and test functions from a factorisation of the extended matrix
 * [F_x; theta xdot_old^T] (abd, with its matrix J); unit (NULL: solve here)
 * the solution of that system for e_last, when already solved. */
static int tangent_from(cable_cont *cc, abd_solver *abd, colloc_jac *J, const double *unit, const double *x,
                        double *xdot_new, cont_tests *tf)
{
  int sign = 0;
  double logdet = 0;
  abd_solver_det(abd, &sign, &logdet);
  /* [F_x; theta xdot_old^T] xdot_new = e_last keeps the orientation: <xdot_new, xdot_old> > 0 */
  if (unit) {
    memcpy(xdot_new, unit, (size_t)cc->n * sizeof *xdot_new);
  } else {
    memset(xdot_new, 0, (size_t)cc->n * sizeof *xdot_new);
    xdot_new[cc->n - 1] = 1.0;
    if (abd_solver_solve(abd, xdot_new) != 0) return CABLE_ERR_LINSOLVE;
  }
  cont_normalize(cc, xdot_new);
  cc->tan_abd = abd;
  cc->tan_J = J;
  tf->det_sign = sign;
  tf->det_log = logdet;
  tf->sv1 = tf->sv2 = 0.0;
  if (cc->c->nsv > 0 || cont_bp_detect(cc)) {
    double sv[2] = {0, 0};
    /* two values: the second tells a double branch point from a simple one;
       ABD_NOT_CONVERGED (2) still leaves usable estimates */
    int iters = 0;
    int src = abd_solver_smallest_svd(abd, J, 2, NULL, sv, cc->tan_v, cc->tan_u, CONT_SV_MAXIT, CONT_SV_RTOL, &iters);
    cc->cnt.sv_calls++;
    cc->cnt.sv_iters += iters;
    cc->tan_sv[0] = src == 0 || src == 2 ? sv[0] : 0.0;
    cc->tan_sv[1] = src == 0 || src == 2 ? sv[1] : 0.0;
    if (src == 0 || src == 2) {
      tf->sv1 = sv[0];
      tf->sv2 = sv[1];
    }
  }
  cont_tests_fill(cc, x, xdot_new, tf);
  return CABLE_SUCCESS;
}

int cont_tangent(cable_cont *cc, const double *x, const double *xdot_old, double *xdot_new,
                 cont_tests *tf)
{
  colloc_system *s = cc->sys;
  memcpy(s->xdot0, xdot_old, (size_t)cc->n * sizeof *xdot_old);
  s->closing = COLLOC_CLOSE_ARCLENGTH;
  int rc = cont_factor_at(cc, x, NULL, NULL);
  cc->cnt.tan_fact++;
  if (rc != CABLE_SUCCESS) return rc;
  return tangent_from(cc, cc->abd, cc->J, NULL, x, xdot_new, tf);
}

int cont_tangent_after_newton(cable_cont *cc, const double *x, const double *xdot_old, double *xdot_new,
                              cont_tests *tf)
{
  abd_solver *abd;
  colloc_jac *J;
  /* the corrector's last matrix is [F_x; theta xdot_old^T] at the last iterate
     but one, which differs from x by less than the convergence tolerance */
  if (colloc_newton_factorization(cc->nw, &abd, &J) == 0)
    return tangent_from(cc, abd, J, colloc_newton_tangent_unit(cc->nw), x, xdot_new, tf);
  return cont_tangent(cc, x, xdot_old, xdot_new, tf);
}
