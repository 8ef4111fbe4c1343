/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "test_problems.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

/* ---- Bratu ---- */
static int bratu_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                      double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp; (void)params;
  double e = exp(u[0]);
  f[0] = u[1];
  f[1] = -par[0] * e;
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0; dfdu[0 + ndim * 1] = 1.0;
    dfdu[1 + ndim * 0] = -par[0] * e; dfdu[1 + ndim * 1] = 0.0;
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = 0.0;
    dfdp[1 + ndim * 0] = -e;
  }
  return 0;
}

/* Dirichlet conditions on component `comp` at both ends: fb = (u0[comp] - a, u1[comp] - b). */
static int dirichlet(int ndim, int nbc, int comp, const double *u0, const double *u1, double a,
                     double b, int ijac, double *fb, double *dbc)
{
  fb[0] = u0[comp] - a;
  fb[1] = u1[comp] - b;
  if (ijac >= 1) {
    for (int j = 0; j < 2 * ndim; j++) dbc[0 + nbc * j] = dbc[1 + nbc * j] = 0.0;
    dbc[0 + nbc * comp] = 1.0;
    dbc[1 + nbc * (ndim + comp)] = 1.0;
  }
  return 0;
}

static void zero_par_columns(int nbc, int ndim, int npar, int ijac, double *dbc)
{
  if (ijac >= 2)
    for (int k = 0; k < npar; k++)
      for (int i = 0; i < nbc; i++) dbc[i + nbc * (2 * ndim + k)] = 0.0;
}

static int bratu_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                      const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par; (void)icp; (void)params;
  dirichlet(ndim, nbc, 0, u0, u1, 0.0, 0.0, ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 1, ijac, dbc);
  return 0;
}

static int zero_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 0.0;
  return 0;
}

static const char *const lambda_names[] = {"lambda"};
static const char *const u_names[] = {"u", "u'"};

/* Variational structures (doc/stability.md S4): y = u[0], the second
 * variation's densities P = L_{y'y'}, C = L_{y'y}, R = L_{yy}. */
static int dirichlet_vbc(int ndim, const double *u0, const double *u1, const double *par, int nvar, int nvbc,
                         double *B, double *Hb, void *params)
{
  (void)ndim; (void)u0; (void)u1; (void)par; (void)Hb; (void)params;
  /* v(0) = 0, v(1) = 0 (Hb stays zero: the conditions are linear) */
  for (int j = 0; j < 2 * nvar * nvbc; j++) B[j] = 0.0;
  B[0 + nvbc * 0] = 1.0;
  B[1 + nvbc * nvar] = 1.0;
  return 0;
}

/* Bratu: A = int u'^2/2 - lambda e^u dt, so P = 1, C = 0, R = -lambda e^u. */
static int bratu_hessian(int ndim, const double *u, const double *par, int nvar, double *P, double *C, double *R,
                         void *params)
{
  (void)ndim; (void)nvar; (void)params;
  P[0] = 1.0;
  C[0] = 0.0;
  R[0] = -par[0] * exp(u[0]);
  return 0;
}

/* bratu_int's integral condition int u dt = mu with mu free constrains no
 * variation (mu follows it): the structure is Bratu's. */
static const cable_variational bratu_var = {
  .nvar = 1, .ncon = 0, .nvbc = 2, .hessian = bratu_hessian, .vbc = dirichlet_vbc,
};

static const cable_problem bratu = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "bratu", .description = "Bratu: u'' + lambda e^u = 0, u(0) = u(1) = 0",
  .ndim = 2, .nbc = 2, .nint = 0, .npar = 1, .parnames = lambda_names, .unames = u_names,
  .func = bratu_func, .bcnd = bratu_bcnd, .stpnt = zero_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
  .variational = &bratu_var,
};

const cable_problem *cable_testproblem_bratu(void) { return &bratu; }

static double bratu_root_fn(double th, void *p)
{
  double lambda = *(const double *)p;
  return th - sqrt(2.0 * lambda) * cosh(th / 4.0);
}

