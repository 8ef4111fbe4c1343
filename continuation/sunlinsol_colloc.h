/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A SUNDIALS SUNLinearSolver (SUNLINEARSOLVER_DIRECT) that factors a
 * SUNMat_Colloc matrix with the structured solver abd_solver.h.
 *
 * Use with KINSOL: KINSetLinearSolver(kin, LS, A) and a Jacobian function
 * (KINSetJacFn) that fills SUNMat_Colloc_Jac(J).  Setup returns
 * SUNLS_LUFACT_FAIL (> 0, recoverable) when the matrix is exactly singular,
 * SUNLS_PACKAGE_FAIL_UNREC for a non-finite matrix or a size mismatch;
 * lastflag reports the abd_solver code of the last setup or solve. */
#ifndef CABLE_SUNLINSOL_COLLOC_H
#define CABLE_SUNLINSOL_COLLOC_H

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nvector.h>

#include "abd_solver.h"

/* y: a template vector of length n (only its length is checked); A: a
 * SUNMat_Colloc matrix, whose sizes fix the solver's.  NULL on bad input or
 * allocation failure. */
SUNLinearSolver SUNLinSol_Colloc(N_Vector y, SUNMatrix A, SUNContext ctx);

/* Sign and log|det| of the matrix of the last successful setup (sign 0 when
 * it was singular or setup has not run).  Returns 0, or SUNLS_ILL_INPUT if S
 * is not a SUNLinSol_Colloc solver. */
int SUNLinSol_Colloc_Det(SUNLinearSolver S, int *sign, double *logabs);

/* The structured solver inside S (for abd_solver_smallest_sv, growth,
 * transpose solves); NULL if S is not a SUNLinSol_Colloc solver. */
abd_solver *SUNLinSol_Colloc_Solver(SUNLinearSolver S);

/* With on != 0, every solve J x = b also solves J y = e_last (the unit
 * vector of the last equation) in the same pass over the factors
 * (abd_solver_solve_many; x is bit for bit what the plain solve gives): the
 * continuation tangent of the corrector's last matrix without another
 * solve.  0, SUNLS_MEM_FAIL (then off) or SUNLS_ILL_INPUT. */
int SUNLinSol_Colloc_SolveLastUnit(SUNLinearSolver S, int on);

/* y of the last solve when it was made with the current factorisation (the
 * last setup, successful), else NULL.  Valid until the next setup, solve or
 * SUNLinSol_Colloc_ExpectRhs. */
const double *SUNLinSol_Colloc_LastUnitSolution(SUNLinearSolver S);

/* The right-hand side b (length n) the solve after the next setup will
 * probably get: that setup factors with abd_solver_factor_prepared for b
 * (and e_last when SolveLastUnit is on), and the solve, if its b is b bit for
 * bit, skips its first stage (the same result).  0, SUNLS_MEM_FAIL or
 * SUNLS_ILL_INPUT. */
int SUNLinSol_Colloc_ExpectRhs(SUNLinearSolver S, const double *b);

#endif
