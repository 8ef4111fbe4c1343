/* The engine host: AUTO-07p's script commands on cable's continuation engine,
 * constants parser and b./s./d. files.  Results live in memory
 * (script_host_store.c); files are written only by sv=, ap=, save, and
 * merge/relabel of file names. */
#include "script_host_cable.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "cable/cable_cont.h"
#include "cable/cable_fold.h"
#include "cable/cable_status.h"
#include "cable/cable_constants.h"
#include "script_host_impl.h"

void cable_replay_options_init(cable_replay_options *o)
{
  memset(o, 0, sizeof *o);
}

static FILE *rp_log(const cable_replay *r) { return r->opt.log ? r->opt.log : stdout; }

static int file_exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* ---- problems ---------------------------------------------------------------- */

typedef struct rp_problem {
  const cable_problem *tmpl;  /* what e=NAME names (built-in, equation file, plug-in or opt.problems) */
  const cable_problem *pb;    /* the instance a run uses (prepared), or tmpl */
  int user;                   /* from opt.problems: released after use */
  int autoeq;                 /* from an AUTO equation file: dimensions from the constants */
} rp_problem;

static void problem_release(cable_replay *r, rp_problem *p)
{
  if (p->pb && p->pb != p->tmpl) cable_problem_release(p->tmpl, p->pb);
  if (p->user && r->opt.problems && r->opt.problems->release)
    r->opt.problems->release(r->opt.problems->ctx, p->tmpl);
  p->pb = p->tmpl = NULL;
  p->user = 0;
  p->autoeq = 0;
}

/* A plug-in for e=NAME: NAME.so (or NAME itself when it ends in .so), opened
 * once per session. */
static int plugin_problem(cable_replay *r, const char *e, const cable_problem **pb, cable_error *err)
{
  for (int i = 0; i < r->nplugins; i++)
    if (strcmp(r->plugin_name[i], e) == 0) {
      *pb = cable_plugin_problem(r->plugin[i]);
      return 0;
    }
  char path[1024];
  size_t n = strlen(e);
  const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
  int has_so = n > 3 && strcmp(e + n - 3, ".so") == 0;
  if (dir && e[0] != '/') snprintf(path, sizeof path, "%s/%s%s", dir, e, has_so ? "" : ".so");
  else snprintf(path, sizeof path, "%s%s", e, has_so ? "" : ".so");
  if (!has_so && !file_exists(path)) return CABLE_ERR_NOTFOUND;
  if (r->nplugins == RP_MAX_PLUGINS)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, e, "more than %d plug-ins in one session", RP_MAX_PLUGINS);
  cable_plugin *p = cable_plugin_open(path, pb, err);
  if (!p) return err && err->status ? err->status : CABLE_ERR_PLUGIN;
  snprintf(r->plugin_name[r->nplugins], sizeof r->plugin_name[0], "%s", e);
  r->plugin[r->nplugins++] = p;
  return 0;
}

/* A file named in the constants (dat=), relative to the run directory. */
static void rp_path_plain(const cable_replay *r, const char *name, char *buf, size_t len)
{
  const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
  snprintf(buf, len, "%s%s%s", dir && name[0] != '/' ? dir : "", dir && name[0] != '/' ? "/" : "", name);
}

/* An AUTO equation file for e=NAME (NAME.f90, NAME.f or NAME.c in the run
 * directory), built and loaded once per session; its problem takes NDIM,
 * NBC, NINT and NPAR from c (c NULL: a problem good for names only). */
static int autoeq_problem(cable_replay *r, const char *e, const cable_constants *c, const cable_problem **pb,
                          cable_error *err)
{
  cable_autoeq *m = NULL;
  for (int i = 0; i < r->nautoeq && !m; i++)
    if (strcmp(r->autoeq_name[i], e) == 0) m = r->autoeq[i];
  if (!m) {
    char src[1024];
    if (cable_autoeq_find(r->opt.dir, e, src, sizeof src) != 0) return CABLE_ERR_NOTFOUND;
    if (r->nautoeq == RP_MAX_PLUGINS)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, e, "more than %d equation files in one session", RP_MAX_PLUGINS);
    if (!(m = cable_autoeq_open(src, err))) return err && err->status ? err->status : CABLE_ERR_PLUGIN;
    if (cable_autoeq_was_built(m)) fprintf(rp_log(r), "built %s (module %s)\n", src, cable_autoeq_module(m));
    snprintf(r->autoeq_name[r->nautoeq], sizeof r->autoeq_name[0], "%s", e);
    r->autoeq[r->nautoeq++] = m;
  }
  char dat[1024] = "";
  if (c && c->dat[0]) rp_path_plain(r, c->dat, dat, sizeof dat);
  return cable_autoeq_problem(m, c, dat, pb, err);
}

/* The problem for e=NAME.  c NULL: only its names and keys are needed;
 * otherwise the problem prepares itself for the run (its prepare). */
static int find_problem(cable_replay *r, const char *e, const cable_constants *c, int from_stpnt,
                        rp_problem *out, cable_error *err)
{
  out->pb = out->tmpl = NULL;
  out->user = 0;
  out->autoeq = 0;
  if (!e[0])
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "e", "no problem given (e='NAME' in the call or the constants file)");
  const cable_replay_problems *up = r->opt.problems;
  int rc = CABLE_ERR_NOTFOUND;
  if (up && up->find) {
    rc = up->find(up->ctx, e, c, from_stpnt, &out->tmpl, err);
    if (rc == 0) out->user = 1;
    else if (rc != CABLE_ERR_NOTFOUND) return rc;
  }
  /* an AUTO user's own equation file wins over cable's test problems */
  if (rc == CABLE_ERR_NOTFOUND) {
    rc = autoeq_problem(r, e, c, &out->tmpl, err);
    if (rc == 0) out->autoeq = 1;
    else if (rc != CABLE_ERR_NOTFOUND) return rc;
  }
  if (rc == CABLE_ERR_NOTFOUND && (out->tmpl = cable_problem_builtin(e)) != NULL) rc = 0;
  if (rc == CABLE_ERR_NOTFOUND) {
    rc = plugin_problem(r, e, &out->tmpl, err);
    if (rc == CABLE_ERR_NOTFOUND)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, "e",
                             "unknown problem '%s' (not a built-in problem, no equation file %s.f90, %s.f or %s.c and "
                             "no %s.so plug-in)", e, e, e, e, e);
    if (rc) return rc;
  }
  out->pb = out->tmpl;
  if (!c) return 0;
  const cable_problem *inst = NULL;
  rc = cable_problem_prepare(out->tmpl, c, from_stpnt, &inst, err);
  if (rc) {
    problem_release(r, out);
    return rc;
  }
  out->pb = inst;
  return 0;
}

