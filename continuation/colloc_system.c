/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "colloc_system.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "cable_team.h"

/* Central differences have error O(d^2 f''') + O(eps f / d); balancing gives
 * d ~ eps^(1/3) relative to the variable's size: about 6e-6. */
#define COLLOC_FD_REL_STEP 6.0e-6

static void *xcalloc(size_t n, size_t size, int *fail)
{
  void *p = calloc(n ? n : 1, size);
  if (!p) *fail = 1;
  return p;
}

colloc_system *colloc_system_alloc(const cable_problem *pb, const cable_constants *c,
                                   int ntst, int ncol, const int *icp, int nfpr, int *status)
{
  return colloc_system_alloc_team(pb, c, ntst, ncol, icp, nfpr, NULL, status);
}

colloc_system *colloc_system_alloc_team(const cable_problem *pb, const cable_constants *c, int ntst, int ncol,
                                        const int *icp, int nfpr, struct cable_team *t, int *status)
{
  *status = CABLE_ERR_INPUT;
  if (!pb || !pb->func || ntst < 1 || nfpr < 1 || nfpr > CABLE_MAX_ICP) return NULL;
  if (nfpr != pb->nbc + pb->nint - pb->ndim + 1) return NULL;
  colloc_system *s = calloc(1, sizeof *s);
  if (!s) {
    *status = CABLE_ERR_ALLOC;
    return NULL;
  }
  s->pb = pb;
  s->ndim = pb->ndim; s->nbc = pb->nbc; s->nint = pb->nint;
  s->npar = c->npar > pb->npar ? c->npar : pb->npar;
  s->ntst = ntst; s->ncol = ncol; s->nfpr = nfpr;
  s->n = s->ndim * (ntst * ncol + 1) + nfpr;
  for (int p = 0; p < nfpr; p++) s->icp[p] = icp[p];
  int jac = c->jac;
  s->use_jac_func = jac != 0 && pb->func_has_jac;
  s->use_jac_bcnd = jac != 0 && pb->bcnd_has_jac;
  s->use_jac_icnd = jac != 0 && pb->icnd_has_jac;
  s->fd_par = jac == -1;
  if (colloc_basis_init(&s->basis, ncol) != CABLE_SUCCESS) {
    free(s);
    return NULL;
  }
  int fail = 0, nd = s->ndim, np = s->npar, nb = s->nbc > 0 ? s->nbc : 1;
  int ni = s->nint > 0 ? s->nint : 1;
  s->mesh = xcalloc((size_t)ntst + 1, sizeof(double), &fail);
  s->par = xcalloc((size_t)np, sizeof(double), &fail);
  s->x0 = xcalloc((size_t)s->n, sizeof(double), &fail);
  s->xdot0 = xcalloc((size_t)s->n, sizeof(double), &fail);
  s->thu = xcalloc((size_t)nd, sizeof(double), &fail);
  s->thl = xcalloc((size_t)nfpr, sizeof(double), &fail);
  s->w_u = xcalloc((size_t)nd, sizeof(double), &fail);
  /* one chunk of intervals per thread, and more threads than intervals do nothing */
  int nt = pb->concurrent ? cable_threads(c) : 1;
  s->nwork = nt < ntst ? nt : ntst;
  s->work = xcalloc((size_t)s->nwork, sizeof *s->work, &fail);
  for (int k = 0; s->work && k < s->nwork; k++) {
    colloc_work *w = &s->work[k];
    w->u = xcalloc((size_t)nd, sizeof(double), &fail);
    w->du = xcalloc((size_t)nd, sizeof(double), &fail);
    w->f = xcalloc((size_t)nd, sizeof(double), &fail);
    w->fp = xcalloc((size_t)nd, sizeof(double), &fail);
    w->dfdu = xcalloc((size_t)nd * (size_t)nd, sizeof(double), &fail);
    w->dfdp = xcalloc((size_t)nd * (size_t)np, sizeof(double), &fail);
    w->par = xcalloc((size_t)np, sizeof(double), &fail);
  }
  if (!fail && s->nwork > 1 && t && cable_team_size(t) == s->nwork) {
    s->team = t;
    s->team_borrowed = 1;
  } else if (!fail && s->nwork > 1 && !(s->team = cable_team_alloc(s->nwork))) {
    fail = 1;
  }
  s->w_fb = xcalloc((size_t)nb, sizeof(double), &fail);
  s->w_fbp = xcalloc((size_t)nb, sizeof(double), &fail);
  s->w_dbc = xcalloc((size_t)nb * (size_t)(2 * nd + np), sizeof(double), &fail);
  s->w_fi = xcalloc((size_t)ni, sizeof(double), &fail);
  s->w_fip = xcalloc((size_t)ni, sizeof(double), &fail);
  s->w_dint = xcalloc((size_t)ni * (size_t)(nd + np), sizeof(double), &fail);
  s->w_uold = xcalloc((size_t)nd, sizeof(double), &fail);
  s->w_udot = xcalloc((size_t)nd, sizeof(double), &fail);
  s->w_upold = xcalloc((size_t)nd, sizeof(double), &fail);
  s->w_parp = xcalloc((size_t)np, sizeof(double), &fail);
  if (fail) {
    colloc_system_free(s);
    *status = CABLE_ERR_ALLOC;
    return NULL;
  }
  for (int i = 0; i < nd; i++) s->thu[i] = c->thu_default;
  for (int p = 0; p < nfpr; p++) {
    s->thl[p] = 1.0;
    for (int k = 0; k < c->nthl; k++)
      if (c->thl[k].index == icp[p]) s->thl[p] = c->thl[k].weight;
  }
  colloc_system_uniform_mesh(s);
  *status = CABLE_SUCCESS;
  return s;
}

