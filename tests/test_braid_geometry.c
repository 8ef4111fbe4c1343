/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Braid solutions built from exact ribbon geometry: sampling (braid_curves),
 * contact curvature, Tw/Wr/Lk of the braid ribbon and the topology summary.
 *
 * A synthetic cable_solution is built from a contact curve c(theta) with a unit
 * normal d(theta): r1 = c - (Delta/2) d, r2 = c + (Delta/2) d, t1 = r1'/|r1'|,
 * d1 = d, u1 = t1 x d1, q from the frame; the stored points are uniform in
 * s = L t, found by inverting s(theta) = \int |r1'| (GSL QAG, rel. 1e-13).
 * Only the geometric state components are filled.
 *
 * Tolerances: the stored solution is interpolated by degree-ncol polynomials,
 * so positions are accurate to O(h^(ncol+1)) and tangents to O(h^ncol); Tw
 * and Wr inherit O(h^ncol).  Each check states the bound it uses; the
 * convergence checks verify the order itself. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>

#include "braid_geometry.h"
#include "braid_state.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "ribbon.h"
#include "tube_distance.h"

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* ---- exact ribbons: curve c with frame normal nu (perpendicular to c'),
 * and d = cos(psi) nu + sin(psi) T x nu with psi = k theta ---- */
typedef struct {
  int kind;            /* 0: circle of radius R, 1: torus knot T(p,q) on (R, a),
                          2: lemniscate (R cos, R sin 2th / 2, a sin th), crossing itself at
                          the origin at height 2a, with the blackboard normal */
  double R, a, k;
  int p, q;
  double hand;
} ribbon_def;

/* c, c', c'' and nu, nu' at theta */
static void axis_eval(const ribbon_def *rd, double th, double c[3], double dc[3], double d2c[3],
                      double nu[3], double dnu[3])
{
  if (rd->kind == 2) {
    /* nu = P/|P|, P = e_z - (e_z.T) T: the normal of the blackboard framing
     * (the xy-projection), so Lk = (writhe of the diagram) + turns of d */
    double cs = cos(th), sn = sin(th), c2 = cos(2 * th), s2 = sin(2 * th), R = rd->R, a = rd->a;
    c[0] = R * cs; c[1] = 0.5 * R * s2; c[2] = a * sn;
    dc[0] = -R * sn; dc[1] = R * c2; dc[2] = a * cs;
    d2c[0] = -R * cs; d2c[1] = -2 * R * s2; d2c[2] = -a * sn;
    double sp = sqrt(dot(dc, dc)), T[3], Tt[3], P[3], Pt[3];
    for (int i = 0; i < 3; i++) T[i] = dc[i] / sp;
    double tc = dot(T, d2c);
    for (int i = 0; i < 3; i++) Tt[i] = (d2c[i] - tc * T[i]) / sp;
    for (int i = 0; i < 3; i++) {
      P[i] = (i == 2) - T[2] * T[i];
      Pt[i] = -Tt[2] * T[i] - T[2] * Tt[i];
    }
    double pn = sqrt(dot(P, P)), pp = dot(P, Pt) / pn;
    for (int i = 0; i < 3; i++) {
      nu[i] = P[i] / pn;
      dnu[i] = (Pt[i] - pp * nu[i]) / pn;
    }
  } else if (rd->kind == 0) {
    double cs = cos(th), sn = sin(th);
    c[0] = rd->R * cs; c[1] = rd->R * sn; c[2] = 0;
    dc[0] = -rd->R * sn; dc[1] = rd->R * cs; dc[2] = 0;
    d2c[0] = -rd->R * cs; d2c[1] = -rd->R * sn; d2c[2] = 0;
    nu[0] = cs; nu[1] = sn; nu[2] = 0;
    dnu[0] = -sn; dnu[1] = cs; dnu[2] = 0;
  } else {
    double P = rd->p, Q = rd->q, m = -rd->hand;
    double cp = cos(P * th), sp = sin(P * th), cq = cos(Q * th), sq = sin(Q * th);
    double rho = rd->R + rd->a * cq, drho = -rd->a * Q * sq, d2rho = -rd->a * Q * Q * cq;
    c[0] = rho * cp; c[1] = rho * sp; c[2] = m * rd->a * sq;
    dc[0] = drho * cp - rho * P * sp;
    dc[1] = drho * sp + rho * P * cp;
    dc[2] = m * rd->a * Q * cq;
    d2c[0] = d2rho * cp - 2 * drho * P * sp - rho * P * P * cp;
    d2c[1] = d2rho * sp + 2 * drho * P * cp - rho * P * P * sp;
    d2c[2] = -m * rd->a * Q * Q * sq;
    nu[0] = cq * cp; nu[1] = cq * sp; nu[2] = m * sq;
    dnu[0] = -Q * sq * cp - P * cq * sp;
    dnu[1] = -Q * sq * sp + P * cq * cp;
    dnu[2] = m * Q * cq;
  }
}

static int ribbon_exact(double th, double r[3], double dr[3], double d[3], double dd[3], void *params)
{
  const ribbon_def *rd = params;
  double d2c[3], nu[3], dnu[3];
  axis_eval(rd, th, r, dr, d2c, nu, dnu);
  if (!d) return 0;
  double sp = sqrt(dot(dr, dr)), T[3], Tt[3], b[3], db[3], x[3];
  for (int i = 0; i < 3; i++) T[i] = dr[i] / sp;
  double tc = dot(T, d2c);
  for (int i = 0; i < 3; i++) Tt[i] = (d2c[i] - tc * T[i]) / sp;
  cross(T, nu, b);
  cross(Tt, nu, db);
  cross(T, dnu, x);
  for (int i = 0; i < 3; i++) db[i] += x[i];
  double psi = rd->k * th, c = cos(psi), s = sin(psi);
  for (int i = 0; i < 3; i++) {
    d[i] = c * nu[i] + s * b[i];
    dd[i] = rd->k * (-s * nu[i] + c * b[i]) + c * dnu[i] + s * db[i];
  }
  return 0;
}

typedef struct { const ribbon_def *rd; double delta, sgn; } speed_par;

/* |r1'| (sgn = -1) or |r2'| (sgn = +1) */
static double strand_speed(double th, void *params)
{
  const speed_par *sp = params;
  double c[3], dc[3], d[3], dd[3];
  ribbon_exact(th, c, dc, d, dd, (void *)sp->rd);
  double v[3];
  for (int i = 0; i < 3; i++) v[i] = dc[i] + sp->sgn * 0.5 * sp->delta * dd[i];
  return sqrt(dot(v, v));
}

static double integrate(double (*f)(double, void *), void *par, double a, double b,
                        gsl_integration_workspace *w)
{
  gsl_function F = {f, par};
  double res, err;
  if (b <= a) return 0.0;
  gsl_integration_qag(&F, a, b, 0.0, 1e-13, 1000, GSL_INTEG_GAUSS61, w, &res, &err);
  return res;
}

static void quat_from_frame(const double *t1, const double *d1, const double *u1, const double *prev, double *q)
{
  /* R = (t1 | d1 | u1), R_ij row i column j; Shepperd's branch choice */
  double R[3][3];
  for (int i = 0; i < 3; i++) { R[i][0] = t1[i]; R[i][1] = d1[i]; R[i][2] = u1[i]; }
  double tr = R[0][0] + R[1][1] + R[2][2];
  if (tr > 0) {
    double S = 2 * sqrt(tr + 1);
    q[0] = S / 4; q[1] = (R[2][1] - R[1][2]) / S; q[2] = (R[0][2] - R[2][0]) / S; q[3] = (R[1][0] - R[0][1]) / S;
  } else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
    double S = 2 * sqrt(1 + R[0][0] - R[1][1] - R[2][2]);
    q[0] = (R[2][1] - R[1][2]) / S; q[1] = S / 4; q[2] = (R[0][1] + R[1][0]) / S; q[3] = (R[0][2] + R[2][0]) / S;
  } else if (R[1][1] > R[2][2]) {
    double S = 2 * sqrt(1 + R[1][1] - R[0][0] - R[2][2]);
    q[0] = (R[0][2] - R[2][0]) / S; q[1] = (R[0][1] + R[1][0]) / S; q[2] = S / 4; q[3] = (R[1][2] + R[2][1]) / S;
  } else {
    double S = 2 * sqrt(1 + R[2][2] - R[0][0] - R[1][1]);
    q[0] = (R[1][0] - R[0][1]) / S; q[1] = (R[0][2] + R[2][0]) / S; q[2] = (R[1][2] + R[2][1]) / S; q[3] = S / 4;
  }
  if (prev && q[0] * prev[0] + q[1] * prev[1] + q[2] * prev[2] + q[3] * prev[3] < 0)
    for (int i = 0; i < 4; i++) q[i] = -q[i];
}

