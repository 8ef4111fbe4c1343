/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "tube_distance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "braid_state.h"
#include "cable/cable_status.h"

/* Segments per leaf of the bounding-sphere trees: a leaf pair costs LEAF^2
 * segment distances, a level of the tree one sphere test per node pair. */
#define TUBE_LEAF 4

typedef struct tube_node {
  int curve, first, count;      /* segments first .. first+count-1 of curve */
  int child[2];                 /* node indices, -1 for a leaf */
  double ctr[3], rad;           /* bounding sphere */
  double pmid, phalf;           /* midpoint-position range as centre +- half width */
} tube_node;

typedef struct tube_npair {
  double lb;                    /* distance bound of the pair (computed when pushed) */
  int a, b;
} tube_npair;

struct tube_workspace {
  int nseg;
  tube_node *node;              /* [maxnode] */
  int maxnode;
  tube_npair *stack;            /* [maxstack], grown on demand */
  size_t maxstack;
};

tube_workspace *tube_workspace_alloc(int nseg)
{
  if (nseg < 1) return NULL;
  tube_workspace *w = calloc(1, sizeof *w);
  if (!w) return NULL;
  w->nseg = nseg;
  /* a binary tree over m segments with leaves of >= 1 segment has < 2m
     nodes; one tree per curve (at most 64) */
  w->maxnode = 2 * nseg + 128;
  w->maxstack = 1024;
  w->node = malloc((size_t)w->maxnode * sizeof *w->node);
  w->stack = malloc(w->maxstack * sizeof *w->stack);
  if (!w->node || !w->stack) {
    tube_workspace_free(w);
    return NULL;
  }
  return w;
}

void tube_workspace_free(tube_workspace *w)
{
  if (!w) return;
  free(w->node);
  free(w->stack);
  free(w);
}

/* Distance of positions, periodic when period > 0. */
static double pos_sep(double a, double b, double period)
{
  double d = fabs(a - b);
  if (period > 0) {
    d = fmod(d, period);
    if (period - d < d) d = period - d;
  }
  return d;
}

/* Closest points of segments p0 + s (p1 - p0) and q0 + t (q1 - q0), s, t in
 * [0,1]: minimise the quadratic over the square, first over the interior,
 * then on the edges (clamping one parameter and re-solving the other). */
static double seg_seg(const double *p0, const double *p1, const double *q0, const double *q1,
                      double *sp, double *tp)
{
  double d1[3], d2[3], r[3];
  for (int i = 0; i < 3; i++) {
    d1[i] = p1[i] - p0[i];
    d2[i] = q1[i] - q0[i];
    r[i] = p0[i] - q0[i];
  }
  double a = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
  double e = d2[0] * d2[0] + d2[1] * d2[1] + d2[2] * d2[2];
  double f = d2[0] * r[0] + d2[1] * r[1] + d2[2] * r[2];
  double s, t;
  if (a <= 0 && e <= 0) {
    s = t = 0;
  } else if (a <= 0) {
    s = 0;
    t = fmin(fmax(f / e, 0.0), 1.0);
  } else {
    double c = d1[0] * r[0] + d1[1] * r[1] + d1[2] * r[2];
    if (e <= 0) {
      t = 0;
      s = fmin(fmax(-c / a, 0.0), 1.0);
    } else {
      double b = d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2];
      double den = a * e - b * b;
      s = den > 0 ? fmin(fmax((b * f - c * e) / den, 0.0), 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = fmin(fmax(-c / a, 0.0), 1.0);
      } else if (t > 1) {
        t = 1;
        s = fmin(fmax((b - c) / a, 0.0), 1.0);
      }
    }
  }
  double dx = 0;
  for (int i = 0; i < 3; i++) {
    double v = p0[i] + s * d1[i] - q0[i] - t * d2[i];
    dx += v * v;
  }
  *sp = s;
  *tp = t;
  return sqrt(dx);
}

static double seg_mid_pos(const tube_polyline *c, int i) { return 0.5 * (c->pos[i] + c->pos[i + 1]); }

/* Node over segments first .. first+count-1 of curve k (a subtree built
 * below it when count > TUBE_LEAF); returns its index. */
