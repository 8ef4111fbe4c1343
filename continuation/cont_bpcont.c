/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Branch-point continuation (cable_bpcont.h): the extended problem whose
 * solutions with b = 0 are branch points of a problem's branches, its
 * adjoint rows by central differences.  doc/fold-continuation.md. */
#include "cable/cable_bpcont.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "cable/cable_fold.h"
#include "cable/cable_status.h"
#include "constants_check.h"
#include "solution_mesh.h"

struct cable_bpcont {
  cable_problem pb;             /* the extended problem; params = this struct */
  cable_constants c;
  const cable_problem *orig;    /* not owned */
  int n, k, nbc, nint;          /* original NDIM, free parameters, NBC, NINT */
  int npar0, npar;
  int p[CABLE_MAX_ICP];         /* the original free parameters p1..pk */
  int sb, sps, so, sd, sa;      /* slots: b, psi*_1 (nbc of them), omega_1 (nint), d_1 (k), the norm a */
  cable_solution *start;        /* owned copy of the BP */
  double a0;                    /* a at the start */
  int start_ext;                /* the start is a point of a curve of branch points (2 NDIM) */
  int nnode;                    /* the start's psi: on the BP's mesh nodes tnode[0..nnode-1] */
  double *tnode, *psi0;         /* psi0[m * n + i] */
  double *pstar0, *om0, *d0;    /* psi* (nbc), omega (nint) and d (k) of the start */
};

static double fd_step(double xmax) { return CABLE_FOLD_FD_STEP * (1.0 + xmax); }

static double maxabs(const double *x, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(x[i]));
  return m;
}

/* The original integral conditions' integrands g are evaluated as cable's
 * FUNC' must (it has no UOLD): UOLD = u, UDOT = 0, UPOLD = f(u, p) (AUTO's
 * FFBBP passes the previous point and f there).  Exact for conditions that
 * do not read UOLD, UDOT or UPOLD; doc/fold-continuation.md. */
/* column i of g_u (i < n) or of g_{p_l} (i = n + l), central differences, in gd[nint] */
static int g_deriv(const cable_bpcont *f, const double *u, const double *par, const double *fu0, int i, double *gd)
{
  const cable_problem *o = f->orig;
  double zero[CABLE_FOLD_MAXDIM] = {0}, up[CABLE_FOLD_MAXDIM], pp[CABLE_FOLD_MAXPAR];
  double ga[CABLE_FOLD_MAXDIM], gb[CABLE_FOLD_MAXDIM];
  int n = f->n, rc;
  memcpy(up, u, (size_t)n * sizeof *up);
  memcpy(pp, par, (size_t)f->npar * sizeof *pp);
  double *x = i < n ? &up[i] : &pp[f->p[i - n]], x0 = *x, h = i < n ? fd_step(maxabs(u, n)) : fd_step(fabs(x0));
  *x = x0 + h;
  if ((rc = o->icnd(n, pp, f->p, f->nint, up, u, zero, fu0, 0, ga, NULL, o->params)) != 0) return rc;
  *x = x0 - h;
  if ((rc = o->icnd(n, pp, f->p, f->nint, up, u, zero, fu0, 0, gb, NULL, o->params)) != 0) return rc;
  for (int j = 0; j < f->nint; j++) gd[j] = (ga[j] - gb[j]) / (2.0 * h);
  return 0;
}

/* FUNC': f(u, p) - b psi and -f_u^T psi + g_u^T omega (column i of f_u and
   g_u by central differences) */
