/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO's loadbd and merge through the public API (cable_session.h): a
 * branch read back from b./s.NAME has every b-file row (not only the
 * labelled ones), takes its problem from the b-file's header in a new
 * session without c.NAME, and written again gives the same rows; merging
 * two runs from one start renumbers the labels 1, 2, 3 with the shared start
 * labelled once, as auto-07p's merge does (tests/python/test_auto_objects.py
 * compares with auto-07p).  Built with -I include only, linked with
 * libcable.so. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "api_check.h"
#include "cable/cable.h"

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fputs(text, f);
  return fclose(f);
}

/* The b-file's point rows (lines whose first field is not 0), concatenated. */
static char *rows_of(const char *path)
{
  FILE *f = fopen(path, "r");
  if (!f) return NULL;
  size_t cap = 1 << 16, len = 0;
  char *out = malloc(cap), line[1024];
  if (out) out[0] = '\0';
  while (out && fgets(line, sizeof line, f)) {
    int first = -1;
    if (sscanf(line, "%d", &first) == 1 && first == 0) continue;
    size_t n = strlen(line);
    if (len + n + 1 > cap) {
      char *grown = realloc(out, cap *= 2);
      if (!grown) {
        free(out);
        out = NULL;
        break;
      }
      out = grown;
    }
    memcpy(out + len, line, n + 1);
    len += n;
  }
  fclose(f);
  return out;
}

static cable_session *new_session(const char *dir)
{
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = dir;
  o.log = fopen("/dev/null", "w");
  return cable_session_alloc(&o);
}

int main(void)
{
  const char *dir = "tests/tmp/api_loadbd";
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(dir, 0755);
  char path[512], path2[512];
  snprintf(path, sizeof path, "%s/c.bratu", dir);
  if (!api_check("c.bratu written",
                 write_file(path, "e = 'bratu', IPS = 4\nICP = [1], NTST = 20, NCOL = 4, DS = 0.1, DSMAX = 0.5, NMX = 30\n"
                                  "RL0 = -1, RL1 = 5, UZR = {1: [1.0, 3.0]}\n") == 0))
    return api_summary();

  cable_session *s = new_session(dir);
  cable_error err;
  cable_error_clear(&err);
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.c = "bratu";
  a.sv = "x";
  cable_branch *up = NULL, *down = NULL;
  api_check_int("a run from STPNT, saved to x", cable_session_run(s, &a, &up, &err), 0);
  const char *over[] = {"DS='-'", "NMX=4"};
  memset(&a, 0, sizeof a);
  a.c = "bratu";
  a.over = over;
  a.nover = 2;
  api_check_int("the other direction", cable_session_run(s, &a, &down, &err), 0);

  /* a new session and no c.bratu: everything from the files */
  remove(path);
  cable_session *t = new_session(dir);
  cable_branch **list = NULL;
  int n = 0;
  int st = cable_session_loadbd(t, "x", &list, &n, &err);
  api_check_int("loadbd('x') in a new session without c.x", st, 0);
  api_check("  one branch with every row of the run, its labelled solutions",
            n == 1 && up && cable_branch_npoints(list[0]) == cable_branch_npoints(up) &&
                cable_branch_npoints(up) == 30 && cable_branch_nsolutions(list[0]) == cable_branch_nsolutions(up));
  api_check("  the problem from the b-file's header", n == 1 && strcmp(cable_branch_problem(list[0]), "bratu") == 0);
  int same_rows = n == 1;
  for (int i = 0; same_rows && i < cable_branch_npoints(up); i++) {
    const cable_point *p = cable_branch_point(up, i), *q = cable_branch_point(list[0], i);
    same_rows = p->pt == q->pt && p->lab == q->lab && p->itp == q->itp && p->npar > 0 &&
                q->npar >= 1 && fabs(p->par[0] - q->par[0]) <= 1e-10 * (1 + fabs(p->par[0]));
  }
  api_check("  each row's PT, LAB, TY and PAR(1) (to the file's 11 digits)", same_rows);
  st = n == 1 ? cable_session_save(t, list, 1, -1, "y", 0, &err) : -1;
  api_check_int("saved again as y", st, 0);
  snprintf(path, sizeof path, "%s/b.x", dir);
  snprintf(path2, sizeof path2, "%s/b.y", dir);
  char *rx = rows_of(path), *ry = rows_of(path2);
  api_check("  b.y has b.x's rows, character for character", rx && ry && strcmp(rx, ry) == 0);
  free(rx);
  free(ry);
  cable_branch_list_free(list, n);

  /* merge: the backward run reversed, then the forward one without its start */
  cable_branch *both[2] = {up, down}, **m = NULL;
  int nm = 0;
  st = up && down ? cable_session_transform(s, both, 2, 0, &m, &nm, &err) : -1;
  api_check_int("merge of the two directions", st, 0);
  int labs_ok = nm == 1, expect = 1, nlab = 0;
  for (int i = 0; labs_ok && i < cable_branch_npoints(m[0]); i++) {
    const cable_point *p = cable_branch_point(m[0], i);
    labs_ok = p->pt == i + 1;
    if (p->lab > 0) {
      labs_ok = labs_ok && p->lab == expect++;
      nlab++;
    }
  }
  api_check("  one branch, points 1, 2, ..., labels 1, 2, ... in order",
            labs_ok && cable_branch_npoints(m[0]) == cable_branch_npoints(up) + cable_branch_npoints(down) - 1);
  api_check("  the shared start labelled once",
            nm == 1 && nlab == cable_branch_nsolutions(up) + cable_branch_nsolutions(down) - 1);
  cable_branch_list_free(m, nm);
  cable_branch_decref(up);
  cable_branch_decref(down);
  cable_session_free(s);
  cable_session_free(t);
  return api_summary();
}
