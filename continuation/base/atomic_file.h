/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Atomic output files: everything is written to a temporary file in the same
 * directory (".NAME.tmpXXXXXX") and renamed over NAME only at commit (or at a
 * checkpoint, which publishes a complete copy of what has been written so
 * far).  A run that fails or is killed leaves NAME as it was before the run
 * (or as of the last checkpoint), never truncated; at worst a stray
 * ".NAME.tmp*" file remains, which no reader looks at.
 *
 *   cable_atomic_file *af = cable_atomic_open("runs/x/b.knot", 0, &err);
 *   fprintf(cable_atomic_stream(af), ...);
 *   if (cable_atomic_commit(af, &err) != 0) ...      // af is freed either way
 */
#ifndef CABLE_ATOMIC_FILE_H
#define CABLE_ATOMIC_FILE_H

#include <stdio.h>

#include "cable/cable_error.h"

typedef struct cable_atomic_file cable_atomic_file;

/* Create the temporary file.  append = 1 starts it with a copy of the
 * current contents of path (when path exists), so that committing appends
 * (AUTO's `ap`).  NULL on failure (err says why). */
cable_atomic_file *cable_atomic_open(const char *path, int append, cable_error *err);

/* The stream to write to (never NULL for an open file). */
FILE *cable_atomic_stream(cable_atomic_file *af);

/* Target path as given to cable_atomic_open. */
const char *cable_atomic_path(const cable_atomic_file *af);

/* Publish what has been written so far: a complete copy replaces path
 * atomically; writing continues afterwards.  0 or a negative status. */
int cable_atomic_checkpoint(cable_atomic_file *af, cable_error *err);

/* A complete copy of what has been written so far, at dest (created or
 * truncated), followed by the text trailer (NULL: none), synced to disk when
 * sync is non-zero.  Writing continues afterwards.  For publishers that
 * place the copy themselves (auto_iface/files/live_files.c).  0 or a negative
 * status. */
int cable_atomic_copy(cable_atomic_file *af, const char *dest, const char *trailer, int sync, cable_error *err);

/* Flush, sync and close the temporary file, without publishing it: the
 * first half of a commit, so that several files can be made complete before
 * any of them is renamed into place.  Nothing can be written afterwards; af
 * still needs commit or abort.  0 or a negative status. */
int cable_atomic_finish(cable_atomic_file *af, cable_error *err);

/* Finish (when not done yet) and rename into place; frees af (also on
 * failure, when the temporary file is removed and path keeps its previous
 * contents). */
int cable_atomic_commit(cable_atomic_file *af, cable_error *err);

/* Discard: remove the temporary file, leave path untouched, free af.
 * NULL is a no-op. */
void cable_atomic_abort(cable_atomic_file *af);

#endif
