/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_version.h"

#include <gsl/gsl_version.h>
#include <stdio.h>
#include <sundials/sundials_config.h>

/* LAPACK's own version routine (Fortran calling convention). */
void ilaver_(int *major, int *minor, int *patch);

const char *cable_version_string(char *buf, unsigned long len)
{
  if (!buf || len == 0) return NULL;
  int ma = 0, mi = 0, pa = 0;
  ilaver_(&ma, &mi, &pa);
  snprintf(buf, len, "cable %s (SUNDIALS %s, GSL %s, LAPACK %d.%d.%d)", CABLE_VERSION,
           SUNDIALS_VERSION, GSL_VERSION, ma, mi, pa);
  return buf;
}
