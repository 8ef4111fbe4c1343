/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable_braid_analysis_compute on converged braid solutions whose answers are known
 * without the code under test:
 *  - the flat (7,2) knot presses its strands together at T = 2: pmin > 0,
 *    no sign change;
 *  - its mirror image, the left-handed knot at T = -2: the material closure
 *    of the two adds up to 2 pi (derivation at check_mirror_closure);
 *  - the flat (6,2) link at T = 17.5, whose contact pressure changes sign:
 *    the positions must have the solution's symmetries (S0 and the 3-fold
 *    rotation) and agree between the two strands' independent pressures;
 *  - cable_braid_branch_settled on made-up branches, and the error paths.
 * The scene functions analyze() and branch_table() are tested through the
 * Python package (tests/python/test_scenes.py). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gsl/gsl_math.h>

#include "cable/cable_analysis.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "engine_util.h"
#include "harness.h"

static const double KNOT_DELTA = 0.0051364907419, KNOT_LTOT = 1.98889;
static const double LINK_DELTA = 0.016016913268;

static cable_constants braid_constants(int ntst, double ds)
{
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  /* a uniform mesh (IAD=0) is mapped onto itself by the mirror and by S0
     (s -> L - s), so the discrete solutions keep those symmetries exactly */
  c.ntst = ntst; c.ncol = 4; c.jac = 1; c.iad = 0;
  c.ds = ds; c.dsmin = 1e-6; c.dsmax = 2.0; c.nmx = 200; c.isp = 0; c.ilp = 0;
  c.epss = 1e-9;
  return c;
}

/* Continue the torus guess in T to T = target; the solution there (or NULL). */
static cable_solution *flat_at(const char *name, int p, int hand, double delta, double length, double target,
                               const int *icp, int nicp, int ntst, memrun *r)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, p, hand, delta, length, 0.0);
  cable_problem pb;
  if (braid_start_prepare(&sp) != 0 || braid_problem_instance(name, &sp, &pb) != 0) return NULL;
  cable_constants c = braid_constants(ntst, target > 0 ? 1.0 : -1.0);
  for (int k = 0; k < nicp; k++) c.icp[k] = icp[k];
  c.nicp = nicp;
  c.nuzr = 1; c.uzr[0].par = BP_T; c.uzr[0].value = target; c.uzr[0].stop = 1;
  memrun_run(&pb, &c, NULL, r);
  cable_solution *s = r->status == CABLE_END_UZSTOP ? cable_solution_clone(r->sol[r->nsol - 1]) : NULL;
  memrun_free(r);
  return s;
}

/* At T = 2, between the branch points of the v-branch's two arms, the flat
 * knot's strands press on each other everywhere: p > 0 (the paper reports a
 * non-negative pressure for all its knots). */
static void check_flat_knot(const cable_solution *knot)
{
  cable_braid_analysis *a = malloc(sizeof *a);
  int rc = cable_braid_analysis_compute(knot, a);
  test_int("flat (7,2) knot: analysed", rc, 0);
  if (!rc) {
    char what[160];
    snprintf(what, sizeof what, "flat (7,2) knot at T = 2: pmin > 0 (strand 1 %.6g, strand 2 %.6g)", a->pmin1, a->pmin2);
    test_true(what, a->pmin1 > 0 && a->pmin2 > 0);
    test_int("flat (7,2) knot: no sign change of p1", a->psign1.n, 0);
    test_int("flat (7,2) knot: no sign change of p2", a->psign2.n, 0);
    test_int("flat (7,2) knot: the braid axis is an unknot", strcmp(a->topo.axis.name, "unknot"), 0);
  }
  free(a);
}

/* The mirror image of a solution (reflection in a plane) is a solution of the
 * mirrored problem: the left-handed knot at -T.  A reflection reverses the
 * sense of rotations, so each strand's twist angle xi_i (the rotation of its
 * material frame against the braid frame about the tangent) changes sign
 * while lengths and |F| do not.  The knot's closure is
 * wrap(xi1(0) + xi2(L)) with xi1(0) = 0 imposed, i.e. wrap(xi2(L)); the
 * mirror image has wrap(-xi2(L)) = 2 pi - wrap(xi2(L)) (for a closure other
 * than 0).  So the two closures add up to 2 pi, to the Newton tolerance (the
 * two discrete problems on the same uniform mesh are mirror images too). */
static void check_mirror_closure(const cable_solution *right, const cable_solution *left)
{
  cable_braid_analysis *a = malloc(sizeof *a), *b = malloc(sizeof *b);
  int rc = cable_braid_analysis_compute(right, a) || cable_braid_analysis_compute(left, b);
  test_int("right- and left-handed (7,2) knots: analysed", rc, 0);
  if (!rc) {
    char what[160];
    snprintf(what, sizeof what, "closure right %.8f + left %.8f = 2 pi", a->closure, b->closure);
    /* xi2(L) ~ 10 rad; EPSS/EPSU 1e-9 relative on the solution, so 1e-7 */
    test_abs(what, a->closure + b->closure, 2 * M_PI, 1e-7);
    test_true("closure is not 0 (the relation needs wrap(x) != 0)", a->closure > 1e-3 && a->closure < 2 * M_PI - 1e-3);
    test_true("mirror images: Lk = +3.5 and -3.5", fabs(a->topo.lk - 3.5) < 1e-6 && fabs(b->topo.lk + 3.5) < 1e-6);
    test_rel("mirror images: same pmin", b->pmin1, a->pmin1, 1e-7);
  }
  free(a);
  free(b);
}

