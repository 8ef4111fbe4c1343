/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Branch identity across the runs of a session (cable_session_add_known,
 * auto_iface/session/cable_session_known.c): the branch points computed on
 * earlier branches are handed to later runs, and a branch that reaches one
 * ends there (CABLE_END_LOOP) with an end note that names it; a closed loop
 * ends as well.
 *
 * 1. The elastica theta'' + lambda sin theta = 0, theta'(0) = theta'(1) = 0:
 *    its trivial branch theta = 0 has simple branch points at lambda =
 *    (k pi)^2.  Run A goes up from lambda = 1 past pi^2 to RL1 = 12 and
 *    locates BP1 there.  Run B comes down from A's end (DS < 0) to RL0 = 2:
 *    with A's BPs known, it ends at pi^2 (to the location tolerance, EPSS =
 *    1e-9 in arclength: 1e-7 relative is far above it) with CABLE_END_LOOP
 *    and the note "joins a known branch ... BP label L of branch 1"; after
 *    clear_known it passes the BP and ends at RL0 (CABLE_END_BOUNDS).
 * 2. u' = 0, u(0)^2 + lambda^2 = 1 (a problem the caller gives the session):
 *    the branch is the unit circle, and the run ends after one turn with
 *    CABLE_END_LOOP and "closed loop" in the end note, not at NMX = 500.
 * 3. Arguments: a solution that is not a BP, an index outside the branch. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_session.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "session_util.h"

#define PI_ 3.14159265358979323846

static const char *ELASTICA = "e=elastica NDIM=2 IPS=4 NBC=2 NINT=0 ICP=[1] NTST=20 NCOL=4 ISP=2 ILP=0 "
                              "DSMIN=1e-6 DSMAX=2 NMX=100 NPR=100 EPSS=1e-9";

static double end_lambda(const cable_branch *b)
{
  int n = cable_branch_npoints(b);
  return n ? cable_branch_point(b, n - 1)->par[0] : (double)NAN;
}

static void known_branch_point(void)
{
  FILE *log = NULL;
  cable_session *s = session_open(NULL, &log);
  cable_error err;
  char line[600], what[1200];
  cable_branch *a = NULL, *b = NULL;
  snprintf(line, sizeof line, "%s DS=0.5 RL0=0 RL1=12", ELASTICA);
  int rc = session_line(s, line, NULL, &a, &err);
  int bp = -1;
  for (int i = 0; a && i < cable_branch_nsolutions(a); i++)
    if (cable_type_base(cable_branch_solution(a, i)->itp) == CABLE_TY_BP) bp = i;
  test_true("run A computes a BP on the trivial branch and ends beyond it",
            rc == 0 && bp >= 0 && end_lambda(a) > 12.0);
  if (bp < 0) {
    cable_branch_decref(a);
    session_close(s, log);
    return;
  }
  test_rel("run A: the BP is at lambda = pi^2", cable_branch_solution(a, bp)->par[0], PI_ * PI_, 1e-7);
  test_int("add_known: one BP added", cable_session_add_known(s, a, -1, &err), 1);
  test_int("nknown", cable_session_nknown(s), 1);
  /* run B restarts from A's last solution (IRS: its last label) */
  snprintf(line, sizeof line, "%s DS=-0.5 RL0=2 RL1=20 IRS=%d", ELASTICA,
           cable_branch_solution(a, cable_branch_nsolutions(a) - 1)->lab);
  rc = session_line(s, line, a, &b, &err);
  const char *note = cable_branch_end_note(b);
  char name[64];
  snprintf(name, sizeof name, "BP label %d of branch %d", cable_branch_solution(a, bp)->lab,
           cable_branch_number(a));
  snprintf(what, sizeof what, "run B ends at the known BP with CABLE_END_LOOP (rc %d: %s)", rc,
           note ? note : "no note");
  test_int(what, cable_branch_end_status(b), CABLE_END_LOOP);
  test_rel("run B ends at lambda = pi^2", end_lambda(b), PI_ * PI_, 1e-7);
  test_true("the end note says it joins a known branch", note && strstr(note, "joins a known branch"));
  snprintf(what, sizeof what, "the end note names the point (%s)", name);
  test_true(what, note && strstr(note, name));
  cable_branch_decref(b);
  b = NULL;
  /* a run from the BP itself (a switch) does not stop at its own start */
  snprintf(line, sizeof line, "%s ISW=-1 DS=0.1 RL0=2 RL1=20 NMX=8 IRS=%d", ELASTICA, cable_branch_solution(a, bp)->lab);
  rc = session_line(s, line, a, &b, &err);
  snprintf(what, sizeof what, "a switch at the known BP is not stopped by it (rc %d, end %d, %d points)", rc,
           cable_branch_end_status(b), cable_branch_npoints(b));
  test_true(what, rc == 0 && cable_branch_end_status(b) == CABLE_END_NMX && cable_branch_npoints(b) == 8);
  cable_branch_decref(b);
  b = NULL;
  test_int("clear_known", cable_session_clear_known(s), CABLE_SUCCESS);
  test_int("nknown after clear", cable_session_nknown(s), 0);
  snprintf(line, sizeof line, "%s DS=-0.5 RL0=2 RL1=20 IRS=%d", ELASTICA,
           cable_branch_solution(a, cable_branch_nsolutions(a) - 1)->lab);
  rc = session_line(s, line, a, &b, &err);
  snprintf(what, sizeof what, "without known points run B passes the BP to RL0 (lambda = %.4f)", end_lambda(b));
  test_true(what, rc == 0 && cable_branch_end_status(b) == CABLE_END_BOUNDS && end_lambda(b) < 2.0);
  cable_branch_decref(b);
  /* arguments */
  int notbp = bp == 0 ? 1 : 0;
  test_int("a solution that is not a BP is refused", cable_session_add_known(s, a, notbp, &err), CABLE_ERR_INPUT);
  test_int("an index outside the branch is refused",
           cable_session_add_known(s, a, cable_branch_nsolutions(a), &err), CABLE_ERR_RANGE);
  test_int("one BP by index", cable_session_add_known(s, a, bp, &err), 1);
  test_int("NULL branch", cable_session_add_known(s, NULL, -1, &err), CABLE_ERR_NULL);
  test_int("NULL session", cable_session_add_known(NULL, a, -1, &err), CABLE_ERR_NULL);
  cable_branch_decref(a);
  session_close(s, log);
}

