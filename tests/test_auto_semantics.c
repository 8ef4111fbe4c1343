/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO-07p's run semantics (issue 15, item 3), each confirmed by running
 * auto-07p 0.9.2 on the same problem (doc/engine.md, "AUTO's run semantics"):
 *   1. the stored direction: the step is DS times it, so a restart with DS < 0
 *      from a run made with DS < 0 goes on;
 *   2. no special point in the first step of a run (the start on a UZR value,
 *      a UZR value inside the first step);
 *   3. after a switch at a branch point (ISW = -1) the first step reports no
 *      BP and is not shortened (the test function is ~0 at the start);
 *   4. UZR and UZSTOP on a parameter that PVLS computes fire;
 *   5. branch points of BVPs are looked for with ISP = 2 or 3 only, and a
 *      switched run's first point has no label;
 *   6. an LP and a BP inside one step are both reported, in arclength order;
 *   7. a switch at a simple BP is oriented by AUTO's rule for AUTO's equations;
 *   8. every UZR value once, in order, where a step lands on it or one step
 *      crosses several.
 * (run('NAME') = e='NAME', c='NAME': tests/test_cli.c and tests/python/test_commands.py.) */
#include <math.h>
#include <string.h>

#include "cable/cable_cont.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"

/* Bratu: lambda = th^2 / (2 cosh^2(th/4)), max u = u(1/2) = 2 ln cosh(th/4). */
static double bratu_lambda_at_umax(double umax)
{
  double c = exp(0.5 * umax), th = 4.0 * acosh(c);
  return th * th / (2.0 * c * c);
}

/* Bratu's constants of runs/bratu (NTST = 20, NCOL = 4) without adaptation. */
static void bratu_constants(cable_constants *c)
{
  engine_constants(c, 20, 4);
  c->ds = 0.1; c->dsmin = 1e-5; c->dsmax = 0.5; c->nmx = 60;
  c->rl0 = -0.01; c->rl1 = 5.0;
  c->ilp = 1; c->isp = 2;
  c->epsl = c->epsu = 1e-8; c->epss = 1e-7;
}

/* 1. The direction convention.  auto-07p on Bratu (DS = -0.1, NMX = 4 from the
 * fold, then from that run's end): DS = -0.1 goes on down the lower branch
 * (lambda 3.4686 -> 3.3628), DS = +0.1 turns back (-> 3.5121). */
static void test_direction(memrun *r)
{
  cable_constants c;
  bratu_constants(&c);
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  cable_solution *lp = cable_solution_clone(memrun_find(r, CABLE_TY_LP, 0));
  memrun_free(r);
  test_true("Bratu: the fold is found", lp != NULL);
  if (!lp) return;
  bratu_constants(&c);
  c.ds = -0.1; c.nmx = 4; c.ilp = 0; c.iads = 0;
  memrun_run(cable_testproblem_bratu(), &c, lp, r);
  cable_solution *end = r->nsol > 0 ? cable_solution_clone(r->sol[r->nsol - 1]) : NULL;
  double lam_fold = lp->par[0], lam_end = end ? end->par[0] : (double)NAN;
  test_true("from the fold with DS = -0.1: down the lower branch (lambda decreases)", lam_end < lam_fold);
  memrun_free(r);
  if (end) {
    memrun_run(cable_testproblem_bratu(), &c, end, r);
    test_true("restart with DS = -0.1 from a DS = -0.1 run goes on (lambda decreases at every point)",
              r->n == 4 && r->par[1][0] < lam_end && r->par[3][0] < r->par[1][0]);
    memrun_free(r);
    c.ds = 0.1;
    memrun_run(cable_testproblem_bratu(), &c, end, r);
    test_true("restart with DS = +0.1 from a DS = -0.1 run turns back (lambda increases)",
              r->n == 4 && r->par[1][0] > lam_end && r->par[3][0] > r->par[1][0]);
    memrun_free(r);
  }
  cable_solution_free(end);
  cable_solution_free(lp);
}

