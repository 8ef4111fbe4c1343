/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The session: AUTO-07p's runner on cable's continuation engine, constants
 * parser and b./s./d. files.  Branches live in memory (cable_session_store.c);
 * files are written only by sv=, ap=, save, and merge/relabel of file names. */
#include "cable/cable_session.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cable/cable_analysis.h"
#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "cable/cable_bpcont.h"
#include "cable/cable_fold.h"
#include "cable/cable_status.h"
#include "cable_session_impl.h"
#include "live_files.h"
#include "run_guard.h"

void cable_session_options_init(cable_session_options *o)
{
  if (o) memset(o, 0, sizeof *o);
}

/* ---- the API contract: NULL and inconsistent arguments (doc/api.md) -------------- */

/* CABLE_ERR_NULL naming the argument of fn. */
static int null_arg(const char *fn, const char *what, cable_error *err)
{
  return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "%s: %s is NULL", fn, what);
}

/* A list of n branches: n >= 0, and when n > 0 an array without NULL entries. */
static int check_branch_list(const char *fn, cable_branch *const *list, int n, cable_error *err)
{
  if (n < 0) return cable_error_set(err, CABLE_ERR_SIZE, NULL, 0, "n", "%s: %d branches (a count < 0)", fn, n);
  if (n > 0 && !list) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "%s: %d branches but the list is NULL", fn, n);
  for (int k = 0; k < n; k++)
    if (!list[k]) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "%s: branch %d of %d is NULL", fn, k + 1, n);
  return 0;
}

/* The run arguments agree with themselves: counts with their arrays, at
 * most one start, a solution index inside its branch. */
static int check_run_args(const char *fn, const cable_run_args *a, cable_error *err)
{
  int rc = check_branch_list(fn, a->branches, a->nbranch, err);
  if (rc) return rc;
  if (a->nover < 0) return cable_error_set(err, CABLE_ERR_SIZE, NULL, 0, NULL, "%s: nover = %d (a count < 0)", fn, a->nover);
  if (a->nover > 0 && !a->over)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "%s: nover = %d but over is NULL", fn, a->nover);
  for (int i = 0; i < a->nover; i++)
    if (!a->over[i]) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "%s: override %d of %d is NULL", fn, i + 1, a->nover);
  if (a->sol_branch && a->nbranch > 0)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "%s: a solution and a result given as the start (at most one)", fn);
  if (a->sol_branch && (a->sol_index < 0 || a->sol_index >= cable_branch_nsolutions(a->sol_branch)))
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, NULL, "%s: solution index %d outside the branch's 0..%d", fn,
                           a->sol_index, cable_branch_nsolutions(a->sol_branch) - 1);
  return 0;
}

static FILE *rp_log(const cable_session *r) { return r->opt.log ? r->opt.log : stdout; }

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

static void problem_release(cable_session *r, rp_problem *p)
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
static int plugin_problem(cable_session *r, const char *e, const cable_problem **pb, cable_error *err)
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
static void rp_path_plain(const cable_session *r, const char *name, char *buf, size_t len)
{
  const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
  snprintf(buf, len, "%s%s%s", dir && name[0] != '/' ? dir : "", dir && name[0] != '/' ? "/" : "", name);
}

/* An AUTO equation file for e=NAME (NAME.f90, NAME.f or NAME.c in the run
 * directory), built and loaded once per session; its problem takes NDIM,
 * NBC, NINT and NPAR from c (c NULL: a problem good for names only). */
