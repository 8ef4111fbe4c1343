/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The problem interface: the C form of AUTO-07p's FUNC, BCND, ICND, STPNT and
 * PVLS user routines, plus the dimensions and names AUTO keeps in the
 * constants file.  Built-in problems and user plug-ins (.so files exporting
 * `cable_problem_entry`) are described by the same struct.
 *
 * Conventions (identical to AUTO-07p's C interface, with a trailing params):
 *  - the independent variable is t in [0,1]; the system is autonomous;
 *  - par[k] is AUTO's PAR(k+1); icp[] holds 0-based parameter indices;
 *  - derivative arrays are column-major (Fortran, LAPACK):
 *      dfdu[i + ndim*j]            = d f_i / d u_j            (ndim x ndim)
 *      dfdp[i + ndim*k]            = d f_i / d par_k          (ndim x npar)
 *      dbc [i + nbc*j]             j <  ndim:      d fb_i / d u0_j
 *                                  j <  2 ndim:    d fb_i / d u1_(j-ndim)
 *                                  j >= 2 ndim:    d fb_i / d par_(j-2ndim)
 *      dint[i + nint*j]            j < ndim: d fi_i / d u_j; else d/d par_(j-ndim)
 *  - ijac = 0: values only; 1: also derivatives w.r.t. u; 2: also w.r.t. par.
 *    Only the columns of the free parameters (icp[0..nfpr-1]) are read.
 *  - return value: 0 success; > 0 recoverable (the engine rejects the step and
 *    retries with a smaller one); < 0 fatal (the run stops with a diagnostic).
 *  - the callbacks may not keep pointers to their array arguments.
 */
#ifndef CABLE_PROBLEM_H
#define CABLE_PROBLEM_H

#include "cable/cable_api.h"

#include <stddef.h>

#define CABLE_PROBLEM_ABI 6        /* bump when the struct layout changes (2: keys, prepare, release;
                                      3: concurrent; 4: variational; 5: variational.ritz;
                                      6: symmetries) */
/* The oldest layout still loaded: an ABI 5 plug-in (no symmetries) is copied
 * into the current struct with nsym = 0. */
#define CABLE_PROBLEM_ABI_OLDEST 5
#define CABLE_NPAR_DEFAULT 36      /* AUTO's default NPAR */
#define CABLE_PROBLEM_ENTRY "cable_problem_entry"

struct cable_solution;
struct cable_constants;
struct cable_error;
struct cable_problem;

typedef int cable_func_fn(int ndim, const double *u, const int *icp, const double *par,
                          int ijac, double *f, double *dfdu, double *dfdp, void *params);
typedef int cable_bcnd_fn(int ndim, const double *par, const int *icp, int nbc,
                          const double *u0, const double *u1, int ijac, double *fb,
                          double *dbc, void *params);
/* uold, udot, upold: the previous solution, the tangent and its t-derivative at
 * the same point (AUTO's arguments; used by phase conditions). */
typedef int cable_icnd_fn(int ndim, const double *par, const int *icp, int nint,
                          const double *u, const double *uold, const double *udot,
                          const double *upold, int ijac, double *fi, double *dint,
                          void *params);
/* Starting solution at t; also sets the parameters' starting values. */
typedef int cable_stpnt_fn(int ndim, double t, double *u, double *par, void *params);
/* Derived quantities of a converged solution, written into par[] slots that the
 * constants file may list in ICP after the free parameters (AUTO's PVLS). */
typedef int cable_pvls_fn(const struct cable_solution *sol, double *par, void *params);

/* Problem-specific constants keys (e.g. the braid's TORUS and HAND).  The
 * constants parser accepts a key a problem declares, checks its type and
 * range with the same file:line:key errors as cable's own keys, and keeps
 * the value in cable_constants (cable_constants_key reads it). */
enum cable_key_type {
  CABLE_KEY_INT = 1,    /* an integer in [min, max] */
  CABLE_KEY_REAL = 2    /* a finite real in [min, max] */
};

/* A value that may be given by name (HAND = 'left'). */
typedef struct cable_key_word {
  const char *word;             /* compared without regard to case; NULL ends a list */
  double value;
} cable_key_word;

typedef struct cable_problem_key {
  const char *name;             /* as written in constants files; not one of cable's keys */
  int type;                     /* enum cable_key_type */
  double min, max;              /* accepted range, inclusive */
  double def;                   /* the value when the constants do not set the key */
  const cable_key_word *words;  /* NULL, or the accepted values by name ({NULL, 0} ends the
                                   list); an INT key with words accepts only their values */
  const char *help;             /* one line: what the key means (shown in errors) */
} cable_problem_key;

