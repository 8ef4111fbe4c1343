/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Mesh adaptation, re-interpolation, restarts and the error estimate.
 *
 * Error monitor (AUTO's idea): on interval j the collocation polynomial's
 * NCOL-th derivative D_j is constant; divided differences of D between
 * neighbouring intervals estimate u^(NCOL+1).  The local error between mesh
 * points is about  kappa * h_j^(NCOL+1) * |u^(NCOL+1)|,  kappa the
 * interpolation-error constant of the equally spaced nodes.  Adaptation
 * equidistributes |u^(NCOL+1)|^(1/(NCOL+1)) over [0,1], which equalises
 * that local error. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"
#include "solution_mesh.h"

/* The monitor is floored at this fraction of its maximum so that smooth parts
 * keep some resolution and the mesh ratio stays bounded. */
#define CONT_MONITOR_FLOOR 1.0e-3
/* kappa(NCOL) is the maximum of a polynomial with simple zeros, sampled at
 * this many equal subintervals of [0,1]: near the maximum the polynomial is
 * flat, so the sampled value is low by O((1/CONT_KAPPA_SAMPLES)^2) relative
 * (below 1e-5 for NCOL <= 7), far below the estimate's own uncertainty
 * (a factor 1-9, doc/engine.md). */
#define CONT_KAPPA_SAMPLES 2000
/* Below this many rounding units (relative to max(1, max|u|)) the error
 * estimate is rounding noise, not truncation error: differences of the
 * NCOL-th derivative of an exact or trivial solution (u = 0, u linear).
 * Equidistributing noise moves the mesh at random, and with it the point
 * values by the interpolation error of the remap: on elasz.f90 (u = 0 on
 * the trivial branch) at DS = 0.1 the second branch point moved by 2e-6
 * from one build to another.  1e3 covers the sums over NCOL+1 nodes
 * divided by h^NCOL at NTST <= 1000 with a margin. */
#define CONT_MESH_NOISE 1.0e3

/* max over components of |u^(ncol+1)| estimated on each interval, into e[ntst] */
static void high_derivative(const colloc_system *s, const double *x, double *e, double *dn)
{
  int nd = s->ndim, nc = s->ncol, nt = s->ntst;
  for (int j = 0; j < nt; j++) {
    double h = s->mesh[j + 1] - s->mesh[j], hp = pow(h, nc);
    const double *uj = x + (size_t)(j * nc) * (size_t)nd;
    for (int i = 0; i < nd; i++) {
      double v = 0.0;
      for (int k = 0; k <= nc; k++) v += s->basis.dnl[k] * uj[k * nd + i];
      dn[(size_t)j * nd + i] = v / hp;
    }
  }
  for (int j = 0; j < nt; j++) {
    int a = j > 0 ? j - 1 : j, b = j < nt - 1 ? j + 1 : j;
    if (a == b) {
      e[j] = 0.0;
      continue;
    }
    double ta = 0.5 * (s->mesh[a] + s->mesh[a + 1]), tb = 0.5 * (s->mesh[b] + s->mesh[b + 1]);
    double m = 0.0;
    for (int i = 0; i < nd; i++)
      m = fmax(m, fabs(dn[(size_t)b * nd + i] - dn[(size_t)a * nd + i]) / (tb - ta));
    e[j] = m;
  }
}

static double kappa(int ncol)
{
  /* max over [0,1] of |prod_k (x - k/ncol)| / (ncol+1)!, sampled finely */
  double best = 0.0, fact = 1.0;
  for (int i = 2; i <= ncol + 1; i++) fact *= i;
  for (int q = 0; q <= CONT_KAPPA_SAMPLES; q++) {
    double x = (double)q / CONT_KAPPA_SAMPLES, p = 1.0;
    for (int k = 0; k <= ncol; k++) p *= x - (double)k / ncol;
    best = fmax(best, fabs(p));
  }
  return best / fact;
}

double cont_error_estimate(const cable_cont *cc, const double *x)
{
  const colloc_system *s = cc->sys;
  double *e = malloc((size_t)s->ntst * sizeof *e);
  double *dn = malloc((size_t)s->ntst * (size_t)s->ndim * sizeof *dn);
  if (!e || !dn) {
    free(e); free(dn);
    return -1.0;
  }
  high_derivative(s, x, e, dn);
  double k = kappa(s->ncol), err = 0.0;
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    err = fmax(err, k * pow(h, s->ncol + 1) * e[j]);
  }
  free(e); free(dn);
  return err;
}