/* ---- handles ------------------------------------------------------------------- */

static int wrap_result(cable_replay *r, rp_result *res, script_value *out, cable_error *err)
{
  if (!res) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  int rc = script_handle_new(out, &r->host, SCRIPT_HANDLE_RESULT, res);
  return rc ? cable_error_set(err, rc, NULL, 0, NULL, "out of memory") : 0;
}

static int wrap_solution(cable_replay *r, rp_branch *b, int isol, script_value *out, cable_error *err)
{
  rp_sol *s = malloc(sizeof *s);
  if (!s) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  b->refs++;
  s->br = b;
  s->isol = isol;
  int rc = script_handle_new(out, &r->host, SCRIPT_HANDLE_SOLUTION, s);
  return rc ? cable_error_set(err, rc, NULL, 0, NULL, "out of memory") : 0;
}

static void rp_release(void *ctx, void *ptr, int kind)
{
  (void)ctx;
  if (kind == SCRIPT_HANDLE_RESULT) {
    rp_result_free(ptr);
  } else {
    rp_sol *s = ptr;
    rp_branch_decref(s->br);
    free(s);
  }
}

/* The handle's result, or NULL (with err) when it is something else. */
static const rp_result *as_result(const script_value *v, const char *what, cable_error *err)
{
  if (script_handle_kind(v) == SCRIPT_HANDLE_RESULT) return script_handle_ptr(v);
  cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "%s needs a result, got a %s", what, script_type_name(v));
  return NULL;
}

/* ---- run setup: constants, problem, start ----------------------------------------- */

typedef struct rp_setup {
  cable_constants c;
  cable_names names;
  char e[CABLE_NAME_MAX];
  const cable_solution *start;   /* borrowed from a branch or from sf */
  cable_sfile *sf;               /* owned: s.NAME of a string start or s= */
  char sfpath[1024];             /* its path */
  char sv[CABLE_NAME_MAX], ap[CABLE_NAME_MAX];
} rp_setup;

static void setup_free(rp_setup *s)
{
  cable_sfile_free(s->sf);
  s->sf = NULL;
}

/* The problem's parameter names, for constants that name parameters.  A
 * problem that cannot be had (unknown name, rejected plug-in) is reported
 * here, before its constants are read.  Release p after use. */
static int problem_names(cable_replay *r, const char *e, rp_problem *p, const char *const **parnames,
                         int *npar, cable_error *err)
{
  *parnames = NULL;
  *npar = 0;
  p->pb = NULL;
  p->user = 0;
  if (!e[0]) return 0;
  int rc = find_problem(r, e, NULL, 0, p, err);
  if (rc) return rc;
  *parnames = p->pb->parnames;
  *npar = p->pb->npar;
  return 0;
}

/* The problem a constants file names (e = 'NAME'), found before parsing it,
 * because the parser needs the problem's parameter names to read ICP=['T'].
 * A light scan: statements start a line or follow ',' or ';'; comments are
 * skipped.  Leaves e unchanged when there is none (the parser then says what
 * it cannot resolve). */
static void peek_problem_name(const char *path, char *e, size_t len)
{
  FILE *f = fopen(path, "r");
  if (!f) return;
  char line[1024];
  while (fgets(line, sizeof line, f)) {
    char *hash = strpbrk(line, "#!");
    if (hash) *hash = '\0';
    for (char *p = line; *p; p++) {
      if (p != line && p[-1] != ',' && p[-1] != ';' && p[-1] != ' ' && p[-1] != '\t') continue;
      if (*p != 'e') continue;
      char *q = p + 1;
      while (*q == ' ' || *q == '\t') q++;
      if (*q != '=') continue;
      q++;
      while (*q == ' ' || *q == '\t') q++;
      if (*q != '\'' && *q != '"') continue;
      char quote = *q++, *end = strchr(q, quote);
      if (!end || end == q || (size_t)(end - q) >= len) continue;
      snprintf(e, len, "%.*s", (int)(end - q), q);
      fclose(f);
      return;
    }
  }
  fclose(f);
}

static int read_constants_file(cable_replay *r, const char *name, rp_setup *s, int required,
                               cable_error *err)
{
  char path[1024];
  rp_path(r, "c", name, path, sizeof path);
  if (!required && !file_exists(path)) return 0;
  if (!s->e[0]) peek_problem_name(path, s->e, sizeof s->e);
  const char *const *parnames;
  int npar;
  rp_problem p;
  int rc = problem_names(r, s->e, &p, &parnames, &npar, err);
  if (rc) return rc;
  (void)parnames, (void)npar;
  rc = cable_constants_parse_file_for(path, p.pb, &s->c, &s->names, err);
  /* the file's names win; the problem names the rest (sol['lambda']) */
  if (!rc && p.pb) cable_names_fill(&s->names, p.pb->parnames, p.pb->npar, p.pb->unames, p.pb->ndim);
  problem_release(r, &p);
  if (!rc && s->c.e[0] && !s->e[0]) {
    snprintf(s->e, sizeof s->e, "%s", s->c.e);
    rc = problem_names(r, s->e, &p, &parnames, &npar, err);
    if (!rc) cable_names_fill(&s->names, p.pb->parnames, p.pb->npar, p.pb->unames, p.pb->ndim);
    problem_release(r, &p);
  }
  return rc;
}

