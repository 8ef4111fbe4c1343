/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Replays the fuzzing regression inputs (tests/data/fuzz_regressions/<target>/)
 * through the same entry points as the libFuzzer targets in tests/fuzz/:
 *   constants/  cable_constants_parse_string, then parse_override on the first half
 *   sfile/      cable_sfile_read on the file itself
 * Each input must come back with 0 or a negative cable_status and, on error,
 * a message (a clear diagnostic); the crashes themselves show up under
 * make asan / make valgrind.  A file whose name starts with "error-" must be
 * rejected (negative status): the bug it recorded let it through. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_status.h"
#include "cable/cable_constants.h"
#include "harness.h"

#define REGRESSION_DIR "tests/data/fuzz_regressions"
#define REGRESSION_MAX_BYTES (1 << 20)

static const char *const regression_parnames[] = {"T", "L", "L2", "eps21", "F", "Delta", "Ltot"};

/* The file's bytes, NUL-terminated; NULL when unreadable. */
static char *regression_slurp(const char *path, size_t *len)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  char *buf = malloc(REGRESSION_MAX_BYTES + 1);
  size_t n = buf ? fread(buf, 1, REGRESSION_MAX_BYTES, f) : 0;
  fclose(f);
  if (buf) buf[n] = '\0';
  *len = n;
  return buf;
}

static int regression_error_ok(const char *path, int st, const cable_error *err)
{
  const char *base = strrchr(path, '/');
  int must_fail = strncmp(base ? base + 1 : path, "error-", 6) == 0;
  return (st == 0 && !must_fail) || (st < 0 && err->msg[0] != '\0');
}

static void regression_constants(const char *path)
{
  size_t len;
  char *text = regression_slurp(path, &len);
  if (!test_true(path, text != NULL)) return;
  cable_constants c;
  cable_names names;
  cable_error err;
  cable_error_clear(&err);
  cable_constants_init(&c);
  cable_names_init(&names);
  int st = cable_constants_parse_string("fuzz", text, &c, &names, regression_parnames, 7, &err);
  if (st == 0) {
    text[len / 2] = '\0';
    st = cable_constants_parse_override(text, &c, &names, regression_parnames, 7, &err);
  }
  char what[700];
  snprintf(what, sizeof what, "%s: constants parser returns %s with a message", path, cable_status_name(st));
  test_true(what, regression_error_ok(path, st, &err));
  free(text);
}

static void regression_sfile(const char *path)
{
  cable_error err;
  cable_error_clear(&err);
  cable_sfile *s = cable_sfile_read(path, &err);
  char what[700];
  snprintf(what, sizeof what, "%s: s-file reader returns %s", path, s ? "a file" : "an error with a message");
  test_true(what, s != NULL || err.msg[0] != '\0');
  cable_sfile_free(s);
}

int main(void)
{
  static const char *const targets[] = {"constants", "sfile"};
  void (*const replay[])(const char *) = {regression_constants, regression_sfile};
  int total = 0;
  for (int t = 0; t < 2; t++) {
    char dir[256];
    snprintf(dir, sizeof dir, "%s/%s", REGRESSION_DIR, targets[t]);
    DIR *d = opendir(dir);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      if (e->d_name[0] == '.') continue;
      char path[600];
      snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
      replay[t](path);
      total++;
    }
    closedir(d);
  }
  char what[128];
  snprintf(what, sizeof what, "fuzz regression inputs replayed: %d", total);
  test_true(what, total > 0);
  return test_summary();
}
