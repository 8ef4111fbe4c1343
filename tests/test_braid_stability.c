/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The Morse index of the braid link (doc/stability.md S7):
 *  - at a buckled (6,2) link (tests/data/s.link62_buckled) the Ritz matrices
 *    of the second variation in the strain variables: the first variation on
 *    the Ritz space vanishes with the multipliers F and -h of the solution
 *    (the check of tests/test_braid_first_variation.c, on another basis);
 *    the Hessian from central differences of the adjoint first variation is
 *    symmetric (it would not be with a wrong gradient); the shift along the
 *    closed link is a zero mode: without its orthogonality row one more
 *    eigenvalue lies near zero; the index is the same at degrees 1-3;
 *  - along the flat (6,2) link's branch (runs/link62/c.link62, coarser mesh)
 *    with STAB=1 up to T = 25: stable from T = 0 up to the first branch
 *    point, and the index changes only at the located branch points, by 2 at
 *    a double one and by 1 at a simple one (the determinant's sign tells
 *    which).  Further up, at this mesh and step, the simple BP at T = 29.81
 *    is stepped over unlocated and the index shows it (doc/stability.md S7);
 *  - the same along the flat (7,2) knot's right arm (runs/knot72/c.knot72 at
 *    NTST 20, T = 0 to 34): 0, 2, 4, 6, 8 across its four double BPs. */
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "braid_bc.h"
#include "braid_model.h"
#include "braid_problems.h"
#include "braid_second_variation.h"
#include "cable/cable_aufile.h"
#include "cable/cable_constants.h"
#include "cable/cable_cont.h"
#include "cable/cable_output.h"
#include "cable/cable_status.h"
#include "cable/cable_stability.h"
#include "harness.h"

/* The first variation on the Ritz space: the solution is a collocation
 * solution at NTST 50 and the grid's RK4/Simpson error is O(h^4); measured
 * 2.6e-5 relative at degree 2 (the local basis sees the discretisation error
 * that the smooth directions of test_braid_first_variation, 6.4e-9, do not);
 * a non-stationary action (t20 = +T there) gives 1.5e-2. */
static const double stat_tol = 1e-3;
/* the multipliers by least squares over the local basis: |F| measured to
 * 1e-5; h (whose constraint sigma(L) = L2 is weakly determined: its gradient
 * carries Delta) varies by 3e-4 between degrees 1-2 and refinements 1-4,
 * the discretisation noise of the local directions (the smooth directions of
 * test_braid_first_variation give 1e-6) */
static const double mult_tol = 1e-4, h_tol = 2e-3;
/* H from central differences (eps 1e-5) of the adjoint gradient: symmetric to
 * the O(h^4) inconsistency of the continuous adjoint with the RK4 forward
 * sweep, measured 8.8e-6 of max |H| at degree 2; a gradient with one wrong
 * sign or factor gives O(1) */
static const double asym_tol = 1e-4;

/* the spectrum of (Z^T K Z, Z^T M Z), Z the null space of the first nc rows
   of G (ld ldg): an independent solve of stability.c's (S2.1) by the SVD of G */
