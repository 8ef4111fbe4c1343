/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Readers of s- and b-files in AUTO-07p's layout (cable's own and AUTO's):
 * the s-file block structure follows io.f90's READSOL (header of 12 or 16
 * integers, NROWPR lines of numbers), the b-file sections follow parseB
 * (header lines start with 0, a point number of 1 starts a new branch). */
#include "cable/cable_aufile.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

#include "cable/cable_status.h"
#include "constants_check.h"

#define SFILE_MAX_VALUES 100000000L   /* numbers per solution block: a sanity bound (800 MB) */
#define BFILE_MAX_COLS 4096           /* value columns per b-file row */
#define ROTATE_PT 9999                /* AUTO wraps point numbers after 9999 */

/* ---------------------------------------------------------------- numbers */

int cable_aufile_parse_double(const char *tok, double *out)
{
  char buf[1040];   /* a constants file's longest token (1023 characters) fits */
  if (!tok || !out) return -1;
  size_t n = strlen(tok);
  if (n == 0 || n + 2 >= sizeof buf) return -1;
  memcpy(buf, tok, n + 1);
  char *end;
  double v = strtod(buf, &end);
  if (end != buf && *end == '\0') {
    *out = v;
    return 0;
  }
  int has_e = 0;
  for (size_t k = 0; k < n; k++) {
    if (buf[k] == 'D' || buf[k] == 'd') buf[k] = 'E';
    if (buf[k] == 'E' || buf[k] == 'e') has_e = 1;
  }
  if (!has_e) {
    /* Fortran drops the 'E' of three-digit exponents: 1.5-103 */
    for (size_t k = n - 1; k > 0; k--)
      if ((buf[k] == '+' || buf[k] == '-') && (isdigit((unsigned char)buf[k - 1]) || buf[k - 1] == '.')) {
        memmove(buf + k + 1, buf + k, n - k + 1);
        buf[k] = 'E';
        break;
      }
  } else if (buf[n - 1] == 'E' || buf[n - 1] == 'e') {
    buf[n - 1] = '\0';  /* "0.0000E": an old AUTO quirk, exponent 0 */
  }
  v = strtod(buf, &end);
  if (end == buf || *end != '\0') return -1;
  *out = v;
  return 0;
}

/* ---------------------------------------------------------------- line reader */

typedef struct {
  FILE *f;
  const char *path;
  char *line;
  size_t cap;
  ssize_t len;
  int lineno;
} lreader;

static int lr_next(lreader *r)
{
  r->len = getline(&r->line, &r->cap, r->f);
  if (r->len < 0) return 0;
  r->lineno++;
  return 1;
}

static int is_blank(const char *s)
{
  for (; *s; s++)
    if (!isspace((unsigned char)*s)) return 0;
  return 1;
}

/* ---------------------------------------------------------------- s-files */

struct cable_sfile {
  int n, cap;
  cable_solution **sol;
  char path[512];   /* for messages of the lookups */
};

void cable_sfile_free(cable_sfile *s)
{
  if (!s) return;
  for (int i = 0; i < s->n; i++) cable_solution_free(s->sol[i]);
  free(s->sol);
  free(s);
}

int cable_sfile_count(const cable_sfile *s)
{
  return s ? s->n : 0;
}

const cable_solution *cable_sfile_get(const cable_sfile *s, int i)
{
  return (s && i >= 0 && i < s->n) ? s->sol[i] : NULL;
}

const cable_solution *cable_sfile_find_label(const cable_sfile *s, int lab)
{
  if (!s) return NULL;
  for (int i = 0; i < s->n; i++)
    if (s->sol[i]->lab == lab) return s->sol[i];
  return NULL;
}

typedef struct {
  double *v;
  long n, cap;
} dvec;

static int dvec_push(dvec *d, double x)
{
  if (d->n == d->cap) {
    long nc = d->cap ? 2 * d->cap : 1024;
    double *p = realloc(d->v, (size_t)nc * sizeof *p);
    if (!p) return -1;
    d->v = p;
    d->cap = nc;
  }
  d->v[d->n++] = x;
  return 0;
}

