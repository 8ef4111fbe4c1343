/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Structured LU of the collocation Newton matrix: local condensation with
 * partial pivoting, then banded LU with partial pivoting of the augmented
 * mesh-point system.  doc/linear-algebra.md explains the augmented system,
 * the orderings below and why the determinant of J is recovered exactly.
 *
 * Augmented unknowns at mesh point j (0..ntst), "z_j", m of them, in order
 *   c_j (ndim)  copy of u(0)
 *   q_j (nfpr)  copy of the free parameters (q_0 is the true parameter vector)
 *   u_j (ndim)  the mesh-point value
 *   s_j (nq)    running sums of the dense rows over intervals 0..j-1
 * Band rows, in order:
 *   start (ndim + nq):  c_0 - u_0 = 0,  s_0 = 0
 *   interval j (m):     c_{j+1} - c_j = 0 (ndim), q_{j+1} - q_j = 0 (nfpr),
 *                       the ndim+nq condensed rows of interval j
 *   end (nbc + nq):     b(c_N, u_N, q_N),  s_N + dense_par q_N = rhs
 * Interval j's local rows ("slots"): its ncol*ndim collocation rows (which use
 * the parameter copy q_{j+1}) then nq running-sum rows
 *   s_{j+1} - s_j - D_j x_j = 0.
 * Local columns: the (ncol-1)*ndim interior unknowns, then the "outer" ones
 *   u_j, u_{j+1}, q_{j+1}, s_j, s_{j+1}. */
#include "abd_solver.h"

#include "abd_band.h"
#include "cable_team.h"

#include <cblas.h>
#include <lapacke.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { STATE_NONE = 0, STATE_OK = 1, STATE_SINGULAR = 2 };

/* Intervals the condensation may run ahead of the band elimination
 * (cable_team_run_ordered_window).  The band storage holds the columns of
 * ABD_LOOKAHEAD + 1 intervals as a ring (abd_band_set_ring): interval j
 * writes the columns of z_j and z_{j+1}, the elimination after interval i
 * has left the columns of z_0..z_i zero, so the live columns span at most
 * (ABD_LOOKAHEAD + 1) m (and m + kl + ku for the elimination's own reach).
 * On the flat (7,2) knot at NTST 150: 0.9 MB of band storage instead of
 * 7.8 MB. */
#define ABD_LOOKAHEAD 16



struct abd_solver {
  int nd, N, nc, nf, nb, nint, nq; /* sizes of colloc_jac.h; nq = nint + 1 */
  int n;                           /* unknowns of J */
  int nr;                          /* collocation rows per interval, ncol*ndim */
  int nI;                          /* interior unknowns per interval, (ncol-1)*ndim */
  int r;                           /* local rows per interval, nr + nq */
  int nO;                          /* outer local columns, 2*ndim + nfpr + 2*nq */
  int m;                           /* augmented unknowns per mesh point */
  int a;                           /* start rows, ndim + nq */
  int nband;                       /* order of the banded system, (N+1)*m */
  int kl, ku, ldab;                /* band widths and LAPACK leading dimension */
  int off_c, off_q, off_u, off_s;  /* offsets inside z_j */
  int *omap;                       /* [nO] band column of outer column o, relative to j*m */
  int perm_sign;                   /* parity of the structural reordering (see factor) */
  size_t loc_size;                 /* doubles per local block, r*(nI+nO) */
  double *loc;                     /* [N] local blocks after condensation: L\U | X over S */
  lapack_int *loc_piv;             /* [N*nI] local row interchanges */
  double *ab;                      /* [ldab*ring] banded LU, a ring of columns (ABD_LOOKAHEAD) */
  int ring;                        /* its columns */
  abd_band band;                   /* its LU factors, compressed (abd_band.h) */
  double *w_rhs;                   /* [nband] band right-hand side, per vector of a block */
  double *w_piv;                   /* [N*nI] transformed pivot-row right-hand sides, per vector */
  double *w_loc;                   /* [r] one interval's local right-hand side */
  double *w_o;                     /* [nO] one interval's outer values */
  int state;                       /* STATE_* */
  int band_overflow;               /* an entry fell outside kl/ku (internal error) */
  int det_sign;
  double det_log;
  double growth_band, amax;        /* max |U| of the band stage, max |entry| of the augmented matrix */
  /* per-interval results of the parallel stages, reduced in interval order
     (the same numbers for every thread count) */
  cable_team *team;                /* threads for the per-interval stages (NULL: none) */
  int team_borrowed;               /* 1: team is the caller's (abd_solver_use_team), not freed here */
  int *iv_status;                  /* [N] 0 ok, 1 singular, -1 LAPACK, -2 non-finite, -3 band overflow */
  int *iv_sign;                    /* [N] sign of the interval's pivots and interchanges */
  double *iv_logabs;               /* [N] sum of log |pivot| */
  double *iv_amax;                 /* [N] max |entry| of the local block */
  double *iv_sumsq;                /* [N] sum of squares of J's collocation blocks (smallest_sv) */
  double *w_g;                     /* [N*r] per-interval local right-hand sides, per vector */
  double *w_oo;                    /* [N*nO] per-interval outer values, per vector */
  /* right-hand sides whose forward stage was done by the factorisation
     (abd_solver_factor_prepared): their copy, and how many of them the w_
     buffers still hold that stage for (0: none; a solve of anything uses
     them up); behind a pointer because the solves take a const solver */
  double *prep;                    /* [ABD_SOLVE_BLOCK*n] */
  int *prep_k;
  /* smallest_sv workspace, grown on demand */
  int sv_k;
  double *sv_v, *sv_w, *sv_b, *sv_r, *sv_x, *sv_yt, *sv_s, *sv_work, *sv_vec, *sv_res, *sv_rn;
  double *sv_rest, *sv_pair;       /* J^T residuals, colloc_jac_matvec_pair_team's scratch */
  lapack_int sv_lwork;
};

/* Band column of component i of block `off` of z_j. */
static int zcol(const abd_solver *s, int j, int off, int i) { return j * s->m + off + i; }
/* First band row of interval j's group. */
static int grow_base(const abd_solver *s, int j) { return s->a + j * s->m; }
static int end_base(const abd_solver *s) { return s->a + s->N * s->m; }
static double *loc_block(const abd_solver *s, int j) { return s->loc + (size_t)j * s->loc_size; }

/* Writes one band entry into the ring's storage column sc of column col; 1
 * when it falls outside kl/ku (internal error). */
static int band_set_slot(const abd_solver *s, int row, int col, size_t sc, double v)
{
  int d = row - col;
  if (d > s->kl || -d > s->ku) return 1;
  s->ab[sc * (size_t)s->ldab + (size_t)(s->kl + s->ku + d)] = v;
  return 0;
}

static int band_set(const abd_solver *s, int row, int col, double v)
{
  return band_set_slot(s, row, col, (size_t)(col % s->ring), v);
}

/* Interval j's entries (columns j m .. j m + 2 m - 1 < j m + ring): the
 * storage column from the slot of column j m, without a division. */
static int band_set_iv(const abd_solver *s, size_t base, int j, int row, int col, double v)
{
  size_t sc = base + (size_t)(col - j * s->m);
  if (sc >= (size_t)s->ring) sc -= (size_t)s->ring;
  return band_set_slot(s, row, col, sc, v);
}

