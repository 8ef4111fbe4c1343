/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Internals of the AUTO equation-file loader (autoeq_build.c builds and
 * caches, autoeq_load.c loads and checks, autoeq_shim.c adapts the routines
 * and implements GETP). */
#ifndef CABLE_AUTOEQ_IMPL_H
#define CABLE_AUTOEQ_IMPL_H

#include "auto_compat/cable_getp.h"
#include "cable/cable_autoeq.h"

#define AUTOEQ_PATH_MAX 1024
#define AUTOEQ_MAX_ICP (CABLE_MAX_ICP + 8)
#define AUTOEQ_MAX_ARGS 24     /* arguments of one routine recorded for the check */
#define AUTOEQ_ARGNAME 32

/* The files of auto_iface/autoeq/auto_compat, embedded at build time (the Makefile
 * generates the table from the files themselves). */
typedef struct cable_autoeq_compat_file {
  const char *name;
  const char *text;
} cable_autoeq_compat_file;
extern const cable_autoeq_compat_file cable_autoeq_compat_files[];
extern const int cable_autoeq_compat_nfiles;

typedef enum { AUTOEQ_FORTRAN = 0, AUTOEQ_C = 1 } autoeq_lang;

/* The six routines, in this order everywhere. */
enum { AE_FUNC, AE_STPNT, AE_BCND, AE_ICND, AE_FOPT, AE_PVLS, AE_NROUTINES };
extern const char *const autoeq_routine_name[AE_NROUTINES];   /* "FUNC" ... */

/* Fortran calling convention (gfortran: lower case, trailing underscore). */
typedef void autoeq_f_func(const int *ndim, const double *u, const int *icp, const double *par, const int *ijac,
                           double *f, double *dfdu, double *dfdp);
typedef void autoeq_f_stpnt(const int *ndim, double *u, double *par, const double *t);
typedef void autoeq_f_bcnd(const int *ndim, const double *par, const int *icp, const int *nbc, const double *u0,
                           const double *u1, double *fb, const int *ijac, double *dbc);
typedef void autoeq_f_icnd(const int *ndim, const double *par, const int *icp, const int *nint, const double *u,
                           const double *uold, const double *udot, const double *upold, double *fi,
                           const int *ijac, double *dint);
typedef void autoeq_f_pvls(const int *ndim, const double *u, double *par);

/* AUTO's C interface (auto_compat/auto_f2c.h). */
typedef int autoeq_c_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f,
                          double *dfdu, double *dfdp);
typedef int autoeq_c_stpnt(int ndim, double t, double *u, double *par);
typedef int autoeq_c_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1,
                          int ijac, double *fb, double *dbc);
typedef int autoeq_c_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                          const double *udot, const double *upold, int ijac, double *fi, double *dint);
typedef int autoeq_c_pvls(int ndim, const double *u, double *par);
typedef struct autoeq_c_table {
  int version;
  autoeq_c_func *func;
  autoeq_c_stpnt *stpnt;
  autoeq_c_bcnd *bcnd;
  autoeq_c_icnd *icnd;
  void *fopt;
  autoeq_c_pvls *pvls;
} autoeq_c_table;

struct cable_autoeq {
  char src[AUTOEQ_PATH_MAX];     /* the equation file */
  char so[AUTOEQ_PATH_MAX];      /* the module in the cache */
  char name[64];                 /* NAME, the problem's name */
  autoeq_lang lang;
  int built;                     /* 1: built by this open */
  int nargs[AE_NROUTINES];       /* arguments of each routine (Fortran: from the
                                    compiler; -1 absent, 0 a dummy without arguments) */
  int def_line[AE_NROUTINES];    /* line of each routine's definition (0 unknown) */
  /* Fortran: each argument's type by position as the compiler declares it
     ('i' INTEGER, 'd' DOUBLE PRECISION, 'z' COMPLEX(KIND(1.0D0)), 'r' REAL,
     'c' COMPLEX, '?' another), whether the routine ever refers to it (bit k
     of unused: argument k+1 is never used), and its name.  Checked per run
     against the routines the run calls (autoeq_check.c). */
  char argtype[AE_NROUTINES][AUTOEQ_MAX_ARGS + 1];
  unsigned long unused[AE_NROUTINES];
  char argname[AE_NROUTINES][AUTOEQ_MAX_ARGS][AUTOEQ_ARGNAME];
  void *handle;
  int runs;                      /* problems made for runs from this opening of the module */
  /* the routines, one set used */
  autoeq_f_func *f_func;
  autoeq_f_stpnt *f_stpnt;
  autoeq_f_bcnd *f_bcnd;
  autoeq_f_icnd *f_icnd;
  autoeq_f_pvls *f_pvls;
  const autoeq_c_table *c_tab;
  /* the problem of the current run */
  cable_problem pb;
  int ndim, nbc, nint, npar, nfpr0;
  int icp_tail[AUTOEQ_MAX_ICP]; int nicp;   /* the run's ICP list, 1-based */
  int icp1[AUTOEQ_MAX_ICP];                 /* scratch: 1-based ICP for a call */
  double *scratch;                          /* derivative arrays AUTO always passes */
  size_t nscratch;
  /* dat= start data: rows of t, u_1..u_ndim (t rescaled to [0,1]) */
  double *dat;
  int ndat;
  /* PVLS: header + solution block; GETP's state */
  double *pvls_block;
  size_t npvls_block;
  const struct cable_solution *pvls_sol;
  char getp_error[160];
};

/* Fills m->so and m->nargs/def_line (building when the cache lacks the
 * module).  autoeq_build.c */
int autoeq_build(cable_autoeq *m, cable_error *err);
/* AUTO's argument lists ('i' INTEGER, 'd' DOUBLE PRECISION, by position)
 * and its calls, for messages. autoeq_build.c */
extern const char *const autoeq_auto_args[AE_NROUTINES];
extern const char *const autoeq_auto_sig[AE_NROUTINES];
/* Refuses a run whose called routines AUTO itself could not run (a used
 * argument of another type or beyond AUTO's list, an output the run takes
 * that the routine does not have or never sets). autoeq_check.c */
int autoeq_check_called(const cable_autoeq *m, const cable_constants *c, cable_error *err);
/* Resolves the routines of the loaded module. autoeq_shim.c */
int autoeq_bind(cable_autoeq *m, cable_error *err);
/* Fills m->pb for the constants. autoeq_shim.c */
int autoeq_make_problem(cable_autoeq *m, const cable_constants *c, cable_error *err);
/* Reads a dat= table into m->dat. autoeq_shim.c */
int autoeq_read_dat(cable_autoeq *m, const char *path, cable_error *err);

#endif
