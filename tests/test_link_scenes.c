/* Acceptance tests of the link scenes runs/link62, runs/link43, runs/link102:
 * the path to each scene's branch point, replayed with the scene's constants
 * files on a coarser mesh (NTST 50-60 instead of 100) and without the costly
 * Lk/dmin columns, with each scene's own selection (kind and T window, the
 * lines of runs/NAME/NAME.auto), checking what the scene relies on:
 *   - the flat branch's branch points, each of the kind the scene's comments
 *     and doc/links.md give, at T within 1e-3 of the NTST-100 values (the
 *     coarser mesh moves them by up to 5e-5; the location is exact to
 *     EPSS * DS = 5e-7 of arclength, or to the bracket it reports when the
 *     corrector does not converge inside it: up to 1.4e-3 of arclength at
 *     NTST 50, which moves T by less than 1e-3 on these branches);
 *   - exactly one BP in the scene's window of the scene's kind;
 *   - the switch there, and at link62's double BP at T = 23.57, treats the
 *     kernel as the detector found it (double: two-dimensional).
 * These are also the regression tests of the BP location fixes (cont_special.c):
 *   - link62 at DSMAX = 5: the simple BP at T = 29.81, 0.12 before a double
 *     one, was not located (only the double one was labelled); the simple BP
 *     at 17.55 was missed by the location and found by the dip test;
 *   - link102: the simple BPs at T = 30.77 and 35.75 were not located ("could
 *     not locate the branch point within ITMX=9 iterations") because the
 *     corrector does not converge within about 1e-6 of a BP;
 *   - the double BP at T = 23.57 was switched as simple (sigma1 <= 0.1 sigma2
 *     was tested first).
 * The mode branches themselves (hundreds of steps each) are left to
 * make scenes; CABLE_TEST_QUICK skips the replays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "scene_util.h"

typedef struct expected_bp {
  double t;
  const char *kind;
} expected_bp;

/* Replays text, then checks the printed lines 'bp KIND T' against want[]
 * (in order) and 'pick N T' for the selection; returns the log. */
