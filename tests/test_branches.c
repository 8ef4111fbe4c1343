/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The branch directions at double branch points (continuation/cont_branches.c,
 * doc/engine.md "Multiple branch points") on problems whose bifurcation
 * equations are solved in closed form.
 *
 * Both are pairs theta1, theta2 on [0, 1] with theta_i'(0) = theta_i'(1) = 0,
 * written first order as u = (theta1, theta1', theta2, theta2'); the trivial
 * branch theta = 0 has a double branch point at lambda = pi^2 with kernel
 * (cos pi t, 0), (0, cos pi t).
 *
 * 1. Two uncoupled elasticas, theta_i'' + lambda sin theta_i = 0: the four
 *    branches are theta1 alone, theta2 alone, theta1 = theta2, theta1 =
 *    -theta2, i.e. phi = 0, 90, 45, 135 degrees in the canonical basis
 *    (e1 = only theta1 moves).
 * 2. A coupled pair without the exchange symmetry,
 *        theta1'' + lambda theta1 - theta1^3 = 0,
 *        theta2'' + lambda theta2 - theta2^3 + 2 theta2 theta1^2 = 0:
 *    with theta2 = k theta1 both equations are theta1'' + lambda theta1 -
 *    theta1^3 = 0 when k^2 - 2 = 1, so theta2 = +-sqrt(3) theta1 are exact
 *    branches (phi = 60, 120 degrees), besides theta1 alone and theta2 alone.
 *    By hand: projecting on cos(pi t) (int cos^4 / int cos^2 = 3/4), with
 *    theta_i = s c alpha_i cos(pi t) + ..., lambda = pi^2 + nu, the cubic ABE
 *    are alpha1 (nu - (3/4) c^2 s^2 alpha1^2) = 0 and
 *    alpha2 (nu - (3/4) c^2 s^2 (alpha2^2 - 2 alpha1^2)) = 0: the mixed
 *    solutions have alpha1^2 = alpha2^2 - 2 alpha1^2, tan^2 phi = 3.
 *
 * 3. The coupled pair with + b theta_i^2 added to equation i (b = 1): the
 *    quadratic terms project to zero on the kernel (int cos^3 = 0), so the
 *    cubic ABE again, now with the w2 term: theta'' + lambda theta +
 *    b theta^2 - g theta^3 = 0 has w = -(b a^2 / 2)(1/pi^2 - cos(2 pi t) /
 *    (3 pi^2)) at second order and, projected at third order,
 *    nu = a^2 (3 g / 4 + 5 b^2 / (6 pi^2)): the cubic coefficients gain the
 *    factor 1 + B, B = (4/3) 5 b^2 / (6 pi^2), on the alpha_i^3 terms only, and
 *    the mixed directions move to tan^2 phi = (3 + B) / (1 + B).
 *
 * mu (lambda = pi^2 + mu s^2 along the branch, s the arclength of the unit
 * kernel direction): the kernel vector c (cos pi t, -pi sin pi t) of unit
 * theta-norm (node quadrature of the integral of u.u) has c^2 = 2 / (1 + pi^2);
 * an amplitude a of cos(pi t) in one equation theta'' + lambda theta - g
 * theta^3 shifts lambda by (3/4) g a^2 (sin: g = lambda / 6).  Hence
 *   elastica, one buckled: mu = (3/4) (pi^2 / 6) c^2 = pi^2 c^2 / 8; both:
 *   each has amplitude c / sqrt 2, mu = pi^2 c^2 / 16;
 *   coupled: theta1 alone and theta2 alone mu = (3/4) c^2, mixed (alpha1^2 =
 *   1/4) mu = (3/16) c^2.
 * Tolerances: the ABE's coefficients come from differences accurate to about
 * 1e-6 relative (h3^2 truncation, doc/engine.md), the kernel vectors of the
 * NTST = 40, NCOL = 4 discretisation differ from cos(pi t) by about
 * (0.025)^8 pi^8 ~ 1e-9: phi to 1e-3 degrees (a simple root moves by the
 * coefficient error over |g'|, of order 1e-6 rad), mu to 1e-4 relative. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "engine_util.h"
#include "harness.h"

#define CB_PI 3.14159265358979323846

typedef struct pair_params {
  int elastica; /* 1: lambda sin theta; 0: the coupled cubic pair; 2: the O(2) pair */
  double b;     /* + b theta_i^2 in equation i of the coupled pair */
} pair_params;

static int pair_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                     double *dfdu, double *dfdp, void *params)
{
  const pair_params *pp = params;
  double lam = par[0], t1 = u[0], t2 = u[2];
  f[0] = u[1];
  f[2] = u[3];
  if (pp->elastica == 2) {
    double r2 = t1 * t1 + t2 * t2;
    f[1] = -(lam * t1 - r2 * t1);
    f[3] = -(lam * t2 - r2 * t2);
  } else if (pp->elastica) {
    f[1] = -lam * sin(t1);
    f[3] = -lam * sin(t2);
  } else {
    f[1] = -(lam * t1 + pp->b * t1 * t1 - t1 * t1 * t1);
    f[3] = -(lam * t2 + pp->b * t2 * t2 - t2 * t2 * t2 + 2.0 * t2 * t1 * t1);
  }
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  return 0;
}