static int build(tube_workspace *w, const tube_polyline *c, int k, int first, int count, int *nnode)
{
  int id = (*nnode)++;
  tube_node *nd = &w->node[id];
  nd->curve = k;
  nd->first = first;
  nd->count = count;
  double m0 = seg_mid_pos(c, first), m1 = seg_mid_pos(c, first + count - 1);
  nd->pmid = 0.5 * (m0 + m1);
  nd->phalf = 0.5 * (m1 - m0);
  nd->child[0] = nd->child[1] = -1;
  if (count <= TUBE_LEAF) {
    /* a leaf: the sphere about the centre of its points' box */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = first; i <= first + count; i++)
      for (int j = 0; j < 3; j++) {
        double v = c->xyz[3 * i + j];
        if (v < lo[j]) lo[j] = v;
        if (v > hi[j]) hi[j] = v;
      }
    double r2 = 0;
    for (int j = 0; j < 3; j++) nd->ctr[j] = 0.5 * (lo[j] + hi[j]);
    for (int i = first; i <= first + count; i++) {
      double d2 = 0;
      for (int j = 0; j < 3; j++) {
        double v = c->xyz[3 * i + j] - nd->ctr[j];
        d2 += v * v;
      }
      if (d2 > r2) r2 = d2;
    }
    nd->rad = sqrt(r2);
    return id;
  }
  int half = count / 2;
  int l = build(w, c, k, first, half, nnode);
  int r = build(w, c, k, first + half, count - half, nnode);
  /* an inner node: the smallest sphere holding both children's spheres (a
     bound as valid as the points' own, built in O(1)) */
  nd = &w->node[id];
  nd->child[0] = l;
  nd->child[1] = r;
  const tube_node *a = &w->node[l], *b = &w->node[r];
  double d2 = 0;
  for (int j = 0; j < 3; j++) d2 += (b->ctr[j] - a->ctr[j]) * (b->ctr[j] - a->ctr[j]);
  double d = sqrt(d2);
  if (d + b->rad <= a->rad || d == 0) {
    for (int j = 0; j < 3; j++) nd->ctr[j] = a->ctr[j];
    nd->rad = fmax(a->rad, b->rad);
  } else if (d + a->rad <= b->rad) {
    for (int j = 0; j < 3; j++) nd->ctr[j] = b->ctr[j];
    nd->rad = b->rad;
  } else {
    nd->rad = 0.5 * (d + a->rad + b->rad);
    for (int j = 0; j < 3; j++) nd->ctr[j] = a->ctr[j] + (nd->rad - a->rad) / d * (b->ctr[j] - a->ctr[j]);
  }
  return id;
}

/* Lower bound of the distance of two nodes' segments. */
static inline double bound(const tube_node *x, const tube_node *y)
{
  double d2 = 0;
  for (int j = 0; j < 3; j++) d2 += (x->ctr[j] - y->ctr[j]) * (x->ctr[j] - y->ctr[j]);
  return fmax(0.0, sqrt(d2) - x->rad - y->rad);
}

static int grow(tube_workspace *w)
{
  tube_npair *p = realloc(w->stack, 2 * w->maxstack * sizeof *p);
  if (!p) return 1;
  w->stack = p;
  w->maxstack *= 2;
  return 0;
}

/* Every admissible segment pair of two leaves (pairs i < j within one leaf). */
static void leaf_pair(const tube_polyline *c, const tube_node *x, const tube_node *y, double period,
                      double window, double overlap, tube_closest *out, unsigned char *const *flags)
{
  const tube_polyline *ca = &c[x->curve], *cb = &c[y->curve];
  for (int i = x->first; i < x->first + x->count; i++) {
    double pi_ = seg_mid_pos(ca, i);
    int j0 = x == y ? i + 1 : y->first;
    for (int j = j0; j < y->first + y->count; j++) {
      if (pos_sep(pi_, seg_mid_pos(cb, j), period) < window) continue;
      /* the segments' bounding spheres (centre at the midpoint, radius half
         the length): a bound below which their distance cannot fall */
      const double *p0 = ca->xyz + 3 * i, *p1 = p0 + 3, *q0 = cb->xyz + 3 * j, *q1 = q0 + 3;
      double dm2 = 0, lp2 = 0, lq2 = 0;
      for (int k = 0; k < 3; k++) {
        double dm = 0.5 * (p0[k] + p1[k] - q0[k] - q1[k]), dp = p1[k] - p0[k], dq = q1[k] - q0[k];
        dm2 += dm * dm;
        lp2 += dp * dp;
        lq2 += dq * dq;
      }
      double lbs = sqrt(dm2) - 0.5 * (sqrt(lp2) + sqrt(lq2));
      if (lbs > out->dist && lbs >= overlap) continue;
      double s, t;
      double d = seg_seg(ca->xyz + 3 * i, ca->xyz + 3 * i + 3, cb->xyz + 3 * j, cb->xyz + 3 * j + 3, &s, &t);
      if (d < out->dist) *out = (tube_closest){d, x->curve, i, s, y->curve, j, t};
      if (flags && d < overlap) {
        flags[x->curve][i] = 1;
        flags[y->curve][j] = 1;
      }
    }
  }
}