/* prepare (optional): a runnable instance of the problem for a run with
 * constants c (every override applied); from_stpnt is 1 when the run starts
 * from STPNT, 0 for a restart from a stored solution.  Sets *instance (pb
 * itself when nothing needs preparing) and returns 0, or returns a negative
 * status with err naming the key at fault.  Whatever prepare builds belongs
 * to the instance until release(pb, instance). */
typedef int cable_prepare_fn(const struct cable_problem *pb, const struct cable_constants *c, int from_stpnt,
                             const struct cable_problem **instance, struct cable_error *err);
typedef void cable_release_fn(const struct cable_problem *pb, const struct cable_problem *instance);

/* The variational structure of a problem (doc/stability.md, S1 and S4): its
 * solutions are critical points of A[y] = int_0^1 L(y, y', p) dt over
 * y: [0,1] -> R^nvar under boundary and integral constraints, L holding the
 * constraints' multipliers.  The Morse index (STAB=1) needs only L's second
 * derivatives at a solution and the linearised constraints on variations v.
 * The callbacks return 0, or non-zero on failure (the index is then unknown). */
typedef struct cable_variational {
  int nvar;    /* configuration variables y (>= 1) */
  int ncon;    /* integral rows: int (a.v + b.v') dt = 0 (linearised integral constraints,
                  L2-orthogonality to symmetry generators: a = w, b = 0) */
  int nvbc;    /* boundary rows: B [v(0); v(1)] = 0 */
  /* At a state u of the ODE system: P = L_{y'y'}, C = L_{y'y}
   * (C[i + nvar*j] = d2L / dy'_i dy_j), R = L_{yy}, each nvar x nvar column-major. */
  int (*hessian)(int ndim, const double *u, const double *par, int nvar, double *P, double *C,
                 double *R, void *params);
  /* At u: a[k + ncon*i], b[k + ncon*i], the coefficients of v_i and v_i' in row k
   * (may be NULL when ncon = 0). */
  int (*constraints)(int ndim, const double *u, const double *par, int nvar, int ncon, double *a,
                     double *b, void *params);
  /* B[r + nvbc*j]: j < nvar the coefficient of v_j(0), else of v_(j-nvar)(1); Hb (NULL when
   * not wanted) the boundary Hessian, 2 nvar x 2 nvar, zero for linear conditions (may be
   * NULL when nvbc = 0). */
  int (*vbc)(int ndim, const double *u0, const double *u1, const double *par, int nvar, int nvbc,
             double *B, double *Hb, void *params);
  /* A problem whose second variation is not of the local form above (the braid: its closure
   * constraints are integrals of the kinematics, doc/stability.md S7) assembles the Ritz
   * matrices itself: *n unknowns, K and M (n x n, symmetric, M positive definite), G (*nc x n,
   * column-major, the linearised constraints G x = 0), malloc'ed, freed by the caller.  When
   * set, hessian, constraints and vbc are not used (may be NULL) and nvar is ignored. */
  int (*ritz)(const struct cable_solution *sol, int refine, int degree, int *n, int *nc, double **K, double **M,
              double **G, void *params);
} cable_variational;

/* A reflection S of the problem (doc/plugins.md, "Symmetries"; doc/engine.md,
 * "Symmetry: the restriction to Fix(S)"): S maps solutions to solutions and
 * S^2 = 1.  At a double branch point whose kernel S splits into a symmetric
 * and an antisymmetric direction, the engine restricts the problem to Fix(S)
 * (one condition: the odd quantity below = 0, and one unfolding parameter,
 * zero on the restricted branch), where the branch point is simple, and
 * switches there.  S is given either
 *  - by act (pointwise: su = S u for the state at one t, linear; the
 *    parameters are fixed by S): the engine forms the odd quantity itself, or
 *  - by odd_comp, odd_at (act NULL): u_{odd_comp}(odd_at) (odd_at 0: t = 0,
 *    1: t = 1) changes sign under S and vanishes exactly on Fix(S) near the
 *    branch point (e.g. a reversing symmetry u(t) -> R u(1 - t) of a
 *    reversible ODE, which the pointwise act cannot express). */
