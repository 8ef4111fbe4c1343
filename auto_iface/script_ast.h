/* The parsed form of a run script.  All nodes and texts live in the
 * program's arena; sibling lists are linked through `next`, so no node is
 * ever reallocated. */
#ifndef CABLE_SCRIPT_AST_H
#define CABLE_SCRIPT_AST_H

#include <stddef.h>

#include "cable/cable_error.h"
#include "script_lex.h"

typedef enum script_expr_kind {
  SCRIPT_E_NUMBER,
  SCRIPT_E_STRING,
  SCRIPT_E_NAME,
  SCRIPT_E_NONE,
  SCRIPT_E_TRUE,
  SCRIPT_E_FALSE,
  SCRIPT_E_LIST,     /* [a, b]; also tuples (a, b), which behave as lists */
  SCRIPT_E_DICT,     /* items: key, value, key, value ... */
  SCRIPT_E_NEG,      /* -a */
  SCRIPT_E_NOT,      /* not a */
  SCRIPT_E_BINARY,   /* a OP b */
  SCRIPT_E_AND,      /* a and b (short-circuit) */
  SCRIPT_E_OR,       /* a or b */
  SCRIPT_E_CALL,     /* a(items): items with kwname set are keyword arguments */
  SCRIPT_E_INDEX     /* a[b] */
} script_expr_kind;

typedef enum script_binop {
  SCRIPT_OP_ADD,
  SCRIPT_OP_SUB,
  SCRIPT_OP_MOD,
  SCRIPT_OP_EQ,
  SCRIPT_OP_NE,
  SCRIPT_OP_LT,
  SCRIPT_OP_LE,
  SCRIPT_OP_GT,
  SCRIPT_OP_GE
} script_binop;

typedef struct script_expr script_expr;
struct script_expr {
  script_expr_kind kind;
  script_binop op;
  int line;
  int height;            /* 1 + tallest child (bounded by SCRIPT_MAX_EXPR_HEIGHT) */
  double num;            /* NUMBER */
  int is_int;
  const char *text;      /* STRING (decoded), NAME; the operator text for BINARY */
  size_t len;            /* STRING */
  script_expr *a, *b;    /* operands; CALL: a = the callee; INDEX: a[b] */
  script_expr *items;    /* LIST, DICT, CALL arguments */
  int nitems;
  const char *kwname;    /* a keyword argument's name (inside CALL items) */
  script_expr *next;     /* next sibling in items */
};

typedef enum script_stmt_kind {
  SCRIPT_S_EXPR,
  SCRIPT_S_ASSIGN,     /* name = expr */
  SCRIPT_S_ADDASSIGN,  /* name += expr */
  SCRIPT_S_FOR,        /* for names in expr: body */
  SCRIPT_S_IF,         /* if/elif clauses, else body */
  SCRIPT_S_PASS,
  SCRIPT_S_BREAK,
  SCRIPT_S_CONTINUE
} script_stmt_kind;

typedef struct script_stmt script_stmt;

typedef struct script_clause {
  int line;
  script_expr *cond;
  script_stmt *body;
  struct script_clause *next;
} script_clause;

#define SCRIPT_MAX_FOR_NAMES 8   /* for a, b, c in ...: names unpacked per element */

struct script_stmt {
  script_stmt_kind kind;
  int line;
  const char *name;                          /* ASSIGN, ADDASSIGN */
  const char *names[SCRIPT_MAX_FOR_NAMES];   /* FOR */
  int nnames;
  script_expr *expr;                         /* value, iterable */
  script_stmt *body;                         /* FOR */
  script_clause *clauses;                    /* IF */
  script_stmt *else_body;                    /* IF */
  script_stmt *next;
};

typedef struct script_program {
  script_arena arena;
  script_stmt *first;
} script_program;

/* Parses the whole text; NULL on failure with err set (CABLE_ERR_PARSE or
 * CABLE_ERR_ALLOC). */
script_program *script_program_parse(const char *file, const char *text, size_t len,
                                     cable_error *err);
void script_program_free(script_program *p);   /* NULL is a no-op */

#endif