void colloc_system_free(colloc_system *s)
{
  if (!s) return;
  double *bufs[] = {s->mesh, s->par, s->x0, s->xdot0, s->thu, s->thl, s->w_u,
                    s->w_fb, s->w_fbp, s->w_dbc, s->w_fi,
                    s->w_fip, s->w_dint, s->w_uold, s->w_udot, s->w_upold, s->w_parp};
  for (size_t i = 0; i < sizeof bufs / sizeof bufs[0]; i++) free(bufs[i]);
  if (!s->team_borrowed) cable_team_free(s->team);
  for (int k = 0; s->work && k < s->nwork; k++) {
    colloc_work *w = &s->work[k];
    double *wb[] = {w->u, w->du, w->f, w->fp, w->dfdu, w->dfdp, w->par};
    for (size_t i = 0; i < sizeof wb / sizeof wb[0]; i++) free(wb[i]);
  }
  free(s->work);
  free(s);
}

void colloc_system_uniform_mesh(colloc_system *s)
{
  for (int j = 0; j <= s->ntst; j++) s->mesh[j] = (double)j / s->ntst;
}

void colloc_system_times(const colloc_system *s, double *t)
{
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    for (int k = 0; k < s->ncol; k++) t[j * s->ncol + k] = s->mesh[j] + h * k / s->ncol;
  }
  t[s->ntst * s->ncol] = s->mesh[s->ntst];
}

/* Copy the free parameters of x into the full parameter vector. */
static void load_params(colloc_system *s, const double *x)
{
  const double *p = x + (size_t)s->ndim * (size_t)(s->ntst * s->ncol + 1);
  for (int k = 0; k < s->nfpr; k++) s->par[s->icp[k]] = p[k];
}

/* u and u' (in the local variable) at collocation point m of interval j. */
static void colloc_point(const colloc_system *s, const double *x, int j, int m, double *u,
                         double *du)
{
  int nd = s->ndim, nc = s->ncol;
  const double *uj = x + (size_t)(j * nc) * (size_t)nd;
  for (int i = 0; i < nd; i++) {
    double v = 0.0, dv = 0.0;
    for (int k = 0; k <= nc; k++) {
      v += s->basis.l[m][k] * uj[k * nd + i];
      dv += s->basis.dl[m][k] * uj[k * nd + i];
    }
    u[i] = v;
    if (du) du[i] = dv;
  }
}

/* FUNC with work w's parameters; counts and failures go to w (a pass
 * hands them to the system, see run_pass). */
static int call_func(const colloc_system *s, colloc_work *w, const double *u, int ijac, double *f,
                     double *dfdu, double *dfdp)
{
  w->nfunc++;
  int rc = s->pb->func(s->ndim, u, s->icp, w->par, ijac, f, dfdu, dfdp, s->pb->params);
  if (rc != 0) {
    w->last_callback = rc;
    return rc;
  }
  for (int i = 0; i < s->ndim; i++)
    if (!isfinite(f[i])) return w->last_callback = 1; /* NaN/Inf: reject the point */
  return 0;
}

