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
  /* AUTO-07p's defaults (its INIT; tests/python/test_auto07p_defaults.py compares
     them with the b-file header auto-07p writes for an empty constants
     file), except NDIM = 0 ("take it from the problem") and ICP (none: a run
     must name its parameters), doc/constants.md.  IPS = 1 is AUTO's default
     (algebraic equilibria), which cable does not solve: the run refuses it. */
  c->ndim = 0; c->ips = 1; c->nbc = 0; c->nint = 0; c->npar = 36;
  c->ntst = 20; c->ncol = 4; c->iad = 3;
  c->irs = 0; c->isw = 1; c->isp = 2; c->ilp = 1;
  c->nmx = 0; c->npr = 0; c->iplt = 0;
  /* unbounded, as AUTO's -HUGE, HUGE; 1e300 rather than HUGE itself because
     the b-file header's ES12.4 rounds HUGE up to 1.7977+308, which reads
     back as an overflow */
  c->rl0 = -1e300; c->rl1 = 1e300; c->a0 = -1e300; c->a1 = 1e300;
  c->ds = 0.01; c->dsmin = 0.005; c->dsmax = 0.1; c->iads = 1;
  c->epsl = 1e-7; c->epsu = 1e-7; c->epss = 1e-5;
  c->itmx = 9; c->itnw = 5; c->nwtn = 3; c->jac = 0;
  c->thu_default = 1.0;
  c->iid = 2; c->iis = 3;
  c->linsolver = CABLE_LINSOLVER_CONDENSE;
  c->nsv = 0; c->nthreads = 0; c->bpsym = 0; c->bpangle = (double)NAN; c->branch = 0; c->predictor = 1;
  c->npkey = 0;
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
