/* SPDX-License-Identifier: GPL-3.0-or-later */
/* One, two and three threads give the same results, bit for bit (issue 17):
 * the structured solver's per-interval stages run on a thread team
 * (NTHREADS, continuation/base/cable_team.h) and every reduction runs in interval
 * order, so nothing may depend on the team size.  Checked on the flat (7,2)
 * braid knot through its first (double) branch point with the branch-point
 * tests on (ISP=2, NSV=2: determinant, singular values, the pencil test and
 * the dip location), on an adaptive mesh (IAD=3): every point's parameters,
 * test functions, type, iterations and the last solution are compared with
 * memcmp.  Also the team itself: every index of a loop is visited exactly
 * once for team sizes 1..4 and loop lengths 0..9.  And the per-interval
 * passes of the collocation system (residual and Jacobian, FUNC on the
 * team with per-thread scratch) directly: for 1, 2 and 3 threads on a mesh
 * that does not split evenly, with finite-difference Jacobians (which
 * perturb each thread's own copy of the parameters), the residual, every
 * Jacobian block and the FUNC count are identical; a FUNC that fails in
 * some intervals gives the same status for every thread count; a problem
 * that is not concurrent is evaluated on one thread. */
#define _GNU_SOURCE 1 /* sched_getaffinity, sched_setaffinity */
#include <dirent.h>
#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "braid_problems.h"
#include "braid_start.h"
#include "braid_state.h"
#include "cable/cable_cont.h"
#include "cable/cable_status.h"
#include "cable_team.h"
#include "colloc_system.h"
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
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
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

/* cable_team_run_ordered: the producer marks item i done (after a little
 * work, so that the consumer does wait sometimes); the consumer checks that
 * items 0..i are done and that it is called in order. */
typedef struct {
  int n;
  int produced[64];
  double work[64];
  int consumed, bad;
} ordered_probe;

static void ordered_produce(void *ctx, int i)
{
  ordered_probe *p = ctx;
  double x = 0.0;
  for (int k = 0; k < 2000 * (1 + i % 3); k++) x += sin(k * 1e-3 + i);
  p->work[i] = x;
  p->produced[i]++;
}

static void ordered_consume(void *ctx, int i)
{
  ordered_probe *p = ctx;
  if (i != p->consumed) p->bad = 1;
  for (int k = 0; k <= i; k++)
    if (p->produced[k] != 1) p->bad = 1;
  p->consumed++;
}

static void test_team_ordered(void)
{
  int ok = 1;
  for (int size = 1; size <= 3; size++) {
    cable_team *t = size == 1 ? NULL : cable_team_alloc(size);
    static const int ns[] = {0, 1, 2, 5, 64};
    for (int rep = 0; rep < 20; rep++)
      for (size_t q = 0; q < sizeof ns / sizeof ns[0]; q++) {
        ordered_probe p = {.n = ns[q]};
        cable_team_run_ordered(t, ordered_produce, &p, p.n, ordered_consume, &p);
        int once = 1;
        for (int i = 0; i < p.n; i++) once &= p.produced[i] == 1;
        if (p.bad || p.consumed != p.n || !once) ok = 0;
      }
    cable_team_free(t);
  }
  test_true("cable_team_run_ordered: every item made once and consumed once, in order, after items 0..i were made "
            "(teams of 1..3 threads, 0..64 items, 20 repeats)", ok);
}

/* u0' = u1, u1' = -lambda e^u0 + sin(3 u0 u1); fails (status 3) where u0 > fail_above. */
typedef struct {
  double fail_above;
} probe_params;

static int probe_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                      double *dfdu, double *dfdp, void *params)
{
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  const probe_params *pp = params;
  if (u[0] > pp->fail_above) return 3;
  f[0] = u[1];
  f[1] = -par[0] * exp(u[0]) + sin(3.0 * u[0] * u[1]);
  return 0;
}

static int probe_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                      int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)par; (void)icp; (void)nbc; (void)ijac; (void)dbc; (void)params;
  fb[0] = u0[0];
  fb[1] = u1[0];
  return 0;
}

typedef struct {
  int rc_res, rc_jac, last_callback, nwork;
  long nfunc;
  double *F, *coll, *bc, *dense, *dense_par;
  size_t ncoll, nbcv, ndensev, npar;
} pass_result;

static void pass_result_free(pass_result *r)
{
  free(r->F); free(r->coll); free(r->bc); free(r->dense); free(r->dense_par);
}

static double *dup(const double *a, size_t n)
{
  double *b = malloc(n * sizeof *b);
  if (b) memcpy(b, a, n * sizeof *b);
  return b;
}

