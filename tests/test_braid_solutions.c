/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Converged braid solutions (engine + braid model + conditions + geometry):
 *  - the flat right-handed (7,2) knot at T = 2 and the left-handed one at
 *    T = -2: the same |F| (mirror symmetry), Lk = +3.5 and -3.5;
 *  - eps21 (the unfolding parameter of the redundant condition) vanishes and
 *    the first integrals are constant along the braid;
 *  - the flat left-handed (6,2) link: Lk = -3, an integer;
 *  - the PVLS columns Lk, Tw, Wr, pmin, dmin and err of a run that prints
 *    them, read back from the b-file, agree with cable_braid_analysis on the
 *    stored solutions (from STPNT and on a restart), and a run that does not
 *    print them leaves them uncomputed; both runs note their start's
 *    residual in the d-file;
 *  - along a whole stored branch (mode 1 of the flat (7,2) knot, every point
 *    labelled, through the self-passage of the braid axis where Lk jumps
 *    from 3.5 to 5.5), Lk is a half-integer to 1e-6 at every label, or the
 *    label is flagged unresolved with its writhe error estimate;
 *  - the link continued in Phi: every solution's end frame is its start
 *    frame turned by Phi about t1(0), and the strand closes;
 *  - braid_link from the two rings (TORUS=0) is refused with a message
 *    naming TORUS; the (1,2) torus knot (TORUS=1) converges with full Newton
 *    steps (ITNW = NWTN = 10) and has Lk = +-0.5. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_math.h>

#include "cable/cable_aufile.h"
#include "cable/cable_analysis.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_cont.h"
#include "harness.h"
#include "ribbon.h"
#include "session_util.h"

/* Continue from the torus guess in T to T = target; returns the solution there. */
static cable_solution *flat_at(const char *name, int p, int hand, double delta, double length, double target,
                               const int *icp, int nicp, int ntst)
{
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, p, hand, delta, length, 0.0);
  if (braid_start_prepare(&sp) != 0) return NULL;
  cable_problem pb;
  if (braid_problem_instance(name, &sp, &pb) != 0) return NULL;
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  /* a uniform mesh (IAD=0) keeps the two mirror-image computations identical */
  c.ntst = ntst; c.ncol = 4; c.jac = 1; c.iad = 0;
  for (int k = 0; k < nicp; k++) c.icp[k] = icp[k];
  c.nicp = nicp;
  c.ds = target > 0 ? 0.5 : -0.5; c.dsmin = 1e-6; c.dsmax = 2.0; c.nmx = 200; c.isp = 0; c.ilp = 0;
  c.nuzr = 1; c.uzr[0].par = BP_T; c.uzr[0].value = target; c.uzr[0].stop = 1;
  c.epss = 1e-9;
  int st;
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  while (st == 0) st = cable_cont_step(cc);
  cable_solution *s = st == CABLE_END_UZSTOP ? cable_solution_clone(cable_cont_solution(cc)) : NULL;
  cable_cont_free(cc);
  return s;
}

/* ---- PVLS columns through the run host and the b-file ------------------- */

static int write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fputs(text, f);
  return fclose(f);
}

static const double *bcol(const cable_bfile *b, int br, const char *name)
{
  return b && br < b->nbranch ? cable_bfile_column(&b->branch[br], name) : NULL;
}

/* Every labelled row of branch br against cable_braid_analysis on the s-file's
 * solution of that label. */
