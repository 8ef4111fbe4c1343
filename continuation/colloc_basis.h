/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Collocation basis on one mesh interval, in the local variable x in [0,1]:
 * the Lagrange polynomials l_k through the NCOL+1 equally spaced nodes
 * x_k = k/NCOL (where AUTO stores the solution) and the NCOL Gauss-Legendre
 * collocation points c_m with their weights. */
#ifndef CABLE_COLLOC_BASIS_H
#define CABLE_COLLOC_BASIS_H

#include "cable/cable_constants.h"   /* CABLE_NCOL_MIN, CABLE_NCOL_MAX */

typedef struct colloc_basis {
  int ncol;
  double c[CABLE_NCOL_MAX];        /* Gauss points in (0,1) */
  double w[CABLE_NCOL_MAX];        /* Gauss weights on [0,1] (sum 1) */
  /* l[m][k] = l_k(c_m), dl[m][k] = l_k'(c_m) (derivative in x) */
  double l[CABLE_NCOL_MAX][CABLE_NCOL_MAX + 1];
  double dl[CABLE_NCOL_MAX][CABLE_NCOL_MAX + 1];
  /* node quadrature: integral over [0,1] of the interpolant = sum_k wn[k] * value_k
     (Gauss quadrature of the interpolating polynomial, exact for degree NCOL) */
  double wn[CABLE_NCOL_MAX + 1];
  /* NCOL-th derivative of l_k (a constant): used by the error monitor */
  double dnl[CABLE_NCOL_MAX + 1];
} colloc_basis;

/* 0 on success, CABLE_ERR_INPUT when ncol is outside [2,7]. */
int colloc_basis_init(colloc_basis *b, int ncol);

/* Lagrange basis values (and derivatives when dl != NULL) at x in [0,1]. */
void colloc_basis_eval(int ncol, double x, double *l, double *dl);

/* Evaluate a stored piecewise polynomial (mesh t[0..ntst*ncol], values
 * u[(j*ncol+k)*ndim + i]) at time s into out[ndim]. */
void colloc_interp(int ndim, int ntst, int ncol, const double *t, const double *u, double s,
                   double *out);

#endif
