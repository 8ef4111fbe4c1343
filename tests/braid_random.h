/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Random numbers, braid states and boundary points for the tests (one
 * helper, header-only).  Two generators: test_rng, a xorshift64* stream a
 * test seeds itself (its numbers are the same on every machine), and GSL's
 * gsl_rng where a test already holds one. */
#ifndef CABLE_TEST_BRAID_RANDOM_H
#define CABLE_TEST_BRAID_RANDOM_H

#include <math.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "braid_model.h"
#include "braid_state.h"

typedef struct {
  uint64_t s;   /* the state; any non-zero seed */
} test_rng;

/* Uniform in [a, b) (53 random bits). */
static inline double test_rng_uniform(test_rng *r, double a, double b)
{
  r->s ^= r->s >> 12;
  r->s ^= r->s << 25;
  r->s ^= r->s >> 27;
  const uint64_t x = r->s * 2685821657736338717u;
  return a + (b - a) * (double)(x >> 11) * (1.0 / 9007199254740992.0);
}

/* A random point of the boundary conditions: u(0), u(1) in [-1.5, 1.5]^ndim,
 * every parameter in [0.5, 2], T, Delta, Phi, w2fix and eps13 in their own
 * ranges.  knot: also |eta| < 1.2 at both ends (cos eta > 0.36, the knot
 * conditions' domain) and eps21. */
static inline void braid_random_bc_point(test_rng *r, int knot, double *u0, double *u1, double *par)
{
  for (int i = 0; i < BR_NDIM; i++) {
    u0[i] = test_rng_uniform(r, -1.5, 1.5);
    u1[i] = test_rng_uniform(r, -1.5, 1.5);
  }
  if (knot) {
    u0[BR_ETA] = test_rng_uniform(r, -1.2, 1.2);
    u1[BR_ETA] = test_rng_uniform(r, -1.2, 1.2);
  }
  for (int k = 0; k < BP_NPAR; k++) par[k] = test_rng_uniform(r, 0.5, 2.0);
  par[BP_T] = test_rng_uniform(r, -3, 3);
  par[BP_DELTA] = test_rng_uniform(r, 0.01, 0.3);
  par[BP_PHI] = test_rng_uniform(r, -8, 8);
  par[BP_W2FIX] = test_rng_uniform(r, -1, 1);
  if (knot) par[BP_EPS21] = test_rng_uniform(r, -0.1, 0.1);
  par[BP_EPS13] = test_rng_uniform(r, -0.1, 0.1);
}

static inline double braid_random_uniform(gsl_rng *r, double a, double b)
{
  return a + (b - a) * gsl_rng_uniform(r);
}

/* The half-widths of a random state's components (see braid_random_state). */
typedef struct {
  double force, moment, eta, w2, w3;
  int position;   /* 1: r1 in [-1, 1]^3 and sigma in [0, 1]; 0: both 0 */
} braid_random_ranges;

/* A non-singular state with the magnitudes of the paper's braids scaled to
 * L ~ 1: Delta 0.02-0.1, B 0.5-2, C 0.4-1.5, |w0| <= 1, forces, moments,
 * eta, omega2, omega3 within the given half-widths, xi in [-3, 3], T in
 * [-2, 2], a random unit quaternion. */
static inline void braid_random_state(gsl_rng *r, const braid_random_ranges *g, double *u,
                                      braid_material *m)
{
  m->Delta = braid_random_uniform(r, 0.02, 0.1);
  m->B1 = braid_random_uniform(r, 0.5, 2.0);
  m->B2 = braid_random_uniform(r, 0.5, 2.0);
  m->C1 = braid_random_uniform(r, 0.4, 1.5);
  m->C2 = braid_random_uniform(r, 0.4, 1.5);
  m->w01 = braid_random_uniform(r, -1.0, 1.0);
  m->w02 = braid_random_uniform(r, -1.0, 1.0);
  for (int i = BR_F1; i <= BR_F3; i++) u[i] = braid_random_uniform(r, -g->force, g->force);
  for (int i = BR_M1; i <= BR_M3; i++) u[i] = braid_random_uniform(r, -g->moment, g->moment);
  u[BR_ETA] = braid_random_uniform(r, -g->eta, g->eta);
  u[BR_W2] = braid_random_uniform(r, -g->w2, g->w2);
  u[BR_W3] = braid_random_uniform(r, -g->w3, g->w3);
  u[BR_XI1] = braid_random_uniform(r, -3.0, 3.0);
  u[BR_T1] = braid_random_uniform(r, -2.0, 2.0);
  u[BR_XI2] = braid_random_uniform(r, -3.0, 3.0);
  u[BR_T2] = braid_random_uniform(r, -2.0, 2.0);
  double qn = 0.0;
  for (int i = BR_Q0; i <= BR_Q3; i++) {
    u[i] = braid_random_uniform(r, -1.0, 1.0);
    qn += u[i] * u[i];
  }
  for (int i = BR_Q0; i <= BR_Q3; i++) u[i] /= sqrt(qn);
  for (int i = BR_X1; i <= BR_Z1; i++) u[i] = g->position ? braid_random_uniform(r, -1.0, 1.0) : 0.0;
  u[BR_SIGMA] = g->position ? braid_random_uniform(r, 0.0, 1.0) : 0.0;
}

#endif
