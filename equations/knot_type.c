/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "knot_type.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_math.h>
#include <lapacke.h>

#include "cable/cable_status.h"

/* ---- tolerances of an admissible projection (relative to the polygon's size) ----
 * A crossing is degenerate when the projected segments meet at an angle with
 * |sin| < KT_MIN_SIN, when it lies within KT_MIN_MARGIN * size of a segment end
 * (it could then be counted on the wrong segment), or when the two strands pass
 * within KT_MIN_GAP * size of each other in height (over/under undecidable).
 * All are far below the geometry of a smooth curve sampled at a few thousand
 * points and far above round-off. */
#define KT_MIN_SIN 1e-7
#define KT_MIN_MARGIN 1e-11
#define KT_MIN_GAP 1e-9
/* Tolerance on |det G| = |Delta(-1)| and on the smallest eigenvalue of G
 * relative to the largest (G is an integer matrix with nonzero determinant). */
#define KT_DET_RTOL 1e-6
#define KT_EIG_RTOL 1e-10
/* Projections whose invariants are compared before giving up. */
#define KT_MAX_TRIES 6

typedef struct kt_crossing {
  int seg_o, seg_u;            /* segment (start vertex) over and under */
  double par_o, par_u;         /* position along the segment in [0,1) */
  int sign;                    /* +1: right-handed (over x under points to the viewer) */
} kt_crossing;

typedef struct kt_diagram {
  int ncross, cap;
  kt_crossing *cr;
  int degenerate;
  double quality;              /* smallest |sin| of a crossing angle */
  int writhe;
} kt_diagram;

typedef struct kt_invariants {
  int deg;
  long alex[CABLE_KNOT_TYPE_MAX_DEGREE + 1];
  long det;
  int signature;
} kt_invariants;

/* ------------------------------------------------------------------ */
/* projection and crossings                                            */

static void projection_basis(const double *dir, double *e1, double *e2, double *nz)
{
  double nn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  for (int i = 0; i < 3; i++) nz[i] = dir[i] / nn;
  int k = 0;                                   /* axis least aligned with nz */
  for (int i = 1; i < 3; i++)
    if (fabs(nz[i]) < fabs(nz[k])) k = i;
  double a[3] = {0, 0, 0};
  a[k] = 1.0;
  /* e1 = normalise(a - (a.n) n), e2 = n x e1: (e1, e2, n) right-handed, so
   * anticlockwise in the (e1, e2) plane is anticlockwise seen from +n */
  double an = a[0] * nz[0] + a[1] * nz[1] + a[2] * nz[2];
  for (int i = 0; i < 3; i++) e1[i] = a[i] - an * nz[i];
  double ne = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int i = 0; i < 3; i++) e1[i] /= ne;
  e2[0] = nz[1] * e1[2] - nz[2] * e1[1];
  e2[1] = nz[2] * e1[0] - nz[0] * e1[2];
  e2[2] = nz[0] * e1[1] - nz[1] * e1[0];
}

static int diagram_push(kt_diagram *d, const kt_crossing *c)
{
  if (d->ncross == d->cap) {
    int cap = d->cap ? 2 * d->cap : 64;
    kt_crossing *p = realloc(d->cr, (size_t)cap * sizeof *p);
    if (!p) return CABLE_ERR_ALLOC;
    d->cr = p;
    d->cap = cap;
  }
  d->cr[d->ncross++] = *c;
  return CABLE_SUCCESS;
}

/* Crossings of the projection along dir.  Segments are bucketed on a uniform
 * grid by bounding box; a pair is tested only in the first grid cell common to
 * both boxes, so every pair is tested once without a hash table. */