/* Header line: 12 (AUTO-07p before 0.9) or 16 integers. */
static int parse_header(lreader *r, long h[16], int *nh, cable_error *err)
{
  char *save = NULL, *tok;
  int n = 0;
  for (tok = strtok_r(r->line, " \t\r\n", &save); tok; tok = strtok_r(NULL, " \t\r\n", &save)) {
    char *end;
    errno = 0;
    long v = strtol(tok, &end, 10);
    if (*end != '\0' || errno == ERANGE)
      return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                             "expected a solution header of integers, got '%.40s'", tok);
    if (n >= 16)
      return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                             "solution header with more than 16 integers");
    h[n++] = v;
  }
  if (n != 12 && n != 16)
    return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                           "solution header has %d integers, expected 12 or 16", n);
  *nh = n;
  return 0;
}

static int read_block(lreader *r, cable_sfile *s, dvec *buf, cable_error *err)
{
  long h[16];
  int nh, hline = r->lineno;
  int st = parse_header(r, h, &nh, err);
  if (st) return st;
  long ibr = h[0], ntot = h[1], itp = h[2], lab = h[3], nfpr = h[4], isw = h[5], ntpl = h[6], nar = h[7],
       nrowpr = h[8], ntst = h[9], ncol = h[10], npar = h[11];
  if (ntst < 1)
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, r->path, hline, "",
                           "label %ld has NTST=%ld: not a boundary-value (IPS=4) solution", lab, ntst);
  /* the bounds come before NTST*NCOL so that the product cannot overflow */
  if (ncol < 1 || nar < 2 || npar < 1 || nfpr < 0 || nrowpr < 1 || ntst > 1000000 || ncol > 1000 ||
      ntpl != ntst * ncol + 1 || nar > 1000000 || npar > 1000000 || nfpr > 1000000 || nfpr > npar)
    return cable_error_set(err, CABLE_ERR_PARSE, r->path, hline, "",
                           "inconsistent solution header for label %ld (NTPL=%ld NAR=%ld NTST=%ld NCOL=%ld "
                           "NPAR=%ld NFPR=%ld)", lab, ntpl, nar, ntst, ncol, npar, nfpr);
  long ndim = nar - 1;
  long small = ((nar - 1) / 7 + 1) * ntpl + (npar + 6) / 7;
  int dir = nrowpr > small;
  long expect = nar * ntpl + npar + (dir ? 2 * nfpr + ndim * ntpl : 0);
  if (expect > SFILE_MAX_VALUES)
    return cable_error_set(err, CABLE_ERR_PARSE, r->path, hline, "", "solution block for label %ld too large", lab);
  buf->n = 0;
  for (long k = 0; k < nrowpr; k++) {
    if (!lr_next(r))
      return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                             "truncated file: the solution with label %ld (header on line %d) needs %ld lines, "
                             "the file ends after %ld",
                             lab, hline, nrowpr, k);
    char *save = NULL, *tok;
    for (tok = strtok_r(r->line, " \t\r\n", &save); tok; tok = strtok_r(NULL, " \t\r\n", &save)) {
      double v;
      if (cable_aufile_parse_double(tok, &v) != 0)
        return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "", "bad number '%.40s' (label %ld)",
                               tok, lab);
      if (!isfinite(v))
        return cable_error_set(err, CABLE_ERR_NONFINITE, r->path, r->lineno, "",
                               "non-finite value '%.40s' in the solution with label %ld", tok, lab);
      if (buf->n >= expect)
        return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                               "the solution with label %ld (header on line %d) has more than the %ld numbers "
                               "its header announces",
                               lab, hline, expect);
      if (dvec_push(buf, v) != 0) return cable_error_set(err, CABLE_ERR_ALLOC, r->path, r->lineno, "", "out of memory");
    }
  }
  if (buf->n != expect)
    return cable_error_set(err, CABLE_ERR_PARSE, r->path, r->lineno, "",
                           "the solution with label %ld (header on line %d) has %ld numbers, expected %ld", lab,
                           hline, buf->n, expect);
  cable_solution *sol = cable_solution_alloc((int)ndim, (int)ntst, (int)ncol, (int)npar, (int)nfpr);
  if (!sol) return cable_error_set(err, CABLE_ERR_ALLOC, r->path, hline, "", "out of memory");
  sol->ibr = (int)ibr;
  sol->ntot = (int)ntot;
  sol->itp = (int)itp;
  sol->lab = (int)lab;
  sol->isw = (int)isw;
  const double *v = buf->v;
  for (long j = 0; j < ntpl; j++) {
    sol->t[j] = v[j * nar];
    for (long i = 0; i < ndim; i++) sol->u[j * ndim + i] = v[j * nar + 1 + i];
  }
  long p = nar * ntpl;
  if (dir) {
    for (long k = 0; k < nfpr; k++) {
      double ic = v[p + k];
      if (ic != floor(ic) || ic < 1 || ic > npar) {
        cable_solution_free(sol);
        return cable_error_set(err, CABLE_ERR_PARSE, r->path, hline, "",
                               "label %ld: free-parameter index %g is not in 1..NPAR", lab, ic);
      }
      sol->icp[k] = (int)ic - 1;
    }
    p += nfpr;
    for (long k = 0; k < nfpr; k++) sol->pardot[k] = v[p + k];
    p += nfpr;
    for (long k = 0; k < ndim * ntpl; k++) sol->udot[k] = v[p + k];
    p += ndim * ntpl;
  } else {
    for (long k = 0; k < nfpr; k++) sol->icp[k] = -1;   /* not stored (IIS) */
  }
  for (long k = 0; k < npar; k++) sol->par[k] = v[p + k];
  if (s->n == s->cap) {
    int nc = s->cap ? 2 * s->cap : 16;
    cable_solution **q = realloc(s->sol, (size_t)nc * sizeof *q);
    if (!q) {
      cable_solution_free(sol);
      return cable_error_set(err, CABLE_ERR_ALLOC, r->path, hline, "", "out of memory");
    }
    s->sol = q;
    s->cap = nc;
  }
  s->sol[s->n++] = sol;
  return 0;
}