/* Distance of x from the nearest member of the sorted list y[0..n-1], with
 * positions taken modulo the period L. */
static double nearest(double x, const double *y, int n, double L)
{
  double best = HUGE_VAL;
  for (int i = 0; i < n; i++) {
    double d = fmod(fabs(x - y[i]), L);
    best = fmin(best, fmin(d, L - d));
  }
  return best;
}

/* The flat (6,2) link is not uniform along s: the braid force F, a fixed
 * vector, breaks the circle's rotational symmetry down to the link's
 * D6-type symmetry (doc/links.md, section 2).  What remains acts on p1 as
 * the S0 reflection s -> L - s and the rotation by 4 pi/6 about the torus
 * axis, s -> s + L/3 (it keeps each strand).  Between T ~ 10 (p > 0) and
 * T ~ 23.6 (p < 0) the pressure changes sign along s, at positions that must
 * have both symmetries. */
static void check_flat_link(memrun *r)
{
  const int icp[1] = {BP_T};
  const double T = 17.5;
  cable_solution *s = flat_at("braid_link", 6, -1, LINK_DELTA, 1.0, T, icp, 1, 42, r);
  test_true("flat (6,2) link reaches T = 17.5", s != NULL);
  if (!s) return;
  cable_braid_analysis *a = malloc(sizeof *a);
  int rc = cable_braid_analysis_compute(s, a);
  test_int("flat (6,2) link at T = 17.5: analysed", rc, 0);
  if (!rc) {
    double L = s->par[BP_L];
    int n = a->psign1.n;
    char what[200];
    snprintf(what, sizeof what, "flat link: p1 changes sign, a multiple of 6 times (3-fold x S0 orbits): %d", n);
    test_true(what, n > 0 && n % 6 == 0);
    test_int("flat link: p2 changes sign as often as p1", a->psign2.n, n);
    /* NTST 42 makes the uniform mesh invariant under both maps, so the
       discrete solution has the symmetries to the Newton tolerance (EPSS
       1e-9, relative) and the refined positions to the bisection width
       (1e-12) on top: 1e-9 in s is a margin of 1000 over the measured
       7e-13 and 1e6 below the node spacing 1/168, all that node values
       alone would resolve */
    double sym = 0, rot = 0, two = 0;
    for (int i = 0; i < n && n <= CABLE_BRAID_PSIGN_MAX; i++) {
      sym = fmax(sym, nearest(L - a->psign1.s[i], a->psign1.s, n, L));
      rot = fmax(rot, nearest(a->psign1.s[i] + L / 3, a->psign1.s, n, L));
      if (a->psign2.n == n) two = fmax(two, fabs(a->psign2.s[i] - a->psign1.s[i]));
    }
    snprintf(what, sizeof what, "flat link: sign changes symmetric under s -> L - s (S0), worst %.2e", sym);
    test_le(what, sym, 1e-9);
    snprintf(what, sizeof what, "flat link: sign changes repeat after L/3, worst %.2e", rot);
    test_le(what, rot, 1e-9);
    /* p1 = sigma' p2 with sigma' > 0: the two strands' pressures, computed
       from different balance laws, vanish together (the bisections then take
       the same decisions and usually end at the same t exactly) */
    snprintf(what, sizeof what, "flat link: p1 and p2 change sign at the same s, worst %.2e", two);
    test_le(what, two, 1e-9);
    /* and they are zeros: |p| there against its range, with the slope
       |p'| <= ~1e4 L times the bisection width 1e-12 */
    double pz = 0;
    for (int i = 0; i < n && n <= CABLE_BRAID_PSIGN_MAX; i++) {
      double p1, p2;
      if (cable_braid_pressure_at(s, a->psign1.s[i] / L, &p1, &p2, NULL) == 0) pz = fmax(pz, fabs(p1));
      else pz = HUGE_VAL;
    }
    snprintf(what, sizeof what, "flat link: p1 vanishes at its sign changes, worst |p1| = %.2e (range %.4g)", pz,
             a->pmax1 - a->pmin1);
    test_le(what, pz, 1e-6 * (a->pmax1 - a->pmin1));
    int inside = 1, ordered = 1;
    for (int i = 0; i < n; i++) {
      inside = inside && a->psign1.s[i] > 0 && a->psign1.s[i] < L && a->psign2.sigma[i] > 0 &&
               a->psign2.sigma[i] < s->par[BP_L2];
      if (i > 0) ordered = ordered && a->psign1.s[i] > a->psign1.s[i - 1] && a->psign2.sigma[i] > a->psign2.sigma[i - 1];
    }
    test_true("flat link: positions inside (0, L) and (0, L2), in braid order", inside && ordered);
    test_true("flat link: p1 takes both signs", a->pmin1 < 0 && a->pmax1 > 0);
    test_true("flat link: closure2 of strand 2 in [0, 2 pi)", a->closure2 >= 0 && a->closure2 < 2 * M_PI);
    test_true("flat link: Lk = -3", fabs(a->topo.lk + 3) < 1e-6);
  }
  free(a);
  cable_solution_free(s);
}