static int spectrum(int n, const double *K, const double *M, const double *G, int ldg, int nc, double *ev)
{
  double *A = malloc((size_t)nc * (size_t)n * sizeof *A), *s = malloc((size_t)n * sizeof *s);
  double *Vt = malloc((size_t)n * (size_t)n * sizeof *Vt), *sup = malloc((size_t)n * sizeof *sup);
  for (int i = 0; i < n; i++)
    for (int r = 0; r < nc; r++) A[(size_t)r + (size_t)nc * (size_t)i] = G[(size_t)r + (size_t)ldg * (size_t)i];
  int rc = LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'A', nc, n, A, nc, s, NULL, 1, Vt, n, sup);
  int rank = 0;
  for (int i = 0; i < nc; i++) rank += s[i] > 1e-12 * s[0];
  const int nz = n - rank;
  double *Z = malloc((size_t)n * (size_t)nz * sizeof *Z), *T = malloc((size_t)n * (size_t)nz * sizeof *T);
  double *Kz = malloc((size_t)nz * (size_t)nz * sizeof *Kz), *Mz = malloc((size_t)nz * (size_t)nz * sizeof *Mz);
  for (int j = 0; j < nz; j++)
    for (int i = 0; i < n; i++) Z[(size_t)i + (size_t)n * (size_t)j] = Vt[(size_t)(rank + j) + (size_t)n * (size_t)i];
  const double *mats[2] = {K, M};
  double *outs[2] = {Kz, Mz};
  for (int m = 0; m < 2; m++) {
    for (int j = 0; j < nz; j++)
      for (int i = 0; i < n; i++) {
        double v = 0.0;
        for (int l = 0; l < n; l++) v += mats[m][(size_t)i + (size_t)n * (size_t)l] * Z[(size_t)l + (size_t)n * (size_t)j];
        T[(size_t)i + (size_t)n * (size_t)j] = v;
      }
    for (int j = 0; j < nz; j++)
      for (int i = 0; i < nz; i++) {
        double v = 0.0;
        for (int l = 0; l < n; l++) v += Z[(size_t)l + (size_t)n * (size_t)i] * T[(size_t)l + (size_t)n * (size_t)j];
        outs[m][(size_t)i + (size_t)nz * (size_t)j] = v;
      }
  }
  if (rc == 0) rc = LAPACKE_dsygv(LAPACK_COL_MAJOR, 1, 'N', 'U', nz, Kz, nz, Mz, nz, ev);
  free(A); free(s); free(Vt); free(sup); free(Z); free(T); free(Kz); free(Mz);
  return rc == 0 ? nz : -1;
}

static void test_buckled_link(void)
{
  cable_error err;
  cable_sfile *sf = cable_sfile_read("tests/data/s.link62_buckled", &err);
  if (!test_true("link: tests/data/s.link62_buckled read", sf != NULL)) return;
  const cable_solution *sol = cable_sfile_get(sf, 0);
  int n, nc;
  double *K, *M, *G;
  braid_sv_info info;
  int st = braid_ritz(sol, 0, 1, 2, &n, &nc, &K, &M, &G, &info);
  if (!test_int("link: the Ritz matrices at degree 2", st, 0)) {
    cable_sfile_free(sf);
    return;
  }
  printf("# N = %d, %d rows, first variation %.3e, asymmetry %.3e, closure %.3e\n", n, nc, info.stat_res, info.asym,
         info.closure);
  test_le("link: the first variation vanishes on the Ritz space (dA = lambda . dc, rel. residual)", info.stat_res,
          stat_tol);
  /* lambda of the closure of r1 is F in the inertial frame: its magnitude is |F| */
  const double lf = sqrt(info.lambda[0] * info.lambda[0] + info.lambda[1] * info.lambda[1] +
                         info.lambda[2] * info.lambda[2]);
  braid_material mat;
  braid_material_from_par(sol->par, &mat);
  braid_aux aux;
  braid_aux_eval(sol->u, &mat, &aux);
  test_rel("link: |lambda| of the closure of r1 is |F|", lf, sol->par[BP_F], mult_tol);
  test_rel("link: lambda of sigma(L) = L2 is -h", info.lambda[6], -aux.h, h_tol);
  test_le("link: the Hessian by differences of the first variation is symmetric (max |H - H^T| / max |H|)",
          info.asym, asym_tol);
  test_true("link: the shift generator's row is there (the buckled link's fields vary)", info.shift_row == 1);

  /* the zero mode: without the shift row one eigenvalue more, near zero */
  double *ev1 = malloc((size_t)n * sizeof *ev1), *ev0 = malloc((size_t)n * sizeof *ev0);
  int nz1 = spectrum(n, K, M, G, nc, nc, ev1), nz0 = spectrum(n, K, M, G, nc, nc - 1, ev0);
  test_int("link: the shift row removes one degree of freedom", nz0 - nz1, 1);
  double min1 = INFINITY, min0 = INFINITY, scale = 0.0;
  int neg1 = 0, neg0 = 0;
  for (int i = 0; i < nz1; i++) {
    min1 = fmin(min1, fabs(ev1[i]));
    neg1 += ev1[i] < 0;
  }
  for (int i = 0; i < nz0; i++) {
    min0 = fmin(min0, fabs(ev0[i]));
    neg0 += ev0[i] < 0;
  }
  scale = fabs(ev1[0]);
  printf("# smallest |sigma|: %.3e with the shift row, %.3e without; sigma_1 = %.6g; index %d / %d\n", min1, min0,
         ev1[0], neg1, neg0);
  /* the zero mode is represented to the Ritz error: measured 1e-4 of |sigma_1| */
  test_le("link: without the shift row an eigenvalue near zero (|sigma| / |sigma_1|)", min0 / scale, 1e-2);
  test_true("link: with it, none that near", min1 > 10 * min0);

  /* the engine's path (stability.c on the problem's Ritz callback) agrees */
  const cable_problem *pb = braid_problem_find("braid_link");
  cable_stab_result res;
  st = cable_stability_index(pb, sol, 1, 2, &res, &err);
  test_int("link: cable_stability_index through the problem's Ritz callback", st, 0);
  test_int("link: its index is the independent solve's", res.index, neg1);
  test_rel("link: its sigma_1 is the independent solve's", res.eig[0], ev1[0], 1e-8);
  /* the index at degrees 1 and 3: the same (converged; S7's table) */
  for (int deg = 1; deg <= 3; deg += 2) {
    cable_stab_result r2;
    st = cable_stability_index(pb, sol, 1, deg, &r2, &err);
    char what[120];
    snprintf(what, sizeof what, "link: degree %d gives the same index (%d), sigma_1 %.6g", deg, r2.index, r2.eig[0]);
    test_true(what, st == 0 && r2.index == res.index && fabs(r2.eig[0] - res.eig[0]) < 1e-2 * fabs(res.eig[0]));
  }
  printf("# buckled (6,2) link at T = %.6g: index %d, sigma = %.6g %.6g %.6g %.6g\n", sol->par[BP_T], res.index,
         res.eig[0], res.eig[1], res.eig[2], res.eig[3]);
  free(ev1); free(ev0);
  free(K); free(M); free(G);
  cable_sfile_free(sf);
}

