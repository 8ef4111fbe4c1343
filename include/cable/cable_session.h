/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A session of AUTO-07p's runner on cable's engine: what the Python package
 * (python/cable, its C side auto_iface/python/pycable_*.c) and `cable run` use;
 * everything a script can do goes through it.
 *
 *   run             constants (c=NAME reads c.NAME; KEY=VALUE overrides, as in
 *                   AUTO), the problem (e=NAME), the start (STPNT, a solution,
 *                   a result with IRS, or files s.NAME), one continuation run
 *                   on the engine; the branch is kept in memory; sv=NAME /
 *                   ap=NAME write or append b./s./d.NAME.
 *   load/loadbd/save/merge/relabel   as in AUTO (files b./s./d.NAME).
 *
 * Like AUTO's runner, the session remembers the constants and problem of the
 * last run: a run without c= continues with them (sv= excepted), and the
 * solutions it started from (those of the last s=NAME or name, or the one
 * solution of the last start from a solution or result): a run without a
 * start of its own restarts from them as IRS selects (IRS=0: STPNT).  It
 * numbers labels and branches after every label it has used or read.
 *
 * Branches (cable_branch) are immutable once built and reference-counted:
 * cable_branch_incref / cable_branch_decref. */
#ifndef CABLE_SESSION_H
#define CABLE_SESSION_H

#include <stdio.h>

#include "cable/cable_api.h"
#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "cable/cable_error.h"
#include "cable/cable_names.h"
#include "cable/cable_output.h"
#include "cable/cable_problem.h"
#include "cable/cable_solution.h"

/* Where e=NAME problems come from.  The session always knows the engine's
 * test problems (bratu, elastica, layer, stiff), the braid templates when a
 * run restarts from a stored solution, and plug-ins (e='path/x.so', or e='x'
 * when x.so exists in the run directory).  A caller adds problems (the braid
 * problems from STPNT, which need prepared starting parameters) here. */
typedef struct cable_session_problems {
  void *ctx;
  /* The problem for e=name.  c: the run's constants after every override, or
   * NULL when only the problem's names (parnames/unames) are needed to read
   * the overrides.  from_stpnt: 1 when the run starts from STPNT.  Return 0
   * and *pb (valid until release), CABLE_ERR_NOTFOUND without touching err
   * when the name is not yours, or another error with err. */
  int (*find)(void *ctx, const char *name, const cable_constants *c, int from_stpnt,
              const cable_problem **pb, cable_error *err);
  /* The session no longer needs pb (NULL: nothing to do). */
  void (*release)(void *ctx, const cable_problem *pb);
} cable_session_problems;

typedef struct cable_session_options {
  const char *dir;                          /* directory of c./s./b./d. files; NULL or "": the
                                               current directory */
  const cable_session_problems *problems;   /* NULL: the session's own problems only */
  FILE *log;                                /* labelled points of each run; NULL: stdout */
  FILE *diag;                               /* the engine's per-point diagnostics (AUTO's
                                               fort.9 lines); NULL: not shown */
  /* Asked after every computed point (NULL: never): non-zero stops the run
   * there with CABLE_ERR_INTERRUPTED; its sv=/ap= files keep every point
   * (doc/failures.md). */
  int (*interrupt)(void *ctx);
  void *interrupt_ctx;
  /* The session's error handler (NULL: none; doc/api.md, One error
   * channel): every error status a call on the session returns (run, load,
   * save, loadbd, transform, transform_files, info) is first reported to
   * on_error(report, on_error_ctx) with the report the call's err gets, also
   * when the caller passes err NULL.  Last, so that the fields above keep
   * their offsets. */
  cable_error_handler on_error;
  void *on_error_ctx;
} cable_session_options;

CABLE_API void cable_session_options_init(cable_session_options *o);

typedef struct cable_session cable_session;
typedef struct cable_branch cable_branch;

/* *out a new session and 0 (opt NULL: the defaults of
 * cable_session_options_init), or *out NULL and a status with err.  The
 * options are copied (the FILE pointers and problems must outlive it). */
CABLE_API int cable_session_create(const cable_session_options *opt, cable_session **out, cable_error *err);
/* The same, older form: the session, or NULL when memory ran out. */
CABLE_API cable_session *cable_session_alloc(const cable_session_options *opt);
/* Frees the session: plug-ins it opened are closed.  NULL is a no-op.
 * Branches live on independently of the session. */
CABLE_API void cable_session_free(cable_session *s);

