/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Structured collocation solver (continuation/abd_solver.h) against dense
 * LAPACK on colloc_jac_to_dense, a long-double reference for a stiff
 * boundary-value problem, and dgesvd for the smallest singular values.
 *
 * Tolerances (kappa = infinity-norm condition number estimated by dgecon,
 * eps = DBL_EPSILON):
 *  - solution:   ||x - x_ref||_inf / ||x_ref||_inf <= SOLVE_C * n * eps * kappa.
 *    Both solutions are backward stable (Gaussian elimination with partial
 *    pivoting): each has forward error <= kappa times a backward error of
 *    order n*eps; SOLVE_C = 4 covers the two of them plus the estimate's slack.
 *  - backward error: ||J x - b|| / (||J|| ||x|| + ||b||) <= n * eps * max(1, growth).
 *  - log|det|: d log det = trace(J^{-1} dJ), |.| <= n * kappa * ||dJ|| / ||J||,
 *    with ||dJ||/||J|| <= n*eps for each of the two factorisations:
 *    tol = 2 * n^2 * eps * kappa.
 */
#include "abd_solver.h"
#include "colloc_jac.h"
#include "harness.h"

#include <float.h>
#include <gsl/gsl_integration.h>
#include <lapacke.h>
#include <stdint.h>
#include <string.h>

#define SOLVE_C 4.0
/* Stiff problem: the brief's acceptance bound on the relative error against
 * the exact discrete solution (long-double elimination). */
#define STIFF_TOL 1e-10
#define STIFF_PI 3.14159265358979323846

typedef struct {
  uint64_t s;
} rng;

static double rng_uniform(rng *g) /* in [-1, 1) */
{
  g->s = g->s * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
  return (double)(g->s >> 11) * 0x1.0p-52 - 1.0;
}

static void fill_random(double *v, size_t len, rng *g)
{
  for (size_t i = 0; i < len; i++) v[i] = rng_uniform(g);
}

static void jac_random(colloc_jac *J, rng *g)
{
  fill_random(J->coll, (size_t)J->ntst * J->coll_stride, g);
  fill_random(J->bc, (size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr), g);
  fill_random(J->dense, (size_t)J->ntst * J->dense_stride, g);
  fill_random(J->dense_par, (size_t)J->ndense * (size_t)J->nfpr, g);
}

static double norm_inf(const double *x, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++)
    if (fabs(x[i]) > m) m = fabs(x[i]);
  return m;
}

static double diff_inf(const double *x, const double *y, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++)
    if (fabs(x[i] - y[i]) > m) m = fabs(x[i] - y[i]);
  return m;
}

/* Dense reference: LU of A (n x n) in LU/ipiv, kappa_inf, log|det| and sign. */
typedef struct {
  int n;
  double *A, *LU;
  lapack_int *ipiv;
  double anorm, kappa;
  int sign;
  double logabs;
  int info;
} dense_ref;

static void dense_ref_init(dense_ref *d, const colloc_jac *J)
{
  int n = J->n;
  d->n = n;
  d->A = malloc((size_t)n * (size_t)n * sizeof(double));
  d->LU = malloc((size_t)n * (size_t)n * sizeof(double));
  d->ipiv = malloc((size_t)n * sizeof(lapack_int));
  colloc_jac_to_dense(J, d->A);
  memcpy(d->LU, d->A, (size_t)n * (size_t)n * sizeof(double));
  d->anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, 'I', n, n, d->A, n);
  d->info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, d->LU, n, d->ipiv);
  double rcond = 0.0;
  if (d->info == 0) LAPACKE_dgecon(LAPACK_COL_MAJOR, 'I', n, d->LU, n, d->anorm, &rcond);
  d->kappa = rcond > 0 ? 1.0 / rcond : (double)INFINITY;
  d->sign = 1;
  d->logabs = 0.0;
  for (int i = 0; i < n; i++) {
    double u = d->LU[(size_t)i * (size_t)n + (size_t)i];
    if (d->ipiv[i] != i + 1) d->sign = -d->sign;
    if (u < 0) d->sign = -d->sign;
    if (u == 0) d->sign = 0;
    d->logabs += log(fabs(u));
  }
}

static void dense_ref_free(dense_ref *d)
{
  free(d->A);
  free(d->LU);
  free(d->ipiv);
}

/* y = A x or A^T x, dense. */
static void dense_mv(const double *A, int n, int trans, const double *x, double *y)
{
  for (int i = 0; i < n; i++) y[i] = 0.0;
  for (int c = 0; c < n; c++)
    for (int r = 0; r < n; r++) {
      double a = A[(size_t)c * (size_t)n + (size_t)r];
      if (trans) y[c] += a * x[r];
      else y[r] += a * x[c];
    }
}

