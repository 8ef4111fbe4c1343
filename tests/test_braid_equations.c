/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The braid right-hand side (equations/braid_model.h): exact Jacobians
 * against central differences, AUTO's FUNC against the plain right-hand side,
 * independent consistency checks of the generated equations, the mirror
 * symmetry, and every guard rail. */
#include <float.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_rng.h>

#include "braid_integrals.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_random.h"
#include "harness.h"

#define N BR_NDIM
#define NM BRAID_NMAT
#define NPOINTS 6 /* random states for the Jacobian and consistency checks */

/* Central differences with step h = cbrt(eps) * scale have truncation error
 * (h^2/6)|f'''| scale^3 ~ 1e-11 and round-off eps|f|/h ~ 4e-11 (relative to
 * the row scale), i.e. ~ eps^(2/3).  The third derivatives carry factors like
 * 1/Delta (Delta down to 0.02 here) and 1/cos(eta)^k, so we allow 1e-8:
 * 270 eps^(2/3) (the worst seen is ~4e-10).  A wrong entry (a sign, a missing
 * term) is O(1) in these units; test_fd_detects_error() shows that 1e-5 is
 * caught. */
#define FD_TOL 1e-8
/* Identities that hold exactly in exact arithmetic, evaluated with a few
 * hundred flops: 1e3 DBL_EPSILON relative to the scale of the terms. */
#define ROUND_TOL (1e3 * DBL_EPSILON)
/* The same for identities that chain two generated expressions (a rate into
 * a partial of g), each with its own rounding: one more factor 10. */
#define ROUND_TOL2 (1e4 * DBL_EPSILON)
/* q.q' is a sum of 4 products of 4 terms that cancel exactly: a few ulps of
 * the sum of their magnitudes. */
#define QQ_TOL (4 * DBL_EPSILON)
/* d/ds of h and Ham along f by central differences with step ALONG_F_STEP:
 * truncation ~ step^2 |I'''| ~ 1e-12, round-off ~ DBL_EPSILON |I|/step ~ 2e-10
 * (relative); 1e-7 leaves a factor 500.  A wrong rate gives O(1). */
#define ALONG_F_STEP 1e-6
#define ALONG_F_TOL 1e-7

/* A non-singular state with the magnitudes of the paper's braids, scaled to L ~ 1:
 * Delta 0.02-0.1, |eta| <= 0.5, curvatures and forces O(1-5). */
static void random_state(gsl_rng *r, double *u, braid_material *m)
{
  static const braid_random_ranges ranges = {5.0, 3.0, 0.5, 2.0, 3.0, 1};
  braid_random_state(r, &ranges, u, m);
}

static void mat_to_array(const braid_material *m, double *p)
{
  p[0] = m->Delta; p[1] = m->B1; p[2] = m->B2; p[3] = m->C1; p[4] = m->C2;
  p[5] = m->w01; p[6] = m->w02;
}

static void array_to_mat(const double *p, braid_material *m)
{
  m->Delta = p[0]; m->B1 = p[1]; m->B2 = p[2]; m->C1 = p[3]; m->C2 = p[4];
  m->w01 = p[5]; m->w02 = p[6];
}

/* Largest scaled discrepancy between an analytic Jacobian column set and
 * central differences.  x: the variables (state or material), scale_j their
 * scales; err_ij = |J - Jfd| scale_j / rowscale_i with rowscale_i =
 * max(|f_i|, max_k |J_ik| scale_k). */
typedef int (*eval_fn)(const double *x, const void *ctx, double *f);

