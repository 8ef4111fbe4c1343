/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Constants-file parser: a small lexer and recursive-descent parser build a
 * value tree per statement; statements are collected (unknown, unsupported
 * and duplicate keys are rejected there), then applied to a working copy in
 * two passes (names and NPAR first, so that every other key may use names
 * defined anywhere in the file), then cross-checked; the caller's structs
 * change only on success. */
#include "cable/cable_constants.h"
#include "cable/cable_aufile.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cable/cable_status.h"
#include "constants_check.h"

#define TOK_MAX 1024          /* longest token (strings are names or file names) */
#define DEPTH_MAX 8           /* nesting of lists/dicts; AUTO needs 2 */
#define STMT_MAX 512          /* statements per file */
#define FILE_MAX (4L << 20)   /* a constants file is a few hundred bytes */
#define STOP_MAX ((int)(sizeof(((cable_constants *)0)->stop_on) / sizeof(int)))
#define THU_MAX CABLE_NAMES_MAX

/* ---------------------------------------------------------------- values */

typedef enum { CV_INT, CV_REAL, CV_STR, CV_LIST, CV_DICT } cv_kind;

typedef struct cv {
  cv_kind kind;
  int line;
  int bare;               /* CV_STR written without quotes */
  long i;
  double r;
  char *text;             /* scalars: string contents or the number's source text */
  struct cv **item;       /* list: n items; dict: 2n, key then value */
  int n, cap;
} cv;

static void cv_free(cv *v)
{
  if (!v) return;
  for (int k = 0; k < v->n; k++) cv_free(v->item[k]);
  free(v->item);
  free(v->text);
  free(v);
}

static cv *cv_new(cv_kind kind, int line, const char *text)
{
  cv *v = calloc(1, sizeof *v);
  if (!v) return NULL;
  v->kind = kind;
  v->line = line;
  if (text) {
    v->text = strdup(text);
    if (!v->text) {
      free(v);
      return NULL;
    }
  }
  return v;
}

static int cv_push(cv *v, cv *item)
{
  if (v->n == v->cap) {
    int cap = v->cap ? 2 * v->cap : 8;
    cv **p = realloc(v->item, (size_t)cap * sizeof *p);
    if (!p) return -1;
    v->item = p;
    v->cap = cap;
  }
  v->item[v->n++] = item;
  return 0;
}

/* ---------------------------------------------------------------- context */

/* Each key of cable/cable_constants_keys.h by its row: KEY_NTST ... */
enum {
#define KEY_ENUM(key, field, kind, who, def, lo, hi, line) KEY_##key,
  CABLE_CONSTANTS_KEYS(KEY_ENUM)
#undef KEY_ENUM
  KEY_COUNT
};

typedef struct {
  char key[32];
  int line;
  cv *value;
} stmt;

typedef struct {
  int par;      /* 0-based */
  int u;        /* 0-based component */
  double w;
} thu_entry;

typedef struct {
  const char *file;         /* for messages ("" for overrides) */
  const char *origin;       /* override text, appended to messages */
  cable_error *err;
  /* lexer */
  const char *src;
  size_t pos;
  int line;
  int tok_kind, tok_line;
  char tok[TOK_MAX];
  int depth;
  /* statements */
  stmt st[STMT_MAX];
  int nst;
  /* working copies */
  cable_constants c;
  cable_names names;
  const char *const *parnames;
  int npar_caller;
  const cable_problem *pb;  /* the problem whose keys are accepted (NULL: none) */
  /* the problem found while reading (cable_constants_parse_file_resolve):
     called after pass 1 (which applies e), with e_given or the file's e;
     keys that are not cable's wait for it (defer: statement indices) */
  cable_constants_resolve_fn *resolve;
  void *resolve_ctx;
  const char *e_given;
  int defer[STMT_MAX], ndefer;
  int line_of[KEY_COUNT];   /* line of the statement that set a key (cross-checks) */
  thu_entry thu[THU_MAX];
  int nthu, thu_set, thu_line;
  int applied;              /* statements applied (an empty override is an error) */
  char cur_key[32];         /* key being parsed, named by lexer errors */
  char uzr_from_stop[CABLE_MAX_UZR];  /* per c.uzr entry: 1 if it came from UZSTOP */
} pctx;

enum { T_EOF, T_NL, T_IDENT, T_NUM, T_STR, T_PUNCT };

static int perr(pctx *x, int status, int line, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 5, 6)));
static int perr(pctx *x, int status, int line, const char *key, const char *fmt, ...)
{
  char msg[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if ((!key || !key[0]) && x->cur_key[0]) key = x->cur_key;
  if (x->origin)
    return cable_error_set(x->err, status, x->file, line, key, "%s (in '%.200s')", msg, x->origin);
  return cable_error_set(x->err, status, x->file, line, key, "%s", msg);
}

/* ---------------------------------------------------------------- lexer */

static int lex_is_ident0(int ch) { return isalpha(ch) || ch == '_'; }
static int lex_is_ident(int ch) { return isalnum(ch) || ch == '_'; }

static int lex_number(pctx *x)
{
  const char *s = x->src + x->pos;
  size_t n = 0;
  int digits = 0;
  if (s[n] == '+' || s[n] == '-') n++;
  while (isdigit((unsigned char)s[n])) n++, digits++;
  if (s[n] == '.') {
    n++;
    while (isdigit((unsigned char)s[n])) n++, digits++;
  }
  if (digits > 0 && strchr("eEdD", s[n]) && s[n] != '\0') {
    size_t m = n + 1;
    if (s[m] == '+' || s[m] == '-') m++;
    if (isdigit((unsigned char)s[m])) {
      while (isdigit((unsigned char)s[m])) m++;
      n = m;
    }
  }
  /* a number glued to letters ("12abc", "1.5.3") is a typo, not two tokens */
  size_t end = n;
  while (lex_is_ident((unsigned char)s[end]) || s[end] == '.') end++;
  if (digits == 0 || end != n || n >= TOK_MAX) {
    size_t len = end > n ? end : n;
    if (len >= TOK_MAX) len = TOK_MAX - 1;
    if (len == 0) len = 1;
    return perr(x, CABLE_ERR_PARSE, x->line, "", "bad number '%.*s'", (int)len, s);
  }
  memcpy(x->tok, s, n);
  x->tok[n] = '\0';
  x->pos += n;
  x->tok_kind = T_NUM;
  return 0;
}

static int lex_string(pctx *x)
{
  char quote = x->src[x->pos];
  int start = x->line;
  size_t n = 0;
  x->pos++;
  for (;;) {
    char ch = x->src[x->pos];
    if (ch == '\0' || ch == '\n')
      return perr(x, CABLE_ERR_PARSE, start, "", "unterminated string (missing closing %c)", quote);
    x->pos++;
    if (ch == quote) {
      if (x->src[x->pos] != quote) break;
      x->pos++;  /* a doubled quote stands for one (Fortran and AUTO) */
    }
    if (n + 1 >= TOK_MAX) return perr(x, CABLE_ERR_PARSE, start, "", "string too long");
    x->tok[n++] = ch;
  }
  x->tok[n] = '\0';
  x->tok_kind = T_STR;
  return 0;
}

/* Advance to the next token; 0 or an error status. */
static int lex_next(pctx *x)
{
  const char *s = x->src;
  for (;;) {
    char ch = s[x->pos];
    if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\f' || ch == '\v') {
      x->pos++;
    } else if (ch == '#' || ch == '!') {
      while (s[x->pos] && s[x->pos] != '\n') x->pos++;
    } else {
      break;
    }
  }
  char ch = s[x->pos];
  x->tok_line = x->line;
  x->tok[0] = '\0';
  if (ch == '\0') {
    x->tok_kind = T_EOF;
    return 0;
  }
  if (ch == '\n') {
    x->pos++;
    x->line++;
    x->tok_kind = T_NL;
    strcpy(x->tok, "end of line");
    return 0;
  }
  if (ch == '\'' || ch == '"') return lex_string(x);
  char next = s[x->pos + 1];
  if (isdigit((unsigned char)ch) || (ch == '.' && isdigit((unsigned char)next)) ||
      ((ch == '+' || ch == '-') && (isdigit((unsigned char)next) || next == '.')))
    return lex_number(x);
  if (lex_is_ident0((unsigned char)ch)) {
    size_t n = 0;
    while (lex_is_ident((unsigned char)s[x->pos + n])) n++;
    if (n >= 32) return perr(x, CABLE_ERR_PARSE, x->line, "", "name too long: '%.40s...'", s + x->pos);
    memcpy(x->tok, s + x->pos, n);
    x->tok[n] = '\0';
    x->pos += n;
    x->tok_kind = T_IDENT;
    return 0;
  }
  if (strchr("=,:[]{};-+()", ch)) {
    x->tok[0] = ch;
    x->tok[1] = '\0';
    x->pos++;
    x->tok_kind = T_PUNCT;
    return 0;
  }
  if (isprint((unsigned char)ch))
    return perr(x, CABLE_ERR_PARSE, x->line, "", "unexpected character '%c'", ch);
  return perr(x, CABLE_ERR_PARSE, x->line, "", "unexpected byte 0x%02x", (unsigned)(unsigned char)ch);
}