/* Re-interpolate v (on the old mesh, values at nodes) onto the new mesh. */
static void remap(const colloc_system *s, const double *told, const double *v, double *out, int ntst_old,
                  int ncol_old)
{
  int nd = s->ndim, nc = s->ncol;
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    for (int k = 0; k < nc; k++)
      colloc_interp(nd, ntst_old, ncol_old, told, v, s->mesh[j] + h * k / nc,
                    out + (size_t)(j * nc + k) * (size_t)nd);
  }
  colloc_interp(nd, ntst_old, ncol_old, told, v, 1.0, out + (size_t)(s->ntst * nc) * (size_t)nd);
}

int cont_adapt_mesh(cable_cont *cc)
{
  colloc_system *s = cc->sys;
  int nt = s->ntst, nc = s->ncol, nd = s->ndim;
  size_t npts = (size_t)(nt * nc + 1);
  double *e = malloc((size_t)nt * sizeof *e);
  double *dn = malloc((size_t)nt * (size_t)nd * sizeof *dn);
  double *cum = malloc(((size_t)nt + 1) * sizeof *cum);
  double *told = malloc(npts * sizeof *told);
  double *newmesh = malloc(((size_t)nt + 1) * sizeof *newmesh);
  double *tmp = malloc((size_t)cc->n * sizeof *tmp);
  int rc = CABLE_ERR_ALLOC;
  if (!e || !dn || !cum || !told || !newmesh || !tmp) goto done;
  high_derivative(s, cc->x, e, dn);
  double emax = 0.0, est = 0.0, kap = kappa(nc), umax = 1.0;
  for (int j = 0; j < nt; j++) {
    est = fmax(est, kap * pow(s->mesh[j + 1] - s->mesh[j], nc + 1) * e[j]);
    e[j] = pow(e[j], 1.0 / (nc + 1));
    emax = fmax(emax, e[j]);
  }
  for (size_t i = 0; i < npts * (size_t)nd; i++) umax = fmax(umax, fabs(cc->x[i]));
  rc = CABLE_SUCCESS;
  if (!(emax > 0) || !isfinite(emax)) goto done; /* nothing to equidistribute */
  if (est <= CONT_MESH_NOISE * DBL_EPSILON * umax) goto done; /* only rounding noise */
  cum[0] = 0.0;
  for (int j = 0; j < nt; j++)
    cum[j + 1] = cum[j] + fmax(e[j], CONT_MONITOR_FLOOR * emax) * (s->mesh[j + 1] - s->mesh[j]);
  newmesh[0] = 0.0;
  newmesh[nt] = 1.0;
  int j = 0;
  for (int i = 1; i < nt; i++) {
    double target = cum[nt] * i / nt;
    while (j < nt - 1 && cum[j + 1] < target) j++;
    double frac = (target - cum[j]) / (cum[j + 1] - cum[j]);
    newmesh[i] = s->mesh[j] + frac * (s->mesh[j + 1] - s->mesh[j]);
  }
  colloc_system_times(s, told);
  memcpy(s->mesh, newmesh, ((size_t)nt + 1) * sizeof *newmesh);
  double *vecs[] = {cc->x, cc->xdot, cc->xp, cc->xdotp};
  size_t nu = npts * (size_t)nd;
  for (int v = 0; v < 4; v++) {
    remap(s, told, vecs[v], tmp, nt, nc);
    memcpy(vecs[v], tmp, nu * sizeof *tmp);
  }
  cont_normalize(cc, cc->xdot);
  /* test functions of the current point on the new mesh, for the next
     comparison.  The point itself has not moved, so their signs stay: a
     located special point carries the sign of the far side of its event
     (cont_locate), which recomputing it could undo when the point sits on
     the near side within the location tolerance (Bratu's fold was then found
     twice after the IAD-th step). */
  cont_tests old = cc->tf;
  /* The factorisation on the new mesh gives only the determinant's sign
     (kept from the old mesh below, unless it was 0) and the singular values;
     without singular values (NSV = 0 and no branch-point test) it is skipped:
     the other test functions come from x and xdot (a fifth of the
     factorisations of a run with IAD = 3, doc/benchmarks.md). */
  int need_factor = cc->c->nsv > 0 || cont_bp_detect(cc) || old.det_sign == 0;
  rc = need_factor ? cont_tangent(cc, cc->x, cc->xdotp, tmp, &cc->tf) : CABLE_SUCCESS;
  if (rc == CABLE_SUCCESS) {
    cont_tests_fill(cc, cc->x, cc->xdot, &cc->tf);
    cc->tf.lp = copysign(fabs(cc->tf.lp), old.lp);
    for (int k = 0; k < cc->c->nuzr; k++) cc->tf.uz[k] = copysign(fabs(cc->tf.uz[k]), old.uz[k]);
    if (old.det_sign != 0) cc->tf.det_sign = old.det_sign;
  }
done:
  free(e); free(dn); free(cum); free(told); free(newmesh); free(tmp);
  return rc;
}

