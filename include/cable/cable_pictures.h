/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Pictures from cable's own output files: bifurcation diagrams of b-files and
 * 3-D renders of braid solutions (post-processing only; nothing here runs
 * during continuation).  The command-line `cable plot` and `cable render`
 * are built on these. */
#ifndef CABLE_PICTURES_H
#define CABLE_PICTURES_H

#include "cable/cable_api.h"
#include "cable/cable_error.h"
#include "cable/cable_solution.h"

/* Extra marks at arbitrary data points, e.g. Fig. 12.2's "(a)".."(d)". */
typedef struct {
  double x, y;
  const char *text;   /* NULL -> no text */
  int filled;         /* 1: filled black circle, 0: open circle */
} plot_annotation;

enum {
  RENDER_COLORMAP_NONE = 0,       /* one colour per tube (render_tube.rgb) */
  RENDER_COLORMAP_SEQUENTIAL = 1, /* viridis over [min, max] of the scalars */
  RENDER_COLORMAP_DIVERGING = 2   /* blue-white-red over [-m, m], m = max |scalar| */
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
} render_options;

/* Diagram of the branches of b-files (dir/bfiles[i]; dir may be NULL): x and
 * y are column headings (NULL: the principal parameter, and F when present,
 * else L2-NORM); marks are extra annotated points; out's suffix .svg gives
 * SVG, .png PNG, any other is refused (CABLE_ERR_INPUT, nothing written).
 * Regular output points (RG) are not labelled. */
CABLE_API int cable_plot_files(const char *dir, const char *const *bfiles, int nfiles, const char *x, const char *y,
                     const plot_annotation *marks, int nmarks, const char *title, const char *out,
                     cable_error *err);

/* Picture (out, PNG; NULL: none) and exports (vtp, ply; NULL: none) of a
 * braid solution: both strands as tubes, the contact-pressure profiles along
 * the contact curve (white: strand 1, black: strand 2).  The names must end
 * in .png, .vtp and .ply (CABLE_ERR_INPUT before anything is written). */
CABLE_API int cable_render_solution(const cable_solution *s, const render_options *o, const char *out, const char *vtp,
                          const char *ply, cable_error *err);

/* The strands of a braid solution at its mesh points, as the pictures and
 * the HTML view (cable view) draw them: centre lines r1, r2 = r1 + Delta d1
 * [3n], the contact pressures p1, p2 [n] on strand 1 and 2, the tube radius
 * Delta/2 and closed = 1 for a link (each strand closes on itself), 0 for a
 * knot (the two strands join end to end).  The arrays are the caller's:
 * cable_strands_free releases them (also after a failed call). */
typedef struct {
  int n, closed;
  double radius;
  double *r1, *r2, *p1, *p2;
} cable_strands;

CABLE_API int cable_solution_strands(const cable_solution *s, cable_strands *out);
CABLE_API void cable_strands_free(cable_strands *st);

/* Release cairo's and fontconfig's process-wide caches once, at the very
 * end of a program that drew text (so that leak checkers stay quiet); no
 * picture may be drawn afterwards. */
CABLE_API void cable_pictures_cleanup(void);

#endif
