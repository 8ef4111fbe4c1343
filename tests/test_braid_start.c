/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Starting solutions (bc/braid_start.h) and the braid problems' STPNT/PVLS:
 *  - the two-ring solution against closed-form derivatives through braid_rhs,
 *    the link conditions at Phi = 0, the contact pressure, PVLS values;
 *  - the torus knot/link guesses: exactness of the kinematic and balance
 *    rows, the eta row against its first-order prediction from the fit
 *    residual, second-order (Delta^2) convergence of the residual, symmetric
 *    boundary values, mirror symmetry, the contact circle;
 *  - Newton polish by the collocation engine and the conditioning of the
 *    Newton matrix at the converged knot and link (phase condition, eps21,
 *    the symmetric variant, and the singular 23 printed conditions);
 *  - error paths. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "braid_bc.h"
#include "braid_integrals.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "abd_solver.h"
#include "cable/cable_constants.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"
#include "colloc_newton.h"
#include "colloc_system.h"
#include "harness.h"

static const double pi = 3.14159265358979323846;
static const double sqrt_half = 0.70710678118654752440;

/* The paper's parameters (Fig. 12.2 and Fig. 12.7). */
static const double knot_delta = 0.0051364907419, knot_ltot = 1.98889;
static const double link_delta = 0.016016913268, link_l = 1.0;

/* Ring state values are closed forms of O(1..100) numbers; the model's omega2'
 * and omega3' equations subtract terms of size |M|/Delta ~ 1e3 and divide by
 * B1 (resp. (cos eta/Delta)(B1 + B2 ...)), so their rounding is ~1e3 eps.
 * 1e-11 absolute (times max(1, |f|)) bounds all rows with a margin. */
static const double ring_rhs_tol = 1e-11;
/* Boundary residuals of exact constructions: arguments up to p pi ~ 22 and
 * division by speeds ~ 0.16 lose ~ 22/0.16 eps ~ 3e-14. */
static const double bc_exact_tol = 1e-13;
/* Kinematic/balance rows of the torus guess are exact: their difference-
 * quotient defect is the truncation (estimated, factor 2 for the estimate's
 * own error) plus rounding of u (~10 eps |u| from Fourier sums and the
 * Newton-solved arclength) times 1.5/dt from the five-point weights. */
static const double fd_est_factor = 2.0;
static const double fd_round_factor = 16.0;
/* The fit residual is O(eta^2) (second order in the braid angle); halving
 * Delta must divide it by 4 up to the O(eta^2) relative size of the next
 * term (~1% at the paper's eta ~ 0.11); 10% is ten times that. */
static const double order2_tol = 0.1;
/* Mirror images are computed by the same operations on sign-flipped inputs;
 * only the least-squares solve and Newton iterations may round differently. */
static const double mirror_tol = 1e-11;

/* ---------------------------------------------------------------- rings */

static void ring_exact_derivative(const braid_start_params *sp, double t, double *f)
{
  const double kappa = 1.0 / sp->rc, a = 1.0 - sp->delta * kappa, s = sp->l * t;
  const double th = kappa * s, ch = cos(th / 2), sh = sin(th / 2);
  for (int i = 0; i < BR_NDIM; i++) f[i] = 0.0;
  f[BR_XI1] = sp->torque / sp->c1 - sp->w01;
  f[BR_XI2] = a * (-sp->torque / sp->c2 + sp->w02);
  f[BR_Q1] = -sqrt_half * (-sh + ch) * kappa / 2;
  f[BR_Q2] = -sqrt_half * (-sh - ch) * kappa / 2;
  f[BR_X1] = sin(th);
  f[BR_Y1] = cos(th);
  f[BR_SIGMA] = a;
}

