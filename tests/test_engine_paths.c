/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Engine behaviour beyond the known answers:
 *  - mesh adaptation reduces the error of a boundary-layer solution at equal NTST;
 *  - the stiff dichotomy u'' = k^2 u (k up to 60) is solved to 1e-10 relative at
 *    NTST = 50, and the determinant sign stays constant along the k continuation;
 *  - condensation vs KLU, analytic vs finite-difference Jacobians: same points;
 *  - no allocation inside the Newton iteration (counted malloc calls);
 *  - modified Newton: NWTN factorisations, then chord iterations;
 *  - restart from a stored label reproduces the next points; a restart onto
 *    another NTST and NCOL reaches the fold with the new mesh's accuracy;
 *  - failures: a fatal callback, a recoverable one down to DSMIN, a
 *    non-converging start: clean stop, status, message, last good point kept;
 *  - a solution that FUNC refuses at a mesh point is never accepted. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cable/cable_constants.h"
#include "colloc_newton.h"
#include "colloc_system.h"
#include "engine_util.h"
#include "harness.h"
#include "test_problems.h"

/* Counting allocations: this program's malloc family forwards to glibc's and
 * counts the calls, so that a test can assert that a code region allocates
 * nothing (an allocation freed again before the region ends would escape a
 * heap-size comparison).  malloc has no context argument, so the counter is
 * a file-level variable, used by test_newton_no_alloc only.  Under
 * AddressSanitizer (which must own malloc) the interposition is left out and
 * only the net heap size (mallinfo2) is compared. */
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define COUNT_ALLOCS 1
#define HEAP_MEASURED 1
static long alloc_calls;
extern void *__libc_malloc(size_t n);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t n);
extern void *__libc_memalign(size_t align, size_t n);
extern void __libc_free(void *p);
void *malloc(size_t n)
{
  alloc_calls++;
  return __libc_malloc(n);
}
void *calloc(size_t n, size_t size)
{
  alloc_calls++;
  return __libc_calloc(n, size);
}
void *realloc(void *p, size_t n)
{
  alloc_calls++;
  return __libc_realloc(p, n);
}
int posix_memalign(void **p, size_t align, size_t n)
{
  alloc_calls++;
  *p = __libc_memalign(align, n);
  return *p || n == 0 ? 0 : 12; /* ENOMEM */
}
void *aligned_alloc(size_t align, size_t n)
{
  alloc_calls++;
  return __libc_memalign(align, n);
}
void free(void *p) { __libc_free(p); }
#else
#define COUNT_ALLOCS 0
#define HEAP_MEASURED 0
static long alloc_calls; /* stays 0: nothing counts */
#endif

/* no special-point detection unless a test asks */
static void base_constants_quiet(cable_constants *c, int ntst, int ncol)
{
  engine_constants(c, ntst, ncol);
  c->isp = 0;
  c->ilp = 0;
}


static double layer_error(const cable_solution *s)
{
  double p = s->par[0], eps = s->par[1], den = -expm1(-1.0 / eps), err = 0;
  for (int k = 0; k < s->ntst * s->ncol + 1; k++) {
    double exact = p * -expm1(-s->t[k] / eps) / den;
    err = fmax(err, fabs(s->u[2 * k] - exact));
  }
  return err;
}

static void test_adaptation(memrun *r)
{
  double err[2];
  for (int iad = 0; iad <= 1; iad++) {
    cable_constants c;
    base_constants_quiet(&c, 12, 3);
    c.iad = iad;
    c.ds = 0.05; c.dsmin = 1e-4; c.dsmax = 0.05; c.nmx = 8; c.iads = 0;
    memrun_run(cable_testproblem_layer(), &c, NULL, r);
    const cable_solution *last = r->nsol ? r->sol[r->nsol - 1] : NULL;
    err[iad] = last ? layer_error(last) : HUGE_VAL;
    memrun_free(r);
  }
  char what[128];
  snprintf(what, sizeof what, "boundary layer: adapted error %.3g < uniform error %.3g / 10", err[1], err[0]);
  test_true(what, err[1] < err[0] / 10);
}

