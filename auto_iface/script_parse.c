/* Recursive-descent parser for run scripts.  Grammar (a subset of Python):
 *
 *   program  := stmt* EOF
 *   stmt     := simple NEWLINE | 'for' names 'in' expr ':' suite
 *             | 'if' expr ':' suite ('elif' expr ':' suite)* ('else' ':' suite)?
 *   simple   := 'pass' | 'break' | 'continue' | NAME '=' expr | NAME '+=' expr | expr
 *   suite    := simple NEWLINE | NEWLINE INDENT stmt+ DEDENT
 *   expr     := and ('or' and)*            and := not ('and' not)*
 *   not      := 'not' not | cmp            cmp := sum (CMPOP sum)?
 *   sum      := term (('+'|'-') term)*     term := unary ('%' unary)*
 *   unary    := ('-'|'+') unary | postfix
 *   postfix  := atom ('(' args ')' | '[' expr ']')*
 *   atom     := NUMBER | STRING+ | NAME | None | True | False
 *             | '(' expr ')' | '(' expr ',' ... ')' | '[' ... ']' | '{' k: v, ... '}'
 *
 * Recursion is bounded: the depth of parse_expr/unary/not calls by
 * SCRIPT_MAX_NESTING and the height of every tree by SCRIPT_MAX_EXPR_HEIGHT,
 * so neither parsing nor evaluating can exhaust the C stack. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script.h"
#include "script_ast.h"

typedef struct parser {
  const char *file;
  const script_token *tok;
  size_t pos;
  script_arena *arena;
  cable_error *err;
  int depth;       /* current expression recursion depth */
  int loops;       /* enclosing for-loops (for break/continue) */
  int failed;
} parser;

/* Python keywords and constructs cable scripts do not support, with advice. */
static const struct {
  const char *word;
  const char *why;
} unsupported_words[] = {
  {"while", "while loops are not supported in cable scripts (use for NAME in range(N))"},
  {"def", "function definitions are not supported in cable scripts"},
  {"class", "classes are not supported in cable scripts"},
  {"lambda", "lambda is not supported in cable scripts"},
  {"import", "import is not supported in cable scripts (the AUTO commands are built in)"},
  {"from", "import is not supported in cable scripts (the AUTO commands are built in)"},
  {"return", "return is not supported in cable scripts"},
  {"try", "try/except is not supported in cable scripts (a failing command stops the script)"},
  {"except", "try/except is not supported in cable scripts"},
  {"finally", "try/finally is not supported in cable scripts"},
  {"raise", "raise is not supported in cable scripts"},
  {"with", "with is not supported in cable scripts"},
  {"global", "global is not supported in cable scripts (all names are global)"},
  {"nonlocal", "nonlocal is not supported in cable scripts"},
  {"del", "del is not supported in cable scripts"},
  {"yield", "yield is not supported in cable scripts"},
  {"assert", "assert is not supported in cable scripts"},
  {"async", "async is not supported in cable scripts"},
  {"await", "await is not supported in cable scripts"},
  {"is", "'is' is not supported in cable scripts (use == or !=)"},
  {NULL, NULL}};

static const char *const reserved_words[] = {"for", "in", "if", "elif", "else", "and", "or",
                                             "not", "None", "True", "False", "pass", "break",
                                             "continue", NULL};

static int parse_fail(parser *p, const script_token *t, const char *fmt, ...)
  __attribute__((format(printf, 3, 4)));
static int parse_fail(parser *p, const script_token *t, const char *fmt, ...)
{
  if (p->failed) return CABLE_ERR_PARSE;
  char msg[400];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  char key[64];
  if (t->type == SCRIPT_TOK_STRING) snprintf(key, sizeof key, "'%.40s'", t->text);
  else snprintf(key, sizeof key, "%s", t->text);
  p->failed = 1;
  return cable_error_set(p->err, CABLE_ERR_PARSE, p->file, t->line, key, "%s", msg);
}

