/* AUTO-07p constants files (c.NAME) and KEY=VALUE overrides.
 *
 * Syntax (AUTO-07p's keyword form): `KEY = value`, one or more statements per
 * line separated by commas (or `;`), `#` and `!` start comments, values are
 * integers, reals (1e-7, Fortran 1.0d-7), quoted strings, lists [1, 'T'] and
 * dicts {'T': [1.0, 2.0], 11: 0.5}; lists and dicts may span lines.
 * Parameters may be given by AUTO index (1-based, as in AUTO) or by name;
 * names are resolved through the file's `parnames` (they win) and then the
 * caller's table parnames[0..npar-1] (0-based: parnames[k] names PAR(k+1)).
 * The result holds 0-based indices (continuation/cable_constants.h).
 * Every key, its default and its AUTO difference: doc/constants.md.
 *
 * Errors: one message naming file, line and key (auto_iface/cable_error.h)
 * and a negative cable_status:
 *   CABLE_ERR_IO           the file cannot be read
 *   CABLE_ERR_PARSE        syntax (missing '=', unterminated string or list ...)
 *   CABLE_ERR_INPUT        unknown key, duplicate key, wrong type, out of range
 *   CABLE_ERR_NONFINITE    NaN or Inf where a finite number is needed
 *   CABLE_ERR_NOTFOUND     unknown parameter or component name
 *   CABLE_ERR_UNSUPPORTED  an AUTO key or value cable does not support
 * On error *c and *names are left unchanged. */
#ifndef CABLE_CONSTANTS_PARSE_H
#define CABLE_CONSTANTS_PARSE_H

#include "cable_constants.h"
#include "cable_error.h"
#include "names.h"

/* Read a constants file: *c is reset to the defaults (cable_constants_init)
 * and *names cleared, then the file's keys are applied (AUTO's semantics of
 * loading a c. file).  names may be NULL when the caller does not need the
 * file's parnames/unames afterwards. */
int cable_constants_parse_file(const char *path, cable_constants *c, cable_names *names,
                               const char *const *parnames, int npar, cable_error *err);

/* The same for text already in memory; `name` stands for the file in messages. */
int cable_constants_parse_string(const char *name, const char *text, cable_constants *c,
                                 cable_names *names, const char *const *parnames, int npar,
                                 cable_error *err);

/* Merge `KEY=VALUE` (e.g. from `cable run DS=-0.01` or a script keyword) into
 * an already filled *c: the key's old value is replaced (UZR replaces the user
 * zeros, UZSTOP the stopping ones); DS='-' reverses the current DS.  Several
 * statements separated by commas are accepted; a key may appear once. */
int cable_constants_parse_override(const char *keyvalue, cable_constants *c, cable_names *names,
                                   const char *const *parnames, int npar, cable_error *err);

/* NDIM, NBC and NINT left at 0 ("take them from the problem") get the
 * problem's values; the run driver calls this before the engine and the
 * output writer (whose header and free-parameter count need them). */
void cable_constants_take_problem_dims(cable_constants *c, int ndim, int nbc, int nint);

/* 1 when `key` is a key cable accepts (case-sensitive, as in AUTO). */
int cable_constants_key_known(const char *key);

#endif