/* Largest collocation residual of a stored solution on its own mesh (the
 * closing row fixes the principal parameter at its stored value). */
static double stored_residual(const cable_problem *pb, const cable_constants *c, const cable_solution *sol)
{
  int st, nfpr = sol->nfpr;
  colloc_system *s = colloc_system_alloc(pb, c, sol->ntst, sol->ncol, sol->icp, nfpr, &st);
  if (!s) return HUGE_VAL;
  for (int j = 0; j <= sol->ntst; j++) s->mesh[j] = sol->t[j * sol->ncol];
  memcpy(s->par, sol->par, (size_t)sol->npar * sizeof *s->par);
  s->closing = COLLOC_CLOSE_FIXPAR;
  s->fixval = sol->par[sol->icp[0]];
  double *x = calloc((size_t)s->n, sizeof *x), *F = calloc((size_t)s->n, sizeof *F), worst = HUGE_VAL;
  if (x && F) {
    size_t nu = (size_t)cable_solution_npts(sol) * (size_t)sol->ndim;
    memcpy(x, sol->u, nu * sizeof *x);
    for (int q = 0; q < nfpr; q++) x[nu + (size_t)q] = sol->par[sol->icp[q]];
    if (colloc_system_residual(s, x, F) == 0) {
      worst = 0;
      for (int i = 0; i < s->n; i++) worst = fmax(worst, fabs(F[i]));
    }
  }
  free(x);
  free(F);
  colloc_system_free(s);
  return worst;
}

/* With the mesh adapted at every step (IAD = 1), every stored solution must
 * still be the converged one on its own mesh, not the interpolant onto the
 * next mesh: its collocation residual is at Newton's level.  EPSL = EPSU =
 * 1e-10 here; the residual of a converged point is far below 1e-8, that of
 * an interpolant is the interpolation error (about 1e-3 on this layer). */
static void test_stored_after_adapt(memrun *r)
{
  cable_constants c;
  base_constants_quiet(&c, 12, 3);
  c.iad = 1;
  c.epsl = c.epsu = 1e-10;
  c.ds = 0.05; c.dsmin = 1e-4; c.dsmax = 0.05; c.nmx = 8; c.iads = 0; c.npr = 1;
  memrun_run(cable_testproblem_layer(), &c, NULL, r);
  double worst = 0;
  for (int i = 0; i < r->nsol; i++) worst = fmax(worst, stored_residual(cable_testproblem_layer(), &c, r->sol[i]));
  char what[160];
  snprintf(what, sizeof what, "IAD=1: the %d stored solutions are converged on their own meshes (max residual %.3g)",
           r->nsol, worst);
  test_true(what, r->nsol >= 8 && worst < 1e-8);
  memrun_free(r);
}

