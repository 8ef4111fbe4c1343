/* SPDX-License-Identifier: GPL-3.0-or-later */
/* No circle between files of different jobs (doc/api.md, Layers).
 *
 * test_layers.c checks the #include lines; this test checks the calls, from
 * the symbol tables of libcable.a (`nm`): file A uses file B when A's object
 * needs a symbol B's object defines.  It fails when
 *  - a file calls into a folder above its own (the layer rule for calls);
 *  - files call each other in a circle (a strongly connected set of the
 *    call graph), unless the circle is one of the few whose files share one
 *    job (listed below, each with the reason);
 *  - private headers include each other in a circle;
 *  - the library carries the command line (auto_iface/cli: a program over
 *    libcable, not part of it).
 * Runs from the repository root as BUILD/tests/test_file_circles; BUILD is
 * taken from argv[0]. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"
#include "layer_dirs.h"

#define MAXF 400
#define MAXS 8000

typedef struct {
  char name[64];   /* "cont_engine" */
  int layer;       /* index in layer_dirs, -1: not found */
} node;

static node nodes[MAXF];
static int nnodes;
static unsigned char reach[MAXF][MAXF];

/* the strongly connected sets allowed: files of one job split for size */
static const char *const same_job[][2] = {
  /* the starts of the braid problems and the torus-knot start they offer */
  {"braid_start", "braid_start_torus"},
  /* the braid problems' table and the preparation of a run it calls back */
  {"braid_prepare", "braid_problems"},
  /* the session's stored rows and its store of branches */
  {"cable_session_rows", "cable_session_store"},
};
#define NSAME ((int)(sizeof same_job / sizeof same_job[0]))

