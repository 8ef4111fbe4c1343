/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Contact pressure: u'' = J(u) u' from the exact Jacobian, then the
 * generated strand balance expressions. */
#include "braid_pressure.h"

#include <math.h>
#include <string.h>

#include "braid_rhs_gen.h"
#include "cable/cable_status.h"

int braid_contact_detail_eval(const double *u, const double *dudS, const braid_material *m,
                              braid_contact_detail *out)
{
  double r[BRAID_GEN_NPRES] = {0};
  double f[BR_NDIM], jac[BR_NDIM * BR_NDIM];
  int st = braid_rhs(u, m, f, jac, NULL);
  if (st == BRAID_OK && dudS) {
    for (int i = 0; i < BR_NDIM; i++)
      if (!isfinite(dudS[i])) st = BRAID_NONFINITE;
  }
  if (st == BRAID_OK) {
    const double *up = dudS ? dudS : f;
    double upp[BR_NDIM];
    for (int i = 0; i < BR_NDIM; i++) {
      double s = 0.0;
      for (int j = 0; j < BR_NDIM; j++) s += jac[i + BR_NDIM * j] * up[j];
      upp[i] = s;
    }
    const double p[BRAID_NMAT] = {m->Delta, m->B1, m->B2, m->C1, m->C2, m->w01, m->w02};
    braid_gen_pressure(u, up, upp, p, r);
    for (int i = 0; i < BRAID_GEN_NPRES; i++)
      if (!isfinite(r[i])) st = BRAID_NONFINITE;
    if (st != BRAID_OK) memset(r, 0, sizeof r);
  }
  out->p_from1 = r[0];
  out->p_from2 = r[1];
  for (int i = 0; i < 3; i++) {
    out->n1[i] = r[2 + i];
    out->n2[i] = r[5 + i];
  }
  out->res_t = r[8];
  out->res_u = r[9];
  out->sigmap = r[10];
  return st;
}

int braid_contact_pressure(const double *u, const double *dudS, const braid_material *m,
                           double *p1, double *p2)
{
  braid_contact_detail d;
  int st = braid_contact_detail_eval(u, dudS, m, &d);
  *p1 = d.p_from1;
  *p2 = st == BRAID_OK ? d.p_from2 / d.sigmap : 0.0;
  return st;
}

int braid_contact_pressure_min(const cable_solution *sol, const braid_material *m, double *pmin)
{
  if (!sol || !m || !pmin || sol->ndim != BR_NDIM) return CABLE_ERR_INPUT;
  double lo = HUGE_VAL;
  for (int k = 0; k < cable_solution_npts(sol); k++) {
    double p1, p2;
    int st = braid_contact_pressure(sol->u + (size_t)k * BR_NDIM, NULL, m, &p1, &p2);
    if (st != BRAID_OK) return st;
    lo = fmin(lo, fmin(p1, p2));
  }
  *pmin = lo;
  return CABLE_SUCCESS;
}