static void test_stiff(void)
{
  /* iad = 0: uniform mesh; iad = 1: adapted every step */
  for (int iad = 0; iad <= 1; iad++) {
    cable_constants c;
    base_constants_quiet(&c, 50, 7);
    c.iad = iad;
    c.ds = 1.0; c.dsmin = 1e-4; c.dsmax = 2.0; c.nmx = 100;
    c.nuzr = 1; c.uzr[0].par = 0; c.uzr[0].value = 60.0; c.uzr[0].stop = 1;
    c.epss = 1e-10;
    int st;
    cable_cont *cc = cable_cont_alloc(cable_testproblem_stiff(), &c, &st);
    if (st == 0) st = cable_cont_set_start(cc, NULL);
    int sign0 = 0, same = 1, npts = 0;
    while (st == 0 && (st = cable_cont_step(cc)) == 0) {
      int sg;
      cable_cont_test_functions(cc, &sg, NULL, NULL);
      if (npts++ == 0) sign0 = sg;
      else if (sg != sign0) same = 0;
    }
    char what[128];
    snprintf(what, sizeof what, "stiff IAD=%d: branch ends at the user zero k = 60", iad);
    test_int(what, st, CABLE_END_UZSTOP);
    snprintf(what, sizeof what, "stiff IAD=%d: determinant sign constant along k = 40..60", iad);
    test_true(what, same && npts > 5);
    const cable_solution *s = cable_cont_solution(cc);
    double k = s->par[0], err = 0, umax = 0, errmesh = 0;
    for (int i = 0; i < s->ntst * s->ncol + 1; i++) {
      double t = s->t[i], a = exp(-k * t), b = exp(-k * (1 - t)), e = exp(-k);
      double exact = (a - b * e + 2 * (b - a * e)) / (1 - e * e);
      err = fmax(err, fabs(s->u[2 * i] - exact));
      if (i % s->ncol == 0) errmesh = fmax(errmesh, fabs(s->u[2 * i] - exact));
      umax = fmax(umax, fabs(exact));
    }
    snprintf(what, sizeof what, "stiff IAD=%d: reached k = 60", iad);
    test_abs(what, k, 60.0, 1e-8);
    /* Gauss collocation with 7 points is the 14th-order Gauss RK method: at mesh
       points the per-step error is ~2e-16 (kh)^15 = 3e-15 for kh = 1.2.  Between
       mesh points the error is O((kh)^8) on a uniform mesh (~1e-9), so the
       all-node check is made on the adapted mesh. */
    if (iad == 0) {
      snprintf(what, sizeof what, "stiff uniform mesh: max relative error at mesh points, NTST=50, NCOL=7");
      test_le(what, errmesh / umax, 1e-10);
    } else {
      snprintf(what, sizeof what, "stiff adapted mesh: max relative error at all nodes, NTST=50, NCOL=7");
      test_le(what, err / umax, 1e-10);
    }
    cable_cont_free(cc);
  }
}

/* the points of two runs agree to tol (relative to 1 + |value|) */

/* The same Newton iterates with both linear solvers: Bratu at lambda = 2 from
 * u = 0, closing row lambda = 2, full Newton. */
static void test_newton_solvers(void)
{
  double *x[2] = {NULL, NULL};
  int iters[2] = {0, 0}, n = 0;
  for (int k = 0; k < 2; k++) {
    cable_constants c;
    base_constants_quiet(&c, 20, 4);
    c.linsolver = k ? CABLE_LINSOLVER_KLU : CABLE_LINSOLVER_CONDENSE;
    c.nwtn = c.itnw = 8;
    int icp[1] = {0}, st;
    colloc_system *s = colloc_system_alloc(cable_testproblem_bratu(), &c, 20, 4, icp, 1, &st);
    colloc_newton *nw = s ? colloc_newton_alloc(s, &c, &st) : NULL;
    if (!nw) {
      test_true("newton setup", 0);
      colloc_system_free(s);
      return;
    }
    n = s->n;
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixval = 2.0;
    x[k] = calloc((size_t)n, sizeof(double));
    x[k][n - 1] = 2.0;
    test_int(k ? "KLU Newton converges" : "condensation Newton converges", colloc_newton_solve(nw, x[k]), 0);
    iters[k] = colloc_newton_iterations(nw);
    colloc_newton_free(nw);
    colloc_system_free(s);
  }
  double d = 0;
  for (int i = 0; i < n; i++) d = fmax(d, fabs(x[0][i] - x[1][i]));
  test_int("condensation vs KLU: same number of Newton iterations", iters[0], iters[1]);
  /* the iterates differ only by the two factorisations' round-off (backward
     errors ~1e-16 times a condition number ~1e3, over a few iterations) */
  test_le("condensation vs KLU: same Newton iterates (max difference of the solutions)", d, 1e-12);
  free(x[0]);
  free(x[1]);
}

/* No allocation inside the Newton iteration: after a warm-up solve (KINSOL
 * sets up its linear solver on the first call), a second colloc_newton_solve
 * from another start (several iterations: residuals, Jacobians,
 * factorisations, solves) makes no malloc-family call and leaves the heap
 * size unchanged.  Condensation and KLU, analytic and finite-difference
 * Jacobians, full and modified Newton. */