static void check_pvls_rows(const char *what, const cable_bfile *b, int br, const cable_sfile *s)
{
  const double *lk = bcol(b, br, "Lk"), *tw = bcol(b, br, "Tw"), *wr = bcol(b, br, "Wr");
  const double *pmin = bcol(b, br, "pmin"), *dmin = bcol(b, br, "dmin"), *err = bcol(b, br, "err");
  const double *T = bcol(b, br, "T"), *T1 = bcol(b, br, "T1"), *T2 = bcol(b, br, "T2");
  const double *wrerr = bcol(b, br, "Wrerr"), *qn = bcol(b, br, "qnorm");
  const char *fi[4] = {"FM", "h", "Ham", "F"};
  char t0[200];
  snprintf(t0, sizeof t0, "%s: b-file has the columns T1 T2 Wrerr qnorm FM h Ham F", what);
  int have_fi = T && T1 && T2 && wrerr && qn;
  for (int k = 0; k < 4; k++) have_fi = have_fi && bcol(b, br, fi[k]);
  test_true(t0, have_fi);
  if (have_fi) {
    const cable_bfile_branch *bb0 = &b->branch[br];
    double dt = 0.0, dq = 0.0, we = 0.0;
    for (int i = 0; i < bb0->nrow; i++) {
      dt = fmax(dt, fmax(fabs(T1[i] - T[i]), fabs(T2[i] + T[i])));
      dq = fmax(dq, fabs(qn[i]));
      we = fmax(we, wrerr[i]);
    }
    /* T' = 0 is integrated exactly by collocation: T1(1) = T1(0) = T to
       round-off (and the b-file's 11 digits, |T| <= 1) */
    snprintf(t0, sizeof t0, "%s: every row has T1 = T and T2 = -T", what);
    test_le(t0, dt, 1e-9);
    /* |q|^2 is conserved by the ODE; the discrete solution keeps it to the
       discretisation error */
    snprintf(t0, sizeof t0, "%s: every row has |qnorm| small", what);
    test_le(t0, dq, 1e-6);
    snprintf(t0, sizeof t0, "%s: Wrerr column within BRAID_RIBBON_WR_TOL", what);
    test_true(t0, we > 0 && we <= BRAID_RIBBON_WR_TOL);
  }
  char t[200];
  snprintf(t, sizeof t, "%s: b-file has the columns Lk Tw Wr pmin dmin err", what);
  test_true(t, lk && tw && wr && pmin && dmin && err);
  if (!(lk && tw && wr && pmin && dmin && err)) return;
  const cable_bfile_branch *bb = &b->branch[br];
  int nlab = 0;
  for (int i = 0; i < bb->nrow; i++) {
    if (bb->lab[i] <= 0) continue;
    const cable_solution *sol = cable_sfile_find_label(s, bb->lab[i]);
    cable_braid_analysis a;
    if (!sol || cable_braid_analysis_compute(sol, &a) != 0) {
      snprintf(t, sizeof t, "%s: label %d analysed", what, bb->lab[i]);
      test_true(t, 0);
      continue;
    }
    nlab++;
    /* a flat (7,2) knot: Lk = 3.5 up to the interpolant's closure and the
       quadrature (the writhe test's 1e-6); Tw + Wr = Lk to the b-file's 11
       digits */
    snprintf(t, sizeof t, "%s LAB %d: Lk column = 3.5", what, bb->lab[i]);
    test_abs(t, lk[i], 3.5, 1e-6);
    snprintf(t, sizeof t, "%s LAB %d: Tw + Wr = Lk", what, bb->lab[i]);
    test_abs(t, tw[i] + wr[i], lk[i], 1e-9);
    snprintf(t, sizeof t, "%s LAB %d: Tw column = analyze's Tw", what, bb->lab[i]);
    test_abs(t, tw[i], a.topo.tw, 1e-8);
    /* the b-file row and the s-file solution differ by the s-file's rounding
       of u (~1e-11 relative), which moves pmin and dmin by as little */
    snprintf(t, sizeof t, "%s LAB %d: pmin column = analyze's min(pmin1, pmin2)", what, bb->lab[i]);
    test_rel(t, pmin[i], fmin(a.pmin1, a.pmin2), 1e-8);
    snprintf(t, sizeof t, "%s LAB %d: dmin column = analyze's dmin", what, bb->lab[i]);
    test_rel(t, dmin[i], a.tube.dmin, 1e-8);
    snprintf(t, sizeof t, "%s LAB %d: err column = the solution's error estimate", what, bb->lab[i]);
    test_rel(t, err[i], sol->err_est, 1e-8);
  }
  snprintf(t, sizeof t, "%s: labelled rows checked", what);
  test_true(t, nlab >= 2);
}

