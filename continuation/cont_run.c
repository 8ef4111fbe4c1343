/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Starting a branch and the driver loop that hands points to a sink. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_fold.h"
#include "cable/cable_stability.h"
#include "cont_impl.h"

int cont_set_mesh(cable_cont *cc, const double *mesh)
{
  if (!cc || !mesh) return CABLE_ERR_NULL;
  if (cc->ended) return cc->end_status;
  /* the mesh of a STPNT start: once a start is set its solution lives on the
     old mesh, so a new one now would silently change the problem */
  if (cc->have_start || cc->npt > 0) {
    cont_set_error(cc, "cable_cont_set_mesh after cable_cont_set_start: set the mesh first");
    return CABLE_ERR_STATE;
  }
  int nt = cc->sys->ntst;
  int ok = mesh[0] == 0.0 && mesh[nt] == 1.0;
  for (int j = 0; j < nt && ok; j++) ok = mesh[j + 1] > mesh[j];
  if (!ok) {
    cont_set_error(cc, "the mesh must increase from 0 to 1 in NTST = %d intervals", nt);
    return CABLE_ERR_INPUT;
  }
  memcpy(cc->sys->mesh, mesh, (size_t)(nt + 1) * sizeof *mesh);
  return CABLE_SUCCESS;
}

int cont_set_start(cable_cont *cc, const cable_solution *start)
{
  if (!cc) return CABLE_ERR_NULL;
  if (cc->ended) return cc->end_status;
  cc->have_start = 0;
  colloc_system *s = cc->sys;
  int rc;
  memset(cc->xdot, 0, (size_t)cc->n * sizeof *cc->xdot);
  if (!start) {
    if (!cc->pb->stpnt) {
      cont_set_error(cc, "problem '%s' has no STPNT: give a restart label (IRS)", cc->pb->name);
      return CABLE_ERR_INPUT;
    }
    double *t = cc->w1; /* npts <= n */
    colloc_system_times(s, t);
    int npts = s->ntst * s->ncol + 1;
    for (int k = 0; k < npts; k++) {
      rc = cc->pb->stpnt(cc->ndim, t[k], cc->x + (size_t)k * (size_t)cc->ndim, s->par, cc->pb->params);
      if (rc != 0) {
        cont_set_error(cc, "STPNT failed (status %d) at t = %g", rc, t[k]);
        return CABLE_ERR_CALLBACK;
      }
    }
    cc->restart = 0;
    cc->loop.start_lab = 0;
  } else {
    if ((rc = cont_load_solution(cc, start)) != CABLE_SUCCESS) return rc;
    cc->restart = 1;
    cc->loop.start_lab = start->lab;
    if (cc->c->isw == -1) {
      if (start->itp % 10 != CABLE_TY_BP) {
        cont_set_error(cc, "ISW=-1 needs a branch point (BP) to start from; label %d has type %d",
                       start->lab, start->itp);
        return CABLE_ERR_SWITCH;
      }
      cc->switch_pending = 1;
    }
  }
  /* PAR={...} (AUTO's PARVALS) applies after STPNT or the stored solution.
     A stored solution whose parameters it changes no longer solves the
     problem: the first point is then corrected by Newton (first_point), so
     that the branch's first row holds the point the engine continues from.
     A branch switch (ISW=-1) happens at the stored branch point itself,
     which a changed parameter would move: refused. */
  cc->restart_moved = 0;
  for (int k = 0; k < cc->c->npar_override; k++) {
    int i = cc->c->par_override[k].index;
    double v = cc->c->par_override[k].value;
    if (start && s->par[i] != v) {
      if (cc->switch_pending) {
        cont_set_error_key(cc, "PAR",
                           "PAR sets PAR(%d) = %.10g, but the branch point (label %d) has PAR(%d) = %.10g: a "
                           "switch (ISW=-1) starts at the stored branch point; leave PAR(%d) out of PAR",
                           i + 1, v, start->lab, i + 1, s->par[i], i + 1);
        cc->switch_pending = 0;
        return CABLE_ERR_INPUT;
      }
      cc->restart_moved = 1;
    }
    s->par[i] = v;
  }
  double *p = cc->x + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++) p[q] = s->par[s->icp[q]];
  for (int i = 0; i < cc->n; i++)
    if (!isfinite(cc->x[i])) {
      cont_set_error(cc, "the starting solution contains NaN or Inf");
      return CABLE_ERR_NONFINITE;
    }
  cc->started = 0;
  cc->have_start = 1;
  return CABLE_SUCCESS;
}

static const char *type_name(int itp)
{
  switch (itp >= 0 ? itp % 10 : -((-itp) % 10)) {
  case CABLE_TY_BP: return "BP";
  case CABLE_TY_LP: return "LP";
  case CABLE_TY_UZ: return "UZ";
  case CABLE_TY_EP: return "EP";
  case CABLE_TY_MX: return "MX";
  case CABLE_TY_RG: return "RG";
  default: return "  ";
  }
}

/* STAB=1: the Morse index of the point's solution (doc/stability.md S6), at
 * the run's NCOL on its own mesh.  A failure leaves the point unmarked and is
 * said in the d-file; it does not stop the run. */