static void test_newton_no_alloc(void)
{
  static const struct {
    cable_linsolver ls;
    int jac, nwtn;
    const char *name;
  } cases[] = {{CABLE_LINSOLVER_CONDENSE, 1, 8, "condensation, JAC=1, full Newton"},
               {CABLE_LINSOLVER_CONDENSE, 0, 8, "condensation, JAC=0, full Newton"},
               {CABLE_LINSOLVER_CONDENSE, 1, 1, "condensation, JAC=1, NWTN=1 (modified Newton)"},
               {CABLE_LINSOLVER_KLU, 1, 8, "KLU, JAC=1, full Newton"}};
  /* KLU is the reference path and is not held to this: SUNDIALS' KLU wrapper
     (SUNLinSolInitialize_KLU, called by every KINSol call) forces a new
     symbolic analysis and factorisation (klu_analyze, klu_factor: allocating)
     at the first setup of each solve; the count is printed, not tested. */
  for (size_t q = 0; q < sizeof cases / sizeof cases[0]; q++) {
    cable_constants c;
    base_constants_quiet(&c, 20, 4);
    c.linsolver = cases[q].ls;
    c.jac = cases[q].jac;
    c.itnw = 30;
    c.nwtn = cases[q].nwtn;
    int icp[1] = {0}, st;
    colloc_system *s = colloc_system_alloc(cable_testproblem_bratu(), &c, 20, 4, icp, 1, &st);
    colloc_newton *nw = s ? colloc_newton_alloc(s, &c, &st) : NULL;
    double *x = s ? calloc((size_t)s->n, sizeof *x) : NULL;
    if (!nw || !x) {
      test_true("newton (allocation test) setup", 0);
      free(x);
      colloc_newton_free(nw);
      colloc_system_free(s);
      return;
    }
    int n = s->n;
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixval = 2.0;
    x[n - 1] = 2.0;
    int warm = colloc_newton_solve(nw, x);
    for (int i = 0; i < n; i++) x[i] = 0.0;
    s->fixval = 3.0;
    x[n - 1] = 3.0;
#if defined(__GLIBC__)
    struct mallinfo2 m0 = mallinfo2();
#endif
    long calls0 = COUNT_ALLOCS ? alloc_calls : 0;
    int rc = colloc_newton_solve(nw, x);
    long calls = COUNT_ALLOCS ? alloc_calls - calls0 : 0;
#if defined(__GLIBC__)
    struct mallinfo2 m1 = mallinfo2();
    long grown = (long)m1.uordblks - (long)m0.uordblks;
#else
    long grown = 0;
#endif
    char what[200];
    snprintf(what, sizeof what, "Newton (%s): warm-up and measured solves converge (%d iterations)", cases[q].name,
             colloc_newton_iterations(nw));
    test_true(what, warm == CABLE_SUCCESS && rc == CABLE_SUCCESS && colloc_newton_iterations(nw) >= 3);
    if (cases[q].ls == CABLE_LINSOLVER_KLU) {
      printf("  Newton (%s): %ld allocation calls, heap in use %+ld bytes (reference path, not tested)\n",
             cases[q].name, calls, grown);
    } else {
      snprintf(what, sizeof what, "Newton (%s): no malloc/calloc/realloc call inside the iteration", cases[q].name);
      if (COUNT_ALLOCS) test_int(what, calls, 0);
      else test_skip(what, "not counted: the sanitizer owns malloc, so this build cannot interpose it");
      snprintf(what, sizeof what, "Newton (%s): heap in use unchanged (mallinfo2 uordblks)", cases[q].name);
      if (HEAP_MEASURED) test_int(what, grown, 0);
      else test_skip(what, "not measured: glibc's mallinfo2 does not see the sanitizer's heap");
    }
    free(x);
    colloc_newton_free(nw);
    colloc_system_free(s);
  }
}