static int diagram_build(const double *xyz, int n, const double *dir, kt_diagram *d)
{
  d->ncross = 0;
  d->degenerate = 0;
  d->quality = 1.0;
  d->writhe = 0;
  double e1[3], e2[3], nz[3];
  projection_basis(dir, e1, e2, nz);
  double *P = malloc(2 * (size_t)n * sizeof *P), *Z = malloc((size_t)n * sizeof *Z);
  int *box = malloc(4 * (size_t)n * sizeof *box);
  int *cnt = NULL, *list = NULL;
  int rc = CABLE_SUCCESS;
  if (!P || !Z || !box) { rc = CABLE_ERR_ALLOC; goto done; }
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, zmin = INFINITY,
         zmax = -INFINITY;
  for (int i = 0; i < n; i++) {
    const double *v = xyz + 3 * i;
    P[2 * i] = v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2];
    P[2 * i + 1] = v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2];
    Z[i] = v[0] * nz[0] + v[1] * nz[1] + v[2] * nz[2];
    xmin = fmin(xmin, P[2 * i]); xmax = fmax(xmax, P[2 * i]);
    ymin = fmin(ymin, P[2 * i + 1]); ymax = fmax(ymax, P[2 * i + 1]);
    zmin = fmin(zmin, Z[i]); zmax = fmax(zmax, Z[i]);
  }
  double size = sqrt((xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin) +
                     (zmax - zmin) * (zmax - zmin));
  if (!(size > 0)) { rc = CABLE_ERR_INPUT; goto done; }
  double W = fmax(xmax - xmin, 1e-300 * size), H = fmax(ymax - ymin, 1e-300 * size);
  double cell = sqrt(W * H / n);
  int nx = (int)fmin(W / cell + 1.0, 2048.0), ny = (int)fmin(H / cell + 1.0, 2048.0);
  double cx = W / nx, cy = H / ny;
  long ncell = (long)nx * ny;
  cnt = calloc((size_t)ncell + 1, sizeof *cnt);
  if (!cnt) { rc = CABLE_ERR_ALLOC; goto done; }
  for (int i = 0; i < n; i++) {
    int j = (i + 1) % n;
    int *b = box + 4 * i;
    /* a segment seen end-on has no direction in the plane */
    if (hypot(P[2 * j] - P[2 * i], P[2 * j + 1] - P[2 * i + 1]) <= KT_MIN_MARGIN * size) d->degenerate = 1;
    b[0] = (int)fmin((fmin(P[2 * i], P[2 * j]) - xmin) / cx, nx - 1);
    b[1] = (int)fmin((fmax(P[2 * i], P[2 * j]) - xmin) / cx, nx - 1);
    b[2] = (int)fmin((fmin(P[2 * i + 1], P[2 * j + 1]) - ymin) / cy, ny - 1);
    b[3] = (int)fmin((fmax(P[2 * i + 1], P[2 * j + 1]) - ymin) / cy, ny - 1);
    for (int y = b[2]; y <= b[3]; y++)
      for (int x = b[0]; x <= b[1]; x++) cnt[(long)y * nx + x + 1]++;
  }
  for (long c = 0; c < ncell; c++) cnt[c + 1] += cnt[c];
  list = malloc((size_t)cnt[ncell] * sizeof *list + 1);
  if (!list) { rc = CABLE_ERR_ALLOC; goto done; }
  {
    int *fill = malloc((size_t)ncell * sizeof *fill);
    if (!fill) { rc = CABLE_ERR_ALLOC; goto done; }
    memcpy(fill, cnt, (size_t)ncell * sizeof *fill);
    for (int i = 0; i < n; i++) {
      int *b = box + 4 * i;
      for (int y = b[2]; y <= b[3]; y++)
        for (int x = b[0]; x <= b[1]; x++) list[fill[(long)y * nx + x]++] = i;
    }
    free(fill);
  }
  for (long c = 0; c < ncell && rc == CABLE_SUCCESS; c++) {
    int cxi = (int)(c % nx), cyi = (int)(c / nx);
    for (int u = cnt[c]; u < cnt[c + 1] && rc == CABLE_SUCCESS; u++) {
      for (int v = u + 1; v < cnt[c + 1]; v++) {
        int a = list[u], b = list[v];
        if (a > b) { int t = a; a = b; b = t; }
        if (b == a + 1 || (a == 0 && b == n - 1)) continue;   /* neighbours share a vertex */
        const int *ba = box + 4 * a, *bb = box + 4 * b;
        int fx = ba[0] > bb[0] ? ba[0] : bb[0], fy = ba[2] > bb[2] ? ba[2] : bb[2];
        if (fx != cxi || fy != cyi) continue;                  /* tested in another cell */
        int a1 = (a + 1) % n, b1 = (b + 1) % n;
        double px = P[2 * a], py = P[2 * a + 1], rx = P[2 * a1] - px, ry = P[2 * a1 + 1] - py;
        double qx = P[2 * b], qy = P[2 * b + 1], sx = P[2 * b1] - qx, sy = P[2 * b1 + 1] - qy;
        double den = rx * sy - ry * sx;
        double lr = sqrt(rx * rx + ry * ry), ls = sqrt(sx * sx + sy * sy);
        if (den == 0.0) {
          /* parallel projections: degenerate only if they touch (collinear) */
          double cr = (qx - px) * ry - (qy - py) * rx;
          if (fabs(cr) <= KT_MIN_MARGIN * size * lr) d->degenerate = 1;
          continue;
        }
        double ta = ((qx - px) * sy - (qy - py) * sx) / den;
        double tb = ((qx - px) * ry - (qy - py) * rx) / den;
        /* near misses at a segment end count as degenerate as well */
        double ma = fmin(fabs(ta), fabs(1.0 - ta)) * lr, mb = fmin(fabs(tb), fabs(1.0 - tb)) * ls;
        int inside = ta >= 0.0 && ta < 1.0 && tb >= 0.0 && tb < 1.0;
        int near = ta > -KT_MIN_MARGIN * size / lr && ta < 1.0 + KT_MIN_MARGIN * size / lr &&
                   tb > -KT_MIN_MARGIN * size / ls && tb < 1.0 + KT_MIN_MARGIN * size / ls;
        if (near && (ma < KT_MIN_MARGIN * size || mb < KT_MIN_MARGIN * size)) d->degenerate = 1;
        if (!inside) continue;
        double za = Z[a] + ta * (Z[a1] - Z[a]), zb = Z[b] + tb * (Z[b1] - Z[b]);
        double sn = fabs(den) / (lr * ls);
        if (sn < KT_MIN_SIN || fabs(za - zb) < KT_MIN_GAP * size) d->degenerate = 1;
        if (sn < d->quality) d->quality = sn;
        kt_crossing k;
        if (za > zb) {
          k.seg_o = a; k.par_o = ta; k.seg_u = b; k.par_u = tb;
          k.sign = den > 0 ? 1 : -1;              /* (over x under) . n */
        } else {
          k.seg_o = b; k.par_o = tb; k.seg_u = a; k.par_u = ta;
          k.sign = den > 0 ? -1 : 1;
        }
        d->writhe += k.sign;
        rc = diagram_push(d, &k);
        if (rc != CABLE_SUCCESS) break;
      }
    }
  }
