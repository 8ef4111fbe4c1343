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
 *   compare('table.txt', rows, ref=sol, notes=['line', ...])  -> [dict per row]
 *       rows: [[name, x, T_target, F_target, Lk_target(, ref)], ...]; x a
 *       result (its UZ label at T_target with F nearest F_target is taken) or
 *       a solution at T_target.  Writes the comparison table (atomically, in
 *       the run directory) and prints it.  ref: a solution of the unbuckled
 *       branch; (Lk - Lk_ref)/2 is the net number of self-passages of the
 *       braid axis that Lk implies.  Lk_tube is Lk minus the writhe of the
 *       companion's minimal diagram (braid_topology.lk_in_tube).  notes:
 *       lines written after the table (the scene's own tabulations).
 *   plot('fig.png', ['flat', 'mode1', ...], marks=[[sol, '(a)'], ...],
 *        x='T', y='F', title='...')
 *       a bifurcation diagram of the saved b-files b.flat, b.mode1, ... in the
 *       run directory, with the marked solutions as open circles
 *   render(sol, 'fig.png', view=[x, y, z], size=600, thicken=0, color='pressure', vtp='f.vtp', ply='f.ply')
 *       a shaded picture of a braid solution with its pressure profiles
 *       (color='pressure': tubes coloured by it, blue < 0 < red)
 *   overlap_free(result)          -> [[T_from, T_to, T_lo, T_hi, to_end, to_passage], ...]
 *       the stretches of each branch (in branch order, T at their ends, the
 *       range of T they cover, 1 when the branch ends inside, 1 when it ends at
 *       a self-passage of the braid axis) where the strand tubes do not
 *       overlap (dmin > 1), from the labelled solutions; an end between two
 *       labels is interpolated linearly in dmin, so its accuracy is the label
 *       spacing (NPR); a passage of the axis through itself between two labels
 *       (axis_passages.h) ends a stretch at the passage's interpolated T even
 *       when both labels are free (the overlap around it is narrower than the
 *       label spacing) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "axis_passages.h"
#include "cable/cable_analysis.h"
#include "tube_distance.h"
#include "braid_state.h"
#include "cable/cable_pictures.h"
#include "cable/cable_status.h"
#include "cable/cable_names.h"
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

static void knot_text(const knot_type_result *k, char *buf, size_t len)
{
  snprintf(buf, len, "%s%s", k->handedness > 0 ? "right " : k->handedness < 0 ? "left " : "", k->name);
}

/* Self-passages of the braid axis between consecutive labelled solutions
 * of a branch, solutions 0..upto (axis_passages.h).  Per interval only the
 * net signed number is trusted: parts that pass and come back between two
 * labels, or a straight-line homotopy that is no longer faithful (at folds,
 * where distant parts of the axis come within a fraction of Delta), give
 * events of both signs that cancel.  *passes: the sum of |net| over the
 * intervals (a lower bound of the passages), *net: the signed sum (equal to
 * (Lk(end) - Lk(start))/2, an independent check of Lk), *mixed: intervals
 * with events of both signs.  tau/net_iv (may be NULL, [upto]): per interval
 * i -> i+1, the homotopy parameter of its first passage (NAN: none) and its
 * net count. */
static int branch_passages(const rp_branch *br, int upto, int *passes, int *net, int *mixed, double *tau, int *net_iv,
                           cable_error *err)
{
  *passes = *net = *mixed = 0;
  for (int i = 0; i < upto && i + 1 < br->nsol; i++) {
    axis_passages ap;
    int rc = braid_axis_passages(br->sol[i], br->sol[i + 1], &ap);
    if (rc)
      return cable_error_set(err, rc, NULL, 0, NULL, "labels %d and %d: cannot follow the braid axis between them (%s)",
                             br->sol[i]->lab, br->sol[i + 1]->lab, cable_status_message(rc));
    *passes += abs(ap.net);
    *net += ap.net;
    *mixed += ap.count > abs(ap.net);
    if (tau) tau[i] = ap.net != 0 ? ap.tau_first : (double)NAN;
    if (net_iv) net_iv[i] = ap.net;
  }
  return 0;
}

/* A UZ label lies at the target T to the engine's location accuracy: the
 * arclength of a located user zero converges to EPSS |DS| (1e-7 x DSMAX 5 in
 * the knot scenes), so T is off by well under 1e-6; 1e-5 (relative above
 * |T| = 1) leaves a margin and is still far below the T spacing of distinct
 * stored points. */
#define COMPARE_T_TOL 1e-5

static int at_target_t(double t, double target)
{
  return fabs(t - target) <= COMPARE_T_TOL * fmax(1.0, fabs(target));
}

static int is_uz(const cable_solution *s)
{
  return strcmp(cable_type_name(s->itp), "UZ") == 0;
}

/* The solution a compare row refers to: a solution as given, or of a result
 * the UZ label at T_target whose F is nearest F_target (a branch that passes
 * the paper's T several times, e.g. out to a fold and back, crosses it at
 * several labels; the paper's point is the one with its F).  nuz: UZ labels
 * at T_target on the result (1 for a solution), k: the chosen one (1-based). */
typedef struct compare_pick {
  const rp_branch *br;
  int isol;
  int nuz, k;
} compare_pick;

static int compare_pick_solution(const script_value *x, double t_target, double f_target, size_t row,
                                 compare_pick *p, cable_error *err)
{
  memset(p, 0, sizeof *p);
  if (script_handle_kind(x) == SCRIPT_HANDLE_SOLUTION) {
    const rp_sol *so = script_handle_ptr(x);
    double t = so->br->sol[so->isol]->par[BP_T];
    if (!at_target_t(t, t_target))
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                             "compare: row %zu: label %d has T = %.10g, not the target T = %.10g", row,
                             so->br->sol[so->isol]->lab, t, t_target);
    *p = (compare_pick){so->br, so->isol, 1, 1};
    return 0;
  }
  if (script_handle_kind(x) != SCRIPT_HANDLE_RESULT)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "compare: row %zu: the second entry must be a result or a solution", row);
  const rp_result *res = script_handle_ptr(x);
  double best = INFINITY;
  for (int b = 0; b < res->nbr; b++)
    for (int i = 0; i < res->br[b]->nsol; i++) {
      const cable_solution *s = res->br[b]->sol[i];
      if (!is_uz(s) || !at_target_t(s->par[BP_T], t_target)) continue;
      p->nuz++;
      double d = fabs(s->par[BP_F] - f_target);
      if (d < best) {
        best = d;
        p->br = res->br[b];
        p->isol = i;
        p->k = p->nuz;
      }
    }
  if (!p->br)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "compare: row %zu: no UZ label at T = %.10g on that result (run it with UZR={'T': %.10g})",
                           row, t_target, t_target);
  return 0;
}