typedef struct {
  int ndim, ntst, ncol, nfpr, nint;
  int periodic; /* bc rows 0..ndim-1 are u(0) - u(1) (non-separated) */
} config;

static int cfg_nbc(const config *c) { return c->ndim + c->nfpr - c->nint - 1; }

static void check_config(const config *c, uint64_t seed)
{
  char what[160];
  char tag[96];
  snprintf(tag, sizeof tag, "[ndim %d ntst %d ncol %d nfpr %d nbc %d nint %d%s]", c->ndim, c->ntst, c->ncol, c->nfpr,
           cfg_nbc(c), c->nint, c->periodic ? " periodic" : "");
  colloc_jac *J = colloc_jac_alloc(c->ndim, c->ntst, c->ncol, c->nfpr, cfg_nbc(c), c->nint);
  abd_solver *s = abd_solver_alloc(c->ndim, c->ntst, c->ncol, c->nfpr, cfg_nbc(c), c->nint);
  snprintf(what, sizeof what, "%s alloc", tag);
  if (!test_true(what, J && s)) {
    colloc_jac_free(J);
    abd_solver_free(s);
    return;
  }
  rng g = {seed};
  jac_random(J, &g);
  if (c->periodic) {
    int nb = J->nbc, nd = J->ndim;
    for (int b = 0; b < nd && b < nb; b++)
      for (int col = 0; col < 2 * nd + J->nfpr; col++)
        J->bc[(size_t)col * (size_t)nb + (size_t)b] = col == b ? 1.0 : col == nd + b ? -1.0 : 0.0;
  }
  const int n = J->n;
  const double eps = DBL_EPSILON;
  dense_ref d;
  dense_ref_init(&d, J);

  double *b = malloc((size_t)n * sizeof(double)), *x = malloc((size_t)n * sizeof(double));
  double *xr = malloc((size_t)n * sizeof(double)), *t = malloc((size_t)n * sizeof(double));
  double *t2 = malloc((size_t)n * sizeof(double));
  fill_random(b, (size_t)n, &g);

  /* matvec and matvec_transpose against the dense copy */
  colloc_jac_matvec(J, b, t);
  dense_mv(d.A, n, 0, b, t2);
  snprintf(what, sizeof what, "%s matvec vs dense (tol n*eps*||J||*||x||)", tag);
  test_le(what, diff_inf(t, t2, n), n * eps * d.anorm * norm_inf(b, n));
  test_int("matvec_transpose: status", colloc_jac_matvec_transpose(J, b, t), 0);
  dense_mv(d.A, n, 1, b, t2);
  snprintf(what, sizeof what, "%s matvec_transpose vs dense", tag);
  test_le(what, diff_inf(t, t2, n), n * eps * LAPACKE_dlange(LAPACK_COL_MAJOR, '1', n, n, d.A, n) * norm_inf(b, n));

  snprintf(what, sizeof what, "%s factor", tag);
  test_int(what, abd_solver_factor(s, J), ABD_OK);
  printf("  n %d kappa_inf %.3g growth %.3g\n", n, d.kappa, abd_solver_growth(s));

  const double tol_x = SOLVE_C * n * eps * d.kappa;
  for (int trans = 0; trans < 2; trans++) {
    memcpy(x, b, (size_t)n * sizeof(double));
    int rc = trans ? abd_solver_solve_transpose(s, x) : abd_solver_solve(s, x);
    snprintf(what, sizeof what, "%s %s returns 0", tag, trans ? "solve_transpose" : "solve");
    test_int(what, rc, ABD_OK);
    memcpy(xr, b, (size_t)n * sizeof(double));
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, trans ? 'T' : 'N', n, 1, d.LU, n, d.ipiv, xr, n);
    snprintf(what, sizeof what, "%s %s vs dgesv rel.err (tol %g n eps kappa)", tag, trans ? "J^T x = b" : "J x = b",
             SOLVE_C);
    test_le(what, diff_inf(x, xr, n) / norm_inf(xr, n), tol_x);
    dense_mv(d.A, n, trans, x, t);
    double anorm = trans ? LAPACKE_dlange(LAPACK_COL_MAJOR, '1', n, n, d.A, n) : d.anorm;
    double growth = abd_solver_growth(s);
    snprintf(what, sizeof what, "%s %s backward error (tol n eps max(1,growth))", tag, trans ? "J^T" : "J");
    test_le(what, diff_inf(t, b, n) / (anorm * norm_inf(x, n) + norm_inf(b, n)), n * eps * fmax(1.0, growth));
  }

  int sign;
  double logabs;
  abd_solver_det(s, &sign, &logabs);
  snprintf(what, sizeof what, "%s det sign vs dgetrf", tag);
  test_int(what, sign, d.sign);
  snprintf(what, sizeof what, "%s log|det| vs dgetrf (tol 2 n^2 eps kappa)", tag);
  test_abs(what, logabs, d.logabs, 2.0 * n * (double)n * eps * d.kappa);

  free(b);
  free(x);
  free(xr);
  free(t);
  free(t2);
  dense_ref_free(&d);
  colloc_jac_free(J);
  abd_solver_free(s);
}

