/* Tokeniser for run scripts: Python's rules for names, numbers, strings,
 * comments, implicit line joining inside brackets, backslash continuation and
 * indentation (INDENT/DEDENT), restricted to what cable scripts use.  Every
 * rejection names the line and the text at fault. */
#include "script_lex.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script.h"

/* ---- arena ------------------------------------------------------------------ */

struct script_arena_block {
  script_arena_block *next;
  size_t used, cap;   /* in units of max_align_t */
  max_align_t data[];
};

enum { ARENA_BLOCK_UNITS = 1024 };

void *script_arena_alloc(script_arena *a, size_t n)
{
  size_t units = (n + sizeof(max_align_t) - 1) / sizeof(max_align_t);
  if (units == 0) units = 1;
  script_arena_block *b = a->head;
  if (!b || b->cap - b->used < units) {
    size_t cap = units > ARENA_BLOCK_UNITS ? units : ARENA_BLOCK_UNITS;
    b = malloc(sizeof *b + cap * sizeof(max_align_t));
    if (!b) return NULL;
    b->next = a->head;
    b->used = 0;
    b->cap = cap;
    a->head = b;
  }
  void *p = &b->data[b->used];
  b->used += units;
  memset(p, 0, units * sizeof(max_align_t));
  return p;
}

char *script_arena_strndup(script_arena *a, const char *s, size_t n)
{
  char *d = script_arena_alloc(a, n + 1);
  if (!d) return NULL;
  if (n) memcpy(d, s, n);
  d[n] = '\0';
  return d;
}

void script_arena_free(script_arena *a)
{
  script_arena_block *b = a->head;
  while (b) {
    script_arena_block *next = b->next;
    free(b);
    b = next;
  }
  a->head = NULL;
}

/* ---- lexer state -------------------------------------------------------------- */

typedef struct lexer {
  const char *file;
  const char *src, *end, *p;
  int line;
  script_arena *arena;
  script_tokens *out;
  cable_error *err;
  /* indentation stack: columns with tabs to multiples of 8 and with tabs as 1,
   * as Python does, so that ambiguous tab/space mixes are detected */
  int ind8[SCRIPT_MAX_BLOCK_DEPTH + 1], ind1[SCRIPT_MAX_BLOCK_DEPTH + 1];
  int nind;
  /* open brackets */
  char br[SCRIPT_MAX_NESTING];
  int brline[SCRIPT_MAX_NESTING];
  int nbr;
} lexer;

static int lex_fail(lexer *lx, int line, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 4, 5)));
static int lex_fail(lexer *lx, int line, const char *key, const char *fmt, ...)
{
  char msg[256];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return cable_error_set(lx->err, CABLE_ERR_PARSE, lx->file, line, key, "%s", msg);
}

static int push(lexer *lx, script_tok_type type, int line, const char *text, size_t len)
{
  script_tokens *t = lx->out;
  if (t->n == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 256;
    script_token *nt = realloc(t->tok, cap * sizeof *nt);
    if (!nt) return cable_error_set(lx->err, CABLE_ERR_ALLOC, lx->file, line, "", "out of memory");
    t->tok = nt;
    t->cap = cap;
  }
  script_token *k = &t->tok[t->n];
  memset(k, 0, sizeof *k);
  k->type = type;
  k->line = line;
  k->text = script_arena_strndup(lx->arena, text ? text : "", text ? len : 0);
  k->len = len;
  if (!k->text) return cable_error_set(lx->err, CABLE_ERR_ALLOC, lx->file, line, "", "out of memory");
  t->n++;
  return 0;
}

static script_tok_type last_type(const lexer *lx)
{
  return lx->out->n ? lx->out->tok[lx->out->n - 1].type : SCRIPT_TOK_NEWLINE;
}

/* Short excerpt of the source at p for messages. */
static void excerpt(const char *p, const char *end, char *buf, size_t len)
{
  size_t n = 0;
  while (p + n < end && n + 1 < len && n < 16 && p[n] != '\n' && p[n] != '\r') n++;
  memcpy(buf, p, n);
  buf[n] = '\0';
}

/* ---- indentation ------------------------------------------------------------ */

/* At the start of a logical line: measure the indentation, skip blank and
 * comment lines, emit INDENT/DEDENT.  Returns 1 at end of input. */
