/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Guarded wrappers around the generated braid right-hand side
 * (braid_rhs_gen.c): material and state checks, AUTO's FUNC, auxiliary
 * quantities and the partials of g. */
#include "braid_model.h"

#include <math.h>
#include <string.h>

#include "braid_rhs_gen.h"

void braid_material_from_par(const double *par, braid_material *m)
{
  m->Delta = par[BP_DELTA];
  m->B1 = par[BP_B1];
  m->B2 = par[BP_B2];
  m->C1 = par[BP_C1];
  m->C2 = par[BP_C2];
  m->w01 = par[BP_W01];
  m->w02 = par[BP_W02];
}

/* The order of the generated code's parameter array. */
static void material_to_array(const braid_material *m, double p[BRAID_NMAT])
{
  p[0] = m->Delta;
  p[1] = m->B1;
  p[2] = m->B2;
  p[3] = m->C1;
  p[4] = m->C2;
  p[5] = m->w01;
  p[6] = m->w02;
}

static int positive_finite(double x) { return isfinite(x) && x > 0.0; }

int braid_material_check(const braid_material *m)
{
  if (!positive_finite(m->Delta) || !positive_finite(m->B1) || !positive_finite(m->B2)
      || !positive_finite(m->C1) || !positive_finite(m->C2) || !isfinite(m->w01)
      || !isfinite(m->w02))
    return BRAID_BAD_MATERIAL;
  return BRAID_OK;
}

/* cos(eta) and 1 - Delta*omega3 against the thresholds; the comparisons are
 * written so that NaN fails them. */
static int domain_check(double eta, double w3, double Delta)
{
  if (!(cos(eta) > BRAID_COS_ETA_MIN)) return BRAID_SINGULAR_COS_ETA;
  if (!(1.0 - Delta * w3 > BRAID_ONE_MINUS_DW3_MIN)) return BRAID_SINGULAR_SIGMA;
  return BRAID_OK;
}

int braid_state_check(const double *u, const braid_material *m)
{
  int st = braid_material_check(m);
  if (st != BRAID_OK) return st;
  for (int i = 0; i < BR_NDIM; i++)
    if (!isfinite(u[i])) return BRAID_NONFINITE;
  return domain_check(u[BR_ETA], u[BR_W3], m->Delta);
}

static int all_finite(const double *x, int n)
{
  for (int i = 0; i < n; i++)
    if (!isfinite(x[i])) return 0;
  return 1;
}

static void zero(double *x, int n)
{
  if (x) memset(x, 0, (size_t)n * sizeof *x);
}

int braid_rhs(const double *u, const braid_material *m, double *f, double *jac_u, double *jac_m)
{
  int st = braid_state_check(u, m);
  if (st == BRAID_OK) {
    double p[BRAID_NMAT];
    material_to_array(m, p);
    if (jac_u || jac_m) {
      /* the generated code fills both Jacobians; scratch for the unwanted one */
      double ju_scratch[BR_NDIM * BR_NDIM], jm_scratch[BR_NDIM * BRAID_NMAT];
      double *ju = jac_u ? jac_u : ju_scratch;
      double *jm = jac_m ? jac_m : jm_scratch;
      braid_gen_rhs_jac(u, p, f, ju, jm);
      if (!all_finite(ju, BR_NDIM * BR_NDIM) || !all_finite(jm, BR_NDIM * BRAID_NMAT))
        st = BRAID_NONFINITE;
    } else {
      braid_gen_rhs(u, p, f);
    }
    if (!all_finite(f, BR_NDIM)) st = BRAID_NONFINITE;
  }
  if (st != BRAID_OK) {
    zero(f, BR_NDIM);
    zero(jac_u, BR_NDIM * BR_NDIM);
    zero(jac_m, BR_NDIM * BRAID_NMAT);
  }
  return st;
}

/* The material columns of jac_m in parameter-slot order. */
static const int material_slot[BRAID_NMAT] = {BP_DELTA, BP_B1, BP_B2, BP_C1,
                                              BP_C2,    BP_W01, BP_W02};

