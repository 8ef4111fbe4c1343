/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Contact pressure between the two strands of a braid (doc/braid-equations.md,
 * D9): frictionless hard contact, so the only force between the strands is
 * a line load along the chord d1; each strand is a Kirchhoff rod in its own
 * force and moment balance under that load.  Positive p means the strands
 * press on each other (compression); p < 0 means they would have to be held
 * together (glue). */
#ifndef CABLE_BRAID_PRESSURE_H
#define CABLE_BRAID_PRESSURE_H

#include "braid_model.h"
#include "cable/cable_solution.h"

/* u: the 21 states at one point; dudS: du/ds there (s = arclength of strand 1,
 * i.e. braid_rhs's output, NOT the AUTO derivative d/dt = L d/ds), or NULL to
 * evaluate it with braid_rhs.  The second derivative is J(u) du/ds.
 *  *p1: contact force on strand 1 per unit length of strand 1 (from strand 1's
 *       balance laws);
 *  *p2: contact force on strand 2 per unit length of strand 2, i.e. per unit
 *       sigma (from strand 2's balance laws).
 * Action and reaction give p1 = sigma' p2 on every solution of the braid
 * equations; the two are computed independently.  Returns like braid_rhs
 * (0, or the guard code with *p1 = *p2 = 0). */
int braid_contact_pressure(const double *u, const double *dudS, const braid_material *m,
                           double *p1, double *p2);

/* Everything behind the pressure, for checks and plots.  Vectors are
 * components in the first braid frame (t1, d1, u1). */
typedef struct {
  double p_from1;  /* contact force per unit s, from strand 1's balance */
  double p_from2;  /* the same from strand 2's balance (= p_from1 on solutions) */
  double n1[3];    /* internal force of strand 1 */
  double n2[3];    /* internal force of strand 2 (n1 + n2 = F on solutions) */
  double res_t;    /* t1 component of dn2/ds: 0 when the load is along d1 */
  double res_u;    /* u1 component of dn2/ds: 0 when the load is along d1 */
  double sigmap;   /* sigma' */
} braid_contact_detail;

int braid_contact_detail_eval(const double *u, const double *dudS, const braid_material *m,
                              braid_contact_detail *out);

/* Smallest contact pressure of a stored braid solution: min over its
 * ntst*ncol+1 stored points of min(p1, p2) (the `pmin` column; the same
 * quantity as analyze()'s pmin).  0, CABLE_ERR_INPUT for a solution that is
 * not a braid solution, or the guard code of braid_contact_pressure. */
int braid_contact_pressure_min(const cable_solution *sol, const braid_material *m, double *pmin);

#endif