cable_sfile *cable_sfile_read(const char *path, cable_error *err)
{
  lreader r = {0};
  r.path = path ? path : "";
  r.f = path ? fopen(path, "r") : NULL;
  if (!r.f) {
    cable_error_set(err, CABLE_ERR_IO, r.path, 0, "", "cannot open solution file: %s", strerror(errno));
    return NULL;
  }
  cable_sfile *s = calloc(1, sizeof *s);
  dvec buf = {0};
  int st = s ? 0 : cable_error_set(err, CABLE_ERR_ALLOC, r.path, 0, "", "out of memory");
  if (s) snprintf(s->path, sizeof s->path, "%s", r.path);
  while (st == 0 && lr_next(&r)) {
    if (is_blank(r.line)) continue;
    st = read_block(&r, s, &buf, err);
  }
  if (st == 0 && ferror(r.f)) st = cable_error_set(err, CABLE_ERR_IO, r.path, r.lineno, "", "read error");
  fclose(r.f);
  free(r.line);
  free(buf.v);
  if (st != 0) {
    cable_sfile_free(s);
    return NULL;
  }
  cable_error_clear(err);
  return s;
}

const cable_solution *cable_sfile_find(const cable_sfile *s, const char *spec, cable_error *err)
{
  if (!s || !spec || !spec[0]) {
    cable_error_set(err, CABLE_ERR_INPUT, s ? s->path : "", 0, "IRS", "empty label");
    return NULL;
  }
  char *end;
  long v = strtol(spec, &end, 10);
  if (*end == '\0') {
    const cable_solution *sol = NULL;
    if (v > 0) sol = cable_sfile_find_label(s, (int)v);
    else if (v < 0) sol = cable_sfile_get(s, (int)(-v - 1));
    if (!sol && v < 0)
      cable_error_set(err, CABLE_ERR_NOTFOUND, s->path, 0, "IRS", "there is no solution number %ld (the file has %d)",
                      -v, s->n);
    else if (!sol)
      cable_error_set(err, CABLE_ERR_NOTFOUND, s->path, 0, "IRS", "label %ld not found", v);
    return sol;
  }
  int type, nth;
  if (cable_label_spec_parse(spec, &type, &nth) != 0) {
    cable_error_set(err, CABLE_ERR_INPUT, s->path, 0, "IRS",
                    "unknown label '%.40s': expected a number or TYPEn (BP1, UZ2, LP1, EP1, MX1, RG1)", spec);
    return NULL;
  }
  int count = 0;
  for (int i = 0; i < s->n; i++)
    if (cable_type_base(s->sol[i]->itp) == type && ++count == nth) return s->sol[i];
  cable_error_set(err, CABLE_ERR_NOTFOUND, s->path, 0, "IRS", "label '%s' not found: the file has %d %s solution%s",
                  spec, count, cable_type_name(type), count == 1 ? "" : "s");
  return NULL;
}

