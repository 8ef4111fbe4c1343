/* Scene post-processing functions of the run host, computed only for the
 * solutions a script names (never during continuation):
 *
 *   analyze(sol)                  -> dict: Lk, Tw, Wr, Lk_defect, knot, hand,
 *                                    crossings, lk_in_tube, pmin, pmin1, pmax1,
 *                                    pmin2, pmax2, psign, psign2 (sign changes
 *                                    of p1, p2), psign_s1, psign_s2 (their s),
 *                                    psign_sigma2 (p2's, in sigma), dmin,
 *                                    axis_dmin, noverlap, overlap ([[s_lo,
 *                                    s_hi], ...]), overlap_length,
 *                                    axis_kappa_max, drift, closure, closure2, err
 *   branch_table('table.txt', result, paper={'knot': 'right trefoil', 'Lk': 3,
 *                'linked': False, 'psign': True, 'T': .., 'F': ..}, title='...') -> LAB
 *       analyzes every labelled solution of the result, decides from the
 *       branch alone the knot type its axis settles into (that of the last
 *       labelled solution) and the reported point (the first overlap-free
 *       one of the final stretch of that type), writes (atomically, in the
 *       run directory) and prints the table: the reported point against the
 *       paper's statements, a row per labelled solution, the pressure sign
 *       changes.  Returns the reported point's label (None: no solution).
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
 *   render(sol, 'fig.png', view=[x, y, z], size=600, thicken=0, color='pressure', vtp='f.vtp', ply='f.ply')
 *       a shaded picture of a braid solution with its pressure profiles
 *       (color='pressure': tubes coloured by it, blue < 0 < red)
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
#include "names.h"
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

/* A list of numbers as a dict entry. */
static int dict_numbers(script_value *d, const char *key, const double *x, int n)
{
  script_value k, list;
  int rc = script_list_new(&list);
  for (int i = 0; !rc && i < n; i++) rc = script_list_append(&list, script_number(x[i]));
  if (!rc) rc = script_string_new(&k, key, strlen(key));
  if (rc) {
    script_value_release(&list);
    return rc;
  }
  return script_dict_set(d, k, list);
}

/* The overlap s-intervals as [[s_lo, s_hi], ...]. */
static int dict_intervals(script_value *d, const char *key, const tube_distance_result *t)
{
  script_value k, list;
  int rc = script_list_new(&list);
  int n = t->noverlap < TUBE_MAX_INTERVALS ? t->noverlap : TUBE_MAX_INTERVALS;
  for (int i = 0; !rc && i < n; i++) {
    script_value iv;
    if ((rc = script_list_new(&iv))) break;
    if ((rc = script_list_append(&iv, script_number(t->overlap[i][0]))) ||
        (rc = script_list_append(&iv, script_number(t->overlap[i][1]))) || (rc = script_list_append(&list, iv)))
      script_value_release(&iv);
  }
  if (!rc) rc = script_string_new(&k, key, strlen(key));
  if (rc) {
    script_value_release(&list);
    return rc;
  }
  return script_dict_set(d, k, list);
}

static int psign_stored(const braid_psign *p)
{
  return p->n < BRAID_PSIGN_MAX ? p->n : BRAID_PSIGN_MAX;
}

static int dict_int(script_value *d, const char *key, long n)
{
  script_value k;
  int rc = script_string_new(&k, key, strlen(key));
  if (rc) return rc;
  return script_dict_set(d, k, script_integer(n));
}

