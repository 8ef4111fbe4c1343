/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Boundary conditions of the closed standard 2-braid (paper Sect. 12.3) in
 * AUTO's BCND form (cable_bcnd_fn), with analytic Jacobians.
 * State and parameter layout: equations/braid_state.h.  Derivation, the
 * phase condition and the unfolding parameters: doc/braid-boundary-conditions.md.
 *
 * fb[i] is always "left side - right side" of the printed condition; the row
 * order is the paper's equation order (enums below).
 *
 * Jacobian (ijac >= 1): dbc is column-major, nbc rows, and must hold
 * 2*ndim + BP_NPAR columns (the problem's npar): the u(0) and u(1) columns are
 * written when ijac >= 1, the BP_NPAR parameter columns when ijac >= 2 (every
 * one of them, so any parameter can be made free).
 *
 * Return: 0 ok; CABLE_BRAID_BC_DOMAIN (> 0, recoverable) when a condition's
 * denominator vanishes or a value is not finite; CABLE_BRAID_BC_SIZE (< 0,
 * fatal) when ndim or nbc does not match. */
#ifndef CABLE_BRAID_BC_H
#define CABLE_BRAID_BC_H

#include "braid_state.h"

#define CABLE_BRAID_BC_DOMAIN 1
#define CABLE_BRAID_BC_SIZE (-1)

/* Knot rows: (12.3.1)-(12.3.23), the phase condition, and (sym only) F2(0). */
enum braid_knot_row {
  BK_X0 = 0, BK_Y0, BK_Z0,            /* (12.3.1)-(12.3.3)  r1(0) = 0 */
  BK_Q00, BK_Q10, BK_Q20, BK_Q30,     /* (12.3.4)-(12.3.7)  q(0) = (0,-1/sqrt2,-1/sqrt2,0) */
  BK_XI10, BK_XI20,                   /* (12.3.8),(12.3.9)  xi_i(0) = 0 */
  BK_T10, BK_T20,                     /* (12.3.10),(12.3.11) T1(0) = T, T2(0) = -T */
  BK_SIG0,                            /* (12.3.12) sigma(0) = 0 */
  BK_XL, BK_YL, BK_ZL,                /* (12.3.13)-(12.3.15) r1(L) = r1(0) + Delta e_x [+ eps13] */
  BK_Q0Q3, BK_Q1Q2, BK_SINETA,        /* (12.3.16)-(12.3.18) */
  BK_ETA,                             /* (12.3.19) eta(L) = eta(0) */
  BK_OMEGA2,                          /* (12.3.20) */
  BK_OMEGA3,                          /* (12.3.21) [+ eps21] */
  BK_SIGL,                            /* (12.3.22) sigma(L) = L2 */
  BK_LTOT,                            /* (12.3.23) L + L2 = Ltot */
  BK_PHASE,                           /* omega2(0) = w2fix */
  BK_NBC,                             /* = 24 */
  BK_F20 = BK_NBC,                    /* symmetric variant: F2(0) = 0 */
  BK_SYM_NBC                          /* = 25 */
};

/* Link rows: (12.3.24)-(12.3.44), row BL_W2FIX being (12.3.42) omega2(0) = w2fix. */
enum braid_link_row {
  BL_X0 = 0, BL_Y0, BL_Z0,            /* (12.3.24)-(12.3.26) */
  BL_Q00, BL_Q10, BL_Q20, BL_Q30,     /* (12.3.27)-(12.3.30) */
  BL_XI10, BL_XI20,                   /* (12.3.31),(12.3.32) */
  BL_T10, BL_T20,                     /* (12.3.33),(12.3.34) T1(0) = T, T2(0) = -T */
  BL_SIG0,                            /* (12.3.35) */
  BL_XL, BL_YL, BL_ZL,                /* (12.3.36)-(12.3.38) r1(L) = r1(0) */
  BL_Q0Q3, BL_Q1Q2,                   /* (12.3.39),(12.3.40) */
  BL_PHI,                             /* (12.3.41) q0(L) + q1(L) = -sin(Phi/2 - pi/4) */
  BL_W2FIX,                           /* (12.3.42) */
  BL_OMEGA2,                          /* (12.3.43) */
  BL_SIGL,                            /* (12.3.44) */
  BL_NBC,                             /* = 21 */
  BL_F20 = BL_NBC,                    /* symmetric variant: F2(0) = 0 */
  BL_SYM_NBC                          /* = 22 */
};

/* What the knot and the link share (braid_bc_origin.c): the first 12 rows,
 * the conditions at s = 0.  _residual: fb rows 0..11 from u(0) and T;
 * _du0: zeroes the u(0) and u(1) columns of dbc (nbc rows) and writes those
 * rows' entries; _dpar: zeroes the BP_NPAR parameter columns and writes those
 * rows' T entries.  braid_bc_all_finite: 1 when fb[0..nbc) are all finite. */
enum { BRAID_BC_ORIGIN_NROWS = 12 };
void braid_bc_origin_residual(const double *par, const double *u0, double *fb);
void braid_bc_origin_du0(int nbc, double *dbc);
void braid_bc_origin_dpar(int nbc, double *dbc);
int braid_bc_all_finite(int nbc, const double *fb);

/* braid_knot: nbc = BK_NBC; free parameters T, L, L2, eps21. */
int braid_knot_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                    const double *u1, int ijac, double *fb, double *dbc, void *params);
/* braid_knot_sym: nbc = BK_SYM_NBC; free parameters T, L, L2, eps21, eps13. */
int braid_knot_sym_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                        const double *u1, int ijac, double *fb, double *dbc, void *params);
/* braid_link: nbc = BL_NBC; one free parameter (T, Delta or Phi). */
int braid_link_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                    const double *u1, int ijac, double *fb, double *dbc, void *params);
/* braid_link_sym: nbc = BL_SYM_NBC; braid_link + F2(0) = 0, with the unfolding
 * parameter eps13 added to (12.3.36) (doc/links.md); free parameters T, eps13. */
int braid_link_sym_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                        const double *u1, int ijac, double *fb, double *dbc, void *params);

#endif
