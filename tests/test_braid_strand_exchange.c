/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Strand exchange (equations/braid_exchange.h, doc/links.md "Strand exchange"):
 * the braid seen with s along strand 2 must solve the same equations and, for
 * a link, the same conditions with the same T.
 *
 * 1. The ODEs are equivariant: for w(s) = X(u(s)), dw/dsigma computed from
 *    braid_rhs(u) through the map equals braid_rhs(w), at random states of the
 *    physical domain (an identity of the model, not of one solution).
 * 2. At a buckled (6,2) link of Fig. 12.7's branch (tests/data/s.link62_buckled,
 *    written by scripts/link_readings.sh), the same identity at every stored
 *    point, and the mapped end states satisfy the 21 link conditions with
 *    T_n = T, L_n = L2, L2_n = L and the phase w2fix_n = omega2_n(0); |F|, h
 *    and T1 - T2 are the same. */
#include <math.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "braid_bc.h"
#include "braid_exchange.h"
#include "cable/cable_error.h"
#include "braid_random.h"
#include "harness.h"

/* Derivative of the map along the flow by Richardson-extrapolated central
 * differences, D = (4 D(h/2) - D(h))/3 with h = 1e-5 (in s).  Measured at one
 * random state: the plain central difference's error falls as h^2 from
 * h = 1e-2 to 1e-5 in every component (largest 6.8e5 h^2, on F1' ~ 3e3), so
 * after extrapolation truncation is far below rounding, eps |w| / h ~ 1e-8
 * absolute on |w| ~ 1e3 (~1e-11 relative).  A component error of
 * 1e-7 * max(1, |f_i|, |w_i|) leaves a factor 1e3 over rounding and is far
 * below any wrong sign or factor (those give O(1) relative errors). */
static const double fd_h = 1e-5;
static const double equiv_tol = 1e-7;
/* The stored solution solves the collocation equations: its end states
 * satisfy the link rows to the Newton tolerance (EPSL = EPSU = 1e-7 scaled),
 * and closure after the map holds to the solution's discretisation error
 * (err est. ~1e-4 at NTST 100 for link62, doc/links.md).  1e-5 absolute on the
 * O(1) rows; a wrong map misses them by O(1e-2..1). */
static const double bc_tol = 1e-5;
enum { NRANDOM = 200 };

/* the tests' random numbers (tests/braid_random.h) */
static test_rng rng = {0x9E3779B97F4A7C15u};

/* dw/dsigma at u (arclength s) by Richardson-extrapolated central differences */
static int map_derivative(const double *u, double s, const braid_material *m,
                          const braid_exchange_frame *g, double *dw)
{
  double f[BR_NDIM], up[BR_NDIM], um[BR_NDIM], wp[BR_NDIM], wm[BR_NDIM], d1[BR_NDIM];
  int st = braid_rhs(u, m, f, NULL, NULL);
  braid_aux aux;
  st |= braid_aux_eval(u, m, &aux);
  for (int pass = 0; pass < 2; pass++) {
    const double h = pass == 0 ? fd_h : 0.5 * fd_h;
    for (int i = 0; i < BR_NDIM; i++) {
      up[i] = u[i] + h * f[i];
      um[i] = u[i] - h * f[i];
    }
    st |= braid_exchange_state(up, s + h, m, g, wp);
    st |= braid_exchange_state(um, s - h, m, g, wm);
    for (int i = 0; i < BR_NDIM; i++) {
      const double d = (wp[i] - wm[i]) / (2 * h) / aux.sigmap;
      if (pass == 0) d1[i] = d;
      else dw[i] = (4 * d - d1[i]) / 3;
    }
  }
  return st;
}

/* max over components of |dw_i - f(w)_i| / max(1, |f(w)_i|, |w_i|) */
static double equivariance_error(const double *u, double s, const braid_material *m,
                                 const braid_exchange_frame *g, int *status)
{
  double w[BR_NDIM], fw[BR_NDIM], dw[BR_NDIM];
  int st = braid_exchange_state(u, s, m, g, w);
  st |= braid_rhs(w, m, fw, NULL, NULL);
  st |= map_derivative(u, s, m, g, dw);
  *status |= st;
  double worst = 0.0;
  for (int i = 0; i < BR_NDIM; i++)
    worst = fmax(worst, fabs(dw[i] - fw[i]) / fmax(1.0, fmax(fabs(fw[i]), fabs(w[i]))));
  return worst;
}

