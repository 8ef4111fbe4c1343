/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Fold continuation: the extended problem of cable_fold.h, a cable_problem
 * whose callbacks evaluate the original problem and its derivative in the
 * direction of the null vector.  doc/fold-continuation.md derives it. */
#include "cable/cable_fold.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "constants_check.h"
#include "solution_mesh.h"

struct cable_fold {
  cable_problem pb;             /* the extended problem; params = this struct */
  cable_constants c;            /* the extended run's constants */
  const cable_problem *orig;    /* not owned */
  int n, k;                     /* original NDIM and number of free parameters */
  int npar0, npar;              /* parameter slots: original, extended (npar0 + k) */
  int p[CABLE_MAX_ICP];         /* p[0..k-1]: the original free parameters p1..pk */
  int q;                        /* the new parameter */
  int wslot[CABLE_MAX_ICP];     /* wslot[j], j = 1..k-1: the slot of w for p[j] */
  int nslot;                    /* the slot of the null vector's squared norm (AUTO's PAR(NPAR+k)) */
  cable_solution *start;        /* owned copy of the start */
  int start_ext;                /* the start is a point of a fold curve */
  double vscale;                /* sqrt(n0) / norm of the start's null vector */
  double n0;                    /* N at an LP start: 1, or CABLE_FOLD_START_NORM for starting data */
  cable_solution *pvsol;        /* original-NDIM scratch for PVLS */
  char **parnames, **unames;    /* owned names of the extended problem */
};

/* ---- directional derivatives ------------------------------------------------- */

/* Step for a central difference at x (max-norm xmax) along d (max-norm dmax). */
static double fd_step(double xmax, double dmax) { return CABLE_FOLD_FD_STEP * (1.0 + xmax) / dmax; }

/* max |v_i| over the u part and |w_j| over the w slots; likewise for (u, p) */
static void norms(const cable_fold *f, int n, const double *u, const double *v, const double *par, double *xmax,
                  double *dmax)
{
  double a = 0.0, b = 0.0;
  for (int i = 0; i < n; i++) {
    a = fmax(a, fabs(u[i]));
    b = fmax(b, fabs(v[i]));
  }
  for (int j = 1; j < f->k; j++) {
    a = fmax(a, fabs(par[f->p[j]]));
    b = fmax(b, fabs(par[f->wslot[j]]));
  }
  *xmax = a;
  *dmax = b;
}

/* par +- h w into pp, pm (the free parameters p2..pk move, p1 and q do not) */
static void shift_par(const cable_fold *f, const double *par, double h, double *pp, double *pm)
{
  memcpy(pp, par, (size_t)f->npar * sizeof *pp);
  memcpy(pm, par, (size_t)f->npar * sizeof *pm);
  for (int j = 1; j < f->k; j++) {
    double w = par[f->wslot[j]];
    pp[f->p[j]] += h * w;
    pm[f->p[j]] -= h * w;
  }
}

/* FUNC': f(u, p) and D f(u, p)[v, w] */
static int fold_func(int ndim, const double *U, const int *icp, const double *par, int ijac, double *F,
                     double *dfdu, double *dfdp, void *params)
{
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  const cable_fold *f = params;
  const cable_problem *o = f->orig;
  int n = f->n;
  const double *u = U, *v = U + n;
  int rc = o->func(n, u, f->p, par, 0, F, NULL, NULL, o->params);
  if (rc != 0) return rc;
  double xmax, dmax;
  norms(f, n, u, v, par, &xmax, &dmax);
  if (!(dmax > 0)) {
    for (int i = 0; i < n; i++) F[n + i] = 0.0;
    return 0;
  }
  double h = fd_step(xmax, dmax);
  double up[CABLE_FOLD_MAXDIM], um[CABLE_FOLD_MAXDIM], fp[CABLE_FOLD_MAXDIM], fm[CABLE_FOLD_MAXDIM];
  double pp[CABLE_FOLD_MAXPAR], pm[CABLE_FOLD_MAXPAR];
  for (int i = 0; i < n; i++) {
    up[i] = u[i] + h * v[i];
    um[i] = u[i] - h * v[i];
  }
  shift_par(f, par, h, pp, pm);
  if ((rc = o->func(n, up, f->p, pp, 0, fp, NULL, NULL, o->params)) != 0) return rc;
  if ((rc = o->func(n, um, f->p, pm, 0, fm, NULL, NULL, o->params)) != 0) return rc;
  for (int i = 0; i < n; i++) F[n + i] = (fp[i] - fm[i]) / (2.0 * h);
  return 0;
}

