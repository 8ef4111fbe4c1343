/* SPDX-License-Identifier: GPL-3.0-or-later */
/* First variation of the action at a buckled link (doc/links.md, "First
 * variation").  The link conditions (12.3.24)-(12.3.44) must make a computed
 * link a critical point of
 *
 *   A = int_0^L g_e(omega2, omega3, eta, eta', xi1', xi2') ds - t10 xi1(L) - t20 xi2(L)
 *
 * (Eq. 12.2.22; xi_i(0) = 0, xi_i(L) free, t10 = T, t20 = -T) among closed
 * links of the same strand lengths at the same finite Delta: for every
 * admissible variation, dA is a combination of the variations of the 7
 * constraints c = (r1(L) - r1(0), vector part of q(0)^-1 q(L), sigma(L) - L2).
 * Nothing of the ODEs is used: the configuration is rebuilt from the strain
 * fields by integrating the kinematics (12.2.23), r1' = t1, sigma' (12.2.6).
 *
 * Variations: omega2, omega3, xi1', xi2' by 1, s, cos and sin(2 pi k s/L)
 * (k = 1..3), eta by the periodic ones (strand 2's tangent must close), 39 in
 * all.  dA_j and dc_j by central differences; a = C^T lambda is solved by
 * least squares and the residual |a - C^T lambda| / |a| must vanish to the
 * discretisation error.  lambda must then be the solution's own multipliers:
 * the force F (inertial frame) for the closure of r1, -h for sigma(L).  Negative
 * control: the action with t20 = +T (the reading "t20 = t10") is not stationary. */
#include <math.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "braid_model.h"
#include "cable/cable_error.h"
#include "harness.h"

enum { NBASIS = 8, NFIELD = 5, NDIR = 4 * NBASIS + (NBASIS - 1), NCON = 7, NSUB = 2 };
static const double two_pi = 6.28318530717958647692;
/* central differences in the variation amplitude: eps = 1e-6 on strains of
 * O(1..50): truncation eps^2 |A'''| and rounding eps_mach |A| / eps ~ 1e-8
 * for |A| ~ 1e2, both below the discretisation level checked below */
static const double var_eps = 1e-6;
/* The configuration is rebuilt with RK4 on the collocation polynomial
 * (NSUB steps per collocation point spacing, h ~ 1/400 at NTST 50): the
 * residual is the collocation solution's own discretisation error seen
 * through A, measured 6.4e-9 relative (NTST 50, doc/links.md); 1e-6 leaves a
 * factor 150, and the wrong reading below gives 1.5e-2. */
static const double stat_tol = 1e-6;
/* the multipliers are recovered to the collocation accuracy: measured
 * 8.6e-8 (F) and 1.0e-6 (h, which carries 1/Delta factors) at NTST 50 */
static const double mult_tol = 1e-5;

typedef struct {
  const cable_solution *sol;
  braid_material m;
  double L, L2, T, t20;
  int dir;       /* variation direction, -1 for none */
  double amp;    /* its amplitude */
} action_ctx;

static double basis(int j, double x, double *dphi, double L)
{
  /* x = s/L; j = 0: 1, 1: s/L (non-periodic), 2..7: cos, sin(2 pi k x) */
  if (j == 0) { *dphi = 0.0; return 1.0; }
  if (j == 1) { *dphi = 1.0 / L; return x; }
  const int k = (j - 2) / 2 + 1;
  const double w = two_pi * k;
  if ((j - 2) % 2 == 0) { *dphi = -w / L * sin(w * x); return cos(w * x); }
  *dphi = w / L * cos(w * x);
  return sin(w * x);
}

