/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The braid problem templates, their PVLS, and instances with a start. */
#include <math.h>
#include <string.h>

#include "braid_bc.h"
#include "braid_integrals.h"
#include "braid_model.h"
#include "braid_pressure.h"
#include "braid_prepare.h"
#include "braid_problems.h"
#include "braid_second_variation.h"
#include "cable/cable_analysis.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"
#include "ribbon.h"
#include "ribbon_track.h"
#include "tube_distance.h"

static const char *const braid_parnames[BP_NPAR] = {
  "T", "L", "L2", "Ltot", "Delta", "Phi", "w2fix", "B1", "B2", "C1", "C2", "w01", "w02",
  "eps21", "eps13", "F", "FM", "h", "qnorm", "Ham", "pmin", "dmin", "Lk", "Tw", "Wr", "err",
  "Wrerr", "T1", "T2", "drift"};

static const char *const braid_unames[BR_NDIM] = {
  "F1", "F2", "F3", "M1", "M2", "M3", "eta", "w2", "w3", "xi1", "T1",
  "xi2", "T2", "q0", "q1", "q2", "q3", "x1", "y1", "z1", "sigma"};

/* 1 when the run prints parameter slot k (it is in ICP), or when no run is
 * asking (sol->pvls_icp NULL: a test or a post-processing call wants all). */
static int requested(const cable_solution *sol, int k)
{
  if (sol->pvls_icp == NULL) return 1;
  for (int q = 0; q < sol->pvls_nicp; q++)
    if (sol->pvls_icp[q] == k) return 1;
  return 0;
}

static int any_requested(const cable_solution *sol, int k0, int k1)
{
  for (int k = k0; k <= k1; k++)
    if (requested(sol, k)) return 1;
  return 0;
}

int braid_pvls(const cable_solution *sol, double *par, void *params)
{
  /* a prepared run's params carry the Lk tracker (NULL for the bare templates) */
  braid_lk_track *track = params ? ((const braid_start_params *)params)->lk_track : NULL;
  if (sol == NULL || sol->ndim != BR_NDIM || sol->ntst < 1 || sol->ncol < 1 || sol->npar < BP_NPAR)
    return -1;
  braid_material m;
  braid_material_from_par(par, &m);
  braid_first_integrals fi;
  const int st = braid_first_integrals_eval(sol->u, &m, &fi);
  if (st != 0) return st;
  const double *u1 = sol->u + (size_t)(cable_solution_npts(sol) - 1) * BR_NDIM;
  par[BP_F] = sqrt(fi.F2);
  par[BP_FM] = fi.FM;
  par[BP_H] = fi.h;
  par[BP_HAM] = fi.ham;
  par[BP_QN] = u1[BR_Q0] * u1[BR_Q0] + u1[BR_Q1] * u1[BR_Q1] + u1[BR_Q2] * u1[BR_Q2] +
               u1[BR_Q3] * u1[BR_Q3] - 1.0;
  /* T1' = T2' = 0 (D8): with T1(0) = T, T2(0) = -T imposed by the
     conditions, the columns at s = L show how well the torques are kept */
  par[BP_T1END] = u1[BR_T1];
  par[BP_T2END] = u1[BR_T2];
  if (sol->err_est >= 0) par[BP_ERR] = sol->err_est;
  /* the spread of the first integrals over the mesh points (cheap: no
     geometry; negative when a mesh point leaves the model's domain); the
     run log reports its worst value per branch */
  par[BP_DRIFT] = cable_braid_first_integral_drift(sol);
  /* The geometric columns cost a pressure sweep (pmin), a tube-distance
   * search (dmin) or the writhe double integral (Lk, Tw, Wr): only when the
   * run prints them.  A quantity that cannot be computed (e.g. Lk of a braid
   * whose axis does not close) is written as 0 and reported by the return
   * value; output never gets NaN. */
  int rc = 0;
  if (requested(sol, BP_PMIN)) {
    double pmin;
    int e = braid_contact_pressure_min(sol, &m, &pmin);
    par[BP_PMIN] = e == 0 ? pmin : 0.0;
    if (e != 0) rc = 1;
  }
  if (requested(sol, BP_DMIN)) {
    double dmin = 0.0;
    int e = braid_tube_dmin_solution(sol, &dmin);
    par[BP_DMIN] = e == 0 && isfinite(dmin) ? dmin : 0.0;
    if (par[BP_DMIN] == 0.0) rc = 1;
  }
  if ((any_requested(sol, BP_LK, BP_WR) || requested(sol, BP_WRERR)) && track) {
    /* along the branch: the update from the previous point (ribbon_track.h) */
    braid_lk_value v;
    int e = braid_lk_track_eval(track, sol, &v);
    par[BP_LK] = e == 0 ? v.lk : 0.0;
    par[BP_TW] = e == 0 ? v.tw : 0.0;
    par[BP_WR] = e == 0 ? v.wr : 0.0;
    par[BP_WRERR] = e == 0 ? v.wr_err : 0.0;
    if (e != 0) rc = 1;
  } else if (any_requested(sol, BP_LK, BP_WR) || requested(sol, BP_WRERR)) {
    braid_ribbon rb;
    int e = braid_ribbon_compute(sol, 0, &rb);
    par[BP_LK] = e == 0 ? rb.lk : 0.0;
    par[BP_TW] = e == 0 ? rb.tw : 0.0;
    par[BP_WR] = e == 0 ? rb.wr : 0.0;
    par[BP_WRERR] = e == 0 ? rb.wr_err : 0.0;
    if (e != 0) rc = 1;
  }
  return rc;
}