/* ---------------------------------------------------------------- the flat branch */

#define RUN_MAX 400
typedef struct {
  int n;
  int itp[RUN_MAX], stab[RUN_MAX], index[RUN_MAX], det[RUN_MAX];
  double T[RUN_MAX];
} brun;

static int brun_point(void *ctx, const cable_point *pt)
{
  brun *r = ctx;
  if (r->n >= RUN_MAX) return 0;
  r->itp[r->n] = pt->itp;
  r->stab[r->n] = pt->stab;
  r->index[r->n] = pt->stab_index;
  r->det[r->n] = pt->det_sign;
  r->T[r->n] = pt->par[BP_T];
  r->n++;
  return 0;
}

/* a STAB=1 run of a flat branch; the index must change exactly at the
   located BPs, by their multiplicity */
static void flat_branch(const char *what, const char *name, const char *cfile, const char *const *over, int nover,
                        int want_bp)
{
  const cable_problem *tpl = braid_problem_find(name), *pb = NULL;
  cable_constants c;
  cable_error err;
  char msg[200];
  int st = cable_constants_parse_file_for(cfile, tpl, &c, NULL, &err);
  snprintf(msg, sizeof msg, "%s: %s read, overrides", what, cfile);
  for (int i = 0; i < nover; i++) st |= cable_constants_parse_override(over[i], &c, NULL, tpl->parnames, tpl->npar, &err);
  if (!test_int(msg, st, 0)) return;
  st = cable_problem_prepare(tpl, &c, 1, &pb, &err);
  snprintf(msg, sizeof msg, "%s: prepared", what);
  if (!test_int(msg, st, 0)) return;
  brun *r = calloc(1, sizeof *r);
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, NULL);
  if (st == CABLE_SUCCESS) {
    cable_sink sink = {r, brun_point, NULL, NULL};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  cable_cont_free(cc);
  printf("# %s: %d points, status %d (%s)\n", what, r->n, st, cable_status_message(st));
  snprintf(msg, sizeof msg, "%s: the STAB=1 run reaches RL1", what);
  test_true(msg, st == CABLE_END_BOUNDS);
  /* the engine hands a located BP over after the point that stepped past
     it: order the points by T (monotone on these flat branches) */
  for (int i = 1; i < r->n; i++)
    for (int j = i; j > 0 && r->T[j] < r->T[j - 1]; j--) {
      int ti;
      double td;
#define SWAP(a) (ti = a[j], a[j] = a[j - 1], a[j - 1] = ti)
      SWAP(r->itp); SWAP(r->stab); SWAP(r->index); SWAP(r->det);
#undef SWAP
      td = r->T[j], r->T[j] = r->T[j - 1], r->T[j - 1] = td;
    }
  int nbp = 0, all = 1, ok = 1, first_bp = -1;
  for (int i = 0; i < r->n; i++) all &= r->stab[i] != 0;
  snprintf(msg, sizeof msg, "%s: every point has an index", what);
  test_true(msg, all);
  /* walk the branch: between two located BPs the index is constant; across
     a BP it changes by its multiplicity (the BP's own index is not used:
     an eigenvalue is zero there) */
  int prev = r->index[0], prev_bp_mult = 0;
  for (int i = 1; i < r->n; i++) {
    if (r->itp[i] % 10 == CABLE_TY_BP) {
      nbp++;
      if (first_bp < 0) first_bp = i;
      /* the multiplicity's parity from the determinant: it changes sign
         across a simple BP and keeps it across a double one */
      prev_bp_mult = i + 1 < r->n && r->det[i - 1] == r->det[i + 1] ? 2 : 1;
      printf("# BP at T = %.6f (%s), index before %d\n", r->T[i], prev_bp_mult == 2 ? "double" : "simple", prev);
      continue;
    }
    if (r->index[i] != prev) {
      int by = abs(r->index[i] - prev);
      if (prev_bp_mult == 0 || by != prev_bp_mult) {
        ok = 0;
        printf("# index %d -> %d at T = %.6f, not across a BP of that multiplicity\n", prev, r->index[i], r->T[i]);
      }
      printf("# index %d -> %d at T = %.6f\n", prev, r->index[i], r->T[i]);
      prev = r->index[i];
    } else if (prev_bp_mult) {
      ok = 0;   /* a located BP that the index does not see */
      printf("# BP before T = %.6f but the index stays %d\n", r->T[i], prev);
    }
    prev_bp_mult = 0;
  }
  snprintf(msg, sizeof msg, "%s: %d branch points located", what, want_bp);
  test_int(msg, nbp, want_bp);
  int stable = first_bp > 0;
  for (int i = 0; i < first_bp; i++) stable &= r->index[i] == 0 && r->stab[i] == 1;
  snprintf(msg, sizeof msg, "%s: stable (index 0) from T = 0 to the first branch point", what);
  test_true(msg, stable);
  snprintf(msg, sizeof msg, "%s: the index changes exactly at the located BPs, by their multiplicity", what);
  test_true(msg, ok);
  free(r);
  cable_problem_release(tpl, pb);
}

