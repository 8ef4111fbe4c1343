/* SPDX-License-Identifier: GPL-3.0-or-later */
/* One namespace (issue 27): every symbol libcable.so exports starts with
 * cable_, and every name the public headers give a program (functions,
 * types, struct and enum tags, enum constants, macros) starts with cable_ or
 * CABLE_.  The exported symbols come from `nm -D --defined-only` on the
 * libcable.so this program has loaded (/proc/self/maps); the names from a
 * small scanner over the headers of include/cable/ (run from the repository root, as
 * scripts/run-tests.sh does).  Linked with libcable.so, public headers only. */
#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api_check.h"
#include "cable/cable.h"

#define LINE_MAX_LEN 4096
#define PATH_LEN 1024

/* The path of the libcable.so mapped into this process, or "" */
static void loaded_library(char *path, size_t len)
{
  path[0] = '\0';
  FILE *f = fopen("/proc/self/maps", "r");
  if (!f) return;
  char line[LINE_MAX_LEN];
  while (fgets(line, sizeof line, f)) {
    char *p = strchr(line, '/');
    if (!p || !strstr(p, "/libcable.so")) continue;
    p[strcspn(p, "\n")] = '\0';
    snprintf(path, len, "%s", p);
    break;
  }
  fclose(f);
}

static int starts_with(const char *s, const char *prefix) { return strncmp(s, prefix, strlen(prefix)) == 0; }

static void check_exports(void)
{
  char lib[PATH_LEN];
  loaded_library(lib, sizeof lib);
  if (!api_check("libcable.so is loaded (/proc/self/maps)", lib[0] != '\0')) return;
  char cmd[PATH_LEN + 64];
  snprintf(cmd, sizeof cmd, "nm -D --defined-only '%s'", lib);
  FILE *p = popen(cmd, "r");
  if (!api_check("nm -D runs", p != NULL)) return;
  char line[LINE_MAX_LEN];
  int n = 0, bad = 0, have_compute = 0;
  while (fgets(line, sizeof line, p)) {
    char addr[64], type[8], name[512];
    if (sscanf(line, "%63s %7s %511s", addr, type, name) != 3) continue;
    n++;
    if (strcmp(name, "cable_braid_analysis_compute") == 0) have_compute = 1;
    if (!starts_with(name, "cable_")) {
      bad++;
      printf("FAIL exported symbol without the cable_ prefix: %s (%s)\n", name, type);
    }
  }
  int st = pclose(p);
  api_check_int("nm -D exit status", st, 0);
  printf("%d symbols exported by %s\n", n, lib);
  api_check("libcable.so exports the API (more than 100 symbols, cable_braid_analysis_compute among them)",
            n > 100 && have_compute);
  api_check_int("exported symbols without the cable_ prefix", bad, 0);
}

/* ------------------------------------------------------------ the headers */

/* The header's text without comments, string and character literals. */
static char *read_code(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long len = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *t = len >= 0 ? malloc((size_t)len + 1) : NULL;
  if (!t || fread(t, 1, (size_t)len, f) != (size_t)len) {
    free(t);
    fclose(f);
    return NULL;
  }
  fclose(f);
  t[len] = '\0';
  for (char *s = t; *s; s++) {
    if (s[0] == '/' && s[1] == '*') {
      char *e = strstr(s + 2, "*/");
      char *stop = e ? e + 2 : s + strlen(s);
      for (char *q = s; q < stop; q++)
        if (*q != '\n') *q = ' ';
      s = stop - 1;
    } else if (s[0] == '/' && s[1] == '/') {
      while (*s && *s != '\n') *s++ = ' ';
      s--;
    } else if (*s == '"' || *s == '\'') {
      char quote = *s;
      for (s++; *s && *s != quote; s++) {
        if (*s == '\\' && s[1]) *s++ = ' ';
        if (*s != '\n') *s = ' ';
      }
      if (!*s) break;
    }
  }
  return t;
}

typedef struct {
  const char *file;
  int bad;
  int names;
  int quiet;   /* the scanner's self-test: found names are listed, not failed */
} scan_state;

