/* `cable info e=NAME` and Python's info('NAME'): what a new study needs to
 * know about a problem without reading its source: its dimensions, its
 * parameters and components by index and name, its own constants keys with
 * their ranges and defaults, and the constants it recommends (the settings
 * its scenes use, the defaults of a keywords-only first run). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_problem.h"
#include "cable_session_impl.h"

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
  fprintf(out, "keys (the problem's own constants, KEY=VALUE in a constants file or a run's keywords):\n");
  if (pb->nkeys == 0 || !pb->keys) fprintf(out, "  none\n");
  for (int k = 0; k < pb->nkeys && pb->keys; k++) write_key(&pb->keys[k], out);
  const char *rec = pb->name ? cable_problem_recommended(pb->name) : NULL;
  fprintf(out, "recommended constants (the defaults of a first run with no constants file and no start; every "
               "other key\nhas AUTO's default, doc/constants.md):\n");
  fprintf(out, "  %s\n", rec ? rec : "none beyond AUTO's defaults");
  return 0;
}
