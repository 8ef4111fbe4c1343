/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Self-passages of a closed curve between two of its shapes: where distant
 * parts of the braid axis pass through each other between two solutions of
 * a branch (a crossing change of the companion knot, which changes Lk of the
 * ribbon by 2 and, on the way, makes the tubes overlap).
 *
 * Method (continuous collision detection of polyline edges): both shapes are
 * sampled at the same n parameter values and joined by the straight-line
 * homotopy P_k(tau) = (1 - tau) A_k + tau B_k, tau in [0, 1).  Two segments
 * can meet only where their four end points are coplanar, a cubic in tau;
 * its roots are bracketed between the critical points and bisected, and a
 * root counts as a passage when the segments really intersect there (both
 * closest-point parameters in [0, 1), half-open so that a shared vertex is
 * counted once).  Its sign is the sign of the cubic's slope at the root: the
 * direction of the crossing change.  A tangency (double root) is not a
 * passage.  Segment pairs closer than `window` along the curve are never
 * compared (a curve whose radius of curvature is at least rho cannot meet
 * itself within pi rho of arclength), and pairs whose swept bounding boxes
 * are apart are skipped (found by sweep and prune along x: O(n log n) plus
 * the pairs whose boxes overlap in x).
 *
 * The homotopy stands for the branch between the two solutions: it is
 * faithful when the shapes are close compared with the distances between
 * distant parts of the curve.  The net signed count of a homotopy is fixed
 * by its ends (it is (Lk(B) - Lk(A))/2 up to sign for the braid), so a net
 * count that disagrees with the change of Lk flags an unfaithful homotopy;
 * the unsigned count can exceed |net| when parts pass through and back. */
#ifndef CABLE_AXIS_PASSAGES_H
#define CABLE_AXIS_PASSAGES_H

#include "cable/cable_analysis.h"   /* cable_axis_passages, cable_braid_axis_passages */
#include "cable/cable_solution.h"

/* Two shapes a, b [3n] of one closed curve (point n-1 joins point 0; do not
 * repeat the first point), sampled at positions pos[n] (increasing, in
 * [0, period)) along it.  0 or CABLE_ERR_INPUT (n < 4, window or period not
 * positive, a non-finite coordinate). */
int curve_passages(const double *a, const double *b, const double *pos, int n, double period, double window,
                   cable_axis_passages *out);

/* Samples of the braid axis per Delta of length: a segment of Delta/2 keeps
 * the polyline within h^2 kappa / 8 = Delta/32 of the axis (kappa <= 1/Delta),
 * far below the distances (Delta and more) between distant parts that a
 * passage must close. */
#define AXIS_PASSAGE_SAMPLES_PER_DELTA 2
#define AXIS_PASSAGE_MIN_SAMPLES 200

#endif