static int read_solutions_file(cable_replay *r, const char *name, rp_setup *s, cable_error *err)
{
  char path[1024];
  rp_path(r, "s", name, path, sizeof path);
  snprintf(s->sfpath, sizeof s->sfpath, "%s", path);
  cable_sfile_free(s->sf);
  s->sf = cable_sfile_read(path, err);
  return s->sf ? 0 : (err && err->status ? err->status : CABLE_ERR_IO);
}

/* KEY=VALUE text for the constants parser: Python's repr is its syntax. */
static int kw_text(const script_kwarg *k, char *buf, size_t len, cable_error *err)
{
  const script_value *v = &k->value;
  char val[4096];
  switch (v->type) {
  case SCRIPT_BOOL: snprintf(val, sizeof val, "%d", v->num != 0); break;
  case SCRIPT_NUMBER:
  case SCRIPT_LIST:
  case SCRIPT_DICT: script_value_format(v, NULL, val, sizeof val); break;
  case SCRIPT_STRING: {
    const char *s = script_string_chars(v);
    char q = strchr(s, '\'') ? '"' : '\'';
    if (strchr(s, '\'') && strchr(s, '"'))
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, k->name, "a value cannot contain both quote characters");
    snprintf(val, sizeof val, "%c%s%c", q, s, q);
    break;
  }
  default:
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, k->name, "a %s is not a constants value",
                           script_type_name(v));
  }
  if ((size_t)snprintf(buf, len, "%s=%s", k->name, val) >= len)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, k->name, "value too long");
  return 0;
}

static int kw_string(const script_kwarg *k, char *dst, size_t len, cable_error *err)
{
  if (k->value.type != SCRIPT_STRING || script_string_len(&k->value) == 0 ||
      script_string_len(&k->value) >= len)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, k->name, "must be a non-empty name, got a %s",
                           script_type_name(&k->value));
  snprintf(dst, len, "%s", script_string_chars(&k->value));
  return 0;
}

/* The last labelled solution of a result. */
static const cable_solution *result_last(const rp_result *res)
{
  for (int k = res->nbr - 1; k >= 0; k--)
    if (res->br[k]->nsol > 0) return res->br[k]->sol[res->br[k]->nsol - 1];
  return NULL;
}

/* A solution of a result by IRS (a label, or 'BP1'-style in irs_name). */
static const cable_solution *result_irs(const rp_result *res, const cable_constants *c)
{
  int type = 0, nth = 0;
  if (c->irs_name[0] && cable_label_spec_parse(c->irs_name, &type, &nth) != 0) return NULL;
  for (int k = 0; k < res->nbr; k++)
    for (int i = 0; i < res->br[k]->nsol; i++) {
      const cable_solution *s = res->br[k]->sol[i];
      if (c->irs_name[0] ? (cable_type_base(s->itp) == type && --nth == 0) : s->lab == c->irs) return s;
    }
  return NULL;
}

/* AUTO's load/run argument handling: the base constants from the data (or
 * the runner), then c=, e=, s=, sv=, ap=, then every other keyword as an
 * override, then the start. */