static int bp_func(int ndim, const double *U, const int *icp, const double *par, int ijac, double *F, double *dfdu,
                   double *dfdp, void *params)
{
  (void)ndim; (void)icp; (void)ijac; (void)dfdu; (void)dfdp;
  const cable_bpcont *f = params;
  const cable_problem *o = f->orig;
  int n = f->n, rc;
  const double *u = U, *psi = U + n;
  if ((rc = o->func(n, u, f->p, par, 0, F, NULL, NULL, o->params)) != 0) return rc;
  double fu0[CABLE_FOLD_MAXDIM], gd[CABLE_FOLD_MAXDIM];
  memcpy(fu0, F, (size_t)n * sizeof *fu0);
  for (int i = 0; i < n; i++) F[i] -= par[f->sb] * psi[i];
  double h = fd_step(maxabs(u, n));
  double up[CABLE_FOLD_MAXDIM], fp[CABLE_FOLD_MAXDIM], fm[CABLE_FOLD_MAXDIM];
  memcpy(up, u, (size_t)n * sizeof *up);
  for (int i = 0; i < n; i++) {
    up[i] = u[i] + h;
    if ((rc = o->func(n, up, f->p, par, 0, fp, NULL, NULL, o->params)) != 0) return rc;
    up[i] = u[i] - h;
    if ((rc = o->func(n, up, f->p, par, 0, fm, NULL, NULL, o->params)) != 0) return rc;
    up[i] = u[i];
    double s = 0;
    for (int m = 0; m < n; m++) s += psi[m] * (fp[m] - fm[m]);
    F[n + i] = -s / (2.0 * h);
    if (f->nint > 0) {
      if ((rc = g_deriv(f, u, par, fu0, i, gd)) != 0) return rc;
      for (int j = 0; j < f->nint; j++) F[n + i] += gd[j] * par[f->so + j];
    }
  }
  return 0;
}

/* BCND': b + b psi*, the adjoint's boundary rows, d_j + b_{p_j}^T psi* */
static int bp_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *U0, const double *U1,
                   int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)icp; (void)nbc; (void)ijac; (void)dbc;
  const cable_bpcont *f = params;
  const cable_problem *o = f->orig;
  int n = f->n, nb = f->nbc, rc;
  if ((rc = o->bcnd(n, par, f->p, nb, U0, U1, 0, fb, NULL, o->params)) != 0) return rc;
  const double *ps = par + f->sps;
  for (int i = 0; i < nb; i++) fb[i] += par[f->sb] * ps[i];
  double a0[CABLE_FOLD_MAXDIM], a1[CABLE_FOLD_MAXDIM], bp[CABLE_FOLD_MAXPAR], bm[CABLE_FOLD_MAXPAR];
  double pp[CABLE_FOLD_MAXPAR];
  memcpy(a0, U0, (size_t)n * sizeof *a0);
  memcpy(a1, U1, (size_t)n * sizeof *a1);
  double h = fd_step(fmax(maxabs(U0, n), maxabs(U1, n)));
  for (int side = 0; side < 2; side++)
    for (int j = 0; j < n; j++) {
      double *x = side ? a1 : a0, x0 = x[j];
      x[j] = x0 + h;
      if ((rc = o->bcnd(n, par, f->p, nb, a0, a1, 0, bp, NULL, o->params)) != 0) return rc;
      x[j] = x0 - h;
      if ((rc = o->bcnd(n, par, f->p, nb, a0, a1, 0, bm, NULL, o->params)) != 0) return rc;
      x[j] = x0;
      double s = 0;
      for (int i = 0; i < nb; i++) s += ps[i] * (bp[i] - bm[i]);
      s /= 2.0 * h;
      fb[nb + side * n + j] = side ? U1[n + j] + s : -U0[n + j] + s;
    }
  memcpy(pp, par, (size_t)f->npar * sizeof *pp);
  for (int l = 0; l < f->k; l++) {
    int q = f->p[l];
    double hp = fd_step(fabs(par[q]));
    pp[q] = par[q] + hp;
    if ((rc = o->bcnd(n, pp, f->p, nb, U0, U1, 0, bp, NULL, o->params)) != 0) return rc;
    pp[q] = par[q] - hp;
    if ((rc = o->bcnd(n, pp, f->p, nb, U0, U1, 0, bm, NULL, o->params)) != 0) return rc;
    pp[q] = par[q];
    double s = 0;
    for (int i = 0; i < nb; i++) s += ps[i] * (bp[i] - bm[i]);
    fb[nb + 2 * n + l] = par[f->sd + l] + s / (2.0 * hp);
  }
  return 0;
}

