/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Fold continuation (ISW = 2, continuation/cable_fold.h) against a closed
 * form.  The generalised Bratu problem
 *     u'' + lambda e^u = 0,   u(0) = u(1) = a
 * becomes Bratu's own with w = u - a and lambda e^a in place of lambda, so
 * its fold curve in (lambda, a) is
 *     lambda = lambda* e^(-a),   max u = a + 2 ln cosh(y),
 * lambda* = 8 y^2 / cosh^2(y) with y tanh y = 1 (doc/fold-continuation.md).
 * The closed form is checked two ways: lambda* from Newton on y tanh y = 1
 * against the 30-digit value, and the one-parameter branch at fixed a = 1
 * (no fold code involved) against lambda* / e.  Then the fold curve from
 * the LP at a = 0, in both directions, with a UZ at a = 1; the same with an
 * integral condition (a second free parameter mu = int u dt, so the null
 * vector has a parameter component: the w slot); bad starts. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_cont.h"
#include "cable/cable_fold.h"
#include "engine_util.h"
#include "harness.h"

#define BRATU_FOLD_LAMBDA 3.5138307191251612062   /* 30-digit mpmath value */
/* NTST = 20, NCOL = 4 without adaptation: lambda at a fold converges as
 * h^(2 NCOL) = 20^-8 ~ 4e-11 (superconvergence of the parameters); the fold
 * system's directional differences add O(1e-11); the tolerance 1e-8 is the
 * issue's. */
#define FOLD_TOL 1e-8

/* lambda* two ways: Newton on g(y) = y tanh y - 1 */
static double bratu_lambda_star(void)
{
  double y = 1.2;
  for (int it = 0; it < 50; it++) {
    double t = tanh(y), g = y * t - 1.0, dg = t + y * (1.0 - t * t);
    double dy = g / dg;
    y -= dy;
    if (fabs(dy) < 1e-16 * y) break;
  }
  double c = cosh(y);
  return 8.0 * y * y / (c * c);
}

static double bratu_umax_star(void)
{
  double y = 1.2;
  for (int it = 0; it < 50; it++) {
    double t = tanh(y);
    y -= (y * t - 1.0) / (t + y * (1.0 - t * t));
  }
  return 2.0 * log(cosh(y));
}

/* u1' = u2, u2' = -lambda e^u1; PAR(1) = lambda, PAR(2) = a (the boundary
 * value), PAR(3) = mu (with the integral condition). */
static int gb_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                   double *dfdp, void *params)
{
  (void)icp; (void)params;
  double e = exp(u[0]);
  if (!isfinite(e)) return 1;
  f[0] = u[1];
  f[1] = -par[0] * e;
  if (ijac >= 1) {
    dfdu[0] = 0.0; dfdu[1] = -par[0] * e;
    dfdu[ndim] = 1.0; dfdu[1 + ndim] = 0.0;
  }
  if (ijac >= 2) {
    for (int k = 0; k < 3 * ndim; k++) dfdp[k] = 0.0;
    dfdp[1] = -e;
  }
  return 0;
}

static int gb_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                   double *fb, double *dbc, void *params)
{
  (void)ndim; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[0] - par[1];
  fb[1] = u1[0] - par[1];
  return 0;
}

static int gb_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                   const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  (void)ndim; (void)icp; (void)nint; (void)uold; (void)udot; (void)upold; (void)ijac; (void)dint; (void)params;
  fi[0] = u[0] - par[2];
  return 0;
}

static int gb_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)t; (void)params;
  u[0] = u[1] = 0.0;
  par[0] = par[1] = par[2] = 0.0;
  return 0;
}

static const char *const gb_names[] = {"lambda", "a", "mu"};

static cable_problem gb_problem(int with_integral)
{
  cable_problem pb = {
      .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "bratu_bc",
      .description = "u'' + lambda e^u = 0, u(0) = u(1) = a", .ndim = 2, .nbc = 2, .nint = with_integral, .npar = 3,
      .parnames = gb_names, .func = gb_func, .bcnd = gb_bcnd, .icnd = with_integral ? gb_icnd : NULL,
      .stpnt = gb_stpnt, .func_has_jac = 1};
  return pb;
}

