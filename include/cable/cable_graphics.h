/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The graphics layer's own public types (graphics/): the marks a diagram
 * carries and the options of a 3-D picture.  The picture functions
 * (cable/cable_pictures.h) take them; the graphics folder needs nothing
 * above itself to know them. */
#ifndef CABLE_GRAPHICS_H
#define CABLE_GRAPHICS_H

/* Extra marks at arbitrary data points, e.g. Fig. 12.2's "(a)".."(d)". */
typedef struct {
  double x, y;
  const char *text;   /* NULL -> no text */
  int filled;         /* 1: filled black circle, 0: open circle */
} cable_plot_annotation;

enum {
  CABLE_RENDER_COLORMAP_NONE = 0,       /* one colour per tube (render_tube.rgb) */
  CABLE_RENDER_COLORMAP_SEQUENTIAL = 1, /* viridis over [min, max] of the scalars */
  CABLE_RENDER_COLORMAP_DIVERGING = 2   /* blue-white-red over [-m, m], m = max |scalar| */
};

typedef struct {
  int width, height;     /* pixels; <= 0 -> 600 */
  double view_dir[3];    /* direction the camera looks along; zero -> the
                            direction of least extent of the centreline points
                            (the knot is seen "from above") */
  double up[3];          /* picture's up direction; zero (or parallel to the
                            view) -> world z, or world y when looking along z */
  int colormap;          /* RENDER_COLORMAP_*: colour tubes that have a scalar
                            and draw a colour bar on the right */
  double thicken;        /* draw radius * thicken; <= 0 -> automatic: thin
                            tubes are widened to RENDER_MIN_RADIUS_PX pixels */
} cable_render_options;

#endif