static double fd_max_error(eval_fn fn, const void *ctx, const double *x0, int nx,
                           const double *scale, const double *f0, const double *jac, int *worst_i,
                           int *worst_j)
{
  const double hrel = cbrt(DBL_EPSILON);
  double x[N], fp[N], fm[N], rowscale[N];
  for (int i = 0; i < N; i++) {
    rowscale[i] = fabs(f0[i]);
    for (int k = 0; k < nx; k++) rowscale[i] = fmax(rowscale[i], fabs(jac[i + N * k]) * scale[k]);
    if (rowscale[i] == 0.0) rowscale[i] = 1.0;
  }
  double worst = 0.0;
  *worst_i = *worst_j = -1;
  for (int j = 0; j < nx; j++) {
    const double h = hrel * scale[j];
    memcpy(x, x0, (size_t)nx * sizeof *x);
    x[j] = x0[j] + h;
    if (fn(x, ctx, fp) != 0) return INFINITY;
    x[j] = x0[j] - h;
    if (fn(x, ctx, fm) != 0) return INFINITY;
    for (int i = 0; i < N; i++) {
      const double fd = (fp[i] - fm[i]) / (2.0 * h);
      const double err = fabs(fd - jac[i + N * j]) * scale[j] / rowscale[i];
      if (err > worst) {
        worst = err;
        *worst_i = i;
        *worst_j = j;
      }
    }
  }
  return worst;
}

static int eval_u(const double *x, const void *ctx, double *f)
{
  return braid_rhs(x, (const braid_material *)ctx, f, NULL, NULL);
}

typedef struct {
  const double *u;
} mat_ctx;

static int eval_m(const double *x, const void *ctx, double *f)
{
  braid_material m;
  array_to_mat(x, &m);
  return braid_rhs(((const mat_ctx *)ctx)->u, &m, f, NULL, NULL);
}

static void state_scales(const double *u, double *scale)
{
  for (int j = 0; j < N; j++) scale[j] = fmax(fabs(u[j]), 1.0);
}

static void test_jacobians(gsl_rng *r)
{
  for (int n = 0; n < NPOINTS; n++) {
    double u[N], f[N], ju[N * N], jm[N * NM], scale[N], p[NM], pscale[NM];
    braid_material m;
    random_state(r, u, &m);
    for (int i = 0; i < N; i++) f[i] = NAN; /* every entry must be written */
    int st = braid_rhs(u, &m, f, ju, jm);
    test_int("braid_rhs status at a random state", st, 0);
    double f2[N];
    braid_rhs(u, &m, f2, NULL, NULL);
    double dmax = 0.0;
    for (int i = 0; i < N; i++) dmax = fmax(dmax, fabs(f2[i] - f[i]) / fmax(fabs(f[i]), 1.0));
    test_le("rhs without Jacobian = rhs with Jacobian (rel.)", dmax, ROUND_TOL);
    int wi, wj;
    state_scales(u, scale);
    double e = fd_max_error(eval_u, &m, u, N, scale, f, ju, &wi, &wj);
    printf("  point %d: worst state-Jacobian entry (%d,%d)\n", n, wi, wj);
    test_le("d rhs/d u vs central differences (scaled error)", e, FD_TOL);
    mat_to_array(&m, p);
    for (int k = 0; k < NM; k++) pscale[k] = k < 5 ? fabs(p[k]) : 1.0;
    mat_ctx c = {u};
    e = fd_max_error(eval_m, &c, p, NM, pscale, f, jm, &wi, &wj);
    printf("  point %d: worst material-Jacobian entry (%d,%d)\n", n, wi, wj);
    test_le("d rhs/d (Delta,B1,B2,C1,C2,w01,w02) vs central differences (scaled error)", e, FD_TOL);
  }
}

/* The comparison above must be able to fail: perturb one entry by 1e-5 of its
 * row scale and see the error reported. */
static void test_fd_detects_error(gsl_rng *r)
{
  double u[N], f[N], ju[N * N], jm[N * NM], scale[N];
  braid_material m;
  random_state(r, u, &m);
  braid_rhs(u, &m, f, ju, jm);
  state_scales(u, scale);
  double rowscale = fabs(f[BR_W3]);
  for (int k = 0; k < N; k++) rowscale = fmax(rowscale, fabs(ju[BR_W3 + N * k]) * scale[k]);
  ju[BR_W3 + N * BR_ETA] += 1e-5 * rowscale / scale[BR_ETA];
  int wi, wj;
  double e = fd_max_error(eval_u, &m, u, N, scale, f, ju, &wi, &wj);
  test_true("a 1e-5 error in d(omega3')/d(eta) is detected by the FD check", e > FD_TOL);
  test_true("... and located at (omega3, eta)", wi == BR_W3 && wj == BR_ETA);
}

