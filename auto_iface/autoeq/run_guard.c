/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The user's routines called through a guard (run_guard.h). */
#define _DEFAULT_SOURCE   /* glibc's on_exit: an exit handler that sees the status */
#include "run_guard.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The routine a thread is in and its run's guard: set around every call of a
 * user routine, read by the handlers below (which run in that thread). */
static _Thread_local const char *tl_routine;
static _Thread_local rp_guard *tl_guard;

/* Process-wide, written once (pthread_once) before any handler can run:
 * the handlers that were installed before cable's, chained to. */
static const int watched[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
#define NWATCHED ((int)(sizeof watched / sizeof watched[0]))
static struct sigaction before[NWATCHED];
static pthread_once_t install_once = PTHREAD_ONCE_INIT;

static void say(const char *s)
{
  size_t n = strlen(s);
  while (n > 0) {
    ssize_t k = write(STDERR_FILENO, s, n);
    if (k <= 0) return;
    s += k;
    n -= (size_t)k;
  }
}

static void report(const rp_guard *g, const char *routine, const char *how)
{
  say("\ncable: the ");
  say(routine);
  say(" routine of ");
  say(g->origin);
  say(" ");
  say(how);
  say(" ");
  say(g->where);
  say("\n");
}

static const char *signal_text(int sig)
{
  switch (sig) {
  case SIGSEGV: return "crashed (SIGSEGV: a bad memory access)";
  case SIGBUS: return "crashed (SIGBUS: a bad memory access)";
  case SIGFPE: return "crashed (SIGFPE: an arithmetic trap)";
  case SIGILL: return "crashed (SIGILL: an illegal instruction)";
  default: return "aborted the process (SIGABRT: abort() or a failed assertion)";
  }
}

static void on_fault(int sig)
{
  rp_guard *g = tl_guard;
  const char *r = tl_routine;
  if (g && r) {
    tl_guard = NULL;
    report(g, r, signal_text(sig));
  }
  /* what would have happened without cable: the handler before, or the default */
  for (int i = 0; i < NWATCHED; i++)
    if (watched[i] == sig) sigaction(sig, &before[i], NULL);
  raise(sig);   /* delivered when this handler returns */
}

static void on_process_exit(int status, void *arg)
{
  (void)arg;
  rp_guard *g = tl_guard;
  const char *r = tl_routine;
  if (!g || !r) return;   /* an exit outside the user's routines is not ours to judge */
  tl_guard = NULL;
  char how[160];
  snprintf(how, sizeof how, "ended the process with exit status %d (a Fortran STOP or ERROR STOP, or exit())",
           status);
  fflush(NULL);
  report(g, r, how);
  _exit(status != 0 ? status : 1);   /* the run did not finish: never success */
}

static void install(void)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_fault;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < NWATCHED; i++) sigaction(watched[i], &sa, &before[i]);
  on_exit(on_process_exit, NULL);
}

#define ENTER(name)                  \
  rp_guard *g = params;              \
  const char *prev_r = tl_routine;   \
  rp_guard *prev_g = tl_guard;       \
  tl_routine = name;                 \
  tl_guard = g

#define LEAVE(name, rc)                                  \
  tl_routine = prev_r;                                   \
  tl_guard = prev_g;                                     \
  if ((rc) < 0 && !g->fatal) {                           \
    g->fatal_routine = name;                             \
    g->fatal = (rc);                                     \
  }

static int g_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                  double *dfdp, void *params)
{
  ENTER("FUNC");
  int rc = g->user->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, g->user->params);
  LEAVE("FUNC", rc);
  return rc;
}

static int g_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                  double *fb, double *dbc, void *params)
{
  ENTER("BCND");
  int rc = g->user->bcnd(ndim, par, icp, nbc, u0, u1, ijac, fb, dbc, g->user->params);
  LEAVE("BCND", rc);
  return rc;
}

static int g_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                  const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  ENTER("ICND");
  int rc = g->user->icnd(ndim, par, icp, nint, u, uold, udot, upold, ijac, fi, dint, g->user->params);
  LEAVE("ICND", rc);
  return rc;
}

static int g_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  ENTER("STPNT");
  int rc = g->user->stpnt(ndim, t, u, par, g->user->params);
  LEAVE("STPNT", rc);
  return rc;
}

static int g_pvls(const struct cable_solution *sol, double *par, void *params)
{
  ENTER("PVLS");
  int rc = g->user->pvls(sol, par, g->user->params);
  LEAVE("PVLS", rc);
  return rc;
}

void rp_guard_init(rp_guard *g, const cable_problem *user, const char *origin)
{
  pthread_once(&install_once, install);
  memset(g, 0, sizeof *g);
  g->user = user;
  g->pb = *user;
  g->pb.params = g;
  g->pb.func = user->func ? g_func : NULL;
  g->pb.bcnd = user->bcnd ? g_bcnd : NULL;
  g->pb.icnd = user->icnd ? g_icnd : NULL;
  g->pb.stpnt = user->stpnt ? g_stpnt : NULL;
  g->pb.pvls = user->pvls ? g_pvls : NULL;
  snprintf(g->origin, sizeof g->origin, "%s", origin);
  snprintf(g->where, sizeof g->where, "before the run's first point");
}

void rp_guard_set_where(rp_guard *g, const char *text)
{
  /* written between steps, when no user routine runs */
  snprintf(g->where, sizeof g->where, "%s", text);
}
