/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Writer of b./s./d. files in AUTO-07p's layout (io.f90 STHD/HEADNG/WRLINE,
 * bvp.f90 WRTBV8/WRTBV9), behind the engine's cable_sink.  Learned from
 * AUTO's formats, written afresh; differences are listed in
 * doc/output-formats.md. */
#include "cable/cable_aufile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomic_file.h"
#include "aufile_live.h"
#include "cable/cable_status.h"
#include "constants_check.h"

#define BCOL 19            /* b-file and s-file number width: ES19.10E3 */
#define BDIG 10            /* digits after the point: 11 significant digits */
#define BEXP 3             /* exponent digits: E+003 always has its 'E' */
#define SPER_LINE 7        /* s-file numbers per line (AUTO's 4X,7ES19.10) */
#define ICP_PER_LINE 20    /* s-file free-parameter indices per line (20I5) */
#define SCREEN_MAX 7       /* AUTO prints at most 7 parameter + MAX U columns */
#define DSEP "===============================================\n"  /* parseD block divider */
#define MAX_SECTIONS 4096  /* branch sections per writer session (CSV files) */

struct cable_aufile {
  char bpath[4096], spath[4096], dpath[4096], csvbase[4096];
  cable_constants c;
  cable_names names;
  cable_aufile_options opt;
  cable_atomic_file *b, *s, *d;
  cable_atomic_file **csv;     /* one per section written in this session */
  int ncsv, csvcap;
  int nsections;               /* sections in the b-file incl. those appended to */
  /* current section */
  int in_section, sec_ibr, sec_ndim, sec_nicp, sec_icp[CABLE_MAX_ICP], sec_n2;
  int sec_npcol, sec_pcol[CABLE_MAX_ICP];   /* the parameter columns after MAX U: icp[1..]
                                               without an extended problem's own slots */
  int last_lab_point;          /* label of the last point (for the solution that follows) */
  /* d-file: 1 once the file has content (the next point's block needs a divider) */
  int d_started;
  /* label bookkeeping: labels with a b-row / with an s-block */
  int *blab, nblab, blabcap;
  int *slab, nslab, slabcap;
  int last_label, last_branch;
  double *parbuf;
  int parcap;
  cable_error err;             /* first failure */
  int failed;
};

/* ---------------------------------------------------------------- numbers */

char *cable_aufile_format_es(char *buf, double x, int width, int digits, int expdigits)
{
  if (!buf) return NULL;
  char body[128];
  if (digits < 0) digits = 0;
  if (digits > 30) digits = 30;
  if (expdigits < 1) expdigits = 1;
  if (expdigits > 4) expdigits = 4;
  if (!isfinite(x)) {
    snprintf(body, sizeof body, "%s", isnan(x) ? "NaN" : (x > 0 ? "Infinity" : "-Infinity"));
  } else {
    char tmp[64];
    snprintf(tmp, sizeof tmp, "%.*E", digits, x);
    char *e = strchr(tmp, 'E');
    int ex = abs(atoi(e + 2)) % 10000;
    char sign = e[1];
    *e = '\0';
    snprintf(body, sizeof body, "%.40sE%c%0*d", tmp, sign, expdigits, ex);
  }
  snprintf(buf, (size_t)width + 8, "%*s", width, body);
  return buf;
}

/* Diagnostics (d-file) numbers: two exponent digits, three when needed. */
static char *fmt_es2(char *buf, double x, int width, int digits)
{
  return cable_aufile_format_es(buf, x, width, digits, 2);
}

/* b-file header numbers exactly as AUTO's Fortran writes ESw.d without Ee:
 * E+dd, and for three-digit exponents the 'E' gives way to the third digit
 * (1.0000+300), which keeps the field width and a separating blank;
 * AUTO's readers (parseB.AUTOatof, Fortran list input) accept it. */
static char *header_es(char *buf, double x, int width, int digits)
{
  cable_aufile_format_es(buf, x, width, digits, 2);
  char *e = strchr(buf, 'E');
  if (e && strlen(e) == 5) {     /* "E+300": drop the E, shift right by one */
    memmove(buf + 1, buf, (size_t)(e - buf));
    buf[0] = ' ';
  }
  return buf;
}

static const char *trim(const char *s)
{
  while (*s == ' ') s++;
  return s;
}

/* ---------------------------------------------------------------- errors */

static int w_fail(cable_aufile *w, int status, const char *path, const char *fmt, ...)
  __attribute__((format(printf, 4, 5)));
static int w_fail(cable_aufile *w, int status, const char *path, const char *fmt, ...)
{
  if (!w->failed) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cable_error_set(&w->err, status, path, 0, "", "%s", msg);
    w->failed = 1;
  }
  return status;
}

static int w_check_stream(cable_aufile *w, cable_atomic_file *af)
{
  if (ferror(cable_atomic_stream(af)))
    return w_fail(w, CABLE_ERR_IO, cable_atomic_path(af), "write error: %s", strerror(errno));
  return 0;
}

static int int_push(int **a, int *n, int *cap, int v)
{
  if (*n == *cap) {
    int nc = *cap ? 2 * *cap : 64;
    int *p = realloc(*a, (size_t)nc * sizeof *p);
    if (!p) return -1;
    *a = p;
    *cap = nc;
  }
  (*a)[(*n)++] = v;
  return 0;
}

/* ---------------------------------------------------------------- names */

/* Column heading as AUTO's WRITECOL: `text` placed at 1-based position pos
 * of a 19-character field (pos -1: centred the AUTO way). */
