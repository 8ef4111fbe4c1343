/* Scene post-processing functions of the run host, computed only for the
 * solutions a script names (never during continuation):
 *
 *   analyze(sol)                  -> dict: Lk, Tw, Wr, knot, hand, crossings,
 *                                    lk_in_tube, pmin, psign, dmin, axis_dmin,
 *                                    drift, closure, err
 *   compare('table.txt', rows, ref=sol, notes=['line', ...])
 *       rows: [[name, sol, F_target, Lk_target(, ref)], ...]; writes the comparison
 *       table (atomically, in the run directory) and prints it.  ref: a
 *       solution of the unbuckled branch; (Lk - Lk_ref)/2 counts the
 *       self-crossing passages of the braid axis since then.  notes: lines
 *       written after the table (the scene's own tabulations).
 *   plot('fig.png', ['flat', 'mode1', ...], marks=[[sol, '(a)'], ...],
 *        x='T', y='F', title='...')
 *       a bifurcation diagram of the saved b-files b.flat, b.mode1, ... in the
 *       run directory, with the marked solutions as open circles
 *   render(sol, 'fig.png', view=[x, y, z], size=600, thicken=0, vtp='f.vtp', ply='f.ply')
 *       a shaded picture of a braid solution with its pressure profiles
 *   overlap_free(result)          -> [[T_from, T_to], ...]
 *       the stretches of each branch (in branch order, T at their ends) where
 *       the strand tubes do not overlap (dmin > 1), from the labelled
 *       solutions; an end between two labels is interpolated linearly in
 *       dmin, so its accuracy is the label spacing (NPR) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "braid_analysis.h"
#include "braid_state.h"
#include "cable_pictures.h"
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
    size_t nrow = row && row->type == SCRIPT_LIST ? script_list_len(row) : 0;
    const cable_solution *s = nrow == 4 || nrow == 5 ? handle_solution(script_list_get(row, 1)) : NULL;
    const cable_solution *rref = nrow == 5 ? handle_solution(script_list_get(row, 4)) : NULL;
    double lk_row_ref = lk_ref;
    const char *name = s ? script_string_chars(script_list_get(row, 0)) : NULL;
    const script_value *fv = s ? script_list_get(row, 2) : NULL, *lv = s ? script_list_get(row, 3) : NULL;
    if (!s || !name || fv->type != SCRIPT_NUMBER || lv->type != SCRIPT_NUMBER) {
      cable_atomic_abort(af);
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                             "compare: row %zu must be [name, solution, F_target, Lk_target(, reference solution)]",
                             i + 1);
    }
    if (nrow == 5) {
      if (!rref || (rc = analyze_solution(rref, &a, err))) {
        cable_atomic_abort(af);
        return rref ? rc : cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "compare: row %zu: the reference must be a solution", i + 1);
      }
      lk_row_ref = a.topo.lk;
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
            s->par[BP_T], Ft, F, fabs(F - Ft) / fabs(Ft), a.topo.lk, isnan(lk_row_ref) ? (double)NAN : (a.topo.lk - lk_row_ref) / 2,
            tube, kt, fmin(a.pmin1, a.pmin2), a.tube.dmin, s->err_est);
  }
  const script_value *notes = script_kwargs_find(kw, "notes");
  if (notes && notes->type != SCRIPT_LIST) {
    cable_atomic_abort(af);
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "notes", "notes must be a list of strings");
  }
  if (notes && script_list_len(notes) > 0) fputc('\n', f);
  for (size_t i = 0; notes && i < script_list_len(notes); i++) {
    const char *line = script_string_chars(script_list_get(notes, i));
    if (!line) {
      cable_atomic_abort(af);
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "notes", "notes entry %zu is not a string", i + 1);
    }
    fprintf(f, "%s\n", line);
  }
  rc = cable_atomic_commit(af, err);
  if (rc) return rc;
  FILE *in = fopen(path, "r");
  char line[512];
  while (in && fgets(line, sizeof line, in)) fputs(line, r->opt.log ? r->opt.log : stdout);
  if (in) fclose(in);
  return 0;
}

static void run_path(const cable_replay *r, const char *file, char *buf, size_t len)
{
  int rel = file[0] != '/' && r->opt.dir && r->opt.dir[0];
  snprintf(buf, len, "%s%s%s", rel ? r->opt.dir : "", rel ? "/" : "", file);
}

static const char *kw_str(const script_kwargs *kw, const char *name)
{
  const script_value *v = script_kwargs_find(kw, name);
  return v ? script_string_chars(v) : NULL;
}

#define PLOT_MAX_FILES 64
#define PLOT_MAX_MARKS 64

static int fn_plot(cable_replay *r, int nargs, const script_value *args, const script_kwargs *kw, cable_error *err)
{
  const char *file = nargs == 2 ? script_string_chars(&args[0]) : NULL;
  const script_value *names = nargs == 2 ? &args[1] : NULL;
  if (!file || !names || names->type != SCRIPT_LIST || script_list_len(names) < 1 ||
      script_list_len(names) > PLOT_MAX_FILES)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "plot('fig.png', ['name', ...] (1 to %d saved results), marks=[[sol, 'text'], ...])",
                           PLOT_MAX_FILES);
  char bnames[PLOT_MAX_FILES][CABLE_NAME_MAX + 3];
  const char *bf[PLOT_MAX_FILES];
  int nf = (int)script_list_len(names);
  for (int i = 0; i < nf; i++) {
    const char *nm = script_string_chars(script_list_get(names, (size_t)i));
    if (!nm) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "plot: result names must be strings");
    snprintf(bnames[i], sizeof bnames[i], "b.%s", nm);
    bf[i] = bnames[i];
  }
  plot_annotation marks[PLOT_MAX_MARKS];
  int nm = 0;
  const script_value *mv = script_kwargs_find(kw, "marks");
  const char *xc = kw_str(kw, "x"), *yc = kw_str(kw, "y");
  for (size_t i = 0; mv && i < script_list_len(mv) && nm < PLOT_MAX_MARKS; i++) {
    const script_value *m = script_list_get(mv, i);
    const cable_solution *s = m && script_list_len(m) == 2 ? handle_solution(script_list_get(m, 0)) : NULL;
    const char *text = s ? script_string_chars(script_list_get(m, 1)) : NULL;
    if (!s || !text)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "marks", "marks are [solution, 'text'] pairs");
    /* marks sit at (T, F) of the solution: the default axes of braid diagrams */
    if ((xc && strcmp(xc, "T") != 0) || (yc && strcmp(yc, "F") != 0))
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "marks", "marks are drawn on the default (T, F) axes only");
    marks[nm++] = (plot_annotation){s->par[BP_T], s->par[BP_F], text, 0};
  }
  char out[1200];
  run_path(r, file, out, sizeof out);
  int rc = cable_plot_files(r->opt.dir, bf, nf, xc, yc, marks, nm, kw_str(kw, "title"), out, err);
  if (!rc) fprintf(r->opt.log ? r->opt.log : stdout, "  diagram written to %s\n", out);
  return rc;
}