static int tok_is(const pctx *x, char punct)
{
  return x->tok_kind == T_PUNCT && x->tok[0] == punct;
}

static int lex_skip_newlines(pctx *x)
{
  int st = 0;
  while (st == 0 && x->tok_kind == T_NL) st = lex_next(x);
  return st;
}

/* ---------------------------------------------------------------- parser */

static int parse_value(pctx *x, const char *key, cv **out);

static int parse_scalar(pctx *x, const char *key, cv **out)
{
  cv *v = NULL;
  if (x->tok_kind == T_NUM) {
    char buf[TOK_MAX];
    snprintf(buf, sizeof buf, "%s", x->tok);
    int real = strpbrk(buf, ".eEdD") != NULL;
    if (real) {
      v = cv_new(CV_REAL, x->tok_line, x->tok);
      if (!v) return perr(x, CABLE_ERR_ALLOC, x->tok_line, key, "out of memory");
      /* the one reader of AUTO/Fortran numbers (1.5D-3), shared with the
       * s- and b-file readers; overflow gives +-HUGE_VAL, reported as
       * non-finite where it matters */
      if (cable_aufile_parse_double(buf, &v->r) != 0) {
        cv_free(v);
        return perr(x, CABLE_ERR_PARSE, x->tok_line, key, "bad number '%s'", x->tok);
      }
    } else {
      v = cv_new(CV_INT, x->tok_line, x->tok);
      if (!v) return perr(x, CABLE_ERR_ALLOC, x->tok_line, key, "out of memory");
      errno = 0;
      v->i = strtol(buf, NULL, 10);
      if (errno == ERANGE || v->i > INT_MAX || v->i < INT_MIN) {
        cv_free(v);
        return perr(x, CABLE_ERR_INPUT, x->tok_line, key, "integer out of range: '%s'", x->tok);
      }
      v->r = (double)v->i;
    }
  } else if (x->tok_kind == T_STR) {
    v = cv_new(CV_STR, x->tok_line, x->tok);
    if (!v) return perr(x, CABLE_ERR_ALLOC, x->tok_line, key, "out of memory");
  } else {  /* T_IDENT: a bare word, or nan/inf spelled out */
    const char *t = x->tok;
    if (strcasecmp(t, "nan") == 0 || strcasecmp(t, "inf") == 0 || strcasecmp(t, "infinity") == 0) {
      v = cv_new(CV_REAL, x->tok_line, t);
      if (!v) return perr(x, CABLE_ERR_ALLOC, x->tok_line, key, "out of memory");
      v->r = (tolower((unsigned char)t[0]) == 'n') ? NAN : INFINITY;
    } else {
      v = cv_new(CV_STR, x->tok_line, t);
      if (!v) return perr(x, CABLE_ERR_ALLOC, x->tok_line, key, "out of memory");
      v->bare = 1;
    }
  }
  int st = lex_next(x);
  if (st) {
    cv_free(v);
    return st;
  }
  *out = v;
  return 0;
}

static int parse_seq(pctx *x, const char *key, cv **out)
{
  int dict = tok_is(x, '{');
  char close = dict ? '}' : ']';
  int start = x->tok_line;
  const char *what = dict ? "dict" : "list";
  if (++x->depth > DEPTH_MAX)
    return perr(x, CABLE_ERR_PARSE, start, key, "lists or dicts nested too deeply");
  cv *v = cv_new(dict ? CV_DICT : CV_LIST, start, NULL);
  if (!v) return perr(x, CABLE_ERR_ALLOC, start, key, "out of memory");
  int st = lex_next(x);
  for (;;) {
    if (st == 0) st = lex_skip_newlines(x);
    if (st) break;
    if (x->tok_kind == T_EOF) {
      st = perr(x, CABLE_ERR_PARSE, start, key, "unterminated %s (missing '%c')", what, close);
      break;
    }
    if (tok_is(x, close)) {
      st = lex_next(x);
      break;
    }
    cv *item = NULL;
    if (dict) {
      if (x->tok_kind != T_NUM && x->tok_kind != T_STR && x->tok_kind != T_IDENT) {
        st = perr(x, CABLE_ERR_PARSE, x->tok_line, key, "expected a dict key, got '%s'", x->tok);
        break;
      }
      st = parse_scalar(x, key, &item);
      if (st == 0 && cv_push(v, item) != 0) {
        cv_free(item);
        st = perr(x, CABLE_ERR_ALLOC, start, key, "out of memory");
      }
      if (st == 0) st = lex_skip_newlines(x);
      if (st) break;
      if (!tok_is(x, ':')) {
        st = perr(x, CABLE_ERR_PARSE, x->tok_line, key, "expected ':' after dict key, got '%s'", x->tok);
        break;
      }
      st = lex_next(x);
      if (st == 0) st = lex_skip_newlines(x);
      if (st) break;
    }
    item = NULL;
    st = parse_value(x, key, &item);
    if (st) break;
    if (cv_push(v, item) != 0) {
      cv_free(item);
      st = perr(x, CABLE_ERR_ALLOC, start, key, "out of memory");
      break;
    }
    st = lex_skip_newlines(x);
    if (st) break;
    if (tok_is(x, ',')) {
      st = lex_next(x);
    } else if (!tok_is(x, close)) {
      if (x->tok_kind == T_EOF)
        st = perr(x, CABLE_ERR_PARSE, start, key, "unterminated %s (missing '%c')", what, close);
      else if (x->tok_line > start && x->tok_kind == T_IDENT)
        st = perr(x, CABLE_ERR_PARSE, start, key, "unterminated %s (missing '%c'; '%s' on line %d looks like the next key)",
                  what, close, x->tok, x->tok_line);
      else
        st = perr(x, CABLE_ERR_PARSE, x->tok_line, key, "expected ',' or '%c' in %s, got '%s'", close,
                  what, x->tok);
      break;
    }
  }
  x->depth--;
  if (st) {
    cv_free(v);
    return st;
  }
  *out = v;
  return 0;
}