static void band_put(abd_solver *s, int row, int col, double v)
{
  if (band_set(s, row, col, v)) s->band_overflow = 1;
}

static void extent_update(int row, int col, int *kl, int *ku)
{
  if (row - col > *kl) *kl = row - col;
  if (col - row > *ku) *ku = col - row;
}

/* Band widths from the structural nonzeros of every band row (the same
 * enumeration as factor's assembly; band_put checks the agreement). */
static void band_extent(abd_solver *s)
{
  int kl = 0, ku = 0;
  for (int i = 0; i < s->nd; i++) {
    extent_update(i, zcol(s, 0, s->off_c, i), &kl, &ku);
    extent_update(i, zcol(s, 0, s->off_u, i), &kl, &ku);
  }
  for (int d = 0; d < s->nq; d++) extent_update(s->nd + d, zcol(s, 0, s->off_s, d), &kl, &ku);
  for (int j = 0; j < s->N; j++) {
    int g = grow_base(s, j);
    for (int i = 0; i < s->nd; i++) {
      extent_update(g + i, zcol(s, j, s->off_c, i), &kl, &ku);
      extent_update(g + i, zcol(s, j + 1, s->off_c, i), &kl, &ku);
    }
    for (int p = 0; p < s->nf; p++) {
      extent_update(g + s->nd + p, zcol(s, j, s->off_q, p), &kl, &ku);
      extent_update(g + s->nd + p, zcol(s, j + 1, s->off_q, p), &kl, &ku);
    }
    for (int k = 0; k < s->r - s->nI; k++)
      for (int o = 0; o < s->nO; o++) extent_update(g + s->nd + s->nf + k, j * s->m + s->omap[o], &kl, &ku);
  }
  int e = end_base(s);
  for (int b = 0; b < s->nb; b++) {
    for (int i = 0; i < s->nd; i++) {
      extent_update(e + b, zcol(s, s->N, s->off_c, i), &kl, &ku);
      extent_update(e + b, zcol(s, s->N, s->off_u, i), &kl, &ku);
    }
    for (int p = 0; p < s->nf; p++) extent_update(e + b, zcol(s, s->N, s->off_q, p), &kl, &ku);
  }
  for (int d = 0; d < s->nq; d++) {
    for (int p = 0; p < s->nf; p++) extent_update(e + s->nb + d, zcol(s, s->N, s->off_q, p), &kl, &ku);
    extent_update(e + s->nb + d, zcol(s, s->N, s->off_s, d), &kl, &ku);
  }
  s->kl = kl;
  s->ku = ku;
  s->ldab = 2 * kl + ku + 1;
}

/* ---- sign of the structural reordering --------------------------------
 * Canonical augmented matrix M: rows = the n equations of J (dense rows
 * replaced by the final rows s_N + dense_par q = rhs), then the definition
 * rows of the extra unknowns; columns = the n unknowns of J, then the extras.
 * Ordered so, the definitions form a unit lower bidiagonal block and
 * det M = det J (block elimination of the extras).  The factorisation works
 * on M with rows and columns permuted to "final" order (interior pivot rows
 * and interior unknowns first, then the band order); perm_sign is the product
 * of the parities of those two permutations. */
static long canon_cdef(const abd_solver *s, int j, int i) { return s->n + (long)j * s->nd + i; }
static long canon_qdef(const abd_solver *s, int j, int p) /* j >= 1 */
{
  return s->n + (long)(s->N + 1) * s->nd + (long)(j - 1) * s->nf + p;
}
static long canon_sdef(const abd_solver *s, int j, int d)
{
  return s->n + (long)(s->N + 1) * s->nd + (long)s->N * s->nf + (long)j * s->nq + d;
}
/* Canonical row of slot k of interval j. */
static long canon_slot(const abd_solver *s, int j, int k)
{
  return k < s->nr ? (long)j * s->nr + k : canon_sdef(s, j + 1, k - s->nr);
}
/* Canonical column of band column (j, off, i). */
static long canon_zcol(const abd_solver *s, int j, int off, int i)
{
  if (off == s->off_u) return (long)j * s->nr + i;
  if (off == s->off_c) return canon_cdef(s, j, i);
  if (off == s->off_q) return j == 0 ? s->n - s->nf + i : canon_qdef(s, j, i);
  return canon_sdef(s, j, i);
}

static int perm_parity(const long *p, long len, unsigned char *seen)
{
  long cycles = 0;
  memset(seen, 0, (size_t)len);
  for (long i = 0; i < len; i++) {
    if (seen[i]) continue;
    cycles++;
    for (long k = i; !seen[k]; k = p[k]) seen[k] = 1;
  }
  return ((len - cycles) % 2) ? -1 : 1;
}

static int structural_sign(abd_solver *s)
{
  long len = (long)s->N * s->nI + s->nband;
  long *p = malloc((size_t)len * sizeof *p);
  unsigned char *seen = malloc((size_t)len);
  if (!p || !seen) {
    free(p);
    free(seen);
    return 0;
  }
  /* rows */
  long f = 0;
  for (int j = 0; j < s->N; j++)
    for (int k = 0; k < s->nI; k++) p[f++] = canon_slot(s, j, k);
  for (int i = 0; i < s->nd; i++) p[f++] = canon_cdef(s, 0, i);
  for (int d = 0; d < s->nq; d++) p[f++] = canon_sdef(s, 0, d);
  for (int j = 0; j < s->N; j++) {
    for (int i = 0; i < s->nd; i++) p[f++] = canon_cdef(s, j + 1, i);
    for (int q = 0; q < s->nf; q++) p[f++] = canon_qdef(s, j + 1, q);
    for (int k = s->nI; k < s->r; k++) p[f++] = canon_slot(s, j, k);
  }
  for (int b = 0; b < s->nb + s->nq; b++) p[f++] = (long)s->N * s->nr + b;
  int sign = perm_parity(p, len, seen);
  /* columns */
  f = 0;
  for (int j = 0; j < s->N; j++)
    for (int t = 0; t < s->nI; t++) p[f++] = (long)j * s->nr + s->nd + t;
  for (int j = 0; j <= s->N; j++) {
    for (int i = 0; i < s->nd; i++) p[f++] = canon_zcol(s, j, s->off_c, i);
    for (int q = 0; q < s->nf; q++) p[f++] = canon_zcol(s, j, s->off_q, q);
    for (int i = 0; i < s->nd; i++) p[f++] = canon_zcol(s, j, s->off_u, i);
    for (int d = 0; d < s->nq; d++) p[f++] = canon_zcol(s, j, s->off_s, d);
  }
  sign *= perm_parity(p, len, seen);
  free(p);
  free(seen);
  return sign;
}

