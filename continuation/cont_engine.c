/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Continuation driver: start, predictor-corrector steps, step control, limits. */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "constants_check.h"
#include "cont_impl.h"

/* Step-size control (IADS): Newton iteration counts at or below
 * CONT_FAST_ITERS mean the predictor was excellent (grow by CONT_GROW_FAST);
 * up to half of ITNW is comfortable (grow by CONT_GROW); at ITNW - 1 or more
 * the step was too ambitious (shrink by CONT_SHRINK).  A failed corrector
 * halves the step (AUTO's rule) until DSMIN. */
#define CONT_FAST_ITERS 2
#define CONT_GROW_FAST 2.0
#define CONT_GROW 1.3
#define CONT_SHRINK 0.5
/* AUTO halves the step after a failed corrector (CONT_FAIL_SHRINK), down to
 * DSMIN; a step counts as DSMIN when within CONT_DSMIN_SLACK (relative) of
 * it, so that the repeated halving, floored at DSMIN, ends exactly there in
 * spite of round-off in fmax/copysign. */
#define CONT_FAIL_SHRINK 0.5
#define CONT_DSMIN_SLACK 1.0e-12
/* PREDICTOR = 2 extrapolates the curvature of the last step over the next
 * (step_predict) only for a step at most this many times as long: the
 * curvature estimate (xdot - xdotp) / ds_used carries the tangents' errors
 * divided by ds_used, which a short last step (a located special point, a
 * rejected step) magnifies. */
#define CONT_PRED2_MAXRATIO 2.0
/* The first step of a branch switched at a branch point (ISW = -1) is
 * rejected like a failed corrector, down to DSMIN, when its converged point's
 * unit tangent lies at more than 60 degrees to the switch direction (cosine
 * below CONT_TURN_COS_MIN, in the arclength inner product): the branch
 * switched from passes through the same point, and a corrector that
 * converged onto it (or onto a branch of a nearby branch point) leaves the
 * tangent at a large angle, where the new branch's own tangent is the
 * switch direction to first order.  Measured: the link62 mode branch
 * switched at NTST 40 from the simple BP at T = 29.81 (0.12 from a double
 * one, sigma_2 = 4.8e-8) took its first step (DS = 0.05) to a point whose
 * tangent had cosine 0.35 with the switch direction, and the next step back
 * onto the flat branch, on an AMD EPYC (on another machine it stayed on the
 * branch: the BLAS's rounding decided); halved, the step stays on the
 * branch.  Only the first step: along a branch a turn of more than 60
 * degrees in one step is no sign of a jump (Bratu's fold at DSMAX = 2 in
 * tests/test_predictor.c turns that much on one branch).  AUTO-07p has no
 * such test. */
#define CONT_TURN_COS_MIN 0.5

/* The pencil test (cont_pencil.c) may shorten one step up to
 * CONT_PAIR_MAXSPLIT times, each time to the middle of its first two
 * predicted branch points, when they are more than CONT_PAIR_MINSEP of the
 * step apart; closer ones are a double branch point (or as good as one for
 * the step) and are located by minimising sigma_1 (cont_dip_in_step).
 * Predicted crossings within CONT_PAIR_EDGE of the start of a step that starts
 * at a located special point are that point itself.  Three splits shrink a
 * step at most 8-fold; the elastica pairs (DS = 35..45) need one. */
#define CONT_PAIR_MAXSPLIT 3
#define CONT_PAIR_MINSEP 1.0e-2
#define CONT_PAIR_EDGE 1.0e-2
#define CONT_PAIR_MAXCROSS 8

typedef struct {
  int n;                          /* predicted crossings in the accepted step */
  double t[CONT_PAIR_MAXCROSS];   /* their fractions of the step, ascending */
  int coincident;                 /* the first two are closer than CONT_PAIR_MINSEP */
  double tmid;                    /* the middle of the first two */
  int splits;                     /* times the step was shortened */
  double ds_first;                /* the step before the first split */
  double ds_split;                /* the step after the last split */
  int unresolved;                 /* still two separate crossings after the last split */
} pencil_result;

const char *cable_cont_error(const cable_cont *cc)
{
  return cc ? cc->err : "no continuation handle (NULL)";
}

void cable_cont_free(cable_cont *cc)
{
  if (!cc) return;
  cont_counts_report(cc);
  cont_loop_free(cc);
  colloc_newton_free(cc->nw);
  colloc_system_free(cc->sys);
  if (!cc->linalg_shared) {
    colloc_jac_free(cc->J);
    abd_solver_free(cc->abd);
  }
  cable_team_free(cc->team);   /* after the three that borrowed it */
  double *v[] = {cc->x, cc->xdot, cc->xp, cc->xdotp, cc->xt, cc->xdott, cc->w1, cc->w2, cc->w3,
                 cc->xlo, cc->xhi, cc->svec, cc->umax, cc->xq, cc->xdotq};
  for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) free(v[i]);
  cable_solution_free(cc->sol);
  cable_solution_free(cc->pvsol);
  cont_pencil_free(cc);
  cont_gate_free(cc);
  free(cc->abe_psi);
  free(cc->rs_vec);
  cont_restrict_free(cc->rs);
  free(cc);
}