static int build_setup(cable_replay *r, const script_value *data, const script_kwargs *kw, int nover,
                       const char *const *over, rp_setup *s, cable_error *err)
{
  memset(s, 0, sizeof *s);
  const rp_result *res = NULL;
  int rc = 0;
  if (data && data->type == SCRIPT_HANDLE) {
    const rp_branch *b;
    if (script_handle_kind(data) == SCRIPT_HANDLE_SOLUTION) {
      const rp_sol *so = script_handle_ptr(data);
      b = so->br;
      s->start = b->sol[so->isol];
    } else {
      res = script_handle_ptr(data);
      if (res->nbr == 0) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "the result is empty");
      b = res->br[res->nbr - 1];
    }
    s->c = b->c;
    s->names = b->names;
    snprintf(s->e, sizeof s->e, "%s", b->e);
    /* a stored solution's IRS is history: AUTO resets it */
    s->c.irs = 0;
    s->c.irs_name[0] = '\0';
  } else {
    s->c = r->cur;
    s->names = r->cur_names;
    snprintf(s->e, sizeof s->e, "%s", r->cur_e);
  }
  s->c.s[0] = s->c.sv[0] = '\0';   /* one-off, like IRS: set below for this run */
  const script_kwarg *ke = NULL, *kc = NULL, *ks = NULL;
  for (int i = 0; kw && i < kw->n && !rc; i++) {
    const script_kwarg *k = &kw->items[i];
    if (strcmp(k->name, "e") == 0) ke = k;
    else if (strcmp(k->name, "c") == 0) kc = k;
    else if (strcmp(k->name, "s") == 0) ks = k;
    else if (strcmp(k->name, "sv") == 0) rc = kw_string(k, s->sv, sizeof s->sv, err);
    else if (strcmp(k->name, "ap") == 0) rc = kw_string(k, s->ap, sizeof s->ap, err);
  }
  if (!rc && ke) rc = kw_string(ke, s->e, sizeof s->e, err);
  /* a constants file's s= and sv= count for the run that reads it, under
     the keywords (AUTO: keyword arguments override the c-file) */
  char cfile_s[CABLE_NAME_MAX] = "", cfile_sv[CABLE_NAME_MAX] = "";
  if (!rc && data && data->type == SCRIPT_STRING) {
    /* run('NAME') is AUTO's e='NAME', c='NAME', s='NAME': the equations
       NAME (an explicit e= wins), c.NAME and s.NAME when they exist.  When
       there is no problem NAME, the c-file's e names it (cable's
       extension: c.knot72 says e='braid_knot'). */
    const char *name = script_string_chars(data);
    if (!ke) {
      rp_problem p;
      s->e[0] = '\0';
      rc = find_problem(r, name, NULL, 0, &p, err);
      if (rc == 0) snprintf(s->e, sizeof s->e, "%s", name);
      problem_release(r, &p);
      if (rc == CABLE_ERR_NOTFOUND) {
        rc = 0;
        cable_error_clear(err);
      }
    }
    if (!rc) rc = read_constants_file(r, name, s, 0, err);
    if (!rc) snprintf(cfile_sv, sizeof cfile_sv, "%s", s->c.sv);
    char spath[1024];
    rp_path(r, "s", name, spath, sizeof spath);
    if (!rc && file_exists(spath)) {
      rc = read_solutions_file(r, name, s, err);
      if (!rc) snprintf(s->c.s, sizeof s->c.s, "%s", name);
    }
    if (!rc && !s->e[0]) snprintf(s->e, sizeof s->e, "%s", name);
  }
  if (!rc && kc) {
    char name[CABLE_NAME_MAX];
    rc = kw_string(kc, name, sizeof name, err);
    if (!rc) rc = read_constants_file(r, name, s, 1, err);
    if (!rc && ke) snprintf(s->e, sizeof s->e, "%s", script_string_chars(&ke->value));
    if (!rc) {
      snprintf(cfile_s, sizeof cfile_s, "%s", s->c.s);
      snprintf(cfile_sv, sizeof cfile_sv, "%s", s->c.sv);
    }
  }
  if (!rc && ks) {
    char name[CABLE_NAME_MAX];
    rc = kw_string(ks, name, sizeof name, err);
    if (!rc) rc = read_solutions_file(r, name, s, err);
    if (!rc) snprintf(s->c.s, sizeof s->c.s, "%s", name);
  } else if (!rc && cfile_s[0] && !data) {
    rc = read_solutions_file(r, cfile_s, s, err);   /* an explicit start wins over the file's s= */
  } else if (!rc && !s->sf) {
    s->c.s[0] = '\0';
  }
  if (!rc && cfile_sv[0] && !s->sv[0] && !s->ap[0]) snprintf(s->sv, sizeof s->sv, "%s", cfile_sv);
  if (!rc) snprintf(s->c.sv, sizeof s->c.sv, "%s", s->sv);   /* the b-file header says where it went */
  if (rc) return rc;
  const char *const *parnames;
  int npar;
  rp_problem p;
  rc = problem_names(r, s->e, &p, &parnames, &npar, err);
  for (int i = 0; kw && i < kw->n && !rc; i++) {
    const script_kwarg *k = &kw->items[i];
    if (k == ke || k == kc || k == ks || strcmp(k->name, "sv") == 0 || strcmp(k->name, "ap") == 0) continue;
    char text[4200];
    rc = kw_text(k, text, sizeof text, err);
    if (!rc) rc = cable_constants_parse_override_for(text, p.pb, &s->c, &s->names, err);
  }
  (void)parnames, (void)npar;
  for (int i = 0; i < nover && !rc; i++) {
    rc = cable_constants_parse_override_for(over[i], p.pb, &s->c, &s->names, err);
    if (rc && err && !err->file[0]) {
      snprintf(err->file, sizeof err->file, "<command line>");
      err->line = 0;   /* the message quotes the argument */
    }
  }
  problem_release(r, &p);
  if (rc) return rc;
  snprintf(s->c.e, sizeof s->c.e, "%s", s->e);
  int irs_given = s->c.irs != 0 || s->c.irs_name[0];
  if (res) {
    s->start = irs_given ? result_irs(res, &s->c) : result_last(res);
    if (!s->start)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, "IRS",
                             irs_given ? "no such label in the result" : "the result has no labelled solution");
  } else if (!s->start && s->sf && irs_given) {
    if ((rc = cable_sfile_resolve_irs(s->sf, &s->c, err))) {
      if (err && !err->file[0]) snprintf(err->file, sizeof err->file, "%.500s", s->sfpath);
      return rc;
    }
    s->start = cable_sfile_find_label(s->sf, s->c.irs);
  } else if (!s->start && irs_given) {
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "IRS",
                           "a restart needs solutions: give a result, a solution, a name or s='NAME'");
  }
  return 0;
}

/* ---- run ------------------------------------------------------------------------- */

typedef struct collector {
  rp_branch *b;
  FILE *diag;
  int rc;
  int tty;          /* stderr is a terminal: show the progress line */
} collector;

static double now_seconds(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One-line live progress on a terminal (stderr), rewritten in place. */
static void progress(const collector *c, const cable_point *pt)
{
  if (!c->tty) return;
  int k = pt->nicp > 0 ? pt->icp[0] : 0;
  fprintf(stderr, "\r  branch %d  point %5d  PAR(%d) = %-14.8g ds = %-9.3g Newton %d   ", pt->ibr, pt->pt, k + 1,
          pt->par[k], pt->ds, pt->newton_iters);
  fflush(stderr);
}

static int collect_point(void *ctx, const cable_point *pt)
{
  collector *c = ctx;
  progress(c, pt);
  if (c->diag && pt->note) fprintf(c->diag, "%s\n", pt->note);
  /* a labelled point's solution comes next, with the same point: add both then */
  if (pt->lab > 0) return 0;
  if (!c->rc) c->rc = rp_branch_add(c->b, pt, NULL);
  return c->rc;
}

static int collect_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  collector *c = ctx;
  if (!c->rc) c->rc = rp_branch_add(c->b, pt, sol);
  return c->rc;
}

static void collect_diag(void *ctx, const char *line)
{
  collector *c = ctx;
  if (c->diag) fprintf(c->diag, "%s\n", line);
}

static const char *par_name(const cable_names *n, int k, char *buf, size_t len)
{
  if (k >= 0 && k < CABLE_NAMES_MAX && n->par[k][0]) snprintf(buf, len, "%s", n->par[k]);
  else snprintf(buf, len, "PAR(%d)", k + 1);
  return buf;
}

