/* Tokens of a run script (Python's lexical rules, restricted): the whole text
 * is tokenised before parsing, with INDENT/DEDENT tokens for blocks.  Token
 * texts live in an arena that the parsed program keeps. */
#ifndef CABLE_SCRIPT_LEX_H
#define CABLE_SCRIPT_LEX_H

#include <stddef.h>

#include "cable/cable_error.h"

/* A bump allocator: everything the parser builds is freed at once. */
typedef struct script_arena_block script_arena_block;
typedef struct script_arena {
  script_arena_block *head;
} script_arena;

void *script_arena_alloc(script_arena *a, size_t n);   /* zeroed; NULL when out of memory */
char *script_arena_strndup(script_arena *a, const char *s, size_t n);
void script_arena_free(script_arena *a);

typedef enum script_tok_type {
  SCRIPT_TOK_EOF = 0,
  SCRIPT_TOK_NEWLINE,
  SCRIPT_TOK_INDENT,
  SCRIPT_TOK_DEDENT,
  SCRIPT_TOK_NAME,
  SCRIPT_TOK_NUMBER,
  SCRIPT_TOK_STRING,
  SCRIPT_TOK_OP
} script_tok_type;

typedef struct script_token {
  script_tok_type type;
  int line;
  const char *text;   /* NAME: the name; STRING: the decoded text; OP: the operator;
                         NUMBER: the literal as written (all NUL-terminated) */
  size_t len;         /* STRING: decoded length (may contain NUL bytes) */
  double num;         /* NUMBER */
  int is_int;         /* NUMBER without '.' or exponent */
} script_token;

typedef struct script_tokens {
  script_token *tok;
  size_t n, cap;
} script_tokens;

/* Tokenises src[0..len).  Returns 0 or CABLE_ERR_PARSE / CABLE_ERR_ALLOC with
 * err naming file, line and the text at fault.  tokens->tok is malloc'd (free
 * it with free() even on failure). */
int script_lex(const char *file, const char *src, size_t len, script_arena *arena,
               script_tokens *tokens, cable_error *err);

#endif