static int out_of_memory(parser *p)
{
  if (!p->failed) cable_error_set(p->err, CABLE_ERR_ALLOC, p->file, p->tok[p->pos].line, "", "out of memory");
  p->failed = 1;
  return CABLE_ERR_ALLOC;
}

static const script_token *peek(const parser *p) { return &p->tok[p->pos]; }
static const script_token *peek2(const parser *p)
{
  return p->tok[p->pos].type == SCRIPT_TOK_EOF ? &p->tok[p->pos] : &p->tok[p->pos + 1];
}
static const script_token *next(parser *p)
{
  const script_token *t = &p->tok[p->pos];
  if (t->type != SCRIPT_TOK_EOF) p->pos++;
  return t;
}

static int is_op(const script_token *t, const char *op)
{
  return t->type == SCRIPT_TOK_OP && strcmp(t->text, op) == 0;
}

static int is_word(const script_token *t, const char *w)
{
  return t->type == SCRIPT_TOK_NAME && strcmp(t->text, w) == 0;
}

static const char *unsupported_reason(const script_token *t)
{
  if (t->type != SCRIPT_TOK_NAME) return NULL;
  for (int i = 0; unsupported_words[i].word; i++)
    if (strcmp(t->text, unsupported_words[i].word) == 0) return unsupported_words[i].why;
  return NULL;
}

static int is_reserved(const char *s)
{
  for (int i = 0; reserved_words[i]; i++)
    if (strcmp(s, reserved_words[i]) == 0) return 1;
  for (int i = 0; unsupported_words[i].word; i++)
    if (strcmp(s, unsupported_words[i].word) == 0) return 1;
  return 0;
}

/* Operators that Python has and cable scripts do not. */
static int is_unsupported_op(const script_token *t)
{
  static const char *const ops[] = {"*", "/", "//", "**", "@", "&", "|", "^", "~", "<<", ">>",
                                    "-=", "*=", "/=", "//=", "%=", "**=", "&=", "|=", "^=",
                                    "@=", ">>=", "<<=", ":=", "->", "!", ";", NULL};
  if (t->type != SCRIPT_TOK_OP) return 0;
  for (int i = 0; ops[i]; i++)
    if (strcmp(t->text, ops[i]) == 0) return 1;
  return 0;
}

static int fail_unsupported_op(parser *p, const script_token *t)
{
  if (is_op(t, ";"))
    return parse_fail(p, t, "one statement per line (';' is not supported)");
  return parse_fail(p, t,
                    "operator '%s' is not supported in cable scripts "
                    "(supported: + - %% == != < <= > >= and or not)",
                    t->text);
}

/* A message for an unexpected token. */
static int fail_expected(parser *p, const script_token *t, const char *what)
{
  if (is_unsupported_op(t)) return fail_unsupported_op(p, t);
  const char *why = unsupported_reason(t);
  if (why) return parse_fail(p, t, "%s", why);
  if (t->type == SCRIPT_TOK_INDENT) return parse_fail(p, t, "unexpected indent");
  if (is_op(t, ".")) return parse_fail(p, t, "attribute access (x.name) is not supported in cable scripts");
  return parse_fail(p, t, "syntax error: expected %s", what);
}

static script_expr *new_expr(parser *p, script_expr_kind kind, int line)
{
  script_expr *e = script_arena_alloc(p->arena, sizeof *e);
  if (!e) {
    out_of_memory(p);
    return NULL;
  }
  e->kind = kind;
  e->line = line;
  e->height = 1;
  return e;
}

/* Records a child's height; fails when the tree grows too tall. */
static int grow(parser *p, script_expr *parent, const script_expr *child, const script_token *at)
{
  if (child && child->height + 1 > parent->height) parent->height = child->height + 1;
  if (parent->height > SCRIPT_MAX_EXPR_HEIGHT) {
    parse_fail(p, at, "expression too long or too deeply nested (limit %d levels)",
               SCRIPT_MAX_EXPR_HEIGHT);
    return -1;
  }
  return 0;
}

