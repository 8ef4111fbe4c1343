/* Collocation basis and discretised system: quadrature exactness, partition of
 * unity, and the block Newton matrix against central differences of the
 * residual (analytic and finite-difference problem Jacobians), also with an
 * integral condition (bratu_int, NINT = 1). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable_constants.h"
#include "cable_status.h"
#include "colloc_basis.h"
#include "colloc_jac.h"
#include "colloc_system.h"
#include "harness.h"
#include "test_problems.h"

static void test_basis(void)
{
  for (int nc = COLLOC_NCOL_MIN; nc <= COLLOC_NCOL_MAX; nc++) {
    colloc_basis b;
    test_int("basis init", colloc_basis_init(&b, nc), 0);
    double maxpu = 0, maxd = 0, sw = 0, swn = 0, gauss = 0, nodes = 0;
    for (int m = 0; m < nc; m++) {
      double s = 0, ds = 0;
      for (int k = 0; k <= nc; k++) { s += b.l[m][k]; ds += b.dl[m][k]; }
      maxpu = fmax(maxpu, fabs(s - 1));
      maxd = fmax(maxd, fabs(ds));
      sw += b.w[m];
      gauss += b.w[m] * pow(b.c[m], 2 * nc - 1); /* Gauss: exact to degree 2 nc - 1 */
    }
    for (int k = 0; k <= nc; k++) {
      swn += b.wn[k];
      nodes += b.wn[k] * pow((double)k / nc, nc); /* interpolant of x^nc is exact */
    }
    char what[96];
    /* sums of O(1) terms of alternating sign: a few hundred ulps */
    snprintf(what, sizeof what, "ncol %d partition of unity", nc);
    test_le(what, maxpu, 1e-13);
    snprintf(what, sizeof what, "ncol %d derivatives sum to zero", nc);
    test_le(what, maxd, 1e-11);
    snprintf(what, sizeof what, "ncol %d Gauss weights", nc);
    test_abs(what, sw, 1.0, 1e-14);
    snprintf(what, sizeof what, "ncol %d Gauss exact for x^(2ncol-1)", nc);
    test_abs(what, gauss, 1.0 / (2 * nc), 1e-14);
    snprintf(what, sizeof what, "ncol %d node weights", nc);
    test_abs(what, swn, 1.0, 1e-13);
    snprintf(what, sizeof what, "ncol %d node quadrature exact for x^ncol", nc);
    test_abs(what, nodes, 1.0 / (nc + 1), 1e-13);
  }
  test_int("ncol 8 rejected", colloc_basis_init(&(colloc_basis){0}, 8), CABLE_ERR_INPUT);
}

/* max |J - FD(F)| / max|J| with central differences of step 1e-6:
 * truncation ~ 1e-12 |F'''|, round-off ~ 1e-16 |F| / 1e-6 = 1e-10 |F|. */
static double jacobian_error_rows(colloc_system *s, const double *x, int row0, int nrows)
{
  int n = s->n;
  colloc_jac *J = colloc_jac_alloc(s->ndim, s->ntst, s->ncol, s->nfpr, s->nbc, s->nint);
  double *A = calloc((size_t)n * (size_t)n, sizeof *A);
  double *xp = malloc((size_t)n * sizeof *xp), *Fp = malloc((size_t)n * sizeof *Fp);
  double *Fm = malloc((size_t)n * sizeof *Fm);
  colloc_system_jacobian(s, x, J);
  colloc_jac_to_dense(J, A);
  double err = 0, scale = 0;
  for (int c = 0; c < n; c++) {
    memcpy(xp, x, (size_t)n * sizeof *x);
    double h = 1e-6 * (1 + fabs(x[c]));
    xp[c] = x[c] + h;
    colloc_system_residual(s, xp, Fp);
    xp[c] = x[c] - h;
    colloc_system_residual(s, xp, Fm);
    for (int r = row0; r < row0 + nrows; r++) {
      double fd = (Fp[r] - Fm[r]) / (2 * h);
      err = fmax(err, fabs(fd - A[r + (size_t)n * c]));
      scale = fmax(scale, fabs(A[r + (size_t)n * c]));
    }
  }
  colloc_jac_free(J);
  free(A); free(xp); free(Fp); free(Fm);
  return err / scale;
}

static double jacobian_error(colloc_system *s, const double *x) { return jacobian_error_rows(s, x, 0, s->n); }

static void test_system(const cable_problem *pb, const char *name, int jac)
{
  cable_constants c;
  cable_constants_init(&c);
  c.jac = jac;
  int icp[2] = {0, 1}, st, nfpr = pb->nbc + pb->nint - pb->ndim + 1;
  colloc_system *s = colloc_system_alloc(pb, &c, 5, 3, icp, nfpr, &st);
  test_true("system alloc", s != NULL);
  if (!s) return;
  /* a smooth non-uniform mesh, random state, arclength closing */
  for (int j = 0; j <= s->ntst; j++) s->mesh[j] = pow((double)j / s->ntst, 1.3);
  srand(7);
  double *x = malloc((size_t)s->n * sizeof *x);
  for (int i = 0; i < s->n; i++) {
    x[i] = 0.5 * ((double)rand() / RAND_MAX - 0.5);
    s->x0[i] = x[i] + 0.01;
    s->xdot0[i] = (double)rand() / RAND_MAX;
  }
  x[s->n - nfpr] = 2.0; /* the principal parameter */
  s->par[1] = 0.05; /* eps of the layer problem (unused by the others) */
  s->closing = COLLOC_CLOSE_ARCLENGTH;
  s->ds = 0.1;
  char what[96];
  snprintf(what, sizeof what, "%s JAC=%d: Newton matrix vs differences of the residual", name, jac);
  /* analytic: FD error bound above; JAC=0 adds the inner FD error (step 6e-6: ~1e-10) */
  test_le(what, jacobian_error(s, x), jac ? 1e-8 : 1e-7);
  if (s->nint > 0) {
    /* the integral rows alone (their entries are O(h), smaller than the
       collocation rows', so the whole-matrix check could hide an error) */
    snprintf(what, sizeof what, "%s JAC=%d: integral-condition rows vs differences", name, jac);
    test_le(what, jacobian_error_rows(s, x, s->ntst * s->ncol * s->ndim + s->nbc, s->nint), jac ? 1e-8 : 1e-7);
  }
  free(x);
  colloc_system_free(s);
}

int main(void)
{
  test_basis();
  test_system(cable_testproblem_bratu(), "bratu", 1);
  test_system(cable_testproblem_bratu(), "bratu", 0);
  test_system(cable_testproblem_elastica(), "elastica", 1);
  test_system(cable_testproblem_layer(), "layer", 0);
  /* NINT = 1: the integral row and its derivatives (ICND's dint, JAC=1, and
     the engine's differences of ICND, JAC=0) */
  test_system(cable_testproblem_bratu_int(), "bratu_int", 1);
  test_system(cable_testproblem_bratu_int(), "bratu_int", 0);
  return test_summary();
}