static void check_random_states(void)
{
  const braid_material m = {0.016016913268, 1.0, 1.0, 1.0 / 1.3, 1.0 / 1.3, 0.0, 0.0};
  double worst = 0.0;
  int st = 0;
  for (int n = 0; n < NRANDOM; n++) {
    double u[BR_NDIM];
    for (int i = 0; i < BR_NDIM; i++) u[i] = test_rng_uniform(&rng, -3.0, 3.0);
    u[BR_F1] = test_rng_uniform(&rng, -400, 400); u[BR_F2] = test_rng_uniform(&rng, -400, 400); u[BR_F3] = test_rng_uniform(&rng, -400, 400);
    u[BR_M1] = test_rng_uniform(&rng, -60, 60); u[BR_M2] = test_rng_uniform(&rng, -60, 60); u[BR_M3] = test_rng_uniform(&rng, -60, 60);
    u[BR_ETA] = test_rng_uniform(&rng, -0.5, 0.5);
    u[BR_W2] = test_rng_uniform(&rng, -20, 20); u[BR_W3] = test_rng_uniform(&rng, -20, 20);
    u[BR_T1] = test_rng_uniform(&rng, -15, 15); u[BR_T2] = test_rng_uniform(&rng, -15, 15);
    double qn = 0.0;
    for (int i = 0; i < 4; i++) qn += u[BR_Q0 + i] * u[BR_Q0 + i];
    for (int i = 0; i < 4; i++) u[BR_Q0 + i] /= sqrt(qn);
    braid_exchange_frame g;
    st |= braid_exchange_frame_at(u, &m, &g);
    worst = fmax(worst, equivariance_error(u, test_rng_uniform(&rng, 0, 1), &m, &g, &st));
  }
  test_int("strand exchange: map and rhs defined at the random states", st, 0);
  test_le("strand exchange: dX(u)/dsigma = f(X(u)) at 200 random states (max scaled err)", worst,
          equiv_tol);

  /* the map is not the identity in disguise: it fails for a wrong sign of
     the moment shift (M about r1 instead of r2) */
  double u[BR_NDIM];
  for (int i = 0; i < BR_NDIM; i++) u[i] = test_rng_uniform(&rng, -1.0, 1.0);
  u[BR_F1] = 300.0; u[BR_F3] = -200.0; u[BR_ETA] = 0.2; u[BR_W3] = 5.0;
  double qn = 0.0;
  for (int i = 0; i < 4; i++) qn += u[BR_Q0 + i] * u[BR_Q0 + i];
  for (int i = 0; i < 4; i++) u[BR_Q0 + i] /= sqrt(qn);
  braid_exchange_frame g;
  braid_exchange_frame_at(u, &m, &g);
  double w[BR_NDIM], fw[BR_NDIM], dw[BR_NDIM];
  braid_exchange_state(u, 0.3, &m, &g, w);
  w[BR_M1] += m.Delta * u[BR_F3]; /* undo part of the shift */
  braid_rhs(w, &m, fw, NULL, NULL);
  map_derivative(u, 0.3, &m, &g, dw);
  double bad = 0.0;
  for (int i = 0; i < BR_NDIM; i++)
    bad = fmax(bad, fabs(dw[i] - fw[i]) / fmax(1.0, fmax(fabs(fw[i]), fabs(w[i]))));
  test_true("strand exchange: a wrong moment shift is detected (error > 1e3 tol)", bad > 1e3 * equiv_tol);
}