/* The residual in the d-file's NOTE "<what> ... max |F| = <r>" (the first
 * such line), or INFINITY when there is none. */
static double start_residual(const char *dfile, const char *what)
{
  FILE *f = fopen(dfile, "r");
  if (!f) return INFINITY;
  char line[1024];
  double r = INFINITY;
  while (fgets(line, sizeof line, f)) {
    const char *n = strstr(line, "NOTE: "), *m = strstr(line, "max |F| = ");
    if (n && m && strncmp(n + 6, what, strlen(what)) == 0) {
      r = strtod(m + 10, NULL);
      break;
    }
  }
  fclose(f);
  return r;
}

static void test_pvls_columns(void)
{
  char dir[] = "/tmp/cable_pvls_XXXXXX";
  if (!mkdtemp(dir)) {
    test_true("temporary directory", 0);
    return;
  }
  char path[256];
  snprintf(path, sizeof path, "%s/c.pvls", dir);
  write_file(path, "e = 'braid_knot'\n"
                   "NDIM = 21, IPS = 4\n"
                   "ICP = ['T', 'L', 'L2', 'eps21', 'F', 'Lk', 'Tw', 'Wr', 'pmin', 'dmin', 'err', 'Wrerr', "
                   "'T1', 'T2', 'FM', 'h', 'qnorm', 'Ham']\n"
                   "TORUS = 7, HAND = 1\n"
                   "PAR = {'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0.0}\n"
                   "NTST = 40, NCOL = 4, IAD = 3, JAC = 1, ISP = 0, ILP = 0\n"
                   "DS = 1.0, DSMIN = 1e-6, DSMAX = 5.0, NMX = 4, NPR = 2\n");
  /* the restart's constants set no PAR: a PAR={'T': ...} in the constants
     would override the stored solution's T on restart (AUTO's rule) while
     the first point is written without Newton, so its T1 column would not
     equal its T */
  snprintf(path, sizeof path, "%s/c.pvlsr", dir);
  write_file(path, "e = 'braid_knot'\n"
                   "NDIM = 21, IPS = 4\n"
                   "ICP = ['T', 'L', 'L2', 'eps21', 'F', 'Lk', 'Tw', 'Wr', 'pmin', 'dmin', 'err', 'Wrerr', "
                   "'T1', 'T2', 'FM', 'h', 'qnorm', 'Ham']\n"
                   "NTST = 40, NCOL = 4, IAD = 3, JAC = 1, ISP = 0, ILP = 0\n"
                   "DS = 1.0, DSMIN = 1e-6, DSMAX = 5.0, NMX = 4, NPR = 2\n");
  FILE *log;
  cable_session *r = session_open(dir, &log);
  cable_error err;
  memset(&err, 0, sizeof err);
  /* from STPNT, a restart from a stored label, and a run without the columns */
  cable_branch *first = NULL;
  int rc = r ? session_line(r, "e=braid_knot c=pvls sv=pvls", NULL, &first, &err) : -1;
  if (!rc) rc = session_line(r, "e=braid_knot c=pvlsr IRS='EP2' NMX=3 sv=pvls2", first, NULL, &err);
  if (!rc) rc = session_line(r, "e=braid_knot c=pvls ICP=['T', 'L', 'L2', 'eps21'] NMX=2 sv=pvls3", NULL, NULL, &err);
  cable_branch_decref(first);
  session_close(r, log);
  test_int("PVLS runs: the runs succeed", rc, 0);
  if (rc != 0) printf("  %s\n", err.msg);
  const char *names[2] = {"pvls", "pvls2"};
  for (int k = 0; k < 2 && rc == 0; k++) {
    char bp[256], sp[256];
    snprintf(bp, sizeof bp, "%s/b.%s", dir, names[k]);
    snprintf(sp, sizeof sp, "%s/s.%s", dir, names[k]);
    cable_bfile *b = cable_bfile_read(bp, &err);
    cable_sfile *s = cable_sfile_read(sp, &err);
    test_true("PVLS runs: b- and s-file read back", b && s);
    if (b && s) {
      cable_sfile_take_err_est(s, BP_ERR);
      check_pvls_rows(k == 0 ? "from STPNT" : "restart", b, 0, s);
    }
    cable_bfile_free(b);
    cable_sfile_free(s);
  }
  /* every start reports its Newton residual (d-file NOTE of point 1) */
  const char *dnames[2] = {"pvls", "pvls2"};
  const char *what[2] = {"start: Newton converged in", "restart: stored solution taken without Newton"};
  for (int k = 0; k < 2 && rc == 0; k++) {
    snprintf(path, sizeof path, "%s/d.%s", dir, dnames[k]);
    double res = start_residual(path, what[k]);
    char t[200];
    /* the engine's Newton stops at |dx| <= EPSL (1 + |x|) = 1e-7: one more
       quadratic step leaves round-off (measured 4e-14); a restart of a
       converged solution keeps its residual */
    snprintf(t, sizeof t, "d.%s point 1 notes '%s ... max |F| = r' with r <= 1e-9", dnames[k], what[k]);
    test_le(t, res, 1e-9);
  }
  if (rc == 0) {
    /* not printed: not computed (the slots keep the constants' 0) */
    snprintf(path, sizeof path, "%s/s.pvls3", dir);
    cable_sfile *s = cable_sfile_read(path, &err);
    const cable_solution *sol = s ? cable_sfile_get(s, cable_sfile_count(s) - 1) : NULL;
    test_true("run without the columns: s-file read", sol != NULL);
    if (sol) {
      test_true("run without Lk, Tw, Wr in ICP leaves them uncomputed (0)",
                sol->par[BP_LK] == 0.0 && sol->par[BP_TW] == 0.0 && sol->par[BP_WR] == 0.0);
      test_true("run without pmin, dmin in ICP leaves them uncomputed (0)",
                sol->par[BP_PMIN] == 0.0 && sol->par[BP_DMIN] == 0.0);
    }
    cable_sfile_free(s);
  }
  const char *files[] = {"c.pvls", "c.pvlsr", "b.pvls", "s.pvls", "d.pvls", "b.pvls2", "s.pvls2", "d.pvls2",
                         "b.pvls3", "s.pvls3", "d.pvls3", "pvls.csv", "pvls2.csv", "pvls3.csv"};
  for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
    snprintf(path, sizeof path, "%s/%s", dir, files[i]);
    remove(path);
  }
  rmdir(dir);
}

