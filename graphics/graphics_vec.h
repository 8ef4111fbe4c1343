/* Small 3-vector helpers shared by the tube mesher, the renderer and the
 * exports (header-only, inline). */
#ifndef CABLE_GRAPHICS_VEC_H
#define CABLE_GRAPHICS_VEC_H

#include <math.h>

/* M_PI is not in strict C11/POSIX. */
#define GRAPHICS_PI 3.14159265358979323846

static inline double gvec_dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double gvec_norm(const double a[3])
{
  return sqrt(gvec_dot(a, a));
}

static inline void gvec_cross(const double a[3], const double b[3], double c[3])
{
  double c0 = a[1] * b[2] - a[2] * b[1];
  double c1 = a[2] * b[0] - a[0] * b[2];
  double c2 = a[0] * b[1] - a[1] * b[0];
  c[0] = c0, c[1] = c1, c[2] = c2;
}

static inline void gvec_sub(const double a[3], const double b[3], double c[3])
{
  c[0] = a[0] - b[0], c[1] = a[1] - b[1], c[2] = a[2] - b[2];
}

/* c = a + s b */
static inline void gvec_axpy(const double a[3], double s, const double b[3], double c[3])
{
  c[0] = a[0] + s * b[0], c[1] = a[1] + s * b[1], c[2] = a[2] + s * b[2];
}

/* Normalise in place; returns the old length (0 leaves a unchanged). */
static inline double gvec_normalize(double a[3])
{
  double n = gvec_norm(a);
  if (n > 0) a[0] /= n, a[1] /= n, a[2] /= n;
  return n;
}

#endif