/* theta at each stored point; also returns the solution */
static cable_solution *build_solution(const ribbon_def *rd, double delta, int ntst, int ncol, double *theta_out)
{
  cable_solution *sol = cable_solution_alloc(BR_NDIM, ntst, ncol, BP_NPAR, 1);
  gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
  speed_par s1 = {rd, delta, -1.0}, s2 = {rd, delta, 1.0};
  double L = integrate(strand_speed, &s1, 0, 2 * M_PI, w);
  int np = cable_solution_npts(sol);
  double th = 0, s_th = 0, sig = 0, th_prev = 0, qprev[4];
  for (int k = 0; k < np; k++) {
    double t = (double)k / (np - 1), target = L * t;
    if (k == np - 1) th = 2 * M_PI;
    else
      for (int it = 0; it < 50; it++) {    /* Newton on s(theta) = target */
        double f = s_th + integrate(strand_speed, &s1, th_prev, th, w) - target;
        if (fabs(f) < 1e-14 * L) break;
        th -= f / strand_speed(th, &s1);
      }
    s_th += integrate(strand_speed, &s1, th_prev, th, w);
    sig += integrate(strand_speed, &s2, th_prev, th, w);
    th_prev = th;
    if (theta_out) theta_out[k] = th;
    double c[3], dc[3], d[3], dd[3], t1[3], u1[3], q[4], v[3];
    ribbon_exact(th, c, dc, d, dd, (void *)rd);
    for (int i = 0; i < 3; i++) v[i] = dc[i] - 0.5 * delta * dd[i];
    double sp = sqrt(dot(v, v));
    for (int i = 0; i < 3; i++) t1[i] = v[i] / sp;
    cross(t1, d, u1);
    quat_from_frame(t1, d, u1, k ? qprev : NULL, q);
    memcpy(qprev, q, sizeof q);
    sol->t[k] = t;
    double *u = sol->u + (size_t)k * BR_NDIM;
    for (int i = 0; i < 4; i++) u[BR_Q0 + i] = q[i];
    for (int i = 0; i < 3; i++) u[BR_X1 + i] = c[i] - 0.5 * delta * d[i];
    u[BR_SIGMA] = sig;
    th += 2 * M_PI / (np - 1);                 /* next Newton start */
  }
  sol->par[BP_L] = L;
  sol->par[BP_L2] = sig;
  sol->par[BP_LTOT] = L + sig;
  sol->par[BP_DELTA] = delta;
  gsl_integration_workspace_free(w);
  return sol;
}