int braid_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
               double *f, double *dfdu, double *dfdp, void *params)
{
  (void)icp;
  (void)params;
  if (ndim != BR_NDIM) return BRAID_BAD_DIM;
  const int want_u = ijac >= 1 && dfdu != NULL;
  const int want_p = ijac >= 2 && dfdp != NULL;
  const double L = par[BP_L];
  braid_material m;
  braid_material_from_par(par, &m);
  double rhs[BR_NDIM], jm[BR_NDIM * BRAID_NMAT];
  if (want_p) zero(dfdp, BR_NDIM * BP_NPAR);
  int st = isfinite(L) ? BRAID_OK : BRAID_NONFINITE;
  if (st == BRAID_OK) st = braid_rhs(u, &m, rhs, want_u ? dfdu : NULL, want_p ? jm : NULL);
  if (st != BRAID_OK) {
    zero(f, BR_NDIM);
    if (want_u) zero(dfdu, BR_NDIM * BR_NDIM);
    return st;
  }
  for (int i = 0; i < BR_NDIM; i++) f[i] = L * rhs[i];
  if (want_u)
    for (int i = 0; i < BR_NDIM * BR_NDIM; i++) dfdu[i] *= L;
  if (want_p) {
    for (int i = 0; i < BR_NDIM; i++) dfdp[i + BR_NDIM * BP_L] = rhs[i];
    for (int k = 0; k < BRAID_NMAT; k++)
      for (int i = 0; i < BR_NDIM; i++)
        dfdp[i + BR_NDIM * material_slot[k]] = L * jm[i + BR_NDIM * k];
  }
  /* L * rhs can overflow only for absurd L; keep the no-Inf promise */
  if (!all_finite(f, BR_NDIM) || (want_u && !all_finite(dfdu, BR_NDIM * BR_NDIM))
      || (want_p && !all_finite(dfdp, BR_NDIM * BP_NPAR))) {
    zero(f, BR_NDIM);
    if (want_u) zero(dfdu, BR_NDIM * BR_NDIM);
    if (want_p) zero(dfdp, BR_NDIM * BP_NPAR);
    return BRAID_NONFINITE;
  }
  return BRAID_OK;
}

/* The generated auxiliary vector behind the guards; zero on failure. */
static int aux_raw(const double *u, const braid_material *m, double a[BRAID_GEN_NAUX])
{
  zero(a, BRAID_GEN_NAUX);
  int st = braid_state_check(u, m);
  if (st != BRAID_OK) return st;
  double p[BRAID_NMAT];
  material_to_array(m, p);
  braid_gen_aux(u, p, a);
  if (!all_finite(a, BRAID_GEN_NAUX)) {
    zero(a, BRAID_GEN_NAUX);
    return BRAID_NONFINITE;
  }
  return BRAID_OK;
}

int braid_aux_eval(const double *u, const braid_material *m, braid_aux *aux)
{
  double a[BRAID_GEN_NAUX];
  int st = aux_raw(u, m, a);
  aux->w1 = a[0];
  aux->sigmap = a[1];
  aux->etap = a[2];
  aux->xi1p = a[3];
  aux->xi2p = a[4];
  aux->h = a[5];
  return st;
}

int braid_w3_denominator(const double *u, const braid_material *m, double *den)
{
  double a[BRAID_GEN_NAUX];
  int st = aux_raw(u, m, a);
  *den = a[6];
  return st;
}

int braid_g_partials(double eta, double etap, double w2, double w3, double xi1p, double xi2p,
                     double h, const braid_material *m, braid_gpartials *out)
{
  const double x[7] = {eta, etap, w2, w3, xi1p, xi2p, h};
  double r[BRAID_GEN_NGP] = {0};
  int st = braid_material_check(m);
  if (st == BRAID_OK && !all_finite(x, 7)) st = BRAID_NONFINITE;
  if (st == BRAID_OK) st = domain_check(eta, w3, m->Delta);
  if (st == BRAID_OK) {
    double p[BRAID_NMAT];
    material_to_array(m, p);
    braid_gen_gpartials(x, p, r);
    if (!all_finite(r, BRAID_GEN_NGP)) {
      st = BRAID_NONFINITE;
      zero(r, BRAID_GEN_NGP);
    }
  }
  out->g = r[0];
  out->dw2 = r[1];
  out->dw3 = r[2];
  out->deta = r[3];
  out->detap = r[4];
  out->dxi1p = r[5];
  out->dxi2p = r[6];
  return st;
}
