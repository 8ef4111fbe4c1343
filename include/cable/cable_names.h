/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Names used in AUTO-07p files: parameter and solution-component names
 * (the `parnames` and `unames` of a constants file) and the two-letter point
 * type names (BP, LP, UZ, EP, MX, RG) that label specs such as 'BP1' use.
 *
 * Indices are 0-based (name of AUTO's PAR(k) is par[k-1]).  The table is a
 * plain struct of fixed-size strings, so it needs no allocation and can be
 * copied with `=`. */
#ifndef CABLE_NAMES_H
#define CABLE_NAMES_H

#include "cable/cable_api.h"

#define CABLE_NAMES_MAX 256   /* parameter / component slots that can be named */
#define CABLE_NAME_LEN 32     /* bytes per name incl. NUL (AUTO allows 13 chars) */

typedef struct cable_names {
  char par[CABLE_NAMES_MAX][CABLE_NAME_LEN];  /* par[k]: name of PAR(k+1), "" unnamed */
  char u[CABLE_NAMES_MAX][CABLE_NAME_LEN];    /* u[i]: name of U(i+1), "" unnamed */
} cable_names;

CABLE_API void cable_names_init(cable_names *n);

/* 0-based index of parameter `name`: the table's own names first (they come
 * from the constants file and win), then the problem's table
 * (parnames[0..npar-1], NULL entries allowed; parnames may be NULL).
 * -1 when the name is unknown. */
CABLE_API int cable_names_par_index(const cable_names *n, const char *name,
                          const char *const *parnames, int npar);
/* 0-based index of solution component `name` (the table's unames), or -1. */
CABLE_API int cable_names_u_index(const cable_names *n, const char *name);

/* Fill the slots the table leaves unnamed from a problem's parnames/unames
 * (either may be NULL); a problem name already used at another slot is
 * skipped so that lookups stay unambiguous. */
CABLE_API void cable_names_fill(cable_names *n, const char *const *parnames, int npar,
                      const char *const *unames, int ndim);

/* Point types.  cable_type_name(6) == "BP"; 0 gives ""; regular output
 * points (4) give "RG".  Only the last decimal digit of itp counts, as in
 * AUTO (+-10*k encodes the branch type). */
CABLE_API const char *cable_type_name(int itp);
/* Type code of a two-letter name ("BP" -> 6); 0 when unknown. */
CABLE_API int cable_type_code(const char *name);
/* AUTO's reduction of a type code to its base type (26 -> 6, -14 -> -4). */
CABLE_API int cable_type_base(int itp);

/* Parse a label spec "BP1", "UZ12": *type = 6, *nth = 1.  Returns 0 on
 * success, -1 when spec is not TYPE followed by a positive integer. */
CABLE_API int cable_label_spec_parse(const char *spec, int *type, int *nth);

#endif