/* ---- checks ---- */

static void check_curves(void)
{
  ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
  double delta = 0.05;
  int ntst = 40, ncol = 5;
  double *th = malloc(((size_t)ntst * ncol + 1) * sizeof *th);
  cable_solution *sol = build_solution(&rd, delta, ntst, ncol, th);
  int n = 173;                        /* not aligned with the 201 stored points */
  braid_curves *bc = braid_curves_alloc(n);
  test_int("curves from solution", braid_curves_from_solution(sol, bc), CABLE_SUCCESS);
  test_abs("L copied", bc->L, sol->par[BP_L], 0);
  test_abs("Delta copied", bc->Delta, delta, 0);
  test_abs("s(0) = 0", bc->s[0], 0, 0);
  test_abs("s(end) = L", bc->s[n - 1], bc->L, 1e-15 * bc->L);
  test_abs("sigma(end) = L2 (last stored point)", bc->sigma[n - 1], bc->L2, 1e-14 * bc->L2);
  double e_orth = 0, e_dist = 0, e_circ = 0, e_plane = 0, e_tan = 0;
  for (int k = 0; k < n; k++) {
    const double *t1 = bc->t1 + 3 * k, *d1 = bc->d1 + 3 * k, *u1 = bc->u1 + 3 * k, *c = bc->c + 3 * k;
    double x[3];
    cross(t1, d1, x);
    e_orth = fmax(e_orth, fabs(dot(t1, t1) - 1) + fabs(dot(d1, d1) - 1) + fabs(dot(t1, d1)) +
                              fabs(x[0] - u1[0]) + fabs(x[1] - u1[1]) + fabs(x[2] - u1[2]));
    double r21[3] = {bc->r2[3 * k] - bc->r1[3 * k], bc->r2[3 * k + 1] - bc->r1[3 * k + 1],
                     bc->r2[3 * k + 2] - bc->r1[3 * k + 2]};
    e_dist = fmax(e_dist, fabs(sqrt(dot(r21, r21)) - delta));
    e_circ = fmax(e_circ, fabs(hypot(c[0], c[1]) - rd.R));
    e_plane = fmax(e_plane, fabs(c[2]));
    /* tangent t1 vs the difference quotient of r1 (central, O(h^2)) */
    if (k > 0 && k < n - 1) {
      double h = bc->s[k + 1] - bc->s[k - 1];
      for (int i = 0; i < 3; i++)
        e_tan = fmax(e_tan, fabs((bc->r1[3 * k + 3 + i] - bc->r1[3 * k - 3 + i]) / h - t1[i]));
    }
  }
  test_le("frame orthonormal, u1 = t1 x d1 (round-off)", e_orth, 1e-13);
  test_le("|r2 - r1| = Delta (round-off)", e_dist, 1e-15);
  /* positions: the degree-5 interpolant on intervals h = L/40 = 0.158 with 6
   * equally spaced nodes errs by <= |f^(6)| max|prod(x - x_i)| / 6! with
   * max|prod| ~ 17 (h/5)^6; the fastest part is (Delta/2) d1, turning at
   * k = 3.5/R: 0.025 k^6 17 (h/5)^6 / 720 ~ 1e-9; 1e-8 allows for the sum of
   * components */
  test_le("contact curve on the circle |c| = R (interpolation)", e_circ, 1e-8);
  test_le("contact curve in the plane z = 0 (interpolation)", e_plane, 1e-8);
  /* central difference over 2h (h = L/172 = 0.037): error h^2 |r1'''| / 6 with
   * |r1'''| <= 1/R^2 + (Delta/2) k^3 = 2.07, i.e. 4.6e-4 */
  test_le("t1 matches dr1/ds (central difference)", e_tan, 4.6e-4);
  /* knot closure: r1(L) = r2(0) */
  double gap = 0;
  for (int i = 0; i < 3; i++) gap += fabs(bc->r1[3 * (n - 1) + i] - bc->r2[i]);
  test_le("knot closure r1(L) = r2(0)", gap, 1e-12);
  /* the strands r1 (s in [0,L)) then r2 form the right-handed (7,2) torus knot */
  double *poly = malloc(6 * (size_t)(n - 1) * sizeof *poly);
  memcpy(poly, bc->r1, 3 * (size_t)(n - 1) * sizeof *poly);
  memcpy(poly + 3 * (n - 1), bc->r2, 3 * (size_t)(n - 1) * sizeof *poly);
  cable_knot_type_result kt;
  int rc = knot_type_identify(poly, 2 * (n - 1), &kt);
  test_true("strands of the Lk = 3.5 braid form torus(7,2)", rc == 0 && strcmp(kt.name, "torus(7,2)") == 0);
  test_int("... right-handed", kt.handedness, 1);
  free(poly);
  braid_curves_free(bc);
  braid_curves_free(NULL);
  cable_solution_free(sol);
  free(th);
}

