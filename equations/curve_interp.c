/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "curve_interp.h"

#include <math.h>

#include "cable/cable_status.h"

int curve_interp_check(const cable_solution *sol)
{
  if (!sol || !sol->t || !sol->u || sol->ndim < 1 || sol->ntst < 1 || sol->ncol < 1 ||
      sol->ncol > CURVE_INTERP_MAX_NCOL)
    return CABLE_ERR_INPUT;
  int np = cable_solution_npts(sol);
  for (int k = 0; k < np; k++) {
    if (!isfinite(sol->t[k])) return CABLE_ERR_NONFINITE;
    if (k > 0 && !(sol->t[k] > sol->t[k - 1])) return CABLE_ERR_INPUT;
  }
  for (long k = 0; k < (long)np * sol->ndim; k++)
    if (!isfinite(sol->u[k])) return CABLE_ERR_NONFINITE;
  return CABLE_SUCCESS;
}

int curve_interp_locate(const cable_solution *sol, double t, int hint)
{
  int m = sol->ncol, n = sol->ntst;
  const double *x = sol->t;
  if (hint >= 0 && hint < n && t >= x[hint * m] && t <= x[(hint + 1) * m]) return hint;
  if (hint >= 0 && hint + 1 < n && t >= x[(hint + 1) * m] && t <= x[(hint + 2) * m]) return hint + 1;
  if (t <= x[m]) return 0;
  if (t >= x[(n - 1) * m]) return n - 1;
  int lo = 0, hi = n - 1;          /* invariant: x[lo*m] <= t < x[(hi+1)*m] */
  while (hi > lo) {
    int mid = (lo + hi + 1) / 2;
    if (x[mid * m] <= t) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/* Lagrange basis polynomials of the interval's nodes and their first two
 * derivatives, built factor by factor in the scaled variable xi in [0,1]
 * (scaling keeps the products O(1) for any interval length). */
static void lagrange_basis(const double *x, int m, double t, double *l, double *dl, double *d2l)
{
  double h = x[m] - x[0];
  double xi = (t - x[0]) / h;
  double node[CURVE_INTERP_MAX_NCOL + 1];
  for (int k = 0; k <= m; k++) node[k] = (x[k] - x[0]) / h;
  for (int i = 0; i <= m; i++) {
    double p = 1.0, dp = 0.0, d2p = 0.0, den = 1.0;
    for (int k = 0; k <= m; k++) {
      if (k == i) continue;
      double f = xi - node[k];
      d2p = d2p * f + 2.0 * dp;
      dp = dp * f + p;
      p *= f;
      den *= node[i] - node[k];
    }
    l[i] = p / den;
    dl[i] = dp / (den * h);
    d2l[i] = d2p / (den * h * h);
  }
}

void curve_interp_eval_on(const cable_solution *sol, int j, double t, int first, int ncomp,
                          double *v, double *dv, double *d2v)
{
  int m = sol->ncol, nd = sol->ndim;
  double l[CURVE_INTERP_MAX_NCOL + 1], dl[CURVE_INTERP_MAX_NCOL + 1], d2l[CURVE_INTERP_MAX_NCOL + 1];
  lagrange_basis(sol->t + (long)j * m, m, t, l, dl, d2l);
  for (int c = 0; c < ncomp; c++) {
    double a = 0.0, b = 0.0, e = 0.0;
    for (int i = 0; i <= m; i++) {
      double y = sol->u[((long)j * m + i) * nd + first + c];
      a += l[i] * y;
      b += dl[i] * y;
      e += d2l[i] * y;
    }
    v[c] = a;
    if (dv) dv[c] = b;
    if (d2v) d2v[c] = e;
  }
}

int curve_interp_eval(const cable_solution *sol, double t, int first, int ncomp,
                      double *v, double *dv, double *d2v)
{
  int j = curve_interp_locate(sol, t, -1);
  curve_interp_eval_on(sol, j, t, first, ncomp, v, dv, d2v);
  return j;
}
