/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The braid ribbon of a solution (ribbon.h; doc/geometry.md, 2): Tw by
 * Gauss-Legendre on the collocation mesh, Wr by the Gauss double integral on
 * samples of the contact curve placed by its arclength, densest where
 * non-adjacent parts of the axis come close, refined until the writhe's
 * error estimate is below BRAID_RIBBON_WR_TOL. */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "braid_geometry.h"
#include "braid_state.h"
#include "cable/cable_status.h"
#include "cable_vec3.h"
#include "ribbon.h"
#include "ribbon_fuller.h"

/* Twist rate T . (p x p_t) / |p|^2 of the normal d1 projected on the normal
 * plane of the contact curve, p = d1 - (d1.T) T.  Projection makes the rate
 * exact for the interpolated curve, whose d1 is perpendicular to c' only up
 * to the discretisation error. */
double braid_point_twist_rate(const braid_point *q)
{
  double sp = sqrt(cable_vec3_dot(q->dc, q->dc));
  double T[3], Tt[3], p[3], pt[3], x[3];
  for (int i = 0; i < 3; i++) T[i] = q->dc[i] / sp;
  double tc = cable_vec3_dot(T, q->d2c);
  for (int i = 0; i < 3; i++) Tt[i] = (q->d2c[i] - tc * T[i]) / sp;
  double dT = cable_vec3_dot(q->d1, T), dtT = cable_vec3_dot(q->dd1, T), dTt = cable_vec3_dot(q->d1, Tt);
  for (int i = 0; i < 3; i++) {
    p[i] = q->d1[i] - dT * T[i];
    pt[i] = q->dd1[i] - (dtT + dTt) * T[i] - dT * Tt[i];
  }
  cable_vec3_cross(p, pt, x);
  return cable_vec3_dot(T, x) / cable_vec3_dot(p, p);
}

/* ---- the contact curve by arclength ------------------------------------- */

typedef struct {
  const cable_solution *sol;
  const gsl_integration_glfixed_table *tab;
  int ntst, ncol;
  double *arc;       /* [ntst + 1] arclength of the contact curve at the mesh points */
  double A;          /* its length */
  int hint;          /* mesh interval of the last point evaluation */
  int rc;            /* first error of a point evaluation */
} axis;

static double mesh_t(const axis *x, int j) { return x->sol->t[j * x->ncol]; }

static double contact_speed(axis *x, double t)
{
  braid_point q;
  int e = braid_point_eval(x->sol, t, &x->hint, &q);
  if (e != CABLE_SUCCESS && x->rc == CABLE_SUCCESS) x->rc = e;
  return sqrt(cable_vec3_dot(q.dc, q.dc));
}

/* \int_a^b |c_t| dt by Gauss-Legendre (a, b inside one mesh interval). */
static double arc_gl(axis *x, double a, double b)
{
  double s = 0.0;
  for (size_t i = 0; i < x->tab->n; i++) {
    double tt, wgt;
    gsl_integration_glfixed_point(a, b, i, &tt, &wgt, x->tab);
    s += wgt * contact_speed(x, tt);
  }
  return s;
}

