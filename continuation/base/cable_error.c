/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void cable_error_clear(cable_error *e)
{
  if (e) memset(e, 0, sizeof *e);
}

int cable_error_set(cable_error *e, int status, const char *file, int line, const char *key,
                    const char *fmt, ...)
{
  if (!e) return status;
  e->status = status;
  snprintf(e->file, sizeof e->file, "%s", file ? file : "");
  e->line = line;
  snprintf(e->key, sizeof e->key, "%s", key ? key : "");
  if (!fmt) fmt = "";
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(e->msg, sizeof e->msg, fmt, ap);
  va_end(ap);
  return status;
}

const char *cable_error_format(const cable_error *e, char *buf, size_t len)
{
  if (!buf || len == 0) return "";
  size_t n = 0;
  buf[0] = '\0';
  if (!e) return buf;
  if (e->file[0]) n += (size_t)snprintf(buf + n, len - n, "%s:", e->file);
  if (n < len && e->file[0] && e->line > 0) n += (size_t)snprintf(buf + n, len - n, "%d:", e->line);
  if (n < len && n > 0) n += (size_t)snprintf(buf + n, len - n, " ");
  if (n < len && e->key[0]) n += (size_t)snprintf(buf + n, len - n, "%s: ", e->key);
  if (n < len) snprintf(buf + n, len - n, "%s", e->msg);
  return buf;
}
