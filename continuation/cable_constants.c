/* SPDX-License-Identifier: GPL-3.0-or-later */
#define _GNU_SOURCE 1 /* sched_getaffinity, CPU_COUNT */
#include "cable/cable_constants.h"
#include "cable/cable_status.h"

#include <sched.h>
#include <unistd.h>

#include <math.h>
#include <string.h>

void cable_constants_init(cable_constants *c)
{
  if (!c) return;
  memset(c, 0, sizeof *c);
  /* The default column of cable/cable_constants_keys.h: AUTO-07p's defaults
     (its INIT; tests/python/test_auto07p_defaults.py compares them with the
     b-file header auto-07p writes for an empty constants file), except
     NDIM = 0 ("take it from the problem") and ICP (none: a run must name its
     parameters), doc/constants.md.  IPS = 1 is AUTO's default
     (algebraic equilibria), which cable does not solve: the run refuses it. */
#define CABLE_CK_DEFAULT(key, field, kind, who, def, lo, hi, line) CABLE_CK_INIT_##kind(c, field, def)
  CABLE_CONSTANTS_KEYS(CABLE_CK_DEFAULT)
#undef CABLE_CK_DEFAULT
}

double cable_constants_key(const cable_constants *c, const cable_problem *pb, const char *name)
{
  const cable_problem_key *k = cable_problem_key_find(pb, name);
  if (!c || !k) return (double)NAN;
  for (int i = 0; i < c->npkey && i < CABLE_MAX_PKEYS; i++)
    if (strcmp(c->pkey[i].name, name) == 0) return c->pkey[i].value;
  return k->def;
}

int cable_threads(const cable_constants *c)
{
  if (!c) return CABLE_ERR_NULL;
  if (c->nthreads > 0) return c->nthreads;
  /* the processors this process may run on (taskset, cgroup cpusets), not
     the machine's: more threads than that only wait for each other */
  long np = 0;
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) np = CPU_COUNT(&set);
  if (np < 1) np = sysconf(_SC_NPROCESSORS_ONLN);
  if (np < 1) np = 1;
  return np < CABLE_THREADS_MAX ? (int)np : CABLE_THREADS_MAX;
}
