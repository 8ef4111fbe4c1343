/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Special points: folds (LP), branch points (BP), user zeros (UZ).
 * Test functions (each changes sign at its special point):
 *   LP: the principal parameter's component of the unit tangent;
 *   BP: the signed smallest singular value of the extended Newton matrix
 *       [F_x; theta xdot^T], sign from its determinant (from the stable
 *       factorisation: no overflow, no end-to-end products);
 *   UZ: PAR(k) - value.
 * A sign change between two accepted points is located on the arclength
 * from the first point by Dekker's rule (secant through the last two
 * iterates, safeguarded by the bracket; Illinois regula falsi and bisection
 * as fallbacks), starting from the pencil test's prediction for a BP, until
 * the arclength correction is below EPSS * |ds| (AUTO's EPSS).
 *
 * Second test (cont_check_dip, cont_dip_in_step): a branch point where two
 * singular values vanish together (a double BP, e.g. from a symmetry), or
 * two simple BPs inside one step, leaves the determinant's sign unchanged.
 * Both show as a dip of the smallest singular value sigma_1, between three
 * consecutive points or at a double crossing the pencil test predicts inside
 * the step; the dip is located by minimising sigma_1^2 along the branch
 * (safeguarded parabolic interpolation, vee_min.c) and labelled BP when
 * sigma_1 nearly vanishes there.  (Pairs of simple BPs in one step are
 * normally separated by the pencil test first, cont_pencil.c.) */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"
#include "vee_min.h"

/* The Illinois modification of regula falsi: when the same end of the bracket
 * is kept twice, its function value is scaled by this factor (Dowell and
 * Jarratt 1971), which restores superlinear convergence. */
#define CONT_ILLINOIS 0.5
/* When the corrector fails at a locating iterate, how much farther from it
 * each alternative point is than the one before (see locate()). */
#define CONT_LOCATE_GROW 16.0
/* sigma_1 below this fraction of its values at the ends of a step (or at a
 * dip's neighbours) has vanished to discretisation accuracy: a branch point
 * (cont_check_dip below; locate() when the corrector fails inside a bracket) */
#define CONT_SV_ZERO_REL 1.0e-2

static double bp_test(const cont_tests *t) { return t->det_sign * (t->sv1 > 0 ? t->sv1 : 1.0); }

double cont_bp_value(const cable_cont *cc, const cont_tests *t)
{
  return (cont_bp_detect(cc) || cc->c->nsv > 0) ? bp_test(t) : 0.0;
}

static double test_value(const cont_tests *t, int type, int which)
{
  switch (type) {
  case CABLE_TY_LP: return t->lp;
  case CABLE_TY_BP: return bp_test(t);
  case CABLE_TY_UZ: return t->uz[which];
  default: return 0.0;
  }
}

static int sign_change(double a, double b) { return (a < 0 && b > 0) || (a > 0 && b < 0) || (a != 0 && b == 0); }

/* The event closest to the first point (by linear interpolation), or NONE;
 * uz_only: user zeros only. */
static int find_event(const cable_cont *cc, const cont_tests *a, const cont_tests *b, int uz_only, int *which)
{
  int best = CABLE_TY_NONE;
  double bestf = 2.0;
  *which = -1;
#define CONSIDER(TYPE, W)                                                   \
  do {                                                                      \
    double fa = test_value(a, TYPE, W), fb = test_value(b, TYPE, W);        \
    if (sign_change(fa, fb)) {                                              \
      double f = fa / (fa - fb);                                            \
      if (f < bestf) { bestf = f; best = TYPE; *which = W; }                \
    }                                                                       \
  } while (0)
  if (cc->c->ilp > 0 && !uz_only) CONSIDER(CABLE_TY_LP, -1);
  if (cont_bp_detect(cc) && a->det_sign != b->det_sign && !uz_only) CONSIDER(CABLE_TY_BP, -1);
  for (int k = 0; k < cc->c->nuzr; k++) CONSIDER(CABLE_TY_UZ, k);
#undef CONSIDER
  return best;
}

int cont_find_event(const cable_cont *cc, const cont_tests *a, const cont_tests *b, int *which)
{
  return find_event(cc, a, b, 0, which);
}

/* At a branch point the extended matrix is singular, so the tangent computed
 * there is dominated by its kernel, not the branch direction: take the
 * branch tangent from the regular neighbours instead, interpolated at
 * fraction theta of the step from x (tangent xdot) to the trial point
 * (tangent xdott), into out (which may be xdott). */
static void branch_tangent(cable_cont *cc, double theta, double *out)
{
  for (int i = 0; i < cc->n; i++) out[i] = (1.0 - theta) * cc->xdot[i] + theta * cc->xdott[i];
  cont_normalize(cc, out);
}

/* The corrector at arclength s of the step, started from the linear
 * interpolant of the solutions xlo, xhi at the bracket's ends s0, s1 (it lies
 * on the hyperplane of s: the arclength condition is affine).  The linear
 * predictor from the step's start leaves an error of order curvature * s^2,
 * and next to a branch point the nearly singular Newton matrix amplifies its
 * kernel component by 1 / sigma_1: the corrector then failed at the located
 * point itself (link102's simple BPs at T = 30.77 and 35.75: every iterate
 * that came within 1e-5 of the zero of sigma_1, with DS = 5).  The interpolant
 * of the bracket's ends is off only by curvature * |s1 - s0|^2, which
 * shrinks with the bracket. */
static int correct_in_bracket(cable_cont *cc, double s, double s0, double s1, double *out)
{
  double w = (s - s0) / (s1 - s0);
  for (int i = 0; i < cc->n; i++) out[i] = (1.0 - w) * cc->xlo[i] + w * cc->xhi[i];
  return cont_correct_from(cc, cc->x, cc->xdot, s, out);
}

/* The located point: xs (tangent xds, tests ts) at arclength s of the step
 * becomes the trial point, counted as past the event (far: the test
 * function's value at the step's far end). */
static int locate_accept(cable_cont *cc, int type, int which, double s, const double *xs, const double *xds,
                         cont_tests ts, double far)
{
  memcpy(cc->xt, xs, (size_t)cc->n * sizeof *xs);
  if (type == CABLE_TY_BP)
    branch_tangent(cc, s / cc->ds_used, cc->xdott); /* the matrix is singular here */
  else
    memcpy(cc->xdott, xds, (size_t)cc->n * sizeof *xds);
  cont_tests_fill(cc, cc->xt, cc->xdott, &ts);
  /* count the located point as past the event, so that it is not found again */
  if (type == CABLE_TY_LP) ts.lp = copysign(fabs(ts.lp), far);
  else if (type == CABLE_TY_BP) ts.det_sign = cc->tft.det_sign;
  cc->ds_used = s;
  if (type == CABLE_TY_UZ) {
    /* every user zero at this parameter value (UZR and UZSTOP may both
       list it) is passed, and any of them may ask to stop */
    cc->uz_hit = which;
    cc->uz_stop = 0;
    const cable_uzr *z = &cc->c->uzr[which];
    for (int k = 0; k < cc->c->nuzr; k++) {
      const cable_uzr *y = &cc->c->uzr[k];
      if (y->par != z->par || y->value != z->value) continue;
      ts.uz[k] = copysign(fabs(ts.uz[k]), test_value(&cc->tft, CABLE_TY_UZ, k));
      cc->uz_stop |= y->stop;
    }
  }
  cc->tft = ts;
  return CABLE_SUCCESS;
}

/* Whether sigma_1 has vanished at both ends of a location's bracket (g0, g1:
 * the BP test there): below CONT_SV_ZERO_REL of its values at the step's
 * ends (gstep), the dip test's criterion.  A short step next to the BP has
 * small values at its ends too (the flat (10,2) link at NTST 40, T = 35.75:
 * 7.2e-11 at the bracket's ends, 8.3e-10 at the step's), so the last
 * attempt (last) also takes sigma_1 below CONT_SV_ZERO_REL of sigma_2 at
 * each end (there 7.5e-8): the matrix is that close to one with a
 * one-dimensional kernel, and the determinant changes sign in between. */
static int sv1_vanished(double g0, double g1, double gstep, const cont_tests *tlo, const cont_tests *thi, int last)
{
  if (fmax(fabs(g0), fabs(g1)) < CONT_SV_ZERO_REL * gstep) return 1;
  return last && tlo->sv2 > 0 && thi->sv2 > 0 && fabs(g0) < CONT_SV_ZERO_REL * tlo->sv2 &&
         fabs(g1) < CONT_SV_ZERO_REL * thi->sv2;
}

/* The end of a location's bracket [s0, s1] where the test function (g0, g1)
 * is smaller: its converged solution (cc->xlo or cc->xhi) into xs, its tests
 * (tlo or thi) into ts; returns its arclength. */
static double end_of_bracket(const cable_cont *cc, double s0, double s1, double g0, double g1, const cont_tests *tlo,
                             const cont_tests *thi, double *xs, cont_tests *ts)
{
  int lo = fabs(g0) <= fabs(g1);
  memcpy(xs, lo ? cc->xlo : cc->xhi, (size_t)cc->n * sizeof *xs);
  *ts = lo ? *tlo : *thi;
  return lo ? s0 : s1;
}

static int locate(cable_cont *cc, int type, int which, double seed, int plain)
{
  double s0 = 0.0, f0 = test_value(&cc->tf, type, which);
  double s1 = cc->ds_used, f1 = test_value(&cc->tft, type, which);
  double far = f1, sprev = s1;
  /* the test function's true values at the bracket's ends (f0, f1 are
     scaled by the Illinois rule), and at the step's ends */
  double g0 = f0, g1 = f1, gstep = fmin(fabs(f0), fabs(f1));
  /* the last two evaluated points, for the secant step */
  double sp = s0, fp = f0, sq = s1, fq = f1;
  int side = 0, corrector_failed = 0;
  cont_tests ts = cc->tft;
  /* the tests at the bracket's ends, for the last resort below */
  cont_tests tlo = cc->tf, thi = cc->tft;
  double *xs = cc->w1, *xds = cc->w2;
  /* the solutions at the bracket's ends: the step's start and the trial point */
  memcpy(cc->xlo, cc->x, (size_t)cc->n * sizeof *cc->x);
  memcpy(cc->xhi, cc->xt, (size_t)cc->n * sizeof *cc->xt);
  const char *what = type == CABLE_TY_LP ? "fold" : type == CABLE_TY_BP ? "branch point" : "user zero";
  double tol = cc->c->epss * fabs(cc->ds_used);
  if (f1 == 0.0) {
    /* The trial point lies exactly on the zero (a UZR value on the step
       grid: the elastica's straight branch from P = 20 with DS = 0.5 lands
       on P = 21, 22, ... to the last bit).  It is the special point: no
       bracket has a sign change to shrink (the rule below counted f = 0 as
       the far side and moved the bracket to the step's start, and the
       point was lost).  AUTO takes a trial point whose secant correction is
       below its tolerance as the point itself, without a further step. */
    memcpy(xs, cc->xt, (size_t)cc->n * sizeof *xs);
    memcpy(xds, cc->xdott, (size_t)cc->n * sizeof *xds);
    return locate_accept(cc, type, which, s1, xs, xds, cc->tft, far);
  }
  for (int it = 0; it < cc->c->itmx; it++) {
    double lo = fmin(s0, s1), hi = fmax(s0, s1);
    /* Dekker's rule: the secant through the last two iterates, kept inside
       the bracket; else the Illinois regula falsi on the bracket; else its
       middle.  The secant through the latest iterates, not the bracket's
       ends, matters when an end is itself a located special point: its test
       value is ~0 (the previous BP) and a regula falsi through it crawls.
       The first iterate is the pencil test's prediction when there is one:
       exact for a matrix affine in the arclength, and far better than a
       secant through far-apart values of the kinked sigma_1 (regula falsi
       from the step's ends needed more than ITMX = 9 iterations for the
       elastica's BP1 from a 35-wide step). */
    double s = !plain && fq != fp ? sq - fq * (sq - sp) / (fq - fp) : (double)NAN;
    if (!plain && it == 0 && seed > lo && seed < hi) s = seed;
    if (!(s > lo && s < hi)) s = s1 - f1 * (s1 - s0) / (f1 - f0);
    if (!(s > lo && s < hi)) s = 0.5 * (s0 + s1);
    int rc = correct_in_bracket(cc, s, s0, s1, xs);
    cc->cnt.locate_evals++;
    if (rc == CABLE_SUCCESS) rc = cont_tangent(cc, xs, cc->xdot, xds, &ts);
    /* The corrector fails at and next to a branch point: the extended
       matrix is singular there, exactly (a zero pivot, CABLE_ERR_LINSOLVE)
       or nearly, and Newton's kernel component does not settle within ITNW
       iterations (KINSOL's maximum iterations: link102's simple BPs at
       T = 30.77 and 35.75, every iterate within about 1e-6 of the zero of
       sigma_1, 2e-7 of the step).  The failing s is the secant's estimate of
       the zero, so step off it into the larger part of the bracket, first
       by half the location tolerance, then CONT_LOCATE_GROW times farther
       each retry, up to halfway to that end (link62's simple BP at
       T = 29.81, seeded by the pencil test right on it, needed the
       halfway point).  The converged point is an ordinary iterate: it
       shrinks the bracket, and the location ends when the bracket is no
       wider than the tolerance. */
    int singular = rc == CABLE_ERR_LINSOLVE, nudged = 0;
    if (rc == CABLE_ERR_NEWTON || rc == CABLE_ERR_RECOVERABLE || rc == CABLE_ERR_LINSOLVE) corrector_failed = 1;
    /* a zero pivot (the matrix singular to working precision, e.g. an exact
       trivial branch started from exact neighbours): sfail is the BP, and a
       step of sqrt(eps) of the step makes the matrix regular while moving
       the point far less than the tolerance (half the tolerance moved the
       elastica's BP2 by 1e-5 in lambda) */
    double sfail = s, off = singular ? sqrt(DBL_EPSILON) * fabs(cc->ds_used) : 0.5 * tol;
    const double off0 = off;
    for (int last = 0; !last && (rc == CABLE_ERR_NEWTON || rc == CABLE_ERR_RECOVERABLE || rc == CABLE_ERR_LINSOLVE);
         off *= CONT_LOCATE_GROW) {
      double room = (sfail - lo > hi - sfail) ? lo - sfail : hi - sfail; /* signed, to the farther end */
      last = !(0.5 * fabs(room) > off);
      s = sfail + (last ? 0.5 * room : copysign(off, room));
      rc = correct_in_bracket(cc, s, s0, s1, xs);
      if (rc == CABLE_SUCCESS) rc = cont_tangent(cc, xs, cc->xdot, xds, &ts);
      /* a zero pivot at sfail: it is the branch point to working precision */
      nudged = singular && rc == CABLE_SUCCESS && off == off0;
    }
    if (rc != CABLE_SUCCESS && type == CABLE_TY_BP && rc != CABLE_ERR_CALLBACK && rc != CABLE_ERR_ALLOC &&
        sv1_vanished(g0, g1, gstep, &tlo, &thi, plain)) {
      /* No point between the bracket's ends converges, and sigma_1 has
         nearly vanished at both (below CONT_SV_ZERO_REL of its values at
         the step's ends, the dip test's criterion for a branch point): the
         bracket is the branch point to the corrector's resolution.  Take
         the end where sigma_1 is smaller and say how wide the bracket is. */
      s = fabs(g0) <= fabs(g1) ? s0 : s1;
      rc = correct_in_bracket(cc, s, s0, s1, xs);
      if (rc == CABLE_SUCCESS) rc = cont_tangent(cc, xs, cc->xdot, xds, &ts);
      if (rc == CABLE_SUCCESS) {
        snprintf(cc->note, sizeof cc->note,
                 "branch point located to %.3e of arclength (sigma1 = %.3e, %.3e at the ends; the corrector does not "
                 "converge between them)",
                 fabs(s1 - s0), fabs(g0), fabs(g1));
        nudged = 1; /* done */
      } else if (plain && rc != CABLE_ERR_CALLBACK && rc != CABLE_ERR_ALLOC) {
        /* The last attempt: the corrector does not even converge again
           from the converged end (sigma_1 ~ 1e-14 there, and the Newton
           step amplifies the residual left at convergence by 1 / sigma_1;
           so the first attempt failed at the flat (10,2) link at NTST 40,
           T = 30.77, sigma_1 = 8.0e-15, 3.4e-14 at the bracket's ends).
           The end's stored solution and tests are the branch point. */
        s = end_of_bracket(cc, s0, s1, g0, g1, &tlo, &thi, xs, &ts);
        snprintf(cc->note, sizeof cc->note,
                 "branch point located to %.3e of arclength (sigma1 = %.3e, %.3e at the ends; the corrector does not "
                 "converge between them, nor again at the end taken)",
                 fabs(s1 - s0), fabs(g0), fabs(g1));
        rc = CABLE_SUCCESS;
        nudged = 1;
      }
    }
    if (rc != CABLE_SUCCESS) {
      /* one line with what matters: where the point lies (the bracket's
         width) and why it was not reached; the corrector's own message is
         in the d-file's rejected-step notes */
      cont_set_error(cc, "could not locate the %s: it lies within %.3e of arclength, where %s", what, hi - lo,
                     rc == CABLE_ERR_LINSOLVE ? "the extended Jacobian is singular" : "the corrector does not converge");
      (void)sfail;
      (void)gstep;
      return rc;
    }
    double f = test_value(&ts, type, which);
    /* the bracket this iterate leaves, and whether it is within tolerance */
    double width = (f > 0) == (f1 > 0) ? fabs(s - s0) : fabs(s1 - s);
    /* the width test only after the corrector failed inside the bracket: the
       secant's own test (successive iterates within tol) is far more
       accurate when every point converges (AUTO equation file elastica.f:
       its BP2 moved by 1e-5 in lambda with the width test alone) */
    int done = nudged || fabs(s - sprev) <= tol || f == 0.0 || (corrector_failed && width <= tol);
    sprev = s;
    sp = sq; fp = fq;
    sq = s; fq = f;
    if (done) return locate_accept(cc, type, which, s, xs, xds, ts, far);
    if ((f > 0) == (f1 > 0)) {
      s1 = s; f1 = f; g1 = f; thi = ts;
      memcpy(cc->xhi, xs, (size_t)cc->n * sizeof *xs);
      if (side == 1) f0 *= CONT_ILLINOIS;
      side = 1;
    } else {
      s0 = s; f0 = f; g0 = f; tlo = ts;
      memcpy(cc->xlo, xs, (size_t)cc->n * sizeof *xs);
      if (side == -1) f1 *= CONT_ILLINOIS;
      side = -1;
    }
  }
  if (plain && type == CABLE_TY_BP && sv1_vanished(g0, g1, gstep, &tlo, &thi, plain)) {
    /* The last attempt ran out of iterations, but sigma_1 has vanished at
       both ends of its bracket (CONT_SV_ZERO_REL, as above): near a zero of
       sigma_1 of about 1e-12 its computed values are rounding noise, so
       the secant and regula falsi stop shrinking the bracket (the flat
       (10,2) link at NTST 55, T = 35.75: ITMX = 9 iterations left a bracket
       2.6e-4 wide, sigma_1 = 5.5e-12, 5.8e-12 at its ends, against 6.2e-10
       at the step's; at NTST 40, T = 30.77: 8.0e-6 wide, 1.1e-13 at both
       ends, 4.1e-8 at the step's).  Label the end where sigma_1 is
       smaller, as above. */
    double s = end_of_bracket(cc, s0, s1, g0, g1, &tlo, &thi, xs, &ts);
    snprintf(cc->note, sizeof cc->note,
             "branch point located to %.3e of arclength (sigma1 = %.3e, %.3e, sigma2 = %.3e, %.3e at the ends, "
             "sigma1 = %.3e at the step's; ITMX = %d iterations did not shrink the bracket to the tolerance %.3e)",
             fabs(s1 - s0), fabs(g0), fabs(g1), tlo.sv2, thi.sv2, gstep, cc->c->itmx, tol);
    return locate_accept(cc, type, which, s, xs, xds, ts, far);
  }
  cont_set_error(cc, "could not locate the %s within ITMX=%d iterations: it lies within %.3e of arclength", what,
                 cc->c->itmx, fabs(s1 - s0));
  return CABLE_ERR_NEWTON;
}

/* Dekker's secant steps (seeded by the pencil test) first; when they do not
 * converge (near a double branch point sign(det) sigma_1 follows different
 * singular values and is not smooth: link62's simple BP at T = 29.81, 0.12
 * from a double one), the plain Illinois regula falsi on the step's bracket,
 * which keeps a bracket that shrinks every iteration. */
int cont_locate(cable_cont *cc, int type, int which, double seed)
{
  cc->cnt.locates++;
  int rc = locate(cc, type, which, seed, 0);
  if (rc == CABLE_SUCCESS || rc == CABLE_ERR_CALLBACK) return rc;
  rc = locate(cc, type, which, (double)NAN, 1);
  if (rc != CABLE_SUCCESS && rc != CABLE_ERR_CALLBACK) {
    /* one line: the regula falsi's bracket (it shrinks every iteration, so
       it is the closer of the two attempts) */
    char second[400];
    snprintf(second, sizeof second, "%.399s", cc->err);
    cont_set_error(cc, "%s (secant steps, then regula falsi)", second);
  }
  return rc;
}

/* Two test functions may change sign inside one step: an LP and a BP that
 * coincide (the (7,2) knot's mode branches turn in T where a branch point
 * sits: the LP located to EPSS may lie on the far side of the BP), or any
 * two zeros closer than the step.  The event cont_find_event picks is the
 * first by linear interpolation, not necessarily the first in arclength; once
 * it is located, the test functions between x and the located point show
 * whether another lies before it.  Then that one is located in the shorter
 * bracket and emitted first, and the first located point is queued behind it
 * (before, its sign change was consumed: the next step started beyond it).
 * A second zero beyond the located point needs nothing: the next step starts
 * there and finds it.  With three or more zeros in one step (UZR values
 * closer than the step) the search goes on from the point located last until
 * no zero lies before it; the farthest points are dropped and found again by
 * the following steps.  At most CONT_EVENTS_MAX points come out of one step,
 * the earliest ones, in order along the branch. */
#define CONT_EVENTS_MAX 2
/* the fold test at a located BP is taken this fraction of its arclength back */
#define CONT_BP_LP_BACK 1.0e-3

int cont_locate_events(cable_cont *cc, int type, int which, double seed, int *itp)
{
  *itp = CABLE_TY_NONE;
  const double lp_far = cc->tft.lp;
  int lp_at_bp = 0;   /* the fold test's sign change is the located BP's */
  int rc = cont_locate(cc, type, which, seed);
  if (rc != CABLE_SUCCESS && rc != CABLE_ERR_CALLBACK && type == CABLE_TY_LP && cont_bp_detect(cc) &&
      cc->tf.det_sign != cc->tft.det_sign) {
    /* The fold test's sign change was not located, and the determinant
       changed sign in the same step: the extended matrix is singular inside
       it, and the tangent there is dominated by its kernel, so the fold test
       computed from it passes through a pole, not a zero (the (7,2) knot's
       mode 3 branch in braid_knot_sym at T = -15.507: -4.1e-4 and 3.7e-4 at
       the step's ends, -1.1e-2 and -2.7e-2 at iterates 2e-3 apart in its
       middle; whether the secant still converged depended on the BLAS's
       rounding).  The branch point is the special point to locate, and
       the fold test's sign change is counted as passed there: the turn in
       the parameter and the singular point are one point to the location's
       resolution (the next step's fold location failed again, within 3e-6
       of arclength of the located BP). */
    char lp_err[300];
    snprintf(lp_err, sizeof lp_err, "%.299s", cc->err);
    type = CABLE_TY_BP;
    which = -1;
    rc = cont_locate(cc, type, which, (double)NAN);
    if (rc == CABLE_SUCCESS) {
      char note[sizeof cc->note];
      snprintf(note, sizeof note, "%s", cc->note);
      snprintf(cc->note, sizeof cc->note, "%.199s%.2sa fold and a branch point in one point: the fold test changed "
               "sign with the determinant and was not located (%.200s); the branch point is", note,
               note[0] ? "; " : "", lp_err);
      cc->tft.lp = copysign(fabs(cc->tft.lp), lp_far);
      lp_at_bp = 1;
    }
  }
  if (rc != CABLE_SUCCESS) return rc;
  *itp = type;
  if (type == CABLE_TY_BP) cc->bp_kind = CABLE_BP_SIMPLE; /* det changed sign */
  if (CONT_EVENTS_MAX < 2) return rc;
  if (type == CABLE_TY_BP && cc->c->ilp > 0 && !lp_at_bp) {
    /* At the located BP the tangent is the interpolated one (branch_tangent):
       its principal-parameter component is no fold test when a fold is
       closer than the step's curvature error (a BP 0.005 from an LP: the
       sign came out either way).  The branch's own tangent a little before
       the BP (CONT_BP_LP_BACK of the way back) is regular and decides on
       which side of the fold the BP lies. */
    double sb = cc->ds_used, sback = sb * (1.0 - CONT_BP_LP_BACK);
    cont_tests tb;
    if (cont_correct(cc, cc->x, cc->xdot, sback, cc->w1) == CABLE_SUCCESS &&
        cont_tangent(cc, cc->w1, cc->xdot, cc->w2, &tb) == CABLE_SUCCESS)
      cc->tft.lp = cc->w2[cc->n - cc->nfpr];
  }
  /* Each round: is there another zero between x and the point located
     last?  Then that point is queued (it goes after) and the earlier zero
     is located.  A point queued before is dropped: it lies beyond, and the
     next step, which starts before it, finds it again.  Each round moves
     to a strictly earlier zero, so there are at most as many rounds as test
     functions; the points come out in order along the branch. */
  int max_rounds = cc->c->nuzr + 2;
  for (int round = 0; round < max_rounds; round++) {
    /* the zero just located counts as passed at the located point: mask
       it, and any user zero that vanishes there too (it is at the point,
       not before it: one point, AUTO's "first come, first served") */
    cont_tests seen = cc->tft;
    if (type == CABLE_TY_LP || lp_at_bp) seen.lp = cc->tf.lp;
    if (type == CABLE_TY_BP) seen.det_sign = cc->tf.det_sign;
    for (int k = 0; k < cc->c->nuzr; k++)
      if (seen.uz[k] == 0.0 ||
          (type == CABLE_TY_UZ && cc->c->uzr[k].par == cc->c->uzr[which].par &&
           cc->c->uzr[k].value == cc->c->uzr[which].value))
        seen.uz[k] = cc->tf.uz[k];
    int which2 = -1, type2 = find_event(cc, &cc->tf, &seen, round > 0, &which2);
    if (type2 == CABLE_TY_NONE) return CABLE_SUCCESS;
    cont_tests seen_q = seen;
    /* keep the located point: it goes second */
    const size_t nb = (size_t)cc->n * sizeof *cc->xt;
    memcpy(cc->xq, cc->xt, nb);
    memcpy(cc->xdotq, cc->xdott, nb);
    cc->tfq = cc->tft;
    cc->itp_q = type;
    cc->bp_kind_q = cc->bp_kind;
    cc->uz_hit_q = cc->uz_hit;
    cc->uz_stop_q = cc->uz_stop;
    cc->queued = 0;
    double s_first = cc->ds_used;
    cc->uz_hit = -1;
    cc->uz_stop = 0;
    char note[200];
    snprintf(note, sizeof note, "%.199s", cc->note);
    int rc2 = cont_locate(cc, type2, which2, (double)NAN);
    if (rc2 == CABLE_ERR_CALLBACK) return rc2;
    if (rc2 != CABLE_SUCCESS) {
      /* the located point stands alone (what was queued before is found
         again by the next step); say what was missed */
      char err[300];
      snprintf(err, sizeof err, "%.299s", cc->err);
      memcpy(cc->xt, cc->xq, nb);
      memcpy(cc->xdott, cc->xdotq, nb);
      cc->tft = cc->tfq;
      cc->ds_used = s_first;
      cc->bp_kind = cc->bp_kind_q;
      cc->uz_hit = cc->uz_hit_q;
      cc->uz_stop = cc->uz_stop_q;
      cc->itp_q = CABLE_TY_NONE;
      *itp = type;
      snprintf(cc->note, sizeof cc->note, "%.199s%.2sa second special point in this step was not located: %.299s",
               note, note[0] ? "; " : "", err);
      return CABLE_SUCCESS;
    }
    type = type2;
    which = which2;
    *itp = type2;
    if (type2 == CABLE_TY_BP) cc->bp_kind = CABLE_BP_SIMPLE;
    cc->ds_q = s_first - cc->ds_used;
    cc->queued = 1;
    /* a user zero between the point just located and the queued one: the
       queued point is dropped (the next step finds both again, in order) */
    int wq = -1;
    if (find_event(cc, &cc->tft, &seen_q, 1, &wq) != CABLE_TY_NONE) {
      cc->queued = 0;
      cc->itp_q = CABLE_TY_NONE;
    }
  }
  return CABLE_SUCCESS;
}

/* A dip counts when sigma_1 at the middle point is a local minimum below
 * this fraction of the larger neighbour (two samples can straddle a zero of
 * sigma_1 almost symmetrically, so the smaller neighbour may be as small as
 * the middle value); it is a branch point when the located minimum is below
 * CONT_SV_ZERO_REL of the neighbours' values (sigma_1 vanishes to
 * discretisation accuracy at a branch point of the discrete problem, while a
 * near miss keeps a minimum of the order of the neighbours' values).  A
 * false alarm costs one minimisation (about 10-20 corrector solves). */
#define CONT_DIP_RATIO 0.9
#define CONT_DIP_MAXIT 60

typedef struct {
  cable_cont *cc;
  cont_tests t;
  double *xb;   /* the converged point with the smallest sigma_1 so far (NULL: none kept) */
  double sb, vb; /* its arclength from x and its sigma_1 */
} dip_ctx;

static double dip_fn(double s, void *p)
{
  dip_ctx *d = p;
  cable_cont *cc = d->cc;
  cc->cnt.dip_evals++;
  /* Next to a double branch point the Newton matrix is nearly singular and
     the corrector from the linear predictor at x fails within a
     neighbourhood of the point; started from the closest converged point
     instead (its tangent continued to s: the same arclength condition) it
     converges much closer: on the atlas's (3,2) knot (NTST 30, DS 2, DSMAX
     10) every corrector from x within 2.5e-4 of the arclength of its second
     double branch point failed (sigma_1 no smaller than 5.9e-11 against
     6.9e-8 at the neighbours, too large for the double-point test); from the
     closest converged point none failed and sigma_1 reached 1.9e-12.  A warm
     start that fails is repeated from x.
     sigma_1 and the tangent come from the corrector's last factorisation
     (at the last iterate but one), as after every step, not from a new
     one: printed for the ten evaluations of the two dips of the flat (7,2)
     branch at issue 17's settings, the two values of sigma_1 agreed to
     7.3e-4 relative at sigma_1 = 6.8e-14 and to 2.5e-4 or better above,
     against the factor 1e-2 (CONT_SV_ZERO_REL) the double-point test asks
     of the minimum; one factorisation per evaluation less. */
  int rc = CABLE_ERR_NEWTON;
  if (d->xb && isfinite(d->vb)) {
    for (int i = 0; i < cc->n; i++) cc->w1[i] = d->xb[i] + (s - d->sb) * cc->xdot[i];
    rc = cont_correct_from(cc, cc->x, cc->xdot, s, cc->w1);
  }
  if (rc != CABLE_SUCCESS) rc = cont_correct(cc, cc->x, cc->xdot, s, cc->w1);
  if (rc != CABLE_SUCCESS || cont_tangent_after_newton(cc, cc->w1, cc->xdot, cc->w2, &d->t) != CABLE_SUCCESS)
    return (double)NAN; /* vee_min retries closer to its best point */
  if (d->xb && !(d->t.sv1 >= d->vb)) {
    memcpy(d->xb, cc->w1, (size_t)cc->n * sizeof *d->xb);
    d->sb = s;
    d->vb = d->t.sv1;
  }
  return d->t.sv1;
}

/* sigma_1^2 is a parabola in s near a zero of sigma_1 (vee_min.h) */
static double dip_fn_sq(double s, void *p)
{
  double v = dip_fn(s, p);
  return v * v;
}

/* Minimisation of sigma_1^2 (vee_min) on [lo, hi] (arclength from x) from the
 * interior point mid where sigma_1 = fm is below the values fa, fb at the
 * ends; when the minimum nearly vanishes the located point becomes the trial
 * point and the old trial point is queued behind it.  ref: the scale of
 * sigma_1 (and sigma_2) away from the dip that "nearly vanishes" is measured
 * against: the smaller neighbour, or the other one when a neighbour is a
 * located branch point (its sigma_1 vanishes by construction, to the
 * location's accuracy: judged against it, a double BP right after a located
 * simple one, sigma = 7.2e-14, 8.0e-13 against 1.6e-11, counted as a pair). */
static int dip_minimise(cable_cont *cc, double lo, double mid, double fm, double hi, double a, double b,
                        double ref)
{
  if (!(lo < mid && mid < hi && fm < a && fm < b && isfinite(a) && isfinite(b))) {
    snprintf(cc->note, sizeof cc->note,
             "smallest singular value %.3e does not dip below its neighbours %.3e, %.3e: no branch point", fm, a, b);
    return CABLE_TY_NONE;
  }
  dip_ctx ctx = {cc, cc->tf, malloc((size_t)cc->n * sizeof(double)), 0.0, (double)NAN};
  if (ctx.xb && mid == 0.0) { /* the middle point is x itself */
    memcpy(ctx.xb, cc->x, (size_t)cc->n * sizeof *ctx.xb);
    ctx.vb = fm;
  }
  cc->cnt.dips++;
  /* half the location tolerance of a sign change (EPSS |ds|): the vertex
     test below bounds the distance to the minimum by about tol */
  vee_min_result r;
  vee_min(dip_fn_sq, &ctx, lo, a * a, mid, fm * fm, hi, b * b, 0.5 * cc->c->epss * fabs(cc->ds_used), CONT_DIP_MAXIT,
          &r);
  double smin = r.s;
  /* the point, its tangent and tests in w1, w2 and ctx.t: from the last
     evaluation when that was the minimum, else evaluated again */
  double fmin_val = r.last_is_best ? sqrt(r.g) : dip_fn(smin, &ctx);
  free(ctx.xb);
  if (!(fmin_val < CONT_SV_ZERO_REL * ref)) {
    snprintf(cc->note, sizeof cc->note,
             "smallest singular value dips to %.3e (neighbours %.3e, %.3e): no branch point", fmin_val, a, b);
    return CABLE_TY_NONE;
  }
  /* queue the trial point; the located point goes first */
  memcpy(cc->xq, cc->xt, (size_t)cc->n * sizeof *cc->xt);
  memcpy(cc->xdotq, cc->xdott, (size_t)cc->n * sizeof *cc->xdott);
  cc->tfq = cc->tft;
  cc->queued = 1;
  memcpy(cc->xt, cc->w1, (size_t)cc->n * sizeof *cc->w1);
  /* tangent from the regular neighbours: x's for a dip behind x, else interpolated */
  branch_tangent(cc, smin > 0 ? smin / cc->ds_used : 0.0, cc->xdott);
  cc->tft = ctx.t;
  cont_tests_fill(cc, cc->xt, cc->xdott, &cc->tft);
  cc->tft.det_sign = cc->tfq.det_sign; /* no sign change is counted across the dip */
  cc->ds_used = smin;
  int dbl = ctx.t.sv2 > 0 && ctx.t.sv2 < CONT_SV_ZERO_REL * ref;
  cc->bp_kind = dbl ? CABLE_BP_DOUBLE : CABLE_BP_PAIR;
  snprintf(cc->note, sizeof cc->note,
           "%s: det keeps its sign, sigma1 = %.3e, sigma2 = %.3e (neighbours %.3e, %.3e)%s",
           dbl ? "double branch point" : "branch point without a sign change (a pair of BPs in one step?)",
           ctx.t.sv1, ctx.t.sv2, a, b,
           smin < 0 ? "; located before the previous output point" : "");
  return CABLE_SUCCESS;
}

int cont_check_dip(cable_cont *cc)
{
  double a = cc->tfp.sv1, m = cc->tf.sv1, b = cc->tft.sv1;
  /* the three points must not include the start: its first step reports
     nothing (AUTO), and after a switch its sigma_1 is the BP's ~0 */
  if (!cont_bp_detect(cc) || cc->npt < 3 || !(a > 0 && m > 0 && b > 0)) return CABLE_TY_NONE;
  if (!(m < a && m < b && m < CONT_DIP_RATIO * fmax(a, b))) return CABLE_TY_NONE;
  return dip_minimise(cc, -fabs(cc->ds_prev), 0.0, m, fabs(cc->ds_used), a, b, fmin(a, b));
}

int cont_dip_in_step(cable_cont *cc, double smid)
{
  double a = cc->tf.sv1, b = cc->tft.sv1;
  if (!cont_bp_detect(cc) || !(a > 0 && b > 0) || !(smid > 0 && smid < cc->ds_used)) return CABLE_TY_NONE;
  dip_ctx ctx = {cc, cc->tf, NULL, 0.0, (double)NAN};
  double m = dip_fn(smid, &ctx), lo = 0.0;
  /* x itself may be a located branch point (cont_engine.c: the pencil
     test's coincident crossings are looked at after the determinant's sign
     change is located, and in the step after a located BP).  Its sigma_1
     vanishes by construction, so a dip is then bracketed on the left by the
     point halfway from x to the predicted crossing instead.  link62's flat branch at DSMAX = 5, NTST 100: the
     step from its simple BP at T = 29.8077 (sigma_1 = 3.3e-13) to
     T = 30.2039 (7.2e-8) holds the double BP at T = 29.93, which the
     pencil test predicted (two crossings at 0.3135 of the step) and this
     test dropped because sigma_1 there was not below x's. */
  int x_located = cc->itp_x == CABLE_TY_BP;
  if (x_located && !(m < a) && m < b) {
    lo = 0.5 * smid;
    a = dip_fn(lo, &ctx);
    if (!(a > 0)) return CABLE_TY_NONE;
  }
  if (!(m < a && m < b)) return CABLE_TY_NONE;
  return dip_minimise(cc, lo, smid, m, cc->ds_used, a, b, x_located ? b : fmin(a, b));
}
