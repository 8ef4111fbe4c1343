/* Special points: folds (LP), branch points (BP), user zeros (UZ).
 * Test functions (each changes sign at its special point):
 *   LP: the principal parameter's component of the unit tangent;
 *   BP: the signed smallest singular value of the extended Newton matrix
 *       [F_x; theta xdot^T], sign from its determinant (from the stable
 *       factorisation: no overflow, no end-to-end products);
 *   UZ: PAR(k) - value.
 * A sign change between two accepted points is located by regula falsi
 * with the Illinois modification on the arclength from the first point,
 * until the arclength correction is below EPSS * |ds| (AUTO's EPSS). */
#include <math.h>
#include <string.h>

#include "cont_impl.h"

static double param_value(const cable_cont *cc, const double *x, int k)
{
  const double *p = x + (cc->n - cc->nfpr);
  for (int q = 0; q < cc->nfpr; q++)
    if (cc->sys->icp[q] == k) return p[q];
  return cc->sys->par[k];
}

void cont_tests_fill(cable_cont *cc, const double *x, const double *xdot, cont_tests *tf)
{
  tf->lp = xdot[cc->n - cc->nfpr];
  for (int k = 0; k < cc->c.nuzr; k++)
    tf->uz[k] = param_value(cc, x, cc->c.uzr[k].par) - cc->c.uzr[k].value;
}

static double bp_test(const cont_tests *t) { return t->det_sign * (t->sv1 > 0 ? t->sv1 : 1.0); }

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

/* The event closest to the first point (by linear interpolation), or NONE. */
int cont_find_event(const cable_cont *cc, const cont_tests *a, const cont_tests *b, int *which)
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
  if (cc->c.ilp > 0) CONSIDER(CABLE_TY_LP, -1);
  if (cc->c.isp > 0 && a->det_sign != b->det_sign) CONSIDER(CABLE_TY_BP, -1);
  for (int k = 0; k < cc->c.nuzr; k++) CONSIDER(CABLE_TY_UZ, k);
#undef CONSIDER
  return best;
}

int cont_locate(cable_cont *cc, int type, int which)
{
  double s0 = 0.0, f0 = test_value(&cc->tf, type, which);
  double s1 = cc->ds_used, f1 = test_value(&cc->tft, type, which);
  double far = f1, sprev = s1;
  int side = 0;
  cont_tests ts = cc->tft;
  double *xs = cc->w1, *xds = cc->w2;
  for (int it = 0; it < cc->c.itmx; it++) {
    double s = s1 - f1 * (s1 - s0) / (f1 - f0);
    double lo = fmin(s0, s1), hi = fmax(s0, s1);
    if (!(s > lo && s < hi)) s = 0.5 * (s0 + s1);
    if (cont_correct(cc, cc->x, cc->xdot, s, xs) != CABLE_SUCCESS) return CABLE_ERR_NEWTON;
    if (cont_tangent(cc, xs, cc->xdot, xds, &ts) != CABLE_SUCCESS) return CABLE_ERR_LINSOLVE;
    double f = test_value(&ts, type, which);
    int done = fabs(s - sprev) <= cc->c.epss * fabs(cc->ds_used) || f == 0.0;
    sprev = s;
    if (done) {
      memcpy(cc->xt, xs, (size_t)cc->n * sizeof *xs);
      memcpy(cc->xdott, xds, (size_t)cc->n * sizeof *xds);
      /* count the located point as past the event, so that it is not found again */
      if (type == CABLE_TY_LP) ts.lp = copysign(fabs(ts.lp), far);
      else if (type == CABLE_TY_BP) ts.det_sign = cc->tft.det_sign;
      else ts.uz[which] = copysign(fabs(ts.uz[which]), far);
      cc->tft = ts;
      cc->ds_used = s;
      if (type == CABLE_TY_UZ) {
        cc->uz_hit = which;
        cc->uz_stop = cc->c.uzr[which].stop;
      }
      return CABLE_SUCCESS;
    }
    if ((f > 0) == (f1 > 0)) {
      s1 = s; f1 = f;
      if (side == 1) f0 *= 0.5;
      side = 1;
    } else {
      s0 = s; f0 = f;
      if (side == -1) f1 *= 0.5;
      side = -1;
    }
  }
  cont_set_error(cc, "could not locate the %s within ITMX=%d iterations",
                 type == CABLE_TY_LP ? "fold" : type == CABLE_TY_BP ? "branch point" : "user zero",
                 cc->c.itmx);
  return CABLE_ERR_NEWTON;
}
