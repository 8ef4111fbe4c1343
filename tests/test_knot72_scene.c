/* The project's acceptance test: the knot72 scene's path (runs/knot72/knot72.auto:
 * the flat right-handed (7,2) knot, its branch points BP1-BP4 and the mode 1-4
 * branches from them, exactly the scene's own run lines, replayed in a scratch
 * directory with the scene's constants files) must reproduce the paper's cable
 * knots (a)-(d) of Figs. 12.3-12.6: F within 1e-4, the braid axis an unknot, a
 * right trefoil, a right (4,3) and a right (5,4) torus knot, Lk = Tw + Wr = 5.5,
 * 9.5, 15.5, 23.5 and the paper's 'linking numbers' 5.5, 6.5, 7.5, 8.5 as Lk
 * minus the writhe of the companion's minimal diagram, non-negative contact
 * pressure.  The paper's values are comparison targets only.
 *
 * First, the axis-passage counter (axis_passages.h) on closed-form curves, and
 * compare() itself on a small case: two cheap flat branches with a UZ
 * label each at the same T (different Delta, so different F); compare must take
 * the crossing whose F is nearest the target, and refuse rows it cannot match
 * without leaving a table file behind.
 *
 * CABLE_TEST_QUICK (valgrind runs) skips the scene replay (about a minute of
 * continuation natively). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "axis_passages.h"
#include "script_host_cable.h"
#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "harness.h"
#include "test_files.h"
#include "script.h"
#include "script_host_cable.h"

static const char *const scratch_files[] = {
    "c.knot72", "c.knot72sym", "small.txt", "bad.txt", "knot72_check.txt",
    "b.flat", "s.flat", "d.flat", "b.mode1", "s.mode1", "d.mode1", "b.mode2", "s.mode2", "d.mode2",
    "b.mode3", "s.mode3", "d.mode3", "b.mode4", "s.mode4", "d.mode4"};

typedef struct scratch {
  char dir[64];
} scratch;

static void scratch_path(const scratch *sc, const char *name, char *buf, size_t len)
{
  snprintf(buf, len, "%s/%s", sc->dir, name);
}

static int file_exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

static void scratch_remove(const scratch *sc)
{
  char p[128];
  for (size_t i = 0; i < sizeof scratch_files / sizeof scratch_files[0]; i++) {
    scratch_path(sc, scratch_files[i], p, sizeof p);
    remove(p);
  }
  rmdir(sc->dir);
}

/* Runs the script text on a fresh engine-host session with the braid
 * problems, in the scratch directory; the log (print output, labelled points)
 * comes back in *log (free it). */
static int replay(const scratch *sc, const char *text, char **log, cable_error *err)
{
  size_t len;
  FILE *f = open_memstream(log, &len);
  cable_replay_options o;
  cable_replay_options_init(&o);
  o.dir = sc->dir;
  o.log = f;
  cable_replay *r = cable_replay_alloc(&o);
  int rc = r ? script_run_string("t.auto", text, cable_replay_host(r), err) : CABLE_ERR_ALLOC;
  cable_replay_free(r);
  fclose(f);
  return rc;
}

/* The rest of the log line starting with prefix (the k-th such line, 0-based). */
static const char *log_line(const char *log, const char *prefix, int k)
{
  for (const char *p = log; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL)
    if (strncmp(p, prefix, strlen(prefix)) == 0 && k-- == 0) return p + strlen(prefix);
  return NULL;
}

/* ---- the axis-passage counter on closed-form curves ----------------------------- */

#define NCURVE 400
static const double PI = 3.14159265358979323846;

/* A figure-eight-like closed curve (x, y) = (cos th, sin th cos th) whose one
 * planar self-crossing (th = pi/2 and 3 pi/2) is lifted apart by z = eps sin th,
 * or a trefoil projection (sin th + 2 sin 2th, cos th - 2 cos 2th) lifted by
 * z = eps sin 3th at its three crossings; rot: a rotation about z. */
static void test_curve(int trefoil, double eps, double rot, double *xyz, double *pos)
{
  for (int k = 0; k < NCURVE; k++) {
    double th = 2 * PI * k / NCURVE, x, y, z;
    if (trefoil) x = sin(th) + 2 * sin(2 * th), y = cos(th) - 2 * cos(2 * th), z = eps * sin(3 * th);
    else x = cos(th), y = sin(th) * cos(th), z = eps * sin(th);
    xyz[3 * k] = cos(rot) * x - sin(rot) * y;
    xyz[3 * k + 1] = sin(rot) * x + cos(rot) * y;
    xyz[3 * k + 2] = z;
    pos[k] = (double)k / NCURVE;
  }
}

