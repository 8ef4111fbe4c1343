/* SPDX-License-Identifier: GPL-3.0-or-later */
#define _GNU_SOURCE 1 /* RTLD_DEFAULT */
#include "cable/cable_cont.h"

#include <dlfcn.h>
#include <stdlib.h>

typedef void set_threads_fn(int);

void cable_blas_single_thread(void)
{
  /* CABLE_BLAS_THREADS=n lets a user keep a threaded BLAS for huge meshes */
  const char *env = getenv("CABLE_BLAS_THREADS");
  int n = env ? atoi(env) : 1;
  if (n < 1) n = 1;
  void *sym = dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
  /* inside a process that loaded the BLAS locally (the Python extension:
     CPython opens modules RTLD_LOCAL) the symbol is not global: ask the
     library itself, if it is loaded */
  static const char *const libs[] = {"libblas.so.3", "libopenblas.so.0"};
  for (size_t i = 0; !sym && i < sizeof libs / sizeof libs[0]; i++) {
    void *h = dlopen(libs[i], RTLD_LAZY | RTLD_NOLOAD);
    if (h) {
      sym = dlsym(h, "openblas_set_num_threads");
      dlclose(h);   /* RTLD_NOLOAD took a reference; the library stays loaded */
    }
  }
  if (sym) {
    set_threads_fn *set;
    *(void **)&set = sym;
    set(n);
  }
}