static int autoeq_problem(cable_session *r, const char *e, const cable_constants *c, const cable_problem **pb,
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
static int find_problem(cable_session *r, const char *e, const cable_constants *c, int from_stpnt,
                        rp_problem *out, cable_error *err)
{
  out->pb = out->tmpl = NULL;
  out->user = 0;
  out->autoeq = 0;
  if (!e[0])
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "e", "no problem given (e='NAME' in the call or the constants file)");
  const cable_session_problems *up = r->opt.problems;
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

int rp_session_info(cable_session *r, const char *e, FILE *out, cable_error *err)
{
  if (!r || !e || !out) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_session_info: NULL argument");
  rp_problem p;
  int rc = find_problem(r, e, NULL, 0, &p, err);
  if (rc) return rc;
  const char *src = NULL;
  for (int k = 0; p.autoeq && k < r->nautoeq; k++)
    if (strcmp(r->autoeq_name[k], e) == 0) src = cable_autoeq_source(r->autoeq[k]);
  rc = rp_problem_info_write(p.pb, p.autoeq ? (src ? src : e) : NULL, out);
  problem_release(r, &p);
  return rc;
}

/* ---- run setup: constants, problem, start ----------------------------------------- */

typedef struct rp_setup {
  cable_constants c;
  cable_names names;
  char e[CABLE_NAME_MAX];
  const cable_solution *start;   /* borrowed from a branch or from sf */
  const rp_branch *start_br;     /* the branch of a start given as a solution or result */
  int start_isol;                /* and its index there */
  cable_sfile *sf;               /* s.NAME of a string start or s= (owned), or the runner's */
  int sf_borrowed;               /* sf is the runner's (cable_session.cur_sf): not freed here */
  int forget_sf;                 /* run('NAME') without s.NAME: the runner's solutions are dropped */
  int fatal;                     /* the branch ended with a user routine's fatal (negative) status */
  char fatal_msg[640];
  char sfpath[1024];             /* its path */
  char sv[CABLE_NAME_MAX], ap[CABLE_NAME_MAX];
  int mbr, mlab;                 /* AUTO's MBR, MLAB: the restart data's largest branch number and label */
  rp_problem found;              /* the problem found_e names, looked up once per run (setup_problem) */
  char found_e[CABLE_NAME_MAX];
} rp_setup;

static void setup_free(cable_session *r, rp_setup *s)
{
  if (!s->sf_borrowed) cable_sfile_free(s->sf);
  s->sf = NULL;
  s->sf_borrowed = 0;
  problem_release(r, &s->found);
  s->found_e[0] = '\0';
}

/* The problem e names, for its parameter names and keys (no constants yet):
 * looked up once per run and kept in s until setup_free; *pb NULL for
 * e "".  A problem that cannot be had (unknown name, rejected plug-in) is
 * an error naming e. */
static int setup_problem(cable_session *r, rp_setup *s, const char *e, const cable_problem **pb, cable_error *err)
{
  *pb = NULL;
  if (!e[0]) return 0;
  if (!s->found.tmpl || strcmp(s->found_e, e) != 0) {
    problem_release(r, &s->found);
    s->found_e[0] = '\0';
    int rc = find_problem(r, e, NULL, 0, &s->found, err);
    if (rc) return rc;
    snprintf(s->found_e, sizeof s->found_e, "%s", e);
  }
  *pb = s->found.pb;
  return 0;
}

/* The problem instance a run uses: the one setup_problem found, prepared
 * for c, when what it is does not depend on the constants (a built-in or
 * plug-in problem); a user's (opt.problems) or an AUTO equation file's is
 * made for c (its dimensions come from them).  Release out after use. */
static int run_problem(cable_session *r, rp_setup *s, const cable_constants *c, int from_stpnt, rp_problem *out,
                       cable_error *err)
{
  if (!s->found.tmpl || s->found.user || s->found.autoeq || strcmp(s->found_e, s->e) != 0)
    return find_problem(r, s->e, c, from_stpnt, out, err);
  memset(out, 0, sizeof *out);
  const cable_problem *inst = NULL;
  int rc = cable_problem_prepare(s->found.tmpl, c, from_stpnt, &inst, err);
  if (rc) return rc;
  out->tmpl = s->found.tmpl;
  out->pb = inst;
  return 0;
}

/* The session's way to find the problem a constants file names, for the
 * parser (cable_constants_parse_file_resolve). */
typedef struct {
  cable_session *r;
  rp_setup *s;
} resolve_ctx;

static int resolve_in_session(void *ctx, const char *e, const cable_problem **pb, cable_error *err)
{
  const resolve_ctx *x = ctx;
  return setup_problem(x->r, x->s, e, pb, err);
}

/* c.NAME, read once: the parser asks for the problem (the run's e, else the
 * file's) as soon as it knows its name, and reads the rest of the file with
 * its parameter names and keys. */
static int read_constants_file(cable_session *r, const char *name, rp_setup *s, int required,
                               cable_error *err)
{
  char path[1024];
  rp_path(r, "c", name, path, sizeof path);
  if (!required && !file_exists(path)) return 0;
  resolve_ctx ctx = {r, s};
  int rc = cable_constants_parse_file_resolve(path, s->e, resolve_in_session, &ctx, &s->c, &s->names, err);
  if (rc) return rc;
  if (!s->e[0]) snprintf(s->e, sizeof s->e, "%s", s->c.e);
  /* the file's names win; the problem names the rest (sol['lambda']) */
  const cable_problem *pb = NULL;
  rc = setup_problem(r, s, s->e, &pb, err);
  if (!rc && pb) cable_names_fill(&s->names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  return rc;
}

static int read_solutions_file(cable_session *r, const char *name, rp_setup *s, cable_error *err)
{
  char path[1024];
  rp_path(r, "s", name, path, sizeof path);
  snprintf(s->sfpath, sizeof s->sfpath, "%s", path);
  if (!s->sf_borrowed) cable_sfile_free(s->sf);
  s->sf_borrowed = 0;
  s->sf = cable_sfile_read(path, err);
  return s->sf ? 0 : (err && err->status ? err->status : CABLE_ERR_IO);
}

/* The last solution of a result (its branch and index in s). */
static const cable_solution *result_last(const rp_result *res, rp_setup *st)
{
  for (int k = res->nbr - 1; k >= 0; k--)
    if (res->br[k]->nsol > 0) {
      st->start_br = res->br[k];
      st->start_isol = res->br[k]->nsol - 1;
      return res->br[k]->sol[st->start_isol];
    }
  return NULL;
}

/* A solution of a result by IRS (a label, or 'BP1'-style in irs_name). */
static const cable_solution *result_irs(const rp_result *res, const cable_constants *c, rp_setup *st)
{
  int type = 0, nth = 0;
  if (c->irs_name[0] && cable_label_spec_parse(c->irs_name, &type, &nth) != 0) return NULL;
  for (int k = 0; k < res->nbr; k++)
    for (int i = 0; i < res->br[k]->nsol; i++) {
      const cable_solution *s = res->br[k]->sol[i];
      if (c->irs_name[0] ? (cable_type_base(s->itp) == type && --nth == 0) : s->lab == c->irs) {
        st->start_br = res->br[k];
        st->start_isol = i;
        return s;
      }
    }
  return NULL;
}

/* AUTO's load/run argument handling: the base constants from the data (or
 * the runner), then c=, e=, s=, sv=, ap=, then every other keyword as an
 * override, then the start. */
/* A name argument (e=, c=, s=, sv=, ap=): non-empty and short enough. */
static int name_arg(const char *key, const char *v, char *dst, size_t len, cable_error *err)
{
  if (!v[0] || strlen(v) >= len)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key, "must be a non-empty name of at most %zu characters",
                           len - 1);
  snprintf(dst, len, "%s", v);
  return 0;
}

/* ---- AUTO's NEWLAB: the restart data's largest branch number and label ---------------- */

static void max_into(int *m, int v)
{
  if (v > *m) *m = v;
}

/* A branch's branch number and labels, and those of the data it was loaded from. */
static void branch_maxima(const rp_branch *b, int *mbr, int *mlab)
{
  max_into(mbr, b->ibr);
  max_into(mbr, b->src_mbr);
  max_into(mlab, b->src_mlab);
  for (int i = 0; i < b->nsol; i++) max_into(mlab, b->sol[i]->lab);
}

static void sfile_maxima(const cable_sfile *sf, int *mbr, int *mlab)
{
  for (int i = 0; i < cable_sfile_count(sf); i++) {
    max_into(mbr, cable_sfile_get(sf, i)->ibr);
    max_into(mlab, cable_sfile_get(sf, i)->lab);
  }
}

/* MBR and MLAB (AUTO's NEWLAB reads them from the restart data it is given):
 * for a solution, the bundle it was taken from (AUTO's _mbr, _mlab, written
 * as the dummy header after it), for a result all its branches, for an
 * s-file the whole file; 0 and 0 for a start from STPNT. */
static void restart_maxima(const cable_session *r, const cable_run_args *a, const rp_result *res, rp_setup *s)
{
  s->mbr = s->mlab = 0;
  if (!s->start) return;
  if (a->sol_branch) {
    max_into(&s->mbr, a->sol_mbr);
    max_into(&s->mlab, a->sol_mlab);
    branch_maxima(a->sol_branch, &s->mbr, &s->mlab);
  } else if (res) {
    for (int k = 0; k < res->nbr; k++) branch_maxima(res->br[k], &s->mbr, &s->mlab);
  } else if (s->sf) {
    sfile_maxima(s->sf, &s->mbr, &s->mlab);
  } else if (s->start_br && s->start_br == r->cur_br) {
    max_into(&s->mbr, r->cur_mbr);
    max_into(&s->mlab, r->cur_mlab);
    branch_maxima(s->start_br, &s->mbr, &s->mlab);
  }
  max_into(&s->mbr, s->start->ibr);
  max_into(&s->mlab, s->start->lab);
}

/* IRS among the call's overrides ("IRS=3", "IRS = 'UZ1'"). */
static int irs_in_call(const cable_run_args *a)
{
  for (int i = 0; i < a->nover; i++) {
    const char *p = a->over[i];
    while (*p == ' ' || *p == '\t') p++;
    if (strncmp(p, "IRS", 3) != 0) continue;
    p += 3;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '=') return 1;
  }
  return 0;
}

/* AUTO's load/run argument handling: the base constants from the start (or
 * the runner), then c=, e=, s=, sv=, ap=, then every override, then the
 * start. */