abd_solver *abd_solver_alloc(int ndim, int ntst, int ncol, int nfpr, int nbc, int nint)
{
  if (ndim < 1 || ntst < 1 || ncol < 1 || nfpr < 0 || nbc < 0 || nint < 0) return NULL;
  if (nbc + nint + 1 != ndim + nfpr) return NULL;
  abd_solver *s = calloc(1, sizeof *s);
  if (!s) return NULL;
  s->nd = ndim;
  s->N = ntst;
  s->nc = ncol;
  s->nf = nfpr;
  s->nb = nbc;
  s->nint = nint;
  s->nq = nint + 1;
  s->n = ndim * (ntst * ncol + 1) + nfpr;
  s->nr = ncol * ndim;
  s->nI = (ncol - 1) * ndim;
  s->r = s->nr + s->nq;
  s->nO = 2 * ndim + nfpr + 2 * s->nq;
  s->m = 2 * ndim + nfpr + s->nq;
  s->a = ndim + s->nq;
  s->nband = (ntst + 1) * s->m;
  s->off_c = 0;
  s->off_q = ndim;
  s->off_u = ndim + nfpr;
  s->off_s = 2 * ndim + nfpr;
  s->loc_size = (size_t)s->r * (size_t)(s->nI + s->nO);

  s->omap = malloc((size_t)s->nO * sizeof *s->omap);
  if (!s->omap) goto fail;
  {
    int o = 0;
    for (int i = 0; i < ndim; i++) s->omap[o++] = s->off_u + i;
    for (int i = 0; i < ndim; i++) s->omap[o++] = s->m + s->off_u + i;
    for (int p = 0; p < nfpr; p++) s->omap[o++] = s->m + s->off_q + p;
    for (int d = 0; d < s->nq; d++) s->omap[o++] = s->off_s + d;
    for (int d = 0; d < s->nq; d++) s->omap[o++] = s->m + s->off_s + d;
  }
  band_extent(s);

  size_t nIt = (size_t)ntst * (size_t)s->nI;
  s->loc = malloc((size_t)ntst * s->loc_size * sizeof(double));
  s->loc_piv = malloc((nIt ? nIt : 1) * sizeof(lapack_int));
  {
    long ring = (long)(ABD_LOOKAHEAD + 1) * s->m, reach = (long)s->m + s->kl + s->ku + 1;
    if (ring < reach) ring = reach;
    s->ring = ring < s->nband ? (int)ring : s->nband;
  }
  s->ab = calloc((size_t)s->ldab * (size_t)s->ring, sizeof(double));
  s->w_rhs = malloc(ABD_SOLVE_BLOCK * (size_t)s->nband * sizeof(double));
  s->w_piv = malloc(ABD_SOLVE_BLOCK * (nIt ? nIt : 1) * sizeof(double));
  s->w_loc = malloc((size_t)s->r * sizeof(double));
  s->w_o = malloc((size_t)s->nO * sizeof(double));
  s->iv_status = malloc((size_t)ntst * sizeof(int));
  s->iv_sign = malloc((size_t)ntst * sizeof(int));
  s->iv_logabs = malloc((size_t)ntst * sizeof(double));
  s->iv_amax = malloc((size_t)ntst * sizeof(double));
  s->iv_sumsq = malloc((size_t)ntst * sizeof(double));
  s->w_g = malloc(ABD_SOLVE_BLOCK * (size_t)ntst * (size_t)s->r * sizeof(double));
  s->w_oo = malloc(ABD_SOLVE_BLOCK * (size_t)ntst * (size_t)s->nO * sizeof(double));
  s->prep = malloc(ABD_SOLVE_BLOCK * (size_t)s->n * sizeof(double));
  s->prep_k = calloc(1, sizeof *s->prep_k);
  if (abd_band_alloc(&s->band, s->nband, s->kl, s->ku) != 0) goto fail;
  abd_band_set_ring(&s->band, s->ring);
  if (!s->loc || !s->loc_piv || !s->ab || !s->w_rhs || !s->w_piv || !s->w_loc || !s->w_o ||
      !s->iv_status || !s->iv_sign || !s->iv_logabs || !s->iv_amax || !s->iv_sumsq || !s->w_g || !s->w_oo ||
      !s->prep || !s->prep_k)
    goto fail;
  s->perm_sign = structural_sign(s);
  if (s->perm_sign == 0) goto fail;
  s->det_log = -INFINITY;
  return s;
fail:
  abd_solver_free(s);
  return NULL;
}

static void sv_free(abd_solver *s)
{
  free(s->sv_v);
  free(s->sv_w);
  free(s->sv_b);
  free(s->sv_r);
  free(s->sv_x);
  free(s->sv_yt);
  free(s->sv_s);
  free(s->sv_work);
  free(s->sv_vec);
  free(s->sv_res);
  free(s->sv_rest);
  free(s->sv_pair);
  s->sv_rest = s->sv_pair = NULL;
  free(s->sv_rn);
  s->sv_v = s->sv_w = s->sv_b = s->sv_r = s->sv_x = s->sv_yt = s->sv_s = s->sv_work = s->sv_vec = s->sv_res = NULL;
  s->sv_rn = NULL;
  s->sv_k = 0;
}

void abd_solver_free(abd_solver *s)
{
  if (!s) return;
  free(s->omap);
  free(s->loc);
  free(s->loc_piv);
  free(s->ab);
  abd_band_free(&s->band);
  free(s->w_rhs);
  free(s->w_piv);
  free(s->w_loc);
  free(s->w_o);
  free(s->iv_status);
  free(s->iv_sign);
  free(s->iv_logabs);
  free(s->iv_amax);
  free(s->iv_sumsq);
  free(s->w_g);
  free(s->w_oo);
  free(s->prep);
  free(s->prep_k);
  if (!s->team_borrowed) cable_team_free(s->team);
  sv_free(s);
  free(s);
}

int abd_solver_size(const abd_solver *s) { return s->n; }

int abd_solver_set_threads(abd_solver *s, int nthreads)
{
  if (!s) return ABD_ERR_SIZE;
  if (nthreads < 1) nthreads = 1;
  if (cable_team_size(s->team) == nthreads) return ABD_OK;
  if (!s->team_borrowed) cable_team_free(s->team);
  s->team = NULL;
  s->team_borrowed = 0;
  if (nthreads == 1) return ABD_OK;
  s->team = cable_team_alloc(nthreads);
  return s->team ? ABD_OK : ABD_ERR_MEM;
}

int abd_solver_threads(const abd_solver *s) { return s ? cable_team_size(s->team) : 0; }

void abd_solver_use_team(abd_solver *s, struct cable_team *t)
{
  if (!s || !t) return;
  if (!s->team_borrowed) cable_team_free(s->team);
  s->team = t;
  s->team_borrowed = 1;
}

cable_team *abd_solver_team(const abd_solver *s) { return s ? s->team : NULL; }

void abd_solver_bandwidths(const abd_solver *s, int *kl, int *ku)
{
  *kl = s->kl;
  *ku = s->ku;
}

void abd_solver_space(const abd_solver *s, long *ndoubles, long *nints)
{
  long nIt = (long)s->N * s->nI;
  *ndoubles = (long)s->N * (long)s->loc_size + (long)s->ldab * s->ring + ABD_SOLVE_BLOCK * (s->nband + nIt) + s->r +
              s->nO + 2L * s->N + ABD_SOLVE_BLOCK * (long)s->N * (s->r + s->nO) +
              (s->sv_k ? (long)s->sv_k * (6L * s->n + 3L * s->sv_k + 3) +
                             (long)s->N * s->sv_k * (2L * (s->nc + 1) * s->nd + s->nf) : 0L) +
              (long)s->sv_lwork;
  long nu = (long)s->band.ucap, nl = (long)s->band.lcap; /* compressed factors, as grown so far */
  *ndoubles += s->nband + nu + nl + ABD_SOLVE_BLOCK * (long)s->n; /* + the prepared right-hand sides */
  *nints = s->nO + nIt + s->nband + s->kl + 1 + 2L * (s->nband + 1) + nu + nl + 2L * s->N + 1;
}

