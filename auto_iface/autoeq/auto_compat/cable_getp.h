/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The block that cable puts in front of the solution array it hands to an
 * AUTO-style PVLS.  AUTO's GETP(CODE, IC, U) receives PVLS's own U, so the
 * GETP shim compiled into the equation module (cable_getp.c) finds this
 * header just before U and calls back into cable: no global state.
 * Shared, byte for byte, by cable (auto_iface/autoeq/autoeq_shim.c) and every
 * module it builds; bump CABLE_GETP_MAGIC when the layout changes. */
#ifndef CABLE_GETP_H
#define CABLE_GETP_H

#include <stddef.h>

#define CABLE_GETP_MAGIC 0x63626c6567657031ULL   /* "cblegep1" */

typedef struct cable_getp_header {
  unsigned long long magic;   /* CABLE_GETP_MAGIC while PVLS runs */
  /* GETP itself: code (len bytes, not terminated), 1-based component ic */
  double (*getp)(const struct cable_getp_header *h, const char *code, size_t len, int ic);
  void *ctx;                  /* cable's PVLS context */
  double pad;                 /* keeps U (which follows) 16-byte aligned */
} cable_getp_header;

#endif
