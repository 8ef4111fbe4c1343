#include "braid_resolver.h"

#include <stdlib.h>
#include <string.h>

#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_status.h"

typedef struct {
  cable_problem pb;          /* first member: the pointer handed out is the owner */
  braid_start_params sp;
} braid_instance;

static int override(const cable_constants *c, int index, double *value)
{
  for (int k = 0; k < c->npar_override; k++)
    if (c->par_override[k].index == index) {
      *value = c->par_override[k].value;
      return 1;
    }
  return 0;
}

int braid_problem_prepare(const char *name, const cable_constants *c, int from_stpnt, const cable_problem **pb,
                          cable_error *err)
{
  int knot = strcmp(name, "braid_knot") == 0 || strcmp(name, "braid_knot_sym") == 0;
  int link = strcmp(name, "braid_link") == 0;
  if ((!knot && !link) || !c || !from_stpnt) return CABLE_ERR_NOTFOUND;
  double delta = 0, length = 0, torque = 0;
  if (!override(c, BP_DELTA, &delta))
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "PAR",
                           "a braid start needs the strand distance: PAR={'Delta': ...}");
  int have_len = knot ? override(c, BP_LTOT, &length) : override(c, BP_L, &length);
  if (!have_len)
    return cable_error_set(err, CABLE_ERR_INPUT, NULL, 0, "PAR", "a braid %s start needs PAR={'%s': ...}",
                           knot ? "knot" : "link", knot ? "Ltot" : "L");
  override(c, BP_T, &torque);
  int p = c->torus_p;
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
  braid_start_params_init(&bi->sp, p > 0 ? BRAID_START_TORUS : BRAID_START_RINGS, p, c->hand, delta, length,
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
                           p, c->hand, delta, cable_status_message(rc));
  }
  rc = braid_problem_instance(name, &bi->sp, &bi->pb);
  if (rc != 0) {
    free(bi);
    return cable_error_set(err, rc, NULL, 0, "e", "unknown braid problem '%s'", name);
  }
  *pb = &bi->pb;
  return CABLE_SUCCESS;
}

void braid_problem_release(const cable_problem *pb)
{
  free((void *)pb); /* pb is the first member of the braid_instance we allocated */
}
