/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable's auto_f2c.h for AUTO-07p equation files written in C.
 *
 * cable compiles NAME.c with this header first on the include path.  It gives
 * the f2c types and helper macros that AUTO's C interface uses, and declares
 * the six user routines with their full prototypes, so that a routine with the
 * wrong arguments is a compile error at its own line instead of a crash.  All
 * six must be defined, as for AUTO.  The routines stay static; cable reaches
 * them through the table cable_auto_user at the end of the file.
 */
#ifndef CABLE_AUTO_F2C_H
#define CABLE_AUTO_F2C_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef int integer;
typedef int logical;
typedef float real;
typedef double doublereal;
typedef struct { real r, i; } complex;
typedef struct { doublereal r, i; } doublecomplex;

#define TRUE_ (1)
#define FALSE_ (0)
#define VOID void

#ifndef abs
#define abs(x) ((x) >= 0 ? (x) : -(x))
#endif
#ifndef min
#define min(a, b) ((a) <= (b) ? (a) : (b))
#endif
#ifndef max
#define max(a, b) ((a) >= (b) ? (a) : (b))
#endif
#define dmin(a, b) (doublereal) min(a, b)
#define dmax(a, b) (doublereal) max(a, b)
#define ARRAY2D(array, i, j) array[(i) + (j) * array##_dim1]
#define ARRAY3D(array, i, j, k) array[(i) + ((j) + (k) * array##_dim2) * array##_dim1]

/* AUTO's GETP: a quantity of the solution u that PVLS received */
extern doublereal getp(const char *code, integer ic, const doublereal *u);

typedef int user_func_t(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
                        integer ijac, doublereal *f, doublereal *dfdu, doublereal *dfdp);
typedef int user_stpnt_t(integer ndim, doublereal t, doublereal *u, doublereal *par);
typedef int user_bcnd_t(integer ndim, const doublereal *par, const integer *icp, integer nbc,
                        const doublereal *u0, const doublereal *u1, integer ijac, doublereal *fb,
                        doublereal *dbc);
typedef int user_icnd_t(integer ndim, const doublereal *par, const integer *icp, integer nint,
                        const doublereal *u, const doublereal *uold, const doublereal *udot,
                        const doublereal *upold, integer ijac, doublereal *fi, doublereal *dint);
typedef int user_fopt_t(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
                        integer ijac, doublereal *fs, doublereal *dfdu, doublereal *dfdp);
typedef int user_pvls_t(integer ndim, const doublereal *u, doublereal *par);

#ifndef CABLE_AUTO_NO_USER_TABLE
static user_func_t func;
static user_stpnt_t stpnt;
static user_bcnd_t bcnd;
static user_icnd_t icnd;
static user_fopt_t fopt;
static user_pvls_t pvls;

/* What cable's loader looks up (auto_iface/autoeq/autoeq_load.c). */
typedef struct cable_auto_user_table {
  int version;   /* 1 */
  user_func_t *func;
  user_stpnt_t *stpnt;
  user_bcnd_t *bcnd;
  user_icnd_t *icnd;
  user_fopt_t *fopt;
  user_pvls_t *pvls;
} cable_auto_user_table;
const cable_auto_user_table cable_auto_user = {1, func, stpnt, bcnd, icnd, fopt, pvls};
#endif

#endif
