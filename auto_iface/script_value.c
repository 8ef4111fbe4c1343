/* Script values: scalars by value, strings/lists/dicts/handles in shared,
 * immutable, reference-counted objects.  Values cannot form cycles (a list
 * only ever contains values that existed before it), so reference counting
 * frees everything. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script_internal.h"

struct script_obj {
  long refs;
  script_type type;
  int depth;   /* see script_value_depth */
  union {
    struct {
      size_t len;
      char *chars;
    } str;
    struct {
      size_t len, cap;
      script_value *items;   /* lists: elements; dicts: keys */
      script_value *vals;    /* dicts only */
    } seq;
    struct {
      void *ptr;
      int kind;
      void *ctx;
      void (*release)(void *ctx, void *ptr, int kind);
    } handle;
  } u;
};

script_value script_none(void)
{
  script_value v = {SCRIPT_NONE, 0, 0.0, NULL};
  return v;
}

script_value script_bool(int b)
{
  script_value v = {SCRIPT_BOOL, 0, b ? 1.0 : 0.0, NULL};
  return v;
}

script_value script_number(double x)
{
  script_value v = {SCRIPT_NUMBER, 0, x, NULL};
  return v;
}

script_value script_integer(long n)
{
  script_value v = {SCRIPT_NUMBER, 1, (double)n, NULL};
  return v;
}

static script_obj *obj_alloc(script_type type)
{
  script_obj *o = calloc(1, sizeof *o);
  if (!o) return NULL;
  o->refs = 1;
  o->type = type;
  return o;
}

int script_string_new(script_value *out, const char *s, size_t len)
{
  *out = script_none();
  if (len > SCRIPT_MAX_STRING) return CABLE_ERR_INPUT;
  script_obj *o = obj_alloc(SCRIPT_STRING);
  if (!o) return CABLE_ERR_ALLOC;
  o->u.str.chars = malloc(len + 1);
  if (!o->u.str.chars) {
    free(o);
    return CABLE_ERR_ALLOC;
  }
  if (len) memcpy(o->u.str.chars, s, len);
  o->u.str.chars[len] = '\0';
  o->u.str.len = len;
  out->type = SCRIPT_STRING;
  out->obj = o;
  return 0;
}

int script_string_from_buf(script_value *out, script_buf *b)
{
  *out = script_none();
  script_obj *o = obj_alloc(SCRIPT_STRING);
  if (!o) {
    script_buf_free(b);
    return CABLE_ERR_ALLOC;
  }
  if (!b->data) {
    int rc = script_buf_putn(b, "", 0);
    if (rc) {
      free(o);
      return rc;
    }
  }
  o->u.str.chars = b->data;
  o->u.str.len = b->len;
  b->data = NULL;
  b->len = b->cap = 0;
  out->type = SCRIPT_STRING;
  out->obj = o;
  return 0;
}

int script_list_new(script_value *out)
{
  *out = script_none();
  script_obj *o = obj_alloc(SCRIPT_LIST);
  if (!o) return CABLE_ERR_ALLOC;
  out->type = SCRIPT_LIST;
  out->obj = o;
  return 0;
}

int script_dict_new(script_value *out)
{
  *out = script_none();
  script_obj *o = obj_alloc(SCRIPT_DICT);
  if (!o) return CABLE_ERR_ALLOC;
  out->type = SCRIPT_DICT;
  out->obj = o;
  return 0;
}

/* Room for one more element (and value, for dicts). */
static int seq_reserve(script_obj *o)
{
  if (o->u.seq.len < o->u.seq.cap) return 0;
  if (o->u.seq.len >= SCRIPT_MAX_LIST) return CABLE_ERR_INPUT;
  size_t cap = o->u.seq.cap ? 2 * o->u.seq.cap : 4;
  if (cap > SCRIPT_MAX_LIST) cap = SCRIPT_MAX_LIST;
  script_value *items = realloc(o->u.seq.items, cap * sizeof *items);
  if (!items) return CABLE_ERR_ALLOC;
  o->u.seq.items = items;
  if (o->type == SCRIPT_DICT) {
    script_value *vals = realloc(o->u.seq.vals, cap * sizeof *vals);
    if (!vals) return CABLE_ERR_ALLOC;
    o->u.seq.vals = vals;
  }
  o->u.seq.cap = cap;
  return 0;
}

int script_list_append(script_value *list, script_value item)
{
  if (list->type != SCRIPT_LIST) {
    script_value_release(&item);
    return CABLE_ERR_INPUT;
  }
  script_obj *o = list->obj;
  int d = script_value_depth(&item) + 1;
  int rc = d > SCRIPT_MAX_NESTING ? CABLE_ERR_INPUT : seq_reserve(o);
  if (rc) {
    script_value_release(&item);
    return rc;
  }
  o->u.seq.items[o->u.seq.len++] = item;
  if (d > o->depth) o->depth = d;
  return 0;
}

