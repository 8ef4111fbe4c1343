/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Piecewise-polynomial view of a stored collocation solution.
 *
 * A cable_solution keeps values at ntst*ncol+1 points; on mesh interval j,
 * [t[j*ncol], t[(j+1)*ncol]], the solution is the polynomial of degree ncol
 * through the ncol+1 stored points of that interval (AUTO's representation).
 * These routines evaluate that polynomial and its first two t-derivatives.
 * The representation is continuous at mesh points; its derivatives jump there
 * by the discretisation error. */
#ifndef CABLE_CURVE_INTERP_H
#define CABLE_CURVE_INTERP_H

#include "cable/cable_solution.h"

/* Largest NCOL handled (AUTO allows 2..7); fixes the size of stack buffers. */
#define CURVE_INTERP_MAX_NCOL 15

/* 0 when sol can be interpolated (sizes in range, mesh strictly increasing,
 * finite values), else CABLE_ERR_INPUT or CABLE_ERR_NONFINITE. */
int curve_interp_check(const cable_solution *sol);

/* Mesh interval j in [0, ntst) holding t (t outside [t0, t_end] is clamped to
 * the first or last interval).  hint: an interval to try first (or -1). */
int curve_interp_locate(const cable_solution *sol, double t, int hint);

/* Components first .. first+ncomp-1 at t on interval j (from
 * curve_interp_locate): values v[ncomp], and when not NULL dv = d/dt,
 * d2v = d2/dt2.  t may lie outside the interval (extrapolation). */
void curve_interp_eval_on(const cable_solution *sol, int j, double t, int first, int ncomp,
                          double *v, double *dv, double *d2v);

/* The same with the interval located for you; returns the interval used. */
int curve_interp_eval(const cable_solution *sol, double t, int first, int ncomp,
                      double *v, double *dv, double *d2v);

#endif