/* One row of the comparison, as written and as returned to the script. */
typedef struct compare_row {
  const char *name;
  const cable_solution *s;
  compare_pick pick;
  double t_target, f_target, lk_target, rel;
  double dlk_half;              /* (Lk - Lk_ref)/2, NAN without a reference */
  int passes, net, mixed;       /* axis self-passages along the branch up to the point */
  braid_analysis a;
  char knot[64];
} compare_row;

static int compare_row_dict(const compare_row *w, script_value *out)
{
  script_value d;
  int rc = script_dict_new(&d);
  if (rc) return rc;
  const knot_type_result *k = &w->a.topo.axis;
  rc = dict_str(&d, "name", w->name);
  if (!rc) rc = dict_num(&d, "LAB", w->s->lab);
  if (!rc) rc = dict_num(&d, "T", w->s->par[BP_T]);
  if (!rc) rc = dict_num(&d, "F", w->s->par[BP_F]);
  if (!rc) rc = dict_num(&d, "T_paper", w->t_target);
  if (!rc) rc = dict_num(&d, "F_paper", w->f_target);
  if (!rc) rc = dict_num(&d, "rel", w->rel);
  if (!rc) rc = dict_num(&d, "uz_at_T", w->pick.nuz);
  if (!rc) rc = dict_num(&d, "uz_chosen", w->pick.k);
  if (!rc) rc = dict_num(&d, "Lk", w->a.topo.lk);
  if (!rc) rc = dict_num(&d, "lk_in_tube", w->a.topo.lk_in_tube);
  if (!rc) rc = dict_num(&d, "lk_paper", w->lk_target);
  if (!rc) rc = dict_num(&d, "dLk_half", w->dlk_half);
  if (!rc) rc = dict_num(&d, "passes", w->passes);
  if (!rc) rc = dict_num(&d, "passes_net", w->net);
  if (!rc) rc = dict_num(&d, "passes_mixed", w->mixed);
  if (!rc) rc = dict_str(&d, "knot", k->name);
  if (!rc) rc = dict_num(&d, "hand", k->handedness);
  if (!rc) rc = dict_num(&d, "crossings", k->crossing_number);
  if (!rc) rc = dict_num(&d, "pmin", fmin(w->a.pmin1, w->a.pmin2));
  if (!rc) rc = dict_num(&d, "dmin", w->a.tube.dmin);
  if (!rc) rc = dict_num(&d, "err", w->s->err_est);
  if (rc) {
    script_value_release(&d);
    return rc;
  }
  *out = d;
  return 0;
}

