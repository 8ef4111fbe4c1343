/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Private: the continuation engine's state.  Only continuation/cont_*.c
 * include this header; users see the opaque cable_cont. */
#ifndef CABLE_CONT_IMPL_H
#define CABLE_CONT_IMPL_H

#include <stdarg.h>
#include <stdio.h>

#include "abd_solver.h"
#include "cable/cable_cont.h"
#include "colloc_jac.h"
#include "colloc_newton.h"
#include "colloc_system.h"

/* Sign-change test functions at one accepted point. */
typedef struct cont_tests {
  int det_sign;                 /* sign of det of the extended Newton matrix */
  double det_log;               /* log |det| */
  double lp;                    /* principal-parameter component of the unit tangent */
  double uz[CABLE_MAX_UZR];     /* par[uzr.par] - uzr.value */
  double sv1;                   /* smallest singular value of the extended matrix (NSV > 0) */
  double sv2;                   /* second smallest (NSV > 1) */
} cont_tests;

/* Work counters of one run (cont_counts.c): machine-independent measures of
 * the cost of the corrector and of the branch-point tests. */
typedef struct cont_counts {
  long steps;                   /* calls of cable_cont_step after the start */
  long correct;                 /* corrector solves (every call of cont_correct_from) */
  long newton_iters;            /* their Newton iterations (one linear solve each) */
  long newton_fact;             /* their factorisations */
  long tan_fact;                /* factorisations made for a tangent (cont_tangent) */
  long sv_calls, sv_iters;      /* smallest-singular-value iterations: calls, sweeps
                                   (each sweep = 2 k solves with the factorisation) */
  long dip_evals, dips;         /* corrector+tangent evaluations in sigma_1 minimisations, minimisations */
  long locate_evals, locates;   /* the same in sign-change locations */
} cont_counts;

/* Closed-loop detection (cont_loop.c): summaries of the start and of the
 * previous point, the largest distance from the start so far. */
typedef struct cont_loop {
  double *z0, *zp, *z;          /* [m]: free parameters, U(0), U(1), IPLT's measure, of the
                                   start, the previous point and the new one */
  int m;
  double dmax;                  /* largest distance of a point from the start */
  int start_lab;                /* the start's label in its restart data (0: STPNT) */
  /* branch points computed on other branches (cable_cont_add_known_point):
     summaries [nknown * (nfpr + 2 ndim)] and their names */
  double *known;
  char (*known_name)[64];
  int nknown;
} cont_loop;

