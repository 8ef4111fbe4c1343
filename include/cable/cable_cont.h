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
#include "cable/cable_output.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"

typedef struct cable_cont cable_cont;

/* Check the problem against the constants and allocate all workspaces.
 * On failure returns NULL and sets *status (message via cable_cont_error). */
CABLE_API cable_cont *cable_cont_alloc(const cable_problem *pb, const cable_constants *c, int *status);
CABLE_API void cable_cont_free(cable_cont *cc);   /* NULL is a no-op */

/* Starting point: the problem's STPNT when start == NULL, else a stored
 * solution re-interpolated onto the constants' NTST and NCOL.  With ISW = -1
 * and a BP start, the first step goes along the bifurcating branch. */
CABLE_API int cable_cont_set_start(cable_cont *cc, const cable_solution *start);

/* The mesh for a STPNT start (call before cable_cont_set_start(cc, NULL)):
 * NTST + 1 points, 0 = mesh[0] < ... < mesh[NTST] = 1.  Without it a STPNT
 * start uses the uniform mesh.  CABLE_ERR_INPUT for a mesh that is not. */
CABLE_API int cable_cont_set_mesh(cable_cont *cc, const double *mesh);

/* Compute and accept the next point (the first call converges the start).
 * CABLE_SUCCESS: a new point; > 0: the branch ended normally; < 0: error
 * (the last good point stays available). */
CABLE_API int cable_cont_step(cable_cont *cc);

/* The current (last accepted) point and solution; owned by cc. */
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

/* Human-readable account of the last error (never NULL). */
CABLE_API const char *cable_cont_error(const cable_cont *cc);

#endif
