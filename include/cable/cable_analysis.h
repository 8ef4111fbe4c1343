/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Derived quantities of one stored braid solution, computed only when a
 * scene or `cable analyze` asks (they cost far more than a continuation step):
 * linking, twist and writhe of the contact-curve ribbon, the knot type of the
 * braid axis, contact pressures and where they change sign, tube overlap,
 * first-integral drift and the closure of the material frames. */
#ifndef CABLE_BRAID_ANALYSIS_H
#define CABLE_BRAID_ANALYSIS_H

#include "cable/cable_api.h"
#include "cable/cable_solution.h"

/* Knot type of a closed curve (the braid axis), from its Alexander polynomial
 * and signature (equations/knot_type.c). */
#define CABLE_KNOT_TYPE_NAME_MAX 32
#define CABLE_KNOT_TYPE_MAX_DEGREE 100
typedef struct cable_knot_type_result {
  char name[CABLE_KNOT_TYPE_NAME_MAX]; /* "unknot", "trefoil", "figure-eight", "torus(5,2)", ..., "unknown" */
  int torus_p, torus_q;          /* p > q >= 2 for a torus knot, else 0 */
  int handedness;                /* +1 right, -1 left, 0 amphichiral or unknown */
  int crossing_number;           /* of the identified type; -1 when unknown */
  int signature;                 /* knot signature, sigma(right-handed trefoil) = -2 */
  long determinant;              /* |Delta(-1)| */
  int alex_degree;
  long alex[CABLE_KNOT_TYPE_MAX_DEGREE + 1]; /* Delta(t) = sum_i alex[i] t^i */
  int ncross;                    /* crossings of the projection used */
  int diagram_writhe;            /* sum of the crossing signs of that projection */
  double dir[3];                 /* projection direction (viewer on the +dir side) */
  int nagree;                    /* projections that gave identical invariants */
} cable_knot_type_result;

/* Topology of a braid solution: the ribbon numbers and the knot type of the
 * braid axis (the companion knot of a cable knot or link). */
typedef struct cable_braid_topology {
  double lk, tw, wr;            /* Lk = Tw + Wr of the contact-curve ribbon (ribbon.h) */
  double wr_err;                /* error estimate of Wr (braid_ribbon.wr_err) */
  int resolved;                 /* 1: wr_err <= BRAID_RIBBON_WR_TOL; 0: Lk is not trustworthy */
  int closure;                  /* -1 knot (d1(L) = -d1(0)), +1 link (d1(L) = d1(0)), 0 neither */
  double lk_defect;             /* distance of lk from the nearest half-odd integer (knot) or integer (link) */
  cable_knot_type_result axis;        /* knot type of the contact curve */
  /* lk minus the writhe of the companion's minimal diagram, handedness x
   * crossing number for torus knots, 0 for the unknot and figure-eight: the
   * paper's "linking number" of a cable knot inside the companion's tube
   * (5.5, 6.5, 7.5, 8.5 for Figs. 12.3-12.6); NAN when the axis type is unknown. */
  double lk_in_tube;
} cable_braid_topology;

/* Overlap intervals reported (the count of all is kept). */
#define CABLE_TUBE_MAX_INTERVALS 64
typedef struct cable_tube_distance_result {
  double dmin;                  /* closest non-adjacent strand centrelines / Delta (tubes overlap if < 1) */
  int strand_a, strand_b;       /* 1 or 2 */
  double s_a, s_b;              /* braid positions (arclength s of strand 1) of that pair */
  double axis_dmin;             /* closest non-adjacent points of the contact curve / Delta */
  double axis_s_a, axis_s_b;
  int noverlap;                 /* overlap intervals found (may exceed CABLE_TUBE_MAX_INTERVALS) */
  double overlap[CABLE_TUBE_MAX_INTERVALS][2]; /* [s_lo, s_hi] where a strand tube overlaps another part */
  double overlap_length;        /* total length in s of all intervals */
  int closed;                   /* 1: the axis closes and positions are periodic */
  double axis_kappa_max;        /* max curvature of the contact curve (solution variant; NAN otherwise) */
} cable_tube_distance_result;


/* Sign changes of one strand's contact pressure stored; the count of all is
 * kept.  The paper's cable links have 12-20 (doc/links.md).  Node values can
 * show at most NTST * NCOL of them: 400 on the scenes' meshes (NTST 100,
 * NCOL 4), so every one is stored there. */
#define CABLE_BRAID_PSIGN_MAX 512
/* A sign change found between two neighbouring nodes is refined by bisection
 * on the piecewise-polynomial solution down to this width in t = s/L: far
 * below the interpolant's own accuracy (O(h^(NCOL+1)), h ~ 1e-2). */
#define CABLE_BRAID_PSIGN_TTOL 1e-12

/* Where one strand's contact pressure changes sign, in braid order. */
typedef struct cable_braid_psign {
  int n;                          /* sign changes found (only CABLE_BRAID_PSIGN_MAX are stored) */
  double s[CABLE_BRAID_PSIGN_MAX];      /* braid position: arclength s of strand 1 */
  double sigma[CABLE_BRAID_PSIGN_MAX];  /* the same points as arclength sigma of strand 2 (sigma(0) = 0) */
} cable_braid_psign;

