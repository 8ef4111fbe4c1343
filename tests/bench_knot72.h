/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The flat (7,2) braid knot of the benchmarks (issue 17's problem): the
 * torus start of runs/knot72 and the built-in braid_knot problem on it. */
#ifndef CABLE_BENCH_KNOT72_H
#define CABLE_BENCH_KNOT72_H

#include "braid_problems.h"
#include "braid_start.h"

/* 0, or -1 when the start cannot be prepared.  sp must outlive pb. */
static inline int bench_knot72(braid_start_params *sp, cable_problem *pb)
{
  braid_start_params_init(sp, BRAID_START_TORUS, 7, +1, 0.0051364907419, 1.98889, 0.0);
  if (braid_start_prepare(sp) != 0) return -1;
  braid_problem_instance("braid_knot", sp, pb);
  return 0;
}

#endif
