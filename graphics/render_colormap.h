/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Colour maps for scalars on tubes, and the colour bar beside the picture. */
#ifndef CABLE_RENDER_COLORMAP_H
#define CABLE_RENDER_COLORMAP_H

#include <cairo/cairo.h>

/* Colour of u in [0, 1] (clamped) for map CABLE_RENDER_COLORMAP_SEQUENTIAL or
 * CABLE_RENDER_COLORMAP_DIVERGING. */
void render_colormap_eval(int map, double u, double rgb[3]);
/* The range mapped to [0, 1]: [min, max] (sequential) or [-m, m] with
 * m = max |value| (diverging); widened when it has zero width. */
void render_colormap_range(int map, double vmin, double vmax, double *lo, double *hi);
/* Width in pixels reserved for the colour bar and its labels. */
int render_colorbar_width(int width, int height);
/* Draw the bar for [lo, hi] in the strip x >= x0 of a width x height picture. */
void render_colorbar_draw(cairo_t *cr, int map, double lo, double hi, double x0, int width,
                          int height, const char *title);

#endif
