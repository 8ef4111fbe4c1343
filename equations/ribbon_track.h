/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Lk of the braid ribbon along a branch (doc/geometry.md, "Lk along a
 * branch"): the first point gets the full computation (braid_ribbon_compute),
 * every later one the update from the previous point by Fuller's integral and
 * the counted axis passages (ribbon_fuller.h); Tw is integrated at every
 * point (O(ntst) point evaluations).  An update falls back to the full
 * computation when its premises fail: the two solutions close differently
 * (knot, link) or not at all, their tangents come near antiparallel
 * (T_A . T_B < RIBBON_TRACK_MIN_DOT somewhere), or its Lk misses the integer
 * (link) or half-integer (knot) by RIBBON_TRACK_DRIFT more than the last
 * full computation did.  The update is exact for the interpolated curves
 * (Fuller's integral includes the geodesic arcs across the tangent's jumps
 * at mesh points), but the full Lk and the updated one carry different
 * discretisation errors (1e-7 per step at NTST 40, doc/geometry.md): the
 * drift bound keeps the reported Lk within about RIBBON_TRACK_DRIFT of a
 * full computation at every point. */
#ifndef CABLE_RIBBON_TRACK_H
#define CABLE_RIBBON_TRACK_H

#include "cable/cable_solution.h"

#define RIBBON_TRACK_MIN_DOT 0.0
/* Lk of a closed ribbon is an integer or half-integer; the full computation
 * meets it to 2.3e-5 at worst in the scenes (doc/links.md). */
#define RIBBON_TRACK_DRIFT 1e-5

typedef struct braid_lk_track braid_lk_track;
braid_lk_track *braid_lk_track_alloc(void);
void braid_lk_track_free(braid_lk_track *tr);     /* NULL is a no-op */

typedef struct braid_lk_value {
  double lk, tw, wr;
  double wr_err;       /* the Romberg estimate of the full writhe the chain started from */
  int updated;         /* 1: by the update, 0: by the full computation */
  int net;             /* updated: the signed passage count from the previous point */
} braid_lk_value;

/* Lk, Tw, Wr of sol; sol becomes the next update's start.  0 or a
 * cable_status (the tracker then forgets its start). */
int braid_lk_track_eval(braid_lk_track *tr, const cable_solution *sol, braid_lk_value *out);

#endif
