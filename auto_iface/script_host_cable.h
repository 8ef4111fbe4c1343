/* The script host that runs cable's engine: what `cable replay SCRIPT` uses.
 * It gives AUTO-07p's commands their meaning (doc/scripts.md, "The cable
 * host"):
 *
 *   run(...)        constants (c=NAME reads c.NAME; KEY=VALUE overrides, as in
 *                   AUTO), the problem (e=NAME), the start (STPNT, a solution,
 *                   a result with IRS, or files s.NAME), one continuation run
 *                   on the engine; the branch is kept in memory as a result;
 *                   sv=NAME / ap=NAME write or append b./s./d.NAME.
 *   r('BP1') ...    labelled solutions of a result; sol['T'] a parameter.
 *   save/loadbd/load/merge/relabel/clean   as in AUTO (files b./s./d.NAME).
 *
 * Like AUTO's runner, the host remembers the constants and problem of the
 * last run: run() without c= continues with them (IRS and sv= excepted).
 *
 *   cable_replay_options o;
 *   cable_replay_options_init(&o);
 *   if (cable_replay_run_file("runs/knot72/knot72.auto", &o, &err)) ...report err
 */
#ifndef CABLE_SCRIPT_HOST_CABLE_H
#define CABLE_SCRIPT_HOST_CABLE_H

#include <stdio.h>

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"
#include "script.h"

/* Where e=NAME problems come from.  The host always knows the engine's test
 * problems (bratu, elastica, layer, stiff), the braid templates when a run
 * restarts from a stored solution, and plug-ins (e='path/x.so', or e='x' when
 * x.so exists in the run directory).  A caller adds problems (the braid
 * problems from STPNT, which need prepared starting parameters) here. */
typedef struct cable_replay_problems {
  void *ctx;
  /* The problem for e=name.  c: the run's constants after every override, or
   * NULL when the host only needs the problem's names (parnames/unames) to
   * read the overrides.  from_stpnt: 1 when the run starts from STPNT.
   * Return 0 and *pb (valid until release), CABLE_ERR_NOTFOUND without
   * touching err when the name is not yours, or another error with err. */
  int (*find)(void *ctx, const char *name, const cable_constants *c, int from_stpnt,
              const cable_problem **pb, cable_error *err);
  /* The host no longer needs pb (NULL: nothing to do). */
  void (*release)(void *ctx, const cable_problem *pb);
} cable_replay_problems;

typedef struct cable_replay_options {
  const char *dir;                        /* directory of c./s./b./d. files; NULL or "": the
                                             current directory */
  const cable_replay_problems *problems;  /* NULL: the host's own problems only */
  FILE *log;                              /* labelled points of each run, print() output,
                                             notes; NULL: stdout */
  FILE *diag;                             /* the engine's per-point diagnostics (AUTO's
                                             fort.9 lines); NULL: not shown */
} cable_replay_options;

void cable_replay_options_init(cable_replay_options *o);

typedef struct cable_replay cable_replay;

/* The options are copied (the FILE pointers and problems must outlive r). */
cable_replay *cable_replay_alloc(const cable_replay_options *opt);
/* Frees the session: plug-ins it opened are closed.  Every script run with
 * its host must have finished.  NULL is a no-op. */
void cable_replay_free(cable_replay *r);
/* The script host of the session, for script_run_file/script_run_string.
 * Several scripts may run one after another in one session. */
const script_host *cable_replay_host(cable_replay *r);

/* `cable run`: one run(...) of the session.  name: NULL, or the NAME of
 * `cable run NAME`, which is AUTO's run('NAME') (e='NAME', c='NAME' and
 * s='NAME' where those exist).  names holds the keywords that
 * take names (c, e, s, sv, ap) as strings; overrides[0..nover-1] are
 * constants-file statements ("NTST=50", "IRS=BP1", "DS='-'") applied in
 * order after the constants file, each as cable_constants_parse_override
 * reads it (an error names the statement and its key).  0 or a negative
 * cable_status with err. */
int cable_replay_run_cli(cable_replay *r, const char *name, const script_kwargs *names, int nover,
                         const char *const *overrides, cable_error *err);

/* Allocates a session, runs the script file, frees the session.  0 or a
 * negative cable_status with err naming the script line (and the constants
 * file or engine message behind it). */
int cable_replay_run_file(const char *path, const cable_replay_options *opt, cable_error *err);

#endif
