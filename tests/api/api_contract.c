/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The cases of the API contract (doc/api.md, Contracts) a generated NULL
 * test cannot make: counts that disagree with their arrays, indices beyond
 * the parameters, unterminated strings, arguments that contradict each
 * other, calls in the wrong order, on valid handles.  Each gives its own
 * status with a message and nothing is read or written past an array (the
 * test runs under ASan/UBSan in make asan, and under valgrind).  Public
 * headers only, linked with libcable.so. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "api_check.h"
#include "cable/cable.h"

#define DIR_ "tests/tmp/api_contract"

static const char *const bratu_text = "IPS = 4, ICP = ['lambda'], NTST = 10, NCOL = 3, DS = 0.1, DSMAX = 0.5, NMX = 40, RL1 = 10\n";

static void bratu_constants(cable_constants *c)
{
  const cable_problem *pb = cable_problem_builtin("bratu");
  cable_constants_parse_string_for("c.bratu", bratu_text, pb, c, NULL, NULL);
  cable_constants_take_problem_dims(c, pb->ndim, pb->nbc, pb->nint);
}

/* status st, and the error says it naming `key` */
static void expect(const char *what, int rc, int st, const cable_error *err, const char *key)
{
  char line[400];
  snprintf(line, sizeof line, "%s: %s", what, cable_status_name(st));
  int ok = rc == st && err->status == st && err->msg[0] && (!key || strstr(err->msg, key) || strstr(err->key, key));
  if (!ok) printf("  got %d (%s): key '%s', '%s'\n", rc, cable_status_name(rc), err->key, err->msg);
  api_check(line, ok);
}

/* A constants struct filled by hand whose counts or indices leave its
 * arrays: every entry point that takes constants refuses it. */
static void spoil_nuzr(cable_constants *c) { c->nuzr = 100000; }
static void spoil_nuzr_neg(cable_constants *c) { c->nuzr = -1; }
static void spoil_uzr_par(cable_constants *c) { c->nuzr = 1; c->uzr[0].par = 999; c->uzr[0].value = 1; }
static void spoil_nicp(cable_constants *c) { c->nicp = 1000; }
static void spoil_nthl(cable_constants *c) { c->nthl = 1000; }
static void spoil_thl_index(cable_constants *c) { c->nthl = 1; c->thl[0].index = -5; c->thl[0].weight = 1; }
static void spoil_npar_override(cable_constants *c) { c->npar_override = 1000; }
static void spoil_par_override(cable_constants *c) { c->npar_override = 1; c->par_override[0].index = 999; }
static void spoil_nstop(cable_constants *c) { c->nstop = 100; }
static void spoil_npkey(cable_constants *c) { c->npkey = 99; }
static void spoil_nthreads(cable_constants *c) { c->nthreads = 100000; }
static void spoil_e(cable_constants *c) { memset(c->e, 'x', sizeof c->e); }
static void spoil_irs_name(cable_constants *c) { memset(c->irs_name, 'B', sizeof c->irs_name); }
static void spoil_npar(cable_constants *c) { c->npar = 100000; }

static const struct bad_case {
  const char *what, *key;
  int status;
  void (*spoil)(cable_constants *c);
} bad_cases[] = {
    {"NUZR = 100000 (128 slots)", "NUZR", CABLE_ERR_SIZE, spoil_nuzr},
    {"NUZR = -1", "NUZR", CABLE_ERR_SIZE, spoil_nuzr_neg},
    {"UZR[0].par = 999 (NPAR 36)", "UZR", CABLE_ERR_RANGE, spoil_uzr_par},
    {"NICP = 1000 (64 slots)", "NICP", CABLE_ERR_SIZE, spoil_nicp},
    {"NTHL = 1000", "NTHL", CABLE_ERR_SIZE, spoil_nthl},
    {"THL[0].index = -5", "THL", CABLE_ERR_RANGE, spoil_thl_index},
    {"npar_override = 1000", "PAR", CABLE_ERR_SIZE, spoil_npar_override},
    {"par_override[0].index = 999", "PAR", CABLE_ERR_RANGE, spoil_par_override},
    {"nstop = 100 (8 slots)", "STOP", CABLE_ERR_SIZE, spoil_nstop},
    {"npkey = 99 (16 slots)", "problem keys", CABLE_ERR_SIZE, spoil_npkey},
    {"NTHREADS = 100000", "NTHREADS", CABLE_ERR_RANGE, spoil_nthreads},
    {"e without a terminating NUL", "e", CABLE_ERR_SIZE, spoil_e},
    {"irs_name without a terminating NUL", "IRS", CABLE_ERR_SIZE, spoil_irs_name},
    {"NPAR = 100000", "NPAR", CABLE_ERR_RANGE, spoil_npar},
};

