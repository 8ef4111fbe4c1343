/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "tube_distance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "braid_state.h"
#include "cable/cable_status.h"

/* Segments per chunk: large enough that chunk pairs are few, small enough
 * that the bounding spheres are tight. */
#define TUBE_CHUNK_MIN 32
#define TUBE_MAX_CHUNKS 1024

typedef struct tube_chunk {
  int curve, first, count;      /* segments first .. first+count-1 of curve */
  double ctr[3], rad;           /* bounding sphere */
  double pmid, phalf;           /* midpoint-position range as centre +- half width */
} tube_chunk;

typedef struct tube_cpair {
  double lb;                    /* lower bound of the distance */
  int a, b;
} tube_cpair;

struct tube_workspace {
  int nseg;
  tube_chunk *chunk;            /* [TUBE_MAX_CHUNKS + ncurve] */
  int maxchunk;
  tube_cpair *pair;             /* [maxchunk (maxchunk + 1) / 2] */
  size_t maxpair;
};

tube_workspace *tube_workspace_alloc(int nseg)
{
  if (nseg < 1) return NULL;
  tube_workspace *w = calloc(1, sizeof *w);
  if (!w) return NULL;
  w->nseg = nseg;
  /* ncurve extra chunks: each polyline's last chunk may be short */
  w->maxchunk = TUBE_MAX_CHUNKS + 64;
  w->maxpair = (size_t)w->maxchunk * ((size_t)w->maxchunk + 1) / 2;
  w->chunk = malloc((size_t)w->maxchunk * sizeof *w->chunk);
  w->pair = malloc(w->maxpair * sizeof *w->pair);
  if (!w->chunk || !w->pair) {
    tube_workspace_free(w);
    return NULL;
  }
  return w;
}

void tube_workspace_free(tube_workspace *w)
{
  if (!w) return;
  free(w->chunk);
  free(w->pair);
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

static int cpair_cmp(const void *x, const void *y)
{
  const tube_cpair *a = x, *b = y;
  return a->lb < b->lb ? -1 : (a->lb > b->lb ? 1 : 0);
}

static double seg_mid_pos(const tube_polyline *c, int i) { return 0.5 * (c->pos[i] + c->pos[i + 1]); }

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
  int K = TUBE_CHUNK_MIN;
  while (nseg / K > TUBE_MAX_CHUNKS) K *= 2;
  /* chunks with bounding spheres */
  int nch = 0;
  for (int k = 0; k < ncurve; k++) {
    for (int f = 0; f < c[k].n - 1; f += K) {
      tube_chunk *ch = &w->chunk[nch++];
      ch->curve = k;
      ch->first = f;
      ch->count = f + K <= c[k].n - 1 ? K : c[k].n - 1 - f;
      double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
      for (int i = f; i <= f + ch->count; i++)
        for (int j = 0; j < 3; j++) {
          lo[j] = fmin(lo[j], c[k].xyz[3 * i + j]);
          hi[j] = fmax(hi[j], c[k].xyz[3 * i + j]);
        }
      double r2 = 0;
      for (int j = 0; j < 3; j++) ch->ctr[j] = 0.5 * (lo[j] + hi[j]);
      for (int i = f; i <= f + ch->count; i++) {
        double d2 = 0;
        for (int j = 0; j < 3; j++) {
          double v = c[k].xyz[3 * i + j] - ch->ctr[j];
          d2 += v * v;
        }
        r2 = fmax(r2, d2);
      }
      ch->rad = sqrt(r2);
      double m0 = seg_mid_pos(&c[k], f), m1 = seg_mid_pos(&c[k], f + ch->count - 1);
      ch->pmid = 0.5 * (m0 + m1);
      ch->phalf = 0.5 * (m1 - m0);
    }
  }
  /* chunk pairs that hold at least one admissible segment pair, by lower bound */
  size_t np = 0;
  for (int a = 0; a < nch; a++)
    for (int b = a; b < nch; b++) {
      const tube_chunk *x = &w->chunk[a], *y = &w->chunk[b];
      if (pos_sep(x->pmid, y->pmid, period) + x->phalf + y->phalf < window) continue;
      double d2 = 0;
      for (int j = 0; j < 3; j++) d2 += (x->ctr[j] - y->ctr[j]) * (x->ctr[j] - y->ctr[j]);
      w->pair[np++] = (tube_cpair){fmax(0.0, sqrt(d2) - x->rad - y->rad), a, b};
    }
  qsort(w->pair, np, sizeof *w->pair, cpair_cmp);
  if (flags)
    for (int k = 0; k < ncurve; k++) memset(flags[k], 0, (size_t)(c[k].n - 1));
  out->dist = INFINITY;
  out->curve_a = out->curve_b = out->seg_a = out->seg_b = -1;
  out->u_a = out->u_b = 0;
  for (size_t q = 0; q < np; q++) {
    if (w->pair[q].lb > out->dist && w->pair[q].lb >= overlap) break;
    const tube_chunk *x = &w->chunk[w->pair[q].a], *y = &w->chunk[w->pair[q].b];
    const tube_polyline *ca = &c[x->curve], *cb = &c[y->curve];
    for (int i = x->first; i < x->first + x->count; i++) {
      double pi_ = seg_mid_pos(ca, i);
      int j0 = x == y ? i + 1 : y->first;
      for (int j = j0; j < y->first + y->count; j++) {
        if (pos_sep(pi_, seg_mid_pos(cb, j), period) < window) continue;
        double s, t;
        double d = seg_seg(ca->xyz + 3 * i, ca->xyz + 3 * i + 3, cb->xyz + 3 * j, cb->xyz + 3 * j + 3,
                           &s, &t);
        if (d < out->dist) {
          *out = (tube_closest){d, x->curve, i, s, y->curve, j, t};
        }
        if (flags && d < overlap) {
          flags[x->curve][i] = 1;
          flags[y->curve][j] = 1;
        }
      }
    }
  }
  return CABLE_SUCCESS;
}

