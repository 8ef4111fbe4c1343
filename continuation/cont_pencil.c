/* SPDX-License-Identifier: GPL-3.0-or-later */
/* How many branch points lie inside one step: the pencil test.
 *
 * The determinant's sign only gives the parity of the number of branch
 * points between two points; two inside one step cancel.  Along the step the
 * extended Newton matrix is close to the linear interpolation
 *     J(t) = (1 - t) J_a + t J_b,   t in [0, 1],
 * of its values at the step's ends, and J(t) is singular exactly when
 *     J_b^{-1} J_a v = nu v,   nu = -t / (1 - t) < 0.
 * So the real negative eigenvalues nu of J_b^{-1} J_a predict the branch
 * points inside the step, at t = nu / (nu - 1).  Their number has the parity
 * of the determinant test (det J_a / det J_b is the product of all
 * eigenvalues), and for a matrix affine in the arclength (a trivial branch
 * in its parameter) the prediction is exact up to round-off.
 *
 * Only the eigenvalues with nu < 0 matter; for A = J_b^{-1} J_a - I they are
 * those with alpha = nu - 1 < -1: branch points closer than one step to the
 * step's end.  A = J_b^{-1} (J_a - J_b) is a difference quotient of a
 * zeroth-order (multiplication) operator preconditioned by the collocation
 * operator, so its spectrum accumulates at 0 and the few outlying
 * eigenvalues are found by a short Arnoldi iteration: CONT_PENCIL_KRYLOV
 * steps, each one solve with J_b's factorisation (already computed for the
 * tangent) and one product with J_a.  No allocation: the workspace belongs
 * to cable_cont. */
#include <cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

/* Arnoldi steps.  The elastica tests of test_engine_bvp.c (fixed DS = 35,
 * 40, 45, 99 on the trivial branch) pass with 6 or more and fail with 4 (a
 * pair missed again); 12 leave a factor 2 for curved branches. */
#define CONT_PENCIL_KRYLOV 12
/* A new Krylov vector shorter than this (relative to the image's norm before
 * orthogonalisation) means the space is invariant: stop early. */
#define CONT_PENCIL_BREAKDOWN 1.0e-12
/* A complex pair of Ritz values with Re nu < 0 and |Im nu| below this
 * fraction of |nu| is a double real eigenvalue perturbed by round-off (two
 * singular values vanishing together, e.g. by symmetry): counted as two
 * coincident crossings. */
#define CONT_PENCIL_IMAG_REL 1.0e-2

int cont_pencil_alloc(cable_cont *cc)
{
  int m = CONT_PENCIL_KRYLOV < cc->n ? CONT_PENCIL_KRYLOV : cc->n;
  cc->pen_m = m;
  cc->pen_V = calloc((size_t)cc->n * (size_t)(m + 1), sizeof(double));
  cc->pen_H = calloc((size_t)(m + 1) * (size_t)m, sizeof(double));
  cc->pen_work = calloc(4 * (size_t)m, sizeof(double));
  cc->Ja = colloc_jac_alloc(cc->ndim, cc->ntst, cc->ncol, cc->nfpr, cc->pb->nbc, cc->pb->nint);
  return cc->pen_V && cc->pen_H && cc->pen_work && cc->Ja ? CABLE_SUCCESS : CABLE_ERR_ALLOC;
}

void cont_pencil_free(cable_cont *cc)
{
  free(cc->pen_V);
  free(cc->pen_H);
  free(cc->pen_work);
  colloc_jac_free(cc->Ja);
}

static void insert_sorted(double *t, int *nt, int tmax, double v)
{
  if (*nt >= tmax) return;
  int i = *nt;
  while (i > 0 && t[i - 1] > v) {
    t[i] = t[i - 1];
    i--;
  }
  t[i] = v;
  (*nt)++;
}

int cont_pencil_crossings(cable_cont *cc, const abd_solver *fb, double *t, int tmax, int *ndouble)
{
  *ndouble = 0;
  const int n = cc->n, m = cc->pen_m, ldh = m + 1;
  double *V = cc->pen_V, *H = cc->pen_H;
  /* J_a: the Newton matrix at the step's start with this step's closing row
     (s->xdot0 is the start's tangent); only its sign pattern matters to the
     count, and [F_x; theta v^T] has the same determinant sign for every v
     with <v, xdot> > 0 */
  int rc = colloc_system_jacobian(cc->sys, cc->x, cc->Ja);
  if (rc != 0) return rc > 0 ? CABLE_ERR_RECOVERABLE : CABLE_ERR_CALLBACK;
  memset(H, 0, (size_t)ldh * (size_t)m * sizeof *H);
  uint64_t st = UINT64_C(0x2545F4914F6CDD1D); /* a fixed start: reproducible runs */
  for (int i = 0; i < n; i++) {
    st = st * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
    V[i] = (double)(st >> 11) * 0x1.0p-53 - 0.5;
  }
  cblas_dscal(n, 1.0 / cblas_dnrm2(n, V, 1), V, 1);
  int k = m;
  for (int j = 0; j < m; j++) {
    double *vj = V + (size_t)j * (size_t)n, *w = V + (size_t)(j + 1) * (size_t)n;
    colloc_jac_matvec_team(cc->Ja, abd_solver_team(fb), vj, w);
    if (abd_solver_solve(fb, w) != ABD_OK) return CABLE_ERR_LINSOLVE;
    cblas_daxpy(n, -1.0, vj, 1, w, 1);
    double w0 = cblas_dnrm2(n, w, 1);
    /* classical Gram-Schmidt, twice (enough for orthogonality to round-off) */
    for (int pass = 0; pass < 2; pass++)
      for (int i = 0; i <= j; i++) {
        const double *vi = V + (size_t)i * (size_t)n;
        double h = cblas_ddot(n, vi, 1, w, 1);
        H[i + (size_t)ldh * j] += h;
        cblas_daxpy(n, -h, vi, 1, w, 1);
      }
    double h = cblas_dnrm2(n, w, 1);
    H[j + 1 + (size_t)ldh * j] = h;
    if (!(h > CONT_PENCIL_BREAKDOWN * w0)) {
      k = j + 1;
      break;
    }
    cblas_dscal(n, 1.0 / h, w, 1);
  }
  double *wr = cc->pen_work, *wi = wr + m, *work = wi + m;
  if (LAPACKE_dhseqr_work(LAPACK_COL_MAJOR, 'E', 'N', k, 1, k, H, ldh, wr, wi, NULL, 1, work, 2 * m) != 0)
    return CABLE_ERR_LINSOLVE;
  int nt = 0;
  for (int i = 0; i < k; i++) {
    double re = wr[i] + 1.0, im = wi[i]; /* nu = alpha + 1 */
    if (!(re < 0)) continue;
    if (im == 0.0) {
      insert_sorted(t, &nt, tmax, re / (re - 1.0));
    } else if (im > 0 && fabs(im) <= CONT_PENCIL_IMAG_REL * hypot(re, im)) {
      /* a conjugate pair (the partner has im < 0): two crossings at one t */
      insert_sorted(t, &nt, tmax, re / (re - 1.0));
      insert_sorted(t, &nt, tmax, re / (re - 1.0));
      (*ndouble)++;
    }
  }
  return nt;
}
