/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Nice axis ticks (1, 2, 5 x 10^k). */
#include "plot_ticks.h"

#include <math.h>
#include <stdio.h>

#include "cable/cable_status.h"

/* A range narrower than this fraction of its magnitude cannot be resolved in
 * double precision tick labels (about 15 significant digits, less a margin
 * for the labels' own rounding), so it is treated as a single value. */
#define PLOT_TICKS_MIN_REL_RANGE 1e-12
/* Relative slack when snapping the limits to whole steps: data that lie on a
 * tick up to round-off must not get an extra, empty interval. */
#define PLOT_TICKS_SNAP 1e-9
/* Fixed-point labels are used for magnitudes in [1e-4, 1e6); beyond that the
 * labels would carry too many zeros to read, so exponent form is used. */
#define PLOT_TICKS_FIXED_MAX 1e6
#define PLOT_TICKS_FIXED_MIN_STEP 1e-4

/* Heckbert's rounding: the nice number nearest to x (in a log sense). */
static double plot_ticks_round_nice(double x)
{
  double e = floor(log10(x));
  double p = pow(10.0, e);
  double f = x / p;
  double nf = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
  return nf * p;
}

int plot_ticks_nice(double lo, double hi, int target, plot_ticks *t)
{
  if (t == NULL || !isfinite(lo) || !isfinite(hi) || target < 1) return CABLE_ERR_INPUT;
  if (hi < lo) {
    double s = lo;
    lo = hi;
    hi = s;
  }
  double mag = fmax(fabs(lo), fabs(hi));
  if (hi - lo <= PLOT_TICKS_MIN_REL_RANGE * mag || hi - lo == 0.0) {
    /* one value: show a tenth of its magnitude either side (or +-1 at zero) */
    double d = mag > 0 ? 0.1 * mag : 1.0;
    lo -= d;
    hi += d;
  }
  double step = plot_ticks_round_nice((hi - lo) / target);
  double a = floor(lo / step + PLOT_TICKS_SNAP);
  double b = ceil(hi / step - PLOT_TICKS_SNAP);
  t->step = step;
  t->first = (long)a;
  t->n = (int)(b - a) + 1;
  t->lo = a * step;
  t->hi = b * step;
  return CABLE_SUCCESS;
}

double plot_ticks_value(const plot_ticks *t, int i)
{
  return (double)(t->first + i) * t->step;
}

void plot_ticks_format(const plot_ticks *t, double v, char *buf, size_t len)
{
  /* a value within round-off of zero is zero (never "-0" or "1e-17") */
  if (fabs(v) < PLOT_TICKS_SNAP * t->step) v = 0.0;
  double mag = fmax(fabs(t->lo), fabs(t->hi));
  int step_exp = (int)floor(log10(t->step) + PLOT_TICKS_SNAP);
  if (mag < PLOT_TICKS_FIXED_MAX && t->step >= PLOT_TICKS_FIXED_MIN_STEP) {
    int decimals = step_exp < 0 ? -step_exp : 0;
    snprintf(buf, len, "%.*f", decimals, v);
  } else {
    int mag_exp = (int)floor(log10(mag));
    int digits = mag_exp - step_exp;
    if (digits < 0) digits = 0;
    snprintf(buf, len, "%.*e", digits, v);
  }
}