static int check_input(const cable_problem *pb, const cable_constants *c, char *msg, size_t len)
{
  if (!pb || !pb->func) return snprintf(msg, len, "the problem has no FUNC"), CABLE_ERR_INPUT;
  if (pb->abi_version != CABLE_PROBLEM_ABI)
    return snprintf(msg, len, "problem ABI %d, cable expects %d", pb->abi_version, CABLE_PROBLEM_ABI),
           CABLE_ERR_INPUT;
  /* a problem struct filled by hand: sizes the engine can allocate and index
     with int (the unknowns number (NTST NCOL + 1) NDIM + NFPR) */
  if (pb->ndim < 1 || pb->nbc < 0 || pb->nint < 0 || pb->npar < 0)
    return snprintf(msg, len, "problem '%s': NDIM=%d, NBC=%d, NINT=%d, npar=%d (need NDIM >= 1, the others >= 0)",
                    pb->name ? pb->name : "?", pb->ndim, pb->nbc, pb->nint, pb->npar), CABLE_ERR_INPUT;
  /* NTST, NCOL and the other integer keys: the key table's ranges, the
     parser's rules for a file (constants filled by hand get here unchecked) */
  int rc = cable_constants_int_ranges(c, msg, len);
  if (rc) return rc;
  if ((double)pb->ndim * ((double)c->ntst * c->ncol + 1) + pb->nbc + pb->nint > (double)(INT_MAX / 16) ||
      pb->npar > INT_MAX / 16)
    return snprintf(msg, len, "problem '%s' with NTST=%d, NCOL=%d: NDIM=%d, NBC=%d, NINT=%d, npar=%d are too large",
                    pb->name ? pb->name : "?", c->ntst, c->ncol, pb->ndim, pb->nbc, pb->nint, pb->npar), CABLE_ERR_INPUT;
  if (c->ips != 4) return snprintf(msg, len, "IPS=%d: cable solves IPS=4 problems only", c->ips), CABLE_ERR_UNSUPPORTED;
  if (c->ndim && c->ndim != pb->ndim)
    return snprintf(msg, len, "NDIM=%d but problem '%s' has %d equations", c->ndim, pb->name, pb->ndim),
           CABLE_ERR_INPUT;
  if (pb->nbc > 0 && !pb->bcnd) return snprintf(msg, len, "NBC=%d but no BCND", pb->nbc), CABLE_ERR_INPUT;
  if (pb->nint > 0 && !pb->icnd) return snprintf(msg, len, "NINT=%d but no ICND", pb->nint), CABLE_ERR_INPUT;
  int nfpr = pb->nbc + pb->nint - pb->ndim + 1;
  if (nfpr < 1) return snprintf(msg, len, "NBC+NINT-NDIM+1 = %d: need at least one free parameter", nfpr), CABLE_ERR_INPUT;
  if (c->nicp < nfpr)
    return snprintf(msg, len, "ICP lists %d parameter(s); this problem needs %d free parameters (NBC+NINT-NDIM+1)",
                    c->nicp, nfpr), CABLE_ERR_INPUT;
  int npar = c->npar > pb->npar ? c->npar : pb->npar;
  for (int k = 0; k < c->nicp; k++)
    if (c->icp[k] < 0 || c->icp[k] >= npar)
      return snprintf(msg, len, "ICP entry %d is outside 1..NPAR=%d", c->icp[k] + 1, npar), CABLE_ERR_INPUT;
  if (!(c->dsmin > 0) || !(c->dsmax >= c->dsmin) || !(fabs(c->ds) > 0))
    return snprintf(msg, len, "need 0 < DSMIN <= DSMAX and DS != 0"), CABLE_ERR_INPUT;
  if (c->epsl <= 0 || c->epsu <= 0 || c->epss <= 0) return snprintf(msg, len, "EPSL, EPSU, EPSS must be positive"), CABLE_ERR_INPUT;
  if (c->stab && !pb->variational)
    return snprintf(msg, len, "STAB=1 but problem '%s' does not declare its variational structure", pb->name),
           CABLE_ERR_INPUT;
  return CABLE_SUCCESS;
}

int cable_cont_check(const cable_problem *pb, const cable_constants *c, cable_error *err)
{
  char msg[512];
  if (!pb || !c)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_cont_check: %s is NULL",
                           !pb ? "the problem" : "the constants");
  /* counts beyond their arrays and indices beyond the parameters first:
     everything below reads the arrays */
  int rc = cable_constants_consistent(c, c->npar > pb->npar ? c->npar : pb->npar, err);
  if (rc) return rc;
  rc = check_input(pb, c, msg, sizeof msg);
  if (rc) return cable_error_set(err, rc, NULL, 0, NULL, "%s", msg);
  if (err) cable_error_clear(err);
  return CABLE_SUCCESS;
}

