/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The plug-in tests/plugins/link_t2plus.c (the reading "t20 = +t10" of the
 * link conditions, doc/links.md §4.2): it loads and validates, every row but
 * (12.3.34) is braid_link's, that row is T2(0) - T, and its Jacobian
 * (states and parameters) agrees with central differences. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "braid_bc.h"
#include "cable/cable_error.h"
#include "braid_random.h"
#include "harness.h"
#include "cable/cable_plugin.h"

/* rows are the same operations on the same numbers: exact */
static const double same_tol = 0.0;
/* central differences, h = 1e-6 max(1, |x|): the rows are at most quadratic
 * in the trigonometric terms; truncation ~1e-13, rounding ~1e-10 (as
 * test_braid_link_sym) */
static const double fd_rel = 1e-6, fd_tol = 1e-8;
enum { NCOLS = 2 * BR_NDIM + BP_NPAR, NSAMPLES = 10 };

/* the tests' random numbers (tests/braid_random.h) */
static test_rng rng = {0x853C49E6748FEA9Bu};

int main(int argc, char **argv)
{
  (void)argc;
  char path[600] = "build/release/plugins/link_t2plus.so";
  const char *t = strstr(argv[0], "/tests/");
  if (t && t > argv[0]) snprintf(path, sizeof path, "%.*s/plugins/link_t2plus.so", (int)(t - argv[0]), argv[0]);
  const cable_problem *pb = NULL;
  cable_error err;
  cable_plugin *pl = cable_plugin_open(path, &pb, &err);
  if (pl == NULL) {
    char buf[1024];
    printf("# %s\n", cable_error_format(&err, buf, sizeof buf));
  }
  if (!test_true("link_t2plus: the plug-in loads and validates", pl != NULL && pb != NULL))
    return test_summary();
  test_true("link_t2plus: name, NDIM 21, NBC 21", strcmp(pb->name, "link_t2plus") == 0 &&
            pb->ndim == BR_NDIM && pb->nbc == BL_NBC);
  /* the plug-in's layout constants are braid_link's (the rows below check
     ROW_T20, U_T2 and PAR_T) */
  const cable_problem *bl = cable_problem_builtin("braid_link");
  test_true("link_t2plus: NPAR and the parameter names are braid_link's",
            bl != NULL && pb->npar == bl->npar && pb->npar == BP_NPAR &&
            strcmp(pb->parnames[BP_T], "T") == 0 && strcmp(pb->parnames[BP_NPAR - 1], bl->parnames[BP_NPAR - 1]) == 0);

  static double dbc[BL_NBC * NCOLS];
  double worst_same = 0.0, worst_fd = 0.0, worst_row = 0.0;
  int st = 0;
  for (int n = 0; n < NSAMPLES; n++) {
    double u0[BR_NDIM], u1[BR_NDIM], par[BP_NPAR], fb[BL_NBC], fl[BL_NBC], fp[BL_NBC], fm[BL_NBC];
    for (int i = 0; i < BR_NDIM; i++) { u0[i] = test_rng_uniform(&rng, -2, 2); u1[i] = test_rng_uniform(&rng, -2, 2); }
    for (int k = 0; k < BP_NPAR; k++) par[k] = test_rng_uniform(&rng, 0.5, 2.0);
    par[BP_T] = test_rng_uniform(&rng, -20, 20);
    par[BP_PHI] = test_rng_uniform(&rng, -20, 20);
    st |= pb->bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 2, fb, dbc, pb->params);
    st |= braid_link_bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fl, NULL, NULL);
    for (int i = 0; i < BL_NBC; i++)
      if (i != BL_T20) worst_same = fmax(worst_same, fabs(fb[i] - fl[i]));
    worst_row = fmax(worst_row, fabs(fb[BL_T20] - (u0[BR_T2] - par[BP_T])));
    for (int j = 0; j < NCOLS; j++) {
      double *x = j < BR_NDIM ? &u0[j] : j < 2 * BR_NDIM ? &u1[j - BR_NDIM] : &par[j - 2 * BR_NDIM];
      const double x0 = *x, h = fd_rel * fmax(1.0, fabs(x0));
      *x = x0 + h;
      st |= pb->bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fp, NULL, pb->params);
      *x = x0 - h;
      st |= pb->bcnd(BR_NDIM, par, NULL, BL_NBC, u0, u1, 0, fm, NULL, pb->params);
      *x = x0;
      for (int i = 0; i < BL_NBC; i++) {
        const double an = dbc[i + BL_NBC * j];
        worst_fd = fmax(worst_fd, fabs((fp[i] - fm[i]) / (2 * h) - an) / fmax(1.0, fabs(an)));
      }
    }
  }
  test_int("link_t2plus: status 0", st, 0);
  test_le("link_t2plus: the 20 other rows are braid_link's (max abs diff)", worst_same, same_tol);
  test_le("link_t2plus: row (12.3.34) is T2(0) - T", worst_row, 0.0);
  test_le("link_t2plus: Jacobian (states, parameters) vs central differences", worst_fd, fd_tol);
  cable_plugin_close(pl);
  return test_summary();
}