int cable_sfile_resolve_irs(const cable_sfile *s, cable_constants *c, cable_error *err)
{
  char spec[32];
  if (!s || !c) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "IRS", "no s-file or no constants (NULL)");
  int rc0 = cable_constants_consistent(c, CABLE_NAMES_MAX, err);
  if (rc0) return rc0;
  if (c->irs_name[0]) snprintf(spec, sizeof spec, "%s", c->irs_name);
  else snprintf(spec, sizeof spec, "%d", c->irs);
  if (!c->irs_name[0] && c->irs == 0) return 0;   /* STPNT start: nothing to look up */
  const cable_solution *sol = cable_sfile_find(s, spec, err);
  if (!sol) return err ? err->status : CABLE_ERR_NOTFOUND;
  c->irs = sol->lab;
  c->irs_name[0] = '\0';
  return 0;
}

void cable_sfile_take_err_est(cable_sfile *s, int err_par)
{
  if (!s || err_par < 0) return;
  for (int i = 0; i < s->n; i++)
    if (err_par < s->sol[i]->npar) s->sol[i]->err_est = s->sol[i]->par[err_par];
}

/* ---------------------------------------------------------------- b-files */

typedef struct {
  cable_bfile_branch b;
  int cap;
  double *rows;     /* row-major while reading */
  long rcap;
} bbuild;

static void branch_free(cable_bfile_branch *b)
{
  if (b->colname)
    for (int j = 0; j < b->ncol; j++) free(b->colname[j]);
  free(b->colname);
  free(b->br);
  free(b->pt);
  free(b->ty);
  free(b->lab);
  free(b->data);
}

void cable_bfile_free(cable_bfile *b)
{
  if (!b) return;
  for (int i = 0; i < b->nbranch; i++) branch_free(&b->branch[i]);
  free(b->branch);
  free(b);
}

const double *cable_bfile_column(const cable_bfile_branch *br, const char *name)
{
  if (!br || !name) return NULL;
  for (int j = 0; j < br->ncol; j++)
    if (strcmp(br->colname[j], name) == 0) return br->data + (size_t)j * (size_t)br->nrow;
  return NULL;
}

/* Column headings from the header line, located the way parseB does it:
 * the value fields end at the end of the data line. */
