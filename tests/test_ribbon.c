/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Ribbon quantities on curves with known answers (ribbon.h).
 *
 * Tolerances: the twist and linking sums are periodic trapezoidal rules of
 * analytic integrands, so their error is exp(-2 pi delta / h) (delta: width of
 * the strip of analyticity, h: step) and reaches round-off on the grids used
 * here; the writhe uses Romberg on the diagonal kink, error O(h^6).  The
 * checks below therefore use 1e-12 where the integrand is constant or
 * identically zero (only round-off of n ~ 10^3..10^6 terms), and 1e-8 (the
 * required accuracy) for the torus-knot writhe, where the two independent
 * computations each reach ~1e-11 (see the convergence check). */
#include <math.h>
#include <string.h>

#include <gsl/gsl_math.h>

#include "cable/cable_status.h"
#include "harness.h"
#include "ribbon.h"

/* round-off level for sums of ~10^6 O(1) terms */
#define TOL_ROUNDOFF 1e-12
/* required accuracy of the writhe and twist of smooth curves */
#define TOL_WRITHE 1e-8

static void cross(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* ---- circle of radius R in the xy-plane; normal turning by 2 pi k per circuit ---- */
typedef struct { double R, k; } circle_par;

static int circle_eval(double u, double r[3], double dr[3], double d[3], double dd[3], void *params)
{
  const circle_par *p = params;
  double c = cos(u), s = sin(u);
  r[0] = p->R * c; r[1] = p->R * s; r[2] = 0;
  dr[0] = -p->R * s; dr[1] = p->R * c; dr[2] = 0;
  if (d) {
    /* N = (c, s, 0) outward, B = T x N = -z for T = (-s, c, 0); d = cos(psi) N + sin(psi) B.
     * psi = k u turns d anticlockwise about T (right-handed). */
    double psi = p->k * u, cp = cos(psi), sp = sin(psi);
    double N[3] = {c, s, 0}, B[3] = {0, 0, -1}, dN[3] = {-s, c, 0};
    double T[3] = {-s, c, 0}, TxN[3];
    cross(T, N, TxN);
    for (int i = 0; i < 3; i++) {
      d[i] = cp * N[i] + sp * TxN[i];
      /* d' = psi' (-sin N + cos B) + cos N' ;  B is constant */
      dd[i] = p->k * (-sp * N[i] + cp * B[i]) + cp * dN[i];
    }
  }
  return 0;
}

/* ---- torus knot: winds p times about the z axis and q times about the tube;
 * the normal is the torus' surface normal (perpendicular to the curve, which
 * lies on the torus).  hand = +1 gives the right-handed knot: its push-off
 * along the torus normal (the surface framing) links it hand * p * q times. ---- */
typedef struct { int p, q; double R, a, hand; } torus_par;

static int torus_eval(double u, double r[3], double dr[3], double d[3], double dd[3], void *params)
{
  const torus_par *t = params;
  double P = t->p, Q = t->q, m = -t->hand;
  double cp = cos(P * u), sp = sin(P * u), cq = cos(Q * u), sq = sin(Q * u);
  double rho = t->R + t->a * cq, drho = -t->a * Q * sq;
  r[0] = rho * cp; r[1] = rho * sp; r[2] = m * t->a * sq;
  dr[0] = drho * cp - rho * P * sp;
  dr[1] = drho * sp + rho * P * cp;
  dr[2] = m * t->a * Q * cq;
  if (d) {
    d[0] = cq * cp; d[1] = cq * sp; d[2] = m * sq;
    dd[0] = -Q * sq * cp - P * cq * sp;
    dd[1] = -Q * sq * sp + P * cq * cp;
    dd[2] = m * Q * cq;
  }
  return 0;
}

static int failing_eval(double u, double r[3], double dr[3], double d[3], double dd[3], void *params)
{
  (void)u; (void)r; (void)dr; (void)d; (void)dd; (void)params;
  return -1;
}

static void check_circle(void)
{
  ribbon_workspace *w = ribbon_workspace_alloc(512);
  circle_par cp = {1.7, 3.0};
  ribbon_curve c = {circle_eval, 2 * M_PI, 0, &cp};
  ribbon_result res;
  test_int("circle: compute", ribbon_compute(w, &c, &res), CABLE_SUCCESS);
  test_abs("circle: Wr = 0 (planar curve)", res.wr, 0.0, TOL_ROUNDOFF);
  test_abs("circle: Tw = 3 (normal turns 3 times)", res.tw, 3.0, TOL_ROUNDOFF);
  test_abs("circle: Lk = Tw + Wr = 3", res.lk, 3.0, TOL_ROUNDOFF);
  double lk;
  /* push-off at eps = 0.2 R; h = 2 pi R / 512 = 0.012 R: exp(-2 pi 0.2/0.012) ~ 1e-45 */
  test_int("circle: push-off", ribbon_pushoff_linking(w, &c, 0.2 * cp.R, &lk), CABLE_SUCCESS);
  test_abs("circle: Gauss Lk(c, c + eps d) = +3 (right-handed twist is positive)", lk, 3.0, 1e-10);
  cp.k = -2.0;
  ribbon_compute(w, &c, &res);
  ribbon_pushoff_linking(w, &c, 0.2 * cp.R, &lk);
  test_abs("circle: Tw = -2 for left-handed turning", res.tw, -2.0, TOL_ROUNDOFF);
  test_abs("circle: Gauss Lk = -2", lk, -2.0, 1e-10);
  /* the (7,2) torus-knot braid: contact curve a circle, d1 turning by 7 pi (knot: antiperiodic) */
  cp.k = 3.5;
  c.antiperiodic = 1;
  ribbon_compute(w, &c, &res);
  test_abs("(7,2) braid ribbon: Tw = 3.5", res.tw, 3.5, TOL_ROUNDOFF);
  test_abs("(7,2) braid ribbon: Wr = 0", res.wr, 0.0, TOL_ROUNDOFF);
  test_abs("(7,2) braid ribbon: Lk = 3.5", res.lk, 3.5, TOL_ROUNDOFF);
  ribbon_pushoff_linking(w, &c, 0.2 * cp.R, &lk);
  test_abs("(7,2) braid ribbon: Gauss Lk of the edge taken twice round / 2 = 3.5", lk, 3.5, 1e-10);
  cp.k = -3.5;
  ribbon_compute(w, &c, &res);
  ribbon_pushoff_linking(w, &c, 0.2 * cp.R, &lk);
  test_abs("left-handed (7,2) braid ribbon: Lk = -3.5", res.lk, -3.5, TOL_ROUNDOFF);
  test_abs("left-handed (7,2) braid ribbon: Gauss Lk = -3.5", lk, -3.5, 1e-10);
  ribbon_workspace_free(w);
}

/* Wr of a torus knot two ways: the Gauss double integral, and Lk - Tw with
 * Lk the Gauss linking integral of the curve and its push-off along the
 * torus normal (an integer) and Tw the twist of that normal. */
static void check_torus(int p, int q, double hand, int n)
{
  char what[160];
  const char *h = hand > 0 ? "right" : "left";
  torus_par tp = {p, q, 2.0, 1.0, hand};
  ribbon_curve c = {torus_eval, 2 * M_PI, 0, &tp};
  ribbon_workspace *w = ribbon_workspace_alloc(n), *w2 = ribbon_workspace_alloc(2 * n);
  ribbon_result res, res2;
  double lk;
  int ok = ribbon_compute(w, &c, &res) == 0 && ribbon_compute(w2, &c, &res2) == 0 &&
           ribbon_pushoff_linking(w, &c, 0.25 * tp.a, &lk) == 0;
  snprintf(what, sizeof what, "T(%d,%d) %s: computations succeed", p, q, h);
  test_true(what, ok);
  snprintf(what, sizeof what, "T(%d,%d) %s: push-off Lk is the integer hand*p*q (surface framing)", p, q, h);
  test_abs(what, lk, hand * p * q, TOL_WRITHE);
  snprintf(what, sizeof what, "T(%d,%d) %s: Wr (Gauss) = Lk - Tw (push-off), n=%d", p, q,
           h, n);
  test_abs(what, res.wr, round(lk) - res.tw, TOL_WRITHE);
  snprintf(what, sizeof what, "T(%d,%d) %s: Wr converged (n vs 2n)", p, q, h);
  test_abs(what, res.wr, res2.wr, 1e-10);
  snprintf(what, sizeof what, "T(%d,%d) %s: Romberg correction estimate small", p, q,
           h);
  test_le(what, res.wr_err, 1e-6);
  printf("     T(%d,%d) hand %+g: Wr = %.12f  Tw = %.12f  Lk(push-off) = %.12f\n", p, q, hand,
         res.wr, res.tw, lk);
  if (hand > 0) {
    snprintf(what, sizeof what, "T(%d,%d) right-handed: Wr > 0", p, q);
    test_true(what, res.wr > 0);
  }
  ribbon_workspace_free(w);
  ribbon_workspace_free(w2);
}

/* The plain trapezoidal rule on the diagonal kink is only O(h^2); Romberg is
 * what buys the accuracy.  Reference: Lk - Tw from the push-off (independent
 * of the writhe quadrature). */
static double trapezoid_writhe(int n, const double *r, const double *dr)
{
  double s = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < n; k++) {
      if (i == k) continue;
      double x[3] = {r[3 * i] - r[3 * k], r[3 * i + 1] - r[3 * k + 1], r[3 * i + 2] - r[3 * k + 2]}, c[3];
      cross(dr + 3 * i, dr + 3 * k, c);
      double d2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
      s += (c[0] * x[0] + c[1] * x[1] + c[2] * x[2]) / (d2 * sqrt(d2));
    }
  return s * (2 * M_PI / n) * (2 * M_PI / n) / (4 * M_PI);
}

