/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "graphics_file.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"

cairo_status_t graphics_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length)
{
  FILE *f = cable_atomic_stream(closure);
  return f && fwrite(data, 1, length, f) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* cairo's PNG bytes in memory, to insert the caption chunk after IHDR. */
typedef struct {
  unsigned char *data;
  size_t n, cap;
} png_buffer;

static cairo_status_t png_buffer_write(void *closure, const unsigned char *data, unsigned int length)
{
  png_buffer *b = closure;
  if (b->n + length > b->cap) {
    size_t cap = b->cap ? b->cap : 65536;
    while (cap < b->n + length) cap *= 2;
    unsigned char *d = realloc(b->data, cap);
    if (!d) return CAIRO_STATUS_NO_MEMORY;
    b->data = d;
    b->cap = cap;
  }
  memcpy(b->data + b->n, data, length);
  b->n += length;
  return CAIRO_STATUS_SUCCESS;
}

/* The CRC-32 of the PNG specification (ISO 3309, polynomial 0xedb88320),
 * bit by bit: a caption chunk is a few hundred bytes. */
static uint32_t png_crc(uint32_t crc, const unsigned char *p, size_t n)
{
  for (size_t i = 0; i < n; i++) {
    crc ^= p[i];
    for (int k = 0; k < 8; k++) crc = crc & 1u ? 0xedb88320u ^ (crc >> 1) : crc >> 1;
  }
  return crc;
}

static void put_be32(unsigned char *p, uint32_t v)
{
  p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16), p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}

/* A tEXt chunk "Description\0caption" (Latin-1 text; the captions are ASCII). */
static int write_text_chunk(FILE *f, const char *caption)
{
  static const char key[] = "Description";
  size_t nk = sizeof key, nc = strlen(caption), len = nk + nc;
  unsigned char head[8], crc[4];
  put_be32(head, (uint32_t)len);
  memcpy(head + 4, "tEXt", 4);
  uint32_t c = png_crc(0xffffffffu, head + 4, 4);
  c = png_crc(c, (const unsigned char *)key, nk);
  c = png_crc(c, (const unsigned char *)caption, nc);
  put_be32(crc, c ^ 0xffffffffu);
  return fwrite(head, 1, 8, f) == 8 && fwrite(key, 1, nk, f) == nk && fwrite(caption, 1, nc, f) == nc &&
                 fwrite(crc, 1, 4, f) == 4
             ? 0
             : -1;
}

/* PNG signature (8 bytes) and IHDR (4 length + 4 type + 13 data + 4 CRC):
 * the caption goes right after them, where readers look first. */
#define PNG_HEAD_BYTES 33

int graphics_file_write_png_caption(cairo_surface_t *surface, const char *path, const char *caption)
{
  if (caption && (strlen(caption) > GRAPHICS_CAPTION_MAX || strchr(caption, '\n'))) return CABLE_ERR_INPUT;
  png_buffer b = {NULL, 0, 0};
  if (cairo_surface_write_to_png_stream(surface, png_buffer_write, &b) != CAIRO_STATUS_SUCCESS ||
      b.n < PNG_HEAD_BYTES || memcmp(b.data + 12, "IHDR", 4) != 0) {
    free(b.data);
    return CABLE_ERR_IO;
  }
  cable_atomic_file *f = cable_atomic_open(path, 0, NULL);
  if (f == NULL) {
    free(b.data);
    return CABLE_ERR_IO;
  }
  FILE *s = cable_atomic_stream(f);
  int bad = !s || fwrite(b.data, 1, PNG_HEAD_BYTES, s) != PNG_HEAD_BYTES ||
            (caption && caption[0] && write_text_chunk(s, caption) != 0) ||
            fwrite(b.data + PNG_HEAD_BYTES, 1, b.n - PNG_HEAD_BYTES, s) != b.n - PNG_HEAD_BYTES;
  free(b.data);
  if (bad) {
    cable_atomic_abort(f);
    return CABLE_ERR_IO;
  }
  return cable_atomic_commit(f, NULL) == 0 ? CABLE_SUCCESS : CABLE_ERR_IO;
}

int graphics_file_write_png(cairo_surface_t *surface, const char *path)
{
  return graphics_file_write_png_caption(surface, path, NULL);
}
