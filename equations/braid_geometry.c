/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "braid_geometry.h"

#include <math.h>
#include <stdlib.h>

#include "braid_state.h"
#include "cable/cable_status.h"
#include "curve_interp.h"
#include "ribbon.h"

braid_curves *braid_curves_alloc(int n)
{
  if (n < 2) return NULL;
  braid_curves *bc = calloc(1, sizeof *bc);
  if (!bc) return NULL;
  bc->n = n;
  size_t m = (size_t)n;
  bc->s = calloc(m, sizeof *bc->s);
  bc->sigma = calloc(m, sizeof *bc->sigma);
  bc->r1 = calloc(3 * m, sizeof *bc->r1);
  bc->r2 = calloc(3 * m, sizeof *bc->r2);
  bc->c = calloc(3 * m, sizeof *bc->c);
  bc->t1 = calloc(3 * m, sizeof *bc->t1);
  bc->d1 = calloc(3 * m, sizeof *bc->d1);
  bc->u1 = calloc(3 * m, sizeof *bc->u1);
  if (!bc->s || !bc->sigma || !bc->r1 || !bc->r2 || !bc->c || !bc->t1 || !bc->d1 || !bc->u1) {
    braid_curves_free(bc);
    return NULL;
  }
  return bc;
}

void braid_curves_free(braid_curves *bc)
{
  if (!bc) return;
  free(bc->s); free(bc->sigma); free(bc->r1); free(bc->r2); free(bc->c);
  free(bc->t1); free(bc->d1); free(bc->u1);
  free(bc);
}

int braid_geometry_check(const cable_solution *sol)
{
  if (!sol || sol->ndim < BR_NDIM || !sol->par || sol->npar <= BP_DELTA) return CABLE_ERR_INPUT;
  int rc = curve_interp_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  double L = sol->par[BP_L], Delta = sol->par[BP_DELTA];
  if (!isfinite(L) || !isfinite(Delta)) return CABLE_ERR_NONFINITE;
  if (!(L > 0) || !(Delta > 0)) return CABLE_ERR_INPUT;
  return CABLE_SUCCESS;
}

/* Symmetric bilinear forms B(p,q) with B(q,q) = the paper's quadratic
 * expressions for t1, d1, u1 (Sect. 12.2.3); differentiating B(q,q) by the
 * product rule gives exact derivatives of the frame of the interpolant. */
static void bil_t(const double *p, const double *q, double *v)
{
  v[0] = p[0] * q[0] + p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
  v[1] = p[1] * q[2] + p[2] * q[1] + p[0] * q[3] + p[3] * q[0];
  v[2] = p[1] * q[3] + p[3] * q[1] - p[0] * q[2] - p[2] * q[0];
}

static void bil_d(const double *p, const double *q, double *v)
{
  v[0] = p[1] * q[2] + p[2] * q[1] - p[0] * q[3] - p[3] * q[0];
  v[1] = p[0] * q[0] - p[1] * q[1] + p[2] * q[2] - p[3] * q[3];
  v[2] = p[2] * q[3] + p[3] * q[2] + p[0] * q[1] + p[1] * q[0];
}

static void bil_u(const double *p, const double *q, double *v)
{
  v[0] = p[1] * q[3] + p[3] * q[1] + p[0] * q[2] + p[2] * q[0];
  v[1] = p[2] * q[3] + p[3] * q[2] - p[0] * q[1] - p[1] * q[0];
  v[2] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] + p[3] * q[3];
}

