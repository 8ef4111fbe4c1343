/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Plug-in loader and the template plug-in.
 *
 * The Bratu template is checked against the closed-form solution family
 *   u(x) = -2 ln[ cosh((x - 1/2) th/2) / cosh(th/4) ],  lambda = th^2 / (2 cosh^2(th/4)),
 * (u'' = -(th^2/2) sech^2((x - 1/2) th/2) = -lambda e^u, u(0) = u(1) = 0), its
 * analytic Jacobians against central differences, and its FUNC against a
 * high-accuracy GSL integration of the initial-value problem from the exact
 * u'(0).  Every broken plug-in in tests/plugins must be rejected with its
 * reason, and so must a missing file. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cable/cable_cont.h"
#include "cable/cable_error.h"
#include "cable/cable_output.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"
#include "cable/cable_constants.h"
#include "harness.h"
#include "cable/cable_names.h"
#include "cable/cable_plugin.h"

/* Plug-ins live beside the tests of the same build: BUILD/tests/test_plugin
 * loads BUILD/plugins/NAME.so (build/release or build/asan). */
static char plugin_dir[512] = "build/release/plugins";

static void set_plugin_dir(const char *argv0)
{
  const char *t = strstr(argv0, "/tests/");
  if (t && t > argv0) snprintf(plugin_dir, sizeof plugin_dir, "%.*s/plugins", (int)(t - argv0), argv0);
}

static const char *plugin_path(const char *name, char *buf, size_t len)
{
  snprintf(buf, len, "%s/%s.so", plugin_dir, name);
  return buf;
}

/* ---- the closed-form Bratu solution ----------------------------------------------- */

static double bratu_lambda(double th) { return th * th / (2 * cosh(th / 4) * cosh(th / 4)); }
static double bratu_u(double th, double x) { return -2 * log(cosh((x - 0.5) * th / 2) / cosh(th / 4)); }
static double bratu_du(double th, double x) { return -th * tanh((x - 0.5) * th / 2); }
static double bratu_d2u(double th, double x)
{
  double c = cosh((x - 0.5) * th / 2);
  return -th * th / (2 * c * c);
}

/* Central differences: step cbrt(eps) * max(1, |x|) balances the truncation
 * error h^2/6 |f'''| against the rounding error eps |f| / h, both about
 * 1e-11 relative for this problem's smooth exponentials; the checks use
 * 1e-8 (relative to max(1, |value|)), a margin of 1000. */
#define FD_REL_STEP 6.0554544523933429e-06   /* cbrt(DBL_EPSILON) */
#define FD_TOL 1e-8

static void check_func(const cable_problem *pb, double th)
{
  int ndim = pb->ndim, icp[1] = {0};
  double par[CABLE_NPAR_DEFAULT] = {0};
  par[0] = bratu_lambda(th);
  char what[160];
  for (int k = 0; k <= 4; k++) {
    double x = k / 4.0;
    double u[2] = {bratu_u(th, x), bratu_du(th, x)};
    double f[2], dfdu[4], dfdp[2 * CABLE_NPAR_DEFAULT];
    int rc = pb->func(ndim, u, icp, par, 2, f, dfdu, dfdp, pb->params);
    snprintf(what, sizeof what, "th=%g x=%g FUNC status", th, x);
    test_int(what, rc, 0);
    /* f equals the exact derivative of the exact solution: a few ulps of exp/cosh */
    snprintf(what, sizeof what, "th=%g x=%g f1 = u'", th, x);
    test_abs(what, f[0], bratu_du(th, x), 4 * DBL_EPSILON * fmax(1, fabs(f[0])));
    snprintf(what, sizeof what, "th=%g x=%g f2 = u'' (closed form)", th, x);
    test_rel(what, f[1], bratu_d2u(th, x), 1e-13);
    /* Jacobians against central differences */
    for (int j = 0; j < ndim; j++) {
      double up[2] = {u[0], u[1]}, um[2] = {u[0], u[1]}, fp[2], fm[2];
      double h = FD_REL_STEP * fmax(1, fabs(u[j]));
      up[j] += h;
      um[j] -= h;
      pb->func(ndim, up, icp, par, 0, fp, NULL, NULL, pb->params);
      pb->func(ndim, um, icp, par, 0, fm, NULL, NULL, pb->params);
      for (int i = 0; i < ndim; i++) {
        double fd = (fp[i] - fm[i]) / (2 * h), an = dfdu[i + ndim * j];
        snprintf(what, sizeof what, "th=%g x=%g dfdu[%d,%d] vs differences", th, x, i, j);
        test_abs(what, an, fd, FD_TOL * fmax(1, fabs(an)));
      }
    }
    double pp[CABLE_NPAR_DEFAULT], pm[CABLE_NPAR_DEFAULT], fp[2], fm[2];
    memcpy(pp, par, sizeof pp);
    memcpy(pm, par, sizeof pm);
    double h = FD_REL_STEP * fmax(1, fabs(par[0]));
    pp[0] += h;
    pm[0] -= h;
    pb->func(ndim, u, icp, pp, 0, fp, NULL, NULL, pb->params);
    pb->func(ndim, u, icp, pm, 0, fm, NULL, NULL, pb->params);
    for (int i = 0; i < ndim; i++) {
      double fd = (fp[i] - fm[i]) / (2 * h), an = dfdp[i];
      snprintf(what, sizeof what, "th=%g x=%g dfdp[%d,lambda] vs differences", th, x, i);
      test_abs(what, an, fd, FD_TOL * fmax(1, fabs(an)));
    }
  }
}