done:
  free(P); free(Z); free(box); free(cnt); free(list);
  return rc;
}

/* ------------------------------------------------------------------ */
/* Gauss code: the 2c passages in order along the curve                */

typedef struct kt_passage {
  int seg;
  double par;
  int k;                       /* crossing */
  int over;                    /* 1: over-passage */
} kt_passage;

static int passage_cmp(const void *a, const void *b)
{
  const kt_passage *x = a, *y = b;
  if (x->seg != y->seg) return x->seg < y->seg ? -1 : 1;
  if (x->par != y->par) return x->par < y->par ? -1 : 1;
  return 0;
}

typedef struct kt_code {
  int c;
  kt_passage *pas;             /* [2c] sorted */
  int *mo, *mu;                /* [c] passage index of the over / under passage */
  int *sign;                   /* [c] crossing signs */
} kt_code;

static void code_free(kt_code *g)
{
  free(g->pas); free(g->mo); free(g->mu); free(g->sign);
}

static int code_build(const kt_diagram *d, kt_code *g)
{
  int c = d->ncross;
  memset(g, 0, sizeof *g);
  g->c = c;
  g->pas = malloc(2 * (size_t)c * sizeof *g->pas + 1);
  g->mo = malloc((size_t)c * sizeof *g->mo + 1);
  g->mu = malloc((size_t)c * sizeof *g->mu + 1);
  g->sign = malloc((size_t)c * sizeof *g->sign + 1);
  if (!g->pas || !g->mo || !g->mu || !g->sign) { code_free(g); return CABLE_ERR_ALLOC; }
  for (int k = 0; k < c; k++) {
    g->pas[2 * k] = (kt_passage){d->cr[k].seg_o, d->cr[k].par_o, k, 1};
    g->pas[2 * k + 1] = (kt_passage){d->cr[k].seg_u, d->cr[k].par_u, k, 0};
    g->sign[k] = d->cr[k].sign;
  }
  qsort(g->pas, 2 * (size_t)c, sizeof *g->pas, passage_cmp);
  for (int m = 0; m < 2 * c; m++) {
    if (m > 0 && passage_cmp(&g->pas[m - 1], &g->pas[m]) == 0) { code_free(g); return CABLE_ERR_INPUT; }
    if (g->pas[m].over) g->mo[g->pas[m].k] = m;
    else g->mu[g->pas[m].k] = m;
  }
  return CABLE_SUCCESS;
}

/* ------------------------------------------------------------------ */
/* Alexander polynomial, exactly                                       */

static const uint64_t kt_primes[] = {2147483647u, 2147483629u, 2147483587u, 2147483579u,
                                     2147483563u, 2147483549u, 2147483543u, 2147483497u,
                                     2147483489u, 2147483477u, 2147483423u, 2147483399u};
#define KT_NPRIMES ((int)(sizeof kt_primes / sizeof kt_primes[0]))
/* Every prime exceeds 2^30.99. */
#define KT_PRIME_BITS 30.99

static uint64_t pow_mod(uint64_t a, uint64_t e, uint64_t p)
{
  uint64_t r = 1;
  a %= p;
  while (e) {
    if (e & 1) r = r * a % p;
    a = a * a % p;
    e >>= 1;
  }
  return r;
}

static uint64_t inv_mod(uint64_t a, uint64_t p) { return pow_mod(a, p - 2, p); }

