/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Branch-point continuation (continuation/cable_bpcont.h) against a closed
 * form: the elastica theta'' + P L^2 sin theta = 0, theta'(0) = theta'(1) = 0
 * (u1 = theta, u2 = theta'; PAR(1) = P, PAR(2) = L) has the straight rod
 * theta = 0 for every P and L, and its first branch point at P L^2 = pi^2:
 * the curve of branch points is P = (pi / L)^2.  NTST = 20, NCOL = 4: the
 * collocation's error in the parameter is O(h^8), far below the test's
 * 1e-8 (doc/fold-continuation.md, "Branch-point continuation").
 *
 * With an integral condition (NINT = 1): the rod u1' = L u2,
 * u2' = -L (P sin u1 + mu), u1(0) = u1(1) = 0, int u1 dt = 0 (PAR(1) = P,
 * PAR(2) = L, PAR(3) = mu; free P and mu, k = 2).  On u = 0, mu = 0 its
 * branch points are at P L^2 = kappa^2 with kappa = 2 pi n (antisymmetric
 * modes, the adjoint's multiplier omega of the integral condition 0) or
 * tan(kappa/2) = kappa/2 (symmetric modes, omega != 0): the curves of
 * branch points are P = kappa^2 / L^2 (doc/fold-continuation.md,
 * "With integral conditions"). */
#include <math.h>
#include <stdio.h>

#include "cable/cable_bpcont.h"
#include "cable/cable_cont.h"
#include "cable/cable_status.h"
#include "engine_util.h"
#include "harness.h"

#define PI 3.14159265358979323846
#define BP_TOL 1e-8

static int el_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                   double *dfdp, void *params)
{
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp; (void)params;
  f[0] = u[1];
  f[1] = -par[0] * par[1] * par[1] * sin(u[0]);
  return 0;
}

static int el_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                   double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[1];
  fb[1] = u1[1];
  return 0;
}

static int el_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)t; (void)params;
  u[0] = u[1] = 0.0;
  par[0] = 1.0;
  par[1] = 1.0;
  return 0;
}

static int cl_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                   double *dfdp, void *params)
{
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp; (void)params;
  f[0] = par[1] * u[1];
  f[1] = -par[1] * (par[0] * sin(u[0]) + par[2]);
  return 0;
}

static int cl_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                   double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[0];
  fb[1] = u1[0];
  return 0;
}

static int cl_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                   const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nint; (void)uold; (void)udot; (void)upold; (void)ijac; (void)dint;
  (void)params;
  fi[0] = u[0];
  return 0;
}

static int cl_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)t; (void)params;
  u[0] = u[1] = 0.0;
  par[0] = 1.0;
  par[1] = 1.0;
  par[2] = 0.0;
  return 0;
}

/* the first positive root of tan x = x, by Newton from 4.49 */
static double tan_root(void)
{
  double x = 4.49;
  for (int i = 0; i < 50; i++) x -= (tan(x) - x) / (1.0 / (cos(x) * cos(x)) - 1.0);
  return x;
}

/* NINT = 1: the curves of branch points through the first two BPs of the
   constrained rod, both ways from each, against P = kappa^2 / L^2 */