/* A per-interval pass: chunk k of the intervals on thread k of the team. */
typedef struct pass_ctx {
  colloc_system *s;
  const double *x;
  double *F;                  /* residual pass */
  colloc_jac *J;              /* Jacobian pass */
} pass_ctx;

static void chunk_range(const colloc_system *s, int k, int *j0, int *j1)
{
  *j0 = (int)((long)k * s->ntst / s->nwork);
  *j1 = (int)((long)(k + 1) * s->ntst / s->nwork);
}

/* Runs fn on every chunk (the works start from the system's parameters) and
 * gathers: the FUNC count, and the first failure in interval order (the one a
 * loop over the intervals would have stopped at). */
static int run_pass(colloc_system *s, cable_team_fn *fn, pass_ctx *ctx)
{
  for (int k = 0; k < s->nwork; k++) {
    colloc_work *w = &s->work[k];
    memcpy(w->par, s->par, (size_t)s->npar * sizeof *w->par);
    w->nfunc = 0;
    w->rc = 0;
  }
  cable_team_run(s->team, fn, ctx, s->nwork);
  int rc = 0;
  for (int k = 0; k < s->nwork; k++) {
    colloc_work *w = &s->work[k];
    s->nfunc += w->nfunc;
    if (rc == 0 && w->rc != 0) {
      rc = w->rc;
      s->last_callback = w->last_callback;
    }
  }
  return rc;
}

int colloc_system_check_nodes(colloc_system *s, const double *x, int *node)
{
  load_params(s, x);
  colloc_work *w = &s->work[0];
  memcpy(w->par, s->par, (size_t)s->npar * sizeof *w->par);
  w->nfunc = 0;
  const int npts = s->ntst * s->ncol + 1;
  int rc = 0;
  for (int k = 0; k < npts && rc == 0; k++) {
    rc = call_func(s, w, x + (size_t)k * (size_t)s->ndim, 0, w->f, NULL, NULL);
    if (rc != 0) {
      s->last_callback = w->last_callback;
      if (node) *node = k;
    }
  }
  s->nfunc += w->nfunc;
  return rc;
}

/* Values of the integral-condition integrand at collocation point (j, m). */
static int call_icnd(colloc_system *s, const double *x, int j, int m, int ijac, double *fi,
                     double *dint)
{
  colloc_point(s, x, j, m, s->w_u, NULL);
  colloc_point(s, s->x0, j, m, s->w_uold, s->w_upold);
  colloc_point(s, s->xdot0, j, m, s->w_udot, NULL);
  double h = s->mesh[j + 1] - s->mesh[j];
  for (int i = 0; i < s->ndim; i++) s->w_upold[i] /= h;
  int rc = s->pb->icnd(s->ndim, s->par, s->icp, s->nint, s->w_u, s->w_uold, s->w_udot,
                       s->w_upold, ijac, fi, dint, s->pb->params);
  if (rc != 0) s->last_callback = rc;
  return rc;
}

double colloc_system_inner(const colloc_system *s, const double *a, const double *b)
{
  int nd = s->ndim, nc = s->ncol;
  double sum = 0.0;
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j], part = 0.0;
    for (int k = 0; k <= nc; k++) {
      const double *ak = a + (size_t)(j * nc + k) * (size_t)nd;
      const double *bk = b + (size_t)(j * nc + k) * (size_t)nd;
      double dot = 0.0;
      for (int i = 0; i < nd; i++) dot += s->thu[i] * ak[i] * bk[i];
      part += s->basis.wn[k] * dot;
    }
    sum += h * part;
  }
  size_t off = (size_t)nd * (size_t)(s->ntst * nc + 1);
  for (int p = 0; p < s->nfpr; p++) sum += s->thl[p] * a[off + p] * b[off + p];
  return sum;
}

/* The collocation rows of the intervals of chunk k. */
static void residual_chunk(void *p, int k)
{
  pass_ctx *ctx = p;
  colloc_system *s = ctx->s;
  colloc_work *w = &s->work[k];
  int nd = s->ndim, nc = s->ncol, j0, j1;
  chunk_range(s, k, &j0, &j1);
  for (int j = j0; j < j1; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    for (int m = 0; m < nc; m++) {
      colloc_point(s, ctx->x, j, m, w->u, w->du);
      if ((w->rc = call_func(s, w, w->u, 0, w->f, NULL, NULL)) != 0) return;
      double *Fr = ctx->F + (size_t)(j * nc + m) * (size_t)nd;
      for (int i = 0; i < nd; i++) Fr[i] = w->du[i] - h * w->f[i];
    }
  }
}

