/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Stress cases on the braid knot and link problems (issue 8, part 2).
 *
 *   build/release/tests/test_stress          the quick subset (make check)
 *   build/release/tests/test_stress --full   the whole grid (make stress,
 *                                            scripts/stress.sh; doc/stress.md)
 *   build/release/tests/test_stress --case NAME   one case of the grid
 *
 * Every case runs the engine through cable_cont_run with the real output
 * writer (b./s./d. files in a temporary directory) behind a sink that also
 * measures the first-integral drift (cable_braid_first_integral_drift, mesh points)
 * of every accepted point.  Every case has an expected end status (the
 * measured one, doc/stress.md): reaching its target (UZSTOP; for perturbed
 * starts the same solution as the clean reference), a normal end (NMX) or a
 * clean stop (a negative status with a message).  A case passes when it ends
 * as expected, and in every case: no NaN/Inf in any
 * point, the files read back (cable_sfile_read, cable_bfile_read) with finite
 * numbers only, and the drift computable (mesh-point states inside the
 * model's domain).  The drift bound of the issue (DRIFT_GOAL) is measured and
 * printed for every case; it is checked only where the mesh resolves the
 * braid well enough to meet it (see doc/stress.md for the measured grid).
 * The fuzz regression inputs are replayed by tests/test_fuzz_regressions.c. */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "cable/cable_analysis.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_cont.h"
#include "cable/cable_constants.h"
#include "harness.h"

/* The goal for the first-integral drift on every accepted point. */
#define DRIFT_GOAL 1e-9
/* Perturbed starts converge to the clean run's solution on the same uniform
 * mesh: they agree up to the Newton tolerance EPSS = 1e-9 amplified by the
 * conditioning of the parameters (measured agreement 2e-15 to 5e-13, see
 * doc/stress.md; 1e-7 leaves a factor 100 over the Newton tolerance for the
 * condition number). */
#define SAME_SOLUTION_TOL 1e-7
/* Relative size of the start perturbation (issue 8). */
#define START_NOISE 1e-3

typedef struct stress_case {
  const char *name;
  const char *problem;   /* braid_knot / braid_link */
  int p, hand;
  double delta, length;  /* knot: Ltot; link: L */
  int ntst;
  int icp[5], nicp;
  double ds, dsmax;
  int nmx;
  double target_t;       /* UZSTOP on the principal parameter; 0: none (runs until NMX or failure) */
  int noise;             /* 1: perturb the converged start by START_NOISE */
  int isp;               /* branch-point tests (ISP) */
  int quick;             /* 1: part of the make-check subset */
  int drift_checked;     /* 1: every accepted point must meet DRIFT_GOAL */
  int expect_bp;         /* > 0: branch points the run must locate */
  int expect;            /* the end status the case must give (measured, doc/stress.md):
                            CABLE_END_UZSTOP where the target must be reached, a
                            normal end (NMX) or the clean failure the case shows */
} stress_case;

#define KNOT_ICP {BP_T, BP_L, BP_L2, BP_EPS21, BP_F}, 5
#define LINK_ICP {BP_T, BP_F}, 2
#define DELTA72 0.0051364907419
#define LTOT72 1.98889
#define DELTA62 0.016016913268

static const stress_case cases[] = {
  /* name                problem       p  hand delta    length  ntst icp       ds    dsmax nmx  target noise isp quick drift bp expect */
  {"knot72-base",        "braid_knot", 7, +1, DELTA72, LTOT72, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 1, 1, 0, CABLE_END_UZSTOP},
  {"knot72-noise",       "braid_knot", 7, +1, DELTA72, LTOT72, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 1, 0, 1, 1, 0, CABLE_END_UZSTOP},
  {"knot72-left-noise",  "braid_knot", 7, -1, DELTA72, LTOT72, 80, KNOT_ICP, -0.5, 2.0, 200, -2.0, 1, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot72-ntst10",      "braid_knot", 7, +1, DELTA72, LTOT72, 10, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 1, 0, 0, CABLE_END_UZSTOP},
  {"knot72-ntst40",      "braid_knot", 7, +1, DELTA72, LTOT72, 40, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 0, 0, CABLE_END_UZSTOP},
  {"knot72-ntst400",     "braid_knot", 7, +1, DELTA72, LTOT72, 400, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot72-ntst2000",    "braid_knot", 7, +1, DELTA72, LTOT72, 2000, KNOT_ICP, 1.0, 2.0, 20, 2.0, 0, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot72-thin1e-3",    "braid_knot", 7, +1, 1e-3, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot72-thin1e-4",    "braid_knot", 7, +1, 1e-4, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 1, 1, 0, CABLE_END_UZSTOP},
  {"knot72-thin1e-4-n",  "braid_knot", 7, +1, 1e-4, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 1, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot72-thick0.02",   "braid_knot", 7, +1, 0.02, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 0, 0, CABLE_END_UZSTOP},
  {"knot72-thick0.05",   "braid_knot", 7, +1, 0.05, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 1, 0, 0, CABLE_ERR_NEWTON},
  {"knot72-thick0.08",   "braid_knot", 7, +1, 0.08, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 1, 0, 0, CABLE_ERR_INPUT},
  /* the right-handed flat branch folds at T = 43.88 and at a negative T:
     |T| = 50 is not on it, the run goes through the fold (LP) and back; NMX
     ends it */
  {"knot72-T50-fold",    "braid_knot", 7, +1, DELTA72, LTOT72, 80, KNOT_ICP, 1.0, 5.0, 300, 0.0, 0, 0, 0, 0, 0, CABLE_END_NMX},
  {"knot72-T-50-fold",   "braid_knot", 7, +1, DELTA72, LTOT72, 80, KNOT_ICP, -1.0, 5.0, 300, 0.0, 0, 0, 0, 0, 0, CABLE_END_NMX},
  {"knot72-Delta-up",    "braid_knot", 7, +1, DELTA72, LTOT72, 80, {BP_DELTA, BP_L, BP_L2, BP_EPS21, BP_F}, 5, 0.001, 2.0, 2000, 0.3, 0, 0, 0, 0, 0, CABLE_ERR_DSMIN},
  {"link62-Delta-up",    "braid_link", 6, -1, DELTA62, 1.0, 80, {BP_DELTA, BP_F}, 2, 0.001, 2.0, 2000, 0.3, 0, 0, 0, 0, 0, CABLE_ERR_DSMIN},
  /* branch-point tests on: the flat branch's first two BPs (T = 11.08, 18.00 in runs/knot72) */
  {"knot72-bp",          "braid_knot", 7, +1, DELTA72, LTOT72, 80, KNOT_ICP, 0.5, 2.0, 200, 20.0, 0, 2, 0, 1, 2, CABLE_END_UZSTOP},
  {"knot52-base",        "braid_knot", 5, +1, 0.01, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"knot32-thick",       "braid_knot", 3, +1, 0.1, 2.0, 80, KNOT_ICP, 0.5, 2.0, 200, 2.0, 0, 0, 0, 0, 0, CABLE_ERR_UNSUPPORTED},
  {"link62-base",        "braid_link", 6, -1, DELTA62, 1.0, 80, LINK_ICP, -0.5, 2.0, 200, -1.0, 0, 0, 1, 1, 0, CABLE_END_UZSTOP},
  {"link62-noise",       "braid_link", 6, -1, DELTA62, 1.0, 80, LINK_ICP, -0.5, 2.0, 200, -1.0, 1, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"link62-thin1e-4",    "braid_link", 6, -1, 1e-4, 1.0, 80, LINK_ICP, -0.5, 2.0, 200, -1.0, 0, 0, 0, 1, 0, CABLE_END_UZSTOP},
  {"link62-T-50",        "braid_link", 6, -1, DELTA62, 1.0, 80, LINK_ICP, -1.0, 5.0, 300, -50.0, 0, 0, 0, 0, 0, CABLE_END_UZSTOP},
  {"link62-T50-fold",    "braid_link", 6, -1, DELTA62, 1.0, 80, LINK_ICP, 1.0, 5.0, 300, 0.0, 0, 0, 0, 0, 0, CABLE_END_NMX},
  {"link42-thick",       "braid_link", 4, +1, 0.05, 1.0, 80, LINK_ICP, 0.5, 2.0, 200, 1.0, 0, 0, 0, 0, 0, CABLE_END_UZSTOP},
  {"knot72-nmx5000",     "braid_knot", 7, +1, DELTA72, LTOT72, 20, KNOT_ICP, 0.002, 0.002, 5000, 0.0, 0, 0, 0, 0, 0, CABLE_END_NMX},
};
#define NCASES ((int)(sizeof cases / sizeof cases[0]))

/* ---- the sink: the output writer plus per-point checks ------------------- */

typedef struct stress_sink {
  const cable_cont *cc;
  cable_sink inner;
  int npoints, nonfinite;
  double drift_max;      /* over accepted points; -1 when a point is not a braid */
  int drift_bad;         /* points with drift > DRIFT_GOAL or negative */
  double t_last;
  double drift_start;    /* drift of an uncorrected restart point (-2: none) */
  double eta_max;        /* max |eta| over the mesh of every accepted point */
  int nlp, nbp;          /* folds (LP) and branch points (BP) located */
  int outside;           /* accepted points whose mesh-point states are outside the
                            model's domain (first integrals not evaluable) */
  int verbose;           /* print every point's drift (--verbose) */
} stress_sink;

static int stress_point(void *ctx, const cable_point *pt)
{
  stress_sink *s = ctx;
  s->npoints++;
  if (pt->itp % 10 == CABLE_TY_LP) s->nlp++;
  if (pt->itp % 10 == CABLE_TY_BP) s->nbp++;
  for (int k = 0; k < pt->npar; k++)
    if (!isfinite(pt->par[k])) s->nonfinite++;
  if (!isfinite(pt->l2norm)) s->nonfinite++;
  const cable_solution *sol = cable_cont_solution(s->cc);
  if (sol == NULL) return CABLE_ERR_STATE;   /* a point without its solution: never from the engine */
  int npts = cable_solution_npts(sol);
  for (int k = 0; k < npts * sol->ndim; k++)
    if (!isfinite(sol->u[k])) { s->nonfinite++; break; }
  double eta_pt = 0.0, gap_pt = HUGE_VAL;   /* max |eta|, min 1 - Delta omega3 */
  for (int j = 0; j < npts; j++) {
    eta_pt = fmax(eta_pt, fabs(sol->u[j * sol->ndim + BR_ETA]));
    gap_pt = fmin(gap_pt, 1.0 - sol->par[BP_DELTA] * sol->u[j * sol->ndim + BR_W3]);
  }
  s->eta_max = fmax(s->eta_max, eta_pt);
  double d = cable_braid_first_integral_drift(sol);
  /* a restart reports its stored start as point 1 without correcting it
     (AUTO does the same): a perturbed start's drift is the noise's, kept apart */
  if (pt->pt == 1 && pt->newton_iters == 0) {
    s->drift_start = d;
  } else {
    if (!(d >= 0) || d > DRIFT_GOAL) s->drift_bad++;
    if (!(d >= 0)) s->outside++;
    else if (d > s->drift_max) s->drift_max = d;
  }
  s->t_last = pt->par[pt->icp[0]];   /* the principal parameter */
  if (s->verbose) printf("  point %d PAR(ICP(1)) = %.8g type %d newton %d ds %.3g max|eta| %.9f min(1-Delta*w3) %.3g drift %.3g\n",
                        pt->pt, pt->par[pt->icp[0]], pt->itp, pt->newton_iters, pt->ds, eta_pt, gap_pt, d);
  return s->inner.point(s->inner.ctx, pt);
}

static int stress_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  stress_sink *s = ctx;
  return s->inner.solution(s->inner.ctx, pt, sol);
}

static void stress_diag(void *ctx, const char *line)
{
  stress_sink *s = ctx;
  if (s->inner.diag) s->inner.diag(s->inner.ctx, line);
}

/* ---- one case ---------------------------------------------------------- */

typedef struct stress_outcome {
  int status;            /* the run's end status */
  char msg[600];         /* the engine's message on a negative status */
  int npoints, nonfinite, files_ok, drift_bad, nlp, nbp, outside;
  double drift_max, drift_start, eta_max, t_last, f_end, l_end;
  double seconds;
} stress_outcome;

/* Deterministic noise in [-1, 1] (no global state: the caller owns the seed). */
static double stress_noise(unsigned long *seed)
{
  *seed = *seed * 6364136223846793005UL + 1442695040888963407UL;
  return (double)(*seed >> 11) / (double)(1UL << 53) * 2.0 - 1.0;
}

/* Every number in the files that were written reads back finite. */
static int stress_files_ok(const char *dir, char *why, size_t len)
{
  char path[600];
  cable_error err;
  snprintf(path, sizeof path, "%s/s.stress", dir);
  cable_sfile *s = cable_sfile_read(path, &err);
  if (!s) { snprintf(why, len, "s-file: %s", err.msg); return 0; }
  int ok = cable_sfile_count(s) > 0;
  for (int i = 0; ok && i < cable_sfile_count(s); i++) {
    const cable_solution *sol = cable_sfile_get(s, i);
    for (int k = 0; k < cable_solution_npts(sol) * sol->ndim; k++) ok = ok && isfinite(sol->u[k]);
    for (int k = 0; k < sol->npar; k++) ok = ok && isfinite(sol->par[k]);
  }
  cable_sfile_free(s);
  if (!ok) { snprintf(why, len, "s-file: empty or not finite"); return 0; }
  snprintf(path, sizeof path, "%s/b.stress", dir);
  cable_bfile *b = cable_bfile_read(path, &err);
  if (!b) { snprintf(why, len, "b-file: %s", err.msg); return 0; }
  for (int j = 0; j < b->nbranch; j++)
    for (int k = 0; k < b->branch[j].nrow * b->branch[j].ncol; k++) ok = ok && isfinite(b->branch[j].data[k]);
  ok = ok && b->nbranch > 0;
  cable_bfile_free(b);
  if (!ok) snprintf(why, len, "b-file: empty or not finite");
  return ok;
}

static void stress_rmdir(const char *dir)
{
  DIR *d = opendir(dir);
  if (!d) return;
  struct dirent *e;
  char path[600];
  while ((e = readdir(d)) != NULL) {
    if (e->d_name[0] == '.') continue;
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    unlink(path);
  }
  closedir(d);
  rmdir(dir);
}

static void stress_constants(const stress_case *k, cable_constants *c)
{
  cable_constants_init(c); c->ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c->ntst = k->ntst; c->ncol = 4; c->jac = 1; c->iad = 0;   /* uniform mesh: clean and perturbed runs comparable */
  for (int q = 0; q < k->nicp; q++) c->icp[q] = k->icp[q];
  c->nicp = k->nicp;
  c->ds = k->ds; c->dsmin = 1e-6; c->dsmax = k->dsmax; c->nmx = k->nmx;
  c->isp = k->isp; c->ilp = 1;   /* folds are located (LP) wherever a branch turns */ c->npr = 50; c->epss = 1e-9;
  if (k->target_t != 0.0) {
    c->nuzr = 1; c->uzr[0].par = k->icp[0]; c->uzr[0].value = k->target_t; c->uzr[0].stop = 1;
  }
}

/* Run case k; noise: perturb the converged start first. */
static int stress_run(const stress_case *k, int noise, stress_outcome *o)
{
  memset(o, 0, sizeof *o);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  braid_start_params sp;
  cable_problem pb;
  braid_start_params_init(&sp, BRAID_START_TORUS, k->p, k->hand, k->delta, k->length, 0.0);
  o->status = braid_start_prepare(&sp);
  if (o->status == 0) o->status = braid_problem_instance(k->problem, &sp, &pb);
  if (o->status != 0) {
    snprintf(o->msg, sizeof o->msg, "torus start (braid_start_prepare): %s%s", cable_status_message(o->status),
             o->status == CABLE_ERR_INPUT ? " (Delta at or beyond the contact-circle radius: the tubes overlap)" : "");
    return o->status;
  }
  cable_constants c;
  stress_constants(k, &c);
  cable_constants_take_problem_dims(&c, pb.ndim, pb.nbc, pb.nint);
  cable_solution *start = NULL;
  if (noise) {
    /* converge the clean start (one point), then perturb every value of u and
       the free lengths by START_NOISE relative noise */
    cable_constants c1 = c;
    c1.nmx = 1; c1.nuzr = 0;
    c.ds = fabs(c.ds);   /* the stored tangent already points towards the target */
    int st;
    cable_cont *cc = cable_cont_alloc(&pb, &c1, &st);
    if (st == 0) st = cable_cont_set_start(cc, NULL);
    if (st == 0) st = cable_cont_step(cc);
    if (st == 0) start = cable_solution_clone(cable_cont_solution(cc));
    cable_cont_free(cc);
    if (!start) {
      o->status = st ? st : CABLE_ERR_ALLOC;
      snprintf(o->msg, sizeof o->msg, "clean start: %s", cable_status_message(o->status));
      return o->status;
    }
    unsigned long seed = 12345;
    for (int j = 0; j < cable_solution_npts(start) * start->ndim; j++)
      start->u[j] *= 1.0 + START_NOISE * stress_noise(&seed);
    /* the knot's strand lengths are free (L2 = Ltot - L); the link's L is
       fixed data of the problem, so perturbing it would change the problem */
    if (strcmp(k->problem, "braid_knot") == 0) {
      start->par[BP_L] *= 1.0 + START_NOISE * stress_noise(&seed);
      start->par[BP_L2] = start->par[BP_LTOT] - start->par[BP_L];
    }
  }
  char dir[] = "/tmp/cable-stress.XXXXXX";
  if (!mkdtemp(dir)) { o->status = CABLE_ERR_IO; snprintf(o->msg, sizeof o->msg, "mkdtemp"); return o->status; }
  cable_names names;
  cable_names_init(&names);
  cable_names_fill(&names, pb.parnames, pb.npar, pb.unames, pb.ndim);
  cable_error err;
  cable_aufile *w = cable_aufile_open(dir, "stress", &c, &names, NULL, &err);
  int st = w ? 0 : err.status;
  cable_cont *cc = NULL;
  if (st == 0) cc = cable_cont_alloc(&pb, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, start);
  stress_sink sk = {cc, {0}, 0, 0, 0.0, 0, 0.0, -2.0, 0.0, 0, 0, 0, getenv("STRESS_VERBOSE") != NULL};
  if (w) sk.inner = cable_aufile_sink(w);
  if (st == 0) {
    cable_sink sink = {&sk, stress_point, stress_solution, stress_diag};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  o->status = st;
  if (cc) {
    snprintf(o->msg, sizeof o->msg, "%s", st < 0 ? cable_cont_error(cc) : cable_status_message(st));
  } else if (st < 0) {
    cable_error e;
    if (cable_cont_check(&pb, &c, &e) != 0) snprintf(o->msg, sizeof o->msg, "%s", e.msg);
  }
  if (cc && sk.npoints > 0) {
    o->f_end = cable_cont_point(cc)->par[BP_F];
    o->l_end = cable_cont_point(cc)->par[BP_L];
  }
  cable_cont_free(cc);
  if (w) {
    int cst = cable_aufile_close(w, &err);
    char why[600] = "";
    /* no point at all: the writer still commits (empty) files without error */
    o->files_ok = sk.npoints == 0 ? cst == 0 : cst == 0 && stress_files_ok(dir, why, sizeof why);
    if (!o->files_ok) snprintf(o->msg + strlen(o->msg), sizeof o->msg - strlen(o->msg), " [files: %s]", why);
  }
  stress_rmdir(dir);
  cable_solution_free(start);
  o->npoints = sk.npoints;
  o->nonfinite = sk.nonfinite;
  o->drift_max = sk.drift_max;
  o->drift_bad = sk.drift_bad;
  o->drift_start = sk.drift_start;
  o->eta_max = sk.eta_max;
  o->nlp = sk.nlp;
  o->nbp = sk.nbp;
  o->outside = sk.outside;
  o->t_last = sk.t_last;
  clock_gettime(CLOCK_MONOTONIC, &t1);
  o->seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
  return st;
}

static const char *stress_end_name(int st)
{
  return cable_status_name(st);
}

/* Checks and one table row for case k. */
static void stress_case_check(const stress_case *k, FILE *table)
{
  stress_outcome o, ref;
  stress_run(k, k->noise, &o);
  char what[900];
  /* the expected outcome, exactly: a case that must reach its target fails
     when it stops cleanly before it (e.g. at DSMIN); a case that is expected
     to stop must stop with that status and a message */
  snprintf(what, sizeof what, "%s: %s after %d points, PAR(ICP(1)) = %.6g (%s); expected %s", k->name,
           stress_end_name(o.status), o.npoints, o.t_last, o.msg, stress_end_name(k->expect));
  test_true(what, o.status == k->expect && (o.status > 0 || o.msg[0] != '\0'));
  snprintf(what, sizeof what, "%s: no NaN or Inf in %d accepted points", k->name, o.npoints);
  test_int(what, o.nonfinite, 0);
  snprintf(what, sizeof what, "%s: b- and s-files read back, all numbers finite", k->name);
  test_true(what, o.files_ok || o.npoints == 0);
  /* the drift is measured at the mesh points, where FUNC is never evaluated
     (Gauss collocation): a state there may have left the model's domain
     (cos eta or 1 - Delta omega3 below the guards) without the engine noticing */
  snprintf(what, sizeof what,
           "%s: first-integral drift measured on every accepted point (max %.3g, %d above %.0e): points "
           "outside the model's domain at mesh points",
           k->name, o.drift_max, o.drift_bad, DRIFT_GOAL);
  test_int(what, o.outside, 0);
  if (k->drift_checked) {
    snprintf(what, sizeof what, "%s: drift below the goal on every accepted point", k->name);
    test_le(what, o.drift_max, DRIFT_GOAL);
  }
  if (k->expect_bp > 0) {
    snprintf(what, sizeof what, "%s: branch points located", k->name);
    test_int(what, o.nbp, k->expect_bp);
  }
  double same = NAN;
  if (k->noise) {
    stress_run(k, 0, &ref);
    same = fabs(o.f_end - ref.f_end) / fabs(ref.f_end);
    snprintf(what, sizeof what, "%s: perturbed start reaches the clean solution: |F|", k->name);
    test_rel(what, o.f_end, ref.f_end, SAME_SOLUTION_TOL);
    snprintf(what, sizeof what, "%s: perturbed start reaches the clean solution: L", k->name);
    test_rel(what, o.l_end, ref.l_end, SAME_SOLUTION_TOL);
  }
  char same_txt[64] = "-", drift_txt[32] = "-";
  if (o.npoints > 0) snprintf(drift_txt, sizeof drift_txt, "%.3g", o.drift_max);
  if (k->noise) snprintf(same_txt, sizeof same_txt, "%.2g (start drift %.2g)", same, o.drift_start);
  if (table)
    fprintf(table, "TABLE | %s | %s | %d | %.3g | %.4g | %d | %s | %d | %d/%d | %.6g | %.4f | %s | %d | %s | %s | %.1f |\n",
            k->name, k->problem + 6, k->p * k->hand, k->delta, k->length, k->ntst, stress_end_name(o.status),
            o.npoints, o.nlp, o.nbp, o.t_last, o.eta_max, drift_txt, o.outside, o.npoints == 0 ? "-" : o.drift_bad == 0 ? "yes" : "no",
            same_txt, o.seconds);
}

int main(int argc, char **argv)
{
  int full = argc > 1 && strcmp(argv[1], "--full") == 0;
  const char *only = argc > 2 && strcmp(argv[1], "--case") == 0 ? argv[2] : NULL;
  FILE *table = (full || only) ? stdout : NULL;
  for (int i = 0; i < NCASES; i++) {
    if (only ? strcmp(cases[i].name, only) != 0 : !full && !cases[i].quick) continue;
    stress_case_check(&cases[i], table);
  }
  return test_summary();
}