static void check_rings(const char *label, braid_start_params *sp)
{
  char what[200];
  snprintf(what, sizeof what, "%s: prepare", label);
  test_int(what, braid_start_prepare(sp), CABLE_SUCCESS);
  const double r = sp->length / (2 * pi);
  snprintf(what, sizeof what, "%s: R = L/(2 pi)", label);
  test_rel(what, sp->rc, r, 4 * DBL_EPSILON);
  snprintf(what, sizeof what, "%s: L2 = L - 2 pi Delta", label);
  test_rel(what, sp->l2, sp->length - 2 * pi * sp->delta, 8 * DBL_EPSILON);

  braid_material m = {sp->delta, sp->b1, sp->b2, sp->c1, sp->c2, sp->w01, sp->w02};
  double worst = 0.0, u[BR_NDIM], par[BP_NPAR], f[BR_NDIM], fe[BR_NDIM];
  int st = 0;
  for (int k = 0; k <= 10; k++) {
    const double t = k / 10.0;
    st |= braid_start_stpnt(BR_NDIM, t, u, par, sp);
    st |= braid_rhs(u, &m, f, NULL, NULL);
    ring_exact_derivative(sp, t, fe);
    for (int i = 0; i < BR_NDIM; i++) worst = fmax(worst, fabs(f[i] - fe[i]) / fmax(1.0, fabs(fe[i])));
  }
  snprintf(what, sizeof what, "%s: stpnt and braid_rhs succeed", label);
  test_int(what, st, 0);
  snprintf(what, sizeof what, "%s: braid_rhs(u) = closed-form u' at 11 points (max scaled err)", label);
  test_le(what, worst, ring_rhs_tol);

  /* the stpnt's parameters */
  braid_start_stpnt(BR_NDIM, 0.5, u, par, sp);
  snprintf(what, sizeof what, "%s: par L, L2, Delta, T, Phi = 0, w2fix = 0, eps = 0", label);
  test_true(what, par[BP_L] == sp->length && par[BP_L2] == sp->l2 && par[BP_DELTA] == sp->delta &&
                      par[BP_T] == sp->torque && par[BP_PHI] == 0 && par[BP_W2FIX] == 0 &&
                      par[BP_EPS21] == 0 && par[BP_EPS13] == 0 && par[BP_B2] == sp->b2 &&
                      par[BP_W02] == sp->w02);

  /* link conditions at Phi = 0 */
  double u0[BR_NDIM], u1[BR_NDIM], fb[BL_NBC], worst_bc = 0.0;
  braid_start_stpnt(BR_NDIM, 0.0, u0, par, sp);
  braid_start_stpnt(BR_NDIM, 1.0, u1, par, sp);
  snprintf(what, sizeof what, "%s: link BCs callable", label);
  test_int(what, braid_link_bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fb, NULL, NULL), 0);
  for (int i = 0; i < BL_NBC; i++) worst_bc = fmax(worst_bc, fabs(fb[i]));
  snprintf(what, sizeof what, "%s: link conditions (12.3.24-44) at Phi = 0, max |fb|", label);
  test_le(what, worst_bc, bc_exact_tol);

  /* contact pressure: two free rings do not touch (ring_dm3 = 0); an extra
   * M3 = dm3 is a hoop force N2 = -dm3/Delta in the inner ring, carried by a
   * pressure N2/(R - Delta) per unit sigma, i.e. dm3/(Delta R) per unit s. */
  double p1, p2;
  braid_start_stpnt(BR_NDIM, 0.3, u, par, sp);
  snprintf(what, sizeof what, "%s: contact pressure callable", label);
  test_int(what, braid_contact_pressure(u, NULL, &m, &p1, &p2), 0);
  const double dm3 = sp->ring_dm3;
  const double scale = (sp->b1 + sp->b2) / (sp->delta * r * r); /* |M|/(Delta R) */
  snprintf(what, sizeof what, "%s: pressure p1 = ring_dm3/(Delta R)", label);
  test_abs(what, p1, dm3 / (sp->delta * r), 1e-12 * scale);
  snprintf(what, sizeof what, "%s: pressure p2 = ring_dm3/(Delta (R - Delta))", label);
  test_abs(what, p2, dm3 / (sp->delta * (r - sp->delta)), 1e-12 * scale);

  /* PVLS against closed forms */
  cable_solution *sol = cable_solution_alloc(BR_NDIM, 4, 3, BP_NPAR, 1);
  for (int k = 0; k < cable_solution_npts(sol); k++) {
    sol->t[k] = (double)k / (cable_solution_npts(sol) - 1);
    braid_start_stpnt(BR_NDIM, sol->t[k], sol->u + k * BR_NDIM, sol->par, sp);
  }
  snprintf(what, sizeof what, "%s: pvls", label);
  test_int(what, braid_pvls(sol, sol->par, NULL), 0);
  const double kappa = 1 / r, a = 1 - sp->delta * kappa, tq = sp->torque;
  const double m1 = -tq - tq / a, f3 = kappa * m1;
  const double m3 = sp->b1 * kappa + sp->b2 * kappa / a + dm3;
  const double xi1p = tq / sp->c1 - sp->w01, xi2p = a * (-tq / sp->c2 + sp->w02);
  const double h = sp->b2 * kappa * kappa / (2 * a * a) +
                   sp->c2 / 2 * (xi2p * xi2p / (a * a) - sp->w02 * sp->w02) - dm3 / sp->delta;
  const double ge = 0.5 * (sp->b1 * kappa * kappa + sp->b2 * kappa * kappa / a +
                           sp->c1 * (xi1p + sp->w01) * (xi1p + sp->w01) +
                           sp->c2 * (xi2p * xi2p / a - 2 * sp->w02 * xi2p + sp->w02 * sp->w02 * a));
  const double ham = m3 * kappa + tq * xi1p - tq * xi2p - ge - h * a;
  snprintf(what, sizeof what, "%s: PVLS F = |kappa M1|", label);
  test_abs(what, sol->par[BP_F], fabs(f3), 1e-13 * fmax(1, fabs(f3)));
  snprintf(what, sizeof what, "%s: PVLS FM = F3 M3", label);
  test_abs(what, sol->par[BP_FM], f3 * m3, 1e-13 * fmax(1, fabs(f3 * m3)));
  snprintf(what, sizeof what, "%s: PVLS h (closed form)", label);
  test_abs(what, sol->par[BP_H], h, 1e-11 * fmax(1, fabs(h)));
  snprintf(what, sizeof what, "%s: PVLS Hamiltonian (closed form)", label);
  test_abs(what, sol->par[BP_HAM], ham, 1e-11 * fmax(1, fabs(ham)));
  snprintf(what, sizeof what, "%s: PVLS qnorm = |q(1)|^2 - 1", label);
  test_abs(what, sol->par[BP_QN], 0.0, 4 * DBL_EPSILON);
  cable_solution_free(sol);
}

