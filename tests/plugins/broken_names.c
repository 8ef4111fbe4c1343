/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: two parameters with the same name. */
#include "broken_common.h"

static const char *const names[] = {"T", "L", "T"};
static const cable_problem problem = BROKEN_PROBLEM(BROKEN_OK_ABI, BROKEN_OK_SIZE, 1, 3, broken_func, broken_bcnd, names);

const cable_problem *cable_problem_entry(void) { return &problem; }
