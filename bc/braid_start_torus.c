/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The equidistant torus braid: a circular contact curve of radius rc with the
 * chord director d1 turning uniformly about it, psi = nu phi (phi the angle
 * along the circle, nu = hand p/2), strands at -/+ Delta/2 d1.  Construction
 * frame: contact circle c(phi) = rc (cos phi, sin phi, 0) with tangent T,
 * inward normal N, binormal B = e_z; d1 = cos psi N + sin psi B.
 *
 * Every local quantity (speeds, strains, eta, xi_i') depends on phi only
 * through psi, because the circle is homogeneous.  The integrals along the
 * strand (arclength, sigma, xi_i) and the derivative of dg/deta' are
 * therefore taken from Fourier series in psi, which converge geometrically
 * for these analytic periodic functions.  Formulas:
 * doc/braid-boundary-conditions.md, "Torus knots and links". */
#include <float.h>
#include <lapacke.h>
#include <stdlib.h>

#include "braid_model.h"
#include "braid_start_impl.h"
#include "cable/cable_status.h"
#include "cable_vec3.h"

#define NF BRAID_START_NFOURIER
#define NH (BRAID_START_NFOURIER / 2)

/* A Fourier coefficient from index NF/4 up is taken as the series' tail; it
 * must be below this fraction of the function's size.  The coefficients of
 * an analytic periodic function decay geometrically, so a tail this small
 * means the aliased coefficients beyond NF/2 are below ~1e-26 and the
 * series reproduces the function to rounding. */
static const double fs_tail_tol = 1e-13;
/* Newton iterations for the circle radius and for phi(s): both converge
 * quadratically from the first guess (the ratio Delta/rc is small); stop when
 * the correction is a few units of rounding. */
static const double newton_tol = 8.0 * DBL_EPSILON;
static const int newton_maxit = 50;
/* Least-squares samples per half turn of d1 (p half turns along strand 1):
 * the residual functions are trigonometric polynomials in psi dominated by
 * the first few harmonics, so 32 samples per half turn over-determine the 7
 * unknowns with a margin of several times the Nyquist count. */
static const int fit_samples_per_half_turn = 32;
/* Rank check on the column-scaled QR factor: below this ratio the fitted
 * constants would be determined to fewer than ~6 digits by data that are
 * accurate to rounding (1e-16 * 1e10). */
static const double fit_rcond_min = 1e-10;

typedef struct {
  double cpsi, spsi;
  double A, A2;      /* speed terms: |dr1/dphi|^2 = A^2 + beta^2, |dr2/dphi|^2 = A2^2 + beta^2 */
  double v1, v2;     /* |dr1/dphi|, |dr2/dphi| */
  double gamma;      /* tilt of t1 from T about d1 */
  double w1, w2, w3; /* braid strains (per unit s) */
  double eta, etap, sigmap, xi1p, xi2p;
} torus_local;

static void torus_local_eval(const braid_start_params *sp, double rc, double psi, torus_local *g)
{
  const double hd = 0.5 * sp->delta, nu = sp->nu;
  const double beta = -hd * nu; /* dr1/dphi = A T + beta e, e = T x d1 */
  g->cpsi = cos(psi);
  g->spsi = sin(psi);
  g->A = rc + hd * g->cpsi;
  g->A2 = rc - hd * g->cpsi;
  g->v1 = hypot(g->A, beta);
  g->v2 = hypot(g->A2, beta);
  const double a = g->A / g->v1, b = beta / g->v1;
  const double aphi = -hd * g->spsi * nu; /* dA/dphi */
  g->gamma = atan2(-b, a);
  g->w1 = (b * g->cpsi + a * nu) / g->v1;
  g->w2 = (g->spsi + beta * aphi / (g->v1 * g->v1)) / g->v1;
  g->w3 = (a * g->cpsi - b * nu) / g->v1;
  const double y = 2.0 * beta * rc, x = g->A * g->A2 - beta * beta; /* v1 v2 (sin, cos) eta */
  g->eta = atan2(y, x);
  g->etap = -y * aphi * (g->A2 - g->A) / ((x * x + y * y) * g->v1);
  g->sigmap = g->v2 / g->v1;
  g->xi1p = g->w1 - sp->w01 + sp->torque / sp->c1;
  g->xi2p = sin(g->eta) / sp->delta +
            (-sp->torque / sp->c2 + sp->w02) * (1.0 - sp->delta * g->w3) / cos(g->eta);
}

/* ---- Fourier series in psi: f = a0 + sum_{k=1}^{NH-1} a_k cos k psi + b_k sin k psi */

static double fs_value(const braid_start_params *sp, int f, double psi)
{
  double v = sp->fs_a[f][0];
  for (int k = 1; k < NH; k++) v += sp->fs_a[f][k] * cos(k * psi) + sp->fs_b[f][k] * sin(k * psi);
  return v;
}

static double fs_integral(const braid_start_params *sp, int f, double psi) /* int_0^psi */
{
  double v = sp->fs_a[f][0] * psi;
  for (int k = 1; k < NH; k++)
    v += (sp->fs_a[f][k] * sin(k * psi) + sp->fs_b[f][k] * (1.0 - cos(k * psi))) / k;
  return v;
}

static double fs_derivative(const braid_start_params *sp, int f, double psi)
{
  double v = 0.0;
  for (int k = 1; k < NH; k++)
    v += k * (sp->fs_b[f][k] * cos(k * psi) - sp->fs_a[f][k] * sin(k * psi));
  return v;
}

/* Coefficients from NF samples on [0, 2 pi); fails when the tail is too big. */
static int fs_set(braid_start_params *sp, int f, const double *samples)
{
  double scale = 0.0, tail = 0.0;
  for (int k = 0; k < NH; k++) {
    double a = 0.0, b = 0.0;
    for (int j = 0; j < NF; j++) {
      const double x = 2.0 * BRAID_PI * (double)((long)k * j % NF) / NF;
      a += samples[j] * cos(x);
      b += samples[j] * sin(x);
    }
    sp->fs_a[f][k] = (k == 0 ? 1.0 : 2.0) * a / NF;
    sp->fs_b[f][k] = k == 0 ? 0.0 : 2.0 * b / NF;
    if (k >= NF / 4) tail = fmax(tail, fmax(fabs(sp->fs_a[f][k]), fabs(sp->fs_b[f][k])));
  }
  for (int j = 0; j < NF; j++) scale = fmax(scale, fabs(samples[j]));
  return tail <= fs_tail_tol * scale ? CABLE_SUCCESS : CABLE_ERR_UNSUPPORTED;
}

/* Contact-circle radius for a strand-1 length target: L(rc) = 2 pi mean(v1). */
static int solve_rc(const braid_start_params *sp, double target, double *rc_out)
{
  double rc = target / (2.0 * BRAID_PI);
  for (int it = 0; it < newton_maxit; it++) {
    double mean = 0.0, dmean = 0.0;
    for (int j = 0; j < NF; j++) {
      torus_local g;
      torus_local_eval(sp, rc, 2.0 * BRAID_PI * j / NF, &g);
      mean += g.v1 / NF;
      dmean += g.A / g.v1 / NF;
    }
    const double step = (2.0 * BRAID_PI * mean - target) / (2.0 * BRAID_PI * dmean);
    rc -= step;
    if (!isfinite(rc)) break;
    if (fabs(step) <= newton_tol * rc) {
      *rc_out = rc;
      return CABLE_SUCCESS;
    }
  }
  return CABLE_ERR_NEWTON;
}

/* Orientation of the first braid frame in the construction frame:
 * R = Rz(phi + pi/2) Rx(psi) Ry(gamma) (doc: the frame factorisation). */
static void construction_quat(double phi, const torus_local *g, double psi, double *q)
{
  double qz[4], qx[4], qy[4], tmp[4];
  braid_quat_axis(2, phi + 0.5 * BRAID_PI, qz);
  braid_quat_axis(0, psi, qx);
  braid_quat_axis(1, g->gamma, qy);
  braid_quat_mul(qz, qx, tmp);
  braid_quat_mul(tmp, qy, q);
}

/* Construction-frame position of r1 = c - Delta/2 d1 (R: frame matrix). */
static void construction_r1(const braid_start_params *sp, double phi, const double *r, double *x)
{
  x[0] = sp->rc * cos(phi) - 0.5 * sp->delta * r[3];
  x[1] = sp->rc * sin(phi) - 0.5 * sp->delta * r[4];
  x[2] = -0.5 * sp->delta * r[5];
}

/* The three constitutive residuals at phi as rows of the linear least-squares
 * problem in x = (F (3), M(0) (3), h), all in the construction frame:
 *   M2 - dg/domega2,  M1 - k (dg/deta - d/ds dg/deta'),  M3 + tan(eta) M1 - dg/domega3,
 * with k = Delta cos^2 eta/(Delta omega3 - 1) and body components
 * M = R^T (M(0) - (r1 - r1(0)) x F).  residual = rows x - rhs. */
static int fit_rows(const braid_start_params *sp, const braid_material *m, double phi,
                    double rows[3][7], double rhs[3])
{
  const double psi = sp->nu * phi;
  torus_local g;
  torus_local_eval(sp, sp->rc, psi, &g);
  double q[4], r[9], x[3], d[3];
  construction_quat(phi, &g, psi, q);
  braid_quat_matrix(q, r);
  construction_r1(sp, phi, r, x);
  for (int i = 0; i < 3; i++) d[i] = x[i] - sp->r0[i];
  double cf[3][3], cm[3][3]; /* body M = cm M(0) + cf F */
  for (int j = 0; j < 3; j++) {
    double e[3] = {0, 0, 0}, dxe[3];
    e[j] = 1.0;
    cable_vec3_cross(d, e, dxe);
    for (int i = 0; i < 3; i++) {
      cm[i][j] = r[j + 3 * i];
      cf[i][j] = -(r[0 + 3 * i] * dxe[0] + r[1 + 3 * i] * dxe[1] + r[2 + 3 * i] * dxe[2]);
    }
  }
  braid_gpartials g0, g1;
  if (braid_g_partials(g.eta, g.etap, g.w2, g.w3, g.xi1p, g.xi2p, 0.0, m, &g0) != 0 ||
      braid_g_partials(g.eta, g.etap, g.w2, g.w3, g.xi1p, g.xi2p, 1.0, m, &g1) != 0)
    return CABLE_ERR_INPUT;
  const double k = sp->delta * cos(g.eta) * cos(g.eta) / (sp->delta * g.w3 - 1.0);
  const double te = tan(g.eta);
  const double dpds = sp->nu / g.v1 * fs_derivative(sp, BRAID_FS_DETAP, psi);
  for (int j = 0; j < 3; j++) {
    rows[0][j] = cf[1][j];
    rows[0][3 + j] = cm[1][j];
    rows[1][j] = cf[0][j];
    rows[1][3 + j] = cm[0][j];
    rows[2][j] = cf[2][j] + te * cf[0][j];
    rows[2][3 + j] = cm[2][j] + te * cm[0][j];
  }
  rows[0][6] = -(g1.dw2 - g0.dw2);
  rows[1][6] = -k * (g1.deta - g0.deta);
  rows[2][6] = -(g1.dw3 - g0.dw3);
  rhs[0] = g0.dw2;
  rhs[1] = k * (g0.deta - dpds);
  rhs[2] = g0.dw3;
  return CABLE_SUCCESS;
}

static int fit_forces(braid_start_params *sp, const braid_material *m)
{
  /* Knots: the braid continued past s = L (strands swapped) closes after two
   * turns of the contact circle; fitting over both keeps the Z_p symmetry. */
  const int turns = sp->p % 2 == 1 ? 2 : 1;
  const int ns = fit_samples_per_half_turn * (sp->p + 1) * turns, nr = 3 * ns, nc = 7;
  double *a = malloc(sizeof(double) * (size_t)nr * nc);
  double *b = malloc(sizeof(double) * (size_t)nr);
  int status = CABLE_SUCCESS;
  if (a == NULL || b == NULL) {
    status = CABLE_ERR_ALLOC;
    goto done;
  }
  for (int i = 0; i < ns && status == CABLE_SUCCESS; i++) {
    double rows[3][7], rhs[3];
    status = fit_rows(sp, m, 2.0 * BRAID_PI * turns * i / ns, rows, rhs);
    for (int e = 0; e < 3; e++) {
      for (int j = 0; j < nc; j++) a[(3 * i + e) + (size_t)nr * j] = rows[e][j];
      b[3 * i + e] = rhs[e];
    }
  }
  if (status != CABLE_SUCCESS) goto done;
  double colscale[7];
  for (int j = 0; j < nc; j++) {
    double s = 0.0;
    for (int i = 0; i < nr; i++) s = hypot(s, a[i + (size_t)nr * j]);
    colscale[j] = s > 0 ? s : 1.0;
    for (int i = 0; i < nr; i++) a[i + (size_t)nr * j] /= colscale[j];
  }
  if (LAPACKE_dgels(LAPACK_COL_MAJOR, 'N', nr, nc, 1, a, nr, b, nr) != 0) {
    status = CABLE_ERR_LINSOLVE;
    goto done;
  }
  double rmin = INFINITY, rmax = 0.0;
  for (int j = 0; j < nc; j++) {
    const double rjj = fabs(a[j + (size_t)nr * j]);
    rmin = fmin(rmin, rjj);
    rmax = fmax(rmax, rjj);
  }
  sp->fit_rcond = rmax > 0 ? rmin / rmax : 0.0;
  if (!(sp->fit_rcond >= fit_rcond_min)) {
    status = CABLE_ERR_LINSOLVE;
    goto done;
  }
  double xs[7];
  for (int j = 0; j < nc; j++) xs[j] = b[j] / colscale[j];
  for (int j = 0; j < 3; j++) {
    sp->fin[j] = xs[j];
    sp->m0[j] = xs[3 + j];
  }
  sp->h = xs[6];
  double sum2 = 0.0, worst = 0.0;
  for (int i = 0; i < ns; i++) {
    double rows[3][7], rhs[3];
    fit_rows(sp, m, 2.0 * BRAID_PI * turns * i / ns, rows, rhs);
    for (int e = 0; e < 3; e++) {
      double res = -rhs[e];
      for (int j = 0; j < nc; j++) res += rows[e][j] * xs[j];
      sum2 += res * res;
      worst = fmax(worst, fabs(res));
    }
  }
  sp->fit_max = worst;
  sp->fit_rms = sqrt(sum2 / nr);
done:
  free(a);
  free(b);
  return status;
}

int braid_start_torus_prepare(braid_start_params *sp)
{
  if (sp->p < 1 || (sp->hand != 1 && sp->hand != -1)) return CABLE_ERR_INPUT;
  const int knot = sp->p % 2 == 1;
  const braid_material m = {sp->delta, sp->b1, sp->b2, sp->c1, sp->c2, sp->w01, sp->w02};
  sp->nu = 0.5 * sp->hand * sp->p;
  int status = solve_rc(sp, knot ? 0.5 * sp->length : sp->length, &sp->rc);
  if (status != CABLE_SUCCESS) return status;
  if (!(sp->rc > sp->delta)) return CABLE_ERR_INPUT;

  double samples[BRAID_FS_N][NF];
  for (int j = 0; j < NF; j++) {
    torus_local g;
    torus_local_eval(sp, sp->rc, 2.0 * BRAID_PI * j / NF, &g);
    braid_gpartials gp;
    if (braid_g_partials(g.eta, g.etap, g.w2, g.w3, g.xi1p, g.xi2p, 0.0, &m, &gp) != 0)
      return CABLE_ERR_INPUT;
    samples[BRAID_FS_V1][j] = g.v1;
    samples[BRAID_FS_V2][j] = g.v2;
    samples[BRAID_FS_XI1][j] = g.xi1p * g.v1;
    samples[BRAID_FS_XI2][j] = g.xi2p * g.v1;
    samples[BRAID_FS_DETAP][j] = gp.detap;
  }
  for (int f = 0; f < BRAID_FS_N; f++)
    if ((status = fs_set(sp, f, samples[f])) != CABLE_SUCCESS) return status;
  sp->l = 2.0 * BRAID_PI * sp->fs_a[BRAID_FS_V1][0];
  sp->l2 = 2.0 * BRAID_PI * sp->fs_a[BRAID_FS_V2][0];

  /* Rigid motion to the BC frame: r1(0) -> 0, frame(0) -> q(0) of (12.3.4-7). */
  torus_local g0;
  torus_local_eval(sp, sp->rc, 0.0, &g0);
  double q0[4], r[9], q0c[4];
  construction_quat(0.0, &g0, 0.0, q0);
  braid_quat_matrix(q0, r);
  construction_r1(sp, 0.0, r, sp->r0);
  const double qbc[4] = {0.0, -BRAID_SQRT_HALF, -BRAID_SQRT_HALF, 0.0};
  q0c[0] = q0[0];
  for (int i = 1; i < 4; i++) q0c[i] = -q0[i];
  braid_quat_mul(qbc, q0c, sp->qp);

  if ((status = fit_forces(sp, &m)) != CABLE_SUCCESS) return status;
  const double phi_link = knot ? 0.0 : sp->hand * sp->p * BRAID_PI;
  braid_start_set_par(sp, sp->l, sp->l2, knot ? sp->length : sp->l + sp->l2, phi_link, g0.w2);
  return CABLE_SUCCESS;
}

static int solve_phi(const braid_start_params *sp, double s, double *phi_out);

int braid_start_fit_residual(const braid_start_params *sp, double t, double *res)
{
  if (sp == NULL || !sp->ready || sp->kind != BRAID_START_TORUS) return CABLE_ERR_INPUT;
  const braid_material m = {sp->delta, sp->b1, sp->b2, sp->c1, sp->c2, sp->w01, sp->w02};
  const double x[7] = {sp->fin[0], sp->fin[1], sp->fin[2], sp->m0[0], sp->m0[1], sp->m0[2], sp->h};
  double phi, rows[3][7], rhs[3];
  int st = solve_phi(sp, sp->l * t, &phi);
  if (st == CABLE_SUCCESS) st = fit_rows(sp, &m, phi, rows, rhs);
  if (st != CABLE_SUCCESS) return st;
  for (int e = 0; e < 3; e++) {
    res[e] = -rhs[e];
    for (int j = 0; j < 7; j++) res[e] += rows[e][j] * x[j];
  }
  return CABLE_SUCCESS;
}

/* phi with arclength s along strand 1: int_0^phi v1 = I_V1(nu phi)/nu = s. */
static int solve_phi(const braid_start_params *sp, double s, double *phi_out)
{
  double phi = s / sp->fs_a[BRAID_FS_V1][0];
  for (int it = 0; it < newton_maxit; it++) {
    const double psi = sp->nu * phi;
    const double f = fs_integral(sp, BRAID_FS_V1, psi) / sp->nu - s;
    const double step = f / fs_value(sp, BRAID_FS_V1, psi);
    phi -= step;
    if (!isfinite(phi)) break;
    if (fabs(step) <= newton_tol * (1.0 + fabs(phi))) {
      *phi_out = phi;
      return CABLE_SUCCESS;
    }
  }
  return CABLE_ERR_NEWTON;
}

int braid_start_torus_state(const braid_start_params *sp, double t, double *u)
{
  double phi;
  if (solve_phi(sp, sp->l * t, &phi) != CABLE_SUCCESS) return 1;
  const double psi = sp->nu * phi;
  torus_local g;
  torus_local_eval(sp, sp->rc, psi, &g);
  double qc[4], r[9], x[3], d[3], dxf[3], min[3];
  construction_quat(phi, &g, psi, qc);
  braid_quat_matrix(qc, r);
  construction_r1(sp, phi, r, x);
  for (int i = 0; i < 3; i++) d[i] = x[i] - sp->r0[i];
  cable_vec3_cross(d, sp->fin, dxf);
  for (int i = 0; i < 3; i++) min[i] = sp->m0[i] - dxf[i];
  for (int i = 0; i < 3; i++) {
    const double *col = r + 3 * i;
    u[BR_F1 + i] = col[0] * sp->fin[0] + col[1] * sp->fin[1] + col[2] * sp->fin[2];
    u[BR_M1 + i] = col[0] * min[0] + col[1] * min[1] + col[2] * min[2];
  }
  u[BR_ETA] = g.eta;
  u[BR_W2] = g.w2;
  u[BR_W3] = g.w3;
  u[BR_XI1] = fs_integral(sp, BRAID_FS_XI1, psi) / sp->nu;
  u[BR_T1] = sp->torque;
  u[BR_XI2] = fs_integral(sp, BRAID_FS_XI2, psi) / sp->nu;
  u[BR_T2] = -sp->torque;
  double q[4], rp[9];
  braid_quat_mul(sp->qp, qc, q);
  for (int i = 0; i < 4; i++) u[BR_Q0 + i] = q[i];
  braid_quat_matrix(sp->qp, rp);
  for (int i = 0; i < 3; i++)
    u[BR_X1 + i] = rp[i] * d[0] + rp[i + 3] * d[1] + rp[i + 6] * d[2];
  u[BR_SIGMA] = fs_integral(sp, BRAID_FS_V2, psi) / sp->nu;
  return 0;
}
