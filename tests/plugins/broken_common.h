/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Shared by the deliberately broken plug-ins (each a test of one rejection):
 * a valid one-equation problem that each file then spoils in one way. */
#ifndef CABLE_BROKEN_COMMON_H
#define CABLE_BROKEN_COMMON_H

#include "cable/cable_problem.h"

__attribute__((unused)) static int broken_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                       double *f, double *dfdu, double *dfdp, void *params)
{
  (void)ndim, (void)icp, (void)ijac, (void)dfdu, (void)dfdp, (void)params;
  f[0] = par[0] - u[0];
  return 0;
}

__attribute__((unused)) static int broken_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0,
                       const double *u1, int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim, (void)par, (void)icp, (void)nbc, (void)u1, (void)ijac, (void)dbc, (void)params;
  fb[0] = u0[0];
  return 0;
}

/* A one-equation problem with the given (possibly wrong) fields; a valid one is
 * BROKEN_PROBLEM(CABLE_PROBLEM_ABI, sizeof(cable_problem), 1, 1, broken_func, broken_bcnd, NULL). */
#define BROKEN_PROBLEM(ABI, SIZE, NBC, NPAR, FUNC, BCND, PARNAMES)                         \
  {                                                                                      \
    .abi_version = (ABI), .struct_size = (SIZE), .name = "broken",                       \
    .description = "a deliberately broken plug-in", .ndim = 1, .nbc = (NBC), .nint = 0, \
    .npar = (NPAR), .parnames = (PARNAMES), .func = (FUNC), .bcnd = (BCND)               \
  }
#define BROKEN_OK_ABI CABLE_PROBLEM_ABI
#define BROKEN_OK_SIZE sizeof(cable_problem)

const cable_problem *cable_problem_entry(void);

#endif