/* 2. No special point in the first step.  auto-07p on Bratu from u = 0 with
 * DS = 0.1 and UZR = {1: [0.0, 0.05, 0.15]}: only 0.15 is a UZ (label 2). */
static void test_first_step(memrun *r)
{
  cable_constants c;
  bratu_constants(&c);
  c.iads = 0; c.nmx = 4;
  c.nuzr = 3;
  double vals[3] = {0.0, 0.05, 0.15};
  for (int k = 0; k < 3; k++) {
    c.uzr[k].par = 0;
    c.uzr[k].value = vals[k];
    c.uzr[k].stop = 0;
  }
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  int nuz = memrun_count(r, CABLE_TY_UZ);
  const cable_solution *uz = memrun_find(r, CABLE_TY_UZ, 0);
  test_int("UZR at the start (0) and inside the first step (0.05): not reported; 0.15: one UZ", nuz, 1);
  test_rel("the one UZ is at lambda = 0.15", uz ? uz->par[0] : (double)NAN, 0.15, 1e-12);
  test_int("its label is 2 (the start is 1), as auto-07p's", uz ? uz->lab : -1, 2);
  memrun_free(r);
}

/* A sink that keeps each point's type and step. */
typedef struct {
  int n, nbp;
  double ds[64];
  int itp[64];
  double l2;     /* of the last point */
} steprec;

static int steprec_point(void *ctx, const cable_point *pt)
{
  steprec *s = ctx;
  if (s->n < 64) {
    s->ds[s->n] = pt->ds;
    s->itp[s->n] = pt->itp;
    s->n++;
  }
  s->l2 = pt->l2norm;
  s->nbp += pt->itp % 10 == CABLE_TY_BP;
  return 0;
}

/* 3. After a switch at the elastica's branch points (runs/elastica's mesh,
 * NTST = 50, NCOL = 5), with the BP test on (ISP = 2): the buckled branches
 * have no branch point near the straight state's, so none may be reported,
 * the first step is DS, and after 9 steps the branch is well away from the
 * straight state.  (Before the rule, these three switches reported the start
 * again as a BP at PT 2 and then crawled: L2-NORM 2.5e-4 after 9 steps.) */
static void test_after_switch(memrun *r)
{
  cable_constants c;
  elastica_trivial_constants(&c, 50, 5);
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  cable_solution *bp[3];
  for (int k = 0; k < 3; k++) bp[k] = cable_solution_clone(memrun_find(r, CABLE_TY_BP, k));
  memrun_free(r);
  test_true("elastica: BP1, BP2, BP3 found", bp[0] && bp[1] && bp[2]);
  static const struct { int k; double ds; } cases[] = {{0, -0.2}, {1, 0.05}, {2, -0.05}};
  for (size_t q = 0; q < sizeof cases / sizeof cases[0] && bp[2]; q++) {
    engine_constants(&c, 50, 5);
    c.isw = -1;
    c.ds = cases[0].ds; c.dsmin = 1e-6; c.dsmax = 2.0; c.nmx = 10;
    c.isp = 2; c.ilp = 0;
    c.epss = 1e-10;
    int st;
    steprec rec = {0};
    cable_cont *cc = cable_cont_alloc(cable_testproblem_elastica(), &c, &st);
    if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, bp[cases[0].k]);
    if (st == CABLE_SUCCESS) {
      cable_sink sink = {&rec, steprec_point, NULL, NULL};
      st = cable_cont_run(cc, &sink, 1, 1, NULL);
    }
    cable_cont_free(cc);
    char what[160];
    snprintf(what, sizeof what, "switch at BP%d with DS = %+.2f, ISP = 2: 10 points, no BP reported", cases[0].k + 1,
             c.ds);
    test_true(what, st > 0 && rec.n == 10 && rec.nbp == 0);
    /* auto-07p (demos lin, bvp): a switched run's first point has no label */
    snprintf(what, sizeof what, "switch at BP%d with DS = %+.2f: the first point is not labelled EP", cases[0].k + 1,
             c.ds);
    test_int(what, rec.n > 0 ? rec.itp[0] : -99, CABLE_TY_NONE);
    snprintf(what, sizeof what, "switch at BP%d with DS = %+.2f: the first step is |DS|", cases[0].k + 1, c.ds);
    test_rel(what, rec.n > 1 ? fabs(rec.ds[1]) : (double)NAN, fabs(c.ds), 1e-14);
    snprintf(what, sizeof what, "switch at BP%d with DS = %+.2f: L2-NORM after 9 steps > 1 (no collapse)",
             cases[0].k + 1, c.ds);
    test_true(what, rec.n == 10 && rec.l2 > 1.0);
  }
  for (int k = 0; k < 3; k++) cable_solution_free(bp[k]);
}

