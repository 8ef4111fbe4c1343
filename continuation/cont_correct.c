/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The corrector and the test functions at one point: Newton on the
 * collocation system closed by the pseudo-arclength equation, the check of
 * the converged nodes, and the LP and UZ test functions (cont_special.c
 * locates their zeros; the BP test function's ingredients, the determinant's
 * sign and the smallest singular value, come from cont_tangent.c).  Below
 * the driver (cont_engine.c) and the locating of special points
 * (cont_special.c), which both call it. */
#include <string.h>

#include "cont_impl.h"

/* A converged point whose stored nodes leave FUNC's domain is rejected like
 * a failed corrector (recoverable: the step is halved), or ends the run when
 * FUNC says the failure is fatal. */
int cont_check_nodes(cable_cont *cc, const double *x)
{
  int node = 0;
  int st = colloc_system_check_nodes(cc->sys, x, &node);
  if (st == 0) return CABLE_SUCCESS;
  const colloc_system *s = cc->sys;
  int j = node / s->ncol, k = node % s->ncol;
  double t = j < s->ntst ? s->mesh[j] + (s->mesh[j + 1] - s->mesh[j]) * k / s->ncol : s->mesh[s->ntst];
  snprintf(cc->rejected, sizeof cc->rejected,
           "FUNC rejects the converged solution at t = %.6g (node %d, status %d)", t, node, st);
  return st < 0 ? CABLE_ERR_CALLBACK : CABLE_ERR_RECOVERABLE;
}

/* Predictor x0 + ds xdot0, then Newton on the collocation system closed by the
 * pseudo-arclength equation <x - x0, xdot0> = ds. */
int cont_correct(cable_cont *cc, const double *x0, const double *xdot0, double ds, double *x)
{
  for (int i = 0; i < cc->n; i++) x[i] = x0[i] + ds * xdot0[i];
  return cont_correct_from(cc, x0, xdot0, ds, x);
}

/* Newton from the initial guess in x instead of the linear predictor (the
 * locating iterations start from the interpolant of the bracket's ends). */
int cont_correct_from(cable_cont *cc, const double *x0, const double *xdot0, double ds, double *x)
{
  colloc_system *s = cc->sys;
  size_t n = (size_t)cc->n;
  memcpy(s->x0, x0, n * sizeof *x0);
  memcpy(s->xdot0, xdot0, n * sizeof *xdot0);
  s->ds = ds;
  s->closing = COLLOC_CLOSE_ARCLENGTH;
  int rc = colloc_newton_solve(cc->nw, x);
  cc->newton_iters = colloc_newton_iterations(cc->nw);
  cc->cnt.correct++;
  cc->cnt.newton_iters += cc->newton_iters;
  cc->cnt.newton_fact += colloc_newton_setups(cc->nw);
  cc->rejected[0] = '\0';
  if (rc == CABLE_SUCCESS) rc = cont_check_nodes(cc, x);
  return rc;
}

static double param_value(const cable_cont *cc, const double *x, int k)
{
  const double *p = x + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++)
    if (cc->sys->icp[q] == k) return p[q];
  return cc->sys->par[k];
}

/* PVLS at the point x into cc->pvsol->par (its other parameters are the
 * run's); 0 on success. */
static int pvls_at(cable_cont *cc, const double *x)
{
  cable_solution *sol = cc->pvsol;
  const colloc_system *s = cc->sys;
  int npts = s->ntst * s->ncol + 1;
  if (sol->ntst != s->ntst) return 1; /* the mesh size is fixed for a run: not usable, not PVLS's failure */
  colloc_system_times(s, sol->t);
  memcpy(sol->u, x, (size_t)npts * (size_t)cc->ndim * sizeof *sol->u);
  memcpy(sol->par, s->par, (size_t)cc->npar * sizeof *sol->par);
  const double *p = x + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++) {
    sol->par[s->icp[q]] = p[q];
    sol->icp[q] = s->icp[q];
  }
  sol->pvls_icp = cc->c->icp;
  sol->pvls_nicp = cc->c->nicp;
  sol->err_est = -1.0;
  return cc->pb->pvls(sol, sol->par, cc->pb->params);
}

void cont_tests_fill(cable_cont *cc, const double *x, const double *xdot, cont_tests *tf)
{
  tf->lp = xdot[cc->n - cc->nfpr];
  int pvst = cc->pvsol && cc->c->nuzr > 0 ? pvls_at(cc, x) : 1;
  int pv = pvst == 0;
  if (pvst < 0 && !cc->pvls_fatal) cc->pvls_fatal = pvst;   /* fatal: reported when the point is stored */
  for (int k = 0; k < cc->c->nuzr; k++) {
    int j = cc->c->uzr[k].par;
    double v = param_value(cc, x, j);
    int free_par = 0;
    for (int q = 0; q < cc->nfpr; q++) free_par |= cc->sys->icp[q] == j;
    if (pv && !free_par) v = cc->pvsol->par[j];
    tf->uz[k] = v - cc->c->uzr[k].value;
  }
}
