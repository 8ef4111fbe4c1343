/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Engine validation on problems with known answers:
 *  - Bratu: the fold lambda* = 3.513830719125162 (NTST=20, NCOL=4) to 1e-9;
 *  - elastica: branch points of the trivial branch at (n pi)^2, n = 1,2,3, to
 *    relative 1e-8; after switching at the first, lambda = 4 K(sin(theta(0)/2))^2
 *    on the buckled branch to relative 1e-8, in both directions;
 *  - Bratu at lambda = 1 against its closed form: mesh-point errors decay like
 *    h^(2 NCOL) (superconvergence), slope fitted for NCOL = 2..5;
 *  - two uncoupled elasticas: every branch point is double (two singular values
 *    vanish, the determinant keeps its sign); the singular-value test finds and
 *    locates them at (n pi)^2, and switching with BPANGLE (or BPDIR) in the
 *    canonical kernel basis reaches each of the four bifurcating branches. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdlib.h>

#include "cable/cable_constants.h"
#include "colloc_basis.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"


static void test_bratu_fold(memrun *r)
{
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.ds = 0.1; c.dsmin = 1e-6; c.dsmax = 0.5; c.nmx = 60;
  c.rl1 = 10.0;
  c.ilp = 1; c.isp = 0;
  c.epss = 1e-7;
  c.iad = 3;
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  test_true("bratu run ends normally", r->status > 0);
  const cable_solution *lp = memrun_find(r, CABLE_TY_LP, 0);
  test_true("bratu fold found", lp != NULL);
  /* discretisation error of the fold at NTST=20, NCOL=4: O(h^8) ~ 1e-11;
     location to EPSS in arclength: O((EPSS ds)^2) in lambda */
  if (lp) test_abs("bratu fold lambda*", lp->par[0], 3.513830719125162, 1e-9);
  test_int("bratu: exactly one fold", memrun_count(r, CABLE_TY_LP), 1);
  memrun_free(r);
}

/* The structured BP fields of a run's BP points: how many BPs there are,
 * and how many of them carry the given kind and multiplicity (the engine
 * says what it found in fields, the note is for people). */
static int memrun_bp_fields(const memrun *r, int kind, int mult, int *nbp)
{
  int n = 0;
  *nbp = 0;
  for (int i = 0; i < r->n; i++) {
    if (cable_type_base(r->itp[i]) != CABLE_TY_BP) continue;
    (*nbp)++;
    n += r->bp_kind[i] == kind && r->bp_mult[i] == mult;
  }
  return n;
}

static void test_elastica(memrun *r)
{
  cable_constants c;
  elastica_trivial_constants(&c, 50, 5);
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  test_true("elastica trivial branch ends at RL1", r->status == CABLE_END_BOUNDS);
  test_int("elastica: three branch points below lambda = 100", memrun_count(r, CABLE_TY_BP), 3);
  int nbp, nfields = memrun_bp_fields(r, CABLE_BP_SIMPLE, 1, &nbp);
  test_int("elastica: every BP point says kind simple, multiplicity 1 (det changes sign)", nfields, nbp);
  cable_solution *bp1 = NULL;
  for (int n = 1; n <= 3; n++) {
    const cable_solution *bp = memrun_find(r, CABLE_TY_BP, n - 1);
    char what[64];
    snprintf(what, sizeof what, "elastica BP%d at (%d pi)^2", n, n);
    /* eigenvalue error of Gauss collocation: O(h^(2 NCOL)) = (0.02)^10 times (n pi)^12: < 1e-9 */
    if (bp) test_rel(what, bp->par[0], (n * M_PI) * (n * M_PI), 1e-8);
    if (n == 1 && bp) bp1 = cable_solution_clone(bp);
  }
  memrun_free(r);
  if (!bp1) return;
  for (int dir = -1; dir <= 1; dir += 2) {
    engine_constants(&c, 50, 5);
    c.isw = -1;
    c.ds = 0.05 * dir; c.dsmin = 1e-6; c.dsmax = 0.2; c.nmx = 25; c.npr = 5;
    c.isp = 0; c.ilp = 0;
    memrun_run(cable_testproblem_elastica(), &c, bp1, r);
    test_true("elastica buckled branch computed", r->nsol >= 4);
    double worst = 0, amp = 0;
    for (int i = 1; i < r->nsol; i++) {
      const cable_solution *s = r->sol[i];
      double th0 = s->u[0], lam = s->par[0];
      double K = gsl_sf_ellint_Kcomp(sin(fabs(th0) / 2), GSL_PREC_DOUBLE);
      worst = fmax(worst, fabs(lam - 4 * K * K) / lam);
      amp = fmax(amp, fabs(th0));
    }
    char what[96];
    snprintf(what, sizeof what, "elastica branch (DS sign %+d) leaves the trivial branch", dir);
    test_true(what, amp > 0.3);
    snprintf(what, sizeof what, "elastica: lambda = 4 K(sin(theta0/2))^2 on the branch (DS %+d)", dir);
    test_le(what, worst, 1e-8);
    memrun_free(r);
  }
  cable_solution_free(bp1);
}