static void test_curve_passages(void)
{
  static double a[3 * NCURVE], b[3 * NCURVE], c[3 * NCURVE], pos[NCURVE];
  axis_passages ap, back;
  /* window 0.05 of the period: the crossing parts are half a period apart */
  test_curve(0, 0.1, 0, a, pos);
  test_curve(0, -0.1, 0, b, pos);
  test_int("passages: figure eight lifted to the other side: status", curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap), 0);
  test_int("  one passage", ap.count, 1);
  test_int("  of one sign", abs(ap.net), 1);
  /* the parts meet where eps (1 - 2 tau) = 0 */
  test_abs("  halfway along the homotopy", ap.tau_first, 0.5, 1e-9);
  curve_passages(b, a, pos, NCURVE, 1, 0.05, &back);
  test_true("  and the way back has the opposite sign", back.count == 1 && back.net == -ap.net);
  curve_passages(a, a, pos, NCURVE, 1, 0.05, &ap);
  test_true("passages: no motion, none", ap.count == 0 && ap.net == 0 && isnan(ap.tau_first));
  test_curve(0, 0.1, 0.2, c, pos);
  curve_passages(a, c, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: a rigid rotation passes nothing", ap.count, 0);
  test_curve(0, 0.05, 0, c, pos);
  curve_passages(a, c, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: parts that approach without meeting pass nothing", ap.count, 0);
  curve_passages(a, b, pos, NCURVE, 1, 0.6, &ap);
  test_int("passages: parts closer than the window along the curve are not compared", ap.count, 0);
  test_curve(0, 0.0, 0, c, pos);
  test_curve(0, 0.0, 0.3, b, pos);
  curve_passages(c, b, pos, NCURVE, 1, 0.05, &ap);
  test_int("passages: two planar shapes (coplanar all along) pass nothing", ap.count, 0);
  /* the trefoil's three crossings all change, and all the same way (a right
     trefoil becomes a left one: each crossing's sign flips alike) */
  test_curve(1, 0.5, 0, a, pos);
  test_curve(1, -0.5, 0, b, pos);
  curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap);
  test_true("passages: trefoil lifted to its mirror: three passages of one sign", ap.count == 3 && abs(ap.net) == 3);
  test_int("passages: fewer than four points refused", curve_passages(a, b, pos, 3, 1, 0.05, &ap), CABLE_ERR_INPUT);
  b[7] = NAN;
  test_int("passages: a non-finite point refused", curve_passages(a, b, pos, NCURVE, 1, 0.05, &ap), CABLE_ERR_INPUT);
}

/* ---- compare() on a small case -------------------------------------------------- */

/* Two flat (7,2) branches from STPNT (NTST=20, NCOL=4: cheap; accuracy does not
 * matter here), Delta 0.0051 and 0.006, each ending with a UZ label at T = 4. */
static const char small_runs[] =
    "r = run(e='braid_knot', c='knot72', NTST=20, NCOL=4, ISP=0, NMX=30, UZSTOP={'T': 4.0})\n"
    "r = r + run(e='braid_knot', c='knot72', NTST=20, NCOL=4, ISP=0, NMX=30, UZSTOP={'T': 4.0},\n"
    "            PAR={'Delta': 0.006, 'Ltot': 1.98889, 'T': 0.0})\n"
    "u = r('UZ')\n"
    "print('uz %d %d %d %.17g %.17g' % (len(u), u[0]['LAB'], u[1]['LAB'], u[0]['F'], u[1]['F']))\n";