static int build_setup(cable_session *r, const cable_run_args *a, rp_setup *s, cable_error *err)
{
  memset(s, 0, sizeof *s);
  rp_result view = {a->nbranch, (rp_branch **)a->branches};
  const rp_result *res = NULL;
  int rc = 0;
  if (a->sol_branch || a->nbranch > 0) {
    const rp_branch *b;
    if (a->sol_branch) {
      b = a->sol_branch;
      if (a->sol_index < 0 || a->sol_index >= b->nsol)
        return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "no such solution in the branch");
      s->start = b->sol[a->sol_index];
      s->start_br = b;
      s->start_isol = a->sol_index;
    } else {
      res = &view;
      b = res->br[res->nbr - 1];
    }
    s->c = b->has_c_user ? b->c_user : b->c;
    s->names = b->names;
    snprintf(s->e, sizeof s->e, "%s", b->e);
    /* a stored solution's IRS is history: AUTO resets it; so are PAR and U
       (AUTO's bifDiag.nonekeys): the PAR={'T': 0.0} of the run that computed
       the solution would otherwise move a restart from it */
    s->c.irs = 0;
    s->c.irs_name[0] = '\0';
    s->c.npar_override = 0;
    s->c.lab = 0;   /* nor LAB (bifDiag's nonekeys) */
  } else {
    s->c = r->cur;
    s->names = r->cur_names;
    snprintf(s->e, sizeof s->e, "%s", r->cur_e);
  }
  s->c.s[0] = s->c.sv[0] = '\0';   /* one-off, like IRS: set below for this run */
  if (a->sv) rc = name_arg("sv", a->sv, s->sv, sizeof s->sv, err);
  if (!rc && a->ap) rc = name_arg("ap", a->ap, s->ap, sizeof s->ap, err);
  if (!rc && a->e) rc = name_arg("e", a->e, s->e, sizeof s->e, err);
  /* a constants file's s= and sv= count for the run that reads it, under
     the keywords (AUTO: keyword arguments override the c-file) */
  char cfile_s[CABLE_NAME_MAX] = "", cfile_sv[CABLE_NAME_MAX] = "";
  if (!rc && a->name) {
    /* run('NAME') is AUTO's e='NAME', c='NAME', s='NAME': the equations
       NAME (an explicit e= wins), c.NAME and s.NAME when they exist.  When
       there is no problem NAME, the c-file's e names it (cable's
       extension: c.knot72 says e='braid_knot'). */
    char name[CABLE_NAME_MAX];
    rc = name_arg("run", a->name, name, sizeof name, err);
    if (!rc && !a->e) {
      const cable_problem *pb;
      s->e[0] = '\0';
      rc = setup_problem(r, s, name, &pb, err);
      if (rc == 0) snprintf(s->e, sizeof s->e, "%s", name);
      if (rc == CABLE_ERR_NOTFOUND) {
        rc = 0;
        cable_error_clear(err);
      }
    }
    /* c= names the run's constants: c.NAME is then neither read nor checked */
    if (!rc && !a->c) rc = read_constants_file(r, name, s, 0, err);
    if (!rc && !a->c) snprintf(cfile_sv, sizeof cfile_sv, "%s", s->c.sv);
    char spath[1024];
    rp_path(r, "s", name, spath, sizeof spath);
    if (!rc && file_exists(spath)) {
      rc = read_solutions_file(r, name, s, err);
      if (!rc) snprintf(s->c.s, sizeof s->c.s, "%s", name);
    } else {
      s->forget_sf = 1;   /* AUTO: load('NAME') without s.NAME erases the runner's solutions */
    }
    if (!rc && !s->e[0]) snprintf(s->e, sizeof s->e, "%s", name);
  }
  if (!rc && a->c) {
    char name[CABLE_NAME_MAX];
    rc = name_arg("c", a->c, name, sizeof name, err);
    if (!rc) rc = read_constants_file(r, name, s, 1, err);
    if (!rc && a->e) snprintf(s->e, sizeof s->e, "%s", a->e);
    if (!rc) {
      snprintf(cfile_s, sizeof cfile_s, "%s", s->c.s);
      snprintf(cfile_sv, sizeof cfile_sv, "%s", s->c.sv);
    }
  }
  int has_start = a->sol_branch || a->nbranch > 0 || a->name;
  if (!rc && a->s) {
    char name[CABLE_NAME_MAX];
    rc = name_arg("s", a->s, name, sizeof name, err);
    if (!rc) rc = read_solutions_file(r, name, s, err);
    if (!rc) snprintf(s->c.s, sizeof s->c.s, "%s", name);
  } else if (!rc && cfile_s[0] && !has_start) {
    rc = read_solutions_file(r, cfile_s, s, err);   /* an explicit start wins over the file's s= */
  } else if (!rc && !s->sf) {
    s->c.s[0] = '\0';
  }
  /* no start of its own: AUTO's runner restarts from the solutions of its
     last load or run (ld(s='x', IRS=3); run() restarts from label 3 of s.x),
     as the runner's IRS (or this call's) selects */
  int runner_start = !rc && !has_start && !a->s && !cfile_s[0];
  if (runner_start && r->cur_sf) {
    s->sf = r->cur_sf;
    s->sf_borrowed = 1;
    snprintf(s->sfpath, sizeof s->sfpath, "%s", r->cur_sfpath);
  }
  if (!rc && cfile_sv[0] && !s->sv[0] && !s->ap[0]) snprintf(s->sv, sizeof s->sv, "%s", cfile_sv);
  if (!rc) snprintf(s->c.sv, sizeof s->c.sv, "%s", s->sv);   /* the b-file header says where it went */
  if (rc) return rc;
  const cable_problem *pb = NULL;
  rc = setup_problem(r, s, s->e, &pb, err);
  /* A first run from nothing but keywords (no constants file, no start, no
     earlier run or load whose constants the runner keeps) takes its
     problem's recommended constants as defaults, under the keywords: the
     braid problems' are the scenes' settings (cable_problem_recommended) */
  const char *rec = cable_problem_recommended(s->e);
  char cpath[1024];
  if (a->name) rp_path(r, "c", a->name, cpath, sizeof cpath);
  int cfile = a->c || (a->name && file_exists(cpath));
  if (!rc && rec && !cfile && !a->sol_branch && a->nbranch == 0 && !a->s && !cfile_s[0] && !r->cur_e[0]) {
    rc = cable_constants_parse_override_for(rec, pb, &s->c, &s->names, err);
    if (!rc) fprintf(rp_log(r), "  %s: no constants file: the problem's recommended constants apply under the "
                     "keywords (cable info e=%s)\n", s->e, s->e);
  }
  for (int i = 0; i < a->nover && !rc; i++) {
    rc = cable_constants_parse_override_for(a->over[i], pb, &s->c, &s->names, err);
    if (rc && err && !err->file[0] && a->over_file) {
      snprintf(err->file, sizeof err->file, "%s", a->over_file);
      err->line = 0;   /* the message quotes the argument */
    }
  }
  if (rc) return rc;
  snprintf(s->c.e, sizeof s->c.e, "%s", s->e);
  int irs_given = s->c.irs != 0 || s->c.irs_name[0];
  if (runner_start && !r->cur_sf && r->cur_br && irs_given) {
    /* one remembered solution: AUTO restarts from it unless IRS=0 */
    s->start = r->cur_br->sol[r->cur_isol];
    s->start_br = r->cur_br;
    s->start_isol = r->cur_isol;
  }
  if (res) {
    s->start = irs_given ? result_irs(res, &s->c, s) : result_last(res, s);
    if (!s->start)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, "IRS",
                             irs_given ? "no such label in the result" : "the result has no labelled solution");
  } else if (!s->start && s->sf && irs_given) {
    /* the solution itself: a label repeats in a file of several runs (NEWLAB),
       so 'UZ2' or -n is not looked up again by the label it resolves to, and
       the runner's own solution (its last load or run) is kept while IRS is
       its label */
    const cable_solution *kept =
        s->sf_borrowed && !a->c && !irs_in_call(a) && !s->c.irs_name[0] ? cable_sfile_get(s->sf, r->cur_pick) : NULL;
    char spec[CABLE_NAME_MAX + 16];
    if (s->c.irs_name[0]) snprintf(spec, sizeof spec, "%s", s->c.irs_name);
    else snprintf(spec, sizeof spec, "%d", s->c.irs);
    s->start = kept && kept->lab == s->c.irs ? kept : cable_sfile_find(s->sf, spec, err);
    if (!s->start) {
      if (err && !err->file[0]) snprintf(err->file, sizeof err->file, "%.500s", s->sfpath);
      return err && err->status ? err->status : CABLE_ERR_NOTFOUND;
    }
    s->c.irs = s->start->lab;   /* as cable_sfile_resolve_irs: the label it picked */
    s->c.irs_name[0] = '\0';
  } else if (!s->start && irs_given) {
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "IRS",
                           "a restart needs solutions: give a result, a solution, a name or s='NAME'");
  }
  restart_maxima(r, a, res, s);
  return 0;
}

