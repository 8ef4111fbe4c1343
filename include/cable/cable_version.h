/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef CABLE_VERSION_H
#define CABLE_VERSION_H

#include "cable/cable_api.h"
#define CABLE_VERSION "0.1.0"
/* "cable 0.1.0 (SUNDIALS x, GSL y, LAPACK z)" into buf (cut to len - 1
 * characters); returns buf, or NULL when buf is NULL or len is 0. */
CABLE_API const char *cable_version_string(char *buf, unsigned long len);
#endif
