/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A run's b./s./d.NAME on disk as it is computed: generations published by
 * one rename, the lock of NAME, a killed writer's leftovers (live_files.h). */
#include "live_files.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "atomic_file.h"
#include "aufile_live.h"
#include "cable/cable_status.h"

#define WORK_PREFIX ".cable-"   /* the work directory .cable-NAME beside the files */
#define LIVE_PATH 4400
#define GEN_DIRS 3              /* generation K is written in .cable-NAME/g(K mod 3): the current
                                   one and the one before stay whole for a reader that has just
                                   resolved the links */
#define SYNC_EVERY 1.0          /* seconds: a generation is synced to disk at most this often
                                   (every one is whole for readers and after a kill) */
/* the longest name written beside b.NAME: ".b.NAME.NNNN.csv.ckptXXXXXX" */
#define NAME_EXTRA ((int)sizeof ".b..9999.csv.ckptXXXXXX" - 1)
/* the d-file copy of a step ends with this line; a finished run's d-file has none */
#define LIVE_NOTE \
  " NOTE: cable was still computing this run when these files were written; the points above are complete\n"

static const char *const kinds[3] = {"s", "b", "d"};   /* s first: a restart reads s */

int rp_out_name_check(const char *key, const char *name, cable_error *err)
{
  size_t n = name ? strlen(name) : 0;
  if (n == 0) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key, "the output name is empty");
  for (const char *p = name; *p; p++)
    if (*p == '/' || (unsigned char)*p < 0x20 || *p == 0x7f)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key,
                             "'%.80s%s' is not a plain file name (no '/' or control characters: the files are "
                             "b.NAME, s.NAME, d.NAME in the run's directory)", name, n > 80 ? "..." : "");
  if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key, "'%s' is not a file name", name);
  if ((int)n > NAME_MAX - NAME_EXTRA)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key,
                           "the output name has %zu characters, at most %d fit (its files' temporary names "
                           "must stay within the file system's %d)", n, NAME_MAX - NAME_EXTRA, NAME_MAX);
  return 0;
}

/* ---- paths ---------------------------------------------------------------------- */

/* dir/leaf; paths longer than the buffers are refused by the open that
 * gets the truncated name (it names no existing file of ours) */
static void join(char *out, size_t len, const char *dir, const char *leaf)
{
  int n = dir && dir[0] ? snprintf(out, len, "%s/%s", dir, leaf) : snprintf(out, len, "%s", leaf);
  if (n < 0 || (size_t)n >= len) out[0] = '\0';
}

struct rp_lock {
  int fd;
  char dir[LIVE_PATH];    /* the files' directory ("" : the current one) */
  char name[NAME_MAX + 1];
  char work[LIVE_PATH];   /* dir/.cable-NAME */
};

/* dir/KIND.NAME */
static void file_path(const rp_lock *l, const char *kind, char *out, size_t len)
{
  char leaf[NAME_MAX + 8];
  snprintf(leaf, sizeof leaf, "%s.%s", kind, l->name);
  join(out, len, l->dir, leaf);
}

/* What KIND.NAME links to while a run writes it (relative to dir). */
static void link_target(const rp_lock *l, const char *kind, char *out, size_t len)
{
  snprintf(out, len, "%s%s/cur/%s", WORK_PREFIX, l->name, kind);
}

static int is_our_link(const rp_lock *l, const char *kind)
{
  char p[LIVE_PATH], want[LIVE_PATH], got[LIVE_PATH];
  file_path(l, kind, p, sizeof p);
  link_target(l, kind, want, sizeof want);
  ssize_t n = readlink(p, got, sizeof got - 1);
  if (n < 0) return 0;
  got[n] = '\0';
  return strcmp(got, want) == 0;
}

static void remove_tree(const char *path)
{
  DIR *d = opendir(path);
  if (!d) {
    unlink(path);
    return;
  }
  struct dirent *e;
  char p[LIVE_PATH + NAME_MAX + 2];
  while ((e = readdir(d)) != NULL) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    snprintf(p, sizeof p, "%s/%s", path, e->d_name);
    struct stat st;
    if (lstat(p, &st) == 0 && S_ISDIR(st.st_mode)) remove_tree(p);
    else unlink(p);
  }
  closedir(d);
  rmdir(path);
}

/* The generation cur points to (-1: none). */
static int current_gen(const rp_lock *l)
{
  char p[LIVE_PATH + 8], got[64];
  snprintf(p, sizeof p, "%s/cur", l->work);
  ssize_t n = readlink(p, got, sizeof got - 1);
  if (n <= 1 || got[0] != 'g') return -1;
  got[n] = '\0';
  return atoi(got + 1);
}

