/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The discretised boundary-value problem: orthogonal collocation of
 *   u' = f(u, p), b(u(0), u(1), p) = 0, int_0^1 q(u, p) dt = 0,
 * plus one closing equation (the principal parameter fixed, or AUTO's
 * pseudo-arclength equation), as a square nonlinear system F(x) = 0 in the
 * unknowns x of continuation/colloc_jac.h.
 *
 * Collocation rows are scaled by the interval length h_j:
 *   sum_k l_k'(c_m) u_{j,k} - h_j f(u(t_j + c_m h_j)) = 0,
 * so that Jacobian entries are O(1) whatever the mesh. */
#ifndef CABLE_COLLOC_SYSTEM_H
#define CABLE_COLLOC_SYSTEM_H

#include "cable/cable_constants.h"
#include "cable/cable_problem.h"
#include "colloc_basis.h"
#include "colloc_jac.h"

typedef enum {
  COLLOC_CLOSE_FIXPAR = 0,   /* par[icp[fixpar]] = fixval */
  COLLOC_CLOSE_ARCLENGTH = 1 /* <x - x0, xdot0>_theta = ds */
} colloc_closing;

/* Scratch of one thread's share of the mesh intervals (the per-interval
 * passes of the residual and the Jacobian run on a team of threads when the
 * problem is concurrent; colloc_system.c). */
typedef struct colloc_work {
  double *u, *du, *f, *fp;    /* [ndim] */
  double *dfdu;               /* [ndim * ndim] */
  double *dfdp;               /* [ndim * npar] */
  double *par;                /* [npar] a copy of the system's parameters (differences perturb it) */
  long nfunc;                 /* FUNC calls of the current pass */
  int rc;                     /* first nonzero callback status of the current pass, 0 if none */
  int last_callback;          /* the system's last_callback value that goes with rc */
} colloc_work;

struct cable_team;

typedef struct colloc_system {
  const cable_problem *pb;
  int ndim, ntst, ncol, nbc, nint, npar, nfpr;
  int n;                      /* unknowns */
  int icp[CABLE_MAX_ICP];     /* free parameters (0-based), nfpr of them */
  int use_jac_func, use_jac_bcnd, use_jac_icnd; /* analytic derivatives in use */
  int fd_par;                 /* JAC=-1 (AUTO's meaning): analytic derivatives with respect
                                 to u only, parameter derivatives by central differences */
  colloc_basis basis;
  double *mesh;               /* [ntst+1] */
  double *par;                /* [npar] all parameters; free ones overwritten from x */
  /* closing equation */
  colloc_closing closing;
  int fixpar;                 /* which free parameter FIXPAR fixes (0: the principal one) */
  double fixval;
  double ds;
  double *x0, *xdot0;         /* [n] previous point and its tangent */
  double *thu;                /* [ndim] weights of u components */
  double *thl;                /* [nfpr] weights of the free parameters */
  /* counters */
  long nfunc, njac;
  int last_callback;          /* last nonzero callback return, 0 if none */
  /* threads: the collocation intervals are split into nwork contiguous
     chunks [k ntst / nwork, (k+1) ntst / nwork), chunk k computed with work[k]
     on thread k of team (NULL: one thread; then nwork = 1).  nwork > 1 only
     for a concurrent problem (cable_problem.concurrent) and NTHREADS > 1.
     Each interval's arithmetic is the same whatever the chunk, so the
     results do not depend on the number of threads. */
  int nwork;
  colloc_work *work;          /* [nwork] (owned) */
  struct cable_team *team;    /* NULL when nwork = 1 */
  int team_borrowed;          /* 1: the caller's (colloc_system_alloc_team), not freed here */
  /* workspace (owned) */
  double *w_u, *w_fb, *w_fbp, *w_dbc;
  double *w_fi, *w_fip, *w_dint, *w_uold, *w_udot, *w_upold;
  double *w_parp;             /* [npar] perturbed parameters */
} colloc_system;

/* nfpr = nbc + nint - ndim + 1 free parameters icp[0..nfpr-1]. */
colloc_system *colloc_system_alloc(const cable_problem *pb, const cable_constants *c,
                                   int ntst, int ncol, const int *icp, int nfpr, int *status);
/* The same with the caller's thread team t (may be NULL), used when its size
 * is the system's worker count (else the system builds its own); t outlives
 * the system. */
colloc_system *colloc_system_alloc_team(const cable_problem *pb, const cable_constants *c, int ntst, int ncol,
                                        const int *icp, int nfpr, struct cable_team *t, int *status);
void colloc_system_free(colloc_system *s);

/* Uniform mesh. */
void colloc_system_uniform_mesh(colloc_system *s);

/* Residual F(x) into F[n].  Returns 0, or the callback's nonzero status. */
int colloc_system_residual(colloc_system *s, const double *x, double *F);
/* Newton matrix at x into J (closing row included).  0 or callback status. */
int colloc_system_jacobian(colloc_system *s, const double *x, colloc_jac *J);

/* FUNC (values only) at every stored node of x, mesh points included: Gauss
 * collocation evaluates FUNC only between the mesh points, so a converged x
 * can hold node values outside the problem's domain that no residual saw.
 * Returns 0, or the first nonzero callback status (1 for NaN/Inf) with the
 * node's index in *node. */
int colloc_system_check_nodes(colloc_system *s, const double *x, int *node);

/* Weighted inner product <a, b>_theta over u (node quadrature) and free parameters. */
double colloc_system_inner(const colloc_system *s, const double *a, const double *b);

/* Node times t[k], k = 0..ntst*ncol, into t (the s-file's time column). */
void colloc_system_times(const colloc_system *s, double *t);

/* Pointer to u at node k of interval j inside x. */
static inline double *colloc_node(const colloc_system *s, double *x, int j, int k)
{
  return x + (size_t)(j * s->ncol + k) * (size_t)s->ndim;
}
/* Free parameters inside x. */
static inline double *colloc_params(const colloc_system *s, double *x)
{
  return x + (size_t)s->ndim * (size_t)(s->ntst * s->ncol + 1);
}

#endif
