#include "ribbon.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "braid_geometry.h"
#include "braid_state.h"
#include "cable_status.h"

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

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
    double s = 0.0;
    for (int i = 0; i < n; i++) {
      int k = i + j < n ? i + j : i + j - n;
      s += gauss_kernel(r + 3 * i, dr + 3 * i, r + 3 * k, dr + 3 * k);
    }
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
    double na = sqrt(dot3(a, a)), nb2 = dot3(b, b);
    if (!(na > 0) || !(nb2 > 0)) return CABLE_ERR_INPUT;
    if (fabs(dot3(a, b)) > RIBBON_PERP_TOL * na * sqrt(nb2)) return CABLE_ERR_INPUT;
    double x[3];
    cross3(b, c, x);
    sum += dot3(a, x) / (na * nb2);
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

/* ---- the braid ribbon ---- */

/* Twist rate T . (p x p_t) / |p|^2 of the normal d1 projected on the normal
 * plane of the contact curve, p = d1 - (d1.T) T.  Projection makes the rate
 * exact for the interpolated curve, whose d1 is perpendicular to c' only up
 * to the discretisation error. */
static double braid_twist_rate(const braid_point *q)
{
  double sp = sqrt(dot3(q->dc, q->dc));
  double T[3], Tt[3], p[3], pt[3], x[3];
  for (int i = 0; i < 3; i++) T[i] = q->dc[i] / sp;
  double tc = dot3(T, q->d2c);
  for (int i = 0; i < 3; i++) Tt[i] = (q->d2c[i] - tc * T[i]) / sp;
  double dT = dot3(q->d1, T), dtT = dot3(q->dd1, T), dTt = dot3(q->d1, Tt);
  for (int i = 0; i < 3; i++) {
    p[i] = q->d1[i] - dT * T[i];
    pt[i] = q->dd1[i] - (dtT + dTt) * T[i] - dT * Tt[i];
  }
  cross3(p, pt, x);
  return dot3(T, x) / dot3(p, p);
}

static double contact_speed(const cable_solution *sol, double t, int *hint, int *rc)
{
  braid_point q;
  int e = braid_point_eval(sol, t, hint, &q);
  if (e != CABLE_SUCCESS) *rc = e;
  return sqrt(dot3(q.dc, q.dc));
}

/* \int_a^b |c_t| dt by Gauss-Legendre (a, b inside one mesh interval). */
static double arc_gl(const cable_solution *sol, double a, double b, const gsl_integration_glfixed_table *tab,
                     int *hint, int *rc)
{
  double s = 0.0;
  for (size_t i = 0; i < tab->n; i++) {
    double x, wgt;
    gsl_integration_glfixed_point(a, b, i, &x, &wgt, tab);
    s += wgt * contact_speed(sol, x, hint, rc);
  }
  return s;
}

/* Relative accuracy of the arclength inversion t(a): round-off level. */
#define BRAID_ARC_INVERT_TOL 1e-14
#define BRAID_ARC_INVERT_MAXIT 60