static int line_start(lexer *lx, int *status)
{
  for (;;) {
    int c8 = 0, c1 = 0;
    while (lx->p < lx->end && (*lx->p == ' ' || *lx->p == '\t' || *lx->p == '\f')) {
      if (*lx->p == '\t') c8 = (c8 / 8 + 1) * 8;
      else if (*lx->p == ' ') c8++;
      if (*lx->p != '\f') c1++;
      lx->p++;
    }
    if (lx->p >= lx->end) return 1;
    if (*lx->p == '#') {
      while (lx->p < lx->end && *lx->p != '\n') lx->p++;
    }
    if (lx->p < lx->end && *lx->p == '\r') lx->p++;
    if (lx->p >= lx->end) return 1;
    if (*lx->p == '\n') {
      lx->p++;
      lx->line++;
      continue;
    }
    /* a statement line */
    int top8 = lx->ind8[lx->nind - 1], top1 = lx->ind1[lx->nind - 1];
    if ((c8 > top8) != (c1 > top1) || (c8 == top8) != (c1 == top1)) {
      *status = lex_fail(lx, lx->line, "indent", "inconsistent use of tabs and spaces in indentation");
      return 0;
    }
    if (c8 > top8) {
      if (lx->nind > SCRIPT_MAX_BLOCK_DEPTH) {
        *status = lex_fail(lx, lx->line, "indent", "blocks nested too deeply (limit %d)",
                           SCRIPT_MAX_BLOCK_DEPTH);
        return 0;
      }
      lx->ind8[lx->nind] = c8;
      lx->ind1[lx->nind] = c1;
      lx->nind++;
      *status = push(lx, SCRIPT_TOK_INDENT, lx->line, "indent", 6);
      return 0;
    }
    while (c8 < lx->ind8[lx->nind - 1]) {
      lx->nind--;
      *status = push(lx, SCRIPT_TOK_DEDENT, lx->line, "dedent", 6);
      if (*status) return 0;
    }
    if (c8 != lx->ind8[lx->nind - 1] || c1 != lx->ind1[lx->nind - 1]) {
      *status = lex_fail(lx, lx->line, "indent",
                         "unindent does not match any outer indentation level");
      return 0;
    }
    *status = 0;
    return 0;
  }
}

/* ---- tokens ----------------------------------------------------------------- */

static int lex_number(lexer *lx)
{
  const char *s = lx->p;
  int is_int = 1;
  while (lx->p < lx->end && isdigit((unsigned char)*lx->p)) lx->p++;
  if (lx->p < lx->end && *lx->p == '.') {
    is_int = 0;
    lx->p++;
    while (lx->p < lx->end && isdigit((unsigned char)*lx->p)) lx->p++;
  }
  if (lx->p < lx->end && (*lx->p == 'e' || *lx->p == 'E')) {
    const char *q = lx->p + 1;
    if (q < lx->end && (*q == '+' || *q == '-')) q++;
    if (q < lx->end && isdigit((unsigned char)*q)) {
      is_int = 0;
      lx->p = q;
      while (lx->p < lx->end && isdigit((unsigned char)*lx->p)) lx->p++;
    }
  }
  size_t n = (size_t)(lx->p - s);
  if (lx->p < lx->end && (isalnum((unsigned char)*lx->p) || *lx->p == '_' || *lx->p == '.')) {
    char ex[32];
    excerpt(s, lx->end, ex, sizeof ex);
    return lex_fail(lx, lx->line, ex, "invalid number");
  }
  int rc = push(lx, SCRIPT_TOK_NUMBER, lx->line, s, n);
  if (rc) return rc;
  script_token *t = &lx->out->tok[lx->out->n - 1];
  t->num = strtod(t->text, NULL);
  t->is_int = is_int;
  return 0;
}

