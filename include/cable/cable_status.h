/* SPDX-License-Identifier: GPL-3.0-or-later */
/* One table of status codes and their messages (SUNDIALS style).
 * 0 is success, > 0 a normal end of a branch, < 0 an error. */
#ifndef CABLE_STATUS_H
#define CABLE_STATUS_H

#include "cable/cable_api.h"

#define CABLE_STATUS_TABLE(X) \
  X(CABLE_SUCCESS,          0, "success") \
  X(CABLE_END_NMX,          1, "NMX points computed") \
  X(CABLE_END_BOUNDS,       2, "a parameter or norm limit (RL0, RL1, A0, A1) was reached") \
  X(CABLE_END_UZSTOP,       3, "a user zero with UZSTOP was reached") \
  X(CABLE_END_STOP,         4, "a STOP condition was met") \
  X(CABLE_END_LOOP,         5, "the branch closed on itself (a closed loop)") \
  X(CABLE_ERR_ALLOC,       -1, "out of memory") \
  X(CABLE_ERR_INPUT,       -2, "invalid input") \
  X(CABLE_ERR_NEWTON,      -3, "Newton iteration did not converge") \
  X(CABLE_ERR_DSMIN,       -4, "no convergence with step size DSMIN") \
  X(CABLE_ERR_CALLBACK,    -5, "a problem callback reported a fatal error") \
  X(CABLE_ERR_RECOVERABLE, -6, "a problem callback rejected the point (recoverable)") \
  X(CABLE_ERR_LINSOLVE,    -7, "the linear system is singular or could not be solved") \
  X(CABLE_ERR_KINSOL,      -8, "KINSOL reported an error") \
  X(CABLE_ERR_IO,          -9, "file input or output failed") \
  X(CABLE_ERR_PARSE,      -10, "syntax error") \
  X(CABLE_ERR_PLUGIN,     -11, "the plug-in was rejected") \
  X(CABLE_ERR_NOTFOUND,   -12, "not found") \
  X(CABLE_ERR_UNSUPPORTED,-13, "not supported by cable") \
  X(CABLE_ERR_NONFINITE,  -14, "a NaN or Inf appeared") \
  X(CABLE_ERR_SWITCH,     -15, "branch switching failed") \
  X(CABLE_ERR_NULL,       -16, "a required handle or argument is NULL") \
  X(CABLE_ERR_STATE,      -17, "the handle is not in a state for this call (wrong order of calls)") \
  X(CABLE_ERR_SIZE,       -18, "sizes do not match") \
  X(CABLE_ERR_RANGE,      -19, "an argument is out of its range") \
  X(CABLE_ERR_INTERRUPTED,-20, "interrupted")

enum cable_status {
#define CABLE_STATUS_ENUM(name, value, msg) name = value,
  CABLE_STATUS_TABLE(CABLE_STATUS_ENUM)
#undef CABLE_STATUS_ENUM
};

/* Message for a status code; never NULL. */
CABLE_API const char *cable_status_message(int status);
/* Symbolic name ("CABLE_ERR_DSMIN"); never NULL. */
CABLE_API const char *cable_status_name(int status);

#endif