int colloc_system_residual(colloc_system *s, const double *x, double *F)
{
  int nd = s->ndim, nc = s->ncol, rc;
  load_params(s, x);
  pass_ctx ctx = {.s = s, .x = x, .F = F};
  if ((rc = run_pass(s, residual_chunk, &ctx)) != 0) return rc;
  size_t row = (size_t)s->ntst * (size_t)nc * (size_t)nd;
  if (s->nbc > 0) {
    const double *u0 = x, *u1 = x + (size_t)(s->ntst * nc) * (size_t)nd;
    rc = s->pb->bcnd(nd, s->par, s->icp, s->nbc, u0, u1, 0, F + row, NULL, s->pb->params);
    if (rc != 0) return s->last_callback = rc;
    row += (size_t)s->nbc;
  }
  if (s->nint > 0) {
    for (int q = 0; q < s->nint; q++) F[row + (size_t)q] = 0.0;
    for (int j = 0; j < s->ntst; j++) {
      double h = s->mesh[j + 1] - s->mesh[j];
      for (int m = 0; m < nc; m++) {
        if ((rc = call_icnd(s, x, j, m, 0, s->w_fi, NULL)) != 0) return rc;
        for (int q = 0; q < s->nint; q++) F[row + (size_t)q] += h * s->basis.w[m] * s->w_fi[q];
      }
    }
    row += (size_t)s->nint;
  }
  if (s->closing == COLLOC_CLOSE_FIXPAR) {
    F[row] = s->par[s->icp[s->fixpar]] - s->fixval;
  } else {
    /* <x - x0, xdot0> - ds, without forming x - x0 in a work vector */
    F[row] = colloc_system_inner(s, x, s->xdot0) - colloc_system_inner(s, s->x0, s->xdot0) - s->ds;
  }
  for (int i = 0; i < s->n; i++)
    if (!isfinite(F[i])) return s->last_callback = 1;
  return 0;
}

/* d f / d u and d f / d par(free) at u into w->dfdu, w->dfdp, analytically or
 * by central differences (which perturb w's copy of the parameters). */
static int func_derivs(const colloc_system *s, colloc_work *w, const double *u)
{
  int nd = s->ndim;
  double *dfdu = w->dfdu, *dfdp = w->dfdp;
  if (s->use_jac_func && !s->fd_par) return call_func(s, w, u, 2, w->f, dfdu, dfdp);
  int rc;
  if (s->use_jac_func) {
    /* JAC=-1 (AUTO): d f / d u from FUNC, parameter derivatives below */
    if ((rc = call_func(s, w, u, 1, w->f, dfdu, dfdp)) != 0) return rc;
  } else {
    double *up = w->du; /* free during Jacobian assembly */
    memcpy(up, u, (size_t)nd * sizeof *up);
    for (int l = 0; l < nd; l++) {
      double d = COLLOC_FD_REL_STEP * (1.0 + fabs(u[l]));
      up[l] = u[l] + d;
      if ((rc = call_func(s, w, up, 0, w->fp, NULL, NULL)) != 0) return rc;
      up[l] = u[l] - d;
      if ((rc = call_func(s, w, up, 0, w->f, NULL, NULL)) != 0) return rc;
      up[l] = u[l];
      for (int i = 0; i < nd; i++) dfdu[i + nd * l] = (w->fp[i] - w->f[i]) / (2 * d);
    }
  }
  for (int p = 0; p < s->nfpr; p++) {
    int k = s->icp[p];
    double pk = w->par[k], d = COLLOC_FD_REL_STEP * (1.0 + fabs(pk));
    w->par[k] = pk + d;
    rc = call_func(s, w, u, 0, w->fp, NULL, NULL);
    w->par[k] = pk - d;
    if (rc == 0) rc = call_func(s, w, u, 0, w->f, NULL, NULL);
    w->par[k] = pk;
    if (rc != 0) return rc;
    for (int i = 0; i < nd; i++) dfdp[i + nd * k] = (w->fp[i] - w->f[i]) / (2 * d);
  }
  return 0;
}

