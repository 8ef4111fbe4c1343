/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Braid boundary conditions (bc/braid_bc.h): every row against the paper's
 * printed formula, analytic Jacobians against central differences, the
 * geometric meaning of the end-frame conditions, and the error paths. */
#include <math.h>
#include <string.h>

#include "braid_bc.h"
#include "braid_problems.h"
#include "braid_random.h"
#include "harness.h"

#define NPARAM BP_NPAR
#define NCOL (2 * BR_NDIM + NPARAM)
#define MAXBC 25
static const double sqrt_half = 0.70710678118654752440;
static const double pi = 3.14159265358979323846;

/* Central differences with step h = fd_rel * max(1, |x|): truncation error
 * h^2 |f'''|/6 ~ 1e-13 and rounding error ~ eps |f| / h ~ 1e-10 for the O(1..10)
 * values and derivatives of the random points below, so 1e-8 * max(1, |J|)
 * leaves a margin of 100. */
static const double fd_rel = 1e-6;
static const double fd_tol = 1e-8;
/* Rows compared with the printed formulas are computed with the same
 * operations in possibly another order: a few units of rounding. */
static const double formula_tol = 1e-14;
/* Frame vectors from quaternions built of a few products and sums of unit
 * numbers: each entry carries a few roundings of size eps. */
static const double geom_tol = 8 * 2.220446049250313e-16;
/* Number of random points per problem. */
enum { NSAMPLES = 20 };

/* the tests' random numbers (tests/braid_random.h) */
static test_rng rng = {0x9E3779B97F4A7C15u};

/* The printed conditions, written independently, "lhs - rhs". */
static void knot_formulas(int sym, const double *u0, const double *u1, const double *p, double *e)
{
  const double d = p[BP_DELTA];
  const double x[] = {
    u0[BR_X1], u0[BR_Y1], u0[BR_Z1],                                         /* 12.3.1-3 */
    u0[BR_Q0], u0[BR_Q1] - (-sqrt_half), u0[BR_Q2] - (-sqrt_half), u0[BR_Q3], /* 12.3.4-7 */
    u0[BR_XI1], u0[BR_XI2], u0[BR_T1] - p[BP_T], u0[BR_T2] - (-p[BP_T]),      /* 12.3.8-11 */
    u0[BR_SIGMA],                                                            /* 12.3.12 */
    (u1[BR_X1] - u0[BR_X1] + (sym ? p[BP_EPS13] : 0.0)) - d,                  /* 12.3.13 */
    u1[BR_Y1], u1[BR_Z1], u1[BR_Q0] - u1[BR_Q3], u1[BR_Q1] - (-u1[BR_Q2]),    /* 12.3.14-17 */
    4 * u1[BR_Q0] * u1[BR_Q1] - sin(u1[BR_ETA]), u1[BR_ETA] - u0[BR_ETA],     /* 12.3.18-19 */
    (u0[BR_M2] - p[BP_B1] * u0[BR_W2]) / p[BP_B2] - (-u1[BR_W2]),             /* 12.3.20 */
    ((1 - d * u0[BR_W3]) / cos(u0[BR_ETA]) + p[BP_EPS21]) -
        cos(u1[BR_ETA]) / (1 - d * u1[BR_W3]),                               /* 12.3.21 */
    u1[BR_SIGMA] - p[BP_L2], p[BP_L] + p[BP_L2] - p[BP_LTOT],                 /* 12.3.22-23 */
    u0[BR_W2] - p[BP_W2FIX],                                                 /* phase */
    u0[BR_F2]};                                                              /* sym: F2(0) */
  memcpy(e, x, sizeof(double) * (size_t)(sym ? BK_SYM_NBC : BK_NBC));
}