/* Modified Newton (NWTN < ITNW): NWTN factorisations, then chord iterations
 * with the last one (AUTO's rule), converging to the full-Newton solution.
 * Bratu at lambda = 3 from u = 0 (a poor start: several iterations). */
static void test_modified_newton(void)
{
  static const int nwtns[] = {30, 3, 2, 1};
  double *ref = NULL;
  int n = 0, full_iters = 0;
  for (size_t q = 0; q < sizeof nwtns / sizeof nwtns[0]; q++) {
    cable_constants c;
    base_constants_quiet(&c, 20, 4);
    c.itnw = 30;
    c.nwtn = nwtns[q];
    c.epsl = c.epsu = 1e-10;
    int icp[1] = {0}, st;
    colloc_system *s = colloc_system_alloc(cable_testproblem_bratu(), &c, 20, 4, icp, 1, &st);
    colloc_newton *nw = s ? colloc_newton_alloc(s, &c, &st) : NULL;
    double *x = s ? calloc((size_t)s->n, sizeof *x) : NULL;
    if (!nw || !x) {
      test_true("modified Newton setup", 0);
      free(x); colloc_newton_free(nw); colloc_system_free(s);
      break;
    }
    n = s->n;
    s->closing = COLLOC_CLOSE_FIXPAR;
    s->fixval = 3.0;
    x[n - 1] = 3.0;
    int rc = colloc_newton_solve(nw, x);
    int it = colloc_newton_iterations(nw), ns = colloc_newton_setups(nw);
    char what[160];
    snprintf(what, sizeof what, "NWTN=%d ITNW=30: converges (%d iterations, %d factorisations)", nwtns[q], it, ns);
    test_true(what, rc == CABLE_SUCCESS);
    if (q == 0) {
      snprintf(what, sizeof what, "NWTN >= ITNW (full Newton): one factorisation per iteration");
      test_int(what, ns, it);
      full_iters = it;
      ref = x;
      x = NULL;
    } else {
      /* NWTN factorisations, then chord iterations (more of them than full
         Newton needs); one more when the chord phase ends by the step test
         (KINSOL re-factors before accepting it: colloc_newton.h) */
      snprintf(what, sizeof what, "NWTN=%d: NWTN or NWTN+1 factorisations (%d) for %d iterations", nwtns[q], ns, it);
      test_true(what, ns >= nwtns[q] && ns <= nwtns[q] + 1 && ns < it);
      snprintf(what, sizeof what, "NWTN=%d: the chord method needs more iterations (%d) than full Newton (%d)", nwtns[q],
               it, full_iters);
      test_true(what, it > full_iters);
      double d = 0;
      for (int i = 0; ref && i < n; i++) d = fmax(d, fabs(x[i] - ref[i]));
      /* both stop when the last correction is below 1e-10 (1 + |x|); the chord
         method's linear rate leaves at most a few times that */
      snprintf(what, sizeof what, "NWTN=%d: same solution as full Newton", nwtns[q]);
      test_le(what, d, 1e-8);
      /* the factorisation is offered for the tangent exactly when KINSOL's
         final re-factorisation made it for the last iteration */
      snprintf(what, sizeof what, "NWTN=%d: the last factorisation is offered for the tangent iff it is fresh", nwtns[q]);
      struct abd_solver *abd;
      colloc_jac *J;
      test_int(what, colloc_newton_factorization(nw, &abd, &J) == 0, ns == nwtns[q] + 1);
    }
    free(x);
    colloc_newton_free(nw);
    colloc_system_free(s);
  }
  free(ref);
}

