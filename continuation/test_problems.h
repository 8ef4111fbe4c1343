/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The engine's built-in test problems (selected with e=NAME like the braid):
 *   bratu     u'' + lambda e^u = 0,  u(0) = u(1) = 0;       PAR(1) = lambda
 *   bratu_int the same with the integral condition int_0^1 u dt - mu = 0 (NINT = 1):
 *             PAR(1) = lambda, PAR(2) = mu, both free
 *   elastica  theta'' + lambda sin theta = 0, theta'(0) = theta'(1) = 0;
 *             PAR(1) = lambda; STPNT: theta = 0 at lambda = 1
 *   elastica_int  the Euler column with its ends on one line: theta'' + lambda sin theta
 *             + nu cos theta = 0, theta'(0) = theta'(1) = 0, int_0^1 sin theta dt = 0;
 *             PAR(1) = lambda, PAR(2) = nu, both free; STPNT: theta = 0 at lambda = 1
 *   layer     eps u'' + u' = 0, u(0) = 0, u(1) = p;         PAR(1) = p, PAR(2) = eps
 *   stiff     u'' = k^2 u, u(0) = 1, u(1) = 2;              PAR(1) = k
 * Each has analytic Jacobians (JAC=1) and a closed-form solution or
 * bifurcation structure; tests/test_engine_bvp.c and test_engine_paths.c
 * compare the engine with them (doc/engine.md).  bratu, bratu_int, elastica and
 * elastica_int declare their variational structure (doc/stability.md). */
#ifndef CABLE_TEST_PROBLEMS_H
#define CABLE_TEST_PROBLEMS_H

#include "cable/cable_problem.h"

const cable_problem *cable_testproblem_bratu(void);
const cable_problem *cable_testproblem_bratu_int(void);
const cable_problem *cable_testproblem_elastica(void);
const cable_problem *cable_testproblem_elastica_int(void);
const cable_problem *cable_testproblem_layer(void);
const cable_problem *cable_testproblem_stiff(void);

/* Bratu's exact solution on the lower branch: u(t) = -2 ln(cosh((t-1/2) th/2) / cosh(th/4))
 * with th the smaller root of th = sqrt(2 lambda) cosh(th/4).  Returns th. */
double cable_bratu_theta(double lambda);
double cable_bratu_exact(double lambda, double th, double t);

#endif
