/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Fold continuation (AUTO's ISW = 2 at an LP of a boundary-value problem):
 * the extended problem whose solutions are the folds of a problem's branches,
 * followed in one more parameter.  doc/fold-continuation.md derives it.
 *
 * For a problem with k = NBC + NINT - NDIM + 1 free parameters p1..pk (p1 the
 * principal one, the fold is with respect to it) and a new parameter q, the
 * extended problem has the unknowns (u, v) (2 NDIM components), the free
 * parameters p1, q, p2..pk and the null vector's parameter components
 * w2..wk (in parameter slots after the problem's, then the norm N), and the conditions
 *   u' = f(u, p),                         b(u(0), u(1), p) = 0,  int g(u, p) = 0,
 *   v' = D f(u, p)[v, w],                 D b[v(0), v(1), w] = 0, int D g[v, w] = 0,
 *   int |v|^2 dt + |w|^2 = N   (N = PAR(NPAR + k): 1, or the starting data's),
 * where D is the derivative in the direction (v, 0, w2..wk) of (u, p1, p2..pk)
 * (central differences along that direction, step CABLE_FOLD_FD_STEP).  So
 * NDIM' = 2 NDIM, NBC' = 2 NBC, NINT' = 2 NINT + 1 and NFPR' = 2k.
 *
 *   cable_fold *f; cable_cont *cc;
 *   st = cable_fold_create(pb, &c, lp_solution, &f, &err);        // the reason in err
 *   st = cable_cont_create(cable_fold_problem(f), cable_fold_constants(f), &cc, &err);
 *   cable_fold_mesh(f, NTST, mesh); cable_cont_set_mesh(cc, mesh);   // the LP's mesh
 *   cable_cont_set_start(cc, NULL);   // STPNT: the LP solution and its null vector
 *   ...
 *   cable_cont_free(cc); cable_fold_free(f);
 */
#ifndef CABLE_FOLD_H
#define CABLE_FOLD_H

#include <stddef.h>

#include "cable/cable_api.h"
#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"

/* Central-difference step of the directional derivatives, relative to
 * 1 + max|u| over the unit direction: eps^(1/3) balances truncation
 * O(h^2) and round-off O(eps/h) (as COLLOC_FD_REL_STEP). */
#define CABLE_FOLD_FD_STEP 6.0e-6
/* Largest NDIM and NPAR of a problem whose folds can be followed (the
 * callbacks work in stack buffers of these sizes: no allocation, no shared
 * mutable state). */
#define CABLE_FOLD_MAXDIM 256
#define CABLE_FOLD_MAXPAR 512
/* AUTO's type codes on a fold curve of a BVP: the point's type plus
 * 10 * ITPST, ITPST = 5 (the LP's code; auto-07p 0.9.2 writes 59 for the
 * end point, 54 for regular labels) */
#define CABLE_FOLD_ITPST 5

/* AUTO's number of steps of the run that generates a fold curve's starting
 * data (its NMX = 5 for ISW = 2 at an LP of a BVP) */
#define CABLE_FOLD_START_STEPS 5
/* N at the start of that run: AUTO's starts at N = 0 (the null vector 0,
 * where the extended system is singular); cable's at a small N, so that
 * the steps grow the null vector from almost nothing as AUTO's do */
#define CABLE_FOLD_START_NORM 1e-4

typedef struct cable_fold cable_fold;

/* c: the fold run's constants, ISW = 2, ICP = [p1, ..., pk, q, printed
 * ...] (the problem's k free parameters, then the new one q: AUTO's order).  start:
 * an LP of the problem's branch (its stored direction is the null vector),
 * or a point of a fold curve of the same problem (NDIM = 2 NDIM).  NULL
 * with *status and msg on error (CABLE_ERR_NULL for a NULL problem or
 * constants; status and msg may be NULL: not wanted). */
CABLE_API cable_fold *cable_fold_alloc(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                                       int *status, char *msg, size_t len);
/* The same, status-returning: *out the fold problem and 0, or *out NULL
 * and the status with its message in err (may be NULL); CABLE_ERR_NULL for
 * a NULL problem, constants, start or out. */
CABLE_API int cable_fold_create(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                                cable_fold **out, cable_error *err);
CABLE_API void cable_fold_free(cable_fold *f);   /* NULL is a no-op */

/* The extended problem and the constants of its run (ICP with the w slots
 * after p1..pk, q; NDIM, NBC, NINT, NPAR of the extended problem). */
/* The start's mesh density resampled to ntst intervals (as a restart keeps
 * it, cont_mesh.c) into mesh[0..ntst]: the fold run's mesh, so that the
 * fold curve starts on the discrete problem the LP was located on. */
CABLE_API void cable_fold_mesh(const cable_fold *f, int ntst, double *mesh);   /* NULL f or mesh: nothing */

/* AUTO's run at an LP (ISW = 2, the session's dispatch): switch f, made from
 * an LP, to the run that generates the fold curve's starting data: the LP and
 * its null vector followed along the null vector's norm N (PAR(NPAR + k),
 * free in place of q, which is fixed and printed) for CABLE_FOLD_START_STEPS
 * steps, ISW = -2, ILP = ISP = 0; its last point is the EP (type 59) a fold
 * curve restarts from.  Without this call the run from the LP follows the
 * fold curve itself with N = 1.  0, or CABLE_ERR_INPUT with the reason in
 * err (may be NULL). */
CABLE_API int cable_fold_starting_data(cable_fold *f, cable_error *err);
/* f's copy of its start (a fold-curve point with the norm slot N filled in:
 * 1 for a point stored without it), to restart the curve from. */
CABLE_API const cable_solution *cable_fold_start(const cable_fold *f);

/* NULL for a NULL handle. */
CABLE_API const cable_problem *cable_fold_problem(const cable_fold *f);
CABLE_API const cable_constants *cable_fold_constants(const cable_fold *f);

#endif