/* ---- stiff problem: u'' = k^2 u by Gauss collocation ------------------- */

/* Lagrange basis on the ncol+1 equidistant nodes of [0,1]: l_k(xi), l_k'(xi). */
static void lagrange(int nc, double xi, double *l, double *dl)
{
  for (int k = 0; k <= nc; k++) {
    double xk = (double)k / nc, val = 1.0, der = 0.0;
    for (int i = 0; i <= nc; i++) {
      if (i == k) continue;
      double xi_i = (double)i / nc;
      double prod = 1.0 / (xk - xi_i);
      for (int m = 0; m <= nc; m++)
        if (m != k && m != i) prod *= (xi - (double)m / nc) / (xk - (double)m / nc);
      der += prod;
      val *= (xi - xi_i) / (xk - xi_i);
    }
    l[k] = val;
    dl[k] = der;
  }
}

/* y1' = y2, y2' = sgn*kk^2 y1 on NTST intervals; bc y1(0) - p = 0, y1(1) = 1;
 * dense row: trapezoid over nodes of y1 plus p = 1/2.  sgn = +1: exponential
 * dichotomy (modes e^{+-kk t}); sgn = -1: oscillator.
 * periodic: y2' = sgn*kk^2 y1 - p + cos(2 pi t) with y(0) = y(1) (two
 * non-separated rows), the same dense row. */
static void stiff_build(colloc_jac *J, double kk, double sgn, const gsl_integration_glfixed_table *gl, double *rhs,
                        int periodic)
{
  const int nd = 2, nc = J->ncol, N = J->ntst, nr = nc * nd;
  const double h = 1.0 / N;
  double l[8], dl[8];
  const int n = J->n;
  colloc_jac_zero(J);
  for (int i = 0; i < n; i++) rhs[i] = 0.0;
  for (int m = 0; m < nc; m++) {
    double xi, w;
    gsl_integration_glfixed_point(0.0, 1.0, (size_t)m, &xi, &w, gl);
    lagrange(nc, xi, l, dl);
    for (int j = 0; j < N; j++) {
      double *C = colloc_jac_coll_block(J, j);
      for (int k = 0; k <= nc; k++) {
        /* row m*nd + i: sum_k dl_k u_k - h A sum_k l_k u_k */
        C[(size_t)(k * nd + 0) * nr + (size_t)(m * nd + 0)] = dl[k];
        C[(size_t)(k * nd + 1) * nr + (size_t)(m * nd + 0)] = -h * l[k];
        C[(size_t)(k * nd + 1) * nr + (size_t)(m * nd + 1)] = dl[k];
        C[(size_t)(k * nd + 0) * nr + (size_t)(m * nd + 1)] = -h * sgn * kk * kk * l[k];
      }
      if (periodic) {
        C[(size_t)((nc + 1) * nd) * nr + (size_t)(m * nd + 1)] = h;
        rhs[j * nr + m * nd + 1] = h * cos(2.0 * STIFF_PI * (j + xi) * h);
      }
    }
  }
  /* bc: columns u(0) (0,1), u(1) (2,3), p (4) */
  if (periodic) {
    J->bc[0 * 2 + 0] = 1.0;
    J->bc[2 * 2 + 0] = -1.0;
    J->bc[1 * 2 + 1] = 1.0;
    J->bc[3 * 2 + 1] = -1.0;
  } else {
    J->bc[0 * 2 + 0] = 1.0;
    J->bc[4 * 2 + 0] = -1.0;
    J->bc[2 * 2 + 1] = 1.0;
    rhs[N * nr + 1] = 1.0;
  }
  for (int j = 0; j < N; j++) {
    double *D = colloc_jac_dense_block(J, j);
    for (int k = 0; k <= nc; k++) D[k * nd + 0] = h / nc * ((k == 0 || k == nc) ? 0.5 : 1.0);
  }
  J->dense_par[0] = 1.0;
  rhs[N * nr + 2] = 0.5;
}