/* ---------------------------------------------------------------- torus */

static int is_constitutive(int i) { return i == BR_ETA || i == BR_W2 || i == BR_W3; }

/* Five-point derivative of component i of the stpnt guess. */
static double fd_component(braid_start_params *sp, double t, double h, int i)
{
  double up[BR_NDIM], um[BR_NDIM], upp[BR_NDIM], umm[BR_NDIM], par[BP_NPAR];
  braid_start_stpnt(BR_NDIM, t + h, up, par, sp);
  braid_start_stpnt(BR_NDIM, t - h, um, par, sp);
  braid_start_stpnt(BR_NDIM, t + 2 * h, upp, par, sp);
  braid_start_stpnt(BR_NDIM, t - 2 * h, umm, par, sp);
  return (umm[i] - 8 * um[i] + 8 * up[i] - upp[i]) / (12 * h);
}

static void check_torus(const char *label, braid_start_params *sp, const char *pbname)
{
  char what[220];
  const int knot = sp->p % 2 == 1;
  snprintf(what, sizeof what, "%s: prepare", label);
  if (!test_int(what, braid_start_prepare(sp), CABLE_SUCCESS)) return;
  printf("     %s: rc = %.12g, L = %.12g, L2 = %.12g, fitted |F| = %.6g, h = %.6g\n", label, sp->rc,
         sp->l, sp->l2, hypot(hypot(sp->fin[0], sp->fin[1]), sp->fin[2]), sp->h);
  printf("     %s: fit residual max %.4e rms %.4e (moment units), QR rank ratio %.3f\n", label,
         sp->fit_max, sp->fit_rms, sp->fit_rcond);
  if (knot) {
    snprintf(what, sizeof what, "%s: L = Ltot/2", label);
    test_rel(what, sp->l, sp->length / 2, 1e-14);
    snprintf(what, sizeof what, "%s: L2 = L (equal strands by symmetry)", label);
    test_rel(what, sp->l2, sp->l, 1e-14);
  } else {
    snprintf(what, sizeof what, "%s: L = 1", label);
    test_rel(what, sp->l, sp->length, 1e-14);
    snprintf(what, sizeof what, "%s: L2 = L", label);
    test_rel(what, sp->l2, sp->l, 1e-14);
    snprintf(what, sizeof what, "%s: Phi = hand p pi", label);
    test_rel(what, sp->par[BP_PHI], sp->hand * sp->p * pi, 1e-15);
  }

  cable_problem pb;
  snprintf(what, sizeof what, "%s: instance of %s", label, pbname);
  test_int(what, braid_problem_instance(pbname, sp, &pb), CABLE_SUCCESS);
  braid_start_quality q;
  snprintf(what, sizeof what, "%s: quality evaluation", label);
  test_int(what, braid_start_quality_eval(&pb, 201, &q), 0);
  printf("     %s: ODE defect max|u' - f| = %.4e (eta %.4e, omega2 %.4e, omega3 %.4e), "
         "BC residual max|fb| = %.4e\n",
         label, q.ode_max, q.ode_comp[BR_ETA], q.ode_comp[BR_W2], q.ode_comp[BR_W3], q.bc_max);
  double worst_ratio = 0.0;
  int worst_i = -1;
  for (int i = 0; i < BR_NDIM; i++) {
    if (is_constitutive(i)) continue;
    const double bound = fd_est_factor * q.fd_err[i] +
                         fd_round_factor * DBL_EPSILON * fmax(q.u_scale[i], 1.0) / q.fd_step;
    if (q.ode_comp[i] / bound > worst_ratio) {
      worst_ratio = q.ode_comp[i] / bound;
      worst_i = i;
    }
  }
  snprintf(what, sizeof what,
           "%s: the 18 kinematic/balance/torque rows are exact: max defect/(FD error bound) (worst %s)",
           label, worst_i >= 0 ? pb.unames[worst_i] : "-");
  test_le(what, worst_ratio, 1.0);
  snprintf(what, sizeof what, "%s: boundary conditions of %s hold, max |fb|", label, pbname);
  test_le(what, q.bc_max, bc_exact_tol);
  if (knot) { /* the symmetric knot conditions too (adds F2(0) = 0) */
    cable_problem pbs;
    braid_problem_instance("braid_knot_sym", sp, &pbs);
    braid_start_quality qs;
    braid_start_quality_eval(&pbs, 11, &qs);
    snprintf(what, sizeof what, "%s: braid_knot_sym conditions hold (S0-symmetric guess), max |fb|", label);
    test_le(what, qs.bc_max, bc_exact_tol);
  }

  /* eta row: eta'(guess) - eta'(model) = -res0/(B2 c) per unit s, pointwise. */
  const braid_material m = {sp->delta, sp->b1, sp->b2, sp->c1, sp->c2, sp->w01, sp->w02};
  double worst_eta = 0.0, eta_bound = 0.0, cmin = INFINITY, res_max = 0.0, fdtol = 0.0;
  for (int k = 0; k <= 40; k++) {
    const double t = 0.01 + 0.98 * k / 40.0, hh = q.fd_step;
    double u[BR_NDIM], par[BP_NPAR], f[BR_NDIM], res[3];
    braid_start_stpnt(BR_NDIM, t, u, par, sp);
    braid_rhs(u, &m, f, NULL, NULL);
    braid_start_fit_residual(sp, t, res);
    const double c = cos(u[BR_ETA]) / (1 - sp->delta * u[BR_W3]);
    const double d1 = fd_component(sp, t, hh, BR_ETA), d2 = fd_component(sp, t, 2 * hh, BR_ETA);
    const double defect = d1 / sp->l - f[BR_ETA]; /* per unit s */
    worst_eta = fmax(worst_eta, fabs(defect + res[0] / (sp->b2 * c)));
    fdtol = fmax(fdtol, (fd_est_factor * fabs(d2 - d1) / 15 + fd_round_factor * DBL_EPSILON / hh) / sp->l);
    cmin = fmin(cmin, c);
    res_max = fmax(res_max, fabs(res[0]));
    for (int e = 0; e < 3; e++) eta_bound = fmax(eta_bound, fabs(res[e]));
  }
  snprintf(what, sizeof what,
           "%s: eta row defect = -res0/(B2 c) pointwise at 41 points (max diff; FD bound %.2e)", label, fdtol);
  test_le(what, worst_eta, fdtol + 1e-9);
  snprintf(what, sizeof what, "%s: fit residual at 41 points <= 1.05 x reported fit_max", label);
  test_le(what, eta_bound, 1.05 * sp->fit_max);
  snprintf(what, sizeof what, "%s: eta-row defect <= L max|res0|/(B2 min c) + FD error", label);
  test_le(what, q.ode_comp[BR_ETA], sp->l * res_max / (sp->b2 * cmin) * 1.05 + q.fd_err[BR_ETA] * 2);

  /* boundary values of the S0-symmetric guess */
  double u0[BR_NDIM], par[BP_NPAR];
  braid_start_stpnt(BR_NDIM, 0.0, u0, par, sp);
  snprintf(what, sizeof what, "%s: F2(0) = M2(0) = omega2(0) = w2fix = 0", label);
  test_le(what, fabs(u0[BR_F2]) + fabs(u0[BR_M2]) + fabs(u0[BR_W2]) + fabs(par[BP_W2FIX]), 1e-12);

  /* contact curve r1 + Delta/2 d1: a circle of radius rc about (Delta/2 + rc, 0, 0) */
  double worst_c = 0.0;
  for (int k = 0; k <= 50; k++) {
    double u[BR_NDIM];
    braid_start_stpnt(BR_NDIM, k / 50.0, u, par, sp);
    const double *qq = u + BR_Q0;
    const double d1[3] = {2 * qq[1] * qq[2] - 2 * qq[0] * qq[3],
                          qq[0] * qq[0] - qq[1] * qq[1] + qq[2] * qq[2] - qq[3] * qq[3],
                          2 * qq[2] * qq[3] + 2 * qq[0] * qq[1]};
    const double cx = u[BR_X1] + sp->delta / 2 * d1[0] - (sp->delta / 2 + sp->rc);
    const double cy = u[BR_Y1] + sp->delta / 2 * d1[1], cz = u[BR_Z1] + sp->delta / 2 * d1[2];
    worst_c = fmax(worst_c, fabs(sqrt(cx * cx + cy * cy + cz * cz) - sp->rc));
  }
  snprintf(what, sizeof what, "%s: contact curve is the circle of radius rc (max deviation)", label);
  test_le(what, worst_c, 1e-14);
}

