/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Building an AUTO equation file into a module, with a cache keyed by the
 * file's content: the module of a file cable has built before is reused, a
 * changed file is built again.  Fortran files are checked against AUTO's
 * signatures with the compiler's own list of the file's external procedures
 * (gfortran -fc-prototypes-external); C files are compiled with cable's
 * auto_f2c.h, whose prototypes turn a wrong signature into a compile error. */
#include <ctype.h>
#include <dirent.h>
#include <stdarg.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "autoeq_impl.h"
#include "cable/cable_status.h"

#define AUTOEQ_SRC_MAX (16L << 20)   /* an equation file larger than this is refused */
#define AUTOEQ_EXEC_FAILED 127       /* the child's exit status when exec fails */
#define AUTOEQ_CACHE_TAG "cable-autoeq-2"   /* bump when the build recipe changes */

const char *const autoeq_routine_name[AE_NROUTINES] = {"FUNC", "STPNT", "BCND", "ICND", "FOPT", "PVLS"};

/* AUTO's argument lists: 'i' INTEGER, 'd' DOUBLE PRECISION (all by reference). */
const char *const autoeq_auto_args[AE_NROUTINES] = {"idididdd", "iddd", "idiidddid", "idiidddddid", "idididdd", "idd"};
const char *const autoeq_auto_sig[AE_NROUTINES] = {
  "FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)", "STPNT(NDIM,U,PAR,T)", "BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)",
  "ICND(NDIM,PAR,ICP,NINT,U,UOLD,UDOT,UPOLD,FI,IJAC,DINT)", "FOPT(NDIM,U,ICP,PAR,IJAC,FS,DFDU,DFDP)",
  "PVLS(NDIM,U,PAR)"};

#define AUTOEQ_MAX_PROCS 512   /* procedure statements remembered per file */

/* snprintf for paths: -1 when the result does not fit. */
static int fmt_path(char *out, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fmt_path(char *out, size_t len, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(out, len, fmt, ap);
  va_end(ap);
  return n < 0 || (size_t)n >= len ? -1 : 0;
}

/* Free-form Fortran (.f90) as opposed to fixed form (.f). */
static int has_f90_suffix(const char *path)
{
  size_t n = strlen(path);
  return n > 4 && strcmp(path + n - 4, ".f90") == 0;
}

static uint64_t fnv1a(uint64_t h, const void *p, size_t n)
{
  const unsigned char *b = p;
  for (size_t i = 0; i < n; i++) {
    h ^= b[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

static const char *compiler(autoeq_lang lang)
{
  const char *v = getenv(lang == AUTOEQ_FORTRAN ? "CABLE_FC" : "CABLE_CC");
  return v && v[0] ? v : lang == AUTOEQ_FORTRAN ? "gfortran" : "cc";
}

static int mkdir_p(const char *path)
{
  char buf[AUTOEQ_PATH_MAX];
  snprintf(buf, sizeof buf, "%s", path);
  for (char *p = buf + 1; *p; p++)
    if (*p == '/') {
      *p = '\0';
      if (mkdir(buf, 0755) != 0 && errno != EEXIST) return -1;
      *p = '/';
    }
  return mkdir(buf, 0755) != 0 && errno != EEXIST ? -1 : 0;
}

static int cache_dir(char *out, size_t len, cable_error *err)
{
  const char *v = getenv("CABLE_CACHE_DIR"), *x = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
  if (v && v[0]) snprintf(out, len, "%s", v);
  else if (x && x[0]) snprintf(out, len, "%s/cable/equations", x);
  else if (home && home[0]) snprintf(out, len, "%s/.cache/cable/equations", home);
  else
    return cable_error_set(err, CABLE_ERR_IO, "", 0, "", "no cache directory for built equation files: set "
                           "CABLE_CACHE_DIR or HOME");
  if (mkdir_p(out) != 0)
    return cable_error_set(err, CABLE_ERR_IO, out, 0, "", "cannot create the cache directory: %s", strerror(errno));
  return 0;
}

static char *read_all(const char *path, size_t *n, cable_error *err)
{
  FILE *f = fopen(path, "rb");
  struct stat st;
  if (!f || fstat(fileno(f), &st) != 0) {
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot open the equation file: %s", strerror(errno));
    if (f) fclose(f);
    return NULL;
  }
  if (st.st_size > AUTOEQ_SRC_MAX) {
    fclose(f);
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "larger than %ld bytes: not an equation file", AUTOEQ_SRC_MAX);
    return NULL;
  }
  size_t cap = (size_t)st.st_size;
  char *buf = malloc(cap + 1);
  if (!buf) {
    fclose(f);
    cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
    return NULL;
  }
  *n = fread(buf, 1, cap, f);
  int bad = ferror(f) || *n != cap;
  fclose(f);
  if (bad) {
    free(buf);
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "read error");
    return NULL;
  }
  buf[*n] = '\0';
  return buf;
}

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  int bad = fputs(text, f) < 0;
  return fclose(f) != 0 || bad ? -1 : 0;
}

/* Runs argv[0] with stdout to out (NULL: to log) and stderr to log; the exit
 * status, AUTOEQ_EXEC_FAILED when the program cannot be run, -1 when fork
 * fails. */
static int run_tool(char *const argv[], const char *out, const char *log)
{
  pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    int fl = open(log, O_WRONLY | O_CREAT | O_APPEND, 0644);
    int fo = out ? open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644) : fl;
    if (fl < 0 || fo < 0) _exit(AUTOEQ_EXEC_FAILED);
    dup2(fo, 1);
    dup2(fl, 2);
    execvp(argv[0], argv);
    dprintf(2, "cable: cannot run %s: %s\n", argv[0], strerror(errno));
    _exit(AUTOEQ_EXEC_FAILED);
  }
  int st;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* A Fortran comment line: '!' first, or (fixed form) C, c or * in column 1. */