/* ICND': the original conditions g + b omega, -d_j - psi . f_{p_j} + omega .
   g_{p_j} and the normalisation |psi|^2 + |psi*|^2 + |omega|^2 - a */
static int bp_icnd(int ndim, const double *par, const int *icp, int nint, const double *U, const double *uold,
                   const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  (void)ndim; (void)icp; (void)nint; (void)ijac; (void)dint;
  const cable_bpcont *f = params;
  const cable_problem *o = f->orig;
  int n = f->n, ni = f->nint, rc;
  const double *u = U, *psi = U + n;
  double pp[CABLE_FOLD_MAXPAR], fp[CABLE_FOLD_MAXDIM], fm[CABLE_FOLD_MAXDIM], fu0[CABLE_FOLD_MAXDIM];
  double gd[CABLE_FOLD_MAXDIM];
  if (ni > 0) {
    /* the user's conditions see the problem's own u, UOLD, UDOT, UPOLD
       (the first n components of the extended ones, AUTO's ICNI call) */
    if ((rc = o->icnd(n, par, f->p, ni, u, uold, udot, upold, 0, fi, NULL, o->params)) != 0) return rc;
    for (int j = 0; j < ni; j++) fi[j] += par[f->sb] * par[f->so + j];
    if ((rc = o->func(n, u, f->p, par, 0, fu0, NULL, NULL, o->params)) != 0) return rc;
  }
  memcpy(pp, par, (size_t)f->npar * sizeof *pp);
  for (int l = 0; l < f->k; l++) {
    int q = f->p[l];
    double hp = fd_step(fabs(par[q]));
    pp[q] = par[q] + hp;
    if ((rc = o->func(n, u, f->p, pp, 0, fp, NULL, NULL, o->params)) != 0) return rc;
    pp[q] = par[q] - hp;
    if ((rc = o->func(n, u, f->p, pp, 0, fm, NULL, NULL, o->params)) != 0) return rc;
    pp[q] = par[q];
    double s = 0;
    for (int m = 0; m < n; m++) s += psi[m] * (fp[m] - fm[m]);
    fi[ni + l] = -par[f->sd + l] - s / (2.0 * hp);
    if (ni > 0) {
      if ((rc = g_deriv(f, u, par, fu0, n + l, gd)) != 0) return rc;
      for (int j = 0; j < ni; j++) fi[ni + l] += gd[j] * par[f->so + j];
    }
  }
  double norm = -par[f->sa];
  for (int i = 0; i < n; i++) norm += psi[i] * psi[i];
  for (int i = 0; i < f->nbc + ni; i++) norm += par[f->sps + i] * par[f->sps + i];   /* psi*, omega */
  fi[ni + f->k] = norm;
  return 0;
}

/* STPNT': the BP's u (Lagrange interpolation on its stored interval), psi
 * a first guess (1 / sqrt(n) in every component: the start's Newton, at
 * fixed q, solves the adjoint rows, linear in psi, onto their null space
 * unless the guess is orthogonal to it), b = psi* = d = 0. */
static int bp_stpnt(int ndim, double t, double *U, double *par, void *params)
{
  (void)ndim;
  const cable_bpcont *f = params;
  const cable_solution *s = f->start;
  int n = f->n, nc = s->ncol, j = 0;
  for (int k = 0; k < f->npar; k++) par[k] = k < s->npar ? s->par[k] : 0.0;
  if (f->start_ext) return CABLE_ERR_STATE;   /* a curve point restarts as stored (cable_bpcont_start) */
  while (j < s->ntst - 1 && t > s->t[(j + 1) * nc]) j++;
  double a = s->t[j * nc], b = s->t[(j + 1) * nc], x = b > a ? (t - a) / (b - a) : 0.0;
  for (int i = 0; i < n; i++) U[i] = 0.0;
  for (int m = 0; m <= nc; m++) {
    double l = 1.0;
    for (int r = 0; r <= nc; r++)
      if (r != m) l *= (x - (double)r / nc) / ((double)(m - r) / nc);
    for (int i = 0; i < n; i++) U[i] += l * s->u[(size_t)(j * nc + m) * (size_t)n + i];
  }
  /* psi: linear between the mesh nodes it was computed on (adjoint_start) */
  int m = 0;
  while (m < f->nnode - 2 && t > f->tnode[m + 1]) m++;
  double ta = f->tnode[m], tb = f->tnode[m + 1], w = tb > ta ? (t - ta) / (tb - ta) : 0.0;
  for (int i = 0; i < n; i++) U[n + i] = (1 - w) * f->psi0[m * n + i] + w * f->psi0[(m + 1) * n + i];
  for (int i = 0; i < f->nbc; i++) par[f->sps + i] = f->pstar0[i];
  for (int i = 0; i < f->nint; i++) par[f->so + i] = f->om0[i];
  for (int l = 0; l < f->k; l++) par[f->sd + l] = f->d0[l];
  par[f->sb] = 0.0;
  par[f->sa] = f->a0;
  return 0;
}