static void want(scan_state *st, const char *name, const char *what, int upper)
{
  st->names++;
  if (starts_with(name, upper ? "CABLE_" : "cable_")) return;
  /* the X-macro parameter of CABLE_STATUS_TABLE and C keywords are no names */
  if (upper && strcmp(name, "X") == 0) return;
  st->bad++;
  printf("%s %s: %s '%s' without the %s prefix\n", st->quiet ? "  found" : "FAIL", st->file, what, name, upper ? "CABLE_" : "cable_");
}

static int ident_start(int c) { return isalpha(c) || c == '_'; }
static int ident_char(int c) { return isalnum(c) || c == '_'; }

/* Next identifier or punctuation character of s from *pos into tok;
 * 0 at the end. */
static int next_token(const char *s, size_t *pos, char *tok, size_t len)
{
  while (s[*pos] && isspace((unsigned char)s[*pos])) (*pos)++;
  if (!s[*pos]) return 0;
  size_t n = 0;
  if (ident_start((unsigned char)s[*pos]) || isdigit((unsigned char)s[*pos])) {
    while (ident_char((unsigned char)s[*pos]) || s[*pos] == '.') {
      if (n + 1 < len) tok[n++] = s[*pos];
      (*pos)++;
    }
  } else {
    tok[n++] = s[(*pos)++];
  }
  tok[n] = '\0';
  return 1;
}

static int is_keyword(const char *t)
{
  static const char *const kw[] = {"typedef", "struct", "enum", "union", "const", "static", "inline", "extern",
                                   "void", "int", "long", "double", "float", "char", "short", "unsigned",
                                   "signed", "size_t", "FILE", "CABLE_API", "__attribute__", "format", "printf",
                                   "return", "restrict", "volatile", NULL};
  for (int i = 0; kw[i]; i++)
    if (strcmp(t, kw[i]) == 0) return 1;
  return 0;
}

/* The names a header declares at file scope: #define, struct/enum tags,
 * enum constants, typedef names, functions. */