/* Halving Delta divides the fit residual, the eta-row and the omega3-row
 * defects by 4 (second order in the braid angle).  The omega2 row is only
 * first order: the model solves (12.2.18) for omega2' after dividing by
 * k = Delta cos^2 eta/(Delta omega3 - 1) = O(Delta), so the O(Delta^2)
 * residual of that relation becomes an O(Delta) defect; its ratio lies
 * between 2 (first-order term dominating) and 4. */
static void check_order(const char *label, int p, double length)
{
  braid_start_params a, b;
  char what[200];
  braid_start_params_init(&a, BRAID_START_TORUS, p, 1, p % 2 ? knot_delta : link_delta, length, 0.0);
  b = a;
  b.delta = a.delta / 2;
  braid_start_prepare(&a);
  braid_start_prepare(&b);
  const double ratio = a.fit_max / b.fit_max;
  snprintf(what, sizeof what, "%s: fit residual ratio for Delta -> Delta/2 is 4 (second order)", label);
  test_rel(what, ratio, 4.0, order2_tol);
  cable_problem pa, pbb;
  braid_problem_instance(p % 2 ? "braid_knot" : "braid_link", &a, &pa);
  braid_problem_instance(p % 2 ? "braid_knot" : "braid_link", &b, &pbb);
  braid_start_quality qa, qb;
  braid_start_quality_eval(&pa, 101, &qa);
  braid_start_quality_eval(&pbb, 101, &qb);
  snprintf(what, sizeof what, "%s: eta-row ODE defect ratio for Delta -> Delta/2 is 4", label);
  test_rel(what, qa.ode_comp[BR_ETA] / qb.ode_comp[BR_ETA], 4.0, order2_tol);
  snprintf(what, sizeof what, "%s: omega3-row ODE defect ratio for Delta -> Delta/2 is 4", label);
  test_rel(what, qa.ode_comp[BR_W3] / qb.ode_comp[BR_W3], 4.0, order2_tol);
  const double r2 = qa.ode_comp[BR_W2] / qb.ode_comp[BR_W2];
  snprintf(what, sizeof what, "%s: omega2-row ODE defect ratio for Delta -> Delta/2 in [2, 4] (got %.4f)",
           label, r2);
  test_true(what, r2 >= 2.0 * (1 - order2_tol) && r2 <= 4.0 * (1 + order2_tol));
}