/* Regressions on the straight elastica, whose extended matrices are exactly
 * structured, so that a branch point can meet an exact zero pivot:
 *  - at NTST = 50, NCOL = 4 the regula falsi on the BP test lands on
 *    lambda = pi^2 to working precision; the located point was dropped
 *    without a note (the branch went on with two BPs);
 *  - switching (ISW=-1) at BP1 (NTST 30 and 40, NCOL 4) and at BP3
 *    (NTST 50, NCOL 5) failed with "no test functions at the starting
 *    point": [F_x; phi^T] is singular at a BP (the old tangent is in its
 *    kernel) and the factorisation met an exact zero pivot.
 * Every BP below lambda = 100 must be found and every switch must start. */
static void test_elastica_exact_zero_pivot(memrun *r)
{
  static const int meshes[][2] = {{50, 4}, {50, 5}, {40, 4}, {30, 4}};
  for (size_t m = 0; m < sizeof meshes / sizeof meshes[0]; m++) {
    int ntst = meshes[m][0], ncol = meshes[m][1];
    char what[700];
    cable_constants c;
    elastica_trivial_constants(&c, ntst, ncol);
    memrun_run(cable_testproblem_elastica(), &c, NULL, r);
    snprintf(what, sizeof what, "elastica NTST=%d NCOL=%d: three branch points below lambda = 100", ntst, ncol);
    test_int(what, memrun_count(r, CABLE_TY_BP), 3);
    cable_solution *bp[3] = {NULL, NULL, NULL};
    for (int k = 0; k < 3; k++) {
      const cable_solution *b = memrun_find(r, CABLE_TY_BP, k);
      if (b) bp[k] = cable_solution_clone(b);
    }
    memrun_free(r);
    for (int k = 0; k < 3; k++) {
      if (!bp[k]) continue;
      double exact = ((k + 1) * M_PI) * ((k + 1) * M_PI);
      /* Gauss collocation's eigenvalue error O(h^(2 NCOL)) (n pi)^(2 NCOL + 2):
         at most 0.033^8 (3 pi)^10 ~ 2e-9 relative here */
      snprintf(what, sizeof what, "elastica NTST=%d NCOL=%d: BP%d at (%d pi)^2", ntst, ncol, k + 1, k + 1);
      test_rel(what, bp[k]->par[0], exact, 1e-8);
      engine_constants(&c, ntst, ncol);
      c.isw = -1;
      c.ds = 0.05; c.dsmin = 1e-6; c.dsmax = 0.2; c.nmx = 10;
      c.isp = 0; c.ilp = 0;
      c.epss = 1e-10;
      memrun_run(cable_testproblem_elastica(), &c, bp[k], r);
      snprintf(what, sizeof what, "elastica NTST=%d NCOL=%d: switching at BP%d starts and runs (%s)", ntst, ncol,
               k + 1, r->err);
      test_true(what, r->status > 0 && r->n == 10);
      snprintf(what, sizeof what, "elastica NTST=%d NCOL=%d: the branch from BP%d leaves theta = 0", ntst, ncol, k + 1);
      test_true(what, r->n == 10 && r->l2[9] > 0.5);
      memrun_free(r);
      cable_solution_free(bp[k]);
    }
  }
}