cable_cont *cable_cont_alloc(const cable_problem *pb, const cable_constants *c, int *status)
{
  int dummy;
  if (!status) status = &dummy;
  int rc = cable_cont_check(pb, c, NULL);
  if (rc) {
    *status = rc;
    return NULL;
  }
  cable_cont *cc = calloc(1, sizeof *cc);
  if (cc) cc->nbr = -1;
  if (cc) cc->rs_sym = -1;
  if (!cc) {
    *status = CABLE_ERR_ALLOC;
    return NULL;
  }
  cc->pb = pb;
  cc->c = c;   /* by pointer: the caller keeps it (cable_cont.h) */
  cc->ndim = pb->ndim;
  cc->npar = c->npar > pb->npar ? c->npar : pb->npar;
  cc->nfpr = pb->nbc + pb->nint - pb->ndim + 1;
  cc->ntst = c->ntst;
  cc->ncol = c->ncol;
  /* One thread team per handle, of the run's thread count: the Newton
     solver's and the tangent's factorisations and solves and (when the
     problem's loops have as many workers) the residual and Jacobian loops use
     it in turn.  Every team job ends on the engine's thread before the next
     starts and none starts another (no nesting), and a loop's partition
     depends only on the team's size: the same bits as with a team each. */
  int nthreads = cable_threads(c);
  if (nthreads > 1 && !(cc->team = cable_team_alloc(nthreads))) {
    rc = CABLE_ERR_ALLOC;
    goto fail;
  }
  cc->sys = colloc_system_alloc_team(pb, c, c->ntst, c->ncol, c->icp, cc->nfpr, cc->team, &rc);
  if (!cc->sys) goto fail;
  cc->n = cc->sys->n;
  cc->nw = colloc_newton_alloc_team(cc->sys, c, cc->team, &rc);
  if (!cc->nw) goto fail;
  rc = CABLE_ERR_ALLOC;
  /* the tangents and test functions factor in the Newton solver's storage
     (its matrix and structured solver; one set instead of two: 26 MB less on
     the flat (7,2) knot at NTST 150); with KLU they have their own */
  if (colloc_newton_storage(cc->nw, &cc->abd, &cc->J) == 0) {
    cc->linalg_shared = 1;
  } else {
    cc->J = colloc_jac_alloc(cc->ndim, cc->ntst, cc->ncol, cc->nfpr, pb->nbc, pb->nint);
    cc->abd = abd_solver_alloc(cc->ndim, cc->ntst, cc->ncol, cc->nfpr, pb->nbc, pb->nint);
    if (cc->abd && cc->team) abd_solver_use_team(cc->abd, cc->team);
    else if (cc->abd) abd_solver_set_threads(cc->abd, nthreads);
  }
  size_t n = (size_t)cc->n;
  cc->x = calloc(n, sizeof(double)); cc->xdot = calloc(n, sizeof(double));
  cc->xp = calloc(n, sizeof(double)); cc->xdotp = calloc(n, sizeof(double));
  cc->xt = calloc(n, sizeof(double)); cc->xdott = calloc(n, sizeof(double));
  cc->w1 = calloc(n, sizeof(double)); cc->w2 = calloc(n, sizeof(double)); cc->w3 = calloc(n, sizeof(double));
  cc->xlo = calloc(n, sizeof(double)); cc->xhi = calloc(n, sizeof(double));
  cc->svec = calloc(3 * n, sizeof(double)); /* up to three singular vectors (switching) */
  if (cont_pencil_alloc(cc) != CABLE_SUCCESS || cont_gate_alloc(cc) != CABLE_SUCCESS) goto fail;
  cc->xq = calloc(n, sizeof(double)); cc->xdotq = calloc(n, sizeof(double));
  cc->umax = calloc((size_t)cc->ndim, sizeof(double));
  cc->sol = cable_solution_alloc(cc->ndim, cc->ntst, cc->ncol, cc->npar, cc->nfpr);
  if (!cc->J || !cc->abd || !cc->x || !cc->xdot || !cc->xp || !cc->xdotp || !cc->xt || !cc->xdott ||
      !cc->w1 || !cc->w2 || !cc->w3 || !cc->xlo || !cc->xhi || !cc->svec || !cc->umax || !cc->sol || !cc->xq || !cc->xdotq)
    goto fail;
  /* a user zero on a parameter that is not free is a value PVLS computes
     (AUTO calls PVLS before its test functions): PVLS runs at every point
     the test functions are evaluated at */
  int uz_pvls = 0;
  for (int k = 0; k < c->nuzr; k++) {
    int free_par = 0;
    for (int q = 0; q < cc->nfpr; q++) free_par |= c->icp[q] == c->uzr[k].par;
    uz_pvls |= !free_par;
  }
  if (uz_pvls && pb->pvls) {
    cc->pvsol = cable_solution_alloc(cc->ndim, cc->ntst, cc->ncol, cc->npar, cc->nfpr);
    if (!cc->pvsol) goto fail;
  }
  cc->ds = c->ds;
  cc->uz_hit = -1;
  *status = CABLE_SUCCESS;
  return cc;
fail:
  /* a constructor returns a usable object or nothing: undo what was built */
  *status = rc ? rc : CABLE_ERR_ALLOC;
  cable_cont_free(cc);
  return NULL;
}

static double principal(const cable_cont *cc, const double *x)
{
  return x[cc->n - cc->nfpr];
}