/* AUTO prints every labelled point of a run; so does the host. */
static void log_branch(const cable_replay *r, const rp_branch *b, int status, const char *why, double seconds)
{
  FILE *f = rp_log(r);
  char nm[64];
  for (int i = 0; i < b->npt; i++) {
    const cable_point *p = &b->pts[i].pt;
    /* the engine's remarks (special points it could not locate, rejected
       steps, double branch points) are also in the d-file */
    if (p->note) fprintf(f, "  PT %5d: %s\n", p->pt, p->note);
    if (p->lab <= 0) continue;
    int k = p->nicp > 0 ? p->icp[0] : 0;
    const char *ty = cable_type_name(p->itp);
    fprintf(f, "  BR %4d  PT %5d  TY %-2s  LAB %4d  %s = %.10g  L2-NORM = %.10g\n", p->ibr, p->pt,
            ty[0] ? ty : "-", p->lab, par_name(&b->names, k, nm, sizeof nm), p->par[k], p->l2norm);
  }
  fprintf(f, "  branch %d: %d points, %d labelled; end: %s%s%s\n", b->ibr, b->npt, b->nsol,
          cable_status_message(status), why && why[0] ? ": " : "", why ? why : "");
  /* summary: special points, time, and the worst first-integral drift of
     the stored solutions when the problem's PVLS reports one (a parameter
     named "drift", e.g. the braid problems' |F|^2, F.M, h, Hamiltonian along s) */
  int nbp = 0, nlp = 0, nuz = 0;
  double drift = -1;
  int kdrift = cable_names_par_index(&b->names, "drift", NULL, 0);
  for (int i = 0; i < b->nsol; i++) {
    int ty = cable_type_base(b->sol[i]->itp);
    nbp += ty == 6;
    nlp += ty == 5;
    nuz += ty == -4;
    if (kdrift >= 0 && kdrift < b->sol[i]->npar) drift = fmax(drift, b->sol[i]->par[kdrift]);
  }
  fprintf(f, "  summary: %d BP, %d LP, %d UZ; %.1f s", nbp, nlp, nuz, seconds);
  if (drift >= 0) fprintf(f, "; worst first-integral drift %.2e", drift);
  fprintf(f, "\n");
}