/* One residual and one Jacobian of the probe problem on NTST 7, NCOL 3, JAC=0. */
static int probe_pass(int nthreads, int concurrent, double fail_above, pass_result *r)
{
  memset(r, 0, sizeof *r);
  probe_params pp = {fail_above};
  cable_problem pb = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "probe",
                      .ndim = 2, .nbc = 2, .nint = 0, .npar = 1, .func = probe_func, .bcnd = probe_bcnd,
                      .params = &pp, .concurrent = concurrent};
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.jac = 0;
  c.nthreads = nthreads;
  const int icp[] = {0};
  int st;
  colloc_system *s = colloc_system_alloc(&pb, &c, 7, 3, icp, 1, &st);
  if (!s) return -1;
  colloc_jac *J = colloc_jac_alloc(2, 7, 3, 1, 2, 0);
  double *x = calloc((size_t)s->n, sizeof *x), *F = calloc((size_t)s->n, sizeof *F);
  if (!J || !x || !F) return -1;
  for (int k = 0; k < 7 * 3 + 1; k++) {
    double t = (double)k / 21.0, pi = acos(-1.0);
    x[2 * k] = 0.8 * sin(pi * t) + 0.1 * t * t;
    x[2 * k + 1] = 0.8 * pi * cos(pi * t) + 0.2 * t;
  }
  x[s->n - 1] = 1.3;
  s->fixval = 1.3;
  r->nwork = s->nwork;
  r->rc_res = colloc_system_residual(s, x, F);
  r->rc_jac = colloc_system_jacobian(s, x, J);
  r->last_callback = s->last_callback;
  r->nfunc = s->nfunc;
  r->ncoll = (size_t)J->ntst * J->coll_stride;
  r->nbcv = (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr);
  r->ndensev = (size_t)J->ntst * J->dense_stride;
  r->npar = (size_t)J->ndense * (size_t)J->nfpr;
  r->F = dup(F, (size_t)s->n);
  r->coll = dup(J->coll, r->ncoll);
  r->bc = dup(J->bc, r->nbcv);
  r->dense = dup(J->dense, r->ndensev);
  r->dense_par = dup(J->dense_par, r->npar);
  free(x); free(F);
  colloc_jac_free(J);
  colloc_system_free(s);
  return r->F && r->coll && r->bc && r->dense && r->dense_par ? 0 : -1;
}

static int same_values(const pass_result *a, const pass_result *b, size_t n)
{
  return memcmp(a->F, b->F, n * sizeof(double)) == 0 && memcmp(a->coll, b->coll, a->ncoll * sizeof(double)) == 0 &&
         memcmp(a->bc, b->bc, a->nbcv * sizeof(double)) == 0 &&
         memcmp(a->dense, b->dense, a->ndensev * sizeof(double)) == 0 &&
         memcmp(a->dense_par, b->dense_par, a->npar * sizeof(double)) == 0;
}

static void test_passes(void)
{
  pass_result one, other;
  size_t n = 2 * (7 * 3 + 1) + 1;
  test_int("probe problem, one thread: residual and Jacobian evaluate", probe_pass(1, 1, 1e300, &one), 0);
  test_true("one thread: both passes succeed and FUNC was called", one.rc_res == 0 && one.rc_jac == 0 && one.nfunc > 0);
  test_int("one thread: one chunk", one.nwork, 1);
  for (int nt = 2; nt <= 3; nt++) {
    test_int("probe problem evaluates", probe_pass(nt, 1, 1e300, &other), 0);
    test_int("a concurrent problem: one chunk of intervals per thread", other.nwork, nt);
    test_report(other.rc_res == 0 && other.rc_jac == 0 && same_values(&one, &other, n),
                "NTHREADS=%d: the residual and every Jacobian block (finite differences in u and the parameter) "
                "equal one thread's bit for bit", nt);
    test_report(other.nfunc == one.nfunc, "NTHREADS=%d: the same FUNC count (%ld, one thread %ld)", nt, other.nfunc,
                one.nfunc);
    pass_result_free(&other);
  }
  pass_result_free(&one);
  /* u0 peaks at 0.8 + 0.1 t^2 near t = 0.5: FUNC fails in the middle intervals only */
  test_int("failing FUNC, one thread", probe_pass(1, 1, 0.7, &one), 0);
  test_true("one thread: both passes return FUNC's status 3 and last_callback is 3",
            one.rc_res == 3 && one.rc_jac == 3 && one.last_callback == 3);
  for (int nt = 2; nt <= 3; nt++) {
    test_int("failing FUNC", probe_pass(nt, 1, 0.7, &other), 0);
    test_report(other.rc_res == 3 && other.rc_jac == 3 && other.last_callback == 3,
                "NTHREADS=%d: the same failure status from both passes (%d %d %d)", nt, other.rc_res, other.rc_jac,
                other.last_callback);
    pass_result_free(&other);
  }
  pass_result_free(&one);
  test_int("a problem that is not concurrent", probe_pass(3, 0, 1e300, &other), 0);
  test_int("not concurrent: NTHREADS=3 evaluates FUNC on one thread (one chunk)", other.nwork, 1);
  pass_result_free(&other);
}