int script_dict_set(script_value *dict, script_value key, script_value value)
{
  int rc = 0;
  if (dict->type != SCRIPT_DICT || (key.type != SCRIPT_STRING && key.type != SCRIPT_NUMBER))
    rc = CABLE_ERR_INPUT;
  int d = script_value_depth(&value) + 1;
  if (!rc && d > SCRIPT_MAX_NESTING) rc = CABLE_ERR_INPUT;
  if (rc) {
    script_value_release(&key);
    script_value_release(&value);
    return rc;
  }
  script_obj *o = dict->obj;
  for (size_t i = 0; i < o->u.seq.len; i++) {
    if (script_value_equal(&o->u.seq.items[i], &key)) {
      script_value_release(&o->u.seq.vals[i]);
      o->u.seq.vals[i] = value;
      script_value_release(&key);
      if (d > o->depth) o->depth = d;
      return 0;
    }
  }
  rc = seq_reserve(o);
  if (rc) {
    script_value_release(&key);
    script_value_release(&value);
    return rc;
  }
  o->u.seq.items[o->u.seq.len] = key;
  o->u.seq.vals[o->u.seq.len] = value;
  o->u.seq.len++;
  if (d > o->depth) o->depth = d;
  return 0;
}

int script_handle_new(script_value *out, const script_host *host, int kind, void *ptr)
{
  *out = script_none();
  script_obj *o = obj_alloc(SCRIPT_HANDLE);
  if (!o) {
    if (host && host->release) host->release(host->ctx, ptr, kind);
    return CABLE_ERR_ALLOC;
  }
  o->u.handle.ptr = ptr;
  o->u.handle.kind = kind;
  o->u.handle.ctx = host ? host->ctx : NULL;
  o->u.handle.release = host ? host->release : NULL;
  out->type = SCRIPT_HANDLE;
  out->obj = o;
  return 0;
}

script_value script_value_retain(const script_value *v)
{
  if (v->obj) v->obj->refs++;
  return *v;
}

void script_value_release(script_value *v)
{
  script_obj *o = v->obj;
  *v = script_none();
  if (!o || --o->refs > 0) return;
  switch (o->type) {
  case SCRIPT_STRING:
    free(o->u.str.chars);
    break;
  case SCRIPT_LIST:
  case SCRIPT_DICT:
    /* recursion depth bounded by SCRIPT_MAX_NESTING (see depth) */
    for (size_t i = 0; i < o->u.seq.len; i++) {
      script_value_release(&o->u.seq.items[i]);
      if (o->type == SCRIPT_DICT) script_value_release(&o->u.seq.vals[i]);
    }
    free(o->u.seq.items);
    free(o->u.seq.vals);
    break;
  case SCRIPT_HANDLE:
    if (o->u.handle.release) o->u.handle.release(o->u.handle.ctx, o->u.handle.ptr, o->u.handle.kind);
    break;
  default:
    break;
  }
  free(o);
}

const char *script_type_name(const script_value *v)
{
  switch (v->type) {
  case SCRIPT_NONE: return "None";
  case SCRIPT_BOOL: return "bool";
  case SCRIPT_NUMBER: return "number";
  case SCRIPT_STRING: return "string";
  case SCRIPT_LIST: return "list";
  case SCRIPT_DICT: return "dict";
  case SCRIPT_HANDLE:
    switch (v->obj->u.handle.kind) {
    case SCRIPT_HANDLE_RESULT: return "result";
    case SCRIPT_HANDLE_SOLUTION: return "solution";
    default: return "handle";
    }
  }
  return "value";
}

const char *script_string_chars(const script_value *v)
{
  return v->type == SCRIPT_STRING ? v->obj->u.str.chars : NULL;
}

size_t script_string_len(const script_value *v)
{
  return v->type == SCRIPT_STRING ? v->obj->u.str.len : 0;
}

size_t script_list_len(const script_value *v)
{
  return (v->type == SCRIPT_LIST || v->type == SCRIPT_DICT) ? v->obj->u.seq.len : 0;
}

const script_value *script_list_get(const script_value *v, size_t i)
{
  if (v->type != SCRIPT_LIST || i >= v->obj->u.seq.len) return NULL;
  return &v->obj->u.seq.items[i];
}

size_t script_dict_len(const script_value *v)
{
  return v->type == SCRIPT_DICT ? v->obj->u.seq.len : 0;
}

