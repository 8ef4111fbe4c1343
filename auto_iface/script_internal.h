/* Shared between the script_*.c files; not part of the public interface. */
#ifndef CABLE_SCRIPT_INTERNAL_H
#define CABLE_SCRIPT_INTERNAL_H

#include <stddef.h>

#include "script.h"

/* A growable text buffer bounded by SCRIPT_MAX_STRING. */
typedef struct script_buf {
  char *data;   /* NUL-terminated when not NULL */
  size_t len, cap;
} script_buf;

/* 0, CABLE_ERR_ALLOC, or CABLE_ERR_INPUT when the text would exceed
 * SCRIPT_MAX_STRING. */
int script_buf_putn(script_buf *b, const char *s, size_t n);
int script_buf_puts(script_buf *b, const char *s);
void script_buf_free(script_buf *b);

/* Appends the text of v: repr = 1 quotes strings (as inside a list). */
int script_value_write(script_buf *b, const script_value *v, const script_host *host, int repr);
/* Python's text of a number (repr of a float, or an integer). */
void script_number_text(double x, int is_int, char *buf, size_t len);

/* Nesting depth of a value (0 for scalars, 1 + deepest element for lists and
 * dicts).  Bounded by SCRIPT_MAX_NESTING so that freeing, printing and
 * comparing values cannot exhaust the C stack. */
int script_value_depth(const script_value *v);

/* Equality as in Python for the supported types (handles: same object). */
int script_value_equal(const script_value *a, const script_value *b);
/* Python truth value: None, False, 0, '', [], {} are false. */
int script_value_truthy(const script_value *v);

/* A string value built from a buffer (takes the text over, frees b). */
int script_string_from_buf(script_value *out, script_buf *b);

#endif
