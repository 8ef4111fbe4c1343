/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The cable program through its real binary: malformed constants files,
 * command lines, s-files and scripts each give one line on stderr naming the
 * file, line and key, a non-zero exit, and leave every file in the directory
 * as it was (pre-existing b./s./d. files byte-identical, no new file); then
 * the good paths: labels of appended restarts, cable list without direction,
 * the CSV tables, a constants file's s= and sv=, KEY=VALUE overrides.
 * Everything runs in a scratch copy of tests/data/cli. */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "harness.h"
#include "cable/cable_names.h"

static char cable_bin[3 * PATH_MAX];   /* BUILD/cable, absolute */
static char python_ext[3 * PATH_MAX];  /* BUILD/python/cable/_cable.so: `cable replay` needs it */
static char work[2 * PATH_MAX];        /* tests/tmp/cli.PID, absolute */

static int exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

/* A path in the work directory (four rotating buffers: a few per expression). */
static const char *wpath(const char *name)
{
  static char buf[4][3 * PATH_MAX];
  static int k;
  k = (k + 1) % 4;
  snprintf(buf[k], sizeof buf[k], "%s/%s", work, name);
  return buf[k];
}

/* run a shell command, capture its output; returns the exit status */
static int run(const char *cmd, char *out, size_t len)
{
  FILE *p = popen(cmd, "r");
  if (!p) return -1;
  size_t n = fread(out, 1, len - 1, p);
  out[n] = '\0';
  int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* `cable ARGS` in the work directory; stdout and stderr into out, or stderr
 * only when stderr_only. */
static int cable_in_work(char *out, size_t len, int stderr_only, const char *fmt, va_list ap)
{
  char args[2048], cmd[8 * PATH_MAX];
  vsnprintf(args, sizeof args, fmt, ap);
  snprintf(cmd, sizeof cmd, "cd '%s' && '%s' %s %s", work, cable_bin, args, stderr_only ? "2>&1 >/dev/null" : "2>&1");
  return run(cmd, out, len);
}

static int cli(char *out, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int cli(char *out, size_t len, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int rc = cable_in_work(out, len, 0, fmt, ap);
  va_end(ap);
  return rc;
}

static int cli_stderr(char *out, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int cli_stderr(char *out, size_t len, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int rc = cable_in_work(out, len, 1, fmt, ap);
  va_end(ap);
  return rc;
}

static void remove_outputs(const char *name)
{
  char cmd[4 * PATH_MAX];
  snprintf(cmd, sizeof cmd, "cd '%s' && rm -f b.%s s.%s d.%s b.%s.*.csv", work, name, name, name, name);
  (void)!system(cmd);
}

/* ---- the directory's contents, to prove that nothing was touched --------------- */

#define SNAP_MAX 128
typedef struct {
  int n;
  char name[SNAP_MAX][256];
  char *data[SNAP_MAX];
  long len[SNAP_MAX];
} snapshot;

static char *slurp(const char *path, long *len)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 4096, n = 0, k;
  char *t = malloc(cap);
  while (t && (k = fread(t + n, 1, cap - n, f)) > 0) {
    n += k;
    if (n == cap) {
      char *g = realloc(t, cap *= 2);
      if (!g) free(t);
      t = g;
    }
  }
  fclose(f);
  *len = (long)n;
  return t;
}

static int cmp_name(const void *a, const void *b)
{
  return strcmp((const char *)a, (const char *)b);
}

static void snap_free(snapshot *s)
{
  for (int i = 0; i < s->n; i++) free(s->data[i]);
  s->n = 0;
}

/* Every file name (hidden ones too: temporaries) and its bytes. */
static void snap_take(snapshot *s)
{
  s->n = 0;
  DIR *d = opendir(work);
  struct dirent *e;
  while (d && (e = readdir(d)) && s->n < SNAP_MAX)
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) snprintf(s->name[s->n++], 256, "%s", e->d_name);
  if (d) closedir(d);
  qsort(s->name, (size_t)s->n, sizeof s->name[0], cmp_name);
  for (int i = 0; i < s->n; i++) s->data[i] = slurp(wpath(s->name[i]), &s->len[i]);
}

/* 1 when the directory holds exactly the snapshot's files with the same
 * bytes; otherwise says what differs. */
static int snap_same(const snapshot *s, const char *what)
{
  snapshot now;
  snap_take(&now);
  int same = now.n == s->n;
  for (int i = 0; same && i < s->n; i++)
    same = strcmp(now.name[i], s->name[i]) == 0 && now.len[i] == s->len[i] && s->data[i] && now.data[i] &&
           memcmp(now.data[i], s->data[i], (size_t)s->len[i]) == 0;
  if (!same) {
    printf("  %s: the directory changed:", what);
    for (int i = 0; i < now.n; i++) printf(" %s(%ld)", now.name[i], now.len[i]);
    printf("\n");
  }
  snap_free(&now);
  return same;
}

/* ---- bad input ------------------------------------------------------------------- */

/* cable ARGS must fail with one line on stderr containing where (file:line:
 * or the argument) and key, and leave the directory as snap says. */
/* nlines: 1, or 2 for a script error (the message and the script's line). */
static void bad_lines(const snapshot *snap, const char *what, const char *args, const char *where, const char *key,
                      int nlines)
{
  char out[4096], t[300];
  int rc = cli_stderr(out, sizeof out, "%s", args);
  int lines = 0;
  for (const char *c = out; *c; c++) lines += *c == '\n';
  snprintf(t, sizeof t, "%s: non-zero exit", what);
  test_true(t, rc != 0);
  snprintf(t, sizeof t, nlines == 1 ? "%s: one line on stderr" : "%s: the message and the script's line on stderr",
           what);
  test_int(t, lines, nlines);
  int named = where[0] && key[0] && strstr(out, where) && strstr(out, key);
  snprintf(t, sizeof t, "%s: the message names '%s' and '%s'", what, where, key);
  test_true(t, named);
  if (!named) printf("  message was: %s", out);
  snprintf(t, sizeof t, "%s: b./s./d. files byte-identical, no new file", what);
  test_true(t, snap_same(snap, what));
}

static void bad(const snapshot *snap, const char *what, const char *args, const char *where, const char *key)
{
  bad_lines(snap, what, args, where, key, 1);
}

/* An s-file cut inside its second solution (a restart would read it). */
static void make_truncated(const char *from, const char *to)
{
  long n = 0;
  char *s = slurp(wpath(from), &n);
  long cut = 0;
  int lines = 0, first_nrowpr = s ? atoi(s + 50) : 0;   /* NROWPR: columns 51-58 of the header */
  for (long i = 0; s && i < n; i++)
    if (s[i] == '\n' && ++lines == 1 + first_nrowpr + 3) {
      cut = i + 1;
      break;
    }
  FILE *f = fopen(wpath(to), "wb");
  if (f && s) fwrite(s, 1, (size_t)cut, f);
  if (f) fclose(f);
  free(s);
}

static void test_bad_input(void)
{
  char out[8192];
  /* the files the bad runs would write or read: they exist before, and must
     be byte-identical after */
  int rc = cli(out, sizeof out, "run c=good sv=bad");
  rc |= cli(out, sizeof out, "run c=good sv=good");
  test_int("setup: b./s./d.bad and b./s./d.good written", rc, 0);
  make_truncated("s.good", "s.trunc");
  snapshot snap;
  snap_take(&snap);
  /* constants files */
  bad(&snap, "constants file missing", "run c=nosuch sv=bad", "c.nosuch", "cannot open");
  bad(&snap, "missing '='", "run c=noequals sv=bad", "c.noequals:3:", "DS: missing '='");
  bad(&snap, "unknown key", "run c=unknownkey sv=bad", "c.unknownkey:2:", "FOO: unknown key");
  bad(&snap, "wrong type", "run c=wrongtype sv=bad", "c.wrongtype:2:", "NMX: must be an integer");
  bad(&snap, "NaN", "run c=nan sv=bad", "c.nan:3:", "DSMAX: must be a finite number");
  bad(&snap, "negative NTST", "run c=negntst sv=bad", "c.negntst:2:", "NTST: must be an integer >= 1");
  bad(&snap, "NCOL=9", "run c=ncol9 sv=bad", "c.ncol9:3:", "NCOL: must be an integer in 2..7");
  bad(&snap, "unknown parameter name", "run c=badname sv=bad", "c.badname:2:", "ICP: unknown parameter name 'nosuch'");
  bad(&snap, "unsupported AUTO key", "run c=ibr sv=bad", "c.ibr:2:", "IBR: AUTO key not supported");
  bad(&snap, "unterminated list", "run c=unterminated sv=bad", "c.unterminated:3:", "ICP: unterminated list");
  bad(&snap, "duplicate key", "run c=dupkey sv=bad", "c.dupkey:3:", "NMX: duplicate key");
  /* command-line arguments */
  bad(&snap, "unknown key argument", "run c=good FOO=1 sv=bad", "command line", "FOO: unknown key");
  bad(&snap, "negative NTST argument", "run c=good NTST=-5 sv=bad", "NTST=-5", "NTST: must be an integer >= 1");
  bad(&snap, "NaN argument", "run c=good NTST=nan sv=bad", "NTST=nan", "NTST: must be an integer");
  bad(&snap, "argument without '='", "run c=good NMX sv=bad", "command line", "NMX: arguments are NAME (first) and KEY=VALUE");
  bad(&snap, "argument without a value", "run c=good NMX= sv=bad", "command line", "NMX: no value");
  bad(&snap, "argument given twice", "run c=good NMX=3 NMX=4 sv=bad", "command line", "NMX: given twice");
  bad(&snap, "malformed label name", "run c=good s=good IRS=XY1 sv=bad", "IRS=XY1", "IRS: unknown label 'XY1'");
  bad(&snap, "unknown problem", "run c=good e=nosuch sv=bad", "nosuch", "e: unknown problem");
  bad(&snap, "bad plug-in path", "run c=good e=./nosuch.so sv=bad", "nosuch.so", "cannot open the plug-in");
  bad(&snap, "IRS without solutions", "run c=good IRS=2 sv=bad", "IRS", "a restart needs solutions");
  /* s-files */
  bad(&snap, "missing s-file", "run c=good s=nosuch IRS=1 sv=bad", "s.nosuch", "cannot open");
  bad(&snap, "IRS not in the s-file", "run c=good s=good IRS=7 sv=bad", "s.good", "IRS: label 7 not found");
  bad(&snap, "unknown label in the s-file", "run c=good s=good IRS=BP1 ap=bad", "s.good", "IRS: label 'BP1' not found");
  bad(&snap, "truncated s-file", "run c=good s=trunc IRS=1 sv=bad", "s.trunc:", "truncated file");
  bad(&snap, "cable list of a truncated s-file", "list s.trunc", "s.trunc:", "truncated file");
  bad(&snap, "appending to a truncated s-file", "run c=good ap=trunc", "s.trunc:", "truncated file");
  bad(&snap, "cable table of a missing b-file", "table b.nosuch", "b.nosuch", "cannot open");
  bad(&snap, "render of a missing label", "render s.good LAB99", "s.good", "LAB99");
  /* scripts */
  /* scripts: Python through `cable replay` (python/cable/script.py).  A
     sanitizer build has no Python package (CPython cannot load an
     instrumented extension): make asan checks the rest. */
  if (!exists(python_ext)) printf("no %s (a sanitizer build): the script cases are skipped\n", python_ext);
  else {
    bad(&snap, "missing script", "replay nosuch.auto", "nosuch.auto", "cannot open the script");
    bad_lines(&snap, "bad script line", "replay badsyntax.auto", "badsyntax.auto:2:", "SyntaxError: invalid syntax", 2);
    bad_lines(&snap, "bad indentation in a script", "replay badindent.auto", "badindent.auto:2:", "IndentationError", 2);
    bad_lines(&snap, "unknown label in a script", "replay badlabel.auto", "badlabel.auto:2:", "BP7: no such label", 2);
    bad_lines(&snap, "unknown problem in a script", "replay badproblem.auto", "badproblem.auto:1:", "run: e: unknown problem 'nosuch'", 2);
    bad_lines(&snap, "bad override in a script", "replay badoverride.auto", "badoverride.auto:2:", "run: NTST: must be an integer >= 1", 2);
    bad_lines(&snap, "unknown function in a script", "replay badfunc.auto", "badfunc.auto:2:", "NameError: name 'foo' is not defined", 2);
  }
  bad(&snap, "unknown command", "frobnicate", "frobnicate", "unknown command");
  snap_free(&snap);
  remove_outputs("bad");
  remove_outputs("good");
  remove(wpath("s.trunc"));
}

/* AUTO's NEWLAB through the command line: a plain restart from s.lab (ISW=1)
 * keeps its branch number and numbers its labels after the file's largest;
 * a run from STPNT appended to the same files is branch 1 with labels from 1
 * again (AUTO's ap appends as it is, a label then repeats in the s-file);
 * IRS picks the first solution with the label, as AUTO's FINDLB does. */
static void test_append_labels(void)
{
  char out[8192];
  int rc = cli(out, sizeof out, "run c=good sv=lab");
  test_int("labels: first run exit 0", rc, 0);
  cable_error err;
  cable_sfile *sf = cable_sfile_read(wpath("s.lab"), &err);
  int nold = sf ? cable_sfile_count(sf) : 0, maxold = 0;
  for (int i = 0; i < nold; i++)
    if (cable_sfile_get(sf, i)->lab > maxold) maxold = cable_sfile_get(sf, i)->lab;
  cable_sfile_free(sf);
  rc = cli(out, sizeof out, "run c=good s=lab IRS=2 ap=lab");
  test_int("labels: restart from s.lab appended to it: exit 0", rc, 0);
  sf = cable_sfile_read(wpath("s.lab"), &err);
  int n = sf ? cable_sfile_count(sf) : 0, uniq = sf != NULL;
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) uniq &= cable_sfile_get(sf, i)->lab != cable_sfile_get(sf, j)->lab;
  test_true("labels: s.lab has no label twice (the restart numbers on after its restart data)", uniq && n > nold && nold >= 2);
  const cable_solution *first_new = sf && n > nold ? cable_sfile_get(sf, nold) : NULL;
  test_int("labels: the appended run's first label is the file's largest + 1", first_new ? first_new->lab : 0, maxold + 1);
  int allbr1 = sf != NULL;
  for (int i = 0; i < n; i++) allbr1 &= cable_sfile_get(sf, i)->ibr == 1;
  test_true("labels: the plain restart keeps branch 1 (AUTO's NEWLAB)", allbr1);
  cable_sfile_free(sf);
  cable_bfile *bf = cable_bfile_read(wpath("b.lab"), &err);
  test_true("labels: b.lab has two sections (two runs), both branch 1",
            bf && bf->nbranch == 2 && bf->branch[0].br[0] == 1 && bf->branch[1].br[0] == 1);
  cable_bfile_free(bf);
  /* a second run from STPNT appended: branch 1, labels 1, 2, ... again */
  rc = cli(out, sizeof out, "run c=good ap=lab");
  test_int("labels: a run from STPNT appended: exit 0", rc, 0);
  sf = cable_sfile_read(wpath("s.lab"), &err);
  int m = sf ? cable_sfile_count(sf) : 0;
  const cable_solution *third = sf && m > n ? cable_sfile_get(sf, n) : NULL;
  test_true("labels: the run from STPNT starts again at label 1 on branch 1 (label 1 now twice in s.lab)",
            third && third->lab == 1 && third->ibr == 1 && cable_sfile_get(sf, 0)->lab == 1);
  test_true("labels: IRS=1 finds the first solution with label 1 (AUTO's FINDLB)",
            sf && cable_sfile_find_label(sf, 1) == cable_sfile_get(sf, 0));
  cable_sfile_free(sf);
  bf = cable_bfile_read(wpath("b.lab"), &err);
  test_true("labels: b.lab has three sections, all branch 1",
            bf && bf->nbranch == 3 && bf->branch[2].br[0] == 1 && bf->branch[2].lab[0] == 1);
  cable_bfile_free(bf);
  remove_outputs("lab");
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
  int rc = cli(out, sizeof out, "list s.auto07p");
  test_int("list s.auto07p: exit 0", rc, 0);
  const char *l1 = list_line(out, 1, line, sizeof line);
  test_true("list s.auto07p: label 1 (with direction) lists PAR(1) and PAR(11)",
            l1 && strstr(l1, "PAR(1)=1 PAR(11)=6.283185307"));
  const char *l2 = list_line(out, 2, line, sizeof line);
  test_true("list s.auto07p: label 2 (12-integer header, no direction) names no PAR(0) and says why",
            l2 && !strstr(l2, "PAR(0)") && strstr(l2, "not stored"));
  if (l2) printf("  line: %s\n", l2);
  rc = cli(out, sizeof out, "run c=good IIS=0 sv=iis0");
  test_int("IIS=0 run: exit 0", rc, 0);
  rc = cli(out, sizeof out, "list s.iis0");
  test_int("list s.iis0: exit 0", rc, 0);
  cable_error err;
  cable_sfile *sf = cable_sfile_read(wpath("s.iis0"), &err);
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
  remove_outputs("iis0");
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
  int rc = cli(out, sizeof out, "run c=good sv=csvt");
  test_int("csv: cable run ... sv=csvt: exit 0", rc, 0);
  test_true("csv: b.csvt.1.csv exists", exists(wpath("b.csvt.1.csv")));
  cable_error err;
  cable_bfile *bf = cable_bfile_read(wpath("b.csvt"), &err);
  FILE *f = fopen(wpath("b.csvt.1.csv"), "r");
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
  remove_outputs("csvt");
}

