/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Template plug-in: the Bratu problem (AUTO-07p's demo 'exp' is the same
 * equation), written as a cable problem.  Copy this file to start your own;
 * doc/plugins.md explains every field.  Build it with one command from the
 * cable source tree:
 *
 *   cc -shared -fPIC -I auto_iface -I continuation tests/plugins/bratu_plugin.c -o bratu.so
 *
 * The problem: u'' + lambda e^u = 0 on [0, 1], u(0) = u(1) = 0, as the
 * first-order system
 *
 *   u1' = u2,   u2' = -lambda e^{u1},   u1(0) = 0,   u1(1) = 0,
 *
 * with PAR(1) = lambda.  NBC + NINT - NDIM + 1 = 1 free parameter (lambda):
 * a one-parameter family starting at u = 0, lambda = 0, with a fold at
 * lambda = 3.5138...  PAR(2) = umax is a derived quantity (PVLS): the largest
 * value of u1 on the solution, which the b-file can print after lambda by
 * listing it in ICP.
 */
#include <math.h>
#include <stddef.h>

#include "cable/cable_problem.h"
#include "cable/cable_solution.h"

/* FUNC: f(u, par).  ijac = 0 values only; 1 also dfdu; 2 also dfdp.  Arrays
 * are column-major: dfdu[i + ndim*j] = d f_i / d u_j. */
static int bratu_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                      double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp;      /* the free parameters: only their dfdp columns are read */
  (void)params;   /* this problem has no private data */
  double lambda = par[0];
  double e = exp(u[0]);
  if (!isfinite(e)) return 1;   /* > 0: recoverable, the engine retries with a smaller step */
  f[0] = u[1];
  f[1] = -lambda * e;
  if (ijac >= 1) {
    dfdu[0 + ndim * 0] = 0.0;          /* d f1 / d u1 */
    dfdu[1 + ndim * 0] = -lambda * e;  /* d f2 / d u1 */
    dfdu[0 + ndim * 1] = 1.0;          /* d f1 / d u2 */
    dfdu[1 + ndim * 1] = 0.0;          /* d f2 / d u2 */
  }
  if (ijac >= 2) {
    dfdp[0 + ndim * 0] = 0.0;          /* d f / d lambda */
    dfdp[1 + ndim * 0] = -e;
    dfdp[0 + ndim * 1] = 0.0;          /* umax does not enter f */
    dfdp[1 + ndim * 1] = 0.0;
  }
  return 0;
}

/* BCND: fb(u(0), u(1), par) = 0.  dbc[i + nbc*j]: columns 0..ndim-1 are
 * u(0), ndim..2ndim-1 are u(1), then the parameters. */
static int bratu_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                      const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)par;
  (void)icp;
  (void)params;
  fb[0] = u0[0];
  fb[1] = u1[0];
  if (ijac >= 1) {
    int ncols = 2 * ndim + (ijac >= 2 ? 2 : 0);   /* 2 = this problem's npar */
    for (int k = 0; k < nbc * ncols; k++) dbc[k] = 0.0;
    dbc[0 + nbc * 0] = 1.0;            /* d fb1 / d u1(0) */
    dbc[1 + nbc * ndim] = 1.0;         /* d fb2 / d u1(1) */
  }
  return 0;
}

/* STPNT: the trivial solution u = 0 at lambda = 0, for every t. */
static int bratu_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)t;
  (void)params;
  for (int i = 0; i < ndim; i++) u[i] = 0.0;
  par[0] = 0.0;   /* lambda */
  par[1] = 0.0;   /* umax */
  return 0;
}

/* PVLS: derived values of a converged solution.  u[k*ndim + i] is u_i at
 * the stored point t[k]. */
static int bratu_pvls(const struct cable_solution *sol, double *par, void *params)
{
  (void)params;
  int npts = sol->ntst * sol->ncol + 1;
  double umax = sol->u[0];
  for (int k = 1; k < npts; k++)
    if (sol->u[k * sol->ndim] > umax) umax = sol->u[k * sol->ndim];
  par[1] = umax;
  return 0;
}

static const char *const bratu_parnames[] = {"lambda", "umax"};
static const char *const bratu_unames[] = {"u", "du"};

static const cable_problem bratu_problem = {
  .abi_version = CABLE_PROBLEM_ABI,
  .struct_size = sizeof(cable_problem),
  .name = "bratu",
  .description = "Bratu problem u'' + lambda e^u = 0, u(0) = u(1) = 0",
  .ndim = 2,
  .nbc = 2,
  .nint = 0,
  .npar = 2,
  .parnames = bratu_parnames,
  .unames = bratu_unames,
  .func = bratu_func,
  .bcnd = bratu_bcnd,
  .icnd = NULL,
  .stpnt = bratu_stpnt,
  .pvls = bratu_pvls,
  .func_has_jac = 1,
  .bcnd_has_jac = 1,
  .icnd_has_jac = 0,
  .params = NULL,
};

/* The one symbol cable looks for.  The prototype keeps -Wmissing-prototypes
 * quiet; the definition must have external linkage. */
const cable_problem *cable_problem_entry(void);
const cable_problem *cable_problem_entry(void)
{
  return &bratu_problem;
}