static void check_romberg_needed(void)
{
  torus_par tp = {3, 2, 2.0, 1.0, 1.0};
  ribbon_workspace *w = ribbon_workspace_alloc(2048);
  ribbon_curve c = {torus_eval, 2 * M_PI, 0, &tp};
  ribbon_result res;
  double lk;
  ribbon_compute(w, &c, &res);
  ribbon_pushoff_linking(w, &c, 0.25, &lk);
  ribbon_workspace_free(w);
  double ref = round(lk) - res.tw;
  enum { N = 1024 };
  static double r[3 * N], dr[3 * N];
  double wr, err;
  for (int i = 0; i < N; i++) torus_eval(2 * M_PI * i / N, r + 3 * i, dr + 3 * i, NULL, NULL, &tp);
  test_int("samples API", ribbon_writhe_samples(N, 2 * M_PI, r, dr, &wr, &err), CABLE_SUCCESS);
  double tr = trapezoid_writhe(N, r, dr);
  printf("     trefoil n=%d: Romberg error %.2e (estimate %.2e), plain trapezoid error %.2e\n", N, wr - ref, err,
         tr - ref);
  test_abs("trefoil n=1024: Romberg writhe = Lk - Tw", wr, ref, 1e-12);
  test_true("trefoil n=1024: plain trapezoid error above 1e-7 (the O(h^2) kink term)", fabs(tr - ref) > 1e-7);
  test_true("trefoil n=1024: the error estimate bounds the error", err >= fabs(wr - ref));
}