static int fortran_comment(const char *line, size_t n, int fixed)
{
  if (fixed && n > 0 && (line[0] == 'c' || line[0] == 'C' || line[0] == '*')) return 1;
  size_t i = 0;
  while (i < n && (line[i] == ' ' || line[i] == '\t')) i++;
  return i < n && line[i] == '!';
}

/* Whether a (lower-case, non-comment) line opens a procedure: the word
 * "subroutine" or "function" before its first '(' (prefixes such as
 * "double precision function" or "recursive subroutine" allowed), not an END
 * statement. */
static int opens_procedure(const char *low)
{
  while (*low == ' ' || *low == '\t') low++;
  if (strncmp(low, "end", 3) == 0 && !isalnum((unsigned char)low[3]) && low[3] != '_') return 0;
  const char *paren = strchr(low, '(');
  const char *const words[] = {"subroutine", "function"};
  for (int w = 0; w < 2; w++)
    for (const char *q = strstr(low, words[w]); q && (!paren || q < paren); q = strstr(q + 1, words[w])) {
      size_t len = strlen(words[w]);
      int before = q == low || q[-1] == ' ' || q[-1] == '\t' || q[-1] == ')';
      if (before && (q[len] == ' ' || q[len] == '\t')) return 1;
    }
  return 0;
}

/* The 1-based line of each SUBROUTINE NAME in a Fortran source (0: none), and
 * the lines of every procedure statement (procs, *nprocs of them, ascending). */