/* the collocation polynomial of the stored solution at t in [0, 1] */
static void interp(const cable_solution *s, double t, double *u)
{
  const int ncol = s->ncol;
  int j = 0;
  while (j < s->ntst - 1 && t > s->t[(j + 1) * ncol]) j++;
  const double *tt = s->t + j * ncol;
  for (int i = 0; i < BR_NDIM; i++) u[i] = 0.0;
  for (int a = 0; a <= ncol; a++) {
    double l = 1.0;
    for (int b = 0; b <= ncol; b++)
      if (b != a) l *= (t - tt[b]) / (tt[a] - tt[b]);
    const double *ua = s->u + (size_t)(j * ncol + a) * BR_NDIM;
    for (int i = 0; i < BR_NDIM; i++) u[i] += l * ua[i];
  }
}

/* fields (eta, eta', omega2, omega3, xi1', xi2') at s, with the variation */
static int fields(const action_ctx *c, double s, double *f)
{
  double u[BR_NDIM];
  interp(c->sol, s / c->L, u);
  braid_aux aux;
  const int st = braid_aux_eval(u, &c->m, &aux);
  if (st != 0) return st;
  f[0] = u[BR_ETA]; f[1] = aux.etap; f[2] = u[BR_W2]; f[3] = u[BR_W3];
  f[4] = aux.xi1p; f[5] = aux.xi2p;
  if (c->dir >= 0) {
    double dphi;
    if (c->dir < 4 * NBASIS) {
      const int field = c->dir / NBASIS, j = c->dir % NBASIS;
      const double phi = basis(j, s / c->L, &dphi, c->L);
      const int slot[4] = {2, 3, 4, 5}; /* omega2, omega3, xi1', xi2' */
      f[slot[field]] += c->amp * phi;
    } else {
      const int j = c->dir - 4 * NBASIS; /* periodic: skip s/L */
      const double phi = basis(j == 0 ? 0 : j + 1, s / c->L, &dphi, c->L);
      f[0] += c->amp * phi;
      f[1] += c->amp * dphi;
    }
  }
  return 0;
}

/* dy/ds for y = (q0..q3, x, y, z, sigma, A) */
static int deriv(const action_ctx *c, double s, const double *y, double *dy)
{
  double f[6];
  int st = fields(c, s, f);
  if (st != 0) return st;
  const double eta = f[0], w2 = f[2], w3 = f[3], D = c->m.Delta;
  const double w1 = (w3 - 1.0 / D) * tan(eta);
  const double *q = y;
  dy[0] = 0.5 * (-w1 * q[1] - w2 * q[2] - w3 * q[3]);
  dy[1] = 0.5 * (w1 * q[0] + w3 * q[2] - w2 * q[3]);
  dy[2] = 0.5 * (w2 * q[0] - w3 * q[1] + w1 * q[3]);
  dy[3] = 0.5 * (w3 * q[0] + w2 * q[1] - w1 * q[2]);
  dy[4] = q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3];
  dy[5] = 2 * (q[1] * q[2] + q[0] * q[3]);
  dy[6] = 2 * (q[1] * q[3] - q[0] * q[2]);
  dy[7] = (1.0 - D * w3) / cos(eta);
  braid_gpartials gp;
  st = braid_g_partials(eta, f[1], w2, w3, f[4], f[5], 0.0, &c->m, &gp);
  if (st != 0) return st;
  /* A = int g_e - t10 xi1(L) - t20 xi2(L), xi_i(L) = int xi_i' */
  dy[8] = gp.g - c->T * f[4] - c->t20 * f[5];
  return 0;
}

enum { NY = 9 };

