/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The session's runner state through the public API (cable_session.h):
 * cable_session_constants gives the constants the next run without a start
 * uses (AUTO's pr()): the defaults at first, a load's c= file with its
 * keyword overrides (a load from STPNT gives no solution and only sets
 * them), then a run's, with the one-off IRS and sv cleared; a NULL session
 * is CABLE_ERR_NULL with a message.  Built with -I include only and linked
 * with libcable.so. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "api_check.h"
#include "cable/cable.h"

static const char *const constants_text =
    "e = 'bratu'\nIPS = 4, ICP = ['lambda'], NTST = 20, NCOL = 4, DS = 0.1, DSMAX = 0.5, NMX = 40\n"
    "RL0 = -0.01, RL1 = 5, UZR = {'lambda': 1.5}\n";

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fputs(text, f);
  return fclose(f);
}

int main(void)
{
  const char *dir = "tests/tmp/api_session";
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(dir, 0755);
  char path[512];
  snprintf(path, sizeof path, "%s/c.bratu", dir);
  if (!api_check("c.bratu written", write_file(path, constants_text) == 0)) return api_summary();

  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = dir;
  o.log = fopen("/dev/null", "w");
  cable_session *s = cable_session_alloc(&o);
  if (!api_check("cable_session_alloc", s != NULL)) return api_summary();
  cable_error err;
  cable_error_clear(&err);

  /* before any run: AUTO's defaults, no problem */
  const cable_constants *c = NULL;
  const cable_names *names = NULL;
  const char *e = NULL;
  int st = cable_session_constants(s, &c, &names, &e, &err);
  api_check_int("constants of a new session", st, 0);
  api_check("  the defaults: NTST = 20, DS = 0.01, no ICP, problem ''",
            c && c->ntst == 20 && c->ds == 0.01 && c->nicp == 0 && e && e[0] == '\0' && names &&
                names->par[0][0] == '\0');

  /* AUTO's ld(c='bratu', NTST=33, DS='-'): no solution (the run would start
     from STPNT), the runner's constants set */
  const char *over1[] = {"NTST=33", "DS='-'"};
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.sol_index = -1;
  a.c = "bratu";
  a.nover = 2;
  a.over = over1;
  cable_branch *b = (cable_branch *)&a;
  st = cable_session_load(s, &a, &b, &err);
  api_check_int("load(c='bratu', NTST=33, DS='-') from STPNT", st, 0);
  api_check("  gives no solution", b == NULL);
  st = cable_session_constants(s, &c, &names, &e, &err);
  api_check("  then: NTST = 33 (override), DS = -0.1 (DS='-' of the file's 0.1), NMX = 40 (file)",
            st == 0 && c->ntst == 33 && c->ds == -0.1 && c->nmx == 40);
  api_check("  ICP = [PAR(1)], named 'lambda' by the problem's names; problem 'bratu'",
            c->nicp == 1 && c->icp[0] == 0 && strcmp(e, "bratu") == 0);
  api_check("  UZR = {'lambda': 1.5}", c->nuzr == 1 && c->uzr[0].par == 0 && c->uzr[0].value == 1.5);

  /* a run without c= keeps them and adds its overrides; IRS and sv are one-off */
  const char *over2[] = {"NMX=5", "DS=0.2"};
  memset(&a, 0, sizeof a);
  a.sol_index = -1;
  a.sv = "one";
  a.nover = 2;
  a.over = over2;
  st = cable_session_run(s, &a, &b, &err);
  api_check_int("run(NMX=5, DS=0.2, sv='one')", st, 0);
  api_check("  computed 5 points", b && cable_branch_npoints(b) == 5);
  st = cable_session_constants(s, &c, &names, &e, &err);
  api_check("  then: NTST = 33 (the load's), NMX = 5, DS = 0.2; sv cleared",
            st == 0 && c->ntst == 33 && c->nmx == 5 && c->ds == 0.2 && c->sv[0] == '\0');
  api_check("  the names of the run's problem: PAR(1) 'lambda', U(1) 'u'",
            strcmp(names->par[0], "lambda") == 0 && strcmp(names->u[0], "u") == 0);

  /* read back: the labelled points keep the engine's notes from d.one (the
     start's Newton report on label 1), which also carry a BP's kind */
  cable_branch **list = NULL;
  int nlist = 0;
  st = cable_session_loadbd(s, "one", &list, &nlist, &err);
  api_check("loadbd('one'): one branch with its labelled solutions",
            st == 0 && nlist == 1 && cable_branch_nsolutions(list[0]) == cable_branch_nsolutions(b));
  const char *note = st == 0 && nlist == 1 ? cable_branch_solution_note(list[0], 0) : NULL;
  const char *note0 = cable_branch_solution_note(b, 0);
  api_check("  label 1's note read from d.one is the run's ('start: Newton converged ...')",
            note && note0 && strcmp(note, note0) == 0 && strncmp(note, "start: Newton converged", 23) == 0);
  api_check("  a point that is no BP has no kind",
            st == 0 && nlist == 1 && cable_branch_solution(list[0], 0)->bp_kind == CABLE_BP_UNKNOWN);
  cable_branch_list_free(list, nlist);

  /* a restart with IRS: the runner keeps IRS and the solutions, as AUTO's does (the next run
     without a start restarts from label 2 of s.one again) */
  const char *over3[] = {"IRS=2", "NMX=3"};
  memset(&a, 0, sizeof a);
  a.sol_index = -1;
  a.s = "one";
  a.nover = 2;
  a.over = over3;
  cable_branch *b2 = NULL;
  st = cable_session_run(s, &a, &b2, &err);
  api_check_int("run(s='one', IRS=2, NMX=3)", st, 0);
  st = cable_session_constants(s, &c, NULL, NULL, &err);
  api_check("  then: IRS = 2, NMX = 3, s cleared (outputs not wanted may be NULL)",
            st == 0 && c->irs == 2 && c->irs_name[0] == '\0' && c->nmx == 3 && c->s[0] == '\0');
  /* AUTO's NEWLAB through the library: the restart from s.one (labels 1, 2) keeps branch 1 and
     labels after s.one's largest; a run from a solution given with its bundle's maxima
     (sol_mbr, sol_mlab: AUTO's _mbr, _mlab) numbers after those */
  const cable_solution *l3 = b2 ? cable_branch_solution(b2, 0) : NULL;
  api_check("  the restart is branch 1, its first label 3", l3 && l3->ibr == 1 && l3->lab == 3 &&
            cable_branch_number(b2) == 1);
  const char *over4[] = {"NMX=2"};
  memset(&a, 0, sizeof a);
  a.sol_branch = b;
  a.sol_index = 0;
  a.sol_mbr = 4;
  a.sol_mlab = 7;
  a.nover = 1;
  a.over = over4;
  cable_branch *b3 = NULL;
  st = cable_session_run(s, &a, &b3, &err);
  const cable_solution *l8 = st == 0 && b3 ? cable_branch_solution(b3, 0) : NULL;
  api_check("run(label 1 of the first run, from a bundle with labels up to 7): branch 1, first label 8",
            l8 && l8->ibr == 1 && l8->lab == 8);
  cable_branch_decref(b3);
  const char *over5[] = {"NMX=2", "IRS=0"};
  memset(&a, 0, sizeof a);
  a.sol_index = -1;
  a.nover = 2;
  a.over = over5;
  st = cable_session_run(s, &a, &b3, &err);
  l3 = st == 0 && b3 ? cable_branch_solution(b3, 0) : NULL;
  api_check("run(IRS=0) from STPNT: branch 1, label 1", l3 && l3->ibr == 1 && l3->lab == 1);
  cable_branch_decref(b3);
  cable_branch_decref(b2);
  cable_branch_decref(b);

  /* the contract: a NULL session is a status with a message, outputs NULL */
  cable_error_clear(&err);
  c = (const cable_constants *)&a;
  e = "x";
  st = cable_session_constants(NULL, &c, NULL, &e, &err);
  api_check_int("cable_session_constants(NULL session)", st, CABLE_ERR_NULL);
  api_check("  outputs NULL, the message names the function",
            c == NULL && e == NULL && err.status == CABLE_ERR_NULL && strstr(err.msg, "cable_session_constants"));
  api_check_int("cable_session_constants(NULL, everything NULL)", cable_session_constants(NULL, NULL, NULL, NULL, NULL),
                CABLE_ERR_NULL);
  api_check_int("cable_session_constants(s, nothing wanted)", cable_session_constants(s, NULL, NULL, NULL, NULL), 0);

  cable_session_free(s);
  if (o.log) fclose(o.log);
  return api_summary();
}
