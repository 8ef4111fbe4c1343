/* Built-in functions of run scripts: AUTO's commands (routed to the host,
 * with AUTO's short aliases) and a few Python helpers (print, len, range,
 * str, int, float, enumerate). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script_interp.h"

static int unsupported(script_interp *in, const script_call *c)
{
  return script_fail(in, CABLE_ERR_UNSUPPORTED, c->line, c->name, "not supported by this host");
}

/* Releases *out and reports a failed host callback. */
static int host_result(script_interp *in, const script_call *c, int rc, const cable_error *he,
                       script_value *out)
{
  if (!rc) return 0;
  script_value_release(out);
  return script_host_fail(in, rc, c->line, c->name, he);
}

static int check_data(script_interp *in, const script_call *c, const script_value *v,
                      const char *what)
{
  if (v->type == SCRIPT_HANDLE || v->type == SCRIPT_STRING || v->type == SCRIPT_NONE) return 0;
  return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "%s must be a result, a solution or a name, got a %s",
                     what, script_type_name(v));
}

/* ---- AUTO commands -------------------------------------------------------------- */

static int bi_run(script_interp *in, const script_call *c, script_value *out)
{
  const script_host *h = in->host;
  if (!h->run) return unsupported(in, c);
  const script_value *start = c->nargs ? &c->args[0] : NULL;
  if (start && start->type == SCRIPT_NONE) start = NULL;
  int rc = start ? check_data(in, c, start, "the start") : 0;
  if (rc) return rc;
  cable_error he;
  cable_error_clear(&he);
  rc = h->run(h->ctx, start, &c->kw, out, &he);
  return host_result(in, c, rc, &he, out);
}

static int load_common(script_interp *in, const script_call *c, int what, script_value *out)
{
  const script_host *h = in->host;
  if (!h->load) return unsupported(in, c);
  const script_value *data = c->nargs ? &c->args[0] : NULL;
  if (data && data->type == SCRIPT_NONE) data = NULL;
  int rc = data ? check_data(in, c, data, "the data") : 0;
  if (rc) return rc;
  cable_error he;
  cable_error_clear(&he);
  rc = h->load(h->ctx, what, data, &c->kw, out, &he);
  return host_result(in, c, rc, &he, out);
}

static int bi_load(script_interp *in, const script_call *c, script_value *out)
{
  return load_common(in, c, SCRIPT_LOAD_SOLUTION, out);
}

static int bi_loadbd(script_interp *in, const script_call *c, script_value *out)
{
  return load_common(in, c, SCRIPT_LOAD_RESULT, out);
}

static int bi_save(script_interp *in, const script_call *c, script_value *out)
{
  const script_host *h = in->host;
  (void)out;
  if (!h->save) return unsupported(in, c);
  if (c->args[0].type != SCRIPT_HANDLE)
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "the first argument must be a result or a solution, got a %s",
                       script_type_name(&c->args[0]));
  if (c->args[1].type != SCRIPT_STRING || script_string_len(&c->args[1]) == 0)
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "the second argument must be a non-empty name, got a %s",
                       script_type_name(&c->args[1]));
  cable_error he;
  cable_error_clear(&he);
  int rc = h->save(h->ctx, &c->args[0], script_string_chars(&c->args[1]), &he);
  return rc ? script_host_fail(in, rc, c->line, c->name, &he) : 0;
}

static int bi_merge_relabel(script_interp *in, const script_call *c, script_value *out,
                            int (*fn)(void *, const script_value *, script_value *, cable_error *))
{
  const script_host *h = in->host;
  if (!fn) return unsupported(in, c);
  if (c->args[0].type != SCRIPT_HANDLE && c->args[0].type != SCRIPT_STRING)
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "needs a result or a name, got a %s",
                       script_type_name(&c->args[0]));
  cable_error he;
  cable_error_clear(&he);
  return host_result(in, c, fn(h->ctx, &c->args[0], out, &he), &he, out);
}

static int bi_merge(script_interp *in, const script_call *c, script_value *out)
{
  return bi_merge_relabel(in, c, out, in->host->merge);
}

