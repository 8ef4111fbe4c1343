/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: declares a constants key that is one of cable's own. */
#include "broken_common.h"

static const cable_problem_key keys[] = {
  {"NTST", CABLE_KEY_INT, 1, 100, 10, NULL, "clashes with cable's NTST"},
};

static const cable_problem problem = {
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .name = "broken",
  .description = "a deliberately broken plug-in", .ndim = 1, .nbc = 1, .nint = 0, .npar = 1,
  .func = broken_func, .bcnd = broken_bcnd, .keys = keys, .nkeys = 1};

const cable_problem *cable_problem_entry(void) { return &problem; }
