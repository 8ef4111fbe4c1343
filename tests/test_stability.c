/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The Morse index of a variational BVP (doc/stability.md) against closed forms:
 *  - Bratu (u'' + lambda e^u = 0, u(0) = u(1) = 0) on its exact solutions:
 *    lower branch index 0, upper branch index 1, and the two smallest
 *    eigenvalues of the second variation against an independent computation
 *    (three-point finite differences on a fine grid, LAPACK dstev, Richardson
 *    extrapolated);
 *  - a STAB=1 continuation of Bratu through its fold: index 0 before the LP,
 *    1 after, and the change exactly at the LP;
 *  - the Euler column with its ends on one line (elastica_int): on the straight
 *    state index n for (n pi)^2 < lambda < ((n+1) pi)^2 with sigma_1 = pi^2 -
 *    lambda, the first buckled branch stable (index 0), the second index 1;
 *    without the constraint (elastica) sigma_1 = -lambda, unstable;
 *  - two uncoupled columns: the index jumps by 2 at each (double) branch point
 *    and nowhere else;
 *  - the convergence table of doc/stability.md S5 (printed);
 *  - STAB=1 is refused for a problem that is not variational (file:line:key);
 *  - the b-file of a STAB=1 run: header line STAB = 1, PT < 0 exactly at the
 *    stable points (AUTO's convention), read back by cable_bfile_read; without
 *    STAB nothing of it. */
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/stat.h>

#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_stability.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"

static const double M_PI_ = 3.14159265358979323846;
#ifndef M_PI
#define M_PI M_PI_
#endif

/* ---------------------------------------------------------------- Bratu, exactly */

/* the roots of th = sqrt(2 lambda) cosh(th/4): lower (th < th*) and upper */
static double bratu_theta_upper(double lambda)
{
  double lo = 4.798714561, hi = 60.0;
  for (int it = 0; it < 200; it++) {
    double mid = 0.5 * (lo + hi), f = mid - sqrt(2.0 * lambda) * cosh(mid / 4.0);
    if (f > 0) lo = mid;   /* above th*, f decreases: f > 0 left of the root */
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

static double bratu_u(double th, double t) { return cable_bratu_exact(0.0, th, t); }
static double bratu_du(double th, double t) { return -th * tanh((t - 0.5) * th / 2.0); }

/* The exact solution stored as the engine stores a solution. */
static cable_solution *bratu_solution(double lambda, double th, int ntst, int ncol)
{
  cable_solution *s = cable_solution_alloc(2, ntst, ncol, 1, 1);
  if (!s) return NULL;
  for (int k = 0; k <= ntst * ncol; k++) {
    double t = (double)k / (ntst * ncol);
    s->t[k] = t;
    s->u[2 * k] = bratu_u(th, t);
    s->u[2 * k + 1] = bratu_du(th, t);
  }
  s->par[0] = lambda;
  s->icp[0] = 0;
  return s;
}

/* The two smallest eigenvalues of -v'' - lambda e^u v, v(0) = v(1) = 0, by
 * three-point differences on n interior points (dstev). */
static int fd_bratu(double lambda, double th, int n, double ev[2])
{
  double h = 1.0 / (n + 1);
  double *d = malloc((size_t)n * sizeof *d), *e = malloc((size_t)n * sizeof *e);
  if (!d || !e) {
    free(d); free(e);
    return -1;
  }
  for (int i = 0; i < n; i++) {
    double t = (i + 1) * h;
    d[i] = 2.0 / (h * h) - lambda * exp(bratu_u(th, t));
    e[i] = -1.0 / (h * h);
  }
  int rc = (int)LAPACKE_dstev(LAPACK_COL_MAJOR, 'N', n, d, e, NULL, 1);
  if (rc == 0) { ev[0] = d[0]; ev[1] = d[1]; }
  free(d); free(e);
  return rc;
}

static void test_bratu_exact(void)
{
  const double lambda = 2.0;
  const double th[2] = {cable_bratu_theta(lambda), bratu_theta_upper(lambda)};
  const char *name[2] = {"lower", "upper"};
  for (int b = 0; b < 2; b++) {
    cable_solution *s = bratu_solution(lambda, th[b], 20, 4);
    cable_stab_result r;
    cable_error e;
    int st = cable_stability_index(cable_testproblem_bratu(), s, 1, 4, &r, &e);
    char what[160];
    snprintf(what, sizeof what, "bratu %s branch at lambda = 2: index computed", name[b]);
    test_true(what, st == CABLE_SUCCESS);
    snprintf(what, sizeof what, "bratu %s branch at lambda = 2: Morse index", name[b]);
    test_int(what, r.index, b);
    test_int("  no zero eigenvalue", r.nzero, 0);
    /* FD at n and 2n + 1 interior points (h and h/2), Richardson: O(h^4) */
    double f1[2], f2[2];
    int n = 2000;
    test_true("finite-difference eigenvalues", fd_bratu(lambda, th[b], n, f1) == 0 &&
                                                   fd_bratu(lambda, th[b], 2 * n + 1, f2) == 0);
    for (int j = 0; j < 2; j++) {
      double ref = (4.0 * f2[j] - f1[j]) / 3.0;
      /* Ritz (NTST 20, degree 4): O(h^8) ~ 1e-10 relative; the extrapolated
         FD: O(h^4) ~ 1e-12 plus rounding of dstev on a matrix of norm 4/h^2 =
         1.6e7 (eps 1.6e7 ~ 4e-9 absolute); the uncorrected FD differs by
         4e-7: tolerance 1e-8 relative, sigma of order 1..100 */
      snprintf(what, sizeof what, "bratu %s branch: sigma_%d (Ritz) against FD", name[b], j + 1);
      test_abs(what, r.eig[j], ref, 1e-8 * fmax(1.0, fabs(ref)));
    }
    cable_solution_free(s);
  }
}

/* ---------------------------------------------------------------- STAB=1 runs */

#define SRUN_MAX 800
typedef struct {
  int n;
  int itp[SRUN_MAX], stab[SRUN_MAX], index[SRUN_MAX], nzero[SRUN_MAX];
  double lambda[SRUN_MAX], sigma1[SRUN_MAX];
  int nsol;
  cable_solution *sol[64];
} srun;

static int srun_point(void *ctx, const cable_point *pt)
{
  srun *r = ctx;
  if (r->n >= SRUN_MAX) return 0;
  r->itp[r->n] = pt->itp;
  r->stab[r->n] = pt->stab;
  r->index[r->n] = pt->stab_index;
  r->nzero[r->n] = pt->stab_nzero;
  r->sigma1[r->n] = pt->stab_sigma1;
  r->lambda[r->n] = pt->par[0];
  r->n++;
  return 0;
}

static int srun_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  (void)pt;
  srun *r = ctx;
  if (r->nsol < 64) r->sol[r->nsol++] = cable_solution_clone(sol);
  return 0;
}

static int srun_run(const cable_problem *pb, const cable_constants *c, const cable_solution *start, srun *r)
{
  memset(r, 0, sizeof *r);
  int st;
  cable_cont *cc = cable_cont_alloc(pb, c, &st);
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, start);
  if (st == CABLE_SUCCESS) {
    cable_sink sink = {r, srun_point, srun_solution, NULL};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  cable_cont_free(cc);
  return st;
}

static void srun_free(srun *r)
{
  for (int i = 0; i < r->nsol; i++) cable_solution_free(r->sol[i]);
  r->nsol = 0;
}

static void test_bratu_run(void)
{
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.ds = 0.1; c.dsmin = 1e-6; c.dsmax = 0.5; c.nmx = 60;
  c.rl1 = 10.0; c.ilp = 1; c.isp = 0; c.epss = 1e-7; c.iad = 3;
  c.stab = 1;
  srun r;
  int st = srun_run(cable_testproblem_bratu(), &c, NULL, &r);
  test_true("bratu STAB=1 run ends normally", st > 0);
  int lp = -1, changes = 0, all = 1, before = 1, after = 1;
  for (int i = 0; i < r.n; i++) {
    if (r.itp[i] % 10 == CABLE_TY_LP) lp = i;
    all &= r.stab[i] != 0;
  }
  test_true("bratu: the fold is located", lp > 0);
  test_true("bratu: every point has an index", all);
  for (int i = 0; i < r.n; i++) {
    if (i > 0 && r.index[i] != r.index[i - 1]) changes++;
    if (i < lp) before &= r.index[i] == 0 && r.stab[i] == 1;
    if (i > lp) after &= r.index[i] == 1 && r.stab[i] == -1;
  }
  test_true("bratu: index 0 (stable, PT < 0) on the lower branch, before the LP", before);
  test_true("bratu: index 1 (unstable) on the upper branch, after the LP", after);
  /* at the located LP sigma_1 is the location error: |sigma_1| << the
     neighbours' (the eigenvalue crosses zero there) */
  if (lp > 0 && lp + 1 < r.n)
    test_le("bratu: |sigma_1| at the LP far below its neighbours'", fabs(r.sigma1[lp]),
            1e-3 * fmin(fabs(r.sigma1[lp - 1]), fabs(r.sigma1[lp + 1])));
  test_int("bratu: the index changes once along the branch", changes, 1);
  srun_free(&r);
}

/* the straight column: sigma_j = (j pi)^2 - lambda (j >= 1; j >= 0 without
   the constraint) */
static int straight_index(double lambda, int constrained)
{
  int n = constrained ? 0 : 1;
  for (int j = 1; (j * M_PI) * (j * M_PI) < lambda; j++) n++;
  return n;
}

static void test_elastica_run(void)
{
  for (int constrained = 1; constrained >= 0; constrained--) {
    const cable_problem *pb = constrained ? cable_testproblem_elastica_int() : cable_testproblem_elastica();
    cable_constants c;
    elastica_trivial_constants(&c, 50, 5);
    if (constrained) {
      c.icp[1] = 1;
      c.nicp = 2;
    }
    c.stab = 1;
    srun r;
    int st = srun_run(pb, &c, NULL, &r);
    char what[160];
    snprintf(what, sizeof what, "%s trivial branch with STAB=1 reaches RL1", pb->name);
    test_true(what, st == CABLE_END_BOUNDS);
    int nbp = 0, ok_index = 1, ok_sigma = 1, nfar = 0;
    double worst = 0;
    for (int i = 0; i < r.n; i++) {
      if (r.itp[i] % 10 == CABLE_TY_BP) nbp++;
      double l = r.lambda[i];
      int near = 0;
      for (int j = 1; j <= 4; j++) near |= fabs(l - (j * M_PI) * (j * M_PI)) < 1e-6 * (j * M_PI) * (j * M_PI);
      if (near) continue;
      nfar++;
      ok_index &= r.index[i] == straight_index(l, constrained) && r.nzero[i] == 0;
      double want = constrained ? M_PI * M_PI - l : -l;
      worst = fmax(worst, fabs(r.sigma1[i] - want) / fmax(1.0, fabs(want)));
    }
    ok_sigma = worst < 1e-9;
    snprintf(what, sizeof what, "%s: three branch points below 100", pb->name);
    test_int(what, nbp, 3);
    snprintf(what, sizeof what, "%s: index %s on the straight state (%d points)", pb->name,
             constrained ? "n for (n pi)^2 < lambda < ((n+1) pi)^2" : "n + 1 (the rigid rotation)", nfar);
    test_true(what, ok_index && nfar > 10);
    /* Ritz on an exact solution (theta = 0): error O(h^(2k)) = 0.02^10 pi^12 ~ 1e-11 */
    snprintf(what, sizeof what, "%s: sigma_1 = %s on the straight state (max rel. err %.2g)", pb->name,
             constrained ? "pi^2 - lambda" : "-lambda", worst);
    test_true(what, ok_sigma);
    if (!constrained) {
      srun_free(&r);
      continue;
    }
    /* the buckled branches from BP1 and BP2: index 0 and 1 */
    for (int k = 0; k < 2; k++) {
      const cable_solution *bp = NULL;
      for (int i = 0, seen = 0; i < r.nsol; i++)
        if (r.sol[i]->itp % 10 == CABLE_TY_BP && seen++ == k) bp = r.sol[i];
      if (!bp) {
        test_true("elastica_int: branch point to switch at", 0);
        continue;
      }
      cable_constants cb;
      engine_constants(&cb, 50, 5);
      cb.icp[1] = 1; cb.nicp = 2;
      cb.isw = -1; cb.ds = 0.05; cb.dsmin = 1e-6; cb.dsmax = 0.5; cb.nmx = 30;
      cb.isp = 0; cb.ilp = 0;
      cb.stab = 1;
      srun rb;
      st = srun_run(pb, &cb, bp, &rb);
      int good = rb.n > 10, moved = 0;
      for (int i = 1; i < rb.n; i++) {
        good &= rb.index[i] == k && rb.nzero[i] == 0 && rb.stab[i] == (k == 0 ? 1 : -1);
        moved |= fabs(rb.lambda[i] - bp->par[0]) > 1e-2 * bp->par[0];
      }
      snprintf(what, sizeof what, "elastica_int: buckled branch %d has index %d at all its %d points", k + 1, k,
               rb.n - 1);
      test_true(what, good && moved);
      srun_free(&rb);
    }
    srun_free(&r);
  }
}

/* ---------------------------------------------------------------- double branch points */

/* Two uncoupled Euler columns under one load lambda, each with its ends on
 * one line: u = (theta1, theta1', theta2, theta2'), PAR = (lambda, nu1, nu2).
 * Every branch point of the straight state is double, and there two
 * eigenvalues of the second variation cross zero together: the index must
 * jump by 2 exactly there (the braid's D7-symmetric flat knot in small). */
static void sub_par(const double *par, int k, double p2[2])
{
  p2[0] = par[0];
  p2[1] = par[1 + k];
}

static int dcol_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                     double *dfdu, double *dfdp, void *params)
{
  (void)ndim; (void)ijac; (void)dfdu; (void)dfdp;
  const cable_problem *e = cable_testproblem_elastica_int();
  int rc = 0;
  for (int k = 0; k < 2; k++) {
    double p2[2];
    sub_par(par, k, p2);
    rc |= e->func(2, u + 2 * k, icp, p2, 0, f + 2 * k, NULL, NULL, params);
  }
  return rc;
}

static int dcol_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                     int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[1]; fb[1] = u1[1]; fb[2] = u0[3]; fb[3] = u1[3];
  return 0;
}

