/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO's GETP for equation files, compiled by cable into every module it
 * builds from NAME.f90, NAME.f or NAME.c.  Fortran calls GETP_(CODE, IC, U)
 * with the hidden length of CODE; C calls getp(code, ic, u).  Both find
 * cable's header in front of U (cable_getp.h).  A U that did not come from
 * PVLS gives NaN. */
#include <math.h>
#include <string.h>

#include "cable_getp.h"

double getp_(const char *code, const int *ic, const double *u, size_t len);
double getp(const char *code, int ic, const double *u);

static double forward(const char *code, size_t len, int ic, const double *u)
{
  if (!u) return nan("");
  const cable_getp_header *h = (const cable_getp_header *)(const void *)((const char *)u - sizeof *h);
  if (h->magic != CABLE_GETP_MAGIC || !h->getp) return nan("");
  return h->getp(h, code, len, ic);
}

double getp_(const char *code, const int *ic, const double *u, size_t len)
{
  return forward(code, len, ic ? *ic : 0, u);
}

double getp(const char *code, int ic, const double *u)
{
  return forward(code, code ? strlen(code) : 0, ic, u);
}