/* The variational structure (doc/stability.md S7): the Ritz matrices of the
 * second variation in the strain variables. */
static int link_ritz(const cable_solution *sol, int refine, int degree, int *n, int *nc, double **K, double **M,
                     double **G, void *params)
{
  (void)params;
  return braid_ritz(sol, BSV_LINK, refine, degree < BSV_DEGREE_MAX ? degree : BSV_DEGREE_MAX, n, nc, K, M, G, NULL);
}

static int knot_ritz(const cable_solution *sol, int refine, int degree, int *n, int *nc, double **K, double **M,
                     double **G, void *params)
{
  (void)params;
  return braid_ritz(sol, BSV_KNOT, refine, degree < BSV_DEGREE_MAX ? degree : BSV_DEGREE_MAX, n, nc, K, M, G, NULL);
}

/* braid_knot_sym: its solutions (the mode branches) carry the family that
 * changes F2(0), removed by the row delta F2(0) = 0 (doc/stability.md S7.3) */
static int knot_sym_ritz(const cable_solution *sol, int refine, int degree, int *n, int *nc, double **K, double **M,
                         double **G, void *params)
{
  (void)params;
  return braid_ritz(sol, BSV_KNOT_SYM, refine, degree < BSV_DEGREE_MAX ? degree : BSV_DEGREE_MAX, n, nc, K, M, G, NULL);
}

static const cable_variational link_var = {.nvar = BSV_NFIELD, .ritz = link_ritz};
static const cable_variational knot_var = {.nvar = BSV_NFIELD, .ritz = knot_ritz};
static const cable_variational knot_sym_var = {.nvar = BSV_NFIELD, .ritz = knot_sym_ritz};

/* The S0 symmetry (doc/braid-boundary-conditions.md, doc/links.md): F2(0) is
 * odd under it, and braid_knot_sym / braid_link_sym impose F2(0) = 0 with the
 * unfolding parameter eps13 on the closure condition x1(L) (BK_XL, BL_XL).
 * Declared on the full problems, it lets the engine switch at their double
 * branch points into the S0-symmetric branch (the restriction is exactly the
 * symmetric formulation).  The multiplicity, TORUS (the rotations of the
 * torus knot or link carry a symmetric branch into TORUS copies), is set by
 * the prepared instance (braid_prepare.c); 0 here: unknown. */
