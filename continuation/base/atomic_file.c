/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/sendfile.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_status.h"

#define NEW_FILE_MODE 0644   /* a new output file: rw-r--r--, like AUTO's fort.7 under umask 022 */
#define COPY_CHUNK 65536

struct cable_atomic_file {
  char *path;   /* target */
  char *tmp;    /* temporary file in the same directory (rename is atomic there) */
  FILE *f;
};

/* "dir/.base<tag>XXXXXX" for mkstemp. */
static char *tmp_name(const char *path, const char *tag)
{
  const char *slash = strrchr(path, '/');
  size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
  const char *base = path + dirlen;
  size_t len = dirlen + 1 + strlen(base) + strlen(tag) + 6 + 1;
  char *t = malloc(len);
  if (!t) return NULL;
  memcpy(t, path, dirlen);
  snprintf(t + dirlen, len - dirlen, ".%s%sXXXXXX", base, tag);
  return t;
}

static int copy_stream(FILE *from, FILE *to)
{
  char buf[COPY_CHUNK];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, from)) > 0)
    if (fwrite(buf, 1, n, to) != n) return -1;
  return ferror(from) ? -1 : 0;
}

/* The whole of from (a file just opened, at offset 0) after what to holds:
 * in the kernel (sendfile, no copy through user space: a run's live files
 * copy the growing b-, d- and s-file at every step, auto_iface/files/
 * live_files.c), or through a buffer where the kernel refuses. */
static int copy_file(FILE *from, FILE *to)
{
  if (fflush(to) != 0) return -1;
  int in = fileno(from), out = fileno(to);
  struct stat st;
  if (fstat(in, &st) == 0 && S_ISREG(st.st_mode)) {
    off_t off = 0;
    while (off < st.st_size) {
      ssize_t n = sendfile(out, in, &off, (size_t)(st.st_size - off));
      if (n <= 0) break;
    }
    if (off == st.st_size) return 0;
    /* refused or short: the rest through the buffer, from where it stopped */
    if (off > 0 && (lseek(out, 0, SEEK_END) < 0 || fseeko(from, off, SEEK_SET) != 0)) return -1;
  }
  return copy_stream(from, to);
}

static void sync_dir(const char *path)
{
  /* make the rename durable; best effort (some file systems refuse) */
  const char *slash = strrchr(path, '/');
  char dir[4096];
  if (!slash) {
    snprintf(dir, sizeof dir, ".");
  } else {
    size_t n = (size_t)(slash - path);
    if (n == 0) n = 1;
    if (n >= sizeof dir) return;
    memcpy(dir, path, n);
    dir[n] = '\0';
  }
  int fd = open(dir, O_RDONLY);
  if (fd >= 0) {
    (void)fsync(fd);
    close(fd);
  }
}

/* Open a fresh temporary file next to path with path's mode (or the default). */
static FILE *tmp_create(const char *path, const char *tag, char **name, cable_error *err)
{
  *name = tmp_name(path, tag);
  if (!*name) {
    cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
    return NULL;
  }
  int fd = mkstemp(*name);
  if (fd < 0) {
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot create a temporary file next to it: %s",
                    strerror(errno));
    free(*name);
    *name = NULL;
    return NULL;
  }
  struct stat sb;
  mode_t mode = NEW_FILE_MODE;
  if (stat(path, &sb) == 0) mode = sb.st_mode & 0777;
  (void)fchmod(fd, mode);
  FILE *f = fdopen(fd, "w+b");
  if (!f) {
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "fdopen failed: %s", strerror(errno));
    close(fd);
    unlink(*name);
    free(*name);
    *name = NULL;
  }
  return f;
}

void cable_atomic_abort(cable_atomic_file *af)
{
  if (!af) return;
  if (af->f) fclose(af->f);
  if (af->tmp) unlink(af->tmp);
  free(af->tmp);
  free(af->path);
  free(af);
}

cable_atomic_file *cable_atomic_open(const char *path, int append, cable_error *err)
{
  if (!path || !path[0]) {
    cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "no output file name");
    return NULL;
  }
  cable_atomic_file *af = calloc(1, sizeof *af);
  if (!af || !(af->path = strdup(path))) {
    free(af);
    cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
    return NULL;
  }
  af->f = tmp_create(path, ".tmp", &af->tmp, err);
  if (!af->f) {
    cable_atomic_abort(af);
    return NULL;
  }
  if (append) {
    FILE *old = fopen(path, "rb");
    if (old) {
      int st = copy_stream(old, af->f);
      fclose(old);
      if (st != 0) {
        cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot copy the existing file for appending");
        cable_atomic_abort(af);
        return NULL;
      }
    } else if (errno != ENOENT) {
      cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot read the existing file: %s", strerror(errno));
      cable_atomic_abort(af);
      return NULL;
    }
  }
  return af;
}