static void base_constants(cable_constants *c)
{
  engine_constants(c, 20, 4);
  c->ds = 0.1; c->dsmin = 1e-5; c->dsmax = 0.5; c->nmx = 60;
  c->rl0 = -0.01; c->rl1 = 5.0;
  c->ilp = 1; c->isp = 0;
  c->epsl = c->epsu = 1e-10; c->epss = 1e-7;
}

/* The fold curve from lp: every point on lambda = lambda* e^(-a); a UZ at a = 1
 * (or -0.5 going the other way); no LP or BP on it. */
static void fold_curve(const cable_problem *pb, const cable_solution *lp, int k, double ds, double lstar,
                       const char *tag)
{
  cable_constants c;
  base_constants(&c);
  c.isw = 2;
  c.icp[0] = 0; c.icp[1] = 1; c.nicp = 2;
  if (k == 2) { c.icp[1] = 2; c.icp[2] = 1; c.nicp = 3; }   /* AUTO's order [lambda, mu, a]: p1, p2, q */
  c.ds = ds; c.dsmax = 0.5; c.nmx = 200; c.npr = 5;
  c.rl0 = 0.5; c.rl1 = 6.0;
  c.ilp = 1; c.isp = 2;
  c.nuzr = 1;
  c.uzr[0].par = 1; c.uzr[0].value = ds > 0 ? -0.5 : 1.0; c.uzr[0].stop = 0;
  int st = 0;
  char msg[300];
  cable_fold *f = cable_fold_alloc(pb, &c, lp, &st, msg, sizeof msg);
  char what[1000];
  snprintf(what, sizeof what, "%s: the fold problem is set up (%s)", tag, f ? "ok" : msg);
  test_true(what, f != NULL);
  if (!f) return;
  test_int("  extended NDIM, NBC, NINT", cable_fold_problem(f)->ndim * 100 + cable_fold_problem(f)->nbc * 10 +
                                             cable_fold_problem(f)->nint, 400 + 40 + (2 * pb->nint + 1));
  static memrun r;
  memrun_run(cable_fold_problem(f), cable_fold_constants(f), NULL, &r);
  snprintf(what, sizeof what, "%s: the curve ends at RL0 = 0.5 or RL1 = 6 in lambda (%d points; %s)", tag, r.n, r.err);
  test_true(what, r.status == CABLE_END_BOUNDS && r.n > 5);
  double worst = 0.0, amin = 1e9, amax = -1e9, worst_u = 0.0;
  for (int i = 0; i < r.n; i++) {
    double lam = r.par[i][0], a = r.par[i][1];
    worst = fmax(worst, fabs(lam - lstar * exp(-a)) / lam);
    amin = fmin(amin, a);
    amax = fmax(amax, a);
  }
  for (int i = 0; i < r.nsol; i++) {
    /* max u = u(1/2): a mesh point (NTST even, no adaptation) */
    const cable_solution *s = r.sol[i];
    double um = -1e9;
    for (int m = 0; m < cable_solution_npts(s); m++) um = fmax(um, s->u[m * s->ndim]);
    worst_u = fmax(worst_u, fabs(um - (s->par[1] + bratu_umax_star())));
  }
  snprintf(what, sizeof what, "%s: every point on lambda = lambda* e^-a (a in [%.3f, %.3f]), max rel. error", tag,
           amin, amax);
  test_le(what, worst, FOLD_TOL);
  /* lambda = 6 at a = -0.535, lambda = 0.5 at a = 1.950 */
  snprintf(what, sizeof what, "%s: the curve reaches a = %s", tag, ds > 0 ? "-0.53" : "1.9");
  test_true(what, ds > 0 ? amin < -0.53 : amax > 1.9);
  snprintf(what, sizeof what, "%s: max u = a + 2 ln cosh y at every labelled point, max abs. error", tag);
  test_le(what, worst_u, FOLD_TOL);
  const cable_solution *uz = memrun_find(&r, CABLE_TY_UZ, 0);
  snprintf(what, sizeof what, "%s: the UZ at a = %g has AUTO's fold-curve type -54", tag, c.uzr[0].value);
  test_int(what, uz ? uz->itp : 0, -54);
  snprintf(what, sizeof what, "%s: at the UZ, lambda = lambda* e^-a", tag);
  test_rel(what, uz ? uz->par[0] : (double)NAN, lstar * exp(-c.uzr[0].value), FOLD_TOL);
  int nlp = 0, nbp = 0;
  for (int i = 0; i < r.n; i++) {
    nlp += r.itp[i] % 10 == CABLE_TY_LP;
    nbp += r.itp[i] % 10 == CABLE_TY_BP;
  }
  snprintf(what, sizeof what, "%s: no LP and no BP on the fold curve (lambda* e^-a is monotone)", tag);
  test_int(what, nlp + nbp, 0);
  snprintf(what, sizeof what, "%s: the start is AUTO's EP of a fold curve (59)", tag);
  test_int(what, r.nsol > 0 ? r.sol[0]->itp : 0, 59);
  memrun_free(&r);
  cable_fold_free(f);
}