/* KIND.NAME, a link into the work directory, becomes a plain file with the
 * same contents (or goes, when its target does not exist). */
static void materialize(const rp_lock *l, const char *kind)
{
  char p[LIVE_PATH], src[LIVE_PATH + 16];
  file_path(l, kind, p, sizeof p);
  snprintf(src, sizeof src, "%s/cur/%s", l->work, kind);
  FILE *in = fopen(src, "rb");
  if (!in) {
    unlink(p);
    return;
  }
  cable_error e;
  cable_atomic_file *af = cable_atomic_open(p, 0, &e);
  int ok = af != NULL;
  char buf[65536];
  size_t n;
  while (ok && (n = fread(buf, 1, sizeof buf, in)) > 0) ok = fwrite(buf, 1, n, cable_atomic_stream(af)) == n;
  fclose(in);
  if (ok) cable_atomic_commit(af, &e);   /* a failure leaves the link, which still reads */
  else cable_atomic_abort(af);
}

/* Temporary files of a killed writer of NAME in dir: .KIND.NAME.tmpXXXXXX,
 * .KIND.NAME.ckptXXXXXX and .b.NAME.N.csv.tmpXXXXXX (and .ckpt). */
static int is_leftover(const rp_lock *l, const char *f)
{
  size_t nl = strlen(l->name);
  if (f[0] != '.' || !strchr("bsd", f[1]) || f[2] != '.' || strncmp(f + 3, l->name, nl) != 0) return 0;
  const char *rest = f + 3 + nl;
  if (f[1] == 'b' && rest[0] == '.' && rest[1] >= '0' && rest[1] <= '9') {
    rest++;
    while (*rest >= '0' && *rest <= '9') rest++;
    if (strncmp(rest, ".csv", 4) != 0) return 0;
    rest += 4;
  }
  if (strncmp(rest, ".tmp", 4) == 0) rest += 4;
  else if (strncmp(rest, ".ckpt", 5) == 0) rest += 5;
  else return 0;
  return strlen(rest) == 6;   /* mkstemp's XXXXXX */
}

static void remove_leftovers(const rp_lock *l)
{
  DIR *d = opendir(l->dir[0] ? l->dir : ".");
  if (!d) return;
  struct dirent *e;
  char p[LIVE_PATH + NAME_MAX + 2];
  while ((e = readdir(d)) != NULL)
    if (is_leftover(l, e->d_name)) {
      join(p, sizeof p, l->dir, e->d_name);
      unlink(p);
    }
  closedir(d);
  /* generations no link reads any more */
  int cur = current_gen(l), linked = 0;
  for (int k = 0; k < 3; k++) linked |= is_our_link(l, kinds[k]);
  if (!(d = opendir(l->work))) return;
  while ((e = readdir(d)) != NULL) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    if (linked && (strcmp(e->d_name, "cur") == 0 || (e->d_name[0] == 'g' && atoi(e->d_name + 1) == cur))) continue;
    snprintf(p, sizeof p, "%s/%s", l->work, e->d_name);
    remove_tree(p);
  }
  closedir(d);
}

rp_lock *rp_lock_take(const char *dir, const char *name, FILE *log, cable_error *err)
{
  rp_lock *l = calloc(1, sizeof *l);
  if (!l) {
    cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    return NULL;
  }
  l->fd = -1;
  snprintf(l->dir, sizeof l->dir, "%s", dir ? dir : "");
  snprintf(l->name, sizeof l->name, "%s", name);
  char leaf[NAME_MAX + 16];
  snprintf(leaf, sizeof leaf, "%s%s", WORK_PREFIX, name);
  join(l->work, sizeof l->work, l->dir, leaf);
  int waited = 0;
  for (;;) {
    if (mkdir(l->work, 0755) != 0 && errno != EEXIST) break;
    int fd = open(l->work, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ENOENT) continue;   /* its holder has just removed it */
      break;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      if (errno != EWOULDBLOCK) {
        close(fd);
        break;
      }
      if (!waited && log) {
        fprintf(log, "  waiting: another process is writing b.%s, s.%s, d.%s\n", name, name, name);
        fflush(log);
      }
      waited = 1;
      if (flock(fd, LOCK_EX) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        break;
      }
    }
    /* the holder before us may have removed the directory we locked */
    struct stat a, b;
    if (fstat(fd, &a) == 0 && stat(l->work, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
      l->fd = fd;
      remove_leftovers(l);
      return l;
    }
    close(fd);
  }
  cable_error_set(err, CABLE_ERR_IO, l->work, 0, NULL, "cannot lock the output name %s: %s", name, strerror(errno));
  free(l);
  return NULL;
}