struct cable_cont {
  const cable_problem *pb;      /* not owned */
  const cable_constants *c;     /* the caller's, not owned: alive and unchanged while
                                   the handle lives (cable_cont.h) */
  int ndim, npar, nfpr, n;
  int ntst, ncol;
  struct cable_team *team;      /* the handle's one thread team (NULL: one thread), lent to
                                   sys, nw and abd (cable_cont_alloc) */
  colloc_system *sys;           /* discretisation (mesh, closing equation) */
  colloc_newton *nw;            /* KINSOL Newton solver */
  colloc_jac *J;                /* Newton matrix for tangents and test functions */
  abd_solver *abd;              /* its factorisation */
  int linalg_shared;            /* 1: J and abd are the Newton solver's (colloc_newton_storage), not owned */
  double *x, *xdot;             /* current accepted point and its unit tangent */
  double *xp, *xdotp;           /* previous accepted point and tangent */
  double *xt, *xdott;           /* trial point and tangent */
  double *w1, *w2, *w3;         /* work vectors of length n */
  double *xlo, *xhi;            /* locating: the solutions at the bracket's ends */
  double *svec;                 /* [n * 3] singular-vector work */
  double ds;                    /* signed step size for the next step */
  double ds_used;               /* step size that produced the current point */
  double ds_prev;               /* step size that produced the previous point */
  int have_start;               /* cable_cont_set_start succeeded */
  int started;                  /* the start has been processed */
  int restart;                  /* start came from a stored solution */
  int switch_pending;           /* ISW = -1 from a BP: first step along the kernel */
  int switched_start;           /* the run's first point was such a switch (its first step is checked) */
  int pvls_fatal;               /* a negative PVLS status seen at a trial point (0: none) */
  int store_failed;             /* PVLS failed while storing a point: its solution is half
                                   written, so no MX point repeats it */
  int restart_moved;            /* PAR changed a stored solution's parameters: correct it first */
  int npt;                      /* points accepted on this branch */
  int nstep_adapt;              /* steps since the last mesh adaptation */
  int newton_iters;             /* iterations of the last corrector */
  int ended;                    /* the branch has ended (status in end_status) */
  int end_status;
  cont_tests tf;                /* test functions at x */
  cont_tests tft;               /* at the trial point */
  cont_tests tfp;               /* at the previous point xp */
  /* a located singular-value dip (double BP or a pair of BPs in one step) is
     emitted before the trial point, which waits in the queue */
  int queued;                   /* 1: xq/xdotq/tfq is the next point to accept */
  double *xq, *xdotq;
  cont_tests tfq;
  /* the queued point is itself a located special point (two test functions
     change sign in one step, cont_locate_events): its type, the arclength
     from the point emitted before it, and its user zero */
  int itp_q, bp_kind_q, uz_hit_q, uz_stop_q;
  double ds_q;
  int dip_at_x;                 /* the current point is a located dip */
  char note[1200];              /* remark on the current point for the d-file ("" none) */
  int itp;                      /* type of the current point (0 regular) */
  int itp_x;                    /* type found for x when it was accepted (located points) */
  int bp_kind;                  /* enum cable_bp_kind of the current point when it is a BP */
  int uz_hit;                   /* index of the user zero located at x, or -1 */
  int uz_stop;                  /* the located user zero asks to stop */
  /* output */
  cable_point pt;               /* row of the current point */
  double *umax;                 /* [ndim] */
  cable_solution *sol;          /* current solution in s-file form */
  cable_solution *pvsol;        /* scratch for PVLS at trial points: UZR on a parameter
                                   that PVLS computes (NULL when no UZR needs it) */
  char err[512];                /* last error message */
  char err_key[64];             /* the key it is about ("PAR"), "" none */
  int err_status;               /* the status the last error was returned with (cont_errors.c) */
  long nerr;                    /* messages set so far: a call that sets none has no message of its own */
  cable_error_handler on_error; /* cable_cont_set_error_handler; NULL: none */
  void *on_error_ctx;
  char rejected[200];           /* why the last corrected point was rejected ("" none) */
  /* pencil test (cont_pencil.c): branch points inside one step */
  abd_solver *tan_abd;          /* factorisation behind the last tangent (not owned) */
  colloc_jac *Ja;               /* Newton matrix at the step's start */
  int pen_m;                    /* Arnoldi steps */
  double *pen_V, *pen_H, *pen_work; /* Krylov basis [n*(m+1)], Hessenberg, eigenvalues */
  /* the pencil test's gate (cont_gate.c) */
  colloc_jac *tan_J;            /* the matrix behind tan_abd (not owned) */
  double *tan_v, *tan_u;        /* [n*2] right, left singular vectors of the last tangent's matrix */
  double tan_sv[2];             /* their singular values */
  double *gate_v, *gate_u, *gate_w; /* [n*2] the same at the step's start x; work */
  double gate_sv[2];
  int gate_valid;               /* gate_v, gate_u, gate_sv belong to x */
  long gate_skipped, gate_run;  /* pencil tests skipped and run on this branch */
  cont_counts cnt;              /* work counters of the run */
  cont_loop loop;               /* closed-loop detection */
  /* the branch directions at a double BP (cont_branches.c) */
  cable_branch_dir br[CABLE_MAX_BRANCHES];
  int nbr;                      /* -1: not computed */
  int abe_order;                /* 2 quadratic, 3 cubic ABE, 0 none */
  double *abe_psi;              /* [2n] the left kernel the ABE used (NULL: not computed) */
  double abe_L[2][2];           /* L_i = abe_L[i][0] cos + abe_L[i][1] sin on the kernel */
  /* the restriction to Fix(S) (cont_symmetry.c, cont_restrict.c): a request
     from the switch (rs_sym >= 0: symmetries[rs_sym], rs_vec = e_s, e_a,
     psi_a [3n]), then the restricted problem the handle runs (owned) */
  int rs_sym, rs_comp, rs_at;   /* the symmetry, the odd quantity's component and end */
  double *rs_vec;
  struct cont_restricted *rs;
};

/* cont_tangent.c */
int cont_factor_at(cable_cont *cc, const double *x, double *logdet, int *sign);
int cont_tangent(cable_cont *cc, const double *x, const double *xdot_old, double *xdot_new,
                 cont_tests *tf);
/* The same right after a successful corrector from the point with tangent
 * xdot_old: reuses the corrector's factorisation when it has one. */