static void link_formulas(const double *u0, const double *u1, const double *p, double *e)
{
  const double f = p[BP_PHI];
  const double x[] = {
    u0[BR_X1], u0[BR_Y1], u0[BR_Z1],                                         /* 12.3.24-26 */
    u0[BR_Q0], u0[BR_Q1] + sqrt_half, u0[BR_Q2] + sqrt_half, u0[BR_Q3],       /* 12.3.27-30 */
    u0[BR_XI1], u0[BR_XI2], u0[BR_T1] - p[BP_T], u0[BR_T2] + p[BP_T],         /* 12.3.31-34 */
    u0[BR_SIGMA],                                                            /* 12.3.35 */
    u1[BR_X1] - u0[BR_X1], u1[BR_Y1] - u0[BR_Y1], u1[BR_Z1] - u0[BR_Z1],      /* 12.3.36-38 */
    u1[BR_Q0] - u1[BR_Q3], u1[BR_Q1] - u1[BR_Q2],                             /* 12.3.39-40 */
    u1[BR_Q0] + u1[BR_Q1] - (-sin(f / 2 - pi / 4)),                           /* 12.3.41 */
    u0[BR_W2] - p[BP_W2FIX],                                                 /* 12.3.42 */
    u1[BR_W2] - (u0[BR_W2] * cos(f) + u0[BR_W3] * sin(f)),                    /* 12.3.43 */
    u1[BR_SIGMA] - p[BP_L2]};                                                /* 12.3.44 */
  memcpy(e, x, sizeof x);
}

typedef struct {
  const char *name;
  cable_bcnd_fn *fn;
  int nbc;
  int kind; /* 0 knot, 1 knot_sym, 2 link */
} bc_case;

static void check_formulas(const bc_case *c)
{
  double worst = 0.0;
  int st_all = 0;
  for (int n = 0; n < NSAMPLES; n++) {
    double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[MAXBC], e[MAXBC];
    braid_random_bc_point(&rng, 1, u0, u1, par);
    st_all |= c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fb, NULL, NULL);
    if (c->kind == 2) link_formulas(u0, u1, par, e);
    else knot_formulas(c->kind == 1, u0, u1, par, e);
    for (int i = 0; i < c->nbc; i++) worst = fmax(worst, fabs(fb[i] - e[i]) / fmax(1.0, fabs(e[i])));
  }
  char what[128];
  snprintf(what, sizeof what, "%s: status 0 at %d random points", c->name, NSAMPLES);
  test_int(what, st_all, 0);
  snprintf(what, sizeof what, "%s: every row equals the printed formula (max rel. diff)", c->name);
  test_le(what, worst, formula_tol);
}

static void check_jacobian(const bc_case *c)
{
  static double dbc[MAXBC * NCOL];
  double worst = 0.0, worst_par = 0.0;
  int st_all = 0;
  for (int n = 0; n < NSAMPLES; n++) {
    double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[MAXBC], fp[MAXBC], fm[MAXBC];
    braid_random_bc_point(&rng, 1, u0, u1, par);
    st_all |= c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 2, fb, dbc, NULL);
    for (int j = 0; j < NCOL; j++) {
      double *x = j < BR_NDIM ? &u0[j] : j < 2 * BR_NDIM ? &u1[j - BR_NDIM] : &par[j - 2 * BR_NDIM];
      const double x0 = *x, h = fd_rel * fmax(1.0, fabs(x0));
      *x = x0 + h;
      st_all |= c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fp, NULL, NULL);
      *x = x0 - h;
      st_all |= c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fm, NULL, NULL);
      *x = x0;
      for (int i = 0; i < c->nbc; i++) {
        const double fd = (fp[i] - fm[i]) / (2 * h), an = dbc[i + c->nbc * j];
        const double err = fabs(fd - an) / fmax(1.0, fabs(an));
        if (j < 2 * BR_NDIM) worst = fmax(worst, err);
        else worst_par = fmax(worst_par, err);
      }
    }
  }
  char what[128];
  snprintf(what, sizeof what, "%s: Jacobian calls return 0", c->name);
  test_int(what, st_all, 0);
  snprintf(what, sizeof what, "%s: d fb/d(u0,u1) vs central differences (max scaled err)", c->name);
  test_le(what, worst, fd_tol);
  snprintf(what, sizeof what, "%s: d fb/d par (all %d slots) vs central differences", c->name, NPARAM);
  test_le(what, worst_par, fd_tol);

  /* ijac = 1 leaves the parameter columns alone; ijac = 0 accepts dbc = NULL. */
  double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[MAXBC], fb0[MAXBC];
  braid_random_bc_point(&rng, 1, u0, u1, par);
  for (int k = 0; k < MAXBC * NCOL; k++) dbc[k] = 12345.0;
  c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 1, fb, dbc, NULL);
  int untouched = 1;
  for (int k = c->nbc * 2 * BR_NDIM; k < c->nbc * NCOL; k++) untouched &= dbc[k] == 12345.0;
  snprintf(what, sizeof what, "%s: ijac = 1 does not write parameter columns", c->name);
  test_true(what, untouched);
  c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fb0, NULL, NULL);
  int same = 1;
  for (int i = 0; i < c->nbc; i++) same &= fb0[i] == fb[i];
  snprintf(what, sizeof what, "%s: ijac = 0 with dbc = NULL gives the same fb", c->name);
  test_true(what, same);
}

