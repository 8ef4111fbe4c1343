/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable_commands.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_analysis.h"
#include "cable/cable_stability.h"
#include "braid_state.h"
#include "cable/cable_names.h"
#include "cable/cable_session.h"
#include "cable/cable_status.h"

/* The run's keywords that take names: their slot in the arguments, or NULL. */
static const char **name_slot(cable_run_args *a, const char *key)
{
  if (strcmp(key, "c") == 0) return &a->c;
  if (strcmp(key, "e") == 0) return &a->e;
  if (strcmp(key, "s") == 0) return &a->s;
  if (strcmp(key, "sv") == 0) return &a->sv;
  if (strcmp(key, "ap") == 0) return &a->ap;
  return NULL;
}

/* A name as given, without one pair of surrounding quotes. */
static void unquote(const char *v, char *out, size_t len)
{
  size_t n = strlen(v);
  if (n >= 2 && (v[0] == '\'' || v[0] == '"') && v[n - 1] == v[0]) snprintf(out, len, "%.*s", (int)(n - 2), v + 1);
  else snprintf(out, len, "%s", v);
}

int cable_cmd_info(const char *e, FILE *out, cable_error *err)
{
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = ".";
  o.log = stderr;
  cable_session *r = cable_session_alloc(&o);
  if (!r) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  int rc = cable_session_info(r, e, out, err);
  cable_session_free(r);
  return rc;
}

#define CLI_MAX_ARGS 256   /* arguments of one `cable run` */

/* Each KEY=VALUE is what a constants file line would say (bare words are
 * strings there: IRS=BP1, LINSOLVER=klu); only DS=- needs its quotes,
 * because a lone '-' is not a value in the file syntax. */
int cable_cmd_run(int argc, char **argv, int (*interrupt)(void *ctx), void *ctx, cable_error *err)
{
  if (argc > CLI_MAX_ARGS)
    return cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, NULL, "more than %d arguments", CLI_MAX_ARGS);
  cable_run_args a;
  memset(&a, 0, sizeof a);
  char names[5][CABLE_NAME_MAX];
  int nnames = 0, nover = 0, rc = 0;
  const char **over = calloc((size_t)argc + 1, sizeof *over);
  char **owned = calloc((size_t)argc + 1, sizeof *owned);
  if (!over || !owned) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  /* `cable run NAME ...` is AUTO's run('NAME'): e='NAME', c='NAME' */
  const char *runname = argc > 0 && !strchr(argv[0], '=') ? argv[0] : NULL;
  if (runname && (!runname[0] || strlen(runname) >= CABLE_NAME_MAX))
    rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, runname, "not a run name");
  for (int i = runname ? 1 : 0; i < argc && !rc; i++) {
    const char *eq = strchr(argv[i], '=');
    char key[64];
    if (!eq || eq == argv[i] || (size_t)(eq - argv[i]) >= sizeof key) {
      rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i],
                           "arguments are NAME (first) and KEY=VALUE (for example c=knot72 NMX=50)");
      break;
    }
    snprintf(key, sizeof key, "%.*s", (int)(eq - argv[i]), argv[i]);
    if (!eq[1]) {
      rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, key, "no value after '=' (in '%s')", argv[i]);
      break;
    }
    for (int j = 0; j < i; j++)
      if (strncmp(argv[j], argv[i], (size_t)(eq - argv[i]) + 1) == 0)
        rc = cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, key, "given twice ('%s' and '%s')", argv[j],
                             argv[i]);
    if (rc) break;
    const char **slot = name_slot(&a, key);
    if (slot) {
      unquote(eq + 1, names[nnames], sizeof names[nnames]);
      *slot = names[nnames++];
    } else if (strcmp(eq + 1, "-") == 0) {
      size_t len = strlen(argv[i]) + 3;
      if (!(owned[nover] = malloc(len))) {
        rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
        break;
      }
      snprintf(owned[nover], len, "%s='-'", key);
      over[nover] = owned[nover];
      nover++;
    } else {
      over[nover++] = argv[i];
    }
  }
  if (!rc) {
    cable_session_options o;
    cable_session_options_init(&o);
    o.dir = ".";
    o.interrupt = interrupt;
    o.interrupt_ctx = ctx;
    cable_session *r = cable_session_alloc(&o);
    a.name = runname;
    a.nover = nover;
    a.over = over;
    a.over_file = "<command line>";
    cable_branch *b = NULL;
    rc = r ? cable_session_run(r, &a, &b, err) : cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    cable_branch_decref(b);
    cable_session_free(r);
  }
  for (int k = 0; owned && k < argc; k++) free(owned[k]);
  free(owned);
  free(over);
  return rc;
}

