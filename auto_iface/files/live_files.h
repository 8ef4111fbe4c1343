/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A run's b./s./d.NAME on disk as it is computed (doc/failures.md).
 *
 * While a run writes NAME, b.NAME, s.NAME and d.NAME are symbolic links to
 * .cable-NAME/cur/b, s and d, and .cable-NAME/cur is a link to the newest
 * complete generation .cable-NAME/gK of the three files.  A step is published
 * by one rename of cur, so every reader (cable's, AUTO's parseB/parseS) sees
 * the three files of one step, each ending with a whole record, whatever
 * kills the writer.  At the end the writer's own complete files are renamed
 * over the links (the same contents) and .cable-NAME goes.
 *
 * .cable-NAME is also the lock of NAME: every writer of NAME (a run, save,
 * merge) holds it, so two processes cannot mix their files; a writer that
 * finds the leftovers of one that was killed (the links, temporary files
 * .b.NAME.tmpXXXXXX) turns them into plain files or removes them. */
#ifndef CABLE_LIVE_FILES_H
#define CABLE_LIVE_FILES_H

#include <stdio.h>

#include "cable/cable_aufile.h"
#include "cable/cable_error.h"

/* An output name (sv=, ap=, save): a plain file name whose files and their
 * temporary names fit the file system (key names the keyword in errors). */
int rp_out_name_check(const char *key, const char *name, cable_error *err);

/* NAME's lock in dir (NULL: the current directory), waited for (with a note
 * on log) when another process holds it; a killed writer's leftovers are
 * cleaned up.  NULL on failure (err says why). */
typedef struct rp_lock rp_lock;
rp_lock *rp_lock_take(const char *dir, const char *name, FILE *log, cable_error *err);
/* Leftover links become plain files, .cable-NAME goes, the lock is freed. */
void rp_lock_release(rp_lock *l);

typedef struct rp_live rp_live;
/* Takes the lock and opens the writer (append: AUTO's ap=); the files keep
 * their old contents until the first publish. */
rp_live *rp_live_open(const char *dir, const char *name, int append, const cable_constants *c,
                      const cable_names *names, FILE *log, cable_error *err);
cable_sink rp_live_sink(rp_live *l);
/* Publishes what has been written (the d-file's copy ends with a line saying
 * that the run was still going).  0 or a negative status. */
int rp_live_publish(rp_live *l, cable_error *err);
/* Ends the files: the end note (NULL: none) into the d-file, the final
 * files in place.  Frees l.  0 or a negative status. */
int rp_live_close(rp_live *l, const char *end_note, cable_error *err);
/* Before any publish: nothing of this run is kept, the files are as before
 * it (after one: as of the last publish).  Frees l. */
void rp_live_abort(rp_live *l);
/* "b.NAME, s.NAME, d.NAME" (with the directory), for messages. */
const char *rp_live_files(const rp_live *l);

#endif
