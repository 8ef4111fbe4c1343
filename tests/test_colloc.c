/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Collocation basis and discretised system: quadrature exactness, partition of
 * unity, and the block Newton matrix against central differences of the
 * residual (analytic and finite-difference problem Jacobians), also with an
 * integral condition (bratu_int, NINT = 1). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_constants.h"
#include "cable/cable_status.h"
#include "colloc_basis.h"
#include "colloc_jac.h"
#include "colloc_system.h"
#include "harness.h"
#include "test_problems.h"

static void test_basis(void)
{
  for (int nc = CABLE_NCOL_MIN; nc <= CABLE_NCOL_MAX; nc++) {
    colloc_basis b;
    test_int("basis init", colloc_basis_init(&b, nc), 0);
    double maxpu = 0, maxd = 0, sw = 0, swn = 0, gauss = 0, nodes = 0;
    for (int m = 0; m < nc; m++) {
      double s = 0, ds = 0;
      for (int k = 0; k <= nc; k++) { s += b.l[m][k]; ds += b.dl[m][k]; }
      maxpu = fmax(maxpu, fabs(s - 1));
      maxd = fmax(maxd, fabs(ds));
      sw += b.w[m];
      gauss += b.w[m] * pow(b.c[m], 2 * nc - 1); /* Gauss: exact to degree 2 nc - 1 */
    }
    for (int k = 0; k <= nc; k++) {
      swn += b.wn[k];
      nodes += b.wn[k] * pow((double)k / nc, nc); /* interpolant of x^nc is exact */
    }
    char what[96];
    /* sums of O(1) terms of alternating sign: a few hundred ulps */
    snprintf(what, sizeof what, "ncol %d partition of unity", nc);
    test_le(what, maxpu, 1e-13);
    snprintf(what, sizeof what, "ncol %d derivatives sum to zero", nc);
    test_le(what, maxd, 1e-11);
    snprintf(what, sizeof what, "ncol %d Gauss weights", nc);
    test_abs(what, sw, 1.0, 1e-14);
    snprintf(what, sizeof what, "ncol %d Gauss exact for x^(2ncol-1)", nc);
    test_abs(what, gauss, 1.0 / (2 * nc), 1e-14);
    snprintf(what, sizeof what, "ncol %d node weights", nc);
    test_abs(what, swn, 1.0, 1e-13);
    snprintf(what, sizeof what, "ncol %d node quadrature exact for x^ncol", nc);
    test_abs(what, nodes, 1.0 / (nc + 1), 1e-13);
  }
  test_int("ncol 8 rejected", colloc_basis_init(&(colloc_basis){0}, 8), CABLE_ERR_INPUT);
}

/* max |J - FD(F)| / max|J| with central differences of step 1e-6:
 * truncation ~ 1e-12 |F'''|, round-off ~ 1e-16 |F| / 1e-6 = 1e-10 |F|. */
static double jacobian_error_rows(colloc_system *s, const double *x, int row0, int nrows)
{
  int n = s->n;
  colloc_jac *J = colloc_jac_alloc(s->ndim, s->ntst, s->ncol, s->nfpr, s->nbc, s->nint);
  double *A = calloc((size_t)n * (size_t)n, sizeof *A);
  double *xp = malloc((size_t)n * sizeof *xp), *Fp = malloc((size_t)n * sizeof *Fp);
  double *Fm = malloc((size_t)n * sizeof *Fm);
  colloc_system_jacobian(s, x, J);
  colloc_jac_to_dense(J, A);
  double err = 0, scale = 0;
  for (int c = 0; c < n; c++) {
    memcpy(xp, x, (size_t)n * sizeof *x);
    double h = 1e-6 * (1 + fabs(x[c]));
    xp[c] = x[c] + h;
    colloc_system_residual(s, xp, Fp);
    xp[c] = x[c] - h;
    colloc_system_residual(s, xp, Fm);
    for (int r = row0; r < row0 + nrows; r++) {
      double fd = (Fp[r] - Fm[r]) / (2 * h);
      err = fmax(err, fabs(fd - A[r + (size_t)n * c]));
      scale = fmax(scale, fabs(A[r + (size_t)n * c]));
    }
  }
  colloc_jac_free(J);
  free(A); free(xp); free(Fp); free(Fm);
  return err / scale;
}

static double jacobian_error(colloc_system *s, const double *x) { return jacobian_error_rows(s, x, 0, s->n); }

/* Relative error of the Newton matrix against differences of the residual
 * (a smooth non-uniform mesh, a random state, the arclength closing). */
static double system_error(const cable_problem *pb, int jac, int integral_rows_only)
{
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.jac = jac;
  int icp[2] = {0, 1}, st, nfpr = pb->nbc + pb->nint - pb->ndim + 1;
  colloc_system *s = colloc_system_alloc(pb, &c, 5, 3, icp, nfpr, &st);
  if (!s) return INFINITY;
  for (int j = 0; j <= s->ntst; j++) s->mesh[j] = pow((double)j / s->ntst, 1.3);
  srand(7);
  double *x = malloc((size_t)s->n * sizeof *x);
  for (int i = 0; i < s->n; i++) {
    x[i] = 0.5 * ((double)rand() / RAND_MAX - 0.5);
    s->x0[i] = x[i] + 0.01;
    s->xdot0[i] = (double)rand() / RAND_MAX;
  }
  x[s->n - nfpr] = 2.0;
  s->par[1] = 0.05;
  s->closing = COLLOC_CLOSE_ARCLENGTH;
  s->ds = 0.1;
  double e = integral_rows_only ? jacobian_error_rows(s, x, s->ntst * s->ncol * s->ndim + s->nbc, s->nint)
                                : jacobian_error(s, x);
  free(x);
  colloc_system_free(s);
  return e;
}

