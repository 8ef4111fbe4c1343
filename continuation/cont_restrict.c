/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The problem restricted to the fixed-point space of a declared reflection S
 * (doc/engine.md, "Symmetry: the restriction to Fix(S)"): the original
 * problem plus one boundary condition, the odd quantity of S = 0, and one
 * free unfolding parameter eps added to one of the original boundary
 * conditions, so that the system stays square.  On Fix(S) the residual is
 * S-symmetric and eps times a row with an antisymmetric part can only vanish
 * with eps = 0: the restricted branch is the symmetric branch of the
 * original problem, with eps = 0 to the corrector's tolerance.  At the double
 * branch point the restricted kernel is the symmetric kernel direction
 * alone: a simple branch point.
 *
 * The wrapper forwards every callback to the original problem with its own
 * params; its boundary conditions are differenced (bcnd_has_jac = 0), the
 * other Jacobians are the original's with the unfolding parameter's column
 * zero (FUNC and ICND do not depend on it). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

struct cont_restricted {
  cable_problem pb;             /* the wrapper (params = this struct) */
  cable_constants c;            /* the run's constants with eps freed after the original free parameters */
  const cable_problem *orig;
  const cable_symmetry *sy;
  int comp, at;                 /* the odd quantity: component, end (0: t = 0, 1: t = 1) */
  int unfold_row, unfold_par;
  double *su;                   /* [ndim] S u (act) */
  char desc[300];
};

/* the row with the unfolding parameter must carry at least this fraction of
   the antisymmetric left null vector (else the restricted system stays
   singular: doc/engine.md) */
#define RESTRICT_ROW_SHARE 1.0e-8

static int r_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                  double *dfdp, void *params)
{
  const cont_restricted *r = params;
  int rc = r->orig->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, r->orig->params);
  if (rc == 0 && ijac >= 2 && dfdp)
    for (int i = 0; i < ndim; i++) dfdp[i + (size_t)ndim * r->unfold_par] = 0.0;
  return rc;
}

static int r_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                  double *fb, double *dbc, void *params)
{
  const cont_restricted *r = params;
  (void)ijac; (void)dbc;
  int rc = r->orig->bcnd(ndim, par, icp, nbc - 1, u0, u1, 0, fb, NULL, r->orig->params);
  if (rc != 0) return rc;
  fb[r->unfold_row] += par[r->unfold_par];
  const double *u = r->at ? u1 : u0;
  if (r->sy->act) {
    r->sy->act(ndim, u, r->su, r->orig->params);
    fb[nbc - 1] = u[r->comp] - r->su[r->comp];
  } else {
    fb[nbc - 1] = u[r->comp];
  }
  return 0;
}

static int r_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                  const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  const cont_restricted *r = params;
  int rc = r->orig->icnd(ndim, par, icp, nint, u, uold, udot, upold, ijac, fi, dint, r->orig->params);
  if (rc == 0 && ijac >= 2 && dint)
    for (int i = 0; i < nint; i++) dint[i + (size_t)nint * (ndim + r->unfold_par)] = 0.0;
  return rc;
}

static int r_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  const cont_restricted *r = params;
  return r->orig->stpnt(ndim, t, u, par, r->orig->params);
}

static int r_pvls(const cable_solution *sol, double *par, void *params)
{
  const cont_restricted *r = params;
  return r->orig->pvls(sol, par, r->orig->params);
}

