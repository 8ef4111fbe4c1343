/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The engine's notes on the labelled points of a d-file (d.NAME), read back
 * for the solutions of s.NAME: a branch point's kind (cable_solution.bp_kind)
 * is not in AUTO's s-file format, but the d-file (AUTO's diagnostics, which
 * AUTO reads only for display) has each point's NOTE line.
 *
 * The d-file as aufile_write.c writes it: per point a heading
 * "  BR    PT  IT ...", the point's line, an optional " NOTE: text" line,
 * and for a labelled point AUTO's screen heading "  BR    PT  TY  LAB ..."
 * and the screen line "%4d%6d %3s%5d ..." (label in columns 15-19).  The
 * note of the last point line before a screen line belongs to its label.
 * Every labelled point is kept, in file order, with or without a note: a
 * label can appear more than once (runs appended with AUTO's numbering), and
 * its n-th screen line belongs to its n-th solution in the s-file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"
#include "cable_session_impl.h"

#define DNOTE_LINE_MAX 4096

static const char k_point_head[] = "  BR    PT  IT";
static const char k_screen_head[] = "  BR    PT  TY  LAB";
static const char k_note[] = " NOTE: ";

void rp_dnotes_free(rp_dnotes *d)
{
  if (!d) return;
  for (int i = 0; i < d->n; i++) free(d->note[i]);
  free(d->note);
  free(d->lab);
  d->n = 0;
  d->note = NULL;
  d->lab = NULL;
}

static int dnotes_add(rp_dnotes *d, int lab, const char *note, int *cap)
{
  if (d->n == *cap) {
    int nc = *cap ? 2 * *cap : 16;
    int *l = realloc(d->lab, (size_t)nc * sizeof *l);
    if (!l) return CABLE_ERR_ALLOC;
    d->lab = l;
    char **t = realloc(d->note, (size_t)nc * sizeof *t);
    if (!t) return CABLE_ERR_ALLOC;
    d->note = t;
    *cap = nc;
  }
  size_t len = strlen(note);
  char *copy = malloc(len + 1);
  if (!copy) return CABLE_ERR_ALLOC;
  memcpy(copy, note, len + 1);
  d->lab[d->n] = lab;
  d->note[d->n] = copy;
  d->n++;
  return 0;
}

int rp_dnotes_read(const char *path, rp_dnotes *d)
{
  memset(d, 0, sizeof *d);
  FILE *f = fopen(path, "r");
  if (!f) return 0;   /* no d-file: no notes */
  d->found = 1;
  char line[DNOTE_LINE_MAX], note[DNOTE_LINE_MAX] = "";
  int cap = 0, rc = 0, screen = 0;
  while (!rc && fgets(line, sizeof line, f)) {
    line[strcspn(line, "\r\n")] = '\0';
    if (strncmp(line, k_point_head, sizeof k_point_head - 1) == 0) {
      note[0] = '\0';   /* a new point: its note follows its line */
      screen = 0;
    } else if (strncmp(line, k_note, sizeof k_note - 1) == 0) {
      snprintf(note, sizeof note, "%s", line + sizeof k_note - 1);
    } else if (strncmp(line, k_screen_head, sizeof k_screen_head - 1) == 0) {
      screen = 1;
    } else if (screen) {
      screen = 0;
      char field[6] = "";
      if (strlen(line) >= 19) memcpy(field, line + 14, 5);
      char *end;
      long lab = strtol(field, &end, 10);
      if (end != field && lab > 0) rc = dnotes_add(d, (int)lab, note, &cap);
    }
  }
  fclose(f);
  if (rc) rp_dnotes_free(d);
  return rc;
}

const char *rp_dnotes_find(const rp_dnotes *d, int lab, int nth)
{
  for (int i = 0; d && i < d->n; i++)
    if (d->lab[i] == lab && nth-- == 0) return d->note[i][0] ? d->note[i] : NULL;
  return NULL;
}

/* The engine's detector (continuation/cont_special.c, cont_engine.c) finds a
 * BP either by a sign change of the determinant (simple, no note of its
 * kind) or by the singular-value dip test, whose note starts with "double
 * branch point" or "branch point without a sign change" (a pair). */
int rp_bp_kind_from_note(int itp, const char *note)
{
  if (cable_type_base(itp) != 6) return CABLE_BP_UNKNOWN;
  if (note && strncmp(note, "double branch point", 19) == 0) return CABLE_BP_DOUBLE;
  if (note && strncmp(note, "branch point without a sign change", 34) == 0) return CABLE_BP_PAIR;
  return CABLE_BP_SIMPLE;
}
