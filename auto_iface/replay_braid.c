#include "replay_braid.h"

#include "braid_resolver.h"

static int braid_find(void *ctx, const char *name, const cable_constants *c, int from_stpnt,
                      const cable_problem **pb, cable_error *err)
{
  (void)ctx;
  return braid_problem_prepare(name, c, from_stpnt, pb, err);
}

static void braid_release(void *ctx, const cable_problem *pb)
{
  (void)ctx;
  braid_problem_release(pb);
}

static const cable_replay_problems resolver = {NULL, braid_find, braid_release};

const cable_replay_problems *cable_braid_resolver(void) { return &resolver; }
