/* Run scripts: a small, safe interpreter for the subset of AUTO-07p's Python
 * command language that continuation runs are written in (doc/scripts.md):
 *
 *   flat = run(e='braid_knot', c='knot72', ICP=['T','L'], NMX=200, DS=0.01)
 *   for bp in flat('BP'):
 *       save(run(bp, ISW=-1), 'mode%d' % bp_count)
 *
 * The interpreter knows nothing about the engine.  Every AUTO command (run,
 * load, save, merge, ...) and every operation on a result or a solution
 * (label selection, '+', iteration) is routed to a host: a struct of callbacks
 * (script_host below).  Results and solutions are opaque host handles that the
 * interpreter reference-counts; when the last reference goes the host's
 * release callback is called exactly once.
 *
 * Errors are reported through cable_error with the script file, the line and
 * the function or token at fault; every entry point returns 0 or a negative
 * cable_status code.
 */
#ifndef CABLE_SCRIPT_H
#define CABLE_SCRIPT_H

#include <stddef.h>

#include "cable/cable_error.h"

/* Limits.  A script is untrusted input: these bound memory, recursion and
 * running time whatever the text says.  They are far above what a real
 * continuation script needs (a few dozen statements, a few loops over the
 * special points of a branch). */
#define SCRIPT_MAX_SOURCE (1 << 20)   /* bytes of script text */
#define SCRIPT_MAX_NESTING 64         /* brackets / unary operators nested in one expression */
#define SCRIPT_MAX_EXPR_HEIGHT 256    /* height of one expression tree (a+b+c+... chains) */
#define SCRIPT_MAX_BLOCK_DEPTH 32     /* nested indented blocks (for/if) */
#define SCRIPT_MAX_ARGS 64            /* positional + keyword arguments of one call */
#define SCRIPT_MAX_RANGE 100000       /* elements one range() may produce */
#define SCRIPT_MAX_LIST 1000000       /* elements of any list or dict */
#define SCRIPT_MAX_STRING (1 << 20)   /* bytes of any string value */
#define SCRIPT_MAX_STEPS 1000000L     /* statements + calls executed by one script */
#define SCRIPT_NAME_MAX 64            /* identifier length, including the NUL */

/* ---- values --------------------------------------------------------------- */

typedef enum script_type {
  SCRIPT_NONE = 0,
  SCRIPT_BOOL,
  SCRIPT_NUMBER,
  SCRIPT_STRING,
  SCRIPT_LIST,
  SCRIPT_DICT,
  SCRIPT_HANDLE
} script_type;

/* Kinds of host handles; the interpreter uses them only in messages
 * ("a solution cannot be ...").  Hosts may use other positive values. */
enum script_handle_kind {
  SCRIPT_HANDLE_RESULT = 1,    /* a bundle of branches (AUTO's bifurcation diagram) */
  SCRIPT_HANDLE_SOLUTION = 2   /* one labelled solution of a result */
};

typedef struct script_obj script_obj;   /* reference-counted payload, opaque */

/* A value.  Plain data (None, bool, number) lives in the struct; strings,
 * lists, dicts and handles in a shared, immutable, reference-counted object.
 * A script_value variable owns one reference: copy it with
 * script_value_retain, drop it with script_value_release.  Read the fields
 * through the accessors below. */
typedef struct script_value {
  script_type type;
  int is_int;       /* NUMBER written without '.' or exponent, or from range()/len():
                       only changes how the number is printed (3 vs 3.0) */
  double num;       /* NUMBER; BOOL as 0 or 1 */
  script_obj *obj;  /* STRING, LIST, DICT, HANDLE */
} script_value;

typedef struct script_host script_host;

script_value script_none(void);
script_value script_bool(int b);
script_value script_number(double x);
script_value script_integer(long n);           /* a number printed without ".0" */

/* Constructors of shared objects return 0 or CABLE_ERR_ALLOC / CABLE_ERR_INPUT
 * (too long); *out is None on failure. */
int script_string_new(script_value *out, const char *s, size_t len);
int script_list_new(script_value *out);
/* Appends, taking ownership of item even on failure.  Only for lists the
 * caller has just created and not yet handed to the script (values are
 * immutable once the script sees them). */
int script_list_append(script_value *list, script_value item);
int script_dict_new(script_value *out);
/* Sets key (a string or a number) to value, replacing an equal key; takes
 * ownership of both, even on failure. */
int script_dict_set(script_value *dict, script_value key, script_value value);
/* Wraps a host object.  The host's release callback is called with ptr when
 * the last reference goes, or at once when this function fails. */
int script_handle_new(script_value *out, const script_host *host, int kind, void *ptr);

script_value script_value_retain(const script_value *v);   /* one more reference */
void script_value_release(script_value *v);                /* drops it; *v becomes None */

/* Accessors; they never fail (wrong types give NULL / 0). */
const char *script_type_name(const script_value *v);  /* "number", "string", "result", ... */
const char *script_string_chars(const script_value *v);  /* NUL-terminated, NULL if not a string */
size_t script_string_len(const script_value *v);
size_t script_list_len(const script_value *v);         /* also dicts (number of keys) */
const script_value *script_list_get(const script_value *v, size_t i);
size_t script_dict_len(const script_value *v);
const script_value *script_dict_key(const script_value *v, size_t i);   /* insertion order */
const script_value *script_dict_value(const script_value *v, size_t i);
const script_value *script_dict_find(const script_value *v, const script_value *key);
void *script_handle_ptr(const script_value *v);        /* NULL if not a handle */
int script_handle_kind(const script_value *v);         /* 0 if not a handle */
/* 0 and *out when v is a finite number with an integral value that fits a
 * long; CABLE_ERR_INPUT otherwise. */