void rp_lock_release(rp_lock *l)
{
  if (!l) return;
  for (int k = 0; k < 3; k++)
    if (is_our_link(l, kinds[k])) materialize(l, kinds[k]);
  remove_tree(l->work);
  if (l->fd >= 0) close(l->fd);   /* unlocks */
  free(l);
}

/* ---- a run's live files ------------------------------------------------------------ */

struct rp_live {
  rp_lock *lock;
  cable_aufile *w;
  cable_sink sink;       /* the writer's */
  int gen;               /* the last published generation */
  int s_changed;         /* a solution since the last publish */
  int published;         /* this run has published a generation */
  double synced_at;      /* when a generation was last synced to disk (monotonic seconds) */
  char files[3 * LIVE_PATH + 8];
};

static int live_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  rp_live *l = ctx;
  l->s_changed = 1;
  return l->sink.solution(l->sink.ctx, pt, sol);
}

static int live_point(void *ctx, const cable_point *pt)
{
  rp_live *l = ctx;
  return l->sink.point(l->sink.ctx, pt);
}

static void live_diag(void *ctx, const char *line)
{
  rp_live *l = ctx;
  l->sink.diag(l->sink.ctx, line);
}

cable_sink rp_live_sink(rp_live *l)
{
  cable_sink s = {l, live_point, live_solution, live_diag};
  return s;
}

const char *rp_live_files(const rp_live *l)
{
  return l ? l->files : "";
}

static double now_seconds(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void sync_path(const char *dir)
{
  int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    (void)fsync(fd);
    close(fd);
  }
}

/* cur -> gN, by one rename (the publish). */
static int set_current(const rp_lock *l, int gen, int sync, cable_error *err)
{
  char tmp[LIVE_PATH + 16], cur[LIVE_PATH + 8], target[32];
  snprintf(tmp, sizeof tmp, "%s/cur.new", l->work);
  snprintf(cur, sizeof cur, "%s/cur", l->work);
  snprintf(target, sizeof target, "g%d", gen);
  unlink(tmp);
  if (symlink(target, tmp) != 0 || rename(tmp, cur) != 0)
    return cable_error_set(err, CABLE_ERR_IO, cur, 0, NULL, "cannot publish the run's files: %s", strerror(errno));
  if (sync) sync_path(l->work);   /* the new link survives a power loss with its files */
  return 0;
}

/* Generation 0: the files as they are before the run (hard links, or copies
 * where the file system has none), then KIND.NAME become links through cur:
 * their contents do not change here. */
static int start_links(rp_live *l, cable_error *err)
{
  rp_lock *k = l->lock;
  char g0[LIVE_PATH + 8], p[LIVE_PATH], q[LIVE_PATH + 16], target[LIVE_PATH], tmp[LIVE_PATH + 16];
  snprintf(g0, sizeof g0, "%s/g0", k->work);
  if (mkdir(g0, 0755) != 0)
    return cable_error_set(err, CABLE_ERR_IO, g0, 0, NULL, "cannot create: %s", strerror(errno));
  for (int i = 0; i < 3; i++) {
    file_path(k, kinds[i], p, sizeof p);
    snprintf(q, sizeof q, "%s/%s", g0, kinds[i]);
    struct stat st;
    if (stat(p, &st) != 0) continue;   /* no such file yet */
    if (link(p, q) != 0) {
      FILE *in = fopen(p, "rb"), *out = in ? fopen(q, "wb") : NULL;
      char buf[65536];
      size_t n;
      int ok = in && out;
      while (ok && (n = fread(buf, 1, sizeof buf, in)) > 0) ok = fwrite(buf, 1, n, out) == n;
      if (in) fclose(in);
      if (out && fclose(out) != 0) ok = 0;
      if (!ok) return cable_error_set(err, CABLE_ERR_IO, p, 0, NULL, "cannot keep the file's contents: %s", strerror(errno));
    }
  }
  int rc = set_current(k, 0, 1, err);
  for (int i = 0; i < 3 && !rc; i++) {
    file_path(k, kinds[i], p, sizeof p);
    link_target(k, kinds[i], target, sizeof target);
    snprintf(tmp, sizeof tmp, "%s.cable-link", p);
    unlink(tmp);
    if (symlink(target, tmp) != 0 || rename(tmp, p) != 0) {
      rc = cable_error_set(err, CABLE_ERR_IO, p, 0, NULL, "cannot link the file for the run: %s", strerror(errno));
      unlink(tmp);
    }
  }
  return rc;
}