/* Fixed steps (IADS = 0) long enough to hold two branch points: from
 * lambda = 1, DS = 35, 40 and 45 steps (the trivial branch's tangent is pure
 * lambda) put BP1 and BP2 inside the step from lambda = 1 for DS = 40 and 45,
 * where the determinant keeps its sign; DS = 35 puts BP1 alone in a 35-wide
 * bracket; DS = 99 puts all three in that step.  The run starts one step
 * earlier, at lambda = 1 - DS (PAR override), because no special point is
 * reported in a run's first step (AUTO's rule, test_auto_semantics.c).
 * Before the pencil test, DS = 45 lost BP1 and BP2 without a word, DS = 40
 * lost BP1, and DS = 35 failed to locate BP1 within ITMX. */
static void test_elastica_fixed_steps(memrun *r)
{
  static const double steps[] = {35.0, 40.0, 45.0, 99.0};
  for (size_t q = 0; q < sizeof steps / sizeof steps[0]; q++) {
    cable_constants c;
    engine_constants(&c, 50, 5);
    c.ds = c.dsmax = steps[q]; c.dsmin = 1e-6; c.iads = 0; c.nmx = 200;
    c.rl1 = 100.0;
    c.isp = 2; c.ilp = 0;
    c.epss = 1e-10;
    c.npar_override = 1;
    c.par_override[0].index = 0;
    c.par_override[0].value = 1.0 - steps[q];
    memrun_run(cable_testproblem_elastica(), &c, NULL, r);
    char what[96];
    /* the step that crosses RL1 = 100 may hold (4 pi)^2 = 158 too: count below 100 */
    int nbp = 0;
    for (int i = 0; i < r->nsol; i++) nbp += r->sol[i]->itp == CABLE_TY_BP && r->sol[i]->par[0] < 100.0;
    snprintf(what, sizeof what, "elastica DS=%g fixed: three branch points below lambda = 100", steps[q]);
    test_int(what, nbp, 3);
    for (int n = 1; n <= 3; n++) {
      const cable_solution *bp = memrun_find(r, CABLE_TY_BP, n - 1);
      snprintf(what, sizeof what, "elastica DS=%g fixed: BP%d at (%d pi)^2", steps[q], n, n);
      /* the same discretisation bound as test_elastica (NTST=50, NCOL=5) */
      if (bp) test_rel(what, bp->par[0], (n * M_PI) * (n * M_PI), 1e-8);
      else test_true(what, 0);
    }
    memrun_free(r);
  }
}

/* int_0^1 u dt of Bratu's exact lower-branch solution with parameter th, by
 * GSL's adaptive Gauss-Kronrod rule (independent of the engine's quadrature). */
static double bratu_exact_u(double t, void *p) { return cable_bratu_exact(0.0, *(const double *)p, t); }

static double bratu_exact_mean(double th)
{
  gsl_integration_workspace *w = gsl_integration_workspace_alloc(100);
  gsl_function F = {bratu_exact_u, &th};
  double res = NAN, err = 0;
  if (w) gsl_integration_qag(&F, 0.0, 1.0, 1e-15, 1e-14, 100, GSL_INTEG_GAUSS61, w, &res, &err);
  gsl_integration_workspace_free(w);
  return res;
}

/* th at the fold: d lambda / d th = 0 on lambda = th^2 / (2 cosh^2(th/4)) gives th tanh(th/4) = 4 */
static double fold_fn(double th, void *p)
{
  (void)p;
  return th * tanh(th / 4.0) - 4.0;
}

static double bratu_fold_theta(void)
{
  gsl_function F = {fold_fn, NULL};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double r = NAN;
  if (s && gsl_root_fsolver_set(s, &F, 3.0, 6.0) == GSL_SUCCESS)
    for (int it = 0; it < 200; it++) {
      gsl_root_fsolver_iterate(s);
      r = gsl_root_fsolver_root(s);
      if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-15) == GSL_SUCCESS)
        break;
    }
  gsl_root_fsolver_free(s);
  return r;
}

/* An integral condition (NINT = 1, NFPR = 2): Bratu with mu = int_0^1 u dt.
 * The lambda branch and its fold are Bratu's; mu at user zeros lambda = 1, 2,
 * 3 and at the fold must equal the mean of the exact solution. */