static void check_errors(const bc_case *c)
{
  double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[MAXBC];
  char what[128];
  braid_random_bc_point(&rng, 1, u0, u1, par);
  snprintf(what, sizeof what, "%s: ndim != 21 is fatal", c->name);
  test_int(what, c->fn(20, par, NULL, c->nbc, u0, u1, 0, fb, NULL, NULL), CABLE_BRAID_BC_SIZE);
  snprintf(what, sizeof what, "%s: wrong nbc is fatal", c->name);
  test_int(what, c->fn(BR_NDIM, par, NULL, c->nbc - 1, u0, u1, 0, fb, NULL, NULL),
           CABLE_BRAID_BC_SIZE);
  u0[BR_X1] = NAN;
  snprintf(what, sizeof what, "%s: a NaN state is recoverable", c->name);
  test_int(what, c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fb, NULL, NULL), CABLE_BRAID_BC_DOMAIN);
  if (c->kind == 2) return;
  braid_random_bc_point(&rng, 1, u0, u1, par);
  par[BP_DELTA] = 0.25; /* exact: 1 - 0.25 * 4 = 0 */
  u1[BR_W3] = 4.0;
  snprintf(what, sizeof what, "%s: 1 - Delta omega3(L) = 0 is recoverable", c->name);
  test_int(what, c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fb, NULL, NULL), CABLE_BRAID_BC_DOMAIN);
  braid_random_bc_point(&rng, 1, u0, u1, par);
  par[BP_B2] = 0.0;
  snprintf(what, sizeof what, "%s: B2 = 0 is recoverable", c->name);
  test_int(what, c->fn(BR_NDIM, par, NULL, c->nbc, u0, u1, 0, fb, NULL, NULL), CABLE_BRAID_BC_DOMAIN);
}

/* Quaternion helpers for the geometric checks. */
static void qmul(const double *a, const double *b, double *r)
{
  r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}
static void qaxis(int k, double a, double *q)
{
  q[0] = cos(a / 2);
  q[1] = q[2] = q[3] = 0;
  q[1 + k] = sin(a / 2);
}
/* t1 and d1 of the paper's Sect. 12.2.3 */
static void frame_t1_d1(const double *q, double *t1, double *d1)
{
  t1[0] = q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3];
  t1[1] = 2 * q[1] * q[2] + 2 * q[0] * q[3];
  t1[2] = 2 * q[1] * q[3] - 2 * q[0] * q[2];
  d1[0] = 2 * q[1] * q[2] - 2 * q[0] * q[3];
  d1[1] = q[0] * q[0] - q[1] * q[1] + q[2] * q[2] - q[3] * q[3];
  d1[2] = 2 * q[2] * q[3] + 2 * q[0] * q[1];
}

