/* SPDX-License-Identifier: GPL-3.0-or-later */
/* libcable as another project sees it: `make install` into a temporary
 * prefix, then, with nothing but `pkg-config --cflags --libs cable`,
 *   - tests/api/api_run.c builds and runs (Bratu through its fold, files
 *     written and read back, the fold against the closed form);
 *   - the template plug-in tests/plugins/bratu_plugin.c builds, loads and
 *     runs through the same program;
 *   - the installed library exports the public API and hides the rest.
 * Under a sanitizer build the check is skipped: a program compiled without
 * the sanitizer cannot load a sanitized libcable. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

static int file_exists(const char *path)
{
  struct stat sb;
  return stat(path, &sb) == 0;
}

/* Runs cmd through the shell; 0 when it exits with status 0.  Its output
 * goes to the test's log. */
static int sh(const char *cmd)
{
  printf("  $ %s\n", cmd);
  fflush(stdout);
  return system(cmd);
}

int main(int argc, char **argv)
{
  (void)argc;
  const char *what = "make install and a program, a plug-in built with pkg-config";
  if (SANITIZED) {
    test_skip(what, "sanitizer build: an unsanitized program cannot load this build's libcable.so");
    return test_summary();
  }
  /* the build mode from this program's path: build/MODE/tests/test_api_install */
  char mode[64] = "release";
  const char *b = strstr(argv[0], "build/");
  if (b && sscanf(b, "build/%63[^/]/tests/", mode) != 1) snprintf(mode, sizeof mode, "release");
  char cwd[900], prefix[1024], cmd[16384], path[1200];
  if (!getcwd(cwd, sizeof cwd)) {
    test_true("the working directory's path fits", 0);
    return test_summary();
  }
  mkdir("tests/tmp", 0755);
  snprintf(prefix, sizeof prefix, "%s/tests/tmp/prefix.%ld", cwd, (long)getpid());
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", prefix);
  (void)!system(cmd);

  snprintf(cmd, sizeof cmd,
           "env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s --no-print-directory MODE=%s install PREFIX='%s'",
           mode, prefix);
  test_int("make install PREFIX=<temporary prefix>", sh(cmd), 0);
  const char *const installed[] = {"include/cable/cable.h", "include/cable/cable_cont.h", "lib/libcable.so",
                                   "lib/libcable.so.1", "lib/pkgconfig/cable.pc", "bin/cable"};
  for (size_t i = 0; i < sizeof installed / sizeof installed[0]; i++) {
    char w[300];
    snprintf(path, sizeof path, "%s/%s", prefix, installed[i]);
    snprintf(w, sizeof w, "installed: %s", installed[i]);
    test_true(w, file_exists(path));
  }
  snprintf(path, sizeof path, "%s/include/cable/cable_impl.h", prefix);
  test_true("no private header is installed (only include/cable/)", !file_exists(path));

  char pkg[1100];
  snprintf(pkg, sizeof pkg, "PKG_CONFIG_PATH='%s/lib/pkgconfig' pkg-config", prefix);
  snprintf(cmd, sizeof cmd, "cc -std=c11 -Wall -Wextra -Werror tests/api/api_run.c $(%s --cflags --libs cable) -lm -o '%s/api_run'",
           pkg, prefix);
  test_int("a program builds with pkg-config --cflags --libs cable only", sh(cmd), 0);
  snprintf(cmd, sizeof cmd,
           "cc -std=c11 -Wall -Wextra -Werror -shared -fPIC tests/plugins/bratu_plugin.c "
           "$(%s --cflags --libs cable) -o '%s/bratu.so'",
           pkg, prefix);
  test_int("the template plug-in builds with pkg-config --cflags --libs cable only", sh(cmd), 0);

  snprintf(cmd, sizeof cmd, "LD_LIBRARY_PATH='%s/lib' '%s/api_run' > '%s/run.log' 2>&1; s=$?; cat '%s/run.log'; exit $s",
           prefix, prefix, prefix, prefix);
  test_int("the program runs against the installed library (built-in bratu)", sh(cmd), 0);
  snprintf(cmd, sizeof cmd,
           "LD_LIBRARY_PATH='%s/lib' '%s/api_run' '%s/bratu.so' '%s/out' > '%s/plugin.log' 2>&1; s=$?; "
           "cat '%s/plugin.log'; exit $s",
           prefix, prefix, prefix, prefix, prefix, prefix);
  test_int("the plug-in runs through it (Bratu's fold against the closed form)", sh(cmd), 0);
  snprintf(cmd, sizeof cmd, "grep -q '^PASS s-file: fold lambda' '%s/plugin.log'", prefix);
  test_int("  the plug-in run checked the fold", sh(cmd), 0);

  /* The export table is read with nm, not by dlopen into this process: under
   * valgrind the dynamic loader's own word-wise string reads and the
   * constructors of libcable's dependencies (unmapped again at dlclose) are
   * reported as errors that are not libcable's.  That the library loads is
   * shown by the two runs above. */
  snprintf(cmd, sizeof cmd, "nm -D --defined-only '%s/lib/libcable.so' > '%s/symbols.txt'", prefix, prefix);
  test_int("the installed libcable.so has a dynamic symbol table", sh(cmd), 0);
  snprintf(cmd, sizeof cmd,
           "grep -qw cable_cont_alloc '%s/symbols.txt' && grep -qw cable_constants_parse_file_for '%s/symbols.txt'",
           prefix, prefix);
  test_int("  it exports the public API (cable_cont_alloc, cable_constants_parse_file_for)", sh(cmd), 0);
  snprintf(cmd, sizeof cmd, "! grep -qwE 'colloc_newton_solve|braid_pvls|cable_atomic_open' '%s/symbols.txt'",
           prefix);
  test_int("  and hides the rest (colloc_newton_solve, braid_pvls, cable_atomic_open)", sh(cmd), 0);
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", prefix);
  (void)!system(cmd);
  return test_summary();
}