static void test_variants(void)
{
  memrun *a = calloc(1, sizeof *a), *b = calloc(1, sizeof *b);
  cable_constants c;
  base_constants_quiet(&c, 20, 4);
  c.ds = 0.1; c.dsmin = 1e-5; c.dsmax = 0.3; c.nmx = 20; c.ilp = 1;
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  c.linsolver = CABLE_LINSOLVER_KLU;
  memrun_run(cable_testproblem_bratu(), &c, NULL, b);
  /* the condensation run takes its tangents from the corrector's own
     factorisation (at the last iterate but one), the KLU run factors again at
     the converged point: predictors differ by the Newton tolerance, and so do
     the converged points (EPSU = 1e-7, quadratic convergence leaves less) */
  test_le("condensation vs KLU runs: same points to the Newton tolerance", memrun_compare(a, b), 1e-7);
  memrun_free(b);
  test_newton_solvers();
  c.linsolver = CABLE_LINSOLVER_CONDENSE;
  c.jac = 0;
  memrun_run(cable_testproblem_bratu(), &c, NULL, b);
  /* FD Jacobians change only the Newton path, not the converged points: the
     points agree to the Newton tolerance EPSU = 1e-7 (quadratic convergence
     leaves far less) */
  test_le("analytic vs finite-difference Jacobian: same points", memrun_compare(a, b), 1e-7);
  test_int("both runs converge", a->status > 0 && b->status > 0, 1);
  memrun_free(b);

  /* restart from label 3 with fixed steps reproduces the following points */
  memrun_free(a);
  c.jac = 1; c.iads = 0; c.npr = 3; c.nmx = 12; c.ilp = 0;
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  const cable_solution *s3 = NULL;
  int at = -1;
  for (int i = 0; i < a->nsol; i++)
    if (a->sol[i]->lab == 3) s3 = a->sol[i];
  for (int i = 0; i < a->n; i++)
    if (a->lab[i] == 3) at = i;
  test_true("label 3 stored", s3 != NULL && at >= 0);
  if (s3) {
    c.nmx = 4;
    memrun_run(cable_testproblem_bratu(), &c, s3, b);
    /* NMX counts the restart point: 3 new points, each compared (an empty or
       one-point restart used to pass with nothing compared) */
    int compared = 0;
    double d = 0;
    for (int i = 1; i < b->n && at + i < a->n; i++, compared++)
      d = fmax(d, fabs(b->par[i][0] - a->par[at + i][0]) + fabs(b->l2[i] - a->l2[at + i]));
    test_int("restart from label 3: the restart computes NMX points", b->n, 4);
    test_int("restart from label 3: three points compared with the first run", compared, 3);
    test_le("restart from label 3 reproduces the next points", d, 1e-10);
  }
  memrun_free(a);
  memrun_free(b);
  free(a);
  free(b);
}

/* max |u - exact| at the mesh points of a lower-branch Bratu solution */
static double bratu_mesh_error(const cable_solution *s)
{
  double lam = s->par[0], th = cable_bratu_theta(lam), err = 0;
  for (int j = 0; j <= s->ntst; j++) {
    int k = j * s->ncol;
    err = fmax(err, fabs(s->u[2 * k] - cable_bratu_exact(lam, th, s->t[k])));
  }
  return err;
}

/* Restart onto another mesh: the lower-branch solution at lambda = 3 from an
 * NTST=20, NCOL=4 run, re-interpolated onto NTST=13, NCOL=6, continues to the
 * fold.  The fold and the first new point must have the new discretisation's
 * accuracy, not the interpolant's: NCOL=6 interpolation of the NCOL=4
 * polynomials is exact, but the NTST=13 mesh is not a refinement of the
 * NTST=20 one, so the start is off by the old method's interpolation error. */
