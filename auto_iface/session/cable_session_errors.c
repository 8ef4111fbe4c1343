/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The session's error channel (doc/api.md, One error channel): every public
 * call on a session returns a status and fills the caller's cable_error;
 * the session's handler (cable_session_options.on_error) is told the same
 * report before the call returns, also when the caller passed no err.  The
 * handler lives in the session: nothing here is process-wide. */
#include <stdio.h>

#include "cable/cable_status.h"
#include "cable_session_impl.h"

/* The report of rc: the body's, or the status's message when the body set
 * none; told to the handler. */
static int report(const cable_session *s, int rc, cable_error *e)
{
  if (rc >= 0 || rc == CABLE_ERR_INTERRUPTED) return rc;   /* a stop the caller asked for is no error */
  if (e->status == 0 || !e->msg[0]) {
    e->status = rc;
    snprintf(e->msg, sizeof e->msg, "%s", cable_status_message(rc));
  }
  if (s && s->opt.on_error) s->opt.on_error(e, s->opt.on_error_ctx);
  return rc;
}

/* The caller's err, or local when it passed none (the handler still gets
 * the report), cleared. */
static cable_error *target(cable_error *err, cable_error *local)
{
  cable_error *e = err ? err : local;
  cable_error_clear(e);
  return e;
}

int cable_session_create(const cable_session_options *opt, cable_session **out, cable_error *err)
{
  if (out) *out = NULL;
  if (!out) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_session_create: out is NULL");
  cable_session *s = cable_session_alloc(opt);
  if (!s) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "cable_session_create: out of memory");
  *out = s;
  return CABLE_SUCCESS;
}

int cable_session_run(cable_session *s, const cable_run_args *a, cable_branch **out, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_run(s, a, out, e), e);
}

int cable_session_info(cable_session *s, const char *name, FILE *out, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_info(s, name, out, e), e);
}

int cable_session_load(cable_session *s, const cable_run_args *a, cable_branch **out, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_load(s, a, out, e), e);
}

int cable_session_save(cable_session *s, cable_branch *const *branches, int n, int sol_index, const char *name,
                       int append, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_save(s, branches, n, sol_index, name, append, e), e);
}

int cable_session_loadbd(cable_session *s, const char *name, cable_branch ***out, int *n, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_loadbd(s, name, out, n, e), e);
}

int cable_session_transform(cable_session *s, cable_branch *const *in, int n, int relabel, cable_branch ***out,
                            int *nout, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_transform(s, in, n, relabel, out, nout, e), e);
}

int cable_session_transform_files(cable_session *s, const char *name, int relabel, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_transform_files(s, name, relabel, e), e);
}

int cable_session_add_known(cable_session *s, const cable_branch *b, int sol_index, cable_error *err)
{
  cable_error local, *e = target(err, &local);
  return report(s, rp_session_add_known(s, b, sol_index, e), e);
}
