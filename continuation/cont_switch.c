/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Branch switching at a branch point (ISW = -1).
 * At a simple BP the extended matrix [F_x; theta xdot_old^T] is singular with
 * a one-dimensional kernel: the vector phi with F_x phi = 0 that is
 * theta-orthogonal to the old tangent, i.e. the direction of the bifurcating
 * branch.  It is the right singular vector of the smallest singular value,
 * computed by inverse iteration with the stable factorisation.
 *
 * At a double BP the kernel is two-dimensional and the two singular vectors
 * are an arbitrary orthonormal basis of it (any rotation of them is as
 * good).  The switch first makes the basis canonical, from the solution
 * components U(1), U(2), ... in turn:
 *   1. the first component c whose energy int u_c^2 dt, as a quadratic form on
 *      the kernel, has two clearly different principal values: e1 is the
 *      kernel direction with the most energy in U(c), e2 (orthogonal) the one
 *      with the least (for two uncoupled copies of a problem: e1 moves only
 *      the first copy, e2 only the second);
 *   2. otherwise (every component's energy is the same in all kernel
 *      directions, e.g. a rotation-type symmetry) the first c with u_c(0) not
 *      zero on the kernel: e1 moves u_c(0), e2 keeps u_c(0) = 0 (keeps a
 *      reflection symmetry that fixes u_c(0) = 0);
 * then follows cos(BPANGLE) e1 + sin(BPANGLE) e2, or e1 / e2 for BPDIR = 0 / 1
 * when BPANGLE is not set.  Orientation of e1 and e2: the first component
 * that is not negligible at t = 0 is positive there (else the entry of
 * largest magnitude); DS < 0 reverses the direction. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

/* A BP start whose smallest singular value exceeds this fraction of the
 * second one is not a branch point of the discretised problem: switching
 * would follow an arbitrary direction. */
#define CONT_SWITCH_SV_RATIO 0.1
/* Rule 1 takes component c when its energy form's principal values differ by
 * more than CONT_KERNEL_GAP of their sum, and c carries at least
 * CONT_KERNEL_SHARE of the kernel's total energy (below that the form is
 * round-off).  Rule 2 takes c when |u_c(0)| over the kernel exceeds
 * CONT_KERNEL_SHARE of the kernel vectors' largest entry. */
#define CONT_KERNEL_GAP 0.1
#define CONT_KERNEL_SHARE 1.0e-6
/* orient(): a value at t = 0 below this fraction of the vector's largest
 * entry counts as zero (the kernel vectors are accurate to about CONT_SV_RTOL
 * relative, cont_tangent.c, so a smaller value's sign is noise) */
#define CONT_KERNEL_ORIENT 1.0e-3
#define CONT_PI 3.14159265358979323846

/* sum over nodes of the quadrature weight times a_c b_c (component c), or
   over all components when c < 0 */
static double component_inner(const colloc_system *s, const double *a, const double *b, int c)
{
  int nd = s->ndim, nc = s->ncol;
  double sum = 0.0;
  for (int j = 0; j < s->ntst; j++) {
    double h = s->mesh[j + 1] - s->mesh[j];
    for (int k = 0; k <= nc; k++) {
      size_t o = (size_t)(j * nc + k) * (size_t)nd;
      double d = 0.0;
      for (int i = (c < 0 ? 0 : c); i < (c < 0 ? nd : c + 1); i++) d += a[o + i] * b[o + i];
      sum += h * s->basis.wn[k] * d;
    }
  }
  return sum;
}

/* index of the entry of largest magnitude among u components c (all when c < 0) */
static int largest_entry(const cable_cont *cc, const double *v, int c)
{
  int nd = cc->ndim, nu = cc->n - cc->nfpr, best = -1;
  for (int i = 0; i < nu; i++)
    if ((c < 0 || i % nd == c) && (best < 0 || fabs(v[i]) > fabs(v[best]))) best = i;
  return best < 0 ? 0 : best;
}

/* The first component U(c) whose value at t = 0 is not negligible is made
 * positive there (so that e1 + e2 moves both copies of a doubled problem in
 * phase); failing that, the entry of largest magnitude. */