/* Determinant mod p of the m x m matrix a (row-major, entries in [0,p)), destroyed. */
static uint64_t det_mod(uint64_t *a, int m, uint64_t p)
{
  uint64_t det = 1;
  for (int col = 0; col < m; col++) {
    int piv = -1;
    for (int r = col; r < m; r++)
      if (a[(size_t)r * m + col]) { piv = r; break; }
    if (piv < 0) return 0;
    if (piv != col) {
      for (int k = 0; k < m; k++) {
        uint64_t t = a[(size_t)piv * m + k];
        a[(size_t)piv * m + k] = a[(size_t)col * m + k];
        a[(size_t)col * m + k] = t;
      }
      det = (p - det) % p;
    }
    uint64_t pv = a[(size_t)col * m + col];
    det = det * pv % p;
    uint64_t ip = inv_mod(pv, p);
    for (int r = col + 1; r < m; r++) {
      uint64_t f = a[(size_t)r * m + col] * ip % p;
      if (!f) continue;
      for (int k = col; k < m; k++)
        a[(size_t)r * m + k] = (a[(size_t)r * m + k] + (p - f) * a[(size_t)col * m + k]) % p;
    }
  }
  return det;
}

/* Coefficients mod p of the polynomial of degree <= m through (x_i, y_i),
 * x_i = i + 1 (Newton divided differences, then expansion). */
static void interp_mod(const uint64_t *y, int npt, uint64_t p, uint64_t *coef, uint64_t *work)
{
  uint64_t *dd = work;
  for (int i = 0; i < npt; i++) dd[i] = y[i];
  for (int k = 1; k < npt; k++)
    for (int i = npt - 1; i >= k; i--) {
      uint64_t num = (dd[i] + p - dd[i - 1]) % p;
      dd[i] = num * inv_mod((uint64_t)k, p) % p;     /* x_i - x_{i-k} = k */
    }
  for (int i = 0; i < npt; i++) coef[i] = 0;
  for (int k = npt - 1; k >= 0; k--) {                 /* Horner on Newton form */
    /* coef <- coef * (x - x_k) + dd[k], x_k = k + 1 */
    uint64_t xk = (uint64_t)(k + 1) % p;
    for (int i = npt - 1; i >= 1; i--) coef[i] = (coef[i - 1] + (p - xk) * coef[i] % p) % p;
    coef[0] = ((p - xk) * coef[0] % p + dd[k]) % p;
  }
}

