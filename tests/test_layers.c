/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The layer rule (doc/api.md): a folder includes only the public headers
 * (include/cable/), its own headers and those of the layers below it:
 *
 *   continuation/base < continuation < equations < bc < graphics
 *     < auto_iface/files < auto_iface/autoeq < auto_iface/session < auto_iface/cli
 *
 * (continuation/base: the ground floor every layer may use; the Python
 * extension, auto_iface/python, sees the public headers only.)
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
#include "layer_dirs.h"


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
 * NLAYER_DIRS-1), -1 for a public header, -2 for a folder that sees only the
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
      for (int k = 0; k < NLAYER_DIRS; k++)
        if (file_exists(layer_dirs[k], inc)) found = k;
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
  for (int a = 0; a < NLAYER_DIRS; a++) {
    DIR *d = opendir(layer_dirs[a]);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      size_t n = strlen(e->d_name);
      if (n < 3 || strcmp(e->d_name + n - 2, ".h") != 0) continue;
      for (int b = a + 1; b < NLAYER_DIRS; b++)
        if (file_exists(layer_dirs[b], e->d_name)) {
          test_report(0, "header %s is in both %s/ and %s/", e->d_name, layer_dirs[a], layer_dirs[b]);
          dup++;
        }
    }
    closedir(d);
  }
  /* the extension's folder as well: its headers share the include space of
     the tests */
  for (int a = 0; a < NLAYER_DIRS; a++) {
    DIR *d = opendir(layer_dirs[a]);
    if (!d) continue;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      size_t n = strlen(e->d_name);
      if (n >= 3 && strcmp(e->d_name + n - 2, ".h") == 0 && file_exists("auto_iface/python", e->d_name)) {
        test_report(0, "header %s is in both %s/ and auto_iface/python/", e->d_name, layer_dirs[a]);
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
  for (int k = 0; k < NLAYER_DIRS; k++) {
    int before = nfiles;
    int bad = check_dir(layer_dirs[k], k, &nfiles);
    char what[160];
    snprintf(what, sizeof what, "%s/ (%d files) includes only its own, lower and public headers", layer_dirs[k],
             nfiles - before);
    test_true(what, bad == 0 && nfiles > before);
  }
  int before = nfiles;
  test_true("the Python extension (auto_iface/python) includes only public headers and its own",
            check_dir("auto_iface/python", -2, &nfiles) == 0 && nfiles > before);
  before = nfiles;
  test_true("the files written next to an equation file (auto_iface/autoeq/auto_compat) include only their own",
            check_dir("auto_iface/autoeq/auto_compat", -2, &nfiles) == 0 && nfiles > before);
  /* a source file straight in auto_iface/ would belong to no layer (and the
     Makefile would not build it) */
  before = nfiles;
  int loose = check_dir("auto_iface", -2, &nfiles);
  test_int("no source file lies in auto_iface/ outside its sub-folders", nfiles - before + loose, 0);
  before = nfiles;
  test_true("test plug-ins include only public headers",
            check_dir("tests/plugins", -2, &nfiles) == 0 && nfiles > before);
  before = nfiles;
  int bad = check_dir("tests/api", -2, &nfiles);
  if (nfiles > before) test_true("API tests include only public headers", bad == 0);
  check_unique_names();

  /* The checker itself must see a violation: a ground-floor file (level 0)
   * that includes the graphics layer's plot.h, and one that includes the
   * engine's cont_impl.h (the floor just above). */
  mkdir("tests/tmp", 0755);
  mkdir("tests/tmp/layers", 0755);
  FILE *f = fopen("tests/tmp/layers/planted.c", "w");
  int planted = -1;
  if (f) {
    fputs("#include \"plot.h\"\n#include \"cable/cable_status.h\"\n#include \"cont_impl.h\"\n", f);
    fclose(f);
    planted = check_file("tests/tmp/layers", "planted.c", 0, 0);
  }
  test_int("two planted upward includes of a ground-floor file are reported", planted, 2);
  /* and between the sub-folders of auto_iface: a file of the AUTO files'
     layer that includes the session's private header */
  int files_level = layer_index("auto_iface/files");
  f = fopen("tests/tmp/layers/planted_files.c", "w");
  planted = -1;
  if (f) {
    fputs("#include \"cable_session_impl.h\"\n#include \"atomic_file.h\"\n", f);
    fclose(f);
    planted = check_file("tests/tmp/layers", "planted_files.c", files_level, 0);
  }
  test_int("a planted include of auto_iface/session from auto_iface/files is reported", planted, 1);
  return test_summary();
}
