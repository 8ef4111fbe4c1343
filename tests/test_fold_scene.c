/* Acceptance test of the fold scene (runs/link62fold): fold continuation
 * (ISW=2) on the braid.  The scene follows the fold of the (6,2) link's
 * mode-2 branch at T = -8.2543 in (T, Delta); this test replays its fold run,
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
#include "script_host_cable.h"
#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "script.h"
#include "script_host_cable.h"
#include "test_files.h"

static const char *const files[] = {"c.link62mode", "c.link62fold", "s.link62lp",
                                    "b.fold", "s.fold", "d.fold", "b.chk", "s.chk", "d.chk"};

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

static int replay(const char *text, char **log, cable_error *err)
{
  size_t len;
  FILE *f = open_memstream(log, &len);
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = dir;
  o.log = f;
  cable_replay *r = cable_replay_alloc(&o);
  int rc = r ? script_run_string("t.auto", text, cable_replay_host(r), err) : CABLE_ERR_ALLOC;
  cable_replay_free(r);
  fclose(f);
  return rc;
}

/* the number after the k-th occurrence of prefix in the log, NAN if none */
static double after(const char *log, const char *prefix, int k)
{
  const char *p = log;
  while (p && (p = strstr(p, prefix)) != NULL) {
    if (k-- == 0) return strtod(p + strlen(prefix), NULL);
    p += strlen(prefix);
  }
  return (double)NAN;
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
  const char *text =
      "f = run(s='link62lp', IRS='LP1', c='link62fold', NTST=40, IAD=0, ISP=0, NMX=8, NPR=100,\n"
      "        UZR={'Delta': [0.0163]}, sv='fold')\n"
      "u = f('UZ1')\n"
      "print('uz T= %.15g Delta= %.15g' % (u['T'], u['Delta']))\n"
      "c = run(s='link62lp', IRS='LP1', c='link62mode', NTST=40, IAD=0, ISW=1, ILP=1, ISP=0, ITMX=24,\n"
      "        PAR={'Delta': 0.0163}, DS=-0.01, DSMAX=0.2, NMX=30, STOP=['LP1'], sv='chk')\n"
      "l = c('LP1')\n"
      "print('lp T= %.15g Delta= %.15g' % (l['T'], l['Delta']))\n";
  char *log = NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = replay(text, &log, &err);
  char what[700];
  snprintf(what, sizeof what, "the fold run and the check run replay (%s)", rc ? err.msg : "ok");
  test_int(what, rc, 0);
  if (log) {
    double tuz = after(log, "uz T= ", 0);
    const char *u = strstr(log, "uz T= ");
    double delta_uz = u ? after(u, "Delta= ", 0) : (double)NAN;
    test_rel("the fold curve reaches the UZ at Delta = 0.0163", delta_uz, 0.0163, 1e-9);
    double tlp = after(log, "lp T= ", 0);
    const char *l = strstr(log, "lp T= ");
    double delta_lp = l ? after(l, "Delta= ", 0) : (double)NAN;
    test_rel("the check branch runs at Delta = 0.0163", delta_lp, 0.0163, 1e-14);
    test_rel("fold curve at Delta = 0.0163 = the LP of the branch at that Delta (T)", tuz, tlp, 1e-7);
    test_rel("coarse fold at Delta = 0.0163 against the scene's (NTST = 100)", tuz, SCENE_T_AT_0163, 1e-5);
  }
  /* AUTO's type codes in the b-file: 59 for the start, -54 for the UZ */
  char bf[128];
  path("b.fold", bf, sizeof bf);
  cable_bfile *b = cable_bfile_read(bf, &err);
  int nuz = 0, first = 0;
  const double *delta = b && b->nbranch ? cable_bfile_column(&b->branch[0], "Delta") : NULL;
  if (delta) {
    first = b->branch[0].ty[0];
    for (int i = 0; i < b->branch[0].nrow; i++) nuz += b->branch[0].ty[i] == -54;
  }
  test_int("b.fold: the first row is AUTO's EP of a BVP fold curve (TY 59)", first, 59);
  test_int("b.fold: one UZ row, TY -54", nuz, 1);
  test_rel("b.fold: the curve starts at the LP's Delta", delta ? delta[0] : (double)NAN, 0.016016913268, 1e-10);
  cable_bfile_free(b);
  free(log);
  cleanup();
  return test_summary();
}
