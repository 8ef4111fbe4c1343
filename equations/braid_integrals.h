/* SPDX-License-Identifier: GPL-3.0-or-later */
/* First integrals of the braid ODEs (doc/braid-equations.md, D8): they are
 * constant along every solution of braid_rhs, so their drift measures the
 * accuracy of a computed solution. */
#ifndef CABLE_BRAID_INTEGRALS_H
#define CABLE_BRAID_INTEGRALS_H

#include "braid_model.h"

typedef struct {
  double F2;  /* |F|^2 */
  double FM;  /* F.M */
  double h;   /* multiplier of the length constraint on strand 2 */
  double q2;  /* |q|^2 (1 for a normalised quaternion) */
  double T1;  /* strand torque T1 */
  double T2;  /* strand torque T2 */
  double ham; /* Hamiltonian of the s-independent Lagrangian */
} braid_first_integrals;

/* Returns like braid_rhs (0, or the guard code with every field zero). */
int braid_first_integrals_eval(const double *u, const braid_material *m,
                               braid_first_integrals *out);

#endif