static int dcol_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                     const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nint; (void)uold; (void)udot; (void)upold; (void)ijac; (void)dint;
  (void)params;
  fi[0] = sin(u[0]);
  fi[1] = sin(u[2]);
  return 0;
}

static int dcol_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 1.0; par[1] = par[2] = 0.0;
  return 0;
}

static int dcol_hessian(int ndim, const double *u, const double *par, int nvar, double *P, double *C, double *R,
                        void *params)
{
  (void)ndim; (void)params;
  const cable_variational *v = cable_testproblem_elastica_int()->variational;
  for (int i = 0; i < nvar * nvar; i++) P[i] = C[i] = R[i] = 0.0;
  for (int k = 0; k < 2; k++) {
    double p2[2], p, c, r;
    sub_par(par, k, p2);
    int rc = v->hessian(2, u + 2 * k, p2, 1, &p, &c, &r, NULL);
    if (rc) return rc;
    P[k + 2 * k] = p; C[k + 2 * k] = c; R[k + 2 * k] = r;
  }
  return 0;
}

static int dcol_constraints(int ndim, const double *u, const double *par, int nvar, int ncon, double *a, double *b,
                            void *params)
{
  (void)ndim; (void)par; (void)nvar; (void)params;
  for (int i = 0; i < 2 * ncon; i++) a[i] = b[i] = 0.0;
  a[0 + ncon * 0] = cos(u[0]);   /* row 0: int cos(theta1) v1 = 0 */
  a[1 + ncon * 1] = cos(u[2]);   /* row 1: int cos(theta2) v2 = 0 */
  return 0;
}