static void col_heading(char out[BCOL + 1], int pos, const char *text)
{
  memset(out, ' ', BCOL);
  out[BCOL] = '\0';
  int len = (int)strlen(text);
  if (pos == -1) {
    pos = 7 - (len - 1) / 2;
    if (pos < 2) pos = 2;
  }
  for (int k = 0; k < len && pos - 1 + k < BCOL; k++) out[pos - 1 + k] = text[k];
}

static void par_heading(const cable_aufile *w, int idx, char out[BCOL + 1])
{
  char t[64];
  if (idx >= 0 && idx < CABLE_NAMES_MAX && w->names.par[idx][0]) {
    col_heading(out, -1, w->names.par[idx]);
  } else {
    snprintf(t, sizeof t, "PAR(%d)", idx + 1);
    col_heading(out, 4, t);
  }
}

/* "MAX U(i)" (what = "MAX"), or "MIN", "INTEGRAL", "L2-NORM" of component i. */
static void ucol_heading(const cable_aufile *w, const char *what, int i, char out[BCOL + 1])
{
  char t[64];
  if (i < CABLE_NAMES_MAX && w->names.u[i][0]) {
    snprintf(t, sizeof t, "%s %s", what, w->names.u[i]);
    col_heading(out, -1, t);
  } else {
    snprintf(t, sizeof t, "%s U(%d)", what, i + 1);
    col_heading(out, 4, t);
  }
}

static void umax_heading(const cable_aufile *w, int i, char out[BCOL + 1])
{
  ucol_heading(w, "MAX", i, out);
}

/* The heading of IPLT's measure, as AUTO writes it. */
static void iplt_heading(const cable_aufile *w, char out[BCOL + 1])
{
  int ip = w->c.iplt, nd = w->c.ndim;
  if (ip == 0 || nd <= 0) col_heading(out, 4, "L2-NORM");
  else if (ip < 0) ucol_heading(w, "MIN", -ip - 1, out);
  else if (ip <= nd) ucol_heading(w, "MAX", ip - 1, out);
  else if (ip <= 2 * nd) ucol_heading(w, "INTEGRAL", ip - nd - 1, out);
  else ucol_heading(w, "L2-NORM", ip - 2 * nd - 1, out);
}

/* Number of MAX U columns, as AUTO's WRLINE: at most 7 printed columns. */
static int n_umax(int nicp, int ndim)
{
  if (nicp > SCREEN_MAX) return 0;
  if (nicp + ndim > SCREEN_MAX) return SCREEN_MAX - nicp;
  return ndim;
}

/* Heading of value column j of the current section (0-based). */
static void section_heading(const cable_aufile *w, int j, char out[BCOL + 1])
{
  int n2 = w->sec_n2;
  if (j == 0) {
    par_heading(w, w->sec_icp[0], out);
  } else if (j == 1) {
    iplt_heading(w, out);
  } else if (j < 2 + n2) {
    umax_heading(w, j - 2, out);
  } else {
    par_heading(w, w->sec_pcol[j - 2 - n2], out);
  }
}

static int section_ncol(const cable_aufile *w)
{
  return 2 + w->sec_n2 + w->sec_npcol;
}

/* A name as a quoted string both AUTO's parseC and cable's parser read:
 * 'T'; "theta'" when the name holds a single quote (Python's repr does the
 * same); doubled quotes when it holds both kinds. */
static void put_name(FILE *f, const char *name)
{
  if (!strchr(name, '\'')) {
    fprintf(f, "'%s'", name);
  } else if (!strchr(name, '"')) {
    fprintf(f, "\"%s\"", name);
  } else {
    fputc('\'', f);
    for (; *name; name++) {
      if (*name == '\'') fputc('\'', f);
      fputc(*name, f);
    }
    fputc('\'', f);
  }
}

static void quoted_par(const cable_aufile *w, FILE *f, int idx)
{
  if (idx >= 0 && idx < CABLE_NAMES_MAX && w->names.par[idx][0]) put_name(f, w->names.par[idx]);
  else fprintf(f, "%d", idx + 1);
}

/* A number in a header dict: integral values as integers, others ES19.10. */
static void dict_number(FILE *f, double v)
{
  char b[64];
  if (v == floor(v) && fabs(v) < 1e15) fprintf(f, "%.0f", v);
  else fputs(trim(header_es(b, v, 19, 10)), f);
}

/* ---------------------------------------------------------------- b-file header */

static void write_uzr_dict(const cable_aufile *w, FILE *f, const char *label, int stop)
{
  const cable_constants *c = &w->c;
  int any = 0;
  for (int k = 0; k < c->nuzr; k++) any |= (c->uzr[k].stop == stop);
  if (!any) return;
  fprintf(f, "   0   %s = {", label);
  int first = 1;
  for (int k = 0; k < c->nuzr; k++) {
    if (c->uzr[k].stop != stop) continue;
    int seen = 0;
    for (int j = 0; j < k; j++) seen |= (c->uzr[j].stop == stop && c->uzr[j].par == c->uzr[k].par);
    if (seen) continue;
    int count = 0;
    for (int j = k; j < c->nuzr; j++) count += (c->uzr[j].stop == stop && c->uzr[j].par == c->uzr[k].par);
    if (!first) fputs(", ", f);
    first = 0;
    quoted_par(w, f, c->uzr[k].par);
    fputs(": ", f);
    if (count > 1) fputc('[', f);
    int m = 0;
    for (int j = k; j < c->nuzr; j++) {
      if (c->uzr[j].stop != stop || c->uzr[j].par != c->uzr[k].par) continue;
      if (m++) fputs(", ", f);
      dict_number(f, c->uzr[j].value);
    }
    if (count > 1) fputc(']', f);
  }
  fputs("}\n", f);
}

