/* `cable plot`, `cable render`: pictures from cable's own output files
 * (post-processing only; nothing here runs during continuation). */
#ifndef CABLE_PICTURES_H
#define CABLE_PICTURES_H

#include "cable_error.h"
#include "cable_solution.h"
#include "plot.h"
#include "render.h"

/* Diagram of the branches of b-files (dir/bfiles[i]; dir may be NULL): x and
 * y are column headings (NULL: the principal parameter, and F when present,
 * else L2-NORM); marks are extra annotated points; out's suffix .svg gives
 * SVG, .png PNG, any other is refused (CABLE_ERR_INPUT, nothing written).
 * Regular output points (RG) are not labelled. */
int cable_plot_files(const char *dir, const char *const *bfiles, int nfiles, const char *x, const char *y,
                     const plot_annotation *marks, int nmarks, const char *title, const char *out,
                     cable_error *err);

/* cable plot [x=COL] [y=COL] [o=FILE.png|FILE.svg] [title=TEXT] b.NAME ... */
int cable_cmd_plot(int argc, char **argv, cable_error *err);
/* Picture (out, PNG; NULL: none) and exports (vtp, ply; NULL: none) of a
 * braid solution: both strands as tubes, the contact-pressure profiles along
 * the contact curve (white: strand 1, black: strand 2).  The names must end
 * in .png, .vtp and .ply (CABLE_ERR_INPUT before anything is written). */
int cable_render_solution(const cable_solution *s, const render_options *o, const char *out, const char *vtp,
                          const char *ply, cable_error *err);

/* cable render s.NAME LABEL [o=FILE.png] [view=X,Y,Z] [size=N] [thicken=K]
 *              [color=pressure] [vtp=FILE.vtp] [ply=FILE.ply] */
int cable_cmd_render(int argc, char **argv, cable_error *err);

#endif