static int enter(parser *p, const script_token *at)
{
  if (++p->depth > SCRIPT_MAX_NESTING) {
    parse_fail(p, at, "expression nested too deeply (limit %d levels)", SCRIPT_MAX_NESTING);
    return -1;
  }
  return 0;
}

static script_expr *parse_expr(parser *p);

/* Comma-separated expressions up to the closer; dict: key ':' value pairs.
 * Fills parent->items/nitems.  Returns 1 when a top-level comma was seen. */
static int parse_items(parser *p, script_expr *parent, const char *closer, int dict, int call)
{
  script_expr **tail = &parent->items;
  int commas = 0, seen_kw = 0;
  while (!p->failed && !is_op(peek(p), closer)) {
    const script_token *start = peek(p);
    const char *kwname = NULL;
    if (call && start->type == SCRIPT_TOK_NAME && is_op(peek2(p), "=")) {
      if (is_reserved(start->text)) {
        parse_fail(p, start, "'%s' cannot be a keyword argument", start->text);
        return 0;
      }
      kwname = start->text;
      next(p);
      next(p);
      seen_kw = 1;
    } else if (call && seen_kw) {
      parse_fail(p, start, "positional argument follows keyword argument");
      return 0;
    }
    if (call && parent->nitems >= SCRIPT_MAX_ARGS) {
      parse_fail(p, start, "too many arguments (limit %d)", SCRIPT_MAX_ARGS);
      return 0;
    }
    script_expr *e = parse_expr(p);
    if (!e) return 0;
    e->kwname = kwname;
    *tail = e;
    tail = &e->next;
    parent->nitems++;
    if (grow(p, parent, e, start)) return 0;
    if (dict) {
      if (!is_op(peek(p), ":")) {
        fail_expected(p, peek(p), "':' after a dict key");
        return 0;
      }
      next(p);
      script_expr *v = parse_expr(p);
      if (!v) return 0;
      *tail = v;
      tail = &v->next;
      parent->nitems++;
      if (grow(p, parent, v, start)) return 0;
    }
    if (is_op(peek(p), ",")) {
      next(p);
      commas = 1;
    } else if (!is_op(peek(p), closer)) {
      char what[32];
      snprintf(what, sizeof what, "',' or '%s'", closer);
      fail_expected(p, peek(p), what);
      return 0;
    }
  }
  if (!p->failed) next(p);   /* the closer */
  return commas;
}