static void definition_lines(const char *src, int fixed, int *lines, int *procs, int *nprocs)
{
  int line = 1;
  *nprocs = 0;
  for (const char *p = src; *p; line++) {
    const char *eol = strchr(p, '\n');
    size_t n = eol ? (size_t)(eol - p) : strlen(p);
    char low[256];
    size_t k = 0;
    for (size_t i = 0; i < n && k + 1 < sizeof low; i++) low[k++] = (char)tolower((unsigned char)p[i]);
    low[k] = '\0';
    if (!fortran_comment(p, n, fixed) && opens_procedure(low) && *nprocs < AUTOEQ_MAX_PROCS) procs[(*nprocs)++] = line;
    const char *q = low;
    while (*q == ' ' || *q == '\t') q++;
    if (strncmp(q, "subroutine", 10) == 0 && (q[10] == ' ' || q[10] == '\t')) {
      q += 10;
      while (*q == ' ' || *q == '\t') q++;
      for (int r = 0; r < AE_NROUTINES; r++) {
        size_t len = strlen(autoeq_routine_name[r]);
        char lname[8];
        for (size_t i = 0; i <= len; i++) lname[i] = (char)tolower((unsigned char)autoeq_routine_name[r][i]);
        if (strncmp(q, lname, len) == 0 && !isalnum((unsigned char)q[len]) && q[len] != '_' && !lines[r])
          lines[r] = line;
      }
    }
    if (!eol) break;
    p = eol + 1;
  }
}

/* GETP codes cable provides (autoeq_shim.c) and why it refuses the others. */
static const char *const getp_codes[] = {"NRM", "INT", "MAX", "MIN", "BV0", "BV1", "STP", "FLD", "BIF", "MXT",
                                          "MNT", "NDI", "NDX", "NTS", "NCO", "NBC", "NIN", "DTM", "WIN"};
static const struct {
  const char *code, *why;
} getp_refused[] = {
  {"HBF", "Hopf test functions belong to AUTO's ODE and periodic problems, not to boundary-value problems"},
  {"SPB", "period-doubling and torus test functions belong to AUTO's periodic problems"},
  {"EIG", "eigenvalues and Floquet multipliers belong to AUTO's ODE and periodic problems"},
  {"STA", "stability counts belong to AUTO's ODE and periodic problems"},
};

/* Every literal GETP('XXX', ...) in the source (comment lines skipped) must
 * name a code cable provides; file and line of the first that does not. */
static int check_getp_codes(const cable_autoeq *m, const char *src, cable_error *err)
{
  int line = 1;
  for (const char *p = src; *p; line++) {
    const char *eol = strchr(p, '\n');
    size_t n = eol ? (size_t)(eol - p) : strlen(p);
    const char *q = p;
    while (q < p + n && (*q == ' ' || *q == '\t')) q++;
    int comment = *q == '!' || (q < p + n - 1 && q[0] == '/' && (q[1] == '/' || q[1] == '*')) || *q == '*' ||
                  (m->lang == AUTOEQ_FORTRAN && q == p && (*p == 'c' || *p == 'C') && m->src[strlen(m->src) - 1] == 'f');
    for (const char *g = p; !comment && g + 4 < p + n; g++) {
      if (strncasecmp(g, "getp", 4) != 0 || (g > p && (isalnum((unsigned char)g[-1]) || g[-1] == '_'))) continue;
      const char *a = g + 4;
      while (a < p + n && (*a == ' ' || *a == '\t')) a++;
      if (a >= p + n || *a != '(') continue;
      a++;
      while (a < p + n && (*a == ' ' || *a == '\t')) a++;
      if (a >= p + n || (*a != '\'' && *a != '"')) continue;
      char code[4] = "";
      int k = 0;
      for (const char *c = a + 1; c < p + n && *c != *a && k < 3; c++) code[k++] = (char)toupper((unsigned char)*c);
      code[k] = '\0';
      int ok = 0;
      for (size_t i = 0; i < sizeof getp_codes / sizeof getp_codes[0]; i++) ok |= strcmp(code, getp_codes[i]) == 0;
      if (ok) continue;
      const char *why = "not a GETP code of AUTO's";
      for (size_t i = 0; i < sizeof getp_refused / sizeof getp_refused[0]; i++)
        if (strcmp(code, getp_refused[i].code) == 0) why = getp_refused[i].why;
      return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, line, "GETP",
                             "'%s': cable does not provide it (%s); it provides NRM, INT, MAX, MIN, MXT, MNT, BV0, BV1, STP, FLD, BIF, NDIM, NDX, NTST, NCOL, NBC, NINT, DTM and WINT",
                             code, why);
    }
    if (!eol) break;
    p = eol + 1;
  }
  return 0;
}

