/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The gate of the pencil test: run it only when the test functions say a
 * branch point may lie inside the step (doc/engine.md, "The pencil test's
 * gate").
 *
 * At the step's start x the engine knows the two smallest singular values
 * sigma_a of the extended matrix J_a with their unit right and left vectors
 * V_a, U_a (J_a V_a = U_a diag(sigma_a)); at the trial point it has factored
 * J_b.  Restricted to these directions the linear interpolation of the
 * pencil test, J(t) = (1 - t) J_a + t J_b, is the 2 x 2 matrix
 *     M(t) = (1 - t) diag(sigma_a) + t B,   B = U_a^T J_b V_a,
 * up to the residual R = J_b V_a - U_a B (what J_b does outside span U_a).
 * A branch point inside the step is a zero of a singular value of J(t);
 * while the smallest ones stay in the tracked plane it shows as a dip of
 * sigma_min(M(t)) towards zero.  The pencil test (cont_pencil.c) runs when
 *  - the determinant changes sign (a branch point to locate: the pencil
 *    test's prediction seeds the location);
 *  - the start's vectors are not at hand (first step, a queued point,
 *    after a switch);
 *  - the model is not faithful: ||R||_F above CONT_GATE_RES times the
 *    smallest of the tracked values at b, or the trial point's smallest
 *    singular value is below CONT_GATE_NEW times sigma_min(B) (a new
 *    direction has come in);
 *  - sigma_min(M(t)) dips below CONT_GATE_DIP times the smaller of its end
 *    values anywhere on CONT_GATE_GRID points of [0, 1].
 * Cost: two products with J_b and a few inner products, against the pencil
 * test's assembly of J_a and CONT_PENCIL_KRYLOV solves. */
#include <cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cont_impl.h"

#define CONT_GATE_AGREE 0.25
#define CONT_GATE_DIP 0.5
#define CONT_GATE_GRID 64

int cont_gate_alloc(cable_cont *cc)
{
  size_t n2 = 2 * (size_t)cc->n;
  cc->tan_v = calloc(n2, sizeof(double));
  cc->tan_u = calloc(n2, sizeof(double));
  cc->gate_v = calloc(n2, sizeof(double));
  cc->gate_u = calloc(n2, sizeof(double));
  cc->gate_w = calloc(n2, sizeof(double));
  return cc->tan_v && cc->tan_u && cc->gate_v && cc->gate_u && cc->gate_w ? CABLE_SUCCESS : CABLE_ERR_ALLOC;
}

void cont_gate_free(cable_cont *cc)
{
  free(cc->tan_v);
  free(cc->tan_u);
  free(cc->gate_v);
  free(cc->gate_u);
  free(cc->gate_w);
}

void cont_gate_start(cable_cont *cc)
{
  /* the last tangent's vectors belong to x when its values are x's */
  cc->gate_valid = cc->tf.sv1 > 0 && cc->tf.sv2 > 0 && cc->tan_sv[0] == cc->tf.sv1 && cc->tan_sv[1] == cc->tf.sv2;
  if (!cc->gate_valid) return;
  size_t n2 = 2 * (size_t)cc->n;
  memcpy(cc->gate_v, cc->tan_v, n2 * sizeof(double));
  memcpy(cc->gate_u, cc->tan_u, n2 * sizeof(double));
  cc->gate_sv[0] = cc->tf.sv1;
  cc->gate_sv[1] = cc->tf.sv2;
}

/* Singular values smin <= smax of the 2 x 2 matrix [[a, b], [c, d]]. */
static void sigma2(double a, double b, double c, double d, double *smin, double *smax)
{
  double f2 = a * a + b * b + c * c + d * d, det = fabs(a * d - b * c);
  *smax = sqrt(0.5 * (f2 + sqrt(fmax(f2 * f2 - 4.0 * det * det, 0.0))));
  *smin = *smax > 0 ? det / *smax : 0.0;
}

static double sigma_min2(double a, double b, double c, double d)
{
  double lo, hi;
  sigma2(a, b, c, d, &lo, &hi);
  return lo;
}

static int needed(cable_cont *cc)
{
  if (!cc->gate_valid || !cc->tan_J || cc->tf.det_sign != cc->tft.det_sign) return 1;
  if (!(cc->tft.sv1 > 0 && cc->tft.sv2 > 0)) return 1;
  const int n = cc->n;
  double *W = cc->gate_w;
  const double *V = cc->gate_v, *U = cc->gate_u;
  colloc_jac_matvec_many_team(cc->tan_J, abd_solver_team(cc->tan_abd), 2, V, W);
  double B[2][2];
  for (int i = 0; i < 2; i++)
    for (int l = 0; l < 2; l++) B[i][l] = cblas_ddot(n, U + (size_t)i * (size_t)n, 1, W + (size_t)l * (size_t)n, 1);
  const double sa = cc->gate_sv[0], sa2 = cc->gate_sv[1];
  double sb, sb2;
  sigma2(B[0][0], B[0][1], B[1][0], B[1][1], &sb, &sb2);
  /* the plane still holds the trial point's two smallest singular values */
  if (fabs(sb - cc->tft.sv1) > CONT_GATE_AGREE * cc->tft.sv1) return 1;
  if (fabs(sb2 - cc->tft.sv2) > CONT_GATE_AGREE * cc->tft.sv2) return 1;
  double ends = fmin(sa, sb), lo = ends;
  for (int g = 1; g < CONT_GATE_GRID; g++) {
    double t = (double)g / CONT_GATE_GRID;
    double m = sigma_min2((1 - t) * sa + t * B[0][0], t * B[0][1], t * B[1][0], (1 - t) * sa2 + t * B[1][1]);
    if (m < lo) lo = m;
  }
  return lo < CONT_GATE_DIP * ends;
}

int cont_gate_needed(cable_cont *cc)
{
  int need = needed(cc);
  if (need) cc->gate_run++;
  else cc->gate_skipped++;
  return need;
}