double cable_bratu_theta(double lambda)
{
  /* the lower-branch root lies below the fold value th* = 4.7987 (where the
     two roots merge); bracket it in (0, th*] */
  gsl_function F = {bratu_root_fn, &lambda};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double lo = 1e-12, hi = 4.798714560;
  if (!s || bratu_root_fn(lo, &lambda) * bratu_root_fn(hi, &lambda) > 0) {
    gsl_root_fsolver_free(s);
    return NAN;
  }
  gsl_root_fsolver_set(s, &F, lo, hi);
  double r = NAN;
  for (int it = 0; it < 200; it++) {
    gsl_root_fsolver_iterate(s);
    r = gsl_root_fsolver_root(s);
    lo = gsl_root_fsolver_x_lower(s);
    hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  return r;
}

double cable_bratu_exact(double lambda, double th, double t)
{
  (void)lambda;
  return -2.0 * log(cosh((t - 0.5) * th / 2.0) / cosh(th / 4.0));
}

/* ---- Bratu with an integral condition: int_0^1 u dt - mu = 0 ----
 * NBC = 2, NINT = 1, so NFPR = 2: lambda and mu = PAR(2) are both free; the
 * branch is Bratu's, and mu reports the mean of u along it. */
static int bratu_int_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                          const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par; (void)icp; (void)params;
  dirichlet(ndim, nbc, 0, u0, u1, 0.0, 0.0, ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 2, ijac, dbc);
  return 0;
}

static int bratu_int_icnd(int ndim, const double *par, const int *icp, int nint, const double *u,
                          const double *uold, const double *udot, const double *upold, int ijac,
                          double *fi, double *dint, void *params)
{
  (void)icp; (void)uold; (void)udot; (void)upold; (void)params;
  fi[0] = u[0] - par[1];
  if (ijac >= 1) {
    dint[0 + nint * 0] = 1.0;
    for (int j = 1; j < ndim; j++) dint[0 + nint * j] = 0.0;
  }
  if (ijac >= 2) {
    dint[0 + nint * (ndim + 0)] = 0.0;
    dint[0 + nint * (ndim + 1)] = -1.0;
  }
  return 0;
}

static int bratu_int_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 0.0;
  par[1] = 0.0;
  return 0;
}

static const char *const lambda_mu_names[] = {"lambda", "mu"};

static const cable_problem bratu_int = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "bratu_int", .description = "Bratu with mu = int_0^1 u dt as an integral condition",
  .ndim = 2, .nbc = 2, .nint = 1, .npar = 2, .parnames = lambda_mu_names, .unames = u_names,
  .func = bratu_func, .bcnd = bratu_int_bcnd, .icnd = bratu_int_icnd, .stpnt = bratu_int_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1, .icnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
  .variational = &bratu_var,
};

const cable_problem *cable_testproblem_bratu_int(void) { return &bratu_int; }

/* ---- elastica ---- */
static int elastica_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                         double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp; (void)params;
  f[0] = u[1];
  f[1] = -par[0] * sin(u[0]);
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0; dfdu[0 + ndim * 1] = 1.0;
    dfdu[1 + ndim * 0] = -par[0] * cos(u[0]); dfdu[1 + ndim * 1] = 0.0;
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = 0.0;
    dfdp[1 + ndim * 0] = -sin(u[0]);
  }
  return 0;
}

static int elastica_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                         const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par; (void)icp; (void)params;
  dirichlet(ndim, nbc, 1, u0, u1, 0.0, 0.0, ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 1, ijac, dbc);
  return 0;
}

static int elastica_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 1.0;
  return 0;
}

static const char *const theta_names[] = {"theta", "theta'"};

/* The elastica: A = int theta'^2/2 + lambda cos theta dt (bending energy
 * minus the load's work), free ends: P = 1, C = 0, R = -lambda cos theta and
 * no constraint on the variations (the rigid rotation v = 1 is admissible). */
static int elastica_hessian(int ndim, const double *u, const double *par, int nvar, double *P, double *C, double *R,
                            void *params)
{
  (void)ndim; (void)nvar; (void)params;
  P[0] = 1.0;
  C[0] = 0.0;
  R[0] = -par[0] * cos(u[0]);
  return 0;
}

