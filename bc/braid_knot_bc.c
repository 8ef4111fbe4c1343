/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Knot boundary conditions (12.3.1)-(12.3.23) plus the phase condition
 * omega2(0) = w2fix, with the unfolding parameter eps21 in (12.3.21); the
 * symmetric variant adds F2(0) = 0 and eps13 in (12.3.13).  Why the extra rows
 * and parameters are needed: doc/braid-boundary-conditions.md. */
#include <math.h>

#include "braid_bc.h"

/* dbc entry of row i, column j (u0: j, u1: ndim + j, par k: 2 ndim + k). */
#define DU0(i, j) dbc[(i) + nbc * (j)]
#define DU1(i, j) dbc[(i) + nbc * (BR_NDIM + (j))]
#define DP(i, k) dbc[(i) + nbc * (2 * BR_NDIM + (k))]

static int knot_conditions(int ndim, const double *par, int nbc, int sym, const double *u0,
                           const double *u1, int ijac, double *fb, double *dbc)
{
  if (ndim != BR_NDIM || nbc != (sym ? BK_SYM_NBC : BK_NBC)) return CABLE_BRAID_BC_SIZE;

  const double delta = par[BP_DELTA], b1 = par[BP_B1], b2 = par[BP_B2];
  const double c0 = cos(u0[BR_ETA]), s0 = sin(u0[BR_ETA]);
  const double cl = cos(u1[BR_ETA]), sl = sin(u1[BR_ETA]);
  const double a0 = 1.0 - delta * u0[BR_W3];  /* sigma'(0) cos eta(0) */
  const double al = 1.0 - delta * u1[BR_W3];
  if (c0 == 0.0 || al == 0.0 || b2 == 0.0) return CABLE_BRAID_BC_DOMAIN;
  const double eps13 = sym ? par[BP_EPS13] : 0.0;

  braid_bc_origin_residual(par, u0, fb);
  fb[BK_XL] = u1[BR_X1] - u0[BR_X1] - delta + eps13;
  fb[BK_YL] = u1[BR_Y1];
  fb[BK_ZL] = u1[BR_Z1];
  fb[BK_Q0Q3] = u1[BR_Q0] - u1[BR_Q3];
  fb[BK_Q1Q2] = u1[BR_Q1] + u1[BR_Q2];
  fb[BK_SINETA] = 4.0 * u1[BR_Q0] * u1[BR_Q1] - sl;
  fb[BK_ETA] = u1[BR_ETA] - u0[BR_ETA];
  fb[BK_OMEGA2] = (u0[BR_M2] - b1 * u0[BR_W2]) / b2 + u1[BR_W2];
  fb[BK_OMEGA3] = a0 / c0 - cl / al + par[BP_EPS21];
  fb[BK_SIGL] = u1[BR_SIGMA] - par[BP_L2];
  fb[BK_LTOT] = par[BP_L] + par[BP_L2] - par[BP_LTOT];
  fb[BK_PHASE] = u0[BR_W2] - par[BP_W2FIX];
  if (sym) fb[BK_F20] = u0[BR_F2];

  if (!braid_bc_all_finite(nbc, fb)) return CABLE_BRAID_BC_DOMAIN;
  if (ijac < 1) return 0;

  braid_bc_origin_du0(nbc, dbc);
  DU1(BK_XL, BR_X1) = 1.0;
  DU0(BK_XL, BR_X1) = -1.0;
  DU1(BK_YL, BR_Y1) = 1.0;
  DU1(BK_ZL, BR_Z1) = 1.0;
  DU1(BK_Q0Q3, BR_Q0) = 1.0;
  DU1(BK_Q0Q3, BR_Q3) = -1.0;
  DU1(BK_Q1Q2, BR_Q1) = 1.0;
  DU1(BK_Q1Q2, BR_Q2) = 1.0;
  DU1(BK_SINETA, BR_Q0) = 4.0 * u1[BR_Q1];
  DU1(BK_SINETA, BR_Q1) = 4.0 * u1[BR_Q0];
  DU1(BK_SINETA, BR_ETA) = -cl;
  DU1(BK_ETA, BR_ETA) = 1.0;
  DU0(BK_ETA, BR_ETA) = -1.0;
  DU0(BK_OMEGA2, BR_M2) = 1.0 / b2;
  DU0(BK_OMEGA2, BR_W2) = -b1 / b2;
  DU1(BK_OMEGA2, BR_W2) = 1.0;
  DU0(BK_OMEGA3, BR_W3) = -delta / c0;
  DU0(BK_OMEGA3, BR_ETA) = a0 * s0 / (c0 * c0);
  DU1(BK_OMEGA3, BR_W3) = -cl * delta / (al * al);
  DU1(BK_OMEGA3, BR_ETA) = sl / al;
  DU1(BK_SIGL, BR_SIGMA) = 1.0;
  DU0(BK_PHASE, BR_W2) = 1.0;
  if (sym) DU0(BK_F20, BR_F2) = 1.0;
  if (ijac < 2) return 0;

  braid_bc_origin_dpar(nbc, dbc);
  DP(BK_XL, BP_DELTA) = -1.0;
  if (sym) DP(BK_XL, BP_EPS13) = 1.0;
  DP(BK_OMEGA2, BP_B1) = -u0[BR_W2] / b2;
  DP(BK_OMEGA2, BP_B2) = -(u0[BR_M2] - b1 * u0[BR_W2]) / (b2 * b2);
  DP(BK_OMEGA3, BP_DELTA) = -u0[BR_W3] / c0 - cl * u1[BR_W3] / (al * al);
  DP(BK_OMEGA3, BP_EPS21) = 1.0;
  DP(BK_SIGL, BP_L2) = -1.0;
  DP(BK_LTOT, BP_L) = 1.0;
  DP(BK_LTOT, BP_L2) = 1.0;
  DP(BK_LTOT, BP_LTOT) = -1.0;
  DP(BK_PHASE, BP_W2FIX) = -1.0;
  return 0;
}

int braid_knot_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                    const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)icp; (void)params;
  return knot_conditions(ndim, par, nbc, 0, u0, u1, ijac, fb, dbc);
}

int braid_knot_sym_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                        const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)icp; (void)params;
  return knot_conditions(ndim, par, nbc, 1, u0, u1, ijac, fb, dbc);
}