/* The adjoint null function at the BP, the start's psi: the adjoint BVP
 * (psi' = -f_u^T psi + g_u^T omega, its boundary rows, the d rows and their
 * integrals)
 * discretised by the trapezoidal rule on the BP's mesh nodes, an
 * overdetermined homogeneous system (one row more than unknowns) that has a
 * null vector at a branch point: its right singular vector of the smallest
 * singular value (O(h^2) accurate: a first guess the start's Newton refines
 * on the collocation mesh).  Normalised to int |psi|^2 + |psi*|^2 + |omega|^2 = a0. */
static int adjoint_start(cable_bpcont *f, char *msg, size_t len)
{
  const cable_problem *o = f->orig;
  const cable_solution *s = f->start;
  int n = f->n, nb = f->nbc, ni = f->nint, k = f->k, M = s->ntst, nc = s->ncol, rc;
  int N = n * (M + 1) + nb + ni + k, R = n * M + 2 * n + 2 * k;
  f->nnode = M + 1;
  f->tnode = calloc((size_t)(M + 1), sizeof *f->tnode);
  f->psi0 = calloc((size_t)(n * (M + 1)), sizeof *f->psi0);
  f->pstar0 = calloc((size_t)nb + 1, sizeof *f->pstar0);
  f->om0 = calloc((size_t)ni + 1, sizeof *f->om0);
  f->d0 = calloc((size_t)k + 1, sizeof *f->d0);
  double *A = calloc((size_t)R * (size_t)N, sizeof *A), *S = calloc((size_t)N, sizeof *S);
  double *VT = calloc((size_t)N * (size_t)N, sizeof *VT), *sup = calloc((size_t)N, sizeof *sup);
  double *fu = calloc((size_t)(n * n) * (size_t)(M + 1), sizeof *fu), *fp = calloc((size_t)(n * k) * (size_t)(M + 1), sizeof *fp);
  /* g_u and g_p at the nodes: gx[(m * (n + k) + i) * ni + j], column i of g_j */
  double *gx = calloc((size_t)(ni * (n + k)) * (size_t)(M + 1) + 1, sizeof *gx);
  if (!f->tnode || !f->psi0 || !f->pstar0 || !f->om0 || !f->d0 || !A || !S || !VT || !sup || !fu || !fp || !gx) {
    rc = CABLE_ERR_ALLOC;
    snprintf(msg, len, "out of memory (the adjoint start: %d unknowns)", N);
    goto done;
  }
  const double *par = s->par;
  double pp[CABLE_FOLD_MAXPAR], up[CABLE_FOLD_MAXDIM], fa[CABLE_FOLD_MAXDIM], fb[CABLE_FOLD_MAXDIM];
  for (int q = 0; q < f->npar; q++) pp[q] = q < s->npar ? par[q] : 0.0;
  /* f_u and f_p at the nodes, central differences */
  for (int m = 0; m <= M; m++) {
    const double *u = s->u + (size_t)(m * nc) * (size_t)n;
    f->tnode[m] = s->t[m * nc];
    memcpy(up, u, (size_t)n * sizeof *up);
    double h = fd_step(maxabs(u, n));
    for (int i = 0; i < n; i++) {
      up[i] = u[i] + h;
      if ((rc = o->func(n, up, f->p, pp, 0, fa, NULL, NULL, o->params)) != 0) goto cb;
      up[i] = u[i] - h;
      if ((rc = o->func(n, up, f->p, pp, 0, fb, NULL, NULL, o->params)) != 0) goto cb;
      up[i] = u[i];
      for (int j = 0; j < n; j++) fu[(size_t)m * n * n + j * n + i] = (fa[j] - fb[j]) / (2 * h);   /* df_j/du_i */
    }
    for (int l = 0; l < k; l++) {
      int q = f->p[l];
      double hp = fd_step(fabs(pp[q])), p0 = pp[q];
      pp[q] = p0 + hp;
      if ((rc = o->func(n, u, f->p, pp, 0, fa, NULL, NULL, o->params)) != 0) goto cb;
      pp[q] = p0 - hp;
      if ((rc = o->func(n, u, f->p, pp, 0, fb, NULL, NULL, o->params)) != 0) goto cb;
      pp[q] = p0;
      for (int j = 0; j < n; j++) fp[(size_t)m * n * k + j * k + l] = (fa[j] - fb[j]) / (2 * hp);
    }
    if (ni > 0) {
      double f0[CABLE_FOLD_MAXDIM];
      if ((rc = o->func(n, u, f->p, pp, 0, f0, NULL, NULL, o->params)) != 0) goto cb;
      for (int i = 0; i < n + k; i++)
        if ((rc = g_deriv(f, u, pp, f0, i, gx + ((size_t)m * (size_t)(n + k) + (size_t)i) * (size_t)ni)) != 0) goto cb;
    }
  }
#define AT(r, c) A[(size_t)(c) * (size_t)R + (size_t)(r)]
  int pst = n * (M + 1), om = pst + nb, dd = om + ni;
#define GX(m, i, j) gx[((size_t)(m) * (size_t)(n + k) + (size_t)(i)) * (size_t)ni + (size_t)(j)]
  for (int m = 0; m < M; m++) {
    double h = f->tnode[m + 1] - f->tnode[m];
    for (int i = 0; i < n; i++) {
      int r = m * n + i;
      AT(r, (m + 1) * n + i) += 1.0 / h;
      AT(r, m * n + i) -= 1.0 / h;
      for (int j = 0; j < n; j++) {
        AT(r, m * n + j) += 0.5 * fu[(size_t)m * n * n + j * n + i];
        AT(r, (m + 1) * n + j) += 0.5 * fu[(size_t)(m + 1) * n * n + j * n + i];
      }
      for (int j = 0; j < ni; j++) AT(r, om + j) -= 0.5 * (GX(m, i, j) + GX(m + 1, i, j));
    }
  }
  /* boundary rows: b's derivatives by central differences */
  const double *u0 = s->u, *u1 = s->u + (size_t)(M * nc) * (size_t)n;
  double a0v[CABLE_FOLD_MAXDIM], a1v[CABLE_FOLD_MAXDIM], ba[CABLE_FOLD_MAXPAR], bm[CABLE_FOLD_MAXPAR];
  memcpy(a0v, u0, (size_t)n * sizeof *a0v);
  memcpy(a1v, u1, (size_t)n * sizeof *a1v);
  double hb = fd_step(fmax(maxabs(u0, n), maxabs(u1, n)));
  for (int side = 0; side < 2; side++)
    for (int i = 0; i < n; i++) {
      double *x = side ? a1v : a0v, x0 = x[i];
      x[i] = x0 + hb;
      if ((rc = o->bcnd(n, pp, f->p, nb, a0v, a1v, 0, ba, NULL, o->params)) != 0) goto cb;
      x[i] = x0 - hb;
      if ((rc = o->bcnd(n, pp, f->p, nb, a0v, a1v, 0, bm, NULL, o->params)) != 0) goto cb;
      x[i] = x0;
      int r = n * M + side * n + i;
      AT(r, (side ? M : 0) * n + i) = side ? 1.0 : -1.0;
      for (int q = 0; q < nb; q++) AT(r, pst + q) = (ba[q] - bm[q]) / (2 * hb);
    }
  double tw[2] = {0, 0};
  for (int l = 0; l < k; l++) {
    int q = f->p[l];
    double hp = fd_step(fabs(pp[q])), p0 = pp[q];
    pp[q] = p0 + hp;
    if ((rc = o->bcnd(n, pp, f->p, nb, u0, u1, 0, ba, NULL, o->params)) != 0) goto cb;
    pp[q] = p0 - hp;
    if ((rc = o->bcnd(n, pp, f->p, nb, u0, u1, 0, bm, NULL, o->params)) != 0) goto cb;
    pp[q] = p0;
    int r = n * M + 2 * n + l, ri = r + k;
    AT(r, dd + l) = 1.0;
    for (int i = 0; i < nb; i++) AT(r, pst + i) = (ba[i] - bm[i]) / (2 * hp);
    AT(ri, dd + l) = -1.0;
    for (int m = 0; m <= M; m++) {
      tw[0] = m > 0 ? f->tnode[m] - f->tnode[m - 1] : 0.0;
      tw[1] = m < M ? f->tnode[m + 1] - f->tnode[m] : 0.0;
      double w = 0.5 * (tw[0] + tw[1]);
      for (int j = 0; j < n; j++) AT(ri, m * n + j) -= w * fp[(size_t)m * n * k + j * k + l];
      for (int j = 0; j < ni; j++) AT(ri, om + j) += w * GX(m, n + l, j);
    }
  }
#undef AT
#undef GX
  if (LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'A', R, N, A, R, S, NULL, 1, VT, N, sup) != 0) {
    rc = CABLE_ERR_LINSOLVE;
    snprintf(msg, len, "ISW=2 at a BP: the adjoint null vector at the start could not be computed (SVD)");
    goto done;
  }
  /* the last row of VT: the smallest singular value's right singular vector */
  double nrm = 0;
  for (int m = 0; m <= M; m++) {
    double w = 0.5 * ((m > 0 ? f->tnode[m] - f->tnode[m - 1] : 0.0) + (m < M ? f->tnode[m + 1] - f->tnode[m] : 0.0));
    for (int i = 0; i < n; i++) {
      double v = VT[(size_t)(N - 1) + (size_t)N * (size_t)(m * n + i)];
      nrm += w * v * v;
    }
  }
  for (int q = 0; q < nb + ni; q++) {   /* psi*, omega */
    double v = VT[(size_t)(N - 1) + (size_t)N * (size_t)(pst + q)];
    nrm += v * v;
  }
  double sc = sqrt(f->a0 / nrm);
  for (int c = 0; c < n * (M + 1); c++) f->psi0[c] = sc * VT[(size_t)(N - 1) + (size_t)N * (size_t)c];
  for (int q = 0; q < nb; q++) f->pstar0[q] = sc * VT[(size_t)(N - 1) + (size_t)N * (size_t)(pst + q)];
  for (int j = 0; j < ni; j++) f->om0[j] = sc * VT[(size_t)(N - 1) + (size_t)N * (size_t)(om + j)];
  for (int l = 0; l < k; l++) f->d0[l] = sc * VT[(size_t)(N - 1) + (size_t)N * (size_t)(dd + l)];
  rc = CABLE_SUCCESS;
  goto done;