/* ---- run ------------------------------------------------------------------------- */

typedef struct collector {
  rp_branch *b;
  FILE *diag;
  FILE *log;        /* the labelled points and notes as they come (AUTO's screen lines) */
  int rc;
  int tty;          /* stderr is a terminal: show the progress line */
  int (*interrupt)(void *ctx);   /* the session's interrupt check (NULL: none) */
  void *interrupt_ctx;
  int interrupted;
  rp_live *live;    /* the run's files, written as it goes (NULL: no sv= or ap=) */
  cable_sink out;   /* live's sink */
  int out_rc;       /* the first failure writing them */
  cable_error out_err;
  rp_guard *guard;  /* the user's routines' watch (NULL: cable's own problem) */
  const char *e, *out_name;
} collector;

static void guard_where(rp_guard *g, const collector *c, const char *e, const char *out_name);

static double now_seconds(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *par_name(const cable_names *n, int k, char *buf, size_t len);

/* One-line live progress on a terminal (stderr), rewritten in place. */
static void progress(const collector *c, const cable_point *pt)
{
  if (!c->tty) return;
  int k = pt->nicp > 0 ? pt->icp[0] : 0;
  char nm[64];
  fprintf(stderr, "\r  branch %d  point %5d  %s = %-14.8g ds = %-9.3g Newton %d   ", pt->ibr, pt->pt,
          par_name(&c->b->names, k, nm, sizeof nm), pt->par[k], pt->ds, pt->newton_iters);
  fflush(stderr);
}

/* AUTO prints every labelled point of a run as it is computed; so does the
 * host, with the engine's remarks on the point (special points it could not
 * locate, rejected steps, double branch points; also in the d-file). */
static void log_point(const collector *c, const cable_point *p)
{
  char nm[64];
  if (c->tty && (p->note || p->lab > 0)) fprintf(stderr, "\r%*s\r", 100, "");
  if (p->note) fprintf(c->log, "  PT %5d: %s\n", p->pt, p->note);
  if (p->lab > 0) {
    int k = p->nicp > 0 ? p->icp[0] : 0;
    const char *ty = cable_type_name(p->itp);
    fprintf(c->log, "  BR %4d  PT %5d  TY %-2s  LAB %4d  %s = %.10g  L2-NORM = %.10g\n", p->ibr, p->pt,
            ty[0] ? ty : "-", p->lab, par_name(&c->b->names, k, nm, sizeof nm), p->par[k], p->l2norm);
  }
  if (p->note || p->lab > 0) fflush(c->log);   /* through a pipe too, as it happens */
}

/* Every point is kept and, with sv= or ap=, on disk before the next step
 * (published once its solution, if any, is written); an interrupt stops the
 * run after the point just computed. */
static int collect_point(void *ctx, const cable_point *pt)
{
  collector *c = ctx;
  progress(c, pt);
  if (c->diag && pt->note) fprintf(c->diag, "%s\n", pt->note);
  log_point(c, pt);
  /* a labelled point's solution comes next, with the same point: add both then */
  if (pt->lab <= 0 && !c->rc) c->rc = rp_branch_add(c->b, pt, NULL);
  if (c->live && !c->out_rc) {
    c->out_rc = c->out.point(c->out.ctx, pt);
    if (!c->out_rc && pt->lab <= 0) c->out_rc = rp_live_publish(c->live, &c->out_err);
  }
  if (c->interrupt && c->interrupt(c->interrupt_ctx)) c->interrupted = 1;
  if (c->guard && pt->lab <= 0) guard_where(c->guard, c, c->e, c->out_name);
  /* the engine stops here (CABLE_ERR_INTERRUPTED); a user routine's fatal
     return too (the run reports it) */
  return c->interrupted || c->rc || c->out_rc || (c->guard && c->guard->fatal);
}

static int collect_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  collector *c = ctx;
  if (!c->rc) c->rc = rp_branch_add(c->b, pt, sol);
  if (c->live && !c->out_rc) {
    c->out_rc = c->out.solution(c->out.ctx, pt, sol);
    if (!c->out_rc) c->out_rc = rp_live_publish(c->live, &c->out_err);
  }
  if (c->guard) guard_where(c->guard, c, c->e, c->out_name);
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

/* The run's end (its points were printed as they came: log_point). */
static void log_branch(const cable_session *r, const rp_branch *b, int status, const char *why, double seconds)
{
  FILE *f = rp_log(r);
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

/* What messages call a user's problem e ("equation file ./x.f90", "plug-in
 * ./x.so"); 0 for cable's own problems (not watched). */
static int user_origin(const cable_session *r, const char *e, char *buf, size_t len)
{
  for (int i = 0; i < r->nautoeq; i++)
    if (strcmp(r->autoeq_name[i], e) == 0) {
      snprintf(buf, len, "equation file %s", cable_autoeq_source(r->autoeq[i]));
      return 1;
    }
  for (int i = 0; i < r->nplugins; i++)
    if (strcmp(r->plugin_name[i], e) == 0) {
      snprintf(buf, len, "plug-in %s", cable_plugin_path(r->plugin[i]));
      return 1;
    }
  return 0;
}

/* The guard's text: the run, its last point and its files. */
static void guard_where(rp_guard *g, const collector *c, const char *e, const char *out_name)
{
  char text[RP_GUARD_TEXT], at[64] = "before its first point";
  const rp_branch *b = c->b;
  if (b->npt > 0) snprintf(at, sizeof at, "after PT %d", b->pts[b->npt - 1].pt.pt);
  if (out_name && b->npt > 0)
    snprintf(text, sizeof text, "during branch %d of e='%s', %s; the points so far are in b.%s, s.%s, d.%s", b->ibr, e,
             at, out_name, out_name, out_name);
  else
    snprintf(text, sizeof text, "during branch %d of e='%s', %s%s", b->ibr, e, at,
             out_name ? "; nothing of the run is saved yet" : " (no sv=: nothing is saved)");
  rp_guard_set_where(g, text);
}

/* A switch (ISW < 0) at a double branch point of the flat braid_knot or
 * braid_link: the full formulation has a two-dimensional kernel there and
 * almost every direction in it is a rotated copy of the buckling pattern, so
 * the switched run crawls along an almost free rotation (doc/knot72.md
 * section 2: 40 steps moved T by 0.0018).  The S0-symmetric formulation has
 * one direction left and follows the branch.  The run goes ahead (the
 * engine's switch at a double BP, BPDIR/BPANGLE, is a tool of its own,
 * tests/python/test_link_scenes.py), with a note that says what to do. */
static void note_double_switch(cable_session *r, const rp_setup *s)
{
  if (s->c.isw >= 0 || !s->start || s->start->bp_kind != CABLE_BP_DOUBLE) return;
  const char *sym = strcmp(s->e, "braid_knot") == 0 ? "braid_knot_sym" : strcmp(s->e, "braid_link") == 0 ? "braid_link_sym" : NULL;
  if (!sym) return;
  fprintf(rp_log(r), "  note: label %d (%s = %.7g) is a double branch point: %s cannot follow a branch from it "
          "(almost every direction of its two-dimensional kernel is a rotation of the buckling pattern, and the "
          "switch crawls along it); switch in the S0-symmetric formulation, where it is simple: run(bp, e='%s', "
          "ICP=[... 'eps13' ...], ISW=-1, ISP=0) (cable info e=%s; runs/knot72/c.knot72sym; doc/knot72.md "
          "sections 2-4)\n", s->start->lab, s->names.par[0][0] ? s->names.par[0] : "PAR(1)", s->start->par[0], s->e,
          sym, sym);
}

/* One run; out_name (NULL: none) gets its b./s./d. files as it goes
 * (out_append: AUTO's ap=).  An interrupted run returns
 * CABLE_ERR_INTERRUPTED with its branch in *out. */
static int engine_run(cable_session *r, rp_setup *s, const char *out_name, int out_append, rp_branch **out,
                      cable_error *err)
{
  *out = NULL;
  if (s->c.ips != 4) {
    /* a constants file without IPS means AUTO's IPS=1 (algebraic
       equilibria), never silently another problem type; a value other than
       4 was refused at its line when read */
    const cable_key_origin *o = &s->c.origin_ips;
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, o->file[0] ? o->file : "<no constants file>", o->line, "IPS",
                           "IPS=%d%s is a problem type cable does not solve: cable solves boundary-value problems "
                           "(IPS=4); write IPS = 4 in the constants file (or give IPS=4)",
                           s->c.ips, o->line ? "" : " (not set: AUTO's default)");
  }
  note_double_switch(r, s);
  rp_problem prob;
  int rc = run_problem(r, s, &s->c, s->start == NULL, &prob, err);
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
  /* AUTO's equations switch branches the way AUTO orients them, cable's own problems
     theirs (a restart keeps the stored constants: set it for this run's problem) */
  s->c.bp_orient_auto = prob.autoeq;
  /* a user's routines run under a watch: one that ends the process is named */
  char origin[600];
  rp_guard *guard = NULL;
  if (user_origin(r, s->e, origin, sizeof origin)) {
    if (!(guard = malloc(sizeof *guard))) {
      problem_release(r, &prob);
      return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    }
    rp_guard_init(guard, pb, origin);
    pb = &guard->pb;
  }
  if (s->c.ignored[0] && strcmp(s->c.ignored, r->noted_ignored) != 0) {
    fprintf(rp_log(r), "  note: accepted and ignored, as AUTO does for boundary-value problems: %s\n", s->c.ignored);
    snprintf(r->noted_ignored, sizeof r->noted_ignored, "%s", s->c.ignored);
  }
  int st = 0;
  /* ISW = 2 at an LP: the fold's extended problem, its constants (ICP with
     the null vector's parameter slots) and its own start (cable_fold.h) */
  cable_fold *fold = NULL;
  cable_bpcont *bpc = NULL;
  const cable_constants *crun = &s->c;
  const cable_solution *start = s->start;
  /* ISW = 2 at a BP, or from a point of a curve of branch points (type 6x):
     branch-point continuation (cable_bpcont.h), in AUTO's two runs as the
     fold's below */
  int at_bp = s->c.isw == 2 && s->start &&
              ((s->start->ndim == pb->ndim && cable_type_base(s->start->itp) == 6) ||
               (s->start->ndim == 2 * pb->ndim && abs(s->start->itp) / 10 == CABLE_BPCONT_ITPST));
  if (at_bp) {
    st = cable_bpcont_create(pb, &s->c, s->start, &bpc, err);
    int curve_restart = s->start->ndim == 2 * pb->ndim;
    if (!st && !curve_restart) st = cable_bpcont_starting_data(bpc, err);
    if (st) {
      cable_bpcont_free(bpc);
      problem_release(r, &prob);
      if (err) snprintf(err->key, sizeof err->key, "ISW");
      return st;
    }
    if (!curve_restart) fprintf(rp_log(r), "  Generating starting data : Restart at EP label below :\n");
    pb = cable_bpcont_problem(bpc);
    crun = cable_bpcont_constants(bpc);
    start = curve_restart ? cable_bpcont_start(bpc) : NULL;
  } else if (s->c.isw == 2) {
    st = cable_fold_create(pb, &s->c, s->start, &fold, err);
    if (st) {
      problem_release(r, &prob);
      free(guard);
      if (err) snprintf(err->key, sizeof err->key, "ISW");
      return st;
    }
    /* a point of a fold curve (NDIM = 2n) restarts the curve as it is
       stored, with its direction (run(r2) after a fold run goes on, as in
       AUTO); at an LP the run is AUTO's first one: it generates the curve's
       starting data (five steps along the null vector's norm, one EP label)
       through the extended problem's STPNT, and the next run from that EP
       follows the curve (doc/fold-continuation.md, "AUTO's runs") */
    int curve_restart = s->start && s->start->ndim == 2 * pb->ndim;
    if (!curve_restart && (st = cable_fold_starting_data(fold, err)) != 0) {
      cable_fold_free(fold);
      cable_bpcont_free(bpc);
      problem_release(r, &prob);
      if (err) snprintf(err->key, sizeof err->key, "ISW");
      return st;
    }
    if (!curve_restart) fprintf(rp_log(r), "  Generating starting data : Restart at EP label below :\n");
    pb = cable_fold_problem(fold);
    crun = cable_fold_constants(fold);
    start = curve_restart ? cable_fold_start(fold) : NULL;
  }
  cable_names_fill(&s->names, pb->parnames, pb->npar, pb->unames, pb->ndim);
  st = cable_cont_check(pb, crun, err);
  if (st) {
    cable_fold_free(fold);
    cable_bpcont_free(bpc);
    problem_release(r, &prob);
    free(guard);
    return st;
  }
  cable_cont *cc = cable_cont_alloc(pb, crun, &st);
  if (!cc) {
    cable_fold_free(fold);
    cable_bpcont_free(bpc);
    problem_release(r, &prob);
    free(guard);
    return cable_error_set(err, st, NULL, 0, NULL, "could not set up the solver: %s", cable_status_message(st));
  }
  if (st == 0 && (fold || bpc)) {
    /* the fold run starts on the LP's mesh, the branch-point run on the BP's */
    double *mesh = malloc((size_t)(crun->ntst + 1) * sizeof *mesh);
    if (!mesh) st = CABLE_ERR_ALLOC;
    if (mesh) {
      if (fold) cable_fold_mesh(fold, crun->ntst, mesh);
      else cable_bpcont_mesh(bpc, crun->ntst, mesh);
      st = cable_cont_set_mesh(cc, mesh);
      free(mesh);
    }
  }
  /* the branch points earlier branches computed (cable_session_add_known) */
  if (st == 0) st = rp_session_known_to(r, cc, pb->ndim);
  if (st == 0) st = cable_cont_set_start(cc, start);
  if (st) {
    /* the engine's report: its message and the key it is about (PAR) */
    cable_error why;
    cable_cont_last_error(cc, &why);
    cable_error_set(err, st, NULL, 0, why.key, "%s", why.msg[0] ? why.msg : cable_status_message(st));
    cable_cont_free(cc);
    cable_fold_free(fold);
    cable_bpcont_free(bpc);
    problem_release(r, &prob);
    free(guard);
    return st;
  }
  /* AUTO's NEWLAB: a new branch number after a start from STPNT, a switch
     or (ISW = -2 inside AUTO) the starting data of a fold curve, MBR + 1
     (auto-07p, demo int: its run 2 from LP4 of branch 1 is branch 2); a
     restart, a fold curve's from its starting data included, keeps the
     start's branch number */
  int ibr = s->mbr + 1;
  if (s->start && s->c.isw >= 0 && !((fold || bpc) && start == NULL)) ibr = s->start->ibr;
  double t_start = now_seconds();
  collector col;
  memset(&col, 0, sizeof col);
  col.b = rp_branch_alloc(ibr, crun, &s->names, s->e);
  col.diag = r->opt.diag;
  col.log = rp_log(r);
  col.tty = isatty(fileno(stderr));
  col.interrupt = r->opt.interrupt;
  col.interrupt_ctx = r->opt.interrupt_ctx;
  if (col.b && (fold || bpc)) {
    col.b->has_c_user = 1;
    col.b->c_user = s->c;
  }
  if (!col.b) {
    cable_cont_free(cc);
    cable_fold_free(fold);
    cable_bpcont_free(bpc);
    problem_release(r, &prob);
    free(guard);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  }
  /* the files are open (and NAME locked) before the first step */
  if (out_name) {
    const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
    col.live = rp_live_open(dir, out_name, out_append, &col.b->c, &col.b->names, rp_log(r), err);
    if (!col.live) {
      rp_branch_decref(col.b);
      cable_cont_free(cc);
      cable_fold_free(fold);
      cable_bpcont_free(bpc);
      problem_release(r, &prob);
      free(guard);
      return err && err->status ? err->status : CABLE_ERR_IO;
    }
    col.out = rp_live_sink(col.live);
  }
  col.guard = guard;
  col.e = s->e;
  col.out_name = out_name;
  if (guard) guard_where(guard, &col, s->e, out_name);
  cable_sink sink = {&col, collect_point, collect_solution, collect_diag};
  /* LAB > 0: the run's first label (AUTO's LAB), else NEWLAB's MLAB + 1 */
  int first_lab = s->c.lab > 0 ? s->c.lab : s->mlab + 1, next = first_lab;
  st = cable_cont_run(cc, &sink, ibr, first_lab, &next);
  char why[512], end_note[600], fatal[1200] = "";
  /* an error's message, or the closed loop's (it names the point the branch returned to) */
  snprintf(why, sizeof why, "%s", st < 0 || st == CABLE_END_LOOP ? cable_cont_error(cc) : "");
  if (guard && guard->fatal) {
    /* doc/plugins.md: a negative return is fatal; the run ends with what it has */
    snprintf(fatal, sizeof fatal, "the %s routine of %s returned %d (fatal)", guard->fatal_routine, guard->origin,
             guard->fatal);
    snprintf(why, sizeof why, "%.500s", fatal);
    if (st >= 0 || st == CABLE_ERR_INTERRUPTED) st = CABLE_ERR_PLUGIN;
  } else if (st == CABLE_ERR_INTERRUPTED && col.interrupted)
    snprintf(why, sizeof why, "stopped after PT %d (a signal, or KeyboardInterrupt); the points before are complete",
             col.b->npt > 0 ? col.b->pts[col.b->npt - 1].pt.pt : 0);
  snprintf(end_note, sizeof end_note, "branch %d ended: %s: %s", ibr, cable_status_message(st), why);
  if (!col.rc && (st < 0 || st == CABLE_END_LOOP)) col.rc = rp_branch_set_end_note(col.b, end_note);
  col.b->end_status = st;
  col.b->ndirs = cable_cont_branches(cc, col.b->dirs, CABLE_MAX_BRANCHES, &col.b->dir_order);
  cable_cont_free(cc);
  cable_fold_free(fold);
  cable_bpcont_free(bpc);
  problem_release(r, &prob);
  free(guard);
  if (col.tty) fprintf(stderr, "\r%*s\r", 100, "");
  int live_rc = col.out_rc;
  if (col.live && col.b->npt == 0) {
    rp_live_abort(col.live);   /* nothing computed: the files stay as they were */
  } else if (col.live) {
    /* close reports a failed write again, with its message */
    cable_error cerr;
    cable_error_clear(&cerr);
    int rc2 = rp_live_close(col.live, col.b->end_note, &cerr);
    if (!live_rc) live_rc = rc2;
    if (live_rc && err) *err = col.out_err.msg[0] ? col.out_err : cerr;
  }
  if (live_rc) {
    rp_branch_decref(col.b);
    return live_rc;
  }
  if (col.rc) {
    rp_branch_decref(col.b);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory keeping the branch");
  }
  if (st == CABLE_ERR_INTERRUPTED) {
    const rp_branch *b = col.b;
    const cable_point *last = b->npt > 0 ? &b->pts[b->npt - 1].pt : NULL;
    char nm[64], at[160] = "before its first point";
    if (last) {
      int k = last->nicp > 0 ? last->icp[0] : 0;
      snprintf(at, sizeof at, "after PT %d (%s = %.10g)", last->pt, par_name(&b->names, k, nm, sizeof nm),
               last->par[k]);
    }
    char files[1200];
    if (out_name && b->npt > 0) {
      snprintf(files, sizeof files, "its %d points (%d labelled) are in b.%s, s.%s, d.%s", b->npt, b->nsol,
               out_name, out_name, out_name);
    } else {
      snprintf(files, sizeof files, "its %d points are kept in memory only (no sv=)", b->npt);
    }
    cable_error_set(err, st, NULL, 0, NULL, "branch %d of e='%s' interrupted %s; %s", ibr, s->e, at, files);
    *out = col.b;
    return st;
  }
  if (fatal[0]) {
    const rp_branch *b = col.b;
    char files[1200] = "";
    if (out_name && b->npt > 0)
      snprintf(files, sizeof files, "; its %d points before are in b.%s, s.%s, d.%s", b->npt, out_name, out_name,
               out_name);
    cable_error_set(err, CABLE_ERR_PLUGIN, NULL, 0, NULL, "%s during branch %d of e='%s'%s", fatal, ibr, s->e, files);
    rp_branch_decref(col.b);
    return CABLE_ERR_PLUGIN;
  }
  if (st < 0 && col.b->npt == 0) {
    rp_branch_decref(col.b);
    return cable_error_set(err, st, NULL, 0, NULL, "no point converged: %s", why[0] ? why : cable_status_message(st));
  }
  /* like AUTO, a branch that ends abnormally (MX) is still a result; a
     user routine's fatal return (doc/plugins.md) also fails the run once its
     points are saved (cable_session_run) */
  if (st == CABLE_ERR_CALLBACK) {
    s->fatal = st;
    snprintf(s->fatal_msg, sizeof s->fatal_msg, "branch %d ended after %d points: %s", col.b->ibr, col.b->npt, why);
  }
  log_branch(r, col.b, st, why, now_seconds() - t_start);
  *out = col.b;
  return 0;
}

/* AUTO's runner keeps the constants of the last run or load, and the
 * solutions it started from: the s-file it read (taken over from s), or the
 * one solution it was given; IRS becomes the label it started from (AUTO's
 * solution load sets IRS to the solution's LAB).  A run from STPNT keeps the
 * runner's solutions.  The save settings are one-off. */
static void remember(cable_session *r, rp_setup *s)
{
  /* the runner's solution in its s-file (labels may repeat in it): run()
     without a new IRS restarts from this one, as AUTO's selected solution */
  int pick = -1;
  for (int i = 0; s->sf && s->start && i < cable_sfile_count(s->sf); i++)
    if (cable_sfile_get(s->sf, i) == s->start) pick = i;
  if (s->sf) r->cur_pick = pick;
  r->cur = s->c;
  if (s->start) {
    r->cur.irs = s->start->lab;
    r->cur.irs_name[0] = '\0';
  }
  r->cur.s[0] = r->cur.sv[0] = '\0';
  r->cur_names = s->names;
  snprintf(r->cur_e, sizeof r->cur_e, "%s", s->e);
  if (s->forget_sf) {
    cable_sfile_free(r->cur_sf);
    r->cur_sf = NULL;
    rp_branch_decref(r->cur_br);
    r->cur_br = NULL;
  }
  if (s->sf && !s->sf_borrowed) {
    cable_sfile_free(r->cur_sf);
    r->cur_sf = s->sf;
    snprintf(r->cur_sfpath, sizeof r->cur_sfpath, "%s", s->sfpath);
    s->sf = NULL;
    rp_branch_decref(r->cur_br);
    r->cur_br = NULL;
  } else if (!s->sf && s->start_br) {
    if (s->start_br != r->cur_br) {
      rp_branch *b = (rp_branch *)s->start_br;
      __atomic_add_fetch(&b->refs, 1, __ATOMIC_RELAXED);
      rp_branch_decref(r->cur_br);
      r->cur_br = b;
      cable_sfile_free(r->cur_sf);
      r->cur_sf = NULL;
    }
    r->cur_isol = s->start_isol;
    r->cur_mbr = s->mbr;
    r->cur_mlab = s->mlab;
  }
}

int rp_session_run(cable_session *r, const cable_run_args *a, cable_branch **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!r || !a || !out) return null_arg("cable_session_run", !r ? "the session" : !a ? "the arguments" : "out", err);
  int rc = check_run_args("cable_session_run", a, err);
  if (rc) return rc;
  rp_setup s;
  rp_branch *b = NULL;
  rc = build_setup(r, a, &s, err);
  /* output names are checked before anything is computed */
  if (!rc && s.sv[0]) rc = rp_out_name_check("sv", s.sv, err);
  if (!rc && s.ap[0]) rc = rp_out_name_check("ap", s.ap, err);
  /* sv= is written as the run goes (ap= too, when there is no sv=) */
  const char *live = s.sv[0] ? s.sv : s.ap[0] ? s.ap : NULL;
  if (!rc) rc = engine_run(r, &s, live, !s.sv[0], &b, err);
  if (!rc && !a->keep_state) remember(r, &s);
  rp_result res = {1, &b};
  if (!rc && s.sv[0] && s.ap[0]) rc = rp_result_write(r, &res, s.ap, 1, err);
  if (!rc && (s.sv[0] || s.ap[0]))
    fprintf(rp_log(r), "  %s b.%s, s.%s, d.%s\n", s.sv[0] ? "saved to" : "appended to", s.sv[0] ? s.sv : s.ap,
            s.sv[0] ? s.sv : s.ap, s.sv[0] ? s.sv : s.ap);
  if (!rc && s.sv[0] && s.ap[0]) fprintf(rp_log(r), "  appended to b.%s, s.%s, d.%s\n", s.ap, s.ap, s.ap);
  if (!rc && s.fatal)
    rc = cable_error_set(err, s.fatal, NULL, 0, NULL, "%s%s%s", s.fatal_msg,
                         s.sv[0] || s.ap[0] ? "; its points are saved to b./s./d." : "", s.sv[0] ? s.sv : s.ap);
  fflush(rp_log(r));
  setup_free(r, &s);
  if (rc && rc != CABLE_ERR_INTERRUPTED) rp_branch_decref(b);
  else *out = b;
  return rc;
}