/* J X by a team of 1, 2, 3 threads: the same bits as colloc_jac_matvec_many,
 * and the dense product to round-off (an independent check). */
static void test_matvec(void)
{
  colloc_jac *J = colloc_jac_alloc(3, 9, 3, 2, 3, 1);
  if (!J) {
    test_true("matvec: allocation", 0);
    return;
  }
  const size_t n = (size_t)J->n, k = 2;
  double *X = malloc(k * n * sizeof *X), *Y0 = malloc(k * n * sizeof *Y0), *Y = malloc(k * n * sizeof *Y);
  double *A = malloc(n * n * sizeof *A);
  if (!X || !Y0 || !Y || !A) {
    test_true("matvec: allocation", 0);
    free(X); free(Y0); free(Y); free(A);
    colloc_jac_free(J);
    return;
  }
  uint64_t st = 12345;
  double *blocks[] = {J->coll, J->bc, J->dense, J->dense_par, X};
  size_t sizes[] = {(size_t)J->ntst * J->coll_stride, (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr),
                    (size_t)J->ntst * J->dense_stride, (size_t)J->ndense * (size_t)J->nfpr, k * n};
  for (int b = 0; b < 5; b++)
    for (size_t i = 0; i < sizes[b]; i++) {
      st = st * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
      blocks[b][i] = (double)(st >> 11) * 0x1.0p-53 - 0.5;
    }
  colloc_jac_matvec_many(J, (int)k, X, Y0);
  colloc_jac_to_dense(J, A);
  double err = 0, scale = 0;
  for (size_t v = 0; v < k; v++)
    for (size_t r = 0; r < n; r++) {
      double y = 0;
      for (size_t c = 0; c < n; c++) y += A[c * n + r] * X[v * n + c];
      err = fmax(err, fabs(y - Y0[v * n + r]));
      scale = fmax(scale, fabs(y));
    }
  /* sums of at most (NCOL+1) NDIM + NFPR products of numbers below 1/2:
     round-off a few units of 1e-16 times the number of terms */
  test_le("matvec: J X equals the dense product (max abs error / max |J X|)", err / scale, 1e-14);
  for (int size = 1; size <= 3; size++) {
    cable_team *t = cable_team_alloc(size);
    colloc_jac_matvec_many_team(J, t, (int)k, X, Y);
    int same = memcmp(Y, Y0, k * n * sizeof *Y) == 0;
    colloc_jac_matvec_team(J, t, X + n, Y);
    same = same && memcmp(Y, Y0 + n, n * sizeof *Y) == 0;
    test_report(t != NULL && same, "matvec: a team of %d thread(s) gives colloc_jac_matvec_many's bits", size);
    cable_team_free(t);
  }
  /* J X and J^T X' in one pass (colloc_jac_matvec_pair_team): the bits of
     the separate calls for every team size; J^T X' against the dense
     product, the blocks' sums of squares against a plain sum */
  double *XT = malloc(k * n * sizeof *XT), *YT0 = malloc(k * n * sizeof *YT0), *YT = malloc(k * n * sizeof *YT);
  double *scr = malloc(colloc_jac_pair_scratch(J, (int)k) * sizeof *scr), *sq = malloc((size_t)J->ntst * sizeof *sq);
  if (XT && YT0 && YT && scr && sq) {
    for (size_t i = 0; i < k * n; i++) XT[i] = X[(i * 7 + 3) % (k * n)] - 0.25;
    test_int("matvec: J^T X (status)", colloc_jac_matvec_transpose_many(J, (int)k, XT, YT0), CABLE_SUCCESS);
    double errt = 0, scalet = 0;
    for (size_t v = 0; v < k; v++)
      for (size_t c = 0; c < n; c++) {
        double y = 0;
        for (size_t r = 0; r < n; r++) y += A[c * n + r] * XT[v * n + r];
        errt = fmax(errt, fabs(y - YT0[v * n + c]));
        scalet = fmax(scalet, fabs(y));
      }
    test_le("matvec: J^T X equals the dense product (max abs error / max |J^T X|)", errt / scalet, 1e-14);
    double sqerr = 0;
    for (int size = 1; size <= 3; size++) {
      cable_team *t = cable_team_alloc(size);
      colloc_jac_matvec_pair_team(J, t, (int)k, X, Y, XT, YT, scr, sq);
      int same = memcmp(Y, Y0, k * n * sizeof *Y) == 0 && memcmp(YT, YT0, k * n * sizeof *YT) == 0;
      test_report(t != NULL && same,
                  "matvec: J X and J^T X' in one pass, team of %d: the bits of the separate calls", size);
      cable_team_free(t);
    }
    for (int j = 0; j < J->ntst; j++) {
      double s = 0;
      for (size_t i = 0; i < J->coll_stride; i++) s += J->coll[(size_t)j * J->coll_stride + i] * J->coll[(size_t)j * J->coll_stride + i];
      sqerr = fmax(sqerr, fabs(s - sq[j]) / s);
    }
    test_le("matvec: the blocks' sums of squares from the pair pass (relative error)", sqerr, 1e-14);
  } else {
    test_true("matvec: allocation", 0);
  }
  free(XT); free(YT0); free(YT); free(scr); free(sq);
  free(X); free(Y0); free(Y); free(A);
  colloc_jac_free(J);
}