static int bi_relabel(script_interp *in, const script_call *c, script_value *out)
{
  return bi_merge_relabel(in, c, out, in->host->relabel);
}

static int bi_clean(script_interp *in, const script_call *c, script_value *out)
{
  const script_host *h = in->host;
  (void)out;
  if (!h->clean) return unsupported(in, c);
  cable_error he;
  cable_error_clear(&he);
  int rc = h->clean(h->ctx, &he);
  return rc ? script_host_fail(in, rc, c->line, c->name, &he) : 0;
}

/* ---- Python helpers --------------------------------------------------------------- */

static int bi_print(script_interp *in, const script_call *c, script_value *out)
{
  (void)out;
  script_buf b = {NULL, 0, 0};
  int rc = script_buf_puts(&b, "");
  for (int i = 0; i < c->nargs && !rc; i++) {
    if (i) rc = script_buf_puts(&b, " ");
    if (!rc) rc = script_value_write(&b, &c->args[i], in->host, 0);
  }
  if (rc) {
    script_buf_free(&b);
    return script_fail(in, rc, c->line, c->name, "text too long (limit %d bytes)", SCRIPT_MAX_STRING);
  }
  if (in->host->print) {
    in->host->print(in->host->ctx, b.data);
  } else {
    fputs(b.data, stdout);
    fputc('\n', stdout);
  }
  script_buf_free(&b);
  return 0;
}

/* fail('text'): stop the script with that message (Python's raise; a scene
 * that does not find the branch point it expects says so and stops). */
static int bi_fail(script_interp *in, const script_call *c, script_value *out)
{
  (void)out;
  const char *text = c->args[0].type == SCRIPT_STRING ? script_string_chars(&c->args[0]) : NULL;
  return script_fail(in, CABLE_ERR_NOTFOUND, c->line, c->name, "%s",
                     text ? text : "fail() takes the message as a string");
}

static int bi_len(script_interp *in, const script_call *c, script_value *out)
{
  const script_value *v = &c->args[0];
  if (v->type == SCRIPT_STRING) {
    *out = script_integer((long)script_string_len(v));
    return 0;
  }
  script_value seq;
  int rc = script_iterable(in, c->line, c->name, v, &seq);
  if (rc) {
    if (v->type != SCRIPT_HANDLE)
      rc = script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "a %s has no length", script_type_name(v));
    return rc;
  }
  *out = script_integer((long)script_list_len(&seq));
  script_value_release(&seq);
  return 0;
}

static int bi_range(script_interp *in, const script_call *c, script_value *out)
{
  long a[3] = {0, 0, 1};
  for (int i = 0; i < c->nargs; i++)
    if (script_value_to_long(&c->args[i], &a[i]))
      return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "arguments must be integers, got a %s",
                         c->args[i].type == SCRIPT_NUMBER ? "non-integral number" : script_type_name(&c->args[i]));
  long start = 0, stop = a[0], step = 1;
  if (c->nargs >= 2) {
    start = a[0];
    stop = a[1];
  }
  if (c->nargs == 3) step = a[2];
  if (step == 0) return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "step must not be zero");
  double count = ceil(((double)stop - (double)start) / (double)step);
  if (count < 0) count = 0;
  if (count > SCRIPT_MAX_RANGE)
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "%.0f elements requested, the limit is %d", count,
                       SCRIPT_MAX_RANGE);
  int rc = script_list_new(out);
  for (long i = 0; i < (long)count && !rc; i++) rc = script_list_append(out, script_integer(start + i * step));
  if (rc) {
    script_value_release(out);
    return script_fail(in, rc, c->line, c->name, "out of memory");
  }
  return 0;
}

static int bi_str(script_interp *in, const script_call *c, script_value *out)
{
  script_buf b = {NULL, 0, 0};
  int rc = script_value_write(&b, &c->args[0], in->host, 0);
  if (!rc) rc = script_string_from_buf(out, &b);
  script_buf_free(&b);
  return rc ? script_fail(in, rc, c->line, c->name, "text too long (limit %d bytes)", SCRIPT_MAX_STRING) : 0;
}

