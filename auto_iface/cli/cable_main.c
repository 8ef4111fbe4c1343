/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The `cable` command line: uses only the public API and reports every error
 * on one line with file, line and key, exiting non-zero.  `cable replay`
 * runs a script in CPython with the cable package (python/cable). */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cable/cable_aufile.h"
#include "cable/cable_cont.h"
#include "cable_commands.h"
#include "cable/cable_pictures.h"
#include "cable/cable_status.h"
#include "cable/cable_version.h"

static void usage(FILE *out)
{
  fputs("usage: cable COMMAND [ARGS]\n"
        "commands:\n"
        "  run [NAME] [c=NAME] [e=PROBLEM] [s=NAME] [sv=NAME] [KEY=VALUE ...]\n"
        "                     one continuation run, AUTO's run(...) semantics (a first\n"
        "                     NAME is run('NAME'): e=NAME c=NAME); KEY=VALUE overrides\n"
        "                     the constants file c.NAME\n"
        "  replay SCRIPT      run a script in Python with AUTO's commands (the cable\n"
        "                     package, as `python3 -m cable SCRIPT`); output files go\n"
        "                     to the script's directory\n"
        "  atlas SWEEP.toml [--workers N | --scheduler ADDRESS] [--check] [--retry-failed]\n"
        "                     an atlas of cable knots and links on Dask (python3 -m\n"
        "                     cable.atlas; doc/atlas.md)\n"
        "  explore TORUS=p HAND=+-1 Delta=D Ltot=L [modes=N] [out=DIR] [KEY=VALUE ...]\n"
        "                     the flat branch of a torus knot or link, its branch points\n"
        "                     and every branch from the first N of them: the diagram, the\n"
        "                     pictures and a table (python3 -m cable.explorer; doc/explore.md)\n"
        "  view DIR [o=FILE.html]\n"
        "                     one offline HTML page of a run directory's b./s. files or\n"
        "                     an atlas: the diagram beside the 3-D knot (python3 -m\n"
        "                     cable.webview; doc/view.md)\n"
        "  info e=PROBLEM     a problem's parameters, components, keys, their defaults and\n"
        "                     the recommended constants (an equation file PROBLEM.f90,\n"
        "                     .f or .c in the current directory counts, as for run)\n"
        "  table b.NAME       the branch table of a b-file\n"
        "  list s.NAME        the labelled solutions of an s-file\n"
        "  analyze s.NAME LABEL... [STAB=1]\n"
        "                     derived quantities of braid solutions (Lk, Tw, Wr, knot type,\n"
        "                     contact pressure, tube overlap, first integrals)\n"
        "  plot [x=COL] [y=COL] [o=FILE.png|.svg] b.NAME ...\n"
        "                     bifurcation diagram (default: T against F) of b-files\n"
        "  render s.NAME LABEL [o=FILE.png] [view=X,Y,Z] [size=N] [thicken=K]\n"
        "                     [color=pressure] [vtp=FILE.vtp] [ply=FILE.ply]\n"
        "                     shaded 3-D picture of a braid solution with its contact\n"
        "                     pressure profiles; exports for ParaView and Blender\n"
        "  --version          cable's version and the library versions\n"
        "  --help             this text\n"
        "See README.md and doc/ for constants keys, scripts and file formats.\n",
        out);
}

static int report(int rc, const cable_error *err)
{
  char buf[1400];
  if (rc == 0) return 0;
  fprintf(stderr, "cable: %s\n", err->msg[0] ? cable_error_format(err, buf, sizeof buf) : cable_status_message(rc));
  return 1;
}

#ifndef CABLE_PYTHON
#define CABLE_PYTHON "/usr/bin/python3"
#endif

/* The directory holding the package cable/ beside this program: BINDIR/python
 * (the build tree) or BINDIR/../lib/cable/python (make install). */
static int find_package(char *dir, size_t len)
{
  char exe[PATH_MAX];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return -1;
  exe[n] = '\0';
  char *slash = strrchr(exe, '/');
  if (!slash) return -1;
  *slash = '\0';
  static const char *const rel[] = {"python", "../lib/cable/python"};
  for (size_t i = 0; i < sizeof rel / sizeof rel[0]; i++) {
    char probe[PATH_MAX + 64];
    struct stat st;
    snprintf(probe, sizeof probe, "%s/%s/cable/__init__.py", exe, rel[i]);
    if (stat(probe, &st) == 0 && (size_t)snprintf(dir, len, "%s/%s", exe, rel[i]) < len) return 0;
  }
  return -1;
}

/* Puts the package's directory first on PYTHONPATH; -1 when it is not found. */
static int package_on_path(void)
{
  char dir[PATH_MAX + 64], path[2 * PATH_MAX + 128];
  if (find_package(dir, sizeof dir) != 0) {
    fprintf(stderr, "cable: the Python package (cable/) is not beside this program (build it with make)\n");
    return -1;
  }
  const char *old = getenv("PYTHONPATH");
  snprintf(path, sizeof path, "%s%s%s", dir, old && old[0] ? ":" : "", old && old[0] ? old : "");
  setenv("PYTHONPATH", path, 1);
  return 0;
}

