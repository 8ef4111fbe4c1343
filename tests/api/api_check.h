/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Checks for the API tests, which see the public headers only: one
 * PASS/FAIL line per check (the format scripts/run-tests.sh counts). */
#ifndef CABLE_API_CHECK_H
#define CABLE_API_CHECK_H

#include <stdio.h>

typedef struct {
  int passed, failed;
} api_counts;

static api_counts api_counts_state;

static inline int api_check(const char *what, int ok)
{
  printf("%s %s\n", ok ? "PASS" : "FAIL", what);
  fflush(stdout);
  if (ok) api_counts_state.passed++;
  else api_counts_state.failed++;
  return ok;
}

static inline int api_check_int(const char *what, long got, long want)
{
  printf("%s %s: got %ld want %ld\n", got == want ? "PASS" : "FAIL", what, got, want);
  fflush(stdout);
  if (got == want) api_counts_state.passed++;
  else api_counts_state.failed++;
  return got == want;
}

static inline int api_summary(void)
{
  printf("%d passed, %d failed\n", api_counts_state.passed, api_counts_state.failed);
  return api_counts_state.failed == 0 ? 0 : 1;
}

#endif
