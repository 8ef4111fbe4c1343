/* The reading "t20 = +t10" of the link conditions (doc/links.md §4.2): the
 * built-in braid_link with (12.3.34) read as T2(0) = +T instead of -T, i.e. the
 * two strands twisted in opposite senses.  A plug-in, so that the built-in
 * problem stays as the paper prints it; FUNC and PVLS are the built-in ones.
 * There is no STPNT: restart from a stored braid_link solution at T = 0,
 * where the two readings coincide (scripts/link_readings/t2plus.auto).
 * Test: test_link_t2plus (every other row is braid_link's). */
#include "braid_bc.h"
#include "braid_model.h"
#include "braid_problems.h"
#include "cable_problem.h"

const cable_problem *cable_problem_entry(void);

static int t2plus_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                       const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  const int rc = braid_link_bcnd(ndim, par, icp, nbc, u0, u1, ijac, fb, dbc, params);
  if (rc != 0) return rc;
  fb[BL_T20] = u0[BR_T2] - par[BP_T];
  if (ijac >= 2) dbc[BL_T20 + nbc * (2 * BR_NDIM + BP_T)] = -1.0;
  return 0;
}

static const char *const t2plus_parnames[BP_NPAR] = {
  "T", "L", "L2", "Ltot", "Delta", "Phi", "w2fix", "B1", "B2", "C1", "C2", "w01", "w02",
  "eps21", "eps13", "F", "FM", "h", "qnorm", "Ham", "pmin", "dmin", "Lk", "Tw", "Wr", "err",
  "Wrerr", "T1", "T2"};

static const cable_problem t2plus_problem = {
  .abi_version = CABLE_PROBLEM_ABI,
  .struct_size = sizeof(cable_problem),
  .name = "link_t2plus",
  .description = "braid_link with T2(0) = +T (reading t20 = t10; doc/links.md)",
  .ndim = BR_NDIM,
  .nbc = BL_NBC,
  .nint = 0,
  .npar = BP_NPAR,
  .parnames = t2plus_parnames,
  .unames = NULL,
  .func = braid_func,
  .bcnd = t2plus_bcnd,
  .pvls = braid_pvls,
  .func_has_jac = 1,
  .bcnd_has_jac = 1,
};

const cable_problem *cable_problem_entry(void) { return &t2plus_problem; }
