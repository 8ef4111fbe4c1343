/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The Morse index of a solution of a variational BVP (doc/stability.md, S2):
 * the second variation Q[v] = int v'.P v' + 2 v'.C v + v.R v dt on continuous
 * piecewise polynomials, restricted to the null space of the linearised
 * constraints, against the L2 mass form; LAPACK's dsygv gives the spectrum. */
#include <float.h>
#include <gsl/gsl_integration.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_stability.h"
#include "cable/cable_status.h"

/* Lagrange basis on the n + 1 equally spaced nodes a/n of [0,1]: values and
 * derivatives at x (the engine's collocation layout, colloc_basis.c). */
static void lagrange(int n, double x, double *l, double *dl)
{
  for (int a = 0; a <= n; a++) {
    double xa = (double)a / n, v = 1.0, d = 0.0;
    for (int b = 0; b <= n; b++) {
      if (b == a) continue;
      double xb = (double)b / n, f = (x - xb) / (xa - xb);
      if (dl) d = d * f + v / (xa - xb);
      v *= f;
    }
    l[a] = v;
    if (dl) dl[a] = d;
  }
}

typedef struct {
  int m, k, nq, nnode, n, nc, ndim;
  double *K, *M, *G;       /* N x N, N x N, nc x N (column-major) */
  double *P, *C, *R, *a, *b, *B, *Hb, *u;
  double *phi, *dphi;      /* (k+1) x nq: the piece's basis at the quadrature points */
  double *ls, *dls;        /* the stored solution's basis, ncol + 1 */
} stab_ws;

static void ws_free(stab_ws *w)
{
  free(w->K); free(w->M); free(w->G);
  free(w->P); free(w->C); free(w->R); free(w->a); free(w->b); free(w->B); free(w->Hb); free(w->u);
  free(w->phi); free(w->dphi); free(w->ls); free(w->dls);
}

/* The stored solution (a polynomial of degree ncol on every mesh interval)
 * at t = mesh_j + x h_j. */
static void sol_eval(const cable_solution *s, int j, double x, double *ls, double *u)
{
  lagrange(s->ncol, x, ls, NULL);
  int nd = s->ndim;
  for (int i = 0; i < nd; i++) u[i] = 0.0;
  for (int a = 0; a <= s->ncol; a++) {
    const double *ua = s->u + (size_t)(j * s->ncol + a) * (size_t)nd;
    for (int i = 0; i < nd; i++) u[i] += ls[a] * ua[i];
  }
}