static int parse_value(pctx *x, const char *key, cv **out)
{
  *out = NULL;
  if (tok_is(x, '-') || tok_is(x, '+')) {
    /* only "-inf"/"+nan" get here (signed numbers are single tokens): keep
     * them as numbers so that the message says "must be finite" */
    int neg = tok_is(x, '-'), line = x->tok_line;
    int st = lex_next(x);
    if (st) return st;
    if (x->tok_kind == T_IDENT && (strcasecmp(x->tok, "inf") == 0 || strcasecmp(x->tok, "infinity") == 0 ||
                                   strcasecmp(x->tok, "nan") == 0)) {
      st = parse_scalar(x, key, out);
      if (st == 0 && neg) {
        char *t = malloc(strlen((*out)->text) + 2);
        if (!t) {
          cv_free(*out);
          *out = NULL;
          return perr(x, CABLE_ERR_ALLOC, line, key, "out of memory");
        }
        t[0] = '-';
        strcpy(t + 1, (*out)->text);
        free((*out)->text);
        (*out)->text = t;
        (*out)->r = -(*out)->r;
      }
      return st;
    }
    return perr(x, CABLE_ERR_PARSE, line, key, "bad value: '%s' must be followed by a number", neg ? "-" : "+");
  }
  if (x->tok_kind == T_NUM || x->tok_kind == T_STR || x->tok_kind == T_IDENT) return parse_scalar(x, key, out);
  if (tok_is(x, '[') || tok_is(x, '{')) return parse_seq(x, key, out);
  if (x->tok_kind == T_NL || x->tok_kind == T_EOF)
    return perr(x, CABLE_ERR_PARSE, x->tok_line, key, "missing value after '='");
  if (tok_is(x, '('))
    return perr(x, CABLE_ERR_PARSE, x->tok_line, key, "tuples are not accepted: write a list [...]");
  return perr(x, CABLE_ERR_PARSE, x->tok_line, key, "bad value starting with '%s'", x->tok);
}

/* ---------------------------------------------------------------- key table */

typedef struct key_desc key_desc;
typedef int key_apply_fn(pctx *x, const key_desc *d, const stmt *s);

struct key_desc {
  const char *key;
  key_apply_fn *apply;
  size_t off;        /* offset of the int/double/string field (generic readers) */
  int pass;          /* 1: applied before the others (names, NPAR) */
  double lo, hi;     /* integer kinds: the accepted range */
  int id;            /* KEY_... (the row), index of pctx.line_of */
};

static const char *describe(const cv *v, char *buf, size_t len)
{
  switch (v->kind) {
  case CV_LIST: snprintf(buf, len, "a list"); break;
  case CV_DICT: snprintf(buf, len, "a dict"); break;
  case CV_STR: snprintf(buf, len, "string '%.100s'", v->text); break;
  default: snprintf(buf, len, "'%.100s'", v->text); break;
  }
  return buf;
}

static int int_field(pctx *x, const key_desc *d, const stmt *s, int *out)
{
  char b[160];
  const cv *v = s->value;
  if (v->kind != CV_INT)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be an integer, got %s", describe(v, b, sizeof b));
  char m[160];
  if (cable_int_range_msg(v->i, d->lo, d->hi, m, sizeof m)) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "%s", m);
  *out = (int)v->i;
  return 0;
}

static int real_value(pctx *x, const char *key, const cv *v, int line, double *out)
{
  char b[160];
  if (v->kind != CV_INT && v->kind != CV_REAL)
    return perr(x, CABLE_ERR_INPUT, line, key, "must be a number, got %s", describe(v, b, sizeof b));
  if (!isfinite(v->r))
    return perr(x, CABLE_ERR_NONFINITE, line, key, "must be a finite number, got '%s'", v->text);
  *out = v->r;
  return 0;
}

static int apply_int(pctx *x, const key_desc *d, const stmt *s)
{
  int val;
  int st = int_field(x, d, s, &val);
  if (st) return st;
  *(int *)((char *)&x->c + d->off) = val;
  return 0;
}

/* STAB=1 needs a problem that declares its variational structure
 * (doc/stability.md); without a problem the engine checks it at the run. */
static int apply_stab(pctx *x, const key_desc *d, const stmt *s)
{
  int st = apply_int(x, d, s);
  if (st == 0 && x->c.stab && x->pb && !x->pb->variational)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key,
                "problem '%s' does not declare its variational structure: its stability cannot be computed",
                x->pb->name ? x->pb->name : "?");
  return st;
}

static int apply_pos(pctx *x, const key_desc *d, const stmt *s);

static int apply_real(pctx *x, const key_desc *d, const stmt *s)
{
  double val = 0;
  int st = real_value(x, s->key, s->value, s->line, &val);
  if (st) return st;
  if (d->apply == apply_pos && !(val > 0))
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be positive, got '%s'", s->value->text);
  *(double *)((char *)&x->c + d->off) = val;
  return 0;
}

/* POS: a real > 0 (apply_real checks the sign for it) */
static int apply_pos(pctx *x, const key_desc *d, const stmt *s)
{
  return apply_real(x, d, s);
}

static int apply_ips(pctx *x, const key_desc *d, const stmt *s)
{
  int val;
  int st = int_field(x, d, s, &val);
  if (st) return st;
  if (val != 4)
    return perr(x, CABLE_ERR_UNSUPPORTED, s->line, s->key,
                "IPS=%d is not supported by cable: cable supports IPS=4 boundary-value problems only", val);
  x->c.ips = 4;
  return 0;
}

static int apply_isw(pctx *x, const key_desc *d, const stmt *s)
{
  int val;
  int st = int_field(x, d, s, &val);
  if (st) return st;
  if (val != 1 && val != -1 && val != 2)
    return perr(x, CABLE_ERR_UNSUPPORTED, s->line, s->key,
                "ISW=%d is not supported by cable: use ISW=1 (continue), ISW=-1 (switch at a BP) or ISW=2 (follow "
                "an LP in two parameters)", val);
  x->c.isw = val;
  return 0;
}

static int apply_ds(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  const cv *v = s->value;
  if (v->kind == CV_STR && strcmp(v->text, "-") == 0) {
    x->c.ds = -x->c.ds;   /* AUTO's DS='-': same step, other direction */
    return 0;
  }
  double val = 0;
  int st = real_value(x, s->key, v, s->line, &val);
  if (st) return st;
  if (val == 0) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be non-zero, got '%s'", v->text);
  x->c.ds = val;
  return 0;
}

static int is_int_text(const char *t)
{
  if (*t == '+' || *t == '-') t++;
  if (!*t) return 0;
  for (; *t; t++)
    if (!isdigit((unsigned char)*t)) return 0;
  return 1;
}

/* Resolve a parameter given by AUTO index (1-based) or name to a 0-based
 * index.  allow_neg: AUTO's UZR convention, -k = stop at PAR(k). */
static int resolve_par(pctx *x, const char *key, const cv *v, int allow_neg, int *index, int *neg)
{
  char b[160];
  long k;
  *neg = 0;
  if (v->kind == CV_INT || (v->kind == CV_STR && is_int_text(v->text))) {
    k = v->kind == CV_INT ? v->i : strtol(v->text, NULL, 10);
    if (k < 0 && allow_neg) {
      *neg = 1;
      k = -k;
    }
    if (k < 1 || k > CABLE_NAMES_MAX)
      return perr(x, CABLE_ERR_INPUT, v->line, key, "parameter index %ld out of range 1..%d (AUTO numbers PAR from 1)",
                  v->kind == CV_INT ? v->i : k, CABLE_NAMES_MAX);
    *index = (int)k - 1;
    return 0;
  }
  if (v->kind != CV_STR)
    return perr(x, CABLE_ERR_INPUT, v->line, key, "expected a parameter index or name, got %s",
                describe(v, b, sizeof b));
  int idx = cable_names_par_index(&x->names, v->text, x->parnames, x->npar_caller);
  if (idx < 0)
    return perr(x, CABLE_ERR_NOTFOUND, v->line, key,
                "unknown parameter name '%s' (not in parnames of the file or the problem)", v->text);
  *index = idx;
  return 0;
}

