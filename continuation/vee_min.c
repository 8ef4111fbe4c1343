/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Safeguarded successive parabolic interpolation (vee_min.h).
 *
 * Why not GSL's Brent minimiser, which cont_special.c used before: Brent
 * starts with golden-section steps (its parabolic step needs a step two
 * iterations old to compare with) and accepts a parabolic step only when it
 * is less than half that older step.  On the squared singular value, which is
 * a parabola to first order, the first vertex is already the minimum to the
 * model's accuracy, yet Brent needed 12-26 evaluations per dip of the (7,2)
 * knot's flat branch (each a Newton correction and a factorisation), most of
 * them to shrink its bracket below the tolerance.  Here the vertex is taken
 * as soon as it is inside the bracket, and the iteration stops when the next
 * vertex lies within tol of the best point: for a parabola that is after one
 * evaluation.  The golden-section fallback keeps the bracket shrinking when
 * the function is not parabolic (two zeros close together, noise). */
#include "vee_min.h"

#include <math.h>

/* 1 - 1/phi: the golden-section fraction of the larger part of the bracket */
#define VEE_GOLDEN 0.3819660112501051
/* a bracket that did not shrink below this fraction of its length two steps
 * earlier gets a golden-section step */
#define VEE_SHRINK 0.5

/* Vertex of the parabola through (a, ga), (x, gx), (b, gb), a < x < b;
 * NAN when the three points are collinear. */
static double parabola_vertex(double a, double ga, double x, double gx, double b, double gb)
{
  double r = (x - a) * (gx - gb), q = (x - b) * (gx - ga);
  double p = (x - a) * r - (x - b) * q;
  double den = 2.0 * (r - q);
  if (den == 0.0) return (double)NAN;
  return x - p / den;
}

/* The two evaluated points with the smallest g other than the best point
 * (index best), into *i1, *i2. */
static void next_best(const double *gs, int n, int best, int *i1, int *i2)
{
  *i1 = *i2 = -1;
  for (int k = 0; k < n; k++) {
    if (k == best) continue;
    if (*i1 < 0 || gs[k] < gs[*i1]) {
      *i2 = *i1;
      *i1 = k;
    } else if (*i2 < 0 || gs[k] < gs[*i2]) {
      *i2 = k;
    }
  }
}

int vee_min(vee_min_fn g, void *ctx, double lo, double ga, double mid, double gm, double hi, double gb, double tol,
            int maxeval, vee_min_result *res)
{
  double a = lo, x = mid, b = hi, gx = gm;
  res->s = mid;
  res->g = gm;
  res->evals = 0;
  res->last_is_best = 0;
  if (!(a < x && x < b && gx <= ga && gx <= gb && tol > 0.0 && maxeval >= 0)) return -1;
  /* every point evaluated, for the parabola through the three best: the
     bracket's ends can be far outside the region where g is parabolic (the
     whole step, while sigma_1 is linear only near its zero), and a parabola
     through a stale far end converges only linearly */
  if (maxeval > VEE_MIN_MAXEVAL) maxeval = VEE_MIN_MAXEVAL;
  int n = 3, best = 1, nfail = 0;
  double fails[VEE_MIN_MAXEVAL]; /* the points where g failed */
  double ss[VEE_MIN_MAXEVAL + 3], gs[VEE_MIN_MAXEVAL + 3];
  ss[0] = a, gs[0] = ga, ss[1] = x, gs[1] = gx, ss[2] = b, gs[2] = gb;
  double len1 = b - a, len2 = b - a; /* the bracket's lengths one and two evaluations ago */
  while (b - a > 2.0 * tol) {
    int i1, i2;
    next_best(gs, n, best, &i1, &i2);
    /* the three points in ascending order (parabola_vertex's argument order) */
    double t[3] = {ss[i1], x, ss[i2]}, h[3] = {gs[i1], gx, gs[i2]};
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2 - i; j++)
        if (t[j] > t[j + 1]) {
          double tt = t[j], hh = h[j];
          t[j] = t[j + 1], h[j] = h[j + 1], t[j + 1] = tt, h[j + 1] = hh;
        }
    double u = parabola_vertex(t[0], h[0], t[1], h[1], t[2], h[2]);
    if (isfinite(u) && fabs(u - x) < tol) break; /* the model's minimum is the best point */
    int near_fail = 0;
    for (int k = 0; k < nfail; k++) near_fail |= isfinite(u) && fabs(u - fails[k]) < tol;
    if (near_fail) return 2; /* the minimum lies where g cannot be evaluated: the best point is the closest */
    int shrinking = res->evals < 2 || (b - a) <= VEE_SHRINK * len2;
    if (!(isfinite(u) && u > a + tol && u < b - tol && shrinking))
      u = (x - a > b - x) ? x - VEE_GOLDEN * (x - a) : x + VEE_GOLDEN * (b - x);
    if (res->evals >= maxeval) return 1;
    double gu = g(u, ctx);
    res->evals++;
    if (!isfinite(gu)) {
      res->last_is_best = 0; /* the failed call may have left its side effects */
      /* g fails near a singular point: remember where, and try the points
         4 tol, 16 tol, ... from it towards the best point, then halfway */
      if (nfail < VEE_MIN_MAXEVAL) fails[nfail++] = u;
      double uf = u, dir = x > u ? 1.0 : -1.0;
      for (double d = 4.0 * tol; !isfinite(gu); d *= 4.0) {
        if (res->evals >= maxeval) return 1;
        u = d < 0.5 * fabs(x - uf) ? uf + dir * d : 0.5 * (uf + x);
        gu = g(u, ctx);
        res->evals++;
        if (!isfinite(gu) && nfail < VEE_MIN_MAXEVAL) fails[nfail++] = u;
        if (!isfinite(gu) && !(d < 0.5 * fabs(x - uf))) return 2; /* not even halfway: give up */
      }
    }
    ss[n] = u;
    gs[n] = gu;
    n++;
    len2 = len1;
    len1 = b - a;
    /* the bracket around the best point (the parabola takes its points
       from ss, gs) */
    if (gu < gx) {
      if (u < x) b = x;
      else a = x;
      x = u;
      gx = gu;
      best = n - 1;
      res->last_is_best = 1;
    } else {
      if (u < x) a = u;
      else b = u;
      res->last_is_best = 0;
    }
    res->s = x;
    res->g = gx;
  }
  return 0;
}