static int engine_run(cable_replay *r, rp_setup *s, rp_branch **out, cable_error *err)
{
  *out = NULL;
  rp_problem prob;
  int rc = find_problem(r, s->e, &s->c, s->start == NULL, &prob, err);
  if (rc) return rc;
  const cable_problem *pb = prob.pb;
  if (!prob.autoeq) {
    /* a built-in or plug-in problem's dimensions are its own: a constants
       value that says otherwise is an error at its line, never ignored */
    const struct {
      const char *key;
      int value, want;
      const cable_key_origin *o;
    } dims[] = {{"NDIM", s->c.ndim, pb->ndim, &s->c.origin_ndim},
                {"NBC", s->c.nbc, pb->nbc, &s->c.origin_nbc},
                {"NINT", s->c.nint, pb->nint, &s->c.origin_nint}};
    for (size_t k = 0; k < sizeof dims / sizeof dims[0]; k++)
      if ((dims[k].o->file[0] || dims[k].o->line) && dims[k].value != dims[k].want) {
        cable_error_set(err, CABLE_ERR_INPUT, dims[k].o->file, dims[k].o->line, dims[k].key,
                        "%s=%d contradicts problem '%s', which has %s=%d (the problem fixes it: remove the "
                        "line, or write the equations as an AUTO file NAME.f90 or NAME.c)",
                        dims[k].key, dims[k].value, pb->name, dims[k].key, dims[k].want);
        problem_release(r, &prob);
        return CABLE_ERR_INPUT;
      }
  }
  if (s->c.ignored[0])
    fprintf(rp_log(r), "  note: accepted and ignored, as AUTO does for boundary-value problems: %s\n", s->c.ignored);
  int st = 0;
  /* ISW = 2 at an LP: the fold's extended problem, its constants (ICP with
     the null vector's parameter slots) and its own start (cable_fold.h) */
  cable_fold *fold = NULL;
  const cable_constants *crun = &s->c;
  const cable_solution *start = s->start;
  if (s->c.isw == 2) {
    char msg[400];
    fold = cable_fold_alloc(pb, &s->c, s->start, &st, msg, sizeof msg);
    if (!fold) {
      problem_release(r, &prob);
      return cable_error_set(err, st, NULL, 0, "ISW", "%s", msg);
    }
    pb = cable_fold_problem(fold);
    crun = cable_fold_constants(fold);
    start = NULL;
  }
  cable_names_fill(&s->names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  st = cable_cont_check(pb, crun, err);
  if (st) {
    cable_fold_free(fold);
    problem_release(r, &prob);
    return st;
  }
  cable_cont *cc = cable_cont_alloc(pb, crun, &st);
  if (!cc) {
    cable_fold_free(fold);
    problem_release(r, &prob);
    return cable_error_set(err, st, NULL, 0, NULL, "could not set up the solver: %s", cable_status_message(st));
  }
  if (st == 0 && fold) {
    /* the fold run starts on the LP's mesh */
    double *mesh = malloc((size_t)(crun->ntst + 1) * sizeof *mesh);
    if (!mesh) st = CABLE_ERR_ALLOC;
    if (mesh) {
      cable_fold_mesh(fold, crun->ntst, mesh);
      st = cable_cont_set_mesh(cc, mesh);
      free(mesh);
    }
  }
  if (st == 0) st = cable_cont_set_start(cc, start);
  if (st) {
    cable_error_set(err, st, NULL, 0, NULL, "%s", cable_cont_error(cc)[0] ? cable_cont_error(cc) : cable_status_message(st));
    cable_cont_free(cc);
    cable_fold_free(fold);
    problem_release(r, &prob);
    return st;
  }
  int ibr = ++r->next_branch;
  double t_start = now_seconds();
  collector col = {rp_branch_alloc(ibr, crun, &s->names, s->e), r->opt.diag, 0, isatty(fileno(stderr))};
  if (!col.b) {
    cable_cont_free(cc);
    cable_fold_free(fold);
    problem_release(r, &prob);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  }
  cable_sink sink = {&col, collect_point, collect_solution, collect_diag};
  int next = r->last_label + 1;
  st = cable_cont_run(cc, &sink, ibr, r->last_label + 1, &next);
  if (next - 1 > r->last_label) r->last_label = next - 1;
  char why[512], end_note[600];
  snprintf(why, sizeof why, "%s", st < 0 ? cable_cont_error(cc) : "");
  snprintf(end_note, sizeof end_note, "branch %d ended: %s: %s", ibr, cable_status_message(st), why);
  if (!col.rc && st < 0) col.rc = rp_branch_set_end_note(col.b, end_note);
  cable_cont_free(cc);
  cable_fold_free(fold);
  problem_release(r, &prob);
  if (col.rc) {
    rp_branch_decref(col.b);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory keeping the branch");
  }
  if (st < 0 && col.b->npt == 0) {
    rp_branch_decref(col.b);
    return cable_error_set(err, st, NULL, 0, NULL, "no point converged: %s", why[0] ? why : cable_status_message(st));
  }
  /* like AUTO, a branch that ends abnormally (MX) is still a result */
  if (col.tty) fprintf(stderr, "\r%*s\r", 100, "");
  log_branch(r, col.b, st, why, now_seconds() - t_start);
  *out = col.b;
  return 0;
}

/* AUTO's runner keeps the constants of the last run, except the one-off
 * start and save settings. */
static void remember(cable_replay *r, const rp_setup *s)
{
  r->cur = s->c;
  r->cur.irs = 0;
  r->cur.irs_name[0] = '\0';
  r->cur.s[0] = r->cur.sv[0] = '\0';
  r->cur_names = s->names;
  snprintf(r->cur_e, sizeof r->cur_e, "%s", s->e);
}

/* ---- label and branch numbers ------------------------------------------------------- */

static void note_label(cable_replay *r, int lab, int ibr)
{
  if (lab > r->last_label) r->last_label = lab;
  if (ibr > r->next_branch) r->next_branch = ibr;
}

static void note_sfile(cable_replay *r, const cable_sfile *sf)
{
  for (int i = 0; sf && i < cable_sfile_count(sf); i++) note_label(r, cable_sfile_get(sf, i)->lab, cable_sfile_get(sf, i)->ibr);
}

/* Labels and branch numbers already in b./s.NAME (when they exist). */
static int note_files(cable_replay *r, const char *name, cable_error *err)
{
  char path[1024];
  rp_path(r, "s", name, path, sizeof path);
  if (file_exists(path)) {
    cable_sfile *sf = cable_sfile_read(path, err);
    if (!sf) return err && err->status ? err->status : CABLE_ERR_IO;
    note_sfile(r, sf);
    cable_sfile_free(sf);
  }
  rp_path(r, "b", name, path, sizeof path);
  if (file_exists(path)) {
    cable_bfile *bf = cable_bfile_read(path, err);
    if (!bf) return err && err->status ? err->status : CABLE_ERR_IO;
    for (int k = 0; k < bf->nbranch; k++)
      for (int i = 0; i < bf->branch[k].nrow; i++) note_label(r, bf->branch[k].lab[i], bf->branch[k].br[i]);
    cable_bfile_free(bf);
  }
  return 0;
}

/* AUTO's NEWLAB: the new labels follow the largest label of the solutions
 * file the run restarts from, and a new branch number follows its largest
 * branch number.  cable also continues after the labels of the files an
 * ap= run appends to (AUTO can repeat a label there), and after every label
 * of the session, so that no s-file receives a label twice. */
static int continue_numbering(cable_replay *r, const rp_setup *s, cable_error *err)
{
  note_sfile(r, s->sf);
  return s->ap[0] ? note_files(r, s->ap, err) : 0;
}

static int run_with(cable_replay *r, const script_value *start, const script_kwargs *kw, int nover,
                    const char *const *over, script_value *out, cable_error *err)
{
  rp_setup s;
  rp_branch *b = NULL;
  int rc = build_setup(r, start, kw, nover, over, &s, err);
  if (!rc) rc = continue_numbering(r, &s, err);
  if (!rc) rc = engine_run(r, &s, &b, err);
  rp_result *res = NULL;
  if (!rc) {
    remember(r, &s);
    res = rp_result_alloc(1);
    if (res) res->br[0] = b;
    else rp_branch_decref(b);
    rc = wrap_result(r, res, out, err);
  }
  if (!rc && s.sv[0]) rc = rp_result_write(r, res, s.sv, 0, err);
  if (!rc && s.ap[0]) rc = rp_result_write(r, res, s.ap, 1, err);
  if (!rc && (s.sv[0] || s.ap[0]))
    fprintf(rp_log(r), "  %s b.%s, s.%s, d.%s\n", s.sv[0] ? "saved to" : "appended to", s.sv[0] ? s.sv : s.ap,
            s.sv[0] ? s.sv : s.ap, s.sv[0] ? s.sv : s.ap);
  setup_free(&s);
  return rc;
}

static int rp_run(void *ctx, const script_value *start, const script_kwargs *kw, script_value *out,
                  cable_error *err)
{
  return run_with(ctx, start, kw, 0, NULL, out, err);
}

int cable_replay_run_cli(cable_replay *r, const char *name, const script_kwargs *names, int nover,
                         const char *const *overrides, cable_error *err)
{
  script_value out = script_none(), data = script_none();
  if (name && script_string_new(&data, name, strlen(name)))
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  int rc = run_with(r, name ? &data : NULL, names, nover, overrides, &out, err);
  script_value_release(&data);
  script_value_release(&out);
  return rc;
}

/* ---- label selection, iteration, '+' ---------------------------------------------- */

static int rp_select(void *ctx, const script_value *result, const script_value *spec, script_value *out,
                     cable_error *err)
{
  cable_replay *r = ctx;
  const rp_result *res = as_result(result, "label selection", err);
  if (!res) return CABLE_ERR_INPUT;
  long lab = 0;
  int type = 0, nth = 0, list = 0;
  char key[64] = "";
  if (!spec) {
    list = 1;
  } else if (spec->type == SCRIPT_NUMBER) {
    if (script_value_to_long(spec, &lab) || lab <= 0)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "a label number must be a positive integer");
    snprintf(key, sizeof key, "%ld", lab);
  } else {
    const char *t = script_string_chars(spec);
    snprintf(key, sizeof key, "%s", t);
    if (cable_label_spec_parse(t, &type, &nth) != 0) {
      type = cable_type_code(t);
      list = 1;
      if (!type)
        return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key,
                               "not a label: use a number, a type (BP, LP, UZ, EP, MX) or a type and count (BP1)");
    }
  }
  int rc = list ? script_list_new(out) : 0;
  for (int k = 0; k < res->nbr && !rc; k++)
    for (int i = 0; i < res->br[k]->nsol && !rc; i++) {
      const cable_solution *s = res->br[k]->sol[i];
      int match = !spec || (lab ? s->lab == lab : cable_type_base(s->itp) == type);
      if (!match || (!list && nth > 1 && --nth > 0)) continue;
      if (!list) return wrap_solution(r, res->br[k], i, out, err);
      script_value v;
      rc = wrap_solution(r, res->br[k], i, &v, err);
      if (!rc && script_list_append(out, v)) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    }
  if (!list && !rc) return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, key, "no such label in the result");
  return rc;
}