/* Remove the files a replay in dir wrote (names: without the prefix). */
static void remove_outputs(const char *dir, const char *const *names, size_t n)
{
  char path[256];
  const char *pre[] = {"b.", "s.", "d.", "c.", ""};
  for (size_t i = 0; i < n; i++)
    for (size_t k = 0; k < sizeof pre / sizeof pre[0]; k++) {
      snprintf(path, sizeof path, "%s/%s%s%s", dir, pre[k], names[i], k == 4 ? ".csv" : "");
      remove(path);
    }
  rmdir(dir);
}

static void test_branch_lk(void)
{
  char dir[] = "/tmp/cable_lkbranch_XXXXXX";
  if (!mkdtemp(dir)) {
    test_true("temporary directory", 0);
    return;
  }
  char path[256];
  /* runs/knot72's path on a coarser mesh (NTST 20, NCOL 6: 2 s), every point
     of the mode-1 branch labelled (NPR=1) */
  snprintf(path, sizeof path, "%s/c.br", dir);
  write_file(path, "e = 'braid_knot'\nNDIM = 21, IPS = 4\nICP = ['T', 'L', 'L2', 'eps21', 'F']\n"
                   "TORUS = 7, HAND = 1\nPAR = {'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0.0}\n"
                   "NTST = 20, NCOL = 6, IAD = 3, JAC = 1, ISP = 2, ILP = 0, NSV = 2\n"
                   "DS = 5.0, DSMIN = 1e-6, DSMAX = 20.0, NMX = 60, RL0 = -34.0, RL1 = 12.0\n"
                   "EPSL = 1e-7, EPSU = 1e-7, EPSS = 1e-7\n");
  snprintf(path, sizeof path, "%s/c.brsym", dir);
  write_file(path, "e = 'braid_knot_sym'\nNDIM = 21, IPS = 4\nICP = ['T', 'L', 'L2', 'eps21', 'eps13', 'F']\n"
                   "NTST = 20, NCOL = 6, IAD = 3, JAC = 1, ISW = -1, ISP = 0, ILP = 0\n"
                   "DS = 0.05, DSMIN = 1e-6, DSMAX = 2.0, NMX = 800, NPR = 1, RL0 = -30.0, RL1 = 40.0\n"
                   "EPSL = 1e-7, EPSU = 1e-7, EPSS = 1e-7\n");
  FILE *log;
  cable_session *r = session_open(dir, &log);
  cable_error err;
  memset(&err, 0, sizeof err);
  cable_branch *flat = NULL;
  int rc = r ? session_line(r, "e=braid_knot c=br sv=brflat", NULL, &flat, &err) : -1;
  if (!rc) rc = session_line(r, "e=braid_knot_sym c=brsym IRS='BP1' UZSTOP={'T': -2.10752} sv=brmode1", flat, NULL, &err);
  cable_branch_decref(flat);
  session_close(r, log);
  test_int("Lk branch: the runs succeed", rc, 0);
  snprintf(path, sizeof path, "%s/s.brmode1", dir);
  cable_sfile *s = rc == 0 ? cable_sfile_read(path, &err) : NULL;
  test_true("Lk branch: stored branch read back", s != NULL);
  int n = s ? cable_sfile_count(s) : 0, bad = 0, unresolved = 0, close = 0, n35 = 0, n55 = 0;
  double worst = 0.0, dmin = INFINITY;
  for (int i = 0; i < n; i++) {
    const cable_solution *sol = cable_sfile_get(s, i);
    braid_ribbon rb;
    if (braid_ribbon_compute(sol, 0, &rb) != 0 || rb.closure != -1) {
      bad++;
      continue;
    }
    if (!rb.resolved) {
      unresolved++;
      printf("  LAB %d: T = %.6g, Lk = %.10f unresolved: Wr error estimate %.3g\n", sol->lab, sol->par[BP_T],
             rb.lk, rb.wr_err);
      continue;
    }
    /* the writhe to BRAID_RIBBON_WR_TOL; the rest is the interpolant's
       (tangent kinks of O(h^NCOL) at the mesh points), measured <= 1e-7 */
    if (rb.lk_defect > 1e-6) {
      bad++;
      printf("  LAB %d: T = %.6g, Lk = %.10f is %.3g off a half-integer (Wr error estimate %.3g)\n", sol->lab,
             sol->par[BP_T], rb.lk, rb.lk_defect, rb.wr_err);
    }
    worst = fmax(worst, rb.lk_defect);
    dmin = fmin(dmin, rb.axis_dmin);
    close += rb.axis_dmin < 1.0;
    n35 += fabs(rb.lk - 3.5) < 1e-6;
    n55 += fabs(rb.lk - 5.5) < 1e-6;
  }
  printf("  %d labels: worst |Lk - half-integer| %.3g, %d unresolved, %d with the axis closer than Delta "
         "to itself (closest %.3g Delta)\n", n, worst, unresolved, close, dmin);
  test_true("Lk branch: more than 50 labelled solutions", n > 50);
  test_int("Lk branch: every label has Lk a half-integer to 1e-6 or is flagged unresolved", bad, 0);
  /* the branch must really test the hard case: non-adjacent parts of the
     axis closer than Delta, and both sides of the self-passage */
  test_true("Lk branch: labels with the axis closer than Delta to itself", close >= 1);
  test_true("Lk branch: Lk = 3.5 before and 5.5 after the self-passage", n35 > 0 && n55 > 0);
  cable_sfile_free(s);
  const char *names[] = {"br", "brsym", "brflat", "brmode1"};
  remove_outputs(dir, names, sizeof names / sizeof names[0]);
}