/* BCND': b(u(0), u(1), p) and D b[v(0), v(1), w] */
static int fold_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *U0, const double *U1,
                     int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)icp; (void)nbc; (void)ijac; (void)dbc;
  const cable_fold *f = params;
  const cable_problem *o = f->orig;
  int n = f->n, nb = o->nbc;
  int rc = o->bcnd(n, par, f->p, nb, U0, U1, 0, fb, NULL, o->params);
  if (rc != 0) return rc;
  double a0, b0, a1, b1;
  norms(f, n, U0, U0 + n, par, &a0, &b0);
  norms(f, n, U1, U1 + n, par, &a1, &b1);
  double dmax = fmax(b0, b1);
  if (!(dmax > 0)) {
    for (int i = 0; i < nb; i++) fb[nb + i] = 0.0;
    return 0;
  }
  double h = fd_step(fmax(a0, a1), dmax);
  double u0p[CABLE_FOLD_MAXDIM], u0m[CABLE_FOLD_MAXDIM], u1p[CABLE_FOLD_MAXDIM], u1m[CABLE_FOLD_MAXDIM];
  double pp[CABLE_FOLD_MAXPAR], pm[CABLE_FOLD_MAXPAR], bp[CABLE_FOLD_MAXPAR], bm[CABLE_FOLD_MAXPAR];
  for (int i = 0; i < n; i++) {
    u0p[i] = U0[i] + h * U0[n + i];
    u0m[i] = U0[i] - h * U0[n + i];
    u1p[i] = U1[i] + h * U1[n + i];
    u1m[i] = U1[i] - h * U1[n + i];
  }
  shift_par(f, par, h, pp, pm);
  if ((rc = o->bcnd(n, pp, f->p, nb, u0p, u1p, 0, bp, NULL, o->params)) != 0) return rc;
  if ((rc = o->bcnd(n, pm, f->p, nb, u0m, u1m, 0, bm, NULL, o->params)) != 0) return rc;
  for (int i = 0; i < nb; i++) fb[nb + i] = (bp[i] - bm[i]) / (2.0 * h);
  return 0;
}

/* ICND': g(u, p), D g[v, w] and the normalisation |v|^2 + |w|^2 - N, whose
 * integral over [0, 1] is int |v|^2 dt + |w|^2 - N (N = par[nslot]).  The previous solution,
 * tangent and its derivative reach the original ICND in their u parts. */
static int fold_icnd(int ndim, const double *par, const int *icp, int nint, const double *U, const double *uold,
                     const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  (void)ndim; (void)icp; (void)nint; (void)ijac; (void)dint;
  const cable_fold *f = params;
  const cable_problem *o = f->orig;
  int n = f->n, ni = o->nint, rc;
  const double *u = U, *v = U + n;
  double norm = -par[f->nslot];
  for (int i = 0; i < n; i++) norm += v[i] * v[i];
  for (int j = 1; j < f->k; j++) norm += par[f->wslot[j]] * par[f->wslot[j]];
  fi[2 * ni] = norm;
  if (ni == 0) return 0;
  if ((rc = o->icnd(n, par, f->p, ni, u, uold, udot, upold, 0, fi, NULL, o->params)) != 0) return rc;
  double xmax, dmax;
  norms(f, n, u, v, par, &xmax, &dmax);
  if (!(dmax > 0)) {
    for (int i = 0; i < ni; i++) fi[ni + i] = 0.0;
    return 0;
  }
  double h = fd_step(xmax, dmax);
  double up[CABLE_FOLD_MAXDIM], um[CABLE_FOLD_MAXDIM];
  double pp[CABLE_FOLD_MAXPAR], pm[CABLE_FOLD_MAXPAR], gp[CABLE_FOLD_MAXPAR], gm[CABLE_FOLD_MAXPAR];
  for (int i = 0; i < n; i++) {
    up[i] = u[i] + h * v[i];
    um[i] = u[i] - h * v[i];
  }
  shift_par(f, par, h, pp, pm);
  if ((rc = o->icnd(n, pp, f->p, ni, up, uold, udot, upold, 0, gp, NULL, o->params)) != 0) return rc;
  if ((rc = o->icnd(n, pm, f->p, ni, um, uold, udot, upold, 0, gm, NULL, o->params)) != 0) return rc;
  for (int i = 0; i < ni; i++) fi[ni + i] = (gp[i] - gm[i]) / (2.0 * h);
  return 0;
}