/* The type letter of one C parameter of gfortran's prototypes (autoeq_impl.h). */
static char proto_type(const char *a)
{
  if (strncmp(a, "const ", 6) == 0) a += 6;
  const struct {
    const char *c;
    char t;
  } types[] = {{"int *", 'i'}, {"double *", 'd'}, {"__GFORTRAN_DOUBLE_COMPLEX *", 'z'}, {"float *", 'r'},
               {"__GFORTRAN_FLOAT_COMPLEX *", 'c'}};
  for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
    if (strncmp(a, types[i].c, strlen(types[i].c)) == 0) return types[i].t;
  return '?';
}

/* Reads gfortran's prototypes of the file's external procedures: the number,
 * types and names of each routine's arguments (m->nargs: -1 absent, 0 a
 * dummy).  Whether they fit AUTO's is decided per run, for the routines the
 * run calls (autoeq_check.c); here only a FUNC is required. */
static int read_fortran_prototypes(cable_autoeq *m, const char *proto, cable_error *err)
{
  for (int r = 0; r < AE_NROUTINES; r++) {
    m->nargs[r] = -1;
    m->argtype[r][0] = '\0';
  }
  FILE *f = fopen(proto, "r");
  if (!f) return cable_error_set(err, CABLE_ERR_IO, proto, 0, "", "cannot read the compiler's prototypes");
  char line[2048];
  while (fgets(line, sizeof line, f)) {
    if (strncmp(line, "void ", 5) != 0) continue;
    char *open = strstr(line, "_ ("), *close = strrchr(line, ')');
    if (!open || !close) continue;
    *open = '\0';
    int r;
    for (r = 0; r < AE_NROUTINES; r++)
      if (strcasecmp(line + 5, autoeq_routine_name[r]) == 0) break;
    if (r == AE_NROUTINES) continue;
    *close = '\0';
    char *args = open + 3;
    int n = 0;
    if (strcmp(args, "") != 0 && strcmp(args, "void") != 0) {
      char *save = NULL;
      for (char *a = strtok_r(args, ",", &save); a; a = strtok_r(NULL, ",", &save), n++) {
        while (*a == ' ') a++;
        if (n >= AUTOEQ_MAX_ARGS) continue;
        const char *argname = strrchr(a, '*') ? strrchr(a, '*') + 1 : a;
        m->argtype[r][n] = proto_type(a);
        m->argtype[r][n + 1] = '\0';
        snprintf(m->argname[r][n], sizeof m->argname[r][n], "%s", argname);
      }
    }
    m->nargs[r] = n;
  }
  fclose(f);
  if (m->nargs[AE_FUNC] <= 0)
    return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, m->def_line[AE_FUNC], "FUNC",
                           m->nargs[AE_FUNC] < 0 ? "the equation file does not define SUBROUTINE %s"
                                                 : "has no arguments: AUTO calls %s",
                           autoeq_auto_sig[AE_FUNC]);
  return 0;
}

/* gfortran's -Wunused-dummy-argument warnings ("FILE:LINE:COL:" ... "Unused
 * dummy argument 'name'"), each at the procedure statement that names the
 * argument: marks the arguments of the six routines that are never used. */
