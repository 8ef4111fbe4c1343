/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A program written against the public headers only (include/cable/) and
 * linked with libcable.so: it runs Bratu's problem from u = 0 through its
 * fold with the output writer, reads the files back and compares the fold
 * with the closed form.
 *
 *   api_run                  the built-in problem `bratu`
 *   api_run PLUGIN.so [DIR]  the same problem from a plug-in; output in DIR
 *
 * make check builds it in the tree (test_api_run) and, through pkg-config,
 * against an installed prefix (test_api_install). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "api_check.h"
#include "cable/cable.h"

/* Bratu's fold (30-digit mpmath value, as in tests/python/test_commands.py). */
#define BRATU_FOLD_LAMBDA 3.5138307191251612062
/* NTST=20, NCOL=4, EPSS=1e-7: tests/test_engine_bvp.c bounds the fold's
 * lambda by 1e-9 (discretisation O(h^8) ~ 1e-11, location to EPSS). */
#define BRATU_FOLD_TOL 1e-9

static const char *const constants_text =
  "IPS = 4, ICP = ['lambda'], NTST = 20, NCOL = 4, JAC = 1, IAD = 3\n"
  "DS = 0.1, DSMIN = 1e-6, DSMAX = 0.5, NMX = 60, RL1 = 10\n"
  "ILP = 1, ISP = 0, EPSS = 1e-7\n";

static void report(const char *what, const cable_error *err)
{
  char buf[1200];
  printf("  %s: %s\n", what, cable_error_format(err, buf, sizeof buf));
}

int main(int argc, char **argv)
{
  const char *plugin = argc > 1 ? argv[1] : NULL;
  const char *dir = argc > 2 ? argv[2] : "tests/tmp/api_run";
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(dir, 0755);
  cable_error err;
  cable_error_clear(&err);
  cable_plugin *pl = NULL;
  const cable_problem *tmpl = NULL;
  if (plugin) {
    pl = cable_plugin_open(plugin, &tmpl, &err);
    if (!pl) report("plug-in", &err);
    api_check("the plug-in loads", pl != NULL && tmpl != NULL);
  } else {
    tmpl = cable_problem_builtin("bratu");
    api_check("the built-in problem bratu", tmpl != NULL);
  }
  if (!tmpl) return api_summary();

  cable_constants c;
  cable_names names;
  int st = cable_constants_parse_string_for("c.bratu", constants_text, tmpl, &c, &names, &err);
  if (st) report("constants", &err);
  api_check_int("constants parse", st, CABLE_SUCCESS);
  cable_constants_take_problem_dims(&c, tmpl->ndim, tmpl->nbc, tmpl->nint);
  cable_names_fill(&names, tmpl->parnames, tmpl->npar, tmpl->unames, tmpl->ndim);

  const cable_problem *pb = NULL;
  st = cable_problem_prepare(tmpl, &c, 1, &pb, &err);
  api_check_int("the problem prepares itself", st, CABLE_SUCCESS);
  st = cable_cont_check(pb, &c, &err);
  if (st) report("check", &err);
  api_check_int("the engine accepts problem and constants", st, CABLE_SUCCESS);
  cable_cont *cc = NULL;
  st = cable_cont_create(pb, &c, &cc, &err);
  if (st) report("create", &err);
  api_check("a continuation handle", cc != NULL && st == CABLE_SUCCESS);
  st = cable_cont_set_start(cc, NULL);
  api_check_int("start from STPNT", st, CABLE_SUCCESS);
  cable_aufile *w = cable_aufile_open(dir, "bratu", &c, &names, NULL, &err);
  if (!w) report("writer", &err);
  api_check("the output writer opens", w != NULL);
  cable_sink sink = cable_aufile_sink(w);
  int next = 0;
  st = cable_cont_run(cc, &sink, 1, 1, &next);
  printf("  run ended: %s (%s)\n", cable_status_name(st), cable_status_message(st));
  api_check("the run ends normally (RL1 or NMX)", st == CABLE_END_BOUNDS || st == CABLE_END_NMX);
  api_check("labels were given", next > 1);
  cable_cont_free(cc);
  cable_problem_release(tmpl, pb);
  st = cable_aufile_close(w, &err);
  if (st) report("close", &err);
  api_check_int("the files are committed", st, CABLE_SUCCESS);

  /* read back: the fold in the s-file (label LP1) and in the b-file */
  char path[1024];
  snprintf(path, sizeof path, "%s/s.bratu", dir);
  cable_sfile *sf = cable_sfile_read(path, &err);
  if (!sf) report("s-file", &err);
  const cable_solution *lp = sf ? cable_sfile_find(sf, "LP1", &err) : NULL;
  char what[200];
  double lam = lp ? lp->par[0] : (double)NAN;
  snprintf(what, sizeof what, "s-file: fold lambda %.15g vs the closed form %.15g (tol %g)", lam,
           BRATU_FOLD_LAMBDA, BRATU_FOLD_TOL);
  api_check(what, fabs(lam - BRATU_FOLD_LAMBDA) <= BRATU_FOLD_TOL);
  cable_sfile_free(sf);
  snprintf(path, sizeof path, "%s/b.bratu", dir);
  cable_bfile *bf = cable_bfile_read(path, &err);
  if (!bf) report("b-file", &err);
  int nlp = 0;
  double blam = (double)NAN;
  for (int k = 0; bf && k < bf->nbranch; k++) {
    const cable_bfile_branch *br = &bf->branch[k];
    const double *col = cable_bfile_column(br, "lambda");
    for (int i = 0; col && i < br->nrow; i++)
      if (cable_type_base(br->ty[i]) == CABLE_TY_LP) {
        if (nlp++ == 0) blam = col[i];
      }
  }
  api_check_int("b-file: one fold", nlp, 1);
  snprintf(what, sizeof what, "b-file: fold lambda %.10g (10 digits printed) vs the closed form", blam);
  api_check(what, fabs(blam - BRATU_FOLD_LAMBDA) <= 1e-9 * BRATU_FOLD_LAMBDA + BRATU_FOLD_TOL);
  cable_bfile_free(bf);
  cable_plugin_close(pl);
  return api_summary();
}
