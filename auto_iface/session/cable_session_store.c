/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The engine host's results in memory: branches of copied points and
 * solutions, shared by reference counting; writing them as b./s./d. files,
 * reading them back, AUTO's merge and relabel. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_status.h"
#include "cable_session_impl.h"
#include "live_files.h"

rp_branch *rp_branch_alloc(int ibr, const cable_constants *c, const cable_names *names, const char *e)
{
  rp_branch *b = calloc(1, sizeof *b);
  if (!b) return NULL;
  b->refs = 1;
  b->ibr = ibr;
  b->ndirs = -1;
  b->c = *c;
  if (names) b->names = *names;
  else cable_names_init(&b->names);
  snprintf(b->e, sizeof b->e, "%s", e ? e : "");
  return b;
}

void rp_branch_decref(rp_branch *b)
{
  /* atomic: Python threads drop references while another session's run holds one */
  if (!b || __atomic_sub_fetch(&b->refs, 1, __ATOMIC_ACQ_REL) > 0) return;
  for (int i = 0; i < b->npt; i++) {
    free(b->pts[i].mem);
    free(b->pts[i].note);
  }
  for (int i = 0; i < b->nsol; i++) cable_solution_free(b->sol[i]);
  free(b->end_note);
  free(b->pts);
  free(b->sol);
  free(b);
}

static char *copy_text(const char *text)
{
  size_t len = strlen(text) + 1;
  char *c = malloc(len);
  if (c) memcpy(c, text, len);
  return c;
}

int rp_branch_set_end_note(rp_branch *b, const char *text)
{
  free(b->end_note);
  b->end_note = NULL;
  if (text && text[0] && !(b->end_note = copy_text(text))) return CABLE_ERR_ALLOC;
  return 0;
}

/* A copy of *pt whose arrays live in one block. */
static int point_copy(rp_point *dst, const cable_point *pt)
{
  size_t ni = (size_t)(pt->nicp > 0 ? pt->nicp : 0), np = (size_t)(pt->npar > 0 ? pt->npar : 0);
  size_t nd = (size_t)(pt->ndim > 0 ? pt->ndim : 0);
  double *d = malloc((np + nd + 1) * sizeof(double) + (ni + 1) * sizeof(int));
  if (!d) return CABLE_ERR_ALLOC;
  char *note = NULL;
  if (pt->note && pt->note[0] && !(note = copy_text(pt->note))) {
    free(d);
    return CABLE_ERR_ALLOC;
  }
  dst->pt = *pt;
  dst->mem = d;
  dst->note = note;
  dst->pt.note = note;
  if (pt->par) memcpy(d, pt->par, np * sizeof *d);
  else memset(d, 0, np * sizeof *d);
  if (pt->umax) memcpy(d + np, pt->umax, nd * sizeof *d);
  else memset(d + np, 0, nd * sizeof *d);
  int *ic = (int *)(void *)(d + np + nd + 1);
  if (pt->icp) memcpy(ic, pt->icp, ni * sizeof *ic);
  dst->pt.par = d;
  dst->pt.umax = d + np;
  dst->pt.icp = ic;
  dst->sol = -1;
  return 0;
}

/* Solution q's BP kind read back from a d-file, on the solution and on its
 * point (the branch is still being built). */
static void branch_set_bp_kind(rp_branch *b, int q, int kind)
{
  b->sol[q]->bp_kind = kind;
  for (int k = 0; k < b->npt; k++)
    if (b->pts[k].sol == q) {
      b->pts[k].pt.bp_kind = kind;
      b->pts[k].pt.bp_mult = cable_bp_multiplicity(kind);
    }
}

int rp_branch_add(rp_branch *b, const cable_point *pt, const cable_solution *sol)
{
  if (b->npt == b->cappt) {
    int cap = b->cappt ? 2 * b->cappt : 64;
    rp_point *p = realloc(b->pts, (size_t)cap * sizeof *p);
    if (!p) return CABLE_ERR_ALLOC;
    b->pts = p;
    b->cappt = cap;
  }
  if (sol && b->nsol == b->capsol) {
    int cap = b->capsol ? 2 * b->capsol : 16;
    cable_solution **s = realloc(b->sol, (size_t)cap * sizeof *s);
    if (!s) return CABLE_ERR_ALLOC;
    b->sol = s;
    b->capsol = cap;
  }
  cable_solution *copy = NULL;
  if (sol && !(copy = cable_solution_clone(sol))) return CABLE_ERR_ALLOC;
  if (point_copy(&b->pts[b->npt], pt)) {
    cable_solution_free(copy);
    return CABLE_ERR_ALLOC;
  }
  if (copy) {
    b->pts[b->npt].sol = b->nsol;
    b->sol[b->nsol++] = copy;
  }
  b->npt++;
  return 0;
}