static int assemble(const cable_problem *pb, const cable_solution *sol, int refine, stab_ws *w,
                    cable_error *err)
{
  const cable_variational *vs = pb->variational;
  const int m = w->m, k = w->k, N = w->n, ncon = vs->ncon, nvbc = vs->nvbc;
  gsl_integration_glfixed_table *tbl = gsl_integration_glfixed_table_alloc((size_t)w->nq);
  if (!tbl) return cable_error_set(err, CABLE_ERR_ALLOC, "", 0, "STAB", "out of memory");
  for (int q = 0; q < w->nq; q++) {
    double x, wt;
    gsl_integration_glfixed_point(0.0, 1.0, (size_t)q, &x, &wt, tbl);
    lagrange(k, x, w->phi + (size_t)q * (size_t)(k + 1), w->dphi + (size_t)q * (size_t)(k + 1));
  }
  for (int j = 0; j < sol->ntst; j++) {
    double t0 = sol->t[j * sol->ncol], hj = sol->t[(j + 1) * sol->ncol] - t0, hp = hj / refine;
    for (int r = 0; r < refine; r++) {
      int e = j * refine + r, g0 = e * k;   /* first global node of the piece */
      for (int q = 0; q < w->nq; q++) {
        double x, wt;
        gsl_integration_glfixed_point(0.0, 1.0, (size_t)q, &x, &wt, tbl);
        sol_eval(sol, j, (r + x) / refine, w->ls, w->u);
        if (vs->hessian(w->ndim, w->u, sol->par, m, w->P, w->C, w->R, pb->params) != 0) {
          gsl_integration_glfixed_table_free(tbl);
          return cable_error_set(err, CABLE_ERR_CALLBACK, "", 0, "STAB",
                                 "the problem's second-variation callback failed at t = %g", t0 + (r + x) * hp);
        }
        if (ncon > 0 && vs->constraints(w->ndim, w->u, sol->par, m, ncon, w->a, w->b, pb->params) != 0) {
          gsl_integration_glfixed_table_free(tbl);
          return cable_error_set(err, CABLE_ERR_CALLBACK, "", 0, "STAB",
                                 "the problem's constraint callback failed at t = %g", t0 + (r + x) * hp);
        }
        const double *ph = w->phi + (size_t)q * (size_t)(k + 1), *dph = w->dphi + (size_t)q * (size_t)(k + 1);
        double c = wt * hp;
        for (int A = 0; A <= k; A++) {
          double fa = ph[A], da = dph[A] / hp;
          for (int B = 0; B <= k; B++) {
            double fb = ph[B], db = dph[B] / hp;
            for (int i = 0; i < m; i++) {
              size_t row = (size_t)(g0 + A) * (size_t)m + (size_t)i;
              for (int jj = 0; jj < m; jj++) {
                size_t col = (size_t)(g0 + B) * (size_t)m + (size_t)jj;
                double v = da * db * w->P[i + m * jj] + da * fb * w->C[i + m * jj] + fa * db * w->C[jj + m * i] +
                           fa * fb * w->R[i + m * jj];
                w->K[row + (size_t)N * col] += c * v;
              }
              w->M[row + (size_t)N * ((size_t)(g0 + B) * (size_t)m + (size_t)i)] += c * fa * fb;
            }
          }
          for (int kk = 0; kk < ncon; kk++)
            for (int i = 0; i < m; i++) {
              size_t col = (size_t)(g0 + A) * (size_t)m + (size_t)i;
              w->G[(size_t)(nvbc + kk) + (size_t)w->nc * col] +=
                c * (w->a[kk + ncon * i] * fa + w->b[kk + ncon * i] * da);
            }
        }
      }
    }
  }
  gsl_integration_glfixed_table_free(tbl);
  if (nvbc > 0) {
    const double *u0 = sol->u, *u1 = sol->u + (size_t)(sol->ntst * sol->ncol) * (size_t)w->ndim;
    memset(w->Hb, 0, (size_t)(4 * m * m) * sizeof *w->Hb);
    if (vs->vbc(w->ndim, u0, u1, sol->par, m, nvbc, w->B, w->Hb, pb->params) != 0)
      return cable_error_set(err, CABLE_ERR_CALLBACK, "", 0, "STAB", "the problem's boundary-variation callback failed");
    size_t last = (size_t)(w->nnode - 1) * (size_t)m;
    for (int r = 0; r < nvbc; r++)
      for (int i = 0; i < m; i++) {
        w->G[(size_t)r + (size_t)w->nc * (size_t)i] = w->B[r + nvbc * i];
        w->G[(size_t)r + (size_t)w->nc * (last + (size_t)i)] = w->B[r + nvbc * (m + i)];
      }
    for (int p = 0; p < 2 * m; p++)
      for (int q = 0; q < 2 * m; q++) {
        size_t dp = p < m ? (size_t)p : last + (size_t)(p - m), dq = q < m ? (size_t)q : last + (size_t)(q - m);
        w->K[dp + (size_t)N * dq] += w->Hb[p + 2 * m * q];
      }
  }
  return CABLE_SUCCESS;
}

static int stab_solve(stab_ws *wp, cable_stab_result *res, cable_error *err);

