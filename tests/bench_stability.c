/* SPDX-License-Identifier: GPL-3.0-or-later */
/* What STAB=1 costs (doc/stability.md S2, S6): the time per continuation step
 * of the Euler column's trivial branch (elastica_int, ISP = 2) with STAB = 0
 * and 1, and the time of one index computation against the basis size N.
 * Medians of `reps` repetitions (argv[1], default 5).  Not a test: it prints
 * numbers only. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "braid_problems.h"
#include "braid_second_variation.h"
#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_stability.h"
#include "engine_util.h"
#include "test_problems.h"

static int count_point(void *ctx, const cable_point *pt)
{
  (void)pt;
  (*(int *)ctx)++;
  return 0;
}

/* seconds per step of a run of nmx steps at NTST, NCOL */
static double run_time(int stab, int ntst, int ncol, int nmx, int *npts)
{
  cable_constants c;
  engine_constants(&c, ntst, ncol);
  c.icp[1] = 1; c.nicp = 2;
  c.ds = 0.25; c.dsmin = 1e-6; c.dsmax = 0.25; c.iads = 0; c.nmx = nmx;
  c.isp = 2; c.ilp = 0; c.nthreads = 1;
  c.stab = stab;
  int st, n = 0;
  cable_cont *cc = cable_cont_alloc(cable_testproblem_elastica_int(), &c, &st);
  if (!cc) return -1;
  double t0 = bench_now();
  cable_cont_set_start(cc, NULL);
  cable_sink sink = {&n, count_point, NULL, NULL};
  cable_cont_run(cc, &sink, 1, 1, NULL);
  double t = bench_now() - t0;
  cable_cont_free(cc);
  *npts = n;
  return t / n;
}

/* seconds per step of the flat (7,2) knot (runs/knot72/c.knot72 at NTST 20,
   NCOL 7, nmx steps from T = 0), STAB = 0 or 1; -1 when it cannot run */