static int file_exists(const char *dir, const char *name)
{
  char path[1024];
  struct stat sb;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

static int node_of(const char *name)
{
  for (int i = 0; i < nnodes; i++)
    if (strcmp(nodes[i].name, name) == 0) return i;
  if (nnodes == MAXF) return -1;
  snprintf(nodes[nnodes].name, sizeof nodes[nnodes].name, "%s", name);
  char c[80];
  snprintf(c, sizeof c, "%s.c", name);
  nodes[nnodes].layer = -1;
  for (int k = 0; k < NLAYER_DIRS; k++)
    if (file_exists(layer_dirs[k], c)) nodes[nnodes].layer = k;
  /* the embedded auto_compat files (the Makefile's gen/) serve the
     equation-file compiler */
  if (strcmp(name, "autoeq_compat_text") == 0) nodes[nnodes].layer = layer_index("auto_iface/autoeq");
  return nnodes++;
}

typedef struct {
  char sym[128];
  int file;
} symref;

static symref defs[MAXS], uses[MAXS];
static int ndefs, nuses;

/* Reads `nm -A archive`: defined and undefined symbols per member. */
static int read_archive(const char *archive)
{
  char cmd[1200], line[1024];
  snprintf(cmd, sizeof cmd, "nm -A '%s' 2>/dev/null", archive);
  FILE *p = popen(cmd, "r");
  if (!p) return -1;
  size_t alen = strlen(archive);
  while (fgets(line, sizeof line, p)) {
    if (strncmp(line, archive, alen) != 0 || line[alen] != ':') continue;
    char *member = line + alen + 1, *colon = strchr(member, ':');
    if (!colon) continue;
    *colon = '\0';
    char *dot = strrchr(member, '.');
    if (dot) *dot = '\0';
    char f1[128], f2[128], f3[128];
    int nf = sscanf(colon + 1, "%127s %127s %127s", f1, f2, f3);
    int file = node_of(member);
    if (file < 0) continue;
    if (nf == 2 && strcmp(f1, "U") == 0 && nuses < MAXS) {
      snprintf(uses[nuses].sym, sizeof uses[nuses].sym, "%s", f2);
      uses[nuses++].file = file;
    } else if (nf == 3 && strchr("TDBRC", f2[0]) && ndefs < MAXS) {
      snprintf(defs[ndefs].sym, sizeof defs[ndefs].sym, "%s", f3);
      defs[ndefs++].file = file;
    }
  }
  return pclose(p);
}

static void close_transitively(void)
{
  for (int k = 0; k < nnodes; k++)
    for (int i = 0; i < nnodes; i++)
      if (reach[i][k])
        for (int j = 0; j < nnodes; j++)
          if (reach[k][j]) reach[i][j] = 1;
}

static int allowed_pair(const char *a, const char *b)
{
  for (int k = 0; k < NSAME; k++)
    if ((strcmp(a, same_job[k][0]) == 0 && strcmp(b, same_job[k][1]) == 0) ||
        (strcmp(a, same_job[k][1]) == 0 && strcmp(b, same_job[k][0]) == 0))
      return 1;
  return 0;
}

/* Circles of the closed relation: pairs i < j that reach each other and are
 * not of one job.  report: FAIL lines (1) or notes (0). */
static int circles(int report)
{
  int bad = 0;
  for (int i = 0; i < nnodes; i++)
    for (int j = i + 1; j < nnodes; j++)
      if (reach[i][j] && reach[j][i] && !allowed_pair(nodes[i].name, nodes[j].name)) {
        if (report) test_report(0, "%s.c and %s.c call each other (directly or through others)", nodes[i].name,
                                nodes[j].name);
        else printf("found (as expected): %s.c <-> %s.c\n", nodes[i].name, nodes[j].name);
        bad++;
      }
  return bad;
}

/* The call graph of libcable.a. */
static void check_calls(const char *build)
{
  char archive[1100];
  snprintf(archive, sizeof archive, "%s/libcable.a", build);
  int rc = read_archive(archive);
  test_true("nm reads libcable.a", rc == 0 && nnodes > 50 && ndefs > 300);
  int unplaced = 0, upward = 0, cli = 0, nedges = 0;
  for (int i = 0; i < nnodes; i++) {
    if (nodes[i].layer < 0) {
      test_report(0, "%s.o of libcable.a has no source in a layer folder", nodes[i].name);
      unplaced++;
    } else if (strcmp(layer_dirs[nodes[i].layer], "auto_iface/cli") == 0) {
      test_report(0, "%s.o (auto_iface/cli) is inside libcable.a", nodes[i].name);
      cli++;
    }
  }
  test_int("every member of libcable.a has its source in a layer folder", unplaced, 0);
  test_int("libcable.a holds no file of the command line (auto_iface/cli)", cli, 0);
  for (int u = 0; u < nuses; u++)
    for (int d = 0; d < ndefs; d++) {
      if (strcmp(uses[u].sym, defs[d].sym) != 0) continue;
      int a = uses[u].file, b = defs[d].file;
      if (a == b) continue;
      if (!reach[a][b]) nedges++;
      reach[a][b] = 1;
      if (nodes[a].layer >= 0 && nodes[b].layer > nodes[a].layer) {
        test_report(0, "%s/%s.c calls %s of %s/%s.c, a higher layer", layer_dirs[nodes[a].layer], nodes[a].name,
                    uses[u].sym, layer_dirs[nodes[b].layer], nodes[b].name);
        upward++;
      }
    }
  test_true("the call graph has edges", nedges > 100);
  test_int("no file calls into a higher layer", upward, 0);

  /* the checker must see a circle: a planted call from the geometry of a
     braid solution back to its ribbon (the circle opened in issue 27) */
  static unsigned char saved[MAXF][MAXF];
  memcpy(saved, reach, sizeof reach);
  int g = node_of("braid_geometry"), r = node_of("ribbon_braid");
  int planted = -1;
  if (g >= 0 && r >= 0 && reach[r][g]) {
    reach[g][r] = 1;
    close_transitively();
    planted = circles(0);
  }
  test_true("a planted call braid_geometry.c -> ribbon_braid.c is reported as a circle", planted >= 1);
  memcpy(reach, saved, sizeof reach);
  close_transitively();
  test_int("no circle of calls between files of different jobs", circles(1), 0);
}

/* `#include "X"` of private headers: no circle. */
static int header_index(const char *name)
{
  int found = -1;
  for (int k = 0; k < NLAYER_DIRS; k++)
    if (file_exists(layer_dirs[k], name)) found = k;
  return found;
}

static void check_header_circles(void)
{
  nnodes = 0;
  memset(reach, 0, sizeof reach);
  int nh = 0;
  for (int k = 0; k < NLAYER_DIRS; k++) {
    DIR *d = opendir(layer_dirs[k]);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      size_t n = strlen(e->d_name);
      if (n < 3 || strcmp(e->d_name + n - 2, ".h") != 0) continue;
      int a = node_of(e->d_name);
      if (a < 0) continue;
      nh++;
      char path[1024], line[1024];
      snprintf(path, sizeof path, "%s/%s", layer_dirs[k], e->d_name);
      FILE *f = fopen(path, "r");
      if (!f) continue;
      while (fgets(line, sizeof line, f)) {
        char inc[256];
        if (sscanf(line, " #include \"%255[^\"]\"", inc) != 1) continue;
        if (header_index(inc) < 0) continue;   /* public or system */
        int b = node_of(inc);
        if (b >= 0 && b != a) reach[a][b] = 1;
      }
      fclose(f);
    }
    closedir(d);
  }
  close_transitively();
  test_true("private headers read", nh > 40);
  int bad = 0;
  for (int i = 0; i < nnodes; i++)
    for (int j = i + 1; j < nnodes; j++)
      if (reach[i][j] && reach[j][i]) {
        test_report(0, "headers %s and %s include each other", nodes[i].name, nodes[j].name);
        bad++;
      }
  test_int("no circle of #include between private headers", bad, 0);
}

/* The shared library carries no command of the command line. */
static void check_shared(const char *build)
{
  char cmd[1200], line[1024];
  snprintf(cmd, sizeof cmd, "nm '%s/libcable.so' 2>/dev/null", build);
  FILE *p = popen(cmd, "r");
  int nsym = 0, ncmd = 0;
  if (p) {
    while (fgets(line, sizeof line, p)) {
      nsym++;
      if (strstr(line, " cable_cmd_") || strstr(line, " main\n")) ncmd++;
    }
    pclose(p);
  }
  test_true("nm reads libcable.so", nsym > 500);
  test_int("libcable.so holds no command (cable_cmd_*, main)", ncmd, 0);
}

int main(int argc, char **argv)
{
  (void)argc;
  /* BUILD/tests/test_file_circles -> BUILD */
  char build[1024];
  snprintf(build, sizeof build, "%s", argv[0]);
  for (int up = 0; up < 2; up++) {
    char *slash = strrchr(build, '/');
    if (slash) *slash = '\0';
    else snprintf(build, sizeof build, ".");
  }
  check_calls(build);
  check_shared(build);
  check_header_circles();
  return test_summary();
}