int cable_cmd_table(const char *bfile, FILE *out, cable_error *err)
{
  cable_bfile *b = cable_bfile_read(bfile, err);
  if (!b) return err->status ? err->status : CABLE_ERR_IO;
  for (int s = 0; s < b->nbranch; s++) {
    const cable_bfile_branch *br = &b->branch[s];
    fprintf(out, "%s  BR    PT  TY  LAB", s ? "\n" : "");
    for (int j = 0; j < br->ncol; j++) fprintf(out, " %15.15s", br->colname[j]);
    fputc('\n', out);
    for (int i = 0; i < br->nrow; i++) {
      const char *ty = cable_type_name(br->ty[i]);
      fprintf(out, "%4d %5d  %-2s %4d", br->br[i], br->pt[i], ty, br->lab[i]);
      for (int j = 0; j < br->ncol; j++) fprintf(out, " %15.8g", br->data[(size_t)j * (size_t)br->nrow + (size_t)i]);
      fputc('\n', out);
    }
  }
  cable_bfile_free(b);
  return 0;
}

/* The d. or b. file beside s.NAME; 0 when sfile is not named s.NAME. */
static int sibling(const char *sfile, char type, char *path, size_t len)
{
  const char *base = strrchr(sfile, '/');
  base = base ? base + 1 : sfile;
  if (strncmp(base, "s.", 2) != 0) return 0;
  snprintf(path, len, "%.*s%c.%s", (int)(base - sfile), sfile, type, base + 2);
  return 1;
}

/* The error estimate that the d-file records for the nth (0, 1, ...) stored
 * solution with label lab (a label repeats in a file of several runs; the
 * d-file has them in the s-file's order). */
static double dfile_error_estimate(const char *sfile, int lab, int nth)
{
  char path[1024];
  if (!sibling(sfile, 'd', path, sizeof path)) return -1;
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  char line[512];
  double est = -1;
  while (fgets(line, sizeof line, f)) {
    int l;
    const char *e = strstr(line, "error estimate ");
    if (sscanf(line, " Solution label %d", &l) == 1 && l == lab && e && nth-- == 0) {
      est = strtod(e + 15, NULL);
      break;
    }
  }
  fclose(f);
  return est;
}

/* The parameter columns of solution x's row in the b-file (the principal
 * parameter and the other ICP columns; not L2-NORM or MAX U).  0 when the
 * b-file has no row with x's label, branch and point. */
static int bfile_parameters(const cable_bfile *b, const cable_solution *x, FILE *out)
{
  for (int k = 0; b && k < b->nbranch; k++) {
    const cable_bfile_branch *br = &b->branch[k];
    for (int i = 0; i < br->nrow; i++) {
      if (br->lab[i] != x->lab || br->br[i] != x->ibr || br->pt[i] != x->ntot) continue;
      for (int j = 0; j < br->ncol; j++) {
        const char *h = br->colname[j];
        if (j == 1 || strcmp(h, "L2-NORM") == 0 || strncmp(h, "MAX ", 4) == 0) continue;
        fprintf(out, " %s=%.10g", h, br->data[(size_t)j * (size_t)br->nrow + (size_t)i]);
      }
      return 1;
    }
  }
  return 0;
}

int cable_cmd_list(const char *sfile, FILE *out, cable_error *err)
{
  cable_sfile *s = cable_sfile_read(sfile, err);
  if (!s) return err->status ? err->status : CABLE_ERR_IO;
  cable_bfile *b = NULL;   /* read only when a solution lacks its free-parameter list */
  int b_tried = 0;
  fprintf(out, "  LAB  TY    BR    PT  NTST NCOL  error-est   free parameters\n");
  for (int i = 0; i < cable_sfile_count(s); i++) {
    const cable_solution *x = cable_sfile_get(s, i);
    int nth = 0;
    for (int q = 0; q < i; q++) nth += cable_sfile_get(s, q)->lab == x->lab;
    double e = x->err_est >= 0 ? x->err_est : dfile_error_estimate(sfile, x->lab, nth);
    fprintf(out, "%5d  %-2s %5d %5d %5d %4d  ", x->lab, cable_type_name(x->itp), x->ibr, x->ntot, x->ntst, x->ncol);
    if (e >= 0) fprintf(out, "%9.2e  ", e);
    else fprintf(out, "%9s  ", "-");
    /* the free-parameter indices come with the direction (icp -1 without
       it: IIS=0, or AUTO's 12-integer headers) */
    int shown = 0;
    for (int q = 0; q < x->nfpr; q++)
      if (x->icp[q] >= 0 && x->icp[q] < x->npar) {
        fprintf(out, " PAR(%d)=%.10g", x->icp[q] + 1, x->par[x->icp[q]]);
        shown++;
      }
    if (!shown) {
      char path[1024];
      if (!b_tried && sibling(sfile, 'b', path, sizeof path)) {
        cable_error berr;
        b = cable_bfile_read(path, &berr);   /* optional: a missing b-file is no error */
      }
      b_tried = 1;
      if (!bfile_parameters(b, x, out)) fputs(" (not stored: no direction in the s-file, no b-file row)", out);
    }
    fputc('\n', out);
  }
  cable_bfile_free(b);
  cable_sfile_free(s);
  return 0;
}