static int apply_icp(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  const cv *v = s->value;
  int n = v->kind == CV_LIST ? v->n : 1;
  if (v->kind == CV_DICT)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be a list of parameter indices or names");
  if (n == 0) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must name at least one parameter");
  if (n > CABLE_MAX_ICP)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "at most %d parameters, got %d", CABLE_MAX_ICP, n);
  int icp[CABLE_MAX_ICP];
  for (int k = 0; k < n; k++) {
    const cv *e = v->kind == CV_LIST ? v->item[k] : v;
    if (e->kind == CV_LIST || e->kind == CV_DICT)
      return perr(x, CABLE_ERR_INPUT, e->line, s->key, "must be a flat list of parameter indices or names");
    int neg, st = resolve_par(x, s->key, e, 0, &icp[k], &neg);
    if (st) return st;
    for (int j = 0; j < k; j++)
      if (icp[j] == icp[k])
        return perr(x, CABLE_ERR_INPUT, e->line, s->key, "PAR(%d) is listed twice", icp[k] + 1);
  }
  memcpy(x->c.icp, icp, (size_t)n * sizeof icp[0]);
  x->c.nicp = n;
  return 0;
}

static int apply_irs(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  const cv *v = s->value;
  char b[160];
  if (v->kind == CV_INT || (v->kind == CV_STR && is_int_text(v->text))) {
    x->c.irs = v->kind == CV_INT ? (int)v->i : (int)strtol(v->text, NULL, 10);
    x->c.irs_name[0] = '\0';
    return 0;
  }
  if (v->kind != CV_STR)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be a label number or a label name like 'BP1', got %s",
                describe(v, b, sizeof b));
  int type, nth;
  if (cable_label_spec_parse(v->text, &type, &nth) != 0 || strlen(v->text) >= sizeof x->c.irs_name)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key,
                "unknown label '%s': expected a label number, -n (n-th solution) or TYPEn with TYPE one of "
                "BP, LP, UZ, EP, MX, RG and n >= 1",
                v->text);
  snprintf(x->c.irs_name, sizeof x->c.irs_name, "%s", v->text);
  x->c.irs = 1;   /* AUTO's placeholder until the name is looked up in the s-file */
  return 0;
}

static int check_dict(pctx *x, const stmt *s, const char *example)
{
  char b[160];
  if (s->value->kind != CV_DICT)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be a dict like %s, got %s", example,
                describe(s->value, b, sizeof b));
  return 0;
}

/* UZR / UZSTOP: {par: value or [values]}; UZR replaces the entries UZR
 * made, UZSTOP those UZSTOP made (a negative UZR index, AUTO's old way to ask
 * for a stop, belongs to UZR within one parse; entries from an earlier parse
 * count as UZSTOP's when they stop). */
static int apply_uzr(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  int is_stop = strcmp(s->key, "UZSTOP") == 0;
  int st = check_dict(x, s, is_stop ? "{'T': -3.0}" : "{'T': [1.0, 2.0], 11: 0.5}");
  if (st) return st;
  cable_uzr keep[CABLE_MAX_UZR];
  char from_stop[CABLE_MAX_UZR];
  int nkeep = 0;
  memset(keep, 0, sizeof keep);   /* defined padding: the result may be memcmp'ed */
  for (int k = 0; k < x->c.nuzr; k++)
    if (x->uzr_from_stop[k] != is_stop) {
      from_stop[nkeep] = x->uzr_from_stop[k];
      keep[nkeep++] = x->c.uzr[k];
    }
  const cv *v = s->value;
  for (int k = 0; k < v->n; k += 2) {
    int par, neg;
    st = resolve_par(x, s->key, v->item[k], !is_stop, &par, &neg);
    if (st) return st;
    const cv *val = v->item[k + 1];
    int nv = val->kind == CV_LIST ? val->n : 1;
    if (val->kind == CV_DICT)
      return perr(x, CABLE_ERR_INPUT, val->line, s->key, "values must be numbers or lists of numbers");
    for (int j = 0; j < nv; j++) {
      const cv *e = val->kind == CV_LIST ? val->item[j] : val;
      double r;
      st = real_value(x, s->key, e, e->line, &r);
      if (st) return st;
      if (nkeep >= CABLE_MAX_UZR)
        return perr(x, CABLE_ERR_INPUT, e->line, s->key, "more than %d user zeros", CABLE_MAX_UZR);
      keep[nkeep].par = par;
      keep[nkeep].value = r;
      keep[nkeep].stop = is_stop || neg;
      from_stop[nkeep] = (char)is_stop;
      nkeep++;
    }
  }
  memcpy(x->c.uzr, keep, (size_t)nkeep * sizeof keep[0]);
  memcpy(x->uzr_from_stop, from_stop, (size_t)nkeep);
  x->c.nuzr = nkeep;
  return 0;
}

/* A dict {parameter index or name: real} into idx[]/val[] (at most max
 * entries); example is shown in the error for a value that is not a dict. */
static int par_real_dict(pctx *x, const stmt *s, const char *example, int max, int *idx, double *val, int *n)
{
  int st = check_dict(x, s, example);
  if (st) return st;
  const cv *v = s->value;
  if (v->n / 2 > max) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "at most %d entries", max);
  *n = 0;
  for (int k = 0; k < v->n; k += 2) {
    int neg;
    st = resolve_par(x, s->key, v->item[k], 0, &idx[*n], &neg);
    if (st == 0) st = real_value(x, s->key, v->item[k + 1], v->item[k + 1]->line, &val[*n]);
    if (st) return st;
    (*n)++;
  }
  return 0;
}

static int apply_thl(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  int idx[CABLE_MAX_THL], n;
  double w[CABLE_MAX_THL];
  int st = par_real_dict(x, s, "{'T': 1.0, 11: 0.0}", CABLE_MAX_THL, idx, w, &n);
  if (st) return st;
  for (int k = 0; k < n; k++)
    if (w[k] < 0)
      return perr(x, CABLE_ERR_INPUT, s->value->item[2 * k + 1]->line, s->key, "weights must be >= 0, got '%s'",
                  s->value->item[2 * k + 1]->text);
  for (int k = 0; k < n; k++) {
    x->c.thl[k].index = idx[k];
    x->c.thl[k].weight = w[k];
  }
  x->c.nthl = n;
  return 0;
}

/* PAR={'Delta': 0.005, 4: 1.98889}: starting values that override STPNT or
 * the restart solution (AUTO-07p's PAR constant).  As in AUTO, a later PAR
 * (a keyword over a constants file's, or a second statement) updates the
 * entries it names and keeps the others. */
static int apply_par(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  int idx[CABLE_MAX_THL], n;
  double v[CABLE_MAX_THL];
  int st = par_real_dict(x, s, "{'T': 0.0, 5: 0.01}", CABLE_MAX_THL, idx, v, &n);
  if (st) return st;
  for (int k = 0; k < n; k++) {
    int j = 0;
    while (j < x->c.npar_override && x->c.par_override[j].index != idx[k]) j++;
    if (j == CABLE_MAX_THL)
      return perr(x, CABLE_ERR_INPUT, s->line, s->key, "more than %d parameters given start values", CABLE_MAX_THL);
    x->c.par_override[j].index = idx[k];
    x->c.par_override[j].value = v[k];
    if (j == x->c.npar_override) x->c.npar_override++;
  }
  return 0;
}