/* The arguments of AUTO's run(...) and load(...).  The start is at most one
 * of: a solution (sol_branch, sol_index), a result (branches[0..nbranch-1]:
 * its solution IRS, or its last one), a name (run('NAME'): c.NAME when
 * present and s.NAME), or nothing (s= with IRS; else the runner's solutions
 * with IRS, as in AUTO; else STPNT).  e, c, s, sv, ap:
 * the keywords that take names (NULL: not given).  over[0..nover-1] are
 * constants-file statements ("NTST=50", "IRS='BP1'", "DS='-'",
 * "UZR={'T': -2.1}") applied in order after the constants file, each as
 * cable_constants_parse_override reads it (an error names its key).
 *
 * Numbering (AUTO-07p's NEWLAB): MBR and MLAB are the largest branch number
 * and label of the restart data: the s-file the start is read from, the
 * result given, or for a solution the bundle it was taken from
 * (sol_mbr, sol_mlab, AUTO's _mbr and _mlab; 0: the solution's own
 * branch); 0 for a start from STPNT.  The run is branch MBR + 1 when it
 * starts from STPNT or switches (ISW < 0), the start's label for ISW = 2
 * from a point that is not on a fold curve, else the start's own branch
 * number; its labels are MLAB + 1, MLAB + 2, ... */
typedef struct cable_run_args {
  const cable_branch *sol_branch;
  int sol_index;
  cable_branch *const *branches;
  int nbranch;
  const char *name;
  const char *e, *c, *s, *sv, *ap;
  int nover;
  const char *const *over;
  const char *over_file;   /* the file name errors in over[] report ("<command line>"); NULL: none */
  int sol_mbr, sol_mlab;   /* a solution start: its bundle's largest branch number and label (0: none) */
  int keep_state;          /* 1: the run leaves the runner's state (constants, current solution) as it
                              was: a probe, as Python's branches() makes (0: AUTO's run) */
} cable_run_args;

/* One continuation run; *out: the new branch (also when it ended abnormally,
 * MX).  0 or a negative cable_status with err.  sv=NAME / ap=NAME files are
 * written as the run goes (doc/failures.md): an output name that cannot be
 * written is refused before the first step.  CABLE_ERR_INTERRUPTED: the
 * interrupt callback stopped it; *out is then the partial branch (the
 * caller's reference) and the files hold its points.
 * The session functions check their arguments first (doc/api.md,
 * Contracts): a NULL session, arguments or output give CABLE_ERR_NULL; in a
 * (and in save's and transform's lists) a negative count gives
 * CABLE_ERR_SIZE, a count with a NULL array or a NULL entry CABLE_ERR_NULL, a
 * sol_index outside sol_branch CABLE_ERR_RANGE, and a solution together with
 * a result CABLE_ERR_INPUT; *out is NULL then. */
CABLE_API int cable_session_run(cable_session *s, const cable_run_args *a, cable_branch **out, cable_error *err);
/* What a study needs to know about problem e (as a run's e= finds it: a
 * built-in, an AUTO equation file in the session's directory, a plug-in):
 * dimensions, parameters, components, keys and their defaults, the
 * recommended constants, as text on out (`cable info e=NAME`, Python's
 * info('NAME')).  0, or a negative status with err (an unknown problem). */
CABLE_API int cable_session_info(cable_session *s, const char *e, FILE *out, cable_error *err);

/* AUTO's load: the start a run with the same arguments would use, as a
 * one-solution branch, and the runner state of that run.  A name without IRS
 * gives the file's last solution.  When that run would start from STPNT
 * (AUTO's ld(e='x', c='x')), *out is NULL and only the runner state is set. */
CABLE_API int cable_session_load(cable_session *s, const cable_run_args *a, cable_branch **out, cable_error *err);
/* b./s./d.NAME from branches (append: AUTO's ap=).  sol_index >= 0: only that
 * solution of branches[0] (a one-point file). */
CABLE_API int cable_session_save(cable_session *s, cable_branch *const *branches, int n, int sol_index, const char *name,
                       int append, cable_error *err);
/* b.NAME and s.NAME as AUTO's loadbd reads them: one branch per b-file
 * section with every row, the labelled rows with s.NAME's solutions (the
 * labelled solutions only when there is no b-file, or one that does not pair
 * with the s-file); the problem, names, NDIM/NBC/NINT and ICP the b-file's
 * header records where c.NAME and the runner leave them open.  *out: free
 * with cable_branch_list_free. */
CABLE_API int cable_session_loadbd(cable_session *s, const char *name, cable_branch ***out, int *n, cable_error *err);
/* AUTO's merge (relabel 0) and relabel (1) of branches: *out as loadbd's. */
CABLE_API int cable_session_transform(cable_session *s, cable_branch *const *in, int n, int relabel, cable_branch ***out,
                            int *nout, cable_error *err);
