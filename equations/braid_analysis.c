/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_analysis.h"
#include "braid_geometry.h"
#include "tube_distance.h"

#include <gsl/gsl_math.h>
#include <math.h>
#include <string.h>

#include "braid_integrals.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_state.h"
#include "cable/cable_status.h"
#include "curve_interp.h"
#include "ribbon.h"

static double wrap_2pi(double a)
{
  double r = fmod(a, 2.0 * M_PI);
  return r < 0 ? r + 2.0 * M_PI : r;
}

/* Relative drift of a first integral: spread over the nodes, scaled by its
 * largest magnitude (or 1 when it vanishes identically). */
static double spread(double lo, double hi, double scale)
{
  return (hi - lo) / (scale > 0 ? scale : 1.0);
}

double cable_braid_first_integral_drift(const cable_solution *sol)
{
  if (!sol || !sol->u || !sol->par || sol->ntst < 1 || sol->ncol < 1 || sol->ndim != BR_NDIM ||
      sol->npar <= BP_EPS13)
    return -1.0;
  braid_material m;
  braid_material_from_par(sol->par, &m);
  double lo[4] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[4] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double mag[4] = {0, 0, 0, 0}, drift = 0;
  /* at the mesh points, where collocation is superconvergent (O(h^(2 NCOL)));
     between them the solution is only O(h^(NCOL+1)) accurate */
  for (int k = 0; k < cable_solution_npts(sol); k += sol->ncol) {
    braid_first_integrals fi;
    if (braid_first_integrals_eval(sol->u + (size_t)k * BR_NDIM, &m, &fi) != 0) return -1.0;
    double v[4] = {fi.F2, fi.FM, fi.h, fi.ham};
    for (int q = 0; q < 4; q++) {
      lo[q] = fmin(lo[q], v[q]);
      hi[q] = fmax(hi[q], v[q]);
      mag[q] = fmax(mag[q], fabs(v[q]));
    }
  }
  for (int q = 0; q < 4; q++) drift = fmax(drift, spread(lo[q], hi[q], mag[q]));
  return drift;
}

int cable_braid_pressure_at(const cable_solution *sol, double t, double *p1, double *p2, double *sigma)
{
  if (!sol || !p1 || !p2) return CABLE_ERR_NULL;
  if (sol->ndim != BR_NDIM || sol->npar <= BP_W02 || curve_interp_check(sol) != 0 || !(t >= 0 && t <= 1))
    return CABLE_ERR_INPUT;
  double u[BR_NDIM];
  braid_material m;
  braid_material_from_par(sol->par, &m);
  curve_interp_eval(sol, t, 0, BR_NDIM, u, NULL, NULL);
  if (braid_contact_pressure(u, NULL, &m, p1, p2) != 0) return CABLE_ERR_NONFINITE;
  if (sigma) *sigma = u[BR_SIGMA];
  return CABLE_SUCCESS;
}

int cable_braid_solution_curves(const cable_solution *sol, double *r1, double *r2, double *c, double *p1, double *p2,
                          double *sigma)
{
  if (!sol) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  double delta = sol->par[BP_DELTA];
  int hint = -1;
  for (int k = 0; k < cable_solution_npts(sol); k++) {
    braid_point p;
    rc = braid_point_eval(sol, sol->t[k], &hint, &p);
    double q1, q2, sg;
    if (rc == CABLE_SUCCESS) rc = cable_braid_pressure_at(sol, sol->t[k], &q1, &q2, &sg);
    if (rc != CABLE_SUCCESS) return rc;
    for (int j = 0; j < 3; j++) {
      if (r1) r1[3 * k + j] = p.r1[j];
      if (r2) r2[3 * k + j] = p.r1[j] + delta * p.d1[j];
      if (c) c[3 * k + j] = p.c[j];
    }
    if (p1) p1[k] = q1;
    if (p2) p2[k] = q2;
    if (sigma) sigma[k] = sg;
  }
  return CABLE_SUCCESS;
}

static int negative(double p)
{
  return p < 0;
}

/* The t in [ta, tb] where strand `which`'s pressure changes sign (it does:
 * the node values differ in sign), by bisection on the interpolant. */
static int refine_sign_change(const cable_solution *sol, int which, double ta, double tb, double *t)
{
  double pa1, pa2;
  int rc = cable_braid_pressure_at(sol, ta, &pa1, &pa2, NULL);
  int neg_a = negative(which == 1 ? pa1 : pa2);
  /* each halving gains one bit: 64 halvings take any mesh interval below
     CABLE_BRAID_PSIGN_TTOL; the bound only guards against a non-shrinking interval */
  for (int it = 0; !rc && it < 64 && tb - ta > CABLE_BRAID_PSIGN_TTOL; it++) {
    double tm = 0.5 * (ta + tb), q1, q2;
    rc = cable_braid_pressure_at(sol, tm, &q1, &q2, NULL);
    if (negative(which == 1 ? q1 : q2) == neg_a) ta = tm;
    else tb = tm;
  }
  *t = 0.5 * (ta + tb);
  return rc;
}