int cont_tangent_after_newton(cable_cont *cc, const double *x, const double *xdot_old, double *xdot_new,
                              cont_tests *tf);
void cont_normalize(cable_cont *cc, double *v);
int cont_smallest_sv(cable_cont *cc, int k, double *sv, double *vecs);

/* cont_special.c */
int cont_find_event(const cable_cont *cc, const cont_tests *a, const cont_tests *b, int *which);
/* The branch-point test function's value (the one whose sign change is a BP):
 * the signed smallest singular value; 0 when ISP and NSV are both 0. */
double cont_bp_value(const cable_cont *cc, const cont_tests *t);
/* AUTO's rule for boundary-value problems: branch points are looked for
 * with |ISP| = 2 or 3, not with ISP = 0, 1 or 4 (auto-07p 0.9.2 on the
 * elastica: BPs at (n pi)^2 with ISP=2, 3, none with ISP=1, 4) */
static inline int cont_bp_detect(const cable_cont *cc)
{
  return cc->c->isp == 2 || cc->c->isp == 3 || cc->c->isp == -2 || cc->c->isp == -3;
}
/* seed: a first guess of the arclength of the special point (NAN: none) */
int cont_locate(cable_cont *cc, int type, int which, double seed);
/* cont_locate, then every other test function that changes sign between x
 * and the located point: the first of them in arclength is located too and
 * goes first, the first located point waits in the queue (AUTO reports each
 * in turn).  On success *itp is the type of the point that goes first. */
int cont_locate_events(cable_cont *cc, int type, int which, double seed, int *itp);
int cont_check_dip(cable_cont *cc);
/* A minimum of sigma_1 inside the step predicted at arclength smid (two
 * coincident crossings of the pencil test): located like cont_check_dip. */
int cont_dip_in_step(cable_cont *cc, double smid);

/* cont_pencil.c: the branch points that the linear interpolation of the
 * extended matrix between x (start of the step, closing row from
 * sys->xdot0) and the trial point (factorisation fb) predicts inside the
 * step, as fractions t in (0,1) of the step, ascending, at most tmax of
 * them.  Returns their number (a double crossing counts twice; *ndouble
 * counts those), or < 0 on error. */
int cont_pencil_alloc(cable_cont *cc);
void cont_pencil_free(cable_cont *cc);
int cont_pencil_crossings(cable_cont *cc, const abd_solver *fb, double *t, int tmax, int *ndouble);

/* cont_gate.c: the pencil test only when the tracked singular values say a
 * crossing may lie inside the step.  cont_gate_start at the start of a step
 * (keeps x's singular vectors), cont_gate_needed after the trial point's
 * tangent: 1 when the pencil test is to run. */
int cont_gate_alloc(cable_cont *cc);
void cont_gate_free(cable_cont *cc);
void cont_gate_start(cable_cont *cc);
int cont_gate_needed(cable_cont *cc);

/* cont_counts.c: the counters on stderr when the environment variable
 * CABLE_COUNTS is set (called when the run's state is freed) */
void cont_counts_report(const cable_cont *cc);

/* cont_mesh.c */
int cont_adapt_mesh(cable_cont *cc);
/* Closed loops (cont_loop.c): record the start (after the first point is
 * stored); after each accepted point, 1 when the step from the previous
 * point passed through the start again (cc->err then names it). */
int cont_loop_start(cable_cont *cc, int start_lab);
int cont_loop_closed(cable_cont *cc);
/* 1 when the current point is a located BP that is a known point (cc->err
 * then names it) */
int cont_loop_known(cable_cont *cc);
void cont_loop_free(cable_cont *cc);
double cont_error_estimate(const cable_cont *cc, const double *x);
int cont_load_solution(cable_cont *cc, const cable_solution *s);
/* CABLE_SUCCESS, or CABLE_ERR_CALLBACK when PVLS returned a negative
 * (fatal) status, here or at a trial point since the last call (the message
 * is set; the point is not stored). */
int cont_store_solution(cable_cont *cc, int itp, int lab);

/* cont_loop.c: the known branch points of from, for a handle on the problem
   restricted to Fix(S) (its extra free parameters are 0 at them) */
int cont_loop_transfer_known(const cable_cont *from, cable_cont *to);

/* cont_symmetry.c: a declared reflection on the kernel and on the branch list */
/* S v for a discretised vector (pointwise act on the nodes' states; the
   parameters unchanged) */
