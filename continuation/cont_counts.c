/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Work counters: printed (one line on stderr) when CABLE_COUNTS is set in the
 * environment, for scripts/bench and doc/benchmarks.md.  Counts, unlike
 * times, do not depend on the machine's load. */
#include <stdio.h>
#include <stdlib.h>

#include "cont_impl.h"

void cont_counts_report(const cable_cont *cc)
{
  if (!getenv("CABLE_COUNTS")) return;
  const cont_counts *k = &cc->cnt;
  fprintf(stderr,
          "cable counts: steps %ld correct %ld newton_iters %ld newton_fact %ld tan_fact %ld sv_calls %ld "
          "sv_iters %ld dips %ld dip_evals %ld locates %ld locate_evals %ld pencil_run %ld pencil_skipped %ld\n",
          k->steps, k->correct, k->newton_iters, k->newton_fact, k->tan_fact, k->sv_calls, k->sv_iters, k->dips,
          k->dip_evals, k->locates, k->locate_evals, cc->gate_run, cc->gate_skipped);
}