/* The free parameter a STPNT start is converged and its direction computed
 * at: the principal one, except on a fold curve (ISW = 2), where it is the
 * second parameter q.  At a simple LP the fold system at fixed q is regular
 * (<psi, F_p1> != 0 because the LP is a regular point of its branch), at
 * fixed p1 only where the fold curve does not turn in p1: it does at a
 * symmetric problem's fold (AUTO's demo int, q = PAR(2) in u(0) - u(1) = q,
 * whose fold curve is even in q). doc/fold-continuation.md. */
static int start_fixpar(const cable_cont *cc)
{
  return (cc->c->isw == 2 || cc->c->isw == -2) && cc->nfpr >= 2 ? 1 : 0;
}

/* A start direction computed at fixed q is oriented as the one at fixed p1
 * was (p1 increasing) wherever p1 moves along it; where it does not (to
 * round-off), q increases. */
#define START_P1_MOVES 1e-6
static void orient_start_direction(cable_cont *cc, int fix)
{
  if (fix == 0) return;
  double p1 = cc->xdot[cc->n - cc->nfpr], q = cc->xdot[cc->n - cc->nfpr + fix];
  double lead = fabs(p1) > START_P1_MOVES ? p1 : q;
  if (lead < 0)
    for (int i = 0; i < cc->n; i++) cc->xdot[i] = -cc->xdot[i];
}

/* The first point: converge a STPNT start at fixed principal parameter (q on
 * a fold curve), or take a stored solution as it is; then its tangent and
 * test functions. */
static void check_limits(cable_cont *cc);

/* The switch asked for the problem restricted to Fix(S) (cont_restrict.c):
 * a handle on it is built, given the branch point (the same mesh, the
 * solution, the parameters, eps = 0; the known branch's tangent with eps' =
 * 0), the caller's error handler and known points, and swapped into *cc, so
 * that the caller's handle runs the restricted branch; then the switch is
 * made there, where the branch point is simple. */
static int restrict_in_place(cable_cont *cc)
{
  char why[300] = "";
  cont_restricted *r = cont_restrict_build(cc, why, sizeof why);
  if (!r) {
    cont_set_error(cc, "ISW=-1: cannot restrict to the symmetric branch: %s", why);
    return CABLE_ERR_SWITCH;
  }
  int st = 0;
  cable_cont *nc = cable_cont_alloc(cont_restrict_problem(r), cont_restrict_constants(r), &st);
  if (!nc) {
    cont_restrict_free(r);
    cont_set_error(cc, "ISW=-1: the restricted problem: %s", cable_status_message(st));
    return st;
  }
  nc->rs = r;
  int nu = cc->n - cc->nfpr;
  memcpy(nc->sys->mesh, cc->sys->mesh, (size_t)(cc->ntst + 1) * sizeof *nc->sys->mesh);
  memcpy(nc->sys->par, cc->sys->par, (size_t)cc->npar * sizeof *nc->sys->par);
  int up = cont_restrict_unfold_par(r);
  nc->sys->par[up] = 0.0;
  memcpy(nc->x, cc->x, (size_t)nu * sizeof *nc->x);
  memcpy(nc->xdot, cc->xdot, (size_t)nu * sizeof *nc->xdot);
  for (int q = 0; q < nc->nfpr; q++) {
    nc->x[nu + q] = nc->sys->par[nc->sys->icp[q]];
    nc->xdot[nu + q] = q < cc->nfpr ? cc->xdot[nu + q] : 0.0;
  }
  nc->have_start = 1;
  nc->started = 1;
  nc->restart = cc->restart;
  nc->switch_pending = 1;
  nc->loop.start_lab = cc->loop.start_lab;
  nc->on_error = cc->on_error;
  nc->on_error_ctx = cc->on_error_ctx;
  memcpy(nc->br, cc->br, sizeof nc->br);
  nc->nbr = cc->nbr;
  nc->abe_order = cc->abe_order;
  if (cont_loop_transfer_known(cc, nc) != CABLE_SUCCESS) {
    cable_cont_free(nc);
    cont_set_error(cc, "ISW=-1: out of memory");
    return CABLE_ERR_ALLOC;
  }
  char old_note[sizeof cc->note];
  memcpy(old_note, cc->note, sizeof old_note);
  cable_cont tmp = *cc;
  *cc = *nc;
  *nc = tmp;
  cable_cont_free(nc);   /* the unrestricted handle's parts */
  int rc = cont_switch_direction(cc);
  char sw[sizeof cc->note];
  memcpy(sw, cc->note, sizeof sw);
  snprintf(cc->note, sizeof cc->note, "%s; %s; there %s", old_note, cont_restrict_describe(cc->rs), sw);
  return rc;
}

