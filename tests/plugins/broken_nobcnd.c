/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: two boundary conditions but no BCND. */
#include "broken_common.h"

static const cable_problem problem = BROKEN_PROBLEM(BROKEN_OK_ABI, BROKEN_OK_SIZE, 2, 1, broken_func, NULL, NULL);

const cable_problem *cable_problem_entry(void) { return &problem; }