int cont_load_solution(cable_cont *cc, const cable_solution *src)
{
  colloc_system *s = cc->sys;
  int nd = s->ndim;
  if (src->ndim != nd) {
    cont_set_error(cc, "the stored solution has NDIM=%d, the problem %d", src->ndim, nd);
    return CABLE_ERR_INPUT;
  }
  int nt = s->ntst, ntold = src->ntst, ncold = src->ncol;
  /* new mesh: the old mesh's density, resampled to NTST intervals */
  solution_mesh_resample(src, nt, s->mesh);
  remap(s, src->t, src->u, cc->x, ntold, ncold);
  int np = src->npar < cc->npar ? src->npar : cc->npar;
  for (int k = 0; k < np; k++) s->par[k] = src->par[k];
  double *p = cc->x + (cc->n - cc->nfpr), *pd = cc->xdot + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++) p[q] = s->par[s->icp[q]];
  /* A stored direction is used when every free parameter that moves along it
     is free here too (the restart may free more parameters, e.g. an unfolding
     parameter that is zero along the old branch); its components are mapped by
     parameter index. */
  int usable = src->udot != NULL && src->nfpr > 0;
  for (int k = 0; usable && k < src->nfpr; k++) {
    int found = 0;
    for (int q = 0; q < cc->nfpr; q++) found |= s->icp[q] == src->icp[k];
    if (!found && src->pardot[k] != 0.0) usable = 0;
  }
  memset(cc->xdot, 0, (size_t)cc->n * sizeof *cc->xdot);
  if (usable) {
    remap(s, src->t, src->udot, cc->xdot, ntold, ncold);
    for (int q = 0; q < cc->nfpr; q++)
      for (int k = 0; k < src->nfpr; k++)
        if (src->icp[k] == s->icp[q]) pd[q] = src->pardot[k];
  }
  return CABLE_SUCCESS;
}