static script_expr *parse_atom(parser *p)
{
  const script_token *t = peek(p);
  script_expr *e = NULL;
  switch (t->type) {
  case SCRIPT_TOK_NUMBER:
    next(p);
    if (!(e = new_expr(p, SCRIPT_E_NUMBER, t->line))) return NULL;
    e->num = t->num;
    e->is_int = t->is_int;
    e->text = t->text;
    return e;
  case SCRIPT_TOK_STRING: {
    /* adjacent literals concatenate, as in Python */
    size_t total = 0, i = p->pos;
    for (; p->tok[i].type == SCRIPT_TOK_STRING; i++) total += p->tok[i].len;
    if (total > SCRIPT_MAX_STRING) {
      parse_fail(p, t, "string literal too long");
      return NULL;
    }
    char *s = script_arena_alloc(p->arena, total + 1);
    if (!s) {
      out_of_memory(p);
      return NULL;
    }
    size_t n = 0;
    while (peek(p)->type == SCRIPT_TOK_STRING) {
      const script_token *k = next(p);
      memcpy(s + n, k->text, k->len);
      n += k->len;
    }
    if (!(e = new_expr(p, SCRIPT_E_STRING, t->line))) return NULL;
    e->text = s;
    e->len = n;
    return e;
  }
  case SCRIPT_TOK_NAME: {
    const char *why = unsupported_reason(t);
    if (why) {
      parse_fail(p, t, "%s", why);
      return NULL;
    }
    script_expr_kind k = SCRIPT_E_NAME;
    if (is_word(t, "None")) k = SCRIPT_E_NONE;
    else if (is_word(t, "True")) k = SCRIPT_E_TRUE;
    else if (is_word(t, "False")) k = SCRIPT_E_FALSE;
    else if (is_reserved(t->text)) {
      parse_fail(p, t, "syntax error: unexpected '%s'", t->text);
      return NULL;
    }
    next(p);
    if (!(e = new_expr(p, k, t->line))) return NULL;
    e->text = t->text;
    return e;
  }
  case SCRIPT_TOK_OP:
    if (is_op(t, "(")) {
      next(p);
      if (is_op(peek(p), ")")) {   /* () : the empty tuple */
        next(p);
        return new_expr(p, SCRIPT_E_LIST, t->line);
      }
      script_expr *first = parse_expr(p);
      if (!first) return NULL;
      if (is_op(peek(p), ")")) {
        next(p);
        return first;
      }
      if (!is_op(peek(p), ",")) {
        fail_expected(p, peek(p), "')'");
        return NULL;
      }
      next(p);
      /* a tuple: behaves as a list */
      if (!(e = new_expr(p, SCRIPT_E_LIST, t->line))) return NULL;
      parse_items(p, e, ")", 0, 0);
      if (p->failed) return NULL;
      first->next = e->items;
      e->items = first;
      e->nitems++;
      if (grow(p, e, first, t)) return NULL;
      return e;
    }
    if (is_op(t, "[") || is_op(t, "{")) {
      int dict = is_op(t, "{");
      next(p);
      if (!(e = new_expr(p, dict ? SCRIPT_E_DICT : SCRIPT_E_LIST, t->line))) return NULL;
      parse_items(p, e, dict ? "}" : "]", dict, 0);
      return p->failed ? NULL : e;
    }
    fail_expected(p, t, "an expression");
    return NULL;
  default:
    fail_expected(p, t, "an expression");
    return NULL;
  }
}

static script_expr *parse_postfix(parser *p)
{
  script_expr *e = parse_atom(p);
  while (e && !p->failed) {
    const script_token *t = peek(p);
    if (is_op(t, "(")) {
      next(p);
      script_expr *c = new_expr(p, SCRIPT_E_CALL, t->line);
      if (!c) return NULL;
      c->a = e;
      if (grow(p, c, e, t)) return NULL;
      parse_items(p, c, ")", 0, 1);
      if (p->failed) return NULL;
      e = c;
    } else if (is_op(t, "[")) {
      next(p);
      script_expr *x = new_expr(p, SCRIPT_E_INDEX, t->line);
      if (!x) return NULL;
      x->a = e;
      if (is_op(peek(p), ":") ) {
        parse_fail(p, peek(p), "slices (x[a:b]) are not supported in cable scripts");
        return NULL;
      }
      x->b = parse_expr(p);
      if (!x->b) return NULL;
      if (is_op(peek(p), ":")) {
        parse_fail(p, peek(p), "slices (x[a:b]) are not supported in cable scripts");
        return NULL;
      }
      if (!is_op(peek(p), "]")) {
        fail_expected(p, peek(p), "']'");
        return NULL;
      }
      next(p);
      if (grow(p, x, e, t) || grow(p, x, x->b, t)) return NULL;
      e = x;
    } else if (is_op(t, ".")) {
      const script_token *n = peek2(p);
      parse_fail(p, t, "attribute access ('.%s') is not supported in cable scripts",
                 n->type == SCRIPT_TOK_NAME ? n->text : "");
      return NULL;
    } else {
      break;
    }
  }
  return e;
}

static script_expr *parse_unary(parser *p)
{
  const script_token *t = peek(p);
  if (is_op(t, "-") || is_op(t, "+")) {
    if (enter(p, t)) return NULL;
    next(p);
    script_expr *a = parse_unary(p);
    p->depth--;
    if (!a) return NULL;
    if (is_op(t, "+")) return a;
    if (a->kind == SCRIPT_E_NUMBER && !a->a) {   /* fold -literal */
      a->num = -a->num;
      return a;
    }
    script_expr *e = new_expr(p, SCRIPT_E_NEG, t->line);
    if (!e) return NULL;
    e->a = a;
    return grow(p, e, a, t) ? NULL : e;
  }
  return parse_postfix(p);
}

