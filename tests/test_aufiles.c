/* SPDX-License-Identifier: GPL-3.0-or-later */
/* b./s./d. files in AUTO-07p's layout: write a synthetic branch (u_i(t) =
 * sin((i+1)t), NDIM 3, NTST 5, NCOL 4) and an appended second branch (NDIM 8,
 * no direction data), read them back with cable's readers and with an
 * independent fixed-width reader written here (also on the engine's own
 * output for bratu, elastica, layer and stiff), and check the atomic-write
 * guarantees.  Numbers are printed as ES19.10E3: 11 significant digits, so a
 * re-read value is within 0.5e-10 relative of the original (tolerance 1e-10). */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "cable/cable_constants.h"
#include "test_problems.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "cable/cable_names.h"

#define OUTDIR "tests/tmp/aufiles"
#define PI 3.14159265358979323846
#define REL_TOL 1e-10      /* ES19.10: 11 significant digits, rounding error <= 5e-11 relative */
#define NPAR1 12
#define ERR_SLOT 11        /* PAR(12) is named "err" */

/* ---------------------------------------------------------------- helpers */

static void clean_dir(const char *dir)
{
  mkdir("tests/tmp", 0755);
  mkdir(dir, 0755);
  DIR *d = opendir(dir);
  if (!d) return;
  struct dirent *e;
  char p[1024];
  while ((e = readdir(d))) {
    if (e->d_name[0] == '.' && (e->d_name[1] == '\0' || (e->d_name[1] == '.' && e->d_name[2] == '\0'))) continue;
    snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
    unlink(p);
  }
  closedir(d);
}

static int count_tmp_files(const char *dir)
{
  DIR *d = opendir(dir);
  int n = 0;
  struct dirent *e;
  if (!d) return -1;
  while ((e = readdir(d)))
    if (strstr(e->d_name, ".tmp") || strstr(e->d_name, ".ckpt")) n++;
  closedir(d);
  return n;
}

static int file_exists(const char *p)
{
  return access(p, F_OK) == 0;
}

