/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Test harness: one PASS/FAIL/SKIP line per check, with the compared values
 * and the tolerance.  NaN and Inf never pass a numeric check.  A check that
 * cannot be performed in this build or environment (e.g. counting mallocs
 * under a sanitizer that owns malloc) is reported with test_skip and the
 * reason, never as a PASS.  A test program ends with `return test_summary();`,
 * which exits non-zero when any check failed. */
#ifndef CABLE_TEST_HARNESS_H
#define CABLE_TEST_HARNESS_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
  int passed;
  int failed;
  int skipped;
} test_counts;

/* One counter per test program; it lives in the program's own translation unit. */
static test_counts test_counts_state;

static void test_report(int ok, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void test_report(int ok, const char *fmt, ...)
{
  va_list ap;
  printf("%s ", ok ? "PASS" : "FAIL");
  va_start(ap, fmt);
  vprintf(fmt, ap);
  va_end(ap);
  printf("\n");
  fflush(stdout);
  if (ok) test_counts_state.passed++;
  else test_counts_state.failed++;
}

/* |got - want| <= tol * max(|want|, tiny) : relative check */
static inline int test_rel(const char *what, double got, double want, double tol)
{
  double scale = fabs(want) > 0 ? fabs(want) : 1.0;
  double err = fabs(got - want) / scale;
  int ok = isfinite(got) && isfinite(want) && err <= tol;
  test_report(ok, "%s: got %.16g want %.16g rel.err %.3g tol %.3g", what, got, want, err, tol);
  return ok;
}

/* |got - want| <= tol : absolute check */
static inline int test_abs(const char *what, double got, double want, double tol)
{
  double err = fabs(got - want);
  int ok = isfinite(got) && isfinite(want) && err <= tol;
  test_report(ok, "%s: got %.16g want %.16g abs.err %.3g tol %.3g", what, got, want, err, tol);
  return ok;
}

/* got <= bound (for error norms, residuals) */
static inline int test_le(const char *what, double got, double bound)
{
  int ok = isfinite(got) && got <= bound;
  test_report(ok, "%s: %.6g <= %.6g", what, got, bound);
  return ok;
}

static inline int test_int(const char *what, long got, long want)
{
  int ok = got == want;
  test_report(ok, "%s: got %ld want %ld", what, got, want);
  return ok;
}

static inline int test_true(const char *what, int cond)
{
  test_report(cond != 0, "%s", what);
  return cond != 0;
}

/* A check that was not performed: "SKIP what: why".  Neither passes nor fails. */
static inline void test_skip(const char *what, const char *why)
{
  printf("SKIP %s: %s\n", what, why);
  fflush(stdout);
  test_counts_state.skipped++;
}

static inline int test_summary(void)
{
  if (test_counts_state.skipped) printf("%d skipped\n", test_counts_state.skipped);
  printf("%d passed, %d failed\n", test_counts_state.passed, test_counts_state.failed);
  return test_counts_state.failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

#endif
