/* Braid problems started from STPNT for the run host: the starting geometry
 * comes from the constants: TORUS=p ((p,2) torus knot for odd p, link for even
 * p >= 2; the two-ring start is refused: it is degenerate), HAND=1|-1, and PAR={...} values of
 * Delta, Ltot (knots) or L (links), T and the material constants. */
#ifndef CABLE_BRAID_RESOLVER_H
#define CABLE_BRAID_RESOLVER_H

#include "cable_session.h"

/* A resolver object for cable_session_options.problems (no state of its own:
 * each problem it hands out owns its prepared starting parameters). */
const cable_session_problems *cable_braid_resolver(void);

#endif
