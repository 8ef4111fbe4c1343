/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Newton's method for the collocation system, run by SUNDIALS KINSOL.
 * The residual and the Newton matrix come from colloc_system; the linear
 * systems are solved by the structured condensation solver (a custom
 * SUNLinearSolver) or, as a reference, by KLU (LINSOLVER=klu).
 *
 * Convergence (AUTO's test, through KINSOL's scaled-step test): the last
 * Newton correction satisfies |dx_i| <= EPS (1 + |x_i|) for every unknown,
 * EPS = min(EPSU, EPSL), and the residual has decreased below
 * COLLOC_NEWTON_RES_ACCEPT relative to its scale; full Newton (a new
 * factorisation every iteration) for the first NWTN iterations, then the
 * factorisation of iteration NWTN is reused (the chord method, KINSOL's
 * modified Newton) up to ITNW iterations, as in AUTO: min(iterations, NWTN)
 * factorisations, plus one when the chord iterations end by the step test
 * (KINSOL re-factors before it accepts a small step made with an old
 * factorisation; AUTO does not). */
#ifndef CABLE_COLLOC_NEWTON_H
#define CABLE_COLLOC_NEWTON_H

#include "cable/cable_constants.h"
#include "colloc_system.h"

typedef struct colloc_newton colloc_newton;

colloc_newton *colloc_newton_alloc(colloc_system *sys, const cable_constants *c, int *status);
/* The same with the caller's thread team t for the structured solver (t NULL:
 * its own, of cable_threads(c) threads); t outlives the solver. */
colloc_newton *colloc_newton_alloc_team(colloc_system *sys, const cable_constants *c, struct cable_team *t,
                                        int *status);
void colloc_newton_free(colloc_newton *nw);

/* Solve F(x) = 0 starting from x (overwritten with the solution).
 * Returns CABLE_SUCCESS, CABLE_ERR_NEWTON (no convergence: x is undefined),
 * CABLE_ERR_RECOVERABLE (a callback rejected an iterate) or CABLE_ERR_CALLBACK. */
int colloc_newton_solve(colloc_newton *nw, double *x);

int colloc_newton_iterations(const colloc_newton *nw);  /* of the last solve */
int colloc_newton_setups(const colloc_newton *nw);      /* factorisations in the last solve */
double colloc_newton_residual(const colloc_newton *nw); /* max-norm of F at the last iterate */
const char *colloc_newton_message(const colloc_newton *nw);

struct abd_solver;
/* The structured factorisation KINSOL used in the last solve, and the matrix
 * it factored (at the last iterate but one): the continuation reuses it for
 * the tangent, whose system is exactly that Newton matrix.  0 when available
 * (LINSOLVER=condense, at least one iteration, and the last factorisation
 * made for the last iteration: after a chord iteration it is older), -1
 * otherwise. */
int colloc_newton_factorization(colloc_newton *nw, struct abd_solver **abd, colloc_jac **J);

/* The solution y of M y = e_last with that factorisation's matrix M, solved
 * along with the last Newton correction (SUNLinSol_Colloc_SolveLastUnit), bit
 * for bit what abd_solver_solve gives; NULL when colloc_newton_factorization
 * has none or the last solve did not use it.  Valid until the next solve. */
const double *colloc_newton_tangent_unit(colloc_newton *nw);

/* The Newton solver's matrix and structured solver, for a caller that
 * factors other matrices in the same storage between solves (the
 * continuation's tangents and test functions: one set of storage instead of
 * two).  0 with LINSOLVER=condense; -1 (nothing shared) with KLU.  Every
 * solve assembles and factors afresh, so what the caller leaves there does
 * not reach it; the caller calls colloc_newton_forget after overwriting
 * them, so that colloc_newton_factorization no longer hands out the
 * overwritten factorisation. */
int colloc_newton_storage(colloc_newton *nw, struct abd_solver **abd, colloc_jac **J);
void colloc_newton_forget(colloc_newton *nw);

#endif