int braid_ribbon_compute(const cable_solution *sol, int nsamples, braid_ribbon *out)
{
  if (!out || nsamples < 0) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  int ntst = sol->ntst, ncol = sol->ncol, npts = cable_solution_npts(sol);
  const double *mesh = sol->t;
  double Delta = sol->par[BP_DELTA];
  gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(BRAID_RIBBON_GL_ORDER);
  double *arc = malloc(((size_t)ntst + 1) * sizeof *arc);
  double *r = NULL, *dr = NULL;
  if (!tab || !arc) { rc = CABLE_ERR_ALLOC; goto done; }

  /* twist and cumulative arclength, interval by interval */
  int hint = -1;
  double tw = 0.0;
  arc[0] = 0.0;
  for (int j = 0; j < ntst && rc == CABLE_SUCCESS; j++) {
    double a = mesh[j * ncol], b = mesh[(j + 1) * ncol], tws = 0.0;
    for (size_t i = 0; i < tab->n; i++) {
      double x, wgt;
      braid_point q;
      gsl_integration_glfixed_point(a, b, i, &x, &wgt, tab);
      rc = braid_point_eval(sol, x, &hint, &q);
      if (rc != CABLE_SUCCESS) break;
      tws += wgt * braid_twist_rate(&q);
    }
    tw += tws;
    arc[j + 1] = arc[j] + arc_gl(sol, a, b, tab, &hint, &rc);
  }
  if (rc != CABLE_SUCCESS) goto done;
  out->tw = tw / (2.0 * M_PI);
  double A = arc[ntst];
  out->axis_length = A;

  braid_point p0, p1;
  if ((rc = braid_point_eval(sol, mesh[0], NULL, &p0)) != CABLE_SUCCESS) goto done;
  if ((rc = braid_point_eval(sol, mesh[npts - 1], NULL, &p1)) != CABLE_SUCCESS) goto done;
  double gap[3] = {p1.c[0] - p0.c[0], p1.c[1] - p0.c[1], p1.c[2] - p0.c[2]};
  out->closure_gap = sqrt(dot3(gap, gap));
  if (!isfinite(A) || !isfinite(out->tw)) { rc = CABLE_ERR_NONFINITE; goto done; }
  if (!(A > 0) || out->closure_gap > BRAID_CLOSURE_TOL * A) { rc = CABLE_ERR_INPUT; goto done; }
  double dd = dot3(p0.d1, p1.d1);
  out->closure = dd < -0.5 ? -1 : (dd > 0.5 ? 1 : 0);

  /* writhe on samples uniform in arclength of the contact curve: the curve
   * closes smoothly in arclength even where the parametrisation by s does not
   * (for knots the contact-curve speed jumps at s = 0 by the factor sigma') */
  long n = nsamples;
  if (n == 0) {
    n = (long)ceil(A * BRAID_RIBBON_SAMPLES_PER_DELTA / Delta);
    if (n < 2L * npts) n = 2L * npts;
    if (n < BRAID_RIBBON_MIN_SAMPLES) n = BRAID_RIBBON_MIN_SAMPLES;
    if (n > BRAID_RIBBON_MAX_SAMPLES) n = BRAID_RIBBON_MAX_SAMPLES;
  }
  if (n < RIBBON_MIN_SAMPLES) n = RIBBON_MIN_SAMPLES;
  n = (n + 7) / 8 * 8;
  r = malloc(3 * (size_t)n * sizeof *r);
  dr = malloc(3 * (size_t)n * sizeof *dr);
  if (!r || !dr) { rc = CABLE_ERR_ALLOC; goto done; }
  int j = 0;
  hint = -1;
  for (long i = 0; i < n && rc == CABLE_SUCCESS; i++) {
    double target = A * (double)i / (double)n;
    while (j < ntst - 1 && arc[j + 1] <= target) j++;
    double lo = mesh[j * ncol], hi = mesh[(j + 1) * ncol];
    double t = lo + (hi - lo) * (target - arc[j]) / (arc[j + 1] - arc[j]);
    double tl = lo, th = hi;
    int it;
    for (it = 0; it < BRAID_ARC_INVERT_MAXIT; it++) {
      double f = arc[j] + arc_gl(sol, lo, t, tab, &hint, &rc) - target;
      if (rc != CABLE_SUCCESS) break;
      if (fabs(f) <= BRAID_ARC_INVERT_TOL * A) break;
      if (f > 0) th = t;
      else tl = t;
      double tn = t - f / contact_speed(sol, t, &hint, &rc);
      t = (tn > tl && tn < th) ? tn : 0.5 * (tl + th);   /* safeguarded Newton */
    }
    if (rc != CABLE_SUCCESS) break;
    if (it == BRAID_ARC_INVERT_MAXIT) { rc = CABLE_ERR_NONFINITE; break; }
    braid_point q;
    rc = braid_point_eval(sol, t, &hint, &q);
    double sp = sqrt(dot3(q.dc, q.dc));
    for (int k = 0; k < 3; k++) {
      r[3 * i + k] = q.c[k];
      dr[3 * i + k] = q.dc[k] / sp;
    }
  }
  if (rc != CABLE_SUCCESS) goto done;
  rc = ribbon_writhe_samples((int)n, A, r, dr, &out->wr, &out->wr_err);
  if (rc != CABLE_SUCCESS) goto done;
  out->nsamples = (int)n;
  out->lk = out->tw + out->wr;
  if (out->closure == -1) out->lk_defect = fabs(out->lk - (floor(out->lk) + 0.5));
  else if (out->closure == 1) out->lk_defect = fabs(out->lk - round(out->lk));
  else out->lk_defect = NAN;
done:
  free(r);
  free(dr);
  free(arc);
  gsl_integration_glfixed_table_free(tab);
  return rc;
}

int braid_ribbon_lk(const cable_solution *sol, double *lk, double *tw, double *wr)
{
  braid_ribbon b;
  int rc = braid_ribbon_compute(sol, 0, &b);
  if (rc != CABLE_SUCCESS) return rc;
  if (lk) *lk = b.lk;
  if (tw) *tw = b.tw;
  if (wr) *wr = b.wr;
  return CABLE_SUCCESS;
}