static void test_double_bp(void)
{
  static const cable_variational var = {.nvar = 2, .ncon = 2, .nvbc = 0, .hessian = dcol_hessian,
                                        .constraints = dcol_constraints};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = "double-column", .ndim = 4, .nbc = 4, .nint = 2, .npar = 3,
                      .func = dcol_func, .bcnd = dcol_bcnd, .icnd = dcol_icnd, .stpnt = dcol_stpnt,
                      .variational = &var};
  cable_constants c;
  engine_constants(&c, 40, 4);
  c.jac = 0;   /* the problem gives no derivatives */
  c.icp[1] = 1; c.icp[2] = 2; c.nicp = 3;
  c.ds = 0.5; c.dsmin = 1e-6; c.dsmax = 3.0; c.nmx = 200;
  c.rl1 = 45.0; c.isp = 2; c.epss = 1e-9;
  c.stab = 1;
  srun r;
  int st = srun_run(&pb, &c, NULL, &r);
  test_true("double column: the straight branch with STAB=1 reaches RL1", st == CABLE_END_BOUNDS);
  int nbp = 0, jumps = 0, at_bp = 1, by2 = 1, right = 1;
  for (int i = 0; i < r.n; i++) {
    if (r.itp[i] % 10 == CABLE_TY_BP) nbp++;
    else right &= r.index[i] == 2 * straight_index(r.lambda[i], 1) && r.nzero[i] == 0;
    if (i == 0 || r.index[i] == r.index[i - 1]) continue;
    jumps++;
    /* a jump happens between a point and a located BP, or across one (the BP
       itself, a zero eigenvalue pair, counts its own index either way) */
    int bp_here = r.itp[i] % 10 == CABLE_TY_BP || r.itp[i - 1] % 10 == CABLE_TY_BP;
    at_bp &= bp_here;
    int lo = i - 1, hi = i;
    if (r.itp[hi] % 10 == CABLE_TY_BP && hi + 1 < r.n) hi++;
    if (r.itp[lo] % 10 == CABLE_TY_BP && lo > 0) lo--;
    by2 &= abs(r.index[hi] - r.index[lo]) == 2;
  }
  test_int("double column: two double branch points below 45", nbp, 2);
  test_true("double column: index 2n for (n pi)^2 < lambda < ((n+1) pi)^2 (away from the BPs)", right);
  test_true("double column: the index changes only next to a located BP", jumps >= 2 && at_bp);
  test_true("double column: across each double BP it changes by 2", by2);
  srun_free(&r);
}

