/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Self-distance of tubes: the closest approach of non-adjacent parts of one or
 * more polylines (strand centrelines, braid axis), with the parts closer than
 * a given distance (overlapping tubes) marked.
 *
 * "Adjacent" is decided by a position along the rod attached to every vertex
 * (for the braid: arclength along the braid axis at that braid position):
 * two segments whose midpoint positions differ by less than `window` (modulo
 * the period of a closed axis) are neighbours and never compared.
 *
 * Method: a binary tree of bounding spheres over each polyline's consecutive
 * segments (leaves of 8), descended in pairs from the roots: a node pair is
 * dropped when all its segment pairs are neighbours or when its distance
 * bound exceeds both the best distance found and the overlap distance, and
 * the exact segment-segment distances are computed for the leaf pairs left.
 * The result is the brute-force minimum over all admissible pairs (the same
 * distance function on every pair that can matter).  Near the window edge,
 * where braids have their closest admissible pairs, the descent reaches
 * only the leaves within a sphere radius of the best distance: O(n log n)
 * for smooth curves. */
#ifndef CABLE_TUBE_DISTANCE_H
#define CABLE_TUBE_DISTANCE_H

#include "braid_geometry.h"
#include "cable/cable_analysis.h"   /* cable_tube_distance_result */

typedef struct tube_polyline {
  int n;                        /* vertices, n >= 2 (n - 1 segments) */
  const double *xyz;            /* [3n] */
  const double *pos;            /* [n] nondecreasing position along the rod */
} tube_polyline;

typedef struct tube_closest {
  double dist;                  /* INFINITY when no admissible pair exists */
  int curve_a, seg_a;           /* segment seg_a (vertices seg_a, seg_a+1) of curve_a */
  double u_a;                   /* closest point at parameter u_a in [0,1] */
  int curve_b, seg_b;
  double u_b;
} tube_closest;

typedef struct tube_workspace tube_workspace;
/* For up to nseg segments in all polylines together; NULL on failure. */
tube_workspace *tube_workspace_alloc(int nseg);
void tube_workspace_free(tube_workspace *w);          /* NULL is a no-op */

/* Closest admissible pair of segments among the ncurve polylines (pairs within
 * one polyline included).  period > 0: positions are periodic (closed rod),
 * 0: open.  window > 0 must exceed every segment's position increment
 * (CABLE_ERR_INPUT otherwise: sample more finely).  flags (may be NULL):
 * flags[k][i] is set to 1 for segment i of curve k when it lies closer than
 * `overlap` to an admissible partner, else 0. */
int tube_polylines_distance(tube_workspace *w, int ncurve, const tube_polyline *c, double period,
                            double window, double overlap, tube_closest *out,
                            unsigned char *const *flags);

/* ---- braid solutions ---- */

/* Neighbour window along the braid axis, in units of Delta.  The braid lies in
 * a tube of radius Delta about its axis.  For a curve whose radius of
 * curvature is at least rho, points closer than 2 rho in space must be at
 * least pi rho apart along the curve to belong to different parts of it
 * (Schur's comparison: chord >= 2 rho sin(l / 2 rho) for l <= pi rho).  With
 * rho = Delta for the braid (and rho = Delta/2 for a strand, whose arclength
 * is at least the axial one) a window of pi Delta separates local neighbours
 * from distinct parts.  Consequence: for a braid without distant approaches
 * dmin is set by the window edge, about pi; overlap means dmin < 1. */
#define TUBE_WINDOW_FACTOR 3.14159265358979323846
/* Axis treated as closed when |c(L) - c(0)| <= this times its length. */
#define TUBE_CLOSURE_TOL 1e-3


/* Uses braid_curves' samples (bc->n points; their spacing must be below
 * pi Delta).  Returns 0, CABLE_ERR_INPUT, CABLE_ERR_NONFINITE or CABLE_ERR_ALLOC. */
int braid_tube_distance(const braid_curves *bc, cable_tube_distance_result *out);

/* Samples per Delta of strand length for the solution variant.  Chords of
 * the sampled strands deviate from the curves by h^2 kappa / 8; strands wound
 * about each other have kappa <= 2/Delta, so h = Delta/10 bounds the error
 * of dmin by Delta/400 (0.25 %). */
#define TUBE_SAMPLES_PER_DELTA 10
/* cable_braid_tube_distance_solution: in cable/cable_analysis.h (public). */
/* Its dmin alone (the same samples, the same value), without the overlap
 * intervals, the axis's self-distance and its curvature: PVLS's column. */
int braid_tube_dmin_solution(const cable_solution *sol, double *dmin);

/* Along a branch sampled at n points with torque t[i] and tube distance d[i]
 * (in units of Delta): the stretches where d > 1 (tubes apart), as [from, to]
 * pairs in branch order into iv (at most max of them).  An end between two
 * samples is the linear interpolant's crossing of d = 1; an end of the branch
 * inside a stretch closes it at that sample.  Returns the number of stretches
 * (it may exceed max; only max are stored). */
int tube_free_intervals(const double *t, const double *d, int n, double (*iv)[2], int max);

#endif
