/* SPDX-License-Identifier: GPL-3.0-or-later */
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

/* The settings of the scenes in runs/ (c.knot72, c.knot72sym, c.link62,
 * c.link62mode): the flat branches' (from STPNT, double branch points found
 * by the singular-value test NSV=2) and the symmetric formulations' (switched
 * at a branch point, ISW=-1).  Measured (doc/scripts.md): DS, DSMAX and NTST,
 * NCOL are what make a keywords-only flat branch as fast as the scene's.
 * IPS=4: they are boundary-value problems (a run that leaves IPS at AUTO's
 * default 1 is refused, cable_session.c). */
static const struct {
  const char *name, *text;
} recommended[] = {
  {"braid_knot", "IPS=4, ICP=['T', 'L', 'L2', 'eps21', 'F', 'h', 'Ham'], NTST=30, NCOL=7, IAD=3, JAC=1, ISP=2, ILP=0, "
                 "NSV=2, DS=5.0, DSMIN=1e-6, DSMAX=20.0, EPSL=1e-7, EPSU=1e-7, EPSS=1e-7"},
  {"braid_knot_sym", "IPS=4, ICP=['T', 'L', 'L2', 'eps21', 'eps13', 'F', 'h', 'Ham'], NTST=30, NCOL=7, IAD=3, JAC=1, "
                     "ISW=-1, ISP=0, ILP=0, DS=0.05, DSMIN=1e-6, DSMAX=10.0, PREDICTOR=2, EPSL=1e-7, EPSU=1e-7, "
                     "EPSS=1e-7"},
  {"braid_link", "IPS=4, ICP=['T', 'F', 'h', 'Ham', 'Phi', 'Lk', 'pmin', 'dmin'], NTST=100, NCOL=4, IAD=3, JAC=1, ISP=2, "
                 "ILP=0, NSV=2, DS=1.0, DSMIN=1e-6, DSMAX=1.0, EPSL=1e-7, EPSU=1e-7, EPSS=1e-7"},
  {"braid_link_sym", "IPS=4, ICP=['T', 'eps13', 'F', 'h', 'Ham', 'Phi', 'Lk', 'pmin', 'dmin'], NTST=100, NCOL=4, IAD=3, "
                     "JAC=1, ISW=-1, ISP=0, ILP=0, DS=0.05, DSMIN=1e-6, DSMAX=2.0, EPSL=1e-7, EPSU=1e-7, EPSS=1e-7"},
};

const char *cable_problem_recommended(const char *name)
{
  if (name == NULL) return NULL;
  for (size_t i = 0; i < sizeof recommended / sizeof recommended[0]; i++)
    if (strcmp(name, recommended[i].name) == 0) return recommended[i].text;
  return NULL;
}
