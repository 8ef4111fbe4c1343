/* The cable program on bad input: one line on stderr naming the file, line
 * and key, a non-zero exit, and no output file written; and a good run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "aufile.h"
#include "harness.h"
#include "names.h"

#define CABLE "./build/release/cable"
#define DIR "tests/data/cli"

static int exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

/* run cmd, capture its output; returns the exit status */
static int run(const char *cmd, char *out, size_t len)
{
  FILE *p = popen(cmd, "r");
  if (!p) return -1;
  size_t n = fread(out, 1, len - 1, p);
  out[n] = '\0';
  int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void bad(const char *what, const char *args, const char *expect1, const char *expect2)
{
  char cmd[512], out[4096];
  snprintf(cmd, sizeof cmd, "cd " DIR " && ../../../" CABLE " %s 2>&1 >/dev/null", args);
  int rc = run(cmd, out, sizeof out);
  int lines = 0;
  for (const char *c = out; *c; c++) lines += *c == '\n';
  char t[160];
  snprintf(t, sizeof t, "%s: non-zero exit", what);
  test_true(t, rc != 0);
  snprintf(t, sizeof t, "%s: one line on stderr", what);
  test_int(t, lines, 1);
  snprintf(t, sizeof t, "%s: message names '%s' and '%s'", what, expect1, expect2);
  test_true(t, strstr(out, expect1) && strstr(out, expect2));
  if (!(strstr(out, expect1) && strstr(out, expect2))) printf("  message was: %s", out);
}

/* Labels a restart (s=) appends (ap=) to the file it came from continue after
 * the file's largest label, as AUTO's NEWLAB; the new branch is numbered
 * after the file's largest branch; no label appears twice. */
static void test_append_labels(void)
{
  char out[8192];
  int rc = run("cd " DIR " && ../../../" CABLE " run c=good sv=lab 2>&1", out, sizeof out);
  test_int("labels: first run exit 0", rc, 0);
  rc = run("cd " DIR " && ../../../" CABLE " run c=good s=lab IRS=2 ap=lab 2>&1", out, sizeof out);
  test_int("labels: restart from s.lab appended to it: exit 0", rc, 0);
  cable_error err;
  cable_sfile *sf = cable_sfile_read(DIR "/s.lab", &err);
  int n = sf ? cable_sfile_count(sf) : 0, uniq = sf != NULL, maxold = 0, newlab = 0, newbr = 0;
  for (int i = 0; i < n; i++) {
    const cable_solution *a = cable_sfile_get(sf, i);
    for (int j = i + 1; j < n; j++) uniq &= a->lab != cable_sfile_get(sf, j)->lab;
    if (a->ibr == 1 && a->lab > maxold) maxold = a->lab;
    if (a->ibr != 1) newlab = a->lab, newbr = a->ibr;
  }
  test_true("labels: s.lab has no label twice", uniq && n >= 3);
  test_int("labels: the appended run's label is the file's largest + 1", newlab, maxold + 1);
  test_int("labels: the appended run is branch 2", newbr, 2);
  cable_sfile_free(sf);
  cable_bfile *bf = cable_bfile_read(DIR "/b.lab", &err);
  test_true("labels: b.lab's second section is branch 2", bf && bf->nbranch == 2 && bf->branch[1].br[0] == 2);
  cable_bfile_free(bf);
  remove(DIR "/b.lab"); remove(DIR "/s.lab"); remove(DIR "/d.lab");
  (void)!system("rm -f " DIR "/b.lab.*.csv");
}

/* The line of `cable list` output that starts with label lab, or NULL. */
static const char *list_line(const char *out, int lab, char *line, size_t len)
{
  for (const char *p = out; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
    int l;
    if (sscanf(p, "%d", &l) == 1 && l == lab) {
      size_t n = strcspn(p, "\n");
      snprintf(line, len, "%.*s", (int)n, p);
      return line;
    }
  }
  return NULL;
}

/* cable list of solutions stored without their direction: the s-file has no
 * free-parameter indices (icp = -1); never index PAR with them. */
static void test_list_without_direction(void)
{
  char out[8192], line[512];
  int rc = run(CABLE " list tests/data/s.auto07p 2>&1", out, sizeof out);
  test_int("list s.auto07p: exit 0", rc, 0);
  const char *l1 = list_line(out, 1, line, sizeof line);
  test_true("list s.auto07p: label 1 (with direction) lists PAR(1) and PAR(11)",
            l1 && strstr(l1, "PAR(1)=1 PAR(11)=6.283185307"));
  const char *l2 = list_line(out, 2, line, sizeof line);
  test_true("list s.auto07p: label 2 (12-integer header, no direction) names no PAR(0) and says why",
            l2 && !strstr(l2, "PAR(0)") && strstr(l2, "not stored"));
  if (l2) printf("  line: %s\n", l2);
  rc = run("cd " DIR " && ../../../" CABLE " run c=good IIS=0 sv=iis0 2>&1", out, sizeof out);
  test_int("IIS=0 run: exit 0", rc, 0);
  rc = run("cd " DIR " && ../../../" CABLE " list s.iis0 2>&1", out, sizeof out);
  test_int("list s.iis0: exit 0", rc, 0);
  cable_error err;
  cable_sfile *sf = cable_sfile_read(DIR "/s.iis0", &err);
  int n = sf ? cable_sfile_count(sf) : 0, ok = n > 1;
  for (int i = 0; i < n; i++) {
    const cable_solution *x = cable_sfile_get(sf, i);
    char want[64];
    snprintf(want, sizeof want, " lambda=%.10g", x->par[0]);   /* the b-file row's value, 11 digits */
    const char *l = list_line(out, x->lab, line, sizeof line);
    ok &= x->icp[0] == -1 && l && strstr(l, want) && !strstr(l, "PAR(0)");
    if (!(l && strstr(l, want))) printf("  label %d: want '%s' in '%s'\n", x->lab, want, l ? l : "(none)");
  }
  test_true("list s.iis0: every label shows lambda from its b-file row, no PAR(0)", ok);
  cable_sfile_free(sf);
  remove(DIR "/b.iis0"); remove(DIR "/s.iis0"); remove(DIR "/d.iis0");
  (void)!system("rm -f " DIR "/b.iis0.*.csv");
}

/* The CSV heading of a b-file column heading: blanks become '_',
 * L2-NORM becomes L2NORM (doc/output-formats.md). */
static void csv_name(const char *heading, char *out, size_t len)
{
  if (strcmp(heading, "L2-NORM") == 0) heading = "L2NORM";
  snprintf(out, len, "%s", heading);
  for (char *c = out; *c; c++)
    if (*c == ' ') *c = '_';
}

/* A saved run writes b.NAME.1.csv: named columns, one row per b-file row,
 * the same numbers (the b-file's have 11 significant digits: REL_TOL). */
#define CSV_REL_TOL 1e-10
static void test_csv(void)
{
  char out[8192];
  int rc = run("cd " DIR " && ../../../" CABLE " run c=good sv=csvt 2>&1", out, sizeof out);
  test_int("csv: cable run ... sv=csvt: exit 0", rc, 0);
  test_true("csv: b.csvt.1.csv exists", exists(DIR "/b.csvt.1.csv"));
  cable_error err;
  cable_bfile *bf = cable_bfile_read(DIR "/b.csvt", &err);
  FILE *f = fopen(DIR "/b.csvt.1.csv", "r");
  char line[4096];
  int head_ok = bf && bf->nbranch == 1 && f && fgets(line, sizeof line, f);
  if (head_ok) {
    /* BR,PT,TY,LAB, then the b-file's columns by name, then NEWTON,DS,ERR_EST */
    char want[4096] = "BR,PT,TY,LAB", nm[128];
    for (int j = 0; j < bf->branch[0].ncol; j++) {
      csv_name(bf->branch[0].colname[j], nm, sizeof nm);
      strcat(want, ",");
      strcat(want, nm);
    }
    strcat(want, ",NEWTON,DS,ERR_EST\n");
    head_ok = strcmp(line, want) == 0;
    if (!head_ok) printf("  header: got %s  want %s", line, want);
  }
  test_true("csv: header names the b-file's columns (lambda, L2NORM, MAX_u, ...)", head_ok && strstr(line, ",lambda,L2NORM,"));
  int nrow = 0, rows_ok = head_ok;
  double emax = 0;
  while (rows_ok && fgets(line, sizeof line, f)) {
    const cable_bfile_branch *b = &bf->branch[0];
    if (nrow >= b->nrow) {
      rows_ok = 0;
      break;
    }
    /* split at every comma (TY may be empty) */
    char *field[64];
    int nf = 0;
    for (char *c = line; nf < 64;) {
      field[nf++] = c;
      c = strpbrk(c, ",\n");
      if (!c || *c == '\n') {
        if (c) *c = '\0';
        break;
      }
      *c++ = '\0';
    }
    if (nf != 4 + b->ncol + 3) {
      rows_ok = 0;
      break;
    }
    rows_ok &= atoi(field[0]) == b->br[nrow] && atoi(field[1]) == b->pt[nrow] && atoi(field[3]) == b->lab[nrow] &&
               strcmp(field[2], b->ty[nrow] ? cable_type_name(b->ty[nrow]) : "") == 0;
    for (int j = 0; j < b->ncol; j++) {
      double v = strtod(field[4 + j], NULL), w = b->data[(size_t)j * (size_t)b->nrow + (size_t)nrow];
      emax = fmax(emax, fabs(v - w) / fmax(fabs(w), 1e-300));
    }
    nrow++;
  }
  if (f) fclose(f);
  test_int("csv: one row per b-file row", nrow, bf && bf->nbranch ? bf->branch[0].nrow : -1);
  test_true("csv: BR, PT, TY, LAB of every row as in the b-file", rows_ok);
  test_le("csv: values vs the b-file's, max rel. error", emax, CSV_REL_TOL);
  cable_bfile_free(bf);
  remove(DIR "/b.csvt"); remove(DIR "/s.csvt"); remove(DIR "/d.csvt"); remove(DIR "/b.csvt.1.csv");
}

static void remove_outputs(const char *name)
{
  char cmd[256];
  snprintf(cmd, sizeof cmd, "rm -f " DIR "/b.%s " DIR "/s.%s " DIR "/d.%s " DIR "/b.%s.*.csv", name, name, name, name);
  (void)!system(cmd);
}

/* A constants file's s= and sv= are honoured, and keywords override them
 * (c.svfile: sv='fromc'; c.sfile: s='sbase', IRS=2, sv='restarted'). */
static void test_cfile_s_sv(void)
{
  char out[8192];
  int rc = run("cd " DIR " && ../../../" CABLE " run c=svfile 2>&1", out, sizeof out);
  test_int("c-file sv='fromc': exit 0", rc, 0);
  test_true("c-file sv='fromc': b.fromc, s.fromc, d.fromc written",
            exists(DIR "/b.fromc") && exists(DIR "/s.fromc") && exists(DIR "/d.fromc"));
  remove_outputs("fromc");
  rc = run("cd " DIR " && ../../../" CABLE " run c=svfile sv=kw 2>&1", out, sizeof out);
  test_true("keyword sv=kw overrides the c-file's sv: b.kw written, no b.fromc",
            rc == 0 && exists(DIR "/b.kw") && !exists(DIR "/b.fromc"));
  remove_outputs("kw");
  rc = run("cd " DIR " && ../../../" CABLE " run c=good sv=sbase 2>&1", out, sizeof out);
  rc |= run("cd " DIR " && ../../../" CABLE " run c=sfile 2>&1", out, sizeof out);
  test_int("c-file s='sbase', IRS=2: exit 0", rc, 0);
  cable_error err;
  cable_sfile *base = cable_sfile_read(DIR "/s.sbase", &err);
  cable_bfile *bf = cable_bfile_read(DIR "/b.restarted", &err);
  const cable_solution *l2 = base ? cable_sfile_find_label(base, 2) : NULL;
  const double *lam = bf && bf->nbranch ? cable_bfile_column(&bf->branch[0], "lambda") : NULL;
  test_true("c-file s= and IRS=2: b.restarted written (the c-file's sv)", lam && l2);
  /* the first row is the restart point itself (11 digits in both files) */
  test_rel("b.restarted starts at label 2 of s.sbase", lam ? lam[0] : (double)NAN, l2 ? l2->par[0] : (double)NAN, 1e-10);
  cable_bfile_free(bf);
  cable_sfile_free(base);
  rc = run("cd " DIR " && ../../../" CABLE " run c=sfile s=nosuch sv=x 2>&1", out, sizeof out);
  test_true("keyword s=nosuch overrides the c-file's s: the error names s.nosuch", rc != 0 && strstr(out, "s.nosuch"));
  remove_outputs("sbase");
  remove_outputs("restarted");
  remove_outputs("x");
}

/* The principal-parameter column of b.NAME's first section, or NULL. */
static cable_bfile *bcol(const char *path, const char *col, const double **v, int *n)
{
  cable_error err;
  cable_bfile *bf = cable_bfile_read(path, &err);
  *v = bf && bf->nbranch ? cable_bfile_column(&bf->branch[0], col) : NULL;
  *n = *v ? bf->branch[0].nrow : 0;
  return bf;
}

/* cable run KEY=VALUE: each argument is a constants-file statement (bare
 * words are strings), DS=- reverses the direction as AUTO's DS='-'. */
static void test_run_overrides(void)
{
  char out[8192];
  const double *lam;
  int n;
  int rc = run("cd " DIR " && ../../../" CABLE " run c=good sv=ovbase 2>&1", out, sizeof out);
  test_int("overrides: base run", rc, 0);
  rc = run("cd " DIR " && ../../../" CABLE " run c=good s=ovbase IRS=EP2 NMX=3 sv=ov1 2>&1", out, sizeof out);
  test_int("IRS=EP2 (a bare label name): exit 0", rc, 0);
  cable_bfile *b1 = bcol(DIR "/b.ov1", "lambda", &lam, &n);
  cable_error err;
  cable_sfile *base = cable_sfile_read(DIR "/s.ovbase", &err);
  const cable_solution *ep2 = base ? cable_sfile_find(base, "EP2", &err) : NULL;
  /* the first row is the restart point (11 digits in both files) */
  test_true("IRS=EP2 restarts at s.ovbase's second EP", lam && ep2 && n == 3 &&
                                                             fabs(lam[0] - ep2->par[0]) <= 1e-10 * fabs(ep2->par[0]));
  int up = lam && n == 3 && lam[1] > lam[0] && lam[2] > lam[1];
  test_true("  and continues with DS > 0: lambda increases", up);
  cable_bfile_free(b1);
  rc = run("cd " DIR " && ../../../" CABLE " run c=good s=ovbase IRS=EP2 NMX=3 DS=- sv=ov2 2>&1", out, sizeof out);
  test_int("DS=- (AUTO's DS='-'): exit 0", rc, 0);
  b1 = bcol(DIR "/b.ov2", "lambda", &lam, &n);
  test_true("DS=- reverses the direction: lambda decreases from EP2",
            lam && ep2 && n == 3 && lam[1] < lam[0] && lam[2] < lam[1]);
  cable_bfile_free(b1);
  cable_sfile_free(base);
  rc = run("cd " DIR " && ../../../" CABLE " run c=good LINSOLVER=klu NMX=3 sv=ov3 2>&1", out, sizeof out);
  FILE *f = fopen(DIR "/b.ov3", "r");
  char line[512];
  int klu = 0;
  while (f && fgets(line, sizeof line, f)) klu |= strstr(line, "LINSOLVER = 'klu'") != NULL;
  if (f) fclose(f);
  test_true("LINSOLVER=klu (a bare word): exit 0, the b-file header says 'klu'", rc == 0 && klu);
  for (int i = 0; i < 4; i++) {
    static const char *const name[] = {"ovbase", "ov1", "ov2", "ov3"};
    remove_outputs(name[i]);
  }
}

int main(void)
{
  char out[8192];
  /* files the runs below must not create */
  const char *outputs[] = {DIR "/b.bad", DIR "/s.bad", DIR "/d.bad"};
  bad("constants file missing", "run c=nosuch sv=bad", "c.nosuch", "cannot open");
  bad("NCOL out of range", "run c=ncol9 sv=bad", "c.ncol9:3", "NCOL");
  bad("missing '='", "run c=noequals sv=bad", "c.noequals:3", "DS");
  bad("unknown parameter name", "run c=badname sv=bad", "c.badname:2", "nosuch");
  bad("negative NTST override", "run c=good NTST=-5 sv=bad", "NTST", "-5");
  bad("NaN override", "run c=good NTST=nan sv=bad", "NTST=nan", "NTST: must be an integer");
  bad("unknown key", "run c=good FOO=1 sv=bad", "FOO", "unknown key");
  bad("argument without '='", "run c=good NMX", "NMX", "KEY=VALUE");
  bad("unknown label in a script", "replay badlabel.auto", "badlabel.auto:2", "BP7");
  bad("bad indentation in a script", "replay badindent.auto", "badindent.auto:2", "indent");
  bad("unknown problem in a script", "replay badproblem.auto", "badproblem.auto:1", "nosuch");
  bad("missing script", "replay nosuch.auto", "nosuch.auto", "");
  bad("table of a missing b-file", "table b.nosuch", "b.nosuch", "");
  bad("render of a missing label", "render s.out LAB99", "LAB99", "");
  bad("unknown command", "frobnicate", "frobnicate", "unknown command");
  for (size_t i = 0; i < sizeof outputs / sizeof outputs[0]; i++) {
    char t[128];
    snprintf(t, sizeof t, "no output written: %s", outputs[i]);
    test_true(t, !exists(outputs[i]));
  }
  /* a good run writes its files */
  int rc = run("cd " DIR " && ../../../" CABLE " run c=good sv=good 2>&1", out, sizeof out);
  test_int("good run: exit 0", rc, 0);
  test_true("good run: b-, s-, d-files written", exists(DIR "/b.good") && exists(DIR "/s.good") && exists(DIR "/d.good"));
  rc = run("cd " DIR " && ../../../" CABLE " list s.good 2>&1", out, sizeof out);
  test_true("cable list reads it", rc == 0 && strstr(out, "EP") != NULL);
  rc = run(CABLE " --version", out, sizeof out);
  test_true("--version names SUNDIALS, GSL and LAPACK",
            rc == 0 && strstr(out, "SUNDIALS") && strstr(out, "GSL") && strstr(out, "LAPACK"));
  remove(DIR "/b.good"); remove(DIR "/s.good"); remove(DIR "/d.good");
  remove(DIR "/b.out"); remove(DIR "/s.out"); remove(DIR "/d.out");
  remove(DIR "/b.out2"); remove(DIR "/s.out2"); remove(DIR "/d.out2");
  (void)!system("rm -f " DIR "/b.*.csv");
  test_append_labels();
  test_list_without_direction();
  test_csv();
  test_cfile_s_sv();
  test_run_overrides();
  return test_summary();
}