static int fn_analyze(int nargs, const script_value *args, script_value *out, cable_error *err)
{
  const cable_solution *s = nargs == 1 ? handle_solution(&args[0]) : NULL;
  if (!s) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "analyze(sol) takes one solution");
  braid_analysis *a = malloc(sizeof *a);
  if (!a) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  int rc = analyze_solution(s, a, err);
  if (rc) {
    free(a);
    return rc;
  }
  script_value d;
  if ((rc = script_dict_new(&d))) {
    free(a);
    return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  }
  const knot_type_result *k = &a->topo.axis;
  rc = dict_num(&d, "Lk", a->topo.lk);
  if (!rc) rc = dict_num(&d, "Tw", a->topo.tw);
  if (!rc) rc = dict_num(&d, "Wr", a->topo.wr);
  if (!rc) rc = dict_num(&d, "Lk_defect", a->topo.lk_defect);
  if (!rc) rc = dict_str(&d, "knot", k->name);
  if (!rc) rc = dict_num(&d, "hand", k->handedness);
  if (!rc) rc = dict_num(&d, "crossings", k->crossing_number);
  if (!rc) rc = dict_num(&d, "lk_in_tube", a->topo.lk_in_tube);
  if (!rc) rc = dict_num(&d, "pmin", fmin(a->pmin1, a->pmin2));
  if (!rc) rc = dict_num(&d, "pmin1", a->pmin1);
  if (!rc) rc = dict_num(&d, "pmax1", a->pmax1);
  if (!rc) rc = dict_num(&d, "pmin2", a->pmin2);
  if (!rc) rc = dict_num(&d, "pmax2", a->pmax2);
  if (!rc) rc = dict_int(&d, "psign", a->psign1.n);
  if (!rc) rc = dict_int(&d, "psign2", a->psign2.n);
  if (!rc) rc = dict_numbers(&d, "psign_s1", a->psign1.s, psign_stored(&a->psign1));
  if (!rc) rc = dict_numbers(&d, "psign_s2", a->psign2.s, psign_stored(&a->psign2));
  if (!rc) rc = dict_numbers(&d, "psign_sigma2", a->psign2.sigma, psign_stored(&a->psign2));
  if (!rc) rc = dict_num(&d, "dmin", a->tube.dmin);
  if (!rc) rc = dict_num(&d, "axis_dmin", a->tube.axis_dmin);
  if (!rc) rc = dict_int(&d, "noverlap", a->tube.noverlap);
  if (!rc) rc = dict_intervals(&d, "overlap", &a->tube);
  if (!rc) rc = dict_num(&d, "overlap_length", a->tube.overlap_length);
  if (!rc) rc = dict_num(&d, "axis_kappa_max", a->tube.axis_kappa_max);
  if (!rc) rc = dict_num(&d, "drift", a->drift);
  if (!rc) rc = dict_num(&d, "closure", a->closure);
  if (!rc) rc = dict_num(&d, "closure2", a->closure2);
  if (!rc) rc = dict_num(&d, "err", s->err_est);
  free(a);
  if (rc) {
    script_value_release(&d);
    return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  }
  *out = d;
  return 0;
}

/* ---- branch_table: the analysis of every labelled solution of a branch ---- */

static void run_path(const cable_replay *r, const char *file, char *buf, size_t len);

/* The paper's statements a branch table compares with (absent: not compared). */
typedef struct paper_targets {
  const char *knot;             /* e.g. "right trefoil" */
  int has_lk, has_linked, has_psign, has_t, has_f;
  double lk, t, f;
  int linked, psign;
} paper_targets;

static int paper_parse(const script_value *d, paper_targets *p, cable_error *err)
{
  memset(p, 0, sizeof *p);
  if (!d) return 0;
  if (d->type != SCRIPT_DICT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "paper",
                           "paper={'knot': 'right trefoil', 'Lk': 3, 'linked': False, 'psign': True, 'T': .., 'F': ..}");
  for (size_t i = 0; i < script_dict_len(d); i++) {
    const char *key = script_string_chars(script_dict_key(d, i));
    const script_value *v = script_dict_value(d, i);
    int num = v->type == SCRIPT_NUMBER, flag = v->type == SCRIPT_BOOL || num;
    if (key && strcmp(key, "knot") == 0 && script_string_chars(v)) p->knot = script_string_chars(v);
    else if (key && strcmp(key, "Lk") == 0 && num) p->has_lk = 1, p->lk = v->num;
    else if (key && strcmp(key, "T") == 0 && num) p->has_t = 1, p->t = v->num;
    else if (key && strcmp(key, "F") == 0 && num) p->has_f = 1, p->f = v->num;
    else if (key && strcmp(key, "linked") == 0 && flag) p->has_linked = 1, p->linked = v->num != 0;
    else if (key && strcmp(key, "psign") == 0 && flag) p->has_psign = 1, p->psign = v->num != 0;
    else
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, key ? key : "paper",
                             "paper: keys are 'knot' (a string), 'Lk', 'T', 'F' (numbers), 'linked', 'psign' (True/False)");
  }
  return 0;
}

static void axis_text(const knot_type_result *k, char *buf, size_t len)
{
  snprintf(buf, len, "%s%s", k->handedness > 0 ? "right " : k->handedness < 0 ? "left " : "", k->name);
}

/* Lk rounded to the integer (link) or half-integer (knot) a closed ribbon has. */
static double lk_closed(const braid_analysis *a)
{
  return a->topo.closure < 0 ? floor(a->topo.lk) + 0.5 : round(a->topo.lk);
}

/* -1 unknown, 0 not linked, 1 linked inside the tube around the axis. */
static int linked_in_tube(const braid_analysis *a)
{
  return isnan(a->topo.lk_in_tube) ? -1 : round(a->topo.lk_in_tube) != 0;
}