/* Columns of the braid frame (t1, d1, u1) from the Euler parameters (12.2.23). */
static void frame(const double *q, double t1[3], double d1[3], double u1[3])
{
  const double a = q[0], b = q[1], c = q[2], d = q[3];
  t1[0] = a * a + b * b - c * c - d * d;
  t1[1] = 2 * b * c + 2 * a * d;
  t1[2] = 2 * b * d - 2 * a * c;
  d1[0] = 2 * b * c - 2 * a * d;
  d1[1] = a * a - b * b + c * c - d * d;
  d1[2] = 2 * c * d + 2 * a * b;
  u1[0] = 2 * b * d + 2 * a * c;
  u1[1] = 2 * c * d - 2 * a * b;
  u1[2] = a * a - b * b - c * c + d * d;
}

static const char link_constants[] =
    "e = 'braid_link'\nNDIM = 21, IPS = 4\nICP = ['T', 'F']\nTORUS = 6, HAND = -1\n"
    "PAR = {'Delta': 0.016016913268, 'L': 1.0, 'T': 0.0}\n"
    "NTST = 60, NCOL = 4, IAD = 3, JAC = 1, ISP = 0, ILP = 0\n"
    "DS = -0.5, DSMIN = 1e-6, DSMAX = 2.0, NMX = 10, NPR = 5\n";

