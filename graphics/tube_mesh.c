/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Rotation-minimising frames and tube meshes. */
#include "tube_mesh.h"

#include <math.h>
#include <stdlib.h>

#include "cable/cable_status.h"
#include "graphics_vec.h"

/* A vector keeping less than this fraction of its length after removing its
 * tangential part is too close to the tangent to define a normal reliably
 * (the normalised rest would carry round-off of relative size 1e-16 / 1e-3). */
#define TUBE_PERP_MIN 1e-3

int tube_points_count(int n, const double *xyz, int closed)
{
  if (n < 2 || xyz == NULL) return 0;
  if (!closed) return n;
  double total = 0, gap[3];
  for (int i = 0; i + 1 < n; i++) {
    cable_vec3_sub(xyz + 3 * (i + 1), xyz + 3 * i, gap);
    total += cable_vec3_norm(gap);
  }
  cable_vec3_sub(xyz + 3 * (n - 1), xyz, gap);
  if (n > 2 && cable_vec3_norm(gap) <= TUBE_DUPLICATE_REL * total / (n - 1)) return n - 1;
  return n;
}

/* Unit chord from point a to point b; 0 when they coincide. */
static double tube_chord(const double *xyz, int a, int b, double u[3])
{
  cable_vec3_sub(xyz + 3 * b, xyz + 3 * a, u);
  return cable_vec3_normalize(u);
}

static int tube_tangents(int n, const double *xyz, int closed, double *t)
{
  int have = -1;
  for (int i = 0; i < n; i++) {
    double a[3] = {0, 0, 0}, b[3] = {0, 0, 0}, *ti = t + 3 * i;
    int prev = i > 0 ? i - 1 : closed ? n - 1 : -1;
    int next = i < n - 1 ? i + 1 : closed ? 0 : -1;
    if (prev >= 0) tube_chord(xyz, prev, i, a);
    if (next >= 0) tube_chord(xyz, i, next, b);
    cable_vec3_axpy(a, 1.0, b, ti);
    if (cable_vec3_normalize(ti) == 0) {
      /* a cusp (a = -b) or a repeated point: fall back on one chord */
      ti[0] = b[0], ti[1] = b[1], ti[2] = b[2];
      if (cable_vec3_normalize(ti) == 0) {
        ti[0] = a[0], ti[1] = a[1], ti[2] = a[2];
        if (cable_vec3_normalize(ti) == 0) continue;
      }
    }
    if (have < 0) have = i;
  }
  if (have < 0) return CABLE_ERR_INPUT;
  /* points with no usable chord inherit the nearest earlier tangent */
  for (int i = 0; i < n; i++) {
    double *ti = t + 3 * i;
    if (cable_vec3_norm(ti) > 0.5) continue; /* unit, i.e. set above */
    const double *src = t + 3 * (i == 0 ? have : i - 1);
    ti[0] = src[0], ti[1] = src[1], ti[2] = src[2];
  }
  return CABLE_SUCCESS;
}

/* r minus its component along unit t, normalised; a fallback normal when r
 * is (nearly) parallel to t. */
static void tube_perp(const double t[3], double r[3])
{
  cable_vec3_axpy(r, -cable_vec3_dot(r, t), t, r);
  if (cable_vec3_normalize(r) > TUBE_PERP_MIN) return;
  /* the axis least aligned with t */
  int k = fabs(t[0]) <= fabs(t[1]) && fabs(t[0]) <= fabs(t[2]) ? 0 : fabs(t[1]) <= fabs(t[2]) ? 1 : 2;
  r[0] = r[1] = r[2] = 0;
  r[k] = 1;
  cable_vec3_axpy(r, -cable_vec3_dot(r, t), t, r);
  cable_vec3_normalize(r);
}

/* Double reflection: transports normal r (at point a, tangent ta) to point b
 * (tangent tb). */