static int jac_matches(const abd_solver *s, const colloc_jac *J)
{
  return J->ndim == s->nd && J->ntst == s->N && J->ncol == s->nc && J->nfpr == s->nf && J->nbc == s->nb &&
         J->nint == s->nint && J->n == s->n;
}

/* Interval j's local block (r x (nI+nO), ld r) from J. */
static void local_fill(const abd_solver *s, const colloc_jac *J, int j, double *L)
{
  const int nd = s->nd, nc = s->nc, nr = s->nr, r = s->r, nI = s->nI, nq = s->nq;
  const int oU0 = nI, oU1 = nI + nd, oQ = nI + 2 * nd, oS0 = oQ + s->nf, oS1 = oS0 + nq;
  const double *C = colloc_jac_coll_block(J, j);
  const double *D = colloc_jac_dense_block(J, j);
  /* every entry is written once below (no memset of the whole block: it
     was a tenth of a factorisation) */
  for (int k = 0; k <= nc; k++)
    for (int i = 0; i < nd; i++) {
      int src = k * nd + i;
      int dst = k == 0 ? oU0 + i : k == nc ? oU1 + i : (k - 1) * nd + i;
      double *Lc = L + (size_t)dst * (size_t)r;
      memcpy(Lc, C + (size_t)src * (size_t)nr, (size_t)nr * sizeof(double));
      for (int d = 0; d < nq; d++) Lc[nr + d] = -D[(size_t)src * (size_t)nq + (size_t)d];
    }
  for (int p = 0; p < s->nf; p++) {
    double *Lc = L + (size_t)(oQ + p) * (size_t)r;
    memcpy(Lc, C + (size_t)((nc + 1) * nd + p) * (size_t)nr, (size_t)nr * sizeof(double));
    for (int d = 0; d < nq; d++) Lc[nr + d] = 0.0;
  }
  memset(L + (size_t)oS0 * (size_t)r, 0, 2 * (size_t)nq * (size_t)r * sizeof(double));
  for (int d = 0; d < nq; d++) {
    L[(size_t)(oS0 + d) * (size_t)r + (size_t)(nr + d)] = -1.0;
    L[(size_t)(oS1 + d) * (size_t)r + (size_t)(nr + d)] = 1.0;
  }
}

static void det_accumulate(double pivot, int *sign, double *logabs)
{
  if (pivot == 0.0) {
    *sign = 0;
    return;
  }
  if (pivot < 0.0) *sign = -*sign;
  *logabs += log(fabs(pivot));
}

static double *wv_rhs(const abd_solver *s, int v) { return s->w_rhs + (size_t)v * (size_t)s->nband; }
static double *wv_piv(const abd_solver *s, int v) { return s->w_piv + (size_t)v * (size_t)s->N * (size_t)s->nI; }
static double *wv_g(const abd_solver *s, int v) { return s->w_g + (size_t)v * (size_t)s->N * (size_t)s->r; }
static double *wv_oo(const abd_solver *s, int v) { return s->w_oo + (size_t)v * (size_t)s->N * (size_t)s->nO; }

/* Solve stage 1 for one vector x (length n) and interval j, in the workspace
 * of block slot v: g_j = L_j^{-1} P_j b_j; its pivot rows to w_piv, the rest
 * to the band right-hand side.  Called by the solves, and by the
 * factorisation for prepared right-hand sides (the same code: the same bits). */
static void forward_interval(const abd_solver *s, int j, const double *x, int v)
{
  const int nd = s->nd, nf = s->nf, nq = s->nq, nI = s->nI, r = s->r, nr = s->nr;
  const double *L = loc_block(s, j);
  const lapack_int *piv = s->loc_piv + (size_t)j * (size_t)nI;
  double *g = wv_g(s, v) + (size_t)j * (size_t)r;
  memcpy(g, x + (size_t)j * (size_t)nr, (size_t)nr * sizeof(double));
  for (int d = 0; d < nq; d++) g[nr + d] = 0.0;
  if (nI > 0) {
    for (int i = 0; i < nI; i++) {
      int ip = (int)piv[i] - 1;
      if (ip != i) {
        double t = g[i];
        g[i] = g[ip];
        g[ip] = t;
      }
    }
    cblas_dtrsv(CblasColMajor, CblasLower, CblasNoTrans, CblasUnit, nI, L, r, g, 1);
    cblas_dgemv(CblasColMajor, CblasNoTrans, r - nI, nI, -1.0, L + nI, r, g, 1, 1.0, g + nI, 1);
    memcpy(wv_piv(s, v) + (size_t)j * (size_t)nI, g, (size_t)nI * sizeof(double));
  }
  memcpy(wv_rhs(s, v) + grow_base(s, j) + nd + nf, g + nI, (size_t)(r - nI) * sizeof(double));
}

/* Interval j's stage of the factorisation: local fill, condensation, growth
 * and its band rows.  Touches only interval j's storage and band rows, so
 * intervals run in parallel; the results go to the iv_ arrays. */
typedef struct {
  abd_solver *s;
  const colloc_jac *J;
  const double *B; /* k prepared right-hand sides (abd_solver_factor_prepared) */
  int k;
} factor_ctx;

static void factor_interval(void *ctx, int j)
{
  const factor_ctx *fc = ctx;
  abd_solver *s = fc->s;
  const colloc_jac *J = fc->J;
  const int nd = s->nd, nf = s->nf, nI = s->nI, r = s->r, nO = s->nO;
  double *L = loc_block(s, j);
  double *O = L + (size_t)nI * (size_t)r;
  lapack_int *piv = s->loc_piv + (size_t)j * (size_t)nI;
  int sign = 1, status = 0;
  double logabs = 0.0, amax = 0.0;
  local_fill(s, J, j, L);
  for (size_t i = 0; i < s->loc_size; i++) {
    double x = fabs(L[i]);
    if (!(x <= DBL_MAX)) status = -2; /* NaN or infinity */
    if (x > amax) amax = x;
  }
  if (status == 0 && nI > 0) {
    lapack_int info = LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, r, nI, L, r, piv);
    if (info < 0) status = -1;
    else if (info > 0) status = 1;
    for (int i = 0; status >= 0 && i < nI; i++) {
      if (piv[i] != i + 1) sign = -sign;
      det_accumulate(L[(size_t)i * (size_t)r + (size_t)i], &sign, &logabs);
    }
    if (status >= 0 && LAPACKE_dlaswp_work(LAPACK_COL_MAJOR, nO, O, r, 1, nI, piv, 1) < 0) status = -1;
    if (status >= 0) {
      cblas_dtrsm(CblasColMajor, CblasLeft, CblasLower, CblasNoTrans, CblasUnit, nI, nO, 1.0, L, r, O, r);
      cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, r - nI, nO, nI, -1.0, L + nI, r, O, r, 1.0, O + nI, r);
    }
  }
  if (status >= 0) {
    int over = 0, g = grow_base(s, j);
    const size_t b = (size_t)(((long)j * s->m) % s->ring);
    for (int k = 0; k < r - nI; k++)
      for (int o = 0; o < nO; o++)
        over |= band_set_iv(s, b, j, g + nd + nf + k, j * s->m + s->omap[o], O[(size_t)o * (size_t)r + (size_t)(nI + k)]);
    for (int i = 0; i < nd; i++) {
      over |= band_set_iv(s, b, j, g + i, zcol(s, j, s->off_c, i), -1.0);
      over |= band_set_iv(s, b, j, g + i, zcol(s, j + 1, s->off_c, i), 1.0);
    }
    for (int p = 0; p < nf; p++) {
      over |= band_set_iv(s, b, j, g + nd + p, zcol(s, j, s->off_q, p), -1.0);
      over |= band_set_iv(s, b, j, g + nd + p, zcol(s, j + 1, s->off_q, p), 1.0);
    }
    if (over) status = -3;
  }
  /* the prepared right-hand sides' stage 1 while the block is in cache
     (abd_solver_factor_prepared) */
  if (status == 0)
    for (int v = 0; v < fc->k; v++) forward_interval(s, j, fc->B + (size_t)v * (size_t)s->n, v);
  s->iv_status[j] = status;
  s->iv_sign[j] = sign;
  s->iv_logabs[j] = logabs;
  s->iv_amax[j] = amax;
}