cb:
  snprintf(msg, len, "ISW=2 at a BP: a callback failed (status %d) computing the adjoint start", rc);
  rc = CABLE_ERR_CALLBACK;
done:
  free(A); free(S); free(VT); free(sup); free(fu); free(fp); free(gx);
  return rc;
}

void cable_bpcont_free(cable_bpcont *f)
{
  if (!f) return;
  cable_solution_free(f->start);
  free(f->tnode); free(f->psi0); free(f->pstar0); free(f->om0); free(f->d0);
  free(f);
}

const cable_problem *cable_bpcont_problem(const cable_bpcont *f) { return f ? &f->pb : NULL; }
const cable_constants *cable_bpcont_constants(const cable_bpcont *f) { return f ? &f->c : NULL; }

static int starting_data(cable_bpcont *f, char *msg, size_t len)
{
  if (f->start_ext) {
    snprintf(msg, len, "ISW=2: label %d is already a point of a curve of branch points", f->start->lab);
    return CABLE_ERR_INPUT;
  }
  /* ICP = [p1, a, p2..pk, b, psi*, omega, d, q, printed...]: q fixed and printed */
  cable_constants *c = &f->c;
  if (c->nicp + 1 > CABLE_MAX_ICP) {
    snprintf(msg, len, "ISW=2: too many ICP entries for the starting data");
    return CABLE_ERR_INPUT;
  }
  int nfree = 2 * f->k + 2 + f->nbc + f->nint, q = c->icp[1], icp[CABLE_MAX_ICP], m = 0;
  for (int a = 0; a < c->nicp; a++) {
    if (a == nfree) icp[m++] = q;
    icp[m++] = a == 1 ? f->sa : c->icp[a];
  }
  if (c->nicp == nfree) icp[m++] = q;
  memcpy(c->icp, icp, (size_t)m * sizeof *icp);
  c->nicp = m;
  c->isw = -2;
  c->ilp = 0;
  c->isp = 0;
  c->nmx = CABLE_FOLD_START_STEPS;
  /* psi grows from almost nothing, as AUTO's from 0 (cable_fold.h) */
  double sc = sqrt(CABLE_FOLD_START_NORM / f->a0);
  for (int i = 0; i < f->n * f->nnode; i++) f->psi0[i] *= sc;
  for (int i = 0; i < f->nbc; i++) f->pstar0[i] *= sc;
  for (int j = 0; j < f->nint; j++) f->om0[j] *= sc;
  for (int l = 0; l < f->k; l++) f->d0[l] *= sc;
  f->a0 = CABLE_FOLD_START_NORM;
  return CABLE_SUCCESS;
}