static const char knot_constants[] =
    "e = 'braid_knot'\nNDIM = 21, IPS = 4\nICP = ['T', 'L', 'L2', 'eps21', 'F']\nTORUS = 7, HAND = 1\n"
    "PAR = {'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0.0}\n"
    "NTST = 60, NCOL = 4, IAD = 3, JAC = 1, ISP = 0, ILP = 0\n"
    "DS = 1.0, DSMIN = 1e-6, DSMAX = 5.0, NMX = 3, NPR = 5\n";

/* Run the `cable run`-style lines (one per line of text) in dir, each
 * restarting from nothing; 0 or the error (err filled). */
static int replay_in(const char *dir, const char *lines, cable_error *err)
{
  FILE *log;
  cable_session *r = session_open(dir, &log);
  char buf[1024];
  int rc = r ? 0 : CABLE_ERR_ALLOC;
  memset(err, 0, sizeof *err);
  for (const char *p = lines; !rc && *p;) {
    const char *nl = strchr(p, '\n');
    size_t n = nl ? (size_t)(nl - p) : strlen(p);
    snprintf(buf, sizeof buf, "%.*s", (int)n, p);
    rc = session_line(r, buf, NULL, NULL, err);
    p += n + (nl != NULL);
  }
  session_close(r, log);
  return rc;
}