static void test_func(gsl_rng *r)
{
  double u[N], f[N], ju[N * N], jm[N * NM];
  braid_material m;
  random_state(r, u, &m);
  double par[BP_NPAR];
  for (int k = 0; k < BP_NPAR; k++) par[k] = 100.0 + k; /* distinct junk in unused slots */
  par[BP_L] = 1.7;
  par[BP_DELTA] = m.Delta;
  par[BP_B1] = m.B1;
  par[BP_B2] = m.B2;
  par[BP_C1] = m.C1;
  par[BP_C2] = m.C2;
  par[BP_W01] = m.w01;
  par[BP_W02] = m.w02;
  braid_material m2;
  braid_material_from_par(par, &m2);
  test_true("braid_material_from_par reads the slots of braid_state.h",
            m2.Delta == m.Delta && m2.B1 == m.B1 && m2.B2 == m.B2 && m2.C1 == m.C1
                && m2.C2 == m.C2 && m2.w01 == m.w01 && m2.w02 == m.w02);
  braid_rhs(u, &m, f, ju, jm);
  double F[N], dfdu[N * N], dfdp[N * BP_NPAR];
  for (int i = 0; i < N * BP_NPAR; i++) dfdp[i] = NAN;
  int icp[1] = {BP_T};
  int st = braid_func(N, u, icp, par, 2, F, dfdu, dfdp, NULL);
  test_int("braid_func(ijac=2) status", st, 0);
  double e = 0.0, ez = 0.0;
  for (int i = 0; i < N; i++) e = fmax(e, fabs(F[i] - 1.7 * f[i]));
  test_le("braid_func f = L * rhs (abs.)", e, 0.0);
  e = 0.0;
  for (int i = 0; i < N * N; i++) e = fmax(e, fabs(dfdu[i] - 1.7 * ju[i]));
  test_le("braid_func dfdu = L * jac_u (abs.)", e, 0.0);
  e = 0.0;
  for (int i = 0; i < N; i++) e = fmax(e, fabs(dfdp[i + N * BP_L] - f[i]));
  test_le("braid_func dfdp(:,L) = rhs (abs.)", e, 0.0);
  const int slot[NM] = {BP_DELTA, BP_B1, BP_B2, BP_C1, BP_C2, BP_W01, BP_W02};
  e = 0.0;
  for (int k = 0; k < NM; k++)
    for (int i = 0; i < N; i++) e = fmax(e, fabs(dfdp[i + N * slot[k]] - 1.7 * jm[i + N * k]));
  test_le("braid_func dfdp(:,Delta..w02) = L * jac_m (abs.)", e, 0.0);
  for (int k = 0; k < BP_NPAR; k++) {
    int is_set = k == BP_L;
    for (int j = 0; j < NM; j++) is_set |= k == slot[j];
    if (!is_set)
      for (int i = 0; i < N; i++) ez = fmax(ez, isnan(dfdp[i + N * k]) ? HUGE_VAL : fabs(dfdp[i + N * k]));
  }
  test_le("braid_func dfdp other columns are zero", ez, 0.0);
  /* ijac = 0 and 1 must not touch what they were not asked for */
  double sentinel[N * N];
  for (int i = 0; i < N * N; i++) sentinel[i] = 42.0;
  st = braid_func(N, u, icp, par, 0, F, sentinel, NULL, NULL);
  int untouched = 1;
  for (int i = 0; i < N * N; i++) untouched &= sentinel[i] == 42.0;
  test_true("braid_func(ijac=0) leaves dfdu alone", st == 0 && untouched);
  st = braid_func(N, u, icp, par, 1, F, dfdu, NULL, NULL);
  test_int("braid_func(ijac=1, dfdp=NULL) status", st, 0);
  st = braid_func(N - 1, u, icp, par, 0, F, NULL, NULL, NULL);
  test_int("braid_func with ndim = 20 is fatal (BRAID_BAD_DIM)", st, BRAID_BAD_DIM);
  par[BP_L] = NAN;
  st = braid_func(N, u, icp, par, 2, F, dfdu, dfdp, NULL);
  test_int("braid_func with L = NaN: BRAID_NONFINITE", st, BRAID_NONFINITE);
  par[BP_L] = 1e308;
  st = braid_func(N, u, icp, par, 2, F, dfdu, dfdp, NULL);
  int clean = 1;
  for (int i = 0; i < N; i++) clean &= F[i] == 0.0;
  for (int i = 0; i < N * N; i++) clean &= dfdu[i] == 0.0;
  for (int i = 0; i < N * BP_NPAR; i++) clean &= dfdp[i] == 0.0;
  test_true("braid_func with L = 1e308 overflows: BRAID_NONFINITE, outputs zeroed",
            st == BRAID_NONFINITE && clean);
  par[BP_L] = 1.0;
  par[BP_B2] = 0.0;
  st = braid_func(N, u, icp, par, 0, F, NULL, NULL, NULL);
  test_int("braid_func with B2 = 0 is fatal (BRAID_BAD_MATERIAL)", st, BRAID_BAD_MATERIAL);
}