static void check_buckled_link(void)
{
  cable_error err;
  cable_sfile *sf = cable_sfile_read("tests/data/s.link62_buckled", &err);
  if (!test_true("strand exchange: tests/data/s.link62_buckled read", sf != NULL)) return;
  const cable_solution *sol = cable_sfile_get(sf, 0);
  braid_material m;
  braid_material_from_par(sol->par, &m);
  const int npts = cable_solution_npts(sol);
  const double L = sol->par[BP_L];
  const double *u0 = sol->u, *u1 = sol->u + (size_t)(npts - 1) * BR_NDIM;
  braid_exchange_frame g;
  int st = braid_exchange_frame_at(u0, &m, &g);
  double worst = 0.0;
  for (int k = 0; k < npts; k++)
    worst = fmax(worst, equivariance_error(sol->u + (size_t)k * BR_NDIM, L * sol->t[k], &m, &g, &st));
  test_int("strand exchange (buckled link): map defined at every stored point", st, 0);
  test_le("strand exchange (buckled link): dX(u)/dsigma = f(X(u)) at every stored point", worst,
          equiv_tol);

  /* mapped ends: new s runs along sigma, so the new start is X(u(0)) and the new
     end X(u(L)); new L = old L2 (= sigma(L)), new L2 = old L */
  double w0[BR_NDIM], w1[BR_NDIM], par[BP_NPAR], fb[BL_NBC];
  st = braid_exchange_state(u0, 0.0, &m, &g, w0);
  st |= braid_exchange_state(u1, L, &m, &g, w1);
  memcpy(par, sol->par, sizeof par);
  par[BP_L] = sol->par[BP_L2];
  par[BP_L2] = L;
  par[BP_W2FIX] = w0[BR_W2];
  st |= braid_link_bcnd(BR_NDIM, par, NULL, BL_NBC, w0, w1, 0, fb, NULL, NULL);
  double worst_bc = 0.0, worst_orig = 0.0;
  for (int i = 0; i < BL_NBC; i++) worst_bc = fmax(worst_bc, fabs(fb[i]));
  st |= braid_link_bcnd(BR_NDIM, sol->par, NULL, BL_NBC, u0, u1, 0, fb, NULL, NULL);
  for (int i = 0; i < BL_NBC; i++) worst_orig = fmax(worst_orig, fabs(fb[i]));
  test_int("strand exchange (buckled link): conditions evaluated", st, 0);
  test_le("strand exchange (buckled link): the stored solution meets the 21 link rows", worst_orig, bc_tol);
  test_le("strand exchange (buckled link): the mapped solution meets them with T_n = T", worst_bc, bc_tol);
  const double F = sqrt(u0[BR_F1] * u0[BR_F1] + u0[BR_F2] * u0[BR_F2] + u0[BR_F3] * u0[BR_F3]);
  const double Fn = sqrt(w0[BR_F1] * w0[BR_F1] + w0[BR_F2] * w0[BR_F2] + w0[BR_F3] * w0[BR_F3]);
  test_rel("strand exchange (buckled link): |F| is the same", Fn, F, 1e-13);
  braid_aux a0, an;
  braid_aux_eval(u0, &m, &a0);
  braid_aux_eval(w0, &m, &an);
  /* h multiplies strand 2's length; after the exchange it multiplies old
     strand 1's, which the old description does not constrain: the mapped h is
     the old Hamiltonian (PVLS slot Ham, stored to 11 digits; 1e-9 covers the
     stored digits and the Ham formula's rounding at |Ham| ~ 700) */
  printf("# buckled link: T = %.10g, F = %.10g, h = %.10g, mapped h = %.10g, Ham = %.10g, "
         "w2fix_n = %.10g\n", sol->par[BP_T], F, a0.h, an.h, sol->par[BP_HAM], w0[BR_W2]);
  test_rel("strand exchange (buckled link): the mapped h is the stored Hamiltonian", an.h,
           sol->par[BP_HAM], 1e-9);
  test_rel("strand exchange (buckled link): T1_n(0) = T", w0[BR_T1], sol->par[BP_T], 1e-12);
  test_rel("strand exchange (buckled link): T2_n(0) = -T", w0[BR_T2], -sol->par[BP_T], 1e-12);
  cable_sfile_free(sf);
}

int main(void)
{
  check_random_states();
  check_buckled_link();
  return test_summary();
}