int tube_polylines_distance(tube_workspace *w, int ncurve, const tube_polyline *c, double period,
                            double window, double overlap, tube_closest *out,
                            unsigned char *const *flags)
{
  if (!w || !c || !out || ncurve < 1 || ncurve > 64 || !(window > 0) || !(period >= 0) ||
      !(overlap >= 0))
    return CABLE_ERR_INPUT;
  long nseg = 0;
  for (int k = 0; k < ncurve; k++) {
    if (c[k].n < 2 || !c[k].xyz || !c[k].pos) return CABLE_ERR_INPUT;
    for (int i = 0; i < c[k].n; i++) {
      for (int j = 0; j < 3; j++)
        if (!isfinite(c[k].xyz[3 * i + j])) return CABLE_ERR_NONFINITE;
      if (!isfinite(c[k].pos[i])) return CABLE_ERR_NONFINITE;
      if (i > 0 && (c[k].pos[i] < c[k].pos[i - 1] || c[k].pos[i] - c[k].pos[i - 1] > window))
        return CABLE_ERR_INPUT;
    }
    nseg += c[k].n - 1;
  }
  if (nseg > w->nseg) return CABLE_ERR_INPUT;
  int nnode = 0, root[64];
  for (int k = 0; k < ncurve; k++) root[k] = build(w, &c[k], k, 0, c[k].n - 1, &nnode);
  if (flags)
    for (int k = 0; k < ncurve; k++) memset(flags[k], 0, (size_t)(c[k].n - 1));
  out->dist = INFINITY;
  out->curve_a = out->curve_b = out->seg_a = out->seg_b = -1;
  out->u_a = out->u_b = 0;
  /* dual-tree descent: a node pair is dropped when no segment pair in it is
     admissible or when its distance bound exceeds both the best distance
     found and the overlap distance; nearer child pairs are visited first */
  size_t top = 0;
  for (int k = 0; k < ncurve; k++)
    for (int l = k; l < ncurve; l++) {
      if (top + 1 > w->maxstack && grow(w)) return CABLE_ERR_ALLOC;
      w->stack[top++] = (tube_npair){bound(&w->node[root[k]], &w->node[root[l]]), root[k], root[l]};
    }
  while (top > 0) {
    tube_npair q = w->stack[--top];
    const tube_node *x = &w->node[q.a], *y = &w->node[q.b];
    if (q.lb > out->dist && q.lb >= overlap) continue;
    if (pos_sep(x->pmid, y->pmid, period) + x->phalf + y->phalf < window) continue;
    if (x->child[0] < 0 && y->child[0] < 0) {
      leaf_pair(c, x, y, period, window, overlap, out, flags);
      continue;
    }
    /* split the larger node (both halves of a node paired with itself) */
    tube_npair kids[4];
    int nk = 0;
    if (q.a == q.b) {
      kids[nk++] = (tube_npair){0, x->child[0], x->child[0]};
      kids[nk++] = (tube_npair){0, x->child[1], x->child[1]};
      kids[nk++] = (tube_npair){0, x->child[0], x->child[1]};
    } else if (y->child[0] < 0 || (x->child[0] >= 0 && x->rad >= y->rad)) {
      kids[nk++] = (tube_npair){0, x->child[0], q.b};
      kids[nk++] = (tube_npair){0, x->child[1], q.b};
    } else {
      kids[nk++] = (tube_npair){0, q.a, y->child[0]};
      kids[nk++] = (tube_npair){0, q.a, y->child[1]};
    }
    for (int i = 0; i < nk; i++) kids[i].lb = bound(&w->node[kids[i].a], &w->node[kids[i].b]);
    /* push the farthest first: the nearest is taken next */
    for (int i = 0; i < nk; i++)
      for (int j = i + 1; j < nk; j++)
        if (kids[j].lb > kids[i].lb) {
          tube_npair tp = kids[i];
          kids[i] = kids[j];
          kids[j] = tp;
        }
    if (top + (size_t)nk > w->maxstack && grow(w)) return CABLE_ERR_ALLOC;
    for (int i = 0; i < nk; i++) w->stack[top++] = kids[i];
  }
  return CABLE_SUCCESS;
}