/* interpolation order: errors of r1 at the stored-point midpoints vs exact */
static double r1_error(int ntst, int ncol)
{
  ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
  double delta = 0.05;
  int np = ntst * ncol + 1;
  double *th = malloc((size_t)np * sizeof *th);
  cable_solution *sol = build_solution(&rd, delta, ntst, ncol, th);
  /* exact r1 at theta between stored points: use the stored thetas of a
   * solution twice as fine (its even points are ours) */
  cable_solution *fine = build_solution(&rd, delta, 2 * ntst, ncol, NULL);
  double err = 0;
  for (int k = 1; k < cable_solution_npts(fine); k += 2) {
    braid_point p;
    braid_point_eval(sol, fine->t[k], NULL, &p);
    for (int i = 0; i < 3; i++) err = fmax(err, fabs(p.r1[i] - fine->u[(size_t)k * BR_NDIM + BR_X1 + i]));
  }
  cable_solution_free(sol);
  cable_solution_free(fine);
  free(th);
  return err;
}

/* max |kappa - 1/R| of the contact circle at n samples */
static double curvature_error(int ntst, int ncol, double *kmax)
{
  ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
  cable_solution *sol = build_solution(&rd, 0.05, ntst, ncol, NULL);
  int n = 201;
  double kap[201], e = 0;
  if (braid_contact_curvature(sol, n, kap, kmax) != CABLE_SUCCESS) e = INFINITY;
  for (int k = 0; k < n; k++) e = fmax(e, fabs(kap[k] - 1.0 / rd.R));
  cable_solution_free(sol);
  return e;
}