/* NTHREADS = 0 (the default) takes the processors this process may run on,
 * without a cap: the count of /proc/self/status's Cpus_allowed_list, and 1
 * after the process is pinned to one of them (sched_setaffinity). */
static int allowed_cpus(void)
{
  FILE *f = fopen("/proc/self/status", "r");
  char line[4096];
  int n = -1;
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, "Cpus_allowed_list:", 18) == 0) {
      n = 0;
      for (char *p = line + 18; *p;) {
        char *end;
        long a = strtol(p, &end, 10);
        if (end == p) { p++; continue; }
        long b = a;
        if (*end == '-') b = strtol(end + 1, &end, 10);
        n += (int)(b - a + 1);
        p = end;
      }
    }
  if (f) fclose(f);
  return n;
}

static void test_default_threads(void)
{
  cable_constants c;
  cable_constants_init(&c);
  int want = allowed_cpus();
  if (want < 1) {
    test_skip("default NTHREADS", "no Cpus_allowed_list in /proc/self/status");
    return;
  }
  test_int("default NTHREADS = the processors this process may use (no cap)", cable_threads(&c),
           want < CABLE_THREADS_MAX ? want : CABLE_THREADS_MAX);
  cpu_set_t all, one;
  if (sched_getaffinity(0, sizeof all, &all) != 0) return;
  CPU_ZERO(&one);
  for (int k = 0; k < CPU_SETSIZE; k++)
    if (CPU_ISSET(k, &all)) {
      CPU_SET(k, &one);
      break;
    }
  if (sched_setaffinity(0, sizeof one, &one) == 0) {
    test_int("default NTHREADS after pinning to one processor", cable_threads(&c), 1);
    sched_setaffinity(0, sizeof all, &all);
  }
  c.nthreads = 3;
  test_int("NTHREADS = 3 as set", cable_threads(&c), 3);
}

/* The threads of this process (/proc/self/task). */
static int process_threads(void)
{
  DIR *d = opendir("/proc/self/task");
  if (!d) return -1;
  int n = 0;
  for (struct dirent *e; (e = readdir(d)) != NULL;) n += e->d_name[0] != '.';
  closedir(d);
  return n;
}

/* One thread team per engine handle: NTHREADS = 3 on a concurrent problem
 * (the braid knot: its residual and Jacobian loops run on the team too)
 * starts 2 workers, not 2 for each of the Newton solver, the tangent solver
 * and the collocation loops. */
static void test_one_team(void)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, 1, 0.0051364907419, 1.98889, 0.0);
  cable_problem pb;
  int ok = braid_start_prepare(&sp) == 0 && braid_problem_instance("braid_knot", &sp, &pb) == 0;
  test_true("one team: the braid knot is a concurrent problem", ok && pb.concurrent);
  if (!ok) return;
  cable_constants c;
  cable_constants_init(&c);
  c.ips = 4;
  const int icp[] = {BP_T, BP_L, BP_L2, BP_EPS21, BP_F};
  for (int k = 0; k < 5; k++) c.icp[k] = icp[k];
  c.nicp = 5;
  c.ntst = 20;
  c.nthreads = 3;
  int before = process_threads(), st;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  int during = process_threads();
  cable_cont_free(cc);
  int after = process_threads();
  test_int("one team: NTHREADS=3 starts 2 worker threads per handle", during - before, 2);
  test_int("one team: cable_cont_free ends them", after, before);
}

int main(void)
{
  test_one_team();
  test_team();
  test_team_ordered();
  test_matvec();
  test_passes();
  test_branch();
  test_default_threads();
  return test_summary();
}