const script_value *script_dict_key(const script_value *v, size_t i)
{
  if (v->type != SCRIPT_DICT || i >= v->obj->u.seq.len) return NULL;
  return &v->obj->u.seq.items[i];
}

const script_value *script_dict_value(const script_value *v, size_t i)
{
  if (v->type != SCRIPT_DICT || i >= v->obj->u.seq.len) return NULL;
  return &v->obj->u.seq.vals[i];
}

const script_value *script_dict_find(const script_value *v, const script_value *key)
{
  if (v->type != SCRIPT_DICT) return NULL;
  for (size_t i = 0; i < v->obj->u.seq.len; i++)
    if (script_value_equal(&v->obj->u.seq.items[i], key)) return &v->obj->u.seq.vals[i];
  return NULL;
}

void *script_handle_ptr(const script_value *v)
{
  return v->type == SCRIPT_HANDLE ? v->obj->u.handle.ptr : NULL;
}

int script_handle_kind(const script_value *v)
{
  return v->type == SCRIPT_HANDLE ? v->obj->u.handle.kind : 0;
}

int script_value_to_long(const script_value *v, long *out)
{
  /* 2^53: beyond it a double no longer holds every integer, and every long
   * bound we care about (labels, counts) is far below. */
  const double exact_limit = 9007199254740992.0;
  if ((v->type != SCRIPT_NUMBER && v->type != SCRIPT_BOOL) || !isfinite(v->num) ||
      v->num != floor(v->num) || fabs(v->num) > exact_limit)
    return CABLE_ERR_INPUT;
  *out = (long)v->num;
  return 0;
}

int script_value_depth(const script_value *v)
{
  return (v->type == SCRIPT_LIST || v->type == SCRIPT_DICT) ? v->obj->depth : 0;
}

int script_value_equal(const script_value *a, const script_value *b)
{
  int an = a->type == SCRIPT_NUMBER || a->type == SCRIPT_BOOL;
  int bn = b->type == SCRIPT_NUMBER || b->type == SCRIPT_BOOL;
  if (an && bn) return a->num == b->num;
  if (a->type != b->type) return 0;
  switch (a->type) {
  case SCRIPT_NONE: return 1;
  case SCRIPT_STRING:
    return a->obj->u.str.len == b->obj->u.str.len &&
           memcmp(a->obj->u.str.chars, b->obj->u.str.chars, a->obj->u.str.len) == 0;
  case SCRIPT_LIST:
  case SCRIPT_DICT:
    if (a->obj->u.seq.len != b->obj->u.seq.len) return 0;
    for (size_t i = 0; i < a->obj->u.seq.len; i++) {
      if (a->type == SCRIPT_LIST) {
        if (!script_value_equal(&a->obj->u.seq.items[i], &b->obj->u.seq.items[i])) return 0;
      } else {
        const script_value *bv = script_dict_find(b, &a->obj->u.seq.items[i]);
        if (!bv || !script_value_equal(&a->obj->u.seq.vals[i], bv)) return 0;
      }
    }
    return 1;
  case SCRIPT_HANDLE: return a->obj->u.handle.ptr == b->obj->u.handle.ptr;
  default: return 0;
  }
}

int script_value_truthy(const script_value *v)
{
  switch (v->type) {
  case SCRIPT_NONE: return 0;
  case SCRIPT_BOOL:
  case SCRIPT_NUMBER: return v->num != 0;
  case SCRIPT_STRING: return v->obj->u.str.len > 0;
  case SCRIPT_LIST:
  case SCRIPT_DICT: return v->obj->u.seq.len > 0;
  default: return 1;
  }
}

/* ---- text ------------------------------------------------------------------ */

int script_buf_putn(script_buf *b, const char *s, size_t n)
{
  if (b->len + n > SCRIPT_MAX_STRING) return CABLE_ERR_INPUT;
  if (b->len + n + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 64;
    while (cap < b->len + n + 1) cap *= 2;
    char *d = realloc(b->data, cap);
    if (!d) return CABLE_ERR_ALLOC;
    b->data = d;
    b->cap = cap;
  }
  if (n) memcpy(b->data + b->len, s, n);
  b->len += n;
  b->data[b->len] = '\0';
  return 0;
}

int script_buf_puts(script_buf *b, const char *s)
{
  return script_buf_putn(b, s, strlen(s));
}

void script_buf_free(script_buf *b)
{
  free(b->data);
  b->data = NULL;
  b->len = b->cap = 0;
}

