/* The interpreter's state, shared by script_eval.c, script_builtins.c and
 * script_format.c; not part of the public interface. */
#ifndef CABLE_SCRIPT_INTERP_H
#define CABLE_SCRIPT_INTERP_H

#include "script.h"
#include "script_internal.h"

typedef struct script_var {
  char name[SCRIPT_NAME_MAX];
  script_value value;
} script_var;

typedef struct script_interp {
  const script_host *host;
  const char *file;
  cable_error *err;
  script_var *vars;   /* the script's global names (a script has no other scope) */
  size_t nvars, cap;
  long steps;         /* statements + calls so far (SCRIPT_MAX_STEPS) */
} script_interp;

/* One call of a built-in: arguments are owned by the caller. */
typedef struct script_call {
  int line;
  const char *name;
  int nargs;
  const script_value *args;
  script_kwargs kw;
} script_call;

typedef int script_builtin_fn(script_interp *in, const script_call *c, script_value *out);

typedef struct script_builtin {
  const char *name;
  int min_args, max_args;   /* positional */
  int keywords;             /* 1: keyword arguments are passed on (to the host) */
  script_builtin_fn *fn;
} script_builtin;

/* The built-in with this name, or NULL. */
const script_builtin *script_builtin_find(const char *name);

/* Fills in->err and returns status. */
int script_fail(script_interp *in, int status, int line, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 5, 6)));
/* Reports a failed host callback rc with the host's error he, adding the
 * script's file and line and the function name. */
int script_host_fail(script_interp *in, int rc, int line, const char *fname,
                     const cable_error *he);
/* The elements of a value for iteration and len(): lists as they are, dict
 * keys, a handle's items (host).  Strings and scalars are rejected. */
int script_iterable(script_interp *in, int line, const char *what, const script_value *v,
                    script_value *list_out);

/* fmt % arg (Python's printf-style formatting: %d %i %s %r %g %G %e %E %f %F %%). */
int script_format_percent(script_interp *in, int line, const script_value *fmt,
                          const script_value *arg, script_value *out);

#endif