static void check_bcnd(const cable_problem *pb, double th)
{
  int ndim = pb->ndim, nbc = pb->nbc, icp[1] = {0};
  double par[CABLE_NPAR_DEFAULT] = {0};
  par[0] = bratu_lambda(th);
  double u0[2] = {bratu_u(th, 0), bratu_du(th, 0)}, u1[2] = {bratu_u(th, 1), bratu_du(th, 1)};
  double fb[2], dbc[2 * (4 + CABLE_NPAR_DEFAULT)];
  char what[160];
  test_int("BCND status", pb->bcnd(ndim, par, icp, nbc, u0, u1, 2, fb, dbc, pb->params), 0);
  /* cosh is even, so u(0) and u(1) are exactly -2 ln(1) = 0 */
  snprintf(what, sizeof what, "th=%g fb1 = u(0) of the exact solution", th);
  test_abs(what, fb[0], 0, 0);
  snprintf(what, sizeof what, "th=%g fb2 = u(1) of the exact solution", th);
  test_abs(what, fb[1], 0, 0);
  /* the Jacobian: columns u(0), u(1), parameters; the BCs are linear, so the
   * differences are exact up to rounding */
  int ncols = 2 * ndim + pb->npar;
  for (int j = 0; j < ncols; j++) {
    double a0[2] = {u0[0], u0[1]}, a1[2] = {u1[0], u1[1]}, b0[2] = {u0[0], u0[1]}, b1[2] = {u1[0], u1[1]};
    double pp[CABLE_NPAR_DEFAULT], pm[CABLE_NPAR_DEFAULT], fp[2], fm[2];
    memcpy(pp, par, sizeof pp);
    memcpy(pm, par, sizeof pm);
    double h = FD_REL_STEP;
    if (j < ndim) a0[j] += h, b0[j] -= h;
    else if (j < 2 * ndim) a1[j - ndim] += h, b1[j - ndim] -= h;
    else pp[j - 2 * ndim] += h, pm[j - 2 * ndim] -= h;
    pb->bcnd(ndim, pp, icp, nbc, a0, a1, 0, fp, NULL, pb->params);
    pb->bcnd(ndim, pm, icp, nbc, b0, b1, 0, fm, NULL, pb->params);
    for (int i = 0; i < nbc; i++) {
      snprintf(what, sizeof what, "th=%g dbc[%d,%d] vs differences", th, i, j);
      test_abs(what, dbc[i + nbc * j], (fp[i] - fm[i]) / (2 * h), FD_TOL);
    }
  }
}

/* GSL integration of u' = FUNC(u) through the plug-in. */
typedef struct ivp_ctx {
  const cable_problem *pb;
  double par[CABLE_NPAR_DEFAULT];
} ivp_ctx;

