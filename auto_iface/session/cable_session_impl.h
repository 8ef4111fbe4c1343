/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Internals of the session (cable_session.c, cable_session_store.c). */
#ifndef CABLE_SCRIPT_HOST_IMPL_H
#define CABLE_SCRIPT_HOST_IMPL_H

#include "cable/cable_aufile.h"
#include "cable/cable_autoeq.h"
#include "cable/cable_cont.h"
#include "cable/cable_names.h"
#include "cable/cable_output.h"
#include "cable/cable_plugin.h"
#include "cable/cable_session.h"

/* One computed point (a b-file row) with its own copies of the arrays. */
typedef struct rp_point {
  cable_point pt;   /* pt.icp, pt.par, pt.umax point into mem */
  void *mem;
  char *note;       /* owned copy of pt.note, NULL: none */
  int sol;          /* index of its labelled solution in the branch, -1: none */
} rp_point;

/* One branch: what one run computed, with the constants, names and problem
 * it was computed with.  Immutable once built and shared between results by
 * reference counting. */
typedef struct cable_branch {
  long refs;
  int ibr;
  cable_constants c;
  cable_names names;
  char e[CABLE_NAME_MAX];
  int npt, cappt;
  rp_point *pts;
  int nsol, capsol;
  cable_solution **sol;
  char *end_note;   /* why the branch ended abnormally (d-file), NULL: normal end */
  int end_status;   /* the run's end (enum cable_status: > 0 normal, < 0 error); 0: not a run's */
  /* a fold run (ISW=2): c holds the extended problem's constants (its files'
     headers), c_user the run's own (original NDIM, NBC, NINT, ICP, ISW=2),
     which a restart from the branch takes, as AUTO's run(r2) does */
  int has_c_user;
  cable_constants c_user;
  /* a branch made by load from restart data (a file, a result): that data's
     largest branch number and label (AUTO's _mbr, _mlab), which a run from
     its solution continues after; 0 for a computed branch */
  int src_mbr, src_mlab;
  /* the switch's branch directions at a double BP (cable_branch_switch_directions):
     ndirs -1 none */
  int ndirs, dir_order;
  cable_branch_dir dirs[CABLE_MAX_BRANCHES];
} rp_branch;

/* A result: branches in order. */
typedef struct rp_result {
  int nbr;
  rp_branch **br;
} rp_result;

/* A solution handle: solution isol of a branch. */
typedef struct rp_sol {
  rp_branch *br;
  int isol;
} rp_sol;

#define RP_MAX_PLUGINS 16

struct cable_session {
  cable_session_options opt;
  /* AUTO's runner state: the constants, names and problem of the last run */
  cable_constants cur;
  cable_names cur_names;
  char cur_e[CABLE_NAME_MAX];
  /* AUTO's runner solution: what a run without a start of its own restarts
     from (IRS in cur selects from it): the solutions of the last s=NAME,
     run('NAME') or ld('NAME') (owned), or the one solution of the last
     run(sol) or run(result) (a reference); neither: STPNT */
  cable_sfile *cur_sf;
  char cur_sfpath[1024];
  int cur_pick;   /* the index in cur_sf of the solution the last load or run started from, -1: none */
  rp_branch *cur_br;
  int cur_isol;
  int cur_mbr, cur_mlab;   /* cur_br's solution: its bundle's largest branch number and label */
  int nplugins;
  char plugin_name[RP_MAX_PLUGINS][CABLE_NAME_MAX];
  cable_plugin *plugin[RP_MAX_PLUGINS];
  /* the last "accepted and ignored" note printed: the same note is not
     printed again before every run of a script */
  char noted_ignored[sizeof ((cable_constants *)0)->ignored];
  /* AUTO equation files (NAME.f90, NAME.f, NAME.c) loaded by this session */
  int nautoeq;
  char autoeq_name[RP_MAX_PLUGINS][CABLE_NAME_MAX];
  cable_autoeq *autoeq[RP_MAX_PLUGINS];
  /* known branch points (cable_session_add_known): owned clones and names */
  int nknown, capknown;
  cable_solution **known;
  char (*known_name)[64];
};

/* ---- known branch points (cable_session_known.c) ------------------------------------ */

int rp_session_add_known(cable_session *r, const cable_branch *b, int sol_index, cable_error *err);
/* Hands every known point of the run's NDIM to cc; 0 or the engine's status. */
int rp_session_known_to(const cable_session *r, cable_cont *cc, int ndim);
void rp_session_known_free(cable_session *r);

/* ---- store (cable_session_store.c) ------------------------------------------------- */

rp_branch *rp_branch_alloc(int ibr, const cable_constants *c, const cable_names *names, const char *e);
void rp_branch_decref(rp_branch *b);   /* frees at zero; NULL is a no-op */
/* Appends a copy of pt (and of sol when not NULL); 0 or CABLE_ERR_ALLOC. */
int rp_branch_add(rp_branch *b, const cable_point *pt, const cable_solution *sol);
/* Keep a copy of text (NULL or "": none) as the branch's end note. */
int rp_branch_set_end_note(rp_branch *b, const char *text);
/* A deep copy (solutions cloned); NULL when out of memory. */
rp_branch *rp_branch_copy(const rp_branch *b);