static int first_point(cable_cont *cc)
{
  colloc_system *s = cc->sys;
  int rc;
  cc->started = 1;
  int fix = cc->restart ? 0 : start_fixpar(cc);
  if (!cc->restart) {
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixpar = fix;
    s->fixval = cc->x[cc->n - cc->nfpr + fix];
    rc = colloc_newton_solve(cc->nw, cc->x);
    s->fixpar = 0;
    cc->newton_iters = colloc_newton_iterations(cc->nw);
    cc->rejected[0] = '\0';
    if (rc == CABLE_SUCCESS) rc = cont_check_nodes(cc, cc->x);
    if (rc != CABLE_SUCCESS) {
      cont_set_error(cc, "the starting solution did not converge (%s; %s)", cable_status_message(rc),
                     cc->rejected[0] ? cc->rejected : colloc_newton_message(cc->nw));
      cc->ended = 1;
      return cc->end_status = rc == CABLE_ERR_CALLBACK ? rc : CABLE_ERR_NEWTON;
    }
    snprintf(cc->note, sizeof cc->note, "start: Newton converged in %d iterations, max |F| = %.3e",
             cc->newton_iters, colloc_newton_residual(cc->nw));
  } else if (cc->restart_moved) {
    /* PAR changed parameters of the stored solution (cont_run.c): Newton in
       the plane through it normal to its stored direction (a zero step of
       the arclength equation, which stays regular at a fold), or at fixed
       principal parameter when it has none */
    int dir = 0;
    for (int i = 0; i < cc->n; i++) dir |= cc->xdot[i] != 0.0;
    if (dir) {
      cont_normalize(cc, cc->xdot);
      rc = cont_correct_from(cc, cc->x, cc->xdot, 0.0, cc->x);
    } else {
      s->closing = COLLOC_CLOSE_FIXPAR;
      s->fixpar = 0;
      s->fixval = principal(cc, cc->x);
      rc = colloc_newton_solve(cc->nw, cc->x);
      cc->newton_iters = colloc_newton_iterations(cc->nw);
      cc->rejected[0] = '\0';
      if (rc == CABLE_SUCCESS) rc = cont_check_nodes(cc, cc->x);
    }
    if (rc != CABLE_SUCCESS) {
      cont_set_error(cc, "the restart with the parameters PAR changed did not converge (%s; %s)",
                     cable_status_message(rc), cc->rejected[0] ? cc->rejected : colloc_newton_message(cc->nw));
      cc->ended = 1;
      return cc->end_status = rc == CABLE_ERR_CALLBACK ? rc : CABLE_ERR_NEWTON;
    }
    snprintf(cc->note, sizeof cc->note,
             "restart: PAR changed the stored solution's parameters; Newton converged in %d iterations, max |F| = %.3e",
             cc->newton_iters, colloc_newton_residual(cc->nw));
  } else if (!cc->switch_pending) {
    /* a restart is taken as stored (AUTO): its residual shows whether it
       still solves the problem with this run's parameters */
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixval = principal(cc, cc->x);
    double r = colloc_system_residual(s, cc->x, cc->w1) == 0 ? 0.0 : HUGE_VAL;
    for (int i = 0; i < cc->n && r < HUGE_VAL; i++) r = fmax(r, fabs(cc->w1[i]));
    snprintf(cc->note, sizeof cc->note, "restart: stored solution taken without Newton, max |F| = %.3e", r);
  }
  int have_dir = 0;
  for (int i = 0; i < cc->n; i++)
    if (cc->xdot[i] != 0.0) have_dir = 1;
  if (cc->switch_pending) {
    rc = cont_switch_direction(cc);
    if (rc == CONT_SWITCH_RESTRICT) rc = restrict_in_place(cc);
    if (rc != CABLE_SUCCESS) {
      cc->ended = 1;
      return cc->end_status = rc;
    }
  } else if (!have_dir) {
    /* tangent at fixed principal parameter: the closing row is e_p0, rhs e_last
       (on a fold curve at fixed q, restarts included: a fold curve restarted
       from its starting data has no usable direction, and at fixed p1 its
       start is singular where the curve turns in p1) */
    fix = start_fixpar(cc);
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixpar = fix;
    rc = cont_factor_at(cc, cc->x, NULL, NULL);
    s->fixpar = 0;
    if (rc != CABLE_SUCCESS) {
      cont_set_error(cc, "cannot compute a direction at the starting point: %s", cable_status_message(rc));
      cc->ended = 1;
      return cc->end_status = CABLE_ERR_LINSOLVE;
    }
    memset(cc->xdot, 0, (size_t)cc->n * sizeof *cc->xdot);
    cc->xdot[cc->n - 1] = 1.0; /* rhs: last equation is the closing row */
    abd_solver_solve(cc->abd, cc->xdot);
    cont_normalize(cc, cc->xdot);
    orient_start_direction(cc, fix);
    if (cc->c->ds < 0) for (int i = 0; i < cc->n; i++) cc->xdot[i] = -cc->xdot[i];
    cc->ds = fabs(cc->c->ds);
  } else {
    /* a stored direction; DS < 0 reverses it (AUTO) */
    cont_normalize(cc, cc->xdot);
    if (cc->c->ds < 0) for (int i = 0; i < cc->n; i++) cc->xdot[i] = -cc->xdot[i];
    cc->ds = fabs(cc->c->ds);
  }
  /* test functions with the tangent itself as closing row */
  rc = cont_tangent(cc, cc->x, cc->xdot, cc->w3, &cc->tf);
  if (rc == CABLE_ERR_LINSOLVE && cc->switch_pending) {
    /* At a branch point [F_x; theta phi^T] is singular for every phi: the old
       tangent stays in its kernel (and at a double BP a kernel direction
       does too); it is only numerically regular because the BP was located
       to EPSS.  An exactly singular one (the uncoupled double elastica
       hits one) has no determinant sign: the start gets none, so the first
       step counts no BP sign change. */
    memset(&cc->tf, 0, sizeof cc->tf);
    cont_tests_fill(cc, cc->x, cc->xdot, &cc->tf);
    rc = CABLE_SUCCESS;
  }
  if (rc != CABLE_SUCCESS) {
    cont_set_error(cc, "no test functions at the starting point: %s", cable_status_message(rc));
    cc->ended = 1;
    return cc->end_status = CABLE_ERR_LINSOLVE;
  }
  cc->npt = 1;
  cc->ds_used = 0.0;
  /* AUTO labels the first point of a run EP only when it is a new start: a
     restart, the switched first point at a branch point (ISW = -1) included,
     is not labelled (auto-07p, demo lin: run 2 from BP1 has no EP at PT 1),
     nor is the LP that a fold curve's starting data (ISW = -2) start from */
  cc->itp = !cc->restart && cc->c->isw != -2 ? CABLE_TY_EP : CABLE_TY_NONE;
  cc->switched_start = cc->switch_pending;
  cc->switch_pending = 0;
  if ((rc = cont_store_solution(cc, cc->itp, 0)) != CABLE_SUCCESS) {
    cc->npt = 0;   /* nothing to store as MX */
    cc->ended = 1;
    return cc->end_status = rc;
  }
  return cont_loop_start(cc, cc->loop.start_lab);
}