/* Long-double Gaussian elimination with partial pivoting (reference). */
static int ld_solve(int n, const double *A, const double *b, double *x, int *sign)
{
  long double *M = malloc((size_t)n * (size_t)n * sizeof(long double));
  long double *y = malloc((size_t)n * sizeof(long double));
  for (size_t i = 0; i < (size_t)n * (size_t)n; i++) M[i] = A[i];
  for (int i = 0; i < n; i++) y[i] = b[i];
  int sg = 1, rc = 0;
#define ML(r, c) M[(size_t)(c) * (size_t)n + (size_t)(r)]
  for (int c = 0; c < n; c++) {
    int p = c;
    for (int r = c + 1; r < n; r++)
      if (fabsl(ML(r, c)) > fabsl(ML(p, c))) p = r;
    if (ML(p, c) == 0.0L) {
      rc = 1;
      sg = 0;
      break;
    }
    if (p != c) {
      sg = -sg;
      for (int k = 0; k < n; k++) {
        long double t = ML(c, k);
        ML(c, k) = ML(p, k);
        ML(p, k) = t;
      }
      long double t = y[c];
      y[c] = y[p];
      y[p] = t;
    }
    if (ML(c, c) < 0) sg = -sg;
    for (int r = c + 1; r < n; r++) {
      long double f = ML(r, c) / ML(c, c);
      if (f == 0.0L) continue;
      for (int k = c + 1; k < n; k++) ML(r, k) -= f * ML(c, k);
      y[r] -= f * y[c];
    }
  }
  if (rc == 0)
    for (int c = n - 1; c >= 0; c--) {
      long double v = y[c];
      for (int k = c + 1; k < n; k++) v -= ML(c, k) * y[k];
      y[c] = v / ML(c, c);
      x[c] = (double)y[c];
    }
#undef ML
  *sign = sg;
  free(M);
  free(y);
  return rc;
}

static void check_stiff(void)
{
  const int nc = 4, N = 50;
  gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc((size_t)nc);
  colloc_jac *J = colloc_jac_alloc(2, N, nc, 1, 2, 0);
  abd_solver *s = abd_solver_alloc(2, N, nc, 1, 2, 0);
  const int n = J->n;
  double *rhs = malloc((size_t)n * sizeof(double)), *x = malloc((size_t)n * sizeof(double));
  double *xr = malloc((size_t)n * sizeof(double)), *A = malloc((size_t)n * (size_t)n * sizeof(double));
  lapack_int *ipiv = malloc((size_t)n * sizeof(lapack_int));
  char what[200];

  stiff_build(J, 60.0, 1.0, gl, rhs, 0);
  test_int("stiff k=60 NTST=50 NCOL=4: factor", abd_solver_factor(s, J), ABD_OK);
  memcpy(x, rhs, (size_t)n * sizeof(double));
  abd_solver_solve(s, x);
  colloc_jac_to_dense(J, A);
  int ldsign;
  test_int("stiff: long-double reference elimination succeeds", ld_solve(n, A, rhs, xr, &ldsign), 0);
  snprintf(what, sizeof what, "stiff k=60: rel.err vs long-double discrete solution (growth %.3g, max|u| %.3g)",
           abd_solver_growth(s), norm_inf(xr, n));
  test_le(what, diff_inf(x, xr, n) / norm_inf(xr, n), STIFF_TOL);
  int sign;
  double logabs;
  abd_solver_det(s, &sign, &logabs);
  test_int("stiff k=60: det sign vs long-double elimination", sign, ldsign);

  /* determinant sign along k in [40, 60]: J(k) is never singular */
  int sign0 = 0, constant = 1, agree = 1;
  for (int it = 0; it <= 20; it++) {
    double kk = 40.0 + it;
    stiff_build(J, kk, 1.0, gl, rhs, 0);
    if (abd_solver_factor(s, J) != ABD_OK) constant = 0;
    abd_solver_det(s, &sign, &logabs);
    colloc_jac_to_dense(J, A);
    LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, A, n, ipiv);
    int ds = 1;
    for (int i = 0; i < n; i++) {
      if (ipiv[i] != i + 1) ds = -ds;
      if (A[(size_t)i * (size_t)n + (size_t)i] < 0) ds = -ds;
    }
    if (it == 0) sign0 = sign;
    if (sign != sign0 || sign == 0) constant = 0;
    if (sign != ds) agree = 0;
    printf("  k %.0f sign %d log|det| %.12g (dgetrf sign %d)\n", kk, sign, logabs, ds);
  }
  test_true("stiff: det sign constant for k in [40,60] (no singularity)", constant);
  test_true("stiff: det sign equals dgetrf's for k in [40,60]", agree);

  /* periodic (non-separated) conditions with the same dichotomy: no Floquet
   * multiplier on the unit circle, so J is regular for every k */
  stiff_build(J, 60.0, 1.0, gl, rhs, 1);
  test_int("stiff periodic k=60: factor", abd_solver_factor(s, J), ABD_OK);
  memcpy(x, rhs, (size_t)n * sizeof(double));
  abd_solver_solve(s, x);
  colloc_jac_to_dense(J, A);
  test_int("stiff periodic: long-double reference succeeds", ld_solve(n, A, rhs, xr, &ldsign), 0);
  /* u only (the parameter, last unknown, is O(1) while u is O(1e-3)) */
  snprintf(what, sizeof what, "stiff periodic k=60: rel.err of u vs long-double discrete solution (growth %.3g, max|u| %.3g)",
           abd_solver_growth(s), norm_inf(xr, n - 1));
  test_le(what, diff_inf(x, xr, n - 1) / norm_inf(xr, n - 1), STIFF_TOL);
  abd_solver_det(s, &sign, &logabs);
  test_int("stiff periodic k=60: det sign vs long-double elimination", sign, ldsign);
  constant = 1;
  for (int it = 0; it <= 20; it++) {
    stiff_build(J, 40.0 + it, 1.0, gl, rhs, 1);
    int sg;
    if (abd_solver_factor(s, J) != ABD_OK) constant = 0;
    abd_solver_det(s, &sg, &logabs);
    if (sg != sign) constant = 0;
  }
  test_true("stiff periodic: det sign constant for k in [40,60]", constant);

  /* oscillator u'' = -w^2 u with u(0) = p, u(1) = 1, int u + p = 1/2: the
   * homogeneous problem has the solution A sin(w(1-t)) when
   * sin w + (1 - cos w)/w = 0, once in [3, 4.5] (w = 3.69...; the next root
   * is near 2 pi), so the sign must flip exactly once there. */
  int flips = 0, prev = 0;
  agree = 1;
  for (int it = 0; it <= 20; it++) {
    double w = 3.0 + 0.075 * it;
    stiff_build(J, w, -1.0, gl, rhs, 0);
    abd_solver_factor(s, J);
    abd_solver_det(s, &sign, &logabs);
    colloc_jac_to_dense(J, A);
    LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, A, n, ipiv);
    int ds = 1;
    for (int i = 0; i < n; i++) {
      if (ipiv[i] != i + 1) ds = -ds;
      if (A[(size_t)i * (size_t)n + (size_t)i] < 0) ds = -ds;
    }
    if (sign != ds) agree = 0;
    if (it > 0 && sign != prev) flips++;
    prev = sign;
  }
  test_int("oscillator: det sign flips exactly once for w in [3, 4.5]", flips, 1);
  test_true("oscillator: det sign equals dgetrf's along w in [3, 4.5]", agree);

  free(rhs);
  free(x);
  free(xr);
  free(A);
  free(ipiv);
  colloc_jac_free(J);
  abd_solver_free(s);
  gsl_integration_glfixed_table_free(gl);
}