/* A constants file's s= and sv= are honoured, and keywords override them
 * (c.svfile: sv='fromc'; c.sfile: s='sbase', IRS=2, sv='restarted'). */
static void test_cfile_s_sv(void)
{
  char out[8192];
  int rc = cli(out, sizeof out, "run c=svfile");
  test_int("c-file sv='fromc': exit 0", rc, 0);
  test_true("c-file sv='fromc': b.fromc, s.fromc, d.fromc written",
            exists(wpath("b.fromc")) && exists(wpath("s.fromc")) && exists(wpath("d.fromc")));
  remove_outputs("fromc");
  rc = cli(out, sizeof out, "run c=svfile sv=kw");
  test_true("keyword sv=kw overrides the c-file's sv: b.kw written, no b.fromc",
            rc == 0 && exists(wpath("b.kw")) && !exists(wpath("b.fromc")));
  remove_outputs("kw");
  rc = cli(out, sizeof out, "run c=good sv=sbase");
  rc |= cli(out, sizeof out, "run c=sfile");
  test_int("c-file s='sbase', IRS=2: exit 0", rc, 0);
  cable_error err;
  cable_sfile *base = cable_sfile_read(wpath("s.sbase"), &err);
  cable_bfile *bf = cable_bfile_read(wpath("b.restarted"), &err);
  const cable_solution *l2 = base ? cable_sfile_find_label(base, 2) : NULL;
  const double *lam = bf && bf->nbranch ? cable_bfile_column(&bf->branch[0], "lambda") : NULL;
  test_true("c-file s= and IRS=2: b.restarted written (the c-file's sv)", lam && l2);
  /* the first row is the restart point itself (11 digits in both files) */
  test_rel("b.restarted starts at label 2 of s.sbase", lam ? lam[0] : (double)NAN, l2 ? l2->par[0] : (double)NAN, 1e-10);
  cable_bfile_free(bf);
  cable_sfile_free(base);
  rc = cli(out, sizeof out, "run c=sfile s=nosuch sv=x");
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

/* cable run NAME is AUTO's run('NAME'): e='NAME', c='NAME' (auto-07p 0.9.2
 * runs br2.f90 for run('br2') although c.br2 says e='nosuch'), and s.NAME
 * only when it exists.  Here c.bratu names another problem and there is no
 * s.bratu: the run must be Bratu's (its fold at lambda* = 3.5138307191). */
/* One read of a constants file gives the problem's name and the constants:
 * e as a bare word (the syntax reads it as a string) names the problem
 * whose parameter names ICP uses.  (A second, lighter reader that ran before
 * the parser saw only quoted names: ICP = ['lambda'] was an unknown name.) */
static void test_one_parse(void)
{
  char out[8192];
  FILE *f = fopen(wpath("c.bare"), "w");
  if (f) {
    fputs("NDIM = 2, NBC = 2, IPS = 4\nICP = ['lambda']   # lambda: the problem's name for PAR(1)\n"
          "e = bratu\nNTST = 10, NCOL = 4, JAC = 1\n"
          "ILP = 1, DS = 0.1, DSMIN = 1e-5, DSMAX = 0.5, NMX = 40, RL1 = 5\n", f);
    fclose(f);
  }
  int rc = cli(out, sizeof out, "run c=bare sv=bare");
  test_int("e = bratu (a bare word, after ICP = ['lambda']): exit 0", rc, 0);
  const double *lam;
  int n;
  cable_bfile *b = bcol(wpath("b.bare"), "lambda", &lam, &n);
  double lmax = -1;
  for (int i = 0; i < n; i++) lmax = lam[i] > lmax ? lam[i] : lmax;
  /* NTST = 10, NCOL = 4: the fold's discretisation error O(h^8) ~ 1e-8 */
  test_rel("e = bratu: Bratu's fold", lmax, 3.5138307191251612, 1e-7);
  cable_bfile_free(b);
  remove_outputs("bare");
}

static void test_run_name(void)
{
  char out[8192];
  FILE *f = fopen(wpath("c.bratu"), "w");
  if (f) {
    fputs("e = 'elastica'\nNDIM = 2, NBC = 2, IPS = 4\nICP = ['lambda']\nNTST = 10, NCOL = 4, JAC = 1\n"
          "ILP = 1, DS = 0.1, DSMIN = 1e-5, DSMAX = 0.5, NMX = 40, RL1 = 5\n", f);
    fclose(f);
  }
  int rc = cli(out, sizeof out, "run bratu sv=byname");
  test_int("cable run bratu (c.bratu says e='elastica', no s.bratu): exit 0", rc, 0);
  const double *lam;
  int n;
  cable_bfile *b = bcol(wpath("b.byname"), "lambda", &lam, &n);
  double lmax = -1;
  for (int i = 0; i < n; i++) lmax = lam[i] > lmax ? lam[i] : lmax;
  /* NTST = 10, NCOL = 4: the fold's discretisation error O(h^8) ~ 1e-8 */
  test_rel("cable run bratu ran Bratu's problem: its fold", lmax, 3.5138307191251612, 1e-7);
  cable_bfile_free(b);
  /* an explicit e= wins over the name: the straight elastica passes
     lambda = 3.6, which no Bratu solution reaches */
  rc = cli(out, sizeof out, "run bratu e=elastica sv=byname2");
  b = bcol(wpath("b.byname2"), "lambda", &lam, &n);
  lmax = -1;
  for (int i = 0; i < n; i++) lmax = lam[i] > lmax ? lam[i] : lmax;
  test_true("cable run bratu e=elastica runs the elastica (lambda passes 3.6)", rc == 0 && lmax > 3.6);
  cable_bfile_free(b);
  remove(wpath("c.bratu"));
  remove_outputs("byname");
  remove_outputs("byname2");
}

/* cable run KEY=VALUE: each argument is a constants-file statement (bare
 * words are strings), DS=- reverses the direction as AUTO's DS='-'. */
static void test_run_overrides(void)
{
  char out[8192];
  const double *lam;
  int n;
  int rc = cli(out, sizeof out, "run c=good sv=ovbase");
  test_int("overrides: base run", rc, 0);
  rc = cli(out, sizeof out, "run c=good s=ovbase IRS=EP2 NMX=3 sv=ov1");
  test_int("IRS=EP2 (a bare label name): exit 0", rc, 0);
  cable_bfile *b1 = bcol(wpath("b.ov1"), "lambda", &lam, &n);
  cable_error err;
  cable_sfile *base = cable_sfile_read(wpath("s.ovbase"), &err);
  const cable_solution *ep2 = base ? cable_sfile_find(base, "EP2", &err) : NULL;
  /* the first row is the restart point (11 digits in both files) */
  test_true("IRS=EP2 restarts at s.ovbase's second EP", lam && ep2 && n == 3 &&
                                                             fabs(lam[0] - ep2->par[0]) <= 1e-10 * fabs(ep2->par[0]));
  int up = lam && n == 3 && lam[1] > lam[0] && lam[2] > lam[1];
  test_true("  and continues with DS > 0: lambda increases", up);
  cable_bfile_free(b1);
  rc = cli(out, sizeof out, "run c=good s=ovbase IRS=EP2 NMX=3 DS=- sv=ov2");
  test_int("DS=- (AUTO's DS='-'): exit 0", rc, 0);
  b1 = bcol(wpath("b.ov2"), "lambda", &lam, &n);
  test_true("DS=- reverses the direction: lambda decreases from EP2",
            lam && ep2 && n == 3 && lam[1] < lam[0] && lam[2] < lam[1]);
  cable_bfile_free(b1);
  cable_sfile_free(base);
  rc = cli(out, sizeof out, "run c=good LINSOLVER=klu NMX=3 sv=ov3");
  FILE *f = fopen(wpath("b.ov3"), "r");
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


/* The work directory: a copy of tests/data/cli and AUTO-07p's sample files. */
static int setup(const char *argv0)
{
  char cwd[PATH_MAX], build[PATH_MAX];
  if (!getcwd(cwd, sizeof cwd)) return -1;
  /* BUILD/tests/test_cli: the program is BUILD/cable */
  const char *t = strstr(argv0, "/tests/");
  snprintf(build, sizeof build, "%.*s", t ? (int)(t - argv0) : 0, argv0);
  if (!t) snprintf(build, sizeof build, "build/release");
  snprintf(cable_bin, sizeof cable_bin, "%s%s%s/cable", build[0] == '/' ? "" : cwd, build[0] == '/' ? "" : "/", build);
  snprintf(python_ext, sizeof python_ext, "%s%s%s/python/cable/_cable.so", build[0] == '/' ? "" : cwd,
           build[0] == '/' ? "" : "/", build);
  snprintf(work, sizeof work, "%s/tests/tmp/cli.%ld", cwd, (long)getpid());
  char cmd[8 * PATH_MAX];
  snprintf(cmd, sizeof cmd,
           "mkdir -p '%s' && cp tests/data/cli/* '%s'/ && cp tests/data/s.auto07p tests/data/b.auto07p '%s'/", work, work,
           work);
  return system(cmd);
}

int main(int argc, char **argv)
{
  (void)argc;
  test_int("set up the work directory", setup(argv[0]), 0);
  char out[8192];
  test_bad_input();
  /* a good run writes its files */
  int rc = cli(out, sizeof out, "run c=good sv=good");
  test_int("good run: exit 0", rc, 0);
  test_true("good run: b-, s-, d-files written", exists(wpath("b.good")) && exists(wpath("s.good")) && exists(wpath("d.good")));
  rc = cli(out, sizeof out, "list s.good");
  test_true("cable list reads it", rc == 0 && strstr(out, "EP") != NULL);
  rc = cli(out, sizeof out, "--version");
  test_true("--version names SUNDIALS, GSL and LAPACK",
            rc == 0 && strstr(out, "SUNDIALS") && strstr(out, "GSL") && strstr(out, "LAPACK"));
  remove_outputs("good");
  test_append_labels();
  test_list_without_direction();
  test_csv();
  test_cfile_s_sv();
  test_run_overrides();
  test_run_name();
  test_one_parse();
  char cmd[4 * PATH_MAX];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", work);
  (void)!system(cmd);
  return test_summary();
}
