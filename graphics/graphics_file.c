#include "graphics_file.h"

#include "cable/cable_status.h"

cairo_status_t graphics_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length)
{
  FILE *f = cable_atomic_stream(closure);
  return f && fwrite(data, 1, length, f) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

int graphics_file_write_png(cairo_surface_t *surface, const char *path)
{
  cable_atomic_file *f = cable_atomic_open(path, 0, NULL);
  if (f == NULL) return CABLE_ERR_IO;
  if (cairo_surface_write_to_png_stream(surface, graphics_file_cairo_write, f) != CAIRO_STATUS_SUCCESS) {
    cable_atomic_abort(f);
    return CABLE_ERR_IO;
  }
  return cable_atomic_commit(f, NULL) == 0 ? CABLE_SUCCESS : CABLE_ERR_IO;
}
