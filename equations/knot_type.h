/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Knot type of a closed space polygon from a generic planar projection.
 *
 * Method (doc/geometry.md has the details and the conventions):
 *  1. Projection: candidate directions on a Fibonacci lattice of the upper
 *     hemisphere; a direction is rejected when a crossing is degenerate (crossing
 *     angle, distance to a vertex or height gap below the named tolerances);
 *     the accepted direction with the fewest crossings is used, and a second one
 *     must give the same invariants.
 *  2. Alexander polynomial: crossing relations of the Fox-calculus Alexander
 *     matrix, one row and column deleted; the determinant is computed exactly:
 *     evaluated at integer points modulo several 31-bit primes (Gaussian
 *     elimination), interpolated, and lifted by the Chinese remainder theorem
 *     with a certificate (enough primes for the Hadamard bound 4^(c-1)).
 *     Normalised to Delta(t) = Delta(1/t) t^deg, Delta(1) = +1.
 *  3. Signature (for chirality): Gordon-Litherland, sigma = sign(G) - mu, with
 *     G the Goeritz matrix of a checkerboard colouring and mu the correction
 *     over the crossings of type II; both colourings are computed and must agree.
 *     Convention: sigma(right-handed trefoil) = -2 (Seifert form V + V^T), so
 *     positive (right-handed) torus knots have negative signature.
 *  4. Identification by the Alexander polynomial: unknot (1), figure-eight
 *     (-1 + 3t - t^2), torus knots T(p,q) ((t^pq - 1)(t - 1)/((t^p - 1)(t^q - 1)));
 *     handedness of a torus knot = -sign(sigma).  Knots sharing an Alexander
 *     polynomial with these (e.g. the Conway knot has Delta = 1) are reported
 *     as the listed type: the polynomial does not separate them. */
#ifndef CABLE_KNOT_TYPE_H
#define CABLE_KNOT_TYPE_H

#include "cable/cable_analysis.h"   /* cable_knot_type_result */

/* Projections with more crossings are refused (the exact determinant costs
 * O(c^4) per prime); smooth curves of the knots named here need far fewer. */
#define KNOT_TYPE_MAX_CROSSINGS 100
/* Candidate projection directions tried by knot_type_identify. */
#define KNOT_TYPE_NDIRS 24


/* Closed polygon xyz[3n] (vertex n-1 joins vertex 0), n >= 3.  Returns 0,
 * CABLE_ERR_INPUT (bad arguments, or no admissible projection: the polygon
 * (nearly) intersects itself), CABLE_ERR_NONFINITE, CABLE_ERR_ALLOC or
 * CABLE_ERR_UNSUPPORTED (too many crossings, polynomial out of range, or
 * projections that disagree). */
int knot_type_identify(const double *xyz, int n, cable_knot_type_result *out);
/* The same for one given projection direction (need not be normalised);
 * CABLE_ERR_INPUT when that projection is degenerate. */
int knot_type_identify_dir(const double *xyz, int n, const double dir[3], cable_knot_type_result *out);

/* Alexander polynomial of the torus knot T(p,q) (p, q >= 1 coprime) in the
 * normalisation above; returns its degree (p-1)(q-1), or -1 if it exceeds maxdeg. */
int knot_type_torus_alexander(int p, int q, long *coef, int maxdeg);
/* Crossing number of T(p,q): min(p(q-1), q(p-1)). */
int knot_type_torus_crossings(int p, int q);

#endif
