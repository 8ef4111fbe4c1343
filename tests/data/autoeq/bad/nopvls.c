/* Bratu's problem u'' + lambda exp(u) = 0, u(0) = u(1) = 0, in AUTO's C
 * interface: PAR(1) = lambda, u1 = u, u2 = u'. */
#include "auto_f2c.h"

int func(integer ndim, const doublereal *u, const integer *icp, const doublereal *par, integer ijac,
         doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
  f[0] = u[1];
  f[1] = -par[0] * exp(u[0]);
  if (ijac == 0) return 0;
  dfdu[0] = 0.0;                      /* d f1 / d u1 */
  dfdu[1] = -par[0] * exp(u[0]);      /* d f2 / d u1 */
  dfdu[2] = 1.0;                      /* d f1 / d u2 */
  dfdu[3] = 0.0;
  if (ijac == 1) return 0;
  dfdp[0] = 0.0;
  dfdp[1] = -exp(u[0]);
  return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  par[0] = 0.0;
  u[0] = 0.0;
  u[1] = 0.0;
  return 0;
}

int bcnd(integer ndim, const doublereal *par, const integer *icp, integer nbc, const doublereal *u0,
         const doublereal *u1, integer ijac, doublereal *fb, doublereal *dbc)
{
  fb[0] = u0[0];
  fb[1] = u1[0];
  if (ijac == 0) return 0;
  /* dbc[i + nbc*j]: columns u0 (j < ndim), u1, then PAR(1) */
  for (integer k = 0; k < nbc * (2 * ndim + 1); k++) dbc[k] = 0.0;
  dbc[0 + nbc * 0] = 1.0;
  dbc[1 + nbc * ndim] = 1.0;
  return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp, integer nint, const doublereal *u,
         const doublereal *uold, const doublereal *udot, const doublereal *upold, integer ijac,
         doublereal *fi, doublereal *dint)
{
  return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp, const doublereal *par, integer ijac,
         doublereal *fs, doublereal *dfdu, doublereal *dfdp)
{
  return 0;
}