/* 5. ISP: auto-07p 0.9.2 looks for branch points of boundary-value problems
 * with ISP = 2 or 3 only (the elastica from P = 1 with ISP = 1, 2, 3, 4:
 * BPs at pi^2 and 4 pi^2 with ISP = 2 and 3, none with 1 and 4). */
static void test_isp(memrun *r)
{
  static const int want[5] = {0, 0, 3, 3, 0};
  for (int isp = 1; isp <= 4; isp++) {
    cable_constants c;
    elastica_trivial_constants(&c, 50, 5);
    c.isp = isp;
    memrun_run(cable_testproblem_elastica(), &c, NULL, r);
    int nbp = 0;
    for (int i = 0; i < r->n; i++) nbp += r->itp[i] % 10 == CABLE_TY_BP;
    char what[120];
    snprintf(what, sizeof what, "elastica, ISP = %d: %d branch points reported (AUTO's rule)", isp, want[isp]);
    test_int(what, nbp, want[isp]);
    memrun_free(r);
  }
}

/* 4. Bratu with PAR(2) = max u from PVLS (auto-07p fires UZR on PVLS
 * parameters: its UZ4/UZ5 at PAR(3) = 2, 3 in the same experiment). */
static int bratu_pvls_umax(const struct cable_solution *sol, double *par, void *params)
{
  (void)params;
  int npts = sol->ntst * sol->ncol + 1;
  double umax = sol->u[0];
  for (int k = 1; k < npts; k++) umax = fmax(umax, sol->u[k * sol->ndim]);
  par[1] = umax;
  return 0;
}

static void test_pvls_uzr(memrun *r)
{
  static const char *const names[] = {"lambda", "umax"};
  cable_problem pb = *cable_testproblem_bratu();
  pb.npar = 3;
  pb.parnames = names;
  pb.pvls = bratu_pvls_umax;
  cable_constants c;
  bratu_constants(&c);
  c.icp[1] = 1;
  c.nicp = 2;
  c.nuzr = 1;
  c.uzr[0].par = 1;
  c.uzr[0].value = 1.0;
  c.uzr[0].stop = 0;
  memrun_run(&pb, &c, NULL, r);
  const cable_solution *uz = memrun_find(r, CABLE_TY_UZ, 0);
  test_int("UZR on umax (PVLS) = 1: one UZ (max u is 1.1868 at the fold)", memrun_count(r, CABLE_TY_UZ), 1);
  /* max u sits at t = 1/2, a mesh point (NTST even): superconvergent, error
     O(h^8) ~ 1e-11; located to EPSS = 1e-7 of the step in arclength, along
     which lambda moves with slope < 1 */
  test_rel("at the UZ, lambda is the closed form's for max u = 1", uz ? uz->par[0] : (double)NAN, bratu_lambda_at_umax(1.0), 1e-7);
  test_rel("at the UZ, max u = 1", uz ? uz->par[1] : (double)NAN, 1.0, 1e-7);
  memrun_free(r);
  c.uzr[0].stop = 1;
  memrun_run(&pb, &c, NULL, r);
  test_true("UZSTOP on umax = 1 ends the branch there", r->status == CABLE_END_UZSTOP && r->nsol > 0 &&
                                                       fabs(r->sol[r->nsol - 1]->par[1] - 1.0) < 1e-7);
  memrun_free(r);
}