/* Mesh interval holding arclength a (binary search). */
static int arc_interval(const axis *x, double a)
{
  int lo = 0, hi = x->ntst - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (x->arc[mid] <= a) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/* Relative accuracy of the arclength inversion t(a): round-off level. */
#define BRAID_ARC_INVERT_TOL 1e-14
#define BRAID_ARC_INVERT_MAXIT 60

/* The point at arclength a in [0, A]: parameter *t and the curve's point and
 * derivatives (*q). */
static int axis_at(axis *x, double a, double *t, braid_point *q)
{
  int j = arc_interval(x, a);
  double lo = mesh_t(x, j), hi = mesh_t(x, j + 1);
  double tt = lo + (hi - lo) * (a - x->arc[j]) / (x->arc[j + 1] - x->arc[j]);
  double tl = lo, th = hi;
  int it;
  for (it = 0; it < BRAID_ARC_INVERT_MAXIT; it++) {
    double f = x->arc[j] + arc_gl(x, lo, tt) - a;
    if (x->rc != CABLE_SUCCESS) return x->rc;
    if (fabs(f) <= BRAID_ARC_INVERT_TOL * x->A) break;
    if (f > 0) th = tt;
    else tl = tt;
    double tn = tt - f / contact_speed(x, tt);
    tt = (tn > tl && tn < th) ? tn : 0.5 * (tl + th);   /* safeguarded Newton */
  }
  if (it == BRAID_ARC_INVERT_MAXIT) return CABLE_ERR_NONFINITE;
  *t = tt;
  return braid_point_eval(x->sol, tt, &x->hint, q);
}

/* ---- where the axis comes close to itself -------------------------------- */

/* A closest approach of two non-adjacent parts of the axis: arclengths a, b,
 * distance d and the sine of the angle between the tangents there. */
typedef struct {
  double a, b, d, s;
} near_pair;

/* Sample density (samples per unit arclength) of the writhe quadrature:
 *   rho(a) = 1/h + sum over near pairs and both of their ends c of
 *            beta / sqrt(d^2 + s^2 x^2),   x = a - c wrapped into [-A/2, A/2).
 * Near an end the spacing is sqrt(d^2 + s^2 x^2)/beta: a fixed fraction of
 * the distance to the other part of the axis (for two straight pieces
 * crossing at angle asin(s)), so the Gauss integrand's peak, of width d, is
 * resolved however small d is, at a cost of O(beta/s log(A s/d)) samples.
 * Its integral U(a) is closed-form (asinh), so the samples a_i = U^-1(Z i/n)
 * and the weights da/du = Z/rho(a_i) (u = U/Z in [0,1)) are exact. */
typedef struct {
  double A, h, beta;
  int nnear;
  const near_pair *np;
} density;

static double wrap(double y, double A) { return y - A * floor(y / A + 0.5); }

static double rho_term(const density *D, double a, double c, double d, double s)
{
  double x = wrap(a - c, D->A);
  return D->beta / sqrt(d * d + s * s * x * x);
}

static double rho(const density *D, double a)
{
  double r = 1.0 / D->h;
  for (int m = 0; m < D->nnear; m++) {
    const near_pair *p = &D->np[m];
    r += rho_term(D, a, p->a, p->d, p->s) + rho_term(D, a, p->b, p->d, p->s);
  }
  return r;
}

/* \int_0^y of one term's density, continued periodically (y any real). */
static double cum_term(const density *D, double y, double d, double s)
{
  double k = floor(y / D->A + 0.5), x = y - k * D->A;
  return D->beta / s * (2.0 * k * asinh(s * D->A / (2.0 * d)) + asinh(s * x / d));
}

/* U(a) = \int_0^a rho. */
static double cum(const density *D, double a)
{
  double u = a / D->h;
  for (int m = 0; m < D->nnear; m++) {
    const near_pair *p = &D->np[m];
    u += cum_term(D, a - p->a, p->d, p->s) - cum_term(D, -p->a, p->d, p->s);
    u += cum_term(D, a - p->b, p->d, p->s) - cum_term(D, -p->b, p->d, p->s);
  }
  return u;
}

/* a in [lo, hi] with U(a) = target: safeguarded Newton (U' = rho > 0) to
 * 1e-9 samples, far below what moves the quadrature. */
#define DENSITY_INVERT_TOL 1e-9
#define DENSITY_INVERT_MAXIT 200   /* bisection alone halves [lo, hi] to round-off in ~60 */
static double cum_invert(const density *D, double target, double lo, double hi)
{
  double a = lo + (target - cum(D, lo)) / rho(D, lo);
  for (int it = 0; it < DENSITY_INVERT_MAXIT; it++) {
    if (!(a > lo && a < hi)) a = 0.5 * (lo + hi);
    double f = cum(D, a) - target;
    if (fabs(f) <= DENSITY_INVERT_TOL) break;
    if (f > 0) hi = a;
    else lo = a;
    a -= f / rho(D, a);
  }
  return a;
}

/* n samples of the contact curve at a_i = U^-1(Z i/n): positions r and the
 * derivatives dr = dc/du = T Z/rho (period 1 in u). */
static int sample_axis(axis *x, const density *D, int n, double *r, double *dr)
{
  double Z = cum(D, x->A), a = 0.0;
  for (int i = 0; i < n; i++) {
    if (i > 0) a = cum_invert(D, Z * i / n, a, x->A);
    braid_point q;
    double t;
    int rc = axis_at(x, a, &t, &q);
    if (rc != CABLE_SUCCESS) return rc;
    double sp = sqrt(cable_vec3_dot(q.dc, q.dc)), w = Z / rho(D, a);
    for (int k = 0; k < 3; k++) {
      r[3 * i + k] = q.c[k];
      dr[3 * i + k] = q.dc[k] / sp * w;
    }
  }
  return CABLE_SUCCESS;
}

/* Unit tangent T and curvature vector K = dT/da of the contact curve at q. */
void braid_point_tangent_curvature(const braid_point *q, double T[3], double K[3])
{
  double sp2 = cable_vec3_dot(q->dc, q->dc), sp = sqrt(sp2);
  for (int i = 0; i < 3; i++) T[i] = q->dc[i] / sp;
  double tc = cable_vec3_dot(T, q->d2c);
  for (int i = 0; i < 3; i++) K[i] = (q->d2c[i] - tc * T[i]) / sp2;
}

/* Newton on the gradient of |c(a) - c(b)|^2 / 2 in arclength (which, unlike
 * t, runs smoothly through the knot's hand-over point t = 0 = 1), from a pair
 * of samples; the steps stay within `span` of the start.  Returns 1 and the
 * refined pair when it converges to a minimum, 0 otherwise. */
#define NEAR_NEWTON_MAXIT 30
#define NEAR_NEWTON_TOL 1e-15
static int refine_pair(axis *x, double a, double b, double span, near_pair *out)
{
  double a0 = a, b0 = b;
  for (int it = 0; it < NEAR_NEWTON_MAXIT; it++) {
    braid_point p, q;
    double ta, tb, Ta[3], Ka[3], Tb[3], Kb[3];
    if (axis_at(x, a - x->A * floor(a / x->A), &ta, &p) != CABLE_SUCCESS) return 0;
    if (axis_at(x, b - x->A * floor(b / x->A), &tb, &q) != CABLE_SUCCESS) return 0;
    braid_point_tangent_curvature(&p, Ta, Ka);
    braid_point_tangent_curvature(&q, Tb, Kb);
    double D[3] = {p.c[0] - q.c[0], p.c[1] - q.c[1], p.c[2] - q.c[2]};
    double g1 = cable_vec3_dot(D, Ta), g2 = -cable_vec3_dot(D, Tb);
    double h11 = 1.0 + cable_vec3_dot(D, Ka), h22 = 1.0 - cable_vec3_dot(D, Kb), h12 = -cable_vec3_dot(Ta, Tb);
    double det = h11 * h22 - h12 * h12;
    if (!(det > 0) || !(h11 > 0)) return 0;              /* not a minimum (parallel parts) */
    double da = -(h22 * g1 - h12 * g2) / det, db = -(h11 * g2 - h12 * g1) / det;
    if (fabs(da) + fabs(db) <= NEAR_NEWTON_TOL * x->A) {
      double c[3];
      cable_vec3_cross(Ta, Tb, c);
      out->d = sqrt(cable_vec3_dot(D, D));
      out->s = sqrt(cable_vec3_dot(c, c));
      out->a = a - x->A * floor(a / x->A);
      out->b = b - x->A * floor(b / x->A);
      return 1;
    }
    a += da;
    b += db;
    if (fabs(a - a0) > span || fabs(b - b0) > span) return 0;
  }
  return 0;
}

/* Near pairs from n uniform samples (r, unit tangents T,
 * spacing h = A/n): the discrete local minima of the distance between
 * samples more than `window` apart along the axis that are closer than
 * `dnear`, refined by Newton.  Keeps the BRAID_RIBBON_MAX_NEAR closest; the
 * closest distance found is *dmin (INFINITY when there is none). */
static int find_near(axis *x, int n, const double *r, const double *T, double window,
                     double dnear, near_pair *np, int *nnear, double *dmin)
{
  int w = (int)ceil(window / (x->A / n)), cnt = 0;
  double h = x->A / n;
  *dmin = INFINITY;
  for (int i = 0; i < n; i++) {
    for (int k = i + w; k <= i + n - w && k < n; k++) {
      if (k <= i) continue;
      double d2 = cable_vec3_dist2(r + 3 * i, r + 3 * k);
      if (d2 >= dnear * dnear) continue;
      int ismin = 1;
      for (int di = -1; di <= 1 && ismin; di++)
        for (int dk = -1; dk <= 1 && ismin; dk++) {
          if (di == 0 && dk == 0) continue;
          int ii = (i + di + n) % n, kk = (k + dk + n) % n;
          double e2 = cable_vec3_dist2(r + 3 * ii, r + 3 * kk);
          /* ties go to the first pair in scan order */
          if (e2 < d2 || (e2 == d2 && (di < 0 || (di == 0 && dk < 0)))) ismin = 0;
        }
      if (!ismin) continue;
      near_pair p;
      if (!refine_pair(x, i * h, k * h, 4.0 * h, &p) || p.d > sqrt(d2)) {
        double c[3];
        cable_vec3_cross(T + 3 * i, T + 3 * k, c);
        p.a = i * h;
        p.b = k * h;
        p.d = sqrt(d2);
        p.s = sqrt(cable_vec3_dot(c, c));
      }
      if (x->rc != CABLE_SUCCESS) return x->rc;
      /* a floor on d: the density needs d > 0, and below round-off relative
         to the curve's size the two parts are not told apart anyway */
      p.d = fmax(p.d, 1e-14 * x->A);
      p.s = fmax(p.s, BRAID_RIBBON_MIN_SINE);
      *dmin = fmin(*dmin, p.d);
      if (cnt < BRAID_RIBBON_MAX_NEAR) {
        np[cnt++] = p;
      } else {
        int far = 0;
        for (int m = 1; m < cnt; m++)
          if (np[m].d > np[far].d) far = m;
        if (p.d < np[far].d) np[far] = p;
      }
    }
  }
  *nnear = cnt;
  return CABLE_SUCCESS;
}

static int round8(double n)
{
  return n >= (double)BRAID_RIBBON_MAX_SAMPLES ? BRAID_RIBBON_MAX_SAMPLES + 8 : ((int)ceil(n) + 7) / 8 * 8;
}

int braid_ribbon_compute(const cable_solution *sol, int nsamples, braid_ribbon *out)
{
  if (!out || nsamples < 0) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  int ntst = sol->ntst, ncol = sol->ncol, npts = cable_solution_npts(sol);
  double Delta = sol->par[BP_DELTA];
  gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(BRAID_RIBBON_GL_ORDER);
  axis x = {sol, tab, ntst, ncol, malloc(((size_t)ntst + 1) * sizeof(double)), 0.0, -1, CABLE_SUCCESS};
  double *r = NULL, *dr = NULL;
  near_pair *np = malloc(BRAID_RIBBON_MAX_NEAR * sizeof *np);
  if (!tab || !x.arc || !np) { rc = CABLE_ERR_ALLOC; goto done; }

  /* twist and cumulative arclength, interval by interval */
  double tw = 0.0;
  x.arc[0] = 0.0;
  for (int j = 0; j < ntst && x.rc == CABLE_SUCCESS; j++) {
    double a = mesh_t(&x, j), b = mesh_t(&x, j + 1), tws = 0.0;
    for (size_t i = 0; i < tab->n; i++) {
      double tt, wgt;
      braid_point q;
      gsl_integration_glfixed_point(a, b, i, &tt, &wgt, tab);
      x.rc = braid_point_eval(sol, tt, &x.hint, &q);
      if (x.rc != CABLE_SUCCESS) break;
      tws += wgt * braid_point_twist_rate(&q);
    }
    tw += tws;
    x.arc[j + 1] = x.arc[j] + arc_gl(&x, a, b);
  }
  if ((rc = x.rc) != CABLE_SUCCESS) goto done;
  out->tw = tw / (2.0 * M_PI);
  double A = x.arc[ntst];
  x.A = A;
  out->axis_length = A;

  braid_point p0, p1;
  if ((rc = braid_point_eval(sol, sol->t[0], NULL, &p0)) != CABLE_SUCCESS) goto done;
  if ((rc = braid_point_eval(sol, sol->t[npts - 1], NULL, &p1)) != CABLE_SUCCESS) goto done;
  out->closure_gap = sqrt(cable_vec3_dist2(p1.c, p0.c));
  if (!isfinite(A) || !isfinite(out->tw)) { rc = CABLE_ERR_NONFINITE; goto done; }
  if (!(A > 0) || out->closure_gap > BRAID_CLOSURE_TOL * A) { rc = CABLE_ERR_INPUT; goto done; }
  double dd = cable_vec3_dot(p0.d1, p1.d1);
  out->closure = dd < -0.5 ? -1 : (dd > 0.5 ? 1 : 0);

  /* Writhe on samples placed by the arclength of the contact curve: the curve
   * closes smoothly in arclength even where the parametrisation by s does not
   * (for knots the contact-curve speed jumps at s = 0 by the factor sigma'). */
  size_t cap = 3 * ((size_t)BRAID_RIBBON_MAX_SAMPLES + 8);
  r = malloc(cap * sizeof *r);
  dr = malloc(cap * sizeof *dr);
  if (!r || !dr) { rc = CABLE_ERR_ALLOC; goto done; }
  out->nnear = 0;
  out->axis_dmin = INFINITY;
  if (nsamples > 0) {
    /* a fixed uniform sample count (studies of the quadrature) */
    int n = nsamples < RIBBON_MIN_SAMPLES ? RIBBON_MIN_SAMPLES : (nsamples + 7) / 8 * 8;
    if (n > BRAID_RIBBON_MAX_SAMPLES) n = BRAID_RIBBON_MAX_SAMPLES;
    density D = {A, A / n, 0.0, 0, np};
    if ((rc = sample_axis(&x, &D, n, r, dr)) != CABLE_SUCCESS) goto done;
    if ((rc = ribbon_writhe_samples(n, 1.0, r, dr, &out->wr, &out->wr_err)) != CABLE_SUCCESS) goto done;
    out->nsamples = n;
  } else {
    /* uniform samples h = Delta/BRAID_RIBBON_SAMPLES_PER_DELTA apart find
       the near pairs; the density adds samples around them; each refinement
       halves every spacing */
    double h = Delta / BRAID_RIBBON_SAMPLES_PER_DELTA;
    double nmin = fmax(BRAID_RIBBON_MIN_SAMPLES, 2.0 * npts);
    if (A / h < nmin) h = A / nmin;
    int n0 = round8(A / h);
    if (n0 > BRAID_RIBBON_MAX_SAMPLES) n0 = BRAID_RIBBON_MAX_SAMPLES;
    h = A / n0;
    density D = {A, h, 0.0, 0, np};
    if ((rc = sample_axis(&x, &D, n0, r, dr)) != CABLE_SUCCESS) goto done;
    for (int i = 0; i < 3 * n0; i++) dr[i] /= A;   /* unit tangents for the search */
    rc = find_near(&x, n0, r, dr, BRAID_RIBBON_WINDOW * Delta, BRAID_RIBBON_NEAR * Delta, np,
                   &out->nnear, &out->axis_dmin);
    if (rc != CABLE_SUCCESS) goto done;
    out->axis_dmin /= Delta;
    out->wr_err = INFINITY;
    out->nsamples = 0;
    for (int level = 0;; level++) {
      D.h = h / (1 << level);
      D.beta = out->nnear > 0 ? BRAID_RIBBON_NEAR_BETA * (1 << level) : 0.0;
      D.nnear = out->nnear;
      int n = level == 0 && out->nnear == 0 ? n0 : round8(cum(&D, A));
      if (n > BRAID_RIBBON_MAX_SAMPLES) {
        if (level > 0) break;
        /* spacing above the density's: valid, but the estimate will say so */
        n = BRAID_RIBBON_MAX_SAMPLES;
      }
      double wr, err;
      if (level == 0 && out->nnear == 0) {
        for (int i = 0; i < 3 * n0; i++) dr[i] *= A;   /* back to dc/du: the same samples */
      } else if ((rc = sample_axis(&x, &D, n, r, dr)) != CABLE_SUCCESS) {
        goto done;
      }
      if ((rc = ribbon_writhe_samples(n, 1.0, r, dr, &wr, &err)) != CABLE_SUCCESS) goto done;
      out->wr = wr;
      out->wr_err = err;
      out->nsamples = n;
      if (err <= BRAID_RIBBON_WR_TOL) break;
    }
  }
  out->resolved = out->wr_err <= BRAID_RIBBON_WR_TOL;
  out->lk = out->tw + out->wr;
  if (out->closure == -1) out->lk_defect = fabs(out->lk - (floor(out->lk) + 0.5));
  else if (out->closure == 1) out->lk_defect = fabs(out->lk - round(out->lk));
  else out->lk_defect = NAN;
done:
  free(r);
  free(dr);
  free(np);
  free(x.arc);
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

int braid_topology_compute(const cable_solution *sol, int nsamples, cable_braid_topology *out)
{
  if (!out || nsamples < 0) return CABLE_ERR_INPUT;
  braid_ribbon rb;
  int rc = braid_ribbon_compute(sol, 0, &rb);
  if (rc != CABLE_SUCCESS) return rc;
  out->lk = rb.lk;
  out->tw = rb.tw;
  out->wr = rb.wr;
  out->wr_err = rb.wr_err;
  out->resolved = rb.resolved;
  out->closure = rb.closure;
  out->lk_defect = rb.lk_defect;
  int n = nsamples > 0 ? nsamples : BRAID_TOPOLOGY_SAMPLES;
  if (n < 3) return CABLE_ERR_INPUT;
  /* n + 1 samples uniform in t; the last repeats the first on a closed axis */
  braid_curves *bc = braid_curves_alloc(n + 1);
  if (!bc) return CABLE_ERR_ALLOC;
  rc = braid_curves_from_solution(sol, bc);
  if (rc == CABLE_SUCCESS) rc = knot_type_identify(bc->c, n, &out->axis);
  braid_curves_free(bc);
  if (rc != CABLE_SUCCESS) return rc;
  /* writhe of the minimal diagram: torus knots' minimal diagrams are closed
   * positive (right-handed) or negative braids, so it is handedness x
   * crossing number; the unknot's and the amphichiral figure-eight's are 0 */
  const cable_knot_type_result *k = &out->axis;
  if (k->crossing_number < 0 || (k->torus_p > 0 && k->handedness == 0)) out->lk_in_tube = NAN;
  else out->lk_in_tube = out->lk - (double)(k->handedness * k->crossing_number);
  return CABLE_SUCCESS;
}
