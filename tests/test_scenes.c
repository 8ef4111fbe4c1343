/* Acceptance tests of the small scenes runs/bratu, runs/elastica and
 * runs/torus: each scene's own script is replayed in a scratch directory with
 * its constants files, then a second script loads what it saved and prints
 * what the scene claims, which is checked against closed forms:
 *   bratu: the fold at lambda* = 3.513830719125162 (the root of the closed
 *     form's fold condition; tests/bench_testproblems.c);
 *   elastica: branch points of the straight rod at lambda = (k pi)^2,
 *     k = 1, 2, 3 (RL1 = 100), and the two directions of the buckled branch
 *     from the first one at the same lambda point by point (theta -> -theta);
 *   torus: the flat (p,2) torus knots and links it starts have
 *     Lk = Tw + Wr = hand * p/2 (torus.auto: half-integers for knots, integers
 *     for links, within 1e-6) and an unknotted braid axis.
 * A scene that changes what it computes fails here (make check). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "scene_util.h"

static const double PI = 3.14159265358979323846;

static char *run_scene(scene_scratch *sc, const char *scene, const char *const *files, const char *check_text)
{
  char path[192], buf[1400];
  cable_error err;
  char *log = NULL, *log2 = NULL;
  int ok = scene_scratch_make(sc, scene, scene, files);
  snprintf(buf, sizeof buf, "%s: scene files copied to a scratch directory", scene);
  test_true(buf, ok);
  if (!ok) return NULL;
  snprintf(path, sizeof path, "runs/%s/%s.auto", scene, scene);
  int rc = scene_replay(sc, path, NULL, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  snprintf(buf, sizeof buf, "%s: the scene replays", scene);
  test_int(buf, rc, 0);
  free(log);
  if (rc) return NULL;
  rc = scene_replay(sc, NULL, check_text, &log2, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  snprintf(buf, sizeof buf, "%s: its saved results load and analyse", scene);
  test_int(buf, rc, 0);
  return log2;
}

static void test_bratu(void)
{
  static const char *const files[] = {"c.bratu", NULL};
  scene_scratch sc;
  char *log = run_scene(&sc, "bratu", files,
                        "r = loadbd('bratu')\n"
                        "print('folds %d' % len(r[0]('LP')))\n"
                        "print('fold %.17g' % r('LP1')['lambda'])\n");
  int n = -1;
  double lam = NAN;
  const char *l = scene_log_line(log, "folds ", 0);
  test_true("bratu: one fold on the lower branch", l && sscanf(l, "%d", &n) == 1 && n == 1);
  l = scene_log_line(log, "fold ", 0);
  if (l) sscanf(l, "%lf", &lam);
  /* NTST 20, NCOL 4: collocation error of order h^8 at the mesh points, far
     below 1e-8; the location tolerance EPSS 1e-7 of a step <= 0.5 */
  test_rel("bratu: the fold at lambda* (closed form)", lam, 3.513830719125162, 1e-7);
  free(log);
  scene_scratch_remove(&sc);
}

static void test_elastica(void)
{
  static const char *const files[] = {"c.elastica", NULL};
  scene_scratch sc;
  char *log = run_scene(&sc, "elastica", files,
                        "r = loadbd('elastica')\n"
                        "bps = r[0]('BP')\n"
                        "print('bps %d' % len(bps))\n"
                        "for b in bps:\n"
                        "    print('bp %.17g' % b['lambda'])\n"
                        "up = r[1]()\n"
                        "down = r[2]()\n"
                        "print('halves %d %d' % (len(up), len(down)))\n"
                        "d = 0.0\n"
                        "m = 0.0\n"
                        "for i in range(len(up)):\n"
                        "    x = up[i]['lambda'] - down[i]['lambda']\n"
                        "    if x < 0:\n"
                        "        x = -x\n"
                        "    if x > d:\n"
                        "        d = x\n"
                        "    if up[i]['lambda'] > m:\n"
                        "        m = up[i]['lambda']\n"
                        "print('mirror %.17g %.17g' % (d, m))\n");
  int n = -1;
  const char *l = scene_log_line(log, "bps ", 0);
  test_true("elastica: three branch points below RL1 = 100", l && sscanf(l, "%d", &n) == 1 && n == 3);
  for (int k = 1; k <= 3; k++) {
    double lam = NAN;
    l = scene_log_line(log, "bp ", k - 1);
    if (l) sscanf(l, "%lf", &lam);
    char what[96];
    snprintf(what, sizeof what, "elastica: BP%d at (%d pi)^2", k, k);
    /* NTST 50, NCOL 5 and EPSS 1e-10: both far below 1e-8 */
    test_rel(what, lam, (k * PI) * (k * PI), 1e-8);
  }
  int nu = -1, nd = -1;
  l = scene_log_line(log, "halves ", 0);
  test_true("elastica: both directions from BP1 have labelled points",
            l && sscanf(l, "%d %d", &nu, &nd) == 2 && nu > 2 && nu == nd);
  double d = NAN, m = NAN;
  l = scene_log_line(log, "mirror ", 0);
  if (l) sscanf(l, "%lf %lf", &d, &m);
  test_le("elastica: the two directions at the same lambda point by point (theta -> -theta)", d, 1e-9 * PI * PI);
  test_true("elastica: the buckled branch leaves BP1 to larger lambda", m > PI * PI + 0.01);
  free(log);
  scene_scratch_remove(&sc);
}

static void test_torus(void)
{
  static const char *const files[] = {"c.knot", "c.link", NULL};
  static const struct {
    const char *name;
    double lk;
  } starts[] = {{"knot72_right", 3.5}, {"knot72_left", -3.5}, {"knot52_right", 2.5}, {"knot312_right", 15.5},
                {"knot12_right", 0.5}, {"link62_left", -3.0}, {"link42_right", 2.0}, {"link202_left", -10.0}};
  char text[4096];
  size_t len = 0;
  for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++)
    len += (size_t)snprintf(text + len, sizeof text - len,
                            "a = analyze(loadbd('%s')('EP1'))\n"
                            "print('lk %s %%.17g %%.17g %%.17g %%s' %% (a['Lk'], a['Tw'], a['Wr'], a['knot']))\n",
                            starts[i].name, starts[i].name);
  scene_scratch sc;
  char *log = run_scene(&sc, "torus", files, text);
  for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
    char prefix[64], what[128], knot[64] = "";
    double lk = NAN, tw = NAN, wr = NAN;
    snprintf(prefix, sizeof prefix, "lk %s ", starts[i].name);
    const char *l = scene_log_line(log, prefix, 0);
    if (l) sscanf(l, "%lf %lf %lf %63s", &lk, &tw, &wr, knot);
    snprintf(what, sizeof what, "torus: %s: Lk = hand p/2 (torus.auto's 1e-6)", starts[i].name);
    test_abs(what, lk, starts[i].lk, 1e-6);
    snprintf(what, sizeof what, "torus: %s: Lk = Tw + Wr", starts[i].name);
    test_abs(what, tw + wr, lk, 1e-9);
    snprintf(what, sizeof what, "torus: %s: the braid axis is unknotted (got '%s')", starts[i].name, knot);
    test_true(what, strcmp(knot, "unknot") == 0);
  }
  free(log);
  scene_scratch_remove(&sc);
}

int main(void)
{
  test_bratu();
  test_elastica();
  test_torus();
  return test_summary();
}