static void test_compare_small(const scratch *sc)
{
  char text[4096], buf[1400], *log = NULL;
  cable_error err;
  snprintf(text, sizeof text,
           "%s"
           "rows = compare('small.txt', [['one', r, 4.0, u[0]['F'] - 0.01, 3.5],\n"
           "                             ['two', r, 4.0, u[1]['F'] + 0.01, 3.5],\n"
           "                             ['sol', u[1], 4.0, 100.0, 3.5]])\n"
           "for d in rows:\n"
           "    print('row %%s %%d %%d %%d %%.17g %%.17g %%.17g' %% (d['name'], d['LAB'], d['uz_at_T'],"
           " d['uz_chosen'], d['F'], d['F_paper'], d['rel']))\n",
           small_runs);
  int rc = replay(sc, text, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("compare on two flat branches: the script runs", rc, 0);
  int n = 0, lab0 = -1, lab1 = -1;
  double f0 = NAN, f1 = NAN;
  const char *l = log_line(log, "uz ", 0);
  test_true("two UZ labels at T = 4", l && sscanf(l, "%d %d %d %lf %lf", &n, &lab0, &lab1, &f0, &f1) == 5 && n == 2);
  /* the picks below are told apart by F: the two branches must differ by more
     than the 0.01 offsets of the targets */
  snprintf(buf, sizeof buf, "the two crossings differ in F (%.6g vs %.6g)", f0, f1);
  test_true(buf, fabs(f0 - f1) > 0.1);
  const char *want_name[3] = {"one", "two", "sol"};
  int want_lab[3] = {lab0, lab1, lab1}, want_nuz[3] = {2, 2, 1}, want_k[3] = {1, 2, 1};
  for (int i = 0; i < 3; i++) {
    char name[16] = "";
    int lab = -1, nuz = -1, k = -1;
    double F = NAN, Ft = NAN, rel = NAN;
    l = log_line(log, "row ", i);
    int ok = l && sscanf(l, "%15s %d %d %d %lf %lf %lf", name, &lab, &nuz, &k, &F, &Ft, &rel) == 7 &&
             strcmp(name, want_name[i]) == 0;
    snprintf(buf, sizeof buf, "compare row '%s' returned", want_name[i]);
    test_true(buf, ok);
    snprintf(buf, sizeof buf, "  row '%s' takes label %d (nearest F of the crossings)", want_name[i], want_lab[i]);
    test_int(buf, lab, want_lab[i]);
    snprintf(buf, sizeof buf, "  row '%s': UZ labels at T and the one chosen", want_name[i]);
    test_true(buf, nuz == want_nuz[i] && k == want_k[i]);
    snprintf(buf, sizeof buf, "  row '%s': rel = |F - F_target| / F_target", want_name[i]);
    test_rel(buf, rel, fabs(F - Ft) / Ft, 1e-15);
  }
  char p[128];
  scratch_path(sc, "small.txt", p, sizeof p);
  test_true("the table file is written", file_exists(p));
  free(log);

  /* rows compare cannot match: an error naming the row, and no table file */
  static const struct {
    const char *row, *want;
  } bad[] = {
      {"['x', r, 7.0, 100.0, 3.5]", "no UZ label at T = 7"},
      {"['x', u[0], 5.0, 100.0, 3.5]", "not the target T"},
      {"['x', r, 4.0, 100.0]", "must be [name, result or solution, T_target"},
      {"['x', 3, 4.0, 100.0, 3.5]", "must be a result or a solution"},
  };
  scratch_path(sc, "bad.txt", p, sizeof p);
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    snprintf(text, sizeof text, "%scompare('bad.txt', [['ok', r, 4.0, 100.0, 3.5], %s])\n", small_runs, bad[i].row);
    log = NULL;
    rc = replay(sc, text, &log, &err);
    snprintf(buf, sizeof buf, "compare refuses row %s (message: %s)", bad[i].row, err.msg);
    test_true(buf, rc == CABLE_ERR_INPUT && strstr(err.msg, bad[i].want) && strstr(err.msg, "row 2"));
    test_true("  and writes no table file", !file_exists(p));
    free(log);
  }
}

/* ---- the acceptance test -------------------------------------------------------- */

typedef struct paper_point {
  const char *name, *branch;
  double T, F;          /* the paper's T (its UZ label) and F */
  double lk;            /* Tw + Wr of the paper's shape (independent computations) */
  double lk_paper;      /* the paper's 'linking number' */
  const char *knot;     /* braid-axis knot type and handedness */
  int hand;
} paper_point;

