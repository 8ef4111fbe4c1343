/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Every row of a b-file back into branches (AUTO's loadbd: its parseB
 * keeps every computed point, not only the labelled ones), and the names
 * its header records (e, parnames, unames), which AUTO's parseB reads
 * without a constants file. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_status.h"
#include "cable_session_impl.h"

/* ---- the header ------------------------------------------------------------------ */

/* The quoted value after "KEY = " in text ("e = 'bratu' s = '/'"), or 0. */
static int quoted_after(const char *text, const char *key, char *out, size_t len)
{
  size_t k = strlen(key);
  const char *p = text;
  while ((p = strstr(p, key)) != NULL) {
    int start = p == text || isspace((unsigned char)p[-1]);
    const char *q = p + k;
    while (*q == ' ') q++;
    if (start && *q == '=') {
      q++;
      while (*q == ' ') q++;
      if (*q == '\'' || *q == '"') {
        const char *end = strchr(q + 1, *q);
        if (end && (size_t)(end - q - 1) < len) {
          memcpy(out, q + 1, (size_t)(end - q - 1));
          out[end - q - 1] = '\0';
          return 1;
        }
      }
    }
    p += k;
  }
  return 0;
}

/* The integer after "KEY" and "=" in an AUTO header line ("NDIM=   2"), or -1. */
static int header_int(const char *text, const char *key)
{
  const char *p = strstr(text, key);
  if (!p || (p != text && !isspace((unsigned char)p[-1]))) return -1;
  p += strlen(key);
  while (*p == ' ') p++;
  int v;
  return *p == '=' && sscanf(p + 1, "%d", &v) == 1 ? v : -1;
}

void rp_bfile_header(const char *path, char *e, size_t elen, cable_names *names, int *has_names, cable_constants *c)
{
  *has_names = 0;
  if (e && elen) e[0] = '\0';
  FILE *f = fopen(path, "r");
  if (!f) return;
  char line[8192];
  while (fgets(line, sizeof line, f)) {
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (p[0] != '0' || !isspace((unsigned char)p[1])) break;   /* the first row: the header is over */
    p++;
    while (*p == ' ' || *p == '\t') p++;
    p[strcspn(p, "\r\n")] = '\0';
    if (e && elen && !e[0] && strncmp(p, "e ", 2) == 0) quoted_after(p, "e", e, elen);
    /* the run's ICP ("User-specified parameters: 'T' 'L'" or "... : 1 2"),
       when the constants have none */
    char *colon = strchr(p, ':'), *save = NULL;
    if (c && c->nicp == 0 && strncmp(p, "User-specified parameter", 24) == 0 && colon) {
      char stmt[1024] = "ICP=[";
      size_t len = strlen(stmt);
      int n = 0;
      for (char *tok = strtok_r(colon + 1, " \t", &save); tok && len + strlen(tok) + 4 < sizeof stmt;
           tok = strtok_r(NULL, " \t", &save))
        len += (size_t)snprintf(stmt + len, sizeof stmt - len, "%s%s", n++ ? ", " : "", tok);
      snprintf(stmt + len, sizeof stmt - len, "]");
      if (n > 0) (void)cable_constants_parse_override(stmt, c, names, NULL, 0, NULL);
      continue;
    }
    /* NDIM, NBC, NINT the constants leave to the problem: an AUTO equation
       file needs them, and the header records those of the run */
    static const char *const dims[] = {"NDIM", "NBC", "NINT"};
    for (int k = 0; c && k < 3; k++) {
      int v = header_int(p, dims[k]), *have = k == 0 ? &c->ndim : k == 1 ? &c->nbc : &c->nint;
      char stmt[32];
      snprintf(stmt, sizeof stmt, "%s=%d", dims[k], v);
      if (v >= 0 && *have == 0 && (k > 0 || v > 0)) (void)cable_constants_parse_override(stmt, c, NULL, NULL, 0, NULL);
    }
    /* IPS, when the constants leave it at AUTO's default 1 (a value other
       than 4 is refused where it is set): the header's IPS = 4 is the run's,
       as AUTO restarts a loaded solution with its file's constants */
    if (c && c->ips != 4 && header_int(p, "IPS") == 4) (void)cable_constants_parse_override("IPS=4", c, NULL, NULL, 0, NULL);
    if (names && (strncmp(p, "parnames", 8) == 0 || strncmp(p, "unames", 6) == 0)) {
      /* the dict in the constants syntax; a malformed one is ignored (a
         header is a record, not an input the user wrote) */
      cable_constants scratch;
      cable_constants_init(&scratch);
      cable_names n = *names;
      if (cable_constants_parse_override(p, &scratch, &n, NULL, 0, NULL) == 0) {
        *names = n;
        *has_names = 1;
      }
    }
  }
  fclose(f);
}