static void write_names_dict(FILE *f, const char *label, char tab[][CABLE_NAME_LEN])
{
  int any = 0;
  for (int k = 0; k < CABLE_NAMES_MAX; k++) any |= tab[k][0] != '\0';
  if (!any) return;
  fprintf(f, "   0   %s = {", label);
  int first = 1;
  for (int k = 0; k < CABLE_NAMES_MAX; k++) {
    if (!tab[k][0]) continue;
    fprintf(f, "%s%d: ", first ? "" : ", ", k + 1);
    put_name(f, tab[k]);
    first = 0;
  }
  fputs("}\n", f);
}

/* Free parameters of an IPS=4 run: NBC + NINT - NDIM + 1 (AUTO's count). */
static int n_free(const cable_aufile *w, int ndim, int nicp)
{
  int nfpr = w->c.nbc + w->c.nint - ndim + 1;
  if (nfpr < 1) nfpr = 1;
  if (nfpr > nicp) nfpr = nicp;
  return nfpr;
}

static void write_b_header(cable_aufile *w, const cable_point *pt)
{
  FILE *f = cable_atomic_stream(w->b);
  const cable_constants *c = &w->c;
  char b1[64], b2[64], b3[64], b4[64];
  int ndim = c->ndim > 0 ? c->ndim : pt->ndim;
  fprintf(f, "%4d %s%s%s%s\n", 0, header_es(b1, c->rl0, 12, 4), header_es(b2, c->rl1, 12, 4),
          header_es(b3, c->a0, 12, 4), header_es(b4, c->a1, 12, 4));
  fprintf(f, "   0%8s%s%8s%s%8s%s\n", "EPSL=", header_es(b1, c->epsl, 11, 4), "EPSU =",
          header_es(b2, c->epsu, 11, 4), "EPSS =", header_es(b3, c->epss, 11, 4));
  fprintf(f, "   0%8s%s%8s%s%8s%s\n", "DS  =", header_es(b1, c->ds, 11, 4), "DSMIN=",
          header_es(b2, c->dsmin, 11, 4), "DSMAX=", header_es(b3, c->dsmax, 11, 4));
  fprintf(f, "   0%8s%4d%8s%4d%8s%4d%8s%4d\n", "NDIM=", ndim, "IPS =", 4, "IRS =", c->irs, "ILP =", c->ilp);
  fprintf(f, "   0%8s%4d%8s%4d%8s%4d%8s%4d\n", "NTST=", c->ntst, "NCOL=", c->ncol, "IAD =", c->iad, "ISP =",
          c->isp);
  fprintf(f, "   0%8s%4d%8s%4d%8s%4d%8s%4d\n", "ISW =", c->isw, "IPLT=", c->iplt, "NBC =", c->nbc, "NINT=",
          c->nint);
  fprintf(f, "   0%7s%5d%7s%5d%8s%4d%8s%4d%8s%4d\n", " NMX=", c->nmx, "NPR=", c->npr, "MXBF=", 0, "IID =",
          c->iid, "IADS=", c->iads);
  fprintf(f, "   0%8s%4d%8s%4d%8s%4d%8s%4d%8s%4d\n", "ITMX=", c->itmx, "ITNW=", c->itnw, "NWTN=", c->nwtn,
          "JAC =", c->jac, "  NUZR=", c->nuzr);
  fprintf(f, "   0   NPAR=%4d   THL = {", c->npar);
  for (int k = 0; k < c->nthl; k++) {
    if (k) fputs(", ", f);
    quoted_par(w, f, c->thl[k].index);
    fputs(": ", f);
    dict_number(f, c->thl[k].weight);
  }
  fputs("}    THU = {", f);
  if (c->thu_default != 1.0)
    for (int i = 0; i < ndim; i++) {
      fprintf(f, "%s%d: ", i ? ", " : "", i + 1);
      dict_number(f, c->thu_default);
    }
  fputs("}\n", f);
  write_uzr_dict(w, f, "UZR", 0);
  write_uzr_dict(w, f, "UZSTOP", 1);
  if (c->e[0] || c->s[0] || c->dat[0] || c->sv[0]) {
    fputs("   0  ", f);
    if (c->e[0]) fprintf(f, " e = '%s'", c->e);
    if (c->s[0]) fprintf(f, " s = '%s'", c->s);
    if (c->dat[0]) fprintf(f, " dat = '%s'", c->dat);
    if (c->sv[0]) fprintf(f, " sv = '%s'", c->sv);
    fputc('\n', f);
  }
  write_names_dict(f, "parnames", w->names.par);
  write_names_dict(f, "unames  ", w->names.u);
  if (c->nstop > 0) {
    fputs("   0   STOP=[", f);
    for (int k = 0; k < c->nstop; k++)
      fprintf(f, "%s'%s%d'", k ? ", " : "", cable_type_name(c->stop_on[k]), c->stop_count[k]);
    fputs("]\n", f);
  }
  /* cable's own keys, in the same KEY = value syntax (parseC ignores keys it
   * does not know in b-file headers) */
  fprintf(f, "   0   LINSOLVER = '%s'   NSV = %d   BPDIR = %d   IIS = %d\n",
          c->linsolver == CABLE_LINSOLVER_KLU ? "klu" : "condense", c->nsv, c->bpsym, c->iis);
  if (c->stab) fputs("   0   STAB = 1\n", f);   /* PT's sign is stability (doc/stability.md) */
  int nicp = pt->nicp;
  fprintf(f, "   0   User-specified parameter%s", nicp == 1 ? ":       " : "s:      ");
  for (int k = 0; k < nicp; k++) {
    int idx = pt->icp[k];
    fputs(idx < CABLE_NAMES_MAX && w->names.par[idx][0] ? " " : "   ", f);
    quoted_par(w, f, idx);
  }
  int nfpr = n_free(w, pt->ndim, nicp);
  fprintf(f, "\n   0   Active continuation parameter%s", nfpr == 1 ? ":  " : "s: ");
  for (int k = 0; k < nfpr; k++) {
    int idx = pt->icp[k];
    fputs(idx < CABLE_NAMES_MAX && w->names.par[idx][0] ? " " : "   ", f);
    quoted_par(w, f, idx);
  }
  fputc('\n', f);
  /* AUTO's HEADNG: a lone "   0" line, then the column headings */
  fputs("   0\n   0    PT  TY  LAB ", f);
  char h[BCOL + 1];
  for (int j = 0; j < section_ncol(w); j++) {
    section_heading(w, j, h);
    fputs(h, f);
  }
  fputc('\n', f);
}

