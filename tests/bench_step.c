/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Benchmark (make bench, not a test): cost of continuation steps and of the
 * linear algebra on the flat (7,2) braid knot, NDIM = 21, NCOL = 4.
 * Prints a Markdown table; every time is the median of REPEATS runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <dirent.h>
#include <unistd.h>

#include "bench_util.h"
#include "bench_knot72.h"
#include "abd_solver.h"
#include "cable/cable_aufile.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_cont.h"
#include "colloc_jac.h"
#include "colloc_newton.h"
#include "colloc_system.h"
#include "cable/cable_constants.h"
#include "cable/cable_names.h"

#define REPEATS 3
#define STEPS 10

typedef struct {
  cable_linsolver ls;
  int jac;        /* 1 analytic, 0 finite differences */
  int isp;        /* 2: determinant sign and singular values every step; 0: none */
  int repeats;
} step_setup;

static void constants(cable_constants *c, int ntst, cable_linsolver ls)
{
  cable_constants_init(c); c->ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c->ntst = ntst; c->ncol = 4; c->jac = 1; c->iad = 0; c->linsolver = ls;
  c->icp[0] = BP_T; c->icp[1] = BP_L; c->icp[2] = BP_L2; c->icp[3] = BP_EPS21; c->nicp = 4;
  c->ds = 1.0; c->dsmin = 1e-6; c->dsmax = 1.0; c->iads = 0; c->nmx = STEPS + 1;
  c->isp = 2; c->ilp = 0; c->rl0 = -40; c->rl1 = 40;
}

/* seconds per continuation step (after the start), median over REPEATS */
static double step_time(const cable_problem *pb, int ntst, step_setup su, double *newton_per_step)
{
  double t[REPEATS];
  int iters = 0, steps = 0;
  for (int r = 0; r < su.repeats; r++) {
    cable_constants c;
    constants(&c, ntst, su.ls);
    c.jac = su.jac;
    c.isp = su.isp;
    int st;
    cable_cont *cc = cable_cont_alloc(pb, &c, &st);
    if (st == 0) st = cable_cont_set_start(cc, NULL);
    if (st == 0) st = cable_cont_step(cc); /* the start: not timed */
    double t0 = bench_now();
    iters = steps = 0;
    while (st == 0 && (st = cable_cont_step(cc)) == 0) {
      iters += cable_cont_point(cc)->newton_iters;
      steps++;
    }
    t[r] = (bench_now() - t0) / (steps > 0 ? steps : 1);
    cable_cont_free(cc);
  }
  *newton_per_step = steps ? (double)iters / steps : 0;
  return bench_median(t, su.repeats);
}

/* the writer's temporary directory and the files in it */
static void remove_dir(const char *dir)
{
  DIR *d = opendir(dir);
  if (d) {
    struct dirent *e;
    char path[4096];
    while ((e = readdir(d)) != NULL) {
      if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
      snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
      unlink(path);
    }
    closedir(d);
  }
  rmdir(dir);
}

/* seconds per step spent writing output: the same run through cable_cont_run
 * with the b./s./d./CSV writer (NPR = 1: every point labelled and stored in
 * the s-file, the most output a run can ask for) minus the run with a sink
 * that discards everything; median over REPEATS of each.  NAN when the
 * temporary directory or a file cannot be written. */
