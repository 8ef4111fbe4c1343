/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "ribbon_track.h"

#include <math.h>
#include <stdlib.h>

#include "braid_geometry.h"
#include "cable/cable_analysis.h"
#include "cable/cable_status.h"
#include "ribbon.h"
#include "ribbon_fuller.h"

struct braid_lk_track {
  cable_solution *prev;   /* copy of the last point (NULL: none yet) */
  double wr, wr_err;      /* its writhe, the chain's error estimate */
  double full_defect;     /* distance of the last full Lk from its (half-)integer */
  int closure;            /* its closure: -1 knot, +1 link */
};

braid_lk_track *braid_lk_track_alloc(void) { return calloc(1, sizeof(braid_lk_track)); }

void braid_lk_track_free(braid_lk_track *tr)
{
  if (!tr) return;
  cable_solution_free(tr->prev);
  free(tr);
}

/* The copy of sol kept for the next update (reallocated when the sizes change). */
static int keep(braid_lk_track *tr, const cable_solution *sol)
{
  cable_solution *p = tr->prev;
  if (p && (p->ndim != sol->ndim || p->ntst != sol->ntst || p->ncol != sol->ncol || p->npar != sol->npar ||
            p->nfpr != sol->nfpr)) {
    cable_solution_free(p);
    p = tr->prev = NULL;
  }
  if (!p && !(p = tr->prev = cable_solution_alloc(sol->ndim, sol->ntst, sol->ncol, sol->npar, sol->nfpr)))
    return CABLE_ERR_ALLOC;
  /* only t, u and par are read; the tangent may be absent */
  for (int i = 0; i < cable_solution_npts(sol); i++) p->t[i] = sol->t[i];
  for (size_t i = 0; i < (size_t)cable_solution_npts(sol) * (size_t)sol->ndim; i++) p->u[i] = sol->u[i];
  for (int k = 0; k < sol->npar; k++) p->par[k] = sol->par[k];
  return CABLE_SUCCESS;
}

/* -1 knot (d1(1) = -d1(0)), +1 link, 0 neither. */
static int closure_of(const cable_solution *sol)
{
  braid_point p0, p1;
  if (braid_point_eval(sol, sol->t[0], NULL, &p0) ||
      braid_point_eval(sol, sol->t[cable_solution_npts(sol) - 1], NULL, &p1))
    return 0;
  double d = p0.d1[0] * p1.d1[0] + p0.d1[1] * p1.d1[1] + p0.d1[2] * p1.d1[2];
  return d < -0.5 ? -1 : (d > 0.5 ? 1 : 0);
}

static double defect(double lk, int closure)
{
  return closure < 0 ? fabs(lk - (floor(lk) + 0.5)) : fabs(lk - round(lk));
}

/* The update from tr->prev; 1 when its premises failed (use the full computation). */
static int update(braid_lk_track *tr, const cable_solution *sol, int closure, braid_lk_value *out, int *rc)
{
  const cable_solution *a = tr->prev;
  if (!a || closure == 0 || closure != tr->closure) return 1;
  double tw, dwr, mind;
  cable_axis_passages ap;
  if ((*rc = braid_ribbon_twist(sol, &tw)) != CABLE_SUCCESS) return 0;
  if ((*rc = braid_writhe_change(a, sol, &dwr, &mind)) != CABLE_SUCCESS) return 0;
  if (mind < RIBBON_TRACK_MIN_DOT) return 1;
  if ((*rc = cable_braid_axis_passages(a, sol, &ap)) != CABLE_SUCCESS) return 0;
  double wr = tr->wr + dwr + 2.0 * RIBBON_PASSAGE_WR_SIGN * ap.net;
  if (defect(tw + wr, closure) > tr->full_defect + RIBBON_TRACK_DRIFT) return 1;
  *out = (braid_lk_value){tw + wr, tw, wr, tr->wr_err, 1, ap.net};
  return 0;
}

int braid_lk_track_eval(braid_lk_track *tr, const cable_solution *sol, braid_lk_value *out)
{
  if (!tr || !sol || !out) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(sol);
  int closure = rc ? 0 : closure_of(sol);
  if (!rc && update(tr, sol, closure, out, &rc) && !rc) {
    braid_ribbon rb;
    rc = braid_ribbon_compute(sol, 0, &rb);
    if (!rc) *out = (braid_lk_value){rb.lk, rb.tw, rb.wr, rb.wr_err, 0, 0};
    if (!rc) tr->full_defect = defect(rb.lk, closure);
  }
  if (!rc) rc = keep(tr, sol);
  if (rc) {
    cable_solution_free(tr->prev);
    tr->prev = NULL;
    return rc;
  }
  tr->wr = out->wr;
  tr->wr_err = out->wr_err;
  tr->closure = closure;
  return CABLE_SUCCESS;
}
