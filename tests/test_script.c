/* Run-script interpreter: a mock host records every call it receives, so the
 * tests check the exact sequence of AUTO commands and arguments a script
 * produces, the label selection, iteration, '+', save/load, the Python
 * subset's semantics, handle lifetimes (every handle released exactly once)
 * and every error path (message, line, status).  The last part runs scripts
 * on the engine host (script_host_cable.h): Bratu's fold through a script,
 * through the template plug-in, files written and read back, and the host's
 * errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "script_host_cable.h"
#include "harness.h"
#include "test_files.h"
#include "script.h"
#include "script_host_cable.h"

/* ---- the mock host ----------------------------------------------------------- */

#define MOCK_MAX_OBJS 512
#define MOCK_MAX_SOL 32
#define MOCK_MAX_SAVED 16

/* A result: labelled solutions with their AUTO type and branch.  A solution:
 * a copy of one of them plus the result it came from. */
typedef struct mock_obj {
  int kind;   /* SCRIPT_HANDLE_RESULT / SCRIPT_HANDLE_SOLUTION */
  int live;
  int id;     /* result number R<id>, or the owner's number for a solution */
  int nsol;
  char type[MOCK_MAX_SOL][3];
  int branch[MOCK_MAX_SOL];
  int lab;    /* solution: its label */
  int ord;    /* solution: BP<ord> */
  char stype[3];
} mock_obj;

typedef struct mock {
  mock_obj *objs[MOCK_MAX_OBJS];
  int nobjs;
  int next_id, next_branch;
  int live, bad_releases;
  char log[16384];
  int nsaved;
  char saved_name[MOCK_MAX_SAVED][32];
  mock_obj saved[MOCK_MAX_SAVED];
  /* error injection */
  int fail_run_constants;   /* run() fails as if c.NAME had a bad line */
} mock;

static void mock_log(mock *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void mock_log(mock *m, const char *fmt, ...)
{
  size_t n = strlen(m->log);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(m->log + n, sizeof m->log - n, fmt, ap);
  va_end(ap);
  n = strlen(m->log);
  if (n + 1 < sizeof m->log) {
    m->log[n] = '\n';
    m->log[n + 1] = '\0';
  }
}

static mock_obj *mock_new(mock *m, int kind)
{
  if (m->nobjs == MOCK_MAX_OBJS) return NULL;
  mock_obj *o = calloc(1, sizeof *o);
  if (!o) return NULL;
  o->kind = kind;
  o->live = 1;
  m->objs[m->nobjs++] = o;
  m->live++;
  return o;
}

static void mock_free_all(mock *m)
{
  for (int i = 0; i < m->nobjs; i++) free(m->objs[i]);
  m->nobjs = 0;
}

static void mock_describe(void *ctx, const script_value *h, char *buf, size_t len)
{
  (void)ctx;
  const mock_obj *o = script_handle_ptr(h);
  if (o->kind == SCRIPT_HANDLE_RESULT) snprintf(buf, len, "R%d", o->id);
  else snprintf(buf, len, "R%d:%s%d", o->id, o->stype, o->ord);
}

/* A value as Python's repr() writes it (strings quoted). */
static const char *mock_repr(const script_value *v, char *buf, size_t len, const script_host *h)
{
  if (v->type == SCRIPT_STRING) {
    snprintf(buf, len, "'%s'", script_string_chars(v));
    return buf;
  }
  return script_value_format(v, h, buf, len);
}

static const script_host *mock_host_of(mock *m);

static void mock_args_text(mock *m, const script_value *start, const script_kwargs *kw,
                           char *buf, size_t len)
{
  char v[512];
  snprintf(buf, len, "%s", start ? mock_repr(start, v, sizeof v, mock_host_of(m)) : "None");
  for (int i = 0; i < kw->n; i++) {
    size_t n = strlen(buf);
    snprintf(buf + n, len - n, ", %s=%s", kw->items[i].name,
             mock_repr(&kw->items[i].value, v, sizeof v, mock_host_of(m)));
  }
}

static int mock_wrap(mock *m, mock_obj *o, script_value *out)
{
  return script_handle_new(out, mock_host_of(m), o->kind, o);
}

static int mock_run(void *ctx, const script_value *start, const script_kwargs *kw,
                    script_value *out, cable_error *err)
{
  static const char *const known[] = {"e", "c", "ICP", "NMX", "DS", "ISW", "UZR", "UZSTOP", "sv", NULL};
  mock *m = ctx;
  for (int i = 0; i < kw->n; i++) {
    int ok = 0;
    for (int k = 0; known[k]; k++) ok |= strcmp(kw->items[i].name, known[k]) == 0;
    if (!ok)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, kw->items[i].name, "unknown AUTO constant");
  }
  const script_value *nmx = script_kwargs_find(kw, "NMX");
  long n;
  if (nmx && script_value_to_long(nmx, &n))
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "NMX", "must be an integer, got a %s",
                           script_type_name(nmx));
  if (m->fail_run_constants)
    return cable_error_set(err, CABLE_ERR_PARSE, "c.knot72", 12, "NTST", "must be a positive integer, got '-5'");
  mock_obj *r = mock_new(m, SCRIPT_HANDLE_RESULT);
  if (!r) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "mock full");
  r->id = ++m->next_id;
  int br = ++m->next_branch;
  /* from STPNT: EP BP BP EP; from a solution: EP (UZ when UZR is given) EP */
  const char *from_stpnt[] = {"EP", "BP", "BP", "EP"};
  const char *with_uz[] = {"EP", "UZ", "EP"};
  const char *plain[] = {"EP", "EP"};
  const char *const *types = !start ? from_stpnt : script_kwargs_find(kw, "UZR") ? with_uz : plain;
  r->nsol = !start ? 4 : script_kwargs_find(kw, "UZR") ? 3 : 2;
  for (int i = 0; i < r->nsol; i++) {
    snprintf(r->type[i], sizeof r->type[i], "%s", types[i]);
    r->branch[i] = br;
  }
  char args[2048];
  mock_args_text(m, start, kw, args, sizeof args);
  mock_log(m, "run(%s) -> R%d", args, r->id);
  return mock_wrap(m, r, out);
}

/* The solution of result r at index i (labels are 1 + index). */
static int mock_solution(mock *m, const mock_obj *r, int i, script_value *out)
{
  mock_obj *s = mock_new(m, SCRIPT_HANDLE_SOLUTION);
  if (!s) return CABLE_ERR_ALLOC;
  s->id = r->id;
  s->lab = i + 1;
  snprintf(s->stype, sizeof s->stype, "%s", r->type[i]);
  for (int k = 0; k <= i; k++) s->ord += strcmp(r->type[k], r->type[i]) == 0;
  return mock_wrap(m, s, out);
}

static int mock_select(void *ctx, const script_value *result, const script_value *spec,
                       script_value *out, cable_error *err)
{
  mock *m = ctx;
  const mock_obj *r = script_handle_ptr(result);
  char what[64], got[1024];
  mock_repr(spec ? spec : &(script_value){SCRIPT_NONE, 0, 0, NULL}, what, sizeof what, mock_host_of(m));
  if (r->kind != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "a solution has no labels");
  long lab;
  int rc = 0;
  if (spec && script_value_to_long(spec, &lab) == 0) {
    if (lab < 1 || lab > r->nsol)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, what, "no such label in R%d", r->id);
    rc = mock_solution(m, r, (int)lab - 1, out);
  } else if (spec && script_string_len(spec) > 2) {
    const char *s = script_string_chars(spec);
    int want = atoi(s + 2), count = 0, found = -1;
    for (int i = 0; i < r->nsol && found < 0; i++)
      if (strncmp(r->type[i], s, 2) == 0 && ++count == want) found = i;
    if (found < 0) return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, s, "no such label in R%d", r->id);
    rc = mock_solution(m, r, found, out);
  } else {
    const char *s = spec ? script_string_chars(spec) : NULL;
    rc = script_list_new(out);
    for (int i = 0; i < r->nsol && !rc; i++) {
      if (s && strcmp(r->type[i], s) != 0) continue;
      script_value sol;
      rc = mock_solution(m, r, i, &sol);
      if (!rc) rc = script_list_append(out, sol);
    }
  }
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "mock failure");
  mock_log(m, "select(R%d, %s) -> %s", r->id, what, script_value_format(out, mock_host_of(m), got, sizeof got));
  return 0;
}

/* A new result holding a's then b's solutions (AUTO's r1 + r2). */
static int mock_add(void *ctx, const script_value *a, const script_value *b, script_value *out,
                    cable_error *err)
{
  mock *m = ctx;
  const mock_obj *ra = script_handle_ptr(a), *rb = script_handle_ptr(b);
  if (!ra || !rb || ra->kind != SCRIPT_HANDLE_RESULT || rb->kind != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "only results can be added");
  if (ra->nsol + rb->nsol > MOCK_MAX_SOL) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "too big");
  mock_obj *r = mock_new(m, SCRIPT_HANDLE_RESULT);
  if (!r) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "mock full");
  r->id = ++m->next_id;
  for (int k = 0; k < 2; k++) {
    const mock_obj *src = k ? rb : ra;
    for (int i = 0; i < src->nsol; i++) {
      memcpy(r->type[r->nsol], src->type[i], 3);
      r->branch[r->nsol++] = src->branch[i];
    }
  }
  mock_log(m, "add(R%d, R%d) -> R%d", ra->id, rb->id, r->id);
  return mock_wrap(m, r, out);
}