static void read_unused_arguments(cable_autoeq *m, const char *log, const int *procs, int nprocs)
{
  for (int r = 0; r < AE_NROUTINES; r++) m->unused[r] = 0;
  FILE *f = fopen(log, "r");
  if (!f) return;
  char line[1024];
  size_t sl = strlen(m->src);
  int lno = 0;
  while (fgets(line, sizeof line, f)) {
    if (strncmp(line, m->src, sl) == 0 && line[sl] == ':' && isdigit((unsigned char)line[sl + 1])) {
      lno = atoi(line + sl + 1);
      continue;
    }
    const char *w = strstr(line, "Unused dummy argument ");
    if (!w || !lno) continue;
    w += strlen("Unused dummy argument ");
    while (*w && !isalnum((unsigned char)*w) && *w != '_') w++;   /* the opening quote, ASCII or UTF-8 */
    char name[AUTOEQ_ARGNAME];
    size_t k = 0;
    while ((isalnum((unsigned char)*w) || *w == '_') && k + 1 < sizeof name) name[k++] = (char)tolower((unsigned char)*w++);
    name[k] = '\0';
    int start = 0;   /* the procedure statement at or before the warning */
    for (int i = 0; i < nprocs && procs[i] <= lno; i++) start = procs[i];
    for (int r = 0; r < AE_NROUTINES; r++) {
      if (!start || m->def_line[r] != start) continue;
      for (int a = 0; a < m->nargs[r] && a < AUTOEQ_MAX_ARGS; a++)
        if (strcasecmp(m->argname[r][a], name) == 0) m->unused[r] |= 1UL << a;
    }
  }
  fclose(f);
}

/* The first compiler error about the user's file, as file:line: message. */
static int report_compile_error(cable_autoeq *m, const char *log, const char *kept_log, cable_error *err)
{
  FILE *f = fopen(log, "r");
  char line[1024], msg[400] = "";
  int lno = 0;
  size_t sl = strlen(m->src);
  while (f && fgets(line, sizeof line, f)) {
    line[strcspn(line, "\n")] = '\0';
    char *u = strstr(line, "undefined reference to `");
    if (u && !msg[0]) {
      char sym[64];
      snprintf(sym, sizeof sym, "%s", u + 24);
      sym[strcspn(sym, "'")] = '\0';
      int r;
      for (r = 0; r < AE_NROUTINES; r++)
        if (strcasecmp(sym, autoeq_routine_name[r]) == 0) break;
      if (r < AE_NROUTINES)
        snprintf(msg, sizeof msg, "%s: the equation file does not define it (AUTO's C interface needs func, stpnt, "
                 "bcnd, icnd, fopt and pvls)", sym);
      else
        snprintf(msg, sizeof msg, "calls '%s', which is defined nowhere", sym);
      lno = 0;
      break;
    }
    if (strncmp(line, m->src, sl) == 0 && line[sl] == ':' && isdigit((unsigned char)line[sl + 1])) {
      if (!lno) lno = atoi(line + sl + 1);
      const char *e = strstr(line, "error: ");
      if (e && !msg[0]) {
        lno = atoi(line + sl + 1);
        snprintf(msg, sizeof msg, "%s", e + 7);
        break;
      }
      continue;
    }
    if (lno && !msg[0] && (strncmp(line, "Error: ", 7) == 0 || strncmp(line, "Fatal Error: ", 13) == 0)) {
      snprintf(msg, sizeof msg, "%s", strchr(line, ':') + 2);
      break;
    }
  }
  if (f) fclose(f);
  if (!msg[0]) snprintf(msg, sizeof msg, "the compiler rejected the file");
  return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, lno, "", "%s (compiler output: %s)", msg, kept_log);
}

/* Removes the build directory and everything in it (the compat files, the
 * compiler's outputs, Fortran .mod files). */
static void remove_tree(const char *dir)
{
  DIR *d = opendir(dir);
  char p[AUTOEQ_PATH_MAX + 300];
  for (struct dirent *e; d && (e = readdir(d)) != NULL;) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    if (fmt_path(p, sizeof p, "%s/%s", dir, e->d_name) == 0) unlink(p);
  }
  if (d) closedir(d);
  rmdir(dir);
}

/* The cache's record of the checks' facts, one line per routine:
 * NAME nargs line types unused-mask names (types and names "-" when empty). */