/* bratu_int with deliberately wrong analytic derivatives: the parameter
 * columns (corrupt = 1) or the u columns (corrupt = 2) of FUNC, BCND and
 * ICND are off by 0.5.  JAC=-1 (AUTO's meaning) must use the u columns and
 * difference the parameter columns. */
static int corrupt_mode(const void *params) { return *(const int *)params; }

static int corrupt_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                        double *dfdu, double *dfdp, void *params)
{
  int rc = cable_testproblem_bratu_int()->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, NULL);
  if (corrupt_mode(params) == 2 && ijac >= 1) dfdu[1] += 0.5;
  if (corrupt_mode(params) == 1 && ijac >= 2) dfdp[1 + ndim * 0] += 0.5;
  return rc;
}

static int corrupt_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                        int ijac, double *fb, double *dbc, void *params)
{
  int rc = cable_testproblem_bratu_int()->bcnd(ndim, par, icp, nbc, u0, u1, ijac, fb, dbc, NULL);
  if (corrupt_mode(params) == 2 && ijac >= 1) dbc[0] += 0.5;
  if (corrupt_mode(params) == 1 && ijac >= 2) dbc[0 + nbc * (2 * ndim + 0)] += 0.5;
  return rc;
}

static int corrupt_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                        const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  int rc = cable_testproblem_bratu_int()->icnd(ndim, par, icp, nint, u, uold, udot, upold, ijac, fi, dint, NULL);
  if (corrupt_mode(params) == 2 && ijac >= 1) dint[0] += 0.5;
  if (corrupt_mode(params) == 1 && ijac >= 2) dint[0 + nint * (ndim + 1)] += 0.5;
  return rc;
}

static void test_jac_minus_one(void)
{
  for (int mode = 1; mode <= 2; mode++) {
    cable_problem pb = *cable_testproblem_bratu_int();
    pb.func = corrupt_func;
    pb.bcnd = corrupt_bcnd;
    pb.icnd = corrupt_icnd;
    pb.params = &mode;
    const char *what = mode == 1 ? "wrong parameter derivatives" : "wrong u derivatives";
    char buf[160];
    /* a 0.5 error in one entry of O(1)-scaled blocks: relative error > 1e-3;
       a correct matrix: the 1e-7 bound of the JAC=0 checks above */
    double e1 = system_error(&pb, 1, 0), em1 = system_error(&pb, -1, 0), e0 = system_error(&pb, 0, 0);
    double ei1 = system_error(&pb, -1, 1);
    if (mode == 1) {
      snprintf(buf, sizeof buf, "%s: JAC=1 uses them (error %.3g > 1e-3)", what, e1);
      test_true(buf, e1 > 1e-3);
      snprintf(buf, sizeof buf, "%s: JAC=-1 differences them (error %.3g <= 1e-7)", what, em1);
      test_true(buf, em1 <= 1e-7);
      snprintf(buf, sizeof buf, "%s: JAC=-1 integral rows (error %.3g <= 1e-7)", what, ei1);
      test_true(buf, ei1 <= 1e-7);
    } else {
      snprintf(buf, sizeof buf, "%s: JAC=-1 uses the problem's u derivatives (error %.3g > 1e-3)", what, em1);
      test_true(buf, em1 > 1e-3);
      snprintf(buf, sizeof buf, "%s: JAC=-1 integral rows use ICND's u derivatives (error %.3g > 1e-3)", what, ei1);
      test_true(buf, ei1 > 1e-3);
      snprintf(buf, sizeof buf, "%s: JAC=0 differences everything (error %.3g <= 1e-7)", what, e0);
      test_true(buf, e0 <= 1e-7);
    }
  }
}

static void test_system(const cable_problem *pb, const char *name, int jac)
{
  char what[96];
  snprintf(what, sizeof what, "%s JAC=%d: Newton matrix vs differences of the residual", name, jac);
  /* analytic: FD error bound above; JAC=0 adds the inner FD error (step 6e-6: ~1e-10) */
  test_le(what, system_error(pb, jac, 0), jac ? 1e-8 : 1e-7);
  if (pb->nint > 0) {
    /* the integral rows alone (their entries are O(h), smaller than the
       collocation rows', so the whole-matrix check could hide an error) */
    snprintf(what, sizeof what, "%s JAC=%d: integral-condition rows vs differences", name, jac);
    test_le(what, system_error(pb, jac, 1), jac ? 1e-8 : 1e-7);
  }
}

int main(void)
{
  test_basis();
  test_system(cable_testproblem_bratu(), "bratu", 1);
  test_system(cable_testproblem_bratu(), "bratu", 0);
  test_system(cable_testproblem_elastica(), "elastica", 1);
  test_system(cable_testproblem_layer(), "layer", 0);
  /* NINT = 1: the integral row and its derivatives (ICND's dint, JAC=1, and
     the engine's differences of ICND, JAC=0) */
  test_system(cable_testproblem_bratu_int(), "bratu_int", 1);
  test_system(cable_testproblem_bratu_int(), "bratu_int", 0);
  test_jac_minus_one();
  return test_summary();
}