/* u' = 0 with u(0)^2 + lambda^2 = 1: the unit circle */
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

static int circle_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                       int ijac, double *fb, double *dbc, void *params)
{
  (void)icp, (void)u1, (void)params;
  fb[0] = u0[0] * u0[0] + par[0] * par[0] - 1.0;
  if (ijac > 0 && dbc) {
    for (int k = 0; k < 2 * ndim + 36; k++) dbc[k * nbc] = 0.0;
    dbc[0] = 2.0 * u0[0];
    dbc[2 * ndim * nbc] = 2.0 * par[0];
  }
  return 0;
}

static int circle_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim, (void)t, (void)params;
  par[0] = 0.0;
  u[0] = 1.0;
  return 0;
}

static int find_circle(void *ctx, const char *name, const cable_constants *c, int from_stpnt,
                       const cable_problem **pb, cable_error *err)
{
  (void)c, (void)from_stpnt, (void)err;
  if (strcmp(name, "circle") != 0) return CABLE_ERR_NOTFOUND;
  *pb = ctx;
  return 0;
}

static void closed_loop(void)
{
  cable_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.abi_version = CABLE_PROBLEM_ABI;
  pb.struct_size = sizeof pb;
  pb.name = "circle";
  pb.description = "u' = 0, u(0)^2 + lambda^2 = 1";
  pb.ndim = 1;
  pb.nbc = 1;
  pb.npar = 1;
  pb.func = flat_func;
  pb.bcnd = circle_bcnd;
  pb.stpnt = circle_stpnt;
  cable_session_problems probs = {&pb, find_circle, NULL};
  cable_session_options o;
  cable_session_options_init(&o);
  FILE *log = fopen("/dev/null", "w");
  o.log = log;
  o.problems = &probs;
  cable_session *s = cable_session_alloc(&o);
  cable_error err;
  cable_branch *b = NULL;
  int rc = session_line(s, "e=circle NDIM=1 IPS=4 NBC=1 ICP=[1] NTST=4 NCOL=2 ISP=0 ILP=0 DS=0.1 DSMIN=1e-4 "
                           "DSMAX=0.2 NMX=500 NPR=1000", NULL, &b, &err);
  const char *note = cable_branch_end_note(b);
  char what[900];
  snprintf(what, sizeof what, "the circle ends as a closed loop (rc %d, %d points: %s)", rc, cable_branch_npoints(b),
           note ? note : (rc ? err.msg : "no note"));
  test_int(what, cable_branch_end_status(b), CABLE_END_LOOP);
  test_true("the end note says closed loop", note && strstr(note, "closed loop"));
  /* one turn of arclength 2 pi at steps of at most DSMAX = 0.2: at least 32 points, far below NMX */
  test_true("after one turn, not NMX", cable_branch_npoints(b) >= 32 && cable_branch_npoints(b) < 100);
  cable_branch_decref(b);
  cable_session_free(s);
  if (log) fclose(log);
}

int main(void)
{
  known_branch_point();
  closed_loop();
  return test_summary();
}