static int fn_render(cable_replay *r, int nargs, const script_value *args, const script_kwargs *kw,
                     cable_error *err)
{
  const cable_solution *s = nargs == 2 ? handle_solution(&args[0]) : NULL;
  const char *file = nargs == 2 ? script_string_chars(&args[1]) : NULL;
  if (!s || !file) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "render(sol, 'fig.png', view=[x, y, z], ...)");
  render_options o;
  memset(&o, 0, sizeof o);
  const script_value *v;
  if ((v = script_kwargs_find(kw, "view"))) {
    if (script_list_len(v) != 3) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "view", "view=[x, y, z]");
    for (size_t i = 0; i < 3; i++) o.view_dir[i] = script_list_get(v, i)->num;
  }
  if ((v = script_kwargs_find(kw, "size"))) o.width = o.height = (int)v->num;
  if ((v = script_kwargs_find(kw, "thicken"))) o.thicken = v->num;
  char out[1200], vtp[1200], ply[1200];
  run_path(r, file, out, sizeof out);
  const char *vn = kw_str(kw, "vtp"), *pn = kw_str(kw, "ply");
  if (vn) run_path(r, vn, vtp, sizeof vtp);
  if (pn) run_path(r, pn, ply, sizeof ply);
  int rc = cable_render_solution(s, &o, out, vn ? vtp : NULL, pn ? ply : NULL, err);
  if (!rc) fprintf(r->opt.log ? r->opt.log : stdout, "  label %d rendered to %s\n", s->lab, out);
  return rc;
}

static int interval_append(script_value *list, double t0, double t1)
{
  script_value iv;
  int rc = script_list_new(&iv);
  if (rc) return rc;
  if ((rc = script_list_append(&iv, script_number(t0))) || (rc = script_list_append(&iv, script_number(t1))) ||
      (rc = script_list_append(list, iv))) {
    script_value_release(&iv);
    return rc;
  }
  return 0;
}

#define OVERLAP_MAX_INTERVALS 256

static int fn_overlap_free(int nargs, const script_value *args, script_value *out, cable_error *err)
{
  if (nargs != 1 || script_handle_kind(&args[0]) != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "overlap_free(result) takes one result");
  const rp_result *res = script_handle_ptr(&args[0]);
  script_value list;
  int rc = script_list_new(&list);
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  for (int b = 0; b < res->nbr && !rc; b++) {
    const rp_branch *br = res->br[b];
    size_t n = (size_t)(br->nsol > 0 ? br->nsol : 1);
    double *t = malloc(n * sizeof *t), *d = malloc(n * sizeof *d);
    double (*iv)[2] = malloc(OVERLAP_MAX_INTERVALS * sizeof *iv);
    if (!t || !d || !iv) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    for (int i = 0; !rc && i < br->nsol; i++) {
      const cable_solution *s = br->sol[i];
      tube_distance_result td;
      if ((rc = braid_tube_distance_solution(s, 0, &td)))
        cable_error_set(err, rc, NULL, 0, NULL, "label %d is not a closed braid solution (%s)", s->lab,
                        cable_status_message(rc));
      t[i] = s->par[BP_T];
      d[i] = td.dmin;
    }
    int m = rc ? 0 : tube_free_intervals(t, d, br->nsol, iv, OVERLAP_MAX_INTERVALS);
    for (int k = 0; !rc && k < m && k < OVERLAP_MAX_INTERVALS; k++)
      if ((rc = interval_append(&list, iv[k][0], iv[k][1]))) cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    free(t);
    free(d);
    free(iv);
  }
  if (rc) {
    script_value_release(&list);
    return rc;
  }
  *out = list;
  return 0;
}

int rp_call(void *ctx, const char *name, int nargs, const script_value *args, const script_kwargs *kw,
            script_value *out, cable_error *err)
{
  cable_replay *r = ctx;
  if (strcmp(name, "analyze") == 0) return fn_analyze(nargs, args, out, err);
  if (strcmp(name, "compare") == 0) return fn_compare(r, nargs, args, kw, err);
  if (strcmp(name, "plot") == 0) return fn_plot(r, nargs, args, kw, err);
  if (strcmp(name, "render") == 0) return fn_render(r, nargs, args, kw, err);
  if (strcmp(name, "overlap_free") == 0) return fn_overlap_free(nargs, args, out, err);
  return CABLE_ERR_NOTFOUND;
}