/* THU is kept raw and checked at the end, when NDIM is known. */
static int apply_thu(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  int st = check_dict(x, s, "{1: 1.0}");
  if (st) return st;
  const cv *v = s->value;
  x->nthu = 0;
  for (int k = 0; k < v->n; k += 2) {
    const cv *key = v->item[k];
    int idx;
    if (key->kind == CV_INT) {
      if (key->i < 1 || key->i > THU_MAX)
        return perr(x, CABLE_ERR_INPUT, key->line, s->key, "component index %ld out of range 1..%d", key->i,
                    THU_MAX);
      idx = (int)key->i - 1;
    } else if (key->kind == CV_STR) {
      idx = cable_names_u_index(&x->names, key->text);
      if (idx < 0)
        return perr(x, CABLE_ERR_NOTFOUND, key->line, s->key, "unknown component name '%s' (not in unames)",
                    key->text);
    } else {
      return perr(x, CABLE_ERR_INPUT, key->line, s->key, "keys must be component indices or names");
    }
    double w;
    st = real_value(x, s->key, v->item[k + 1], v->item[k + 1]->line, &w);
    if (st) return st;
    if (x->nthu >= THU_MAX) return perr(x, CABLE_ERR_INPUT, key->line, s->key, "too many entries");
    x->thu[x->nthu].u = idx;
    x->thu[x->nthu].w = w;
    x->nthu++;
  }
  x->thu_set = 1;
  x->thu_line = s->line;
  return 0;
}

/* 1 when t is well-formed UTF-8 (no overlong forms, surrogates or code
 * points beyond U+10FFFF): names and file names go into b-file headers,
 * which AUTO's parser reads as UTF-8 text. */
static int utf8_valid(const char *t)
{
  const unsigned char *p = (const unsigned char *)t;
  while (*p) {
    unsigned c = *p;
    int n = c < 0x80 ? 0 : (c & 0xE0) == 0xC0 ? 1 : (c & 0xF0) == 0xE0 ? 2 : (c & 0xF8) == 0xF0 ? 3 : -1;
    if (n < 0 || c == 0xC0 || c == 0xC1 || c > 0xF4) return 0;
    unsigned cp = n == 0 ? c : c & (0x3Fu >> n);
    for (int k = 1; k <= n; k++) {
      if ((p[k] & 0xC0) != 0x80) return 0;
      cp = (cp << 6) | (p[k] & 0x3Fu);
    }
    if ((n == 2 && cp < 0x800) || (n == 3 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF))
      return 0;
    p += n + 1;
  }
  return 1;
}

static int check_utf8(pctx *x, const cv *v, const char *key)
{
  if (utf8_valid(v->text)) return 0;
  return perr(x, CABLE_ERR_INPUT, v->line, key, "the string contains bytes that are not UTF-8 text");
}

static int apply_names(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  int is_par = strcmp(s->key, "parnames") == 0;
  int st = check_dict(x, s, is_par ? "{1: 'T', 2: 'L'}" : "{1: 'F1'}");
  if (st) return st;
  char (*tab)[CABLE_NAME_LEN] = is_par ? x->names.par : x->names.u;
  char fresh[CABLE_NAMES_MAX][CABLE_NAME_LEN];
  memset(fresh, 0, sizeof fresh);
  const cv *v = s->value;
  for (int k = 0; k < v->n; k += 2) {
    const cv *key = v->item[k], *val = v->item[k + 1];
    if (key->kind != CV_INT)
      return perr(x, CABLE_ERR_INPUT, key->line, s->key, "keys must be %s indices (1-based), got '%s'",
                  is_par ? "parameter" : "component", key->text ? key->text : "?");
    if (key->i < 1 || key->i > CABLE_NAMES_MAX)
      return perr(x, CABLE_ERR_INPUT, key->line, s->key, "index %ld out of range 1..%d", key->i, CABLE_NAMES_MAX);
    if (val->kind != CV_STR || !val->text[0])
      return perr(x, CABLE_ERR_INPUT, val->line, s->key, "names must be non-empty strings");
    if (!utf8_valid(val->text))
      return perr(x, CABLE_ERR_INPUT, val->line, s->key, "the name for index %ld contains bytes that are not UTF-8 text",
                  key->i);
    if (strlen(val->text) >= CABLE_NAME_LEN)
      return perr(x, CABLE_ERR_INPUT, val->line, s->key, "name '%s' longer than %d characters", val->text,
                  CABLE_NAME_LEN - 1);
    if (is_int_text(val->text))
      return perr(x, CABLE_ERR_INPUT, val->line, s->key, "name '%s' is a number; names must not be", val->text);
    int idx = (int)key->i - 1;
    if (fresh[idx][0])
      return perr(x, CABLE_ERR_INPUT, key->line, s->key, "index %ld named twice", key->i);
    for (int j = 0; j < CABLE_NAMES_MAX; j++)
      if (fresh[j][0] && strcmp(fresh[j], val->text) == 0)
        return perr(x, CABLE_ERR_INPUT, val->line, s->key, "name '%s' given to indices %d and %d", val->text,
                    j + 1, idx + 1);
    strcpy(fresh[idx], val->text);
  }
  memcpy(tab, fresh, sizeof fresh);
  return 0;
}

static int apply_string(pctx *x, const key_desc *d, const stmt *s)
{
  char b[160];
  const cv *v = s->value;
  if (v->kind != CV_STR)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be a string, got %s", describe(v, b, sizeof b));
  int st = check_utf8(x, v, s->key);
  if (st) return st;
  if (strlen(v->text) >= CABLE_NAME_MAX)
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "longer than %d characters", CABLE_NAME_MAX - 1);
  if (strpbrk(v->text, "/ \t") && d->pass == 1)   /* NAME: the problem's */
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "a problem name may not contain '/' or blanks: '%s'", v->text);
  snprintf((char *)&x->c + d->off, CABLE_NAME_MAX, "%s", v->text);
  return 0;
}

static int apply_stop(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  const cv *v = s->value;
  char b[160];
  int n = v->kind == CV_LIST ? v->n : 1;
  if (v->kind == CV_DICT || (v->kind != CV_LIST && v->kind != CV_STR))
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be a list of labels like ['BP1', 'UZ2'], got %s",
                describe(v, b, sizeof b));
  if (n > STOP_MAX) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "at most %d stop conditions", STOP_MAX);
  int type[STOP_MAX], cnt[STOP_MAX];
  for (int k = 0; k < n; k++) {
    const cv *e = v->kind == CV_LIST ? v->item[k] : v;
    if (e->kind != CV_STR || cable_label_spec_parse(e->text, &type[k], &cnt[k]) != 0)
      return perr(x, CABLE_ERR_INPUT, e->line, s->key,
                  "unknown label %s: expected TYPEn with TYPE one of BP, LP, UZ, EP, MX, RG and n >= 1",
                  describe(e, b, sizeof b));
  }
  for (int k = 0; k < n; k++) {
    x->c.stop_on[k] = type[k];
    x->c.stop_count[k] = cnt[k];
  }
  x->c.nstop = n;
  return 0;
}

static int apply_linsolver(pctx *x, const key_desc *d, const stmt *s)
{
  (void)d;
  const cv *v = s->value;
  char b[160];
  if (v->kind == CV_STR && strcasecmp(v->text, "condense") == 0) {
    x->c.linsolver = CABLE_LINSOLVER_CONDENSE;
  } else if (v->kind == CV_STR && strcasecmp(v->text, "klu") == 0) {
    x->c.linsolver = CABLE_LINSOLVER_KLU;
  } else {
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be 'condense' or 'klu', got %s",
                describe(v, b, sizeof b));
  }
  return 0;
}

#define OFF(f) offsetof(cable_constants, f)

/* A kind of cable/cable_constants_keys.h: its reader, the offset of its field
 * (for the generic readers INT, REAL, POS, STR; 0 when the reader knows its
 * fields) and its pass (1: before the other keys, which may use names). */
