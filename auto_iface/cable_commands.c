#include "cable_commands.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aufile.h"
#include "braid_analysis.h"
#include "braid_resolver.h"
#include "braid_state.h"
#include "cable_status.h"
#include "names.h"
#include "script.h"
#include "script_host_cable.h"

/* keys whose values are names (quoted in the generated run(...) call) */
static int is_name_key(const char *key, size_t len)
{
  static const char *const names[] = {"c", "e", "s", "sv", "ap", "dat"};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
    if (strlen(names[i]) == len && strncmp(key, names[i], len) == 0) return 1;
  return 0;
}

int cable_cmd_run(int argc, char **argv, cable_error *err)
{
  size_t cap = 64;
  for (int i = 0; i < argc; i++) cap += strlen(argv[i]) + 8;
  char *text = malloc(cap);
  if (!text) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  size_t n = (size_t)snprintf(text, cap, "run(");
  for (int i = 0; i < argc; i++) {
    const char *eq = strchr(argv[i], '=');
    if (!eq || eq == argv[i]) {
      free(text);
      return cable_error_set(err, CABLE_ERR_INPUT, "<command line>", 0, argv[i],
                             "arguments are KEY=VALUE (for example c=knot72 NMX=50)");
    }
    size_t klen = (size_t)(eq - argv[i]);
    int quote = is_name_key(argv[i], klen) && eq[1] != '\'' && eq[1] != '"';
    n += (size_t)snprintf(text + n, cap - n, "%s%.*s=%s%s%s", i ? ", " : "", (int)klen, argv[i],
                          quote ? "'" : "", eq + 1, quote ? "'" : "");
  }
  snprintf(text + n, cap - n, ")\n");
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = ".";
  o.problems = cable_braid_resolver();
  cable_replay *r = cable_replay_alloc(&o);
  int rc = r ? script_run_string("<command line>", text, cable_replay_host(r), err)
             : cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  cable_replay_free(r);
  free(text);
  return rc;
}

int cable_cmd_replay(const char *script, cable_error *err)
{
  char dir[1024];
  snprintf(dir, sizeof dir, "%s", script);
  char *slash = strrchr(dir, '/');
  if (slash) *slash = '\0';
  else snprintf(dir, sizeof dir, ".");
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = dir;
  o.problems = cable_braid_resolver();
  return cable_replay_run_file(script, &o, err);
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

/* Error estimates that the d-file records for stored labels. */
static double dfile_error_estimate(const char *sfile, int lab)
{
  char path[1024];
  const char *base = strrchr(sfile, '/');
  base = base ? base + 1 : sfile;
  if (strncmp(base, "s.", 2) != 0) return -1;
  snprintf(path, sizeof path, "%.*sd.%s", (int)(base - sfile), sfile, base + 2);
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  char line[512];
  double est = -1;
  while (fgets(line, sizeof line, f)) {
    int l;
    const char *e = strstr(line, "error estimate ");
    if (sscanf(line, " Solution label %d", &l) == 1 && l == lab && e) est = strtod(e + 15, NULL);
  }
  fclose(f);
  return est;
}

int cable_cmd_list(const char *sfile, FILE *out, cable_error *err)
{
  cable_sfile *s = cable_sfile_read(sfile, err);
  if (!s) return err->status ? err->status : CABLE_ERR_IO;
  fprintf(out, "  LAB  TY    BR    PT  NTST NCOL  error-est   free parameters\n");
  for (int i = 0; i < cable_sfile_count(s); i++) {
    const cable_solution *x = cable_sfile_get(s, i);
    double e = x->err_est >= 0 ? x->err_est : dfile_error_estimate(sfile, x->lab);
    fprintf(out, "%5d  %-2s %5d %5d %5d %4d  ", x->lab, cable_type_name(x->itp), x->ibr, x->ntot, x->ntst, x->ncol);
    if (e >= 0) fprintf(out, "%9.2e  ", e);
    else fprintf(out, "%9s  ", "-");
    for (int q = 0; q < x->nfpr; q++) fprintf(out, " PAR(%d)=%.10g", x->icp[q] + 1, x->par[x->icp[q]]);
    fputc('\n', out);
  }
  cable_sfile_free(s);
  return 0;
}

/* Where one strand's contact pressure changes sign (braid_analysis.h). */
static void print_psign(FILE *out, const char *what, const double *x, int n)
{
  if (n <= 0) return;
  fprintf(out, "    sign changes of %s", what);
  for (int i = 0; i < n && i < BRAID_PSIGN_MAX; i++) fprintf(out, " %.6f", x[i]);
  fputc('\n', out);
}

int cable_cmd_analyze(const char *sfile, int nlab, char **labels, FILE *out, cable_error *err)
{
  cable_sfile *s = cable_sfile_read(sfile, err);
  if (!s) return err->status ? err->status : CABLE_ERR_IO;
  int rc = 0;
  for (int i = 0; i < nlab && rc == 0; i++) {
    const cable_solution *x = cable_sfile_find(s, labels[i], err);
    if (!x) {
      rc = err->status ? err->status : CABLE_ERR_NOTFOUND;
      break;
    }
    braid_analysis a;
    rc = braid_analysis_compute(x, &a);
    if (rc) {
      cable_error_set(err, rc, sfile, 0, labels[i], "label %d is not a closed braid solution (%s)", x->lab,
                      cable_status_message(rc));
      break;
    }
    const knot_type_result *k = &a.topo.axis;
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
  }
  cable_sfile_free(s);
  return rc;
}