static int read_sig(cable_autoeq *m, const char *path)
{
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  int got = 0;
  char line[4096];
  while (fgets(line, sizeof line, f)) {
    char name[16], types[AUTOEQ_MAX_ARGS + 1], names[800];
    int n, l;
    unsigned long mask;
    if (sscanf(line, "%15s %d %d %24s %lu %799s", name, &n, &l, types, &mask, names) != 6) continue;
    for (int r = 0; r < AE_NROUTINES; r++) {
      if (strcmp(name, autoeq_routine_name[r]) != 0) continue;
      m->nargs[r] = n;
      m->def_line[r] = l;
      m->unused[r] = mask;
      memcpy(m->argtype[r], strcmp(types, "-") == 0 ? "" : types, strcmp(types, "-") == 0 ? 1 : strlen(types) + 1);
      char *save = NULL;
      int a = 0;
      for (char *t = strtok_r(names, ",", &save); t && a < AUTOEQ_MAX_ARGS; t = strtok_r(NULL, ",", &save), a++)
        snprintf(m->argname[r][a], sizeof m->argname[r][a], "%s", strcmp(t, "-") == 0 ? "" : t);
      got++;
    }
  }
  fclose(f);
  return got == AE_NROUTINES ? 0 : -1;
}

static int write_sig(const cable_autoeq *m, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  for (int r = 0; r < AE_NROUTINES; r++) {
    fprintf(f, "%s %d %d %s %lu ", autoeq_routine_name[r], m->nargs[r], m->def_line[r],
            m->argtype[r][0] ? m->argtype[r] : "-", m->unused[r]);
    int na = m->nargs[r] < AUTOEQ_MAX_ARGS ? m->nargs[r] : AUTOEQ_MAX_ARGS;
    for (int a = 0; a < na; a++) fprintf(f, "%s%s", a ? "," : "", m->argname[r][a][0] ? m->argname[r][a] : "-");
    fprintf(f, "%s\n", na > 0 ? "" : "-");
  }
  return fclose(f);
}