/* One header line's "KEY = VALUE" statements applied to *c, each on its own
 * (AUTO writes several per line without commas: "NDIM=   2   IPS =   4").
 * The file names (e, s, c, dat, sv), the names dicts and ICP are read
 * elsewhere (rp_bfile_header); a statement cable cannot read is skipped. */
static void header_statements(const char *p, cable_names *names, cable_constants *c)
{
  const char *key[64];
  int nkey = 0;
  for (const char *q = p; *q && nkey < 64; q++) {
    if (!(isalpha((unsigned char)*q) && (q == p || isspace((unsigned char)q[-1])))) continue;
    const char *r = q;
    while (isalnum((unsigned char)*r) || *r == '_') r++;
    const char *k_end = r;
    while (*r == ' ') r++;
    if (*r == '=' && r[1] != '=') {
      key[nkey++] = q;
      q = k_end - 1;
    }
  }
  static const char *const skip[] = {"e", "s", "c", "dat", "sv", "unames", "parnames", "ICP"};
  for (int k = 0; k < nkey; k++) {
    size_t len = (size_t)((k + 1 < nkey ? key[k + 1] : p + strlen(p)) - key[k]);
    char stmt[1024];
    if (len >= sizeof stmt) continue;
    memcpy(stmt, key[k], len);
    stmt[len] = '\0';
    size_t klen = strcspn(stmt, " =");
    int skipped = 0;
    for (size_t j = 0; j < sizeof skip / sizeof skip[0]; j++)
      if (strlen(skip[j]) == klen && strncmp(stmt, skip[j], klen) == 0) skipped = 1;
    if (!skipped) {
      cable_constants t = *c;
      if (cable_constants_parse_override(stmt, &t, names, NULL, 0, NULL) == 0) *c = t;
    }
  }
}

void rp_bfile_section_constants(const char *path, int first_line, cable_names *names, cable_constants *c)
{
  FILE *f = fopen(path, "r");
  if (!f) return;
  char line[8192];
  /* the header block just before the section's first row */
  long start = -1, pos = ftell(f);
  int lineno = 0;
  while (lineno + 1 < first_line && fgets(line, sizeof line, f)) {
    lineno++;
    const char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    int head = p[0] == '0' && isspace((unsigned char)p[1]);
    if (head && start < 0) start = pos;
    if (!head) start = -1;
    pos = ftell(f);
  }
  if (start < 0 || fseek(f, start, SEEK_SET) != 0) {
    fclose(f);
    return;
  }
  int first = 1;
  while (ftell(f) < pos && fgets(line, sizeof line, f)) {
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    p++;   /* the '0' */
    p[strcspn(p, "\r\n")] = '\0';
    double v[5];
    char tail;
    /* AUTO's first header line: RL0 RL1 A0 A1 */
    if (first && sscanf(p, "%lf %lf %lf %lf %c", &v[0], &v[1], &v[2], &v[3], &tail) == 4) {
      c->rl0 = v[0];
      c->rl1 = v[1];
      c->a0 = v[2];
      c->a1 = v[3];
    } else if (!strstr(p, "parameter") && !strstr(p, " PT ")) {
      header_statements(p, names, c);
    }
    first = 0;
  }
  fclose(f);
}

/* ---- the rows --------------------------------------------------------------------- */

/* What value column j of a section holds. */
enum { COL_OTHER, COL_PAR, COL_L2, COL_UMAX };

typedef struct colmap {
  int kind, index;
} colmap;

static colmap column_of(const char *h, const cable_names *names)
{
  colmap m = {COL_OTHER, -1};
  int k;
  char tail[64];
  if (strcmp(h, "L2-NORM") == 0) {
    m.kind = COL_L2;
  } else if (sscanf(h, "PAR(%d)", &k) == 1 && k >= 1) {
    m.kind = COL_PAR;
    m.index = k - 1;
  } else if (sscanf(h, "MAX U(%d)", &k) == 1 && k >= 1) {
    m.kind = COL_UMAX;
    m.index = k - 1;
  } else if (strncmp(h, "MAX ", 4) == 0 && sscanf(h + 4, "%63s", tail) == 1 &&
             (k = cable_names_u_index(names, tail)) >= 0) {
    m.kind = COL_UMAX;
    m.index = k;
  } else if ((k = cable_names_par_index(names, h, NULL, 0)) >= 0) {
    m.kind = COL_PAR;
    m.index = k;
  }
  return m;
}

