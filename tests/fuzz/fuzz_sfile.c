/* libFuzzer target: the s-file reader (auto_iface/files/aufile_read.c: cable_sfile_read)
 * through its only entry point, a path: each input is written to one
 * temporary file per process, then read and, when it parses, queried the way
 * restarts do (labels, AUTO's 'BP1' / '-1' specs, IRS resolution, err_est).
 * Built by scripts/fuzz.sh. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cable/cable_aufile.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* One temporary file per fuzzing process, created on the first input. */
static const char *fuzz_sfile_path(void)
{
  static char path[64];
  if (!path[0]) {
    snprintf(path, sizeof path, "/tmp/cable-fuzz-sfile.XXXXXX");
    int fd = mkstemp(path);
    if (fd < 0) abort();
    close(fd);
  }
  return path;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const char *path = fuzz_sfile_path();
  FILE *f = fopen(path, "wb");
  if (!f) abort();
  if (size && fwrite(data, 1, size, f) != size) abort();
  if (fclose(f) != 0) abort();
  cable_error err;
  cable_sfile *s = cable_sfile_read(path, &err);
  if (!s) return 0;
  int n = cable_sfile_count(s);
  for (int i = 0; i < n; i++) {
    const cable_solution *sol = cable_sfile_get(s, i);
    if (!sol) abort();
    if (cable_sfile_find_label(s, sol->lab) == NULL) abort();
  }
  static const char *const specs[] = {"1", "-1", "BP1", "UZ2", "EP1", "", "X", "BP0", "-99999999999"};
  for (size_t k = 0; k < sizeof specs / sizeof specs[0]; k++) (void)cable_sfile_find(s, specs[k], &err);
  cable_constants c;
  cable_constants_init(&c);
  snprintf(c.irs_name, sizeof c.irs_name, "%s", "LP1");
  (void)cable_sfile_resolve_irs(s, &c, &err);
  cable_sfile_take_err_est(s, 0);
  cable_sfile_free(s);
  return 0;
}
