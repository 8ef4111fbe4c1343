/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Starting solutions (AUTO's STPNT) for the closed standard 2-braid, and a
 * check of how well a guess satisfies the ODEs and the boundary conditions.
 * The constructions are explained in doc/braid-boundary-conditions.md.
 *
 *  BRAID_START_RINGS   two concentric coplanar rings: strand 1 of radius
 *                      R = L/(2 pi), strand 2 inside it at radius R - Delta,
 *                      eta = 0, omega = (0, 0, 1/R).  An exact solution of the
 *                      ODEs and of the link conditions at Phi = 0.
 *  BRAID_START_TORUS   an exact equidistant braid around a circular contact
 *                      curve with the chord director d1 turning uniformly by
 *                      p*pi about it: p odd gives the (p,2) torus knot (strand
 *                      1 of length Ltot/2 joined to strand 2), p even >= 2 the
 *                      (p,2) torus link (two closed strands of length L).  The
 *                      forces and moments are fitted by least squares.
 *
 * Usage:
 *   braid_start_params sp;
 *   braid_start_params_init(&sp, BRAID_START_TORUS, 7, +1, 0.0051364907419, 1.98889, 0.0);
 *   if (braid_start_prepare(&sp) != 0) ...            (computes the guess)
 *   braid_problem_instance("braid_knot", &sp, &pb);   (pb.params = &sp)
 * The problem's stpnt (braid_start_stpnt) then only reads *sp, so one
 * prepared object may serve several problems and threads. */
#ifndef CABLE_BRAID_START_H
#define CABLE_BRAID_START_H

#include "braid_state.h"
#include "cable/cable_problem.h"

typedef enum { BRAID_START_RINGS = 0, BRAID_START_TORUS = 1 } braid_start_kind;

/* Number of samples per period of the braid rotation angle psi used for the
 * Fourier representation of the torus geometry (see braid_start_torus.c). */
#define BRAID_START_NFOURIER 64
/* Functions of psi kept as Fourier series. */
enum { BRAID_FS_V1 = 0, BRAID_FS_V2, BRAID_FS_XI1, BRAID_FS_XI2, BRAID_FS_DETAP, BRAID_FS_N };

typedef struct braid_start_params {
  /* ---- input (braid_start_params_init sets every field; change before prepare) */
  braid_start_kind kind;
  int p;            /* torus: (p,2); odd p: knot, even p >= 2: link.  Ignored for rings */
  int hand;         /* torus: +1 right-handed (Lk > 0), -1 left-handed */
  double delta;     /* strand distance Delta */
  double length;    /* knot: Ltot (= L + L2); link and rings: L (length of strand 1) */
  double torque;    /* T: T1 = T, T2 = -T */
  double b1, b2, c1, c2, w01, w02; /* material (defaults B = 1, C = 1/1.3, w0 = 0) */
  double ring_dm3;  /* rings: M3 - (B1/R + B2/(R - Delta)), the free constant of
                       the exact ring family (contact load); default 0 = no load.
                       dm3 = 0 is a degenerate point of braid_link; to continue
                       from the rings use dm3 != 0 with Delta free (doc, 4.1) */
  /* ---- prepared (braid_start_prepare); read-only afterwards */
  int ready;
  double l, l2;     /* strand lengths of the guess */
  double rc;        /* torus: radius of the contact circle; rings: R */
  double nu;        /* torus: hand * p / 2, d psi / d phi */
  double fs_a[BRAID_FS_N][BRAID_START_NFOURIER / 2]; /* cosine coefficients */
  double fs_b[BRAID_FS_N][BRAID_START_NFOURIER / 2]; /* sine coefficients */
  double qp[4];     /* rotation taking the construction frame to the BC frame */
  double r0[3];     /* construction-frame position of r1(0) */
  double fin[3];    /* fitted force, construction frame (torus) */
  double m0[3];     /* fitted moment about r1(0), construction frame (torus) */
  double h;         /* fitted multiplier h (torus); exact h is not stored for rings */
  double fit_max;   /* max |residual| of the constitutive relations after the fit */
  double fit_rms;   /* rms of the same */
  double fit_rcond; /* min |R_ii| / max |R_ii| of the scaled QR factor (rank check) */
  double par[BP_NPAR]; /* parameter values the stpnt sets (slots up to BP_EPS13) */
  /* ---- run state (not start data): PVLS's Lk along the branch
     (equations/ribbon_track.h), owned by the prepared instance; NULL (init):
     the full writhe at every point */
  struct braid_lk_track *lk_track;
} braid_start_params;

/* Fill every input field (material defaults B1 = B2 = 1, C1 = C2 = 1/1.3,
 * w01 = w02 = 0, ring_dm3 = 0); ready = 0. */
void braid_start_params_init(braid_start_params *sp, braid_start_kind kind, int p, int hand,
                             double delta, double length, double torque);

/* Build the guess.  0 ok; CABLE_ERR_INPUT for inconsistent input (bad p or
 * hand, Delta >= contact-circle radius, ...); CABLE_ERR_NEWTON when a length
 * or the arclength cannot be solved for; CABLE_ERR_LINSOLVE when the force fit
 * is rank deficient; CABLE_ERR_UNSUPPORTED when the braid is so thick that
 * BRAID_START_NFOURIER samples do not resolve it; CABLE_ERR_ALLOC. */
int braid_start_prepare(braid_start_params *sp);

/* cable_stpnt_fn: u(t) and the parameters (T, L, L2, Ltot, Delta, Phi, w2fix,
 * material, eps21 = eps13 = 0).  params: a prepared braid_start_params.
 * Returns -1 (fatal) when params is NULL or not prepared or ndim != 21. */
int braid_start_stpnt(int ndim, double t, double *u, double *par, void *params);

/* Torus guesses: the three constitutive residuals the force fit minimises, at
 * t in [0,1] (moment units):
 *   res[0] = M2 - dg/domega2,
 *   res[1] = M1 - k (dg/deta - d/ds dg/deta'),  k = Delta cos^2 eta/(Delta omega3 - 1),
 *   res[2] = M3 + tan(eta) M1 - dg/domega3,
 * with the guess's geometric eta' and the fitted h.  On a solution all vanish;
 * the ODE for eta then gives eta'(model) - eta'(guess) = res[0]/(B2 c),
 * c = cos(eta)/(1 - Delta omega3).  0 ok; CABLE_ERR_INPUT when sp is not a
 * prepared torus guess. */
int braid_start_fit_residual(const braid_start_params *sp, double t, double *res);

/* How well a problem's STPNT guess satisfies its ODEs and BCs. */
typedef struct {
  double ode_max;               /* max over t, i of |u_i'(t) - f_i(u(t))| (f = pb->func) */
  double ode_comp[BR_NDIM];     /* the same per component */
  double fd_err[BR_NDIM];       /* estimated truncation error of u_i' (|D(2dt) - D(dt)|/15) */
  double u_scale[BR_NDIM];      /* max |u_i| over the samples (for rounding bounds) */
  double bc_max;                /* max |fb| */
  double bc_row[32];            /* |fb_i| per row (nbc <= 32) */
  double fd_step;               /* dt, the step of the difference formula */
} braid_start_quality;

/* Sample npts >= 2 points evenly in [4 dt, 1 - 4 dt], differentiate u(t)
 * with the five-point central formula (steps dt and 2 dt, dt = 2e-4, see
 * braid_start_quality.c), compare with pb->func; evaluate pb->bcnd at the
 * guess's ends.  The problem must have ndim = 21 and nbc <= 32.  Returns 0;
 * CABLE_ERR_INPUT for bad arguments; CABLE_ERR_ALLOC; CABLE_ERR_RECOVERABLE or
 * CABLE_ERR_CALLBACK when a callback returned > 0 or < 0. */
int braid_start_quality_eval(const cable_problem *pb, int npts, braid_start_quality *q);

#endif
