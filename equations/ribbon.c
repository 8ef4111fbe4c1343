/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "ribbon.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_math.h>

#include "cable/cable_status.h"
#include "cable_vec3.h"

static int all_finite(int n, const double *x)
{
  for (int i = 0; i < n; i++)
    if (!isfinite(x[i])) return 0;
  return 1;
}

/* Gauss kernel (a' x b') . (a - b) / |a - b|^3 for one pair of points. */
static inline double gauss_kernel(const double *ra, const double *ta, const double *rb, const double *tb)
{
  double x = ra[0] - rb[0], y = ra[1] - rb[1], z = ra[2] - rb[2];
  double cx = ta[1] * tb[2] - ta[2] * tb[1];
  double cy = ta[2] * tb[0] - ta[0] * tb[2];
  double cz = ta[0] * tb[1] - ta[1] * tb[0];
  double d2 = x * x + y * y + z * z;
  return (cx * x + cy * y + cz * z) / (d2 * sqrt(d2));
}

int ribbon_writhe_samples(int n, double period, const double *r, const double *dr, double *wr,
                          double *err)
{
  if (!r || !dr || !wr || n < RIBBON_MIN_SAMPLES || n % 8 != 0 || !(period > 0))
    return CABLE_ERR_INPUT;
  if (!all_finite(3 * n, r) || !all_finite(3 * n, dr)) return CABLE_ERR_NONFINITE;
  /* Sum over the lag j = 1..n/2 of S_j = sum_i f(u_i, u_i + j h); the
   * integrand is symmetric, so lags j and n - j agree and lag 0 is zero.
   * a1, a2, a4: outer trapezoidal sums with lag steps 1, 2, 4. */
  int half = n / 2;
  double a1 = 0.0, a2 = 0.0, a4 = 0.0;
  for (int j = 1; j <= half; j++) {
    /* the pairs (i, i + j) without the wrap, then (i, i + j - n): two loops
     * without a branch, each summed in two interleaved partial sums (the
     * kernel's square root and division are the cost; ribbon.o is built
     * with -fno-math-errno, so that the square root is one instruction) */
    double s0 = 0.0, s1 = 0.0;
    int i = 0;
    for (; i + 1 < n - j; i += 2) {
      s0 += gauss_kernel(r + 3 * i, dr + 3 * i, r + 3 * (i + j), dr + 3 * (i + j));
      s1 += gauss_kernel(r + 3 * (i + 1), dr + 3 * (i + 1), r + 3 * (i + 1 + j), dr + 3 * (i + 1 + j));
    }
    for (; i < n - j; i++) s0 += gauss_kernel(r + 3 * i, dr + 3 * i, r + 3 * (i + j), dr + 3 * (i + j));
    for (; i + 1 < n; i += 2) {
      s0 += gauss_kernel(r + 3 * i, dr + 3 * i, r + 3 * (i + j - n), dr + 3 * (i + j - n));
      s1 += gauss_kernel(r + 3 * (i + 1), dr + 3 * (i + 1), r + 3 * (i + 1 + j - n), dr + 3 * (i + 1 + j - n));
    }
    for (; i < n; i++) s0 += gauss_kernel(r + 3 * i, dr + 3 * i, r + 3 * (i + j - n), dr + 3 * (i + j - n));
    double s = s0 + s1;
    double wgt = j < half ? 2.0 : 1.0;
    a1 += wgt * s;
    if (j % 2 == 0) a2 += wgt * s;
    if (j % 4 == 0) a4 += wgt * s;
  }
  if (!isfinite(a1)) return CABLE_ERR_NONFINITE;   /* a self-intersecting curve */
  double h = period / n;
  double t1 = h * h * a1, t2 = 2.0 * h * h * a2, t4 = 4.0 * h * h * a4;
  double r1 = (4.0 * t1 - t2) / 3.0, r2 = (4.0 * t2 - t4) / 3.0;
  double rr = (16.0 * r1 - r2) / 15.0;
  *wr = rr / (4.0 * M_PI);
  if (err) *err = fabs(rr - r1) / (4.0 * M_PI);
  return CABLE_SUCCESS;
}

int ribbon_twist_samples(int n, double period, const double *dr, const double *d,
                         const double *dd, double *tw)
{
  if (!dr || !d || !dd || !tw || n < 1 || !(period > 0)) return CABLE_ERR_INPUT;
  if (!all_finite(3 * n, dr) || !all_finite(3 * n, d) || !all_finite(3 * n, dd))
    return CABLE_ERR_NONFINITE;
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    const double *a = dr + 3 * i, *b = d + 3 * i, *c = dd + 3 * i;
    double na = sqrt(cable_vec3_dot(a, a)), nb2 = cable_vec3_dot(b, b);
    if (!(na > 0) || !(nb2 > 0)) return CABLE_ERR_INPUT;
    if (fabs(cable_vec3_dot(a, b)) > RIBBON_PERP_TOL * na * sqrt(nb2)) return CABLE_ERR_INPUT;
    double x[3];
    cable_vec3_cross(b, c, x);
    sum += cable_vec3_dot(a, x) / (na * nb2);
  }
  *tw = sum * (period / n) / (2.0 * M_PI);
  return CABLE_SUCCESS;
}