static char *check_flat(const char *name, const char *scene, const char *const *files, const char *text,
                        const expected_bp *want, int nwant, double pick_t)
{
  scene_scratch sc;
  char buf[1400], *log = NULL;
  cable_error err;
  int ok = scene_scratch_make(&sc, name, scene, files);
  snprintf(buf, sizeof buf, "%s: scene constants copied to a scratch directory", name);
  test_true(buf, ok);
  if (!ok) {
    scene_scratch_remove(&sc);
    return NULL;
  }
  int rc = scene_replay(&sc, NULL, text, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  snprintf(buf, sizeof buf, "%s: the path to the scene's branch point replays", name);
  test_int(buf, rc, 0);
  if (log && (rc || getenv("CABLE_TEST_VERBOSE"))) fputs(log, stdout);
  int n = 0;
  for (; scene_log_line(log, "bp ", n); n++) {}
  snprintf(buf, sizeof buf, "%s: %d branch points on the flat branch", name, nwant);
  test_int(buf, n, nwant);
  for (int i = 0; i < nwant; i++) {
    char kind[16] = "";
    double t = NAN;
    const char *l = scene_log_line(log, "bp ", i);
    if (l) sscanf(l, "%15s %lf", kind, &t);
    snprintf(buf, sizeof buf, "%s: BP%d at T = %.2f", name, i + 1, want[i].t);
    test_abs(buf, t, want[i].t, 1e-3);
    snprintf(buf, sizeof buf, "%s: BP%d is %s (got '%s')", name, i + 1, want[i].kind, kind);
    test_true(buf, strcmp(kind, want[i].kind) == 0);
  }
  int npick = -1;
  double t = NAN;
  const char *l = scene_log_line(log, "pick ", 0);
  if (l) sscanf(l, "%d %lf", &npick, &t);
  snprintf(buf, sizeof buf, "%s: the scene's selection finds exactly one branch point", name);
  test_int(buf, npick, 1);
  snprintf(buf, sizeof buf, "%s: and it is the one at T = %.4f", name, pick_t);
  test_abs(buf, t, pick_t, 1e-3);
  scene_scratch_remove(&sc);
  return log;
}

/* The scene's selection loop, as in runs/NAME/NAME.auto, printing every BP
 * and the pick. */
#define SELECT(COND)                                                                                      \
  "n = 0\n"                                                                                               \
  "t = 0.0\n"                                                                                             \
  "for b in flat('BP'):\n"                                                                                \
  "    print('bp %s %.10f' % (b['kind'], b['T']))\n"                                                      \
  "    if " COND ":\n"                                                                                    \
  "        bp = b\n"                                                                                      \
  "        t = b['T']\n"                                                                                  \
  "        n = n + 1\n"                                                                                   \
  "print('pick %d %.10f' % (n, t))\n"

static void test_link62(void)
{
  static const char *const files[] = {"c.link62", "c.link62mode", NULL};
  /* DSMAX = 5, the value that used to lose the simple BP at 29.81 */
  static const char text[] =
      "flat = run(e='braid_link', c='link62', NTST=50, DSMAX=5.0, ICP=['T', 'F', 'h', 'Ham', 'Phi'],"
      " UZSTOP={'T': 30.5}, sv='flat')\n" SELECT("b['kind'] == 'simple' and b['T'] > 29.0 and b['T'] < 30.5")
      "for b in flat('BP'):\n"
      "    if b['kind'] == 'double' and b['T'] > 23.0 and b['T'] < 24.0:\n"
      "        d = run(b, e='braid_link', c='link62mode', NTST=50, ICP=['T', 'F', 'h', 'Ham', 'Phi'], NMX=2)\n"
      "m = run(bp, e='braid_link', c='link62mode', NTST=50, ICP=['T', 'F', 'h', 'Ham', 'Phi'], NMX=2)\n";
  /* doc/links.md (NTST 100): 10.0783 double, 17.5496 simple, 23.5720 double,
     29.8077 simple, 29.93 double; at DSMAX = 5 the last is found by the dip
     test right after the located simple one, whose sigma_1 makes the dip's
     neighbour vanish: it counts as a pair (two simple BPs in the step) */
  static const expected_bp want[] = {
      {10.0783, "double"}, {17.5496, "simple"}, {23.5720, "double"}, {29.8077, "simple"}, {29.9320, "pair"}};
  char *log = check_flat("link62", "link62", files, text, want, 5, 29.8077);
  const char *a = scene_log_find(log, "PT     1: switching at a double branch point");
  test_true("link62: the double BP at T = 23.57 is switched as a double one", a != NULL);
  const char *b = a ? strstr(a + 1, "PT     1: switching at a simple branch point") : NULL;
  test_true("link62: the scene's simple BP at T = 29.81 is switched as a simple one", b != NULL);
  free(log);
}

static void test_link43(void)
{
  static const char *const files[] = {"c.link43", "c.link43sym", NULL};
  static const char text[] =
      "flat = run(e='braid_link', c='link43', NTST=50, ICP=['T', 'F', 'h', 'Ham', 'Phi'], UZSTOP={'T': 25.0},"
      " sv='flat')\n" SELECT("b['kind'] == 'double' and b['T'] > 23.5 and b['T'] < 25.0")
      "m = run(bp, e='braid_link_sym', c='link43sym', NTST=50, ICP=['T', 'eps13', 'F', 'h', 'Ham', 'Phi'], NMX=2)\n";
  /* doc/links.md and issue 16 (NTST 100): 10.7748 double, 17.74 and 20.6796
     simple (the split 3-fold mode), 24.2269 double */
  static const expected_bp want[] = {{10.7748, "double"}, {17.74, "simple"}, {20.6796, "simple"}, {24.2269, "double"}};
  char *log = check_flat("link43", "link43", files, text, want, 4, 24.2269);
  test_true("link43: the double BP of braid_link is simple in braid_link_sym (the switch)",
            scene_log_find(log, "PT     1: switching at a simple branch point") != NULL);
  free(log);
}

static void test_link102(void)
{
  static const char *const files[] = {"c.link102", "c.link102mode", NULL};
  static const char text[] =
      "flat = run(e='braid_link', c='link102', NTST=60, ICP=['T', 'F', 'h', 'Ham', 'Phi'], UZSTOP={'T': 36.5},"
      " sv='flat')\n" SELECT("b['kind'] == 'simple' and b['T'] > 35.0 and b['T'] < 36.5")
      "m = run(bp, e='braid_link', c='link102mode', NTST=60, ICP=['T', 'F', 'h', 'Ham', 'Phi'], NMX=2)\n";
  /* issue 16 and doc/links.md (NTST 100): 10.8232, 17.7119, 24.2749 double
     (modes 1-3), 30.7654 and 35.7497 simple (the split 5-fold mode) */
  static const expected_bp want[] = {
      {10.8232, "double"}, {17.7119, "double"}, {24.2749, "double"}, {30.7654, "simple"}, {35.7497, "simple"}};
  char *log = check_flat("link102", "link102", files, text, want, 5, 35.7497);
  test_true("link102: the scene's BP is switched as a simple one",
            scene_log_find(log, "PT     1: switching at a simple branch point") != NULL);
  free(log);
}

int main(void)
{
  if (getenv("CABLE_TEST_QUICK")) {
    printf("CABLE_TEST_QUICK: the link scene paths are skipped\n");
    return test_summary();
  }
  test_link62();
  test_link43();
  test_link102();
  return test_summary();
}