/* ---- exact singularity and error paths --------------------------------- */

static void check_singular(void)
{
  const int nd = 3, N = 4, nc = 3, nf = 2, nint = 1, nb = nd + nf - nint - 1;
  colloc_jac *J = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
  abd_solver *s = abd_solver_alloc(nd, N, nc, nf, nb, nint);
  rng g = {7};
  double *x = calloc((size_t)J->n, sizeof(double));
  int sign;
  double logabs;

  /* a zero parameter column: eliminated in the banded stage */
  jac_random(J, &g);
  for (int j = 0; j < N; j++)
    for (int r = 0; r < nc * nd; r++) colloc_jac_coll_block(J, j)[(size_t)((nc + 1) * nd) * (nc * nd) + r] = 0.0;
  for (int b = 0; b < nb; b++) J->bc[(size_t)(2 * nd) * nb + b] = 0.0;
  for (int d = 0; d <= nint; d++) J->dense_par[d] = 0.0;
  test_int("singular (zero parameter column): factor returns ABD_SINGULAR > 0", abd_solver_factor(s, J), ABD_SINGULAR);
  abd_solver_det(s, &sign, &logabs);
  test_int("singular: det sign 0", sign, 0);
  test_true("singular: log|det| = -inf", isinf(logabs) && logabs < 0);
  test_int("singular: solve refused with ABD_SINGULAR", abd_solver_solve(s, x), ABD_SINGULAR);
  test_int("singular: solve_transpose refused", abd_solver_solve_transpose(s, x), ABD_SINGULAR);
  double sv[1];
  test_int("singular: smallest_sv refused", abd_solver_smallest_sv(s, J, 1, sv, x, 10, 1e-10), ABD_SINGULAR);

  /* a zero interior-node column: caught by the local factorisation */
  jac_random(J, &g);
  for (int r = 0; r < nc * nd; r++) colloc_jac_coll_block(J, 2)[(size_t)(nd + 1) * (nc * nd) + r] = 0.0;
  for (int d = 0; d <= nint; d++) colloc_jac_dense_block(J, 2)[(size_t)(nd + 1) * (nint + 1) + d] = 0.0;
  test_int("singular (zero interior column): factor returns ABD_SINGULAR", abd_solver_factor(s, J), ABD_SINGULAR);

  /* a zero collocation row */
  jac_random(J, &g);
  double *C = colloc_jac_coll_block(J, 1);
  for (int c = 0; c < (nc + 1) * nd + nf; c++) C[(size_t)c * (nc * nd) + 4] = 0.0;
  test_int("singular (zero collocation row): factor returns ABD_SINGULAR", abd_solver_factor(s, J), ABD_SINGULAR);

  /* a healthy matrix after a singular one factors again */
  jac_random(J, &g);
  test_int("factor after a singular matrix: 0", abd_solver_factor(s, J), ABD_OK);

  /* error paths */
  J->coll[5] = NAN;
  test_int("NaN entry: factor returns ABD_ERR_NONFINITE", abd_solver_factor(s, J), ABD_ERR_NONFINITE);
  test_int("after a failed factor: solve returns ABD_ERR_NOT_FACTORED", abd_solver_solve(s, x), ABD_ERR_NOT_FACTORED);
  J->coll[5] = INFINITY;
  test_int("Inf entry: factor returns ABD_ERR_NONFINITE", abd_solver_factor(s, J), ABD_ERR_NONFINITE);
  abd_solver_det(s, &sign, &logabs);
  test_int("det after a failed factor: sign 0", sign, 0);
  test_true("growth after a failed factor: NaN", isnan(abd_solver_growth(s)));

  colloc_jac *J2 = colloc_jac_alloc(nd, N + 1, nc, nf, nb, nint);
  test_int("factor with J of other sizes: ABD_ERR_SIZE", abd_solver_factor(s, J2), ABD_ERR_SIZE);
  test_int("factor with J = NULL: ABD_ERR_SIZE", abd_solver_factor(s, NULL), ABD_ERR_SIZE);
  abd_solver *s2 = abd_solver_alloc(nd, N + 1, nc, nf, nb, nint);
  test_int("solve before any factor: ABD_ERR_NOT_FACTORED", abd_solver_solve(s2, x), ABD_ERR_NOT_FACTORED);
  test_int("solve_transpose before any factor: ABD_ERR_NOT_FACTORED", abd_solver_solve_transpose(s2, x),
           ABD_ERR_NOT_FACTORED);
  test_int("smallest_sv before any factor: ABD_ERR_NOT_FACTORED", abd_solver_smallest_sv(s2, J2, 1, sv, x, 5, 1e-8),
           ABD_ERR_NOT_FACTORED);
  jac_random(J2, &g);
  abd_solver_factor(s2, J2);
  test_int("smallest_sv with k = 0: ABD_ERR_SIZE", abd_solver_smallest_sv(s2, J2, 0, sv, x, 5, 1e-8), ABD_ERR_SIZE);
  test_int("smallest_sv with tol = 0: ABD_ERR_SIZE", abd_solver_smallest_sv(s2, J2, 1, sv, x, 5, 0.0), ABD_ERR_SIZE);
  test_int("smallest_sv with J of other sizes: ABD_ERR_SIZE", abd_solver_smallest_sv(s2, J, 1, sv, x, 5, 1e-8),
           ABD_ERR_SIZE);
  double *x2 = malloc((size_t)J2->n * sizeof(double));
  test_int("smallest_sv, 1 iteration, tol 1e-300: ABD_NOT_CONVERGED",
           abd_solver_smallest_sv(s2, J2, 1, sv, x2, 1, 1e-300), ABD_NOT_CONVERGED);
  free(x2);

  test_true("abd_solver_alloc(ndim = 0) is NULL", abd_solver_alloc(0, 4, 3, 1, 0, 0) == NULL);
  test_true("abd_solver_alloc with nbc + nint + 1 != ndim + nfpr is NULL", abd_solver_alloc(3, 4, 3, 1, 2, 0) == NULL);
  test_true("colloc_jac_alloc with nbc + nint + 1 != ndim + nfpr is NULL", colloc_jac_alloc(3, 4, 3, 1, 2, 0) == NULL);
  test_true("colloc_jac_alloc(ntst = 0) is NULL", colloc_jac_alloc(3, 0, 3, 1, 3, 0) == NULL);
  abd_solver_free(NULL);
  colloc_jac_free(NULL);

  free(x);
  abd_solver_free(s2);
  colloc_jac_free(J2);
  colloc_jac_free(J);
  abd_solver_free(s);
}

