/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The consistency of a cable_constants struct filled by hand (the API
 * contract, doc/api.md): every count within its array, every parameter index
 * within the parameter slots, every string terminated.  The constants parser
 * never produces anything else; a program that fills the struct itself may. */
#ifndef CABLE_CONSTANTS_CHECK_H
#define CABLE_CONSTANTS_CHECK_H

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_problem.h"

/* 0, or CABLE_ERR_SIZE (a count beyond its array or negative, a string that
 * fills its array without a terminating NUL) or CABLE_ERR_RANGE (a parameter
 * index outside 0..npar-1, NPAR outside 0..CABLE_NAMES_MAX, NTHREADS outside
 * 0..CABLE_THREADS_MAX, an unknown LINSOLVER) with err naming the field.
 * npar: the parameter slots of the run (the larger of NPAR and the problem's;
 * at most CABLE_NAMES_MAX is used). */
int cable_constants_consistent(const cable_constants *c, int npar, cable_error *err);

/* The one wording of an integer key outside its range (the key table's lo,
 * hi; hi = CABLE_CK_BIG: no upper bound), for the parser's file:line:key
 * messages and the engine's check alike: 0 when lo <= v <= hi, else 1 with
 * "must be an integer >= lo, got v" or "... in lo..hi, got v" in msg. */
int cable_int_range_msg(long v, double lo, double hi, char *msg, size_t len);

/* The ranges of the integer keys (the table's INT, NPAR and STAB rows; DIM
 * rows may also be 0, "the problem's") of constants filled by hand, the
 * rules the parser applies to a file: 0, or CABLE_ERR_INPUT with
 * "KEY: must be an integer ..." in msg. */
int cable_constants_int_ranges(const cable_constants *c, char *msg, size_t len);

/* Where an extended problem's alloc writes its status and message when the
 * caller passed NULL for them (not wanted). */
typedef struct {
  int status;
  char msg[8];
} cable_ext_sink;

/* The common opening of an extended problem's alloc (cable_fold_alloc,
 * cable_bpcont_alloc): points a NULL *status / *msg at sink, checks that pb
 * and c are given and c is consistent for pb's parameters, and returns a
 * zeroed block of size bytes for the caller to own; NULL with **status and
 * *msg set (fn names the call) otherwise. */
void *cable_ext_alloc_open(const char *fn, const cable_problem *pb, const cable_constants *c, size_t size,
                           cable_ext_sink *sink, int **status, char **msg, size_t *len);

/* Inside an extended problem's alloc (status, msg, len and the half-built f
 * in scope): set the status and message, free f with freefn, return NULL. */
#define CABLE_EXT_FAIL(freefn, st, ...)  \
  do {                                   \
    snprintf(msg, len, __VA_ARGS__);     \
    *status = (st);                      \
    freefn(f);                           \
    return NULL;                         \
  } while (0)

/* out = c with the user's ICP in AUTO's order for ISW = 2, [p1, ..., pk, q,
 * printed...], turned into the extended problems' internal order [p1, q,
 * p2, ..., pk, printed...] (the engine converges a start at fixed ICP(2),
 * cont_engine.c's start_fixpar).  k = 1: the same. */
void cable_ext_icp_order(const cable_constants *c, int k, cable_constants *out);

#endif
