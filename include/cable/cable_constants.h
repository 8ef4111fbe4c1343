/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO-07p constants, as the engine consumes them.  Field names follow AUTO's
 * keywords; defaults (cable_constants_init) are AUTO-07p's unless noted in
 * doc/constants.md.  Parameter indices in icp/uzr/thl are 0-based here
 * (AUTO's PAR(k) is index k-1); the constants-file parser converts. */
#ifndef CABLE_CONSTANTS_H
#define CABLE_CONSTANTS_H

#include "cable/cable_api.h"
#include "cable/cable_constants_keys.h"
#include "cable/cable_error.h"
#include "cable/cable_names.h"
#include "cable/cable_problem.h"

#define CABLE_MAX_ICP 64
#define CABLE_MAX_UZR 128
#define CABLE_MAX_THL 64
#define CABLE_NAME_MAX 256
#define CABLE_MAX_BRANCHES 8 /* BRANCH: directions listed at a double BP (cable_cont.h) */
#define CABLE_MAX_PKEYS 16   /* problem-specific keys set in one constants file */
#define CABLE_PKEY_LEN 32
/* NCOL: collocation points per mesh interval (AUTO allows the same range). */
#define CABLE_NCOL_MIN 2
#define CABLE_NCOL_MAX 7
/* NTHREADS: at most this many; the default (NTHREADS = 0) is the number of
 * processors this process may run on (sched_getaffinity), at most this */
#define CABLE_THREADS_MAX 64

typedef struct {
  int par;          /* 0-based parameter index (or -1: unused) */
  double value;
  int stop;         /* 1: UZSTOP, end the branch here */
} cable_uzr;

typedef struct {
  int index;        /* 0-based parameter index */
  double weight;
} cable_thl;

typedef struct {
  int index;        /* 0-based parameter index */
  double value;
} cable_parval;

/* The value of a problem-specific key (cable_problem_key) as set. */
typedef struct {
  char name[CABLE_PKEY_LEN];
  double value;
} cable_keyval;

/* Where a key was set: a constants file and line, or an override (file holds
 * the statement, line 0).  file "" and line 0: not set. */
typedef struct {
  char file[CABLE_NAME_MAX];
  int line;
} cable_key_origin;

typedef enum { CABLE_LINSOLVER_CONDENSE = 0, CABLE_LINSOLVER_KLU = 1 } cable_linsolver;

typedef struct cable_constants {
  /* ---- the engine's settings: what continuation/ (and a problem's
     prepare) reads.  The keys: the ENGINE rows of cable_constants_keys.h */
  CABLE_CONSTANTS_KEYS(CABLE_CK_ENGINE_FIELDS)
  /* problem-specific keys (the problem's cable_problem_key list), as set */
  cable_keyval pkey[CABLE_MAX_PKEYS]; int npkey;
  /* 1: ISW=-1 at a simple branch point orients the kernel vector by AUTO's
     rule (its STDRBV): the first free parameter whose component is not
     negligible (|PAR'| / (1 + |PAR|) > EPSL) increases, else the first U(i)
     at t = 1 with |U(i)'| / (1 + |U(i)|) > EPSU.  0: cable's rule (the
     largest component positive).  No key: the session sets it for equations
     from AUTO files (doc/auto-users.md). */
  int bp_orient_auto;
  /* AUTO's NDM: the components of an extended problem's solution that the
     L2-NORM and MAX U columns cover (the fold's u, not its null vector);
     0: all NDIM.  No key: set by cable_fold.h. */
  int ndm;
  /* AUTO's ITPST: a two-parameter run's type codes are the point's + 10 ITPST
     (5 on a fold curve, 6 on a curve of branch points); 0: none.  No key:
     set by cable_fold.h and cable_bpcont.h. */
  int itpst;
  /* AUTO's NPARI: the extended problem's own parameter slots after NPAR (the
     s-file header's); 0: none.  Set with ndm. */
  int npari;

  /* ---- the session's bookkeeping: file names, the restart label, output
     settings, where keys were set.  The engine never reads them.  The keys:
     the SESSION rows of cable_constants_keys.h */
  CABLE_CONSTANTS_KEYS(CABLE_CK_SESSION_FIELDS)
  /* where NDIM, NBC and NINT were set: a built-in problem's dimensions are
     fixed, and a contradicting value is reported at its line */
  cable_key_origin origin_ndim, origin_nbc, origin_nint;
  /* where IPS was set; when no file or override sets it (AUTO's default
     IPS=1, which cable does not solve), the constants file read last, line 0,
     so that the run's refusal names it */
  cable_key_origin origin_ips;
  /* keys AUTO accepts and ignores for boundary-value problems (MXBF, ...),
     "KEY (line N)" separated by ", ", for the run's log; "" when none */
  char ignored[256];
} cable_constants;

/* AUTO-07p defaults (no problem key set). */
CABLE_API void cable_constants_init(cable_constants *c);
/* The thread count a run uses: NTHREADS, or its default when 0;
 * CABLE_ERR_NULL for NULL. */
CABLE_API int cable_threads(const cable_constants *c);

/* A problem-specific key's value: as set in c, else the default pb declares
 * for it; NAN when pb declares no such key (or an argument is NULL). */
CABLE_API double cable_constants_key(const cable_constants *c, const cable_problem *pb, const char *name);

/* ---------------------------------------------------------------- constants files
 * AUTO-07p constants files (c.NAME) and KEY=VALUE overrides.
 *
 * Syntax (AUTO-07p's keyword form): `KEY = value`, one or more statements per
 * line separated by commas (or `;`), `#` and `!` start comments, values are
 * integers, reals (1e-7, Fortran 1.0d-7), quoted strings, lists [1, 'T'] and
 * dicts {'T': [1.0, 2.0], 11: 0.5}; lists and dicts may span lines.
 * Parameters may be given by AUTO index (1-based, as in AUTO) or by name;
 * names are resolved through the file's `parnames` (they win) and then the
 * caller's table parnames[0..npar-1] (0-based: parnames[k] names PAR(k+1)).
 * The result holds 0-based indices (above).
 * Every key, its default and its AUTO difference: doc/constants.md.
 *
 * Errors: one message naming file, line and key (cable/cable_error.h)
 * and a negative cable_status:
 *   CABLE_ERR_IO           the file cannot be read
 *   CABLE_ERR_PARSE        syntax (missing '=', unterminated string or list ...)
 *   CABLE_ERR_INPUT        unknown key, duplicate key, wrong type, out of range
 *   CABLE_ERR_NONFINITE    NaN or Inf where a finite number is needed
 *   CABLE_ERR_NOTFOUND     unknown parameter or component name
 *   CABLE_ERR_UNSUPPORTED  an AUTO key or value cable does not support
 * On error *c and *names are left unchanged. */
/* Read a constants file: *c is reset to the defaults (cable_constants_init)
 * and *names cleared, then the file's keys are applied (AUTO's semantics of
 * loading a c. file).  names may be NULL when the caller does not need the
 * file's parnames/unames afterwards. */
CABLE_API int cable_constants_parse_file(const char *path, cable_constants *c, cable_names *names,
                               const char *const *parnames, int npar, cable_error *err);

/* The same for text already in memory; `name` stands for the file in messages. */
CABLE_API int cable_constants_parse_string(const char *name, const char *text, cable_constants *c,
                                 cable_names *names, const char *const *parnames, int npar,
                                 cable_error *err);

/* The same for a given problem (may be NULL): its parameter names resolve
 * parameter names, and the keys it declares (cable_problem_key) are
 * accepted and checked (type, range, words) with file:line:key errors. */
CABLE_API int cable_constants_parse_file_for(const char *path, const cable_problem *pb, cable_constants *c,
                                             cable_names *names, cable_error *err);
CABLE_API int cable_constants_parse_string_for(const char *name, const char *text, const cable_problem *pb,
                                               cable_constants *c, cable_names *names, cable_error *err);

/* The same for a run that finds its problem by name (the session): one read
 * of the file yields the problem's name and the constants.  After the keys
 * that do not depend on the problem (e, NPAR, parnames, unames) are applied,
 * resolve(ctx, name, &pb, err) is called once with `e` when it is given and
 * not "" (a keyword wins over the file), else the file's e ("" when it names
 * none); it returns 0 with *pb (NULL: no problem, names and keys of none) or
 * an error status with err set, which the parse returns.  The problem's names
 * then resolve parameter names and its keys are accepted (as
 * cable_constants_parse_file_for); the key a file sets that is neither
 * cable's nor the problem's is reported after the problem is known.
 * e, ctx, names and err may be NULL; path, resolve and c may not. */
typedef int cable_constants_resolve_fn(void *ctx, const char *name, const cable_problem **pb, cable_error *err);
CABLE_API int cable_constants_parse_file_resolve(const char *path, const char *e, cable_constants_resolve_fn *resolve,
                                                 void *ctx, cable_constants *c, cable_names *names, cable_error *err);

/* Merge `KEY=VALUE` (e.g. from `cable run DS=-0.01` or a script keyword) into
 * an already filled *c: the key's old value is replaced (UZR replaces the user
 * zeros, UZSTOP the stopping ones); DS='-' reverses the current DS.  Several
 * statements separated by commas are accepted; a key may appear once. */
CABLE_API int cable_constants_parse_override(const char *keyvalue, cable_constants *c, cable_names *names,
                                   const char *const *parnames, int npar, cable_error *err);

/* The same for a given problem (may be NULL), with its keys. */
CABLE_API int cable_constants_parse_override_for(const char *keyvalue, const cable_problem *pb, cable_constants *c,
                                                 cable_names *names, cable_error *err);

/* NDIM, NBC and NINT left at 0 ("take them from the problem") get the
 * problem's values; the run driver calls this before the engine and the
 * output writer (whose header and free-parameter count need them). */
CABLE_API void cable_constants_take_problem_dims(cable_constants *c, int ndim, int nbc, int nint);

/* 1 when `key` is a key cable accepts (case-sensitive, as in AUTO). */
CABLE_API int cable_constants_key_known(const char *key);
/* 1 when `key` is one of cable's keys or a key pb declares (pb may be NULL). */
CABLE_API int cable_constants_key_known_for(const cable_problem *pb, const char *key);

#endif
