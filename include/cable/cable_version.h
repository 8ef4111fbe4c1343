#ifndef CABLE_VERSION_H
#define CABLE_VERSION_H

#include "cable/cable_api.h"
#define CABLE_VERSION "0.1.0"
/* "cable 0.1.0 (SUNDIALS x, GSL y, LAPACK z)" into buf */
CABLE_API const char *cable_version_string(char *buf, unsigned long len);
#endif
