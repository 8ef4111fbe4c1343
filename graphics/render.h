/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Shaded 3-D pictures of tubes around space curves (the strands of a cable
 * knot or link, Figs. 12.3-12.9 of the paper), with the contact-pressure
 * profile drawn along the contact curve.  A software z-buffer (2 x 2
 * supersampled) with Lambert + Blinn-Phong lighting, orthographic view,
 * written as PNG through cairo. */
#ifndef CABLE_RENDER_H
#define CABLE_RENDER_H

#include "cable/cable_graphics.h"   /* the public option types */

typedef struct {
  int n;                 /* centreline points, >= 2 */
  const double *xyz;     /* [3n] centreline */
  const double *scalar;  /* [n] or NULL (e.g. the contact pressure) */
  double radius;         /* tube radius (Delta / 2 for touching strands), > 0 */
  double rgb[3];         /* strand colour, components in [0, 1] */
  int closed;            /* 1: the last point joins the first (a repeated
                            first point at the end is recognised and dropped) */
} render_tube;

/* A curve drawn as a flat-coloured line, e.g. the contact-pressure profile:
 * point i is drawn at the projection of xyz[i] moved by value[i] * scale
 * (world length) across the curve in the picture plane, i.e. along the
 * screen-space normal of the projected curve, so that the profile reads as a
 * graph over the contact curve from any view.  Colour rgb_pos where
 * value >= 0, rgb_neg where value < 0; each line gets a thin outline of the
 * contrasting grey so that white and black profiles show on any surface.
 * The profile is depth-tested with a bias of two drawn tube radii towards
 * the viewer: it shows over the strands it lies between but is hidden by
 * other parts of the knot passing in front. */
typedef struct {
  const double *xyz;     /* [3n] */
  const double *value;   /* [n] */
  int n;                 /* >= 2 */
  double rgb_pos[3], rgb_neg[3];
  double scale;          /* world length per unit of value */
  const double *toward;  /* [3n] or NULL: point i is moved by value * scale
                            in 3-D towards toward[i] (e.g. the centre line of
                            the strand the pressure acts on), then projected;
                            NULL: across the projected curve, to its left */
} render_profile;


#define RENDER_DEFAULT_SIZE 600
/* A tube drawn narrower than this many pixels in radius breaks up into
 * dashes after supersampling; automatic thickening keeps it at this size. */
#define RENDER_MIN_RADIUS_PX 1.5
/* The supersampled buffer takes 7 bytes per sample, 4 samples per pixel:
 * 4096 x 4096 pixels need 470 MB, the most a workstation should be asked. */
#define RENDER_MAX_SIZE 4096
/* Samples per pixel along each axis (anti-aliasing). */
#define RENDER_SUPERSAMPLE 2

/* The view that render_tubes_png uses. */
typedef struct {
  double right[3], up[3], view[3]; /* orthonormal, right x up = -view */
  double centre[3];                /* world point drawn at (cx, cy) */
  double scale;                    /* pixels per unit length */
  double cx, cy;                   /* image position of centre (pixels, y down) */
  double thicken;                  /* factor applied to every radius */
  int width, height;               /* image size */
  int plot_width;                  /* width left of the colour bar */
} render_camera;

/* Fit the view: the drawn tubes fill the picture (left of the colour bar)
 * less a margin.  CABLE_SUCCESS or CABLE_ERR_INPUT. */
int render_camera_fit(const render_tube *tubes, int ntube, const cable_render_options *opt,
                      render_camera *cam);
/* Image position (x right, y down, pixels) and depth (world length along
 * the view direction; larger is farther) of world point p. */
void render_camera_project(const render_camera *cam, const double p[3], double *x, double *y,
                           double *depth);

/* Render into path (PNG, written atomically).  profiles may be NULL when
 * nprof == 0; opt NULL means all defaults.  Returns CABLE_SUCCESS,
 * CABLE_ERR_INPUT (NULL or non-finite data, n < 2, radius <= 0, ntube < 1,
 * bad sizes), CABLE_ERR_IO (path not writable; nothing is left behind) or
 * CABLE_ERR_ALLOC. */
int render_tubes_png(const render_tube *tubes, int ntube, const render_profile *profiles,
                     int nprof, const cable_render_options *opt, const char *path);

/* Texts of a picture: the colour bar's title (drawn above the bar when a
 * colour map is on) and a one-line caption that the PNG carries in a tEXt
 * chunk with the keyword "Description" (no newline, at most 2000 bytes).
 * NULL: none. */
typedef struct {
  const char *caption;
  const char *colorbar_title;
} render_text;

/* render_tubes_png with texts (text NULL: none). */
int render_tubes_png_text(const render_tube *tubes, int ntube, const render_profile *profiles, int nprof,
                          const cable_render_options *opt, const render_text *text, const char *path);

#endif