static const cable_variational elastica_var = {.nvar = 1, .ncon = 0, .nvbc = 0, .hessian = elastica_hessian};

static const cable_problem elastica = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "elastica", .description = "Euler elastica: theta'' + lambda sin theta = 0, theta'(0) = theta'(1) = 0",
  .ndim = 2, .nbc = 2, .nint = 0, .npar = 1, .parnames = lambda_names, .unames = theta_names,
  .func = elastica_func, .bcnd = elastica_bcnd, .stpnt = elastica_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
  .variational = &elastica_var,
};

const cable_problem *cable_testproblem_elastica(void) { return &elastica; }

/* ---- the Euler column with its ends on one line ----
 * theta'' + lambda sin theta + nu cos theta = 0, theta'(0) = theta'(1) = 0,
 * int_0^1 sin theta dt = 0 (zero end displacement across the load line, NINT
 * = 1); nu = PAR(2), the transverse end force, is the constraint's multiplier
 * and free with lambda (NFPR = 2).  A = int theta'^2/2 + lambda cos theta -
 * nu sin theta dt. */
static int elastica_int_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                             double *dfdu, double *dfdp, void *params)
{
  (void)icp; (void)params;
  double s = sin(u[0]), c = cos(u[0]);
  f[0] = u[1];
  f[1] = -par[0] * s - par[1] * c;
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0; dfdu[0 + ndim * 1] = 1.0;
    dfdu[1 + ndim * 0] = -par[0] * c + par[1] * s; dfdu[1 + ndim * 1] = 0.0;
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = 0.0; dfdp[1 + ndim * 0] = -s;
    dfdp[0 + ndim * 1] = 0.0; dfdp[1 + ndim * 1] = -c;
  }
  return 0;
}

static int elastica_int_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                             const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par; (void)icp; (void)params;
  dirichlet(ndim, nbc, 1, u0, u1, 0.0, 0.0, ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 2, ijac, dbc);
  return 0;
}

static int elastica_int_icnd(int ndim, const double *par, const int *icp, int nint, const double *u,
                             const double *uold, const double *udot, const double *upold, int ijac, double *fi,
                             double *dint, void *params)
{
  (void)par; (void)icp; (void)uold; (void)udot; (void)upold; (void)params;
  fi[0] = sin(u[0]);
  if (ijac >= 1) {
    dint[0 + nint * 0] = cos(u[0]);
    for (int j = 1; j < ndim; j++) dint[0 + nint * j] = 0.0;
  }
  if (ijac >= 2) dint[0 + nint * (ndim + 0)] = dint[0 + nint * (ndim + 1)] = 0.0;
  return 0;
}

static int elastica_int_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t; (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 1.0;
  par[1] = 0.0;
  return 0;
}

static int elastica_int_hessian(int ndim, const double *u, const double *par, int nvar, double *P, double *C,
                                double *R, void *params)
{
  (void)ndim; (void)nvar; (void)params;
  P[0] = 1.0;
  C[0] = 0.0;
  R[0] = -par[0] * cos(u[0]) + par[1] * sin(u[0]);
  return 0;
}

/* the linearised constraint: int cos(theta) v dt = 0 */
static int elastica_int_constraints(int ndim, const double *u, const double *par, int nvar, int ncon, double *a,
                                    double *b, void *params)
{
  (void)ndim; (void)par; (void)nvar; (void)ncon; (void)params;
  a[0] = cos(u[0]);
  b[0] = 0.0;
  return 0;
}

static const cable_variational elastica_int_var = {
  .nvar = 1, .ncon = 1, .nvbc = 0, .hessian = elastica_int_hessian, .constraints = elastica_int_constraints,
};

static const char *const lambda_nu_names[] = {"lambda", "nu"};

static const cable_problem elastica_int = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "elastica_int",
  .description = "Euler column, ends on one line: theta'' + lambda sin theta + nu cos theta = 0, int sin theta = 0",
  .ndim = 2, .nbc = 2, .nint = 1, .npar = 2, .parnames = lambda_nu_names, .unames = theta_names,
  .func = elastica_int_func, .bcnd = elastica_int_bcnd, .icnd = elastica_int_icnd, .stpnt = elastica_int_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1, .icnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
  .variational = &elastica_int_var,
};

