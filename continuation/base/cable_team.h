/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A small team of threads for loops over mesh intervals (pthreads).
 *
 * cable_team_run(t, fn, ctx, n) calls fn(ctx, i) for i = 0..n-1, each i on
 * one thread; thread k of the team takes the contiguous block
 * [k n / size, (k+1) n / size) (the calling thread is k = 0).  The
 * partition depends only on n and the team size, and fn must write only
 * what belongs to its i: then the results are the same for every team size.
 * Idle workers sleep on a condition variable (no spinning: on a machine
 * shared with other jobs a spinning team is several times slower than one
 * thread).  The team is a run constant: its size does not change, and
 * nothing process-wide (BLAS or OpenMP settings) is touched.
 *
 * cable_team_run_ordered(t, fn, ctx, n, consume, cctx) also calls
 * fn(ctx, i) for i = 0..n-1, each once, and on the calling thread
 * consume(cctx, i) for i = 0..n-1 in order, each once fn(ctx, 0..i) have
 * returned: a producer-consumer pipeline.  The workers take items in
 * increasing order; the calling thread consumes, and takes the next item
 * itself while the one it needs is not ready.  Which thread runs which item depends on
 * timing, so fn(ctx, i) must give the same result on every thread, and it
 * may run concurrently with consume(cctx, k) for k < i.  Without workers
 * it is the loop fn(ctx, i); consume(cctx, i).
 *
 * A team is used by one thread at a time (the solver that owns it). */
#ifndef CABLE_TEAM_H
#define CABLE_TEAM_H

typedef struct cable_team cable_team;
typedef void cable_team_fn(void *ctx, int i);

/* size >= 1 threads in all (size - 1 workers); NULL when out of memory or
 * when a thread cannot be created.  size 1: no threads, run is a loop. */
cable_team *cable_team_alloc(int size);
void cable_team_free(cable_team *t); /* NULL: nothing */
int cable_team_size(const cable_team *t);
/* t NULL runs the loop on the calling thread. */
void cable_team_run(cable_team *t, cable_team_fn *fn, void *ctx, int n);
void cable_team_run_ordered(cable_team *t, cable_team_fn *fn, void *ctx, int n, cable_team_fn *consume, void *cctx);
/* The same with a bounded lookahead: fn(ctx, i) starts only once
 * consume(cctx, k) has returned for every k <= i - window (window >= 1), so
 * at most `window` items run ahead of the consumer (abd_solver.c keeps its
 * band storage as a ring of that many intervals' columns). */
void cable_team_run_ordered_window(cable_team *t, cable_team_fn *fn, void *ctx, int n, cable_team_fn *consume,
                                   void *cctx, int window);

#endif
