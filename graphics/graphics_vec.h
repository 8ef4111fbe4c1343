/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The graphics layer's constant pi; the 3-vector helpers are the shared ones
 * (cable_vec3.h). */
#ifndef CABLE_GRAPHICS_VEC_H
#define CABLE_GRAPHICS_VEC_H

#include "cable_vec3.h"

/* M_PI is not in strict C11/POSIX. */
#define GRAPHICS_PI 3.14159265358979323846

#endif
