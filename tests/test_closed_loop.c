/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A branch that returns to its start ends there (CABLE_END_LOOP) with a
 * message naming the start, instead of going round again until NMX
 * (continuation/cont_loop.c).
 *
 * The problem: u' = 0 on [0, 1] with the boundary condition u(0)^2 +
 * lambda^2 = 1, so every solution is a constant u on the unit circle
 * u^2 + lambda^2 = 1 in the (lambda, u) plane: the branch from (0, 1) is a
 * closed loop of arclength 2 pi.  What is checked, exactly: every point lies
 * on the circle (Newton's tolerance, 1e-9); the run ends at the first point
 * whose angle from the start, accumulated along the branch, reaches 2 pi (the
 * point before it has not), with CABLE_END_LOOP, after one turn and not NMX
 * = 500 points (before: 500 points, about 8 turns); the message names the
 * start ("its first point", or the label a restart came from).  A branch that
 * does not close (u(0) = lambda^2, a parabola) still runs to NMX. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_cont.h"
#include "cable/cable_status.h"
#include "engine_util.h"
#include "harness.h"

#define TWO_PI 6.28318530717958647692
#define PI_ 3.14159265358979323846

static int flat_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                     double *dfdu, double *dfdp, void *params)
{
  (void)u, (void)icp, (void)par, (void)params;
  f[0] = 0.0;
  if (ijac > 0 && dfdu) dfdu[0] = 0.0;
  if (ijac > 1 && dfdp)
    for (int k = 0; k < 36; k++) dfdp[k * ndim] = 0.0;
  return 0;
}

/* params: 0 the circle u(0)^2 + lambda^2 = 1, 1 the parabola u(0) = lambda^2 */
static int curve_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                      int ijac, double *fb, double *dbc, void *params)
{
  (void)icp, (void)u1;
  int parabola = params != NULL;
  fb[0] = parabola ? u0[0] - par[0] * par[0] : u0[0] * u0[0] + par[0] * par[0] - 1.0;
  if (ijac > 0 && dbc) {
    /* DBC is NBC x (2 NDIM + NPAR), column-major as AUTO's */
    for (int k = 0; k < 2 * ndim + 36; k++) dbc[k * nbc] = 0.0;
    dbc[0] = parabola ? 1.0 : 2.0 * u0[0];
    dbc[2 * ndim * nbc] = parabola ? -2.0 * par[0] : 2.0 * par[0];
  }
  return 0;
}

static int curve_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim, (void)t;
  par[0] = 0.0;
  u[0] = params != NULL ? 0.0 : 1.0;
  return 0;
}

static int parabola_flag;

static cable_problem curve_problem(int parabola)
{
  cable_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.abi_version = CABLE_PROBLEM_ABI;
  pb.struct_size = sizeof pb;
  pb.name = parabola ? "parabola" : "circle";
  pb.description = "u' = 0 with a curve in (lambda, u) as the boundary condition";
  pb.ndim = 1;
  pb.nbc = 1;
  pb.func = flat_func;
  pb.bcnd = curve_bcnd;
  pb.stpnt = curve_stpnt;
  pb.params = parabola ? &parabola_flag : NULL;
  return pb;
}

static void constants(cable_constants *c)
{
  engine_constants(c, 4, 2);
  c->ndim = 1;
  c->nbc = 1;
  c->ds = 0.1;
  c->dsmin = 1e-4;
  c->dsmax = 0.2;
  c->nmx = 500;
  c->isp = 0;
  c->ilp = 0;
  c->uzr[0].par = 0;   /* a UZ at lambda = 0.5 to restart from */
  c->uzr[0].value = 0.5;
  c->nuzr = 1;
}

/* The angles of the stored solutions (every point: NPR=1) from the start,
 * accumulated along the branch; their number. */
static int angles(const memrun *r, double *phi, int max)
{
  int n = 0;
  double prev = 0;
  for (int i = 0; i < r->nsol && n < max; i++) {
    const cable_solution *s = r->sol[i];
    double a = atan2(s->par[0], s->u[0]);   /* lambda = sin(phi), u = cos(phi) */
    if (n == 0) phi[n++] = 0, prev = a;
    else {
      double d = a - prev;
      while (d > PI_) d -= 2 * PI_;
      while (d < -PI_) d += 2 * PI_;
      phi[n] = phi[n - 1] + d;
      prev = a;
      n++;
    }
  }
  return n;
}

static void circle_loop(const cable_solution *start, const char *name_of_start)
{
  cable_constants c;
  constants(&c);
  c.npr = 1;
  if (start) c.irs = start->lab;
  cable_problem circle = curve_problem(0);
  memrun r;
  int st = memrun_run(&circle, &c, start, &r);
  test_report(st == CABLE_END_LOOP, "circle%s: the branch ends as a closed loop (status %d: %s, %d points; before: "
              "NMX = 500 points, going round again)", start ? " (restart)" : "", st, cable_status_message(st), r.n);
  test_report(strstr(r.err, "closed loop") && strstr(r.err, name_of_start), "circle: the message names the start: %s",
              r.err);
  double on = 0;
  for (int i = 0; i < r.nsol; i++) on = fmax(on, fabs(r.sol[i]->u[0] * r.sol[i]->u[0] + r.sol[i]->par[0] * r.sol[i]->par[0] - 1));
  test_abs("circle: every point on u^2 + lambda^2 = 1", on, 0.0, 1e-9);
  double phi[MEMRUN_MAX];
  int n = angles(&r, phi, MEMRUN_MAX);
  test_report(n >= 3 && fabs(phi[n - 1]) >= TWO_PI - 1e-9 && fabs(phi[n - 2]) < TWO_PI,
              "circle: it ends at the first point one full turn from the start (angle %.6f, the point before %.6f, "
              "2 pi = %.6f)", n > 0 ? fabs(phi[n - 1]) : 0.0, n > 1 ? fabs(phi[n - 2]) : 0.0, TWO_PI);
  test_int("circle: every point was stored (NPR=1)", r.nsol, r.n);
  memrun_free(&r);
}

int main(void)
{
  circle_loop(NULL, "its first point");
  /* from the UZ at lambda = 0.5 of a first run: the loop closes there, and
     the message names the label */
  cable_constants c;
  constants(&c);
  c.nmx = 20;
  cable_problem circle = curve_problem(0);
  memrun first;
  memrun_run(&circle, &c, NULL, &first);
  const cable_solution *uz = memrun_find(&first, CABLE_TY_UZ, 0);
  if (test_true("circle: a UZ at lambda = 0.5 to restart from", uz != NULL)) {
    char want[32];
    snprintf(want, sizeof want, "label %d", uz->lab);
    circle_loop(uz, want);
  }
  memrun_free(&first);
  /* a branch that does not close runs to NMX */
  constants(&c);
  c.nmx = 100;
  cable_problem parabola = curve_problem(1);
  memrun r;
  int st = memrun_run(&parabola, &c, NULL, &r);
  test_report(st == CABLE_END_NMX && r.n == 100, "parabola u(0) = lambda^2: no loop, NMX points (status %d, %d points)",
              st, r.n);
  memrun_free(&r);
  return test_summary();
}