static int alexander(const kt_code *g, kt_invariants *inv)
{
  int c = g->c;
  if (c <= 1) {                              /* no crossing or a single kink */
    inv->deg = 0;
    inv->alex[0] = 1;
    inv->det = 1;
    return CABLE_SUCCESS;
  }
  /* arcs: arc a starts at the a-th under-passage (counted from the first one) */
  int *ov = malloc((size_t)c * sizeof *ov), *in = malloc((size_t)c * sizeof *in),
      *out = malloc((size_t)c * sizeof *out);
  int m = c - 1, npt = m + 1;
  double bits = fmax(2.0 * m + 1.0, 63.0) + 2.0;        /* Hadamard bound 4^m, certificate */
  int np = (int)ceil(bits / KT_PRIME_BITS);
  uint64_t *a = malloc((size_t)m * m * sizeof *a), *val = malloc((size_t)npt * sizeof *val);
  uint64_t *res = malloc((size_t)KT_NPRIMES * npt * sizeof *res), *work = malloc((size_t)npt * sizeof *work);
  int rc = CABLE_SUCCESS;
  if (!ov || !in || !out || !a || !val || !res || !work) { rc = CABLE_ERR_ALLOC; goto done; }
  if (np > KT_NPRIMES) { rc = CABLE_ERR_UNSUPPORTED; goto done; }
  int m0 = 0;
  while (g->pas[m0].over) m0++;
  int arc = -1;
  for (int i = 0; i < 2 * c; i++) {
    const kt_passage *ps = &g->pas[(m0 + i) % (2 * c)];
    if (ps->over) ov[ps->k] = arc;
    else {
      arc++;
      in[ps->k] = (arc - 1 + c) % c;
      out[ps->k] = arc;
    }
  }
  for (int ip = 0; ip < np; ip++) {
    uint64_t p = kt_primes[ip];
    for (int e = 0; e < npt; e++) {
      uint64_t x = (uint64_t)(e + 1);
      memset(a, 0, (size_t)m * m * sizeof *a);
      /* Fox derivatives of the Wirtinger relation, abelianised, one row per
       * crossing: (1 - t) at the over-arc, t and -1 at the incoming and
       * outgoing under-arcs, swapped for a negative crossing.  Row and column
       * c-1 are deleted. */
      for (int k = 0; k < m; k++) {
        uint64_t one_t = (1 + p - x) % p, tt = x % p, mone = p - 1;
        int cols[3] = {ov[k], in[k], out[k]};
        uint64_t v3[3] = {one_t, g->sign[k] > 0 ? tt : mone, g->sign[k] > 0 ? mone : tt};
        for (int q = 0; q < 3; q++)
          if (cols[q] < m) a[(size_t)k * m + cols[q]] = (a[(size_t)k * m + cols[q]] + v3[q]) % p;
      }
      val[e] = det_mod(a, m, p);
    }
    interp_mod(val, npt, p, res + (size_t)ip * npt, work);
  }
  /* lift: Garner on the first two primes (|value| < p0 p1 / 2 < 2^61), then
   * every further prime must agree; with the primes' product above
   * 2 * 4^m + 2^63 agreement certifies the value */
  long coef[CABLE_KNOT_TYPE_MAX_DEGREE + 2];
  int lo = -1, hi = -1;
  uint64_t p0 = kt_primes[0], p1 = kt_primes[1];
  uint64_t i01 = inv_mod(p0 % p1, p1);
  for (int i = 0; i < npt; i++) {
    uint64_t r0 = res[i], r1 = res[(size_t)npt + i];
    uint64_t k1 = (r1 + p1 - r0 % p1) % p1 * i01 % p1;
    int64_t v = (int64_t)(r0 + p0 * k1);
    int64_t P01 = (int64_t)(p0 * p1);
    if (v > P01 / 2) v -= P01;
    for (int ip = 2; ip < np; ip++) {
      int64_t pk = (int64_t)kt_primes[ip];
      int64_t vm = ((v % pk) + pk) % pk;
      if ((uint64_t)vm != res[(size_t)ip * npt + i]) { rc = CABLE_ERR_UNSUPPORTED; goto done; }
    }
    if (v != 0) {
      if (lo < 0) lo = i;
      hi = i;
    }
    if (lo >= 0 && i - lo > CABLE_KNOT_TYPE_MAX_DEGREE) { rc = CABLE_ERR_UNSUPPORTED; goto done; }
    if (lo >= 0) coef[i - lo] = v;
  }
  if (lo < 0) { rc = CABLE_ERR_INPUT; goto done; }      /* Delta = 0: not a knot diagram */
  inv->deg = hi - lo;
  long s1 = 0, sm1 = 0;
  for (int i = 0; i <= inv->deg; i++) {
    s1 += coef[i];
    sm1 += (i % 2 ? -1 : 1) * coef[i];
  }
  if (s1 != 1 && s1 != -1) { rc = CABLE_ERR_INPUT; goto done; }   /* Delta(1) = +-1 for knots */
  for (int i = 0; i <= inv->deg; i++) {
    inv->alex[i] = s1 * coef[i];
    if (coef[i] != coef[inv->deg - i]) { rc = CABLE_ERR_INPUT; goto done; }  /* symmetric */
  }
  inv->det = labs(sm1);
done:
  free(ov); free(in); free(out); free(a); free(val); free(res); free(work);
  return rc;
}

/* ------------------------------------------------------------------ */
/* signature: Goeritz matrix and the Gordon-Litherland correction      */

/* Darts: edge e runs from passage e to passage e+1 (mod 2c); dart 2e leaves
 * passage e forwards, dart 2e+1 leaves passage e+1 backwards; twin = d ^ 1.
 * At a crossing the four darts in anticlockwise order are
 *   sign > 0: out-over, out-under, in-over, in-under
 *   sign < 0: out-over, in-under,  in-over, out-under
 * The face to the left of dart d continues with the dart next clockwise from
 * twin(d) at its origin; the face of d is the sector anticlockwise after d. */