static int bcnd_derivs(colloc_system *s, const double *u0, const double *u1)
{
  int nd = s->ndim, nb = s->nbc, rc;
  double *dbc = s->w_dbc;
  int col0 = 0;
  if (s->use_jac_bcnd) {
    /* JAC=-1: the u columns from BCND, the parameter columns by differences */
    rc = s->pb->bcnd(nd, s->par, s->icp, nb, u0, u1, s->fd_par ? 1 : 2, s->w_fb, dbc, s->pb->params);
    if (rc || !s->fd_par) return rc ? (s->last_callback = rc) : 0;
    col0 = 2 * nd;
  }
  /* perturb a private copy of (u0, u1) */
  double *v0 = s->w_uold, *v1 = s->w_udot;
  memcpy(v0, u0, (size_t)nd * sizeof *v0);
  memcpy(v1, u1, (size_t)nd * sizeof *v1);
  for (int col = col0; col < 2 * nd + s->nfpr; col++) {
    double *var, saved;
    int dcol;
    if (col < 2 * nd) {
      var = col < nd ? &v0[col] : &v1[col - nd];
      dcol = col;
    } else {
      var = &s->par[s->icp[col - 2 * nd]];
      dcol = 2 * nd + s->icp[col - 2 * nd];
    }
    saved = *var;
    double d = COLLOC_FD_REL_STEP * (1.0 + fabs(saved));
    *var = saved + d;
    rc = s->pb->bcnd(nd, s->par, s->icp, nb, v0, v1, 0, s->w_fbp, NULL, s->pb->params);
    *var = saved - d;
    if (rc == 0) rc = s->pb->bcnd(nd, s->par, s->icp, nb, v0, v1, 0, s->w_fb, NULL, s->pb->params);
    *var = saved;
    if (rc != 0) return s->last_callback = rc;
    for (int i = 0; i < nb; i++) dbc[i + nb * dcol] = (s->w_fbp[i] - s->w_fb[i]) / (2 * d);
  }
  return 0;
}

/* d q / d u, d q / d par at collocation point (j, m) into s->w_dint (nint x (ndim+npar)). */
static int icnd_derivs(colloc_system *s, const double *x, int j, int m)
{
  int nd = s->ndim, ni = s->nint, rc;
  double *dint = s->w_dint;
  if (s->use_jac_icnd && !s->fd_par) return call_icnd(s, x, j, m, 2, s->w_fi, dint);
  /* fills w_u etc.; JAC=-1: also the u columns of dint */
  if ((rc = call_icnd(s, x, j, m, s->use_jac_icnd ? 1 : 0, s->w_fi, s->use_jac_icnd ? dint : NULL)) != 0) return rc;
  double *u = s->w_u;
  for (int col = s->use_jac_icnd ? nd : 0; col < nd + s->nfpr; col++) {
    double *var = col < nd ? &u[col] : &s->par[s->icp[col - nd]];
    int dcol = col < nd ? col : nd + s->icp[col - nd];
    double saved = *var, d = COLLOC_FD_REL_STEP * (1.0 + fabs(saved));
    *var = saved + d;
    rc = s->pb->icnd(nd, s->par, s->icp, ni, u, s->w_uold, s->w_udot, s->w_upold, 0, s->w_fip,
                     NULL, s->pb->params);
    *var = saved - d;
    if (rc == 0)
      rc = s->pb->icnd(nd, s->par, s->icp, ni, u, s->w_uold, s->w_udot, s->w_upold, 0, s->w_fi,
                       NULL, s->pb->params);
    *var = saved;
    if (rc != 0) return s->last_callback = rc;
    for (int q = 0; q < ni; q++) dint[q + ni * dcol] = (s->w_fip[q] - s->w_fi[q]) / (2 * d);
  }
  return 0;
}

