/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Every answer is the one asked for (issue 25, item 2), the C side:
 *  - a negative PVLS status is fatal (doc/plugins.md), at a stored point and
 *    at a trial point (PVLS for a user zero on a PVLS parameter); before,
 *    both were ignored and the run went on to its end;
 *  - cable_session_save with a negative count is refused and writes nothing
 *    (before: status 0 and three empty files);
 *  - negative counts in constants are refused with file:line:key.
 * Bratu's problem u'' + lambda e^u = 0 (cable_testproblem_bratu); PVLS
 * writes max u into PAR(2). */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "cable/cable_session.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"

#define TMP "tests/tmp/answers"

typedef struct {
  double lambda_fatal;   /* PVLS fails beyond this lambda */
  int at_trial;          /* 1: only at trial points (err_est < 0, cont_special.c), 0: only at stored points */
  int status;            /* the negative status it returns */
  int calls, stored_calls;
} pvls_ctx;

static int pvls_maxu(const cable_solution *sol, double *par, void *params)
{
  pvls_ctx *c = params;
  c->calls++;
  int trial = sol->err_est < 0;
  if (!trial) c->stored_calls++;
  double m = sol->u[0];
  for (int k = 0; k < sol->ntst * sol->ncol + 1; k++)
    if (sol->u[(size_t)k * 2] > m) m = sol->u[(size_t)k * 2];
  par[1] = m;
  if (par[0] > c->lambda_fatal && trial == c->at_trial) return c->status;
  return 0;
}

static void run_bratu(pvls_ctx *ctx, int uzr_on_pvls, memrun *r)
{
  cable_problem pb = *cable_testproblem_bratu();
  pb.npar = 2;
  pb.parnames = NULL;
  pb.pvls = pvls_maxu;
  pb.params = ctx;
  pb.concurrent = 0;
  cable_constants c;
  engine_constants(&c, 10, 4);
  c.icp[1] = 1;   /* PAR(2) = max u, printed */
  c.nicp = 2;
  c.ds = 0.1; c.dsmin = 1e-5; c.dsmax = 0.3; c.nmx = 60; c.rl1 = 3.4;
  c.ilp = 0; c.isp = 0; c.npr = 0;
  c.nthreads = 1;
  if (uzr_on_pvls) {
    c.uzr[0].par = 1;    /* max u = 5: far beyond this run */
    c.uzr[0].value = 5.0;
    c.nuzr = 1;
  }
  memrun_run(&pb, &c, NULL, r);
}

static void test_pvls_fatal(void)
{
  memrun r;
  pvls_ctx ok = {1e9, 0, -4, 0, 0};
  run_bratu(&ok, 0, &r);
  test_true("PVLS returning 0: the run reaches RL1 (lambda 3.4)", r.status > 0 && r.n > 5 &&
            r.par[r.n - 1][0] > 3.3);
  memrun_free(&r);

  pvls_ctx stored = {1.0, 0, -4, 0, 0};
  run_bratu(&stored, 0, &r);
  test_int("PVLS returning -4 at a stored point beyond lambda 1: the run ends with CABLE_ERR_CALLBACK", r.status,
           CABLE_ERR_CALLBACK);
  test_true("  the message names PVLS and its status", strstr(r.err, "PVLS returned -4") != NULL);
  double last = r.n > 0 ? r.par[r.n - 1][0] : 99;
  test_true("  every point handed out is one PVLS accepted (lambda <= 1, no MX repeating the failed one)", last <= 1.0);
  memrun_free(&r);

  pvls_ctx trial = {0.5, 1, -5, 0, 0};
  run_bratu(&trial, 1, &r);
  test_true("  (PVLS was called at trial points: the user zero on PAR(2))", trial.calls > trial.stored_calls);
  test_int("PVLS returning -5 at a trial point (UZR on its parameter): CABLE_ERR_CALLBACK", r.status,
           CABLE_ERR_CALLBACK);
  test_true("  the message names PVLS and its status", strstr(r.err, "PVLS returned -5") != NULL);
  memrun_free(&r);
}

static int exists(const char *p)
{
  struct stat st;
  return stat(p, &st) == 0;
}

static void test_save_negative_count(void)
{
  if (system("rm -rf " TMP " && mkdir -p " TMP) != 0) {
    test_true("scratch directory", 0);
    return;
  }
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = TMP;
  FILE *log = fopen("/dev/null", "w");
  o.log = log;
  cable_session *s = cable_session_alloc(&o);
  cable_error err;
  cable_error_clear(&err);
  int st = cable_session_save(s, NULL, -1, -1, "neg", 0, &err);
  test_true("cable_session_save(n = -1): refused", st < 0);
  test_true("  the message names n", strcmp(err.key, "n") == 0);
  test_true("  no files written", !exists(TMP "/b.neg") && !exists(TMP "/s.neg") && !exists(TMP "/d.neg"));
  st = cable_session_save(s, NULL, 2, -1, "null", 0, &err);
  test_true("cable_session_save(NULL branches, n = 2): refused, no files", st < 0 && !exists(TMP "/b.null"));
  cable_session_free(s);
  if (log) fclose(log);
}

static void test_negative_counts(void)
{
  static const char *const keys[] = {"NMX", "NPR", "NTST", "NCOL", "IAD", "IADS", "ITMX", "ITNW", "NWTN",
                                     "NPAR", "NBC", "NINT", "NDIM", "NSV", "NTHREADS", "IID", "IIS"};
  for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
    char text[128], what[1400];
    snprintf(text, sizeof text, "IPS = 4\n%s = -1\n", keys[k]);
    cable_constants c;
    cable_error err;
    int st = cable_constants_parse_string("c.neg", text, &c, NULL, NULL, 0, &err);
    snprintf(what, sizeof what, "%s = -1: refused as c.neg:2:%s (got %s:%d:%s: %s)", keys[k], keys[k], err.file,
             err.line, err.key, err.msg);
    test_true(what, st < 0 && err.line == 2 && strcmp(err.key, keys[k]) == 0 && strcmp(err.file, "c.neg") == 0);
  }
}

int main(void)
{
  test_pvls_fatal();
  test_save_negative_count();
  test_negative_counts();
  return test_summary();
}