/* Where one strand's contact pressure changes sign (braid_analysis.h). */
static void print_psign(FILE *out, const char *what, const double *x, int n)
{
  if (n <= 0) return;
  fprintf(out, "    sign changes of %s", what);
  for (int i = 0; i < n && i < CABLE_BRAID_PSIGN_MAX; i++) fprintf(out, " %.6f", x[i]);
  fputc('\n', out);
}

int cable_cmd_analyze(const char *sfile, int nlab, char **labels, FILE *out, cable_error *err)
{
  /* STAB=1 among the arguments: the Morse index too (doc/stability.md S7) */
  int stab = 0, nl = 0;
  for (int i = 0; i < nlab; i++) {
    if (strncmp(labels[i], "STAB=", 5) == 0) {
      if (strcmp(labels[i] + 5, "0") != 0 && strcmp(labels[i] + 5, "1") != 0)
        return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "STAB", "STAB=0 or STAB=1, got '%s'", labels[i]);
      stab = labels[i][5] == '1';
      continue;
    }
    labels[nl++] = labels[i];
  }
  nlab = nl;
  cable_sfile *s = cable_sfile_read(sfile, err);
  if (!s) return err->status ? err->status : CABLE_ERR_IO;
  int rc = 0;
  for (int i = 0; i < nlab && rc == 0; i++) {
    const cable_solution *x = cable_sfile_find(s, labels[i], err);
    if (!x) {
      rc = err->status ? err->status : CABLE_ERR_NOTFOUND;
      break;
    }
    cable_braid_analysis a;
    rc = cable_braid_analysis_compute(x, &a);
    if (rc) {
      cable_error_set(err, rc, sfile, 0, labels[i], "label %d is not a closed braid solution (%s)", x->lab,
                      cable_status_message(rc));
      break;
    }
    const cable_knot_type_result *k = &a.topo.axis;
    fprintf(out, "label %d (%s): T = %.10g  F = %.10g  L = %.10g  L2 = %.10g\n", x->lab, cable_type_name(x->itp),
            x->par[BP_T], x->par[BP_F], x->par[BP_L], x->par[BP_L2]);
    fprintf(out, "  Lk = %.8f  Tw = %.8f  Wr = %.8f  (%s; Lk - nearest %s = %.1e)\n", a.topo.lk, a.topo.tw, a.topo.wr,
            a.topo.closure < 0 ? "knot" : "link", a.topo.closure < 0 ? "half-integer" : "integer", a.topo.lk_defect);
    fprintf(out, "  braid axis: %s%s (crossing number %d), Lk inside the companion's tube = %.4g\n",
            k->handedness > 0 ? "right-handed " : k->handedness < 0 ? "left-handed " : "", k->name,
            k->crossing_number, a.topo.lk_in_tube);
    fprintf(out, "  contact pressure: strand 1 in [%.6g, %.6g], strand 2 in [%.6g, %.6g]; sign changes %d\n",
            a.pmin1, a.pmax1, a.pmin2, a.pmax2, a.psign1.n);
    print_psign(out, "strand 1 at s =", a.psign1.s, a.psign1.n);
    print_psign(out, "strand 2 at sigma =", a.psign2.sigma, a.psign2.n);
    fprintf(out, "  tubes: closest non-adjacent approach %.4f Delta (%s), axis %.4f Delta\n", a.tube.dmin,
            a.tube.dmin < 1 ? "overlap" : "no overlap", a.tube.axis_dmin);
    fprintf(out, "  first integrals drift %.2e; material closure %.6f%s\n", a.drift, a.closure,
            a.topo.closure < 0 ? " (pi for a closed material frame)" : "");
    if (a.topo.closure > 0) fprintf(out, "  material closure of strand 2 %.6f\n", a.closure2);
    if (stab) {
      cable_stab_result r;
      /* a knot computed with eps13 free is a braid_knot_sym solution (the
         mode branches): its second variation has the row delta F2(0) = 0 */
      int sym = 0;
      for (int j = 0; j < x->nfpr; j++) sym |= x->icp[j] == BP_EPS13;
      const cable_problem *pb =
        cable_problem_builtin(a.topo.closure < 0 ? (sym ? "braid_knot_sym" : "braid_knot") : "braid_link");
      rc = cable_stability_index(pb, x, 1, x->ncol, &r, err);
      if (rc) break;
      fprintf(out, "  stability: Morse index %d (%s), zero eigenvalues %d; smallest eigenvalues", r.index,
              r.index == 0 && r.nzero == 0 ? "stable" : "unstable", r.nzero);
      for (int j = 0; j < r.neig && j < 4; j++) fprintf(out, " %.6g", r.eig[j]);
      fputc('\n', out);
    }
  }
  cable_sfile_free(s);
  return rc;
}
