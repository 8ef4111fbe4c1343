/* Benchmark (make bench, not a test): cost of continuation steps and of the
 * linear algebra on the flat (7,2) braid knot, NDIM = 21, NCOL = 4.
 * Prints a Markdown table; every time is the median of REPEATS runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "abd_solver.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable_cont.h"
#include "colloc_jac.h"
#include "colloc_newton.h"
#include "colloc_system.h"

#define REPEATS 3
#define STEPS 10

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n)
{
  qsort(v, (size_t)n, sizeof *v, cmp);
  return v[n / 2];
}

static void constants(cable_constants *c, int ntst, cable_linsolver ls)
{
  cable_constants_init(c);
  c->ntst = ntst; c->ncol = 4; c->jac = 1; c->iad = 0; c->linsolver = ls;
  c->icp[0] = BP_T; c->icp[1] = BP_L; c->icp[2] = BP_L2; c->icp[3] = BP_EPS21; c->nicp = 4;
  c->ds = 1.0; c->dsmin = 1e-6; c->dsmax = 1.0; c->iads = 0; c->nmx = STEPS + 1;
  c->isp = 2; c->ilp = 0; c->rl0 = -40; c->rl1 = 40;
}

/* seconds per continuation step (after the start), median over REPEATS */
static double step_time(const cable_problem *pb, int ntst, cable_linsolver ls, double *newton_per_step)
{
  double t[REPEATS];
  int iters = 0, steps = 0;
  for (int r = 0; r < REPEATS; r++) {
    cable_constants c;
    constants(&c, ntst, ls);
    int st;
    cable_cont *cc = cable_cont_alloc(pb, &c, &st);
    if (st == 0) st = cable_cont_set_start(cc, NULL);
    if (st == 0) st = cable_cont_step(cc); /* the start: not timed */
    double t0 = now();
    iters = steps = 0;
    while (st == 0 && (st = cable_cont_step(cc)) == 0) {
      iters += cable_cont_point(cc)->newton_iters;
      steps++;
    }
    t[r] = (now() - t0) / (steps > 0 ? steps : 1);
    cable_cont_free(cc);
  }
  *newton_per_step = steps ? (double)iters / steps : 0;
  return median(t, REPEATS);
}

/* seconds for one Jacobian assembly and one factorisation at the start point */
static void phase_times(const cable_problem *pb, int ntst, double *t_jac, double *t_fact)
{
  cable_constants c;
  constants(&c, ntst, CABLE_LINSOLVER_CONDENSE);
  int icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21}, st;
  colloc_system *s = colloc_system_alloc(pb, &c, ntst, 4, icp, 4, &st);
  colloc_jac *J = colloc_jac_alloc(21, ntst, 4, 4, pb->nbc, 0);
  abd_solver *a = abd_solver_alloc(21, ntst, 4, 4, pb->nbc, 0);
  double *x = calloc((size_t)s->n, sizeof *x), *t = calloc((size_t)(ntst * 4 + 1), sizeof *t);
  colloc_system_times(s, t);
  for (int k = 0; k <= ntst * 4; k++) pb->stpnt(21, t[k], x + (size_t)k * 21, s->par, pb->params);
  for (int q = 0; q < 4; q++) x[s->n - 4 + q] = s->par[icp[q]];
  s->closing = COLLOC_CLOSE_FIXPAR;
  double tj[REPEATS], tf[REPEATS];
  for (int r = 0; r < REPEATS; r++) {
    double t0 = now();
    colloc_system_jacobian(s, x, J);
    double t1 = now();
    abd_solver_factor(a, J);
    tf[r] = now() - t1;
    tj[r] = t1 - t0;
  }
  *t_jac = median(tj, REPEATS);
  *t_fact = median(tf, REPEATS);
  free(x); free(t);
  abd_solver_free(a);
  colloc_jac_free(J);
  colloc_system_free(s);
}

int main(void)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, +1, 0.0051364907419, 1.98889, 0.0);
  if (braid_start_prepare(&sp) != 0) return 1;
  cable_problem pb;
  braid_problem_instance("braid_knot", &sp, &pb);
  printf("| NTST | step, condensation (s) | Newton it./step | assembly (s) | factorisation (s) | step, KLU (s) | KLU / condensation |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  static const int ntsts[] = {25, 50, 100, 150, 200, 400};
  for (size_t i = 0; i < sizeof ntsts / sizeof ntsts[0]; i++) {
    int ntst = ntsts[i];
    double nit, nitk, tj, tf;
    double tc = step_time(&pb, ntst, CABLE_LINSOLVER_CONDENSE, &nit);
    phase_times(&pb, ntst, &tj, &tf);
    /* KLU becomes very slow beyond NTST ~ 100 at NDIM = 21 (doc/linear-algebra.md) */
    double tk = ntst <= 100 ? step_time(&pb, ntst, CABLE_LINSOLVER_KLU, &nitk) : (double)NAN;
    if (isnan(tk))
      printf("| %d | %.4f | %.1f | %.4f | %.4f | not run | - |\n", ntst, tc, nit, tj, tf);
    else
      printf("| %d | %.4f | %.1f | %.4f | %.4f | %.4f | %.1f |\n", ntst, tc, nit, tj, tf, tk, tk / tc);
    fflush(stdout);
  }
  return 0;
}
