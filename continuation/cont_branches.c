/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The branch directions at a double branch point: the algebraic bifurcation
 * equations (ABE) of the Lyapunov-Schmidt reduction, derived in
 * doc/engine.md ("Multiple branch points").  Only the residual F is
 * evaluated; its second and third derivatives on the kernel come from
 * directional differences.  With q0 the known branch's tangent, e1, e2 the
 * kernel of A = [F_x; theta q0^T] and psi1, psi2 its left kernel:
 *   L_i(u) = psi_i^T F_xx[q0, u],  P_i(u) = psi_i^T F_xx[u, u],
 *   C_i(u) = psi_i^T (F_xx[u, w2] + F_xxx[u,u,u] / 6),  F_x w2 = -F_xx[u,u] / 2;
 * the directions u = cos(phi) e1 + sin(phi) e2 are the roots of
 *   g(phi) = L_1 N_2 - L_2 N_1,  N = P (quadratic ABE) or C (cubic ABE, when
 * P vanishes on the kernel). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

/* difference steps in the theta-norm of the unit vectors q0, e1, e2: about
   eps^(1/4) for second differences, eps^(1/5) for the odd third ones */
#define CONT_ABE_H2 1.0e-4
#define CONT_ABE_H3 1.0e-3
/* P counts as vanishing below this fraction of L (the differences are good to
   about 1e-8 relative) */
#define CONT_ABE_QUAD 1.0e-5
/* a coefficient (or g) is taken for nonzero only above this multiple of its
   error estimate from the two step sizes */
#define CONT_ABE_SIGNIF 10.0
/* g vanishes identically below this fraction of max|L| max|N| */
#define CONT_ABE_ZERO 1.0e-6
/* L vanishes (no transversal crossing) below this fraction of max|N| */
#define CONT_ABE_NOL 1.0e-8
/* angles sampled in [-delta, pi - delta) for sign changes of g */
#define CONT_ABE_GRID 720
/* left and right singular vectors of A: more sweeps, tighter than the
   tracking's CONT_SV_RTOL (convergence ratio (sigma2/sigma3)^2 is tiny at a
   located BP) */
#define CONT_ABE_SV_MAXIT 30
#define CONT_ABE_SV_RTOL 1.0e-13
/* inverse-iteration sweeps for the left kernel: the ratio sigma_{1,2} /
   sigma_3 per sweep is below 1e-3 at a located BP, so three reach round-off */
#define CONT_ABE_LEFT_IT 3
#define CONT_ABE_PI 3.14159265358979323846

typedef struct abe_work {
  cable_cont *cc;
  int n;
  double *xp, *F, *U, *V, *r, *w, *y; /* [n] except U, V [2n] */
} abe_work;

/* psi^T F(x + c1 d1 + c2 d2 + c3 d3) into out[2] (d2, d3 may be NULL); full F
   into full (NULL: not wanted) */
static int proj(abe_work *aw, const double *d1, double c1, const double *d2, double c2, const double *d3,
                double c3, double out[2], double *full)
{
  cable_cont *cc = aw->cc;
  int n = aw->n;
  for (int i = 0; i < n; i++)
    aw->xp[i] = cc->x[i] + c1 * d1[i] + (d2 ? c2 * d2[i] : 0.0) + (d3 ? c3 * d3[i] : 0.0);
  if (colloc_system_residual(cc->sys, aw->xp, aw->F) != 0) return CABLE_ERR_CALLBACK;
  for (int k = 0; k < 2; k++) {
    double s = 0.0;
    for (int i = 0; i < n; i++) s += aw->U[(size_t)k * n + i] * aw->F[i];
    out[k] = s;
  }
  if (full) memcpy(full, aw->F, (size_t)n * sizeof *full);
  return CABLE_SUCCESS;
}

/* psi^T F_xx[v, v], v = ca a + cb b (b may be NULL), by the central second
   difference; the full vector into full when not NULL */
static int second(abe_work *aw, double h, const double *a, double ca, const double *b, double cb, const double f0[2],
                  const double *F0, double out[2], double *full)
{
  double fp[2], fm[2];
  int rc = proj(aw, a, h * ca, b, h * cb, NULL, 0, fp, full);
  if (rc == CABLE_SUCCESS) rc = proj(aw, a, -h * ca, b, -h * cb, NULL, 0, fm, NULL);
  if (rc != CABLE_SUCCESS) return rc;
  for (int k = 0; k < 2; k++) out[k] = (fp[k] - 2.0 * f0[k] + fm[k]) / (h * h);
  if (full)
    for (int i = 0; i < aw->n; i++) full[i] = (full[i] - 2.0 * F0[i] + aw->F[i]) / (h * h);
  return CABLE_SUCCESS;
}