/* ---- braid solutions ---- */

static double seg_s(const braid_curves *bc, int seg, double u)
{
  return bc->s[seg] + u * (bc->s[seg + 1] - bc->s[seg]);
}

/* Positions along the axis (chord length of the sampled contact curve: its
 * O(h^2) error is immaterial for a neighbour window) into pos[n]; the axis
 * is closed when it returns to its start within TUBE_CLOSURE_TOL of its
 * length.  0 or CABLE_ERR_NONFINITE. */
static int axis_positions(const braid_curves *bc, double *pos, int *closed)
{
  int n = bc->n;
  pos[0] = 0;
  for (int i = 1; i < n; i++) {
    double d2 = 0;
    for (int j = 0; j < 3; j++) {
      double v = bc->c[3 * i + j] - bc->c[3 * i - 3 + j];
      d2 += v * v;
    }
    pos[i] = pos[i - 1] + sqrt(d2);
  }
  double len = pos[n - 1], gap2 = 0;
  for (int j = 0; j < 3; j++) {
    double v = bc->c[3 * (n - 1) + j] - bc->c[j];
    gap2 += v * v;
  }
  if (!isfinite(len)) return CABLE_ERR_NONFINITE;
  *closed = sqrt(gap2) <= TUBE_CLOSURE_TOL * len;
  return CABLE_SUCCESS;
}

static int braid_curves_ok(const braid_curves *bc)
{
  return bc && bc->n >= 2 && bc->Delta > 0 && bc->s && bc->r1 && bc->r2 && bc->c;
}

int braid_tube_distance(const braid_curves *bc, cable_tube_distance_result *out)
{
  if (!braid_curves_ok(bc) || !out) return CABLE_ERR_INPUT;
  int n = bc->n, rc = CABLE_SUCCESS;
  double Delta = bc->Delta;
  double *pos = malloc((size_t)n * sizeof *pos);
  unsigned char *f1 = malloc((size_t)n), *f2 = malloc((size_t)n);
  tube_workspace *w = tube_workspace_alloc(2 * (n - 1));
  if (!pos || !f1 || !f2 || !w) { rc = CABLE_ERR_ALLOC; goto done; }
  if ((rc = axis_positions(bc, pos, &out->closed)) != CABLE_SUCCESS) goto done;
  out->axis_kappa_max = NAN;
  double period = out->closed ? pos[n - 1] : 0.0, window = TUBE_WINDOW_FACTOR * Delta;
  tube_polyline pl[2] = {{n, bc->r1, pos}, {n, bc->r2, pos}};
  unsigned char *fl[2] = {f1, f2};
  tube_closest cl;
  rc = tube_polylines_distance(w, 2, pl, period, window, Delta, &cl, fl);
  if (rc != CABLE_SUCCESS) goto done;
  out->dmin = cl.dist / Delta;
  out->strand_a = cl.curve_a + 1;
  out->strand_b = cl.curve_b + 1;
  out->s_a = cl.seg_a >= 0 ? seg_s(bc, cl.seg_a, cl.u_a) : (double)NAN;
  out->s_b = cl.seg_b >= 0 ? seg_s(bc, cl.seg_b, cl.u_b) : (double)NAN;
  /* overlap intervals in braid position s, both strands together */
  out->noverlap = 0;
  out->overlap_length = 0;
  for (int i = 0; i < n - 1;) {
    if (!f1[i] && !f2[i]) { i++; continue; }
    int j = i;
    while (j < n - 1 && (f1[j] || f2[j])) j++;
    if (out->noverlap < CABLE_TUBE_MAX_INTERVALS) {
      out->overlap[out->noverlap][0] = bc->s[i];
      out->overlap[out->noverlap][1] = bc->s[j];
    }
    out->noverlap++;
    out->overlap_length += bc->s[j] - bc->s[i];
    i = j;
  }
  tube_polyline ax = {n, bc->c, pos};
  rc = tube_polylines_distance(w, 1, &ax, period, window, 0.0, &cl, NULL);
  if (rc != CABLE_SUCCESS) goto done;
  out->axis_dmin = cl.dist / Delta;
  out->axis_s_a = cl.seg_a >= 0 ? seg_s(bc, cl.seg_a, cl.u_a) : (double)NAN;
  out->axis_s_b = cl.seg_b >= 0 ? seg_s(bc, cl.seg_b, cl.u_b) : (double)NAN;
done:
  free(pos); free(f1); free(f2);
  tube_workspace_free(w);
  return rc;
}