/* A and the constraints c[7] of the varied configuration */
static int evaluate(const action_ctx *c, double *A, double *con)
{
  const cable_solution *s = c->sol;
  double y[NY] = {0}, k1[NY], k2[NY], k3[NY], k4[NY], yt[NY];
  const double *u0 = s->u;
  for (int i = 0; i < 4; i++) y[i] = u0[BR_Q0 + i];
  int st = 0;
  const int npts = cable_solution_npts(s);
  for (int p = 0; p + 1 < npts; p++) {
    const double sa = c->L * s->t[p], sb = c->L * s->t[p + 1];
    for (int k = 0; k < NSUB; k++) {
      const double h = (sb - sa) / NSUB, x = sa + k * h;
      st |= deriv(c, x, y, k1);
      for (int i = 0; i < NY; i++) yt[i] = y[i] + 0.5 * h * k1[i];
      st |= deriv(c, x + 0.5 * h, yt, k2);
      for (int i = 0; i < NY; i++) yt[i] = y[i] + 0.5 * h * k2[i];
      st |= deriv(c, x + 0.5 * h, yt, k3);
      for (int i = 0; i < NY; i++) yt[i] = y[i] + h * k3[i];
      st |= deriv(c, x + h, yt, k4);
      for (int i = 0; i < NY; i++) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
  }
  *A = y[8];
  for (int i = 0; i < 3; i++) con[i] = y[4 + i]; /* r1(L) - r1(0), r1(0) = 0 */
  /* q(0)^-1 q(L) = (w, v): v is half the closure rotation (body frame at 0) */
  const double *a = u0 + BR_Q0, *b = y;
  const double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const double sg = w < 0 ? -1.0 : 1.0;
  con[3] = sg * (a[0] * b[1] - a[1] * b[0] - a[2] * b[3] + a[3] * b[2]);
  con[4] = sg * (a[0] * b[2] + a[1] * b[3] - a[2] * b[0] - a[3] * b[1]);
  con[5] = sg * (a[0] * b[3] - a[1] * b[2] + a[2] * b[1] - a[3] * b[0]);
  con[6] = y[7] - c->L2;
  return st;
}

/* least squares a ~ C^T lambda (C: NCON x NDIR) by the normal equations
 * (7 x 7, Cholesky-free Gaussian elimination with partial pivoting); returns
 * |a - C^T lambda| / |a| */
static double stationarity(const double *a, const double C[NCON][NDIR], double *lambda)
{
  double N[NCON][NCON + 1];
  for (int i = 0; i < NCON; i++) {
    for (int j = 0; j < NCON; j++) {
      double sum = 0.0;
      for (int k = 0; k < NDIR; k++) sum += C[i][k] * C[j][k];
      N[i][j] = sum;
    }
    double r = 0.0;
    for (int k = 0; k < NDIR; k++) r += C[i][k] * a[k];
    N[i][NCON] = r;
  }
  for (int col = 0; col < NCON; col++) {
    int piv = col;
    for (int r = col + 1; r < NCON; r++)
      if (fabs(N[r][col]) > fabs(N[piv][col])) piv = r;
    for (int j = 0; j <= NCON; j++) { double t = N[col][j]; N[col][j] = N[piv][j]; N[piv][j] = t; }
    for (int r = col + 1; r < NCON; r++) {
      const double f = N[r][col] / N[col][col];
      for (int j = col; j <= NCON; j++) N[r][j] -= f * N[col][j];
    }
  }
  for (int r = NCON - 1; r >= 0; r--) {
    double sum = N[r][NCON];
    for (int j = r + 1; j < NCON; j++) sum -= N[r][j] * lambda[j];
    lambda[r] = sum / N[r][r];
  }
  double res = 0.0, an = 0.0;
  for (int k = 0; k < NDIR; k++) {
    double ct = 0.0;
    for (int i = 0; i < NCON; i++) ct += C[i][k] * lambda[i];
    res += (a[k] - ct) * (a[k] - ct);
    an += a[k] * a[k];
  }
  return sqrt(res / an);
}

/* gradient a and constraint Jacobian C by central differences */
static int gradients(action_ctx *c, double *a, double C[NCON][NDIR])
{
  int st = 0;
  for (int d = 0; d < NDIR; d++) {
    double Ap, Am, cp[NCON], cm[NCON];
    c->dir = d;
    c->amp = var_eps;
    st |= evaluate(c, &Ap, cp);
    c->amp = -var_eps;
    st |= evaluate(c, &Am, cm);
    a[d] = (Ap - Am) / (2 * var_eps);
    for (int i = 0; i < NCON; i++) C[i][d] = (cp[i] - cm[i]) / (2 * var_eps);
  }
  c->dir = -1;
  return st;
}

int main(void)
{
  cable_error err;
  cable_sfile *sf = cable_sfile_read("tests/data/s.link62_buckled", &err);
  if (!test_true("first variation: tests/data/s.link62_buckled read", sf != NULL)) return test_summary();
  const cable_solution *sol = cable_sfile_get(sf, 0);
  action_ctx c = {.sol = sol, .L = sol->par[BP_L], .L2 = sol->par[BP_L2], .T = sol->par[BP_T],
                  .t20 = -sol->par[BP_T], .dir = -1, .amp = 0.0};
  braid_material_from_par(sol->par, &c.m);

  double A0, c0[NCON];
  int st = evaluate(&c, &A0, c0);
  double cmax = 0.0;
  for (int i = 0; i < NCON; i++) cmax = fmax(cmax, fabs(c0[i]));
  test_int("first variation: the configuration is rebuilt", st, 0);
  /* the rebuilt configuration closes to the integration + collocation error */
  test_le("first variation: the rebuilt link closes (max |c|)", cmax, 1e-6);

  static double C[NCON][NDIR];
  double a[NDIR], lambda[NCON];
  st = gradients(&c, a, C);
  test_int("first variation: every varied configuration is in the domain", st, 0);
  const double res = stationarity(a, C, lambda);
  double an = 0.0;
  for (int k = 0; k < NDIR; k++) an = fmax(an, fabs(a[k]));
  printf("# A = %.12g, max |dA| = %.6g, stationarity residual %.3e\n", A0, an, res);
  test_le("first variation: dA = lambda . dc over 39 admissible variations (rel. residual)", res, stat_tol);

  /* the multipliers: F in the inertial frame (t1, d1, u1 at s = 0 are
     R(q(0)) e_k) and -h */
  const double *u0 = sol->u, *q = u0 + BR_Q0;
  const double R[3][3] = {
    {q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3], 2 * (q[1] * q[2] - q[0] * q[3]), 2 * (q[1] * q[3] + q[0] * q[2])},
    {2 * (q[1] * q[2] + q[0] * q[3]), q[0] * q[0] - q[1] * q[1] + q[2] * q[2] - q[3] * q[3], 2 * (q[2] * q[3] - q[0] * q[1])},
    {2 * (q[1] * q[3] - q[0] * q[2]), 2 * (q[2] * q[3] + q[0] * q[1]), q[0] * q[0] - q[1] * q[1] - q[2] * q[2] + q[3] * q[3]}};
  double Fin[3], Fmag = 0.0, dF = 0.0;
  for (int i = 0; i < 3; i++) {
    Fin[i] = R[i][0] * u0[BR_F1] + R[i][1] * u0[BR_F2] + R[i][2] * u0[BR_F3];
    Fmag += Fin[i] * Fin[i];
  }
  Fmag = sqrt(Fmag);
  for (int i = 0; i < 3; i++) dF = fmax(dF, fabs(lambda[i] - Fin[i]));
  braid_aux aux;
  braid_aux_eval(u0, &c.m, &aux);
  printf("# lambda_r = (%.8g, %.8g, %.8g), F = (%.8g, %.8g, %.8g); lambda_sigma = %.8g, h = %.8g\n",
         lambda[0], lambda[1], lambda[2], Fin[0], Fin[1], Fin[2], lambda[6], aux.h);
  test_le("first variation: lambda of the closure of r1 is the braid force F (max diff / |F|)", dF / Fmag,
          mult_tol);
  test_rel("first variation: lambda of sigma(L) = L2 is -h", lambda[6], -aux.h, mult_tol);

  /* negative control: the reading t20 = +t10 is not stationary here */
  c.t20 = sol->par[BP_T];
  gradients(&c, a, C);
  const double res_bad = stationarity(a, C, lambda);
  printf("# with t20 = +T: residual %.3e\n", res_bad);
  test_true("first variation: the action with t20 = +T is not stationary (residual > 1e3 tol)",
            res_bad > 1e3 * stat_tol);
  cable_sfile_free(sf);
  return test_summary();
}
