/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The layer rule (doc/api.md): a folder includes only the public headers
 * (include/cable/), its own headers and those of the layers below it:
 *
 *   continuation/base < continuation < equations < bc < graphics < auto_iface
 *
 * The Makefile gives each folder exactly those include paths, so an upward
 * include does not compile; this test reads the sources as well, so that the
 * rule also holds for headers no .c file includes yet.  Public headers
 * include only public headers; the test plug-ins and the API tests only
 * public headers and their own folder.  Runs from the repository root. */
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"

static const char *const layers[] = {"continuation/base", "continuation", "equations", "bc", "graphics",
                                     "auto_iface"};
#define NLAYERS ((int)(sizeof layers / sizeof layers[0]))

static int file_exists(const char *dir, const char *name)
{
  char path[1024];
  struct stat sb;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

static int is_source(const char *name)
{
  size_t n = strlen(name);
  return n > 2 && name[n - 2] == '.' && (name[n - 1] == 'c' || name[n - 1] == 'h');
}

/* Checks every `#include "X"` of one file.  level: the file's layer (0 ..
 * NLAYERS-1), -1 for a public header, -2 for a folder that sees only the
 * public headers and itself.  Returns the number of violations (each
 * printed as a FAIL line when report is 1, as a note otherwise). */
static int check_file(const char *dir, const char *name, int level, int report)
{
  char path[1024], line[1024];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "r");
  if (!f) {
    test_true(path, 0);
    return 1;
  }
  int bad = 0, lineno = 0;
  while (fgets(line, sizeof line, f)) {
    lineno++;
    const char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (strncmp(p, "#include", 8) != 0) continue;
    p += 8;
    while (*p == ' ' || *p == '\t') p++;
    if (*p != '"') continue;   /* <system> headers */
    char inc[512];
    size_t n = 0;
    for (p++; *p && *p != '"' && n + 1 < sizeof inc; p++) inc[n++] = *p;
    inc[n] = '\0';
    const char *why = NULL;
    if (strncmp(inc, "cable/", 6) == 0) {
      if (!file_exists("include", inc)) why = "no such public header";
    } else if (level == -1) {
      why = "a public header includes a private one";
    } else if (file_exists(dir, inc)) {
      /* own folder */
    } else if (level == -2 && strcmp(inc, "api_misuse_gen.inc") == 0) {
      /* the generated misuse cases (scripts/gen_api_misuse.py): calls of the
         public API, written from the public headers alone */
    } else if (level == -2) {
      why = "only public headers are visible here";
    } else {
      int found = -1;
      for (int k = 0; k < NLAYERS; k++)
        if (file_exists(layers[k], inc)) found = k;
      if (found < 0) why = "not found in any layer";
      else if (found > level) why = "upward include (a higher layer's header)";
    }
    if (why) {
      if (report) test_report(0, "%s:%d: #include \"%s\": %s", path, lineno, inc, why);
      else printf("found (as expected): %s:%d: #include \"%s\": %s\n", path, lineno, inc, why);
      bad++;
    }
  }
  fclose(f);
  return bad;
}

/* Every source file of dir; returns the violations. */
static int check_dir(const char *dir, int level, int *nfiles)
{
  DIR *d = opendir(dir);
  if (!d) return 0;
  int bad = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    if (is_source(e->d_name)) {
      bad += check_file(dir, e->d_name, level, 1);
      (*nfiles)++;
    }
  closedir(d);
  return bad;
}

/* A private header name used in two layers would be shadowed by the
 * include-path order; every name must be unique. */
static void check_unique_names(void)
{
  int dup = 0;
  for (int a = 0; a < NLAYERS; a++) {
    DIR *d = opendir(layers[a]);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      size_t n = strlen(e->d_name);
      if (n < 3 || strcmp(e->d_name + n - 2, ".h") != 0) continue;
      for (int b = a + 1; b < NLAYERS; b++)
        if (file_exists(layers[b], e->d_name)) {
          test_report(0, "header %s is in both %s/ and %s/", e->d_name, layers[a], layers[b]);
          dup++;
        }
    }
    closedir(d);
  }
  test_true("private header names are unique across the layers", dup == 0);
}

int main(void)
{
  int nfiles = 0;
  test_true("public headers include only public headers",
            check_dir("include/cable", -1, &nfiles) == 0 && nfiles > 10);
  for (int k = 0; k < NLAYERS; k++) {
    int before = nfiles;
    int bad = check_dir(layers[k], k, &nfiles);
    char what[160];
    snprintf(what, sizeof what, "%s/ (%d files) includes only its own, lower and public headers", layers[k],
             nfiles - before);
    test_true(what, bad == 0 && nfiles > before);
  }
  int before = nfiles;
  test_true("test plug-ins include only public headers",
            check_dir("tests/plugins", -2, &nfiles) == 0 && nfiles > before);
  before = nfiles;
  int bad = check_dir("tests/api", -2, &nfiles);
  if (nfiles > before) test_true("API tests include only public headers", bad == 0);
  check_unique_names();

  /* The checker itself must see a violation: a ground-floor file (level 0)
   * that includes the graphics layer's plot.h. */
  mkdir("tests/tmp", 0755);
  mkdir("tests/tmp/layers", 0755);
  FILE *f = fopen("tests/tmp/layers/planted.c", "w");
  int planted = -1;
  if (f) {
    fputs("#include \"plot.h\"\n#include \"cable/cable_status.h\"\n", f);
    fclose(f);
    planted = check_file("tests/tmp/layers", "planted.c", 0, 0);
  }
  test_int("a planted upward include is reported", planted, 1);
  return test_summary();
}