static void with_integral_condition(void)
{
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "rod_int",
                      .description = "u1' = L u2, u2' = -L (P sin u1 + mu), int u1 = 0", .ndim = 2, .nbc = 2,
                      .nint = 1, .npar = 3, .func = cl_func, .bcnd = cl_bcnd, .icnd = cl_icnd, .stpnt = cl_stpnt};
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.icp[0] = 0; c.icp[1] = 2; c.nicp = 2;
  c.ds = 0.5; c.dsmin = 1e-5; c.dsmax = 5.0; c.nmx = 100;
  c.rl0 = 0.0; c.rl1 = 100.0;
  c.ilp = 0; c.isp = 2;
  c.epsl = c.epsu = 1e-10; c.epss = 1e-7;
  c.npar = 3;
  static memrun r;
  memrun_run(&pb, &c, NULL, &r);
  double kap[2] = {2 * PI, 2 * tan_root()};
  const char *mode[2] = {"antisymmetric", "symmetric"};
  for (int b = 0; b < 2; b++) {
    const cable_solution *bp0 = memrun_find(&r, CABLE_TY_BP, b);
    char what[600];
    snprintf(what, sizeof what, "NINT=1: BP%d (%s mode) at P = kappa^2 = %.9f (L = 1)", b + 1, mode[b],
             kap[b] * kap[b]);
    if (!test_rel(what, bp0 ? bp0->par[0] : (double)NAN, kap[b] * kap[b], BP_TOL)) continue;
    for (int dir = -1; dir <= 1; dir += 2) {
      cable_constants cb = c;
      cb.isw = 2;
      cb.icp[0] = 0; cb.icp[1] = 2; cb.icp[2] = 1; cb.nicp = 3;   /* [P, mu, L]: p1, p2, q (AUTO's order) */
      cb.ds = 0.05 * dir; cb.dsmax = 2.0; cb.nmx = 40; cb.npr = 5;
      cb.rl0 = 5.0; cb.rl1 = 400.0;
      cb.ilp = 0; cb.isp = 0;
      cb.nuzr = 1;
      cb.uzr[0].par = 1; cb.uzr[0].value = dir > 0 ? 0.9 : 1.1; cb.uzr[0].stop = 0;
      int st = 0;
      char msg[400];
      cable_bpcont *f = cable_bpcont_alloc(&pb, &cb, bp0, &st, msg, sizeof msg);
      snprintf(what, sizeof what, "NINT=1, BP%d, DS = %+.2f: the branch-point problem is set up (%s)", b + 1, cb.ds,
               f ? "ok" : msg);
      if (!test_true(what, f != NULL)) continue;
      static memrun rc;
      memrun_run(cable_bpcont_problem(f), cable_bpcont_constants(f), NULL, &rc);
      snprintf(what, sizeof what, "NINT=1, BP%d, DS = %+.2f: the curve runs (%d points; %s)", b + 1, cb.ds, rc.n,
               rc.err);
      if (test_true(what, rc.n > 5)) {
        /* slots after NPAR = 3: b 3, psi* 4-5, omega 6, d 7-8, a 9 */
        double worst = 0, lmin = 1e9, lmax = -1e9, bmax = 0, mumax = 0, ommin = 1e300;
        for (int i = 0; i < rc.n; i++) {
          double P = rc.par[i][0], L = rc.par[i][1];
          worst = fmax(worst, fabs(P - kap[b] * kap[b] / (L * L)) / fabs(P));
          lmin = fmin(lmin, L);
          lmax = fmax(lmax, L);
          bmax = fmax(bmax, fabs(rc.par[i][3]));
          mumax = fmax(mumax, fabs(rc.par[i][2]));
          ommin = fmin(ommin, fabs(rc.par[i][6]));
        }
        snprintf(what, sizeof what, "NINT=1, BP%d, DS = %+.2f: every point on P = kappa^2/L^2 (L in [%.3f, %.3f])",
                 b + 1, cb.ds, lmin, lmax);
        test_le(what, worst, BP_TOL);
        snprintf(what, sizeof what, "NINT=1, BP%d, DS = %+.2f: b and mu stay 0", b + 1, cb.ds);
        test_le(what, fmax(bmax, mumax), 1e-10);
        if (b == 1) {
          /* the symmetric mode's adjoint needs omega: without the integral
             condition's terms this curve does not exist */
          snprintf(what, sizeof what, "NINT=1, BP2, DS = %+.2f: the multiplier omega is nonzero (min |omega| %.3g)",
                   cb.ds, ommin);
          test_true(what, ommin > 1e-3);
        }
        const cable_solution *uz = memrun_find(&rc, CABLE_TY_UZ, 0);
        double L = cb.uzr[0].value;
        snprintf(what, sizeof what, "NINT=1, BP%d, DS = %+.2f: the UZ at L = %g is at P = kappa^2/L^2", b + 1, cb.ds,
                 L);
        test_rel(what, uz ? uz->par[0] : (double)NAN, kap[b] * kap[b] / (L * L), BP_TOL);
      }
      memrun_free(&rc);
      cable_bpcont_free(f);
    }
  }
  memrun_free(&r);
}

