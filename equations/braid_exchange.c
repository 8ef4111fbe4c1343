/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Strand exchange of a braid state (braid_exchange.h; doc/links.md). */
#include <math.h>

#include "braid_exchange.h"

static const double sqrt_half = 0.70710678118654752440;

/* Hamilton product c = a b (q0 the scalar part; R(a b) = R(a) R(b) for the
 * paper's quaternion-to-frame map, Sect. 12.2.3). */
static void qmul(const double *a, const double *b, double *c)
{
  c[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  c[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  c[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  c[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* v -> R(q) v */
static void qrot(const double *q, const double *v, double *out)
{
  const double p[4] = {0.0, v[0], v[1], v[2]}, qc[4] = {q[0], -q[1], -q[2], -q[3]};
  double t[4], r[4];
  qmul(q, p, t);
  qmul(t, qc, r);
  out[0] = r[1]; out[1] = r[2]; out[2] = r[3];
}

/* q(R2(eta)) q(D): R2(eta) = exp(eta e2^), D = diag(1,-1,-1) = exp(pi e1^) */
static void q_tail(double eta, double *qc)
{
  const double a[4] = {cos(0.5 * eta), 0.0, sin(0.5 * eta), 0.0}, d[4] = {0.0, 1.0, 0.0, 0.0};
  qmul(a, d, qc);
}

int braid_exchange_frame_at(const double *u0, const braid_material *m, braid_exchange_frame *g)
{
  braid_aux aux;
  const int st = braid_aux_eval(u0, m, &aux);
  if (st != 0) return st;
  double qc[4], qn[4];
  q_tail(u0[BR_ETA], qc);
  qmul(u0 + BR_Q0, qc, qn); /* frame of strand 2 at the start, before G */
  /* G = E0 Rn(0)^T with E0 the start frame of the conditions */
  const double q_start[4] = {0.0, -sqrt_half, -sqrt_half, 0.0};
  const double qn_conj[4] = {qn[0], -qn[1], -qn[2], -qn[3]};
  const double nn = qn[0] * qn[0] + qn[1] * qn[1] + qn[2] * qn[2] + qn[3] * qn[3];
  double qg[4];
  qmul(q_start, qn_conj, qg);
  for (int i = 0; i < 4; i++) g->qg[i] = qg[i] / nn;
  const double e2[3] = {0.0, 1.0, 0.0};
  double d1[3];
  qrot(u0 + BR_Q0, e2, d1);
  for (int i = 0; i < 3; i++) g->p0[i] = u0[BR_X1 + i] + m->Delta * d1[i];
  return 0;
}

int braid_exchange_state(const double *u, double s, const braid_material *m,
                         const braid_exchange_frame *g, double *w)
{
  braid_aux aux;
  const int st = braid_aux_eval(u, m, &aux);
  if (st != 0) return st;
  const double eta = u[BR_ETA], c = cos(eta), sn = sin(eta), sp = aux.sigmap;
  const double *F = u + BR_F1, *M = u + BR_M1;
  /* moment about r2 = r1 + Delta d1: M - Delta d1 x F, d1 x F = (F3, 0, -F1) */
  const double Mr2[3] = {M[0] - m->Delta * F[2], M[1], M[2] + m->Delta * F[0]};
  /* D R2(eta)^T v = (c v1 - s v3, -v2, -(s v1 + c v3)) */
  w[BR_F1] = c * F[0] - sn * F[2];
  w[BR_F2] = -F[1];
  w[BR_F3] = -(sn * F[0] + c * F[2]);
  w[BR_M1] = c * Mr2[0] - sn * Mr2[2];
  w[BR_M2] = -Mr2[1];
  w[BR_M3] = -(sn * Mr2[0] + c * Mr2[2]);
  w[BR_ETA] = eta;
  /* Omega = R2^T omega + eta' e2; omega_n = D Omega / sigma' */
  w[BR_W2] = -(u[BR_W2] + aux.etap) / sp;
  w[BR_W3] = -(sn * aux.w1 + c * u[BR_W3]) / sp;
  w[BR_XI1] = -u[BR_XI2];
  w[BR_T1] = -u[BR_T2];
  w[BR_XI2] = -u[BR_XI1];
  w[BR_T2] = -u[BR_T1];
  double qc[4], qn[4], qq[4];
  q_tail(eta, qc);
  qmul(u + BR_Q0, qc, qn);
  qmul(g->qg, qn, qq);
  for (int i = 0; i < 4; i++) w[BR_Q0 + i] = qq[i];
  const double e2[3] = {0.0, 1.0, 0.0};
  double d1[3], r[3], rn[3];
  qrot(u + BR_Q0, e2, d1);
  for (int i = 0; i < 3; i++) r[i] = u[BR_X1 + i] + m->Delta * d1[i] - g->p0[i];
  qrot(g->qg, r, rn);
  for (int i = 0; i < 3; i++) w[BR_X1 + i] = rn[i];
  w[BR_SIGMA] = s;
  return 0;
}