/* Independent checks of the generated equations through braid_g_partials,
 * which is generated from g alone (no balance laws, no elimination). */
static void test_consistency(gsl_rng *r)
{
  for (int n = 0; n < NPOINTS; n++) {
    double u[N], f[N];
    braid_material m;
    random_state(r, u, &m);
    braid_rhs(u, &m, f, NULL, NULL);
    braid_aux a;
    test_int("braid_aux_eval status", braid_aux_eval(u, &m, &a), 0);
    const double eta = u[BR_ETA], w2 = u[BR_W2], w3 = u[BR_W3];
    braid_gpartials gp;
    braid_g_partials(eta, a.etap, w2, w3, a.xi1p, a.xi2p, a.h, &m, &gp);
    const double M1 = u[BR_M1], M2 = u[BR_M2], M3 = u[BR_M3];
    const double te = tan(eta);
    double sc = fabs(M2) + fabs(m.B1 * w2) + 1.0;
    test_le("(12.2.19) M2 = dg/domega2 (rel.)", fabs(gp.dw2 - M2) / sc, ROUND_TOL);
    test_le("dg/deta' = M2 - B1 omega2 (rel.)", fabs(gp.detap - (M2 - m.B1 * w2)) / sc, ROUND_TOL);
    test_le("T1 = dg/dxi1' (rel.)", fabs(gp.dxi1p - u[BR_T1]) / (fabs(u[BR_T1]) + 1.0),
            ROUND_TOL);
    test_le("T2 = dg/dxi2' (rel.)", fabs(gp.dxi2p - u[BR_T2]) / (fabs(u[BR_T2]) + 1.0),
            ROUND_TOL);
    sc = fabs(M3) + fabs(te * M1) + fabs(gp.dw3) + fabs(a.h * m.Delta / cos(eta));
    test_le("(12.2.20) M3 + tan(eta) M1 = dg/domega3 (rel.)",
            fabs(gp.dw3 - (M3 + te * M1)) / sc, ROUND_TOL2);
    /* (12.2.18): M1 = Delta cos^2/(Delta w3 - 1) [dg/deta - (M2' - B1 w2')] */
    const double c2 = cos(eta) * cos(eta);
    const double el = gp.deta - (f[BR_M2] - m.B1 * f[BR_W2]);
    const double rhs18 = m.Delta * c2 / (m.Delta * w3 - 1.0) * el;
    sc = fabs(M1) + m.Delta * c2 / fabs(m.Delta * w3 - 1.0)
         * (fabs(gp.deta) + fabs(f[BR_M2]) + fabs(m.B1 * f[BR_W2]));
    test_le("(12.2.18) with the rhs's M2' and omega2' (rel.)", fabs(rhs18 - M1) / sc, ROUND_TOL2);
    /* omega1 and sigma' */
    test_le("(12.2.8) omega1 = (omega3 - 1/Delta) tan(eta) (rel.)",
            fabs(a.w1 - (w3 - 1.0 / m.Delta) * te) / fabs(a.w1), ROUND_TOL);
    const double sig6 = hypot(m.Delta * a.w1, m.Delta * w3 - 1.0);
    test_le("(12.2.6) sigma' = sqrt((Delta w1)^2 + (Delta w3 - 1)^2) (rel.)",
            fabs(a.sigmap - sig6) / sig6, ROUND_TOL);
    test_le("rhs sigma' = aux sigma' (rel.)", fabs(f[BR_SIGMA] - a.sigmap) / a.sigmap, ROUND_TOL);
    test_le("rhs eta' = aux eta' (abs.)", fabs(f[BR_ETA] - a.etap), ROUND_TOL * (fabs(a.etap) + 1));
    /* the omega3' denominator */
    double den;
    braid_w3_denominator(u, &m, &den);
    const double c = cos(eta), om = 1.0 - m.Delta * w3;
    const double den_closed = c / m.Delta * (m.B1 + m.B2 * c * c * c / (om * om * om));
    test_rel("omega3' denominator = (cos eta/Delta)(B1 + B2 cos^3/(1-Delta w3)^3)", den, den_closed,
             ROUND_TOL);
    /* h is a first integral by construction: its derivative along f vanishes */
    const double eps = ALONG_F_STEP;
    double up[N], um[N];
    for (int i = 0; i < N; i++) {
      up[i] = u[i] + eps * f[i];
      um[i] = u[i] - eps * f[i];
    }
    braid_first_integrals ip, im;
    braid_first_integrals_eval(up, &m, &ip);
    braid_first_integrals_eval(um, &m, &im);
    const double dh = (ip.h - im.h) / (2 * eps), dH = (ip.ham - im.ham) / (2 * eps);
    test_le("dh/ds along the rhs (central difference, rel. to |h|+1)", fabs(dh) / (fabs(a.h) + 1.0),
            ALONG_F_TOL);
    test_le("dHam/ds along the rhs (central difference, rel. to |Ham|+1)",
            fabs(dH) / (fabs(ip.ham) + 1.0), ALONG_F_TOL);
  }
}