/* 6. An LP and a BP inside one step are both reported, in the order of
 * arclength (AUTO locates each test function's zero in turn).  The problem,
 * NDIM = NBC = 2, u' = 0, PAR(1) = lambda, PAR(2) = a, PAR(3) = c:
 *   lambda - (u1(0) - a)^2 = 0,   u2(0) (u1(0) - c - u2(0)^2) = 0.
 * Its branch u2 = 0, lambda = (u1 - a)^2 has the fold (LP) at u1 = a,
 * lambda = 0, and a pitchfork (BP) at u1 = c, lambda = (c - a)^2, where
 * u2^2 = u1 - c branches off (the symmetry u2 -> -u2 keeps the corrector on
 * u2 = 0).  With |c - a| = 0.005 and steps of 0.1 to 0.29, many steps hold
 * both.  Before the rule 5 of these 80 runs lost one of the two (the point
 * located first lay beyond the other zero, whose sign change was consumed;
 * or the fold test at a located BP, from the interpolated tangent, had the
 * wrong sign). */
typedef struct { double u, a, c; } parab_start;
static int parab_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                      double *dfdu, double *dfdp, void *params)
{
  (void)ndim; (void)u; (void)icp; (void)par; (void)ijac; (void)dfdu; (void)dfdp; (void)params;
  f[0] = f[1] = 0.0;
  return 0;
}
static int parab_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                      int ijac, double *fb, double *dbc, void *params)
{
  (void)ndim; (void)icp; (void)nbc; (void)u1; (void)ijac; (void)dbc; (void)params;
  double d = u0[0] - par[1];
  fb[0] = par[0] - d * d;
  fb[1] = u0[1] * (u0[0] - par[2] - u0[1] * u0[1]);
  return 0;
}
static int parab_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  (void)ndim; (void)t;
  const parab_start *s = params;
  double d = s->u - s->a;
  u[0] = s->u;
  u[1] = 0.0;
  par[0] = d * d;
  par[1] = s->a;
  par[2] = s->c;
  return 0;
}

static void test_lp_bp_one_step(memrun *r)
{
  static const char *const names[] = {"lambda", "a", "c"};
  const double a = 0.05, cs[2] = {0.045, 0.055};
  int nbad = 0, nruns = 0;
  for (int ic = 0; ic < 2; ic++)
    for (int side = 0; side < 2; side++)
      for (int k = 0; k < 20; k++) {
        /* from u1 = 0.75 with DS < 0 (lambda falls, u1 falls) or from
           u1 = -0.7 (lambda falls, u1 grows) */
        parab_start st0 = {side ? -0.7 : 0.75, a, cs[ic]};
        cable_problem pb = *cable_testproblem_bratu();
        pb.name = "lpbp";
        pb.ndim = 2; pb.nbc = 2; pb.nint = 0; pb.npar = 3;
        pb.parnames = names; pb.unames = NULL;
        pb.func = parab_func; pb.bcnd = parab_bcnd; pb.icnd = NULL; pb.stpnt = parab_stpnt; pb.pvls = NULL;
        pb.func_has_jac = pb.bcnd_has_jac = pb.icnd_has_jac = 0;
        pb.params = &st0;
        cable_constants c;
        engine_constants(&c, 4, 2);
        c.jac = 0;
        c.ds = -(0.1 + 0.01 * k); c.dsmin = 1e-6; c.dsmax = fabs(c.ds); c.iads = 0; c.nmx = 40;
        c.rl0 = -1.0; c.rl1 = 2.0;
        c.ilp = 1; c.isp = 2;
        c.epsl = c.epsu = 1e-10; c.epss = 1e-8;
        memrun_run(&pb, &c, NULL, r);
        /* u1 moves monotonically along the branch here: the order of arclength
           is the order of u1, falling from the right, growing from the left */
        int ilp = -1, ibp = -1, nlp = 0, nbp = 0;
        for (int i = 0; i < r->nsol; i++) {
          if (r->sol[i]->itp == CABLE_TY_LP) { ilp = i; nlp++; }
          if (r->sol[i]->itp == CABLE_TY_BP) { ibp = i; nbp++; }
        }
        int lp_first = (cs[ic] < a) == (side == 0);
        int ok = nlp == 1 && nbp == 1 && (lp_first ? ilp < ibp : ibp < ilp) &&
                 fabs(r->sol[ilp]->par[0]) < 1e-9 && fabs(r->sol[ilp]->u[0] - a) < 1e-6 &&
                 fabs(r->sol[ibp]->par[0] - (cs[ic] - a) * (cs[ic] - a)) < 1e-9 &&
                 fabs(r->sol[ibp]->u[0] - cs[ic]) < 1e-6;
        if (!ok) {
          nbad++;
          fprintf(stderr, "  c = %g, from u1 = %g, DS = %g: %d LP, %d BP (status %d)", cs[ic], st0.u, c.ds, nlp, nbp,
                  r->status);
          for (int i = 0; i < r->nsol; i++) fprintf(stderr, " [%d %.3g %.6g]", r->sol[i]->itp, r->sol[i]->par[0], r->sol[i]->u[0]);
          fprintf(stderr, "\n");
        }
        nruns++;
        memrun_free(r);
      }
  char what[200];
  snprintf(what, sizeof what,
           "an LP and a BP 0.005 apart, %d runs with steps 0.1..0.29: each reports one LP (lambda = 0, u1 = a) and one "
           "BP (lambda = (c - a)^2, u1 = c), in the order of arclength", nruns);
  test_int(what, nbad, 0);
}