static void test_link_phi_and_starts(void)
{
  char dir[] = "/tmp/cable_phi_XXXXXX";
  if (!mkdtemp(dir)) {
    test_true("temporary directory", 0);
    return;
  }
  char path[256];
  snprintf(path, sizeof path, "%s/c.lk", dir);
  write_file(path, link_constants);
  snprintf(path, sizeof path, "%s/c.kn", dir);
  write_file(path, knot_constants);
  cable_error err;

  /* the flat left-handed (6,2) link (Phi = -6 pi) continued in Phi at T = 0 */
  int rc = replay_in(dir, "e=braid_link c=lk ICP=['Phi', 'F'] DS=0.2 NMX=8 NPR=2 sv=phi\n",
                     &err);
  test_int("link continued in Phi: the run succeeds", rc, 0);
  if (rc) printf("  %s\n", err.msg);
  snprintf(path, sizeof path, "%s/s.phi", dir);
  cable_sfile *s = rc == 0 ? cable_sfile_read(path, &err) : NULL;
  int n = s ? cable_sfile_count(s) : 0;
  double worst = 0.0, phi0 = NAN, phi1 = NAN, tmax = 0.0;
  for (int i = 0; i < n; i++) {
    const cable_solution *sol = cable_sfile_get(s, i);
    const double *u0 = sol->u, *u1 = sol->u + (size_t)(cable_solution_npts(sol) - 1) * BR_NDIM;
    double t0[3], d0[3], n0[3], t1[3], d1[3], n1[3], phi = sol->par[BP_PHI];
    frame(u0 + BR_Q0, t0, d0, n0);
    frame(u1 + BR_Q0, t1, d1, n1);
    for (int k = 0; k < 3; k++) {
      worst = fmax(worst, fabs(t1[k] - t0[k]));
      worst = fmax(worst, fabs(d1[k] - (cos(phi) * d0[k] + sin(phi) * n0[k])));
      worst = fmax(worst, fabs(u1[BR_X1 + k] - u0[BR_X1 + k]));
    }
    tmax = fmax(tmax, fabs(sol->par[BP_T]));
    if (i == 0) phi0 = phi;
    phi1 = phi;
  }
  printf("  Phi from %.6f to %.6f over %d labels; worst end-frame/closure defect %.3g\n", phi0, phi1, n, worst);
  test_true("link continued in Phi: labelled solutions stored", n >= 4);
  test_abs("link continued in Phi: starts at the flat link's Phi = -6 pi", phi0, -6.0 * M_PI, 1e-9);
  /* DS = 0.2 in the pseudo-arclength norm over 8 points; measured 0.27 */
  test_true("link continued in Phi: Phi moves by more than 0.1", phi1 - phi0 > 0.1);
  test_le("link continued in Phi: T stays fixed at 0", tmax, 1e-12);
  /* the conditions hold to Newton's accuracy; the s-file keeps 11 digits */
  test_le("link continued in Phi: t1(L) = t1(0), d1(L) = cos Phi d1(0) + sin Phi u1(0), r1(L) = r1(0)", worst, 1e-8);
  cable_sfile_free(s);

  /* the two rings are a degenerate start of braid_link: refused, naming TORUS */
  rc = replay_in(dir, "e=braid_link c=lk TORUS=0 sv=rings\n", &err);
  test_true("TORUS=0 for braid_link is refused", rc != 0);
  printf("  message: %s (key %s)\n", err.msg, err.key);
  /* the session reports the key in the message ("TORUS: ...") */
  test_true("... the error names the key TORUS", strcmp(err.key, "TORUS") == 0);
  test_true("... and says why (TORUS=0, the two rings)", strstr(err.msg, "TORUS=0") && strstr(err.msg, "rings"));
  snprintf(path, sizeof path, "%s/s.rings", dir);
  FILE *f = fopen(path, "r");
  test_true("... and writes no s-file", f == NULL);
  if (f) fclose(f);

  /* the (1,2) torus knot (an unknot with d1 turning by pi): the guess is 30 %
     off, so Newton needs more full steps than AUTO's defaults allow */
  rc = replay_in(dir, "e=braid_knot c=kn TORUS=1 ITNW=10 NWTN=10 sv=k12\n"
                      "e=braid_knot c=kn TORUS=1 HAND=-1 DS=-1.0 ITNW=10 NWTN=10 sv=k12l\n",
                 &err);
  test_int("(1,2) torus knot converges with ITNW = NWTN = 10", rc, 0);
  const char *kn[2] = {"k12", "k12l"};
  for (int k = 0; k < 2 && rc == 0; k++) {
    snprintf(path, sizeof path, "%s/s.%s", dir, kn[k]);
    s = cable_sfile_read(path, &err);
    int m = s ? cable_sfile_count(s) : 0, ok = m >= 2;
    for (int i = 0; i < m; i++) {
      braid_ribbon rb;
      ok = ok && braid_ribbon_compute(cable_sfile_get(s, i), 0, &rb) == 0 && rb.resolved &&
           fabs(rb.lk - (k ? -0.5 : 0.5)) <= 1e-6;
    }
    test_true(k ? "left-handed (1,2) knot: Lk = -0.5 at every label" : "right-handed (1,2) knot: Lk = 0.5 at every label",
              ok);
    cable_sfile_free(s);
  }
  const char *names[] = {"lk", "kn", "phi", "rings", "k12", "k12l"};
  remove_outputs(dir, names, sizeof names / sizeof names[0]);
}

