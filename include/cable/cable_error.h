/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Error reports for user input: every message names the file, the line and
 * the key (or script statement) at fault, e.g.
 *   runs/knot72/c.knot72:12: NTST: must be a positive integer, got '-5'   */
#ifndef CABLE_ERROR_H
#define CABLE_ERROR_H

#include "cable/cable_api.h"

#include <stddef.h>

typedef struct cable_error {
  int status;          /* a cable_status code (< 0) */
  char file[512];      /* "" when not from a file */
  int line;            /* 0 when unknown */
  char key[64];        /* constants key, script function or "" */
  char msg[512];
} cable_error;

/* An error handler, as GSL's gsl_error_handler_t and SUNDIALS'
 * KINErrHandlerFn: told the full report of an error (status, file, line,
 * key, message) before the call that met it returns its status.  It is
 * installed per handle, never process-wide (the library keeps no global
 * mutable state, doc/api.md, One error channel): cable_session_options's
 * on_error for a session, cable_cont_set_error_handler for a continuation
 * handle.  ctx is the pointer given with it.  It may not call back into the
 * handle that reports. */
typedef void (*cable_error_handler)(const cable_error *e, void *ctx);

CABLE_API void cable_error_clear(cable_error *e);
/* Fill e (when not NULL) and return status. */
CABLE_API int cable_error_set(cable_error *e, int status, const char *file, int line, const char *key,
                    const char *fmt, ...) __attribute__((format(printf, 6, 7)));
/* "file:line: key: msg" (parts omitted when empty) into buf; returns buf
 * ("" for a NULL error), or "" when buf is NULL or len is 0. */
CABLE_API const char *cable_error_format(const cable_error *e, char *buf, size_t len);

#endif
