/* SPDX-License-Identifier: GPL-3.0-or-later */
/* User problems from shared objects (doc/plugins.md).
 *
 * A plug-in is a .so file exporting
 *     const cable_problem *cable_problem_entry(void);
 * The loader opens it, finds that symbol, and checks the returned problem
 * before anything calls it: the ABI version and struct size first (so an
 * old or foreign module is never read past its own struct), then the
 * dimensions, the required callbacks and the name arrays.  A rejected module
 * is closed again and the error names the file, the field and the reason:
 *
 *   build/release/plugins/broken_abi.so: abi_version: built for ABI 99, this
 *   cable expects 3 (rebuild the plug-in against this cable's cable_problem.h)
 */
#ifndef CABLE_PLUGIN_LOADER_H
#define CABLE_PLUGIN_LOADER_H

#include "cable/cable_api.h"

#include "cable/cable_error.h"
#include "cable/cable_problem.h"

typedef struct cable_plugin cable_plugin;

/* Opens path and validates its problem against AUTO's default NPAR
 * (CABLE_NPAR_DEFAULT).  A path without '/' is taken relative to the current
 * directory (never searched for in the system library path).  On success
 * *pb points into the module and stays valid until cable_plugin_close.  On
 * failure returns NULL, *pb = NULL, err: CABLE_ERR_IO (missing or unreadable
 * file), CABLE_ERR_PLUGIN (the module was rejected) or CABLE_ERR_ALLOC. */
CABLE_API cable_plugin *cable_plugin_open(const char *path, const cable_problem **pb, cable_error *err);
/* The same with the NPAR the run uses (the problem's npar must not exceed it). */
CABLE_API cable_plugin *cable_plugin_open_npar(const char *path, int npar_max, const cable_problem **pb,
                                     cable_error *err);
/* Unloads the module: every pointer obtained from it becomes invalid.
 * NULL is a no-op. */
CABLE_API void cable_plugin_close(cable_plugin *p);

CABLE_API const cable_problem *cable_plugin_problem(const cable_plugin *p);
CABLE_API const char *cable_plugin_path(const cable_plugin *p);

/* The checks the loader applies, for built-in problems too.  origin names
 * the problem's source in messages (a file name or "built-in").  Returns 0 or
 * CABLE_ERR_PLUGIN with err->key the offending field. */
CABLE_API int cable_problem_validate(const cable_problem *pb, int npar_max, const char *origin,
                           cable_error *err);

#endif