static int signature_gl(const kt_code *g, long det_expected, int *sigma)
{
  int c = g->c;
  if (c <= 1) { *sigma = 0; return CABLE_SUCCESS; }
  int nd = 4 * c;
  int *ord = malloc(4 * (size_t)c * sizeof *ord), *dcr = malloc((size_t)nd * sizeof *dcr),
      *dpos = malloc((size_t)nd * sizeof *dpos), *face = malloc((size_t)nd * sizeof *face);
  int *col = malloc(((size_t)c + 2) * sizeof *col), *widx = malloc(((size_t)c + 2) * sizeof *widx);
  double *G = NULL, *ev = NULL;
  int rc = CABLE_SUCCESS;
  if (!ord || !dcr || !dpos || !face || !col || !widx) { rc = CABLE_ERR_ALLOC; goto done; }
  int n2 = 2 * c;
  for (int k = 0; k < c; k++) {
    int oo = 2 * g->mo[k], io = 2 * ((g->mo[k] - 1 + n2) % n2) + 1;
    int ou = 2 * g->mu[k], iu = 2 * ((g->mu[k] - 1 + n2) % n2) + 1;
    int *o = ord + 4 * k;
    o[0] = oo; o[2] = io;
    if (g->sign[k] > 0) { o[1] = ou; o[3] = iu; }
    else { o[1] = iu; o[3] = ou; }
    for (int i = 0; i < 4; i++) { dcr[o[i]] = k; dpos[o[i]] = i; }
  }
  for (int d = 0; d < nd; d++) face[d] = -1;
  int nf = 0;
  for (int d0 = 0; d0 < nd; d0++) {
    if (face[d0] >= 0) continue;
    int d = d0;
    do {
      face[d] = nf;
      int t = d ^ 1;
      d = ord[4 * dcr[t] + (dpos[t] + 3) % 4];
    } while (face[d] < 0);
    if (d != d0) { rc = CABLE_ERR_INPUT; goto done; }
    nf++;
  }
  if (nf != c + 2) { rc = CABLE_ERR_INPUT; goto done; }   /* Euler: V - E + F = 2 */
  /* checkerboard colouring: the two sides of every edge differ */
  for (int f = 0; f < nf; f++) col[f] = -1;
  col[face[0]] = 0;
  for (int changed = 1; changed;) {
    changed = 0;
    for (int d = 0; d < nd; d++) {
      int a = face[d], b = face[d ^ 1];
      if (col[a] >= 0 && col[b] < 0) { col[b] = 1 - col[a]; changed = 1; }
      else if (col[b] >= 0 && col[a] < 0) { col[a] = 1 - col[b]; changed = 1; }
    }
  }
  for (int d = 0; d < nd; d++)
    if (col[face[d]] < 0 || col[face[d]] == col[face[d ^ 1]]) { rc = CABLE_ERR_INPUT; goto done; }
  G = malloc(((size_t)c + 2) * ((size_t)c + 2) * sizeof *G);
  ev = malloc(((size_t)c + 2) * sizeof *ev);
  if (!G || !ev) { rc = CABLE_ERR_ALLOC; goto done; }
  int sig[2];
  for (int white = 0; white < 2; white++) {
    int nw = 0;
    for (int f = 0; f < nf; f++) widx[f] = col[f] == white ? nw++ : -1;
    int m = nw - 1;                               /* white region 0 deleted */
    if (m > 0) memset(G, 0, (size_t)m * m * sizeof *G);
    int mu = 0;
    for (int k = 0; k < c; k++) {
      const int *o = ord + 4 * k;
      /* rotating the over-strand anticlockwise sweeps the sectors after
       * out-over and after in-over; eta = -1 when they are white, +1 when black
       * (so that the closed positive 2-braid has sigma = 1 - n) */
      int swept_white = col[face[o[0]]] == white;
      int eta = swept_white ? -1 : 1;
      int fa = swept_white ? face[o[0]] : face[o[1]];
      int fb = swept_white ? face[o[2]] : face[o[3]];
      /* the swept sectors lie between two outgoing (and two incoming) strands
       * exactly when sign > 0; type II: the white sectors are the mixed ones */
      int white_mixed = swept_white ? g->sign[k] < 0 : g->sign[k] > 0;
      if (white_mixed) mu += eta;
      int ia = widx[fa], ib = widx[fb];
      if (ia == ib) continue;                       /* nugatory crossing */
      if (ia > 0 && ib > 0) {
        G[(size_t)(ia - 1) * m + ib - 1] -= eta;
        G[(size_t)(ib - 1) * m + ia - 1] -= eta;
      }
      if (ia > 0) G[(size_t)(ia - 1) * m + ia - 1] += eta;
      if (ib > 0) G[(size_t)(ib - 1) * m + ib - 1] += eta;
    }
    int sgn = 0;
    if (m > 0) {
      if (LAPACKE_dsyev(LAPACK_COL_MAJOR, 'N', 'U', m, G, m, ev) != 0) { rc = CABLE_ERR_LINSOLVE; goto done; }
      double emax = 0.0, logdet = 0.0;
      for (int i = 0; i < m; i++) emax = fmax(emax, fabs(ev[i]));
      for (int i = 0; i < m; i++) {
        if (fabs(ev[i]) <= KT_EIG_RTOL * emax) { rc = CABLE_ERR_INPUT; goto done; }
        sgn += ev[i] > 0 ? 1 : -1;
        logdet += log(fabs(ev[i]));
      }
      if (fabs(exp(logdet) - (double)det_expected) > KT_DET_RTOL * (double)det_expected) {
        rc = CABLE_ERR_INPUT;                       /* |det G| must be |Delta(-1)| */
        goto done;
      }
    } else if (det_expected != 1) { rc = CABLE_ERR_INPUT; goto done; }
    sig[white] = sgn - mu;
  }
  if (sig[0] != sig[1]) { rc = CABLE_ERR_INPUT; goto done; }
  *sigma = sig[0];
done:
  free(ord); free(dcr); free(dpos); free(face); free(col); free(widx); free(G); free(ev);
  return rc;
}

/* ------------------------------------------------------------------ */
/* identification                                                      */

static int gcd_int(int a, int b)
{
  while (b) { int t = a % b; a = b; b = t; }
  return a;
}