/* Mirror z -> -z maps (F, M, eta, omega, xi, T, q, r, sigma) to
 * (F1, F2, -F3, -M1, -M2, M3, -eta, -omega2, omega3, -xi1, -T1, -xi2, -T2,
 *  -q0, q1, q2, -q3, x, y, -z, sigma), and T, Phi, w2fix to their negatives. */
static void check_mirror(const char *label, int p, double delta, double length, double torque)
{
  static const double sign[BR_NDIM] = {1, 1, -1, -1, -1, 1, -1, -1, 1, -1, -1,
                                       -1, -1, -1, 1, 1, -1, 1, 1, -1, 1};
  braid_start_params r, l;
  braid_start_params_init(&r, BRAID_START_TORUS, p, 1, delta, length, torque);
  braid_start_params_init(&l, BRAID_START_TORUS, p, -1, delta, length, -torque);
  char what[200];
  snprintf(what, sizeof what, "%s: both hands prepare", label);
  test_true(what, braid_start_prepare(&r) == 0 && braid_start_prepare(&l) == 0);
  double worst = 0.0;
  for (int k = 0; k <= 20; k++) {
    double ur[BR_NDIM], ul[BR_NDIM], pr[BP_NPAR], pl[BP_NPAR];
    braid_start_stpnt(BR_NDIM, k / 20.0, ur, pr, &r);
    braid_start_stpnt(BR_NDIM, k / 20.0, ul, pl, &l);
    for (int i = 0; i < BR_NDIM; i++)
      worst = fmax(worst, fabs(ul[i] - sign[i] * ur[i]) / fmax(1.0, fabs(ur[i])));
    worst = fmax(worst, fabs(pl[BP_T] + pr[BP_T]) + fabs(pl[BP_PHI] + pr[BP_PHI]) +
                            fabs(pl[BP_W2FIX] + pr[BP_W2FIX]));
  }
  snprintf(what, sizeof what, "%s: left-handed at -T is the mirror image of right-handed at T", label);
  test_le(what, worst, mirror_tol);
  snprintf(what, sizeof what, "%s: mirror images have the same fit residual", label);
  test_rel(what, l.fit_max, r.fit_max, 1e-10);
}

/* ---------------------------------------------------------------- polish */

/* Mesh for the polish: NTST 50, NCOL 4 (converges in 3 Newton steps, ~0.1 s). */
enum { POLISH_NTST = 50, POLISH_NCOL = 4 };
/* Newton stop: AUTO's |dx_i| <= EPS (1 + |x_i|) with EPSL = EPSU = 1e-10. */
static const double polish_eps = 1e-10;
/* eps21 and eps13 are the residuals of conditions implied by the others, so
 * at a converged point they measure the discretisation error at the mesh
 * points, O(h^8) for NCOL = 4 (measured 4.8e-12 at NTST 50 and 2.1e-14 at
 * NTST 100, a ratio of 230 ~ 2^8); 1e-9 leaves a factor 200. */
static const double unfold_tol = 1e-9;
/* Singular-value separation.  All singular values of the h-scaled collocation
 * matrix scale like h, so the mesh-independent measure is sigma_1/sigma_2.
 * Measured at NTST 50/100/200/400: 0.65 (knot), 0.75 (link), 0.05 (sym), and
 * ~1e-6 for the 23 printed conditions (at the eigen-solver's resolution).
 * Thresholds: a regular problem must keep a ratio of O(1); the singular one
 * must be orders of magnitude below. */