/* ---- start: the stored solution at any t ------------------------------------------ */

/* Lagrange interpolation of the stored values (layout [point][dim], stride
 * dim) on the equally spaced nodes of the stored interval holding t. */
static void interp(const cable_solution *s, const double *vals, int dim, int off, int cnt, double t, double *out)
{
  int nc = s->ncol, j = 0;
  while (j < s->ntst - 1 && t > s->t[(j + 1) * nc]) j++;
  double a = s->t[j * nc], b = s->t[(j + 1) * nc];
  double x = b > a ? (t - a) / (b - a) : 0.0;
  for (int i = 0; i < cnt; i++) out[i] = 0.0;
  for (int m = 0; m <= nc; m++) {
    double l = 1.0;
    for (int r = 0; r <= nc; r++)
      if (r != m) l *= (x - (double)r / nc) / ((double)(m - r) / nc);
    const double *row = vals + (size_t)(j * nc + m) * (size_t)dim + off;
    for (int i = 0; i < cnt; i++) out[i] += l * row[i];
  }
}

/* STPNT': the start (u and its null vector v, w) at t, parameters with w. */
static int fold_stpnt(int ndim, double t, double *U, double *par, void *params)
{
  (void)ndim;
  const cable_fold *f = params;
  const cable_solution *s = f->start;
  int n = f->n;
  int np = s->npar < f->npar ? s->npar : f->npar;
  for (int k = 0; k < f->npar; k++) par[k] = k < np ? s->par[k] : 0.0;
  if (!f->start_ext) par[f->nslot] = f->n0;
  else if (s->npar <= f->nslot) par[f->nslot] = 1.0;
  if (f->start_ext) {
    interp(s, s->u, 2 * n, 0, 2 * n, t, U);
    return 0;
  }
  interp(s, s->u, n, 0, n, t, U);
  interp(s, s->udot, n, 0, n, t, U + n);
  for (int i = 0; i < n; i++) U[n + i] *= f->vscale;
  for (int j = 1; j < f->k; j++) {
    double w = 0.0;
    for (int r = 0; r < s->nfpr; r++)
      if (s->icp[r] == f->p[j]) w = s->pardot[r];
    par[f->wslot[j]] = w * f->vscale;
  }
  return 0;
}

/* PVLS': the original PVLS on the u part. */
static int fold_pvls(const cable_solution *sol, double *par, void *params)
{
  const cable_fold *f = params;
  cable_solution *o = f->pvsol;
  if (!f->orig->pvls) return 0;
  if (!o || o->ntst != sol->ntst || o->ncol != sol->ncol) return -1;
  int npts = cable_solution_npts(sol), n = f->n;
  memcpy(o->t, sol->t, (size_t)npts * sizeof *o->t);
  for (int k = 0; k < npts; k++) memcpy(o->u + (size_t)k * n, sol->u + (size_t)k * 2 * n, (size_t)n * sizeof *o->u);
  memcpy(o->par, sol->par, (size_t)f->npar0 * sizeof *o->par);
  for (int j = 0; j < f->k; j++) o->icp[j] = f->p[j];
  o->pvls_icp = sol->pvls_icp;
  o->pvls_nicp = sol->pvls_nicp;
  o->err_est = sol->err_est;
  return f->orig->pvls(o, par, f->orig->params);
}

/* ---- set-up ------------------------------------------------------------------------ */

static char *name_with(const char *prefix, const char *name, int index)
{
  char buf[96];
  if (name) snprintf(buf, sizeof buf, "%s%s", prefix, name);
  else snprintf(buf, sizeof buf, "%sPAR(%d)", prefix, index + 1);
  char *s = malloc(strlen(buf) + 1);
  if (s) memcpy(s, buf, strlen(buf) + 1);
  return s;
}

static void free_names(char **names, int n)
{
  for (int i = 0; names && i < n; i++) free(names[i]);
  free(names);
}

