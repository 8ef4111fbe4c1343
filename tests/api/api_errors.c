/* SPDX-License-Identifier: GPL-3.0-or-later */
/* One error channel (doc/api.md): a status with its report (status, file,
 * line, key, message), and an error handler installed per handle that is
 * told the report before the call returns: a session's
 * (cable_session_options.on_error), a continuation handle's
 * (cable_cont_set_error_handler).  Handlers of two handles do not see each
 * other's errors (no process-wide handler).  The status-returning
 * constructors (cable_*_create) give the reason in err.  Built with
 * -I include only, linked with libcable.so. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "api_check.h"
#include "cable/cable.h"

#define DIR "tests/tmp/api_errors"

/* What a handler was told. */
typedef struct {
  int calls;
  cable_error last;
} told;

static void handler(const cable_error *e, void *ctx)
{
  told *t = ctx;
  t->calls++;
  t->last = *e;
}

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fputs(text, f);
  return fclose(f);
}

static cable_session *session_with_handler(FILE *log, told *t)
{
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = DIR;
  o.log = log;
  o.on_error = handler;
  o.on_error_ctx = t;
  cable_session *s = NULL;
  cable_error err;
  int st = cable_session_create(&o, &s, &err);
  api_check("cable_session_create: a session and 0", st == 0 && s != NULL);
  return s;
}

static void session_handler(void)
{
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(DIR, 0755);
  if (!api_check("c.el written",
                 write_file(DIR "/c.el", "e = 'elastica', IPS = 4, ICP = [1], NTST = 20, NCOL = 4, DS = 0.5\n"
                                         "DSMIN = 1e-6, DSMAX = 4.0, NMX = 200, RL1 = 12, ISP = 2, ILP = 0, EPSS = 1e-8\n") == 0))
    return;
  FILE *log = fopen("/dev/null", "w");
  told t1 = {0}, t2 = {0};
  cable_session *s1 = session_with_handler(log, &t1), *s2 = session_with_handler(log, &t2);
  if (!s1 || !s2) {
    cable_session_free(s1);
    cable_session_free(s2);
    if (log) fclose(log);
    return;
  }

  /* a bad override, err NULL: the handler still gets the full report */
  const char *bad[] = {"NTST=-5"};
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.c = "el";
  a.over = bad;
  a.nover = 1;
  a.over_file = "<command line>";
  cable_branch *b = NULL;
  int st = cable_session_run(s1, &a, &b, NULL);
  api_check("run(NTST=-5), err NULL: an error status", st < 0 && b == NULL);
  api_check_int("  the session's handler was told once", t1.calls, 1);
  api_check_int("  with the status the call returned", t1.last.status, st);
  api_check("  and the key and file of the report (NTST, <command line>)",
            strcmp(t1.last.key, "NTST") == 0 && strcmp(t1.last.file, "<command line>") == 0 && t1.last.msg[0]);
  printf("  the report: %s: %s: %s\n", t1.last.file, t1.last.key, t1.last.msg);
  api_check_int("  the other session's handler was not told", t2.calls, 0);

  /* the same with err: err and the handler hold the same report */
  cable_error err;
  st = cable_session_run(s1, &a, &b, &err);
  api_check("  with err: the caller's report is the handler's",
            t1.calls == 2 && err.status == st && strcmp(err.msg, t1.last.msg) == 0 && strcmp(err.key, "NTST") == 0);

  /* a good run: no report */
  a.over = NULL;
  a.nover = 0;
  st = cable_session_run(s2, &a, &b, &err);
  api_check("run(c='el') on the second session: 0, its handler not told", st == 0 && b && t2.calls == 0);

  /* an engine error: a switch at the BP with PAR moving its parameter; the
     key is the engine's (cable_cont_last_error), not read from its text */
  const char *sw[] = {"IRS=2", "ISW=-1", "PAR={1: 11.0}", "NMX=3"};
  cable_run_args a2;
  memset(&a2, 0, sizeof a2);
  a2.branches = &b;
  a2.nbranch = 1;
  a2.over = sw;
  a2.nover = 4;
  cable_branch *b2 = NULL;
  int bp_itp = b && cable_branch_nsolutions(b) >= 2 ? cable_type_base(cable_branch_solution(b, 1)->itp) : 0;
  api_check_int("  label 2 of that run is the BP at pi^2", bp_itp, CABLE_TY_BP);
  st = cable_session_run(s2, &a2, &b2, NULL);
  api_check("switching with PAR(1) moved off the BP: an error, told to the second session's handler with key PAR",
            st == CABLE_ERR_INPUT && t2.calls == 1 && t2.last.status == st && strcmp(t2.last.key, "PAR") == 0);
  printf("  the report: %s: %s\n", t2.last.key, t2.last.msg);
  cable_branch_decref(b2);
  cable_branch_decref(b);

  /* the handler's report of a NULL argument names the call */
  int calls = t1.calls;
  st = cable_session_loadbd(s1, NULL, NULL, NULL, NULL);
  api_check("loadbd(NULL name): CABLE_ERR_NULL, told with the call's message",
            st == CABLE_ERR_NULL && t1.calls == calls + 1 && strstr(t1.last.msg, "cable_session_loadbd") != NULL);
  api_check_int("  still nothing told to the other session's handler about the first's errors", t2.calls, 1);
  cable_session_free(s1);
  cable_session_free(s2);
  if (log) fclose(log);
}