int main(void)
{
  with_integral_condition();
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "elastica_l",
                      .description = "theta'' + P L^2 sin theta = 0", .ndim = 2, .nbc = 2, .nint = 0, .npar = 2,
                      .func = el_func, .bcnd = el_bcnd, .stpnt = el_stpnt};
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.ds = 0.5; c.dsmin = 1e-5; c.dsmax = 2.0; c.nmx = 30;
  c.rl0 = 0.0; c.rl1 = 15.0;
  c.ilp = 0; c.isp = 2;
  c.epsl = c.epsu = 1e-10; c.epss = 1e-7;
  c.npar = 2;
  static memrun r;
  memrun_run(&pb, &c, NULL, &r);
  const cable_solution *bp0 = memrun_find(&r, CABLE_TY_BP, 0);
  test_rel("the straight rod's first BP at P = pi^2 (L = 1)", bp0 ? bp0->par[0] : (double)NAN, PI * PI, BP_TOL);
  cable_solution *bp = bp0 ? cable_solution_clone(bp0) : NULL;
  memrun_free(&r);
  if (!bp) return test_summary();
  for (int dir = -1; dir <= 1; dir += 2) {
    cable_constants cb = c;
    cb.isw = 2;
    cb.icp[0] = 0; cb.icp[1] = 1; cb.nicp = 2;
    cb.ds = 0.05 * dir; cb.dsmax = 0.2; cb.nmx = 40; cb.npr = 5;
    cb.rl0 = 2.0; cb.rl1 = 40.0;
    cb.ilp = 0; cb.isp = 0;
    cb.nuzr = 1;
    cb.uzr[0].par = 1; cb.uzr[0].value = dir > 0 ? 0.8 : 1.5; cb.uzr[0].stop = 0;
    int st = 0;
    char msg[400], what[600];
    cable_bpcont *f = cable_bpcont_alloc(&pb, &cb, bp, &st, msg, sizeof msg);
    snprintf(what, sizeof what, "DS = %+.2f: the branch-point problem is set up (%s)", cb.ds, f ? "ok" : msg);
    if (!test_true(what, f != NULL)) continue;
    memrun_run(cable_bpcont_problem(f), cable_bpcont_constants(f), NULL, &r);
    snprintf(what, sizeof what, "DS = %+.2f: the curve runs (%d points; %s)", cb.ds, r.n, r.err);
    if (!test_true(what, r.n > 5)) {
      memrun_free(&r);
      cable_bpcont_free(f);
      continue;
    }
    double worst = 0, lmin = 1e9, lmax = -1e9, bmax = 0;
    for (int i = 0; i < r.n; i++) {
      double P = r.par[i][0], L = r.par[i][1];
      worst = fmax(worst, fabs(P - PI * PI / (L * L)) / fabs(P));
      lmin = fmin(lmin, L);
      lmax = fmax(lmax, L);
      bmax = fmax(bmax, fabs(r.par[i][2]));
    }
    snprintf(what, sizeof what, "DS = %+.2f: every point on P = (pi/L)^2 (L in [%.3f, %.3f]), max rel. error", cb.ds,
             lmin, lmax);
    test_le(what, worst, BP_TOL);
    snprintf(what, sizeof what, "DS = %+.2f: the unfolding parameter b stays 0", cb.ds);
    test_le(what, bmax, 1e-10);
    const cable_solution *uz = memrun_find(&r, CABLE_TY_UZ, 0);
    snprintf(what, sizeof what, "DS = %+.2f: the UZ at L = %g is at P = (pi/L)^2", cb.ds, cb.uzr[0].value);
    test_rel(what, uz ? uz->par[0] : (double)NAN, PI * PI / (cb.uzr[0].value * cb.uzr[0].value), BP_TOL);
    snprintf(what, sizeof what, "DS = %+.2f: AUTO's type codes on a curve of branch points: start 69, UZ -64", cb.ds);
    test_true(what, r.nsol > 0 && r.sol[0]->itp == 69 && uz && uz->itp == -64);
    memrun_free(&r);
    cable_bpcont_free(f);
  }
  /* AUTO's two runs: the starting data at the BP (five points, one label,
     the EP 69; P and L do not move), then the curve from their EP */
  {
    cable_constants cb = c;
    cb.isw = 2;
    cb.icp[0] = 0; cb.icp[1] = 1; cb.nicp = 2;
    cb.ds = 0.05; cb.dsmax = 0.2; cb.nmx = 40;
    cb.rl0 = 2.0; cb.rl1 = 40.0;
    cb.nuzr = 1;
    cb.uzr[0].par = 1; cb.uzr[0].value = 0.8; cb.uzr[0].stop = 0;
    int st = 0;
    char msg[400];
    cable_bpcont *f = cable_bpcont_alloc(&pb, &cb, bp, &st, msg, sizeof msg);
    int rc = f ? cable_bpcont_starting_data(f, NULL) : -1;
    test_true("AUTO's runs: the starting data are set up", rc == 0);
    cable_solution *ep = NULL;
    if (rc == 0) {
      memrun_run(cable_bpcont_problem(f), cable_bpcont_constants(f), NULL, &r);
      double dp = 0;
      for (int i = 0; i < r.n; i++) dp = fmax(dp, fabs(r.par[i][0] - bp->par[0]) + fabs(r.par[i][1] - 1.0));
      test_true("  five points, one label: the EP of type 69, the start unlabelled",
                r.n == 5 && r.nsol == 1 && r.sol[0]->itp == 69 && r.lab[0] == 0);
      test_le("  P and L stay the BP's (P converged at fixed L: to round-off)", dp, 1e-12);
      ep = r.nsol == 1 ? cable_solution_clone(r.sol[0]) : NULL;
      memrun_free(&r);
    }
    cable_bpcont_free(f);
    f = ep ? cable_bpcont_alloc(&pb, &cb, ep, &st, msg, sizeof msg) : NULL;
    test_true("AUTO's runs: the curve from the EP is set up", f != NULL);
    if (f) {
      memrun_run(cable_bpcont_problem(f), cable_bpcont_constants(f), cable_bpcont_start(f), &r);
      const cable_solution *uz = memrun_find(&r, CABLE_TY_UZ, 0);
      test_rel("  its UZ at L = 0.8 is at P = (pi/L)^2", uz ? uz->par[0] : (double)NAN, PI * PI / 0.64, BP_TOL);
      memrun_free(&r);
    }
    cable_bpcont_free(f);
    cable_solution_free(ep);
  }
  cable_solution_free(bp);
  return test_summary();
}