/* After a point is accepted: end the branch at NMX, outside RL0..RL1 or
 * A0..A1 (AUTO's limits), or at a user zero with UZSTOP.  The point itself
 * stays valid; the next step returns the end status. */
static void check_limits(cable_cont *cc)
{
  double p0 = principal(cc, cc->x), m = cc->pt.measure;   /* A0, A1 bound IPLT's measure, as in AUTO */
  int end = 0;
  if (cc->uz_stop) end = CABLE_END_UZSTOP;
  else if (p0 < cc->c->rl0 || p0 > cc->c->rl1 || m < cc->c->a0 || m > cc->c->a1) end = CABLE_END_BOUNDS;
  else if (cont_loop_closed(cc)) end = CABLE_END_LOOP;   /* before NMX: the reason that says more */
  else if (cont_loop_known(cc)) end = CABLE_END_LOOP;
  else if (cc->c->nmx > 0 && cc->npt >= cc->c->nmx) end = CABLE_END_NMX;
  if (!end) return;
  if (end != CABLE_END_UZSTOP && cc->itp == CABLE_TY_NONE) {
    cc->itp = CABLE_TY_EP;
    cc->pt.itp = CABLE_TY_EP;
    cc->sol->itp = CABLE_TY_EP;
  }
  cc->ended = 1;
  cc->end_status = end;
}

static void swap_ptr(double **a, double **b)
{
  double *t = *a;
  *a = *b;
  *b = t;
}

/* The next step from a step of length ds_taken whose corrector took it
 * iterations. */
static void control_step(cable_cont *cc, int it, double ds_taken)
{
  if (cc->c->iads <= 0 || cc->npt % cc->c->iads != 0) return;
  int itnw = cc->c->itnw;
  double a = fabs(ds_taken) > 0 ? fabs(ds_taken) : fabs(cc->ds);
  if (it <= CONT_FAST_ITERS) a *= CONT_GROW_FAST;
  else if (it <= itnw / 2) a *= CONT_GROW;
  else if (it >= itnw - 1) a *= CONT_SHRINK;
  a = fmin(fmax(a, cc->c->dsmin), cc->c->dsmax);
  cc->ds = copysign(a, cc->ds);
}

/* Make the trial point (xt, xdott, tft) the current point. */
static void accept_trial(cable_cont *cc)
{
  swap_ptr(&cc->xp, &cc->x);
  swap_ptr(&cc->x, &cc->xt);
  swap_ptr(&cc->xdotp, &cc->xdot);
  swap_ptr(&cc->xdot, &cc->xdott);
  cc->tfp = cc->tf;
  cc->tf = cc->tft;
  cc->npt++;
}

/* The predictor of a step of length ds from x into xt.  PREDICTOR = 1 is
 * AUTO's tangent predictor x + ds xdot, with an error of order ds^2 along the
 * branch's curvature.  PREDICTOR = 2 adds the second-order Taylor term with
 * the curvature estimated from the last step, x'' ~ (xdot - xdotp) / ds_used
 * (both unit tangents along the signed arclength), leaving an error of order
 * ds^3 (doc/engine.md, "The second-order predictor"): where the tangent
 * predictor's first correction is large, Newton needs one iteration less,
 * and the step control (IADS) lets the steps grow.  The first step of a
 * branch, a step after a reversal of direction, and a step more than
 * CONT_PRED2_MAXRATIO times the last use the tangent predictor. */
static void step_predict(cable_cont *cc, double ds, double *xt)
{
  const int n = cc->n;
  double c2 = 0.0;
  if (cc->c->predictor == 2 && cc->npt >= 2 && cc->ds_used * ds > 0.0 &&
      fabs(ds) <= CONT_PRED2_MAXRATIO * fabs(cc->ds_used))
    c2 = 0.5 * ds * ds / cc->ds_used;
  for (int i = 0; i < n; i++) xt[i] = cc->x[i] + ds * cc->xdot[i];
  if (c2 != 0.0)
    for (int i = 0; i < n; i++) xt[i] += c2 * (cc->xdot[i] - cc->xdotp[i]);
}