static void orient(const cable_cont *cc, double *v)
{
  int imax = largest_entry(cc, v, -1), pick = imax;
  for (int c = cc->ndim - 1; c >= 0; c--)
    if (fabs(v[c]) > CONT_KERNEL_ORIENT * fabs(v[imax])) pick = c;
  if (v[pick] < 0)
    for (int i = 0; i < cc->n; i++) v[i] = -v[i];
}

/* e1 = cos(psi) v1 + sin(psi) v2, e2 = -sin(psi) v1 + cos(psi) v2 into out1, out2 */
static void rotate(int n, const double *v1, const double *v2, double psi, double *out1, double *out2)
{
  double cs = cos(psi), sn = sin(psi);
  for (int i = 0; i < n; i++) {
    out1[i] = cs * v1[i] + sn * v2[i];
    out2[i] = -sn * v1[i] + cs * v2[i];
  }
}

/* The canonical basis (rules above) of the kernel spanned by v1, v2 into e1,
 * e2; a description into how.  -1 when no rule applies. */
static int canonical_kernel(cable_cont *cc, const double *v1, const double *v2, double *e1, double *e2,
                            char *how, size_t len)
{
  const colloc_system *s = cc->sys;
  int n = cc->n, nd = cc->ndim, comp = -1;
  double total = component_inner(s, v1, v1, -1) + component_inner(s, v2, v2, -1);
  for (int c = 0; c < nd && comp < 0; c++) {
    double g11 = component_inner(s, v1, v1, c), g12 = component_inner(s, v1, v2, c);
    double g22 = component_inner(s, v2, v2, c), tr = g11 + g22;
    double spread = 2.0 * hypot(0.5 * (g11 - g22), g12);
    if (!(tr > CONT_KERNEL_SHARE * total) || !(spread > CONT_KERNEL_GAP * tr)) continue;
    rotate(n, v1, v2, 0.5 * atan2(2.0 * g12, g11 - g22), e1, e2); /* e1: the larger principal value */
    comp = c;
    snprintf(how, len, "e1 = the kernel direction with the most energy in U(%d) (%.3g of the kernel's), e2 the least",
             c + 1, (0.5 * tr + 0.5 * spread) / total);
  }
  double vmax = fabs(v1[largest_entry(cc, v1, -1)]) + fabs(v2[largest_entry(cc, v2, -1)]);
  for (int c = 0; c < nd && comp < 0; c++) {
    double a = v1[c], b = v2[c], r = hypot(a, b); /* node 0 is t = 0 */
    if (!(r > CONT_KERNEL_SHARE * vmax)) continue;
    rotate(n, v1, v2, atan2(b, a), e1, e2); /* e1 = (a v1 + b v2) / r: u_c(0) = r; e2: u_c(0) = 0 */
    comp = c;
    snprintf(how, len, "e1 = the kernel direction that moves U(%d) at t = 0, e2 the one that keeps it", c + 1);
  }
  if (comp < 0) return -1;
  orient(cc, e1);
  orient(cc, e2);
  return comp;
}

/* AUTO-07p's orientation of a starting direction (its STDRBV, which also
 * starts a switched BVP branch, ISW < 0): of the unit vector, the first free
 * parameter's component that is not negligible, |p'| / (1 + |p|) > EPSL, is
 * made positive; when every one is negligible (a pitchfork: the bifurcating
 * direction leaves the parameters fixed), the first solution component at
 * t = 1 with |u_i'| / (1 + |u_i|) > EPSU.  (auto-07p's demo lin: the switch
 * at BP1 follows u = -sqrt(2) sin(pi t), whose u' is positive at t = 1.) */
static void orient_auto(cable_cont *cc, double *v)
{
  int n = cc->n, nfpr = cc->nfpr, nd = cc->ndim;
  cont_normalize(cc, v);
  int pick = -1;
  for (int q = 0; q < nfpr && pick < 0; q++) {
    int i = n - nfpr + q;
    if (fabs(v[i]) / (1.0 + fabs(cc->x[i])) > cc->c->epsl) pick = i;
  }
  size_t last = (size_t)cc->sys->ntst * (size_t)cc->sys->ncol * (size_t)nd; /* the node at t = 1 */
  for (int c = 0; c < nd && pick < 0; c++) {
    size_t i = last + (size_t)c;
    if (fabs(v[i]) / (1.0 + fabs(cc->x[i])) > cc->c->epsu) pick = (int)i;
  }
  if (pick >= 0 && v[pick] < 0)
    for (int i = 0; i < n; i++) v[i] = -v[i];
}

