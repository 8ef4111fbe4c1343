/* The braid problems started from STPNT (bc/braid_resolver.h) as a problem
 * source of the script host (cable_replay_options.problems). */
#ifndef CABLE_REPLAY_BRAID_H
#define CABLE_REPLAY_BRAID_H

#include "script_host_cable.h"

/* A resolver object for cable_replay_options.problems (no state of its own:
 * each problem it hands out owns its prepared starting parameters). */
const cable_replay_problems *cable_braid_resolver(void);

#endif
