/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A stored solution: what AUTO writes to an s-file for one label.
 * Values are kept at the NTST*NCOL+1 points AUTO stores: the mesh points and
 * NCOL-1 equally spaced nodes inside each mesh interval. */
#ifndef CABLE_SOLUTION_H
#define CABLE_SOLUTION_H

#include "cable/cable_api.h"
#include "cable/cable_error.h"

/* How the branch-point detector found a BP (cont_special.c): the
 * determinant changed sign (one singular value crossed zero: simple), or
 * sigma_1 dipped to zero without a sign change, with sigma_2 vanishing
 * too (double) or not (a pair of simple BPs in one step). */
enum cable_bp_kind { CABLE_BP_UNKNOWN = 0, CABLE_BP_SIMPLE = 1, CABLE_BP_DOUBLE = 2, CABLE_BP_PAIR = 3 };

/* "simple", "double", "pair"; "" for CABLE_BP_UNKNOWN or another value (the
 * word the d-file's BP record and the Python package use). */
CABLE_API const char *cable_bp_kind_name(int kind);
/* The kind of a name cable_bp_kind_name gives; CABLE_BP_UNKNOWN for any
 * other (and NULL). */
CABLE_API int cable_bp_kind_code(const char *name);
/* The multiplicity of a BP of that kind: the singular values that vanish
 * there, 1 for a simple BP and for each of a pair, 2 for a double one; 0
 * for CABLE_BP_UNKNOWN. */
CABLE_API int cable_bp_multiplicity(int kind);

typedef struct cable_solution {
  int ndim, ntst, ncol;
  int npar;        /* length of par[] (AUTO's NPAR) */
  int nfpr;        /* number of free parameters */
  int ibr;         /* branch number */
  int ntot;        /* point number on the branch */
  int itp;         /* AUTO type code (BP 6, LP 5, UZ -4, EP 9, MX -9; +10*k for regular) */
  int lab;         /* label */
  int isw;
  double *t;       /* [ntst*ncol+1] in [0,1]; t[j*ncol] are the mesh points */
  double *u;       /* [(ntst*ncol+1)*ndim], u[k*ndim + i] = u_i(t[k]) */
  double *udot;    /* tangent, same layout; NULL when unknown */
  double *par;     /* [npar] */
  int *icp;        /* [nfpr] free-parameter indices (0-based) */
  double *pardot;  /* [nfpr] tangent components of the free parameters */
  double err_est;  /* estimated max-norm discretisation error (< 0: unknown) */
  /* While the engine calls PVLS: the run's ICP list (free and printed
   * parameters, 0-based), so that PVLS can skip costly columns nobody asked
   * for.  Borrowed from the engine, never copied; NULL (alloc, clone, files)
   * means "unknown": PVLS then computes everything. */
  const int *pvls_icp;
  int pvls_nicp;
  double pvls_ds;  /* while the engine calls PVLS: the step that reached this point (AUTO's
                      GETP('STP')); 0 otherwise */
  double pvls_fld; /* while the engine calls PVLS: the fold test function at this point, the
                      principal parameter's component of the unit tangent (AUTO's GETP('FLD')) */
  double pvls_bif; /* ... and the branch-point test function, the smallest singular value of the
                      extended Newton matrix signed by its determinant (GETP('BIF')); 0 when
                      neither ISP nor NSV asks for it */
  /* last, so that the fields above keep their offsets for plug-ins built before it */
  int bp_kind;     /* a BP's kind as the detector found it (enum cable_bp_kind); 0: not a BP or
                      unknown (the s-file does not store it) */
} cable_solution;

/* Every field zeroed except the sizes; arrays allocated.  NULL when a size
 * is out of range (ndim, ntst, ncol, npar < 1 or nfpr < 0) or memory ran
 * out; nothing is left allocated then. */
CABLE_API cable_solution *cable_solution_alloc(int ndim, int ntst, int ncol, int npar, int nfpr);
/* The same, status-returning: *out the solution and 0, or *out NULL and
 * CABLE_ERR_RANGE (a size out of range, named in err), CABLE_ERR_ALLOC or
 * CABLE_ERR_NULL (out NULL); err may be NULL. */
CABLE_API int cable_solution_create(int ndim, int ntst, int ncol, int npar, int nfpr, cable_solution **out,
                                    cable_error *err);
CABLE_API void cable_solution_free(cable_solution *s);            /* NULL is a no-op */
/* Copies the values of src into dst, which must have the same sizes.
 * CABLE_SUCCESS, CABLE_ERR_NULL (a NULL solution or array) or
 * CABLE_ERR_SIZE (the sizes differ; dst is unchanged). */
CABLE_API int cable_solution_copy(cable_solution *dst, const cable_solution *src);
/* AUTO's principal solution measure for IPLT (doc/constants.md): 0 the
 * L2-NORM of the whole solution (passed in as l2); i in 1..NDIM the maximum
 * of U(i); -i its minimum; NDIM+i the integral of U(i); 2 NDIM+i the L2-norm
 * of U(i), over the stored points with the collocation node quadrature.  An
 * IPLT outside -NDIM..3 NDIM gives l2. */
CABLE_API double cable_solution_measure(const cable_solution *s, int iplt, double l2);
/* A new solution equal to src; NULL for NULL or when memory ran out. */
CABLE_API cable_solution *cable_solution_clone(const cable_solution *src);

/* Number of stored points, ntst*ncol + 1 (0 for NULL). */
static inline int cable_solution_npts(const cable_solution *s) { return s ? s->ntst * s->ncol + 1 : 0; }

#endif