/* The boundary and dense rows, in z_N's columns: written once the last
 * interval is condensed (the ring's storage of z_N's columns is free only
 * then; the interval stages write those columns in other rows). */
static void put_end_rows(abd_solver *s, const colloc_jac *J)
{
  const int nd = s->nd, nf = s->nf, nq = s->nq, N = s->N;
  const int e = end_base(s), nb = s->nb;
  for (int b = 0; b < nb; b++) {
    for (int i = 0; i < nd; i++) {
      band_put(s, e + b, zcol(s, N, s->off_c, i), J->bc[(size_t)i * (size_t)nb + (size_t)b]);
      band_put(s, e + b, zcol(s, N, s->off_u, i), J->bc[(size_t)(nd + i) * (size_t)nb + (size_t)b]);
    }
    for (int p = 0; p < nf; p++)
      band_put(s, e + b, zcol(s, N, s->off_q, p), J->bc[(size_t)(2 * nd + p) * (size_t)nb + (size_t)b]);
  }
  for (int d = 0; d < nq; d++) {
    for (int p = 0; p < nf; p++)
      band_put(s, e + nb + d, zcol(s, N, s->off_q, p), J->dense_par[(size_t)p * (size_t)nq + (size_t)d]);
    band_put(s, e + nb + d, zcol(s, N, s->off_s, d), 1.0);
  }
}

/* The band columns of z_j, once intervals 0..j are condensed. */
static void band_eliminate(void *ctx, int j)
{
  const factor_ctx *fc = ctx;
  abd_solver *s = fc->s;
  if (j == s->N - 1) put_end_rows(s, fc->J);
  abd_band_factor_upto(&s->band, s->ab, s->ldab, (j + 1) * s->m);
}

/* Largest |entry| of the boundary and dense-parameter blocks, or NaN when an
 * entry is not finite (the interval blocks are scanned by factor_interval). */
static double end_maxabs(const colloc_jac *J)
{
  double mx = 0.0;
  size_t len[2] = {(size_t)J->nbc * (size_t)(2 * J->ndim + J->nfpr), (size_t)J->ndense * (size_t)J->nfpr};
  const double *v[2] = {J->bc, J->dense_par};
  for (int b = 0; b < 2; b++)
    for (size_t i = 0; i < len[b]; i++) {
      if (!isfinite(v[b][i])) return NAN;
      double x = fabs(v[b][i]);
      if (x > mx) mx = x;
    }
  return mx;
}

static int factor(abd_solver *s, const colloc_jac *J, const double *B, int k);

int abd_solver_factor(abd_solver *s, const colloc_jac *J) { return factor(s, J, NULL, 0); }

int abd_solver_factor_prepared(abd_solver *s, const colloc_jac *J, const double *B, int k)
{
  return factor(s, J, B, k);
}

static int factor(abd_solver *s, const colloc_jac *J, const double *B, int k)
{
  if (!s) return ABD_ERR_SIZE;
  *s->prep_k = 0;
  s->state = STATE_NONE;
  s->det_sign = 0;
  s->det_log = -INFINITY;
  if (!J || !jac_matches(s, J) || k < 0 || k > ABD_SOLVE_BLOCK || (k > 0 && !B)) return ABD_ERR_SIZE;
  double amax = end_maxabs(J);
  if (isnan(amax)) return ABD_ERR_NONFINITE;

  const int nd = s->nd, nq = s->nq, N = s->N;
  int sign = s->perm_sign, singular = 0;
  double logabs = 0.0;

  s->band_overflow = 0;
  factor_ctx fc = {s, J, B, k};
  for (int v = 0; v < k; v++) {
    memset(wv_rhs(s, v), 0, (size_t)s->nband * sizeof(double));
    memcpy(s->prep + (size_t)v * (size_t)s->n, B + (size_t)v * (size_t)s->n, (size_t)s->n * sizeof(double));
  }
  /* ab is all zero here: calloc, then every factorisation clears it
     (abd_band.h) */
  for (int i = 0; i < nd; i++) {
    band_put(s, i, zcol(s, 0, s->off_c, i), 1.0);
    band_put(s, i, zcol(s, 0, s->off_u, i), -1.0);
  }
  for (int d = 0; d < nq; d++) band_put(s, nd + d, zcol(s, 0, s->off_s, d), 1.0);

  /* The band LU runs behind the interval stages (the pipeline of
     cable_team.h): once intervals 0..j are condensed, the columns of
     z_0..z_j are final and the rows of intervals > j are still zero in
     them, so band_eliminate may factor them while later intervals are
     condensed (abd_band.h, abd_band_factor_upto). */
  abd_band_factor_begin(&s->band);
  cable_team_run_ordered_window(s->team, factor_interval, &fc, N, band_eliminate, &fc, ABD_LOOKAHEAD);
  int binfo = abd_band_factor_end(&s->band, s->ab, s->ldab);
  if (binfo < 0) { /* the elimination stopped part way: clear its storage for the next matrix */
    memset(s->ab, 0, (size_t)s->ldab * (size_t)s->ring * sizeof(double));
    return ABD_ERR_MEM;
  }
  if (binfo > 0) singular = 1;
  if (s->band_overflow) return ABD_ERR_LAPACK;
  /* reduce in interval order */
  for (int j = 0; j < N; j++) {
    if (s->iv_status[j] == -2) return ABD_ERR_NONFINITE;
    if (s->iv_status[j] == -1 || s->iv_status[j] == -3) return ABD_ERR_LAPACK;
    if (s->iv_status[j] == 1) singular = 1;
    sign *= s->iv_sign[j];
    logabs += s->iv_logabs[j];
    if (s->iv_amax[j] > amax) amax = s->iv_amax[j];
  }
  if (amax < 1.0) amax = 1.0; /* the identity copy entries */

  for (int i = 0; i < s->nband; i++) {
    if (s->band.ipiv[i] != i) sign = -sign;
    det_accumulate(s->band.ud[i], &sign, &logabs);
  }

  s->growth_band = s->band.umax; /* the local stages' part: abd_solver_growth */
  s->amax = amax;
  if (singular || sign == 0) {
    s->state = STATE_SINGULAR;
    s->det_sign = 0;
    s->det_log = -INFINITY;
    return ABD_SINGULAR;
  }
  s->state = STATE_OK;
  s->det_sign = sign;
  s->det_log = logabs;
  *s->prep_k = k;
  return ABD_OK;
}