/* 6b. A fold the engine cannot locate is reported in one line with the
 * number that matters (how closely it is bracketed), not the corrector's
 * message twice (it was up to 350 characters).  The problem of 6 with its
 * pitchfork far away (c = 0.5) and ITMX = 2: two secant iterations do not
 * reach the tolerance EPSS = 1e-8. */
typedef struct {
  int n;
  char note[8][600];
} note_log;
static int note_point(void *ctx, const cable_point *pt)
{
  note_log *l = ctx;
  if (pt->note && strstr(pt->note, "could not locate the fold") && l->n < 8)
    snprintf(l->note[l->n++], sizeof l->note[0], "%s", pt->note);
  return 0;
}

static void test_fold_not_located_one_line(void)
{
  static const char *const names[] = {"lambda", "a", "c"};
  int found = 0, ok = 1;
  for (int k = 0; k < 20 && !found; k++) {
    parab_start st0 = {0.75, 0.05, 0.5};
    cable_problem pb = *cable_testproblem_bratu();
    pb.name = "lpbp";
    pb.ndim = 2; pb.nbc = 2; pb.nint = 0; pb.npar = 3;
    pb.parnames = names; pb.unames = NULL;
    pb.func = parab_func; pb.bcnd = parab_bcnd; pb.icnd = NULL; pb.stpnt = parab_stpnt; pb.pvls = NULL;
    pb.func_has_jac = pb.bcnd_has_jac = pb.icnd_has_jac = 0;
    pb.params = &st0;
    cable_constants c;
    engine_constants(&c, 4, 2);
    c.jac = 0;
    c.ds = -(0.1 + 0.01 * k); c.dsmin = 1e-6; c.dsmax = fabs(c.ds); c.iads = 0; c.nmx = 40;
    c.rl0 = -1.0; c.rl1 = 2.0;
    c.ilp = 1; c.isp = 0; c.itmx = 2;
    c.epsl = c.epsu = 1e-10; c.epss = 1e-8;
    int st = 0;
    cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
    note_log l = {0};
    cable_sink sink = {&l, note_point, NULL, NULL};
    if (cc && cable_cont_set_start(cc, NULL) == 0) cable_cont_run(cc, &sink, 1, 1, NULL);
    cable_cont_free(cc);
    for (int i = 0; i < l.n; i++) {
      found = 1;
      const char *n = l.note[i];
      const char *first = strstr(n, "corrector");
      ok &= strlen(n) <= 160 && !strchr(n, '\n') && strstr(n, "it lies within") != NULL &&
            (!first || !strstr(first + 1, "corrector"));
      if (!ok) fprintf(stderr, "  note: %s\n", n);
    }
  }
  test_true("ITMX = 2: the fold is not located and a point's note says so", found);
  test_true("that note is one line of at most 160 characters with the bracket's width, the reason once", found && ok);
}