/* Smallest sample count of the solution variant. */
#define TUBE_MIN_SAMPLES 1001

static int solution_samples(const cable_solution *sol)
{
  double m = ceil(TUBE_SAMPLES_PER_DELTA * sol->par[BP_L] / sol->par[BP_DELTA]) + 1;
  return m < TUBE_MIN_SAMPLES ? TUBE_MIN_SAMPLES : (m > 1e8 ? 100000000 : (int)m);
}

int braid_tube_dmin_solution(const cable_solution *sol, double *dmin)
{
  if (!sol || !dmin) return CABLE_ERR_NULL;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  int n = solution_samples(sol), closed = 0;
  braid_curves *bc = braid_curves_alloc(n);
  double *pos = malloc((size_t)n * sizeof *pos);
  tube_workspace *w = tube_workspace_alloc(2 * (n - 1));
  rc = bc && pos && w ? CABLE_SUCCESS : CABLE_ERR_ALLOC;
  if (!rc) rc = braid_curves_from_solution(sol, bc);
  if (!rc && !braid_curves_ok(bc)) rc = CABLE_ERR_INPUT;
  if (!rc) rc = axis_positions(bc, pos, &closed);
  tube_closest cl;
  if (!rc) {
    /* overlap 0 and no flags: only the closest pair is wanted */
    tube_polyline pl[2] = {{n, bc->r1, pos}, {n, bc->r2, pos}};
    rc = tube_polylines_distance(w, 2, pl, closed ? pos[n - 1] : 0.0, TUBE_WINDOW_FACTOR * bc->Delta, 0.0, &cl,
                                 NULL);
  }
  if (!rc) *dmin = cl.dist / bc->Delta;
  braid_curves_free(bc);
  free(pos);
  tube_workspace_free(w);
  return rc;
}

int cable_braid_tube_distance_solution(const cable_solution *sol, int n, cable_tube_distance_result *out)
{
  if (!sol || !out) return CABLE_ERR_NULL;
  if (n < 0 || n == 1) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  if (n == 0) n = solution_samples(sol);
  braid_curves *bc = braid_curves_alloc(n);
  if (!bc) return CABLE_ERR_ALLOC;
  rc = braid_curves_from_solution(sol, bc);
  if (rc == CABLE_SUCCESS) rc = braid_tube_distance(bc, out);
  braid_curves_free(bc);
  double kmax;
  if (rc == CABLE_SUCCESS) rc = braid_contact_curvature(sol, n, NULL, &kmax);
  if (rc == CABLE_SUCCESS) out->axis_kappa_max = kmax;
  return rc;
}

int tube_free_intervals(const double *t, const double *d, int n, double (*iv)[2], int max)
{
  int count = 0;
  double open_at = 0.0;
  for (int i = 0; i < n; i++) {
    int free_now = d[i] > 1.0, free_before = i > 0 && d[i - 1] > 1.0;
    double cross = i > 0 && free_now != free_before ? t[i - 1] + (1.0 - d[i - 1]) * (t[i] - t[i - 1]) / (d[i] - d[i - 1])
                                                    : t[i];
    if (free_now && !free_before) open_at = cross;
    int close_here = (!free_now && free_before) || (free_now && i == n - 1);
    if (close_here) {
      if (count < max) {
        iv[count][0] = open_at;
        iv[count][1] = free_now ? t[i] : cross;
      }
      count++;
    }
  }
  return count;
}