/* Knot: the end frame with d1(L) = -d1(0) and t1(L) = t2(0) = cos eta t1(0) -
 * sin eta u1(0) satisfies (12.3.16)-(12.3.19) for either sign of q(L); the
 * frame at s = 0 given by (12.3.4)-(12.3.7) is t1 = e_y, d1 = e_x. */
static void check_knot_geometry(void)
{
  double worst = 0.0, worst_t = 0.0, dcheck = 0.0;
  for (int n = 0; n < NSAMPLES; n++) {
    double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[BK_NBC], qx[4], qz[4], q[4], t1[3], d1[3];
    braid_random_bc_point(&rng, 1, u0, u1, par);
    const double eta = test_rng_uniform(&rng, -1.2, 1.2), sign = n % 2 ? 1.0 : -1.0;
    u0[BR_ETA] = u1[BR_ETA] = eta;
    qaxis(0, eta, qx);
    qaxis(2, pi / 2, qz);
    qmul(qx, qz, q);
    for (int i = 0; i < 4; i++) u1[BR_Q0 + i] = sign * q[i];
    braid_knot_bcnd(BR_NDIM, par, NULL, BK_NBC, u0, u1, 0, fb, NULL, NULL);
    for (int i = BK_Q0Q3; i <= BK_ETA; i++) worst = fmax(worst, fabs(fb[i]));
    frame_t1_d1(u1 + BR_Q0, t1, d1);
    /* t2(0) = cos eta e_y - sin eta (-e_z) */
    worst_t = fmax(worst_t, fabs(t1[0]) + fabs(t1[1] - cos(eta)) + fabs(t1[2] - sin(eta)));
    dcheck = fmax(dcheck, fabs(d1[0] + 1) + fabs(d1[1]) + fabs(d1[2]));
  }
  test_le("knot: (12.3.16)-(12.3.19) hold for d1(L) = -d1(0), t1(L) = t2(0)", worst, geom_tol);
  test_le("knot: that frame has t1(L) = cos eta e_y + sin eta e_z", worst_t, geom_tol);
  test_le("knot: that frame has d1(L) = -e_x", dcheck, geom_tol);

  double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[BK_NBC], t1[3], d1[3];
  braid_random_bc_point(&rng, 1, u0, u1, par);
  const double q0[4] = {0, -sqrt_half, -sqrt_half, 0};
  for (int i = 0; i < 4; i++) u0[BR_Q0 + i] = q0[i];
  u0[BR_X1] = u0[BR_Y1] = u0[BR_Z1] = 0;
  braid_knot_bcnd(BR_NDIM, par, NULL, BK_NBC, u0, u1, 0, fb, NULL, NULL);
  frame_t1_d1(q0, t1, d1);
  test_le("knot: (12.3.1)-(12.3.7) vanish at the stated frame",
          fabs(fb[BK_X0]) + fabs(fb[BK_Y0]) + fabs(fb[BK_Z0]) + fabs(fb[BK_Q00]) + fabs(fb[BK_Q10]) +
              fabs(fb[BK_Q20]) + fabs(fb[BK_Q30]), 0.0);
  test_le("knot: q(0) gives t1 = e_y, d1 = e_x",
          fabs(t1[0]) + fabs(t1[1] - 1) + fabs(t1[2]) + fabs(d1[0] - 1) + fabs(d1[1]) + fabs(d1[2]),
          geom_tol);
}

/* Link: rotating the ring's end frame -q(0) by Phi about t1(0) = e_y
 * (right-handed) satisfies (12.3.39)-(12.3.41) for that Phi, and turns d1 to
 * cos Phi d1(0) + sin Phi u1(0).  (12.3.41) is what fixes the sense of Phi. */
