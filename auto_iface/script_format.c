/* Python's printf-style string formatting, 'mode%d' % n and
 * '%s_%03d' % (name, k): conversions d i s r g G e E f F and %%, with flags
 * (- + space # 0), width and precision.  Widths and precisions are bounded so
 * a script cannot ask for a huge string. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_status.h"
#include "script_interp.h"

/* Largest width or precision accepted: far beyond any file name or table
 * column, small enough that one conversion stays a few kilobytes. */
#define SCRIPT_FORMAT_MAX_WIDTH 999

static int fmt_fail(script_interp *in, int line, const char *fmt, const char *what)
{
  return script_fail(in, CABLE_ERR_INPUT, line, "%", "%s in format '%.60s'", what, fmt);
}

int script_format_percent(script_interp *in, int line, const script_value *fmtv,
                          const script_value *arg, script_value *out)
{
  const char *fmt = script_string_chars(fmtv);
  size_t flen = script_string_len(fmtv);
  /* a list (or tuple) supplies one value per conversion; anything else is one value */
  size_t nargs = arg->type == SCRIPT_LIST ? script_list_len(arg) : 1;
  size_t used = 0;
  script_buf b = {NULL, 0, 0};
  int rc = script_buf_puts(&b, "");
  for (size_t i = 0; i < flen && !rc;) {
    const char *pct = memchr(fmt + i, '%', flen - i);
    size_t lit = pct ? (size_t)(pct - (fmt + i)) : flen - i;
    if ((rc = script_buf_putn(&b, fmt + i, lit))) break;
    i += lit;
    if (i >= flen) break;
    i++;   /* '%' */
    if (i < flen && fmt[i] == '%') {
      rc = script_buf_puts(&b, "%");
      i++;
      continue;
    }
    /* %[flags][width][.precision]conversion */
    char spec[32];
    size_t sn = 0;
    spec[sn++] = '%';
    while (i < flen && fmt[i] != '\0' && strchr("-+ #0", fmt[i]) && sn < 8) spec[sn++] = fmt[i++];
    int width = 0, prec = -1;
    if (i < flen && (fmt[i] == '*' || fmt[i] == '(')) {
      rc = fmt_fail(in, line, fmt, fmt[i] == '*' ? "'*' widths are not supported"
                                                  : "'%(name)s' mappings are not supported");
      break;
    }
    while (i < flen && fmt[i] >= '0' && fmt[i] <= '9' && width <= SCRIPT_FORMAT_MAX_WIDTH)
      width = 10 * width + (fmt[i++] - '0');
    if (i < flen && fmt[i] == '.') {
      i++;
      prec = 0;
      while (i < flen && fmt[i] >= '0' && fmt[i] <= '9' && prec <= SCRIPT_FORMAT_MAX_WIDTH)
        prec = 10 * prec + (fmt[i++] - '0');
    }
    if (width > SCRIPT_FORMAT_MAX_WIDTH || prec > SCRIPT_FORMAT_MAX_WIDTH) {
      rc = fmt_fail(in, line, fmt, "width or precision too large (limit 999)");
      break;
    }
    if (i >= flen) {
      rc = fmt_fail(in, line, fmt, "incomplete format");
      break;
    }
    char conv = fmt[i++];
    /* strchr finds the terminating NUL too: a NUL (from '\0' in the script)
       must not pass as a conversion, or snprintf gets an incomplete spec */
    if (conv == '\0' || !strchr("disrgGeEfF", conv)) {
      char what[64];
      if (conv == '\0') snprintf(what, sizeof what, "unsupported format character '\\0'");
      else snprintf(what, sizeof what, "unsupported format character '%c'", conv);
      rc = fmt_fail(in, line, fmt, what);
      break;
    }
    if (used >= nargs) {
      rc = fmt_fail(in, line, fmt, "not enough values for the format");
      break;
    }
    const script_value *v = arg->type == SCRIPT_LIST ? script_list_get(arg, used) : arg;
    used++;
    char piece[2 * SCRIPT_FORMAT_MAX_WIDTH + 64];
    int numeric = v->type == SCRIPT_NUMBER || v->type == SCRIPT_BOOL;
    if (conv == 's' || conv == 'r') {
      script_buf t = {NULL, 0, 0};
      rc = script_value_write(&t, v, in->host, conv == 'r');
      if (!rc) {
        /* width and precision apply to the text; only '-' matters among the flags */
        int left = memchr(spec, '-', sn) != NULL;
        size_t tl = t.len;
        if (prec >= 0 && (size_t)prec < tl) tl = (size_t)prec;
        size_t pad = (size_t)width > tl ? (size_t)width - tl : 0;
        for (size_t k = 0; !left && k < pad && !rc; k++) rc = script_buf_puts(&b, " ");
        if (!rc) rc = script_buf_putn(&b, t.data ? t.data : "", tl);
        for (size_t k = 0; left && k < pad && !rc; k++) rc = script_buf_puts(&b, " ");
      }
      script_buf_free(&t);
      continue;
    }
    if (!numeric) {
      char what[96];
      snprintf(what, sizeof what, "%%%c needs a number, got a %s", conv, script_type_name(v));
      rc = fmt_fail(in, line, fmt, what);
      break;
    }
    if (conv == 'd' || conv == 'i') {
      /* Python truncates toward zero; beyond 2^63 a long long overflows */
      const double ll_limit = 9.2e18;
      if (!isfinite(v->num) || fabs(v->num) >= ll_limit) {
        rc = fmt_fail(in, line, fmt, "%d of a number that is not a finite integer");
        break;
      }
      if (prec >= 0) snprintf(spec + sn, sizeof spec - sn, "%d.%dlld", width, prec);
      else snprintf(spec + sn, sizeof spec - sn, "%dlld", width);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
      snprintf(piece, sizeof piece, spec, (long long)trunc(v->num));
    } else {
      if (prec >= 0) snprintf(spec + sn, sizeof spec - sn, "%d.%d%c", width, prec, conv);
      else snprintf(spec + sn, sizeof spec - sn, "%d%c", width, conv);
      snprintf(piece, sizeof piece, spec, v->num);
#pragma GCC diagnostic pop
    }
    rc = script_buf_puts(&b, piece);
  }
  if (!rc && used < nargs && arg->type == SCRIPT_LIST)
    rc = fmt_fail(in, line, fmt, "not all values converted (more values than conversions)");
  if (!rc && used == 0 && arg->type != SCRIPT_LIST)
    rc = fmt_fail(in, line, fmt, "not all values converted (no conversion in the format)");
  if (rc && in->err->status == 0)
    rc = script_fail(in, rc, line, "%", "formatted text too long (limit %d bytes)", SCRIPT_MAX_STRING);
  if (!rc) rc = script_string_from_buf(out, &b);
  script_buf_free(&b);
  if (rc && in->err->status == 0) rc = script_fail(in, rc, line, "%", "out of memory");
  return rc;
}
