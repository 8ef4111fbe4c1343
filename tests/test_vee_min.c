/* SPDX-License-Identifier: GPL-3.0-or-later */
/* vee_min (continuation/vee_min.c): the minimiser behind the location of
 * double branch points, on functions with known minima: the squared
 * singular value's model (an exact parabola), a |sin| dip (linear only near
 * its zero, as sigma_1 along a branch step), a near miss, two zeros close
 * together, a neighbourhood where the function cannot be evaluated, and bad
 * input.  Against GSL's Brent minimiser on sigma itself (what
 * cont_special.c used before) the evaluation counts are compared: that is
 * the reason vee_min exists. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <math.h>

#include "harness.h"
#include "vee_min.h"

typedef struct {
  double s0, c, d;  /* g = c^2 sin^2(s - s0) + d^2 */
  double a, b;      /* second zero of the W case */
  double hole;      /* NaN within this distance of s0 */
  int kind;         /* 0 parabola, 1 sin, 2 W */
  int calls;
} model;

static double g_model(double s, void *p)
{
  model *m = p;
  m->calls++;
  if (m->hole > 0 && fabs(s - m->s0) < m->hole) return (double)NAN;
  if (m->kind == 0) return m->c * m->c * (s - m->s0) * (s - m->s0) + m->d * m->d;
  if (m->kind == 1) {
    double v = sin(s - m->s0);
    return m->c * m->c * v * v + m->d * m->d;
  }
  double v = (s - m->a) * (s - m->b);
  return v * v;
}

static double sigma_model(double s, void *p) { return sqrt(g_model(s, p)); }

/* GSL's Brent on sigma = sqrt(g), stopped as cont_special.c stopped it
 * (bracket shorter than tol); returns its evaluations */
static int brent_calls(model *m, double lo, double mid, double hi, double tol, double *smin)
{
  m->calls = 0;
  gsl_function F = {sigma_model, m};
  gsl_min_fminimizer *mz = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  double fl = sigma_model(lo, m), fm = sigma_model(mid, m), fh = sigma_model(hi, m);
  m->calls = 0;
  gsl_min_fminimizer_set_with_values(mz, &F, mid, fm, lo, fl, hi, fh);
  for (int it = 0; it < 100; it++) {
    if (gsl_min_fminimizer_iterate(mz) != GSL_SUCCESS) break;
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(mz), gsl_min_fminimizer_x_upper(mz), tol, 0.0) ==
        GSL_SUCCESS)
      break;
  }
  *smin = gsl_min_fminimizer_x_minimum(mz);
  gsl_min_fminimizer_free(mz);
  return m->calls;
}

static int run(model *m, double lo, double mid, double hi, double tol, int maxeval, vee_min_result *r)
{
  double ga = g_model(lo, m), gm = g_model(mid, m), gb = g_model(hi, m);
  m->calls = 0;
  return vee_min(g_model, m, lo, ga, mid, gm, hi, gb, tol, maxeval, r);
}

int main(void)
{
  gsl_set_error_handler_off();
  vee_min_result r;
  const double tol = 1e-7;

  /* an exact parabola: the first vertex is the minimum; the second confirms it */
  model par = {.s0 = 0.3, .c = 3.0, .kind = 0};
  int rc = run(&par, -1.0, 0.0, 2.0, tol, 60, &r);
  test_int("parabola: converged", rc, 0);
  test_abs("parabola: minimum at s0", r.s, 0.3, tol);
  test_le("parabola: one evaluation", (double)r.evals, (double)(1));
  test_int("parabola: the last evaluation is the best point", r.last_is_best, 1);
  test_int("parabola: evals counted as calls", r.evals, par.calls);

  /* sigma = |sin(s - s0)|, the bracket a whole step wide (sigma linear only
     near its zero), started at the bracket's middle and near the minimum */
  double starts[3] = {0.5, 1.05, 1.3};
  for (int k = 0; k < 3; k++) {
    model sn = {.s0 = 1.234567, .c = 2.5e-7, .kind = 1};
    rc = run(&sn, 0.0, starts[k], 2.0, tol, 60, &r);
    char what[96];
    snprintf(what, sizeof what, "sin dip from %.2f: converged", starts[k]);
    test_int(what, rc, 0);
    snprintf(what, sizeof what, "sin dip from %.2f: minimum within 2 tol", starts[k]);
    test_abs(what, r.s, sn.s0, 2 * tol);
    double sb;
    int nb = brent_calls(&sn, 0.0, starts[k], 2.0, tol, &sb);
    snprintf(what, sizeof what, "sin dip from %.2f: Brent on sigma finds it too", starts[k]);
    test_abs(what, sb, sn.s0, 2 * tol);
    snprintf(what, sizeof what, "sin dip from %.2f: fewer evaluations than Brent (%d)", starts[k], nb);
    test_le(what, (double)r.evals, (double)(nb - 1));
  }

  /* a near miss: the minimum of sqrt((s - s0)^2 c^2 + d^2) is still at s0 */
  model miss = {.s0 = -0.4, .c = 1.0, .d = 1e-3, .kind = 1};
  rc = run(&miss, -2.0, 0.0, 1.0, tol, 60, &r);
  test_int("near miss: converged", rc, 0);
  test_abs("near miss: minimum at s0", r.s, -0.4, 2 * tol);
  test_rel("near miss: g there is d^2", r.g, 1e-6, 1e-9);

  /* two zeros 0.01 apart: either one, to tol */
  model w = {.a = 0.50, .b = 0.51, .kind = 2};
  rc = run(&w, 0.0, 0.4, 1.0, tol, 60, &r);
  test_int("two zeros: converged", rc, 0);
  test_le("two zeros: at one of them", fmin(fabs(r.s - 0.50), fabs(r.s - 0.51)), 2 * tol);

  /* no evaluation within 3 tol of the minimum (Newton near a singular
     point): the closest point that can be evaluated, code 2 */
  model hole = {.s0 = 0.7, .c = 1.0, .kind = 1, .hole = 3 * tol};
  rc = run(&hole, 0.0, 0.2, 2.0, tol, 60, &r);
  test_int("hole: stops where g cannot be evaluated", rc, 2);
  test_le("hole: best point next to the hole", fabs(r.s - 0.7), 3 * tol + 4 * tol + tol);
  test_int("hole: the best point is a finite value", isfinite(r.g), 1);

  /* bad input and the evaluation limit */
  model up = {.s0 = 5.0, .c = 1.0, .kind = 0};
  rc = run(&up, -1.0, 0.0, 2.0, tol, 60, &r);
  test_int("no bracket (minimum outside): refused", rc, -1);
  rc = run(&par, 1.0, 0.0, 2.0, tol, 60, &r);
  test_int("lo > mid: refused", rc, -1);
  rc = run(&par, -1.0, 0.0, 2.0, 0.0, 60, &r);
  test_int("tol 0: refused", rc, -1);
  model sn = {.s0 = 1.234567, .c = 1.0, .kind = 1};
  rc = run(&sn, 0.0, 0.5, 2.0, 1e-12, 2, &r);
  test_int("maxeval 2: stops with code 1", rc, 1);
  test_int("maxeval 2: two evaluations", r.evals, 2);
  return test_summary();
}