/* int(x) and float(x): numbers and numeric strings. */
static int to_number(script_interp *in, const script_call *c, script_value *out, int integer)
{
  const script_value *v = &c->args[0];
  double x;
  if (v->type == SCRIPT_NUMBER || v->type == SCRIPT_BOOL) {
    x = v->num;
  } else if (v->type == SCRIPT_STRING) {
    const char *s = script_string_chars(v);
    char *end;
    errno = 0;
    x = integer ? (double)strtol(s, &end, 10) : strtod(s, &end);
    while (*end == ' ' || *end == '\t' || *end == '\n') end++;
    if (end == s || *end != '\0' || errno == ERANGE)
      return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "'%.40s' is not a%s number", s,
                         integer ? "n integer" : "");
  } else {
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "cannot convert a %s to a number",
                       script_type_name(v));
  }
  if (integer) {
    if (!isfinite(x)) return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "cannot convert %g to an integer", x);
    *out = script_number(trunc(x));
    out->is_int = 1;
  } else {
    *out = script_number(x);
  }
  return 0;
}

static int bi_int(script_interp *in, const script_call *c, script_value *out)
{
  return to_number(in, c, out, 1);
}

static int bi_float(script_interp *in, const script_call *c, script_value *out)
{
  return to_number(in, c, out, 0);
}

static int bi_enumerate(script_interp *in, const script_call *c, script_value *out)
{
  script_value seq;
  int rc = script_iterable(in, c->line, c->name, &c->args[0], &seq);
  if (rc) return rc;
  long start = 0;
  if (c->nargs == 2 && script_value_to_long(&c->args[1], &start)) {
    script_value_release(&seq);
    return script_fail(in, CABLE_ERR_INPUT, c->line, c->name, "start must be an integer");
  }
  rc = script_list_new(out);
  for (size_t i = 0; i < script_list_len(&seq) && !rc; i++) {
    script_value pair;
    rc = script_list_new(&pair);
    if (!rc) rc = script_list_append(&pair, script_integer(start + (long)i));
    if (!rc) rc = script_list_append(&pair, script_value_retain(script_list_get(&seq, i)));
    if (!rc) rc = script_list_append(out, pair);
    else script_value_release(&pair);
  }
  script_value_release(&seq);
  if (rc) {
    script_value_release(out);
    return script_fail(in, rc, c->line, c->name, "list too long or nested too deeply");
  }
  return 0;
}

/* AUTO's long names and its CLI aliases (AUTOclui: r/rn, ld, bd, sv, mb, rl, cl).
 * A script's own variables shadow these names. */
static const script_builtin builtins[] = {
  {"run", 0, 1, 1, bi_run},        {"r", 0, 1, 1, bi_run},          {"rn", 0, 1, 1, bi_run},
  {"load", 0, 1, 1, bi_load},      {"ld", 0, 1, 1, bi_load},        {"loadbd", 0, 1, 1, bi_loadbd},
  {"bd", 0, 1, 1, bi_loadbd},      {"save", 2, 2, 0, bi_save},      {"sv", 2, 2, 0, bi_save},
  {"merge", 1, 1, 0, bi_merge},    {"mb", 1, 1, 0, bi_merge},       {"relabel", 1, 1, 0, bi_relabel},
  {"rl", 1, 1, 0, bi_relabel},     {"clean", 0, 0, 0, bi_clean},    {"cl", 0, 0, 0, bi_clean},
  {"print", 0, SCRIPT_MAX_ARGS, 0, bi_print},      {"fail", 1, 1, 0, bi_fail},
  {"len", 1, 1, 0, bi_len},        {"range", 1, 3, 0, bi_range},    {"str", 1, 1, 0, bi_str},
  {"int", 1, 1, 0, bi_int},        {"float", 1, 1, 0, bi_float},    {"enumerate", 1, 2, 0, bi_enumerate},
  {NULL, 0, 0, 0, NULL}};

const script_builtin *script_builtin_find(const char *name)
{
  for (int i = 0; builtins[i].name; i++)
    if (strcmp(builtins[i].name, name) == 0) return &builtins[i];
  return NULL;
}