static int solve_state(const abd_solver *s)
{
  if (!s || s->state == STATE_NONE) return ABD_ERR_NOT_FACTORED;
  if (s->state == STATE_SINGULAR) return ABD_SINGULAR;
  return ABD_OK;
}

/* The per-interval stages of the solves, one interval per call (run by the
 * team: each writes only its interval's rows and scratch).  A call handles
 * the k right-hand sides one after the other (each with its own scratch,
 * block v of every w_ array), so the interval's factors are read from memory
 * once for all of them; each vector sees exactly the operations of a solve
 * of its own. */
typedef struct {
  const abd_solver *s;
  double *x; /* k vectors of length n, one after the other */
  int k;
} solve_ctx;

/* J x = b, stage 1: apply interval j's L^{-1} P to its rows' right-hand side. */
static void solve_forward(void *p, int j)
{
  const solve_ctx *c = p;
  for (int v = 0; v < c->k; v++) forward_interval(c->s, j, c->x + (size_t)v * (size_t)c->s->n, v);
}

/* J x = b, stage 3: interior unknowns, U_j x_I = g_j - X_j x_O. */
static void solve_back(void *p, int j)
{
  const solve_ctx *c = p;
  const abd_solver *s = c->s;
  const int nd = s->nd, nI = s->nI, r = s->r, nr = s->nr, nO = s->nO;
  if (nI == 0) return;
  const double *L = loc_block(s, j);
  for (int v = 0; v < c->k; v++) {
    const double *rhs = wv_rhs(s, v);
    double *t = wv_piv(s, v) + (size_t)j * (size_t)nI, *wo = wv_oo(s, v) + (size_t)j * (size_t)nO;
    for (int o = 0; o < nO; o++) wo[o] = rhs[j * s->m + s->omap[o]];
    cblas_dgemv(CblasColMajor, CblasNoTrans, nI, nO, -1.0, L + (size_t)nI * (size_t)r, r, wo, 1, 1.0, t, 1);
    cblas_dtrsv(CblasColMajor, CblasUpper, CblasNoTrans, CblasNonUnit, nI, L, r, t, 1);
    memcpy(c->x + (size_t)v * (size_t)s->n + (size_t)j * (size_t)nr + (size_t)nd, t, (size_t)nI * sizeof(double));
  }
}

static int solve_many(const abd_solver *s, double *X, int k)
{
  const int nd = s->nd, nf = s->nf, nq = s->nq, nr = s->nr, N = s->N;
  solve_ctx c = {s, X, k};
  /* stage 1 was done by the factorisation when X is what it prepared */
  int prepared = k == *s->prep_k && memcmp(X, s->prep, (size_t)k * (size_t)s->n * sizeof(double)) == 0;
  *s->prep_k = 0; /* this solve uses the workspace up */
  if (!prepared) {
    for (int v = 0; v < k; v++) memset(wv_rhs(s, v), 0, (size_t)s->nband * sizeof(double));
    cable_team_run(s->team, solve_forward, &c, N);
  }
  const int e = end_base(s);
  for (int v = 0; v < k; v++) {
    double *rhs = wv_rhs(s, v);
    memcpy(rhs + e, X + (size_t)v * (size_t)s->n + (size_t)N * (size_t)nr, (size_t)(s->nb + nq) * sizeof(double));
    abd_band_solve(&s->band, rhs);
  }
  cable_team_run(s->team, solve_back, &c, N);
  for (int v = 0; v < k; v++) {
    double *x = X + (size_t)v * (size_t)s->n;
    const double *rhs = wv_rhs(s, v);
    for (int j = 0; j <= N; j++)
      memcpy(x + (size_t)j * (size_t)nr, rhs + zcol(s, j, s->off_u, 0), (size_t)nd * sizeof(double));
    memcpy(x + s->n - nf, rhs + zcol(s, 0, s->off_q, 0), (size_t)nf * sizeof(double));
  }
  return ABD_OK;
}

int abd_solver_solve(const abd_solver *s, double *x) { return abd_solver_solve_many(s, x, 1); }

int abd_solver_solve_many(const abd_solver *s, double *X, int k)
{
  int st = solve_state(s);
  if (st != ABD_OK) return st;
  if (k < 0) return ABD_ERR_SIZE;
  for (int v = 0; v < k; v += ABD_SOLVE_BLOCK)
    solve_many(s, X + (size_t)v * (size_t)s->n, k - v < ABD_SOLVE_BLOCK ? k - v : ABD_SOLVE_BLOCK);
  return ABD_OK;
}

/* J^T y = c, stage 1: w_I = U_j^{-T} c_I and X_j^T w_I (subtracted later). */
static void solve_t_first(void *p, int j)
{
  const solve_ctx *c = p;
  const abd_solver *s = c->s;
  const int nd = s->nd, nI = s->nI, r = s->r, nr = s->nr, nO = s->nO;
  if (nI == 0) return;
  const double *L = loc_block(s, j);
  for (int v = 0; v < c->k; v++) {
    double *wI = wv_piv(s, v) + (size_t)j * (size_t)nI, *wo = wv_oo(s, v) + (size_t)j * (size_t)nO;
    memcpy(wI, c->x + (size_t)v * (size_t)s->n + (size_t)j * (size_t)nr + (size_t)nd, (size_t)nI * sizeof(double));
    cblas_dtrsv(CblasColMajor, CblasUpper, CblasTrans, CblasNonUnit, nI, L, r, wI, 1);
    cblas_dgemv(CblasColMajor, CblasTrans, nI, nO, 1.0, L + (size_t)nI * (size_t)r, r, wI, 1, 0.0, wo, 1);
  }
}

/* J^T y = c, stage 3: undo interval j's row operations, P_j^T L_j^{-T}. */
static void solve_t_last(void *p, int j)
{
  const solve_ctx *c = p;
  const abd_solver *s = c->s;
  const int nd = s->nd, nf = s->nf, nI = s->nI, r = s->r, nr = s->nr;
  const double *L = loc_block(s, j);
  const lapack_int *piv = s->loc_piv + (size_t)j * (size_t)nI;
  for (int v = 0; v < c->k; v++) {
    double *g = wv_g(s, v) + (size_t)j * (size_t)r;
    if (nI > 0) memcpy(g, wv_piv(s, v) + (size_t)j * (size_t)nI, (size_t)nI * sizeof(double));
    memcpy(g + nI, wv_rhs(s, v) + grow_base(s, j) + nd + nf, (size_t)(r - nI) * sizeof(double));
    if (nI > 0) {
      cblas_dgemv(CblasColMajor, CblasTrans, r - nI, nI, -1.0, L + nI, r, g + nI, 1, 1.0, g, 1);
      cblas_dtrsv(CblasColMajor, CblasLower, CblasTrans, CblasUnit, nI, L, r, g, 1);
      for (int i = nI - 1; i >= 0; i--) {
        int ip = (int)piv[i] - 1;
        if (ip != i) {
          double t = g[i];
          g[i] = g[ip];
          g[ip] = t;
        }
      }
    }
    /* slots nr.. are the running-sum definitions: not equations of J */
    memcpy(c->x + (size_t)v * (size_t)s->n + (size_t)j * (size_t)nr, g, (size_t)nr * sizeof(double));
  }
}

