/* SPDX-License-Identifier: GPL-3.0-or-later */
/* `cable info e=NAME` and Python's info('NAME'): what a new study needs to
 * know about a problem without reading its source: its dimensions, its
 * parameters and components by index and name, its own constants keys with
 * their ranges and defaults, and the constants it recommends (the settings
 * its scenes use, the defaults of a keywords-only first run). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "braid_model.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_problem.h"
#include "cable_session_impl.h"

#define INFO_MAX_NDIM 64   /* a test problem's STPNT is asked only up to this size */

static void write_key(const cable_problem_key *k, FILE *out)
{
  fprintf(out, "  %-8s ", k->name);
  if (k->type == CABLE_KEY_INT) fprintf(out, "integer %.0f..%.0f, default %.0f", k->min, k->max, k->def);
  else fprintf(out, "real %g..%g, default %g", k->min, k->max, k->def);
  for (const cable_key_word *w = k->words; w && w->word; w++)
    fprintf(out, "%s'%s' = %g", w == k->words ? " (or " : ", ", w->word, w->value);
  if (k->words && k->words->word) fputc(')', out);
  fprintf(out, ": %s\n", k->help ? k->help : "");
}

/* Index and name, six to a line; unnamed ones as PAR(k) or U(k) (prefix). */
static void write_names(const char *prefix, const char *const *names, int n, FILE *out)
{
  for (int k = 0; k < n; k++) {
    char cell[48];
    const char *nm = names && names[k] ? names[k] : "";
    if (nm[0]) snprintf(cell, sizeof cell, "%3d %s", k + 1, nm);
    else snprintf(cell, sizeof cell, "%3d %s(%d)", k + 1, prefix, k + 1);
    fprintf(out, "%s%-14s", k % 6 == 0 ? (k ? "\n  " : "  ") : " ", cell);
  }
  fprintf(out, "%s", n > 0 ? "\n" : "");
}

/* The parameter values a start from STPNT gives unless PAR={...} does (NAN:
 * none, set by the geometry, or required): the braid problems' material
 * (braid_start_params_init's defaults), a problem without prepare its
 * STPNT's values at t = 0.  1 when any is known. */
static int start_values(const cable_problem *pb, double *par, int npar)
{
  for (int k = 0; k < npar; k++) par[k] = (double)NAN;
  /* braid_link_sym has no start from STPNT (braid_prepare) */
  if (pb->name && braid_problem_find(pb->name) && strcmp(pb->name, "braid_link_sym") != 0 && npar >= BP_NPAR) {
    braid_start_params sp;
    braid_start_params_init(&sp, BRAID_START_TORUS, 0, 1, 0.0, 0.0, 0.0);
    par[BP_T] = sp.torque;
    par[BP_B1] = sp.b1;
    par[BP_B2] = sp.b2;
    par[BP_C1] = sp.c1;
    par[BP_C2] = sp.c2;
    par[BP_W01] = sp.w01;
    par[BP_W02] = sp.w02;
    return 1;
  }
  if (pb->prepare || !pb->stpnt || pb->ndim < 1 || pb->ndim > INFO_MAX_NDIM) return 0;
  double u[INFO_MAX_NDIM];
  return pb->stpnt(pb->ndim, 0.0, u, par, pb->params) == 0;
}

int rp_problem_info_write(const cable_problem *pb, const char *source, FILE *out)
{
  fprintf(out, "problem %s: %s\n", pb->name ? pb->name : "?", pb->description ? pb->description : "");
  if (source) {
    fprintf(out, "  an AUTO equation file (%s): NDIM, NBC, NINT and NPAR come from the constants, as in AUTO;\n"
                 "  its parameters are PAR(1)..PAR(NPAR) and its components U(1)..U(NDIM) (no names: name them\n"
                 "  in the constants file with parnames={1: 'lambda'} and unames={1: 'u'}); doc/auto-users.md\n",
            source);
    return 0;
  }
  fprintf(out, "  NDIM=%d, NBC=%d, NINT=%d (fixed by the problem: a constants value that differs is an error)\n",
          pb->ndim, pb->nbc, pb->nint);
  fprintf(out, "parameters (ICP, UZR, THL and PAR={...} take these names or PAR(k)):\n");
  write_names("PAR", pb->parnames, pb->npar, out);
  fprintf(out, "components (sol['name'] or sol['U(i)'], THU, unames):\n");
  write_names("U", pb->unames, pb->ndim, out);
  double par[CABLE_NAMES_MAX];
  int npar = pb->npar < CABLE_NAMES_MAX ? pb->npar : CABLE_NAMES_MAX, any = 0;
  if (npar > 0 && start_values(pb, par, npar)) {
    fprintf(out, "start values (what a start from STPNT gives unless PAR={...} does):\n ");
    for (int k = 0; k < npar; k++)
      if (!isnan(par[k])) {
        fprintf(out, "%s %s = %.10g", any ? "," : "", pb->parnames && pb->parnames[k] ? pb->parnames[k] : "?", par[k]);
        any = 1;
      }
    fprintf(out, "%s\n", any ? "" : " none");
    if (pb->name && braid_problem_find(pb->name) && strcmp(pb->name, "braid_link_sym") != 0)
      fprintf(out, "  the geometry comes from TORUS, HAND and PAR={'Delta': ..., '%s': ...}, which a start needs\n",
              strncmp(pb->name, "braid_knot", 10) == 0 ? "Ltot" : "L");
  }
  fprintf(out, "keys (the problem's own constants, KEY=VALUE in a constants file or a run's keywords):\n");
  if (pb->nkeys == 0 || !pb->keys) fprintf(out, "  none\n");
  for (int k = 0; k < pb->nkeys && pb->keys; k++) write_key(&pb->keys[k], out);
  const char *rec = pb->name ? cable_problem_recommended(pb->name) : NULL;
  fprintf(out, "recommended constants (the defaults of a first run with no constants file and no start; every "
               "other key\nhas AUTO's default, doc/constants.md):\n");
  fprintf(out, "  %s\n", rec ? rec : "none beyond AUTO's defaults");
  return 0;
}