int cable_stability_index(const cable_problem *pb, const cable_solution *sol, int refine, int degree,
                          cable_stab_result *res, cable_error *err)
{
  if (!pb || !sol || !res) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "STAB", "NULL argument");
  memset(res, 0, sizeof *res);
  const cable_variational *vs = pb->variational;
  if (!vs)
    return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "STAB",
                           "problem '%s' does not declare its variational structure (cable_problem.variational)",
                           pb->name ? pb->name : "?");
  if (!vs->ritz && (vs->nvar < 1 || vs->ncon < 0 || vs->nvbc < 0 || !vs->hessian ||
                    (vs->ncon > 0 && !vs->constraints) || (vs->nvbc > 0 && !vs->vbc)))
    return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "STAB", "problem '%s': incomplete cable_variational",
                           pb->name ? pb->name : "?");
  if (refine < 1 || degree < 1 || degree > 10 || sol->ntst < 1 || sol->ncol < 1 || sol->ndim != pb->ndim)
    return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "STAB", "bad sizes (refine %d, degree %d, NDIM %d)", refine,
                           degree, sol->ndim);
  stab_ws w = {0};
  if (vs->ritz) {
    /* the problem assembles K, M, G itself (a nonlocal second variation) */
    int rc = vs->ritz(sol, refine, degree, &w.n, &w.nc, &w.K, &w.M, &w.G, pb->params);
    if (rc != 0 || !w.K || !w.M || !w.G || w.n < 1 || w.nc < 0) {
      ws_free(&w);
      return cable_error_set(err, CABLE_ERR_CALLBACK, "", 0, "STAB",
                             "the problem's Ritz callback failed (status %d)", rc);
    }
    return stab_solve(&w, res, err);
  }
  w.m = vs->nvar;
  w.k = degree;
  w.nq = degree + 3;
  w.nnode = sol->ntst * refine * degree + 1;
  w.n = w.m * w.nnode;
  w.nc = vs->nvbc + vs->ncon;
  w.ndim = sol->ndim;
  const int N = w.n, m = w.m, nc = w.nc;
  (void)nc;
  size_t NN = (size_t)N * (size_t)N;
  w.K = calloc(NN, sizeof *w.K);
  w.M = calloc(NN, sizeof *w.M);
  w.G = calloc((size_t)(nc > 0 ? nc : 1) * (size_t)N, sizeof *w.G);
  w.P = malloc((size_t)(m * m) * sizeof *w.P);
  w.C = malloc((size_t)(m * m) * sizeof *w.C);
  w.R = malloc((size_t)(m * m) * sizeof *w.R);
  w.a = calloc((size_t)((vs->ncon + 1) * m), sizeof *w.a);
  w.b = calloc((size_t)((vs->ncon + 1) * m), sizeof *w.b);
  w.B = calloc((size_t)((vs->nvbc + 1) * 2 * m), sizeof *w.B);
  w.Hb = calloc((size_t)(4 * m * m), sizeof *w.Hb);
  w.u = malloc((size_t)w.ndim * sizeof *w.u);
  w.phi = malloc((size_t)((degree + 1) * w.nq) * sizeof *w.phi);
  w.dphi = malloc((size_t)((degree + 1) * w.nq) * sizeof *w.dphi);
  w.ls = malloc((size_t)(sol->ncol + 1) * sizeof *w.ls);
  w.dls = malloc((size_t)(sol->ncol + 1) * sizeof *w.dls);
  int st = CABLE_SUCCESS;
  if (!w.K || !w.M || !w.G || !w.P || !w.C || !w.R || !w.a || !w.b || !w.B || !w.Hb || !w.u || !w.phi || !w.dphi ||
      !w.ls || !w.dls) {
    st = cable_error_set(err, CABLE_ERR_ALLOC, "", 0, "STAB", "out of memory (N = %d)", N);
    goto done;
  }
  if ((st = assemble(pb, sol, refine, &w, err)) != CABLE_SUCCESS) goto done;
  return stab_solve(&w, res, err);
done:
  ws_free(&w);
  return st;
}