/* A result's branches, as results of their own. */
static int mock_items(void *ctx, const script_value *h, script_value *list, cable_error *err)
{
  mock *m = ctx;
  const mock_obj *r = script_handle_ptr(h);
  if (r->kind != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "a solution has no branches");
  int rc = script_list_new(list);
  for (int i = 0; i < r->nsol && !rc; i++) {
    if (i > 0 && r->branch[i] == r->branch[i - 1]) continue;
    mock_obj *b = mock_new(m, SCRIPT_HANDLE_RESULT);
    if (!b) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "mock full");
    b->id = ++m->next_id;
    for (int k = i; k < r->nsol && r->branch[k] == r->branch[i]; k++) {
      memcpy(b->type[b->nsol], r->type[k], 3);
      b->branch[b->nsol++] = r->branch[k];
    }
    script_value v;
    rc = mock_wrap(m, b, &v);
    if (!rc) rc = script_list_append(list, v);
  }
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "mock failure");
  char got[512];
  mock_log(m, "items(R%d) -> %s", r->id, script_value_format(list, mock_host_of(m), got, sizeof got));
  return 0;
}

/* sol['T']: the mock's parameter T is 1.5 * label; result[i]: branch i. */
static int mock_getitem(void *ctx, const script_value *h, const script_value *key, script_value *out,
                        cable_error *err)
{
  mock *m = ctx;
  const mock_obj *o = script_handle_ptr(h);
  char k[64], d[64];
  if (o->kind == SCRIPT_HANDLE_SOLUTION && key->type == SCRIPT_STRING) {
    if (strcmp(script_string_chars(key), "T") != 0)
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, script_string_chars(key), "no such parameter");
    *out = script_number(1.5 * o->lab);
  } else if (o->kind == SCRIPT_HANDLE_RESULT) {
    script_value list;
    int rc = mock_items(ctx, h, &list, err);
    if (rc) return rc;
    long i;
    if (script_value_to_long(key, &i) || i < 0 || (size_t)i >= script_list_len(&list)) {
      script_value_release(&list);
      return cable_error_set(err, CABLE_ERR_NOTFOUND, NULL, 0, NULL, "no such branch");
    }
    *out = script_value_retain(script_list_get(&list, (size_t)i));
    script_value_release(&list);
  } else {
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "bad index");
  }
  mock_describe(ctx, h, d, sizeof d);
  char got[64];
  mock_log(m, "getitem(%s, %s) -> %s", d, mock_repr(key, k, sizeof k, mock_host_of(m)),
           script_value_format(out, mock_host_of(m), got, sizeof got));
  return 0;
}

static int mock_save(void *ctx, const script_value *data, const char *name, cable_error *err)
{
  mock *m = ctx;
  const mock_obj *r = script_handle_ptr(data);
  if (r->kind != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "the mock saves results only");
  if (m->nsaved == MOCK_MAX_SAVED) return cable_error_set(err, CABLE_ERR_IO, NULL, 0, NULL, "disk full");
  snprintf(m->saved_name[m->nsaved], sizeof m->saved_name[0], "%s", name);
  m->saved[m->nsaved++] = *r;
  mock_log(m, "save(R%d, '%s')", r->id, name);
  return 0;
}

static int mock_load(void *ctx, int what, const script_value *data, const script_kwargs *kw,
                     script_value *out, cable_error *err)
{
  mock *m = ctx;
  (void)kw;
  if (what != SCRIPT_LOAD_RESULT || !data || data->type != SCRIPT_STRING)
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, NULL, "the mock loads results by name only");
  const char *name = script_string_chars(data);
  for (int i = m->nsaved - 1; i >= 0; i--) {
    if (strcmp(m->saved_name[i], name) != 0) continue;
    mock_obj *r = mock_new(m, SCRIPT_HANDLE_RESULT);
    if (!r) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "mock full");
    *r = m->saved[i];
    r->live = 1;
    r->id = ++m->next_id;
    mock_log(m, "loadbd('%s') -> R%d", name, r->id);
    return mock_wrap(m, r, out);
  }
  return cable_error_set(err, CABLE_ERR_IO, "b.missing", 0, NULL, "cannot open b.%s", name);
}

static int mock_merge(void *ctx, const script_value *data, script_value *out, cable_error *err)
{
  mock *m = ctx;
  const mock_obj *r = script_handle_ptr(data);
  if (!r || r->kind != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, NULL, "the mock merges results only");
  mock_obj *n = mock_new(m, SCRIPT_HANDLE_RESULT);
  if (!n) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "mock full");
  *n = *r;
  n->live = 1;
  n->id = ++m->next_id;
  mock_log(m, "merge(R%d) -> R%d", r->id, n->id);
  return mock_wrap(m, n, out);
}

static int mock_clean(void *ctx, cable_error *err)
{
  (void)err;
  mock_log(ctx, "clean()");
  return 0;
}

/* plot(x) and wait(): host functions outside the interpreter's built-ins. */
static int mock_call(void *ctx, const char *name, int nargs, const script_value *args,
                     const script_kwargs *kw, script_value *out, cable_error *err)
{
  (void)args;
  (void)kw;
  (void)out;
  if (strcmp(name, "wait") == 0) {
    mock_log(ctx, "wait(%d args)", nargs);
    return 0;
  }
  if (strcmp(name, "plot") == 0) return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, NULL, "no display");
  return CABLE_ERR_NOTFOUND;
}

static void mock_print(void *ctx, const char *line)
{
  mock_log(ctx, "print: %s", line);
}

static void mock_release(void *ctx, void *ptr, int kind)
{
  mock *m = ctx;
  mock_obj *o = ptr;
  if (!o->live || o->kind != kind) m->bad_releases++;
  o->live = 0;
  m->live--;
}

/* One host per mock: the host struct must outlive the handles. */
typedef struct mock_pair {
  mock m;
  script_host h;
} mock_pair;

static const script_host *mock_host_of(mock *m)
{
  return &((mock_pair *)(void *)m)->h;
}

static mock_pair *mock_alloc(void)
{
  mock_pair *p = calloc(1, sizeof *p);
  if (!p) exit(2);
  p->h.ctx = &p->m;
  p->h.run = mock_run;
  p->h.select = mock_select;
  p->h.add = mock_add;
  p->h.items = mock_items;
  p->h.getitem = mock_getitem;
  p->h.load = mock_load;
  p->h.save = mock_save;
  p->h.merge = mock_merge;
  p->h.relabel = mock_merge;
  p->h.clean = mock_clean;
  p->h.call = mock_call;
  p->h.describe = mock_describe;
  p->h.print = mock_print;
  p->h.release = mock_release;
  return p;
}

static void mock_pair_free(mock_pair *p)
{
  mock_free_all(&p->m);
  free(p);
}

/* ---- helpers ------------------------------------------------------------------ */

static int check_text(const char *what, const char *got, const char *want)
{
  int ok = strcmp(got, want) == 0;
  if (!ok) {
    printf("---- %s: got\n%s\n---- want\n%s\n----\n", what, got, want);
  }
  return test_true(what, ok);
}

static void check_handles(const char *what, const mock *m)
{
  char d[160];
  snprintf(d, sizeof d, "%s: live handles after the script", what);
  test_int(d, m->live, 0);
  snprintf(d, sizeof d, "%s: double or mismatched releases", what);
  test_int(d, m->bad_releases, 0);
}

/* Runs text on a fresh mock; checks status 0, the log and the handles. */
static void expect_log(const char *name, const char *text, const char *want_log)
{
  mock_pair *p = mock_alloc();
  cable_error err;
  int rc = script_run_string(name, text, &p->h, &err);
  char buf[1200], d[160];
  snprintf(d, sizeof d, "%s: status", name);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int(d, rc, 0);
  snprintf(d, sizeof d, "%s: host call sequence", name);
  check_text(d, p->m.log, want_log);
  check_handles(name, &p->m);
  mock_pair_free(p);
}

/* Runs a broken script; checks the status, the line and the whole message. */
static void expect_error_in(const char *name, const char *text, const char *path, int want_status,
                            int want_line, const char *want_msg, const char *want_log)
{
  mock_pair *p = mock_alloc();
  cable_error err;
  int rc = path ? script_run_file(path, &p->h, &err) : script_run_string(name, text, &p->h, &err);
  char buf[1200], d[200];
  snprintf(d, sizeof d, "%s: status %s", name, cable_status_name(want_status));
  test_int(d, rc, want_status);
  snprintf(d, sizeof d, "%s: error line", name);
  test_int(d, err.line, want_line);
  snprintf(d, sizeof d, "%s: message", name);
  check_text(d, cable_error_format(&err, buf, sizeof buf), want_msg);
  if (want_log) {
    snprintf(d, sizeof d, "%s: nothing runs after the error", name);
    check_text(d, p->m.log, want_log);
  }
  check_handles(name, &p->m);
  mock_pair_free(p);
}

static void expect_error(const char *name, const char *text, int want_status, int want_line,
                         const char *want_msg)
{
  expect_error_in(name, text, NULL, want_status, want_line, want_msg, NULL);
}

/* ---- the realistic script ------------------------------------------------------- */