/* the second derivative of the interpolant is O(h^(ncol-1)) accurate */
static void check_curvature(void)
{
  double km1, km2;
  double e1 = curvature_error(40, 5, &km1), e2 = curvature_error(80, 5, &km2);
  printf("     contact curvature error ntst=40: %.3e, ntst=80: %.3e, observed order %.2f\n", e1, e2, log2(e1 / e2));
  test_true("contact curvature converges with order >= ncol - 1.5 = 3.5", log2(e1 / e2) >= 3.5);
  /* from the observed order, ntst = 80 is 16x below the ntst = 40 error (~1e-4) */
  test_le("contact curvature = 1/R at ntst=80", e2, 1e-5);
  test_abs("max curvature at ntst=80", km2, 1.0, 1e-5);
}

static void check_interp_order(void)
{
  int ncol = 4;
  double e1 = r1_error(16, ncol), e2 = r1_error(32, ncol);
  double order = log2(e1 / e2);
  printf("     r1 interpolation error ntst=16: %.3e, ntst=32: %.3e, observed order %.2f\n", e1, e2, order);
  test_abs("interpolation order ncol+1 = 5 (within 0.5)", order, ncol + 1.0, 0.5);
}

static void ribbon_exact_numbers(const ribbon_def *rd, int antip, ribbon_result *res, double *lk_push)
{
  ribbon_workspace *w = ribbon_workspace_alloc(4096);
  ribbon_curve c = {ribbon_exact, 2 * M_PI, antip, (void *)rd};
  ribbon_compute(w, &c, res);
  ribbon_pushoff_linking(w, &c, 0.1, lk_push);   /* spacing 0.01-0.014: error ~ 1e-14 */
  ribbon_workspace_free(w);
}