static const double sv_regular_min = 0.1;
static const double sv_sym_min = 0.01;
static const double sv_singular_max = 1e-4;

/* The 23 printed knot conditions only: rows 0-22 of braid_knot, eps21 = 0. */
static int knot23_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                       const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)nbc;
  double p[BP_NPAR], fb24[BK_NBC], d24[BK_NBC * (2 * BR_NDIM + BP_NPAR)];
  memcpy(p, par, sizeof p);
  p[BP_EPS21] = 0.0;
  const int st = braid_knot_bcnd(ndim, p, icp, BK_NBC, u0, u1, ijac, fb24, d24, params);
  for (int i = 0; i < 23; i++) fb[i] = fb24[i];
  const int ncol = ijac >= 2 ? 2 * BR_NDIM + BP_NPAR : ijac == 1 ? 2 * BR_NDIM : 0;
  for (int j = 0; j < ncol; j++)
    for (int i = 0; i < 23; i++) dbc[i + 23 * j] = d24[i + BK_NBC * j];
  return st;
}

typedef struct {
  int status, iters;
  double sv[3];
  double par[BP_NPAR];
  double guess_dist; /* max_i max_t |u_i - guess_i| / max(1, max_t |u_i|) */
} polish_result;

/* Converge pb's STPNT guess with T fixed (x given: evaluate at x instead),
 * then the three smallest singular values of the Newton matrix. */
static void polish(const cable_problem *pb, const int *icp, int nfpr, double *x, int converge,
                   polish_result *out)
{
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.ndim = BR_NDIM; c.nbc = pb->nbc; c.nint = 0; c.ntst = POLISH_NTST; c.ncol = POLISH_NCOL;
  c.jac = 1; c.epsl = c.epsu = polish_eps; c.itnw = 20; c.nwtn = 20;
  memset(out, 0, sizeof *out);
  int st;
  colloc_system *s = colloc_system_alloc(pb, &c, POLISH_NTST, POLISH_NCOL, icp, nfpr, &st);
  if (s == NULL) { out->status = st; return; }
  colloc_system_uniform_mesh(s);
  s->closing = COLLOC_CLOSE_FIXPAR;
  const int npts = POLISH_NTST * POLISH_NCOL + 1;
  double *t = malloc(sizeof(double) * npts), *guess = malloc(sizeof(double) * s->n);
  colloc_system_times(s, t);
  for (int k = 0; k < npts; k++) pb->stpnt(BR_NDIM, t[k], guess + (size_t)k * BR_NDIM, s->par, pb->params);
  for (int i = 0; i < nfpr; i++) colloc_params(s, guess)[i] = s->par[icp[i]];
  s->fixval = s->par[icp[0]];
  if (converge) {
    memcpy(x, guess, sizeof(double) * s->n);
    colloc_newton *nw = colloc_newton_alloc(s, &c, &st);
    out->status = nw ? colloc_newton_solve(nw, x) : st;
    out->iters = nw ? colloc_newton_iterations(nw) : -1;
    colloc_newton_free(nw);
  }
  for (int i = 0; i < nfpr; i++) s->par[icp[i]] = colloc_params(s, x)[i];
  memcpy(out->par, s->par, sizeof out->par);
  for (int i = 0; i < BR_NDIM; i++) {
    double d = 0.0, m = 1.0;
    for (int k = 0; k < npts; k++) {
      d = fmax(d, fabs(x[k * BR_NDIM + i] - guess[k * BR_NDIM + i]));
      m = fmax(m, fabs(x[k * BR_NDIM + i]));
    }
    out->guess_dist = fmax(out->guess_dist, d / m);
  }
  colloc_jac *J = colloc_jac_alloc(BR_NDIM, POLISH_NTST, POLISH_NCOL, nfpr, pb->nbc, 0);
  abd_solver *as = abd_solver_alloc(BR_NDIM, POLISH_NTST, POLISH_NCOL, nfpr, pb->nbc, 0);
  double *vecs = malloc(sizeof(double) * s->n * 3);
  st = colloc_system_jacobian(s, x, J);
  if (st == 0) st = abd_solver_factor(as, J);
  if (st == 0) st = abd_solver_smallest_sv(as, J, 3, out->sv, vecs, 300, 1e-12);
  if (st != 0 && out->status == 0) out->status = st;
  free(vecs);
  abd_solver_free(as);
  colloc_jac_free(J);
  free(guess);
  free(t);
  colloc_system_free(s);
}