static char *slurp(const char *p, long *len)
{
  FILE *f = fopen(p, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *b = malloc((size_t)n + 1);
  if (b && fread(b, 1, (size_t)n, f) != (size_t)n) n = 0;
  if (b) b[n] = '\0';
  fclose(f);
  if (len) *len = n;
  return b;
}

static double relerr(double got, double want)
{
  double scale = fabs(want) > 0 ? fabs(want) : 1.0;
  return fabs(got - want) / scale;
}

/* Parameter values spanning exponents with 1, 2 and 3 digits and both signs. */
static double par_value(int k, int phase)
{
  static const double base[] = {1.0, -2.5e-120, 3.25e150, 0.0, 1e-5, -7.0e99, 6.02214076e23, -1.0e100,
                                4.0e-99, 123456.789, -0.5, 9.99999999999e2};
  return base[k % 12] * (1.0 + 0.001 * phase) + (k == 0 ? 0.1 * phase : 0.0);
}

/* A solution with u_i(t) = sin((i+1) t + 0.01 phase) on a graded mesh. */
static cable_solution *make_solution(int ndim, int ntst, int ncol, int npar, int nfpr, int phase)
{
  cable_solution *s = cable_solution_alloc(ndim, ntst, ncol, npar, nfpr);
  if (!s) return NULL;
  for (int j = 0; j < ntst; j++) {
    double t0 = pow((double)j / ntst, 1.3), t1 = pow((double)(j + 1) / ntst, 1.3);
    for (int k = 0; k < ncol; k++) s->t[j * ncol + k] = t0 + k * (t1 - t0) / ncol;
  }
  s->t[ntst * ncol] = 1.0;
  int np = cable_solution_npts(s);
  for (int m = 0; m < np; m++)
    for (int i = 0; i < ndim; i++) {
      double a = (i + 1) * s->t[m] + 0.01 * phase;
      s->u[m * ndim + i] = sin(a);
      s->udot[m * ndim + i] = (i + 1) * cos(a) * 1e-3;
    }
  for (int k = 0; k < npar; k++) s->par[k] = par_value(k, phase);
  for (int k = 0; k < nfpr; k++) {
    s->icp[k] = k == 0 ? 0 : 1;
    s->pardot[k] = 0.5 + 0.25 * k - 0.001 * phase;
  }
  s->err_est = 1.5e-9 * (1 + phase);
  return s;
}

typedef struct {
  int pt, itp, lab;
  double vals[16];   /* the b-file row values as the writer must print them */
  int nval;
} expect_row;

/* Emit points 1..npt of a branch; labelled ones (lab > 0) also get solutions. */
static int emit_branch(cable_sink *sink, int ibr, int ndim, int ntst, int ncol, int npar, int nfpr, int npt,
                       const int *itp, const int *lab, const int *icp, int nicp, expect_row *rows,
                       cable_solution **keep)
{
  int st = 0;
  for (int p = 0; p < npt && st == 0; p++) {
    cable_solution *s = make_solution(ndim, ntst, ncol, npar, nfpr, 10 * ibr + p);
    double umax[16];
    int np = cable_solution_npts(s);
    double l2 = 0;
    for (int i = 0; i < ndim; i++) {
      umax[i] = 0;
      for (int m = 0; m < np; m++)
        if (fabs(s->u[m * ndim + i]) > fabs(umax[i])) umax[i] = s->u[m * ndim + i];
    }
    for (int m = 0; m < np * ndim; m++) l2 += s->u[m] * s->u[m];
    l2 = sqrt(l2 / np);
    cable_point pt = {0};
    pt.ibr = ibr;
    pt.pt = p + 1;
    pt.itp = itp[p];
    pt.lab = lab[p];
    pt.ndim = ndim;
    pt.npar = npar;
    pt.nicp = nicp;
    pt.icp = icp;
    pt.par = s->par;
    pt.l2norm = l2;
    pt.measure = l2;   /* IPLT = 0 */
    pt.umax = umax;
    pt.newton_iters = 2 + p % 3;
    pt.ds = 0.01 * (p + 1);
    pt.err_est = s->err_est;
    s->ibr = ibr;
    s->ntot = p + 1;
    s->itp = itp[p];
    s->lab = lab[p];
    s->isw = 1;
    expect_row *r = &rows[p];
    r->pt = p + 1;
    r->itp = itp[p];
    r->lab = lab[p];
    r->nval = 0;
    r->vals[r->nval++] = s->par[icp[0]];
    r->vals[r->nval++] = l2;
    int n2 = nicp > 7 ? 0 : (nicp + ndim > 7 ? 7 - nicp : ndim);
    for (int i = 0; i < n2; i++) r->vals[r->nval++] = umax[i];
    for (int k = 1; k < nicp; k++) r->vals[r->nval++] = s->par[icp[k]];
    char line[128];
    snprintf(line, sizeof line, "Newton iteration %d: residual %.3e", 1, 1e-9 * (p + 1));
    st = sink->point(sink->ctx, &pt);
    if (st == 0 && lab[p] != 0) st = sink->solution(sink->ctx, &pt, s);
    sink->diag(sink->ctx, line);   /* the engine reports after the point, as here */
    if (keep && lab[p] != 0) keep[p] = s;
    else cable_solution_free(s);
  }
  return st;
}

/* ---------------------------------------------------------------- independent layout reader */

/* One field written by Fortran ES19.10E3: right-justified, -?d.ddddddddddE[+-]ddd. */
static int is_es19_10e3(const char *f)
{
  int k = 0;
  while (k < 19 && f[k] == ' ') k++;
  const char *s = f + k;
  int len = 19 - k, p = 0;
  if (len < 17) return 0;
  if (s[p] == '-') p++;
  if (len - p != 17) return 0;
  if (!(s[p] >= '0' && s[p] <= '9') || s[p + 1] != '.') return 0;
  for (int i = 0; i < 10; i++)
    if (!(s[p + 2 + i] >= '0' && s[p + 2 + i] <= '9')) return 0;
  const char *e = s + p + 12;
  if (e[0] != 'E' || (e[1] != '+' && e[1] != '-')) return 0;
  for (int i = 2; i < 5; i++)
    if (!(e[i] >= '0' && e[i] <= '9')) return 0;
  return k >= 1;   /* at least one blank separates neighbouring fields */
}

static long fixed_int(const char *line, int from, int width)
{
  char b[32];
  memcpy(b, line + from, (size_t)width);
  b[width] = '\0';
  return strtol(b, NULL, 10);
}

static int ceil_div(int a, int b)
{
  return (a + b - 1) / b;
}

/* Walk an s-file with fixed widths: check every header and line layout and
 * that NROWPR lines follow each header.  Returns the number of blocks. */
static int check_s_layout(const char *path, int *bad_lines, int *nrowpr_ok)
{
  FILE *f = fopen(path, "r");
  char line[4096];
  int blocks = 0;
  *bad_lines = 0;
  *nrowpr_ok = 1;
  if (!f) return -1;
  while (fgets(line, sizeof line, f)) {
    size_t L = strlen(line);
    if (L != 94) {  /* 6*6 + 8 + 6 + 8 + 7*5 = 93 characters and the newline */
      (*bad_lines)++;
      break;
    }
    int w[16] = {6, 6, 6, 6, 6, 6, 8, 6, 8, 5, 5, 5, 5, 5, 5, 5};
    long h[16];
    int pos = 0;
    for (int k = 0; k < 16; k++) {
      h[k] = fixed_int(line, pos, w[k]);
      pos += w[k];
    }
    int nfpr = (int)h[4], ntpl = (int)h[6], nar = (int)h[7], nrowpr = (int)h[8], npar = (int)h[11];
    int ndim = nar - 1;
    int nosmall = ntpl * ceil_div(nar, 7) + ceil_div(npar, 7);
    int withdir = nosmall + ceil_div(nfpr, 20) + ceil_div(nfpr, 7) + ntpl * ceil_div(ndim, 7);
    if (nrowpr != nosmall && nrowpr != withdir) *nrowpr_ok = 0;
    int dir = nrowpr == withdir && nfpr > 0;
    /* expected numbers per line, record by record */
    int recs = ntpl + 1 + (dir ? 1 + ntpl : 0);
    int lines_read = 0;
    for (int r = 0; r < recs; r++) {
      int m = r < ntpl ? nar : (dir && r == ntpl ? nfpr : (dir && r < 2 * ntpl + 1 ? ndim : npar));
      if (dir && r == ntpl) {
        /* free-parameter indices: 20I5 */
        for (int l = 0; l < ceil_div(nfpr, 20); l++) {
          if (!fgets(line, sizeof line, f)) return -2;
          lines_read++;
          int cnt = (l + 1) * 20 <= nfpr ? 20 : nfpr - l * 20;
          if ((int)strlen(line) != 5 * cnt + 1) (*bad_lines)++;
        }
        m = nfpr;  /* then RL-dot */
      }
      for (int l = 0; l < ceil_div(m, 7); l++) {
        if (!fgets(line, sizeof line, f)) return -2;
        lines_read++;
        int cnt = (l + 1) * 7 <= m ? 7 : m - l * 7;
        if ((int)strlen(line) != 4 + 19 * cnt + 1 || strncmp(line, "    ", 4) != 0) {
          (*bad_lines)++;
          continue;
        }
        for (int k = 0; k < cnt; k++)
          if (!is_es19_10e3(line + 4 + 19 * k)) (*bad_lines)++;
      }
    }
    if (lines_read != nrowpr) *nrowpr_ok = 0;
    blocks++;
  }
  fclose(f);
  return blocks;
}

/* Walk a b-file with fixed widths: header lines start with "   0", rows are
 * I4,I6,I4,I5 then 19-character ES19.10E3 fields.  Collects the rows. */
typedef struct {
  int nrow, bad, sections;
  int br[64], pt[64], ty[64], lab[64], nval[64];
  double v[64][16];
  char heading[8][160];
} bscan;

static void check_b_layout(const char *path, bscan *b)
{
  FILE *f = fopen(path, "r");
  char line[4096];
  int in_header = 0;
  memset(b, 0, sizeof *b);
  if (!f) {
    b->bad = 1;
    return;
  }
  while (fgets(line, sizeof line, f)) {
    size_t L = strlen(line);
    if (strncmp(line, "   0", 4) == 0) {
      if (!in_header) b->sections++;
      in_header = 1;
      if (strstr(line, " PT ") && b->sections <= 8) snprintf(b->heading[b->sections - 1], 160, "%.159s", line);
      continue;
    }
    in_header = 0;
    if (L < 20 || (L - 20) % 19 != 0 || b->nrow >= 64) {
      b->bad++;
      continue;
    }
    int r = b->nrow++;
    b->br[r] = (int)fixed_int(line, 0, 4);
    b->pt[r] = (int)fixed_int(line, 4, 6);
    b->ty[r] = (int)fixed_int(line, 10, 4);
    b->lab[r] = (int)fixed_int(line, 14, 5);
    b->nval[r] = (int)((L - 20) / 19);
    for (int k = 0; k < b->nval[r] && k < 16; k++) {
      const char *fld = line + 19 + 19 * k;
      if (!is_es19_10e3(fld)) b->bad++;
      char tmp[20];
      memcpy(tmp, fld, 19);
      tmp[19] = '\0';
      b->v[r][k] = strtod(tmp, NULL);
    }
  }
  fclose(f);
}

/* Heading of value column j in a b-file header line (19-character fields after
 * "   0    PT  TY  LAB "), trimmed. */
static void heading_field(const char *line, int j, char *out)
{
  int a = 20 + 19 * j;
  int L = (int)strlen(line);
  out[0] = '\0';
  if (a >= L) return;
  int e = a + 19 < L ? a + 19 : L;
  while (a < e && line[a] == ' ') a++;
  while (e > a && (line[e - 1] == ' ' || line[e - 1] == '\n')) e--;
  memcpy(out, line + a, (size_t)(e - a));
  out[e - a] = '\0';
}

/* ---------------------------------------------------------------- tests */

static void test_format(void)
{
  char b[64];
  test_true("ES19.10E3 of 1234.5 is '  1.2345000000E+003'",
            strcmp(cable_aufile_format_es(b, 1234.5, 19, 10, 3), "  1.2345000000E+003") == 0);
  test_true("ES19.10E3 of -2.5e-120 is ' -2.5000000000E-120'",
            strcmp(cable_aufile_format_es(b, -2.5e-120, 19, 10, 3), " -2.5000000000E-120") == 0);
  test_true("ES19.10E3 of 0 is '  0.0000000000E+000'",
            strcmp(cable_aufile_format_es(b, 0.0, 19, 10, 3), "  0.0000000000E+000") == 0);
  test_true("ES19.10E3 rounds to 11 significant digits: 2/3 -> '  6.6666666667E-001'",
            strcmp(cable_aufile_format_es(b, 2.0 / 3.0, 19, 10, 3), "  6.6666666667E-001") == 0);
  test_true("ES11.4 of 1e-7 is ' 1.0000E-07' (AUTO's header form)",
            strcmp(cable_aufile_format_es(b, 1e-7, 11, 4, 2), " 1.0000E-07") == 0);
  test_true("ES12.4 of 1e300 keeps its E: ' 1.0000E+300'",
            strcmp(cable_aufile_format_es(b, 1e300, 12, 4, 2), " 1.0000E+300") == 0);
  double v = 0;
  test_true("parse 1.5-103 (Fortran drops the E)", cable_aufile_parse_double("1.5-103", &v) == 0);
  test_rel("  value of 1.5-103", v, 1.5e-103, 1e-15);
  test_true("parse -2.0D+05", cable_aufile_parse_double("-2.0D+05", &v) == 0);
  test_rel("  value of -2.0D+05", v, -2.0e5, 1e-15);
  test_true("parse 3.0E+000", cable_aufile_parse_double("3.0E+000", &v) == 0 && v == 3.0);
  test_true("parse 0.0000E (old AUTO quirk) as 0", cable_aufile_parse_double("0.0000E", &v) == 0 && v == 0.0);
  test_true("reject 'abc'", cable_aufile_parse_double("abc", &v) != 0);
  test_true("reject '1.0E+0x'", cable_aufile_parse_double("1.0E+0x", &v) != 0);
}

static void check_solution(const char *tag, const cable_solution *got, const cable_solution *want, int with_dir,
                           int err_slot)
{
  char what[160];
  double emax = 0;
  int np = cable_solution_npts(want);
  test_int(tag, got->lab, want->lab);
  snprintf(what, sizeof what, "%s: sizes (ndim ntst ncol npar nfpr)", tag);
  test_true(what, got->ndim == want->ndim && got->ntst == want->ntst && got->ncol == want->ncol &&
                      got->npar == want->npar && got->nfpr == want->nfpr);
  snprintf(what, sizeof what, "%s: ibr ntot itp isw", tag);
  test_true(what, got->ibr == want->ibr && got->ntot == want->ntot && got->itp == want->itp && got->isw == want->isw);
  for (int m = 0; m < np; m++) emax = fmax(emax, relerr(got->t[m], want->t[m]));
  snprintf(what, sizeof what, "%s: all %d t values, max rel. error", tag, np);
  test_le(what, emax, REL_TOL);
  emax = 0;
  for (int m = 0; m < np * want->ndim; m++) emax = fmax(emax, relerr(got->u[m], want->u[m]));
  snprintf(what, sizeof what, "%s: all %d u values, max rel. error", tag, np * want->ndim);
  test_le(what, emax, REL_TOL);
  emax = 0;
  for (int k = 0; k < want->npar; k++) {
    double w = k == err_slot ? want->err_est : want->par[k];
    emax = fmax(emax, relerr(got->par[k], w));
  }
  snprintf(what, sizeof what, "%s: all %d PAR values (PAR(%d) = error estimate), max rel. error", tag, want->npar,
           err_slot + 1);
  test_le(what, emax, REL_TOL);
  if (with_dir) {
    emax = 0;
    for (int m = 0; m < np * want->ndim; m++) emax = fmax(emax, relerr(got->udot[m], want->udot[m]));
    for (int k = 0; k < want->nfpr; k++) emax = fmax(emax, relerr(got->pardot[k], want->pardot[k]));
    snprintf(what, sizeof what, "%s: direction (udot, pardot), max rel. error", tag);
    test_le(what, emax, REL_TOL);
    int icp_ok = 1;
    for (int k = 0; k < want->nfpr; k++) icp_ok &= got->icp[k] == want->icp[k];
    snprintf(what, sizeof what, "%s: free-parameter indices", tag);
    test_true(what, icp_ok);
  } else {
    int zero = 1;
    for (int m = 0; m < np * want->ndim; m++) zero &= got->udot[m] == 0.0;
    for (int k = 0; k < want->nfpr; k++) zero &= got->icp[k] == -1;
    snprintf(what, sizeof what, "%s: no direction stored (IIS=0): udot 0, icp -1", tag);
    test_true(what, zero);
  }
}


/* ---------------------------------------------------------------- with the engine */

/* Forwards to the writer and keeps what the engine handed out. */
typedef struct {
  cable_sink out;
  int n, nsol;
  int lab[256], pt[256];
  double p0[256], l2[256];
  cable_solution *sol[64];
} tee;

static int tee_point(void *ctx, const cable_point *pt)
{
  tee *t = ctx;
  if (t->n < 256) {
    t->lab[t->n] = pt->lab;
    t->pt[t->n] = pt->pt;
    t->p0[t->n] = pt->par[pt->icp[0]];
    t->l2[t->n] = pt->l2norm;
    t->n++;
  }
  return t->out.point(t->out.ctx, pt);
}

static int tee_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  tee *t = ctx;
  if (t->nsol < 64) t->sol[t->nsol++] = cable_solution_clone(sol);
  return t->out.solution(t->out.ctx, pt, sol);
}

