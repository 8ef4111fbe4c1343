/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A plug-in of the ABI 5 layout (before symmetries): abi_version 5 and the
 * struct size up to variational.  The fields past that size are filled with
 * garbage here, as a plug-in built against the old header would leave
 * whatever follows its struct: the loader must not read them (nsym = 0). */
#include <stddef.h>

#include "broken_common.h"

static const cable_problem problem = {
  .abi_version = 5, .struct_size = offsetof(cable_problem, symmetries), .name = "abi5",
  .description = "a plug-in of the ABI 5 layout", .ndim = 1, .nbc = 1, .nint = 0, .npar = 1,
  .func = broken_func, .bcnd = broken_bcnd,
  .symmetries = (const cable_symmetry *)&problem, .nsym = 99};

const cable_problem *cable_problem_entry(void) { return &problem; }