static script_expr *binary(parser *p, script_expr_kind kind, script_binop op,
                           const script_token *t, script_expr *a, script_expr *b)
{
  script_expr *e = new_expr(p, kind, t->line);
  if (!e) return NULL;
  e->op = op;
  e->text = t->text;
  e->a = a;
  e->b = b;
  if (grow(p, e, a, t) || grow(p, e, b, t)) return NULL;
  return e;
}

static script_expr *parse_term(parser *p)
{
  script_expr *e = parse_unary(p);
  while (e && !p->failed) {
    const script_token *t = peek(p);
    if (is_op(t, "%")) {
      next(p);
      script_expr *b = parse_unary(p);
      if (!b) return NULL;
      e = binary(p, SCRIPT_E_BINARY, SCRIPT_OP_MOD, t, e, b);
    } else if (is_unsupported_op(t) && !is_op(t, ";") && !is_op(t, "~") && !is_op(t, "!")) {
      fail_unsupported_op(p, t);
      return NULL;
    } else {
      break;
    }
  }
  return e;
}

static script_expr *parse_sum(parser *p)
{
  script_expr *e = parse_term(p);
  while (e && !p->failed) {
    const script_token *t = peek(p);
    if (!is_op(t, "+") && !is_op(t, "-")) break;
    next(p);
    script_expr *b = parse_term(p);
    if (!b) return NULL;
    e = binary(p, SCRIPT_E_BINARY, is_op(t, "+") ? SCRIPT_OP_ADD : SCRIPT_OP_SUB, t, e, b);
  }
  return e;
}

static int comparison_op(const script_token *t, script_binop *op)
{
  static const struct {
    const char *text;
    script_binop op;
  } ops[] = {{"==", SCRIPT_OP_EQ}, {"!=", SCRIPT_OP_NE}, {"<", SCRIPT_OP_LT},
             {"<=", SCRIPT_OP_LE}, {">", SCRIPT_OP_GT},  {">=", SCRIPT_OP_GE}};
  for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++)
    if (is_op(t, ops[i].text)) {
      *op = ops[i].op;
      return 1;
    }
  return 0;
}

static script_expr *parse_cmp(parser *p)
{
  script_expr *e = parse_sum(p);
  script_binop op;
  if (e && !p->failed && comparison_op(peek(p), &op)) {
    const script_token *t = next(p);
    script_expr *b = parse_sum(p);
    if (!b) return NULL;
    e = binary(p, SCRIPT_E_BINARY, op, t, e, b);
    if (e && comparison_op(peek(p), &op)) {
      parse_fail(p, peek(p), "chained comparisons (a < b < c) are not supported; use 'and'");
      return NULL;
    }
  }
  if (e && (is_word(peek(p), "in") || is_word(peek(p), "is"))) {
    parse_fail(p, peek(p), "'%s' is not supported in expressions in cable scripts", peek(p)->text);
    return NULL;
  }
  return e;
}

static script_expr *parse_not(parser *p)
{
  const script_token *t = peek(p);
  if (is_word(t, "not")) {
    if (enter(p, t)) return NULL;
    next(p);
    script_expr *a = parse_not(p);
    p->depth--;
    if (!a) return NULL;
    script_expr *e = new_expr(p, SCRIPT_E_NOT, t->line);
    if (!e) return NULL;
    e->a = a;
    return grow(p, e, a, t) ? NULL : e;
  }
  return parse_cmp(p);
}

static script_expr *parse_and(parser *p)
{
  script_expr *e = parse_not(p);
  while (e && !p->failed && is_word(peek(p), "and")) {
    const script_token *t = next(p);
    script_expr *b = parse_not(p);
    if (!b) return NULL;
    e = binary(p, SCRIPT_E_AND, SCRIPT_OP_EQ, t, e, b);
  }
  return e;
}

