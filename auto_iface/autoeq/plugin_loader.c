/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Plug-in loader: dlopen, the fixed entry symbol, and the checks that make a
 * module safe to call (Lua's loadlib is the model: one entry name, version
 * and size checks before trusting the module, and a reason for every
 * rejection). */
#include "cable/cable_plugin.h"

#include <ctype.h>
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cable/cable_constants.h"
#include "cable/cable_status.h"

/* Longest parameter or variable name: names become constants-file keys and
 * error keys (cable_error.key holds 63 characters). */
#define CABLE_PLUGIN_NAME_MAX 63

struct cable_plugin {
  void *handle;               /* from dlopen */
  const cable_problem *pb;    /* inside the module, or &copy */
  cable_problem copy;         /* an older layout (ABI 5) completed with this cable's defaults */
  char path[512];
};

static int reject(cable_error *err, const char *origin, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 4, 5)));
static int reject(cable_error *err, const char *origin, const char *key, const char *fmt, ...)
{
  char msg[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return cable_error_set(err, CABLE_ERR_PLUGIN, origin, 0, key, "%s", msg);
}

/* A name usable in constants files and scripts (ICP=['lambda'], sol['T']):
 * printable, no blanks, quotes, brackets, commas or '=' and not a number. */
static const char *name_problem(const char *s)
{
  size_t n = strlen(s);
  if (n == 0) return "is empty";
  if (n > CABLE_PLUGIN_NAME_MAX) return "is longer than 63 characters";
  if (isdigit((unsigned char)s[0]) || s[0] == '-' || s[0] == '+' || s[0] == '.')
    return "starts like a number";
  for (size_t i = 0; i < n; i++) {
    unsigned char c = (unsigned char)s[i];
    if (!isgraph(c) || strchr("'\"=,()[]{}#:;\\", c)) return "contains a blank or one of '\"=,()[]{}#:;\\";
  }
  return NULL;
}

static int check_names(const char *const *names, int n, const char *field, const char *origin,
                       cable_error *err)
{
  char key[64];
  for (int i = 0; i < n; i++) {
    if (!names[i]) continue;   /* unnamed slot */
    const char *why = name_problem(names[i]);
    snprintf(key, sizeof key, "%s[%d]", field, i);
    if (why) return reject(err, origin, key, "the name '%.63s' %s", names[i], why);
    for (int j = 0; j < i; j++)
      if (names[j] && strcmp(names[i], names[j]) == 0)
        return reject(err, origin, key, "the name '%s' is also %s[%d]", names[i], field, j);
  }
  return 0;
}

/* ABI 2: the problem's constants keys and its prepare/release pair. */
static int check_keys(const cable_problem *pb, const char *origin, cable_error *err)
{
  if (pb->prepare && !pb->release)
    return reject(err, origin, "release", "is NULL but prepare is set (an instance must be given back)");
  if (!pb->prepare && pb->release) return reject(err, origin, "prepare", "is NULL but release is set");
  if (pb->nkeys < 0 || pb->nkeys > CABLE_MAX_PKEYS)
    return reject(err, origin, "nkeys", "must be between 0 and %d, got %d", CABLE_MAX_PKEYS, pb->nkeys);
  if (pb->nkeys > 0 && !pb->keys) return reject(err, origin, "keys", "is NULL but nkeys = %d", pb->nkeys);
  char key[64];
  for (int i = 0; i < pb->nkeys; i++) {
    const cable_problem_key *k = &pb->keys[i];
    snprintf(key, sizeof key, "keys[%d]", i);
    const char *why = k->name ? name_problem(k->name) : "is NULL";
    if (!why && strlen(k->name) >= CABLE_PKEY_LEN) why = "is longer than 31 characters";
    if (why) return reject(err, origin, key, "the key name %s", why);
    if (cable_constants_key_known(k->name))
      return reject(err, origin, key, "'%s' is one of cable's own constants keys", k->name);
    for (int j = 0; j < i; j++)
      if (pb->keys[j].name && strcmp(pb->keys[j].name, k->name) == 0)
        return reject(err, origin, key, "the key '%s' is also keys[%d]", k->name, j);
    if (k->type != CABLE_KEY_INT && k->type != CABLE_KEY_REAL)
      return reject(err, origin, key, "'%s': type must be CABLE_KEY_INT or CABLE_KEY_REAL, got %d", k->name, k->type);
    if (!(k->min <= k->max) || !(k->def >= k->min && k->def <= k->max))
      return reject(err, origin, key, "'%s': need min <= def <= max, got %g <= %g <= %g", k->name, k->min, k->def,
                    k->max);
  }
  /* ABI 4: the variational structure (doc/stability.md S4) */
  const cable_variational *v = pb->variational;
  if (v && !v->ritz && (v->nvar < 1 || v->ncon < 0 || v->nvbc < 0 || !v->hessian || (v->ncon > 0 && !v->constraints) ||
                        (v->nvbc > 0 && !v->vbc)))
    return reject(err, origin, "variational",
                  "needs a ritz callback, or nvar >= 1, ncon >= 0, nvbc >= 0, a hessian callback, constraints when "
                  "ncon > 0 and vbc when nvbc > 0");
  return 0;
}

/* the struct size of a layout: ABI 5 ended with variational */
static size_t abi_size(int abi)
{
  return abi == 5 ? offsetof(cable_problem, symmetries) : sizeof(cable_problem);
}

int cable_problem_validate(const cable_problem *pb, int npar_max, const char *origin,
                           cable_error *err)
{
  if (!origin) origin = "";
  if (!pb) return reject(err, origin, CABLE_PROBLEM_ENTRY, "returned NULL (no problem)");
  /* version and size first: past them the layout may not be ours */
  if (pb->abi_version != CABLE_PROBLEM_ABI && pb->abi_version != CABLE_PROBLEM_ABI_OLDEST)
    return reject(err, origin, "abi_version",
                  "built for ABI %d, this cable expects %d (rebuild the plug-in against this "
                  "cable's cable_problem.h)",
                  pb->abi_version, CABLE_PROBLEM_ABI);
  size_t want = abi_size(pb->abi_version);
  if (pb->struct_size != want)
    return reject(err, origin, "struct_size",
                  "is %zu, this cable's cable_problem has %zu bytes (set it to "
                  "sizeof(cable_problem) and rebuild against this cable's headers)",
                  pb->struct_size, want);
  if (!pb->name || name_problem(pb->name))
    return reject(err, origin, "name", "the problem needs a name usable as e=NAME (%s)",
                  pb->name ? name_problem(pb->name) : "it is NULL");
  if (pb->ndim <= 0) return reject(err, origin, "ndim", "must be positive, got %d", pb->ndim);
  if (pb->nbc < 0) return reject(err, origin, "nbc", "must not be negative, got %d", pb->nbc);
  if (pb->nint < 0) return reject(err, origin, "nint", "must not be negative, got %d", pb->nint);
  if (pb->npar < 0 || pb->npar > npar_max)
    return reject(err, origin, "npar", "must be between 0 and NPAR = %d, got %d", npar_max, pb->npar);
  if (!pb->func) return reject(err, origin, "func", "is NULL (FUNC is required)");
  if (pb->nbc > 0 && !pb->bcnd)
    return reject(err, origin, "bcnd", "is NULL but nbc = %d (BCND is required when nbc > 0)", pb->nbc);
  if (pb->nint > 0 && !pb->icnd)
    return reject(err, origin, "icnd", "is NULL but nint = %d (ICND is required when nint > 0)", pb->nint);
  const struct {
    const char *field;
    int value;
  } flags[] = {{"func_has_jac", pb->func_has_jac},
               {"bcnd_has_jac", pb->bcnd_has_jac},
               {"icnd_has_jac", pb->icnd_has_jac}};
  for (size_t i = 0; i < sizeof flags / sizeof flags[0]; i++)
    if (flags[i].value != 0 && flags[i].value != 1)
      return reject(err, origin, flags[i].field, "must be 0 or 1, got %d", flags[i].value);
  if (pb->parnames && pb->npar == 0)
    return reject(err, origin, "parnames", "names are given but npar is 0");
  if (pb->parnames && check_names(pb->parnames, pb->npar, "parnames", origin, err)) return CABLE_ERR_PLUGIN;
  if (pb->unames && check_names(pb->unames, pb->ndim, "unames", origin, err)) return CABLE_ERR_PLUGIN;
  if (check_keys(pb, origin, err)) return CABLE_ERR_PLUGIN;
  if (pb->abi_version < 6) return 0;
  /* ABI 6: the declared reflections (doc/plugins.md, Symmetries) */
  if (pb->nsym < 0 || (pb->nsym > 0 && !pb->symmetries))
    return reject(err, origin, "symmetries", "nsym = %d needs nsym >= 0 and a symmetries array when positive",
                  pb->nsym);
  for (int i = 0; i < pb->nsym; i++) {
    const cable_symmetry *sy = &pb->symmetries[i];
    char key[48];
    snprintf(key, sizeof key, "symmetries[%d]", i);
    if (!sy->act && (sy->odd_comp < 0 || sy->odd_comp >= pb->ndim || (sy->odd_at != 0 && sy->odd_at != 1)))
      return reject(err, origin, key, "needs act, or odd_comp in [0, ndim = %d) and odd_at 0 or 1 (got %d, %d)",
                    pb->ndim, sy->odd_comp, sy->odd_at);
    if (sy->unfold_bc < -1 || sy->unfold_bc >= pb->nbc)
      return reject(err, origin, key, "unfold_bc = %d: -1 or a row below nbc = %d", sy->unfold_bc, pb->nbc);
    if (sy->unfold_par < -1 || sy->unfold_par >= npar_max)
      return reject(err, origin, key, "unfold_par = %d: -1 or a slot below NPAR = %d", sy->unfold_par, npar_max);
    if (sy->multiplicity < 0)
      return reject(err, origin, key, "multiplicity = %d must not be negative", sy->multiplicity);
  }
  return 0;
}

cable_plugin *cable_plugin_open_npar(const char *path, int npar_max, const cable_problem **pb,
                                     cable_error *err)
{
  if (pb) *pb = NULL;
  if (!path || !path[0]) {
    cable_error_set(err, CABLE_ERR_IO, "", 0, "", "no plug-in file given");
    return NULL;
  }
  struct stat st;
  if (stat(path, &st) != 0) {
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot open the plug-in: %s", strerror(errno));
    return NULL;
  }
  if (!S_ISREG(st.st_mode)) {
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "cannot open the plug-in: not a regular file");
    return NULL;
  }
  cable_plugin *p = calloc(1, sizeof *p);
  if (!p) {
    cable_error_set(err, CABLE_ERR_ALLOC, path, 0, "", "out of memory");
    return NULL;
  }
  /* dlopen searches the library path for names without '/'; a user's file is
   * meant relative to the current directory */
  int n = snprintf(p->path, sizeof p->path, "%s%s", strchr(path, '/') ? "" : "./", path);
  if (n < 0 || (size_t)n >= sizeof p->path) {
    free(p);
    cable_error_set(err, CABLE_ERR_IO, path, 0, "", "the plug-in path is too long");
    return NULL;
  }
  dlerror();
  /* RTLD_NOW: unresolved symbols are reported here, not at the first call;
   * RTLD_LOCAL: one plug-in's symbols never satisfy another's */
  p->handle = dlopen(p->path, RTLD_NOW | RTLD_LOCAL);
  if (!p->handle) {
    const char *why = dlerror();
    cable_error_set(err, CABLE_ERR_PLUGIN, path, 0, "", "not a loadable shared object: %s",
                    why ? why : "unknown reason");
    free(p);
    return NULL;
  }
  dlerror();
  void *sym = dlsym(p->handle, CABLE_PROBLEM_ENTRY);
  if (!sym) {
    reject(err, path, CABLE_PROBLEM_ENTRY,
           "the plug-in does not export it (define `const cable_problem *%s(void)` with external "
           "linkage)",
           CABLE_PROBLEM_ENTRY);
    cable_plugin_close(p);
    return NULL;
  }
  /* ISO C has no object-to-function pointer conversion; POSIX guarantees
   * that dlsym's result has the function's representation */
  cable_problem_entry_fn *entry;
  _Static_assert(sizeof entry == sizeof sym, "function and object pointers differ in size");
  memcpy(&entry, &sym, sizeof entry);
  p->pb = entry();
  if (cable_problem_validate(p->pb, npar_max, path, err)) {
    cable_plugin_close(p);
    return NULL;
  }
  if (p->pb->abi_version != CABLE_PROBLEM_ABI) {
    /* an older layout: its fields, the newer ones zero (no symmetries) */
    memset(&p->copy, 0, sizeof p->copy);
    memcpy(&p->copy, p->pb, p->pb->struct_size);
    p->copy.abi_version = CABLE_PROBLEM_ABI;
    p->copy.struct_size = sizeof p->copy;
    p->pb = &p->copy;
  }
  if (pb) *pb = p->pb;
  return p;
}

cable_plugin *cable_plugin_open(const char *path, const cable_problem **pb, cable_error *err)
{
  return cable_plugin_open_npar(path, CABLE_NPAR_DEFAULT, pb, err);
}

void cable_plugin_close(cable_plugin *p)
{
  if (!p) return;
  if (p->handle) dlclose(p->handle);
  free(p);
}

const cable_problem *cable_plugin_problem(const cable_plugin *p)
{
  return p ? p->pb : NULL;
}

const char *cable_plugin_path(const cable_plugin *p)
{
  return p ? p->path : "";
}