rp_branch *rp_branch_copy(const rp_branch *b)
{
  rp_branch *n = rp_branch_alloc(b->ibr, &b->c, &b->names, b->e);
  if (!n) return NULL;
  n->has_c_user = b->has_c_user;
  n->c_user = b->c_user;
  n->end_status = b->end_status;
  for (int i = 0; i < b->npt; i++) {
    const rp_point *p = &b->pts[i];
    if (rp_branch_add(n, &p->pt, p->sol >= 0 ? b->sol[p->sol] : NULL)) {
      rp_branch_decref(n);
      return NULL;
    }
  }
  if (rp_branch_set_end_note(n, b->end_note)) {
    rp_branch_decref(n);
    return NULL;
  }
  return n;
}

const cable_point *rp_sol_point(const rp_branch *b, int isol)
{
  for (int i = 0; i < b->npt; i++)
    if (b->pts[i].sol == isol) return &b->pts[i].pt;
  return NULL;
}

rp_result *rp_result_alloc(int nbr)
{
  rp_result *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  r->br = calloc((size_t)(nbr > 0 ? nbr : 1), sizeof *r->br);
  if (!r->br) {
    free(r);
    return NULL;
  }
  r->nbr = nbr;
  return r;
}

void rp_result_free(rp_result *r)
{
  if (!r) return;
  for (int i = 0; i < r->nbr; i++) rp_branch_decref(r->br[i]);
  free(r->br);
  free(r);
}

void rp_path(const cable_session *r, const char *type, const char *name, char *buf, size_t len)
{
  const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
  if (dir && name[0] != '/') snprintf(buf, len, "%s/%s.%s", dir, type, name);
  else snprintf(buf, len, "%s.%s", type, name);
}

/* ---- files ------------------------------------------------------------------- */

int rp_result_write(const cable_session *r, const rp_result *res, const char *name, int append,
                    cable_error *err)
{
  if (res->nbr == 0)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, name, "the result is empty: nothing to save");
  cable_aufile_options o;
  cable_aufile_options_init(&o);
  o.append = append;
  o.write_csv = 1;   /* b.NAME.<k>.csv beside AUTO's files, for every saved result */
  const char *dir = r->opt.dir && r->opt.dir[0] ? r->opt.dir : NULL;
  if (rp_out_name_check(append ? "ap" : "sv", name, err)) return err && err->status ? err->status : CABLE_ERR_INPUT;
  /* NAME's lock: no other writer mixes its files with these (live_files.h) */
  rp_lock *lock = rp_lock_take(dir, name, r->opt.log ? r->opt.log : stdout, err);
  if (!lock) return err && err->status ? err->status : CABLE_ERR_IO;
  cable_aufile *w = cable_aufile_open(dir, name, &res->br[0]->c, &res->br[0]->names, &o, err);
  if (!w) {
    rp_lock_release(lock);
    return err && err->status ? err->status : CABLE_ERR_IO;
  }
  cable_sink s = cable_aufile_sink(w);
  int rc = 0;
  for (int k = 0; k < res->nbr && !rc; k++) {
    const rp_branch *b = res->br[k];
    cable_aufile_set_constants(w, &b->c);
    for (int i = 0; i < b->npt && !rc; i++) {
      const rp_point *p = &b->pts[i];
      rc = s.point(s.ctx, &p->pt);
      if (!rc && p->sol >= 0) rc = s.solution(s.ctx, &p->pt, b->sol[p->sol]);
    }
    if (!rc && b->end_note) s.diag(s.ctx, b->end_note);
  }
  /* close reports a failed callback again, with its message */
  int rc2 = cable_aufile_close(w, err);
  rp_lock_release(lock);
  return rc2 ? rc2 : rc;
}