static void check_polish(void)
{
  braid_start_params sk, sl;
  braid_start_params_init(&sk, BRAID_START_TORUS, 7, 1, knot_delta, knot_ltot, 0.0);
  braid_start_params_init(&sl, BRAID_START_TORUS, 6, 1, link_delta, link_l, 0.0);
  braid_start_prepare(&sk);
  braid_start_prepare(&sl);
  cable_problem pk, ps, pl;
  braid_problem_instance("braid_knot", &sk, &pk);
  braid_problem_instance("braid_knot_sym", &sk, &ps);
  braid_problem_instance("braid_link", &sl, &pl);
  const int icp[5] = {BP_T, BP_L, BP_L2, BP_EPS21, BP_EPS13};
  const size_t n = (size_t)BR_NDIM * (POLISH_NTST * POLISH_NCOL + 1) + 5;
  double *x = malloc(sizeof(double) * n);
  polish_result r;
  char what[200];

  polish(&pk, icp, 4, x, 1, &r);
  snprintf(what, sizeof what, "braid_knot: Newton from the (7,2) guess converges (%d iterations)", r.iters);
  test_int(what, r.status, 0);
  printf("     braid_knot: max relative distance guess -> solution %.3e; L = %.12g, L2 = %.12g\n",
         r.guess_dist, r.par[BP_L], r.par[BP_L2]);
  test_le("braid_knot: |eps21| at the converged knot", fabs(r.par[BP_EPS21]), unfold_tol);
  test_rel("braid_knot: L + L2 = Ltot", r.par[BP_L] + r.par[BP_L2], knot_ltot, 1e-12);
  snprintf(what, sizeof what, "braid_knot: sigma1/sigma2 of the Newton matrix (sv %.3e %.3e %.3e) is O(1)",
           r.sv[0], r.sv[1], r.sv[2]);
  test_true(what, r.sv[0] / r.sv[1] >= sv_regular_min);

  /* The same converged solution, only the 23 printed conditions (T, L, L2 free):
   * x keeps T, L, L2 in the same slots, eps21 is dropped. */
  cable_problem p23 = pk;
  p23.nbc = 23;
  p23.bcnd = knot23_bcnd;
  polish_result r23;
  polish(&p23, icp, 3, x, 0, &r23);
  snprintf(what, sizeof what,
           "23 printed conditions at that knot: sigma1/sigma2 (sv %.3e %.3e) is tiny (singular)",
           r23.sv[0], r23.sv[1]);
  test_true(what, r23.status == 0 && r23.sv[0] / r23.sv[1] <= sv_singular_max);

  polish(&ps, icp, 5, x, 1, &r);
  snprintf(what, sizeof what, "braid_knot_sym: Newton converges (%d iterations)", r.iters);
  test_int(what, r.status, 0);
  test_le("braid_knot_sym: |eps21|", fabs(r.par[BP_EPS21]), unfold_tol);
  test_le("braid_knot_sym: |eps13|", fabs(r.par[BP_EPS13]), unfold_tol);
  snprintf(what, sizeof what, "braid_knot_sym: sigma1/sigma2 (sv %.3e %.3e %.3e) >= %g", r.sv[0], r.sv[1],
           r.sv[2], sv_sym_min);
  test_true(what, r.sv[0] / r.sv[1] >= sv_sym_min);

  polish(&pl, icp, 1, x, 1, &r);
  snprintf(what, sizeof what, "braid_link: Newton from the (6,2) guess converges (%d iterations)", r.iters);
  test_int(what, r.status, 0);
  printf("     braid_link: max relative distance guess -> solution %.3e\n", r.guess_dist);
  snprintf(what, sizeof what, "braid_link: sigma1/sigma2 (sv %.3e %.3e %.3e) is O(1)", r.sv[0], r.sv[1], r.sv[2]);
  test_true(what, r.sv[0] / r.sv[1] >= sv_regular_min);
  free(x);
}

/* ---------------------------------------------------------------- errors */

