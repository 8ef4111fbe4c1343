/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Starting solutions: parameters, the exact two-ring solution, and the STPNT
 * callback that dispatches to the rings or the torus construction. */
#include <string.h>

#include "braid_start_impl.h"
#include "cable/cable_status.h"

/* Poisson's ratio of the paper's runs: C = B/(1 + nu). */
static const double paper_poisson = 0.3;

void braid_start_params_init(braid_start_params *sp, braid_start_kind kind, int p, int hand,
                             double delta, double length, double torque)
{
  memset(sp, 0, sizeof *sp);
  sp->kind = kind;
  sp->p = p;
  sp->hand = hand;
  sp->delta = delta;
  sp->length = length;
  sp->torque = torque;
  sp->b1 = sp->b2 = 1.0;
  sp->c1 = sp->c2 = 1.0 / (1.0 + paper_poisson);
  sp->w01 = sp->w02 = 0.0;
  sp->ring_dm3 = 0.0;
  sp->ready = 0;
}

/* Parameter slots common to every start. */
void braid_start_set_par(braid_start_params *sp, double l, double l2, double ltot, double phi,
                          double w2fix)
{
  for (int k = 0; k < BP_NPAR; k++) sp->par[k] = 0.0;
  sp->par[BP_T] = sp->torque;
  sp->par[BP_L] = l;
  sp->par[BP_L2] = l2;
  sp->par[BP_LTOT] = ltot;
  sp->par[BP_DELTA] = sp->delta;
  sp->par[BP_PHI] = phi;
  sp->par[BP_W2FIX] = w2fix;
  sp->par[BP_B1] = sp->b1;
  sp->par[BP_B2] = sp->b2;
  sp->par[BP_C1] = sp->c1;
  sp->par[BP_C2] = sp->c2;
  sp->par[BP_W01] = sp->w01;
  sp->par[BP_W02] = sp->w02;
  sp->par[BP_EPS21] = 0.0;
  sp->par[BP_EPS13] = 0.0;
}

static int material_ok(const braid_start_params *sp)
{
  return isfinite(sp->delta) && sp->delta > 0 && isfinite(sp->b1) && sp->b1 > 0 &&
         isfinite(sp->b2) && sp->b2 > 0 && isfinite(sp->c1) && sp->c1 > 0 &&
         isfinite(sp->c2) && sp->c2 > 0 && isfinite(sp->w01) && isfinite(sp->w02) &&
         isfinite(sp->torque) && isfinite(sp->length) && sp->length > 0 &&
         isfinite(sp->ring_dm3);
}

/* Rings: strand 1 of length L on a circle of radius R = L/(2 pi); strand 2
 * at radius R - Delta, so L2 = L - 2 pi Delta.  Needs R > Delta. */
static int rings_prepare(braid_start_params *sp)
{
  sp->l = sp->length;
  sp->rc = sp->l / (2.0 * BRAID_PI);
  if (!(sp->rc > sp->delta)) return CABLE_ERR_INPUT;
  sp->l2 = 2.0 * BRAID_PI * (sp->rc - sp->delta);
  sp->nu = 0.0;
  braid_start_set_par(sp, sp->l, sp->l2, sp->l + sp->l2, 0.0, 0.0);
  return CABLE_SUCCESS;
}

/* The exact ring solution at t (doc/braid-boundary-conditions.md, "Two rings"):
 * kappa = 1/R, a = 1 - Delta kappa (= sigma'), with T1 = T, T2 = -T:
 *   xi1' = T1/C1 - w01, xi2' = a (T2/C2 + w02)                  (from T_i = dg/dxi_i')
 *   M1 = -T1 + T2/a, F3 = kappa M1, F1 = F2 = M2 = 0           ((12.2.18), (12.2.13))
 *   M3 = B1 kappa + B2 kappa/a + ring_dm3                       (free constant)
 *   q(s) = (0, -(c+s)/sqrt2, -(c-s)/sqrt2, 0), c, s = cos, sin(kappa s/2)
 *   r1(s) = ((1 - cos kappa s)/kappa, sin(kappa s)/kappa, 0),  sigma = a s. */
static void rings_state(const braid_start_params *sp, double t, double *u)
{
  const double kappa = 1.0 / sp->rc, a = 1.0 - sp->delta * kappa;
  const double t1 = sp->torque, t2 = -sp->torque;
  const double s = sp->l * t, th = kappa * s;
  const double m1 = -t1 + t2 / a;
  const double ch = cos(0.5 * th), sh = sin(0.5 * th);
  u[BR_F1] = 0.0;
  u[BR_F2] = 0.0;
  u[BR_F3] = kappa * m1;
  u[BR_M1] = m1;
  u[BR_M2] = 0.0;
  u[BR_M3] = sp->b1 * kappa + sp->b2 * kappa / a + sp->ring_dm3;
  u[BR_ETA] = 0.0;
  u[BR_W2] = 0.0;
  u[BR_W3] = kappa;
  u[BR_XI1] = (t1 / sp->c1 - sp->w01) * s;
  u[BR_T1] = t1;
  u[BR_XI2] = a * (t2 / sp->c2 + sp->w02) * s;
  u[BR_T2] = t2;
  u[BR_Q0] = 0.0;
  u[BR_Q1] = -BRAID_SQRT_HALF * (ch + sh);
  u[BR_Q2] = -BRAID_SQRT_HALF * (ch - sh);
  u[BR_Q3] = 0.0;
  u[BR_X1] = (1.0 - cos(th)) / kappa;
  u[BR_Y1] = sin(th) / kappa;
  u[BR_Z1] = 0.0;
  u[BR_SIGMA] = a * s;
}

int braid_start_prepare(braid_start_params *sp)
{
  if (sp == NULL) return CABLE_ERR_INPUT;
  sp->ready = 0;
  if (!material_ok(sp)) return CABLE_ERR_INPUT;
  int status;
  switch (sp->kind) {
  case BRAID_START_RINGS: status = rings_prepare(sp); break;
  case BRAID_START_TORUS: status = braid_start_torus_prepare(sp); break;
  default: status = CABLE_ERR_INPUT; break;
  }
  if (status == CABLE_SUCCESS) sp->ready = 1;
  return status;
}

int braid_start_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  const braid_start_params *sp = params;
  if (sp == NULL || !sp->ready || ndim != BR_NDIM) return -1;
  for (int k = 0; k <= BP_EPS13; k++) par[k] = sp->par[k];
  if (sp->kind == BRAID_START_RINGS) {
    rings_state(sp, t, u);
    return 0;
  }
  return braid_start_torus_state(sp, t, u);
}
