/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The braid link's constrained second variation on a Ritz space of strain
 * variations (doc/stability.md S7).  The action is local in the strains, the
 * closure constraints are not: they are the end values of the kinematics
 * y' = L F(y, strains), y = (q, r1, sigma).  The first variation of
 * Lambda = A - lambda . c is the local density plus an adjoint integral
 * (p' = -L F_y^T p, p(1) = -lambda . dc/dy(1)); its central differences in
 * the Ritz coefficients give the Hessian, whose asymmetry checks the
 * gradient.  The kinematics and the adjoint are integrated by RK4 on a grid
 * that refines the Ritz pieces, the integrals by Simpson's rule on the same
 * grid (both O(h^4)). */
#include <gsl/gsl_integration.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "braid_model.h"
#include "braid_second_variation.h"
#include "cable/cable_status.h"

enum { NY = 8, NF = 6 };   /* y = (q0..q3, x, y, z, sigma); fields (eta, eta', w2, w3, xi1', xi2') */
static const int slot[BSV_NFIELD] = {0, 2, 3, 4, 5};   /* variation field -> field slot */
/* central differences of the gradient: the fields are O(1..1/Delta); the
   truncation eps^2 |Lambda'''| and the rounding eps_mach |grad| / eps are
   both far below the Ritz error */
static const double fd_eps = 1e-5;

typedef struct {
  const cable_solution *sol;
  braid_material mat;
  double L, L2, T;
  int k, refine, npiece, ns, nstep, nnode, n;
  double *h;            /* nstep step lengths in t */
  int *piece;           /* nstep: the Ritz piece of each step */
  double *val, *der;    /* nstep * 3 * (k+1): basis values, d/dt, at the step's 3 Simpson nodes */
  double *f0, *f;       /* nstep * 3 * NF: base and current fields */
  double *y, *Fy, *p;   /* (nstep + 1) * NY */
  double q0[4];
  int knot;             /* 1: the knot's closure (strand 1 continues as strand 2), L free */
  double Lb, Ltot, sg;  /* the solution's L; L + L2; the link's quaternion sign */
  int nL;               /* the unknown delta L (knots), -1 for links */
} sv_ctx;

static void lagrange(int n, double x, double *l, double *dl)
{
  for (int a = 0; a <= n; a++) {
    double xa = (double)a / n, v = 1.0, d = 0.0;
    for (int b = 0; b <= n; b++) {
      if (b == a) continue;
      double xb = (double)b / n, fct = (x - xb) / (xa - xb);
      if (dl) d = d * fct + v / (xa - xb);
      v *= fct;
    }
    l[a] = v;
    if (dl) dl[a] = d;
  }
}

/* the stored solution (degree ncol on each mesh interval) at x in interval j */
static void sol_at(const cable_solution *s, int j, double x, double *u)
{
  double l[32];
  lagrange(s->ncol, x, l, NULL);
  for (int i = 0; i < BR_NDIM; i++) u[i] = 0.0;
  for (int a = 0; a <= s->ncol; a++) {
    const double *ua = s->u + (size_t)(j * s->ncol + a) * BR_NDIM;
    for (int i = 0; i < BR_NDIM; i++) u[i] += l[a] * ua[i];
  }
}

/* the base fields at x in Ritz piece e */
static int fields_at(const sv_ctx *c, int e, double x, double *f)
{
  const int j = e / c->refine, r = e % c->refine;
  double u[BR_NDIM];
  sol_at(c->sol, j, (r + x) / c->refine, u);
  braid_aux aux;
  if (braid_aux_eval(u, &c->mat, &aux) != 0) return -1;
  f[0] = u[BR_ETA]; f[1] = aux.etap; f[2] = u[BR_W2]; f[3] = u[BR_W3]; f[4] = aux.xi1p; f[5] = aux.xi2p;
  return 0;
}

/* dy/dt */
static int kin(const sv_ctx *c, const double *f, const double *y, double *dy)
{
  const double eta = f[0], w2 = f[2], w3 = f[3], D = c->mat.Delta, L = c->L, ce = cos(eta);
  if (!(ce > 0.0) || !(1.0 - D * w3 > 0.0)) return -1;
  const double w1 = (w3 - 1.0 / D) * tan(eta);
  const double *q = y;
  dy[0] = 0.5 * L * (-w1 * q[1] - w2 * q[2] - w3 * q[3]);
  dy[1] = 0.5 * L * (w1 * q[0] + w3 * q[2] - w2 * q[3]);
  dy[2] = 0.5 * L * (w2 * q[0] - w3 * q[1] + w1 * q[3]);
  dy[3] = 0.5 * L * (w3 * q[0] + w2 * q[1] - w1 * q[2]);
  dy[4] = L * (q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3]);
  dy[5] = L * 2 * (q[1] * q[2] + q[0] * q[3]);
  dy[6] = L * 2 * (q[1] * q[3] - q[0] * q[2]);
  dy[7] = L * (1.0 - D * w3) / ce;
  return 0;
}

