#include "braid_analysis.h"

#include <gsl/gsl_math.h>
#include <math.h>
#include <string.h>

#include "braid_integrals.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_state.h"
#include "cable_status.h"

static double wrap_2pi(double a)
{
  double r = fmod(a, 2.0 * M_PI);
  return r < 0 ? r + 2.0 * M_PI : r;
}

/* Relative drift of a first integral: spread over the nodes, scaled by its
 * largest magnitude (or 1 when it vanishes identically). */
static double spread(double lo, double hi, double scale)
{
  return (hi - lo) / (scale > 0 ? scale : 1.0);
}

double braid_first_integral_drift(const cable_solution *sol)
{
  if (sol->ndim != BR_NDIM || sol->npar <= BP_EPS13) return -1.0;
  braid_material m;
  braid_material_from_par(sol->par, &m);
  double lo[4] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[4] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double mag[4] = {0, 0, 0, 0}, drift = 0;
  /* at the mesh points, where collocation is superconvergent (O(h^(2 NCOL)));
     between them the solution is only O(h^(NCOL+1)) accurate */
  for (int k = 0; k < cable_solution_npts(sol); k += sol->ncol) {
    braid_first_integrals fi;
    if (braid_first_integrals_eval(sol->u + (size_t)k * BR_NDIM, &m, &fi) != 0) return -1.0;
    double v[4] = {fi.F2, fi.FM, fi.h, fi.ham};
    for (int q = 0; q < 4; q++) {
      lo[q] = fmin(lo[q], v[q]);
      hi[q] = fmax(hi[q], v[q]);
      mag[q] = fmax(mag[q], fabs(v[q]));
    }
  }
  for (int q = 0; q < 4; q++) drift = fmax(drift, spread(lo[q], hi[q], mag[q]));
  return drift;
}

int braid_analysis_compute(const cable_solution *sol, braid_analysis *out)
{
  memset(out, 0, sizeof *out);
  if (sol->ndim != BR_NDIM || sol->npar <= BP_EPS13) return CABLE_ERR_INPUT;
  int rc = braid_topology_compute(sol, 0, &out->topo);
  if (rc) return rc;
  rc = braid_tube_distance_solution(sol, 0, &out->tube);
  if (rc) return rc;
  braid_material m;
  braid_material_from_par(sol->par, &m);
  int npts = cable_solution_npts(sol);
  double f[BR_NDIM];
  out->pmin1 = out->pmin2 = HUGE_VAL;
  out->pmax1 = out->pmax2 = -HUGE_VAL;
  double pprev = 0.0;
  for (int k = 0; k < npts; k++) {
    const double *u = sol->u + (size_t)k * BR_NDIM;
    if (braid_rhs(u, &m, f, NULL, NULL) != 0) return CABLE_ERR_NONFINITE;
    double p1, p2;
    if (braid_contact_pressure(u, f, &m, &p1, &p2) != 0) return CABLE_ERR_NONFINITE;
    out->pmin1 = fmin(out->pmin1, p1);
    out->pmax1 = fmax(out->pmax1, p1);
    out->pmin2 = fmin(out->pmin2, p2);
    out->pmax2 = fmax(out->pmax2, p2);
    if (k > 0 && ((pprev < 0 && p1 >= 0) || (pprev >= 0 && p1 < 0))) {
      if (out->psign_changes < 8) out->s_psign[out->psign_changes] = sol->t[k] * sol->par[BP_L];
      out->psign_changes++;
    }
    pprev = p1;
  }
  out->drift = braid_first_integral_drift(sol);
  if (out->drift < 0) return CABLE_ERR_NONFINITE;
  const double *u0 = sol->u, *u1 = sol->u + (size_t)(npts - 1) * BR_NDIM;
  if (out->topo.closure < 0) {
    out->closure = wrap_2pi(u0[BR_XI1] + u1[BR_XI2]);
  } else {
    out->closure = wrap_2pi(u1[BR_XI1] - u0[BR_XI1]);
    out->closure2 = wrap_2pi(u1[BR_XI2] - u0[BR_XI2]);
  }
  return CABLE_SUCCESS;
}