/* J^T y = c through the augmented matrix M (det M = det J): M^T (y, w) =
 * (c, 0) gives J^T y = c.  With M_final = [[U, X], [0, B]] (interior pivot
 * rows first), solve U^T w_I = c_I, B^T w_B = c_B - X^T w_I, then undo the
 * local row operations: rows of interval j get P_j^T L_j^{-T} (w_I, w_B). */
static int solve_transpose_many(const abd_solver *s, double *X, int k)
{
  const int nd = s->nd, nf = s->nf, nq = s->nq, nI = s->nI, nr = s->nr, nO = s->nO, N = s->N;
  solve_ctx c = {s, X, k};
  *s->prep_k = 0; /* the workspace is used up */
  for (int v = 0; v < k; v++) {
    double *rhs = wv_rhs(s, v);
    const double *x = X + (size_t)v * (size_t)s->n;
    memset(rhs, 0, (size_t)s->nband * sizeof(double));
    for (int j = 0; j <= N; j++)
      memcpy(rhs + zcol(s, j, s->off_u, 0), x + (size_t)j * (size_t)nr, (size_t)nd * sizeof(double));
    memcpy(rhs + zcol(s, 0, s->off_q, 0), x + s->n - nf, (size_t)nf * sizeof(double));
  }
  cable_team_run(s->team, solve_t_first, &c, N);
  for (int v = 0; v < k; v++) {
    double *rhs = wv_rhs(s, v);
    /* in interval order: neighbouring intervals share a mesh point's entries */
    for (int j = 0; j < N && nI > 0; j++) {
      const double *wo = wv_oo(s, v) + (size_t)j * (size_t)nO;
      for (int o = 0; o < nO; o++) rhs[j * s->m + s->omap[o]] -= wo[o];
    }
    abd_band_solve_transpose(&s->band, rhs);
  }
  cable_team_run(s->team, solve_t_last, &c, N);
  for (int v = 0; v < k; v++)
    memcpy(X + (size_t)v * (size_t)s->n + (size_t)N * (size_t)nr, wv_rhs(s, v) + end_base(s),
           (size_t)(s->nb + nq) * sizeof(double));
  return ABD_OK;
}

int abd_solver_solve_transpose(const abd_solver *s, double *x) { return abd_solver_solve_transpose_many(s, x, 1); }

int abd_solver_solve_transpose_many(const abd_solver *s, double *X, int k)
{
  int st = solve_state(s);
  if (st != ABD_OK) return st;
  if (k < 0) return ABD_ERR_SIZE;
  for (int v = 0; v < k; v += ABD_SOLVE_BLOCK)
    solve_transpose_many(s, X + (size_t)v * (size_t)s->n, k - v < ABD_SOLVE_BLOCK ? k - v : ABD_SOLVE_BLOCK);
  return ABD_OK;
}

void abd_solver_det(const abd_solver *s, int *sign, double *logabs)
{
  if (!s || s->state == STATE_NONE) {
    *sign = 0;
    *logabs = -INFINITY;
    return;
  }
  *sign = s->det_sign;
  *logabs = s->det_log;
}

/* The local stages' max |U| is taken here, from the factors kept in the
 * local blocks (the U rows of each stage and the condensed rows it passed
 * on), not in every factorisation: only tests and diagnostics ask. */
double abd_solver_growth(const abd_solver *s)
{
  if (s->state == STATE_NONE) return (double)NAN;
  const int nI = s->nI, r = s->r, nO = s->nO;
  double umax = s->growth_band;
  for (int j = 0; j < s->N && nI > 0; j++) {
    const double *L = loc_block(s, j);
    for (int c = 0; c < nI + nO; c++) {
      int top = c < nI ? c + 1 : r;
      for (int i = 0; i < top; i++) {
        double x = fabs(L[(size_t)c * (size_t)r + (size_t)i]);
        if (x > umax) umax = x;
      }
    }
  }
  return umax / s->amax;
}

/* ---- smallest singular values ----------------------------------------- */

/* ||J||_F from the sums of squares of the collocation blocks in iv_sumsq
 * (computed on the team by colloc_jac_matvec_pair_team along with the first
 * residuals of the iteration, while each block is in cache: four independent
 * chains in a fixed order, the same for every thread count; a pass of its own
 * over the 11 MB of blocks was 3 % of an ISP=2 step), summed in interval
 * order (contributions of two intervals to a mesh point in a dense row add
 * before squaring). */
static double jac_frobenius(const abd_solver *s, const colloc_jac *J)
{
  const int nd = J->ndim, nc = J->ncol, nq = J->ndense;
  double sum = 0.0;
  for (int j = 0; j < J->ntst; j++) sum += s->iv_sumsq[j];
  size_t nbcv = (size_t)J->nbc * (size_t)(2 * nd + J->nfpr);
  for (size_t i = 0; i < nbcv; i++) sum += J->bc[i] * J->bc[i];
  for (size_t i = 0; i < (size_t)nq * (size_t)J->nfpr; i++) sum += J->dense_par[i] * J->dense_par[i];
  for (int j = 0; j <= J->ntst; j++)
    for (int k = 0; k < (j < J->ntst ? nc : 1); k++)
      for (int i = 0; i < nd; i++)
        for (int d = 0; d < nq; d++) {
          double v = 0.0;
          if (j < J->ntst) v += colloc_jac_dense_block(J, j)[(size_t)(k * nd + i) * (size_t)nq + (size_t)d];
          if (k == 0 && j > 0) v += colloc_jac_dense_block(J, j - 1)[(size_t)(nc * nd + i) * (size_t)nq + (size_t)d];
          sum += v * v;
        }
  return sqrt(sum);
}

/* Orthonormalise the k columns of A (n x k) by Gram-Schmidt with one
 * reorthogonalisation pass ("twice is enough"); R (k x k, may be NULL)
 * receives the triangular factor.  Returns -1 if a column vanishes. */
static int orthonormalise(int n, int k, double *A, double *R)
{
  if (R) memset(R, 0, (size_t)k * (size_t)k * sizeof(double));
  for (int i = 0; i < k; i++) {
    double *ai = A + (size_t)i * (size_t)n;
    for (int pass = 0; pass < 2; pass++)
      for (int l = 0; l < i; l++) {
        const double *al = A + (size_t)l * (size_t)n;
        double h = cblas_ddot(n, al, 1, ai, 1);
        cblas_daxpy(n, -h, al, 1, ai, 1);
        if (R) R[(size_t)i * (size_t)k + (size_t)l] += h;
      }
    double nrm = cblas_dnrm2(n, ai, 1);
    if (!(nrm > 0.0) || !isfinite(nrm)) return -1;
    cblas_dscal(n, 1.0 / nrm, ai, 1);
    if (R) R[(size_t)i * (size_t)k + (size_t)i] = nrm;
  }
  return 0;
}