const cable_symmetry braid_knot_s0 = {.name = "S0", .act = NULL, .odd_comp = BR_F2, .odd_at = 0,
                                      .unfold_bc = BK_XL, .unfold_par = BP_EPS13, .multiplicity = 0};
const cable_symmetry braid_link_s0 = {.name = "S0", .act = NULL, .odd_comp = BR_F2, .odd_at = 0,
                                      .unfold_bc = BL_XL, .unfold_par = BP_EPS13, .multiplicity = 0};

#define BRAID_PROBLEM_COMMON                                                           \
  .abi_version = CABLE_PROBLEM_ABI, .struct_size = sizeof(cable_problem), .ndim = BR_NDIM, \
  .nint = 0, .npar = BP_NPAR, .parnames = braid_parnames, .unames = braid_unames,       \
  .func = braid_func, .icnd = NULL, .stpnt = braid_start_stpnt, .pvls = braid_pvls,     \
  .func_has_jac = 1, .bcnd_has_jac = 1, .icnd_has_jac = 0, .params = NULL,             \
  .keys = braid_keys, .nkeys = BRAID_NKEYS, .prepare = braid_prepare, .release = braid_release, \
  .concurrent = 1

static const cable_problem knot_template = {
  BRAID_PROBLEM_COMMON,
  .name = "braid_knot",
  .description = "closed 2-braid forming a knot (12.3.1-23 + phase omega2(0) = w2fix; "
                 "free T, L, L2, eps21)",
  .nbc = BK_NBC,
  .bcnd = braid_knot_bcnd,
  .variational = &knot_var,
  .symmetries = &braid_knot_s0, .nsym = 1,
};

static const cable_problem knot_sym_template = {
  BRAID_PROBLEM_COMMON,
  .name = "braid_knot_sym",
  .description = "S0-symmetric knot: braid_knot + F2(0) = 0 (free T, L, L2, eps21, eps13)",
  .nbc = BK_SYM_NBC,
  .bcnd = braid_knot_sym_bcnd,
  .variational = &knot_sym_var,
};

static const cable_problem link_template = {
  BRAID_PROBLEM_COMMON,
  .name = "braid_link",
  .description = "closed 2-braid forming a two-component link (12.3.24-44; free T, Delta or Phi)",
  .nbc = BL_NBC,
  .bcnd = braid_link_bcnd,
  .variational = &link_var,
  .symmetries = &braid_link_s0, .nsym = 1,
};

static const cable_problem link_sym_template = {
  BRAID_PROBLEM_COMMON,
  .name = "braid_link_sym",
  .description = "S0-symmetric link: braid_link + F2(0) = 0, eps13 on (12.3.36) (free T, eps13)",
  .nbc = BL_SYM_NBC,
  .bcnd = braid_link_sym_bcnd,
  .variational = &link_var,
};

const cable_problem *braid_knot_problem(void) { return &knot_template; }
const cable_problem *braid_knot_sym_problem(void) { return &knot_sym_template; }
const cable_problem *braid_link_problem(void) { return &link_template; }

const cable_problem *braid_problem_find(const char *name)
{
  const cable_problem *const all[] = {&knot_template, &knot_sym_template, &link_template,
                                     &link_sym_template};
  if (name == NULL) return NULL;
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
    if (strcmp(all[i]->name, name) == 0) return all[i];
  return NULL;
}

int braid_problem_instance(const char *name, const braid_start_params *sp, cable_problem *out)
{
  const cable_problem *tp = braid_problem_find(name);
  if (tp == NULL) return CABLE_ERR_NOTFOUND;
  if (out == NULL || (sp != NULL && !sp->ready)) return CABLE_ERR_INPUT;
  *out = *tp;
  /* The callbacks only read *sp; params is untyped in the interface. */
  out->params = (void *)sp;
  return CABLE_SUCCESS;
}