/* ---- smallest singular values ------------------------------------------ */

/* Parameter columns 1 and 2 := column 0 times a constant plus d1, d2 times a
 * random column: J gets two singular values of order d1 and d2. */
static void plant_small_sv(colloc_jac *J, double d1, double d2, rng *g)
{
  const int nr = J->ncol * J->ndim, c0 = (J->ncol + 1) * J->ndim, nb = J->nbc, nq = J->ndense, nd = J->ndim;
  const double alpha[3] = {1.0, 0.7, -1.3}, delta[3] = {0.0, d1, d2};
  for (int p = 1; p <= 2; p++) {
    for (int j = 0; j < J->ntst; j++) {
      double *C = colloc_jac_coll_block(J, j);
      for (int r = 0; r < nr; r++) C[(size_t)(c0 + p) * nr + r] = alpha[p] * C[(size_t)c0 * nr + r] + delta[p] * rng_uniform(g);
    }
    for (int b = 0; b < nb; b++)
      J->bc[(size_t)(2 * nd + p) * nb + b] = alpha[p] * J->bc[(size_t)(2 * nd) * nb + b] + delta[p] * rng_uniform(g);
    for (int d = 0; d < nq; d++)
      J->dense_par[(size_t)p * nq + d] = alpha[p] * J->dense_par[d] + delta[p] * rng_uniform(g);
  }
}

