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
#define BSV_NCON 7
/* braid_ritz's `knot`: a link, a knot (braid_knot), a knot of the S0-symmetric
   formulation (braid_knot_sym: the row delta F2(0) = 0 is added, S7.3) */
enum { BSV_LINK = 0, BSV_KNOT = 1, BSV_KNOT_SYM = 2 };
/* RK4/Simpson steps per Ritz piece and per unit of degree: the integration
   error of the first variation on a degree-k piece is O((h / (BSV_STEPS k))^4)
   times the basis' fourth derivative, which grows with k; at 2 k steps the
   first variation of a mode-1 knot (NTST 30) is 2e-5 relative at degree 2,
   1.1e-4 at 4, 1.9e-3 at 7 (the spurious eigenvalues of degrees 6-7), at 4 k
   steps 6.8e-6 at degree 4 (doc/stability.md S7.2) */
#define BSV_STEPS 4
/* the Ritz degree the braid problems' callbacks use at most (a run asks for
   NCOL): above it the first variation's integration error reaches the
   eigenvalues nearest zero (S7.2) */
#define BSV_DEGREE_MAX 4     /* closure of r1 (3), of the frame (3), sigma(L) = L2 */

/* Diagnostics of one assembly (the two checks of S7). */
typedef struct braid_sv_info {
  double lambda[BSV_NCON];  /* the multipliers from dA = lambda . dc (least squares) */
  double stat_res;          /* |dA - C^T lambda| / |dA|: the first variation on the Ritz space */
  double asym;              /* max |H - H^T| / max |H|: H by differences of the first variation */
  int shift_row;            /* 1: the shift generator's orthogonality row was added */
  int f2_row;               /* 1: the row delta F2(0) = 0 was added (BSV_KNOT_SYM) */
  double f2;                /* F2(0) = lambda_r . d1(0) from the multipliers (0 on S0-symmetric knots) */
  double closure;           /* max |c| of the rebuilt configuration */
} braid_sv_info;

/* The Ritz matrices on continuous piecewise polynomials of degree `degree`
 * on sol's mesh, every interval cut into `refine` pieces, for a link (knot =
 * BSV_LINK: braid_link, braid_link_sym) or a knot (BSV_KNOT: braid_knot;
 * BSV_KNOT_SYM: braid_knot_sym, with the row delta F2(0) = 0 that removes the
 * mode branches' family, doc/stability.md S7.3b; L is one more unknown): *n = 5 nnode (+ 1) unknowns, K (n x n, the constrained Lagrangian's Hessian, symmetrised), M
 * (n x n, the L2 mass form), G (*nc x n, column-major: the 7 constraint
 * gradients, eta(1) = eta(0), the shift generator's row when it is not
 * zero, and for BSV_KNOT_SYM the F2(0) row).  The arrays are malloc'ed, the caller frees them.  info may be NULL.
 * 0, or a negative cable_status (a non-braid solution, a state outside the
 * domain, out of memory). */
int braid_ritz(const cable_solution *sol, int knot, int refine, int degree, int *n, int *nc, double **K,
               double **M, double **G, braid_sv_info *info);

#endif