static void test_knot_script(void)
{
  /* Derived by hand from tests/data/scripts/knot72.auto and the mock's rules:
   * a run from STPNT gives EP BP BP EP, a run from a solution EP EP (EP UZ EP
   * with UZR); '+' concatenates, so flat = R3 holds EP BP BP EP EP EP. */
  const char *want =
    "run(None, e='braid_knot', c='knot72', ICP=['T', 'L', 'L2', 'eps21'], NMX=200, DS=0.01) -> R1\n"
    "select(R1, 'EP1') -> R1:EP1\n"
    "run(R1:EP1, DS='-') -> R2\n"
    "add(R1, R2) -> R3\n"
    "save(R3, 'flat')\n"
    "select(R3, 'BP') -> [R3:BP1, R3:BP2]\n"
    "run(R3:BP1, ISW=-1, NMX=400) -> R4\n"
    "save(R4, 'mode1')\n"
    "run(R3:BP2, ISW=-1, NMX=400) -> R5\n"
    "save(R5, 'mode2')\n"
    "select(R3, 'BP1') -> R3:BP1\n"
    "run(R3:BP1, ISW=-1, DS='-', UZR={'T': [-2.10752]}, UZSTOP={'T': -3.0}) -> R6\n"
    "add(R3, R6) -> R7\n"
    "merge(R7) -> R8\n"
    "select(R3, 'BP') -> [R3:BP1, R3:BP2]\n"
    "select(R3, 'BP1') -> R3:BP1\n"
    "getitem(R3:BP1, 'T') -> 3.0\n"
    "print: branch points: 2 first at T = 3.0\n"
    "clean()\n";
  mock_pair *p = mock_alloc();
  cable_error err;
  int rc = script_run_file("tests/data/scripts/knot72.auto", &p->h, &err);
  char buf[1200];
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("knot72.auto: status", rc, 0);
  check_text("knot72.auto: host call sequence", p->m.log, want);
  check_handles("knot72.auto", &p->m);
  mock_pair_free(p);
}

static void test_selection_and_iteration(void)
{
  expect_log("labels",
             "r = run(e='x')\n"
             "print(r(3))\n"          /* by label number */
             "print(len(r()))\n"      /* every labelled solution */
             "print(len(r('UZ')))\n"  /* a type with no points: an empty list */
             "print(r('EP2'))\n",
             "run(None, e='x') -> R1\n"
             "select(R1, 3) -> R1:BP2\n"
             "print: R1:BP2\n"
             "select(R1, None) -> [R1:EP1, R1:BP1, R1:BP2, R1:EP2]\n"
             "print: 4\n"
             "select(R1, 'UZ') -> []\n"
             "print: 0\n"
             "select(R1, 'EP2') -> R1:EP2\n"
             "print: R1:EP2\n");
  expect_log("branches",
             "a = run(e='x')\n"
             "b = a + run(a('BP1'))\n"
             "for br in b:\n"
             "    print(len(br('EP')), br)\n"
             "print(len(b), b[1])\n",
             "run(None, e='x') -> R1\n"
             "select(R1, 'BP1') -> R1:BP1\n"
             "run(R1:BP1) -> R2\n"
             "add(R1, R2) -> R3\n"
             "items(R3) -> [R4, R5]\n"
             "select(R4, 'EP') -> [R4:EP1, R4:EP2]\n"
             "print: 2 R4\n"
             "select(R5, 'EP') -> [R5:EP1, R5:EP2]\n"
             "print: 2 R5\n"
             "items(R3) -> [R6, R7]\n"
             "items(R3) -> [R8, R9]\n"
             "getitem(R3, 1) -> R9\n"
             "print: 2 R9\n");
  expect_log("save and load",
             "save(run(e='x'), 'flat')\n"
             "f = loadbd('flat')\n"
             "g = bd('flat')\n"
             "print(len(f('BP')), f == g, f == f)\n",
             "run(None, e='x') -> R1\n"
             "save(R1, 'flat')\n"
             "loadbd('flat') -> R2\n"
             "loadbd('flat') -> R3\n"
             "select(R2, 'BP') -> [R2:BP1, R2:BP2]\n"
             "print: 2 False True\n");
  expect_log("aliases and host functions",
             "x = r(e='x')\n"
             "sv(x, 'a')\n"
             "y = mb(x)\n"
             "y = rl(y)\n"
             "wait()\n"
             "cl()\n"
             "r = 5\n"            /* a variable shadows the alias */
             "print(r + 1)\n",
             "run(None, e='x') -> R1\n"
             "save(R1, 'a')\n"
             "merge(R1) -> R2\n"
             "merge(R2) -> R3\n"
             "wait(0 args)\n"
             "clean()\n"
             "print: 6\n");
}

static void test_python_subset(void)
{
  expect_log("values print like Python",
             "print(1, 2.0, 0.1, 1e20, -3, 2.5e-7, 123456789.0, 0.1 + 0.2, 1e16)\n"
             "print(True, False, None, [1, 'a', [2.5]], {'T': 1, 2: 'x'}, (1, 2))\n"
             "print('it''s', \"q'uote\", ['q\\'uote'])\n",
             "print: 1 2.0 0.1 1e+20 -3 2.5e-07 123456789.0 0.30000000000000004 1e+16\n"
             "print: True False None [1, 'a', [2.5]] {'T': 1, 2: 'x'} [1, 2]\n"
             "print: its q'uote [\"q'uote\"]\n");
  expect_log("arithmetic and strings",
             "x = 1 + 2 - 0.5\n"
             "s = 'mode' + '%d' % 3 + '_' + str(x)\n"
             "print(x, s, -x, len(s), s[0], s[-1])\n"
             "print('%s_%03d|%5.2f|%-4s|%g|%e|%i%%' % ('br', 7, 3.14159, 'ab', 0.5, 1234.5, -2.9))\n"
             "xs = [1, 2] + [3]\n"
             "xs += [4]\n"
             "print(xs, xs[0], xs[-1], len(xs), int('12') + 1, float('2.5'), int(-2.7))\n",
             "print: 2.5 mode3_2.5 -2.5 9 m 5\n"
             "print: br_007| 3.14|ab  |0.5|1.234500e+03|-2%\n"
             "print: [1, 2, 3, 4] 1 4 4 13 2.5 -2\n");
  expect_log("control flow",
             "total = 0\n"
             "for i in range(10):\n"
             "    if i == 2:\n"
             "        continue\n"
             "    elif i >= 5 and not i == 7:\n"
             "        pass\n"
             "    else:\n"
             "        total = total + i\n"
             "    if i == 8: break\n"
             "print(total)\n"
             "for i, v in enumerate(['a', 'b'], 1):\n"
             "    for j in range(i, 3):\n"
             "        print(i, v, j)\n"
             "d = {'T': [-2.1], 'L': 3}\n"
             "for k in d:\n"
             "    print(k, d[k])\n"
             "print(range(2, 8, 3), range(3, 0, -1), len(range(0)), 'a' < 'b', [1] == [1], 0 or 'x', 1 and 0)\n",
             "print: 15\n"
             "print: 1 a 1\n"
             "print: 1 a 2\n"
             "print: 2 b 2\n"
             "print: T [-2.1]\n"
             "print: L 3\n"
             "print: [2, 5] [3, 2, 1] 0 True True x 0\n");
  expect_log("layout: comments, blank lines, continuations, tabs, CRLF",
             "# comment\r\n"
             "\r\n"
             "x = [1,\r\n"
             "     2]   # inside brackets\r\n"
             "y = 1 + \\\n"
             "    2\n"
             "if x:\n"
             "\tprint(x, y)\n"
             "\"\"\"a docstring\n"
             "over two lines\"\"\"\n"
             "print(r'a\\n', 'b\\tc')\n",
             "print: [1, 2] 3\n"
             "print: a\\n b\tc\n");
  /* AUTO's shorthand: its command line turns `name args` into `name(args)`,
     so AUTO's own scripts print with Python 2's statement form */
  expect_log("AUTO's shorthand: name args is name(args)",
             "pgm = 'int'\n"
             "print \"\\nDemo %s is started\"%pgm\n"
             "print \"Branch \" , 2 , \"***\"\n"
             "for i in range(2):\n"
             "    print i, pgm\n"
             "print 'no newline',\n"
             "print(pgm)\n"
             "xs = [5, 6]\n"
             "print xs [1]\n",
             "print: \nDemo int is started\n"
             "print: Branch  2 ***\n"
             "print: 0 int\n"
             "print: 1 int\n"
             "print: no newline\n"
             "print: int\n"
             "print: 6\n");
}

/* ---- broken scripts ---------------------------------------------------------------- */

