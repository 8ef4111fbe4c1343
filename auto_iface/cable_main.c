/* The `cable` command line: uses only the public API and reports every error
 * on one line with file, line and key, exiting non-zero. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_aufile.h"
#include "cable/cable_cont.h"
#include "cable_commands.h"
#include "cable/cable_pictures.h"
#include "cable/cable_status.h"
#include "cable/cable_version.h"
#include "script.h"
#include "script_host_cable.h"

static void usage(FILE *out)
{
  fputs("usage: cable COMMAND [ARGS]\n"
        "commands:\n"
        "  run [NAME] [c=NAME] [e=PROBLEM] [s=NAME] [sv=NAME] [KEY=VALUE ...]\n"
        "                     one continuation run, AUTO's run(...) semantics (a first\n"
        "                     NAME is run('NAME'): e=NAME c=NAME); KEY=VALUE overrides\n"
        "                     the constants file c.NAME\n"
        "  replay SCRIPT      replay a run script (a subset of AUTO's Python CLI); output\n"
        "                     files go to the script's directory\n"
        "  table b.NAME       the branch table of a b-file\n"
        "  list s.NAME        the labelled solutions of an s-file\n"
        "  analyze s.NAME LABEL...\n"
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
  if (strcmp(cmd, "run") == 0) return report(cable_cmd_run(argc - 2, argv + 2, &err), &err);
  if (strcmp(cmd, "replay") == 0) {
    if (argc != 3) {
      fprintf(stderr, "cable: usage: cable replay SCRIPT\n");
      return 2;
    }
    return report(cable_cmd_replay(argv[2], &err), &err);
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
      fprintf(stderr, "cable: usage: cable analyze s.NAME LABEL...\n");
      return 2;
    }
    return report(cable_cmd_analyze(argv[2], argc - 3, argv + 3, stdout, &err), &err);
  }
  fprintf(stderr, "cable: unknown command '%s' (see cable --help)\n", cmd);
  return 2;
}
