/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "axis_passages.h"

#include <math.h>
#include <stdlib.h>

#include "braid_geometry.h"
#include "braid_state.h"
#include "cable/cable_status.h"
#include "cable_vec3.h"
#include "tube_distance.h"

/* Bisection steps on a root bracket in [0, 1]: 2^-60 is below the rounding
 * of tau itself. */
#define PASSAGE_BISECT 60
/* At the root, the two segments' closest points must lie within this
 * fraction of the longer segment: the cubic's root is exact to rounding, so
 * a real intersection leaves a residual of order 1e-12, while a near miss in
 * the coplanar position is as far apart as the curve's parts (Delta). */
#define PASSAGE_HIT_TOL 1e-6

static double triple(const double *a, const double *b, const double *c)
{
  double x[3];
  cable_vec3_cross(b, c, x);
  return cable_vec3_dot(a, x);
}

static double cubic(const double *c, double t)
{
  return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
}

static double cubic_slope(const double *c, double t)
{
  return (3 * c[3] * t + 2 * c[2]) * t + c[1];
}

/* Point k of the homotopy at tau. */
static void at(const double *a, const double *b, int k, double tau, double *p)
{
  for (int i = 0; i < 3; i++) p[i] = (1 - tau) * a[3 * k + i] + tau * b[3 * k + i];
}

/* Do segments (i, i+1) and (j, j+1) of the homotopy intersect at tau? */
static int segments_meet(const double *a, const double *b, int n, int i, int j, double tau)
{
  double p0[3], p1[3], q0[3], q1[3], e[3], w[3], d[3];
  at(a, b, i, tau, p0), at(a, b, (i + 1) % n, tau, p1);
  at(a, b, j, tau, q0), at(a, b, (j + 1) % n, tau, q1);
  cable_vec3_sub(p1, p0, e), cable_vec3_sub(q1, q0, w), cable_vec3_sub(q0, p0, d);
  double ee = cable_vec3_dot(e, e), ew = cable_vec3_dot(e, w), ww = cable_vec3_dot(w, w), ed = cable_vec3_dot(e, d), wd = cable_vec3_dot(w, d);
  double den = ee * ww - ew * ew;
  if (!(den > 1e-14 * ee * ww)) return 0; /* parallel: a tangency, not a passage */
  double s = (ww * ed - ew * wd) / den, t = (ew * ed - ee * wd) / den;
  if (s < 0 || s >= 1 || t < 0 || t >= 1) return 0;
  double gap[3];
  for (int k = 0; k < 3; k++) gap[k] = p0[k] + s * e[k] - q0[k] - t * w[k];
  return sqrt(cable_vec3_dot(gap, gap)) <= PASSAGE_HIT_TOL * sqrt(fmax(ee, ww));
}

/* The coplanarity cubic det[p1 - p0, q0 - p0, q1 - p0](tau), coefficients
 * c[0] + c[1] tau + c[2] tau^2 + c[3] tau^3. */
static void coplanarity(const double *a, const double *b, int n, int i, int j, double *c)
{
  int i1 = (i + 1) % n, j1 = (j + 1) % n;
  double e0[3], u0[3], v0[3], e1[3], u1[3], v1[3];
  for (int k = 0; k < 3; k++) {
    e0[k] = a[3 * i1 + k] - a[3 * i + k];
    u0[k] = a[3 * j + k] - a[3 * i + k];
    v0[k] = a[3 * j1 + k] - a[3 * i + k];
    e1[k] = (b[3 * i1 + k] - a[3 * i1 + k]) - (b[3 * i + k] - a[3 * i + k]);
    u1[k] = (b[3 * j + k] - a[3 * j + k]) - (b[3 * i + k] - a[3 * i + k]);
    v1[k] = (b[3 * j1 + k] - a[3 * j1 + k]) - (b[3 * i + k] - a[3 * i + k]);
  }
  c[0] = triple(e0, u0, v0);
  c[1] = triple(e1, u0, v0) + triple(e0, u1, v0) + triple(e0, u0, v1);
  c[2] = triple(e0, u1, v1) + triple(e1, u1, v0) + triple(e1, u0, v1);
  c[3] = triple(e1, u1, v1);
}

/* Roots of the cubic in [0, 1) where it changes sign, into r (at most 3). */
static int sign_change_roots(const double *c, double *r)
{
  double cut[4] = {0, 0, 0, 1};
  int nc = 1;
  /* critical points: c1 + 2 c2 t + 3 c3 t^2 = 0 */
  double qa = 3 * c[3], qb = 2 * c[2], qc = c[1];
  double crit[2];
  int ncrit = 0;
  if (qa != 0) {
    double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      double sq = sqrt(disc), q = -0.5 * (qb + copysign(sq, qb));
      if (q != 0) crit[ncrit++] = q / qa, crit[ncrit++] = qc / q;
    }
  } else if (qb != 0) {
    crit[ncrit++] = -qc / qb;
  }
  if (ncrit == 2 && crit[0] > crit[1]) {
    double t = crit[0];
    crit[0] = crit[1], crit[1] = t;
  }
  for (int k = 0; k < ncrit; k++)
    if (crit[k] > 0 && crit[k] < 1) cut[nc++] = crit[k];
  cut[nc] = 1;
  int nr = 0;
  for (int k = 0; k < nc; k++) {
    double lo = cut[k], hi = cut[k + 1], flo = cubic(c, lo), fhi = cubic(c, hi);
    /* [lo, hi) half open: a root exactly at 1 belongs to the next pair of shapes */
    if (!((flo < 0 && fhi > 0) || (flo > 0 && fhi < 0) || (flo == 0 && k == 0 && lo == 0))) continue;
    if (flo == 0) {
      r[nr++] = lo;
      continue;
    }
    for (int it = 0; it < PASSAGE_BISECT; it++) {
      double mid = 0.5 * (lo + hi), fm = cubic(c, mid);
      if ((fm < 0) == (flo < 0)) lo = mid, flo = fm;
      else hi = mid;
    }
    r[nr++] = 0.5 * (lo + hi);
  }
  return nr;
}