static int record_sign_change(const cable_solution *sol, int which, double ta, double tb, cable_braid_psign *ps)
{
  if (ps->n < CABLE_BRAID_PSIGN_MAX) {
    double t, p1, p2, sigma;
    int rc = refine_sign_change(sol, which, ta, tb, &t);
    if (!rc) rc = cable_braid_pressure_at(sol, t, &p1, &p2, &sigma);
    if (rc) return rc;
    ps->s[ps->n] = t * sol->par[BP_L];
    ps->sigma[ps->n] = sigma;
  }
  ps->n++;
  return CABLE_SUCCESS;
}

int cable_braid_pressure_signs(const cable_solution *sol, cable_braid_analysis *out)
{
  if (!sol || !out) return CABLE_ERR_NULL;
  if (sol->ndim != BR_NDIM || sol->npar <= BP_W02 || curve_interp_check(sol) != 0) return CABLE_ERR_INPUT;
  braid_material m;
  braid_material_from_par(sol->par, &m);
  out->pmin1 = out->pmin2 = HUGE_VAL;
  out->pmax1 = out->pmax2 = -HUGE_VAL;
  out->psign1.n = out->psign2.n = 0;
  double prev1 = 0.0, prev2 = 0.0;
  for (int k = 0; k < cable_solution_npts(sol); k++) {
    const double *u = sol->u + (size_t)k * BR_NDIM;
    double f[BR_NDIM], p1, p2;
    if (braid_rhs(u, &m, f, NULL, NULL) != 0) return CABLE_ERR_NONFINITE;
    if (braid_contact_pressure(u, f, &m, &p1, &p2) != 0) return CABLE_ERR_NONFINITE;
    out->pmin1 = fmin(out->pmin1, p1);
    out->pmax1 = fmax(out->pmax1, p1);
    out->pmin2 = fmin(out->pmin2, p2);
    out->pmax2 = fmax(out->pmax2, p2);
    int rc = CABLE_SUCCESS;
    if (k > 0 && negative(prev1) != negative(p1)) rc = record_sign_change(sol, 1, sol->t[k - 1], sol->t[k], &out->psign1);
    if (!rc && k > 0 && negative(prev2) != negative(p2))
      rc = record_sign_change(sol, 2, sol->t[k - 1], sol->t[k], &out->psign2);
    if (rc) return rc;
    prev1 = p1;
    prev2 = p2;
  }
  return CABLE_SUCCESS;
}

int cable_braid_analysis_compute(const cable_solution *sol, cable_braid_analysis *out)
{
  if (!sol || !out) return CABLE_ERR_NULL;
  memset(out, 0, sizeof *out);
  if (sol->ndim != BR_NDIM || sol->npar <= BP_EPS13 || curve_interp_check(sol) != 0) return CABLE_ERR_INPUT;
  int rc = braid_topology_compute(sol, 0, &out->topo);
  if (rc) return rc;
  rc = cable_braid_tube_distance_solution(sol, 0, &out->tube);
  if (rc) return rc;
  rc = cable_braid_pressure_signs(sol, out);
  if (rc) return rc;
  out->drift = cable_braid_first_integral_drift(sol);
  if (out->drift < 0) return CABLE_ERR_NONFINITE;
  int npts = cable_solution_npts(sol);
  const double *u0 = sol->u, *u1 = sol->u + (size_t)(npts - 1) * BR_NDIM;
  if (out->topo.closure < 0) {
    out->closure = wrap_2pi(u0[BR_XI1] + u1[BR_XI2]);
  } else {
    out->closure = wrap_2pi(u1[BR_XI1] - u0[BR_XI1]);
    out->closure2 = wrap_2pi(u1[BR_XI2] - u0[BR_XI2]);
  }
  return CABLE_SUCCESS;
}

int cable_braid_axis_same_type(const cable_braid_analysis *a, const cable_braid_analysis *b)
{
  if (!a || !b) return 0;
  return strcmp(a->topo.axis.name, b->topo.axis.name) == 0 && a->topo.axis.handedness == b->topo.axis.handedness;
}

int cable_braid_branch_settled(const cable_braid_analysis *const *a, int n, int *first)
{
  if (!a || n <= 0) {
    if (first) *first = -1;
    return -1;
  }
  int dummy;
  if (!first) first = &dummy;
  int last = n - 1;
  while (last >= 0 && !a[last]) last--;
  *first = last;
  if (last < 0) return -1;
  for (int i = last - 1; i >= 0; i--) {
    if (!a[i]) continue;
    if (!cable_braid_axis_same_type(a[i], a[last])) break;
    *first = i;
  }
  for (int i = *first; i <= last; i++)
    if (a[i] && a[i]->tube.dmin > 1.0) return i;
  return -1;
}
