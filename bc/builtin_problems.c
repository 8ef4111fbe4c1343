/* The built-in problems by name: the engine's test problems and the braid
 * templates (include/cable/cable_problem.h, cable_problem_builtin). */
#include <stddef.h>
#include <string.h>

#include "braid_problems.h"
#include "cable/cable_problem.h"
#include "test_problems.h"

static const struct {
  const char *name;
  const cable_problem *(*get)(void);
} tests[] = {{"bratu", cable_testproblem_bratu},
             {"bratu_int", cable_testproblem_bratu_int},
             {"elastica", cable_testproblem_elastica},
             {"elastica_int", cable_testproblem_elastica_int},
             {"layer", cable_testproblem_layer},
             {"stiff", cable_testproblem_stiff}};
static const char *const braids[] = {"braid_knot", "braid_knot_sym", "braid_link", "braid_link_sym"};

#define NTESTS ((int)(sizeof tests / sizeof tests[0]))
#define NBRAIDS ((int)(sizeof braids / sizeof braids[0]))

const cable_problem *cable_problem_builtin(const char *name)
{
  if (name == NULL) return NULL;
  for (int i = 0; i < NTESTS; i++)
    if (strcmp(name, tests[i].name) == 0) return tests[i].get();
  return braid_problem_find(name);
}

const char *cable_problem_builtin_name(int i)
{
  if (i >= 0 && i < NTESTS) return tests[i].name;
  return i >= NTESTS && i < NTESTS + NBRAIDS ? braids[i - NTESTS] : NULL;
}