static void scan_header(scan_state *st, char *code)
{
  /* macros: the preprocessor lines, then blanked out */
  for (char *line = code; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
    char *h = line;
    while (*h == ' ' || *h == '\t') h++;
    if (*h != '#') continue;
    char name[256] = "";
    if (sscanf(h, "# define %255[A-Za-z0-9_]", name) == 1) want(st, name, "macro", 1);
    /* the directive and its continuation lines */
    char before = ' ';
    for (char *q = line; *q; q++) {
      if (*q == '\n' && before != '\\') break;
      before = *q;
      if (*q != '\n') *q = ' ';
    }
  }
  size_t pos = 0;
  char tok[256], prev[256] = "", prev2[256] = "", last_ident[256] = "", fptr_name[256] = "";
  int depth = 0, paren = 0, in_enum = 0, enum_depth = -1, typedef_stmt = 0, expect_enumerator = 0;
  int pending_enum = 0, seen_paren = 0;
  while (next_token(code, &pos, tok, sizeof tok)) {
    int ident = ident_start((unsigned char)tok[0]);
    if (ident && (strcmp(prev, "struct") == 0 || strcmp(prev, "enum") == 0 || strcmp(prev, "union") == 0))
      want(st, tok, "tag", 0);
    if (strcmp(tok, "enum") == 0) pending_enum = 1;
    if (strcmp(tok, "{") == 0) {
      if (pending_enum && !in_enum) {
        in_enum = 1;
        enum_depth = depth;
        expect_enumerator = 1;
      }
      pending_enum = 0;
      depth++;
    } else if (strcmp(tok, "}") == 0) {
      depth--;
      if (in_enum && depth == enum_depth) in_enum = 0;
    } else if (strcmp(tok, "(") == 0) {
      /* a function (or function pointer) declared at file scope: its name is
         the identifier just before the first parenthesis */
      if (depth == 0 && paren == 0 && !seen_paren && last_ident[0] && strcmp(prev, last_ident) == 0 &&
          !typedef_stmt && strcmp(last_ident, "__attribute__") != 0)
        want(st, last_ident, "function", 0);
      if (depth == 0 && paren == 0) seen_paren = 1;
      paren++;
    } else if (strcmp(tok, ")") == 0) {
      paren--;
    } else if (strcmp(tok, ";") == 0 && depth == 0) {
      if (typedef_stmt) want(st, fptr_name[0] ? fptr_name : last_ident, "typedef", 0);
      typedef_stmt = 0;
      seen_paren = 0;
      fptr_name[0] = last_ident[0] = '\0';
    } else if (strcmp(tok, "}") != 0 && depth == 0 && strcmp(tok, "typedef") == 0) {
      typedef_stmt = 1;
    }
    if (in_enum && depth == enum_depth + 1) {
      if (strcmp(tok, ",") == 0) expect_enumerator = 1;
      else if (ident && expect_enumerator) {
        want(st, tok, "enum constant", 1);
        expect_enumerator = 0;
      }
    }
    if (ident && depth == 0 && !is_keyword(tok)) {
      /* typedef void (*name)(...): the name after "(*" */
      if (typedef_stmt && strcmp(prev, "*") == 0 && strcmp(prev2, "(") == 0 && paren == 1 && !fptr_name[0])
        snprintf(fptr_name, sizeof fptr_name, "%s", tok);
      if (paren == 0) snprintf(last_ident, sizeof last_ident, "%s", tok);
    }
    /* a static inline function's body ends its declaration */
    if (strcmp(tok, "}") == 0 && depth == 0 && !typedef_stmt) seen_paren = 0, last_ident[0] = '\0';
    snprintf(prev2, sizeof prev2, "%s", prev);
    snprintf(prev, sizeof prev, "%s", tok);
  }
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void check_headers(void)
{
  DIR *d = opendir("include/cable");
  if (!api_check("include/cable/ is readable (run from the repository root)", d != NULL)) return;
  char *names[128];
  int nh = 0;
  struct dirent *e;
  while ((e = readdir(d)) && nh < 128) {
    size_t l = strlen(e->d_name);
    if (l > 2 && strcmp(e->d_name + l - 2, ".h") == 0) names[nh++] = strdup(e->d_name);
  }
  closedir(d);
  qsort(names, (size_t)nh, sizeof names[0], by_name);
  int bad = 0, total = 0;
  for (int i = 0; i < nh; i++) {
    char path[PATH_LEN];
    snprintf(path, sizeof path, "include/cable/%s", names[i]);
    char *code = read_code(path);
    if (!api_check(path, code != NULL)) {
      free(names[i]);
      continue;
    }
    scan_state st = {path, 0, 0, 0};
    scan_header(&st, code);
    bad += st.bad;
    total += st.names;
    free(code);
    free(names[i]);
  }
  printf("%d public headers, %d names declared\n", nh, total);
  api_check("the public headers declare names (more than 300)", total > 300);
  api_check_int("public names without the cable_/CABLE_ prefix", bad, 0);
}

/* The scanner itself finds names without the prefix (so that a pass above
 * means something). */
static void check_scanner(void)
{
  char code[] = "#define TUBE_MAX 64\n"
                "typedef struct knot_result { int a; } knot_result;\n"
                "enum { RENDER_NONE = 0, CABLE_OK = 1 };\n"
                "typedef void (*handler_fn)(int x);\n"
                "CABLE_API int braid_compute(const cable_solution *s, int n);\n"
                "static inline int cable_ok(int x) { return x; }\n";
  scan_state st = {"(scanner self-test)", 0, 0, 1};
  scan_header(&st, code);
  api_check_int("the scanner finds TUBE_MAX, knot_result (tag and typedef), RENDER_NONE, handler_fn, braid_compute",
                st.bad, 6);
}

int main(void)
{
  /* a call into libcable, so that the library is loaded (--as-needed) */
  api_check("cable_status_name(CABLE_SUCCESS)", strcmp(cable_status_name(CABLE_SUCCESS), "CABLE_SUCCESS") == 0);
  check_scanner();
  check_exports();
  check_headers();
  return api_summary();
}
