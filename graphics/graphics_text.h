/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Text placement helpers for cairo (toy font API, sans-serif). */
#ifndef CABLE_GRAPHICS_TEXT_H
#define CABLE_GRAPHICS_TEXT_H

#include <cairo/cairo.h>

/* Select the sans-serif face at the given size (bold when bold != 0). */
void graphics_text_font(cairo_t *cr, double size, int bold);
/* Draw s so that the point (x, y) sits at fraction (ax, ay) of its ink box:
 * ax = 0 left, 0.5 centre, 1 right; ay = 0 top, 0.5 middle, 1 bottom. */
void graphics_text_show(cairo_t *cr, double x, double y, const char *s, double ax, double ay);
/* Advance width of s in the current font. */
double graphics_text_width(cairo_t *cr, const char *s);
/* Release cairo's static caches and fontconfig's configuration.  cairo's
 * text drops its last references to fontconfig's configuration at exit
 * without freeing it, which valgrind and LeakSanitizer report as definite
 * leaks (cairo 1.16, fontconfig 2.14).  A program that drew text and wants
 * leak-checker-clean runs calls this once, at the very end, after every
 * cairo object is destroyed; no cairo or fontconfig call may follow. */
void graphics_text_cleanup(void);

#endif
