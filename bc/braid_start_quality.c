/* SPDX-License-Identifier: GPL-3.0-or-later */
/* How well a STPNT guess satisfies the ODEs (by differences along t) and the
 * boundary conditions. */
#include <math.h>
#include <stdlib.h>

#include "braid_start.h"
#include "cable/cable_status.h"

/* Step of the five-point difference formula in t.  Its truncation error is
 * dt^4 |u^(5)|/30 and its rounding error ~ 1.5 eps |u|/dt; for the paper's
 * braids (d1 turning by up to ~10 pi over t in [0,1], so |u^(5)| ~ 30^5 |u|)
 * dt = 2e-4 makes both ~1e-11 |u|.  The reported fd_err estimates the
 * truncation error from a second evaluation with step 2 dt. */
static const double quality_dt = 2e-4;

/* Five-point central derivative at t with step h, per component. */
static int derivative5(const cable_problem *pb, double t, double h, double *up, double *um,
                       double *upp, double *umm, double *par, double *d)
{
  int st;
  if ((st = pb->stpnt(BR_NDIM, t + h, up, par, pb->params)) != 0) return st;
  if ((st = pb->stpnt(BR_NDIM, t - h, um, par, pb->params)) != 0) return st;
  if ((st = pb->stpnt(BR_NDIM, t + 2 * h, upp, par, pb->params)) != 0) return st;
  if ((st = pb->stpnt(BR_NDIM, t - 2 * h, umm, par, pb->params)) != 0) return st;
  for (int i = 0; i < BR_NDIM; i++) d[i] = (umm[i] - 8.0 * um[i] + 8.0 * up[i] - upp[i]) / (12.0 * h);
  return 0;
}

int braid_start_quality_eval(const cable_problem *pb, int npts, braid_start_quality *q)
{
  if (pb == NULL || q == NULL || pb->stpnt == NULL || pb->func == NULL || pb->bcnd == NULL ||
      pb->ndim != BR_NDIM || pb->nbc < 1 || pb->nbc > 32 || npts < 2)
    return CABLE_ERR_INPUT;
  const int nbc = pb->nbc;
  double u[BR_NDIM], f[BR_NDIM], d1[BR_NDIM], d2[BR_NDIM], w[4][BR_NDIM], u0[BR_NDIM],
      u1[BR_NDIM], fb[32];
  double *par = calloc(BP_NPAR > pb->npar ? BP_NPAR : (size_t)pb->npar, sizeof(double));
  if (par == NULL) return CABLE_ERR_ALLOC;
  const int icp[1] = {BP_T};
  const double h = quality_dt;
  int st = 0;
  q->ode_max = q->bc_max = 0.0;
  q->fd_step = h;
  for (int i = 0; i < BR_NDIM; i++) q->ode_comp[i] = q->fd_err[i] = q->u_scale[i] = 0.0;
  for (int i = 0; i < 32; i++) q->bc_row[i] = 0.0;
  for (int k = 0; k < npts && st == 0; k++) {
    const double t = 4 * h + (1.0 - 8 * h) * k / (npts - 1);
    if ((st = pb->stpnt(BR_NDIM, t, u, par, pb->params)) != 0) break;
    if ((st = pb->func(BR_NDIM, u, icp, par, 0, f, NULL, NULL, pb->params)) != 0) break;
    if ((st = derivative5(pb, t, h, w[0], w[1], w[2], w[3], par, d1)) != 0) break;
    if ((st = derivative5(pb, t, 2 * h, w[0], w[1], w[2], w[3], par, d2)) != 0) break;
    for (int i = 0; i < BR_NDIM; i++) {
      const double e = fabs(d1[i] - f[i]);
      q->ode_comp[i] = fmax(q->ode_comp[i], e);
      q->ode_max = fmax(q->ode_max, e);
      q->fd_err[i] = fmax(q->fd_err[i], fabs(d2[i] - d1[i]) / 15.0);
      q->u_scale[i] = fmax(q->u_scale[i], fabs(u[i]));
    }
  }
  if (st == 0 && (st = pb->stpnt(BR_NDIM, 0.0, u0, par, pb->params)) == 0 &&
      (st = pb->stpnt(BR_NDIM, 1.0, u1, par, pb->params)) == 0 &&
      (st = pb->bcnd(BR_NDIM, par, icp, nbc, u0, u1, 0, fb, NULL, pb->params)) == 0) {
    for (int i = 0; i < nbc; i++) {
      q->bc_row[i] = fabs(fb[i]);
      q->bc_max = fmax(q->bc_max, fabs(fb[i]));
    }
  }
  free(par);
  if (st > 0) return CABLE_ERR_RECOVERABLE;
  return st < 0 ? CABLE_ERR_CALLBACK : 0;
}
