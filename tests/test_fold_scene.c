/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Acceptance test of the fold scene (runs/link62fold): fold continuation
 * (ISW=2) on the braid.  The scene follows the fold of the (6,2) link's
 * mode-2 branch at T = -8.2543 in (T, Delta); this test replays its fold runs
 * (AUTO's two: the starting data at the LP, then the curve from their EP),
 * with the scene's own constants files, from the same LP computed on a
 * coarser mesh (tests/data/fold/s.link62lp: the scene's lp run with NTST = 40,
 * label 100), and checks the fold curve independently: at Delta = 0.0163 (a
 * UZ of the fold run) the ordinary one-parameter branch at fixed Delta,
 * restarted from the LP with PAR={'Delta': 0.0163}, has its own LP at the
 * same T.  Both solve the same discrete problem (same mesh, IAD = 0), so they
 * agree to the location tolerances: the UZ is located in Delta to EPSS of a
 * step (T moves by dT/dDelta ~ 200 times that), the LP to EPSS in arclength
 * (T moves quadratically there); 1e-7 relative covers both.  Then the
 * scene's coarse-mesh fold against its fine-mesh value (the scene's replay,
 * NTST = 100, doc/fold-continuation.md): the fold's T moved by 9e-7 from
 * NTST = 100 to 40, so 1e-5 relative.  About 30 s; skipped under
 * CABLE_TEST_QUICK (valgrind). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "session_util.h"
#include "test_files.h"

static const char *const files[] = {"c.link62mode", "c.link62fold", "s.link62lp", "b.foldstart", "s.foldstart",
                                    "d.foldstart", "b.fold", "s.fold", "d.fold", "b.chk", "s.chk", "d.chk"};

/* the scene's fold curve at Delta = 0.0163 (runs/link62fold replay, NTST = 100) */
#define SCENE_T_AT_0163 (-8.181832414)

static char dir[64];

static void path(const char *name, char *buf, size_t len) { snprintf(buf, len, "%s/%s", dir, name); }

static void cleanup(void)
{
  char p[128];
  for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
    path(files[i], p, sizeof p);
    remove(p);
  }
  rmdir(dir);
}

/* The first solution of type ty (AUTO's base code) of branch b, or NULL. */
static const cable_solution *first_of(const cable_branch *b, int ty)
{
  for (int i = 0; b && i < cable_branch_nsolutions(b); i++)
    if (cable_type_base(cable_branch_solution(b, i)->itp) == ty) return cable_branch_solution(b, i);
  return NULL;
}

int main(void)
{
  if (getenv("CABLE_TEST_QUICK")) {
    test_true("fold scene skipped under CABLE_TEST_QUICK", 1);
    return test_summary();
  }
  snprintf(dir, sizeof dir, "tests/tmp/foldscene.%ld", (long)getpid());
  mkdir("tests/tmp", 0777);
  mkdir(dir, 0777);
  char to[128];
  path("c.link62mode", to, sizeof to);
  int ok = copy_file("runs/link62fold/c.link62mode", to);
  path("c.link62fold", to, sizeof to);
  ok = ok && copy_file("runs/link62fold/c.link62fold", to);
  path("s.link62lp", to, sizeof to);
  ok = ok && copy_file("tests/data/fold/s.link62lp", to);
  test_true("scene constants and the LP copied into the scratch directory", ok);
  /* the scene's fold run (its c.link62fold), coarse: NTST = 40 as the LP,
     no mesh adaptation, no BP test, 8 points; then the check at fixed Delta */
  cable_error err;
  cable_error_clear(&err);
  FILE *slog;
  cable_session *r = session_open(dir, &slog);
  cable_branch *f = NULL, *c = NULL;
  /* AUTO's two runs: the starting data at the LP, then the curve from its EP */
  int rc = r ? session_line(r, "s=link62lp IRS='LP1' c=link62fold NTST=40 IAD=0 ISP=0 sv=foldstart", NULL, NULL, &err)
             : CABLE_ERR_ALLOC;
  if (!rc)
    rc = session_line(r, "s=foldstart IRS='EP1' c=link62fold NTST=40 IAD=0 ISP=0 NMX=8 NPR=100 "
                         "UZR={'Delta': [0.0163]} sv=fold", NULL, &f, &err);
  if (!rc)
    rc = session_line(r, "s=link62lp IRS='LP1' c=link62mode NTST=40 IAD=0 ISW=1 ILP=1 ISP=0 ITMX=24 "
                         "PAR={'Delta': 0.0163} DS=-0.01 DSMAX=0.2 NMX=30 STOP=['LP1'] sv=chk", NULL, &c, &err);
  char what[700];
  snprintf(what, sizeof what, "the fold run and the check run (%s)", rc ? err.msg : "ok");
  test_int(what, rc, 0);
  const cable_solution *u = first_of(f, -4), *l = first_of(c, 5);
  test_true("the fold run has a UZ and the check run an LP", u && l);
  if (u && l) {
    const cable_names *nf = cable_branch_names(f), *nc = cable_branch_names(c);
    int it = cable_names_par_index(nf, "T", NULL, 0), id = cable_names_par_index(nf, "Delta", NULL, 0);
    int jt = cable_names_par_index(nc, "T", NULL, 0), jd = cable_names_par_index(nc, "Delta", NULL, 0);
    double tuz = u->par[it], delta_uz = u->par[id], tlp = l->par[jt], delta_lp = l->par[jd];
    test_rel("the fold curve reaches the UZ at Delta = 0.0163", delta_uz, 0.0163, 1e-9);
    test_rel("the check branch runs at Delta = 0.0163", delta_lp, 0.0163, 1e-14);
    test_rel("fold curve at Delta = 0.0163 = the LP of the branch at that Delta (T)", tuz, tlp, 1e-7);
    test_rel("coarse fold at Delta = 0.0163 against the scene's (NTST = 100)", tuz, SCENE_T_AT_0163, 1e-5);
  }
  cable_branch_decref(f);
  cable_branch_decref(c);
  session_close(r, slog);
  /* AUTO's type codes in the b-files: the starting data end at their only
     label, the EP (59); the curve's restart row is unlabelled (0), its UZ -54 */
  char bf[128];
  path("b.foldstart", bf, sizeof bf);
  cable_bfile *b = cable_bfile_read(bf, &err);
  int nlab = 0, last = 0, nrow = 0;
  if (b && b->nbranch) {
    nrow = b->branch[0].nrow;
    for (int i = 0; i < nrow; i++) nlab += b->branch[0].lab[i] > 0;
    last = nrow > 0 ? b->branch[0].ty[nrow - 1] : 0;
  }
  test_int("b.foldstart: AUTO's five points of starting data", nrow, 5);
  test_true("b.foldstart: one label, the last row, TY 59", nlab == 1 && last == 59);
  cable_bfile_free(b);
  path("b.fold", bf, sizeof bf);
  b = cable_bfile_read(bf, &err);
  int nuz = 0, first = 0;
  const double *delta = b && b->nbranch ? cable_bfile_column(&b->branch[0], "Delta") : NULL;
  if (delta) {
    first = b->branch[0].ty[0];
    for (int i = 0; i < b->branch[0].nrow; i++) nuz += b->branch[0].ty[i] == -54;
  }
  test_int("b.fold: the first row is the unlabelled restart (TY 0)", first, 0);
  test_int("b.fold: one UZ row, TY -54", nuz, 1);
  test_rel("b.fold: the curve starts at the LP's Delta", delta ? delta[0] : (double)NAN, 0.016016913268, 1e-10);
  cable_bfile_free(b);
  cleanup();
  return test_summary();
}
