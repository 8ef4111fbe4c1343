/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: built for another ABI version. */
#include "broken_common.h"

static const cable_problem problem = BROKEN_PROBLEM(99, BROKEN_OK_SIZE, 1, 1, broken_func, broken_bcnd, NULL);

const cable_problem *cable_problem_entry(void) { return &problem; }