static void check_link_geometry(void)
{
  double worst = 0.0, worst_other = -INFINITY, dworst = 0.0;
  const double q0[4] = {0, -sqrt_half, -sqrt_half, 0};
  for (int n = 0; n < NSAMPLES; n++) {
    double u0[BR_NDIM], u1[BR_NDIM], par[NPARAM], fb[BL_NBC], qy[4], q[4], t1[3], d1[3];
    braid_random_bc_point(&rng, 1, u0, u1, par);
    const double phi = test_rng_uniform(&rng, 0.3, 2.8) * (n % 2 ? 1 : -1);
    par[BP_PHI] = phi;
    qaxis(1, phi, qy);
    qmul(qy, q0, q);
    for (int i = 0; i < 4; i++) u1[BR_Q0 + i] = -q[i];
    braid_link_bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fb, NULL, NULL);
    worst = fmax(worst, fabs(fb[BL_Q0Q3]) + fabs(fb[BL_Q1Q2]) + fabs(fb[BL_PHI]));
    frame_t1_d1(u1 + BR_Q0, t1, d1);
    /* d1(0) = e_x, u1(0) = -e_z */
    dworst = fmax(dworst, fabs(d1[0] - cos(phi)) + fabs(d1[1]) + fabs(d1[2] + sin(phi)) +
                              fabs(t1[0]) + fabs(t1[1] - 1) + fabs(t1[2]));
    par[BP_PHI] = -phi; /* the opposite sense must violate (12.3.41) */
    braid_link_bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fb, NULL, NULL);
    worst_other = fmax(worst_other, -fabs(fb[BL_PHI]));
  }
  test_le("link: (12.3.39)-(12.3.41) hold for the end frame rotated by +Phi about t1(0)", worst, geom_tol);
  test_le("link: that frame has d1(L) = cos Phi d1(0) + sin Phi u1(0), t1(L) = t1(0)", dworst, geom_tol);
  test_le("link: the frame rotated by -Phi violates (12.3.41) (-min |fb|)", worst_other, -1e-2);
}

int main(void)
{
  const bc_case cases[] = {
    {"braid_knot", braid_knot_bcnd, BK_NBC, 0},
    {"braid_knot_sym", braid_knot_sym_bcnd, BK_SYM_NBC, 1},
    {"braid_link", braid_link_bcnd, BL_NBC, 2},
  };
  test_int("knot has 24 conditions", BK_NBC, 24);
  test_int("symmetric knot has 25 conditions", BK_SYM_NBC, 25);
  test_int("link has 21 conditions", BL_NBC, 21);
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    check_formulas(&cases[c]);
    check_jacobian(&cases[c]);
    check_errors(&cases[c]);
  }
  check_knot_geometry();
  check_link_geometry();

  /* The problem templates use these functions and dimensions. */
  const cable_problem *k = braid_knot_problem(), *ks = braid_knot_sym_problem(),
                      *l = braid_link_problem();
  test_true("braid_knot template: bcnd, nbc, ndim",
            k->bcnd == braid_knot_bcnd && k->nbc == 24 && k->ndim == 21 && k->nint == 0);
  test_true("braid_knot_sym template: bcnd, nbc",
            ks->bcnd == braid_knot_sym_bcnd && ks->nbc == 25 && ks->ndim == 21);
  test_true("braid_link template: bcnd, nbc", l->bcnd == braid_link_bcnd && l->nbc == 21);
  /* AUTO's count: free parameters = NBC + NINT - NDIM + 1. */
  test_int("knot: NBC - NDIM + 1 = 4 free parameters (T, L, L2, eps21)", k->nbc - k->ndim + 1, 4);
  test_int("knot_sym: 5 free parameters (T, L, L2, eps21, eps13)", ks->nbc - ks->ndim + 1, 5);
  test_int("link: 1 free parameter", l->nbc - l->ndim + 1, 1);
  return test_summary();
}
