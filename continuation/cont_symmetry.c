/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The reflections a problem declares (cable_problem.symmetries) at a double
 * branch point: how one splits the kernel into its symmetric and
 * antisymmetric directions, the odd quantity that vanishes on Fix(S), and
 * the branch list's directions that are equivalent under the declared
 * actions (reported once, with their multiplicity).  doc/engine.md,
 * "Symmetry: the restriction to Fix(S)". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

#define SYM_PI 3.14159265358979323846
/* S splits the kernel when its matrix on the kernel has trace within this of 0
   (eigenvalues +1 and -1; +-2 when S is +-identity there) */
#define SYM_TRACE_TOL 0.5
/* a kernel direction lies in Fix(S) (or two directions are images) when the
   angles agree to this many degrees (the ABE's directions are accurate to
   about 1e-6 rad, doc/engine.md) */
#define SYM_ANGLE_TOL 0.01
/* the odd quantity separates the kernel when it exceeds this fraction of the
   kernel vectors' largest entry */
#define SYM_ODD_SHARE 1.0e-6

static int node_count(const cable_cont *cc)
{
  return cc->sys->ntst * cc->sys->ncol + 1;
}

void cont_sym_apply(const cable_cont *cc, const cable_symmetry *sy, const double *v, double *out)
{
  int nd = cc->ndim, npts = node_count(cc);
  for (int k = 0; k < npts; k++) sy->act(nd, v + (size_t)k * nd, out + (size_t)k * nd, cc->pb->params);
  for (int i = npts * nd; i < cc->n; i++) out[i] = v[i];
}

double cont_sym_odd(const cable_cont *cc, const cable_symmetry *sy, int comp, int at, const double *v)
{
  int nd = cc->ndim;
  const double *u = v + (at ? (size_t)(node_count(cc) - 1) * nd : 0);
  if (!sy->act) return u[comp];
  double *su = malloc((size_t)nd * sizeof *su);
  if (!su) return (double)NAN;
  sy->act(nd, u, su, cc->pb->params);
  double r = u[comp] - su[comp];
  free(su);
  return r;
}

static double vmax(int n, const double *v)
{
  double m = 0.0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
  return m;
}

int cont_sym_split(cable_cont *cc, const cable_symmetry *sy, const double *e1, const double *e2, double *es,
                   double *ea, double *phi_s, int *comp, int *at, char *msg, size_t len)
{
  int n = cc->n, nd = cc->ndim, last = node_count(cc) - 1;
  const char *name = sy->name ? sy->name : "S";
  double phi;
  if (sy->act) {
    double *s1 = malloc(2 * (size_t)n * sizeof *s1);
    if (!s1) return snprintf(msg, len, "out of memory"), -1;
    double *s2 = s1 + n;
    cont_sym_apply(cc, sy, e1, s1);
    cont_sym_apply(cc, sy, e2, s2);
    /* S on the kernel: M[i][j] = <e_i, S e_j> */
    double m11 = colloc_system_inner(cc->sys, e1, s1), m12 = colloc_system_inner(cc->sys, e1, s2);
    double m21 = colloc_system_inner(cc->sys, e2, s1), m22 = colloc_system_inner(cc->sys, e2, s2);
    free(s1);
    if (!(fabs(m11 + m22) < SYM_TRACE_TOL)) {
      snprintf(msg, len, "%s does not split the kernel (its trace there is %.3g: it fixes%s both directions)", name,
               m11 + m22, m11 + m22 > 0 ? "" : " neither of");
      return -1;
    }
    /* the projector (I + M) / 2 onto the +1 eigenvector: its larger column */
    double c1a = 1.0 + m11, c1b = m21, c2a = m12, c2b = 1.0 + m22;
    phi = hypot(c1a, c1b) >= hypot(c2a, c2b) ? atan2(c1b, c1a) : atan2(c2b, c2a);
  } else {
    if (sy->odd_comp < 0 || sy->odd_comp >= nd || (sy->odd_at != 0 && sy->odd_at != 1)) {
      snprintf(msg, len, "%s: odd_comp %d or odd_at %d out of range", name, sy->odd_comp, sy->odd_at);
      return -1;
    }
    size_t o = (size_t)(sy->odd_at ? last : 0) * nd + (size_t)sy->odd_comp;
    double o1 = e1[o], o2 = e2[o];
    if (!(hypot(o1, o2) > SYM_ODD_SHARE * fmax(vmax(n, e1), vmax(n, e2)))) {
      snprintf(msg, len, "%s: U(%d) at t = %d vanishes on the whole kernel (both directions in Fix(%s))", name,
               sy->odd_comp + 1, sy->odd_at, name);
      return -1;
    }
    phi = atan2(-o1, o2); /* o1 cos + o2 sin = 0 */
  }
  /* the line, not the half-line: phi in (-90, 90] degrees */
  if (phi > 0.5 * SYM_PI) phi -= SYM_PI;
  if (phi <= -0.5 * SYM_PI) phi += SYM_PI;
  double cs = cos(phi), sn = sin(phi);
  for (int i = 0; i < n; i++) {
    es[i] = cs * e1[i] + sn * e2[i];
    ea[i] = -sn * e1[i] + cs * e2[i];
  }
  *phi_s = phi;
  if (sy->act) {
    /* the odd quantity: (u - S u)_c at the end and component where e_a is largest */
    double best = -1.0;
    for (int end = 0; end < 2; end++)
      for (int c = 0; c < nd; c++) {
        double v = fabs(ea[(size_t)(end ? last : 0) * nd + (size_t)c]);
        if (v > best) { best = v; *comp = c; *at = end; }
      }
  } else {
    *comp = sy->odd_comp;
    *at = sy->odd_at;
  }
  return 0;
}

