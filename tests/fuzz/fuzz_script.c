/* libFuzzer target: the run-script interpreter (auto_iface/script.h:
 * script_run_string).  No engine: the first input byte picks how the host's
 * callbacks behave, the rest is the script.
 *   mode 0: every callback fails (recoverable error status in err);
 *   mode 1: every callback succeeds and returns None;
 *   mode 2: every callback succeeds and returns a fresh dummy handle, so
 *           that the handle paths (label selection, '+', iteration,
 *           indexing, reference counting and release) run too;
 *   mode 3: callbacks fail without setting err (CABLE_ERR_CALLBACK path).
 * Built by scripts/fuzz.sh. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { FUZZ_FAIL = 0, FUZZ_NONE = 1, FUZZ_HANDLE = 2, FUZZ_FAIL_SILENT = 3, FUZZ_NMODE = 4 };

typedef struct fuzz_host {
  int mode;
  long live;   /* handles created and not yet released: must end at 0 */
  int dummy;
  const script_host *self;   /* the host struct, for script_handle_new */
} fuzz_host;

static int fuzz_answer(void *ctx, script_value *out, cable_error *err, int kind);

static int fuzz_answer(void *ctx, script_value *out, cable_error *err, int kind)
{
  fuzz_host *h = ctx;
  switch (h->mode) {
  case FUZZ_FAIL:
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "fuzz", "host refuses");
  case FUZZ_FAIL_SILENT:
    return 1;
  case FUZZ_HANDLE:
    if (!out) return 0;
    h->live++;
    return script_handle_new(out, h->self, kind, &h->dummy);
  default:
    return 0;
  }
}

static int fuzz_run(void *ctx, const script_value *start, const script_kwargs *kw, script_value *out,
                    cable_error *err)
{
  (void)start; (void)kw;
  return fuzz_answer(ctx, out, err, SCRIPT_HANDLE_RESULT);
}

static int fuzz_select(void *ctx, const script_value *result, const script_value *spec, script_value *out,
                       cable_error *err)
{
  (void)result;
  /* 'BP' (a type alone) asks for a list; give one element so that loops run */
  fuzz_host *h = ctx;
  if (h->mode == FUZZ_HANDLE && spec && script_string_chars(spec) && script_string_len(spec) == 2) {
    script_value item = script_none();
    int st = fuzz_answer(ctx, &item, err, SCRIPT_HANDLE_SOLUTION);
    if (st) return st;
    st = script_list_new(out);
    if (st) { script_value_release(&item); return st; }
    return script_list_append(out, item);
  }
  return fuzz_answer(ctx, out, err, SCRIPT_HANDLE_SOLUTION);
}

static int fuzz_add(void *ctx, const script_value *a, const script_value *b, script_value *out,
                    cable_error *err)
{
  (void)a; (void)b;
  return fuzz_answer(ctx, out, err, SCRIPT_HANDLE_RESULT);
}

static int fuzz_items(void *ctx, const script_value *handle, script_value *list_out, cable_error *err)
{
  (void)handle;
  fuzz_host *h = ctx;
  if (h->mode != FUZZ_HANDLE) return fuzz_answer(ctx, NULL, err, 0);
  int st = script_list_new(list_out);
  for (int k = 0; st == 0 && k < 2; k++) {
    script_value item = script_none();
    st = fuzz_answer(ctx, &item, err, SCRIPT_HANDLE_SOLUTION);
    if (st == 0) st = script_list_append(list_out, item);
  }
  return st;
}

static int fuzz_getitem(void *ctx, const script_value *handle, const script_value *key, script_value *out,
                        cable_error *err)
{
  (void)handle; (void)key;
  fuzz_host *h = ctx;
  if (h->mode == FUZZ_HANDLE) { *out = script_number(1.5); return 0; }
  return fuzz_answer(ctx, out, err, 0);
}

static int fuzz_load(void *ctx, int what, const script_value *d, const script_kwargs *kw, script_value *out,
                     cable_error *err)
{
  (void)d; (void)kw;
  return fuzz_answer(ctx, out, err, what == SCRIPT_LOAD_RESULT ? SCRIPT_HANDLE_RESULT : SCRIPT_HANDLE_SOLUTION);
}

static int fuzz_save(void *ctx, const script_value *d, const char *name, cable_error *err)
{
  (void)d; (void)name;
  return fuzz_answer(ctx, NULL, err, 0);
}

static int fuzz_merge(void *ctx, const script_value *d, script_value *out, cable_error *err)
{
  (void)d;
  return fuzz_answer(ctx, out, err, SCRIPT_HANDLE_RESULT);
}

static int fuzz_clean(void *ctx, cable_error *err)
{
  return fuzz_answer(ctx, NULL, err, 0);
}

static int fuzz_call(void *ctx, const char *name, int nargs, const script_value *args, const script_kwargs *kw,
                     script_value *out, cable_error *err)
{
  (void)nargs; (void)args; (void)kw;
  if (strcmp(name, "analyze") != 0 && strcmp(name, "compare") != 0) return CABLE_ERR_NOTFOUND;
  return fuzz_answer(ctx, out, err, SCRIPT_HANDLE_RESULT);
}

static void fuzz_describe(void *ctx, const script_value *handle, char *buf, size_t len)
{
  (void)ctx; (void)handle;
  if (len) { strncpy(buf, "<fuzz>", len - 1); buf[len - 1] = '\0'; }
}

static void fuzz_print(void *ctx, const char *line)
{
  (void)ctx; (void)line;
}

static void fuzz_release(void *ctx, void *ptr, int kind)
{
  fuzz_host *h = ctx;
  (void)kind;
  if (ptr != &h->dummy) abort();
  h->live--;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size < 1) return 0;
  fuzz_host h = {data[0] % FUZZ_NMODE, 0, 0, NULL};
  script_host host = {&h, fuzz_run, fuzz_select, fuzz_add, fuzz_items, fuzz_getitem, fuzz_load,
                            fuzz_save, fuzz_merge, fuzz_merge, fuzz_clean, fuzz_call, fuzz_describe, fuzz_print,
                            fuzz_release};
  h.self = &host;
  char *text = malloc(size);
  if (!text) return 0;
  memcpy(text, data + 1, size - 1);
  text[size - 1] = '\0';
  cable_error err;
  (void)script_run_string("fuzz.auto", text, &host, &err);
  free(text);
  /* every handle the interpreter received must have been released exactly once */
  if (h.live != 0) abort();
  return 0;
}