static int branch_names(cable_bfile_branch *b, const char *head, long datalen, const cable_bfile_branch *prev)
{
  b->colname = calloc((size_t)b->ncol, sizeof *b->colname);
  if (!b->colname) return -1;
  long colw = b->ncol > 0 ? (datalen - 19) / b->ncol : 0;
  long start = datalen - colw * b->ncol;
  long hlen = head ? (long)strlen(head) : 0;
  for (int j = 0; j < b->ncol; j++) {
    char name[64] = "";
    if (head && colw > 0 && start + j * colw < hlen) {
      long a = start + j * colw, e = a + colw;
      if (e > hlen) e = hlen;
      while (a < e && isspace((unsigned char)head[a])) a++;
      while (e > a && isspace((unsigned char)head[e - 1])) e--;
      if (e - a >= (long)sizeof name) e = a + (long)sizeof name - 1;
      memcpy(name, head + a, (size_t)(e - a));
      name[e - a] = '\0';
    } else if (!head && prev && prev->ncol == b->ncol) {
      snprintf(name, sizeof name, "%s", prev->colname[j]);
    }
    if (!name[0]) snprintf(name, sizeof name, "COLUMN(%d)", j + 1);
    b->colname[j] = strdup(name);
    if (!b->colname[j]) return -1;
  }
  return 0;
}

static int bb_push(bbuild *bb, int br, int pt, int ty, int lab, const double *v)
{
  cable_bfile_branch *b = &bb->b;
  if (b->nrow == bb->cap) {
    int nc = bb->cap ? 2 * bb->cap : 256;
    int *p1 = realloc(b->br, (size_t)nc * sizeof *p1);
    if (p1) b->br = p1;
    int *p2 = realloc(b->pt, (size_t)nc * sizeof *p2);
    if (p2) b->pt = p2;
    int *p3 = realloc(b->ty, (size_t)nc * sizeof *p3);
    if (p3) b->ty = p3;
    int *p4 = realloc(b->lab, (size_t)nc * sizeof *p4);
    if (p4) b->lab = p4;
    double *p5 = realloc(bb->rows, (size_t)nc * (size_t)b->ncol * sizeof *p5 + sizeof *p5);
    if (p5) bb->rows = p5;
    if (!p1 || !p2 || !p3 || !p4 || !p5) return -1;
    bb->cap = nc;
  }
  int i = b->nrow++;
  b->br[i] = br;
  b->pt[i] = pt;
  b->ty[i] = ty;
  b->lab[i] = lab;
  memcpy(bb->rows + (size_t)i * (size_t)b->ncol, v, (size_t)b->ncol * sizeof *v);
  return 0;
}

/* Move a finished section into the file (transposing to column-major). */
static int bb_finish(bbuild *bb, cable_bfile *out)
{
  cable_bfile_branch *b = &bb->b;
  b->data = malloc((size_t)b->nrow * (size_t)b->ncol * sizeof *b->data + sizeof *b->data);
  if (!b->data) return -1;
  for (int i = 0; i < b->nrow; i++)
    for (int j = 0; j < b->ncol; j++) b->data[(size_t)j * (size_t)b->nrow + (size_t)i] = bb->rows[(size_t)i * (size_t)b->ncol + (size_t)j];
  cable_bfile_branch *p = realloc(out->branch, (size_t)(out->nbranch + 1) * sizeof *p);
  if (!p) return -1;
  out->branch = p;
  out->branch[out->nbranch++] = *b;
  free(bb->rows);
  memset(bb, 0, sizeof *bb);
  return 0;
}