/* ---- files: save, load, merge, relabel ------------------------------------------------ */

int rp_session_save(cable_session *r, cable_branch *const *branches, int n, int sol_index, const char *name,
                    int append, cable_error *err)
{
  if (!r || !name) return null_arg("cable_session_save", !r ? "the session" : "the name", err);
  int rc = check_branch_list("cable_session_save", branches, n, err);
  if (rc) return rc;
  char nm[CABLE_NAME_MAX];
  rc = name_arg("save", name, nm, sizeof nm, err);
  if (rc) return rc;
  if (sol_index >= 0) {
    /* one solution: a one-point result */
    const rp_branch *src = n > 0 ? branches[0] : NULL;
    if (!src || sol_index >= src->nsol)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "no such solution in the branch");
    rp_branch *b = rp_branch_alloc(src->ibr, &src->c, &src->names, src->e);
    const cable_point *pt = rp_sol_point(src, sol_index);
    rc = b && pt ? rp_branch_add(b, pt, src->sol[sol_index]) : CABLE_ERR_ALLOC;
    rp_result one = {1, &b};
    if (!rc) rc = rp_result_write(r, &one, nm, append, err);
    else cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    rp_branch_decref(b);
  } else {
    rp_result res = {n, (rp_branch **)branches};
    rc = rp_result_write(r, &res, nm, append, err);
  }
  if (!rc) fprintf(rp_log(r), "  %s b.%s, s.%s, d.%s\n", append ? "appended to" : "saved to", nm, nm, nm);
  return rc;
}

