/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Ribbon quantities: twist Tw, writhe Wr and linking number Lk = Tw + Wr
 * (Calugareanu-White-Fuller) of a closed curve r(u) with a unit normal field
 * d(u), and the braid ribbon of paper Sect. 12.3 (contact curve with director
 * (Delta/2) d1).
 *
 * Definitions (u in [0, P), r' = dr/du):
 *   Tw = (1/2pi) \int T . (d x d') du,           T = r'/|r'|, d perpendicular to T
 *   Wr = (1/4pi) \int\int (r'(u) x r'(v)) . (r(u) - r(v)) / |r(u) - r(v)|^3 du dv
 *   Lk(a, b) = (1/4pi) \int\int (a'(u) x b'(v)) . (a(u) - b(v)) / |a(u) - b(v)|^3 du dv
 * The normal may be periodic, d(P) = d(0), or antiperiodic, d(P) = -d(0) (a
 * one-sided ribbon, like a Moebius strip: the knot case, Lk a half-integer).
 * Right-handed twist (d turning anticlockwise about T) and right-handed links
 * are positive.
 *
 * Quadrature (errors are stated in doc/geometry.md):
 *  - Tw and Lk of two disjoint curves: periodic trapezoidal rule on n uniform
 *    samples; spectrally accurate for smooth periodic integrands (error
 *    ~ exp(-2 pi delta / h) for an integrand analytic in a strip |Im u| < delta;
 *    for Lk, delta is set by the distance of the two curves).
 *  - Wr: the Gauss integrand is continuous but has a kink |u - v| on the
 *    diagonal, so the trapezoidal rule is only second order there.  With
 *    h = v - u the inner sums over u stay spectrally accurate and the outer
 *    trapezoidal rule in h has an Euler-Maclaurin error expansion in even
 *    powers of its step; Romberg extrapolation over steps 1, 2, 4 (every
 *    sample, every 2nd, every 4th) removes the h^2 and h^4 terms, leaving
 *    O(h^6).  n must be a multiple of 8. */
#ifndef CABLE_RIBBON_H
#define CABLE_RIBBON_H

#include "cable/cable_analysis.h"   /* cable_braid_topology */
#include "cable/cable_solution.h"

/* The normal handed to the twist routines must satisfy |d.T| <= RIBBON_PERP_TOL |d|:
 * the twist formula assumes d perpendicular to T; 1e-6 admits normals computed
 * by finite means (e.g. from an ODE solution) and rejects wrong inputs. */
#define RIBBON_PERP_TOL 1e-6
/* Smallest sample count accepted by the writhe routine (a multiple of 8). */
#define RIBBON_MIN_SAMPLES 16

/* ---- sample arrays: n points u_i = i P / n, derivatives with respect to u ---- */

/* Writhe of the closed curve (r[3n], dr[3n]); *err (may be NULL) is the size
 * of the last Romberg correction.  n a multiple of 8, >= RIBBON_MIN_SAMPLES. */
int ribbon_writhe_samples(int n, double period, const double *r, const double *dr, double *wr,
                          double *err);
/* Twist of the normal field d (dd = d') along the curve with tangent dr. */
int ribbon_twist_samples(int n, double period, const double *dr, const double *d,
                         const double *dd, double *tw);
/* Gauss linking integral of two disjoint closed curves. */
int ribbon_linking_samples(int n1, double period1, const double *r1, const double *dr1, int n2,
                           double period2, const double *r2, const double *dr2, double *lk);

/* ---- callback interface ---- */

/* r(u), r'(u) and, when d is not NULL, the normal d(u) and d'(u).  Returns 0
 * on success, != 0 on failure (passed on as CABLE_ERR_CALLBACK). */
typedef int ribbon_eval_fn(double u, double r[3], double dr[3], double d[3], double dd[3],
                           void *params);

typedef struct ribbon_curve {
  ribbon_eval_fn *eval;
  double period;               /* P > 0 */
  int antiperiodic;            /* 1: d(P) = -d(0) */
  void *params;
} ribbon_curve;

typedef struct ribbon_workspace ribbon_workspace;
/* Workspace for n samples (a multiple of 8, >= RIBBON_MIN_SAMPLES); NULL on failure. */
ribbon_workspace *ribbon_workspace_alloc(int n);
void ribbon_workspace_free(ribbon_workspace *w);     /* NULL is a no-op */

typedef struct ribbon_result {
  double tw, wr, lk;           /* lk = tw + wr */
  double wr_err;               /* Romberg correction of the writhe */
} ribbon_result;

/* Tw, Wr and Lk = Tw + Wr of the ribbon (c->eval must provide d). */
int ribbon_compute(ribbon_workspace *w, const ribbon_curve *c, ribbon_result *res);
/* Writhe of the curve alone (d is not requested). */
int ribbon_writhe(ribbon_workspace *w, const ribbon_curve *c, double *wr, double *err);
/* Gauss linking integral of the curve with its push-off r + eps d (taken
 * twice round, and halved, when d is antiperiodic): the ribbon's Lk computed
 * independently of Tw + Wr; an integer (half-integer) up to quadrature error.
 * Accurate when the largest distance h between consecutive samples is well
 * below eps: error ~ exp(-2 pi eps / h) (5 samples per eps: ~1e-13). */
int ribbon_pushoff_linking(ribbon_workspace *w, const ribbon_curve *c, double eps, double *lk);

/* ---- the braid ribbon of a solution (paper Sect. 12.3) ---- */

/* Writhe quadrature of the braid ribbon (doc/geometry.md, 2).  The samples
 * are uniform in a variable u with du/da = rho(a)/Z (a the arclength of the
 * contact curve): rho = 1/h plus, around both ends of every closest approach
 * of non-adjacent parts of the axis at distance d < BRAID_RIBBON_NEAR Delta,
 * beta / sqrt(d^2 + s^2 x^2) (x the arclength from the end, s the sine of the
 * angle between the two parts).  The trapezoidal error of a pair at distance
 * d with spacing h is ~ exp(-2 pi d / h), and the Romberg extrapolation uses
 * the spacing 4h as well:
 *  - h = Delta / BRAID_RIBBON_SAMPLES_PER_DELTA gives d/(4h) = 4 at d = 2 Delta
 *    (exp(-8 pi) ~ 1e-11), so parts at least BRAID_RIBBON_NEAR Delta apart
 *    need nothing more;
 *  - closer approaches get spacing d/beta at the closest point, d/(4 beta/16)
 *    with beta = BRAID_RIBBON_NEAR_BETA = 16: the same margin, whatever d.
 * Parts nearer than BRAID_RIBBON_WINDOW Delta along the axis are neighbours,
 * not approaches (the Romberg extrapolation handles the diagonal).  While the
 * Romberg correction wr_err exceeds BRAID_RIBBON_WR_TOL, h is halved and beta
 * doubled, up to BRAID_RIBBON_MAX_SAMPLES samples; a result still above it is
 * flagged unresolved. */
#define BRAID_RIBBON_SAMPLES_PER_DELTA 8
#define BRAID_RIBBON_NEAR 2.0
#define BRAID_RIBBON_NEAR_BETA 16.0
#define BRAID_RIBBON_WINDOW 3.14159265358979323846
/* Floor on s: nearly parallel parts get the density of s = 0.1 (their
 * contribution carries the factor s itself). */
#define BRAID_RIBBON_MIN_SINE 0.1
/* Closest approaches kept (the closest ones). */
#define BRAID_RIBBON_MAX_NEAR 64
/* Target of the writhe's error estimate: Lk must come out half-integer
 * (integer) to 1e-6, so 1e-9 leaves the interpolant's own error the larger. */
#define BRAID_RIBBON_WR_TOL 1e-9
#define BRAID_RIBBON_MIN_SAMPLES 1024
/* Cap on the samples (cost grows as n^2: 16384 samples take about 0.5 s). */
#define BRAID_RIBBON_MAX_SAMPLES 16384
/* Gauss-Legendre nodes per mesh interval for the twist and arclength integrals. */
#define BRAID_RIBBON_GL_ORDER 16
/* The contact curve must close to |c(L) - c(0)| <= BRAID_CLOSURE_TOL * length;
 * otherwise the writhe of a closed curve is undefined and an error is returned.
 * Converged solutions close to the Newton tolerance, far below this. */
#define BRAID_CLOSURE_TOL 1e-3

typedef struct braid_ribbon {
  double lk, tw, wr;           /* Lk = Tw + Wr */
  double wr_err;               /* Romberg correction of the writhe quadrature (error estimate) */
  int resolved;                /* 1: wr_err <= BRAID_RIBBON_WR_TOL */
  int closure;                 /* -1 knot (d1(L) = -d1(0)), +1 link (d1(L) = d1(0)), 0 neither */
  double lk_defect;            /* |lk - nearest half-odd integer| (knot) or integer (link); NAN if closure 0 */
  double axis_length;          /* length of the contact curve */
  double closure_gap;          /* |c(L) - c(0)| */
  int nsamples;                /* writhe samples used */
  int nnear;                   /* closest approaches closer than BRAID_RIBBON_NEAR Delta */
  double axis_dmin;            /* the closest of them / Delta (INFINITY: none) */
} braid_ribbon;

/* Tw is integrated over each mesh interval of the piecewise-polynomial
 * solution with Gauss-Legendre; Wr is the Gauss integral on samples placed
 * by the arclength of the contact curve: nsamples = 0 chooses and refines
 * them as described above; nsamples > 0 takes that many uniform samples
 * (rounded up to a multiple of 8, at most BRAID_RIBBON_MAX_SAMPLES) without
 * refinement.  The result is as accurate as the solution's interpolant
 * (O(h^ncol) for derivatives). */
int braid_ribbon_compute(const cable_solution *sol, int nsamples, braid_ribbon *out);
/* The same with default samples; any output pointer may be NULL. */
int braid_ribbon_lk(const cable_solution *sol, double *lk, double *tw, double *wr);

/* The topology of a braid solution: the ribbon's Lk = Tw + Wr and the knot
 * type of its axis (braid_curves, knot_type_identify).  nsamples: polygon
 * vertices for the knot type of the axis (0: default BRAID_TOPOLOGY_SAMPLES). */
#define BRAID_TOPOLOGY_SAMPLES 2000
int braid_topology_compute(const cable_solution *sol, int nsamples, cable_braid_topology *out);

#endif