int cont_store_solution(cable_cont *cc, int itp, int lab)
{
  if (cc->pvls_fatal) {
    cont_set_error(cc, "PVLS returned %d (fatal) at a trial point near point %d", cc->pvls_fatal, cc->npt);
    cc->store_failed = 1;
    return CABLE_ERR_CALLBACK;
  }
  colloc_system *s = cc->sys;
  cable_solution *sol = cc->sol;
  int nd = s->ndim, npts = s->ntst * s->ncol + 1;
  colloc_system_times(s, sol->t);
  memcpy(sol->u, cc->x, (size_t)npts * (size_t)nd * sizeof *sol->u);
  /* AUTO's convention: the step is DS times the stored direction, so the
     direction of travel is stored multiplied by the sign of DS (a restart
     with DS < 0 from a run made with DS < 0 goes on, cont_engine.c) */
  double dsign = cc->c->ds < 0 ? -1.0 : 1.0;
  for (size_t i = 0; i < (size_t)npts * (size_t)nd; i++) sol->udot[i] = dsign * cc->xdot[i];
  const double *p = cc->x + (cc->n - cc->nfpr), *pd = cc->xdot + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++) s->par[s->icp[q]] = p[q];
  memcpy(sol->par, s->par, (size_t)cc->npar * sizeof *sol->par);
  for (int q = 0; q < cc->nfpr; q++) {
    sol->icp[q] = s->icp[q];
    sol->pardot[q] = dsign * pd[q];
  }
  sol->ntot = cc->npt;
  sol->itp = itp;
  sol->lab = lab;
  sol->bp_kind = itp == CABLE_TY_BP ? cc->bp_kind : CABLE_BP_UNKNOWN;
  sol->isw = cc->c->isw;
  sol->err_est = cont_error_estimate(cc, cc->x);
  sol->pvls_icp = cc->c->icp;   /* PVLS computes only the columns the run prints */
  sol->pvls_nicp = cc->c->nicp;
  sol->pvls_ds = cc->ds_used;
  sol->pvls_fld = cc->tf.lp;
  sol->pvls_bif = cont_bp_value(cc, &cc->tf);
  /* a negative PVLS status is fatal (doc/plugins.md); > 0 at a converged
     point has no step to reject and is not an error */
  int pv = cc->pb->pvls ? cc->pb->pvls(sol, sol->par, cc->pb->params) : 0;
  if (pv < 0) {
    cont_set_error(cc, "PVLS returned %d (fatal) at point %d", pv, cc->npt);
    cc->store_failed = 1;
    return CABLE_ERR_CALLBACK;
  }
  /* L2-NORM: sqrt of the integral of |u|^2 (unweighted); MAX U(i): AUTO's
     MXUPSP, the largest value (signed, not the modulus) of u_i over the
     NTST*NCOL+1 stored points */
  /* an extended problem's columns cover its first NDM components (AUTO's
     NDM: a fold's u, not its null vector) */
  int nd_all = nd;
  if (cc->c->ndm > 0 && cc->c->ndm < nd) nd = cc->c->ndm;
  double l2 = 0.0;
  for (int i = 0; i < nd; i++) cc->umax[i] = sol->u[i];
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    for (int k = 0; k <= s->ncol; k++) {
      const double *u = sol->u + (size_t)(j * s->ncol + k) * (size_t)nd_all;
      double sq = 0.0;
      for (int i = 0; i < nd; i++) {
        sq += u[i] * u[i];
        cc->umax[i] = fmax(cc->umax[i], u[i]);
      }
      l2 += h * s->basis.wn[k] * sq;
    }
  }
  cable_point *pt = &cc->pt;
  pt->pt = cc->npt;
  pt->itp = itp;
  pt->lab = lab;
  pt->ndim = nd;
  pt->npar = cc->npar;
  pt->nicp = cc->c->nicp;
  pt->icp = cc->c->icp;
  pt->par = sol->par;
  pt->l2norm = sqrt(l2);
  pt->measure = cable_solution_measure(sol, cc->c->iplt, pt->l2norm);
  pt->umax = cc->umax;
  pt->newton_iters = cc->newton_iters;
  pt->ds = cc->ds_used;
  pt->err_est = sol->err_est;
  pt->det_sign = cc->tf.det_sign;
  pt->sv1 = cc->tf.sv1;
  pt->sv2 = cc->tf.sv2;
  pt->bp_kind = sol->bp_kind;
  pt->bp_mult = cable_bp_multiplicity(sol->bp_kind);
  return CABLE_SUCCESS;
}
