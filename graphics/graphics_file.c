/* Atomic output files: temporary name in the same directory, then rename(2),
 * which POSIX makes atomic within one file system. */
#include "graphics_file.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable_status.h"

/* mkstemp creates files readable by the owner only; pictures and meshes are
 * ordinary documents, so they get the usual rw-r--r--. */
#define GRAPHICS_FILE_MODE 0644

struct graphics_file {
  FILE *stream;
  char *path;   /* destination */
  char *tmp;    /* temporary name, same directory */
};

graphics_file *graphics_file_open(const char *path)
{
  static const char suffix[] = ".tmpXXXXXX";
  if (path == NULL || path[0] == '\0') return NULL;
  graphics_file *f = calloc(1, sizeof *f);
  if (f == NULL) return NULL;
  size_t len = strlen(path);
  f->path = malloc(len + 1);
  f->tmp = malloc(len + sizeof suffix);
  if (f->path == NULL || f->tmp == NULL) goto fail;
  memcpy(f->path, path, len + 1);
  memcpy(f->tmp, path, len);
  memcpy(f->tmp + len, suffix, sizeof suffix);
  int fd = mkstemp(f->tmp);
  if (fd < 0) goto fail;
  if (fchmod(fd, GRAPHICS_FILE_MODE) != 0 || (f->stream = fdopen(fd, "wb")) == NULL) {
    close(fd);
    unlink(f->tmp);
    goto fail;
  }
  return f;
fail:
  free(f->path);
  free(f->tmp);
  free(f);
  return NULL;
}

FILE *graphics_file_stream(graphics_file *f)
{
  return f->stream;
}

static void graphics_file_release(graphics_file *f)
{
  free(f->path);
  free(f->tmp);
  free(f);
}

int graphics_file_commit(graphics_file *f)
{
  if (f == NULL) return CABLE_ERR_IO;
  int bad = fflush(f->stream) != 0 || ferror(f->stream);
  bad |= fclose(f->stream) != 0;
  if (!bad) bad = rename(f->tmp, f->path) != 0;
  if (bad) unlink(f->tmp);
  graphics_file_release(f);
  return bad ? CABLE_ERR_IO : CABLE_SUCCESS;
}

void graphics_file_abort(graphics_file *f)
{
  if (f == NULL) return;
  fclose(f->stream);
  unlink(f->tmp);
  graphics_file_release(f);
}

cairo_status_t graphics_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length)
{
  graphics_file *f = closure;
  return fwrite(data, 1, length, f->stream) == length ? CAIRO_STATUS_SUCCESS
                                                      : CAIRO_STATUS_WRITE_ERROR;
}

int graphics_file_write_png(cairo_surface_t *surface, const char *path)
{
  graphics_file *f = graphics_file_open(path);
  if (f == NULL) return CABLE_ERR_IO;
  if (cairo_surface_write_to_png_stream(surface, graphics_file_cairo_write, f)
      != CAIRO_STATUS_SUCCESS) {
    graphics_file_abort(f);
    return CABLE_ERR_IO;
  }
  return graphics_file_commit(f);
}
