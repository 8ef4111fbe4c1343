/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_solution.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_status.h"

#include "colloc_basis.h"
#include "solution_mesh.h"

cable_solution *cable_solution_alloc(int ndim, int ntst, int ncol, int npar, int nfpr)
{
  if (ndim < 1 || ntst < 1 || ncol < 1 || npar < 1 || nfpr < 0) return NULL;
  /* point counts and indices are ints (cable_solution_npts): sizes whose
     products do not fit are refused before anything is allocated */
  long long npts_ll = (long long)ntst * ncol + 1;
  if (npts_ll > INT_MAX || npts_ll * ndim > INT_MAX || nfpr == INT_MAX) return NULL;
  cable_solution *s = calloc(1, sizeof *s);
  if (!s) return NULL;
  s->ndim = ndim; s->ntst = ntst; s->ncol = ncol; s->npar = npar; s->nfpr = nfpr;
  s->err_est = -1.0;
  size_t np = (size_t)ntst * (size_t)ncol + 1;
  s->t = calloc(np, sizeof *s->t);
  s->u = calloc(np * (size_t)ndim, sizeof *s->u);
  s->udot = calloc(np * (size_t)ndim, sizeof *s->udot);
  s->par = calloc((size_t)npar, sizeof *s->par);
  s->icp = calloc((size_t)nfpr + 1, sizeof *s->icp);
  s->pardot = calloc((size_t)nfpr + 1, sizeof *s->pardot);
  if (!s->t || !s->u || !s->udot || !s->par || !s->icp || !s->pardot) {
    cable_solution_free(s);
    return NULL;
  }
  return s;
}

void cable_solution_free(cable_solution *s)
{
  if (!s) return;
  free(s->t); free(s->u); free(s->udot); free(s->par); free(s->icp); free(s->pardot);
  free(s);
}

int cable_solution_copy(cable_solution *dst, const cable_solution *src)
{
  if (!dst || !src) return CABLE_ERR_NULL;
  if (dst->ndim != src->ndim || dst->ntst != src->ntst || dst->ncol != src->ncol ||
      dst->npar != src->npar || dst->nfpr != src->nfpr)
    return CABLE_ERR_SIZE;
  if (!src->t || !src->u || !src->par || (src->nfpr > 0 && (!src->icp || !src->pardot))) return CABLE_ERR_NULL;
  size_t np = (size_t)cable_solution_npts(src);
  dst->ibr = src->ibr; dst->ntot = src->ntot; dst->itp = src->itp; dst->lab = src->lab;
  dst->bp_kind = src->bp_kind;
  dst->isw = src->isw; dst->err_est = src->err_est;
  memcpy(dst->t, src->t, np * sizeof *dst->t);
  memcpy(dst->u, src->u, np * (size_t)src->ndim * sizeof *dst->u);
  if (src->udot) memcpy(dst->udot, src->udot, np * (size_t)src->ndim * sizeof *dst->udot);
  else memset(dst->udot, 0, np * (size_t)src->ndim * sizeof *dst->udot);
  memcpy(dst->par, src->par, (size_t)src->npar * sizeof *dst->par);
  memcpy(dst->icp, src->icp, (size_t)src->nfpr * sizeof *dst->icp);
  memcpy(dst->pardot, src->pardot, (size_t)src->nfpr * sizeof *dst->pardot);
  return CABLE_SUCCESS;
}

cable_solution *cable_solution_clone(const cable_solution *src)
{
  if (!src) return NULL;
  cable_solution *s = cable_solution_alloc(src->ndim, src->ntst, src->ncol, src->npar, src->nfpr);
  if (s && cable_solution_copy(s, src) != 0) {
    cable_solution_free(s);
    return NULL;
  }
  return s;
}

double cable_solution_measure(const cable_solution *s, int iplt, double l2)
{
  if (!s || !s->u || !s->t || s->ndim < 1) return l2;
  int nd = s->ndim, npts = cable_solution_npts(s);
  if (iplt == 0 || iplt < -nd || iplt > 3 * nd) return l2;
  int i = (iplt > 0 ? iplt - 1 : -iplt - 1) % nd;
  if (iplt < 0 || iplt <= nd) {
    double v = s->u[i];
    for (int k = 1; k < npts; k++) {
      double x = s->u[(size_t)k * (size_t)nd + (size_t)i];
      v = iplt < 0 ? fmin(v, x) : fmax(v, x);
    }
    return v;
  }
  colloc_basis b;
  if (colloc_basis_init(&b, s->ncol) != 0) return NAN;
  int sq = iplt > 2 * nd;
  double sum = 0.0;
  for (int j = 0; j < s->ntst; j++) {
    double h = s->t[(j + 1) * s->ncol] - s->t[j * s->ncol];
    for (int k = 0; k <= s->ncol; k++) {
      double x = s->u[(size_t)(j * s->ncol + k) * (size_t)nd + (size_t)i];
      sum += h * b.wn[k] * (sq ? x * x : x);
    }
  }
  return sq ? sqrt(sum) : sum;
}

void solution_mesh_resample(const cable_solution *s, int ntst, double *mesh)
{
  int ntold = s->ntst, nc = s->ncol;
  for (int j = 0; j <= ntst; j++) {
    double q = (double)j * ntold / ntst;
    int a = (int)q;
    if (a >= ntold) a = ntold - 1;
    double w = q - a;
    mesh[j] = (1 - w) * s->t[a * nc] + w * s->t[(a + 1) * nc];
  }
  mesh[0] = 0.0;
  mesh[ntst] = 1.0;
}

/* ---------------------------------------------------------------- BP kinds */

static const char *const k_bp_kind_names[] = {"", "simple", "double", "pair"};
#define BP_KIND_COUNT ((int)(sizeof k_bp_kind_names / sizeof k_bp_kind_names[0]))

const char *cable_bp_kind_name(int kind)
{
  return kind > CABLE_BP_UNKNOWN && kind < BP_KIND_COUNT ? k_bp_kind_names[kind] : "";
}

int cable_bp_kind_code(const char *name)
{
  for (int k = CABLE_BP_UNKNOWN + 1; name && k < BP_KIND_COUNT; k++)
    if (strcmp(name, k_bp_kind_names[k]) == 0) return k;
  return CABLE_BP_UNKNOWN;
}

int cable_bp_multiplicity(int kind)
{
  /* a double BP: sigma_1 and sigma_2 vanish (cont_special.c's dip test); a
     simple one (det changes sign) and each BP of a pair: sigma_1 only */
  switch (kind) {
  case CABLE_BP_SIMPLE:
  case CABLE_BP_PAIR: return 1;
  case CABLE_BP_DOUBLE: return 2;
  default: return 0;
  }
}