/* cable replay SCRIPT: exec CABLE_PYTHON -m cable SCRIPT with the package on PYTHONPATH. */
static int replay(const char *script)
{
  if (package_on_path() != 0) return 1;
  execl(CABLE_PYTHON, CABLE_PYTHON, "-m", "cable", script, (char *)NULL);
  fprintf(stderr, "cable: cannot run %s: %s\n", CABLE_PYTHON, strerror(errno));
  return 1;
}

/* cable atlas|view ARGS: exec CABLE_PYTHON -m MODULE ARGS (argv[2..]) with the package on PYTHONPATH. */
static int python_module(const char *name, int argc, char **argv)
{
  enum { MAX_ARGS = 64 };
  char *args[MAX_ARGS + 4];
  if (argc - 2 > MAX_ARGS) {
    fprintf(stderr, "cable: %s: too many arguments\n", argv[1]);
    return 2;
  }
  if (package_on_path() != 0) return 1;
  static char python[] = CABLE_PYTHON, dash_m[] = "-m";
  char module[32];
  snprintf(module, sizeof module, "%s", name);
  int n = 0;
  args[n++] = python;
  args[n++] = dash_m;
  args[n++] = module;
  for (int i = 2; i < argc; i++) args[n++] = argv[i];
  args[n] = NULL;
  execv(CABLE_PYTHON, args);
  fprintf(stderr, "cable: cannot run %s: %s\n", CABLE_PYTHON, strerror(errno));
  return 1;
}

/* The signal that asked `cable run` to stop (0: none).  Process-wide by
 * nature: a signal handler has no other place to leave it. */
static volatile sig_atomic_t stop_signal;

static void on_stop_signal(int sig)
{
  stop_signal = sig;
}

static int stop_requested(void *ctx)
{
  (void)ctx;
  return stop_signal != 0;
}

/* SIGINT and SIGTERM end the run after the point being computed (its files
 * hold every point before); a second one acts at once, as by default. */
static void catch_stop_signals(void)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);
}

/* cable run: 0, 1 for an error, 128 + the signal when SIGINT or SIGTERM stopped it. */
static int run_command(int argc, char **argv, cable_error *err)
{
  /* the log goes out line by line, also into a file or a pipe */
  setvbuf(stdout, NULL, _IOLBF, 0);
  catch_stop_signals();
  int rc = cable_cmd_run(argc, argv, stop_requested, NULL, err);
  fflush(stdout);
  int sig = stop_signal;
  if (rc == CABLE_ERR_INTERRUPTED && sig) {
    char buf[1400];
    fprintf(stderr, "cable: run stopped by %s: %s\n", sig == SIGINT ? "SIGINT" : "SIGTERM",
            cable_error_format(err, buf, sizeof buf));
    return 128 + sig;
  }
  return report(rc, err);
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  const char *cmd = argv[1];
  /* the application's choice, not the library's: small BLAS blocks run
     fastest on one thread */
  cable_blas_single_thread();
  cable_error err;
  cable_error_clear(&err);
  if (strcmp(cmd, "--version") == 0) {
    char buf[256];
    puts(cable_version_string(buf, sizeof buf));
    return 0;
  }
  if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
    usage(stdout);
    return 0;
  }
  if (strcmp(cmd, "run") == 0) return run_command(argc - 2, argv + 2, &err);
  if (strcmp(cmd, "atlas") == 0) return python_module("cable.atlas", argc, argv);
  if (strcmp(cmd, "view") == 0) return python_module("cable.webview", argc, argv);
  if (strcmp(cmd, "explore") == 0) return python_module("cable.explorer", argc, argv);
  if (strcmp(cmd, "replay") == 0) {
    if (argc != 3) {
      fprintf(stderr, "cable: usage: cable replay SCRIPT\n");
      return 2;
    }
    return replay(argv[2]);
  }
  if (strcmp(cmd, "info") == 0) {
    const char *e = argc == 3 ? argv[2] : NULL;
    if (e && strncmp(e, "e=", 2) == 0) e += 2;
    if (!e || !e[0]) {
      fprintf(stderr, "cable: usage: cable info e=PROBLEM\n");
      return 2;
    }
    return report(cable_cmd_info(e, stdout, &err), &err);
  }
  if (strcmp(cmd, "table") == 0) {
    if (argc != 3) {
      fprintf(stderr, "cable: usage: cable table b.NAME\n");
      return 2;
    }
    return report(cable_cmd_table(argv[2], stdout, &err), &err);
  }
  if (strcmp(cmd, "list") == 0) {
    if (argc != 3) {
      fprintf(stderr, "cable: usage: cable list s.NAME\n");
      return 2;
    }
    return report(cable_cmd_list(argv[2], stdout, &err), &err);
  }
  if (strcmp(cmd, "plot") == 0) {
    int rc = report(cable_cmd_plot(argc - 2, argv + 2, &err), &err);
    cable_pictures_cleanup(); /* fontconfig's caches, for leak checkers */
    return rc;
  }
  if (strcmp(cmd, "render") == 0) return report(cable_cmd_render(argc - 2, argv + 2, &err), &err);
  if (strcmp(cmd, "analyze") == 0) {
    if (argc < 4) {
      fprintf(stderr, "cable: usage: cable analyze s.NAME LABEL... [STAB=1]\n");
      return 2;
    }
    return report(cable_cmd_analyze(argv[2], argc - 3, argv + 3, stdout, &err), &err);
  }
  fprintf(stderr, "cable: unknown command '%s' (see cable --help)\n", cmd);
  return 2;
}
