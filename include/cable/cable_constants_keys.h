/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The AUTO constants keys cable accepts: ONE line per key.  Everything else
 * comes from this table: the fields of struct cable_constants
 * (cable_constants.h), the defaults (cable_constants_init), the parser's key
 * table with its range checks (auto_iface/constants_parse.c), the Python dict
 * of a run's constants (auto_iface/pycable_constants.c), the printed layout
 * of pr() (python/cable/constants.py asks the extension for it) and the key
 * table of doc/constants.md (scripts/gen_constants_doc.py writes it,
 * tests/python/test_constants_doc.py fails when it differs).
 *
 * Adding a key: one X(...) line here, plus its use.  A new key of an existing
 * kind needs nothing else; a new kind needs its CABLE_CK_DECL_ and
 * CABLE_CK_INIT_ macros below, its reader in constants_parse.c (KIND_...) and
 * its Python value in pycable_constants.c (PY_...).
 *
 * X(KEY, field, KIND, WHO, default, lo, hi, line)
 *   KEY      the key as written in a constants file (case-sensitive, AUTO's)
 *   field    the member of cable_constants it sets
 *   KIND     how it is stored, read, checked and shown:
 *            INT     int, an integer in lo..hi (hi = CABLE_CK_BIG: no upper bound)
 *            DIM     as INT; 0 and not set means "the problem's" (NDIM, NBC, NINT:
 *                    the line that sets it is kept in origin_<field>)
 *            NPAR    as INT, read before the other keys (they may name parameters)
 *            REAL    double, any finite number
 *            POS     double, a finite number > 0
 *            STR     char[CABLE_NAME_MAX], a UTF-8 string
 *            NAME    as STR, a problem name (no '/' or blanks), read before the
 *                    other keys: it names the problem whose keys they may be
 *            and one kind per key of its own shape (IPS, ISW, STAB, DS, IRS,
 *            ICP, THL, THU, UZR, UZSTOP, STOP, PAR, NAMES, LINSOLVER, ...)
 *   WHO      who reads it: ENGINE (the continuation engine, continuation/,
 *            and the problems' prepare) or SESSION (only the session and the
 *            file writers: file names, the restart label, output settings).
 *            The struct keeps the two apart (cable_constants.h), and
 *            tests/python/test_constants_doc.py fails when a file of
 *            continuation/, equations/, bc/ or graphics/ reads a SESSION field
 *   default  the value cable_constants_init gives it (AUTO-07p's unless
 *            doc/constants.md says otherwise); 0 for kinds without one
 *   lo, hi   the accepted range of the integer kinds (INT, DIM, NPAR, IPS, ISW,
 *            STAB: the reader checks it first; else 0, 0)
 *   line     the line of the printed constants (pr(), s.c) the key is on;
 *            0: not shown */
#ifndef CABLE_CONSTANTS_KEYS_H
#define CABLE_CONSTANTS_KEYS_H

#include <limits.h>
#include <math.h>

#define CABLE_CK_BIG INT_MAX

/* clang-format off */
#define CABLE_CONSTANTS_KEYS(X)                                                                                   \
  X(e,         e,            NAME,      SESSION, 0,                        0,              0,                 1)  \
  X(s,         s,            STR,       SESSION, 0,                        0,              0,                 1)  \
  X(dat,       dat,          STR,       SESSION, 0,                        0,              0,                 1)  \
  X(sv,        sv,           STR,       SESSION, 0,                        0,              0,                 1)  \
  X(unames,    unames,       NAMES,     SESSION, 0,                        0,              0,                 2)  \
  X(parnames,  parnames,     NAMES,     SESSION, 0,                        0,              0,                 3)  \
  X(PAR,       par_override, PAR,       ENGINE,  0,                        0,              0,                 4)  \
  X(NDIM,      ndim,         DIM,       ENGINE,  0,                        1,              CABLE_CK_BIG,      5)  \
  X(IPS,       ips,          IPS,       ENGINE,  1,                        -CABLE_CK_BIG,  CABLE_CK_BIG,      5)  \
  X(IRS,       irs,          IRS,       SESSION, 0,                        0,              0,                 5)  \
  X(ILP,       ilp,          INT,       ENGINE,  1,                        0,              1,                 5)  \
  X(ICP,       icp,          ICP,       ENGINE,  0,                        0,              0,                 6)  \
  X(NTST,      ntst,         INT,       ENGINE,  20,                       1,              CABLE_CK_BIG,      7)  \
  X(NCOL,      ncol,         INT,       ENGINE,  4,                        CABLE_NCOL_MIN, CABLE_NCOL_MAX,    7)  \
  X(IAD,       iad,          INT,       ENGINE,  3,                        0,              CABLE_CK_BIG,      7)  \
  X(ISP,       isp,          INT,       ENGINE,  2,                        0,              4,                 7)  \
  X(ISW,       isw,          ISW,       ENGINE,  1,                        -CABLE_CK_BIG,  CABLE_CK_BIG,      7)  \
  X(IPLT,      iplt,         INT,       ENGINE,  0,                        -CABLE_CK_BIG,  CABLE_CK_BIG,      7)  \
  X(NBC,       nbc,          DIM,       ENGINE,  0,                        0,              CABLE_CK_BIG,      7)  \
  X(NINT,      nint,         DIM,       ENGINE,  0,                        0,              CABLE_CK_BIG,      7)  \
  X(NMX,       nmx,          INT,       ENGINE,  0,                        0,              CABLE_CK_BIG,      8)  \
  X(NPR,       npr,          INT,       ENGINE,  0,                        0,              CABLE_CK_BIG,      8)  \
  X(IID,       iid,          INT,       SESSION, 2,                        0,              5,                 8)  \
  X(ITMX,      itmx,         INT,       ENGINE,  9,                        1,              CABLE_CK_BIG,      8)  \
  X(ITNW,      itnw,         INT,       ENGINE,  5,                        1,              CABLE_CK_BIG,      8)  \
  X(NWTN,      nwtn,         INT,       ENGINE,  3,                        1,              CABLE_CK_BIG,      8)  \
  X(JAC,       jac,          INT,       ENGINE,  0,                        -1,             1,                 8)  \
  X(EPSL,      epsl,         POS,       ENGINE,  1e-7,                     0,              0,                 9)  \
  X(EPSU,      epsu,         POS,       ENGINE,  1e-7,                     0,              0,                 9)  \
  X(EPSS,      epss,         POS,       ENGINE,  1e-5,                     0,              0,                 9)  \
  X(DS,        ds,           DS,        ENGINE,  0.01,                     0,              0,                 10) \
  X(DSMIN,     dsmin,        POS,       ENGINE,  0.005,                    0,              0,                 10) \
  X(DSMAX,     dsmax,        POS,       ENGINE,  0.1,                      0,              0,                 10) \
  X(IADS,      iads,         INT,       ENGINE,  1,                        0,              CABLE_CK_BIG,      10) \
  X(NPAR,      npar,         NPAR,      ENGINE,  36,                       1,              CABLE_NAMES_MAX,   11) \
  X(LAB,       lab,          INT,       SESSION, 0,                        0,              CABLE_CK_BIG,      11) \
  X(THL,       thl,          THL,       ENGINE,  0,                        0,              0,                 11) \
  X(THU,       thu_default,  THU,       ENGINE,  1.0,                      0,              0,                 11) \
  X(IIS,       iis,          INT,       SESSION, 3,                        0,              3,                 12) \
  X(UZR,       uzr,          UZR,       ENGINE,  0,                        0,              0,                 13) \
  X(UZSTOP,    uzr,          UZSTOP,    ENGINE,  0,                        0,              0,                 14) \
  X(STOP,      stop_on,      STOP,      ENGINE,  0,                        0,              0,                 15) \
  X(RL0,       rl0,          REAL,      ENGINE,  -1e300,                   0,              0,                 16) \
  X(RL1,       rl1,          REAL,      ENGINE,  1e300,                    0,              0,                 16) \
  X(A0,        a0,           REAL,      ENGINE,  -1e300,                   0,              0,                 16) \
  X(A1,        a1,           REAL,      ENGINE,  1e300,                    0,              0,                 16) \
  X(LINSOLVER, linsolver,    LINSOLVER, ENGINE,  CABLE_LINSOLVER_CONDENSE, 0,              0,                 17) \
  X(NSV,       nsv,          INT,       ENGINE,  0,                        0,              CABLE_CK_BIG,      17) \
  X(NTHREADS,  nthreads,     INT,       ENGINE,  0,                        0,              CABLE_THREADS_MAX, 17) \
  X(BPDIR,     bpsym,        INT,       ENGINE,  0,                        0,              1,                 17) \
  X(BPANGLE,   bpangle,      REAL,      ENGINE,  NAN,                      0,              0,                 17) \
  X(BRANCH,    branch,       INT,       ENGINE,  0,                        0,              CABLE_MAX_BRANCHES, 0)  \
  X(PREDICTOR, predictor,    INT,       ENGINE,  1,                        1,              2,                 17) \
  X(STAB,      stab,         STAB,      ENGINE,  0,                        0,              1,                 0)
/* clang-format on */

/* The fields of the ENGINE rows, or of the SESSION rows (the struct's two
 * parts): X(key, field, kind, who, ...) gives the fields when who matches. */
#define CABLE_CK_ONLY_ENGINE_ENGINE(decl) decl
#define CABLE_CK_ONLY_ENGINE_SESSION(decl)
#define CABLE_CK_ONLY_SESSION_ENGINE(decl)
#define CABLE_CK_ONLY_SESSION_SESSION(decl) decl
#define CABLE_CK_ENGINE_FIELDS(key, field, kind, who, def, lo, hi, line) \
  CABLE_CK_ONLY_ENGINE_##who(CABLE_CK_DECL_##kind(field))
#define CABLE_CK_SESSION_FIELDS(key, field, kind, who, def, lo, hi, line) \
  CABLE_CK_ONLY_SESSION_##who(CABLE_CK_DECL_##kind(field))

/* The fields a kind declares in cable_constants. */
#define CABLE_CK_DECL_INT(f) int f;
#define CABLE_CK_DECL_DIM(f) int f;
#define CABLE_CK_DECL_NPAR(f) int f;
#define CABLE_CK_DECL_IPS(f) int f;
#define CABLE_CK_DECL_ISW(f) int f;
#define CABLE_CK_DECL_STAB(f) int f;
#define CABLE_CK_DECL_REAL(f) double f;
#define CABLE_CK_DECL_POS(f) double f;
#define CABLE_CK_DECL_DS(f) double f;
#define CABLE_CK_DECL_THU(f) double f; /* one weight for all u (AUTO's THU) */
#define CABLE_CK_DECL_STR(f) char f[CABLE_NAME_MAX];
#define CABLE_CK_DECL_NAME(f) char f[CABLE_NAME_MAX];
#define CABLE_CK_DECL_LINSOLVER(f) cable_linsolver f;
/* 0: STPNT; >0 label; <0: -n-th solution; f##_name: 'BP1', 'UZ2' ... ("" when numeric) */
#define CABLE_CK_DECL_IRS(f) int f; char f##_name[16];
#define CABLE_CK_DECL_ICP(f) int f[CABLE_MAX_ICP]; int n##f;   /* free + printed parameters */
#define CABLE_CK_DECL_THL(f) cable_thl f[CABLE_MAX_THL]; int n##f;
#define CABLE_CK_DECL_UZR(f) cable_uzr f[CABLE_MAX_UZR]; int n##f;
#define CABLE_CK_DECL_UZSTOP(f) /* in UZR's entries, with stop = 1 */
/* STOP=['BP1'...] by type code and count */
#define CABLE_CK_DECL_STOP(f) int f[8]; int nstop; int stop_count[8];
/* starting parameter values overriding STPNT / the restart (AUTO-07p's PAR={...}) */
#define CABLE_CK_DECL_PAR(f) cable_parval f[CABLE_MAX_THL]; int n##f;
#define CABLE_CK_DECL_NAMES(f) /* in cable_names, not in the constants */

/* The default a kind sets (after the struct is zeroed). */
#define CABLE_CK_INIT_SCALAR(c, f, def) (c)->f = (def);
#define CABLE_CK_INIT_NONE(c, f, def)
#define CABLE_CK_INIT_INT CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_DIM CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_NPAR CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_IPS CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_ISW CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_STAB CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_REAL CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_POS CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_DS CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_THU CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_LINSOLVER CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_IRS CABLE_CK_INIT_SCALAR
#define CABLE_CK_INIT_STR CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_NAME CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_ICP CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_THL CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_UZR CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_UZSTOP CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_STOP CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_PAR CABLE_CK_INIT_NONE
#define CABLE_CK_INIT_NAMES CABLE_CK_INIT_NONE

#endif