/* dp/dt = -L F_y^T p (only the q block of F_y is non-zero; Omega is skew) */
static void adj(const sv_ctx *c, const double *f, const double *y, const double *p, double *dp)
{
  const double eta = f[0], w2 = f[2], w3 = f[3], D = c->mat.Delta, L = c->L;
  const double w1 = (w3 - 1.0 / D) * tan(eta);
  const double *q = y, *pq = p, *pr = p + 4;
  /* Omega^T pq = -Omega pq */
  double om[4] = {-w1 * pq[1] - w2 * pq[2] - w3 * pq[3], w1 * pq[0] + w3 * pq[2] - w2 * pq[3],
                  w2 * pq[0] - w3 * pq[1] + w1 * pq[3], w3 * pq[0] + w2 * pq[1] - w1 * pq[2]};
  const double Dr[3][4] = {{2 * q[0], 2 * q[1], -2 * q[2], -2 * q[3]},
                           {2 * q[3], 2 * q[2], 2 * q[1], 2 * q[0]},
                           {-2 * q[2], 2 * q[3], -2 * q[0], 2 * q[1]}};
  for (int j = 0; j < 4; j++) {
    double s = -0.5 * om[j];
    for (int r = 0; r < 3; r++) s += Dr[r][j] * pr[r];
    dp[j] = -L * s;
  }
  for (int j = 4; j < NY; j++) dp[j] = 0.0;
}

/* p . dF/d(eta, w2, w3) (times L: the t-derivative) */
static void pfphi(const sv_ctx *c, const double *f, const double *y, const double *p, double *g)
{
  const double eta = f[0], w3 = f[3], D = c->mat.Delta, L = c->L, ce = cos(eta), te = tan(eta);
  const double *q = y, *pq = p;
  const double a1 = 0.5 * (-pq[0] * q[1] + pq[1] * q[0] + pq[2] * q[3] - pq[3] * q[2]);
  const double a2 = 0.5 * (-pq[0] * q[2] - pq[1] * q[3] + pq[2] * q[0] + pq[3] * q[1]);
  const double a3 = 0.5 * (-pq[0] * q[3] + pq[1] * q[2] - pq[2] * q[1] + pq[3] * q[0]);
  g[0] = L * (a1 * (w3 - 1.0 / D) / (ce * ce) + p[7] * (1.0 - D * w3) * sin(eta) / (ce * ce));
  g[1] = L * a2;
  g[2] = L * (a1 * te + a3 - p[7] * D / ce);
}

#define FLD(c, st, nu) ((c)->f + ((size_t)(st) * 3 + (size_t)(nu)) * NF)

/* constraint k at the end state y1 (eta1 = eta(1)): its value, its gradient
   in y(1), in eta(1) and its direct dependence on L.  Link (12.3.36-44):
   r1(L) = r1(0), q(0)^-1 q(L) = +-1, sigma(L) = L2.  Knot (12.3.13-22):
   r1(L) - r1(0) = (Delta, 0, 0), q0 = q3, q1 = -q2, 4 q0 q1 = sin eta at L,
   sigma(L) = Ltot - L. */