static void check_braid_ribbon(void)
{
  double delta = 0.05;
  /* (7,2) torus-knot braid on a circle: exact Tw = 3.5, Wr = 0 */
  double err[2];
  for (int lvl = 0; lvl < 2; lvl++) {
    ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
    int ntst = lvl == 0 ? 32 : 64, ncol = 6;
    cable_solution *sol = build_solution(&rd, delta, ntst, ncol, NULL);
    braid_ribbon br;
    test_int("braid ribbon (7,2)", braid_ribbon_compute(sol, 0, &br), CABLE_SUCCESS);
    printf("     ntst=%d ncol=%d: Tw = %.12f Wr = %.3e Lk = %.12f (%d samples, Romberg %.1e)\n", ntst, ncol,
           br.tw, br.wr, br.lk, br.nsamples, br.wr_err);
    err[lvl] = fabs(br.lk - 3.5);
    test_int("closure detected: knot", br.closure, -1);
    test_abs("Wr = 0 for the circular axis (interpolated curve planar to O(h^7))", br.wr, 0.0, 1e-8);
    if (lvl == 1) {
      /* O(h^ncol) with the twist rate 3.5/R as scale: (0.1*3.5)^6 ~ 2e-3 x
       * interval constants ~ 1e-9 observed; 1e-8 leaves a margin */
      test_abs("Tw = 3.5 (ntst=64, ncol=6)", br.tw, 3.5, 1e-8);
      test_abs("Lk = 3.5", br.lk, 3.5, 1e-8);
      test_le("lk_defect from a half-integer", br.lk_defect, 1e-8);
      double lk, tw, wr;
      test_int("braid_ribbon_lk", braid_ribbon_lk(sol, &lk, &tw, &wr), CABLE_SUCCESS);
      test_abs("braid_ribbon_lk = compute", lk, br.lk, 0);
    }
    cable_solution_free(sol);
  }
  printf("     Lk error ntst=32: %.3e, ntst=64: %.3e\n", err[0], err[1]);
  test_true("Lk error decreases at least 2^4 when h halves (O(h^ncol))", err[1] <= err[0] / 16 || err[1] < 1e-12);
  /* mirror: left-handed */
  ribbon_def lh = {0, 1.0, 0, -3.5, 0, 0, 1};
  cable_solution *sol = build_solution(&lh, delta, 64, 6, NULL);
  double lk, tw, wr;
  braid_ribbon_lk(sol, &lk, &tw, &wr);
  test_abs("left-handed (7,2): Lk = -3.5", lk, -3.5, 1e-8);
  cable_solution_free(sol);
  /* a link: d1 turns 3 times; integer Lk */
  ribbon_def lnk = {0, 1.0, 0, 3.0, 0, 0, 1};
  sol = build_solution(&lnk, delta, 64, 6, NULL);
  braid_ribbon br;
  braid_ribbon_compute(sol, 0, &br);
  test_int("closure detected: link", br.closure, 1);
  test_abs("link: Lk = 3", br.lk, 3.0, 1e-8);
  cable_solution_free(sol);

  /* knotted axis: right-handed trefoil with d turning 6.5 times relative to
   * the torus normal; Lk = 6 (torus surface framing) + 6.5 = 12.5 */
  ribbon_def tref = {1, 2.0, 1.0, 6.5, 3, 2, 1};
  ribbon_result ex;
  double lk_push;
  ribbon_exact_numbers(&tref, 1, &ex, &lk_push);
  printf("     exact trefoil ribbon: Tw = %.12f Wr = %.12f Lk = %.12f, push-off Lk = %.12f\n", ex.tw, ex.wr,
         ex.lk, lk_push);
  test_abs("exact trefoil ribbon: push-off Lk = 12.5", lk_push, 12.5, 1e-8);
  test_abs("exact trefoil ribbon: Tw + Wr = push-off Lk", ex.lk, lk_push, 1e-8);
  double e[2];
  for (int lvl = 0; lvl < 2; lvl++) {
    int ntst = lvl == 0 ? 64 : 128;
    sol = build_solution(&tref, delta, ntst, 6, NULL);
    braid_ribbon_compute(sol, 0, &br);
    e[lvl] = fabs(br.lk - ex.lk);
    printf("     trefoil braid ntst=%d: Tw = %.10f (%.1e) Wr = %.10f (%.1e) Lk = %.10f\n", ntst, br.tw,
           br.tw - ex.tw, br.wr, br.wr - ex.wr, br.lk);
    if (lvl == 1) {
      test_abs("trefoil braid: Tw (ntst=128, ncol=6)", br.tw, ex.tw, 1e-7);
      test_abs("trefoil braid: Wr", br.wr, ex.wr, 1e-7);
      test_abs("trefoil braid: Lk = 12.5", br.lk, 12.5, 1e-7);
      cable_braid_topology top;
      test_int("topology", braid_topology_compute(sol, 0, &top), CABLE_SUCCESS);
      test_true("axis is a trefoil", strcmp(top.axis.name, "trefoil") == 0);
      test_int("axis right-handed", top.axis.handedness, 1);
      test_int("axis crossing number", top.axis.crossing_number, 3);
      test_abs("Lk inside the tube = 12.5 - 3", top.lk_in_tube, 9.5, 1e-7);
    }
    cable_solution_free(sol);
  }
  test_true("trefoil braid: Lk error decreases at least 2^4 when h halves", e[1] <= e[0] / 16 || e[1] < 1e-11);
  sol = build_solution(&(ribbon_def){0, 1.0, 0, 3.5, 0, 0, 1}, delta, 32, 6, NULL);
  cable_braid_topology top;
  braid_topology_compute(sol, 500, &top);
  test_true("circular axis is the unknot", strcmp(top.axis.name, "unknot") == 0);
  test_abs("... Lk inside the tube = Lk", top.lk_in_tube, top.lk, 0);
  cable_solution_free(sol);
}

