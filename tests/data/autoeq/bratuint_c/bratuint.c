/* bratuint.f90 in AUTO's C interface: Bratu's problem with the integral
 * condition  integral of u = PAR(2)  and PVLS reporting GETP's values. */
#include "auto_f2c.h"

int func(integer ndim, const doublereal *u, const integer *icp, const doublereal *par, integer ijac,
         doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
  /* ICP as AUTO passes it: 1-based, the free parameters PAR(1), PAR(2) first,
     then the printed ones; cable treats a negative return as fatal (AUTO
     ignores the return value) */
  if (icp[0] != 1 || icp[1] != 2 || icp[2] != 3 || icp[7] != 8) return -1;
  f[0] = u[1];
  f[1] = -par[0] * exp(u[0]);
  return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
  par[0] = par[1] = 0.0;
  u[0] = u[1] = 0.0;
  return 0;
}

int bcnd(integer ndim, const doublereal *par, const integer *icp, integer nbc, const doublereal *u0,
         const doublereal *u1, integer ijac, doublereal *fb, doublereal *dbc)
{
  fb[0] = u0[0];
  fb[1] = u1[0];
  return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp, integer nint, const doublereal *u,
         const doublereal *uold, const doublereal *udot, const doublereal *upold, integer ijac,
         doublereal *fi, doublereal *dint)
{
  fi[0] = u[0] - par[1];
  return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp, const doublereal *par, integer ijac,
         doublereal *fs, doublereal *dfdu, doublereal *dfdp)
{
  return 0;
}

int pvls(integer ndim, const doublereal *u, doublereal *par)
{
  par[2] = getp("INT", 1, u);
  par[3] = getp("MAX", 1, u);
  par[4] = getp("BV0", 2, u);
  par[5] = getp("NRM", 1, u);
  par[6] = getp("BV1", 2, u);
  par[7] = getp("MIN", 2, u);
  return 0;
}