static void compare_header(FILE *f)
{
  fprintf(f, "# point: the paper's point; T: its torque; F: paper and cable; rel: |dF|/F.  The cable point is\n"
             "#   the UZ label at the paper's T on that branch whose F is nearest the paper's (uz: which of\n"
             "#   the branch's UZ labels at that T was taken, of how many)\n"
             "# Lk = Tw + Wr of the contact-curve ribbon; dLk/2: (Lk - Lk_ref)/2 against the unbuckled\n"
             "#   reference, the net number of self-passages of the braid axis that Lk implies;\n"
             "# pass: self-passages of the braid axis counted along the branch from its start to the point\n"
             "#   (edges of the axis polyline that pass through each other between consecutive labels), and\n"
             "#   their signed sum in brackets, which must equal dLk/2; '*': between some labels the axis\n"
             "#   passed both ways (those cancel and are not counted)\n"
             "# Lk_tube: Lk minus the writhe of the companion knot's minimal diagram (handedness x crossing\n"
             "#   number for a torus knot: +3 right trefoil, -3 left), the paper's 'linking number', quoted\n"
             "#   in brackets; pmin: minimum contact force per length;\n"
             "# dmin: closest approach of non-adjacent strand centrelines / Delta (< 1: tubes overlap);\n"
             "# err: discretisation-error estimate of the stored solution\n");
  fprintf(f, "%-5s %4s %5s %12s %12s %14s %9s %9s %5s %9s %15s %-22s %11s %7s %9s\n", "point", "LAB", "uz", "T",
          "F_paper", "F_cable", "rel", "Lk", "dLk/2", "pass", "Lk_tube(paper)", "braid axis", "pmin", "dmin", "err");
}

static void compare_line(FILE *f, const compare_row *w)
{
  char tube[40], uz[16], pass[24];
  snprintf(tube, sizeof tube, "%.4g (%.4g)", w->a.topo.lk_in_tube, w->lk_target);
  snprintf(uz, sizeof uz, "%d/%d", w->pick.k, w->pick.nuz);
  snprintf(pass, sizeof pass, "%d (%d)%s", w->passes, w->net, w->mixed ? "*" : "");
  fprintf(f, "%-5s %4d %5s %12.6f %12.6f %14.7f %9.2e %9.5f %5.1f %9s %15s %-22s %11.4g %7.3f %9.2e\n", w->name,
          w->s->lab, uz, w->s->par[BP_T], w->f_target, w->s->par[BP_F], w->rel, w->a.topo.lk, w->dlk_half, pass, tube,
          w->knot, fmin(w->a.pmin1, w->a.pmin2), w->a.tube.dmin, w->s->err_est);
}

static int row_number(const script_value *row, size_t k, double *x)
{
  const script_value *v = script_list_get(row, k);
  if (!v || v->type != SCRIPT_NUMBER) return 0;
  *x = v->num;
  return 1;
}