/* The pencil test at a converged trial point (ISP > 0).  Returns 1 when the
 * step is to be repeated with the shorter *ds_step, to separate the first
 * group of predicted branch points from the next. */
static int pencil_step(cable_cont *cc, pencil_result *pr, double *ds_step)
{
  pr->n = 0;
  pr->coincident = pr->unresolved = 0;
  if (!cont_bp_detect(cc) || !cc->tan_abd) return 0;
  if (!cont_gate_needed(cc)) return 0;
  double t[CONT_PAIR_MAXCROSS];
  int ndouble = 0, nc = cont_pencil_crossings(cc, cc->tan_abd, t, CONT_PAIR_MAXCROSS, &ndouble);
  if (nc < 0) return 0; /* the test is advisory: the determinant test still runs */
  int at_special = cc->dip_at_x || cc->itp_x != CABLE_TY_NONE;
  for (int i = 0; i < nc; i++)
    if (!(at_special && t[i] < CONT_PAIR_EDGE)) pr->t[pr->n++] = t[i];
  if (pr->n < 2) return 0;
  /* the first group: crossings closer than CONT_PAIR_MINSEP to their predecessor */
  int g = 1;
  while (g < pr->n && pr->t[g] - pr->t[g - 1] <= CONT_PAIR_MINSEP) g++;
  if (g == pr->n) {
    pr->coincident = 1;
    pr->tmid = 0.5 * (pr->t[0] + pr->t[g - 1]);
    return 0;
  }
  if (pr->splits >= CONT_PAIR_MAXSPLIT) {
    pr->unresolved = 1;
    return 0;
  }
  if (pr->splits++ == 0) pr->ds_first = *ds_step;
  *ds_step *= 0.5 * (pr->t[g - 1] + pr->t[g]);
  pr->ds_split = *ds_step;
  return 1;
}

static void append_note(cable_cont *cc, const char *text)
{
  size_t len = strlen(cc->note);
  snprintf(cc->note + len, sizeof cc->note - len, "%s%s", len ? "; " : "", text);
}

static void pencil_note(cable_cont *cc, const pencil_result *pr)
{
  char buf[240];
  if (pr->splits > 0) {
    snprintf(buf, sizeof buf, "step DS = %.6g shortened to %.6g: the pencil test predicted more than one branch point in it",
             pr->ds_first, pr->ds_split);
    append_note(cc, buf);
  }
  if (pr->unresolved) {
    int len = snprintf(buf, sizeof buf, "the pencil test still predicts %d branch points in this step (at", pr->n);
    for (int i = 0; i < pr->n && len < (int)sizeof buf - 24; i++)
      len += snprintf(buf + len, sizeof buf - (size_t)len, " %.4f", pr->t[i]);
    snprintf(buf + len, sizeof buf - (size_t)len, " of it): not all are located");
    append_note(cc, buf);
  }
}

