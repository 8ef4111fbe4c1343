/* SPDX-License-Identifier: GPL-3.0-or-later */
/* A branch that returns to its start: a closed loop (an isola, or a mode
 * branch that comes back to the branch point it left).  AUTO follows it
 * round again until NMX; cable ends it there with CABLE_END_LOOP and a
 * message naming the start.  A branch that reaches a branch point already
 * computed on another branch (cable_cont_add_known_point) joins a known
 * branch: it ends there too (CABLE_END_LOOP), the message naming the point.
 *
 * Mesh adaptation changes the discretisation between points, so the test
 * compares mesh-independent summaries z of the stored solutions: the free
 * parameters, U(0), U(1) and IPLT's measure (the b-file's L2-NORM column),
 * in the distance d(a, b) = max_j |a_j - b_j| / (1 + |z0_j|) (the relative-
 * absolute scale of AUTO's EPSL/EPSU tests).  The branch closes when the
 * chord from the previous point zp to the new point z passes within
 * CONT_LOOP_CHORD of its own length of z0: a curve through z0 leaves its
 * chord at most about kappa l^2 / 8 away from it (kappa l, the turn per
 * step, is well below 1 under the step control), and a curve that passes
 * z0 at a distance comparable to a step does not come that close in every
 * component at once.  It must first have gone away from the start by more
 * than CONT_LOOP_AWAY steps' worth, so that the first steps never count. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

#define CONT_LOOP_CHORD 0.1   /* a pass within this fraction of the chord's length */
#define CONT_LOOP_AWAY 3.0    /* first away from the start by this many chord lengths */
/* A located BP is a known point when its summary is within this distance d
 * of the known one: both are located to EPSS in arclength (1e-7 relative in
 * the scenes), far below; distinct BPs of one problem differ in PAR(ICP(1))
 * or in U by O(1) relative. */
#define CONT_KNOWN_TOL 1.0e-5

static void summary(const cable_cont *cc, double *z)
{
  const cable_solution *s = cc->sol;
  int k = 0, npts = cable_solution_npts(s);
  for (int q = 0; q < cc->nfpr; q++) z[k++] = s->par[cc->c->icp[q]];
  for (int i = 0; i < cc->ndim; i++) z[k++] = s->u[i];
  for (int i = 0; i < cc->ndim; i++) z[k++] = s->u[(size_t)(npts - 1) * (size_t)cc->ndim + (size_t)i];
  z[k] = cc->pt.measure;
}

static double dist(const cont_loop *l, const double *a, const double *b)
{
  double d = 0;
  for (int j = 0; j < l->m; j++) d = fmax(d, fabs(a[j] - b[j]) / (1.0 + fabs(l->z0[j])));
  return d;
}

int cont_loop_start(cable_cont *cc, int start_lab)
{
  cont_loop *l = &cc->loop;
  l->m = cc->nfpr + 2 * cc->ndim + 1;
  double **bufs[3] = {&l->z0, &l->zp, &l->z};
  for (int k = 0; k < 3; k++) {
    free(*bufs[k]);
    *bufs[k] = malloc((size_t)l->m * sizeof **bufs[k]);
    if (!*bufs[k]) return CABLE_ERR_ALLOC;
  }
  summary(cc, l->z0);
  memcpy(l->zp, l->z0, (size_t)l->m * sizeof *l->zp);
  l->dmax = 0;
  l->start_lab = start_lab;
  return CABLE_SUCCESS;
}

int cont_loop_closed(cable_cont *cc)
{
  cont_loop *l = &cc->loop;
  if (!l->z0 || !l->zp || !l->z) return 0;
  double *z = l->z;
  summary(cc, z);
  /* the point of the chord zp + a (z - zp), a in [0, 1], closest to z0 in
     the scaled Euclidean norm; its distance in d */
  double num = 0, den = 0;
  for (int j = 0; j < l->m; j++) {
    double w = 1.0 / ((1.0 + fabs(l->z0[j])) * (1.0 + fabs(l->z0[j])));
    num += w * (l->z0[j] - l->zp[j]) * (z[j] - l->zp[j]);
    den += w * (z[j] - l->zp[j]) * (z[j] - l->zp[j]);
  }
  double a = den > 0 ? fmin(1.0, fmax(0.0, num / den)) : 0.0, near = 0, chord = dist(l, z, l->zp);
  for (int j = 0; j < l->m; j++)
    near = fmax(near, fabs(l->zp[j] + a * (z[j] - l->zp[j]) - l->z0[j]) / (1.0 + fabs(l->z0[j])));
  int closed = l->dmax > CONT_LOOP_AWAY * chord && chord > 0 && near <= CONT_LOOP_CHORD * chord;
  l->dmax = fmax(l->dmax, dist(l, z, l->z0));
  memcpy(l->zp, z, (size_t)l->m * sizeof *z);
  if (closed) {
    char start[64];
    if (l->start_lab > 0) snprintf(start, sizeof start, "label %d", l->start_lab);
    else snprintf(start, sizeof start, "its first point");
    cont_set_error(cc, "closed loop: the branch returned to its start (%s, PAR(%d) = %.10g) between points %d "
                   "and %d; following it further would repeat the loop", start, cc->c->icp[0] + 1, l->z0[0],
                   cc->npt - 1, cc->npt);
  }
  return closed;
}