/* ---------------------------------------------------------------- convergence */

/* The straight column (theta = 0) at lambda = 50 stored on a uniform mesh. */
static cable_solution *straight_solution(double lambda, int ntst, int ncol)
{
  cable_solution *s = cable_solution_alloc(2, ntst, ncol, 2, 2);
  if (!s) return NULL;
  for (int k = 0; k <= ntst * ncol; k++) s->t[k] = (double)k / (ntst * ncol);
  s->par[0] = lambda;
  return s;
}

static void test_convergence(void)
{
  printf("convergence (doc/stability.md S5): problem, NTST, degree, N, index, sigma_1, sigma_2, errors\n");
  const double lambda_b = 2.0, thu = bratu_theta_upper(lambda_b);
  double f1[2], f2[2], ref[2];
  fd_bratu(lambda_b, thu, 2000, f1);
  fd_bratu(lambda_b, thu, 4001, f2);
  for (int j = 0; j < 2; j++) ref[j] = (4.0 * f2[j] - f1[j]) / 3.0;
  const int nts[4] = {2, 4, 8, 16}, degs[3] = {1, 2, 4};
  double prev_err = 0;
  int monotone = 1, index_ok = 1;
  for (int d = 0; d < 3; d++)
    for (int i = 0; i < 4; i++) {
      /* the solution itself on a fine mesh (its error out of the way); the Ritz
         space on NTST pieces: refine = 1 on a solution stored on that mesh */
      cable_solution *s = bratu_solution(lambda_b, thu, nts[i], 7);
      cable_stab_result r;
      cable_error e;
      cable_stability_index(cable_testproblem_bratu(), s, 1, degs[d], &r, &e);
      double e1 = fabs(r.eig[0] - ref[0]), e2 = fabs(r.eig[1] - ref[1]);
      printf("  bratu upper lambda=2 | %2d | %d | %4d | %d | %.10f | %.10f | %.2e | %.2e\n", nts[i], degs[d],
             r.nbasis, r.index, r.eig[0], r.eig[1], e1, e2);
      if (i > 0 && e1 > prev_err && e1 > 1e-9) monotone = 0;
      if (nts[i] * degs[d] >= 8) index_ok &= r.index == 1;
      prev_err = e1;
      cable_solution_free(s);
    }
  printf("  bratu reference (FD, Richardson): sigma_1 = %.10f sigma_2 = %.10f\n", ref[0], ref[1]);
  test_true("bratu upper branch: Ritz sigma_1 error decreases with the basis", monotone);
  test_true("bratu upper branch: index 1 from N >= 9", index_ok);
  const double lambda_e = 50.0, ex[2] = {M_PI * M_PI - lambda_e, 4 * M_PI * M_PI - lambda_e};
  for (int d = 0; d < 3; d++)
    for (int i = 0; i < 4; i++) {
      cable_solution *s = straight_solution(lambda_e, nts[i], 4);
      cable_stab_result r;
      cable_error e;
      cable_stability_index(cable_testproblem_elastica_int(), s, 1, degs[d], &r, &e);
      printf("  column lambda=50     | %2d | %d | %4d | %d | %.10f | %.10f | %.2e | %.2e\n", nts[i], degs[d],
             r.nbasis, r.index, r.eig[0], r.eig[1], fabs(r.eig[0] - ex[0]), fabs(r.eig[1] - ex[1]));
      cable_solution_free(s);
    }
  /* the refinement option (refine > 1) gives the same space as a finer mesh */
  cable_solution *s4 = straight_solution(lambda_e, 4, 4), *s16 = straight_solution(lambda_e, 16, 4);
  cable_stab_result ra, rb;
  cable_error e;
  cable_stability_index(cable_testproblem_elastica_int(), s4, 4, 2, &ra, &e);
  cable_stability_index(cable_testproblem_elastica_int(), s16, 1, 2, &rb, &e);
  test_abs("refine 4 on NTST 4 = NTST 16 (sigma_2)", ra.eig[1], rb.eig[1], 1e-9 * fabs(rb.eig[1]));
  /* Ritz values lie above the exact ones (min-max) */
  test_true("column: Ritz sigma_1, sigma_2 >= exact (min-max)", ra.eig[0] >= ex[0] - 1e-9 && ra.eig[1] >= ex[1] - 1e-9);
  test_int("column at lambda = 50: index 2", ra.index, 2);
  cable_solution_free(s4);
  cable_solution_free(s16);
}