static void test_flat_branches(void)
{
  /* NTST 20: the index needs only the eigenvalues' signs away from the BPs */
  const char *link[] = {"NTST=20", "DS=2", "DSMAX=2", "RL1=25", "NMX=300", "STAB=1"};
  flat_branch("flat (6,2) link to T = 25", "braid_link", "runs/link62/c.link62", link, 6, 3);
  const char *knot[] = {"NTST=20", "STAB=1"};
  flat_branch("flat (7,2) knot, right arm", "braid_knot", "runs/knot72/c.knot72", knot, 2, 4);
}

/* ------------------------------------------------ the mode branches' family */

/* braid_knot_sym with F2(0) = Phi instead of F2(0) = 0 (Phi is unused by
   knots): continuing in Phi at fixed T pushes a solution along the family
   that changes F2(0); eps13 (the unfolding of (12.3.13)) stays zero exactly
   when the pushed states are solutions of the plain knot problem */
static int push_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                     int ijac, double *fb, double *dbc, void *params)
{
  int rc = braid_knot_sym_bcnd(ndim, par, icp, nbc, u0, u1, ijac, fb, dbc, params);
  if (rc != 0) return rc;
  fb[BK_F20] -= par[BP_PHI];
  if (ijac >= 2) dbc[BK_F20 + nbc * (2 * BR_NDIM + BP_PHI)] = -1.0;
  return 0;
}

typedef struct {
  int n;
  double phi[16], eps13[16], T[16];
} push_run;

static int push_point(void *ctx, const cable_point *pt)
{
  push_run *r = ctx;
  if (r->n < 16) {
    r->phi[r->n] = pt->par[BP_PHI];
    r->eps13[r->n] = pt->par[BP_EPS13];
    r->T[r->n] = pt->par[BP_T];
    r->n++;
  }
  return 0;
}