static int pair_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                     int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[1]; fb[1] = u1[1]; fb[2] = u0[3]; fb[3] = u1[3];
  return 0;
}

static int pair_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 1.0;
  return 0;
}

/* the first BP of the trivial branch */
static cable_solution *first_bp(const cable_problem *pb, memrun *r)
{
  cable_constants c;
  engine_constants(&c, 40, 4);
  c.jac = 0;
  c.ds = 0.5; c.dsmin = 1e-6; c.dsmax = 3.0; c.nmx = 100;
  c.rl1 = 12.0;
  c.isp = 2;
  c.epss = 1e-9;
  memrun_run(pb, &c, NULL, r);
  const cable_solution *bp = memrun_find(r, CABLE_TY_BP, 0);
  cable_solution *s = bp ? cable_solution_clone(bp) : NULL;
  memrun_free(r);
  return s;
}

static void switch_constants(cable_constants *c, int branch, double ds)
{
  engine_constants(c, 40, 4);
  c->jac = 0; c->isw = -1; c->isp = 0;
  c->branch = branch;
  c->ds = ds; c->dsmin = 1e-6; c->dsmax = 0.2; c->nmx = 25; c->npr = 5;
}

/* the branch list at the BP: one step of an ISW = -1 run */
static int list_branches(const cable_problem *pb, const cable_solution *bp, cable_branch_dir *br, int *order)
{
  cable_constants c;
  switch_constants(&c, 0, 0.05);
  int st = 0, nb = -1;
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  if (!cc) return -1;
  if (cable_cont_set_start(cc, bp) == CABLE_SUCCESS && cable_cont_step(cc) == CABLE_SUCCESS)
    nb = cable_cont_branches(cc, br, CABLE_MAX_BRANCHES, order);
  printf("# %s: %s\n", pb->name, cable_cont_note(cc));
  cable_cont_free(cc);
  return nb;
}

static void check_list(const char *name, const cable_branch_dir *br, int nb, int order, const double *phi,
                       const double *mu)
{
  char what[200];
  snprintf(what, sizeof what, "%s: the cubic bifurcation equations (quadratic terms vanish by symmetry)", name);
  test_int(what, order, 3);
  snprintf(what, sizeof what, "%s: four branch directions", name);
  test_int(what, nb, 4);
  for (int k = 0; k < nb && k < 4; k++) {
    snprintf(what, sizeof what, "%s: direction %d at phi = %g degrees", name, k + 1, phi[k]);
    test_abs(what, br[k].phi, phi[k], 1e-3);
    snprintf(what, sizeof what, "%s: direction %d, lambda = pi^2 + mu s^2", name, k + 1);
    test_rel(what, br[k].mu, mu[k], 1e-4);
    snprintf(what, sizeof what, "%s: direction %d stands for itself (no symmetry declared)", name, k + 1);
    test_int(what, br[k].multiplicity, 1);
  }
}

