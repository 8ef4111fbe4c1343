/* One, two and three threads give the same results, bit for bit (issue 17):
 * the structured solver's per-interval stages run on a thread team
 * (NTHREADS, continuation/cable_team.h) and every reduction runs in interval
 * order, so nothing may depend on the team size.  Checked on the flat (7,2)
 * braid knot through its first (double) branch point with the branch-point
 * tests on (ISP=2, NSV=2: determinant, singular values, the pencil test and
 * the dip location), on an adaptive mesh (IAD=3): every point's parameters,
 * test functions, type, iterations and the last solution are compared with
 * memcmp.  Also the team itself: every index of a loop is visited exactly
 * once for team sizes 1..4 and loop lengths 0..9. */
#include <string.h>

#include "braid_problems.h"
#include "braid_start.h"
#include "braid_state.h"
#include "cable/cable_cont.h"
#include "cable/cable_status.h"
#include "cable_team.h"
#include "harness.h"

#define MAXPTS 64

typedef struct {
  int npts;
  int end;
  int itp[MAXPTS], iters[MAXPTS], det[MAXPTS];
  double par[MAXPTS][BP_NPAR];
  double sv[MAXPTS][2];
  double ds[MAXPTS];
  cable_solution *last;
} branch;

static int run_flat(int nthreads, branch *b)
{
  memset(b, 0, sizeof *b);
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, 1, 0.0051364907419, 1.98889, 0.0);
  if (braid_start_prepare(&sp) != 0) return -1;
  cable_problem pb;
  if (braid_problem_instance("braid_knot", &sp, &pb) != 0) return -1;
  cable_constants c;
  cable_constants_init(&c);
  const int icp[] = {BP_T, BP_L, BP_L2, BP_EPS21, BP_F};
  for (int k = 0; k < 5; k++) c.icp[k] = icp[k];
  c.nicp = 5;
  c.ntst = 20; c.ncol = 4; c.iad = 3; c.jac = 1;
  c.isp = 2; c.nsv = 2; c.ilp = 0;
  c.ds = 5.0; c.dsmin = 1e-6; c.dsmax = 20.0; c.nmx = 12;
  c.epsl = c.epsu = c.epss = 1e-7;
  c.nthreads = nthreads;
  int st;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  while (st == 0 && b->npts < MAXPTS) {
    st = cable_cont_step(cc);
    if (st != 0) break;
    const cable_point *p = cable_cont_point(cc);
    int k = b->npts++;
    b->itp[k] = p->itp;
    b->iters[k] = p->newton_iters;
    b->det[k] = p->det_sign;
    b->sv[k][0] = p->sv1;
    b->sv[k][1] = p->sv2;
    b->ds[k] = p->ds;
    memcpy(b->par[k], p->par, sizeof b->par[k]);
  }
  b->end = st;
  b->last = cable_solution_clone(cable_cont_solution(cc));
  cable_cont_free(cc);
  return 0;
}

static int same_solution(const cable_solution *a, const cable_solution *b)
{
  if (!a || !b || a->ndim != b->ndim || a->ntst != b->ntst || a->ncol != b->ncol || a->npar != b->npar) return 0;
  size_t np = (size_t)a->ntst * (size_t)a->ncol + 1;
  return memcmp(a->t, b->t, np * sizeof(double)) == 0 &&
         memcmp(a->u, b->u, np * (size_t)a->ndim * sizeof(double)) == 0 &&
         memcmp(a->par, b->par, (size_t)a->npar * sizeof(double)) == 0;
}

static void test_branch(void)
{
  static branch one, other;
  test_int("flat branch, NTHREADS=1, runs", run_flat(1, &one), 0);
  int bps = 0;
  for (int k = 0; k < one.npts; k++) bps += one.itp[k] % 10 == CABLE_TY_BP;
  test_true("NTHREADS=1: the branch reaches NMX and passes a branch point (the tests are exercised)",
            one.end == CABLE_END_NMX && bps >= 1);
  for (int nt = 2; nt <= 3; nt++) {
    test_int("flat branch runs", run_flat(nt, &other), 0);
    test_int("the same end", other.end, one.end);
    test_int("the same number of points", other.npts, one.npts);
    int n = one.npts < other.npts ? one.npts : other.npts;
    int same = memcmp(one.itp, other.itp, (size_t)n * sizeof(int)) == 0 &&
               memcmp(one.iters, other.iters, (size_t)n * sizeof(int)) == 0 &&
               memcmp(one.det, other.det, (size_t)n * sizeof(int)) == 0 &&
               memcmp(one.par, other.par, (size_t)n * sizeof one.par[0]) == 0 &&
               memcmp(one.sv, other.sv, (size_t)n * sizeof one.sv[0]) == 0 &&
               memcmp(one.ds, other.ds, (size_t)n * sizeof(double)) == 0;
    test_report(same, "NTHREADS=%d: every point's parameters, singular values, det signs, types, iterations and "
                "step sizes equal NTHREADS=1's bit for bit (%d points, T at the last %.17g / %.17g)",
                nt, n, other.par[n - 1][BP_T], one.par[n - 1][BP_T]);
    test_report(same_solution(one.last, other.last), "NTHREADS=%d: the last solution (mesh, nodes, PAR) is "
                "identical bit for bit", nt);
    cable_solution_free(other.last);
  }
  cable_solution_free(one.last);
}

static void count_visit(void *ctx, int i) { ((int *)ctx)[i]++; }

static void test_team(void)
{
  int ok = 1;
  for (int size = 1; size <= 4; size++) {
    cable_team *t = cable_team_alloc(size);
    if (!t || cable_team_size(t) != size) ok = 0;
    for (int n = 0; n < 10 && t; n++) {
      int seen[10] = {0};
      cable_team_run(t, count_visit, seen, n);
      for (int i = 0; i < 10; i++)
        if (seen[i] != (i < n)) ok = 0;
    }
    cable_team_free(t);
  }
  test_true("cable_team: every index of loops of length 0..9 visited exactly once by teams of 1..4 threads", ok);
  cable_team_free(NULL);
  int seen[3] = {0};
  cable_team_run(NULL, count_visit, seen, 3);
  test_true("cable_team_run(NULL, ...) is the plain loop", seen[0] == 1 && seen[1] == 1 && seen[2] == 1);
}

int main(void)
{
  test_team();
  test_branch();
  return test_summary();
}