static void swept_box(const double *a, const double *b, int n, int i, double *lo, double *hi)
{
  int i1 = (i + 1) % n;
  for (int k = 0; k < 3; k++) {
    double v[4] = {a[3 * i + k], a[3 * i1 + k], b[3 * i + k], b[3 * i1 + k]};
    lo[k] = fmin(fmin(v[0], v[1]), fmin(v[2], v[3]));
    hi[k] = fmax(fmax(v[0], v[1]), fmax(v[2], v[3]));
  }
}

typedef struct {
  double lo;   /* the swept box's low x */
  int i;
} box_key;

static int box_key_cmp(const void *x, const void *y)
{
  const box_key *p = x, *q = y;
  return p->lo < q->lo ? -1 : (p->lo > q->lo ? 1 : p->i - q->i);
}

int curve_passages(const double *a, const double *b, const double *pos, int n, double period, double window,
                   cable_axis_passages *out)
{
  if (!a || !b || !pos || !out || n < 4 || !(window > 0) || !(period > 0)) return CABLE_ERR_INPUT;
  for (int k = 0; k < 3 * n; k++)
    if (!isfinite(a[k]) || !isfinite(b[k])) return CABLE_ERR_INPUT;
  double *box = malloc(6 * (size_t)n * sizeof *box);
  box_key *key = malloc((size_t)n * sizeof *key);
  if (!box || !key) {
    free(box);
    free(key);
    return CABLE_ERR_ALLOC;
  }
  for (int i = 0; i < n; i++) {
    swept_box(a, b, n, i, box + 6 * i, box + 6 * i + 3);
    key[i] = (box_key){box[6 * i], i};
  }
  /* sweep and prune: segments sorted by the low x of their swept boxes; the
     partners of one are those after it whose low x is below its high x (the
     pairs whose boxes overlap in x, each once), then the other axes */
  qsort(key, (size_t)n, sizeof *key, box_key_cmp);
  out->count = out->net = 0;
  out->tau_first = NAN;
  for (int p = 0; p < n; p++)
    for (int q = p + 1; q < n && key[q].lo <= box[6 * key[p].i + 3]; q++) {
      /* in index order: the coplanarity cubic's sign, hence the passage's, depends on it */
      int i = key[p].i < key[q].i ? key[p].i : key[q].i, j = key[p].i < key[q].i ? key[q].i : key[p].i;
      double sep = fabs(pos[j] - pos[i]);
      if (fmin(sep, period - sep) < window) continue;
      const double *bi = box + 6 * i, *bj = box + 6 * j;
      if (bi[1] > bj[4] || bj[1] > bi[4] || bi[2] > bj[5] || bj[2] > bi[5]) continue;
      double c[4], r[3];
      coplanarity(a, b, n, i, j, c);
      int nr = sign_change_roots(c, r);
      for (int k = 0; k < nr; k++) {
        double slope = cubic_slope(c, r[k]);
        if (slope == 0 || !segments_meet(a, b, n, i, j, r[k])) continue;
        out->count++;
        out->net += slope > 0 ? 1 : -1;
        if (!(out->tau_first <= r[k])) out->tau_first = r[k];
      }
    }
  free(box);
  free(key);
  return CABLE_SUCCESS;
}

/* The braid axis of a solution at n + 1 points uniform in t (the last one
 * closes the curve and is checked against the first). */
static int axis_samples(const cable_solution *s, int n, braid_curves *bc)
{
  int rc = braid_curves_from_solution(s, bc);
  if (rc) return rc;
  double len = 0, gap = 0;
  for (int k = 0; k < n; k++) {
    double d[3];
    cable_vec3_sub(bc->c + 3 * (k + 1), bc->c + 3 * k, d);
    len += sqrt(cable_vec3_dot(d, d));
  }
  double d[3];
  cable_vec3_sub(bc->c + 3 * n, bc->c, d);
  gap = sqrt(cable_vec3_dot(d, d));
  return gap <= TUBE_CLOSURE_TOL * len ? CABLE_SUCCESS : CABLE_ERR_INPUT;
}

int cable_braid_axis_passages(const cable_solution *a, const cable_solution *b, cable_axis_passages *out)
{
  if (!a || !b || !out) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(a);
  if (!rc) rc = braid_geometry_check(b);
  if (rc) return rc;
  double L = a->par[BP_L], delta = a->par[BP_DELTA];
  double m = ceil(AXIS_PASSAGE_SAMPLES_PER_DELTA * L / delta);
  int n = m < AXIS_PASSAGE_MIN_SAMPLES ? AXIS_PASSAGE_MIN_SAMPLES : (m > 1e6 ? 1000000 : (int)m);
  braid_curves *ca = braid_curves_alloc(n + 1), *cb = braid_curves_alloc(n + 1);
  double *pos = malloc((size_t)n * sizeof *pos);
  rc = ca && cb && pos ? CABLE_SUCCESS : CABLE_ERR_ALLOC;
  if (!rc) rc = axis_samples(a, n, ca);
  if (!rc) rc = axis_samples(b, n, cb);
  for (int k = 0; !rc && k < n; k++) pos[k] = L * k / n;
  if (!rc) rc = curve_passages(ca->c, cb->c, pos, n, L, TUBE_WINDOW_FACTOR * delta, out);
  braid_curves_free(ca);
  braid_curves_free(cb);
  free(pos);
  return rc;
}