static void test_integral_condition(memrun *r)
{
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.icp[1] = 1; c.nicp = 2;
  c.ds = 0.1; c.dsmin = 1e-6; c.dsmax = 0.5; c.nmx = 60;
  c.rl1 = 10.0;
  c.ilp = 1; c.isp = 0;
  c.epss = 1e-7;
  c.nuzr = 3;
  for (int k = 0; k < 3; k++) {
    c.uzr[k].par = 0;
    c.uzr[k].value = k + 1.0;
  }
  memrun_run(cable_testproblem_bratu_int(), &c, NULL, r);
  test_true("bratu_int (NINT=1): run ends normally", r->status > 0);
  test_int("bratu_int: three user zeros on the lower branch (and three on the upper)", memrun_count(r, CABLE_TY_UZ), 6);
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  for (int k = 0; k < 3; k++) {
    const cable_solution *s = memrun_find(r, CABLE_TY_UZ, k);
    char what[96];
    snprintf(what, sizeof what, "bratu_int: mu = int u dt at lambda = %d (exact solution, GSL quadrature)", k + 1);
    /* Gauss quadrature of the NCOL=4 collocation polynomial on NTST=20: the
       solution's O(h^(2 NCOL)) = 5e-11 superconvergent error (test_superconvergence)
       sets the level; 1e-9 relative leaves a margin */
    if (s) test_rel(what, s->par[1], bratu_exact_mean(cable_bratu_theta(s->par[0])), 1e-9);
    else test_true(what, 0);
  }
  const cable_solution *lp = memrun_find(r, CABLE_TY_LP, 0);
  test_true("bratu_int: fold found", lp != NULL);
  if (lp) {
    /* the same bounds as test_bratu_fold; mu is stationary in arclength at
       neither end, so its location error is O(EPSS ds) ~ 1e-8 */
    test_abs("bratu_int: fold lambda*", lp->par[0], 3.513830719125162, 1e-9);
    test_rel("bratu_int: mu at the fold", lp->par[1], bratu_exact_mean(bratu_fold_theta()), 1e-7);
  }
  gsl_set_error_handler(old);
  memrun_free(r);
}

/* AUTO's STOP: the straight elastica with STOP = ['BP2'] ends at its second
 * branch point (4 pi^2), which is the branch's last point; RG counts the
 * NPR-labelled points. */
static void test_stop(memrun *r)
{
  cable_constants c;
  elastica_trivial_constants(&c, 50, 5);
  c.nstop = 1; c.stop_on[0] = CABLE_TY_BP; c.stop_count[0] = 2;
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  test_int("STOP=['BP2']: the branch ends with CABLE_END_STOP", r->status, CABLE_END_STOP);
  test_int("STOP=['BP2']: two branch points", memrun_count(r, CABLE_TY_BP), 2);
  test_true("STOP=['BP2']: the last point is the BP at (2 pi)^2",
            r->n > 0 && r->itp[r->n - 1] == CABLE_TY_BP && fabs(r->par[r->n - 1][0] - 4 * M_PI * M_PI) < 1e-6);
  memrun_free(r);
  c.nstop = 1; c.stop_on[0] = CABLE_TY_RG; c.stop_count[0] = 3;
  c.npr = 4; c.isp = 0;
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  test_int("STOP=['RG3'] with NPR=4: ends with CABLE_END_STOP", r->status, CABLE_END_STOP);
  test_int("STOP=['RG3'] with NPR=4: ends at point 12", r->n, 12);
  memrun_free(r);
}

/* Bratu's branch from u = 0, stopped (UZSTOP) at lambda = 1 on its lower part. */
static void bratu_to_lambda1_constants(cable_constants *c, int ntst, int ncol)
{
  engine_constants(c, ntst, ncol);
  c->ds = 0.1; c->dsmin = 1e-6; c->dsmax = 0.2; c->nmx = 100;
  c->isp = 0; c->ilp = 0;
  c->nuzr = 1;
  c->uzr[0].par = 0; c->uzr[0].value = 1.0; c->uzr[0].stop = 1;
  c->epss = 1e-10;
}