int knot_type_torus_crossings(int p, int q)
{
  int a = p * (q - 1), b = q * (p - 1);
  return a < b ? a : b;
}

int knot_type_torus_alexander(int p, int q, long *coef, int maxdeg)
{
  if (p < 1 || q < 1 || gcd_int(p, q) != 1 || !coef) return -1;
  int deg = (p - 1) * (q - 1);
  if (deg > maxdeg) return -1;
  int nn = p * q + 1;
  long *num = calloc((size_t)nn + 1, sizeof *num);
  if (!num) return -1;
  /* (t^pq - 1)(t - 1) */
  num[0] = 1; num[1] = -1; num[p * q] = -1; num[p * q + 1] = 1;
  int top = p * q + 1;
  /* divide by the monic t^p - 1, then t^q - 1 (exact) */
  int dv[2] = {p, q};
  for (int s = 0; s < 2; s++) {
    int e = dv[s];
    long *quo = calloc((size_t)top + 1, sizeof *quo);
    if (!quo) { free(num); return -1; }
    for (int i = top; i >= e; i--) {
      long f = num[i];
      quo[i - e] = f;
      num[i] -= f;
      num[i - e] += f;
    }
    top -= e;
    memcpy(num, quo, ((size_t)top + 1) * sizeof *num);
    for (int i = top + 1; i <= nn; i++) num[i] = 0;
    free(quo);
  }
  for (int i = 0; i <= deg; i++) coef[i] = num[i];
  free(num);
  return deg;
}

static int same_poly(const long *a, int da, const long *b, int db)
{
  if (da != db) return 0;
  for (int i = 0; i <= da; i++)
    if (a[i] != b[i]) return 0;
  return 1;
}

static void identify(const kt_invariants *inv, cable_knot_type_result *out)
{
  out->torus_p = out->torus_q = 0;
  out->handedness = 0;
  out->crossing_number = -1;
  snprintf(out->name, sizeof out->name, "unknown");
  static const long fig8[3] = {-1, 3, -1};
  if (inv->deg == 0 && inv->alex[0] == 1) {
    snprintf(out->name, sizeof out->name, "unknot");
    out->crossing_number = 0;
    return;
  }
  if (same_poly(inv->alex, inv->deg, fig8, 2)) {
    snprintf(out->name, sizeof out->name, "figure-eight");
    out->crossing_number = 4;
    return;
  }
  long tp[CABLE_KNOT_TYPE_MAX_DEGREE + 1];
  for (int q = 2; (q - 1) * (q - 1) < inv->deg + 1 || q == 2; q++) {
    if ((q - 1) == 0 || inv->deg % (q - 1) != 0) continue;
    int p = inv->deg / (q - 1) + 1;
    if (p <= q || gcd_int(p, q) != 1) continue;
    int d = knot_type_torus_alexander(p, q, tp, CABLE_KNOT_TYPE_MAX_DEGREE);
    if (d < 0 || !same_poly(inv->alex, inv->deg, tp, d)) continue;
    out->torus_p = p;
    out->torus_q = q;
    out->crossing_number = knot_type_torus_crossings(p, q);
    if (p == 3 && q == 2) snprintf(out->name, sizeof out->name, "trefoil");
    else snprintf(out->name, sizeof out->name, "torus(%d,%d)", p, q);
    out->handedness = inv->signature < 0 ? 1 : (inv->signature > 0 ? -1 : 0);
    return;
  }
}

static int invariants_of(const kt_diagram *d, kt_invariants *inv)
{
  if (d->ncross > KNOT_TYPE_MAX_CROSSINGS) return CABLE_ERR_UNSUPPORTED;
  kt_code g;
  int rc = code_build(d, &g);
  if (rc != CABLE_SUCCESS) return rc;
  rc = alexander(&g, inv);
  if (rc == CABLE_SUCCESS) rc = signature_gl(&g, inv->det, &inv->signature);
  code_free(&g);
  return rc;
}

static int check_input(const double *xyz, int n, const cable_knot_type_result *out)
{
  if (!xyz || !out || n < 3) return CABLE_ERR_INPUT;
  for (long i = 0; i < 3L * n; i++)
    if (!isfinite(xyz[i])) return CABLE_ERR_NONFINITE;
  return CABLE_SUCCESS;
}

typedef struct kt_diagram_info {
  double dir[3];
  int ncross, writhe;
} kt_diagram_info;

static void fill_result(const kt_invariants *inv, const kt_diagram_info *d, int nagree,
                        cable_knot_type_result *out)
{
  memset(out, 0, sizeof *out);
  out->alex_degree = inv->deg;
  memcpy(out->alex, inv->alex, ((size_t)inv->deg + 1) * sizeof *out->alex);
  out->determinant = inv->det;
  out->signature = inv->signature;
  out->ncross = d->ncross;
  out->diagram_writhe = d->writhe;
  double nn = sqrt(d->dir[0] * d->dir[0] + d->dir[1] * d->dir[1] + d->dir[2] * d->dir[2]);
  for (int i = 0; i < 3; i++) out->dir[i] = d->dir[i] / nn;
  out->nagree = nagree;
  identify(inv, out);
}