static void test_restart_new_mesh(memrun *a, memrun *b)
{
  cable_constants c;
  base_constants_quiet(&c, 20, 4);
  c.ds = 0.1; c.dsmin = 1e-6; c.dsmax = 0.5; c.nmx = 100;
  c.nuzr = 1; c.uzr[0].par = 0; c.uzr[0].value = 3.0; c.uzr[0].stop = 1;
  c.epss = 1e-10;
  memrun_run(cable_testproblem_bratu(), &c, NULL, a);
  const cable_solution *uz = memrun_find(a, CABLE_TY_UZ, 0);
  test_true("restart onto NTST=13 NCOL=6: the lambda = 3 solution stored", uz != NULL);
  if (!uz) return;
  base_constants_quiet(&c, 13, 6);
  c.ds = 0.05; c.dsmin = 1e-6; c.dsmax = 0.2; c.nmx = 60; c.npr = 1;
  c.ilp = 1; c.rl1 = 10.0;
  c.epss = 1e-10;
  memrun_run(cable_testproblem_bratu(), &c, uz, b);
  const cable_solution *lp = memrun_find(b, CABLE_TY_LP, 0);
  test_true("restart onto NTST=13 NCOL=6: the fold is found", lp != NULL);
  /* NTST=13, NCOL=6: eigenvalue-type error O(h^(2 NCOL)) = 13^-12 ~ 4e-14 times
     a modest constant; location to EPSS = 1e-10 of the step: the same 1e-9
     bound as at NTST=20, NCOL=4 (test_engine_bvp.c) */
  if (lp) {
    test_int("restart onto NTST=13 NCOL=6: the stored fold has the new NTST", lp->ntst, 13);
    test_int("restart onto NTST=13 NCOL=6: the stored fold has the new NCOL", lp->ncol, 6);
    test_abs("restart onto NTST=13 NCOL=6: fold lambda*", lp->par[0], 3.513830719125162, 1e-9);
  }
  /* the first computed point (solution 1; 0 is the restart itself) on the
     lower branch: mesh-point error at the new method's level, O(h^12) (13^-12
     ~ 4e-14 times the derivative growth: < 1e-11; measured 2e-15), against
     the interpolated start's O(h^5) of NCOL=4 between the old mesh points
     (measured 7e-10 at the new mesh points) */
  const cable_solution *first = b->nsol > 1 ? b->sol[1] : NULL;
  if (first) {
    char what[128];
    snprintf(what, sizeof what, "restart onto NTST=13 NCOL=6: first new point (lambda = %.4f) has the new method's accuracy",
             first->par[0]);
    test_le(what, bratu_mesh_error(first), 1e-11);
  } else {
    test_true("restart onto NTST=13 NCOL=6: a point computed", 0);
  }
  memrun_free(a);
  memrun_free(b);
}

/* Bratu, but FUNC fails beyond lambda = limit: fatal (< 0) or recoverable (> 0). */
typedef struct {
  double limit;
  int code;
} failing_params;

static int failing_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                        double *f, double *dfdu, double *dfdp, void *params)
{
  const failing_params *fp = params;
  if (par[0] > fp->limit) return fp->code;
  return cable_testproblem_bratu()->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, NULL);
}

/* Bratu, but FUNC refuses states with u' above a limit.  u' is largest at
 * t = 0, a mesh point, where collocation never evaluates FUNC: only the
 * engine's check of the stored nodes keeps such states out of the output. */
static int slope_limited_func(int ndim, const double *u, const int *icp, const double *par, int ijac,
                              double *f, double *dfdu, double *dfdp, void *params)
{
  const failing_params *fp = params;
  if (u[1] > fp->limit) return fp->code;
  return cable_testproblem_bratu()->func(ndim, u, icp, par, ijac, f, dfdu, dfdp, NULL);
}

static void test_domain_at_mesh_points(memrun *r)
{
  cable_problem pb = *cable_testproblem_bratu();
  failing_params fp = {0.5, 1};
  pb.func = slope_limited_func;
  pb.params = &fp;
  cable_constants c;
  base_constants_quiet(&c, 10, 3);
  c.ds = 0.1; c.dsmin = 1e-4; c.dsmax = 0.1; c.nmx = 200; c.npr = 1;
  memrun_run(&pb, &c, NULL, r);
  test_int("domain at mesh points: ends at DSMIN", r->status, CABLE_ERR_DSMIN);
  test_true("domain at mesh points: message names FUNC and t", strstr(r->err, "FUNC rejects") && strstr(r->err, "t = 0"));
  double worst = -HUGE_VAL;
  for (int i = 0; i < r->nsol; i++)
    for (int k = 0; k < cable_solution_npts(r->sol[i]); k++) worst = fmax(worst, r->sol[i]->u[2 * k + 1]);
  char what[160];
  snprintf(what, sizeof what, "domain at mesh points: max u' over all stored nodes of %d solutions %.6f <= limit %.1f",
           r->nsol, worst, fp.limit);
  test_true(what, r->nsol > 3 && worst <= fp.limit);
  memrun_free(r);
}