static double output_time(const cable_problem *pb, int ntst)
{
  double tw[REPEATS], tn[REPEATS];
  cable_names names;
  cable_names_init(&names);
  cable_names_fill(&names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  for (int r = 0; r < REPEATS; r++) {
    for (int with_files = 0; with_files <= 1; with_files++) {
      cable_constants c;
      constants(&c, ntst, CABLE_LINSOLVER_CONDENSE);
      c.npr = 1;
      cable_constants_take_problem_dims(&c, pb->ndim, pb->nbc, pb->nint);
      char dir[] = "/tmp/cable-bench-out.XXXXXX";
      cable_aufile *w = NULL;
      cable_error err;
      cable_sink sink = {NULL, NULL, NULL, NULL};
      if (with_files) {
        if (!mkdtemp(dir)) return (double)NAN;
        w = cable_aufile_open(dir, "bench", &c, &names, NULL, &err);
        if (!w) return (double)NAN;
        sink = cable_aufile_sink(w);
      }
      int st;
      double t0 = bench_now();
      cable_cont *cc = cable_cont_alloc(pb, &c, &st);
      if (st == 0) st = cable_cont_set_start(cc, NULL);
      if (st == 0) st = cable_cont_run(cc, &sink, 1, 1, NULL);
      cable_cont_free(cc);
      int cst = w ? cable_aufile_close(w, &err) : 0;
      double t = (bench_now() - t0) / (STEPS + 1);
      if (with_files) {
        remove_dir(dir);
        if (cst != 0) return (double)NAN;
        tw[r] = t;
      } else {
        tn[r] = t;
      }
      if (st < 0) return (double)NAN;
    }
  }
  return bench_median(tw, REPEATS) - bench_median(tn, REPEATS);
}

/* Medians (s) of the phases of one Newton iteration at the start point,
 * and of the branch-point test functions' extra work. */
typedef struct {
  double residual;   /* collocation residual: NTST*NCOL FUNC calls + BCND */
  double assembly;   /* analytic Newton matrix (FUNC and DFDU/DFDP at every node) */
  double factor;     /* structured factorisation: local condensation + banded LU */
  double solve;      /* one solve with that factorisation */
  double sv;         /* two smallest singular values by inverse iteration (ISP=2) */
} phase_costs;

static phase_costs phase_times(const cable_problem *pb, int ntst)
{
  phase_costs pc = {0, 0, 0, 0, 0};
  cable_constants c;
  constants(&c, ntst, CABLE_LINSOLVER_CONDENSE);
  int icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21}, st;
  colloc_system *s = colloc_system_alloc(pb, &c, ntst, 4, icp, 4, &st);
  colloc_jac *J = colloc_jac_alloc(21, ntst, 4, 4, pb->nbc, 0);
  abd_solver *a = abd_solver_alloc(21, ntst, 4, 4, pb->nbc, 0);
  double *x = calloc((size_t)s->n, sizeof *x), *t = calloc((size_t)(ntst * 4 + 1), sizeof *t);
  double *F = calloc((size_t)s->n, sizeof *F), *vecs = calloc((size_t)s->n * 2, sizeof *vecs);
  colloc_system_times(s, t);
  for (int k = 0; k <= ntst * 4; k++) pb->stpnt(21, t[k], x + (size_t)k * 21, s->par, pb->params);
  for (int q = 0; q < 4; q++) x[s->n - 4 + q] = s->par[icp[q]];
  s->closing = COLLOC_CLOSE_FIXPAR;
  double tr[REPEATS], tj[REPEATS], tf[REPEATS], ts[REPEATS], tv[REPEATS];
  for (int r = 0; r < REPEATS; r++) {
    double t0 = bench_now();
    colloc_system_residual(s, x, F);
    double t1 = bench_now();
    colloc_system_jacobian(s, x, J);
    double t2 = bench_now();
    abd_solver_factor(a, J);
    double t3 = bench_now();
    abd_solver_solve(a, F);
    double t4 = bench_now();
    double sv[2];
    abd_solver_smallest_sv(a, J, 2, sv, vecs, 12, 1e-6); /* the engine's CONT_SV_MAXIT, CONT_SV_RTOL */
    double t5 = bench_now();
    tr[r] = t1 - t0; tj[r] = t2 - t1; tf[r] = t3 - t2; ts[r] = t4 - t3; tv[r] = t5 - t4;
  }
  pc.residual = bench_median(tr, REPEATS);
  pc.assembly = bench_median(tj, REPEATS);
  pc.factor = bench_median(tf, REPEATS);
  pc.solve = bench_median(ts, REPEATS);
  pc.sv = bench_median(tv, REPEATS);
  free(x); free(t); free(F); free(vecs);
  abd_solver_free(a);
  colloc_jac_free(J);
  colloc_system_free(s);
  return pc;
}

int main(void)
{
  braid_start_params sp;
  cable_problem pb;
  if (bench_knot72(&sp, &pb) != 0) return 1;
  static const int ntsts[] = {25, 50, 100, 150, 200, 400, 800};
  enum { NN = sizeof ntsts / sizeof ntsts[0] };

  printf("Phases of one Newton iteration (s):\n\n");
  printf("| NTST | residual | assembly | factorisation | solve | one Newton iteration | the same per NTST (us) | two smallest singular values |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int i = 0; i < NN; i++) {
    phase_costs pc = phase_times(&pb, ntsts[i]);
    double it = pc.residual + pc.assembly + pc.factor + pc.solve;
    printf("| %d | %.5f | %.5f | %.5f | %.5f | %.5f | %.1f | %.5f |\n", ntsts[i], pc.residual, pc.assembly, pc.factor,
           pc.solve, it, 1e6 * it / ntsts[i], pc.sv);
    fflush(stdout);
  }

  printf("\nContinuation steps (s per step):\n\n");
  printf("| NTST | step, condensation | Newton it./step | step without BP tests, ISP=0 | BP tests' share | output per step, NPR=1 | output share | step, FD Jacobian | FD / analytic | step, KLU | KLU / condensation |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int i = 0; i < NN; i++) {
    int ntst = ntsts[i];
    double nit, nit0, nitf, nitk;
    step_setup base = {CABLE_LINSOLVER_CONDENSE, 1, 2, REPEATS};
    double tc = step_time(&pb, ntst, base, &nit);
    step_setup noisp = base, fd = base, klu = base;
    noisp.isp = 0;
    fd.jac = 0;
    klu.ls = CABLE_LINSOLVER_KLU;
    double t0 = step_time(&pb, ntst, noisp, &nit0);
    double tfd = ntst <= 200 ? step_time(&pb, ntst, fd, &nitf) : (double)NAN;
    /* KLU's fill-in makes it very slow beyond NTST ~ 100 at NDIM = 21
       (doc/linear-algebra.md): one run at NTST = 200, none beyond */
    klu.repeats = ntst >= 200 ? 1 : REPEATS;
    double tk = ntst <= 200 ? step_time(&pb, ntst, klu, &nitk) : (double)NAN;
    char fds[64] = "not run | -", klus[64] = "not run | -";
    if (!isnan(tfd)) snprintf(fds, sizeof fds, "%.4f | %.1f", tfd, tfd / tc);
    if (!isnan(tk)) snprintf(klus, sizeof klus, "%.4f%s | %.1f", tk, klu.repeats == 1 ? " (1 run)" : "", tk / tc);
    double tout = output_time(&pb, ntst);
    printf("| %d | %.4f | %.1f | %.4f | %.0f %% | %.5f | %.0f %% | %s | %s |\n", ntst, tc, nit, t0,
           100.0 * (tc - t0) / tc, tout, 100.0 * tout / tc, fds, klus);
    fflush(stdout);
  }
  return 0;
}