static void check_errors(void)
{
  double r[3 * 16] = {0}, dr[3 * 16] = {0}, wr, tw, lk;
  test_int("writhe: n not a multiple of 8", ribbon_writhe_samples(20, 1.0, r, dr, &wr, NULL), CABLE_ERR_INPUT);
  test_int("writhe: n too small", ribbon_writhe_samples(8, 1.0, r, dr, &wr, NULL), CABLE_ERR_INPUT);
  test_int("writhe: NULL array", ribbon_writhe_samples(16, 1.0, NULL, dr, &wr, NULL), CABLE_ERR_INPUT);
  test_int("writhe: period <= 0", ribbon_writhe_samples(16, 0.0, r, dr, &wr, NULL), CABLE_ERR_INPUT);
  r[5] = NAN;
  test_int("writhe: NaN sample", ribbon_writhe_samples(16, 1.0, r, dr, &wr, NULL), CABLE_ERR_NONFINITE);
  r[5] = 0;
  test_int("writhe: coincident points (self-intersection)",
           ribbon_writhe_samples(16, 1.0, r, dr, &wr, NULL), CABLE_ERR_NONFINITE);
  double t1[3] = {1, 0, 0}, d1[3] = {1, 0, 0}, dd1[3] = {0, 1, 0}, d0[3] = {0, 0, 0};
  test_int("twist: normal not perpendicular", ribbon_twist_samples(1, 1.0, t1, d1, dd1, &tw), CABLE_ERR_INPUT);
  test_int("twist: zero normal", ribbon_twist_samples(1, 1.0, t1, d0, dd1, &tw), CABLE_ERR_INPUT);
  test_int("twist: zero tangent", ribbon_twist_samples(1, 1.0, d0, dd1, t1, &tw), CABLE_ERR_INPUT);
  test_int("linking: n2 = 0", ribbon_linking_samples(1, 1.0, r, dr, 0, 1.0, r, dr, &lk), CABLE_ERR_INPUT);
  test_int("linking: intersecting curves", ribbon_linking_samples(1, 1.0, r, t1, 1, 1.0, r, dd1, &lk),
           CABLE_ERR_NONFINITE);
  test_true("workspace: n not a multiple of 8 refused", ribbon_workspace_alloc(100) == NULL);
  test_true("workspace: n too small refused", ribbon_workspace_alloc(8) == NULL);
  ribbon_workspace_free(NULL);
  ribbon_workspace *w = ribbon_workspace_alloc(16);
  ribbon_curve bad = {failing_eval, 1.0, 0, NULL};
  ribbon_result res;
  test_int("callback failure reported", ribbon_compute(w, &bad, &res), CABLE_ERR_CALLBACK);
  ribbon_curve none = {NULL, 1.0, 0, NULL};
  test_int("no callback", ribbon_compute(w, &none, &res), CABLE_ERR_INPUT);
  circle_par cp = {1, 1};
  ribbon_curve c = {circle_eval, 2 * M_PI, 0, &cp};
  test_int("push-off: eps <= 0", ribbon_pushoff_linking(w, &c, 0.0, &lk), CABLE_ERR_INPUT);
  test_int("writhe: NULL workspace", ribbon_writhe(NULL, &c, &wr, NULL), CABLE_ERR_INPUT);
  ribbon_workspace_free(w);
}

int main(void)
{
  check_circle();
  check_torus(3, 2, 1.0, 2048);
  check_torus(3, 2, -1.0, 2048);
  check_torus(2, 3, 1.0, 2048);
  check_torus(5, 2, 1.0, 2048);
  check_torus(4, 3, 1.0, 2048);
  check_torus(5, 4, 1.0, 2048);
  check_romberg_needed();
  check_errors();
  return test_summary();
}
