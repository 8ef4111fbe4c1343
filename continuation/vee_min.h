/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Minimisation of a function that is a parabola near its minimum: the square
 * of a singular value that crosses zero (sigma^2 = c^2 (s - s0)^2 + d^2 to
 * first order, exact for d = 0 and a fixed singular vector), by safeguarded
 * successive parabolic interpolation.  Used to locate the dips of the
 * smallest singular value at double branch points (cont_special.c). */
#ifndef CABLE_VEE_MIN_H
#define CABLE_VEE_MIN_H

/* the most calls of g one minimisation makes (a larger maxeval is cut to it) */
#define VEE_MIN_MAXEVAL 64

typedef double (*vee_min_fn)(double s, void *ctx);

typedef struct {
  double s;     /* the best point found */
  double g;     /* g(s) */
  int evals;    /* calls of g */
  int last_is_best; /* 1 when the last call of g was at s (its side effects are the best point's) */
} vee_min_result;

/* Minimise g on [lo, hi] from the interior point mid, with g(mid) = gm below
 * g(lo) = ga and g(hi) = gb (a bracket; -1 when it is not one).  Each step
 * takes the vertex of the parabola through the three best points evaluated; it
 * falls back to a golden-section step when the vertex is not inside the
 * bracket or the bracket has not halved in two steps.  Stops when the vertex
 * lies within tol of the best point or the bracket is shorter than 2 tol
 * (returns 0), after maxeval calls of g (returns 1), or when g cannot be
 * evaluated where the minimum is (returns 2).  A failed evaluation (NaN:
 * near a singular point a corrector may not converge) is retried at 4 tol,
 * 16 tol, ... from the failed point towards the best point, at most up to
 * halfway; a vertex within tol of a failed point ends the search.  In every
 * case res holds the best point evaluated. */
int vee_min(vee_min_fn g, void *ctx, double lo, double ga, double mid, double gm, double hi, double gb, double tol,
            int maxeval, vee_min_result *res);

#endif
