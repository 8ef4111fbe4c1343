/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Benchmark (make bench, not a test): work against precision of the knot72
 * scene, reduced to the path to the paper's point (a):
 *   flat (7,2) branch (braid_knot, c.knot72) -> its first branch point BP1
 *   -> switch in braid_knot_sym (c.knot72sym, ISW=-1) -> mode-1 branch
 *   -> UZSTOP at T = -2.10752, point (a).
 * For NTST x NCOL on a grid: the run time (median of REPEATS scene runs)
 * against the errors in F at (a) and in T at BP1, both measured against a
 * Richardson-extrapolated reference from the two finest meshes.  Also the
 * cost of computing derived quantities (cable_braid_analysis_compute) at every
 * accepted point instead of only at labelled ones.
 *
 * Usage: bench_workprecision IMGDIR [quick]
 * Prints Markdown to stdout; writes IMGDIR/work-precision.png and .svg. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "cable/cable_analysis.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_cont.h"
#include "cable/cable_constants.h"
#include "plot.h"

/* Scene runs per grid point; the time is their median.  The whole grid then
 * takes about 12 minutes on 2 cores (measured), within make bench's budget. */
#define REPEATS 3
/* The paper's point (a): T on the mode-1 branch (runs/knot72/knot72.auto). */
#define T_POINT_A (-2.10752)
/* The accuracy asked for: relative error in F at (a). */
#define TARGET_REL_ERR 1e-8
/* Location tolerance for the untimed BP1 runs that measure T(BP1): with the
   scene's EPSS = 1e-7 the located T of the double BP1 scatters by ~1e-7
   (measured: NCOL = 5 and 7 at NTST = 100 give 11.07607113 and ...124, at
   EPSS = 1e-10 ...117 and ...118), above the discretisation error of the
   finer meshes. */
#define EPSS_BP1 1e-10
/* BP1 of the flat branch is at T = 11.076 and BP2 at T = 18.004
   (runs/knot72/s.flat); a first BP beyond the midpoint means the flat run
   missed BP1 (seen at NTST = 400, NCOL = 3) and the scene would follow
   mode 2: such a grid point is reported, not used. */
#define BP1_T_MAX 14.5
/* Steps allowed on the flat branch before BP1 must have been found (the scene
   finds it at point 10 with DS = 5). */
#define FLAT_MAX_STEPS 60

static const int ntsts[] = {25, 50, 100, 200, 400};
static const int ncols[] = {3, 4, 5, 7};
#define NNTST ((int)(sizeof ntsts / sizeof ntsts[0]))
#define NNCOL ((int)(sizeof ncols / sizeof ncols[0]))

typedef struct {
  int ok;                 /* 1: the scene reached (a) from BP1 */
  int missed_bp1;         /* the first BP of the flat run was not BP1 */
  double seconds;         /* whole scene */
  int steps;              /* accepted points after the two starts */
  double t_bp1, f_a;      /* results */
  double t_bp1_tight;     /* T(BP1) located with EPSS_BP1 (separate, untimed run) */
  double t_a;             /* T at the located (a), should be T_POINT_A */
  double eps13;           /* unfolding parameter at (a): ~0 on a true solution */
} scene_result;

typedef struct {
  const cable_problem *knot, *sym;
  cable_constants cflat, csym;
} scene;

/* What `every point' costs: the sink a scene would use to analyse every
 * accepted solution (the engine itself hands only labelled ones to sinks). */
typedef struct {
  int count;
  double checksum;        /* keeps the work observable */
} analysis_ctx;

static int analyse_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  (void)pt;
  analysis_ctx *a = ctx;
  cable_braid_analysis an;
  int rc = cable_braid_analysis_compute(sol, &an);
  if (rc == 0) {
    a->count++;
    a->checksum += an.topo.lk;
  }
  return rc;
}

/* Step a branch; every accepted point's solution goes to sink (may be NULL).
 * stop_bp: end at the first BP (returned through *bp, cloned). */