static double con(const sv_ctx *c, int k, const double *y1, double eta1, double *gy, double *geta, double *gL)
{
  for (int i = 0; i < NY; i++) gy[i] = 0.0;
  *geta = *gL = 0.0;
  const double *a = c->q0, *b = y1;
  if (k < 3) {
    gy[4 + k] = 1.0;
    return y1[4 + k] - (c->knot && k == 0 ? c->mat.Delta : 0.0);
  }
  if (k == 6) {
    gy[7] = 1.0;
    if (c->knot) {
      *gL = 1.0;
      return y1[7] + c->L - c->Ltot;
    }
    return y1[7] - c->L2;
  }
  if (c->knot) {
    if (k == 3) { gy[0] = 1.0; gy[3] = -1.0; return b[0] - b[3]; }
    if (k == 4) { gy[1] = 1.0; gy[2] = 1.0; return b[1] + b[2]; }
    gy[0] = 4 * b[1]; gy[1] = 4 * b[0]; *geta = -cos(eta1);
    return 4 * b[0] * b[1] - sin(eta1);
  }
  const double dv[3][4] = {{-a[1], a[0], a[3], -a[2]}, {-a[2], -a[3], a[0], a[1]}, {-a[3], a[2], -a[1], a[0]}};
  double v = 0.0;
  for (int i = 0; i < 4; i++) {
    gy[i] = c->sg * dv[k - 3][i];
    v += gy[i] * b[i];
  }
  return v;
}

