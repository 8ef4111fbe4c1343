/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Strand exchange: the same braid described with s along strand 2.
 *
 * A braid state u(s) (braid_state.h) seen from the second strand: its first
 * strand is the old strand 2 (arclength sigma), its chord the old -d1, so its
 * braid frame is R11 R2(eta) diag(1,-1,-1) and
 *   eta_n = eta, omega_n = (Omega1, -Omega2, -Omega3)/sigma',
 *   F_n = D R2(eta)^T F, M_n = D R2(eta)^T (M - Delta d1 x F) (moment about r2),
 *   xi1_n = -xi2, T1_n = -T2, xi2_n = -xi1, T2_n = -T1,
 *   q_n = qG q q(R2(eta)) q(D), r1_n = G (r1 + Delta d1 - p0), sigma_n = s.
 * G (quaternion qG) and p0 are one rigid motion, chosen by
 * braid_exchange_frame so that the mapped start meets the link conditions
 * (12.3.24)-(12.3.30).  Derivation: doc/links.md, "Strand exchange". */
#ifndef CABLE_BRAID_EXCHANGE_H
#define CABLE_BRAID_EXCHANGE_H

#include "braid_model.h"

typedef struct {
  double qg[4]; /* quaternion of the rigid rotation G */
  double p0[3]; /* point moved to the origin: r2 at the start */
} braid_exchange_frame;

/* The rigid motion that takes the strand-2 start of state u0 to the start
 * of the link conditions: r1_n(0) = 0, q_n(0) = (0, -1/sqrt2, -1/sqrt2, 0).
 * Returns like braid_aux_eval. */
int braid_exchange_frame_at(const double *u0, const braid_material *m, braid_exchange_frame *g);

/* The mapped state w[21] of u at arclength s of strand 1 (sigma_n = s).
 * Returns like braid_aux_eval (0, > 0 outside the physical domain). */
int braid_exchange_state(const double *u, double s, const braid_material *m,
                         const braid_exchange_frame *g, double *w);

#endif
