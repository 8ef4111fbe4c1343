/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO-format equation files (cable/cable_autoeq.h, auto_iface/autoeq/) run through e='NAME':
 * Fortran (free and fixed form) and C files written for these tests, for
 * problems with closed-form answers; the build cache; and bad files, which
 * must give a clear error and no output files.
 *
 * Closed forms (doc/auto-users.md): Bratu's u'' + lambda e^u = 0, u(0) =
 * u(1) = 0 has u(x) = 2 ln cosh s - 2 ln cosh(s(2x - 1)) with lambda =
 * 8 s^2 / cosh^2 s; the fold is where s tanh s = 1, and there u'(0) =
 * 4 s tanh s = 4, max u = 2 ln cosh s.  The straight elastica theta'' +
 * P sin theta = 0, theta'(0) = theta'(1) = 0 branches at P = (n pi)^2.
 * Tolerances: NTST=20, NCOL=4 collocation is accurate to about h^8 ~ 4e-11
 * in the mesh points' values (h = 1/20); the fold and branch points are
 * located by the engine's secant iteration to EPSS-type tolerances, so 1e-8
 * for their parameter values; the solution quantities at the fold move to
 * first order with the located arclength, hence 1e-6. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#include "cable/cable_aufile.h"
#include "cable/cable_autoeq.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "cable/cable_session.h"
#include "test_files.h"

#define DATA "tests/data/autoeq"
#define TMP "tests/tmp/autoeq"
#define PI 3.14159265358979323846

static int exists(const char *p)
{
  struct stat st;
  return stat(p, &st) == 0;
}

/* Copies DATA/folder/{files} into TMP/folder (removing old outputs). */
static void stage(const char *folder, const char *const *files)
{
  char from[512], to[512];
  snprintf(to, sizeof to, "%s/%s", TMP, folder);
  mkdir(TMP, 0755);
  mkdir(to, 0755);
  const char *outs[] = {"b.", "s.", "d."};
  for (const char *const *f = files; *f; f++) {
    snprintf(from, sizeof from, "%s/%s/%s", DATA, folder, *f);
    snprintf(to, sizeof to, "%s/%s/%s", TMP, folder, *f);
    if (!copy_file(from, to)) test_true(from, 0);
    for (int k = 0; k < 3; k++) {
      snprintf(to, sizeof to, "%s/%s/%s%s", TMP, folder, outs[k], *f);
      unlink(to);
    }
  }
}

/* What the scripts tests/data/autoeq/FOLDER/NAME.auto say (run(e=E, c=C)
 * and save as SV), on a session in TMP/folder; 0 or the error. */
static int replay_over(const char *folder, const char *e, const char *c, const char *sv, int nover,
                       const char *const *over, cable_error *err)
{
  char dir[512];
  snprintf(dir, sizeof dir, "%s/%s", TMP, folder);
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = dir;
  FILE *log = fopen(TMP "/log.txt", "a");
  o.log = log;
  cable_session *r = cable_session_alloc(&o);
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.e = e;
  a.c = c;
  a.sv = sv;
  a.nover = nover;
  a.over = over;
  cable_branch *b = NULL;
  cable_error_clear(err);
  int rc = r ? cable_session_run(r, &a, &b, err) : CABLE_ERR_ALLOC;
  cable_branch_decref(b);
  cable_session_free(r);
  if (log) fclose(log);
  return rc;
}

static int replay(const char *folder, const char *e, const char *c, const char *sv, cable_error *err)
{
  return replay_over(folder, e, c, sv, 0, NULL, err);
}

/* The b-file row of the k-th point of type ty (AUTO code), or -1. */
static int row_of(const cable_bfile_branch *br, int ty, int k)
{
  for (int i = 0; i < br->nrow; i++)
    if (br->ty[i] == ty && k-- == 0) return i;
  return -1;
}

static double col(const cable_bfile_branch *br, const char *name, int row)
{
  const double *c = cable_bfile_column(br, name);
  return c && row >= 0 ? c[row] : nan("");
}

/* s with s tanh s = 1 (Newton from 1.2, quadratic convergence). */
static double fold_s(void)
{
  double s = 1.2;
  for (int i = 0; i < 50; i++) s -= (s * tanh(s) - 1) / (tanh(s) + s / (cosh(s) * cosh(s)));
  return s;
}

/* integral over [0,1] of u^p for Bratu's solution with parameter s
 * (composite Simpson, 20000 panels: error ~ 1e-16 for this smooth u). */
static double bratu_integral(double s, int p)
{
  int n = 20000;
  double sum = 0;
  for (int i = 0; i <= n; i++) {
    double x = (double)i / n, u = 2 * log(cosh(s)) - 2 * log(cosh(s * (2 * x - 1)));
    double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += w * (p == 1 ? u : u * u);
  }
  return sum / (3.0 * n);
}

