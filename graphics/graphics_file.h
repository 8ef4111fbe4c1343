/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Pictures written through the one atomic-file module (continuation/base/atomic_file.h):
 * everything goes to a temporary file in the destination's directory, renamed
 * over the destination only when the whole file was written, so a reader
 * never sees a half-written picture and a failed call leaves an existing
 * file untouched.  This file only adapts cairo's stream writer to it. */
#ifndef CABLE_GRAPHICS_FILE_H
#define CABLE_GRAPHICS_FILE_H

#include <cairo/cairo.h>

#include "atomic_file.h"

/* cairo stream writer; the closure is a cable_atomic_file. */
cairo_status_t graphics_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length);
/* Write an image surface as PNG to path, atomically.  CABLE_SUCCESS or
 * CABLE_ERR_IO. */
int graphics_file_write_png(cairo_surface_t *surface, const char *path);
/* The same with a one-line caption (no newline, at most GRAPHICS_CAPTION_MAX
 * bytes, else CABLE_ERR_INPUT and nothing written) in a tEXt chunk with the
 * keyword "Description" (PNG 1.2, 11.3.4.2) right after IHDR; NULL or "": none. */
#define GRAPHICS_CAPTION_MAX 2000
int graphics_file_write_png_caption(cairo_surface_t *surface, const char *path, const char *caption);

#endif