/* 7. The orientation of a switch at a simple branch point, for equations from
 * AUTO files (AUTO's STDRBV, the BVP start that ISW = -1 uses): the first free
 * parameter's component that is not negligible is positive, else the first
 * U(i) at t = 1 that is not.  At the elastica's pitchforks the kernel
 * cos(n pi t) leaves lambda fixed, so AUTO makes theta(1) positive: the switch
 * with DS > 0 starts with theta(1) > 0 at BP1, BP2 and BP3 (auto-07p's lin
 * demo by the same rule: u'(1) > 0 at its BP1).  cable's own rule (the largest
 * component positive) gives theta(1) < 0 at BP3; it stays for cable's problems
 * (the scenes' switches). */
static void test_switch_orientation(memrun *r)
{
  cable_constants c;
  elastica_trivial_constants(&c, 50, 5);
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  cable_solution *bp[3];
  for (int k = 0; k < 3; k++) bp[k] = cable_solution_clone(memrun_find(r, CABLE_TY_BP, k));
  memrun_free(r);
  for (int k = 0; k < 3 && bp[2]; k++)
    for (int rule = 0; rule < 2; rule++) {
      engine_constants(&c, 50, 5);
      c.isw = -1;
      c.ds = 0.05; c.dsmin = 1e-6; c.dsmax = 0.05; c.nmx = 3;
      c.isp = 2; c.ilp = 0;
      c.bp_orient_auto = rule;
      memrun_run(cable_testproblem_elastica(), &c, bp[k], r);
      const cable_solution *e = r->nsol > 0 ? r->sol[r->nsol - 1] : NULL;
      double th1 = e ? e->u[(size_t)(e->ntst * e->ncol) * (size_t)e->ndim] : (double)NAN, th0 = e ? e->u[0] : (double)NAN;
      char what[200];
      if (rule) {
        snprintf(what, sizeof what, "AUTO's orientation, switch at BP%d with DS = +0.05: theta(1) > 0 after 2 steps "
                 "(theta(1) = %.4f)", k + 1, th1);
        test_true(what, th1 > 0);
      } else if (k == 2) {
        /* the two rules differ here, so the check above can fail */
        snprintf(what, sizeof what, "cable's orientation, switch at BP3 with DS = +0.05: theta(1) < 0 after 2 steps "
                 "(theta(0) = %.4f, theta(1) = %.4f)", th0, th1);
        test_true(what, th1 < 0);
      }
      memrun_free(r);
    }
  for (int k = 0; k < 3; k++) cable_solution_free(bp[k]);
}

/* 8. Every UZR value is reported once, in order along the branch, at its
 * value: when a step lands exactly on it, and when one step crosses several.
 * The elastica's straight branch (theta = 0, P = PAR(1)) has P linear in the
 * arclength, so its steps land exactly on a grid of P: from P = 1 with
 * DS = 0.5 on P = 1.5, 2, 2.5, ... (auto-07p on the same problem reports each,
 * tests/data/autoeq/numbering). */
typedef struct {
  int n;
  double p[16];
  int lab[16], bad_lab;
} uzlist;

static void uz_points(const memrun *r, int par, uzlist *u)
{
  memset(u, 0, sizeof *u);
  int prev = -1;
  for (int i = 0; i < r->n; i++) {
    if (r->itp[i] % 10 != CABLE_TY_UZ) continue;
    if (u->n < 16) {
      u->p[u->n] = r->par[i][par];
      u->lab[u->n] = r->lab[i];
    }
    if (prev >= 0 && r->lab[i] != prev + 1) u->bad_lab = 1;
    prev = r->lab[i];
    u->n++;
  }
}