static void check_errors(void)
{
  braid_start_params sp;
  double u[BR_NDIM], par[BP_NPAR];
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, 1, knot_delta, knot_ltot, 0);
  test_int("stpnt before prepare is fatal", braid_start_stpnt(BR_NDIM, 0.5, u, par, &sp), -1);
  test_int("stpnt with params NULL is fatal", braid_start_stpnt(BR_NDIM, 0.5, u, par, NULL), -1);
  cable_problem pb;
  test_int("instance with an unprepared start is refused", braid_problem_instance("braid_knot", &sp, &pb),
           CABLE_ERR_INPUT);
  test_int("prepare(NULL)", braid_start_prepare(NULL), CABLE_ERR_INPUT);
  braid_start_prepare(&sp);
  test_int("stpnt with ndim != 21 is fatal", braid_start_stpnt(20, 0.5, u, par, &sp), -1);
  test_int("unknown problem name", braid_problem_instance("braid_trefoil", &sp, &pb), CABLE_ERR_NOTFOUND);
  test_int("instance into NULL", braid_problem_instance("braid_link", &sp, NULL), CABLE_ERR_INPUT);
  test_int("instance without a start (restart from a stored solution)",
           braid_problem_instance("braid_link", NULL, &pb), CABLE_SUCCESS);
  test_true("... has params NULL and the link dimensions", pb.params == NULL && pb.nbc == 21);
  test_true("braid_problem_find(NULL) is NULL", braid_problem_find(NULL) == NULL);
  double res[3];
  braid_start_params ring;
  braid_start_params_init(&ring, BRAID_START_RINGS, 0, 1, link_delta, 1.0, 0);
  braid_start_prepare(&ring);
  test_int("fit residual of a ring start is refused", braid_start_fit_residual(&ring, 0.5, res),
           CABLE_ERR_INPUT);

  const struct { const char *what; int p, hand; double delta, length; int want; } bad[] = {
    {"torus p = 0", 0, 1, knot_delta, knot_ltot, CABLE_ERR_INPUT},
    {"torus hand = 0", 7, 0, knot_delta, knot_ltot, CABLE_ERR_INPUT},
    {"Delta <= 0", 7, 1, 0.0, knot_ltot, CABLE_ERR_INPUT},
    {"length <= 0", 7, 1, knot_delta, -1.0, CABLE_ERR_INPUT},
    {"Delta NaN", 7, 1, NAN, knot_ltot, CABLE_ERR_INPUT},
    {"Delta >= contact radius (p = 1, rc = 0.149)", 1, 1, 0.2, 2.0, CABLE_ERR_INPUT},
    {"length shorter than the winding allows (no radius)", 7, 1, 0.5, knot_ltot, CABLE_ERR_NEWTON},
    {"braid too thick for the Fourier grid (Delta = 0.9 rc)", 1, 1, 0.135, 1.94, CABLE_ERR_UNSUPPORTED},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    braid_start_params_init(&sp, BRAID_START_TORUS, bad[k].p, bad[k].hand, bad[k].delta, bad[k].length, 0);
    char what[160];
    snprintf(what, sizeof what, "prepare refuses: %s", bad[k].what);
    test_int(what, braid_start_prepare(&sp), bad[k].want);
    test_true("... and stays unprepared", sp.ready == 0);
  }
  braid_start_params_init(&sp, BRAID_START_RINGS, 0, 1, 0.2, 1.0, 0);
  test_int("rings refuse R <= Delta", braid_start_prepare(&sp), CABLE_ERR_INPUT);
  braid_start_params_init(&sp, (braid_start_kind)7, 0, 1, 0.01, 1.0, 0);
  test_int("unknown start kind", braid_start_prepare(&sp), CABLE_ERR_INPUT);

  braid_start_quality q;
  test_int("quality: NULL problem", braid_start_quality_eval(NULL, 11, &q), CABLE_ERR_INPUT);
  braid_problem_instance("braid_link", &ring, &pb);
  test_int("quality: npts < 2", braid_start_quality_eval(&pb, 1, &q), CABLE_ERR_INPUT);
  pb.params = NULL; /* the stpnt now fails fatally */
  test_int("quality: a fatal stpnt is reported", braid_start_quality_eval(&pb, 11, &q), CABLE_ERR_CALLBACK);

  cable_solution *bad_sol = cable_solution_alloc(3, 2, 2, BP_NPAR, 1);
  test_int("pvls refuses a solution with ndim != 21", braid_pvls(bad_sol, bad_sol->par, NULL), -1);
  cable_solution_free(bad_sol);
}

int main(void)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_RINGS, 0, 1, link_delta, link_l, 0.0);
  check_rings("rings (paper link Delta, L = 1, T = 0)", &sp);
  braid_start_params_init(&sp, BRAID_START_RINGS, 0, 1, 0.02, 1.3, 3.0);
  sp.b2 = 1.4; sp.c1 = 0.6; sp.c2 = 0.9; sp.w01 = 0.7; sp.w02 = -0.4; sp.ring_dm3 = 0.25;
  check_rings("rings (T = 3, unequal strands, intrinsic twist, contact load)", &sp);

  braid_start_params_init(&sp, BRAID_START_TORUS, 7, 1, knot_delta, knot_ltot, 0.0);
  check_torus("(7,2) knot right-handed", &sp, "braid_knot");
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, -1, knot_delta, knot_ltot, 0.0);
  check_torus("(7,2) knot left-handed", &sp, "braid_knot");
  braid_start_params_init(&sp, BRAID_START_TORUS, 6, 1, link_delta, link_l, 0.0);
  check_torus("(6,2) link right-handed", &sp, "braid_link");
  braid_start_params_init(&sp, BRAID_START_TORUS, 6, -1, link_delta, link_l, 0.0);
  check_torus("(6,2) link left-handed", &sp, "braid_link");
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, 1, knot_delta, knot_ltot, -4.0);
  sp.w01 = 0.3; sp.w02 = 0.3;
  check_torus("(7,2) knot, T = -4, intrinsic twist", &sp, "braid_knot");

  check_order("(7,2) knot", 7, knot_ltot);
  check_order("(6,2) link", 6, link_l);
  check_mirror("(7,2) knot", 7, knot_delta, knot_ltot, 2.0);
  check_mirror("(6,2) link", 6, link_delta, link_l, 1.5);
  check_polish();
  check_errors();
  return test_summary();
}
