/* SPDX-License-Identifier: GPL-3.0-or-later */
/* "Nice" axis ticks: steps of 1, 2 or 5 times a power of ten, axis limits
 * widened to whole steps (Heckbert, "Nice numbers for graph labels",
 * Graphics Gems, 1990). */
#ifndef CABLE_PLOT_TICKS_H
#define CABLE_PLOT_TICKS_H

#include <stddef.h>

typedef struct {
  double lo, hi;   /* axis limits: multiples of step enclosing the data */
  double step;     /* 1, 2 or 5 times 10^k */
  long first;      /* lo = first * step */
  int n;           /* number of ticks: lo, lo + step, ..., hi */
} plot_ticks;

/* Ticks for data in [lo, hi] with about `target` intervals (target >= 1).
 * A zero-width range is widened around its value.  Returns CABLE_SUCCESS or
 * CABLE_ERR_INPUT (non-finite limits, target < 1, NULL t). */
int plot_ticks_nice(double lo, double hi, int target, plot_ticks *t);
/* Value of tick i (0 <= i < n), computed without accumulated round-off. */
double plot_ticks_value(const plot_ticks *t, int i);
/* Tick label with just enough digits to tell neighbouring ticks apart;
 * exponent form for very large or very small magnitudes. */
void plot_ticks_format(const plot_ticks *t, double v, char *buf, size_t len);

#endif