static void test_errors(void)
{
  /* 1 syntax error */
  expect_error("syntax", "x = 1\ny = = 2\n", CABLE_ERR_PARSE, 2,
               "syntax:2: =: syntax error: expected an expression");
  expect_error("missing comma", "run(e='x' c='y')\n", CABLE_ERR_PARSE, 1,
               "missing comma:1: c: syntax error: expected ',' or ')'");
  expect_error("unclosed bracket", "x = run(e='x',\n  DS=0.1\nsave(x, 'a')\n", CABLE_ERR_PARSE, 1,
               "unclosed bracket:1: (: '(' is never closed");
  /* 2 bad indentation (three kinds) */
  expect_error_in("bad_indent.auto", NULL, "tests/data/scripts/bad_indent.auto", CABLE_ERR_PARSE, 4,
                  "tests/data/scripts/bad_indent.auto:4: indent: unindent does not match any outer "
                  "indentation level",
                  "");
  expect_error("unexpected indent", "x = 1\n    y = 2\n", CABLE_ERR_PARSE, 2,
               "unexpected indent:2: indent: unexpected indent");
  expect_error("missing block", "for i in range(2):\nprint(i)\n", CABLE_ERR_PARSE, 2,
               "missing block:2: print: expected an indented block after 'for' on line 1");
  /* 3 unknown function */
  expect_error("unknown function", "x = 1\nfoo(x)\n", CABLE_ERR_NOTFOUND, 2,
               "unknown function:2: foo: unknown function");
  /* 4 unknown keyword: the host rejects it, the script stops before save */
  expect_error_in("unknown_keyword.auto", NULL, "tests/data/scripts/unknown_keyword.auto",
                  CABLE_ERR_INPUT, 2,
                  "tests/data/scripts/unknown_keyword.auto:2: run: NMXX: unknown AUTO constant", "");
  /* 5 wrong types */
  expect_error("wrong type", "r = run(e='x')\n\nsave(r, 3)\n", CABLE_ERR_INPUT, 3,
               "wrong type:3: save: the second argument must be a non-empty name, got a number");
  expect_error("wrong type for +", "x = 'mode' + 1\n", CABLE_ERR_INPUT, 1,
               "wrong type for +:1: +: cannot add a string and a number");
  expect_error("wrong type for the host", "r = run(e='x', NMX='many')\n", CABLE_ERR_INPUT, 1,
               "wrong type for the host:1: run: NMX: must be an integer, got a string");
  expect_error("wrong start", "r = run(3)\n", CABLE_ERR_INPUT, 1,
               "wrong start:1: run: the start must be a result, a solution or a name, got a number");
  /* 6 unterminated string */
  expect_error_in("unterminated.auto", NULL, "tests/data/scripts/unterminated.auto", CABLE_ERR_PARSE, 3,
                  "tests/data/scripts/unterminated.auto:3: 'flat): unterminated string", "");
  /* 7 unknown variable */
  expect_error("unknown variable", "r = run(e='x')\nsave(flat, 'a')\n", CABLE_ERR_NOTFOUND, 2,
               "unknown variable:2: flat: unknown variable (not assigned before this line)");
  /* 8 calling a number */
  expect_error("calling a number", "x = 3\ny = x('BP1')\n", CABLE_ERR_INPUT, 2,
               "calling a number:2: x: a number cannot be called (it is not a function)");
  /* 9 a missing label: the host's error, with the script line */
  expect_error_in("missing label", "r = run(e='x')\nfor s in r('BP'):\n    print(s)\nhb = r('HB1')\n", NULL,
                  CABLE_ERR_NOTFOUND, 4, "missing label:4: r: HB1: no such label in R1",
                  "run(None, e='x') -> R1\n"
                  "select(R1, 'BP') -> [R1:BP1, R1:BP2]\n"
                  "print: R1:BP1\n"
                  "print: R1:BP2\n");
  /* 10 division-like operators */
  expect_error_in("division.auto", NULL, "tests/data/scripts/division.auto", CABLE_ERR_PARSE, 2,
                  "tests/data/scripts/division.auto:2: /: operator '/' is not supported in cable "
                  "scripts (supported: + - % == != < <= > >= and or not)",
                  "");
  expect_error("power", "x = 2 ** 3\n", CABLE_ERR_PARSE, 1,
               "power:1: **: operator '**' is not supported in cable scripts (supported: + - % == != < "
               "<= > >= and or not)");
  expect_error("modulo of numbers", "x = 7 % 2\n", CABLE_ERR_UNSUPPORTED, 1,
               "modulo of numbers:1: %: '%' is only supported for string formatting ('mode%d' % n), got a "
               "number on the left");
  /* 11 too deep nesting: brackets, unary operators, blocks, long chains, values */
  {
    char text[400], want[160];
    int n = SCRIPT_MAX_NESTING + 1;
    snprintf(text, sizeof text, "x = %.*s1%.*s\n", n, "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((",
             n, "))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))");
    snprintf(want, sizeof want, "brackets:1: (: brackets nested too deeply (limit %d)", SCRIPT_MAX_NESTING);
    expect_error("brackets", text, CABLE_ERR_PARSE, 1, want);
    char minus[200];
    memset(minus, '-', 100);
    snprintf(minus + 100, sizeof minus - 100, "1\n");
    snprintf(text, sizeof text, "x = 0\ny = %s", minus);
    snprintf(want, sizeof want, "unary:2: -: expression nested too deeply (limit %d levels)", SCRIPT_MAX_NESTING);
    expect_error("unary", text, CABLE_ERR_PARSE, 2, want);
  }
  {
    static char text[8192];
    size_t n = 0;
    for (int d = 0; d <= SCRIPT_MAX_BLOCK_DEPTH; d++)
      n += (size_t)snprintf(text + n, sizeof text - n, "%*sfor i%d in range(1):\n", 4 * d, "", d);
    snprintf(text + n, sizeof text - n, "%*spass\n", 4 * (SCRIPT_MAX_BLOCK_DEPTH + 1), "");
    char want[160];
    /* 33 nested loops on lines 1..33: the body on line 34 is block level 33 */
    snprintf(want, sizeof want, "blocks:%d: indent: blocks nested too deeply (limit %d)",
             SCRIPT_MAX_BLOCK_DEPTH + 2, SCRIPT_MAX_BLOCK_DEPTH);
    expect_error("blocks", text, CABLE_ERR_PARSE, SCRIPT_MAX_BLOCK_DEPTH + 2, want);
    /* one level less is fine */
    n = 0;
    for (int d = 0; d < SCRIPT_MAX_BLOCK_DEPTH; d++)
      n += (size_t)snprintf(text + n, sizeof text - n, "%*sfor i%d in range(1):\n", 4 * d, "", d);
    snprintf(text + n, sizeof text - n, "%*sprint('deep')\n", 4 * SCRIPT_MAX_BLOCK_DEPTH, "");
    expect_log("blocks at the limit", text, "print: deep\n");
  }
  {
    static char text[4096];
    size_t n = (size_t)snprintf(text, sizeof text, "x = 1");
    for (int i = 0; i < SCRIPT_MAX_EXPR_HEIGHT; i++) n += (size_t)snprintf(text + n, sizeof text - n, " + 1");
    snprintf(text + n, sizeof text - n, "\n");
    char want[160];
    snprintf(want, sizeof want, "chain:1: +: expression too long or too deeply nested (limit %d levels)",
             SCRIPT_MAX_EXPR_HEIGHT);
    expect_error("chain", text, CABLE_ERR_PARSE, 1, want);
  }
  {
    char want[160];
    snprintf(want, sizeof want, "deep list:3: [: list too long (limit %d elements) or nested too deeply (limit %d levels)",
             SCRIPT_MAX_LIST, SCRIPT_MAX_NESTING);
    expect_error("deep list", "x = []\nfor i in range(100):\n    x = [x]\n", CABLE_ERR_INPUT, 3, want);
  }
  /* 12 a missing file */
  expect_error_in("missing file", NULL, "tests/data/scripts/no_such_script.auto", CABLE_ERR_IO, 0,
                  "tests/data/scripts/no_such_script.auto: cannot open the script: No such file or directory",
                  "");
  /* bounded loops */
  {
    char want[160];
    snprintf(want, sizeof want, "huge range:1: range: 1000000000 elements requested, the limit is %d",
             SCRIPT_MAX_RANGE);
    expect_error("huge range", "for i in range(1000000000):\n    pass\n", CABLE_ERR_INPUT, 1, want);
    snprintf(want, sizeof want, "steps:3: the script ran more than %ld steps (limit)", SCRIPT_MAX_STEPS);
    expect_error("steps", "for i in range(100000):\n    for j in range(100000):\n        pass\n",
                 CABLE_ERR_INPUT, 3, want);
    snprintf(want, sizeof want, "long string:3: +: string too long (limit %d bytes)", SCRIPT_MAX_STRING);
    expect_error("long string", "s = 'ab'\nfor i in range(40):\n    s = s + s\n", CABLE_ERR_INPUT, 3, want);
  }
  /* Python features outside the subset say so */
  expect_error("while", "while True:\n    pass\n", CABLE_ERR_PARSE, 1,
               "while:1: while: while loops are not supported in cable scripts (use for NAME in range(N))");
  expect_error("import", "from auto import *\n", CABLE_ERR_PARSE, 1,
               "import:1: from: import is not supported in cable scripts (the AUTO commands are built in)");
  expect_error("attribute", "r = run(e='x')\nn = r.c\n", CABLE_ERR_PARSE, 2,
               "attribute:2: .: attribute access ('.c') is not supported in cable scripts");
  expect_error("def", "def f(x):\n    return x\n", CABLE_ERR_PARSE, 1,
               "def:1: def: function definitions are not supported in cable scripts");
  expect_error("f-string", "x = f'{1}'\n", CABLE_ERR_PARSE, 1,
               "f-string:1: f: f-strings and byte strings are not supported (use 'text %d' % value)");
  expect_error("break outside", "break\n", CABLE_ERR_PARSE, 1, "break outside:1: break: 'break' outside a for loop");
  expect_error("tuple assignment", "a, b = 1, 2\n", CABLE_ERR_PARSE, 1,
               "tuple assignment:1: ,: tuple assignment and bare tuples are not supported in cable scripts");
  expect_error("assign to call", "run(e='x') = 3\n", CABLE_ERR_PARSE, 1,
               "assign to call:1: =: can only assign to a name (NAME = value)");
  expect_error("invalid character", "x = 1 $ 2\n", CABLE_ERR_PARSE, 1,
               "invalid character:1: $: invalid character in script");
  expect_error("mismatched bracket", "x = [1, 2)\n", CABLE_ERR_PARSE, 1,
               "mismatched bracket:1: ): ')' does not match '[' opened on line 1");
  /* run-time errors */
  expect_error("index", "x = [1, 2]\nprint(x[5])\n", CABLE_ERR_INPUT, 2,
               "index:2: [: index 5 out of range (the list has 2 elements)");
  expect_error("format count", "print('%s_%d' % ('a',))\n", CABLE_ERR_INPUT, 1,
               "format count:1: %: not enough values for the format in format '%s_%d'");
  expect_error("format type", "print('%d' % 'a')\n", CABLE_ERR_INPUT, 1,
               "format type:1: %: %d needs a number, got a string in format '%d'");
  expect_error("function as value", "x = run\n", CABLE_ERR_INPUT, 1,
               "function as value:1: run: is a function: call it as run(...)");
  expect_error("too many arguments", "save(1, 2, 3)\n", CABLE_ERR_INPUT, 1,
               "too many arguments:1: save: takes 2 positional arguments, got 3");
  expect_error("keyword for len", "print(len([1], x=2))\n", CABLE_ERR_INPUT, 1,
               "keyword for len:1: len: unexpected keyword argument x");
  expect_error("repeated keyword", "r = run(DS=1, DS=2)\n", CABLE_ERR_INPUT, 1,
               "repeated keyword:1: run: keyword argument DS given twice");
  expect_error("label type", "r = run(e='x')\ns = r([1])\n", CABLE_ERR_INPUT, 2,
               "label type:2: r: a label must be a string ('BP1', 'UZ') or a number, got a list");
  expect_error("host function error", "plot(1)\n", CABLE_ERR_UNSUPPORTED, 1, "host function error:1: plot: no display");
  expect_error("iterate a number", "for i in 3:\n    pass\n", CABLE_ERR_INPUT, 1,
               "iterate a number:1: for: cannot iterate over a number");
  expect_error("compare", "if [1] < 2:\n    pass\n", CABLE_ERR_INPUT, 1, "compare:1: <: cannot compare a list and a number");
  /* an error from another file (a constants file read by the host) keeps its place */
  {
    mock_pair *p = mock_alloc();
    p->m.fail_run_constants = 1;
    cable_error err;
    char buf[1200];
    int rc = script_run_string("scene.auto", "\nr = run(e='braid_knot', c='knot72')\n", &p->h, &err);
    test_int("constants error: status", rc, CABLE_ERR_PARSE);
    check_text("constants error: message", cable_error_format(&err, buf, sizeof buf),
               "scene.auto:2: run: c.knot72:12: NTST: must be a positive integer, got '-5'");
    check_handles("constants error", &p->m);
    mock_pair_free(p);
  }
  /* a host without a callback */
  {
    mock_pair *p = mock_alloc();
    p->h.save = NULL;
    cable_error err;
    char buf[1200];
    int rc = script_run_string("nosave", "r = run(e='x')\nsave(r, 'a')\n", &p->h, &err);
    test_int("missing callback: status", rc, CABLE_ERR_UNSUPPORTED);
    check_text("missing callback: message", cable_error_format(&err, buf, sizeof buf),
               "nosave:2: save: not supported by this host");
    check_handles("missing callback", &p->m);
    mock_pair_free(p);
  }
  /* a NULL error pointer is allowed */
  {
    mock_pair *p = mock_alloc();
    test_int("NULL err: status", script_run_string("n", "x = y\n", &p->h, NULL), CABLE_ERR_NOTFOUND);
    mock_pair_free(p);
  }
}

