/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The axis-passage counter (equations/axis_passages.h) on closed-form curves
 * whose self-passages are known: a lifted figure eight, a lifted trefoil
 * projection, rigid motions and near misses.  The knot72 scene's acceptance
 * test, which counts the passages along the mode branches, is
 * tests/python/test_knot72_scene.py. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "axis_passages.h"
#include "cable/cable_status.h"
#include "harness.h"

/* ---- the axis-passage counter on closed-form curves ----------------------------- */

#define NCURVE 400
static const double PI = 3.14159265358979323846;

/* A figure-eight-like closed curve (x, y) = (cos th, sin th cos th) whose one
 * planar self-crossing (th = pi/2 and 3 pi/2) is lifted apart by z = eps sin th,
 * or a trefoil projection (sin th + 2 sin 2th, cos th - 2 cos 2th) lifted by
 * z = eps sin 3th at its three crossings; rot: a rotation about z. */
static void test_curve(int trefoil, double eps, double rot, double *xyz, double *pos)
{
  for (int k = 0; k < NCURVE; k++) {
    double th = 2 * PI * k / NCURVE, x, y, z;
    if (trefoil) x = sin(th) + 2 * sin(2 * th), y = cos(th) - 2 * cos(2 * th), z = eps * sin(3 * th);
    else x = cos(th), y = sin(th) * cos(th), z = eps * sin(th);
    xyz[3 * k] = cos(rot) * x - sin(rot) * y;
    xyz[3 * k + 1] = sin(rot) * x + cos(rot) * y;
    xyz[3 * k + 2] = z;
    pos[k] = (double)k / NCURVE;
  }
}

static void test_curve_passages(void)
{
  static double a[3 * NCURVE], b[3 * NCURVE], c[3 * NCURVE], pos[NCURVE];
  cable_axis_passages ap, back;
  /* window 0.05 of the period: the crossing parts are half a period apart */
  test_curve(0, 0.1, 0, a, pos);
  test_curve(0, -0.1, 0, b, pos);
  test_int("passages: figure eight lifted to the other side: status", curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap), 0);
  test_int("  one passage", ap.count, 1);
  test_int("  of one sign", abs(ap.net), 1);
  /* the parts meet where eps (1 - 2 tau) = 0 */
  test_abs("  halfway along the homotopy", ap.tau_first, 0.5, 1e-9);
  curve_passages(b, a, pos, NCURVE, 1, 0.05, &back);
  test_true("  and the way back has the opposite sign", back.count == 1 && back.net == -ap.net);
  curve_passages(a, a, pos, NCURVE, 1, 0.05, &ap);
  test_true("passages: no motion, none", ap.count == 0 && ap.net == 0 && isnan(ap.tau_first));
  test_curve(0, 0.1, 0.2, c, pos);
  curve_passages(a, c, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: a rigid rotation passes nothing", ap.count, 0);
  test_curve(0, 0.05, 0, c, pos);
  curve_passages(a, c, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: parts that approach without meeting pass nothing", ap.count, 0);
  curve_passages(a, b, pos, NCURVE, 1, 0.6, &ap);
  test_int("passages: parts closer than the window along the curve are not compared", ap.count, 0);
  test_curve(0, 0.0, 0, c, pos);
  test_curve(0, 0.0, 0.3, b, pos);
  curve_passages(c, b, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: two planar shapes (coplanar all along) pass nothing", ap.count, 0);
  /* the trefoil's three crossings all change, and all the same way (a right
     trefoil becomes a left one: each crossing's sign flips alike) */
  test_curve(1, 0.5, 0, a, pos);
  test_curve(1, -0.5, 0, b, pos);
  curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap);
  test_true("passages: trefoil lifted to its mirror: three passages of one sign", ap.count == 3 && abs(ap.net) == 3);
  test_int("passages: fewer than four points refused", curve_passages(a, b, pos, 3, 1, 0.05, &ap), CABLE_ERR_INPUT);
  b[7] = NAN;
  test_int("passages: a non-finite point refused", curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap), CABLE_ERR_INPUT);
}

int main(void)
{
  test_curve_passages();
  return test_summary();
}
