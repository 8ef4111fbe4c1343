/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Benchmark (not a test; build/<mode>/tests/bench_factor_solve): one
 * structured factorisation of the flat (7,2) knot's Newton matrix at NTST 150,
 * NCOL 4 and the solve that follows it, plain (abd_solver_factor, then
 * abd_solver_solve_many) against prepared (abd_solver_factor_prepared with the
 * same right-hand sides), for 1 and 2 threads and 1 and 2 right-hand sides.
 * The two alternate inside every repeat; medians of R repeats.  The matrix is
 * assembled before every factorisation, as in a Newton step. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench_util.h"
#include "bench_knot72.h"
#include "abd_solver.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "colloc_jac.h"
#include "colloc_system.h"
#include "cable/cable_constants.h"
#include "cable/cable_names.h"
#include "cable/cable_cont.h"
#define R 61 /* repeats per median */
int main(void)
{
  braid_start_params sp;
  cable_problem pb;
  if (bench_knot72(&sp, &pb) != 0) return 1;
  cable_blas_single_thread();
  int ntst = 150;
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.ntst = ntst; c.ncol = 4; c.jac = 1;
  int icp[4] = {BP_T, BP_L, BP_L2, BP_EPS21}, st;
  colloc_system *s = colloc_system_alloc(&pb, &c, ntst, 4, icp, 4, &st);
  colloc_jac *J = colloc_jac_alloc(21, ntst, 4, 4, pb.nbc, 0);
  abd_solver *a = abd_solver_alloc(21, ntst, 4, 4, pb.nbc, 0);
  double *x = calloc((size_t)s->n, sizeof *x), *t = calloc((size_t)(ntst * 4 + 1), sizeof *t);
  double *F = calloc((size_t)s->n, sizeof *F), *B = calloc((size_t)s->n * 2, sizeof *B), *X = calloc((size_t)s->n * 2, sizeof *X);
  colloc_system_times(s, t);
  for (int k = 0; k <= ntst * 4; k++) pb.stpnt(21, t[k], x + (size_t)k * 21, s->par, pb.params);
  for (int q = 0; q < 4; q++) x[s->n - 4 + q] = s->par[icp[q]];
  s->closing = COLLOC_CLOSE_FIXPAR;
  colloc_system_jacobian(s, x, J);
  colloc_system_residual(s, x, F);
  for (int nt = 1; nt <= 2; nt++) {
    abd_solver_set_threads(a, nt);
    for (int k = 1; k <= 2; k++) {
      double tf[2][R], ts[2][R];
      memcpy(B, F, sizeof(double) * (size_t)s->n);
      memset(B + s->n, 0, sizeof(double) * (size_t)s->n);
      B[2 * s->n - 1] = 1.0;
      for (int r = 0; r < R; r++)
        for (int mode = 0; mode < 2; mode++) {
          colloc_system_jacobian(s, x, J);
          double t0 = bench_now();
          if (mode) abd_solver_factor_prepared(a, J, B, k);
          else abd_solver_factor(a, J);
          double t1 = bench_now();
          memcpy(X, B, sizeof(double) * (size_t)s->n * (size_t)k);
          abd_solver_solve_many(a, X, k);
          double t2 = bench_now();
          tf[mode][r] = t1 - t0;
          ts[mode][r] = t2 - t1;
        }
      printf("threads %d k %d: plain factor %.6f solve %.6f sum %.6f | prepared factor %.6f solve %.6f sum %.6f\n", nt, k,
             bench_median(tf[0], R), bench_median(ts[0], R), bench_median(tf[0], R) + bench_median(ts[0], R),
             bench_median(tf[1], R), bench_median(ts[1], R), bench_median(tf[1], R) + bench_median(ts[1], R));
    }
  }
  free(x);
  free(t);
  free(F);
  free(B);
  free(X);
  abd_solver_free(a);
  colloc_jac_free(J);
  colloc_system_free(s);
  return 0;
}