rp_live *rp_live_open(const char *dir, const char *name, int append, const cable_constants *c,
                      const cable_names *names, FILE *log, cable_error *err)
{
  if (rp_out_name_check(append ? "ap" : "sv", name, err)) return NULL;
  rp_live *l = calloc(1, sizeof *l);
  if (!l) {
    cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    return NULL;
  }
  if (!(l->lock = rp_lock_take(dir, name, log, err))) {
    free(l);
    return NULL;
  }
  char b[LIVE_PATH], s[LIVE_PATH], d[LIVE_PATH];
  file_path(l->lock, "b", b, sizeof b);
  file_path(l->lock, "s", s, sizeof s);
  file_path(l->lock, "d", d, sizeof d);
  snprintf(l->files, sizeof l->files, "%s, %s, %s", b, s, d);
  cable_aufile_options o;
  cable_aufile_options_init(&o);
  o.append = append;
  o.write_csv = 1;   /* as rp_result_write */
  l->w = cable_aufile_open(dir && dir[0] ? dir : NULL, name, c, names, &o, err);
  l->sink = cable_aufile_sink(l->w);
  int linked = 0;
  for (int k = 0; k < 3; k++) linked |= is_our_link(l->lock, kinds[k]);
  /* a killed writer's links stay as they are until this run's first step */
  if (l->w && !linked && start_links(l, err) != 0) {
    cable_aufile_abort(l->w);
    l->w = NULL;
  }
  if (!l->w) {
    rp_lock_release(l->lock);
    free(l);
    return NULL;
  }
  l->gen = current_gen(l->lock);
  if (l->gen < 0) l->gen = 0;
  return l;
}

/* A new generation of the three files (the d-file's copy followed by note),
 * made current.  Each file is written beside its place and renamed over the
 * file of three generations before (on ext4 a replace-by-rename also orders
 * the data before the rename); sync (or a second since the last) syncs it. */
static int publish(rp_live *l, const char *note, int sync, cable_error *err)
{
  rp_lock *k = l->lock;
  int gen = l->gen + 1, slot = gen % GEN_DIRS, prev = l->gen % GEN_DIRS;
  char g[LIVE_PATH + 16], from[LIVE_PATH + 32], to[LIVE_PATH + 32];
  snprintf(g, sizeof g, "%s/g%d", k->work, slot);
  if (mkdir(g, 0755) != 0 && errno != EEXIST)
    return cable_error_set(err, CABLE_ERR_IO, g, 0, NULL, "cannot create: %s", strerror(errno));
  double now = now_seconds();
  if (now - l->synced_at >= SYNC_EVERY) sync = 1;
  /* s changes only at labelled points: an unchanged s is the previous generation's file */
  int with_s = l->s_changed || !l->published;
  snprintf(to, sizeof to, "%s/s.new", g);
  unlink(to);
  if (!with_s) {
    snprintf(from, sizeof from, "%s/g%d/s", k->work, prev);
    if (link(from, to) != 0) with_s = 1;
  }
  int rc = cable_aufile_snapshot(l->w, g, with_s, note, sync, err);
  static const char *const parts[3] = {"b", "d", "s"};
  for (int i = 0; i < 3 && !rc; i++) {
    snprintf(from, sizeof from, "%s/%s.new", g, parts[i]);
    snprintf(to, sizeof to, "%s/%s", g, parts[i]);
    if (rename(from, to) != 0 && (i < 2 || errno != ENOENT))
      rc = cable_error_set(err, CABLE_ERR_IO, to, 0, NULL, "cannot write: %s", strerror(errno));
  }
  if (!rc && sync) sync_path(g);
  if (!rc) rc = set_current(k, slot, sync, err);
  if (rc) return rc;
  if (sync) l->synced_at = now;
  l->s_changed = 0;
  l->published = 1;
  l->gen = gen;
  return 0;
}

int rp_live_publish(rp_live *l, cable_error *err)
{
  return publish(l, LIVE_NOTE, 0, err);
}

int rp_live_close(rp_live *l, const char *end_note, cable_error *err)
{
  if (end_note && end_note[0]) l->sink.diag(l->sink.ctx, end_note);
  /* the last generation is the final files: the renames below change no contents */
  int rc = publish(l, NULL, 1, err);
  if (rc) {
    cable_aufile_abort(l->w);   /* the links keep the last step that was published */
  } else {
    rc = cable_aufile_close(l->w, err);
  }
  rp_lock_release(l->lock);
  free(l);
  return rc;
}

void rp_live_abort(rp_live *l)
{
  if (!l) return;
  cable_aufile_abort(l->w);
  rp_lock_release(l->lock);   /* generation 0, if nothing was published: the files as before */
  free(l);
}