/* want[k] for k < n: the values in order; tol: absolute, in PAR(par) */
static void check_uz(const char *what, const memrun *r, int par, const double *want, int n, double tol)
{
  uzlist u;
  uz_points(r, par, &u);
  char buf[300];
  snprintf(buf, sizeof buf, "%s: %d UZ points", what, n);
  test_int(buf, u.n, n);
  for (int k = 0; k < n && k < u.n; k++) {
    snprintf(buf, sizeof buf, "%s: UZ %d at PAR(%d) = %g", what, k + 1, par + 1, want[k]);
    test_abs(buf, u.p[k], want[k], tol);
  }
  snprintf(buf, sizeof buf, "%s: the UZ labels are consecutive", what);
  test_true(buf, !u.bad_lab);
}

/* (P - 3)^4 / 16 into PAR(2): a value PVLS computes, convex in P, so that
 * linear interpolation in one step puts its crossing far too early */
static int elastica_pvls_quartic(const struct cable_solution *sol, double *par, void *params)
{
  (void)sol; (void)params;
  double d = par[0] - 3.0;
  par[1] = d * d * d * d / 16.0;
  return 0;
}

static void test_uz_grid(memrun *r)
{
  cable_constants c;
  elastica_trivial_constants(&c, 20, 4);
  c.isp = 0; c.rl1 = 9.0; /* below the first branch point, P = pi^2 */
  c.epss = 1e-7;
  /* DS = DSMAX = 0.5 from P = 1: the steps land on P = 3, 4, 5 */
  c.ds = c.dsmax = 0.5;
  c.nuzr = 3;
  for (int k = 0; k < 3; k++) {
    c.uzr[k].par = 0;
    c.uzr[k].value = 3.0 + k;
    c.uzr[k].stop = 0;
  }
  static const double on_grid[] = {3.0, 4.0, 5.0};
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  check_uz("elastica, DS = DSMAX = 0.5, UZR on the step grid", r, 0, on_grid, 3, 1e-12);
  memrun_free(r);
  /* DSMAX = 2: steps 1 -> 1.5 -> 2.5 -> 4.5 (3 and 4 in one step), then
     from the located UZ on; several values in a step and values hit exactly */
  c.dsmax = 2.0;
  c.nuzr = 5;
  for (int k = 0; k < 5; k++) {
    c.uzr[k].par = 0;
    c.uzr[k].value = 3.0 + k;
    c.uzr[k].stop = 0;
  }
  static const double grid5[] = {3.0, 4.0, 5.0, 6.0, 7.0};
  memrun_run(cable_testproblem_elastica(), &c, NULL, r);
  check_uz("elastica, DSMAX = 2, UZR 3, 4, 5, 6, 7", r, 0, grid5, 5, 1e-6);
  memrun_free(r);
  /* three zeros in one step, of two parameters: DS = DSMAX = 2 from P = 1
     (P = 3, 5, 7: the step 3 -> 5 holds all three), UZR on P at 3.9 and
     4.2 and on PVLS's (P - 3)^4 / 16 at 0.4096, i.e. P = 4.6, whose
     linear interpolation (0.20 of the step) comes first; in order along
     the branch: 3.9, 4.2, 4.6 */
  static const char *const names[] = {"P", "q"};
  cable_problem pb = *cable_testproblem_elastica();
  pb.npar = 2;
  pb.parnames = names;
  pb.pvls = elastica_pvls_quartic;
  c.ds = c.dsmax = 2.0;
  c.iads = 0;
  c.nuzr = 3;
  c.uzr[0].par = 0; c.uzr[0].value = 3.9;
  c.uzr[1].par = 1; c.uzr[1].value = 0.4096;
  c.uzr[2].par = 0; c.uzr[2].value = 4.2;
  static const double mixed[] = {3.9, 4.2, 4.6};
  memrun_run(&pb, &c, NULL, r);
  check_uz("elastica, one step over UZR P = 3.9, 4.2 and PVLS (P - 3)^4 / 16 = 0.4096", r, 0, mixed, 3, 1e-6);
  memrun_free(r);
}

int main(void)
{
  static memrun r;
  test_direction(&r);
  test_first_step(&r);
  test_after_switch(&r);
  test_pvls_uzr(&r);
  test_isp(&r);
  test_lp_bp_one_step(&r);
  test_fold_not_located_one_line();
  test_switch_orientation(&r);
  test_uz_grid(&r);
  return test_summary();
}