static const char *agree(int yes)
{
  return yes ? "yes" : "NO";
}

static void print_positions(FILE *f, const char *what, const double *x, const braid_psign *p)
{
  fprintf(f, "%s", what);
  if (p->n == 0) fprintf(f, " none");
  for (int i = 0; i < psign_stored(p); i++) fprintf(f, " %.5f", x[i]);
  if (p->n > BRAID_PSIGN_MAX) fprintf(f, " ... (%d in all)", p->n);
  fputc('\n', f);
}

/* A number with its paper value (when given) and their relative difference. */
static void table_value(FILE *f, const char *what, double x, int has, double target)
{
  fprintf(f, "%-30s %-42.10f ", what, x);
  if (has) fprintf(f, "%-16.10g rel %.1e\n", target, fabs(x - target) / fabs(target));
  else fprintf(f, "-\n");
}

static void table_point(FILE *f, const cable_solution *s, const braid_analysis *a, const paper_targets *p)
{
  char kt[64], buf[128];
  axis_text(&a->topo.axis, kt, sizeof kt);
  int link = a->topo.closure > 0, lk_in = linked_in_tube(a);
  fprintf(f, "%-30s %-42s %-16s %s\n", "quantity", "cable", "paper", "agree");
  table_value(f, "T = T1 = -T2", s->par[BP_T], p->has_t, p->t);
  table_value(f, "F", s->par[BP_F], p->has_f, p->f);
  snprintf(buf, sizeof buf, "%g (Lk - %g = %.1e)", lk_closed(a), lk_closed(a), a->topo.lk - lk_closed(a));
  char pv[40] = "-";
  if (p->has_lk) snprintf(pv, sizeof pv, "%g", p->lk);
  fprintf(f, "%-30s %-42s %-16s %s\n", link ? "Lk (an integer for a link)" : "Lk (a half-integer for a knot)", buf, pv,
          p->has_lk ? agree(lk_closed(a) == p->lk) : "");
  fprintf(f, "%-30s %.6f, %.6f\n", "Tw, Wr", a->topo.tw, a->topo.wr);
  snprintf(buf, sizeof buf, "%s (crossing number %d)", kt, a->topo.axis.crossing_number);
  fprintf(f, "%-30s %-42s %-16s %s\n", "braid axis", buf, p->knot ? p->knot : "-",
          p->knot ? agree(strcmp(kt, p->knot) == 0) : "");
  snprintf(buf, sizeof buf, "%s (Lk_tube = %.4g)", lk_in < 0 ? "unknown" : lk_in ? "yes" : "no", a->topo.lk_in_tube);
  fprintf(f, "%-30s %-42s %-16s %s\n", "strands linked inside tube", buf,
          p->has_linked ? (p->linked ? "yes" : "no") : "-", p->has_linked ? agree(lk_in == p->linked) : "");
  snprintf(buf, sizeof buf, "%s: %d on strand 1, %d on strand 2", a->psign1.n || a->psign2.n ? "yes" : "no",
           a->psign1.n, a->psign2.n);
  fprintf(f, "%-30s %-42s %-16s %s\n", "contact pressure changes sign", buf,
          p->has_psign ? (p->psign ? "yes" : "no") : "-", p->has_psign ? agree((a->psign1.n > 0) == p->psign) : "");
  snprintf(buf, sizeof buf, "%.6g (p1 in [%.6g, %.6g], p2 in [%.6g, %.6g])", fmin(a->pmin1, a->pmin2), a->pmin1,
           a->pmax1, a->pmin2, a->pmax2);
  fprintf(f, "%-30s %s\n", "pmin", buf);
  fprintf(f, "%-30s %.4f (axis %.4f)\n", "dmin", a->tube.dmin, a->tube.axis_dmin);
  fprintf(f, "%-30s %.6g (%.4f / Delta)\n", "max curvature of the axis", a->tube.axis_kappa_max,
          a->tube.axis_kappa_max * s->par[BP_DELTA]);
  if (link) fprintf(f, "%-30s %.6f, %.6f (mod 2 pi; 0: closed)\n", "material closure xi1, xi2", a->closure, a->closure2);
  else fprintf(f, "%-30s %.6f (mod 2 pi)\n", "material closure", a->closure);
  fprintf(f, "%-30s %.2e\n", "first-integral drift", a->drift);
  if (s->err_est >= 0) fprintf(f, "%-30s %.2e\n", "error estimate", s->err_est);
  else fprintf(f, "%-30s -\n", "error estimate");
  print_positions(f, "p1 changes sign at s        =", a->psign1.s, &a->psign1);
  print_positions(f, "p2 changes sign at sigma    =", a->psign2.sigma, &a->psign2);
  print_positions(f, "p2 changes sign at s        =", a->psign2.s, &a->psign2);
}