void cable_fold_free(cable_fold *f)
{
  if (!f) return;
  cable_solution_free(f->start);
  cable_solution_free(f->pvsol);
  free_names(f->parnames, f->npar);
  free_names(f->unames, 2 * f->n);
  free(f);
}

void cable_fold_mesh(const cable_fold *f, int ntst, double *mesh)
{
  if (!f || !mesh || ntst < 1) return;
  solution_mesh_resample(f->start, ntst, mesh);
}

const cable_problem *cable_fold_problem(const cable_fold *f) { return f ? &f->pb : NULL; }
const cable_constants *cable_fold_constants(const cable_fold *f) { return f ? &f->c : NULL; }

/* int |v|^2 dt of the stored direction (trapezoid on the stored points: a
 * first guess only, the start's Newton solves the normalisation) plus |w|^2 */
static double start_norm(const cable_fold *f, const cable_solution *s)
{
  int npts = cable_solution_npts(s), n = f->n;
  double sum = 0.0;
  for (int k = 0; k + 1 < npts; k++) {
    double a = 0.0, b = 0.0;
    for (int i = 0; i < n; i++) {
      a += s->udot[(size_t)k * n + i] * s->udot[(size_t)k * n + i];
      b += s->udot[(size_t)(k + 1) * n + i] * s->udot[(size_t)(k + 1) * n + i];
    }
    sum += 0.5 * (a + b) * (s->t[k + 1] - s->t[k]);
  }
  for (int j = 1; j < f->k; j++)
    for (int r = 0; r < s->nfpr; r++)
      if (s->icp[r] == f->p[j]) sum += s->pardot[r] * s->pardot[r];
  return sqrt(sum);
}

/* A copy of a fold-curve point with room for the norm slot: a point stored
 * before the slot existed (NPAR = npar0 + k - 1) had |v|^2 + |w|^2 = 1. */
static cable_solution *widen_start(const cable_solution *src, int npar)
{
  if (src->npar >= npar) return cable_solution_clone(src);
  cable_solution *s = cable_solution_alloc(src->ndim, src->ntst, src->ncol, npar, src->nfpr);
  if (!s) return NULL;
  size_t np = (size_t)cable_solution_npts(src);
  s->ibr = src->ibr; s->ntot = src->ntot; s->itp = src->itp; s->lab = src->lab;
  s->bp_kind = src->bp_kind; s->isw = src->isw; s->err_est = src->err_est;
  memcpy(s->t, src->t, np * sizeof *s->t);
  memcpy(s->u, src->u, np * (size_t)src->ndim * sizeof *s->u);
  if (src->udot) memcpy(s->udot, src->udot, np * (size_t)src->ndim * sizeof *s->udot);
  memcpy(s->par, src->par, (size_t)src->npar * sizeof *s->par);
  s->par[npar - 1] = 1.0;
  if (src->nfpr > 0) {
    memcpy(s->icp, src->icp, (size_t)src->nfpr * sizeof *s->icp);
    memcpy(s->pardot, src->pardot, (size_t)src->nfpr * sizeof *s->pardot);
  }
  return s;
}

#define FAIL(st, ...) CABLE_EXT_FAIL(cable_fold_free, st, __VA_ARGS__)

