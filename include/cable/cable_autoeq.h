/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO-07p equation files as plug-ins: e='NAME' with NAME.f90, NAME.f or
 * NAME.c in the run directory (AUTO's search order).  cable compiles the file
 * once (gfortran or cc), keeps the module in a cache keyed by the file's
 * content, loads it and adapts AUTO's FUNC/STPNT/BCND/ICND/PVLS (Fortran
 * calling convention or AUTO's C interface) to a cable_problem whose
 * dimensions come from the constants, as in AUTO.  doc/auto-users.md.
 *
 *   cable_error err;
 *   char src[1024];
 *   if (cable_autoeq_find(".", "bratu", src, sizeof src) == 0) {
 *     cable_autoeq *m = cable_autoeq_open(src, &err);           // builds or reuses
 *     const cable_problem *pb;
 *     if (m && cable_autoeq_problem(m, &constants, NULL, &pb, &err) == 0)
 *       ... cable_cont_alloc(pb, &constants, ...) ...
 *     cable_autoeq_close(m);
 *   }
 *
 * The cache directory is $CABLE_CACHE_DIR, else $XDG_CACHE_HOME/cable/equations,
 * else $HOME/.cache/cable/equations.  Compilers: $CABLE_FC (default gfortran)
 * and $CABLE_CC (default cc). */
#ifndef CABLE_AUTOEQ_H
#define CABLE_AUTOEQ_H

#include <stddef.h>

#include "cable/cable_api.h"

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"

typedef struct cable_autoeq cable_autoeq;

/* The equation file for e=name in dir (NULL or "": the current directory):
 * dir/name.f90, dir/name.f, dir/name.c, the first that exists, into path.
 * A name ending in one of these suffixes is taken as the file itself.
 * 0, or CABLE_ERR_NOTFOUND (path untouched). */
CABLE_API int cable_autoeq_find(const char *dir, const char *name, char *path, size_t len);

/* Builds src (or takes the cached build of the same content) and loads it.
 * NULL with err on failure: CABLE_ERR_IO (unreadable file, no cache
 * directory), CABLE_ERR_PLUGIN (the compiler rejected the file: err names the
 * file and line of the first error; a routine is missing or has arguments
 * that are not AUTO's), CABLE_ERR_ALLOC. */
CABLE_API cable_autoeq *cable_autoeq_open(const char *src, cable_error *err);

/* The problem for a run with constants c: NDIM, NBC, NINT and NPAR from c
 * (AUTO's rule), the parameter and component names from names (may be NULL),
 * the routines from the module.  dat: AUTO's dat= start data (a table of t and
 * u_1..u_NDIM; NULL or "": none), read here.  *pb stays valid until the next
 * call with m or cable_autoeq_close.  c NULL: a problem that only carries the
 * name (for reading constants before a run; never run it).  0 or an error naming the constants key
 * (NDIM missing) or the routine the run needs but the file lacks. */
CABLE_API int cable_autoeq_problem(cable_autoeq *m, const cable_constants *c, const char *dat, const cable_problem **pb,
                         cable_error *err);

/* The source file and the module built from it. */
CABLE_API const char *cable_autoeq_source(const cable_autoeq *m);
CABLE_API const char *cable_autoeq_module(const cable_autoeq *m);
/* 1 when the last open built the module, 0 when it came from the cache. */
CABLE_API int cable_autoeq_was_built(const cable_autoeq *m);

/* Unloads the module; every problem pointer from it becomes invalid.  NULL is
 * a no-op. */
CABLE_API void cable_autoeq_close(cable_autoeq *m);

#endif
