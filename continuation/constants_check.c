/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Counts, indices and strings of a cable_constants struct (constants_check.h). */
#include "constants_check.h"

#include <stdio.h>
#include <string.h>

#include "cable/cable_status.h"

#define NELEM(a) ((int)(sizeof(a) / sizeof((a)[0])))

static int count_ok(const char *key, int n, int max, cable_error *err)
{
  if (n >= 0 && n <= max) return 0;
  return cable_error_set(err, CABLE_ERR_SIZE, NULL, 0, key, "%s = %d: the constants hold 0..%d entries", key, n, max);
}

static int index_ok(const char *key, int k, int i, int npar, cable_error *err)
{
  if (i >= 0 && i < npar) return 0;
  return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, key, "%s entry %d is PAR(%d), outside PAR(1)..PAR(%d)", key,
                         k + 1, i + 1, npar);
}

static int string_ok(const char *key, const char *s, size_t size, cable_error *err)
{
  if (memchr(s, '\0', size)) return 0;
  return cable_error_set(err, CABLE_ERR_SIZE, NULL, 0, key, "%s is not terminated within its %zu bytes", key, size);
}

int cable_constants_consistent(const cable_constants *c, int npar, cable_error *err)
{
  if (!c) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "the constants are NULL");
  if (c->npar < 0 || c->npar > CABLE_NAMES_MAX)
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, "NPAR", "NPAR = %d outside 0..%d", c->npar, CABLE_NAMES_MAX);
  if (npar > CABLE_NAMES_MAX) npar = CABLE_NAMES_MAX;
  int rc;
  if ((rc = count_ok("NICP", c->nicp, CABLE_MAX_ICP, err)) || (rc = count_ok("NUZR", c->nuzr, CABLE_MAX_UZR, err)) ||
      (rc = count_ok("NTHL", c->nthl, CABLE_MAX_THL, err)) ||
      (rc = count_ok("PAR (overrides)", c->npar_override, NELEM(c->par_override), err)) ||
      (rc = count_ok("STOP", c->nstop, NELEM(c->stop_on), err)) ||
      (rc = count_ok("problem keys", c->npkey, CABLE_MAX_PKEYS, err)))
    return rc;
  for (int k = 0; k < c->nuzr; k++)
    if ((rc = index_ok("UZR", k, c->uzr[k].par, npar, err))) return rc;
  for (int k = 0; k < c->nthl; k++)
    if ((rc = index_ok("THL", k, c->thl[k].index, npar, err))) return rc;
  for (int k = 0; k < c->npar_override; k++)
    if ((rc = index_ok("PAR", k, c->par_override[k].index, npar, err))) return rc;
  if (c->nthreads < 0 || c->nthreads > CABLE_THREADS_MAX)
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, "NTHREADS", "NTHREADS = %d outside 0..%d", c->nthreads,
                           CABLE_THREADS_MAX);
  if (c->linsolver != CABLE_LINSOLVER_CONDENSE && c->linsolver != CABLE_LINSOLVER_KLU)
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, "LINSOLVER", "LINSOLVER = %d is neither condense (0) nor klu (1)",
                           (int)c->linsolver);
  const struct {
    const char *key;
    const char *s;
    size_t size;
  } str[] = {{"IRS", c->irs_name, sizeof c->irs_name}, {"e", c->e, sizeof c->e},     {"s", c->s, sizeof c->s},
             {"sv", c->sv, sizeof c->sv},               {"dat", c->dat, sizeof c->dat}, {"ignored keys", c->ignored, sizeof c->ignored},
             {"NDIM (origin)", c->origin_ndim.file, sizeof c->origin_ndim.file},
             {"NBC (origin)", c->origin_nbc.file, sizeof c->origin_nbc.file},
             {"NINT (origin)", c->origin_nint.file, sizeof c->origin_nint.file}};
  for (int k = 0; k < NELEM(str); k++)
    if ((rc = string_ok(str[k].key, str[k].s, str[k].size, err))) return rc;
  for (int k = 0; k < c->npkey; k++)
    if ((rc = string_ok("problem key", c->pkey[k].name, sizeof c->pkey[k].name, err))) return rc;
  return 0;
}

int cable_ext_alloc_check(const char *fn, const cable_problem *pb, const cable_constants *c, char *msg, size_t len)
{
  if (!pb || !c) {
    snprintf(msg, len, "%s: %s is NULL", fn, !pb ? "the problem" : "the constants");
    return CABLE_ERR_NULL;
  }
  cable_error cerr;
  int st = cable_constants_consistent(c, c->npar > pb->npar ? c->npar : pb->npar, &cerr);
  if (st) snprintf(msg, len, "%s", cerr.msg);
  return st;
}

void cable_ext_icp_order(const cable_constants *c, int k, cable_constants *out)
{
  *out = *c;
  if (k < 2 || c->nicp < k + 1) return;
  out->icp[1] = c->icp[k];
  for (int j = 1; j < k; j++) out->icp[j + 1] = c->icp[j];
}