void cont_sym_apply(const cable_cont *cc, const cable_symmetry *sy, const double *v, double *out);
/* the odd quantity of sy at a discretised vector (u_c at t = 0 or 1; with
   act, (v - S v)_c at the end where the kernel's antisymmetric direction is
   largest, chosen by cont_sym_split into *comp, *at) */
double cont_sym_odd(const cable_cont *cc, const cable_symmetry *sy, int comp, int at, const double *v);
/* Splits the kernel span{e1, e2} (theta-orthonormal) into e_s (in Fix(S)) and
   e_a (orthogonal): *phi_s their angle from e1 (radians); *comp, *at the odd
   quantity's component and end.  0, or -1 when S does not split the kernel
   (msg says why). */
int cont_sym_split(cable_cont *cc, const cable_symmetry *sy, const double *e1, const double *e2, double *es,
                   double *ea, double *phi_s, int *comp, int *at, char *msg, size_t len);
/* Marks the directions of cc->br in a declared Fix(S) and merges those that a
   declared act maps onto each other (multiplicity) */
void cont_sym_merge(cable_cont *cc, const double *e1, const double *e2);

/* cont_restrict.c: the problem restricted to Fix(S) */
typedef struct cont_restricted cont_restricted;
/* builds it from the request in cc (rs_sym, rs_vec); NULL with msg on failure */
cont_restricted *cont_restrict_build(const cable_cont *cc, char *msg, size_t len);
const cable_problem *cont_restrict_problem(const cont_restricted *r);
const cable_constants *cont_restrict_constants(const cont_restricted *r);
/* the unfolding parameter's slot and its boundary-condition row; a one-line account */
int cont_restrict_unfold_par(const cont_restricted *r);
const char *cont_restrict_describe(const cont_restricted *r);
void cont_restrict_free(cont_restricted *r);

/* cont_switch.c: the direction of the bifurcating branch at a BP start */
int cont_switch_direction(cable_cont *cc);
/* cont_switch_direction's answer when the branch asked for lies in a declared
   Fix(S) and needs the restricted problem (cc->rs_sym, cc->rs_vec set): the
   step rebuilds the handle on it and switches again */
#define CONT_SWITCH_RESTRICT 1

/* cont_branches.c: the ABE at a double BP (x = cc->x, A = cc->J factored in
 * cc->abd with closing row theta q0^T; e1, e2 are made theta-orthonormal in
 * place, the coordinates of the directions): fills cc->br, cc->nbr (-1 when
 * degenerate, msg says why), cc->abe_order.  CABLE_SUCCESS or an error. */
int cont_branches_compute(cable_cont *cc, const double *q0, double *e1, double *e2, char *msg, size_t len);

/* cont_correct.c: the corrector and the test functions at one point */
int cont_correct(cable_cont *cc, const double *x0, const double *xdot0, double ds, double *x);
/* the same corrector from the initial guess x (on the hyperplane of ds) */
int cont_correct_from(cable_cont *cc, const double *x0, const double *xdot0, double ds, double *x);
/* CABLE_SUCCESS, or the status of a converged point whose nodes FUNC rejects
 * (cc->rejected says where) */
int cont_check_nodes(cable_cont *cc, const double *x);
void cont_tests_fill(cable_cont *cc, const double *x, const double *xdot, cont_tests *tf);

/* The handle's error text (cable_cont_error); every part of the engine sets
 * it, so it lives here rather than in one of them. */
__attribute__((format(printf, 2, 3))) static inline void cont_set_error(cable_cont *cc, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(cc->err, sizeof cc->err, fmt, ap);
  va_end(ap);
  cc->err_key[0] = '\0';
  cc->nerr++;
}

/* the same, about a constants key (cable_cont_last_error's key) */
__attribute__((format(printf, 3, 4))) static inline void cont_set_error_key(cable_cont *cc, const char *key, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(cc->err, sizeof cc->err, fmt, ap);
  va_end(ap);
  snprintf(cc->err_key, sizeof cc->err_key, "%s", key);
  cc->nerr++;
}

/* The public calls' bodies (cont_engine.c, cont_run.c); the public entry
 * points (cont_errors.c) report their errors to the handle's handler. */
int cont_step(cable_cont *cc);
int cont_set_start(cable_cont *cc, const cable_solution *start);
int cont_set_mesh(cable_cont *cc, const double *mesh);
int cont_run(cable_cont *cc, const cable_sink *sink, int ibr, int first_label, int *next_label);

#endif
