/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The BLAS of libcable.so and of the Python extension (cable._cable): a
 * private copy of OpenBLAS, linked in statically with its symbols hidden
 * (the Makefile's LIBS_PRIVBLAS), asked for one thread when the library is
 * loaded.  The structured solver works on blocks of a few dozen rows, where
 * BLAS threads only add hand-offs; a threaded BLAS shared with the host
 * (numpy's, in a Python process) spins its threads on the cores cable's own
 * team uses (a braid run of 30 steps: 6.4 s of CPU under `import cable`
 * against 1.6 s by `cable run`, doc/scripts.md).  Only the private copy is
 * set, so the host's BLAS keeps its own settings: the library changes no
 * process-wide setting.  CABLE_BLAS_THREADS=n asks the copy for n threads.
 *
 * Not part of libcable.a: a program linked with the static library uses the
 * BLAS it links with, and the application decides about its threads
 * (cable_blas_single_thread). */
#include <stdlib.h>

/* OpenBLAS's own (openblas_config.h; no header is included so that the
 * file builds without it) */
void gotoblas_init(void);
void openblas_set_num_threads(int n);

__attribute__((constructor)) static void private_blas_threads(void)
{
  /* the copy's own constructor may not have run yet (the order of
     constructors within one shared object is the link order);
     gotoblas_init is idempotent */
  gotoblas_init();
  const char *env = getenv("CABLE_BLAS_THREADS");
  int n = env ? atoi(env) : 1;
  openblas_set_num_threads(n < 1 ? 1 : n);
}