static script_expr *parse_expr(parser *p)
{
  if (enter(p, peek(p))) return NULL;
  script_expr *e = parse_and(p);
  while (e && !p->failed && is_word(peek(p), "or")) {
    const script_token *t = next(p);
    script_expr *b = parse_and(p);
    if (!b) {
      e = NULL;
      break;
    }
    e = binary(p, SCRIPT_E_OR, SCRIPT_OP_EQ, t, e, b);
  }
  p->depth--;
  return p->failed ? NULL : e;
}

/* ---- statements --------------------------------------------------------------- */

static script_stmt *parse_stmt(parser *p);

static script_stmt *new_stmt(parser *p, script_stmt_kind kind, int line)
{
  script_stmt *s = script_arena_alloc(p->arena, sizeof *s);
  if (!s) {
    out_of_memory(p);
    return NULL;
  }
  s->kind = kind;
  s->line = line;
  return s;
}

static int expect_newline(parser *p)
{
  const script_token *t = peek(p);
  if (t->type == SCRIPT_TOK_NEWLINE) {
    next(p);
    return 0;
  }
  if (is_op(t, "=")) return parse_fail(p, t, "can only assign to a name (NAME = value)");
  if (t->type == SCRIPT_TOK_NAME && !is_reserved(t->text) && !unsupported_reason(t))
    return parse_fail(p, t, "syntax error: expected end of line (missing operator or comma?)");
  return fail_expected(p, t, "end of line");
}

/* AUTO's command line rewrites a line `name args` into `name(args)` before
 * Python sees it (its shorthand, IPython's autocall), which is how AUTO's own
 * scripts write `print "text"` and `print "a", x`.  A name followed on the
 * same line directly by a string, a number or another (non-reserved) name is
 * never valid Python otherwise, so cable reads such a line as that call.
 * Whether the name is callable is found when it runs, as in AUTO.  A
 * following '(' , '[', an operator or '=' keeps its ordinary meaning. */
static int is_shorthand(const script_token *t, const script_token *t2)
{
  if (t->type != SCRIPT_TOK_NAME || is_reserved(t->text) || unsupported_reason(t)) return 0;
  if (t2->line != t->line) return 0;
  if (t2->type == SCRIPT_TOK_STRING || t2->type == SCRIPT_TOK_NUMBER) return 1;
  return t2->type == SCRIPT_TOK_NAME && !is_reserved(t2->text) && !unsupported_reason(t2);
}

/* name arg, arg, ..., kw=value ... up to the end of the line, as a call. */
static script_expr *parse_shorthand(parser *p)
{
  const script_token *t = next(p);
  script_expr *callee = new_expr(p, SCRIPT_E_NAME, t->line);
  script_expr *c = new_expr(p, SCRIPT_E_CALL, t->line);
  if (!callee || !c) return NULL;
  callee->text = t->text;
  c->a = callee;
  if (grow(p, c, callee, t)) return NULL;
  script_expr **tail = &c->items;
  int seen_kw = 0;
  for (;;) {
    const script_token *start = peek(p);
    const char *kwname = NULL;
    if (start->type == SCRIPT_TOK_NAME && is_op(peek2(p), "=")) {
      if (is_reserved(start->text)) {
        parse_fail(p, start, "'%s' cannot be a keyword argument", start->text);
        return NULL;
      }
      kwname = start->text;
      next(p);
      next(p);
      seen_kw = 1;
    } else if (seen_kw) {
      parse_fail(p, start, "positional argument follows keyword argument");
      return NULL;
    }
    if (c->nitems >= SCRIPT_MAX_ARGS) {
      parse_fail(p, start, "too many arguments (limit %d)", SCRIPT_MAX_ARGS);
      return NULL;
    }
    script_expr *e = parse_expr(p);
    if (!e) return NULL;
    e->kwname = kwname;
    *tail = e;
    tail = &e->next;
    c->nitems++;
    if (grow(p, c, e, start)) return NULL;
    if (!is_op(peek(p), ",")) break;
    next(p);
    if (peek(p)->type == SCRIPT_TOK_NEWLINE) break;   /* a trailing comma, as print "a", in Python 2 */
  }
  return c;
}

