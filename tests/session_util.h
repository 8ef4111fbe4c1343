/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Runs for the C tests on a session (cable/cable_session.h, auto_iface/session/), written as
 * `cable run` argument lines: "e=braid_knot c=pvls NMX=3 sv=pvls".  Words are
 * separated by blanks outside brackets and quotes; e, c, s, sv, ap name
 * files, every other KEY=VALUE is a constants-file override.  The Python
 * package's tests (tests/python) cover AUTO's script commands. */
#ifndef CABLE_TEST_SESSION_UTIL_H
#define CABLE_TEST_SESSION_UTIL_H

#include <stdio.h>
#include <string.h>

#include "cable/cable_session.h"
#include "cable/cable_status.h"

#define SESSION_LINE_MAX 32

/* One run of the line in session s, restarting from branch `from` (its
 * solution IRS, e.g. "IRS='BP1'" in the line, or its last) when not NULL.
 * *out: the new branch (release with cable_branch_decref), may be NULL. */
static int session_line(cable_session *s, const char *line, cable_branch *from, cable_branch **out, cable_error *err)
{
  char buf[4096], *word[SESSION_LINE_MAX];
  int n = 0, depth = 0;
  char quote = 0;
  snprintf(buf, sizeof buf, "%s", line);
  for (char *p = buf, *start = NULL;; p++) {
    int end = !*p || (!quote && depth == 0 && (*p == ' ' || *p == '\n'));
    if (end) {
      if (start && n < SESSION_LINE_MAX) word[n++] = start;
      start = NULL;
      if (!*p) break;
      *p = '\0';
      continue;
    }
    if (!start) start = p;
    if (quote) quote = *p == quote ? 0 : quote;
    else if (*p == '\'' || *p == '"') quote = *p;
    else depth += (*p == '[' || *p == '{') - (*p == ']' || *p == '}');
  }
  cable_run_args a;
  memset(&a, 0, sizeof a);
  const char *over[SESSION_LINE_MAX];
  for (int i = 0; i < n; i++) {
    char *eq = strchr(word[i], '=');
    if (!eq) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, word[i], "not KEY=VALUE");
    size_t k = (size_t)(eq - word[i]);
    const char **slot = NULL;
    if (k == 1 && word[i][0] == 'e') slot = &a.e;
    else if (k == 1 && word[i][0] == 'c') slot = &a.c;
    else if (k == 1 && word[i][0] == 's') slot = &a.s;
    else if (k == 2 && strncmp(word[i], "sv", 2) == 0) slot = &a.sv;
    else if (k == 2 && strncmp(word[i], "ap", 2) == 0) slot = &a.ap;
    if (slot) *slot = eq + 1;
    else over[a.nover++] = word[i];
  }
  a.over = over;
  cable_branch *one[1] = {from};
  if (from) {
    a.branches = one;
    a.nbranch = 1;
  }
  cable_branch *b = NULL;
  cable_error_clear(err);
  int rc = cable_session_run(s, &a, &b, err);
  if (out) *out = b;
  else cable_branch_decref(b);
  return rc;
}

/* A session in dir with the braid problems, its log to /dev/null (*log: close it). */
static cable_session *session_open(const char *dir, FILE **log)
{
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = dir;
  *log = fopen("/dev/null", "w");
  o.log = *log;
  return cable_session_alloc(&o);
}

static void session_close(cable_session *s, FILE *log)
{
  cable_session_free(s);
  if (log) fclose(log);
}

#endif