int ribbon_linking_samples(int n1, double period1, const double *r1, const double *dr1, int n2,
                           double period2, const double *r2, const double *dr2, double *lk)
{
  if (!r1 || !dr1 || !r2 || !dr2 || !lk || n1 < 1 || n2 < 1 || !(period1 > 0) || !(period2 > 0))
    return CABLE_ERR_INPUT;
  if (!all_finite(3 * n1, r1) || !all_finite(3 * n1, dr1) || !all_finite(3 * n2, r2) ||
      !all_finite(3 * n2, dr2))
    return CABLE_ERR_NONFINITE;
  double sum = 0.0;
  for (int i = 0; i < n1; i++) {
    double s = 0.0;
    for (int k = 0; k < n2; k++) s += gauss_kernel(r1 + 3 * i, dr1 + 3 * i, r2 + 3 * k, dr2 + 3 * k);
    sum += s;
  }
  if (!isfinite(sum)) return CABLE_ERR_NONFINITE;  /* the curves intersect */
  *lk = sum * (period1 / n1) * (period2 / n2) / (4.0 * M_PI);
  return CABLE_SUCCESS;
}

/* ---- callback interface ---- */

struct ribbon_workspace {
  int n;
  double *r, *dr, *d, *dd;      /* [3n] samples */
  double *pr, *pdr;             /* [6n] push-off (twice round when antiperiodic) */
};

ribbon_workspace *ribbon_workspace_alloc(int n)
{
  if (n < RIBBON_MIN_SAMPLES || n % 8 != 0) return NULL;
  ribbon_workspace *w = calloc(1, sizeof *w);
  if (!w) return NULL;
  w->n = n;
  size_t m = 3 * (size_t)n;
  w->r = malloc(m * sizeof *w->r);
  w->dr = malloc(m * sizeof *w->dr);
  w->d = malloc(m * sizeof *w->d);
  w->dd = malloc(m * sizeof *w->dd);
  w->pr = malloc(2 * m * sizeof *w->pr);
  w->pdr = malloc(2 * m * sizeof *w->pdr);
  if (!w->r || !w->dr || !w->d || !w->dd || !w->pr || !w->pdr) {
    ribbon_workspace_free(w);
    return NULL;
  }
  return w;
}

void ribbon_workspace_free(ribbon_workspace *w)
{
  if (!w) return;
  free(w->r); free(w->dr); free(w->d); free(w->dd); free(w->pr); free(w->pdr);
  free(w);
}

static int sample_curve(ribbon_workspace *w, const ribbon_curve *c, int want_normal)
{
  if (!w || !c || !c->eval || !(c->period > 0)) return CABLE_ERR_INPUT;
  for (int i = 0; i < w->n; i++) {
    double u = c->period * i / w->n;
    int rc = c->eval(u, w->r + 3 * i, w->dr + 3 * i, want_normal ? w->d + 3 * i : NULL,
                     want_normal ? w->dd + 3 * i : NULL, c->params);
    if (rc != 0) return CABLE_ERR_CALLBACK;
  }
  return CABLE_SUCCESS;
}

int ribbon_writhe(ribbon_workspace *w, const ribbon_curve *c, double *wr, double *err)
{
  int rc = sample_curve(w, c, 0);
  if (rc != CABLE_SUCCESS) return rc;
  return ribbon_writhe_samples(w->n, c->period, w->r, w->dr, wr, err);
}

int ribbon_compute(ribbon_workspace *w, const ribbon_curve *c, ribbon_result *res)
{
  if (!res) return CABLE_ERR_INPUT;
  int rc = sample_curve(w, c, 1);
  if (rc != CABLE_SUCCESS) return rc;
  rc = ribbon_twist_samples(w->n, c->period, w->dr, w->d, w->dd, &res->tw);
  if (rc != CABLE_SUCCESS) return rc;
  rc = ribbon_writhe_samples(w->n, c->period, w->r, w->dr, &res->wr, &res->wr_err);
  if (rc != CABLE_SUCCESS) return rc;
  res->lk = res->tw + res->wr;
  return CABLE_SUCCESS;
}

int ribbon_pushoff_linking(ribbon_workspace *w, const ribbon_curve *c, double eps, double *lk)
{
  if (!lk || !(eps > 0)) return CABLE_ERR_INPUT;
  int rc = sample_curve(w, c, 1);
  if (rc != CABLE_SUCCESS) return rc;
  int n = w->n, turns = c->antiperiodic ? 2 : 1;
  for (int k = 0; k < turns; k++) {
    double sgn = k == 0 ? eps : -eps;   /* second turn: d -> -d */
    for (int i = 0; i < 3 * n; i++) {
      w->pr[3 * n * k + i] = w->r[i] + sgn * w->d[i];
      w->pdr[3 * n * k + i] = w->dr[i] + sgn * w->dd[i];
    }
  }
  double v;
  rc = ribbon_linking_samples(n, c->period, w->r, w->dr, turns * n, turns * c->period, w->pr,
                              w->pdr, &v);
  if (rc != CABLE_SUCCESS) return rc;
  *lk = v / turns;
  return CABLE_SUCCESS;
}
