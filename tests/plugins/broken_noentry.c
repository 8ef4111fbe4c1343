/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Broken on purpose: the entry symbol is misspelt, so the loader finds no
 * cable_problem_entry. */
#include "broken_common.h"

static const cable_problem problem = BROKEN_PROBLEM(BROKEN_OK_ABI, BROKEN_OK_SIZE, 1, 1, broken_func, broken_bcnd, NULL);

const cable_problem *cable_problem_entyr(void);
const cable_problem *cable_problem_entyr(void) { return &problem; }