/* ---------------------------------------------------------------- CSV */

static void csv_field(FILE *f, const char *s)
{
  if (strpbrk(s, ",\"\n")) {
    fputc('"', f);
    for (; *s; s++) {
      if (*s == '"') fputc('"', f);
      fputc(*s, f);
    }
    fputc('"', f);
  } else {
    fputs(s, f);
  }
}

static int csv_open_section(cable_aufile *w)
{
  if (w->ncsv >= MAX_SECTIONS) return w_fail(w, CABLE_ERR_INPUT, w->bpath, "more than %d branch sections", MAX_SECTIONS);
  if (w->ncsv == w->csvcap) {
    int nc = w->csvcap ? 2 * w->csvcap : 8;
    cable_atomic_file **p = realloc(w->csv, (size_t)nc * sizeof *p);
    if (!p) return w_fail(w, CABLE_ERR_ALLOC, w->bpath, "out of memory");
    w->csv = p;
    w->csvcap = nc;
  }
  char path[4200];
  snprintf(path, sizeof path, "%s.%d.csv", w->csvbase, w->nsections);
  cable_error e;
  cable_atomic_file *af = cable_atomic_open(path, 0, &e);
  if (!af) {
    w->err = e;
    w->failed = 1;
    return e.status;
  }
  w->csv[w->ncsv++] = af;
  FILE *f = cable_atomic_stream(af);
  fputs("BR,PT,TY,LAB", f);
  char h[BCOL + 1];
  for (int j = 0; j < section_ncol(w); j++) {
    section_heading(w, j, h);
    char name[BCOL + 1], *q = name;
    const char *t = trim(h);
    if (strncmp(t, "L2-NORM", 7) == 0) t = "L2NORM";
    for (; *t && q < name + BCOL; t++) *q++ = (*t == ' ') ? '_' : *t;
    while (q > name && q[-1] == '_') q--;   /* trailing blanks of the field */
    *q = '\0';
    fputc(',', f);
    csv_field(f, name);
  }
  fputs(",NEWTON,DS,ERR_EST\n", f);
  return 0;
}

/* ---------------------------------------------------------------- d-file */

/* One d-file block per point, as AUTO's fort.9: it starts with the divider
 * parseD splits on and the point's lines; the solution note and the
 * engine's diagnostics that follow (until the next point) stay in it. */
static void d_begin_block(cable_aufile *w)
{
  if (w->d_started) fputs(DSEP, cable_atomic_stream(w->d));
  w->d_started = 1;
}

static void d_diag(void *ctx, const char *line)
{
  cable_aufile *w = ctx;
  if (!w || !w->d) return;
  fprintf(cable_atomic_stream(w->d), " %s\n", line ? line : "");
  w->d_started = 1;
}

/* ---------------------------------------------------------------- points */

static int same_section(const cable_aufile *w, const cable_point *pt)
{
  if (!w->in_section || pt->pt == 1 || pt->ibr != w->sec_ibr || pt->ndim != w->sec_ndim ||
      pt->nicp != w->sec_nicp)
    return 0;
  for (int k = 0; k < pt->nicp; k++)
    if (pt->icp[k] != w->sec_icp[k]) return 0;
  return 1;
}

static int start_section(cable_aufile *w, const cable_point *pt)
{
  w->in_section = 1;
  w->sec_ibr = pt->ibr;
  w->sec_ndim = pt->ndim;
  w->sec_nicp = pt->nicp;
  memcpy(w->sec_icp, pt->icp, (size_t)pt->nicp * sizeof pt->icp[0]);
  /* AUTO prints the user's parameters, not an extended problem's own (a
     fold's w and N, a branch-point curve's b, psi*, d and a: the NPARI
     slots after NPAR), and counts its MAX U columns with them */
  w->sec_npcol = 0;
  int nuser = 0;   /* of them, the free ones: q, p2..pk on a fold or branch-point curve */
  int nfpr = w->c.nbc + w->c.nint - w->c.ndim + 1;
  for (int k = 1; k < pt->nicp; k++)
    if (!(w->c.npari > 0 && pt->icp[k] >= w->c.npar - w->c.npari)) {
      if (k < nfpr) nuser++;
      w->sec_pcol[w->sec_npcol++] = pt->icp[k];
    }
  /* the curve's engine order is [p1, q, p2..pk] (cable_ext_icp_order), the
     user's and AUTO's [p1, p2..pk, q]: print q after p2..pk, as AUTO */
  if (w->c.isw == 2 && w->c.npari > 0 && w->c.ndm > 0 && nuser > 1) {
    int q = w->sec_pcol[0];
    memmove(w->sec_pcol, w->sec_pcol + 1, (size_t)(nuser - 1) * sizeof w->sec_pcol[0]);
    w->sec_pcol[nuser - 1] = q;
  }
  w->sec_n2 = n_umax(1 + w->sec_npcol, pt->ndim);
  w->nsections++;
  write_b_header(w, pt);
  FILE *d = cable_atomic_stream(w->d);
  fprintf(d, " cable: branch %d, section %d of %s\n", pt->ibr, w->nsections, w->bpath);
  fprintf(d, " NDIM=%d NTST=%d NCOL=%d ISW=%d IRS=%d%s%s DS=%g DSMIN=%g DSMAX=%g NMX=%d NPR=%d IIS=%d\n",
          pt->ndim, w->c.ntst, w->c.ncol, w->c.isw, w->c.irs, w->c.irs_name[0] ? " " : "", w->c.irs_name,
          w->c.ds, w->c.dsmin, w->c.dsmax, w->c.nmx, w->c.npr, w->c.iis);
  fputs(" ICP:", d);
  for (int k = 0; k < pt->nicp; k++) {
    fputc(' ', d);
    quoted_par(w, d, pt->icp[k]);
  }
  fputc('\n', d);
  if (w->opt.write_csv) return csv_open_section(w);
  return 0;
}