static void tube_transport(const double *xa, const double *xb, const double ta[3],
                           const double tb[3], const double r[3], double out[3])
{
  double v1[3], rl[3], tl[3], v2[3];
  cable_vec3_sub(xb, xa, v1);
  double c1 = cable_vec3_dot(v1, v1);
  out[0] = r[0], out[1] = r[1], out[2] = r[2];
  if (c1 > 0) {
    cable_vec3_axpy(r, -2.0 / c1 * cable_vec3_dot(v1, r), v1, rl);
    cable_vec3_axpy(ta, -2.0 / c1 * cable_vec3_dot(v1, ta), v1, tl);
    cable_vec3_sub(tb, tl, v2);
    double c2 = cable_vec3_dot(v2, v2);
    if (c2 > 0) cable_vec3_axpy(rl, -2.0 / c2 * cable_vec3_dot(v2, rl), v2, out);
    else out[0] = rl[0], out[1] = rl[1], out[2] = rl[2];
  }
  /* keep exact orthonormality against round-off drift over many steps */
  tube_perp(tb, out);
}

int tube_frames_compute(int n, const double *xyz, int closed, double *t, double *nrm,
                        double *closure)
{
  if (closure) *closure = 0;
  if (n < 2 || xyz == NULL || t == NULL || nrm == NULL) return CABLE_ERR_INPUT;
  for (int i = 0; i < 3 * n; i++)
    if (!isfinite(xyz[i])) return CABLE_ERR_INPUT;
  int st = tube_tangents(n, xyz, closed, t);
  if (st != CABLE_SUCCESS) return st;
  double r0[3] = {0, 0, 0};
  tube_perp(t, r0);
  nrm[0] = r0[0], nrm[1] = r0[1], nrm[2] = r0[2];
  for (int i = 0; i + 1 < n; i++)
    tube_transport(xyz + 3 * i, xyz + 3 * (i + 1), t + 3 * i, t + 3 * (i + 1), nrm + 3 * i,
                   nrm + 3 * (i + 1));
  if (!closed) return CABLE_SUCCESS;

  double rend[3], c[3], gap[3];
  tube_transport(xyz + 3 * (n - 1), xyz, t + 3 * (n - 1), t, nrm + 3 * (n - 1), rend);
  cable_vec3_cross(nrm, rend, c);
  double phi = atan2(cable_vec3_dot(c, t), cable_vec3_dot(nrm, rend));
  if (closure) *closure = phi;
  double total = 0;
  for (int i = 0; i + 1 < n; i++) {
    cable_vec3_sub(xyz + 3 * (i + 1), xyz + 3 * i, gap);
    total += cable_vec3_norm(gap);
  }
  cable_vec3_sub(xyz, xyz + 3 * (n - 1), gap);
  total += cable_vec3_norm(gap);
  if (total <= 0) return CABLE_ERR_INPUT;
  double s = 0;
  for (int i = 1; i < n; i++) {
    cable_vec3_sub(xyz + 3 * i, xyz + 3 * (i - 1), gap);
    s += cable_vec3_norm(gap);
    /* rotate about t_i by -phi s / total: the frame then arrives back at
     * s = total rotated by exactly -phi, i.e. on the starting normal */
    double a = -phi * s / total, *r = nrm + 3 * i, tr[3];
    cable_vec3_cross(t + 3 * i, r, tr);
    double ca = cos(a), sa = sin(a);
    for (int k = 0; k < 3; k++) r[k] = ca * r[k] + sa * tr[k];
  }
  return CABLE_SUCCESS;
}

void tube_mesh_counts(int npts, int nsides, int closed, int *nv, int *ntri)
{
  if (closed) {
    *nv = npts * nsides;
    *ntri = 2 * npts * nsides;
  } else {
    *nv = npts * nsides + 2 * (nsides + 1);
    *ntri = 2 * (npts - 1) * nsides + 2 * nsides;
  }
}

tube_mesh *tube_mesh_alloc(int npts, int nsides, int closed)
{
  if (npts < 2 || nsides < TUBE_NSIDES_MIN || nsides > TUBE_NSIDES_MAX) return NULL;
  tube_mesh *m = calloc(1, sizeof *m);
  if (m == NULL) return NULL;
  m->npts = npts;
  m->nsides = nsides;
  m->closed = closed != 0;
  tube_mesh_counts(npts, nsides, m->closed, &m->nv, &m->ntri);
  m->xyz = malloc(sizeof(double) * 3 * (size_t)m->nv);
  m->normal = malloc(sizeof(double) * 3 * (size_t)m->nv);
  m->scalar = malloc(sizeof(double) * (size_t)m->nv);
  m->tri = malloc(sizeof(int) * 3 * (size_t)m->ntri);
  m->t = malloc(sizeof(double) * 3 * (size_t)npts);
  m->nrm = malloc(sizeof(double) * 3 * (size_t)npts);
  if (!m->xyz || !m->normal || !m->scalar || !m->tri || !m->t || !m->nrm) {
    tube_mesh_free(m);
    return NULL;
  }
  return m;
}

