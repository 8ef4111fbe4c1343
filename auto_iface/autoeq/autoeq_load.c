/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Finding, opening and closing AUTO equation files (autoeq.h). */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "autoeq_impl.h"
#include "cable/cable_status.h"

/* AUTO's order: NAME.f90, NAME.f, NAME.c */
static const char *const suffixes[] = {".f90", ".f", ".c"};
#define NSUFFIX ((int)(sizeof suffixes / sizeof suffixes[0]))

static int regular_file(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int has_suffix(const char *name, const char *suf)
{
  size_t n = strlen(name), k = strlen(suf);
  return n > k && strcmp(name + n - k, suf) == 0;
}

int cable_autoeq_find(const char *dir, const char *name, char *path, size_t len)
{
  if (!name || !name[0]) return CABLE_ERR_NOTFOUND;
  char buf[AUTOEQ_PATH_MAX];
  const char *d = dir && dir[0] && name[0] != '/' ? dir : NULL;
  for (int i = 0; i < NSUFFIX; i++)
    if (has_suffix(name, suffixes[i])) {
      snprintf(buf, sizeof buf, "%s%s%s", d ? d : "", d ? "/" : "", name);
      if (!regular_file(buf)) return CABLE_ERR_NOTFOUND;
      snprintf(path, len, "%s", buf);
      return 0;
    }
  for (int i = 0; i < NSUFFIX; i++) {
    snprintf(buf, sizeof buf, "%s%s%s%s", d ? d : "", d ? "/" : "", name, suffixes[i]);
    if (regular_file(buf)) {
      snprintf(path, len, "%s", buf);
      return 0;
    }
  }
  return CABLE_ERR_NOTFOUND;
}

cable_autoeq *cable_autoeq_open(const char *src, cable_error *err)
{
  cable_error local;
  if (!err) err = &local;   /* the build reads err->status */
  if (!src || !src[0]) {
    cable_error_set(err, src ? CABLE_ERR_INPUT : CABLE_ERR_NULL, "", 0, "e", "no equation file given");
    return NULL;
  }
  cable_autoeq *m = calloc(1, sizeof *m);
  if (!m) {
    cable_error_set(err, CABLE_ERR_ALLOC, src, 0, "", "out of memory");
    return NULL;
  }
  snprintf(m->src, sizeof m->src, "%s", src);
  const char *base = strrchr(src, '/');
  base = base ? base + 1 : src;
  int i;
  for (i = 0; i < NSUFFIX; i++)
    if (has_suffix(base, suffixes[i])) break;
  if (i == NSUFFIX) {
    cable_error_set(err, CABLE_ERR_INPUT, src, 0, "e", "an AUTO equation file ends in .f90, .f or .c");
    free(m);
    return NULL;
  }
  m->lang = i == 2 ? AUTOEQ_C : AUTOEQ_FORTRAN;
  snprintf(m->name, sizeof m->name, "%.*s", (int)(strlen(base) - strlen(suffixes[i])), base);
  if (autoeq_build(m, err) != 0) {
    free(m);
    return NULL;
  }
  dlerror();
  m->handle = dlopen(m->so, RTLD_NOW | RTLD_LOCAL);
  if (!m->handle) {
    const char *why = dlerror();
    cable_error_set(err, CABLE_ERR_PLUGIN, src, 0, "", "the built module does not load: %s", why ? why : "?");
    free(m);
    return NULL;
  }
  if (autoeq_bind(m, err) != 0) {
    cable_autoeq_close(m);
    return NULL;
  }
  return m;
}

/* AUTO runs every computation in a process of its own, so a routine's static
 * storage (a COMMON block or SAVE variable that STPNT fills on its first call
 * only, as AUTO's demos nag and fsh do) starts at zero in every run.  A module
 * that served a run is therefore opened again before the next: dlclose drops
 * it (it was opened RTLD_LOCAL and nothing else refers to it), dlopen maps it
 * with fresh storage, and its routines are bound again. */
static int reopen_module(cable_autoeq *m, cable_error *err)
{
  if (m->handle) dlclose(m->handle);
  m->c_tab = NULL;
  m->f_func = NULL;
  m->f_stpnt = NULL;
  m->f_bcnd = NULL;
  m->f_icnd = NULL;
  m->f_pvls = NULL;
  dlerror();
  m->handle = dlopen(m->so, RTLD_NOW | RTLD_LOCAL);
  if (!m->handle) {
    const char *why = dlerror();
    return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, 0, "", "the built module does not load again: %s",
                           why ? why : "?");
  }
  m->runs = 0;
  return autoeq_bind(m, err);
}

int cable_autoeq_problem(cable_autoeq *m, const cable_constants *c, const char *dat, const cable_problem **pb,
                         cable_error *err)
{
  if (!pb) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "no place for the problem (NULL)");
  *pb = NULL;
  if (!m) return cable_error_set(err, CABLE_ERR_NULL, "", 0, "", "no equation module (NULL)");
  if (!c) {   /* names only: AUTO's equations have no names of their own */
    memset(&m->pb, 0, sizeof m->pb);
    m->pb.abi_version = CABLE_PROBLEM_ABI;
    m->pb.struct_size = sizeof m->pb;
    m->pb.name = m->name;
    m->pb.description = m->src;
    *pb = &m->pb;
    return 0;
  }
  if (m->runs > 0) {
    int rc = reopen_module(m, err);
    if (rc) return rc;
  }
  m->runs++;
  free(m->dat);
  m->dat = NULL;
  m->ndat = 0;
  m->ndim = c->ndim;
  if (dat && dat[0] && c->ndim > 0) {
    int rc = autoeq_read_dat(m, dat, err);
    if (rc) return rc;
  }
  int rc = autoeq_make_problem(m, c, err);
  if (rc) return rc;
  *pb = &m->pb;
  return 0;
}

const char *cable_autoeq_source(const cable_autoeq *m) { return m ? m->src : NULL; }
const char *cable_autoeq_module(const cable_autoeq *m) { return m ? m->so : NULL; }
int cable_autoeq_was_built(const cable_autoeq *m) { return m ? m->built : 0; }

void cable_autoeq_close(cable_autoeq *m)
{
  if (!m) return;
  if (m->handle) dlclose(m->handle);
  free(m->scratch);
  free(m->dat);
  free(m->pvls_block);
  free(m);
}
