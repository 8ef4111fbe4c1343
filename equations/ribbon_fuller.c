/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "ribbon_fuller.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>

#include "braid_state.h"
#include "cable_vec3.h"
#include "cable/cable_status.h"
#include "ribbon.h"

double ribbon_fuller_density(const double ta[3], const double dta[3], const double tb[3], const double dtb[3])
{
  double x[3];
  cable_vec3_cross(ta, tb, x);
  double s[3] = {dta[0] + dtb[0], dta[1] + dtb[1], dta[2] + dtb[2]};
  return cable_vec3_dot(x, s) / (1.0 + cable_vec3_dot(ta, tb)) / (2.0 * M_PI);
}

int braid_ribbon_twist(const cable_solution *sol, double *tw)
{
  if (!tw) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(BRAID_RIBBON_GL_ORDER);
  if (!tab) return CABLE_ERR_ALLOC;
  double sum = 0.0;
  int hint = -1;
  for (int j = 0; j < sol->ntst && rc == CABLE_SUCCESS; j++) {
    double a = sol->t[j * sol->ncol], b = sol->t[(j + 1) * sol->ncol];
    for (size_t i = 0; i < tab->n && rc == CABLE_SUCCESS; i++) {
      double tt, wgt;
      braid_point q;
      gsl_integration_glfixed_point(a, b, i, &tt, &wgt, tab);
      rc = braid_point_eval(sol, tt, &hint, &q);
      sum += wgt * braid_point_twist_rate(&q);
    }
  }
  gsl_integration_glfixed_table_free(tab);
  if (rc != CABLE_SUCCESS) return rc;
  *tw = sum / (2.0 * M_PI);
  return isfinite(*tw) ? CABLE_SUCCESS : CABLE_ERR_NONFINITE;
}

/* Unit tangent and its t-derivative at q. */
/* Offset in t of the one-sided limits at a corner: the tangent moves by
 * O(this) from the limit, far below the jumps (1e-8 and more). */
#define RIBBON_FULLER_SIDE 1e-13

static void tangent_dt(const braid_point *q, double T[3], double dT[3])
{
  double K[3];
  braid_point_tangent_curvature(q, T, K);
  double sp = sqrt(cable_vec3_dot(q->dc, q->dc));
  for (int k = 0; k < 3; k++) dT[k] = K[k] * sp;
}

/* The geodesic from unit vector u to v at sigma in [0, 1] (normalised linear
 * interpolation) and its sigma-derivative. */
static void geodesic(const double *u, const double *v, double sg, double T[3], double dT[3])
{
  double w[3], x[3];
  for (int k = 0; k < 3; k++) {
    x[k] = (1 - sg) * u[k] + sg * v[k];
    w[k] = v[k] - u[k];
  }
  double nx = sqrt(cable_vec3_dot(x, x));
  for (int k = 0; k < 3; k++) T[k] = x[k] / nx;
  double tw = cable_vec3_dot(T, w);
  for (int k = 0; k < 3; k++) dT[k] = (w[k] - tw * T[k]) / nx;
}

/* Fuller's integral over the corners at t: the interpolants' derivatives
 * jump at mesh points (and the contact curve's at the closure t = 0 = 1),
 * so each tangent curve closes only with the geodesic arcs across its jumps,
 * from T(t-) to T(t+).  tl, tr: just left and right of the corner. */
static int corner(const cable_solution *a, const cable_solution *b, double tl, double tr,
                  const gsl_integration_glfixed_table *tab, double *sum)
{
  braid_point p[4];
  int rc = braid_point_eval(a, tl, NULL, &p[0]);
  if (!rc) rc = braid_point_eval(a, tr, NULL, &p[1]);
  if (!rc) rc = braid_point_eval(b, tl, NULL, &p[2]);
  if (!rc) rc = braid_point_eval(b, tr, NULL, &p[3]);
  if (rc) return rc;
  double T[4][3], K[3];
  for (int m = 0; m < 4; m++) braid_point_tangent_curvature(&p[m], T[m], K);
  for (size_t i = 0; i < tab->n; i++) {
    double sg, wgt, Ta[3], dTa[3], Tb[3], dTb[3];
    gsl_integration_glfixed_point(0.0, 1.0, i, &sg, &wgt, tab);
    geodesic(T[0], T[1], sg, Ta, dTa);
    geodesic(T[2], T[3], sg, Tb, dTb);
    if (cable_vec3_dot(Ta, Tb) > -1.0 + 1e-12) *sum += wgt * ribbon_fuller_density(Ta, dTa, Tb, dTb);
  }
  return CABLE_SUCCESS;
}

int braid_writhe_change(const cable_solution *a, const cable_solution *b, double *dwr, double *min_dot)
{
  if (!dwr || !min_dot) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(a);
  if (!rc) rc = braid_geometry_check(b);
  if (rc) return rc;
  /* the union of the two meshes: both interpolants are polynomials on each piece */
  int na = a->ntst + 1, nb = b->ntst + 1, nu = 0;
  double *cut = malloc(((size_t)na + (size_t)nb) * sizeof *cut);
  gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(RIBBON_FULLER_GL_ORDER);
  if (!cut || !tab) {
    free(cut);
    if (tab) gsl_integration_glfixed_table_free(tab);
    return CABLE_ERR_ALLOC;
  }
  for (int i = 0, j = 0; i < na || j < nb;) {
    double ta = i < na ? a->t[i * a->ncol] : (double)INFINITY, tb = j < nb ? b->t[j * b->ncol] : (double)INFINITY;
    double t = ta <= tb ? ta : tb;
    if (ta <= tb) i++;
    else j++;
    if (nu == 0 || t > cut[nu - 1]) cut[nu++] = t;
  }
  double sum = 0.0, mind = 1.0;
  int ha = -1, hb = -1;
  for (int k = 0; k + 1 < nu && rc == CABLE_SUCCESS; k++)
    for (size_t i = 0; i < tab->n && rc == CABLE_SUCCESS; i++) {
      double tt, wgt, Ta[3], dTa[3], Tb[3], dTb[3];
      braid_point p, q;
      gsl_integration_glfixed_point(cut[k], cut[k + 1], i, &tt, &wgt, tab);
      rc = braid_point_eval(a, tt, &ha, &p);
      if (!rc) rc = braid_point_eval(b, tt, &hb, &q);
      if (rc) break;
      tangent_dt(&p, Ta, dTa);
      tangent_dt(&q, Tb, dTb);
      double d = cable_vec3_dot(Ta, Tb);
      if (d < mind) mind = d;
      /* near antiparallel tangents the formula does not hold: the caller
         checks min_dot; keep the sum finite */
      if (d > -1.0 + 1e-12) sum += wgt * ribbon_fuller_density(Ta, dTa, Tb, dTb);
    }
  /* the corners: interior cuts, and the closure (left of 1, right of 0) */
  for (int k = 0; k + 1 < nu && rc == CABLE_SUCCESS; k++) {
    double tl = k == 0 ? cut[nu - 1] - RIBBON_FULLER_SIDE : cut[k] - RIBBON_FULLER_SIDE;
    rc = corner(a, b, tl, cut[k] + RIBBON_FULLER_SIDE, tab, &sum);
  }
  free(cut);
  gsl_integration_glfixed_table_free(tab);
  if (rc) return rc;
  *dwr = sum;
  *min_dot = mind;
  return isfinite(sum) ? CABLE_SUCCESS : CABLE_ERR_NONFINITE;
}
