/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The continuation engine: orthogonal collocation for boundary-value problems
 * (AUTO's IPS=4 class), pseudo-arclength continuation, special points,
 * branch switching.  set / step / inspect, plus a driver (cable_cont_run).
 *
 *   cable_cont *cc = cable_cont_alloc(problem, constants, &status);
 *   cable_cont_set_start(cc, NULL);          // STPNT, or a stored solution
 *   while ((status = cable_cont_step(cc)) == CABLE_SUCCESS) { inspect }
 *   cable_cont_free(cc);
 */
#ifndef CABLE_CONT_H
#define CABLE_CONT_H

#include "cable/cable_api.h"

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_output.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"

typedef struct cable_cont cable_cont;

/* Check the problem against the constants (dimensions, callbacks, ICP,
 * NTST, NCOL, step sizes, tolerances) without allocating anything.  0, or a
 * status (CABLE_ERR_NULL, CABLE_ERR_INPUT, CABLE_ERR_UNSUPPORTED;
 * CABLE_ERR_SIZE for a count beyond its array, NUZR = 100000, and
 * CABLE_ERR_RANGE for an index beyond the parameters, UZR[0].par = 999, in
 * constants filled by hand) with the reason in err (may be NULL). */
CABLE_API int cable_cont_check(const cable_problem *pb, const cable_constants *c, cable_error *err);

/* Check (as cable_cont_check) and allocate every workspace: *out a usable
 * handle, and 0; or *out NULL, nothing left allocated, and a status with
 * the reason in err (may be NULL).  The library changes no process-wide
 * setting (see cable_blas_single_thread).
 * Lifetime: the handle keeps pb and c by pointer, it copies neither; both
 * must stay alive and unchanged until cable_cont_free (as pb always had to). */
CABLE_API int cable_cont_create(const cable_problem *pb, const cable_constants *c, cable_cont **out,
                                cable_error *err);
/* The same, older form: the handle or NULL with *status (status may be
 * NULL); cable_cont_check gives the message. */
CABLE_API cable_cont *cable_cont_alloc(const cable_problem *pb, const cable_constants *c, int *status);
CABLE_API void cable_cont_free(cable_cont *cc);   /* NULL is a no-op */

/* Starting point: the problem's STPNT when start == NULL, else a stored
 * solution re-interpolated onto the constants' NTST and NCOL.  With ISW = -1
 * and a BP start, the first step goes along the bifurcating branch. */
CABLE_API int cable_cont_set_start(cable_cont *cc, const cable_solution *start);

/* The mesh for a STPNT start (call before cable_cont_set_start(cc, NULL)):
 * NTST + 1 points, 0 = mesh[0] < ... < mesh[NTST] = 1.  Without it a STPNT
 * start uses the uniform mesh.  CABLE_ERR_INPUT for a mesh that is not,
 * CABLE_ERR_STATE after cable_cont_set_start (wrong order). */
CABLE_API int cable_cont_set_mesh(cable_cont *cc, const double *mesh);

/* Compute and accept the next point (the first call converges the start).
 * CABLE_SUCCESS: a new point; > 0: the branch ended normally; < 0: error
 * (the last good point stays available). */
CABLE_API int cable_cont_step(cable_cont *cc);

/* The current (last accepted) point and solution; owned by cc.  NULL
 * before the first point (and for a NULL handle). */
CABLE_API const cable_point *cable_cont_point(const cable_cont *cc);
CABLE_API const cable_solution *cable_cont_solution(const cable_cont *cc);

/* Driver: steps until the branch ends; hands points, labelled solutions and
 * diagnostics to the sink.  first_label: the label the first stored solution
 * gets.  Returns the end status; *next_label the next free label. */
CABLE_API int cable_cont_run(cable_cont *cc, const cable_sink *sink, int ibr, int first_label,
                   int *next_label);

/* Test functions at the current point: sign of det of the extended Newton
 * matrix and its smallest singular values (0 when not computed). */
CABLE_API void cable_cont_test_functions(const cable_cont *cc, int *det_sign, double *sv1, double *sv2);

/* The branch directions at a double branch point (doc/engine.md, "Multiple
 * branch points"), computed by the first cable_cont_step of an ISW = -1
 * run from a BP: the real solutions of the algebraic bifurcation equations,
 * ordered by phi.  The unit direction is a[0] q0 + a[1] e1 + a[2] e2 (q0 the
 * known branch's tangent, e1, e2 the canonical kernel basis of BPANGLE). */
typedef struct cable_branch_dir {
  double phi;     /* degrees from e1 towards e2, in [-0.125, 179.875) */
  double a[3];    /* coefficients of q0, e1, e2 (a[0] = 0 for the cubic ABE) */
  double mu;      /* cubic ABE: the s^2 coefficient of q0 along the branch; NAN otherwise */
  double L[2];    /* L_1, L_2 at the direction (psi_i^T F_xx[q0, u]) */
  double N[2];    /* P_i (quadratic ABE) or C_i (cubic) at the direction */
  double dg;      /* |g'(phi)|: small means an ill-conditioned direction (0 for a direction
                     from a symmetry) */
  int multiplicity; /* equivalent directions under the problem's declared symmetries that this
                       entry stands for (>= 1) */
  int sym;        /* 0: from the bifurcation equations and in no declared Fix(S); k > 0: it lies
                     in Fix(S) of the problem's k-th symmetry (symmetries[k - 1]) */
  int restricted; /* 1: found by the restriction to Fix(S) (the ABE were degenerate); following
                     it runs the restricted problem */
} cable_branch_dir;

/* Copies at most max of them into out; returns their number (0 when the
 * equations have no real solution), -1 when none were computed (not a
 * double BP, or degenerate equations: cable_cont_error's note says why).
 * *order (may be NULL): 2 quadratic, 3 cubic ABE, 0 none. */
CABLE_API int cable_cont_branches(const cable_cont *cc, cable_branch_dir *out, int max, int *order);

/* The note of the current point (the switch's account at an ISW = -1 start);
 * "" when none, never NULL. */
CABLE_API const char *cable_cont_note(const cable_cont *cc);

/* A branch point computed on another branch (a stored BP solution; name,
 * e.g. "BP label 3 of branch 1", goes into the message): a branch that
 * locates a BP at the same place (free parameters, U(0), U(1) within 1e-5
 * relative) joins a known branch and ends there with CABLE_END_LOOP and a
 * message naming it (cable_cont_error).  Call before the first step; any
 * number of points.  CABLE_ERR_INPUT for a solution of another NDIM. */
CABLE_API int cable_cont_add_known_point(cable_cont *cc, const cable_solution *s, const char *name);

/* Every entry point checks its handle: NULL gives CABLE_ERR_NULL, step and
 * run before a successful set_start give CABLE_ERR_STATE. */

/* Human-readable account of the last error (never NULL). */
CABLE_API const char *cable_cont_error(const cable_cont *cc);
/* The last error as a report (doc/api.md, One error channel): its status
 * (0: none yet), the key it is about ("PAR" for a PAR override that moves a
 * branch point's parameters, "" otherwise) and the message of
 * cable_cont_error.  Returns that status; CABLE_ERR_NULL for a NULL handle
 * or report. */
CABLE_API int cable_cont_last_error(const cable_cont *cc, cable_error *out);
/* Install (fn NULL: remove) the handle's error handler: every error status
 * (< 0) that cable_cont_set_mesh, _set_start, _step or _run returns on cc is
 * first reported to fn(report, ctx), with the report cable_cont_last_error
 * gives.  0, or CABLE_ERR_NULL for a NULL handle. */
CABLE_API int cable_cont_set_error_handler(cable_cont *cc, cable_error_handler fn, void *ctx);

/* For applications: ask a threaded BLAS (OpenBLAS) for one thread.  The
 * structured solver works on blocks of a few dozen rows, where BLAS threads
 * only add hand-offs (measured: 42% of a braid run's time in sched_yield).
 * This is a process-wide setting, so the library never calls it itself; the
 * `cable` program does at start.  CABLE_BLAS_THREADS=n asks for n threads
 * instead.  Nothing happens when the BLAS has no such setter. */
CABLE_API void cable_blas_single_thread(void);

#endif