cable_fold *cable_fold_alloc(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                             int *status, char *msg, size_t len)
{
  /* status and msg may be NULL (not wanted) */
  cable_ext_sink sink;
  cable_fold *f = cable_ext_alloc_open("cable_fold_alloc", pb, c, sizeof *f, &sink, &status, &msg, &len);
  if (!f) return NULL;
  int n = pb->ndim, k = pb->nbc + pb->nint - pb->ndim + 1;
  f->orig = pb;
  f->n = n;
  f->k = k;
  f->npar0 = c->npar > pb->npar ? c->npar : pb->npar;
  f->npar = f->npar0 + k;
  f->nslot = f->npar0 + k - 1;
  if (n > CABLE_FOLD_MAXDIM || f->npar > CABLE_FOLD_MAXPAR || pb->nbc > CABLE_FOLD_MAXPAR ||
      pb->nint > CABLE_FOLD_MAXPAR)
    FAIL(CABLE_ERR_UNSUPPORTED, "ISW=2: fold continuation supports NDIM <= %d and NPAR <= %d", CABLE_FOLD_MAXDIM,
         CABLE_FOLD_MAXPAR);
  if (k < 1) FAIL(CABLE_ERR_INPUT, "ISW=2: the problem has no free parameter (NBC+NINT-NDIM+1 = %d)", k);
  if (c->nicp < k + 1 || c->nicp + k - 1 > CABLE_MAX_ICP)
    FAIL(CABLE_ERR_INPUT,
         "ISW=2: ICP must list the %d free parameter(s) of the branch, then the fold's second parameter "
         "(ICP = [p1, %sq], AUTO's order), it lists %d", k, k > 1 ? "p2, ..., " : "", c->nicp);
  cable_constants cu;   /* ICP in the internal order [p1, q, p2..pk, ...] */
  cable_ext_icp_order(c, k, &cu);
  c = &cu;
  if (!start) FAIL(CABLE_ERR_INPUT, "ISW=2: fold continuation starts from a labelled LP (give a restart label)");
  f->start_ext = start->ndim == 2 * n;
  if (!f->start_ext && start->ndim != n)
    FAIL(CABLE_ERR_INPUT, "ISW=2: the start has NDIM=%d, the problem %d (or %d on a fold curve)", start->ndim, n,
         2 * n);
  int base = start->itp >= 0 ? start->itp % 10 : -((-start->itp) % 10);
  if (!f->start_ext && base == 6)
    FAIL(CABLE_ERR_INPUT,
         "ISW=2 at a BP (label %d) is branch-point continuation (cable_bpcont.h), not fold continuation, which "
         "starts from an LP", start->lab);
  if (!f->start_ext && base != 5)
    FAIL(CABLE_ERR_INPUT, "ISW=2: fold continuation starts from an LP; label %d has type %d", start->lab,
         start->itp);
  if (!f->start_ext && (!start->udot || start->nfpr < 1))
    FAIL(CABLE_ERR_INPUT, "ISW=2: the LP (label %d) has no stored direction (its null vector)", start->lab);
  f->p[0] = c->icp[0];
  f->q = c->icp[1];
  for (int j = 1; j < k; j++) f->p[j] = c->icp[j + 1];
  for (int j = 1; j < k; j++) f->wslot[j] = f->npar0 + j - 1;
  for (int a = 0; a <= k; a++)
    for (int b = 0; b < a; b++)
      if (c->icp[a] == c->icp[b]) FAIL(CABLE_ERR_INPUT, "ISW=2: PAR(%d) is listed twice in ICP", c->icp[a] + 1);
  if (!(f->start = f->start_ext ? widen_start(start, f->npar) : cable_solution_clone(start)))
    FAIL(CABLE_ERR_ALLOC, "out of memory");
  if (!f->start_ext) {
    double nv = start_norm(f, start);
    if (!(nv > 0)) FAIL(CABLE_ERR_INPUT, "ISW=2: the LP's stored direction is zero");
    f->vscale = 1.0 / nv;
    f->n0 = 1.0;
  }
  if (pb->pvls && !(f->pvsol = cable_solution_alloc(n, c->ntst, c->ncol, f->npar0, k)))
    FAIL(CABLE_ERR_ALLOC, "out of memory");
  /* names: the problem's, then w(p2)..w(pk); U, then v(U) */
  f->parnames = calloc((size_t)f->npar, sizeof *f->parnames);
  f->unames = calloc((size_t)(2 * n), sizeof *f->unames);
  if (!f->parnames || !f->unames) FAIL(CABLE_ERR_ALLOC, "out of memory");
  for (int i = 0; i < f->npar0; i++)
    if (pb->parnames && i < pb->npar && pb->parnames[i] && !(f->parnames[i] = name_with("", pb->parnames[i], i)))
      FAIL(CABLE_ERR_ALLOC, "out of memory");
  for (int j = 1; j < k; j++) {
    const char *nm = pb->parnames && f->p[j] < pb->npar ? pb->parnames[f->p[j]] : NULL;
    if (!(f->parnames[f->wslot[j]] = name_with("w_", nm, f->p[j]))) FAIL(CABLE_ERR_ALLOC, "out of memory");
  }
  if (pb->parnames && !(f->parnames[f->nslot] = name_with("", "v_norm", 0))) FAIL(CABLE_ERR_ALLOC, "out of memory");
  for (int i = 0; i < n; i++) {
    const char *nm = pb->unames ? pb->unames[i] : NULL;
    char idx[32];
    snprintf(idx, sizeof idx, "U(%d)", i + 1);
    if (!(f->unames[i] = name_with("", nm ? nm : idx, i)) || !(f->unames[n + i] = name_with("v_", nm ? nm : idx, i)))
      FAIL(CABLE_ERR_ALLOC, "out of memory");
  }
  cable_problem *e = &f->pb;
  e->abi_version = CABLE_PROBLEM_ABI;
  e->struct_size = sizeof *e;
  e->name = pb->name;
  e->description = "fold continuation (ISW=2): the problem, its linearisation along the null vector, its norm";
  e->ndim = 2 * n;
  e->nbc = 2 * pb->nbc;
  e->nint = 2 * pb->nint + 1;
  e->npar = f->npar;
  e->parnames = (const char *const *)f->parnames;
  e->unames = (const char *const *)f->unames;
  e->func = fold_func;
  e->bcnd = pb->nbc > 0 ? fold_bcnd : NULL;
  e->icnd = fold_icnd;
  e->stpnt = fold_stpnt;
  e->pvls = pb->pvls ? fold_pvls : NULL;
  e->params = f;
  /* constants: ICP = [p1, q, p2..pk, w2..wk, printed...] */
  f->c = *c;
  f->c.ndim = e->ndim;
  f->c.nbc = e->nbc;
  f->c.nint = e->nint;
  f->c.npar = f->npar;
  int icp[CABLE_MAX_ICP], m = 0;
  for (int a = 0; a <= k; a++) icp[m++] = c->icp[a];
  for (int j = 1; j < k; j++) icp[m++] = f->wslot[j];
  for (int a = k + 1; a < c->nicp; a++) icp[m++] = c->icp[a];
  memcpy(f->c.icp, icp, (size_t)m * sizeof *icp);
  f->c.nicp = m;
  f->c.ndm = n;
  f->c.itpst = CABLE_FOLD_ITPST;
  f->c.npari = k;   /* w2..wk and N */
  *status = CABLE_SUCCESS;
  return f;
}