int main(void)
{
  test_link_phi_and_starts();
  test_pvls_columns();
  test_branch_lk();

  const double delta = 0.0051364907419, ltot = 1.98889;
  const int knot_icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21};
  cable_solution *right = flat_at("braid_knot", 7, +1, delta, ltot, 2.0, knot_icp, 4, 40);
  cable_solution *left = flat_at("braid_knot", 7, -1, delta, ltot, -2.0, knot_icp, 4, 40);
  test_true("right-handed (7,2) knot reaches T = 2", right != NULL);
  test_true("left-handed (7,2) knot reaches T = -2", left != NULL);
  if (right && left) {
    /* the mirror image of a discrete solution solves the mirrored discrete
       problem on the same mesh: equal up to the Newton tolerance */
    test_rel("mirror symmetry: F(right, T) = F(left, -T)", left->par[BP_F], right->par[BP_F], 1e-8);
    test_rel("mirror symmetry: L", left->par[BP_L], right->par[BP_L], 1e-8);
    double lk, tw, wr;
    /* Lk is exactly half-integer for a closed knot ribbon; the interpolant's
       O(h^NCOL) geometry error and the quadrature bound the defect */
    if (braid_ribbon_lk(right, &lk, &tw, &wr) == 0) test_abs("right-handed (7,2): Lk = 3.5", lk, 3.5, 1e-6);
    else test_true("right-handed Lk computed", 0);
    if (braid_ribbon_lk(left, &lk, &tw, &wr) == 0) test_abs("left-handed (7,2): Lk = -3.5", lk, -3.5, 1e-6);
    else test_true("left-handed Lk computed", 0);
    /* eps21 must vanish on solutions of the original problem: only the
       Newton tolerance and round-off remain */
    test_le("eps21 vanishes on the knot", fabs(right->par[BP_EPS21]), 1e-9);
    /* first integrals are constant along s up to the discretisation error at
       the mesh points, O(h^(2 NCOL)) = O(h^8): halving h must shrink the drift
       by at least 2^6 (asymptotic rate 2^8, with slack for coarse meshes) */
    cable_solution *fine = flat_at("braid_knot", 7, +1, delta, ltot, 2.0, knot_icp, 4, 80);
    double d40 = cable_braid_first_integral_drift(right), d80 = fine ? cable_braid_first_integral_drift(fine) : 1.0;
    char what[128];
    snprintf(what, sizeof what, "first-integral drift converges like h^8: %.3g (NTST=40) -> %.3g (NTST=80)", d40, d80);
    test_true(what, d40 > 0 && d80 >= 0 && d80 * 64 <= d40);
    test_le("first-integral drift at NTST=40 (mesh points)", d40, 1e-7);
    cable_solution_free(fine);
  }
  cable_solution_free(right);
  cable_solution_free(left);

  const int link_icp[1] = {BP_T};
  cable_solution *link = flat_at("braid_link", 6, -1, 0.016016913268, 1.0, -1.0, link_icp, 1, 40);
  test_true("left-handed (6,2) link reaches T = -1", link != NULL);
  if (link) {
    double lk, tw, wr;
    if (braid_ribbon_lk(link, &lk, &tw, &wr) == 0) test_abs("left-handed (6,2) link: Lk = -3", lk, -3.0, 1e-6);
    else test_true("link Lk computed", 0);
    test_le("first-integral drift along the link at NTST=40 (mesh points)", cable_braid_first_integral_drift(link), 1e-7);
  }
  cable_solution_free(link);
  return test_summary();
}