static void table_row(FILE *f, const cable_solution *s, const braid_analysis *a, int status)
{
  fprintf(f, "%4d %-2s %13.7f %13.6f ", s->lab, cable_type_name(s->itp % 10), s->par[BP_T], s->par[BP_F]);
  if (!a) {
    fprintf(f, "not analysable: %s\n", cable_status_message(status));
    return;
  }
  char kt[64];
  axis_text(&a->topo.axis, kt, sizeof kt);
  int lk_in = linked_in_tube(a);
  fprintf(f, "%10.6f %-18s %8.4f %-6s %11.5g %11.5g %3d %3d %7.4f %8.4f ", a->topo.lk, kt, a->topo.lk_in_tube,
          lk_in < 0 ? "?" : lk_in ? "yes" : "no", a->pmin1, a->pmin2, a->psign1.n, a->psign2.n, a->tube.dmin,
          a->tube.overlap_length);
  if (s->err_est >= 0) fprintf(f, "%9.2e\n", s->err_est);
  else fprintf(f, "%9s\n", "-");
}

/* Writes the table; returns the index of the reported solution, -1 if none. */
static int branch_table_write(FILE *f, const char *title, const cable_solution *const *sol,
                               const braid_analysis *const *a, const int *status, int n, const paper_targets *p)
{
  int first, rep = braid_branch_settled(a, n, &first), last = n - 1;
  while (last >= 0 && !a[last]) last--;
  if (title) fprintf(f, "# %s\n", title);
  fprintf(f,
          "# Every labelled solution of the branch (%d), analysed as analyze() and `cable analyze` do.\n"
          "# T = T1(0) = -T2(0) (the paper's T1 = -T2, t10 = -t20; PAR 'T').  Sign convention: T1 = -C1 (omega1~ - w01)\n"
          "#   is minus strand 1's twisting moment and T2 = C2 (Omega1~/sigma' - w02) is strand 2's, so T > 0 means\n"
          "#   both strands carry the twisting moment -T about their own tangents (doc/braid-boundary-conditions.md).\n"
          "# F = |F|, the braid force; Lk = Tw + Wr of the contact-curve ribbon (integer for a link, half-integer for a knot).\n"
          "# axis: knot type of the braid axis (Alexander polynomial and signature of a projection, knot_type.h).\n"
          "# Lk_tube: Lk minus the writhe of the axis's minimal diagram; the two strands are linked inside the tube\n"
          "#   around the axis when it is not 0 ('linked').\n"
          "# p1, p2: contact force per unit length on strand 1, strand 2 (< 0: the strands must be held together);\n"
          "#   np1, np2: their sign changes along the braid, at the s (arclength of strand 1) and sigma (of strand 2)\n"
          "#   listed at the end.  dmin: closest approach of non-adjacent strand centrelines / Delta (< 1: the tubes\n"
          "#   overlap), overlap: length in s where they do; err: discretisation-error estimate.\n"
          "# The paper's values are comparison targets, never inputs: the final knot type and the reported point are\n"
          "#   decided from the branch alone.\n\n",
          n);
  if (last < 0) {
    fprintf(f, "no labelled solution could be analysed\n");
  } else {
    char kt[64];
    axis_text(&a[last]->topo.axis, kt, sizeof kt);
    int nst = 0;
    for (int i = first; i <= last; i++) nst += a[i] != NULL;
    fprintf(f, "final knot type of the braid axis (decided from the branch): %s\n", kt);
    fprintf(f, "  the type of its last labelled solution, LAB %d; the last %d analysed labelled solutions\n"
               "  (LAB %d-%d, T from %.5f to %.5f) all have it\n",
            sol[last]->lab, nst, sol[first]->lab, sol[last]->lab, sol[first]->par[BP_T], sol[last]->par[BP_T]);
    if (rep >= 0) {
      fprintf(f, "reported point: LAB %d, the first of them whose tubes do not overlap (dmin > 1)\n\n", sol[rep]->lab);
    } else {
      rep = first;
      for (int i = first; i <= last; i++)
        if (a[i] && a[i]->tube.dmin > a[rep]->tube.dmin) rep = i;
      fprintf(f, "reported point: none of them is free of overlap; LAB %d, the one with the largest dmin\n\n",
              sol[rep]->lab);
    }
    table_point(f, sol[rep], a[rep], p);
  }
  if (last < 0) rep = -1;
  fprintf(f, "\n%4s %-2s %13s %13s %10s %-18s %8s %-6s %11s %11s %3s %3s %7s %8s %9s\n", "LAB", "TY", "T", "F", "Lk",
          "axis", "Lk_tube", "linked", "p1min", "p2min", "np1", "np2", "dmin", "overlap", "err");
  for (int i = 0; i < n; i++) table_row(f, sol[i], a[i], status[i]);
  fprintf(f, "\n# where the contact pressure changes sign: p1 at s (strand 1), p2 at sigma (strand 2)\n");
  for (int i = 0; i < n; i++) {
    if (!a[i]) continue;
    char what[40];
    snprintf(what, sizeof what, "LAB %4d  p1 at s     =", sol[i]->lab);
    print_positions(f, what, a[i]->psign1.s, &a[i]->psign1);
    print_positions(f, "          p2 at sigma =", a[i]->psign2.sigma, &a[i]->psign2);
  }
  return rep;
}