/* AUTO's L2-NORM of a stored solution, for rows the b-file does not give:
 * sqrt(int_0^1 |u|^2 dt) by the trapezoidal rule on the stored points. */
static double l2norm_estimate(const cable_solution *s)
{
  int n = cable_solution_npts(s);
  double sum = 0;
  for (int k = 0; k + 1 < n; k++) {
    double a = 0, b = 0;
    for (int i = 0; i < s->ndim; i++) {
      a += s->u[k * s->ndim + i] * s->u[k * s->ndim + i];
      b += s->u[(k + 1) * s->ndim + i] * s->u[(k + 1) * s->ndim + i];
    }
    sum += 0.5 * (a + b) * (s->t[k + 1] - s->t[k]);
  }
  return sqrt(sum);
}

/* The run each solution of sf belongs to, run[i], and its b-file row's
 * norm, l2[i] (NAN: none).  AUTO's parseB splits a b-file into branches at
 * its header lines (a run's start), and its bifDiag gives the labelled rows
 * of each branch the s-file's solutions in order; so do these, when the
 * b-file's labelled rows are the s-file's labels in order.  Without such a
 * b-file a run starts where the branch number changes or the point number
 * does not increase (every run starts at PT 1).  Branch numbers alone do not
 * split runs: AUTO numbers two runs from STPNT both branch 1. */
static int assign_runs(const cable_sfile *sf, const cable_bfile *bf, int *run, double *l2)
{
  int n = cable_sfile_count(sf), i = 0, ok = bf != NULL;
  for (int j = 0; ok && j < bf->nbranch; j++) {
    const cable_bfile_branch *bb = &bf->branch[j];
    const double *col = cable_bfile_column(bb, "L2-NORM");
    for (int q = 0; ok && q < bb->nrow; q++) {
      if (bb->lab[q] == 0) continue;
      if (i >= n || cable_sfile_get(sf, i)->lab != bb->lab[q]) ok = 0;
      else {
        run[i] = j;
        l2[i++] = col ? col[q] : (double)NAN;
      }
    }
  }
  if (ok && i == n) return 1;
  for (i = 0; i < n; i++) {
    const cable_solution *s = cable_sfile_get(sf, i), *p = i > 0 ? cable_sfile_get(sf, i - 1) : NULL;
    run[i] = !p ? 0 : run[i - 1] + (s->ibr != p->ibr || abs(s->ntot) <= abs(p->ntot));
    l2[i] = (double)NAN;
    /* a b-file that does not pair with the s-file row by row: the norm of a row with the label */
    for (int j = 0; bf && j < bf->nbranch; j++) {
      const cable_bfile_branch *bb = &bf->branch[j];
      const double *col = cable_bfile_column(bb, "L2-NORM");
      for (int q = 0; col && q < bb->nrow && isnan(l2[i]); q++)
        if (bb->lab[q] == s->lab && bb->br[q] == s->ibr) l2[i] = col[q];
    }
  }
  return 0;
}

/* The d-file's note and BP kind on each solution of sf (its nth label lab:
 * the nth such line). */
static void solution_notes(const cable_sfile *sf, const rp_dnotes *dn, const char **notes, int *kinds)
{
  int n = cable_sfile_count(sf);
  for (int i = 0; i < n; i++) {
    const cable_solution *s = cable_sfile_get(sf, i);
    int nth = 0, lab = s->lab;
    for (int q = 0; q < i; q++) nth += cable_sfile_get(sf, q)->lab == lab;
    notes[i] = rp_dnotes_find(dn, lab, nth);
    kinds[i] = rp_dnotes_bp_kind(dn, s->itp, lab, nth);
  }
}

/* Every row of a b-file (at bpath) that pairs with its s-file row by row:
 * one branch per section (AUTO's parseB), labelled rows with their
 * solutions, each branch with the constants its section's header records
 * over c (AUTO's branch c). */