static script_stmt *parse_simple(parser *p)
{
  const script_token *t = peek(p);
  const char *why = unsupported_reason(t);
  if (why) {
    parse_fail(p, t, "%s", why);
    return NULL;
  }
  if (is_word(t, "pass") || is_word(t, "break") || is_word(t, "continue")) {
    next(p);
    if (!is_word(t, "pass") && p->loops == 0) {
      parse_fail(p, t, "'%s' outside a for loop", t->text);
      return NULL;
    }
    script_stmt *s = new_stmt(p, is_word(t, "pass") ? SCRIPT_S_PASS
                                 : is_word(t, "break") ? SCRIPT_S_BREAK : SCRIPT_S_CONTINUE,
                              t->line);
    if (!s || expect_newline(p)) return NULL;
    return s;
  }
  if (is_word(t, "else") || is_word(t, "elif")) {
    parse_fail(p, t, "'%s' without a matching 'if' (check the indentation)", t->text);
    return NULL;
  }
  const script_token *t2 = peek2(p);
  if (t->type == SCRIPT_TOK_NAME && (is_op(t2, "=") || is_op(t2, "+="))) {
    if (is_reserved(t->text)) {
      parse_fail(p, t, "cannot assign to '%s'", t->text);
      return NULL;
    }
    next(p);
    next(p);
    script_stmt *s = new_stmt(p, is_op(t2, "=") ? SCRIPT_S_ASSIGN : SCRIPT_S_ADDASSIGN, t->line);
    if (!s) return NULL;
    s->name = t->text;
    s->expr = parse_expr(p);
    if (!s->expr || expect_newline(p)) return NULL;
    return s;
  }
  if (t->type == SCRIPT_TOK_NAME && is_unsupported_op(t2)) {
    fail_unsupported_op(p, t2);
    return NULL;
  }
  if (is_shorthand(t, t2)) {
    script_stmt *s = new_stmt(p, SCRIPT_S_EXPR, t->line);
    if (!s) return NULL;
    s->expr = parse_shorthand(p);
    if (!s->expr || expect_newline(p)) return NULL;
    return s;
  }
  script_stmt *s = new_stmt(p, SCRIPT_S_EXPR, t->line);
  if (!s) return NULL;
  s->expr = parse_expr(p);
  if (!s->expr) return NULL;
  if (is_op(peek(p), "=") || is_op(peek(p), "+=")) {
    parse_fail(p, peek(p), "can only assign to a name (NAME = value)");
    return NULL;
  }
  if (is_op(peek(p), ",")) {
    parse_fail(p, peek(p), "tuple assignment and bare tuples are not supported in cable scripts");
    return NULL;
  }
  if (expect_newline(p)) return NULL;
  return s;
}

/* After ':' : a simple statement on the same line, or an indented block. */
static script_stmt *parse_suite(parser *p, const script_token *head)
{
  if (peek(p)->type != SCRIPT_TOK_NEWLINE) return parse_simple(p);
  next(p);
  if (peek(p)->type != SCRIPT_TOK_INDENT) {
    parse_fail(p, peek(p), "expected an indented block after '%s' on line %d", head->text,
               head->line);
    return NULL;
  }
  next(p);
  script_stmt *first = NULL, **tail = &first;
  while (!p->failed && peek(p)->type != SCRIPT_TOK_DEDENT && peek(p)->type != SCRIPT_TOK_EOF) {
    script_stmt *s = parse_stmt(p);
    if (!s) return NULL;
    *tail = s;
    tail = &s->next;
  }
  if (p->failed) return NULL;
  next(p);   /* DEDENT */
  return first;
}

static int expect_colon(parser *p, const script_token *head)
{
  if (is_op(peek(p), ":")) {
    next(p);
    return 0;
  }
  char what[64];
  snprintf(what, sizeof what, "':' to end the '%s' line", head->text);
  return fail_expected(p, peek(p), what);
}

