/* SPDX-License-Identifier: GPL-3.0-or-later */
/* State and parameter layout of the standard elastic 2-braid (paper Sect. 12.2-12.3).
 * The independent variable is t = s/L in [0,1]; every ODE right-hand side is
 * d/dt = L d/ds.  Indices are 0-based (u[BR_F1] is AUTO's U(1)). */
#ifndef CABLE_BRAID_STATE_H
#define CABLE_BRAID_STATE_H

enum braid_state {
  BR_F1 = 0, BR_F2, BR_F3,        /* braid force in the first braid frame */
  BR_M1, BR_M2, BR_M3,            /* braid moment in the first braid frame */
  BR_ETA,                         /* braid angle eta */
  BR_W2, BR_W3,                   /* braid strains omega_2, omega_3 */
  BR_XI1, BR_T1,                  /* strand 1 twist angle and torque */
  BR_XI2, BR_T2,                  /* strand 2 twist angle and torque */
  BR_Q0, BR_Q1, BR_Q2, BR_Q3,     /* Euler parameters of {t1, d1, u1} */
  BR_X1, BR_Y1, BR_Z1,            /* centreline r1 */
  BR_SIGMA,                       /* arclength of strand 2 */
  BR_NDIM                         /* = 21 */
};

/* Parameter slots (0-based; AUTO's PAR(k+1)).  Names are the parnames. */
enum braid_par {
  BP_T = 0,       /* "T"     strand torque t10 (T1(0) = T, T2(0) = -T) */
  BP_L,           /* "L"     length of strand 1 */
  BP_L2,          /* "L2"    length of strand 2 */
  BP_LTOT,        /* "Ltot"  L + L2 (knots) */
  BP_DELTA,       /* "Delta" strand distance (rod diameter) */
  BP_PHI,         /* "Phi"   link closure angle */
  BP_W2FIX,       /* "w2fix" value of omega_2(0) held by the phase/link condition */
  BP_B1, BP_B2,   /* "B1","B2" bending stiffnesses */
  BP_C1, BP_C2,   /* "C1","C2" torsional stiffnesses */
  BP_W01, BP_W02, /* "w01","w02" intrinsic twist rates */
  BP_EPS21,       /* "eps21" unfolding parameter of condition (12.3.21) (must be ~0) */
  BP_EPS13,       /* "eps13" unfolding parameter of (12.3.13) in the S0-symmetric knot */
  /* derived quantities (PVLS), written for converged solutions */
  BP_F,           /* "F"     |F| */
  BP_FM,          /* "FM"    F.M */
  BP_H,           /* "h"     multiplier h (constant along the braid) */
  BP_QN,          /* "qnorm" |q|^2 - 1 at s = L */
  BP_HAM,         /* "Ham"   Hamiltonian */
  BP_PMIN,        /* "pmin"  minimum contact pressure */
  BP_DMIN,        /* "dmin"  minimum distance of non-adjacent axis parts / Delta */
  BP_LK, BP_TW, BP_WR, /* "Lk","Tw","Wr" of the contact-curve ribbon */
  BP_ERR,         /* "err"   discretisation-error estimate */
  BP_WRERR,       /* "Wrerr" error estimate of Wr (and so of Lk) */
  BP_T1END,       /* "T1"    strand torque T1 at s = L (a first integral: = T) */
  BP_T2END,       /* "T2"    strand torque T2 at s = L (a first integral: = -T) */
  BP_DRIFT,       /* "drift" max relative spread of |F|^2, F.M, h, Hamiltonian over the mesh points */
  BP_NPAR         /* number of slots used */
};

#endif