static void test_closed_form(double lstar)
{
  test_rel("lambda* from y tanh y = 1 (Newton) against the 30-digit value", lstar, BRATU_FOLD_LAMBDA, 1e-15);
  /* the one-parameter branch at a = 1: its LP is at lambda* / e */
  cable_problem pb = gb_problem(0);
  cable_constants c;
  base_constants(&c);
  c.npar_override = 1;
  c.par_override[0].index = 1;
  c.par_override[0].value = 1.0;
  static memrun r;
  memrun_run(&pb, &c, NULL, &r);
  const cable_solution *lp = memrun_find(&r, CABLE_TY_LP, 0);
  test_rel("closed form, second way: the LP of the branch at a = 1 is at lambda* / e", lp ? lp->par[0] : (double)NAN,
           lstar * exp(-1.0), FOLD_TOL);
  memrun_free(&r);
}

/* u(0) = b, u(1) = -b: t -> 1 - t maps b to -b, so the fold curve lambda(b)
 * is even and does not move in lambda at b = 0 (AUTO's demo int has the same
 * symmetry, q = PAR(2) in u(0) - u(1) = q).  There the fold system at fixed
 * lambda is singular (lambda = lambda* is a double root in b); the start is
 * converged at fixed q = b instead (cont_engine.c, start_fixpar). */
static int ab_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                   double *fb, double *dbc, void *params)
{
  (void)ndim; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[0] - par[1];
  fb[1] = u1[0] + par[1];
  return 0;
}

/* lambda of the LP of the ordinary branch at fixed b (no fold code) */
static double ab_branch_lp(const cable_problem *pb, double b, cable_solution **lp_out)
{
  cable_constants c;
  base_constants(&c);
  c.npar_override = 1;
  c.par_override[0].index = 1;
  c.par_override[0].value = b;
  static memrun r;
  memrun_run(pb, &c, NULL, &r);
  const cable_solution *lp = memrun_find(&r, CABLE_TY_LP, 0);
  double lam = lp ? lp->par[0] : (double)NAN;
  if (lp_out) *lp_out = lp ? cable_solution_clone(lp) : NULL;
  memrun_free(&r);
  return lam;
}