static void tee_diag(void *ctx, const char *line)
{
  tee *t = ctx;
  t->out.diag(t->out.ctx, line);
}

static void tee_free(tee *t)
{
  for (int i = 0; i < t->nsol; i++) cable_solution_free(t->sol[i]);
  t->nsol = 0;
  t->n = 0;
}

/* Constants file -> engine -> b./s./d. -> s-file lookup 'BP1' -> ISW=-1 run
 * appended -> every stored number re-read within the ES19.10 rounding. */
static void test_with_engine(void)
{
  const cable_problem *pb = cable_testproblem_elastica();
  static const char ctext[] =
    "e = 'elastica', NDIM = 2, IPS = 4, NBC = 2, NINT = 0, ICP = ['lambda']\n"
    "NTST = 50, NCOL = 5, JAC = 1, IAD = 0\n"
    "DS = 0.5, DSMIN = 1e-6, DSMAX = 4.0, NMX = 200, RL1 = 100\n"
    "ISP = 2, ILP = 0, EPSS = 1e-10\n";
  cable_constants c;
  cable_names names;
  cable_error err;
  char msg[1024];
  int st = cable_constants_parse_string("c.elastica", ctext, &c, &names, pb->parnames, pb->npar, &err);
  test_int("engine run: constants parse (ICP by the problem's name 'lambda')", st, 0);
  if (st) return;
  cable_names_fill(&names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  int status = 0;
  cable_cont *cc = cable_cont_alloc(pb, &c, &status);
  test_true("engine run: cable_cont_alloc", cc != NULL);
  if (!cc) return;
  cable_cont_set_start(cc, NULL);
  cable_aufile *w = cable_aufile_open(OUTDIR, "ela", &c, &names, NULL, &err);
  tee t;
  memset(&t, 0, sizeof t);
  t.out = cable_aufile_sink(w);
  cable_sink sink = {&t, tee_point, tee_solution, tee_diag};
  int next = 0;
  int rc = cable_cont_run(cc, &sink, 1, 1, &next);
  cable_cont_free(cc);
  test_true("engine run 1 ends normally (RL1)", rc > 0);
  test_int("engine run 1: writer closes cleanly", cable_aufile_close(w, &err), 0);
  cable_sfile *sf = cable_sfile_read(OUTDIR "/s.ela", &err);
  test_true("engine run 1: s.ela reads back", sf != NULL);
  if (!sf) {
    tee_free(&t);
    return;
  }
  test_int("engine run 1: one s-file solution per labelled point", cable_sfile_count(sf), t.nsol);
  double emax = 0;
  int labs_ok = 1;
  for (int i = 0; i < t.nsol && i < cable_sfile_count(sf); i++) {
    const cable_solution *g = cable_sfile_get(sf, i), *x = t.sol[i];
    labs_ok &= g->lab == x->lab && g->itp == x->itp && g->ntst == x->ntst;
    for (int m = 0; m < cable_solution_npts(x) * x->ndim; m++) emax = fmax(emax, fabs(g->u[m] - x->u[m]) / fmax(fabs(x->u[m]), 1e-300));
    for (int k = 0; k < x->npar; k++) emax = fmax(emax, relerr(g->par[k], x->par[k]));
  }
  test_true("engine run 1: labels, types and sizes match the engine's", labs_ok);
  test_le("engine run 1: every u and PAR re-read, max rel. error", emax, REL_TOL);
  cable_bfile *bf = cable_bfile_read(OUTDIR "/b.ela", &err);
  int rows_ok = bf && bf->nbranch == 1 && bf->branch[0].nrow == t.n;
  const double *lam = bf ? cable_bfile_column(&bf->branch[0], "lambda") : NULL;
  const double *l2 = bf ? cable_bfile_column(&bf->branch[0], "L2-NORM") : NULL;
  emax = 0;
  for (int r = 0; rows_ok && lam && l2 && r < t.n; r++) {
    rows_ok &= bf->branch[0].lab[r] == t.lab[r] && bf->branch[0].pt[r] == t.pt[r];
    emax = fmax(emax, fmax(relerr(lam[r], t.p0[r]), relerr(l2[r], t.l2[r])));
  }
  test_true("engine run 1: b.ela has every point with its label, column 'lambda'", rows_ok && lam && l2);
  test_le("engine run 1: lambda and L2-NORM columns, max rel. error", emax, REL_TOL);
  cable_bfile_free(bf);
  tee_free(&t);
  /* the header's names lines are constants syntax: cable's parser reads them back */
  char *btext = slurp(OUTDIR "/b.ela", NULL);
  char *un = btext ? strstr(btext, "unames   = ") : NULL;
  cable_constants hc;
  cable_names hn;
  if (un) *strchr(un, '\n') = '\0';
  st = un ? cable_constants_parse_string("b.ela header", un, &hc, &hn, NULL, 0, &err) : -1;
  test_true("b.ela header line unames = {1: 'theta', 2: \"theta'\"} parses back", st == 0 &&
            strcmp(hn.u[0], "theta") == 0 && strcmp(hn.u[1], "theta'") == 0);
  free(btext);

  /* restart at the first BP on the bifurcating branch, appended (AUTO's ap) */
  st = cable_constants_parse_override("IRS='BP1', ISW=-1, DS=0.05, DSMAX=0.2, NMX=12, NPR=5", &c, &names, pb->parnames,
                                      pb->npar, &err);
  if (st == 0) st = cable_constants_parse_override("ISP=0", &c, &names, pb->parnames, pb->npar, &err);
  test_int("engine run 2: overrides IRS='BP1', ISW=-1, ...", st, 0);
  st = cable_sfile_resolve_irs(sf, &c, &err);
  test_true("engine run 2: IRS='BP1' resolves to a label", st == 0 && c.irs > 0);
  const cable_solution *start = cable_sfile_find_label(sf, c.irs);
  test_true("engine run 2: BP1 at lambda = pi^2 in the s-file (collocation error < 1e-8)",
            start && start->itp == 6 && fabs(start->par[0] - PI * PI) < 1e-8 * PI * PI);
  if (!start) {
    cable_sfile_free(sf);
    return;
  }
  cable_aufile_options opt;
  cable_aufile_options_init(&opt);
  opt.append = 1;
  w = cable_aufile_open(OUTDIR, "ela", &c, &names, &opt, &err);
  cc = cable_cont_alloc(pb, &c, &status);
  test_true("engine run 2: writer and engine", w && cc);
  if (!w || !cc) {
    cable_aufile_abort(w);
    cable_cont_free(cc);
    cable_sfile_free(sf);
    return;
  }
  int first = cable_aufile_last_label(w) + 1, ibr = cable_aufile_last_branch(w) + 1;
  cable_cont_set_start(cc, start);
  memset(&t, 0, sizeof t);
  t.out = cable_aufile_sink(w);
  rc = cable_cont_run(cc, &sink, ibr, first, &next);
  cable_cont_free(cc);
  st = cable_aufile_close(w, &err);
  if (st) printf("  %s\n", cable_error_format(&err, msg, sizeof msg));
  test_int("engine run 2: appending writer closes cleanly", st, 0);
  cable_sfile_free(sf);
  sf = cable_sfile_read(OUTDIR "/s.ela", &err);
  bf = cable_bfile_read(OUTDIR "/b.ela", &err);
  test_true("engine run 2: b.ela has 2 sections, the second on branch 2",
            bf && bf->nbranch == 2 && bf->branch[1].br[0] == 2);
  int uniq = sf != NULL, nlab = sf ? cable_sfile_count(sf) : 0;
  for (int i = 0; uniq && i < nlab; i++)
    for (int j = i + 1; j < nlab; j++) uniq &= cable_sfile_get(sf, i)->lab != cable_sfile_get(sf, j)->lab;
  test_true("engine run 2: labels unique across both runs, new ones continue the old", uniq && t.nsol > 0 &&
                                                                                          t.sol[0]->lab == first);
  double amp = 0;
  for (int i = 0; sf && i < nlab; i++) {
    const cable_solution *g = cable_sfile_get(sf, i);
    if (g->ibr == 2) amp = fmax(amp, fabs(g->u[0]));
  }
  test_true("engine run 2: the stored branch-2 solutions are buckled (|theta(0)| > 0.3)", amp > 0.3);
  /* the other direction from BP1 (theta = a cos(pi s) with a > 0 where run 2
     had a < 0): there max theta' = 0 < max |theta'| */
  c.ds = -c.ds;
  w = cable_aufile_open(OUTDIR, "ela", &c, &names, &opt, &err);
  cc = cable_cont_alloc(pb, &c, &status);
  const cable_solution *bp1 = sf ? cable_sfile_find_label(sf, c.irs) : NULL;
  st = w && cc && bp1 ? cable_cont_set_start(cc, bp1) : -1;
  tee_free(&t);
  if (w) t.out = cable_aufile_sink(w);
  if (st == 0) rc = cable_cont_run(cc, &sink, cable_aufile_last_branch(w) + 1, cable_aufile_last_label(w) + 1, &next);
  cable_cont_free(cc);
  st = w ? cable_aufile_close(w, &err) : -1;
  test_int("engine run 3 (DS < 0 from BP1) appended", st, 0);
  tee_free(&t);
  cable_bfile_free(bf);
  cable_sfile_free(sf);
  sf = cable_sfile_read(OUTDIR "/s.ela", &err);
  bf = cable_bfile_read(OUTDIR "/b.ela", &err);
  /* MAX U columns are AUTO's MXUPSP: max_t u_i(t), signed (not max |u_i|),
     over the stored points; compared with the s-file's points (both files
     round to 11 digits) */
  double dmax = 0;
  int nrows = 0, signed_differs = 0;
  for (int k = 0; bf && sf && k < bf->nbranch; k++) {
    const cable_bfile_branch *bb = &bf->branch[k];
    const double *mx[2] = {cable_bfile_column(bb, "MAX theta"), cable_bfile_column(bb, "MAX theta'")};
    for (int r = 0; mx[0] && mx[1] && r < bb->nrow; r++) {
      const cable_solution *g = bb->lab[r] ? cable_sfile_find_label(sf, bb->lab[r]) : NULL;
      if (!g) continue;
      for (int i = 0; i < 2; i++) {
        double m = g->u[i], ma = fabs(g->u[i]);
        for (int q = 1; q < cable_solution_npts(g); q++) {
          m = fmax(m, g->u[q * g->ndim + i]);
          ma = fmax(ma, fabs(g->u[q * g->ndim + i]));
        }
        dmax = fmax(dmax, fabs(mx[i][r] - m) / fmax(fabs(m), 1e-300));
        signed_differs += ma - m > 1e-3 * ma;
      }
      nrows++;
    }
  }
  test_int("MAX theta, MAX theta' columns of every labelled row checked", nrows, sf ? cable_sfile_count(sf) : -1);
  test_le("MAX U columns = max over the stored points of u_i (signed), max rel. error", dmax, REL_TOL);
  snprintf(msg, sizeof msg, "the buckled branch has rows where max u_i < max |u_i| (%d), so the test tells them apart",
           signed_differs);
  test_true(msg, signed_differs > 0);
  cable_bfile_free(bf);
  cable_sfile_free(sf);
  tee_free(&t);
}

/* The independent fixed-width readers on real engine output: each test
 * problem's branch written by cable's writer, then every s-file line and
 * b-file row checked field by field and against what the engine handed out. */
static void layout_of_engine_run(const char *name, const cable_problem *pb, const char *ctext)
{
  cable_constants c;
  cable_names names;
  cable_error err;
  char what[256], path[256];
  int st = cable_constants_parse_string(name, ctext, &c, &names, pb->parnames, pb->npar, &err);
  snprintf(what, sizeof what, "%s: constants parse", name);
  test_int(what, st, 0);
  if (st) return;
  cable_constants_take_problem_dims(&c, pb->ndim, pb->nbc, pb->nint);
  cable_names_fill(&names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  int status = 0, next = 0;
  cable_cont *cc = cable_cont_alloc(pb, &c, &status);
  cable_aufile *w = cable_aufile_open(OUTDIR, name, &c, &names, NULL, &err);
  if (!cc || !w || cable_cont_set_start(cc, NULL) != 0) {
    snprintf(what, sizeof what, "%s: engine and writer", name);
    test_true(what, 0);
    cable_cont_free(cc);
    cable_aufile_abort(w);
    return;
  }
  tee t;
  memset(&t, 0, sizeof t);
  t.out = cable_aufile_sink(w);
  cable_sink sink = {&t, tee_point, tee_solution, tee_diag};
  int rc = cable_cont_run(cc, &sink, 1, 1, &next);
  cable_cont_free(cc);
  st = cable_aufile_close(w, &err);
  snprintf(what, sizeof what, "%s: run ends normally (%d points, %d labelled) and the files close", name, t.n, t.nsol);
  test_true(what, rc > 0 && st == 0 && t.nsol >= 2 && t.n <= 64);
  int bad_lines = 0, nrowpr_ok = 0;
  snprintf(path, sizeof path, OUTDIR "/s.%s", name);
  int blocks = check_s_layout(path, &bad_lines, &nrowpr_ok);
  snprintf(what, sizeof what, "%s: fixed-width s-file reader: one block per stored solution", name);
  test_int(what, blocks, t.nsol);
  snprintf(what, sizeof what, "%s: s-file lines with wrong widths or not ES19.10E3", name);
  test_int(what, bad_lines, 0);
  snprintf(what, sizeof what, "%s: NROWPR = ceil((NDIM+1)/7)*NTPL + ceil(NPAR/7) [+ direction], that many lines%s", name,
           c.iis == 0 ? " (IIS=0: none)" : "");
  test_true(what, nrowpr_ok);
  bscan bs;
  snprintf(path, sizeof path, OUTDIR "/b.%s", name);
  check_b_layout(path, &bs);
  snprintf(what, sizeof what, "%s: fixed-width b-file reader: 1 section, one row per point", name);
  test_true(what, bs.sections == 1 && bs.nrow == t.n);
  snprintf(what, sizeof what, "%s: b-file rows or fields not in the I4,I6,I4,I5,ES19.10E3 layout", name);
  test_int(what, bs.bad, 0);
  /* AUTO's column count: PAR(ICP(1)), L2-NORM, N2 MAX U, the other ICP */
  int n2 = c.nicp > 7 ? 0 : (c.nicp + pb->ndim > 7 ? 7 - c.nicp : pb->ndim), meta = 1;
  double emax = 0;
  for (int r = 0; r < bs.nrow && r < t.n; r++) {
    meta &= bs.br[r] == 1 && bs.pt[r] == t.pt[r] && bs.lab[r] == t.lab[r] && bs.nval[r] == 2 + n2 + c.nicp - 1;
    emax = fmax(emax, fmax(relerr(bs.v[r][0], t.p0[r]), relerr(bs.v[r][1], t.l2[r])));
  }
  snprintf(what, sizeof what, "%s: BR PT LAB of every row as the engine's, %d value columns", name, 2 + n2 + c.nicp - 1);
  test_true(what, meta);
  snprintf(what, sizeof what, "%s: principal parameter and L2-NORM columns vs the engine's, max rel. error", name);
  test_le(what, emax, REL_TOL);
  tee_free(&t);
}

static void test_layout_engine_problems(void)
{
  layout_of_engine_run("bratu", cable_testproblem_bratu(),
                       "IPS = 4, ICP = ['lambda'], NTST = 20, NCOL = 4, JAC = 1, IAD = 3\n"
                       "DS = 0.1, DSMIN = 1e-6, DSMAX = 0.5, NMX = 40, RL1 = 10, ILP = 1, NPR = 10\n");
  layout_of_engine_run("elastica", cable_testproblem_elastica(),
                       "IPS = 4, ICP = ['lambda'], NTST = 30, NCOL = 5, JAC = 1, IAD = 0, ISP = 2, ILP = 0, EPSS = 1e-10\n"
                       "DS = 0.5, DSMIN = 1e-6, DSMAX = 4.0, NMX = 60, RL1 = 50\n");
  layout_of_engine_run("layer", cable_testproblem_layer(),
                       "IPS = 4, ICP = ['p', 'eps'], NTST = 12, NCOL = 3, IAD = 1, JAC = 1, IIS = 2\n"
                       "DS = 0.05, DSMIN = 1e-4, DSMAX = 0.05, NMX = 10, IADS = 0, NPR = 3\n");
  layout_of_engine_run("stiff", cable_testproblem_stiff(),
                       "IPS = 4, ICP = ['k'], NTST = 50, NCOL = 7, JAC = 1, IIS = 0, EPSS = 1e-10\n"
                       "DS = 1.0, DSMIN = 1e-4, DSMAX = 2.0, NMX = 40, UZSTOP = {'k': 60}, UZR = {'k': 50}\n");
}

int main(void)
{
  test_format();
  clean_dir(OUTDIR);

  /* ---- branch 1: NDIM 3, NTST 5, NCOL 4, IIS 3 (direction everywhere) */
  static const char *const parnames[NPAR1] = {"T", "L", NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, "err"};
  static const char *const unames[3] = {"x", "y", NULL};
  cable_constants c;
  cable_constants_init(&c);
  c.ips = 4;
  c.ndim = 3;
  c.ntst = 5;
  c.ncol = 4;
  c.nbc = 3;
  c.nint = 1;        /* NFPR = NBC + NINT - NDIM + 1 = 2 */
  c.npar = NPAR1;
  c.nicp = 3;
  c.icp[0] = 0;
  c.icp[1] = 1;
  c.icp[2] = 5;
  c.nuzr = 2;
  c.uzr[0].par = 0;
  c.uzr[0].value = -2.10752;
  c.uzr[1].par = 0;
  c.uzr[1].value = -3.0;
  c.uzr[1].stop = 1;
  c.nstop = 1;
  c.stop_on[0] = 6;
  c.stop_count[0] = 2;
  snprintf(c.e, sizeof c.e, "synthetic");
  cable_names names;
  cable_names_init(&names);
  cable_names_fill(&names, parnames, NPAR1, unames, 3);
  cable_error err;
  char msg[1024];
  cable_aufile *w = cable_aufile_open(OUTDIR, "syn", &c, &names, NULL, &err);
  test_true("open writer", w != NULL);
  if (!w) return test_summary();
  cable_sink sink = cable_aufile_sink(w);
  const int icp1[3] = {0, 1, 5};
  const int itp1[10] = {9, 0, 0, 6, 0, -4, 0, 4, 0, 9};
  const int lab1[10] = {1, 0, 0, 2, 0, 3, 0, 4, 0, 5};
  expect_row rows1[10];
  cable_solution *keep1[10] = {0};
  int st = emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 10, itp1, lab1, icp1, 3, rows1, keep1);
  test_int("branch 1: every sink callback succeeds", st, 0);
  test_true("nothing under the final names before close", !file_exists(OUTDIR "/b.syn") && !file_exists(OUTDIR "/s.syn"));
  st = cable_aufile_close(w, &err);
  test_int("close writer", st, 0);
  test_true("b.syn, s.syn, d.syn and b.syn.1.csv exist",
            file_exists(OUTDIR "/b.syn") && file_exists(OUTDIR "/s.syn") && file_exists(OUTDIR "/d.syn") &&
                file_exists(OUTDIR "/b.syn.1.csv"));
  test_int("no temporary files left", count_tmp_files(OUTDIR), 0);

  /* ---- branch 2 appended: NDIM 8 (T + 8 numbers wrap to 7 + 2), IIS 0 */
  cable_constants c2 = c;
  c2.ndim = 8;
  c2.ntst = 3;
  c2.ncol = 2;
  c2.nbc = 8;
  c2.nint = 0;
  c2.iis = 0;
  c2.nicp = 1;
  c2.nuzr = 0;
  c2.nstop = 0;
  cable_aufile_options opt;
  cable_aufile_options_init(&opt);
  opt.append = 1;
  w = cable_aufile_open(OUTDIR, "syn", &c2, &names, &opt, &err);
  test_true("open writer for appending", w != NULL);
  if (!w) return test_summary();
  test_int("append sees the last label", cable_aufile_last_label(w), 5);
  test_int("append sees the last branch", cable_aufile_last_branch(w), 1);
  sink = cable_aufile_sink(w);
  const int icp2[1] = {1};
  const int itp2[4] = {9, 5, 0, -9};
  const int lab2[4] = {6, 7, 0, 8};
  expect_row rows2[4];
  cable_solution *keep2[4] = {0};
  st = emit_branch(&sink, 2, 8, 3, 2, NPAR1, 1, 4, itp2, lab2, icp2, 1, rows2, keep2);
  test_int("branch 2: every sink callback succeeds", st, 0);
  test_int("close appending writer", cable_aufile_close(w, &err), 0);

  /* ---- s-file: cable's reader */
  cable_sfile *sf = cable_sfile_read(OUTDIR "/s.syn", &err);
  test_true("read s.syn", sf != NULL);
  if (!sf) {
    printf("  %s\n", cable_error_format(&err, msg, sizeof msg));
    return test_summary();
  }
  test_int("s.syn holds 5 + 3 solutions", cable_sfile_count(sf), 8);
  cable_sfile_take_err_est(sf, ERR_SLOT);
  int k = 0;
  char tag[64];
  for (int p = 0; p < 10; p++)
    if (lab1[p]) {
      snprintf(tag, sizeof tag, "s.syn label %d", lab1[p]);
      const cable_solution *g = cable_sfile_get(sf, k++);
      check_solution(tag, g, keep1[p], 1, ERR_SLOT);
      snprintf(tag, sizeof tag, "s.syn label %d error estimate", lab1[p]);
      test_rel(tag, g->err_est, keep1[p]->err_est, REL_TOL);
    }
  for (int p = 0; p < 4; p++)
    if (lab2[p]) {
      snprintf(tag, sizeof tag, "s.syn label %d", lab2[p]);
      check_solution(tag, cable_sfile_get(sf, k++), keep2[p], 0, ERR_SLOT);
    }

  /* ---- label lookups */
  const cable_solution *q;
  q = cable_sfile_find(sf, "BP1", &err);
  test_int("find 'BP1' -> label 2", q ? q->lab : -1, 2);
  q = cable_sfile_find(sf, "UZ1", &err);
  test_int("find 'UZ1' -> label 3", q ? q->lab : -1, 3);
  q = cable_sfile_find(sf, "EP2", &err);
  test_int("find 'EP2' -> label 5", q ? q->lab : -1, 5);
  q = cable_sfile_find(sf, "EP3", &err);
  test_int("find 'EP3' -> label 6 (second branch)", q ? q->lab : -1, 6);
  q = cable_sfile_find(sf, "LP1", &err);
  test_int("find 'LP1' -> label 7", q ? q->lab : -1, 7);
  q = cable_sfile_find(sf, "MX1", &err);
  test_int("find 'MX1' -> label 8", q ? q->lab : -1, 8);
  q = cable_sfile_find(sf, "RG1", &err);
  test_int("find 'RG1' -> label 4", q ? q->lab : -1, 4);
  q = cable_sfile_find(sf, "-2", &err);
  test_int("find '-2' (second solution) -> label 2", q ? q->lab : -1, 2);
  q = cable_sfile_find(sf, "7", &err);
  test_int("find '7' -> label 7", q ? q->lab : -1, 7);
  q = cable_sfile_find_label(sf, 3);
  test_int("find_label(3)", q ? q->lab : -1, 3);
  q = cable_sfile_find(sf, "BP2", &err);
  test_true("find 'BP2' fails: only one BP", q == NULL && err.status == CABLE_ERR_NOTFOUND);
  printf("  message: %s\n", cable_error_format(&err, msg, sizeof msg));
  q = cable_sfile_find(sf, "XX1", &err);
  test_true("find 'XX1' fails with an input error", q == NULL && err.status == CABLE_ERR_INPUT);
  q = cable_sfile_find(sf, "-9", &err);
  test_true("find '-9' fails: 8 solutions", q == NULL && err.status == CABLE_ERR_NOTFOUND);
  q = cable_sfile_find(sf, "99", &err);
  test_true("find '99' fails", q == NULL && err.status == CABLE_ERR_NOTFOUND);
  cable_constants cr = c;
  snprintf(cr.irs_name, sizeof cr.irs_name, "UZ1");
  cr.irs = 1;
  test_int("resolve IRS='UZ1'", cable_sfile_resolve_irs(sf, &cr, &err), 0);
  test_true("  IRS becomes label 3, name cleared", cr.irs == 3 && cr.irs_name[0] == '\0');
  cr.irs = -4;
  test_int("resolve IRS=-4", cable_sfile_resolve_irs(sf, &cr, &err), 0);
  test_int("  IRS=-4 is label 4", cr.irs, 4);
  cable_sfile_free(sf);

  /* ---- s-file: independent fixed-width layout check */
  int bad_lines, nrowpr_ok;
  int blocks = check_s_layout(OUTDIR "/s.syn", &bad_lines, &nrowpr_ok);
  test_int("layout reader: 8 solution blocks", blocks, 8);
  test_int("layout reader: lines with wrong widths or number format", bad_lines, 0);
  test_true("layout reader: NROWPR = ceil((NDIM+1)/7)*NTPL + ceil(NPAR/7) [+ direction] and that many lines",
            nrowpr_ok);

  /* ---- b-file: independent fixed-width reader */
  bscan bs;
  check_b_layout(OUTDIR "/b.syn", &bs);
  test_int("b.syn: 2 header sections", bs.sections, 2);
  test_int("b.syn: 14 rows", bs.nrow, 14);
  test_int("b.syn: rows or fields not in ES19.10E3 layout", bs.bad, 0);
  double emax = 0;
  int meta_ok = 1;
  for (int r = 0; r < bs.nrow && r < 14; r++) {
    const expect_row *x = r < 10 ? &rows1[r] : &rows2[r - 10];
    meta_ok &= bs.br[r] == (r < 10 ? 1 : 2) && bs.pt[r] == x->pt && bs.ty[r] == x->itp && bs.lab[r] == x->lab &&
               bs.nval[r] == x->nval;
    for (int j = 0; j < x->nval && j < bs.nval[r]; j++) emax = fmax(emax, relerr(bs.v[r][j], x->vals[j]));
  }
  test_true("b.syn: BR PT TY LAB and column counts of every row", meta_ok);
  test_le("b.syn: every value, max rel. error", emax, REL_TOL);
  const char *want_head1[] = {"T", "L2-NORM", "MAX x", "MAX y", "MAX U(3)", "L", "PAR(6)"};
  int head_ok = 1;
  char hf[64];
  for (int j = 0; j < 7; j++) {
    heading_field(bs.heading[0], j, hf);
    if (strcmp(hf, want_head1[j]) != 0) {
      printf("  heading %d: got '%s' want '%s'\n", j, hf, want_head1[j]);
      head_ok = 0;
    }
  }
  test_true("b.syn section 1 headings: T L2-NORM 'MAX x' 'MAX y' 'MAX U(3)' L PAR(6)", head_ok);
  test_true("b.syn headings line starts '   0    PT  TY  LAB '", strncmp(bs.heading[0], "   0    PT  TY  LAB ", 20) == 0);
  /* AUTO's n_umax rule: ICP of 1 and NDIM 8 -> 6 MAX U columns */
  test_int("b.syn section 2: 1 + 1 + 6 MAX U columns", bs.nval[10], 8);

  /* ---- b-file: cable's reader */
  cable_bfile *bf = cable_bfile_read(OUTDIR "/b.syn", &err);
  test_true("cable_bfile_read b.syn", bf != NULL);
  if (bf) {
    test_int("  2 branches", bf->nbranch, 2);
    test_int("  branch 1: 10 rows, 7 columns", bf->branch[0].nrow * 100 + bf->branch[0].ncol, 1007);
    const double *col = cable_bfile_column(&bf->branch[0], "L2-NORM");
    const double *cpar = cable_bfile_column(&bf->branch[0], "PAR(6)");
    test_true("  columns found by heading (L2-NORM, PAR(6))", col && cpar);
    emax = 0;
    for (int r = 0; col && cpar && r < 10; r++) {
      emax = fmax(emax, relerr(col[r], rows1[r].vals[1]));
      emax = fmax(emax, relerr(cpar[r], rows1[r].vals[6]));
    }
    test_le("  column values, max rel. error", emax, REL_TOL);
    test_true("  branch 2 first heading is 'L'", strcmp(bf->branch[1].colname[0], "L") == 0);
    int tyok = 1;
    for (int r = 0; r < 10; r++) tyok &= bf->branch[0].ty[r] == itp1[r] && bf->branch[0].lab[r] == lab1[r];
    test_true("  TY and LAB columns", tyok);
    cable_bfile_free(bf);
  }

  /* ---- b-file header: AUTO's STHD lines parse back */
  long blen;
  char *btext = slurp(OUTDIR "/b.syn", &blen);
  test_true("b.syn header: first line '0 RL0 RL1 A0 A1' as Fortran's ES12.4 writes 1e300 (no E)",
            btext && strncmp(btext, "   0  -1.0000+300  1.0000+300 -1.0000+300  1.0000+300\n", 54) == 0);
  test_true("b.syn header: EPSL line in AUTO's A8,ES11.4 form",
            btext && strstr(btext, "   0   EPSL= 1.0000E-07  EPSU = 1.0000E-07  EPSS = 1.0000E-05\n"));
  test_true("b.syn header: NDIM line", btext && strstr(btext, "   0   NDIM=   3   IPS =   4   IRS =   0   ILP =   1\n"));
  test_true("b.syn header: UZR and UZSTOP dicts by name",
            btext && strstr(btext, "   0   UZR = {'T': -2.1075200000E+00}\n") &&
                strstr(btext, "   0   UZSTOP = {'T': -3}\n"));
  test_true("b.syn header: parnames and unames", btext && strstr(btext, "   0   parnames = {1: 'T', 2: 'L', 12: 'err'}\n") &&
                                                      strstr(btext, "   0   unames   = {1: 'x', 2: 'y'}\n"));
  test_true("b.syn header: STOP list", btext && strstr(btext, "   0   STOP=['BP2']\n"));
  test_true("b.syn header: user-specified and active parameters",
            btext && strstr(btext, "   0   User-specified parameters:       'T' 'L'   6\n") &&
                strstr(btext, "   0   Active continuation parameters:  'T' 'L'\n"));
  free(btext);

  /* ---- d-file */
  char *dtext = slurp(OUTDIR "/d.syn", NULL);
  test_true("d.syn: blocks divided by AUTO's '=' line", dtext && strstr(dtext, "===============================================\n"));
  test_true("d.syn: diagnostics lines kept", dtext && strstr(dtext, " Newton iteration 1: residual 1.000e-09\n"));
  test_true("d.syn: labelled point line with TY name", dtext && strstr(dtext, "   1     4  BP    2"));
  test_true("d.syn: error estimate of label 2 noted", dtext && strstr(dtext, "Solution label 2 (BP) stored") &&
                                                          strstr(dtext, "error estimate 1.6500E-08"));
  free(dtext);

  /* ---- CSV */
  char *csv = slurp(OUTDIR "/b.syn.1.csv", NULL);
  test_true("b.syn.1.csv header", csv && strncmp(csv, "BR,PT,TY,LAB,T,L2NORM,MAX_x,MAX_y,MAX_U(3),L,PAR(6),NEWTON,DS,ERR_EST\n",
                                                 strlen("BR,PT,TY,LAB,T,L2NORM,MAX_x,MAX_y,MAX_U(3),L,PAR(6),NEWTON,DS,ERR_EST\n")) == 0);
  if (csv) {
    /* row 4 is the BP: values at full precision */
    char *line = csv;
    for (int i = 0; i < 4 && line; i++) line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL;
    int br = 0, pt = 0, lab = 0;
    char ty[8] = "";
    double v[7] = {0};
    int n = line ? sscanf(line, "%d,%d,%2[A-Z],%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &br, &pt, ty, &lab, &v[0], &v[1], &v[2],
                          &v[3], &v[4], &v[5], &v[6])
                 : 0;
    int exact = n == 11 && br == 1 && pt == 4 && strcmp(ty, "BP") == 0 && lab == 2;
    for (int j = 0; j < 7 && exact; j++) exact = v[j] == rows1[3].vals[j];
    test_true("b.syn.1.csv: BP row 1,4,BP,2 with exact (%.17g) values", exact);
  }
  free(csv);
  test_true("b.syn.2.csv for the appended branch", file_exists(OUTDIR "/b.syn.2.csv"));

  /* ---- truncated and malformed s-files */
  {
    long n;
    char *s = slurp(OUTDIR "/s.syn", &n);
    /* cut inside the second block: keep the first block and 5 lines of the second */
    int lines = 0, keep_lines = 0;
    long cut = 0;
    FILE *hf2 = fopen(OUTDIR "/s.syn", "r");
    char l[4096];
    int first_nrowpr = 0;
    if (hf2 && fgets(l, sizeof l, hf2)) first_nrowpr = (int)fixed_int(l, 50, 8);
    if (hf2) fclose(hf2);
    keep_lines = 1 + first_nrowpr + 6;
    for (long i = 0; s && i < n; i++)
      if (s[i] == '\n' && ++lines == keep_lines) {
        cut = i + 1;
        break;
      }
    FILE *t = fopen(OUTDIR "/s.truncated", "w");
    if (t && s) fwrite(s, 1, (size_t)cut, t);
    if (t) fclose(t);
    free(s);
    cable_sfile *bad = cable_sfile_read(OUTDIR "/s.truncated", &err);
    cable_error_format(&err, msg, sizeof msg);
    printf("  message: %s\n", msg);
    test_true("truncated s-file: NULL", bad == NULL);
    test_int("truncated s-file: error line is the last line of the file", err.line, keep_lines);
    test_true("truncated s-file: message names the file, the label and 'truncated'",
              strstr(msg, "s.truncated:") && strstr(msg, "label 2") && strstr(msg, "truncated"));
    cable_sfile_free(bad);
  }
  {
    cable_sfile *bad = cable_sfile_read("tests/data/s.badnumber", &err);
    cable_error_format(&err, msg, sizeof msg);
    printf("  message: %s\n", msg);
    test_true("s-file with a bad number: NULL, line 3, 'bad number'",
              bad == NULL && err.line == 3 && strstr(msg, "tests/data/s.badnumber:3:") && strstr(msg, "bad number"));
    cable_sfile_free(bad);
    bad = cable_sfile_read("tests/data/s.badheader", &err);
    cable_error_format(&err, msg, sizeof msg);
    printf("  message: %s\n", msg);
    test_true("s-file with a 9-integer header: NULL, line 1", bad == NULL && err.line == 1 && strstr(msg, "header"));
    cable_sfile_free(bad);
    bad = cable_sfile_read("tests/data/s.missing_file", &err);
    test_true("missing s-file: I/O error naming the file", bad == NULL && err.status == CABLE_ERR_IO &&
                                                              strcmp(err.file, "tests/data/s.missing_file") == 0);
  }

  /* ---- AUTO-07p's own layout (two-digit exponents, 1.0-100 form, 12-int header) */
  {
    cable_sfile *a = cable_sfile_read("tests/data/s.auto07p", &err);
    test_true("read an s-file in AUTO-07p's own ES19.10 layout", a != NULL);
    if (!a) printf("  %s\n", cable_error_format(&err, msg, sizeof msg));
    if (a) {
      test_int("  two solutions", cable_sfile_count(a), 2);
      const cable_solution *s1 = cable_sfile_get(a, 0), *s2 = cable_sfile_get(a, 1);
      test_true("  first: label 1, EP, NDIM 2, NTST 1, NCOL 2, with direction",
                s1->lab == 1 && s1->itp == 9 && s1->ndim == 2 && s1->ntst == 1 && s1->ncol == 2 && s1->icp[0] == 0 &&
                    s1->icp[1] == 10);
      test_rel("  u_2(t=0.5) = -2.5e-103 (written 2.5000000000-103)", s1->u[1 * 2 + 1], -2.5e-103, 1e-15);
      test_rel("  PAR(11) = 6.2831853072", s1->par[10], 6.2831853072, 1e-15);
      test_rel("  udot_1(t=1) = 0.5", s1->udot[2 * 2 + 0], 0.5, 1e-15);
      test_true("  second: label 2, BP (12-integer header, no direction)", s2->lab == 2 && s2->itp == 6 && s2->icp[0] == -1);
      test_rel("  second: PAR(1) = 1.5", s2->par[0], 1.5, 1e-15);
      cable_sfile_free(a);
    }
    cable_bfile *ab = cable_bfile_read("tests/data/b.auto07p", &err);
    test_true("read a b-file in AUTO-07p's own layout", ab != NULL);
    if (!ab) printf("  %s\n", cable_error_format(&err, msg, sizeof msg));
    if (ab) {
      test_int("  two sections (header-less second branch starts at PT 1)", ab->nbranch, 2);
      test_true("  headings PAR(1) L2-NORM 'MAX U(1)' PERIOD", ab->branch[0].ncol == 4 &&
                                                                  strcmp(ab->branch[0].colname[0], "PAR(1)") == 0 &&
                                                                  strcmp(ab->branch[0].colname[1], "L2-NORM") == 0 &&
                                                                  strcmp(ab->branch[0].colname[2], "MAX U(1)") == 0 &&
                                                                  strcmp(ab->branch[0].colname[3], "PERIOD") == 0);
      test_true("  second section inherits the headings", strcmp(ab->branch[1].colname[3], "PERIOD") == 0);
      const double *per = cable_bfile_column(&ab->branch[0], "PERIOD");
      test_rel("  PERIOD of row 3 (written 1.2345678901+100)", per ? per[2] : 0, 1.2345678901e100, 1e-15);
      cable_bfile_free(ab);
    }
  }

  /* ---- atomic behaviour */
  {
    long n0, n1;
    char *before_b = slurp(OUTDIR "/b.syn", &n0);
    char *before_s = slurp(OUTDIR "/s.syn", &n1);
    w = cable_aufile_open(OUTDIR, "syn", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    expect_row rr[10];
    emit_branch(&sink, 5, 3, 5, 4, NPAR1, 2, 3, itp1, lab1, icp1, 3, rr, NULL);
    cable_aufile_abort(w);
    long m0, m1;
    char *after_b = slurp(OUTDIR "/b.syn", &m0);
    char *after_s = slurp(OUTDIR "/s.syn", &m1);
    test_true("aborted run: b.syn and s.syn keep their previous contents",
              before_b && after_b && m0 == n0 && memcmp(before_b, after_b, (size_t)n0) == 0 && before_s && after_s &&
                  m1 == n1 && memcmp(before_s, after_s, (size_t)n1) == 0);
    test_int("aborted run: no temporary files left", count_tmp_files(OUTDIR), 0);
    free(before_b);
    free(before_s);
    free(after_b);
    free(after_s);

    w = cable_aufile_open(OUTDIR, "fresh", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 3, itp1, lab1, icp1, 3, rr, NULL);
    cable_aufile_abort(w);
    test_true("aborted first run: no b.fresh, s.fresh, d.fresh",
              !file_exists(OUTDIR "/b.fresh") && !file_exists(OUTDIR "/s.fresh") && !file_exists(OUTDIR "/d.fresh") &&
                  !file_exists(OUTDIR "/b.fresh.1.csv"));

    /* a checkpoint publishes complete files; the run then fails and is aborted */
    w = cable_aufile_open(OUTDIR, "chk", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 4, itp1, lab1, icp1, 3, rr, NULL);
    test_int("checkpoint", cable_aufile_checkpoint(w, &err), 0);
    emit_branch(&sink, 2, 3, 5, 4, NPAR1, 2, 3, itp1, lab1, icp1, 3, rr, NULL);
    cable_aufile_abort(w);
    cable_sfile *ck = cable_sfile_read(OUTDIR "/s.chk", &err);
    test_int("after checkpoint + abort: s.chk holds the 2 checkpointed solutions", ck ? cable_sfile_count(ck) : -1, 2);
    cable_sfile_free(ck);
    cable_bfile *ckb = cable_bfile_read(OUTDIR "/b.chk", &err);
    test_int("after checkpoint + abort: b.chk holds the 4 checkpointed rows",
             ckb && ckb->nbranch == 1 ? ckb->branch[0].nrow : -1, 4);
    cable_bfile_free(ckb);
    test_int("after checkpoint + abort: no temporary files left", count_tmp_files(OUTDIR), 0);

    /* commit failure: the target is a directory */
    mkdir(OUTDIR "/b.blocked", 0755);
    cable_atomic_file *af = cable_atomic_open(OUTDIR "/b.blocked", 0, &err);
    test_true("atomic open next to a directory", af != NULL);
    if (af) fputs("some text\n", cable_atomic_stream(af));
    st = cable_atomic_commit(af, &err);
    printf("  message: %s\n", cable_error_format(&err, msg, sizeof msg));
    test_true("commit onto a directory fails with an I/O error", st == CABLE_ERR_IO);
    test_int("failed commit leaves no temporary file", count_tmp_files(OUTDIR), 0);
    rmdir(OUTDIR "/b.blocked");
    af = cable_atomic_open(OUTDIR "/no/such/dir/b.x", 0, &err);
    test_true("atomic open in a missing directory fails, creating nothing", af == NULL && err.status == CABLE_ERR_IO &&
                                                                              !file_exists(OUTDIR "/no"));
  }

  /* ---- label mismatch is reported at close */
  {
    w = cable_aufile_open(OUTDIR, "mismatch", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    cable_solution *s = make_solution(3, 5, 4, NPAR1, 2, 0);
    double umax[3] = {1, 1, 1};
    cable_point pt = {0};
    pt.ibr = 1;
    pt.pt = 1;
    pt.itp = 9;
    pt.lab = 1;
    pt.ndim = 3;
    pt.npar = NPAR1;
    pt.nicp = 3;
    pt.icp = icp1;
    pt.par = s->par;
    pt.umax = umax;
    sink.point(sink.ctx, &pt);   /* labelled row, but no solution follows */
    pt.pt = 2;
    pt.lab = 0;
    pt.itp = 0;
    st = sink.solution(sink.ctx, &pt, s);
    test_true("solution for an unlabelled point is refused", st < 0);
    st = cable_aufile_close(w, &err);
    printf("  message: %s\n", cable_error_format(&err, msg, sizeof msg));
    test_true("close reports the first failure", st < 0 && strstr(msg, "unlabelled point"));
    w = cable_aufile_open(OUTDIR, "mismatch2", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    pt.pt = 1;
    pt.lab = 1;
    pt.itp = 9;
    sink.point(sink.ctx, &pt);
    st = cable_aufile_close(w, &err);
    printf("  message: %s\n", cable_error_format(&err, msg, sizeof msg));
    test_true("close: label 1 has a b-row but no s-file solution", st < 0 && strstr(msg, "label 1 has a b-file row"));
    cable_solution_free(s);
    test_true("failed label checks publish nothing: no b./s./d.mismatch, b./s./d.mismatch2",
              !file_exists(OUTDIR "/b.mismatch") && !file_exists(OUTDIR "/s.mismatch") &&
                  !file_exists(OUTDIR "/d.mismatch") && !file_exists(OUTDIR "/b.mismatch2") &&
                  !file_exists(OUTDIR "/s.mismatch2") && !file_exists(OUTDIR "/d.mismatch2") &&
                  !file_exists(OUTDIR "/b.mismatch.1.csv"));
    test_int("  and leave no temporary files", count_tmp_files(OUTDIR), 0);
  }

  /* ---- commit order: s before b; a failed s commit publishes nothing after it */
  {
    expect_row rr[10];
    mkdir(OUTDIR "/s.order", 0755);   /* the s-file cannot be renamed into place */
    FILE *old = fopen(OUTDIR "/b.order", "w");
    if (old) {
      fputs("old b-file\n", old);
      fclose(old);
    }
    w = cable_aufile_open(OUTDIR, "order", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 4, itp1, lab1, icp1, 3, rr, NULL);
    st = cable_aufile_close(w, &err);
    printf("  message: %s\n", cable_error_format(&err, msg, sizeof msg));
    char *b = slurp(OUTDIR "/b.order", NULL);
    test_true("s.NAME cannot be committed: close fails naming s.order", st == CABLE_ERR_IO && strstr(msg, "s.order"));
    test_true("  b.order keeps its old contents (s is committed first)", b && strcmp(b, "old b-file\n") == 0);
    test_true("  no d.order, no CSV", !file_exists(OUTDIR "/d.order") && !file_exists(OUTDIR "/b.order.1.csv"));
    test_int("  no temporary files left", count_tmp_files(OUTDIR), 0);
    free(b);
    rmdir(OUTDIR "/s.order");
    mkdir(OUTDIR "/b.order2", 0755);
    w = cable_aufile_open(OUTDIR, "order2", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 4, itp1, lab1, icp1, 3, rr, NULL);
    st = cable_aufile_close(w, &err);
    cable_sfile *s2 = cable_sfile_read(OUTDIR "/s.order2", &err);
    test_true("b.NAME cannot be committed: close fails, s.order2 (committed first) is complete",
              st == CABLE_ERR_IO && s2 && cable_sfile_count(s2) == 2);
    cable_sfile_free(s2);
    test_int("  no temporary files left", count_tmp_files(OUTDIR), 0);
    rmdir(OUTDIR "/b.order2");
  }

  /* ---- AUTO's ap appends as it is: a label the file already has is kept
     (runs number their labels from their own restart data, so labels repeat
     across runs; AUTO's merge joins two runs from one start without
     relabelling, so they can repeat within one branch too) */
  {
    cable_aufile_options ap;
    cable_aufile_options_init(&ap);
    ap.append = 1;
    cable_sfile *s0 = cable_sfile_read(OUTDIR "/s.syn", &err);
    int n0 = cable_sfile_count(s0);
    const cable_solution *old3 = cable_sfile_find_label(s0, 3);
    double old3par = old3 ? old3->par[0] : -1e300;
    cable_sfile_free(s0);
    w = cable_aufile_open(OUTDIR, "syn", &c, &names, &ap, &err);
    sink = cable_aufile_sink(w);
    const int lab3[3] = {9, 3, 10};   /* s.syn already holds labels 1..8 */
    expect_row rr[3];
    st = emit_branch(&sink, 3, 3, 5, 4, NPAR1, 2, 3, itp1, lab3, icp1, 3, rr, NULL);
    test_int("appending label 3 to s.syn (labels 1-8) is accepted, as AUTO's ap", st, 0);
    st = cable_aufile_close(w, &err);
    test_int("  close succeeds", st, 0);
    cable_sfile *s1 = cable_sfile_read(OUTDIR "/s.syn", &err);
    test_int("  s.syn has the three new solutions after the old ones", cable_sfile_count(s1), n0 + 3);
    int twice = 0;
    for (int i = 0; i < cable_sfile_count(s1); i++) twice += cable_sfile_get(s1, i)->lab == 3;
    test_int("  label 3 is in s.syn twice", twice, 2);
    const cable_solution *f3 = cable_sfile_find_label(s1, 3);
    test_true("  label 3 finds the first one, the old solution (AUTO's FINDLB)",
              f3 && f3 == cable_sfile_get(s1, 2) && f3->par[0] == old3par && f3->ibr != 3);
    cable_sfile_free(s1);
    w = cable_aufile_open(OUTDIR, "dup", &c, &names, NULL, &err);
    sink = cable_aufile_sink(w);
    const int labd[3] = {1, 2, 1};
    st = emit_branch(&sink, 1, 3, 5, 4, NPAR1, 2, 3, itp1, labd, icp1, 3, rr, NULL);
    test_int("one branch with label 1 twice is written, as AUTO writes it", st, 0);
    st = cable_aufile_close(w, &err);
    cable_sfile *sd = cable_sfile_read(OUTDIR "/s.dup", &err);
    test_true("  s.dup holds labels 1, 2, 1 in order", st == 0 && sd && cable_sfile_count(sd) == 3 &&
              cable_sfile_get(sd, 0)->lab == 1 && cable_sfile_get(sd, 1)->lab == 2 && cable_sfile_get(sd, 2)->lab == 1);
    cable_sfile_free(sd);
  }

  for (int p = 0; p < 10; p++) cable_solution_free(keep1[p]);
  for (int p = 0; p < 4; p++) cable_solution_free(keep2[p]);
  test_with_engine();
  test_layout_engine_problems();
  return test_summary();
}
