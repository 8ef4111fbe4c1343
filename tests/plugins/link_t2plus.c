/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The reading "t20 = +t10" of the link conditions (doc/links.md §4.2): the
 * built-in braid_link with (12.3.34) read as T2(0) = +T instead of -T, i.e. the
 * two strands twisted in opposite senses.  A plug-in, so that the built-in
 * problem stays as the paper prints it; FUNC, BCND and PVLS are braid_link's
 * (through the public cable_problem_builtin), only row (12.3.34) differs.
 * There is no STPNT: restart from a stored braid_link solution at T = 0,
 * where the two readings coincide (scripts/link_readings/t2plus.auto).
 * Test: test_link_t2plus (every other row is braid_link's, the layout
 * constants below are those of equations/braid_state.h and bc/braid_bc.h). */
#include "cable/cable_problem.h"

const cable_problem *cable_problem_entry(void);

/* layout of the braid problems (equations/braid_state.h, bc/braid_bc.h) */
enum { NDIM = 21, NBC = 21, NPAR = 30, U_T2 = 12, PAR_T = 0, ROW_T20 = 10 };

static const cable_problem *base(void) { return cable_problem_builtin("braid_link"); }

static int t2plus_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                       double *f, double *dfdu, double *dfdp, void *params)
{
  (void)params;
  const cable_problem *b = base();
  return b->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, b->params);
}

static int t2plus_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                       const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)params;
  const cable_problem *b = base();
  const int rc = b->bcnd(ndim, par, icp, nbc, u0, u1, ijac, fb, dbc, b->params);
  if (rc != 0) return rc;
  fb[ROW_T20] = u0[U_T2] - par[PAR_T];
  if (ijac >= 2) dbc[ROW_T20 + nbc * (2 * NDIM + PAR_T)] = -1.0;
  return 0;
}

static int t2plus_pvls(const struct cable_solution *sol, double *par, void *params)
{
  (void)params;
  const cable_problem *b = base();
  return b->pvls(sol, par, b->params);
}

static const char *const t2plus_parnames[NPAR] = {
  "T", "L", "L2", "Ltot", "Delta", "Phi", "w2fix", "B1", "B2", "C1", "C2", "w01", "w02",
  "eps21", "eps13", "F", "FM", "h", "qnorm", "Ham", "pmin", "dmin", "Lk", "Tw", "Wr", "err",
  "Wrerr", "T1", "T2", "drift"};

static const cable_problem t2plus_problem = {
  .abi_version = CABLE_PROBLEM_ABI,
  .struct_size = sizeof(cable_problem),
  .name = "link_t2plus",
  .description = "braid_link with T2(0) = +T (reading t20 = t10; doc/links.md)",
  .ndim = NDIM,
  .nbc = NBC,
  .nint = 0,
  .npar = NPAR,
  .parnames = t2plus_parnames,
  .unames = NULL,
  .func = t2plus_func,
  .bcnd = t2plus_bcnd,
  .pvls = t2plus_pvls,
  .func_has_jac = 1,
  .bcnd_has_jac = 1,
};

const cable_problem *cable_problem_entry(void) { return &t2plus_problem; }