int script_value_to_long(const script_value *v, long *out);
/* Python-like text of a value: str() for top level strings, repr() inside
 * lists/dicts (AUTO users read these in messages).  Truncated to len. */
const char *script_value_format(const script_value *v, const script_host *host, char *buf,
                                size_t len);

/* ---- calls ----------------------------------------------------------------- */

/* Keyword arguments of one call, in the order written.  Names and values are
 * borrowed for the duration of the callback. */
typedef struct script_kwarg {
  const char *name;
  script_value value;
} script_kwarg;

typedef struct script_kwargs {
  int n;
  const script_kwarg *items;
} script_kwargs;

/* The value of keyword name, or NULL. */
const script_value *script_kwargs_find(const script_kwargs *kw, const char *name);

/* What load() should produce (AUTO's load vs loadbd). */
enum script_load_what {
  SCRIPT_LOAD_SOLUTION = 1,   /* load(...): a solution (and runner settings) */
  SCRIPT_LOAD_RESULT = 2      /* loadbd(...) / bd(...): a whole result */
};

/* The host.  Conventions for every callback:
 *  - arguments are borrowed; *out starts as None and receives one new
 *    reference (leave it None to return None);
 *  - return 0 on success; anything else is an error: fill err (status < 0,
 *    msg; key = the offending keyword or label, file/line when the error
 *    comes from another file, e.g. a constants file).  The interpreter adds
 *    the script's file, line and function name.  A non-zero return without a
 *    status in err is reported as CABLE_ERR_CALLBACK;
 *  - a NULL callback means "not supported by this host": a script that needs
 *    it stops with CABLE_ERR_UNSUPPORTED.
 */
struct script_host {
  void *ctx;
  /* run([start], KEY=value, ...): start is NULL, a solution, a result or a
   * string (AUTO: files s.NAME/c.NAME).  Unknown keywords are the host's to
   * reject (with err->key set to the keyword). */
  int (*run)(void *ctx, const script_value *start, const script_kwargs *kw, script_value *out,
             cable_error *err);
  /* result(spec): spec NULL (all labelled solutions, as a list), a number
   * (label), a type with a count ('BP1': the first BP, a solution) or a type
   * alone ('BP': a list of all BP solutions, possibly empty). */
  int (*select)(void *ctx, const script_value *result, const script_value *spec,
                script_value *out, cable_error *err);
  /* a + b when a or b is a handle (AUTO: the branches of b appended to a). */
  int (*add)(void *ctx, const script_value *a, const script_value *b, script_value *out,
             cable_error *err);
  /* The elements of a handle as a new list: `for x in h`, len(h), h[i]
   * (AUTO: the branches of a result). */
  int (*items)(void *ctx, const script_value *handle, script_value *list_out, cable_error *err);
  /* h[key] for a handle, e.g. sol['T'] (a parameter by name); NULL: h[i] is
   * items(h)[i]. */
  int (*getitem)(void *ctx, const script_value *handle, const script_value *key,
                 script_value *out, cable_error *err);
  /* load([data], KEY=value, ...) and loadbd/bd: data NULL, a string or a handle. */
  int (*load)(void *ctx, int what, const script_value *data, const script_kwargs *kw,
              script_value *out, cable_error *err);
  /* save(data, 'name'): AUTO writes b.name, s.name, d.name. */
  int (*save)(void *ctx, const script_value *data, const char *name, cable_error *err);
  /* merge(x) / relabel(x): x a result (returns the new result) or a string
   * (the files are rewritten in place; returns None). */
  int (*merge)(void *ctx, const script_value *data, script_value *out, cable_error *err);
  int (*relabel)(void *ctx, const script_value *data, script_value *out, cable_error *err);
  /* clean() / cl(): AUTO deletes fort.* and friends. */
  int (*clean)(void *ctx, cable_error *err);
  /* Any other function name the script calls: return CABLE_ERR_NOTFOUND
   * without touching err when the name is not the host's ("unknown
   * function" is then reported). */
  int (*call)(void *ctx, const char *name, int nargs, const script_value *args,
              const script_kwargs *kw, script_value *out, cable_error *err);
  /* Short text for print() and '%s' of a handle; NULL: "<result>". */
  void (*describe)(void *ctx, const script_value *handle, char *buf, size_t len);
  /* One line printed by print(), without the newline; NULL: stdout. */
  void (*print)(void *ctx, const char *line);
  /* The last reference to a handle went away. */
  void (*release)(void *ctx, void *ptr, int kind);
};

/* ---- running ---------------------------------------------------------------- */

/* Parse the whole text first (syntax errors stop before anything runs), then
 * execute.  name is used in messages ("script.auto:12: ...").  Returns 0 or a
 * negative cable_status; err (may be NULL) says where and why. */
int script_run_string(const char *name, const char *text, const script_host *host,
                      cable_error *err);
/* Reads path (at most SCRIPT_MAX_SOURCE bytes) and runs it. */
int script_run_file(const char *path, const script_host *host, cable_error *err);

#endif