/* max mesh-point error of the Bratu solution at lambda ~ 1 */
static double bratu_error(memrun *r, int ntst, int ncol)
{
  cable_constants c;
  bratu_to_lambda1_constants(&c, ntst, ncol);
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  const cable_solution *s = memrun_find(r, CABLE_TY_UZ, 0);
  double err = INFINITY;
  if (s) {
    double lam = s->par[0], th = cable_bratu_theta(lam);
    err = 0;
    for (int j = 0; j <= ntst; j++) {
      double t = s->t[j * ncol];
      err = fmax(err, fabs(s->u[(size_t)(j * ncol) * 2] - cable_bratu_exact(lam, th, t)));
    }
  }
  memrun_free(r);
  return err;
}

/* The per-solution error estimate (err_est, cont_mesh.c) against the true
 * max-norm error of the collocation solution over [0,1] (the piecewise
 * polynomial sampled at ERR_SAMPLES + 1 points per interval against Bratu's
 * closed form) at lambda = 1, NCOL = 2..7, three meshes each.  Measured
 * ratios estimate / true: 1.04 (NTST=4, NCOL=3) to 8.4 (NTST=4, NCOL=7).
 * The estimate is kappa h^(NCOL+1) |u^(NCOL+1)| from divided differences of
 * the NCOL-th derivative, i.e. the interpolation error of the exact solution
 * at equally spaced nodes; the collocation error's own constant differs from
 * kappa by an NCOL-dependent factor, hence the spread.  Stated factor: the
 * estimate lies between 1/2 and 10 times the true error (it is conservative,
 * or at worst a factor 2 optimistic). */
#define ERR_SAMPLES 50
static void test_error_estimate(memrun *r)
{
  static const int meshes[6][3] = {{8, 16, 32}, {4, 8, 16}, {4, 8, 12}, {3, 5, 8}, {2, 3, 5}, {2, 3, 4}};
  double lo = INFINITY, hi = 0;
  for (int ncol = 2; ncol <= 7; ncol++)
    for (int q = 0; q < 3; q++) {
      int ntst = meshes[ncol - 2][q];
      cable_constants c;
      bratu_to_lambda1_constants(&c, ntst, ncol);
      memrun_run(cable_testproblem_bratu(), &c, NULL, r);
      const cable_solution *s = memrun_find(r, CABLE_TY_UZ, 0);
      if (!s) {
        test_true("error estimate: solution at lambda = 1", 0);
        memrun_free(r);
        continue;
      }
      double lam = s->par[0], th = cable_bratu_theta(lam), err = 0;
      for (int j = 0; j < ntst; j++) {
        double t0 = s->t[j * ncol], t1 = s->t[(j + 1) * ncol];
        for (int k = 0; k <= ERR_SAMPLES; k++) {
          double t = t0 + (t1 - t0) * k / ERR_SAMPLES, u[2];
          colloc_interp(2, ntst, ncol, s->t, s->u, t, u);
          err = fmax(err, fabs(u[0] - cable_bratu_exact(lam, th, t)));
        }
      }
      double ratio = s->err_est / err;
      lo = fmin(lo, ratio);
      hi = fmax(hi, ratio);
      char what[128];
      snprintf(what, sizeof what, "error estimate NTST=%d NCOL=%d: estimate %.3e / true max error %.3e = %.2f in [0.5, 10]",
               ntst, ncol, s->err_est, err, ratio);
      test_true(what, ratio >= 0.5 && ratio <= 10.0);
      memrun_free(r);
    }
  printf("error estimate / true error over all meshes: %.2f .. %.2f\n", lo, hi);
}

static void test_superconvergence(memrun *r)
{
  /* mesh sizes chosen so that errors stay well above round-off (1e-14) */
  static const int meshes[4][3] = {{8, 16, 32}, {4, 8, 16}, {4, 6, 8}, {2, 3, 4}};
  for (int ncol = 2; ncol <= 5; ncol++) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < 3; k++) {
      int ntst = meshes[ncol - 2][k];
      double e = bratu_error(r, ntst, ncol), x = log(1.0 / ntst), y = log(e);
      sx += x; sy += y; sxx += x * x; sxy += x * y;
    }
    double slope = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
    char what[80];
    snprintf(what, sizeof what, "superconvergence NCOL=%d: slope %.2f vs 2 NCOL = %d", ncol, slope, 2 * ncol);
    /* the asymptotic rate is approached from either side on coarse meshes */
    test_abs(what, slope, 2.0 * ncol, 0.6);
  }
}