/* ---------------------------------------------------------------- refusals */

static void test_refusal(void)
{
  cable_constants c;
  cable_error e;
  int st = cable_constants_parse_string_for("c.layer", "NTST = 10\nSTAB = 1\n", cable_testproblem_layer(), &c,
                                            NULL, &e);
  test_true("STAB=1 for a non-variational problem is refused", st == CABLE_ERR_INPUT);
  test_int("  at the line of STAB", e.line, 2);
  test_true("  naming the key and the file", strcmp(e.key, "STAB") == 0 && strcmp(e.file, "c.layer") == 0);
  st = cable_constants_parse_string_for("c.bratu", "STAB = 1\n", cable_testproblem_bratu(), &c, NULL, &e);
  test_true("STAB=1 for bratu is accepted", st == CABLE_SUCCESS && c.stab == 1);
  st = cable_constants_parse_string_for("c.bratu", "STAB = 2\n", cable_testproblem_bratu(), &c, NULL, &e);
  test_true("STAB=2 is out of range", st == CABLE_ERR_INPUT && e.line == 1);
  cable_constants k;
  engine_constants(&k, 10, 4);
  k.stab = 1;
  test_true("the engine refuses STAB=1 without a variational structure",
            cable_cont_check(cable_testproblem_layer(), &k, &e) == CABLE_ERR_INPUT);
  cable_stab_result r;
  cable_solution *s = straight_solution(1.0, 4, 4);
  test_true("cable_stability_index refuses a non-variational problem",
            cable_stability_index(cable_testproblem_layer(), s, 1, 4, &r, &e) == CABLE_ERR_INPUT);
  cable_solution_free(s);
}

