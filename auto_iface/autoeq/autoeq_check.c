/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Which equation files a run can use: the rule is AUTO's own, "what AUTO can
 * run", applied to the routines this run calls (FUNC always; BCND when
 * NBC > 0; ICND when NINT > 0; STPNT for a start from STPNT; PVLS when it has
 * arguments; FOPT never, it is for AUTO's algebraic optimisation problems).
 *
 * AUTO calls a Fortran routine with its argument list by reference and never
 * checks the callee's declarations.  So, for a called routine:
 *  - an argument of another type than AUTO's passes unless the routine uses
 *    it: COMPLEX(KIND(1.0D0)) where AUTO passes DOUBLE PRECISION reads the
 *    same storage as (re, im) pairs and is accepted; INTEGER, REAL (single
 *    precision, e.g. by Fortran's implicit typing) or anything else would
 *    read AUTO's numbers as other numbers;
 *  - fewer arguments than AUTO passes are fine (the legacy STPNT(NDIM,U,PAR)
 *    of AUTO's older versions) as long as the routine has the outputs the run
 *    takes from it: F (and DFDU with JAC != 0, DFDP with JAC = 1) from FUNC,
 *    FB (DBC) from BCND, FI (DINT) from ICND, U from STPNT;
 *  - more arguments than AUTO passes are fine unless the routine uses one of
 *    them (it would read memory AUTO never passed);
 *  - an output the run takes that the routine never sets (an argument-less
 *    dummy, or a stub whose F, FB, FI or U is unused) is refused: AUTO would
 *    compute with uninitialised numbers.
 * Uses are gfortran's (-Wunused-dummy-argument, autoeq_build.c).  C files are
 * checked by the compiler against auto_f2c.h's prototypes instead. */
#include <stdio.h>
#include <string.h>

#include "autoeq_impl.h"
#include "cable/cable_status.h"

static const char *type_name(char t)
{
  switch (t) {
  case 'i': return "INTEGER";
  case 'd': return "DOUBLE PRECISION";
  case 'z': return "COMPLEX(KIND(1.0D0))";
  case 'r': return "REAL (single precision; an implicitly typed argument is REAL unless IMPLICIT DOUBLE "
                   "PRECISION (A-H,O-Z) says otherwise)";
  case 'c': return "COMPLEX (single precision)";
  default: return "of another type";
  }
}

/* The outputs a run takes from routine r: the 1-based position of the last
 * argument it needs (0: none), that argument (*what) and, when JAC is why
 * it is needed, 1 in *by_jac. */
static int needed_args(int r, int jac, const char **what, int *by_jac)
{
  *by_jac = 0;
  switch (r) {
  case AE_FUNC:
    *by_jac = jac != 0;
    *what = jac == 1 ? "DFDP (argument 8)" : jac != 0 ? "DFDU (argument 7)" : "F (argument 6)";
    return jac == 1 ? 8 : jac != 0 ? 7 : 6;
  case AE_BCND:
    *by_jac = jac != 0;
    *what = jac != 0 ? "DBC (argument 9)" : "FB (argument 7)";
    return jac != 0 ? 9 : 7;
  case AE_ICND:
    *by_jac = jac != 0;
    *what = jac != 0 ? "DINT (argument 11)" : "FI (argument 9)";
    return jac != 0 ? 11 : 9;
  case AE_STPNT: *what = "U (argument 2)"; return 2;
  default: *what = ""; return 0;
  }
}

/* The argument whose value the run always takes (F, U, FB, FI), 1-based. */
static int output_arg(int r)
{
  static const int pos[AE_NROUTINES] = {6, 2, 7, 9, 0, 0};
  return pos[r];
}

static int check_routine(const cable_autoeq *m, int r, const char *why, int jac, cable_error *err)
{
  const char *name = autoeq_routine_name[r], *sig = autoeq_auto_sig[r], *auto_args = autoeq_auto_args[r];
  int n = m->nargs[r], line = m->def_line[r], nauto = (int)strlen(auto_args);
  for (int a = 0; a < n && a < AUTOEQ_MAX_ARGS; a++) {
    int used = !(m->unused[r] & (1UL << a));
    char t = m->argtype[r][a];
    if (a >= nauto) {
      if (used)
        return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, line, name, "has %d arguments, AUTO passes %d, and "
                               "uses argument %d (%s), which AUTO does not pass: AUTO calls %s", n, nauto, a + 1,
                               m->argname[r][a], sig);
      continue;
    }
    int fits = t == auto_args[a] || (auto_args[a] == 'd' && t == 'z');
    if (!fits && used)
      return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, line, name, "argument %d (%s) is %s, AUTO passes %s: "
                             "AUTO calls %s", a + 1, m->argname[r][a], type_name(t),
                             auto_args[a] == 'i' ? "an INTEGER" : "DOUBLE PRECISION", sig);
  }
  const char *what;
  int by_jac;
  int need = needed_args(r, jac, &what, &by_jac);
  char reason[64];
  if (by_jac) snprintf(reason, sizeof reason, "JAC=%d", jac);
  else snprintf(reason, sizeof reason, "%s", why);
  if (n < need)
    return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, line, name, "has %d arguments, but the run takes %s from "
                           "it (%s): AUTO calls %s", n, what, reason, sig);
  int out = output_arg(r);
  if (out > 0 && out <= AUTOEQ_MAX_ARGS && (m->unused[r] & (1UL << (out - 1))))
    return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, line, name, "never sets %s (argument %d), but %s",
                           m->argname[r][out - 1], out, why);
  return 0;
}

int autoeq_check_called(const cable_autoeq *m, const cable_constants *c, cable_error *err)
{
  if (m->lang != AUTOEQ_FORTRAN) return 0;
  char why[64];
  int rc = check_routine(m, AE_FUNC, "AUTO calls FUNC in every run", c->jac, err);
  snprintf(why, sizeof why, "NBC=%d", c->nbc);
  if (!rc && c->nbc > 0 && m->nargs[AE_BCND] > 0) rc = check_routine(m, AE_BCND, why, c->jac, err);
  snprintf(why, sizeof why, "NINT=%d", c->nint);
  if (!rc && c->nint > 0 && m->nargs[AE_ICND] > 0) rc = check_routine(m, AE_ICND, why, c->jac, err);
  if (!rc && c->irs == 0 && !c->irs_name[0] && m->nargs[AE_STPNT] > 0)
    rc = check_routine(m, AE_STPNT, "the run starts from STPNT (IRS=0)", c->jac, err);
  if (!rc && m->nargs[AE_PVLS] > 0) rc = check_routine(m, AE_PVLS, "AUTO calls PVLS at every point", c->jac, err);
  return rc;
}