/* An axis that nearly passes through itself: the lemniscate crosses itself
 * at height 2a.  The braid ribbon's Lk is the diagram's writhe (+1 for a > 0,
 * -1 for a < 0) plus the turns k of d1 about the blackboard normal, for any
 * a != 0; the Gauss integrand peaks there with width 2a, and the quadrature
 * must resolve it (uniform samples Delta/4 apart, as before, gave Lk wrong by
 * up to 0.4 at axis distances of 3e-4 Delta on runs/knot72). */
static void check_near_crossing(void)
{
  const double delta = 0.05;
  const double heights[3] = {0.1, 1e-4, -1e-6};
  for (int c = 0; c < 3; c++) {
    for (int knot = 0; knot < 2; knot++) {
      double k = knot ? 3.5 : 3.0, a = heights[c];
      ribbon_def rd = {2, 1.0, a, k, 0, 0, 1};
      cable_solution *sol = build_solution(&rd, delta, 128, 6, NULL);
      braid_ribbon br;
      int rc = braid_ribbon_compute(sol, 0, &br);
      double want = (a > 0 ? 1.0 : -1.0) + k;
      char what[160];
      snprintf(what, sizeof what, "lemniscate crossing at height %g, d turning %g times: computed", 2 * a, k);
      test_int(what, rc, CABLE_SUCCESS);
      printf("     2a = %g: Tw %.12f Wr %.12f Lk %.12f, %d samples, %d close approaches, closest %.3g Delta, "
             "Wr error estimate %.2g\n", 2 * a, br.tw, br.wr, br.lk, br.nsamples, br.nnear, br.axis_dmin, br.wr_err);
      snprintf(what, sizeof what, "lemniscate 2a = %g: closest approach found (= 2|a|/Delta)", 2 * a);
      /* Newton on the interpolated axis: its O(h^7) position error */
      if (fabs(2 * a) < 2 * delta) test_rel(what, br.axis_dmin, 2 * fabs(a) / delta, 1e-3);
      else test_true(what, br.nnear == 0);
      snprintf(what, sizeof what, "lemniscate 2a = %g: writhe resolved", 2 * a);
      test_true(what, br.resolved && br.wr_err <= BRAID_RIBBON_WR_TOL);
      /* interpolant (ntst 64, ncol 6): Tw and the tangent kinks ~1e-9, see
         check_braid_ribbon; quadrature BRAID_RIBBON_WR_TOL */
      snprintf(what, sizeof what, "lemniscate 2a = %g, k = %g: Lk = %g", 2 * a, k, want);
      test_abs(what, br.lk, want, 1e-7);
      cable_solution_free(sol);
    }
  }
}

/* tube distance of a solution: the (7,2) braid on a circle of radius 1 has no
 * distant approach; the axis curvature is 1/R (interpolation, O(h^4)) */
static void check_tube_solution(void)
{
  ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
  cable_solution *sol = build_solution(&rd, 0.05, 80, 5, NULL);
  cable_tube_distance_result r;
  test_int("tube distance of a solution", cable_braid_tube_distance_solution(sol, 0, &r), CABLE_SUCCESS);
  printf("     (7,2) braid, Delta = 0.05: dmin %.4f, axis dmin %.4f, kappa max %.8f\n", r.dmin, r.axis_dmin,
         r.axis_kappa_max);
  test_int("no overlap", r.noverlap, 0);
  test_true("dmin above the window-edge bound pi - 1", r.dmin > M_PI - 1);
  test_abs("contact curvature max = 1/R (ntst=80, see above)", r.axis_kappa_max, 1.0, 1e-5);
  double dmin = -1;
  test_int("PVLS's dmin alone: status", braid_tube_dmin_solution(sol, &dmin), CABLE_SUCCESS);
  test_abs("PVLS's dmin alone = the analysis's dmin (same samples)", dmin, r.dmin, 0.0);
  test_int("PVLS's dmin alone: NULL output", braid_tube_dmin_solution(sol, NULL), CABLE_ERR_NULL);
  test_int("tube distance: n = 1 refused", cable_braid_tube_distance_solution(sol, 1, &r), CABLE_ERR_INPUT);
  test_int("tube distance: NULL output", cable_braid_tube_distance_solution(sol, 0, NULL), CABLE_ERR_NULL);
  cable_solution_free(sol);
}