static int sv_reserve(abd_solver *s, int k)
{
  if (s->sv_k >= k) return 0;
  sv_free(s);
  size_t nk = (size_t)s->n * (size_t)k, kk = (size_t)k * (size_t)k;
  s->sv_v = malloc(nk * sizeof(double));
  s->sv_w = malloc(nk * sizeof(double));
  s->sv_b = malloc(nk * sizeof(double));
  s->sv_r = malloc(kk * sizeof(double));
  s->sv_x = malloc(kk * sizeof(double));
  s->sv_yt = malloc(kk * sizeof(double));
  s->sv_s = malloc((size_t)k * sizeof(double));
  s->sv_vec = malloc(nk * sizeof(double));
  s->sv_res = malloc(nk * sizeof(double));
  s->sv_rest = malloc(nk * sizeof(double));
  s->sv_pair = malloc((size_t)s->N * (size_t)k * (2 * (size_t)(s->nc + 1) * (size_t)s->nd + (size_t)s->nf) *
                      sizeof(double));
  s->sv_rn = malloc(2 * (size_t)k * sizeof(double));
  if (!s->sv_v || !s->sv_w || !s->sv_b || !s->sv_r || !s->sv_x || !s->sv_yt || !s->sv_s || !s->sv_vec || !s->sv_res || !s->sv_rn ||
      !s->sv_rest || !s->sv_pair) {
    sv_free(s);
    return -1;
  }
  double q;
  if (LAPACKE_dgesvd_work(LAPACK_COL_MAJOR, 'A', 'A', k, k, s->sv_r, k, s->sv_s, s->sv_x, k, s->sv_yt, k, &q, -1) != 0) {
    sv_free(s);
    return -1;
  }
  s->sv_lwork = (lapack_int)q;
  s->sv_work = malloc((size_t)s->sv_lwork * sizeof(double));
  if (!s->sv_work) {
    sv_free(s);
    return -1;
  }
  s->sv_k = k;
  return 0;
}

/* Deterministic start block: the iteration must not depend on a global
 * random state, and any block with a component along the wanted singular
 * subspace converges. */
static void sv_start(int n, int k, double *V)
{
  uint64_t st = UINT64_C(0x9E3779B97F4A7C15);
  for (size_t i = 0; i < (size_t)n * (size_t)k; i++) {
    st = st * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
    V[i] = (double)(st >> 11) * 0x1.0p-53 - 0.5;
  }
}

int abd_solver_smallest_sv(abd_solver *s, const colloc_jac *J, int k, double *sv, double *vecs, int maxit, double tol)
{
  return abd_solver_smallest_svd(s, J, k, NULL, sv, vecs, NULL, maxit, tol, NULL);
}

int abd_solver_smallest_svd(abd_solver *s, const colloc_jac *J, int k, const double *start, double *sv, double *vecs,
                            double *uvecs, int maxit, double tol, int *iters)
{
  if (iters) *iters = 0;
  if (!s || !J || !jac_matches(s, J) || k < 1 || k > s->n || maxit < 1 || !(tol > 0.0)) return ABD_ERR_SIZE;
  if (s->state != STATE_OK) return s->state == STATE_SINGULAR ? ABD_SINGULAR : ABD_ERR_NOT_FACTORED;
  if (sv_reserve(s, k) != 0) return ABD_ERR_MEM;
  const int n = s->n;
  double *V = s->sv_v, *W = s->sv_w, *QL = s->sv_b, *R = s->sv_r, *X = s->sv_x, *YT = s->sv_yt, *S = s->sv_s;
  double *U = s->sv_vec, *res = s->sv_res;
  double normF = -1.0; /* from the first residual pass */

  if (start) memcpy(V, start, (size_t)n * (size_t)k * sizeof(double));
  else sv_start(n, k, V);
  if (orthonormalise(n, k, V, NULL) != 0) {
    if (!start) return ABD_ERR_LAPACK;
    sv_start(n, k, V); /* a degenerate start block: the fixed one */
    if (orthonormalise(n, k, V, NULL) != 0) return ABD_ERR_LAPACK;
  }
  int status = ABD_NOT_CONVERGED;
  for (int it = 0; it < maxit && status != ABD_OK; it++) {
    if (iters) *iters = it + 1;
    /* Left block QL = orth(J^{-T} V), right block W R = J^{-1} QL.  Then
     * J W = QL R^{-1} up to the solves' backward error, so the projection
     * QL^T J W is R^{-1}: with R = X S Y^T, the Ritz triplets are
     * sigma_i = 1/S_i, v_i = W X e_i, u_i = QL Y e_i.  Taking sigma from R
     * rather than from J W keeps the relative accuracy of tiny sigma, and
     * u_i from J^{-T} rather than J v_i / sigma_i keeps u_i accurate. */
    memcpy(QL, V, (size_t)n * (size_t)k * sizeof(double));
    if (abd_solver_solve_transpose_many(s, QL, k) != ABD_OK) return ABD_ERR_LAPACK;
    if (orthonormalise(n, k, QL, NULL) != 0) return ABD_ERR_LAPACK;
    memcpy(W, QL, (size_t)n * (size_t)k * sizeof(double));
    if (abd_solver_solve_many(s, W, k) != ABD_OK) return ABD_ERR_LAPACK;
    if (orthonormalise(n, k, W, R) != 0) return ABD_ERR_LAPACK;
    if (LAPACKE_dgesvd_work(LAPACK_COL_MAJOR, 'A', 'A', k, k, R, k, S, X, k, YT, k, s->sv_work, s->sv_lwork) != 0)
      return ABD_ERR_LAPACK;
    /* S is descending, so sigma_i = 1/S_i is ascending.  The k Ritz vectors
       first, then their residuals with one pass over J for all of them. */
    status = ABD_OK;
    for (int i = 0; i < k; i++) {
      double *vi = V + (size_t)i * (size_t)n, *u = U + (size_t)i * (size_t)n;
      memset(vi, 0, (size_t)n * sizeof(double));
      memset(u, 0, (size_t)n * sizeof(double));
      for (int l = 0; l < k; l++) {
        cblas_daxpy(n, X[(size_t)i * (size_t)k + (size_t)l], W + (size_t)l * (size_t)n, 1, vi, 1);
        cblas_daxpy(n, YT[(size_t)l * (size_t)k + (size_t)i], QL + (size_t)l * (size_t)n, 1, u, 1);
      }
      sv[i] = 1.0 / S[i];
    }
    double *rn[2] = {s->sv_rn, s->sv_rn + k};
    /* J V and J^T U in one pass over J (and ||J||_F in the first) */
    colloc_jac_matvec_pair_team(J, s->team, k, V, res, U, s->sv_rest, s->sv_pair, normF < 0 ? s->iv_sumsq : NULL);
    if (normF < 0) normF = jac_frobenius(s, J);
    for (int pass = 0; pass < 2; pass++) {
      /* pass 0: J v_i - sigma_i u_i; pass 1: J^T u_i - sigma_i v_i */
      for (int i = 0; i < k; i++) {
        double *ri = (pass == 0 ? res : s->sv_rest) + (size_t)i * (size_t)n;
        cblas_daxpy(n, -sv[i], (pass == 0 ? U : V) + (size_t)i * (size_t)n, 1, ri, 1);
        rn[pass][i] = cblas_dnrm2(n, ri, 1);
      }
    }
    for (int i = 0; i < k; i++) {
      if (!(fmax(rn[0][i], rn[1][i]) <= tol * normF)) status = ABD_NOT_CONVERGED;
      if (uvecs) memcpy(uvecs + (size_t)i * (size_t)n, U + (size_t)i * (size_t)n, (size_t)n * sizeof(double));
    }
  }
  memcpy(vecs, V, (size_t)n * (size_t)k * sizeof(double));
  return status;
}