/* follow BRANCH = k: max |theta1|, |theta2|, |theta2 - r theta1| over the branch */
static void follow(const cable_problem *pb, const cable_solution *bp, int k, double ds, double r, double out[3])
{
  cable_constants c;
  switch_constants(&c, k, ds);
  memrun *m = calloc(1, sizeof *m);
  memrun_run(pb, &c, bp, m);
  out[0] = out[1] = out[2] = 0.0;
  for (int i = 1; i < m->nsol; i++) {
    const cable_solution *s = m->sol[i];
    for (int j = 0; j < cable_solution_npts(s); j++) {
      double t1 = s->u[4 * j], t2 = s->u[4 * j + 2];
      out[0] = fmax(out[0], fabs(t1));
      out[1] = fmax(out[1], fabs(t2));
      out[2] = fmax(out[2], fabs(t2 - r * t1));
    }
  }
  if (m->nsol < 3) out[0] = out[1] = -1.0; /* not computed */
  memrun_free(m);
  free(m);
}

static void test_pair(int elastica, double b)
{
  pair_params pp = {elastica, b};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = elastica ? "two elasticas" : b == 0 ? "coupled cubic pair" : "coupled pair with b theta^2", .ndim = 4, .nbc = 4, .npar = 1,
                      .func = pair_func, .bcnd = pair_bcnd, .stpnt = pair_stpnt, .params = &pp};
  memrun *r = calloc(1, sizeof *r);
  cable_solution *bp = first_bp(&pb, r);
  free(r);
  char what[200];
  snprintf(what, sizeof what, "%s: a branch point on the trivial branch", pb.name);
  test_true(what, bp != NULL);
  if (!bp) return;
  snprintf(what, sizeof what, "%s: the branch point at pi^2", pb.name);
  test_rel(what, bp->par[0], CB_PI * CB_PI, 1e-7);
  cable_branch_dir br[CABLE_MAX_BRANCHES];
  int order = 0, nb = list_branches(&pb, bp, br, &order);
  double c2 = 2.0 / (1.0 + CB_PI * CB_PI), pi2 = CB_PI * CB_PI;
  double r3 = sqrt(3.0);
  if (elastica) {
    const double phi[4] = {0, 45, 90, 135}, mu[4] = {pi2 * c2 / 8, pi2 * c2 / 16, pi2 * c2 / 8, pi2 * c2 / 16};
    check_list(pb.name, br, nb, order, phi, mu);
  } else if (b != 0) {
    const double B = (4.0 / 3.0) * 5.0 * b * b / (6.0 * pi2), pm = atan(sqrt((3.0 + B) / (1.0 + B))) * 180.0 / CB_PI;
    const double phi[4] = {0, pm, 90, 180.0 - pm};
    double s2 = sin(pm * CB_PI / 180.0), c1 = 1.0 - s2 * s2; /* alpha2^2, alpha1^2 of the mixed direction */
    const double mu[4] = {0.75 * (1 + B) * c2, 0.75 * (1 + B) * c1 * c2, 0.75 * (1 + B) * c2, 0.75 * (1 + B) * c1 * c2};
    check_list(pb.name, br, nb, order, phi, mu);
  } else {
    const double phi[4] = {0, 60, 90, 120}, mu[4] = {0.75 * c2, 0.1875 * c2, 0.75 * c2, 0.1875 * c2};
    check_list(pb.name, br, nb, order, phi, mu);
  }
  if (b != 0) {
    /* no closed-form mixed branch: each BRANCH = k is computed and leaves
       the trivial branch */
    for (int k = 1; k <= 4; k++) {
      double m[3];
      follow(&pb, bp, k, 0.05, 0.0, m);
      snprintf(what, sizeof what, "%s: BRANCH=%d is computed (max |theta1| %.3f, |theta2| %.3f)", pb.name, k, m[0],
               m[1]);
      test_true(what, fmax(m[0], m[1]) > 0.3);
    }
    cable_solution_free(bp);
    return;
  }
  /* each BRANCH = k is the exact branch: theta2 = ratio theta1 (ratio
     infinite: theta1 = 0); a zero component stays zero to the Newton
     tolerance (EPSU = 1e-7 relative corrections, converged quadratically) */
  const double ratio_el[4] = {0, 1, INFINITY, -1}, ratio_cp[4] = {0, r3, INFINITY, -r3};
  for (int k = 1; k <= 4; k++) {
    double q = elastica ? ratio_el[k - 1] : ratio_cp[k - 1], m[3];
    double ds = k == 2 ? -0.05 : 0.05; /* DS < 0: the other half of the branch */
    follow(&pb, bp, k, ds, isinf(q) ? 0.0 : q, m);
    double dev = isinf(q) ? m[0] : m[2], amp = isinf(q) ? m[1] : m[0];
    snprintf(what, sizeof what, "%s: BRANCH=%d DS=%g follows theta2 = %s theta1 (amplitude %.3f, deviation %.2e)",
             pb.name, k, ds, isinf(q) ? "inf" : q == 0 ? "0" : q == 1 ? "" : q == -1 ? "-" : q > 0 ? "sqrt3" : "-sqrt3",
             amp, dev);
    test_true(what, amp > 0.3 && dev < 1e-6);
  }
  /* BRANCH beyond the list is refused */
  cable_constants c;
  switch_constants(&c, 5, 0.05);
  int st = 0;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  int rc = cc && cable_cont_set_start(cc, bp) == CABLE_SUCCESS ? cable_cont_step(cc) : CABLE_SUCCESS;
  snprintf(what, sizeof what, "%s: BRANCH=5 is refused (%s)", pb.name, cc ? cable_cont_error(cc) : "no handle");
  test_int(what, rc, CABLE_ERR_SWITCH);
  cable_cont_free(cc);
  cable_solution_free(bp);
}