static const paper_point points[] = {
    {"a", "m1", -2.10752, 171.50131, 5.5, 5.5, "unknot", 0},
    {"b", "m2", -9.89105, 368.075, 9.5, 6.5, "trefoil", 1},
    {"c", "m3", -10.97932, 634.5698, 15.5, 7.5, "torus(4,3)", 1},
    {"d", "m4", -15.51471, 942.989, 23.5, 8.5, "torus(5,4)", 1},
};
#define NPOINTS ((int)(sizeof points / sizeof points[0]))

/* The goal for the knot72 scene: |dF|/F <= 1e-4 at (a)-(d). */
#define ACCEPT_REL_F 1e-4
/* Lk of a closed knot ribbon is a half-odd integer; a wrong shape or topology
 * is off by at least 1, the ribbon quadrature by far less than 0.01. */
#define LK_TOL 0.01

/* The scene's lines that compute the path: flat = run(...) and m1..m4 = run(...),
 * continuation lines included.  NULL when the scene cannot be read. */
static char *scene_path_lines(const char *scene, int *found)
{
  FILE *f = fopen(scene, "r");
  if (!f) return NULL;
  size_t cap = 1 << 16, n = 0;
  char *out = calloc(cap, 1), line[1024];
  int in_call = 0;
  *found = 0;
  while (out && fgets(line, sizeof line, f)) {
    int start = strncmp(line, "flat = run(", 11) == 0 ||
                (line[0] == 'm' && line[1] >= '1' && line[1] <= '4' && strncmp(line + 2, " = run(", 7) == 0);
    if (start) (*found)++;
    if (start || in_call) {
      size_t k = strlen(line);
      if (n + k + 1 < cap) {
        memcpy(out + n, line, k + 1);
        n += k;
      }
      /* a call continues while its brackets are open */
      int depth = 0;
      for (const char *c = out; *c; c++) depth += (*c == '(') - (*c == ')');
      in_call = depth > 0;
    }
  }
  fclose(f);
  return out;
}