int autoeq_build(cable_autoeq *m, cable_error *err)
{
  size_t n;
  char *src = read_all(m->src, &n, err);
  if (!src) return err->status;
  int procs[AUTOEQ_MAX_PROCS], nprocs = 0;
  for (int r = 0; r < AE_NROUTINES; r++) {
    m->def_line[r] = 0;
    m->unused[r] = 0;
    m->argtype[r][0] = '\0';
  }
  if (m->lang == AUTOEQ_FORTRAN) definition_lines(src, !has_f90_suffix(m->src), m->def_line, procs, &nprocs);
  if (check_getp_codes(m, src, err)) {
    free(src);
    return err->status;
  }
  uint64_t h = fnv1a(0xcbf29ce484222325ULL, AUTOEQ_CACHE_TAG, sizeof AUTOEQ_CACHE_TAG);
  const char *cc = compiler(m->lang);
  h = fnv1a(h, cc, strlen(cc) + 1);
  h = fnv1a(h, &m->lang, sizeof m->lang);
  for (int i = 0; i < cable_autoeq_compat_nfiles; i++)
    h = fnv1a(h, cable_autoeq_compat_files[i].text, strlen(cable_autoeq_compat_files[i].text) + 1);
  h = fnv1a(h, src, n);
  free(src);
  char dir[AUTOEQ_PATH_MAX], sig[AUTOEQ_PATH_MAX + 64], tmp[AUTOEQ_PATH_MAX + 64];
  int rc = cache_dir(dir, sizeof dir, err);
  if (rc) return rc;
  if (fmt_path(m->so, sizeof m->so, "%s/%s-%016llx.so", dir, m->name, (unsigned long long)h) ||
      fmt_path(sig, sizeof sig, "%s/%s-%016llx.sig", dir, m->name, (unsigned long long)h))
    return cable_error_set(err, CABLE_ERR_IO, dir, 0, "", "the cache directory's path is too long");
  struct stat st;
  if (stat(m->so, &st) == 0 && read_sig(m, sig) == 0) {
    m->built = 0;
    return 0;
  }
  fmt_path(tmp, sizeof tmp, "%s/build-XXXXXX", dir);
  if (!mkdtemp(tmp)) return cable_error_set(err, CABLE_ERR_IO, tmp, 0, "", "cannot create a build directory: %s", strerror(errno));
  char p[AUTOEQ_PATH_MAX + 128], log[AUTOEQ_PATH_MAX + 128], proto[AUTOEQ_PATH_MAX + 128], mod[AUTOEQ_PATH_MAX + 128],
      shim[AUTOEQ_PATH_MAX + 128], inc[AUTOEQ_PATH_MAX + 128], kept[AUTOEQ_PATH_MAX + 128];
  fmt_path(log, sizeof log, "%s/build.log", tmp);
  fmt_path(proto, sizeof proto, "%s/proto.h", tmp);
  fmt_path(mod, sizeof mod, "%s/module.so", tmp);
  fmt_path(shim, sizeof shim, "%s/cable_getp.c", tmp);
  fmt_path(inc, sizeof inc, "-I%s", tmp);
  fmt_path(kept, sizeof kept, "%s/%s.log", dir, m->name);
  for (int i = 0; i < cable_autoeq_compat_nfiles && !rc; i++) {
    fmt_path(p, sizeof p, "%s/%s", tmp, cable_autoeq_compat_files[i].name);
    if (write_file(p, cable_autoeq_compat_files[i].text))
      rc = cable_error_set(err, CABLE_ERR_IO, p, 0, "", "cannot write: %s", strerror(errno));
  }
  /* argv strings must be writable (execvp's prototype) */
  char *src_arg = m->src, ccb[256], a_proto[] = "-fc-prototypes-external", a_syntax[] = "-fsyntax-only", a_unused[] = "-Wunused-dummy-argument",
       a_legacy[] = "-std=legacy", a_o2[] = "-O2", a_pic[] = "-fPIC", a_shared[] = "-shared", a_o[] = "-o",
       a_defs[] = "-Wl,-z,defs", a_lm[] = "-lm", modj[AUTOEQ_PATH_MAX + 128];
  snprintf(ccb, sizeof ccb, "%s", cc);
  fmt_path(modj, sizeof modj, "-J%s", tmp);   /* Fortran .mod files go to the build directory */
  int st_tool = 0;
  if (!rc && m->lang == AUTOEQ_FORTRAN) {
    char *argv[] = {ccb, a_proto, a_syntax, a_unused, a_legacy, modj, src_arg, NULL};
    st_tool = run_tool(argv, proto, log);
    if (st_tool == 0) rc = read_fortran_prototypes(m, proto, err);
    if (st_tool == 0 && !rc) read_unused_arguments(m, log, procs, nprocs);
  }
  if (!rc && st_tool == 0) {
    if (m->lang == AUTOEQ_FORTRAN) {
      char *argv[] = {ccb, a_o2, a_pic, a_shared, a_legacy, modj, inc, src_arg, shim, a_o, mod, a_defs, NULL};
      st_tool = run_tool(argv, NULL, log);
    } else {
      char *argv[] = {ccb, a_o2, a_pic, a_shared, inc, src_arg, shim, a_o, mod, a_defs, a_lm, NULL};
      st_tool = run_tool(argv, NULL, log);
      for (int r = 0; r < AE_NROUTINES; r++) {   /* auto_f2c.h's prototypes made them AUTO's */
        m->nargs[r] = (int)strlen(autoeq_auto_args[r]);
        snprintf(m->argtype[r], sizeof m->argtype[r], "%s", autoeq_auto_args[r]);
      }
    }
  }
  if (!rc && st_tool == AUTOEQ_EXEC_FAILED) {
    rc = cable_error_set(err, CABLE_ERR_PLUGIN, m->src, 0, "", "cannot run the compiler '%s' (install it with "
                         "scripts/install-deps.sh, or name another with %s)", cc,
                         m->lang == AUTOEQ_FORTRAN ? "CABLE_FC" : "CABLE_CC");
  } else if (!rc && st_tool != 0) {
    rename(log, kept);
    rc = report_compile_error(m, kept, kept, err);
  }
  if (!rc && (write_sig(m, sig) != 0 || rename(mod, m->so) != 0))
    rc = cable_error_set(err, CABLE_ERR_IO, m->so, 0, "", "cannot store the built module: %s", strerror(errno));
  remove_tree(tmp);
  if (!rc) m->built = 1;
  return rc;
}