static int branch_run(cable_cont *cc, const cable_sink *sink, int stop_bp, int max_steps,
                      cable_solution **bp, int *steps)
{
  int st;
  while ((st = cable_cont_step(cc)) == CABLE_SUCCESS) {
    const cable_point *pt = cable_cont_point(cc);
    (*steps)++;
    if (sink && sink->solution && sink->solution(sink->ctx, pt, cable_cont_solution(cc)) < 0) return -1;
    if (stop_bp && pt->itp % 10 == CABLE_TY_BP) {
      *bp = cable_solution_clone(cable_cont_solution(cc));
      if (!*bp) return -1;
      (*bp)->itp = CABLE_TY_BP; /* the engine's driver marks it when it emits */
      return 0;
    }
    if (*steps > max_steps) return -1;
  }
  /* the last point (UZSTOP) has been accepted too */
  if (st > 0 && sink && sink->solution &&
      sink->solution(sink->ctx, cable_cont_point(cc), cable_cont_solution(cc)) < 0)
    return -1;
  return st;
}

/* The flat branch from the torus start to BP1; *bp its solution (NULL on failure). */
static cable_solution *flat_to_bp1(const scene *sc, const cable_constants *cf, const cable_sink *sink, int *steps)
{
  /* the start's geometry from the constants file's PAR={'Delta', 'Ltot', 'T'} */
  double par[BP_NPAR] = {0};
  for (int k = 0; k < cf->npar_override; k++)
    if (cf->par_override[k].index >= 0 && cf->par_override[k].index < BP_NPAR)
      par[cf->par_override[k].index] = cf->par_override[k].value;
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, (int)cable_constants_key(cf, sc->knot, "TORUS"),
                          (int)cable_constants_key(cf, sc->knot, "HAND"), par[BP_DELTA], par[BP_LTOT], par[BP_T]);
  if (braid_start_prepare(&sp) != 0) return NULL;
  cable_problem knot = *sc->knot;
  knot.params = &sp;
  int st;
  cable_solution *bp = NULL;
  cable_cont *cc = cable_cont_alloc(&knot, cf, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  if (st == 0) st = branch_run(cc, sink, 1, FLAT_MAX_STEPS, &bp, steps);
  cable_cont_free(cc);
  if (st != 0) {
    cable_solution_free(bp);
    return NULL;
  }
  return bp;
}

static void scene_run(const scene *sc, int ntst, int ncol, const cable_sink *sink, scene_result *r)
{
  memset(r, 0, sizeof *r);
  r->t_bp1 = r->t_bp1_tight = r->f_a = r->t_a = r->eps13 = (double)NAN;
  cable_constants cf = sc->cflat, cs = sc->csym;
  cf.ntst = cs.ntst = ntst;
  cf.ncol = cs.ncol = ncol;
  double t0 = bench_now();
  int st, steps = 0;
  cable_solution *bp = flat_to_bp1(sc, &cf, sink, &steps);
  if (!bp) return;
  r->t_bp1 = bp->par[BP_T];
  r->missed_bp1 = r->t_bp1 > BP1_T_MAX;
  cable_cont *cc = cable_cont_alloc(sc->sym, &cs, &st);
  if (st == 0) st = cable_cont_set_start(cc, bp);
  if (st == 0) st = branch_run(cc, sink, 0, cs.nmx + 1, NULL, &steps);
  if (st == CABLE_END_UZSTOP) {
    const cable_solution *s = cable_cont_solution(cc);
    r->f_a = s->par[BP_F];
    r->t_a = s->par[BP_T];
    r->eps13 = s->par[BP_EPS13];
    r->ok = !r->missed_bp1;
  }
  cable_cont_free(cc);
  cable_solution_free(bp);
  r->seconds = bench_now() - t0;
  r->steps = steps;
  /* T(BP1) at a tight location tolerance, outside the timing */
  cf.epss = EPSS_BP1;
  int steps2 = 0;
  bp = flat_to_bp1(sc, &cf, NULL, &steps2);
  if (bp) r->t_bp1_tight = bp->par[BP_T];
  if (!bp || r->t_bp1_tight > BP1_T_MAX) r->ok = 0;
  cable_solution_free(bp);
}

/* Median time of n scene runs; *r gets the results of the first (the
 * results of all runs must agree: the engine is deterministic). */
static double scene_time(const scene *sc, int ntst, int ncol, const cable_sink *sink, int n, scene_result *r,
                         int *consistent)
{
  double t[REPEATS];
  *consistent = 1;
  for (int k = 0; k < n; k++) {
    scene_result x;
    scene_run(sc, ntst, ncol, sink, &x);
    t[k] = x.seconds;
    if (k == 0) *r = x;
    else if (x.ok != r->ok || memcmp(&x.f_a, &r->f_a, sizeof x.f_a) || memcmp(&x.t_bp1, &r->t_bp1, sizeof x.t_bp1))
      *consistent = 0;
  }
  return bench_median(t, n);
}