static void stab_point(cable_cont *cc, const cable_sink *sink)
{
  cable_point *pt = &cc->pt;
  cable_stab_result r;
  cable_error e;
  pt->stab = 0;
  if (cable_stability_index(cc->pb, cc->sol, 1, cc->ncol, &r, &e) != CABLE_SUCCESS) {
    if (sink && sink->diag) {
      char line[640];
      snprintf(line, sizeof line, "STAB: no index at PT %d: %s", pt->pt, e.msg);
      sink->diag(sink->ctx, line);
    }
    return;
  }
  pt->stab = r.index == 0 && r.nzero == 0 ? 1 : -1;
  pt->stab_index = r.index;
  pt->stab_nzero = r.nzero;
  pt->stab_sigma1 = r.neig > 0 ? r.eig[0] : 0.0;
}

/* Hands the point to the sink; 1 when the sink asks to stop (returns > 0). */
static int emit(cable_cont *cc, const cable_sink *sink, int ibr, int *lab)
{
  cable_point *pt = &cc->pt;
  int labelled = pt->itp != CABLE_TY_NONE;
  if (!labelled && cc->c->npr > 0 && pt->pt % cc->c->npr == 0) {
    pt->itp = CABLE_TY_RG;
    labelled = 1;
  }
  /* AUTO's types on a fold curve or a curve of branch points (ISW = 2): the
     point's type + 10 ITPST */
  if (cc->c->itpst > 0 && pt->itp != CABLE_TY_NONE && abs(pt->itp) < 10)
    pt->itp += pt->itp > 0 ? 10 * cc->c->itpst : -10 * cc->c->itpst;
  pt->ibr = ibr;
  pt->lab = labelled ? (*lab)++ : 0;
  pt->note = cc->note[0] ? cc->note : NULL;
  cc->sol->ibr = ibr;
  cc->sol->lab = pt->lab;
  cc->sol->itp = pt->itp;
  if (cc->c->stab) stab_point(cc, sink);
  int stop = sink && sink->point ? sink->point(sink->ctx, pt) : 0;
  if (labelled && sink && sink->solution) sink->solution(sink->ctx, pt, cc->sol);
  if (sink && sink->diag) {
    char line[320];
    snprintf(line, sizeof line,
             "BR %d PT %d TY %s LAB %d PAR(%d)=%.10g ds=%.4g newton=%d err=%.3g det=%+d sv1=%.3e sv2=%.3e", ibr,
             pt->pt, type_name(pt->itp), pt->lab, cc->c->icp[0] + 1, pt->par[cc->c->icp[0]], pt->ds,
             pt->newton_iters, pt->err_est, pt->det_sign, pt->sv1, pt->sv2);
    sink->diag(sink->ctx, line);
    if (pt->stab) {
      snprintf(line, sizeof line, "BR %d PT %d STAB index=%d zero=%d sigma1=%.6e", ibr, pt->pt, pt->stab_index,
               pt->stab_nzero, pt->stab_sigma1);
      sink->diag(sink->ctx, line);
    }
  }
  return stop > 0;
}

/* AUTO's STOP = ['BP2', 'UZ3', ...]: end the branch at the n-th labelled
 * point of that type (the start, always an EP or a restart, is not counted).
 * seen[k] counts the points of the k-th entry's type so far. */
static int stop_reached(const cable_cont *cc, int *seen)
{
  if (cc->ended || cc->npt <= 1 || cc->pt.itp == CABLE_TY_NONE) return 0;
  int itp = cc->pt.itp, base = itp >= 0 ? itp % 10 : -((-itp) % 10);
  for (int k = 0; k < cc->c->nstop; k++)
    if (base == cc->c->stop_on[k] && ++seen[k] == cc->c->stop_count[k]) return 1;
  return 0;
}

int cont_run(cable_cont *cc, const cable_sink *sink, int ibr, int first_label, int *next_label)
{
  if (next_label) *next_label = first_label;
  if (!cc) return CABLE_ERR_NULL;
  if (!cc->have_start && !cc->ended) {
    cont_set_error(cc, "cable_cont_run before cable_cont_set_start");
    return CABLE_ERR_STATE;
  }
  int lab = first_label, rc;
  int seen[sizeof cc->c->stop_on / sizeof cc->c->stop_on[0]] = {0};
  while ((rc = cont_step(cc)) == CABLE_SUCCESS) {
    if (emit(cc, sink, ibr, &lab)) {
      rc = CABLE_ERR_INTERRUPTED;   /* the caller stopped the run (its files stay as they were) */
      break;
    }
    if (stop_reached(cc, seen)) {
      cc->ended = 1;
      cc->end_status = CABLE_END_STOP;
    }
  }
  if (rc < 0 && rc != CABLE_ERR_INTERRUPTED && cc->npt > 0 && !cc->store_failed) {
    /* the branch ends abnormally: the last good point is stored as MX */
    cc->pt.itp = CABLE_TY_MX;
    (void)emit(cc, sink, ibr, &lab);
  }
  if (rc < 0 && sink && sink->diag) {
    char line[640];
    snprintf(line, sizeof line, "branch %d ended: %s: %s", ibr, cable_status_message(rc), cc->err);
    sink->diag(sink->ctx, line);
  }
  if (next_label) *next_label = lab;
  return rc;
}

void cable_cont_test_functions(const cable_cont *cc, int *det_sign, double *sv1, double *sv2)
{
  if (!cc) {
    if (det_sign) *det_sign = 0;
    if (sv1) *sv1 = 0;
    if (sv2) *sv2 = 0;
    return;
  }
  if (det_sign) *det_sign = cc->tf.det_sign;
  if (sv1) *sv1 = cc->tf.sv1;
  if (sv2) *sv2 = cc->tf.sv2;
}