/* The mirror map z -> -z (doc D10) maps solutions to solutions:
 * f(S u; S m) = S f(u; m). */
static void mirror(const double *u, double *v)
{
  static const int flip[] = {BR_F3, BR_M1, BR_M2, BR_ETA, BR_W2, BR_XI1, BR_T1,
                             BR_XI2, BR_T2, BR_Q1, BR_Q2, BR_Z1};
  memcpy(v, u, N * sizeof *u);
  for (size_t k = 0; k < sizeof flip / sizeof flip[0]; k++) v[flip[k]] = -u[flip[k]];
}

static void test_symmetry(gsl_rng *r)
{
  for (int n = 0; n < 3; n++) {
    double u[N], v[N], f[N], g[N], Sf[N];
    braid_material m, mm;
    random_state(r, u, &m);
    mirror(u, v);
    mm = m;
    mm.w01 = -m.w01;
    mm.w02 = -m.w02;
    braid_rhs(u, &m, f, NULL, NULL);
    int st = braid_rhs(v, &mm, g, NULL, NULL);
    mirror(f, Sf);
    double e = 0.0;
    for (int i = 0; i < N; i++) e = fmax(e, fabs(g[i] - Sf[i]) / (fabs(f[i]) + 1.0));
    test_true("mirror image is non-singular", st == 0);
    test_le("mirror symmetry f(Su) = S f(u) (rel.)", e, ROUND_TOL);
    /* q . q' = 0: the quaternion norm is conserved exactly by (12.2.23) */
    double qq = 0.0, qs = 0.0;
    for (int i = BR_Q0; i <= BR_Q3; i++) {
      qq += u[i] * f[i];
      qs += fabs(u[i] * f[i]);
    }
    test_le("q . q' = 0 (rel. to sum |q_i q_i'|)", fabs(qq) / qs, QQ_TOL);
    braid_first_integrals a, b;
    braid_first_integrals_eval(u, &m, &a);
    braid_first_integrals_eval(v, &mm, &b);
    test_rel("h is mirror invariant", b.h, a.h, ROUND_TOL);
    test_rel("Hamiltonian is mirror invariant", b.ham, a.ham, ROUND_TOL);
  }
}