static void test_even_fold_curve(double lstar)
{
  cable_problem pb = gb_problem(0);
  pb.bcnd = ab_bcnd;
  pb.description = "u'' + lambda e^u = 0, u(0) = b, u(1) = -b";
  cable_solution *lp = NULL;
  test_rel("even fold curve: the LP at b = 0 is Bratu's", ab_branch_lp(&pb, 0.0, &lp), lstar, FOLD_TOL);
  double lam_half = ab_branch_lp(&pb, 0.5, NULL);
  if (!lp) return;
  for (int dir = -1; dir <= 1; dir += 2) {
    cable_constants c;
    base_constants(&c);
    c.isw = 2;
    c.icp[0] = 0; c.icp[1] = 1; c.nicp = 2;
    c.ds = 0.1 * dir; c.dsmax = 0.2; c.nmx = 40; c.npr = 100;
    c.rl0 = 0.5; c.rl1 = 6.0;
    c.nuzr = 2;
    c.uzr[0].par = 1; c.uzr[0].value = 0.5; c.uzr[0].stop = 0;
    c.uzr[1].par = 1; c.uzr[1].value = -0.5; c.uzr[1].stop = 0;
    int st = 0;
    char msg[300], what[600];
    cable_fold *f = cable_fold_alloc(&pb, &c, lp, &st, msg, sizeof msg);
    test_true("even fold curve: the fold problem is set up", f != NULL);
    if (!f) break;
    static memrun r;
    memrun_run(cable_fold_problem(f), cable_fold_constants(f), NULL, &r);
    snprintf(what, sizeof what, "even fold curve, DS = %+.1f: the start converges and the curve goes on (%d points; %s)",
             c.ds, r.n, r.err);
    test_true(what, r.n > 5 && (r.status == CABLE_END_NMX || r.status == CABLE_END_BOUNDS));
    const cable_solution *ep = r.nsol > 0 ? r.sol[0] : NULL;
    test_rel("  its start is the LP (lambda = lambda*)", ep ? ep->par[0] : (double)NAN, lstar, FOLD_TOL);
    test_le("  at b = 0 (the start is converged at fixed b)", ep ? fabs(ep->par[1]) : 1.0, 1e-14);
    const cable_solution *uz = memrun_find(&r, CABLE_TY_UZ, 0);
    /* DS > 0: b increases (lambda does not move at the start); DS < 0: it decreases */
    snprintf(what, sizeof what, "  the first UZ is at b = %+.1f", 0.5 * dir);
    test_rel(what, uz ? uz->par[1] : (double)NAN, 0.5 * dir, 1e-10);   /* located to EPSL = 1e-10 */
    test_rel("  there lambda is the LP of the branch at fixed b = 0.5 (the fold curve is even)",
             uz ? uz->par[0] : (double)NAN, lam_half, FOLD_TOL);
    memrun_free(&r);
    cable_fold_free(f);
  }
  cable_solution_free(lp);
}

/* AUTO's runs at an LP (the session's ISW=2 dispatch, doc/fold-continuation.md
 * "AUTO's runs"): the first run generates the starting data, five steps along
 * the null vector's norm N at fixed q, the LP's u and lambda unchanged, one
 * label (the EP, type 59) and an unlabelled start, N growing from a small
 * value (AUTO's from 0); the L2-NORM and MAX U
 * columns are the problem's u only.  The fold curve restarted from that EP
 * (N fixed at its value) is lambda* e^-a, a UZ on it at the closed form. */
