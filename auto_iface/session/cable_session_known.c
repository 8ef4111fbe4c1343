/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Known branch points of a session (cable_session_add_known): the BPs that
 * earlier branches computed, handed to every later run as the engine's
 * known points (cable_cont_add_known_point, continuation/cont_loop.c), so
 * that a branch reaching one ends there (it joins a known branch) instead
 * of computing that branch again. */
#include <stdio.h>
#include <stdlib.h>

#include "cable/cable_names.h"
#include "cable/cable_status.h"
#include "cable_session_impl.h"

static int add_one(cable_session *r, const rp_branch *b, int i, cable_error *err)
{
  if (r->nknown == r->capknown) {
    int cap = r->capknown ? 2 * r->capknown : 8;
    cable_solution **k = realloc(r->known, (size_t)cap * sizeof *k);
    if (!k) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "cable_session_add_known: out of memory");
    r->known = k;
    char(*nm)[64] = realloc(r->known_name, (size_t)cap * sizeof *nm);
    if (!nm) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "cable_session_add_known: out of memory");
    r->known_name = nm;
    r->capknown = cap;
  }
  const cable_solution *s = b->sol[i];
  cable_solution *c = cable_solution_clone(s);
  if (!c) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, NULL, "cable_session_add_known: out of memory");
  r->known[r->nknown] = c;
  snprintf(r->known_name[r->nknown], sizeof r->known_name[0], "BP label %d of branch %d", s->lab, s->ibr);
  r->nknown++;
  return CABLE_SUCCESS;
}

int rp_session_add_known(cable_session *r, const cable_branch *b, int sol_index, cable_error *err)
{
  if (!r || !b)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_session_add_known: %s is NULL",
                           r ? "the branch" : "the session");
  if (sol_index >= b->nsol)
    return cable_error_set(err, CABLE_ERR_RANGE, NULL, 0, NULL,
                           "cable_session_add_known: solution %d of a branch with %d", sol_index, b->nsol);
  if (sol_index >= 0) {
    if (cable_type_base(b->sol[sol_index]->itp) != CABLE_TY_BP)
      return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, NULL,
                             "cable_session_add_known: solution %d (label %d) is not a branch point", sol_index,
                             b->sol[sol_index]->lab);
    int rc = add_one(r, b, sol_index, err);
    return rc ? rc : 1;
  }
  int n = 0;
  for (int i = 0; i < b->nsol; i++) {
    if (cable_type_base(b->sol[i]->itp) != CABLE_TY_BP) continue;
    int rc = add_one(r, b, i, err);
    if (rc) return rc;
    n++;
  }
  return n;
}

int rp_session_known_to(const cable_session *r, cable_cont *cc, int ndim)
{
  for (int k = 0; k < r->nknown; k++) {
    if (r->known[k]->ndim != ndim) continue;
    int st = cable_cont_add_known_point(cc, r->known[k], r->known_name[k]);
    /* a point without the run's free parameters (another problem's) is not comparable: skipped */
    if (st && st != CABLE_ERR_INPUT) return st;
  }
  return CABLE_SUCCESS;
}

void rp_session_known_free(cable_session *r)
{
  for (int k = 0; k < r->nknown; k++) cable_solution_free(r->known[k]);
  free(r->known);
  free(r->known_name);
  r->known = NULL;
  r->known_name = NULL;
  r->nknown = r->capknown = 0;
}

int cable_session_clear_known(cable_session *s)
{
  if (!s) return CABLE_ERR_NULL;
  rp_session_known_free(s);
  return CABLE_SUCCESS;
}

int cable_session_nknown(const cable_session *s)
{
  return s ? s->nknown : 0;
}