static int fn_branch_table(cable_replay *r, int nargs, const script_value *args, const script_kwargs *kw,
                           script_value *out, cable_error *err)
{
  const char *file = nargs == 2 ? script_string_chars(&args[0]) : NULL;
  if (!file || script_handle_kind(&args[1]) != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "branch_table('file', result, paper={...}, title='...') takes a file name and a result");
  paper_targets p;
  int rc = paper_parse(script_kwargs_find(kw, "paper"), &p, err);
  if (rc) return rc;
  const script_value *tv = script_kwargs_find(kw, "title");
  const char *title = tv ? script_string_chars(tv) : NULL;
  if (tv && !title) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "title", "title must be a string");
  const rp_result *res = script_handle_ptr(&args[1]);
  int n = 0;
  for (int b = 0; b < res->nbr; b++) n += res->br[b]->nsol;
  const cable_solution **sol = calloc((size_t)(n > 0 ? n : 1), sizeof *sol);
  braid_analysis **a = calloc((size_t)(n > 0 ? n : 1), sizeof *a);
  int *status = calloc((size_t)(n > 0 ? n : 1), sizeof *status);
  if (!sol || !a || !status) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
  for (int b = 0, i = 0; !rc && b < res->nbr; b++)
    for (int k = 0; k < res->br[b]->nsol; k++, i++) sol[i] = res->br[b]->sol[k];
  /* a solution that cannot be analysed (an axis passing through itself has
     no knot type) is a row of the table, not an error */
  for (int i = 0; !rc && i < n; i++) {
    if (!(a[i] = malloc(sizeof *a[i]))) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    else if ((status[i] = braid_analysis_compute(sol[i], a[i]))) {
      free(a[i]);
      a[i] = NULL;
    }
  }
  char path[1200];
  run_path(r, file, path, sizeof path);
  cable_atomic_file *af = rc ? NULL : cable_atomic_open(path, 0, err);
  if (!rc && !af) rc = err->status ? err->status : CABLE_ERR_IO;
  int rep = -1;
  if (!rc) {
    rep = branch_table_write(cable_atomic_stream(af), title, sol, (const braid_analysis *const *)a, status, n, &p);
    rc = cable_atomic_commit(af, err);
  }
  *out = rep >= 0 && !rc ? script_integer(sol[rep]->lab) : script_none();
  for (int i = 0; a && i < n; i++) free(a[i]);
  free(a);
  free(sol);
  free(status);
  if (rc) return rc;
  FILE *in = fopen(path, "r");
  char line[4096];
  while (in && fgets(line, sizeof line, in)) fputs(line, r->opt.log ? r->opt.log : stdout);
  if (in) fclose(in);
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
  if ((v = script_kwargs_find(kw, "color"))) {
    /* as `cable render ... color=pressure`: the tubes coloured by the contact pressure, so its sign shows */
    if (!script_string_chars(v) || strcmp(script_string_chars(v), "pressure") != 0)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "color", "color='pressure' is the only colour map");
    o.colormap = RENDER_COLORMAP_DIVERGING;
  }
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
  if (strcmp(name, "branch_table") == 0) return fn_branch_table(r, nargs, args, kw, out, err);
  if (strcmp(name, "compare") == 0) return fn_compare(r, nargs, args, kw, err);
  if (strcmp(name, "plot") == 0) return fn_plot(r, nargs, args, kw, err);
  if (strcmp(name, "render") == 0) return fn_render(r, nargs, args, kw, err);
  if (strcmp(name, "overlap_free") == 0) return fn_overlap_free(nargs, args, out, err);
  return CABLE_ERR_NOTFOUND;
}
