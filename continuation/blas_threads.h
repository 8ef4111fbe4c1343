/* BLAS threading: the structured solver works on blocks of a few dozen rows,
 * where a threaded BLAS (OpenBLAS) only adds thread hand-offs and spinning
 * (measured: 42% of a braid run's time in sched_yield).  cable asks the BLAS
 * for one thread when the BLAS offers the setter; otherwise nothing happens. */
#ifndef CABLE_BLAS_THREADS_H
#define CABLE_BLAS_THREADS_H

/* Idempotent; safe to call before every engine allocation. */
void cable_blas_single_thread(void);

#endif