static int all_zero(const double *x, int n)
{
  for (int i = 0; i < n; i++)
    if (x[i] != 0.0) return 0;
  return 1;
}

/* Every guarded function at one bad state: the expected code, zero outputs.
 * braid_g_partials sees only (eta, omega2, omega3) of the state: gp_code is
 * what it must return (it is not called when eta or omega3 is not finite). */
static void expect_guard_gp(const char *what, const double *u, const braid_material *m, int code,
                            int gp_code)
{
  double f[N], ju[N * N], jm[N * NM];
  char msg[160];
  int st = braid_rhs(u, m, f, ju, jm);
  snprintf(msg, sizeof msg, "%s: braid_rhs returns %d, outputs zero", what, code);
  test_true(msg, st == code && all_zero(f, N) && all_zero(ju, N * N) && all_zero(jm, N * NM));
  braid_aux a;
  st = braid_aux_eval(u, m, &a);
  snprintf(msg, sizeof msg, "%s: braid_aux_eval returns %d, outputs zero", what, code);
  test_true(msg, st == code && a.w1 == 0 && a.sigmap == 0 && a.etap == 0 && a.xi1p == 0
                     && a.xi2p == 0 && a.h == 0);
  braid_first_integrals fi;
  st = braid_first_integrals_eval(u, m, &fi);
  snprintf(msg, sizeof msg, "%s: braid_first_integrals_eval returns %d, outputs zero", what, code);
  test_true(msg, st == code && fi.F2 == 0 && fi.FM == 0 && fi.h == 0 && fi.q2 == 0 && fi.T1 == 0
                     && fi.T2 == 0 && fi.ham == 0);
  double p1 = 1, p2 = 1;
  st = braid_contact_pressure(u, NULL, m, &p1, &p2);
  snprintf(msg, sizeof msg, "%s: braid_contact_pressure returns %d, outputs zero", what, code);
  test_true(msg, st == code && p1 == 0 && p2 == 0);
  double den = 1;
  st = braid_w3_denominator(u, m, &den);
  snprintf(msg, sizeof msg, "%s: braid_w3_denominator returns %d, output zero", what, code);
  test_true(msg, st == code && den == 0);
  if (isfinite(u[BR_ETA]) && isfinite(u[BR_W3])) {
    braid_gpartials gp;
    st = braid_g_partials(u[BR_ETA], 0.1, u[BR_W2], u[BR_W3], 0.2, 0.3, 0.4, m, &gp);
    snprintf(msg, sizeof msg, "%s: braid_g_partials returns %d%s", what, gp_code,
             gp_code ? ", outputs zero" : "");
    test_true(msg, st == gp_code
                       && (gp_code == 0
                           || (gp.g == 0 && gp.dw2 == 0 && gp.dw3 == 0 && gp.deta == 0
                               && gp.detap == 0 && gp.dxi1p == 0 && gp.dxi2p == 0)));
  }
}

static void expect_guard(const char *what, const double *u, const braid_material *m, int code)
{
  expect_guard_gp(what, u, m, code, code);
}