/* A known point's summary: the free parameters, U(0), U(1) (no IPLT measure:
 * a stored solution does not carry it) */
static void solution_summary(const cable_cont *cc, const cable_solution *s, double *z)
{
  int k = 0, npts = cable_solution_npts(s);
  for (int q = 0; q < cc->nfpr; q++) z[k++] = s->par[cc->c->icp[q]];
  for (int i = 0; i < cc->ndim; i++) z[k++] = s->u[i];
  for (int i = 0; i < cc->ndim; i++) z[k++] = s->u[(size_t)(npts - 1) * (size_t)cc->ndim + (size_t)i];
}

int cable_cont_add_known_point(cable_cont *cc, const cable_solution *s, const char *name)
{
  if (!cc || !s) return CABLE_ERR_NULL;
  if (s->ndim != cc->ndim || s->npar <= cc->c->icp[cc->nfpr - 1]) return CABLE_ERR_INPUT;
  cont_loop *l = &cc->loop;
  int m = cc->nfpr + 2 * cc->ndim;
  double *k = realloc(l->known, (size_t)(l->nknown + 1) * (size_t)m * sizeof *k);
  if (!k) return CABLE_ERR_ALLOC;
  l->known = k;
  char(*nm)[64] = realloc(l->known_name, (size_t)(l->nknown + 1) * sizeof *nm);
  if (!nm) return CABLE_ERR_ALLOC;
  l->known_name = nm;
  solution_summary(cc, s, l->known + (size_t)l->nknown * (size_t)m);
  snprintf(l->known_name[l->nknown], sizeof l->known_name[0], "%s", name ? name : "a known point");
  l->nknown++;
  return CABLE_SUCCESS;
}

int cont_loop_known(cable_cont *cc)
{
  cont_loop *l = &cc->loop;
  if (cc->itp != CABLE_TY_BP || cc->npt <= 1 || l->nknown == 0 || !l->z) return 0;
  int m = cc->nfpr + 2 * cc->ndim;
  double *z = l->z; /* scratch here: cont_loop_closed has copied it to zp */
  solution_summary(cc, cc->sol, z);
  for (int q = 0; q < l->nknown; q++) {
    const double *kq = l->known + (size_t)q * (size_t)m;
    double d = 0;
    for (int j = 0; j < m; j++) d = fmax(d, fabs(z[j] - kq[j]) / (1.0 + fabs(kq[j])));
    if (d <= CONT_KNOWN_TOL) {
      cont_set_error(cc, "joins a known branch: the branch point at point %d (PAR(%d) = %.10g) is %s (distance "
                     "%.1e); following it further would repeat a computed branch", cc->npt, cc->c->icp[0] + 1, z[0],
                     l->known_name[q], d);
      return 1;
    }
  }
  return 0;
}

void cont_loop_free(cable_cont *cc)
{
  free(cc->loop.known);
  free(cc->loop.known_name);
  cc->loop.known = NULL;
  cc->loop.known_name = NULL;
  cc->loop.nknown = 0;
  free(cc->loop.z0);
  free(cc->loop.zp);
  free(cc->loop.z);
  cc->loop.z0 = cc->loop.zp = cc->loop.z = NULL;
}

int cont_loop_transfer_known(const cable_cont *from, cable_cont *to)
{
  const cont_loop *a = &from->loop;
  cont_loop *b = &to->loop;
  if (a->nknown == 0) return CABLE_SUCCESS;
  int ma = from->nfpr + 2 * from->ndim, mb = to->nfpr + 2 * to->ndim;
  double *k = malloc((size_t)a->nknown * (size_t)mb * sizeof *k);
  char(*nm)[64] = malloc((size_t)a->nknown * sizeof *nm);
  if (!k || !nm) {
    free(k);
    free(nm);
    return CABLE_ERR_ALLOC;
  }
  for (int q = 0; q < a->nknown; q++) {
    const double *src = a->known + (size_t)q * (size_t)ma;
    double *dst = k + (size_t)q * (size_t)mb;
    int j = 0;
    /* the free parameters the handles share, then the new ones (the restricted
       problem's unfolding parameter: 0 on the known branches), then U(0), U(1) */
    for (int p = 0; p < to->nfpr; p++) dst[j++] = p < from->nfpr ? src[p] : 0.0;
    for (int i = from->nfpr; i < ma; i++) dst[j++] = src[i];
    memcpy(nm[q], a->known_name[q], sizeof nm[q]);
  }
  free(b->known);
  free(b->known_name);
  b->known = k;
  b->known_name = nm;
  b->nknown = a->nknown;
  return CABLE_SUCCESS;
}
