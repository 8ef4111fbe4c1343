#include "cable_team.h"

#include <pthread.h>
#include <stdlib.h>

struct cable_team {
  int size;
  pthread_t *threads;          /* [size - 1] workers */
  int nstarted;                /* workers created */
  pthread_mutex_t mu;
  pthread_cond_t go, done;
  unsigned long generation;    /* bumped for every job */
  int pending;                 /* workers still busy with the current job */
  int quit;
  cable_team_fn *fn;
  void *ctx;
  int n;
};

typedef struct {
  cable_team *t;
  int k;
} worker_arg;

static void run_block(cable_team *t, cable_team_fn *fn, void *ctx, int n, int k)
{
  long lo = (long)k * n / t->size, hi = (long)(k + 1) * n / t->size;
  for (long i = lo; i < hi; i++) fn(ctx, (int)i);
}

static void *worker(void *p)
{
  worker_arg *a = p;
  cable_team *t = a->t;
  const int k = a->k;
  free(a);
  unsigned long seen = 0;
  pthread_mutex_lock(&t->mu);
  for (;;) {
    while (!t->quit && t->generation == seen) pthread_cond_wait(&t->go, &t->mu);
    if (t->quit) break;
    seen = t->generation;
    cable_team_fn *fn = t->fn;
    void *ctx = t->ctx;
    int n = t->n;
    pthread_mutex_unlock(&t->mu);
    run_block(t, fn, ctx, n, k);
    pthread_mutex_lock(&t->mu);
    if (--t->pending == 0) pthread_cond_signal(&t->done);
  }
  pthread_mutex_unlock(&t->mu);
  return NULL;
}

cable_team *cable_team_alloc(int size)
{
  if (size < 1) size = 1;
  cable_team *t = calloc(1, sizeof *t);
  if (!t) return NULL;
  t->size = size;
  if (size == 1) return t;
  t->threads = calloc((size_t)(size - 1), sizeof *t->threads);
  if (!t->threads) {
    free(t);
    return NULL;
  }
  pthread_mutex_init(&t->mu, NULL);
  pthread_cond_init(&t->go, NULL);
  pthread_cond_init(&t->done, NULL);
  for (int k = 1; k < size; k++) {
    worker_arg *a = malloc(sizeof *a);
    if (!a) break;
    a->t = t;
    a->k = k;
    if (pthread_create(&t->threads[k - 1], NULL, worker, a) != 0) {
      free(a);
      break;
    }
    t->nstarted++;
  }
  if (t->nstarted != size - 1) {
    cable_team_free(t);
    return NULL;
  }
  return t;
}

void cable_team_free(cable_team *t)
{
  if (!t) return;
  if (t->size > 1) {
    pthread_mutex_lock(&t->mu);
    t->quit = 1;
    pthread_cond_broadcast(&t->go);
    pthread_mutex_unlock(&t->mu);
    for (int k = 0; k < t->nstarted; k++) pthread_join(t->threads[k], NULL);
    pthread_cond_destroy(&t->go);
    pthread_cond_destroy(&t->done);
    pthread_mutex_destroy(&t->mu);
  }
  free(t->threads);
  free(t);
}

int cable_team_size(const cable_team *t) { return t ? t->size : 1; }

void cable_team_run(cable_team *t, cable_team_fn *fn, void *ctx, int n)
{
  if (!t || t->size == 1 || n < 2) {
    for (int i = 0; i < n; i++) fn(ctx, i);
    return;
  }
  pthread_mutex_lock(&t->mu);
  t->fn = fn;
  t->ctx = ctx;
  t->n = n;
  t->pending = t->size - 1;
  t->generation++;
  pthread_cond_broadcast(&t->go);
  pthread_mutex_unlock(&t->mu);
  run_block(t, fn, ctx, n, 0);
  pthread_mutex_lock(&t->mu);
  while (t->pending > 0) pthread_cond_wait(&t->done, &t->mu);
  pthread_mutex_unlock(&t->mu);
}