static int read_rows(const cable_sfile *sf, const cable_bfile *bf, const char *bpath, const rp_dnotes *dn,
                     const cable_constants *c, const cable_names *names, const char *e, rp_result **out)
{
  int n = cable_sfile_count(sf), nbr = 0, rc = 0;
  for (int j = 0; j < bf->nbranch; j++) nbr += bf->branch[j].nrow > 0;
  const cable_solution **sols = malloc((size_t)(n > 0 ? n : 1) * sizeof *sols);
  const char **notes = malloc((size_t)(n > 0 ? n : 1) * sizeof *notes);
  int *kinds = malloc((size_t)(n > 0 ? n : 1) * sizeof *kinds);
  rp_result *res = rp_result_alloc(nbr);
  cable_constants *cs = malloc(sizeof *cs);
  if (!sols || !notes || !kinds || !res || !cs) rc = CABLE_ERR_ALLOC;
  for (int i = 0; !rc && i < n; i++) sols[i] = cable_sfile_get(sf, i);
  if (!rc) solution_notes(sf, dn, notes, kinds);
  int i = 0, k = 0;
  for (int j = 0; !rc && j < bf->nbranch; j++) {
    const cable_bfile_branch *bb = &bf->branch[j];
    if (bb->nrow == 0) continue;
    *cs = *c;
    cable_names nm = *names;
    rp_bfile_section_constants(bpath, bb->first_line, &nm, cs);
    rc = rp_branch_from_rows(bb, sols + i, notes + i, cs, names, e, &res->br[k]);
    if (rc) break;
    rp_branch *b = res->br[k++];
    for (int q = 0; q < b->nsol; q++)
      if (dn->found) branch_set_bp_kind(b, q, kinds[i + q]);
    i += b->nsol;
  }
  free(sols);
  free(notes);
  free(kinds);
  free(cs);
  if (rc) {
    rp_result_free(res);
    return rc;
  }
  *out = res;
  return 0;
}

int rp_result_read(const cable_session *r, const char *name, const cable_constants *c,
                   const cable_names *names, const char *e, rp_result **out, cable_error *err)
{
  char path[1024];
  *out = NULL;
  rp_path(r, "s", name, path, sizeof path);
  cable_sfile *sf = cable_sfile_read(path, err);
  if (!sf) return err && err->status ? err->status : CABLE_ERR_IO;
  rp_path(r, "b", name, path, sizeof path);
  char bpath[sizeof path];
  snprintf(bpath, sizeof bpath, "%s", path);
  cable_error berr;
  cable_bfile *bf = cable_bfile_read(path, &berr);   /* optional: runs and norms */
  /* the engine's notes (d.NAME) give the labelled points their notes and the BPs their kinds */
  rp_dnotes dn;
  rp_path(r, "d", name, path, sizeof path);
  int rc = rp_dnotes_read(path, &dn);
  int n = cable_sfile_count(sf), nbr = 0;
  int *run = malloc((size_t)(n > 0 ? n : 1) * sizeof *run);
  double *l2 = malloc((size_t)(n > 0 ? n : 1) * sizeof *l2);
  if (!run || !l2) rc = CABLE_ERR_ALLOC;
  if (!rc && assign_runs(sf, bf, run, l2)) {
    /* the b-file pairs with the s-file: every row comes back, as AUTO's loadbd */
    rp_result *rows = NULL;
    rc = read_rows(sf, bf, bpath, &dn, c, names, e, &rows);
    free(run);
    free(l2);
    rp_dnotes_free(&dn);
    cable_bfile_free(bf);
    cable_sfile_free(sf);
    if (rc) return cable_error_set(err, rc, NULL, 0, name, "out of memory");
    *out = rows;
    return 0;
  }
  for (int i = 0; i < n && !rc; i++)
    if (i == 0 || run[i] != run[i - 1]) nbr++;
  rp_result *res = rc ? NULL : rp_result_alloc(nbr);
  if (!res) rc = CABLE_ERR_ALLOC;
  int k = -1;
  for (int i = 0; i < n && !rc; i++) {
    const cable_solution *s = cable_sfile_get(sf, i);
    if (i == 0 || run[i] != run[i - 1]) {
      res->br[++k] = rp_branch_alloc(s->ibr, c, names, e);
      if (!res->br[k]) {
        rc = CABLE_ERR_ALLOC;
        break;
      }
    }
    double umax[CABLE_NAMES_MAX];
    int nd = s->ndim < CABLE_NAMES_MAX ? s->ndim : CABLE_NAMES_MAX;
    /* AUTO's MAX U(d): the largest value of u_d over the stored points */
    for (int d = 0; d < nd; d++) {
      umax[d] = s->u[d];
      for (int q = 1; q < cable_solution_npts(s); q++) umax[d] = fmax(umax[d], s->u[q * s->ndim + d]);
    }
    cable_point pt;
    memset(&pt, 0, sizeof pt);
    pt.ibr = s->ibr;
    pt.pt = s->ntot;
    pt.itp = s->itp;
    pt.lab = s->lab;
    pt.ndim = nd;
    pt.npar = s->npar;
    pt.icp = c->nicp > 0 ? c->icp : s->icp;
    pt.nicp = c->nicp > 0 ? c->nicp : s->nfpr;
    pt.par = s->par;
    /* the b-file's row, when there is one, has the exact norm */
    pt.l2norm = isnan(l2[i]) ? l2norm_estimate(s) : l2[i];
    pt.umax = umax;
    pt.err_est = s->err_est;
    pt.measure = cable_solution_measure(s, c->iplt, pt.l2norm);
    /* the d-file's screen lines are in the s-file's order: a repeated label's nth one is its nth solution */
    int nth = 0;
    for (int q = 0; q < i; q++) nth += cable_sfile_get(sf, q)->lab == s->lab;
    pt.note = rp_dnotes_find(&dn, s->lab, nth);
    rc = rp_branch_add(res->br[k], &pt, s);
    if (!rc && dn.found)
      branch_set_bp_kind(res->br[k], res->br[k]->nsol - 1, rp_dnotes_bp_kind(&dn, s->itp, s->lab, nth));
  }
  free(run);
  free(l2);
  rp_dnotes_free(&dn);
  cable_bfile_free(bf);
  cable_sfile_free(sf);
  if (rc) {
    rp_result_free(res);
    return cable_error_set(err, rc, NULL, 0, name, "out of memory");
  }
  *out = res;
  return 0;
}

