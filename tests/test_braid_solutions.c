/* Converged braid solutions (engine + braid model + conditions + geometry):
 *  - the flat right-handed (7,2) knot at T = 2 and the left-handed one at
 *    T = -2: the same |F| (mirror symmetry), Lk = +3.5 and -3.5;
 *  - eps21 (the unfolding parameter of the redundant condition) vanishes and
 *    the first integrals are constant along the braid;
 *  - the flat left-handed (6,2) link: Lk = -3, an integer. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "braid_analysis.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable_cont.h"
#include "harness.h"
#include "ribbon.h"

/* Continue from the torus guess in T to T = target; returns the solution there. */
static cable_solution *flat_at(const char *name, int p, int hand, double delta, double length, double target,
                               const int *icp, int nicp, int ntst)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, p, hand, delta, length, 0.0);
  if (braid_start_prepare(&sp) != 0) return NULL;
  cable_problem pb;
  if (braid_problem_instance(name, &sp, &pb) != 0) return NULL;
  cable_constants c;
  cable_constants_init(&c);
  /* a uniform mesh (IAD=0) keeps the two mirror-image computations identical */
  c.ntst = ntst; c.ncol = 4; c.jac = 1; c.iad = 0;
  for (int k = 0; k < nicp; k++) c.icp[k] = icp[k];
  c.nicp = nicp;
  c.ds = target > 0 ? 0.5 : -0.5; c.dsmin = 1e-6; c.dsmax = 2.0; c.nmx = 200; c.isp = 0; c.ilp = 0;
  c.nuzr = 1; c.uzr[0].par = BP_T; c.uzr[0].value = target; c.uzr[0].stop = 1;
  c.epss = 1e-9;
  int st;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  while (st == 0) st = cable_cont_step(cc);
  cable_solution *s = st == CABLE_END_UZSTOP ? cable_solution_clone(cable_cont_solution(cc)) : NULL;
  cable_cont_free(cc);
  return s;
}

int main(void)
{
  const double delta = 0.0051364907419, ltot = 1.98889;
  const int knot_icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21};
  cable_solution *right = flat_at("braid_knot", 7, +1, delta, ltot, 2.0, knot_icp, 4, 40);
  cable_solution *left = flat_at("braid_knot", 7, -1, delta, ltot, -2.0, knot_icp, 4, 40);
  test_true("right-handed (7,2) knot reaches T = 2", right != NULL);
  test_true("left-handed (7,2) knot reaches T = -2", left != NULL);
  if (right && left) {
    /* the mirror image of a discrete solution solves the mirrored discrete
       problem on the same mesh: equal up to the Newton tolerance */
    test_rel("mirror symmetry: F(right, T) = F(left, -T)", left->par[BP_F], right->par[BP_F], 1e-8);
    test_rel("mirror symmetry: L", left->par[BP_L], right->par[BP_L], 1e-8);
    double lk, tw, wr;
    /* Lk is exactly half-integer for a closed knot ribbon; the interpolant's
       O(h^NCOL) geometry error and the quadrature bound the defect */
    if (braid_ribbon_lk(right, &lk, &tw, &wr) == 0) test_abs("right-handed (7,2): Lk = 3.5", lk, 3.5, 1e-6);
    else test_true("right-handed Lk computed", 0);
    if (braid_ribbon_lk(left, &lk, &tw, &wr) == 0) test_abs("left-handed (7,2): Lk = -3.5", lk, -3.5, 1e-6);
    else test_true("left-handed Lk computed", 0);
    /* eps21 must vanish on solutions of the original problem: only the
       Newton tolerance and round-off remain */
    test_le("eps21 vanishes on the knot", fabs(right->par[BP_EPS21]), 1e-9);
    /* first integrals are constant along s up to the discretisation error at
       the mesh points, O(h^(2 NCOL)) = O(h^8): halving h must shrink the drift
       by at least 2^6 (asymptotic rate 2^8, with slack for coarse meshes) */
    cable_solution *fine = flat_at("braid_knot", 7, +1, delta, ltot, 2.0, knot_icp, 4, 80);
    double d40 = braid_first_integral_drift(right), d80 = fine ? braid_first_integral_drift(fine) : 1.0;
    char what[128];
    snprintf(what, sizeof what, "first-integral drift converges like h^8: %.3g (NTST=40) -> %.3g (NTST=80)", d40, d80);
    test_true(what, d40 > 0 && d80 >= 0 && d80 * 64 <= d40);
    test_le("first-integral drift at NTST=40 (mesh points)", d40, 1e-7);
    cable_solution_free(fine);
  }
  cable_solution_free(right);
  cable_solution_free(left);

  const int link_icp[1] = {BP_T};
  cable_solution *link = flat_at("braid_link", 6, -1, 0.016016913268, 1.0, -1.0, link_icp, 1, 40);
  test_true("left-handed (6,2) link reaches T = -1", link != NULL);
  if (link) {
    double lk, tw, wr;
    if (braid_ribbon_lk(link, &lk, &tw, &wr) == 0) test_abs("left-handed (6,2) link: Lk = -3", lk, -3.0, 1e-6);
    else test_true("link Lk computed", 0);
    test_le("first-integral drift along the link at NTST=40 (mesh points)", braid_first_integral_drift(link), 1e-7);
  }
  cable_solution_free(link);
  return test_summary();
}