static script_stmt *parse_for(parser *p)
{
  const script_token *head = next(p);
  script_stmt *s = new_stmt(p, SCRIPT_S_FOR, head->line);
  if (!s) return NULL;
  for (;;) {
    const script_token *n = peek(p);
    if (n->type != SCRIPT_TOK_NAME || is_reserved(n->text)) {
      fail_expected(p, n, "a loop variable name after 'for'");
      return NULL;
    }
    if (s->nnames == SCRIPT_MAX_FOR_NAMES) {
      parse_fail(p, n, "too many loop variables (limit %d)", SCRIPT_MAX_FOR_NAMES);
      return NULL;
    }
    s->names[s->nnames++] = next(p)->text;
    if (!is_op(peek(p), ",")) break;
    next(p);
  }
  if (!is_word(peek(p), "in")) {
    fail_expected(p, peek(p), "'in' after the loop variable");
    return NULL;
  }
  next(p);
  s->expr = parse_expr(p);
  if (!s->expr || expect_colon(p, head)) return NULL;
  p->loops++;
  s->body = parse_suite(p, head);
  p->loops--;
  return s->body ? s : NULL;
}

static script_stmt *parse_if(parser *p)
{
  const script_token *head = peek(p);
  script_stmt *s = new_stmt(p, SCRIPT_S_IF, head->line);
  if (!s) return NULL;
  script_clause **tail = &s->clauses;
  do {
    const script_token *kw = next(p);   /* 'if' or 'elif' */
    script_clause *c = script_arena_alloc(p->arena, sizeof *c);
    if (!c) {
      out_of_memory(p);
      return NULL;
    }
    c->line = kw->line;
    c->cond = parse_expr(p);
    if (!c->cond || expect_colon(p, kw)) return NULL;
    c->body = parse_suite(p, kw);
    if (!c->body) return NULL;
    *tail = c;
    tail = &c->next;
  } while (is_word(peek(p), "elif"));
  if (is_word(peek(p), "else")) {
    const script_token *kw = next(p);
    if (expect_colon(p, kw)) return NULL;
    s->else_body = parse_suite(p, kw);
    if (!s->else_body) return NULL;
  }
  return s;
}

static script_stmt *parse_stmt(parser *p)
{
  const script_token *t = peek(p);
  if (t->type == SCRIPT_TOK_INDENT) {
    parse_fail(p, t, "unexpected indent");
    return NULL;
  }
  if (is_word(t, "for")) return parse_for(p);
  if (is_word(t, "if")) return parse_if(p);
  return parse_simple(p);
}

script_program *script_program_parse(const char *file, const char *text, size_t len,
                                     cable_error *err)
{
  script_program *prog = calloc(1, sizeof *prog);
  if (!prog) {
    cable_error_set(err, CABLE_ERR_ALLOC, file, 0, "", "out of memory");
    return NULL;
  }
  script_tokens toks = {NULL, 0, 0};
  int rc = script_lex(file, text, len, &prog->arena, &toks, err);
  if (rc) {
    free(toks.tok);
    script_program_free(prog);
    return NULL;
  }
  parser p;
  memset(&p, 0, sizeof p);
  p.file = file;
  p.tok = toks.tok;
  p.arena = &prog->arena;
  p.err = err;
  script_stmt **tail = &prog->first;
  while (!p.failed && peek(&p)->type != SCRIPT_TOK_EOF) {
    script_stmt *s = parse_stmt(&p);
    if (!s) break;
    *tail = s;
    tail = &s->next;
  }
  if (!p.failed && peek(&p)->type != SCRIPT_TOK_EOF) fail_expected(&p, peek(&p), "a statement");
  free(toks.tok);
  if (p.failed) {
    script_program_free(prog);
    return NULL;
  }
  return prog;
}

void script_program_free(script_program *p)
{
  if (!p) return;
  script_arena_free(&p->arena);
  free(p);
}