static void test_failures(memrun *r)
{
  cable_problem pb = *cable_testproblem_bratu();
  failing_params fp = {1.0, -1};
  pb.func = failing_func;
  pb.params = &fp;
  cable_constants c;
  base_constants_quiet(&c, 10, 3);
  c.ds = 0.1; c.dsmin = 1e-3; c.dsmax = 0.1; c.nmx = 50;
  memrun_run(&pb, &c, NULL, r);
  test_int("fatal callback: status CABLE_ERR_CALLBACK", r->status, CABLE_ERR_CALLBACK);
  test_true("fatal callback: message names the callback", strstr(r->err, "callback") != NULL);
  test_true("fatal callback: last good point kept as MX", r->nsol >= 2 && r->sol[r->nsol - 1]->itp == CABLE_TY_MX &&
                                                           r->sol[r->nsol - 1]->par[0] <= 1.0);
  memrun_free(r);
  fp.code = 1;
  memrun_run(&pb, &c, NULL, r);
  test_int("recoverable callback: ends at DSMIN", r->status, CABLE_ERR_DSMIN);
  test_true("DSMIN: message", strstr(r->err, "DSMIN") != NULL);
  int finite = 1;
  for (int i = 0; i < r->n; i++)
    if (!isfinite(r->par[i][0]) || !isfinite(r->l2[i])) finite = 0;
  test_true("DSMIN: no NaN or Inf in the output", finite);
  test_true("DSMIN: last good point below the limit", r->n > 0 && r->par[r->n - 1][0] <= 1.0);
  memrun_free(r);
  /* a start that cannot converge: lambda = 5 has no Bratu solution */
  base_constants_quiet(&c, 10, 3);
  c.npar_override = 1;
  c.par_override[0].index = 0;
  c.par_override[0].value = 5.0;
  c.itnw = 6;
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  test_int("no solution at the start: CABLE_ERR_NEWTON", r->status, CABLE_ERR_NEWTON);
  test_int("no solution at the start: nothing stored", r->nsol, 0);
  memrun_free(r);
  /* the same value in UZR and UZSTOP: one located user zero, and the branch stops there */
  base_constants_quiet(&c, 10, 3);
  c.ds = 0.1; c.dsmax = 0.3; c.nmx = 100;
  c.nuzr = 2;
  c.uzr[0].par = 0; c.uzr[0].value = 2.0; c.uzr[0].stop = 0;
  c.uzr[1].par = 0; c.uzr[1].value = 2.0; c.uzr[1].stop = 1;
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  test_int("UZR and UZSTOP at one value: stops there", r->status, CABLE_END_UZSTOP);
  test_int("UZR and UZSTOP at one value: one UZ point", memrun_count(r, CABLE_TY_UZ), 1);
  memrun_free(r);
  /* bad input is refused before any work */
  base_constants_quiet(&c, 10, 3);
  c.nicp = 0;
  memrun_run(cable_testproblem_bratu(), &c, NULL, r);
  test_int("ICP missing: CABLE_ERR_INPUT", r->status, CABLE_ERR_INPUT);
  test_true("ICP missing: message", strstr(r->err, "ICP") != NULL);
  memrun_free(r);
}

int main(void)
{
  memrun *r = calloc(1, sizeof *r);
  test_adaptation(r);
  test_stored_after_adapt(r);
  test_stiff();
  test_variants();
  test_newton_no_alloc();
  test_modified_newton();
  {
    memrun *a = calloc(1, sizeof *a), *b = calloc(1, sizeof *b);
    if (a && b) test_restart_new_mesh(a, b);
    free(a);
    free(b);
  }
  test_failures(r);
  test_domain_at_mesh_points(r);
  free(r);
  return test_summary();
}
