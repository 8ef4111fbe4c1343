/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The b./s./d. writer's live copies (aufile_write.c), for the session's
 * files written as a run goes (live_files.c); not part of the public API. */
#ifndef CABLE_AUFILE_LIVE_H
#define CABLE_AUFILE_LIVE_H

#include "cable/cable_aufile.h"

/* Complete copies of what w has written so far: dir/b.new, dir/d.new
 * (followed by the line dnote, NULL: none) and, when with_s, dir/s.new,
 * synced to disk when sync is non-zero.  0, or a negative status with err
 * (w stays usable). */
int cable_aufile_snapshot(cable_aufile *w, const char *dir, int with_s, const char *dnote, int sync,
                          cable_error *err);

#endif
