/* Derived quantities of one stored braid solution, computed only when a
 * scene or `cable analyze` asks (they cost far more than a continuation step):
 * linking, twist and writhe of the contact-curve ribbon, the knot type of the
 * braid axis, contact pressures, tube overlap, first-integral drift and the
 * closure of the material frames. */
#ifndef CABLE_BRAID_ANALYSIS_H
#define CABLE_BRAID_ANALYSIS_H

#include "braid_geometry.h"
#include "cable_solution.h"
#include "tube_distance.h"

typedef struct braid_analysis {
  braid_topology topo;          /* Lk, Tw, Wr, axis knot type, Lk inside the companion's tube */
  tube_distance_result tube;    /* dmin (strand tubes, / Delta), axis closest approach */
  double pmin1, pmax1;          /* contact force on strand 1 per unit length of strand 1 */
  double pmin2, pmax2;          /* on strand 2 per unit length of strand 2 */
  int psign_changes;            /* sign changes of p1 along s (node values) */
  double s_psign[8];            /* first few arclengths s where p1 changes sign */
  double drift;                 /* max relative drift of |F|^2, F.M, h, Hamiltonian over the mesh points */
  double closure;               /* knot: xi1(0) + xi2(L) mod 2 pi; link: xi1(L) - xi1(0) mod 2 pi */
  double closure2;              /* link: xi2(L) - xi2(0) mod 2 pi; knot: unused (0) */
} braid_analysis;

/* Max relative spread of the first integrals |F|^2, F.M, h and the
 * Hamiltonian over the solution's mesh points (cheap: no geometry); negative
 * when the solution is not a braid solution. */
double braid_first_integral_drift(const cable_solution *sol);

/* 0, or a cable_status (< 0) when the solution is not a closed braid. */
int braid_analysis_compute(const cable_solution *sol, braid_analysis *out);

#endif