typedef struct cable_braid_analysis {
  cable_braid_topology topo;          /* Lk, Tw, Wr, axis knot type, Lk inside the companion's tube */
  cable_tube_distance_result tube;    /* dmin (strand tubes, / Delta), axis closest approach, overlap
                                   s-intervals, max curvature of the contact curve */
  double pmin1, pmax1;          /* contact force on strand 1 per unit length of strand 1 */
  double pmin2, pmax2;          /* on strand 2 per unit length of strand 2 */
  /* Sign changes along the braid: psign1 of p1 (strand 1's balance), psign2
   * of p2 (strand 2's, computed independently).  Since p1 = sigma' p2 with
   * sigma' > 0 the two sets coincide on exact solutions; their distance is a
   * check of the solution. */
  cable_braid_psign psign1, psign2;
  double drift;                 /* max relative drift of |F|^2, F.M, h, Hamiltonian over the mesh points */
  double closure;               /* knot: xi1(0) + xi2(L) mod 2 pi; link: xi1(L) - xi1(0) mod 2 pi */
  double closure2;              /* link: xi2(L) - xi2(0) mod 2 pi; knot: unused (0) */
} cable_braid_analysis;

/* Max relative spread of the first integrals |F|^2, F.M, h and the
 * Hamiltonian over the solution's mesh points (cheap: no geometry); negative
 * when the solution is not a braid solution. */
CABLE_API double cable_braid_first_integral_drift(const cable_solution *sol);

/* Contact pressures p1, p2 (braid_pressure.h) of the solution's
 * piecewise-polynomial interpolant at t in [0, 1], and sigma there.  0, or
 * CABLE_ERR_NONFINITE at a singular state. */
CABLE_API int cable_braid_pressure_at(const cable_solution *sol, double t, double *p1, double *p2, double *sigma);

/* The geometry along a braid solution at its stored points t_k (k = 0 ..
 * NTST*NCOL): strand 1 r1, strand 2 r2 = r1 + Delta d1 and the contact curve
 * c = r1 + (Delta/2) d1 ([3 npts] each, x y z per point), the contact
 * pressures p1 (on strand 1 per unit length of strand 1), p2 (on strand 2 per
 * unit length of strand 2) and sigma, the arclength of strand 2 ([npts]
 * each).  Any output may be NULL.  0 or a cable_status (< 0) when sol is not
 * a braid solution. */
CABLE_API int cable_braid_solution_curves(const cable_solution *sol, double *r1, double *r2, double *c, double *p1,
                                    double *p2, double *sigma);

/* Where p1 and p2 change sign (out->psign1, out->psign2) and their ranges:
 * node values are scanned for sign changes (p >= 0 counts as non-negative);
 * each one is refined by bisection on cable_braid_pressure_at.  Two sign changes
 * between neighbouring nodes are not seen.  Part of cable_braid_analysis_compute. */
CABLE_API int cable_braid_pressure_signs(const cable_solution *sol, cable_braid_analysis *out);

/* 0, or a cable_status (< 0) when the solution is not a closed braid. */
CABLE_API int cable_braid_analysis_compute(const cable_solution *sol, cable_braid_analysis *out);

/* 1 when the two braid axes have the same knot type (name and handedness). */
CABLE_API int cable_braid_axis_same_type(const cable_braid_analysis *a, const cable_braid_analysis *b);

/* The knot type a branch settles into, decided from the branch alone: a[i]
 * are the analyses of its labelled solutions in branch order (NULL: not
 * analysable, skipped).  The final type is that of the last analysed
 * solution; the final stretch is the longest run of analysed solutions at
 * the end of the branch that all have it, and starts at *first (-1 when no
 * solution was analysed).  Returns the index of the stretch's first solution
 * whose tubes do not overlap (tube.dmin > 1), or -1 when it has none. */
CABLE_API int cable_braid_branch_settled(const cable_braid_analysis *const *a, int n, int *first);

/* The tube distance of a braid solution sampled at n points (0: default,
 * about two samples per Delta of length, at least 1001): dmin (closest
 * approach of non-adjacent strand parts / Delta), overlap intervals, the
 * maximum curvature of the contact curve.  0 or a cable_status. */
CABLE_API int cable_braid_tube_distance_solution(const cable_solution *sol, int n, cable_tube_distance_result *out);

/* Self-passages of the braid axis (contact curve) between two solutions a and
 * b of one branch, under the straight-line homotopy between them
 * (equations/axis_passages.h has the method). */
typedef struct cable_axis_passages {
  int count;          /* passages: segment pairs that pass through each other */
  int net;            /* the sum of their signs */
  double tau_first;   /* homotopy parameter of the first passage, NAN without one */
} cable_axis_passages;

/* Same problem, closed axes; the window is pi Delta.  0 or a cable_status
 * (not braid solutions, CABLE_ERR_ALLOC). */
CABLE_API int cable_braid_axis_passages(const cable_solution *a, const cable_solution *b, cable_axis_passages *out);

#endif
