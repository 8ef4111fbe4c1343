/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Fuller's writhe update with counted passages (equations/ribbon_fuller.h) on
 * closed-form curves: Wr(B) - Wr(A) against F(A, B) + 2 sign N(A, B), both
 * sides computed independently (the writhe by ribbon_writhe_samples' Gauss
 * double integral, F by the trapezoidal rule, N by curve_passages).  The
 * braid-level update along the link scenes' branches is checked against the
 * full writhe at every labelled point in tests/test_ribbon_track.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "axis_passages.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "ribbon.h"
#include "ribbon_fuller.h"

#define N 1024
static const double PI = 3.14159265358979323846;

/* Samples u_k = k/N of the lifted figure eight (cos th, sin th cos th, eps sin th)
 * or the lifted trefoil projection (sin th + 2 sin 2th, cos th - 2 cos 2th,
 * eps sin 3th), th = 2 pi u, rotated by rot about z: r, r_u and r_uu. */
static void curve(int trefoil, double eps, double rot, double *r, double *dr, double *ddr, double *pos)
{
  double w = 2 * PI, cr = cos(rot), sr = sin(rot);
  for (int k = 0; k < N; k++) {
    double th = w * k / N, p[3], d[3], dd[3];
    if (trefoil) {
      p[0] = sin(th) + 2 * sin(2 * th), p[1] = cos(th) - 2 * cos(2 * th), p[2] = eps * sin(3 * th);
      d[0] = cos(th) + 4 * cos(2 * th), d[1] = -sin(th) + 4 * sin(2 * th), d[2] = 3 * eps * cos(3 * th);
      dd[0] = -sin(th) - 8 * sin(2 * th), dd[1] = -cos(th) + 8 * cos(2 * th), dd[2] = -9 * eps * sin(3 * th);
    } else {
      p[0] = cos(th), p[1] = 0.5 * sin(2 * th), p[2] = eps * sin(th);
      d[0] = -sin(th), d[1] = cos(2 * th), d[2] = eps * cos(th);
      dd[0] = -cos(th), dd[1] = -2 * sin(2 * th), dd[2] = -eps * sin(th);
    }
    const double *src[3] = {p, d, dd};
    double *dst[3] = {r, dr, ddr}, scale[3] = {1, w, w * w};
    for (int m = 0; m < 3; m++) {
      dst[m][3 * k] = scale[m] * (cr * src[m][0] - sr * src[m][1]);
      dst[m][3 * k + 1] = scale[m] * (sr * src[m][0] + cr * src[m][1]);
      dst[m][3 * k + 2] = scale[m] * src[m][2];
    }
    pos[k] = (double)k / N;
  }
}

/* Unit tangent and dT/du from r_u, r_uu. */
static void tangent(const double *d, const double *dd, double *T, double *dT)
{
  double sp = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double td = (d[0] * dd[0] + d[1] * dd[1] + d[2] * dd[2]) / sp;
  for (int k = 0; k < 3; k++) {
    T[k] = d[k] / sp;
    dT[k] = (dd[k] - td * T[k]) / sp;
  }
}

/* F(A, B) by the periodic trapezoidal rule (spectrally accurate: the
 * integrand is smooth and periodic). */
static double fuller(const double *da, const double *dda, const double *db, const double *ddb)
{
  double s = 0;
  for (int k = 0; k < N; k++) {
    double Ta[3], dTa[3], Tb[3], dTb[3];
    tangent(da + 3 * k, dda + 3 * k, Ta, dTa);
    tangent(db + 3 * k, ddb + 3 * k, Tb, dTb);
    s += ribbon_fuller_density(Ta, dTa, Tb, dTb);
  }
  return s / N;
}

typedef struct {
  double r[3 * N], dr[3 * N], ddr[3 * N];
} shape;

/* Wr(B) - Wr(A) - F(A, B) and the passages between A and B. */
static double defect(int trefoil, double ea, double ra, double eb, double rb, cable_axis_passages *ap)
{
  static shape a, b;
  static double pos[N];
  double wa, wb, err;
  curve(trefoil, ea, ra, a.r, a.dr, a.ddr, pos);
  curve(trefoil, eb, rb, b.r, b.dr, b.ddr, pos);
  if (ribbon_writhe_samples(N, 1.0, a.r, a.dr, &wa, &err) || ribbon_writhe_samples(N, 1.0, b.r, b.dr, &wb, &err))
    return NAN;
  if (curve_passages(a.r, b.r, pos, N, 1.0, 0.05, ap)) return NAN;
  return wb - wa - fuller(a.dr, a.ddr, b.dr, b.ddr);
}

int main(void)
{
  cable_axis_passages ap;
  /* no passage: Fuller's integral is the whole change (to the writhe
     quadrature's error, below 1e-9 at N = 1024 for these curves) */
  double d = defect(0, 0.3, 0.0, 0.15, 0.4, &ap);
  test_int("fuller: figure eight lifted less and rotated: no passage", ap.count, 0);
  test_abs("  Wr(B) - Wr(A) = F(A, B)", d, 0.0, 1e-9);
  d = defect(1, 0.5, 0.0, 0.9, -0.3, &ap);
  test_int("fuller: trefoil lifted more and rotated: no passage", ap.count, 0);
  test_abs("  Wr(B) - Wr(A) = F(A, B)", d, 0.0, 1e-9);
  /* one passage: the rest is 2 RIBBON_PASSAGE_WR_SIGN net */
  d = defect(0, 0.1, 0.0, -0.1, 0.1, &ap);
  test_int("fuller: figure eight lifted to the other side: one passage", ap.count, 1);
  test_abs("  Wr(B) - Wr(A) - F(A, B) = 2 sign net", d, 2.0 * RIBBON_PASSAGE_WR_SIGN * ap.net, 1e-9);
  d = defect(0, -0.1, 0.1, 0.1, 0.0, &ap);
  test_abs("  and back", d, 2.0 * RIBBON_PASSAGE_WR_SIGN * ap.net, 1e-9);
  d = defect(1, 0.5, 0.0, -0.5, 0.2, &ap);
  test_int("fuller: trefoil lifted to its mirror: three passages", ap.count, 3);
  test_abs("  Wr(B) - Wr(A) - F(A, B) = 2 sign net", d, 2.0 * RIBBON_PASSAGE_WR_SIGN * ap.net, 1e-9);
  return test_summary();
}