/* A string literal starting at the quote; raw: no escapes (r'...'). */
static int lex_string(lexer *lx, int raw)
{
  const char *start = lx->p;
  int start_line = lx->line;
  char q = *lx->p;
  int triple = lx->end - lx->p >= 3 && lx->p[1] == q && lx->p[2] == q;
  lx->p += triple ? 3 : 1;
  char *buf = malloc((size_t)(lx->end - lx->p) + 1);
  if (!buf) return cable_error_set(lx->err, CABLE_ERR_ALLOC, lx->file, lx->line, "", "out of memory");
  size_t n = 0;
  int rc = 0, closed = 0;
  while (lx->p < lx->end) {
    char c = *lx->p;
    if (c == q && (!triple || (lx->end - lx->p >= 3 && lx->p[1] == q && lx->p[2] == q))) {
      lx->p += triple ? 3 : 1;
      closed = 1;
      break;
    }
    if (c == '\n') {
      if (!triple) break;
      lx->line++;
      buf[n++] = c;
      lx->p++;
      continue;
    }
    if (c == '\\' && lx->p + 1 < lx->end) {
      char e = lx->p[1];
      if (raw) {
        buf[n++] = c;
        buf[n++] = e;
        if (e == '\n') lx->line++;
        lx->p += 2;
        continue;
      }
      lx->p += 2;
      switch (e) {
      case 'n': buf[n++] = '\n'; break;
      case 't': buf[n++] = '\t'; break;
      case 'r': buf[n++] = '\r'; break;
      case '0': buf[n++] = '\0'; break;
      case '\\': buf[n++] = '\\'; break;
      case '\'': buf[n++] = '\''; break;
      case '"': buf[n++] = '"'; break;
      case '\n': lx->line++; break;   /* line continuation inside the string */
      default:   /* Python keeps unknown escapes as written */
        buf[n++] = '\\';
        buf[n++] = e;
        break;
      }
      continue;
    }
    buf[n++] = c;
    lx->p++;
  }
  if (!closed) {
    char ex[32];
    excerpt(start, lx->end, ex, sizeof ex);
    rc = lex_fail(lx, start_line, ex, "unterminated string%s",
                  triple ? " (a triple-quoted string is never closed)" : "");
  } else if (n > SCRIPT_MAX_STRING) {
    rc = lex_fail(lx, start_line, "string", "string literal too long");
  } else {
    rc = push(lx, SCRIPT_TOK_STRING, start_line, buf, n);
  }
  free(buf);
  return rc;
}

/* Longest operators first. */
static const char *const lex_ops[] = {
  "**=", "//=", ">>=", "<<=", "**", "//", "==", "!=", "<=", ">=", "+=", "-=", "*=", "/=", "%=",
  "&=", "|=", "^=", "@=", "->", "<<", ">>", ":=", "(", ")", "[", "]", "{", "}", ",", ":", ";",
  ".", "=", "+", "-", "*", "/", "%", "<", ">", "@", "&", "|", "^", "~", "!", NULL};

static int lex_op(lexer *lx)
{
  for (int i = 0; lex_ops[i]; i++) {
    size_t n = strlen(lex_ops[i]);
    if ((size_t)(lx->end - lx->p) >= n && memcmp(lx->p, lex_ops[i], n) == 0) {
      char c = lex_ops[i][0];
      if (n == 1 && (c == '(' || c == '[' || c == '{')) {
        if (lx->nbr == SCRIPT_MAX_NESTING) {
          return lex_fail(lx, lx->line, lex_ops[i], "brackets nested too deeply (limit %d)",
                          SCRIPT_MAX_NESTING);
        }
        lx->br[lx->nbr] = c;
        lx->brline[lx->nbr] = lx->line;
        lx->nbr++;
      } else if (n == 1 && (c == ')' || c == ']' || c == '}')) {
        char want = c == ')' ? '(' : c == ']' ? '[' : '{';
        if (lx->nbr == 0) return lex_fail(lx, lx->line, lex_ops[i], "unmatched '%s'", lex_ops[i]);
        if (lx->br[lx->nbr - 1] != want) {
          return lex_fail(lx, lx->line, lex_ops[i], "'%c' does not match '%c' opened on line %d",
                          c, lx->br[lx->nbr - 1], lx->brline[lx->nbr - 1]);
        }
        lx->nbr--;
      }
      int rc = push(lx, SCRIPT_TOK_OP, lx->line, lx->p, n);
      lx->p += n;
      return rc;
    }
  }
  char ex[8];
  unsigned char u = (unsigned char)*lx->p;
  if (u >= 0x20 && u < 0x7f) snprintf(ex, sizeof ex, "%c", u);
  else snprintf(ex, sizeof ex, "\\x%02x", u);
  return lex_fail(lx, lx->line, ex, "invalid character in script%s",
                  u >= 0x80 ? " (only ASCII outside strings and comments)" : "");
}

