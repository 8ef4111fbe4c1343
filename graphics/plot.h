/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Bifurcation diagrams (like Fig. 12.2 of the paper): branches as polylines
 * in distinct colours, branch points as filled black circles, labelled
 * points as open circles with their label, nice axes and a legend; PNG or
 * SVG through cairo.  The data come from memory (the b-file reader is
 * elsewhere). */
#ifndef CABLE_PLOT_H
#define CABLE_PLOT_H

#include "cable/cable_graphics.h"   /* the public option types */

typedef struct {
  const char *name;   /* legend entry; NULL -> "branch <index+1>" */
  int n;              /* number of points, >= 1 */
  const double *x, *y;/* [n]; a non-finite point breaks the polyline */
  const int *type;    /* [n] AUTO type codes or NULL: 6 (BP) -> filled circle */
  const int *label;   /* [n] AUTO labels or NULL: label != 0 and type != BP ->
                         open circle with the label number; a BP with a label
                         gets the number beside its filled circle */
  const int *unstable;/* [n] or NULL: 1 at an unstable point (a b-file written with
                         STAB=1, positive PT); a segment with both ends unstable is
                         drawn dashed (doc/stability.md) */
} plot_branch;

enum { PLOT_FORMAT_PNG = 0, PLOT_FORMAT_SVG = 1 };

typedef struct {
  const char *xlabel, *ylabel, *title;  /* NULL -> none */
  int width, height;  /* pixels (PNG) or points (SVG); <= 0 -> 640 x 480 */
  int format;         /* PLOT_FORMAT_PNG or PLOT_FORMAT_SVG */
} plot_options;


#define PLOT_DEFAULT_WIDTH 640
#define PLOT_DEFAULT_HEIGHT 480
/* cairo's image surfaces are limited to 32767 pixels a side; a diagram
 * larger than this is a mistake in the caller. */
#define PLOT_MAX_SIZE 16384

/* Draw the diagram into path (written atomically: a temporary file in the
 * same directory renamed at the end).  Returns CABLE_SUCCESS, CABLE_ERR_INPUT
 * (NULL branches/opt/path, nbranch < 1, a branch with n < 1 or NULL x/y, no
 * finite point at all, unknown format, size too large), CABLE_ERR_IO (the
 * file could not be written; nothing is left behind) or CABLE_ERR_ALLOC. */
int plot_bifurcation(const plot_branch *branches, int nbranch, const plot_options *opt,
                     const char *path);
/* The same with extra marks (annot may be NULL when nannot == 0). */
int plot_bifurcation_annotated(const plot_branch *branches, int nbranch,
                               const cable_plot_annotation *annot, int nannot,
                               const plot_options *opt, const char *path);

/* The same with a caption: one line (no newline, at most 2000 bytes) that a
 * PNG carries in a tEXt chunk with the keyword "Description" (an SVG: none). */
int plot_bifurcation_captioned(const plot_branch *branches, int nbranch, const cable_plot_annotation *annot, int nannot,
                               const plot_options *opt, const char *caption, const char *path);
/* The colour of branch i (a fixed palette, repeated after 10 branches). */
void plot_branch_color(int i, double rgb[3]);

#endif