static int point_cb(void *ctx, const cable_point *pt)
{
  cable_aufile *w = ctx;
  if (!w) return CABLE_ERR_INPUT;
  if (w->failed) return w->err.status;
  if (!pt || pt->ndim < 1 || pt->nicp < 1 || pt->nicp > CABLE_MAX_ICP || !pt->icp || !pt->par ||
      (!pt->umax && pt->ndim > 0))
    return w_fail(w, CABLE_ERR_INPUT, w->bpath, "malformed point from the engine");
  for (int k = 0; k < pt->nicp; k++)
    if (pt->icp[k] < 0 || pt->icp[k] >= pt->npar)
      return w_fail(w, CABLE_ERR_INPUT, w->bpath, "point lists PAR(%d) beyond NPAR=%d", pt->icp[k] + 1, pt->npar);
  if (w->c.iplt < -pt->ndim || w->c.iplt > 3 * pt->ndim)
    return w_fail(w, CABLE_ERR_INPUT, w->bpath, "IPLT=%d is outside -NDIM..3*NDIM (NDIM=%d)", w->c.iplt, pt->ndim);
  d_begin_block(w);
  if (!same_section(w, pt)) {
    int st = start_section(w, pt);
    if (st) return st;
  }
  /* the row: AUTO's (I4,I6,I4,I5,nES19.10) with three-digit exponents */
  double val[2 + SCREEN_MAX + CABLE_MAX_ICP];
  int n = 0;
  val[n++] = pt->par[pt->icp[0]];
  val[n++] = pt->measure;
  for (int i = 0; i < w->sec_n2; i++) val[n++] = pt->umax[i];
  for (int k = 0; k < w->sec_npcol; k++) val[n++] = pt->par[w->sec_pcol[k]];
  int mtot = (pt->pt - 1) % 9999 + 1;   /* AUTO wraps point numbers at 9999 */
  if (pt->pt < 1) mtot = pt->pt;
  if (pt->stab == 1) mtot = -mtot;      /* STAB=1: AUTO's sign for a stable point */
  FILE *f = cable_atomic_stream(w->b);
  char buf[64];
  fprintf(f, "%4d%6d%4d%5d", pt->ibr, mtot, pt->itp, pt->lab);
  for (int j = 0; j < n; j++) fputs(cable_aufile_format_es(buf, val[j], BCOL, BDIG, BEXP), f);
  fputc('\n', f);
  if (pt->lab != 0) {
    /* labels may repeat, as in AUTO's files: each run numbers its labels from
       its own restart data (NEWLAB), ap appends as it is, merge joins two
       runs from one start without relabelling */
    if (int_push(&w->blab, &w->nblab, &w->blabcap, pt->lab) != 0)
      return w_fail(w, CABLE_ERR_ALLOC, w->bpath, "out of memory");
    if (pt->lab > w->last_label) w->last_label = pt->lab;
  }
  if (pt->ibr > w->last_branch) w->last_branch = pt->ibr;
  w->last_lab_point = pt->lab;
  /* d-file: AUTO's WRTBV9 line plus step size and error estimate */
  FILE *d = cable_atomic_stream(w->d);
  fputs("  BR    PT  IT         PAR           L2-NORM          DS        ERR-EST  DET     SIGMA1        SIGMA2\n", d);
  char e1[64], e2[64], e3[64], e4[64], e5[64], e6[64];
  fprintf(d, "%4d%6d%4d   %s%s%s%s   %+d%s%s\n", pt->ibr, mtot, pt->newton_iters, fmt_es2(e1, val[0], 14, 5),
          fmt_es2(e2, pt->l2norm, 14, 5), fmt_es2(e3, pt->ds, 14, 5),
          pt->err_est >= 0 ? fmt_es2(e4, pt->err_est, 14, 5) : "       unknown", pt->det_sign,
          fmt_es2(e5, pt->sv1, 14, 5), fmt_es2(e6, pt->sv2, 14, 5));
  if (pt->note && pt->note[0]) fprintf(d, " NOTE: %s\n", pt->note);
  /* the BP's kind as a record a program reads back (cable_session_dnotes.c),
     apart from the note, which is for people */
  if (cable_type_base(pt->itp) == CABLE_TY_BP && pt->bp_kind != CABLE_BP_UNKNOWN)
    fprintf(d, " BP: kind=%s multiplicity=%d\n", cable_bp_kind_name(pt->bp_kind), pt->bp_mult);
  if (pt->lab != 0) {
    /* AUTO's screen line for labelled points (parseD finds the label here) */
    char h[BCOL + 1];
    fputs("  BR    PT  TY  LAB ", d);
    for (int j = 0; j < n && j < 2 + SCREEN_MAX; j++) {
      section_heading(w, j, h);
      fprintf(d, "%-14.14s", h);   /* AUTO's screen columns: A14 of the same field */
    }
    const char *ty = cable_type_base(pt->itp) == CABLE_TY_RG ? "" : cable_type_name(pt->itp);
    fprintf(d, "\n%4d%6d %3s%5d", pt->ibr, mtot, ty, pt->lab);
    for (int j = 0; j < n && j < 2 + SCREEN_MAX; j++) fputs(fmt_es2(e1, val[j], 14, 5), d);
    fputc('\n', d);
  }
  if (w->opt.write_csv && w->ncsv > 0) {
    FILE *cf = cable_atomic_stream(w->csv[w->ncsv - 1]);
    const char *ty = pt->itp == 0 ? "" : cable_type_name(pt->itp);
    fprintf(cf, "%d,%d,%s,%d", pt->ibr, pt->pt, ty, pt->lab);
    for (int j = 0; j < n; j++) fprintf(cf, ",%.17g", val[j]);
    fprintf(cf, ",%d,%.17g,%.17g\n", pt->newton_iters, pt->ds, pt->err_est);
  }
  int st = w_check_stream(w, w->b);
  if (st == 0) st = w_check_stream(w, w->d);
  return st;
}