static int read_named(cable_session *r, const char *name, rp_result **res, cable_error *err)
{
  rp_setup s;
  memset(&s, 0, sizeof s);
  s.c = r->cur;
  s.names = r->cur_names;
  snprintf(s.e, sizeof s.e, "%s", r->cur_e);
  char nm[CABLE_NAME_MAX];
  int rc = name_arg("loadbd", name, nm, sizeof nm, err);
  if (!rc) rc = read_constants_file(r, nm, &s, 0, err);
  /* what the b-file's header records (AUTO's parseB reads it): the problem
     and the names the columns were written with */
  char path[1024], e[sizeof s.e];
  int has_names = 0;
  rp_path(r, "b", nm, path, sizeof path);
  if (!rc) rp_bfile_header(path, e, sizeof e, &s.names, &has_names, &s.c);
  if (!rc && e[0]) {
    snprintf(s.e, sizeof s.e, "%s", e);
    snprintf(s.c.e, sizeof s.c.e, "%s", e);
  }
  if (!rc) rc = rp_result_read(r, nm, &s.c, &s.names, s.e, res, err);
  setup_free(r, &s);
  return rc;
}

/* The branches of a result handed over to a caller's list (the result freed). */
static int result_to_list(rp_result *res, cable_branch ***out, int *n, cable_error *err)
{
  *out = calloc((size_t)(res->nbr > 0 ? res->nbr : 1), sizeof **out);
  if (!*out) {
    rp_result_free(res);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  }
  *n = res->nbr;
  for (int k = 0; k < res->nbr; k++) {
    (*out)[k] = res->br[k];
    res->br[k] = NULL;
  }
  res->nbr = 0;
  rp_result_free(res);
  return 0;
}