int rp_branch_from_rows(const cable_bfile_branch *bb, const cable_solution *const *sols, const char *const *notes,
                        const cable_constants *c, const cable_names *names, const char *e, rp_branch **out)
{
  *out = NULL;
  int nsol = 0, npar = 0, ndim = 0, rc = 0;
  for (int q = 0; q < bb->nrow; q++)
    if (bb->lab[q] > 0) {
      const cable_solution *s = sols[nsol++];
      if (s->npar > npar) npar = s->npar;
      if (s->ndim > ndim) ndim = s->ndim;
    }
  colmap *map = calloc((size_t)(bb->ncol > 0 ? bb->ncol : 1), sizeof *map);
  int *icp = calloc((size_t)(bb->ncol > 0 ? bb->ncol : 1), sizeof *icp);
  if (!map || !icp) rc = CABLE_ERR_ALLOC;
  int nicp = 0, nmax = 0, icp_ok = 1;
  for (int j = 0; !rc && j < bb->ncol; j++) {
    map[j] = column_of(bb->colname[j], names);
    if (map[j].kind == COL_PAR && map[j].index + 1 > npar) npar = map[j].index + 1;
    if (map[j].kind == COL_UMAX) nmax = map[j].index + 1 > nmax ? map[j].index + 1 : nmax;
    /* the free parameters are the first column and those after the MAX U ones */
    if (j != 1 && map[j].kind != COL_UMAX) {
      if (map[j].kind == COL_PAR) icp[nicp++] = map[j].index;
      else icp_ok = 0;
    }
  }
  if (ndim < nmax) ndim = nmax;
  if (npar > CABLE_NAMES_MAX) npar = CABLE_NAMES_MAX;
  if (ndim > CABLE_NAMES_MAX) ndim = CABLE_NAMES_MAX;
  /* parameters the file has no column for: constant along a branch unless
     they are computed outputs; a value every labelled solution agrees on is
     the branch's, any other is unknown (NaN) at an unlabelled row */
  double tmpl[CABLE_NAMES_MAX];
  for (int k = 0; k < npar; k++) {
    tmpl[k] = (double)NAN;
    int first = 1;
    for (int i = 0; i < nsol; i++) {
      double v = k < sols[i]->npar ? sols[i]->par[k] : (double)NAN;
      if (first) tmpl[k] = v;
      else if (!(v == tmpl[k])) tmpl[k] = (double)NAN;
      first = 0;
    }
  }
  rp_branch *b = rc ? NULL : rp_branch_alloc(bb->nrow > 0 ? bb->br[0] : 1, c, names, e);
  if (!rc && !b) rc = CABLE_ERR_ALLOC;
  int isol = 0;
  for (int q = 0; !rc && q < bb->nrow; q++) {
    const cable_solution *s = bb->lab[q] > 0 ? sols[isol] : NULL;
    double par[CABLE_NAMES_MAX], umax[CABLE_NAMES_MAX];
    for (int k = 0; k < npar; k++) par[k] = s && k < s->npar ? s->par[k] : tmpl[k];
    for (int d = 0; d < ndim; d++) umax[d] = (double)NAN;
    if (s) {   /* AUTO's MAX U(d) of the stored solution */
      for (int d = 0; d < ndim && d < s->ndim; d++) {
        umax[d] = s->u[d];
        for (int t = 1; t < cable_solution_npts(s); t++) umax[d] = fmax(umax[d], s->u[t * s->ndim + d]);
      }
    }
    cable_point pt;
    memset(&pt, 0, sizeof pt);
    pt.l2norm = (double)NAN;
    pt.measure = (double)NAN;
    for (int j = 0; j < bb->ncol; j++) {
      double v = bb->data[(size_t)j * (size_t)bb->nrow + (size_t)q];
      if (j == 1) pt.measure = v;
      if (map[j].kind == COL_L2) pt.l2norm = v;
      else if (map[j].kind == COL_PAR && map[j].index < npar && !s) par[map[j].index] = v;
      else if (map[j].kind == COL_UMAX && map[j].index < ndim) umax[map[j].index] = v;
    }
    pt.ibr = bb->br[q];
    pt.pt = bb->pt[q];
    pt.itp = bb->ty[q];
    pt.lab = bb->lab[q];
    pt.ndim = ndim;
    pt.npar = npar;
    pt.par = par;
    pt.umax = umax;
    pt.err_est = s ? s->err_est : -1;
    if (icp_ok && nicp > 0) {
      pt.icp = icp;
      pt.nicp = nicp;
    } else {
      pt.icp = c->nicp > 0 ? c->icp : s ? s->icp : icp;
      pt.nicp = c->nicp > 0 ? c->nicp : s ? s->nfpr : nicp;
    }
    pt.note = s ? notes[isol] : NULL;
    rc = rp_branch_add(b, &pt, s);
    if (s) isol++;
  }
  free(map);
  free(icp);
  if (rc) {
    rp_branch_decref(b);
    return rc;
  }
  *out = b;
  return 0;
}