/* remove the components along the two columns of B (orthonormal) */
static void deflate(int n, const double *B, double *v)
{
  for (int k = 0; k < 2; k++) {
    double s = 0.0;
    for (int i = 0; i < n; i++) s += B[(size_t)k * n + i] * v[i];
    for (int i = 0; i < n; i++) v[i] -= s * B[(size_t)k * n + i];
  }
}

/* w2 with F_x w2 = r (r the full second difference F_xx[u,u], scaled here by
   -1/2), in the complement of the kernel; relative residual into *res */
static int solve_w2(abe_work *aw, double *res)
{
  cable_cont *cc = aw->cc;
  int n = aw->n;
  double *r = aw->r, *w = aw->w, *y = aw->y;
  for (int i = 0; i < n; i++) r[i] *= -0.5;
  r[n - 1] = 0.0; /* A's closing row: theta q0^T w2 = 0 */
  deflate(n, aw->U, r);
  double rn = 0.0;
  for (int i = 0; i < n; i++) rn = fmax(rn, fabs(r[i]));
  memcpy(w, r, (size_t)n * sizeof *w);
  if (abd_solver_solve(cc->abd, w) != 0) return CABLE_ERR_LINSOLVE;
  deflate(n, aw->V, w);
  double rr = 0.0;
  for (int pass = 0; pass < 2; pass++) { /* one refinement, then the residual */
    colloc_jac_matvec(cc->J, w, y);
    for (int i = 0; i < n; i++) y[i] = r[i] - y[i];
    deflate(n, aw->U, y);
    rr = 0.0;
    for (int i = 0; i < n; i++) rr = fmax(rr, fabs(y[i]));
    if (pass == 1) break;
    if (abd_solver_solve(cc->abd, y) != 0) return CABLE_ERR_LINSOLVE;
    deflate(n, aw->V, y);
    for (int i = 0; i < n; i++) w[i] += y[i];
  }
  *res = rn > 0 ? rr / rn : 0.0;
  return CABLE_SUCCESS;
}

/* Gram-Schmidt (twice) of the two columns of B */
static void orthonormalize(int n, double *B)
{
  for (int pass = 0; pass < 2; pass++)
    for (int k = 0; k < 2; k++) {
      double *b = B + (size_t)k * n;
      for (int j = 0; j < k; j++) {
        const double *a = B + (size_t)j * n;
        double d = 0.0;
        for (int i = 0; i < n; i++) d += a[i] * b[i];
        for (int i = 0; i < n; i++) b[i] -= d * a[i];
      }
      double nr = 0.0;
      for (int i = 0; i < n; i++) nr += b[i] * b[i];
      nr = sqrt(nr);
      if (nr > 0)
        for (int i = 0; i < n; i++) b[i] /= nr;
    }
}

/* The left kernel of A by inverse iteration on A^T from a fixed start: each
 * solve multiplies the left near-null components by 1 / sigma_{1,2} against
 * 1 / sigma_3 for the rest.  (The Rayleigh-Ritz left vectors of
 * abd_solver_smallest_svd are J v / sigma, round-off when sigma is at
 * round-off level, as at a BP of a trivial branch.) */
static int left_kernel(cable_cont *cc, double *U)
{
  int n = cc->n;
  unsigned long long st = 0x9E3779B97F4A7C15ULL;
  for (int i = 0; i < 2 * n; i++) {
    st = st * 6364136223846793005ULL + 1442695040888963407ULL;
    U[i] = (double)(st >> 11) * 0x1.0p-53 - 0.5;
  }
  orthonormalize(n, U);
  for (int it = 0; it < CONT_ABE_LEFT_IT; it++) {
    for (int k = 0; k < 2; k++)
      if (abd_solver_solve_transpose(cc->abd, U + (size_t)k * n) != 0) return CABLE_ERR_LINSOLVE;
    orthonormalize(n, U);
  }
  return CABLE_SUCCESS;
}

/* a binary form of degree d: sum_k c[k] cos^(d-k) sin^k */
static double form(const double *c, int d, double phi)
{
  double cs = cos(phi), sn = sin(phi), v = 0.0;
  for (int k = 0; k <= d; k++) v += c[k] * pow(cs, d - k) * pow(sn, k);
  return v;
}

typedef struct abe_eq {
  double L[2][2];  /* L_i = L[i][0] cos + L[i][1] sin */
  double N[2][4];  /* N_i: degree nd */
  int nd;
} abe_eq;