int rp_session_loadbd(cable_session *r, const char *name, cable_branch ***out, int *n, cable_error *err)
{
  if (out) *out = NULL;
  if (n) *n = 0;
  if (!r || !name || !out || !n)
    return null_arg("cable_session_loadbd", !r ? "the session" : !name ? "the name" : !out ? "out" : "n", err);
  rp_result *res = NULL;
  int rc = read_named(r, name, &res, err);
  return rc ? rc : result_to_list(res, out, n, err);
}

int rp_session_load(cable_session *r, const cable_run_args *a, cable_branch **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!r || !a || !out) return null_arg("cable_session_load", !r ? "the session" : !a ? "the arguments" : "out", err);
  int rc = check_run_args("cable_session_load", a, err);
  if (rc) return rc;
  rp_setup s;
  rc = build_setup(r, a, &s, err);
  /* AUTO's load('name') / load(s='name') without IRS: the file's last solution */
  int n = s.sf ? cable_sfile_count(s.sf) : 0;
  if (!rc && !s.start && n > 0 && s.c.irs == 0 && !s.c.irs_name[0]) {
    s.start = cable_sfile_get(s.sf, n - 1);
    restart_maxima(r, a, NULL, &s);
  }
  /* no solution (a run from STPNT): AUTO's ld(e=..., c=...) sets the runner's constants only */
  if (!rc && s.start) {
    rp_branch *b = rp_branch_alloc(s.start->ibr, &s.c, &s.names, s.e);
    if (b) {
      b->src_mbr = s.mbr;   /* a run from it numbers on after its restart data, as AUTO's */
      b->src_mlab = s.mlab;
    }
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
    if (rc) {
      cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
      rp_branch_decref(b);
    } else {
      *out = b;
    }
  }
  if (!rc) remember(r, &s);
  setup_free(r, &s);
  return rc;
}