/* ---------------------------------------------------------------- solutions */

/* AUTO's DIRECTION(IIS, ITP): whether the s-file block carries the tangent. */
static int with_direction(int iis, int itp)
{
  int base = cable_type_base(itp);
  switch (iis) {
  case 0: return 0;
  case 1: return base == 1 || (base >= 5 && base <= 8);
  case 2: return base != 4;
  default: return 1;
  }
}

static void put_values(FILE *f, const double *v, int n)
{
  char buf[64];
  for (int k = 0; k < n; k++) {
    if (k % SPER_LINE == 0) fputs("    ", f);
    fputs(cable_aufile_format_es(buf, v[k], BCOL, BDIG, BEXP), f);
    if (k % SPER_LINE == SPER_LINE - 1 || k == n - 1) fputc('\n', f);
  }
}

static int solution_cb(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  cable_aufile *w = ctx;
  if (!w) return CABLE_ERR_INPUT;
  if (w->failed) return w->err.status;
  if (!pt || !sol || sol->ndim < 1 || sol->ntst < 1 || sol->ncol < 1 || sol->npar < 1 || sol->nfpr < 0 ||
      !sol->t || !sol->u || !sol->par)
    return w_fail(w, CABLE_ERR_INPUT, w->spath, "malformed solution from the engine");
  if (pt->lab == 0)
    return w_fail(w, CABLE_ERR_INPUT, w->spath, "solution for an unlabelled point (PT %d): labels in b and s must match",
                  pt->pt);
  if (sol->lab != 0 && sol->lab != pt->lab)
    return w_fail(w, CABLE_ERR_INPUT, w->spath, "solution label %d differs from its point's label %d", sol->lab,
                  pt->lab);
  if (pt->lab != w->last_lab_point)
    return w_fail(w, CABLE_ERR_INPUT, w->spath, "solution for label %d does not follow its b-file row", pt->lab);
  int ndim = sol->ndim, ntpl = cable_solution_npts(sol), npar = sol->npar, nfpr = sol->nfpr;
  int dir = with_direction(w->c.iis, pt->itp) && sol->udot && nfpr >= 1;
  int nrowpr = (ndim / 7 + 1) * ntpl + (npar + 6) / 7;
  if (dir) nrowpr += (nfpr + 19) / 20 + (nfpr + 6) / 7 + ((ndim + 6) / 7) * ntpl;
  int mtot = pt->pt >= 1 ? (pt->pt - 1) % 9999 + 1 : pt->pt;
  FILE *f = cable_atomic_stream(w->s);
  /* AUTO's header: 6I6,I8,I6,I8,7I5 (16 integers: NPARI, NDM, IPS=4, IPRIV=0);
     an extended problem's (cable_fold.h, cable_bpcont.h: constants' ndm = n
     < NDIM) has AUTO's NPARI (its own parameter slots) and NDM = n, as
     auto-07p writes */
  int ext = w->c.ndm > 0 && w->c.ndm < ndim;
  fprintf(f, "%6d%6d%6d%6d%6d%6d%8d%6d%8d%5d%5d%5d%5d%5d%5d%5d\n", pt->ibr, mtot, pt->itp, pt->lab, nfpr,
          sol->isw, ntpl, ndim + 1, nrowpr, sol->ntst, sol->ncol, npar, ext ? w->c.npari : 0, ext ? w->c.ndm : ndim,
          4, 0);
  for (int j = 0; j < ntpl; j++) {
    /* t then u(t): AUTO writes them as one record of ndim+1 numbers */
    char buf[64];
    const double *u = sol->u + (size_t)j * (size_t)ndim;
    for (int k = 0; k <= ndim; k++) {
      double v = k == 0 ? sol->t[j] : u[k - 1];
      if (k % SPER_LINE == 0) fputs("    ", f);
      fputs(cable_aufile_format_es(buf, v, BCOL, BDIG, BEXP), f);
      if (k % SPER_LINE == SPER_LINE - 1 || k == ndim) fputc('\n', f);
    }
  }
  if (dir) {
    for (int k = 0; k < nfpr; k++) {
      fprintf(f, "%5d", sol->icp[k] + 1);
      if (k % ICP_PER_LINE == ICP_PER_LINE - 1 || k == nfpr - 1) fputc('\n', f);
    }
    put_values(f, sol->pardot, nfpr);
    for (int j = 0; j < ntpl; j++) put_values(f, sol->udot + (size_t)j * (size_t)ndim, ndim);
  }
  if (npar > w->parcap) {
    double *p = realloc(w->parbuf, (size_t)npar * sizeof *p);
    if (!p) return w_fail(w, CABLE_ERR_ALLOC, w->spath, "out of memory");
    w->parbuf = p;
    w->parcap = npar;
  }
  memcpy(w->parbuf, sol->par, (size_t)npar * sizeof *sol->par);
  if (w->opt.err_par >= 0 && w->opt.err_par < npar && sol->err_est >= 0) w->parbuf[w->opt.err_par] = sol->err_est;
  put_values(f, w->parbuf, npar);
  if (int_push(&w->slab, &w->nslab, &w->slabcap, pt->lab) != 0)
    return w_fail(w, CABLE_ERR_ALLOC, w->spath, "out of memory");
  /* the note joins its point's d-file block (no divider in between) */
  FILE *d = cable_atomic_stream(w->d);
  char e1[64];
  fprintf(d, " Solution label %d (%s) stored: NTST=%d NCOL=%d NDIM=%d, error estimate %s\n", pt->lab,
          cable_type_name(pt->itp)[0] ? cable_type_name(pt->itp) : "regular", sol->ntst, sol->ncol, ndim,
          sol->err_est >= 0 ? trim(fmt_es2(e1, sol->err_est, 12, 4)) : "unknown");
  int st = w_check_stream(w, w->s);
  if (st == 0) st = w_check_stream(w, w->d);
  return st;
}