static void check_errors(void)
{
  ribbon_def rd = {0, 1.0, 0, 3.5, 0, 0, 1};
  cable_solution *sol = build_solution(&rd, 0.05, 8, 4, NULL);
  braid_curves *bc = braid_curves_alloc(10);
  braid_ribbon br;
  test_true("curves: n < 2 refused", braid_curves_alloc(1) == NULL);
  test_int("curves: NULL solution", braid_curves_from_solution(NULL, bc), CABLE_ERR_INPUT);
  test_int("curves: NULL output", braid_curves_from_solution(sol, NULL), CABLE_ERR_INPUT);
  sol->par[BP_DELTA] = 0;
  test_int("curves: Delta = 0", braid_curves_from_solution(sol, bc), CABLE_ERR_INPUT);
  test_int("ribbon: Delta = 0", braid_ribbon_compute(sol, 0, &br), CABLE_ERR_INPUT);
  sol->par[BP_DELTA] = 0.05;
  double L = sol->par[BP_L];
  sol->par[BP_L] = -1;
  test_int("curves: L < 0", braid_curves_from_solution(sol, bc), CABLE_ERR_INPUT);
  sol->par[BP_L] = NAN;
  test_int("curves: L NaN", braid_curves_from_solution(sol, bc), CABLE_ERR_NONFINITE);
  sol->par[BP_L] = L;
  double keep = sol->u[5 * BR_NDIM + BR_Y1];
  sol->u[5 * BR_NDIM + BR_Y1] = INFINITY;
  test_int("curves: Inf in the state", braid_curves_from_solution(sol, bc), CABLE_ERR_NONFINITE);
  sol->u[5 * BR_NDIM + BR_Y1] = keep;
  double t3 = sol->t[3];
  sol->t[3] = sol->t[2];
  test_int("curves: mesh not increasing", braid_curves_from_solution(sol, bc), CABLE_ERR_INPUT);
  sol->t[3] = t3;
  for (int i = 0; i < 4; i++) sol->u[BR_Q0 + i] = 0;
  test_int("curves: zero quaternion", braid_curves_from_solution(sol, bc), CABLE_ERR_INPUT);
  cable_solution_free(sol);
  sol = build_solution(&rd, 0.05, 8, 4, NULL);
  /* open the contact curve: move the last point */
  sol->u[(size_t)(cable_solution_npts(sol) - 1) * BR_NDIM + BR_X1] += 0.1;
  test_int("ribbon: contact curve not closed", braid_ribbon_compute(sol, 0, &br), CABLE_ERR_INPUT);
  test_int("ribbon: negative sample count", braid_ribbon_compute(sol, -8, &br), CABLE_ERR_INPUT);
  test_int("ribbon: NULL output", braid_ribbon_compute(sol, 0, NULL), CABLE_ERR_INPUT);
  cable_solution_free(sol);
  cable_solution *small = cable_solution_alloc(10, 4, 4, BP_NPAR, 1);
  test_int("curves: ndim < BR_NDIM", braid_curves_from_solution(small, bc), CABLE_ERR_INPUT);
  test_int("curvature: ndim < BR_NDIM", braid_contact_curvature(small, 10, NULL, NULL), CABLE_ERR_INPUT);
  cable_braid_topology top;
  test_int("topology: ndim < BR_NDIM", braid_topology_compute(small, 0, &top), CABLE_ERR_INPUT);
  cable_solution_free(small);
  braid_curves_free(bc);
}

int main(void)
{
  gsl_set_error_handler_off();
  check_curves();
  check_interp_order();
  check_curvature();
  check_braid_ribbon();
  check_near_crossing();
  check_tube_solution();
  check_errors();
  return test_summary();
}