void script_number_text(double x, int is_int, char *buf, size_t len)
{
  /* Python prints integers exactly and floats with the fewest digits that
   * read back to the same double (at most 17), in positional notation for
   * decimal exponents in [-4, 16). */
  const double int_print_limit = 1e16;
  if (isnan(x)) {
    snprintf(buf, len, "nan");
    return;
  }
  if (isinf(x)) {
    snprintf(buf, len, "%s", x < 0 ? "-inf" : "inf");
    return;
  }
  if (is_int && fabs(x) < int_print_limit && x == floor(x)) {
    snprintf(buf, len, "%.0f", x);
    return;
  }
  char tmp[64];
  int p;
  for (p = 1; p < 17; p++) {
    snprintf(tmp, sizeof tmp, "%.*e", p - 1, x);
    if (strtod(tmp, NULL) == x) break;
  }
  snprintf(tmp, sizeof tmp, "%.*e", p - 1, x);
  int e10 = atoi(strchr(tmp, 'e') + 1);
  if (e10 >= -4 && e10 < 16) {
    int decimals = p - 1 - e10;
    if (decimals < 0) decimals = 0;
    snprintf(buf, len, "%.*f", decimals, x);
    if (!strchr(buf, '.') && strlen(buf) + 2 < len) strcat(buf, ".0");
  } else {
    snprintf(buf, len, "%.*e", p - 1, x);
  }
}

static int write_string_repr(script_buf *b, const char *s, size_t n)
{
  /* Python prefers single quotes unless the text contains one and no double. */
  int q = (memchr(s, '\'', n) && !memchr(s, '"', n)) ? '"' : '\'';
  char qc = (char)q;
  int rc = script_buf_putn(b, &qc, 1);
  for (size_t i = 0; !rc && i < n; i++) {
    char c = s[i];
    if (c == '\\' || c == qc) {
      char esc[2] = {'\\', c};
      rc = script_buf_putn(b, esc, 2);
    } else if (c == '\n') {
      rc = script_buf_puts(b, "\\n");
    } else if (c == '\t') {
      rc = script_buf_puts(b, "\\t");
    } else {
      rc = script_buf_putn(b, &c, 1);
    }
  }
  if (!rc) rc = script_buf_putn(b, &qc, 1);
  return rc;
}

int script_value_write(script_buf *b, const script_value *v, const script_host *host, int repr)
{
  char tmp[512];
  int rc = 0;
  switch (v->type) {
  case SCRIPT_NONE: return script_buf_puts(b, "None");
  case SCRIPT_BOOL: return script_buf_puts(b, v->num != 0 ? "True" : "False");
  case SCRIPT_NUMBER:
    script_number_text(v->num, v->is_int, tmp, sizeof tmp);
    return script_buf_puts(b, tmp);
  case SCRIPT_STRING:
    if (repr) return write_string_repr(b, v->obj->u.str.chars, v->obj->u.str.len);
    return script_buf_putn(b, v->obj->u.str.chars, v->obj->u.str.len);
  case SCRIPT_LIST:
  case SCRIPT_DICT: {
    int dict = v->type == SCRIPT_DICT;
    rc = script_buf_puts(b, dict ? "{" : "[");
    for (size_t i = 0; !rc && i < v->obj->u.seq.len; i++) {
      if (i) rc = script_buf_puts(b, ", ");
      if (!rc) rc = script_value_write(b, &v->obj->u.seq.items[i], host, 1);
      if (!rc && dict) rc = script_buf_puts(b, ": ");
      if (!rc && dict) rc = script_value_write(b, &v->obj->u.seq.vals[i], host, 1);
    }
    if (!rc) rc = script_buf_puts(b, dict ? "}" : "]");
    return rc;
  }
  case SCRIPT_HANDLE:
    if (host && host->describe) {
      tmp[0] = '\0';
      host->describe(host->ctx, v, tmp, sizeof tmp);
      tmp[sizeof tmp - 1] = '\0';
    } else {
      snprintf(tmp, sizeof tmp, "<%s>", script_type_name(v));
    }
    return script_buf_puts(b, tmp);
  }
  return 0;
}

const char *script_value_format(const script_value *v, const script_host *host, char *buf,
                                size_t len)
{
  /* a value too long for SCRIPT_MAX_STRING is shown as far as it was written */
  script_buf b = {NULL, 0, 0};
  (void)script_value_write(&b, v, host, 0);
  if (len) snprintf(buf, len, "%s", b.data ? b.data : "");
  script_buf_free(&b);
  return buf;
}

const script_value *script_kwargs_find(const script_kwargs *kw, const char *name)
{
  if (!kw) return NULL;
  for (int i = 0; i < kw->n; i++)
    if (strcmp(kw->items[i].name, name) == 0) return &kw->items[i].value;
  return NULL;
}