static double gval(const abe_eq *e, double phi)
{
  return form(e->L[0], 1, phi) * form(e->N[1], e->nd, phi) - form(e->L[1], 1, phi) * form(e->N[0], e->nd, phi);
}

/* L and N (P when h3 = 0, else C with w2) with steps h2, h3; *w2res the
   largest relative residual of w2 so far */
static int coeffs(abe_work *aw, const double *q0, const double *e1, const double *e2, const double f0[2],
                  const double *F0, double h2, double h3, abe_eq *eq, double *w2res)
{
  int rc = CABLE_SUCCESS;
  double B[6][2]; /* psi^T F_xx[a+b, a+b] for q0, e1, e2, q0+e1, q0+e2, e1+e2 */
  const double *dirs[6][2] = {{q0, NULL}, {e1, NULL}, {e2, NULL}, {q0, e1}, {q0, e2}, {e1, e2}};
  for (int k = 0; k < 6 && rc == CABLE_SUCCESS; k++)
    rc = second(aw, h2, dirs[k][0], 1.0, dirs[k][1], 1.0, f0, F0, B[k], NULL);
  if (rc != CABLE_SUCCESS) return rc;
  memset(eq, 0, sizeof *eq);
  for (int i = 0; i < 2; i++) {
    eq->L[i][0] = 0.5 * (B[3][i] - B[0][i] - B[1][i]);
    eq->L[i][1] = 0.5 * (B[4][i] - B[0][i] - B[2][i]);
    eq->N[i][0] = B[1][i];                     /* cos^2 */
    eq->N[i][1] = B[5][i] - B[1][i] - B[2][i]; /* 2 cos sin F_xx[e1,e2] */
    eq->N[i][2] = B[2][i];                     /* sin^2 */
  }
  eq->nd = 2;
  if (h3 == 0.0) return CABLE_SUCCESS;
  /* the cubic ABE: C at u = e1, e2, e1 + e2, e1 - e2 */
  eq->nd = 3;
  double C[4][2];
  const double sg[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  for (int k = 0; k < 4; k++) {
    double dummy[2], res = 0.0;
    /* the full second difference along u = sg0 e1 + sg1 e2, then w2 */
    rc = second(aw, h2, e1, sg[k][0], e2, sg[k][1], f0, F0, dummy, aw->r);
    if (rc == CABLE_SUCCESS) rc = solve_w2(aw, &res);
    if (rc != CABLE_SUCCESS) return rc;
    *w2res = fmax(*w2res, res);
    /* G(s) = psi^T F(x0 + s u + s^2 w2) at s = +-h, +-2h; the five-point
       third difference cancels psi^T F_x u (not zero to the differences'
       accuracy when F_x is a difference Jacobian, JAC = 0) and gives the
       third derivative of G, 6 C */
    double g[4][2];
    const double sk[4] = {2 * h3, h3, -h3, -2 * h3};
    for (int q = 0; q < 4 && rc == CABLE_SUCCESS; q++)
      rc = proj(aw, e1, sk[q] * sg[k][0], e2, sk[q] * sg[k][1], aw->w, sk[q] * sk[q], g[q], NULL);
    if (rc != CABLE_SUCCESS) return rc;
    for (int i = 0; i < 2; i++)
      C[k][i] = (g[0][i] - 2.0 * g[1][i] + 2.0 * g[2][i] - g[3][i]) / (12.0 * h3 * h3 * h3);
  }
  for (int i = 0; i < 2; i++) {
    double c0 = C[0][i], c3 = C[1][i], cp = C[2][i], cm = C[3][i];
    eq->N[i][0] = c0;
    eq->N[i][3] = c3;
    eq->N[i][1] = 0.5 * (cp - cm) - c3;
    eq->N[i][2] = 0.5 * (cp + cm) - c0;
  }
  return CABLE_SUCCESS;
}

int cont_branches_compute(cable_cont *cc, const double *q0, double *e1, double *e2, char *msg, size_t len)
{
  int n = cc->n, rc = CABLE_SUCCESS;
  /* the ABE's coordinates: e1, e2 theta-orthonormal (e1 kept in direction) */
  cont_normalize(cc, e1);
  double d12 = colloc_system_inner(cc->sys, e1, e2);
  for (int i = 0; i < n; i++) e2[i] -= d12 * e1[i];
  cont_normalize(cc, e2);
  cc->nbr = -1;
  cc->abe_order = 0;
  msg[0] = '\0';
  abe_work aw = {.cc = cc, .n = n};
  double *mem = calloc((size_t)n * 10, sizeof *mem);
  if (!mem) return CABLE_ERR_ALLOC;
  aw.xp = mem; aw.F = mem + n; aw.U = mem + 2 * (size_t)n; aw.V = mem + 4 * (size_t)n;
  aw.r = mem + 6 * (size_t)n; aw.w = mem + 7 * (size_t)n; aw.y = mem + 8 * (size_t)n;
  double *F0 = mem + 9 * (size_t)n;
  /* the left kernel (and the right one, Euclidean-orthonormal, for the
     projections), warm-started from e1, e2 */
  memcpy(aw.V, e1, (size_t)n * sizeof *e1);
  memcpy(aw.V + n, e2, (size_t)n * sizeof *e2);
  double sv[2];
  int src = abd_solver_smallest_svd(cc->abd, cc->J, 2, aw.V, sv, aw.V, NULL, CONT_ABE_SV_MAXIT, CONT_ABE_SV_RTOL, NULL);
  if ((src != 0 && src != 2) || left_kernel(cc, aw.U) != CABLE_SUCCESS) {
    snprintf(msg, len, "ABE: the kernels did not converge");
    free(mem);
    return CABLE_SUCCESS;
  }
  /* kept for the restriction to Fix(S) (cont_restrict.c picks the unfolding
     row from the antisymmetric left null vector) */
  if (!cc->abe_psi) cc->abe_psi = malloc(2 * (size_t)n * sizeof *cc->abe_psi);
  if (cc->abe_psi) memcpy(cc->abe_psi, aw.U, 2 * (size_t)n * sizeof *cc->abe_psi);
  memset(cc->abe_L, 0, sizeof cc->abe_L);
  double f0[2];
  rc = proj(&aw, q0, 0.0, NULL, 0, NULL, 0, f0, F0);
  /* every coefficient at two step sizes: the Richardson combination
     (4 c(h) - c(2h)) / 3 removes the O(h^2) truncation, and
     |c(h) - c(2h)| / 3 estimates the error of c(h) (doc/engine.md) */
  abe_eq qa, qb, eq;
  double w2res = 0.0, lmax = 0.0, pmax = 0.0, perr = 0.0, nmax = 0.0;
  if (rc == CABLE_SUCCESS) rc = coeffs(&aw, q0, e1, e2, f0, F0, CONT_ABE_H2, 0.0, &qa, &w2res);
  if (rc == CABLE_SUCCESS) rc = coeffs(&aw, q0, e1, e2, f0, F0, 2.0 * CONT_ABE_H2, 0.0, &qb, &w2res);
  if (rc != CABLE_SUCCESS) {
    free(mem);
    return rc;
  }
  eq = qa;
  for (int i = 0; i < 2; i++) {
    for (int k = 0; k < 2; k++) lmax = fmax(lmax, fabs(qa.L[i][k]));
    for (int k = 0; k < 3; k++) {
      eq.N[i][k] = (4.0 * qa.N[i][k] - qb.N[i][k]) / 3.0;
      pmax = fmax(pmax, fabs(eq.N[i][k]));
      perr = fmax(perr, fabs(qa.N[i][k] - qb.N[i][k]) / 3.0);
    }
  }
  nmax = pmax;
  /* the quadratic terms count when they exceed their error estimate
     CONT_ABE_SIGNIF-fold and the floor CONT_ABE_QUAD of L */
  if (!(pmax > CONT_ABE_SIGNIF * perr && pmax > CONT_ABE_QUAD * lmax)) {
    rc = coeffs(&aw, q0, e1, e2, f0, F0, CONT_ABE_H2, CONT_ABE_H3, &qa, &w2res);
    if (rc == CABLE_SUCCESS) rc = coeffs(&aw, q0, e1, e2, f0, F0, CONT_ABE_H2, 2.0 * CONT_ABE_H3, &qb, &w2res);
    if (rc != CABLE_SUCCESS) {
      free(mem);
      return rc;
    }
    eq = qa;
    nmax = 0.0;
    for (int i = 0; i < 2; i++)
      for (int k = 0; k < 4; k++) {
        eq.N[i][k] = (4.0 * qa.N[i][k] - qb.N[i][k]) / 3.0;
        nmax = fmax(nmax, fabs(eq.N[i][k]));
      }
  }
  free(mem);
  memcpy(cc->abe_L, eq.L, sizeof cc->abe_L);
  cc->abe_order = eq.nd;
  if (!(lmax > CONT_ABE_NOL * nmax)) {
    snprintf(msg, len, "ABE (%s): L vanishes (max %.2e, N %.2e): no transversal crossing, no directions",
             eq.nd == 2 ? "quadratic" : "cubic", lmax, nmax);
    return CABLE_SUCCESS;
  }
  const double step = CONT_ABE_PI / CONT_ABE_GRID, a = -0.5 * step;
  double gmax = 0.0, gerr = 0.0;
  for (int k = 0; k <= CONT_ABE_GRID; k++) {
    double phi = a + k * step;
    gmax = fmax(gmax, fabs(gval(&eq, phi)));
    gerr = fmax(gerr, fabs(gval(&qa, phi) - gval(&qb, phi)) / 3.0);
  }
  if (!(gmax > CONT_ABE_SIGNIF * gerr && gmax > CONT_ABE_ZERO * lmax * nmax)) {
    snprintf(msg, len, "ABE (%s, max|P|/max|L| = %.1e, error %.1e): g vanishes identically (max %.2e, error %.1e, "
             "scale %.2e): a continuum of directions", eq.nd == 2 ? "quadratic" : "cubic", lmax > 0 ? pmax / lmax : 0.0,
             lmax > 0 ? perr / lmax : 0.0, gmax, gerr, lmax * nmax);
    return CABLE_SUCCESS;
  }
  int nb = 0;
  double glo = gval(&eq, a);
  for (int k = 0; k < CONT_ABE_GRID && nb < CABLE_MAX_BRANCHES; k++) {
    double lo = a + k * step, hi = lo + step, ghi = gval(&eq, hi), gl = glo;
    glo = ghi;
    if (!(gl * ghi < 0) && ghi != 0.0) continue;
    if (ghi == 0.0) {
      lo = hi;
    } else {
      for (int it = 0; it < 60; it++) {
        double mid = 0.5 * (lo + hi), gm = gval(&eq, mid);
        if (gm == 0.0) { lo = hi = mid; break; }
        if ((gm < 0) == (gl < 0)) { lo = mid; gl = gm; } else hi = mid;
      }
    }
    double phi = 0.5 * (lo + hi), cs = cos(phi), sn = sin(phi);
    cable_branch_dir *b = &cc->br[nb++];
    memset(b, 0, sizeof *b);
    b->phi = phi * (180.0 / CONT_ABE_PI);
    b->multiplicity = 1;
    double Lv[2], Nv[2];
    for (int i = 0; i < 2; i++) {
      Lv[i] = form(eq.L[i], 1, phi);
      Nv[i] = form(eq.N[i], eq.nd, phi);
      b->L[i] = Lv[i];
      b->N[i] = Nv[i];
    }
    int i = fabs(Lv[0]) >= fabs(Lv[1]) ? 0 : 1;
    double t = Lv[i] != 0 ? -Nv[i] / Lv[i] : (double)NAN;
    /* quadratic: direction a0 q0 + u with a0 = -P/(2L); cubic: u, mu = -C/L */
    b->a[0] = eq.nd == 2 ? 0.5 * t : 0.0;
    b->a[1] = cs;
    b->a[2] = sn;
    b->mu = eq.nd == 3 ? t : (double)NAN;
    double h = 1e-7;
    b->dg = fabs(gval(&eq, phi + h) - gval(&eq, phi - h)) / (2 * h);
  }
  cc->nbr = nb;
  size_t l = (size_t)snprintf(msg, len, "ABE (%s, max|P|/max|L| = %.1e, error %.1e): %d direction%s at phi =",
                              eq.nd == 2 ? "quadratic" : "cubic", lmax > 0 ? pmax / lmax : 0.0,
                              lmax > 0 ? perr / lmax : 0.0, nb, nb == 1 ? "" : "s");
  for (int k = 0; k < nb && l < len; k++) l += (size_t)snprintf(msg + l, len - l, " %.4g", cc->br[k].phi);
  if (eq.nd == 3 && l < len) l += (size_t)snprintf(msg + l, len - l, " degrees (w2 residual %.1e)", w2res);
  else if (l < len) l += (size_t)snprintf(msg + l, len - l, " degrees");
  return CABLE_SUCCESS;
}

int cable_cont_branches(const cable_cont *cc, cable_branch_dir *out, int max, int *order)
{
  if (order) *order = cc ? cc->abe_order : 0;
  if (!cc || cc->nbr < 0) return -1;
  for (int k = 0; k < cc->nbr && k < max && out; k++) out[k] = cc->br[k];
  return cc->nbr;
}

const char *cable_cont_note(const cable_cont *cc)
{
  return cc ? cc->note : "";
}
