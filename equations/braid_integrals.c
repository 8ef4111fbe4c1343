/* SPDX-License-Identifier: GPL-3.0-or-later */
/* First integrals: guarded wrapper around the generated expressions. */
#include "braid_integrals.h"

#include <math.h>

#include "braid_rhs_gen.h"

int braid_first_integrals_eval(const double *u, const braid_material *m,
                               braid_first_integrals *out)
{
  double r[BRAID_GEN_NINT] = {0};
  int st = braid_state_check(u, m);
  if (st == BRAID_OK) {
    const double p[BRAID_NMAT] = {m->Delta, m->B1, m->B2, m->C1, m->C2, m->w01, m->w02};
    braid_gen_integrals(u, p, r);
    for (int i = 0; i < BRAID_GEN_NINT; i++)
      if (!isfinite(r[i])) st = BRAID_NONFINITE;
    if (st != BRAID_OK)
      for (int i = 0; i < BRAID_GEN_NINT; i++) r[i] = 0.0;
  }
  out->F2 = r[0];
  out->FM = r[1];
  out->h = r[2];
  out->q2 = r[3];
  out->T1 = r[4];
  out->T2 = r[5];
  out->ham = r[6];
  return st;
}