const cable_solution *cable_bpcont_start(const cable_bpcont *f) { return f ? f->start : NULL; }

void cable_bpcont_mesh(const cable_bpcont *f, int ntst, double *mesh)
{
  if (!f || !mesh || ntst < 1) return;
  solution_mesh_resample(f->start, ntst, mesh);
}

#define FAIL(st, ...) CABLE_EXT_FAIL(cable_bpcont_free, st, __VA_ARGS__)

cable_bpcont *cable_bpcont_alloc(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                                 int *status, char *msg, size_t len)
{
  /* status and msg may be NULL (not wanted) */
  cable_ext_sink sink;
  cable_bpcont *f = cable_ext_alloc_open("cable_bpcont_alloc", pb, c, sizeof *f, &sink, &status, &msg, &len);
  if (!f) return NULL;
  int n = pb->ndim, k = pb->nbc + pb->nint - pb->ndim + 1;
  f->orig = pb;
  f->n = n;
  f->k = k;
  f->nbc = pb->nbc;
  f->nint = pb->nint;
  f->npar0 = c->npar > pb->npar ? c->npar : pb->npar;
  f->sb = f->npar0;
  f->sps = f->sb + 1;
  f->so = f->sps + pb->nbc;
  f->sd = f->so + pb->nint;
  f->sa = f->sd + k;
  f->npar = f->sa + 1;
  f->a0 = 1.0;
  if (pb->nint > 0 && !pb->icnd) FAIL(CABLE_ERR_INPUT, "ISW=2 at a BP: NINT=%d but the problem has no ICND", pb->nint);
  if (n > CABLE_FOLD_MAXDIM || pb->nint > CABLE_FOLD_MAXDIM || f->npar > CABLE_FOLD_MAXPAR)
    FAIL(CABLE_ERR_UNSUPPORTED, "ISW=2 at a BP: supports NDIM, NINT <= %d and NPAR <= %d", CABLE_FOLD_MAXDIM,
         CABLE_FOLD_MAXPAR);
  if (k < 1) FAIL(CABLE_ERR_INPUT, "ISW=2 at a BP: the problem has no free parameter (NBC-NDIM+1 = %d)", k);
  int nfree = 2 * k + 2 + pb->nbc + pb->nint;
  if (c->nicp < k + 1 || c->nicp - (k + 1) + nfree > CABLE_MAX_ICP)
    FAIL(CABLE_ERR_INPUT,
         "ISW=2 at a BP: ICP must list the %d free parameter(s) of the branch, then the second parameter "
         "(ICP = [p1, %sq], AUTO's order), it lists %d", k, k > 1 ? "p2, ..., " : "", c->nicp);
  cable_constants cu;   /* ICP in the internal order [p1, q, p2..pk, ...] */
  cable_ext_icp_order(c, k, &cu);
  c = &cu;
  if (!start) FAIL(CABLE_ERR_INPUT, "ISW=2 at a BP: give a restart label");
  int base = start->itp >= 0 ? start->itp % 10 : -((-start->itp) % 10);
  f->start_ext = start->ndim == 2 * n && abs(start->itp) / 10 == CABLE_BPCONT_ITPST;
  if (!f->start_ext && (start->ndim != n || base != 6))
    FAIL(CABLE_ERR_INPUT, "ISW=2 at a BP: label %d (type %d, NDIM=%d) is not a BP of this problem", start->lab,
         start->itp, start->ndim);
  if (f->start_ext && start->npar < f->npar)
    FAIL(CABLE_ERR_INPUT, "ISW=2: label %d has NPAR=%d, a curve of branch points of this problem %d", start->lab,
         start->npar, f->npar);
  f->p[0] = c->icp[0];
  for (int j = 1; j < k; j++) f->p[j] = c->icp[j + 1];
  if (!(f->start = cable_solution_clone(start))) FAIL(CABLE_ERR_ALLOC, "out of memory");
  int rc = f->start_ext ? CABLE_SUCCESS : adjoint_start(f, msg, len);
  if (rc) {
    *status = rc;
    cable_bpcont_free(f);
    return NULL;
  }
  cable_problem *e = &f->pb;
  e->abi_version = CABLE_PROBLEM_ABI;
  e->struct_size = sizeof *e;
  e->name = pb->name;
  e->description = "branch-point continuation (ISW=2 at a BP): the problem unfolded by b psi, its adjoint, |psi| = 1";
  e->ndim = 2 * n;
  e->nbc = pb->nbc + 2 * n + k;
  e->nint = pb->nint + k + 1;
  e->npar = f->npar;
  e->func = bp_func;
  e->bcnd = bp_bcnd;
  e->icnd = bp_icnd;
  e->stpnt = bp_stpnt;
  e->params = f;
  f->c = *c;
  f->c.ndim = e->ndim;
  f->c.nbc = e->nbc;
  f->c.nint = e->nint;
  f->c.npar = f->npar;
  f->c.ndm = n;
  f->c.itpst = CABLE_BPCONT_ITPST;
  f->c.npari = f->npar - f->npar0;   /* b, psi*, omega, d and a */
  int icp[CABLE_MAX_ICP], m = 0;
  for (int a = 0; a <= k; a++) icp[m++] = c->icp[a];
  icp[m++] = f->sb;
  for (int i = 0; i < pb->nbc + pb->nint; i++) icp[m++] = f->sps + i;   /* psi*, omega */
  for (int l = 0; l < k; l++) icp[m++] = f->sd + l;
  for (int a = k + 1; a < c->nicp; a++) icp[m++] = c->icp[a];
  memcpy(f->c.icp, icp, (size_t)m * sizeof *icp);
  f->c.nicp = m;
  *status = CABLE_SUCCESS;
  return f;
}

int cable_bpcont_starting_data(cable_bpcont *f, cable_error *err)
{
  if (!f) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_bpcont_starting_data: the handle is NULL");
  char msg[512] = "";
  int rc = starting_data(f, msg, sizeof msg);
  return rc ? cable_error_set(err, rc, NULL, 0, NULL, "%s", msg[0] ? msg : cable_status_message(rc)) : rc;
}