static int starting_data(cable_fold *f, char *msg, size_t len)
{
  if (f->start_ext) {
    snprintf(msg, len, "ISW=2: label %d is already a point of a fold curve (it restarts the curve)", f->start->lab);
    return CABLE_ERR_INPUT;
  }
  /* ICP = [p1, N, p2..pk, w2..wk, q, printed...]: q is fixed and printed,
     the norm N is free (doc/fold-continuation.md, "AUTO's runs") */
  cable_constants *c = &f->c;
  if (c->nicp + 1 > CABLE_MAX_ICP) {
    snprintf(msg, len, "ISW=2: too many ICP entries for the starting data (at most %d)", CABLE_MAX_ICP - 1);
    return CABLE_ERR_INPUT;
  }
  int icp[CABLE_MAX_ICP], m = 0;
  icp[m++] = c->icp[0];
  icp[m++] = f->nslot;
  for (int a = 2; a < c->nicp; a++) {
    if (a == 2 * f->k) icp[m++] = f->q;
    icp[m++] = c->icp[a];
  }
  if (c->nicp == 2 * f->k) icp[m++] = f->q;
  memcpy(c->icp, icp, (size_t)m * sizeof *icp);
  c->nicp = m;
  c->isw = -2;
  c->ilp = 0;
  c->isp = 0;
  c->nmx = CABLE_FOLD_START_STEPS;
  /* AUTO starts the null vector at 0, where the extended system (at fixed
     q, N free) is singular; cable starts it small, and the run grows it */
  f->vscale *= sqrt(CABLE_FOLD_START_NORM / f->n0);
  f->n0 = CABLE_FOLD_START_NORM;
  return CABLE_SUCCESS;
}

const cable_solution *cable_fold_start(const cable_fold *f) { return f ? f->start : NULL; }

int cable_fold_starting_data(cable_fold *f, cable_error *err)
{
  if (!f) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_fold_starting_data: the handle is NULL");
  char msg[512] = "";
  int rc = starting_data(f, msg, sizeof msg);
  return rc ? cable_error_set(err, rc, NULL, 0, NULL, "%s", msg[0] ? msg : cable_status_message(rc)) : rc;
}