/* Branch identity: a branch that locates a branch point already computed on
 * another branch stops there (cont_loop.c).  Run A, the pair's trivial
 * branch from lambda = 1 to 12, computes the double BP at pi^2; run B comes
 * down the trivial branch from A's end (DS < 0) and reaches that BP: with
 * A's BP declared known it ends there with CABLE_END_LOOP and a message that
 * names it; without, it goes on to RL0. */
static int run_down(const cable_problem *pb, const cable_solution *from, const cable_solution *known, double *lam_end,
                    char *err, size_t len)
{
  cable_constants c;
  engine_constants(&c, 40, 4);
  c.jac = 0;
  c.ds = -0.5; c.dsmin = 1e-6; c.dsmax = 3.0; c.nmx = 100;
  c.rl0 = 2.0; c.rl1 = 20.0;
  c.isp = 2;
  c.epss = 1e-9;
  int st = 0;
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  if (!cc) return st;
  if (known) st = cable_cont_add_known_point(cc, known, "BP label 2 of the first run");
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, from);
  while (st == CABLE_SUCCESS) st = cable_cont_step(cc);
  const cable_point *pt = cable_cont_point(cc);
  *lam_end = pt ? pt->par[0] : (double)NAN;
  snprintf(err, len, "%s", cable_cont_error(cc));
  cable_cont_free(cc);
  return st;
}

static void test_known_branch_point(void)
{
  pair_params pp = {1, 0.0};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = "two elasticas", .ndim = 4, .nbc = 4, .npar = 1,
                      .func = pair_func, .bcnd = pair_bcnd, .stpnt = pair_stpnt, .params = &pp};
  memrun *r = calloc(1, sizeof *r);
  cable_constants c;
  engine_constants(&c, 40, 4);
  c.jac = 0;
  c.ds = 0.5; c.dsmin = 1e-6; c.dsmax = 3.0; c.nmx = 100;
  c.rl1 = 12.0;
  c.isp = 2;
  c.epss = 1e-9;
  memrun_run(&pb, &c, NULL, r);
  const cable_solution *bp = memrun_find(r, CABLE_TY_BP, 0);
  const cable_solution *end = r->nsol ? r->sol[r->nsol - 1] : NULL;
  test_true("known BP: the first run computes the BP and ends beyond it", bp && end && end->par[0] > 12.0);
  if (bp && end) {
    double lam = 0;
    char err[600];
    int st = run_down(&pb, end, bp, &lam, err, sizeof err);
    char what[900];
    snprintf(what, sizeof what, "known BP: the run down the branch ends at the known BP (%s)", err);
    test_int(what, st, CABLE_END_LOOP);
    test_rel("known BP: it ends at lambda = pi^2", lam, CB_PI * CB_PI, 1e-7);
    test_true("known BP: the message names the point", strstr(err, "BP label 2 of the first run") != NULL);
    st = run_down(&pb, end, NULL, &lam, err, sizeof err);
    snprintf(what, sizeof what, "known BP: without it the run passes the BP and ends at RL0 (lambda = %.4f)", lam);
    test_true(what, st == CABLE_END_BOUNDS && lam < 2.0);
  }
  memrun_free(r);
  free(r);
}