static int load_constants(const char *path, const cable_problem *pb, cable_constants *c)
{
  cable_error err;
  memset(&err, 0, sizeof err);
  int rc = cable_constants_parse_file_for(path, pb, c, NULL, &err);
  if (rc) {
    fprintf(stderr, "bench_workprecision: %s: error %d\n", path, rc);
    return rc;
  }
  cable_constants_take_problem_dims(c, pb->ndim, pb->nbc, pb->nint);
  return 0;
}

/* Richardson extrapolation of q(h) = q* + C h^p from h and h/2. */
static double richardson(double q_h, double q_h2, int p)
{
  return q_h2 + (q_h2 - q_h) / (pow(2.0, p) - 1.0);
}

static void plot_errors(const char *imgdir, const double err[NNCOL][NNTST], const double tm[NNCOL][NNTST],
                        double floor_err)
{
  double x[NNCOL][NNTST], y[NNCOL][NNTST];
  int lab[NNCOL][NNTST];
  char names[NNCOL][32];
  plot_branch br[NNCOL + 1];
  double tmin = INFINITY, tmax = -INFINITY;
  for (int c = 0; c < NNCOL; c++) {
    for (int i = 0; i < NNTST; i++) {
      /* an error below the reference's own uncertainty is not measurable */
      int show = isfinite(err[c][i]) && err[c][i] > floor_err && tm[c][i] > 0;
      x[c][i] = show ? log10(tm[c][i]) : (double)NAN;
      y[c][i] = show ? log10(err[c][i]) : (double)NAN;
      lab[c][i] = ntsts[i];
      if (show) {
        tmin = fmin(tmin, x[c][i]);
        tmax = fmax(tmax, x[c][i]);
      }
    }
    snprintf(names[c], sizeof names[c], "NCOL = %d", ncols[c]);
    br[c] = (plot_branch){names[c], NNTST, x[c], y[c], NULL, lab[c], NULL};
  }
  double tx[2] = {tmin, tmax}, ty[2] = {log10(TARGET_REL_ERR), log10(TARGET_REL_ERR)};
  br[NNCOL] = (plot_branch){"1e-8 target", 2, tx, ty, NULL, NULL, NULL};
  plot_options opt = {"log10 time of the scene (s)", "log10 relative error of F at (a)",
                      "knot72 to point (a): error against time (labels: NTST)",
                      800, 600, PLOT_FORMAT_PNG};
  char path[1024];
  snprintf(path, sizeof path, "%s/work-precision.png", imgdir);
  if (plot_bifurcation(br, NNCOL + 1, &opt, path) != 0) fprintf(stderr, "bench_workprecision: cannot write %s\n", path);
  opt.format = PLOT_FORMAT_SVG;
  snprintf(path, sizeof path, "%s/work-precision.svg", imgdir);
  if (plot_bifurcation(br, NNCOL + 1, &opt, path) != 0) fprintf(stderr, "bench_workprecision: cannot write %s\n", path);
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: bench_workprecision IMGDIR [quick]\n");
    return 2;
  }
  int quick = argc > 2 && strcmp(argv[2], "quick") == 0;
  scene sc;
  sc.knot = braid_problem_find("braid_knot");
  sc.sym = braid_problem_find("braid_knot_sym");
  if (!sc.knot || !sc.sym) return 1;
  if (load_constants("runs/knot72/c.knot72", sc.knot, &sc.cflat) ||
      load_constants("runs/knot72/c.knot72sym", sc.sym, &sc.csym))
    return 1;
  sc.csym.nuzr = 1;
  sc.csym.uzr[0] = (cable_uzr){BP_T, T_POINT_A, 1};
  sc.csym.npr = 0; /* no regular labels: nothing is written anyway */

  static scene_result res[NNCOL][NNTST];
  static double tm[NNCOL][NNTST];
  int cons[NNCOL][NNTST];
  for (int c = 0; c < NNCOL; c++)
    for (int i = 0; i < NNTST; i++) {
      int n = quick ? 1 : REPEATS;
      if (quick && ntsts[i] > 100) {
        res[c][i].ok = 0;
        tm[c][i] = (double)NAN;
        cons[c][i] = 1;
        continue;
      }
      tm[c][i] = scene_time(&sc, ntsts[i], ncols[c], NULL, n, &res[c][i], &cons[c][i]);
      fprintf(stderr, "NTST %3d NCOL %d: %s %.3f s, %d steps, T(BP1) = %.15g (tight %.15g), F(a) = %.15g, T(a) = %.15g\n",
              ntsts[i], ncols[c], res[c][i].ok ? "ok" : "FAILED", tm[c][i], res[c][i].steps, res[c][i].t_bp1, res[c][i].t_bp1_tight,
              res[c][i].f_a, res[c][i].t_a);
    }

  /* references: Richardson from NTST = 200, 400 at each NCOL (rate 2 NCOL);
     the one at NCOL = 7 is the reference, the others check it */
  int i200 = NNTST - 2, i400 = NNTST - 1, c7 = NNCOL - 1;
  double fref[NNCOL], tref[NNCOL];
  for (int c = 0; c < NNCOL; c++) {
    const scene_result *a = &res[c][i200], *b = &res[c][i400];
    fref[c] = a->ok && b->ok ? richardson(a->f_a, b->f_a, 2 * ncols[c]) : (double)NAN;
    tref[c] = a->ok && b->ok ? richardson(a->t_bp1_tight, b->t_bp1_tight, 2 * ncols[c]) : (double)NAN;
  }
  double f_ref = fref[c7], t_ref = tref[c7];
  /* the reference's uncertainty: its own Richardson correction, and its
     spread against the NCOL = 5 reference */
  double f_unc = fmax(fabs(f_ref - res[c7][i400].f_a), fabs(f_ref - fref[NNCOL - 2]));
  double t_unc = fmax(fabs(t_ref - res[c7][i400].t_bp1_tight), fabs(t_ref - tref[NNCOL - 2]));
  /* noise floor: at NCOL = 7 the discretisation error (h^14) is below
     round-off from NTST = 25 on (NCOL = 5 is at 1.7e-8 there), so the
     scatter of the NCOL = 7 values is what the Newton tolerance and the
     location of UZ and BP points leave: smaller errors are not measurable */
  double f_floor = f_unc, t_floor = t_unc;
  for (int i = 0; i < NNTST; i++)
    if (res[c7][i].ok) {
      f_floor = fmax(f_floor, fabs(res[c7][i].f_a - f_ref));
      t_floor = fmax(t_floor, fabs(res[c7][i].t_bp1_tight - t_ref));
    }

  printf("Reference (Richardson, NTST = 200 and 400, rate h^(2 NCOL)):\n\n");
  printf("| NCOL | F(a), extrapolated | - reference | T(BP1) (EPSS = 1e-10), extrapolated | - reference | observed order in F: log2 of |F25-F50| / |F50-F100| | the same, NTST 50, 100, 200 |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int c = 0; c < NNCOL; c++) {
    double order[2];
    for (int k = 0; k < 2; k++) {
      const scene_result *a = &res[c][k], *b = &res[c][k + 1], *d = &res[c][k + 2];
      double d1 = b->f_a - a->f_a, d2 = d->f_a - b->f_a;
      order[k] = a->ok && b->ok && d->ok && d2 != 0 ? log2(fabs(d1 / d2)) : (double)NAN;
    }
    printf("| %d | %.12f | %.2e | %.12f | %.2e | %.1f | %.1f (theory %d) |\n", ncols[c], fref[c], fref[c] - f_ref,
           tref[c], tref[c] - t_ref, order[0], order[1], 2 * ncols[c]);
  }
  printf("\nReference: F(a) = %.12f (uncertainty %.1e, relative %.1e), T(BP1) = %.12f (uncertainty %.1e, "
         "relative %.1e); uncertainty = the larger of the NCOL = 7 Richardson correction and the distance to the "
         "NCOL = 5 extrapolation. Noise floor (the largest distance of an NCOL = 7 value, NTST = 25..400, from the "
         "reference; at NCOL = 7 the h^14 error is below round-off from NTST = 25 on): relative %.1e in F(a), "
         "%.1e in T(BP1). \"<\" below: an error not larger than the floor (not measurable).\n\n",
         f_ref, f_unc, f_unc / fabs(f_ref), t_ref, t_unc, t_unc / fabs(t_ref), f_floor / fabs(f_ref),
         t_floor / fabs(t_ref));

  double errf[NNCOL][NNTST];
  printf("| NTST | NCOL | scene (s) | runs | steps | per step (s) | rel. error F(a) | rel. error T(BP1), EPSS=1e-10 | the same, scene's EPSS | T(a) + 2.10752 | eps13 at (a) |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  int best_c = -1, best_i = -1;
  for (int c = 0; c < NNCOL; c++)
    for (int i = 0; i < NNTST; i++) {
      const scene_result *r = &res[c][i];
      int n = quick ? 1 : REPEATS;
      errf[c][i] = r->ok ? fabs(r->f_a - f_ref) / fabs(f_ref) : (double)NAN;
      double et = r->ok ? fabs(r->t_bp1_tight - t_ref) / fabs(t_ref) : (double)NAN;
      double es = r->ok ? fabs(r->t_bp1 - t_ref) / fabs(t_ref) : (double)NAN;
      if (!r->ok) {
        if (r->missed_bp1 || r->t_bp1_tight > BP1_T_MAX)
          printf("| %d | %d | %.2f | %d | %d | %.4f | BP1 missed: the first BP found is at T = %.4f (scene's EPSS), "
                 "%.4f (EPSS = 1e-10); F there at T = -2.10752: %.4f | | | | |\n",
                 ntsts[i], ncols[c], tm[c][i], n, r->steps, tm[c][i] / r->steps, r->t_bp1, r->t_bp1_tight, r->f_a);
        else
          printf("| %d | %d | %s | | | | | | | | |\n", ntsts[i], ncols[c], quick && ntsts[i] > 100 ? "not run" : "FAILED");
        continue;
      }
      /* "<": not larger than the reference's own uncertainty */
      printf("| %d | %d | %.2f | %d%s | %d | %.4f | %s%.1e | %s%.1e | %s%.1e | %.1e | %.1e |\n", ntsts[i], ncols[c], tm[c][i],
             n, cons[c][i] ? "" : " (results differ)", r->steps, tm[c][i] / r->steps,
             errf[c][i] * fabs(f_ref) <= f_floor ? "< " : "", errf[c][i], et * fabs(t_ref) <= t_floor ? "< " : "", et,
             es * fabs(t_ref) <= t_floor ? "< " : "", es,
             r->t_a - T_POINT_A, r->eps13);
      if (errf[c][i] <= TARGET_REL_ERR && (best_c < 0 || tm[c][i] < tm[best_c][best_i])) {
        best_c = c;
        best_i = i;
      }
    }
  if (best_c >= 0)
    printf("\nFastest setting with relative error in F(a) <= %.0e: NTST = %d, NCOL = %d (%.2f s, error %.1e).\n",
           TARGET_REL_ERR, ntsts[best_i], ncols[best_c], tm[best_c][best_i], errf[best_c][best_i]);
  else
    printf("\nNo setting reached a relative error in F(a) <= %.0e.\n", TARGET_REL_ERR);
  plot_errors(argv[1], (const double(*)[NNTST])errf, (const double(*)[NNTST])tm, f_floor / fabs(f_ref));

  /* derived quantities at every accepted point, at the scene's mesh */
  int ntst0 = sc.cflat.ntst, ncol0 = sc.cflat.ncol, n = REPEATS, c1, c2;
  analysis_ctx actx = {0, 0.0};
  cable_sink every = {&actx, NULL, analyse_solution, NULL};
  scene_result r0, r1;
  double t_plain = scene_time(&sc, ntst0, ncol0, NULL, n, &r0, &c1);
  double t_every = scene_time(&sc, ntst0, ncol0, &every, n, &r1, &c2);
  printf("\nDerived quantities (NTST = %d, NCOL = %d, median of %d): the scene takes %.2f s as the engine runs it "
         "(analysis only for labelled solutions, on request) and %.2f s with cable_braid_analysis_compute at every one of "
         "its %d accepted points (%d analyses in %d runs): ratio %.1f, %.3f s per analysis against %.4f s per "
         "continuation step.\n",
         ntst0, ncol0, n, t_plain, t_every, r1.steps, actx.count, n, t_every / t_plain,
         (t_every - t_plain) / (r1.steps > 0 ? r1.steps : 1), t_plain / (r0.steps > 0 ? r0.steps : 1));
  return r0.ok && r1.ok ? 0 : 1;
}
