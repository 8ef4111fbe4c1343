/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Small 3-vector helpers (header-only, inline), the one set every layer uses:
 * the braid geometry, the starts, the tube mesher, the renderer and the
 * exports.  Vectors are double[3]; an output may alias an input. */
#ifndef CABLE_VEC3_H
#define CABLE_VEC3_H

#include <math.h>

static inline double cable_vec3_dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double cable_vec3_norm(const double a[3])
{
  return sqrt(cable_vec3_dot(a, a));
}

/* c = a x b */
static inline void cable_vec3_cross(const double a[3], const double b[3], double c[3])
{
  double c0 = a[1] * b[2] - a[2] * b[1];
  double c1 = a[2] * b[0] - a[0] * b[2];
  double c2 = a[0] * b[1] - a[1] * b[0];
  c[0] = c0, c[1] = c1, c[2] = c2;
}

/* c = a - b */
static inline void cable_vec3_sub(const double a[3], const double b[3], double c[3])
{
  c[0] = a[0] - b[0], c[1] = a[1] - b[1], c[2] = a[2] - b[2];
}

/* c = a + s b */
static inline void cable_vec3_axpy(const double a[3], double s, const double b[3], double c[3])
{
  c[0] = a[0] + s * b[0], c[1] = a[1] + s * b[1], c[2] = a[2] + s * b[2];
}

/* |a - b|^2 */
static inline double cable_vec3_dist2(const double a[3], const double b[3])
{
  double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

/* Normalise in place; returns the old length (0 leaves a unchanged). */
static inline double cable_vec3_normalize(double a[3])
{
  double n = cable_vec3_norm(a);
  if (n > 0) a[0] /= n, a[1] /= n, a[2] /= n;
  return n;
}

#endif
