/* Branch switching at a branch point (ISW = -1).
 * At a simple BP the extended matrix [F_x; theta xdot_old^T] is singular with
 * a one-dimensional kernel: the vector phi with F_x phi = 0 that is
 * theta-orthogonal to the old tangent, i.e. the direction of the bifurcating
 * branch.  It is the right singular vector of the smallest singular value,
 * computed by inverse iteration with the stable factorisation.  With NSV >= 2
 * and a two-dimensional kernel (a double BP), BPDIR picks the kernel vector
 * (0: smallest singular value, 1: the next). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cont_impl.h"

/* A BP start whose smallest singular value exceeds this fraction of the
 * second one is not a branch point of the discretised problem: switching
 * would follow an arbitrary direction. */
#define CONT_SWITCH_SV_RATIO 0.1

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
  int dim = sv[0] <= CONT_SWITCH_SV_RATIO * sv[1] ? 1 : sv[1] <= CONT_SWITCH_SV_RATIO * sv[2] ? 2 : 0;
  if (dim == 0) {
    cont_set_error(cc, "ISW=-1: not a branch point (smallest singular values %.3e, %.3e, %.3e)", sv[0], sv[1],
                   sv[2]);
    return CABLE_ERR_SWITCH;
  }
  if (cc->c.bpsym >= dim) {
    cont_set_error(cc, "ISW=-1: BPDIR=%d but the kernel at this branch point is %d-dimensional", cc->c.bpsym, dim);
    return CABLE_ERR_SWITCH;
  }
  snprintf(cc->note, sizeof cc->note, "switching at a %s branch point: singular values %.3e, %.3e, %.3e",
           dim == 1 ? "simple" : "double", sv[0], sv[1], sv[2]);
  int pick = cc->c.bpsym;
  const double *phi = cc->svec + (size_t)pick * (size_t)n;
  memcpy(cc->xdot, phi, (size_t)n * sizeof *phi);
  cont_normalize(cc, cc->xdot);
  /* a deterministic orientation: the largest component positive; DS < 0 reverses */
  int imax = 0;
  for (int i = 1; i < n; i++)
    if (fabs(cc->xdot[i]) > fabs(cc->xdot[imax])) imax = i;
  double sgn = (cc->xdot[imax] < 0 ? -1.0 : 1.0) * (cc->c.ds < 0 ? -1.0 : 1.0);
  for (int i = 0; i < n; i++) cc->xdot[i] *= sgn;
  cc->ds = fabs(cc->c.ds);
  return CABLE_SUCCESS;
}
