/* SPDX-License-Identifier: GPL-3.0-or-later */
/* What the engine found, in fields (issue 27): a branch point's kind and
 * multiplicity on its point (cable_point.bp_kind, .bp_mult) and solution,
 * in memory and read back from the d-file's BP record, never from the
 * English note; how a run ended (cable_branch_end_status).  The elastica's
 * trivial branch has simple BPs at lambda = (n pi)^2.  Built with -I include
 * only, linked with libcable.so. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "api_check.h"
#include "cable/cable.h"

#define DIR "tests/tmp/api_structured"

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fputs(text, f);
  return fclose(f);
}

static char *read_file(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *t = n >= 0 ? malloc((size_t)n + 1) : NULL;
  if (t && fread(t, 1, (size_t)n, f) != (size_t)n) {
    free(t);
    t = NULL;
  }
  if (t) t[n] = '\0';
  fclose(f);
  return t;
}

/* path with every line starting with `from` replaced by `to` (NULL: the line
 * dropped); the number of lines replaced */
static int rewrite_lines(const char *path, const char *from, const char *to)
{
  char *t = read_file(path);
  if (!t) return -1;
  FILE *f = fopen(path, "w");
  if (!f) {
    free(t);
    return -1;
  }
  int n = 0;
  for (char *line = t; *line;) {
    char *end = strchr(line, '\n');
    size_t len = end ? (size_t)(end - line) + 1 : strlen(line);
    if (strncmp(line, from, strlen(from)) == 0) {
      n++;
      if (to) fputs(to, f);
    } else {
      fwrite(line, 1, len, f);
    }
    line += len;
  }
  fclose(f);
  free(t);
  return n;
}

static cable_session *new_session(FILE *log)
{
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = DIR;
  o.log = log;
  return cable_session_alloc(&o);
}

/* BP points of b: how many, and how many carry kind and multiplicity on
 * the point and on its solution. */
static int bp_fields(const cable_branch *b, int kind, int mult, int *nbp)
{
  int n = 0, isol = 0;
  *nbp = 0;
  for (int i = 0; i < cable_branch_npoints(b); i++) {
    const cable_point *pt = cable_branch_point(b, i);
    const cable_solution *sol = pt->lab > 0 ? cable_branch_solution(b, isol++) : NULL;
    if (cable_type_base(pt->itp) != CABLE_TY_BP) continue;
    (*nbp)++;
    n += pt->bp_kind == kind && pt->bp_mult == mult && sol && sol->bp_kind == kind;
  }
  return n;
}

/* loadbd(name): the kinds of the BPs read back */
static int loaded_fields(cable_session *s, int kind, int mult, int *nbp, int *end_status)
{
  cable_branch **list = NULL;
  int nlist = 0, n = -1;
  cable_error err;
  cable_error_clear(&err);
  *nbp = 0;
  *end_status = -999;
  if (cable_session_loadbd(s, "el", &list, &nlist, &err) == 0 && nlist == 1) {
    n = bp_fields(list[0], kind, mult, nbp);
    *end_status = cable_branch_end_status(list[0]);
  } else {
    printf("  loadbd: %s\n", err.msg);
  }
  cable_branch_list_free(list, nlist);
  return n;
}

static void structured_fields(void)
{
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(DIR, 0755);
  if (!api_check("c.el written",
                 write_file(DIR "/c.el", "e = 'elastica', IPS = 4, ICP = [1], NTST = 20, NCOL = 4, DS = 0.5\n"
                                         "DSMIN = 1e-6, DSMAX = 4.0, NMX = 200, RL1 = 45, ISP = 2, ILP = 0, EPSS = 1e-8\n") == 0))
    return;
  FILE *log = fopen("/dev/null", "w");
  cable_session *s = new_session(log);
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.c = "el";
  a.sv = "el";
  cable_branch *b = NULL;
  cable_error err;
  cable_error_clear(&err);
  int st = cable_session_run(s, &a, &b, &err);
  if (!api_check("run(c='el', sv='el'): the elastica's trivial branch", st == 0 && b)) {
    printf("  %s\n", err.msg);
    cable_session_free(s);
    if (log) fclose(log);
    return;
  }
  int nbp, n = bp_fields(b, CABLE_BP_SIMPLE, 1, &nbp);
  api_check_int("  two BPs below lambda = 45, at pi^2 and 4 pi^2", nbp, 2);
  api_check_int("  each says kind simple, multiplicity 1 on its point and solution", n, 2);
  api_check_int("  the run's end in a field: CABLE_END_BOUNDS (RL1)", cable_branch_end_status(b), CABLE_END_BOUNDS);
  api_check("  a normal end has no end note", cable_branch_end_note(b) == NULL);
  cable_branch_decref(b);
  api_check_int("cable_branch_end_status(NULL)", cable_branch_end_status(NULL), 0);

  /* the d-file carries a record per BP beside the note */
  char *d = read_file(DIR "/d.el");
  int nrec = 0;
  for (const char *p = d; p && (p = strstr(p, "\n BP: kind=simple multiplicity=1\n")); p++) nrec++;
  api_check_int("d.el: one BP record per BP", nrec, 2);
  free(d);

  int end_status;
  n = loaded_fields(s, CABLE_BP_SIMPLE, 1, &nbp, &end_status);
  api_check("loadbd('el'): the kinds read back from d.el's records", nbp == 2 && n == 2);
  api_check_int("  a branch read from files has no run's end status", end_status, 0);

  /* the record decides, whatever the note says: a record that says double
     (the note saying nothing about it) gives double */
  api_check_int("d.el's records changed to double",
                rewrite_lines(DIR "/d.el", " BP: kind=simple", " BP: kind=double multiplicity=2\n"), 2);
  n = loaded_fields(s, CABLE_BP_DOUBLE, 2, &nbp, &end_status);
  api_check("  loadbd('el'): kind double, multiplicity 2, from the records", nbp == 2 && n == 2);
  /* and a note is never parsed: no record, a note in the words the engine
     writes for a double BP, gives an unknown kind */
  rewrite_lines(DIR "/d.el", " BP: kind=", " NOTE: double branch point: det keeps its sign\n");
  n = loaded_fields(s, CABLE_BP_UNKNOWN, 0, &nbp, &end_status);
  api_check("  without records, a note 'double branch point' gives kind unknown (notes are for people)",
            nbp == 2 && n == 2);

  api_check("cable_bp_kind_name/code/multiplicity",
            strcmp(cable_bp_kind_name(CABLE_BP_DOUBLE), "double") == 0 &&
                strcmp(cable_bp_kind_name(CABLE_BP_UNKNOWN), "") == 0 && strcmp(cable_bp_kind_name(99), "") == 0 &&
                cable_bp_kind_code("pair") == CABLE_BP_PAIR && cable_bp_kind_code("Double") == CABLE_BP_UNKNOWN &&
                cable_bp_kind_code(NULL) == CABLE_BP_UNKNOWN && cable_bp_multiplicity(CABLE_BP_DOUBLE) == 2 &&
                cable_bp_multiplicity(CABLE_BP_SIMPLE) == 1 && cable_bp_multiplicity(CABLE_BP_PAIR) == 1 &&
                cable_bp_multiplicity(CABLE_BP_UNKNOWN) == 0);
  cable_session_free(s);
  if (log) fclose(log);
}

int main(void)
{
  structured_fields();
  return api_summary();
}