static void cont_handler(void)
{
  const cable_problem *bratu = cable_problem_builtin("bratu");
  cable_constants c;
  cable_names names;
  cable_error err;
  int st = cable_constants_parse_string_for(
      "c.bratu", "IPS = 4, ICP = ['lambda'], NTST = 10, NCOL = 3, DS = 0.1, NMX = 20\n", bratu, &c, &names, &err);
  cable_constants_take_problem_dims(&c, bratu->ndim, bratu->nbc, bratu->nint);
  api_check_int("bratu's constants", st, 0);

  /* the status-returning constructor: the reason in err */
  cable_cont *cc = (cable_cont *)&err;   /* not NULL: the call must set it */
  c.ntst = -5;
  st = cable_cont_create(bratu, &c, &cc, &err);
  api_check("cable_cont_create(NTST = -5): an error status, *out NULL, the reason in err",
            st < 0 && cc == NULL && err.status == st && strstr(err.msg, "NTST") != NULL);
  printf("  the report: %s\n", err.msg);
  c.ntst = 10;
  st = cable_cont_create(bratu, &c, &cc, &err);
  if (!api_check("cable_cont_create(NTST = 10): a handle and 0", st == 0 && cc != NULL)) return;

  told t = {0};
  api_check_int("cable_cont_set_error_handler", cable_cont_set_error_handler(cc, handler, &t), 0);
  cable_error last;
  api_check_int("cable_cont_last_error before any error: 0", cable_cont_last_error(cc, &last), 0);

  st = cable_cont_step(cc);
  api_check("step before set_start: CABLE_ERR_STATE, told with the engine's message",
            st == CABLE_ERR_STATE && t.calls == 1 && t.last.status == CABLE_ERR_STATE &&
                strcmp(t.last.msg, "cable_cont_step before cable_cont_set_start") == 0);
  st = cable_cont_set_mesh(cc, NULL);
  api_check("set_mesh(NULL): CABLE_ERR_NULL, told with the status's message (the call set none)",
            st == CABLE_ERR_NULL && t.calls == 2 && strcmp(t.last.msg, cable_status_message(CABLE_ERR_NULL)) == 0);
  double mesh[11] = {0, 0.5, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.97, 1};
  st = cable_cont_set_mesh(cc, mesh);
  api_check("set_mesh(a mesh that does not increase): CABLE_ERR_INPUT, told",
            st == CABLE_ERR_INPUT && t.calls == 3 && strstr(t.last.msg, "must increase") != NULL);
  api_check("cable_cont_last_error is the handler's report",
            cable_cont_last_error(cc, &last) == CABLE_ERR_INPUT && strcmp(last.msg, t.last.msg) == 0);

  /* a good run: nothing told */
  st = cable_cont_set_start(cc, NULL);
  int next = 0;
  if (st == 0) st = cable_cont_run(cc, NULL, 1, 1, &next);
  if (!api_check("set_start and run to NMX: a normal end, nothing told", st > 0 && t.calls == 3))
    printf("  status %d, told %d: %s\n", st, t.calls, t.last.msg);

  /* removed: no more reports */
  cable_cont_set_error_handler(cc, NULL, NULL);
  st = cable_cont_set_mesh(cc, NULL);
  api_check("handler removed: the status only", st < 0 && t.calls == 3);
  cable_cont_free(cc);

  /* the other status-returning constructors */
  cable_solution *sol = NULL;
  st = cable_solution_create(2, 0, 4, 1, 1, &sol, &err);
  api_check("cable_solution_create(NTST = 0): CABLE_ERR_RANGE naming the sizes",
            st == CABLE_ERR_RANGE && sol == NULL && strstr(err.msg, "NTST = 0") != NULL);
  st = cable_solution_create(2, 5, 4, 3, 1, &sol, &err);
  api_check("cable_solution_create(2, 5, 4, 3, 1): a solution of those sizes",
            st == 0 && sol && sol->ndim == 2 && sol->ntst == 5 && sol->ncol == 4 && sol->npar == 3);
  cable_fold *fold = NULL;
  st = cable_fold_create(bratu, &c, sol, &fold, &err);
  api_check("cable_fold_create from a point that is no LP: an error with its reason, *out NULL",
            st < 0 && fold == NULL && err.status == st && err.msg[0]);
  printf("  the report: %s\n", err.msg);
  cable_solution_free(sol);
}

int main(void)
{
  session_handler();
  cont_handler();
  return api_summary();
}
