/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Link boundary conditions (12.3.24)-(12.3.44); (12.3.42) is omega2(0) = w2fix.
 * Derivation and the meaning of Phi: doc/braid-boundary-conditions.md. */
#include <math.h>

#include "braid_bc.h"

#define DU0(i, j) dbc[(i) + nbc * (j)]
#define DU1(i, j) dbc[(i) + nbc * (BR_NDIM + (j))]
#define DP(i, k) dbc[(i) + nbc * (2 * BR_NDIM + (k))]

static const double quarter_pi = 0.78539816339744830962;

int braid_link_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                    const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)icp; (void)params;
  if (ndim != BR_NDIM || nbc != BL_NBC) return CABLE_BRAID_BC_SIZE;

  const double phi = par[BP_PHI];
  const double cphi = cos(phi), sphi = sin(phi);
  const double arg = 0.5 * phi - quarter_pi;

  braid_bc_origin_residual(par, u0, fb);
  fb[BL_XL] = u1[BR_X1] - u0[BR_X1];
  fb[BL_YL] = u1[BR_Y1] - u0[BR_Y1];
  fb[BL_ZL] = u1[BR_Z1] - u0[BR_Z1];
  fb[BL_Q0Q3] = u1[BR_Q0] - u1[BR_Q3];
  fb[BL_Q1Q2] = u1[BR_Q1] - u1[BR_Q2];
  fb[BL_PHI] = u1[BR_Q0] + u1[BR_Q1] + sin(arg);
  fb[BL_W2FIX] = u0[BR_W2] - par[BP_W2FIX];
  fb[BL_OMEGA2] = u1[BR_W2] - u0[BR_W2] * cphi - u0[BR_W3] * sphi;
  fb[BL_SIGL] = u1[BR_SIGMA] - par[BP_L2];

  if (!braid_bc_all_finite(nbc, fb)) return CABLE_BRAID_BC_DOMAIN;
  if (ijac < 1) return 0;

  braid_bc_origin_du0(nbc, dbc);
  DU1(BL_XL, BR_X1) = 1.0;
  DU0(BL_XL, BR_X1) = -1.0;
  DU1(BL_YL, BR_Y1) = 1.0;
  DU0(BL_YL, BR_Y1) = -1.0;
  DU1(BL_ZL, BR_Z1) = 1.0;
  DU0(BL_ZL, BR_Z1) = -1.0;
  DU1(BL_Q0Q3, BR_Q0) = 1.0;
  DU1(BL_Q0Q3, BR_Q3) = -1.0;
  DU1(BL_Q1Q2, BR_Q1) = 1.0;
  DU1(BL_Q1Q2, BR_Q2) = -1.0;
  DU1(BL_PHI, BR_Q0) = 1.0;
  DU1(BL_PHI, BR_Q1) = 1.0;
  DU0(BL_W2FIX, BR_W2) = 1.0;
  DU1(BL_OMEGA2, BR_W2) = 1.0;
  DU0(BL_OMEGA2, BR_W2) = -cphi;
  DU0(BL_OMEGA2, BR_W3) = -sphi;
  DU1(BL_SIGL, BR_SIGMA) = 1.0;
  if (ijac < 2) return 0;

  braid_bc_origin_dpar(nbc, dbc);
  DP(BL_PHI, BP_PHI) = 0.5 * cos(arg);
  DP(BL_W2FIX, BP_W2FIX) = -1.0;
  DP(BL_OMEGA2, BP_PHI) = u0[BR_W2] * sphi - u0[BR_W3] * cphi;
  DP(BL_SIGL, BP_L2) = -1.0;
  return 0;
}