static void bratu_fold(const char *folder, const char *src)
{
  const char *files[] = {src, "c.bratu", "bratu.auto", NULL};
  stage(folder, files);
  cable_error err;
  cable_error_clear(&err);
  int rc = replay(folder, "bratu", "bratu", "bratu", &err);
  char buf[1200];
  test_report(rc == 0, "%s: e='bratu' runs (%s)", src, rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  char b[512];
  snprintf(b, sizeof b, "%s/%s/b.bratu", TMP, folder);
  cable_bfile *bf = cable_bfile_read(b, &err);
  if (!test_true("b.bratu was written", bf != NULL && bf->nbranch == 1)) {
    cable_bfile_free(bf);
    return;
  }
  const cable_bfile_branch *br = &bf->branch[0];
  double s = fold_s(), lam = 8 * s * s / (cosh(s) * cosh(s));
  int lp = row_of(br, 5, 0);
  char what[160];
  snprintf(what, sizeof what, "%s: Bratu's fold lambda* = 8 s^2/cosh^2 s, s tanh s = 1", src);
  test_rel(what, col(br, "PAR(1)", lp), lam, 1e-8);
  test_int("one LP", row_of(br, 5, 1) < 0 && lp >= 0, 1);
  /* the UZ labels: lambda = 1, 3 on the lower branch, then 3, 1 on the upper */
  test_int("four UZ (lambda = 1, 3, 3, 1)", row_of(br, -4, 3) >= 0 && row_of(br, -4, 4) < 0, 1);
  cable_bfile_free(bf);
}

static void elastica_bps(void)
{
  const char *files[] = {"elastica.f", "c.elastica", "elastica.auto", NULL};
  stage("elastica_f", files);
  cable_error err;
  int rc = replay("elastica_f", "elastica", "elastica", "elastica", &err);
  char buf[1200];
  test_report(rc == 0, "elastica.f (fixed form): runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  cable_bfile *bf = cable_bfile_read(TMP "/elastica_f/b.elastica", &err);
  if (!test_true("b.elastica was written", bf != NULL)) return;
  const cable_bfile_branch *br = &bf->branch[0];
  test_rel("elastica.f: first BP at P = pi^2", col(br, "PAR(1)", row_of(br, 6, 0)), PI * PI, 1e-8);
  test_rel("elastica.f: second BP at P = (2 pi)^2", col(br, "PAR(1)", row_of(br, 6, 1)), 4 * PI * PI, 1e-8);
  test_true("elastica.f: no third BP below RL1 = 42", row_of(br, 6, 2) < 0);
  cable_bfile_free(bf);
}

/* ICND and PVLS with GETP, Fortran or C. */
static void bratu_integral_getp(const char *folder, const char *src)
{
  const char *files[] = {src, "c.bratuint", "bratuint.auto", NULL};
  stage(folder, files);
  cable_error err;
  int rc = replay(folder, "bratuint", "bratuint", "bratuint", &err);
  char buf[1200], b[512], what[200];
  test_report(rc == 0, "%s: runs (%s)", src, rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  snprintf(b, sizeof b, "%s/%s/b.bratuint", TMP, folder);
  cable_bfile *bf = cable_bfile_read(b, &err);
  if (!test_true("b.bratuint was written", bf != NULL)) return;
  const cable_bfile_branch *br = &bf->branch[0];
  int lp = row_of(br, 5, 0);
  double s = fold_s(), lam = 8 * s * s / (cosh(s) * cosh(s));
  struct {
    const char *col, *what;
    double want, tol;
  } chk[] = {
    {"PAR(1)", "fold lambda* with NINT=1", lam, 1e-8},
    {"PAR(2)", "ICND: PAR(2) = integral of u at the fold", bratu_integral(s, 1), 1e-6},
    {"PAR(3)", "GETP('INT',1) = integral of u", bratu_integral(s, 1), 1e-6},
    {"PAR(4)", "GETP('MAX',1) = u(1/2) = 2 ln cosh s", 2 * log(cosh(s)), 1e-6},
    {"PAR(5)", "GETP('BV0',2) = u'(0) = 4", 4.0, 1e-6},
    {"PAR(6)", "GETP('NRM',1) = sqrt(integral of u^2)", sqrt(bratu_integral(s, 2)), 1e-6},
    {"PAR(7)", "GETP('BV1',2) = u'(1) = -4", -4.0, 1e-6},
    {"PAR(8)", "GETP('MIN',2) = u'(1) = -4", -4.0, 1e-6},
  };
  for (size_t k = 0; k < sizeof chk / sizeof chk[0]; k++) {
    snprintf(what, sizeof what, "%s: %s", src, chk[k].what);
    test_rel(what, col(br, chk[k].col, lp), chk[k].want, chk[k].tol);
  }
  /* GETP's integral and the integral condition agree at every point */
  double worst = 0;
  for (int i = 0; i < br->nrow; i++) worst = fmax(worst, fabs(col(br, "PAR(3)", i) - col(br, "PAR(2)", i)));
  snprintf(what, sizeof what, "%s: GETP('INT') equals the ICND value along the branch", src);
  test_le(what, worst, 1e-9);
  cable_bfile_free(bf);
  if (strstr(src, ".f90")) {
    /* GETP('STP') into PAR(9) (s-file only): the step that reached each
       labelled point, which the d-file's DS column prints to 6 digits */
    char sp[512], dp[512], line[512];
    snprintf(sp, sizeof sp, "%s/%s/s.bratuint", TMP, folder);
    snprintf(dp, sizeof dp, "%s/%s/d.bratuint", TMP, folder);
    cable_sfile *sf = cable_sfile_read(sp, &err);
    int nchk = 0, bad = 0;
    for (int i = 0; sf && i < cable_sfile_count(sf); i++) {
      const cable_solution *x = cable_sfile_get(sf, i);
      FILE *d = fopen(dp, "r");
      while (d && fgets(line, sizeof line, d)) {
        int ibr, pt, it;
        double par, l2, ds;
        if (sscanf(line, "%d %d %d %lf %lf %lf", &ibr, &pt, &it, &par, &l2, &ds) == 6 && pt == x->ntot) {
          nchk++;
          bad += fabs(x->par[8] - ds) > 5e-6 * fmax(fabs(ds), 1e-300) + 1e-300;
          break;
        }
      }
      if (d) fclose(d);
    }
    cable_sfile_free(sf);
    snprintf(what, sizeof what, "%s: GETP('STP') is the d-file's DS at every stored solution (%d checked)", src, nchk);
    test_true(what, nchk >= 3 && bad == 0);
  }
}

/* IPLT = NDIM + 1: the second column is the integral of U(1), and A1 bounds
 * it (AUTO's principal solution measure). */
static void iplt_integral(void)
{
  const char *files[] = {"bratu.f90", "c.bratu", "bratu.auto", NULL};
  stage("bratu_iplt", files);
  cable_error err;
  int rc = replay("bratu_iplt", "bratu", "bratu", "bratu", &err);
  test_true("IPLT=3: runs", rc == 0);
  cable_bfile *bf = cable_bfile_read(TMP "/bratu_iplt/b.bratu", &err);
  if (!test_true("IPLT=3: b.bratu was written", bf != NULL)) return;
  const cable_bfile_branch *br = &bf->branch[0];
  /* the lower solution at lambda = 1: 8 s^2 / cosh^2 s = 1 with s < 1.2 (bisection) */
  double lo = 0.0, hi = 1.2;
  for (int i = 0; i < 200; i++) {
    double m = 0.5 * (lo + hi);
    if (8 * m * m / (cosh(m) * cosh(m)) < 1) lo = m;
    else hi = m;
  }
  test_rel("IPLT=3: column INTEGRAL U(1) at the UZ lambda = 1 is the integral of u", col(br, "INTEGRAL U(1)", row_of(br, -4, 0)),
           bratu_integral(0.5 * (lo + hi), 1), 1e-6);
  int last = br->nrow - 1;
  test_true("IPLT=3, A1=0.5: the run ends (EP) once the integral passes 0.5, before the fold",
            last > 0 && br->ty[last] == 9 && col(br, "INTEGRAL U(1)", last) > 0.5 &&
                col(br, "INTEGRAL U(1)", last - 1) <= 0.5 && row_of(br, 5, 0) < 0);
  cable_bfile_free(bf);
}

/* Bratu's branch through s: lambda(s) = 8 s^2/cosh^2 s; the unit tangent in
 * the engine's norm (integral over [0,1] of u_s^2 + v_s^2, plus lambda_s^2,
 * THU = THL = 1) has the lambda component lambda_s / sqrt(that), which is
 * what GETP('FLD') returns (doc/auto-users.md).  With x' = 2x - 1:
 * u_s = 2 tanh s - 2 x' tanh(s x'), v = u' = -4 s tanh(s x'),
 * v_s = -4 tanh(s x') - 4 s x' / cosh^2(s x'),
 * lambda_s = 16 s (1 - s tanh s) / cosh^2 s.  Simpson, 20000 panels. */
static double bratu_fld(double s)
{
  int n = 20000;
  double sum = 0;
  for (int i = 0; i <= n; i++) {
    double x = 2.0 * i / n - 1, c = cosh(s * x);
    double us = 2 * tanh(s) - 2 * x * tanh(s * x), vs = -4 * tanh(s * x) - 4 * s * x / (c * c);
    double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += w * (us * us + vs * vs);
  }
  double ls = 16 * s * (1 - s * tanh(s)) / (cosh(s) * cosh(s));
  return ls / sqrt(sum / (3.0 * n) + ls * ls);
}

/* s on the lower (upper = 0) or upper branch with lambda(s) = lam (bisection). */
static double bratu_s(double lam, int upper)
{
  double sf = fold_s(), lo = upper ? sf : 0.0, hi = upper ? 10.0 : sf;
  for (int i = 0; i < 200; i++) {
    double m = 0.5 * (lo + hi), f = 8 * m * m / (cosh(m) * cosh(m)) - lam;
    if ((f < 0) == !upper) lo = m;
    else hi = m;
  }
  return 0.5 * (lo + hi);
}

/* GETP('FLD') and GETP('BIF') (fldbif/: equation files written for this
 * test, PVLS stores them in PAR(2) and PAR(3)). */
static void fold_bp_functions(void)
{
  const char *files[] = {"bratufb.f90", "elasfb.f90", "c.bratufb", "c.elasfb", "fldbif.auto", NULL};
  stage("fldbif", files);
  cable_error err;
  cable_error_clear(&err);
  /* what fldbif.auto says */
  static const char *const e0[] = {"ISP=0", "NMX=5"}, *const isp3[] = {"ISP=3"};
  int rc = replay("fldbif", "bratufb", "bratufb", "bratufb", &err);
  if (!rc) rc = replay_over("fldbif", "bratufb", "bratufb", "bratufb3", 1, isp3, &err);
  if (!rc) rc = replay("fldbif", "elasfb", "elasfb", "elasfb", &err);
  if (!rc) rc = replay_over("fldbif", "elasfb", "elasfb", "elasfb0", 2, e0, &err);
  char buf[1200];
  test_report(rc == 0, "fldbif.auto: runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  cable_bfile *bf = cable_bfile_read(TMP "/fldbif/b.bratufb", &err);
  if (test_true("b.bratufb was written", bf != NULL && bf->nbranch == 1)) {
    const cable_bfile_branch *br = &bf->branch[0];
    /* UZ at lambda = 1, 3 (lower), 3 (upper): the closed form; NTST=20 collocation
       is accurate far below 1e-7, the UZ located to ~1e-10 in lambda */
    const struct { int k, upper; double lam; } uz[] = {{0, 0, 1.0}, {1, 0, 3.0}, {2, 1, 3.0}};
    for (int i = 0; i < 3; i++) {
      char what[160];
      snprintf(what, sizeof what, "GETP('FLD') at the UZ lambda = %g (%s branch) = lambda_s/|(u_s, v_s, lambda_s)|",
               uz[i].lam, uz[i].upper ? "upper" : "lower");
      test_abs(what, col(br, "PAR(2)", row_of(br, -4, uz[i].k)), bratu_fld(bratu_s(uz[i].lam, uz[i].upper)), 1e-7);
    }
    /* at the located fold the test function vanishes to the location accuracy */
    test_abs("GETP('FLD') = 0 at the LP", col(br, "PAR(2)", row_of(br, 5, 0)), 0.0, 1e-8);
    int lp = row_of(br, 5, 0), signs_ok = lp > 1;
    for (int r = 1; r < br->nrow && lp > 1; r++)
      if (r != lp) signs_ok &= (r < lp) == (col(br, "PAR(2)", r) > 0);
    test_true("GETP('FLD') > 0 before the fold and < 0 after it, at every point", signs_ok);
    /* c.bratufb has ISP=1: no branch-point test for a BVP (AUTO's rule), so
       'BIF' is 0 at every point, as AUTO's is */
    double bmax = 0;
    for (int r = 0; r < br->nrow; r++) bmax = fmax(bmax, fabs(col(br, "PAR(3)", r)));
    test_abs("GETP('BIF') = 0 on Bratu's branch with ISP=1 (no BP test, as AUTO)", bmax, 0.0, 0.0);
  }
  cable_bfile_free(bf);
  bf = cable_bfile_read(TMP "/fldbif/b.bratufb3", &err);
  if (test_true("b.bratufb3 (ISP=3) was written", bf != NULL && bf->nbranch == 1)) {
    const cable_bfile_branch *br = &bf->branch[0];
    /* no BP on Bratu's branch: with the test on, the BP function keeps its sign and is nonzero */
    double b0 = col(br, "PAR(3)", 0);
    int same = b0 != 0;
    for (int r = 1; r < br->nrow; r++) same &= col(br, "PAR(3)", r) * b0 > 0;
    test_true("GETP('BIF') keeps its sign on Bratu's branch with ISP=3 (no BP)", same);
  }
  cable_bfile_free(bf);
  bf = cable_bfile_read(TMP "/fldbif/b.elasfb", &err);
  if (test_true("b.elasfb was written", bf != NULL && bf->nbranch == 1)) {
    const cable_bfile_branch *br = &bf->branch[0];
    /* the straight rod: the tangent is (0, 1) in (theta, P), so FLD = 1 exactly */
    double dmax = 0;
    for (int r = 0; r < br->nrow; r++) dmax = fmax(dmax, fabs(col(br, "PAR(2)", r) - 1.0));
    test_abs("GETP('FLD') = 1 at every point of the straight elastica", dmax, 0.0, 1e-12);
    /* BIF vanishes at each located BP and changes sign there, nowhere else */
    int bp[2] = {row_of(br, 6, 0), row_of(br, 6, 1)};
    double away = 0;
    int changes = 0, at_bp = 0;
    for (int r = 0; r < br->nrow; r++) {
      double b = col(br, "PAR(3)", r);
      if (r != bp[0] && r != bp[1]) away = away == 0 ? fabs(b) : fmin(away, fabs(b));
      int q = r + 1 + (r + 1 == bp[0] || r + 1 == bp[1]);
      if (q < br->nrow && r != bp[0] && r != bp[1] && col(br, "PAR(3)", q) * b < 0) changes++;
      at_bp += (r == bp[0] || r == bp[1]) && fabs(b) < 1e-9;
    }
    test_int("GETP('BIF') is below 1e-9 at both BPs", at_bp, 2);
    test_int("GETP('BIF') changes sign exactly at the two BPs", changes, 2);
    test_true("GETP('BIF') is not small away from the BPs (> 1e-4)", away > 1e-4);
  }
  cable_bfile_free(bf);
  bf = cable_bfile_read(TMP "/fldbif/b.elasfb0", &err);
  if (test_true("b.elasfb0 (ISP=0) was written", bf != NULL && bf->nbranch == 1)) {
    const cable_bfile_branch *br = &bf->branch[0];
    double m = 0;
    for (int r = 0; r < br->nrow; r++) m = fmax(m, fabs(col(br, "PAR(3)", r)));
    test_abs("GETP('BIF') = 0 when ISP=0 (no branch-point test, as in AUTO)", m, 0.0, 0.0);
  }
  cable_bfile_free(bf);
}

/* GETP's discretisation codes (getpmesh/: an equation file written for this
 * test; PVLS stores what GETP gives in PAR(2..10)). */
static void getp_mesh_codes(void)
{
  const char *files[] = {"bratumesh.f90", "c.bratumesh", "getpmesh.auto", NULL};
  stage("getpmesh", files);
  cable_error err;
  cable_error_clear(&err);
  int rc = replay("getpmesh", "bratumesh", "bratumesh", "bratumesh", &err);   /* what getpmesh.auto says */
  char buf[1200];
  test_report(rc == 0, "getpmesh.auto: runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  cable_bfile *bf = cable_bfile_read(TMP "/getpmesh/b.bratumesh", &err);
  if (test_true("b.bratumesh was written", bf != NULL && bf->nbranch == 1)) {
    const cable_bfile_branch *br = &bf->branch[0];
    int uz = row_of(br, -4, 0);
    test_abs("GETP('NDX') = NDIM = 2", col(br, "PAR(2)", uz), 2, 0);
    test_abs("GETP('NTST') = 20 (c.bratumesh)", col(br, "PAR(3)", uz), 20, 0);
    test_abs("GETP('NCOL') = 4", col(br, "PAR(4)", uz), 4, 0);
    test_abs("10 GETP('NBC') + GETP('NINT') = 20", col(br, "PAR(5)", uz), 20, 0);
    /* the mesh intervals cover [0,1]; the node weights integrate the linear
       function j = NCOL t exactly: sum_j WINT(j) j = NCOL / 2 */
    test_abs("sum over j of GETP('DTM', j) = 1", col(br, "PAR(6)", uz), 1.0, 1e-14);
    test_abs("sum over j of GETP('WINT', j) j = NCOL/2 = 2", col(br, "PAR(7)", uz), 2.0, 1e-13);
    /* u = 2 ln cosh s - 2 ln cosh(s(2t - 1)) is largest at t = 1/2 (a mesh
       point of the uniform mesh, IAD=0); u' = -4 s tanh(s(2t - 1)) is
       smallest at t = 1 */
    test_abs("GETP('MXT', 1) = 1/2 at the UZ lambda = 1", col(br, "PAR(8)", uz), 0.5, 1e-14);
    test_abs("GETP('MNT', 2) = 1 at the UZ lambda = 1", col(br, "PAR(9)", uz), 1.0, 0);
    double dmax = 0;
    for (int r = 0; r < br->nrow; r++) dmax = fmax(dmax, fabs(col(br, "PAR(10)", r)));
    test_abs("U(2, NCOL*NTST) read as AUTO lays U out equals GETP('BV1', 2), every point", dmax, 0, 0);
  }
  cable_bfile_free(bf);
}

/* dat='bratu.dat': AUTO's start data (t and U(1), U(2) per row) instead of
 * STPNT's u = 0: the exact upper solution at s = 2 (lambda = 32/cosh^2 2),
 * continued towards smaller lambda, gives the upper solution at lambda = 1,
 * which STPNT's start never reaches with DS < 0. */
static void dat_start(void)
{
  const char *files[] = {"bratu.f90", NULL};
  stage("bratu_f90", files);
  double s0 = 2.0, lam0 = 8 * s0 * s0 / (cosh(s0) * cosh(s0));
  FILE *f = fopen(TMP "/bratu_f90/bratu.dat", "w");
  for (int i = 0; f && i <= 200; i++) {
    double x = i / 200.0;
    /* t in the data's own units, [0, 2]: AUTO rescales it to [0, 1] */
    fprintf(f, "%.17g %.17g %.17g\n", 2 * x, 2 * log(cosh(s0)) - 2 * log(cosh(s0 * (2 * x - 1))),
            -4 * s0 * tanh(s0 * (2 * x - 1)));
  }
  if (f) fclose(f);
  f = fopen(TMP "/bratu_f90/c.bratudat", "w");
  if (f) {
    fprintf(f, "e='bratu', dat='bratu.dat'\nNDIM=2, IPS=4, IRS=0, ICP=[1], NBC=2, NINT=0, IPLT=3\n"
               "NTST=20, NCOL=4, NMX=60, DS=-0.01, DSMAX=0.5, RL0=0.5, RL1=4\nPAR={1: %.17g}\nUZR={1: 1.0}\n",
            lam0);
    fclose(f);
  }
  f = fopen(TMP "/bratu_f90/dat.auto", "w");
  if (f) {
    fputs("r = run(c='bratudat', sv='bratudat')\n", f);
    fclose(f);
  }
  cable_error err;
  char buf[1200];
  int rc = replay("bratu_f90", "bratu", "bratudat", "bratudat", &err);
  test_report(rc == 0, "dat=: runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  cable_bfile *bf = cable_bfile_read(TMP "/bratu_f90/b.bratudat", &err);
  if (!test_true("dat=: b.bratudat was written", bf != NULL)) return;
  const cable_bfile_branch *br = &bf->branch[0];
  double lo = 1.2, hi = 6.0;   /* the upper root of 8 s^2 / cosh^2 s = 1 */
  for (int i = 0; i < 200; i++) {
    double m = 0.5 * (lo + hi);
    if (8 * m * m / (cosh(m) * cosh(m)) > 1) lo = m;
    else hi = m;
  }
  test_rel("dat=: the start is the table's solution (integral of u at s = 2)", col(br, "INTEGRAL U(1)", 0),
           bratu_integral(s0, 1), 1e-6);
  test_rel("dat=: the UZ at lambda = 1 is the upper solution (its integral)", col(br, "INTEGRAL U(1)", row_of(br, -4, 0)),
           bratu_integral(0.5 * (lo + hi), 1), 1e-6);
  cable_bfile_free(bf);
}

static void cache(void)
{
  const char *files[] = {"bratu.f90", "c.bratu", "bratu.auto", NULL};
  stage("bratu_f90", files);
  cable_error err;
  cable_autoeq *m = cable_autoeq_open(TMP "/bratu_f90/bratu.f90", &err);
  test_true("open after the run: the module comes from the cache", m && !cable_autoeq_was_built(m));
  char so[1100];
  snprintf(so, sizeof so, "%s", m ? cable_autoeq_module(m) : "");
  cable_autoeq_close(m);
  FILE *f = fopen(TMP "/bratu_f90/bratu.f90", "a");
  if (f) {
    fputs("! a changed file is built again\n", f);
    fclose(f);
  }
  m = cable_autoeq_open(TMP "/bratu_f90/bratu.f90", &err);
  test_true("a changed file is rebuilt into another module",
            m && cable_autoeq_was_built(m) && strcmp(so, cable_autoeq_module(m)) != 0);
  cable_autoeq_close(m);
  char path[256];
  test_true("find: NAME.f90 before NAME.f and NAME.c", cable_autoeq_find(TMP "/bratu_f90", "bratu", path, sizeof path) == 0 &&
                                                         strstr(path, "bratu.f90") != NULL);
  test_int("find: no file, CABLE_ERR_NOTFOUND", cable_autoeq_find(TMP "/bratu_f90", "nothing", path, sizeof path),
           CABLE_ERR_NOTFOUND);
}

/* name: the run's e= and c= (e_name NULL: the same); src: the file the
 * error must name (the equation file or the constants file). */
static void bad_run(const char *name, const char *e_name, const char *src, int status, int line, const char *needle)
{
  char c[64];
  snprintf(c, sizeof c, "c.%s", name);
  const char *files[] = {src, c, NULL};
  stage("bad", strcmp(src, c) == 0 ? files + 1 : files);
  cable_error err;
  cable_error_clear(&err);
  int rc = replay("bad", e_name ? e_name : name, name, name, &err);
  char buf[1200];
  cable_error_format(&err, buf, sizeof buf);
  test_report(rc == status && strstr(buf, src) && strstr(buf, needle), "%s: refused: %s", src, buf);
  char want[64];
  snprintf(want, sizeof want, "%s:%d:", src, line);
  if (line > 0) test_report(strstr(buf, want) != NULL, "%s: the error names line %d of the file", src, line);
  const char *outs[] = {"b.", "s.", "d."};
  char sp[512];
  int none = 1;
  for (int k = 0; k < 3; k++) {
    snprintf(sp, sizeof sp, "%s/bad/%s%s", TMP, outs[k], name);
    none &= !exists(sp);
  }
  test_true("no b./s./d. file written", none);
}

/* A singularly perturbed problem: the steady viscous Burgers equation
 * eps u'' + u u' = 0, u(0) = -1, u(1) = 2, continued in eps from 0.05 to the
 * UZSTOP at 1e-5 (burgers_f90).  Exact solution u = b tanh(b (t - t0) /
 * (2 eps)) with b tanh(-b t0 / (2 eps)) = -1 and b tanh(b (1 - t0) / (2 eps))
 * = 2, so b = 2 up to exp(-2/eps) (below 1e-17 here) and u'(0) = (b^2 - 1) /
 * (2 eps) = 3 / (2 eps).  FUNC's 1/eps makes the residual of a converged point
 * large (3e-2 at eps = 1.5e-5 where 1e-6 (1 + max|x|) allowed 2e-2): the
 * corrector called such points stagnated and the run ended MX at eps =
 * 1.46e-5; now a point whose next Newton correction passes the step test too
 * is converged (colloc_newton.c), as AUTO's test on the corrections alone
 * says.  Tolerances: down to eps = 1e-4 the adapted NTST=40 mesh resolves the
 * layer (smallest interval 3.5e-5) and u'(0) agrees to 1.2e-8 (measured), so
 * 1e-6; at 1e-5 the smallest interval is 2.9e-5, about 3 eps (the monitor's
 * floor, doc/auto-users.md, spb), and u'(0) is 2.1e-4 off (measured), so 1e-3. */
static void burgers_layer(void)
{
  const char *files[] = {"burgers.f90", "c.burgers", "burgers.auto", NULL};
  stage("burgers_f90", files);
  cable_error err;
  int rc = replay("burgers_f90", "burgers", "burgers", "burgers", &err);
  char buf[1200];
  test_report(rc == 0, "burgers.f90: runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  cable_bfile *bf = cable_bfile_read(TMP "/burgers_f90/b.burgers", &err);
  cable_sfile *sf = cable_sfile_read(TMP "/burgers_f90/s.burgers", &err);
  if (test_true("b.burgers and s.burgers were written", bf != NULL && sf != NULL)) {
    const cable_bfile_branch *br = &bf->branch[bf->nbranch - 1];
    int last = br->nrow - 1;
    test_report(br->ty[last] == -4 && row_of(br, -4, 3) == last,
                "burgers: the run ends at its 4th UZ, the UZSTOP (last row: TY %d, eps = %.6g; before: MX at 1.46e-5)",
                br->ty[last], col(br, "PAR(1)", last));
    test_rel("burgers: the UZSTOP at eps = 1e-5", col(br, "PAR(1)", last), 1e-5, 1e-6);
    for (int k = 0; k < 4; k++) {
      const cable_solution *sol = cable_sfile_find_label(sf, k + 2);
      if (!test_true("burgers: the UZ is stored", sol != NULL)) continue;
      double eps = sol->par[0];
      char what[160];
      snprintf(what, sizeof what, "burgers: u'(0) = 3/(2 eps) at the UZ eps = %.3g", eps);
      test_rel(what, sol->u[1], 1.5 / eps, k < 3 ? 1e-6 : 1e-3);
    }
  }
  cable_bfile_free(bf);
  cable_sfile_free(sf);
}

/* What firstcall_f90/bratu1.auto says: two runs from STPNT in one session.
 * bratu1.f90's STPNT sets the scale PAR(2) = 1 on its first call only (a
 * COMMON flag, as AUTO's demos nag and fsh do); AUTO runs each computation in
 * a new process, so both runs find Bratu's fold at lambda* (the closed form,
 * located to 1e-8 as above).  Before the module was opened afresh for each
 * run, the second run kept the flag, started with PAR(2) = 0 and found no
 * fold (AUTO's nag: its second run did not converge at all). */
static void static_storage_per_run(void)
{
  const char *files[] = {"bratu1.f90", "c.bratu1", "bratu1.auto", NULL};
  stage("firstcall_f90", files);
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = TMP "/firstcall_f90";
  FILE *log = fopen(TMP "/log.txt", "a");
  o.log = log;
  cable_session *r = cable_session_alloc(&o);
  const char *sv[] = {"first", "second"};
  double lstar = 8 * fold_s() * fold_s() / (cosh(fold_s()) * cosh(fold_s()));
  for (int k = 0; k < 2 && r; k++) {
    cable_run_args a;
    memset(&a, 0, sizeof a);
    a.e = "bratu1";
    a.c = "bratu1";
    a.sv = sv[k];
    cable_branch *b = NULL;
    cable_error err;
    cable_error_clear(&err);
    char buf[1200];
    int rc = cable_session_run(r, &a, &b, &err);
    test_report(rc == 0, "bratu1.f90: run %d from STPNT (%s)", k + 1,
                rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
    cable_branch_decref(b);
    char path[512];
    snprintf(path, sizeof path, TMP "/firstcall_f90/b.%s", sv[k]);
    cable_bfile *bf = cable_bfile_read(path, &err);
    if (!test_true("bratu1.f90: the b-file was written", bf != NULL)) continue;
    const cable_bfile_branch *br = &bf->branch[0];
    char what[160];
    snprintf(what, sizeof what, "bratu1.f90: run %d (STPNT's first call again) has Bratu's fold", k + 1);
    test_rel(what, col(br, "PAR(1)", row_of(br, 5, 0)), lstar, 1e-8);
    cable_bfile_free(bf);
  }
  cable_session_free(r);
  if (log) fclose(log);
}


/* Declarations AUTO accepts (issue 26 item 1; autoeq_check.c): the rule is
 * "refuse only what AUTO itself cannot run, in the routines the run calls".
 *
 * complex_f90/elasz.f90 declares the state COMPLEX(KIND(1.0D0)) U(NDIM/2):
 * the elastica theta'' + P sin theta = 0, theta'(0) = theta'(1) = 0, with the
 * centre line z = x + i y, z' = exp(i theta), z(0) = 0.  Closed forms: the
 * straight rod branches at P = (n pi)^2; on the first buckled branch theta
 * goes from theta0 to -theta0 over half a period, so sqrt(P) = 2 K(k) with
 * k = sin(theta0/2), and the end of the rod is at x(1) = 2 E(k)/K(k) - 1,
 * y(1) = 0 (the classical elastica; K, E the complete elliptic integrals).
 * NTST=20, NCOL=4 collocation is accurate to about 1e-10 in these values
 * (h^8), so 1e-8.  implicit_f/bratuimp.f has implicitly typed FOPT, ICND and
 * PVLS stubs (REAL arguments); stpnt3_f/gelf.f the legacy STPNT(NDIM,U,PAR):
 * Bratu's problem on [-1, 1] folded at its centre, fold at lambda* / 4.  All
 * three were refused before ("argument 2 (u) is of another type", "has 3
 * arguments, AUTO passes 4"); test_auto07p compares them with auto-07p. */
static void auto_declarations(void)
{
  cable_error err;
  char buf[1200], what[200];
  const char *fz[] = {"elasz.f90", "c.elasz", "elasz.auto", NULL};
  stage("complex_f90", fz);
  int rc = replay("complex_f90", "elasz", "elasz", "elasz", &err);
  test_report(rc == 0, "elasz.f90 (COMPLEX(KIND(1.0D0)) state): runs (%s)",
              rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  {   /* elasz.auto's second run: the buckled branch from BP1 (label 3) */
    cable_session_options o;
    cable_session_options_init(&o);
    o.dir = TMP "/complex_f90";
    FILE *log = fopen(TMP "/log.txt", "a");
    o.log = log;
    cable_session *r = cable_session_alloc(&o);
    const char *over[] = {"IRS=3", "ISW=-1", "DS=0.05", "DSMAX=0.2", "NMX=80", "UZR={1: [10.0, 12.0]}",
                          "UZSTOP={1: 14.0}"};
    cable_run_args a;
    memset(&a, 0, sizeof a);
    a.e = "elasz";
    a.c = "elasz";
    a.s = "elasz";
    a.ap = "elasz";
    a.nover = (int)(sizeof over / sizeof over[0]);
    a.over = over;
    cable_branch *b = NULL;
    cable_error_clear(&err);
    rc = r ? cable_session_run(r, &a, &b, &err) : CABLE_ERR_ALLOC;
    test_report(rc == 0, "elasz.f90: the switch at BP1 runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
    cable_branch_decref(b);
    cable_session_free(r);
    if (log) fclose(log);
  }
  cable_bfile *bf = cable_bfile_read(TMP "/complex_f90/b.elasz", &err);
  cable_sfile *sf = cable_sfile_read(TMP "/complex_f90/s.elasz", &err);
  if (test_true("b.elasz and s.elasz were written", bf != NULL && sf != NULL)) {
    const cable_bfile_branch *br = &bf->branch[0];
    test_rel("elasz.f90: first BP at P = pi^2", col(br, "PAR(1)", row_of(br, 6, 0)), PI * PI, 1e-8);
    test_rel("elasz.f90: second BP at P = (2 pi)^2", col(br, "PAR(1)", row_of(br, 6, 1)), 4 * PI * PI, 1e-8);
    /* the straight rod: x(1) + i y(1) = 1 at the start */
    const cable_solution *s0 = cable_sfile_find_label(sf, 1);
    if (test_true("elasz: the start is stored", s0 != NULL)) {
      size_t last = (size_t)(cable_solution_npts(s0) - 1) * (size_t)s0->ndim;
      test_abs("elasz: straight rod, x(1) = 1", s0->u[last + 2], 1.0, 1e-10);
    }
    /* the buckled branch at its UZ P = 10 and 12 */
    for (int lab = 7; lab <= 8; lab++) {
      const cable_solution *s = cable_sfile_find_label(sf, lab);
      if (!test_true("elasz: a UZ of the buckled branch is stored", s != NULL)) continue;
      double P = s->par[0], theta0 = fabs(s->u[0]);
      double k = sin(theta0 / 2);
      gsl_mode_t mode = GSL_PREC_DOUBLE;
      double K = gsl_sf_ellint_Kcomp(k, mode), E = gsl_sf_ellint_Ecomp(k, mode);
      size_t last = (size_t)(cable_solution_npts(s) - 1) * (size_t)s->ndim;
      snprintf(what, sizeof what, "elasz: buckled at P = %.6g: sqrt(P) = 2 K(sin(theta0/2))", P);
      test_rel(what, 2 * K, sqrt(P), 1e-8);
      snprintf(what, sizeof what, "elasz: buckled at P = %.6g: x(1) = 2 E/K - 1 (through z' = exp(i theta))", P);
      test_rel(what, s->u[last + 2], 2 * E / K - 1, 1e-8);
      snprintf(what, sizeof what, "elasz: buckled at P = %.6g: y(1) = 0", P);
      test_abs(what, s->u[last + 3], 0.0, 1e-9);
    }
  }
  cable_bfile_free(bf);
  cable_sfile_free(sf);
  /* The trivial branch at small steps: u = 0 exactly, so the mesh monitor sees
   * only rounding noise.  Adapting to it moved the second branch point by 2e-6
   * (39.47849888) before cont_mesh.c's noise floor (CONT_MESH_NOISE). */
  const char *small[] = {"DS=0.1", "DSMAX=0.1", "NMX=500", "NPR=500"};
  rc = replay_over("complex_f90", "elasz", "elasz", "elasz_small", 4, small, &err);
  test_report(rc == 0, "elasz.f90 at DS = DSMAX = 0.1: runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  bf = cable_bfile_read(TMP "/complex_f90/b.elasz_small", &err);
  if (test_true("b.elasz_small was written", bf != NULL)) {
    const cable_bfile_branch *br = &bf->branch[0];
    test_rel("elasz.f90 at DS = 0.1: first BP at P = pi^2", col(br, "PAR(1)", row_of(br, 6, 0)), PI * PI, 1e-8);
    test_rel("elasz.f90 at DS = 0.1: second BP at P = (2 pi)^2", col(br, "PAR(1)", row_of(br, 6, 1)), 4 * PI * PI,
             1e-8);
  }
  cable_bfile_free(bf);

  const char *fi[] = {"bratuimp.f", "c.bratuimp", "bratuimp.auto", NULL};
  stage("implicit_f", fi);
  rc = replay("implicit_f", "bratuimp", "bratuimp", "bratuimp", &err);
  test_report(rc == 0, "bratuimp.f (implicitly typed FOPT, ICND, PVLS stubs): runs (%s)",
              rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  bf = cable_bfile_read(TMP "/implicit_f/b.bratuimp", &err);
  if (test_true("b.bratuimp was written", bf != NULL)) {
    const cable_bfile_branch *br = &bf->branch[0];
    double s = fold_s();
    test_rel("bratuimp.f: the fold at lambda* = 8 s^2/cosh^2 s", col(br, "PAR(1)", row_of(br, 5, 0)),
             8 * s * s / (cosh(s) * cosh(s)), 1e-8);
  }
  cable_bfile_free(bf);
  /* the same file with NINT=1: ICND is called now and never sets FI */
  const char *nint1[] = {"NINT=1", "ICP=[1, 2]"};
  rc = replay_over("implicit_f", "bratuimp", "bratuimp", "bratuimp_nint", 2, nint1, &err);
  cable_error_format(&err, buf, sizeof buf);
  test_report(rc == CABLE_ERR_PLUGIN && strstr(buf, "bratuimp.f:32:") && strstr(buf, "ICND: never sets fi (argument 9), but NINT=1"),
              "bratuimp.f with NINT=1: the ICND stub is called and refused: %s", buf);

  const char *fg[] = {"gelf.f", "c.gelf", "gelf.auto", NULL};
  stage("stpnt3_f", fg);
  rc = replay("stpnt3_f", "gelf", "gelf", "gelf", &err);
  test_report(rc == 0, "gelf.f (STPNT(NDIM,U,PAR)): runs (%s)", rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  bf = cable_bfile_read(TMP "/stpnt3_f/b.gelf", &err);
  if (test_true("b.gelf was written", bf != NULL)) {
    const cable_bfile_branch *br = &bf->branch[0];
    double s = fold_s();
    test_rel("gelf.f: the fold at lambda*/4", col(br, "PAR(1)", row_of(br, 5, 0)), 2 * s * s / (cosh(s) * cosh(s)), 1e-8);
  }
  cable_bfile_free(bf);

  /* a FUNC without DFDP: AUTO runs it with JAC=0 (it never reads DFDP), not
     with JAC=1 */
  const char *fw[] = {"wrongsig.f90", "c.wrongsig", NULL};
  stage("bad", fw);
  rc = replay("bad", "wrongsig", "wrongsig", "wrongsig", &err);
  test_report(rc == 0, "wrongsig.f90 (FUNC without DFDP) with JAC=0: runs (%s)",
              rc ? cable_error_format(&err, buf, sizeof buf) : "ok");
  unlink(TMP "/bad/b.wrongsig");
  unlink(TMP "/bad/s.wrongsig");
  unlink(TMP "/bad/d.wrongsig");
}

static void bad_file(const char *name, const char *src, int line, const char *needle)
{
  bad_run(name, NULL, src, CABLE_ERR_PLUGIN, line, needle);
}

int main(void)
{
  setenv("CABLE_CACHE_DIR", TMP "/cache", 1);
  mkdir("tests/tmp", 0755);
  mkdir(TMP, 0755);
  if (system("rm -rf " TMP "/cache") != 0) test_true("clear the cache", 0);
  bratu_fold("bratu_f90", "bratu.f90");
  bratu_fold("bratu_c", "bratu.c");
  elastica_bps();
  bratu_integral_getp("bratuint_f90", "bratuint.f90");
  bratu_integral_getp("bratuint_c", "bratuint.c");
  iplt_integral();
  fold_bp_functions();
  getp_mesh_codes();
  dat_start();
  burgers_layer();
  static_storage_per_run();
  cache();
  bad_file("syntax", "syntax.f90", 8, "array reference");
  bad_file("nofunc", "nofunc.f90", 0, "does not define SUBROUTINE FUNC");
  auto_declarations();
  bad_run("wrongsigjac", "wrongsig", "wrongsig.f90", CABLE_ERR_PLUGIN, 2,
          "FUNC: has 7 arguments, but the run takes DFDP (argument 8) from it (JAC=1)");
  bad_file("implicitfunc", "implicitfunc.f", 5, "FUNC: argument 2 (u) is REAL (single precision");
  bad_file("wrongsigc", "wrongsigc.c", 5, "conflicting types for");
  bad_file("toomany", "toomany.f90", 6, "has 9 arguments, AUTO passes 8, and uses argument 9 (extra)");
  test_true("a Fortran MODULE leaves no .mod file in the working or the run directory",
            !exists("bratu_consts.mod") && !exists(TMP "/bad/bratu_consts.mod"));
  bad_file("nopvls", "nopvls.c", 0, "pvls: the equation file does not define it");
  bad_file("getphbf", "getphbf.f90", 55, "GETP: 'HBF': cable does not provide it");
  /* constants as AUTO reads them */
  bad_run("nintbuiltin", "bratu", "c.nintbuiltin", CABLE_ERR_INPUT, 3,
          "NINT: NINT=1 contradicts problem 'bratu', which has NINT=0");
  bad_run("nondim", NULL, "nondim.f90", CABLE_ERR_INPUT, 0, "NDIM: equations from an AUTO file take NDIM from the constants");
  return test_summary();
}