/* Reads and evaluates row i (0-based) of compare's list. */
static int compare_eval_row(const script_value *row, size_t i, double lk_ref, compare_row *w, cable_error *err)
{
  size_t nrow = row && row->type == SCRIPT_LIST ? script_list_len(row) : 0;
  memset(w, 0, sizeof *w);
  w->name = nrow == 5 || nrow == 6 ? script_string_chars(script_list_get(row, 0)) : NULL;
  if (!w->name || !row_number(row, 2, &w->t_target) || !row_number(row, 3, &w->f_target) ||
      !row_number(row, 4, &w->lk_target))
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "compare: row %zu must be [name, result or solution, T_target, F_target, Lk_target"
                           "(, reference solution)]", i + 1);
  int rc;
  if (nrow == 6) {
    const cable_solution *rref = handle_solution(script_list_get(row, 5));
    if (!rref)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL, "compare: row %zu: the reference must be a solution",
                             i + 1);
    if ((rc = analyze_solution(rref, &w->a, err))) return rc;
    lk_ref = w->a.topo.lk;
  }
  if ((rc = compare_pick_solution(script_list_get(row, 1), w->t_target, w->f_target, i + 1, &w->pick, err)))
    return rc;
  w->s = w->pick.br->sol[w->pick.isol];
  if ((rc = analyze_solution(w->s, &w->a, err))) return rc;
  w->rel = fabs(w->s->par[BP_F] - w->f_target) / fabs(w->f_target);
  w->dlk_half = isnan(lk_ref) ? (double)NAN : (w->a.topo.lk - lk_ref) / 2;
  if ((rc = branch_passages(w->pick.br, w->pick.isol, &w->passes, &w->net, &w->mixed, NULL, NULL, err))) return rc;
  knot_text(&w->a.topo.axis, w->knot, sizeof w->knot);
  return 0;
}

static int fn_compare(cable_replay *r, int nargs, const script_value *args, const script_kwargs *kw,
                      script_value *out, cable_error *err)
{
  const char *file = nargs == 2 ? script_string_chars(&args[0]) : NULL;
  const script_value *rows = nargs == 2 ? &args[1] : NULL;
  if (!file || !rows || rows->type != SCRIPT_LIST)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                           "compare('file', [[name, result, T_target, F_target, Lk_target], ...], ref=sol)");
  const script_value *refv = script_kwargs_find(kw, "ref");
  const cable_solution *ref = refv ? handle_solution(refv) : NULL;
  if (refv && !ref) return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "ref", "ref must be a solution");
  const script_value *notes = script_kwargs_find(kw, "notes");
  if (notes && notes->type != SCRIPT_LIST)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "notes", "notes must be a list of strings");
  for (size_t i = 0; notes && i < script_list_len(notes); i++)
    if (!script_string_chars(script_list_get(notes, i)))
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "notes", "notes entry %zu is not a string", i + 1);
  double lk_ref = NAN;
  compare_row w;
  int rc;
  if (ref) {
    if ((rc = analyze_solution(ref, &w.a, err))) return rc;
    lk_ref = w.a.topo.lk;
  }
  script_value list;
  if ((rc = script_list_new(&list))) return cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
  char path[1200];
  run_path(r, file, path, sizeof path);
  cable_atomic_file *af = cable_atomic_open(path, 0, err);
  if (!af) {
    script_value_release(&list);
    return err->status ? err->status : CABLE_ERR_IO;
  }
  FILE *f = cable_atomic_stream(af);
  compare_header(f);
  for (size_t i = 0; !rc && i < script_list_len(rows); i++) {
    script_value d;
    if ((rc = compare_eval_row(script_list_get(rows, i), i, lk_ref, &w, err))) break;
    compare_line(f, &w);
    if ((rc = compare_row_dict(&w, &d)) || (rc = script_list_append(&list, d))) {
      script_value_release(&d);
      cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    }
  }
  if (!rc && notes && script_list_len(notes) > 0) fputc('\n', f);
  for (size_t i = 0; !rc && notes && i < script_list_len(notes); i++)
    fprintf(f, "%s\n", script_string_chars(script_list_get(notes, i)));
  if (rc) cable_atomic_abort(af);
  else rc = cable_atomic_commit(af, err);
  if (rc) {
    script_value_release(&list);
    return rc;
  }
  FILE *in = fopen(path, "r");
  char line[512];
  while (in && fgets(line, sizeof line, in)) fputs(line, r->opt.log ? r->opt.log : stdout);
  if (in) fclose(in);
  *out = list;
  return 0;
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

/* One overlap-free stretch of a branch: T at its ends (in branch order), the
 * range of T it covers (a fold inside it turns T back), whether it runs to
 * the branch's last label (the branch ends inside it, so it may go on), and
 * whether it ends at a self-passage of the braid axis. */
typedef struct free_stretch {
  double t_from, t_to, t_lo, t_hi;
  int to_end, to_passage;
} free_stretch;

static void stretch_extend(free_stretch *st, double t)
{
  st->t_lo = fmin(st->t_lo, t);
  st->t_hi = fmax(st->t_hi, t);
}