static int ivp_rhs(double t, const double y[], double f[], void *params)
{
  (void)t;
  ivp_ctx *c = params;
  int icp[1] = {0};
  int rc = c->pb->func(c->pb->ndim, y, icp, c->par, 0, f, NULL, NULL, c->pb->params);
  return rc ? GSL_EBADFUNC : GSL_SUCCESS;
}

/* Local tolerance of the rk8pd integration (absolute and relative, so at
 * most 1e-12 (1 + |y|) < 4e-12 per step here).  Errors made along the way
 * grow at most like exp(int_0^1 sqrt(lambda e^u) dx) = exp(2 sqrt(2) gd(th/4))
 * (gd: the Gudermannian), which is 2.0 for th = 1 and 40 for th = 8; with
 * fewer than 60 steps (the driver's count is printed) the global error is
 * below 60 * 4e-12 * 40 < 1e-8, the tolerance used. */
#define IVP_EPS 1e-12
#define IVP_TOL 1e-8

static void check_shooting(const cable_problem *pb, double th)
{
  ivp_ctx c = {pb, {0}};
  c.par[0] = bratu_lambda(th);
  gsl_odeiv2_system sys = {ivp_rhs, NULL, (size_t)pb->ndim, &c};
  gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, IVP_EPS, IVP_EPS);
  double x = 0, y[2] = {0, bratu_du(th, 0)};
  char what[160];
  int rc = gsl_odeiv2_driver_apply(d, &x, 0.5, y);
  snprintf(what, sizeof what, "th=%g GSL integration to x=1/2", th);
  test_int(what, rc, GSL_SUCCESS);
  snprintf(what, sizeof what, "th=%g u(1/2) from FUNC vs closed form", th);
  test_abs(what, y[0], bratu_u(th, 0.5), IVP_TOL);
  snprintf(what, sizeof what, "th=%g u'(1/2) from FUNC (symmetry: 0)", th);
  test_abs(what, y[1], 0, IVP_TOL);
  rc = gsl_odeiv2_driver_apply(d, &x, 1.0, y);
  snprintf(what, sizeof what, "th=%g GSL steps (the tolerance assumes fewer than 60)", th);
  test_le(what, (double)d->n, 60);
  snprintf(what, sizeof what, "th=%g u(1) from FUNC meets the boundary condition", th);
  test_abs(what, y[0], 0, IVP_TOL);
  snprintf(what, sizeof what, "th=%g u'(1) from FUNC vs closed form", th);
  test_abs(what, y[1], bratu_du(th, 1), IVP_TOL);
  gsl_odeiv2_driver_free(d);
}

static void check_stpnt_pvls(const cable_problem *pb)
{
  double u[2] = {1, 1}, par[CABLE_NPAR_DEFAULT];
  for (int k = 0; k < CABLE_NPAR_DEFAULT; k++) par[k] = 7;
  test_int("STPNT status", pb->stpnt(pb->ndim, 0.3, u, par, pb->params), 0);
  test_abs("STPNT u1 = 0", u[0], 0, 0);
  test_abs("STPNT u2 = 0", u[1], 0, 0);
  test_abs("STPNT lambda = 0", par[0], 0, 0);
  /* PVLS on the exact solution stored at 4 x 4 collocation points: the
   * largest u1 is u(1/2) = 2 ln cosh(th/4), a stored point */
  double th = 3;
  cable_solution *s = cable_solution_alloc(2, 4, 4, CABLE_NPAR_DEFAULT, 1);
  test_true("solution alloc", s != NULL);
  if (!s) return;
  int npts = cable_solution_npts(s);
  for (int k = 0; k < npts; k++) {
    s->t[k] = (double)k / (npts - 1);
    s->u[2 * k] = bratu_u(th, s->t[k]);
    s->u[2 * k + 1] = bratu_du(th, s->t[k]);
  }
  test_int("PVLS status", pb->pvls(s, s->par, pb->params), 0);
  test_rel("PVLS umax = 2 ln cosh(th/4)", s->par[1], 2 * log(cosh(th / 4)), 4 * DBL_EPSILON);
  cable_solution_free(s);
  /* the recoverable-failure convention: exp overflow gives > 0 */
  double big[2] = {800, 0}, f[2];
  int icp[1] = {0};
  par[0] = 1;
  test_true("FUNC returns > 0 when e^u overflows",
            pb->func(pb->ndim, big, icp, par, 0, f, NULL, NULL, pb->params) > 0);
}