int cont_step(cable_cont *cc)
{
  if (!cc) return CABLE_ERR_NULL;
  if (cc->ended) return cc->end_status;
  if (!cc->have_start) {
    cont_set_error(cc, "cable_cont_step before cable_cont_set_start");
    return CABLE_ERR_STATE;
  }
  if (!cc->started) return first_point(cc);
  int rc;
  cc->cnt.steps++;
  cc->note[0] = '\0';
  if (cc->queued) {
    /* the point computed before a located dip */
    swap_ptr(&cc->xt, &cc->xq);
    swap_ptr(&cc->xdott, &cc->xdotq);
    cc->tft = cc->tfq;
    cc->queued = 0;
    cc->itp = cc->itp_x = cc->itp_q;
    cc->dip_at_x = 0;
    if (cc->itp_q != CABLE_TY_NONE) {
      /* the second special point located in one step (cont_locate_events) */
      cc->ds_prev = cc->ds_used;
      cc->ds_used = cc->ds_q;
      cc->bp_kind = cc->bp_kind_q;
      cc->uz_hit = cc->uz_hit_q;
      cc->uz_stop = cc->uz_stop_q;
      cc->itp_q = CABLE_TY_NONE;
    }
    accept_trial(cc);
    if ((rc = cont_store_solution(cc, cc->itp, 0)) != CABLE_SUCCESS) {
      cc->ended = 1;
      return cc->end_status = rc;
    }
    check_limits(cc);
    return CABLE_SUCCESS;
  }
  double ds_step = cc->ds;
  pencil_result pr = {0};
  cont_gate_start(cc);
  /* AUTO reports no special point in the first step of a run: neither the
     start (on a UZR value, or the BP a switch starts from, where the test
     functions vanish) nor a crossing inside the step.  The test functions
     at the end of the first step are the reference for the second. */
  int first_step = cc->npt == 1;
  for (;;) {
    step_predict(cc, ds_step, cc->xt);
    rc = cont_correct_from(cc, cc->x, cc->xdot, ds_step, cc->xt);
    if (rc == CABLE_SUCCESS) rc = cont_tangent_after_newton(cc, cc->xt, cc->xdot, cc->xdott, &cc->tft);
    if (rc == CABLE_SUCCESS && first_step && cc->switched_start &&
        fabs(ds_step) > cc->c->dsmin * (1.0 + CONT_DSMIN_SLACK)) {
      double turn = colloc_system_inner(cc->sys, cc->xdot, cc->xdott);
      if (turn < CONT_TURN_COS_MIN) {
        snprintf(cc->rejected, sizeof cc->rejected,
                 "its tangent lies at %.0f degrees to the switch direction (another branch?)",
                 acos(fmax(-1.0, turn)) * 180.0 / acos(-1.0));
        rc = CABLE_ERR_RECOVERABLE;
      }
    }
    if (rc == CABLE_SUCCESS && !first_step && pencil_step(cc, &pr, &ds_step))
      continue; /* a shorter step separates a pair */
    if (rc == CABLE_SUCCESS) break;
    if (rc == CABLE_ERR_CALLBACK) {
      cont_set_error(cc, "a problem callback failed fatally (status %d) at step size %g",
                     cc->sys->last_callback, ds_step);
      cc->ended = 1;
      return cc->end_status = rc;
    }
    if (fabs(ds_step) <= cc->c->dsmin * (1.0 + CONT_DSMIN_SLACK)) {
      cont_set_error(cc, "no convergence with DSMIN = %g after point %d (%s)", cc->c->dsmin, cc->npt,
                     cc->rejected[0] ? cc->rejected : colloc_newton_message(cc->nw));
      cc->ended = 1;
      cc->itp = CABLE_TY_MX;
      return cc->end_status = CABLE_ERR_DSMIN;
    }
    if (cc->rejected[0])
      snprintf(cc->note, sizeof cc->note, "step DS = %g rejected: %s", ds_step, cc->rejected);
    cc->ds = ds_step = copysign(fmax(fabs(ds_step) * CONT_FAIL_SHRINK, cc->c->dsmin), ds_step);
  }
  cc->ds_prev = cc->ds_used;
  cc->ds_used = ds_step;
  int step_iters = cc->newton_iters;
  cc->itp = CABLE_TY_NONE;
  cc->uz_hit = -1;
  int which = -1, type = first_step ? CABLE_TY_NONE : cont_find_event(cc, &cc->tf, &cc->tft, &which);
  /* a located special point sits at a zero of a test function: a dip of the
     singular value there is the point itself, not a new one */
  int was_dip = cc->dip_at_x || cc->itp_x != CABLE_TY_NONE;
  cc->dip_at_x = 0;
  if (type != CABLE_TY_NONE) {
    /* the pencil's first predicted crossing seeds the BP location */
    double seed = type == CABLE_TY_BP && pr.n > 0 ? pr.t[0] * ds_step : (double)NAN;
    int itp;
    rc = cont_locate_events(cc, type, which, seed, &itp); /* replaces the trial point by the located one */
    if (rc == CABLE_SUCCESS) cc->itp = itp;
    /* only a failure's message: cc->err keeps the last failure of the run,
       which a point located later must not inherit */
    if (rc != CABLE_SUCCESS) snprintf(cc->note, sizeof cc->note, "%s", cc->err);
  } else if (pr.coincident && cont_dip_in_step(cc, pr.tmid * ds_step) == CABLE_SUCCESS && cc->queued) {
    cc->itp = CABLE_TY_BP;
    cc->dip_at_x = 1;
  } else if (!first_step && !was_dip && cont_check_dip(cc) == CABLE_SUCCESS && cc->queued) {
    cc->itp = CABLE_TY_BP;
    cc->dip_at_x = 1;
  }
  pencil_note(cc, &pr);
  accept_trial(cc);
  cc->itp_x = cc->itp;
  /* After a located dip the next step starts from the trial point queued
     behind it, which the whole step reached with the step's own corrector.
     The minimisation's last corrector (many iterations, or a failure, next
     to the singular point) says nothing about the step: judged by it, the
     step after every double branch point of the flat (7,2) knot was halved
     and grew back over four steps. */
  if (cc->queued) control_step(cc, step_iters, ds_step);
  else control_step(cc, cc->newton_iters, cc->ds_used);
  /* output first: the stored solution is the converged one on its own mesh;
     the new mesh's interpolant is only the next corrector's start (AUTO
     writes its point before ADAPT too) */
  if ((rc = cont_store_solution(cc, cc->itp, 0)) != CABLE_SUCCESS) {
    cc->ended = 1;
    return cc->end_status = rc;
  }
  check_limits(cc);
  if (!cc->ended && cc->c->iad > 0 && !cc->queued && ++cc->nstep_adapt >= cc->c->iad) {
    cc->nstep_adapt = 0;
    if ((rc = cont_adapt_mesh(cc)) != CABLE_SUCCESS) {
      cc->ended = 1;
      return cc->end_status = rc;
    }
  }
  return CABLE_SUCCESS;
}

const cable_solution *cable_cont_solution(const cable_cont *cc) { return cc && cc->npt > 0 ? cc->sol : NULL; }
const cable_point *cable_cont_point(const cable_cont *cc) { return cc && cc->npt > 0 ? &cc->pt : NULL; }