FILE *cable_atomic_stream(cable_atomic_file *af)
{
  return af ? af->f : NULL;
}

const char *cable_atomic_path(const cable_atomic_file *af)
{
  return af ? af->path : "";
}

int cable_atomic_checkpoint(cable_atomic_file *af, cable_error *err)
{
  if (!af || !af->f) return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "file is not open");
  if (fflush(af->f) != 0 || ferror(af->f))
    return cable_error_set(err, CABLE_ERR_IO, af->path, 0, "", "write error: %s", strerror(errno));
  char *ck = NULL;
  FILE *out = tmp_create(af->path, ".ckpt", &ck, err);
  if (!out) return err ? err->status : CABLE_ERR_IO;
  FILE *in = fopen(af->tmp, "rb");
  int st = in ? copy_stream(in, out) : -1;
  if (in) fclose(in);
  if (st == 0 && fflush(out) != 0) st = -1;
  if (st == 0 && fsync(fileno(out)) != 0) st = -1;
  if (fclose(out) != 0) st = -1;
  if (st == 0 && rename(ck, af->path) != 0) st = -1;
  if (st != 0) {
    int e = errno;
    unlink(ck);
    free(ck);
    return cable_error_set(err, CABLE_ERR_IO, af->path, 0, "", "checkpoint failed: %s", strerror(e));
  }
  free(ck);
  sync_dir(af->path);
  return 0;
}

int cable_atomic_copy(cable_atomic_file *af, const char *dest, const char *trailer, int sync, cable_error *err)
{
  if (!af || !af->f || !dest) return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "file is not open");
  if (fflush(af->f) != 0 || ferror(af->f))
    return cable_error_set(err, CABLE_ERR_IO, af->path, 0, "", "write error: %s", strerror(errno));
  int fd = open(dest, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, NEW_FILE_MODE);
  if (fd < 0) return cable_error_set(err, CABLE_ERR_IO, dest, 0, "", "cannot create: %s", strerror(errno));
  FILE *out = fdopen(fd, "wb");
  if (!out) {
    close(fd);
    unlink(dest);
    return cable_error_set(err, CABLE_ERR_IO, dest, 0, "", "fdopen failed: %s", strerror(errno));
  }
  FILE *in = fopen(af->tmp, "rb");
  int st = in ? copy_file(in, out) : -1;
  if (in) fclose(in);
  if (st == 0 && trailer && fputs(trailer, out) < 0) st = -1;
  if (st == 0 && fflush(out) != 0) st = -1;
  if (st == 0 && sync && fsync(fileno(out)) != 0) st = -1;
  int e = errno;
  if (fclose(out) != 0 && st == 0) st = -1, e = errno;
  if (st != 0) {
    unlink(dest);
    return cable_error_set(err, CABLE_ERR_IO, dest, 0, "", "cannot write the copy: %s", strerror(e));
  }
  return 0;
}

int cable_atomic_finish(cable_atomic_file *af, cable_error *err)
{
  if (!af) return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "file is not open");
  if (!af->f) return 0;
  int st = 0, e = 0;
  if (ferror(af->f) || fflush(af->f) != 0) st = -1, e = errno;
  if (st == 0 && fsync(fileno(af->f)) != 0) st = -1, e = errno;
  if (fclose(af->f) != 0 && st == 0) st = -1, e = errno;
  af->f = NULL;
  if (st != 0)
    return cable_error_set(err, CABLE_ERR_IO, af->path, 0, "", "cannot write the file: %s",
                           e ? strerror(e) : "write error");
  return 0;
}

int cable_atomic_commit(cable_atomic_file *af, cable_error *err)
{
  if (!af) return cable_error_set(err, CABLE_ERR_INPUT, "", 0, "", "file is not open");
  int st = cable_atomic_finish(af, err), e = 0;
  if (st != 0) {
    cable_atomic_abort(af);
    return st;
  }
  if (rename(af->tmp, af->path) != 0) st = -1, e = errno;
  int status = 0;
  if (st != 0) {
    status = cable_error_set(err, CABLE_ERR_IO, af->path, 0, "", "cannot write the file: %s",
                             e ? strerror(e) : "write error");
  } else {
    free(af->tmp);   /* renamed: nothing to remove */
    af->tmp = NULL;
    sync_dir(af->path);
  }
  cable_atomic_abort(af);
  return status;
}
