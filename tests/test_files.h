/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Test helper: copy a file byte for byte (scene inputs into scratch directories). */
#ifndef CABLE_TEST_FILES_H
#define CABLE_TEST_FILES_H

#include <stdio.h>

/* 1 when every byte of from reached to, 0 otherwise. */
static inline int copy_file(const char *from, const char *to)
{
  FILE *a = fopen(from, "rb"), *b = a ? fopen(to, "wb") : NULL;
  char buf[4096];
  size_t n;
  int ok = a && b;
  while (ok && (n = fread(buf, 1, sizeof buf, a)) > 0) ok = fwrite(buf, 1, n, b) == n;
  if (a) fclose(a);
  if (b && fclose(b) != 0) ok = 0;
  return ok;
}

#endif