void tube_mesh_free(tube_mesh *m)
{
  if (m == NULL) return;
  free(m->xyz);
  free(m->normal);
  free(m->scalar);
  free(m->tri);
  free(m->t);
  free(m->nrm);
  free(m);
}

static void tube_set_vertex(tube_mesh *m, int v, const double c[3], double radius,
                            const double dir[3], const double nrm[3], double scalar)
{
  cable_vec3_axpy(c, radius, dir, m->xyz + 3 * v);
  for (int k = 0; k < 3; k++) m->normal[3 * v + k] = nrm[k];
  m->scalar[v] = scalar;
}

static int *tube_set_tri(int *tri, int a, int b, int c)
{
  tri[0] = a, tri[1] = b, tri[2] = c;
  return tri + 3;
}

/* Flat end cap at ring `ring`; outward is +t at the end, -t at the start. */
static int *tube_cap(tube_mesh *m, int *tri, int ring, int base, const double *xyz,
                     double radius, double scalar, int at_end)
{
  int ns = m->nsides;
  double ax[3];
  const double *t = m->t + 3 * ring, *c = xyz + 3 * ring;
  for (int k = 0; k < 3; k++) ax[k] = at_end ? t[k] : -t[k];
  tube_set_vertex(m, base, c, 0.0, ax, ax, scalar);
  for (int j = 0; j < ns; j++) {
    double dir[3];
    const double *ring_n = m->normal + 3 * (ring * ns + j);
    dir[0] = ring_n[0], dir[1] = ring_n[1], dir[2] = ring_n[2];
    tube_set_vertex(m, base + 1 + j, c, radius, dir, ax, scalar);
  }
  for (int j = 0; j < ns; j++) {
    int a = base + 1 + j, b = base + 1 + (j + 1) % ns;
    tri = at_end ? tube_set_tri(tri, base, a, b) : tube_set_tri(tri, base, b, a);
  }
  return tri;
}

int tube_mesh_build(tube_mesh *m, const double *xyz, const double *scalar, double radius)
{
  if (m == NULL || xyz == NULL || !(radius > 0) || !isfinite(radius)) return CABLE_ERR_INPUT;
  int n = m->npts, ns = m->nsides;
  int st = tube_frames_compute(n, xyz, m->closed, m->t, m->nrm, NULL);
  if (st != CABLE_SUCCESS) return st;
  for (int i = 0; i < n; i++) {
    const double *t = m->t + 3 * i, *r = m->nrm + 3 * i;
    double b[3];
    cable_vec3_cross(t, r, b);
    double sv = scalar ? scalar[i] : 0.0;
    for (int j = 0; j < ns; j++) {
      double th = 2.0 * GRAPHICS_PI * j / ns, dir[3];
      for (int k = 0; k < 3; k++) dir[k] = cos(th) * r[k] + sin(th) * b[k];
      tube_set_vertex(m, i * ns + j, xyz + 3 * i, radius, dir, dir, sv);
    }
  }
  int *tri = m->tri, nseg = m->closed ? n : n - 1;
  for (int i = 0; i < nseg; i++) {
    int i1 = (i + 1) % n;
    for (int j = 0; j < ns; j++) {
      int j1 = (j + 1) % ns;
      int a = i * ns + j, b = i * ns + j1, c = i1 * ns + j1, d = i1 * ns + j;
      tri = tube_set_tri(tri, a, b, c);
      tri = tube_set_tri(tri, a, c, d);
    }
  }
  if (!m->closed) {
    int base = n * ns;
    tri = tube_cap(m, tri, 0, base, xyz, radius, scalar ? scalar[0] : 0.0, 0);
    tri = tube_cap(m, tri, n - 1, base + ns + 1, xyz, radius, scalar ? scalar[n - 1] : 0.0, 1);
  }
  return CABLE_SUCCESS;
}