typedef void cable_sym_act_fn(int ndim, const double *u, double *su, void *params);
typedef struct cable_symmetry {
  const char *name;             /* one word, shown in notes ("swap", "S0") */
  cable_sym_act_fn *act;        /* S on the state, or NULL (then odd_comp, odd_at) */
  int odd_comp;                 /* 0-based state component, with act NULL */
  int odd_at;                   /* 0: at t = 0, 1: at t = 1 */
  int unfold_bc;                /* the boundary condition (0-based row) that gets the unfolding
                                   parameter added; -1: the engine picks the row where the
                                   antisymmetric left null vector is largest */
  int unfold_par;               /* 0-based parameter slot of the unfolding parameter; -1: the first
                                   slot at or after npar that ICP does not use (< NPAR) */
  int multiplicity;             /* copies of a branch in Fix(S) under the problem's whole symmetry
                                   group (the torus knot's rotations: TORUS); 0 counts as 1 */
} cable_symmetry;

typedef struct cable_problem {
  int abi_version;              /* CABLE_PROBLEM_ABI */
  size_t struct_size;           /* sizeof(cable_problem) when compiled */
  const char *name;             /* selected with e=NAME */
  const char *description;      /* one line */
  int ndim;                     /* number of ODEs */
  int nbc;                      /* number of boundary conditions */
  int nint;                     /* number of integral conditions */
  int npar;                     /* parameter slots the problem uses (<= NPAR) */
  const char *const *parnames;  /* npar names, a NULL entry means unnamed; may be NULL */
  const char *const *unames;    /* ndim names or NULL */
  cable_func_fn *func;          /* required */
  cable_bcnd_fn *bcnd;          /* required when nbc > 0 */
  cable_icnd_fn *icnd;          /* required when nint > 0 */
  cable_stpnt_fn *stpnt;        /* required for IRS = 0 starts */
  cable_pvls_fn *pvls;          /* optional */
  int func_has_jac;             /* 1: func fills dfdu/dfdp when asked; 0: engine differences */
  int bcnd_has_jac;
  int icnd_has_jac;
  void *params;                 /* passed to every callback */
  /* ABI 2 */
  const cable_problem_key *keys;  /* nkeys problem-specific constants keys, or NULL */
  int nkeys;
  cable_prepare_fn *prepare;    /* optional (NULL: the problem runs as it is) */
  cable_release_fn *release;    /* required with prepare */
  /* ABI 3 */
  int concurrent;               /* 1: func may be called from several threads at once (it only
                                   reads params and its arguments); the engine then evaluates
                                   the mesh intervals on NTHREADS threads.  0 (the default of a
                                   zero-initialised struct): func is called from one thread. */
  /* ABI 4 */
  const cable_variational *variational;  /* NULL: not variational (STAB=1 is refused) */
  /* ABI 6 */
  const cable_symmetry *symmetries;  /* nsym reflections of the problem, or NULL */
  int nsym;
} cable_problem;

/* A plug-in exports `const cable_problem *cable_problem_entry(void);`. */
typedef const cable_problem *cable_problem_entry_fn(void);

/* The built-in problems: the engine's test problems (bratu, bratu_int,
 * elastica, layer, stiff) and the braid templates (braid_knot,
 * braid_knot_sym, braid_link, braid_link_sym; their params are NULL, which
 * serves restarts from stored solutions).  NULL for an unknown name. */
CABLE_API const cable_problem *cable_problem_builtin(const char *name);
/* The i-th built-in problem's name (0-based), NULL past the last. */
CABLE_API const char *cable_problem_builtin_name(int i);
/* The constants a built-in problem recommends, as constants text
 * ("NTST=30, NCOL=7, ..."): the settings its scenes use.  A run with no
 * constants file, no start and no earlier run in the session takes them
 * as its defaults (doc/scripts.md); NULL when the problem has none. */
CABLE_API const char *cable_problem_recommended(const char *name);

/* What a front end calls before a run: pb's prepare, or *instance = pb when
 * it has none.  0, or a negative status with err (CABLE_ERR_NULL for a NULL
 * argument).  *instance is NULL after a failure. */
CABLE_API int cable_problem_prepare(const cable_problem *pb, const struct cable_constants *c, int from_stpnt,
                                    const cable_problem **instance, struct cable_error *err);
/* Gives back an instance from cable_problem_prepare (NULL is a no-op). */
CABLE_API void cable_problem_release(const cable_problem *pb, const cable_problem *instance);
/* The problem's key called name, or NULL. */
CABLE_API const cable_problem_key *cable_problem_key_find(const cable_problem *pb, const char *name);

#endif
