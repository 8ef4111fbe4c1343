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
  if (sym) {
    set_threads_fn *set;
    *(void **)&set = sym;
    set(n);
  }
}