/* ---------------------------------------------------------------- the b-file */

#define OUTDIR "tests/tmp/stability"

/* Bratu through its fold with the b-file writer; returns the file read back. */
static cable_bfile *bratu_bfile(int stab, const char *name)
{
  const cable_problem *pb = cable_testproblem_bratu();
  cable_constants c;
  engine_constants(&c, 20, 4);
  c.ds = 0.1; c.dsmin = 1e-6; c.dsmax = 0.5; c.nmx = 30;
  c.rl1 = 10.0; c.ilp = 1; c.isp = 0; c.epss = 1e-7; c.iad = 3;
  c.stab = stab;
  cable_constants_take_problem_dims(&c, pb->ndim, pb->nbc, pb->nint);
  cable_names names;
  memset(&names, 0, sizeof names);
  cable_names_fill(&names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  cable_error err;
  int st;
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  cable_aufile *w = cc ? cable_aufile_open(OUTDIR, name, &c, &names, NULL, &err) : NULL;
  if (!cc || !w || cable_cont_set_start(cc, NULL) != CABLE_SUCCESS) {
    cable_cont_free(cc);
    if (w) cable_aufile_close(w, &err);
    return NULL;
  }
  cable_sink sink = cable_aufile_sink(w);
  cable_cont_run(cc, &sink, 1, 1, NULL);
  cable_cont_free(cc);
  if (cable_aufile_close(w, &err) != CABLE_SUCCESS) return NULL;
  char path[256];
  snprintf(path, sizeof path, OUTDIR "/b.%s", name);
  return cable_bfile_read(path, &err);
}

static void test_bfile(void)
{
  mkdir("tests/tmp", 0755);
  mkdir(OUTDIR, 0755);
  cable_bfile *b1 = bratu_bfile(1, "stab"), *b0 = bratu_bfile(0, "nostab");
  test_true("b-files written and read back", b1 && b0 && b1->nbranch == 1 && b0->nbranch == 1);
  if (b1 && b0 && b1->nbranch == 1 && b0->nbranch == 1) {
    const cable_bfile_branch *r1 = &b1->branch[0], *r0 = &b0->branch[0];
    test_true("STAB=1: the section says so (STAB = 1 in its header)", r1->stab == 1);
    test_true("without STAB: it does not", r0->stab == 0);
    int lp = -1, signs = 1, same = r1->nrow == r0->nrow, plain = 1;
    for (int i = 0; i < r1->nrow; i++)
      if (r1->ty[i] == CABLE_TY_LP) lp = i;
    for (int i = 0; i < r1->nrow && i < r0->nrow; i++) {
      /* stable (PT < 0) before the fold; the fold itself (a zero eigenvalue)
         and the upper branch unstable (PT > 0) */
      signs &= i < lp ? r1->pt[i] == -(i + 1) : r1->pt[i] == i + 1;
      plain &= r0->pt[i] == i + 1;
      same &= r1->data[i] == r0->data[i];
    }
    test_true("STAB=1: PT < 0 exactly on the lower branch (before the LP)", lp > 0 && signs);
    test_true("without STAB: every PT positive", plain);
    test_true("the same points with and without STAB", same);
  }
  cable_bfile_free(b1);
  cable_bfile_free(b0);
}

int main(void)
{
  test_bratu_exact();
  test_bratu_run();
  test_elastica_run();
  test_double_bp();
  test_convergence();
  test_refusal();
  test_bfile();
  return test_summary();
}