static void test_auto_runs(const cable_problem *pb, const cable_solution *lp, double lp_l2, double lstar)
{
  cable_constants c;
  base_constants(&c);
  c.isw = 2;
  c.icp[0] = 0; c.icp[1] = 1; c.nicp = 2;
  c.nmx = 200; c.ilp = 1; c.isp = 2;
  c.rl0 = 0.5; c.rl1 = 6.0;
  c.npar = pb->npar;   /* N in PAR(4): inside memrun's parameter columns */
  int st = 0;
  char msg[300] = "", what[600];
  cable_fold *f = cable_fold_alloc(pb, &c, lp, &st, msg, sizeof msg);
  cable_error serr;
  cable_error_clear(&serr);
  int rc = f ? cable_fold_starting_data(f, &serr) : -1;
  snprintf(what, sizeof what, "AUTO's runs: the starting-data problem is set up (%s)", rc ? (f ? serr.msg : msg) : "ok");
  if (!test_true(what, rc == 0)) {
    cable_fold_free(f);
    return;
  }
  const cable_constants *cs = cable_fold_constants(f);
  int nslot = cs->icp[1];
  test_true("  its constants: ISW = -2, NMX = 5, ILP = ISP = 0, N free in place of a, a printed",
            cs->isw == -2 && cs->nmx == 5 && cs->ilp == 0 && cs->isp == 0 && cs->icp[0] == 0 &&
                nslot == cable_fold_problem(f)->npar - 1 && cs->nicp == 3 && cs->icp[2] == 1);
  static memrun r;
  memrun_run(cable_fold_problem(f), cs, NULL, &r);
  snprintf(what, sizeof what, "  five points (%d; %s)", r.n, r.err);
  test_int(what, r.n, 5);
  int nlab = 0;
  for (int i = 0; i < r.n; i++) nlab += r.lab[i] > 0;
  test_int("  one label", nlab, 1);
  test_true("  the start unlabelled, the last point the EP of type 59", r.n == 5 && r.lab[0] == 0 && r.itp[4] == 59);
  double dl = 0, dl2 = 0, da = 0;
  int ngrow = 1;
  for (int i = 0; i < r.n; i++) {
    dl = fmax(dl, fabs(r.par[i][0] - lstar) / lstar);
    dl2 = fmax(dl2, fabs(r.l2[i] - lp_l2));
    da = fmax(da, fabs(r.par[i][1]));
    if (i > 0) ngrow &= r.par[i][nslot] > r.par[i - 1][nslot];
  }
  test_le("  lambda stays at lambda* (max rel. error)", dl, FOLD_TOL);
  test_le("  a stays 0 (q is fixed)", da, 0.0);
  test_le("  L2-NORM is the LP's (u only, not the null vector): max abs. difference", dl2, 1e-9);
  test_true("  N grows from CABLE_FOLD_START_NORM at every step", r.par[0][nslot] == CABLE_FOLD_START_NORM && ngrow);
  cable_solution *ep = r.nsol > 0 ? cable_solution_clone(r.sol[r.nsol - 1]) : NULL;
  double n_ep = ep ? ep->par[nslot] : 0;
  memrun_free(&r);
  cable_fold_free(f);
  if (!ep) return;
  /* the next run: from the EP (a fold-curve point), the user's constants */
  c.nuzr = 1;
  c.uzr[0].par = 1; c.uzr[0].value = -0.5; c.uzr[0].stop = 0;
  f = cable_fold_alloc(pb, &c, ep, &st, msg, sizeof msg);
  test_true("AUTO's runs: the fold curve from the EP is set up", f != NULL);
  if (f) {
    test_int("  restarting from the EP is not starting data again", cable_fold_starting_data(f, &serr),
             CABLE_ERR_INPUT);
    test_true("  with the reason in err", serr.status == CABLE_ERR_INPUT && strstr(serr.msg, "already a point") != NULL);
    memrun_run(cable_fold_problem(f), cable_fold_constants(f), cable_fold_start(f), &r);
    snprintf(what, sizeof what, "  the curve runs to RL1 = 6 (%d points; %s)", r.n, r.err);
    test_true(what, r.status == CABLE_END_BOUNDS && r.n > 5);
    double worst = 0;
    for (int i = 0; i < r.n; i++) worst = fmax(worst, fabs(r.par[i][0] - lstar * exp(-r.par[i][1])) / r.par[i][0]);
    test_le("  every point on lambda = lambda* e^-a (max rel. error)", worst, FOLD_TOL);
    test_le("  N stays the starting data's", r.n > 0 ? fabs(r.par[r.n - 1][nslot] - n_ep) : 1.0, 0.0);
    test_true("  the restart is unlabelled", r.n > 0 && r.lab[0] == 0);
    const cable_solution *uz = memrun_find(&r, CABLE_TY_UZ, 0);
    test_int("  the UZ at a = -0.5 has type -54", uz ? uz->itp : 0, -54);
    test_rel("  at the UZ, lambda = lambda* e^0.5", uz ? uz->par[0] : (double)NAN, lstar * exp(0.5), FOLD_TOL);
    memrun_free(&r);
  }
  cable_fold_free(f);
  cable_solution_free(ep);
}

