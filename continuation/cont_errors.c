/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The continuation handle's error channel (doc/api.md, One error channel):
 * the public calls that work on a handle return a status; the report behind
 * an error (status, key, message) is cable_cont_last_error's, and a handler
 * installed on the handle is told it before the call returns.  The handler
 * lives in the handle: nothing here is process-wide. */
#include <stdio.h>
#include <string.h>

#include "cont_impl.h"

/* The handle's report of the error rc a call just returned: the message the
 * call set, or the status's own when it set none (a NULL argument) and the
 * error is not the same one again (a call on a handle whose branch ended
 * with an error returns it again, with its message). */
static int report(cable_cont *cc, int rc, long nerr_before)
{
  if (!cc || rc >= 0) return rc;
  if (cc->nerr == nerr_before && rc != cc->err_status) {
    snprintf(cc->err, sizeof cc->err, "%s", cable_status_message(rc));
    cc->err_key[0] = '\0';
  }
  cc->err_status = rc;
  if (cc->on_error) {
    cable_error e;
    cable_cont_last_error(cc, &e);
    cc->on_error(&e, cc->on_error_ctx);
  }
  return rc;
}

int cable_cont_last_error(const cable_cont *cc, cable_error *out)
{
  if (!out) return CABLE_ERR_NULL;
  cable_error_clear(out);
  if (!cc) return cable_error_set(out, CABLE_ERR_NULL, NULL, 0, NULL, "cable_cont_last_error: the handle is NULL");
  out->status = cc->err_status;
  snprintf(out->key, sizeof out->key, "%s", cc->err_key);
  snprintf(out->msg, sizeof out->msg, "%s", cc->err);
  return cc->err_status;
}

int cable_cont_set_error_handler(cable_cont *cc, cable_error_handler fn, void *ctx)
{
  if (!cc) return CABLE_ERR_NULL;
  cc->on_error = fn;
  cc->on_error_ctx = fn ? ctx : NULL;
  return CABLE_SUCCESS;
}

int cable_cont_create(const cable_problem *pb, const cable_constants *c, cable_cont **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!out) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_cont_create: out is NULL");
  int rc = cable_cont_check(pb, c, err);
  if (rc) return rc;
  cable_cont *cc = cable_cont_alloc(pb, c, &rc);
  if (!cc)
    return cable_error_set(err, rc, NULL, 0, NULL, "cable_cont_create: the workspaces of NTST = %d, NCOL = %d: %s",
                           c->ntst, c->ncol, cable_status_message(rc));
  *out = cc;
  return CABLE_SUCCESS;
}

int cable_cont_set_mesh(cable_cont *cc, const double *mesh)
{
  long n0 = cc ? cc->nerr : 0;
  return report(cc, cont_set_mesh(cc, mesh), n0);
}

int cable_cont_set_start(cable_cont *cc, const cable_solution *start)
{
  long n0 = cc ? cc->nerr : 0;
  return report(cc, cont_set_start(cc, start), n0);
}

int cable_cont_step(cable_cont *cc)
{
  long n0 = cc ? cc->nerr : 0;
  return report(cc, cont_step(cc), n0);
}

int cable_cont_run(cable_cont *cc, const cable_sink *sink, int ibr, int first_label, int *next_label)
{
  long n0 = cc ? cc->nerr : 0;
  int rc = cont_run(cc, sink, ibr, first_label, next_label);
  /* a stop the sink asked for is the caller's own, not an error to report */
  return rc == CABLE_ERR_INTERRUPTED ? rc : report(cc, rc, n0);
}
