/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Foundation checks: status table, solution alloc/copy, error formatting. */
#include <string.h>

#include "cable/cable_error.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"
#include "harness.h"

int main(void)
{
  test_true("status message for CABLE_ERR_DSMIN",
            strcmp(cable_status_message(CABLE_ERR_DSMIN), "no convergence with step size DSMIN") == 0);
  test_true("unknown status has a message", strcmp(cable_status_message(12345), "unknown status") == 0);

  cable_solution *s = cable_solution_alloc(3, 5, 4, 36, 2);
  test_true("solution alloc", s != NULL);
  test_int("solution points", cable_solution_npts(s), 21);
  s->u[20 * 3 + 2] = 7.5;
  s->par[35] = -1.25;
  cable_solution *c = cable_solution_clone(s);
  test_true("clone", c != NULL);
  test_abs("clone keeps last u", c->u[20 * 3 + 2], 7.5, 0);
  test_abs("clone keeps last par", c->par[35], -1.25, 0);
  cable_solution *d = cable_solution_alloc(3, 6, 4, 36, 2);
  test_int("copy refuses other sizes (CABLE_ERR_SIZE, not an allocation error)", cable_solution_copy(d, s), CABLE_ERR_SIZE);
  cable_solution_free(d);
  cable_solution_free(c);
  cable_solution_free(s);
  cable_solution_free(NULL);
  test_true("bad sizes give NULL", cable_solution_alloc(0, 5, 4, 36, 1) == NULL);

  cable_error e;
  char buf[1024];
  cable_error_clear(&e);
  cable_error_set(&e, CABLE_ERR_PARSE, "c.x", 12, "NTST", "must be a positive integer, got '%s'", "-5");
  test_true("error format",
            strcmp(cable_error_format(&e, buf, sizeof buf), "c.x:12: NTST: must be a positive integer, got '-5'") == 0);
  return test_summary();
}
