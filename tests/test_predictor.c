/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The second-order predictor (PREDICTOR = 2, cont_engine.c step_predict;
 * doc/engine.md, "The second-order predictor"), against AUTO's tangent
 * predictor (PREDICTOR = 1), on Bratu's branch through its fold:
 *  - with fixed steps (IADS = 0) both predictors solve the same equations
 *    (the same arclength steps from the same points), so the points agree to
 *    the Newton tolerance, and the fold is the same;
 *  - the first step uses the tangent predictor in both runs: its point is
 *    the same to the last bit;
 *  - the curvature term leaves a smaller first correction: fewer Newton
 *    iterations in all, and never more in any step;
 *  - with step control (IADS = 1) the run reaches the fold in fewer steps and
 *    finds it at the same lambda; a reversed run (DS < 0 from the fold's far
 *    side) works the same way. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cable/cable_constants.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"

static void bratu_constants(cable_constants *c, int predictor, int iads)
{
  engine_constants(c, 20, 4);
  c->isp = 0;
  c->ilp = 1;
  c->ds = 0.25; c->dsmin = 1e-6; c->dsmax = 1.0;
  c->iads = iads;
  c->nmx = 40;
  c->rl1 = 10.0;
  c->epss = 1e-8;
  c->predictor = predictor;
}


static int total_newton(const memrun *r)
{
  int s = 0;
  for (int i = 1; i < r->n; i++) s += r->newton[i];
  return s;
}

/* lambda of the first located fold, NAN when none */
static double fold_lambda(const memrun *r)
{
  const cable_solution *lp = memrun_find(r, CABLE_TY_LP, 0);
  return lp ? lp->par[0] : (double)NAN;
}

static void test_fixed_steps(memrun *a, memrun *b)
{
  cable_constants c;
  bratu_constants(&c, 1, 0);
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  bratu_constants(&c, 2, 0);
  memrun_run(cable_testproblem_bratu(), &c, NULL, b);
  test_true("fixed steps: both runs end normally", a->status > 0 && b->status > 0);
  test_int("fixed steps: the same number of points", b->n, a->n);
  /* the same arclength equations from points that agree to the Newton
     tolerance EPSU = 1e-7 (quadratic convergence leaves far less) */
  test_le("fixed steps: PREDICTOR=2 points = PREDICTOR=1 points (relative)", memrun_compare(a, b), 1e-7);
  test_true("fixed steps: the first step's point is the same to the last bit",
            a->n > 1 && b->n > 1 && a->par[1][0] == b->par[1][0] && a->l2[1] == b->l2[1]);
  double la = fold_lambda(a), lb = fold_lambda(b);
  /* lambda at a fold is quadratic in the arclength error of its location */
  test_le("fixed steps: the same fold lambda", fabs(la - lb), 1e-9);
  test_abs("fixed steps: the fold is Bratu's (lambda* = 3.5138307191)", lb, 3.5138307191, 1e-6);
  int na = total_newton(a), nb = total_newton(b), worse = 0;
  for (int i = 1; i < a->n && i < b->n; i++)
    if (b->newton[i] > a->newton[i]) worse++;
  char what[160];
  snprintf(what, sizeof what, "fixed steps: fewer Newton iterations with PREDICTOR=2 (%d against %d)", nb, na);
  test_true(what, nb < na);
  test_int("fixed steps: no step needs more iterations with PREDICTOR=2", worse, 0);
}

static void test_step_control(memrun *a, memrun *b)
{
  cable_constants c;
  bratu_constants(&c, 1, 1);
  c.ds = 0.05; c.dsmax = 2.0;
  c.nuzr = 1; c.uzr[0].par = 0; c.uzr[0].value = 1.0; c.uzr[0].stop = 0;
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  bratu_constants(&c, 2, 1);
  c.ds = 0.05; c.dsmax = 2.0;
  c.nuzr = 1; c.uzr[0].par = 0; c.uzr[0].value = 1.0; c.uzr[0].stop = 0;
  memrun_run(cable_testproblem_bratu(), &c, NULL, b);
  int ia = -1, ib = -1;
  for (int i = 0; i < a->n && ia < 0; i++)
    if (a->itp[i] % 10 == CABLE_TY_LP) ia = i;
  for (int i = 0; i < b->n && ib < 0; i++)
    if (b->itp[i] % 10 == CABLE_TY_LP) ib = i;
  char what[160];
  snprintf(what, sizeof what, "step control: the fold reached in fewer steps with PREDICTOR=2 (%d against %d)", ib, ia);
  test_true(what, ia > 0 && ib > 0 && ib < ia);
  test_le("step control: the same fold lambda", fabs(fold_lambda(a) - fold_lambda(b)), 1e-9);
  /* the user zero lambda = 1 on the upper branch (after the fold): both runs
     locate it to EPSS on the same uniform mesh (IAD = 0), so the two
     solutions agree to the Newton tolerance */
  const cable_solution *ua = memrun_find(a, CABLE_TY_UZ, 1), *ub = memrun_find(b, CABLE_TY_UZ, 1);
  test_true("step control: lambda = 1 labelled on both branches in both runs", ua != NULL && ub != NULL);
  if (ua && ub && ua->ntst == ub->ntst && ua->ncol == ub->ncol) {
    double d = 0;
    for (int k = 0; k <= ua->ntst * ua->ncol; k++) d = fmax(d, fabs(ua->u[2 * k] - ub->u[2 * k]));
    test_le("step control: the upper lambda = 1 solution is the same with both predictors", d, 1e-6);
  }
}

static void test_reversed(memrun *a, memrun *b)
{
  /* from the last point of the fixed-step PREDICTOR=1 run (past the fold),
     back with DS < 0: the second-order term has the sign of ds^2 / ds_used,
     which both keep negative together */
  cable_constants c;
  bratu_constants(&c, 1, 0);
  c.npr = 1;
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  const cable_solution *last = a->nsol > 0 ? a->sol[a->nsol - 1] : NULL;
  test_true("reversed: a start past the fold", last != NULL && last->par[0] < 3.5);
  if (!last) return;
  cable_solution *start = cable_solution_clone(last);
  memrun_free(a);
  bratu_constants(&c, 1, 0);
  c.ds = -0.25;
  memrun_run(cable_testproblem_bratu(), &c, start, a);
  bratu_constants(&c, 2, 0);
  c.ds = -0.25;
  memrun_run(cable_testproblem_bratu(), &c, start, b);
  test_le("reversed: the same points", memrun_compare(a, b), 1e-7);
  test_le("reversed: the same fold", fabs(fold_lambda(a) - fold_lambda(b)), 1e-9);
  test_true("reversed: fewer Newton iterations", total_newton(b) < total_newton(a));
  cable_solution_free(start);
}

int main(void)
{
  memrun *a = calloc(1, sizeof *a), *b = calloc(1, sizeof *b);
  test_fixed_steps(a, b);
  memrun_free(a);
  memrun_free(b);
  test_step_control(a, b);
  memrun_free(a);
  memrun_free(b);
  test_reversed(a, b);
  memrun_free(a);
  memrun_free(b);
  free(a);
  free(b);
  return test_summary();
}