cont_restricted *cont_restrict_build(const cable_cont *cc, char *msg, size_t len)
{
  const cable_problem *pb = cc->pb;
  if (cc->rs_sym < 0 || cc->rs_sym >= pb->nsym || !cc->rs_vec) {
    snprintf(msg, len, "no symmetry to restrict to");
    return NULL;
  }
  if (pb->nbc < 1) {
    snprintf(msg, len, "the problem has no boundary condition to carry the unfolding parameter");
    return NULL;
  }
  const cable_symmetry *sy = &pb->symmetries[cc->rs_sym];
  const char *name = sy->name ? sy->name : "S";
  cont_restricted *r = calloc(1, sizeof *r);
  if (!r || !(r->su = calloc((size_t)pb->ndim, sizeof *r->su))) {
    if (r) free(r);
    snprintf(msg, len, "out of memory");
    return NULL;
  }
  r->orig = pb;
  r->sy = sy;
  r->comp = cc->rs_comp;
  r->at = cc->rs_at;
  /* the unfolding parameter: declared, or the first slot past the problem's
     own that ICP does not use */
  int up = sy->unfold_par;
  if (up < 0)
    for (int p = pb->npar; p < cc->npar && up < 0; p++) {
      int used = 0;
      for (int q = 0; q < cc->c->nicp; q++) used |= cc->c->icp[q] == p;
      if (!used) up = p;
    }
  for (int q = 0; q < cc->nfpr && up >= 0; q++)
    if (cc->c->icp[q] == up) up = -2;
  if (up < 0 || up >= cc->npar) {
    snprintf(msg, len, "%s: no free parameter slot for the unfolding parameter (%s; NPAR = %d)", name,
             up == -2 ? "the declared one is already free" : "declare unfold_par or raise NPAR", cc->npar);
    cont_restrict_free(r);
    return NULL;
  }
  r->unfold_par = up;
  /* the row: declared, or where the antisymmetric left null vector is largest */
  int row = sy->unfold_bc;
  if (row < 0) {
    const double *psi = cc->rs_vec + 2 * (size_t)cc->n;
    size_t r0 = (size_t)cc->ntst * (size_t)cc->ncol * (size_t)cc->ndim;
    double all = 0.0, best = 0.0;
    for (int i = 0; i < cc->n; i++) all = fmax(all, fabs(psi[i]));
    for (int k = 0; k < pb->nbc; k++)
      if (fabs(psi[r0 + (size_t)k]) > best) { best = fabs(psi[r0 + (size_t)k]); row = k; }
    if (!(best > RESTRICT_ROW_SHARE * all)) {
      snprintf(msg, len, "%s: the antisymmetric left null vector vanishes on every boundary condition (%.1e of "
               "%.1e): declare unfold_bc", name, best, all);
      cont_restrict_free(r);
      return NULL;
    }
  }
  if (row >= pb->nbc) {
    snprintf(msg, len, "%s: unfold_bc = %d but the problem has %d boundary conditions", name, row, pb->nbc);
    cont_restrict_free(r);
    return NULL;
  }
  r->unfold_row = row;
  /* the wrapper */
  r->pb = *pb;
  r->pb.nbc = pb->nbc + 1;
  r->pb.func = r_func;
  r->pb.bcnd = r_bcnd;
  r->pb.icnd = pb->icnd ? r_icnd : NULL;
  r->pb.stpnt = pb->stpnt ? r_stpnt : NULL;
  r->pb.pvls = pb->pvls ? r_pvls : NULL;
  r->pb.bcnd_has_jac = 0;
  r->pb.params = r;
  r->pb.prepare = NULL;
  r->pb.release = NULL;
  r->pb.variational = NULL;
  r->pb.symmetries = NULL;
  r->pb.nsym = 0;
  if (r->pb.npar <= up) r->pb.npar = up + 1;
  /* the constants: eps free right after the original free parameters */
  r->c = *cc->c;
  cable_constants *c = &r->c;
  for (int q = cc->nfpr; q < c->nicp; q++)
    if (c->icp[q] == up) {
      memmove(&c->icp[q], &c->icp[q + 1], (size_t)(c->nicp - q - 1) * sizeof c->icp[0]);
      c->nicp--;
      break;
    }
  if (c->nicp < cc->nfpr) c->nicp = cc->nfpr;
  if (c->nicp >= CABLE_MAX_ICP) {
    snprintf(msg, len, "%s: ICP is full", name);
    cont_restrict_free(r);
    return NULL;
  }
  memmove(&c->icp[cc->nfpr + 1], &c->icp[cc->nfpr], (size_t)(c->nicp - cc->nfpr) * sizeof c->icp[0]);
  c->icp[cc->nfpr] = up;
  c->nicp++;
  if (c->npar <= up) c->npar = up + 1;
  c->stab = 0;
  if (sy->act)
    snprintf(r->desc, sizeof r->desc, "restricted to Fix(%s): (U(%d) - (S U)(%d)) at t = %d is 0, unfolding PAR(%d) on "
             "boundary condition %d", name, r->comp + 1, r->comp + 1, r->at, up + 1, row + 1);
  else
    snprintf(r->desc, sizeof r->desc, "restricted to Fix(%s): U(%d) at t = %d is 0, unfolding PAR(%d) on boundary "
             "condition %d", name, r->comp + 1, r->at, up + 1, row + 1);
  return r;
}

const cable_problem *cont_restrict_problem(const cont_restricted *r) { return &r->pb; }
const cable_constants *cont_restrict_constants(const cont_restricted *r) { return &r->c; }
int cont_restrict_unfold_par(const cont_restricted *r) { return r->unfold_par; }
const char *cont_restrict_describe(const cont_restricted *r) { return r->desc; }

void cont_restrict_free(cont_restricted *r)
{
  if (!r) return;
  free(r->su);
  free(r);
}