int rp_session_transform(cable_session *r, cable_branch *const *in, int n, int relabel, cable_branch ***out,
                         int *nout, cable_error *err)
{
  if (out) *out = NULL;
  if (nout) *nout = 0;
  if (!r || !out || !nout)
    return null_arg("cable_session_transform", !r ? "the session" : !out ? "out" : "nout", err);
  int rc = check_branch_list("cable_session_transform", in, n, err);
  if (rc) return rc;
  rp_result view = {n, (rp_branch **)in}, *res = NULL;
  rc = relabel ? rp_result_relabel(&view, &res) : rp_result_merge(&view, &res);
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  return result_to_list(res, out, nout, err);
}

int rp_session_transform_files(cable_session *r, const char *name, int relabel, cable_error *err)
{
  if (!r || !name) return null_arg("cable_session_transform_files", !r ? "the session" : "the name", err);
  rp_result *res = NULL, *t = NULL;
  int rc = read_named(r, name, &res, err);
  if (!rc && (rc = relabel ? rp_result_relabel(res, &t) : rp_result_merge(res, &t)))
    cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  if (!rc) rc = rp_result_write(r, t, name, 0, err);
  rp_result_free(res);
  rp_result_free(t);
  return rc;
}

void cable_session_path(const cable_session *r, const char *type, const char *name, char *buf, size_t len)
{
  if (!buf || len == 0) return;
  buf[0] = '\0';
  if (!r || !name) return;
  if (type) {
    rp_path(r, type, name, buf, len);
    return;
  }
  int rel = name[0] != '/' && r->opt.dir && r->opt.dir[0];
  snprintf(buf, len, "%s%s%s", rel ? r->opt.dir : "", rel ? "/" : "", name);
}

void cable_branch_incref(cable_branch *b)
{
  if (b) __atomic_add_fetch(&b->refs, 1, __ATOMIC_RELAXED);
}

void cable_branch_decref(cable_branch *b)
{
  rp_branch_decref(b);
}

void cable_branch_list_free(cable_branch **list, int n)
{
  for (int k = 0; list && k < n; k++) rp_branch_decref(list[k]);
  free(list);
}

/* ---- session ---------------------------------------------------------------------- */

cable_session *cable_session_alloc(const cable_session_options *opt)
{
  cable_session *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  if (opt) r->opt = *opt;
  cable_constants_init(&r->cur);
  cable_names_init(&r->cur_names);
  r->cur_pick = -1;
  return r;
}

void cable_session_free(cable_session *r)
{
  if (!r) return;
  for (int i = 0; i < r->nplugins; i++) cable_plugin_close(r->plugin[i]);
  for (int i = 0; i < r->nautoeq; i++) cable_autoeq_close(r->autoeq[i]);
  cable_sfile_free(r->cur_sf);
  rp_branch_decref(r->cur_br);
  rp_session_known_free(r);
  free(r);
}