/* degrees, the line's angle in [0, 180) */
static double line_angle(double deg)
{
  double a = fmod(deg, 180.0);
  return a < 0 ? a + 180.0 : a;
}

static double angle_gap(double a, double b)
{
  double d = fabs(line_angle(a) - line_angle(b));
  return fmin(d, 180.0 - d);
}

void cont_sym_merge(cable_cont *cc, const double *e1, const double *e2)
{
  const cable_problem *pb = cc->pb;
  int n = cc->n;
  for (int k = 0; k < cc->nbr; k++) {
    if (cc->br[k].multiplicity < 1) cc->br[k].multiplicity = 1;
  }
  if (!pb->symmetries || pb->nsym <= 0 || cc->nbr <= 0) return;
  double *s1 = malloc(2 * (size_t)n * sizeof *s1);
  if (!s1) return;
  double *s2 = s1 + n;
  int last = node_count(cc) - 1, nd = cc->ndim;
  for (int j = 0; j < pb->nsym; j++) {
    const cable_symmetry *sy = &pb->symmetries[j];
    int decl = sy->multiplicity > 1 ? sy->multiplicity : 1;
    if (sy->act) {
      cont_sym_apply(cc, sy, e1, s1);
      cont_sym_apply(cc, sy, e2, s2);
      double m11 = colloc_system_inner(cc->sys, e1, s1), m12 = colloc_system_inner(cc->sys, e1, s2);
      double m21 = colloc_system_inner(cc->sys, e2, s1), m22 = colloc_system_inner(cc->sys, e2, s2);
      for (int k = 0; k < cc->nbr; k++) {
        double p = cc->br[k].phi * (SYM_PI / 180.0), cs = cos(p), sn = sin(p);
        double b1 = m11 * cs + m12 * sn, b2 = m21 * cs + m22 * sn; /* S u in (e1, e2) */
        double img = atan2(b2, b1) * (180.0 / SYM_PI);
        if (angle_gap(img, cc->br[k].phi) < SYM_ANGLE_TOL) {
          if (b1 * cs + b2 * sn > 0 && !cc->br[k].sym) {   /* S u = u: in Fix(S) */
            cc->br[k].sym = j + 1;
            if (decl > cc->br[k].multiplicity) cc->br[k].multiplicity = decl;
          }
          continue;
        }
        for (int l = k + 1; l < cc->nbr; l++) {
          if (angle_gap(img, cc->br[l].phi) >= SYM_ANGLE_TOL) continue;
          /* l is k's image: one class, reported at k */
          cc->br[k].multiplicity += cc->br[l].multiplicity;
          memmove(&cc->br[l], &cc->br[l + 1], (size_t)(cc->nbr - l - 1) * sizeof cc->br[0]);
          cc->nbr--;
          break;
        }
      }
    } else if (sy->odd_comp >= 0 && sy->odd_comp < nd) {
      size_t o = (size_t)(sy->odd_at ? last : 0) * nd + (size_t)sy->odd_comp;
      double o1 = e1[o], o2 = e2[o], on = hypot(o1, o2);
      for (int k = 0; k < cc->nbr && on > 0; k++) {
        double p = cc->br[k].phi * (SYM_PI / 180.0);
        if (fabs(o1 * cos(p) + o2 * sin(p)) < (SYM_ANGLE_TOL * SYM_PI / 180.0) * on && !cc->br[k].sym) {
          cc->br[k].sym = j + 1;
          if (decl > cc->br[k].multiplicity) cc->br[k].multiplicity = decl;
        }
      }
    }
  }
  free(s1);
}
