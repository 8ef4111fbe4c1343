/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The built-in braid problems (AUTO's FUNC/BCND/STPNT/PVLS for the closed
 * standard 2-braid, paper Sect. 12.3):
 *   braid_knot      NDIM 21, NBC 24, NINT 0; free T, L, L2, eps21
 *   braid_knot_sym  NDIM 21, NBC 25, NINT 0; free T, L, L2, eps21, eps13
 *                   (S0-symmetric knots: adds F2(0) = 0)
 *   braid_link      NDIM 21, NBC 21, NINT 0; one free parameter: T, Delta or Phi
 * npar = BP_NPAR; parameter and state names as in equations/braid_state.h.
 * The templates are const and have params = NULL; a runnable instance with a
 * starting solution comes from braid_problem_instance. */
#ifndef CABLE_BRAID_PROBLEMS_H
#define CABLE_BRAID_PROBLEMS_H

#include "braid_start.h"
#include "cable/cable_problem.h"

const cable_problem *braid_knot_problem(void);
const cable_problem *braid_knot_sym_problem(void);
const cable_problem *braid_link_problem(void);

/* The template called name ("braid_knot", "braid_knot_sym", "braid_link"),
 * or NULL. */
const cable_problem *braid_problem_find(const char *name);

/* *out = the template, with out->params = sp (the STPNT reads the prepared
 * starting-solution parameters; sp may be NULL when the run restarts from a
 * stored solution, and must outlive *out otherwise).  0, or
 * CABLE_ERR_NOTFOUND for an unknown name, CABLE_ERR_INPUT when out is NULL
 * or sp is given but not prepared. */
int braid_problem_instance(const char *name, const braid_start_params *sp, cable_problem *out);

/* PVLS of all braid problems, written into par[] (doc/braid-boundary-conditions.md, 6):
 *  always (cheap): F = |F|, FM = F.M, h, Ham (the Hamiltonian), at t = 0
 *    (they are first integrals); qnorm = |q(1)|^2 - 1; T1, T2 = the strand
 *    torques at t = 1 (first integrals: T and -T); err = sol->err_est when
 *    known; drift = cable_braid_first_integral_drift (the max relative spread of
 *    |F|^2, F.M, h and Ham over the mesh points; < 0 when a mesh point is
 *    outside the model's domain);
 *  only when the run prints them (sol->pvls_icp lists the slot, or is NULL):
 *    pmin (braid_contact_pressure_min), dmin (cable_braid_tube_distance_solution),
 *    Lk, Tw, Wr and Wrerr, the writhe's error estimate (braid_ribbon_compute;
 *    any one of the four computes all).
 * Returns 0; 1 (recoverable) when a requested geometric column could not be
 * computed (it is then 0); > 0 when the state at t = 0 is outside the
 * model's domain; -1 for a solution of the wrong size. */
int braid_pvls(const struct cable_solution *sol, double *par, void *params);

/* The S0 symmetry braid_knot and braid_link declare (multiplicity 0: the
 * prepared instance sets TORUS). */
extern const cable_symmetry braid_knot_s0, braid_link_s0;

#endif