/* ---- the value API hosts use ---------------------------------------------------------- */

static void test_value_api(void)
{
  script_value s, l, d, n = script_number(2.5);
  test_int("string_new", script_string_new(&s, "abc", 3), 0);
  test_int("string length", (long)script_string_len(&s), 3);
  test_true("string chars", strcmp(script_string_chars(&s), "abc") == 0);
  test_int("list_new", script_list_new(&l), 0);
  test_int("list_append", script_list_append(&l, script_value_retain(&s)), 0);
  test_int("list_append number", script_list_append(&l, script_integer(-4)), 0);
  test_int("list length", (long)script_list_len(&l), 2);
  long k = 0;
  test_int("to_long of an integer", script_value_to_long(script_list_get(&l, 1), &k), 0);
  test_int("to_long value", k, -4);
  test_int("to_long refuses 2.5", script_value_to_long(&n, &k), CABLE_ERR_INPUT);
  test_int("to_long refuses a string", script_value_to_long(&s, &k), CABLE_ERR_INPUT);
  test_true("list_get out of range is NULL", script_list_get(&l, 2) == NULL);
  test_int("dict_new", script_dict_new(&d), 0);
  script_value key;
  script_string_new(&key, "T", 1);
  test_int("dict_set", script_dict_set(&d, script_value_retain(&key), script_value_retain(&l)), 0);
  test_int("dict_set replaces", script_dict_set(&d, script_value_retain(&key), script_number(1)), 0);
  test_int("dict length", (long)script_dict_len(&d), 1);
  const script_value *got = script_dict_find(&d, &key);
  test_true("dict_find", got && got->type == SCRIPT_NUMBER && got->num == 1);
  test_int("dict_set refuses a list key", script_dict_set(&d, script_value_retain(&l), script_none()),
           CABLE_ERR_INPUT);
  char buf[64];
  test_true("format list", strcmp(script_value_format(&l, NULL, buf, sizeof buf), "['abc', -4]") == 0);
  test_true("type names", strcmp(script_type_name(&d), "dict") == 0 && strcmp(script_type_name(&n), "number") == 0);
  script_value_release(&key);
  script_value_release(&d);
  script_value_release(&l);
  script_value_release(&s);
  test_true("release leaves None", s.type == SCRIPT_NONE && s.obj == NULL);
  script_value_release(&s);   /* releasing None is a no-op */
  /* a failing handle constructor still releases the host object: covered by
   * the mock's counters in every script above */
  script_kwarg items[1] = {{"DS", script_number(0.5)}};
  script_kwargs kw = {1, items};
  test_true("kwargs_find", script_kwargs_find(&kw, "DS") && script_kwargs_find(&kw, "NMX") == NULL);
}


/* ---- the engine host ------------------------------------------------------------------ */

/* One directory per test process: runs of the suite may overlap. */
static char replay_dir[64] = "tests/tmp/replay";
static const char *const replay_files[] = {"c.bratu", "b.bratu", "s.bratu", "d.bratu", "b.bratu.1.csv",
                                           "b.upper", "s.upper", "d.upper", "b.upper.1.csv",
                                           "b.sw", "s.sw", "d.sw", "b.sw.1.csv", "b.sw.2.csv", "b.sw.3.csv", "b.sw.4.csv",
                                           "b.full", "s.full", "d.full", "b.full.1.csv",
                                           "b.rest", "s.rest", "d.rest", "b.rest.1.csv",
                                           "b.sw", "s.sw", "d.sw", "b.sw.5.csv",
                                           "b.sw2", "s.sw2", "d.sw2", "b.sw2.1.csv", "b.sw2.2.csv", "b.sw2.3.csv",
                                           "b.sw2.4.csv", "b.sw2.5.csv"};

/* Bratu's fold: lambda* = th^2 / (2 cosh^2(th/4)) with (th/4) tanh(th/4) = 1,
 * and there max u = u(1/2) = 2 ln cosh(th/4) (30-digit mpmath values). */
#define BRATU_FOLD_LAMBDA 3.5138307191251612062
#define BRATU_FOLD_UMAX 1.1868421686343890972
/* c.bratu has the engine test's constants (NTST=20, NCOL=4, EPSS=1e-7), for
 * which tests/test_engine_bvp.c bounds the fold's lambda by 1e-9
 * (discretisation O(h^8) ~ 1e-11, location to EPSS in arclength). */
#define BRATU_FOLD_TOL 1e-9
/* u at the fold moves linearly along the branch (lambda only quadratically),
 * so it inherits the location error itself: EPSS * DSMAX = 1e-7 * 0.5. */
#define BRATU_UMAX_TOL 5e-8
/* Numbers re-read from b./s.-files: ES19.10, 11 significant digits. */
#define FILE_REL_TOL 1e-10

static char plugin_dir[2048] = "build/release/plugins";

/* The whole file as a string (caller frees), NULL when unreadable. */
static char *read_text(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 4096, n = 0, k;
  char *t = malloc(cap);
  while (t && (k = fread(t + n, 1, cap - n - 1, f)) > 0) {
    n += k;
    if (n + 1 == cap) {
      char *g = realloc(t, cap *= 2);
      if (!g) free(t);
      t = g;
    }
  }
  fclose(f);
  if (t) t[n] = '\0';
  return t;
}

static void replay_files_remove(void)
{
  char path[256];
  for (size_t i = 0; i < sizeof replay_files / sizeof replay_files[0]; i++) {
    snprintf(path, sizeof path, "%s/%s", replay_dir, replay_files[i]);
    remove(path);
  }
}