static void test_bad_starts(const cable_problem *pb, const cable_solution *lp, const cable_solution *other)
{
  cable_constants c;
  base_constants(&c);
  c.isw = 2;
  c.icp[0] = 0; c.icp[1] = 1; c.nicp = 2;
  int st = 0;
  char msg[300] = "";
  cable_fold *f = cable_fold_alloc(pb, &c, other, &st, msg, sizeof msg);
  test_true("ISW=2 from a label that is not an LP: refused, the message says so",
            !f && st == CABLE_ERR_INPUT && strstr(msg, "starts from an LP") != NULL);
  cable_fold_free(f);
  c.nicp = 1;
  f = cable_fold_alloc(pb, &c, lp, &st, msg, sizeof msg);
  test_true("ISW=2 with one ICP entry: refused, the message asks for the second parameter",
            !f && st == CABLE_ERR_INPUT && strstr(msg, "ICP must list") != NULL);
  cable_fold_free(f);
  c.nicp = 2;
  f = cable_fold_alloc(pb, &c, NULL, &st, msg, sizeof msg);
  test_true("ISW=2 without a start: refused", !f && st == CABLE_ERR_INPUT);
  cable_fold_free(f);
  /* at a BP: refused, naming the label and branch-point continuation */
  cable_solution *bp = cable_solution_clone(lp);
  if (bp) {
    bp->itp = CABLE_TY_BP;
    bp->lab = 7;
    f = cable_fold_alloc(pb, &c, bp, &st, msg, sizeof msg);
    test_true("cable_fold_alloc at a BP: refused, the message names the label and branch-point continuation",
              !f && st == CABLE_ERR_INPUT && strstr(msg, "at a BP (label 7)") &&
                  strstr(msg, "branch-point continuation"));
    cable_fold_free(f);
    cable_solution_free(bp);
  }
}

int main(void)
{
  double lstar = bratu_lambda_star();
  test_closed_form(lstar);
  test_even_fold_curve(lstar);
  for (int k = 1; k <= 2; k++) {
    cable_problem pb = gb_problem(k - 1);
    cable_constants c;
    base_constants(&c);
    if (k == 2) { c.icp[1] = 2; c.nicp = 2; }
    static memrun r;
    memrun_run(&pb, &c, NULL, &r);
    cable_solution *lp = cable_solution_clone(memrun_find(&r, CABLE_TY_LP, 0));
    cable_solution *ep = cable_solution_clone(memrun_find(&r, CABLE_TY_EP, 0));
    double lp_l2 = (double)NAN;
    for (int i = 0; i < r.n; i++)
      if (r.itp[i] == CABLE_TY_LP) lp_l2 = r.l2[i];
    memrun_free(&r);
    test_rel(k == 1 ? "the LP at a = 0" : "the LP at a = 0 with mu = int u free", lp ? lp->par[0] : (double)NAN,
             lstar, FOLD_TOL);
    if (lp) {
      fold_curve(&pb, lp, k, 0.1, lstar, k == 1 ? "fold curve, DS = +0.1" : "with NINT = 1, DS = +0.1");
      fold_curve(&pb, lp, k, -0.1, lstar, k == 1 ? "fold curve, DS = -0.1" : "with NINT = 1, DS = -0.1");
      if (k == 1 && ep) test_bad_starts(&pb, lp, ep);
      if (k == 1) test_auto_runs(&pb, lp, lp_l2, lstar);
    }
    cable_solution_free(lp);
    cable_solution_free(ep);
  }
  return test_summary();
}
