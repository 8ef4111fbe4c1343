/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Test helper: run the engine on a problem and keep every point and every
 * labelled solution in memory. */
#ifndef CABLE_TEST_ENGINE_UTIL_H
#define CABLE_TEST_ENGINE_UTIL_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cable/cable_cont.h"

#define MEMRUN_MAX 2000
#define MEMRUN_NPAR 36

typedef struct {
  int n;
  int itp[MEMRUN_MAX], lab[MEMRUN_MAX], newton[MEMRUN_MAX];
  int bp_kind[MEMRUN_MAX], bp_mult[MEMRUN_MAX];   /* the points' structured BP fields */
  double par[MEMRUN_MAX][MEMRUN_NPAR];
  double l2[MEMRUN_MAX];
  int nsol;
  cable_solution *sol[MEMRUN_MAX];
  int status;
  char err[512];
} memrun;



/* AUTO defaults with the fields every engine test sets: mesh, ICP=[PAR(1)],
 * analytic Jacobians, no mesh adaptation. */
static inline void engine_constants(cable_constants *c, int ntst, int ncol)
{
  cable_constants_init(c); c->ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c->ntst = ntst;
  c->ncol = ncol;
  c->icp[0] = 0;
  c->nicp = 1;
  c->jac = 1;
  c->iad = 0;
}

/* The straight elastica's trivial branch to lambda = 100 with the determinant
 * test: its branch points at (n pi)^2, n = 1, 2, 3, located to EPSS = 1e-10. */
static inline void elastica_trivial_constants(cable_constants *c, int ntst, int ncol)
{
  engine_constants(c, ntst, ncol);
  c->ds = 0.5; c->dsmin = 1e-6; c->dsmax = 4.0; c->nmx = 200;
  c->rl1 = 100.0;
  c->isp = 2; c->ilp = 0;
  c->epss = 1e-10;
}

static inline int memrun_point(void *ctx, const cable_point *pt)
{
  memrun *r = ctx;
  if (r->n >= MEMRUN_MAX) return 0;
  r->itp[r->n] = pt->itp;
  r->lab[r->n] = pt->lab;
  r->newton[r->n] = pt->newton_iters;
  r->bp_kind[r->n] = pt->bp_kind;
  r->bp_mult[r->n] = pt->bp_mult;
  r->l2[r->n] = pt->l2norm;
  for (int k = 0; k < MEMRUN_NPAR && k < pt->npar; k++) r->par[r->n][k] = pt->par[k];
  r->n++;
  return 0;
}

static inline int memrun_solution(void *ctx, const cable_point *pt, const cable_solution *sol)
{
  (void)pt;
  memrun *r = ctx;
  if (r->nsol < MEMRUN_MAX) r->sol[r->nsol++] = cable_solution_clone(sol);
  return 0;
}

static inline void memrun_free(memrun *r)
{
  for (int i = 0; i < r->nsol; i++) cable_solution_free(r->sol[i]);
  memset(r, 0, sizeof *r);
}

static inline int memrun_run(const cable_problem *pb, const cable_constants *c, const cable_solution *start, memrun *r)
{
  memset(r, 0, sizeof *r);
  int st;
  cable_cont *cc = cable_cont_alloc(pb, c, &st);
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, start);
  if (st == CABLE_SUCCESS) {
    cable_sink sink = {r, memrun_point, memrun_solution, NULL};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  r->status = st;
  if (cc) {
    snprintf(r->err, sizeof r->err, "%s", cable_cont_error(cc));
  } else {
    cable_error e;   /* a refused constructor returns nothing: ask the check why */
    cable_cont_check(pb, c, &e);
    snprintf(r->err, sizeof r->err, "%s", e.msg);
  }
  cable_cont_free(cc);
  return st;
}

/* The largest relative distance between the points of two runs (principal
 * parameter and L2 norm), INFINITY when they have different numbers of
 * points. */
static inline double memrun_compare(const memrun *a, const memrun *b)
{
  if (a->n != b->n) return INFINITY;
  double d = 0;
  for (int i = 0; i < a->n; i++) {
    d = fmax(d, fabs(a->par[i][0] - b->par[i][0]) / (1 + fabs(a->par[i][0])));
    d = fmax(d, fabs(a->l2[i] - b->l2[i]) / (1 + fabs(a->l2[i])));
  }
  return d;
}

static inline const cable_solution *memrun_find(const memrun *r, int itp, int skip)
{
  for (int i = 0; i < r->nsol; i++)
    if (itp == 0 || r->sol[i]->itp % 10 == itp || r->sol[i]->itp == itp) {
      if (skip-- == 0) return r->sol[i];
    }
  return NULL;
}

static inline int memrun_count(const memrun *r, int itp)
{
  int n = 0;
  for (int i = 0; i < r->nsol; i++)
    if (r->sol[i]->itp == itp) n++;
  return n;
}

#endif