/* The same on files b./s./d.NAME, rewritten in place. */
CABLE_API int cable_session_transform_files(cable_session *s, const char *name, int relabel, cable_error *err);
/* AUTO's runner state (its runner.options["constants"], what AUTO's pr()
 * prints): the constants, names and problem name the next run without a
 * start and without c= uses, i.e. those of the last run or load with every
 * keyword override applied; IRS is the label the last run or load started
 * from (0: STPNT); the one-off s and sv are cleared ("").
 * Before any run or load: the defaults (cable_constants_init), no names,
 * problem "".  NDIM, NBC, NINT are 0 unless a constants file or a keyword
 * set them (a run then uses its problem's).  Each of c, names, e may be NULL
 * (not wanted); the pointers stay valid until the next call that changes
 * the session (run, load, loadbd, transform_files) or its free.
 * 0, or CABLE_ERR_NULL with err when s is NULL (the outputs set to NULL). */
CABLE_API int cable_session_constants(const cable_session *s, const cable_constants **c, const cable_names **names,
                                      const char **e, cable_error *err);
/* Branch identity across runs (doc/engine.md, "Branch identity: known
 * branch points"): the branch points of b become known points of every later
 * run of the session (cable_cont_add_known_point), so that a branch that
 * locates one of them ends there with CABLE_END_LOOP, its end note saying
 * "joins a known branch" and naming the point ("BP label 3 of branch 1").
 * sol_index < 0: every labelled BP solution of b; else solution sol_index,
 * which must be a BP (CABLE_ERR_INPUT otherwise, CABLE_ERR_RANGE outside b).
 * A run hands over only the points of its own NDIM (a fold or branch-point
 * curve's extended problem gets none); its start is never taken for a known
 * point (the engine looks from its second point on).  Returns the number of
 * points added (0 for a branch without BPs) or a negative status with err. */
CABLE_API int cable_session_add_known(cable_session *s, const cable_branch *b, int sol_index, cable_error *err);
/* Forgets every known point (0; CABLE_ERR_NULL for a NULL session). */
CABLE_API int cable_session_clear_known(cable_session *s);
/* The number of known points (0 for a NULL session). */
CABLE_API int cable_session_nknown(const cable_session *s);
/* The path of TYPE.NAME ("c", "s", "b", "d") or of a plain file (type NULL)
 * in the session's directory ("" for a NULL session or name; nothing for a
 * NULL buf or len 0). */
CABLE_API void cable_session_path(const cable_session *s, const char *type, const char *name, char *buf, size_t len);

CABLE_API void cable_branch_incref(cable_branch *b);
CABLE_API void cable_branch_decref(cable_branch *b);   /* NULL is a no-op */
CABLE_API void cable_branch_list_free(cable_branch **list, int n);

/* What a branch holds: its number, its points (the b-file rows, with the
 * engine's notes), its labelled solutions and the constants, names and
 * problem they were computed with.  Pointers stay valid while b lives.  A
 * NULL branch gives 0 and NULL; incref and decref of NULL do nothing. */
CABLE_API int cable_branch_number(const cable_branch *b);
CABLE_API int cable_branch_npoints(const cable_branch *b);
CABLE_API const cable_point *cable_branch_point(const cable_branch *b, int i);
CABLE_API int cable_branch_nsolutions(const cable_branch *b);
CABLE_API const cable_solution *cable_branch_solution(const cable_branch *b, int i);
/* The engine's remark on solution i's point (the d-file note), NULL: none. */
CABLE_API const char *cable_branch_solution_note(const cable_branch *b, int i);
CABLE_API const cable_names *cable_branch_names(const cable_branch *b);
CABLE_API const cable_constants *cable_branch_constants(const cable_branch *b);
CABLE_API const char *cable_branch_problem(const cable_branch *b);
/* Why the branch ended abnormally (the d-file's note, for people), NULL: a
 * normal end. */
CABLE_API const char *cable_branch_end_note(const cable_branch *b);
/* The branch directions its run's switch found at a double branch point
 * (ISW = -1; cable_cont_branches, doc/engine.md "Multiple branch points" and
 * "Symmetry: the restriction to Fix(S)"): copies at most max into out (may be
 * NULL) and returns their number; -1 when the run computed none (not a
 * switch at a double BP, or degenerate equations and no declared symmetry).
 * *order (may be NULL): 2 quadratic, 3 cubic ABE, 0 none. */
CABLE_API int cable_branch_switch_directions(const cable_branch *b, cable_branch_dir *out, int max, int *order);
/* How the run that computed b ended, for programs: its status (enum
 * cable_status: CABLE_END_NMX, CABLE_END_BOUNDS, ... > 0 a normal end, < 0
 * the error, CABLE_ERR_INTERRUPTED a stopped run); 0 for a branch no run of
 * this process computed (read from files, or two runs joined by merge) and
 * for a NULL branch. */
CABLE_API int cable_branch_end_status(const cable_branch *b);

#endif