static void test_bratu(void)
{
  char path[600];
  cable_error err;
  const cable_problem *pb = NULL;
  cable_plugin *p = cable_plugin_open(plugin_path("bratu_plugin", path, sizeof path), &pb, &err);
  char buf[1200];
  if (!p) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_true("bratu_plugin.so loads", p != NULL && pb != NULL);
  if (!p) return;
  test_true("problem pointer via cable_plugin_problem", cable_plugin_problem(p) == pb);
  test_true("name", strcmp(pb->name, "bratu") == 0);
  test_int("ndim", pb->ndim, 2);
  test_int("nbc", pb->nbc, 2);
  test_int("nint", pb->nint, 0);
  test_int("npar", pb->npar, 2);
  test_true("parnames", strcmp(pb->parnames[0], "lambda") == 0 && strcmp(pb->parnames[1], "umax") == 0);
  test_true("analytic Jacobians declared", pb->func_has_jac == 1 && pb->bcnd_has_jac == 1);
  /* th = 1: lower branch (lambda = 0.4688); th = 8: upper branch, past the
   * fold at th = 4.7987 (lambda = 2.2609) */
  check_func(pb, 1.0);
  check_func(pb, 8.0);
  check_bcnd(pb, 1.0);
  check_bcnd(pb, 8.0);
  check_shooting(pb, 1.0);
  check_shooting(pb, 8.0);
  check_stpnt_pvls(pb);
  /* a second handle on the same file is independent */
  const cable_problem *pb2 = NULL;
  cable_plugin *p2 = cable_plugin_open(path, &pb2, &err);
  test_true("opening twice", p2 != NULL && pb2 == pb);
  cable_plugin_close(p2);
  cable_plugin_close(p);
  cable_plugin_close(NULL);
  /* the NPAR of the run bounds the problem's npar */
  p = cable_plugin_open_npar(path, 1, &pb, &err);
  test_true("npar 2 > NPAR 1 is rejected", p == NULL && pb == NULL);
  char want[800];
  snprintf(want, sizeof want, "%s: npar: must be between 0 and NPAR = 1, got 2", path);
  test_true("npar message", strcmp(cable_error_format(&err, buf, sizeof buf), want) == 0);
}

/* ---- rejections ---------------------------------------------------------------------- */

static void expect_reject(const char *name, int want_status, const char *want_tail)
{
  char path[600], buf[1200], want[1200], what[200];
  cable_error err;
  const cable_problem *pb = (const cable_problem *)&err;   /* must be reset to NULL */
  plugin_path(name, path, sizeof path);
  cable_plugin *p = cable_plugin_open(path, &pb, &err);
  snprintf(what, sizeof what, "%s is rejected", name);
  test_true(what, p == NULL && pb == NULL);
  cable_plugin_close(p);
  snprintf(what, sizeof what, "%s: status %s", name, cable_status_name(want_status));
  test_int(what, err.status, want_status);
  snprintf(want, sizeof want, "%s: %s", path, want_tail);
  cable_error_format(&err, buf, sizeof buf);
  int ok = strcmp(buf, want) == 0;
  if (!ok) printf("  got:  %s\n  want: %s\n", buf, want);
  snprintf(what, sizeof what, "%s: message names the file and the reason", name);
  test_true(what, ok);
}

/* An ABI 5 plug-in (no symmetries) still loads: the loader completes its
 * struct with nsym = 0 and never reads past its struct_size. */
