/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Branch-point continuation of a boundary-value problem (AUTO's ISW = 2 at
 * a BP, the non-generic case), with or without integral conditions:
 * doc/fold-continuation.md, "Branch-point continuation", derives it.
 *
 * For a problem with k = NBC + NINT - NDIM + 1 free parameters p1..pk,
 * integral conditions int g(u, p) dt = 0 and a new parameter q, the extended
 * problem has the unknowns (u, psi) (2 NDIM components: psi is the adjoint
 * null function), the free parameters p1..pk, q, the unfolding parameter b,
 * the multipliers psi*_1..NBC of the boundary conditions and
 * omega_1..NINT of the integral conditions, k auxiliaries d, and the conditions
 *   u'   = f(u, p) - b psi,           psi' = -f_u(u, p)^T psi + g_u^T omega,
 *   b(u(0), u(1), p) + b psi* = 0,    int g dt + b omega = 0,
 *   -psi(0) + b_{u(0)}^T psi* = 0,    psi(1) + b_{u(1)}^T psi* = 0,
 *   d_j + b_{p_j}^T psi* = 0,         int (-d_j - psi . f_{p_j} + omega . g_{p_j}) dt = 0,
 *   int |psi|^2 dt + |psi*|^2 + |omega|^2 = a   (a: 1, or the starting data's).
 * Transposed derivatives by central differences (CABLE_FOLD_FD_STEP).
 * Used like cable_fold.h: the extended problem from STPNT (the BP's u, a
 * first guess of psi: the adjoint BVP's null vector on the BP's mesh nodes,
 * trapezoidal rule, by SVD; or a point of a curve of branch points, stored). */
#ifndef CABLE_BPCONT_H
#define CABLE_BPCONT_H

#include <stddef.h>

#include "cable/cable_api.h"
#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"

/* AUTO's type codes on a curve of branch points: the point's + 10 ITPST */
#define CABLE_BPCONT_ITPST 6

typedef struct cable_bpcont cable_bpcont;

/* c: ISW = 2, ICP = [p1, ..., pk, q, printed...] (AUTO's order); start: a BP of the
 * problem's branch.  NULL with *status and msg on error (not a
 * BP, too few ICP entries). */
CABLE_API cable_bpcont *cable_bpcont_alloc(const cable_problem *pb, const cable_constants *c,
                                           const cable_solution *start, int *status, char *msg, size_t len);
/* The same, status-returning (as cable_fold_create). */
CABLE_API int cable_bpcont_create(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                                  cable_bpcont **out, cable_error *err);
CABLE_API void cable_bpcont_free(cable_bpcont *f);   /* NULL is a no-op */
CABLE_API const cable_problem *cable_bpcont_problem(const cable_bpcont *f);
CABLE_API const cable_constants *cable_bpcont_constants(const cable_bpcont *f);
/* AUTO's first run at a BP (cable_fold_starting_data's counterpart): five
 * steps along the adjoint's norm a (free in place of q, which is fixed and
 * printed) from a = CABLE_FOLD_START_NORM, ISW = -2, ILP = ISP = 0; its EP
 * (type 69) restarts the curve.  0, or CABLE_ERR_INPUT with the reason in
 * err (may be NULL). */
CABLE_API int cable_bpcont_starting_data(cable_bpcont *f, cable_error *err);
/* f's copy of its start: a curve point restarts from it as stored */
CABLE_API const cable_solution *cable_bpcont_start(const cable_bpcont *f);
/* the BP's mesh resampled to ntst intervals (as cable_fold_mesh) */
CABLE_API void cable_bpcont_mesh(const cable_bpcont *f, int ntst, double *mesh);

#endif
