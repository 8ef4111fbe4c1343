/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "colloc_basis.h"

#include <gsl/gsl_integration.h>
#include <string.h>

#include "cable/cable_status.h"

void colloc_basis_eval(int ncol, double x, double *l, double *dl)
{
  /* Lagrange polynomials on x_k = k/ncol; products are short (ncol <= 7),
     so the direct formula is accurate and cheap. */
  for (int k = 0; k <= ncol; k++) {
    double xk = (double)k / ncol, p = 1.0, dp = 0.0;
    for (int i = 0; i <= ncol; i++) {
      if (i == k) continue;
      double xi = (double)i / ncol, inv = 1.0 / (xk - xi);
      dp = dp * (x - xi) * inv + p * inv;
      p *= (x - xi) * inv;
    }
    l[k] = p;
    if (dl) dl[k] = dp;
  }
}

int colloc_basis_init(colloc_basis *b, int ncol)
{
  if (ncol < CABLE_NCOL_MIN || ncol > CABLE_NCOL_MAX) return CABLE_ERR_INPUT;
  memset(b, 0, sizeof *b);
  b->ncol = ncol;
  gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc((size_t)ncol);
  if (!tab) return CABLE_ERR_ALLOC;
  for (int m = 0; m < ncol; m++) {
    double xi, wi;
    gsl_integration_glfixed_point(0.0, 1.0, (size_t)m, &xi, &wi, tab);
    b->c[m] = xi;
    b->w[m] = wi;
  }
  gsl_integration_glfixed_table_free(tab);
  for (int m = 0; m < ncol; m++) colloc_basis_eval(ncol, b->c[m], b->l[m], b->dl[m]);
  for (int k = 0; k <= ncol; k++) {
    double s = 0.0;
    for (int m = 0; m < ncol; m++) s += b->w[m] * b->l[m][k];
    b->wn[k] = s;
  }
  /* l_k has leading coefficient 1/prod_{i!=k}(x_k - x_i); its ncol-th derivative is ncol! times that */
  double fact = 1.0;
  for (int i = 2; i <= ncol; i++) fact *= i;
  for (int k = 0; k <= ncol; k++) {
    double den = 1.0, xk = (double)k / ncol;
    for (int i = 0; i <= ncol; i++)
      if (i != k) den *= xk - (double)i / ncol;
    b->dnl[k] = fact / den;
  }
  return CABLE_SUCCESS;
}

void colloc_interp(int ndim, int ntst, int ncol, const double *t, const double *u, double s,
                   double *out)
{
  /* locate the interval by bisection on the mesh points t[j*ncol] */
  int lo = 0, hi = ntst;
  if (s <= t[0]) hi = 1;
  else if (s >= t[ntst * ncol]) lo = ntst - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (s < t[mid * ncol]) hi = mid;
    else lo = mid;
  }
  int j = lo;
  double t0 = t[j * ncol], h = t[(j + 1) * ncol] - t0;
  double l[CABLE_NCOL_MAX + 1];
  colloc_basis_eval(ncol, (s - t0) / h, l, NULL);
  for (int i = 0; i < ndim; i++) {
    double v = 0.0;
    for (int k = 0; k <= ncol; k++) v += l[k] * u[(j * ncol + k) * ndim + i];
    out[i] = v;
  }
}