/* The stretches where d > 1 along samples (t[i], d[i]) in branch order; an
 * end between two samples is the linear interpolant's crossing of d = 1.
 * tau[i] (i < n-1, NAN: none): the braid axis passes through itself between
 * samples i and i+1, at that fraction of the way: the tubes overlap there even
 * if both samples are free, so a stretch ends (and the next begins) at the
 * interpolated T of the passage.  Returns the count (it may exceed max; only
 * max are stored). */
static int free_stretches(const double *t, const double *d, const double *tau, int n, free_stretch *st, int max)
{
  int count = 0;
  free_stretch cur = {0};
#define STRETCH_CLOSE(T_END, END, PASS)        \
  do {                                         \
    cur.t_to = (T_END);                        \
    stretch_extend(&cur, cur.t_to);            \
    cur.to_end = (END), cur.to_passage = (PASS); \
    if (count < max) st[count] = cur;          \
    count++;                                   \
  } while (0)
  for (int i = 0; i < n; i++) {
    int free_now = d[i] > 1.0, free_before = i > 0 && d[i - 1] > 1.0;
    double cross = i > 0 && free_now != free_before ? t[i - 1] + (1.0 - d[i - 1]) * (t[i] - t[i - 1]) / (d[i] - d[i - 1])
                                                    : t[i];
    if (free_before && free_now && !isnan(tau[i - 1])) {
      double tp = t[i - 1] + tau[i - 1] * (t[i] - t[i - 1]);
      STRETCH_CLOSE(tp, 0, 1);
      cur = (free_stretch){tp, tp, tp, tp, 0, 0};
    }
    if (free_now && !free_before) cur = (free_stretch){cross, cross, cross, cross, 0, 0};
    if (free_now) stretch_extend(&cur, t[i]);
    if (!free_now && free_before) STRETCH_CLOSE(cross, 0, 0);
    else if (free_now && i == n - 1) STRETCH_CLOSE(t[i], 1, 0);
  }
#undef STRETCH_CLOSE
  return count;
}

static int stretch_append(script_value *list, const free_stretch *st)
{
  script_value iv;
  int rc = script_list_new(&iv);
  if (rc) return rc;
  double v[6] = {st->t_from, st->t_to, st->t_lo, st->t_hi, st->to_end, st->to_passage};
  for (int k = 0; k < 6 && !rc; k++) rc = script_list_append(&iv, script_number(v[k]));
  if (rc || (rc = script_list_append(list, iv))) {
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
    double *t = malloc(n * sizeof *t), *d = malloc(n * sizeof *d), *tau = malloc(n * sizeof *tau);
    free_stretch *st = malloc(OVERLAP_MAX_INTERVALS * sizeof *st);
    if (!t || !d || !tau || !st) rc = cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "out of memory");
    int passes, net, mixed;
    if (!rc) rc = branch_passages(br, br->nsol - 1, &passes, &net, &mixed, tau, NULL, err);
    for (int i = 0; !rc && i < br->nsol; i++) {
      const cable_solution *s = br->sol[i];
      tube_distance_result td;
      if ((rc = braid_tube_distance_solution(s, 0, &td)))
        cable_error_set(err, rc, NULL, 0, NULL, "label %d is not a closed braid solution (%s)", s->lab,
                        cable_status_message(rc));
      t[i] = s->par[BP_T];
      d[i] = td.dmin;
    }
    int m = rc ? 0 : free_stretches(t, d, tau, br->nsol, st, OVERLAP_MAX_INTERVALS);
    for (int k = 0; !rc && k < m && k < OVERLAP_MAX_INTERVALS; k++)
      if ((rc = stretch_append(&list, &st[k]))) cable_error_set(err, rc, NULL, 0, NULL, "out of memory");
    free(t);
    free(d);
    free(tau);
    free(st);
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
  if (strcmp(name, "compare") == 0) return fn_compare(r, nargs, args, kw, out, err);
  if (strcmp(name, "plot") == 0) return fn_plot(r, nargs, args, kw, err);
  if (strcmp(name, "render") == 0) return fn_render(r, nargs, args, kw, err);
  if (strcmp(name, "overlap_free") == 0) return fn_overlap_free(nargs, args, out, err);
  return CABLE_ERR_NOTFOUND;
}