static void test_abi5(void)
{
  char path[600];
  cable_error err;
  const cable_problem *pb = NULL;
  cable_plugin *p = cable_plugin_open(plugin_path("abi5_plugin", path, sizeof path), &pb, &err);
  char buf[1200];
  if (!p) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_true("an ABI 5 plug-in loads", p != NULL && pb != NULL);
  if (!p) return;
  test_int("ABI 5: completed to the current ABI", pb->abi_version, CABLE_PROBLEM_ABI);
  test_true("ABI 5: the struct size is the current one", pb->struct_size == sizeof(cable_problem));
  test_true("ABI 5: no symmetries (the garbage past its struct is not read)", pb->nsym == 0 && pb->symmetries == NULL);
  test_true("ABI 5: its own fields are kept", strcmp(pb->name, "abi5") == 0 && pb->ndim == 1 && pb->nbc == 1);
  cable_plugin_close(p);
}

static void test_broken(void)
{
  expect_reject("broken_noentry", CABLE_ERR_PLUGIN,
                "cable_problem_entry: the plug-in does not export it (define `const cable_problem "
                "*cable_problem_entry(void)` with external linkage)");
  expect_reject("broken_abi", CABLE_ERR_PLUGIN,
                "abi_version: built for ABI 99, this cable expects 6 (rebuild the plug-in against "
                "this cable's cable_problem.h)");
  char tail[400];
  snprintf(tail, sizeof tail,
           "struct_size: is %zu, this cable's cable_problem has %zu bytes (set it to "
           "sizeof(cable_problem) and rebuild against this cable's headers)",
           sizeof(cable_problem) - 8, sizeof(cable_problem));
  expect_reject("broken_size", CABLE_ERR_PLUGIN, tail);
  expect_reject("broken_nofunc", CABLE_ERR_PLUGIN, "func: is NULL (FUNC is required)");
  expect_reject("broken_nobcnd", CABLE_ERR_PLUGIN,
                "bcnd: is NULL but nbc = 2 (BCND is required when nbc > 0)");
  expect_reject("broken_null", CABLE_ERR_PLUGIN, "cable_problem_entry: returned NULL (no problem)");
  expect_reject("broken_names", CABLE_ERR_PLUGIN, "parnames[2]: the name 'T' is also parnames[0]");
  expect_reject("broken_npar", CABLE_ERR_PLUGIN, "npar: must be between 0 and NPAR = 36, got 40");
  expect_reject("broken_keys", CABLE_ERR_PLUGIN, "keys[0]: 'NTST' is one of cable's own constants keys");
  expect_reject("broken_prepare", CABLE_ERR_PLUGIN,
                "release: is NULL but prepare is set (an instance must be given back)");
  expect_reject("no_such_plugin", CABLE_ERR_IO, "cannot open the plug-in: No such file or directory");

  /* not a shared object: the dynamic loader's reason follows */
  cable_error err;
  char buf[1200];
  const cable_problem *pb;
  cable_plugin *p = cable_plugin_open("runs/knot72/knot72.auto", &pb, &err);
  test_true("a text file is rejected", p == NULL && pb == NULL);
  cable_error_format(&err, buf, sizeof buf);
  const char *head = "runs/knot72/knot72.auto: not a loadable shared object: ";
  if (strncmp(buf, head, strlen(head)) != 0) printf("  got: %s\n", buf);
  test_true("text file: message", strncmp(buf, head, strlen(head)) == 0 && err.status == CABLE_ERR_PLUGIN);
  p = cable_plugin_open("tests", &pb, &err);
  test_true("a directory is rejected", p == NULL);
  test_true("directory: message",
            strcmp(cable_error_format(&err, buf, sizeof buf), "tests: cannot open the plug-in: not a regular file") == 0);
  p = cable_plugin_open("", &pb, &err);
  test_true("an empty path is rejected", p == NULL && err.status == CABLE_ERR_IO);
  /* a bare file name means the current directory, not the library path:
   * libm.so.6 exists in the system path but not here */
  p = cable_plugin_open("libm.so.6", &pb, &err);
  test_true("a bare name is not searched in the library path", p == NULL && err.status == CABLE_ERR_IO);
}

/* The remaining checks on in-memory problems (the same function the loader uses). */
static int dummy_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                      double *f, double *dfdu, double *dfdp, void *params)
{
  (void)ndim, (void)u, (void)icp, (void)par, (void)ijac, (void)dfdu, (void)dfdp, (void)params;
  f[0] = 0;
  return 0;
}

