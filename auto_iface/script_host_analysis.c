/* Scene post-processing functions of the run host, computed only for the
 * solutions a script names (never during continuation):
 *
 *   analyze(sol)                  -> dict: Lk, Tw, Wr, knot, hand, crossings,
 *                                    lk_in_tube, pmin, psign, dmin, axis_dmin,
 *                                    drift, closure, err
 *   compare('table.txt', rows, ref=sol)
 *       rows: [[name, sol, F_target, Lk_target], ...]; writes the comparison
 *       table (atomically, in the run directory) and prints it.  ref: a
 *       solution of the unbuckled branch; (Lk - Lk_ref)/2 counts the
 *       self-crossing passages of the braid axis since then. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "atomic_file.h"
#include "braid_analysis.h"
#include "braid_state.h"
#include "cable_status.h"
#include "script_host_impl.h"

static const cable_solution *handle_solution(const script_value *v)
{
  if (script_handle_kind(v) != SCRIPT_HANDLE_SOLUTION) return NULL;
  const rp_sol *so = script_handle_ptr(v);
  return so->br->sol[so->isol];
}

static int dict_num(script_value *d, const char *key, double x)
{
  script_value k;
  int rc = script_string_new(&k, key, strlen(key));
  if (rc) return rc;
  return script_dict_set(d, k, script_number(x));
}

static int dict_str(script_value *d, const char *key, const char *s)
{
  script_value k, v;
  int rc = script_string_new(&k, key, strlen(key));
  if (rc) return rc;
  rc = script_string_new(&v, s, strlen(s));
  if (rc) {
    script_value_release(&k);
    return rc;
  }
  return script_dict_set(d, k, v);
}

static int analyze_solution(const cable_solution *s, braid_analysis *a, cable_error *err)
{
  int rc = braid_analysis_compute(s, a);
  if (rc)
    return cable_error_set(err, rc, NULL, 0, NULL, "label %d is not a closed braid solution (%s)", s->lab,
                           cable_status_message(rc));
  return 0;
}

static int fn_analyze(int nargs, const script_value *args, script_value *out, cable_error *err)
{
  const cable_solution *s = nargs == 1 ? handle_solution(&args[0]) : NULL;
  if (!s) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "analyze(sol) takes one solution");
  braid_analysis a;
  int rc = analyze_solution(s, &a, err);
  if (rc) return rc;
  script_value d;
  if ((rc = script_dict_new(&d))) return rc;
  const knot_type_result *k = &a.topo.axis;
  rc = dict_num(&d, "Lk", a.topo.lk);
  if (!rc) rc = dict_num(&d, "Tw", a.topo.tw);
  if (!rc) rc = dict_num(&d, "Wr", a.topo.wr);
  if (!rc) rc = dict_str(&d, "knot", k->name);
  if (!rc) rc = dict_num(&d, "hand", k->handedness);
  if (!rc) rc = dict_num(&d, "crossings", k->crossing_number);
  if (!rc) rc = dict_num(&d, "lk_in_tube", a.topo.lk_in_tube);
  if (!rc) rc = dict_num(&d, "pmin", fmin(a.pmin1, a.pmin2));
  if (!rc) rc = dict_num(&d, "psign", a.psign_changes);
  if (!rc) rc = dict_num(&d, "dmin", a.tube.dmin);
  if (!rc) rc = dict_num(&d, "axis_dmin", a.tube.axis_dmin);
  if (!rc) rc = dict_num(&d, "drift", a.drift);
  if (!rc) rc = dict_num(&d, "closure", a.closure);
  if (!rc) rc = dict_num(&d, "err", s->err_est);
  if (rc) {
    script_value_release(&d);
    return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  }
  *out = d;
  return 0;
}

static void knot_text(const knot_type_result *k, char *buf, size_t len)
{
  snprintf(buf, len, "%s%s", k->handedness > 0 ? "right " : k->handedness < 0 ? "left " : "", k->name);
}

static int fn_compare(cable_replay *r, int nargs, const script_value *args, const script_kwargs *kw,
                      cable_error *err)
{
  const char *file = nargs == 2 ? script_string_chars(&args[0]) : NULL;
  const script_value *rows = nargs == 2 ? &args[1] : NULL;
  if (!file || !rows || rows->type != SCRIPT_LIST)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "compare('file', [[name, sol, F_target, Lk_target], ...], ref=sol)");
  const script_value *refv = script_kwargs_find(kw, "ref");
  const cable_solution *ref = refv ? handle_solution(refv) : NULL;
  if (refv && !ref) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "ref", "ref must be a solution");
  double lk_ref = NAN;
  braid_analysis a;
  int rc;
  if (ref) {
    if ((rc = analyze_solution(ref, &a, err))) return rc;
    lk_ref = a.topo.lk;
  }
  char path[1100];
  snprintf(path, sizeof path, "%s%s%s", r->opt.dir && r->opt.dir[0] ? r->opt.dir : "",
           r->opt.dir && r->opt.dir[0] ? "/" : "", file);
  cable_atomic_file *af = cable_atomic_open(path, 0, err);
  if (!af) return err->status ? err->status : CABLE_ERR_IO;
  FILE *f = cable_atomic_stream(af);
  fprintf(f, "# point: the paper's point; T: its torque (the UZ label); F: paper and cable; rel: |dF|/F\n"
             "# Lk = Tw + Wr of the contact-curve ribbon; pass: self-crossing passages of the braid axis\n"
             "# since the reference, (Lk - Lk_ref)/2; Lk_tube: Lk minus the companion's crossing number\n"
             "# (the paper's 'linking number', quoted in brackets); pmin: minimum contact force per length;\n"
             "# dmin: closest approach of non-adjacent strand centrelines / Delta (< 1: tubes overlap);\n"
             "# err: discretisation-error estimate of the stored solution\n");
  fprintf(f, "%-5s %4s %12s %12s %14s %9s %9s %4s %15s %-22s %11s %7s %9s\n", "point", "LAB", "T", "F_paper",
          "F_cable", "rel", "Lk", "pass", "Lk_tube(paper)", "braid axis", "pmin", "dmin", "err");
  for (size_t i = 0; i < script_list_len(rows); i++) {
    const script_value *row = script_list_get(rows, i);
    const cable_solution *s = row && row->type == SCRIPT_LIST && script_list_len(row) == 4
                                  ? handle_solution(script_list_get(row, 1)) : NULL;
    const char *name = s ? script_string_chars(script_list_get(row, 0)) : NULL;
    const script_value *fv = s ? script_list_get(row, 2) : NULL, *lv = s ? script_list_get(row, 3) : NULL;
    if (!s || !name || fv->type != SCRIPT_NUMBER || lv->type != SCRIPT_NUMBER) {
      cable_atomic_abort(af);
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                             "compare: row %zu must be [name, solution, F_target, Lk_target]", i + 1);
    }
    if ((rc = analyze_solution(s, &a, err))) {
      cable_atomic_abort(af);
      return rc;
    }
    double F = s->par[BP_F], Ft = fv->num;
    char kt[64], tube[40];
    knot_text(&a.topo.axis, kt, sizeof kt);
    snprintf(tube, sizeof tube, "%.4g (%.4g)", a.topo.lk_in_tube, lv->num);
    fprintf(f, "%-5s %4d %12.6f %12.6f %14.7f %9.2e %9.5f %4.0f %15s %-22s %11.4g %7.3f %9.2e\n", name, s->lab,
            s->par[BP_T], Ft, F, fabs(F - Ft) / fabs(Ft), a.topo.lk, isnan(lk_ref) ? (double)NAN : (a.topo.lk - lk_ref) / 2,
            tube, kt, fmin(a.pmin1, a.pmin2), a.tube.dmin, s->err_est);
  }
  rc = cable_atomic_commit(af, err);
  if (rc) return rc;
  FILE *in = fopen(path, "r");
  char line[512];
  while (in && fgets(line, sizeof line, in)) fputs(line, r->opt.log ? r->opt.log : stdout);
  if (in) fclose(in);
  return 0;
}

int rp_call(void *ctx, const char *name, int nargs, const script_value *args, const script_kwargs *kw,
            script_value *out, cable_error *err)
{
  cable_replay *r = ctx;
  if (strcmp(name, "analyze") == 0) return fn_analyze(nargs, args, out, err);
  if (strcmp(name, "compare") == 0) return fn_compare(r, nargs, args, kw, err);
  return CABLE_ERR_NOTFOUND;
}