/* ---------------------------------------------------------------- open / close */

void cable_aufile_options_init(cable_aufile_options *o)
{
  if (!o) return;
  o->append = 0;
  o->write_csv = 1;
  o->err_par = -2;
}

static void make_path(char *out, size_t len, const char *dir, const char *prefix, const char *name)
{
  if (dir && dir[0]) snprintf(out, len, "%s/%s%s", dir, prefix, name);
  else snprintf(out, len, "%s%s", prefix, name);
}

static void free_writer(cable_aufile *w)
{
  free(w->csv);
  free(w->blab);
  free(w->slab);
  free(w->parbuf);
  free(w);
}

void cable_aufile_abort(cable_aufile *w)
{
  if (!w) return;
  cable_atomic_abort(w->b);
  cable_atomic_abort(w->s);
  cable_atomic_abort(w->d);
  for (int k = 0; k < w->ncsv; k++) cable_atomic_abort(w->csv[k]);
  free_writer(w);
}

/* Existing files an append continues: sections, last label and branch. */
static int scan_existing(cable_aufile *w, cable_error *err)
{
  if (access(w->spath, F_OK) == 0) {
    cable_sfile *s = cable_sfile_read(w->spath, err);
    if (!s) return err ? err->status : CABLE_ERR_IO;
    for (int i = 0; i < cable_sfile_count(s); i++) {
      const cable_solution *sol = cable_sfile_get(s, i);
      if (sol->lab > w->last_label) w->last_label = sol->lab;
      if (sol->ibr > w->last_branch) w->last_branch = sol->ibr;
    }
    cable_sfile_free(s);
  }
  if (access(w->bpath, F_OK) == 0) {
    cable_bfile *b = cable_bfile_read(w->bpath, err);
    if (!b) return err ? err->status : CABLE_ERR_IO;
    w->nsections = b->nbranch;
    for (int i = 0; i < b->nbranch; i++)
      for (int r = 0; r < b->branch[i].nrow; r++) {
        int lab = b->branch[i].lab[r];
        if (lab > w->last_label) w->last_label = lab;
        if (b->branch[i].br[r] > w->last_branch) w->last_branch = b->branch[i].br[r];
      }
    cable_bfile_free(b);
  }
  return 0;
}

cable_aufile *cable_aufile_open(const char *dir, const char *name, const cable_constants *c,
                                const cable_names *names, const cable_aufile_options *opt,
                                cable_error *err)
{
  if (!name || !name[0] || strchr(name, '/') || !c) {
    cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "output name must be a plain name like 'knot' (got '%s')",
                    name ? name : "(null)");
    return NULL;
  }
  if (cable_constants_consistent(c, CABLE_NAMES_MAX, err)) return NULL;   /* the headers read every array */
  cable_aufile *w = calloc(1, sizeof *w);
  if (!w) {
    cable_error_set(err, CABLE_ERR_ALLOC, "", 0, "", "out of memory");
    return NULL;
  }
  w->c = *c;
  if (names) w->names = *names;
  else cable_names_init(&w->names);
  if (opt) w->opt = *opt;
  else cable_aufile_options_init(&w->opt);
  if (w->opt.err_par == -2) w->opt.err_par = cable_names_par_index(&w->names, "err", NULL, 0);
  make_path(w->bpath, sizeof w->bpath, dir, "b.", name);
  make_path(w->spath, sizeof w->spath, dir, "s.", name);
  make_path(w->dpath, sizeof w->dpath, dir, "d.", name);
  snprintf(w->csvbase, sizeof w->csvbase, "%s", w->bpath);
  if (w->opt.append && scan_existing(w, err) != 0) {
    free_writer(w);
    return NULL;
  }
  w->b = cable_atomic_open(w->bpath, w->opt.append, err);
  if (w->b) w->s = cable_atomic_open(w->spath, w->opt.append, err);
  if (w->s) w->d = cable_atomic_open(w->dpath, w->opt.append, err);
  if (!w->d) {
    cable_aufile_abort(w);
    return NULL;
  }
  /* a d-file being appended to gets a divider before this session */
  w->d_started = w->opt.append && ftell(cable_atomic_stream(w->d)) > 0;
  return w;
}

