/* The `cable` command line: uses only the public API and reports every error
 * on one line with file, line and key. */
#include <stdio.h>
#include <string.h>

#include "cable_version.h"

static void usage(FILE *out)
{
  fputs("usage: cable COMMAND [ARGS]\n"
        "commands:\n"
        "  --version          print cable's version and the library versions\n"
        "  --help             this text\n",
        out);
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  if (strcmp(argv[1], "--version") == 0) {
    char buf[256];
    puts(cable_version_string(buf, sizeof buf));
    return 0;
  }
  if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
    usage(stdout);
    return 0;
  }
  fprintf(stderr, "cable: unknown command '%s' (see cable --help)\n", argv[1]);
  return 2;
}