static int lex_name(lexer *lx)
{
  const char *s = lx->p;
  while (lx->p < lx->end && (isalnum((unsigned char)*lx->p) || *lx->p == '_')) lx->p++;
  size_t n = (size_t)(lx->p - s);
  /* string prefixes: r'..' raw, u'..' plain; f/b strings are not supported */
  if (n <= 2 && lx->p < lx->end && (*lx->p == '\'' || *lx->p == '"')) {
    int raw = 0, bad = 0;
    for (size_t i = 0; i < n; i++) {
      char c = (char)tolower((unsigned char)s[i]);
      if (c == 'r') raw = 1;
      else if (c != 'u') bad = 1;
    }
    if (!bad) return lex_string(lx, raw);
    char ex[8];
    snprintf(ex, sizeof ex, "%.*s", (int)n, s);
    return lex_fail(lx, lx->line, ex, "%s",
                    "f-strings and byte strings are not supported (use 'text %d' % value)");
  }
  if (n >= SCRIPT_NAME_MAX) {
    char ex[32];
    excerpt(s, lx->end, ex, sizeof ex);
    return lex_fail(lx, lx->line, ex, "name too long (limit %d characters)", SCRIPT_NAME_MAX - 1);
  }
  return push(lx, SCRIPT_TOK_NAME, lx->line, s, n);
}

int script_lex(const char *file, const char *src, size_t len, script_arena *arena,
               script_tokens *tokens, cable_error *err)
{
  lexer lx;
  memset(&lx, 0, sizeof lx);
  lx.file = file;
  lx.src = lx.p = src;
  lx.end = src + len;
  lx.line = 1;
  lx.arena = arena;
  lx.out = tokens;
  lx.err = err;
  lx.nind = 1;
  int rc = 0;
  int at_line_start = 1;
  while (!rc) {
    if (at_line_start) {
      at_line_start = 0;
      if (line_start(&lx, &rc)) break;
      if (rc) break;
    }
    if (lx.p >= lx.end) break;
    char c = *lx.p;
    if (c == ' ' || c == '\t' || c == '\f' || c == '\r') {
      lx.p++;
    } else if (c == '#') {
      while (lx.p < lx.end && *lx.p != '\n') lx.p++;
    } else if (c == '\n') {
      if (lx.nbr == 0 && last_type(&lx) != SCRIPT_TOK_NEWLINE)
        rc = push(&lx, SCRIPT_TOK_NEWLINE, lx.line, "end of line", 11);
      lx.p++;
      lx.line++;
      at_line_start = lx.nbr == 0;   /* inside brackets lines join */
    } else if (c == '\\') {
      const char *q = lx.p + 1;
      if (q < lx.end && *q == '\r') q++;
      if (q < lx.end && *q == '\n') {
        lx.p = q + 1;
        lx.line++;
      } else {
        rc = lex_fail(&lx, lx.line, "\\", "%s", "a backslash must end the line (line continuation)");
      }
    } else if (isdigit((unsigned char)c) ||
               (c == '.' && lx.p + 1 < lx.end && isdigit((unsigned char)lx.p[1]))) {
      rc = lex_number(&lx);
    } else if (isalpha((unsigned char)c) || c == '_') {
      rc = lex_name(&lx);
    } else if (c == '\'' || c == '"') {
      rc = lex_string(&lx, 0);
    } else {
      rc = lex_op(&lx);
    }
  }
  if (!rc && lx.nbr > 0) {
    char key[2] = {lx.br[lx.nbr - 1], '\0'};
    rc = lex_fail(&lx, lx.brline[lx.nbr - 1], key, "'%s' is never closed", key);
  }
  if (!rc && lx.out->n && last_type(&lx) != SCRIPT_TOK_NEWLINE)
    rc = push(&lx, SCRIPT_TOK_NEWLINE, lx.line, "end of line", 11);
  while (!rc && lx.nind > 1) {
    lx.nind--;
    rc = push(&lx, SCRIPT_TOK_DEDENT, lx.line, "dedent", 6);
  }
  if (!rc) rc = push(&lx, SCRIPT_TOK_EOF, lx.line, "end of file", 11);
  return rc;
}
