/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO-07p output files: b.NAME (bifurcation diagram, AUTO's fort.7),
 * s.NAME (labelled solutions, fort.8), d.NAME (diagnostics, fort.9), plus a
 * CSV table per branch, written in AUTO-07p's layout so that AUTO's Python
 * tools (parseB, parseS, plotting) read them unchanged; and readers for
 * s- and b-files (ours and AUTO's).  The formats, column by column, and
 * where cable differs from AUTO: doc/output-formats.md.
 *
 * Writing: open a writer, hand its sink to the engine, close it.
 *   cable_aufile *w = cable_aufile_open("runs/knot", "knot", &c, &names, NULL, &err);
 *   cable_sink sink = cable_aufile_sink(w);
 *   cable_cont_run(cc, &sink, ...);
 *   cable_aufile_close(w, &err);     // renames the files into place
 * All files are written atomically (continuation/base/atomic_file.h): nothing
 * appears under the final names before close or a checkpoint. */
#ifndef CABLE_AUFILE_H
#define CABLE_AUFILE_H

#include "cable/cable_api.h"

#include <stdio.h>

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_output.h"
#include "cable/cable_solution.h"
#include "cable/cable_names.h"

/* ---------------------------------------------------------------- writer */

typedef struct cable_aufile_options {
  int append;      /* 1: add the new branches to existing b./s./d. files (AUTO's
                      `ap`, a merged run); 0: replace them (AUTO's `sv`) */
  int write_csv;   /* 1: also b.NAME.<k>.csv for the k-th branch section */
  int err_par;     /* 0-based PAR slot that receives cable_solution.err_est in
                      the s-file (and is read back by cable_sfile_take_err_est);
                      -1: none.  Default: the slot named "err" if any. */
} cable_aufile_options;

/* Defaults: replace, CSV on, err_par from the name "err" (-2 = "look it up"). */
CABLE_API void cable_aufile_options_init(cable_aufile_options *o);

typedef struct cable_aufile cable_aufile;

/* Open b.NAME, s.NAME, d.NAME in directory dir ("" or NULL: current).
 * c: the run's constants (headers, IIS, IPLT), with NDIM, NBC and NINT
 * filled from the problem (cable_constants_take_problem_dims): the header's
 * free-parameter count is NBC+NINT-NDIM+1 as in AUTO; names: the
 * parameter/component names for column headings (may be NULL; fill it from
 * the problem with cable_names_fill first).  opt NULL: defaults. */
CABLE_API cable_aufile *cable_aufile_open(const char *dir, const char *name, const cable_constants *c,
                                const cable_names *names, const cable_aufile_options *opt,
                                cable_error *err);

/* Constants for the branches written from now on (a script's next run). */
CABLE_API void cable_aufile_set_constants(cable_aufile *w, const cable_constants *c);

/* The sink the engine writes to (cable/cable_output.h).  Its
 * callbacks return 0, or a negative status when writing failed; the error is
 * kept and reported again by cable_aufile_close. */
CABLE_API cable_sink cable_aufile_sink(cable_aufile *w);

/* Largest label and branch number in the s-file so far (including what an
 * append found on disk): a new run starts at label last_label+1. */
CABLE_API int cable_aufile_last_label(const cable_aufile *w);
CABLE_API int cable_aufile_last_branch(const cable_aufile *w);

/* Publish complete copies of the files as written so far. */
CABLE_API int cable_aufile_checkpoint(cable_aufile *w, cable_error *err);

/* Commit every file (s first, then b, d and the CSVs) and free w.  When a
 * callback failed, or a label has a b-file row but no s-file solution or the
 * other way round, nothing is published (every file keeps its previous
 * contents) and the error is returned.  A rename that fails stops the files
 * after it. */
CABLE_API int cable_aufile_close(cable_aufile *w, cable_error *err);

/* Discard the run's output (files keep their previous contents); frees w.
 * NULL is a no-op. */
CABLE_API void cable_aufile_abort(cable_aufile *w);

/* Fortran ESw.dEe: x in scientific form with `digits` digits after the point
 * and at least `expdigits` exponent digits, right-justified in `width`
 * characters (ES19.10E3: "   1.2345678901E-003").  buf must hold width+8. */
CABLE_API char *cable_aufile_format_es(char *buf, double x, int width, int digits, int expdigits);

/* ---------------------------------------------------------------- readers */

/* Parse one number as AUTO and Fortran write it: 1.5E+003, 1.5E+03, 1.5D+03,
 * 1.5+103 (Fortran's form for three-digit exponents).  0 or -1. */
CABLE_API int cable_aufile_parse_double(const char *tok, double *out);

typedef struct cable_sfile cable_sfile;

/* Read every solution of an s-file (cable's or AUTO-07p's, IPS=4 style:
 * NTST > 0).  A truncated or malformed file gives NULL and an error naming
 * the file and line. */
CABLE_API cable_sfile *cable_sfile_read(const char *path, cable_error *err);
CABLE_API void cable_sfile_free(cable_sfile *s);          /* NULL is a no-op */

CABLE_API int cable_sfile_count(const cable_sfile *s);
/* i-th solution in file order (0-based), NULL when out of range. */
CABLE_API const cable_solution *cable_sfile_get(const cable_sfile *s, int i);
/* Solution with label lab, NULL when absent. */
CABLE_API const cable_solution *cable_sfile_find_label(const cable_sfile *s, int lab);
/* AUTO's lookups: "12" (label 12), "-3" (third solution in the file),
 * "BP1", "UZ2" (n-th solution of that type).  NULL and an error when absent
 * or when the spec is malformed. */
CABLE_API const cable_solution *cable_sfile_find(const cable_sfile *s, const char *spec, cable_error *err);
/* Resolve c->irs / c->irs_name (IRS='BP1' or IRS=-n) to a label number:
 * on success c->irs is the label and c->irs_name is "". */
CABLE_API int cable_sfile_resolve_irs(const cable_sfile *s, cable_constants *c, cable_error *err);
/* Set every solution's err_est from PAR slot err_par (0-based). */
CABLE_API void cable_sfile_take_err_est(cable_sfile *s, int err_par);

/* One section of a b-file: a header block and the rows after it. */
typedef struct cable_bfile_branch {
  int ncol;            /* value columns after BR PT TY LAB */
  char **colname;      /* [ncol] trimmed column headings ("T", "L2-NORM", "MAX U(1)") */
  int nrow;
  int *br, *pt, *ty, *lab;   /* [nrow] */
  double *data;        /* column-major: column j is data + j*nrow */
  int first_line;      /* line of the section's first row in the file */
  int stab;            /* 1: its header says STAB = 1, so PT < 0 marks a stable point and
                          PT > 0 an unstable one (doc/stability.md) */
} cable_bfile_branch;

typedef struct cable_bfile {
  int nbranch;
  cable_bfile_branch *branch;
} cable_bfile;

CABLE_API cable_bfile *cable_bfile_read(const char *path, cable_error *err);
CABLE_API void cable_bfile_free(cable_bfile *b);          /* NULL is a no-op */
/* Column by heading ("L2-NORM", "T", "PAR(3)"), NULL when absent. */
CABLE_API const double *cable_bfile_column(const cable_bfile_branch *br, const char *name);

#endif