static void replay_prepare(void)
{
  snprintf(replay_dir, sizeof replay_dir, "tests/tmp/replay.%ld", (long)getpid());
  mkdir("tests/tmp", 0777);
  mkdir(replay_dir, 0777);
  replay_files_remove();
  char to[256];
  snprintf(to, sizeof to, "%s/c.bratu", replay_dir);
  test_true("copy c.bratu into the run directory", copy_file("tests/data/scripts/c.bratu", to));
}

static void replay_cleanup(void)
{
  replay_files_remove();
  rmdir(replay_dir);
}

/* Runs a script (a file, or text) on a fresh engine-host session; the log
 * (labelled points, print output) comes back in *log (free it). */
static int replay_with(const char *path, const char *text, const cable_replay_problems *problems, char **log,
                       cable_error *err)
{
  size_t len;
  FILE *f = open_memstream(log, &len);
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = replay_dir;
  if (problems) o.problems = problems;
  o.log = f;
  int rc;
  if (path) {
    rc = cable_replay_run_file(path, &o, err);
  } else {
    cable_replay *r = cable_replay_alloc(&o);
    rc = script_run_string("t.auto", text, cable_replay_host(r), err);
    cable_replay_free(r);
  }
  fclose(f);
  return rc;
}

static int replay(const char *path, const char *text, char **log, cable_error *err)
{
  return replay_with(path, text, NULL, log, err);
}

static const char *log_line(const char *log, const char *prefix)
{
  for (const char *p = log; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL)
    if (strncmp(p, prefix, strlen(prefix)) == 0) return p + strlen(prefix);
  return NULL;
}

