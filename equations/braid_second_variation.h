/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The second variation of the braid's action (links and knots) with its
 * closure constraints kept to first order (doc/stability.md S7): the Ritz
 * matrices in the strain variables (eta, omega2, omega3, xi1', xi2', and the
 * length L of strand 1 for a knot), for the Morse index
 * (continuation/stability.c solves the eigenproblem). */
#ifndef CABLE_BRAID_SECOND_VARIATION_H
#define CABLE_BRAID_SECOND_VARIATION_H

#include "cable/cable_solution.h"

#define BSV_NFIELD 5   /* eta, omega2, omega3, xi1', xi2' */
#define BSV_NCON 7     /* closure of r1 (3), of the frame (3), sigma(L) = L2 */

/* Diagnostics of one assembly (the two checks of S7). */
typedef struct braid_sv_info {
  double lambda[BSV_NCON];  /* the multipliers from dA = lambda . dc (least squares) */
  double stat_res;          /* |dA - C^T lambda| / |dA|: the first variation on the Ritz space */
  double asym;              /* max |H - H^T| / max |H|: H by differences of the first variation */
  int shift_row;            /* 1: the shift generator's orthogonality row was added */
  double closure;           /* max |c| of the rebuilt configuration */
} braid_sv_info;

/* The Ritz matrices on continuous piecewise polynomials of degree `degree`
 * on sol's mesh, every interval cut into `refine` pieces, for a link (knot =
 * 0: braid_link, braid_link_sym) or a knot (knot = 1: braid_knot,
 * braid_knot_sym; L is one more unknown): *n = 5 nnode (+ 1) unknowns, K (n x n, the constrained Lagrangian's Hessian, symmetrised), M
 * (n x n, the L2 mass form), G (*nc x n, column-major: the 7 constraint
 * gradients, eta(1) = eta(0), and the shift generator's row when it is not
 * zero; links only).  The arrays are malloc'ed, the caller frees them.  info may be NULL.
 * 0, or a negative cable_status (a non-braid solution, a state outside the
 * domain, out of memory). */
int braid_ritz(const cable_solution *sol, int knot, int refine, int degree, int *n, int *nc, double **K,
               double **M, double **G, braid_sv_info *info);

#endif