/* The kernel's dimension from the three smallest singular values: the
 * numerical rank drops where the gap between consecutive singular values is
 * largest, and that gap must be at least 1 / CONT_SWITCH_SV_RATIO.  Testing
 * sigma1 <= 0.1 sigma2 first called the double BP of the (6,2) link at
 * T = 23.57 (sigma = 1.5e-14, 2.4e-12, 8.8e-6; the detector: "double branch
 * point") simple; the simple BP at T = 29.81 next to a double one
 * (2.8e-16, 1.95e-8, 2.3e-7) has its largest gap after sigma1.  0: no gap. */
static int kernel_dimension(const double *sv)
{
  double r1 = sv[0] / sv[1], r2 = sv[1] / sv[2]; /* NaN for zero singular values: no gap */
  int one = r1 <= CONT_SWITCH_SV_RATIO, two = r2 <= CONT_SWITCH_SV_RATIO;
  if (one && two) return r2 < r1 ? 2 : 1;
  return one ? 1 : two ? 2 : 0;
}

/* appends to the start's note (truncated at its size) */
static void note_append(cable_cont *cc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void note_append(cable_cont *cc, const char *fmt, ...)
{
  size_t l = strlen(cc->note);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(cc->note + l, sizeof cc->note - l, fmt, ap);
  va_end(ap);
}

/* The branch list with the problem's declared reflections: a list from the
 * ABE is merged (cont_sym_merge); when the ABE gave none (degenerate, e.g. a
 * rotation-type symmetry), each reflection that splits the kernel gives its
 * symmetric direction, to be followed in the restricted problem.  Appends to
 * abe what it did. */
static int symmetric_list(cable_cont *cc, const double *e1, const double *e2, char *abe, size_t len)
{
  const cable_problem *pb = cc->pb;
  size_t l = strlen(abe);
  if (cc->nbr > 0) {
    int before = cc->nbr;
    cont_sym_merge(cc, e1, e2);
    l += (size_t)snprintf(abe + l, len - l, "; symmetry classes: %d of %d directions", cc->nbr, before);
    for (int k = 0; k < cc->nbr && l < len; k++)
      l += (size_t)snprintf(abe + l, len - l, "%s %.4g (x%d%s)", k ? "," : "", cc->br[k].phi, cc->br[k].multiplicity,
                            cc->br[k].sym ? ", symmetric" : "");
    return CABLE_SUCCESS;
  }
  if (!cc->abe_psi) return CABLE_SUCCESS;
  int n = cc->n, nb = 0;
  double *es = malloc(2 * (size_t)n * sizeof *es);
  if (!es) return CABLE_ERR_ALLOC;
  double *ea = es + n;
  for (int j = 0; j < pb->nsym && nb < CABLE_MAX_BRANCHES && l < len; j++) {
    double phi;
    int comp, at;
    char why[200];
    if (cont_sym_split(cc, &pb->symmetries[j], e1, e2, es, ea, &phi, &comp, &at, why, sizeof why) != 0) {
      l += (size_t)snprintf(abe + l, len - l, "; %s", why);
      continue;
    }
    double deg = phi * (180.0 / CONT_PI);
    if (deg < -0.125) deg += 180.0;
    int dup = 0;
    for (int k = 0; k < nb; k++) dup |= fabs(cc->br[k].phi - deg) < 1e-6;
    if (dup) continue;
    cable_branch_dir *b = &cc->br[nb++];
    memset(b, 0, sizeof *b);
    b->phi = deg;
    b->a[1] = cos(deg * (CONT_PI / 180.0));
    b->a[2] = sin(deg * (CONT_PI / 180.0));
    b->mu = (double)NAN;
    b->multiplicity = pb->symmetries[j].multiplicity > 1 ? pb->symmetries[j].multiplicity : 1;
    b->sym = j + 1;
    b->restricted = 1;
    l += (size_t)snprintf(abe + l, len - l, "; Fix(%s) holds the kernel direction at %.4g degrees (x%d)",
                          pb->symmetries[j].name ? pb->symmetries[j].name : "S", deg, b->multiplicity);
  }
  free(es);
  if (nb > 0) cc->nbr = nb;
  return CABLE_SUCCESS;
}

/* Asks the step to rebuild the handle on the problem restricted to Fix(S)
 * of the k-th entry's symmetry: e_s, e_a and the antisymmetric left null
 * vector psi_a = L_2(e_s) psi_1 - L_1(e_s) psi_2 (psi_a^T F_xx[q0, e_s] = 0)
 * into cc->rs_vec. */
static int request_restriction(cable_cont *cc, int k, const double *e1, const double *e2)
{
  int n = cc->n, j = cc->br[k].sym - 1;
  if (!cc->rs_vec && !(cc->rs_vec = malloc(3 * (size_t)n * sizeof *cc->rs_vec))) return CABLE_ERR_ALLOC;
  double *es = cc->rs_vec, *ea = es + n, *pa = ea + n, phi;
  char why[200];
  if (cont_sym_split(cc, &cc->pb->symmetries[j], e1, e2, es, ea, &phi, &cc->rs_comp, &cc->rs_at, why, sizeof why)) {
    cont_set_error(cc, "ISW=-1: %s", why);
    return CABLE_ERR_SWITCH;
  }
  double cs = cos(phi), sn = sin(phi);
  double l1 = cc->abe_L[0][0] * cs + cc->abe_L[0][1] * sn, l2 = cc->abe_L[1][0] * cs + cc->abe_L[1][1] * sn;
  const double *p1 = cc->abe_psi, *p2 = cc->abe_psi + n;
  double nr = 0.0;
  for (int i = 0; i < n; i++) {
    pa[i] = l2 * p1[i] - l1 * p2[i];
    nr = fmax(nr, fabs(pa[i]));
  }
  if (!(nr > 0)) {
    cont_set_error(cc, "ISW=-1: L vanishes on the symmetric kernel direction (no transversal crossing)");
    return CABLE_ERR_SWITCH;
  }
  cc->rs_sym = j;
  return CONT_SWITCH_RESTRICT;
}

int cont_switch_direction(cable_cont *cc)
{
  int n = cc->n;
  double xold_dot_norm = colloc_system_inner(cc->sys, cc->xdot, cc->xdot);
  if (!(xold_dot_norm > 0)) {
    cont_set_error(cc, "ISW=-1: the stored solution has no branch direction to switch from");
    return CABLE_ERR_SWITCH;
  }
  cont_normalize(cc, cc->xdot);
  cont_tests tf;
  int rc = cont_tangent(cc, cc->x, cc->xdot, cc->w1, &tf);
  if (rc == CABLE_ERR_LINSOLVE) {
    cont_set_error(cc, "ISW=-1: the extended Jacobian is exactly singular at the branch point");
    return CABLE_ERR_SWITCH;
  }
  if (rc != CABLE_SUCCESS) return rc;
  /* three values tell a simple kernel (sigma1 << sigma2) from a
     two-dimensional one (sigma2 << sigma3) */
  double sv[3] = {0, 0, 0};
  int svrc = cont_smallest_sv(cc, 3, sv, cc->svec);
  if (svrc != 0 && svrc != 2) {
    cont_set_error(cc, "ISW=-1: singular vectors did not converge");
    return CABLE_ERR_SWITCH;
  }
  int dim = kernel_dimension(sv);
  if (dim == 0) {
    cont_set_error(cc, "ISW=-1: not a branch point (smallest singular values %.3e, %.3e, %.3e)", sv[0], sv[1],
                   sv[2]);
    return CABLE_ERR_SWITCH;
  }
  int angle_set = !isnan(cc->c->bpangle);
  if (dim == 1 && cc->c->bpsym > 0 && !angle_set) {
    cont_set_error(cc, "ISW=-1: BPDIR=%d but the kernel at this branch point is %d-dimensional", cc->c->bpsym, dim);
    return CABLE_ERR_SWITCH;
  }
  int len = snprintf(cc->note, sizeof cc->note, "switching at a %s branch point: singular values %.3e, %.3e, %.3e",
                     dim == 1 ? "simple" : "double", sv[0], sv[1], sv[2]);
  double *dir = cc->xdot;
  if (dim == 1) {
    memcpy(dir, cc->svec, (size_t)n * sizeof *dir);
    if (cc->c->bp_orient_auto) {
      orient_auto(cc, dir);
    } else {
      /* a deterministic orientation: the largest component (parameters included) positive */
      int imax = 0;
      for (int i = 1; i < n; i++)
        if (fabs(dir[i]) > fabs(dir[imax])) imax = i;
      if (dir[imax] < 0) for (int i = 0; i < n; i++) dir[i] = -dir[i];
    }
    if (angle_set) snprintf(cc->note + len, sizeof cc->note - (size_t)len, "; BPANGLE ignored (simple kernel)");
  } else {
    double *e1 = cc->w1, *e2 = cc->w2;
    char how[200];
    if (canonical_kernel(cc, cc->svec, cc->svec + (size_t)n, e1, e2, how, sizeof how) < 0) {
      cont_set_error(cc, "ISW=-1: no solution component distinguishes the two kernel vectors at this double branch point");
      return CABLE_ERR_SWITCH;
    }
    if (!angle_set && cc->c->bpsym == 0) {
      /* the branch directions (cont_branches.c); A = cc->J still holds
         [F_x; theta q0^T] with q0 the stored tangent, now in dir */
      double *q0 = cc->w3;
      char abe[500];
      memcpy(q0, dir, (size_t)n * sizeof *q0);
      int arc = cont_branches_compute(cc, q0, e1, e2, abe, sizeof abe);
      if (arc != CABLE_SUCCESS) return arc;
      int k = cc->c->branch > 0 ? cc->c->branch : 1;
      if (cc->pb->symmetries && cc->pb->nsym > 0) {
        int rrc = symmetric_list(cc, e1, e2, abe, sizeof abe);
        if (rrc != CABLE_SUCCESS) return rrc;
        if (cc->nbr > 0 && k <= cc->nbr && cc->br[k - 1].restricted) {
          note_append(cc, "; %s; %s; following branch %d (%.4g degrees from e1 towards e2)", how, abe, k,
                      cc->br[k - 1].phi);
          return request_restriction(cc, k - 1, e1, e2);
        }
      }
      if (cc->nbr > 0 && k <= cc->nbr) {
        const cable_branch_dir *b = &cc->br[k - 1];
        for (int i = 0; i < n; i++) dir[i] = b->a[0] * q0[i] + b->a[1] * e1[i] + b->a[2] * e2[i];
        note_append(cc, "; %s; %s; following branch %d (%.4g degrees from e1 "
                 "towards e2%s)", how, abe, k, b->phi, b->a[0] != 0 ? ", with the known tangent" : "");
        goto oriented;
      }
      if (cc->c->branch > 1 || cc->nbr > 0) {
        cont_set_error(cc, "ISW=-1: BRANCH=%d but the bifurcation equations give %d direction%s (%s)", k,
                       cc->nbr < 0 ? 0 : cc->nbr, cc->nbr == 1 ? "" : "s", abe);
        return CABLE_ERR_SWITCH;
      }
      len += snprintf(cc->note + len, sizeof cc->note - (size_t)len, "; %s; the canonical basis instead", abe);
    }
    double phi = angle_set ? cc->c->bpangle * (CONT_PI / 180.0) : (cc->c->bpsym ? 0.5 * CONT_PI : 0.0);
    for (int i = 0; i < n; i++) dir[i] = cos(phi) * e1[i] + sin(phi) * e2[i];
    snprintf(cc->note + len, sizeof cc->note - (size_t)len, "; %s; following %g degrees from e1 towards e2", how,
             phi * (180.0 / CONT_PI));
  }
oriented:
  cont_normalize(cc, dir);
  if (cc->c->ds < 0) for (int i = 0; i < n; i++) dir[i] = -dir[i];
  cc->ds = fabs(cc->c->ds);
  return CABLE_SUCCESS;
}
