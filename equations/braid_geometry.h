/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Geometry of a braid solution (paper Sect. 12.2.3, 12.3): the two strand
 * centrelines, the contact curve (braid axis) and the first braid frame,
 * sampled from the piecewise-polynomial collocation solution.
 *
 * Conventions: t in [0,1], s = L t is arclength along strand 1; the first braid
 * frame {t1, d1, u1} is R(q) = (t1 | d1 | u1) for the Euler parameters q
 * (paper's formulas); r2 = r1 + Delta d1; the contact curve is
 * c = (r1 + r2)/2 = r1 + (Delta/2) d1.  The interpolated q is not exactly of
 * unit length; frames are computed from q/|q| (so they are orthonormal to
 * round-off) and |q|^2 - 1 is reported separately. */
#ifndef CABLE_BRAID_GEOMETRY_H
#define CABLE_BRAID_GEOMETRY_H

#include "cable/cable_solution.h"
#include "cable/cable_analysis.h"   /* cable_braid_topology */
#include "knot_type.h"

typedef struct braid_curves {
  int n;                        /* samples along strand 1 */
  double L, L2, Delta;
  double *s;                    /* [n] arclength along strand 1, uniform in t on [0, L] incl. both ends */
  double *sigma;                /* [n] arclength along strand 2 */
  double *r1, *r2, *c;          /* [3n] strand 1, strand 2 = r1 + Delta d1, contact curve c = r1 + Delta/2 d1 */
  double *t1, *d1, *u1;         /* [3n] first braid frame */
} braid_curves;

/* n >= 2 samples; NULL on failure. */
braid_curves *braid_curves_alloc(int n);
void braid_curves_free(braid_curves *bc);           /* NULL is a no-op */
/* Sample a braid solution at out->n points (piecewise-polynomial
 * interpolation of the collocation solution).  0, CABLE_ERR_INPUT (sizes,
 * L <= 0, Delta <= 0, |q| = 0) or CABLE_ERR_NONFINITE. */
int braid_curves_from_solution(const cable_solution *sol, braid_curves *out);

/* Everything the ribbon and curvature code need at one t (derivatives are
 * d/dt of the interpolating polynomials, so d/ds = (1/L) d/dt). */
typedef struct braid_point {
  double r1[3], dr1[3], d2r1[3];
  double t1[3], d1[3], u1[3];   /* frame of q/|q| */
  double dd1[3], d2d1[3];       /* d1 = B(q,q)/|q|^2 differentiated exactly */
  double c[3], dc[3], d2c[3];   /* contact curve and its t-derivatives */
  double qnorm2;                /* |q|^2 of the interpolant */
  double sigma;
} braid_point;

/* 0 when sol is a usable braid solution (ndim >= BR_NDIM, npar > BP_DELTA,
 * L > 0, Delta > 0, interpolable), else a cable_status error. */
int braid_geometry_check(const cable_solution *sol);
/* Evaluate at t; *hint (may be NULL) carries the mesh interval between calls
 * with increasing t.  CABLE_ERR_INPUT if |q| = 0. */
int braid_point_eval(const cable_solution *sol, double t, int *hint, braid_point *p);
/* Curvature |c' x c''| / |c'|^3 of the contact curve at p (any parametrisation). */
double braid_point_contact_curvature(const braid_point *p);
/* Contact-curve curvature at the n sample points of braid_curves (uniform in
 * t, both ends included) and its maximum (either pointer may be NULL). */
int braid_contact_curvature(const cable_solution *sol, int n, double *kappa, double *kappa_max);

#endif