/* 4. The O(2)-symmetric pair theta_i'' + lambda theta_i - (theta1^2 +
 *    theta2^2) theta_i = 0: every rotation of (theta1, theta2) maps
 *    solutions to solutions, the cubic ABE are alpha_i (nu - (3/4) c^2 s^2
 *    |alpha|^2) = 0 and g = L_1 C_2 - L_2 C_1 vanishes for every direction:
 *    a continuum (a group orbit of branches).  The list is empty, the note
 *    says so, and the switch follows the canonical e1, a branch of the orbit
 *    (theta2 = 0 along it). */
static void test_o2_pair(void)
{
  pair_params pp = {2, 0.0};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = "O(2) pair", .ndim = 4, .nbc = 4, .npar = 1,
                      .func = pair_func, .bcnd = pair_bcnd, .stpnt = pair_stpnt, .params = &pp};
  memrun *r = calloc(1, sizeof *r);
  cable_solution *bp = first_bp(&pb, r);
  free(r);
  test_true("O(2) pair: a branch point on the trivial branch", bp != NULL);
  if (!bp) return;
  cable_constants c;
  switch_constants(&c, 0, 0.05);
  int st = 0, order = 0, nb = 0;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  int rc = cc && cable_cont_set_start(cc, bp) == CABLE_SUCCESS ? cable_cont_step(cc) : CABLE_ERR_STATE;
  nb = cable_cont_branches(cc, NULL, 0, &order);
  char what[900];
  snprintf(what, sizeof what, "O(2) pair: the start is computed (%s)", cc ? cable_cont_note(cc) : "");
  test_int(what, rc, CABLE_SUCCESS);
  test_int("O(2) pair: the cubic ABE vanish identically: no list", nb, -1);
  test_true("O(2) pair: the note says a continuum", cc && strstr(cable_cont_note(cc), "g vanishes identically") != NULL);
  cable_cont_free(cc);
  double m[3];
  follow(&pb, bp, 0, 0.05, 0.0, m);
  snprintf(what, sizeof what, "O(2) pair: the canonical e1 is followed, a branch of the orbit (max |theta1| %.3f, "
           "|theta2| %.2e)", m[0], m[1]);
  test_true(what, m[0] > 0.3 && m[1] >= 0 && m[1] < 1e-6);
  cable_solution_free(bp);
}

/* 5. Declared symmetries (cable_problem.symmetries; doc/engine.md,
 *    "Symmetry: the restriction to Fix(S)").
 *    The exchange S (theta1, theta1') <-> (theta2, theta2') by its act. */
static void swap_act(int ndim, const double *u, double *su, void *params)
{
  (void)ndim; (void)params;
  su[0] = u[2]; su[1] = u[3]; su[2] = u[0]; su[3] = u[1];
}

/* The Duffing branch theta'' + lambda theta - g theta^3 = 0, theta'(0) =
 * theta'(1) = 0, first mode with theta(0) = A: with theta = A sin(phi) the
 * energy integral gives the half period
 *   int_0^(pi/2) dphi / sqrt(lambda - g A^2 (1 + sin^2 phi) / 2) = 1/2,
 * decreasing in lambda > g A^2; solved by bisection, the smooth periodic
 * integrand by the composite midpoint rule (exponentially accurate: 400
 * nodes give round-off). */
static double duffing_halfperiod(double lam, double g, double a)
{
  const int m = 400;
  double s = 0.0;
  for (int k = 0; k < m; k++) {
    double ph = (k + 0.5) * (0.5 * CB_PI / m), sn = sin(ph);
    s += 1.0 / sqrt(lam - 0.5 * g * a * a * (1.0 + sn * sn));
  }
  return s * (0.5 * CB_PI / m);
}