static double knot_time(int stab, int nmx, int *npts)
{
  const cable_problem *tpl = braid_problem_find("braid_knot"), *pb = NULL;
  cable_constants c;
  cable_error e;
  char o[3][32];
  snprintf(o[0], sizeof o[0], "NTST=20");
  snprintf(o[1], sizeof o[1], "NMX=%d", nmx);
  snprintf(o[2], sizeof o[2], "STAB=%d", stab);
  int st = cable_constants_parse_file_for("runs/knot72/c.knot72", tpl, &c, NULL, &e);
  for (int i = 0; i < 3 && st == 0; i++) st = cable_constants_parse_override(o[i], &c, NULL, tpl->parnames, tpl->npar, &e);
  c.nthreads = 1;
  if (st != 0 || cable_problem_prepare(tpl, &c, 1, &pb, &e) != 0) return -1;
  int n = 0;
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  double t0 = bench_now();
  if (cc && cable_cont_set_start(cc, NULL) == 0) {
    cable_sink sink = {&n, count_point, NULL, NULL};
    cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  double t = bench_now() - t0;
  cable_cont_free(cc);
  cable_problem_release(tpl, pb);
  *npts = n;
  return n > 0 ? t / n : -1;
}

int main(int argc, char **argv)
{
  int reps = argc > 1 ? atoi(argv[1]) : 5;
  if (reps < 1) reps = 1;
  double *v = malloc((size_t)reps * sizeof *v);
  if (!v) return 1;
  printf("STAB cost per step, elastica_int trivial branch, ISP=2, 1 thread, median of %d runs\n", reps);
  printf("  NTST NCOL  N(index)  points  s/step STAB=0  s/step STAB=1  added\n");
  const int meshes[3][2] = {{20, 4}, {50, 5}, {100, 7}};
  for (int m = 0; m < 3; m++) {
    double t[2];
    int n = 0;
    for (int stab = 0; stab <= 1; stab++) {
      for (int r = 0; r < reps; r++) v[r] = run_time(stab, meshes[m][0], meshes[m][1], 100, &n);
      t[stab] = bench_median(v, reps);
    }
    printf("  %4d %4d  %8d  %6d  %13.3e  %13.3e  %.3e\n", meshes[m][0], meshes[m][1],
           meshes[m][0] * meshes[m][1] + 1, n, t[0], t[1], t[1] - t[0]);
  }
  printf("one index computation against N (nvar = 1: N = NTST NCOL + 1)\n");
  const int sizes[5][2] = {{50, 4}, {100, 4}, {200, 4}, {200, 7}, {400, 7}};
  for (int k = 0; k < 5; k++) {
    int ntst = sizes[k][0], ncol = sizes[k][1];
    cable_solution *s = cable_solution_alloc(2, ntst, ncol, 2, 2);
    if (!s) break;
    for (int i = 0; i <= ntst * ncol; i++) s->t[i] = (double)i / (ntst * ncol);
    s->par[0] = 50.0;
    cable_stab_result res;
    cable_error e;
    for (int r = 0; r < reps; r++) {
      double t0 = bench_now();
      cable_stability_index(cable_testproblem_elastica_int(), s, 1, ncol, &res, &e);
      v[r] = bench_now() - t0;
    }
    double t = bench_median(v, reps);
    printf("  N = %5d  %.3e s   (%.2f N^3 ns)\n", res.nbasis, t, 1e9 * t / ((double)res.nbasis * res.nbasis * res.nbasis));
    cable_solution_free(s);
  }
  printf("the braid: the flat (7,2) knot, c.knot72 at NTST 20, NCOL 7 (Ritz degree %d, N = %d), 1 thread, median of "
         "%d runs\n", BSV_DEGREE_MAX, 5 * (20 * BSV_DEGREE_MAX + 1) + 1, reps);
  double tk[2];
  int nk = 0;
  for (int stab = 0; stab <= 1; stab++) {
    for (int r = 0; r < reps; r++) v[r] = knot_time(stab, 10, &nk);
    tk[stab] = bench_median(v, reps);
  }
  printf("  points %d  s/step STAB=0 %.3e  s/step STAB=1 %.3e  added %.3e\n", nk, tk[0], tk[1], tk[1] - tk[0]);
  printf("one braid index (tests/data/s.link62_buckled, NTST 50) against the Ritz degree\n");
  cable_error e;
  cable_sfile *sf = cable_sfile_read("tests/data/s.link62_buckled", &e);
  for (int deg = 1; sf && deg <= 4; deg++) {
    cable_stab_result res;
    for (int r = 0; r < reps; r++) {
      double t0 = bench_now();
      cable_stability_index(braid_problem_find("braid_link"), cable_sfile_get(sf, 0), 1, deg, &res, &e);
      v[r] = bench_now() - t0;
    }
    printf("  degree %d  N = %5d  %.3e s  index %d\n", deg, res.nbasis, bench_median(v, reps), res.index);
  }
  cable_sfile_free(sf);
  /* a mode-branch knot: (a) of the paper (NTST 30), braid_knot_sym (the
     F2(0) row), at the degree a run uses (NCOL 7 capped) */
  sf = cable_sfile_read("tests/data/s.knot72_mode1_a", &e);
  if (sf) {
    cable_stab_result res;
    const cable_solution *sa = cable_sfile_get(sf, 0);
    for (int r = 0; r < reps; r++) {
      double t0 = bench_now();
      cable_stability_index(braid_problem_find("braid_knot_sym"), sa, 1, sa->ncol, &res, &e);
      v[r] = bench_now() - t0;
    }
    printf("one index at (a), tests/data/s.knot72_mode1_a (NTST 30, braid_knot_sym): N = %d  %.3e s  index %d  "
           "zero %d\n", res.nbasis, bench_median(v, reps), res.index, res.nzero);
    cable_sfile_free(sf);
  }
  free(v);
  return 0;
}