static int forward(sv_ctx *c)
{
  double *y = c->y;
  memset(y, 0, NY * sizeof *y);
  for (int i = 0; i < 4; i++) y[i] = c->q0[i];
  for (int st = 0; st < c->nstep; st++) {
    const double h = c->h[st], *fa = FLD(c, st, 0), *fm = FLD(c, st, 1), *fb = FLD(c, st, 2);
    double *y0 = c->y + (size_t)st * NY, *y1 = y0 + NY, k1[NY], k2[NY], k3[NY], k4[NY], yt[NY];
    int bad = kin(c, fa, y0, k1);
    for (int i = 0; i < NY; i++) yt[i] = y0[i] + 0.5 * h * k1[i];
    bad |= kin(c, fm, yt, k2);
    for (int i = 0; i < NY; i++) yt[i] = y0[i] + 0.5 * h * k2[i];
    bad |= kin(c, fm, yt, k3);
    for (int i = 0; i < NY; i++) yt[i] = y0[i] + h * k3[i];
    bad |= kin(c, fb, yt, k4);
    if (bad) return -1;
    for (int i = 0; i < NY; i++) y1[i] = y0[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    memcpy(c->Fy + (size_t)st * NY, k1, sizeof k1);
    if (st == c->nstep - 1 && kin(c, fb, y1, c->Fy + (size_t)(st + 1) * NY)) return -1;
  }
  return 0;
}

/* the gradient of (local ? A : 0) + sum_k coef_k c_k in the Ritz
   coefficients (and L for a knot); forward() must have run */
static int gradient(sv_ctx *c, const double *coef, int local, double *out)
{
  const int k = c->k;
  memset(out, 0, (size_t)c->n * sizeof *out);
  const double *yend = c->y + (size_t)c->nstep * NY, eta1 = FLD(c, c->nstep - 1, 2)[0];
  double *pend = c->p + (size_t)c->nstep * NY;
  memset(pend, 0, NY * sizeof *pend);
  for (int r = 0; r < BSV_NCON; r++) {
    double gy[NY], geta, gL;
    con(c, r, yend, eta1, gy, &geta, &gL);
    for (int i = 0; i < NY; i++) pend[i] += coef[r] * gy[i];
    out[(size_t)(c->nnode - 1) * BSV_NFIELD] += coef[r] * geta;
    if (c->nL >= 0) out[c->nL] += coef[r] * gL;
  }
  for (int st = c->nstep - 1; st >= 0; st--) {
    const double h = c->h[st], *fa = FLD(c, st, 0), *fm = FLD(c, st, 1), *fb = FLD(c, st, 2);
    const double *y0 = c->y + (size_t)st * NY, *y1 = y0 + NY, *F0 = c->Fy + (size_t)st * NY, *F1 = F0 + NY;
    double *p0 = c->p + (size_t)st * NY, *p1 = p0 + NY, ym[NY], k1[NY], k2[NY], k3[NY], k4[NY], pt[NY];
    for (int i = 0; i < NY; i++) ym[i] = 0.5 * (y0[i] + y1[i]) + h / 8 * (F0[i] - F1[i]);
    adj(c, fb, y1, p1, k1);
    for (int i = 0; i < NY; i++) pt[i] = p1[i] - 0.5 * h * k1[i];
    adj(c, fm, ym, pt, k2);
    for (int i = 0; i < NY; i++) pt[i] = p1[i] - 0.5 * h * k2[i];
    adj(c, fm, ym, pt, k3);
    for (int i = 0; i < NY; i++) pt[i] = p1[i] - h * k3[i];
    adj(c, fa, y0, pt, k4);
    for (int i = 0; i < NY; i++) p0[i] = p1[i] - h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    /* Simpson on the step: the densities at its ends and middle */
    double dp0[NY], pm[NY];
    adj(c, fa, y0, p0, dp0);
    for (int i = 0; i < NY; i++) pm[i] = 0.5 * (p0[i] + p1[i]) + h / 8 * (dp0[i] - k1[i]);
    const double *ys[3] = {y0, ym, y1}, *ps[3] = {p0, pm, p1};
    const double wts[3] = {h / 6, 4 * h / 6, h / 6};
    const int g0 = c->piece[st] * k;
    for (int nu = 0; nu < 3; nu++) {
      const double *f = FLD(c, st, nu);
      double dens[BSV_NFIELD] = {0}, dd = 0.0, pf[3];
      pfphi(c, f, ys[nu], ps[nu], pf);
      dens[0] = pf[0]; dens[1] = pf[1]; dens[2] = pf[2];
      if (local) {
        braid_gpartials gp;
        if (braid_g_partials(f[0], f[1], f[2], f[3], f[4], f[5], 0.0, &c->mat, &gp) != 0) return -1;
        dens[0] += c->L * gp.deta;
        dens[1] += c->L * gp.dw2;
        dens[2] += c->L * gp.dw3;
        dens[3] += c->L * (gp.dxi1p - c->T);
        dens[4] += c->L * (gp.dxi2p + c->T);
        dd = gp.detap;   /* L * g_eta' * (1/L) d(delta eta)/dt */
      }
      if (c->nL >= 0) {
        /* d/dL: y' = L F, A = int L (g - T xi1' + T xi2') dt with eta' = eta_t / L */
        double F[NY], pF = 0.0;
        kin(c, f, ys[nu], F);
        for (int i = 0; i < NY; i++) pF += ps[nu][i] * F[i] / c->L;
        double dl = pF;
        if (local) {
          braid_gpartials gp;
          braid_g_partials(f[0], f[1], f[2], f[3], f[4], f[5], 0.0, &c->mat, &gp);
          dl += gp.g - c->T * f[4] + c->T * f[5] - gp.detap * f[1];
        }
        out[c->nL] += wts[nu] * dl;
      }
      const double *v = c->val + ((size_t)st * 3 + (size_t)nu) * (size_t)(k + 1);
      const double *dv = c->der + ((size_t)st * 3 + (size_t)nu) * (size_t)(k + 1);
      for (int a = 0; a <= k; a++) {
        double *o = out + (size_t)(g0 + a) * BSV_NFIELD;
        for (int j = 0; j < BSV_NFIELD; j++) o[j] += wts[nu] * dens[j] * v[a];
        o[0] += wts[nu] * dd * dv[a];
      }
    }
  }
  return 0;
}

/* add amp times basis function (node, field j) to the current fields, or
   (amp = 0) restore the base fields where it lives */
static void perturb(sv_ctx *c, int node, int j, double amp)
{
  const int k = c->k;
  for (int e = (node - 1) / k; e <= node / k; e++) {
    if (e < 0 || e >= c->npiece || node < e * k || node > e * k + k) continue;
    const int a = node - e * k;
    for (int st = e * c->ns; st < (e + 1) * c->ns; st++)
      for (int nu = 0; nu < 3; nu++) {
        size_t o = (size_t)st * 3 + (size_t)nu;
        double *f = c->f + o * NF;
        if (amp == 0.0) {
          memcpy(f, c->f0 + o * NF, NF * sizeof *f);
          continue;
        }
        f[slot[j]] += amp * c->val[o * (size_t)(k + 1) + (size_t)a];
        if (j == 0) f[1] += amp * c->der[o * (size_t)(k + 1) + (size_t)a] / c->L;
      }
  }
}

/* L = Lb + amp (a knot): eta' = eta_t / L rescales; amp = 0 restores */
static void perturb_L(sv_ctx *c, double amp)
{
  const size_t nfl = (size_t)c->nstep * 3;
  c->L = c->Lb + amp;
  for (size_t o = 0; o < nfl; o++) c->f[o * NF + 1] = c->f0[o * NF + 1] * c->Lb / c->L;
}

static void ctx_free(sv_ctx *c)
{
  free(c->h); free(c->piece); free(c->val); free(c->der); free(c->f0); free(c->f);
  free(c->y); free(c->Fy); free(c->p);
}

int braid_ritz(const cable_solution *sol, int knot, int refine, int degree, int *n_out, int *nc_out, double **K_out,
               double **M_out, double **G_out, braid_sv_info *info)
{
  *K_out = *M_out = *G_out = NULL;
  if (!sol || sol->ndim != BR_NDIM || refine < 1 || degree < 1 || degree > 10 || sol->ncol > 30)
    return CABLE_ERR_INPUT;
  sv_ctx c = {0};
  c.sol = sol;
  braid_material_from_par(sol->par, &c.mat);
  c.L = c.Lb = sol->par[BP_L];
  c.Ltot = sol->par[BP_LTOT];
  c.knot = knot != 0;
  const int f2row = knot == BSV_KNOT_SYM;
  c.L2 = sol->par[BP_L2];
  c.T = sol->par[BP_T];
  c.k = degree;
  c.refine = refine;
  c.npiece = sol->ntst * refine;
  c.ns = BSV_STEPS * degree;   /* RK4/Simpson steps per piece (S7.2) */
  c.nstep = c.npiece * c.ns;
  c.nnode = c.npiece * degree + 1;
  c.n = BSV_NFIELD * c.nnode + c.knot;
  c.nL = c.knot ? c.n - 1 : -1;
  for (int i = 0; i < 4; i++) c.q0[i] = sol->u[BR_Q0 + i];
  const int n = c.n, k = degree;
  const size_t nb = (size_t)c.nstep * 3 * (size_t)(k + 1), nfl = (size_t)c.nstep * 3 * NF;
  c.h = malloc((size_t)c.nstep * sizeof *c.h);
  c.piece = malloc((size_t)c.nstep * sizeof *c.piece);
  c.val = malloc(nb * sizeof *c.val);
  c.der = malloc(nb * sizeof *c.der);
  c.f0 = malloc(nfl * sizeof *c.f0);
  c.f = malloc(nfl * sizeof *c.f);
  c.y = malloc((size_t)(c.nstep + 1) * NY * sizeof *c.y);
  c.Fy = malloc((size_t)(c.nstep + 1) * NY * sizeof *c.Fy);
  c.p = malloc((size_t)(c.nstep + 1) * NY * sizeof *c.p);
  const int ncmax = BSV_NCON + 3;
  double *K = calloc((size_t)n * (size_t)n, sizeof *K), *M = calloc((size_t)n * (size_t)n, sizeof *M);
  double *G = calloc((size_t)ncmax * (size_t)n, sizeof *G);
  double *ga = malloc((size_t)n * sizeof *ga), *gb = malloc((size_t)n * sizeof *gb);
  double *ls = malloc((size_t)n * (BSV_NCON + 1) * sizeof *ls), *rhs = malloc((size_t)n * sizeof *rhs);
  int st = CABLE_SUCCESS;
  gsl_integration_glfixed_table *tbl = gsl_integration_glfixed_table_alloc((size_t)(k + 1));
  if (!c.h || !c.piece || !c.val || !c.der || !c.f0 || !c.f || !c.y || !c.Fy || !c.p || !K || !M || !G || !ga ||
      !gb || !ls || !rhs || !tbl) {
    st = CABLE_ERR_ALLOC;
    goto done;
  }
  /* the grid, the basis at its Simpson nodes, the base fields */
  for (int e = 0; e < c.npiece; e++) {
    const int j = e / refine, r = e % refine;
    const double t0 = sol->t[j * sol->ncol], hj = sol->t[(j + 1) * sol->ncol] - t0, hp = hj / refine;
    for (int s = 0; s < c.ns; s++) {
      const int stp = e * c.ns + s;
      c.h[stp] = hp / c.ns;
      c.piece[stp] = e;
      for (int nu = 0; nu < 3; nu++) {
        const double x = (s + 0.5 * nu) / c.ns;
        const size_t o = (size_t)stp * 3 + (size_t)nu;
        lagrange(k, x, c.val + o * (size_t)(k + 1), c.der + o * (size_t)(k + 1));
        for (int a = 0; a <= k; a++) c.der[o * (size_t)(k + 1) + (size_t)a] /= hp;
        if (fields_at(&c, e, x, c.f0 + o * NF) != 0) {
          st = CABLE_ERR_INPUT;
          goto done;
        }
      }
    }
    (void)r;
  }
  memcpy(c.f, c.f0, nfl * sizeof *c.f);
  if (forward(&c) != 0) {
    st = CABLE_ERR_INPUT;
    goto done;
  }
  /* the constraints at the rebuilt configuration and their gradients */
  {
    const double *a = c.q0, *b = c.y + (size_t)c.nstep * NY;
    c.sg = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0 ? -1.0 : 1.0;
  }
  double cl = 0.0;
  for (int r = 0; r < BSV_NCON; r++) {
    double gy[NY], geta, gL;
    cl = fmax(cl, fabs(con(&c, r, c.y + (size_t)c.nstep * NY, FLD(&c, c.nstep - 1, 2)[0], gy, &geta, &gL)));
  }
  int nc = BSV_NCON + 1;
  for (int r = 0; r < BSV_NCON; r++) {
    double e[BSV_NCON] = {0};
    e[r] = 1.0;
    if (gradient(&c, e, 0, ga) != 0) {
      st = CABLE_ERR_INPUT;
      goto done;
    }
    for (int i = 0; i < n; i++) G[(size_t)r + (size_t)ncmax * (size_t)i] = ga[i];
  }
  /* eta(1) = eta(0): strand 2's tangent closes */
  G[BSV_NCON + 0] = 1.0;
  G[(size_t)BSV_NCON + (size_t)ncmax * (size_t)((c.nnode - 1) * BSV_NFIELD)] = -1.0;
  /* the multipliers: dA = C^T lambda (+ the periodicity row's) by least squares */
  const double zero[BSV_NCON] = {0};
  if (gradient(&c, zero, 1, rhs) != 0) {
    st = CABLE_ERR_INPUT;
    goto done;
  }
  memcpy(ga, rhs, (size_t)n * sizeof *ga);
  for (int r = 0; r <= BSV_NCON; r++)
    for (int i = 0; i < n; i++) ls[(size_t)i + (size_t)n * (size_t)r] = G[(size_t)r + (size_t)ncmax * (size_t)i];
  if (LAPACKE_dgels(LAPACK_COL_MAJOR, 'N', n, BSV_NCON + 1, 1, ls, n, rhs, n) != 0) {
    st = CABLE_ERR_LINSOLVE;
    goto done;
  }
  double lambda[BSV_NCON + 1], res = 0.0, an = 0.0;
  memcpy(lambda, rhs, sizeof lambda);
  for (int i = 0; i < n; i++) {
    double ct = 0.0;
    for (int r = 0; r <= BSV_NCON; r++) ct += G[(size_t)r + (size_t)ncmax * (size_t)i] * lambda[r];
    res += (ga[i] - ct) * (ga[i] - ct);
    an += ga[i] * ga[i];
  }
  /* the Hessian of Lambda = A - lambda . c by differences of its gradient */
  double coef[BSV_NCON];
  for (int r = 0; r < BSV_NCON; r++) coef[r] = -lambda[r];
  for (int node = 0; node < c.nnode; node++)
    for (int j = 0; j < BSV_NFIELD; j++) {
      const int col = node * BSV_NFIELD + j;
      perturb(&c, node, j, fd_eps);
      int bad = forward(&c) || gradient(&c, coef, 1, ga);
      perturb(&c, node, j, 0.0);
      perturb(&c, node, j, -fd_eps);
      bad = bad || forward(&c) || gradient(&c, coef, 1, gb);
      perturb(&c, node, j, 0.0);
      if (bad) {
        st = CABLE_ERR_INPUT;
        goto done;
      }
      for (int i = 0; i < n; i++) K[(size_t)i + (size_t)n * (size_t)col] = (ga[i] - gb[i]) / (2 * fd_eps);
    }
  if (c.nL >= 0) {
    perturb_L(&c, fd_eps);
    int bad = forward(&c) || gradient(&c, coef, 1, ga);
    perturb_L(&c, -fd_eps);
    bad = bad || forward(&c) || gradient(&c, coef, 1, gb);
    perturb_L(&c, 0.0);
    if (bad) {
      st = CABLE_ERR_INPUT;
      goto done;
    }
    for (int i = 0; i < n; i++) K[(size_t)i + (size_t)n * (size_t)c.nL] = (ga[i] - gb[i]) / (2 * fd_eps);
  }
  double hmax = 0.0, amax = 0.0;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < j; i++) {
      double *kij = K + (size_t)i + (size_t)n * (size_t)j, *kji = K + (size_t)j + (size_t)n * (size_t)i;
      amax = fmax(amax, fabs(*kij - *kji));
      *kij = *kji = 0.5 * (*kij + *kji);
      hmax = fmax(hmax, fabs(*kij));
    }
  for (int i = 0; i < n; i++) hmax = fmax(hmax, fabs(K[(size_t)i * (size_t)(n + 1)]));
  /* the mass form (Gauss, exact) and the shift generator's row int w.v dt,
     w = d(fields)/dt (differences in t of the stored solution) */
  double wn = 0.0, fn = 0.0;
  double *wrow = G + BSV_NCON + 1;
  for (int e = 0; e < c.npiece; e++) {
    const int j = e / refine, r = e % refine;
    const double hp = (sol->t[(j + 1) * sol->ncol] - sol->t[j * sol->ncol]) / refine;
    const int g0 = e * k;
    for (int q = 0; q <= k; q++) {
      double x, wt, l[11], fa[NF], fb[NF], f0[NF];
      gsl_integration_glfixed_point(0.0, 1.0, (size_t)q, &x, &wt, tbl);
      lagrange(k, x, l, NULL);
      const double dx = 1e-6;
      if (fields_at(&c, e, x - dx, fa) || fields_at(&c, e, x + dx, fb) || fields_at(&c, e, x, f0)) {
        st = CABLE_ERR_INPUT;
        goto done;
      }
      double wf[BSV_NFIELD];
      for (int jf = 0; jf < BSV_NFIELD; jf++) {
        wf[jf] = (fb[slot[jf]] - fa[slot[jf]]) / (2 * dx * hp);
        wn += wt * hp * wf[jf] * wf[jf];
        fn += wt * hp * f0[slot[jf]] * f0[slot[jf]];
      }
      for (int A = 0; A <= k; A++) {
        for (int jf = 0; jf < BSV_NFIELD; jf++) {
          size_t ia = (size_t)(g0 + A) * BSV_NFIELD + (size_t)jf;
          wrow[(size_t)ncmax * ia] += wt * hp * wf[jf] * l[A];
          for (int B = 0; B <= k; B++) {
            size_t ib = (size_t)(g0 + B) * BSV_NFIELD + (size_t)jf;
            M[ia + (size_t)n * ib] += wt * hp * l[A] * l[B];
          }
        }
      }
    }
    (void)r;
  }
  if (c.nL >= 0) M[(size_t)c.nL * (size_t)(n + 1)] = 1.0;   /* any positive number (Sylvester) */
  /* a generator that vanishes (constant fields) is no row.  The knot's shift
     moves its seam (strand 1 continues as strand 2) and changes L too: its
     generator z is d/dt of the fields plus a delta L component; the row w
     (d/dt of the fields, 0 for L) has w.z = |w|^2 > 0, which is all the
     removal needs (a kernel vector outside w's orthogonal complement: the
     index on that complement is Q's, S7) */
  const int shift = sqrt(wn) > 1e-6 * sqrt(fn);
  if (shift) nc++;
  /* braid_knot_sym: delta F2(0) = 0 (S7.3).  F is the multiplier of the
     closure of r1, F2(0) = lambda_r . d1(0); for a variation v the
     multipliers' first-order change is (G G^T)^-1 G K v (the derivative of
     the least-squares multipliers at a stationary point, G the 8 rows
     above), so the row is x^T G K with (G G^T) x = (d1(0), 0, ..., 0).  On
     the mode branches it removes the family that changes F2(0) (its tangent
     z has K z = G^T dlambda, so the row is dF2(0) != 0 on z) */
  double f2val = 0.0;
  if (f2row) {
    const int ng = BSV_NCON + 1;
    const double *q = c.q0;
    const double d1[3] = {2 * (q[1] * q[2] - q[0] * q[3]), q[0] * q[0] - q[1] * q[1] + q[2] * q[2] - q[3] * q[3],
                          2 * (q[2] * q[3] + q[0] * q[1])};
    double GG[(BSV_NCON + 1) * (BSV_NCON + 1)], x[BSV_NCON + 1] = {0};
    lapack_int ipiv[BSV_NCON + 1];
    for (int a = 0; a < ng; a++)
      for (int b = 0; b < ng; b++) {
        double v = 0.0;
        for (int i = 0; i < n; i++) v += G[(size_t)a + (size_t)ncmax * (size_t)i] * G[(size_t)b + (size_t)ncmax * (size_t)i];
        GG[a + ng * b] = v;
      }
    for (int r = 0; r < 3; r++) {
      x[r] = d1[r];
      f2val += d1[r] * lambda[r];
    }
    if (LAPACKE_dgesv(LAPACK_COL_MAJOR, ng, 1, GG, ng, ipiv, x, ng) != 0) {
      st = CABLE_ERR_LINSOLVE;
      goto done;
    }
    /* gx = G^T x, then the row K gx (K symmetric), scaled to the largest
       constraint row's norm (the rank test of stability.c is relative) */
    for (int i = 0; i < n; i++) {
      double v = 0.0;
      for (int r = 0; r < ng; r++) v += G[(size_t)r + (size_t)ncmax * (size_t)i] * x[r];
      ga[i] = v;
    }
    double rn = 0.0, gmax = 0.0;
    for (int r = 0; r < nc; r++) {
      double g2 = 0.0;
      for (int i = 0; i < n; i++) g2 += G[(size_t)r + (size_t)ncmax * (size_t)i] * G[(size_t)r + (size_t)ncmax * (size_t)i];
      gmax = fmax(gmax, sqrt(g2));
    }
    for (int j = 0; j < n; j++) {
      double v = 0.0;
      for (int i = 0; i < n; i++) v += K[(size_t)i + (size_t)n * (size_t)j] * ga[i];
      gb[j] = v;
      rn += v * v;
    }
    rn = sqrt(rn);
    if (!(rn > 0.0)) {
      st = CABLE_ERR_INPUT;
      goto done;
    }
    for (int j = 0; j < n; j++) G[(size_t)nc + (size_t)ncmax * (size_t)j] = gb[j] * gmax / rn;
    nc++;
  }
  /* compact G to nc rows */
  for (int i = 0; i < n; i++)
    for (int r = 0; r < nc; r++) G[(size_t)r + (size_t)nc * (size_t)i] = G[(size_t)r + (size_t)ncmax * (size_t)i];
  if (info) {
    memcpy(info->lambda, lambda, sizeof info->lambda);
    info->stat_res = an > 0 ? sqrt(res / an) : 0.0;
    info->asym = hmax > 0 ? amax / hmax : 0.0;
    info->shift_row = shift;
    info->f2_row = f2row;
    info->f2 = f2val;
    info->closure = cl;
  }
  *n_out = n;
  *nc_out = nc;
  *K_out = K;
  *M_out = M;
  *G_out = G;
  K = M = G = NULL;
done:
  if (tbl) gsl_integration_glfixed_table_free(tbl);
  ctx_free(&c);
  free(K); free(M); free(G); free(ga); free(gb); free(ls); free(rhs);
  return st;
}