#define KIND_INT(f) apply_int, OFF(f), 2
#define KIND_DIM(f) apply_int, OFF(f), 2
#define KIND_NPAR(f) apply_int, OFF(f), 1
#define KIND_IPS(f) apply_ips, OFF(f), 2
#define KIND_ISW(f) apply_isw, OFF(f), 2
#define KIND_STAB(f) apply_stab, OFF(f), 2
#define KIND_REAL(f) apply_real, OFF(f), 2
#define KIND_POS(f) apply_pos, OFF(f), 2
#define KIND_DS(f) apply_ds, OFF(f), 2
#define KIND_STR(f) apply_string, OFF(f), 2
#define KIND_NAME(f) apply_string, OFF(f), 1
#define KIND_IRS(f) apply_irs, 0, 2
#define KIND_ICP(f) apply_icp, 0, 2
#define KIND_THL(f) apply_thl, 0, 2
#define KIND_THU(f) apply_thu, 0, 2
#define KIND_UZR(f) apply_uzr, 0, 2
#define KIND_UZSTOP(f) apply_uzr, 0, 2
#define KIND_STOP(f) apply_stop, 0, 2
#define KIND_PAR(f) apply_par, 0, 2
#define KIND_NAMES(f) apply_names, 0, 1
#define KIND_LINSOLVER(f) apply_linsolver, 0, 2

static const key_desc key_table[] = {
#define KEY_ROW(key, field, kind, who, def, lo, hi, line) {#key, KIND_##kind(field), lo, hi, KEY_##key},
  CABLE_CONSTANTS_KEYS(KEY_ROW)
#undef KEY_ROW
};
#define KEY_TABLE_N ((int)(sizeof key_table / sizeof key_table[0]))

/* AUTO-07p keys that AUTO itself accepts and ignores for boundary-value
 * problems (IPS=4): accepted, listed in cable_constants.ignored. */
static const char *const ignored_for_bvp[] = {"MXBF", "NUNSTAB", "NSTAB", "IEQUIB", "ITWIST", "ISTART",
                                              "IREV", "IFIXED", "IPSI", "homcont"};
#define IGNORED_N ((int)(sizeof ignored_for_bvp / sizeof ignored_for_bvp[0]))

/* AUTO-07p keys cable knows but does not support, with the reason. */
static const struct {
  const char *key;
  const char *why;
} unsupported_table[] = {
  {"IBR", "branch numbers are assigned by the run driver"},
  {"TY", "branch types (TY) are not used by cable's IPS=4 runs"},
  {"SP", "use ILP and ISP to switch fold and branch-point detection on or off"},
  {"U", "starting values (U) belong in the problem's STPNT or a restart solution"},
};
#define UNSUPPORTED_N ((int)(sizeof unsupported_table / sizeof unsupported_table[0]))

static const key_desc *key_find(const char *key)
{
  for (int i = 0; i < KEY_TABLE_N; i++)
    if (strcmp(key_table[i].key, key) == 0) return &key_table[i];
  return NULL;
}

void cable_constants_take_problem_dims(cable_constants *c, int ndim, int nbc, int nint)
{
  if (!c) return;
  if (c->ndim == 0) c->ndim = ndim;
  if (c->nbc == 0) c->nbc = nbc;
  if (c->nint == 0) c->nint = nint;
}

int cable_constants_key_known(const char *key)
{
  return key && key_find(key) != NULL;
}

int cable_constants_key_known_for(const cable_problem *pb, const char *key)
{
  return cable_constants_key_known(key) || cable_problem_key_find(pb, key) != NULL;
}

/* A problem-specific key: type, range and words as the problem declares
 * them; the value replaces an earlier one of the same key. */
static int apply_problem_key(pctx *x, const cable_problem_key *k, const stmt *s)
{
  const cv *v = s->value;
  char b[160];
  double val = 0.0;
  const char *help = k->help ? k->help : "";
  if (v->kind == CV_STR && k->words) {
    int found = 0;
    for (const cable_key_word *w = k->words; w->word; w++)
      if (strcasecmp(w->word, v->text) == 0) {
        val = w->value;
        found = 1;
        break;
      }
    if (!found) return perr(x, CABLE_ERR_INPUT, s->line, s->key, "unknown value %s (%s)", describe(v, b, sizeof b), help);
  } else if (k->type == CABLE_KEY_INT) {
    if (v->kind != CV_INT)
      return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be an integer, got %s (%s)", describe(v, b, sizeof b),
                  help);
    val = (double)v->i;
    if (k->words) {
      int found = 0;
      for (const cable_key_word *w = k->words; w->word; w++) found |= w->value == val;
      if (!found)
        return perr(x, CABLE_ERR_INPUT, s->line, s->key, "%ld is not an accepted value (%s)", v->i, help);
    } else if (val < k->min || val > k->max) {
      return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be an integer in %.0f..%.0f, got %ld (%s)", k->min,
                  k->max, v->i, help);
    }
  } else if (k->type == CABLE_KEY_REAL) {
    int st = real_value(x, s->key, v, s->line, &val);
    if (st) return st;
    if (val < k->min || val > k->max)
      return perr(x, CABLE_ERR_INPUT, s->line, s->key, "must be in [%g, %g], got %g (%s)", k->min, k->max, val, help);
  } else {
    return perr(x, CABLE_ERR_INPUT, s->line, s->key, "problem key of unknown type %d", k->type);
  }
  int i = 0;
  while (i < x->c.npkey && strcmp(x->c.pkey[i].name, k->name) != 0) i++;
  if (i == x->c.npkey) {
    if (x->c.npkey >= CABLE_MAX_PKEYS)
      return perr(x, CABLE_ERR_INPUT, s->line, s->key, "more than %d problem keys", CABLE_MAX_PKEYS);
    x->c.npkey++;
  }
  snprintf(x->c.pkey[i].name, sizeof x->c.pkey[i].name, "%s", k->name);
  x->c.pkey[i].value = val;
  return 0;
}

/* 1 when key is one AUTO accepts and cable ignores or refuses (the lists above) */
static int key_cable_other(const char *key)
{
  for (int i = 0; i < IGNORED_N; i++)
    if (strcmp(ignored_for_bvp[i], key) == 0) return 1;
  for (int i = 0; i < UNSUPPORTED_N; i++)
    if (strcmp(unsupported_table[i].key, key) == 0) return 1;
  return 0;
}

static int key_check(pctx *x, const char *key, int line)
{
  if (key_find(key) || cable_problem_key_find(x->pb, key)) return 0;
  for (int i = 0; i < IGNORED_N; i++)
    if (strcmp(ignored_for_bvp[i], key) == 0) {
      size_t n = strlen(x->c.ignored);
      snprintf(x->c.ignored + n, sizeof x->c.ignored - n, "%s%s (line %d)", n ? ", " : "", key, line);
      x->applied++;
      return 0;
    }
  for (int i = 0; i < UNSUPPORTED_N; i++)
    if (strcmp(unsupported_table[i].key, key) == 0)
      return perr(x, CABLE_ERR_UNSUPPORTED, line, key, "AUTO key not supported by cable: %s",
                  unsupported_table[i].why);
  for (int i = 0; i < KEY_TABLE_N; i++)
    if (strcasecmp(key_table[i].key, key) == 0)
      return perr(x, CABLE_ERR_INPUT, line, key, "unknown key (keys are case-sensitive: did you mean '%s'?)",
                  key_table[i].key);
  if (x->pb && x->pb->nkeys > 0)
    return perr(x, CABLE_ERR_INPUT, line, key, "unknown key (neither cable's nor one of problem '%s''s %d keys)",
                x->pb->name ? x->pb->name : "?", x->pb->nkeys);
  return perr(x, CABLE_ERR_INPUT, line, key, "unknown key");
}

/* ---------------------------------------------------------------- statements */

static void stmts_free(pctx *x)
{
  for (int i = 0; i < x->nst; i++) cv_free(x->st[i].value);
  x->nst = 0;
}