/* theta1'' + lambda sin theta1 = 0 and theta2'' + lambda sin theta2 = 0,
   theta_i'(0) = theta_i'(1) = 0: the trivial branch has double branch points. */
static int double_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                       double *f, double *dfdu, double *dfdp, void *params)
{
  const cable_problem *e = cable_testproblem_elastica();
  int rc = e->func(2, u, icp, par, 0, f, NULL, NULL, params);
  rc |= e->func(2, u + 2, icp, par, 0, f + 2, NULL, NULL, params);
  (void)ndim; (void)ijac; (void)dfdu; (void)dfdp;
  return rc;
}

static int double_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                       const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[1]; fb[1] = u1[1]; fb[2] = u0[3]; fb[3] = u1[3];
  return 0;
}

static int double_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 1.0;
  return 0;
}

static void test_double_bp(memrun *r)
{
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = "double-elastica", .ndim = 4, .nbc = 4, .npar = 1,
                      .func = double_func, .bcnd = double_bcnd, .stpnt = double_stpnt};
  cable_constants c;
  engine_constants(&c, 40, 4);
  c.jac = 0; /* finite-difference Jacobians: the problem provides none */
  c.ds = 0.5; c.dsmin = 1e-6; c.dsmax = 3.0; c.nmx = 200;
  c.rl1 = 45.0;
  c.isp = 2;
  c.epss = 1e-9;
  memrun_run(&pb, &c, NULL, r);
  test_true("double elastica: branch ends at RL1", r->status == CABLE_END_BOUNDS);
  test_int("double elastica: two double branch points below lambda = 45", memrun_count(r, CABLE_TY_BP), 2);
  int nbp, nfields = memrun_bp_fields(r, CABLE_BP_DOUBLE, 2, &nbp);
  test_true("double elastica: every BP point says kind double, multiplicity 2 (the point's fields)",
            nbp == 2 && nfields == 2);
  for (int n = 1; n <= 2; n++) {
    const cable_solution *bp = memrun_find(r, CABLE_TY_BP, n - 1);
    char what[80];
    snprintf(what, sizeof what, "double elastica BP%d at (%d pi)^2 (det keeps its sign)", n, n);
    /* located by minimising sigma_1 to EPSS in arclength; discretisation error
       (0.025)^8 (n pi)^10 < 1e-8 */
    if (bp) test_rel(what, bp->par[0], (n * M_PI) * (n * M_PI), 1e-7);
  }
  const cable_solution *bp1 = memrun_find(r, CABLE_TY_BP, 0);
  cable_solution *start = bp1 ? cable_solution_clone(bp1) : NULL;
  memrun_free(r);
  if (!start) return;
  /* switching at the double BP.  The kernel is spanned by (cos pi t, 0) and
     (0, cos pi t) in (theta1, theta2); the canonical basis (cont_switch.c,
     rule 1 on U(1) = theta1) is e1 = only theta1 moves, e2 = only theta2.
     The uncoupled pair's solutions have each theta_i either 0 or a buckled
     elastica at the same lambda, so four branches leave the BP: theta1 alone
     (BPANGLE = 0, and BPDIR = 0), theta2 alone (90, BPDIR = 1), both in phase
     (45: theta1 = theta2) and in antiphase (135: theta1 = -theta2). */
  static const struct {
    double angle;  /* NAN: BPDIR */
    int bpdir;
    int kind;      /* 1: theta1 alone, 2: theta2 alone, 3: theta1 = theta2, 4: theta1 = -theta2 */
    double dsign;  /* DS < 0: the other half of the branch */
  } cases[] = {{0.0, 0, 1, 1}, {90.0, 0, 2, 1}, {45.0, 0, 3, 1}, {135.0, 0, 4, 1},
               {90.0, 0, 2, -1}, {45.0, 0, 3, -1}, {NAN, 0, 1, 1}, {NAN, 1, 2, 1}};
  static const char *const kinds[] = {"", "only theta1 buckles", "only theta2 buckles", "theta1 = theta2",
                                      "theta1 = -theta2"};
  for (size_t q = 0; q < sizeof cases / sizeof cases[0]; q++) {
    engine_constants(&c, 40, 4);
    c.jac = 0; c.isw = -1; c.isp = 0;
    c.bpangle = cases[q].angle;
    c.bpsym = cases[q].bpdir;
    c.ds = 0.05 * cases[q].dsign; c.dsmin = 1e-6; c.dsmax = 0.2; c.nmx = 30; c.npr = 10;
    memrun_run(&pb, &c, start, r);
    double worst = 0, amp1 = 0, amp2 = 0, sum = 0, diff = 0;
    for (int i = 1; i < r->nsol; i++) {
      const cable_solution *s = r->sol[i];
      double lam = s->par[0];
      for (int comp = 0; comp < 4; comp += 2) {
        double th0 = fabs(s->u[comp]);
        if (th0 < 1e-6) continue; /* this elastica stays straight */
        double K = gsl_sf_ellint_Kcomp(sin(th0 / 2), GSL_PREC_DOUBLE);
        worst = fmax(worst, fabs(lam - 4 * K * K) / lam);
      }
      for (int k = 0; k < cable_solution_npts(s); k++) {
        double t1 = s->u[4 * k], t2 = s->u[4 * k + 2];
        amp1 = fmax(amp1, fabs(t1));
        amp2 = fmax(amp2, fabs(t2));
        diff = fmax(diff, fabs(t1 - t2));
        sum = fmax(sum, fabs(t1 + t2));
      }
    }
    char what[160], how[40];
    if (isnan(cases[q].angle)) snprintf(how, sizeof how, "BPDIR=%d DS%c", cases[q].bpdir, cases[q].dsign > 0 ? '+' : '-');
    else snprintf(how, sizeof how, "BPANGLE=%g DS%c", cases[q].angle, cases[q].dsign > 0 ? '+' : '-');
    snprintf(what, sizeof what, "double BP, %s: the branch is computed and buckles (max |theta| %.3f)", how,
             fmax(amp1, amp2));
    test_true(what, r->status > 0 && r->nsol >= 3 && fmax(amp1, amp2) > 0.3);
    /* a straight component is zero to the Newton tolerance (EPSU = 1e-7 relative
       corrections, quadratic convergence leaves far less); a buckled one
       reaches amplitude > 0.3 within 30 steps of 0.05..0.2 */
    int kind = cases[q].kind, ok;
    if (kind == 1) ok = amp1 > 0.3 && amp2 < 1e-6;
    else if (kind == 2) ok = amp2 > 0.3 && amp1 < 1e-6;
    else if (kind == 3) ok = amp1 > 0.3 && diff < 1e-6;
    else ok = amp1 > 0.3 && sum < 1e-6;
    snprintf(what, sizeof what, "double BP, %s: %s (max |theta1| %.3g, |theta2| %.3g, |theta1-theta2| %.3g, "
             "|theta1+theta2| %.3g)", how, kinds[kind], amp1, amp2, diff, sum);
    test_true(what, ok);
    /* orientation (cont_switch.c): e1 and e2 are positive at t = 0 in their
       first non-negligible component, so theta1(0) (kinds 1, 3) or theta2(0)
       (kinds 2, 4: e2 enters 135 degrees with +sin) has the sign of DS */
    const cable_solution *last = r->nsol ? r->sol[r->nsol - 1] : NULL;
    double u0 = last ? last->u[kind == 1 || kind == 3 ? 0 : 2] : 0.0;
    snprintf(what, sizeof what, "double BP, %s: the buckled theta(0) = %.4f has the sign of DS", how, u0);
    test_true(what, u0 * cases[q].dsign > 0.3);
    /* FD Jacobians and NTST=40, NCOL=4: discretisation error (0.025)^8 pi^10 ~ 1e-8 */
    snprintf(what, sizeof what, "double BP, %s: each buckled component on lambda = 4K^2", how);
    test_le(what, worst, 1e-6);
    memrun_free(r);
  }
  cable_solution_free(start);
}

int main(void)
{
  memrun *r = calloc(1, sizeof *r);
  test_bratu_fold(r);
  test_elastica(r);
  test_elastica_exact_zero_pivot(r);
  test_stop(r);
  test_elastica_fixed_steps(r);
  test_integral_condition(r);
  test_superconvergence(r);
  test_error_estimate(r);
  test_double_bp(r);
  free(r);
  return test_summary();
}