static void check_sv_case(const char *tag, double d1, double d2, int k, int check_vectors)
{
  const int nd = 3, N = 6, nc = 3, nf = 3, nint = 1, nb = nd + nf - nint - 1;
  colloc_jac *J = colloc_jac_alloc(nd, N, nc, nf, nb, nint);
  abd_solver *s = abd_solver_alloc(nd, N, nc, nf, nb, nint);
  rng g = {12345};
  jac_random(J, &g);
  plant_small_sv(J, d1, d2, &g);
  const int n = J->n;
  const double tol = 1e-12;
  char what[200];

  double *A = malloc((size_t)n * (size_t)n * sizeof(double)), *S = malloc((size_t)n * sizeof(double));
  double *VT = malloc((size_t)n * (size_t)n * sizeof(double)), *superb = malloc((size_t)n * sizeof(double));
  colloc_jac_to_dense(J, A);
  double normF = LAPACKE_dlange(LAPACK_COL_MAJOR, 'F', n, n, A, n);
  LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'A', n, n, A, n, S, NULL, 1, VT, n, superb);

  double sv[4], *vecs = malloc((size_t)n * 4 * sizeof(double));
  test_int("sv: factor", abd_solver_factor(s, J), ABD_OK);
  int rc = abd_solver_smallest_sv(s, J, k, sv, vecs, 50, tol);
  snprintf(what, sizeof what, "%s: smallest_sv converges (tol %g)", tag, tol);
  test_int(what, rc, ABD_OK);
  /* |sigma - sigma_ref| <= residual bound tol*||J||_F plus dgesvd's own
   * absolute error n*eps*||J||_2 (<= ||J||_F) */
  double bound = tol * normF + n * DBL_EPSILON * S[0];
  for (int i = 0; i < k; i++) {
    double ref = S[n - 1 - i];
    snprintf(what, sizeof what, "%s: sigma_%d vs dgesvd (tol tol*||J||_F + n eps ||J||_2)", tag, i + 1);
    test_abs(what, sv[i], ref, bound);
    if (!check_vectors) continue;
    /* sin(angle) <= 2 * bound / gap (Wedin) */
    double gap = INFINITY;
    for (int l = 0; l < n; l++)
      if (l != n - 1 - i && fabs(S[l] - ref) < gap) gap = fabs(S[l] - ref);
    double dot = 0.0;
    for (int r = 0; r < n; r++) dot += vecs[(size_t)i * n + r] * VT[(size_t)r * n + (size_t)(n - 1 - i)];
    double sinang = sqrt(fmax(0.0, 1.0 - dot * dot));
    snprintf(what, sizeof what, "%s: right singular vector %d, sin(angle) vs dgesvd (tol 2 bound/gap)", tag, i + 1);
    test_le(what, sinang, 2.0 * bound / gap);
  }
  printf("  sigma_ref:");
  for (int i = 0; i < k + 1; i++) printf(" %.6g", S[n - 1 - i]);
  printf("  ||J||_F %.4g\n", normF);

  free(A);
  free(S);
  free(VT);
  free(superb);
  free(vecs);
  colloc_jac_free(J);
  abd_solver_free(s);
}

/* abd_solver_factor_prepared: the solve of a prepared right-hand side skips
 * its first stage and must give the plain solve's result bit for bit; a
 * different right-hand side, or one after another solve has used the
 * preparation up, goes the plain way (also bit for bit); bad k is refused. */