/* |d eps13 / d F2(0)| along the push, from a start (start == NULL: the
   flat knot of cfile's STPNT) */
static double push_slope(const char *what, const char *cfile, const cable_solution *start)
{
  const cable_problem *tpl = braid_problem_find("braid_knot_sym"), *inst = NULL;
  cable_constants c;
  cable_error err;
  const char *over[] = {"ICP=['Phi', 'L', 'L2', 'eps21', 'eps13']", "ISW=1", "NMX=5", "DS=2", "DSMAX=2", "NPR=0",
                        "RL0=-100", "RL1=100", "ISP=0", "ILP=0", "NTST=30", "NCOL=7"};
  int st = cable_constants_parse_file_for(cfile, tpl, &c, NULL, &err);
  for (size_t i = 0; i < sizeof over / sizeof *over; i++)
    st |= cable_constants_parse_override(over[i], &c, NULL, tpl->parnames, tpl->npar, &err);
  if (st == 0) st = cable_problem_prepare(tpl, &c, start == NULL, &inst, &err);
  char msg[200];
  snprintf(msg, sizeof msg, "push %s: constants and problem", what);
  if (!test_int(msg, st, 0)) return NAN;
  cable_problem pb = *inst;
  pb.bcnd = push_bcnd;
  cable_solution *s0 = start ? cable_solution_clone(start) : NULL;
  if (s0) s0->par[BP_PHI] = 0.0;
  push_run r = {0};
  cable_cont *cc = cable_cont_alloc(&pb, &c, &st);
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, s0);
  if (st == CABLE_SUCCESS) {
    cable_sink sink = {&r, push_point, NULL, NULL};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  cable_cont_free(cc);
  cable_solution_free(s0);
  cable_problem_release(tpl, inst);
  double slope = 0.0, phimax = 0.0, dT = 0.0;
  for (int i = 1; i < r.n; i++) {
    slope = fmax(slope, fabs((r.eps13[i] - r.eps13[0]) / (r.phi[i] - r.phi[0])));
    phimax = fmax(phimax, fabs(r.phi[i]));
    dT = fmax(dT, fabs(r.T[i] - r.T[0]));
  }
  printf("# push %s: %d points, status %d, F2(0) up to %.3g, |d eps13 / d F2(0)| = %.3e, T moved %.1e\n", what, r.n,
         st, phimax, slope, dT);
  snprintf(msg, sizeof msg, "push %s: the continuation in F2(0) at fixed T takes its steps", what);
  test_true(msg, r.n >= 4 && phimax > 4.0 && dT == 0.0);
  return slope;
}

/* (a) of the paper, point UZ of the mode-1 branch (runs/knot72's constants,
   NTST 30, NCOL 7): the index with the row delta F2(0) = 0 */