static int rp_add(void *ctx, const script_value *a, const script_value *b, script_value *out, cable_error *err)
{
  cable_replay *r = ctx;
  const rp_result *x = as_result(a, "'+'", err), *y = x ? as_result(b, "'+'", err) : NULL;
  if (!x || !y) return CABLE_ERR_INPUT;
  rp_result *res = rp_result_alloc(x->nbr + y->nbr);
  if (!res) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  for (int k = 0; k < x->nbr + y->nbr; k++) {
    rp_branch *br = k < x->nbr ? x->br[k] : y->br[k - x->nbr];
    br->refs++;
    res->br[k] = br;
  }
  return wrap_result(r, res, out, err);
}

static int branch_result(cable_replay *r, rp_branch *b, script_value *out, cable_error *err)
{
  rp_result *res = rp_result_alloc(1);
  if (res) {
    b->refs++;
    res->br[0] = b;
  }
  return wrap_result(r, res, out, err);
}

static int rp_items(void *ctx, const script_value *h, script_value *list, cable_error *err)
{
  cable_replay *r = ctx;
  const rp_result *res = as_result(h, "iteration", err);
  if (!res) return CABLE_ERR_INPUT;
  int rc = script_list_new(list);
  for (int k = 0; k < res->nbr && !rc; k++) {
    script_value v;
    rc = branch_result(r, res->br[k], &v, err);
    if (!rc && script_list_append(list, v)) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  }
  return rc;
}

static int rp_getitem(void *ctx, const script_value *h, const script_value *key, script_value *out,
                      cable_error *err)
{
  cable_replay *r = ctx;
  long i;
  if (script_handle_kind(h) == SCRIPT_HANDLE_RESULT) {
    const rp_result *res = script_handle_ptr(h);
    if (script_value_to_long(key, &i)) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "a branch index must be an integer");
    if (i < 0) i += res->nbr;
    if (i < 0 || i >= res->nbr)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, NULL, "branch index out of range (the result has %d)", res->nbr);
    return branch_result(r, res->br[i], out, err);
  }
  const rp_sol *so = script_handle_ptr(h);
  const cable_solution *s = so->br->sol[so->isol];
  const char *k = script_string_chars(key);
  if (!k) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "a solution is indexed by a name ('T', 'LAB', 'PAR(3)')");
  int idx = -1;
  if (strcmp(k, "LAB") == 0) *out = script_integer(s->lab);
  else if (strcmp(k, "BR") == 0) *out = script_integer(s->ibr);
  else if (strcmp(k, "PT") == 0) *out = script_integer(s->ntot);
  else if (strcmp(k, "TY") == 0) return script_string_new(out, cable_type_name(s->itp), strlen(cable_type_name(s->itp)));
  else if (strcmp(k, "kind") == 0) {
    /* how the detector found a BP: 'simple', 'double', 'pair'; '' otherwise or when read from a file */
    static const char *const kinds[] = {"", "simple", "double", "pair"};
    const char *kd = s->bp_kind >= 0 && s->bp_kind <= CABLE_BP_PAIR ? kinds[s->bp_kind] : "";
    return script_string_new(out, kd, strlen(kd));
  }
  else if (sscanf(k, "PAR(%d)", &idx) == 1 && idx >= 1 && idx <= s->npar) *out = script_number(s->par[idx - 1]);
  else if ((idx = cable_names_par_index(&so->br->names, k, NULL, 0)) >= 0 && idx < s->npar) *out = script_number(s->par[idx]);
  else return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, k, "no such parameter (names: the problem's parnames, PAR(k), LAB, BR, PT, TY, kind)");
  return 0;
}

static void rp_describe(void *ctx, const script_value *h, char *buf, size_t len)
{
  (void)ctx;
  if (script_handle_kind(h) == SCRIPT_HANDLE_RESULT) {
    const rp_result *res = script_handle_ptr(h);
    int nsol = 0;
    for (int k = 0; k < res->nbr; k++) nsol += res->br[k]->nsol;
    snprintf(buf, len, "<result: %d branch%s, %d labelled solution%s>", res->nbr, res->nbr == 1 ? "" : "es", nsol,
             nsol == 1 ? "" : "s");
  } else {
    const rp_sol *so = script_handle_ptr(h);
    const cable_solution *s = so->br->sol[so->isol];
    const char *ty = cable_type_name(s->itp);
    snprintf(buf, len, "<solution %s label %d, branch %d>", ty[0] ? ty : "-", s->lab, s->ibr);
  }
}

static void rp_print(void *ctx, const char *line)
{
  cable_replay *r = ctx;
  fprintf(rp_log(r), "%s\n", line);
}

/* ---- files: save, load, merge, relabel, clean ------------------------------------------ */

static int rp_save(void *ctx, const script_value *data, const char *name, cable_error *err)
{
  cable_replay *r = ctx;
  int rc;
  if (script_handle_kind(data) == SCRIPT_HANDLE_SOLUTION) {
    /* one solution: a one-point result */
    const rp_sol *so = script_handle_ptr(data);
    rp_branch *b = rp_branch_alloc(so->br->ibr, &so->br->c, &so->br->names, so->br->e);
    const cable_point *pt = rp_sol_point(so->br, so->isol);
    rp_result *res = rp_result_alloc(1);
    rc = b && pt && res ? rp_branch_add(b, pt, so->br->sol[so->isol]) : CABLE_ERR_ALLOC;
    if (res) res->br[0] = b;
    else rp_branch_decref(b);
    if (!rc) rc = rp_result_write(r, res, name, 0, err);
    else cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    rp_result_free(res);
  } else {
    rc = rp_result_write(r, script_handle_ptr(data), name, 0, err);
  }
  if (!rc) fprintf(rp_log(r), "  saved to b.%s, s.%s, d.%s\n", name, name, name);
  return rc;
}

