/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The runner state of a session (AUTO's runner.options["constants"]): what
 * AUTO's pr() prints and what the next run without a start uses. */
#include <stddef.h>

#include "cable/cable_status.h"
#include "cable_session_impl.h"

int cable_session_constants(const cable_session *s, const cable_constants **c, const cable_names **names,
                            const char **e, cable_error *err)
{
  if (c) *c = NULL;
  if (names) *names = NULL;
  if (e) *e = NULL;
  if (!s) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_session_constants: the session is NULL");
  if (c) *c = &s->cur;
  if (names) *names = &s->cur_names;
  if (e) *e = s->cur_e;
  return 0;
}
