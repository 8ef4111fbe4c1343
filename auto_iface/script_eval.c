/* Executes a parsed run script: statements, expressions, names, calls.
 * Every evaluation returns a new reference that its caller releases; every
 * failure sets the error with the script's file, the line and the name or
 * operator at fault. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script_ast.h"
#include "script_interp.h"

/* exec results besides 0 and negative errors */
enum { EXEC_BREAK = 1, EXEC_CONTINUE = 2 };

int script_fail(script_interp *in, int status, int line, const char *key, const char *fmt, ...)
{
  char msg[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return cable_error_set(in->err, status, in->file, line, key, "%s", msg);
}

int script_host_fail(script_interp *in, int rc, int line, const char *fname,
                     const cable_error *he)
{
  int status = he->status < 0 ? he->status : CABLE_ERR_CALLBACK;
  char where[600] = "";
  if (he->file[0] && he->line > 0) snprintf(where, sizeof where, "%s:%d: ", he->file, he->line);
  else if (he->file[0]) snprintf(where, sizeof where, "%s: ", he->file);
  size_t n = strlen(where);
  if (he->key[0] && strcmp(he->key, fname) != 0)
    snprintf(where + n, sizeof where - n, "%s: ", he->key);
  const char *msg = he->msg[0] ? he->msg : cable_status_message(status);
  (void)rc;
  return script_fail(in, status, line, fname, "%s%s", where, msg);
}

/* ---- names ---------------------------------------------------------------- */

static script_var *var_find(script_interp *in, const char *name)
{
  for (size_t i = 0; i < in->nvars; i++)
    if (strcmp(in->vars[i].name, name) == 0) return &in->vars[i];
  return NULL;
}

/* Binds name to v, taking ownership of v. */
static int var_set(script_interp *in, int line, const char *name, script_value v)
{
  script_var *x = var_find(in, name);
  if (!x) {
    if (in->nvars == in->cap) {
      size_t cap = in->cap ? 2 * in->cap : 32;
      script_var *nv = realloc(in->vars, cap * sizeof *nv);
      if (!nv) {
        script_value_release(&v);
        return script_fail(in, CABLE_ERR_ALLOC, line, name, "out of memory");
      }
      in->vars = nv;
      in->cap = cap;
    }
    x = &in->vars[in->nvars++];
    snprintf(x->name, sizeof x->name, "%s", name);
    x->value = script_none();
  }
  script_value old = x->value;
  x->value = v;
  script_value_release(&old);
  return 0;
}

static int count_step(script_interp *in, int line)
{
  if (++in->steps > SCRIPT_MAX_STEPS)
    return script_fail(in, CABLE_ERR_INPUT, line, "", "the script ran more than %ld steps (limit)",
                       SCRIPT_MAX_STEPS);
  return 0;
}

/* ---- expressions ------------------------------------------------------------ */

static int eval(script_interp *in, const script_expr *e, script_value *out);

static int eval_list(script_interp *in, const script_expr *e, script_value *out)
{
  int rc = script_list_new(out);
  if (rc) return script_fail(in, rc, e->line, "[", "out of memory");
  for (const script_expr *x = e->items; x; x = x->next) {
    script_value v;
    if ((rc = eval(in, x, &v))) break;
    if ((rc = script_list_append(out, v))) {
      rc = script_fail(in, rc, x->line, "[", "list too long (limit %d elements) or nested too deeply "
                       "(limit %d levels)", SCRIPT_MAX_LIST, SCRIPT_MAX_NESTING);
      break;
    }
  }
  if (rc) script_value_release(out);
  return rc;
}

static int eval_dict(script_interp *in, const script_expr *e, script_value *out)
{
  int rc = script_dict_new(out);
  if (rc) return script_fail(in, rc, e->line, "{", "out of memory");
  for (const script_expr *k = e->items; k && !rc; k = k->next->next) {
    script_value key, val;
    if ((rc = eval(in, k, &key))) break;
    if (key.type != SCRIPT_STRING && key.type != SCRIPT_NUMBER) {
      rc = script_fail(in, CABLE_ERR_INPUT, k->line, "{", "dict keys must be strings or numbers, got a %s",
                       script_type_name(&key));
      script_value_release(&key);
      break;
    }
    if ((rc = eval(in, k->next, &val))) {
      script_value_release(&key);
      break;
    }
    if ((rc = script_dict_set(out, key, val)))
      rc = script_fail(in, rc, k->line, "{", "dict too large or nested too deeply");
  }
  if (rc) script_value_release(out);
  return rc;
}

static int is_num(const script_value *v) { return v->type == SCRIPT_NUMBER || v->type == SCRIPT_BOOL; }

static int add_values(script_interp *in, const script_expr *e, const script_value *a,
                      const script_value *b, script_value *out)
{
  if (is_num(a) && is_num(b)) {
    *out = script_number(a->num + b->num);
    out->is_int = (a->is_int || a->type == SCRIPT_BOOL) && (b->is_int || b->type == SCRIPT_BOOL);
    return 0;
  }
  if (a->type == SCRIPT_STRING && b->type == SCRIPT_STRING) {
    script_buf buf = {NULL, 0, 0};
    int rc = script_buf_putn(&buf, script_string_chars(a), script_string_len(a));
    if (!rc) rc = script_buf_putn(&buf, script_string_chars(b), script_string_len(b));
    if (!rc) rc = script_string_from_buf(out, &buf);
    script_buf_free(&buf);
    if (rc) return script_fail(in, rc, e->line, "+", "string too long (limit %d bytes)", SCRIPT_MAX_STRING);
    return 0;
  }
  if (a->type == SCRIPT_LIST && b->type == SCRIPT_LIST) {
    int rc = script_list_new(out);
    for (int k = 0; k < 2 && !rc; k++) {
      const script_value *src = k ? b : a;
      for (size_t i = 0; i < script_list_len(src) && !rc; i++)
        rc = script_list_append(out, script_value_retain(script_list_get(src, i)));
    }
    if (rc) {
      script_value_release(out);
      return script_fail(in, rc, e->line, "+", "list too long (limit %d elements)", SCRIPT_MAX_LIST);
    }
    return 0;
  }
  if (a->type == SCRIPT_HANDLE || b->type == SCRIPT_HANDLE) {
    const script_host *h = in->host;
    if (!h->add)
      return script_fail(in, CABLE_ERR_UNSUPPORTED, e->line, "+", "adding a %s and a %s is not supported by this host",
                         script_type_name(a), script_type_name(b));
    cable_error he;
    cable_error_clear(&he);
    *out = script_none();
    int rc = h->add(h->ctx, a, b, out, &he);
    if (rc) {
      script_value_release(out);
      return script_host_fail(in, rc, e->line, "+", &he);
    }
    return 0;
  }
  return script_fail(in, CABLE_ERR_INPUT, e->line, "+", "cannot add a %s and a %s", script_type_name(a),
                     script_type_name(b));
}

static int compare(script_interp *in, const script_expr *e, const script_value *a,
                   const script_value *b, script_value *out)
{
  if (e->op == SCRIPT_OP_EQ || e->op == SCRIPT_OP_NE) {
    int eq = script_value_equal(a, b);
    *out = script_bool(e->op == SCRIPT_OP_EQ ? eq : !eq);
    return 0;
  }
  int c;
  if (is_num(a) && is_num(b)) {
    c = a->num < b->num ? -1 : a->num > b->num ? 1 : 0;
    if (isnan(a->num) || isnan(b->num)) {   /* every ordering with NaN is false */
      *out = script_bool(0);
      return 0;
    }
  } else if (a->type == SCRIPT_STRING && b->type == SCRIPT_STRING) {
    size_t la = script_string_len(a), lb = script_string_len(b);
    c = memcmp(script_string_chars(a), script_string_chars(b), la < lb ? la : lb);
    if (c == 0) c = la < lb ? -1 : la > lb ? 1 : 0;
  } else {
    return script_fail(in, CABLE_ERR_INPUT, e->line, e->text, "cannot compare a %s and a %s",
                       script_type_name(a), script_type_name(b));
  }
  int r = 0;
  switch (e->op) {
  case SCRIPT_OP_LT: r = c < 0; break;
  case SCRIPT_OP_LE: r = c <= 0; break;
  case SCRIPT_OP_GT: r = c > 0; break;
  default: r = c >= 0; break;
  }
  *out = script_bool(r);
  return 0;
}

static int eval_binary(script_interp *in, const script_expr *e, script_value *out)
{
  script_value a, b;
  int rc = eval(in, e->a, &a);
  if (rc) return rc;
  if ((rc = eval(in, e->b, &b))) {
    script_value_release(&a);
    return rc;
  }
  switch (e->op) {
  case SCRIPT_OP_ADD: rc = add_values(in, e, &a, &b, out); break;
  case SCRIPT_OP_SUB:
    if (is_num(&a) && is_num(&b)) {
      *out = script_number(a.num - b.num);
      out->is_int = a.is_int && b.is_int;
    } else {
      rc = script_fail(in, CABLE_ERR_INPUT, e->line, "-", "cannot subtract a %s from a %s",
                       script_type_name(&b), script_type_name(&a));
    }
    break;
  case SCRIPT_OP_MOD:
    if (a.type == SCRIPT_STRING) rc = script_format_percent(in, e->line, &a, &b, out);
    else
      rc = script_fail(in, CABLE_ERR_UNSUPPORTED, e->line, "%",
                       "'%%' is only supported for string formatting ('mode%%d' %% n), got a %s on the left",
                       script_type_name(&a));
    break;
  default: rc = compare(in, e, &a, &b, out); break;
  }
  script_value_release(&a);
  script_value_release(&b);
  return rc;
}

int script_iterable(script_interp *in, int line, const char *what, const script_value *v,
                    script_value *list_out)
{
  *list_out = script_none();
  if (v->type == SCRIPT_LIST) {
    *list_out = script_value_retain(v);
    return 0;
  }
  if (v->type == SCRIPT_DICT) {
    int rc = script_list_new(list_out);
    for (size_t i = 0; i < script_dict_len(v) && !rc; i++)
      rc = script_list_append(list_out, script_value_retain(script_dict_key(v, i)));
    if (rc) {
      script_value_release(list_out);
      return script_fail(in, rc, line, what, "out of memory");
    }
    return 0;
  }
  if (v->type == SCRIPT_HANDLE) {
    const script_host *h = in->host;
    if (!h->items)
      return script_fail(in, CABLE_ERR_UNSUPPORTED, line, what,
                         "the elements of a %s are not available from this host", script_type_name(v));
    cable_error he;
    cable_error_clear(&he);
    int rc = h->items(h->ctx, v, list_out, &he);
    if (rc) {
      script_value_release(list_out);
      return script_host_fail(in, rc, line, what, &he);
    }
    if (list_out->type != SCRIPT_LIST) {
      script_value_release(list_out);
      return script_fail(in, CABLE_ERR_CALLBACK, line, what, "the host's items() did not return a list");
    }
    return 0;
  }
  return script_fail(in, CABLE_ERR_INPUT, line, what, "cannot iterate over a %s", script_type_name(v));
}

static int eval_index(script_interp *in, const script_expr *e, script_value *out)
{
  script_value obj, key;
  int rc = eval(in, e->a, &obj);
  if (rc) return rc;
  if ((rc = eval(in, e->b, &key))) {
    script_value_release(&obj);
    return rc;
  }
  *out = script_none();
  const script_host *h = in->host;
  if (obj.type == SCRIPT_DICT) {
    const script_value *v = script_dict_find(&obj, &key);
    if (v) {
      *out = script_value_retain(v);
    } else {
      char kb[80];
      rc = script_fail(in, CABLE_ERR_NOTFOUND, e->line, "[", "key %s not in the dict",
                       script_value_format(&key, h, kb, sizeof kb));
    }
  } else if (obj.type == SCRIPT_HANDLE && h->getitem) {
    cable_error he;
    cable_error_clear(&he);
    rc = h->getitem(h->ctx, &obj, &key, out, &he);
    if (rc) {
      script_value_release(out);
      rc = script_host_fail(in, rc, e->line, "[", &he);
    }
  } else if (obj.type == SCRIPT_LIST || obj.type == SCRIPT_STRING || obj.type == SCRIPT_HANDLE) {
    script_value seq = script_none();
    long i;
    if (script_value_to_long(&key, &i)) {
      rc = script_fail(in, CABLE_ERR_INPUT, e->line, "[", "a %s index must be an integer, got a %s",
                       script_type_name(&obj), script_type_name(&key));
    } else if (obj.type == SCRIPT_STRING) {
      long n = (long)script_string_len(&obj);
      if (i < 0) i += n;
      if (i < 0 || i >= n)
        rc = script_fail(in, CABLE_ERR_INPUT, e->line, "[", "string index out of range");
      else if ((rc = script_string_new(out, script_string_chars(&obj) + i, 1)))
        rc = script_fail(in, rc, e->line, "[", "out of memory");
    } else if (!(rc = script_iterable(in, e->line, "[", &obj, &seq))) {
      long n = (long)script_list_len(&seq);
      if (i < 0) i += n;
      if (i < 0 || i >= n)
        rc = script_fail(in, CABLE_ERR_INPUT, e->line, "[", "index %ld out of range (the %s has %ld elements)",
                         i < 0 ? i - n : i, script_type_name(&obj), n);
      else
        *out = script_value_retain(script_list_get(&seq, (size_t)i));
    }
    script_value_release(&seq);
  } else {
    rc = script_fail(in, CABLE_ERR_INPUT, e->line, "[", "a %s cannot be indexed", script_type_name(&obj));
  }
  script_value_release(&obj);
  script_value_release(&key);
  return rc;
}

/* A handle called with a label: r('BP1'), r('BP'), r(3), r(). */
static int call_handle(script_interp *in, const script_expr *e, const char *fname,
                       const script_value *h, int nargs, const script_value *args,
                       const script_kwargs *kw, script_value *out)
{
  const script_host *host = in->host;
  if (kw->n > 0 || nargs > 1)
    return script_fail(in, CABLE_ERR_INPUT, e->line, fname,
                       "a %s takes one label: x('BP1'), x('BP'), x(3) or x()", script_type_name(h));
  if (nargs == 1 && args[0].type != SCRIPT_STRING && args[0].type != SCRIPT_NUMBER)
    return script_fail(in, CABLE_ERR_INPUT, e->line, fname,
                       "a label must be a string ('BP1', 'UZ') or a number, got a %s",
                       script_type_name(&args[0]));
  if (!host->select)
    return script_fail(in, CABLE_ERR_UNSUPPORTED, e->line, fname, "label selection is not supported by this host");
  cable_error he;
  cable_error_clear(&he);
  int rc = host->select(host->ctx, h, nargs ? &args[0] : NULL, out, &he);
  if (rc) {
    script_value_release(out);
    return script_host_fail(in, rc, e->line, fname, &he);
  }
  return 0;
}

static int eval_call(script_interp *in, const script_expr *e, script_value *out)
{
  const script_expr *f = e->a;
  const char *fname = f->kind == SCRIPT_E_NAME ? f->text : "(";
  int rc = count_step(in, e->line);
  if (rc) return rc;

  /* the callee: a variable, a built-in or a host function (Python looks the
   * name up before evaluating the arguments) */
  script_value callee = script_none();
  const script_builtin *bi = NULL;
  int host_fn = 0;
  if (f->kind == SCRIPT_E_NAME) {
    script_var *v = var_find(in, f->text);
    if (v) callee = script_value_retain(&v->value);
    else if (!(bi = script_builtin_find(f->text))) {
      if (!in->host->call)
        return script_fail(in, CABLE_ERR_NOTFOUND, e->line, fname, "unknown function");
      host_fn = 1;
    }
  } else if ((rc = eval(in, f, &callee))) {
    return rc;
  }
  if (!bi && !host_fn && callee.type != SCRIPT_HANDLE) {
    rc = script_fail(in, CABLE_ERR_INPUT, e->line, fname, "a %s cannot be called (it is not a function)",
                     script_type_name(&callee));
    script_value_release(&callee);
    return rc;
  }

  /* the arguments */
  int n = e->nitems, nargs = 0, nkw = 0;
  script_value *args = calloc((size_t)(n ? n : 1), sizeof *args);
  script_kwarg *kws = calloc((size_t)(n ? n : 1), sizeof *kws);
  if (!args || !kws) rc = script_fail(in, CABLE_ERR_ALLOC, e->line, fname, "out of memory");
  for (const script_expr *x = e->items; x && !rc; x = x->next) {
    script_value v;
    if ((rc = eval(in, x, &v))) break;
    if (x->kwname) {
      for (int k = 0; k < nkw && !rc; k++)
        if (strcmp(kws[k].name, x->kwname) == 0)
          rc = script_fail(in, CABLE_ERR_INPUT, x->line, fname, "keyword argument %s given twice", x->kwname);
      if (rc) {
        script_value_release(&v);
        break;
      }
      kws[nkw].name = x->kwname;
      kws[nkw].value = v;
      nkw++;
    } else {
      args[nargs++] = v;
    }
  }
  script_kwargs kw = {nkw, kws};
  *out = script_none();

  if (!rc) {
    if (bi) {
      if (nargs < bi->min_args || nargs > bi->max_args) {
        if (bi->min_args == bi->max_args)
          rc = script_fail(in, CABLE_ERR_INPUT, e->line, fname, "takes %d positional argument%s, got %d",
                           bi->min_args, bi->min_args == 1 ? "" : "s", nargs);
        else
          rc = script_fail(in, CABLE_ERR_INPUT, e->line, fname, "takes %d to %d positional arguments, got %d",
                           bi->min_args, bi->max_args, nargs);
      } else if (nkw > 0 && !bi->keywords) {
        rc = script_fail(in, CABLE_ERR_INPUT, e->line, fname, "unexpected keyword argument %s", kws[0].name);
      } else {
        script_call c = {e->line, fname, nargs, args, kw};
        rc = bi->fn(in, &c, out);
      }
    } else if (host_fn) {
      cable_error he;
      cable_error_clear(&he);
      rc = in->host->call(in->host->ctx, fname, nargs, args, &kw, out, &he);
      if (rc == CABLE_ERR_NOTFOUND && he.status == 0 && he.msg[0] == '\0')
        rc = script_fail(in, CABLE_ERR_NOTFOUND, e->line, fname, "unknown function");
      else if (rc)
        rc = script_host_fail(in, rc, e->line, fname, &he);
    } else {
      rc = call_handle(in, e, fname, &callee, nargs, args, &kw, out);
    }
  }
  if (rc) script_value_release(out);
  for (int k = 0; k < nargs; k++) script_value_release(&args[k]);
  for (int k = 0; k < nkw; k++) script_value_release(&kws[k].value);
  free(args);
  free(kws);
  script_value_release(&callee);
  return rc;
}

static int eval(script_interp *in, const script_expr *e, script_value *out)
{
  *out = script_none();
  int rc = 0;
  switch (e->kind) {
  case SCRIPT_E_NUMBER:
    *out = script_number(e->num);
    out->is_int = e->is_int;
    return 0;
  case SCRIPT_E_STRING:
    rc = script_string_new(out, e->text, e->len);
    return rc ? script_fail(in, rc, e->line, "", "out of memory") : 0;
  case SCRIPT_E_NONE: return 0;
  case SCRIPT_E_TRUE: *out = script_bool(1); return 0;
  case SCRIPT_E_FALSE: *out = script_bool(0); return 0;
  case SCRIPT_E_NAME: {
    script_var *v = var_find(in, e->text);
    if (v) {
      *out = script_value_retain(&v->value);
      return 0;
    }
    if (script_builtin_find(e->text))
      return script_fail(in, CABLE_ERR_INPUT, e->line, e->text,
                         "is a function: call it as %s(...)", e->text);
    return script_fail(in, CABLE_ERR_NOTFOUND, e->line, e->text,
                       "unknown variable (not assigned before this line)");
  }
  case SCRIPT_E_LIST: return eval_list(in, e, out);
  case SCRIPT_E_DICT: return eval_dict(in, e, out);
  case SCRIPT_E_NEG: {
    script_value a;
    if ((rc = eval(in, e->a, &a))) return rc;
    if (is_num(&a)) {
      *out = script_number(-a.num);
      out->is_int = a.is_int || a.type == SCRIPT_BOOL;
    } else {
      rc = script_fail(in, CABLE_ERR_INPUT, e->line, "-", "unary '-' needs a number, got a %s",
                       script_type_name(&a));
    }
    script_value_release(&a);
    return rc;
  }
  case SCRIPT_E_NOT: {
    script_value a;
    if ((rc = eval(in, e->a, &a))) return rc;
    *out = script_bool(!script_value_truthy(&a));
    script_value_release(&a);
    return 0;
  }
  case SCRIPT_E_AND:
  case SCRIPT_E_OR: {
    /* Python: the deciding operand is the value */
    if ((rc = eval(in, e->a, out))) return rc;
    int t = script_value_truthy(out);
    if ((e->kind == SCRIPT_E_AND) == (t != 0)) {
      script_value_release(out);
      return eval(in, e->b, out);
    }
    return 0;
  }
  case SCRIPT_E_BINARY: return eval_binary(in, e, out);
  case SCRIPT_E_CALL: return eval_call(in, e, out);
  case SCRIPT_E_INDEX: return eval_index(in, e, out);
  }
  return script_fail(in, CABLE_ERR_INPUT, e->line, "", "unknown expression");
}

/* ---- statements ---------------------------------------------------------------- */

static int exec_block(script_interp *in, const script_stmt *s);

static int exec_for(script_interp *in, const script_stmt *s)
{
  script_value it, seq;
  int rc = eval(in, s->expr, &it);
  if (rc) return rc;
  rc = script_iterable(in, s->line, "for", &it, &seq);
  script_value_release(&it);
  if (rc) return rc;
  for (size_t i = 0; i < script_list_len(&seq) && !rc; i++) {
    const script_value *x = script_list_get(&seq, i);
    if (s->nnames == 1) {
      rc = var_set(in, s->line, s->names[0], script_value_retain(x));
    } else if (x->type != SCRIPT_LIST || script_list_len(x) != (size_t)s->nnames) {
      rc = script_fail(in, CABLE_ERR_INPUT, s->line, "for",
                       "cannot unpack a %s into %d loop variables", script_type_name(x), s->nnames);
    } else {
      for (int k = 0; k < s->nnames && !rc; k++)
        rc = var_set(in, s->line, s->names[k], script_value_retain(script_list_get(x, (size_t)k)));
    }
    if (rc) break;
    rc = exec_block(in, s->body);
    if (rc == EXEC_CONTINUE) rc = 0;
    if (rc == EXEC_BREAK) {
      rc = 0;
      break;
    }
  }
  script_value_release(&seq);
  return rc;
}

static int exec_stmt(script_interp *in, const script_stmt *s)
{
  int rc = count_step(in, s->line);
  if (rc) return rc;
  script_value v;
  switch (s->kind) {
  case SCRIPT_S_EXPR:
    if ((rc = eval(in, s->expr, &v))) return rc;
    script_value_release(&v);
    return 0;
  case SCRIPT_S_ASSIGN:
    if ((rc = eval(in, s->expr, &v))) return rc;
    return var_set(in, s->line, s->name, v);
  case SCRIPT_S_ADDASSIGN: {
    script_var *x = var_find(in, s->name);
    if (!x)
      return script_fail(in, CABLE_ERR_NOTFOUND, s->line, s->name,
                         "unknown variable (not assigned before this line)");
    if ((rc = eval(in, s->expr, &v))) return rc;
    x = var_find(in, s->name);   /* the right-hand side may not move it, but be safe */
    script_value sum, old = script_value_retain(&x->value);
    script_expr plus;
    memset(&plus, 0, sizeof plus);
    plus.line = s->line;
    rc = add_values(in, &plus, &old, &v, &sum);
    script_value_release(&old);
    script_value_release(&v);
    return rc ? rc : var_set(in, s->line, s->name, sum);
  }
  case SCRIPT_S_FOR: return exec_for(in, s);
  case SCRIPT_S_IF:
    for (const script_clause *c = s->clauses; c; c = c->next) {
      if ((rc = eval(in, c->cond, &v))) return rc;
      int t = script_value_truthy(&v);
      script_value_release(&v);
      if (t) return exec_block(in, c->body);
    }
    return s->else_body ? exec_block(in, s->else_body) : 0;
  case SCRIPT_S_PASS: return 0;
  case SCRIPT_S_BREAK: return EXEC_BREAK;
  case SCRIPT_S_CONTINUE: return EXEC_CONTINUE;
  }
  return 0;
}

/* Recursion depth: the block nesting, at most SCRIPT_MAX_BLOCK_DEPTH. */
static int exec_block(script_interp *in, const script_stmt *s)
{
  for (; s; s = s->next) {
    int rc = exec_stmt(in, s);
    if (rc) return rc;
  }
  return 0;
}

/* ---- entry points ------------------------------------------------------------- */

int script_run_string(const char *name, const char *text, const script_host *host,
                      cable_error *err)
{
  cable_error local;
  if (!err) err = &local;
  cable_error_clear(err);
  if (!name) name = "<script>";
  if (!text || !host)
    return cable_error_set(err, CABLE_ERR_INPUT, name, 0, "", "no script text or no host");
  size_t len = strlen(text);
  if (len > SCRIPT_MAX_SOURCE)
    return cable_error_set(err, CABLE_ERR_INPUT, name, 0, "", "script longer than %d bytes",
                           SCRIPT_MAX_SOURCE);
  script_program *prog = script_program_parse(name, text, len, err);
  if (!prog) return err->status ? err->status : CABLE_ERR_PARSE;
  script_interp in;
  memset(&in, 0, sizeof in);
  in.host = host;
  in.file = name;
  in.err = err;
  int rc = exec_block(&in, prog->first);
  for (size_t i = 0; i < in.nvars; i++) script_value_release(&in.vars[i].value);
  free(in.vars);
  script_program_free(prog);
  return rc < 0 ? rc : 0;
}

int script_run_file(const char *path, const script_host *host, cable_error *err)
{
  cable_error local;
  if (!err) err = &local;
  cable_error_clear(err);
  if (!path) return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "no script file given");
  FILE *f = fopen(path, "rb");
  if (!f) return cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot open the script: %s", strerror(errno));
  char *text = malloc((size_t)SCRIPT_MAX_SOURCE + 2);
  if (!text) {
    fclose(f);
    return cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
  }
  size_t n = fread(text, 1, (size_t)SCRIPT_MAX_SOURCE + 1, f);
  int bad = ferror(f);
  fclose(f);
  int rc;
  if (bad) {
    rc = cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot read the script");
  } else if (n > SCRIPT_MAX_SOURCE) {
    rc = cable_error_set(err, CABLE_ERR_INPUT, path, 0, "", "script longer than %d bytes", SCRIPT_MAX_SOURCE);
  } else if (memchr(text, '\0', n)) {
    size_t at = (size_t)((char *)memchr(text, '\0', n) - text);
    int line = 1;
    for (size_t i = 0; i < at; i++) line += text[i] == '\n';
    rc = cable_error_set(err, CABLE_ERR_PARSE, path, line, "\\x00", "NUL byte in the script (not a text file?)");
  } else {
    text[n] = '\0';
    rc = script_run_string(path, text, host, err);
  }
  free(text);
  return rc;
}