/* Made-up analyses: only the axis type and dmin matter. */
static void fake(cable_braid_analysis *a, const char *name, int hand, double dmin)
{
  memset(a, 0, sizeof *a);
  snprintf(a->topo.axis.name, sizeof a->topo.axis.name, "%s", name);
  a->topo.axis.handedness = hand;
  a->tube.dmin = dmin;
}

static void check_settled(void)
{
  enum { N = 8 };
  cable_braid_analysis *x = malloc(N * sizeof *x);
  const cable_braid_analysis *a[N];
  /* unknot, then a passage (overlap), then the right trefoil: overlapping,
     then free, then overlapping again */
  fake(&x[0], "unknot", 0, 2.0);
  fake(&x[1], "unknot", 0, 0.1);
  fake(&x[2], "trefoil", -1, 0.2);   /* left-handed: a different type */
  fake(&x[3], "trefoil", 1, 0.3);
  fake(&x[4], "trefoil", 1, 0.9);
  fake(&x[5], "trefoil", 1, 1.2);
  fake(&x[6], "trefoil", 1, 1.5);
  fake(&x[7], "trefoil", 1, 0.8);
  for (int i = 0; i < N; i++) a[i] = &x[i];
  int first, rep = cable_braid_branch_settled(a, N, &first);
  test_int("settled: the final stretch starts after the left trefoil", first, 3);
  test_int("settled: reported point is its first with dmin > 1", rep, 5);
  a[4] = NULL;   /* not analysable: skipped, the stretch goes on */
  rep = cable_braid_branch_settled(a, N, &first);
  test_true("settled: an unanalysable solution inside the stretch is skipped", first == 3 && rep == 5);
  a[7] = NULL;   /* the last one unanalysable: the final type is the previous one's */
  rep = cable_braid_branch_settled(a, N, &first);
  test_true("settled: an unanalysable last solution is skipped", first == 3 && rep == 5);
  for (int i = 0; i < N; i++) a[i] = &x[i];
  fake(&x[5], "trefoil", 1, 1.0);   /* dmin = 1 exactly: touching, not free */
  fake(&x[6], "trefoil", 1, 0.95);
  rep = cable_braid_branch_settled(a, N, &first);
  test_true("settled: no overlap-free solution in the stretch: -1", first == 3 && rep == -1);
  fake(&x[0], "unknot", 0, 3.0);
  rep = cable_braid_branch_settled(a, 1, &first);
  test_true("settled: a one-solution branch", first == 0 && rep == 0);
  for (int i = 0; i < N; i++) a[i] = NULL;
  rep = cable_braid_branch_settled(a, N, &first);
  test_true("settled: nothing analysable: -1, first -1", first == -1 && rep == -1);
  free(x);
}

static void check_errors(const cable_solution *knot)
{
  cable_braid_analysis *a = malloc(sizeof *a);
  cable_solution *s = cable_solution_clone(knot);
  s->ndim = 3;
  test_int("not a braid solution (ndim 3): CABLE_ERR_INPUT", cable_braid_analysis_compute(s, a), CABLE_ERR_INPUT);
  test_int("pressure signs of a non-braid solution: CABLE_ERR_INPUT", cable_braid_pressure_signs(s, a), CABLE_ERR_INPUT);
  s->ndim = knot->ndim;
  s->u[BR_ETA] = NAN;
  test_true("a NaN state is refused", cable_braid_pressure_signs(s, a) < 0);
  cable_solution_free(s);
  free(a);
}

int main(void)
{
  memrun *r = malloc(sizeof *r);
  memset(r, 0, sizeof *r);
  const int knot_icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21};
  cable_solution *right = flat_at("braid_knot", 7, +1, KNOT_DELTA, KNOT_LTOT, 2.0, knot_icp, 4, 40, r);
  cable_solution *left = flat_at("braid_knot", 7, -1, KNOT_DELTA, KNOT_LTOT, -2.0, knot_icp, 4, 40, r);
  test_true("flat (7,2) knots at T = +2 and -2 computed", right && left);
  if (right) check_flat_knot(right);
  if (right && left) check_mirror_closure(right, left);
  if (right) check_errors(right);
  cable_solution_free(right);
  cable_solution_free(left);
  check_flat_link(r);
  check_settled();
  free(r);
  return test_summary();
}
