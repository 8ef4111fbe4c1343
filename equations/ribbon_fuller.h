/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The writhe of the braid ribbon along a branch by updates (doc/geometry.md,
 * "Lk along a branch"): between two shapes A and B of the contact curve,
 * matched at equal braid parameter t,
 *
 *   Wr(B) = Wr(A) + F(A, B) + 2 RIBBON_PASSAGE_WR_SIGN N(A, B),
 *
 * F the Fuller integral (1/2pi) \int (T_A x T_B) . (T_A' + T_B') / (1 + T_A . T_B) dt,
 * valid while T_A . T_B > -1 everywhere, and N the signed count of the
 * axis's self-passages along the straight-line homotopy from A to B
 * (axis_passages.h).  Each costs O(n) point evaluations plus the passage
 * search, against the O(n^2) Gauss double integral of a full writhe. */
#ifndef CABLE_RIBBON_FULLER_H
#define CABLE_RIBBON_FULLER_H

#include "braid_geometry.h"
#include "cable/cable_solution.h"

/* Shared with ribbon_braid.c: the twist rate of d1 about the contact curve
 * (per unit t) and the contact curve's unit tangent and dT/d(arclength). */
double braid_point_twist_rate(const braid_point *q);
void braid_point_tangent_curvature(const braid_point *q, double T[3], double K[3]);

/* The integrand of F per unit of the common parameter: (ta x tb) . (dta + dtb)
 * / (1 + ta . tb) / (2 pi), with unit tangents ta, tb and their derivatives
 * dta, dtb with respect to that parameter. */
double ribbon_fuller_density(const double ta[3], const double dta[3], const double tb[3], const double dtb[3]);

/* Sign with which a passage counted by curve_passages (its `net`) changes the
 * writhe: Wr jumps by 2 RIBBON_PASSAGE_WR_SIGN per unit of net
 * (tests/test_ribbon_fuller.c measures it on a lifted figure eight). */
#define RIBBON_PASSAGE_WR_SIGN 1

/* Gauss-Legendre nodes per interval of the union of the two meshes. */
#define RIBBON_FULLER_GL_ORDER 8

/* Tw of the braid ribbon (as braid_ribbon_compute: Gauss-Legendre on the mesh). */
int braid_ribbon_twist(const cable_solution *sol, double *tw);
/* F(A, B) of two braid solutions of the same problem (any meshes); *min_dot
 * the smallest T_A . T_B at the quadrature nodes.  0 or a cable_status. */
int braid_writhe_change(const cable_solution *a, const cable_solution *b, double *dwr, double *min_dot);

#endif
