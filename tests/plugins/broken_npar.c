/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: more parameters than AUTO's NPAR = 36. */
#include "broken_common.h"

static const cable_problem problem = BROKEN_PROBLEM(BROKEN_OK_ABI, BROKEN_OK_SIZE, 1, 40, broken_func, broken_bcnd, NULL);

const cable_problem *cable_problem_entry(void) { return &problem; }