/* ---- merge and relabel --------------------------------------------------------- */

/* The first points of a and b are the same start: the same parameters and
 * norm to rounding (both runs converged the same start with the same
 * constants, so they agree far below this). */
#define RP_SAME_START_RTOL 1e-9

static int same_start(const rp_branch *a, const rp_branch *b)
{
  if (a->npt == 0 || b->npt == 0) return 0;
  const cable_point *p = &a->pts[0].pt, *q = &b->pts[0].pt;
  if (p->npar != q->npar || p->nicp < 1 || q->nicp < 1 || p->icp[0] != q->icp[0]) return 0;
  double x = p->par[p->icp[0]], y = q->par[q->icp[0]];
  return fabs(x - y) <= RP_SAME_START_RTOL * fmax(1, fabs(x)) &&
         fabs(p->l2norm - q->l2norm) <= RP_SAME_START_RTOL * fmax(1, fabs(p->l2norm));
}

/* b reversed, then a without its first point, as AUTO's merge (parseB):
 * the shared start keeps b's row, label and type; points are numbered 1, 2,
 * ... and labels from the smaller of a's and b's smallest label on, in the
 * new order (AUTO renumbers them so: no label repeats). */
static rp_branch *join(const rp_branch *a, const rp_branch *b)
{
  int lab = 0;
  for (int pass = 0; pass < 2; pass++) {
    const rp_branch *src = pass ? a : b;
    for (int j = 0; j < src->npt; j++)
      if (src->pts[j].pt.lab > 0 && (lab == 0 || src->pts[j].pt.lab < lab)) lab = src->pts[j].pt.lab;
  }
  rp_branch *n = rp_branch_alloc(a->ibr, &a->c, &a->names, a->e);
  if (!n) return NULL;
  n->has_c_user = a->has_c_user;
  n->c_user = a->c_user;
  int k = 0;
  for (int pass = 0; pass < 2; pass++) {
    const rp_branch *src = pass ? a : b;
    for (int j = 0; j < src->npt; j++) {
      int i = pass ? j : src->npt - 1 - j;
      if (pass && i == 0) continue;
      const rp_point *p = &src->pts[i];
      cable_point pt = p->pt;
      const cable_solution *sol = p->sol >= 0 ? src->sol[p->sol] : NULL;
      pt.ibr = a->ibr;
      pt.pt = ++k;
      if (pt.lab > 0) pt.lab = lab++;
      cable_solution *s2 = NULL;
      if (sol) {
        if (!(s2 = cable_solution_clone(sol))) {
          rp_branch_decref(n);
          return NULL;
        }
        s2->ibr = a->ibr;
        s2->ntot = k;
        s2->lab = pt.lab;
      }
      int rc = rp_branch_add(n, &pt, s2);
      cable_solution_free(s2);
      if (rc) {
        rp_branch_decref(n);
        return NULL;
      }
    }
  }
  return n;
}