int knot_type_identify_dir(const double *xyz, int n, const double dir[3], cable_knot_type_result *out)
{
  int rc = check_input(xyz, n, out);
  if (rc != CABLE_SUCCESS) return rc;
  if (!dir || !isfinite(dir[0]) || !isfinite(dir[1]) || !isfinite(dir[2]) ||
      !(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2] > 0))
    return CABLE_ERR_INPUT;
  kt_diagram d = {0};
  kt_invariants inv;
  rc = diagram_build(xyz, n, dir, &d);
  if (rc == CABLE_SUCCESS && d.degenerate) rc = CABLE_ERR_INPUT;
  if (rc == CABLE_SUCCESS) rc = invariants_of(&d, &inv);
  if (rc == CABLE_SUCCESS) {
    kt_diagram_info info = {{dir[0], dir[1], dir[2]}, d.ncross, d.writhe};
    fill_result(&inv, &info, 1, out);
  }
  free(d.cr);
  return rc;
}

typedef struct kt_candidate {
  double dir[3];
  int ncross;
  double quality;
} kt_candidate;

static int candidate_cmp(const void *a, const void *b)
{
  const kt_candidate *x = a, *y = b;
  if (x->ncross != y->ncross) return x->ncross < y->ncross ? -1 : 1;
  if (x->quality != y->quality) return x->quality > y->quality ? -1 : 1;
  return 0;
}

static int same_invariants(const kt_invariants *a, const kt_invariants *b)
{
  return a->signature == b->signature && same_poly(a->alex, a->deg, b->alex, b->deg);
}

int knot_type_identify(const double *xyz, int n, cable_knot_type_result *out)
{
  int rc = check_input(xyz, n, out);
  if (rc != CABLE_SUCCESS) return rc;
  kt_candidate cand[KNOT_TYPE_NDIRS];
  int ncand = 0;
  kt_diagram d = {0};
  /* Fibonacci lattice on the upper hemisphere: well spread, and generic for
   * curves with the usual symmetry axes (no lattice point lies on an axis) */
  const double golden = M_PI * (3.0 - sqrt(5.0));
  for (int i = 0; i < KNOT_TYPE_NDIRS; i++) {
    double z = (i + 0.5) / KNOT_TYPE_NDIRS, rr = sqrt(1.0 - z * z), ph = golden * i;
    double dir[3] = {rr * cos(ph), rr * sin(ph), z};
    rc = diagram_build(xyz, n, dir, &d);
    if (rc != CABLE_SUCCESS) goto done;
    if (d.degenerate) continue;
    cand[ncand] = (kt_candidate){{dir[0], dir[1], dir[2]}, d.ncross, d.quality};
    ncand++;
  }
  if (ncand == 0) { rc = CABLE_ERR_INPUT; goto done; }
  qsort(cand, (size_t)ncand, sizeof *cand, candidate_cmp);
  /* invariants of the projections in order of increasing crossings, until
   * two agree; the earlier (simpler) of the two is reported */
  kt_invariants got[KT_MAX_TRIES];
  kt_diagram_info info[KT_MAX_TRIES];
  int ngot = 0, tried = 0, first_err = CABLE_SUCCESS;
  for (int i = 0; i < ncand && tried < KT_MAX_TRIES; i++, tried++) {
    if (cand[i].ncross > KNOT_TYPE_MAX_CROSSINGS) break;
    rc = diagram_build(xyz, n, cand[i].dir, &d);
    if (rc != CABLE_SUCCESS) goto done;
    rc = invariants_of(&d, &got[ngot]);
    if (rc == CABLE_ERR_ALLOC) goto done;
    if (rc != CABLE_SUCCESS) {
      if (first_err == CABLE_SUCCESS) first_err = rc;
      continue;
    }
    info[ngot] = (kt_diagram_info){{cand[i].dir[0], cand[i].dir[1], cand[i].dir[2]}, d.ncross, d.writhe};
    for (int k = 0; k < ngot; k++) {
      if (!same_invariants(&got[k], &got[ngot])) continue;
      int nag = 0;
      for (int j = 0; j <= ngot; j++) nag += same_invariants(&got[j], &got[k]);
      fill_result(&got[k], &info[k], nag, out);
      rc = CABLE_SUCCESS;
      goto done;
    }
    ngot++;
  }
  rc = first_err != CABLE_SUCCESS ? first_err : CABLE_ERR_UNSUPPORTED;
done:
  free(d.cr);
  return rc;
}
