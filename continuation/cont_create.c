/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The status-returning constructors (doc/api.md, One error channel): the
 * object in *out and 0, or *out NULL and a status with its message in err,
 * for the objects whose older constructors answer NULL (cable_solution_alloc)
 * or a status and a message buffer (cable_fold_alloc, cable_bpcont_alloc). */
#include <limits.h>
#include <stdio.h>

#include "cable/cable_bpcont.h"
#include "cable/cable_error.h"
#include "cable/cable_fold.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"

/* status and message of an older constructor that failed */
static int failed(cable_error *err, int st, const char *msg)
{
  if (st >= 0) st = CABLE_ERR_ALLOC;   /* NULL without a status: memory ran out */
  return cable_error_set(err, st, NULL, 0, NULL, "%s", msg && msg[0] ? msg : cable_status_message(st));
}

int cable_solution_create(int ndim, int ntst, int ncol, int npar, int nfpr, cable_solution **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!out) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_solution_create: out is NULL");
  long long npts = (long long)ntst * ncol + 1;
  if (ndim < 1 || ntst < 1 || ncol < 1 || npar < 1 || nfpr < 0 || npts > INT_MAX || npts * ndim > INT_MAX ||
      nfpr == INT_MAX)
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, NULL,
                           "cable_solution_create: sizes NDIM = %d, NTST = %d, NCOL = %d, NPAR = %d, NFPR = %d "
                           "(NDIM, NTST, NCOL, NPAR >= 1, NFPR >= 0, (NTST NCOL + 1) NDIM within an int)",
                           ndim, ntst, ncol, npar, nfpr);
  cable_solution *s = cable_solution_alloc(ndim, ntst, ncol, npar, nfpr);
  if (!s) return failed(err, CABLE_ERR_ALLOC, "cable_solution_create: out of memory");
  *out = s;
  return CABLE_SUCCESS;
}

int cable_fold_create(const cable_problem *pb, const cable_constants *c, const cable_solution *start, cable_fold **out,
                      cable_error *err)
{
  if (out) *out = NULL;
  if (!pb || !c || !start || !out)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_fold_create: %s is NULL",
                           !pb ? "the problem" : !c ? "the constants" : !start ? "the start" : "out");
  int st = 0;
  char msg[512] = "";
  cable_fold *f = cable_fold_alloc(pb, c, start, &st, msg, sizeof msg);
  if (!f) return failed(err, st, msg);
  *out = f;
  return CABLE_SUCCESS;
}

int cable_bpcont_create(const cable_problem *pb, const cable_constants *c, const cable_solution *start,
                        cable_bpcont **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!pb || !c || !start || !out)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_bpcont_create: %s is NULL",
                           !pb ? "the problem" : !c ? "the constants" : !start ? "the start" : "out");
  int st = 0;
  char msg[512] = "";
  cable_bpcont *f = cable_bpcont_alloc(pb, c, start, &st, msg, sizeof msg);
  if (!f) return failed(err, st, msg);
  *out = f;
  return CABLE_SUCCESS;
}
