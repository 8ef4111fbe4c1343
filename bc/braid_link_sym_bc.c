/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The S0-symmetric link conditions: braid_link's (12.3.24)-(12.3.44) plus
 * F2(0) = 0, with the unfolding parameter eps13 added to the closure condition
 * (12.3.36) x1(L) = x1(0), the one that is redundant within the symmetric class.
 * Why: doc/links.md. */
#include <math.h>

#include "braid_bc.h"

/* dbc holds nbc rows and 2 ndim + BP_NPAR columns */
#define BL_DBC_COLS (2 * BR_NDIM + BP_NPAR)

int braid_link_sym_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                        const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  if (ndim != BR_NDIM || nbc != BL_SYM_NBC) return CABLE_BRAID_BC_SIZE;
  /* the 21 link rows with their own row stride, copied into the 22-row layout */
  double base[BL_NBC * BL_DBC_COLS];
  int rc = braid_link_bcnd(ndim, par, icp, BL_NBC, u0, u1, ijac, fb, base, params);
  if (rc != 0) return rc;
  fb[BL_XL] += par[BP_EPS13];
  fb[BL_F20] = u0[BR_F2];
  if (!isfinite(fb[BL_F20]) || !isfinite(fb[BL_XL])) return CABLE_BRAID_BC_DOMAIN;
  if (ijac < 1) return 0;

  const int ncols = ijac >= 2 ? BL_DBC_COLS : 2 * BR_NDIM;
  for (int j = 0; j < ncols; j++) {
    for (int i = 0; i < BL_NBC; i++) dbc[i + nbc * j] = base[i + BL_NBC * j];
    dbc[BL_F20 + nbc * j] = 0.0;
  }
  dbc[BL_F20 + nbc * BR_F2] = 1.0;
  if (ijac >= 2) dbc[BL_XL + nbc * (2 * BR_NDIM + BP_EPS13)] = 1.0;
  return 0;
}