static void constants_counts(void)
{
  const cable_problem *pb = cable_problem_builtin("bratu");
  cable_names names;
  cable_names_init(&names);
  cable_names_fill(&names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  for (size_t k = 0; k < sizeof bad_cases / sizeof bad_cases[0]; k++) {
    const struct bad_case *b = &bad_cases[k];
    cable_constants c;
    bratu_constants(&c);
    b->spoil(&c);
    char what[300];
    cable_error err;
    cable_error_clear(&err);
    snprintf(what, sizeof what, "%s: cable_cont_check", b->what);
    expect(what, cable_cont_check(pb, &c, &err), b->status, &err, b->key);
    int st = 0;
    cable_cont *cc = cable_cont_alloc(pb, &c, &st);
    snprintf(what, sizeof what, "%s: cable_cont_alloc gives NULL and the status", b->what);
    api_check(what, cc == NULL && st == b->status);
    cable_cont_free(cc);
    const cable_problem *inst = NULL;
    cable_error_clear(&err);
    snprintf(what, sizeof what, "%s: cable_problem_prepare", b->what);
    expect(what, cable_problem_prepare(pb, &c, 1, &inst, &err), b->status, &err, b->key);
    cable_error_clear(&err);
    cable_aufile *w = cable_aufile_open(DIR_, "bad", &c, &names, NULL, &err);
    snprintf(what, sizeof what, "%s: cable_aufile_open", b->what);
    expect(what, w ? 0 : err.status, b->status, &err, b->key);
    cable_aufile_abort(w);
    cable_error_clear(&err);
    snprintf(what, sizeof what, "%s: cable_constants_parse_override into them", b->what);
    expect(what, cable_constants_parse_override("NTST=5", &c, NULL, NULL, 0, &err), b->status, &err, b->key);
    cable_constants fc = c;
    fc.isw = 2;
    fc.icp[1] = 1;
    if (b->spoil != spoil_nicp) fc.nicp = 2;
    char msg[300] = "";
    cable_solution *lp = cable_solution_alloc(2, 10, 3, 36, 1);
    lp->itp = 5;
    cable_fold *f = cable_fold_alloc(pb, &fc, lp, &st, msg, sizeof msg);
    snprintf(what, sizeof what, "%s: cable_fold_alloc gives NULL, the status and a message", b->what);
    api_check(what, f == NULL && st == b->status && strstr(msg, b->key) != NULL);
    cable_fold_free(f);
    cable_solution_free(lp);
  }
  /* a writer keeps its constants when given spoilt ones, and closes cleanly */
  cable_constants c, bad;
  bratu_constants(&c);
  bad = c;
  spoil_nuzr(&bad);
  cable_error err;
  cable_aufile *w = cable_aufile_open(DIR_, "keep", &c, &names, NULL, &err);
  cable_aufile_set_constants(w, &bad);
  api_check_int("cable_aufile_set_constants(NUZR = 100000) is not taken; the writer closes", cable_aufile_close(w, &err), 0);
  /* IRS='BB...' without its NUL: the s-file lookup refuses it */
  cable_sfile *sf = cable_sfile_read(DIR_ "/s.ok", &err);
  if (sf) {
    bad = c;
    spoil_irs_name(&bad);
    cable_error_clear(&err);
    expect("irs_name without a NUL: cable_sfile_resolve_irs", cable_sfile_resolve_irs(sf, &bad, &err), CABLE_ERR_SIZE,
           &err, "IRS");
    cable_sfile_free(sf);
  } else {
    api_check("s.ok for cable_sfile_resolve_irs", 0);
  }
}

/* A problem struct whose sizes contradict themselves: the engine refuses it
 * before allocating anything. */
static void bad_problem(void)
{
  const cable_problem *bratu = cable_problem_builtin("bratu");
  cable_constants c;
  bratu_constants(&c);
  c.ndim = c.nbc = c.nint = 0;   /* the problem's own */
  struct {
    const char *what;
    int ndim, nbc, nint, npar;
  } cases[] = {{"NDIM = 0", 0, 1, 0, 1},         {"NDIM = -2", -2, -1, 0, 1}, {"NBC = -1", 2, -1, 2, 1},
               {"NINT = -1", 2, 3, -1, 1},       {"npar = -1", 2, 2, 0, -1},  {"NDIM = 2^30", 1 << 30, 1 << 30, 0, 1}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    cable_problem pb = *bratu;
    pb.ndim = cases[k].ndim;
    pb.nbc = cases[k].nbc;
    pb.nint = cases[k].nint;
    pb.npar = cases[k].npar;
    cable_error err;
    cable_error_clear(&err);
    char what[200];
    snprintf(what, sizeof what, "a problem with %s: cable_cont_check", cases[k].what);
    expect(what, cable_cont_check(&pb, &c, &err), CABLE_ERR_INPUT, &err, NULL);
    int st = 0;
    cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
    snprintf(what, sizeof what, "a problem with %s: cable_cont_alloc gives NULL", cases[k].what);
    api_check(what, cc == NULL && st == CABLE_ERR_INPUT);
    cable_cont_free(cc);
  }
}

/* Calls out of order on a valid continuation handle. */
static void cont_order(void)
{
  const cable_problem *pb = cable_problem_builtin("bratu");
  cable_constants c;
  bratu_constants(&c);
  int st = 0;
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  api_check_int("cable_cont_step before set_start", cable_cont_step(cc), CABLE_ERR_STATE);
  api_check_int("cable_cont_run before set_start", cable_cont_run(cc, NULL, 1, 1, NULL), CABLE_ERR_STATE);
  api_check("  cable_cont_error says so", strstr(cable_cont_error(cc), "set_start") != NULL);
  api_check("cable_cont_point before any point: NULL", cable_cont_point(cc) == NULL);
  double mesh[11];
  for (int j = 0; j <= 10; j++) mesh[j] = j / 10.0;
  api_check_int("cable_cont_set_mesh before set_start", cable_cont_set_mesh(cc, mesh), CABLE_SUCCESS);
  api_check_int("cable_cont_set_start", cable_cont_set_start(cc, NULL), CABLE_SUCCESS);
  api_check_int("cable_cont_set_mesh after set_start: wrong order", cable_cont_set_mesh(cc, mesh), CABLE_ERR_STATE);
  api_check("  cable_cont_error says so", strstr(cable_cont_error(cc), "set_mesh after") != NULL);
  api_check_int("  the run goes on from the start as set", cable_cont_step(cc), CABLE_SUCCESS);
  cable_cont_free(cc);
}

/* Arguments of a valid session that contradict each other. */
static void session_args(void)
{
  FILE *devnull = fopen("/dev/null", "w");
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = DIR_;
  o.log = devnull;
  cable_session *s = cable_session_alloc(&o);
  cable_error err;
  cable_branch *b = NULL, *out = (cable_branch *)1;
  static const char *const over[] = {"IPS=4", "ICP=['lambda']", "NTST=10", "NCOL=3", "DS=0.1", "DSMAX=0.5", "NMX=40", "RL1=10"};
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.e = "bratu";
  a.over = over;
  a.nover = (int)(sizeof over / sizeof over[0]);
  a.sv = "ok";
  int rc = cable_session_run(s, &a, &b, &err);
  api_check("a Bratu run on the session (the valid state the cases start from)", rc == 0 && b != NULL);
  if (!b) {
    cable_session_free(s);
    fclose(devnull);
    return;
  }
  static const char *const with_null[] = {"NTST=10", NULL};
  struct {
    const char *what;
    int status;
    cable_run_args a;
  } cases[] = {
      {"nover = 2, over = NULL", CABLE_ERR_NULL, {.e = "bratu", .nover = 2}},
      {"over[1] = NULL", CABLE_ERR_NULL, {.e = "bratu", .nover = 2, .over = with_null}},
      {"nover = -1", CABLE_ERR_SIZE, {.e = "bratu", .nover = -1, .over = over}},
      {"nbranch = 1, branches = NULL", CABLE_ERR_NULL, {.nbranch = 1}},
      {"nbranch = -1", CABLE_ERR_SIZE, {.nbranch = -1}},
      {"branches[0] = NULL", CABLE_ERR_NULL, {.nbranch = 1}},
      {"sol_index = 999 beyond the branch", CABLE_ERR_RANGE, {.sol_branch = b, .sol_index = 999}},
      {"sol_index = -1", CABLE_ERR_RANGE, {.sol_branch = b, .sol_index = -1}},
      {"a solution and a result as the start", CABLE_ERR_INPUT, {.sol_branch = b, .nbranch = 1}},
  };
  cable_branch *nulls[1] = {NULL}, *one[1] = {b};
  cases[5].a.branches = nulls;
  cases[8].a.branches = one;
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char what[300];
    out = (cable_branch *)1;
    cable_error_clear(&err);
    snprintf(what, sizeof what, "cable_session_run(%s)", cases[k].what);
    expect(what, cable_session_run(s, &cases[k].a, &out, &err), cases[k].status, &err, NULL);
    api_check("  *out is NULL", out == NULL);
    out = (cable_branch *)1;
    cable_error_clear(&err);
    snprintf(what, sizeof what, "cable_session_load(%s)", cases[k].what);
    expect(what, cable_session_load(s, &cases[k].a, &out, &err), cases[k].status, &err, NULL);
    api_check("  *out is NULL", out == NULL);
  }
  /* save: a count that disagrees with the list writes nothing */
  struct stat st;
  cable_error_clear(&err);
  expect("cable_session_save(n = -1)", cable_session_save(s, one, -1, -1, "neg", 0, &err), CABLE_ERR_SIZE, &err, NULL);
  api_check("  no b.neg, s.neg, d.neg", stat(DIR_ "/b.neg", &st) != 0 && stat(DIR_ "/s.neg", &st) != 0 &&
                                           stat(DIR_ "/d.neg", &st) != 0);
  cable_error_clear(&err);
  expect("cable_session_save(n = 1, branches = NULL)", cable_session_save(s, NULL, 1, -1, "nul", 0, &err), CABLE_ERR_NULL,
         &err, NULL);
  cable_error_clear(&err);
  expect("cable_session_save(branches[0] = NULL)", cable_session_save(s, nulls, 1, -1, "nul", 0, &err), CABLE_ERR_NULL,
         &err, NULL);
  api_check("  no b.nul", stat(DIR_ "/b.nul", &st) != 0);
  /* transform: the same rules */
  cable_branch **list = (cable_branch **)1;
  int n = 7;
  cable_error_clear(&err);
  expect("cable_session_transform(n = -1)", cable_session_transform(s, one, -1, 0, &list, &n, &err), CABLE_ERR_SIZE, &err,
         NULL);
  api_check("  *out NULL, *nout 0", list == NULL && n == 0);
  cable_error_clear(&err);
  expect("cable_session_transform(in = NULL, n = 1)", cable_session_transform(s, NULL, 1, 1, &list, &n, &err),
         CABLE_ERR_NULL, &err, NULL);
  cable_error_clear(&err);
  expect("cable_session_transform(in[0] = NULL)", cable_session_transform(s, nulls, 1, 0, &list, &n, &err),
         CABLE_ERR_NULL, &err, NULL);
  /* the valid calls still work after all of that */
  cable_error_clear(&err);
  rc = cable_session_transform(s, one, 1, 1, &list, &n, &err);
  api_check("cable_session_transform(one branch) afterwards", rc == 0 && n == 1 && list && list[0]);
  cable_branch_list_free(list, n);
  char path[64] = "unchanged";
  cable_session_path(s, "b", "x", path, 0);
  api_check("cable_session_path(len 0) leaves the buffer alone", strcmp(path, "unchanged") == 0);
  cable_branch_decref(b);
  cable_session_free(s);
  fclose(devnull);
}

int main(void)
{
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(DIR_, 0755);
  const char *const stale[] = {"b.neg", "s.neg", "d.neg", "b.nul", "s.nul", "d.nul"};
  for (size_t k = 0; k < sizeof stale / sizeof stale[0]; k++) {
    char p[128];
    snprintf(p, sizeof p, DIR_ "/%s", stale[k]);
    unlink(p);
  }
  session_args();       /* also writes s.ok, read by constants_counts */
  constants_counts();
  bad_problem();
  cont_order();
  return api_summary();
}