const cable_problem *cable_testproblem_elastica_int(void) { return &elastica_int; }

/* ---- boundary layer: eps u'' + u' = 0 ---- */
static int layer_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                      double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp; (void)params;
  double eps = par[1];
  f[0] = u[1];
  f[1] = -u[1] / eps;
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0; dfdu[0 + ndim * 1] = 1.0;
    dfdu[1 + ndim * 0] = 0.0; dfdu[1 + ndim * 1] = -1.0 / eps;
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = dfdp[1 + ndim * 0] = 0.0;
    dfdp[0 + ndim * 1] = 0.0;
    dfdp[1 + ndim * 1] = u[1] / (eps * eps);
  }
  return 0;
}

static int layer_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                      const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)icp; (void)params;
  dirichlet(ndim, nbc, 0, u0, u1, 0.0, par[0], ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 2, ijac, dbc);
  if (ijac >= 2) dbc[1 + nbc * (2 * ndim + 0)] = -1.0;
  return 0;
}

static int layer_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)params;
  /* the exact solution at p = 1 (the test starts there and continues in p) */
  par[0] = 1.0;
  par[1] = 0.01;
  double eps = par[1], den = -expm1(-1.0 / eps);
  u[0] = -expm1(-t / eps) / den;
  u[1] = exp(-t / eps) / (eps * den);
  return 0;
}

static const char *const layer_parnames[] = {"p", "eps"};

static const cable_problem layer = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "layer", .description = "boundary layer: eps u'' + u' = 0, u(0) = 0, u(1) = p",
  .ndim = 2, .nbc = 2, .nint = 0, .npar = 2, .parnames = layer_parnames, .unames = u_names,
  .func = layer_func, .bcnd = layer_bcnd, .stpnt = layer_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
};

const cable_problem *cable_testproblem_layer(void) { return &layer; }

/* ---- stiff dichotomy: u'' = k^2 u, u(0) = 1, u(1) = 2 ---- */
static int stiff_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                      double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp; (void)params;
  double k = par[0];
  f[0] = u[1];
  f[1] = k * k * u[0];
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0; dfdu[0 + ndim * 1] = 1.0;
    dfdu[1 + ndim * 0] = k * k; dfdu[1 + ndim * 1] = 0.0;
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = 0.0;
    dfdp[1 + ndim * 0] = 2.0 * k * u[0];
  }
  return 0;
}

static int stiff_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                      const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par; (void)icp; (void)params;
  dirichlet(ndim, nbc, 0, u0, u1, 1.0, 2.0, ijac, fb, dbc);
  zero_par_columns(nbc, ndim, 1, ijac, dbc);
  return 0;
}

static int stiff_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)params;
  double k = 40.0;
  par[0] = k;
  /* u = [sinh(k(1-t)) + 2 sinh(k t)] / sinh(k), written with decaying exponentials */
  double a = exp(-k * t), b = exp(-k * (1.0 - t)), e2 = exp(-2.0 * k);
  double s = 1.0 - e2;
  u[0] = (a - b * exp(-k) + 2.0 * (b - a * exp(-k))) / s;
  u[1] = k * (-a - b * exp(-k) + 2.0 * (b + a * exp(-k))) / s;
  return 0;
}

static const char *const k_names[] = {"k"};

static const cable_problem stiff = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem),
  .name = "stiff", .description = "exponential dichotomy: u'' = k^2 u, u(0) = 1, u(1) = 2",
  .ndim = 2, .nbc = 2, .nint = 0, .npar = 1, .parnames = k_names, .unames = u_names,
  .func = stiff_func, .bcnd = stiff_bcnd, .stpnt = stiff_stpnt,
  .func_has_jac = 1, .bcnd_has_jac = 1,
  .concurrent = 1, /* FUNC reads only its arguments */
};

const cable_problem *cable_testproblem_stiff(void) { return &stiff; }