static void test_engine_script(void)
{
  replay_prepare();
  char *log = NULL, buf[1200];
  cable_error err;
  int rc = replay("tests/data/scripts/bratu_replay.auto", NULL, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("bratu_replay.auto on the engine: status", rc, 0);
  double fold = 0, reloaded = 0, restart = 0;
  int lab = 0, ty_ok = 0, nbr = 0, nmerged = 0, nlp = 0, rlab = 0;
  const char *l = log_line(log, "fold ");
  ty_ok = l && sscanf(l, "%lf LP %d", &fold, &lab) == 2;
  test_true("the script prints the fold (type LP)", ty_ok);
  test_abs("fold lambda through a script vs closed form", fold, BRATU_FOLD_LAMBDA, BRATU_FOLD_TOL);
  test_int("the fold is label 2 (after the start EP1)", lab, 2);
  l = log_line(log, "branches ");
  test_true("both directions give 2 branches, merge joins them into 1",
            l && sscanf(l, "%d %d", &nbr, &nmerged) == 2 && nbr == 2 && nmerged == 1);
  l = log_line(log, "reloaded ");
  test_true("loadbd finds the one fold again", l && sscanf(l, "%d %lf", &nlp, &reloaded) == 2 && nlp == 1);
  test_rel("reloaded fold lambda (s-file rounding)", reloaded, fold, FILE_REL_TOL);
  l = log_line(log, "restart ");
  test_true("the restart from the reloaded fold ends (EP1)", l && sscanf(l, "%lf %d", &restart, &rlab) == 2);
  test_true("the restart runs onto the upper branch (lambda below the fold)", restart < fold);
  /* labels continue across runs and files: run 1 has 1-3, the backward run 4;
     the restart from the fold reports nothing in its first step (AUTO's rule:
     until 2026-11 it found the LP again there, label 5), so its end is 5 */
  test_int("the restart's end point is label 5", rlab, 5);
  free(log);

  char path[256];
  snprintf(path, sizeof path, "%s/s.upper", replay_dir);
  cable_sfile *sf = cable_sfile_read(path, &err);
  test_true("sv='upper' wrote s.upper", sf != NULL);
  if (sf) {
    test_int("s.upper: 1 labelled solution (the end; no LP again at the restart)", cable_sfile_count(sf), 1);
    test_true("s.upper: label 5", cable_sfile_count(sf) == 1 && cable_sfile_get(sf, 0)->lab == 5);
    cable_sfile_free(sf);
  }
  snprintf(path, sizeof path, "%s/b.bratu", replay_dir);
  cable_bfile *bf = cable_bfile_read(path, &err);
  test_true("save(b, 'bratu') wrote b.bratu: one branch of NMX = 60 rows",
            bf && bf->nbranch == 1 && bf->branch[0].nrow == 60);
  const double *lam = bf ? cable_bfile_column(&bf->branch[0], "lambda") : NULL;
  double lp_row = NAN;
  for (int i = 0; lam && i < bf->branch[0].nrow; i++)
    if (bf->branch[0].lab[i] == 2) lp_row = lam[i];
  test_rel("b.bratu: the fold's row (label 2)", lp_row, fold, FILE_REL_TOL);
  /* save() also writes the branch's CSV table, one line per b-file row */
  snprintf(path, sizeof path, "%s/b.bratu.1.csv", replay_dir);
  char *csv = read_text(path);
  int csv_lines = 0;
  for (const char *c = csv; c && *c; c++) csv_lines += *c == '\n';
  test_true("save(b, 'bratu') wrote b.bratu.1.csv with a header naming lambda",
            csv && strncmp(csv, "BR,PT,TY,LAB,lambda,L2NORM,", 27) == 0);
  test_int("b.bratu.1.csv: header + one line per b-file row", csv_lines, bf && bf->nbranch ? 1 + bf->branch[0].nrow : -1);
  free(csv);
  cable_bfile_free(bf);

  /* the template plug-in, run by the engine through a script (PVLS: umax) */
  char text[4096];
  snprintf(text, sizeof text,
           "r = run(e='%s/bratu_plugin.so', c='bratu')\n"
           "lp = r('LP1')\n"
           "print('plugin', lp['lambda'], lp['umax'])\n",
           plugin_dir);
  rc = replay(NULL, text, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("the template plug-in through a script: status", rc, 0);
  double pl = 0, um = 0;
  l = log_line(log, "plugin ");
  test_true("the plug-in's fold is printed", l && sscanf(l, "%lf %lf", &pl, &um) == 2);
  test_abs("plug-in fold lambda vs closed form", pl, BRATU_FOLD_LAMBDA, BRATU_FOLD_TOL);
  test_abs("plug-in PVLS umax at the fold vs closed form", um, BRATU_FOLD_UMAX, BRATU_UMAX_TOL);
  free(log);

  /* e='bratu_int' from the command-line/script name table: the integral
     condition int u dt = mu leaves Bratu's fold where it was */
  rc = replay(NULL,
              "r = run(e='bratu_int', c='bratu', NINT=1, ICP=['lambda', 'mu'])\n"
              "print('bratu_int', r('LP1')['lambda'])\n",
              &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("e='bratu_int' through a script: status", rc, 0);
  pl = 0;
  l = log_line(log, "bratu_int ");
  test_true("bratu_int: the fold is printed", l && sscanf(l, "%lf", &pl) == 1);
  test_abs("bratu_int: fold lambda vs closed form", pl, BRATU_FOLD_LAMBDA, BRATU_FOLD_TOL);
  free(log);

  /* user zeros by parameter name, and e= from the constants file */
  rc = replay(NULL,
              "r = run(c='bratu', UZR={'lambda': [1, 2]}, NMX=20)\n"
              "print('uz', len(r('UZ')), r('UZ2')['lambda'], r('UZ1')['PAR(1)'])\n",
              &log, &err);
  test_int("UZR by name, e from c.bratu: status", rc, 0);
  double u2 = 0, u1 = 0;
  int nuz = 0;
  l = log_line(log, "uz ");
  test_true("two user zeros", l && sscanf(l, "%d %lf %lf", &nuz, &u2, &u1) == 3 && nuz == 2);
  /* a user zero is located to Newton accuracy in lambda (EPSL = 1e-7 on the
   * step: the zero of lambda - value converges quadratically far below) */
  test_abs("UZ2 at lambda = 2", u2, 2, 1e-9);
  test_abs("UZ1 at lambda = 1", u1, 1, 1e-9);
  free(log);

  /* load('name') without IRS: the last solution of s.NAME, as AUTO's load */
  rc = replay(NULL,
              "x = load('bratu')\n"
              "y = load('bratu', IRS=2)\n"
              "print('ld', x['LAB'], x['TY'], y['LAB'], y['TY'])\n",
              &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("load('bratu') without IRS: status", rc, 0);
  sf = NULL;
  snprintf(path, sizeof path, "%s/s.bratu", replay_dir);
  sf = cable_sfile_read(path, &err);
  int n = sf ? cable_sfile_count(sf) : 0, xl = 0, yl = 0;
  char xty[8] = "", yty[8] = "";
  l = log_line(log, "ld ");
  test_true("load printed two solutions", l && sscanf(l, "%d %7s %d %7s", &xl, xty, &yl, yty) == 4);
  test_true("load('bratu') is s.bratu's last solution (label and type)",
            n > 0 && xl == cable_sfile_get(sf, n - 1)->lab && strcmp(xty, cable_type_name(cable_sfile_get(sf, n - 1)->itp)) == 0);
  test_true("load('bratu', IRS=2) is label 2, the fold", yl == 2 && strcmp(yty, "LP") == 0);
  cable_sfile_free(sf);
  free(log);
}

#define ELASTICA_PI 3.14159265358979323846

/* Sign changes of u_0 along a stored solution (values below tiny ignored). */
static int sign_changes(const cable_solution *x, double tiny)
{
  int n = 0, last = 0;
  for (int q = 0; q < cable_solution_npts(x); q++) {
    double v = x->u[q * x->ndim];
    int sg = v > tiny ? 1 : v < -tiny ? -1 : 0;
    if (sg && last && sg != last) n++;
    if (sg) last = sg;
  }
  return n;
}

/* A scene's loop: the straight elastica's branch points at (k pi)^2 below
 * lambda = 100, and a switch (ISW=-1) at every one of them; the branch from
 * the k-th BP is the buckled mode theta ~ cos(k pi s), whose theta changes
 * sign k times.  NTST=50, NCOL=5 meets an exact zero pivot at the switch
 * from BP3 (the engine must start it all the same: test_engine_bvp). */
static void test_bp_loop(void)
{
  char *log = NULL, buf[1200], path[256];
  cable_error err;
  int rc = replay(NULL,
                  "r = run(e='elastica', ICP=['lambda'], NTST=50, NCOL=5, JAC=1, IAD=0, DS=0.5, DSMIN=1e-6, DSMAX=4.0,"
                  " NMX=200, RL1=100, ISP=2, ILP=0, EPSS=1e-10, sv='sw')\n"
                  "k = 0\n"
                  "for bp in r('BP'):\n"
                  "    k = k + 1\n"
                  "    b = run(bp, ISW=-1, DS=0.05, DSMAX=0.2, NMX=12, NPR=4, ISP=0, ap='sw')\n"
                  "    print('switch', k, bp['lambda'], b('EP1')['lambda'], b('EP1')['LAB'])\n"
                  "print('bps', len(r('BP')))\n"
                  "d = run(r('BP1'), ISW=-1, DS=-0.05, DSMAX=0.2, NMX=12, NPR=4, ISP=0, ap='sw')\n"
                  "x = loadbd('sw')\n"
                  "save(x, 'sw2')\n",
                  &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("loop over every BP with a switch at each: status", rc, 0);
  int nbp = 0;
  const char *l = log_line(log, "bps ");
  test_true("three BPs below lambda = 100", l && sscanf(l, "%d", &nbp) == 1 && nbp == 3);
  snprintf(path, sizeof path, "%s/s.sw", replay_dir);
  cable_sfile *sf = cable_sfile_read(path, &err);
  for (int k = 1; k <= 3; k++) {
    char prefix[32], what[200];
    int lab = 0;
    double lbp = 0, lep = 0;
    snprintf(prefix, sizeof prefix, "switch %d ", k);
    l = log_line(log, prefix);
    snprintf(what, sizeof what, "BP%d: switched, the new branch printed", k);
    test_true(what, l && sscanf(l, "%lf %lf %d", &lbp, &lep, &lab) == 3);
    /* BPs are located to EPSS = 1e-10 in arclength; the collocation error of
       (k pi)^2 with NTST=40, NCOL=5 is far below 1e-8 relative */
    snprintf(what, sizeof what, "BP%d at lambda = (%d pi)^2", k, k);
    test_rel(what, lbp, (k * ELASTICA_PI) * (k * ELASTICA_PI), 1e-8);
    const cable_solution *ep = sf ? cable_sfile_find_label(sf, lab) : NULL;
    int sc = ep ? sign_changes(ep, 1e-6) : -1;
    snprintf(what, sizeof what, "the branch from BP%d is buckled in mode %d (theta changes sign %d times, lambda %.4f > BP)",
             k, k, sc, lep);
    test_true(what, ep && sc == k && lep > lbp && ep->ibr == 1 + k);
  }
  /* MAX U of a loaded result (loadbd, then save) is AUTO's signed maximum
     over the s-file's points, as the engine's: the re-saved rows equal the
     original rows of the same labels (both from 11-digit numbers) */
  snprintf(path, sizeof path, "%s/b.sw", replay_dir);
  cable_bfile *b1 = cable_bfile_read(path, &err);
  snprintf(path, sizeof path, "%s/b.sw2", replay_dir);
  cable_bfile *b2 = cable_bfile_read(path, &err);
  int nrow = 0, negative = 0;
  double emax = 0;
  for (int i = 0; b1 && b2 && i < b2->nbranch; i++) {
    const cable_bfile_branch *q = &b2->branch[i];
    for (int r = 0; r < q->nrow; r++)
      for (int j = 0; j < b1->nbranch; j++) {
        const cable_bfile_branch *o = &b1->branch[j];
        for (int r1 = 0; r1 < o->nrow; r1++) {
          if (o->lab[r1] != q->lab[r]) continue;
          for (int c = 0; c < 2; c++) {
            const char *name = c ? "MAX theta'" : "MAX theta";
            const double *a = cable_bfile_column(o, name), *b = cable_bfile_column(q, name);
            if (!a || !b) continue;
            emax = fmax(emax, fabs(a[r1] - b[r]) / fmax(fmax(fabs(a[r1]), fabs(b[r])), 1e-300));
            const cable_solution *x = sf ? cable_sfile_find_label(sf, q->lab[r]) : NULL;
            double amax = 0;
            for (int m = 0; x && m < cable_solution_npts(x); m++) amax = fmax(amax, fabs(x->u[1 + x->ndim * m]));
            negative += c == 1 && a[r1] < 1e-6 && amax > 0.1;
          }
          nrow++;
        }
      }
  }
  test_int("loadbd + save: every labelled row found in both b-files", nrow, sf ? cable_sfile_count(sf) : -1);
  test_le("loadbd + save: MAX theta, MAX theta' as the engine wrote them, max rel. difference", emax, 1e-10);
  snprintf(buf, sizeof buf, "  the branch from BP1 with DS < 0 has MAX theta' <= 0 rows (%d) where |theta'| reaches 0.1", negative);
  test_true(buf, negative > 0);
  cable_bfile_free(b1);
  cable_bfile_free(b2);
  cable_sfile_free(sf);
  free(log);
}

/* A restart from a saved s-file continues exactly as the run that was not
 * interrupted: fixed step (IADS=0), fixed mesh (IAD=0), no special points,
 * so the points after the restart label must be the same points. */
static void test_restart_reproduces(void)
{
  char *log = NULL, buf[1200], path[256];
  cable_error err;
  int rc = replay(NULL,
                  "full = run(c='bratu', IAD=0, IADS=0, ILP=0, DS=0.05, DSMAX=0.05, NMX=30, NPR=10, sv='full')\n"
                  "rest = run(s='full', IRS=2, NMX=21, sv='rest')\n",
                  &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("run, save, restart from the saved s-file: status", rc, 0);
  free(log);
  snprintf(path, sizeof path, "%s/b.full", replay_dir);
  cable_bfile *full = cable_bfile_read(path, &err);
  snprintf(path, sizeof path, "%s/b.rest", replay_dir);
  cable_bfile *rest = cable_bfile_read(path, &err);
  snprintf(path, sizeof path, "%s/s.full", replay_dir);
  cable_sfile *sf = cable_sfile_read(path, &err);
  const cable_solution *l2 = sf ? cable_sfile_find_label(sf, 2) : NULL;
  int ok = full && rest && l2 && full->nbranch == 1 && rest->nbranch == 1 && full->branch[0].nrow == 30 &&
           rest->branch[0].nrow == 21;
  test_true("b.full has 30 rows, b.rest 21 (label 2 is point 10 of 30)", ok && l2->ntot == 10);
  double emax = 0;
  int m = l2 ? l2->ntot : 0;
  for (int j = 0; ok && j < 21; j++) {
    const char *cols[] = {"lambda", "L2-NORM", "MAX u", "MAX u'"};
    for (int c = 0; c < 4; c++) {
      const double *a = cable_bfile_column(&full->branch[0], cols[c]), *b = cable_bfile_column(&rest->branch[0], cols[c]);
      if (!a || !b) {
        ok = 0;
        break;
      }
      emax = fmax(emax, fabs(b[j] - a[m - 1 + j]) / fmax(fabs(a[m - 1 + j]), 1e-300));
    }
  }
  test_true("every column of both b-files found", ok);
  /* the restart starts from the s-file's 11-digit copy of the point and its
     tangent; Newton (EPSL = EPSU = 1e-7 on the step, quadratic) lands on
     the same discrete points far below that: measured 9.0e-11, bound 1e-9 */
  test_le("the restart's 21 points = the uninterrupted run's points 10..30, max rel. difference", emax, 1e-9);
  cable_bfile_free(full);
  cable_bfile_free(rest);
  cable_sfile_free(sf);
}

/* The engine's remarks reach the d-file (AUTO's fort.9) and the log: a fold
 * that ITMX = 1 cannot locate, and the reason a branch ended at DSMIN. */
static void test_engine_notes(void)
{
  char *log = NULL, buf[1200], path[256];
  cable_error err;
  int rc = replay(NULL,
                  "r = run(c='bratu', ITMX=1, NMX=20, sv='upper')\n"
                  "m = run(c='bratu', ITNW=2, NWTN=2, DS=0.5, DSMIN=0.5, DSMAX=0.5, sv='bratu')\n",
                  &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("engine notes: status", rc, 0);
  test_true("engine notes: the log names the fold ITMX could not locate",
            log && strstr(log, "could not locate the fold within ITMX=1"));
  free(log);
  char *d = NULL;
  snprintf(path, sizeof path, "%s/d.upper", replay_dir);
  test_true("d.upper carries the note on the fold", (d = read_text(path)) && strstr(d, "NOTE: could not locate the fold"));
  free(d);
  snprintf(path, sizeof path, "%s/d.bratu", replay_dir);
  d = read_text(path);
  test_true("d.bratu says why the branch ended (DSMIN, KINSOL's reason)",
            d && strstr(d, "branch 2 ended") && strstr(d, "DSMIN = 0.5") && strstr(d, "KINSOL"));
  free(d);
}

/* overlap_free on a real braid branch: the flat (7,2) knot's tubes stay about
 * 3 Delta apart (tests/test_tube_distance.c checks the interval arithmetic),
 * so the whole branch is one stretch from its first to its last label. */
static void test_overlap_free(void)
{
  char *log = NULL, buf[1200];
  cable_error err;
  int rc = replay_with(NULL,
                  "r = run(e='braid_knot', TORUS=7, HAND=1, PAR={'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0},"
                  " ICP=['T', 'L', 'L2', 'eps21', 'F'], NTST=40, NCOL=4, DS=1, DSMAX=1, NMX=6, NPR=2, ISP=0, ILP=0)\n"
                  "iv = overlap_free(r)\n"
                  "print('ov', len(iv), iv[0][0], iv[0][1], r('EP1')['T'], r('EP2')['T'], analyze(r('EP2'))['dmin'])\n"
                  "x = overlap_free(r('EP2'))\n",
                  NULL, &log, &err);
  if (rc != CABLE_ERR_INPUT) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("overlap_free(solution) is refused", rc, CABLE_ERR_INPUT);
  test_true("  with a message naming the function", strstr(err.msg, "overlap_free(result)") != NULL);
  int n = 0;
  double a = NAN, b = NAN, t0 = 0, t1 = 1, dmin = 0;
  const char *l = log_line(log, "ov ");
  test_true("overlap_free on the flat knot: printed", l && sscanf(l, "%d %lf %lf %lf %lf %lf", &n, &a, &b, &t0, &t1, &dmin) == 6);
  snprintf(buf, sizeof buf, "flat knot: one overlap-free stretch (dmin %.3f > 1)", dmin);
  test_true(buf, n == 1 && dmin > 1);
  test_abs("  from the first label's T", a, t0, 1e-12);
  test_abs("  to the last label's T", b, t1, 1e-12);
  free(log);
}

static void expect_replay_error(const char *what, const char *text, int status, const char *want)
{
  char *log = NULL, buf[1200], d[200];
  cable_error err;
  int rc = replay(NULL, text, &log, &err);
  free(log);
  snprintf(d, sizeof d, "engine host, %s: status %s", what, cable_status_name(status));
  test_int(d, rc, status);
  snprintf(d, sizeof d, "engine host, %s: message", what);
  check_text(d, cable_error_format(&err, buf, sizeof buf), want);
}

static void test_engine_errors(void)
{
  char text[4096], want[4096];
  expect_replay_error("unknown problem", "r = run(e='nosuch', c='bratu')\n", CABLE_ERR_NOTFOUND,
                      "t.auto:1: run: e: unknown problem 'nosuch' (not a built-in problem, no equation file nosuch.f90, "
                      "nosuch.f or nosuch.c and no nosuch.so plug-in)");
  snprintf(text, sizeof text, "r = run(e='%s/broken_abi.so', c='bratu')\n", plugin_dir);
  snprintf(want, sizeof want,
           "t.auto:1: run: %s/broken_abi.so: abi_version: built for ABI 99, this cable expects 2 (rebuild the "
           "plug-in against this cable's cable_problem.h)",
           plugin_dir);
  expect_replay_error("rejected plug-in", text, CABLE_ERR_PLUGIN, want);
  /* every host runs the braid problems from STPNT: they prepare themselves
     from their keys and PAR={...} */
  expect_replay_error("braid from STPNT without Delta", "r = run(e='braid_knot')\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: PAR: a braid start needs the strand distance: PAR={'Delta': ...}");
  expect_replay_error("braid_link_sym from STPNT", "r = run(e='braid_link_sym')\n", CABLE_ERR_UNSUPPORTED,
                      "t.auto:1: run: e: 'braid_link_sym' has no start from STPNT: restart from a stored solution "
                      "(run(sol) or IRS with s=)");
  expect_replay_error("a problem key out of range", "r = run(e='braid_knot', TORUS=-3)\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: TORUS: must be an integer in 0..1001, got -3 (the start from STPNT: the (p,2) "
                      "torus knot (odd p) or link (even p >= 2); 0: the two rings) (in 'TORUS=-3')");
  expect_replay_error("a problem key's words", "r = run(e='braid_knot', HAND='up')\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: HAND: unknown value string 'up' (handedness of the start: 1 or 'right', -1 or "
                      "'left') (in 'HAND='up'')");
  expect_replay_error("another problem's key", "r = run(e='bratu', TORUS=7)\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: TORUS: unknown key (in 'TORUS=7')");
  expect_replay_error("missing label", "r = run(c='bratu')\nbp = r('BP1')\n", CABLE_ERR_NOTFOUND,
                      "t.auto:2: r: BP1: no such label in the result");
  expect_replay_error("IRS without solutions", "r = run(c='bratu', IRS=3)\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: IRS: a restart needs solutions: give a result, a solution, a name or s='NAME'");
  expect_replay_error("unknown parameter name", "r = run(c='bratu')\nx = r('LP1')['mu']\n", CABLE_ERR_NOTFOUND,
                      "t.auto:2: [: mu: no such parameter (names: the problem's parnames, PAR(k), LAB, BR, PT, TY, kind)");
  /* fail('text') stops the script with the text (a scene that misses its BP) */
  expect_replay_error("fail()", "r = run(c='bratu')\nfail('no fold with 3 < lambda < 4')\nr = run(c='bratu')\n",
                      CABLE_ERR_NOTFOUND, "t.auto:2: fail: no fold with 3 < lambda < 4");
  expect_replay_error("fail() without a string", "fail(3)\n", CABLE_ERR_NOTFOUND,
                      "t.auto:1: fail: fail() takes the message as a string");
  expect_replay_error("solution plus result", "r = run(c='bratu')\nx = r('LP1') + r\n", CABLE_ERR_INPUT,
                      "t.auto:2: +: '+' needs a result, got a solution");
  expect_replay_error("None as a constant", "r = run(c='bratu', DS=None)\n", CABLE_ERR_INPUT,
                      "t.auto:1: run: DS: a None is not a constants value");
  /* errors of the constants parser and the engine come through with the
   * script line and the key; their wording is theirs (tests/test_constants.c) */
  const struct {
    const char *what, *text, *head;
    int status;
  } theirs[] = {
    {"unknown keyword", "r = run(c='bratu', NMXX=3)\n", "t.auto:1: run: NMXX: ", CABLE_ERR_INPUT},
    {"bad value", "r = run(c='bratu', NTST=-5)\n", "t.auto:1: run: NTST: ", CABLE_ERR_INPUT},
    {"engine check", "r = run(c='bratu', NCOL=9)\n", "t.auto:1: run: NCOL", CABLE_ERR_INPUT},
    {"missing constants file", "r = run(e='bratu', c='missing')\n", "t.auto:1: run: %s/c.missing: ", CABLE_ERR_IO},
    {"missing files for loadbd", "x = loadbd('nothing')\n", "t.auto:1: loadbd: %s/s.nothing: ", CABLE_ERR_IO},
  };
  for (size_t i = 0; i < sizeof theirs / sizeof theirs[0]; i++) {
    char *log = NULL, buf[1200], d[400], head[256];
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
    snprintf(head, sizeof head, theirs[i].head, replay_dir);   /* "%s" only in the last two */
#pragma GCC diagnostic pop
    cable_error err;
    int rc = replay(NULL, theirs[i].text, &log, &err);
    free(log);
    cable_error_format(&err, buf, sizeof buf);
    snprintf(d, sizeof d, "engine host, %s: status %s", theirs[i].what, cable_status_name(theirs[i].status));
    test_int(d, rc, theirs[i].status);
    int ok = strncmp(buf, head, strlen(head)) == 0;
    if (!ok) printf("  got: %s\n", buf);
    snprintf(d, sizeof d, "engine host, %s: '%s...'", theirs[i].what, head);
    test_true(d, ok);
  }
}

int main(int argc, char **argv)
{
  (void)argc;
  /* BUILD/tests/test_script: plug-ins are in BUILD/plugins */
  const char *t = strstr(argv[0], "/tests/");
  if (t && t > argv[0]) snprintf(plugin_dir, sizeof plugin_dir, "%.*s/plugins", (int)(t - argv[0]), argv[0]);
  /* e='path.so' is relative to the run directory, like c=: use an absolute path */
  char cwd[1024], joined[sizeof cwd + sizeof plugin_dir + 2];
  if (plugin_dir[0] != '/' && getcwd(cwd, sizeof cwd)) {
    snprintf(joined, sizeof joined, "%s/%s", cwd, plugin_dir + (strncmp(plugin_dir, "./", 2) == 0 ? 2 : 0));
    if (strlen(joined) < sizeof plugin_dir) memcpy(plugin_dir, joined, strlen(joined) + 1);
  }
  test_knot_script();
  test_selection_and_iteration();
  test_python_subset();
  test_errors();
  test_value_api();
  test_engine_script();
  test_engine_notes();
  test_bp_loop();
  test_restart_reproduces();
  test_overlap_free();
  test_engine_errors();
  replay_cleanup();
  return test_summary();
}