static void expect_invalid(const char *what, const cable_problem *pb, const char *want)
{
  cable_error err;
  char buf[1200], d[200];
  int rc = cable_problem_validate(pb, CABLE_NPAR_DEFAULT, "built-in", &err);
  snprintf(d, sizeof d, "validate %s: status", what);
  test_int(d, rc, CABLE_ERR_PLUGIN);
  cable_error_format(&err, buf, sizeof buf);
  int ok = strcmp(buf, want) == 0;
  if (!ok) printf("  got:  %s\n  want: %s\n", buf, want);
  snprintf(d, sizeof d, "validate %s: message", what);
  test_true(d, ok);
}

static void test_validate(void)
{
  static const char *const good_names[] = {"T", NULL, "L2"};
  static const char *const blank_names[] = {"T", "two words", "L"};
  static const char *const numeric_names[] = {"1st"};
  static const char *const dup_unames[] = {"x", "x"};
  cable_problem ok = {.abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "ok",
                      .ndim = 2, .nbc = 0, .nint = 0, .npar = 3, .parnames = good_names, .func = dummy_func};
  cable_error err;
  test_int("a valid problem with an unnamed parameter", cable_problem_validate(&ok, 36, "built-in", &err), 0);
  cable_problem b = ok;
  b.ndim = 0;
  expect_invalid("ndim", &b, "built-in: ndim: must be positive, got 0");
  b = ok;
  b.nbc = -1;
  expect_invalid("nbc", &b, "built-in: nbc: must not be negative, got -1");
  b = ok;
  b.nint = -2;
  expect_invalid("nint", &b, "built-in: nint: must not be negative, got -2");
  b = ok;
  b.nint = 1;
  expect_invalid("icnd", &b, "built-in: icnd: is NULL but nint = 1 (ICND is required when nint > 0)");
  b = ok;
  b.npar = -1;
  b.parnames = NULL;
  expect_invalid("negative npar", &b, "built-in: npar: must be between 0 and NPAR = 36, got -1");
  b = ok;
  b.func_has_jac = 2;
  expect_invalid("has_jac flag", &b, "built-in: func_has_jac: must be 0 or 1, got 2");
  b = ok;
  b.npar = 0;
  expect_invalid("names without npar", &b, "built-in: parnames: names are given but npar is 0");
  b = ok;
  b.parnames = blank_names;
  expect_invalid("blank in a name", &b,
                 "built-in: parnames[1]: the name 'two words' contains a blank or one of '\"=,()[]{}#:;\\");
  b = ok;
  b.npar = 1;
  b.parnames = numeric_names;
  expect_invalid("numeric name", &b, "built-in: parnames[0]: the name '1st' starts like a number");
  b = ok;
  b.unames = dup_unames;
  expect_invalid("duplicate unames", &b, "built-in: unames[1]: the name 'x' is also unames[0]");
  b = ok;
  b.name = NULL;
  expect_invalid("no name", &b, "built-in: name: the problem needs a name usable as e=NAME (it is NULL)");
  b = ok;
  b.name = "my problem";
  expect_invalid("bad name", &b,
                 "built-in: name: the problem needs a name usable as e=NAME (contains a blank or one of "
                 "'\"=,()[]{}#:;\\)");
  expect_invalid("NULL problem", NULL, "built-in: cable_problem_entry: returned NULL (no problem)");
}

/* ---- the documented one-line build ------------------------------------------------------ */

/* Bratu's fold (30-digit mpmath value). */
#define BRATU_FOLD_LAMBDA 3.5138307191251612062
/* With NTST=20, NCOL=4, EPSS=1e-7 tests/test_engine_bvp.c bounds the fold's
 * lambda by 1e-9 (discretisation O(h^8) ~ 1e-11, location to EPSS). */
#define BRATU_FOLD_TOL 1e-9

typedef struct {
  double fold;
  int nlp;
} fold_sink;