static int parse_statements(pctx *x)
{
  int st = lex_next(x);
  while (st == 0) {
    x->cur_key[0] = '\0';
    while (st == 0 && (x->tok_kind == T_NL || tok_is(x, ',') || tok_is(x, ';'))) st = lex_next(x);
    if (st || x->tok_kind == T_EOF) break;
    if (x->tok_kind != T_IDENT) {
      if (x->tok_kind == T_NUM && x->nst == 0)
        return perr(x, CABLE_ERR_UNSUPPORTED, x->tok_line, "",
                    "old-style (numeric) constants files are not supported by cable: write KEY = value lines");
      return perr(x, CABLE_ERR_PARSE, x->tok_line, "", "expected 'KEY = value', got '%s'", x->tok);
    }
    char key[32];
    int line = x->tok_line;
    snprintf(key, sizeof key, "%.31s", x->tok);  /* the lexer limits names to 31 */
    snprintf(x->cur_key, sizeof x->cur_key, "%s", key);
    st = lex_next(x);
    if (st) break;
    if (!tok_is(x, '=')) {
      if (x->tok_kind == T_NL || x->tok_kind == T_EOF)
        return perr(x, CABLE_ERR_PARSE, line, key, "missing '=' after the key");
      return perr(x, CABLE_ERR_PARSE, line, key, "missing '=' after the key (got '%s')", x->tok);
    }
    if (x->resolve && !key_find(key) && !key_cable_other(key)) {
      x->defer[x->ndefer++] = x->nst;   /* perhaps the problem's: checked once it is known */
    } else {
      st = key_check(x, key, line);
      if (st) break;
    }
    for (int i = 0; i < x->nst; i++)
      if (strcmp(x->st[i].key, key) == 0)
        return perr(x, CABLE_ERR_INPUT, line, key, "duplicate key (first set on line %d)", x->st[i].line);
    if (x->nst >= STMT_MAX) return perr(x, CABLE_ERR_INPUT, line, key, "more than %d statements", STMT_MAX);
    st = lex_next(x);
    if (st) break;
    cv *value = NULL;
    st = parse_value(x, key, &value);
    if (st) break;
    stmt *s = &x->st[x->nst++];
    snprintf(s->key, sizeof s->key, "%s", key);
    s->line = line;
    s->value = value;
    if (!(x->tok_kind == T_NL || x->tok_kind == T_EOF || tok_is(x, ',') || tok_is(x, ';')))
      return perr(x, CABLE_ERR_PARSE, x->tok_line, key,
                  "unexpected '%s' after the value (separate statements with ',' or a new line)", x->tok);
  }
  return st;
}

/* The problem, once pass 1 has applied e: its names resolve parameters and
 * its keys are accepted in pass 2; the keys that waited for it are checked
 * now, in the file's order. */
static int resolve_problem(pctx *x)
{
  const cable_problem *pb = NULL;
  const char *e = x->e_given && x->e_given[0] ? x->e_given : x->c.e;
  int st = x->resolve(x->resolve_ctx, e, &pb, x->err);
  if (st) return st;
  x->pb = pb;
  x->parnames = pb ? pb->parnames : NULL;
  x->npar_caller = pb ? pb->npar : 0;
  for (int k = 0; k < x->ndefer; k++) {
    const stmt *d = &x->st[x->defer[k]];
    snprintf(x->cur_key, sizeof x->cur_key, "%s", d->key);
    st = key_check(x, d->key, d->line);
    if (st) return st;
  }
  return 0;
}

static int apply_statements(pctx *x)
{
  for (int pass = 1; pass <= 2; pass++) {
    if (pass == 2 && x->resolve) {
      int st = resolve_problem(x);
      if (st) return st;
    }
    for (int i = 0; i < x->nst; i++) {
      const key_desc *d = key_find(x->st[i].key);
      const cable_problem_key *pk = d ? NULL : cable_problem_key_find(x->pb, x->st[i].key);
      if (pk && pass == 2) {
        int st = apply_problem_key(x, pk, &x->st[i]);
        if (st) return st;
        x->applied++;
        continue;
      }
      if (!d || d->pass != pass) continue;  /* every key was checked when collected */
      int st = d->apply(x, d, &x->st[i]);
      if (st) return st;
      x->applied++;
      x->line_of[d->id] = x->st[i].line;
      cable_key_origin *o = strcmp(d->key, "NDIM") == 0 ? &x->c.origin_ndim
                            : strcmp(d->key, "NBC") == 0 ? &x->c.origin_nbc
                            : strcmp(d->key, "NINT") == 0 ? &x->c.origin_nint
                            : strcmp(d->key, "IPS") == 0 ? &x->c.origin_ips : NULL;
      if (o) {
        snprintf(o->file, sizeof o->file, "%s", x->origin ? x->origin : x->file);
        o->line = x->origin ? 0 : x->st[i].line;
      }
    }
  }
  return 0;
}

/* Cross-checks between keys, on the merged result. */
static int finalize(pctx *x)
{
  cable_constants *c = &x->c;
  if (!(c->rl0 < c->rl1))
    return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_RL1] ? x->line_of[KEY_RL1] : x->line_of[KEY_RL0],
                x->line_of[KEY_RL1] ? "RL1" : "RL0", "RL0 (%g) must be less than RL1 (%g)", c->rl0, c->rl1);
  if (!(c->a0 < c->a1))
    return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_A1] ? x->line_of[KEY_A1] : x->line_of[KEY_A0],
                x->line_of[KEY_A1] ? "A1" : "A0", "A0 (%g) must be less than A1 (%g)", c->a0, c->a1);
  if (c->dsmin > c->dsmax)
    return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_DSMAX] ? x->line_of[KEY_DSMAX] : x->line_of[KEY_DSMIN],
                x->line_of[KEY_DSMAX] ? "DSMAX" : "DSMIN", "DSMIN (%g) must not exceed DSMAX (%g)", c->dsmin,
                c->dsmax);
  for (int k = 0; k < c->nicp; k++)
    if (c->icp[k] >= c->npar)
      return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_ICP], "ICP", "PAR(%d) is beyond NPAR=%d", c->icp[k] + 1,
                  c->npar);
  for (int k = 0; k < c->nuzr; k++)
    if (c->uzr[k].par >= c->npar) {
      int stop = c->uzr[k].stop && x->line_of[KEY_UZSTOP];
      return perr(x, CABLE_ERR_INPUT, x->line_of[stop ? KEY_UZSTOP : KEY_UZR], stop ? "UZSTOP" : "UZR",
                  "PAR(%d) is beyond NPAR=%d", c->uzr[k].par + 1, c->npar);
    }
  for (int k = 0; k < c->nthl; k++)
    if (c->thl[k].index >= c->npar)
      return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_THL], "THL", "PAR(%d) is beyond NPAR=%d", c->thl[k].index + 1,
                  c->npar);
  if (c->ndim > 0 && (c->iplt < -c->ndim || c->iplt > 3 * c->ndim))
    return perr(x, CABLE_ERR_INPUT, x->line_of[KEY_IPLT], "IPLT",
                "IPLT=%d is outside -NDIM..3*NDIM = %d..%d (0: L2-norm; i: max of U(i); -i: min of U(i); NDIM+i: "
                "integral of U(i); 2*NDIM+i: L2-norm of U(i))", c->iplt, -c->ndim, 3 * c->ndim);
  if (x->thu_set) {
    /* cable keeps one weight for all components: accept THU only when it
     * says that (all listed weights 1, AUTO's default, or every component
     * listed with the same weight). */
    int uniform = 1, all_one = 1;
    for (int k = 0; k < x->nthu; k++) {
      if (x->thu[k].w != x->thu[0].w) uniform = 0;
      if (x->thu[k].w != 1.0) all_one = 0;
    }
    int covered = 0;
    if (uniform && c->ndim > 0) {
      covered = 1;
      for (int i = 0; i < c->ndim && covered; i++) {
        int found = 0;
        for (int k = 0; k < x->nthu; k++) found |= x->thu[k].u == i;
        covered = found;
      }
    }
    for (int k = 0; k < x->nthu; k++)
      if (c->ndim > 0 && x->thu[k].u >= c->ndim)
        return perr(x, CABLE_ERR_INPUT, x->thu_line, "THU", "U(%d) is beyond NDIM=%d", x->thu[k].u + 1, c->ndim);
    if (x->nthu == 0 || all_one) {
      c->thu_default = 1.0;
    } else if (covered) {
      if (!(x->thu[0].w > 0))
        return perr(x, CABLE_ERR_INPUT, x->thu_line, "THU", "weights must be positive");
      c->thu_default = x->thu[0].w;
    } else {
      return perr(x, CABLE_ERR_UNSUPPORTED, x->thu_line, "THU",
                  "non-uniform THU weights are not supported by cable: give every component of U the same weight "
                  "or leave THU = {}");
    }
  }
  return 0;
}

