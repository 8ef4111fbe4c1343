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

/* Check (as cable_cont_check) and allocate every workspace.  Returns a
 * usable handle, or NULL with *status (status may be NULL) set and nothing
 * left allocated; cable_cont_check gives the message.
 * Lifetime: the handle keeps pb and c by pointer, it copies neither; both
 * must stay alive and unchanged until cable_cont_free (as pb always had to).  The library changes
 * no process-wide setting (see cable_blas_single_thread). */
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

/* Every entry point checks its handle: NULL gives CABLE_ERR_NULL, step and
 * run before a successful set_start give CABLE_ERR_STATE. */

/* Human-readable account of the last error (never NULL). */
CABLE_API const char *cable_cont_error(const cable_cont *cc);

/* For applications: ask a threaded BLAS (OpenBLAS) for one thread.  The
 * structured solver works on blocks of a few dozen rows, where BLAS threads
 * only add hand-offs (measured: 42% of a braid run's time in sched_yield).
 * This is a process-wide setting, so the library never calls it itself; the
 * `cable` program does at start.  CABLE_BLAS_THREADS=n asks for n threads
 * instead.  Nothing happens when the BLAS has no such setter. */
CABLE_API void cable_blas_single_thread(void);

#endif