static int fold_point(void *ctx, const cable_point *pt)
{
  fold_sink *f = ctx;
  if (cable_type_base(pt->itp) == 5 && f->nlp++ == 0) f->fold = pt->par[pt->icp[0]];
  return 0;
}

static int fold_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  (void)ctx, (void)pt, (void)sol;
  return 0;
}

static void fold_diag(void *ctx, const char *line)
{
  (void)ctx, (void)line;
}

/* doc/plugins.md's build command, copied from the page and run as it stands
 * (in a scratch directory that mirrors the source tree's public headers,
 * include/, and tests/plugins), then the plug-in it builds run by the
 * engine to Bratu's fold. */
static void test_documented_build(void)
{
  FILE *f = fopen("doc/plugins.md", "r");
  char line[1024], cmd[1024] = "";
  while (f && fgets(line, sizeof line, f)) {
    const char *t = line + strspn(line, " ");
    if (strncmp(t, "cc -shared", 10) == 0 && !cmd[0]) snprintf(cmd, sizeof cmd, "%s", t);
  }
  if (f) fclose(f);
  cmd[strcspn(cmd, "\n")] = '\0';
  test_true("doc/plugins.md has a one-line 'cc -shared ...' build command", cmd[0] != '\0');
  printf("  command: %s\n", cmd);
  char cwd[PATH_MAX], dir[PATH_MAX + 64], sh[10 * PATH_MAX];
  if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
  snprintf(dir, sizeof dir, "%s/tests/tmp/plugbuild.%ld", cwd, (long)getpid());
  snprintf(sh, sizeof sh,
           "rm -rf '%s' && mkdir -p '%s/tests' && ln -s '%s/include' '%s/include' && "
           "ln -s '%s/tests/plugins' '%s/tests/plugins'",
           dir, dir, cwd, dir, cwd, dir);
  int rc = system(sh);
  test_int("scratch tree for the build", rc, 0);
  snprintf(sh, sizeof sh, "cd '%s' && %s", dir, cmd);
  rc = system(sh);
  test_int("the documented command builds bratu.so (exit status)", rc, 0);
  char so[PATH_MAX + 80];
  snprintf(so, sizeof so, "%s/bratu.so", dir);
  cable_error err;
  const cable_problem *pb = NULL;
  cable_plugin *p = cable_plugin_open(so, &pb, &err);
  char buf[1200];
  if (!p) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_true("the built bratu.so loads", p && pb);
  cable_constants c;
  cable_names names;
  int st = p ? cable_constants_parse_string("c.bratu",
                                            "IPS = 4, ICP = ['lambda'], NTST = 20, NCOL = 4, JAC = 1, IAD = 3\n"
                                            "DS = 0.1, DSMIN = 1e-6, DSMAX = 0.5, NMX = 60, RL1 = 10\n"
                                            "ILP = 1, ISP = 0, EPSS = 1e-7\n",
                                            &c, &names, pb->parnames, pb->npar, &err)
             : -1;
  fold_sink fs = {NAN, 0};
  if (st == 0) {
    cable_constants_take_problem_dims(&c, pb->ndim, pb->nbc, pb->nint);
    cable_cont *cc = cable_cont_alloc(pb, &c, &st);
    if (st == 0) st = cable_cont_set_start(cc, NULL);
    cable_sink sink = {&fs, fold_point, fold_solution, fold_diag};
    int next = 0;
    if (st == 0) st = cable_cont_run(cc, &sink, 1, 1, &next) > 0 ? 0 : -1;
    cable_cont_free(cc);
  }
  test_int("the engine runs the built plug-in to the end", st, 0);
  test_int("  one fold on the way", fs.nlp, 1);
  test_abs("  fold lambda vs the closed form", fs.fold, BRATU_FOLD_LAMBDA, BRATU_FOLD_TOL);
  cable_plugin_close(p);
  snprintf(sh, sizeof sh, "rm -rf '%s'", dir);
  (void)!system(sh);
}

int main(int argc, char **argv)
{
  (void)argc;
  gsl_set_error_handler_off();
  set_plugin_dir(argv[0]);
  test_bratu();
  test_broken();
  test_abi5();
  test_validate();
  test_documented_build();
  return test_summary();
}