/* Branch numbers and labels of files read in: new runs continue after them. */
static void note_result(cable_replay *r, const rp_result *res)
{
  for (int k = 0; k < res->nbr; k++) {
    note_label(r, 0, res->br[k]->ibr);
    for (int i = 0; i < res->br[k]->nsol; i++) note_label(r, res->br[k]->sol[i]->lab, 0);
  }
}

static int read_named(cable_replay *r, const char *name, rp_result **res, cable_error *err)
{
  rp_setup s;
  memset(&s, 0, sizeof s);
  s.c = r->cur;
  s.names = r->cur_names;
  snprintf(s.e, sizeof s.e, "%s", r->cur_e);
  int rc = read_constants_file(r, name, &s, 0, err);
  if (!rc) rc = rp_result_read(r, name, &s.c, &s.names, s.e, res, err);
  if (!rc) note_result(r, *res);
  return rc;
}

static int rp_load(void *ctx, int what, const script_value *data, const script_kwargs *kw, script_value *out,
                   cable_error *err)
{
  cable_replay *r = ctx;
  if (what == SCRIPT_LOAD_RESULT) {
    if (!data || data->type != SCRIPT_STRING)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "loadbd needs a name (files b.NAME, s.NAME)");
    if (kw && kw->n) return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, kw->items[0].name, "loadbd takes no keywords");
    rp_result *res = NULL;
    int rc = read_named(r, script_string_chars(data), &res, err);
    return rc ? rc : wrap_result(r, res, out, err);
  }
  /* load(...): a solution with its constants; also the runner's new state */
  rp_setup s;
  int rc = build_setup(r, data, kw, 0, NULL, &s, err);
  /* AUTO's load('name') / load(s='name') without IRS: the file's last solution */
  int n = s.sf ? cable_sfile_count(s.sf) : 0;
  if (!rc && !s.start && n > 0 && s.c.irs == 0 && !s.c.irs_name[0]) s.start = cable_sfile_get(s.sf, n - 1);
  if (!rc && s.start) {
    rp_branch *b = rp_branch_alloc(s.start->ibr, &s.c, &s.names, s.e);
    cable_point pt;
    memset(&pt, 0, sizeof pt);
    pt.ibr = s.start->ibr;
    pt.pt = s.start->ntot;
    pt.itp = s.start->itp;
    pt.lab = s.start->lab;
    pt.ndim = s.start->ndim;
    pt.npar = s.start->npar;
    pt.nicp = s.c.nicp > 0 ? s.c.nicp : s.start->nfpr;
    pt.icp = s.c.nicp > 0 ? s.c.icp : s.start->icp;
    pt.par = s.start->par;
    rc = b ? rp_branch_add(b, &pt, s.start) : CABLE_ERR_ALLOC;
    if (!rc) rc = wrap_solution(r, b, 0, out, err);
    else cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    rp_branch_decref(b);
  }
  if (!rc) remember(r, &s);
  setup_free(&s);
  return rc;
}

static int transform(cable_replay *r, const script_value *data, script_value *out, cable_error *err,
                     int (*fn)(const rp_result *, rp_result **))
{
  rp_result *res = NULL;
  if (data->type == SCRIPT_STRING) {   /* files rewritten in place */
    const char *name = script_string_chars(data);
    int rc = read_named(r, name, &res, err);
    rp_result *t = NULL;
    if (!rc && (rc = fn(res, &t))) cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    if (!rc) rc = rp_result_write(r, t, name, 0, err);
    rp_result_free(res);
    rp_result_free(t);
    return rc;
  }
  const rp_result *in = as_result(data, "merge/relabel", err);
  if (!in) return CABLE_ERR_INPUT;
  int rc = fn(in, &res);
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  return wrap_result(r, res, out, err);
}

static int rp_merge(void *ctx, const script_value *data, script_value *out, cable_error *err)
{
  return transform(ctx, data, out, err, rp_result_merge);
}

static int rp_relabel(void *ctx, const script_value *data, script_value *out, cable_error *err)
{
  return transform(ctx, data, out, err, rp_result_relabel);
}

static int rp_clean(void *ctx, cable_error *err)
{
  (void)err;
  fprintf(rp_log(ctx), "  clean: nothing to delete (cable writes no fort.* or object files)\n");
  return 0;
}

/* ---- session ---------------------------------------------------------------------- */

cable_replay *cable_replay_alloc(const cable_replay_options *opt)
{
  cable_replay *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  if (opt) r->opt = *opt;
  cable_constants_init(&r->cur);
  cable_names_init(&r->cur_names);
  script_host *h = &r->host;
  h->ctx = r;
  h->run = rp_run;
  h->select = rp_select;
  h->add = rp_add;
  h->items = rp_items;
  h->getitem = rp_getitem;
  h->load = rp_load;
  h->save = rp_save;
  h->merge = rp_merge;
  h->relabel = rp_relabel;
  h->clean = rp_clean;
  h->describe = rp_describe;
  h->print = rp_print;
  h->release = rp_release;
  h->call = rp_call;
  return r;
}

void cable_replay_free(cable_replay *r)
{
  if (!r) return;
  for (int i = 0; i < r->nplugins; i++) cable_plugin_close(r->plugin[i]);
  for (int i = 0; i < r->nautoeq; i++) cable_autoeq_close(r->autoeq[i]);
  free(r);
}

const script_host *cable_replay_host(cable_replay *r)
{
  return &r->host;
}

int cable_replay_run_file(const char *path, const cable_replay_options *opt, cable_error *err)
{
  cable_replay *r = cable_replay_alloc(opt);
  if (!r) return cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
  int rc = script_run_file(path, &r->host, err);
  cable_replay_free(r);
  return rc;
}
