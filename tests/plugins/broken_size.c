/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: the struct size of another build of the header. */
#include "broken_common.h"

static const cable_problem problem = BROKEN_PROBLEM(BROKEN_OK_ABI, sizeof(cable_problem) - 8, 1, 1, broken_func, broken_bcnd, NULL);

const cable_problem *cable_problem_entry(void) { return &problem; }
