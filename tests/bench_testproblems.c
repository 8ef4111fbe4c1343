/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Benchmark (make bench, not a test): work against precision on the engine's
 * test problems, whose special points are known exactly:
 *   Bratu     u'' + lambda e^u = 0, u(0) = u(1) = 0: the fold at
 *             lambda* = 3.513830719125162 (the root of the closed form's
 *             dlambda/dtheta, quoted to 16 digits in the literature);
 *   elastica  theta'' + lambda sin theta = 0, theta'(0) = theta'(1) = 0: the
 *             branch points of the trivial branch at (n pi)^2, n = 1, 2, 3.
 * For NTST in {25, 50, 100, 200, 400} and NCOL in {3, 4, 5, 7}: the time of the
 * whole run (median of REPEATS), the time per accepted step and the relative
 * error of the located points.  Prints Markdown tables. */
#include <gsl/gsl_math.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "cable/cable_constants.h"
#include "engine_util.h"
#include "test_problems.h"

#define REPEATS 3
#define BRATU_FOLD 3.513830719125162
#define NBP 3
/* Errors below this are shown as "<": round-off in lambda* ~ 3.5 (a few ulp
   times the conditioning of the fold).  The location tolerance EPSS = 1e-10
   acts on the arclength: the fold's lambda, quadratic in the arclength there,
   is found far below it; a BP's lambda, linear in it, to about EPSS |DS| /
   lambda (the branch points' floor of ~2e-12 in the table). */
#define FLOOR 1e-13

static const int ntsts[] = {25, 50, 100, 200, 400};
static const int ncols[] = {3, 4, 5, 7};
#define NNTST ((int)(sizeof ntsts / sizeof ntsts[0]))
#define NNCOL ((int)(sizeof ncols / sizeof ncols[0]))

typedef struct {
  double seconds;   /* median over REPEATS */
  int steps;        /* accepted points of the run */
  double err;       /* largest relative error of the located points; NAN if one is missing */
} bench_row;

/* The Bratu branch from u = 0 through its fold (as in runs/bratu). */
static void bratu_constants(cable_constants *c, int ntst, int ncol)
{
  engine_constants(c, ntst, ncol);
  c->ds = 0.1; c->dsmin = 1e-6; c->dsmax = 0.5; c->nmx = 60;
  c->rl1 = 10.0;
  c->ilp = 1; c->isp = 0;
  c->epss = 1e-10;
}

static double bratu_error(const memrun *r)
{
  const cable_solution *lp = memrun_find(r, CABLE_TY_LP, 0);
  return lp ? fabs(lp->par[0] - BRATU_FOLD) / BRATU_FOLD : (double)NAN;
}

static double elastica_error(const memrun *r)
{
  double worst = 0;
  for (int n = 1; n <= NBP; n++) {
    const cable_solution *bp = memrun_find(r, CABLE_TY_BP, n - 1);
    if (!bp) return (double)NAN;
    double exact = (n * M_PI) * (n * M_PI);
    worst = fmax(worst, fabs(bp->par[0] - exact) / exact);
  }
  return worst;
}

static bench_row measure(const cable_problem *pb, void (*setup)(cable_constants *, int, int),
                         double (*error)(const memrun *), int ntst, int ncol, memrun *r)
{
  bench_row row = {0, 0, (double)NAN};
  double t[REPEATS];
  for (int k = 0; k < REPEATS; k++) {
    cable_constants c;
    setup(&c, ntst, ncol);
    double t0 = bench_now();
    int st = memrun_run(pb, &c, NULL, r);
    t[k] = bench_now() - t0;
    if (k == 0) {
      row.steps = r->n;
      row.err = st > 0 ? error(r) : (double)NAN;
      if (st <= 0) fprintf(stderr, "bench_testproblems: NTST=%d NCOL=%d: %s\n", ntst, ncol, r->err);
    }
    memrun_free(r);
  }
  row.seconds = bench_median(t, REPEATS);
  return row;
}

static void table(const char *title, const char *what, const cable_problem *pb,
                  void (*setup)(cable_constants *, int, int), double (*error)(const memrun *), memrun *r)
{
  printf("%s\n\n", title);
  printf("| NTST | NCOL | run (s) | steps | per step (ms) | rel. error %s |\n", what);
  printf("|---:|---:|---:|---:|---:|---:|\n");
  double best_t = INFINITY;
  int best_n = 0, best_c = 0;
  for (int c = 0; c < NNCOL; c++)
    for (int i = 0; i < NNTST; i++) {
      bench_row row = measure(pb, setup, error, ntsts[i], ncols[c], r);
      char err[32];
      if (isnan(row.err)) snprintf(err, sizeof err, "not found");
      else if (row.err < FLOOR) snprintf(err, sizeof err, "< %.0e (%.1e)", FLOOR, row.err);
      else snprintf(err, sizeof err, "%.1e", row.err);
      printf("| %d | %d | %.4f | %d | %.3f | %s |\n", ntsts[i], ncols[c], row.seconds, row.steps,
             1e3 * row.seconds / (row.steps > 0 ? row.steps : 1), err);
      fflush(stdout);
      if (!isnan(row.err) && row.err <= 1e-8 && row.seconds < best_t) {
        best_t = row.seconds;
        best_n = ntsts[i];
        best_c = ncols[c];
      }
    }
  if (best_n)
    printf("\nFastest setting with relative error <= 1e-8: NTST = %d, NCOL = %d (%.4f s).\n\n", best_n, best_c,
           best_t);
  else
    printf("\nNo setting reaches 1e-8.\n\n");
}

int main(void)
{
  memrun *r = calloc(1, sizeof *r); /* about 0.6 MB: not on the stack */
  if (!r) return 1;
  table("### Bratu: the fold lambda* = 3.513830719125162", "of lambda*", cable_testproblem_bratu(),
        bratu_constants, bratu_error, r);
  table("### Elastica: branch points at (n pi)^2, n = 1, 2, 3", "(largest of the three)",
        cable_testproblem_elastica(), elastica_trivial_constants, elastica_error, r);
  free(r);
  return 0;
}