static double dot4(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

int braid_point_eval(const cable_solution *sol, double t, int *hint, braid_point *p)
{
  /* q0..q3, x1..z1, sigma are contiguous in the state (braid_state.h) */
  enum { NC = BR_SIGMA - BR_Q0 + 1 };
  double v[NC], dv[NC], d2v[NC];
  int j = curve_interp_locate(sol, t, hint ? *hint : -1);
  if (hint) *hint = j;
  curve_interp_eval_on(sol, j, t, BR_Q0, NC, v, dv, d2v);
  const double *q = v, *dq = dv, *d2q = d2v;
  double n = dot4(q, q);
  if (!(n > 0)) return CABLE_ERR_INPUT;
  double dn = 2.0 * dot4(q, dq), d2n = 2.0 * (dot4(dq, dq) + dot4(q, d2q));
  double V[3], A[3], B[3], C[3];
  bil_t(q, q, V);
  for (int i = 0; i < 3; i++) p->t1[i] = V[i] / n;
  bil_u(q, q, V);
  for (int i = 0; i < 3; i++) p->u1[i] = V[i] / n;
  bil_d(q, q, V);
  bil_d(q, dq, A);
  bil_d(dq, dq, B);
  bil_d(q, d2q, C);
  for (int i = 0; i < 3; i++) {
    double dV = 2.0 * A[i], d2V = 2.0 * (B[i] + C[i]);
    p->d1[i] = V[i] / n;
    p->dd1[i] = dV / n - V[i] * dn / (n * n);
    p->d2d1[i] = d2V / n - 2.0 * dV * dn / (n * n) - V[i] * d2n / (n * n) +
                 2.0 * V[i] * dn * dn / (n * n * n);
  }
  double hd = 0.5 * sol->par[BP_DELTA];
  for (int i = 0; i < 3; i++) {
    p->r1[i] = v[4 + i];
    p->dr1[i] = dv[4 + i];
    p->d2r1[i] = d2v[4 + i];
    p->c[i] = p->r1[i] + hd * p->d1[i];
    p->dc[i] = p->dr1[i] + hd * p->dd1[i];
    p->d2c[i] = p->d2r1[i] + hd * p->d2d1[i];
  }
  p->qnorm2 = n;
  p->sigma = v[7];
  return CABLE_SUCCESS;
}

double braid_point_contact_curvature(const braid_point *p)
{
  const double *a = p->dc, *b = p->d2c;
  double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
  double sp = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return sqrt(x * x + y * y + z * z) / (sp * sp * sp);
}

/* Sample k of n, uniform in t on [t_first, t_last] with both ends exact. */
static double sample_t(const cable_solution *sol, int k, int n)
{
  double t0 = sol->t[0], t1 = sol->t[cable_solution_npts(sol) - 1];
  if (k == n - 1) return t1;
  return t0 + (t1 - t0) * (double)k / (double)(n - 1);
}

int braid_curves_from_solution(const cable_solution *sol, braid_curves *out)
{
  if (!out || out->n < 2) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  out->L = sol->par[BP_L];
  out->L2 = sol->par[BP_L2];
  out->Delta = sol->par[BP_DELTA];
  int hint = -1;
  for (int k = 0; k < out->n; k++) {
    double t = sample_t(sol, k, out->n);
    braid_point p;
    rc = braid_point_eval(sol, t, &hint, &p);
    if (rc != CABLE_SUCCESS) return rc;
    out->s[k] = out->L * t;
    out->sigma[k] = p.sigma;
    for (int i = 0; i < 3; i++) {
      out->r1[3 * k + i] = p.r1[i];
      out->r2[3 * k + i] = p.r1[i] + out->Delta * p.d1[i];
      out->c[3 * k + i] = p.c[i];
      out->t1[3 * k + i] = p.t1[i];
      out->d1[3 * k + i] = p.d1[i];
      out->u1[3 * k + i] = p.u1[i];
    }
  }
  return CABLE_SUCCESS;
}

int braid_contact_curvature(const cable_solution *sol, int n, double *kappa, double *kappa_max)
{
  if (n < 2) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  int hint = -1;
  double kmax = 0.0;
  for (int k = 0; k < n; k++) {
    braid_point p;
    rc = braid_point_eval(sol, sample_t(sol, k, n), &hint, &p);
    if (rc != CABLE_SUCCESS) return rc;
    double kap = braid_point_contact_curvature(&p);
    if (!isfinite(kap)) return CABLE_ERR_NONFINITE;
    if (kappa) kappa[k] = kap;
    if (kap > kmax) kmax = kap;
  }
  if (kappa_max) *kappa_max = kmax;
  return CABLE_SUCCESS;
}