/* The spectrum of (S2.1) from w's K, M, G; frees w. */
static int stab_solve(stab_ws *wp, cable_stab_result *res, cable_error *err)
{
  stab_ws w = *wp;
  const int N = w.n, nc = w.nc;
  double *Q = NULL, *Kz = NULL, *Mz = NULL, *ev = NULL, *tau = NULL;
  lapack_int *jpvt = NULL;
  int st = CABLE_SUCCESS;
  /* the null space of G: QR with column pivoting of G^T (N x nc); the last
     N - rank columns of its Q span it */
  int rank = 0;
  if (nc > 0) {
    Q = calloc((size_t)N * (size_t)nc, sizeof *Q);
    tau = calloc((size_t)nc, sizeof *tau);
    jpvt = calloc((size_t)nc, sizeof *jpvt);
    if (!Q || !tau || !jpvt) {
      st = cable_error_set(err, CABLE_ERR_ALLOC, "", 0, "STAB", "out of memory (N = %d)", N);
      goto done;
    }
    for (int r = 0; r < nc; r++)
      for (int c = 0; c < N; c++) Q[(size_t)c + (size_t)N * (size_t)r] = w.G[(size_t)r + (size_t)nc * (size_t)c];
    int kq = nc < N ? nc : N;
    if (LAPACKE_dgeqp3(LAPACK_COL_MAJOR, N, nc, Q, N, jpvt, tau) != 0) {
      st = cable_error_set(err, CABLE_ERR_LINSOLVE, "", 0, "STAB", "dgeqp3 failed");
      goto done;
    }
    double r11 = fabs(Q[0]);
    for (int r = 0; r < kq; r++)
      if (fabs(Q[(size_t)r + (size_t)N * (size_t)r]) > 1e-12 * r11) rank++;
    /* Q^T K Q and Q^T M Q by the nc Householder reflectors themselves
       (dormqr, O(N^2 nc)); their trailing (N - rank) blocks are Z^T K Z and
       Z^T M Z (Z: the last N - rank columns of Q) */
    if (LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, N, kq, Q, N, tau, w.K, N) != 0 ||
        LAPACKE_dormqr(LAPACK_COL_MAJOR, 'R', 'N', N, N, kq, Q, N, tau, w.K, N) != 0 ||
        LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, N, kq, Q, N, tau, w.M, N) != 0 ||
        LAPACKE_dormqr(LAPACK_COL_MAJOR, 'R', 'N', N, N, kq, Q, N, tau, w.M, N) != 0) {
      st = cable_error_set(err, CABLE_ERR_LINSOLVE, "", 0, "STAB", "dormqr failed");
      goto done;
    }
  }
  const int nz = N - rank;
  res->nbasis = N;
  res->ndof = nz;
  if (nz < 1) goto done;
  Kz = malloc((size_t)nz * (size_t)nz * sizeof *Kz);
  Mz = malloc((size_t)nz * (size_t)nz * sizeof *Mz);
  ev = malloc((size_t)nz * sizeof *ev);
  if (!Kz || !Mz || !ev) {
    st = cable_error_set(err, CABLE_ERR_ALLOC, "", 0, "STAB", "out of memory (N = %d)", N);
    goto done;
  }
  for (int j = 0; j < nz; j++)
    for (int i = 0; i < nz; i++) {
      size_t src = (size_t)(rank + i) + (size_t)N * (size_t)(rank + j);
      Kz[(size_t)i + (size_t)nz * (size_t)j] = w.K[src];
      Mz[(size_t)i + (size_t)nz * (size_t)j] = w.M[src];
    }
  if (LAPACKE_dsygv(LAPACK_COL_MAJOR, 1, 'N', 'U', nz, Kz, nz, Mz, nz, ev) != 0) {
    st = cable_error_set(err, CABLE_ERR_LINSOLVE, "", 0, "STAB",
                         "dsygv failed (the mass form on the admissible variations is not positive definite?)");
    goto done;
  }
  double big = fmax(fabs(ev[0]), fabs(ev[nz - 1]));
  res->tau = 1e3 * DBL_EPSILON * big;
  for (int i = 0; i < nz; i++) {
    if (ev[i] < -res->tau) res->index++;
    else if (ev[i] <= res->tau) res->nzero++;
  }
  res->neig = nz < CABLE_STAB_NEIG ? nz : CABLE_STAB_NEIG;
  for (int i = 0; i < res->neig; i++) res->eig[i] = ev[i];
done:
  ws_free(&w);
  free(Q); free(Kz); free(Mz); free(ev); free(tau); free(jpvt);
  return st;
}
