/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The engine's notes and BP records on the labelled points of a d-file
 * (d.NAME), read back for the solutions of s.NAME: a branch point's kind
 * (cable_solution.bp_kind) is not in AUTO's s-file format, but the d-file
 * (AUTO's diagnostics, which AUTO reads only for display) has each point's
 * NOTE line (for people: kept as text, never parsed) and each BP's record
 * " BP: kind=double multiplicity=2" (for programs).
 *
 * The d-file as aufile_write.c writes it: per point a heading
 * "  BR    PT  IT ...", the point's line, an optional " NOTE: text" line, an
 * optional BP record, and for a labelled point AUTO's screen heading "  BR    PT  TY  LAB ..."
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
static const char k_bp[] = " BP: kind=";

void rp_dnotes_free(rp_dnotes *d)
{
  if (!d) return;
  for (int i = 0; i < d->n; i++) free(d->note[i]);
  free(d->note);
  free(d->lab);
  free(d->bp_kind);
  d->n = 0;
  d->note = NULL;
  d->lab = NULL;
  d->bp_kind = NULL;
}

static int dnotes_add(rp_dnotes *d, int lab, const char *note, int bp_kind, int *cap)
{
  if (d->n == *cap) {
    int nc = *cap ? 2 * *cap : 16;
    int *l = realloc(d->lab, (size_t)nc * sizeof *l);
    if (!l) return CABLE_ERR_ALLOC;
    d->lab = l;
    int *k = realloc(d->bp_kind, (size_t)nc * sizeof *k);
    if (!k) return CABLE_ERR_ALLOC;
    d->bp_kind = k;
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
  d->bp_kind[d->n] = bp_kind;
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
  int cap = 0, rc = 0, screen = 0, bp_kind = CABLE_BP_UNKNOWN;
  while (!rc && fgets(line, sizeof line, f)) {
    line[strcspn(line, "\r\n")] = '\0';
    if (strncmp(line, k_point_head, sizeof k_point_head - 1) == 0) {
      note[0] = '\0';   /* a new point: its note and record follow its line */
      bp_kind = CABLE_BP_UNKNOWN;
      screen = 0;
    } else if (strncmp(line, k_note, sizeof k_note - 1) == 0) {
      snprintf(note, sizeof note, "%s", line + sizeof k_note - 1);
    } else if (strncmp(line, k_bp, sizeof k_bp - 1) == 0) {
      /* the record's first field, a word of cable_bp_kind_name */
      char word[16] = "";
      sscanf(line + sizeof k_bp - 1, "%15[a-z]", word);
      bp_kind = cable_bp_kind_code(word);
    } else if (strncmp(line, k_screen_head, sizeof k_screen_head - 1) == 0) {
      screen = 1;
    } else if (screen) {
      screen = 0;
      char field[6] = "";
      if (strlen(line) >= 19) memcpy(field, line + 14, 5);
      char *end;
      long lab = strtol(field, &end, 10);
      if (end != field && lab > 0) rc = dnotes_add(d, (int)lab, note, bp_kind, &cap);
    }
  }
  fclose(f);
  if (rc) rp_dnotes_free(d);
  return rc;
}

/* The entry of the nth (0, 1, ...) labelled point with label lab, or -1. */
static int dnotes_index(const rp_dnotes *d, int lab, int nth)
{
  for (int i = 0; d && i < d->n; i++)
    if (d->lab[i] == lab && nth-- == 0) return i;
  return -1;
}

const char *rp_dnotes_find(const rp_dnotes *d, int lab, int nth)
{
  int i = dnotes_index(d, lab, nth);
  return i >= 0 && d->note[i][0] ? d->note[i] : NULL;
}

int rp_dnotes_bp_kind(const rp_dnotes *d, int itp, int lab, int nth)
{
  if (cable_type_base(itp) != CABLE_TY_BP) return CABLE_BP_UNKNOWN;
  int i = dnotes_index(d, lab, nth);
  return i >= 0 ? d->bp_kind[i] : CABLE_BP_UNKNOWN;
}
