/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Pictures from cable's own output files: bifurcation diagrams of b-files and
 * 3-D renders of braid solutions (post-processing only; nothing here runs
 * during continuation).  The command-line `cable plot` and `cable render`
 * are built on these. */
#ifndef CABLE_PICTURES_H
#define CABLE_PICTURES_H

#include "cable/cable_api.h"
#include "cable/cable_error.h"
#include "cable/cable_graphics.h"   /* the option types: plot marks, render options */
#include "cable/cable_solution.h"

/* Diagram of the branches of b-files (dir/bfiles[i]; dir may be NULL): x and
 * y are column headings (NULL: the principal parameter, and F when present,
 * else L2-NORM); marks are extra annotated points; out's suffix .svg gives
 * SVG, .png PNG, any other is refused (CABLE_ERR_INPUT, nothing written).
 * Regular output points (RG) are not labelled. */
CABLE_API int cable_plot_files(const char *dir, const char *const *bfiles, int nfiles, const char *x, const char *y,
                     const cable_plot_annotation *marks, int nmarks, const char *title, const char *out,
                     cable_error *err);

/* Picture (out, PNG; NULL: none) and exports (vtp, ply; NULL: none) of a
 * braid solution: both strands as tubes, the contact-pressure profiles along
 * the contact curve (white: strand 1, black: strand 2).  The names must end
 * in .png, .vtp and .ply (CABLE_ERR_INPUT before anything is written). */
CABLE_API int cable_render_solution(const cable_solution *s, const cable_render_options *o, const char *out,
                                    const char *vtp, const char *ply, cable_error *err);

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
