/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A run's watch over the user's routines (an equation file's FUNC, BCND,
 * ICND, STPNT, PVLS, or a plug-in's): a routine that ends the process
 * (Fortran STOP or ERROR STOP, exit(), abort(), a crash) is reported on
 * stderr naming the file and the routine, the run and where its points are,
 * and the exit status is non-zero; a negative (fatal) return is recorded
 * for the run to stop at (doc/failures.md).
 *
 * The problem the engine gets is a copy of the user's whose routines are
 * called through the guard.  What a signal handler or an exit handler needs
 * is kept per thread (the routine being called and its run's guard): the
 * only process-wide state is the handlers' installation, made once and
 * chaining to the handlers that were there before. */
#ifndef CABLE_RUN_GUARD_H
#define CABLE_RUN_GUARD_H

#include "cable/cable_problem.h"

#define RP_GUARD_TEXT 1600

typedef struct rp_guard {
  cable_problem pb;          /* what the engine calls */
  const cable_problem *user; /* the user's problem */
  char origin[600];          /* "equation file ./x.f90", "plug-in ./x.so" */
  char where[RP_GUARD_TEXT]; /* "during branch 1 of e='x' ...; the points so far are ..." */
  volatile int fatal;        /* the first negative return (0: none) */
  const char *volatile fatal_routine;
} rp_guard;

/* g watches user's routines (origin: what the message calls the problem).
 * g->pb is the problem to run; g must stay where it is while it runs. */
void rp_guard_init(rp_guard *g, const cable_problem *user, const char *origin);
/* The text after the routine's name in the messages (async-signal-safe to
 * read; update between steps). */
void rp_guard_set_where(rp_guard *g, const char *text);

#endif