int rp_result_merge(const rp_result *in, rp_result **out)
{
  rp_result *r = rp_result_alloc(in->nbr);
  if (!r) return CABLE_ERR_ALLOC;
  int n = 0;
  for (int i = 0; i < in->nbr; i++) {
    if (i + 1 < in->nbr && same_start(in->br[i], in->br[i + 1])) {
      /* AUTO keeps the forward run's direction: the second (backward) run is reversed */
      rp_branch *j = join(in->br[i], in->br[i + 1]);
      if (!j) {
        rp_result_free(r);
        return CABLE_ERR_ALLOC;
      }
      r->br[n++] = j;
      i++;
    } else {
      __atomic_add_fetch(&in->br[i]->refs, 1, __ATOMIC_RELAXED);
      r->br[n++] = in->br[i];
    }
  }
  r->nbr = n;
  *out = r;
  return 0;
}

int rp_result_relabel(const rp_result *in, rp_result **out)
{
  rp_result *r = rp_result_alloc(in->nbr);
  if (!r) return CABLE_ERR_ALLOC;
  int lab = 0;
  for (int i = 0; i < in->nbr; i++) {
    rp_branch *b = rp_branch_copy(in->br[i]);
    if (!b) {
      rp_result_free(r);
      return CABLE_ERR_ALLOC;
    }
    for (int k = 0; k < b->npt; k++) {
      if (b->pts[k].pt.lab <= 0) continue;
      b->pts[k].pt.lab = ++lab;
      if (b->pts[k].sol >= 0) b->sol[b->pts[k].sol]->lab = lab;
    }
    r->br[i] = b;
  }
  *out = r;
  return 0;
}

/* ---- what a branch holds (cable_session.h) ------------------------------------------ */

/* A NULL branch has nothing: 0 and NULL (doc/api.md, Contracts). */
int cable_branch_number(const cable_branch *b) { return b ? b->ibr : 0; }
int cable_branch_npoints(const cable_branch *b) { return b ? b->npt : 0; }
int cable_branch_nsolutions(const cable_branch *b) { return b ? b->nsol : 0; }
const cable_names *cable_branch_names(const cable_branch *b) { return b ? &b->names : NULL; }
const cable_constants *cable_branch_constants(const cable_branch *b) { return b ? &b->c : NULL; }
const char *cable_branch_problem(const cable_branch *b) { return b ? b->e : NULL; }
const char *cable_branch_end_note(const cable_branch *b) { return b ? b->end_note : NULL; }
int cable_branch_end_status(const cable_branch *b) { return b ? b->end_status : 0; }

const cable_point *cable_branch_point(const cable_branch *b, int i)
{
  return b && i >= 0 && i < b->npt ? &b->pts[i].pt : NULL;
}

const cable_solution *cable_branch_solution(const cable_branch *b, int i)
{
  return b && i >= 0 && i < b->nsol ? b->sol[i] : NULL;
}

const char *cable_branch_solution_note(const cable_branch *b, int i)
{
  for (int k = 0; b && k < b->npt; k++)
    if (b->pts[k].sol == i) return b->pts[k].note;
  return NULL;
}

int cable_branch_switch_directions(const cable_branch *b, cable_branch_dir *out, int max, int *order)
{
  if (order) *order = b && b->ndirs >= 0 ? b->dir_order : 0;
  if (!b || b->ndirs < 0) return -1;
  for (int k = 0; out && k < b->ndirs && k < max; k++) out[k] = b->dirs[k];
  return b->ndirs;
}