static double duffing_lambda(double g, double a)
{
  double lo = g * a * a * (1.0 + 1e-15) + 1e-300, hi = g * a * a + 4.0 * CB_PI * CB_PI + 10.0;
  for (int it = 0; it < 200; it++) {
    double mid = 0.5 * (lo + hi);
    if (duffing_halfperiod(mid, g, a) > 0.5) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/* follow BRANCH = k of pb from bp; over the stored solutions: the largest
 * relative deviation of lambda from the Duffing closed form with g at
 * A = |theta1(0)| (out[0]), max |theta1| (out[1]), max |theta2 - r theta1|
 * (out[2]), max |PAR(2)| (the unfolding parameter, out[3]); the number of
 * solutions into *nsol */
static void follow_duffing(const cable_problem *pb, const cable_solution *bp, int k, double g, double r, double out[4],
                           int *nsol)
{
  cable_constants c;
  switch_constants(&c, k, 0.05);
  memrun *m = calloc(1, sizeof *m);
  memrun_run(pb, &c, bp, m);
  out[0] = out[1] = out[2] = out[3] = 0.0;
  for (int i = 1; i < m->nsol; i++) {
    const cable_solution *s = m->sol[i];
    for (int j = 0; j < cable_solution_npts(s); j++) {
      double t1 = s->u[4 * j], t2 = s->u[4 * j + 2];
      out[1] = fmax(out[1], fabs(t1));
      out[2] = fmax(out[2], fabs(t2 - r * t1));
    }
    double a = fabs(s->u[0]), lam = s->par[0];
    out[0] = fmax(out[0], fabs(lam - duffing_lambda(g, a)) / lam);
    if (s->npar > 1) out[3] = fmax(out[3], fabs(s->par[1]));
  }
  *nsol = m->nsol;
  memrun_free(m);
  free(m);
}

static void test_declared_swap(void)
{
  pair_params pp = {1, 0.0};
  cable_symmetry sym[1] = {{.name = "swap", .act = swap_act, .unfold_bc = -1, .unfold_par = -1, .multiplicity = 1}};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = "two elasticas with the exchange", .ndim = 4, .nbc = 4, .npar = 1,
                      .func = pair_func, .bcnd = pair_bcnd, .stpnt = pair_stpnt, .params = &pp,
                      .symmetries = sym, .nsym = 1};
  memrun *r = calloc(1, sizeof *r);
  cable_solution *bp = first_bp(&pb, r);
  free(r);
  test_true("swap: a branch point on the trivial branch", bp != NULL);
  if (!bp) return;
  cable_branch_dir br[CABLE_MAX_BRANCHES];
  int order = 0, nb = list_branches(&pb, bp, br, &order);
  /* theta1 alone (0) and theta2 alone (90) are exchanged by S: one class of
     two; theta1 = theta2 (45) lies in Fix(S); theta1 = -theta2 (135) is
     mapped onto itself reversed (the other half of the same branch) */
  test_int("swap: three classes of branch directions", nb, 3);
  if (nb == 3) {
    test_abs("swap: class 1 at 0 degrees", br[0].phi, 0.0, 1e-3);
    test_int("swap: class 1 stands for 0 and 90 degrees (multiplicity 2)", br[0].multiplicity, 2);
    test_int("swap: class 1 is not in Fix(S)", br[0].sym, 0);
    test_abs("swap: class 2 at 45 degrees", br[1].phi, 45.0, 1e-3);
    test_int("swap: class 2 multiplicity 1", br[1].multiplicity, 1);
    test_int("swap: class 2 lies in Fix(swap)", br[1].sym, 1);
    test_abs("swap: class 3 at 135 degrees", br[2].phi, 135.0, 1e-3);
    test_int("swap: class 3 multiplicity 1", br[2].multiplicity, 1);
    test_int("swap: class 3 is not in Fix(S)", br[2].sym, 0);
    test_int("swap: no restriction needed (the ABE decide)", br[0].restricted + br[1].restricted + br[2].restricted, 0);
  }
  /* BRANCH = 2 is the in-phase branch theta1 = theta2 */
  double m[3];
  follow(&pb, bp, 2, 0.05, 1.0, m);
  char what[200];
  snprintf(what, sizeof what, "swap: BRANCH=2 follows theta1 = theta2 (amplitude %.3f, deviation %.2e)", m[0], m[2]);
  test_true(what, m[0] > 0.3 && m[2] < 1e-6);
  cable_solution_free(bp);
}

/* The O(2) pair with one reflection declared: by odd (theta2 -> -theta2:
 * U(3) at t = 0 is odd, Fix = {theta2 = 0}, the branch theta1'' + lambda
 * theta1 - theta1^3 = 0: Duffing g = 1) or by act (the exchange, Fix =
 * {theta1 = theta2}: theta'' + lambda theta - 2 theta^3 = 0, g = 2).  The
 * ABE vanish identically; the switch restricts to Fix(S), where the BP is
 * simple, and follows the symmetric branch.  Tolerance for lambda: the
 * collocation error of NTST = 40, NCOL = 4 at amplitudes below 1 (measured
 * 6.1e-13 relative; the test allows 1e-8), plus the corrector's EPSU = 1e-7
 * on the unknowns (quadratic convergence leaves ~1e-12). */
static void test_o2_declared(int by_act)
{
  pair_params pp = {2, 0.0};
  cable_symmetry sym[1];
  if (by_act)
    sym[0] = (cable_symmetry){.name = "swap", .act = swap_act, .unfold_bc = -1, .unfold_par = -1, .multiplicity = 1};
  else
    sym[0] = (cable_symmetry){.name = "flip2", .odd_comp = 2, .odd_at = 0, .unfold_bc = -1, .unfold_par = -1,
                              .multiplicity = 1};
  const char *name = by_act ? "O(2) pair, exchange by act" : "O(2) pair, theta2 odd";
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
                      .name = name, .ndim = 4, .nbc = 4, .npar = 1,
                      .func = pair_func, .bcnd = pair_bcnd, .stpnt = pair_stpnt, .params = &pp,
                      .symmetries = sym, .nsym = 1};
  memrun *r = calloc(1, sizeof *r);
  cable_solution *bp = first_bp(&pb, r);
  free(r);
  char what[900];
  snprintf(what, sizeof what, "%s: a branch point", name);
  test_true(what, bp != NULL);
  if (!bp) return;
  cable_branch_dir br[CABLE_MAX_BRANCHES];
  int order = 0, nb = list_branches(&pb, bp, br, &order);
  snprintf(what, sizeof what, "%s: one direction, from the symmetry", name);
  test_int(what, nb, 1);
  if (nb == 1) {
    snprintf(what, sizeof what, "%s: it lies in Fix(S) and is followed in the restricted problem", name);
    test_true(what, br[0].sym == 1 && br[0].restricted == 1 && br[0].multiplicity == 1);
  }
  double m[4];
  int nsol = 0;
  follow_duffing(&pb, bp, 1, by_act ? 2.0 : 1.0, by_act ? 1.0 : 0.0, m, &nsol);
  snprintf(what, sizeof what, "%s: the symmetric branch is followed (%d solutions, max |theta1| %.3f)", name, nsol,
           m[1]);
  test_true(what, nsol >= 3 && m[1] > 0.3);
  snprintf(what, sizeof what, "%s: it stays in Fix(S) (max |theta2 - %s theta1| = %.2e)", name, by_act ? "" : "0",
           m[2]);
  test_true(what, m[2] < 1e-6);
  snprintf(what, sizeof what, "%s: lambda agrees with the Duffing closed form, g = %d (max rel. dev. %.2e)", name,
           by_act ? 2 : 1, m[0]);
  test_true(what, m[0] < 1e-8);
  snprintf(what, sizeof what, "%s: the unfolding parameter stays 0 (max |PAR(2)| = %.2e)", name, m[3]);
  test_true(what, m[3] < 1e-9);
  cable_solution_free(bp);
}

int main(void)
{
  test_declared_swap();
  test_o2_declared(0);
  test_o2_declared(1);
  test_pair(1, 0.0);
  test_pair(0, 0.0);
  test_pair(0, 1.0);
  test_o2_pair();
  test_known_branch_point();
  return test_summary();
}