/* ---------------------------------------------------------------- entry points */

static pctx *pctx_new(const char *file, const char *src, cable_error *err)
{
  pctx *x = calloc(1, sizeof *x);
  if (!x) {
    cable_error_set(err, CABLE_ERR_ALLOC, file, 0, "", "out of memory");
    return NULL;
  }
  x->file = file;
  x->err = err;
  x->src = src;
  x->line = 1;
  return x;
}

/* How a parse finds its problem: a resolver (the session's), or none. */
typedef struct {
  cable_constants_resolve_fn *fn;
  void *ctx;
  const char *e;
} resolver;

static int run(pctx *x, const char *const *parnames, int npar, const cable_problem *pb)
{
  x->parnames = parnames;
  x->npar_caller = parnames ? npar : 0;
  x->pb = pb;
  int st = parse_statements(x);
  if (st == 0) st = apply_statements(x);
  if (st == 0) st = finalize(x);
  stmts_free(x);
  return st;
}

static int parse_string(const char *name, const char *text, const cable_problem *pb, const char *const *parnames,
                        int npar, const resolver *rs, cable_constants *c, cable_names *names, cable_error *err)
{
  if (!text || !c) return cable_error_set(err, CABLE_ERR_INPUT, name, 0, "", "no text to parse");
  pctx *x = pctx_new(name ? name : "", text, err);
  if (!x) return CABLE_ERR_ALLOC;
  if (rs) {
    x->resolve = rs->fn;
    x->resolve_ctx = rs->ctx;
    x->e_given = rs->e;
  }
  cable_constants_init(&x->c);
  cable_names_init(&x->names);
  int st = run(x, parnames, npar, pb);
  if (st == 0 && !x->c.origin_ips.file[0])   /* no IPS: AUTO's 1; the run names this file */
    snprintf(x->c.origin_ips.file, sizeof x->c.origin_ips.file, "%s", x->file);
  if (st == 0) {
    memcpy(c, &x->c, sizeof *c);   /* padding included: callers may memcmp */
    if (names) *names = x->names;
    cable_error_clear(err);
  }
  free(x);
  return st;
}

int cable_constants_parse_string(const char *name, const char *text, cable_constants *c,
                                 cable_names *names, const char *const *parnames, int npar,
                                 cable_error *err)
{
  if (!text || !c) return cable_error_set(err, CABLE_ERR_NULL, name, 0, "", "cable_constants_parse_string: %s is NULL", !text ? "the text" : "the constants");
  return parse_string(name, text, NULL, parnames, npar, NULL, c, names, err);
}

int cable_constants_parse_string_for(const char *name, const char *text, const cable_problem *pb,
                                     cable_constants *c, cable_names *names, cable_error *err)
{
  if (!text || !c) return cable_error_set(err, CABLE_ERR_NULL, name, 0, "", "cable_constants_parse_string_for: %s is NULL", !text ? "the text" : "the constants");
  return parse_string(name, text, pb, pb ? pb->parnames : NULL, pb ? pb->npar : 0, NULL, c, names, err);
}

static int parse_file(const char *path, const cable_problem *pb, const char *const *parnames, int npar,
                      const resolver *rs, cable_constants *c, cable_names *names, cable_error *err)
{
  if (!path || !c) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "%s is NULL", !path ? "the constants file name" : "the constants");
  FILE *f = fopen(path, "rb");
  if (!f) return cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot open constants file: %s", strerror(errno));
  char *buf = malloc((size_t)FILE_MAX + 1);
  if (!buf) {
    fclose(f);
    return cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
  }
  size_t n = fread(buf, 1, (size_t)FILE_MAX + 1, f);
  int rerr = ferror(f);
  fclose(f);
  int st;
  if (rerr) {
    st = cable_error_set(err, CABLE_ERR_IO, path, 0, "", "read error");
  } else if (n > (size_t)FILE_MAX) {
    st = cable_error_set(err, CABLE_ERR_INPUT, path, 0, "", "file larger than %ld bytes: not a constants file",
                         FILE_MAX);
  } else if (memchr(buf, '\0', n)) {
    st = cable_error_set(err, CABLE_ERR_PARSE, path, 0, "", "file contains NUL bytes: not a constants file");
  } else {
    buf[n] = '\0';
    st = parse_string(path, buf, pb, parnames, npar, rs, c, names, err);
  }
  free(buf);
  return st;
}

int cable_constants_parse_file(const char *path, cable_constants *c, cable_names *names,
                               const char *const *parnames, int npar, cable_error *err)
{
  return parse_file(path, NULL, parnames, npar, NULL, c, names, err);
}

int cable_constants_parse_file_for(const char *path, const cable_problem *pb, cable_constants *c,
                                   cable_names *names, cable_error *err)
{
  return parse_file(path, pb, pb ? pb->parnames : NULL, pb ? pb->npar : 0, NULL, c, names, err);
}

int cable_constants_parse_file_resolve(const char *path, const char *e, cable_constants_resolve_fn *resolve, void *ctx,
                                       cable_constants *c, cable_names *names, cable_error *err)
{
  if (!resolve) return cable_error_set(err, CABLE_ERR_NULL, path, 0, "", "cable_constants_parse_file_resolve: no resolver");
  resolver rs = {resolve, ctx, e};
  return parse_file(path, NULL, NULL, 0, &rs, c, names, err);
}

static int parse_override(const char *keyvalue, const cable_problem *pb, const char *const *parnames, int npar,
                          cable_constants *c, cable_names *names, cable_error *err)
{
  if (!keyvalue || !c) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "%s is NULL", !keyvalue ? "the override" : "the constants");
  int rc0 = cable_constants_consistent(c, CABLE_NAMES_MAX, err);   /* the constants it adds to */
  if (rc0) return rc0;
  if (strchr(keyvalue, '\n'))
    return cable_error_set(err, CABLE_ERR_PARSE, "", 0, "", "an override is one line of KEY=VALUE");
  pctx *x = pctx_new("", keyvalue, err);
  if (!x) return CABLE_ERR_ALLOC;
  x->origin = keyvalue;
  x->c = *c;
  for (int k = 0; k < c->nuzr && k < CABLE_MAX_UZR; k++) x->uzr_from_stop[k] = (char)(c->uzr[k].stop != 0);
  if (names) x->names = *names;
  else cable_names_init(&x->names);
  int st = run(x, parnames, npar, pb);
  if (st == 0 && x->applied == 0)
    st = cable_error_set(err, CABLE_ERR_PARSE, "", 0, "", "empty override: expected KEY=VALUE");
  if (st == 0) {
    memcpy(c, &x->c, sizeof *c);   /* padding included: callers may memcmp */
    if (names) *names = x->names;
    cable_error_clear(err);
  }
  free(x);
  return st;
}

int cable_constants_parse_override(const char *keyvalue, cable_constants *c, cable_names *names,
                                   const char *const *parnames, int npar, cable_error *err)
{
  return parse_override(keyvalue, NULL, parnames, npar, c, names, err);
}

int cable_constants_parse_override_for(const char *keyvalue, const cable_problem *pb, cable_constants *c,
                                       cable_names *names, cable_error *err)
{
  return parse_override(keyvalue, pb, pb ? pb->parnames : NULL, pb ? pb->npar : 0, c, names, err);
}
