/* AUTO-07p constants, as the engine consumes them.  Field names follow AUTO's
 * keywords; defaults (cable_constants_init) are AUTO-07p's unless noted in
 * doc/constants.md.  Parameter indices in icp/uzr/thl are 0-based here
 * (AUTO's PAR(k) is index k-1); the constants-file parser converts. */
#ifndef CABLE_CONSTANTS_H
#define CABLE_CONSTANTS_H

#define CABLE_MAX_ICP 64
#define CABLE_MAX_UZR 128
#define CABLE_MAX_THL 64
#define CABLE_NAME_MAX 256
/* NTHREADS: at most this many; the default (NTHREADS = 0) is the number of
 * processors this process may run on, at most CABLE_THREADS_DEFAULT_MAX */
#define CABLE_THREADS_MAX 64
#define CABLE_THREADS_DEFAULT_MAX 2

typedef struct {
  int par;          /* 0-based parameter index (or -1: unused) */
  double value;
  int stop;         /* 1: UZSTOP, end the branch here */
} cable_uzr;

typedef struct {
  int index;        /* 0-based parameter index */
  double weight;
} cable_thl;

typedef struct {
  int index;        /* 0-based parameter index */
  double value;
} cable_parval;

typedef enum { CABLE_LINSOLVER_CONDENSE = 0, CABLE_LINSOLVER_KLU = 1 } cable_linsolver;

typedef struct cable_constants {
  /* problem */
  int ndim, ips, nbc, nint, npar;
  int icp[CABLE_MAX_ICP];  int nicp;      /* free + printed parameters */
  /* discretisation */
  int ntst, ncol, iad;
  /* start and switching */
  int irs;                                /* 0: STPNT; >0 label; <0: -n-th solution */
  char irs_name[16];                      /* 'BP1', 'UZ2' ... ("" when numeric) */
  int isw, isp, ilp;
  /* limits */
  int nmx, npr, iplt;
  double rl0, rl1, a0, a1;
  /* step control */
  double ds, dsmin, dsmax;
  int iads;
  /* Newton */
  double epsl, epsu, epss;
  int itmx, itnw, nwtn, jac;
  /* weights */
  cable_thl thl[CABLE_MAX_THL]; int nthl;
  double thu_default;                     /* cable: one weight for all u (AUTO THU) */
  /* user zeros */
  cable_uzr uzr[CABLE_MAX_UZR]; int nuzr;
  /* starting parameter values overriding STPNT / the restart (AUTO-07p's PAR={...}) */
  cable_parval par_override[CABLE_MAX_THL]; int npar_override;
  /* output control */
  int iid, iis;
  /* cable extensions (documented in doc/constants.md) */
  cable_linsolver linsolver;              /* LINSOLVER = condense | klu */
  int nsv;                                /* NSV: singular values tracked for BP test (0: off) */
  int nthreads;                           /* NTHREADS: threads of the structured solver's
                                             per-interval stages (0: cable_default_threads) */
  int bpsym;                              /* BPDIR: kernel vector index for 2-d kernels */
  double bpangle;                         /* BPANGLE: direction in a 2-d kernel, degrees from
                                             the canonical e1 towards e2 (NAN: use BPDIR) */
  int torus_p;                            /* TORUS: braid start, (p,2) torus knot (odd p) or
                                             link (even p); 0: the two-ring start */
  int hand;                               /* HAND: +1 right-handed, -1 left-handed */
  /* names */
  char e[CABLE_NAME_MAX], s[CABLE_NAME_MAX], sv[CABLE_NAME_MAX], dat[CABLE_NAME_MAX];
  int stop_on[8]; int nstop;              /* STOP=['BP1'...] parsed by type code and count */
  int stop_count[8];
} cable_constants;

/* AUTO-07p defaults. */
void cable_constants_init(cable_constants *c);
/* The thread count a run uses: NTHREADS, or its default when 0. */
int cable_threads(const cable_constants *c);

#endif