void cable_aufile_set_constants(cable_aufile *w, const cable_constants *c)
{
  /* constants whose counts exceed their arrays are not taken (the headers
     would read past them): the writer keeps the ones it has */
  if (w && c && cable_constants_consistent(c, CABLE_NAMES_MAX, NULL) == 0) {
    w->c = *c;
    w->in_section = 0;   /* the next point starts a section with the new header */
  }
}

cable_sink cable_aufile_sink(cable_aufile *w)
{
  cable_sink s = {NULL, NULL, NULL, NULL};
  if (!w) return s;   /* nothing to write to: a sink without callbacks */
  s.ctx = w;
  s.point = point_cb;
  s.solution = solution_cb;
  s.diag = d_diag;
  return s;
}

int cable_aufile_last_label(const cable_aufile *w)
{
  return w ? w->last_label : 0;
}

int cable_aufile_last_branch(const cable_aufile *w)
{
  return w ? w->last_branch : 0;
}

int cable_aufile_checkpoint(cable_aufile *w, cable_error *err)
{
  if (!w) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "no writer (NULL)");
  if (w->failed) {
    if (err) *err = w->err;
    return w->err.status;
  }
  int st = cable_atomic_checkpoint(w->b, err);
  if (st == 0) st = cable_atomic_checkpoint(w->s, err);
  if (st == 0) st = cable_atomic_checkpoint(w->d, err);
  for (int k = 0; st == 0 && k < w->ncsv; k++) st = cable_atomic_checkpoint(w->csv[k], err);
  return st;
}

int cable_aufile_snapshot(cable_aufile *w, const char *dir, int with_s, const char *dnote, int sync,
                          cable_error *err)
{
  if (!w || !dir) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "no writer (NULL)");
  if (w->failed) {
    if (err) *err = w->err;
    return w->err.status;
  }
  char path[4200];
  snprintf(path, sizeof path, "%s/b.new", dir);
  int st = cable_atomic_copy(w->b, path, NULL, sync, err);
  snprintf(path, sizeof path, "%s/d.new", dir);
  if (st == 0) st = cable_atomic_copy(w->d, path, dnote, sync, err);
  snprintf(path, sizeof path, "%s/s.new", dir);
  if (st == 0 && with_s) st = cable_atomic_copy(w->s, path, NULL, sync, err);
  return st;
}

static int cmp_int(const void *a, const void *b)
{
  int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

/* Labels with a b-row must be exactly those with an s-block. */
static int check_labels(cable_aufile *w)
{
  if (w->nblab > 1) qsort(w->blab, (size_t)w->nblab, sizeof *w->blab, cmp_int);
  if (w->nslab > 1) qsort(w->slab, (size_t)w->nslab, sizeof *w->slab, cmp_int);
  int i = 0, j = 0;
  while (i < w->nblab || j < w->nslab) {
    if (j >= w->nslab || (i < w->nblab && w->blab[i] < w->slab[j]))
      return w_fail(w, CABLE_ERR_INPUT, w->spath, "label %d has a b-file row but no s-file solution", w->blab[i]);
    if (i >= w->nblab || w->slab[j] < w->blab[i])
      return w_fail(w, CABLE_ERR_INPUT, w->bpath, "label %d has an s-file solution but no b-file row", w->slab[j]);
    i++, j++;
  }
  return 0;
}

/* The files are made complete first and published only when everything
 * is in order: a failed callback or a label check leaves every previous file
 * as it was.  s goes first, because a restart reads s, and a b-file whose
 * labels the s-file lacks is the worse inconsistency; a failed rename stops
 * the files after it. */
int cable_aufile_close(cable_aufile *w, cable_error *err)
{
  if (!w) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "no writer (NULL)");
  if (!w->failed) check_labels(w);
  cable_error e;
  cable_atomic_file **all[3] = {&w->s, &w->b, &w->d};
  for (int k = 0; k < 3 + w->ncsv && !w->failed; k++) {
    cable_atomic_file *af = k < 3 ? *all[k] : w->csv[k - 3];
    if (cable_atomic_finish(af, &e) != 0) w->err = e, w->failed = 1;
  }
  for (int k = 0; k < 3 + w->ncsv; k++) {
    cable_atomic_file **af = k < 3 ? all[k] : &w->csv[k - 3];
    if (w->failed) {
      cable_atomic_abort(*af);
    } else if (cable_atomic_commit(*af, &e) != 0) {
      w->err = e;
      w->failed = 1;
    }
    *af = NULL;
  }
  if (!w->failed && !w->opt.append && w->opt.write_csv) {
    /* replacing: CSVs of sections the new b-file no longer has are stale */
    char path[4200];
    for (int k = w->nsections + 1;; k++) {
      snprintf(path, sizeof path, "%s.%d.csv", w->csvbase, k);
      if (unlink(path) != 0) break;
    }
  }
  int status = 0;
  if (w->failed) {
    status = w->err.status;
    if (err) *err = w->err;
  } else {
    cable_error_clear(err);
  }
  w->ncsv = 0;
  free_writer(w);
  return status;
}
