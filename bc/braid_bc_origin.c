/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The 12 conditions at s = 0 that the knot and the link share: (12.3.1)-(12.3.12)
 * = (12.3.24)-(12.3.35), rows 0 .. BRAID_BC_ORIGIN_NROWS-1 of both problems
 * (braid_bc.h).  Written once here; braid_knot_bc.c and braid_link_bc.c add
 * their own rows. */
#include "braid_bc.h"

#include <math.h>

static const double sqrt_half = 0.70710678118654752440;

/* The two row enums agree on these rows (the paper's order). */
_Static_assert((int)BK_X0 == 0 && (int)BL_X0 == 0 && (int)BK_SIG0 == (int)BL_SIG0 &&
                   (int)BK_SIG0 + 1 == BRAID_BC_ORIGIN_NROWS && (int)BK_Q10 == (int)BL_Q10 &&
                   (int)BK_T10 == (int)BL_T10 && (int)BK_XI10 == (int)BL_XI10,
               "knot and link rows 0..11 are the same conditions");

#define DU0(i, j) dbc[(i) + nbc * (j)]
#define DP(i, k) dbc[(i) + nbc * (2 * BR_NDIM + (k))]

void braid_bc_origin_residual(const double *par, const double *u0, double *fb)
{
  fb[BK_X0] = u0[BR_X1];
  fb[BK_Y0] = u0[BR_Y1];
  fb[BK_Z0] = u0[BR_Z1];
  fb[BK_Q00] = u0[BR_Q0];
  fb[BK_Q10] = u0[BR_Q1] + sqrt_half;
  fb[BK_Q20] = u0[BR_Q2] + sqrt_half;
  fb[BK_Q30] = u0[BR_Q3];
  fb[BK_XI10] = u0[BR_XI1];
  fb[BK_XI20] = u0[BR_XI2];
  fb[BK_T10] = u0[BR_T1] - par[BP_T];
  fb[BK_T20] = u0[BR_T2] + par[BP_T];
  fb[BK_SIG0] = u0[BR_SIGMA];
}

int braid_bc_all_finite(int nbc, const double *fb)
{
  for (int i = 0; i < nbc; i++)
    if (!isfinite(fb[i])) return 0;
  return 1;
}

void braid_bc_origin_du0(int nbc, double *dbc)
{
  for (int j = 0; j < 2 * BR_NDIM; j++)
    for (int i = 0; i < nbc; i++) dbc[i + nbc * j] = 0.0;
  DU0(BK_X0, BR_X1) = 1.0;
  DU0(BK_Y0, BR_Y1) = 1.0;
  DU0(BK_Z0, BR_Z1) = 1.0;
  DU0(BK_Q00, BR_Q0) = 1.0;
  DU0(BK_Q10, BR_Q1) = 1.0;
  DU0(BK_Q20, BR_Q2) = 1.0;
  DU0(BK_Q30, BR_Q3) = 1.0;
  DU0(BK_XI10, BR_XI1) = 1.0;
  DU0(BK_XI20, BR_XI2) = 1.0;
  DU0(BK_T10, BR_T1) = 1.0;
  DU0(BK_T20, BR_T2) = 1.0;
  DU0(BK_SIG0, BR_SIGMA) = 1.0;
}

void braid_bc_origin_dpar(int nbc, double *dbc)
{
  for (int k = 0; k < BP_NPAR; k++)
    for (int i = 0; i < nbc; i++) DP(i, k) = 0.0;
  DP(BK_T10, BP_T) = -1.0;
  DP(BK_T20, BP_T) = 1.0;
}