/* The collocation blocks of the intervals of chunk k. */
static void jacobian_chunk(void *p, int k)
{
  pass_ctx *ctx = p;
  colloc_system *s = ctx->s;
  colloc_work *w = &s->work[k];
  int nd = s->ndim, nc = s->ncol, nf = s->nfpr, ldc = nc * nd, j0, j1;
  chunk_range(s, k, &j0, &j1);
  for (int j = j0; j < j1; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    double *B = colloc_jac_coll_block(ctx->J, j);
    for (int m = 0; m < nc; m++) {
      /* w->u holds u here: func_derivs uses w->du, w->f and w->fp as scratch */
      colloc_point(s, ctx->x, j, m, w->u, NULL);
      if ((w->rc = func_derivs(s, w, w->u)) != 0) return;
      for (int kk = 0; kk <= nc; kk++) {
        double lk = s->basis.l[m][kk], dlk = s->basis.dl[m][kk];
        for (int l = 0; l < nd; l++) {
          double *col = B + (size_t)(kk * nd + l) * (size_t)ldc + (size_t)(m * nd);
          for (int i = 0; i < nd; i++) col[i] = -h * lk * w->dfdu[i + nd * l];
          col[l] += dlk;
        }
      }
      for (int q = 0; q < nf; q++) {
        double *col = B + (size_t)((nc + 1) * nd + q) * (size_t)ldc + (size_t)(m * nd);
        for (int i = 0; i < nd; i++) col[i] = -h * w->dfdp[i + nd * s->icp[q]];
      }
    }
  }
}

int colloc_system_jacobian(colloc_system *s, const double *x, colloc_jac *J)
{
  int nd = s->ndim, nc = s->ncol, nf = s->nfpr, rc;
  int nde = J->ndense;
  s->njac++;
  load_params(s, x);
  /* the collocation blocks are overwritten entry by entry below (every row
     m*nd..m*nd+nd-1 of every column): zero only the accumulated blocks */
  memset(J->bc, 0, (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr) * sizeof(double));
  memset(J->dense, 0, (size_t)J->ntst * J->dense_stride * sizeof(double));
  memset(J->dense_par, 0, (size_t)J->ndense * (size_t)J->nfpr * sizeof(double));
  pass_ctx ctx = {.s = s, .x = x, .J = J};
  if ((rc = run_pass(s, jacobian_chunk, &ctx)) != 0) return rc;
  if (s->nbc > 0) {
    const double *u0 = x, *u1 = x + (size_t)(s->ntst * nc) * (size_t)nd;
    if ((rc = bcnd_derivs(s, u0, u1)) != 0) return rc;
    int nb = s->nbc;
    for (int col = 0; col < 2 * nd; col++)
      for (int i = 0; i < nb; i++) J->bc[i + nb * col] = s->w_dbc[i + nb * col];
    for (int p = 0; p < nf; p++)
      for (int i = 0; i < nb; i++)
        J->bc[i + nb * (2 * nd + p)] = s->w_dbc[i + nb * (2 * nd + s->icp[p])];
  }
  if (s->nint > 0) {
    int ni = s->nint;
    for (int j = 0; j < s->ntst; j++) {
      double h = s->mesh[j + 1] - s->mesh[j];
      double *D = colloc_jac_dense_block(J, j);
      for (int m = 0; m < nc; m++) {
        if ((rc = icnd_derivs(s, x, j, m)) != 0) return rc;
        double hw = h * s->basis.w[m];
        for (int k = 0; k <= nc; k++) {
          double c = hw * s->basis.l[m][k];
          for (int l = 0; l < nd; l++)
            for (int q = 0; q < ni; q++) D[q + nde * (k * nd + l)] += c * s->w_dint[q + ni * l];
        }
        for (int p = 0; p < nf; p++)
          for (int q = 0; q < ni; q++)
            J->dense_par[q + nde * p] += hw * s->w_dint[q + ni * (nd + s->icp[p])];
      }
    }
  }
  /* closing row: the last dense row */
  int r = nde - 1;
  if (s->closing == COLLOC_CLOSE_FIXPAR) {
    J->dense_par[r + nde * s->fixpar] = 1.0;
  } else {
    for (int j = 0; j < s->ntst; j++) {
      double h = s->mesh[j + 1] - s->mesh[j];
      double *D = colloc_jac_dense_block(J, j);
      for (int k = 0; k <= nc; k++) {
        const double *xd = s->xdot0 + (size_t)(j * nc + k) * (size_t)nd;
        for (int l = 0; l < nd; l++) D[r + nde * (k * nd + l)] = h * s->basis.wn[k] * s->thu[l] * xd[l];
      }
    }
    const double *pd = s->xdot0 + (size_t)nd * (size_t)(s->ntst * nc + 1);
    for (int p = 0; p < nf; p++) J->dense_par[r + nde * p] = s->thl[p] * pd[p];
  }
  return 0;
}