rp_result *rp_result_alloc(int nbr);   /* nbr NULL slots */
void rp_result_free(rp_result *r);     /* drops its branch references */
/* The point of the isol-th solution of b. */
const cable_point *rp_sol_point(const rp_branch *b, int isol);

/* The path of a file TYPE.NAME ("c", "s", "b") in the session directory. */
void rp_path(const cable_session *r, const char *type, const char *name, char *buf, size_t len);

/* b./s./d.NAME from a result (append: AUTO's ap). */
int rp_result_write(const cable_session *r, const rp_result *res, const char *name, int append,
                    cable_error *err);
/* A result from s.NAME and b.NAME: one branch per run (b.NAME's sections,
 * split at its header lines as AUTO's parseB does), with every row of the
 * b-file when its labelled rows are the s-file's labels in order (AUTO's
 * loadbd); else (no b-file, or one that does not pair) the labelled points
 * only, with the norms of their rows.  c/names: the constants the branches get. */
int rp_result_read(const cable_session *r, const char *name, const cable_constants *c,
                   const cable_names *names, const char *e, rp_result **out, cable_error *err);

/* ---- b-file rows and header (cable_session_rows.c) ---------------------------------- */

/* The names b-file path's header records: e (its e = '...'; "" when none)
 * and its parnames/unames dicts applied to *names (*has_names: 1 when one was);
 * its NDIM, NBC and NINT set in *c where *c leaves them to the problem (0). */
void rp_bfile_header(const char *path, char *e, size_t elen, cable_names *names, int *has_names, cable_constants *c);
/* The constants the header of the b-file section whose first row is at
 * line first_line records (AUTO's parseB: its branch's c), over *c:
 * RL0, RL1, A0, A1 and every KEY = VALUE cable reads. */
void rp_bfile_section_constants(const char *path, int first_line, cable_names *names, cable_constants *c);
/* One branch from a b-file section: a point per row; the labelled rows take
 * sols[0], sols[1], ... in order, with notes[] (the d-file's).  Parameters
 * without a column take at an unlabelled row the value all labelled
 * solutions share (NaN when they differ). */
int rp_branch_from_rows(const cable_bfile_branch *bb, const cable_solution *const *sols, const char *const *notes,
                        const cable_constants *c, const cable_names *names, const char *e, rp_branch **out);

/* ---- d-file notes (cable_session_dnotes.c) ------------------------------------------- */

/* The engine's NOTE and BP record of each labelled point of a d-file, by label. */
typedef struct rp_dnotes {
  int found;   /* the d-file exists */
  int n;
  int *lab;
  char **note;
  int *bp_kind;   /* enum cable_bp_kind from the point's BP record; CABLE_BP_UNKNOWN: none */
} rp_dnotes;

/* Reads path (a missing file gives no notes); 0 or CABLE_ERR_ALLOC. */
int rp_dnotes_read(const char *path, rp_dnotes *d);
void rp_dnotes_free(rp_dnotes *d);
/* The note of the nth (0, 1, ...) labelled point with label lab, NULL: none. */
const char *rp_dnotes_find(const rp_dnotes *d, int lab, int nth);
/* The kind (enum cable_bp_kind) the BP record of the nth labelled point with
 * label lab gives; CABLE_BP_UNKNOWN when itp is no BP or the point has no
 * record (a d-file of AUTO's or of a cable before the records). */
int rp_dnotes_bp_kind(const rp_dnotes *d, int itp, int lab, int nth);

/* AUTO's merge: a branch that starts where the previous one started (the two
 * directions from one start) is joined to it; relabel: labels 1, 2, ... */
int rp_result_merge(const rp_result *in, rp_result **out);
int rp_result_relabel(const rp_result *in, rp_result **out);

/* The text of `cable info e=NAME` for a problem (cable_info.c); source: the
 * AUTO equation file it was found as, or NULL. */
int rp_problem_info_write(const cable_problem *pb, const char *source, FILE *out);

/* ---- the public calls' bodies (cable_session.c); the public entry points
 * (cable_session_errors.c) report their errors to the session's handler ---- */
int rp_session_run(cable_session *r, const cable_run_args *a, cable_branch **out, cable_error *err);
int rp_session_info(cable_session *r, const char *e, FILE *out, cable_error *err);
int rp_session_load(cable_session *r, const cable_run_args *a, cable_branch **out, cable_error *err);
int rp_session_save(cable_session *r, cable_branch *const *branches, int n, int sol_index, const char *name,
                    int append, cable_error *err);
int rp_session_loadbd(cable_session *r, const char *name, cable_branch ***out, int *n, cable_error *err);
int rp_session_transform(cable_session *r, cable_branch *const *in, int n, int relabel, cable_branch ***out,
                         int *nout, cable_error *err);
int rp_session_transform_files(cable_session *r, const char *name, int relabel, cable_error *err);

#endif
