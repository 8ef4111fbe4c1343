/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The generic part of the problem interface: preparing a problem for a run
 * and finding its constants keys (include/cable/cable_problem.h). */
#include "cable/cable_problem.h"

#include <string.h>

#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "constants_check.h"

int cable_problem_prepare(const cable_problem *pb, const struct cable_constants *c, int from_stpnt,
                          const cable_problem **instance, cable_error *err)
{
  if (instance) *instance = NULL;
  if (!pb || !c || !instance)
    return cable_error_set(err, CABLE_ERR_NULL, NULL, 0, NULL, "cable_problem_prepare: %s is NULL",
                           !pb ? "the problem" : !c ? "the constants" : "the instance pointer");
  int rc0 = cable_constants_consistent(c, c->npar > pb->npar ? c->npar : pb->npar, err);
  if (rc0) return rc0;
  if (!pb->prepare) {
    *instance = pb;
    return CABLE_SUCCESS;
  }
  const cable_problem *inst = NULL;
  int rc = pb->prepare(pb, c, from_stpnt, &inst, err);
  if (rc == 0 && !inst)
    rc = cable_error_set(err, CABLE_ERR_CALLBACK, NULL, 0, NULL, "problem '%s': prepare gave no instance",
                         pb->name ? pb->name : "?");
  if (rc > 0)
    rc = cable_error_set(err, CABLE_ERR_CALLBACK, NULL, 0, NULL, "problem '%s': prepare returned %d",
                         pb->name ? pb->name : "?", rc);
  if (rc != 0) {
    if (inst && pb->release) pb->release(pb, inst);
    return rc;
  }
  *instance = inst;
  return CABLE_SUCCESS;
}

void cable_problem_release(const cable_problem *pb, const cable_problem *instance)
{
  if (!pb || !instance || !pb->release) return;
  pb->release(pb, instance);
}

const cable_problem_key *cable_problem_key_find(const cable_problem *pb, const char *name)
{
  if (!pb || !name || !pb->keys) return NULL;
  for (int i = 0; i < pb->nkeys; i++)
    if (pb->keys[i].name && strcmp(pb->keys[i].name, name) == 0) return &pb->keys[i];
  return NULL;
}
