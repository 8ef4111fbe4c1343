/* Atomic output files for pictures and exports: everything is written to a
 * temporary file in the destination's directory and renamed over the
 * destination only when the whole file was written, so a reader never sees a
 * half-written picture and a failed call leaves an existing file untouched. */
#ifndef CABLE_GRAPHICS_FILE_H
#define CABLE_GRAPHICS_FILE_H

#include <stdio.h>

#include <cairo/cairo.h>

typedef struct graphics_file graphics_file;

/* Create the temporary file "<path>.tmpXXXXXX".  NULL when path is NULL or
 * empty, or the directory is not writable (errno tells why). */
graphics_file *graphics_file_open(const char *path);
/* The stream to write to (never NULL for an open file). */
FILE *graphics_file_stream(graphics_file *f);
/* Flush, close and rename over the destination; frees f.  Returns
 * CABLE_SUCCESS, or CABLE_ERR_IO (the temporary file is removed) when any
 * write, the close or the rename failed. */
int graphics_file_commit(graphics_file *f);
/* Close and remove the temporary file; frees f.  NULL is a no-op. */
void graphics_file_abort(graphics_file *f);

/* cairo stream writer; the closure is a graphics_file. */
cairo_status_t graphics_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length);
/* Write an image surface as PNG to path, atomically.  CABLE_SUCCESS or
 * CABLE_ERR_IO. */
int graphics_file_write_png(cairo_surface_t *surface, const char *path);

#endif
