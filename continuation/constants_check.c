/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Counts, indices and strings of a cable_constants struct (constants_check.h). */
#include "constants_check.h"

#include <stdio.h>
#include <stdlib.h>
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

int cable_int_range_msg(long v, double lo, double hi, char *msg, size_t len)
{
  if ((double)v >= lo && (double)v <= hi) return 0;
  if (hi >= (double)CABLE_CK_BIG)
    snprintf(msg, len, "must be an integer >= %d, got %ld", (int)lo, v);
  else
    snprintf(msg, len, "must be an integer in %d..%d, got %ld", (int)lo, (int)hi, v);
  return 1;
}

/* which kinds of the key table cable_constants_int_ranges checks: 1 the
   range, 2 the range or 0 */
#define RANGE_INT 1
#define RANGE_NPAR 1
#define RANGE_STAB 1
#define RANGE_DIM 2
#define RANGE_IPS 0
#define RANGE_ISW 0
#define RANGE_REAL 0
#define RANGE_POS 0
#define RANGE_DS 0
#define RANGE_STR 0
#define RANGE_NAME 0
#define RANGE_NAMES 0
#define RANGE_PAR 0
#define RANGE_IRS 0
#define RANGE_ICP 0
#define RANGE_THL 0
#define RANGE_THU 0
#define RANGE_UZR 0
#define RANGE_UZSTOP 0
#define RANGE_STOP 0
#define RANGE_LINSOLVER 0
/* the value of an integer kind's field (0 for the others, never read) */
#define FIELD_1(c, f) (long)(c)->f
#define FIELD_2(c, f) (long)(c)->f
#define FIELD_0(c, f) 0L
#define FIELD_(r, c, f) FIELD_##r(c, f)
#define FIELD(r, c, f) FIELD_(r, c, f)

int cable_constants_int_ranges(const cable_constants *c, char *msg, size_t len)
{
  char m[160];
#define RANGE_ROW(key, field, kind, who, def, lo, hi, line)                                         \
  if (RANGE_##kind) {                                                                          \
    long v = FIELD(RANGE_##kind, c, field);                                                   \
    if (!(RANGE_##kind == 2 && v == 0) && cable_int_range_msg(v, lo, hi, m, sizeof m))          \
      return snprintf(msg, len, "%s: %s", #key, m), CABLE_ERR_INPUT;                          \
  }
  CABLE_CONSTANTS_KEYS(RANGE_ROW)
#undef RANGE_ROW
  return 0;
}

void *cable_ext_alloc_open(const char *fn, const cable_problem *pb, const cable_constants *c, size_t size,
                           cable_ext_sink *sink, int **status, char **msg, size_t *len)
{
  if (!*status) *status = &sink->status;
  if (!*msg) {
    *msg = sink->msg;
    *len = sizeof sink->msg;
  }
  if (!pb || !c) {
    snprintf(*msg, *len, "%s: %s is NULL", fn, !pb ? "the problem" : "the constants");
    **status = CABLE_ERR_NULL;
    return NULL;
  }
  cable_error cerr;
  if ((**status = cable_constants_consistent(c, c->npar > pb->npar ? c->npar : pb->npar, &cerr)) != 0) {
    snprintf(*msg, *len, "%s", cerr.msg);
    return NULL;
  }
  void *f = calloc(1, size);
  if (!f) {
    **status = CABLE_ERR_ALLOC;
    snprintf(*msg, *len, "out of memory");
  }
  return f;
}

void cable_ext_icp_order(const cable_constants *c, int k, cable_constants *out)
{
  *out = *c;
  if (k < 2 || c->nicp < k + 1) return;
  out->icp[1] = c->icp[k];
  for (int j = 1; j < k; j++) out->icp[j + 1] = c->icp[j];
}