static void test_knot_mode1(void)
{
  cable_error err;
  cable_sfile *sf = cable_sfile_read("tests/data/s.knot72_mode1_a", &err);
  if (!test_true("mode 1: tests/data/s.knot72_mode1_a read", sf != NULL)) return;
  const cable_solution *sol = cable_sfile_get(sf, 0);
  printf("# mode-1 knot at T = %.6g, F = %.8g\n", sol->par[BP_T], sol->par[BP_F]);
  int n, nc;
  double *K, *M, *G;
  braid_sv_info info;
  int st = braid_ritz(sol, BSV_KNOT_SYM, 1, BSV_DEGREE_MAX, &n, &nc, &K, &M, &G, &info);
  if (!test_int("mode 1: the Ritz matrices with the F2(0) row", st, 0)) {
    cable_sfile_free(sf);
    return;
  }
  printf("# N = %d, %d rows, first variation %.3e, asymmetry %.3e, F2(0) from the multipliers %.3e\n", n, nc,
         info.stat_res, info.asym, info.f2);
  test_le("mode 1: the first variation vanishes on the Ritz space", info.stat_res, stat_tol);
  test_le("mode 1: the Hessian is symmetric", info.asym, asym_tol);
  /* the solution is S0-symmetric: F2(0) = lambda_r . d1(0) = 0 to the
     multipliers' accuracy (mult_tol of |F|) */
  test_le("mode 1: F2(0) from the multipliers is 0 (rel. to |F|)", fabs(info.f2) / sol->par[BP_F], mult_tol);
  test_true("mode 1: the shift row and the F2(0) row are there", info.shift_row == 1 && info.f2_row == 1);
  double *ev1 = malloc((size_t)n * sizeof *ev1), *ev0 = malloc((size_t)n * sizeof *ev0);
  int nz1 = spectrum(n, K, M, G, nc, nc, ev1), nz0 = spectrum(n, K, M, G, nc, nc - 1, ev0);
  test_int("mode 1: the F2(0) row removes one degree of freedom", nz0 - nz1, 1);
  /* without the row: sigma_1 < 0 and a zero eigenvalue to the Ritz error
     (measured 2.6e-6 at degree 4; its sign changes with the degree); with
     it: index 1 and the next eigenvalue 8.9e-4, far from zero */
  double z0 = INFINITY, z1 = INFINITY;
  int neg1 = 0;
  for (int i = 0; i < nz0; i++) z0 = fmin(z0, fabs(ev0[i]));
  for (int i = 0; i < nz1; i++) {
    z1 = fmin(z1, fabs(ev1[i]));
    neg1 += ev1[i] < 0;
  }
  printf("# without the F2(0) row: sigma = %.6g %.4g %.4g; with it: %.6g %.4g %.4g\n", ev0[0], ev0[1], ev0[2], ev1[0],
         ev1[1], ev1[2]);
  test_le("mode 1: without the row an eigenvalue at zero (|sigma| / |sigma_1|)", z0 / fabs(ev0[0]), 1e-6);
  test_true("mode 1: with it none within 100 times that", z1 > 100 * z0);
  test_int("mode 1: index 1 with the row", neg1, 1);
  const cable_problem *pb = braid_problem_find("braid_knot_sym");
  cable_stab_result res;
  st = cable_stability_index(pb, sol, 1, sol->ncol, &res, &err);
  test_true("mode 1: braid_knot_sym's index (degree capped at 4): 1, no zero eigenvalue",
            st == 0 && res.index == 1 && res.nzero == 0 && res.nbasis == n);
  test_rel("mode 1: its sigma_2 is the independent solve's", res.eig[1], ev1[1], 1e-8);
  free(ev0); free(ev1); free(K); free(M); free(G);
  /* the family: pushing F2(0) away from 0 at fixed T keeps eps13 at zero on
     the mode branch (a family of solutions of braid_knot through (a)),
     while on the flat branch it does not (no family there: the flat knot
     needs no row) */
  double sm = push_slope("mode 1 (a)", "runs/knot72/c.knot72sym", sol);
  double sf0 = push_slope("flat knot T = 0", "runs/knot72/c.knot72", NULL);
  test_le("mode 1: eps13 stays 0 along the push (|d eps13 / d F2(0)|)", sm, 1e-7);
  test_true("flat knot: eps13 moves along the push (no family)", sf0 > 1e-4);
  cable_sfile_free(sf);
}

/* a STAB=1 run of the mode-1 branch (braid_knot_sym) from (a), ILP = 1 and
   ISP = 1: the index may change only at a located LP (by 1) or BP; returns
   the index at the first point, -1 on failure */
