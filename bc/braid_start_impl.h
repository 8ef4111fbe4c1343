/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Private to bc/: the pieces of the starting-solution code shared between
 * braid_start.c (parameters, rings, dispatch) and braid_start_torus.c. */
#ifndef CABLE_BRAID_START_IMPL_H
#define CABLE_BRAID_START_IMPL_H

#include <math.h>

#include "braid_start.h"

/* q(0) = (0, -1/sqrt2, -1/sqrt2, 0): t1 = e_y, d1 = e_x, u1 = -e_z (12.3.4-7). */
#define BRAID_SQRT_HALF 0.70710678118654752440
#define BRAID_PI 3.14159265358979323846

/* Hamilton product r = a b (r may not alias a or b). */
static inline void braid_quat_mul(const double *a, const double *b, double *r)
{
  r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* Rotation matrix of a unit quaternion, column-major R[i + 3j]; its columns
 * are t1, d1, u1 of the paper's Sect. 12.2.3. */
static inline void braid_quat_matrix(const double *q, double *r)
{
  const double q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
  r[0] = q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3;
  r[1] = 2 * (q1 * q2 + q0 * q3);
  r[2] = 2 * (q1 * q3 - q0 * q2);
  r[3] = 2 * (q1 * q2 - q0 * q3);
  r[4] = q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3;
  r[5] = 2 * (q2 * q3 + q0 * q1);
  r[6] = 2 * (q1 * q3 + q0 * q2);
  r[7] = 2 * (q2 * q3 - q0 * q1);
  r[8] = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3;
}

/* Unit quaternion of the rotation by angle a about coordinate axis k. */
static inline void braid_quat_axis(int k, double a, double *q)
{
  q[0] = cos(0.5 * a);
  q[1] = q[2] = q[3] = 0.0;
  q[1 + k] = sin(0.5 * a);
}

/* Set sp->par: T, lengths, Delta, Phi, w2fix, the material; eps21 = eps13 = 0. */
void braid_start_set_par(braid_start_params *sp, double l, double l2, double ltot, double phi,
                         double w2fix);

/* Torus construction (braid_start_torus.c). */
int braid_start_torus_prepare(braid_start_params *sp);
int braid_start_torus_state(const braid_start_params *sp, double t, double *u);

#endif