static void check_prepared(void)
{
  rng g = {UINT64_C(4242)};
  const int ndim = 3, ntst = 7, ncol = 3, nfpr = 2, nint = 1, nbc = ndim + nfpr - nint - 1;
  colloc_jac *J = colloc_jac_alloc(ndim, ntst, ncol, nfpr, nbc, nint);
  abd_solver *a = abd_solver_alloc(ndim, ntst, ncol, nfpr, nbc, nint);
  abd_solver *p = abd_solver_alloc(ndim, ntst, ncol, nfpr, nbc, nint);
  if (!J || !a || !p) {
    test_true("prepared: allocation", 0);
    return;
  }
  const int n = abd_solver_size(a);
  double *B = malloc(2 * (size_t)n * sizeof *B), *X = malloc(2 * (size_t)n * sizeof *X);
  double *Y = malloc(2 * (size_t)n * sizeof *Y);
  int ok = 1;
  for (int nt = 1; nt <= 2; nt++) {
    abd_solver_set_threads(a, nt);
    abd_solver_set_threads(p, nt);
    for (int k = 1; k <= 2; k++) {
      jac_random(J, &g);
      fill_random(B, 2 * (size_t)n, &g);
      ok &= abd_solver_factor(a, J) == ABD_OK;
      memcpy(Y, B, 2 * (size_t)n * sizeof *Y);
      ok &= abd_solver_solve_many(a, Y, k) == ABD_OK;
      ok &= abd_solver_factor_prepared(p, J, B, k) == ABD_OK;
      memcpy(X, B, 2 * (size_t)n * sizeof *X);
      ok &= abd_solver_solve_many(p, X, k) == ABD_OK; /* prepared */
      ok &= memcmp(X, Y, (size_t)k * (size_t)n * sizeof *X) == 0;
      memcpy(X, B, 2 * (size_t)n * sizeof *X);
      ok &= abd_solver_solve_many(p, X, k) == ABD_OK; /* used up: the plain way */
      ok &= memcmp(X, Y, (size_t)k * (size_t)n * sizeof *X) == 0;
      /* prepared for B, asked for another vector first, then for B */
      ok &= abd_solver_factor_prepared(p, J, B, k) == ABD_OK;
      memcpy(X, B + n, (size_t)n * sizeof *X);
      ok &= abd_solver_solve(p, X) == ABD_OK;
      memcpy(Y, B + n, (size_t)n * sizeof *Y);
      ok &= abd_solver_solve(a, Y) == ABD_OK;
      ok &= memcmp(X, Y, (size_t)n * sizeof *X) == 0;
      memcpy(X, B, 2 * (size_t)n * sizeof *X);
      memcpy(Y, B, 2 * (size_t)n * sizeof *Y);
      ok &= abd_solver_solve_many(p, X, k) == ABD_OK && abd_solver_solve_many(a, Y, k) == ABD_OK;
      ok &= memcmp(X, Y, (size_t)k * (size_t)n * sizeof *X) == 0;
    }
  }
  test_true("factor_prepared: the prepared solve, a solve after it and a solve after another vector's equal the "
            "plain solve bit for bit (k = 1, 2; 1 and 2 threads)", ok);
  test_int("factor_prepared with k = 3 > ABD_SOLVE_BLOCK: ABD_ERR_SIZE", abd_solver_factor_prepared(p, J, B, 3),
           ABD_ERR_SIZE);
  test_int("factor_prepared with B NULL and k = 1: ABD_ERR_SIZE", abd_solver_factor_prepared(p, J, NULL, 1),
           ABD_ERR_SIZE);
  test_int("solve after a refused factor_prepared: ABD_ERR_NOT_FACTORED", abd_solver_solve(p, X),
           ABD_ERR_NOT_FACTORED);
  free(B);
  free(X);
  free(Y);
  abd_solver_free(a);
  abd_solver_free(p);
  colloc_jac_free(J);
}

int main(void)
{
  const config cfgs[] = {
      {2, 5, 3, 1, 0, 0},  {3, 4, 4, 2, 1, 0},  {4, 6, 2, 3, 2, 0},  {5, 3, 7, 1, 0, 0}, {1, 10, 2, 1, 0, 0},
      {3, 7, 3, 2, 0, 1},  {4, 5, 4, 1, 1, 1},  {2, 1, 5, 2, 2, 0},  {3, 6, 1, 2, 1, 0}, {21, 10, 4, 6, 2, 0},
      {21, 6, 4, 2, 1, 1}, {6, 40, 3, 4, 2, 1},
  };
  /* CABLE_TEST_QUICK (valgrind runs): skip the configurations whose dense
   * references (n > 500) dominate the run time under instrumentation. */
  const int quick = getenv("CABLE_TEST_QUICK") != NULL;
  for (size_t i = 0; i < sizeof cfgs / sizeof cfgs[0]; i++) {
    const config *c = &cfgs[i];
    if (quick && c->ndim * (c->ntst * c->ncol + 1) > 500) continue;
    check_config(c, 1000 + i);
  }
  check_stiff();
  check_singular();
  check_prepared();
  check_sv_case("sv planted 1e-9, 1e-7 (k=2)", 1e-9, 1e-7, 2, 1);
  check_sv_case("sv planted 1e-9, 1e-7 (k=1)", 1e-9, 1e-7, 1, 1);
  check_sv_case("sv double zero 3e-9, 3e-9 (k=2)", 3e-9, 3e-9, 2, 0);
  return test_summary();
}
