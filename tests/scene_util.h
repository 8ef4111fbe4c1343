/* Test helpers for the scene acceptance tests (test_scenes.c,
 * test_link_scenes.c): a scratch directory with a scene's input files, a
 * replay of a script (a scene's own file or a text) in it with the log
 * captured, and the log's lines. */
#ifndef CABLE_TEST_SCENE_UTIL_H
#define CABLE_TEST_SCENE_UTIL_H

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "script_host_cable.h"
#include "script.h"
#include "script_host_cable.h"
#include "test_files.h"

typedef struct scene_scratch {
  char dir[96];
} scene_scratch;

/* A fresh directory tests/tmp/NAME.PID holding copies of the given files of
 * runs/SCENE/ (NULL-terminated list); 1 on success. */
static inline int scene_scratch_make(scene_scratch *sc, const char *name, const char *scene,
                                     const char *const *files)
{
  snprintf(sc->dir, sizeof sc->dir, "tests/tmp/%s.%ld", name, (long)getpid());
  mkdir("tests/tmp", 0777);
  if (mkdir(sc->dir, 0777) != 0) return 0;
  int ok = 1;
  for (int i = 0; files && files[i] && ok; i++) {
    char from[192], to[192];
    snprintf(from, sizeof from, "runs/%s/%s", scene, files[i]);
    snprintf(to, sizeof to, "%s/%s", sc->dir, files[i]);
    ok = copy_file(from, to);
  }
  return ok;
}

/* Removes every file of the scratch directory and the directory. */
static inline void scene_scratch_remove(const scene_scratch *sc)
{
  DIR *d = opendir(sc->dir);
  if (d) {
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
      char p[384];
      snprintf(p, sizeof p, "%s/%s", sc->dir, e->d_name);
      remove(p);
    }
    closedir(d);
  }
  rmdir(sc->dir);
}

/* Runs a script (the file path when text is NULL, else the text) with the
 * braid problems in the scratch directory; the log (print output, labelled
 * points, the engine's notes) comes back in *log (free it). */
static inline int scene_replay(const scene_scratch *sc, const char *path, const char *text, char **log,
                               cable_error *err)
{
  size_t len;
  FILE *f = open_memstream(log, &len);
  if (!f) return CABLE_ERR_ALLOC;
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = sc->dir;
  o.log = f;
  cable_replay *r = cable_replay_alloc(&o);
  int rc = CABLE_ERR_ALLOC;
  if (r) rc = text ? script_run_string("scene.auto", text, cable_replay_host(r), err)
                   : script_run_file(path, cable_replay_host(r), err);
  cable_replay_free(r);
  fclose(f);
  return rc;
}

/* The rest of the k-th (0-based) log line that starts with prefix, or NULL. */
static inline const char *scene_log_line(const char *log, const char *prefix, int k)
{
  for (const char *p = log; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL)
    if (strncmp(p, prefix, strlen(prefix)) == 0 && k-- == 0) return p + strlen(prefix);
  return NULL;
}

/* The first log line containing text, or NULL. */
static inline const char *scene_log_find(const char *log, const char *text)
{
  return log ? strstr(log, text) : NULL;
}

#endif