cable_bfile *cable_bfile_read(const char *path, cable_error *err)
{
  lreader r = {0};
  r.path = path ? path : "";
  r.f = path ? fopen(path, "r") : NULL;
  if (!r.f) {
    cable_error_set(err, CABLE_ERR_IO, r.path, 0, "", "cannot open bifurcation-diagram file: %s", strerror(errno));
    return NULL;
  }
  cable_bfile *out = calloc(1, sizeof *out);
  bbuild bb;
  memset(&bb, 0, sizeof bb);
  int active = 0, header_seen = 0, prev_pt = 0, st = 0, stab = 0;
  char *head = NULL;        /* the last header line with column headings */
  double *vals = malloc(BFILE_MAX_COLS * sizeof *vals);
  if (!out || !vals) st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, 0, "", "out of memory");
  while (st == 0 && lr_next(&r)) {
    if (is_blank(r.line)) continue;
    char *copy = strdup(r.line);
    if (!copy) {
      st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
      break;
    }
    char *save = NULL, *tok = strtok_r(copy, " \t\r\n", &save);
    char *end;
    long first = strtol(tok, &end, 10);
    if (*end != '\0') {
      st = cable_error_set(err, CABLE_ERR_PARSE, r.path, r.lineno, "", "expected a row or a header line starting "
                           "with an integer, got '%.40s'", tok);
      free(copy);
      break;
    }
    if (first == 0) {  /* header line */
      if (active && bb.b.nrow > 0) {
        if (bb_finish(&bb, out) != 0) st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
        active = 0;
      }
      if (!header_seen) {
        free(head);
        head = NULL;
        stab = 0;
      }
      header_seen = 1;
      if (strstr(r.line, " STAB = 1")) stab = 1;   /* cable's header line (aufile_write.c) */
      if (strstr(r.line, " PT ")) {
        free(head);
        head = strdup(r.line);
      }
      free(copy);
      continue;
    }
    int it[3], n = 0, bad = 0;
    for (int k = 0; k < 3 && !bad; k++) {
      tok = strtok_r(NULL, " \t\r\n", &save);
      long v = tok ? strtol(tok, &end, 10) : 0;
      if (!tok || *end != '\0') bad = 1;
      it[k] = (int)v;
    }
    while (!bad && (tok = strtok_r(NULL, " \t\r\n", &save))) {
      if (n >= BFILE_MAX_COLS || cable_aufile_parse_double(tok, &vals[n]) != 0) bad = 2;
      n++;
    }
    free(copy);
    if (bad || n < 1) {
      st = cable_error_set(err, CABLE_ERR_PARSE, r.path, r.lineno, "",
                           bad == 2 ? "bad number in row" : "malformed row: expected BR PT TY LAB and values");
      break;
    }
    int pt = it[0];
    int newsec = !active || header_seen ||
                 ((pt == 1 || pt == -1) && prev_pt != ROTATE_PT && prev_pt != -ROTATE_PT);
    if (newsec) {
      const cable_bfile_branch *prev = out->nbranch > 0 ? &out->branch[out->nbranch - 1] : NULL;
      if (active && bb.b.nrow > 0 && bb_finish(&bb, out) != 0) {
        st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
        break;
      }
      prev = out->nbranch > 0 ? &out->branch[out->nbranch - 1] : NULL;
      bb.b.ncol = n;
      bb.b.first_line = r.lineno;
      bb.b.stab = stab;
      long len = (long)r.len + (r.line[r.len - 1] == '\n' ? 0 : 1);
      if (branch_names(&bb.b, header_seen ? head : NULL, len, prev) != 0) {
        st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
        break;
      }
      active = 1;
      header_seen = 0;
    } else if (n != bb.b.ncol) {
      st = cable_error_set(err, CABLE_ERR_PARSE, r.path, r.lineno, "", "row has %d values, the branch has %d columns",
                           n, bb.b.ncol);
      break;
    }
    if (bb_push(&bb, (int)first, pt, it[1], it[2], vals) != 0) {
      st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
      break;
    }
    prev_pt = pt;
  }
  if (st == 0 && active && bb.b.nrow > 0 && bb_finish(&bb, out) != 0)
    st = cable_error_set(err, CABLE_ERR_ALLOC, r.path, r.lineno, "", "out of memory");
  fclose(r.f);
  free(r.line);
  free(head);
  free(vals);
  if (st != 0) {
    branch_free(&bb.b);
    free(bb.rows);
    cable_bfile_free(out);
    return NULL;
  }
  branch_free(&bb.b);   /* an unfinished empty section (names only) */
  free(bb.rows);
  cable_error_clear(err);
  return out;
}
