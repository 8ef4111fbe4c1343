/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: a prepare without the release that gives instances back. */
#include "broken_common.h"

static int prepare(const cable_problem *pb, const struct cable_constants *c, int from_stpnt,
                   const cable_problem **instance, struct cable_error *err)
{
  (void)c, (void)from_stpnt, (void)err;
  *instance = pb;
  return 0;
}

static const cable_problem problem = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "broken",
  .description = "a deliberately broken plug-in", .ndim = 1, .nbc = 1, .nint = 0, .npar = 1,
  .func = broken_func, .bcnd = broken_bcnd, .prepare = prepare};

const cable_problem *cable_problem_entry(void) { return &problem; }
