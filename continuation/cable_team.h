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

#endif