static void test_guards(gsl_rng *r)
{
  double u0[N], u[N], f[N], ju[N * N];
  braid_material m0, m;
  random_state(r, u0, &m0);

  memcpy(u, u0, sizeof u);
  u[BR_ETA] = acos(0.0); /* pi/2 rounded: cos = 6e-17 */
  expect_guard("eta = pi/2", u, &m0, BRAID_SINGULAR_COS_ETA);
  u[BR_ETA] = -acos(0.5 * BRAID_COS_ETA_MIN);
  expect_guard("cos(eta) = COS_ETA_MIN/2", u, &m0, BRAID_SINGULAR_COS_ETA);
  u[BR_ETA] = 2.0;
  expect_guard("eta = 2 (cos < 0, tubes overlap)", u, &m0, BRAID_SINGULAR_COS_ETA);
  u[BR_ETA] = acos(1e3 * BRAID_COS_ETA_MIN);
  int st = braid_rhs(u, &m0, f, ju, NULL);
  int fin = 1;
  for (int i = 0; i < N; i++) fin &= isfinite(f[i]);
  for (int i = 0; i < N * N; i++) fin &= isfinite(ju[i]);
  test_true("cos(eta) = 1e3 COS_ETA_MIN is accepted with finite output", st == 0 && fin);

  memcpy(u, u0, sizeof u);
  u[BR_W3] = 1.0 / m0.Delta;
  expect_guard("omega3 = 1/Delta (sigma' = 0)", u, &m0, BRAID_SINGULAR_SIGMA);
  u[BR_ETA] = 0.0;
  expect_guard("omega3 = 1/Delta and omega1 = 0 (the paper's excluded case)", u, &m0,
               BRAID_SINGULAR_SIGMA);
  u[BR_W3] = (1.0 - 0.5 * BRAID_ONE_MINUS_DW3_MIN) / m0.Delta;
  expect_guard("1 - Delta omega3 = ONE_MINUS_DW3_MIN/2", u, &m0, BRAID_SINGULAR_SIGMA);
  u[BR_W3] = 2.0 / m0.Delta;
  expect_guard("1 - Delta omega3 = -1 (strand 2 reversed)", u, &m0, BRAID_SINGULAR_SIGMA);
  u[BR_W3] = (1.0 - 1e3 * BRAID_ONE_MINUS_DW3_MIN) / m0.Delta;
  st = braid_rhs(u, &m0, f, ju, NULL);
  fin = 1;
  for (int i = 0; i < N; i++) fin &= isfinite(f[i]);
  for (int i = 0; i < N * N; i++) fin &= isfinite(ju[i]);
  test_true("1 - Delta omega3 = 1e3 ONE_MINUS_DW3_MIN is accepted with finite output",
            st == 0 && fin);

  memcpy(u, u0, sizeof u);
  u[BR_M2] = NAN;
  expect_guard_gp("M2 = NaN", u, &m0, BRAID_NONFINITE, BRAID_OK);
  u[BR_M2] = INFINITY;
  expect_guard_gp("M2 = Inf", u, &m0, BRAID_NONFINITE, BRAID_OK);
  memcpy(u, u0, sizeof u);
  u[BR_ETA] = NAN;
  expect_guard("eta = NaN", u, &m0, BRAID_NONFINITE);
  memcpy(u, u0, sizeof u);
  for (int i = BR_F1; i <= BR_M3; i++) u[i] = 1e300;
  expect_guard_gp("F, M = 1e300 (overflow in the products)", u, &m0, BRAID_NONFINITE, BRAID_OK);

  memcpy(u, u0, sizeof u);
  m = m0;
  m.Delta = 0.0;
  expect_guard("Delta = 0", u, &m, BRAID_BAD_MATERIAL);
  m = m0;
  m.B1 = -1.0;
  expect_guard("B1 = -1", u, &m, BRAID_BAD_MATERIAL);
  m = m0;
  m.C2 = NAN;
  expect_guard("C2 = NaN", u, &m, BRAID_BAD_MATERIAL);
  m = m0;
  m.w01 = INFINITY;
  expect_guard("w01 = Inf", u, &m, BRAID_BAD_MATERIAL);

  braid_gpartials gp;
  st = braid_g_partials(0.1, NAN, 0.0, 0.0, 0.0, 0.0, 0.0, &m0, &gp);
  test_true("braid_g_partials with eta' = NaN: BRAID_NONFINITE, zero outputs",
            st == BRAID_NONFINITE && gp.g == 0 && gp.dw3 == 0);
  double up[N], p1, p2;
  braid_rhs(u0, &m0, up, NULL, NULL);
  up[BR_W3] = NAN;
  st = braid_contact_pressure(u0, up, &m0, &p1, &p2);
  test_true("braid_contact_pressure with du/ds = NaN: BRAID_NONFINITE, zero outputs",
            st == BRAID_NONFINITE && p1 == 0 && p2 == 0);
}

int main(void)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 20240601);
  test_jacobians(r);
  test_fd_detects_error(r);
  test_func(r);
  test_consistency(r);
  test_symmetry(r);
  test_guards(r);
  gsl_rng_free(r);
  return test_summary();
}