static int mode_stretch(const char *what, const cable_solution *start, const char *const *over, int nover, int *nspecial_out)
{
  const cable_problem *tpl = braid_problem_find("braid_knot_sym"), *pb = NULL;
  cable_constants c;
  cable_error err;
  char msg[200];
  int st = cable_constants_parse_file_for("runs/knot72/c.knot72sym", tpl, &c, NULL, &err);
  /* ISP=2: the mode branch turns in T where the extended matrix of
     braid_knot_sym is singular (its determinant changes sign in the step:
     doc/stability.md S7.3b), and the engine labels that point BP when its
     fold test, which passes through the singularity, cannot be located */
  const char *common[] = {"ISW=1", "ILP=1", "ISP=2", "STAB=1", "NPR=0", "UZR={}", "STOP=[]"};
  for (size_t i = 0; i < sizeof common / sizeof *common; i++)
    st |= cable_constants_parse_override(common[i], &c, NULL, tpl->parnames, tpl->npar, &err);
  for (int i = 0; i < nover; i++) st |= cable_constants_parse_override(over[i], &c, NULL, tpl->parnames, tpl->npar, &err);
  if (st == 0) st = cable_problem_prepare(tpl, &c, 0, &pb, &err);
  snprintf(msg, sizeof msg, "%s: constants and problem", what);
  if (!test_int(msg, st, 0)) return -1;
  brun *r = calloc(1, sizeof *r);
  cable_cont *cc = cable_cont_alloc(pb, &c, &st);
  if (st == CABLE_SUCCESS) st = cable_cont_set_start(cc, start);
  if (st == CABLE_SUCCESS) {
    cable_sink sink = {r, brun_point, NULL, NULL};
    st = cable_cont_run(cc, &sink, 1, 1, NULL);
  }
  cable_cont_free(cc);
  cable_problem_release(tpl, pb);
  printf("# %s: %d points, status %d (%s)\n", what, r->n, st, cable_status_message(st));
  int ok = r->n > 5, all = 1, prev = r->index[0], pending = 0, nlp = 0, nbp = 0;
  for (int i = 0; i < r->n; i++) {
    all &= r->stab[i] != 0;
    const int ty = r->itp[i] % 10;
    printf("#   T = %10.5f  index %d%s\n", r->T[i], r->index[i],
           ty == CABLE_TY_LP ? "  LP" : ty == CABLE_TY_BP ? "  BP" : "");
    if (ty == CABLE_TY_LP || ty == CABLE_TY_BP) {
      nlp += ty == CABLE_TY_LP;
      nbp += ty == CABLE_TY_BP;
      pending = 1;   /* the next regular point may differ from the last by the crossing */
      continue;
    }
    if (r->index[i] != prev && !pending) {
      ok = 0;
      printf("#   index %d -> %d at T = %.6f, away from a located LP or BP\n", prev, r->index[i], r->T[i]);
    }
    prev = r->index[i];
    pending = 0;
  }
  printf("# %s: %d LP, %d BP located\n", what, nlp, nbp);
  snprintf(msg, sizeof msg, "%s: every point has an index", what);
  test_true(msg, all);
  snprintf(msg, sizeof msg, "%s: the index changes only at a located LP or BP", what);
  test_true(msg, ok);
  int first = r->n > 0 ? r->index[0] : -1, same = 1;
  for (int i = 0; i < r->n; i++)
    same &= r->index[i] == first || r->itp[i] % 10 == CABLE_TY_LP || r->itp[i] % 10 == CABLE_TY_BP;
  snprintf(msg, sizeof msg, "%s: the index is %d at every point (the LP of the symmetric branch is no fold of the "
           "family's sheet: S7.3)", what, first);
  test_true(msg, same);
  *nspecial_out = nlp + nbp;
  free(r);
  return first;
}

static void test_mode_branch(void)
{
  cable_error err;
  cable_sfile *sf = cable_sfile_read("tests/data/s.knot72_mode1_a", &err);
  if (!test_true("mode 1 stretch: tests/data/s.knot72_mode1_a read", sf != NULL)) return;
  const cable_solution *sol = cable_sfile_get(sf, 0);
  /* (a) past the fold at T = -10.40 (the scene's run from (a) to its UZ2
     in part), and from (a) back towards BP1 (T = 11.076); measured: index 1
     at all 56 points of (a) -> fold -> (a)'s T and (a) -> T = 10.98 */
  const char *fwd[] = {"DS=5", "DSMAX=10", "NMX=24"};
  const char *bwd[] = {"DS=-5", "DSMAX=10", "NMX=12", "RL1=10.9"};
  int nlp1 = 0, nlp2 = 0;
  int i1 = mode_stretch("mode 1 from (a) past the fold", sol, fwd, 3, &nlp1);
  int i2 = mode_stretch("mode 1 from (a) towards BP1", sol, bwd, 4, &nlp2);
  test_int("mode 1 stretch: the turn at T = -10.40 located (LP, or the BP at it), and nothing else", nlp1, 1);
  test_int("mode 1 stretch: nothing located from (a) towards BP1", nlp2, 0);
  test_int("mode 1 stretch: index 1 at (a)", i1, 1);
  test_int("mode 1 stretch: the same at (a) in both runs", i2, 1);
  cable_sfile_free(sf);
}

int main(void)
{
  test_knot_mode1();
  test_mode_branch();
  test_buckled_link();
  test_flat_branches();
  return test_summary();
}
