/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The braid problems prepare themselves: the start from STPNT is built from
 * the problem's own constants keys (TORUS, HAND) and PAR={...}
 * (include/cable/cable_problem.h, prepare/release). */
#include "braid_prepare.h"

#include <stdlib.h>
#include <string.h>

#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_status.h"
#include "ribbon_track.h"

typedef struct {
  cable_problem pb;          /* first member: the pointer handed out is the owner */
  braid_start_params sp;
  cable_symmetry s0;         /* the template's S0 with multiplicity TORUS */
} braid_instance;

/* The declared S0 (braid_problems.c) with multiplicity TORUS, when the
 * constants give it: the rotations of the (p,2) torus knot or link carry a
 * symmetric branch into p copies. */
static void declare_s0(braid_instance *bi, const cable_problem *tmpl, const cable_constants *c)
{
  if (!tmpl->symmetries || tmpl->nsym != 1) return;
  bi->s0 = tmpl->symmetries[0];
  int p = (int)cable_constants_key(c, tmpl, "TORUS");
  bi->s0.multiplicity = p > 0 ? p : 0;
  bi->pb.symmetries = &bi->s0;
  bi->pb.nsym = 1;
}

static int override(const cable_constants *c, int index, double *value)
{
  for (int k = 0; k < c->npar_override; k++)
    if (c->par_override[k].index == index) {
      *value = c->par_override[k].value;
      return 1;
    }
  return 0;
}

static const cable_key_word hand_words[] = {{"right", 1}, {"left", -1}, {NULL, 0}};

const cable_problem_key braid_keys[BRAID_NKEYS] = {
  {"TORUS", CABLE_KEY_INT, 0, 1001, 0, NULL,
   "the start from STPNT: the (p,2) torus knot (odd p) or link (even p >= 2); 0: the two rings"},
  {"HAND", CABLE_KEY_INT, -1, 1, 1, hand_words, "handedness of the start: 1 or 'right', -1 or 'left'"},
};

int braid_prepare(const cable_problem *tmpl, const cable_constants *c, int from_stpnt, const cable_problem **pb,
                  cable_error *err)
{
  if (!tmpl || !c || !pb) return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "braid_prepare: NULL argument");
  const char *name = tmpl->name;
  *pb = NULL;
  if (!from_stpnt) {
    /* restarts read the stored solution: the template's callbacks with a
       start that is never built (stpnt refuses it), and PVLS's Lk tracker */
    braid_instance *bi = calloc(1, sizeof *bi);
    if (bi) braid_start_params_init(&bi->sp, BRAID_START_RINGS, 0, 1, 0.0, 0.0, 0.0);
    if (!bi || !(bi->sp.lk_track = braid_lk_track_alloc())) {
      free(bi);
      return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, "", "out of memory");
    }
    bi->pb = *tmpl;
    bi->pb.params = &bi->sp;
    declare_s0(bi, tmpl, c);
    *pb = &bi->pb;
    return CABLE_SUCCESS;
  }
  int knot = strcmp(name, "braid_knot") == 0 || strcmp(name, "braid_knot_sym") == 0;
  int link = strcmp(name, "braid_link") == 0;
  if (!knot && !link)
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, "e",
                           "'%s' has no start from STPNT: restart from a stored solution (run(sol) or IRS with s=)",
                           name);
  double delta = 0, length = 0, torque = 0;
  if (!override(c, BP_DELTA, &delta))
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "PAR",
                           "a braid start needs the strand distance: PAR={'Delta': ...}");
  int have_len = knot ? override(c, BP_LTOT, &length) : override(c, BP_L, &length);
  if (!have_len)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "PAR", "a braid %s start needs PAR={'%s': ...}",
                           knot ? "knot" : "link", knot ? "Ltot" : "L");
  override(c, BP_T, &torque);
  int p = (int)cable_constants_key(c, tmpl, "TORUS");
  int hand = (int)cable_constants_key(c, tmpl, "HAND");
  if (knot && p % 2 == 0)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "TORUS",
                           "%s starts from a (p,2) torus knot: TORUS must be odd, got %d", name, p);
  if (link && p == 0)
    return cable_error_set(err, CABLE_ERR_UNSUPPORTED, NULL, 0, "TORUS",
                           "braid_link cannot start from the two rings (TORUS=0 or no TORUS): they are a family "
                           "of exact solutions, so Newton's matrix is singular there; give TORUS=2n, a (2n,2) "
                           "torus link");
  if (link && p % 2 != 0)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "TORUS",
                           "braid_link starts from a (p,2) torus link: TORUS must be even, got %d", p);
  braid_instance *bi = calloc(1, sizeof *bi);
  if (!bi) return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, "", "out of memory");
  braid_start_params_init(&bi->sp, p > 0 ? BRAID_START_TORUS : BRAID_START_RINGS, p, hand, delta, length,
                          torque);
  override(c, BP_B1, &bi->sp.b1);
  override(c, BP_B2, &bi->sp.b2);
  override(c, BP_C1, &bi->sp.c1);
  override(c, BP_C2, &bi->sp.c2);
  override(c, BP_W01, &bi->sp.w01);
  override(c, BP_W02, &bi->sp.w02);
  int rc = braid_start_prepare(&bi->sp);
  if (rc != 0) {
    free(bi);
    return cable_error_set(err, rc, NULL, 0, "TORUS", "cannot build the starting braid (TORUS=%d, HAND=%d, Delta=%g): %s",
                           p, hand, delta, cable_status_message(rc));
  }
  rc = braid_problem_instance(name, &bi->sp, &bi->pb);
  if (rc != 0) {
    free(bi);
    return cable_error_set(err, rc, NULL, 0, "e", "unknown braid problem '%s'", name);
  }
  if (!(bi->sp.lk_track = braid_lk_track_alloc())) {
    free(bi);
    return cable_error_set(err, CABLE_ERR_ALLOC, NULL, 0, "", "out of memory");
  }
  declare_s0(bi, tmpl, c);
  *pb = &bi->pb;
  return CABLE_SUCCESS;
}

void braid_release(const cable_problem *tmpl, const cable_problem *pb)
{
  if (!pb || pb == tmpl) return;
  braid_instance *bi = (braid_instance *)(void *)pb; /* pb is the first member of the braid_instance we allocated */
  braid_lk_track_free(bi->sp.lk_track);
  free(bi);
}
