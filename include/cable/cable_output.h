/* SPDX-License-Identifier: GPL-3.0-or-later */
/* What the continuation engine hands to its caller: one row per computed point
 * (a line of AUTO's b-file), the labelled solutions (s-file entries) and
 * diagnostics (d-file).  The engine never writes files itself. */
#ifndef CABLE_OUTPUT_H
#define CABLE_OUTPUT_H

#include "cable/cable_api.h"

#include "cable/cable_solution.h"

/* AUTO's type codes for boundary-value problems. */
enum cable_point_type {
  CABLE_TY_NONE = 0,
  CABLE_TY_BP = 6,   /* branch point */
  CABLE_TY_LP = 5,   /* fold */
  CABLE_TY_UZ = -4,  /* user zero */
  CABLE_TY_EP = 9,   /* end point */
  CABLE_TY_MX = -9,  /* abnormal end (no convergence, DSMIN reached) */
  CABLE_TY_RG = 4    /* regular output point (AUTO prints TY blank, stores 4) */
};

typedef struct cable_point {
  int ibr;              /* branch number (sign: AUTO prints negative for... not used) */
  int pt;               /* point number on the branch, 1-based; AUTO prints it negative for stable... unused for BVPs */
  int itp;              /* type code (enum cable_point_type) */
  int lab;              /* label, 0 when the point is not stored */
  int ndim, npar;
  int nicp;             /* columns printed after L2-NORM and MAX U: icp[1..nicp-1] */
  const int *icp;       /* icp[0] is the principal parameter */
  const double *par;    /* [npar] */
  double l2norm;        /* AUTO's L2-NORM of the solution (its first ndim components: all of
                           them, or an extended problem's NDM, cable_constants.ndm) */
  const double *umax;   /* [ndim] MAX U(i): the signed maximum of u_i over the stored points, as AUTO (MXUPSP) */
  double measure;       /* AUTO's principal solution measure chosen by IPLT (the b-file's second
                           column; A0 and A1 bound it): 0 L2-NORM; i in 1..NDIM MAX U(i); -i MIN U(i);
                           NDIM+i the integral of U(i); 2 NDIM+i the L2-norm of U(i) */
  /* diagnostics */
  int newton_iters;
  double ds;            /* step size that produced the point */
  double err_est;       /* discretisation-error estimate (< 0 unknown) */
  /* branch-point test functions at the point (0 when not computed) */
  int det_sign;         /* sign of det of the extended Newton matrix */
  double sv1, sv2;      /* its two smallest singular values */
  const char *note;     /* the engine's remark on this point (special-point location,
                           rejected steps) for the d-file; NULL: none */
  /* STAB=1 (doc/stability.md): the Morse index at this point */
  int stab;             /* 0: not computed; 1: stable (index 0, no zero eigenvalue);
                           -1: unstable or critical (index > 0 or a zero eigenvalue) */
  int stab_index, stab_nzero;
  double stab_sigma1;   /* the smallest eigenvalue of the second variation */
  /* What the detector found at a branch point, for programs to read (the
     note says the same for people; never parse it).  Last, so that the
     fields above keep their offsets. */
  int bp_kind;          /* enum cable_bp_kind (cable_solution.h); CABLE_BP_UNKNOWN (0): no BP, or
                           a BP read from files that do not record it */
  int bp_mult;          /* the multiplicity: singular values of the extended Newton matrix that
                           vanish at the BP (cable_bp_multiplicity); 0 when bp_kind is unknown */
} cable_point;

typedef struct cable_sink {
  void *ctx;
  /* every point the engine accepts (the caller applies NPR/IPLT choices); a
     positive return stops the run there (cable_cont_run returns
     CABLE_ERR_INTERRUPTED); a negative one is the sink's own error to report */
  int (*point)(void *ctx, const cable_point *pt);
  /* labelled solutions; sol->lab matches the point's lab */
  int (*solution)(void *ctx, const cable_point *pt, const cable_solution *sol);
  /* one line of diagnostics (no trailing newline) */
  void (*diag)(void *ctx, const char *line);
} cable_sink;

#endif