static void test_scene_acceptance(const scratch *sc)
{
  int found = 0;
  char *path = scene_path_lines("runs/knot72/knot72.auto", &found);
  test_true("runs/knot72/knot72.auto defines flat and m1..m4 (its run lines are replayed)", path && found == 5);
  if (!path || found != 5) {
    free(path);
    return;
  }
  size_t cap = strlen(path) + 4096;
  char *text = malloc(cap), buf[1400], *log = NULL;
  size_t n = (size_t)snprintf(text, cap, "%s", path);
  n += (size_t)snprintf(text + n, cap - n, "rows = compare('knot72_check.txt', [");
  for (int i = 0; i < NPOINTS; i++)
    n += (size_t)snprintf(text + n, cap - n, "%s['%s', %s, %.10g, %.10g, %.10g]", i ? ", " : "", points[i].name,
                          points[i].branch, points[i].T, points[i].F, points[i].lk_paper);
  snprintf(text + n, cap - n,
           "], ref=flat('EP1'))\n"
           "for d in rows:\n"
           "    print('row %%s %%d %%.17g %%.17g %%.17g %%.17g %%.17g %%s %%d %%d %%.17g %%d %%d %%d %%.17g' %% (d['name'],"
           " d['LAB'], d['T'], d['F'], d['rel'], d['Lk'], d['lk_in_tube'], d['knot'], d['hand'], d['crossings'],"
           " d['pmin'], d['uz_at_T'], d['passes'], d['passes_net'], d['dLk_half']))\n"
           "print('bp %%d' %% len(flat('BP')))\n"
           "for m in [m1, m2, m3, m4]:\n"
           "    tmin = 1000.0\n"
           "    for s in m():\n"
           "        if s['T'] < tmin:\n"
           "            tmin = s['T']\n"
           "    print('tmin %%.17g' %% tmin)\n");
  cable_error err;
  int rc = replay(sc, text, &log, &err);
  if (rc) printf("  error: %s\n", cable_error_format(&err, buf, sizeof buf));
  test_int("the knot72 path (flat, BP1-BP4, modes 1-4) replays", rc, 0);
  int nbp = 0;
  const char *l = log_line(log, "bp ", 0);
  test_true("the flat branch's right arm has four branch points (BP1-BP4)", l && sscanf(l, "%d", &nbp) == 1 && nbp >= 4);
  for (int i = 0; i < NPOINTS; i++) {
    const paper_point *pp = &points[i];
    char name[16] = "", knot[32] = "";
    int lab = -1, hand = -9, cross = -1, nuz = 0, passes = -1, net = -99;
    double T = NAN, F = NAN, rel = NAN, lk = NAN, lkt = NAN, pmin = NAN, tmin = NAN, dlk = NAN;
    l = log_line(log, "row ", i);
    int ok = l && sscanf(l, "%15s %d %lf %lf %lf %lf %lf %31s %d %d %lf %d %d %d %lf", name, &lab, &T, &F, &rel, &lk, &lkt,
                         knot, &hand, &cross, &pmin, &nuz, &passes, &net, &dlk) == 15 &&
             strcmp(name, pp->name) == 0;
    snprintf(buf, sizeof buf, "(%s): compared (label %d)", pp->name, lab);
    if (!test_true(buf, ok)) continue;
    snprintf(buf, sizeof buf, "(%s): at the paper's T", pp->name);
    test_abs(buf, T, pp->T, 1e-5 * fmax(1.0, fabs(pp->T)));
    snprintf(buf, sizeof buf, "(%s): |dF|/F against the paper's F = %.8g (ours %.10g)", pp->name, pp->F, F);
    test_le(buf, rel, ACCEPT_REL_F);
    snprintf(buf, sizeof buf, "(%s): braid axis is %s%s (got %s, hand %d)", pp->name,
             pp->hand > 0 ? "a right " : pp->hand < 0 ? "a left " : "an ", pp->knot, knot, hand);
    test_true(buf, strcmp(knot, pp->knot) == 0 && hand == pp->hand);
    snprintf(buf, sizeof buf, "(%s): Lk = Tw + Wr", pp->name);
    test_abs(buf, lk, pp->lk, LK_TOL);
    snprintf(buf, sizeof buf, "(%s): the paper's 'linking number' %.1f = Lk - writhe of the companion", pp->name,
             pp->lk_paper);
    test_abs(buf, lkt, pp->lk_paper, LK_TOL);
    snprintf(buf, sizeof buf, "(%s):   which is Lk - hand x crossing number (%d x %d)", pp->name, hand, cross);
    test_abs(buf, lkt, lk - hand * cross, 1e-12);
    snprintf(buf, sizeof buf, "(%s): minimum contact pressure non-negative (pmin = %.6g)", pp->name, pmin);
    test_true(buf, pmin >= 0.0);
    /* self-passages of the braid axis, counted along the branch (axis_passages.h),
       against the change of Lk since the flat knot: each passage changes Lk by 2 */
    snprintf(buf, sizeof buf, "(%s): axis self-passages counted along the branch: %d, signed sum %d = (Lk - Lk_flat)/2 = %.4f",
             pp->name, passes, net, dlk);
    test_true(buf, fabs(dlk - net) < LK_TOL && passes == abs(net));
    if (i == 0) test_int("(a): the axis passed itself once (the paper's figure-eight self-crossing)", passes, 1);
    /* the branch is followed through the point, to the fold beyond and back */
    l = log_line(log, "tmin ", i);
    ok = l && sscanf(l, "%lf", &tmin) == 1;
    snprintf(buf, sizeof buf, "(%s): branch %s passes the point (min T %.4f < %.4f) and crosses its T again (%d UZ)",
             pp->name, pp->branch, tmin, pp->T, nuz);
    test_true(buf, ok && tmin < pp->T - 0.1 && nuz >= 2);
  }
  free(log);
  free(text);
  free(path);
}

int main(void)
{
  scratch sc;
  snprintf(sc.dir, sizeof sc.dir, "tests/tmp/knot72_scene.%ld", (long)getpid());
  mkdir("tests/tmp", 0777);
  mkdir(sc.dir, 0777);
  char p[128];
  scratch_path(&sc, "c.knot72", p, sizeof p);
  int ok = copy_file("runs/knot72/c.knot72", p);
  scratch_path(&sc, "c.knot72sym", p, sizeof p);
  ok = ok && copy_file("runs/knot72/c.knot72sym", p);
  test_true("the scene's constants files copied to a scratch directory", ok);
  test_curve_passages();
  if (ok) {
    test_compare_small(&sc);
    if (!getenv("CABLE_TEST_QUICK")) test_scene_acceptance(&sc);
    else printf("CABLE_TEST_QUICK: the knot72 scene replay is skipped\n");
  }
  scratch_remove(&sc);
  return test_summary();
}