/* ---- braid solutions ---- */

static double seg_s(const braid_curves *bc, int seg, double u)
{
  return bc->s[seg] + u * (bc->s[seg + 1] - bc->s[seg]);
}

int braid_tube_distance(const braid_curves *bc, cable_tube_distance_result *out)
{
  if (!bc || !out || bc->n < 2 || !(bc->Delta > 0) || !bc->s || !bc->r1 || !bc->r2 || !bc->c)
    return CABLE_ERR_INPUT;
  int n = bc->n, rc = CABLE_SUCCESS;
  double Delta = bc->Delta;
  double *pos = malloc((size_t)n * sizeof *pos);
  unsigned char *f1 = malloc((size_t)n), *f2 = malloc((size_t)n);
  tube_workspace *w = tube_workspace_alloc(2 * (n - 1));
  if (!pos || !f1 || !f2 || !w) { rc = CABLE_ERR_ALLOC; goto done; }
  /* position along the axis: chord length of the sampled contact curve (its
   * O(h^2) error is immaterial for a neighbour window) */
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
  if (!isfinite(len)) { rc = CABLE_ERR_NONFINITE; goto done; }
  out->closed = sqrt(gap2) <= TUBE_CLOSURE_TOL * len;
  out->axis_kappa_max = NAN;
  double period = out->closed ? len : 0.0, window = TUBE_WINDOW_FACTOR * Delta;
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

int cable_braid_tube_distance_solution(const cable_solution *sol, int n, cable_tube_distance_result *out)
{
  if (!sol || !out) return CABLE_ERR_NULL;
  if (n < 0 || n == 1) return CABLE_ERR_INPUT;
  int rc = braid_geometry_check(sol);
  if (rc != CABLE_SUCCESS) return rc;
  if (n == 0) {
    double m = ceil(TUBE_SAMPLES_PER_DELTA * sol->par[BP_L] / sol->par[BP_DELTA]) + 1;
    n = m < TUBE_MIN_SAMPLES ? TUBE_MIN_SAMPLES : (m > 1e8 ? 100000000 : (int)m);
  }
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
